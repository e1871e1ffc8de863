/*
 * stream_track.c - grid tracking with FIRST and/or SECOND streamed: the grid
 * is solved in vertical strips of grid columns, each top to bottom, so the
 * strip's band of search areas (FIRST) and of windows (SECOND) slide down
 * through the plates and every byte is read about once.
 *
 * When the plates hold a whole band, each grid row of the strip is solved
 * on the plates as images in RAM (row sources with a base pointer, placed
 * by an origin): the engine runs at in-RAM speed, with no call per row.
 * Otherwise the tracker fetches rows through the plate cache.
 */
#include "stream_internal.h"
#include "track_rows.h"

/* Solve the strip [c0, c1) grid row by grid row on bands of the plates. */
static int strip_on_bands(ssda_source_t *first, ssda_source_t *second,
                          ssda__track_plan_t *plan, uint32_t c0, uint32_t c1,
                          const ssda_rect_t *ar, const ssda_rect_t *wr, uint32_t lo,
                          uint32_t hi, const ssda__rows_t *whole_f, const ssda__rows_t *whole_s,
                          ssda_track_vector_t *out, ssda_track_stats_t *acc)
{
    const ssda_track_grid_t *g = &plan->grid;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    uint32_t r;
    int err = SSDA_OK;
    /* rows whose areas leave FIRST are EDGE: nothing is read for them */
    if (lo > 0u) {
        err = ssda__track_part(whole_f, whole_s, plan, c0, c1, 0u, lo, NULL, out, acc);
    }
    for (r = lo; r <= hi && err == SSDA_OK; r++) {
        const uint32_t wy = g->roi_y + r * g->step_y;
        ssda__track_origin_t o;
        ssda__rows_t fr, sr;
        err = ssda__stream_band_rows(first, ar, ar->x, wy - hy, &fr, &o.first_x, &o.first_y);
        if (err == SSDA_OK) {
            err = ssda__stream_band_rows(second, wr, wr->x, wy, &sr, &o.second_x, &o.second_y);
        }
        if (err == SSDA_OK) {
            o.first_w = first->cfg.width;
            o.first_h = first->cfg.height;
            err = ssda__track_part(&fr, &sr, plan, c0, c1, r, r + 1u, &o, out, acc);
        }
    }
    if (err == SSDA_OK && hi + 1u < g->rows) {
        err = ssda__track_part(whole_f, whole_s, plan, c0, c1, hi + 1u, g->rows, NULL, out, acc);
    }
    return err;
}

/* Grid columns per strip: as many as keep the strip's areas (search_h rows)
   and windows (win_h rows) in the plates; the whole grid width when the
   result could depend on the order (MEDIAN prediction in an inexact mode). */
static uint32_t strip_cols(const ssda__track_plan_t *p, const ssda_source_t *first,
                           const ssda_source_t *second)
{
    const ssda_track_grid_t *g = &p->grid;
    const uint8_t mode = p->match.threshold;
    const bool exact = (mode == (uint8_t)SSDA_THRESHOLD_AUTO ||
                        mode == (uint8_t)SSDA_THRESHOLD_NONE) &&
                       p->match.scan != (uint8_t)SSDA_SCAN_COARSE;
    uint32_t k = 1u;
    if (!exact && p->predict == (uint8_t)SSDA_TRACK_PREDICT_MEDIAN) {
        return g->cols;
    }
    while (k < g->cols) {
        size_t aw = SSDA_STREAM_STRIP_W(k + 1u, g->step_x, g->search_w);
        size_t ww = SSDA_STREAM_STRIP_W(k + 1u, g->step_x, g->win_w);
        if (aw > first->cfg.width) {
            aw = first->cfg.width;
        }
        if (!ssda__stream_holds(first, (uint32_t)aw, g->search_h, ssda__stream_run_extra(first, g->step_y)) ||
            !ssda__stream_holds(second, (uint32_t)ww, g->win_h, ssda__stream_run_extra(second, g->step_y))) {
            break;
        }
        k++;
    }
    return k;
}

int ssda_stream_track(ssda_source_t *first, ssda_source_t *second,
                      const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                      size_t out_count, ssda_track_stats_t *stats)
{
    static const ssda_track_config_t defaults;
    ssda__track_plan_t plan;
    ssda_track_stats_t acc;
    ssda__rows_t frows, srows;
    ssda__stream_rows_ctx_t fctx, sctx;
    ssda_rect_t all_f, all_s;
    uint32_t k, c0;
    int err;

    if (first == NULL || second == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(first) || !ssda__stream_ready(second)) {
        return SSDA_ERR_STATE;
    }
    if (ssda__stream_plates_clash(first, second)) {
        return SSDA_ERR_ARG;
    }
    if (first->cfg.format != second->cfg.format) {
        return SSDA_ERR_FORMAT;
    }
    err = ssda__track_plan(cfg != NULL ? cfg : &defaults, second->cfg.format,
                          second->cfg.width, second->cfg.height, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    if (!ssda__track_out_fits(plan.grid.count, out_count)) {
        return SSDA_ERR_BUFFER;
    }
    /* The tracker fetches whole area rows (mask test, bounds) and whole
       window rows: the narrowest plates that can serve it. */
    if (!ssda__stream_holds(first, plan.grid.search_w, 1u, 0u) || !ssda__stream_holds(second, plan.grid.win_w, 1u, 0u)) {
        return SSDA_ERR_BUFFER;
    }
    (void)ssda__stream_rect(first, NULL, &all_f);
    (void)ssda__stream_rect(second, NULL, &all_s);
    ssda__stream_rows_make(&frows, &fctx, first, &all_f);
    ssda__stream_rows_make(&srows, &sctx, second, &all_s);
    k = strip_cols(&plan, first, second);
    acc.pixel_ops = 0u;
    acc.positions = 0u;
    acc.completed = 0u;
    acc.check_pixels = 0u;
    acc.windows = 0u;
    acc.ok = 0u;
    acc.excluded = 0u;
    acc.masked = 0u;
    acc.edge = 0u;
    for (c0 = 0u; c0 < plan.grid.cols; c0 += k) {
        uint32_t c1 = plan.grid.cols - c0 > k ? c0 + k : plan.grid.cols;
        ssda_rect_t ar, wr;
        uint32_t lo, hi;
        /* Plates as wide as the strip, sliding down one grid step at a
           time (checked above: each holds at least one row). */
        bool inside = ssda__stream_grid_rects(&plan.grid, first->cfg.width, first->cfg.height, c0, c1, &ar, &wr, &lo,
                                        &hi);
        if (first->view == NULL && inside) {
            (void)ssda__stream_plate_plan(first, &ar, plan.grid.search_w, plan.grid.search_h,
                                    plan.grid.step_y, ssda__stream_run_extra(first, plan.grid.step_y));
        }
        if (second->view == NULL && inside) {
            (void)ssda__stream_plate_plan(second, &wr, plan.grid.win_w, plan.grid.win_h,
                                    plan.grid.step_y, ssda__stream_run_extra(second, plan.grid.step_y));
        }
        if (inside && ssda__stream_holds_band(first, &ar, plan.grid.search_h) &&
            ssda__stream_holds_band(second, &wr, plan.grid.win_h)) {
            err = strip_on_bands(first, second, &plan, c0, c1, &ar, &wr, lo, hi, &frows,
                                 &srows, out, &acc);
        } else {
            err = ssda__track_strip(&frows, &srows, &plan, c0, c1, out, &acc);
        }
        if (err != SSDA_OK) {
            return err;
        }
    }
    if (stats != NULL) {
        *stats = acc;
    }
    return SSDA_OK;
}
