/* demo_flow.c - the seed 003 part: a pair whose brightness changes, tracked
   by SAD and by the correlation coefficient, then outliers injected and the
   field cleaned by relaxation labelling and by the median test, each scored
   against the known wind; two overlays. */
#include "demo.h"
#include "draw.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ssda/ncc.h"
#include "ssda/relax.h"

#define WIN 16u
#define AREA 32u

typedef struct {
    int32_t dx, dy; /* Q8 px */
    uint8_t status; /* 0 = valid */
} vec_t;

typedef struct {
    uint32_t cols, rows, n;
    vec_t *sad, *rho, *dirty; /* tracked by SAD, by rho, rho with outliers */
    ssda_relax_vector_t *relaxed, *median;
    double *tx, *ty;          /* the wind at each window's centre */
    uint8_t *injected;
} flow_t;

/* SECOND made brighter and stronger in contrast: 1.35 x - 30, clamped. */
static void change_brightness(gray_image_t *img)
{
    uint8_t *p = img->pixels;
    size_t i;
    for (i = 0; i < (size_t)img->width * img->height; i++) {
        double v = 1.35 * p[i] - 30.0;
        p[i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v + 0.5);
    }
}

/* Both criteria on every window of the grid (step WIN, area AREA centred). */
static int track_both(const gray_image_t *a, const gray_image_t *b, const demo_wind_t *w,
                      flow_t *f)
{
    uint64_t nwork[SSDA_NCC_WORK_SIZE(AREA, WIN, WIN) / 8 + 1];
    uint32_t mwork[SSDA_MATCH_WORK_SIZE(AREA, AREA, WIN, WIN) / 4];
    ssda_view_t va, vb;
    uint32_t i, j;
    (void)gray_image_view(a, &va);
    (void)gray_image_view(b, &vb);
    for (j = 0; j < f->rows; j++) {
        for (i = 0; i < f->cols; i++) {
            const uint32_t k = j * f->cols + i, wx = 8u + i * WIN, wy = 8u + j * WIN;
            ssda_view_t area, win;
            ssda_match_config_t mc;
            ssda_match_result_t mr;
            ssda_ncc_config_t nc;
            ssda_ncc_result_t nr;
            memset(&mc, 0, sizeof mc);
            mc.flags = SSDA_MATCH_BOUNDS;
            mc.work = mwork;
            mc.work_size = sizeof mwork;
            memset(&nc, 0, sizeof nc);
            nc.work = nwork;
            nc.work_size = sizeof nwork;
            nc.flags = SSDA_NCC_PREDICT; /* the area's centre: zero motion */
            nc.predict_x = 8;
            nc.predict_y = 8;
            if (ssda_view_roi(&area, &va, (uint16_t)(wx - 8u), (uint16_t)(wy - 8u), AREA, AREA) !=
                    SSDA_OK ||
                ssda_view_roi(&win, &vb, (uint16_t)wx, (uint16_t)wy, WIN, WIN) != SSDA_OK ||
                ssda_match(&area, &win, &mc, &mr) != SSDA_OK ||
                ssda_ncc_match(&area, &win, &nc, &nr) != SSDA_OK) {
                return -1;
            }
            f->sad[k].dx = (8 - (int32_t)mr.x) * 256;
            f->sad[k].dy = (8 - (int32_t)mr.y) * 256;
            f->rho[k].dx = (8 - (int32_t)nr.x) * 256;
            f->rho[k].dy = (8 - (int32_t)nr.y) * 256;
            f->sad[k].status = f->rho[k].status = 0;
            demo_wind_at(w, wx + WIN / 2.0, wy + WIN / 2.0, &f->tx[k], &f->ty[k]);
        }
    }
    return 0;
}

/* 10 % of the rho vectors replaced by random ones at least 2 px off. */
static void inject(flow_t *f)
{
    uint32_t k, s = 20240611u;
    memcpy(f->dirty, f->rho, f->n * sizeof *f->dirty);
    for (k = 0; k < f->n; k++) {
        s = s * 1103515245u + 12345u;
        f->injected[k] = (s >> 16) % 10u == 0u;
        while (f->injected[k]) {
            int32_t x, y;
            s = s * 1103515245u + 12345u;
            x = (int32_t)((s >> 16) % 4097u) - 2048;
            s = s * 1103515245u + 12345u;
            y = (int32_t)((s >> 16) % 4097u) - 2048;
            if (hypot(x / 256.0 - f->tx[k], y / 256.0 - f->ty[k]) >= 2.0) {
                f->dirty[k].dx = x;
                f->dirty[k].dy = y;
                break;
            }
        }
    }
}

static double within1(const flow_t *f, const int32_t *dx, const int32_t *dy, size_t stride)
{
    uint32_t k, hit = 0;
    for (k = 0; k < f->n; k++) {
        const int32_t x = *(const int32_t *)(const void *)((const char *)dx + k * stride);
        const int32_t y = *(const int32_t *)(const void *)((const char *)dy + k * stride);
        hit += hypot(x / 256.0 - f->tx[k], y / 256.0 - f->ty[k]) <= 1.0;
    }
    return 100.0 * hit / f->n;
}

/* An overlay of n vectors (Q8) over bg, the wind as the truth arrows;
   `changed` (may be NULL) marks vectors drawn as outliers. */
static int overlay(const demo_ctx_t *c, const char *name, const char *title, const gray_image_t *bg,
                   const flow_t *f, const int32_t *dx, const int32_t *dy, size_t stride,
                   const uint8_t *mark)
{
    draw_vector_t *v = calloc(f->n, sizeof *v);
    draw_vectors_opts_t o;
    char path[1024], e[512];
    uint32_t k;
    int rc;
    if (v == NULL) {
        return -1;
    }
    for (k = 0; k < f->n; k++) {
        v[k].x = 8.0 + (k % f->cols) * WIN + WIN / 2.0;
        v[k].y = 8.0 + (k / f->cols) * WIN + WIN / 2.0;
        v[k].dx = *(const int32_t *)(const void *)((const char *)dx + k * stride) / 256.0;
        v[k].dy = *(const int32_t *)(const void *)((const char *)dy + k * stride) / 256.0;
        /* outliers: pink arrows */
        v[k].status = mark != NULL && mark[k] ? DRAW_CHANGED : DRAW_OK;
        v[k].has_truth = 1;
        v[k].tdx = f->tx[k];
        v[k].tdy = f->ty[k];
    }
    memset(&o, 0, sizeof o);
    o.title = title;
    o.grid_step = WIN;
    o.truth_label = "known wind";
    rc = draw_vectors_png(demo_path(c, name, path, sizeof path), bg, v, f->n, &o, NULL, e,
                          sizeof e);
    free(v);
    if (rc != 0) {
        fprintf(stderr, "ssda-demo: %s\n", e);
        return -1;
    }
    printf("   picture:  %s\n", path);
    return 0;
}

static int clean(flow_t *f)
{
    static uint32_t work[SSDA_RELAX_WORK_SIZE(32, 32) / 4];
    ssda_relax_grid_t g;
    ssda_relax_config_t rc;
    memset(&g, 0, sizeof g);
    g.dx = &f->dirty[0].dx;
    g.dy = &f->dirty[0].dy;
    g.status = &f->dirty[0].status;
    g.stride = sizeof f->dirty[0];
    g.cols = (uint16_t)f->cols;
    g.rows = (uint16_t)f->rows;
    g.frac_bits = 8;
    memset(&rc, 0, sizeof rc);
    rc.work = work;
    rc.work_size = sizeof work;
    if (f->cols > 32u || f->rows > 32u ||
        ssda_relax_labels(&g, &rc, f->relaxed, f->n) != SSDA_OK ||
        ssda_relax_median(&g, NULL, f->median, f->n) != SSDA_OK) {
        return -1;
    }
    return 0;
}

int demo_flow(const demo_ctx_t *c, const gray_image_t *first, const gray_image_t *second_in,
              const demo_wind_t *wind)
{
    gray_image_t second = *second_in;
    flow_t f;
    uint32_t k, left_relax = 0, left_median = 0, wrong = 0;
    uint8_t *mark;
    int rc = -1;
    memset(&f, 0, sizeof f);
    f.cols = (first->width - 16u) / WIN - 1u;
    f.rows = (first->height - 16u) / WIN - 1u;
    f.n = f.cols * f.rows;
    second.pixels = malloc((size_t)second.stride * second.height);
    f.sad = calloc(f.n, sizeof *f.sad);
    f.rho = calloc(f.n, sizeof *f.rho);
    f.dirty = calloc(f.n, sizeof *f.dirty);
    f.relaxed = calloc(f.n, sizeof *f.relaxed);
    f.median = calloc(f.n, sizeof *f.median);
    f.tx = calloc(2u * f.n, sizeof *f.tx);
    f.injected = calloc(2u * f.n, 1);
    if (second.pixels == NULL || !f.sad || !f.rho || !f.dirty || !f.relaxed || !f.median ||
        !f.tx || !f.injected) {
        fprintf(stderr, "ssda-demo: out of memory\n");
        goto done;
    }
    f.ty = f.tx + f.n;
    mark = f.injected + f.n;
    memcpy(second.pixels, second_in->pixels, (size_t)second.stride * second.height);
    change_brightness(&second);
    if (track_both(first, &second, wind, &f) != 0 || (inject(&f), clean(&f)) != 0) {
        fprintf(stderr, "ssda-demo: tracking failed\n");
        goto done;
    }
    printf("   input:    the cloud pair above, the second made 1.35 x brighter minus 30 "
           "(gain and offset)\n   grid:     %u x %u windows of %u x %u px in %u x %u areas\n\n",
           f.cols, f.rows, WIN, WIN, AREA, AREA);
    printf("   %-52s %s\n", "vectors within 1 px of the known wind:", "");
    printf("   %-52s %5.1f %%\n", "SAD (ssda_match)", within1(&f, &f.sad[0].dx, &f.sad[0].dy, sizeof(vec_t)));
    printf("   %-52s %5.1f %%\n", "correlation coefficient (ssda_ncc_match)",
           within1(&f, &f.rho[0].dx, &f.rho[0].dy, sizeof(vec_t)));
    printf("   %-52s %5.1f %%\n", "  with 10 % outliers injected",
           within1(&f, &f.dirty[0].dx, &f.dirty[0].dy, sizeof(vec_t)));
    printf("   %-52s %5.1f %%\n", "  cleaned by relaxation labelling (50 iterations)",
           within1(&f, &f.relaxed[0].dx_q8, &f.relaxed[0].dy_q8, sizeof(ssda_relax_vector_t)));
    printf("   %-52s %5.1f %%\n", "  cleaned by the normalised median test",
           within1(&f, &f.median[0].dx_q8, &f.median[0].dy_q8, sizeof(ssda_relax_vector_t)));
    for (k = 0; k < f.n; k++) {
        const double e0 = hypot(f.dirty[k].dx / 256.0 - f.tx[k], f.dirty[k].dy / 256.0 - f.ty[k]);
        if (e0 > 1.0) {
            wrong++;
            left_relax += hypot(f.relaxed[k].dx_q8 / 256.0 - f.tx[k],
                                f.relaxed[k].dy_q8 / 256.0 - f.ty[k]) > 1.0;
            left_median += hypot(f.median[k].dx_q8 / 256.0 - f.tx[k],
                                 f.median[k].dy_q8 / 256.0 - f.ty[k]) > 1.0;
        }
        mark[k] = (f.relaxed[k].flags & SSDA_RELAX_CHANGED) != 0u;
    }
    printf("   wrong vectors left: %u of %u by relaxation, %u by the median test\n\n", left_relax,
           wrong, left_median);
    if (overlay(c, "flow_sad_vs_rho.png", "SAD under a brightness change (yellow; cyan: the wind)",
                &second, &f, &f.sad[0].dx, &f.sad[0].dy, sizeof(vec_t), NULL) != 0 ||
        overlay(c, "flow_raw.png", "correlation coefficient + 10 % outliers (pink: injected)",
                &second, &f, &f.dirty[0].dx, &f.dirty[0].dy, sizeof(vec_t), f.injected) != 0 ||
        overlay(c, "flow_relaxed.png",
                "after relaxation labelling (pink: relabelled vectors; cyan: the wind)", &second, &f,
                &f.relaxed[0].dx_q8, &f.relaxed[0].dy_q8, sizeof(ssda_relax_vector_t),
                mark) != 0) {
        goto done;
    }
    rc = 0;
done:
    free(second.pixels);
    free(f.sad);
    free(f.rho);
    free(f.dirty);
    free(f.relaxed);
    free(f.median);
    free(f.tx);
    free(f.injected);
    return rc;
}
