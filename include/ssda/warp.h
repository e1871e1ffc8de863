/*
 * warp.h - resample a moving image onto the reference grid through a
 * polynomial map (poly.h), from a streamed or in-RAM source into a
 * caller's sink, in a few KB.
 *
 * Seed: Nagao et al. 1975, end of section 3.3: each point (X, Y) of the new
 * grid takes the grey value of the old image's grid point nearest to
 * (x, y) = (f(X, Y), g(X, Y)). Bilinear interpolation is offered too.
 *
 * OUTPUT: the map's reference grid, map->ref_w x map->ref_h pixels of the
 * source's format. Output pixel (X, Y) samples the source at
 * (u, v) = ssda_poly_eval(map, X, Y) (Q8: 1/256 px), exactly: the map is
 * stepped along each row by forward differences of its integer form in
 * 128-bit additions (3 per coordinate and pixel at order 3), which give
 * the same values as ssda_poly_eval at every pixel, so a row costs
 * O(width) and no rounding accumulates.
 *   NEAREST: the source pixel (floor((u + 128) / 256), floor((v + 128) /
 *     256)) (ties of exactly half a pixel go right/down); outside the
 *     source: fill.
 *   BILINEAR: with u = 256 i + a, v = 256 j + b (0 <= a, b < 256),
 *     ((p(i,j) (256-a) + p(i+1,j) a) (256-b) + (p(i,j+1) (256-a) +
 *      p(i+1,j+1) a) b + 32768) >> 16
 *     (<= 65535 * 2^16 + 2^15 < 2^32 for 16-bit samples), defined where
 *     0 <= u <= 256 (w - 1) and 0 <= v <= 256 (h - 1) (a pixel with weight
 *     0 is not read); elsewhere: fill.
 *
 * ORDER: the output is cut into strips of tile_w columns, each into tiles
 * of tile_h rows; tiles are done strip by strip, top to bottom, and each
 * tile row is handed to the sink as one segment (x0, y, n pixels). With
 * tile_w = the output width the sink receives whole rows, top to bottom.
 *
 * MEMORY: a streamed source's plate holds the source rows a tile needs;
 * ssda_warp_plan says what plate reads each source row about once and how
 * many bytes of arena that takes (the bound of the rows one output segment
 * touches: the map's slope and curvature over the tile, plus the
 * interpolation's extra row). Any arena from the minimum up works and gives
 * the same output; a smaller one re-reads rows. The job itself needs only
 * the caller's segment buffer (SSDA_WARP_ROW_SIZE).
 */
#ifndef SSDA_WARP_H
#define SSDA_WARP_H

#include "ssda/poly.h"
#include "ssda/stream.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Resampling rule. */
typedef enum {
    SSDA_WARP_NEAREST = 0, /* the seed's nearest grid point */
    SSDA_WARP_BILINEAR = 1
} ssda_warp_resample_t;

/* Receive n output pixels x .. x+n-1 of output row y (native-order
   uint16_t for 16-bit sources), valid during the call. Return 0 to go on,
   or a negative code: the warp stops and returns it unchanged. */
typedef int (*ssda_warp_sink_fn)(void *context, uint32_t x, uint32_t y, uint32_t n,
                                 const void *pixels);

/* Bytes of the segment buffer for tiles tile_w px wide. */
#define SSDA_WARP_ROW_SIZE(tile_w, format) ((size_t)(tile_w) * (size_t)(format))

/* Smallest tile side the plan picks (or the output's side if smaller). */
#define SSDA_WARP_MIN_TILE 16u

/* A warp's options. */
typedef struct {
    const ssda_poly_t *map;  /* reference -> source px; copied at init */
    ssda_warp_sink_fn sink;  /* required */
    void *context;           /* passed to sink */
    void *row;               /* segment buffer, 2-byte aligned for 16-bit */
    size_t row_size;         /* >= SSDA_WARP_ROW_SIZE(tile_w, format) */
    uint16_t tile_w;         /* strip width, px; 0 = as ssda_warp_plan
                                picks for the source's arena */
    uint16_t tile_h;         /* tile height, rows; 0 = as the plan picks */
    uint16_t fill;           /* output value where the source has no pixel
                                (<= 255 for 8-bit) */
    uint8_t resample;        /* ssda_warp_resample_t */
} ssda_warp_config_t;

/* What a warp of a tile size needs. */
typedef struct {
    uint16_t tile_w, tile_h;   /* the tile: strip width, rows per tile */
    uint16_t plate_w, plate_h; /* a plate holding the widest tile's source
                                  columns and its band of rows plus one */
    uint16_t band;             /* bound of the source rows an output segment
                                  touches */
    size_t arena_size;         /* SSDA_SOURCE_SIZE of that plate for the
                                  source: the arena of a read-once warp */
    size_t row_size;           /* SSDA_WARP_ROW_SIZE(tile_w, format) */
    bool fits;                 /* arena_size <= the config's arena_size */
} ssda_warp_plan_t;

/*
 * Plan a warp of `map` (resample: ssda_warp_resample_t) from a source
 * described by src (a config as for ssda_source_init: its geometry, format,
 * layout, read_size and arena_size are used; read and arena may be NULL).
 *   tile_w, tile_h: the tile; 0 = choose: with src->arena_size 0, whole
 *     output rows (tile_w = output width, tile_h = output height); else the
 *     tallest, then widest tile (heights halving from the output's, widths
 *     bisected, each at least SSDA_WARP_MIN_TILE) whose read-once arena fits
 *     src->arena_size; if none does, a SSDA_WARP_MIN_TILE square tile and
 *     fits = false.
 * Bounds use the map's largest slope and curvature over the grid, so they
 * hold for every tile (tests check every segment against them).
 * Returns SSDA_OK, or without writing *plan: SSDA_ERR_NULL, SSDA_ERR_ARG
 * (map invalid: order or scales out of range, or a grid that leaves the
 * map's domain, |X - cx| > 2^kx or |Y - cy| > 2^ky for some pixel of the
 * ref_w x ref_h grid, as after changing cx, kx or ref_w of a map from
 * ssda_poly_init or ssda_poly_fit; resample unknown, tile larger than the
 * output),
 * SSDA_ERR_SIZE / _FORMAT (source geometry or format invalid).
 */
int ssda_warp_plan(const ssda_poly_t *map, uint8_t resample, const ssda_source_config_t *src,
                   uint16_t tile_w, uint16_t tile_h, ssda_warp_plan_t *plan);

/* A warp job. All fields private; fill with ssda_warp_init. */
typedef struct {
    ssda_poly_t map;
    ssda_source_t *src;
    ssda_warp_sink_fn sink;
    void *context;
    uint8_t *row;
    uint16_t tile_w, tile_h, band;
    uint16_t fill;
    uint8_t resample;
    uint8_t format;
    uint32_t magic; /* written last by ssda_warp_init */
} ssda_warp_t;

/* What a run did. */
typedef struct {
    uint64_t filled;   /* output pixels set to fill (no source pixel) */
    uint64_t moves;    /* plate placements (streamed sources) */
} ssda_warp_stats_t;

/*
 * Resolve a warp of source src (in RAM or streamed; it must outlive the
 * job) by cfg into *job. No read is made.
 * Returns SSDA_OK, or with *job untouched:
 *   SSDA_ERR_NULL    job, cfg, cfg->map, cfg->sink, cfg->row or src NULL
 *   SSDA_ERR_STATE   src not initialised
 *   SSDA_ERR_ARG     map invalid (as ssda_warp_plan), resample unknown, fill
 *                    above the format's maximum, tile larger than the output
 *   SSDA_ERR_STRIDE  16-bit format with an odd row buffer address
 *   SSDA_ERR_BUFFER  row_size below SSDA_WARP_ROW_SIZE; a streamed source
 *                    whose arena cannot hold a 1 x 1 (nearest) or 2 x 2
 *                    (bilinear) plate
 */
int ssda_warp_init(ssda_warp_t *job, const ssda_warp_config_t *cfg, ssda_source_t *src);

/*
 * Run the warp: every output pixel once, to the sink, in the order above.
 * stats (may be NULL) is written on success. Returns SSDA_OK,
 * SSDA_ERR_NULL, SSDA_ERR_STATE (job not initialised), or a read() or
 * sink error unchanged (the segments before it were delivered). The job
 * may be run again (the same output).
 */
int ssda_warp_run(ssda_warp_t *job, ssda_warp_stats_t *stats);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_WARP_H */
