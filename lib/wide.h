/*
 * wide.h - internal: exact unsigned products and comparisons wider than 64
 * bits, in portable C99 (32-bit partial products, no compiler extension),
 * for the correlation search (ncc.h): its comparisons need num^2 * var, up
 * to 2^124 * 2^62 = 2^186.
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

#endif /* SSDA_WIDE_H */
