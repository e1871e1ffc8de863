/*
 * stream_internal.h - internal: the plate cache of a source, its plans, and
 * sources seen as row sources (match_rows.h) by the search and tracking
 * engines.
 */
#ifndef SSDA_STREAM_INTERNAL_H
#define SSDA_STREAM_INTERNAL_H

#include "ssda/stream.h"
#include "match_rows.h"
#include "state.h"
#include "compiler.h"

/* Features compiled in (include/ssda/config.h): a layout or read size left
   out reads as its plain value, so the code behind it is dropped as dead. */
#ifdef SSDA_CFG_NO_TILED
#define STREAM_LAYOUT(c) ((void)(c), (uint8_t)SSDA_LAYOUT_RASTER)
#else
#define STREAM_LAYOUT(c) ((c)->layout)
#endif
#ifdef SSDA_CFG_NO_READ_SIZE
#define STREAM_READ_SIZE(c) ((void)(c), 1u)
#else
#define STREAM_READ_SIZE(c) ((uint32_t)(c)->read_size)
#endif

/* A source is usable once initialised (state.h). */
static inline bool ssda__stream_ready(const ssda_source_t *s)
{
    return ssda__valid(s->magic, SSDA__MAGIC_SOURCE);
}

/* Do the n bytes at p and the m bytes at q overlap (n, m > 0: arenas and
   rings are checked to hold at least a row before)? Compared as addresses:
   they are parts of the caller's memory, each in one object. */
static inline bool ssda__stream_mem_overlap(const void *p, size_t n, const void *q, size_t m)
{
    const uintptr_t a = (uintptr_t)p;
    const uintptr_t b = (uintptr_t)q;
    return a < b + m && b < a + n;
}

/* Does source s keep a plate (it is streamed; an in-RAM source reads its
   view) in memory overlapping the n bytes at p? Then a job that also
   writes there (another plate, a push ring) would overwrite its rows. */
static inline bool ssda__stream_plate_overlaps(const ssda_source_t *s, const void *p, size_t n)
{
    return s->view == NULL && ssda__stream_mem_overlap(s->cfg.arena, s->cfg.arena_size, p, n);
}

/* Would two sources of one job overwrite each other's plate? One source
   given twice, or two whose arenas overlap, cannot hold both operands'
   rows, and the search would run on the wrong pixels. */
static inline bool ssda__stream_plates_clash(const ssda_source_t *a, const ssda_source_t *b)
{
    return a->view == NULL && ssda__stream_plate_overlaps(b, a->cfg.arena, a->cfg.arena_size);
}

/* Largest plate width (px) of h rows that the arena holds with `extra`
   bytes set aside for a larger bounce buffer, 0 if none. */
SSDA_INTERNAL uint32_t ssda__stream_plate_fit_w(const ssda_source_t *s, uint32_t h, size_t extra);

/* Largest number of plate rows of w px that the arena holds with `extra`
   bytes set aside, 0 if none. */
SSDA_INTERNAL uint32_t ssda__stream_plate_fit_h(const ssda_source_t *s, uint32_t w, size_t extra);

/* Does a source hold a w x h plate with `extra` bounce bytes? (In-RAM
   sources: always.) The one "does it fit" test of the jobs. */
static inline bool ssda__stream_holds(const ssda_source_t *s, uint32_t w, uint32_t h,
                                      size_t extra)
{
    return s->view != NULL || ssda__stream_plate_fit_h(s, w, extra) >= h;
}

/*
 * Plan the plate of a streamed source for a job over region r (inside the
 * image) that fetches spans of at most span px and revisits `rows`
 * consecutive rows: the whole region width if `rows` rows of it fit (and as
 * many rows as fit, up to the region height), else the widest plate of
 * `rows` rows, else span x (as many rows as fit). q: rows between the
 * starts of the bands the job visits (the plate's row lattice, see place_y;
 * 0 = 1, at most the plate height). extra: bytes left to the bounce buffer
 * beyond its minimum when the plate is shaped for the region or for `rows`
 * (not in the span x 1 fallback). The plan goes to *plan, which the
 * source is not changed for, or to &s->plate (a job that plans and uses at
 * once), which keeps the plate's pixels when its shape holds (as
 * ssda__stream_plate_use). Returns SSDA_OK or SSDA_ERR_BUFFER (not even one
 * row of span px fits), with *plan and s unchanged.
 */
SSDA_INTERNAL int ssda__stream_plate_plan(ssda_source_t *s, const ssda_rect_t *r,
                                          uint32_t span, uint32_t rows, uint32_t q,
                                          size_t extra, ssda_source_plan_t *plan);

/* Plan the plate of s straight into the source (ssda__stream_plate_plan). */
static inline int ssda__stream_plate_shape(ssda_source_t *s, const ssda_rect_t *r,
                                           uint32_t span, uint32_t rows, uint32_t q,
                                           size_t extra)
{
    return ssda__stream_plate_plan(s, r, span, rows, q, extra, &s->plate);
}

/* Give the plate a shape planned before, keeping its pixels when the shape
   does not change (the same width has the same pitch). */
static inline void ssda__stream_plate_use(ssda_source_t *s, const ssda_source_plan_t *plan)
{
    if (plan->pw != s->plate.pw || plan->ph != s->plate.ph) {
        s->rows = 0u;
    }
    s->plate = *plan;
}

/* Does a planned plate hold the whole region across and `rows` rows of it
   (a band, placed as rows in memory)? */
static inline bool ssda__stream_plan_holds_band(const ssda_source_plan_t *plan, uint32_t rows)
{
    return plan->pw >= plan->region.width && plan->ph >= rows;
}

/* Put the plate at (x0, y0) (inside the image), reading only the rows it
   does not hold yet. Counts a hit when it is there already, else a miss.
   Returns SSDA_OK or a read error (then the plate is empty). */
SSDA_INTERNAL int ssda__stream_plate_place(ssda_source_t *s, uint32_t x0, uint32_t y0);

/* Read-callback source: fetch through the plate (misses move it). Same
   contract as ssda__row_fetch_fn with ctx = the source; the span must lie
   inside the image and n <= the plate width. */
SSDA_INTERNAL int ssda__stream_plate_fetch(ssda_source_t *s, uint32_t x, uint32_t y, uint32_t n,
                                           const uint8_t **px);

/* Fast path of ssda__stream_plate_fetch, always inlined (a frame less under
   ssda_source_row and the engine's fetches). */
static SSDA_ALWAYS_INLINE int ssda__stream_fetch(ssda_source_t *s, uint32_t x, uint32_t y,
                                                 uint32_t n, const uint8_t **px)
{
    uint32_t dy = y - s->py0; /* wraps above the plate: then >= rows */
    uint32_t dx = x - s->px0;
    if (dy < s->rows && dx <= s->plate.pw && n <= s->plate.pw - dx) {
        s->stats.hits++;
        *px = (const uint8_t *)s->cfg.arena + (size_t)dy * s->plate.pitch +
              (size_t)dx * s->cfg.format;
        return SSDA_OK;
    }
    return ssda__stream_plate_fetch(s, x, y, n, px);
}

/* Make *rows the rectangle r of s (NULL: the whole image): a plain pointer
   for in-RAM sources, else fetches through the plate. */
SSDA_INTERNAL void ssda__stream_rows(ssda__rows_t *rows, ssda_source_t *s, const ssda_rect_t *r);

/* Resolve a rectangle (NULL = whole image) and check it lies inside s:
   SSDA_OK or SSDA_ERR_SIZE. */
SSDA_INTERNAL int ssda__stream_rect(const ssda_source_t *s, const ssda_rect_t *in,
                                    ssda_rect_t *out);

/* ----- grid tracking's bands (stream_band.c) ----- */

/* The rectangle of the search areas in FIRST (first_w x first_h) and of
   the windows in SECOND of grid columns [c0, c1), over the windows whose
   areas lie inside FIRST, and the grid rows row_lo..row_hi those are on.
   Returns false when there is none (nothing will be read). */
SSDA_INTERNAL bool ssda__stream_grid_rects(const ssda_track_grid_t *g, uint32_t first_w,
                                           uint32_t first_h, uint32_t c0, uint32_t c1,
                                           ssda_rect_t *area, ssda_rect_t *win,
                                           uint32_t *row_lo, uint32_t *row_hi);

/* Bounce bytes beyond the minimum for a tiled source to read the rows a
   band gains per grid step in one read per tile (0 for raster, RAM). */
SSDA_INTERNAL size_t ssda__stream_run_extra(const ssda_source_t *s, uint32_t step_y);

/* Plan the plate of s (streamed; in RAM: nothing) into *plan for bands of
   `rows` rows of region r moving down q rows at a time, with a tiled
   source's run room when the band still fits with it. The job has checked
   that a band (r's width x rows, or span x rows) fits the arena. */
SSDA_INTERNAL void ssda__stream_band_plan(ssda_source_t *s, const ssda_rect_t *r, uint32_t span,
                                          uint32_t rows, uint32_t q, ssda_source_plan_t *plan);

/* Row source of the band with top-left (x, y) of a streamed source's plate
   (kept inside the plate's region): the plate moved there, as rows in
   memory; *ox, *oy receive where the band starts in the image.
   Returns SSDA_OK or a read error. */
SSDA_INTERNAL int ssda__stream_band_rows(ssda_source_t *s, uint32_t x, uint32_t y,
                                         ssda__rows_t *rows, uint32_t *ox, uint32_t *oy);

#endif /* SSDA_STREAM_INTERNAL_H */
