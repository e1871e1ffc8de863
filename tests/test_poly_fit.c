/*
 * test_poly_fit.c - ssda_poly_fit against a double-precision Householder
 * QR fit computed here (tests/support/test_lsq.c), on known maps with and
 * without noise, at every order, on well- and badly-conditioned point
 * sets; the outlier rejection on the seed's Fig. 9 table (pair 7 misread,
 * about 20 px off); the worst-case sums; and every error.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "unity.h"
#include "ssda/poly.h"
#include "test_lsq.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define MAXP 1024u

static ssda_poly_pair_t g_pairs[MAXP];
static uint8_t g_work[16384];
static uint32_t g_res[MAXP];
static uint8_t g_used[MAXP];

static int32_t q8(double v)
{
    return (int32_t)(v >= 0 ? v * 256.0 + 0.5 : v * 256.0 - 0.5);
}

/* Largest distance between the fixed-point map and the double one over a
   grid of check points of the reference grid, px. */
static double map_gap(const ssda_poly_t *p, const double *cu, const double *cv)
{
    ssda_poly_t ref = *p;
    double worst = 0.0;
    int i, j;
    for (i = 0; i <= 8; i++) {
        for (j = 0; j <= 8; j++) {
            const double X = (p->ref_w - 1) * i / 8.0, Y = (p->ref_h - 1) * j / 8.0;
            double phi[10], xu = 0, xv = 0, fu, fv, d;
            unsigned t;
            test_poly_terms(&ref, X, Y, phi);
            for (t = 0; t < SSDA_POLY_TERMS(p->order); t++) {
                xu += cu[t] * phi[t];
                xv += cv[t] * phi[t];
            }
            test_poly_map(p, X, Y, &fu, &fv);
            d = (fu - xu) * (fu - xu) + (fv - xv) * (fv - xv);
            worst = d > worst ? d : worst;
        }
    }
    return test_sqrt(worst);
}

/* A smooth random map of the given order on a w x h grid: identity plus a
   shift, a small rotation/scale and curvature of a few px at the edges. */
static void random_map(test_rng_t *r, uint16_t w, uint16_t h, uint8_t order, ssda_poly_t *p)
{
    unsigned t;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(p, w, h, order));
    for (t = 0; t < SSDA_POLY_TERMS(order); t++) {
        const double amp = t == 0 ? 40.0 : (t < 3 ? 0.02 * (1 << (t == 1 ? p->kx : p->ky)) : 3.0);
        const double v = ((double)test_rng_next(r) / 4294967296.0 - 0.5) * 2.0 * amp;
        const double v2 = ((double)test_rng_next(r) / 4294967296.0 - 0.5) * 2.0 * amp;
        p->u_q24[t] += (int64_t)(v * 16777216.0);
        p->v_q24[t] += (int64_t)(v2 * 16777216.0);
    }
}

/* n pairs on a jittered grid of the reference (or a small corner region
   when `corner`), moved by map p, plus uniform noise of +-noise px. */
static void make_pairs(test_rng_t *r, const ssda_poly_t *p, size_t n, double noise, int corner)
{
    size_t k;
    for (k = 0; k < n; k++) {
        const double span_x = corner ? p->ref_w / 6.0 : p->ref_w - 1.0;
        const double span_y = corner ? p->ref_h / 6.0 : p->ref_h - 1.0;
        const double X = span_x * (double)test_rng_next(r) / 4294967296.0;
        const double Y = span_y * (double)test_rng_next(r) / 4294967296.0;
        double x, y;
        test_poly_map(p, X, Y, &x, &y);
        x += noise * ((double)test_rng_next(r) / 2147483648.0 - 1.0);
        y += noise * ((double)test_rng_next(r) / 2147483648.0 - 1.0);
        g_pairs[k].ref_x_q8 = q8(X);
        g_pairs[k].ref_y_q8 = q8(Y);
        g_pairs[k].mov_x_q8 = q8(x);
        g_pairs[k].mov_y_q8 = q8(y);
    }
}

/* The fixed-point fit equals the double QR fit of the same pairs to
   within `tol` px over the grid; returns the fit's summary. */
static ssda_poly_fit_result_t fit_and_compare(size_t n, uint16_t w, uint16_t h, uint8_t order,
                                               double tol)
{
    ssda_poly_fit_config_t cfg = {order, UINT32_MAX};
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    double cu[10], cv[10], gap;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_fit(g_pairs, n, w, h, &cfg, &p, g_res, g_used,
                                                 &res, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_INT(0, test_poly_fit_double(g_pairs, n, NULL, w, h, order, cu, cv));
    gap = map_gap(&p, cu, cv);
    if (getenv("SSDA_TEST_VERBOSE") != NULL) /* the figures of docs/registration.md */
        printf("GAP order %u n %u cond %u steps %u gap %.3g\n", order, (unsigned)n, (unsigned)res.cond, res.refinements, gap);
    if (gap > tol) {
        char msg[96];
        snprintf(msg, sizeof msg, "order %u n %u cond %u: gap %.3g px", order, (unsigned)n,
                 (unsigned)res.cond, gap);
        TEST_FAIL_MESSAGE(msg);
    }
    TEST_ASSERT_EQUAL_UINT16(n, res.used);
    TEST_ASSERT_EQUAL_UINT16(0, res.rejected);
    return res;
}

/* Noise-free pairs of a known map: the map is recovered (to the pairs'
   Q8 rounding) and equals the double fit within 2e-4 px. */
static void test_fit_matches_double_exact_maps(void)
{
    test_rng_t r;
    int trial;
    test_rng_seed(&r, 0x46495431u);
    for (trial = 0; trial < 60; trial++) {
        const uint8_t order = (uint8_t)(1 + trial % 3);
        const uint16_t w = (uint16_t)test_rng_range(&r, 64, trial % 5 == 0 ? 65535 : 4000);
        const uint16_t h = (uint16_t)test_rng_range(&r, 64, 4000);
        const size_t n = test_rng_range(&r, SSDA_POLY_TERMS(order) + 2u, 200);
        ssda_poly_t truth;
        ssda_poly_fit_result_t res;
        random_map(&r, w, h, order, &truth);
        make_pairs(&r, &truth, n, 0.0, 0);
        res = fit_and_compare(n, w, h, order, 2e-4);
        /* the pairs' own Q8 rounding is the only misfit */
        TEST_ASSERT_TRUE(res.rms_q8 <= 2u);
        TEST_ASSERT_TRUE(res.refinements >= 1u && res.refinements <= 4u);
    }
}

/* Noisy pairs (+-1.5 px), every order: the same solution as double QR. */
static void test_fit_matches_double_noisy(void)
{
    test_rng_t r;
    int trial;
    test_rng_seed(&r, 0x4E4F4953u);
    for (trial = 0; trial < 60; trial++) {
        const uint8_t order = (uint8_t)(1 + trial % 3);
        const size_t n = test_rng_range(&r, SSDA_POLY_TERMS(order) + 1u, trial % 4 == 0 ? 1000 : 100);
        ssda_poly_t truth;
        random_map(&r, 1000, 800, order, &truth);
        make_pairs(&r, &truth, n, 1.5, 0);
        (void)fit_and_compare(n, 1000, 800, order, 2e-4);
    }
}

/* Pairs crowded into one corner (a sixth of each side): the cubic's normal
   matrix has cond ~10^6 or more; the fit still equals the double one on
   the region the pairs cover (checked over the whole grid with a looser
   bound: extrapolating a cubic amplifies any difference). */
static void test_fit_ill_conditioned(void)
{
    test_rng_t r;
    int trial;
    uint32_t worst_cond = 0;
    test_rng_seed(&r, 0x434F4E44u);
    for (trial = 0; trial < 20; trial++) {
        const uint8_t order = (uint8_t)(2 + trial % 2);
        ssda_poly_t truth;
        ssda_poly_fit_result_t res;
        random_map(&r, 3000, 2000, order, &truth);
        make_pairs(&r, &truth, 60, 0.3, 1);
        res = fit_and_compare(60, 3000, 2000, order, 0.05);
        worst_cond = res.cond > worst_cond ? res.cond : worst_cond;
    }
    TEST_ASSERT_TRUE(worst_cond > 10000u);
}

/* The seed's Fig. 9: nine pairs by correlation on a 1000 x 800 image;
   pair 7, (705, 412) : (683, 410), is about 20 px off the others' map. */
static const int fig9[9][4] = {{517, 172, 475, 171}, {187, 320, 146, 318}, {296, 358, 255, 356},
                               {705, 412, 683, 410}, {397, 507, 356, 505}, {864, 581, 821, 579},
                               {398, 663, 357, 661}, {779, 744, 737, 741}, {912, 757, 870, 754}};

static void load_fig9(void)
{
    int k;
    for (k = 0; k < 9; k++) {
        g_pairs[k].ref_x_q8 = fig9[k][0] * 256;
        g_pairs[k].ref_y_q8 = fig9[k][1] * 256;
        g_pairs[k].mov_x_q8 = fig9[k][2] * 256;
        g_pairs[k].mov_y_q8 = fig9[k][3] * 256;
    }
}

static void test_fig9_outlier_rejected(void)
{
    uint8_t order;
    for (order = 1; order <= 2; order++) {
        ssda_poly_fit_config_t cfg = {order, 0}; /* default bound, 2 px */
        ssda_poly_fit_result_t res;
        ssda_poly_t p;
        double cu[10], cv[10];
        int k;
        load_fig9();
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res,
                                                     g_used, &res, g_work, sizeof g_work));
        TEST_ASSERT_EQUAL_UINT16(8, res.used);
        TEST_ASSERT_EQUAL_UINT16(1, res.rejected);
        TEST_ASSERT_TRUE(res.within_bound);
        for (k = 0; k < 9; k++) {
            TEST_ASSERT_EQUAL_UINT8(k == 3 ? 0 : 1, g_used[k]);
        }
        /* the rejected pair is ~20 px off; the others within 0.6 px */
        TEST_ASSERT_TRUE(g_res[3] > 19u * 256u && g_res[3] < 22u * 256u);
        TEST_ASSERT_TRUE(res.max_q8 <= 154u);
        /* and the map is the double fit of the eight */
        TEST_ASSERT_EQUAL_INT(0, test_poly_fit_double(g_pairs, 9, g_used, 1000, 800, order, cu, cv));
        TEST_ASSERT_TRUE(map_gap(&p, cu, cv) < 2e-4);
        /* residuals against the double map, each pair */
        for (k = 0; k < 9; k++) {
            double phi[10], x = 0, y = 0, d;
            unsigned t;
            test_poly_terms(&p, fig9[k][0], fig9[k][1], phi);
            for (t = 0; t < SSDA_POLY_TERMS(order); t++) {
                x += cu[t] * phi[t];
                y += cv[t] * phi[t];
            }
            d = test_sqrt((x - fig9[k][2]) * (x - fig9[k][2]) + (y - fig9[k][3]) * (y - fig9[k][3]));
            TEST_ASSERT_TRUE(g_res[k] / 256.0 > d - 0.01 && g_res[k] / 256.0 < d + 0.01);
        }
    }
}

/* Without rejection all nine are used (and pair 7 has the largest residual). */
static void test_fig9_no_rejection(void)
{
    ssda_poly_fit_config_t cfg = {2, UINT32_MAX};
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    int k;
    load_fig9();
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used,
                                                 &res, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT16(9, res.used);
    TEST_ASSERT_EQUAL_UINT16(0, res.rejected);
    TEST_ASSERT_TRUE(res.within_bound); /* no bound: everything is within it */
    for (k = 0; k < 9; k++) {
        TEST_ASSERT_TRUE(k == 3 || g_res[k] < g_res[3]);
    }
}

/* Rejection stops at terms + 1 pairs: a tight bound cannot drop more. */
static void test_rejection_stops_at_minimum(void)
{
    ssda_poly_fit_config_t cfg = {2, 1}; /* 1/256 px: nothing meets it */
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    load_fig9();
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, NULL, NULL,
                                                 &res, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT16(7, res.used); /* 6 terms + 1 */
    TEST_ASSERT_EQUAL_UINT16(2, res.rejected);
    TEST_ASSERT_FALSE(res.within_bound);
}

/* Ties: two pairs equally far off (mirror images about the grid's centre
   of a pure shift): the lower index goes first. */
static void test_rejection_tie_lowest_index(void)
{
    ssda_poly_fit_config_t cfg = {1, 512};
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    int k;
    for (k = 0; k < 12; k++) {
        const int X = 10 + 20 * (k % 4), Y = 10 + 25 * (k / 4);
        g_pairs[k].ref_x_q8 = X * 256;
        g_pairs[k].ref_y_q8 = Y * 256;
        g_pairs[k].mov_x_q8 = (X + 5) * 256;
        g_pairs[k].mov_y_q8 = (Y - 3) * 256;
    }
    /* pairs 1 and 10 mirror each other about the centre (50, 50): equal
       residuals by symmetry of the affine fit */
    g_pairs[1].mov_x_q8 += 30 * 256;
    g_pairs[10].mov_x_q8 -= 30 * 256;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_fit(g_pairs, 12, 100, 100, &cfg, &p, g_res, g_used,
                                                 &res, g_work, sizeof g_work));
    TEST_ASSERT_EQUAL_UINT16(2, res.rejected);
    TEST_ASSERT_EQUAL_UINT8(0, g_used[1]);
    TEST_ASSERT_EQUAL_UINT8(0, g_used[10]);
    TEST_ASSERT_EQUAL_UINT32(0, res.max_q8);
    {
        int32_t u, v;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_eval(&p, 37, 61, &u, &v));
        TEST_ASSERT_EQUAL_INT32(42 * 256, u);
        TEST_ASSERT_EQUAL_INT32(58 * 256, v);
    }
}

/* The largest accepted job: 16384 pairs at the corners of a 65535 x 65535
   grid, displacements at the int32 Q8 extremes. The exact sums hold; the
   fit of alternating +-2^22 px displacements is their mean shift 0 with
   the right residuals. */
static void test_worst_case_sums(void)
{
#ifndef SSDA_TEST_SMALL
    static ssda_poly_pair_t big[16384];
    static uint8_t work[16384];
    const size_t n = 16384;
#else
    static ssda_poly_pair_t big[2048];
    static uint8_t work[2048];
    const size_t n = 2048;
#endif
    ssda_poly_fit_config_t cfg = {3, UINT32_MAX};
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    size_t k;
    for (k = 0; k < n; k++) {
        const int corner = (int)(k % 4);
        const int32_t X = (corner & 1) ? 65534 : 0, Y = (corner & 2) ? 65534 : 0;
        const int32_t off = (k / 4) % 2 ? (1 << 30) : -(1 << 30); /* 2^22 px */
        big[k].ref_x_q8 = X * 256;
        big[k].ref_y_q8 = Y * 256;
        big[k].mov_x_q8 = X * 256 + off;
        big[k].mov_y_q8 = Y * 256 - off;
    }
    /* four distinct positions cannot determine 10 terms */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_fit(big, n, 65535, 65535, &cfg, &p, NULL, NULL,
                                                       &res, work, n));
    /* order 1 needs 3 terms: four corners do */
    cfg.order = 1;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_fit(big, n, 65535, 65535, &cfg, &p, NULL, NULL, &res,
                                                 work, n));
    TEST_ASSERT_EQUAL_UINT16(n, res.used);
    {
        int32_t u, v;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_eval(&p, 1000, 2000, &u, &v));
        TEST_ASSERT_INT32_WITHIN(1, 1000 * 256, u);
        TEST_ASSERT_INT32_WITHIN(1, 2000 * 256, v);
    }
    /* every residual is 2^22 * sqrt(2) px */
    TEST_ASSERT_UINT32_WITHIN(2, 1518500250u, res.rms_q8); /* 2^30.5 */
    TEST_ASSERT_UINT32_WITHIN(2, 1518500250u, res.max_q8);
}

static void test_errors_leave_outputs(void)
{
    ssda_poly_fit_config_t cfg = {2, 0};
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    load_fig9();
    memset(&p, 0x5A, sizeof p);
    memset(&res, 0x5A, sizeof res);
    memset(g_res, 0x5A, sizeof g_res);
    memset(g_used, 0x5A, sizeof g_used);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_poly_fit(NULL, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, NULL, g_res, g_used, &res, g_work, 9));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, NULL, 9));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_fit(g_pairs, 9, 0, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_fit(g_pairs, 5, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_fit(g_pairs, 16385, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 16385));
    cfg.order = 4;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    cfg.order = 3; /* 9 pairs < 10 terms */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    cfg.order = 1;
    /* a reference position outside the grid's domain (1000 px wide: |X - 500| <= 512) */
    g_pairs[4].ref_x_q8 = 1013 * 256;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    g_pairs[4].ref_x_q8 = -13 * 256;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    load_fig9();
    g_pairs[4].ref_y_q8 = 913 * 256; /* 800 high: |Y - 400| <= 512 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    g_pairs[4].ref_y_q8 = -130 * 256;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_poly_fit(g_pairs, 9, 1000, 800, &cfg, &p, g_res, g_used, &res, g_work, 9));
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &p, sizeof p);
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &res, sizeof res);
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, g_res, sizeof g_res);
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, g_used, sizeof g_used);
}

/* Pairs on one line cannot fix an affine map; repeated positions cannot
   fix a quadratic. */
static void test_degenerate_pairs(void)
{
    ssda_poly_fit_config_t cfg = {1, 0};
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    int k;
    for (k = 0; k < 10; k++) {
        g_pairs[k].ref_x_q8 = (100 + 30 * k) * 256;
        g_pairs[k].ref_y_q8 = (50 + 20 * k) * 256;
        g_pairs[k].mov_x_q8 = g_pairs[k].ref_x_q8 + 1000;
        g_pairs[k].mov_y_q8 = g_pairs[k].ref_y_q8;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_fit(g_pairs, 10, 1000, 800, &cfg, &p, NULL, NULL, &res, g_work, 10));
    /* a 3 x 3 lattice: fine for order 2, not for order 3 */
    for (k = 0; k < 12; k++) {
        g_pairs[k].ref_x_q8 = (200 + 300 * (k % 3)) * 256;
        g_pairs[k].ref_y_q8 = (100 + 300 * ((k / 3) % 3)) * 256;
        g_pairs[k].mov_x_q8 = g_pairs[k].ref_x_q8 + 700;
        g_pairs[k].mov_y_q8 = g_pairs[k].ref_y_q8 - 300;
    }
    cfg.order = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_fit(g_pairs, 12, 1000, 800, &cfg, &p, NULL, NULL, &res, g_work, 12));
    cfg.order = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_poly_fit(g_pairs, 12, 1000, 800, &cfg, &p, NULL, NULL, &res, g_work, 12));
}

/* A map beyond 2^24 px per normalised unit: pairs 64 px apart (on a
   65535 px grid: pivots 2^-10 of the diagonal, accepted) whose
   displacements differ by 2^24 px. */
static void test_overflow(void)
{
    ssda_poly_fit_config_t cfg = {1, UINT32_MAX};
    ssda_poly_fit_result_t res;
    ssda_poly_t p;
    int k;
    for (k = 0; k < 8; k++) {
        g_pairs[k].ref_x_q8 = (30000 + 64 * (k & 1)) * 256;
        g_pairs[k].ref_y_q8 = (30000 + 64 * ((k >> 1) & 1)) * 256;
        g_pairs[k].mov_x_q8 = (k & 1) ? INT32_MAX : INT32_MIN;
        g_pairs[k].mov_y_q8 = ((k >> 1) & 1) ? INT32_MAX : INT32_MIN;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_OVERFLOW, ssda_poly_fit(g_pairs, 8, 65535, 65535, &cfg, &p, NULL, NULL, &res, g_work, 8));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_fit_matches_double_exact_maps);
    RUN_TEST(test_fit_matches_double_noisy);
    RUN_TEST(test_fit_ill_conditioned);
    RUN_TEST(test_fig9_outlier_rejected);
    RUN_TEST(test_fig9_no_rejection);
    RUN_TEST(test_rejection_stops_at_minimum);
    RUN_TEST(test_rejection_tie_lowest_index);
    RUN_TEST(test_worst_case_sums);
    RUN_TEST(test_errors_leave_outputs);
    RUN_TEST(test_degenerate_pairs);
    RUN_TEST(test_overflow);
    return UNITY_END();
}
