/*
 * test_match_overflow.c - accumulators at their worst cases: all-0 against
 * all-max samples at the largest sizes a test can hold, across the limit of
 * every intermediate type (uint32_t row sums, uint64_t totals).
 */
#include <string.h>
#include "unity.h"
#include "ssda/match.h"

void setUp(void) {}
void tearDown(void) {}

#define W 65535u
/* Two rows of zeros and two rows of 65535, 65535 pixels each (512 KiB). */
static uint16_t g_zero[2][W];
static uint16_t g_max[2][W];
static uint32_t g_work[2048]; /* >= SSDA_MATCH_WORK_SIZE(W, 258, W, 258) and (261, 259, 257, 256) */

static void fill_max(void)
{
    uint32_t i;
    for (i = 0; i < W; i++) {
        g_max[0][i] = 65535u;
        g_max[1][i] = 65535u;
    }
}

static void check_all_modes(const ssda_view_t *area, const ssda_view_t *win, uint64_t expect)
{
    uint8_t mode;
    for (mode = 0; mode <= SSDA_THRESHOLD_AUTO_RAMP; mode++) {
        uint8_t bounds;
        for (bounds = 0; bounds < 2u; bounds++) {
            ssda_match_config_t cfg;
            ssda_match_result_t res;
            memset(&cfg, 0, sizeof cfg);
            cfg.threshold = mode;
            cfg.lambda_q8 = 0xFFFFFFFFu;   /* largest ramp: never overflows */
            cfg.k_q8 = 0xFFFFu;
            cfg.fixed_threshold = UINT64_MAX;
            if (bounds) {
                cfg.flags = SSDA_MATCH_BOUNDS;
                cfg.work = g_work;
                cfg.work_size = sizeof g_work;
            }
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(area, win, &cfg, &res));
            TEST_ASSERT_EQUAL_UINT64(expect, res.sad);
            TEST_ASSERT_EQUAL_UINT32(1, res.positions);
            TEST_ASSERT_EQUAL_UINT32(1, res.completed);
        }
    }
}

/* One row of 65535 differences of 65535: 4 294 836 225, just under 2^32. */
static void test_u16_full_row_fits_uint32(void)
{
    ssda_view_t area, win;
    uint64_t sad = 0;
    fill_max();
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, g_zero, W, 1, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, g_max, W, 1, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_sad_at(&area, &win, 0, 0, &sad));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)W * 65535u, sad);
    TEST_ASSERT_TRUE(sad < 4294967296ull);
    check_all_modes(&area, &win, (uint64_t)W * 65535u);
    /* the other sign of every difference */
    check_all_modes(&win, &area, (uint64_t)W * 65535u);
}

/* Two such rows: 8 589 672 450 > 2^32, so the total must be 64-bit. */
static void test_u16_total_crosses_2_pow_32(void)
{
    ssda_view_t area, win;
    uint64_t sad = 0;
    fill_max();
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, g_zero, W, 2, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, g_max, W, 2, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_sad_at(&area, &win, 0, 0, &sad));
    TEST_ASSERT_EQUAL_UINT64(2ull * W * 65535u, sad);
    TEST_ASSERT_TRUE(sad > 4294967295ull);
    check_all_modes(&area, &win, 2ull * W * 65535u);
}

/* Two positions, full-width sliding sums at their maximum (bounds tables). */
static void test_u16_bounds_tables_at_maximum(void)
{
    ssda_view_t area, win;
    ssda_match_config_t cfg;
    ssda_match_result_t res;
    uint32_t i;
    fill_max();
    for (i = 0; i < W; i++) {
        g_zero[0][i] = (i == 0u) ? 65535u : 0u;
    }
    /* area row: one 65535 then zeros; window: 65534 zeros. Position 1 is exact. */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, g_zero[0], W, 1, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, g_zero[1], W - 1u, 1, W * 2u, SSDA_PIX_U16));
    memset(&cfg, 0, sizeof cfg);
    cfg.flags = SSDA_MATCH_BOUNDS;
    cfg.work = g_work;
    cfg.work_size = sizeof g_work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT32(1, res.x);
    TEST_ASSERT_EQUAL_UINT64(0, res.sad);
    /* a window of 65534 maxima: position 0 covers the single 65535 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, g_max[0], W - 1u, 1, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT32(0, res.x);
    TEST_ASSERT_EQUAL_UINT64((uint64_t)(W - 2u) * 65535u, res.sad);
    g_zero[0][0] = 0u;
}

/* Bounds that pass 2^32: a 16-bit window of 257 x 256 pixels (group terms
   up to 4 * 257 * 65535, their sum up to 256 * 257 * 65535 > 2^32, summed
   in 64 bits). Against brute force, in both exact scans; with the
   prediction on the answer, every other position is rejected by its bound
   alone (a steep ramp makes every group sum differ). */
#define BW 257u
#define BH 256u
#define BAW (BW + 4u) /* 5 x 4 positions */
#define BAH (BH + 3u)
static void test_u16_bounds_beyond_32_bits(void)
{
    uint16_t *a = &g_zero[0][0]; /* BAW * BAH = 67 599 <= 2 * W samples */
    uint16_t *w = &g_max[0][0];
    ssda_view_t area, win;
    ssda_match_config_t cfg;
    ssda_match_result_t brute, res;
    uint32_t x, y;
    uint8_t scan;
    for (y = 0; y < BAH; y++) {
        for (x = 0; x < BAW; x++) {
            a[y * BAW + x] = (uint16_t)(x * 251u + y * 7u + (x * y) % 5u);
        }
    }
    for (y = 0; y < BH; y++) {
        for (x = 0; x < BW; x++) {
            w[y * BW + x] = a[(y + 2u) * BAW + x + 3u];
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, a, BAW, BAH, BAW * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, w, BW, BH, BW * 2u, SSDA_PIX_U16));
    memset(&cfg, 0, sizeof cfg);
    cfg.threshold = SSDA_THRESHOLD_NONE;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &brute));
    TEST_ASSERT_EQUAL_UINT32(3, brute.x);
    TEST_ASSERT_EQUAL_UINT32(2, brute.y);
    TEST_ASSERT_EQUAL_UINT64(0, brute.sad);
    TEST_ASSERT_TRUE(SSDA_MATCH_WORK_SIZE(BAW, BAH, BW, BH) <= sizeof g_work);
    for (scan = SSDA_SCAN_RASTER; scan <= SSDA_SCAN_PREDICT; scan++) {
        memset(&cfg, 0, sizeof cfg);
        cfg.scan = scan;
        cfg.predict_x = 3;
        cfg.predict_y = 2;
        cfg.flags = SSDA_MATCH_BOUNDS;
        cfg.work = g_work;
        cfg.work_size = sizeof g_work;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
        TEST_ASSERT_EQUAL_UINT32(brute.x, res.x);
        TEST_ASSERT_EQUAL_UINT32(brute.y, res.y);
        TEST_ASSERT_EQUAL_UINT64(brute.sad, res.sad);
        TEST_ASSERT_TRUE(res.exact);
        TEST_ASSERT_EQUAL_UINT32(20, res.positions);
        TEST_ASSERT_TRUE(res.pixel_ops < brute.pixel_ops);
        if (scan == SSDA_SCAN_PREDICT) {
            /* one full sum, the tables and 19 bound checks */
            TEST_ASSERT_EQUAL_UINT32(1, res.completed);
            TEST_ASSERT_TRUE(res.pixel_ops < brute.pixel_ops / 4u);
        }
    }
    memset(g_zero, 0, sizeof g_zero);
}

#ifndef SSDA_TEST_SMALL
/* 8-bit: 65535 x 258 pixels of difference 255 = 4 311 640 350 > 2^32. */
#define H8 258u
static uint8_t g_z8[H8][W];
static uint8_t g_m8[H8][W];

static void test_u8_total_crosses_2_pow_32(void)
{
    ssda_view_t area, win;
    uint64_t sad = 0;
    memset(g_m8, 255, sizeof g_m8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, g_z8, W, H8, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, g_m8, W, H8, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_sad_at(&area, &win, 0, 0, &sad));
    TEST_ASSERT_EQUAL_UINT64(255ull * W * H8, sad);
    TEST_ASSERT_TRUE(sad > 4294967295ull);
    check_all_modes(&area, &win, 255ull * W * H8);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_u16_full_row_fits_uint32);
    RUN_TEST(test_u16_total_crosses_2_pow_32);
    RUN_TEST(test_u16_bounds_tables_at_maximum);
    RUN_TEST(test_u16_bounds_beyond_32_bits);
#ifndef SSDA_TEST_SMALL
    RUN_TEST(test_u8_total_crosses_2_pow_32);
#endif
    return UNITY_END();
}
