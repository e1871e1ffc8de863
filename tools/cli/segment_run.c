/* segment_run.c - the work of `ssda segment` (segment_run.h). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "segment_run.h"
#include "cli.h"
#include "ssda/region.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The K-L statistics, transform and feature images of an RGB image. */
static int kl_features(const char *cmd, const rgb_image_t *img, const seg_opts_t *o,
                       seg_result_t *r)
{
    const size_t bps = img->bits == 16 ? 2u : 1u;
    ssda_kl_acc_config_t ac;
    ssda_kl_config_t kc;
    ssda_kl_acc_t acc;
    uint32_t y;
    int k, e;
    memset(&ac, 0, sizeof ac);
    ac.format = img->bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
    ac.flags = o->have_nodata ? SSDA_KL_MASK_NODATA : 0u;
    ac.nodata = (uint16_t)o->nodata;
    if ((e = ssda_kl_acc_init(&acc, &ac)) != SSDA_OK) {
        return cli_input_error(cmd, "K-L transform: %s", ssda_strerror(e));
    }
    for (y = 0; y < img->height; y++) {
        const uint8_t *p = (const uint8_t *)img->pixels + (size_t)y * img->stride;
        const ssda_kl_row_t row = {{p, p + bps, p + 2 * bps}, 3};
        ssda_kl_acc_add_row(&acc, &row, img->width);
    }
    r->masked = acc.masked;
    memset(&kc, 0, sizeof kc);
    kc.matrix = o->matrix;
    kc.nsigma = o->nsigma;
    kc.out_max = (uint16_t)(o->bins - 1u);
    kc.gain_max_q16 = (uint32_t)lround((o->gain_max > 0.0 ? o->gain_max
                                        : img->bits == 16 ? 4096.0 : 1.0) * 65536.0);
    if ((e = ssda_kl_solve(&acc, &kc, &r->kl)) != SSDA_OK) {
        return cli_input_error(cmd, "K-L transform: %s%s", ssda_strerror(e),
                               acc.count == 0 ? " (every pixel is nodata)" : "");
    }
    for (k = 0; k < r->nfeat; k++) {
        seg_feature_t *f = &r->feat[k];
        const double sd = sqrt((double)r->kl.zvar_q16[f->index] / 65536.0);
        double l1 = 0.0, vmax = 0.0;
        int j;
        for (j = 0; j < 3; j++) {
            const double v = fabs(r->kl.vec_q30[f->index][j] / 1073741824.0);
            l1 += v;
            vmax = v > vmax ? v : vmax;
        }
        f->offset = r->kl.out_max / 2.0;
        f->gain = r->kl.range == SSDA_KL_RANGE_SIGMA
                      ? (sd > 0.0 ? f->offset / (r->kl.nsigma * sd) : 4096.0)
                      : f->offset / ((img->bits == 16 ? 65535.0 : 255.0) * l1);
        if (f->gain * vmax > r->kl.gain_max_q16 / 65536.0) {
            f->gain = r->kl.gain_max_q16 / 65536.0 / vmax; /* the library's cap */
        }
        f->bins = o->bins;
        f->shift = 0;
    }
    for (y = 0; y < img->height; y++) {
        const uint8_t *p = (const uint8_t *)img->pixels + (size_t)y * img->stride;
        const ssda_kl_row_t row = {{p, p + bps, p + 2 * bps}, 3};
        uint16_t *out[3] = {NULL, NULL, NULL};
        for (k = 0; k < r->nfeat; k++) {
            out[r->feat[k].index] = r->feat[k].values + (size_t)y * img->width;
        }
        ssda_kl_transform_row(&r->kl, &row, img->width, out, &r->clamped);
    }
    return CLI_OK;
}

/* A gray image as its own feature: values >> shift into at most o->bins. */
static void gray_feature(const gray_image_t *g, const seg_opts_t *o, seg_result_t *r)
{
    seg_feature_t *f = &r->feat[0];
    uint32_t x, y, top = 0;
    for (y = 0; y < g->height; y++) {
        for (x = 0; x < g->width; x++) {
            const uint32_t v = gray_image_get(g, x, y);
            if (!(o->have_nodata && v == o->nodata)) {
                top = v > top ? v : top;
            }
        }
    }
    f->shift = 0;
    if (g->bits == 16) {
        while ((top >> f->shift) >= o->bins) {
            f->shift++;
        }
    }
    f->bins = g->bits == 16 ? (top >> f->shift) + 1u : 256u;
    f->bins = f->bins < SSDA_MIX_MIN_BINS ? SSDA_MIX_MIN_BINS : f->bins;
    f->gain = 1.0 / (double)(1u << f->shift);
    f->offset = 0.0;
    for (y = 0; y < g->height; y++) {
        for (x = 0; x < g->width; x++) {
            const uint32_t v = gray_image_get(g, x, y);
            const int masked = o->have_nodata && v == o->nodata;
            f->values[(size_t)y * g->width + x] = masked ? (uint16_t)SSDA_KL_NODATA : (uint16_t)v;
            r->masked += masked ? 1u : 0u;
        }
    }
}

/* One 3 x 3 job over a whole label image, into out. */
static int region_pass(uint8_t op, uint32_t w, uint32_t h, const uint8_t *in, uint8_t *out,
                       uint32_t *counts)
{
    ssda_region_config_t rc;
    ssda_region_t job;
    uint8_t *ring = malloc(SSDA_REGION_RING_SIZE(w));
    uint32_t y, done = 0;
    int e;
    if (ring == NULL) {
        return SSDA_ERR_BUFFER;
    }
    memset(&rc, 0, sizeof rc);
    rc.width = (uint16_t)w;
    rc.height = (uint16_t)h;
    rc.op = op;
    rc.counts = counts;
    e = ssda_region_init(&job, &rc, ring, SSDA_REGION_RING_SIZE(w));
    for (y = 0; e == SSDA_OK && y < h; y++) {
        const int n = ssda_region_push(&job, in + (size_t)y * w, out + (size_t)done * w);
        if (n < 0) {
            e = n;
        } else {
            done += (uint32_t)n;
        }
    }
    if (e == SSDA_OK) {
        e = ssda_region_flush(&job, out + (size_t)done * w) < 0 ? SSDA_ERR_STATE : SSDA_OK;
    }
    free(ring);
    return e;
}

/* Histogram, fit, table, labels, cleaning, contours and counts of f. */
static int segment_feature(const char *cmd, const seg_opts_t *o, uint32_t w, uint32_t h,
                           seg_feature_t *f)
{
    const size_t n = (size_t)w * h;
    ssda_mix_config_t mc;
    uint8_t lut[SSDA_MIX_MAX_BINS];
    uint8_t *raw = malloc(n);
    void *work = malloc(SSDA_MIX_WORK_SIZE(SSDA_MIX_MAX_BINS));
    double t0 = now();
    uint32_t y;
    int e, rc = CLI_INPUT;
    if (raw == NULL || work == NULL) {
        cli_input_error(cmd, "out of memory");
        goto done;
    }
    for (y = 0; y < h; y++) {
        ssda_mix_hist_add(f->hist, f->bins, f->values + (size_t)y * w, w, f->shift, NULL);
    }
    memset(&mc, 0, sizeof mc);
    mc.components = o->comps[f->index];
    mc.max_components = o->max_comps;
    mc.fit = o->fit;
    mc.init = o->init;
    mc.flags = o->seed_steps ? SSDA_MIX_SEED_STEPS : 0u;
    e = ssda_mix_fit(f->hist, f->bins, &mc, work, SSDA_MIX_WORK_SIZE(SSDA_MIX_MAX_BINS),
                     &f->model);
    if (e == SSDA_OK) {
        e = ssda_mix_lut(&f->model, o->rule, o->band_q8, lut);
    }
    if (e == SSDA_OK) {
        e = ssda_mix_band_pixels(&f->model, f->hist, o->band_q8, f->band_pixels);
    }
    f->fit_secs = now() - t0;
    if (e != SSDA_OK) {
        cli_input_error(cmd, "fit of feature %d: %s%s", f->index + 1, ssda_strerror(e),
                        e == SSDA_ERR_SIZE ? " (no pixel outside nodata)" : "");
        goto done;
    }
    for (y = 0; y < h; y++) {
        ssda_mix_label_row(lut, f->bins, f->values + (size_t)y * w, w, f->shift,
                           (o->clean ? raw : f->labels) + (size_t)y * w);
    }
    e = o->clean ? region_pass(SSDA_REGION_CLEAN, w, h, raw, f->labels, NULL) : SSDA_OK;
    for (y = 0; y < n; y++) {
        /* cleaning may fill a lone nodata pixel: masked pixels stay 0 */
        if (f->values[y] == SSDA_KL_NODATA) {
            f->labels[y] = 0;
        }
        f->counts[f->labels[y]]++;
    }
    if (e == SSDA_OK && o->contours) {
        e = region_pass(SSDA_REGION_CONTOUR, w, h, f->labels, f->contour, NULL);
    }
    if (e != SSDA_OK) {
        cli_input_error(cmd, "regions: %s", ssda_strerror(e));
        goto done;
    }
    rc = CLI_OK;
done:
    free(raw);
    free(work);
    return rc;
}

static int alloc_features(const seg_opts_t *o, uint32_t w, uint32_t h, seg_result_t *r)
{
    const size_t n = (size_t)w * h;
    int k;
    r->nfeat = 0;
    for (k = 0; k < (r->color ? 3 : 1); k++) {
        if (r->color && o->band != 0 && o->band != k + 1) {
            continue;
        }
        r->feat[r->nfeat].index = k;
        r->nfeat++;
    }
    for (k = 0; k < r->nfeat; k++) {
        seg_feature_t *f = &r->feat[k];
        f->values = malloc(n * sizeof(uint16_t));
        f->hist = calloc(SSDA_MIX_MAX_BINS, sizeof(uint32_t));
        f->labels = malloc(n);
        f->contour = o->contours ? malloc(n) : NULL;
        if (f->values == NULL || f->hist == NULL || f->labels == NULL ||
            (o->contours && f->contour == NULL)) {
            return -1;
        }
    }
    return 0;
}

int seg_run(const char *cmd, const char *path, const seg_opts_t *o, seg_result_t *r)
{
    rgb_image_t rgb = {0};
    gray_image_t gray = {0};
    png_source_info_t info;
    char err[512];
    double t0;
    int k, rc = CLI_INPUT;
    memset(r, 0, sizeof *r);
    if (png_read_rgb(path, &rgb, &info, err, sizeof err) != 0) {
        return cli_input_error(cmd, "%s", err);
    }
    r->width = rgb.width;
    r->height = rgb.height;
    r->bits = rgb.bits;
    r->color = info.was_color;
    if (!r->color) {
        rgb_image_free(&rgb);
        if (cli_load_png(cmd, path, PNG_GRAY_NATIVE, &gray) != 0) {
            return CLI_INPUT;
        }
    }
    if (o->have_nodata && o->nodata > (r->bits == 16 ? 65535u : 255u)) {
        rc = cli_input_error(cmd, "--nodata %u is above the largest %u-bit value", o->nodata,
                             r->bits);
        goto done;
    }
    t0 = now();
    if (alloc_features(o, r->width, r->height, r) != 0) {
        rc = cli_input_error(cmd, "out of memory for %u x %u pixels", r->width, r->height);
        goto done;
    }
    if (r->color) {
        if (kl_features(cmd, &rgb, o, r) != CLI_OK) {
            goto done;
        }
    } else {
        gray_feature(&gray, o, r);
    }
    for (k = 0; k < r->nfeat; k++) {
        if (segment_feature(cmd, o, r->width, r->height, &r->feat[k]) != CLI_OK) {
            goto done;
        }
    }
    r->secs = now() - t0;
    rc = CLI_OK;
done:
    rgb_image_free(&rgb);
    gray_image_free(&gray);
    return rc;
}

void seg_result_free(seg_result_t *r)
{
    int k;
    for (k = 0; k < 3; k++) {
        free(r->feat[k].values);
        free(r->feat[k].hist);
        free(r->feat[k].labels);
        free(r->feat[k].contour);
    }
    memset(r, 0, sizeof *r);
}
