/*
 * test_track_shared.c - grid tracking with bound tables shared by the
 * windows (SSDA_TRACK_WORK_SIZE_SHARED, track.h): every vector, status,
 * SAD, exact flag, sub-pixel and uniqueness field and the positions and
 * completed counts equal those of per-window tables (a buffer of
 * SSDA_TRACK_WORK_SIZE), and in the exact mode each searched window's SAD
 * is the minimum of an independent brute force over its area; for many
 * geometries (window widths with and without 4 x 4 blocks, steps smaller
 * and larger than the window), 8 and 16-bit, random, extreme and masked
 * data, every threshold mode and scan, every buffer size around the
 * threshold, row by row (ssda_track_row) and at the accumulators' limits.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/track.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 112u
#define IH 90u
#define MAX_WIN 1200u
static uint16_t g_a16[IH * IW], g_b16[IH * IW];
static uint8_t g_a8[IH * IW], g_b8[IH * IW];
static uint64_t g_work[(256u * 1024u) / 8u];
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];

typedef struct {
    uint16_t win_w, win_h, search_w, search_h, step_x, step_y;
} geom_t;

static const geom_t k_geoms[] = {
    {16, 16, 32, 32, 16, 16}, /* the seed's */
    {16, 16, 32, 32, 8, 8},
    {12, 8, 20, 17, 7, 5},
    {6, 5, 14, 11, 5, 4},  /* width not a multiple of 4: group sums only */
    {8, 4, 17, 9, 6, 3},   /* the smallest height with shared tables */
    {20, 12, 21, 12, 9, 11}, /* 2 x 1 placements */
    {4, 4, 12, 12, 3, 3},
    {16, 3, 24, 9, 8, 4},  /* under 4 rows: per-window tables */
    {24, 20, 40, 36, 30, 25}, /* steps beyond the area: no row kept */
    {16, 16, 47, 40, 15, 13}, /* 32 x 25 placements: the predict scan's masks full */
    {16, 16, 56, 24, 24, 12}, /* 41 placements a row: the predict scan without masks */
};
#define NGEOMS (sizeof k_geoms / sizeof k_geoms[0])

/* kind 0: SECOND = FIRST moved (varying over the image) plus noise;
   1: extreme values (full range, sparse zeros, a checkerboard);
   2: as 0 with the mask value in a patch of both. */
static void make_images(uint32_t seed, uint32_t kind)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u16(g_a16, IW, IH, IW, 65535u, &r);
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            uint32_t mx = (x / 11u + y / 13u) % 5u, my = (x / 17u + y / 7u) % 5u;
            uint32_t sx = (x + IW + 2u - mx) % IW, sy = (y + IH + 2u - my) % IH;
            uint32_t v = g_a16[sy * IW + sx] + test_rng_range(&r, 0, 600);
            if (kind == 1u) {
                uint32_t a = test_rng_range(&r, 0, 9) == 0u ? 0u : 65535u;
                if (((x / 3u) + (y / 2u)) % 2u == 0u && y > IH / 2u) {
                    a = 65535u - a;
                }
                g_a16[y * IW + x] = (uint16_t)a;
                v = test_rng_range(&r, 0, 7) == 0u ? 0u : 65535u;
            }
            g_b16[y * IW + x] = (uint16_t)(v > 65535u ? 65535u : v);
        }
    }
    if (kind == 2u) {
        for (y = 30; y < 36; y++) {
            for (x = 40; x < 47; x++) {
                g_a16[y * IW + x] = 4095u;
                g_b16[(y + 20u) * IW + x + 30u] = 4095u;
            }
        }
    }
    for (x = 0; x < IW * IH; x++) {
        g_a8[x] = (uint8_t)(g_a16[x] >> 8);
        g_b8[x] = (uint8_t)(g_b16[x] >> 8);
    }
    if (kind == 2u) {
        for (x = 0; x < IW * IH; x++) {
            g_a8[x] = g_a16[x] == 4095u ? 200u : (uint8_t)(g_a8[x] == 200u ? 201u : g_a8[x]);
            g_b8[x] = g_b16[x] == 4095u ? 200u : (uint8_t)(g_b8[x] == 200u ? 201u : g_b8[x]);
        }
    }
}

static void views(bool wide, ssda_view_t *a, ssda_view_t *b)
{
    test_view_pair(wide, g_a16, g_b16, g_a8, g_b8, IW, IH, a, b);
}

static bool searched(uint8_t status)
{
    return status == SSDA_TRACK_OK || status == SSDA_TRACK_AMBIGUOUS ||
           status == SSDA_TRACK_AT_LIMIT;
}

static void same_vectors(const ssda_track_vector_t *w, const ssda_track_vector_t *g, uint32_t n,
                         const char *what)
{
    uint32_t k;
    for (k = 0; k < n; k++) {
        if (w[k].status != g[k].status || w[k].dx != g[k].dx || w[k].dy != g[k].dy ||
            w[k].sad != g[k].sad || w[k].exact != g[k].exact ||
            w[k].sub_dx_q8 != g[k].sub_dx_q8 || w[k].sub_dy_q8 != g[k].sub_dy_q8 ||
            w[k].unique_q8 != g[k].unique_q8 || w[k].texture_q8 != g[k].texture_q8 ||
            w[k].x != g[k].x || w[k].y != g[k].y) {
            char msg[160];
            snprintf(msg, sizeof msg, "%s: window %u: status %u (%d,%d) sad %llu vs %u (%d,%d) %llu",
                     what, (unsigned)k, w[k].status, (int)w[k].dx, (int)w[k].dy,
                     (unsigned long long)w[k].sad, g[k].status, (int)g[k].dx, (int)g[k].dy,
                     (unsigned long long)g[k].sad);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

/* Each searched window's SAD is the brute-force minimum over its area and
   the SAD at its vector (independent loops of test_image.c). */
static void check_brute(const ssda_view_t *a, const ssda_view_t *b, const ssda_track_grid_t *g,
                        const ssda_track_vector_t *v)
{
    const uint32_t hx = (g->search_w - g->win_w) / 2u, hy = (g->search_h - g->win_h) / 2u;
    uint32_t k;
    for (k = 0; k < g->count; k++) {
        ssda_view_t area, win;
        uint32_t bx, by;
        uint64_t bsad;
        if (!searched(v[k].status)) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&area, a, (uint16_t)(v[k].x - hx),
                                                     (uint16_t)(v[k].y - hy), g->search_w,
                                                     g->search_h));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&win, b, v[k].x, v[k].y, g->win_w, g->win_h));
        test_best(&area, &win, &bx, &by, &bsad);
        TEST_ASSERT_EQUAL_UINT64(bsad, v[k].sad);
        TEST_ASSERT_EQUAL_UINT64(bsad, test_sad(&area, &win, (uint32_t)((int32_t)hx - v[k].dx),
                                                (uint32_t)((int32_t)hy - v[k].dy)));
    }
}

static void config(const geom_t *gm, ssda_track_config_t *c)
{
    memset(c, 0, sizeof *c);
    c->win_w = gm->win_w;
    c->win_h = gm->win_h;
    c->search_w = gm->search_w;
    c->search_h = gm->search_h;
    c->step_x = gm->step_x;
    c->step_y = gm->step_y;
    c->flags = SSDA_TRACK_NO_FLAT;
    c->match.flags = SSDA_MATCH_BOUNDS;
    c->match.work = g_work;
}

/* Per-window tables, then shared ones: everything equal but pixel_ops. */
static void compare(const ssda_view_t *a, const ssda_view_t *b, ssda_track_config_t *c,
                    size_t shared, ssda_track_stats_t *want, ssda_track_stats_t *got)
{
    ssda_track_grid_t grid;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(c, IW, IH, &grid));
    TEST_ASSERT_TRUE(grid.count <= MAX_WIN);
    TEST_ASSERT_TRUE(shared <= sizeof g_work);
    c->match.work_size = SSDA_TRACK_WORK_SIZE(grid.search_w, grid.search_h, grid.win_w, grid.win_h);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(a, b, c, g_want, MAX_WIN, want));
    c->match.work_size = shared;
    memset(g_got, 0x5A, sizeof g_got);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(a, b, c, g_got, MAX_WIN, got));
    same_vectors(g_want, g_got, grid.count, "shared");
    TEST_ASSERT_EQUAL_UINT64(want->positions, got->positions);
    TEST_ASSERT_EQUAL_UINT64(want->completed, got->completed);
    TEST_ASSERT_EQUAL_UINT32(want->ok, got->ok);
    TEST_ASSERT_EQUAL_UINT32(want->masked, got->masked);
    TEST_ASSERT_EQUAL_UINT32(want->ambiguous, got->ambiguous);
    TEST_ASSERT_EQUAL_UINT32(want->at_limit, got->at_limit);
}

static size_t shared_size(const geom_t *gm)
{
    return SSDA_TRACK_WORK_SIZE_SHARED(IW, gm->search_w, gm->search_h, gm->win_w, gm->win_h);
}

/* Every geometry, format, data kind and mode: shared = per-window; AUTO
   (and brute force) = the independent minimum. */
static void test_shared_equals_per_window(void)
{
    static const uint8_t thr[] = {SSDA_THRESHOLD_AUTO, SSDA_THRESHOLD_AUTO,
                                  SSDA_THRESHOLD_AUTO, SSDA_THRESHOLD_FIXED,
                                  SSDA_THRESHOLD_AUTO_RAMP, SSDA_THRESHOLD_RAMP,
                                  SSDA_THRESHOLD_AUTO};
    static const uint8_t pred[] = {SSDA_TRACK_PREDICT_MEDIAN, SSDA_TRACK_PREDICT_NONE,
                                   SSDA_TRACK_PREDICT_LEFT, SSDA_TRACK_PREDICT_NONE,
                                   SSDA_TRACK_PREDICT_MEDIAN, SSDA_TRACK_PREDICT_NONE,
                                   SSDA_TRACK_PREDICT_NONE};
    uint32_t gi, kind, wide, m;
#ifdef SSDA_TEST_SMALL
    const uint32_t kinds = 2u;
#else
    const uint32_t kinds = 3u;
#endif
    for (kind = 0; kind < kinds; kind++) {
        make_images(100u + kind, kind);
        for (gi = 0; gi < NGEOMS; gi++) {
            for (wide = 0; wide < 2u; wide++) {
                for (m = 0; m < sizeof thr; m++) {
                    ssda_view_t a, b;
                    ssda_track_config_t c;
                    ssda_track_stats_t want, got;
                    ssda_track_grid_t grid;
                    views(wide != 0u, &a, &b);
                    config(&k_geoms[gi], &c);
                    c.predict = pred[m];
                    c.match.threshold = thr[m];
                    c.match.fixed_threshold = 40000u * k_geoms[gi].win_w;
                    c.match.lambda_q8 = 256u * 3000u;
                    if (m == 2u) {
                        c.flags |= SSDA_TRACK_UNIQUE;
                    }
                    if (m == 6u) {
                        c.match.scan = SSDA_SCAN_COARSE;
                        c.match.coarse_step = 3u;
                    }
                    if (kind == 2u) {
                        c.flags |= SSDA_TRACK_MASK;
                        c.mask_value = wide != 0u ? 4095u : 200u;
                    }
                    compare(&a, &b, &c, shared_size(&k_geoms[gi]), &want, &got);
                    (void)ssda_track_grid(&c, IW, IH, &grid);
                    if (thr[m] == SSDA_THRESHOLD_AUTO && m != 6u) {
                        check_brute(&a, &b, &grid, g_got);
                    }
                }
            }
        }
    }
}

/* One table row (search_h = win_h = 4) and areas over FIRST's whole width
   (the ROI starts half the margin in): the tables' last slot has no
   entries to spare after it. Shared = per-window = the brute force. */
static void test_one_row_whole_width(void)
{
    static const geom_t gm = {16, 4, 32, 4, 16, 4};
    uint32_t wide, pred, x, y;
    make_images(23u, 0u);
    for (y = 0; y < IH; y++) { /* SECOND = FIRST moved 8 px left: every
                                  minimum at its area's last column */
        for (x = 0; x + 8u < IW; x++) {
            g_b16[y * IW + x] = g_a16[y * IW + x + 8u];
            g_b8[y * IW + x] = g_a8[y * IW + x + 8u];
        }
    }
    for (wide = 0; wide < 2u; wide++) {
        for (pred = 0; pred < 2u; pred++) {
            ssda_view_t a, b;
            ssda_track_config_t c;
            ssda_track_stats_t want, got;
            ssda_track_grid_t grid;
            views(wide != 0u, &a, &b);
            config(&gm, &c);
            c.roi_x = 8u; /* areas from column 0 */
            c.roi_w = (uint16_t)(IW - 16u); /* to column IW - 1 */
            c.predict = pred != 0u ? SSDA_TRACK_PREDICT_MEDIAN : SSDA_TRACK_PREDICT_NONE;
            compare(&a, &b, &c, shared_size(&gm), &want, &got);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
            check_brute(&a, &b, &grid, g_got);
        }
    }
}

/* The seed's geometry on a grid of many windows: the shared tables cost
   fewer operations than tables per window (the point of sharing). */
static void test_shared_costs_less(void)
{
    ssda_view_t a, b;
    ssda_track_config_t c;
    ssda_track_stats_t want, got;
    uint32_t wide;
    make_images(7u, 0u);
    for (wide = 0; wide < 2u; wide++) {
        views(wide != 0u, &a, &b);
        config(&k_geoms[0], &c);
        c.predict = SSDA_TRACK_PREDICT_MEDIAN;
        c.step_x = 8u;
        c.step_y = 8u;
        compare(&a, &b, &c, shared_size(&k_geoms[0]), &want, &got);
        TEST_ASSERT_TRUE(want.ok > 20u);
        TEST_ASSERT_TRUE(got.pixel_ops < want.pixel_ops);
    }
}

/* Buffers from the per-window size up: below the shared size the
   per-window tables (pixel_ops too), from it the shared ones (a larger
   buffer changes nothing); a misaligned one is refused. */
static void test_buffer_sizes(void)
{
    ssda_view_t a, b;
    ssda_track_config_t c;
    ssda_track_stats_t want, got, more;
    const size_t need = shared_size(&k_geoms[2]);
    uint32_t wide;
    make_images(11u, 0u);
    for (wide = 0; wide < 2u; wide++) {
        views(wide != 0u, &a, &b);
        config(&k_geoms[2], &c);
        c.predict = SSDA_TRACK_PREDICT_MEDIAN;
        compare(&a, &b, &c, need - 1u, &want, &got);
        TEST_ASSERT_EQUAL_UINT64(want.pixel_ops, got.pixel_ops);
        compare(&a, &b, &c, need - 4u, &want, &got);
        TEST_ASSERT_EQUAL_UINT64(want.pixel_ops, got.pixel_ops);
        compare(&a, &b, &c, need, &want, &got);
        TEST_ASSERT_TRUE(got.pixel_ops != want.pixel_ops);
        compare(&a, &b, &c, need + 4096u, &want, &more);
        TEST_ASSERT_EQUAL_UINT64(got.pixel_ops, more.pixel_ops);
        c.match.work = (uint8_t *)(void *)g_work + 2;
        c.match.work_size = need;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_track(&a, &b, &c, g_got, MAX_WIN, NULL));
    }
}

/* ssda_track_row, grid row by grid row (each call builds its rows), with
   shared tables: ssda_track's vectors. */
static void test_track_row_shared(void)
{
    ssda_view_t a, b;
    ssda_track_config_t c;
    ssda_track_grid_t grid;
    ssda_track_stats_t st;
    uint32_t wide, gi, row;
    make_images(23u, 0u);
    for (gi = 0; gi < 3u; gi++) {
        for (wide = 0; wide < 2u; wide++) {
            views(wide != 0u, &a, &b);
            config(&k_geoms[gi], &c);
            c.predict = SSDA_TRACK_PREDICT_MEDIAN;
            c.match.work_size = shared_size(&k_geoms[gi]);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &c, g_want, MAX_WIN, NULL));
            memset(&st, 0, sizeof st);
            for (row = 0; row < grid.rows; row++) {
                /* two parts a row: the tables cover each part's columns */
                const uint32_t half = grid.cols / 2u + 1u;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_row(&a, &b, &c, row, 0u, half, g_got,
                                                              MAX_WIN, &st));
                if (half < grid.cols) {
                    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_row(&a, &b, &c, row, half,
                                                                  grid.cols, g_got, MAX_WIN,
                                                                  &st));
                }
            }
            same_vectors(g_want, g_got, grid.count, "track_row");
        }
    }
}

#ifndef SSDA_TEST_SMALL
/* The accumulators at their limits: 16-bit windows 16384 px wide (the
   widest with shared tables: a win_w x 4 sum of 65535s is 4 * 16384 *
   65535 < 2^32) and 8-bit ones 1024 px wide (the widest with 4 x 4
   blocks), all-max data with a few zeros; the independent brute force. */
#define WW 16392u
#define WH 9u
static uint16_t g_wa[WH * WW], g_wb[WH * WW];
static uint64_t g_wwork[(800u * 1024u) / 8u];
static void wide_case(bool wide, uint32_t win_w, uint32_t search_w, uint32_t img_w)
{
    ssda_view_t a, b;
    ssda_track_config_t c;
    ssda_track_stats_t want, got;
    ssda_track_grid_t grid;
    ssda_track_vector_t w1[4], g1[4];
    size_t need;
    memset(&c, 0, sizeof c);
    c.win_w = (uint16_t)win_w;
    c.win_h = 4u;
    c.search_w = (uint16_t)search_w;
    c.search_h = 8u;
    c.roi_x = (uint16_t)((search_w - win_w) / 2u);
    c.roi_y = 2u;
    c.roi_w = (uint16_t)win_w;
    c.roi_h = 4u;
    c.flags = SSDA_TRACK_NO_FLAT;
    c.match.flags = SSDA_MATCH_BOUNDS;
    c.match.work = g_wwork;
    const ssda_pixfmt_t f = wide ? SSDA_PIX_U16 : SSDA_PIX_U8;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_wa, (uint16_t)img_w, WH, WW * 2u, f));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_wb, (uint16_t)img_w, WH, WW * 2u, f));
    need = SSDA_TRACK_WORK_SIZE_SHARED(img_w, search_w, 8u, win_w, 4u);
    TEST_ASSERT_TRUE(need <= sizeof g_wwork);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, (uint16_t)img_w, WH, &grid));
    TEST_ASSERT_EQUAL_UINT32(1u, grid.count);
    c.match.work_size = SSDA_TRACK_WORK_SIZE(search_w, 8u, win_w, 4u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &c, w1, 4u, &want));
    c.match.work_size = need;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &c, g1, 4u, &got));
    same_vectors(w1, g1, 1u, "limits");
    TEST_ASSERT_TRUE(searched(g1[0].status));
    check_brute(&a, &b, &grid, g1);
}

static void test_accumulator_limits(void)
{
    uint32_t i;
    test_rng_t r;
    test_rng_seed(&r, 5u);
    for (i = 0; i < WH * WW; i++) {
        g_wa[i] = test_rng_range(&r, 0, 999) == 0u ? 0u : 65535u;
        g_wb[i] = test_rng_range(&r, 0, 999) == 0u ? 0u : 65535u;
    }
    wide_case(true, 16384u, 16392u, WW);
    wide_case(true, 16380u, 16392u, WW); /* a multiple of 4 beyond 1024: no blocks */
    wide_case(false, 1024u, 1036u, 1036u);
    wide_case(false, 1020u, 1036u, 1036u);
}
#endif

/* 16-bit images whose values all fit 8 bits track as their 8-bit copies:
   every vector field, statuses, and pixel_ops, positions and completed
   counts equal. With shared tables and 16-px windows the two formats take
   separate row paths on x86 (16-bit rows: one kernel call a position,
   their cut levels per group of rows); values 0..3 make partial sums meet
   the cut levels exactly, where a level off by one shows in the counts.
   Windows 16 x 16 to 16 x 19 (the rows after the 4 groups). */
static void test_u16_counts_equal_u8(void)
{
    static const geom_t k_quad[] = {
        {16, 16, 32, 32, 8, 8}, {16, 16, 32, 32, 16, 16}, {16, 19, 30, 33, 9, 10},
        {16, 17, 28, 27, 11, 7}};
    uint32_t gi, kind, x, pred;
    for (kind = 0; kind < 2u; kind++) {
        test_rng_t r;
        test_rng_seed(&r, 4242u + kind);
        make_images(300u + kind, 0u);
        for (x = 0; x < IW * IH; x++) { /* kind 0: 0..3 noise; 1: texture 0..255 */
            const uint32_t a = kind == 0u ? test_rng_range(&r, 0, 3) : g_a8[x];
            const uint32_t b = kind == 0u ? test_rng_range(&r, 0, 3) : g_b8[x];
            g_a16[x] = (uint16_t)a;
            g_b16[x] = (uint16_t)b;
            g_a8[x] = (uint8_t)a;
            g_b8[x] = (uint8_t)b;
        }
        for (gi = 0; gi < sizeof k_quad / sizeof k_quad[0]; gi++) {
            for (pred = 0; pred < 2u; pred++) {
                ssda_view_t a8, b8, a16, b16;
                ssda_track_config_t c;
                ssda_track_stats_t s8, s16;
                ssda_track_grid_t grid;
                views(false, &a8, &b8);
                views(true, &a16, &b16);
                config(&k_quad[gi], &c);
                c.predict = pred != 0u ? SSDA_TRACK_PREDICT_MEDIAN : SSDA_TRACK_PREDICT_LEFT;
                c.match.work_size = shared_size(&k_quad[gi]);
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a8, &b8, &c, g_want, MAX_WIN, &s8));
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a16, &b16, &c, g_got, MAX_WIN, &s16));
                same_vectors(g_want, g_got, grid.count, "16-bit");
                TEST_ASSERT_TRUE(s8.ok > 10u);
                TEST_ASSERT_EQUAL_UINT64(s8.pixel_ops, s16.pixel_ops);
                TEST_ASSERT_EQUAL_UINT64(s8.positions, s16.positions);
                TEST_ASSERT_EQUAL_UINT64(s8.completed, s16.completed);
                check_brute(&a16, &b16, &grid, g_got);
            }
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_shared_equals_per_window);
    RUN_TEST(test_one_row_whole_width);
    RUN_TEST(test_shared_costs_less);
    RUN_TEST(test_buffer_sizes);
    RUN_TEST(test_track_row_shared);
    RUN_TEST(test_u16_counts_equal_u8);
#ifndef SSDA_TEST_SMALL
    RUN_TEST(test_accumulator_limits);
#endif
    return UNITY_END();
}
