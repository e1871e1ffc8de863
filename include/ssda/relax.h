/*
 * relax.h - cleaning a grid of motion vectors: relaxation labelling (seed
 * 003, Kanehira et al., section 4, eqs. 1-3) and, as the baseline PIV users
 * know, the normalised median test with replacement (Westerweel & Scarano
 * 2005). Both read any grid of vectors through strides, so an
 * ssda_track_vector_t array (ssda_track) and an ssda_composite_tp_t array
 * (composite templates) are read in place.
 *
 * RELAXATION LABELLING. Each valid vector is put in one of 48 classes
 * (SSDA_RELAX_CLASSES) by its angle and length: 8 direction sectors of 45
 * degrees centred on 0, 45, ..., 315 degrees (x right, y down: sector 2 is
 * straight down) times 6 length classes [0, s), [s, 2s), ..., [5s, inf) for
 * a length step s (cfg->len_step_q8; by default 2/7 of the mean length of
 * the valid vectors, so the typical vector sits in the middle of class 3,
 * and at least 1/4 px). Finer length classes than sectors: the seed's
 * compatibility falls by only 0.2 per class step, and lengths are where a
 * tracked vector's errors show (docs/correlation.md compares layouts). The
 * seed's likelihoods 0.53 for the vector's class and
 * 0.01 for the 47 others sum to 1 with 48 classes; they are 17 352 and 328 in
 * Q15 here (exactly 1.0 in all). Each iteration (eqs. 1-2):
 *     q(c)  = (1/n) sum over the n valid 8-neighbours k of sum_c' r(c, c') P_k(c')
 *     P(c) <- P(c) (1 + q(c)) / sum_c'' P(c'') (1 + q(c''))
 * with the compatibility of eq. 3, r = 1 - 0.2 dtheta - 0.2 dl clipped to
 * [-1, 1] (it never clips here: r >= -0.8), dtheta the circular sector
 * distance (0..4) and dl the length class distance (0..5), both in class
 * steps; dtheta counts as 0 when either
 * class is the shortest (a vector shorter than s has no reliable direction).
 * All nodes are updated from the same iteration's likelihoods (synchronous).
 * After N iterations the output is the expectation over the classes of the
 * vectors that belong to them (the seed's restored vector), read locally:
 *     sum_c P(c) v(c) / sum_c P(c)
 * over the classes c present among the node and its valid 8-neighbours,
 * v(c) the mean of their vectors of class c. A vector in a consistent
 * neighbourhood stays what it is; an outlier takes the neighbours' vectors
 * as its own class's likelihood dies. With SSDA_RELAX_KEEP a vector whose
 * most likely class is still its own is kept unchanged.
 *
 * Likelihoods are Q15 (uint16_t, 1.0 = 32768), rounded down at each
 * normalisation (their sum stays within 48 LSB below 1.0). q and r are Q15.
 * Vectors are Q24.8 px in the output.
 *
 * NORMALISED MEDIAN TEST (Westerweel & Scarano 2005, Exp. Fluids 39:1096).
 * For each valid vector u0 and each component, with u_m the median of its
 * valid 8-neighbours and r_m the median of their residuals |u_i - u_m|:
 *     r0* = |u0 - u_m| / (r_m + eps)
 * The vector is an outlier when r0* > threshold for either component
 * (defaults: eps = 0.1 px, threshold 2, the paper's), and is replaced by
 * (u_m,x, u_m,y). Medians of an even count are the mean of the two middle
 * values (rounded toward minus infinity in Q8). Vectors with fewer than 3
 * valid neighbours are not tested. Every test reads the input field
 * (replacements do not feed later tests).
 */
#ifndef SSDA_RELAX_H
#define SSDA_RELAX_H

#include "ssda/ssda.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SSDA_RELAX_CLASSES 48u  /* 8 sectors x 6 length classes */
#define SSDA_RELAX_SECTORS 8u
#define SSDA_RELAX_LENGTHS 6u
#define SSDA_RELAX_DEFAULT_ITERATIONS 50u
/* Largest |component| accepted, in the grid's own units shifted to Q8: 2^23
   (32 768 px). */
#define SSDA_RELAX_MAX_Q8 8388608

/* A grid of vectors read in place. Vector k = row * cols + col is at
   byte offset k * stride from each of dx, dy (and status). */
typedef struct {
    const int32_t *dx;      /* x component of vector 0, Q(frac_bits) px */
    const int32_t *dy;      /* y component of vector 0 */
    const uint8_t *status;  /* NULL: every vector valid; else valid where 0 */
    size_t stride;          /* bytes from one vector to the next, > 0 */
    uint16_t cols, rows;    /* grid size, >= 1 each */
    uint8_t frac_bits;      /* 0 (integer px, ssda_track) .. 8 */
} ssda_relax_grid_t;

/* Output flags. */
#define SSDA_RELAX_VALID 0x01u   /* the input vector was valid (else out is 0) */
#define SSDA_RELAX_CHANGED 0x02u /* relabelled (relaxation: most likely class
                                    differs from the input's) or replaced
                                    (median test: an outlier) */

/* One output vector. */
typedef struct {
    int32_t dx_q8, dy_q8; /* the cleaned vector, Q24.8 px */
    uint16_t p_q15;       /* relaxation: likelihood of the most likely class;
                             median test: 0 */
    uint8_t cls;          /* relaxation: the most likely class (sector +
                             8 * length class); median test: 0 */
    uint8_t flags;        /* SSDA_RELAX_VALID | SSDA_RELAX_CHANGED */
} ssda_relax_vector_t;

/* Option flags. */
#define SSDA_RELAX_KEEP 0x01u /* keep vectors whose most likely class is their own */

/* Bytes of work buffer for a grid of cols x rows: per node the 48 Q15
   likelihoods (96 B) and its class (1 B), and two grid rows of likelihoods
   before the update (96 B per node). 16 272 B for a 12 x 12 grid (the
   seed's 137 templates fit one). */
#define SSDA_RELAX_WORK_SIZE(cols, rows)                                      \
    ((size_t)(cols) * (size_t)(rows) * 97u + (size_t)(cols) * 2u * 96u)

typedef struct {
    uint16_t iterations;  /* N (0 = SSDA_RELAX_DEFAULT_ITERATIONS), <= 1000 */
    uint16_t len_step_q8; /* length class width s, Q8.8 px (0 = automatic) */
    uint8_t flags;        /* SSDA_RELAX_KEEP or 0 */
    void *work;           /* caller buffer, 4-byte aligned, */
    size_t work_size;     /*   >= SSDA_RELAX_WORK_SIZE(cols, rows) bytes */
} ssda_relax_config_t;

/*
 * Relaxation labelling of *grid into out[0 .. cols*rows - 1].
 * Returns SSDA_OK, or without writing out:
 *   SSDA_ERR_NULL    grid, cfg, out, grid->dx, grid->dy or cfg->work NULL
 *   SSDA_ERR_SIZE    cols or rows 0
 *   SSDA_ERR_ARG     stride 0, frac_bits > 8, iterations > 1000, unknown
 *                    flags, or a valid component beyond +-SSDA_RELAX_MAX_Q8
 *                    (after the shift to Q8)
 *   SSDA_ERR_BUFFER  out_count below cols*rows; work too small or misaligned
 * Work: per iteration and node 48 x 48 products (the supports), 48 x 8
 * additions and 48 products and one division (the update).
 */
int ssda_relax_labels(const ssda_relax_grid_t *grid, const ssda_relax_config_t *cfg,
                      ssda_relax_vector_t *out, size_t out_count);

/* Normalised median test options; zero-filled means the paper's defaults. */
typedef struct {
    uint16_t threshold_q8; /* r0* above which a vector is an outlier, Q8.8
                              (0 = 2.0) */
    uint16_t eps_q8;       /* eps, Q8.8 px (0 = 0.1 px, 26); use 1 for none */
} ssda_relax_median_config_t;

/*
 * Normalised median test with replacement of *grid into out (cfg NULL: the
 * defaults). No work buffer. Same errors as ssda_relax_labels (without the
 * work and iteration checks).
 */
int ssda_relax_median(const ssda_relax_grid_t *grid, const ssda_relax_median_config_t *cfg,
                      ssda_relax_vector_t *out, size_t out_count);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_RELAX_H */
