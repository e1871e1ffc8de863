/*
 * i128.h - internal: signed 128-bit integers in two 64-bit words, for the
 * exact polynomial evaluation of the warp (add only, per pixel) and the
 * least-squares fit and shading sums (multiply and divide, per fit or row).
 *
 * A value is hi * 2^64 + lo in two's complement (hi's top bit is the sign);
 * arithmetic is modulo 2^128, so callers keep every value inside
 * (-2^127, 2^127) (each use writes its bound beside it). Unsigned words
 * only: no signed overflow, no implementation-defined shift.
 */
#ifndef SSDA_I128_H
#define SSDA_I128_H

#include <stdbool.h>
#include <stdint.h>
#include "compiler.h"

#ifndef SSDA_INTERNAL
#define SSDA_INTERNAL
#endif

typedef struct {
    uint64_t lo;
    uint64_t hi;
} ssda__w_t;

static inline ssda__w_t ssda__w_i64(int64_t v)
{
    ssda__w_t r;
    r.lo = (uint64_t)v; /* two's complement: the conversion is modulo 2^64 */
    r.hi = v < 0 ? UINT64_MAX : 0u;
    return r;
}

static inline ssda__w_t ssda__w_add(ssda__w_t a, ssda__w_t b)
{
    ssda__w_t r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo ? 1u : 0u);
    return r;
}

static inline ssda__w_t ssda__w_sub(ssda__w_t a, ssda__w_t b)
{
    ssda__w_t r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo ? 1u : 0u);
    return r;
}

static inline bool ssda__w_neg_p(ssda__w_t a)
{
    return (a.hi >> 63) != 0u;
}

static inline bool ssda__w_zero_p(ssda__w_t a)
{
    return a.lo == 0u && a.hi == 0u;
}

static inline ssda__w_t ssda__w_neg(ssda__w_t a)
{
    ssda__w_t z = {0u, 0u};
    return ssda__w_sub(z, a);
}

/* a < b, signed. */
static inline bool ssda__w_lt(ssda__w_t a, ssda__w_t b)
{
    const uint64_t sa = a.hi ^ ((uint64_t)1u << 63); /* order-preserving bias */
    const uint64_t sb = b.hi ^ ((uint64_t)1u << 63);
    return sa < sb || (sa == sb && a.lo < b.lo);
}

/* a * 2^n, 0 <= n < 128 (bits shifted out are lost). */
SSDA_INTERNAL ssda__w_t ssda__w_shl(ssda__w_t a, uint32_t n);

/* floor(a / 2^n), 0 <= n < 128 (arithmetic shift). */
SSDA_INTERNAL ssda__w_t ssda__w_sar(ssda__w_t a, uint32_t n);

/* a * b exactly (|a|, |b| <= 2^63: |a * b| <= 2^126). */
SSDA_INTERNAL ssda__w_t ssda__w_mul64(int64_t a, int64_t b);

/* a * b modulo 2^128: exact when the true product lies in (-2^127, 2^127). */
SSDA_INTERNAL ssda__w_t ssda__w_mul(ssda__w_t a, int64_t b);

/* n / d rounded to nearest, halves away from zero; d != 0. The quotient
   must fit (it does whenever |n| < 2^127). Shift-and-subtract, 128 steps:
   for setup paths (fits, per-row coefficients), never per pixel. */
SSDA_INTERNAL ssda__w_t ssda__w_div_round(ssda__w_t n, ssda__w_t d);

/* floor(n / d); d > 0. As above. */
SSDA_INTERNAL ssda__w_t ssda__w_div_floor(ssda__w_t n, ssda__w_t d);

/* Does a lie in [INT64_MIN, INT64_MAX]? */
static inline bool ssda__w_fits64(ssda__w_t a)
{
    return a.hi == ((a.lo >> 63) != 0u ? UINT64_MAX : 0u);
}

/* a as int64_t; a must fit (ssda__w_fits64). */
static inline int64_t ssda__w_to64(ssda__w_t a)
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

#endif /* SSDA_I128_H */
