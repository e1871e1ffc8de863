/*
 * stream.h - block-streamed images: match images far larger than RAM.
 *
 * Seed: Nagao et al. 1975, section 2.3 and Figs. 5-6: images of 4000 x 4000
 * and more stay on disk; "plate-shaped" blocks of rows, sized to the memory
 * given to each image, are paged in and out so that a routine can ask for
 * pixel (I, J) of image N and never see the I/O.
 *
 * A SOURCE is an image in external memory (SPI flash, PSRAM, SD card, a
 * file) reached through one read callback, described by one config struct
 * (littlefs style). Each source owns a caller-provided ARENA holding its
 * PLATE: a w x h rectangle of the image, rows `pitch` bytes apart, in RAM.
 *
 * PLATE POLICY (the cache's replacement rule). A row span outside the plate
 * is a miss; the plate then moves to cover it:
 *   - columns: if the plate is at least as wide as the job's region, it
 *     starts at the region's left edge; otherwise at the span's left edge
 *     (kept inside the region and the image);
 *   - rows: if the plate is at least as tall as the region, it starts at the
 *     region's top; otherwise its start stays on a lattice of rows q apart
 *     from the region's top (q: the grid step of a tracking job, the plate's
 *     spare rows + 1 in a raster-scan search, the plate's height for
 *     ssda_source_row, 1 otherwise): moving down, at
 *     the first lattice row that covers the missed row (keeping the most
 *     rows above it, so a band sliding down is read once); moving up, at
 *     the last lattice row at or above it;
 *   - rows still inside the moved plate (same columns) are copied, not
 *     read again; every other row is read: one read per plate row in the
 *     raster layout (one per plate load when whole rows are stored at the
 *     plate's pitch), one per tile and run of rows in the tiled one.
 * Jobs (ssda_stream_match, ssda_stream_track, push jobs) shape the plate
 * for their region and refuse (SSDA_ERR_BUFFER, before any read) an arena
 * below the plate that bounds what they read: at most 2x the bytes of
 * reading their region once for a search, and the strips' overlap for
 * tracking (issue 22: a smaller plate re-read rows without bound, 30 000x
 * the image). Each job names its minimum; see docs/streaming.md for the
 * plans, the bounds and the figures.
 *
 * Errors: a negative value returned by read() is passed back unchanged
 * (so it may be any negative int; SSDA_ERR_IO is a good default), and a
 * positive one (not a valid return) is turned into SSDA_ERR_IO; either way
 * the job's result is left untouched. After a failed read the plate is empty and
 * the source stays usable. Counters are never reset by the library.
 *
 * The library never allocates: the source struct and the arena belong to the
 * caller and must outlive every call on the source. A source is not
 * thread-safe; two sources may share one read callback and context, but
 * not arena memory (jobs refuse overlapping arenas with SSDA_ERR_ARG).
 *
 * Initialise before use (ssda_source_init / ssda_source_init_view /
 * ssda_push_init_*): a source or push job its init function did not fill
 * (zero-filled static storage, memset, or leftover stack bytes) is refused
 * with SSDA_ERR_STATE by every function, unless its bytes happen to spell
 * the value the init function writes (a 32-bit magic number); a copy of an
 * initialised one is accepted, and must still have its buffers.
 */
#ifndef SSDA_STREAM_H
#define SSDA_STREAM_H

#include "ssda/match.h"
#include "ssda/track.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How the image is stored in the device. */
typedef enum {
    /* Rows top to bottom, pixels left to right; row y starts at
       offset + y * stride. */
    SSDA_LAYOUT_RASTER = 0,
    /* tile_w x tile_h tiles, row-major over the image (tiles_across =
       ceil(width / tile_w)); tile (tx, ty) starts at
       offset + (ty * tiles_across + tx) * tile_stride, its rows stride bytes
       apart. Edge tiles are stored full size (TIFF style); their padding
       pixels are never read into the plate. */
    SSDA_LAYOUT_TILED = 1
} ssda_layout_t;

/*
 * Read size bytes at byte address offset of the device into buffer.
 * Return 0 on success or a negative error code, which the library passes
 * back unchanged; a positive return is taken as a failure and becomes
 * SSDA_ERR_IO. offset and size are multiples of the source's read_size;
 * size > 0. A read may cover up to read_size - 1 bytes before the image's
 * first byte and after its last (the aligned range around it), never more.
 * buffer lies in the arena but may have any byte alignment (a plate row of
 * a raster source is kept at the device's stride when that is within the
 * row's 4-byte rounding, e.g. 47 bytes): a driver whose DMA needs aligned
 * memory reads through a buffer of its own.
 */
typedef int (*ssda_read_fn)(void *context, uint32_t offset, void *buffer, uint32_t size);

/*
 * Source configuration. Zero means the documented default.
 */
typedef struct {
    ssda_read_fn read;    /* required */
    void *context;        /* passed to read(), may be NULL */
    uint32_t offset;      /* byte address of the image (pixel (0, 0) or tile
                             (0, 0)); a multiple of the pixel size */
    uint32_t stride;      /* bytes from one row start to the next: image rows
                             (raster) or rows inside a tile (tiled); a multiple
                             of the pixel size, >= width (or tile_w) * bpp;
                             0 = packed */
    uint32_t tile_stride; /* tiled: bytes from one tile to the next,
                             >= (tile_h - 1) * stride + tile_w * bpp, a
                             multiple of the pixel size; 0 = stride * tile_h */
    uint32_t read_size;   /* read granularity in bytes: every read's offset
                             and size are multiples of it (flash page, SD
                             sector); 1 or a multiple of the pixel size, at
                             most SSDA_STREAM_MAX_READ_SIZE; 0 = 1 */
    void *arena;          /* cache memory, 4-byte aligned, owned by the caller */
    size_t arena_size;    /* bytes; >= SSDA_SOURCE_SIZE(..., 1, 1, ...) to
                             initialise, more per job (see the job functions) */
    uint16_t width;       /* pixels, 1..65535 */
    uint16_t height;      /* rows, 1..65535 */
    uint16_t tile_w;      /* tiled: tile width, px, 1..65535 */
    uint16_t tile_h;      /* tiled: tile height, rows, 1..65535 */
    uint8_t format;       /* ssda_pixfmt_t */
    uint8_t layout;       /* ssda_layout_t */
} ssda_source_config_t;

/* What a source has cost so far. Counts are cumulative from init and
   wrap only after 2^64 events. */
typedef struct {
    uint64_t bytes_read; /* bytes requested from read(), alignment included */
    uint64_t reads;      /* read() calls */
    uint64_t hits;       /* row spans served from the plate without reading */
    uint64_t misses;     /* row spans that moved the plate (and read) */
} ssda_source_stats_t;

/* A rectangle of a source, px: top-left (x, y), width x height. */
typedef struct {
    uint16_t x, y;
    uint16_t width, height;
} ssda_rect_t;

/*
 * Private (read no field): the plate a job wants of a source, resolved once
 * by the job (its capacity for the job's region and the row lattice of its
 * moves, see PLATE POLICY); the job's later calls only apply it.
 */
typedef struct {
    uint32_t pitch;       /* bytes between plate rows */
    uint32_t bounce;      /* arena offset of the bounce buffer */
    uint32_t bounce_size; /* its bytes; 0: reads go straight to the plate */
    uint16_t pw, ph;      /* plate capacity: pixels per row, rows */
    uint16_t qy;          /* row lattice of plate starts (1..ph) */
    ssda_rect_t region;   /* the job's region of the image */
} ssda_source_plan_t;

/*
 * A source. Allocate it (static, stack, or in a struct); fill it only with
 * ssda_source_init or ssda_source_init_view. All fields are private except
 * stats, which may be read (and zeroed) at any time between calls.
 */
typedef struct {
    ssda_source_config_t cfg; /* resolved copy (defaults filled in) */
    ssda_source_stats_t stats;
    const uint8_t *view;      /* in-RAM source: pixel (0, 0); else NULL */
    ssda_source_plan_t plate; /* the plate's shape for the current job */
    uint16_t px0, py0;        /* image position of the plate's first pixel */
    uint16_t rows;            /* plate rows holding valid pixels: 0 or ph */
    uint32_t magic;           /* set by the init functions */
} ssda_source_t;

/* Largest read granularity a source accepts, bytes (64 KiB: NAND pages,
   SD sectors and flash pages are smaller). */
#define SSDA_STREAM_MAX_READ_SIZE 65536u

/* ----- Arena sizes. All in bytes; read_size 0 counts as 1. ----- */

#define SSDA_STREAM_RS_(rs) ((size_t)(rs) > 1u ? (size_t)(rs) : (size_t)1u)
#define SSDA_STREAM_ALIGN4_(n) ((((size_t)(n)) + 3u) & ~(size_t)3u)

/* Bytes of one plate row of w pixels. */
#define SSDA_STREAM_PITCH(w, format)                                          \
    SSDA_STREAM_ALIGN4_((size_t)(w) * (size_t)(format))

/* Bytes of the smallest bounce buffer, where reads that cannot land in the
   plate go before their pixels are copied into it: tiled, one tile row
   widened to read_size on both sides; raster with read_size > 1, one plate
   row (w px) widened likewise; raster with read_size 1, none (rows are read
   straight into the plate). Any arena beyond the plate enlarges it, so that
   one read covers several rows of a tile. */
#define SSDA_STREAM_BOUNCE(layout, w, format, read_size, tile_w)              \
    ((layout) == SSDA_LAYOUT_TILED                                            \
         ? SSDA_STREAM_ALIGN4_((size_t)(tile_w) * (size_t)(format) +          \
                               2u * (SSDA_STREAM_RS_(read_size) - 1u))        \
         : (SSDA_STREAM_RS_(read_size) > 1u                                   \
                ? SSDA_STREAM_ALIGN4_((size_t)(w) * (size_t)(format) +        \
                                      2u * (SSDA_STREAM_RS_(read_size) - 1u)) \
                : (size_t)0u))

/*
 * Arena bytes for a plate of w x h pixels of a source with this layout,
 * format, read_size and tile width (tile_w unused for raster). A job needs
 * w >= the widest row span it fetches and h >= 1; more rows and width let
 * it read less (see the job functions).
 */
#define SSDA_SOURCE_SIZE(layout, w, h, format, read_size, tile_w)             \
    ((size_t)(h) * SSDA_STREAM_PITCH(w, format) +                             \
     SSDA_STREAM_BOUNCE(layout, w, format, read_size, tile_w))

/* Width of the search-area strip of n grid columns in grid tracking:
   (n - 1) * step + search (the windows' strip is (n - 1) * step + win). */
#define SSDA_STREAM_STRIP_W(n, step, side)                                    \
    (((size_t)(n) - 1u) * (size_t)(step) + (size_t)(side))

/* ----- Sources ----- */

/*
 * Initialise *src from *cfg (copied; cfg may be discarded afterwards). No
 * read is made. The plate starts empty, as wide as the image (or as the
 * arena allows) and as tall as the arena allows.
 * Returns SSDA_OK, or without touching *src:
 *   SSDA_ERR_NULL    src, cfg, cfg->read or cfg->arena NULL
 *   SSDA_ERR_FORMAT  unknown format
 *   SSDA_ERR_ARG     unknown layout; read_size neither 1 nor a multiple of
 *                    the pixel size, or above SSDA_STREAM_MAX_READ_SIZE
 *   SSDA_ERR_SIZE    zero width, height, tile_w or tile_h; the image (with
 *                    read alignment) does not fit below 2^32 bytes
 *   SSDA_ERR_STRIDE  offset, stride or tile_stride not a multiple of the
 *                    pixel size; stride or tile_stride too small
 *   SSDA_ERR_BUFFER  arena not 4-byte aligned, or smaller than a 1 x 1
 *                    plate (SSDA_SOURCE_SIZE(layout, 1, 1, ...))
 */
int ssda_source_init(ssda_source_t *src, const ssda_source_config_t *cfg);

/*
 * Initialise *src as an image already in RAM (no arena, no reads, no
 * counts), so the job functions take any mix of streamed and in-RAM images.
 * The view's pixels must outlive the source. Returns SSDA_OK, SSDA_ERR_NULL,
 * or the errors of ssda_view_check; *src untouched on error.
 */
int ssda_source_init_view(ssda_source_t *src, const ssda_view_t *view);

/*
 * Pixels x .. x+n-1 of row y as one contiguous span (the seed's "pixel
 * (I, J) of image N", a row at a time): on success *px points to them
 * (uint16_t-aligned for 16-bit images) until the next call on this source.
 * Reads as the plate policy says; the job region is the whole image.
 * Returns SSDA_OK, or without writing *px:
 *   SSDA_ERR_NULL    src or px NULL
 *   SSDA_ERR_STATE   src not initialised
 *   SSDA_ERR_SIZE    n == 0 or the span leaves the image
 *   SSDA_ERR_BUFFER  n wider than the arena's plate can be
 *   any negative value read() returned
 */
int ssda_source_row(ssda_source_t *src, uint32_t x, uint32_t y, uint32_t n,
                    const uint8_t **px);

/* ----- Jobs ----- */

/*
 * ssda_match over a rectangle of one source (the search area) and a
 * rectangle of another (the window); either may be streamed or in RAM. The
 * result is the one ssda_match gives on the same pixels in RAM, field for
 * field, in every mode.
 *   area, window: initialised sources of the same format (may be the same
 *             source only if it is in RAM; two streamed sources need arenas
 *             that do not overlap).
 *   area_rect, window_rect: rectangles inside them; NULL = the whole image.
 *             The window rectangle is no larger than the area's.
 *   cfg:      as ssda_match (NULL = defaults).
 *   result:   written on success only.
 * Arena (the minimum; below it SSDA_ERR_BUFFER before any read): a streamed
 * area needs SSDA_SOURCE_SIZE(layout, area width, window height, format,
 * read_size, tile_w) for SSDA_SCAN_RASTER (a band that slides down) and
 * SSDA_SOURCE_SIZE(.., area width, area height, ..) for the other scans
 * (they jump around the area); a streamed window needs its whole rectangle,
 * SSDA_SOURCE_SIZE(.., window width, window height, ..). Then the area's
 * bytes read are at most twice those of reading it once (the raster scan
 * reads its band again after building bounds) and the window's once; a
 * smaller plate would re-read rows without bound (issue 22).
 * Returns SSDA_OK, or without writing *result:
 *   SSDA_ERR_NULL, _SIZE, _FORMAT, _ARG, _BUFFER as ssda_match (SIZE also
 *   for a rectangle outside its source, BUFFER also for a short arena,
 *   found before any read; ARG also for one streamed source given as both
 *   operands, or two whose arenas overlap: one plate cannot hold both);
 *   SSDA_ERR_STATE for an
 *   uninitialised source; any read() error unchanged.
 */
int ssda_stream_match(ssda_source_t *area, const ssda_rect_t *area_rect,
                      ssda_source_t *window, const ssda_rect_t *window_rect,
                      const ssda_match_config_t *cfg, ssda_match_result_t *result);

/*
 * ssda_track with FIRST and/or SECOND streamed.
 * PLAN: the grid is cut into vertical strips of as many grid columns as the
 * arenas hold with the strip's search areas (search_h rows) in FIRST's plate
 * and its windows (win_h rows) in SECOND's; each strip is solved top to
 * bottom while the plates slide down one grid step at a time, so every byte
 * is read about once (strips overlap by search_w - step_x columns), and
 * each grid row is searched on the plates as on images in RAM. Within a
 * strip windows are solved in raster order. Strips change only the order
 * of the work, so:
 *   - vectors, statuses and exact flags equal ssda_track's: with no
 *     prediction or SSDA_TRACK_PREDICT_LEFT (whose neighbours are solved
 *     in both orders) in strips; with SSDA_TRACK_PREDICT_MEDIAN in one
 *     full-width strip, since its up-right neighbour is missing at a
 *     strip's right edge and the prediction steers the scan and breaks
 *     ties between equal SADs (the tie rule of track.h, in every mode):
 *     that strip needs a band of the whole grid width;
 *   - the work counts (pixel_ops, positions, completed) may differ from
 *     ssda_track's when prediction is on, since a window at a strip's right
 *     edge has no solved up-right neighbour.
 * Arena (the minimum; below it SSDA_ERR_BUFFER before any read): a band of
 * one grid column, SSDA_SOURCE_SIZE(.., search_w, search_h, ..) for a
 * streamed FIRST and SSDA_SOURCE_SIZE(.., win_w, win_h, ..) for a streamed
 * SECOND; with MEDIAN prediction a band of every column,
 * SSDA_STREAM_STRIP_W(cols, step_x, search_w) (at most FIRST's width) x
 * search_h and SSDA_STREAM_STRIP_W(cols, step_x, win_w) x win_h (a row is
 * enough when no window's area lies inside FIRST); no width above the
 * image's. Strips of n columns need
 * SSDA_STREAM_STRIP_W(n, step_x, search_w) x search_h and
 * SSDA_STREAM_STRIP_W(n, step_x, win_w) x win_h (tiled sources also
 * (min(tile_h, step_y) - 1) * stride bytes more, so that the rows a band
 * gains at each step come in one read per tile); each image's bytes are
 * then at most (strip width / (n step_x)) times those of reading its
 * region once, plus each strip row's read alignment (issue 22: below one
 * column's band the tracker re-read rows without bound).
 * Returns what ssda_track returns (every argument error before any read or
 * write; SSDA_ERR_BUFFER also for an arena below the minimum, SSDA_ERR_ARG
 * also for one streamed source given as both images or two whose arenas
 * overlap), SSDA_ERR_STATE for an
 * uninitialised source, or a read() error unchanged. On a read error out
 * holds the windows solved before it (the rest of out and *stats are
 * untouched): a streamed call cannot take back what it wrote.
 */
int ssda_stream_track(ssda_source_t *first, ssda_source_t *second,
                      const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                      size_t out_count, ssda_track_stats_t *stats);


/* ----- Push mode: rows arrive one by one (line-streamed cameras) ----- */

/* Which image of a tracking job the pushed rows are. */
typedef enum {
    SSDA_PUSH_FIRST = 0,  /* the earlier image: the search areas */
    SSDA_PUSH_SECOND = 1  /* the later image: the windows */
} ssda_push_role_t;

/*
 * What a push job pushes, and where it keeps rows (both init functions).
 * Every field is read at init only; the pointers must outlive the job.
 */
typedef struct {
    uint16_t width, height;         /* the pushed image (a frame), px, 1..65535 */
    ssda_pixfmt_t format;           /* its pixel format; other's must be the same */
    ssda_push_role_t role;          /* tracking: which image is pushed (search: unused) */
    ssda_source_t *other;           /* the other image, in RAM or streamed: the
                                       window (search) or the other frame (tracking) */
    const ssda_rect_t *area_rect;   /* search: the area in the pushed image
                                       (NULL = whole; tracking: unused) */
    const ssda_rect_t *window_rect; /* search: the window in other (NULL = whole) */
    void *ring;                     /* kept rows: 4-byte aligned caller buffer */
    size_t ring_size;               /* its bytes (see the init functions) */
} ssda_push_config_t;

/*
 * A push job: the rows of one image (a frame) are pushed top to bottom,
 * and each search runs inside the push that brings the last row it needs.
 * The rows a job still needs are kept in a caller buffer (the ring): only
 * the columns the job uses, rows in order, so that searches run on them as
 * on an image in RAM (when the ring is full, the rows still needed move to
 * its start; a ring taller than the minimum moves them less often).
 * All fields are private: the init functions check everything and resolve
 * the job into this state (the search or tracking plan, the plate of a
 * streamed other image, the rows each search waits for), so that a push
 * only executes it (littlefs's lfs_t, CMSIS-DSP's instances). One job per
 * frame: initialise it again for the next frame (no read is made at init).
 */
typedef struct {
    uint8_t *ring;               /* kept rows, pitch bytes apart */
    uint32_t pitch;
    uint16_t cap;                /* rows the ring holds */
    uint16_t count;              /* rows held, from image row first_row */
    uint16_t first_row;
    uint16_t next_row;           /* image row the next push brings */
    uint16_t height;             /* rows of the pushed image */
    uint16_t x0, w;              /* columns kept */
    uint16_t need_from;          /* first image row the unsolved part needs */
    uint16_t ready_at;           /* rows pushed when the next search can run */
    uint16_t next_grid_row;      /* tracking: first grid row not solved */
    uint16_t row_lo, row_hi;     /* tracking: grid rows that read pixels */
    uint8_t format;
    uint8_t state;               /* search, tracking, done, or stopped */
    uint8_t role;                /* ssda_push_role_t (tracking) */
    ssda_source_t *other;        /* the window (search) or the other image */
    ssda_source_plan_t other_plate; /* a streamed other's plate for the job */
    ssda_rect_t area;            /* search: the area in the pushed image */
    ssda_rect_t other_rect;      /* search: the window in its source */
    int32_t predict_x, predict_y; /* search: a SSDA_SCAN_PREDICT's position */
    ssda_track_plan_t plan;      /* tracking; a search uses plan.match */
    ssda_match_result_t *result; /* search: written when it runs */
    ssda_track_vector_t *out;    /* tracking: the grid's vectors */
    ssda_track_stats_t acc;      /* tracking: totals so far */
    ssda_track_stats_t *stats;   /* tracking: written when the grid is done */
    uint32_t magic;              /* set by the init functions */
} ssda_push_t;

/* Ring bytes for rows of w pixels: a job needs rows >= the band it
   searches (see the init functions). */
#define SSDA_PUSH_SIZE(w, rows, format)                                       \
    ((size_t)(rows) * SSDA_STREAM_PITCH(w, format))

/*
 * A search whose area is cfg->area_rect (NULL = whole) of the pushed image,
 * cfg->width x cfg->height pixels of cfg->format; the window is
 * cfg->window_rect (NULL = whole) of the source cfg->other (in RAM or
 * streamed: its arena at least the whole window rectangle, read once). The
 * search runs in the push
 * that brings the area's last row and writes *result (as ssda_match would;
 * match NULL = defaults); that push returns 1.
 *   cfg->ring, cfg->ring_size: 4-byte aligned buffer of at least
 *                    SSDA_PUSH_SIZE(area width, area height, format) bytes.
 * Returns SSDA_OK or, with *push untouched: SSDA_ERR_NULL (push, cfg,
 * cfg->other, result or cfg->ring NULL, or bounds without work buffer),
 * SSDA_ERR_STATE (other not initialised), SSDA_ERR_FORMAT, SSDA_ERR_SIZE
 * (zero size, rectangles outside their images, window larger than the
 * area), SSDA_ERR_ARG (options; a ring overlapping the window's arena),
 * SSDA_ERR_BUFFER (ring or window arena short, or the ring misaligned).
 * The window, result and the ring, and match->work when SSDA_MATCH_BOUNDS
 * is set (the job keeps the pointer), must outlive the job.
 */
int ssda_push_init_match(ssda_push_t *push, const ssda_push_config_t *cfg,
                         const ssda_match_config_t *match, ssda_match_result_t *result);

/*
 * Grid tracking with one image pushed (cfg->role: FIRST or SECOND) and the
 * other a source (cfg->other, in RAM or streamed). The pushed image is
 * cfg->width x cfg->height. Grid rows are solved in order, each in the push
 * that brings the last row of its band (FIRST: its search areas, search_h
 * rows; SECOND: its windows, win_h rows); that push returns how many grid
 * rows it solved. Results equal ssda_track's in every mode (the order is
 * ssda_track's). *stats (may be NULL) is written when the last grid row is
 * solved. track NULL = defaults.
 *   cfg->ring, cfg->ring_size: at least SSDA_PUSH_SIZE(span, band, format)
 *     bytes, span = SSDA_STREAM_STRIP_W(grid cols, step_x, search_w)
 *     (FIRST) or SSDA_STREAM_STRIP_W(grid cols, step_x, win_w) (SECOND),
 *     capped at the image width; band = search_h (FIRST) or win_h (SECOND).
 * A streamed other image needs a band of it as wide as the grid's windows
 * (or areas) in it: SSDA_SOURCE_SIZE(.., SSDA_STREAM_STRIP_W(cols, step_x,
 * win_w) (FIRST pushed) or (.., search_w) (SECOND pushed), at most its
 * width, win_h or search_h rows, ..) (a row when no window reads pixels);
 * it is then read once. Grid rows are solved whole, so a narrower plate
 * would re-read its rows without bound: refused (SSDA_ERR_BUFFER).
 * The other source, out, stats, the ring and track->match.work (with
 * SSDA_MATCH_BOUNDS; the job keeps the pointer) must outlive the job.
 * Returns SSDA_OK or what ssda_stream_track returns for its arguments
 * (SSDA_ERR_NULL also for cfg, cfg->other or cfg->ring NULL, SSDA_ERR_ARG
 * for an unknown role, SSDA_ERR_BUFFER also for a short ring, SSDA_ERR_ARG
 * for a ring that overlaps a streamed other image's arena), with *push
 * untouched.
 */
int ssda_push_init_track(ssda_push_t *push, const ssda_push_config_t *cfg,
                         const ssda_track_config_t *track, ssda_track_vector_t *out,
                         size_t out_count, ssda_track_stats_t *stats);

/*
 * Push the next row of the image: row holds its width pixels (uint16_t
 * aligned for 16-bit images); only the columns the job uses are copied.
 * Returns how many searches (grid rows) completed in this push (0 or more),
 * or an error: SSDA_ERR_NULL, SSDA_ERR_STATE (not initialised, every row
 * already pushed, or stopped by an earlier error), or a read() error of a
 * streamed source, unchanged: the job then stops (initialise it again);
 * the search's result stays untouched, tracking's out keeps the windows
 * solved before the error.
 */
int ssda_push_row(ssda_push_t *push, const void *row);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_STREAM_H */
