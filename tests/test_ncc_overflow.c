/*
 * test_ncc_overflow.c - the correlation search's accumulators at their worst
 * cases (ncc.h, SIZES): windows of SSDA_NCC_MAX_PIXELS 16-bit samples at
 * 0 and 65535 (the largest |num| and variances, num^2 * var near 2^186),
 * nearly all-max windows and areas (the largest products, Saw near 2^48,
 * n * Saw near 2^64), the widest and tallest shapes, and the size limit.
 * Every rho is checked against the double-precision reference.
 */
#include <string.h>
#include "unity.h"
#include "ssda/ncc.h"
#include "test_ncc_ref.h"

void setUp(void) {}
void tearDown(void) {}

#define SIDE 256u /* 256 x 256 = SSDA_NCC_MAX_PIXELS */
#define AWID (SIDE + 2u)
#define AHEI (SIDE + 1u)
static uint16_t g_area[AHEI][AWID];
static uint16_t g_win[SIDE][SIDE];
static uint64_t g_work[(SSDA_NCC_WORK_SIZE(AWID, SIDE, SIDE) + 7u) / 8u];

static ssda_ncc_config_t config(uint8_t metric, uint8_t flags)
{
    ssda_ncc_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.metric = metric;
    cfg.flags = flags;
    cfg.work = g_work;
    cfg.work_size = sizeof g_work;
    return cfg;
}

static void check_q30(const ssda_view_t *a, const ssda_view_t *w, uint32_t x, uint32_t y,
                      int32_t got)
{
    int64_t d = test_ncc_q30(a, w, x, y) - got;
    TEST_ASSERT_TRUE_MESSAGE(d >= -1 && d <= 1, "rho_q30 against the double reference");
}

/* Search in every mode; the best must be the reference's, with its rho. */
static void search_all(const ssda_view_t *a, const ssda_view_t *w, uint32_t ex, uint32_t ey,
                       uint8_t metric, int32_t expect_q30)
{
    uint8_t f;
    uint32_t rx = 0, ry = 0;
    test_ncc_best(a, w, metric == SSDA_NCC_ABS, 0, 0, -1, &rx, &ry);
    for (f = 0; f < 2u; f++) {
        ssda_ncc_config_t cfg = config(metric, f != 0u ? SSDA_NCC_FULL : SSDA_NCC_AROUND);
        ssda_ncc_result_t res;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(a, w, &cfg, &res));
        TEST_ASSERT_EQUAL_UINT16(rx, res.x);
        TEST_ASSERT_EQUAL_UINT16(ry, res.y);
        TEST_ASSERT_EQUAL_UINT16(ex, res.x);
        TEST_ASSERT_EQUAL_UINT16(ey, res.y);
        TEST_ASSERT_EQUAL_INT32(expect_q30, res.rho_q30);
        check_q30(a, w, res.x, res.y, res.rho_q30);
    }
}

/* Left half 0, right half 65535: var_w = n^2 m^2 / 4, the largest; the
   same pattern in the area at (2, 1) gives num = var = n^2 m^2 / 4 < 2^62,
   rho = 1 exactly; inverted at (0, 0) gives rho = -1. */
static void test_halves_u16_largest_window(void)
{
    ssda_view_t a, w;
    uint32_t x, y;
    for (y = 0; y < SIDE; y++) {
        for (x = 0; x < SIDE; x++) {
            g_win[y][x] = x < SIDE / 2u ? 0u : 65535u;
        }
    }
    /* row 0 flat; below, 0 on columns 2 .. 129: the window's pattern at (2, 1) */
    for (y = 0; y < AHEI; y++) {
        for (x = 0; x < AWID; x++) {
            g_area[y][x] = (y >= 1u && x >= 2u && x < 2u + SIDE / 2u) ? 0u : 65535u;
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_area, AWID, AHEI, AWID * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, g_win, SIDE, SIDE, SIDE * 2u, SSDA_PIX_U16));
    search_all(&a, &w, 2, 1, SSDA_NCC_RHO, SSDA_NCC_ONE_Q30);
    /* the inverted pattern at (0, 0): rho = -1 */
    for (y = 0; y < AHEI; y++) {
        for (x = 0; x < AWID; x++) {
            g_area[y][x] = x < SIDE / 2u ? 65535u : 0u;
        }
    }
    search_all(&a, &w, 0, 0, SSDA_NCC_ABS, -SSDA_NCC_ONE_Q30);
}

/* All 65535 but one pixel each: the largest products (Saw near n m^2), and
   flat placements (rho 0) beside textured ones. */
static void test_nearly_all_max_u16(void)
{
    ssda_view_t a, w;
    uint32_t x, y;
    for (y = 0; y < SIDE; y++) {
        for (x = 0; x < SIDE; x++) {
            g_win[y][x] = 65535u;
        }
    }
    g_win[100][37] = 0u;
    for (y = 0; y < AHEI; y++) {
        for (x = 0; x < AWID; x++) {
            g_area[y][x] = 65535u;
        }
    }
    g_area[101][38] = 1u; /* the window's dark pixel seen from (1, 1) */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_area, AWID, AHEI, AWID * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, g_win, SIDE, SIDE, SIDE * 2u, SSDA_PIX_U16));
    /* one dark pixel in each, aligned: rho = 1 exactly (an affine copy) */
    search_all(&a, &w, 1, 1, SSDA_NCC_RHO, SSDA_NCC_ONE_Q30);
    search_all(&a, &w, 1, 1, SSDA_NCC_ABS, SSDA_NCC_ONE_Q30);
}

/* The same worst cases in 8 bits. */
static void test_halves_u8_largest_window(void)
{
    static uint8_t a8[AHEI][AWID], w8[SIDE][SIDE];
    ssda_view_t a, w;
    uint32_t x, y;
    for (y = 0; y < SIDE; y++) {
        for (x = 0; x < SIDE; x++) {
            w8[y][x] = (x + y) % 3u == 0u ? 255u : 0u;
        }
    }
    for (y = 0; y < AHEI; y++) {
        for (x = 0; x < AWID; x++) {
            a8[y][x] = (x + y) % 3u == 1u ? 255u : 0u; /* the pattern seen from (1, 0), (0, 1) */
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, a8, AWID, AHEI, AWID, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, w8, SIDE, SIDE, SIDE, SSDA_PIX_U8));
    search_all(&a, &w, 1, 0, SSDA_NCC_RHO, SSDA_NCC_ONE_Q30);
}

/* The widest window (65535 x 1) and a tall one (2 x 32768): the limits of
   rows, groups and the work size. */
static void test_widest_and_tallest_windows(void)
{
#ifndef SSDA_TEST_SMALL
    static uint16_t wide_a[2][65535], wide_w[65535];
    static uint16_t tall_a[32769][3];
    static uint64_t work[(SSDA_NCC_WORK_SIZE(3, 2, 32768) + 7u) / 8u];
    ssda_view_t a, w;
    ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, 0);
    ssda_ncc_result_t res;
    uint32_t i;
    for (i = 0; i < 65535u; i++) {
        wide_w[i] = (uint16_t)(i % 7u == 0u ? 65535u : i * 3u);
        wide_a[0][i] = (uint16_t)(65535u - wide_w[i]);
        wide_a[1][i] = wide_w[i];
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, wide_a, 65535, 2, 65535u * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, wide_w, 65535, 1, 65535u * 2u, SSDA_PIX_U16));
    search_all(&a, &w, 0, 1, SSDA_NCC_RHO, SSDA_NCC_ONE_Q30);
    search_all(&a, &w, 0, 0, SSDA_NCC_ABS, -SSDA_NCC_ONE_Q30);
    for (i = 0; i < 32769u; i++) {
        tall_a[i][0] = (uint16_t)(i * 977u);
        tall_a[i][1] = (uint16_t)(i * 977u + 65535u / 2u);
        tall_a[i][2] = (uint16_t)(i * 977u);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, tall_a, 3, 32769, 6, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, &tall_a[1][0], 2, 32768, 6, SSDA_PIX_U16));
    cfg.work = work;
    cfg.work_size = sizeof work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&a, &w, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(0, res.x);
    TEST_ASSERT_EQUAL_UINT16(1, res.y);
    TEST_ASSERT_EQUAL_INT32(SSDA_NCC_ONE_Q30, res.rho_q30);
#endif
}

/* Windows above SSDA_NCC_MAX_PIXELS are refused. */
static void test_size_limit(void)
{
    ssda_view_t a, w;
    ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, 0);
    ssda_ncc_result_t res;
    int32_t rho;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_area, AWID, AHEI, AWID * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, g_area, SIDE + 1u, SIDE, AWID * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_ncc_match(&a, &w, &cfg, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_ncc_at(&a, &w, 0, 0, &rho));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, g_area, SIDE, SIDE, AWID * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&a, &w, &cfg, &res));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_halves_u16_largest_window);
    RUN_TEST(test_nearly_all_max_u16);
    RUN_TEST(test_halves_u8_largest_window);
    RUN_TEST(test_widest_and_tallest_windows);
    RUN_TEST(test_size_limit);
    return UNITY_END();
}
