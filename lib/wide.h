/*
 * wide.h - internal: exact unsigned products and comparisons wider than 64
 * bits, in portable C99 (32-bit partial products, no compiler extension),
 * for the correlation search (ncc.h): its comparisons need num^2 * var, up
 * to 2^124 * 2^62 = 2^186; 128-bit sums, shifts, quotients and roots
 * for the K-L transform (kl.h) and the mixture fits (mixture.h); and signed
 * 128-bit arithmetic (ssda__i128_t, ssda__w_*) on the same words for the
 * polynomial maps (poly.h, warp.h) and the shading sums (shade.h).
 */
#ifndef SSDA_WIDE_H
#define SSDA_WIDE_H

#include <stdbool.h>
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

/* Signed 128-bit integers on the same two words, in two's complement (hi's
   top bit is the sign), for the exact polynomial evaluation of the warp
   (add only, per pixel) and the least-squares fit and shading sums
   (multiply and divide, per fit or row). Arithmetic is modulo 2^128, so
   callers keep every value inside (-2^127, 2^127) (each use writes its
   bound beside it). Unsigned words only: no signed overflow, no
   implementation-defined shift. */
typedef ssda__u128_t ssda__i128_t;

static inline ssda__i128_t ssda__w_i64(int64_t v)
{
    ssda__i128_t r;
    r.lo = (uint64_t)v; /* two's complement: the conversion is modulo 2^64 */
    r.hi = v < 0 ? UINT64_MAX : 0u;
    return r;
}

/* a + b, a - b: the same bits as ssda__u128_add / _sub, inline for the
   warp's per-pixel forward differences. */
static inline ssda__i128_t ssda__w_add(ssda__i128_t a, ssda__i128_t b)
{
    ssda__i128_t r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo ? 1u : 0u);
    return r;
}

static inline ssda__i128_t ssda__w_sub(ssda__i128_t a, ssda__i128_t b)
{
    ssda__i128_t r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo ? 1u : 0u);
    return r;
}

static inline bool ssda__w_neg_p(ssda__i128_t a)
{
    return (a.hi >> 63) != 0u;
}

static inline bool ssda__w_zero_p(ssda__i128_t a)
{
    return a.lo == 0u && a.hi == 0u;
}

static inline ssda__i128_t ssda__w_neg(ssda__i128_t a)
{
    const ssda__i128_t z = {0u, 0u}; /* hi, lo */
    return ssda__w_sub(z, a);
}

/* a < b, signed. */
static inline bool ssda__w_lt(ssda__i128_t a, ssda__i128_t b)
{
    const uint64_t sa = a.hi ^ ((uint64_t)1u << 63); /* order-preserving bias */
    const uint64_t sb = b.hi ^ ((uint64_t)1u << 63);
    return sa < sb || (sa == sb && a.lo < b.lo);
}

/* a * 2^n, 0 <= n < 128, bits shifted out lost: ssda__u128_shl (the same
   words, the same bits). */

/* floor(a / 2^n), 0 <= n < 128 (arithmetic shift). */
SSDA_INTERNAL ssda__i128_t ssda__w_sar(ssda__i128_t a, uint32_t n);

/* a * b exactly (|a|, |b| <= 2^63: |a * b| <= 2^126). */
SSDA_INTERNAL ssda__i128_t ssda__w_mul64(int64_t a, int64_t b);

/* a * b modulo 2^128: exact when the true product lies in (-2^127, 2^127). */
SSDA_INTERNAL ssda__i128_t ssda__w_mul(ssda__i128_t a, int64_t b);

/* n / d rounded to nearest, halves away from zero; d != 0. The quotient
   must fit (it does whenever |n| < 2^127). Shift-and-subtract, 128 steps:
   for setup paths (fits, per-row coefficients), never per pixel. */
SSDA_INTERNAL ssda__i128_t ssda__w_div_round(ssda__i128_t n, ssda__i128_t d);

/* floor(n / d); d > 0. As above. */
SSDA_INTERNAL ssda__i128_t ssda__w_div_floor(ssda__i128_t n, ssda__i128_t d);

/* Does a lie in [INT64_MIN, INT64_MAX]? */
static inline bool ssda__w_fits64(ssda__i128_t a)
{
    return a.hi == ((a.lo >> 63) != 0u ? UINT64_MAX : 0u);
}

/* a as int64_t; a must fit (ssda__w_fits64). */
static inline int64_t ssda__i128_to64(ssda__i128_t a)
{
    /* two's complement words back to a signed value without an
       implementation-defined conversion of a value above INT64_MAX */
    const uint64_t inv = ~a.lo;
    return (a.lo >> 63) != 0u ? -(int64_t)inv - 1 : (int64_t)a.lo;
}

/* 2^n as int64_t, 0 <= n <= 62 (an unsigned shift: no signed shift). */
static inline int64_t ssda__pow2(uint32_t n)
{
    const uint64_t v = (uint64_t)1u << n;
    return (int64_t)v;
}

#endif /* SSDA_WIDE_H */
