/* fixmath.c - integer square root and a wide multiply-shift. */
#include "fixmath.h"

uint32_t ssda__isqrt64(uint64_t v)
{
    uint64_t rem = v;
    uint64_t root = 0u;
    uint64_t bit = (uint64_t)1u << 62;
    while (bit > rem) {
        bit >>= 2;
    }
    while (bit != 0u) {
        if (rem >= root + bit) {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)root; /* sqrt(2^64 - 1) < 2^32 */
}

uint64_t ssda__mul_shr24(uint32_t a, uint64_t b)
{
    uint64_t bh = b >> 24;
    uint64_t bl = b & 0xFFFFFFu;
    uint64_t hi;
    if (bh > 0xFFFFFFFFu) {
        return UINT64_MAX;
    }
    hi = (uint64_t)a * bh;                      /* < 2^64 */
    return hi + (((uint64_t)a * bl) >> 24);     /* a*bl < 2^56; sum < 2^64 - 2^32 + 2^32 */
}

uint64_t ssda__mul_u32_u32(uint32_t a, uint32_t b)
{
    const uint32_t al = a & 0xFFFFu, ah = a >> 16;
    const uint32_t bl = b & 0xFFFFu, bh = b >> 16;
    /* each product < 2^32; the sum is the exact product < 2^64 */
    const uint32_t hh = ah * bh, ll = al * bl, hl = ah * bl, lh = al * bh;
    uint64_t r = ((uint64_t)hh << 32) | ll;
    r += (uint64_t)hl << 16;
    r += (uint64_t)lh << 16;
    return r;
}

uint32_t ssda__div64_32(uint64_t n, uint32_t d)
{
    uint32_t rem = (uint32_t)(n >> 32); /* the remainder, < d once started */
    uint32_t lo = (uint32_t)n;
    uint32_t q = 0u;
    uint32_t i;
    if (rem >= d) {
        return UINT32_MAX; /* the quotient needs more than 32 bits */
    }
    for (i = 0u; i < 32u; i++) {
        /* rem * 2 + next bit: 33 bits, the top one in carry */
        uint32_t carry = rem >> 31;
        rem = (rem << 1) | (lo >> 31);
        lo <<= 1;
        q <<= 1;
        if (carry != 0u || rem >= d) {
            rem -= d; /* modulo 2^32: the true difference is < d */
            q |= 1u;
        }
    }
    return q;
}
