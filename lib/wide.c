/* wide.c - 128- and 192-bit unsigned products and comparisons (wide.h). */
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
