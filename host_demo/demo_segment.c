/* demo_segment.c - part 3 of ssda-demo: colour segmentation (seed 004) on a
   synthetic aerial scene with known regions, through the library's K-L
   transform, Gaussian-mixture fits, look-up table and isolated-point
   removal; the labels are scored against the truth (adjusted Rand index). */
#include "demo.h"
#include "draw_seg.h"
#include "atomic_file.h"
#include "ssda/kl.h"
#include "ssda/mixture.h"
#include "ssda/region.h"

#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

#define SW 384u
#define SH 256u
#define NCLASS 5u

static const char *const k_class[NCLASS] = {"deep water", "shallow water", "vegetation",
                                            "bare soil", "cloud"};
static const double k_rgb[NCLASS][3] = {
    {20, 40, 90}, {40, 110, 140}, {50, 110, 40}, {160, 130, 90}, {235, 235, 235}};

static uint32_t g_rng = 0x5EEDu;

static double uniform(void)
{
    g_rng ^= g_rng << 13;
    g_rng ^= g_rng >> 17;
    g_rng ^= g_rng << 5;
    return ((double)g_rng + 0.5) / 4294967296.0;
}

static double normal(void)
{
    return sqrt(-2.0 * log(uniform())) * cos(6.283185307179586 * uniform());
}

/* The class of pixel (x, y): water on the left behind a wavy coast with a
   shallow strip, land on the right with vegetation patches, a cloud. */
static uint8_t scene_class(uint32_t x, uint32_t y)
{
    const double coast = 150.0 + 25.0 * sin(y / 23.0) + 10.0 * sin(y / 7.0);
    const double cx = x - 300.0, cy = y - 70.0;
    if (cx * cx + cy * cy < 38.0 * 38.0) {
        return 5;
    }
    if (x < coast - 30.0) {
        return 1;
    }
    if (x < coast) {
        return 2;
    }
    if (sin(x / 19.0) * cos(y / 17.0) > 0.25) {
        return 3;
    }
    return 4;
}

static int write_rgb(const char *path, const uint8_t *rgb)
{
    atomic_file_t af;
    png_structp png;
    png_infop info;
    uint32_t y;
    if (atomic_file_open(&af, path) != 0) {
        return -1;
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png != NULL ? png_create_info_struct(png) : NULL;
    if (info == NULL || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info != NULL ? &info : NULL);
        atomic_file_abort(&af);
        return -1;
    }
    png_init_io(png, af.fp);
    png_set_IHDR(png, info, SW, SH, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < SH; y++) {
        png_write_row(png, (png_const_bytep)(rgb + (size_t)y * SW * 3u));
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return atomic_file_commit(&af);
}

/* Adjusted Rand index of labels a against b over n pixels (labels < 256). */
static double ari(const uint8_t *a, const uint8_t *b, size_t n)
{
    static double t[256][256];
    double ra[256] = {0}, rb[256] = {0}, sij = 0, sa = 0, sb = 0, e, top;
    size_t i;
    memset(t, 0, sizeof t);
    for (i = 0; i < n; i++) {
        t[a[i]][b[i]] += 1.0;
    }
    for (i = 0; i < 256u * 256u; i++) {
        const double v = t[i / 256u][i % 256u];
        sij += v * (v - 1) / 2;
        ra[i / 256u] += v;
        rb[i % 256u] += v;
    }
    for (i = 0; i < 256u; i++) {
        sa += ra[i] * (ra[i] - 1) / 2;
        sb += rb[i] * (rb[i] - 1) / 2;
    }
    e = sa * sb / ((double)n * (n - 1) / 2);
    top = (sa + sb) / 2;
    return (sij - e) / (top - e);
}

typedef struct {
    uint16_t z[SW * SH];
    uint32_t hist[1024];
    uint8_t labels[SW * SH];
    ssda_mix_model_t model;
} feature_t;

/* Histogram, fit (K by BIC), table, labels and cleaning of one feature. */
static int segment_feature(feature_t *f, void *work, uint8_t *raw, uint8_t *ring)
{
    ssda_mix_config_t mc;
    ssda_region_config_t rc;
    ssda_region_t job;
    uint8_t lut[1024];
    uint32_t y, done = 0;
    memset(&mc, 0, sizeof mc); /* EM, K by BIC up to 8, peaks start */
    memset(f->hist, 0, sizeof f->hist);
    ssda_mix_hist_add(f->hist, 1024, f->z, SW * SH, 0, NULL);
    if (ssda_mix_fit(f->hist, 1024, &mc, work, SSDA_MIX_WORK_SIZE(1024), &f->model) != SSDA_OK ||
        ssda_mix_lut(&f->model, SSDA_MIX_LABEL_BAND, 0, lut) != SSDA_OK) {
        return -1;
    }
    for (y = 0; y < SH; y++) {
        ssda_mix_label_row(lut, 1024, f->z + y * SW, SW, 0, raw + y * SW);
    }
    memset(&rc, 0, sizeof rc);
    rc.width = SW;
    rc.height = SH;
    rc.op = SSDA_REGION_CLEAN;
    if (ssda_region_init(&job, &rc, ring, SSDA_REGION_RING_SIZE(SW)) != SSDA_OK) {
        return -1;
    }
    for (y = 0; y < SH; y++) {
        done += (uint32_t)ssda_region_push(&job, raw + y * SW, f->labels + done * SW);
    }
    return ssda_region_flush(&job, f->labels + done * SW) == 1 ? 0 : -1;
}

static void make_scene(uint8_t *rgb, uint8_t *truth)
{
    uint32_t x, y, k;
    for (y = 0; y < SH; y++) {
        for (x = 0; x < SW; x++) {
            const uint8_t c = scene_class(x, y);
            const double shade = 1.0 + 0.04 * sin(x / 41.0 + y / 29.0); /* illumination */
            truth[y * SW + x] = c;
            for (k = 0; k < 3; k++) {
                double v = k_rgb[c - 1][k] * shade + 5.0 * normal();
                rgb[(y * SW + x) * 3 + k] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : lround(v));
            }
        }
    }
}

static int pictures(const demo_ctx_t *c, feature_t *f, const uint8_t *truth)
{
    draw_hist_panel_t hp[3];
    draw_label_panel_t lp[4];
    double w[3][16], m[3][16], s[3][16];
    char titles[4][64], lines[4][17][80], path[1024], err[512];
    const char *legend[4][17];
    atomic_file_t af;
    int k, rc = 0;
    uint32_t j;
    for (k = 0; k < 3; k++) {
        for (j = 0; j < f[k].model.count; j++) {
            w[k][j] = f[k].model.comp[j].weight_q16 / 65536.0;
            m[k][j] = f[k].model.comp[j].mean_q16 / 65536.0;
            s[k][j] = f[k].model.comp[j].sigma_q16 / 65536.0;
            snprintf(lines[k][j + 1], sizeof lines[k][j + 1], "%u: mean %.1f, sd %.1f",
                     (unsigned)(j + 1), m[k][j], s[k][j]);
            legend[k][j + 1] = lines[k][j + 1];
        }
        snprintf(titles[k], sizeof titles[k], "Z%d: %u components", k + 1,
                 (unsigned)f[k].model.count);
        hp[k] = (draw_hist_panel_t){titles[k], f[k].hist, 1024, f[k].model.count, w[k], m[k],
                                    s[k], (double)SW * SH};
        snprintf(lines[k][0], sizeof lines[k][0], "0: no component");
        legend[k][0] = lines[k][0];
        lp[k + 1] = (draw_label_panel_t){titles[k], f[k].labels, NULL, NULL, f[k].model.count,
                                         legend[k]};
    }
    snprintf(lines[3][0], sizeof lines[3][0], "0: -");
    legend[3][0] = lines[3][0];
    for (j = 0; j < NCLASS; j++) {
        snprintf(lines[3][j + 1], sizeof lines[3][j + 1], "%u: %s", (unsigned)(j + 1), k_class[j]);
        legend[3][j + 1] = lines[3][j + 1];
    }
    lp[0] = (draw_label_panel_t){"truth", truth, NULL, NULL, NCLASS, legend[3]};
    demo_path(c, "segment_hist.png", path, sizeof path);
    if (atomic_file_open(&af, path) != 0 ||
        draw_hist_to(af.fp, path, "ssda-demo: feature histograms and their mixtures", hp, 3, err,
                     sizeof err) != 0 || atomic_file_commit(&af) != 0) {
        fprintf(stderr, "ssda-demo: cannot write %s\n", path);
        rc = -1;
    } else if (!c->quiet) {
        printf("   wrote %s\n", path);
    }
    demo_path(c, "segment_labels.png", path, sizeof path);
    if (atomic_file_open(&af, path) != 0 ||
        draw_labels_to(af.fp, path, "ssda-demo: known regions and the labels of Z1, Z2, Z3", SW,
                       SH, lp, 4, err, sizeof err) != 0 || atomic_file_commit(&af) != 0) {
        fprintf(stderr, "ssda-demo: cannot write %s\n", path);
        rc = -1;
    } else {
        printf("   wrote %s\n", path);
    }
    return rc;
}

int demo_segment(const demo_ctx_t *c)
{
    static feature_t f[3];
    static uint8_t rgb[SW * SH * 3], truth[SW * SH], raw[SW * SH], joint[SW * SH];
    static uint8_t ring[SSDA_REGION_RING_SIZE(SW)];
    static uint64_t work[(SSDA_MIX_WORK_SIZE(1024) + 7) / 8];
    ssda_kl_acc_t acc;
    ssda_kl_config_t kc;
    ssda_kl_t kl;
    char path[1024];
    uint32_t y, i;
    int k;
    make_scene(rgb, truth);
    demo_path(c, "scene.png", path, sizeof path);
    if (write_rgb(path, rgb) != 0) {
        fprintf(stderr, "ssda-demo: cannot write %s\n", path);
        return -1;
    }
    /* pass 1: statistics; solve; pass 2: the three features */
    ssda_kl_acc_init(&acc, NULL);
    for (y = 0; y < SH; y++) {
        const uint8_t *p = rgb + (size_t)y * SW * 3;
        const ssda_kl_row_t row = {{p, p + 1, p + 2}, 3};
        ssda_kl_acc_add_row(&acc, &row, SW);
    }
    memset(&kc, 0, sizeof kc);
    kc.gain_max_q16 = 65536u; /* 8-bit input: no histogram combs */
    if (ssda_kl_solve(&acc, &kc, &kl) != SSDA_OK) {
        return -1;
    }
    for (y = 0; y < SH; y++) {
        const uint8_t *p = rgb + (size_t)y * SW * 3;
        const ssda_kl_row_t row = {{p, p + 1, p + 2}, 3};
        uint16_t *out[3] = {f[0].z + y * SW, f[1].z + y * SW, f[2].z + y * SW};
        ssda_kl_transform_row(&kl, &row, SW, out, NULL);
    }
    if (!c->quiet) {
        printf("   %s: 384 x 256 synthetic aerial scene, 8-bit RGB, five known regions\n"
               "            (deep and shallow water, vegetation, bare soil, a cloud), 4 %% "
               "shading, noise sd 5\n", path);
        printf("   K-L transform (correlation matrix, as the seed's eq. 2.2-2.3):\n");
        for (k = 0; k < 3; k++) {
            printf("     Z%d = %+.3f R %+.3f G %+.3f B   eigenvalue %.3f\n", k + 1,
                   kl.vec_q30[k][0] / 1073741824.0, kl.vec_q30[k][1] / 1073741824.0,
                   kl.vec_q30[k][2] / 1073741824.0, kl.lambda_q16[k] / 65536.0);
        }
        printf("   Gaussian mixtures (EM, K by BIC), labels by the seed's +-2 sigma bands, "
               "isolated points removed:\n");
    }
    for (k = 0; k < 3; k++) {
        if (segment_feature(&f[k], work, raw, ring) != 0) {
            fprintf(stderr, "ssda-demo: segmentation failed\n");
            return -1;
        }
        if (!c->quiet) {
            printf("     Z%d: %u components, agreement with the known regions (adjusted Rand "
                   "index) %.3f\n", k + 1, (unsigned)f[k].model.count,
                   ari(f[k].labels, truth, SW * SH));
        }
    }
    /* the seed's logical products: a region is a combination of the three */
    for (i = 0; i < SW * SH; i++) {
        joint[i] = (uint8_t)((f[0].labels[i] * 17u + f[1].labels[i]) * 17u + f[2].labels[i]);
    }
    if (!c->quiet) {
        printf("     Z1 x Z2 x Z3 combined (the seed's logical product): %.3f\n",
               ari(joint, truth, SW * SH));
    }
    return pictures(c, f, truth);
}
