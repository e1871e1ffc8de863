#include "test_rng.h"

void test_rng_seed(test_rng_t *r, uint32_t seed)
{
    r->s = seed ? seed : 0x9E3779B9u;
}

uint32_t test_rng_next(test_rng_t *r)
{
    uint32_t x = r->s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    r->s = x;
    return x;
}

uint32_t test_rng_range(test_rng_t *r, uint32_t lo, uint32_t hi)
{
    uint32_t span = hi - lo + 1u;
    if (span == 0u) {
        return test_rng_next(r);
    }
    return lo + test_rng_next(r) % span;
}
