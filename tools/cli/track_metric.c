/* track_metric.c - the correlation metric of grid tracking (track_metric.h). */
#include "track_metric.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "progress.h"
#include "ssda/ncc.h"

int track_metric_parse(const char *name)
{
    if (name == NULL) {
        return -1;
    }
    return !strcmp(name, "sad")      ? TRACK_METRIC_SAD
           : !strcmp(name, "ncc")    ? TRACK_METRIC_NCC
           : !strcmp(name, "absncc") ? TRACK_METRIC_ABSNCC
                                     : -1;
}

const char *track_metric_name(int metric)
{
    return metric == TRACK_METRIC_NCC ? "ncc" : metric == TRACK_METRIC_ABSNCC ? "absncc" : "sad";
}

/* Window k's view in SECOND and its search area in FIRST (track.h's
   GEOMETRY); *hx, *hy: the area's half margins. */
static int window_views(const track_result_t *r, const ssda_track_vector_t *v,
                        ssda_view_t *area, ssda_view_t *win, uint32_t *hx, uint32_t *hy)
{
    const ssda_track_grid_t *g = &r->grid;
    ssda_view_t vf, vs;
    int e;
    *hx = (uint32_t)(g->search_w - g->win_w) / 2u;
    *hy = (uint32_t)(g->search_h - g->win_h) / 2u;
    if (gray_image_view(&r->first, &vf) != SSDA_OK || gray_image_view(&r->second, &vs) != SSDA_OK) {
        return SSDA_ERR_ARG;
    }
    /* a searched window's area lies inside FIRST (else it would be EDGE) */
    e = ssda_view_roi(area, &vf, (uint16_t)(v->x - *hx), (uint16_t)(v->y - *hy), g->search_w,
                      g->search_h);
    return e != SSDA_OK ? e : ssda_view_roi(win, &vs, v->x, v->y, g->win_w, g->win_h);
}

/* Whether a placement lies on the border of the range along an axis with
   n placements: track.h's AT_LIMIT rule (one placement: no border). */
static int on_border(uint32_t pos, uint32_t n)
{
    return n > 1u && (pos == 0u || pos == n - 1u);
}

static int searched(uint8_t status)
{
    return status == SSDA_TRACK_OK || status == SSDA_TRACK_AMBIGUOUS ||
           status == SSDA_TRACK_AT_LIMIT;
}

/* The counts of the searched statuses after the correlation search. */
static void recount(track_result_t *r)
{
    size_t k;
    r->stats.ok = r->stats.ambiguous = r->stats.at_limit = 0u;
    for (k = 0; k < r->grid.count; k++) {
        switch (r->vec[k].status) {
        case SSDA_TRACK_OK: r->stats.ok++; break;
        case SSDA_TRACK_AMBIGUOUS: r->stats.ambiguous++; break;
        case SSDA_TRACK_AT_LIMIT: r->stats.at_limit++; break;
        default: break;
        }
    }
}

/* Sub-pixel offset, Q8 in [-128, 128], of the vertex of the parabola through
   r_m, r_0, r_p (Q2.30 at -1, 0, +1; r_0 the best, a trough of rho for
   absncc's negative peaks): 0 where a neighbour lies outside the area or
   the three make no peak. The tool's float twin of composite.c's fit. */
static int32_t peak_q8(int32_t rm, int32_t r0, int32_t rp, int neg)
{
    const double s = neg ? -1.0 : 1.0;
    double den, off;
    if (rm == SSDA_NCC_NONE || rp == SSDA_NCC_NONE) {
        return 0;
    }
    den = s * ((double)rm - 2.0 * r0 + rp);
    if (!(den < 0.0)) {
        return 0;
    }
    off = 0.5 * s * ((double)rm - rp) / den;
    off = off > 0.5 ? 0.5 : (off < -0.5 ? -0.5 : off);
    return (int32_t)floor(off * 256.0 + 0.5);
}

/* One searched window: rho at SAD's placement (sad), or the correlation
   search, whose vector replaces SAD's, its sub-pixel motion too (from rho
   at the 8 neighbours; whole pixels with --no-subpixel), and which decides
   the status (ok or at_limit). */
static int one_window(const track_opts_t *o, track_result_t *r, ssda_ncc_config_t *c, size_t k)
{
    const ssda_track_grid_t *g = &r->grid;
    ssda_track_vector_t *v = &r->vec[k];
    ssda_view_t area, win;
    ssda_ncc_result_t res;
    uint32_t hx, hy;
    int e = window_views(r, v, &area, &win, &hx, &hy);
    /* SAD's placement in the area: (hx - dx, hy - dy) */
    int32_t px = (int32_t)hx - v->dx, py = (int32_t)hy - v->dy;
    if (e != SSDA_OK) {
        return e;
    }
    if (o->metric == TRACK_METRIC_SAD) {
        r->metric_ops += (uint64_t)g->win_w * g->win_h;
        return ssda_ncc_at(&area, &win, (uint16_t)px, (uint16_t)py, &r->rho_q30[k]);
    }
    c->predict_x = px;
    c->predict_y = py;
    if ((e = ssda_ncc_match(&area, &win, c, &res)) != SSDA_OK) {
        return e;
    }
    r->metric_ops += res.pixel_ops;
    r->rho_q30[k] = res.rho_q30;
    v->dx = (int32_t)hx - (int32_t)res.x;
    v->dy = (int32_t)hy - (int32_t)res.y;
    /* the placement x + d is the motion dx - d */
    v->sub_dx_q8 = v->dx * 256;
    v->sub_dy_q8 = v->dy * 256;
    if ((c->flags & SSDA_NCC_AROUND) != 0u) {
        v->sub_dx_q8 -= peak_q8(res.around_q30[3], res.rho_q30, res.around_q30[5], res.rho_q30 < 0);
        v->sub_dy_q8 -= peak_q8(res.around_q30[1], res.rho_q30, res.around_q30[7], res.rho_q30 < 0);
    }
    v->exact = true;
    /* SAD's uniqueness does not describe this placement; not computed */
    v->unique_q8 = SSDA_MATCH_UNIQUE_NONE;
    /* the status of the correlation's own best: on the range's border it
       may lie beyond (track.h's AT_LIMIT rule); SAD's at_limit and
       ambiguous may be nothing but a brightness change, which rho does not
       see */
    v->status = (uint8_t)(on_border(res.x, (uint32_t)g->search_w - g->win_w + 1u) ||
                                  on_border(res.y, (uint32_t)g->search_h - g->win_h + 1u)
                              ? SSDA_TRACK_AT_LIMIT
                              : SSDA_TRACK_OK);
    return ssda_sad_at(&area, &win, res.x, res.y, &v->sad);
}

int track_metric_apply(const char *cmd, const track_opts_t *o, track_result_t *r)
{
    const ssda_track_grid_t *g = &r->grid;
    ssda_ncc_config_t c;
    double t0;
    size_t k;
    int e = SSDA_OK;
    if (o->metric == TRACK_METRIC_NONE) {
        return CLI_OK;
    }
    if ((uint32_t)g->win_w * g->win_h > SSDA_NCC_MAX_PIXELS) {
        return cli_usage_error(cmd, "--metric: window %ux%u; the correlation coefficient takes "
                               "windows of at most %u pixels", g->win_w, g->win_h,
                               SSDA_NCC_MAX_PIXELS);
    }
    memset(&c, 0, sizeof c);
    c.metric = (uint8_t)(o->metric == TRACK_METRIC_ABSNCC ? SSDA_NCC_ABS : SSDA_NCC_RHO);
    c.flags = SSDA_NCC_PREDICT;
    if ((r->cfg.flags & SSDA_TRACK_NO_SUBPIXEL) == 0u) {
        c.flags |= SSDA_NCC_AROUND;
    }
    c.work_size = SSDA_NCC_WORK_SIZE(g->search_w, g->win_w, g->win_h);
    r->rho_q30 = malloc((g->count + 1u) * sizeof *r->rho_q30);
    c.work = malloc(c.work_size);
    if (r->rho_q30 == NULL || c.work == NULL) {
        free(c.work);
        return cli_input_error(cmd, "out of memory");
    }
    t0 = progress_now();
    for (k = 0; k < g->count && e == SSDA_OK; k++) {
        r->rho_q30[k] = INT32_MIN;
        if (searched(r->vec[k].status)) {
            e = one_window(o, r, &c, k);
        }
    }
    r->metric_secs = progress_now() - t0;
    if (o->metric != TRACK_METRIC_SAD) {
        recount(r);
    }
    free(c.work);
    return e == SSDA_OK ? CLI_OK
                        : cli_input_error(cmd, "correlation search failed: %s", ssda_strerror(e));
}

void track_metric_json_window(cJSON *item, const track_result_t *r, size_t k)
{
    if (r->rho_q30 != NULL && r->rho_q30[k] != INT32_MIN) {
        json_out_add_fixed(item, "rho", r->rho_q30[k] / 1073741824.0, 6);
    }
}

void track_metric_json_options(cJSON *opt, const track_opts_t *o)
{
    cJSON_AddStringToObject(opt, "metric", track_metric_name(o->metric));
}

void track_metric_json_stats(cJSON *st, const track_opts_t *o, const track_result_t *r)
{
    if (o->metric != TRACK_METRIC_NONE) {
        json_out_add_u64(st, "metric_pixel_ops", r->metric_ops);
        json_out_add_fixed(st, "metric_time_s", r->metric_secs, 6);
    }
}

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

void track_metric_print(const track_opts_t *o, const track_result_t *r)
{
    int32_t *v;
    uint32_t k, n = 0;
    if (o->metric == TRACK_METRIC_NONE || r->rho_q30 == NULL ||
        (v = malloc((r->grid.count + 1u) * sizeof *v)) == NULL) {
        return;
    }
    for (k = 0; k < r->grid.count; k++) {
        if (r->rho_q30[k] != INT32_MIN && r->vec[k].status == SSDA_TRACK_OK) {
            v[n++] = r->rho_q30[k];
        }
    }
    if (n > 0) {
        qsort(v, n, sizeof *v, cmp_i32);
        printf("metric:  %s%s; median rho of the %u ok windows %.4f; correlation %s %.2f ms "
               "(%llu pixel ops)\n",
               track_metric_name(o->metric),
               o->metric == TRACK_METRIC_SAD ? " (vectors by SAD, rho at their placement)"
                                             : " (vectors by the exact correlation search)",
               n, v[n / 2] / 1073741824.0, o->metric == TRACK_METRIC_SAD ? "at the vectors" : "search",
               1e3 * r->metric_secs, (unsigned long long)r->metric_ops);
    }
    free(v);
}
