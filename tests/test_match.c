/*
 * test_match.c - each mode's documented behaviour, the tie rule, work
 * statistics, and argument validation of ssda_match / ssda_sad_at.
 */
#include <string.h>
#include "unity.h"
#include "ssda/match.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#define AW 48u
#define AH 40u
#define WW 12u
#define WH 10u
static uint8_t g_area[AH][AW];
static uint8_t g_win[WH][WW];
static uint32_t g_work[SSDA_MATCH_WORK_SIZE(AW, AH, WW, WH) / 4u];
static ssda_view_t g_av, g_wv;

/* Textured area, window cut from it at (wx, wy). */
static void setup_texture(uint32_t seed, uint32_t wx, uint32_t wy)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u8(&g_area[0][0], AW, AH, AW, &r);
    for (y = 0; y < WH; y++) {
        for (x = 0; x < WW; x++) {
            g_win[y][x] = g_area[wy + y][wx + x];
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_av, g_area, AW, AH, AW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_wv, g_win, WW, WH, WW, SSDA_PIX_U8));
}

static ssda_match_config_t config(uint8_t mode, uint8_t scan)
{
    ssda_match_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.threshold = mode;
    cfg.scan = scan;
    return cfg;
}

static void test_null_config_is_auto_raster_and_exact(void)
{
    ssda_match_result_t res;
    setup_texture(1u, 17u, 9u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, NULL, &res));
    TEST_ASSERT_EQUAL_UINT16(17, res.x);
    TEST_ASSERT_EQUAL_UINT16(9, res.y);
    TEST_ASSERT_EQUAL_UINT64(0, res.sad);
    TEST_ASSERT_TRUE(res.exact);
}

static void test_none_sums_every_position_in_full(void)
{
    ssda_match_config_t cfg = config(SSDA_THRESHOLD_NONE, SSDA_SCAN_RASTER);
    ssda_match_result_t res;
    const uint32_t npos = (AW - WW + 1u) * (AH - WH + 1u);
    setup_texture(2u, 3u, 30u);
    cfg.flags = SSDA_MATCH_BOUNDS; /* ignored by the reference mode */
    cfg.work = g_work;
    cfg.work_size = sizeof g_work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT32(npos, res.positions);
    TEST_ASSERT_EQUAL_UINT32(npos, res.completed);
    TEST_ASSERT_EQUAL_UINT64((uint64_t)npos * WW * WH, res.pixel_ops);
    TEST_ASSERT_EQUAL_UINT16(3, res.x);
    TEST_ASSERT_EQUAL_UINT16(30, res.y);
}

/* AUTO cuts work; prediction cuts more; bounds cut more; all the same answer. */
static void test_auto_prediction_and_bounds_reduce_work(void)
{
    ssda_match_config_t none = config(SSDA_THRESHOLD_NONE, SSDA_SCAN_RASTER);
    ssda_match_config_t aut = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER);
    ssda_match_config_t pred = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_PREDICT);
    ssda_match_config_t both = pred;
    ssda_match_result_t rn, ra, rp, rb;
    setup_texture(3u, 30u, 25u);
    pred.predict_x = 29; /* one pixel off, as a neighbour's vector would be */
    pred.predict_y = 25;
    both = pred;
    both.flags = SSDA_MATCH_BOUNDS;
    both.work = g_work;
    both.work_size = sizeof g_work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &none, &rn));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &aut, &ra));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &pred, &rp));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &both, &rb));
    TEST_ASSERT_TRUE(ra.pixel_ops < rn.pixel_ops);
    TEST_ASSERT_TRUE(rp.pixel_ops < ra.pixel_ops);
    TEST_ASSERT_TRUE(rb.pixel_ops < rp.pixel_ops);
    TEST_ASSERT_TRUE(ra.completed < rn.completed);
    TEST_ASSERT_EQUAL_UINT16(rn.x, ra.x);
    TEST_ASSERT_EQUAL_UINT16(rn.x, rp.x);
    TEST_ASSERT_EQUAL_UINT16(rn.x, rb.x);
    TEST_ASSERT_EQUAL_UINT16(rn.y, rb.y);
    TEST_ASSERT_EQUAL_UINT64(rn.sad, rb.sad);
}

/* Pixels summed by the paper's constant-threshold rule, checked after each
   row in row order (independent of the library). */
static uint32_t rows_before_cut(uint32_t x, uint32_t y, uint64_t t, uint64_t *partial)
{
    uint64_t s = 0;
    uint32_t r, i;
    for (r = 0; r < WH; r++) {
        for (i = 0; i < WW; i++) {
            int d = (int)g_area[y + r][x + i] - (int)g_win[r][i];
            s += (uint64_t)(d < 0 ? -d : d);
        }
        if (s > t) {
            *partial = s;
            return r + 1u;
        }
    }
    *partial = s;
    return WH;
}

static void test_fixed_below_minimum_falls_back_to_longest_survivor(void)
{
    ssda_match_config_t cfg = config(SSDA_THRESHOLD_FIXED, SSDA_SCAN_RASTER);
    ssda_match_result_t res;
    uint32_t x, y, bx = 0, by = 0, brows = 0;
    uint64_t bpart = 0;
    setup_texture(4u, 10u, 10u);
    g_win[0][0] ^= 0x80u; /* the minimum is no longer 0 */
    g_win[WH - 1u][WW - 1u] ^= 0x80u;
    cfg.fixed_threshold = 100u; /* below the true minimum (~256) */
    for (y = 0; y + WH <= AH; y++) {
        for (x = 0; x + WW <= AW; x++) {
            uint64_t part;
            uint32_t rows = rows_before_cut(x, y, cfg.fixed_threshold, &part);
            if (rows > brows || (rows == brows && part < bpart)) {
                brows = rows;
                bpart = part;
                bx = x;
                by = y;
            }
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT32(0, res.completed);
    TEST_ASSERT_FALSE(res.exact);
    TEST_ASSERT_EQUAL_UINT16(bx, res.x);
    TEST_ASSERT_EQUAL_UINT16(by, res.y);
    /* reported with its full SAD, not the partial one at its cut (issue 14) */
    TEST_ASSERT_TRUE(bpart < test_sad(&g_av, &g_wv, bx, by));
    TEST_ASSERT_EQUAL_UINT64(test_sad(&g_av, &g_wv, bx, by), res.sad);
    /* with T above the minimum the same search is exact */
    cfg.fixed_threshold = 300u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_TRUE(res.exact);
    TEST_ASSERT_EQUAL_UINT16(10, res.x);
    TEST_ASSERT_EQUAL_UINT16(10, res.y);
}

/* A minimum whose error sits in its first row is cut by the ramp, while
   positions with a larger error spread evenly over the rows survive it: the
   ramp misses the minimum, and says so. Area is one position high. */
static void test_ramp_can_miss_and_reports_not_exact(void)
{
    ssda_match_config_t cfg = config(SSDA_THRESHOLD_RAMP, SSDA_SCAN_RASTER);
    ssda_match_result_t res;
    uint32_t x, y, bx = 0, by = 0;
    uint64_t bsad = 0;
    memset(g_win, 50, sizeof g_win);
    memset(g_area, 80, sizeof g_area);   /* 30 per pixel everywhere: 3600 */
    for (x = 5; x < 5u + WW; x++) {
        g_area[0][x] = 250u;             /* row 0: 200 per pixel */
        for (y = 1; y < WH; y++) {
            g_area[y][x] = 50u;          /* rows 1..: exact */
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_av, g_area, AW, WH, AW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_wv, g_win, WW, WH, WW, SSDA_PIX_U8));
    test_best(&g_av, &g_wv, &bx, &by, &bsad);
    TEST_ASSERT_EQUAL_UINT32(5, bx);
    TEST_ASSERT_EQUAL_UINT64(200u * WW, bsad);
    cfg.lambda_q8 = 32u * 256u; /* expects ~32 per pixel, evenly spread */
    cfg.k_q8 = 256u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_FALSE(res.exact);
    TEST_ASSERT_TRUE(res.completed > 0u);
    TEST_ASSERT_NOT_EQUAL(5, res.x);
    TEST_ASSERT_EQUAL_UINT64(30u * WW * WH, res.sad);
    /* the paper's remedy, the automatic threshold, finds it */
    cfg.threshold = SSDA_THRESHOLD_AUTO;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_TRUE(res.exact);
    TEST_ASSERT_EQUAL_UINT16(5, res.x);
    TEST_ASSERT_EQUAL_UINT64(bsad, res.sad);
}

static void test_auto_ramp_is_flagged_inexact_and_cheaper(void)
{
    ssda_match_config_t cfg = config(SSDA_THRESHOLD_AUTO_RAMP, SSDA_SCAN_RASTER);
    ssda_match_config_t aut = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER);
    ssda_match_result_t res, ra;
    setup_texture(6u, 20u, 12u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &aut, &ra));
    TEST_ASSERT_FALSE(res.exact);
    TEST_ASSERT_TRUE(res.pixel_ops <= ra.pixel_ops);
    TEST_ASSERT_EQUAL_UINT16(20, res.x); /* an exact copy is never cut: SAD 0 */
    TEST_ASSERT_EQUAL_UINT16(12, res.y);
}

/* Smooth bowl: the SAD surface has one basin, so coarse-to-fine finds it. */
static void test_coarse_to_fine_finds_smooth_minimum(void)
{
    ssda_match_config_t cfg = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_COARSE);
    ssda_match_result_t res;
    uint32_t x, y, bx = 0, by = 0, pos = (AW - WW + 1u) * (AH - WH + 1u);
    uint64_t bsad = 0;
    for (y = 0; y < AH; y++) {
        for (x = 0; x < AW; x++) {
            int dx = (int)x - 27, dy = (int)y - 19;
            g_area[y][x] = (uint8_t)((dx * dx + dy * dy) / 8);
        }
    }
    for (y = 0; y < WH; y++) {
        for (x = 0; x < WW; x++) {
            g_win[y][x] = g_area[13u + y][19u + x];
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_av, g_area, AW, AH, AW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_wv, g_win, WW, WH, WW, SSDA_PIX_U8));
    test_best(&g_av, &g_wv, &bx, &by, &bsad);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_FALSE(res.exact);
    TEST_ASSERT_EQUAL_UINT16(bx, res.x);
    TEST_ASSERT_EQUAL_UINT16(by, res.y);
    TEST_ASSERT_EQUAL_UINT64(bsad, res.sad);
    TEST_ASSERT_TRUE(res.positions < pos / 4u);
}

/* Flat area: every position ties; the rule picks (0, 0) in every scan. */
static void test_ties_pick_smallest_y_then_x(void)
{
    uint8_t scan;
    memset(g_area, 7, sizeof g_area);
    memset(g_win, 9, sizeof g_win);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_av, g_area, AW, AH, AW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&g_wv, g_win, WW, WH, WW, SSDA_PIX_U8));
    for (scan = 0; scan < 2u; scan++) {
        ssda_match_config_t cfg = config(SSDA_THRESHOLD_AUTO, scan);
        ssda_match_result_t res;
        cfg.predict_x = 20;
        cfg.predict_y = 20;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
        TEST_ASSERT_EQUAL_UINT16(0, res.x);
        TEST_ASSERT_EQUAL_UINT16(0, res.y);
        TEST_ASSERT_EQUAL_UINT64(2u * WW * WH, res.sad);
    }
    /* two exact copies: the upper one wins even when the lower is predicted */
    setup_texture(8u, 30u, 25u);
    {
        uint32_t x, y;
        ssda_match_config_t cfg = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_PREDICT);
        ssda_match_result_t res;
        for (y = 0; y < WH; y++) {
            for (x = 0; x < WW; x++) {
                g_area[4u + y][33u + x] = g_win[y][x];
            }
        }
        cfg.predict_x = 30;
        cfg.predict_y = 25;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
        TEST_ASSERT_EQUAL_UINT16(33, res.x);
        TEST_ASSERT_EQUAL_UINT16(4, res.y);
        TEST_ASSERT_EQUAL_UINT64(0, res.sad);
    }
}

static void test_sad_at_matches_reference(void)
{
    uint64_t sad = 0;
    setup_texture(9u, 1u, 1u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_sad_at(&g_av, &g_wv, 36u, 30u, &sad));
    TEST_ASSERT_EQUAL_UINT64(test_sad(&g_av, &g_wv, 36u, 30u), sad);
    sad = 12345u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_sad_at(&g_av, &g_wv, 37u, 0u, &sad));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_sad_at(&g_av, &g_wv, 0u, 31u, &sad));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_sad_at(&g_av, &g_wv, 0u, 0u, NULL));
    TEST_ASSERT_EQUAL_UINT64(12345u, sad);
}

/* Every invalid argument: the documented error and an untouched result. */
static void test_invalid_arguments_write_nothing(void)
{
    ssda_match_config_t cfg = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER);
    ssda_match_result_t res, before;
    ssda_view_t bad;
    static uint16_t area16[AH][AW];
    ssda_view_t a16;
    setup_texture(10u, 0u, 0u);
    memset(&res, 0xAB, sizeof res);
    before = res;

    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match(NULL, &g_wv, &cfg, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match(&g_av, NULL, &cfg, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match(&g_av, &g_wv, &cfg, NULL));
    bad = g_av; bad.width = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_match(&bad, &g_wv, &cfg, &res));
    bad = g_wv; bad.height = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_match(&g_av, &bad, &cfg, &res));
    bad = g_av; bad.stride = AW - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_match(&bad, &g_wv, &cfg, &res));
    bad = g_av; bad.data = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match(&bad, &g_wv, &cfg, &res));
    bad = g_av; bad.format = 7;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_match(&bad, &g_wv, &cfg, &res));
    /* window larger than the area, in each dimension */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_match(&g_wv, &g_av, &cfg, &res));
    bad = g_wv; bad.width = AW; bad.stride = AW; bad.data = g_area; bad.height = 2;
    {
        ssda_view_t narrow = g_av;
        narrow.width = AW - 1u;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_match(&narrow, &bad, &cfg, &res));
    }
    /* formats differ */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a16, area16, AW, AH, AW * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_match(&a16, &g_wv, &cfg, &res));
    /* configuration */
    cfg.threshold = 5;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&g_av, &g_wv, &cfg, &res));
    cfg = config(SSDA_THRESHOLD_AUTO, 3);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&g_av, &g_wv, &cfg, &res));
    cfg = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER);
    cfg.order = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&g_av, &g_wv, &cfg, &res));
    cfg.order = 0;
    cfg.flags = 0x20; /* no such flag */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&g_av, &g_wv, &cfg, &res));
    cfg = config(SSDA_THRESHOLD_RAMP, SSDA_SCAN_RASTER); /* lambda 0 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&g_av, &g_wv, &cfg, &res));
    cfg = config(SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER);
    cfg.flags = SSDA_MATCH_BOUNDS;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match(&g_av, &g_wv, &cfg, &res));
    cfg.work = g_work;
    cfg.work_size = sizeof g_work - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_match(&g_av, &g_wv, &cfg, &res));
    cfg.work = (uint8_t *)g_work + 2;
    cfg.work_size = sizeof g_work - 4u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_match(&g_av, &g_wv, &cfg, &res));
    TEST_ASSERT_EQUAL_MEMORY(&before, &res, sizeof res);
    /* an area whose work passes 4 GB: 32783 x 32768 with a 16 x 16 window
       needs (2^30 + 32) * 4 bytes, which a 32-bit size_t wraps to 128; the
       search is refused before any pixel is read (the view's memory is
       never touched, so a small buffer stands in for it) */
    {
        ssda_view_t huge, w16;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&huge, g_work, 32783u, 32768u, 32783u,
                                                      SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w16, g_work, 16u, 16u, 16u, SSDA_PIX_U8));
        cfg.work = g_work;
        cfg.work_size = sizeof g_work;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_match(&huge, &w16, &cfg, &res));
        TEST_ASSERT_EQUAL_MEMORY(&before, &res, sizeof res);
    }
    /* exactly the macro's size is enough */
    cfg.work = g_work;
    cfg.work_size = SSDA_MATCH_WORK_SIZE(AW, AH, WW, WH);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&g_av, &g_wv, &cfg, &res));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_null_config_is_auto_raster_and_exact);
    RUN_TEST(test_none_sums_every_position_in_full);
    RUN_TEST(test_auto_prediction_and_bounds_reduce_work);
    RUN_TEST(test_fixed_below_minimum_falls_back_to_longest_survivor);
    RUN_TEST(test_ramp_can_miss_and_reports_not_exact);
    RUN_TEST(test_auto_ramp_is_flagged_inexact_and_cheaper);
    RUN_TEST(test_coarse_to_fine_finds_smooth_minimum);
    RUN_TEST(test_ties_pick_smallest_y_then_x);
    RUN_TEST(test_sad_at_matches_reference);
    RUN_TEST(test_invalid_arguments_write_nothing);
    return UNITY_END();
}
