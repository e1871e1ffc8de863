/*
 * test_fault_stream.c - read failures injected at every read of a job, where
 * the stream tests do not already sweep them: grid tracking (ssda_stream_track)
 * in 8- and 16-bit over raster and tiled storage, followed at once by the
 * same job on the SAME sources (no new init, same arenas), which must give
 * ssda_track's vectors; push-mode search with a streamed window, and
 * push-mode tracking with the pushed image as FIRST, each failing at every
 * read and then run again on the same source. Error codes include values
 * that collide with the library's own (-1, SSDA_ERR_BUFFER) and INT_MIN:
 * they must come back unchanged.
 */
#include <limits.h>
#include <string.h>

#include "unity.h"
#include "ssda/stream.h"
#include "test_image.h"
#include "test_rng.h"
#include "test_source.h"
#include "test_push.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 40u
#define IH 30u
#define MAX_WIN 64u

static uint16_t g_f16[IH][IW], g_s16[IH][IW];
static uint8_t g_f8[IH][IW], g_s8[IH][IW];
static uint8_t g_fdev[6000], g_sdev[6000];
static uint32_t g_farena[256], g_sarena[256]; /* 1 KB each */
static uint32_t g_ring[IW * IH * 2u / 4u];
static uint32_t g_work[SSDA_TRACK_WORK_SIZE(16, 12, 8, 8) / 4u];
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];
static test_source_t g_tf, g_ts;

/* Storage geometries: layout, tile size, offset, stride padding (bytes),
   read granularity (a multiple of 2, so valid for both depths). */
typedef struct {
    uint8_t layout;
    uint16_t tile_w, tile_h;
    uint32_t offset, pad, read_size;
} geometry_t;

static const geometry_t k_geoms[] = {
    {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1},
    {SSDA_LAYOUT_RASTER, 0, 0, 6, 4, 8},
    {SSDA_LAYOUT_TILED, 8, 8, 0, 0, 1},
    {SSDA_LAYOUT_TILED, 7, 5, 4, 2, 16},
};
#define N_GEOMS (sizeof k_geoms / sizeof k_geoms[0])

/* Codes a read may fail with: any negative int comes back unchanged. */
static int fail_code(uint64_t k)
{
    static const int codes[] = {-1, INT_MIN, SSDA_ERR_BUFFER, -4242};
    return codes[k % 4u] - (k % 4u == 3u ? (int)(k / 4u) : 0);
}

/* SECOND is FIRST moved by (+2, -1) with a little noise (8-bit). */
static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_12bit(&g_f16[0][0], &g_f8[0][0], IW, IH, &r);
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            uint32_t sx = (x + IW - 2u) % IW, sy = (y + 1u) % IH;
            g_s16[y][x] = g_f16[sy][sx];
            g_s8[y][x] = (uint8_t)((g_f8[sy][sx] + test_rng_range(&r, 0, 3)) & 0xFFu);
        }
    }
}

static ssda_view_t view_of(uint8_t format, bool first)
{
    ssda_view_t v;
    const void *p = format == SSDA_PIX_U16 ? (first ? (const void *)g_f16 : (const void *)g_s16)
                                           : (first ? (const void *)g_f8 : (const void *)g_s8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, p, IW, IH, IW * format, (ssda_pixfmt_t)format));
    return v;
}

/* Store one image on its device and initialise a source over it. */
static void make_source(ssda_source_t *s, bool first, const geometry_t *g, uint8_t format,
                        size_t arena_size)
{
    ssda_view_t v = view_of(format, first);
    test_source_t *dev = first ? &g_tf : &g_ts;
    uint32_t row = g->layout == SSDA_LAYOUT_TILED ? g->tile_w * format : IW * format;
    ssda_source_config_t c;
    test_source_init(dev, first ? g_fdev : g_sdev, (uint32_t)sizeof g_fdev, g->read_size);
    c = test_source_config(dev, &v, g->layout, g->tile_w, g->tile_h, g->offset, row + g->pad, 0u,
                           g->read_size, first ? (void *)g_farena : (void *)g_sarena, arena_size);
    test_source_store(dev, &c, &v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(s, &c));
}

static ssda_track_config_t track_config(void)
{
    ssda_track_config_t c;
    memset(&c, 0, sizeof c);
    c.win_w = 8;
    c.win_h = 8;
    c.search_w = 16;
    c.search_h = 12;
    c.step_x = 6;
    c.step_y = 5;
    c.predict = SSDA_TRACK_PREDICT_LEFT; /* strips (MEDIAN would take one full-width strip) */
    c.match.flags = SSDA_MATCH_BOUNDS;
    c.match.work = g_work;
    c.match.work_size = sizeof g_work;
    return c;
}

static void assert_same_vectors(uint32_t n)
{
    uint32_t k;
    for (k = 0; k < n; k++) {
        TEST_ASSERT_EQUAL_UINT64(g_want[k].sad, g_got[k].sad);
        TEST_ASSERT_EQUAL_INT32(g_want[k].dx, g_got[k].dx);
        TEST_ASSERT_EQUAL_INT32(g_want[k].dy, g_got[k].dy);
        TEST_ASSERT_EQUAL_UINT16(g_want[k].x, g_got[k].x);
        TEST_ASSERT_EQUAL_UINT16(g_want[k].y, g_got[k].y);
        TEST_ASSERT_EQUAL_UINT8(g_want[k].status, g_got[k].status);
        TEST_ASSERT_EQUAL(g_want[k].exact, g_got[k].exact);
    }
}

static void assert_same_stats(const ssda_track_stats_t *a, const ssda_track_stats_t *b)
{
    TEST_ASSERT_EQUAL_UINT64(a->pixel_ops, b->pixel_ops);
    TEST_ASSERT_EQUAL_UINT64(a->positions, b->positions);
    TEST_ASSERT_EQUAL_UINT64(a->completed, b->completed);
    TEST_ASSERT_EQUAL_UINT32(a->windows, b->windows);
    TEST_ASSERT_EQUAL_UINT32(a->ok, b->ok);
    TEST_ASSERT_EQUAL_UINT32(a->edge, b->edge);
}

/* One depth and geometry: a clean streamed run (equal to ssda_track),
   then for each device and each read k of that run: fail read k, check
   the code and untouched stats, and run the same job again on the same
   sources. */
static void track_sweep(uint8_t format, const geometry_t *g, size_t arena_f, size_t arena_s)
{
    ssda_track_config_t c = track_config();
    ssda_view_t fv = view_of(format, true), sv = view_of(format, false);
    ssda_source_t f, s;
    ssda_track_stats_t ram, clean, st, poison;
    ssda_track_grid_t grid;
    uint64_t n[2], k;
    uint32_t dev;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
    TEST_ASSERT_TRUE(grid.count <= MAX_WIN);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, &c, g_want, MAX_WIN, &ram));
    TEST_ASSERT_TRUE(ram.ok > grid.count / 2u);
    make_source(&f, true, g, format, arena_f);
    make_source(&s, false, g, format, arena_s);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &clean));
    assert_same_vectors(grid.count);
    n[0] = g_tf.reads;
    n[1] = g_ts.reads;
    TEST_ASSERT_TRUE(n[0] > 4u && n[1] > 4u);
    memset(&poison, 0x4E, sizeof poison);
    for (dev = 0; dev < 2u; dev++) {
        test_source_t *t = dev == 0u ? &g_tf : &g_ts;
        for (k = 0; k < n[dev]; k++) {
            make_source(&f, true, g, format, arena_f);
            make_source(&s, false, g, format, arena_s);
            t->fail_at_read = (int64_t)k;
            t->fail_code = fail_code(k);
            st = poison;
            TEST_ASSERT_EQUAL_INT(fail_code(k), ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
            TEST_ASSERT_EQUAL_UINT64(1, t->failures);
            /* the same sources, at once: the whole job again */
            t->fail_at_read = -1;
            memset(g_got, 0, sizeof g_got);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &st));
            assert_same_vectors(grid.count);
            assert_same_stats(&clean, &st);
            TEST_ASSERT_EQUAL_UINT64(0, g_tf.contract_violations + g_ts.contract_violations);
        }
    }
}

static void test_track_fails_at_every_read_and_the_same_sources_recover(void)
{
    uint32_t gi;
    make_images(81u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        const geometry_t *g = &k_geoms[gi];
        /* plates of a few rows: many reads, strips narrower than the grid */
        size_t af = SSDA_SOURCE_SIZE(g->layout, 22u, 13u, 2u, g->read_size, g->tile_w);
        size_t as = SSDA_SOURCE_SIZE(g->layout, 14u, 9u, 2u, g->read_size, g->tile_w);
        track_sweep(gi % 2u == 0u ? SSDA_PIX_U8 : SSDA_PIX_U16, g, af, as);
    }
}

/* Push-mode search, window streamed: a failure at read k of the window
   comes back from the push of the area's last row; the result stays
   untouched and the job stops. A new job on the same window source and
   ring then gives ssda_match's result. */
static void test_push_search_fails_at_every_window_read(void)
{
    static const ssda_rect_t area = {3, 4, 30, 22}, win = {9, 6, 12, 9};
    static const uint8_t formats[] = {SSDA_PIX_U8, SSDA_PIX_U16};
    uint32_t fi;
    make_images(82u);
    for (fi = 0; fi < 2u; fi++) {
        uint8_t format = formats[fi];
        const geometry_t *g = &k_geoms[fi == 0u ? 3u : 1u];
        /* the whole window: a push search's minimum since issue 22 */
        size_t arena = SSDA_SOURCE_SIZE(g->layout, 12u, 9u, 2u, g->read_size, g->tile_w);
        size_t ring = SSDA_PUSH_SIZE(area.width, area.height, format);
        ssda_view_t fv = view_of(format, true), sv = view_of(format, false), ar, wr;
        ssda_match_config_t c;
        ssda_match_result_t want, got, poison;
        ssda_source_t ws;
        ssda_push_t p;
        uint64_t n, k;
        uint32_t y;
        memset(&c, 0, sizeof c);
        c.order = SSDA_ORDER_SPREAD;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&ar, &fv, area.x, area.y, area.width, area.height));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wr, &sv, win.x, win.y, win.width, win.height));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&ar, &wr, &c, &want));
        make_source(&ws, false, g, format, arena);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, format, &area, &ws, &win, &c,
                                                            &got, g_ring, ring));
        for (y = 0; y < IH; y++) {
            TEST_ASSERT_EQUAL_INT(y + 1u == (uint32_t)area.y + area.height ? 1 : 0,
                                  ssda_push_row(&p, ssda_view_row(&fv, y)));
        }
        n = g_ts.reads;
        TEST_ASSERT_TRUE(n >= 2u); /* the window, read once: a read per tile or row run */
        memset(&poison, 0x3D, sizeof poison);
        for (k = 0; k < n; k++) {
            make_source(&ws, false, g, format, arena);
            g_ts.fail_at_read = (int64_t)k;
            g_ts.fail_code = fail_code(k);
            got = poison;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, format, &area, &ws, &win,
                                                                &c, &got, g_ring, ring));
            for (y = 0; y + 1u < (uint32_t)area.y + area.height; y++) {
                TEST_ASSERT_EQUAL_INT(0, ssda_push_row(&p, ssda_view_row(&fv, y)));
            }
            TEST_ASSERT_EQUAL_INT(fail_code(k), ssda_push_row(&p, ssda_view_row(&fv, y)));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
            TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_push_row(&p, ssda_view_row(&fv, y + 1u)));
            /* a new job, the same source and ring */
            g_ts.fail_at_read = -1;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, format, &area, &ws, &win,
                                                                &c, &got, g_ring, ring));
            for (y = 0; y < (uint32_t)area.y + area.height; y++) {
                (void)ssda_push_row(&p, ssda_view_row(&fv, y));
            }
            TEST_ASSERT_EQUAL_UINT64(want.sad, got.sad);
            TEST_ASSERT_EQUAL_UINT16(want.x, got.x);
            TEST_ASSERT_EQUAL_UINT16(want.y, got.y);
            TEST_ASSERT_EQUAL_UINT64(want.pixel_ops, got.pixel_ops);
            TEST_ASSERT_EQUAL_UINT32(want.positions, got.positions);
            TEST_ASSERT_EQUAL(want.exact, got.exact);
        }
    }
}

/* Push-mode tracking with FIRST pushed and SECOND streamed (the stream
   tests sweep the other role): every read of SECOND fails in turn; the
   failing push returns the code, later pushes SSDA_ERR_STATE, stats stay
   untouched; a new job on the same source gives ssda_track's vectors. */
static void test_push_tracking_first_pushed_fails_at_every_read(void)
{
    const geometry_t *g = &k_geoms[2];
    ssda_track_config_t c = track_config();
    ssda_view_t fv, sv;
    ssda_track_grid_t grid;
    ssda_track_stats_t ram, st, poison;
    ssda_source_t s;
    ssda_push_t p;
    /* a band of windows as wide as the image: the minimum since issue 22 */
    size_t arena = SSDA_SOURCE_SIZE(g->layout, IW, 8u, 2u, g->read_size, g->tile_w);
    size_t ring = SSDA_PUSH_SIZE(IW, 12u, 2u);
    uint64_t n, k;
    uint32_t y;
    make_images(83u);
    fv = view_of(SSDA_PIX_U16, true);
    sv = view_of(SSDA_PIX_U16, false);
    c.predict = SSDA_TRACK_PREDICT_LEFT;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, &c, g_want, MAX_WIN, &ram));
    make_source(&s, false, g, SSDA_PIX_U16, arena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, SSDA_PIX_U16, SSDA_PUSH_FIRST, &s,
                                                        &c, g_got, MAX_WIN, &st, g_ring, ring));
    for (y = 0; y < IH; y++) {
        TEST_ASSERT_TRUE(ssda_push_row(&p, ssda_view_row(&fv, y)) >= 0);
    }
    assert_same_vectors(grid.count);
    n = g_ts.reads;
    TEST_ASSERT_TRUE(n > 4u);
    memset(&poison, 0x21, sizeof poison);
    for (k = 0; k < n; k++) {
        int failed = 0, r;
        make_source(&s, false, g, SSDA_PIX_U16, arena);
        g_ts.fail_at_read = (int64_t)k;
        g_ts.fail_code = fail_code(k);
        st = poison;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, SSDA_PIX_U16, SSDA_PUSH_FIRST,
                                                            &s, &c, g_got, MAX_WIN, &st, g_ring, ring));
        for (y = 0; y < IH; y++) {
            r = ssda_push_row(&p, ssda_view_row(&fv, y));
            if (failed) {
                TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, r);
            } else if (r < 0) {
                TEST_ASSERT_EQUAL_INT(fail_code(k), r);
                failed = 1;
            }
        }
        TEST_ASSERT_EQUAL_INT(1, failed);
        TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
        g_ts.fail_at_read = -1;
        memset(g_got, 0, sizeof g_got);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, SSDA_PIX_U16, SSDA_PUSH_FIRST,
                                                            &s, &c, g_got, MAX_WIN, &st, g_ring, ring));
        for (y = 0; y < IH; y++) {
            TEST_ASSERT_TRUE(ssda_push_row(&p, ssda_view_row(&fv, y)) >= 0);
        }
        assert_same_vectors(grid.count);
        TEST_ASSERT_EQUAL_UINT32(ram.ok, st.ok);
        TEST_ASSERT_EQUAL_UINT32(ram.windows, st.windows);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_track_fails_at_every_read_and_the_same_sources_recover);
    RUN_TEST(test_push_search_fails_at_every_window_read);
    RUN_TEST(test_push_tracking_first_pushed_fails_at_every_read);
    return UNITY_END();
}
