/* stream_band.c - grid tracking's bands: which rectangles of the images a
   strip of grid columns reads, and plates (or images in RAM) as row sources
   of one band, placed by an origin. Shared by strips and push mode. */
#include "stream_internal.h"

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
bool ssda__stream_grid_rects(const ssda_track_grid_t *g, uint32_t first_w, uint32_t first_h,
                       uint32_t c0, uint32_t c1, ssda_rect_t *area, ssda_rect_t *win,
                       uint32_t *row_lo, uint32_t *row_hi)
{
    const uint32_t hx = ((uint32_t)g->search_w - g->win_w) / 2u;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    uint32_t x_lo, x_hi, y_lo, y_hi, wx0, wx1, wy0, wy1;
    if (!inside_range(g->roi_x, g->step_x, g->cols, hx, g->search_w, first_w,
                      &x_lo, &x_hi) ||
        !inside_range(g->roi_y, g->step_y, g->rows, hy, g->search_h, first_h,
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

/* The row source and origin of one image for the band whose top-left is
   (x, y): the plate moved there (kept inside its region), or the whole
   image in RAM. Returns SSDA_OK or a read error. */
int ssda__stream_band_rows(ssda_source_t *s, uint32_t x, uint32_t y, ssda__rows_t *rows,
                           uint32_t *ox, uint32_t *oy)
{
    const ssda_source_plan_t *p = &s->plate;
    int err;
    if (s->view != NULL) {
        ssda__stream_rows(rows, s, NULL);
        *ox = 0u;
        *oy = 0u;
        return SSDA_OK;
    }
    if (y > (uint32_t)p->region.y + p->region.height - p->ph) {
        y = (uint32_t)p->region.y + p->region.height - p->ph;
    }
    err = ssda__stream_plate_place(s, x, y);
    if (err != SSDA_OK) {
        return err;
    }
    ssda__rows_mem(rows, s->cfg.arena, p->pitch, p->pw, p->ph, s->cfg.format);
    *ox = x;
    *oy = y;
    return SSDA_OK;
}

/* Bounce bytes beyond the minimum that let a tiled source read the rows a
   band gains at each grid step (up to a tile's height) in one read per
   tile: (run - 1) rows of a tile. Raster strips read row by row. */
size_t ssda__stream_run_extra(const ssda_source_t *s, uint32_t step_y)
{
    uint32_t run;
    if (s->view != NULL || STREAM_LAYOUT(&s->cfg) != (uint8_t)SSDA_LAYOUT_TILED) {
        return 0u;
    }
    run = step_y < s->cfg.tile_h ? step_y : s->cfg.tile_h;
    return (size_t)(run - 1u) * s->cfg.stride;
}

/* Plan the plate of a streamed source (in RAM: nothing) for bands of `rows`
   rows of region r sliding down q rows at a time: with a tiled source's
   run room (ssda__stream_run_extra) when the band still fits with it, else
   without, so that a band that fits the arena is always held (the job
   checked that it fits). */
void ssda__stream_band_plan(ssda_source_t *s, const ssda_rect_t *r, uint32_t span,
                            uint32_t rows, uint32_t q, ssda_source_plan_t *plan)
{
    if (s->view != NULL) {
        return;
    }
    (void)ssda__stream_plate_plan(s, r, span, rows, q, ssda__stream_run_extra(s, q), plan);
    if (!ssda__stream_plan_holds_band(plan, rows)) {
        (void)ssda__stream_plate_plan(s, r, span, rows, q, 0u, plan);
    }
}
