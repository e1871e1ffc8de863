/* test_rng.h - deterministic pseudo-random numbers for tests (xorshift32). */
#ifndef SSDA_TEST_RNG_H
#define SSDA_TEST_RNG_H
#include <stdint.h>

typedef struct { uint32_t s; } test_rng_t;

void test_rng_seed(test_rng_t *r, uint32_t seed);
uint32_t test_rng_next(test_rng_t *r);
/* Uniform in [lo, hi] (inclusive), hi >= lo. */
uint32_t test_rng_range(test_rng_t *r, uint32_t lo, uint32_t hi);

#endif
