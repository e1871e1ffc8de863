/*
 * track_rows.h - internal: grid tracking over row sources, so the same code
 * serves images in RAM (ssda_track) and block-streamed images (the stream
 * layer). Every pixel read, for the mask and texture tests as for the
 * search, is a row span through ssda__rows_get(): never a call per pixel.
 */
#ifndef SSDA_TRACK_ROWS_H
#define SSDA_TRACK_ROWS_H

#include "ssda/track.h"
#include "match_rows.h"

/*
 * Whether out (out_count entries) holds a grid of count windows. On a 32-bit
 * target a grid of more than SIZE_MAX / sizeof(ssda_track_vector_t)
 * windows (about 179 million) would need an array beyond the address space,
 * so SSDA_TRACK_OUT_SIZE wraps there and no out can hold it: refused.
 */
static inline bool ssda__track_out_fits(uint32_t count, size_t out_count)
{
#if SIZE_MAX <= UINT32_MAX
    if (count > SIZE_MAX / sizeof(ssda_track_vector_t)) {
        return false;
    }
#endif
    return out_count >= count;
}

/* Whether the view (valid, in RAM) holds the value v: the grid tracking's
   mask test, shared with ssda_composite_match's mask. */
SSDA_INTERNAL bool ssda__view_holds(const ssda_view_t *view, uint32_t v);

/* The zero-filled options (the seed's grid, AUTO): what a NULL
   configuration means, one copy for the whole library. */
SSDA_INTERNAL extern const ssda_track_config_t ssda__track_defaults;

/*
 * Resolve and check cfg (never NULL) for images of the given format, FIRST
 * first_w x first_h and SECOND second_w x second_h, into *plan
 * (ssda_track_plan_t, track.h):
 * every error ssda_track documents for the configuration (SSDA_ERR_SIZE,
 * _ARG, _NULL, _BUFFER of the match options). On error *plan holds scratch
 * (the callers discard it).
 */
SSDA_INTERNAL int ssda__track_plan(const ssda_track_config_t *cfg, uint8_t format,
                                   uint32_t first_w, uint32_t first_h, uint32_t second_w,
                                   uint32_t second_h, ssda_track_plan_t *plan);

/*
 * ssda_track over row sources. first and second are checked here (non-NULL,
 * known and equal formats, non-zero sizes, a fetch callback when base is
 * NULL, a large enough stride and an aligned 16-bit base when base is set);
 * cfg NULL means defaults.
 * Windows are solved in raster order of the grid, so a streamed SECOND is
 * read top to bottom, and FIRST in bands of search_h rows moving down.
 * Returns what ssda_track returns, or a fetch error unchanged. On a fetch
 * error, out[0 .. k-1] hold the windows solved before the failing window k,
 * the rest of out and *stats are untouched (a streamed call cannot undo
 * what it wrote; argument errors still write nothing).
 */
SSDA_INTERNAL int ssda__track_rows(const ssda__rows_t *first, const ssda__rows_t *second,
                                   const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                                   size_t out_count, ssda_track_stats_t *stats);

/* The checks of every whole-image tracking entry after its sources':
   equal formats, cfg (NULL = defaults) resolved into *plan for these
   sizes, out_count at least the grid count. Returns SSDA_OK or the error
   ssda_track documents (SSDA_ERR_FORMAT, the plan's, SSDA_ERR_BUFFER). */
SSDA_INTERNAL int ssda__track_prepare(const ssda__rows_t *first, const ssda__rows_t *second,
                                      const ssda_track_config_t *cfg, size_t out_count,
                                      ssda_track_plan_t *plan);

/* ssda__track_rows after its checks of the row sources, for callers whose
   sources are valid already (ssda_track's views): formats, the plan, the
   whole grid. Same returns. */
SSDA_INTERNAL int ssda__track_run(const ssda__rows_t *first, const ssda__rows_t *second,
                                  const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                                  size_t out_count, ssda_track_stats_t *stats);

/*
 * Where the row sources given to ssda__track_part lie in the images, for a
 * caller that keeps only a band of each image in RAM (the stream layer's
 * plates and push rings): pixel (0, 0) of first is FIRST's pixel (first_x,
 * first_y) and pixel (0, 0) of second is SECOND's (second_x, second_y).
 * The search area and window of every non-EDGE window of the part must lie
 * inside first and second (the EDGE test uses FIRST's size from the plan,
 * not first's). Whole images have the identity origin.
 */
typedef struct {
    uint32_t first_x, first_y;
    uint32_t second_x, second_y;
} ssda__track_origin_t;

/* The identity origin (all zero): the row sources are the whole images. */
SSDA_INTERNAL extern const ssda__track_origin_t ssda__track_origin_whole;

/*
 * Solve grid columns col0 .. col1-1 (col0 < col1 <= plan->grid.cols) of grid
 * rows row0 .. row1-1 (row0 < row1 <= plan->grid.rows), row by row, left to
 * right, with row sources placed by origin. plan comes from
 * ssda__track_plan and is only read; first and second must already satisfy
 * ssda__track_rows' checks and out must hold the whole grid (entry row *
 * cols + col). For callers that cut the grid into vertical strips and
 * bands of rows (the stream layer): prediction takes as solved every window
 * left of col0 and above row0 (so solve strips left to right, rows top to
 * bottom) and the part's windows solved before; up-right neighbours in
 * column col1 are not solved yet, so with prediction on, the work (not the
 * vectors, in exact modes) can differ from one whole-grid call. Counts are
 * added to *acc (zero it before the first part; windows counts the part's
 * windows). Returns SSDA_OK or a fetch error unchanged, in which case *acc
 * holds partial counts (the callers discard it; it is not copied onto the
 * caller's stack, to keep the deepest call chain short) and out holds the
 * part's windows solved before the failing one.
 */
SSDA_INTERNAL int ssda__track_part(const ssda__rows_t *first, const ssda__rows_t *second,
                                   const ssda_track_plan_t *plan, uint32_t col0, uint32_t col1,
                                   uint32_t row0, uint32_t row1,
                                   const ssda__track_origin_t *origin, ssda_track_vector_t *out,
                                   ssda_track_stats_t *acc);

/*
 * Solve columns col0 .. col1-1 of grid row `row` of whole images (the
 * identity origin) for ssda_track_row: every window the prediction reads is
 * taken as solved, up-right neighbours in columns col1 and beyond too (the
 * caller's promise). Counts are added to *acc. Returns SSDA_OK or a fetch
 * error unchanged (none for views in RAM).
 */
SSDA_INTERNAL int ssda__track_span(const ssda__rows_t *first, const ssda__rows_t *second,
                                   const ssda_track_plan_t *plan, uint32_t row, uint32_t col0,
                                   uint32_t col1, ssda_track_vector_t *out,
                                   ssda_track_stats_t *acc);

/* ssda__track_part over every grid row of whole images (the identity
   origin): one vertical strip. */
static inline int ssda__track_strip(const ssda__rows_t *first, const ssda__rows_t *second,
                                    const ssda_track_plan_t *plan, uint32_t col0, uint32_t col1,
                                    ssda_track_vector_t *out, ssda_track_stats_t *acc)
{
    return ssda__track_part(first, second, plan, col0, col1, 0u, plan->grid.rows,
                            &ssda__track_origin_whole, out, acc);
}

#endif /* SSDA_TRACK_ROWS_H */
