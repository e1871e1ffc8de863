/*
 * warp_affine.h - resample MOV onto REF's grid through an affine map of REF
 * pixel coordinates to MOV ones (bilinear, host doubles). The registration
 * issue's polynomial warp, of which this is order 1, had not landed when
 * `ssda symreg -o` was written.
 */
#ifndef SSDA_WARP_AFFINE_H
#define SSDA_WARP_AFFINE_H

#include "png_io.h"

/* out (allocated here, ref_w x ref_h, mov's depth): out(x, y) = mov(A(x, y))
   with A = [a b c; d e f] (x' = a x + b y + c, y' = d x + e y + f), bilinear;
   pixels mapped outside mov are fill. Returns 0 or -1 (out of memory). */
int warp_affine(const gray_image_t *mov, const double A[6], uint32_t ref_w, uint32_t ref_h,
                uint32_t fill, gray_image_t *out);

#endif /* SSDA_WARP_AFFINE_H */
