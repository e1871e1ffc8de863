/* wide.c - 128- and 192-bit unsigned arithmetic (wide.h). */
#include "wide.h"

ssda__u128_t ssda__mul_64x64_parts(uint64_t a, uint64_t b)
{
    const uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32;
    const uint64_t b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    const uint64_t p00 = a0 * b0; /* each partial product < 2^64 */
    const uint64_t p01 = a0 * b1;
    const uint64_t p10 = a1 * b0;
    const uint64_t p11 = a1 * b1;
    /* the middle column: three terms < 2^32 each, sum < 2^34 */
    const uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    ssda__u128_t r;
    r.lo = (mid << 32) | (p00 & 0xFFFFFFFFu);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32); /* < 2^64: a * b < 2^128 */
    return r;
}

ssda__u192_t ssda__mul_128x64(ssda__u128_t a, uint64_t b)
{
    const ssda__u128_t l = ssda__mul_64x64(a.lo, b);
    const ssda__u128_t h = ssda__mul_64x64(a.hi, b);
    ssda__u192_t r;
    r.w0 = l.lo;
    r.w1 = l.hi + h.lo;
    r.w2 = h.hi + (r.w1 < h.lo ? 1u : 0u); /* carry; < 2^64 as a * b < 2^192 */
    return r;
}

int ssda__cmp_192(const ssda__u192_t *a, const ssda__u192_t *b)
{
    if (a->w2 != b->w2) {
        return a->w2 < b->w2 ? -1 : 1;
    }
    if (a->w1 != b->w1) {
        return a->w1 < b->w1 ? -1 : 1;
    }
    if (a->w0 != b->w0) {
        return a->w0 < b->w0 ? -1 : 1;
    }
    return 0;
}

uint64_t ssda__div_128_64(ssda__u128_t n, uint64_t d)
{
    uint64_t rem = n.hi; /* < d throughout */
    uint64_t lo = n.lo;
    uint64_t q = 0u;
    uint32_t i;
    for (i = 0u; i < 64u; i++) {
        /* rem * 2 + next bit: 65 bits, the top one in carry */
        const uint64_t carry = rem >> 63;
        rem = (rem << 1) | (lo >> 63);
        lo <<= 1;
        q <<= 1;
        if (carry != 0u || rem >= d) {
            rem -= d; /* modulo 2^64: the true difference is < d */
            q |= 1u;
        }
    }
    return q;
}

#if !defined(__GNUC__) && !defined(__clang__)
uint32_t ssda__bitlen64(uint64_t v)
{
    uint32_t n = 0u;
    while (v != 0u) {
        v >>= 1;
        n++;
    }
    return n;
}
#endif

/* ---- sums, shifts, quotients and roots (kl_*.c, mix_*.c) ---- */

ssda__u128_t ssda__u128_from(uint64_t v)
{
    ssda__u128_t r;
    r.hi = 0u;
    r.lo = v;
    return r;
}

ssda__u128_t ssda__u128_add(ssda__u128_t a, ssda__u128_t b)
{
    ssda__u128_t r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo ? 1u : 0u);
    return r;
}

ssda__u128_t ssda__u128_sub(ssda__u128_t a, ssda__u128_t b)
{
    ssda__u128_t r;
    r.lo = a.lo - b.lo;
    r.hi = a.hi - b.hi - (a.lo < b.lo ? 1u : 0u);
    return r;
}

ssda__u128_t ssda__u128_shl(ssda__u128_t a, uint32_t s)
{
    ssda__u128_t r;
    if (s == 0u) {
        r = a;
    } else if (s >= 64u) {
        r.hi = a.lo << (s - 64u);
        r.lo = 0u;
    } else {
        r.hi = (a.hi << s) | (a.lo >> (64u - s));
        r.lo = a.lo << s;
    }
    return r;
}

ssda__u128_t ssda__u128_shr(ssda__u128_t a, uint32_t s)
{
    ssda__u128_t r;
    if (s == 0u) {
        r = a;
    } else if (s >= 64u) {
        r.lo = a.hi >> (s - 64u);
        r.hi = 0u;
    } else {
        r.lo = (a.lo >> s) | (a.hi << (64u - s));
        r.hi = a.hi >> s;
    }
    return r;
}

uint32_t ssda__u128_bits(ssda__u128_t a)
{
    return a.hi != 0u ? 64u + ssda__bitlen64(a.hi) : ssda__bitlen64(a.lo);
}

ssda__u128_t ssda__u128_div(ssda__u128_t n, ssda__u128_t d)
{
    ssda__u128_t q = ssda__u128_from(0u);
    ssda__u128_t rem = ssda__u128_from(0u);
    uint32_t i = ssda__u128_bits(n);
    if (d.hi == 0u && d.lo == 0u) {
        q.hi = UINT64_MAX;
        q.lo = UINT64_MAX;
        return q;
    }
    while (i > 0u) {
        i--;
        /* rem * 2 + next bit: rem <= n >> (i + 1) < 2^127, so no carry */
        rem = ssda__u128_shl(rem, 1u);
        rem.lo |= (i >= 64u ? (n.hi >> (i - 64u)) : (n.lo >> i)) & 1u;
        q = ssda__u128_shl(q, 1u);
        if (ssda__cmp_128(rem, d) >= 0) {
            rem = ssda__u128_sub(rem, d);
            q.lo |= 1u;
        }
    }
    return q;
}

uint64_t ssda__u128_isqrt(ssda__u128_t a)
{
    ssda__u128_t rem = a;
    ssda__u128_t root = ssda__u128_from(0u);
    uint32_t b = ssda__u128_bits(a);
    ssda__u128_t bit;
    if (b == 0u) {
        return 0u;
    }
    /* the highest power of 4 <= a */
    bit = ssda__u128_shl(ssda__u128_from(1u), (b - 1u) & ~1u);
    while (bit.hi != 0u || bit.lo != 0u) {
        const ssda__u128_t trial = ssda__u128_add(root, bit);
        if (ssda__cmp_128(rem, trial) >= 0) {
            rem = ssda__u128_sub(rem, trial);
            root = ssda__u128_add(ssda__u128_shr(root, 1u), bit);
        } else {
            root = ssda__u128_shr(root, 1u);
        }
        bit = ssda__u128_shr(bit, 2u);
    }
    return root.lo; /* sqrt(2^128 - 1) < 2^64 */
}

uint64_t ssda__u128_sat64(ssda__u128_t a)
{
    return a.hi != 0u ? UINT64_MAX : a.lo;
}

int64_t ssda__round_shift(int64_t v, uint32_t s)
{
    const uint32_t s1 = s - 1u;
    const uint64_t half = (uint64_t)1u << s1;
    uint64_t q;
    if (v >= 0) {
        q = ((uint64_t)v + half) >> s;
        return (int64_t)q;
    }
    /* -(v + 1) + 1 = |v| without negating INT64_MIN */
    q = (uint64_t)(-(v + 1));
    q = (q + 1u + half) >> s;
    return -(int64_t)q;
}
