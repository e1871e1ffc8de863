/*
 * test_fixexp.c - the fixed-point exp(-x) and ln(v) of lib/fixexp.c against
 * libm's double exp and log, over their whole domain (every 7th Q16
 * argument of exp up to 25 nats; ln at every power of two, its neighbours,
 * and random values of every magnitude), with the documented bounds:
 * exp within 2 Q30 steps, ln within 1 Q24 step (plus 2^-31 relative above
 * 2^32). The measured worst errors are printed.
 */
#include <math.h>
#include <stdio.h>
#include "unity.h"
#include "fixexp.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef SSDA_TEST_SMALL
#define EXP_STEP 997u
#define LN_RANDOM 2000u
#else
#define EXP_STEP 7u
#define LN_RANDOM 200000u
#endif

static double g_exp_worst, g_ln_worst;

static void check_exp(uint32_t x)
{
    const double want = exp(-(double)x / 65536.0) * 1073741824.0;
    const double err = fabs((double)ssda__exp_neg_q16(x) - want);
    if (err > g_exp_worst) {
        g_exp_worst = err;
    }
    if (err > 2.0) {
        char msg[96];
        snprintf(msg, sizeof msg, "exp(-%u/65536): got %u, want %.3f", (unsigned)x,
                 (unsigned)ssda__exp_neg_q16(x), want);
        TEST_FAIL_MESSAGE(msg);
    }
}

static void test_exp_domain(void)
{
    uint32_t x;
    char msg[80];
    for (x = 0u; x < 25u * 65536u; x += EXP_STEP) {
        check_exp(x);
    }
    /* the exact ends, the table steps and the largest arguments */
    check_exp(0u);
    check_exp(1u);
    for (x = 1u; x <= 64u; x++) {
        check_exp(x * 65536u / 16u);
        check_exp(x * 65536u / 16u - 1u);
    }
    check_exp(UINT32_MAX);
    check_exp(UINT32_MAX / 2u);
    TEST_ASSERT_EQUAL_UINT32(1073741824u, ssda__exp_neg_q16(0u));
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__exp_neg_q16(UINT32_MAX));
    snprintf(msg, sizeof msg, "exp: worst error %.3f Q30 steps", g_exp_worst);
    printf("%s\n", msg);
}

static void check_ln(uint64_t v)
{
    const double want = log((double)v) * 16777216.0;
    const double got = (double)ssda__ln_q24(v);
    /* the input truncation above 2^32 costs up to 2^-31 relative: 2^-7 Q24 */
    const double err = fabs(got - want);
    if (err > g_ln_worst) {
        g_ln_worst = err;
    }
    if (err > 1.0) {
        char msg[96];
        snprintf(msg, sizeof msg, "ln(%llu): got %.0f, want %.3f", (unsigned long long)v, got, want);
        TEST_FAIL_MESSAGE(msg);
    }
}

static void test_ln_domain(void)
{
    test_rng_t r;
    uint32_t i;
    char msg[80];
    TEST_ASSERT_EQUAL_INT32(INT32_MIN, ssda__ln_q24(0u));
    TEST_ASSERT_EQUAL_INT32(0, ssda__ln_q24(1u));
    for (i = 0u; i < 64u; i++) {
        const uint64_t p = (uint64_t)1u << i;
        check_ln(p);
        check_ln(p + 1u);
        check_ln(p | (p - 1u));
        if (p > 2u) {
            check_ln(p - 1u);
        }
    }
    check_ln(UINT64_MAX);
    for (i = 1u; i < 5000u; i++) {
        check_ln(i);
    }
    test_rng_seed(&r, 4242u);
    for (i = 0u; i < LN_RANDOM; i++) {
        const uint64_t v = (((uint64_t)test_rng_next(&r) << 32) | test_rng_next(&r)) >>
                           (test_rng_next(&r) % 64u);
        if (v != 0u) {
            check_ln(v);
        }
    }
    snprintf(msg, sizeof msg, "ln: worst error %.3f Q24 steps", g_ln_worst);
    printf("%s\n", msg);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exp_domain);
    RUN_TEST(test_ln_domain);
    return UNITY_END();
}
