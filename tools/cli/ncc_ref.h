/*
 * ncc_ref.h - exhaustive normalised cross-correlation search (host float):
 * the reference `ssda compare` measures SSDA against (the seed's Table 1
 * compared with FFT cross-correlation; this is the same maximum, computed
 * directly).
 */
#ifndef SSDA_NCC_REF_H
#define SSDA_NCC_REF_H

#include <stdint.h>
#include "png_io.h"

/*
 * Search the win_w x win_h window of img_w at (wx, wy) over every placement
 * in the search_w x search_h area of img_a at (ax, ay) (all inside their
 * images). The best placement maximises
 *     NCC = sum (S - mean S)(W - mean W) / sqrt(sum (S - mean S)^2 sum (W - mean W)^2)
 * (0 where either is flat), ties to the smallest y then x. Writes the
 * placement (0-based in the area) and its NCC; returns 0, or -1 when out of memory.
 */
int ncc_search(const gray_image_t *img_a, uint32_t ax, uint32_t ay, uint32_t search_w,
               uint32_t search_h, const gray_image_t *img_w, uint32_t wx, uint32_t wy,
               uint32_t win_w, uint32_t win_h, uint32_t *best_x, uint32_t *best_y,
               double *best_ncc);

#endif /* SSDA_NCC_REF_H */
