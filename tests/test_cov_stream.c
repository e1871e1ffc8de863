/*
 * test_cov_stream.c - stream sources and jobs at the corners the main
 * stream tests leave out (found by branch coverage, tools/coverage.sh):
 * read_size 0 as 1, tile geometry beyond 32-bit addresses, rectangles
 * outside their sources, spans wider than the arena, one in-RAM source
 * as both operands, grids whose first row or every row needs no border
 * handling, AUTO with the coarse scan, default configs and NULL stats.
 * References: the image's own pixels, brute-force search (test_best),
 * ssda_track in RAM, and documented error codes with outputs untouched.
 */
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "ssda/track.h"
#include "test_image.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 72u
#define IH 60u
static uint8_t g_img[IH][IW];     /* FIRST / area image */
static uint8_t g_moved[IH][IW];   /* SECOND: g_img moved by (SHIFT_X, SHIFT_Y) */
static uint8_t g_dev[6144], g_dev2[6144]; /* 72 x 60 as 16 x 16 tiles: 5120 */
static uint32_t g_arena[1024], g_arena2[1024]; /* 4 KB each */
static test_source_t g_t, g_t2;
#define MAX_WIN 64u
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];

#define SHIFT_X 3
#define SHIFT_Y -2

/* Textured FIRST; SECOND(x, y) = FIRST(x - SHIFT_X, y - SHIFT_Y) (wrapped),
   so every window fully inside gets the vector (SHIFT_X, SHIFT_Y). */
static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u8(&g_img[0][0], IW, IH, IW, &r);
    /* SHIFT_Y = -2: row y of SECOND is row y + 2 of FIRST */
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            g_moved[y][x] = g_img[(y + 2u) % IH][(x + IW - 3u) % IW];
        }
    }
}

static ssda_view_t view_of(uint8_t (*img)[IW])
{
    ssda_view_t v;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, img, IW, IH, IW, SSDA_PIX_U8));
    return v;
}

/* img stored raster in dev (granularity rs) and a source over it. */
static ssda_source_config_t streamed(ssda_source_t *s, test_source_t *dev, uint8_t *bytes,
                                     size_t cap, const ssda_view_t *img, uint32_t read_size,
                                     void *arena, size_t arena_size)
{
    ssda_source_config_t c;
    test_source_init(dev, bytes, (uint32_t)cap, read_size == 0u ? 1u : read_size);
    c = test_source_config(dev, img, SSDA_LAYOUT_RASTER, 0, 0, 0u, 0u, 0u, read_size, arena,
                           arena_size);
    test_source_store(dev, &c, img);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(s, &c));
    return c;
}

static void test_read_size_zero_reads_like_one(void)
{
    ssda_view_t v = view_of(g_img);
    ssda_source_t s0, s1;
    uint32_t y;
    make_images(1u);
    (void)streamed(&s0, &g_t, g_dev, sizeof g_dev, &v, 0u, g_arena, 400u);
    (void)streamed(&s1, &g_t2, g_dev2, sizeof g_dev2, &v, 1u, g_arena2, 400u);
    TEST_ASSERT_EQUAL_UINT32(1u, s0.cfg.read_size); /* the resolved copy */
    for (y = 0; y < IH; y++) {
        const uint8_t *p0, *p1;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s0, 5u, y, 40u, &p0));
        TEST_ASSERT_EQUAL_MEMORY(&g_img[y][5], p0, 40u);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s1, 5u, y, 40u, &p1));
    }
    TEST_ASSERT_EQUAL_UINT64(s1.stats.bytes_read, s0.stats.bytes_read);
    TEST_ASSERT_EQUAL_UINT64(s1.stats.reads, s0.stats.reads);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.contract_violations);
}

/* A tiled configuration whose tile does not fit 32-bit addresses. */
static void test_tiles_beyond_32_bits_are_size_errors(void)
{
    ssda_source_config_t c;
    ssda_source_t s, before;
    memset(&c, 0, sizeof c);
    c.read = test_source_read;
    c.context = &g_t;
    c.arena = g_arena;
    c.arena_size = sizeof g_arena;
    c.width = 1;
    c.height = 1;
    c.format = SSDA_PIX_U8;
    c.layout = SSDA_LAYOUT_TILED;
    c.tile_w = 1;
    memset(&s, 0x5A, sizeof s);
    before = s;
    /* (tile_h - 1) * stride + row = 65534 * 70000 + 1 > 2^32 */
    c.tile_h = 65535;
    c.stride = 70000u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_source_init(&s, &c));
    /* the tile fits (2^31 + 1) but the default tile_stride 2 * 2^31 does not */
    c.tile_h = 2;
    c.stride = 0x80000000u;
    c.tile_stride = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_source_init(&s, &c));
    TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
    /* the same tile with its stride given explicitly is accepted */
    c.tile_stride = 0x80000001u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    TEST_ASSERT_EQUAL_UINT32(0x80000001u, s.cfg.tile_stride);
}

static void test_rectangles_outside_or_taller_are_refused(void)
{
    ssda_view_t v = view_of(g_img);
    ssda_source_t a, w;
    ssda_match_result_t res, poison;
    ssda_rect_t ar = {4, 6, 30, 20}, wr = {0, 0, 8, 8};
    make_images(2u);
    (void)streamed(&a, &g_t, g_dev, sizeof g_dev, &v, 4u, g_arena, sizeof g_arena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&w, &v));
    memset(&poison, 0x3C, sizeof poison);
    res = poison;
    ar.height = 0; /* empty */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&a, &ar, &w, &wr, NULL, &res));
    ar.height = (uint16_t)(IH - ar.y + 1u); /* one row below the image */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&a, &ar, &w, &wr, NULL, &res));
    ar.height = 7;
    wr.height = 8; /* window taller than the area, as wide */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&a, &ar, &w, &wr, NULL, &res));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads);
    /* the area one row taller works and finds the window where it is */
    ar.height = 8;
    wr.x = 10;
    wr.y = 6;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&a, &ar, &w, &wr, NULL, &res));
    {
        ssda_view_t av, wv;
        uint32_t bx, by;
        uint64_t bs;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&av, &v, ar.x, ar.y, ar.width, ar.height));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wv, &v, wr.x, wr.y, wr.width, wr.height));
        test_best(&av, &wv, &bx, &by, &bs);
        TEST_ASSERT_EQUAL_UINT32(bx, res.x);
        TEST_ASSERT_EQUAL_UINT32(by, res.y);
        TEST_ASSERT_EQUAL_UINT64(bs, res.sad);
        TEST_ASSERT_EQUAL_UINT64(0u, bs); /* the window is a part of the area */
    }
}

static void test_row_wider_than_the_arena_is_a_buffer_error(void)
{
    ssda_view_t v = view_of(g_img);
    ssda_source_t s;
    const uint8_t *px = NULL, *poison = (const uint8_t *)&g_t;
    /* 12 plate bytes: rows of at most 12 pixels */
    make_images(3u);
    (void)streamed(&s, &g_t, g_dev, sizeof g_dev, &v, 1u, g_arena,
                   SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 12u, 1u, 1u, 1u, 0u));
    px = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_source_row(&s, 3u, 9u, 13u, &px));
    TEST_ASSERT_EQUAL_PTR(poison, px);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, 3u, 9u, 12u, &px));
    TEST_ASSERT_EQUAL_MEMORY(&g_img[9][3], px, 12u);
}

/* One in-RAM source is both the area and the window: allowed (nothing is
   paged), and a rectangle of the image is found where it was cut. */
static void test_one_in_ram_source_as_both_operands(void)
{
    ssda_view_t v = view_of(g_img), wv;
    ssda_source_t s;
    ssda_match_result_t res;
    const ssda_rect_t wr = {41, 17, 9, 7};
    uint32_t bx, by;
    uint64_t bs;
    make_images(4u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&s, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&s, NULL, &s, &wr, NULL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wv, &v, wr.x, wr.y, wr.width, wr.height));
    test_best(&v, &wv, &bx, &by, &bs);
    TEST_ASSERT_EQUAL_UINT32(bx, res.x);
    TEST_ASSERT_EQUAL_UINT32(by, res.y);
    TEST_ASSERT_EQUAL_UINT64(0u, res.sad);
    TEST_ASSERT_TRUE(res.exact);
    TEST_ASSERT_EQUAL_UINT32((IW - 9u + 1u) * (IH - 7u + 1u), res.positions);
}

/* Brute-force minimum of window rectangle wr of v over area rectangle ar. */
static void best_of(const ssda_view_t *v, const ssda_rect_t *ar, const ssda_rect_t *wr,
                    uint32_t *bx, uint32_t *by, uint64_t *bs)
{
    ssda_view_t av, wv;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&av, v, ar->x, ar->y, ar->width, ar->height));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wv, v, wr->x, wr->y, wr->width, wr->height));
    test_best(&av, &wv, bx, by, bs);
}

static void test_wider_window_and_empty_rectangle_are_refused(void)
{
    ssda_view_t v = view_of(g_img);
    ssda_source_t a, w;
    ssda_match_result_t res, poison;
    ssda_rect_t ar = {4, 6, 10, 20}, wr = {0, 0, 11, 8};
    make_images(9u);
    (void)streamed(&a, &g_t, g_dev, sizeof g_dev, &v, 1u, g_arena, sizeof g_arena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&w, &v));
    memset(&poison, 0x3C, sizeof poison);
    res = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&a, &ar, &w, &wr, NULL, &res));
    wr.width = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&a, &ar, &w, &wr, NULL, &res));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads);
}

/* After a job shaped the plate as narrow as its area (40 of 72 px), a
   wider row span reshapes it (the arena allows) and reads the right
   pixels. */
static void test_row_span_wider_than_a_jobs_plate(void)
{
    ssda_view_t v = view_of(g_img);
    ssda_source_t a, w;
    ssda_match_result_t res;
    const ssda_rect_t ar = {0, 0, 40, IH}, wr = {20, 30, 8, 6};
    const uint8_t *px;
    uint32_t bx, by;
    uint64_t bs;
    make_images(10u);
    /* room for 4 whole rows: the raster scan's band is 40 px x 7 rows */
    (void)streamed(&a, &g_t, g_dev, sizeof g_dev, &v, 1u, g_arena, 4u * IW);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&w, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&a, &ar, &w, &wr, NULL, &res));
    best_of(&v, &ar, &wr, &bx, &by, &bs);
    TEST_ASSERT_EQUAL_UINT32(bx, res.x);
    TEST_ASSERT_EQUAL_UINT32(by, res.y);
    TEST_ASSERT_EQUAL_UINT64(0u, res.sad);
    TEST_ASSERT_TRUE(a.plate.pw < IW);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&a, 1u, 33u, IW - 1u, &px));
    TEST_ASSERT_EQUAL_MEMORY(&g_img[33][1], px, IW - 1u);
}

/* The same job twice reads nothing the second time (its plate already
   holds the area: every span is a hit); a shorter area of the same width
   reshapes the plate and is still brute-force right. */
static void test_repeated_and_shorter_jobs(void)
{
    ssda_view_t v = view_of(g_img);
    ssda_source_t a, w;
    ssda_match_result_t r1, r2;
    ssda_rect_t ar = {6, 10, 40, 30};
    const ssda_rect_t wr = {30, 22, 9, 7};
    uint64_t bytes;
    uint32_t bx, by;
    uint64_t bs;
    make_images(11u);
    (void)streamed(&a, &g_t, g_dev, sizeof g_dev, &v, 4u, g_arena, sizeof g_arena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&w, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&a, &ar, &w, &wr, NULL, &r1));
    bytes = a.stats.bytes_read;
    TEST_ASSERT_TRUE(bytes > 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&a, &ar, &w, &wr, NULL, &r2));
    TEST_ASSERT_EQUAL_UINT64(bytes, a.stats.bytes_read);
    TEST_ASSERT_EQUAL_UINT64(r1.sad, r2.sad);
    TEST_ASSERT_EQUAL_UINT64(r1.pixel_ops, r2.pixel_ops);
    TEST_ASSERT_EQUAL_UINT32(r1.x, r2.x);
    TEST_ASSERT_EQUAL_UINT32(r1.y, r2.y);
    best_of(&v, &ar, &wr, &bx, &by, &bs);
    TEST_ASSERT_EQUAL_UINT32(bx, r1.x);
    TEST_ASSERT_EQUAL_UINT32(by, r1.y);
    TEST_ASSERT_EQUAL_UINT64(bs, r1.sad);
    ar.height = 14;
    ar.y = 19;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&a, &ar, &w, &wr, NULL, &r2));
    best_of(&v, &ar, &wr, &bx, &by, &bs);
    TEST_ASSERT_EQUAL_UINT32(bx, r2.x);
    TEST_ASSERT_EQUAL_UINT32(by, r2.y);
    TEST_ASSERT_EQUAL_UINT64(bs, r2.sad);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.contract_violations);
}

static bool same_vector(const ssda_track_vector_t *a, const ssda_track_vector_t *b)
{
    return a->sad == b->sad && a->dx == b->dx && a->dy == b->dy && a->x == b->x &&
           a->y == b->y && a->status == b->status && a->exact == b->exact;
}

/* Streamed FIRST and SECOND against ssda_track in RAM; returns the count. */
static uint32_t track_both_ways(const ssda_track_config_t *c, size_t arena_f, size_t arena_s)
{
    ssda_view_t fv = view_of(g_img), sv = view_of(g_moved);
    ssda_source_t f, s;
    ssda_track_grid_t g;
    uint32_t k;
    (void)streamed(&f, &g_t, g_dev, sizeof g_dev, &fv, 8u, g_arena, arena_f);
    (void)streamed(&s, &g_t2, g_dev2, sizeof g_dev2, &sv, 1u, g_arena2, arena_s);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(c, IW, IH, &g));
    TEST_ASSERT_TRUE(g.count <= MAX_WIN);
    memset(g_got, 0x77, sizeof g_got);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, c, g_want, MAX_WIN, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, c, g_got, MAX_WIN, NULL));
    for (k = 0; k < g.count; k++) {
        TEST_ASSERT_TRUE(same_vector(&g_want[k], &g_got[k]));
    }
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.contract_violations + g_t2.contract_violations);
    return g.count;
}

/* The grid starts hy rows down, so its first row needs no EDGE handling;
   every window inside gets the known shift. */
static void test_track_grid_without_edge_rows(void)
{
    ssda_track_config_t c;
    uint32_t k, n, ok = 0;
    make_images(5u);
    memset(&c, 0, sizeof c);
    c.win_w = c.win_h = 12;
    c.search_w = c.search_h = 20;
    c.roi_x = 4;
    c.roi_y = 4; /* = hy: the first grid row's areas start at row 0 */
    c.roi_w = IW - 8u;
    c.roi_h = IH - 8u;
    c.step_x = c.step_y = 12;
    n = track_both_ways(&c, 2000u, 1000u);
    TEST_ASSERT_EQUAL_UINT32(5u * 4u, n);
    for (k = 0; k < n; k++) {
        TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_got[k].status);
        TEST_ASSERT_EQUAL_INT32(SHIFT_X, g_got[k].dx);
        TEST_ASSERT_EQUAL_INT32(SHIFT_Y, g_got[k].dy);
        ok++;
    }
    TEST_ASSERT_EQUAL_UINT32(n, ok);
}

/* AUTO threshold with the coarse scan is an inexact mode: MEDIAN
   prediction is refused with it, LEFT-free tracking still equals RAM. */
static void test_track_coarse_scan_with_auto_threshold(void)
{
    ssda_track_config_t c;
    uint32_t k, n, ok = 0;
    make_images(6u);
    memset(&c, 0, sizeof c);
    c.win_w = c.win_h = 12;
    c.search_w = c.search_h = 24;
    c.match.scan = SSDA_SCAN_COARSE;
    c.match.coarse_step = 4;
    n = track_both_ways(&c, 1200u, 600u);
    for (k = 0; k < n; k++) {
        if (g_got[k].status == SSDA_TRACK_OK) {
            TEST_ASSERT_FALSE(g_got[k].exact); /* the coarse scan may miss */
            ok++;
        }
    }
    TEST_ASSERT_TRUE(ok > 0u);
}

/* FIRST smaller than one search area: every window is EDGE, nothing is read. */
static void test_track_with_every_area_outside_first(void)
{
    static uint8_t small[10][10];
    ssda_view_t fv, sv = view_of(g_moved);
    ssda_source_t f, s;
    ssda_track_stats_t st;
    uint32_t k;
    make_images(7u);
    memset(small, 9, sizeof small);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&fv, small, 10, 10, 10, SSDA_PIX_U8));
    test_source_init(&g_t, g_dev, sizeof g_dev, 1u);
    {
        ssda_source_config_t c = test_source_config(&g_t, &fv, SSDA_LAYOUT_RASTER, 0, 0, 0u, 0u,
                                                    0u, 1u, g_arena, sizeof g_arena);
        test_source_store(&g_t, &c, &fv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&f, &c));
    }
    (void)streamed(&s, &g_t2, g_dev2, sizeof g_dev2, &sv, 1u, g_arena2, sizeof g_arena2);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, NULL, g_got, MAX_WIN, &st));
    /* defaults: 16 x 16 windows, step 16: 4 x 3 grid on 72 x 60 */
    TEST_ASSERT_EQUAL_UINT32(12u, st.windows);
    TEST_ASSERT_EQUAL_UINT32(12u, st.edge);
    for (k = 0; k < 12u; k++) {
        TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EDGE, g_got[k].status);
    }
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads + g_t2.reads);
    /* FIRST as wide as SECOND but 20 rows tall: areas fit across, never down */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&fv, g_img, IW, 20, IW, SSDA_PIX_U8));
    test_source_init(&g_t, g_dev, sizeof g_dev, 1u);
    {
        ssda_source_config_t c = test_source_config(&g_t, &fv, SSDA_LAYOUT_RASTER, 0, 0, 0u, 0u,
                                                    0u, 1u, g_arena, sizeof g_arena);
        test_source_store(&g_t, &c, &fv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&f, &c));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, NULL, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_UINT32(12u, st.edge);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads + g_t2.reads);
}

/* Tiled sources with the smallest arenas (a band of one column since
   issue 22): no room for the bytes a band gains per step, so the plates
   are planned without it: still ssda_track's vectors, and the known
   shift. */
static void test_track_tiled_minimal_arenas(void)
{
    ssda_view_t fv = view_of(g_img), sv = view_of(g_moved);
    ssda_source_t f, s;
    ssda_track_config_t c;
    ssda_track_grid_t g;
    uint32_t k, ok = 0;
    make_images(12u);
    memset(&c, 0, sizeof c);
    c.win_w = c.win_h = 12;
    c.search_w = c.search_h = 20;
    c.step_x = c.step_y = 12;
    c.roi_x = c.roi_y = 4;
    c.roi_w = IW - 8u;
    c.roi_h = IH - 8u;
    {
        ssda_source_config_t fc, sc;
        test_source_init(&g_t, g_dev, sizeof g_dev, 1u);
        fc = test_source_config(&g_t, &fv, SSDA_LAYOUT_TILED, 16, 16, 0u, 0u, 0u, 1u, g_arena,
                                SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 20u, 20u, 1u, 1u, 16u));
        test_source_store(&g_t, &fc, &fv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&f, &fc));
        test_source_init(&g_t2, g_dev2, sizeof g_dev2, 1u);
        sc = test_source_config(&g_t2, &sv, SSDA_LAYOUT_TILED, 16, 16, 0u, 0u, 0u, 1u, g_arena2,
                                SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 12u, 12u, 1u, 1u, 16u));
        test_source_store(&g_t2, &sc, &sv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &sc));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &g));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, &c, g_want, MAX_WIN, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_track(&f, &s, &c, g_got, MAX_WIN, NULL));
    for (k = 0; k < g.count; k++) {
        TEST_ASSERT_TRUE(same_vector(&g_want[k], &g_got[k]));
        if (g_got[k].status == SSDA_TRACK_OK) {
            TEST_ASSERT_EQUAL_INT32(SHIFT_X, g_got[k].dx);
            TEST_ASSERT_EQUAL_INT32(SHIFT_Y, g_got[k].dy);
            ok++;
        }
    }
    TEST_ASSERT_EQUAL_UINT32(g.count, ok);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.contract_violations + g_t2.contract_violations);
}

static void test_track_refusals_leave_outputs_untouched(void)
{
    ssda_view_t fv = view_of(g_img);
    ssda_source_t f, zero;
    ssda_track_config_t c;
    ssda_track_stats_t st, poison;
    make_images(8u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&f, &fv));
    memset(&zero, 0, sizeof zero);
    memset(&poison, 0x4E, sizeof poison);
    memset(g_got, 0x6B, sizeof g_got);
    memcpy(g_want, g_got, sizeof g_got);
    st = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_track(&f, &zero, NULL, g_got, MAX_WIN, &st));
    memset(&c, 0, sizeof c);
    c.flags = 0x80; /* unknown flag */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_track(&f, &f, &c, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    TEST_ASSERT_EQUAL_MEMORY(g_want, g_got, sizeof g_got);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_read_size_zero_reads_like_one);
    RUN_TEST(test_tiles_beyond_32_bits_are_size_errors);
    RUN_TEST(test_rectangles_outside_or_taller_are_refused);
    RUN_TEST(test_row_wider_than_the_arena_is_a_buffer_error);
    RUN_TEST(test_one_in_ram_source_as_both_operands);
    RUN_TEST(test_wider_window_and_empty_rectangle_are_refused);
    RUN_TEST(test_row_span_wider_than_a_jobs_plate);
    RUN_TEST(test_repeated_and_shorter_jobs);
    RUN_TEST(test_track_grid_without_edge_rows);
    RUN_TEST(test_track_coarse_scan_with_auto_threshold);
    RUN_TEST(test_track_with_every_area_outside_first);
    RUN_TEST(test_track_tiled_minimal_arenas);
    RUN_TEST(test_track_refusals_leave_outputs_untouched);
    return UNITY_END();
}
