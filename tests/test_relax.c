/*
 * test_relax.c - relaxation labelling and the normalised median test
 * (ssda/relax.h) against independent references written here: the seed's
 * eqs. 1-3 in double precision with the 48 x 48 compatibility matrix formed
 * directly (the library uses a factored form), and the median test with
 * plain sorting in 64-bit integers. Also the class layout, grids read in
 * place from ssda_track_vector_t arrays, outlier repair on known fields, and
 * argument errors leaving the output untouched.
 */
#include <string.h>
#include "unity.h"
#include "ssda/relax.h"
#include "ssda/track.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define MAXC 12u
#define MAXR 10u
#define MAXN (MAXC * MAXR)

typedef struct {
    int32_t dx, dy;
    uint8_t status;
} vec_t;

static vec_t g_in[MAXN];
static ssda_relax_vector_t g_out[MAXN];
static uint32_t g_work[SSDA_RELAX_WORK_SIZE(MAXC, MAXR) / 4u + 1u];

static ssda_relax_grid_t grid_of(const vec_t *v, uint16_t cols, uint16_t rows, uint8_t frac)
{
    ssda_relax_grid_t g;
    memset(&g, 0, sizeof g);
    g.dx = &v[0].dx;
    g.dy = &v[0].dy;
    g.status = &v[0].status;
    g.stride = sizeof(vec_t);
    g.cols = cols;
    g.rows = rows;
    g.frac_bits = frac;
    return g;
}

static ssda_relax_config_t config(uint16_t iterations, uint8_t flags)
{
    ssda_relax_config_t c;
    memset(&c, 0, sizeof c);
    c.iterations = iterations;
    c.flags = flags;
    c.work = g_work;
    c.work_size = sizeof g_work;
    return c;
}

/* ---- the double-precision reference of eqs. 1-3 ---- */

#define PI 3.14159265358979323846

static int ref_class(double x, double y, double step)
{
    double ang = test_atan2(y, x) * 180.0 / PI; /* -180 .. 180 */
    double len = test_sqrt(x * x + y * y);
    int s, l = (int)(len / step);
    if (ang < 0.0) {
        ang += 360.0;
    }
    s = (int)((ang + 22.5) / 45.0) % 8;
    if (l > 5) {
        l = 5;
    }
    return s + 8 * l;
}

static double ref_r(int c, int d)
{
    int sc = c % 8, sd = d % 8, lc = c / 8, ld = d / 8;
    int dt = sc > sd ? sc - sd : sd - sc;
    int dl = lc > ld ? lc - ld : ld - lc;
    double r;
    if (dt > 4) {
        dt = 8 - dt;
    }
    if (lc == 0 || ld == 0) {
        dt = 0;
    }
    r = 1.0 - 0.2 * dt - 0.2 * dl;
    return r < -1.0 ? -1.0 : (r > 1.0 ? 1.0 : r);
}

static double g_p[MAXN][48], g_np[MAXN][48], g_s[MAXN][48], g_r[48][48];
static int g_cls[MAXN];

#ifdef SSDA_TEST_SMALL
#define TRIALS 2u
#else
#define TRIALS 6u
#endif

/* Expected outputs (Q8 px, as double) and classes, for a grid of Q8 vectors. */
static void ref_relax(const vec_t *v, int cols, int rows, double step, int iters, double *ox,
                      double *oy, int *best)
{
    int k, c, d, it, i, j;
    for (c = 0; c < 48; c++) {
        for (d = 0; d < 48; d++) {
            g_r[c][d] = ref_r(c, d);
        }
    }
    for (k = 0; k < cols * rows; k++) {
        g_cls[k] = -1;
        if (v[k].status != 0) {
            continue;
        }
        g_cls[k] = ref_class(v[k].dx, v[k].dy, step);
        for (c = 0; c < 48; c++) {
            g_p[k][c] = c == g_cls[k] ? 0.53 : 0.01;
        }
    }
    for (it = 0; it < iters; it++) {
        for (k = 0; k < cols * rows; k++) { /* each node's support sum_d r(c, d) P(d) */
            for (c = 0; c < 48 && g_cls[k] >= 0; c++) {
                g_s[k][c] = 0.0;
                for (d = 0; d < 48; d++) {
                    g_s[k][c] += g_r[c][d] * g_p[k][d];
                }
            }
        }
        for (j = 0; j < rows; j++) {
            for (i = 0; i < cols; i++) {
                double q[48], t = 0.0;
                int n = 0, di, dj;
                k = j * cols + i;
                if (g_cls[k] < 0) {
                    continue;
                }
                memset(q, 0, sizeof q);
                for (dj = -1; dj <= 1; dj++) {
                    for (di = -1; di <= 1; di++) {
                        int x = i + di, y = j + dj, kk = y * cols + x;
                        if ((di == 0 && dj == 0) || x < 0 || y < 0 || x >= cols || y >= rows ||
                            g_cls[kk] < 0) {
                            continue;
                        }
                        for (c = 0; c < 48; c++) {
                            q[c] += g_s[kk][c];
                        }
                        n++;
                    }
                }
                for (c = 0; c < 48; c++) {
                    g_np[k][c] = g_p[k][c] * (1.0 + (n > 0 ? q[c] / n : 0.0));
                    t += g_np[k][c];
                }
                for (c = 0; c < 48; c++) {
                    g_np[k][c] /= t;
                }
            }
        }
        memcpy(g_p, g_np, sizeof g_p);
    }
    for (j = 0; j < rows; j++) {
        for (i = 0; i < cols; i++) {
            double sx = 0.0, sy = 0.0, sp = 0.0;
            int b = 0, di, dj;
            k = j * cols + i;
            if (g_cls[k] < 0) {
                continue;
            }
            for (c = 0; c < 48; c++) {
                double lx = 0.0, ly = 0.0;
                int ln = 0;
                for (dj = -1; dj <= 1; dj++) {
                    for (di = -1; di <= 1; di++) {
                        int x = i + di, y = j + dj, kk = y * cols + x;
                        if (x >= 0 && y >= 0 && x < cols && y < rows && g_cls[kk] == c) {
                            lx += v[kk].dx;
                            ly += v[kk].dy;
                            ln++;
                        }
                    }
                }
                if (ln > 0) { /* only the classes present around the node */
                    sx += g_p[k][c] * (lx / ln);
                    sy += g_p[k][c] * (ly / ln);
                    sp += g_p[k][c];
                }
                if (g_p[k][c] > g_p[k][b]) {
                    b = c;
                }
            }
            ox[k] = sx / sp;
            oy[k] = sy / sp;
            best[k] = b;
        }
    }
}

/* A random vector in Q8 whose angle is at least 1 degree from a sector edge
   and whose length is at least 2 % from a length-class edge (the reference
   classifies by trigonometry, the library by rational slopes). */
static void safe_vector(test_rng_t *r, double step, int32_t *x, int32_t *y)
{
    for (;;) {
        double ang = (double)test_rng_range(r, 0, 35999) / 100.0;
        double len = (double)test_rng_range(r, 0, 7000) / 1000.0 * step;
        double e = ang + 22.5 - 45.0 * (double)(int)((ang + 22.5) / 45.0); /* from an edge */
        double f = len / step - (double)(int)(len / step);
        if (e < 1.0 || e > 44.0) {
            continue;
        }
        if (len > 0.0 && (f < 0.02 || f > 0.98)) {
            continue;
        }
        *x = (int32_t)(len * test_cos(ang * PI / 180.0));
        *y = (int32_t)(len * test_sin(ang * PI / 180.0));
        if (ref_class(*x, *y, step) == ref_class(len * test_cos(ang * PI / 180.0),
                                                 len * test_sin(ang * PI / 180.0), step)) {
            return;
        }
    }
}

static void test_against_double_reference(void)
{
    static double ox[MAXN], oy[MAXN];
    static int best[MAXN];
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 31u);
    for (t = 0; t < TRIALS; t++) {
        const uint16_t cols = (uint16_t)test_rng_range(&r, 1, MAXC);
        const uint16_t rows = (uint16_t)test_rng_range(&r, 1, MAXR);
        const uint16_t iters = (uint16_t)test_rng_range(&r, 1, 40);
        const uint16_t step = (uint16_t)test_rng_range(&r, 150, 600); /* Q8 */
        ssda_relax_config_t cfg = config(iters, 0);
        ssda_relax_grid_t g = grid_of(g_in, cols, rows, 8);
        int32_t bx, by;
        uint32_t k;
        safe_vector(&r, step, &bx, &by);
        for (k = 0; k < (uint32_t)cols * rows; k++) {
            /* a smooth field: the base vector plus a little, and outliers */
            if (test_rng_range(&r, 0, 9) == 0u) {
                safe_vector(&r, step, &g_in[k].dx, &g_in[k].dy);
            } else {
                g_in[k].dx = bx;
                g_in[k].dy = by;
            }
            g_in[k].status = test_rng_range(&r, 0, 15) == 0u ? 2u : 0u;
        }
        cfg.len_step_q8 = step;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, MAXN));
        ref_relax(g_in, cols, rows, step, iters, ox, oy, best);
        for (k = 0; k < (uint32_t)cols * rows; k++) {
            if (g_in[k].status != 0) {
                TEST_ASSERT_EQUAL_UINT8(0, g_out[k].flags);
                TEST_ASSERT_EQUAL_INT32(0, g_out[k].dx_q8);
                continue;
            }
            TEST_ASSERT_TRUE((g_out[k].flags & SSDA_RELAX_VALID) != 0u);
            /* Q15 likelihoods vs double: within 0.5 % of the step */
            TEST_ASSERT_INT32_WITHIN(2 + step / 200, (int32_t)(ox[k] + (ox[k] < 0 ? -0.5 : 0.5)),
                                     g_out[k].dx_q8);
            TEST_ASSERT_INT32_WITHIN(2 + step / 200, (int32_t)(oy[k] + (oy[k] < 0 ? -0.5 : 0.5)),
                                     g_out[k].dy_q8);
            if (g_p[k][best[k]] > 0.01 + g_p[k][g_out[k].cls]) {
                TEST_ASSERT_EQUAL_UINT8(best[k], g_out[k].cls);
            }
            TEST_ASSERT_INT32_WITHIN(330, (int32_t)(g_p[k][g_out[k].cls] * 32768.0), g_out[k].p_q15);
        }
    }
}

/* Sectors centred on 0, 45, ... degrees (y down), lengths by the step. */
static void test_class_layout(void)
{
    static const int32_t dir[8][2] = {{1000, 0},  {707, 707},   {0, 1000},  {-707, 707},
                                      {-1000, 0}, {-707, -707}, {0, -1000}, {707, -707}};
    uint32_t s, l;
    for (s = 0; s < 8u; s++) {
        for (l = 0; l < 6u; l++) {
            ssda_relax_config_t cfg = config(1, 0);
            ssda_relax_grid_t g = grid_of(g_in, 1, 1, 0);
            /* length (l + 0.5) * 4 px with a 4 px step; integer px (frac 0) */
            int32_t len = (int32_t)(4u * l + 2u);
            g_in[0].dx = dir[s][0] * len / 1000;
            g_in[0].dy = dir[s][1] * len / 1000;
            g_in[0].status = 0;
            cfg.len_step_q8 = 4u * 256u;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, 1));
            if (l > 0u) { /* at 2 px the rounded components may leave the sector */
                TEST_ASSERT_EQUAL_UINT8(s + 8u * l, g_out[0].cls);
            } else {
                TEST_ASSERT_EQUAL_UINT8(0, g_out[0].cls / 8u);
            }
            /* a single node has no neighbours: its likelihoods stay 0.53 */
            TEST_ASSERT_EQUAL_UINT16(17352, g_out[0].p_q15);
            TEST_ASSERT_EQUAL_UINT8(SSDA_RELAX_VALID, g_out[0].flags);
        }
    }
}

/* A uniform field with isolated outliers: every outlier is relabelled to the
   field's class and restored to the field vector; with KEEP the others are
   kept exactly. Read in place from ssda_track_vector_t. */
static void test_outliers_repaired_in_track_grid(void)
{
    static ssda_track_vector_t tv[MAXN];
    ssda_relax_grid_t g;
    ssda_relax_config_t cfg = config(40, SSDA_RELAX_KEEP);
    uint32_t k, i, j;
    memset(tv, 0, sizeof tv);
    for (k = 0; k < MAXN; k++) {
        tv[k].dx = 3;
        tv[k].dy = -2;
        tv[k].status = SSDA_TRACK_OK;
    }
    tv[2 * MAXC + 3].dx = -6; /* outliers, apart from each other */
    tv[2 * MAXC + 3].dy = 5;
    tv[6 * MAXC + 8].dx = 0;
    tv[6 * MAXC + 8].dy = 7;
    tv[8 * MAXC + 1].dx = 9;
    tv[8 * MAXC + 1].dy = 9;
    tv[4 * MAXC + 6].status = SSDA_TRACK_EXCLUDED;
    memset(&g, 0, sizeof g);
    g.dx = &tv[0].dx;
    g.dy = &tv[0].dy;
    g.status = &tv[0].status;
    g.stride = sizeof tv[0];
    g.cols = MAXC;
    g.rows = MAXR;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, MAXN));
    for (j = 0; j < MAXR; j++) {
        for (i = 0; i < MAXC; i++) {
            k = j * MAXC + i;
            if (k == 4 * MAXC + 6) {
                TEST_ASSERT_EQUAL_UINT8(0, g_out[k].flags);
                continue;
            }
            /* kept exactly, or restored within 0.1 px */
            TEST_ASSERT_INT32_WITHIN((g_out[k].flags & SSDA_RELAX_CHANGED) ? 26 : 0, 3 * 256,
                                     g_out[k].dx_q8);
            TEST_ASSERT_INT32_WITHIN((g_out[k].flags & SSDA_RELAX_CHANGED) ? 26 : 0, -2 * 256,
                                     g_out[k].dy_q8);
            TEST_ASSERT_EQUAL_UINT8(k == 2 * MAXC + 3 || k == 6 * MAXC + 8 || k == 8 * MAXC + 1
                                        ? SSDA_RELAX_VALID | SSDA_RELAX_CHANGED
                                        : SSDA_RELAX_VALID,
                                    g_out[k].flags);
        }
    }
}

/* SSDA_RELAX_KEEP keeps a vector whose most likely class is its own
   exactly (relax.h), where without it the output is the local class mean:
   a field of one class whose vectors differ by up to 0.1 px. */
static void test_keep_flag_keeps_input(void)
{
    static ssda_relax_vector_t plain[MAXN];
    test_rng_t r;
    ssda_relax_config_t cfg = config(20, 0);
    ssda_relax_grid_t g = grid_of(g_in, MAXC, MAXR, 8);
    uint32_t k, differ = 0;
    test_rng_seed(&r, 77u);
    for (k = 0; k < MAXN; k++) {
        g_in[k].dx = 3 * 256 + (int32_t)test_rng_range(&r, 0, 50) - 25;
        g_in[k].dy = -2 * 256 + (int32_t)test_rng_range(&r, 0, 50) - 25;
        g_in[k].status = 0;
    }
    g_in[3 * MAXC + 4].dx = -5 * 256; /* an outlier */
    cfg.len_step_q8 = 256;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, plain, MAXN));
    cfg.flags = SSDA_RELAX_KEEP;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, MAXN));
    for (k = 0; k < MAXN; k++) {
        TEST_ASSERT_EQUAL_UINT8(plain[k].flags, g_out[k].flags);
        TEST_ASSERT_EQUAL_UINT8(plain[k].cls, g_out[k].cls);
        TEST_ASSERT_EQUAL_UINT16(plain[k].p_q15, g_out[k].p_q15);
        if ((g_out[k].flags & SSDA_RELAX_CHANGED) != 0u) {
            TEST_ASSERT_EQUAL_INT32(plain[k].dx_q8, g_out[k].dx_q8);
            TEST_ASSERT_EQUAL_INT32(plain[k].dy_q8, g_out[k].dy_q8);
        } else {
            TEST_ASSERT_EQUAL_INT32(g_in[k].dx, g_out[k].dx_q8);
            TEST_ASSERT_EQUAL_INT32(g_in[k].dy, g_out[k].dy_q8);
            differ += plain[k].dx_q8 != g_in[k].dx || plain[k].dy_q8 != g_in[k].dy;
        }
    }
    TEST_ASSERT_TRUE((g_out[3 * MAXC + 4].flags & SSDA_RELAX_CHANGED) != 0u);
    TEST_ASSERT_TRUE(differ > MAXN / 2u); /* without KEEP: the class means */
}

/* The automatic length step (len_step_q8 = 0): 2/7 of the mean length of
   the valid vectors, at least 1/4 px (relax.h). Vectors of exact integer
   lengths: the run equals one with that step given, and differs from one
   with a nearby step (so the step decides the classes here). */
static void test_automatic_length_step(void)
{
    static ssda_relax_vector_t given[MAXN];
    static const int32_t dirs[4][2] = {{280, 0}, {168, 224}, {0, -280}, {-224, 168}};
    ssda_relax_config_t cfg = config(3, 0);
    ssda_relax_grid_t g = grid_of(g_in, 6, 5, 8);
    uint32_t k, pass;
    for (pass = 0; pass < 3; pass++) {
        /* lengths 280 Q8 (mean 280: step 80), 50 (step 14: raised to 64),
           and 0 (no length: 64) */
        const int32_t num = pass == 0 ? 1 : (pass == 1 ? 5 : 0), den = pass == 0 ? 1 : 28;
        const uint16_t step = pass == 0 ? 80 : 64, near = pass == 0 ? 70 : 32;
        for (k = 0; k < 30u; k++) {
            g_in[k].dx = dirs[k % 4u][0] * num / den;
            g_in[k].dy = dirs[k % 4u][1] * num / den;
            g_in[k].status = k == 7u ? 1 : 0;
        }
        g_in[7].dx = 100000; /* invalid: not in the mean */
        cfg.len_step_q8 = 0;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, 30));
        cfg.len_step_q8 = step;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, given, 30));
        TEST_ASSERT_EQUAL_MEMORY(given, g_out, 30u * sizeof given[0]);
        if (pass < 2u) {
            cfg.len_step_q8 = near;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, given, 30));
            TEST_ASSERT_TRUE(memcmp(given, g_out, 30u * sizeof given[0]) != 0);
        }
    }
}

/* ---- normalised median test ---- */

static int64_t ref_median(int64_t *v, int n)
{
    int i, j;
    for (i = 0; i < n; i++) {
        for (j = i + 1; j < n; j++) {
            if (v[j] < v[i]) {
                int64_t t = v[i];
                v[i] = v[j];
                v[j] = t;
            }
        }
    }
    if (n % 2 == 1) {
        return v[n / 2];
    }
    /* floor of the mean of the two middle values */
    return (v[n / 2 - 1] + v[n / 2] - (((v[n / 2 - 1] + v[n / 2]) % 2 != 0 &&
                                         v[n / 2 - 1] + v[n / 2] < 0) ? 1 : 0)) / 2;
}

static void test_median_against_reference(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 41u);
    for (t = 0; t < 10u * TRIALS; t++) {
        const uint16_t cols = (uint16_t)test_rng_range(&r, 1, MAXC);
        const uint16_t rows = (uint16_t)test_rng_range(&r, 1, MAXR);
        ssda_relax_median_config_t mc = {0, 0};
        ssda_relax_grid_t g = grid_of(g_in, cols, rows, (uint8_t)test_rng_range(&r, 0, 8));
        const int64_t scale = (int64_t)1 << (8 - g.frac_bits);
        const int64_t thr = t % 3u == 0u ? 512 : 300, eps = t % 2u == 0u ? 26 : 1;
        uint32_t k;
        int i, j;
        mc.threshold_q8 = (uint16_t)thr;
        mc.eps_q8 = (uint16_t)eps;
        for (k = 0; k < (uint32_t)cols * rows; k++) {
            g_in[k].dx = (int32_t)test_rng_range(&r, 0, 40) - 20;
            g_in[k].dy = (int32_t)test_rng_range(&r, 0, 40) - 20;
            if (test_rng_range(&r, 0, 3) != 0u) {
                g_in[k].dx = 5;
                g_in[k].dy = -3 + (int32_t)test_rng_range(&r, 0, 2);
            }
            g_in[k].status = test_rng_range(&r, 0, 9) == 0u ? 1u : 0u;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_median(&g, t == 0u ? NULL : &mc, g_out, MAXN));
        for (j = 0; j < rows; j++) {
            for (i = 0; i < cols; i++) {
                int64_t xs[8], ys[8], rx[8], ry[8], mx, my, x0, y0;
                int n = 0, di, dj, out = 0;
                k = (uint32_t)(j * cols + i);
                if (g_in[k].status != 0) {
                    TEST_ASSERT_EQUAL_UINT8(0, g_out[k].flags);
                    continue;
                }
                x0 = g_in[k].dx * scale;
                y0 = g_in[k].dy * scale;
                for (dj = -1; dj <= 1; dj++) {
                    for (di = -1; di <= 1; di++) {
                        int x = i + di, y = j + dj;
                        if ((di || dj) && x >= 0 && y >= 0 && x < cols && y < rows &&
                            g_in[y * cols + x].status == 0) {
                            xs[n] = g_in[y * cols + x].dx * scale;
                            ys[n] = g_in[y * cols + x].dy * scale;
                            n++;
                        }
                    }
                }
                if (n >= 3) {
                    int m;
                    mx = ref_median(xs, n);
                    my = ref_median(ys, n);
                    for (m = 0; m < n; m++) {
                        rx[m] = xs[m] > mx ? xs[m] - mx : mx - xs[m];
                        ry[m] = ys[m] > my ? ys[m] - my : my - ys[m];
                    }
                    out = (double)(x0 > mx ? x0 - mx : mx - x0) / (ref_median(rx, n) + eps) >
                              thr / 256.0 ||
                          (double)(y0 > my ? y0 - my : my - y0) / (ref_median(ry, n) + eps) >
                              thr / 256.0;
                }
                TEST_ASSERT_EQUAL_UINT8(out ? 3 : 1, g_out[k].flags);
                TEST_ASSERT_EQUAL_INT32(out ? (int32_t)mx : (int32_t)x0, g_out[k].dx_q8);
                TEST_ASSERT_EQUAL_INT32(out ? (int32_t)my : (int32_t)y0, g_out[k].dy_q8);
            }
        }
    }
}

/* ---- errors ---- */

static void test_errors_leave_output_untouched(void)
{
    ssda_relax_config_t cfg = config(3, 0);
    ssda_relax_grid_t g = grid_of(g_in, 4, 3, 0);
    ssda_relax_vector_t poison[12];
    uint32_t k;
    for (k = 0; k < 12u; k++) {
        g_in[k].dx = 1;
        g_in[k].dy = 2;
        g_in[k].status = 0;
    }
    memset(poison, 0x5A, sizeof poison);
    memcpy(g_out, poison, sizeof poison);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_relax_labels(NULL, &cfg, g_out, 12));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_relax_labels(&g, NULL, g_out, 12));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_relax_labels(&g, &cfg, NULL, 12));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_relax_median(&g, NULL, NULL, 12));
    g.dy = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_relax_labels(&g, &cfg, g_out, 12));
    g.dy = &g_in[0].dy;
    cfg.work = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_relax_labels(&g, &cfg, g_out, 12));
    cfg.work = g_work;
    g.cols = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_relax_labels(&g, &cfg, g_out, 12));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_relax_median(&g, NULL, g_out, 12));
    g.cols = 4;
    g.stride = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_labels(&g, &cfg, g_out, 12));
    g.stride = sizeof(vec_t);
    g.frac_bits = 9;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_labels(&g, &cfg, g_out, 12));
    g.frac_bits = 0;
    cfg.iterations = 1001;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_labels(&g, &cfg, g_out, 12));
    cfg.iterations = 3;
    cfg.flags = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_labels(&g, &cfg, g_out, 12));
    cfg.flags = 0;
    g_in[5].dx = 32769; /* beyond 2^23 in Q8 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_labels(&g, &cfg, g_out, 12));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_median(&g, NULL, g_out, 12));
    g_in[5].dx = -32769;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_labels(&g, &cfg, g_out, 12));
    g_in[5].status = 1; /* invalid vectors are not read */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_relax_labels(&g, &cfg, g_out, 11));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_relax_median(&g, NULL, g_out, 11));
    cfg.work_size = SSDA_RELAX_WORK_SIZE(4, 3) - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_relax_labels(&g, &cfg, g_out, 12));
    cfg.work_size = SSDA_RELAX_WORK_SIZE(4, 3);
    cfg.work = (uint8_t *)(void *)g_work + 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_relax_labels(&g, &cfg, g_out, 12));
    TEST_ASSERT_EQUAL_MEMORY(poison, g_out, sizeof poison);
    cfg.work = g_work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, 12));
    TEST_ASSERT_EQUAL_UINT8(0, g_out[5].flags);
    TEST_ASSERT_EQUAL_INT32(256, g_out[0].dx_q8);
    TEST_ASSERT_EQUAL_INT32(512, g_out[0].dy_q8);
    g.rows = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_relax_labels(&g, &cfg, g_out, 12));
    g.rows = 3;
    g.dx = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_relax_median(&g, NULL, g_out, 12));
    g.dx = &g_in[0].dx;
    g_in[5].status = 0;
    g_in[5].dx = 1;
    g_in[5].dy = 40000;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_median(&g, NULL, g_out, 12));
    g_in[5].dy = -40000;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_relax_median(&g, NULL, g_out, 12));
}

/* The median test's defaults, threshold 2 and eps = 0.1 px = 26 Q8
   (relax.h), at the threshold: a vector d Q8 away from 8 equal neighbours
   (residual median 0) has r0* = d / 26 and is an outlier iff that is
   above 2, i.e. d > 52; the same with the defaults given explicitly. */
static void test_median_defaults_at_the_threshold(void)
{
    const ssda_relax_median_config_t explicit_cfg = {512, 26};
    ssda_relax_grid_t g = grid_of(g_in, 3, 3, 8);
    static ssda_relax_vector_t a[9];
    int32_t d;
    uint32_t k;
    for (d = 48; d <= 56; d++) {
        for (k = 0; k < 9u; k++) {
            g_in[k].dx = 700;
            g_in[k].dy = -300;
            g_in[k].status = 0;
        }
        g_in[4].dy = -300 + d;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_median(&g, NULL, a, 9));
        TEST_ASSERT_EQUAL_UINT8(d > 52 ? SSDA_RELAX_VALID | SSDA_RELAX_CHANGED : SSDA_RELAX_VALID,
                                a[4].flags);
        TEST_ASSERT_EQUAL_INT32(d > 52 ? -300 : -300 + d, a[4].dy_q8);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_median(&g, &explicit_cfg, g_out, 9));
        TEST_ASSERT_EQUAL_MEMORY(a, g_out, sizeof a);
    }
}

/* No status array: every vector valid; a grid with no valid vector at all;
   zero-filled median options are the defaults. */
static void test_status_and_defaults(void)
{
    ssda_relax_config_t cfg = config(5, 0);
    ssda_relax_grid_t g = grid_of(g_in, 3, 3, 4);
    ssda_relax_median_config_t zero = {0, 0};
    static ssda_relax_vector_t a[9], b[9];
    uint32_t k;
    for (k = 0; k < 9u; k++) {
        g_in[k].dx = 16 * (int32_t)k; /* Q4: k px */
        g_in[k].dy = -8;
        g_in[k].status = 7; /* ignored without the status array */
    }
    g.status = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, 9));
    for (k = 0; k < 9u; k++) {
        TEST_ASSERT_TRUE((g_out[k].flags & SSDA_RELAX_VALID) != 0u);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_median(&g, &zero, a, 9));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_median(&g, NULL, b, 9));
    TEST_ASSERT_EQUAL_MEMORY(b, a, sizeof a);
    g.status = &g_in[0].status; /* every vector invalid */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_relax_labels(&g, &cfg, g_out, 9));
    for (k = 0; k < 9u; k++) {
        TEST_ASSERT_EQUAL_UINT8(0, g_out[k].flags);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_against_double_reference);
    RUN_TEST(test_class_layout);
    RUN_TEST(test_outliers_repaired_in_track_grid);
    RUN_TEST(test_keep_flag_keeps_input);
    RUN_TEST(test_automatic_length_step);
    RUN_TEST(test_median_defaults_at_the_threshold);
    RUN_TEST(test_median_against_reference);
    RUN_TEST(test_errors_leave_output_untouched);
    RUN_TEST(test_status_and_defaults);
    return UNITY_END();
}
