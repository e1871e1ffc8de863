/*
 * test_stream_track.c - ssda_stream_track equals ssda_track in RAM: vectors,
 * statuses and exact flags in every threshold mode and prediction, with
 * mask and texture tests, over raster and tiled layouts, read granularities
 * and arenas from the minimum to the whole image (strips of 1..all grid
 * columns); work counts too when the order cannot matter. Each strip's
 * areas and windows are read once; a failed read at every possible read
 * comes back unchanged; short arenas and bad arguments are refused first.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "ssda/track.h"
#include "test_image.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 120u
#define IH 90u
static uint16_t g_first[IH][IW], g_second[IH][IW];
static uint8_t g_fdev[30000], g_sdev[30000];
static uint32_t g_farena[3072], g_sarena[1536]; /* 12 KB, 6 KB */
static uint64_t g_work[(SSDA_TRACK_WORK_SIZE(32, 32, 16, 16) + 7u) / 8u];
/* bounds tables shared by the windows (track.h), for the bounds configs
   (12 x 10 in 26 x 23) when g_shared is set */
static uint64_t g_swork[(SSDA_TRACK_WORK_SIZE_SHARED(IW, 26, 23, 12, 10) + 7u) / 8u];
static bool g_shared;
static test_source_t g_tf, g_ts;
#define MAX_WIN 200u
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];

typedef struct {
    uint8_t layout;
    uint16_t tile_w, tile_h;
    uint32_t offset, stride_pad, read_size;
} geometry_t;

static const geometry_t k_raster = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1};
static const geometry_t k_geoms[] = {
    {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1},
    {SSDA_LAYOUT_RASTER, 0, 0, 8, 12, 32},
    {SSDA_LAYOUT_TILED, 32, 32, 0, 0, 1},
    {SSDA_LAYOUT_TILED, 20, 12, 2, 8, 16},
};
#define N_GEOMS (sizeof k_geoms / sizeof k_geoms[0])

/* FIRST: smooth texture with a fill-value patch (4095) and a flat patch;
   SECOND: FIRST moved by (3, -2) plus noise, so vectors are (3, -2) where
   the texture allows. */
static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u16(&g_first[0][0], IW, IH, IW, 4000u, &r);
    for (y = 60; y < 75; y++) {
        for (x = 5; x < 30; x++) {
            g_first[y][x] = 4095u;
        }
    }
    for (y = 20; y < 45; y++) {
        for (x = 70; x < 100; x++) {
            g_first[y][x] = 700u;
        }
    }
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            uint32_t sx = (x + IW - 3u) % IW, sy = (y + 2u) % IH;
            uint32_t v = g_first[sy][sx] + test_rng_range(&r, 0, 40);
            g_second[y][x] = (uint16_t)(v > 65535u ? 65535u : v);
        }
    }
}

static ssda_view_t view_of(bool first)
{
    ssda_view_t v;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, first ? (void *)g_first : (void *)g_second,
                                                  IW, IH, IW * 2u, SSDA_PIX_U16));
    return v;
}

static void make_source(ssda_source_t *s, bool first, const geometry_t *g, size_t arena_size)
{
    ssda_view_t v = view_of(first);
    test_source_t *dev = first ? &g_tf : &g_ts;
    uint32_t row = g->layout == SSDA_LAYOUT_TILED ? g->tile_w * 2u : IW * 2u;
    ssda_source_config_t c;
    test_source_init(dev, first ? g_fdev : g_sdev, (uint32_t)sizeof g_fdev, g->read_size);
    c = test_source_config(dev, &v, g->layout, g->tile_w, g->tile_h, g->offset,
                           row + g->stride_pad, 0u, g->read_size,
                           first ? (void *)g_farena : (void *)g_sarena, arena_size);
    test_source_store(dev, &c, &v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(s, &c));
}

/* Tracking options under test: thresholds x predictions x flags. */
#define N_CONFIGS 16u
static ssda_track_config_t config(uint32_t i)
{
    static const uint8_t modes[4] = {SSDA_THRESHOLD_AUTO, SSDA_THRESHOLD_NONE,
                                     SSDA_THRESHOLD_AUTO_RAMP, SSDA_THRESHOLD_FIXED};
    ssda_track_config_t c;
    memset(&c, 0, sizeof c);
    c.match.threshold = modes[i % 4u];
    c.predict = (uint8_t)((i / 4u) % 3u);
    c.match.fixed_threshold = 9000u;
    if (i >= 12u) { /* mask, texture, bounds, another geometry */
        c.flags = SSDA_TRACK_MASK | SSDA_TRACK_EXCLUDE;
        if (c.match.threshold == SSDA_THRESHOLD_AUTO || c.match.threshold == SSDA_THRESHOLD_NONE) {
            c.flags |= SSDA_TRACK_UNIQUE; /* its list after the bounds tables */
        }
        c.mask_value = 4095u;
        c.texture_threshold = 1500u;
        c.match.flags = SSDA_MATCH_BOUNDS;
        c.match.work = g_shared ? g_swork : g_work;
        c.match.work_size = g_shared ? sizeof g_swork : sizeof g_work;
        c.win_w = 12;
        c.win_h = 10;
        c.search_w = 26;
        c.search_h = 23;
        c.step_x = 9;
        c.step_y = 7;
        c.roi_x = 3;
        c.roi_y = 4;
        c.roi_w = 110;
        c.predict = (uint8_t)(i % 3u);
    }
    return c;
}

static bool same_vector(const ssda_track_vector_t *a, const ssda_track_vector_t *b)
{
    return a->sad == b->sad && a->dx == b->dx && a->dy == b->dy && a->x == b->x &&
           a->y == b->y && a->status == b->status && a->exact == b->exact &&
           a->sub_dx_q8 == b->sub_dx_q8 && a->sub_dy_q8 == b->sub_dy_q8 &&
           a->texture_q8 == b->texture_q8 && a->unique_q8 == b->unique_q8;
}

/* Compare with ssda_track in RAM. Work counts must agree too unless
   prediction is on and the grid was cut into several strips. */
static void check_against_ram(ssda_source_t *f, ssda_source_t *s, const ssda_track_config_t *c,
                              bool one_strip)
{
    ssda_view_t fv = view_of(true), sv = view_of(false);
    ssda_track_stats_t want, got;
    ssda_track_grid_t grid;
    uint32_t k;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(c, IW, IH, &grid));
    TEST_ASSERT_TRUE(grid.count <= MAX_WIN);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, c, g_want, MAX_WIN, &want));
    memset(g_got, 0, sizeof g_got);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(f, s, c, g_got, MAX_WIN, &got));
    for (k = 0; k < grid.count; k++) {
        if (!same_vector(&g_want[k], &g_got[k])) {
            char msg[96];
            snprintf(msg, sizeof msg, "window %u: status %u (%d,%d) vs %u (%d,%d)", (unsigned)k,
                     g_want[k].status, (int)g_want[k].dx, (int)g_want[k].dy, g_got[k].status,
                     (int)g_got[k].dx, (int)g_got[k].dy);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    TEST_ASSERT_EQUAL_UINT32(want.windows, got.windows);
    TEST_ASSERT_EQUAL_UINT32(want.ok, got.ok);
    TEST_ASSERT_EQUAL_UINT32(want.excluded, got.excluded);
    TEST_ASSERT_EQUAL_UINT32(want.masked, got.masked);
    TEST_ASSERT_EQUAL_UINT32(want.edge, got.edge);
    TEST_ASSERT_EQUAL_UINT64(want.check_pixels, got.check_pixels);
    if (g_shared && c->match.work == g_swork) {
        /* the tables' work depends on how the grid is cut into calls; the
           vectors are those of per-window tables */
        ssda_track_config_t per = *c;
        per.match.work = g_work;
        per.match.work_size = sizeof g_work;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, &per, g_want, MAX_WIN, NULL));
        for (k = 0; k < grid.count; k++) {
            TEST_ASSERT_TRUE(same_vector(&g_want[k], &g_got[k]));
        }
        want.pixel_ops = got.pixel_ops;
    }
    if (one_strip || c->predict == SSDA_TRACK_PREDICT_NONE) {
        TEST_ASSERT_EQUAL_UINT64(want.pixel_ops, got.pixel_ops);
        TEST_ASSERT_EQUAL_UINT64(want.positions, got.positions);
        TEST_ASSERT_EQUAL_UINT64(want.completed, got.completed);
    }
    TEST_ASSERT_EQUAL_UINT64(0, g_tf.contract_violations + g_ts.contract_violations);
}

/* Does the result depend on the order of the windows (MEDIAN prediction:
   it steers the scan and breaks ties, and a strip lacks up-right
   neighbours)? Then the job needs a band of the whole grid width. */
static bool order_matters(const ssda_track_config_t *c)
{
    return c->predict == SSDA_TRACK_PREDICT_MEDIAN;
}

/* Arena sizes: the minimum (a band of one column's areas and windows),
   a strip of 1 column and spare width, strips of 3 columns, the whole grid
   width (7 columns of the default grid: 128 x 32 areas, 112 x 16 windows). */
static void arena_sizes(const geometry_t *g, size_t *fa, size_t *sa)
{
    const uint8_t L = g->layout;
    fa[0] = SSDA_SOURCE_SIZE(L, SSDA_STREAM_STRIP_W(1, 16, 32), 32u, 2u, g->read_size, g->tile_w);
    sa[0] = SSDA_SOURCE_SIZE(L, SSDA_STREAM_STRIP_W(1, 16, 16), 16u, 2u, g->read_size, g->tile_w);
    fa[1] = SSDA_SOURCE_SIZE(L, SSDA_STREAM_STRIP_W(2, 16, 32) - 1u, 32u, 2u, g->read_size, g->tile_w);
    sa[1] = SSDA_SOURCE_SIZE(L, SSDA_STREAM_STRIP_W(2, 16, 16) - 1u, 16u, 2u, g->read_size, g->tile_w);
    fa[2] = SSDA_SOURCE_SIZE(L, SSDA_STREAM_STRIP_W(3, 16, 32), 32u, 2u, g->read_size, g->tile_w);
    sa[2] = SSDA_SOURCE_SIZE(L, SSDA_STREAM_STRIP_W(3, 16, 16), 16u, 2u, g->read_size, g->tile_w);
    fa[3] = SSDA_SOURCE_SIZE(L, IW, 32u, 2u, g->read_size, g->tile_w);
    sa[3] = SSDA_SOURCE_SIZE(L, IW, 16u, 2u, g->read_size, g->tile_w);
}

static void test_equal_to_ram_over_layouts_arenas_and_modes(void)
{
    uint32_t gi, ai, i;
    make_images(31u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        size_t fa[4], sa[4];
        arena_sizes(&k_geoms[gi], fa, sa);
        for (ai = 0; ai < 4; ai++) {
            ssda_source_t f, s;
            TEST_ASSERT_TRUE(fa[ai] <= sizeof g_farena && sa[ai] <= sizeof g_sarena);
            make_source(&f, true, &k_geoms[gi], fa[ai]);
            make_source(&s, false, &k_geoms[gi], sa[ai]);
            for (i = 0; i < N_CONFIGS; i++) {
                ssda_track_config_t c = config(i);
                /* every configuration on the first layout, a third of them
                   on the others; the minimum arena reads for nearly every
                   row span, so a few configurations are enough there */
                if ((gi != 0u && i % 3u != gi % 3u) || (ai == 0u && i % 5u != 0u)) {
                    continue;
                }
                if (order_matters(&c) && ai != 3u) {
                    /* one full-width strip is needed: refused, nothing read */
                    uint64_t reads = g_tf.reads + g_ts.reads;
                    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                                          ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, NULL));
                    TEST_ASSERT_EQUAL_UINT64(reads, g_tf.reads + g_ts.reads);
                    continue;
                }
                check_against_ram(&f, &s, &c, ai == 3u);
            }
        }
    }
}

/* Only FIRST streamed, only SECOND streamed. */
static void test_one_image_streamed(void)
{
    ssda_view_t fv = view_of(true), sv = view_of(false);
    ssda_source_t f, s, fview, sview;
    uint32_t i;
    make_images(32u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&fview, &fv));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&sview, &sv));
    for (i = 0; i < N_CONFIGS; i++) {
        ssda_track_config_t c = config(i);
        const bool full = order_matters(&c); /* a band of the whole width */
        make_source(&f, true, &k_geoms[3], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, full ? IW : 48u, 32u, 2u, 16u, 20u));
        make_source(&s, false, &k_geoms[3], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, full ? IW : 32u, 16u, 2u, 16u, 20u));
        check_against_ram(&f, &sview, &c, false);
        check_against_ram(&fview, &s, &c, false);
        check_against_ram(&fview, &sview, &c, false);
    }
}

/* The same with the bounds tables shared by the windows: streamed rows
   (plates of FIRST per strip and grid row) against images in RAM, every
   layout and arena of the first test for the bounds configurations. */
static void test_shared_tables_streamed(void)
{
    g_shared = true;
    test_one_image_streamed();
    test_equal_to_ram_over_layouts_arenas_and_modes();
    g_shared = false;
}

/* Read once per strip: with brute force (every row needed), FIRST's bytes
   are exactly the sum over strips of the rectangle of the strip's areas
   that lie inside the image, and SECOND's the sum of those windows'
   rectangles. Default grid on 120 x 90: 7 x 5 windows at 16 px steps;
   column 0 and row 0 are EDGE (their areas start at -8), the others'
   areas are inside (the last ones end at 120 and 88). */
static void test_each_strip_reads_its_areas_and_windows_once(void)
{
    const uint32_t k = 3, cols = 7;
    ssda_source_t f, s;
    ssda_track_config_t c;
    uint64_t want_f = 0, want_s = 0;
    uint32_t c0;
    make_images(33u);
    memset(&c, 0, sizeof c);
    c.match.threshold = SSDA_THRESHOLD_NONE;
    for (c0 = 0; c0 < cols; c0 += k) {
        uint32_t c1 = c0 + k < cols ? c0 + k : cols;
        uint32_t lo = c0 > 1u ? c0 : 1u, hi = c1 - 1u;
        want_f += (16u * (hi - lo) + 32u) * 2u; /* areas 16 lo - 8 .. 16 hi + 24 */
        want_s += (16u * (hi - lo) + 16u) * 2u; /* windows 16 lo .. 16 hi + 16 */
    }
    want_f *= 16u * 3u + 32u; /* area rows 8 .. 87 */
    want_s *= 16u * 3u + 16u; /* window rows 16 .. 79 */
    make_source(&f, true, &k_raster,
                SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, SSDA_STREAM_STRIP_W(3, 16, 32), 32u, 2u, 1u, 0u));
    make_source(&s, false, &k_raster,
                SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, SSDA_STREAM_STRIP_W(3, 16, 16), 16u, 2u, 1u, 0u));
    check_against_ram(&f, &s, &c, false);
    TEST_ASSERT_EQUAL_UINT64(want_s, s.stats.bytes_read);
    TEST_ASSERT_EQUAL_UINT64(want_f, f.stats.bytes_read);
}

/* The bound (issue 22) over layouts, read sizes, modes and arenas from the
   minimum (a band of one column) up to the whole grid width: each image's
   bytes read are at most STRIP_W(1, step_x, side) / step_x (the strips'
   overlap at one column a strip: 2 for the default grid, 26 / 9 and 12 / 9
   for the other) plus one, times those of the job with a band of the whole
   grid width in the arena (one strip: every byte read once at the layout's
   granularity). */
static void test_bytes_read_are_bounded_for_every_accepted_arena(void)
{
    uint32_t gi, i, extra;
    double worst_f = 0.0, worst_s = 0.0;
    make_images(36u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        const geometry_t *g = &k_geoms[gi];
        for (i = 0; i < N_CONFIGS; i++) {
            ssda_track_config_t c = config(i);
            ssda_track_grid_t grid;
            ssda_source_t f, s;
            uint64_t once_f, once_s;
            double bound_f, bound_s;
            if (order_matters(&c)) {
                continue; /* one full-width strip only */
            }
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
            /* each strip row's read is widened by up to 2 (read_size - 1)
               bytes, and a tiled one may cover its edge tiles' whole rows
               (up to 2 tile strides) */
            const double slack = 2.0 * (g->read_size - 1u) +
                                 (g->layout == SSDA_LAYOUT_TILED ? 2.0 * (g->tile_w * 2u + g->stride_pad) : 0.0);
            bound_f = ((double)grid.search_w / grid.step_x + 1.0) * (1.0 + slack / (2.0 * grid.search_w));
            bound_s = ((double)grid.win_w / grid.step_x + 1.0) * (1.0 + slack / (2.0 * grid.win_w));
            make_source(&f, true, g, SSDA_SOURCE_SIZE(g->layout, IW, grid.search_h, 2u, g->read_size, g->tile_w));
            make_source(&s, false, g, SSDA_SOURCE_SIZE(g->layout, IW, grid.win_h, 2u, g->read_size, g->tile_w));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, NULL));
            once_f = f.stats.bytes_read;
            once_s = s.stats.bytes_read;
            for (extra = 0; extra < 64u; extra += 7u) {
                double af, as;
                make_source(&f, true, g, SSDA_SOURCE_SIZE(g->layout, grid.search_w + extra, grid.search_h, 2u, g->read_size, g->tile_w));
                make_source(&s, false, g, SSDA_SOURCE_SIZE(g->layout, grid.win_w + extra, grid.win_h, 2u, g->read_size, g->tile_w));
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, NULL));
                af = (double)f.stats.bytes_read / (double)once_f;
                as = (double)s.stats.bytes_read / (double)once_s;
                worst_f = af > worst_f ? af : worst_f;
                worst_s = as > worst_s ? as : worst_s;
                if (af > bound_f || as > bound_s) {
                    char msg[96];
                    snprintf(msg, sizeof msg, "geometry %u config %u extra %u: %.2f, %.2f x once",
                             (unsigned)gi, (unsigned)i, (unsigned)extra, af, as);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        }
    }
    printf("worst amplification: FIRST %.3f, SECOND %.3f\n", worst_f, worst_s);
}

/* A failure at read k of either device, for every k of a clean run: the
   code comes back unchanged and *stats is untouched; a rerun is correct. */
static void test_failure_at_every_read(void)
{
    ssda_source_t f, s;
    ssda_track_config_t c = config(12);
    ssda_track_stats_t st, poison;
    uint64_t n[2], k;
    uint32_t dev;
    c.roi_w = 60; /* 6 x 5 windows */
    c.roi_h = 40;
    make_images(34u);
    make_source(&f, true, &k_geoms[3], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 44u, 23u, 2u, 16u, 20u));
    make_source(&s, false, &k_geoms[3], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 30u, 10u, 2u, 16u, 20u));
    check_against_ram(&f, &s, &c, false);
    n[0] = g_tf.reads;
    n[1] = g_ts.reads;
    TEST_ASSERT_TRUE(n[0] > 10u && n[1] > 10u);
    memset(&poison, 0x4E, sizeof poison);
    for (dev = 0; dev < 2; dev++) {
        for (k = 0; k < n[dev]; k++) {
            test_source_t *t = dev == 0 ? &g_tf : &g_ts;
            make_source(&f, true, &k_geoms[3], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 44u, 23u, 2u, 16u, 20u));
            make_source(&s, false, &k_geoms[3], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 30u, 10u, 2u, 16u, 20u));
            t->fail_code = -900 - (int)k;
            t->fail_at_read = (int64_t)k;
            st = poison;
            TEST_ASSERT_EQUAL_INT(-900 - (int)k, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
            TEST_ASSERT_EQUAL_UINT64(1, t->failures);
        }
    }
    check_against_ram(&f, &s, &c, false); /* the sources recover */
}

static void test_short_arenas_and_bad_arguments(void)
{
    ssda_view_t fv = view_of(true);
    ssda_source_t f, s, zero, f8;
    ssda_track_config_t c;
    ssda_track_stats_t st, poison;
    uint8_t bytes8[IW];
    ssda_view_t v8;
    make_images(35u);
    memset(&c, 0, sizeof c);
    memset(&zero, 0, sizeof zero);
    memset(&poison, 0x4E, sizeof poison);
    memset(bytes8, 0, sizeof bytes8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v8, bytes8, IW, 1, IW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&f8, &v8));
    /* one byte short of a band of one column's search areas for FIRST
       (32 x 32), of its windows for SECOND (16 x 16): below that the
       tracker re-read rows without bound (issue 22) */
    make_source(&f, true, &k_raster, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 32u, 32u, 2u, 1u, 0u) - 1u);
    make_source(&s, false, &k_raster, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 16u, 16u, 2u, 1u, 0u));
    st = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
    make_source(&f, true, &k_raster, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 32u, 32u, 2u, 1u, 0u));
    make_source(&s, false, &k_raster, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 16u, 16u, 2u, 1u, 0u) - 1u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_UINT64(0, g_tf.reads + g_ts.reads);
    make_source(&s, false, &k_raster, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 16u, 16u, 2u, 1u, 0u));
    /* the minimum works (and gives ssda_track's vectors) */
    check_against_ram(&f, &s, &c, false);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_stream_track(&f, &s, &c, g_got, 34u, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_stream_track(NULL, &s, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_stream_track(&f, NULL, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_stream_track(&f, &s, &c, NULL, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_track(&zero, &s, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_track(&f, &f, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_stream_track(&f8, &s, &c, g_got, MAX_WIN, &st));
    c.win_w = 40;
    c.search_w = 30; /* search smaller than the window */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
    memset(&c, 0, sizeof c);
    c.predict = 7;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    /* the same in-RAM source for both images is fine */
    {
        ssda_source_t v;
        ssda_track_stats_t want;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&v, &fv));
        memset(&c, 0, sizeof c);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&v, &v, &c, g_got, MAX_WIN, &st));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &fv, &c, g_want, MAX_WIN, &want));
        TEST_ASSERT_EQUAL_UINT64(want.pixel_ops, st.pixel_ops);
        TEST_ASSERT_TRUE(same_vector(&g_want[8], &g_got[8]));
    }
}

/* A FIRST narrower than a search area (no area lies inside it, every
   window is an edge): the minimum is one row of FIRST's width, not of the
   search width (the 5 s fuzz smoke found the library asking for 32 px of
   an 8-px image); one byte less is refused before any read. */
static void test_first_narrower_than_an_area(void)
{
    const size_t need = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 8u, 1u, 2u, 1u, 0u);
    ssda_view_t fv, sv = view_of(false);
    ssda_source_t f, s;
    ssda_source_config_t cfg;
    ssda_track_config_t c;
    ssda_track_stats_t want, got;
    ssda_track_grid_t grid;
    uint32_t k, pass;
    make_images(36u);
    memset(&c, 0, sizeof c);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&fv, g_first, 8u, IH, IW * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&s, &sv));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, &c, g_want, MAX_WIN, &want));
    TEST_ASSERT_EQUAL_UINT32(grid.count, want.edge);
    for (pass = 0; pass < 2u; pass++) {
        test_source_init(&g_tf, g_fdev, (uint32_t)sizeof g_fdev, 1u);
        cfg = test_source_config(&g_tf, &fv, SSDA_LAYOUT_RASTER, 0u, 0u, 0u, 16u, 0u, 1u,
                                 g_farena, need - pass);
        test_source_store(&g_tf, &cfg, &fv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&f, &cfg));
        memset(g_got, 0, sizeof g_got);
        if (pass == 1u) {
            TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &got));
            TEST_ASSERT_EQUAL_UINT64(0, g_tf.reads);
            break;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &got));
        for (k = 0; k < grid.count; k++) {
            TEST_ASSERT_TRUE(same_vector(&g_want[k], &g_got[k]));
        }
        TEST_ASSERT_EQUAL_UINT32(want.edge, got.edge);
    }
}

/* A periodic pattern: every window's SAD ties at several placements, and
   the tie rule (track.h) picks the one nearest the prediction. With MEDIAN
   prediction that needs the up-right neighbour, so the job takes one
   full-width strip even in the exact mode and refuses a narrower arena;
   the fuzz smoke found strips settling a tie elsewhere. */
static void test_median_ties_need_the_whole_grid_width(void)
{
    const size_t full_f = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, IW, 32u, 2u, 1u, 0u);
    const size_t full_s = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 112u, 16u, 2u, 1u, 0u);
    ssda_source_t f, s;
    ssda_track_config_t c;
    ssda_track_stats_t st;
    uint32_t x, y, pred;
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            g_first[y][x] = (uint16_t)(((x / 3u + y / 5u) % 4u) * 300u);
            g_second[y][x] = (uint16_t)((((x + 1u) / 3u + y / 5u) % 4u) * 300u);
        }
    }
    memset(&c, 0, sizeof c);
    for (pred = 0; pred < 3u; pred++) {
        c.predict = (uint8_t)pred;
        make_source(&f, true, &k_raster, full_f);
        make_source(&s, false, &k_raster, full_s);
        check_against_ram(&f, &s, &c, true);
        /* one column's band: strips of one column, or refused for MEDIAN */
        make_source(&f, true, &k_raster, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 32u, 32u, 2u, 1u, 0u));
        make_source(&s, false, &k_raster, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 16u, 16u, 2u, 1u, 0u));
        if (pred == SSDA_TRACK_PREDICT_MEDIAN) {
            TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
        } else {
            check_against_ram(&f, &s, &c, false);
        }
    }
}

/* FIRST and SECOND streamed with overlapping arenas would overwrite each
   other's plate: refused before any read, out and stats untouched; halves
   of one buffer that do not overlap give ssda_track's vectors. */
static void test_overlapping_arenas_are_refused(void)
{
    const size_t half = sizeof g_farena / 2u;
    ssda_source_t f, s, other;
    ssda_source_config_t cs;
    ssda_track_config_t c;
    ssda_track_stats_t st, poison;
    make_images(36u);
    memset(&c, 0, sizeof c);
    memset(&poison, 0x4E, sizeof poison);
    make_source(&f, true, &k_raster, half);
    make_source(&s, false, &k_raster, sizeof g_sarena);
    cs = s.cfg;
    cs.arena = (uint8_t *)g_farena + half - 4u; /* its first word is FIRST's last */
    cs.arena_size = half;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&other, &cs));
    g_tf.reads = 0;
    g_ts.reads = 0;
    memset(g_got, 0x3C, sizeof g_got);
    memcpy(g_want, g_got, sizeof g_got);
    st = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_track(&f, &other, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_track(&other, &f, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    TEST_ASSERT_EQUAL_MEMORY(g_want, g_got, sizeof g_got);
    TEST_ASSERT_EQUAL_UINT64(0, g_tf.reads + g_ts.reads);
    /* the next word on: two plates in one buffer */
    cs.arena = (uint8_t *)g_farena + half;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&other, &cs));
    check_against_ram(&f, &other, &c, false);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_equal_to_ram_over_layouts_arenas_and_modes);
    RUN_TEST(test_one_image_streamed);
    RUN_TEST(test_shared_tables_streamed);
    RUN_TEST(test_each_strip_reads_its_areas_and_windows_once);
    RUN_TEST(test_bytes_read_are_bounded_for_every_accepted_arena);
    RUN_TEST(test_failure_at_every_read);
    RUN_TEST(test_short_arenas_and_bad_arguments);
    RUN_TEST(test_overlapping_arenas_are_refused);
    RUN_TEST(test_first_narrower_than_an_area);
    RUN_TEST(test_median_ties_need_the_whole_grid_width);
    return UNITY_END();
}
