/*
 * test_symreg.c - symbolic registration (include/ssda/symreg.h) on loops
 * made here: shapes placed in REF, mapped by a known affine transform into
 * MOV with their start points moved, plus loops that have no partner. The
 * transform and every pair must come back; too few loops give no
 * registration; the least squares of eq. 17 agrees with a double-precision
 * fit computed here; errors change nothing.
 */
#include <string.h>
#include "unity.h"
#include "ssda/symreg.h"
#include "symreg_internal.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define NS 64u
#define K 8u        /* shapes seen in both images */
#define EXTRA 3u    /* shapes seen in one only */
#define NL (K + EXTRA)

static ssda_loop_t g_ref[NL], g_mov[NL];
static ssda_fd_t g_fr[NL], g_fm[NL];
static ssda_point_q8_t g_pr[NL][NS], g_pm[NL][NS];
static uint32_t g_work[(SSDA_SYMREG_WORK_SIZE(NL, NL, SSDA_SYMREG_DEFAULT_NUCLEI) + 3u) / 4u + 1u];
static ssda_symreg_pair_t g_pairs[NL];

static double frand(test_rng_t *r, double lo, double hi)
{
    return lo + (hi - lo) * (double)test_rng_next(r) / 4294967296.0;
}

static int32_t q8(double v)
{
    return (int32_t)(v >= 0 ? v * 256.0 + 0.5 : v * 256.0 - 0.5);
}

typedef struct {
    double c[2][4]; /* radial harmonics: amplitude and phase of orders 2..5 */
    double r;
} shape_t;

static void random_shape(test_rng_t *r, shape_t *s)
{
    uint32_t k;
    s->r = frand(r, 8.0, 16.0);
    for (k = 0u; k < 4u; k++) {
        s->c[0][k] = frand(r, 0.0, 0.18) / (1.0 + k);
        s->c[1][k] = frand(r, 0.0, 2.0 * TEST_PI);
    }
}

/* point at parameter t of a shape centred at the origin */
static void shape_at(const shape_t *s, double t, double *x, double *y)
{
    const double a = 2.0 * TEST_PI * t;
    double rad = s->r;
    uint32_t k;
    for (k = 0u; k < 4u; k++) {
        rad += s->r * s->c[0][k] * test_cos((k + 2.0) * a + s->c[1][k]);
    }
    *x = rad * test_cos(a);
    *y = rad * test_sin(a);
}

/* affine (row-major 2 x 3) of a point */
static void map(const double *A, double x, double y, double *u, double *v)
{
    *u = A[0] * x + A[1] * y + A[2];
    *v = A[3] * x + A[4] * y + A[5];
}

/* A loop of shape s centred at (cx, cy), its contour mapped by the linear
   part of A (NULL: none) and started at tau. */
static void make_loop(const shape_t *s, double cx, double cy, const double *A, double tau,
                      ssda_loop_t *lp, ssda_point_q8_t *pts, ssda_fd_t *fd)
{
    double area = 0.0, px = 0.0, py = 0.0;
    uint32_t k;
    for (k = 0u; k < NS; k++) {
        double x, y, u, v;
        shape_at(s, (double)k / NS + tau, &x, &y);
        if (A != NULL) {
            map(A, x, y, &u, &v);
            u -= A[2];
            v -= A[5];
        } else {
            u = x;
            v = y;
        }
        pts[k].x_q8 = q8(cx + u);
        pts[k].y_q8 = q8(cy + v);
        if (k > 0u) {
            area += px * v - py * u;
        }
        px = u;
        py = v;
    }
    lp->cx_q8 = q8(cx);
    lp->cy_q8 = q8(cy);
    lp->area = (uint32_t)(0.5 * (area < 0 ? -area : area) + 0.5);
    lp->contour = pts;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(pts, NS, 10u, fd));
}

/* REF: K shared shapes + EXTRA of its own; MOV: the K mapped by A (in a
   shuffled order, perm[i] = MOV index of REF shape i) + EXTRA others. */
static void make_scene(test_rng_t *r, const double *A, uint32_t *perm)
{
    shape_t s;
    uint32_t i;
    for (i = 0u; i < NL; i++) {
        perm[i] = i;
    }
    for (i = NL - 1u; i > 0u; i--) {
        const uint32_t j = test_rng_range(r, 0u, i), t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    for (i = 0u; i < NL; i++) {
        const double cx = frand(r, 40.0, 460.0), cy = frand(r, 40.0, 460.0);
        random_shape(r, &s);
        make_loop(&s, cx, cy, NULL, 0.0, &g_ref[i], g_pr[i], &g_fr[i]);
        if (i < K) {
            double u, v;
            map(A, cx, cy, &u, &v);
            make_loop(&s, u, v, A, frand(r, 0.0, 1.0), &g_mov[perm[i]], g_pm[perm[i]],
                      &g_fm[perm[i]]);
        } else {
            shape_t o;
            random_shape(r, &o);
            make_loop(&o, frand(r, 40.0, 560.0), frand(r, 40.0, 560.0), NULL, 0.0,
                      &g_mov[perm[i]], g_pm[perm[i]], &g_fm[perm[i]]);
        }
    }
}

static void test_known_transforms_come_back(void)
{
    test_rng_t r;
    uint32_t trial, perm[NL], i;
    test_rng_seed(&r, 21u);
    for (trial = 0u; trial < 6u; trial++) {
        const double s = frand(&r, 0.7, 1.4), phi = frand(&r, 0.0, 2.0 * TEST_PI);
        const double shear = trial < 3u ? 0.0 : 0.02;
        const double A[6] = {s * test_cos(phi), -s * test_sin(phi) + shear, frand(&r, -50, 50),
                             s * test_sin(phi), s * test_cos(phi), frand(&r, -50, 50)};
        ssda_symreg_result_t res;
        make_scene(&r, A, perm);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, NULL, g_work,
                                                   sizeof g_work, g_pairs, NL, &res));
        TEST_ASSERT_EQUAL_UINT32(K, res.pairs);
        for (i = 0u; i < K; i++) {
            TEST_ASSERT_EQUAL_UINT16(i, g_pairs[i].ref); /* REF order */
            TEST_ASSERT_EQUAL_UINT16(perm[i], g_pairs[i].mov);
            TEST_ASSERT_TRUE(g_pairs[i].resid_q8 < 26u); /* 0.1 px */
            TEST_ASSERT_TRUE(g_pairs[i].e2_fixed_q16 < 3277u);
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-3, A[0], res.affine.a_q16 / 65536.0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-3, A[1], res.affine.b_q16 / 65536.0);
        TEST_ASSERT_DOUBLE_WITHIN(0.1, A[2], res.affine.c_q8 / 256.0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-3, A[3], res.affine.d_q16 / 65536.0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-3, A[4], res.affine.e_q16 / 65536.0);
        TEST_ASSERT_DOUBLE_WITHIN(0.1, A[5], res.affine.f_q8 / 256.0);
        /* eq. 14: sqrt |ae - bd| */
        TEST_ASSERT_DOUBLE_WITHIN(2e-3, test_sqrt(A[0] * A[4] - A[1] * A[3]),
                                  res.scale_q16 / 65536.0);
        TEST_ASSERT_TRUE(res.rms_q8 < 26u);
        TEST_ASSERT_TRUE(res.nuclei >= 1u && res.candidates >= res.nuclei);
        TEST_ASSERT_TRUE(res.matches + res.skipped <= NL * NL);
    }
}

/* Tiny loops as ssda_loops_find gives them with area_min 1 or 2: a one-
   pixel region (all samples at its centre: zero energy, which matches
   nothing, fourier.h) in MOV where REF has a two-pixel one, at the place
   the transform maps it to. The registration must be the scene's own:
   same pairs, same affine. A zero energy went into ssda__ratio_q16 as a
   divisor (the E^2 bound of the fixed match) and ssda_fd_match's error
   left the E^2 read afterwards unset. */
static void tiny_loop(uint32_t x, uint32_t y, uint32_t pixels, ssda_loop_t *lp,
                      ssda_point_q8_t *pts, ssda_fd_t *fd)
{
    static uint8_t mask[8][8];
    ssda_view_t v;
    uint32_t k;
    memset(mask, 0, sizeof mask);
    mask[3][3] = 1u;
    mask[3][4] = pixels > 1u ? 1u : 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, mask, 8u, 8u, 8u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_contour(&v, 3u, 3u, NS, pts, NULL));
    for (k = 0u; k < NS; k++) {
        pts[k].x_q8 += (int32_t)(x - 3u) * 256;
        pts[k].y_q8 += (int32_t)(y - 3u) * 256;
    }
    lp->cx_q8 = pts[0].x_q8 + (pixels > 1u ? 128 : 0);
    lp->cy_q8 = pts[0].y_q8;
    lp->area = pixels;
    lp->contour = pts;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(pts, NS, 10u, fd));
}

static void test_zero_energy_loops_match_nothing(void)
{
    static ssda_loop_t ref[NL + 1u], mov[NL + 1u];
    static ssda_fd_t fr[NL + 1u], fm[NL + 1u];
    static ssda_point_q8_t pr[NS], pm[NS];
    static ssda_symreg_pair_t pairs0[NL + 1u], pairs1[NL + 1u];
    static uint32_t work[(SSDA_SYMREG_WORK_SIZE(NL + 1u, NL + 1u, SSDA_SYMREG_DEFAULT_NUCLEI) + 3u) / 4u];
    test_rng_t r;
    uint32_t perm[NL], i;
    const double A[6] = {1.0, 0.0, 20.0, 0.0, 1.0, -10.0};
    ssda_symreg_result_t res0, res1;
    ssda_symreg_config_t cfg;
    test_rng_seed(&r, 77u);
    make_scene(&r, A, perm);
    memset(&cfg, 0, sizeof cfg);
    cfg.area_ratio_q8 = 1024u; /* areas 1 and 2 within 1/4..4 */
    cfg.e2_grow_q16 = 0xFFFFFFFFu; /* every fixed match searched, none skipped by its bound */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, &cfg, g_work,
                                               sizeof g_work, pairs0, NL, &res0));
    TEST_ASSERT_EQUAL_UINT32(K, res0.pairs);
    for (i = 0u; i < NL; i++) {
        ref[i] = g_ref[i];
        mov[i] = g_mov[i];
        fr[i] = g_fr[i];
        fm[i] = g_fm[i];
    }
    tiny_loop(250u, 250u, 2u, &ref[NL], pr, &fr[NL]);
    tiny_loop(270u, 240u, 1u, &mov[NL], pm, &fm[NL]);
    TEST_ASSERT_TRUE(fr[NL].energy_q16 != 0u);
    TEST_ASSERT_EQUAL_UINT64(0u, fm[NL].energy_q16);
    memset(&res1, 0x5C, sizeof res1);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(ref, fr, NL + 1u, mov, fm, NL + 1u, &cfg, work,
                                               sizeof work, pairs1, NL + 1u, &res1));
    TEST_ASSERT_EQUAL_UINT32(res0.pairs, res1.pairs);
    TEST_ASSERT_EQUAL_MEMORY(&res0.affine, &res1.affine, sizeof res0.affine);
    TEST_ASSERT_EQUAL_MEMORY(pairs0, pairs1, res0.pairs * sizeof pairs0[0]);
}

static void test_too_few_loops_register_nothing(void)
{
    test_rng_t r;
    uint32_t perm[NL];
    const double A[6] = {1.0, 0.0, 5.0, 0.0, 1.0, -3.0};
    ssda_symreg_result_t res;
    test_rng_seed(&r, 22u);
    make_scene(&r, A, perm);
    /* two shared loops only: below the seed's 3 */
    {
        ssda_loop_t lr[2], lm[2];
        ssda_fd_t fr[2], fm[2];
        uint32_t i;
        for (i = 0u; i < 2u; i++) {
            lr[i] = g_ref[i];
            fr[i] = g_fr[i];
            lm[i] = g_mov[perm[i]];
            fm[i] = g_fm[perm[i]];
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(lr, fr, 2u, lm, fm, 2u, NULL, g_work,
                                                   sizeof g_work, g_pairs, NL, &res));
        TEST_ASSERT_EQUAL_UINT32(0u, res.pairs);
        TEST_ASSERT_TRUE(res.nuclei >= 2u); /* tried, and every one too small */
    }
    /* no loops at all */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(NULL, NULL, 0u, g_mov, g_fm, NL, NULL, g_work,
                                               sizeof g_work, NULL, 0u, &res));
    TEST_ASSERT_EQUAL_UINT32(0u, res.pairs);
    TEST_ASSERT_EQUAL_UINT32(0u, res.candidates);
    /* min_pairs above what exists */
    {
        ssda_symreg_config_t c;
        memset(&c, 0, sizeof c);
        c.min_pairs = K + 1u;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, &c, g_work,
                                                   sizeof g_work, g_pairs, NL, &res));
        TEST_ASSERT_EQUAL_UINT32(0u, res.pairs);
    }
}

/* eq. 17 against least squares in double on noisy centroids */
static void test_fit_equals_double_least_squares(void)
{
    test_rng_t r;
    ssda__partner_t set[NL];
    ssda_symreg_affine_t t;
    double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, n = NL;
    double rhs[2][3] = {{0, 0, 0}, {0, 0, 0}}, sol[2][3];
    uint32_t i, j;
    test_rng_seed(&r, 23u);
    for (i = 0u; i < NL; i++) {
        g_ref[i].cx_q8 = q8(frand(&r, 0.0, 1000.0));
        g_ref[i].cy_q8 = q8(frand(&r, 0.0, 800.0));
        g_mov[i].cx_q8 = q8(0.9 * g_ref[i].cx_q8 / 256.0 + 0.2 * g_ref[i].cy_q8 / 256.0 + 30.0 +
                            frand(&r, -2.0, 2.0));
        g_mov[i].cy_q8 = q8(-0.3 * g_ref[i].cx_q8 / 256.0 + 1.1 * g_ref[i].cy_q8 / 256.0 + 70.0 +
                            frand(&r, -2.0, 2.0));
        set[i].mov = (uint16_t)i;
        set[i].e2 = 0u;
    }
    TEST_ASSERT_TRUE(ssda__symreg_fit(g_ref, g_mov, set, NL, &t));
    for (i = 0u; i < NL; i++) {
        const double x = g_ref[i].cx_q8 / 256.0, y = g_ref[i].cy_q8 / 256.0;
        const double u[2] = {g_mov[i].cx_q8 / 256.0, g_mov[i].cy_q8 / 256.0};
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
        sx += x;
        sy += y;
        for (j = 0u; j < 2u; j++) {
            rhs[j][0] += u[j] * x;
            rhs[j][1] += u[j] * y;
            rhs[j][2] += u[j];
        }
    }
    for (j = 0u; j < 2u; j++) { /* eq. 17 by Cramer's rule, 3 x 3 */
        const double m[3][3] = {{sxx, sxy, sx}, {sxy, syy, sy}, {sx, sy, n}};
        const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        uint32_t c;
        for (c = 0u; c < 3u; c++) {
            double mm[3][3];
            uint32_t a, b;
            for (a = 0u; a < 3u; a++) {
                for (b = 0u; b < 3u; b++) {
                    mm[a][b] = b == c ? rhs[j][a] : m[a][b];
                }
            }
            sol[j][c] = (mm[0][0] * (mm[1][1] * mm[2][2] - mm[1][2] * mm[2][1]) -
                         mm[0][1] * (mm[1][0] * mm[2][2] - mm[1][2] * mm[2][0]) +
                         mm[0][2] * (mm[1][0] * mm[2][1] - mm[1][1] * mm[2][0])) / det;
        }
    }
    TEST_ASSERT_DOUBLE_WITHIN(5e-5, sol[0][0], t.a_q16 / 65536.0);
    TEST_ASSERT_DOUBLE_WITHIN(5e-5, sol[0][1], t.b_q16 / 65536.0);
    TEST_ASSERT_DOUBLE_WITHIN(0.02, sol[0][2], t.c_q8 / 256.0);
    TEST_ASSERT_DOUBLE_WITHIN(5e-5, sol[1][0], t.d_q16 / 65536.0);
    TEST_ASSERT_DOUBLE_WITHIN(5e-5, sol[1][1], t.e_q16 / 65536.0);
    TEST_ASSERT_DOUBLE_WITHIN(0.02, sol[1][2], t.f_q8 / 256.0);
    /* collinear centroids, and fewer than three pairs: refused */
    for (i = 0u; i < NL; i++) {
        g_ref[i].cy_q8 = g_ref[i].cx_q8 / 2;
    }
    TEST_ASSERT_FALSE(ssda__symreg_fit(g_ref, g_mov, set, NL, &t));
    for (i = 2u; i < NL; i++) {
        set[i].mov = SSDA__NONE;
    }
    TEST_ASSERT_FALSE(ssda__symreg_fit(g_ref, g_mov, set, NL, &t));
}

/* Nearly collinear centroids: a line with offsets of +-9 Q8 steps, which
   puts the determinant near 2^-24 of xx yy (well above the rounding of
   the narrowed sums, ~2^-29). The fit refuses a set below 2^-20 (symreg.h:
   'collinear'); offsets of up to 60 px pass. */
static void test_fit_refuses_nearly_collinear(void)
{
    test_rng_t r;
    ssda__partner_t set[NL];
    ssda_symreg_affine_t t;
    uint32_t i, pass;
    test_rng_seed(&r, 29u);
    for (pass = 0u; pass < 2u; pass++) {
        double mx = 0.0, my = 0.0, xx = 0.0, xy = 0.0, yy = 0.0;
        for (i = 0u; i < NL; i++) {
            const double x = frand(&r, 0.0, 1000.0);
            const double off = pass == 0u ? (i % 2u == 0u ? 9.0 : -9.0) / 256.0
                                          : frand(&r, -60.0, 60.0);
            g_ref[i].cx_q8 = q8(x);
            g_ref[i].cy_q8 = q8(x / 2.0 + 100.0) + (int32_t)(off * 256.0);
            g_mov[i].cx_q8 = g_ref[i].cx_q8 + 5 * 256;
            g_mov[i].cy_q8 = g_ref[i].cy_q8 - 7 * 256;
            set[i].mov = (uint16_t)i;
            set[i].e2 = 0u;
        }
        for (i = 0u; i < NL; i++) {
            mx += g_ref[i].cx_q8 / (256.0 * NL);
            my += g_ref[i].cy_q8 / (256.0 * NL);
        }
        for (i = 0u; i < NL; i++) {
            const double dx = g_ref[i].cx_q8 / 256.0 - mx, dy = g_ref[i].cy_q8 / 256.0 - my;
            xx += dx * dx;
            xy += dx * dy;
            yy += dy * dy;
        }
        if (pass == 0u) {
            TEST_ASSERT_TRUE((xx * yy - xy * xy) < xx * yy / 1048576.0 / 4.0);
            TEST_ASSERT_TRUE((xx * yy - xy * xy) > xx * yy / 1048576.0 / 64.0);
            TEST_ASSERT_FALSE(ssda__symreg_fit(g_ref, g_mov, set, NL, &t));
        } else {
            TEST_ASSERT_TRUE((xx * yy - xy * xy) > xx * yy / 1048576.0 * 4.0);
            TEST_ASSERT_TRUE(ssda__symreg_fit(g_ref, g_mov, set, NL, &t));
            TEST_ASSERT_INT32_WITHIN(2, 65536, t.a_q16); /* a translation */
            TEST_ASSERT_INT32_WITHIN(2, 0, t.b_q16);
        }
    }
}

/* Eqs. 14-15 against double for affines turned every way, with shears
   that put the y axis's angle on either side of the x axis's: the mean
   angle goes the shorter way round (across 0 turns too). */
static void test_scale_rot_vs_double(void)
{
    test_rng_t r;
    uint32_t n;
    test_rng_seed(&r, 31u);
    for (n = 0u; n < 2000u; n++) {
        const double s = frand(&r, 0.3, 3.0), th = frand(&r, 0.0, 2.0 * TEST_PI);
        const double sh = frand(&r, -0.2, 0.2), k = frand(&r, 0.8, 1.25);
        ssda_symreg_affine_t t;
        double a, b, d, e, th1, th2, diff, want, got, det;
        uint32_t s_q16, phi;
        /* x axis to s (cos, sin) th, y axis to s k (-sin, cos)(th + sh) */
        a = s * test_cos(th);
        d = s * test_sin(th);
        b = -s * k * test_sin(th + sh);
        e = s * k * test_cos(th + sh);
        t.a_q16 = (int32_t)(a * 65536.0);
        t.b_q16 = (int32_t)(b * 65536.0);
        t.d_q16 = (int32_t)(d * 65536.0);
        t.e_q16 = (int32_t)(e * 65536.0);
        t.c_q8 = 0;
        t.f_q8 = 0;
        ssda__symreg_scale_rot(&t, &s_q16, &phi);
        th1 = test_atan2(t.d_q16, t.a_q16);
        th2 = test_atan2(t.e_q16, t.b_q16) - TEST_PI / 2.0;
        diff = th2 - th1;
        while (diff > TEST_PI) {
            diff -= 2.0 * TEST_PI;
        }
        while (diff < -TEST_PI) {
            diff += 2.0 * TEST_PI;
        }
        want = (th1 + diff / 2.0) / (2.0 * TEST_PI); /* turns */
        got = phi / 4294967296.0 - want;
        while (got >= 0.5) { /* wrapped to [-0.5, 0.5) */
            got -= 1.0;
        }
        while (got < -0.5) {
            got += 1.0;
        }
        TEST_ASSERT_DOUBLE_WITHIN(1.0 / 1048576.0, 0.0, got);
        det = ((double)t.a_q16 * t.e_q16 - (double)t.b_q16 * t.d_q16) / 4294967296.0;
        TEST_ASSERT_DOUBLE_WITHIN(2.0, test_sqrt(det < 0 ? -det : det) * 65536.0, (double)s_q16);
    }
}

static void test_similarity_scale_rotation_and_apply(void)
{
    ssda_symreg_affine_t t;
    uint32_t s, phi;
    int32_t u, v;
    /* eq. 16 with s 1.5, phi 30 degrees: the REF centroid lands on MOV's */
    ssda__symreg_similarity(98304u, 0x15555555u, 100 * 256, 50 * 256, 300 * 256, 20 * 256, &t);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg_apply(&t, 100 * 256, 50 * 256, &u, &v));
    TEST_ASSERT_INT32_WITHIN(1, 300 * 256, u);
    TEST_ASSERT_INT32_WITHIN(1, 20 * 256, v);
    /* one px along x in REF: 1.5 (cos 30, sin 30) in MOV */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg_apply(&t, 101 * 256, 50 * 256, &u, &v));
    TEST_ASSERT_INT32_WITHIN(2, 300 * 256 + 333, u); /* 1.299 px */
    TEST_ASSERT_INT32_WITHIN(2, 20 * 256 + 192, v);  /* 0.75 px */
    ssda__symreg_scale_rot(&t, &s, &phi);
    TEST_ASSERT_UINT32_WITHIN(8u, 98304u, s);
    TEST_ASSERT_UINT32_WITHIN(1u << 18, 0x15555555u, phi);
    /* saturation */
    t.a_q16 = 0x7FFFFFFF;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg_apply(&t, 0x7FFFFFFF, 0, &u, &v));
    TEST_ASSERT_EQUAL_INT32(0x7FFFFFFF, u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg_apply(NULL, 0, 0, &u, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg_apply(&t, 0, 0, NULL, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg_apply(&t, 0, 0, &u, NULL));
}

static void test_errors_change_nothing(void)
{
    test_rng_t r;
    uint32_t perm[NL];
    const double A[6] = {1.0, 0.0, 5.0, 0.0, 1.0, -3.0};
    ssda_symreg_result_t res, poison;
    ssda_symreg_config_t c;
    ssda_fd_t odd;
    test_rng_seed(&r, 24u);
    make_scene(&r, A, perm);
    memset(&poison, 0x19, sizeof poison);
    res = poison;
    memset(&c, 0, sizeof c);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg(NULL, g_fr, NL, g_mov, g_fm, NL, NULL,
                                                    g_work, sizeof g_work, g_pairs, NL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg(g_ref, g_fr, NL, g_mov, NULL, NL, NULL,
                                                    g_work, sizeof g_work, g_pairs, NL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, NULL,
                                                    NULL, sizeof g_work, g_pairs, NL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, NULL,
                                                    g_work, sizeof g_work, NULL, NL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, NULL,
                                                    g_work, sizeof g_work, g_pairs, NL, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(g_ref, g_fr, SSDA_SYMREG_MAX_LOOPS + 1u,
                                                   g_mov, g_fm, NL, NULL, g_work, sizeof g_work,
                                                   g_pairs, NL, &res));
    c.min_pairs = 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, &c, g_work,
                                                   sizeof g_work, g_pairs, NL, &res));
    memset(&c, 0, sizeof c);
    c.e2_final_q16 = 20000u; /* above e2_grow's 0.25 = 16384 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, &c, g_work,
                                                   sizeof g_work, g_pairs, NL, &res));
    memset(&c, 0, sizeof c);
    c.scale_min_q16 = 200000u; /* above scale_max 2.0 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, &c, g_work,
                                                   sizeof g_work, g_pairs, NL, &res));
    memset(&c, 0, sizeof c);
    c.area_ratio_q8 = 255u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, &c, g_work,
                                                   sizeof g_work, g_pairs, NL, &res));
    odd = g_fm[3];
    g_fm[3].order = 9u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, NULL,
                                                   g_work, sizeof g_work, g_pairs, NL, &res));
    g_fm[3] = odd;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, NULL,
                                                      g_work, SSDA_SYMREG_WORK_SIZE(NL, NL, SSDA_SYMREG_DEFAULT_NUCLEI) - 1u,
                                                      g_pairs, NL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_symreg(g_ref, g_fr, NL, g_mov, g_fm, NL, NULL,
                                                      (uint8_t *)g_work + 2, sizeof g_work - 4u,
                                                      g_pairs, NL, &res));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_known_transforms_come_back);
    RUN_TEST(test_too_few_loops_register_nothing);
    RUN_TEST(test_zero_energy_loops_match_nothing);
    RUN_TEST(test_fit_equals_double_least_squares);
    RUN_TEST(test_similarity_scale_rotation_and_apply);
    RUN_TEST(test_fit_refuses_nearly_collinear);
    RUN_TEST(test_scale_rot_vs_double);
    RUN_TEST(test_errors_change_nothing);
    return UNITY_END();
}
