/*
 * test_register.c - control points on pairs with a known map: the moving
 * image is made here from the reference by a smooth map with a bilinear
 * resampler written in this file (not the library's warp); each point must
 * lie on the map within 0.35 px. The chosen window against a brute-force
 * variance over the lattice, the placement against the brute-force SAD
 * minimum, statuses (flat cells, areas outside the image, matches on the
 * area's border), streamed sources equal to in-RAM ones, and errors.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/register.h"
#include "test_image.h"
#include "test_rng.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#ifndef SSDA_TEST_SMALL
#define TRIALS 6
#else
#define TRIALS 2 /* emulated boards: fewer pairs */
#endif

#define RW 240u
#define RH 180u

static uint8_t g_ref[RH][RW], g_mov[RH][RW];
static uint16_t g_ref16[RH][RW], g_mov16[RH][RW];
static uint64_t g_work[(SSDA_REGISTER_WORK_SIZE(40, 80, 2) + 7u) / 8u];
static ssda_register_point_t g_pts[64], g_pts2[64];
/* devices: the image tiled in 32 x 16 tiles (8 x 12 of them) at 16 bits */
#define DEV_BYTES (8u * 12u * 32u * 16u * 2u + 64u)
static uint8_t g_dev_r[DEV_BYTES], g_dev_m[DEV_BYTES];
/* arenas: up to the whole image (with a bounce buffer) */
#define ARENA_WORDS ((RW * RH * 2u + 1024u) / 4u)
static uint32_t g_arena_r[ARENA_WORDS], g_arena_m[ARENA_WORDS];
static test_source_t g_tr, g_tm;

/* The known map: moving = reference + (dx, dy) + a rotation of `rot` rad
   about the centre (small-angle form, exact as a map). */
typedef struct {
    double dx, dy, rot;
} map_t;

static void map_apply(const map_t *m, double X, double Y, double *x, double *y)
{
    const double cx = RW / 2.0, cy = RH / 2.0;
    *x = X + m->dx - m->rot * (Y - cy);
    *y = Y + m->dy + m->rot * (X - cx);
}

/* A smooth random field: noise blurred by three passes of a 7-tap box
   (correlation length ~5 px), sampled between grid points by Catmull-Rom
   bicubic interpolation, so that the moving image holds the same field at
   sub-pixel positions. */
#define FP 8 /* pad around the field */
static double g_field[RH + 2 * FP][RW + 2 * FP];

static void make_field(test_rng_t *r)
{
    static double tmp[RH + 2 * FP][RW + 2 * FP];
    int x, y, pass, k;
    for (y = 0; y < (int)RH + 2 * FP; y++)
        for (x = 0; x < (int)RW + 2 * FP; x++) g_field[y][x] = (double)test_rng_next(r) / 4294967296.0;
    for (pass = 0; pass < 3; pass++) {
        for (y = 0; y < (int)RH + 2 * FP; y++)
            for (x = 0; x < (int)RW + 2 * FP; x++) {
                double s = 0;
                for (k = -3; k <= 3; k++) {
                    int xx = x + k < 0 ? 0 : (x + k >= (int)RW + 2 * FP ? (int)RW + 2 * FP - 1 : x + k);
                    s += g_field[y][xx];
                }
                tmp[y][x] = s / 7.0;
            }
        for (y = 0; y < (int)RH + 2 * FP; y++)
            for (x = 0; x < (int)RW + 2 * FP; x++) {
                double s = 0;
                for (k = -3; k <= 3; k++) {
                    int yy = y + k < 0 ? 0 : (y + k >= (int)RH + 2 * FP ? (int)RH + 2 * FP - 1 : y + k);
                    s += tmp[yy][x];
                }
                g_field[y][x] = s / 7.0;
            }
    }
}

static double cubic(double p0, double p1, double p2, double p3, double t)
{
    return p1 + 0.5 * t * (p2 - p0 + t * (2 * p0 - 5 * p1 + 4 * p2 - p3 + t * (3 * (p1 - p2) + p3 - p0)));
}

/* The field at (x, y) px of the image (clamped into the padded grid), as a
   grey level: the blurred noise (sd ~0.05) stretched around 128. */
static double texture(double x, double y)
{
    double col[4], v;
    int ix, iy, j, k;
    x += FP;
    y += FP;
    x = x < 1 ? 1 : (x > RW + 2 * FP - 3 ? RW + 2 * FP - 3 : x);
    y = y < 1 ? 1 : (y > RH + 2 * FP - 3 ? RH + 2 * FP - 3 : y);
    ix = (int)x;
    iy = (int)y;
    for (j = 0; j < 4; j++) {
        const double *row = g_field[iy - 1 + j];
        col[j] = cubic(row[ix - 1], row[ix], row[ix + 1], row[ix + 2], x - ix);
    }
    (void)k;
    v = 128.0 + (cubic(col[0], col[1], col[2], col[3], y - iy) - 0.5) * 1400.0;
    v = v < 0 ? 0 : (v > 255 ? 255 : v);
    return (double)(int)(v + 0.5);
}

/* The pair: reference = the field, moving(x, y) = the field at the
   reference position that maps to (x, y) (the map inverted by a fixed-point
   iteration: it is close to the identity). invert: 255 - that. */
static void make_pair(test_rng_t *r, const map_t *m, int invert)
{
    uint32_t x, y;
    make_field(r);
    for (y = 0; y < RH; y++) {
        for (x = 0; x < RW; x++) {
            double X = x, Y = y, u, v;
            int it;
            g_ref[y][x] = (uint8_t)texture(x, y);
            for (it = 0; it < 6; it++) { /* the map is within 1 % of the identity */
                map_apply(m, X, Y, &u, &v);
                X -= u - x;
                Y -= v - y;
            }
            g_mov[y][x] = (uint8_t)(invert ? 255 - (int)texture(X, Y) : (int)texture(X, Y));
            g_ref16[y][x] = (uint16_t)(g_ref[y][x] * 16u);
            g_mov16[y][x] = (uint16_t)(g_mov[y][x] * 16u);
        }
    }
}

static void ram_sources(ssda_source_t *ref, ssda_source_t *mov, uint8_t format)
{
    ssda_view_t a, b;
    if (format == SSDA_PIX_U8) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_ref, RW, RH, RW, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_mov, RW, RH, RW, SSDA_PIX_U8));
    } else {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_ref16, RW, RH, RW * 2, SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_mov16, RW, RH, RW * 2, SSDA_PIX_U16));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(ref, &a));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(mov, &b));
}

/* The device layouts of the bound test: raster read at byte granularity,
   and tiled (32 x 16 tiles) read in 16-byte units. */
typedef struct {
    uint8_t layout;
    uint16_t tile_w, tile_h;
    uint32_t read_size;
} layout_t;
static const layout_t k_raster = {SSDA_LAYOUT_RASTER, 0, 0, 1};
static const layout_t k_tiled = {SSDA_LAYOUT_TILED, 32, 16, 16};

static void stream_sources_in(ssda_source_t *ref, ssda_source_t *mov, uint8_t format,
                              const layout_t *l, size_t ar, size_t am)
{
    ssda_source_t r0, m0;
    ssda_view_t a, b;
    ssda_source_config_t ca, cb;
    TEST_ASSERT_TRUE(ar <= sizeof g_arena_r && am <= sizeof g_arena_m);
    ram_sources(&r0, &m0, format);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, r0.view, RW, RH, RW * format, (ssda_pixfmt_t)format));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, m0.view, RW, RH, RW * format, (ssda_pixfmt_t)format));
    test_source_init(&g_tr, g_dev_r, sizeof g_dev_r, l->read_size);
    test_source_init(&g_tm, g_dev_m, sizeof g_dev_m, l->read_size);
    ca = test_source_config(&g_tr, &a, l->layout, l->tile_w, l->tile_h, 0, 0, 0, l->read_size, g_arena_r, ar);
    cb = test_source_config(&g_tm, &b, l->layout, l->tile_w, l->tile_h, 0, 0, 0, l->read_size, g_arena_m, am);
    test_source_store(&g_tr, &ca, &a);
    test_source_store(&g_tm, &cb, &b);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(ref, &ca));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(mov, &cb));
}

static void stream_sources(ssda_source_t *ref, ssda_source_t *mov, uint8_t format, size_t ar, size_t am)
{
    stream_sources_in(ref, mov, format, &k_raster, ar, am);
}

/* Every cell of a textured pair with a known shift and rotation: OK, on
   the map within 0.75 px, RMS below 0.25 px (sub-pixel), both formats. */
static void test_points_on_known_map(void)
{
    test_rng_t r;
    int trial;
    double sum2 = 0;
    int count = 0;
    test_rng_seed(&r, 0x52454749u);
    for (trial = 0; trial < TRIALS; trial++) {
        const map_t m = {((double)test_rng_next(&r) / 4294967296.0 - 0.5) * 12.0,
                         ((double)test_rng_next(&r) / 4294967296.0 - 0.5) * 12.0,
                         ((double)test_rng_next(&r) / 4294967296.0 - 0.5) * 0.02};
        const uint8_t format = (uint8_t)(1 + trial % 2);
        ssda_source_t ref, mov;
        ssda_register_config_t cfg;
        size_t ok = 0, k;
        make_pair(&r, &m, 0);
        ram_sources(&ref, &mov, format);
        memset(&cfg, 0, sizeof cfg);
        cfg.metric = SSDA_REGISTER_SAD;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok,
                                                            g_work, sizeof g_work));
        TEST_ASSERT_EQUAL_UINT32(16, (uint32_t)ok);
        for (k = 0; k < 16; k++) {
            double x, y, ex, ey;
            TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_OK, g_pts[k].status);
            TEST_ASSERT_EQUAL_UINT16(k % 4, g_pts[k].cell_x);
            TEST_ASSERT_EQUAL_UINT16(k / 4, g_pts[k].cell_y);
            map_apply(&m, g_pts[k].pair.ref_x_q8 / 256.0, g_pts[k].pair.ref_y_q8 / 256.0, &x, &y);
            ex = g_pts[k].pair.mov_x_q8 / 256.0 - x;
            ey = g_pts[k].pair.mov_y_q8 / 256.0 - y;
            TEST_ASSERT_TRUE(ex * ex + ey * ey < 0.75 * 0.75);
            sum2 += ex * ex + ey * ey;
            count++;
        }
    }
    TEST_ASSERT_TRUE(sum2 / count < 0.25 * 0.25);
}

/* The seed's metric (|rho|, the zero-filled config) on the same kind of
   pairs: every cell OK, RMS below 0.2 px; with inverted contrast |rho|
   still matches (rho < -0.65 everywhere) while rho alone rejects every
   cell (LOW_RHO); and the rho of every point equals ssda_ncc_at at the
   integer placement the point rounds to. */
static void test_correlation_metrics(void)
{
    test_rng_t r;
    int invert;
    test_rng_seed(&r, 0x4E434331u);
    for (invert = 0; invert < 2; invert++) {
        const map_t m = {2.7, -4.1, 0.006};
        ssda_source_t ref, mov;
        ssda_register_config_t cfg;
        size_t ok = 0, k;
        double sum2 = 0;
        make_pair(&r, &m, invert);
        ram_sources(&ref, &mov, SSDA_PIX_U8);
        memset(&cfg, 0, sizeof cfg); /* ABSNCC, 0.65, 4 x 4, 20 in 40 */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok,
                                                            g_work, sizeof g_work));
        TEST_ASSERT_EQUAL_UINT32(16, (uint32_t)ok);
        for (k = 0; k < 16; k++) {
            double x, y, ex, ey;
            ssda_view_t mv, rv, area, win;
            int32_t rho;
            const int32_t tx = (g_pts[k].pair.mov_x_q8 + 128) / 256 - 9; /* top-left */
            const int32_t ty = (g_pts[k].pair.mov_y_q8 + 128) / 256 - 9;
            map_apply(&m, g_pts[k].pair.ref_x_q8 / 256.0, g_pts[k].pair.ref_y_q8 / 256.0, &x, &y);
            ex = g_pts[k].pair.mov_x_q8 / 256.0 - x;
            ey = g_pts[k].pair.mov_y_q8 / 256.0 - y;
            sum2 += ex * ex + ey * ey;
            TEST_ASSERT_TRUE(invert ? g_pts[k].rho_q30 < -697932186 : g_pts[k].rho_q30 > 697932186);
            /* rho where the point lies, measured directly (the sub-pixel
               offset may round to a neighbour: then at most that one's) */
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&mv, g_mov, RW, RH, RW, SSDA_PIX_U8));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&rv, g_ref, RW, RH, RW, SSDA_PIX_U8));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&win, &rv, (uint16_t)((g_pts[k].pair.ref_x_q8 - 9 * 256 - 128) / 256),
                                                         (uint16_t)((g_pts[k].pair.ref_y_q8 - 9 * 256 - 128) / 256), 20, 20));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&area, &mv, (uint16_t)(tx - 1), (uint16_t)(ty - 1), 22, 22));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_at(&area, &win, 1, 1, &rho));
            TEST_ASSERT_TRUE(invert ? rho >= g_pts[k].rho_q30 : rho <= g_pts[k].rho_q30);
        }
        TEST_ASSERT_TRUE(sum2 / 16 < 0.2 * 0.2);
        cfg.metric = SSDA_REGISTER_NCC;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok,
                                                            g_work, sizeof g_work));
        /* inverted: rho alone finds no true match (a smooth texture may
           correlate with some other placement: never within 1 px of it) */
        if (!invert) {
            TEST_ASSERT_EQUAL_UINT32(16, (uint32_t)ok);
        }
        for (k = 0; invert && k < 16; k++) {
            double x, y;
            map_apply(&m, g_pts[k].pair.ref_x_q8 / 256.0, g_pts[k].pair.ref_y_q8 / 256.0, &x, &y);
            TEST_ASSERT_TRUE(g_pts[k].status != SSDA_REGISTER_OK ||
                             (g_pts[k].pair.mov_x_q8 / 256.0 - x) * (g_pts[k].pair.mov_x_q8 / 256.0 - x) +
                                     (g_pts[k].pair.mov_y_q8 / 256.0 - y) * (g_pts[k].pair.mov_y_q8 / 256.0 - y) > 1.0);
        }
        /* SSDA reports rho at its minimum too (positive here, no inversion) */
        cfg.metric = SSDA_REGISTER_SAD;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok,
                                                            g_work, sizeof g_work));
        for (k = 0; !invert && k < 16; k++) {
            TEST_ASSERT_TRUE(g_pts[k].rho_q30 > 697932186);
            TEST_ASSERT_TRUE(g_pts[k].pixel_ops > 0);
        }
    }
}

/* A high threshold rejects weak matches: noise against the texture. */
static void test_low_rho(void)
{
    test_rng_t r;
    const map_t m = {0.0, 0.0, 0.0};
    ssda_source_t ref, mov;
    ssda_register_config_t cfg;
    size_t ok = 0, k;
    uint32_t x, y;
    test_rng_seed(&r, 21);
    make_pair(&r, &m, 0);
    for (y = 0; y < RH; y++)
        for (x = 0; x < RW; x++) g_mov[y][x] = (uint8_t)test_rng_next(&r); /* unrelated noise */
    ram_sources(&ref, &mov, SSDA_PIX_U8);
    memset(&cfg, 0, sizeof cfg);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)ok);
    for (k = 0; k < 16; k++) {
        TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_LOW_RHO, g_pts[k].status);
    }
}

/* The window of each cell is the brute-force most-varied one on the
   lattice; the placement is the brute-force SAD minimum of that window in
   that area (search x search, its top-left (search - 16) / 2 px up-left of
   the window's, clipped); the status is BORDER exactly when that minimum
   touches the area's edge (register.h, step 5). Shifts beyond the margin
   put minima on every edge; an odd search - window rounds the margin
   down. */
static void check_window_placement_status(const map_t *m, uint32_t search)
{
    test_rng_t r;
    ssda_source_t ref, mov;
    ssda_register_config_t cfg;
    ssda_view_t rv, mv;
    const uint32_t margin = (search - 16u) / 2u;
    size_t k;
    test_rng_seed(&r, 11);
    make_pair(&r, m, 0);
    ram_sources(&ref, &mov, SSDA_PIX_U8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&rv, g_ref, RW, RH, RW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&mv, g_mov, RW, RH, RW, SSDA_PIX_U8));
    memset(&cfg, 0, sizeof cfg);
    cfg.metric = SSDA_REGISTER_SAD;
    cfg.grid_x = 3;
    cfg.grid_y = 2;
    cfg.window = 16;
    cfg.search = (uint16_t)search;
    cfg.step = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 6, NULL, g_work, sizeof g_work));
    for (k = 0; k < 6; k++) {
        const uint32_t i = k % 3, j = k / 3;
        const uint32_t x0 = i * RW / 3, x1 = (i + 1) * RW / 3, y0 = j * RH / 2, y1 = (j + 1) * RH / 2;
        uint32_t x, y, bx = 0, by = 0, ax, ay, aw, ah, px, py;
        double best = -1;
        uint64_t bsad;
        ssda_view_t area, win;
        for (y = y0; y + 16 <= y1; y += 3) {
            for (x = x0; x + 16 <= x1; x += 3) {
                double s1 = 0, s2 = 0, v;
                uint32_t a, b;
                /* windows whose area fits the image first (every cell has
                   some here) */
                if (x < margin || y < margin || x - margin + search > RW || y - margin + search > RH) {
                    continue;
                }
                for (b = 0; b < 16; b++)
                    for (a = 0; a < 16; a++) {
                        s1 += g_ref[y + b][x + a];
                        s2 += (double)g_ref[y + b][x + a] * g_ref[y + b][x + a];
                    }
                v = 256.0 * s2 - s1 * s1;
                if (v > best) { best = v; bx = x; by = y; }
            }
        }
        TEST_ASSERT_EQUAL_INT32((int32_t)(2 * bx + 15) * 128, g_pts[k].pair.ref_x_q8);
        TEST_ASSERT_EQUAL_INT32((int32_t)(2 * by + 15) * 128, g_pts[k].pair.ref_y_q8);
        /* the area around the window (offset 0), clipped: here it fits */
        ax = bx - margin;
        ay = by - margin;
        aw = search;
        ah = search;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&area, &mv, (uint16_t)ax, (uint16_t)ay, (uint16_t)aw, (uint16_t)ah));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&win, &rv, (uint16_t)bx, (uint16_t)by, 16, 16));
        test_best(&area, &win, &px, &py, &bsad);
        TEST_ASSERT_EQUAL_UINT64(bsad, g_pts[k].sad);
        /* the integer part of the match (sub-pixel within +-1/2) */
        TEST_ASSERT_INT32_WITHIN(128, (int32_t)(2 * (ax + px) + 15) * 128, g_pts[k].pair.mov_x_q8);
        TEST_ASSERT_INT32_WITHIN(128, (int32_t)(2 * (ay + py) + 15) * 128, g_pts[k].pair.mov_y_q8);
        TEST_ASSERT_EQUAL_UINT8(px == 0 || py == 0 || px + 16 == aw || py + 16 == ah
                                    ? SSDA_REGISTER_BORDER : SSDA_REGISTER_OK,
                                g_pts[k].status);
    }
}

static void test_window_and_placement_brute_force(void)
{
    static const map_t maps[5] = {{3.0, -2.0, 0.0}, {9.0, 1.0, 0.0}, {-1.0, -9.0, 0.0},
                                  {-9.0, 9.0, 0.0}, {1.0, 2.0, 0.0}};
    uint32_t t, borders = 0;
    for (t = 0; t < 5u; t++) {
        size_t k;
        check_window_placement_status(&maps[t], t % 2u == 0u ? 30u : 31u);
        for (k = 0; k < 6; k++) {
            borders += g_pts[k].status == SSDA_REGISTER_BORDER;
        }
    }
    TEST_ASSERT_TRUE(borders >= 6u); /* the rule was exercised */
}

/* The thresholds at equality: a cell whose only window has a variance of
   exactly min_texture grey^2 is not FLAT, just below it is (and the
   defaults, 4 at 8 bits and 1024 at 16, are those thresholds); a point
   whose |rho| (rho for NCC) equals min_rho is LOW_RHO, one LSB lower
   it is not (register.h: "not above min_rho"). */
static void test_thresholds_at_equality(void)
{
    static uint8_t img8[8][8];
    static uint16_t img16[8][8];
    ssda_register_config_t cfg;
    ssda_source_t ref, mov;
    ssda_view_t v;
    ssda_register_point_t pt;
    uint32_t i, metric;
    size_t k;
    memset(&cfg, 0, sizeof cfg);
    cfg.grid_x = 1;
    cfg.grid_y = 1;
    cfg.window = 8;
    cfg.search = 8;
    cfg.step = 8;
    for (i = 0; i < 64u; i++) { /* half 0, half 4: variance 4 exactly */
        img8[i / 8u][i % 8u] = (uint8_t)((i + i / 8u) % 2u * 4u);
        img16[i / 8u][i % 8u] = (uint16_t)((i + i / 8u) % 2u * 64u); /* 1024 */
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, img8, 8, 8, 8, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ref, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&mov, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, &pt, 1, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT32(4, pt.texture);
    TEST_ASSERT_TRUE(pt.status != SSDA_REGISTER_FLAT);
    cfg.min_texture = 5;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, &pt, 1, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_FLAT, pt.status);
    cfg.min_texture = 4;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, &pt, 1, NULL, g_work, sizeof g_work));
    TEST_ASSERT_TRUE(pt.status != SSDA_REGISTER_FLAT);
    cfg.min_texture = 0;
    img8[3][3] = 3; /* variance 3.95: below the default */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, &pt, 1, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_FLAT, pt.status);
    TEST_ASSERT_EQUAL_UINT32(3, pt.texture);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, img16, 8, 8, 16, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ref, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&mov, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, &pt, 1, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT32(1024, pt.texture);
    TEST_ASSERT_TRUE(pt.status != SSDA_REGISTER_FLAT);
    img16[3][3] = 63;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, &pt, 1, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_FLAT, pt.status);
    /* equal variances: the first window in raster order of the lattice (a
       reference periodic with the step: every window the same) */
    {
        static uint8_t per[64][64];
        ssda_register_point_t four[4];
        uint32_t x, y;
        for (y = 0; y < 64u; y++) {
            for (x = 0; x < 64u; x++) {
                per[y][x] = (uint8_t)(((x % 4u) * 37u + (y % 4u) * 71u) % 256u);
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, per, 64, 64, 64, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ref, &v));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&mov, &v));
        cfg.grid_x = 2;
        cfg.grid_y = 2;
        cfg.step = 4;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, four, 4, NULL, g_work, sizeof g_work));
        for (k = 0; k < 4; k++) {
            TEST_ASSERT_EQUAL_INT32((int32_t)(2u * 32u * (k % 2u) + 7u) * 128, four[k].pair.ref_x_q8);
            TEST_ASSERT_EQUAL_INT32((int32_t)(2u * 32u * (k / 2u) + 7u) * 128, four[k].pair.ref_y_q8);
        }
    }
    /* min_rho at equality, on textured pairs with both correlation metrics */
    for (metric = SSDA_REGISTER_ABSNCC; metric <= SSDA_REGISTER_NCC; metric++) {
        test_rng_t r;
        const map_t m = {2.0, -1.0, 0.01};
        ssda_register_point_t pts[16];
        uint32_t checked = 0;
        test_rng_seed(&r, 40u + metric);
        make_pair(&r, &m, 0);
        ram_sources(&ref, &mov, SSDA_PIX_U8);
        memset(&cfg, 0, sizeof cfg);
        cfg.metric = (uint8_t)metric;
        cfg.min_rho_q30 = 1; /* every match is above it */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
        memcpy(pts, g_pts, sizeof pts);
        for (k = 0; k < 16; k++) {
            const int32_t a = pts[k].rho_q30 < 0 ? -pts[k].rho_q30 : pts[k].rho_q30;
            if (pts[k].status != SSDA_REGISTER_OK && pts[k].status != SSDA_REGISTER_BORDER) {
                continue;
            }
            cfg.min_rho_q30 = metric == SSDA_REGISTER_NCC ? pts[k].rho_q30 : a;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
            TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_LOW_RHO, g_pts[k].status);
            cfg.min_rho_q30--;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
            TEST_ASSERT_EQUAL_UINT8(pts[k].status, g_pts[k].status);
            if (++checked == 3u) {
                break;
            }
        }
        TEST_ASSERT_EQUAL_UINT32(3, checked);
    }
}

/* Flat cells, areas that leave the image, and matches beyond the search
   range (reported on the border). */
static void test_statuses(void)
{
    test_rng_t r;
    const map_t m = {0.0, 0.0, 0.0};
    ssda_source_t ref, mov;
    ssda_register_config_t cfg;
    size_t ok, k;
    uint32_t x, y;
    test_rng_seed(&r, 12);
    make_pair(&r, &m, 0);
    for (y = 0; y < RH / 4; y++)
        for (x = 0; x < RW / 4; x++) g_ref[y][x] = 77; /* cell (0, 0) flat */
    ram_sources(&ref, &mov, SSDA_PIX_U8);
    memset(&cfg, 0, sizeof cfg);
    cfg.metric = SSDA_REGISTER_SAD;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_FLAT, g_pts[0].status);
    TEST_ASSERT_EQUAL_UINT32(0, g_pts[0].texture);
    TEST_ASSERT_EQUAL_UINT32(15, (uint32_t)ok);
    /* the same pair shifted by 25 px: beyond +-10, matches on the border */
    {
        const map_t far = {25.0, 0.0, 0.0};
        test_rng_seed(&r, 12);
        make_pair(&r, &far, 0);
    }
    /* the true match lies outside every area: no point is on the map
       (what SSDA finds there is the best of wrong placements: on the
       border, or inside; the seed's rho threshold is what rejects those) */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok, g_work, sizeof g_work));
    for (k = 0; k < 16; k++) {
        TEST_ASSERT_FALSE(g_pts[k].status == SSDA_REGISTER_OK &&
                          g_pts[k].pair.mov_x_q8 - g_pts[k].pair.ref_x_q8 > 24 * 256 &&
                          g_pts[k].pair.mov_x_q8 - g_pts[k].pair.ref_x_q8 < 26 * 256);
    }
    /* with the offset given, found again */
    cfg.offset_x = 25;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok, g_work, sizeof g_work));
    TEST_ASSERT_TRUE(ok >= 12); /* the right column's areas leave the image */
    for (k = 0; k < 16; k++) {
        if (g_pts[k].status == SSDA_REGISTER_OK) {
            TEST_ASSERT_INT32_WITHIN(90, g_pts[k].pair.ref_x_q8 + 25 * 256, g_pts[k].pair.mov_x_q8);
        }
    }
    /* an offset that puts every area outside */
    cfg.offset_x = 1000;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, &ok, g_work, sizeof g_work));
    for (k = 0; k < 16; k++) TEST_ASSERT_EQUAL_UINT8(SSDA_REGISTER_OUTSIDE, g_pts[k].status);
}

/* Streamed sources in small arenas (from the least each accepts: a band
   of 20 rows of a 60 px cell, a row of a 40 px area) give the in-RAM
   points. */
static void test_streamed_equals_ram(void)
{
    test_rng_t r;
    const map_t m = {4.5, -3.25, 0.01};
    ssda_source_t ref, mov;
    ssda_register_config_t cfg;
    uint8_t format;
    test_rng_seed(&r, 13);
    make_pair(&r, &m, 0);
    memset(&cfg, 0, sizeof cfg);
    cfg.metric = SSDA_REGISTER_SAD;
    for (format = 1; format <= 2; format++) {
        static const size_t arenas[][2] = {{1200, 40}, {1900, 700}, {4096, 4096}};
        size_t a;
        ram_sources(&ref, &mov, format);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
        for (a = 0; a < 3; a++) {
            stream_sources(&ref, &mov, format, arenas[a][0] * format, arenas[a][1] * format);
            memset(g_pts2, 0xEE, sizeof g_pts2);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts2, 16, NULL, g_work, sizeof g_work));
            TEST_ASSERT_EQUAL_MEMORY(g_pts, g_pts2, 16 * sizeof g_pts[0]);
        }
        /* a read error comes back unchanged */
        stream_sources(&ref, &mov, format, 1900 * format, 700 * format);
        g_tm.fail_at_read = 5;
        g_tm.fail_code = -41;
        TEST_ASSERT_EQUAL_INT(-41, ssda_register_points(&ref, &mov, &cfg, g_pts2, 16, NULL, g_work, sizeof g_work));
        stream_sources(&ref, &mov, format, 1900 * format, 700 * format);
        g_tr.fail_at_read = 3;
        g_tr.fail_code = -42;
        TEST_ASSERT_EQUAL_INT(-42, ssda_register_points(&ref, &mov, &cfg, g_pts2, 16, NULL, g_work, sizeof g_work));
    }
}

/* Columns [x, x + w) of a row of the layout: the bytes a read of that row
   may cost beyond alignment (raster: w px; tiled: every tile row it
   touches whole, since a run of rows of a tile is one read). */
static uint64_t row_cost(const layout_t *l, uint32_t x, uint32_t w, uint8_t fmt)
{
    if (l->layout == SSDA_LAYOUT_RASTER) {
        return (uint64_t)w * fmt;
    }
    return (uint64_t)((x + w - 1u) / l->tile_w - x / l->tile_w + 1u) * l->tile_w * fmt;
}

/* The reference's reads by register.h's plan, from the cells and the
   lattice alone: each cell's windows' rectangle once. */
static uint64_t ref_once(const layout_t *l, const ssda_register_config_t *c, uint8_t fmt)
{
    const uint32_t gx = c->grid_x ? c->grid_x : 4u, gy = c->grid_y ? c->grid_y : 4u;
    const uint32_t win = c->window ? c->window : 20u;
    const uint32_t step = c->step ? c->step : (win / 4u ? win / 4u : 1u);
    uint64_t sum = 0;
    uint32_t i, j;
    for (j = 0; j < gy; j++) {
        for (i = 0; i < gx; i++) {
            const uint32_t x0 = i * RW / gx, x1 = (i + 1u) * RW / gx;
            const uint32_t y0 = j * RH / gy, y1 = (j + 1u) * RH / gy;
            const uint32_t sx = (x1 - x0 - win) / step * step + win;
            const uint32_t sy = (y1 - y0 - win) / step * step + win;
            sum += sy * row_cost(l, x0, sx, fmt);
        }
    }
    return sum;
}

/* The moving image's bound: the clipped search area of every point that
   was searched (neither FLAT nor OUTSIDE), once. */
static uint64_t mov_areas(const layout_t *l, const ssda_register_config_t *c,
                          const ssda_register_point_t *pts, size_t n, uint8_t fmt)
{
    const int32_t win = c->window ? c->window : 20, search = c->search ? c->search : 40;
    const int32_t half = (search - win) / 2;
    uint64_t sum = 0;
    size_t k;
    for (k = 0; k < n; k++) {
        int32_t wx = (pts[k].pair.ref_x_q8 / 128 - (win - 1)) / 2;
        int32_t wy = (pts[k].pair.ref_y_q8 / 128 - (win - 1)) / 2;
        int32_t x0 = wx + c->offset_x - half, y0 = wy + c->offset_y - half;
        int32_t x1 = x0 + search, y1 = y0 + search;
        if (pts[k].status == SSDA_REGISTER_FLAT || pts[k].status == SSDA_REGISTER_OUTSIDE) {
            continue;
        }
        x0 = x0 < 0 ? 0 : x0;
        y0 = y0 < 0 ? 0 : y0;
        x1 = x1 > (int32_t)RW ? (int32_t)RW : x1;
        y1 = y1 > (int32_t)RH ? (int32_t)RH : y1;
        sum += (uint64_t)(y1 - y0) * row_cost(l, (uint32_t)x0, (uint32_t)(x1 - x0), fmt);
    }
    return sum;
}

/* The bound (register.h, issue 17 item 1) over two layouts, both formats
   and two configurations, for arenas from the least each source accepts
   (SSDA_REGISTER_REF_SIZE, _MOV_SIZE) up to its whole image: the points
   equal the in-RAM run's; the reference's bytes read are each cell's
   windows' rectangle once (raster: exactly, the same at every arena;
   tiled: at most, with whole tile rows), the moving image's at most the
   searched areas once, plus 2 (read_size - 1) per read; raster reads never
   rise with the arena. One byte below either least: refused, nothing
   read, the points untouched. (Before the plan, the reference read each
   row once per window revisiting it: 67x its bytes here at the least
   arena, 8-bit raster.) */
static void test_reads_are_bounded_for_every_accepted_arena(void)
{
#ifndef SSDA_TEST_SMALL
    const uint32_t steps = 9u;
    const uint8_t fmt0 = 1u;
#else
    const uint32_t steps = 2u; /* emulated boards: 16-bit, 3 arenas */
    const uint8_t fmt0 = 2u;
#endif
    test_rng_t r;
    const map_t m = {4.5, -3.25, 0.01};
    const layout_t *layouts[2] = {&k_raster, &k_tiled};
    ssda_register_config_t cfgs[2];
    double worst_r = 0.0, worst_m = 0.0;
    uint32_t li, ci, t;
    uint8_t fmt;
    test_rng_seed(&r, 17);
    make_pair(&r, &m, 0);
    memset(cfgs, 0, sizeof cfgs);
    cfgs[0].offset_x = 4;
    cfgs[0].offset_y = -3;
    cfgs[1].grid_x = 3;
    cfgs[1].grid_y = 5;
    cfgs[1].window = 16;
    cfgs[1].search = 48;
    cfgs[1].step = 3;
    cfgs[1].metric = SSDA_REGISTER_SAD;
    cfgs[1].offset_x = -20; /* some areas clipped at the left */
    for (li = 0; li < 2; li++) {
        const layout_t *l = layouts[li];
        const uint64_t slack = 2u * (l->read_size - 1u);
        for (fmt = fmt0; fmt <= 2; fmt++) {
            for (ci = 0; ci < 2; ci++) {
                const ssda_register_config_t *c = &cfgs[ci];
                const size_t n = (size_t)(c->grid_x ? c->grid_x : 4u) * (c->grid_y ? c->grid_y : 4u);
                const size_t min_r = SSDA_REGISTER_REF_SIZE(l->layout, RW, c->grid_x, c->window, fmt, l->read_size, l->tile_w);
                const size_t min_m = SSDA_REGISTER_MOV_SIZE(l->layout, RW, c->search, fmt, l->read_size, l->tile_w);
                const size_t all_r = SSDA_SOURCE_SIZE(l->layout, RW, RH, fmt, l->read_size, l->tile_w);
                const uint64_t once_r = ref_once(l, c, fmt);
                uint64_t areas, prev_r = UINT64_MAX, prev_m = UINT64_MAX;
                ssda_source_t ref, mov;
                ram_sources(&ref, &mov, fmt);
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, c, g_pts, n, NULL, g_work, sizeof g_work));
                areas = mov_areas(l, c, g_pts, n, fmt);
                /* one byte below either least: nothing read, nothing written */
                memset(g_pts2, 0x5A, sizeof g_pts2);
                stream_sources_in(&ref, &mov, fmt, l, min_r - 1u, all_r);
                TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_register_points(&ref, &mov, c, g_pts2, n, NULL, g_work, sizeof g_work));
                stream_sources_in(&ref, &mov, fmt, l, all_r, min_m - 1u);
                TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_register_points(&ref, &mov, c, g_pts2, n, NULL, g_work, sizeof g_work));
                TEST_ASSERT_EQUAL_UINT64(0, g_tr.reads + g_tm.reads);
                TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, g_pts2, sizeof g_pts2);
                for (t = 0; t <= steps; t++) {
                    /* from the least to the whole image, both at once */
                    const size_t ar = min_r + (all_r - min_r) * t / steps;
                    const size_t am = min_m + (all_r - min_m) * t / steps;
                    uint64_t br, bm;
                    char msg[120];
                    stream_sources_in(&ref, &mov, fmt, l, ar, am);
                    memset(g_pts2, 0xEE, sizeof g_pts2);
                    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, c, g_pts2, n, NULL, g_work, sizeof g_work));
                    TEST_ASSERT_EQUAL_MEMORY(g_pts, g_pts2, n * sizeof g_pts[0]);
                    br = ref.stats.bytes_read;
                    bm = mov.stats.bytes_read;
                    TEST_ASSERT_EQUAL_UINT64(g_tr.bytes_read, br);
                    TEST_ASSERT_EQUAL_UINT64(g_tm.bytes_read, bm);
                    snprintf(msg, sizeof msg, "layout %u format %u config %u arenas %u, %u: read %llu, %llu",
                             (unsigned)li, (unsigned)fmt, (unsigned)ci, (unsigned)ar, (unsigned)am,
                             (unsigned long long)br, (unsigned long long)bm);
                    if (l->layout == SSDA_LAYOUT_RASTER) {
                        TEST_ASSERT_EQUAL_UINT64_MESSAGE(once_r, br, msg);
                        TEST_ASSERT_TRUE_MESSAGE(bm <= prev_m && br <= prev_r, msg);
                    } else {
                        TEST_ASSERT_TRUE_MESSAGE(br <= once_r + slack * ref.stats.reads, msg);
                    }
                    TEST_ASSERT_TRUE_MESSAGE(bm <= areas + slack * mov.stats.reads, msg);
                    prev_r = br;
                    prev_m = bm;
                    worst_r = (double)br / (RW * RH * fmt) > worst_r ? (double)br / (RW * RH * fmt) : worst_r;
                    worst_m = (double)bm / (RW * RH * fmt) > worst_m ? (double)bm / (RW * RH * fmt) : worst_m;
                }
            }
        }
    }
    printf("worst bytes read / image bytes: REF %.3f, MOV %.3f\n", worst_r, worst_m);
}

static void test_errors(void)
{
    ssda_source_t ref, mov, zero;
    ssda_register_config_t cfg;
    ram_sources(&ref, &mov, SSDA_PIX_U8);
    memset(&cfg, 0, sizeof cfg);
    cfg.metric = SSDA_REGISTER_SAD;
    memset(g_pts, 0x5A, sizeof g_pts);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_register_points(NULL, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_register_points(&ref, NULL, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_register_points(&ref, &mov, &cfg, NULL, 16, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, NULL, sizeof g_work));
    memset(&zero, 0, sizeof zero);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_register_points(&zero, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_register_points(&ref, &zero, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    {
        ssda_source_t m16, r16;
        ram_sources(&r16, &m16, SSDA_PIX_U16);
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_register_points(&ref, &m16, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_register_points(&ref, &mov, &cfg, g_pts, 15, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, SSDA_REGISTER_WORK_SIZE(20, 40, 1) - 1));
    {
        /* the size macro takes the config's fields as they are: 0 = the
           defaults (before, 0 divided by zero in SSDA_NCC_WORK_SIZE) */
        volatile uint16_t w0 = cfg.window, s0 = cfg.search;
        const size_t need = SSDA_REGISTER_WORK_SIZE(w0, s0, 1);
        TEST_ASSERT_EQUAL_UINT16(0, w0);
        TEST_ASSERT_EQUAL_UINT64(SSDA_REGISTER_WORK_SIZE(20, 40, 1), need);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_register_points(&ref, &mov, &cfg, g_pts2, 16, NULL, g_work, need));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, need - 1));
        memset(g_pts, 0x5A, sizeof g_pts);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, (uint8_t *)g_work + 4, sizeof g_work - 8));
    cfg.grid_x = 13; /* 240 / 13 = 18 < 20 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_register_points(&ref, &mov, &cfg, g_pts, 64, NULL, g_work, sizeof g_work));
    cfg.grid_x = 0;
    cfg.grid_y = 257;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_register_points(&ref, &mov, &cfg, g_pts, 64, NULL, g_work, sizeof g_work));
    cfg.grid_y = 0;
    cfg.window = 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    cfg.window = 30;
    cfg.search = 29;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    cfg.window = 0;
    cfg.search = 0;
    cfg.metric = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    cfg.metric = SSDA_REGISTER_SAD;
    cfg.min_rho_q30 = -1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    cfg.min_rho_q30 = 0;
    cfg.offset_y = 70000;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    cfg.offset_y = 0;
    /* one streamed source given twice */
    stream_sources(&ref, &mov, SSDA_PIX_U8, 4000, 4000);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_register_points(&ref, &ref, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    /* arenas below the least: a row of the window, of the area */
    stream_sources(&ref, &mov, SSDA_PIX_U8, 8, 4000);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    stream_sources(&ref, &mov, SSDA_PIX_U8, 4000, 36);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_register_points(&ref, &mov, &cfg, g_pts, 16, NULL, g_work, sizeof g_work));
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, g_pts, sizeof g_pts);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_points_on_known_map);
    RUN_TEST(test_correlation_metrics);
    RUN_TEST(test_low_rho);
    RUN_TEST(test_window_and_placement_brute_force);
    RUN_TEST(test_thresholds_at_equality);
    RUN_TEST(test_statuses);
    RUN_TEST(test_streamed_equals_ram);
    RUN_TEST(test_reads_are_bounded_for_every_accepted_arena);
    RUN_TEST(test_errors);
    return UNITY_END();
}
