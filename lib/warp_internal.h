/*
 * warp_internal.h - internal: bounds of where a tile of the output samples
 * the source (warp_bounds.c), shared by the plan and the run.
 */
#ifndef SSDA_WARP_INTERNAL_H
#define SSDA_WARP_INTERNAL_H

#include "ssda/warp.h"
#include "poly_internal.h"

/* Largest change of 256 * (moving coordinate c) along `axis` (0: x, 1: y)
   over s px inside the grid: ceil(s * sum |c_t| e_t / 2^(k + 16)), from
   |d/dX xn^i yn^j| <= i / 2^kx on the grid. Saturates at 2^60. */
SSDA_INTERNAL int64_t ssda__warp_slope(const ssda_poly_t *p, const int64_t *c, uint32_t axis,
                                       uint32_t s);

/* Largest distance (Q8) between 256 * c and its bilinear interpolation
   from the corners of an sx x sy px rectangle of the grid:
   ceil((sx^2 max|c_XX| + sy^2 max|c_YY|) / 8), with
   |d2/dX2 xn^i yn^j| <= i (i - 1) / 2^(2 kx). Saturates at 2^60. */
SSDA_INTERNAL int64_t ssda__warp_curve(const ssda_poly_t *p, const int64_t *c, uint32_t sx,
                                       uint32_t sy);

/* Rows of the source (h rows high) that one output segment of n px
   samples, at most (nearest: the rows of the v range; bilinear: one more):
   a bound from the slope and curvature of v, capped at h. */
SSDA_INTERNAL uint32_t ssda__warp_band(const ssda_poly_t *p, bool bilinear, uint32_t n,
                                       uint32_t h);

/* Columns of the source (w wide) that a tile of n x m output px samples,
   at most, capped at w. */
SSDA_INTERNAL uint32_t ssda__warp_span(const ssda_poly_t *p, bool bilinear, uint32_t n,
                                       uint32_t m, uint32_t w);

/* floor(v / 256) for any int64_t v. */
static inline int64_t ssda__warp_px(int64_t v)
{
    return v >= 0 ? v / 256 : -((-v + 255) / 256);
}

#endif /* SSDA_WARP_INTERNAL_H */
