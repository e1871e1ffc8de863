/*
 * test_composite.c - composite template matching (ssda/composite.h) against
 * an independent reference: the origin chosen by a double-precision standard
 * deviation, each template's match an exhaustive exact search
 * (tests/support/test_ncc_ref.c) over the whole image (origin) or over the
 * disk the header defines, computed here in floating point. Known motions
 * with a brightness change, sub-pixel shifts, flat and edge templates, and
 * argument errors leaving the outputs untouched.
 */
#include <string.h>
#include "unity.h"
#include "ssda/composite.h"
#include "ssda/relax.h"
#include "test_image.h"
#include "test_ncc_ref.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define W 96u
#define H 80u
static uint8_t g_ref[H][W], g_next[H][W];
static uint64_t g_work[SSDA_COMPOSITE_WORK_SIZE(W, 20) / 8u + 1u];
static ssda_composite_tp_t g_tp[400];

static ssda_composite_config_t config(uint16_t rx, uint16_t ry, uint16_t rw, uint16_t rh)
{
    ssda_composite_config_t c;
    memset(&c, 0, sizeof c);
    c.roi_x = rx;
    c.roi_y = ry;
    c.roi_w = rw;
    c.roi_h = rh;
    c.work = g_work;
    c.work_size = sizeof g_work;
    return c;
}

/* NEXT: REF moved by (sx, sy) left of column split and by (tx, ty) right of
   it (a shear the disks must follow), times 3/4 plus 30. */
static void make_pair(uint32_t seed, int32_t sx, int32_t sy, int32_t tx, int32_t ty, uint32_t split)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u8(&g_ref[0][0], W, H, W, &r);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            int32_t mx = x < split ? sx : tx, my = x < split ? sy : ty;
            int32_t u = (int32_t)x - mx, v = (int32_t)y - my;
            uint32_t p = (u >= 0 && v >= 0 && u < (int32_t)W && v < (int32_t)H) ? g_ref[v][u] : 128u;
            g_next[y][x] = (uint8_t)(p * 3u / 4u + 30u);
        }
    }
}

/* The whole pipeline against the reference. */
static void check_against_reference(const ssda_composite_config_t *cfg)
{
    ssda_view_t ref, next;
    ssda_composite_result_t res;
    const uint32_t T = cfg->tp ? cfg->tp : 20u, S = cfg->step ? cfg->step : 5u;
    const double f = (cfg->radius_q8 ? cfg->radius_q8 : 64u) / 256.0;
    const double rmin = cfg->min_radius ? cfg->min_radius : 3u;
    const uint32_t cols = (cfg->roi_w - T) / S + 1u, rows = (cfg->roi_h - T) / S + 1u;
    uint32_t k, origin = 0, ox = 0, oy = 0, ok = 0;
    double best_sd = -1.0, rho_sum = 0.0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_UINT16(cols, res.cols);
    TEST_ASSERT_EQUAL_UINT16(rows, res.rows);
    TEST_ASSERT_EQUAL_UINT32(cols * rows, res.count);
    /* the origin: largest standard deviation, first in raster order */
    for (k = 0; k < cols * rows; k++) {
        uint32_t x = cfg->roi_x + (k % cols) * S, y = cfg->roi_y + (k / cols) * S, i, j;
        double m = 0.0, v = 0.0;
        for (j = 0; j < T; j++) {
            for (i = 0; i < T; i++) {
                m += g_ref[y + j][x + i];
            }
        }
        m /= (double)(T * T);
        for (j = 0; j < T; j++) {
            for (i = 0; i < T; i++) {
                v += (g_ref[y + j][x + i] - m) * (g_ref[y + j][x + i] - m);
            }
        }
        TEST_ASSERT_EQUAL_UINT16(x, g_tp[k].x);
        TEST_ASSERT_EQUAL_UINT16(y, g_tp[k].y);
        if (test_sqrt(v / (T * T)) * 256.0 < cfg->min_std_q8 || v == 0.0) {
            TEST_ASSERT_EQUAL_UINT8(SSDA_COMPOSITE_FLAT, g_tp[k].status);
        } else if (v > best_sd + 1e-9) {
            best_sd = v;
            origin = k;
        }
    }
    TEST_ASSERT_EQUAL_UINT32(origin, res.origin);
    TEST_ASSERT_EQUAL_UINT8(1, g_tp[origin].origin);
    for (k = 0; k < cols * rows; k++) {
        ssda_view_t tv;
        if (k == origin) { /* the origin's match first: the others depend on it */
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&tv, &ref, g_tp[k].x, g_tp[k].y,
                                                         (uint16_t)T, (uint16_t)T));
            test_ncc_best(&next, &tv, cfg->metric == SSDA_NCC_ABS, 0, 0, -1, &ox, &oy);
        }
    }
    for (k = 0; k < cols * rows; k++) {
        const uint32_t x = g_tp[k].x, y = g_tp[k].y;
        ssda_view_t tv;
        uint32_t bx = 0, by = 0;
        if (g_tp[k].status == SSDA_COMPOSITE_FLAT) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&tv, &ref, (uint16_t)x, (uint16_t)y,
                                                     (uint16_t)T, (uint16_t)T));
        if (k == origin) {
            bx = ox;
            by = oy;
        } else {
            int64_t vx = (int64_t)x - g_tp[origin].x, vy = (int64_t)y - g_tp[origin].y;
            int64_t px = (int64_t)ox + vx, py = (int64_t)oy + vy;
            double len = test_sqrt((double)(vx * vx + vy * vy));
            int64_t rad = (int64_t)(f * len + 0.999999);
            if (rad < rmin) {
                rad = (int64_t)rmin;
            }
            if (px < 0 || py < 0 || px > (int64_t)(W - T) || py > (int64_t)(H - T)) {
                TEST_ASSERT_EQUAL_UINT8(SSDA_COMPOSITE_EDGE, g_tp[k].status);
                continue;
            }
            test_ncc_best(&next, &tv, cfg->metric == SSDA_NCC_ABS, px, py, rad * rad, &bx, &by);
        }
        TEST_ASSERT_EQUAL_UINT8(SSDA_COMPOSITE_OK, g_tp[k].status);
        if ((cfg->flags & SSDA_COMPOSITE_SUBPIXEL) == 0u) {
            TEST_ASSERT_EQUAL_INT32(((int32_t)bx - (int32_t)x) * 256, g_tp[k].dx);
            TEST_ASSERT_EQUAL_INT32(((int32_t)by - (int32_t)y) * 256, g_tp[k].dy);
        } else {
            TEST_ASSERT_INT32_WITHIN(128, ((int32_t)bx - (int32_t)x) * 256, g_tp[k].dx);
            TEST_ASSERT_INT32_WITHIN(128, ((int32_t)by - (int32_t)y) * 256, g_tp[k].dy);
        }
        TEST_ASSERT_INT32_WITHIN(1, (int32_t)test_ncc_q30(&next, &tv, bx, by), g_tp[k].rho_q30);
        rho_sum += g_tp[k].rho_q30;
        ok++;
    }
    TEST_ASSERT_EQUAL_UINT32(ok, res.ok);
    TEST_ASSERT_INT32_WITHIN(1, (int32_t)(rho_sum / ok), res.mean_rho_q30);
    TEST_ASSERT_TRUE(res.pixel_ops > 0u);
}

static void test_uniform_motion_with_gain_and_offset(void)
{
    ssda_composite_config_t cfg = config(20, 16, 56, 48);
    uint32_t k;
    make_pair(1u, 4, -3, 4, -3, W);
    check_against_reference(&cfg);
    /* a region to the image's edges by default (0 = the rest) */
    cfg = config(W - 56u, H - 48u, 0, 0);
    cfg.roi_w = 0;
    cfg.roi_h = 0;
    {
        ssda_composite_config_t full = cfg;
        full.roi_w = 56;
        full.roi_h = 48;
        check_against_reference(&full);
        memcpy(g_tp + 200, g_tp, 48u * sizeof g_tp[0]);
        cfg.roi_w = 0;
        cfg.roi_h = 0;
    }
    {
        ssda_view_t ref, next;
        ssda_composite_result_t res;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 200, &res));
        TEST_ASSERT_EQUAL_UINT16(8, res.cols);
        TEST_ASSERT_EQUAL_UINT16(6, res.rows);
        TEST_ASSERT_EQUAL_MEMORY(g_tp + 200, g_tp, 48u * sizeof g_tp[0]);
    }
    make_pair(1u, 4, -3, 4, -3, W);
    cfg = config(20, 16, 56, 48);
    check_against_reference(&cfg);
    for (k = 0; k < 8u * 6u; k++) {
        TEST_ASSERT_EQUAL_INT32(4 * 256, g_tp[k].dx);
        TEST_ASSERT_EQUAL_INT32(-3 * 256, g_tp[k].dy);
    }
}

/* Two halves moving differently: the disks must follow (and may not). */
static void test_sheared_field_and_radius_rule(void)
{
    ssda_composite_config_t cfg = config(10, 10, 76, 60);
    make_pair(2u, 2, 1, 6, 3, 48);
    check_against_reference(&cfg);
    cfg.radius_q8 = 16;  /* 1/16: too tight for the far half */
    cfg.min_radius = 1;
    check_against_reference(&cfg);
    cfg.flags = SSDA_COMPOSITE_SUBPIXEL; /* neighbours outside the disk may beat the best */
    check_against_reference(&cfg);
    cfg.flags = 0;
#ifndef SSDA_TEST_SMALL
    cfg.radius_q8 = 200;
    cfg.tp = 16;
    cfg.step = 7;
    cfg.metric = SSDA_NCC_ABS;
    check_against_reference(&cfg);
#endif
}

/* Flat templates are FLAT (and a min_std makes more of them); templates
   whose predicted place leaves NEXT are EDGE. */
static void test_flat_and_edge_templates(void)
{
    ssda_composite_config_t cfg = config(0, 0, 50, 50);
    uint32_t x, y;
    make_pair(3u, -9, -7, -9, -7, W);
    for (y = 0; y < 30u; y++) {
        for (x = 25; x < 50u; x++) {
            g_ref[y][x] = 77u;
        }
    }
    check_against_reference(&cfg);
    cfg.min_std_q8 = 25u * 256u;
    check_against_reference(&cfg);
    /* matches on the edge of NEXT (no neighbour there), inverted: |rho| */
    cfg.min_std_q8 = 0;
    cfg.flags = SSDA_COMPOSITE_SUBPIXEL;
    cfg.metric = SSDA_NCC_ABS;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            g_next[y][x] = (uint8_t)(255u - g_next[y][x]);
        }
    }
    check_against_reference(&cfg);
}

/* SSDA_COMPOSITE_MASK: fill (250) in the left 20 columns of both images.
   Templates over it are MASKED, the others keep the true motion; without
   the mask some template over the fill's edge is matched. An origin whose
   match holds fill is MASKED and the next in rank takes its place. */
static void test_mask_fill(void)
{
    ssda_composite_config_t cfg = config(0, 0, W, H);
    ssda_view_t ref, next;
    ssda_composite_result_t res;
    uint32_t x, y, k, edge_ok = 0, k0;
    make_pair(5u, 3, -2, 3, -2, W);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            if (x < 20u) {
                g_ref[y][x] = 250u;
                g_next[y][x] = 250u;
            } else if (g_ref[y][x] == 250u) {
                g_ref[y][x] = 249u;
            }
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    for (k = 0; k < res.count; k++) {
        edge_ok += g_tp[k].x < 20u && g_tp[k].status == SSDA_COMPOSITE_OK;
    }
    TEST_ASSERT_TRUE(edge_ok > 0u); /* the defect the mask removes */
    cfg.flags = SSDA_COMPOSITE_MASK;
    cfg.mask_value = 250u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_TRUE(res.origin < res.count && g_tp[res.origin].x >= 20u);
    TEST_ASSERT_TRUE(res.ok > 20u);
    for (k = 0; k < res.count; k++) {
        if (g_tp[k].x < 20u) {
            TEST_ASSERT_EQUAL_UINT8(SSDA_COMPOSITE_MASKED, g_tp[k].status);
        }
        if (g_tp[k].status == SSDA_COMPOSITE_OK) {
            TEST_ASSERT_EQUAL_INT32(3 * 256, g_tp[k].dx);
            TEST_ASSERT_EQUAL_INT32(-2 * 256, g_tp[k].dy);
        } else {
            TEST_ASSERT_EQUAL_INT32(0, g_tp[k].dx);
            TEST_ASSERT_EQUAL_INT32(0, g_tp[k].rho_q30);
        }
    }
    /* one fill pixel in the origin's match: it still matches there (rho
       near 1), so it is MASKED and the next in rank is the origin */
    k0 = res.origin;
    g_next[g_tp[k0].y - 2u + 5u][g_tp[k0].x + 3u + 5u] = 250u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_UINT8(SSDA_COMPOSITE_MASKED, g_tp[k0].status);
    TEST_ASSERT_EQUAL_UINT8(0, g_tp[k0].origin);
    TEST_ASSERT_TRUE(res.origin != k0 && res.origin < res.count);
    TEST_ASSERT_EQUAL_UINT8(SSDA_COMPOSITE_OK, g_tp[res.origin].status);
    TEST_ASSERT_EQUAL_UINT8(1, g_tp[res.origin].origin);
    TEST_ASSERT_TRUE(g_tp[res.origin].var <= g_tp[k0].var);
    /* a mask value beyond 8-bit samples */
    cfg.mask_value = 256u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
}

/* Sub-pixel: a shift of (2.5, -1.25) px by linear interpolation. */
static void test_subpixel_vectors(void)
{
    ssda_composite_config_t cfg = config(30, 25, 40, 30);
    ssda_view_t ref, next;
    ssda_composite_result_t res;
    test_rng_t r;
    uint32_t x, y, k;
    test_rng_seed(&r, 4u);
    test_fill_texture_u8(&g_ref[0][0], W, H, W, &r);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            /* NEXT(x, y) = REF(x - 2.5, y + 1.25), bilinear */
            double u = x - 2.5, v = y + 1.25;
            int32_t i = (int32_t)u, j = (int32_t)v;
            double a = u - i, b = v - j, p;
            if (i < 0 || j < 0 || i + 1 >= (int32_t)W || j + 1 >= (int32_t)H) {
                g_next[y][x] = 100u;
                continue;
            }
            p = (1 - a) * (1 - b) * g_ref[j][i] + a * (1 - b) * g_ref[j][i + 1] +
                (1 - a) * b * g_ref[j + 1][i] + a * b * g_ref[j + 1][i + 1];
            g_next[y][x] = (uint8_t)(p + 0.5);
        }
    }
    cfg.flags = SSDA_COMPOSITE_SUBPIXEL;
    check_against_reference(&cfg);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    for (k = 0; k < res.count; k++) {
        TEST_ASSERT_INT32_WITHIN(52, 640, g_tp[k].dx);  /* 2.5 px within 0.2 */
        TEST_ASSERT_INT32_WITHIN(52, -320, g_tp[k].dy); /* -1.25 px */
    }
}

/* The template array is a relax.h grid as it is (Q8 vectors, status). */
static void test_templates_feed_relaxation(void)
{
    static uint32_t work[SSDA_RELAX_WORK_SIZE(8, 6) / 4u + 1u];
    static ssda_relax_vector_t out[48];
    ssda_composite_config_t cfg = config(20, 16, 56, 48);
    ssda_relax_config_t rc;
    ssda_relax_grid_t g;
    ssda_view_t ref, next;
    ssda_composite_result_t res;
    uint32_t k;
    make_pair(5u, 3, 2, 3, 2, W);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    g_tp[10].dx = -5 * 256; /* an outlier */
    memset(&g, 0, sizeof g);
    g.dx = &g_tp[0].dx;
    g.dy = &g_tp[0].dy;
    g.status = &g_tp[0].status;
    g.stride = sizeof g_tp[0];
    g.cols = res.cols;
    g.rows = res.rows;
    g.frac_bits = 8;
    memset(&rc, 0, sizeof rc);
    rc.flags = SSDA_RELAX_KEEP;
    rc.work = work;
    rc.work_size = sizeof work;
    rc.iterations = 40;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &rc, out, 48));
    for (k = 0; k < 48u; k++) {
        TEST_ASSERT_INT32_WITHIN(k == 10u ? 26 : 0, 3 * 256, out[k].dx_q8);
        TEST_ASSERT_INT32_WITHIN(k == 10u ? 26 : 0, 2 * 256, out[k].dy_q8);
    }
}

/* Inverted contrast with |rho| (SSDA_NCC_ABS): NEXT = 255 - REF moved by
   (3, 2), every template's match has rho near -1, and the set's score is
   the mean of those negative rho (truncated toward zero, as the positive
   one). Before, no test had a negative mean (the inverted case of
   test_flat_and_edge_templates loses its origin off NEXT: mean +0.14). */
static void test_inverted_contrast_mean_is_negative(void)
{
    ssda_composite_config_t cfg = config(10, 10, 60, 50);
    ssda_composite_result_t res;
    ssda_view_t ref, next;
    int64_t sum = 0;
    uint32_t x, y, k;
    make_pair(5u, 3, 2, 3, 2, W);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            g_next[y][x] = (uint8_t)(255u - g_next[y][x]);
        }
    }
    cfg.metric = SSDA_NCC_ABS;
    check_against_reference(&cfg);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_UINT32(res.count, res.ok);
    for (k = 0; k < res.count; k++) {
        TEST_ASSERT_EQUAL_INT32(3 * 256, g_tp[k].dx);
        TEST_ASSERT_EQUAL_INT32(2 * 256, g_tp[k].dy);
        TEST_ASSERT_TRUE(g_tp[k].rho_q30 < -SSDA_NCC_ONE_Q30 / 10 * 9);
        sum += g_tp[k].rho_q30;
    }
    TEST_ASSERT_EQUAL_INT32((int32_t)(sum / (int64_t)res.ok), res.mean_rho_q30);
}

/* Ties of variance: the origin is the smallest k among the largest. A
   REF periodic with the template step makes every template the same. */
static void test_origin_tie_smallest_index(void)
{
    ssda_composite_config_t cfg = config(0, 0, 60, 50);
    ssda_composite_result_t res;
    ssda_view_t ref, next;
    uint32_t x, y, k;
    make_pair(6u, 0, 0, 0, 0, W);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            g_ref[y][x] = g_ref[y % 5u][x % 5u];
            g_next[y][x] = g_ref[y][x];
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_TRUE(res.count > 1u);
    TEST_ASSERT_TRUE(g_tp[0].var > 0u);
    for (k = 1; k < res.count; k++) {
        TEST_ASSERT_EQUAL_UINT64(g_tp[0].var, g_tp[k].var);
        TEST_ASSERT_EQUAL_UINT8(0, g_tp[k].origin);
    }
    TEST_ASSERT_EQUAL_UINT32(0, res.origin);
    TEST_ASSERT_EQUAL_UINT8(1, g_tp[0].origin);
}

/* min_std at its edge, exactly: a template is FLAT iff its standard
   deviation sqrt(var) / n is below min_std_q8 / 256, i.e. iff
   256^2 var < (min_std_q8 n)^2 (all in 64 bits for a 4 x 4 template),
   for every min_std_q8 around the template's own (every one on the host). */
static void test_min_std_edge(void)
{
    /* var = 1 578 007: at min_std_q8 = 20 099, 256^2 var < (16 m)^2 <
       256^2 (var + 1), the case a floor instead of a ceiling gets wrong */
    static const uint8_t tpl[16] = {74, 80, 54, 14, 51, 38, 87, 251, 239, 220, 31, 6, 165, 73, 121, 181};
    ssda_composite_config_t cfg = config(0, 0, 4, 4);
    ssda_composite_result_t res;
    ssda_view_t ref, next;
    uint64_t var;
    uint32_t m, lo, hi, i, s1 = 0, s2 = 0;
    for (i = 0; i < 16u; i++) {
        g_ref[i / 4u][i % 4u] = tpl[i];
        g_next[i / 4u][i % 4u] = tpl[i];
        s1 += tpl[i];
        s2 += (uint32_t)tpl[i] * tpl[i];
    }
    var = 16u * (uint64_t)s2 - (uint64_t)s1 * s1;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, 4, 4, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, 4, 4, W, SSDA_PIX_U8));
    cfg.tp = 4;
    cfg.step = 1;
#ifndef SSDA_TEST_SMALL
    lo = 1;
    hi = 65535;
#else
    lo = 18000; /* the edge is at 20 099 */
    hi = 22000;
#endif
    for (m = lo; m <= hi; m++) {
        const uint64_t s = (uint64_t)m * 16u;
        const bool flat = 65536u * var < s * s;
        cfg.min_std_q8 = (uint16_t)m;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 1, &res));
        TEST_ASSERT_EQUAL_UINT8(flat ? SSDA_COMPOSITE_FLAT : SSDA_COMPOSITE_OK, g_tp[0].status);
        TEST_ASSERT_EQUAL_UINT32(flat ? 0u : 1u, res.ok);
    }
}

static void test_errors_leave_outputs_untouched(void)
{
    ssda_composite_config_t cfg = config(20, 16, 56, 48);
    ssda_composite_result_t res, rpoison;
    ssda_view_t ref, next, n16;
    static uint16_t g16[H][W];
    static ssda_composite_tp_t poison[400];
    memset(poison, 0x3C, sizeof poison);
    memset(&rpoison, 0x3C, sizeof rpoison);
    memcpy(g_tp, poison, sizeof poison);
    res = rpoison;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&ref, g_ref, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&next, g_next, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&n16, g16, W, H, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_composite_match(NULL, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_composite_match(&ref, NULL, &cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_composite_match(&ref, &next, NULL, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_composite_match(&ref, &next, &cfg, NULL, 400, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_composite_match(&ref, &n16, &cfg, g_tp, 400, &res));
    next.stride = 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_composite_match(&next, &ref, &cfg, g_tp, 400, &res));
    next.stride = W;
    cfg.tp = 257;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.tp = 0;
    cfg.metric = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.metric = 0;
    cfg.flags = 4; /* 1 and 2 are SUBPIXEL and MASK */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.flags = 0;
    cfg.roi_x = W;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.roi_x = 20;
    cfg.roi_y = H;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.roi_y = 16;
    cfg.roi_w = 19;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.roi_w = W;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.roi_w = 56;
    cfg.roi_h = H;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.roi_h = 48;
    next.width = 19;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    next.width = W;
    next.height = 19;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    next.height = H;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_composite_match(&ref, &next, &cfg, g_tp, 47, &res));
    cfg.work_size = SSDA_COMPOSITE_WORK_SIZE(W, 20) - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.work_size = sizeof g_work;
    cfg.work = (uint8_t *)(void *)g_work + 4;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    cfg.work = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_MEMORY(poison, g_tp, sizeof poison);
    TEST_ASSERT_EQUAL_MEMORY(&rpoison, &res, sizeof res);
    /* all flat: every template FLAT, nothing matched */
    memset(g_ref, 40, sizeof g_ref);
    cfg.work = g_work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_composite_match(&ref, &next, &cfg, g_tp, 400, &res));
    TEST_ASSERT_EQUAL_UINT32(0, res.ok);
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, res.origin);
    TEST_ASSERT_EQUAL_UINT8(SSDA_COMPOSITE_FLAT, g_tp[0].status);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_uniform_motion_with_gain_and_offset);
    RUN_TEST(test_sheared_field_and_radius_rule);
    RUN_TEST(test_flat_and_edge_templates);
    RUN_TEST(test_mask_fill);
    RUN_TEST(test_subpixel_vectors);
    RUN_TEST(test_templates_feed_relaxation);
    RUN_TEST(test_inverted_contrast_mean_is_negative);
    RUN_TEST(test_origin_tie_smallest_index);
    RUN_TEST(test_min_std_edge);
    RUN_TEST(test_errors_leave_outputs_untouched);
    return UNITY_END();
}
