/* i128.c - 128-bit shifts, products and quotients (lib/i128.h). */
#include "i128.h"

ssda__w_t ssda__w_shl(ssda__w_t a, uint32_t n)
{
    ssda__w_t r;
    if (n == 0u) {
        return a;
    }
    if (n >= 64u) {
        r.hi = a.lo << (n - 64u);
        r.lo = 0u;
    } else {
        r.hi = (a.hi << n) | (a.lo >> (64u - n));
        r.lo = a.lo << n;
    }
    return r;
}

ssda__w_t ssda__w_sar(ssda__w_t a, uint32_t n)
{
    const uint64_t fill = ssda__w_neg_p(a) ? UINT64_MAX : 0u;
    ssda__w_t r;
    if (n == 0u) {
        return a;
    }
    if (n >= 64u) {
        const uint32_t down = n - 64u, up = 128u - n;
        r.lo = n == 64u ? a.hi : (a.hi >> down) | (fill << up);
        r.hi = fill;
    } else {
        const uint32_t up = 64u - n;
        r.lo = (a.lo >> n) | (a.hi << up);
        r.hi = (a.hi >> n) | (fill << up);
    }
    return r;
}

/* |a| * |b| for 64-bit magnitudes, from four 32 x 32 -> 64 partial
   products (each < 2^64; the middle sum is carried explicitly). */
static ssda__w_t mul_u64(uint64_t a, uint64_t b)
{
    const uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32;
    const uint64_t b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    /* middle: (p00 >> 32) + low halves of p01, p10: < 3 * 2^32 */
    const uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    ssda__w_t r;
    r.lo = (mid << 32) | (p00 & 0xFFFFFFFFu);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}

static uint64_t mag64(int64_t v)
{
    return v < 0 ? (uint64_t)0u - (uint64_t)v : (uint64_t)v;
}

ssda__w_t ssda__w_mul64(int64_t a, int64_t b)
{
    const ssda__w_t m = mul_u64(mag64(a), mag64(b));
    return (a < 0) != (b < 0) ? ssda__w_neg(m) : m;
}

ssda__w_t ssda__w_mul(ssda__w_t a, int64_t b)
{
    const bool neg = ssda__w_neg_p(a);
    const ssda__w_t m = neg ? ssda__w_neg(a) : a; /* |a| < 2^127 (callers' bound) */
    const uint64_t bm = mag64(b);
    /* |a| * |b| mod 2^128 = lo * bm + (hi * bm) * 2^64 */
    ssda__w_t r = mul_u64(m.lo, bm);
    r.hi += m.hi * bm;
    return neg != (b < 0) ? ssda__w_neg(r) : r;
}

/* Unsigned n / d (d > 0) by restoring shift-and-subtract; *rem receives
   the remainder. */
static ssda__w_t divmod_u(ssda__w_t n, ssda__w_t d, ssda__w_t *rem)
{
    ssda__w_t q = {0u, 0u};
    ssda__w_t r = {0u, 0u};
    uint32_t i;
    for (i = 0u; i < 128u; i++) {
        const uint64_t top = n.hi >> 63;
        r = ssda__w_shl(r, 1u);
        r.lo |= top;
        n = ssda__w_shl(n, 1u);
        q = ssda__w_shl(q, 1u);
        /* r < 2 d <= 2^128 here, and r fits since d < 2^127 (callers) */
        if (r.hi > d.hi || (r.hi == d.hi && r.lo >= d.lo)) {
            r = ssda__w_sub(r, d);
            q.lo |= 1u;
        }
    }
    *rem = r;
    return q;
}

ssda__w_t ssda__w_div_round(ssda__w_t n, ssda__w_t d)
{
    const bool neg = ssda__w_neg_p(n) != ssda__w_neg_p(d);
    const ssda__w_t nm = ssda__w_neg_p(n) ? ssda__w_neg(n) : n;
    const ssda__w_t dm = ssda__w_neg_p(d) ? ssda__w_neg(d) : d;
    ssda__w_t rem;
    ssda__w_t q = divmod_u(nm, dm, &rem);
    /* round half away from zero: 2 rem >= d (rem < d < 2^127: no wrap) */
    const ssda__w_t twice = ssda__w_shl(rem, 1u);
    if (!ssda__w_lt(twice, dm)) {
        const ssda__w_t one = {1u, 0u};
        q = ssda__w_add(q, one);
    }
    return neg ? ssda__w_neg(q) : q;
}

ssda__w_t ssda__w_div_floor(ssda__w_t n, ssda__w_t d)
{
    const ssda__w_t one = {1u, 0u};
    ssda__w_t rem, q;
    if (!ssda__w_neg_p(n)) {
        return divmod_u(n, d, &rem);
    }
    /* floor(-m / d) = -ceil(m / d) */
    q = divmod_u(ssda__w_neg(n), d, &rem);
    if (!ssda__w_zero_p(rem)) {
        q = ssda__w_add(q, one);
    }
    return ssda__w_neg(q);
}
