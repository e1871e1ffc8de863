/* fixmath.c - integer square root and a wide multiply-shift. */
#include "fixmath.h"

uint32_t ssda_isqrt64(uint64_t v)
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

uint64_t ssda_mul_shr24(uint32_t a, uint64_t b)
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
