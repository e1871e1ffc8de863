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
#define SSDA__PRE_CAND_WORDS 48u /* their x, y and bound */

/*
 * The area's group sums for the bounds from its pixels in memory (base,
 * stride bytes a row, 8-bit when u8, else 16-bit; aw x ah), vertical sums
 * first (v: aw entries of scratch, rows of `group` pixels, loops along the
 * row) then sliding sums of L of them: g[y * nx + x], nx = aw - L + 1, is
 * the sum of the L x group pixels at (x, y), for y <= ah - group. A sum <=
 * group * L * 65535 < 2^32 (the engine's groups: L <= 16384 with 16-bit
 * samples). Returns the work in pixel ops (one per pixel added or removed
 * in a sum).
 */
SSDA_INTERNAL uint64_t ssda__pre_tables(const uint8_t *base, uint32_t stride, bool u8,
                                        uint32_t aw, uint32_t ah, uint32_t L, uint32_t group,
                                        uint32_t *g, uint32_t *v);

/* v[i] += row[i] (add) or -= it, i < n, the row 8-bit when u8, else
   16-bit: one op a pixel, modulo 2^32 (vertical sums end exact). Plain
   loops, for vectorising; also the tracking's shared tables' step. */
SSDA_INTERNAL void ssda__pre_vstep(uint32_t *v, const uint8_t *row, bool u8, uint32_t n,
                                   bool add);

/* Insertion sort of n candidates (x, y, bound) by bound, smallest first,
   stable (equal bounds keep their order). */
SSDA_INTERNAL void ssda__pre_sort(uint32_t n, uint32_t *cx, uint32_t *cy, uint32_t *cb);

/*
 * pre[y * nx + x] = sum over k < ngroups of |g[(y + k * group) * pitch + x] - w[k]|
 * for x < nx, y < ny: the successive-elimination bound of every position
 * from the area's group sums g (pitch entries a row; rows y + k * group
 * present) and the window's w. Each term and the bound are below 2^32 - 1
 * (the caller's condition: every SAD of the window is, and the bound is at
 * most the SAD). Also rmin[y], the smallest bound of row y, and the
 * candidates: the positions' range cut into SSDA__PRE_TILES^2 tiles (tile
 * column t holds x with ceil(t * nx / TILES) <= x < ceil((t + 1) * nx /
 * TILES); rows likewise), in each the position of the smallest bound, the
 * first in raster order among equal ones: cx, cy, cb (its bound), sorted
 * by bound, smallest first (stable). Returns the number of candidates
 * (tiles holding a position: nx or ny below SSDA__PRE_TILES leave some
 * empty). pre, rmin and the candidates must not overlap g or w.
 */
SSDA_INTERNAL uint32_t ssda__pre_bounds(const uint32_t *g, uint32_t pitch, uint32_t group,
                                        const uint32_t *w, uint32_t ngroups, uint32_t nx,
                                        uint32_t ny, uint32_t *pre, uint32_t *rmin, uint32_t *cx,
                                        uint32_t *cy, uint32_t *cb);

#endif /* SSDA_MATCH_PRE_H */
