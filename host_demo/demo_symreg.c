/* demo_symreg.c - part 3 of ssda-demo: registration by closed loops (seed
   001) of a synthetic aerial pair with a known similarity and brightness
   change: the library's edges, loops, Fourier descriptors and symbolic
   registration, scored against the truth at the image corners. */
#include "demo.h"
#include "draw_loops.h"
#include "loops_run.h"
#include "ssda/symreg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BUILDINGS 70
#define SIZE 384u

typedef struct {
    int kind;                      /* 0 block, 1 round tank, 2 L-shaped block */
    double cx, cy, a, b, c, s, grey;
} building_t;

static building_t g_b[BUILDINGS];

static double ground(double x, double y)
{
    return 95.0 + 9.0 * sin(x * 0.09 + y * 0.035) + 7.0 * cos(y * 0.11 - x * 0.045);
}

static double scene_at(double x, double y)
{
    double v = ground(x, y);
    int i;
    for (i = 0; i < BUILDINGS; i++) {
        const building_t *b = &g_b[i];
        const double dx = x - b->cx, dy = y - b->cy;
        const double u = b->c * dx + b->s * dy, w = -b->s * dx + b->c * dy;
        int in;
        if (b->kind == 1) {
            in = u * u + w * w < b->a * b->a;
        } else {
            in = fabs(u) < b->a && fabs(w) < b->b;
            if (b->kind == 2 && u > 0 && w > 0) {
                in = 0; /* an L: one quarter cut away */
            }
        }
        if (in) {
            v = b->grey;
        }
    }
    return v;
}

/* img(x, y) shows the scene at Ainv (x, y), times gain, 3 x 3 supersampled. */
static void render(gray_image_t *img, const double Ainv[6], double gain)
{
    uint32_t x, y;
    int i, j;
    for (y = 0; y < img->height; y++) {
        for (x = 0; x < img->width; x++) {
            double acc = 0, v;
            for (j = -1; j <= 1; j++) {
                for (i = -1; i <= 1; i++) {
                    const double u = x + i / 3.0, w = y + j / 3.0;
                    acc += scene_at(Ainv[0] * u + Ainv[1] * w + Ainv[2],
                                    Ainv[3] * u + Ainv[4] * w + Ainv[5]);
                }
            }
            v = gain * acc / 9.0;
            ((uint8_t *)img->pixels)[(size_t)y * img->stride + x] =
                (uint8_t)(v > 255 ? 255 : v + 0.5);
        }
    }
}

static void make_buildings(void)
{
    uint32_t s = 20240611u;
    int i;
    for (i = 0; i < BUILDINGS; i++) {
        double ang;
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        ang = (s % 1000) / 1000.0 * 3.14159;
        g_b[i].kind = (int)(s % 3u);
        g_b[i].cx = 20 + (s >> 8) % (SIZE - 40);
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        g_b[i].cy = 20 + (s >> 8) % (SIZE - 40);
        g_b[i].a = 5.0 + (s % 7);
        g_b[i].b = 4.0 + ((s >> 4) % 6);
        g_b[i].c = cos(ang);
        g_b[i].s = sin(ang);
        g_b[i].grey = 150 + (s >> 12) % 80; /* roofs brighter than the ground */
    }
}

/* The pair's truth: REF -> MOV turns 30 degrees (+x towards +y), scales
   1.15 about the centre and shifts (9, -6) px; MOV is 30 % darker. */
#define TRUE_DEG 30.0
#define TRUE_SCALE 1.15
#define TRUE_GAIN 0.7

/* Everything one run holds. */
typedef struct {
    double A[6], Ainv[6]; /* REF -> MOV and back */
    gray_image_t ref, mov;
    loops_run_t lr, lm;
    ssda_symreg_result_t res;
    ssda_symreg_pair_t *pairs;
    double worst; /* corner error, px */
} run_t;

static void truth(run_t *r)
{
    const double h = SIZE / 2.0, sc = TRUE_SCALE;
    const double co = cos(TRUE_DEG * 3.14159265358979 / 180),
                 si = sin(TRUE_DEG * 3.14159265358979 / 180);
    double *A = r->A, *Ainv = r->Ainv;
    A[0] = sc * co;
    A[1] = -sc * si;
    A[3] = sc * si;
    A[4] = sc * co;
    A[2] = h + 9 - (A[0] * h + A[1] * h);
    A[5] = h - 6 - (A[3] * h + A[4] * h);
    Ainv[0] = co / sc;
    Ainv[1] = si / sc;
    Ainv[3] = -si / sc;
    Ainv[4] = co / sc;
    Ainv[2] = -(Ainv[0] * A[2] + Ainv[1] * A[5]);
    Ainv[5] = -(Ainv[3] * A[2] + Ainv[4] * A[5]);
}

/* Render and write the pair. Returns 0 or -1 (printed). */
static int make_pair(const demo_ctx_t *c, const char *label_prefix, run_t *r)
{
    const double id[6] = {1, 0, 0, 0, 1, 0};
    char p1[1024], p2[1024], e[512];
    make_buildings();
    if (gray_image_alloc(&r->ref, SIZE, SIZE, 8) != 0 ||
        gray_image_alloc(&r->mov, SIZE, SIZE, 8) != 0) {
        fprintf(stderr, "ssda-demo: out of memory\n");
        return -1;
    }
    render(&r->ref, id, 1.0);
    render(&r->mov, r->Ainv, TRUE_GAIN);
    demo_path(c, "aerial_1.png", p1, sizeof p1);
    demo_path(c, "aerial_2.png", p2, sizeof p2);
    if (png_write_gray(p1, &r->ref, e, sizeof e) != 0 ||
        png_write_gray(p2, &r->mov, e, sizeof e) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", e);
        return -1;
    }
    if (!c->quiet) {
        printf("   %s%s and %s:\n"
               "            %u x %u synthetic roofs (blocks, L-blocks, tanks) on textured ground;\n"
               "            the second is the first turned 30 deg, scaled 1.15, shifted (9, -6) px\n"
               "            and 30 %% darker\n",
               label_prefix, p1, p2, SIZE, SIZE);
    }
    return 0;
}

/* Loops of both images, the registration, its worst corner error against
   the truth. Returns 0 or -1 (printed). */
static int register_pair(run_t *r)
{
    loops_run_cfg_t cfg;
    ssda_symreg_affine_t *t = &r->res.affine;
    void *work;
    size_t wsize;
    char e[512];
    int k, rc;
    memset(&cfg, 0, sizeof cfg);
    if (loops_run(&r->ref, &cfg, &r->lr, e, sizeof e) != 0 ||
        loops_run(&r->mov, &cfg, &r->lm, e, sizeof e) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", e);
        return -1;
    }
    wsize = SSDA_SYMREG_WORK_SIZE(r->lr.n, r->lm.n, SSDA_SYMREG_DEFAULT_NUCLEI);
    work = malloc(wsize);
    r->pairs = calloc(r->lr.n + 1u, sizeof *r->pairs);
    rc = work == NULL || r->pairs == NULL ||
                 ssda_symreg(r->lr.loops, r->lr.fds, r->lr.n, r->lm.loops, r->lm.fds, r->lm.n,
                             NULL, work, wsize, r->pairs, r->lr.n, &r->res) != SSDA_OK
             ? -1
             : 0;
    free(work);
    if (rc != 0) {
        fprintf(stderr, "ssda-demo: registration failed\n");
        return -1;
    }
    r->worst = 0;
    for (k = 0; k < 4; k++) {
        const double x = (k & 1) ? SIZE - 1.0 : 0.0, y = (k & 2) ? SIZE - 1.0 : 0.0;
        const double *A = r->A;
        const double ex = t->a_q16 / 65536.0 * x + t->b_q16 / 65536.0 * y + t->c_q8 / 256.0 -
                          (A[0] * x + A[1] * y + A[2]);
        const double ey = t->d_q16 / 65536.0 * x + t->e_q16 / 65536.0 * y + t->f_q8 / 256.0 -
                          (A[3] * x + A[4] * y + A[5]);
        r->worst = fmax(r->worst, sqrt(ex * ex + ey * ey));
    }
    return 0;
}

static void report(const run_t *r)
{
    const loops_run_t *lr = &r->lr;
    printf("   loops: %u in the first, %u in the second (edges %u px thinned, %u T, %u I, %u V "
           "gaps closed)\n",
           lr->n, r->lm.n, lr->edge_stats.thinned, lr->edge_stats.closed_t,
           lr->edge_stats.closed_i, lr->edge_stats.closed_v);
    printf("   matched pairs: %u of %u nuclei tried; centroid RMS %.2f px\n", r->res.pairs,
           r->res.nuclei, r->res.rms_q8 / 256.0);
    printf("   transform      scale %.4f (true %.4f), rotation %.3f deg (true %.3f)\n",
           r->res.scale_q16 / 65536.0, TRUE_SCALE, r->res.rotation * (360.0 / 4294967296.0),
           TRUE_DEG);
    printf("   corners of the first image land within %.2f px of the truth%s\n", r->worst,
           r->worst < 2.0 ? "" : "  <- worse than 2 px");
    printf("   library buffers: %.0f KB for the first image (its edge map: %.0f KB, 2 bytes "
           "per pixel)\n",
           lr->lib_bytes / 1024.0, SSDA_EDGE_MAP_SIZE(SIZE, SIZE) / 1024.0);
}

/* Both images' loops, the pairs joined. Returns 0 or -1 (printed). */
static int overlay(const demo_ctx_t *c, const run_t *r)
{
    draw_loops_side_t sr = {&r->ref, r->lr.loops, r->lr.n, r->lr.samples, "first: loops"};
    draw_loops_side_t sm = {&r->mov, r->lm.loops, r->lm.n, r->lm.samples, "second: loops"};
    draw_loops_pair_t *dp = calloc(r->res.pairs + 1u, sizeof *dp);
    char sub[256], po[1024], e[512];
    uint32_t i;
    int rc;
    demo_path(c, "symreg_overlay.png", po, sizeof po);
    for (i = 0; dp != NULL && i < r->res.pairs; i++) {
        dp[i].ref = r->pairs[i].ref;
        dp[i].mov = r->pairs[i].mov;
    }
    snprintf(sub, sizeof sub,
             "%u pairs; scale %.4f, rotation %.2f deg; corners within %.2f px of the truth",
             r->res.pairs, r->res.scale_q16 / 65536.0, r->res.rotation * (360.0 / 4294967296.0),
             r->worst);
    rc = dp == NULL || draw_loops_png(po, &sr, &sm, dp, r->res.pairs,
                                      "Registration by closed loops (seed 001)", sub, e,
                                      sizeof e) != 0
             ? -1
             : 0;
    if (rc != 0) {
        fprintf(stderr, "ssda-demo: %s\n", dp == NULL ? "out of memory" : e);
    } else {
        printf("   wrote %s\n", po);
    }
    free(dp);
    return rc;
}

int demo_symreg(const demo_ctx_t *c, const char *label_prefix)
{
    run_t r;
    int rc = -1;
    memset(&r, 0, sizeof r);
    truth(&r);
    if (make_pair(c, label_prefix, &r) == 0 && register_pair(&r) == 0) {
        if (!c->quiet) {
            report(&r);
        }
        if (overlay(c, &r) == 0) {
            rc = r.res.pairs >= 3 && r.worst < 2.0 ? 0 : -1;
            if (rc != 0) {
                fprintf(stderr, "ssda-demo: the registration missed the known transform\n");
            }
        }
    }
    free(r.pairs);
    loops_run_free(&r.lr);
    loops_run_free(&r.lm);
    gray_image_free(&r.ref);
    gray_image_free(&r.mov);
    return rc;
}
