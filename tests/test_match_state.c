/*
 * test_match_state.c - ssda_match_search, the search with its state in the
 * caller's ssda_match_state_t: every bad input returns ssda_match's error
 * and leaves both the result and the state untouched (poisoned and
 * compared byte for byte); one state serves searches of any geometry,
 * format and option one after another, on the stack or in static storage,
 * with the results of ssda_match and of the brute force computed here; the
 * documented size of the state. (The property tests run every search
 * through both entries too: test_match_both.h.)
 */
#include <string.h>
#include "unity.h"
#include "ssda/match.h"
#include "test_image.h"
#include "test_match_both.h"

void setUp(void) {}
void tearDown(void) {}

#define AW 48u
#define AH 40u
#define WW 16u
#define WH 12u

static uint16_t g_area[AW * AH];
static uint16_t g_win[WW * WH];
static uint32_t g_work[(SSDA_MATCH_WORK_SIZE_BLOCKS(AW, AH, WW, WH) + 3u) / 4u];
static ssda_match_state_t g_state;

/* area and window (window cut from the area at (21, 17), one pixel off) */
static void make_views(ssda_pixfmt_t fmt, ssda_view_t *area, ssda_view_t *win)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, 99u);
    if (fmt == SSDA_PIX_U8) {
        uint8_t *a = (uint8_t *)g_area, *w = (uint8_t *)g_win;
        test_fill_texture_u8(a, AW, AH, AW, &r);
        for (y = 0; y < WH; y++) {
            for (x = 0; x < WW; x++) {
                w[y * WW + x] = a[(17u + y) * AW + 21u + x];
            }
        }
        w[3] = (uint8_t)(w[3] ^ 1u);
    } else {
        test_fill_texture_u16(g_area, AW, AH, AW, 4095u, &r);
        for (y = 0; y < WH; y++) {
            for (x = 0; x < WW; x++) {
                g_win[y * WW + x] = g_area[(17u + y) * AW + 21u + x];
            }
        }
        g_win[3] = (uint16_t)(g_win[3] ^ 1u);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(area, g_area, AW, AH, AW * (uint32_t)fmt, fmt));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(win, g_win, WW, WH, WW * (uint32_t)fmt, fmt));
}

/* The documented size: SSDA_MATCH_STATE_PTRS pointers and
   SSDA_MATCH_STATE_WORDS 64-bit words, 280 bytes where pointers are 4. */
static void test_state_size_is_documented(void)
{
    TEST_ASSERT_EQUAL_UINT32((uint32_t)(SSDA_MATCH_STATE_PTRS * sizeof(void *) +
                                        SSDA_MATCH_STATE_WORDS * sizeof(uint64_t)),
                             (uint32_t)sizeof(ssda_match_state_t));
    if (sizeof(void *) == 4u) {
        TEST_ASSERT_EQUAL_UINT32(280u, (uint32_t)sizeof(ssda_match_state_t));
    } else if (sizeof(void *) == 8u) {
        TEST_ASSERT_EQUAL_UINT32(368u, (uint32_t)sizeof(ssda_match_state_t));
    }
}

/* One bad call: the error expected, ssda_match's too; the poisoned result
   and state unchanged. */
static void check_refused(int want, const ssda_view_t *area, const ssda_view_t *win,
                          const ssda_match_config_t *cfg, const char *what)
{
    static ssda_match_state_t before;
    ssda_match_result_t res, poison;
    memset(&g_state, 0xA5, sizeof g_state);
    memcpy(&before, &g_state, sizeof before);
    memset(&poison, 0xC3, sizeof poison);
    res = poison;
    TEST_ASSERT_EQUAL_INT_MESSAGE(want, ssda_match_search(&g_state, area, win, cfg, &res), what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&poison, &res, sizeof res, what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&before, &g_state, sizeof g_state, what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(want, ssda_match(area, win, cfg, &res), what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&poison, &res, sizeof res, what);
}

static ssda_match_config_t bounds_cfg(void)
{
    ssda_match_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.flags = SSDA_MATCH_BOUNDS;
    cfg.work = g_work;
    cfg.work_size = sizeof g_work;
    return cfg;
}

static void test_bad_inputs_change_nothing(void)
{
    ssda_view_t area, win, bad, other;
    ssda_match_config_t cfg;
    ssda_match_result_t res;
    make_views(SSDA_PIX_U8, &area, &win);
    /* NULL pointers: nothing is written (the result's own NULL included) */
    memset(&res, 0xC3, sizeof res);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match_search(NULL, &area, &win, NULL, &res));
    check_refused(SSDA_ERR_NULL, NULL, &win, NULL, "area NULL");
    check_refused(SSDA_ERR_NULL, &area, NULL, NULL, "window NULL");
    memset(&g_state, 0xA5, sizeof g_state);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match_search(&g_state, &area, &win, NULL, NULL));
    /* views */
    bad = area;
    bad.data = NULL;
    check_refused(SSDA_ERR_NULL, &bad, &win, NULL, "area data NULL");
    bad = area;
    bad.width = 0u;
    check_refused(SSDA_ERR_SIZE, &bad, &win, NULL, "area width 0");
    bad = win;
    bad.stride = WW - 1u;
    check_refused(SSDA_ERR_STRIDE, &area, &bad, NULL, "window stride");
    bad = win;
    bad.format = 3u;
    check_refused(SSDA_ERR_FORMAT, &area, &bad, NULL, "window format 3");
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&other, g_win, WW / 2u, WH, WW, SSDA_PIX_U16));
    check_refused(SSDA_ERR_FORMAT, &area, &other, NULL, "formats differ");
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&other, g_area, AW, WH - 1u, AW, SSDA_PIX_U8));
    check_refused(SSDA_ERR_SIZE, &other, &win, NULL, "window taller than area");
    /* options */
    memset(&cfg, 0, sizeof cfg);
    cfg.threshold = 5u;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "threshold 5");
    memset(&cfg, 0, sizeof cfg);
    cfg.scan = 3u;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "scan 3");
    memset(&cfg, 0, sizeof cfg);
    cfg.order = 2u;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "order 2");
    memset(&cfg, 0, sizeof cfg);
    cfg.flags = 0x20u;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "unknown flag");
    memset(&cfg, 0, sizeof cfg);
    cfg.threshold = SSDA_THRESHOLD_RAMP;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "RAMP, lambda 0");
    cfg = bounds_cfg();
    cfg.flags = SSDA_MATCH_BLOCKS;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "BLOCKS without BOUNDS");
    cfg = bounds_cfg();
    cfg.flags = SSDA_MATCH_UNIQUE;
    cfg.threshold = SSDA_THRESHOLD_FIXED;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "UNIQUE with FIXED");
    cfg = bounds_cfg();
    cfg.flags = SSDA_MATCH_UNIQUE;
    cfg.unique_q8 = 256u;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "unique_q8 256");
    cfg = bounds_cfg();
    cfg.flags = SSDA_MATCH_UNIQUE;
    cfg.unique_radius = 3u;
    check_refused(SSDA_ERR_ARG, &area, &win, &cfg, "unique_radius 3");
    /* work buffers */
    cfg = bounds_cfg();
    cfg.work = NULL;
    check_refused(SSDA_ERR_NULL, &area, &win, &cfg, "bounds, work NULL");
    cfg = bounds_cfg();
    cfg.work_size = SSDA_MATCH_WORK_SIZE(AW, AH, WW, WH) - 1u;
    check_refused(SSDA_ERR_BUFFER, &area, &win, &cfg, "bounds, work 1 byte short");
    cfg = bounds_cfg();
    cfg.work = (uint8_t *)g_work + 2;
    cfg.work_size = sizeof g_work - 4u;
    check_refused(SSDA_ERR_BUFFER, &area, &win, &cfg, "bounds, misaligned work");
    cfg = bounds_cfg();
    cfg.flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
    cfg.work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(AW, AH, WW, WH) - 1u;
    check_refused(SSDA_ERR_BUFFER, &area, &win, &cfg, "blocks, work 1 byte short");
    /* and a good call with the state still poisoned succeeds */
    cfg = bounds_cfg();
    memset(&g_state, 0xA5, sizeof g_state);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match_search(&g_state, &area, &win, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(21u, res.x);
    TEST_ASSERT_EQUAL_UINT16(17u, res.y);
}

/* One state on this stack, never cleared, and the static one, for
   searches of every kind one after another: both equal ssda_match, and
   the exact ones the brute force. */
static void test_one_state_for_any_search(void)
{
    static const uint8_t flag_sets[] = {
        0u, SSDA_MATCH_BOUNDS, SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS,
        SSDA_MATCH_TIE_NEAREST | SSDA_MATCH_UNIQUE | SSDA_MATCH_SUBPIXEL,
        SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS | SSDA_MATCH_UNIQUE | SSDA_MATCH_SUBPIXEL};
    ssda_match_state_t local; /* uninitialised on purpose */
    uint32_t f, t, s, fmt;
    unsigned long searches = 0u;
    for (fmt = 0u; fmt < 2u; fmt++) {
        ssda_view_t area, win, sub;
        uint32_t bx = 0u, by = 0u;
        uint64_t bsad = 0u;
        make_views(fmt == 0u ? SSDA_PIX_U8 : SSDA_PIX_U16, &area, &win);
        test_best(&area, &win, &bx, &by, &bsad);
        for (f = 0u; f < sizeof flag_sets; f++) {
            for (t = 0u; t <= (uint32_t)SSDA_THRESHOLD_AUTO_RAMP; t++) {
                for (s = 0u; s <= (uint32_t)SSDA_SCAN_COARSE; s++) {
                    ssda_match_config_t cfg = bounds_cfg();
                    ssda_match_result_t ref, a, b;
                    int err;
                    cfg.flags = flag_sets[f];
                    cfg.threshold = (uint8_t)t;
                    cfg.scan = (uint8_t)s;
                    cfg.lambda_q8 = 3u * 256u;
                    cfg.fixed_threshold = bsad + 40u;
                    cfg.predict_x = 19;
                    cfg.predict_y = 18;
                    err = ssda_match(&area, &win, &cfg, &ref);
                    TEST_ASSERT_EQUAL_INT(err, ssda_match_search(&local, &area, &win, &cfg, &a));
                    TEST_ASSERT_EQUAL_INT(err, ssda_match_search(&g_state, &area, &win, &cfg, &b));
                    if (err != SSDA_OK) { /* quality flags with an inexact mode */
                        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, err);
                        continue;
                    }
                    test_match_same_result(&ref, &a, "state on the stack");
                    test_match_same_result(&ref, &b, "static state");
                    if (ref.exact) {
                        TEST_ASSERT_EQUAL_UINT64(bsad, a.sad);
                        TEST_ASSERT_EQUAL_UINT64(test_sad(&area, &win, a.x, a.y), a.sad);
                    }
                    searches++;
                    /* a smaller search in between: the state holds nothing over */
                    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&sub, &area, 3u, 5u,
                                                                 WW + 2u, WH + 1u));
                    TEST_ASSERT_EQUAL_INT(SSDA_OK,
                                          ssda_match_search(&local, &sub, &win, NULL, &a));
                    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&sub, &win, NULL, &ref));
                    test_match_same_result(&ref, &a, "sub-area");
                }
            }
        }
    }
    TEST_ASSERT_TRUE(searches >= 2u * 40u); /* every flag set ran in some mode */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_state_size_is_documented);
    RUN_TEST(test_bad_inputs_change_nothing);
    RUN_TEST(test_one_state_for_any_search);
    return UNITY_END();
}
