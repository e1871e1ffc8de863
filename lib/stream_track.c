/*
 * stream_track.c - grid tracking with FIRST and/or SECOND streamed: the grid
 * is solved in vertical strips of grid columns, each top to bottom, so the
 * strip's band of search areas (FIRST) and of windows (SECOND) slide down
 * through the plates and every byte is read about once.
 *
 * The job is planned once: the tracking plan, the strip width (from the
 * widest band each arena holds), and per strip the plate plans; solving a
 * strip only executes them. When the plates hold a whole band, each grid
 * row of the strip is solved on the plates as images in RAM (row sources in
 * memory, placed by an origin): the engine runs at in-RAM speed, with no
 * call per row. Otherwise the tracker fetches rows through the plate cache.
 */
#include <string.h>
#include "stream_internal.h"
#include "track_rows.h"

/* One strip of the job: its grid columns, rectangles and grid rows. */
typedef struct {
    uint32_t c0, c1;   /* grid columns [c0, c1) */
    ssda_rect_t ar;    /* the strip's search areas in FIRST */
    ssda_rect_t wr;    /* its windows in SECOND */
    uint32_t lo, hi;   /* grid rows whose areas lie inside FIRST */
    bool banded;       /* both plates hold a whole band: solved on bands */
} strip_t;

/* Solve the strip grid row by grid row on bands of the plates. */
static int strip_on_bands(ssda_source_t *first, ssda_source_t *second,
                          const ssda_track_plan_t *plan, const strip_t *st,
                          const ssda__rows_t *whole_f, const ssda__rows_t *whole_s,
                          ssda_track_vector_t *out, ssda_track_stats_t *acc)
{
    const ssda_track_grid_t *g = &plan->grid;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    uint32_t r;
    int err = SSDA_OK;
    /* rows whose areas leave FIRST are EDGE: nothing is read for them */
    if (st->lo > 0u) {
        err = ssda__track_part(whole_f, whole_s, plan, st->c0, st->c1, 0u, st->lo,
                               &ssda__track_origin_whole, out, acc);
    }
    for (r = st->lo; r <= st->hi && err == SSDA_OK; r++) {
        const uint32_t wy = g->roi_y + r * g->step_y;
        ssda__track_origin_t o;
        ssda__rows_t fr, sr;
        err = ssda__stream_band_rows(first, st->ar.x, wy - hy, &fr, &o.first_x, &o.first_y);
        if (err == SSDA_OK) {
            err = ssda__stream_band_rows(second, st->wr.x, wy, &sr, &o.second_x, &o.second_y);
        }
        if (err == SSDA_OK) {
            err = ssda__track_part(&fr, &sr, plan, st->c0, st->c1, r, r + 1u, &o, out, acc);
        }
    }
    if (err == SSDA_OK && st->hi + 1u < g->rows) {
        err = ssda__track_part(whole_f, whole_s, plan, st->c0, st->c1, st->hi + 1u, g->rows,
                               &ssda__track_origin_whole, out, acc);
    }
    return err;
}

/* Widest band of `rows` rows a streamed source's arena holds (as the
   strips' plates are planned: with a tiled source's run room); any width
   for an image in RAM. */
static uint32_t band_width(const ssda_source_t *s, uint32_t rows, uint32_t step_y)
{
    return s->view != NULL ? UINT32_MAX
                           : ssda__stream_plate_fit_w(s, rows, ssda__stream_run_extra(s, step_y));
}

/* Does the result depend on the order windows are solved in? With MEDIAN
   prediction, yes in every mode: the prediction needs the up-right
   neighbour, which a strip's right-edge window lacks, and it steers the
   scan (inexact modes) and picks among equal SADs (the tie rule, exact
   modes too). Then one full-width strip is used. */
static bool order_matters(const ssda_track_plan_t *p)
{
    return p->predict == (uint8_t)SSDA_TRACK_PREDICT_MEDIAN;
}

/* Grid columns per strip: as many as keep the strip's areas (search_h rows)
   and windows (win_h rows) in the plates; the whole grid width when the
   result could depend on the order (MEDIAN prediction). */
static uint32_t strip_cols(const ssda_track_plan_t *p, const ssda_source_t *first,
                           const ssda_source_t *second)
{
    const ssda_track_grid_t *g = &p->grid;
    const uint32_t fit_f = band_width(first, g->search_h, g->step_y);
    const uint32_t fit_s = band_width(second, g->win_h, g->step_y);
    uint32_t k = 1u;
    if (order_matters(p)) {
        return g->cols;
    }
    while (k < g->cols) {
        size_t aw = SSDA_STREAM_STRIP_W(k + 1u, g->step_x, g->search_w);
        size_t ww = SSDA_STREAM_STRIP_W(k + 1u, g->step_x, g->win_w);
        if (aw > first->cfg.width) {
            aw = first->cfg.width;
        }
        if (aw > fit_f || ww > fit_s) {
            break;
        }
        k++;
    }
    return k;
}

/* Plan the strip [c0, c1): its rectangles, and plates as wide as the strip
   sliding down one grid step at a time (each holds at least one row,
   checked by the caller). */
static void plan_strip(ssda_source_t *first, ssda_source_t *second,
                       const ssda_track_plan_t *plan, strip_t *st)
{
    const ssda_track_grid_t *g = &plan->grid;
    st->banded = ssda__stream_grid_rects(g, plan->first_w, plan->first_h, st->c0, st->c1,
                                         &st->ar, &st->wr, &st->lo, &st->hi);
    if (!st->banded) {
        return; /* no window reads anything */
    }
    ssda__stream_band_plan(first, &st->ar, g->search_w, g->search_h, g->step_y, &first->plate);
    ssda__stream_band_plan(second, &st->wr, g->win_w, g->win_h, g->step_y, &second->plate);
}

/* The arena each image needs (issue 22): a band of the strip of one grid
   column (search_h rows of search_w px in FIRST, win_h rows of win_w px in
   SECOND), or of every column (`full`: one full-width strip, when the
   result depends on the order); any less would fetch rows through the
   plate as the tracker asks, re-reading them without bound. A row is
   enough when no window reads pixels. */
/* Does s's arena hold a band of w x h px, w capped at the image width (a
   grid's search width may exceed an image no area lies inside)? */
static bool holds_band(const ssda_source_t *s, uint32_t w, uint32_t h)
{
    return ssda__stream_holds(s, w < s->cfg.width ? w : s->cfg.width, h, 0u);
}

static bool arenas_hold_bands(const ssda_track_plan_t *p, const ssda_source_t *first,
                              const ssda_source_t *second, bool full)
{
    const ssda_track_grid_t *g = &p->grid;
    ssda_rect_t ar, wr;
    uint32_t lo, hi;
    if (!ssda__stream_grid_rects(g, p->first_w, p->first_h, 0u, g->cols, &ar, &wr, &lo, &hi)) {
        return holds_band(first, g->search_w, 1u) && holds_band(second, g->win_w, 1u);
    }
    return holds_band(first, full ? ar.width : g->search_w, g->search_h) &&
           holds_band(second, full ? wr.width : g->win_w, g->win_h);
}

int ssda_stream_track(ssda_source_t *first, ssda_source_t *second,
                      const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                      size_t out_count, ssda_track_stats_t *stats)
{
    ssda_track_plan_t plan;
    ssda_track_stats_t acc;
    ssda__rows_t frows, srows;
    strip_t st;
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
    err = ssda__track_plan(cfg != NULL ? cfg : &ssda__track_defaults, second->cfg.format, first->cfg.width,
                           first->cfg.height, second->cfg.width, second->cfg.height, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    if (!ssda__track_out_fits(plan.grid.count, out_count)) {
        return SSDA_ERR_BUFFER;
    }
    k = strip_cols(&plan, first, second);
    if (!arenas_hold_bands(&plan, first, second, order_matters(&plan))) {
        return SSDA_ERR_BUFFER;
    }
    ssda__stream_rows(&frows, first, NULL);
    ssda__stream_rows(&srows, second, NULL);
    (void)memset(&acc, 0, sizeof acc);
    for (c0 = 0u; c0 < plan.grid.cols; c0 += k) {
        st.c0 = c0;
        st.c1 = plan.grid.cols - c0 > k ? c0 + k : plan.grid.cols;
        plan_strip(first, second, &plan, &st);
        if (st.banded) {
            err = strip_on_bands(first, second, &plan, &st, &frows, &srows, out, &acc);
        } else {
            err = ssda__track_strip(&frows, &srows, &plan, st.c0, st.c1, out, &acc);
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
