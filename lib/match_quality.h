/*
 * match_quality.h - internal: what a search reports besides its best
 * position (match.h: SSDA_MATCH_UNIQUE, SSDA_MATCH_SUBPIXEL): uniqueness
 * from the list of the smallest completed positions the engine keeps, and
 * the equiangular sub-pixel fit. Integers only; every range is written
 * beside its value. Also the full SAD at one position (ssda__sad_full).
 */
#ifndef SSDA_MATCH_QUALITY_H
#define SSDA_MATCH_QUALITY_H

#include "match_rows.h"

/* A position and its SAD, ordered by the tie rule (the engine's cand_t). */
typedef struct {
    uint64_t sad; /* <= 65535^3 < 2^48 */
    uint32_t x;
    uint32_t y;
} ssda__cand_t;

/* floor(v * q8 / 256) for v < 2^48 and q8 <= 1024 (the uniqueness ratio
   times a SAD), from 32-bit partial products: no 64-bit multiply routine
   on cores without one. Result < 2^50. */
SSDA_INTERNAL uint64_t ssda__mul_q8(uint64_t v, uint16_t q8);

/* floor(256 s / b) for b > 0 and s <= 4 b (a quotient below 2^11), by
   shift and subtract: no 64-bit division. b == 0 (then s == 0): 256. */
SSDA_INTERNAL uint16_t ssda__ratio_q8(uint64_t s, uint64_t b);

/* The equiangular fit through (-1, l), (0, c), (+1, r) with c <= l, r:
   (l - r) / (2 (max(l, r) - c)) in Q8.8, -128 .. 128, rounded half away
   from zero; 0 when l == c == r. SADs are < 2^48; a denominator of 2^31
   or more is halved with the numerator until below (relative error of the
   quotient < 2^-30; the quotient stays within +-1 of the exact one). */
SSDA_INTERNAL int16_t ssda__vfit_q8(uint64_t l, uint64_t c, uint64_t r);

/* result.unique_q8 of match.h from the n entries of list (the smallest
   completed positions, ascending by the tie rule; best is list[0]): the
   first entry outside the square of radius rad around best whose SAD is
   at most floor(q8 * best / 256), as ssda__ratio_q8 of best; else
   SSDA_MATCH_UNIQUE_NONE. */
SSDA_INTERNAL uint16_t ssda__unique_q8(const ssda__cand_t *list, uint32_t n,
                                       const ssda__cand_t *best, uint16_t q8, uint32_t rad);

/* Full SAD of the window at (x, y) of the area (L x M pixels, added to
   *ops; no early exit): the all-cut fallback's reported SAD and the fit's
   missing neighbours. Returns SSDA_OK or a fetch error (*sad unchanged). */
SSDA_INTERNAL int ssda__sad_full(const ssda__rows_t *area, const ssda__rows_t *win,
                                 uint32_t x, uint32_t y, uint64_t *ops, uint64_t *sad);

/* The sub-pixel offsets (Q8.8) of best, nx x ny positions: the SADs of its
   neighbours from list (n entries, any order; NULL when n == 0) or summed
   over area and window now (L x M pixels, added to *ops). An axis whose
   best is on the border gets 0. Returns SSDA_OK or a fetch error. */
SSDA_INTERNAL int ssda__subpixel(const ssda__rows_t *area, const ssda__rows_t *win,
                                 const ssda__cand_t *list, uint32_t n, const ssda__cand_t *best,
                                 uint32_t nx, uint32_t ny, uint64_t *ops, int16_t *sub_x_q8,
                                 int16_t *sub_y_q8);

#endif /* SSDA_MATCH_QUALITY_H */
