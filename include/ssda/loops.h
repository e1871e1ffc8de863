/*
 * loops.h - closed loops of an edge map as symbols (Ishii and Hattori
 * 1985, seed 001, section 2 (f)): the regions that the edges of
 * ssda_edge_refine enclose, filtered by the seed's rules, each with its
 * centroid, area, mean grey, perimeter and a fixed number of contour
 * samples for Fourier descriptors (ssda/fourier.h).
 *
 * METHOD. (1) Every open branch is removed from the map (ends are deleted
 * until none is left: what remains are cycles and the branch points
 * between them). (2) The pixels that are not ON split into 4-connected
 * regions. A region is a loop when it does not touch the image border and
 * passes the filters (defaults: the seed's section 5):
 *     mean grey of the image over the region  >= grey_min   (50; 40 was
 *                                                 used for the later photo)
 *     area_min <= area (pixels) <= area_max    (50 .. 1000)
 *     perimeter^2 / area                       <= shape_max (30)
 * The perimeter is the length of the region's outer boundary traced
 * through the centres of its boundary pixels (steps of 1 and sqrt(2)); a
 * disc gives about 4 pi = 12.6, a 1 x 6 bar about 33. (3) Each loop's outer
 * boundary is resampled at `samples` points equally spaced along it
 * (linear interpolation between pixel centres, the seed's eq. 3 remark),
 * counter-clockwise on screen (x right, y down), starting at the region's
 * first pixel in raster order.
 *
 * WHICH THRESHOLDS MATTER. grey_min drops shadows (dark regions) and
 * depends on the exposure: with a gain change between the two images set
 * it per image or to SSDA_LOOPS_GREY_ANY. area_max bounds the work buffer
 * and drops big fields; shape_max drops slivers between parallel edges.
 * area_min drops noise. See docs/symbolic.md.
 */
#ifndef SSDA_LOOPS_H
#define SSDA_LOOPS_H

#include "ssda/view.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A contour sample: pixel coordinates in Q8 (256 = 1 px; pixel centres at
   integers). */
typedef struct {
    int32_t x_q8;
    int32_t y_q8;
} ssda_point_q8_t;

/* One closed loop. */
typedef struct {
    int32_t cx_q8, cy_q8;     /* centroid of the region's pixels, Q8 px */
    uint32_t area;            /* pixels */
    uint32_t perimeter_q8;    /* outer boundary length, Q8 px */
    uint32_t mean_q8;         /* mean grey over the region, Q8 (0..255 << 8) */
    uint16_t x0, y0, x1, y1;  /* bounding box, inclusive */
    ssda_point_q8_t *contour; /* its samples, inside the caller's points buffer */
} ssda_loop_t;

#define SSDA_LOOPS_GREY_ANY (-1)     /* grey_min: keep dark regions too */
#define SSDA_LOOPS_DEFAULT_GREY 50
#define SSDA_LOOPS_DEFAULT_AREA_MIN 50u
#define SSDA_LOOPS_DEFAULT_AREA_MAX 1000u
#define SSDA_LOOPS_DEFAULT_SHAPE 30u
#define SSDA_LOOPS_DEFAULT_SAMPLES 64u
#define SSDA_LOOPS_MAX_SAMPLES 1024u

/* Filters and sampling. Zero-filled = the seed's values. */
typedef struct {
    int16_t grey_min;    /* keep mean grey >= this, 1..255; 0 = 50;
                            SSDA_LOOPS_GREY_ANY = no grey filter */
    uint16_t shape_max;  /* keep perimeter^2 / area <= this (0 = 30) */
    uint32_t area_min;   /* pixels (0 = 50) */
    uint32_t area_max;   /* pixels, >= area_min (0 = 1000); sizes the work */
    uint16_t samples;    /* contour samples per loop: a power of two,
                            8..SSDA_LOOPS_MAX_SAMPLES (0 = 64) */
} ssda_loops_config_t;

/* What ssda_loops_find saw. */
typedef struct {
    uint32_t pruned;        /* open-branch pixels removed from the map */
    uint32_t regions;       /* 4-connected regions (a region larger than
                               area_max may count more than once) */
    uint32_t border;        /* regions touching the image border */
    uint32_t too_small, too_large, too_dark, too_long; /* filtered out */
    uint32_t loops;         /* loops found (all of them, even beyond max_loops) */
    uint32_t dropped;       /* loops beyond max_loops, not written */
} ssda_loops_stats_t;

/* Work buffer bytes: one uint32_t per pixel of the largest region kept. */
#define SSDA_LOOPS_WORK_SIZE(area_max) (((size_t)(area_max) + 1u) * 4u)
/* Points buffer bytes for max_loops loops of `samples` points. */
#define SSDA_LOOPS_POINTS_SIZE(max_loops, samples)                            \
    ((size_t)(max_loops) * (size_t)(samples) * sizeof(ssda_point_q8_t))

/*
 * Closed loops of a refined edge map (ssda_edge_refine).
 *   map:    the map, width x height of img; its open branches are REMOVED
 *           (ON bits cleared) and its private bits used; strength,
 *           direction and the cycles stay.
 *   img:    the 8-bit image the map came from (the mean grey).
 *   cfg:    NULL or filters (zero = default).
 *   work:   SSDA_LOOPS_WORK_SIZE(area_max) bytes, 4-byte aligned; scratch.
 *   loops:  up to max_loops loops, in raster order of their first pixel;
 *           loops beyond are counted (stats) but not written.
 *   points: SSDA_LOOPS_POINTS_SIZE(max_loops, samples) bytes, 4-byte
 *           aligned: loop i's contour is points + i * samples.
 *   n_loops: receives how many loops were written (<= max_loops).
 *   stats:  NULL or receives the counts.
 * Cost: O(pixels) for pruning and regions, O(samples + boundary) per loop.
 * Returns SSDA_OK, or without touching map and outputs:
 *   SSDA_ERR_NULL   map, img, work, n_loops NULL, or loops / points NULL
 *                   with max_loops > 0
 *   SSDA_ERR_FORMAT img not 8-bit;  img's view errors (ssda_view_check)
 *   SSDA_ERR_SIZE   img below 5 x 5
 *   SSDA_ERR_ARG    a cfg field out of range
 *   SSDA_ERR_BUFFER work_size or points_size too small
 *   SSDA_ERR_STRIDE map, work or points misaligned
 */
int ssda_loops_find(uint16_t *map, const ssda_view_t *img, const ssda_loops_config_t *cfg,
                    void *work, size_t work_size, ssda_loop_t *loops, uint32_t max_loops,
                    ssda_point_q8_t *points, size_t points_size, uint32_t *n_loops,
                    ssda_loops_stats_t *stats);

/*
 * Outer boundary of a set of pixels, resampled: the 8-connected set of
 * nonzero pixels of mask (8-bit) containing (x, y), which must be the set's
 * first pixel in raster order (its W, NW, N and NE neighbours zero or
 * outside). Same tracing and sampling as the loops (counter-clockwise on
 * screen, from (x, y)). For silhouettes (ssda shape).
 *   samples: a power of two, 8..SSDA_LOOPS_MAX_SAMPLES; points receives them.
 *   perimeter_q8: NULL or the boundary length, Q8 px (saturates at
 *                 UINT32_MAX for a boundary of 2^24 px or more).
 * A single pixel gives `samples` copies of its centre.
 * Returns SSDA_OK, SSDA_ERR_NULL, the view's errors, SSDA_ERR_FORMAT (not
 * 8-bit), SSDA_ERR_SIZE ((x, y) outside mask), SSDA_ERR_ARG ((x, y) zero
 * or not first in raster order, or samples invalid); points untouched on
 * error.
 */
int ssda_loops_contour(const ssda_view_t *mask, uint16_t x, uint16_t y, uint32_t samples,
                       ssda_point_q8_t *points, uint32_t *perimeter_q8);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_LOOPS_H */
