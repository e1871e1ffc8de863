/*
 * wide.h - internal: exact unsigned products and comparisons wider than 64
 * bits, in portable C99 (32-bit partial products, no compiler extension),
 * for the correlation search (ncc.h): its comparisons need num^2 * var, up
 * to 2^124 * 2^62 = 2^186; and 128-bit sums, shifts, quotients and roots
 * for the K-L transform (kl.h) and the mixture fits (mixture.h).
 */
#ifndef SSDA_WIDE_H
#define SSDA_WIDE_H

#include <stdint.h>

#include "compiler.h"

typedef struct {
    uint64_t hi, lo; /* value = hi * 2^64 + lo */
} ssda__u128_t;

typedef struct {
    uint64_t w2, w1, w0; /* value = w2 * 2^128 + w1 * 2^64 + w0 */
} ssda__u192_t;

/* a * b exactly: on compilers with a native 128-bit type (64-bit GCC and
   clang) through it, elsewhere from four 32-bit partial products
   (ssda__mul_64x64_parts); the same value either way. */
SSDA_INTERNAL ssda__u128_t ssda__mul_64x64_parts(uint64_t a, uint64_t b);
#if defined(__SIZEOF_INT128__) && (defined(__GNUC__) || defined(__clang__))
__extension__ typedef unsigned __int128 ssda__native_u128_t;
static inline ssda__u128_t ssda__mul_64x64(uint64_t a, uint64_t b)
{
    const ssda__native_u128_t p = (ssda__native_u128_t)a * b;
    ssda__u128_t r;
    r.hi = (uint64_t)(p >> 64);
    r.lo = (uint64_t)p;
    return r;
}
#else
#define ssda__mul_64x64(a, b) ssda__mul_64x64_parts((a), (b))
#endif

/* a * b exactly (< 2^192). */
SSDA_INTERNAL ssda__u192_t ssda__mul_128x64(ssda__u128_t a, uint64_t b);

/* -1, 0 or 1 as a <, = or > b. */
static inline int ssda__cmp_128(ssda__u128_t a, ssda__u128_t b)
{
    if (a.hi != b.hi) {
        return a.hi < b.hi ? -1 : 1;
    }
    if (a.lo != b.lo) {
        return a.lo < b.lo ? -1 : 1;
    }
    return 0;
}
SSDA_INTERNAL int ssda__cmp_192(const ssda__u192_t *a, const ssda__u192_t *b);

/* floor(n / d) for d > 0 and n.hi < d (the quotient fits 64 bits), by
   restoring shift-and-subtract (64 steps). */
SSDA_INTERNAL uint64_t ssda__div_128_64(ssda__u128_t n, uint64_t d);

/* Number of significant bits of v (0 for 0, 64 for v >= 2^63). */
#if defined(__GNUC__) || defined(__clang__)
static inline uint32_t ssda__bitlen64(uint64_t v)
{
    return v == 0u ? 0u : 64u - (uint32_t)__builtin_clzll(v);
}
#else
SSDA_INTERNAL uint32_t ssda__bitlen64(uint64_t v);
#endif

/* ---- 128-bit arithmetic of the K-L transform and the mixture fits
   (kl_*.c, mix_*.c): exact sums, shifts and quotients on setup paths (once
   per image or per fit iteration and component), never per pixel ---- */

/* v as a 128-bit value. */
SSDA_INTERNAL ssda__u128_t ssda__u128_from(uint64_t v);
/* a + b and a - b modulo 2^128. */
SSDA_INTERNAL ssda__u128_t ssda__u128_add(ssda__u128_t a, ssda__u128_t b);
SSDA_INTERNAL ssda__u128_t ssda__u128_sub(ssda__u128_t a, ssda__u128_t b);
/* a << s and a >> s for s in 0..127 (bits shifted out are lost). */
SSDA_INTERNAL ssda__u128_t ssda__u128_shl(ssda__u128_t a, uint32_t s);
SSDA_INTERNAL ssda__u128_t ssda__u128_shr(ssda__u128_t a, uint32_t s);
/* Number of significant bits: 0 for 0, 128 for values >= 2^127. */
SSDA_INTERNAL uint32_t ssda__u128_bits(ssda__u128_t a);
/* floor(n / d) for d > 0 (restoring division, one bit per step, up to 128
   steps); a zero d gives all ones. */
SSDA_INTERNAL ssda__u128_t ssda__u128_div(ssda__u128_t n, ssda__u128_t d);
/* floor(sqrt(a)) (< 2^64), bitwise. */
SSDA_INTERNAL uint64_t ssda__u128_isqrt(ssda__u128_t a);
/* min(a, 2^64 - 1). */
SSDA_INTERNAL uint64_t ssda__u128_sat64(ssda__u128_t a);

/* round(v / 2^s) with halves away from zero, for s in 1..62: symmetric in
   sign (round(-v) = -round(v)), so results do not depend on which way a
   vector points; no right shift of a negative value. */
SSDA_INTERNAL int64_t ssda__round_shift(int64_t v, uint32_t s);

#endif /* SSDA_WIDE_H */
