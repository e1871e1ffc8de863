/*
 * test_fixtrig.c - the internal fixed-point trigonometry of the symbolic
 * registration (lib/fixtrig.h) against double-precision references
 * computed here (tests/support/test_signal.c's sin, cos, atan2), and the
 * signed shifts against integer division.
 */
#include <stdio.h>
#include "unity.h"
#include "fixtrig.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef SSDA_TEST_SMALL
#define ANGLE_STEP_LOG2 20u /* 4096 angles */
#define RANDOM_VECTORS 2000u
#else
#define ANGLE_STEP_LOG2 14u /* 262144 angles */
#define RANDOM_VECTORS 200000u
#endif

static double turns_to_rad(uint32_t t)
{
    return (double)t * (2.0 * TEST_PI / 4294967296.0);
}

/* signed difference of two angles in turns, as a double */
static double turn_diff(uint32_t a, uint32_t b)
{
    const uint32_t d = a - b;
    return d < 0x80000000u ? (double)d : -(double)(0u - d);
}

static void test_sin_cos_within_two_lsb(void)
{
    uint32_t i, worst = 0u;
    for (i = 0u; i < (1u << (32u - ANGLE_STEP_LOG2)); i++) {
        const uint32_t a = (i << ANGLE_STEP_LOG2) + (i * 2654435761u >> (32u - ANGLE_STEP_LOG2));
        const double r = turns_to_rad(a);
        const double es = (double)ssda__sin_q15(a) - 32768.0 * test_sin(r);
        const double ec = (double)ssda__cos_q15(a) - 32768.0 * test_cos(r);
        const uint32_t e = (uint32_t)((es < 0 ? -es : es) > (ec < 0 ? -ec : ec)
                                          ? (es < 0 ? -es : es) + 0.5
                                          : (ec < 0 ? -ec : ec) + 0.5);
        worst = e > worst ? e : worst;
        TEST_ASSERT_TRUE(es <= 2.0 && es >= -2.0);
        TEST_ASSERT_TRUE(ec <= 2.0 && ec >= -2.0);
    }
    TEST_ASSERT_TRUE(worst >= 1u); /* the table is not exact: the check can fail */
    /* the axes exactly */
    TEST_ASSERT_EQUAL_INT32(32768, ssda__cos_q15(0u));
    TEST_ASSERT_EQUAL_INT32(0, ssda__sin_q15(0u));
    TEST_ASSERT_EQUAL_INT32(32768, ssda__sin_q15(0x40000000u));
    TEST_ASSERT_EQUAL_INT32(-32768, ssda__cos_q15(0x80000000u));
    TEST_ASSERT_EQUAL_INT32(-32768, ssda__sin_q15(0xC0000000u));
}

static void check_atan2(int64_t y, int64_t x)
{
    const double want = test_atan2((double)y, (double)x) / (2.0 * TEST_PI) * 4294967296.0;
    const uint32_t got = ssda__atan2(y, x);
    const uint32_t want_u = (uint32_t)(int64_t)(want < 0 ? want + 4294967296.0 + 0.5 : want + 0.5);
    const double e = turn_diff(got, want_u);
    if (e > 1024.0 || e < -1024.0) { /* 2^-22 turn */
        char msg[96];
        snprintf(msg, sizeof msg, "atan2(%lld, %lld) off by %.0f", (long long)y, (long long)x, e);
        TEST_FAIL_MESSAGE(msg);
    }
}

/* fourier_match.c sums the orders k and -k with one cos and one sin: that
   is exact only if cos is even and sin odd to the last bit, at every angle
   (the mirrored quarter table makes them so; an unmirrored or rounded
   table would not be). The quadrant edges and every table step's ends are
   among the angles. */
static void test_sin_cos_exactly_even_and_odd(void)
{
    uint32_t i, e;
    for (i = 0u; i < (1u << (32u - ANGLE_STEP_LOG2)); i++) {
        const uint32_t a = (i << ANGLE_STEP_LOG2) + (i * 2654435761u >> (32u - ANGLE_STEP_LOG2));
        TEST_ASSERT_EQUAL_INT32(ssda__cos_q15(a), ssda__cos_q15(0u - a));
        TEST_ASSERT_EQUAL_INT32(-ssda__sin_q15(a), ssda__sin_q15(0u - a));
    }
    for (i = 0u; i < 512u; i++) { /* table steps (2^23) and one unit either side */
        for (e = 0u; e < 3u; e++) {
            const uint32_t a = (i << 23) + e - 1u;
            TEST_ASSERT_EQUAL_INT32(ssda__cos_q15(a), ssda__cos_q15(0u - a));
            TEST_ASSERT_EQUAL_INT32(-ssda__sin_q15(a), ssda__sin_q15(0u - a));
        }
    }
}

static void test_atan2_against_double(void)
{
    test_rng_t r;
    uint32_t i;
    test_rng_seed(&r, 17u);
    for (i = 0u; i < RANDOM_VECTORS; i++) {
        /* magnitudes from 1 to 2^62, any signs */
        const uint32_t bits = test_rng_range(&r, 0u, 62u);
        const int64_t m = (int64_t)1 << bits;
        int64_t x = (int64_t)(((uint64_t)test_rng_next(&r) << 31) % (uint64_t)m);
        int64_t y = (int64_t)(((uint64_t)test_rng_next(&r) << 31) % (uint64_t)m);
        x = (test_rng_next(&r) & 1u) != 0u ? -x : x;
        y = (test_rng_next(&r) & 1u) != 0u ? -y : y;
        check_atan2(y, x);
    }
    /* axes, diagonals, extremes */
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__atan2(0, 0));
    check_atan2(0, 5);
    check_atan2(1, 0);
    check_atan2(0, -1);
    check_atan2(-1, 0);
    check_atan2(1, 1);
    check_atan2(-3, -3);
    check_atan2(INT64_MAX, INT64_MAX);
    check_atan2(INT64_MIN, 1);
    check_atan2(1, INT64_MIN);
    check_atan2(INT64_MIN, INT64_MIN);
    check_atan2(0, INT64_MIN);
}

static void test_shifts_against_division(void)
{
    static const int64_t values[] = {0, 1, -1, 2, -2, 3, -3, 255, -255, 256, -256, 257, -257,
                                     INT64_MAX, INT64_MIN, INT64_MIN + 1, -1000001, 1000001};
    uint32_t i, s;
    for (i = 0u; i < sizeof values / sizeof values[0]; i++) {
        for (s = 0u; s < 63u; s++) {
            const int64_t v = values[i];
            /* floor division: C99 truncates toward zero */
            const int64_t d = (int64_t)((uint64_t)1u << s);
            int64_t fl = v / d;
            if ((v % d) != 0 && v < 0) {
                fl -= 1;
            }
            TEST_ASSERT_TRUE(ssda__asr64(v, s) == fl);
            if (s >= 1u && v != INT64_MIN && v != INT64_MAX && v != INT64_MIN + 1) {
                /* nearest, halves away from zero */
                const int64_t q = v / d, rem = v % d;
                const int64_t arem = rem < 0 ? -rem : rem;
                int64_t want = q;
                if (2 * arem >= d) {
                    want += v < 0 ? -1 : 1;
                }
                TEST_ASSERT_TRUE(ssda__rshr64(v, s) == want);
            }
        }
    }
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__bitlen64(0u));
    TEST_ASSERT_EQUAL_UINT32(1u, ssda__bitlen64(1u));
    TEST_ASSERT_EQUAL_UINT32(64u, ssda__bitlen64(UINT64_MAX));
    TEST_ASSERT_TRUE(ssda__abs64(INT64_MIN) == (uint64_t)1u << 63);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sin_cos_within_two_lsb);
    RUN_TEST(test_sin_cos_exactly_even_and_odd);
    RUN_TEST(test_atan2_against_double);
    RUN_TEST(test_shifts_against_division);
    return UNITY_END();
}
