/*
 * stream_push.c - push mode: the rows of an image arrive one at a time; a
 * search, or a grid row of tracking, runs in the push that brings the last
 * row it needs, on the rows kept in the ring as on an image in RAM.
 *
 * The ring keeps only the columns the job uses, rows in image order from
 * first_row; when it is full, the rows still needed move to its start
 * (row by row, never overlapping), so a band is always contiguous.
 */
#include <string.h>
#include "stream_internal.h"
#include "track_rows.h"
#include "compiler.h"

enum { KIND_STOPPED = 0, KIND_MATCH = 1, KIND_TRACK = 2, KIND_DONE = 3 };

static bool format_ok(uint8_t format)
{
    return format == (uint8_t)SSDA_PIX_U8 || format == (uint8_t)SSDA_PIX_U16;
}

/* Whether ring (ring_size bytes) holds `band` rows of w px: SSDA_OK or
   SSDA_ERR_BUFFER (also for a misaligned ring); SSDA_ERR_ARG when it
   overlaps the other source's plate (each would overwrite the other). */
static int ring_fits(uint8_t format, uint32_t w, uint32_t band, const void *ring,
                     size_t ring_size, const ssda_source_t *other)
{
    size_t pitch = SSDA_STREAM_PITCH(w, format);
    if ((((uintptr_t)ring) & 3u) != 0u || ring_size / pitch < band) {
        return SSDA_ERR_BUFFER;
    }
    if (ssda__stream_plate_overlaps(other, ring, ring_size)) {
        return SSDA_ERR_ARG;
    }
    return SSDA_OK;
}

/* Ring of rows of columns x0 .. x0+w-1 (checked by ring_fits; p->format set). */
static void ring_setup(ssda_push_t *p, uint32_t x0, uint32_t w, void *ring, size_t ring_size)
{
    size_t pitch = SSDA_STREAM_PITCH(w, p->format);
    size_t cap = ring_size / pitch;
    p->ring = (uint8_t *)ring;
    p->pitch = (uint32_t)pitch; /* <= 4 * 65535 */
    p->cap = (uint16_t)(cap > SSDA_MAX_DIM ? SSDA_MAX_DIM : cap);
    p->x0 = (uint16_t)x0;
    p->w = (uint16_t)w;
}

/* The init functions check everything before they write *push (outputs
   untouched on error) and then fill it in place: no copy of the push
   state on the stack. */
int ssda_push_init_match(ssda_push_t *push, uint16_t width, uint16_t height, uint8_t format,
                         const ssda_rect_t *area_rect, ssda_source_t *window,
                         const ssda_rect_t *window_rect, const ssda_match_config_t *cfg,
                         ssda_match_result_t *result, void *ring, size_t ring_size)
{
    static const ssda_match_config_t defaults;
    ssda_rect_t area, wr;
    int err;
    if (push == NULL || window == NULL || result == NULL || ring == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(window)) {
        return SSDA_ERR_STATE;
    }
    if (!format_ok(format) || window->cfg.format != format) {
        return SSDA_ERR_FORMAT;
    }
    area.x = 0u;
    area.y = 0u;
    area.width = width;
    area.height = height;
    if (area_rect != NULL) {
        area = *area_rect;
    }
    if (width == 0u || height == 0u || area.width == 0u || area.height == 0u ||
        (uint32_t)area.x + area.width > width ||
        (uint32_t)area.y + area.height > height) {
        return SSDA_ERR_SIZE;
    }
    err = ssda__stream_rect(window, window_rect, &wr);
    if (err != SSDA_OK) {
        return err;
    }
    if (wr.width > area.width || wr.height > area.height) {
        return SSDA_ERR_SIZE;
    }
    if (cfg == NULL) {
        cfg = &defaults;
    }
    err = ssda__match_check_config(cfg, area.width, area.height, wr.width, wr.height);
    if (err != SSDA_OK) {
        return err;
    }
    if (!ssda__stream_holds(window, wr.width, 1u, 0u)) {
        return SSDA_ERR_BUFFER;
    }
    err = ring_fits(format, area.width, area.height, ring, ring_size, window);
    if (err != SSDA_OK) {
        return err;
    }
    (void)memset(push, 0, sizeof *push);
    push->width = width;
    push->height = height;
    push->format = format;
    push->area = area;
    push->match = *cfg;
    ring_setup(push, area.x, area.width, ring, ring_size);
    push->other = window;
    push->other_rect = wr;
    push->result = result;
    push->kind = KIND_MATCH;
    return SSDA_OK;
}

/* FIRST's and SECOND's sizes: one is pushed, the other is p->other. */
static void image_sizes(const ssda_push_t *p, uint32_t *fw, uint32_t *fh, uint32_t *sw,
                        uint32_t *sh)
{
    const bool first = p->role == (uint8_t)SSDA_PUSH_FIRST;
    *fw = first ? p->width : p->other->cfg.width;
    *fh = first ? p->height : p->other->cfg.height;
    *sw = first ? p->other->cfg.width : p->width;
    *sh = first ? p->other->cfg.height : p->height;
}

int ssda_push_init_track(ssda_push_t *push, uint16_t width, uint16_t height, uint8_t format,
                         uint8_t role, ssda_source_t *other, const ssda_track_config_t *cfg,
                         ssda_track_vector_t *out, size_t out_count, ssda_track_stats_t *stats,
                         void *ring, size_t ring_size)
{
    static const ssda_track_config_t defaults;
    ssda__track_plan_t plan;
    ssda_rect_t ar, wr;
    uint32_t fw, fh, sw, sh, lo, hi, x0 = 0u, w = 1u, band = 1u;
    bool first;
    int err;
    if (push == NULL || other == NULL || out == NULL || ring == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(other)) {
        return SSDA_ERR_STATE;
    }
    if (role > (uint8_t)SSDA_PUSH_SECOND) {
        return SSDA_ERR_ARG;
    }
    if (!format_ok(format) || other->cfg.format != format) {
        return SSDA_ERR_FORMAT;
    }
    if (width == 0u || height == 0u) {
        return SSDA_ERR_SIZE;
    }
    if (cfg == NULL) {
        cfg = &defaults;
    }
    first = role == (uint8_t)SSDA_PUSH_FIRST;
    fw = first ? width : other->cfg.width;
    fh = first ? height : other->cfg.height;
    sw = first ? other->cfg.width : width;
    sh = first ? other->cfg.height : height;
    err = ssda__track_plan(cfg, format, sw, sh, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    if (!ssda__track_out_fits(plan.grid.count, out_count) ||
        !ssda__stream_holds(other, first ? plan.grid.win_w : plan.grid.search_w, 1u, 0u)) {
        return SSDA_ERR_BUFFER;
    }
    if (ssda__stream_grid_rects(&plan.grid, fw, fh, 0u, plan.grid.cols, &ar, &wr, &lo, &hi)) {
        const ssda_rect_t *kept = first ? &ar : &wr;
        x0 = kept->x;
        w = kept->width;
        band = first ? plan.grid.search_h : plan.grid.win_h;
    } /* else every window is EDGE: a one-pixel ring */
    err = ring_fits(format, w, band, ring, ring_size, other);
    if (err != SSDA_OK) {
        return err;
    }
    (void)memset(push, 0, sizeof *push);
    push->width = width;
    push->height = height;
    push->format = format;
    push->role = role;
    push->other = other;
    push->track = *cfg;
    ring_setup(push, x0, w, ring, ring_size);
    push->out = out;
    push->out_count = out_count;
    push->stats = stats;
    push->kind = KIND_TRACK;
    return SSDA_OK;
}

/* Keep row y (pixels in `row`), dropping the rows before `from` when the
   ring is full. */
static void ring_put(ssda_push_t *p, uint32_t y, const uint8_t *row, uint32_t from)
{
    if (p->count != 0u && (uint32_t)p->first_row + p->count != y) {
        p->count = 0u; /* rows were skipped: start over */
    }
    if (p->count == 0u) {
        p->first_row = (uint16_t)y;
    }
    if (p->count == p->cap) {
        /* the pending band's rows so far are fewer than cap: d >= 1 */
        uint32_t d = from - p->first_row;
        uint32_t i;
        for (i = 0u; i + d < p->count; i++) {
            (void)memcpy(p->ring + (size_t)i * p->pitch, p->ring + (size_t)(i + d) * p->pitch, p->pitch);
        }
        p->count = (uint16_t)(p->count - d);
        p->first_row = (uint16_t)from;
    }
    (void)memcpy(p->ring + (size_t)p->count * p->pitch, row + (size_t)p->x0 * p->format,
                 (size_t)p->w * p->format);
    p->count++;
}

/* The ring's rows from image row top, band rows tall, as a row source. */
static void ring_rows(const ssda_push_t *p, uint32_t top, uint32_t band, ssda__rows_t *rows)
{
    rows->base = p->ring + (size_t)(top - p->first_row) * p->pitch;
    rows->stride = p->pitch;
    rows->fetch = NULL;
    rows->ctx = NULL;
    rows->width = p->w;
    rows->height = (uint16_t)band;
    rows->format = p->format;
}

/* The search, once the area's last row is in. Returns 1 or a read error.
   run_match, run_track and needed_from stay out of ssda_push_row: each
   has its own locals (a plan, row sources), which would otherwise add up
   on the frame above the search. */
static SSDA_NOINLINE int run_match(ssda_push_t *p)
{
    ssda__rows_t a, w;
    ssda__stream_rows_ctx_t wctx;
    if (p->other->view == NULL) {
        (void)ssda__stream_plate_plan(p->other, &p->other_rect, p->other_rect.width,
                                p->other_rect.height, 0u, 0u);
    }
    ring_rows(p, p->area.y, p->area.height, &a);
    ssda__stream_rows_make(&w, &wctx, p->other, &p->other_rect);
    {
        int err = ssda__match_rows(&a, &w, &p->match, p->result);
        return err != SSDA_OK ? err : 1;
    }
}

/* Solve the grid rows whose bands are complete, in order. Returns how many
   were solved, or a read error. */
static SSDA_NOINLINE int run_track(ssda_push_t *p, uint32_t rows_in)
{
    const bool first = p->role == (uint8_t)SSDA_PUSH_FIRST;
    ssda__track_plan_t plan;
    ssda_rect_t ar, wr, all;
    ssda__rows_t pushed, whole;
    ssda__stream_rows_ctx_t wctx;
    uint32_t fw, fh, sw, sh, lo = 1u, hi = 0u, hy, band;
    int solved = 0;
    image_sizes(p, &fw, &fh, &sw, &sh);
    (void)ssda__track_plan(&p->track, p->format, sw, sh, &plan); /* checked at init */
    hy = ((uint32_t)plan.grid.search_h - plan.grid.win_h) / 2u;
    band = first ? plan.grid.search_h : plan.grid.win_h;
    if (!ssda__stream_grid_rects(&plan.grid, fw, fh, 0u, plan.grid.cols, &ar, &wr, &lo, &hi)) {
        lo = plan.grid.rows; /* no grid row reads anything */
        hi = 0u;
    }
    (void)ssda__stream_rect(p->other, NULL, &all);
    ssda__stream_rows_make(&whole, &wctx, p->other, &all);
    while (p->next_grid_row < plan.grid.rows) {
        const uint32_t r = p->next_grid_row;
        const uint32_t wy = plan.grid.roi_y + r * plan.grid.step_y;
        ssda__track_origin_t o;
        int err;
        o.first_w = fw;
        o.first_h = fh;
        o.first_x = 0u;
        o.first_y = 0u;
        o.second_x = 0u;
        o.second_y = 0u;
        if (r >= lo && r <= hi) {
            const uint32_t top = first ? wy - hy : wy;
            const ssda_rect_t *oreg = first ? &wr : &ar;
            const uint32_t oband = first ? plan.grid.win_h : plan.grid.search_h;
            ssda__rows_t other_rows;
            uint32_t ox = 0u, oy = 0u;
            if (rows_in < top + band) {
                break; /* the band is not complete yet */
            }
            ring_rows(p, top, band, &pushed);
            other_rows = whole;
            if (p->other->view == NULL) {
                (void)ssda__stream_plate_plan(p->other, oreg, first ? plan.grid.win_w : plan.grid.search_w,
                                        oband, plan.grid.step_y,
                                        ssda__stream_run_extra(p->other, plan.grid.step_y));
            }
            if (p->other->view == NULL && ssda__stream_holds_band(p->other, oreg, oband)) {
                err = ssda__stream_band_rows(p->other, oreg, oreg->x, first ? wy : wy - hy, &other_rows,
                                       &ox, &oy);
                if (err != SSDA_OK) {
                    return err;
                }
            }
            if (first) {
                o.first_x = p->x0;
                o.first_y = top;
                o.second_x = ox;
                o.second_y = oy;
            } else {
                o.first_x = ox;
                o.first_y = oy;
                o.second_x = p->x0;
                o.second_y = top;
            }
            err = ssda__track_part(first ? &pushed : &other_rows, first ? &other_rows : &pushed,
                                  &plan, 0u, plan.grid.cols, r, r + 1u, &o, p->out, &p->acc);
        } else {
            /* EDGE row: no pixel is read, any row sources do */
            ring_rows(p, p->first_row, 0u, &pushed);
            err = ssda__track_part(&pushed, &pushed, &plan, 0u, plan.grid.cols, r, r + 1u, &o,
                                  p->out, &p->acc);
        }
        if (err != SSDA_OK) {
            return err;
        }
        p->next_grid_row++;
        solved++;
    }
    if (p->next_grid_row == plan.grid.rows) {
        if (p->stats != NULL) {
            *p->stats = p->acc;
        }
        p->kind = KIND_DONE;
    }
    return solved;
}

/* First image row any unsolved part of the job needs (tracking: the
   pending grid row's band; search: the area's top). */
static SSDA_NOINLINE uint32_t needed_from(const ssda_push_t *p)
{
    if (p->kind == KIND_TRACK) {
        ssda__track_plan_t plan;
        uint32_t fw, fh, sw, sh, top;
        image_sizes(p, &fw, &fh, &sw, &sh);
        (void)ssda__track_plan(&p->track, p->format, sw, sh, &plan);
        top = plan.grid.roi_y + (uint32_t)p->next_grid_row * plan.grid.step_y;
        if (p->role == (uint8_t)SSDA_PUSH_FIRST) {
            uint32_t hy = ((uint32_t)plan.grid.search_h - plan.grid.win_h) / 2u;
            top = top >= hy ? top - hy : 0u;
        }
        return top;
    }
    return p->area.y;
}

int ssda_push_row(ssda_push_t *push, const void *row)
{
    uint32_t y, from;
    int done;
    if (push == NULL || row == NULL) {
        return SSDA_ERR_NULL;
    }
    if (push->kind == KIND_STOPPED || push->next_row >= push->height) {
        return SSDA_ERR_STATE;
    }
    y = push->next_row;
    push->next_row++;
    if (push->kind == KIND_DONE) {
        return 0;
    }
    from = needed_from(push);
    /* A search ends in the push of its area's last row (DONE or STOPPED
       above), so here y is never below the area in KIND_MATCH. */
    if (y >= from) {
        ring_put(push, y, (const uint8_t *)row, from);
    }
    if (push->kind == KIND_MATCH) {
        if (y + 1u != (uint32_t)push->area.y + push->area.height) {
            return 0;
        }
        done = run_match(push);
        push->kind = done < 0 ? KIND_STOPPED : KIND_DONE;
        return done;
    }
    done = run_track(push, y + 1u);
    if (done < 0) {
        push->kind = KIND_STOPPED;
    }
    return done;
}
