/*
 * stream_push.c - push mode: the rows of an image arrive one at a time; a
 * search, or a grid row of tracking, runs in the push that brings the last
 * row it needs, on the rows kept in the ring as on an image in RAM.
 *
 * The init functions check everything and resolve the job into the push
 * state (the plan of the search or of the tracking, the plate of a streamed
 * other image, the rows the next search waits for); a push only executes
 * it. The ring keeps only the columns the job uses, rows in image order
 * from first_row; when it is full, the rows still needed slide to its
 * start (slide.h), so a band is always contiguous.
 */
#include <string.h>
#include "stream_internal.h"
#include "track_rows.h"
#include "slide.h"
#include "compiler.h"

enum { STATE_STOPPED = 0, STATE_MATCH = 1, STATE_TRACK = 2, STATE_DONE = 3 };

static bool format_ok(uint32_t format)
{
    return format == (uint32_t)SSDA_PIX_U8 || format == (uint32_t)SSDA_PIX_U16;
}

/* The checks both jobs share: pointers, the other source's state, formats
   and the pushed image's size. */
static int check_common(const ssda_push_t *push, const ssda_push_config_t *cfg,
                        const void *output)
{
    if (push == NULL || cfg == NULL || cfg->other == NULL || output == NULL ||
        cfg->ring == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(cfg->other)) {
        return SSDA_ERR_STATE;
    }
    return SSDA_OK;
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

/* The state both jobs share, once everything is checked: *p filled in
   place (no copy of the push state on the stack), the ring of rows of
   columns x0 .. x0+w-1. */
static void setup(ssda_push_t *p, const ssda_push_config_t *cfg, uint32_t x0, uint32_t w,
                  uint8_t state)
{
    size_t pitch = SSDA_STREAM_PITCH(w, (uint32_t)cfg->format);
    size_t cap = cfg->ring_size / pitch;
    (void)memset(p, 0, sizeof *p);
    p->height = cfg->height;
    p->format = (uint8_t)cfg->format;
    p->other = cfg->other;
    p->ring = (uint8_t *)cfg->ring;
    p->pitch = (uint32_t)pitch; /* <= 4 * 65535 */
    p->cap = (uint16_t)(cap > SSDA_MAX_DIM ? SSDA_MAX_DIM : cap);
    p->x0 = (uint16_t)x0;
    p->w = (uint16_t)w;
    p->state = state;
    p->magic = SSDA__MAGIC_PUSH;
}

/* The search's rectangles: the area in the pushed image, the window in
   the other source; SSDA_OK or SSDA_ERR_SIZE. */
static int match_rects(const ssda_push_config_t *cfg, ssda_rect_t *area, ssda_rect_t *wr)
{
    int err;
    area->x = 0u;
    area->y = 0u;
    area->width = cfg->width;
    area->height = cfg->height;
    if (cfg->area_rect != NULL) {
        *area = *cfg->area_rect;
    }
    if (cfg->width == 0u || cfg->height == 0u || area->width == 0u || area->height == 0u ||
        (uint32_t)area->x + area->width > cfg->width ||
        (uint32_t)area->y + area->height > cfg->height) {
        return SSDA_ERR_SIZE;
    }
    err = ssda__stream_rect(cfg->other, cfg->window_rect, wr);
    if (err == SSDA_OK && (wr->width > area->width || wr->height > area->height)) {
        err = SSDA_ERR_SIZE;
    }
    return err;
}

int ssda_push_init_match(ssda_push_t *push, const ssda_push_config_t *cfg,
                         const ssda_match_config_t *match, ssda_match_result_t *result)
{
    ssda_match_plan_t plan;
    ssda_rect_t area, wr;
    int err = check_common(push, cfg, result);
    if (err != SSDA_OK) {
        return err;
    }
    if (!format_ok((uint32_t)cfg->format) || cfg->other->cfg.format != (uint8_t)cfg->format) {
        return SSDA_ERR_FORMAT;
    }
    err = match_rects(cfg, &area, &wr);
    if (err != SSDA_OK) {
        return err;
    }
    if (match == NULL) {
        match = &ssda__match_defaults;
    }
    err = ssda__match_plan(match, area.width, area.height, wr.width, wr.height, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    if (!ssda__stream_holds(cfg->other, wr.width, wr.height, 0u)) {
        return SSDA_ERR_BUFFER; /* the window is read once, whole (issue 22) */
    }
    err = ring_fits((uint8_t)cfg->format, area.width, area.height, cfg->ring, cfg->ring_size,
                    cfg->other);
    if (err != SSDA_OK) {
        return err;
    }
    setup(push, cfg, area.x, area.width, STATE_MATCH);
    push->area = area;
    push->other_rect = wr;
    push->plan.match = plan;
    push->predict_x = match->predict_x;
    push->predict_y = match->predict_y;
    push->result = result;
    push->need_from = area.y;
    push->ready_at = (uint16_t)(area.y + area.height); /* inside the image */
    if (cfg->other->view == NULL) {
        /* the window's whole rectangle, read once (checked: a row fits) */
        (void)ssda__stream_plate_plan(push->other, &wr, wr.width, wr.height, 0u, 0u,
                                      &push->other_plate);
    }
    return SSDA_OK;
}

/* First image row grid row r's band needs (tracking). */
static uint32_t band_top(const ssda_push_t *p, uint32_t r)
{
    const ssda_track_grid_t *g = &p->plan.grid;
    const uint32_t wy = g->roi_y + r * g->step_y;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    if (p->role == (uint8_t)SSDA_PUSH_FIRST) {
        return wy >= hy ? wy - hy : 0u;
    }
    return wy;
}

/* Rows of the pushed image's band (search_h rows of FIRST, win_h of SECOND). */
static uint32_t band_rows(const ssda_push_t *p)
{
    const ssda_track_grid_t *g = &p->plan.grid;
    return p->role == (uint8_t)SSDA_PUSH_FIRST ? g->search_h : g->win_h;
}

/* After grid row next_grid_row - 1 is solved (or at init): the rows the
   next one waits for, and the first row it keeps. */
static void track_next(ssda_push_t *p)
{
    const uint32_t r = p->next_grid_row;
    if (r >= p->row_lo && r <= p->row_hi) {
        p->ready_at = (uint16_t)(band_top(p, r) + band_rows(p)); /* inside the image */
    } else {
        p->ready_at = 0u; /* an EDGE row reads nothing: solved in the next push */
    }
    p->need_from = (uint16_t)band_top(p, r);
}

/* The tracking job's images: FIRST's and SECOND's sizes, the pushed
   image's rectangle of columns kept and band height, and the other
   image's rectangle. SSDA_OK or an argument error. */
static int track_layout(const ssda_push_config_t *cfg, const ssda_track_config_t *track,
                        ssda_track_plan_t *plan, ssda_rect_t *kept, ssda_rect_t *oreg,
                        uint32_t *lo, uint32_t *hi)
{
    const bool first = cfg->role == SSDA_PUSH_FIRST;
    const ssda_source_t *other = cfg->other;
    const uint32_t fw = first ? cfg->width : other->cfg.width;
    const uint32_t fh = first ? cfg->height : other->cfg.height;
    ssda_rect_t ar, wr;
    int err = ssda__track_plan(track, (uint8_t)cfg->format, fw, fh,
                               first ? other->cfg.width : cfg->width,
                               first ? other->cfg.height : cfg->height, plan);
    if (err != SSDA_OK) {
        return err;
    }
    kept->x = 0u;
    kept->width = 1u;
    kept->height = 1u; /* every window EDGE: a one-pixel ring */
    *lo = plan->grid.rows;
    *hi = 0u;
    *oreg = *kept;
    if (ssda__stream_grid_rects(&plan->grid, fw, fh, 0u, plan->grid.cols, &ar, &wr, lo, hi)) {
        *kept = first ? ar : wr;
        kept->height = first ? plan->grid.search_h : plan->grid.win_h;
        *oreg = first ? wr : ar;
    }
    return SSDA_OK;
}

int ssda_push_init_track(ssda_push_t *push, const ssda_push_config_t *cfg,
                         const ssda_track_config_t *track, ssda_track_vector_t *out,
                         size_t out_count, ssda_track_stats_t *stats)
{
    ssda_track_plan_t plan;
    ssda_rect_t kept, oreg;
    uint32_t lo, hi;
    bool first;
    int err = check_common(push, cfg, out);
    if (err != SSDA_OK) {
        return err;
    }
    if ((uint32_t)cfg->role > (uint32_t)SSDA_PUSH_SECOND) {
        return SSDA_ERR_ARG;
    }
    if (!format_ok((uint32_t)cfg->format) || cfg->other->cfg.format != (uint8_t)cfg->format) {
        return SSDA_ERR_FORMAT;
    }
    if (cfg->width == 0u || cfg->height == 0u) {
        return SSDA_ERR_SIZE;
    }
    first = cfg->role == SSDA_PUSH_FIRST;
    err = track_layout(cfg, track != NULL ? track : &ssda__track_defaults, &plan, &kept, &oreg, &lo, &hi);
    if (err != SSDA_OK) {
        return err;
    }
    /* the other image's band as wide as the grid (lo > hi: nothing is read,
       a row will do): grid rows are solved whole, so a narrower plate would
       re-read its rows without bound (issue 22) */
    if (!ssda__track_out_fits(plan.grid.count, out_count) ||
        !ssda__stream_holds(cfg->other, lo <= hi ? oreg.width : 1u,
                            lo <= hi ? (first ? plan.grid.win_h : plan.grid.search_h) : 1u, 0u)) {
        return SSDA_ERR_BUFFER;
    }
    err = ring_fits((uint8_t)cfg->format, kept.width, kept.height, cfg->ring, cfg->ring_size,
                    cfg->other);
    if (err != SSDA_OK) {
        return err;
    }
    setup(push, cfg, kept.x, kept.width, STATE_TRACK);
    push->role = (uint8_t)cfg->role;
    push->plan = plan;
    push->out = out;
    push->stats = stats;
    push->row_lo = (uint16_t)lo;
    push->row_hi = (uint16_t)hi;
    if (lo <= hi && cfg->other->view == NULL) {
        /* the other image's bands, sliding down one grid step at a time */
        ssda__stream_band_plan(push->other, &oreg, oreg.width,
                               first ? plan.grid.win_h : plan.grid.search_h, plan.grid.step_y,
                               &push->other_plate);
    }
    track_next(push);
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
        ssda__slide(p->ring, (size_t)d * p->pitch, (size_t)p->count * p->pitch);
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
    ssda__rows_mem(rows, p->ring + (size_t)(top - p->first_row) * p->pitch, p->pitch, p->w,
                   band, p->format);
}

/* The search, once the area's last row is in. Returns 1 or a read error.
   run_match and run_track stay out of ssda_push_row: each has its own
   locals (row sources, an origin), which would otherwise add up on the
   frame above the search. */
static SSDA_NOINLINE int run_match(ssda_push_t *p)
{
    ssda__rows_t a, w;
    int err;
    if (p->other->view == NULL) {
        ssda__stream_plate_use(p->other, &p->other_plate);
    }
    ring_rows(p, p->area.y, p->area.height, &a);
    ssda__stream_rows(&w, p->other, &p->other_rect);
    err = ssda__match_rows(&a, &w, &p->plan.match, p->predict_x, p->predict_y, p->result);
    return err != SSDA_OK ? err : 1;
}

/* Grid row r, whose band is complete: the pushed band from the ring, the
   other image's band (or its whole rows), placed by their origin. */
static int solve_row(ssda_push_t *p, uint32_t r)
{
    const bool first = p->role == (uint8_t)SSDA_PUSH_FIRST;
    const ssda_track_grid_t *g = &p->plan.grid;
    const uint32_t wy = g->roi_y + r * g->step_y;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    const uint32_t top = first ? wy - hy : wy;
    ssda__track_origin_t o;
    ssda__rows_t pushed, other;
    uint32_t ox = 0u, oy = 0u;
    ring_rows(p, top, band_rows(p), &pushed);
    ssda__stream_rows(&other, p->other, NULL);
    if (p->other->view == NULL) {
        /* the plate holds a whole-width band (checked at init) */
        int err;
        ssda__stream_plate_use(p->other, &p->other_plate);
        err = ssda__stream_band_rows(p->other, p->other_plate.region.x, first ? wy : wy - hy,
                                     &other, &ox, &oy);
        if (err != SSDA_OK) {
            return err;
        }
    }
    o.first_x = first ? p->x0 : ox;
    o.first_y = first ? top : oy;
    o.second_x = first ? ox : p->x0;
    o.second_y = first ? oy : top;
    return ssda__track_part(first ? &pushed : &other, first ? &other : &pushed, &p->plan, 0u,
                            g->cols, r, r + 1u, &o, p->out, &p->acc);
}

/* Solve the grid rows whose bands are complete, in order (called once the
   next one is ready). Returns how many were solved, or a read error. */
static SSDA_NOINLINE int run_track(ssda_push_t *p, uint32_t rows_in)
{
    const uint32_t rows = p->plan.grid.rows;
    int solved = 0;
    while (p->next_grid_row < rows && rows_in >= p->ready_at) {
        const uint32_t r = p->next_grid_row;
        int err;
        if (r >= p->row_lo && r <= p->row_hi) {
            err = solve_row(p, r);
        } else {
            /* EDGE row: no pixel is read, any row sources do */
            ssda__rows_t none;
            ring_rows(p, p->first_row, 0u, &none);
            err = ssda__track_part(&none, &none, &p->plan, 0u, p->plan.grid.cols, r, r + 1u,
                                   &ssda__track_origin_whole, p->out, &p->acc);
        }
        if (err != SSDA_OK) {
            return err;
        }
        p->next_grid_row++;
        track_next(p);
        solved++;
    }
    if (p->next_grid_row == rows) {
        if (p->stats != NULL) {
            *p->stats = p->acc;
        }
        p->state = STATE_DONE;
    }
    return solved;
}

int ssda_push_row(ssda_push_t *push, const void *row)
{
    uint32_t y;
    int done;
    if (push == NULL || row == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(push->magic, SSDA__MAGIC_PUSH) || push->state == STATE_STOPPED ||
        push->next_row >= push->height) {
        return SSDA_ERR_STATE;
    }
    y = push->next_row;
    push->next_row++;
    if (push->state == STATE_DONE) {
        return 0;
    }
    /* A search ends in the push of its area's last row (DONE or STOPPED
       above), so here y is never below the area in a search. */
    if (y >= push->need_from) {
        ring_put(push, y, (const uint8_t *)row, push->need_from);
    }
    if (y + 1u < push->ready_at) {
        return 0; /* the next search waits for more rows */
    }
    if (push->state == STATE_MATCH) {
        done = run_match(push);
        push->state = (uint8_t)(done < 0 ? STATE_STOPPED : STATE_DONE);
        return done;
    }
    done = run_track(push, y + 1u);
    if (done < 0) {
        push->state = STATE_STOPPED;
    }
    return done;
}
