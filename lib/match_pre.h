/*
 * match_pre.h - internal: every position's group bound at once, for a
 * single search over a whole area (SSDA_MATCH_BLOCKS with windows too small
 * for its block levels; match_engine.c, scan_pre). Plain loops over
 * uint32_t rows, so that a host compiler vectorises them.
 */
#ifndef SSDA_MATCH_PRE_H
#define SSDA_MATCH_PRE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "compiler.h"

/* The candidates summed first: the position of the smallest bound in each
   of SSDA__PRE_TILES x SSDA__PRE_TILES tiles of the positions. */
#define SSDA__PRE_TILES 4u
#define SSDA__PRE_CANDS 16u

/*
 * pre[y * nx + x] = sum over k < ngroups of |g[(y + k * group) * pitch + x] - w[k]|
 * for x < nx, y < ny: the successive-elimination bound of every position
 * from the area's group sums g (pitch entries a row; rows y + k * group
 * present) and the window's w. Each term and the bound are below 2^32 - 1
 * (the caller's condition: every SAD of the window is, and the bound is at
 * most the SAD). pre must not overlap g.
 */
SSDA_INTERNAL void ssda__pre_groups(const uint32_t *g, uint32_t pitch, uint32_t group,
                                    const uint32_t *w, uint32_t ngroups, uint32_t nx,
                                    uint32_t ny, uint32_t *pre);

/*
 * The candidates: the positions' range cut into SSDA__PRE_TILES^2 tiles
 * (tile column t holds x with t * nx / TILES <= x < (t + 1) * nx / TILES,
 * rounded up; rows likewise), and in each the position of the smallest
 * pre entry, the first in raster order among equal ones; cx, cy, cb (its
 * bound) in tile order, then sorted by bound, smallest first (stable).
 * Returns the number of candidates (tiles holding a position: nx or ny
 * below SSDA__PRE_TILES leave some empty).
 */
SSDA_INTERNAL uint32_t ssda__pre_seeds(const uint32_t *pre, uint32_t nx, uint32_t ny,
                                       uint32_t *cx, uint32_t *cy, uint32_t *cb);

#endif /* SSDA_MATCH_PRE_H */
