/*
 * test_poly.c - polynomial maps: the domain and identity of
 * ssda_poly_init, and ssda_poly_eval against the definition in poly.h
 * (floor(256 x) of the real polynomial): exactly, with 128-bit integers
 * where the compiler has them, and against double precision everywhere.
 */
#include <string.h>
#include "unity.h"
#include "ssda/poly.h"
#include "test_lsq.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

static int64_t rand_i64(test_rng_t *r, int bits)
{
    uint64_t v = ((uint64_t)test_rng_next(r) << 32) | test_rng_next(r);
    int64_t s = (int64_t)(v >> (64 - bits));
    return (test_rng_next(r) & 1u) ? -s : s;
}

static void test_init_domain_and_identity(void)
{
    static const struct { uint16_t w; int32_t cx; uint8_t kx; } cases[] = {
        {1, 0, 0}, {2, 1, 0}, {3, 1, 0}, {4, 2, 1}, {5, 2, 1}, {1000, 500, 9},
        {1024, 512, 9}, {1025, 512, 9}, {1026, 513, 10}, {20000, 10000, 14}, {65535, 32767, 15}};
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ssda_poly_t p;
        int32_t u, v, x;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&p, cases[i].w, 7, 1));
        TEST_ASSERT_EQUAL_INT32(cases[i].cx, p.cx);
        TEST_ASSERT_EQUAL_UINT8(cases[i].kx, p.kx);
        /* every grid column within the domain: |X - cx| <= 2^kx */
        TEST_ASSERT_TRUE(cases[i].cx <= (1 << p.kx) && cases[i].w - 1 - cases[i].cx <= (1 << p.kx));
        for (x = 0; x < cases[i].w; x += 1 + cases[i].w / 17) {
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_eval(&p, x, 3, &u, &v));
            TEST_ASSERT_EQUAL_INT32(x * 256, u);
            TEST_ASSERT_EQUAL_INT32(3 * 256, v);
        }
    }
}

static void test_init_errors(void)
{
    ssda_poly_t p;
    memset(&p, 0x5A, sizeof p);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_poly_init(NULL, 4, 4, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_init(&p, 0, 4, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_init(&p, 4, 0, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_init(&p, 4, 4, 0));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_init(&p, 4, 4, 4));
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &p, sizeof p);
}

#if defined(__SIZEOF_INT128__)
/* floor(256 x) from poly.h's formula in __int128 (a second, independent
   integer evaluation: each term's exact rational value over a common
   denominator 2^72). */
static int32_t exact_q8(const ssda_poly_t *p, const int64_t *c, int32_t X, int32_t Y)
{
    static const unsigned ex[10] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0};
    static const unsigned ey[10] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3};
    __int128 sum = 0;
    unsigned t;
    for (t = 0; t < SSDA_POLY_TERMS(p->order); t++) {
        __int128 m = c[t];
        unsigned e;
        for (e = 0; e < ex[t]; e++) m *= (X - p->cx);
        for (e = 0; e < ey[t]; e++) m *= (Y - p->cy);
        /* term = c / 2^24 * dx^i dy^j / 2^(i kx + j ky); times 256 * 2^64 */
        sum += m * ((__int128)1 << (48 - ex[t] * p->kx - ey[t] * p->ky));
    }
    /* floor division by 2^64 */
    return (int32_t)(sum >= 0 ? sum >> 64 : -((-sum + (((__int128)1 << 64) - 1)) >> 64));
}
#endif

/* Random maps of every order on assorted grids: eval equals the formula
   exactly (int128 hosts) and matches double precision to 1e-6 px. */
static void test_eval_random_maps(void)
{
    test_rng_t r;
    int trial;
    test_rng_seed(&r, 0x504F4C59u);
    for (trial = 0; trial < 300; trial++) {
        ssda_poly_t p;
        const uint16_t w = (uint16_t)test_rng_range(&r, 1, 65535);
        const uint16_t h = (uint16_t)test_rng_range(&r, 1, trial % 3 == 0 ? 65535 : 3000);
        const uint8_t order = (uint8_t)(1 + trial % 3);
        unsigned t, k;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&p, w, h, order));
        for (t = 0; t < SSDA_POLY_TERMS(order); t++) {
            /* coefficients up to 2^(24+14) px: maps that leave int32 q8
               sometimes (overflow path) */
            p.u_q24[t] += rand_i64(&r, (int)(10 + test_rng_next(&r) % 30));
            p.v_q24[t] += rand_i64(&r, (int)(10 + test_rng_next(&r) % 30));
        }
        for (k = 0; k < 40; k++) {
            const int32_t X = (int32_t)test_rng_range(&r, 0, w - 1u);
            const int32_t Y = (int32_t)test_rng_range(&r, 0, h - 1u);
            double xd, yd;
            int32_t u = 0x12345, v = 0x12345;
            int err = ssda_poly_eval(&p, X, Y, &u, &v);
            test_poly_map(&p, X, Y, &xd, &yd);
            if (xd * 256.0 > 2147483000.0 || xd * 256.0 < -2147483000.0 ||
                yd * 256.0 > 2147483000.0 || yd * 256.0 < -2147483000.0) {
                if (err == SSDA_ERR_OVERFLOW) {
                    TEST_ASSERT_EQUAL_INT32(0x12345, u);
                }
                continue;
            }
            TEST_ASSERT_EQUAL_INT(SSDA_OK, err);
            TEST_ASSERT_TRUE(u / 256.0 <= xd + 1e-6 && xd < (u + 1) / 256.0 + 1e-6);
            TEST_ASSERT_TRUE(v / 256.0 <= yd + 1e-6 && yd < (v + 1) / 256.0 + 1e-6);
#if defined(__SIZEOF_INT128__)
            TEST_ASSERT_EQUAL_INT32(exact_q8(&p, p.u_q24, X, Y), u);
            TEST_ASSERT_EQUAL_INT32(exact_q8(&p, p.v_q24, X, Y), v);
#endif
        }
    }
}

/* Largest coefficients at the corners of the largest grid: the 128-bit
   sums hold (int128 hosts: exact), and results outside int32 overflow. */
static void test_eval_worst_case(void)
{
    ssda_poly_t p;
    int32_t u, v;
    unsigned t;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&p, 65535, 65535, 3));
    for (t = 0; t < 10; t++) {
        p.u_q24[t] = INT64_MAX;
        p.v_q24[t] = INT64_MIN;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_OVERFLOW, ssda_poly_eval(&p, 65534, 65534, &u, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_OVERFLOW, ssda_poly_eval(&p, 0, 0, &u, &v));
    /* tiny cubic terms only: the value is exact and small */
    memset(p.u_q24, 0, sizeof p.u_q24);
    memset(p.v_q24, 0, sizeof p.v_q24);
    p.u_q24[6] = (int64_t)1 << 30;  /* 64 px * xn^3 */
    p.v_q24[9] = -((int64_t)1 << 30);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_eval(&p, 65534, 0, &u, &v));
    /* xn = 32767 / 32768: 64 xn^3 = 63.9941... px */
    {
        double xn = 32767.0 / 32768.0, yn = -32767.0 / 32768.0;
        double want_u = 64.0 * xn * xn * xn * 256.0, want_v = -64.0 * yn * yn * yn * 256.0;
        TEST_ASSERT_EQUAL_INT32((int32_t)want_u, u); /* positive: truncation = floor */
        TEST_ASSERT_EQUAL_INT32((int32_t)want_v, v);
    }
}

static void test_eval_errors(void)
{
    ssda_poly_t p;
    int32_t u = 7, v = 7;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&p, 100, 50, 2));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_poly_eval(NULL, 0, 0, &u, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_poly_eval(&p, 0, 0, NULL, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_poly_eval(&p, 0, 0, &u, NULL));
    /* domain: |X - 50| <= 2 * 64, |Y - 25| <= 2 * 32 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_eval(&p, 50 + 128, 25 - 64, &u, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_eval(&p, 50 + 129, 0, &u, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_eval(&p, 50 - 129, 0, &u, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_eval(&p, 0, 25 + 65, &u, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_eval(&p, 0, 25 - 65, &u, &v));
    u = v = 7;
    p.order = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_eval(&p, 0, 0, &u, &v));
    p.order = 4;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_eval(&p, 0, 0, &u, &v));
    p.order = 2;
    p.kx = 17;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_eval(&p, 0, 0, &u, &v));
    p.kx = 6;
    p.ky = 17;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_eval(&p, 0, 0, &u, &v));
    TEST_ASSERT_EQUAL_INT32(7, u);
    TEST_ASSERT_EQUAL_INT32(7, v);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_init_domain_and_identity);
    RUN_TEST(test_init_errors);
    RUN_TEST(test_eval_random_maps);
    RUN_TEST(test_eval_worst_case);
    RUN_TEST(test_eval_errors);
    return UNITY_END();
}
