/*
 * stream_track.c - grid tracking with FIRST and/or SECOND streamed: the grid
 * is solved in vertical strips of grid columns, each top to bottom, so the
 * strip's band of search areas (FIRST) and of windows (SECOND) slide down
 * through the plates and every byte is read about once.
 */
#include "stream_internal.h"
#include "track_rows.h"

/* Grid positions [lo, hi] along one axis whose search areas lie inside
   FIRST (the others are EDGE windows: neither their areas nor their windows
   are read). start, step: grid; half: (search - win) / 2; img: FIRST's
   size. Returns false when there is none. */
static bool inside_range(uint32_t start, uint32_t step, uint32_t count, uint32_t half,
                         uint32_t search, uint32_t img, uint32_t *lo, uint32_t *hi)
{
    /* first k with start + k step >= half; last with start + k step - half
       + search <= img */
    uint32_t first = start >= half ? 0u : (half - start + step - 1u) / step;
    uint32_t last;
    if (start + search > img + half) {
        return false;
    }
    last = (img + half - search - start) / step;
    if (last >= count) {
        last = count - 1u;
    }
    *lo = first;
    *hi = last;
    return first <= last;
}

/* The strip of grid columns [c0, c1): the rectangle of its search areas in
   FIRST and of its windows in SECOND, over the windows whose areas lie
   inside FIRST. Returns false when there is none (nothing will be read). */
static bool strip_rects(const ssda_track_grid_t *g, const ssda_source_t *first,
                        uint32_t c0, uint32_t c1, ssda_rect_t *area, ssda_rect_t *win)
{
    const uint32_t hx = ((uint32_t)g->search_w - g->win_w) / 2u;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    uint32_t x_lo, x_hi, y_lo, y_hi, wx0, wx1, wy0, wy1;
    if (!inside_range(g->roi_x, g->step_x, g->cols, hx, g->search_w, first->cfg.width,
                      &x_lo, &x_hi) ||
        !inside_range(g->roi_y, g->step_y, g->rows, hy, g->search_h, first->cfg.height,
                      &y_lo, &y_hi)) {
        return false;
    }
    x_lo = x_lo > c0 ? x_lo : c0;
    x_hi = x_hi < c1 - 1u ? x_hi : c1 - 1u;
    if (x_lo > x_hi) {
        return false;
    }
    /* all below are inside SECOND or FIRST, so they fit 16 bits */
    wx0 = g->roi_x + x_lo * g->step_x;
    wx1 = g->roi_x + x_hi * g->step_x;
    wy0 = g->roi_y + y_lo * g->step_y;
    wy1 = g->roi_y + y_hi * g->step_y;
    win->x = (uint16_t)wx0;
    win->y = (uint16_t)wy0;
    win->width = (uint16_t)(wx1 - wx0 + g->win_w);
    win->height = (uint16_t)(wy1 - wy0 + g->win_h);
    area->x = (uint16_t)(wx0 - hx);
    area->y = (uint16_t)(wy0 - hy);
    area->width = (uint16_t)(wx1 - wx0 + g->search_w);
    area->height = (uint16_t)(wy1 - wy0 + g->search_h);
    return true;
}

/* Does a streamed source hold a plate of w x h? (In-RAM sources always.) */
static bool holds(const ssda_source_t *s, uint32_t w, uint32_t h)
{
    return s->view != NULL || stream_plate_fit_h(s, w) >= h;
}

/* Grid columns per strip: as many as keep the strip's areas (search_h rows)
   and windows (win_h rows) in the plates; the whole grid width when the
   result could depend on the order (MEDIAN prediction in an inexact mode). */
static uint32_t strip_cols(const ssda_track_plan_t *p, const ssda_source_t *first,
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
        if (!holds(first, (uint32_t)aw, g->search_h) || !holds(second, (uint32_t)ww, g->win_h)) {
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
    ssda_track_plan_t plan;
    ssda_track_stats_t acc;
    ssda_rows_t frows, srows;
    stream_rows_ctx_t fctx, sctx;
    ssda_rect_t all_f, all_s;
    uint32_t k, c0;
    int err;

    if (first == NULL || second == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!stream_ready(first) || !stream_ready(second)) {
        return SSDA_ERR_STATE;
    }
    if (first == second && first->view == NULL) {
        return SSDA_ERR_ARG; /* one plate cannot hold both images' rows */
    }
    if (first->cfg.format != second->cfg.format) {
        return SSDA_ERR_FORMAT;
    }
    err = ssda_track_plan(cfg != NULL ? cfg : &defaults, second->cfg.format,
                          second->cfg.width, second->cfg.height, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    if (out_count < plan.grid.count) {
        return SSDA_ERR_BUFFER;
    }
    /* The tracker fetches whole area rows (mask test, bounds) and whole
       window rows: the narrowest plates that can serve it. */
    if (!holds(first, plan.grid.search_w, 1u) || !holds(second, plan.grid.win_w, 1u)) {
        return SSDA_ERR_BUFFER;
    }
    (void)stream_rect(first, NULL, &all_f);
    (void)stream_rect(second, NULL, &all_s);
    stream_rows_make(&frows, &fctx, first, &all_f);
    stream_rows_make(&srows, &sctx, second, &all_s);
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
        /* Plates as wide as the strip, sliding down one grid step at a
           time (checked above: each holds at least one row). */
        bool inside = strip_rects(&plan.grid, first, c0, c1, &ar, &wr);
        if (first->view == NULL && inside) {
            (void)stream_plate_plan(first, &ar, plan.grid.search_w, plan.grid.search_h,
                                    plan.grid.step_y);
        }
        if (second->view == NULL && inside) {
            (void)stream_plate_plan(second, &wr, plan.grid.win_w, plan.grid.win_h,
                                    plan.grid.step_y);
        }
        err = ssda_track_strip(&frows, &srows, &plan, c0, c1, out, &acc);
        if (err != SSDA_OK) {
            return err;
        }
    }
    if (stats != NULL) {
        *stats = acc;
    }
    return SSDA_OK;
}
