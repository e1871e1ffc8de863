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
                        uint32_t c0, uint32_t c1, ssda_rect_t *area, ssda_rect_t *win,
                        uint32_t *row_lo, uint32_t *row_hi)
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
    *row_lo = y_lo;
    *row_hi = y_hi;
    return true;
}

/* Does the plate of a streamed source, shaped for region r, hold all of
   it across and `rows` rows of it? (In-RAM sources: always.) */
static bool holds_band(const ssda_source_t *s, const ssda_rect_t *r, uint32_t rows)
{
    return s->view != NULL || (s->pw >= r->width && s->ph >= rows);
}

/* The row source and origin of one image for the band whose top-left is
   (x, y): the plate moved there (kept inside the region), or the whole
   image in RAM. Returns SSDA_OK or a read error. */
static int band_rows(ssda_source_t *s, const ssda_rect_t *r, uint32_t x, uint32_t y,
                     ssda_rows_t *rows, uint32_t *ox, uint32_t *oy)
{
    int err;
    if (s->view != NULL) {
        ssda_rect_t all;
        (void)stream_rect(s, NULL, &all);
        stream_rows_make(rows, NULL, s, &all);
        *ox = 0u;
        *oy = 0u;
        return SSDA_OK;
    }
    if (y > (uint32_t)r->y + r->height - s->ph) {
        y = (uint32_t)r->y + r->height - s->ph;
    }
    err = stream_plate_place(s, x, y);
    if (err != SSDA_OK) {
        return err;
    }
    rows->base = (const uint8_t *)s->cfg.arena;
    rows->stride = s->pitch;
    rows->fetch = NULL;
    rows->ctx = NULL;
    rows->width = s->pw;
    rows->height = s->ph;
    rows->format = s->cfg.format;
    *ox = x;
    *oy = y;
    return SSDA_OK;
}

/* Solve the strip [c0, c1) grid row by grid row on bands of the plates. */
static int strip_on_bands(ssda_source_t *first, ssda_source_t *second,
                          ssda_track_plan_t *plan, uint32_t c0, uint32_t c1,
                          const ssda_rect_t *ar, const ssda_rect_t *wr, uint32_t lo,
                          uint32_t hi, const ssda_rows_t *whole_f, const ssda_rows_t *whole_s,
                          ssda_track_vector_t *out, ssda_track_stats_t *acc)
{
    const ssda_track_grid_t *g = &plan->grid;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    uint32_t r;
    int err = SSDA_OK;
    /* rows whose areas leave FIRST are EDGE: nothing is read for them */
    if (lo > 0u) {
        err = ssda_track_part(whole_f, whole_s, plan, c0, c1, 0u, lo, NULL, out, acc);
    }
    for (r = lo; r <= hi && err == SSDA_OK; r++) {
        const uint32_t wy = g->roi_y + r * g->step_y;
        ssda_track_origin_t o;
        ssda_rows_t fr, sr;
        err = band_rows(first, ar, ar->x, wy - hy, &fr, &o.first_x, &o.first_y);
        if (err == SSDA_OK) {
            err = band_rows(second, wr, wr->x, wy, &sr, &o.second_x, &o.second_y);
        }
        if (err == SSDA_OK) {
            o.first_w = first->cfg.width;
            o.first_h = first->cfg.height;
            err = ssda_track_part(&fr, &sr, plan, c0, c1, r, r + 1u, &o, out, acc);
        }
    }
    if (err == SSDA_OK && hi + 1u < g->rows) {
        err = ssda_track_part(whole_f, whole_s, plan, c0, c1, hi + 1u, g->rows, NULL, out, acc);
    }
    return err;
}

/* Bounce bytes beyond the minimum that let a tiled source read the rows a
   band gains at each grid step (up to a tile's height) in one read per
   tile: (run - 1) rows of a tile. Raster strips read row by row. */
static size_t run_extra(const ssda_source_t *s, uint32_t step_y)
{
    uint32_t run;
    if (s->view != NULL || s->cfg.layout != (uint8_t)SSDA_LAYOUT_TILED) {
        return 0u;
    }
    run = step_y < s->cfg.tile_h ? step_y : s->cfg.tile_h;
    return (size_t)(run - 1u) * s->cfg.stride;
}

/* Does a streamed source hold a plate of w x h (and the bounce room for
   runs of extra bytes)? In-RAM sources always do. */
static bool holds(const ssda_source_t *s, uint32_t w, uint32_t h, size_t extra)
{
    return s->view != NULL || stream_plate_fit_h(s, w, extra) >= h;
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
        if (!holds(first, (uint32_t)aw, g->search_h, run_extra(first, g->step_y)) ||
            !holds(second, (uint32_t)ww, g->win_h, run_extra(second, g->step_y))) {
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
    if (!holds(first, plan.grid.search_w, 1u, 0u) || !holds(second, plan.grid.win_w, 1u, 0u)) {
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
        uint32_t lo, hi;
        /* Plates as wide as the strip, sliding down one grid step at a
           time (checked above: each holds at least one row). */
        bool inside = strip_rects(&plan.grid, first, c0, c1, &ar, &wr, &lo, &hi);
        if (first->view == NULL && inside) {
            (void)stream_plate_plan(first, &ar, plan.grid.search_w, plan.grid.search_h,
                                    plan.grid.step_y, run_extra(first, plan.grid.step_y));
        }
        if (second->view == NULL && inside) {
            (void)stream_plate_plan(second, &wr, plan.grid.win_w, plan.grid.win_h,
                                    plan.grid.step_y, run_extra(second, plan.grid.step_y));
        }
        if (inside && holds_band(first, &ar, plan.grid.search_h) &&
            holds_band(second, &wr, plan.grid.win_h)) {
            err = strip_on_bands(first, second, &plan, c0, c1, &ar, &wr, lo, hi, &frows,
                                 &srows, out, &acc);
        } else {
            err = ssda_track_strip(&frows, &srows, &plan, c0, c1, out, &acc);
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
