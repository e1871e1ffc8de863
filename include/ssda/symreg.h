/*
 * symreg.h - symbolic registration of two images by their closed loops
 * (Ishii and Hattori 1985, seed 001, section 4 (a): "one pair of loops as
 * the nucleus"). Input: the loops of both images (ssda/loops.h) and their
 * Fourier descriptors (ssda/fourier.h). Output: the affine transform
 * taking REF pixel coordinates to MOV ones, the matched loop pairs and the
 * residuals.
 *
 * METHOD (seed [1]-[3]).
 * [1] Every (ref, mov) pair whose areas fit the scale range is matched
 *     with s, phi and alpha unconstrained (ssda_fd_match; a pair whose E^2 lower
 *     bound cannot enter the lists below is skipped without the search).
 *     The `nuclei` pairs of smallest E^2 (<= e2_nucleus), at most two from
 *     any one REF loop, are the nuclei (ties: the earlier pair).
 * [2] For each nucleus in order of E^2 (one already paired in the best
 *     final set is skipped: it grows into that set again, seed (a)):
 *   [2.1] start from the similarity of eq. 16: MOV = s R(phi) (REF - c_ref)
 *         + c_mov with the nucleus's s, phi and centroids;
 *   [2.2] every REF loop's centroid is mapped; MOV loops within
 *         reach_min + reach * (its distance from the nucleus) of it whose
 *         area fits (area_ratio) are matched with scale and rotation fixed
 *         (ssda_fd_match_fixed; s = sqrt|ae - bd| and phi the mean angle of
 *         the mapped axes, eqs. 14-15); the best E^2 <= e2_grow pairs it
 *         (each MOV loop used once: the smaller E^2 keeps it; a pair whose
 *         E^2 lower bound is above e2_grow is not searched). Fewer than
 *         min_pairs pairs, or no more than the last final set: next nucleus;
 *   [2.3] the affine transform is fitted to the pairs' centroids by least
 *         squares (eq. 17);
 *   [2.4] if a residual exceeds resid_max or their mean resid_mean, or
 *         the transform shears more than the seed assumes (views from
 *         straight above: the mapped x and y axes differ in length by more
 *         than shear, or meet further than acos(shear) from 90 degrees),
 *         the pair of largest residual is dropped and [2.3] repeats;
 *   [2.5] if a pair's E^2 with the fitted scale and rotation exceeds
 *         e2_final, the largest is dropped and [2.3] repeats; otherwise
 *         the set is final and [2.2] grows it from the new transform.
 *     Dropping the nucleus itself, or going below min_pairs, ends the
 *     nucleus.
 * [3] The final set with the most pairs wins (ties: the smaller RMS
 *     residual, then the earlier nucleus).
 * A loop whose descriptors have zero energy (all samples equal: a one-pixel
 * region) matches nothing (fourier.h) and is never paired.
 * Not built: the seed's section 4 (b) (two nuclei for the start).
 *
 * FIXED POINT. Centroids Q8 px; the affine's linear part Q16, its
 * translation Q8 px; the least squares on centred coordinates with sums
 * narrowed to 31 bits before the 2 x 2 solve (relative error < 2^-29; a
 * set whose determinant falls below 2^-20 of its scale is collinear and
 * refused). Everything is deterministic: same inputs, same bits.
 */
#ifndef SSDA_SYMREG_H
#define SSDA_SYMREG_H

#include "ssda/fourier.h"

#ifdef __cplusplus
extern "C" {
#endif

/* MOV (x', y') = (a x + b y + c, d x + e y + f) of REF (x, y), pixels. */
typedef struct {
    int32_t a_q16, b_q16, c_q8;
    int32_t d_q16, e_q16, f_q8;
} ssda_symreg_affine_t;

/* Settings. Zero-filled = defaults (docs/symbolic.md says which matter). */
typedef struct {
    uint16_t nuclei;        /* nuclei tried (0 = 100; the seed: "for example 30") */
    uint16_t min_pairs;     /* pairs a registration needs, >= 3 (the seed's
                               least); 0 = SSDA_SYMREG_DEFAULT_MIN_PAIRS */
    uint32_t e2_nucleus_q16; /* [1] unconstrained-match E^2 of a nucleus (0 = 0.05) */
    uint32_t e2_grow_q16;   /* [2.2] fixed-match E^2 to pair (0 = 0.25) */
    uint32_t e2_final_q16;  /* [2.5] fixed-match E^2 kept, <= e2_grow (0 = 0.15) */
    uint32_t scale_min_q16, scale_max_q16; /* [1] nucleus scales (0 = 0.5, 2.0) */
    uint32_t area_ratio_q8; /* [2.2] area / expected area within 1/r..r (0 = 2.0) */
    uint32_t reach_q16;     /* [2.2] search radius per px from the nucleus (0 = 0.1) */
    uint32_t reach_min_q8;  /* [2.2] plus this, px Q8 (0 = 4 px) */
    uint32_t resid_max_q8;  /* [2.4] largest residual, Q8 px (0 = 3 px) */
    uint32_t resid_mean_q8; /* [2.4] largest mean residual, Q8 px (0 = 1.5 px) */
    uint32_t shear_q16;     /* [2.4] largest shear, <= 65536 (0 = 0.15; 65536 = any) */
} ssda_symreg_config_t;

/* A matched pair in the winning registration. */
typedef struct {
    uint16_t ref, mov;      /* loop indices */
    uint32_t s_q16, phi;    /* unconstrained match of the pair (ssda_fd_match ref -> mov) */
    uint32_t e2_q16;        /* its E^2 */
    uint32_t e2_fixed_q16;  /* E^2 with the registration's scale and rotation */
    uint32_t resid_q8;      /* |MOV centroid - affine(REF centroid)|, Q8 px */
} ssda_symreg_pair_t;

/* Outcome. */
typedef struct {
    ssda_symreg_affine_t affine;   /* valid when pairs > 0 */
    uint32_t pairs;         /* pairs of the winner (0: no registration) */
    uint32_t rms_q8;        /* RMS residual of the winner, Q8 px */
    uint32_t scale_q16;     /* sqrt|ae - bd| of the winner (eq. 14) */
    uint32_t rotation;      /* its mean axis rotation (eq. 15), turns */
    uint32_t candidates;    /* [1] pairs that entered a nucleus list (E^2 <=
                               e2_nucleus and below the lists' worst then) */
    uint32_t nuclei;        /* nuclei tried */
    uint32_t best_nucleus;  /* index of the winning nucleus among them */
    uint32_t matches;       /* unconstrained matches run in [1] */
    uint32_t skipped;       /* [1] pairs the E^2 bound skipped */
} ssda_symreg_result_t;

/* Pairs a registration needs when the config says 0: 6, not the seed's 3.
   Three pairs fit an affine transform exactly (nothing left to check) and
   four or five barely: on real photographs turned and scaled, 38 of 41
   wrong registrations had 3 to 5 pairs, every right one 8 or more
   (docs/symbolic.md). */
#define SSDA_SYMREG_DEFAULT_MIN_PAIRS 6u

/* Nuclei tried when the config says 0. */
#define SSDA_SYMREG_DEFAULT_NUCLEI 100u

/* Most loops per image. */
#define SSDA_SYMREG_MAX_LOOPS 4096u

/* Work bytes: nuclei, the current and the best pair sets, MOV owners. */
#define SSDA_SYMREG_WORK_SIZE(n_ref, n_mov, nuclei)                           \
    ((size_t)(nuclei) * 16u + (size_t)(n_ref) * 16u + (size_t)(n_mov) * 2u + 4u)

/*
 * Register MOV to REF.
 *   ref, fd_ref: n_ref loops and their descriptors (same order, all of the
 *                same descriptor order); likewise mov, fd_mov.
 *                n_ref, n_mov <= SSDA_SYMREG_MAX_LOOPS.
 *   cfg:     NULL or settings.
 *   work:    SSDA_SYMREG_WORK_SIZE(n_ref, n_mov, nuclei) bytes, 4-byte aligned.
 *   pairs:   receives up to max_pairs pairs of the winner, in REF order;
 *            may be NULL with max_pairs 0.
 *   res:     receives the outcome. res->pairs = 0 when no nucleus reached
 *            min_pairs (too few loops or matches: res->candidates and
 *            res->nuclei say how far it got); that is SSDA_OK too.
 * Cost: n_ref * n_mov bounds, at most that many unconstrained matches, then per
 * nucleus a few passes of n_ref * n_mov distance tests and fixed matches.
 * Returns SSDA_OK, or without writing outputs: SSDA_ERR_NULL,
 * SSDA_ERR_ARG (a count above the maximum, descriptor orders that differ,
 * a cfg field out of range), SSDA_ERR_BUFFER, SSDA_ERR_STRIDE (work
 * misaligned).
 */
int ssda_symreg(const ssda_loop_t *ref, const ssda_fd_t *fd_ref, uint32_t n_ref,
                const ssda_loop_t *mov, const ssda_fd_t *fd_mov, uint32_t n_mov,
                const ssda_symreg_config_t *cfg, void *work, size_t work_size,
                ssda_symreg_pair_t *pairs, uint32_t max_pairs, ssda_symreg_result_t *res);

/*
 * Map a point (Q8 px) by an affine transform; results saturate at
 * +-2^31 - 1. Returns SSDA_OK or SSDA_ERR_NULL.
 */
int ssda_symreg_apply(const ssda_symreg_affine_t *t, int32_t x_q8, int32_t y_q8, int32_t *u_q8,
                       int32_t *v_q8);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_SYMREG_H */
