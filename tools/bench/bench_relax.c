/*
 * bench_relax.c - ssda-bench-relax: cleaning vector fields with known motion
 * by relaxation labelling (seed 003, ssda_relax_labels) and by the
 * normalised median test (ssda_relax_median). Not a test; prints Markdown
 * (docs/correlation.md).
 *
 *   ssda-bench-relax [--trials N] [--piv FIELD.txt] [--warp IMAGE.png]...
 *
 * Fields (truth known):
 *   uniform, rotation, vortex  synthetic 24 x 20 grids (vortex: a Rankine-
 *                              like core, the hard case for both methods);
 *   --piv FIELD.txt            the OpenPIV reference field of the PIV
 *                              Challenge vortex pair (x y u v mask; masked
 *                              vectors left out), taken as the truth;
 *   --warp IMAGE.png           real matching: IMAGE moved by a smooth known
 *                              field (2 to 5 px), tracked by the correlation
 *                              search (16 x 16 windows in 32 x 32 areas,
 *                              step 16): its own errors, plus the injected.
 * Each field gets noise of +-0.2 px and 5, 10 or 20 % injected outliers
 * (random vectors in +-8 px, at least 2 px from the truth). A vector is
 * correct when within 1 px of the truth (Euclidean). Reported: the share of
 * the vectors that were wrong before and still are after ("outliers
 * left"), and of those correct before that still are ("correct kept"),
 * summed over the trials.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "png_io.h"
#include "ssda/ncc.h"
#include "ssda/relax.h"

#define MAXN 4096

typedef struct {
    int32_t dx, dy; /* Q8 px */
    uint8_t status;
} vec_t;

typedef struct {
    int cols, rows;
    double tx[MAXN], ty[MAXN]; /* truth, px */
    int valid[MAXN];
    vec_t v[MAXN];             /* measured / injected, Q8 */
} field_t;

static uint32_t g_rs = 1u;
static double urand(void)
{
    g_rs ^= g_rs << 13;
    g_rs ^= g_rs >> 17;
    g_rs ^= g_rs << 5;
    return (double)(g_rs % 1000000u) / 1e6;
}

static void synthetic(field_t *f, int kind)
{
    int k;
    f->cols = 24;
    f->rows = 20;
    for (k = 0; k < f->cols * f->rows; k++) {
        double x = k % f->cols - f->cols / 2.0, y = k / f->cols - f->rows / 2.0, r2;
        if (kind == 0) {
            f->tx[k] = 3.2;
            f->ty[k] = -1.7;
        } else if (kind == 1) {
            f->tx[k] = 1.0 - 0.25 * y;
            f->ty[k] = 0.5 + 0.25 * x;
        } else {
            r2 = x * x + y * y + 4.0;
            f->tx[k] = -y * 30.0 / r2;
            f->ty[k] = x * 30.0 / r2;
        }
        f->valid[k] = 1;
    }
}

static int piv_field(field_t *f, const char *path)
{
    FILE *fp = fopen(path, "r");
    char line[256];
    int n = 0;
    if (fp == NULL) {
        perror(path);
        return -1;
    }
    f->cols = 20;
    f->rows = 15;
    while (fgets(line, sizeof line, fp) != NULL && n < 300) {
        double x, y, u, v, m;
        if (line[0] == '#' || sscanf(line, "%lf %lf %lf %lf %lf", &x, &y, &u, &v, &m) != 5) {
            continue;
        }
        /* OpenPIV rows run from y = 468 (image top) down; v > 0 points up */
        f->tx[n] = u;
        f->ty[n] = -v;
        f->valid[n] = m == 0.0;
        n++;
    }
    fclose(fp);
    return n == 300 ? 0 : -1;
}

/* The known motion of the warp at (x, y) of a w x h image, px. */
static void warp_at(double x, double y, int w, int h, double *u, double *v)
{
    *u = 3.0 + 2.0 * sin(2.0 * M_PI * y / h);
    *v = -2.0 + 2.5 * cos(2.0 * M_PI * x / w);
}

/* IMAGE (8-bit) moved by warp_at, bilinear; then tracked by ncc. */
static int warp_field(field_t *f, const char *path)
{
    gray_image_t img = {0};
    char err[256];
    uint8_t *next;
    uint64_t work[SSDA_NCC_WORK_SIZE(32, 16, 16) / 8 + 1];
    int w, h, x, y, k = 0;
    ssda_view_t a, b;
    if (png_read_gray(path, PNG_GRAY_8, &img, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    w = (int)img.width;
    h = (int)img.height;
    next = malloc((size_t)w * (size_t)h);
    if (next == NULL) {
        return -1;
    }
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const uint8_t *p = img.pixels;
            double u, v, sx, sy, fa, fb;
            int i, j;
            warp_at(x, y, w, h, &u, &v);
            sx = x - u;
            sy = y - v;
            i = (int)floor(sx);
            j = (int)floor(sy);
            fa = sx - i;
            fb = sy - j;
            if (i < 0 || j < 0 || i + 1 >= w || j + 1 >= h) {
                next[y * w + x] = 128;
                continue;
            }
            next[y * w + x] = (uint8_t)((1 - fa) * (1 - fb) * p[j * w + i] +
                                        fa * (1 - fb) * p[j * w + i + 1] +
                                        (1 - fa) * fb * p[(j + 1) * w + i] +
                                        fa * fb * p[(j + 1) * w + i + 1] + 0.5);
        }
    }
    (void)ssda_view_init(&a, img.pixels, (uint16_t)w, (uint16_t)h, (uint32_t)w, SSDA_PIX_U8);
    (void)ssda_view_init(&b, next, (uint16_t)w, (uint16_t)h, (uint32_t)w, SSDA_PIX_U8);
    f->cols = (w - 32) / 16;
    f->rows = (h - 32) / 16;
    for (y = 0; y < f->rows; y++) {
        for (x = 0; x < f->cols; x++, k++) {
            int wx = 16 + x * 16, wy = 16 + y * 16;
            ssda_view_t area, win;
            ssda_ncc_config_t c;
            ssda_ncc_result_t r;
            memset(&c, 0, sizeof c);
            c.work = work;
            c.work_size = sizeof work;
            (void)ssda_view_roi(&area, &a, (uint16_t)(wx - 8), (uint16_t)(wy - 8), 32, 32);
            (void)ssda_view_roi(&win, &b, (uint16_t)wx, (uint16_t)wy, 16, 16);
            warp_at(wx + 8.0, wy + 8.0, w, h, &f->tx[k], &f->ty[k]);
            f->valid[k] = ssda_ncc_match(&area, &win, &c, &r) == SSDA_OK &&
                          (r.flags & SSDA_NCC_FLAT_WINDOW) == 0u;
            f->v[k].dx = (8 - (int32_t)r.x) * 256;
            f->v[k].dy = (8 - (int32_t)r.y) * 256;
        }
    }
    free(next);
    gray_image_free(&img);
    return 0;
}

/* Noise (synthetic and PIV truth) and injected outliers. */
static void perturb(field_t *f, double frac, int measured)
{
    int k;
    for (k = 0; k < f->cols * f->rows; k++) {
        if (!measured) {
            f->v[k].dx = (int32_t)lround((f->tx[k] + (urand() - 0.5) * 0.4) * 256.0);
            f->v[k].dy = (int32_t)lround((f->ty[k] + (urand() - 0.5) * 0.4) * 256.0);
        }
        f->v[k].status = f->valid[k] ? 0u : 1u;
        if (f->valid[k] && urand() < frac) {
            double ox, oy;
            do {
                ox = (urand() - 0.5) * 16.0;
                oy = (urand() - 0.5) * 16.0;
            } while (hypot(ox - f->tx[k], oy - f->ty[k]) < 2.0);
            f->v[k].dx = (int32_t)lround(ox * 256.0);
            f->v[k].dy = (int32_t)lround(oy * 256.0);
        }
    }
}

enum { M_MED15, M_MED2, M_MED3, M_R20, M_R50, M_R80, M_R50K, M_R80K, M_COUNT };
static const char *const k_names[M_COUNT] = {
    "median test, threshold 1.5", "**median test, threshold 2 (W&S)**", "median test, threshold 3",
    "relaxation, 20 iterations", "**relaxation, 50 iterations (default)**",
    "relaxation, 80 iterations", "relaxation, 50 iterations, KEEP", "relaxation, 80 iterations, KEEP"};

typedef struct {
    long wrong, left, right, kept;
} tally_t;

static int run_method(field_t *f, int m, ssda_relax_vector_t *out)
{
    static uint32_t work[SSDA_RELAX_WORK_SIZE(64, 64) / 4];
    ssda_relax_grid_t g;
    memset(&g, 0, sizeof g);
    g.dx = &f->v[0].dx;
    g.dy = &f->v[0].dy;
    g.status = &f->v[0].status;
    g.stride = sizeof f->v[0];
    g.cols = (uint16_t)f->cols;
    g.rows = (uint16_t)f->rows;
    g.frac_bits = 8;
    if (m <= M_MED3) {
        ssda_relax_median_config_t mc = {(uint16_t)(m == M_MED15 ? 384 : m == M_MED2 ? 512 : 768),
                                         0};
        return ssda_relax_median(&g, &mc, out, MAXN);
    } else {
        ssda_relax_config_t c;
        memset(&c, 0, sizeof c);
        c.iterations = (uint16_t)(m == M_R20 ? 20 : (m == M_R50 || m == M_R50K) ? 50 : 80);
        c.flags = (m == M_R50K || m == M_R80K) ? SSDA_RELAX_KEEP : 0u;
        c.work = work;
        c.work_size = sizeof work;
        return ssda_relax_labels(&g, &c, out, MAXN);
    }
}

static void score(const field_t *f, const ssda_relax_vector_t *out, tally_t *t)
{
    int k;
    for (k = 0; k < f->cols * f->rows; k++) {
        double e0, e1;
        if (!f->valid[k]) {
            continue;
        }
        e0 = hypot(f->v[k].dx / 256.0 - f->tx[k], f->v[k].dy / 256.0 - f->ty[k]);
        e1 = hypot(out[k].dx_q8 / 256.0 - f->tx[k], out[k].dy_q8 / 256.0 - f->ty[k]);
        if (e0 > 1.0) {
            t->wrong++;
            t->left += e1 > 1.0;
        } else {
            t->right++;
            t->kept += e1 <= 1.0;
        }
    }
}

static void evaluate(const char *name, field_t *f, int measured, int trials)
{
    static const double fracs[] = {0.0, 0.05, 0.10, 0.20};
    static ssda_relax_vector_t out[MAXN];
    static vec_t keep[MAXN];
    size_t fi;
    int m, t;
    memcpy(keep, f->v, sizeof keep);
    for (fi = 0; fi < sizeof fracs / sizeof fracs[0]; fi++) {
        tally_t tal[M_COUNT];
        if (fracs[fi] == 0.0 && !measured) {
            continue; /* nothing to clean */
        }
        memset(tal, 0, sizeof tal);
        for (t = 0; t < trials; t++) {
            g_rs = 12345u + (uint32_t)t * 7919u + (uint32_t)fi * 31u;
            memcpy(f->v, keep, sizeof keep);
            perturb(f, fracs[fi], measured);
            for (m = 0; m < M_COUNT; m++) {
                if (run_method(f, m, out) != SSDA_OK) {
                    fprintf(stderr, "bench-relax: %s failed\n", k_names[m]);
                    exit(1);
                }
                score(f, out, &tal[m]);
            }
        }
        for (m = 0; m < M_COUNT; m++) {
            printf("| %s | %.0f %% | %s | %ld | %.1f %% | %.1f %% |\n", name, fracs[fi] * 100.0,
                   k_names[m], tal[m].wrong, tal[m].wrong ? 100.0 * tal[m].left / tal[m].wrong : 0.0,
                   tal[m].right ? 100.0 * tal[m].kept / tal[m].right : 0.0);
        }
        fflush(stdout);
    }
    memcpy(f->v, keep, sizeof keep);
}

int main(int argc, char **argv)
{
    static field_t f;
    static const char *const kinds[] = {"synthetic uniform", "synthetic rotation",
                                        "synthetic vortex"};
    int trials = 10, i, k;
    printf("| field | injected | method | wrong before | outliers left | correct kept |\n");
    printf("|---|---:|---|---:|---:|---:|\n");
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--trials") && i + 1 < argc) {
            trials = atoi(argv[++i]);
        }
    }
    for (k = 0; k < 3; k++) {
        synthetic(&f, k);
        evaluate(kinds[k], &f, 0, trials);
    }
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--piv") && i + 1 < argc) {
            if (piv_field(&f, argv[++i]) != 0) {
                return 1;
            }
            evaluate("PIV vortex, OpenPIV field", &f, 0, trials);
        } else if (!strcmp(argv[i], "--warp") && i + 1 < argc) {
            const char *p = argv[++i], *s = strrchr(p, '/');
            char name[128];
            if (warp_field(&f, p) != 0) {
                return 1;
            }
            snprintf(name, sizeof name, "%s warped, tracked by rho", s ? s + 1 : p);
            evaluate(name, &f, 1, trials);
        } else if (!strcmp(argv[i], "--trials")) {
            i++;
        } else {
            fprintf(stderr, "usage: ssda-bench-relax [--trials N] [--piv FIELD.txt] "
                            "[--warp IMAGE.png]...\n");
            return 2;
        }
    }
    return 0;
}
