/* demo_track.c - grid tracking in the paper's modes: work, time, agreement
   with brute force and with the known wind; what each window's status
   says; the overlay picture. */
#include "demo.h"
#include "draw.h"
#include "progress.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *name;
    uint8_t threshold, scan, predict, flags;
} demo_mode_t;

/* The first mode is the reference; SHOWN is the one drawn and scored in
   detail (the seed's recommendation: automatic threshold with prediction). */
static const demo_mode_t modes[] = {
    {"brute force: every position in full", SSDA_THRESHOLD_NONE, SSDA_SCAN_RASTER,
     SSDA_TRACK_PREDICT_NONE, 0},
    {"automatic threshold (Fig. 9)", SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER,
     SSDA_TRACK_PREDICT_NONE, 0},
    {"  + prediction from neighbours", SSDA_THRESHOLD_AUTO, SSDA_SCAN_PREDICT,
     SSDA_TRACK_PREDICT_MEDIAN, 0},
    {"  + successive-elimination bounds", SSDA_THRESHOLD_AUTO, SSDA_SCAN_PREDICT,
     SSDA_TRACK_PREDICT_MEDIAN, SSDA_MATCH_BOUNDS},
    {"automatic increasing threshold (eq. 4)", SSDA_THRESHOLD_AUTO_RAMP, SSDA_SCAN_PREDICT,
     SSDA_TRACK_PREDICT_MEDIAN, 0},
    {"coarse-to-fine, 8 px grid (Hall)", SSDA_THRESHOLD_AUTO, SSDA_SCAN_COARSE,
     SSDA_TRACK_PREDICT_NONE, 0},
};
#define NMODES (sizeof modes / sizeof modes[0])
#define SHOWN 2

/* Mean of SECOND without fill pixels: the texture level (as `ssda track --exclude`). */
static uint32_t mean_level(const gray_image_t *img, long mask)
{
    uint64_t sum = 0, n = 0;
    uint32_t x, y;
    for (y = 0; y < img->height; y++) {
        for (x = 0; x < img->width; x++) {
            uint32_t v = gray_image_get(img, x, y);
            if (mask < 0 || v != (uint32_t)mask) {
                sum += v;
                n++;
            }
        }
    }
    return n ? (uint32_t)(sum / n) : 0u;
}

typedef struct {
    ssda_track_vector_t *vec;
    ssda_track_stats_t stats;
    double secs;
} mode_run_t;

/* One mode; timed over repeats when a run is short, for a stable figure.
   The uniqueness test runs in the exact modes (it needs exact SADs). */
static int run_mode(const ssda_view_t *vf, const ssda_view_t *vs, ssda_track_config_t cfg,
                    const demo_mode_t *m, size_t count, void *work, size_t work_size,
                    mode_run_t *out)
{
    double t0, best = 1e30;
    int rep, e = SSDA_OK;
    cfg.match.threshold = m->threshold;
    cfg.match.scan = m->scan;
    cfg.match.flags = m->flags;
    cfg.predict = m->predict;
    if (m->scan != SSDA_SCAN_COARSE &&
        (m->threshold == SSDA_THRESHOLD_AUTO || m->threshold == SSDA_THRESHOLD_NONE)) {
        cfg.flags |= SSDA_TRACK_UNIQUE;
    }
    cfg.match.work = work;
    cfg.match.work_size = work_size;
    for (rep = 0; rep < 5; rep++) {
        t0 = progress_now();
        e = ssda_track(vf, vs, &cfg, out->vec, count, &out->stats);
        t0 = progress_now() - t0;
        best = t0 < best ? t0 : best;
        if (e != SSDA_OK || t0 > 0.05) {
            break;
        }
    }
    out->secs = best;
    return e;
}

/* The wind at the window's centre, and the Chebyshev and Euclidean errors
   of the whole-pixel and the sub-pixel vector against it. */
typedef struct {
    double u, v, cheb, eucl, eucl_sub;
} wind_err_t;

static void error_vs_wind(const demo_wind_t *w, const ssda_track_grid_t *g,
                          const ssda_track_vector_t *v, wind_err_t *e)
{
    double cx = v->x + (g->win_w - 1) / 2.0, cy = v->y + (g->win_h - 1) / 2.0;
    demo_wind_at(w, cx, cy, &e->u, &e->v);
    e->cheb = fmax(fabs(v->dx - e->u), fabs(v->dy - e->v));
    e->eucl = hypot(v->dx - e->u, v->dy - e->v);
    e->eucl_sub = hypot(v->sub_dx_q8 / 256.0 - e->u, v->sub_dy_q8 / 256.0 - e->v);
}

static int draw_status(uint8_t s)
{
    switch (s) {
    case SSDA_TRACK_OK: return DRAW_OK;
    case SSDA_TRACK_EXCLUDED: return DRAW_EXCLUDED;
    case SSDA_TRACK_MASKED: return DRAW_MASKED;
    case SSDA_TRACK_FLAT: return DRAW_FLAT;
    case SSDA_TRACK_AMBIGUOUS: return DRAW_AMBIGUOUS;
    case SSDA_TRACK_AT_LIMIT: return DRAW_AT_LIMIT;
    default: return DRAW_EDGE;
    }
}

/* The window counts of the reference run and what each status means. */
static void print_statuses(const ssda_track_stats_t *st, const ssda_track_config_t *cfg,
                           const ssda_track_grid_t *grid, int exclude)
{
    printf("   windows  %u: %u ok (searched, unique, inside the range), %u flat (no texture:\n"
           "            not searched), %u ambiguous (another match as good), %u at the limit\n"
           "            (best match on the border of the search area: the motion may be\n"
           "            larger)",
           st->windows, st->ok, st->flat, st->ambiguous, st->at_limit);
    if (exclude) {
        printf(", %u excluded beforehand as all dark or all bright", st->excluded);
    }
    printf(", %u masked, %u at the edge (search area leaves the image)\n", st->masked,
           st->edge);
    printf("   statuses are by design, not failures: only ok vectors are to be trusted;\n"
           "            flat = mean absolute deviation under 1.25 grey levels\n");
    if (exclude) { /* many grey crosses look like failures; they are the paper's rule */
        printf("   excluded = by design (the seed's texture rule), not a failure: fewer than %u "
               "of a window's %u pixels on one side of brightness %u (the image mean)\n",
               grid->win_w * grid->win_h / SSDA_TRACK_DEFAULT_MIN_COUNT_DIV,
               grid->win_w * grid->win_h, cfg->texture_threshold);
    }
    printf("\n");
}

/* One row per mode: work, time, agreement with brute force and the wind. */
static void print_modes(const mode_run_t *run, const ssda_track_grid_t *grid,
                        const demo_wind_t *wind)
{
    const double brute_ops = (double)run[0].stats.pixel_ops;
    size_t i, k;
    /* header columns as wide as the rows' fields below */
    printf("   %-40s %18s %10s%14s%s\n", "mode", "work (pixel ops)", "time",
           "same as brute", wind ? "     within 1 px of" : "");
    printf("   %-40s %18s %10s%14s%s\n", "", "", "", "force", wind ? "      the true wind" : "");
    for (i = 0; i < NMODES; i++) {
        size_t same = 0, near = 0, ok = 0;
        for (k = 0; k < grid->count; k++) {
            const ssda_track_vector_t *v = &run[i].vec[k], *r = &run[0].vec[k];
            if (v->status != SSDA_TRACK_OK) {
                continue;
            }
            ok++;
            /* the minimum found: brute force's SAD (a tie may sit elsewhere) */
            same += v->sad == r->sad;
            if (wind != NULL) {
                wind_err_t e;
                error_vs_wind(wind, grid, v, &e);
                near += e.cheb <= 1.0;
            }
        }
        printf("   %-40s %8.2f M %5.1f %% %7.2f ms %11.1f %%", modes[i].name,
               run[i].stats.pixel_ops / 1e6,
               brute_ops > 0 ? 100.0 * (double)run[i].stats.pixel_ops / brute_ops : 0.0,
               1e3 * run[i].secs, ok ? 100.0 * (double)same / (double)ok : 0.0);
        if (wind != NULL) {
            printf("%17.1f %%", ok ? 100.0 * (double)near / (double)ok : 0.0);
        }
        printf("\n");
    }
}

/* The shown mode in detail: accuracy of its ok vectors (whole and
   sub-pixel), agreement with brute force; fills the overlay's vectors. */
static void report_shown(const mode_run_t *run, const ssda_track_grid_t *grid,
                         const demo_wind_t *wind, draw_vector_t *dv)
{
    const mode_run_t *s = &run[SHOWN];
    const double brute_ops = (double)run[0].stats.pixel_ops;
    size_t ok = 0, w1 = 0, same = 0, moved = 0, k;
    double sum_e = 0.0, sum_sub = 0.0;
    for (k = 0; k < grid->count; k++) {
        const ssda_track_vector_t *v = &s->vec[k];
        dv[k].x = v->x + (grid->win_w - 1) / 2.0;
        dv[k].y = v->y + (grid->win_h - 1) / 2.0;
        dv[k].dx = v->sub_dx_q8 / 256.0;
        dv[k].dy = v->sub_dy_q8 / 256.0;
        dv[k].status = draw_status(v->status);
        if (v->status != SSDA_TRACK_OK) {
            continue;
        }
        ok++;
        same += v->sad == run[0].vec[k].sad;
        moved += v->sad == run[0].vec[k].sad &&
                 (v->dx != run[0].vec[k].dx || v->dy != run[0].vec[k].dy);
        if (wind != NULL) {
            wind_err_t e;
            error_vs_wind(wind, grid, v, &e);
            dv[k].has_truth = 1;
            dv[k].tdx = e.u;
            dv[k].tdy = e.v;
            w1 += e.cheb <= 1.0;
            sum_e += e.eucl;
            sum_sub += e.eucl_sub;
        }
    }
    printf("\n");
    if (wind != NULL && ok > 0) {
        printf("   accuracy %.1f %% of the ok windows within 1 px of the true wind; mean error\n"
               "            %.2f px with sub-pixel vectors (equiangular fit), %.2f px whole pixels\n",
               100.0 * (double)w1 / (double)ok, sum_sub / (double)ok, sum_e / (double)ok);
    }
    printf("   saving   the automatic threshold with prediction summed %.1f %% of the "
           "brute-force\n            pixel differences and ",
           brute_ops > 0 ? 100.0 * (double)s->stats.pixel_ops / brute_ops : 0.0);
    if (same == ok) {
        printf("found the same minimum in every ok window (exact)\n");
    } else {
        printf("found brute force's minimum SAD in %zu of %zu ok windows\n", same, ok);
    }
    if (moved > 0) {
        printf("            (%zu of them at another placement of the same SAD as brute force's:\n"
               "            a tie, which the search with prediction breaks toward the predicted\n"
               "            vector and brute force toward zero motion)\n", moved);
    }
}

static int draw_overlay(const demo_ctx_t *c, const gray_image_t *second, const draw_vector_t *dv,
                        const ssda_track_grid_t *grid, const mode_run_t *run,
                        const demo_wind_t *wind, long mask, uint32_t step,
                        const char *overlay_name)
{
    const mode_run_t *s = &run[SHOWN];
    const double brute_ops = (double)run[0].stats.pixel_ops;
    draw_vectors_opts_t o;
    char path[1024], title[256], sub[256], err[512];
    snprintf(title, sizeof title, "ssda-demo: %s", wind ? "synthetic clouds moved by a "
                                                          "known wind" : "your image pair");
    snprintf(sub, sizeof sub,
             "automatic threshold + prediction: %u ok windows, work %.1f %% of brute "
             "force%s",
             s->stats.ok, brute_ops > 0 ? 100.0 * (double)s->stats.pixel_ops / brute_ops : 0.0,
             wind ? "; cyan = true wind" : "");
    memset(&o, 0, sizeof o);
    o.title = title;
    o.subtitle = sub;
    o.grid_step = step;
    o.truth_label = "true wind";
    o.have_mask = mask >= 0;
    o.mask_value = mask >= 0 ? (uint32_t)mask : 0u;
    demo_path(c, overlay_name, path, sizeof path);
    if (draw_vectors_png(path, second, dv, grid->count, &o, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", err);
        return -1;
    }
    printf("   picture  %s\n            (yellow: ok vectors%s; other marks: the statuses, "
           "named in the legend)\n",
           path, wind ? ", cyan: true wind" : "");
    return 0;
}

int demo_track(const demo_ctx_t *c, const gray_image_t *first, const gray_image_t *second,
               const demo_wind_t *wind, long mask, uint32_t step, int exclude,
               const char *overlay_name, const char *label)
{
    ssda_track_config_t cfg;
    ssda_track_grid_t grid;
    ssda_view_t vf, vs;
    mode_run_t run[NMODES];
    void *work = NULL;
    size_t work_size, i;
    draw_vector_t *dv = NULL;
    int rc = -1, e;

    memset(run, 0, sizeof run);
    memset(&cfg, 0, sizeof cfg);
    cfg.step_x = cfg.step_y = (uint16_t)step;
    if (exclude) {
        cfg.flags = SSDA_TRACK_EXCLUDE;
        cfg.texture_threshold = (uint16_t)mean_level(second, mask);
        if (cfg.texture_threshold >= gray_image_max(second)) {
            cfg.texture_threshold = (uint16_t)(gray_image_max(second) - 1u);
        }
    }
    if (mask >= 0) {
        cfg.flags |= SSDA_TRACK_MASK;
        cfg.mask_value = (uint16_t)mask;
    }
    if (gray_image_view(first, &vf) != SSDA_OK || gray_image_view(second, &vs) != SSDA_OK ||
        ssda_track_grid(&cfg, (uint16_t)second->width, (uint16_t)second->height, &grid) !=
            SSDA_OK) {
        fprintf(stderr, "ssda-demo: the images are too small for 16 x 16 windows in 32 x 32 "
                        "areas\n");
        return -1;
    }
    work_size = SSDA_TRACK_WORK_SIZE(grid.search_w, grid.search_h, grid.win_w, grid.win_h);
    work = malloc(work_size); /* malloc's alignment suits the 8 bytes it needs */
    dv = calloc(grid.count + 1u, sizeof *dv);
    for (i = 0; i < NMODES; i++) {
        run[i].vec = calloc(grid.count + 1u, sizeof *run[i].vec);
        if (run[i].vec == NULL) {
            goto done;
        }
    }
    if (work == NULL || dv == NULL) {
        fprintf(stderr, "ssda-demo: out of memory\n");
        goto done;
    }

    printf("   input    %s\n", label);
    printf("   grid     %u x %u windows of %u x %u px every %u px, each searched in the %u x %u\n"
           "            area around it in the first image (the seed's cloud tracking)\n",
           grid.cols, grid.rows, grid.win_w, grid.win_h, grid.step_x, grid.search_w,
           grid.search_h);
    for (i = 0; i < NMODES; i++) {
        e = run_mode(&vf, &vs, cfg, &modes[i], grid.count, work, work_size, &run[i]);
        if (e != SSDA_OK) {
            fprintf(stderr, "ssda-demo: tracking failed: %s\n", ssda_strerror(e));
            goto done;
        }
    }
    print_statuses(&run[0].stats, &cfg, &grid, exclude);
    print_modes(run, &grid, wind);
    report_shown(run, &grid, wind, dv);
    rc = draw_overlay(c, second, dv, &grid, run, wind, mask, step, overlay_name);
done:
    for (i = 0; i < NMODES; i++) {
        free(run[i].vec);
    }
    free(dv);
    free(work);
    return rc;
}
