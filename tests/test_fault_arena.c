/*
 * test_fault_arena.c - arena and ring sizes at every boundary, for every
 * layout, depth and read granularity:
 *   - one byte below SSDA_SOURCE_SIZE(.., 1, 1, ..) init refuses with
 *     SSDA_ERR_BUFFER and leaves the source untouched; at the minimum it
 *     works (every pixel comes back through ssda_source_row);
 *   - one byte below a job's documented minimum the job refuses with
 *     SSDA_ERR_BUFFER before any read, result untouched; at the minimum,
 *     and at every size where the plate gains a row (and one byte below
 *     it), the job equals the in-RAM call (ssda_match field for field,
 *     ssda_track's vectors);
 *   - push mode: a ring one byte short is refused with the job untouched,
 *     the exact ring works.
 */
#include <string.h>

#include "unity.h"
#include "ssda/stream.h"
#include "test_image.h"
#include "test_rng.h"
#include "test_source.h"
#include "test_push.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 28u
#define IH 22u
#define MAX_WIN 32u

static uint16_t g_a16[IH][IW], g_b16[IH][IW];
static uint8_t g_a8[IH][IW], g_b8[IH][IW];
static uint8_t g_adev[4096], g_bdev[4096];
static uint32_t g_aarena[400], g_barena[400]; /* 1600 bytes each */
static uint32_t g_ring[IW * IH * 2u / 4u];
static uint32_t g_work[SSDA_MATCH_WORK_SIZE(IW, IH, 8, 6) / 4u];
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];
static test_source_t g_ta, g_tb;

typedef struct {
    uint8_t layout;
    uint16_t tile_w, tile_h;
    uint32_t read_size;
} geometry_t;

/* Raster and tiled (edge tiles partly outside the image), read sizes 1,
   4 and 16 bytes (multiples of both pixel sizes). */
static const geometry_t k_geoms[] = {
    {SSDA_LAYOUT_RASTER, 0, 0, 1},  {SSDA_LAYOUT_RASTER, 0, 0, 4},
    {SSDA_LAYOUT_RASTER, 0, 0, 16}, {SSDA_LAYOUT_TILED, 8, 6, 1},
    {SSDA_LAYOUT_TILED, 8, 6, 4},   {SSDA_LAYOUT_TILED, 5, 4, 16},
};
#define N_GEOMS (sizeof k_geoms / sizeof k_geoms[0])

static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_12bit(&g_a16[0][0], &g_a8[0][0], IW, IH, &r);
    for (y = 0; y < IH; y++) { /* b: a moved by (-1, +2), wrapped */
        for (x = 0; x < IW; x++) {
            g_b16[y][x] = g_a16[(y + IH - 2u) % IH][(x + 1u) % IW];
            g_b8[y][x] = g_a8[(y + IH - 2u) % IH][(x + 1u) % IW];
        }
    }
}

static ssda_view_t view_of(uint8_t format, bool a)
{
    ssda_view_t v;
    const void *p = format == SSDA_PIX_U16 ? (a ? (const void *)g_a16 : (const void *)g_b16)
                                           : (a ? (const void *)g_a8 : (const void *)g_b8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, p, IW, IH, IW * format, (ssda_pixfmt_t)format));
    return v;
}

/* Store image a or b for g and return the config (arena of arena_size). */
static ssda_source_config_t store(bool a, const geometry_t *g, uint8_t format, size_t arena_size)
{
    ssda_view_t v = view_of(format, a);
    test_source_t *dev = a ? &g_ta : &g_tb;
    ssda_source_config_t c;
    TEST_ASSERT_TRUE(arena_size <= sizeof g_aarena);
    test_source_init(dev, a ? g_adev : g_bdev, (uint32_t)sizeof g_adev, g->read_size);
    c = test_source_config(dev, &v, g->layout, g->tile_w, g->tile_h, 0u, 0u, 0u, g->read_size,
                           a ? (void *)g_aarena : (void *)g_barena, arena_size);
    test_source_store(dev, &c, &v);
    return c;
}

static void make_source(ssda_source_t *s, bool a, const geometry_t *g, uint8_t format,
                        size_t arena_size)
{
    ssda_source_config_t c = store(a, g, format, arena_size);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(s, &c));
}

static size_t source_size(const geometry_t *g, uint8_t format, uint32_t w, uint32_t h)
{
    return SSDA_SOURCE_SIZE(g->layout, w, h, format, g->read_size, g->tile_w);
}

static void test_init_refuses_one_byte_below_the_minimum_and_the_minimum_works(void)
{
    uint32_t gi, fi, x, y;
    make_images(91u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        for (fi = 1; fi <= 2u; fi++) {
            const geometry_t *g = &k_geoms[gi];
            uint8_t format = (uint8_t)fi;
            size_t min = source_size(g, format, 1u, 1u);
            ssda_source_config_t c = store(true, g, format, min - 1u);
            ssda_view_t v = view_of(format, true);
            ssda_source_t s, poison;
            memset(&poison, 0x7C, sizeof poison);
            s = poison;
            TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_source_init(&s, &c));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &s, sizeof s);
            c.arena_size = min;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
            for (y = 0; y < IH; y++) { /* pixel by pixel, bottom-up on odd rows */
                for (x = 0; x < IW; x++) {
                    const uint8_t *px;
                    uint32_t xx = y % 2u ? IW - 1u - x : x;
                    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, xx, y, 1u, &px));
                    TEST_ASSERT_EQUAL_MEMORY(ssda_view_row(&v, y) + xx * format, px, format);
                }
            }
            TEST_ASSERT_EQUAL_UINT64(0, g_ta.contract_violations);
        }
    }
}

static void assert_same_result(const ssda_match_result_t *a, const ssda_match_result_t *b)
{
    TEST_ASSERT_EQUAL_UINT64(a->sad, b->sad);
    TEST_ASSERT_EQUAL_UINT64(a->pixel_ops, b->pixel_ops);
    TEST_ASSERT_EQUAL_UINT32(a->positions, b->positions);
    TEST_ASSERT_EQUAL_UINT32(a->completed, b->completed);
    TEST_ASSERT_EQUAL_UINT16(a->x, b->x);
    TEST_ASSERT_EQUAL_UINT16(a->y, b->y);
    TEST_ASSERT_EQUAL(a->exact, b->exact);
}

/* ssda_stream_match with the area (image a, whole) or the window (a
   rectangle of b) streamed at arena `size`: BUFFER before any read below
   `min`, else the in-RAM result. */
static void match_at(const geometry_t *g, uint8_t format, bool bounds, bool area_streamed,
                     size_t size, size_t min)
{
    static const ssda_rect_t wr = {10, 7, 8, 6};
    ssda_view_t av = view_of(format, true), bv = view_of(format, false), wv;
    ssda_source_t as, ws;
    ssda_match_config_t c;
    ssda_match_result_t want, got, poison;
    int rc;
    memset(&c, 0, sizeof c);
    if (bounds) {
        c.flags = SSDA_MATCH_BOUNDS;
        c.work = g_work;
        c.work_size = sizeof g_work;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wv, &bv, wr.x, wr.y, wr.width, wr.height));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&av, &wv, &c, &want));
    if (area_streamed) {
        make_source(&as, true, g, format, size);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ws, &bv));
    } else {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&as, &av));
        make_source(&ws, false, g, format, size);
    }
    test_source_reset(&g_ta); /* counts of this call only */
    test_source_reset(&g_tb);
    memset(&poison, 0x6B, sizeof poison);
    got = poison;
    rc = ssda_stream_match(&as, NULL, &ws, &wr, &c, &got);
    if (size < min) {
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, rc);
        TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
        TEST_ASSERT_EQUAL_UINT64(0, g_ta.reads + g_tb.reads);
    } else {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, rc);
        assert_same_result(&want, &got);
        TEST_ASSERT_EQUAL_UINT64(0, g_ta.contract_violations + g_tb.contract_violations);
    }
}

static void test_match_arena_at_every_row_boundary(void)
{
    uint32_t gi, fi, b, h;
    make_images(92u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        for (fi = 1; fi <= 2u; fi++) {
            for (b = 0; b < 2u; b++) {
                const geometry_t *g = &k_geoms[gi];
                uint8_t format = (uint8_t)fi;
                /* the documented minimum (issue 22): a band of window-height
                   rows as wide as the area (raster scan), bounds or not */
                uint32_t span = b ? IW : 8u;
                size_t min = source_size(g, format, IW, 6u);
                match_at(g, format, b != 0u, true, min - 1u, min);
                for (h = 1; h <= IH; h++) { /* the plate gains a row at each */
                    size_t at_span = source_size(g, format, span, h);
                    size_t at_full = source_size(g, format, IW, h);
                    match_at(g, format, b != 0u, true, at_span, min);
                    match_at(g, format, b != 0u, true, at_span - 1u, min);
                    match_at(g, format, b != 0u, true, at_full, min);
                    match_at(g, format, b != 0u, true, at_full - 1u, min);
                }
                /* a streamed window: the whole window (8 x 6) */
                min = source_size(g, format, 8u, 6u);
                match_at(g, format, b != 0u, false, min - 1u, min);
                for (h = 1; h <= 7u; h++) {
                    match_at(g, format, b != 0u, false, source_size(g, format, 8u, h), min);
                    match_at(g, format, b != 0u, false, source_size(g, format, 8u, h) - 1u, min);
                }
            }
        }
    }
}

static ssda_track_config_t track_config(void)
{
    ssda_track_config_t c;
    memset(&c, 0, sizeof c);
    c.win_w = 8;
    c.win_h = 6;
    c.search_w = 14;
    c.search_h = 10;
    c.step_x = 5;
    c.step_y = 4;
    c.predict = SSDA_TRACK_PREDICT_LEFT; /* MEDIAN takes one full-width strip */
    /* a region where every search area fits: the push rings then need
       exactly the strips of SSDA_STREAM_STRIP_W (EDGE columns are not kept) */
    c.roi_x = 3;
    c.roi_y = 2;
    c.roi_w = IW - 6u;
    c.roi_h = IH - 4u;
    return c;
}

/* ssda_stream_track with FIRST (image a) and SECOND (b) streamed at the
   given arenas: BUFFER before any read if either is below its minimum,
   else ssda_track's vectors. */
static void track_at(const geometry_t *g, uint8_t format, size_t af, size_t as, size_t min_f,
                     size_t min_s)
{
    ssda_track_config_t c = track_config();
    ssda_view_t av = view_of(format, true), bv = view_of(format, false);
    ssda_source_t f, s;
    ssda_track_grid_t grid;
    ssda_track_stats_t want, got, poison;
    uint32_t k;
    int rc;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &grid));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&av, &bv, &c, g_want, MAX_WIN, &want));
    make_source(&f, true, g, format, af);
    make_source(&s, false, g, format, as);
    memset(&poison, 0x4E, sizeof poison);
    got = poison;
    memset(g_got, 0, sizeof g_got);
    rc = ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, &got);
    if (af < min_f || as < min_s) {
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, rc);
        TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
        TEST_ASSERT_EQUAL_UINT64(0, g_ta.reads + g_tb.reads);
        return;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, rc);
    for (k = 0; k < grid.count; k++) {
        TEST_ASSERT_EQUAL_UINT64(g_want[k].sad, g_got[k].sad);
        TEST_ASSERT_EQUAL_INT32(g_want[k].dx, g_got[k].dx);
        TEST_ASSERT_EQUAL_INT32(g_want[k].dy, g_got[k].dy);
        TEST_ASSERT_EQUAL_UINT8(g_want[k].status, g_got[k].status);
        TEST_ASSERT_EQUAL(g_want[k].exact, g_got[k].exact);
    }
    TEST_ASSERT_EQUAL_UINT32(want.ok, got.ok);
    TEST_ASSERT_EQUAL_UINT32(want.edge, got.edge);
    TEST_ASSERT_EQUAL_UINT64(0, g_ta.contract_violations + g_tb.contract_violations);
}

static void test_track_arena_at_every_row_boundary(void)
{
    uint32_t gi, fi, h;
    make_images(93u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        for (fi = 1; fi <= 2u; fi++) {
            const geometry_t *g = &k_geoms[gi];
            uint8_t format = (uint8_t)fi;
            /* a band of one grid column (issue 22): 14 x 10 areas, 8 x 6 windows */
            size_t min_f = source_size(g, format, 14u, 10u), min_s = source_size(g, format, 8u, 6u);
            size_t big_f = source_size(g, format, IW, IH), big_s = source_size(g, format, IW, IH);
            track_at(g, format, min_f - 1u, big_s, min_f, min_s);
            track_at(g, format, big_f, min_s - 1u, min_f, min_s);
            track_at(g, format, min_f, min_s, min_f, min_s);
            for (h = 1; h <= 12u; h++) { /* one strip, then the whole grid width */
                size_t f1 = source_size(g, format, 14u, h), s1 = source_size(g, format, 8u, h);
                size_t fw = source_size(g, format, IW, h), sw = source_size(g, format, IW, h);
                track_at(g, format, f1, s1, min_f, min_s);
                track_at(g, format, f1 - 1u, s1 - 1u, min_f, min_s);
                track_at(g, format, fw, sw, min_f, min_s);
                track_at(g, format, fw - 1u, sw - 1u, min_f, min_s);
            }
        }
    }
}

/* Rings: one byte short refused (job untouched), the exact size works. */
static void test_push_rings_at_their_minimum(void)
{
    static const ssda_rect_t ar = {2, 3, 20, 16}, wr = {10, 7, 8, 6};
    ssda_track_config_t tc = track_config();
    ssda_track_grid_t grid;
    ssda_track_stats_t st;
    uint32_t fi, role, y, k;
    make_images(94u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&tc, IW, IH, &grid));
    for (fi = 1; fi <= 2u; fi++) {
        uint8_t format = (uint8_t)fi;
        ssda_view_t av = view_of(format, true), bv = view_of(format, false), a2, w2;
        ssda_source_t ws;
        ssda_push_t p, poison;
        ssda_match_result_t want, got;
        size_t ring = SSDA_PUSH_SIZE(ar.width, ar.height, format);
        memset(&poison, 0x2C, sizeof poison);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ws, &bv));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&a2, &av, ar.x, ar.y, ar.width, ar.height));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&w2, &bv, wr.x, wr.y, wr.width, wr.height));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&a2, &w2, NULL, &want));
        p = poison;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, test_push_init_match(&p, IW, IH, format, &ar, &ws, &wr,
                                                                    NULL, &got, g_ring, ring - 1u));
        TEST_ASSERT_EQUAL_MEMORY(&poison, &p, sizeof p);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, format, &ar, &ws, &wr, NULL,
                                                            &got, g_ring, ring));
        for (y = 0; y < IH; y++) {
            TEST_ASSERT_TRUE(ssda_push_row(&p, ssda_view_row(&av, y)) >= 0);
        }
        assert_same_result(&want, &got);
        /* tracking, either image pushed: the band's span and rows */
        for (role = 0; role < 2u; role++) {
            ssda_source_t other;
            ssda_track_stats_t want_st;
            uint32_t side = role == SSDA_PUSH_FIRST ? 14u : 8u;
            uint32_t band = role == SSDA_PUSH_FIRST ? 10u : 6u;
            uint32_t span = (uint32_t)SSDA_STREAM_STRIP_W(grid.cols, 5u, side);
            const ssda_view_t *pushed = role == SSDA_PUSH_FIRST ? &av : &bv;
            span = span < IW ? span : IW;
            ring = SSDA_PUSH_SIZE(span, band, format);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&av, &bv, &tc, g_want, MAX_WIN, &want_st));
            TEST_ASSERT_EQUAL_UINT32(0, want_st.edge); /* every column kept in the ring */
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&other, role == SSDA_PUSH_FIRST
                                                                             ? &bv : &av));
            p = poison;
            TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                                  test_push_init_track(&p, IW, IH, format, (uint8_t)role, &other, &tc,
                                                       g_got, MAX_WIN, &st, g_ring, ring - 1u));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &p, sizeof p);
            TEST_ASSERT_EQUAL_INT(SSDA_OK,
                                  test_push_init_track(&p, IW, IH, format, (uint8_t)role, &other, &tc,
                                                       g_got, MAX_WIN, &st, g_ring, ring));
            for (y = 0; y < IH; y++) {
                TEST_ASSERT_TRUE(ssda_push_row(&p, ssda_view_row(pushed, y)) >= 0);
            }
            for (k = 0; k < grid.count; k++) {
                TEST_ASSERT_EQUAL_UINT64(g_want[k].sad, g_got[k].sad);
                TEST_ASSERT_EQUAL_INT32(g_want[k].dx, g_got[k].dx);
                TEST_ASSERT_EQUAL_INT32(g_want[k].dy, g_got[k].dy);
                TEST_ASSERT_EQUAL_UINT8(g_want[k].status, g_got[k].status);
            }
            TEST_ASSERT_EQUAL_UINT32(want_st.ok, st.ok);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_init_refuses_one_byte_below_the_minimum_and_the_minimum_works);
    RUN_TEST(test_match_arena_at_every_row_boundary);
    RUN_TEST(test_track_arena_at_every_row_boundary);
    RUN_TEST(test_push_rings_at_their_minimum);
    return UNITY_END();
}
