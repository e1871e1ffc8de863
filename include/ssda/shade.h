/*
 * shade.h - shading removal: the seed's low-pass shading function of
 * several images, subtracted keeping the level at the shading centre.
 *
 * Seed: Nagao et al. 1975, section 4: lens shading is a very low-frequency
 * change of brightness; a low-pass filter passing the DC and the one-cycle
 * components of each image, averaged over a few images taken under the
 * same conditions (so that the scenes' own low frequencies average out),
 * gives the shading function, which is subtracted from each image while
 * the DC at the shading centre is kept (Figs. 10-13).
 *
 * THE SHADING FUNCTION of images I_1..I_n (width w, height h, w, h >= 3):
 *     S(x, y) = sum_{p,q in {0,1,2}} K_pq f_p(x) g_q(y)
 * with f_0 = 1, f_1 = cos(2 pi x / w), f_2 = sin(2 pi x / w) (g alike in
 * y / h), and K_pq the mean over the images of their projections on
 * f_p g_q, scaled for the discrete grid (sum f_0^2 = w, sum f_1^2 =
 * sum f_2^2 = w / 2): K_pq = s_p s_q / (n w h) sum_images sum_xy I f_p g_q,
 * s_0 = 1, s_1 = s_2 = 2. That is the 2-D DFT of the mean image kept at
 * frequencies (0, +-1) in each direction and transformed back.
 *
 * FIXED POINT: f and g are sin_q15 of the phase x * round(2^32 / w) (Q32
 * turns; at most one part in 2^31 off 2 pi x / w), from a 7th-order
 * polynomial within 0.03 LSB of Q15 of every bit of that phase, then
 * rounded: within 0.53 LSB of the true value (tests: through K, against
 * a 64-bit reference sine, at every column of widths 3..97); the
 * projections are summed exactly (128 bits); K in Q8 grey levels
 * (<= 4 * 65535 * 256 < 2^27); S in Q8 (K f g summed in 64 bits).
 *
 * CORRECTION: out = clamp(round(I - S(x, y) + S(cx, cy)), 0, max), where
 * (cx, cy) is the shading centre: the maximum of S (SSDA_SHADE_CENTRE_MAX:
 * a bright centre and darker rim, the usual vignetting of a positive) or
 * its minimum (SSDA_SHADE_CENTRE_MIN: film density, as in the seed's
 * Fig. 10), or a point the caller sets. The extremum is searched on a grid
 * of about 32 x 32 points, then by steps halving to 1 px towards the best
 * neighbour (S has one cycle per direction: one extremum of each kind).
 *
 * STREAMING: rows are pushed in order (the images one after another); the
 * state is this struct (about 250 bytes), no buffer. Applying is per row.
 */
#ifndef SSDA_SHADE_H
#define SSDA_SHADE_H

#include "ssda/view.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which extremum of S is the shading centre. */
typedef enum {
    SSDA_SHADE_CENTRE_MAX = 0,
    SSDA_SHADE_CENTRE_MIN = 1
} ssda_shade_centre_t;

/* A shading estimate. Fill with ssda_shade_init; the fields marked public
   may be read after ssda_shade_finish; the rest is private. */
typedef struct {
    uint64_t acc[9][2];    /* exact sums (128-bit words) of I f_p g_q */
    int64_t row[3];        /* this row's sums of I f_p, Q15 */
    int32_t k_q8[9];       /* K_pq, Q8 grey (after finish) */
    uint32_t step_x, step_y; /* phase steps, Q32 turns per px */
    uint16_t width, height;
    uint16_t y;            /* next row to push */
    uint16_t images;       /* complete images pushed (<= 65535) */
    uint8_t format;
    uint32_t magic;        /* which phase: accumulating or finished */
    /* public after ssda_shade_finish (or ssda_shade_set_centre): */
    uint16_t centre_x, centre_y; /* the shading centre, px */
    int32_t centre_q8;     /* S at the centre, Q8 grey */
} ssda_shade_t;

/*
 * Start an estimate for images of width x height pixels (3..65535 each) of
 * the given format. Returns SSDA_OK, or with *sh untouched: SSDA_ERR_NULL,
 * SSDA_ERR_SIZE (a side below 3), SSDA_ERR_FORMAT.
 */
int ssda_shade_init(ssda_shade_t *sh, uint16_t width, uint16_t height, uint8_t format);

/*
 * Push the next row (width pixels; uint16_t-aligned for 16-bit) of the
 * image being accumulated; after `height` rows the next image begins.
 * Cost: two sines per pixel and three multiply-adds.
 * Returns SSDA_OK, SSDA_ERR_NULL, SSDA_ERR_STATE (not initialised, already
 * finished, or 65535 images pushed).
 */
int ssda_shade_add_row(ssda_shade_t *sh, const void *row);

/*
 * Compute K and the centre (mode: ssda_shade_centre_t). Needs at least one
 * complete image and no partial one. Returns SSDA_OK, SSDA_ERR_NULL,
 * SSDA_ERR_STATE (no image, a partial image, not initialised, or finished
 * already), SSDA_ERR_ARG (unknown mode); nothing changes on error.
 */
int ssda_shade_finish(ssda_shade_t *sh, uint8_t mode);

/* Use (x, y) as the shading centre instead (after finish). Returns SSDA_OK,
   SSDA_ERR_NULL, SSDA_ERR_STATE (not finished), SSDA_ERR_SIZE (outside). */
int ssda_shade_set_centre(ssda_shade_t *sh, uint16_t x, uint16_t y);

/* S(x, y) in Q8 grey (after finish). Returns SSDA_OK, SSDA_ERR_NULL,
   SSDA_ERR_STATE, SSDA_ERR_SIZE (outside the image). */
int ssda_shade_eval(const ssda_shade_t *sh, uint32_t x, uint32_t y, int32_t *s_q8);

/*
 * Correct row y (width pixels) of an image of the estimate's size and
 * format: out = clamp(round(in - S + S(centre))). in and out may be the
 * same buffer. Returns SSDA_OK, SSDA_ERR_NULL, SSDA_ERR_STATE (not
 * finished), SSDA_ERR_SIZE (y outside).
 */
int ssda_shade_apply_row(const ssda_shade_t *sh, uint32_t y, const void *in, void *out);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_SHADE_H */
