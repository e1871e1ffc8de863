/*
 * match_rows.h - internal: row sources, and the search engine over them, so
 * the same code serves images in RAM (ssda_match), plates and push rings
 * (stream layer) and block-streamed images read through a callback:
 * kernels always run on contiguous row spans, never a callback per pixel.
 */
#ifndef SSDA_MATCH_ROWS_H
#define SSDA_MATCH_ROWS_H

#include "ssda/match.h"
#include "compiler.h"

/*
 * Fetch pixels x .. x+n-1 of row y (all inside the image) as a contiguous
 * span: on success store its address in *px and return SSDA_OK. The span
 * stays valid until the next fetch on the same source. Any negative return
 * is an error and is passed back unchanged by the engine.
 */
typedef int (*ssda__row_fetch_fn)(void *ctx, uint32_t x, uint32_t y, uint32_t n,
                                  const uint8_t **px);

/* A row source: width x height pixels, in memory or behind a fetch. Built
   only by the constructors below. */
typedef struct {
    const uint8_t *base;      /* in memory: pixel (0, 0); NULL: rows come from fetch */
    uint32_t stride;          /* in memory: bytes between rows */
    ssda__row_fetch_fn fetch; /* when base == NULL */
    void *ctx;                /* passed to fetch */
    uint16_t x0, y0;          /* fetch: pixel (0, 0) is pixel (x0, y0) of ctx's image */
    uint16_t width;           /* pixels */
    uint16_t height;          /* rows */
    uint8_t format;           /* ssda_pixfmt_t */
} ssda__rows_t;

/* Rows in memory: w x h pixels of the format from base, rows stride bytes
   apart (a view, a plate, a push ring). */
SSDA_INTERNAL void ssda__rows_mem(ssda__rows_t *rows, const void *base, uint32_t stride,
                                  uint32_t w, uint32_t h, uint8_t format);

/* Rows of a valid view (ssda__rows_mem of its fields). */
SSDA_INTERNAL void ssda__rows_view(ssda__rows_t *rows, const ssda_view_t *view);

/* Rows of a w x h image behind a fetch callback (a streamed source). */
SSDA_INTERNAL void ssda__rows_dev(ssda__rows_t *rows, ssda__row_fetch_fn fetch, void *ctx,
                                  uint32_t w, uint32_t h, uint8_t format);

/* The one sub-rectangle constructor: *sub = the w x h rectangle at (x, y)
   of parent (inside it; sub may be parent). In memory a pointer offset, on
   a device an origin offset: never a forwarding call per row. */
SSDA_INTERNAL void ssda__rows_sub(ssda__rows_t *sub, const ssda__rows_t *parent, uint32_t x,
                                  uint32_t y, uint32_t w, uint32_t h);

/* Pixels x .. x+n-1 of row y of src: direct in memory, else through fetch. */
static inline int ssda__rows_get(const ssda__rows_t *src, uint32_t x, uint32_t y,
                                 uint32_t n, const uint8_t **px)
{
    if (src->base != NULL) {
        *px = src->base + (size_t)y * src->stride + (size_t)x * src->format;
        return SSDA_OK;
    }
    return src->fetch(src->ctx, src->x0 + x, src->y0 + y, n, px);
}

/* The zero-filled options (AUTO, raster scan, row order): what a NULL
   configuration means, one copy for the whole library. */
SSDA_INTERNAL extern const ssda_match_config_t ssda__match_defaults;

/*
 * Check cfg against area/window geometry and resolve it into *plan (defaults
 * and derived values: the row order's step for a window win_h rows tall, the
 * cuts of the threshold mode). Returns SSDA_OK or the error ssda_match
 * documents for the options (no pointer other than cfg and plan is touched);
 * on error *plan is scratch.
 */
SSDA_INTERNAL int ssda__match_plan(const ssda_match_config_t *cfg, uint32_t area_w,
                                   uint32_t area_h, uint32_t win_w, uint32_t win_h,
                                   ssda_match_plan_t *plan);

/*
 * One search over row sources: executes a plan made by ssda__match_plan for
 * this window size (geometry and formats validated by the caller), with the
 * predicted position (predict_x, predict_y) of a SSDA_SCAN_PREDICT scan
 * (ignored by the others). Returns SSDA_OK, a fetch error unchanged, or
 * SSDA_ERR_UNSUPPORTED for 16-bit rows in a build with SSDA_CFG_NO_U16;
 * *result written on success only.
 */
SSDA_INTERNAL int ssda__match_rows(const ssda__rows_t *area, const ssda__rows_t *window,
                                   const ssda_match_plan_t *plan, int32_t predict_x,
                                   int32_t predict_y, ssda_match_result_t *result);

/*
 * Bound tables shared by the searches of a tracking grid (track_tab.c).
 * With SSDA__MATCH_TAB in a plan's flags (set by the tracking plan only),
 * the work buffer holds, at byte SSDA__MATCH_TAB_AT(...) (the per-window
 * part, SSDA_MATCH_WORK_SIZE_UNIQUE, rounded up to 8), this description of
 * the tables for the next search, written by the caller before each one;
 * the engine then reads the area's group sums there instead of building
 * them: over the search area, with (0, 0) its top-left placement,
 * g[y * pitch + x] is the sum of the L x 4 pixels at (x, y) (L the window
 * width; the engine's groups of 4 rows), and b, when not NULL,
 * b[y * pitch + x] the sum of the 4 x 4 pixels at (x, y), for every
 * x + 4 i, y + 4 k of a placement's groups and blocks; wblk is scratch for
 * the window's (M / 4) * (L / 4) block sums. Only with SSDA_MATCH_BOUNDS
 * in effect, groups of 4 rows (M >= 4, and L <= 16384 for 16-bit samples)
 * and, with b, L a multiple of 4 up to 1024. Results, positions and
 * completed are those without; pixel_ops counts the window's sums and the
 * bound terms, not the shared tables (their builder counts them). Passed
 * in the buffer, not as an argument: the engine's entry keeps its frame.
 */
#define SSDA__MATCH_TAB 0x80u
#define SSDA__MATCH_TAB_AT(area_w, area_h, win_w, win_h)                      \
    ((SSDA_MATCH_WORK_SIZE_UNIQUE(area_w, area_h, win_w, win_h) + 7u) & ~(size_t)7u)
typedef struct {
    const uint32_t *g;
    const uint32_t *b;
    uint32_t *wblk;
    uint32_t pitch;
} ssda__match_tab_t;

#endif /* SSDA_MATCH_ROWS_H */
