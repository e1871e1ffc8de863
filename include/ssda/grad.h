/*
 * grad.h - the seed's differential pre-processing (Onoe, Maeda, Saito 1976,
 * Fig. 8): a first-derivative operator that enhances edges before SSDA, so
 * that motion is found even inside fully cloudy areas (Table 2; worse
 * elsewhere). On the 3 x 3 neighbourhood
 *
 *      A B C
 *      D E F        E' = |A + B + C - G - H - I| + |A + D + G - C - F - I|
 *      G H I
 *
 * (vertical difference of the top and bottom rows plus horizontal difference
 * of the left and right columns; the centre E is not used).
 *
 * RANGE: with samples in 0..V (V = 255 or 65535), E' <= 4 V exactly:
 * whatever the signs, the two terms add to a linear form whose positive
 * coefficients sum to 4 (e.g. 2A + B + D - F - H - 2I), reached by
 * A = B = D = V, F = H = I = 0. So E' <= 1020 for 8-bit and <= 262140 for
 * 16-bit input (the loose bound 6 V = 393210 is never reached).
 *
 * OUTPUT: E' >> shift stored as 8- or 16-bit samples; a value above the
 * output maximum is stored as that maximum and counted (the call reports
 * how many). Shifts that can never saturate:
 *      8-bit in  -> 16-bit out: 0 (exact E')   8-bit in  -> 8-bit out: 2
 *      16-bit in -> 16-bit out: 2              16-bit in -> 8-bit out: 10
 * (SSDA_GRAD_SAFE_SHIFT). Raw 12-bit data (V = 4095, E' <= 16380) fits
 * 16-bit output with shift 0.
 *
 * EDGES: only pixels with a full 3 x 3 neighbourhood are computed: the
 * output is (w - 2) x (h - 2), and output pixel (x, y) is E' centred on
 * input pixel (x + 1, y + 1). Both images of a pair shift alike, so motion
 * vectors measured on the outputs equal those on the inputs; window
 * positions are 1 px less in x and y. To keep the input's coordinates,
 * point the output at pixel (1, 1) of a w x h buffer (stride = w samples)
 * and fill its border as you wish.
 */
#ifndef SSDA_GRAD_H
#define SSDA_GRAD_H

#include "ssda/view.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest E' for an input format: 4 * (255 or 65535). */
#define SSDA_GRAD_MAX(in_format)                                             \
    ((uint32_t)4u * ((in_format) == SSDA_PIX_U8 ? 255u : 65535u))

/* Smallest shift with which E' >> shift never exceeds the output maximum. */
#define SSDA_GRAD_SAFE_SHIFT(in_format, out_format)                          \
    ((in_format) == SSDA_PIX_U8 ? ((out_format) == SSDA_PIX_U8 ? 2u : 0u)    \
                                : ((out_format) == SSDA_PIX_U8 ? 10u : 2u))

/* Bytes of a packed output (rows of (w-2) samples) for a w x h input,
   w, h >= 3; out_format's bytes per pixel is its value (1 or 2). Where
   size_t is 32 bits this wraps for outputs of 4 GB or more; ssda_grad
   refuses those with SSDA_ERR_BUFFER. */
#define SSDA_GRAD_SIZE(w, h, out_format)                                     \
    (((size_t)(w) - 2u) * ((size_t)(h) - 2u) * (size_t)(out_format))

/* Bytes needed when output rows are stride bytes apart. Where size_t is
   32 bits this wraps for outputs of 4 GB or more; ssda_grad checks the size
   in 64 bits and refuses those with SSDA_ERR_BUFFER. */
#define SSDA_GRAD_SIZE_STRIDED(w, h, stride, out_format)                     \
    (((size_t)(h) - 3u) * (size_t)(stride) + ((size_t)(w) - 2u) * (size_t)(out_format))

/* Where and how to write the result. */
typedef struct {
    void *data;       /* output pixel (0, 0); uint16_t-aligned for 16-bit;
                         must not overlap the input */
    size_t size;      /* bytes available at data */
    uint32_t stride;  /* bytes between output rows, a multiple of the output
                         bytes per pixel, >= (w - 2) * bpp (0 = packed) */
    uint8_t format;   /* output ssda_pixfmt_t: SSDA_PIX_U8 or SSDA_PIX_U16 */
    uint8_t shift;    /* E' >> shift is stored, 0..31 */
} ssda_grad_out_t;

/*
 * Apply the Fig. 8 operator to src into out (see the top of this file).
 *   src:       valid view, 8- or 16-bit, at least 3 x 3. Not modified.
 *   out:       destination description; out->data receives (w-2) x (h-2)
 *              samples (row padding beyond w-2 samples is not touched).
 *   saturated: if not NULL, receives how many samples were stored at the
 *              output maximum because E' >> shift exceeded it (0 with
 *              SSDA_GRAD_SAFE_SHIFT); <= 65533^2 < 2^32.
 * Returns SSDA_OK, or without writing anything:
 *   SSDA_ERR_NULL    src, out or out->data NULL
 *   SSDA_ERR_SIZE/_STRIDE/_FORMAT  invalid src; SSDA_ERR_SIZE also when src
 *                    is narrower or shorter than 3
 *   SSDA_ERR_FORMAT  unknown out->format
 *   SSDA_ERR_ARG     shift > 31
 *   SSDA_ERR_STRIDE  out->stride too small or not a multiple of the output
 *                    bytes per pixel; 16-bit output data misaligned
 *   SSDA_ERR_BUFFER  out->size below SSDA_GRAD_SIZE_STRIDED for the stride
 * Cost: 12 additions/subtractions and 2 absolute values per output sample.
 */
int ssda_grad(const ssda_view_t *src, const ssda_grad_out_t *out, uint32_t *saturated);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_GRAD_H */
