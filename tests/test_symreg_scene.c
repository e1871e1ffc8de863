/*
 * test_symreg_scene.c - the whole chain of seed 001 (edges, loops,
 * descriptors, registration) on rendered scenes: bright and dark shapes on
 * a textured ground, REF and MOV drawn from the same geometry through a
 * known similarity with a brightness gain (MOV's pixel (u, v) shows REF's
 * point A^-1 (u, v)), 3 x 3 supersampled (1 sample under SSDA_TEST_SMALL).
 * Checked here: the maps' and loops' invariants on every scene, and that a
 * registration, when one is returned, maps REF's corners within 2 px of the
 * truth in most scenes.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/edge.h"
#include "ssda/loops.h"
#include "ssda/fourier.h"
#include "ssda/symreg.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef SSDA_TEST_SMALL
#define S 160u
#define SCENES 2u
#define SUB 1 /* one sample per pixel: soft float under QEMU is slow */
#else
#define S 160u
#define SCENES 10u
#define SUB 3
#endif
#define MAXL 64u
#define NS 64u
#define SHAPES 24u

typedef struct {
    int kind;           /* 0 rectangle, 1 ellipse */
    double cx, cy, a, b, c, s; /* centre, half sizes, cos and sin of its angle */
    double grey;
} shape_t;

static shape_t g_shapes[SHAPES];
static uint8_t g_img[2][S * S];
static uint16_t g_map[S * S];
static uint8_t g_ring[SSDA_EDGE_RING_SIZE(S)];
static uint32_t g_work[S * S / 4u];
static ssda_loop_t g_loops[2][MAXL];
static ssda_point_q8_t g_pts[2][MAXL * NS];
static ssda_fd_t g_fd[2][MAXL];
static ssda_symreg_pair_t g_pairs[MAXL];

static double frand(test_rng_t *r, double lo, double hi)
{
    return lo + (hi - lo) * (double)test_rng_next(r) / 4294967296.0;
}

/* a triangle wave of period 1 in [-1, 1]: a cheap smooth-enough texture */
static double tri(double t)
{
    double f = t - (double)(long)t;
    f = f < 0.0 ? f + 1.0 : f;
    return f < 0.5 ? 4.0 * f - 1.0 : 3.0 - 4.0 * f;
}

static double value_at(double x, double y)
{
    double v = 90.0 + 10.0 * tri(x * 0.017 + y * 0.006) + 8.0 * tri(y * 0.021 - x * 0.008);
    uint32_t i;
    for (i = 0u; i < SHAPES; i++) {
        const shape_t *s = &g_shapes[i];
        const double dx = x - s->cx, dy = y - s->cy;
        const double u = s->c * dx + s->s * dy, w = -s->s * dx + s->c * dy;
        const int in = s->kind == 0 ? (u > -s->a && u < s->a && w > -s->b && w < s->b)
                                    : (u * u / (s->a * s->a) + w * w / (s->b * s->b) < 1.0);
        if (in) {
            v = s->grey;
        }
    }
    return v;
}

/* MOV pixel (u, v) shows REF point Ainv (u, v); gain on top. */
static void render(uint8_t *img, const double *Ainv, double gain)
{
    uint32_t x, y;
    int i, j;
    for (y = 0u; y < S; y++) {
        for (x = 0u; x < S; x++) {
            double acc = 0.0, v;
            for (j = 0; j < SUB; j++) {
                for (i = 0; i < SUB; i++) {
                    const double u = x + (i + 0.5) / SUB - 0.5, w = y + (j + 0.5) / SUB - 0.5;
                    acc += value_at(Ainv[0] * u + Ainv[1] * w + Ainv[2],
                                    Ainv[3] * u + Ainv[4] * w + Ainv[5]);
                }
            }
            v = gain * acc / (SUB * SUB);
            img[y * S + x] = (uint8_t)(v > 255.0 ? 255.0 : v + 0.5);
        }
    }
}

static uint32_t loops_of(uint32_t side, ssda_edge_stats_t *es, ssda_loops_stats_t *ls)
{
    ssda_view_t v;
    ssda_loops_config_t lc;
    uint32_t n, i, x, y;
    memset(&lc, 0, sizeof lc);
    lc.samples = NS;
    lc.grey_min = SSDA_LOOPS_GREY_ANY;
    lc.area_min = 30u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img[side], S, S, S, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_detect(&v, 0u, g_map, sizeof g_map, g_ring,
                                                    sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, S, S, NULL, g_work, sizeof g_work, es));
    for (y = 0u; y < S; y++) { /* no edge in the two outermost rows and columns */
        for (x = 0u; x < S; x++) {
            if (x < 2u || y < 2u || x + 2u >= S || y + 2u >= S) {
                TEST_ASSERT_EQUAL_HEX16(0, g_map[y * S + x] & SSDA_EDGE_ON);
            }
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_find(g_map, &v, &lc, g_work, sizeof g_work,
                                                   g_loops[side], MAXL, g_pts[side],
                                                   sizeof g_pts[side], &n, ls));
    for (i = 0u; i < S * S; i++) {
        TEST_ASSERT_EQUAL_HEX16(0, g_map[i] & 0xF800u);
        if ((g_map[i] & SSDA_EDGE_ON) != 0u) { /* only cycles and branch points remain */
            const int c = ssda_edge_classify(g_map, S, S, (uint16_t)(i % S), (uint16_t)(i / S));
            TEST_ASSERT_TRUE(c == SSDA_EDGE_CONN || c == SSDA_EDGE_BRANCH);
        }
    }
    for (i = 0u; i < n; i++) {
        const ssda_loop_t *l = &g_loops[side][i];
        TEST_ASSERT_TRUE(l->area >= 30u && l->area <= 1000u);
        TEST_ASSERT_TRUE(l->cx_q8 >= l->x0 * 256 && l->cx_q8 <= l->x1 * 256);
        TEST_ASSERT_TRUE(l->cy_q8 >= l->y0 * 256 && l->cy_q8 <= l->y1 * 256);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(l->contour, NS, 10u, &g_fd[side][i]));
    }
    return n;
}

static void test_scenes_register(void)
{
    test_rng_t r;
    uint32_t scene, ok = 0u, registered = 0u, i;
    test_rng_seed(&r, 31u);
    for (scene = 0u; scene < SCENES; scene++) {
        const double s = frand(&r, 0.8, 1.25), phi = frand(&r, 0.0, 2.0 * TEST_PI);
        const double gain = frand(&r, 0.6, 1.4);
        const double c = test_cos(phi), sn = test_sin(phi);
        /* A: REF -> MOV about the centre; Ainv: MOV -> REF */
        const double h = S / 2.0, tx = frand(&r, -6, 6), ty = frand(&r, -6, 6);
        const double A[6] = {s * c, -s * sn, h + tx - s * (c * h - sn * h),
                             s * sn, s * c, h + ty - s * (sn * h + c * h)};
        const double id[6] = {1, 0, 0, 0, 1, 0};
        double Ainv[6];
        ssda_edge_stats_t es;
        ssda_loops_stats_t ls;
        ssda_symreg_result_t res;
        uint32_t nr, nm;
        Ainv[0] = c / s;
        Ainv[1] = sn / s;
        Ainv[3] = -sn / s;
        Ainv[4] = c / s;
        Ainv[2] = -(Ainv[0] * A[2] + Ainv[1] * A[5]);
        Ainv[5] = -(Ainv[3] * A[2] + Ainv[4] * A[5]);
        for (i = 0u; i < SHAPES; i++) {
            shape_t *sh = &g_shapes[i];
            const double ang = frand(&r, 0.0, TEST_PI);
            sh->kind = (int)(test_rng_next(&r) & 1u);
            sh->cx = frand(&r, 12.0, S - 12.0);
            sh->cy = frand(&r, 12.0, S - 12.0);
            sh->a = frand(&r, 4.0, 9.0);
            sh->b = frand(&r, 3.0, 8.0);
            sh->c = test_cos(ang);
            sh->s = test_sin(ang);
            sh->grey = (test_rng_next(&r) & 1u) != 0u ? frand(&r, 150, 220) : frand(&r, 20, 45);
        }
        render(g_img[0], id, 1.0);
        render(g_img[1], Ainv, gain);
        nr = loops_of(0u, &es, &ls);
        nm = loops_of(1u, &es, &ls);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(g_loops[0], g_fd[0], nr, g_loops[1], g_fd[1],
                                                   nm, NULL, g_work, sizeof g_work, g_pairs,
                                                   MAXL, &res));
        if (res.pairs > 0u) {
            double worst = 0.0;
            uint32_t k;
            registered++;
            TEST_ASSERT_TRUE(res.pairs >= 3u);
            for (k = 0u; k < 4u; k++) { /* REF's corners */
                const double x = (k & 1u) ? S - 1.0 : 0.0, y = (k & 2u) ? S - 1.0 : 0.0;
                const double ux = res.affine.a_q16 / 65536.0 * x + res.affine.b_q16 / 65536.0 * y +
                                  res.affine.c_q8 / 256.0;
                const double uy = res.affine.d_q16 / 65536.0 * x + res.affine.e_q16 / 65536.0 * y +
                                  res.affine.f_q8 / 256.0;
                const double ex = ux - (A[0] * x + A[1] * y + A[2]);
                const double ey = uy - (A[3] * x + A[4] * y + A[5]);
                const double e = test_sqrt(ex * ex + ey * ey);
                worst = e > worst ? e : worst;
            }
            ok += worst < 2.0 ? 1u : 0u;
            for (k = 0u; k < res.pairs; k++) {
                TEST_ASSERT_TRUE(g_pairs[k].resid_q8 <= 768u); /* resid_max 3 px */
                TEST_ASSERT_TRUE(g_pairs[k].e2_fixed_q16 <= 9830u); /* e2_final 0.15 */
            }
        }
    }
    /* most scenes register, and a registration is right */
    printf("%u scenes, %u registered, %u within 2 px\n", (unsigned)SCENES, (unsigned)registered,
           (unsigned)ok);
    TEST_ASSERT_TRUE(registered * 3u >= SCENES * 2u);
    TEST_ASSERT_TRUE(ok * 10u >= registered * 8u);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_scenes_register);
    return UNITY_END();
}
