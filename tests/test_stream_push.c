/*
 * test_stream_push.c - push mode: rows pushed one by one give ssda_match's
 * and ssda_track's results in every mode, each search running in the push
 * that brings the last row it needs (no sooner, no later); rings from the
 * minimum up; the other image in RAM or streamed; a failed read at every
 * possible read stops the job with the code unchanged; bad arguments.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "test_image.h"
#include "test_push.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 100u
#define IH 84u
static uint16_t g_first[IH][IW], g_second[IH][IW];
static uint8_t g_first8[IH][IW];
static uint8_t g_dev[20000];
static uint32_t g_arena[2048];
static uint32_t g_ring[4096]; /* 16 KB */
/* the largest of the jobs' work (bounds, and the tracking jobs' uniqueness list) */
static uint64_t g_work[(SSDA_MATCH_WORK_SIZE_UNIQUE(40, 32, 11, 9) + 7u) / 8u];
static test_source_t g_tdev;
#define MAX_WIN 160u
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];

static const ssda_rect_t k_area = {13, 21, 40, 30};
static const ssda_rect_t k_win = {30, 40, 11, 9};

/* FIRST textured (with a 4095 patch for the mask test); SECOND = FIRST
   moved by (-2, 3) plus noise. */
static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u16(&g_first[0][0], IW, IH, IW, 4000u, &r);
    test_fill_texture_u8(&g_first8[0][0], IW, IH, IW, &r);
    for (y = 50; y < 60; y++) {
        for (x = 60; x < 75; x++) {
            g_first[y][x] = 4095u;
        }
    }
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            uint32_t v = g_first[(y + IH - 3u) % IH][(x + 2u) % IW] + test_rng_range(&r, 0, 30);
            g_second[y][x] = (uint16_t)v;
        }
    }
}

static ssda_view_t view16(bool first)
{
    ssda_view_t v;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, first ? (void *)g_first : (void *)g_second,
                                                  IW, IH, IW * 2u, SSDA_PIX_U16));
    return v;
}

/* The other image as a streamed source (raster, granularity 8) or in RAM. */
static void make_other(ssda_source_t *s, const ssda_view_t *v, bool streamed, size_t arena)
{
    if (streamed) {
        ssda_source_config_t c;
        test_source_init(&g_tdev, g_dev, sizeof g_dev, 8u);
        c = test_source_config(&g_tdev, v, SSDA_LAYOUT_RASTER, 0, 0, 4u, 0u, 0u, 8u, g_arena, arena);
        test_source_store(&g_tdev, &c, v);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(s, &c));
    } else {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(s, v));
    }
}

static bool same_result(const ssda_match_result_t *a, const ssda_match_result_t *b)
{
    return a->sad == b->sad && a->pixel_ops == b->pixel_ops && a->positions == b->positions &&
           a->completed == b->completed && a->x == b->x && a->y == b->y && a->exact == b->exact;
}

static ssda_match_config_t match_config(uint32_t i)
{
    ssda_match_config_t c;
    memset(&c, 0, sizeof c);
    c.threshold = (uint8_t)(i % 5u);
    c.scan = (uint8_t)((i / 5u) % 3u);
    c.order = (uint8_t)((i / 15u) % 2u);
    c.fixed_threshold = 20000u;
    c.lambda_q8 = 2000u;
    c.predict_x = 9;
    c.predict_y = 4;
    if (i % 4u == 1u) {
        c.flags = SSDA_MATCH_BOUNDS;
        c.work = g_work;
        c.work_size = sizeof g_work;
    }
    return c;
}

/* A search: pushes before the area's last row return 0 and leave the
   result alone; that push returns 1 with ssda_match's result; the rest
   return 0; one more push is SSDA_ERR_STATE. */
static void test_search_runs_at_the_areas_last_row(void)
{
    ssda_view_t a = view16(true), w = view16(false), ar, wr;
    uint32_t i, ring_rows, streamed;
    make_images(41u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&ar, &a, k_area.x, k_area.y, k_area.width, k_area.height));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wr, &w, k_win.x, k_win.y, k_win.width, k_win.height));
    for (streamed = 0; streamed < 2; streamed++) {
        for (ring_rows = 30; ring_rows <= 31; ring_rows++) {
            for (i = 0; i < 30; i++) {
                ssda_match_config_t c = match_config(i);
                ssda_match_result_t want, got, poison;
                ssda_source_t ws;
                ssda_push_t p;
                uint32_t y;
                make_other(&ws, &w, streamed != 0u,
                           SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 11u, 9u, 2u, 8u, 0u));
                memset(&poison, 0x33, sizeof poison);
                got = poison;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&ar, &wr, &c, &want));
                TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(
                                                   &p, IW, IH, SSDA_PIX_U16, &k_area, &ws, &k_win, &c, &got,
                                                   g_ring, SSDA_PUSH_SIZE(40u, ring_rows, 2u)));
                for (y = 0; y < IH; y++) {
                    int n = ssda_push_row(&p, g_first[y]);
                    if (y + 1u == (uint32_t)k_area.y + k_area.height) {
                        TEST_ASSERT_EQUAL_INT(1, n);
                        TEST_ASSERT_TRUE(same_result(&want, &got));
                    } else {
                        TEST_ASSERT_EQUAL_INT(0, n);
                        if (y + 1u < (uint32_t)k_area.y + k_area.height) {
                            TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
                        }
                    }
                }
                TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_push_row(&p, g_first[0]));
            }
        }
    }
}

/* 8-bit rows and a whole-image area (NULL rectangle). */
static void test_search_8_bit_whole_image(void)
{
    static uint8_t win8[12][10];
    ssda_view_t a, w;
    ssda_source_t ws;
    ssda_push_t p;
    ssda_match_result_t want, got;
    uint32_t x, y;
    make_images(42u);
    for (y = 0; y < 12; y++) {
        for (x = 0; x < 10; x++) {
            win8[y][x] = g_first8[y + 60u][x + 70u];
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first8, IW, IH, IW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w, win8, 10, 12, 10, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ws, &w));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&a, &w, NULL, &want));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, SSDA_PIX_U8, NULL, &ws, NULL,
                                                        NULL, &got, g_ring, SSDA_PUSH_SIZE(IW, IH, 1u)));
    for (y = 0; y + 1u < IH; y++) {
        TEST_ASSERT_EQUAL_INT(0, ssda_push_row(&p, g_first8[y]));
    }
    TEST_ASSERT_EQUAL_INT(1, ssda_push_row(&p, g_first8[IH - 1u]));
    TEST_ASSERT_TRUE(same_result(&want, &got));
    TEST_ASSERT_EQUAL_UINT16(70, got.x);
    TEST_ASSERT_EQUAL_UINT16(60, got.y);
}

static ssda_track_config_t track_config(uint32_t i)
{
    static const uint8_t modes[4] = {SSDA_THRESHOLD_AUTO, SSDA_THRESHOLD_AUTO_RAMP,
                                     SSDA_THRESHOLD_NONE, SSDA_THRESHOLD_FIXED};
    ssda_track_config_t c;
    memset(&c, 0, sizeof c);
    c.match.threshold = modes[i % 4u];
    c.predict = (uint8_t)((i / 4u) % 3u);
    c.match.fixed_threshold = 6000u;
    if (i >= 8u) { /* other geometries, mask, bounds */
        c.win_w = 14;
        c.win_h = 11;
        c.search_w = 26;
        c.search_h = 25;
        c.step_x = 10;
        c.step_y = i % 2u ? 6 : 16; /* overlapping bands, and gaps between them */
        c.roi_y = 3;
        c.flags = SSDA_TRACK_MASK;
        if (c.match.threshold == SSDA_THRESHOLD_AUTO || c.match.threshold == SSDA_THRESHOLD_NONE) {
            c.flags |= SSDA_TRACK_UNIQUE; /* its list after the bounds tables */
        }
        c.mask_value = 4095;
        c.match.flags = SSDA_MATCH_BOUNDS;
        c.match.work = g_work;
        c.match.work_size = sizeof g_work;
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

/* Push one image of a tracking job; check each push's count against the
   grid rows whose band ends on that row, and the result against
   ssda_track (vectors and every count: the order is ssda_track's). */
static void push_track(uint8_t role, const ssda_track_config_t *c, ssda_source_t *other,
                       size_t ring_size)
{
    ssda_view_t f = view16(true), s = view16(false);
    ssda_track_stats_t want, got;
    ssda_track_grid_t g;
    ssda_push_t p;
    uint16_t (*img)[IW] = role == SSDA_PUSH_FIRST ? g_first : g_second;
    uint32_t y, k, total = 0, hy;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(c, IW, IH, &g));
    TEST_ASSERT_TRUE(g.count <= MAX_WIN);
    hy = (g.search_h - g.win_h) / 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&f, &s, c, g_want, MAX_WIN, &want));
    memset(g_got, 0, sizeof g_got);
    memset(&got, 0x44, sizeof got);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, SSDA_PIX_U16, role, other, c,
                                                        g_got, MAX_WIN, &got, g_ring, ring_size));
    for (y = 0; y < IH; y++) {
        /* grid rows whose band ends on this row; rows whose areas leave
           FIRST (EDGE, nothing read) go at once when their turn comes: the
           top ones with the first push, the bottom ones with the last band */
        int expect = 0, n;
        uint32_t r, last_inside = 0;
        bool any = false;
        for (r = 0; r < g.rows; r++) {
            uint32_t wy = g.roi_y + r * g.step_y;
            bool edge = wy < hy || wy - hy + g.search_h > IH;
            uint32_t last = role == SSDA_PUSH_FIRST ? wy - hy + g.search_h - 1u : wy + g.win_h - 1u;
            if (!edge) {
                expect += last == y;
                last_inside = last;
                any = true;
            } else if (!any) {
                expect += y == 0u;
            }
        }
        for (r = g.rows; r-- > 0;) { /* EDGE rows after the last inside one */
            uint32_t wy = g.roi_y + r * g.step_y;
            if (!(wy < hy || wy - hy + g.search_h > IH)) {
                break;
            }
            expect += any && y == last_inside;
        }
        n = ssda_push_row(&p, img[y]);
        TEST_ASSERT_EQUAL_INT(expect, n);
        total += (uint32_t)n;
    }
    TEST_ASSERT_EQUAL_UINT32(g.rows, total);
    for (k = 0; k < g.count; k++) {
        if (!same_vector(&g_want[k], &g_got[k])) {
            char msg[80];
            snprintf(msg, sizeof msg, "window %u: %d,%d vs %d,%d", (unsigned)k, (int)g_want[k].dx,
                     (int)g_want[k].dy, (int)g_got[k].dx, (int)g_got[k].dy);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    TEST_ASSERT_EQUAL_UINT64(want.pixel_ops, got.pixel_ops);
    TEST_ASSERT_EQUAL_UINT64(want.positions, got.positions);
    TEST_ASSERT_EQUAL_UINT64(want.check_pixels, got.check_pixels);
    TEST_ASSERT_EQUAL_UINT32(want.ok, got.ok);
    TEST_ASSERT_EQUAL_UINT32(want.edge, got.edge);
    TEST_ASSERT_EQUAL_UINT32(want.masked, got.masked);
    TEST_ASSERT_EQUAL_UINT32(want.windows, got.windows);
}

static void test_tracking_equals_ram_for_both_roles(void)
{
    ssda_view_t f = view16(true), s = view16(false);
    uint32_t i, role, mode;
    make_images(43u);
    for (i = 0; i < 12; i++) {
        ssda_track_config_t c = track_config(i);
        ssda_track_grid_t g;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &g));
        for (role = 0; role < 2; role++) {
            const bool first = role == SSDA_PUSH_FIRST;
            const uint32_t band = first ? g.search_h : g.win_h;
            const uint32_t span = first ? IW : (g.cols - 1u) * g.step_x + g.win_w;
            const uint32_t other_w = IW, other_band = first ? g.win_h : g.search_h;
            /* other: in RAM; streamed with a whole-width band; streamed with
               a band of one window (refused since issue 22: grid rows are
               solved whole, so it re-read rows without bound). Ring: the
               band, and a larger one. */
            for (mode = 0; mode < 3; mode++) {
                ssda_source_t other;
                size_t arena = mode == 1u ? SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, other_w, other_band, 2u, 8u, 0u)
                                          : SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER,
                                                             first ? g.win_w : g.search_w, other_band, 2u, 8u, 0u);
                if ((i % 3u) != mode && i >= 4u) {
                    continue; /* keep the run short: every mode on the first configs */
                }
                TEST_ASSERT_TRUE(arena <= sizeof g_arena);
                if (mode == 2u) {
                    ssda_push_t p;
                    make_other(&other, first ? &s : &f, true, arena);
                    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                                          test_push_init_track(&p, IW, IH, SSDA_PIX_U16, (uint8_t)role,
                                                               &other, &c, g_got, MAX_WIN, NULL, g_ring,
                                                               SSDA_PUSH_SIZE(span, band, 2u)));
                    continue;
                }
                make_other(&other, first ? &s : &f, mode != 0u, arena);
                push_track((uint8_t)role, &c, &other, SSDA_PUSH_SIZE(span, band, 2u));
                make_other(&other, first ? &s : &f, mode != 0u, arena);
                push_track((uint8_t)role, &c, &other, SSDA_PUSH_SIZE(span, band + 7u, 2u));
            }
        }
    }
}

/* A failed read of the streamed other image, at every read of a clean
   run: that push returns the code, the job stops (later pushes: STATE). */
static void test_failure_at_every_read_stops_the_job(void)
{
    ssda_view_t f = view16(true), s = view16(false), ar, wr;
    ssda_track_config_t c = track_config(0);
    ssda_source_t other;
    ssda_push_t p;
    uint64_t reads, k;
    uint32_t y;
    const size_t arena = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, IW, 32u, 2u, 8u, 0u);
    make_images(44u);
    make_other(&other, &f, true, arena);
    push_track(SSDA_PUSH_SECOND, &c, &other, SSDA_PUSH_SIZE(IW, 16u, 2u));
    reads = g_tdev.reads;
    TEST_ASSERT_TRUE(reads > 3u);
    for (k = 0; k < reads; k++) {
        ssda_track_stats_t st, poison;
        int failed = 0;
        memset(&poison, 0x21, sizeof poison);
        st = poison;
        make_other(&other, &f, true, arena);
        g_tdev.fail_at_read = (int64_t)k;
        g_tdev.fail_code = -5000 - (int)k;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, SSDA_PIX_U16, SSDA_PUSH_SECOND,
                                                            &other, &c, g_got, MAX_WIN, &st, g_ring,
                                                            SSDA_PUSH_SIZE(IW, 16u, 2u)));
        for (y = 0; y < IH; y++) {
            int n = ssda_push_row(&p, g_second[y]);
            if (failed) {
                TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, n);
            } else if (n < 0) {
                TEST_ASSERT_EQUAL_INT(-5000 - (int)k, n);
                failed = 1;
            }
        }
        TEST_ASSERT_EQUAL_INT(1, failed);
        TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    }
    /* a search whose streamed window fails: result untouched */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&ar, &f, k_area.x, k_area.y, k_area.width, k_area.height));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wr, &s, k_win.x, k_win.y, k_win.width, k_win.height));
    {
        ssda_match_result_t got, poison;
        memset(&poison, 0x55, sizeof poison);
        got = poison;
        make_other(&other, &s, true, arena);
        g_tdev.fail_at_read = 0;
        g_tdev.fail_code = -4242;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, SSDA_PIX_U16, &k_area, &other,
                                                            &k_win, NULL, &got, g_ring,
                                                            SSDA_PUSH_SIZE(40u, 30u, 2u)));
        for (y = 0; y + 1u < (uint32_t)k_area.y + k_area.height; y++) {
            TEST_ASSERT_EQUAL_INT(0, ssda_push_row(&p, g_first[y]));
        }
        TEST_ASSERT_EQUAL_INT(-4242, ssda_push_row(&p, g_first[y]));
        TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_push_row(&p, g_first[y + 1u]));
    }
}

static void test_bad_arguments(void)
{
    ssda_view_t s = view16(false);
    ssda_source_t other, zero;
    ssda_push_t p, before;
    ssda_match_result_t res;
    ssda_track_config_t c;
    ssda_rect_t r;
    memset(&zero, 0, sizeof zero);
    memset(&c, 0, sizeof c);
    memset(&p, 0x66, sizeof p);
    before = p;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&other, &s));
    /* search */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_match(NULL, IW, IH, 2, &k_area, &other, &k_win, NULL, &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_match(&p, IW, IH, 2, &k_area, NULL, &k_win, NULL, &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_match(&p, IW, IH, 2, &k_area, &other, &k_win, NULL, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_match(&p, IW, IH, 2, &k_area, &other, &k_win, NULL, &res, NULL, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, test_push_init_match(&p, IW, IH, 2, &k_area, &zero, &k_win, NULL, &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, test_push_init_match(&p, IW, IH, 1, &k_area, &other, &k_win, NULL, &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, test_push_init_match(&p, IW, IH, 3, &k_area, &other, &k_win, NULL, &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, 0, IH, 2, NULL, &other, &k_win, NULL, &res, g_ring, sizeof g_ring));
    r = k_area;
    r.y = (uint16_t)(IH - 29u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 2, &r, &other, &k_win, NULL, &res, g_ring, sizeof g_ring));
    r = k_area;
    r.height = 8; /* shorter than the window */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 2, &r, &other, &k_win, NULL, &res, g_ring, sizeof g_ring));
    {
        ssda_match_config_t bad;
        memset(&bad, 0, sizeof bad);
        bad.scan = 7;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, test_push_init_match(&p, IW, IH, 2, &k_area, &other, &k_win, &bad, &res, g_ring, sizeof g_ring));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, test_push_init_match(&p, IW, IH, 2, &k_area, &other, &k_win, NULL, &res, g_ring,
                                                                SSDA_PUSH_SIZE(40u, 30u, 2u) - 1u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, test_push_init_match(&p, IW, IH, 2, &k_area, &other, &k_win, NULL, &res,
                                                                (uint8_t *)g_ring + 2, sizeof g_ring - 4u));
    /* tracking */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_track(&p, IW, IH, 2, 0, &other, &c, NULL, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, test_push_init_track(&p, IW, IH, 2, 2, &other, &c, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, test_push_init_track(&p, IW, IH, 2, 0, &zero, &c, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, test_push_init_track(&p, IW, IH, 2, 0, &other, &c, g_got, 5, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, test_push_init_track(&p, IW, IH, 2, 0, &other, &c, g_got, MAX_WIN, NULL, g_ring,
                                                                SSDA_PUSH_SIZE(80u, 31u, 2u)));
    c.search_w = 8; /* smaller than the window */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_track(&p, IW, IH, 2, 0, &other, &c, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    /* no ssda_push_config_t */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_push_init_match(&p, NULL, NULL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_push_init_track(&p, NULL, NULL, g_got, MAX_WIN, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_push_row(NULL, g_first[0]));
    memset(&p, 0, sizeof p);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_push_row(&p, g_first[0]));
}

/* A ring that overlaps the streamed other image's arena would overwrite
   its plate: refused at init for both jobs, *push untouched; the same
   buffer split without overlap is accepted. */
static void test_ring_overlapping_the_other_arena(void)
{
    ssda_view_t w = view16(false);
    uint8_t *tail = (uint8_t *)g_ring + sizeof g_ring - 4096u;
    ssda_source_t os, other;
    ssda_source_config_t c;
    ssda_push_t p, before;
    ssda_match_result_t res;
    ssda_track_config_t tc;
    make_other(&os, &w, true, 4096u);
    c = os.cfg;
    c.arena = tail;
    c.arena_size = 4096u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&other, &c));
    memset(&tc, 0, sizeof tc);
    memset(&p, 0x66, sizeof p);
    before = p;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, test_push_init_match(&p, IW, IH, 2, &k_area, &other, &k_win, NULL,
                                                             &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, test_push_init_track(&p, IW, IH, 2, SSDA_PUSH_FIRST, &other, &tc,
                                                             g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, 2, &k_area, &other, &k_win, NULL, &res,
                                                        g_ring, sizeof g_ring - 4096u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, 2, SSDA_PUSH_FIRST, &other, &tc, g_got,
                                                        MAX_WIN, NULL, g_ring, sizeof g_ring - 4096u));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_search_runs_at_the_areas_last_row);
    RUN_TEST(test_search_8_bit_whole_image);
    RUN_TEST(test_tracking_equals_ram_for_both_roles);
    RUN_TEST(test_failure_at_every_read_stops_the_job);
    RUN_TEST(test_bad_arguments);
    RUN_TEST(test_ring_overlapping_the_other_arena);
    return UNITY_END();
}
