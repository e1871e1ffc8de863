/*
 * test_match_property.c - thousands of random searches: every exact mode,
 * scan, row order and bound option returns the brute-force minimum
 * (computed here independently, tie rule included).
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/match.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#ifndef SSDA_TEST_CASES
#define SSDA_TEST_CASES 1500u
#endif

#define AMAX 40u
static uint16_t g_area[AMAX * AMAX + 64u];
static uint16_t g_win[AMAX * AMAX + 64u];
static uint32_t g_work[4096];

typedef struct {
    uint32_t aw, ah, ww, wh, astride, wstride; /* strides in pixels */
    ssda_pixfmt_t fmt;
} geom_t;

/* Random case: texture, flat, binary (many ties) or noise; window cut from
   the area (exact match somewhere), or perturbed, or unrelated. */
static void make_case(test_rng_t *r, geom_t *g, ssda_view_t *area, ssda_view_t *win)
{
    uint32_t kind = test_rng_range(r, 0, 5);
    uint32_t maxv, x, y, wx, wy;
    g->fmt = test_rng_range(r, 0, 1) ? SSDA_PIX_U16 : SSDA_PIX_U8;
    maxv = g->fmt == SSDA_PIX_U8 ? 255u : (test_rng_range(r, 0, 1) ? 65535u : 4095u);
    g->aw = test_rng_range(r, 1, AMAX);
    g->ah = test_rng_range(r, 1, AMAX);
    g->ww = test_rng_range(r, 1, g->aw < 20u ? g->aw : 20u);
    g->wh = test_rng_range(r, 1, g->ah < 20u ? g->ah : 20u);
    g->astride = g->aw + test_rng_range(r, 0, 3);
    g->wstride = g->ww + test_rng_range(r, 0, 3);
    if (g->astride * g->ah > AMAX * AMAX + 64u) {
        g->astride = g->aw;
    }
    for (y = 0; y < g->ah; y++) {
        for (x = 0; x < g->aw; x++) {
            uint32_t v;
            switch (kind) {
            case 0: v = test_rng_range(r, 0, maxv); break;                      /* noise */
            case 1: v = maxv / 3u; break;                                        /* flat: all tie */
            case 2: v = test_rng_range(r, 0, 1) ? maxv : 0u; break;             /* binary */
            case 3: v = ((x / 3u + y / 3u) & 1u) ? maxv : 0u; break;             /* periodic: ties */
            default: v = (x * 37u + y * 11u + test_rng_range(r, 0, 9)) % (maxv + 1u); break;
            }
            if (g->fmt == SSDA_PIX_U8) {
                ((uint8_t *)g_area)[y * g->astride + x] = (uint8_t)v;
            } else {
                g_area[y * g->astride + x] = (uint16_t)v;
            }
        }
    }
    wx = test_rng_range(r, 0, g->aw - g->ww);
    wy = test_rng_range(r, 0, g->ah - g->wh);
    for (y = 0; y < g->wh; y++) {
        for (x = 0; x < g->ww; x++) {
            uint32_t v = g->fmt == SSDA_PIX_U8 ? ((uint8_t *)g_area)[(wy + y) * g->astride + wx + x]
                                               : g_area[(wy + y) * g->astride + wx + x];
            uint32_t noise = test_rng_range(r, 0, 3);
            if (kind == 5) {
                v = test_rng_range(r, 0, maxv);
            } else if (noise == 0u && v < maxv) {
                v++;
            }
            if (g->fmt == SSDA_PIX_U8) {
                ((uint8_t *)g_win)[y * g->wstride + x] = (uint8_t)v;
            } else {
                g_win[y * g->wstride + x] = (uint16_t)v;
            }
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(area, g_area, (uint16_t)g->aw, (uint16_t)g->ah,
                                                  g->astride * (uint32_t)g->fmt, g->fmt));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(win, g_win, (uint16_t)g->ww, (uint16_t)g->wh,
                                                  g->wstride * (uint32_t)g->fmt, g->fmt));
}

static void test_exact_modes_equal_brute_force(void)
{
    test_rng_t r;
    uint32_t n;
    uint32_t checked = 0;
    test_rng_seed(&r, 12345u);
    for (n = 0; n < SSDA_TEST_CASES; n++) {
        ssda_view_t area, win;
        geom_t g;
        uint32_t bx = 0, by = 0, variant;
        uint64_t bsad = 0;
        make_case(&r, &g, &area, &win);
        test_best(&area, &win, &bx, &by, &bsad);
        /* threshold x scan x order x bounds: 2 x 2 x 2 x 2 */
        for (variant = 0; variant < 16u; variant++) {
            ssda_match_config_t cfg;
            ssda_match_result_t res;
            char msg[96];
            memset(&cfg, 0, sizeof cfg);
            cfg.threshold = (variant & 1u) ? SSDA_THRESHOLD_NONE : SSDA_THRESHOLD_AUTO;
            cfg.scan = (variant & 2u) ? SSDA_SCAN_PREDICT : SSDA_SCAN_RASTER;
            cfg.order = (variant & 4u) ? SSDA_ORDER_SPREAD : SSDA_ORDER_ROWS;
            if (variant & 8u) {
                cfg.flags = SSDA_MATCH_BOUNDS;
                cfg.work = g_work;
                cfg.work_size = sizeof g_work;
            }
            cfg.predict_x = (int32_t)test_rng_range(&r, 0, 60) - 10;
            cfg.predict_y = (int32_t)test_rng_range(&r, 0, 60) - 10;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
            snprintf(msg, sizeof msg, "case %u variant %u area %ux%u win %ux%u fmt %d",
                     (unsigned)n, (unsigned)variant, (unsigned)g.aw, (unsigned)g.ah,
                     (unsigned)g.ww, (unsigned)g.wh, (int)g.fmt);
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(bsad, res.sad, msg);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(by, res.y, msg);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(bx, res.x, msg);
            TEST_ASSERT_TRUE_MESSAGE(res.exact, msg);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE((g.aw - g.ww + 1u) * (g.ah - g.wh + 1u), res.positions, msg);
            checked++;
        }
    }
    TEST_ASSERT_EQUAL_UINT32(SSDA_TEST_CASES * 16u, checked);
}

/* FIXED is exact whenever some position completes: the minimum is never cut. */
static void test_fixed_exact_when_any_position_completes(void)
{
    test_rng_t r;
    uint32_t n;
    test_rng_seed(&r, 777u);
    for (n = 0; n < SSDA_TEST_CASES / 4u; n++) {
        ssda_view_t area, win;
        geom_t g;
        ssda_match_config_t cfg;
        ssda_match_result_t res;
        uint32_t bx = 0, by = 0;
        uint64_t bsad = 0;
        make_case(&r, &g, &area, &win);
        test_best(&area, &win, &bx, &by, &bsad);
        memset(&cfg, 0, sizeof cfg);
        cfg.threshold = SSDA_THRESHOLD_FIXED;
        cfg.fixed_threshold = bsad + test_rng_range(&r, 0, 50);
        cfg.order = (uint8_t)test_rng_range(&r, 0, 1);
        cfg.scan = (uint8_t)test_rng_range(&r, 0, 1);
        if (test_rng_range(&r, 0, 1)) {
            cfg.flags = SSDA_MATCH_BOUNDS;
            cfg.work = g_work;
            cfg.work_size = sizeof g_work;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
        TEST_ASSERT_TRUE(res.exact);
        TEST_ASSERT_TRUE(res.completed >= 1u);
        TEST_ASSERT_EQUAL_UINT64(bsad, res.sad);
        TEST_ASSERT_EQUAL_UINT32(bx, res.x);
        TEST_ASSERT_EQUAL_UINT32(by, res.y);
    }
}

/* Every mode, whatever it returns, returns a real placement and its true
   SAD, the all-cut fallback included (issue 14: it reported a partial SAD),
   with or without bounds. */
static void test_inexact_modes_report_consistent_results(void)
{
    test_rng_t r;
    uint32_t n;
    test_rng_seed(&r, 4242u);
    for (n = 0; n < SSDA_TEST_CASES / 4u; n++) {
        ssda_view_t area, win;
        geom_t g;
        ssda_match_config_t cfg;
        ssda_match_result_t res;
        uint64_t truth;
        make_case(&r, &g, &area, &win);
        memset(&cfg, 0, sizeof cfg);
        cfg.threshold = (uint8_t)test_rng_range(&r, 2, 4);
        cfg.scan = (uint8_t)test_rng_range(&r, 0, 2);
        cfg.lambda_q8 = test_rng_range(&r, 1, 64u * 256u);
        cfg.fixed_threshold = test_rng_range(&r, 0, 5000);
        cfg.k_q8 = (uint16_t)test_rng_range(&r, 0, 1024);
        cfg.coarse_step = (uint16_t)test_rng_range(&r, 0, 9);
        if (test_rng_range(&r, 0, 1)) {
            cfg.flags = SSDA_MATCH_BOUNDS;
            cfg.work = g_work;
            cfg.work_size = sizeof g_work;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
        TEST_ASSERT_TRUE(res.x + g.ww <= g.aw);
        TEST_ASSERT_TRUE(res.y + g.wh <= g.ah);
        truth = test_sad(&area, &win, res.x, res.y);
        TEST_ASSERT_EQUAL_UINT64(truth, res.sad);
        if (res.completed == 0u) {
            TEST_ASSERT_FALSE(res.exact);
        }
        if (cfg.threshold != SSDA_THRESHOLD_FIXED || cfg.scan == SSDA_SCAN_COARSE) {
            TEST_ASSERT_FALSE(res.exact);
        }
    }
}

/* The bound of match.h's SSDA_MATCH_BOUNDS at (x, y), computed here:
   groups of G = 4 window rows (all rows when fewer), a last partial group
   left out, sum over groups of |area group sum - window group sum|. */
static uint64_t bound_ref(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y)
{
    const uint32_t group = win->height < 4u ? win->height : 4u;
    uint64_t total = 0u;
    uint32_t k, yy, xx;
    for (k = 0u; (k + 1u) * group <= win->height; k++) {
        uint64_t a = 0u, w = 0u;
        for (yy = k * group; yy < (k + 1u) * group; yy++) {
            for (xx = 0u; xx < win->width; xx++) {
                a += test_px(area, x + xx, y + yy);
                w += test_px(win, xx, yy);
            }
        }
        total += a > w ? a - w : w - a;
    }
    return total;
}

/* Issue 14: FIXED with bounds, every position cut. A position rejected by
   its bound before any pixel was summed (bound > T) must not be the
   fallback while another summed pixels (bound <= T); when every position
   was rejected so, the fallback is the smallest bound (then smallest y,
   then x). Its SAD is the full one. (Before: the first position by the tie
   rule, (0, 0), with "SAD 0".) */
static void test_all_cut_fallback_is_no_bound_reject(void)
{
    test_rng_t r;
    uint32_t n, some_summed = 0u, none_summed = 0u;
    test_rng_seed(&r, 1414u);
    for (n = 0; n < SSDA_TEST_CASES / 2u; n++) {
        ssda_view_t area, win;
        geom_t g;
        ssda_match_config_t cfg;
        ssda_match_result_t res;
        uint32_t bx = 0, by = 0, x, y, mx = 0u, my = 0u;
        uint64_t bsad = 0, minb = UINT64_MAX;
        make_case(&r, &g, &area, &win);
        test_best(&area, &win, &bx, &by, &bsad);
        if (bsad == 0u) {
            continue; /* a threshold below every SAD needs a minimum above 0 */
        }
        memset(&cfg, 0, sizeof cfg);
        cfg.threshold = SSDA_THRESHOLD_FIXED;
        cfg.fixed_threshold = test_rng_range(&r, 0, bsad - 1u); /* every position cut */
        cfg.scan = (uint8_t)test_rng_range(&r, 0, 1);
        cfg.order = (uint8_t)test_rng_range(&r, 0, 1);
        cfg.predict_x = (int32_t)test_rng_range(&r, 0, 40);
        cfg.predict_y = (int32_t)test_rng_range(&r, 0, 40);
        cfg.flags = SSDA_MATCH_BOUNDS;
        cfg.work = g_work;
        cfg.work_size = sizeof g_work;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
        TEST_ASSERT_EQUAL_UINT32(0u, res.completed);
        TEST_ASSERT_FALSE(res.exact);
        TEST_ASSERT_EQUAL_UINT64(test_sad(&area, &win, res.x, res.y), res.sad);
        for (y = 0u; y + g.wh <= g.ah; y++) {
            for (x = 0u; x + g.ww <= g.aw; x++) {
                uint64_t b = bound_ref(&area, &win, x, y);
                if (b < minb) {
                    minb = b;
                    mx = x;
                    my = y;
                }
            }
        }
        if (minb <= cfg.fixed_threshold) {
            TEST_ASSERT_TRUE(bound_ref(&area, &win, res.x, res.y) <= cfg.fixed_threshold);
            some_summed++;
        } else {
            TEST_ASSERT_EQUAL_UINT32(mx, res.x);
            TEST_ASSERT_EQUAL_UINT32(my, res.y);
            none_summed++;
        }
    }
    TEST_ASSERT_TRUE(some_summed > 0u); /* both cases exercised */
    TEST_ASSERT_TRUE(none_summed > 0u);
}

/* The quality flags against the definitions of match.h, from the full SAD
   surface computed here: the nearest-to-prediction tie rule, uniqueness
   (unique_q8) and the V fit, in every exact mode, scan, order and bound
   option. */
static uint64_t g_surf[AMAX * AMAX];

static uint32_t clamp_to(int32_t v, uint32_t n)
{
    return v < 0 ? 0u : ((uint32_t)v >= n ? n - 1u : (uint32_t)v);
}

static int32_t vfit_ref(uint64_t l, uint64_t c, uint64_t r)
{
    uint64_t den = (l > r ? l : r) - c, num = l > r ? l - r : r - l, q;
    if (den == 0u || c == 0u) {
        return 0;
    }
    q = (256u * num + den) / (2u * den); /* SADs here < 2^31: no scaling */
    return l >= r ? (int32_t)q : -(int32_t)q;
}

static void test_quality_flags_equal_brute_force(void)
{
    test_rng_t r;
    uint32_t n, ambiguous = 0, fitted = 0;
    test_rng_seed(&r, 2468u);
    for (n = 0; n < SSDA_TEST_CASES / 2u; n++) {
        ssda_view_t area, win;
        geom_t g;
        uint32_t nx, ny, x, y, bx = 0, by = 0, px, py, variant, rad;
        uint64_t best = UINT64_MAX, bd = 0, lim, s2 = UINT64_MAX;
        uint16_t uq8, want_u;
        int32_t want_sx = 0, want_sy = 0;
        uint8_t flags = (uint8_t)(test_rng_range(&r, 0, 7) << 1); /* TIE_NEAREST, UNIQUE, SUBPIXEL */
        int32_t pred_x = (int32_t)test_rng_range(&r, 0, 60) - 10;
        int32_t pred_y = (int32_t)test_rng_range(&r, 0, 60) - 10;
        make_case(&r, &g, &area, &win);
        nx = g.aw - g.ww + 1u;
        ny = g.ah - g.wh + 1u;
        px = clamp_to(pred_x, nx);
        py = clamp_to(pred_y, ny);
        uq8 = (uint16_t)(test_rng_range(&r, 0, 1) ? 0u : test_rng_range(&r, 257, 1024));
        rad = test_rng_range(&r, 0, 2);
        for (y = 0; y < ny; y++) {
            for (x = 0; x < nx; x++) {
                uint64_t s = test_sad(&area, &win, x, y);
                uint64_t d = (flags & SSDA_MATCH_TIE_NEAREST)
                                 ? (uint64_t)(((int64_t)x - px) * ((int64_t)x - px) +
                                              ((int64_t)y - py) * ((int64_t)y - py))
                                 : 0u;
                g_surf[y * nx + x] = s;
                if (s < best || (s == best && d < bd)) {
                    best = s;
                    bd = d;
                    bx = x;
                    by = y;
                }
            }
        }
        want_u = SSDA_MATCH_UNIQUE_NONE;
        if (flags & SSDA_MATCH_UNIQUE) {
            uint32_t rr = rad != 0u ? rad : 2u;
            lim = (best * (uq8 != 0u ? uq8 : 282u)) / 256u;
            for (y = 0; y < ny; y++) {
                for (x = 0; x < nx; x++) {
                    uint32_t ddx = x > bx ? x - bx : bx - x, ddy = y > by ? y - by : by - y;
                    if ((ddx > rr || ddy > rr) && g_surf[y * nx + x] <= lim &&
                        g_surf[y * nx + x] < s2) {
                        s2 = g_surf[y * nx + x];
                    }
                }
            }
            if (s2 != UINT64_MAX) {
                want_u = (uint16_t)(best == 0u ? 256u : (s2 * 256u) / best);
                ambiguous++;
            }
        }
        if (flags & SSDA_MATCH_SUBPIXEL) {
            if (bx > 0u && bx + 1u < nx) {
                want_sx = vfit_ref(g_surf[by * nx + bx - 1u], best, g_surf[by * nx + bx + 1u]);
                fitted++;
            }
            if (by > 0u && by + 1u < ny) {
                want_sy = vfit_ref(g_surf[(by - 1u) * nx + bx], best, g_surf[(by + 1u) * nx + bx]);
            }
        }
        for (variant = 0; variant < 16u; variant++) {
            ssda_match_config_t cfg;
            ssda_match_result_t res;
            char msg[128];
            memset(&cfg, 0, sizeof cfg);
            cfg.threshold = (variant & 1u) ? SSDA_THRESHOLD_NONE : SSDA_THRESHOLD_AUTO;
            cfg.scan = (variant & 2u) ? SSDA_SCAN_PREDICT : SSDA_SCAN_RASTER;
            cfg.order = (variant & 4u) ? SSDA_ORDER_SPREAD : SSDA_ORDER_ROWS;
            cfg.flags = (uint8_t)(flags | ((variant & 8u) ? SSDA_MATCH_BOUNDS : 0u));
            cfg.work = g_work;
            cfg.work_size = sizeof g_work;
            cfg.predict_x = pred_x;
            cfg.predict_y = pred_y;
            cfg.unique_q8 = uq8;
            cfg.unique_radius = (uint8_t)rad;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
            snprintf(msg, sizeof msg, "case %u variant %u flags %u area %ux%u win %ux%u",
                     (unsigned)n, (unsigned)variant, (unsigned)flags, (unsigned)g.aw,
                     (unsigned)g.ah, (unsigned)g.ww, (unsigned)g.wh);
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(best, res.sad, msg);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(by, res.y, msg);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(bx, res.x, msg);
            TEST_ASSERT_TRUE_MESSAGE(res.exact, msg);
            TEST_ASSERT_EQUAL_UINT16_MESSAGE(want_u, res.unique_q8, msg);
            TEST_ASSERT_EQUAL_INT16_MESSAGE(want_sx, res.sub_x_q8, msg);
            TEST_ASSERT_EQUAL_INT16_MESSAGE(want_sy, res.sub_y_q8, msg);
        }
    }
    TEST_ASSERT_TRUE(ambiguous > 0u); /* the cases exercise both answers */
    TEST_ASSERT_TRUE(fitted > 0u);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exact_modes_equal_brute_force);
    RUN_TEST(test_fixed_exact_when_any_position_completes);
    RUN_TEST(test_inexact_modes_report_consistent_results);
    RUN_TEST(test_all_cut_fallback_is_no_bound_reject);
    RUN_TEST(test_quality_flags_equal_brute_force);
    return UNITY_END();
}
