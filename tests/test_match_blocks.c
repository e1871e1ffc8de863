/*
 * test_match_blocks.c - SSDA_MATCH_BLOCKS (multilevel block bounds): random
 * searches with windows of 1..128 px, 8 and 16-bit, every exact mode, scan
 * and row order, equal to the brute-force minimum computed here (tie rule
 * included) and to the search with SSDA_MATCH_BOUNDS alone in every result
 * field but the work counts (and ssda_match_search equal to ssda_match in
 * every field, test_match_both.h); scan_pre, the single search's path for
 * windows up to 64 px (every bound at once, tile candidates first) in larger
 * areas with ties; the 32-bit worst cases of a block sum (16-bit blocks of
 * 65536 pixels of 65535, an integral image that wraps) and of scan_pre's
 * bounds (a 16-bit window of 65534 px of 65535 over zeros); argument and
 * buffer errors.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/match.h"
#include "ssda/stream.h"
#include "test_image.h"
#include "test_source.h"
#include "test_match_both.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef SSDA_TEST_SMALL
#define WMAX 40u    /* largest window side */
#define MARGIN 12u  /* area = window + 0..MARGIN */
#define CASES 40u
#else
#define WMAX 128u
#define MARGIN 40u
#define CASES 100u
#endif
#define AMAX (WMAX + MARGIN)

static uint16_t g_area[AMAX * (AMAX + 2u)];
static uint16_t g_win[WMAX * (WMAX + 2u)];
static uint64_t g_work[(SSDA_MATCH_WORK_SIZE_BLOCKS(AMAX, AMAX, 1u, AMAX) + 7u) / 8u];

typedef struct {
    uint32_t aw, ah, ww, wh, astride, wstride; /* strides in pixels */
    ssda_pixfmt_t fmt;
} geom_t;

static void put(uint16_t *buf, ssda_pixfmt_t fmt, uint32_t i, uint32_t v)
{
    if (fmt == SSDA_PIX_U8) {
        ((uint8_t *)buf)[i] = (uint8_t)v;
    } else {
        buf[i] = (uint16_t)v;
    }
}

static uint32_t get(const uint16_t *buf, ssda_pixfmt_t fmt, uint32_t i)
{
    return fmt == SSDA_PIX_U8 ? ((const uint8_t *)buf)[i] : buf[i];
}

/* A random case: noise, flat (all tie), binary, periodic (ties), a smooth
   ramp with noise, or an unrelated window; the window is cut from the area
   and perturbed, or not. Windows of 1..wmax px, mostly 16 px and up (the
   block levels), in areas up to margin px larger. */
static void make_case_in(test_rng_t *r, geom_t *g, ssda_view_t *area, ssda_view_t *win,
                         uint32_t wmax, uint32_t margin)
{
    const uint32_t kind = test_rng_range(r, 0, 5);
    uint32_t maxv, x, y, wx, wy;
    g->fmt = test_rng_range(r, 0, 1) ? SSDA_PIX_U16 : SSDA_PIX_U8;
    maxv = g->fmt == SSDA_PIX_U8 ? 255u : (test_rng_range(r, 0, 1) ? 65535u : 4095u);
    g->ww = test_rng_range(r, 0, 4) == 0u ? test_rng_range(r, 1, 15) : test_rng_range(r, 16, wmax);
    g->wh = test_rng_range(r, 0, 4) == 0u ? test_rng_range(r, 1, 15) : test_rng_range(r, 16, wmax);
    g->aw = g->ww + test_rng_range(r, 0, margin);
    g->ah = g->wh + test_rng_range(r, 0, margin);
    g->astride = g->aw + test_rng_range(r, 0, 2);
    g->wstride = g->ww + test_rng_range(r, 0, 2);
    for (y = 0; y < g->ah; y++) {
        for (x = 0; x < g->aw; x++) {
            uint32_t v;
            switch (kind) {
            case 0: v = test_rng_range(r, 0, maxv); break;
            case 1: v = maxv; break;
            case 2: v = test_rng_range(r, 0, 1) ? maxv : 0u; break;
            case 3: v = ((x / 5u + y / 3u) & 1u) ? maxv : 0u; break;
            default: v = (x * 37u + y * 11u + test_rng_range(r, 0, 9)) % (maxv + 1u); break;
            }
            put(g_area, g->fmt, y * g->astride + x, v);
        }
    }
    wx = test_rng_range(r, 0, g->aw - g->ww);
    wy = test_rng_range(r, 0, g->ah - g->wh);
    for (y = 0; y < g->wh; y++) {
        for (x = 0; x < g->ww; x++) {
            uint32_t v = get(g_area, g->fmt, (wy + y) * g->astride + wx + x);
            if (kind == 5u) {
                v = test_rng_range(r, 0, maxv);
            } else if (test_rng_range(r, 0, 3) == 0u && v < maxv) {
                v++;
            }
            put(g_win, g->fmt, y * g->wstride + x, v);
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(area, g_area, (uint16_t)g->aw, (uint16_t)g->ah,
                                                  g->astride * (uint32_t)g->fmt, g->fmt));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(win, g_win, (uint16_t)g->ww, (uint16_t)g->wh,
                                                  g->wstride * (uint32_t)g->fmt, g->fmt));
}

static void make_case(test_rng_t *r, geom_t *g, ssda_view_t *area, ssda_view_t *win)
{
    make_case_in(r, g, area, win, WMAX, MARGIN);
}

/* AUTO and NONE, raster and predict scans, both row orders, with or without
   the quality flags: the brute-force minimum, and the answer of the
   search with SSDA_MATCH_BOUNDS alone (every field but the work counts). */
static void test_blocks_equal_brute_force(void)
{
    test_rng_t r;
    uint32_t n, leveled = 0u;
    test_rng_seed(&r, 1818u);
    for (n = 0; n < CASES; n++) {
        ssda_view_t area, win;
        geom_t g;
        uint32_t bx = 0, by = 0, variant;
        uint64_t bsad = 0;
        make_case(&r, &g, &area, &win);
        test_best(&area, &win, &bx, &by, &bsad);
        leveled += g.ww >= 16u && g.wh >= 16u;
        /* AUTO x scan x order x quality flags, then NONE once (it ignores
           the bounds: the reference) */
        for (variant = 0; variant < 9u; variant++) {
            ssda_match_config_t cfg;
            ssda_match_result_t with, without;
            char msg[128];
            memset(&cfg, 0, sizeof cfg);
            cfg.threshold = variant == 8u ? SSDA_THRESHOLD_NONE : SSDA_THRESHOLD_AUTO;
            cfg.scan = (variant & 1u) ? SSDA_SCAN_PREDICT : SSDA_SCAN_RASTER;
            cfg.order = (variant & 2u) ? SSDA_ORDER_SPREAD : SSDA_ORDER_ROWS;
            cfg.flags = SSDA_MATCH_BOUNDS;
            if (variant & 4u) { /* TIE_NEAREST, UNIQUE, SUBPIXEL at random */
                cfg.flags = (uint8_t)(cfg.flags | (test_rng_range(&r, 1, 7) << 1));
            }
            cfg.work = g_work;
            cfg.work_size = sizeof g_work;
            cfg.predict_x = (int32_t)test_rng_range(&r, 0, 60) - 10;
            cfg.predict_y = (int32_t)test_rng_range(&r, 0, 60) - 10;
            snprintf(msg, sizeof msg, "case %u variant %u flags %u area %ux%u win %ux%u fmt %d",
                     (unsigned)n, (unsigned)variant, (unsigned)cfg.flags, (unsigned)g.aw,
                     (unsigned)g.ah, (unsigned)g.ww, (unsigned)g.wh, (int)g.fmt);
            TEST_ASSERT_EQUAL_INT_MESSAGE(SSDA_OK, ssda_match(&area, &win, &cfg, &without), msg);
            cfg.flags = (uint8_t)(cfg.flags | SSDA_MATCH_BLOCKS);
            TEST_ASSERT_EQUAL_INT_MESSAGE(SSDA_OK, test_match_both(&area, &win, &cfg, &with), msg);
            test_match_same_answer(&without, &with, msg);
            TEST_ASSERT_TRUE_MESSAGE(with.exact, msg);
            if ((cfg.flags & SSDA_MATCH_TIE_NEAREST) == 0u) {
                TEST_ASSERT_EQUAL_UINT64_MESSAGE(bsad, with.sad, msg);
                TEST_ASSERT_EQUAL_UINT32_MESSAGE(bx, with.x, msg);
                TEST_ASSERT_EQUAL_UINT32_MESSAGE(by, with.y, msg);
            } else {
                TEST_ASSERT_EQUAL_UINT64_MESSAGE(bsad, with.sad, msg);
                TEST_ASSERT_EQUAL_UINT64_MESSAGE(bsad, test_sad(&area, &win, with.x, with.y), msg);
            }
        }
    }
    TEST_ASSERT_TRUE(leveled > CASES / 3u);
}

/* scan_pre (SSDA_MATCH_BLOCKS, AUTO, raster, windows with no side above
   64 px or one below 32): every position's group bound at once, 16 tile
   candidates first, then only positions whose bound does not exceed the
   best SAD. Areas up to 100 px wider and taller than windows of 1..64 px,
   so that tiles hold many positions (and fewer positions than tiles too),
   ties everywhere (flat, binary, periodic images): the brute-force minimum
   by the tie rule, every position counted once, and every field of the
   search with SSDA_MATCH_BOUNDS alone but the work counts. */
static void test_blocks_pre_scan(void)
{
    const uint32_t wmax = WMAX < 64u ? WMAX : 64u;
    test_rng_t r;
    uint32_t n;
    test_rng_seed(&r, 6464u);
    for (n = 0; n < CASES; n++) {
        ssda_view_t area, win;
        geom_t g;
        ssda_match_config_t cfg;
        ssda_match_result_t with, without;
        uint32_t bx = 0, by = 0;
        uint64_t bsad = 0;
        char msg[128];
        make_case_in(&r, &g, &area, &win, wmax, AMAX - wmax);
        test_best(&area, &win, &bx, &by, &bsad);
        memset(&cfg, 0, sizeof cfg);
        cfg.flags = SSDA_MATCH_BOUNDS;
        if (test_rng_range(&r, 0, 1) != 0u) { /* TIE_NEAREST and SUBPIXEL at random */
            cfg.flags = (uint8_t)(cfg.flags | (test_rng_range(&r, 0, 1) ? SSDA_MATCH_TIE_NEAREST : 0u) |
                                  (test_rng_range(&r, 0, 1) ? SSDA_MATCH_SUBPIXEL : 0u));
        }
        cfg.work = g_work;
        cfg.work_size = sizeof g_work;
        cfg.predict_x = (int32_t)test_rng_range(&r, 0, 120) - 10;
        cfg.predict_y = (int32_t)test_rng_range(&r, 0, 120) - 10;
        snprintf(msg, sizeof msg, "case %u flags %u area %ux%u win %ux%u fmt %d", (unsigned)n,
                 (unsigned)cfg.flags, (unsigned)g.aw, (unsigned)g.ah, (unsigned)g.ww,
                 (unsigned)g.wh, (int)g.fmt);
        TEST_ASSERT_EQUAL_INT_MESSAGE(SSDA_OK, ssda_match(&area, &win, &cfg, &without), msg);
        cfg.flags = (uint8_t)(cfg.flags | SSDA_MATCH_BLOCKS);
        TEST_ASSERT_EQUAL_INT_MESSAGE(SSDA_OK, test_match_both(&area, &win, &cfg, &with), msg);
        test_match_same_answer(&without, &with, msg);
        TEST_ASSERT_TRUE_MESSAGE(with.exact, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE((g.aw - g.ww + 1u) * (g.ah - g.wh + 1u), with.positions,
                                         msg);
        TEST_ASSERT_TRUE_MESSAGE(with.completed >= 1u, msg);
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(bsad, with.sad, msg);
        if ((cfg.flags & SSDA_MATCH_TIE_NEAREST) == 0u) {
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(bx, with.x, msg);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(by, with.y, msg);
        } else {
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(bsad, test_sad(&area, &win, with.x, with.y), msg);
        }
    }
}

/* FIXED with a threshold at or above the minimum is exact with the levels
   too; below it (every position cut) the result is a real placement with
   its full SAD, flagged not exact. */
static void test_blocks_fixed(void)
{
    test_rng_t r;
    uint32_t n;
    test_rng_seed(&r, 2929u);
    for (n = 0; n < CASES / 2u; n++) {
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
        cfg.scan = (uint8_t)test_rng_range(&r, 0, 1);
        cfg.order = (uint8_t)test_rng_range(&r, 0, 1);
        cfg.flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
        cfg.work = g_work;
        cfg.work_size = sizeof g_work;
        cfg.fixed_threshold = bsad + test_rng_range(&r, 0, 50);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
        TEST_ASSERT_TRUE(res.exact);
        TEST_ASSERT_EQUAL_UINT64(bsad, res.sad);
        TEST_ASSERT_EQUAL_UINT32(bx, res.x);
        TEST_ASSERT_EQUAL_UINT32(by, res.y);
        if (bsad > 0u) {
            cfg.fixed_threshold = test_rng_range(&r, 0, bsad - 1u);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
            TEST_ASSERT_FALSE(res.exact);
            TEST_ASSERT_EQUAL_UINT32(0u, res.completed);
            TEST_ASSERT_EQUAL_UINT64(test_sad(&area, &win, res.x, res.y), res.sad);
        }
    }
}

#ifndef SSDA_TEST_SMALL
/* The 32-bit worst case of a block sum: 16-bit windows of 512 x 512 px,
   whose level-1 blocks are 256 x 256 = 65536 px (the largest accepted:
   65536 * 65535 = 4 294 901 760 < 2^32), and of 514 x 512 px, whose level-1
   blocks (257 x 256 = 65792 px) would overflow and are left out; all pixels
   65535 but a sparse pattern of zeros, so the area's integral image wraps
   many times. Brute force is the reference. */
#define BW 520u
#define BH 516u
static uint16_t g_big_area[BW * BH];
static uint16_t g_big_win[BW * BH];
static uint64_t g_big_work[(SSDA_MATCH_WORK_SIZE_BLOCKS(BW, BH, 512, 512) + 7u) / 8u];

static void test_blocks_worst_case_16bit(void)
{
    static const uint16_t sizes[2][2] = {{512u, 512u}, {514u, 512u}};
    uint32_t k, x, y;
    for (y = 0; y < BH; y++) {
        for (x = 0; x < BW; x++) {
            g_big_area[y * BW + x] = ((x * 7u + y * 13u) % 97u == 0u) ? 0u : 65535u;
        }
    }
    for (k = 0; k < 2u; k++) {
        ssda_view_t area, win;
        ssda_match_config_t cfg;
        ssda_match_result_t res, plain;
        const uint32_t ww = sizes[k][0], wh = sizes[k][1];
        uint32_t bx = 0, by = 0;
        uint64_t bsad = 0;
        for (y = 0; y < wh; y++) {
            for (x = 0; x < ww; x++) {
                g_big_win[y * ww + x] = g_big_area[(y + 3u) * BW + x + 2u];
            }
        }
        g_big_win[0] = 1000u; /* not a perfect match anywhere */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, g_big_area, BW, BH, BW * 2u,
                                                      SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, g_big_win, (uint16_t)ww,
                                                      (uint16_t)wh, ww * 2u, SSDA_PIX_U16));
        test_best(&area, &win, &bx, &by, &bsad);
        memset(&cfg, 0, sizeof cfg);
        cfg.flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
        cfg.work = g_big_work;
        cfg.work_size = sizeof g_big_work;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
        TEST_ASSERT_TRUE(res.exact);
        TEST_ASSERT_EQUAL_UINT64(bsad, res.sad);
        TEST_ASSERT_EQUAL_UINT32(bx, res.x);
        TEST_ASSERT_EQUAL_UINT32(by, res.y);
        TEST_ASSERT_EQUAL_UINT32(2u, res.x);
        TEST_ASSERT_EQUAL_UINT32(3u, res.y);
        cfg.flags = SSDA_MATCH_BOUNDS;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &plain));
        /* the levels did work: the integral image alone is 2 ops a pixel */
        TEST_ASSERT_TRUE(res.pixel_ops != plain.pixel_ops);
    }
}
#endif

#ifndef SSDA_TEST_SMALL
/* scan_pre's 32-bit worst case: a 16-bit window of 31 x 2114 = 65534 px
   (a side below 32: scan_pre; the largest a 32-bit search takes is 65536
   px) of 65535 over an area of zeros, so every bound and SAD is 65534 *
   65535 = 4 294 770 690, just below 2^32 - 1: all positions tie, the first
   in raster order wins; then the window's own pixels at (5, 3) but one,
   SAD 65535 there. Brute force is the reference. */
#define PW 40u
#define PH 2120u
#define PWW 31u
#define PWH 2114u
static uint16_t g_tall_area[PW * PH];
static uint16_t g_tall_win[PWW * PWH];
static uint64_t g_tall_work[(SSDA_MATCH_WORK_SIZE_BLOCKS(PW, PH, PWW, PWH) + 7u) / 8u];

static void test_blocks_pre_worst_case(void)
{
    uint32_t k, x, y;
    for (k = 0; k < 2u; k++) {
        ssda_view_t area, win;
        ssda_match_config_t cfg;
        ssda_match_result_t res;
        uint32_t bx = 0, by = 0;
        uint64_t bsad = 0;
        memset(g_tall_area, 0, sizeof g_tall_area);
        for (y = 0; y < PWH; y++) {
            for (x = 0; x < PWW; x++) {
                g_tall_win[y * PWW + x] = 65535u;
                if (k == 1u) {
                    g_tall_area[(y + 3u) * PW + x + 5u] = (x == 7u && y == 9u) ? 0u : 65535u;
                }
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, g_tall_area, PW, PH, PW * 2u,
                                                      SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, g_tall_win, PWW, PWH, PWW * 2u,
                                                      SSDA_PIX_U16));
        test_best(&area, &win, &bx, &by, &bsad);
        TEST_ASSERT_EQUAL_UINT64(k == 0u ? 4294770690u : 65535u, bsad);
        memset(&cfg, 0, sizeof cfg);
        cfg.flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
        cfg.work = g_tall_work;
        cfg.work_size = sizeof g_tall_work;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_match_both(&area, &win, &cfg, &res));
        TEST_ASSERT_TRUE(res.exact);
        TEST_ASSERT_EQUAL_UINT64(bsad, res.sad);
        TEST_ASSERT_EQUAL_UINT32(bx, res.x);
        TEST_ASSERT_EQUAL_UINT32(by, res.y);
        TEST_ASSERT_EQUAL_UINT32(k == 0u ? 0u : 5u, res.x);
        TEST_ASSERT_EQUAL_UINT32(k == 0u ? 0u : 3u, res.y);
        TEST_ASSERT_EQUAL_UINT32((PW - PWW + 1u) * (PH - PWH + 1u), res.positions);
    }
}
#endif

/* Images behind a read callback (ssda_stream_match: rows fetched one at a
   time, the engine's general row loop with the levels' rows of blocks as
   row groups) give the result of ssda_match in RAM, 8 and 16-bit, for a
   window with two levels (64 x 64: 2 x 2 and 4 x 4 blocks). */
#define SW 96u
#define SH 80u
static uint16_t g_simg[SW * SH], g_swin[64u * 64u];
static uint8_t g_sdev[2][SW * SH * 2u];
static uint32_t g_sarena[2][(SW * SH * 2u) / 4u + 64u];
static uint64_t g_swork[(SSDA_MATCH_WORK_SIZE_BLOCKS(SW, SH, 64u, 64u) + 7u) / 8u];

static void stream_source(ssda_source_t *src, test_source_t *dev, uint32_t k,
                          const ssda_view_t *v)
{
    ssda_source_config_t c;
    test_source_init(dev, g_sdev[k], (uint32_t)sizeof g_sdev[k], 1u);
    c = test_source_config(dev, v, SSDA_LAYOUT_RASTER, 0u, 0u, 0u, v->width * v->format, 0u, 1u,
                           g_sarena[k], sizeof g_sarena[k]);
    test_source_store(dev, &c, v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(src, &c));
}

static void test_blocks_streamed_rows(void)
{
    test_rng_t r;
    uint32_t f, x, y, n;
    test_rng_seed(&r, 3131u);
    for (n = 0u; n < 6u; n++) {
        const ssda_pixfmt_t fmt = (n & 1u) ? SSDA_PIX_U16 : SSDA_PIX_U8;
        const uint32_t maxv = fmt == SSDA_PIX_U8 ? 255u : 65535u;
        const uint32_t wx = test_rng_range(&r, 0, SW - 64u), wy = test_rng_range(&r, 0, SH - 64u);
        ssda_view_t av, wv;
        ssda_source_t as, ws;
        test_source_t ad, wd;
        ssda_rect_t ar = {0u, 0u, SW, SH}, wr = {0u, 0u, 64u, 64u};
        ssda_match_config_t cfg;
        ssda_match_result_t ram, streamed;
        for (y = 0u; y < SH; y++) {
            for (x = 0u; x < SW; x++) {
                put(g_simg, fmt, y * SW + x,
                    ((x / 7u + y / 5u) * 41u + test_rng_range(&r, 0, maxv / 8u)) % (maxv + 1u));
            }
        }
        for (y = 0u; y < 64u; y++) {
            for (x = 0u; x < 64u; x++) {
                uint32_t v = get(g_simg, fmt, (wy + y) * SW + wx + x);
                put(g_swin, fmt, y * 64u + x, v < maxv ? v + (n / 2u) : v);
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_simg, SW, SH, SW * fmt, fmt));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_swin, 64u, 64u, 64u * fmt, fmt));
        for (f = 0u; f < 2u; f++) { /* rows order, then spread */
            memset(&cfg, 0, sizeof cfg);
            cfg.order = (uint8_t)f;
            cfg.flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
            cfg.work = g_swork;
            cfg.work_size = sizeof g_swork;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&av, &wv, &cfg, &ram));
            stream_source(&as, &ad, 0u, &av);
            stream_source(&ws, &wd, 1u, &wv);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &ar, &ws, &wr, &cfg, &streamed));
            TEST_ASSERT_EQUAL_UINT64(ram.sad, streamed.sad);
            TEST_ASSERT_EQUAL_UINT32(ram.x, streamed.x);
            TEST_ASSERT_EQUAL_UINT32(ram.y, streamed.y);
            TEST_ASSERT_TRUE(streamed.exact);
            TEST_ASSERT_EQUAL_UINT64(test_sad(&av, &wv, ram.x, ram.y), ram.sad);
        }
    }
}

/* Errors: BLOCKS without BOUNDS, a buffer one byte short; nothing written. */
static void test_blocks_errors(void)
{
    static uint8_t a[64 * 48], w[32 * 32];
    ssda_view_t area, win;
    ssda_match_config_t cfg;
    ssda_match_result_t res, poison;
    memset(a, 7, sizeof a);
    memset(w, 7, sizeof w);
    memset(&poison, 0xA5, sizeof poison);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, a, 64, 48, 64, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, w, 32, 32, 32, SSDA_PIX_U8));
    memset(&cfg, 0, sizeof cfg);
    cfg.work = g_work;
    cfg.work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(64, 48, 32, 32);
    cfg.flags = SSDA_MATCH_BLOCKS;
    res = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&area, &win, &cfg, &res));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
    cfg.flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
    cfg.work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(64, 48, 32, 32) - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_match(&area, &win, &cfg, &res));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
    cfg.work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(64, 48, 32, 32);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT64(0u, res.sad);
    TEST_ASSERT_EQUAL_UINT32(0u, res.x);
    TEST_ASSERT_EQUAL_UINT32(0u, res.y);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_blocks_equal_brute_force);
    RUN_TEST(test_blocks_pre_scan);
    RUN_TEST(test_blocks_fixed);
#ifndef SSDA_TEST_SMALL
    RUN_TEST(test_blocks_worst_case_16bit);
    RUN_TEST(test_blocks_pre_worst_case);
#endif
    RUN_TEST(test_blocks_streamed_rows);
    RUN_TEST(test_blocks_errors);
    return UNITY_END();
}
