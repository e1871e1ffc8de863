/*
 * test_track.c - grid tracking on images in RAM: known per-window shifts
 * (uniform, spatially varying, smooth), agreement with an independent brute
 * force per window, prediction (less work, same vectors), texture exclusion,
 * mask and edge statuses, extreme geometry, and argument errors.
 */
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "test_image.h"
#include "test_push.h"

void setUp(void) {}
void tearDown(void) {}

/* The seed's layout: 128 x 128 images, 7 x 7 windows of 16 x 16 starting
   8 px in, each searched in the 32 x 32 area centred on it. */
#define IMG 128u
#define GRID 7u
#define NWIN (GRID * GRID)

static uint8_t g_first[IMG * IMG];
static uint8_t g_second[IMG * IMG];
static uint16_t g_first16[IMG * IMG];
static uint16_t g_second16[IMG * IMG];
static uint64_t g_work[(SSDA_TRACK_WORK_SIZE(32, 32, 16, 16) + 7u) / 8u];
static ssda_track_vector_t g_out[64];
static ssda_track_vector_t g_out2[64];

typedef int32_t (*field_fn)(uint32_t col, uint32_t row, int axis);

/* Rough field: neighbours unrelated, covering -8..8 on both axes. */
static int32_t field_rough(uint32_t col, uint32_t row, int axis)
{
    return axis == 0 ? (int32_t)((col * 5u + row * 3u) % 17u) - 8
                     : (int32_t)((col * 7u + row * 11u + 4u) % 17u) - 8;
}

/* Smooth field: a slow drift, as wind over a small region. */
static int32_t field_smooth(uint32_t col, uint32_t row, int axis)
{
    return axis == 0 ? 3 + (int32_t)(col / 4u) : -2 - (int32_t)(row / 3u);
}

static int32_t field_uniform(uint32_t col, uint32_t row, int axis)
{
    (void)col;
    (void)row;
    return axis == 0 ? 5 : -3;
}

static void seed_config(ssda_track_config_t *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->roi_x = 8;
    cfg->roi_y = 8;
    cfg->roi_w = 112;
    cfg->roi_h = 112;
}

/* FIRST = texture; SECOND = FIRST, except that the content of each grid
   window moved by the field: second(x, y) = first(x - dx, y - dy). */
static void make_pair_u8(field_fn f, uint32_t seed)
{
    test_rng_t r;
    uint32_t col, row, i, j;
    test_rng_seed(&r, seed);
    test_fill_texture_u8(g_first, IMG, IMG, IMG, &r);
    memcpy(g_second, g_first, sizeof g_second);
    for (row = 0; row < GRID; row++) {
        for (col = 0; col < GRID; col++) {
            uint32_t wx = 8u + 16u * col, wy = 8u + 16u * row;
            int32_t dx = f(col, row, 0), dy = f(col, row, 1);
            for (j = 0; j < 16u; j++) {
                for (i = 0; i < 16u; i++) {
                    uint32_t sx = (uint32_t)((int32_t)(wx + i) - dx);
                    uint32_t sy = (uint32_t)((int32_t)(wy + j) - dy);
                    g_second[(wy + j) * IMG + wx + i] = g_first[sy * IMG + sx];
                }
            }
        }
    }
}

static void views_u8(ssda_view_t *a, ssda_view_t *b)
{
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(a, g_first, IMG, IMG, IMG, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(b, g_second, IMG, IMG, IMG, SSDA_PIX_U8));
}

/* Brute force for one window, written from the definition in track.h:
   the area of FIRST centred on the window, minimum SAD by the tie rule. */
static void reference_window(const ssda_view_t *first, const ssda_view_t *second,
                             uint32_t wx, uint32_t wy, int32_t *dx, int32_t *dy, uint64_t *sad)
{
    ssda_view_t area, win;
    uint32_t bx = 0, by = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&win, second, (uint16_t)wx, (uint16_t)wy, 16, 16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&area, first, (uint16_t)(wx - 8u),
                                                 (uint16_t)(wy - 8u), 32, 32));
    test_best(&area, &win, &bx, &by, sad);
    *dx = 8 - (int32_t)bx;
    *dy = 8 - (int32_t)by;
}

/* Every window at the field's vector with SAD 0, equal to the brute-force
   reference; OK, or AT_LIMIT where the vector is at the border of the
   range (+-8); the sub-pixel vector exactly the whole-pixel one (SAD 0:
   an exact match has no fraction, match.h). */
static void check_field(const ssda_track_vector_t *out, field_fn f)
{
    ssda_view_t a, b;
    uint32_t col, row;
    views_u8(&a, &b);
    for (row = 0; row < GRID; row++) {
        for (col = 0; col < GRID; col++) {
            const ssda_track_vector_t *v = &out[row * GRID + col];
            int32_t rdx, rdy;
            uint64_t rsad;
            const bool limit = f(col, row, 0) == 8 || f(col, row, 0) == -8 ||
                               f(col, row, 1) == 8 || f(col, row, 1) == -8;
            reference_window(&a, &b, 8u + 16u * col, 8u + 16u * row, &rdx, &rdy, &rsad);
            TEST_ASSERT_EQUAL_UINT8(limit ? SSDA_TRACK_AT_LIMIT : SSDA_TRACK_OK, v->status);
            TEST_ASSERT_EQUAL_INT32(v->dx * 256, v->sub_dx_q8);
            TEST_ASSERT_EQUAL_INT32(v->dy * 256, v->sub_dy_q8);
            TEST_ASSERT_EQUAL_UINT16(8u + 16u * col, v->x);
            TEST_ASSERT_EQUAL_UINT16(8u + 16u * row, v->y);
            TEST_ASSERT_EQUAL_INT32(f(col, row, 0), v->dx);
            TEST_ASSERT_EQUAL_INT32(f(col, row, 1), v->dy);
            TEST_ASSERT_EQUAL_UINT64(0u, v->sad);
            TEST_ASSERT_EQUAL_INT32(rdx, v->dx);
            TEST_ASSERT_EQUAL_INT32(rdy, v->dy);
            TEST_ASSERT_EQUAL_UINT64(rsad, v->sad);
            TEST_ASSERT_TRUE(v->exact);
        }
    }
}

static void test_grid_layout_and_defaults(void)
{
    ssda_track_config_t cfg;
    ssda_track_grid_t g;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(NULL, IMG, IMG, &g));
    TEST_ASSERT_EQUAL_UINT16(16, g.win_w);
    TEST_ASSERT_EQUAL_UINT16(16, g.win_h);
    TEST_ASSERT_EQUAL_UINT16(32, g.search_w);
    TEST_ASSERT_EQUAL_UINT16(32, g.search_h);
    TEST_ASSERT_EQUAL_UINT16(16, g.step_x);
    TEST_ASSERT_EQUAL_UINT16(IMG, g.roi_w);
    TEST_ASSERT_EQUAL_UINT16(8, g.cols);
    TEST_ASSERT_EQUAL_UINT32(64, g.count);
    TEST_ASSERT_EQUAL_UINT32(SSDA_TRACK_GRID_COUNT(IMG, IMG, 16, 16, 16, 16), g.count);
    seed_config(&cfg);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&cfg, IMG, IMG, &g));
    TEST_ASSERT_EQUAL_UINT32(NWIN, g.count);
    /* overlapping windows, odd sizes, region to the edge */
    cfg.win_w = 10;
    cfg.win_h = 6;
    cfg.search_w = 0; /* twice the window */
    cfg.search_h = 9;
    cfg.step_x = 7;
    cfg.step_y = 5;
    cfg.roi_x = 3;
    cfg.roi_y = 100;
    cfg.roi_w = 0;
    cfg.roi_h = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&cfg, 100, 120, &g));
    TEST_ASSERT_EQUAL_UINT16(20, g.search_w);
    TEST_ASSERT_EQUAL_UINT16(97, g.roi_w);
    TEST_ASSERT_EQUAL_UINT16(20, g.roi_h);
    TEST_ASSERT_EQUAL_UINT16((97 - 10) / 7 + 1, g.cols);
    TEST_ASSERT_EQUAL_UINT16((20 - 6) / 5 + 1, g.rows);
    TEST_ASSERT_EQUAL_UINT32(SSDA_TRACK_GRID_COUNT(97, 20, 10, 6, 7, 5), g.count);
    TEST_ASSERT_EQUAL_UINT64((uint64_t)g.count * sizeof(ssda_track_vector_t),
                             SSDA_TRACK_OUT_SIZE(97, 20, 10, 6, 7, 5));
}

static void test_known_uniform_shift(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st;
    ssda_view_t a, b;
    make_pair_u8(field_uniform, 11);
    views_u8(&a, &b);
    seed_config(&cfg);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    check_field(g_out, field_uniform);
    TEST_ASSERT_EQUAL_UINT32(NWIN, st.windows);
    TEST_ASSERT_EQUAL_UINT32(NWIN, st.ok);
    TEST_ASSERT_EQUAL_UINT32(0, st.edge + st.masked + st.excluded + st.flat);
    TEST_ASSERT_EQUAL_UINT64(NWIN * 2u * 256u, st.check_pixels); /* the flat test's 2 passes */
    cfg.flags = SSDA_TRACK_NO_FLAT;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    check_field(g_out, field_uniform);
    TEST_ASSERT_EQUAL_UINT64(0, st.check_pixels);
    TEST_ASSERT_EQUAL_UINT32(0, g_out[0].texture_q8);
}

static void test_spatially_varying_field(void)
{
    ssda_track_config_t cfg;
    ssda_view_t a, b;
    uint32_t order;
    make_pair_u8(field_rough, 12);
    views_u8(&a, &b);
    for (order = 0; order < 2u; order++) {
        seed_config(&cfg);
        cfg.match.order = (uint8_t)order;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, NULL));
        check_field(g_out, field_rough);
        /* a wrong prediction (rough field) costs work but never a vector */
        cfg.predict = SSDA_TRACK_PREDICT_MEDIAN;
        cfg.match.flags = SSDA_MATCH_BOUNDS;
        cfg.match.work = g_work;
        cfg.match.work_size = sizeof g_work;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, NULL));
        check_field(g_out, field_rough);
    }
}

/* stats.pixel_ops etc. are the sums of ssda_match on each window's views,
   with the flags tracking adds (the tie rule toward the prediction, zero
   motion here, and the sub-pixel fit). */
static void test_stats_are_sums_of_per_window_searches(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st;
    ssda_view_t a, b;
    uint64_t ops = 0, pos = 0, comp = 0;
    uint32_t k;
    make_pair_u8(field_rough, 13);
    views_u8(&a, &b);
    seed_config(&cfg);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    cfg.match.flags = SSDA_MATCH_TIE_NEAREST | SSDA_MATCH_SUBPIXEL;
    cfg.match.predict_x = 8;
    cfg.match.predict_y = 8;
    for (k = 0; k < NWIN; k++) {
        ssda_view_t area, win;
        ssda_match_result_t res;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&win, &b, g_out[k].x, g_out[k].y, 16, 16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&area, &a, (uint16_t)(g_out[k].x - 8u),
                                                     (uint16_t)(g_out[k].y - 8u), 32, 32));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg.match, &res));
        TEST_ASSERT_EQUAL_INT32(8 - (int32_t)res.x, g_out[k].dx);
        ops += res.pixel_ops;
        pos += res.positions;
        comp += res.completed;
    }
    TEST_ASSERT_EQUAL_UINT64(ops, st.pixel_ops);
    TEST_ASSERT_EQUAL_UINT64(pos, st.positions);
    TEST_ASSERT_EQUAL_UINT64(comp, st.completed);
    TEST_ASSERT_EQUAL_UINT64(NWIN * 17u * 17u, st.positions);
}

static void assert_same_vectors(const ssda_track_vector_t *x, const ssda_track_vector_t *y,
                                uint32_t n)
{
    uint32_t k;
    for (k = 0; k < n; k++) {
        TEST_ASSERT_EQUAL_UINT8(x[k].status, y[k].status);
        TEST_ASSERT_EQUAL_INT32(x[k].dx, y[k].dx);
        TEST_ASSERT_EQUAL_INT32(x[k].dy, y[k].dy);
        TEST_ASSERT_EQUAL_UINT64(x[k].sad, y[k].sad);
        TEST_ASSERT_EQUAL_UINT16(x[k].x, y[k].x);
        TEST_ASSERT_EQUAL_UINT16(x[k].y, y[k].y);
    }
}

/* On a smooth field every prediction mode does strictly less work than the
   raster scan, with identical vectors (AUTO is exact), equal to brute force
   (SSDA_THRESHOLD_NONE) and to the field. */
static void test_prediction_reduces_work_same_vectors(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st_raster, st_none, st;
    ssda_view_t a, b;
    uint8_t mode, bounds;
    make_pair_u8(field_smooth, 14);
    views_u8(&a, &b);
    seed_config(&cfg);
    cfg.match.threshold = SSDA_THRESHOLD_NONE;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out2, NWIN, &st_none));
    check_field(g_out2, field_smooth);
    /* every placement, and the 4 neighbours of the best again for the fit */
    TEST_ASSERT_EQUAL_UINT64(NWIN * (17u * 17u + 4u) * 256u, st_none.pixel_ops);

    cfg.match.threshold = SSDA_THRESHOLD_AUTO;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st_raster));
    assert_same_vectors(g_out2, g_out, NWIN);
    TEST_ASSERT_TRUE(st_raster.pixel_ops < st_none.pixel_ops);

    for (bounds = 0; bounds < 2u; bounds++) {
        seed_config(&cfg);
        if (bounds) {
            cfg.match.flags = SSDA_MATCH_BOUNDS;
            cfg.match.work = g_work;
            cfg.match.work_size = sizeof g_work;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st_raster));
            assert_same_vectors(g_out2, g_out, NWIN);
        }
        for (mode = SSDA_TRACK_PREDICT_LEFT; mode <= SSDA_TRACK_PREDICT_MEDIAN; mode++) {
            cfg.match.threshold = SSDA_THRESHOLD_AUTO;
            cfg.predict = mode;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
            assert_same_vectors(g_out2, g_out, NWIN);
            TEST_ASSERT_TRUE(st.pixel_ops < st_raster.pixel_ops);
            /* brute force with prediction: same vectors, same full work */
            cfg.match.threshold = SSDA_THRESHOLD_NONE;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
            assert_same_vectors(g_out2, g_out, NWIN);
            TEST_ASSERT_EQUAL_UINT64(st_none.pixel_ops, st.pixel_ops);
        }
    }
}

/* The median predictor starts each search at the field's vector once the
   neighbours agree: with a uniform field and AUTO, every window after the
   first grid row's left one is summed in full exactly once. */
static void test_median_prediction_hits_uniform_field(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st;
    ssda_view_t a, b;
    make_pair_u8(field_uniform, 15);
    views_u8(&a, &b);
    seed_config(&cfg);
    cfg.predict = SSDA_TRACK_PREDICT_MEDIAN;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    check_field(g_out, field_uniform);
    /* window 0 starts at zero motion, so it may complete more than once */
    TEST_ASSERT_TRUE(st.completed >= NWIN);
    TEST_ASSERT_TRUE(st.completed <= NWIN - 1u + 17u * 17u);
    cfg.predict = SSDA_TRACK_PREDICT_LEFT;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    check_field(g_out, field_uniform);
    TEST_ASSERT_TRUE(st.completed <= NWIN - 1u + 17u * 17u);
}

static void fill_window_u8(uint32_t col, uint32_t row, uint8_t v)
{
    uint32_t i, j;
    for (j = 0; j < 16u; j++) {
        for (i = 0; i < 16u; i++) {
            g_second[(8u + 16u * row + j) * IMG + 8u + 16u * col + i] = v;
        }
    }
}

/* Window (col, row) of SECOND gets exactly n pixels above 128, the rest at 50. */
static void bright_count_window_u8(uint32_t col, uint32_t row, uint32_t n)
{
    uint32_t p;
    fill_window_u8(col, row, 50);
    for (p = 0; p < n; p++) {
        g_second[(8u + 16u * row + p / 16u) * IMG + 8u + 16u * col + p % 16u] = 129;
    }
}

static bool was_searched(uint8_t status)
{
    return status == SSDA_TRACK_OK || status == SSDA_TRACK_AT_LIMIT ||
           status == SSDA_TRACK_AMBIGUOUS;
}

static void test_texture_exclusion_rule(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st;
    ssda_view_t a, b;
    uint32_t k;
    make_pair_u8(field_smooth, 16);
    fill_window_u8(0, 0, 250);              /* all cloud */
    fill_window_u8(1, 0, 3);                /* all clear */
    bright_count_window_u8(2, 0, 15);       /* 15 bright < 16: excluded */
    bright_count_window_u8(3, 0, 16);       /* 16 bright: kept */
    bright_count_window_u8(4, 0, 256 - 15); /* 15 dark: excluded */
    bright_count_window_u8(5, 0, 256 - 16); /* 16 dark: kept */
    views_u8(&a, &b);
    seed_config(&cfg);
    cfg.flags = SSDA_TRACK_EXCLUDE;
    cfg.texture_threshold = 128;            /* min count: default 256/16 = 16 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[0].status);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[1].status);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[2].status);
    TEST_ASSERT_TRUE(was_searched(g_out[3].status)); /* an artificial window: its */
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[4].status);
    TEST_ASSERT_TRUE(was_searched(g_out[5].status)); /* match may be at the limit */
    TEST_ASSERT_EQUAL_INT32(0, g_out[0].dx);
    TEST_ASSERT_EQUAL_UINT64(0, g_out[0].sad);
    TEST_ASSERT_FALSE(g_out[0].exact);
    for (k = 6; k < NWIN; k++) { /* textured windows stay, at their vectors */
        TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_out[k].status);
        TEST_ASSERT_EQUAL_INT32(field_smooth(k % GRID, k / GRID, 0), g_out[k].dx);
        TEST_ASSERT_EQUAL_INT32(field_smooth(k % GRID, k / GRID, 1), g_out[k].dy);
    }
    TEST_ASSERT_EQUAL_UINT32(4, st.excluded);
    TEST_ASSERT_EQUAL_UINT32(NWIN - 4u, st.ok + st.at_limit + st.ambiguous);
    /* windows only; the flat test's second pass on those not excluded */
    TEST_ASSERT_EQUAL_UINT64((uint64_t)NWIN * 256u + (NWIN - 4u) * 256u, st.check_pixels);
    /* an explicit minimum count moves the boundary */
    cfg.texture_min_count = 15;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    TEST_ASSERT_TRUE(was_searched(g_out[2].status));
    TEST_ASSERT_TRUE(was_searched(g_out[4].status));
    TEST_ASSERT_EQUAL_UINT32(2, st.excluded);
    /* the default threshold is half range: 128 */
    cfg.texture_min_count = 0;
    cfg.texture_threshold = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    TEST_ASSERT_EQUAL_UINT32(4, st.excluded);
    fill_window_u8(3, 0, 128); /* 128 is not above the threshold: all dark */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[3].status);
    TEST_ASSERT_EQUAL_UINT32(5, st.excluded);
    /* without the flag nothing is excluded; the constant windows are flat */
    cfg.flags = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    TEST_ASSERT_EQUAL_UINT32(0, st.excluded);
    TEST_ASSERT_EQUAL_UINT32(3, st.flat);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_FLAT, g_out[0].status);
    TEST_ASSERT_EQUAL_UINT32(0, g_out[0].texture_q8);
}

/* 16-bit data with a fill value (GOES: 4095): a window holding it, or an
   area holding it, is masked; neighbours are not. */
static void test_mask_value_u16(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st;
    ssda_view_t a, b;
    test_rng_t r;
    uint32_t i, k;
    test_rng_seed(&r, 17);
    test_fill_texture_u16(g_first16, IMG, IMG, IMG, 4000u, &r);
    /* SECOND = FIRST moved by (2, 1) everywhere */
    for (i = 0; i < IMG * IMG; i++) {
        uint32_t x = i % IMG, y = i / IMG;
        g_second16[i] = (x >= 2u && y >= 1u) ? g_first16[(y - 1u) * IMG + x - 2u] : 7u;
    }
    g_second16[(8u + 16u * 1u + 5u) * IMG + 8u + 16u * 1u + 9u] = 4095u; /* in window (1,1) */
    /* in FIRST at (8+16*4-6, 8+16*4-7): inside the area of window (4,4) only
       (areas reach 8 px beyond their window; window (3,3)'s area ends at
       8+16*3+16+8 = 80 > 66 too, so it is masked as well) */
    g_first16[(8u + 16u * 4u - 7u) * IMG + 8u + 16u * 4u - 6u] = 4095u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first16, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_second16, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
    seed_config(&cfg);
    cfg.flags = SSDA_TRACK_MASK;
    cfg.mask_value = 4095;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    for (k = 0; k < NWIN; k++) {
        uint32_t col = k % GRID, row = k / GRID;
        /* pixel (66, 65) of FIRST lies in the 32 x 32 area at (8+16c-8, 8+16r-8)
           when 16c <= 66 < 16c + 32 and 16r <= 65 < 16r + 32: c, r in {3, 4} */
        bool in_area = (col == 3u || col == 4u) && (row == 3u || row == 4u);
        if (k == 1u * GRID + 1u || in_area) {
            TEST_ASSERT_EQUAL_UINT8_MESSAGE(SSDA_TRACK_MASKED, g_out[k].status, "masked");
            TEST_ASSERT_EQUAL_INT32(0, g_out[k].dx);
        } else {
            TEST_ASSERT_EQUAL_UINT8_MESSAGE(SSDA_TRACK_OK, g_out[k].status, "ok");
            TEST_ASSERT_EQUAL_INT32(2, g_out[k].dx);
            TEST_ASSERT_EQUAL_INT32(1, g_out[k].dy);
            TEST_ASSERT_EQUAL_UINT64(0, g_out[k].sad);
        }
    }
    TEST_ASSERT_EQUAL_UINT32(5, st.masked);
    TEST_ASSERT_EQUAL_UINT32(NWIN - 5u, st.ok);
    /* without the flag the fill value is just a sample */
    cfg.flags = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    TEST_ASSERT_EQUAL_UINT32(NWIN, st.ok);
    /* masking wins over exclusion in a window; exclusion is decided before
       the area is read */
    cfg.flags = SSDA_TRACK_MASK | SSDA_TRACK_EXCLUDE;
    cfg.texture_threshold = 60000; /* every window all dark: excluded */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, &st));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_MASKED, g_out[1u * GRID + 1u].status);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[4u * GRID + 4u].status);
    TEST_ASSERT_EQUAL_UINT32(1, st.masked);
    TEST_ASSERT_EQUAL_UINT32(NWIN - 1u, st.excluded);
}

/* One mask pixel at a time on the edges of a window (SECOND) or a search
   area (FIRST): first and last rows, columns 0, 15, 16 and 31, where a
   shortcut over 16- or 32-px rows could miss it (review, session 7). The
   statuses follow the definition (a window is MASKED when its window or
   its area holds the value), and 16-bit data give 8-bit data's vectors,
   statuses and check_pixels exactly. */
static void test_mask_pixel_on_row_and_column_edges(void)
{
    static const struct {
        uint8_t in_first;       /* 1: FIRST (areas), 0: SECOND (windows) */
        uint16_t x, y;
    } spots[] = {
        {0, 40, 56}, {0, 55, 71}, {0, 55, 56}, {0, 40, 71}, /* window (2, 3)'s corners */
        {1, 48, 32}, {1, 63, 63}, {1, 64, 37}, {1, 79, 63}, /* area of (3, 2): cols 0, 15, 16, 31 */
        {1, 79, 32}, {1, 48, 63},
    };
    ssda_track_config_t cfg;
    ssda_track_stats_t st8, st16;
    ssda_view_t a8, b8, a16, b16;
    uint32_t s, i, k;
    make_pair_u8(field_smooth, 21);
    for (i = 0; i < IMG * IMG; i++) { /* 255 is the mask value alone */
        g_first[i] = g_first[i] == 255u ? 254u : g_first[i];
        g_second[i] = g_second[i] == 255u ? 254u : g_second[i];
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a8, g_first, IMG, IMG, IMG, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b8, g_second, IMG, IMG, IMG, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK,
                          ssda_view_init(&a16, g_first16, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK,
                          ssda_view_init(&b16, g_second16, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
    seed_config(&cfg);
    cfg.flags = SSDA_TRACK_MASK;
    cfg.mask_value = 255;
    for (s = 0; s < sizeof spots / sizeof spots[0]; s++) {
        uint8_t *img = spots[s].in_first ? g_first : g_second;
        const uint32_t at = (uint32_t)spots[s].y * IMG + spots[s].x;
        const uint8_t keep = img[at];
        img[at] = 255u;
        for (i = 0; i < IMG * IMG; i++) {
            g_first16[i] = g_first[i];
            g_second16[i] = g_second[i];
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a8, &b8, &cfg, g_out, NWIN, &st8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a16, &b16, &cfg, g_out2, NWIN, &st16));
        for (k = 0; k < NWIN; k++) {
            const uint32_t wx = 8u + 16u * (k % GRID), wy = 8u + 16u * (k / GRID);
            const uint32_t x = spots[s].x, y = spots[s].y;
            const bool hit = spots[s].in_first
                                 ? (x >= wx - 8u && x < wx + 24u && y >= wy - 8u && y < wy + 24u)
                                 : (x >= wx && x < wx + 16u && y >= wy && y < wy + 16u);
            TEST_ASSERT_EQUAL_UINT8_MESSAGE(hit ? SSDA_TRACK_MASKED : SSDA_TRACK_OK,
                                            g_out2[k].status, "16-bit status");
            TEST_ASSERT_EQUAL_UINT8(g_out[k].status, g_out2[k].status);
            TEST_ASSERT_EQUAL_INT32(g_out[k].dx, g_out2[k].dx);
            TEST_ASSERT_EQUAL_INT32(g_out[k].dy, g_out2[k].dy);
            TEST_ASSERT_EQUAL_UINT64(g_out[k].sad, g_out2[k].sad);
        }
        TEST_ASSERT_TRUE(st16.masked > 0u);
        TEST_ASSERT_EQUAL_UINT32(st8.masked, st16.masked);
        TEST_ASSERT_EQUAL_UINT64(st8.check_pixels, st16.check_pixels);
        img[at] = keep;
    }
}

/* Whole-image region: windows whose 32 x 32 area leaves FIRST are EDGE. */
static void test_edge_status(void)
{
    ssda_track_stats_t st;
    ssda_view_t a, b;
    uint32_t k;
    make_pair_u8(field_smooth, 18);
    views_u8(&a, &b);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, NULL, g_out, 64, &st));
    for (k = 0; k < 64u; k++) {
        uint32_t col = k % 8u, row = k / 8u;
        bool edge = col == 0u || row == 0u || col == 7u || row == 7u;
        TEST_ASSERT_EQUAL_UINT16(16u * col, g_out[k].x);
        TEST_ASSERT_EQUAL_UINT16(16u * row, g_out[k].y);
        TEST_ASSERT_EQUAL_UINT8(edge ? SSDA_TRACK_EDGE : SSDA_TRACK_OK, g_out[k].status);
    }
    TEST_ASSERT_EQUAL_UINT32(28, st.edge);
    TEST_ASSERT_EQUAL_UINT32(36, st.ok);
    TEST_ASSERT_EQUAL_UINT32(64, st.windows);
    /* a smaller FIRST: the areas reaching past its right edge become EDGE */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first, 100, IMG, IMG, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, NULL, g_out, 64, &st));
    /* window column c has its area at x = 16c - 8 .. 16c + 23: inside 100
       columns for c <= 4 */
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_out[8u + 4u].status);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EDGE, g_out[8u + 5u].status);
    TEST_ASSERT_EQUAL_UINT32(64u - 6u * 4u, st.edge); /* OK: rows 1..6 x columns 1..4 */
}

/* Largest geometry: one 1-pixel window searched over 65535 pixels; the
   vector reaches +-32767 and per-row counters see 65535 pixels. */
static uint8_t g_long1[65535];
static uint8_t g_long2[65535];

static void test_extreme_geometry(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st;
    ssda_view_t a, b;
    uint32_t i;
    for (i = 0; i < 65535u; i++) {
        g_long1[i] = (uint8_t)(1u + i % 200u);
        g_long2[i] = 250u;
    }
    g_long1[0] = 255u;   /* the only 255 in FIRST: at x = 0 */
    g_long2[32767] = 255u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_long1, 65535, 1, 65535, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_long2, 65535, 1, 65535, SSDA_PIX_U8));
    memset(&cfg, 0, sizeof cfg);
    cfg.flags = SSDA_TRACK_NO_FLAT; /* a 1-pixel window has no texture */
    cfg.win_w = 1;
    cfg.win_h = 1;
    cfg.search_w = 65535;
    cfg.search_h = 1;
    cfg.roi_x = 32767;
    cfg.roi_w = 1;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, &st));
    /* the best placement is the first of the range: at the limit */
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_AT_LIMIT, g_out[0].status);
    TEST_ASSERT_EQUAL_INT32(32767, g_out[0].dx); /* moved from x = 0 to x = 32767 */
    TEST_ASSERT_EQUAL_INT32(0, g_out[0].dy);
    TEST_ASSERT_EQUAL_UINT64(65535, st.positions);
    /* SECOND's pixel moves to the far left: dx = -32767 */
    g_long1[0] = 1u;
    g_long1[65534] = 255u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, &st));
    TEST_ASSERT_EQUAL_INT32(-32767, g_out[0].dx);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_AT_LIMIT, g_out[0].status);
    g_long1[65534] = 1u;
    g_long1[65533] = 255u; /* one placement in from the border: OK */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, &st));
    TEST_ASSERT_EQUAL_INT32(-32766, g_out[0].dx);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_out[0].status);
    /* a 65535 x 1 window, all bright: bright count 65535 in one row */
    cfg.win_w = 65535;
    cfg.roi_x = 0;
    cfg.roi_w = 0;
    cfg.flags = SSDA_TRACK_EXCLUDE | SSDA_TRACK_NO_FLAT;
    cfg.texture_threshold = 200;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, &st));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[0].status);
    TEST_ASSERT_EQUAL_UINT64(65535, st.check_pixels);
    cfg.texture_min_count = 1; /* still 0 dark pixels: excluded */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, &st));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EXCLUDED, g_out[0].status);
    g_long2[7] = 9u; /* one dark pixel: enough for min count 1 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, &st));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_out[0].status);
    TEST_ASSERT_EQUAL_INT32(0, g_out[0].dx);
    /* the flat test on that row: 65533 x 250, one 255, one 9: m = 249
       (floor), deviation 65533 + 6 + 240 = 65779 -> floor(256 * 65779 /
       65535) = 256: a texture of 1.0, under the default 1.25 */
    cfg.flags = SSDA_TRACK_EXCLUDE;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, &st));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_FLAT, g_out[0].status);
    TEST_ASSERT_EQUAL_UINT32(256, g_out[0].texture_q8);
    TEST_ASSERT_EQUAL_UINT64(2u * 65535u, st.check_pixels); /* the two passes */
}

/* The flat test's accumulators at their worst: a 65535 x 1 16-bit window
   of alternating 65535 and 0 (32768 and 32767 of them): sum 32768 * 65535
   < 2^32 per row, m = 32768, deviation 2 * 32767 * 32768 = 2^31 - 2^16 in
   the row's 32-bit sum, texture floor(256 * that / 65535). */
static uint16_t g_wide1[65535];
static uint16_t g_wide2[65535];

static void test_flat_test_worst_case(void)
{
    ssda_track_config_t cfg;
    ssda_view_t a, b;
    uint32_t i;
    const uint64_t dev = 2ull * 32767u * 32768u;
    for (i = 0; i < 65535u; i++) {
        g_wide2[i] = (uint16_t)(i % 2u == 0u ? 65535u : 0u);
        g_wide1[i] = g_wide2[i];
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_wide1, 65535, 1, 2u * 65535u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_wide2, 65535, 1, 2u * 65535u, SSDA_PIX_U16));
    memset(&cfg, 0, sizeof cfg);
    cfg.win_w = 65535;
    cfg.win_h = 1;
    cfg.search_w = 65535;
    cfg.search_h = 1;
    cfg.flat_q8 = 65535u * 256u; /* the largest level: flat below it */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, NULL));
    TEST_ASSERT_EQUAL_UINT32((uint32_t)(dev * 256u / 65535u), g_out[0].texture_q8);
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_FLAT, g_out[0].status);
    cfg.flat_q8 = (uint32_t)(dev * 256u / 65535u); /* at the level: not flat */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, 1, NULL));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_out[0].status);
    TEST_ASSERT_EQUAL_UINT64(0, g_out[0].sad);
}

/* A default is always valid (issue 22, item 2): with exclusion on, the
   default texture_min_count of a 1 x 1 window (1 before, above 1 / 2) was
   refused with SSDA_ERR_ARG. A single pixel has no texture: nothing is
   excluded, so the vectors equal those of the run without exclusion. Small
   windows (2 and 15 pixels) get at least 1. An explicit count above
   w*h / 2 is still refused. */
static void test_default_min_count_is_valid_for_tiny_windows(void)
{
    ssda_view_t a, b;
    ssda_track_config_t cfg;
    ssda_track_stats_t st, st_plain;
    uint32_t k, n;
    make_pair_u8(field_uniform, 77u);
    views_u8(&a, &b);
    seed_config(&cfg);
    cfg.win_w = 1;
    cfg.win_h = 1;
    cfg.search_w = 9;
    cfg.search_h = 9;
    cfg.step_x = 16;
    cfg.step_y = 16;
    n = 7u * 7u;
    cfg.flags = SSDA_TRACK_EXCLUDE;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, n, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.excluded);
    cfg.flags = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out2, n, &st_plain));
    for (k = 0; k < n; k++) {
        TEST_ASSERT_EQUAL_UINT8(g_out2[k].status, g_out[k].status);
        TEST_ASSERT_EQUAL_INT32(g_out2[k].dx, g_out[k].dx);
        TEST_ASSERT_EQUAL_INT32(g_out2[k].dy, g_out[k].dy);
    }
    TEST_ASSERT_EQUAL_UINT32(st_plain.ok, st.ok);
    cfg.flags = SSDA_TRACK_EXCLUDE;
    cfg.texture_min_count = 1; /* explicit: above 1 / 2 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_track(&a, &b, &cfg, g_out, n, &st));
    /* 1 x 2 and 3 x 5: the default is 1, so a flat window is excluded */
    cfg.texture_min_count = 0;
    cfg.win_h = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, n, &st));
    cfg.win_w = 3;
    cfg.win_h = 5;
    memset(g_second, 7, sizeof g_second);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, n, &st));
    TEST_ASSERT_EQUAL_UINT32(st.windows, st.excluded + st.edge);
    TEST_ASSERT_TRUE(st.excluded > 0u);
}

/* Every argument error returns its code and writes neither out nor stats. */
static void expect_error(int code, const ssda_view_t *a, const ssda_view_t *b,
                         const ssda_track_config_t *cfg, size_t n)
{
    ssda_track_stats_t st, st0;
    memset(g_out, 0xA5, sizeof g_out);
    memset(g_out2, 0xA5, sizeof g_out2);
    memset(&st, 0x5A, sizeof st);
    memcpy(&st0, &st, sizeof st);
    TEST_ASSERT_EQUAL_INT(code, ssda_track(a, b, cfg, g_out, n, &st));
    TEST_ASSERT_EQUAL_MEMORY(g_out2, g_out, sizeof g_out);
    TEST_ASSERT_EQUAL_MEMORY(&st0, &st, sizeof st);
}

static void test_bad_arguments_write_nothing(void)
{
    ssda_track_config_t cfg;
    ssda_track_grid_t g, g0;
    ssda_view_t a, b, bad, a16;
    make_pair_u8(field_smooth, 19);
    views_u8(&a, &b);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a16, g_first16, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
    seed_config(&cfg);

    expect_error(SSDA_ERR_NULL, NULL, &b, &cfg, NWIN);
    expect_error(SSDA_ERR_NULL, &a, NULL, &cfg, NWIN);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_track(&a, &b, &cfg, NULL, NWIN, NULL));
    bad = a;
    bad.width = 0;
    expect_error(SSDA_ERR_SIZE, &bad, &b, &cfg, NWIN);
    bad = b;
    bad.stride = IMG - 1u;
    expect_error(SSDA_ERR_STRIDE, &a, &bad, &cfg, NWIN);
    bad = b;
    bad.format = 3;
    expect_error(SSDA_ERR_FORMAT, &a, &bad, &cfg, NWIN);
    expect_error(SSDA_ERR_FORMAT, &a16, &b, &cfg, NWIN);
    expect_error(SSDA_ERR_BUFFER, &a, &b, &cfg, NWIN - 1u);

    seed_config(&cfg); cfg.search_w = 15;
    expect_error(SSDA_ERR_SIZE, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.roi_x = 20; /* 20 + 112 > 128 */
    expect_error(SSDA_ERR_SIZE, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.roi_y = IMG; cfg.roi_h = 0;
    expect_error(SSDA_ERR_SIZE, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.roi_w = 15;
    expect_error(SSDA_ERR_SIZE, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.win_h = 129;
    expect_error(SSDA_ERR_SIZE, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.predict = 3;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.flags = 0x20;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.flat_q8 = 65535u * 256u + 1u;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); /* the block levels: single searches only */
    cfg.match.flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
    cfg.match.work = g_work;
    cfg.match.work_size = sizeof g_work;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.flags = SSDA_TRACK_UNIQUE; /* no work buffer */
    expect_error(SSDA_ERR_NULL, &a, &b, &cfg, NWIN);
    cfg.match.work = g_work;
    cfg.match.work_size = SSDA_MATCH_UNIQUE_WORK - 1u;
    expect_error(SSDA_ERR_BUFFER, &a, &b, &cfg, NWIN);
    cfg.match.work_size = sizeof g_work;
    cfg.unique_radius = 3;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    cfg.unique_radius = 0;
    cfg.match.threshold = SSDA_THRESHOLD_FIXED; /* uniqueness: exact modes only */
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.flags = SSDA_TRACK_MASK; cfg.mask_value = 256;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.flags = SSDA_TRACK_EXCLUDE; cfg.texture_threshold = 255;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.flags = SSDA_TRACK_EXCLUDE; cfg.texture_min_count = 129;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.predict = SSDA_TRACK_PREDICT_LEFT; cfg.match.scan = SSDA_SCAN_COARSE;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.match.threshold = 9;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.match.threshold = SSDA_THRESHOLD_RAMP;
    expect_error(SSDA_ERR_ARG, &a, &b, &cfg, NWIN);
    seed_config(&cfg); cfg.match.flags = SSDA_MATCH_BOUNDS;
    expect_error(SSDA_ERR_NULL, &a, &b, &cfg, NWIN);
    cfg.match.work = g_work;
    cfg.match.work_size = SSDA_MATCH_WORK_SIZE(32, 32, 16, 16) - 1u;
    expect_error(SSDA_ERR_BUFFER, &a, &b, &cfg, NWIN);
    cfg.match.work = (uint8_t *)g_work + 2;
    cfg.match.work_size = sizeof g_work - 4u;
    expect_error(SSDA_ERR_BUFFER, &a, &b, &cfg, NWIN);
    cfg.flags = SSDA_TRACK_UNIQUE; /* with uniqueness: the tables and the list */
    cfg.match.work = g_work;
    cfg.match.work_size = SSDA_TRACK_WORK_SIZE(32, 32, 16, 16) - 1u;
    expect_error(SSDA_ERR_BUFFER, &a, &b, &cfg, NWIN);
    cfg.match.work_size = SSDA_MATCH_WORK_SIZE(32, 32, 16, 16);
    expect_error(SSDA_ERR_BUFFER, &a, &b, &cfg, NWIN);

    /* the limits themselves are accepted */
    seed_config(&cfg);
    cfg.flags = SSDA_TRACK_EXCLUDE | SSDA_TRACK_MASK;
    cfg.mask_value = 255;
    cfg.texture_threshold = 254;
    cfg.texture_min_count = 128;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, NULL));
    seed_config(&cfg); /* bounds alone: their tables suffice (track.h) */
    cfg.match.flags = SSDA_MATCH_BOUNDS;
    cfg.match.work = g_work;
    cfg.match.work_size = SSDA_MATCH_WORK_SIZE(32, 32, 16, 16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, NULL));
    cfg.flags = SSDA_TRACK_UNIQUE;
    cfg.match.work_size = SSDA_TRACK_WORK_SIZE(32, 32, 16, 16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, NWIN, NULL));

    memset(&g, 0x33, sizeof g);
    memcpy(&g0, &g, sizeof g);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_track_grid(NULL, IMG, IMG, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_track_grid(NULL, 0, IMG, &g));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_track_grid(NULL, 15, IMG, &g));
    seed_config(&cfg); cfg.search_h = 8;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_track_grid(&cfg, IMG, IMG, &g));
    TEST_ASSERT_EQUAL_MEMORY(&g0, &g, sizeof g);
}

/* A grid whose vector array cannot exist: on a 32-bit target 16384 x 32768
   images with 1 x 1 windows at step 1 give 2^29 windows, 18 GB or more
   of vectors, and SSDA_TRACK_OUT_SIZE wraps. Refused with
   SSDA_ERR_BUFFER before any pixel is read (the views claim the size; a
   small buffer stands in) and nothing written, even with out_count =
   the grid count. The stream and push entry points share the check. */
static void test_grid_beyond_the_address_space_is_refused(void)
{
#if SIZE_MAX <= UINT32_MAX
    static uint8_t px[16];
    static ssda_track_vector_t out[2];
    ssda_view_t a;
    ssda_track_config_t c;
    ssda_track_grid_t g;
    ssda_track_stats_t st, poison;
    memset(&c, 0, sizeof c);
    c.win_w = c.win_h = c.search_w = c.search_h = c.step_x = c.step_y = 1;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, px, 16384u, 32768u, 16384u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, 16384u, 32768u, &g));
    TEST_ASSERT_EQUAL_UINT32(1u << 29, g.count);
    /* the macro wraps: below the true size (to 0 with 24- or 40-byte
       vectors, to 2^31 with the 36-byte ones of i386's 4-byte alignment) */
    TEST_ASSERT_TRUE((uint64_t)SSDA_TRACK_OUT_SIZE(16384u, 32768u, 1u, 1u, 1u, 1u) <
                     (uint64_t)g.count * sizeof(ssda_track_vector_t));
    memset(out, 0x77, sizeof out);
    memset(&poison, 0x44, sizeof poison);
    st = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_track(&a, &a, &c, out, g.count, &st));
    {
        static uint32_t ring[4096]; /* 16 KB: the 1-row band of 16384 px fits */
        ssda_source_t src;
        ssda_push_t p, before;
        memset(&p, 0x33, sizeof p);
        before = p;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&src, &a));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                              ssda_stream_track(&src, &src, &c, out, g.count, &st));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                              test_push_init_track(&p, 16384u, 32768u, SSDA_PIX_U8,
                                                   SSDA_PUSH_FIRST, &src, &c, out, g.count,
                                                   &st, ring, sizeof ring));
        TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    }
    TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    TEST_ASSERT_EACH_EQUAL_HEX8(0x77, out, sizeof out);
#else
    TEST_IGNORE_MESSAGE("a 64-bit size_t holds any grid's vectors");
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_grid_layout_and_defaults);
    RUN_TEST(test_grid_beyond_the_address_space_is_refused);
    RUN_TEST(test_known_uniform_shift);
    RUN_TEST(test_spatially_varying_field);
    RUN_TEST(test_stats_are_sums_of_per_window_searches);
    RUN_TEST(test_prediction_reduces_work_same_vectors);
    RUN_TEST(test_median_prediction_hits_uniform_field);
    RUN_TEST(test_texture_exclusion_rule);
    RUN_TEST(test_mask_value_u16);
    RUN_TEST(test_mask_pixel_on_row_and_column_edges);
    RUN_TEST(test_edge_status);
    RUN_TEST(test_extreme_geometry);
    RUN_TEST(test_flat_test_worst_case);
    RUN_TEST(test_bad_arguments_write_nothing);
    RUN_TEST(test_default_min_count_is_valid_for_tiny_windows);
    return UNITY_END();
}
