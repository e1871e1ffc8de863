/*
 * composite.h - composite template matching (seed 003, Kanehira et al.,
 * section 3): motion vectors of many small templates of a reference image,
 * found in the next image relative to one "origin" template.
 *
 * TEMPLATES. Templates of T x T pixels are taken every S px (seed: 20 x 20
 * every 5 px) from the region (roi) of REF: template k = (col, row), k =
 * row * cols + col, has its top-left at (roi_x + col S, roi_y + row S). They
 * are ranked by their standard deviation (the seed's priority): the first,
 * the ORIGIN, is the template of largest variance (ties: the smallest k).
 * Templates whose standard deviation is below min_std (flat ones, whatever
 * min_std) are not matched (status SSDA_COMPOSITE_FLAT).
 *
 * SEARCH (correlation coefficient, ssda/ncc.h). The origin is searched over
 * the whole of NEXT. Every other template k is searched only inside the
 * circle around p0' + (p_k - p0), where p0 and p0' are the origin's places
 * in REF and NEXT and p_k the template's place in REF (the seed's relative
 * vector), of radius
 *     r_k = max(min_radius, ceil(radius_q8 * |p_k - p0| / 256)) px,
 * proportional to the relative vector's length: the farther a template is
 * from the origin, the more the field may have sheared or turned between
 * the two images. The seed gives no factor; the default 1/4 (radius_q8 =
 * 64) admits a relative displacement of a quarter of the distance (a
 * rotation of about 14 degrees, or a 25 % strain, between the two images),
 * and min_radius = 3 px admits noise and small local motion next to the
 * origin; docs/correlation.md measures the choice. A circle that leaves
 * NEXT is clipped to it; a template whose centre p0' + (p_k - p0) is not a
 * position of NEXT (its top-left outside 0..next_w - T, 0..next_h - T) is
 * SSDA_COMPOSITE_EDGE, even where part of its circle is inside.
 *
 * MASK (flag SSDA_COMPOSITE_MASK; the grid tracking's SSDA_TRACK_MASK, see
 * ssda/track.h, by the same test): pixels equal to mask_value are fill (no
 * data: GOES-16's 4095), and nothing that reads one is trusted, because a
 * fill pixel could attract or repel the match:
 *   - a template holding mask_value is SSDA_COMPOSITE_MASKED (not matched,
 *     never the origin; tested before the flat test, as in the tracking);
 *   - a template other than the origin whose search area (the part of NEXT
 *     its search reads: the circle's bounding box plus the template) holds
 *     mask_value is SSDA_COMPOSITE_MASKED (tested after EDGE), as a track
 *     window whose search area holds it;
 *   - the origin's area is the whole of NEXT, which that rule would mask
 *     whenever NEXT holds any fill: instead the origin is searched over the
 *     whole of NEXT, and if the T x T placement it matched holds mask_value
 *     it is SSDA_COMPOSITE_MASKED and the next template in rank (largest
 *     variance left) becomes the origin, searched likewise (each try costs
 *     one whole-NEXT search). No origin left: every entry FLAT or MASKED.
 *
 * SET SCORE: the mean rho of the templates matched (the seed's "total
 * evaluation value of the TP group").
 *
 * VECTORS: the motion REF -> NEXT of each template, (dx, dy) = its place in
 * NEXT minus its place in REF, in Q24.8 px: integers times 256, or with
 * SSDA_COMPOSITE_SUBPIXEL refined by a parabola through rho at the best
 * place and its two neighbours along each axis (offset in [-0.5, 0.5] px).
 *
 * REF and NEXT share one pixel coordinate system (their sizes may differ).
 * Nothing is allocated: the caller passes the template array and a work
 * buffer for the searches.
 */
#ifndef SSDA_COMPOSITE_H
#define SSDA_COMPOSITE_H

#include "ssda/ncc.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SSDA_COMPOSITE_DEFAULT_TP 20u       /* T, px (the seed's) */
#define SSDA_COMPOSITE_DEFAULT_STEP 5u      /* S, px (the seed's) */
#define SSDA_COMPOSITE_DEFAULT_RADIUS_Q8 64u /* 1/4 */
#define SSDA_COMPOSITE_DEFAULT_MIN_RADIUS 3u /* px */

/* Per-template status. */
typedef enum {
    SSDA_COMPOSITE_OK = 0,   /* matched: dx, dy, rho valid */
    SSDA_COMPOSITE_FLAT = 1, /* standard deviation below min_std: not matched */
    SSDA_COMPOSITE_EDGE = 2, /* its circle's centre is not a position of NEXT */
    SSDA_COMPOSITE_MASKED = 3 /* SSDA_COMPOSITE_MASK: it, its search area or (the
                                 origin) its match holds mask_value */
} ssda_composite_status_t;

/* Flags. */
#define SSDA_COMPOSITE_SUBPIXEL 0x01u /* parabolic sub-pixel vectors */
#define SSDA_COMPOSITE_MASK 0x02u     /* mask_value is fill (MASK, above) */

typedef struct {
    uint16_t tp;           /* template side T, px (0 = 20), <= 256 */
    uint16_t step;         /* spacing S, px (0 = 5) */
    uint16_t roi_x, roi_y; /* template region in REF, px */
    uint16_t roi_w, roi_h; /* its size (0 = to the right / bottom edge of REF) */
    uint16_t radius_q8;    /* radius per px of relative vector, Q8.8 (0 = 64: 1/4) */
    uint16_t min_radius;   /* px (0 = 3) */
    uint16_t min_std_q8;   /* templates with a smaller standard deviation, Q8.8
                              sample units, are FLAT (0: only truly flat ones) */
    uint8_t metric;        /* SSDA_NCC_RHO or SSDA_NCC_ABS */
    uint8_t flags;         /* SSDA_COMPOSITE_SUBPIXEL | SSDA_COMPOSITE_MASK, or 0 */
    uint16_t mask_value;   /* SSDA_COMPOSITE_MASK: the fill value, <= the
                              format's maximum (GOES-16: 4095) */
    void *work;            /* caller buffer, 8-byte aligned, */
    size_t work_size;      /*   >= SSDA_COMPOSITE_WORK_SIZE(next_w, tp) bytes */
} ssda_composite_config_t;

/* One template. Laid out so that ssda/relax.h reads an array of these in
   place (dx, dy in Q8, status 0 = OK). */
typedef struct {
    uint64_t var;     /* n^2 times the template's variance, n Sww - Sw^2
                         (n = T^2; standard deviation = sqrt(var) / n) */
    int32_t dx, dy;   /* OK: motion REF -> NEXT, Q24.8 px; else 0 */
    int32_t rho_q30;  /* OK: rho at the match, Q2.30; else 0 */
    uint16_t x, y;    /* template top-left in REF, px */
    uint8_t status;   /* ssda_composite_status_t */
    uint8_t origin;   /* 1 for the origin template */
} ssda_composite_tp_t;

typedef struct {
    uint64_t pixel_ops;    /* sum of the searches' pixel_ops and the variances' */
    int32_t mean_rho_q30;  /* mean rho of the OK templates (0 if none) */
    uint32_t count;        /* templates in the grid (cols * rows) */
    uint32_t ok;           /* templates matched */
    uint32_t origin;       /* index of the origin template */
    uint16_t cols, rows;   /* template grid */
} ssda_composite_result_t;

/* Templates along one axis of a region len px long. */
#define SSDA_COMPOSITE_DIM(len, tp, step)                                     \
    (((size_t)(len) >= (size_t)(tp)) ? (((size_t)(len) - (size_t)(tp)) / (size_t)(step) + 1u) \
                                     : (size_t)0u)

/* Bytes of work buffer for NEXT next_w px wide and templates of tp px (the
   origin's search over the whole of NEXT is the largest). */
#define SSDA_COMPOSITE_WORK_SIZE(next_w, tp) SSDA_NCC_WORK_SIZE(next_w, tp, tp)

/*
 * Match the templates of REF in NEXT.
 *   ref, next: valid views of the same pixel format, each at least T x T.
 *   cfg:       options and work buffer (not NULL).
 *   out:       out_count >= cols * rows entries; entry k is template k.
 *   result:    totals (not NULL).
 * Returns SSDA_OK, or without writing out or result:
 *   SSDA_ERR_NULL    ref, next, cfg, out, result or cfg->work NULL
 *   SSDA_ERR_SIZE/_STRIDE/_FORMAT  invalid views; SSDA_ERR_SIZE also when the
 *                    region is not inside REF or holds no template, or NEXT
 *                    is smaller than a template
 *   SSDA_ERR_FORMAT  ref and next formats differ
 *   SSDA_ERR_ARG     tp > 256, step 0 after defaults (never), unknown metric
 *                    or flags; SSDA_COMPOSITE_MASK with a mask_value above
 *                    the format's maximum (255 for SSDA_PIX_U8)
 *   SSDA_ERR_BUFFER  out_count below the grid; work too small or misaligned
 * If no template has texture (or, with the mask, none is left unmasked),
 * every entry is FLAT or MASKED, result->origin is UINT32_MAX and
 * result->ok = 0.
 */
int ssda_composite_match(const ssda_view_t *ref, const ssda_view_t *next,
                         const ssda_composite_config_t *cfg, ssda_composite_tp_t *out,
                         size_t out_count, ssda_composite_result_t *result);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_COMPOSITE_H */
