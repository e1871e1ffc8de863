/*
 * poly.h - polynomial maps between two images, fitted by least squares to
 * control-point pairs, in fixed point.
 *
 * Seed: Nagao et al. 1975, section 3.3: a 2nd or 3rd order polynomial
 * x = f(X, Y), y = g(X, Y) maps the reference ("new") grid (X, Y) onto the
 * moving ("old") image (x, y); its coefficients come from the control-point
 * pairs by least squares (7th and 9th orders oscillate; orders 1..3 here).
 *
 * COORDINATES. Pixel (X, Y) is the centre of column X, row Y (0-based).
 * A map is defined on the reference grid of ref_w x ref_h pixels, through
 * centred, scaled coordinates with power-of-two scales:
 *     xn = (X - cx) / 2^kx,  yn = (Y - cy) / 2^ky,
 *     cx = floor(ref_w / 2), kx = the smallest k >= 0 with 2^k >= the
 *     largest |X - cx| on the grid (likewise cy, ky),
 * so |xn|, |yn| <= 1 over the grid and xn, yn are exact binary fractions.
 *
 * TERMS, in this order (SSDA_POLY_TERMS(order) of them):
 *     1, xn, yn, xn^2, xn*yn, yn^2, xn^3, xn^2*yn, xn*yn^2, yn^3
 *     x = sum u_q24[t] / 2^24 * term_t,  y = sum v_q24[t] / 2^24 * term_t
 * Coefficients are pixels of the moving image per unit of the normalised
 * term, Q40.24 (any int64_t value is accepted).
 *
 * EVALUATION is exact: ssda_poly_eval returns floor(256 * x) of that real
 * polynomial at integer (X, Y), with no rounding inside (an integer
 * polynomial in 128-bit arithmetic: 256 * x = P(X, Y) / 2^64 with
 * P = sum u_q24[t] * (X-cx)^i (Y-cy)^j * 2^(48 - i kx - j ky), integer
 * since i kx + j ky <= 3 * 16). The warp (warp.h) steps the same P by
 * forward differences and returns the same values bit for bit.
 */
#ifndef SSDA_POLY_H
#define SSDA_POLY_H

#include "ssda/ssda.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Highest order, and the terms of an order: 3, 6 or 10 for 1, 2, 3. */
#define SSDA_POLY_MAX_ORDER 3u
#define SSDA_POLY_MAX_TERMS 10u
#define SSDA_POLY_TERMS(order) ((((uint32_t)(order) + 1u) * ((uint32_t)(order) + 2u)) / 2u)

/* A map from reference pixels to moving-image pixels (see the top of this
   file). Fill with ssda_poly_init or ssda_poly_fit; the coefficients may
   then be changed freely. Terms beyond SSDA_POLY_TERMS(order) are 0. */
typedef struct {
    int64_t u_q24[SSDA_POLY_MAX_TERMS]; /* moving x, px, Q40.24 */
    int64_t v_q24[SSDA_POLY_MAX_TERMS]; /* moving y, px, Q40.24 */
    int32_t cx, cy;                     /* centre, reference px */
    uint8_t kx, ky;                     /* scales 2^kx, 2^ky px, 0..16 */
    uint8_t order;                      /* 1..3 */
    uint16_t ref_w, ref_h;              /* the reference grid, px */
} ssda_poly_t;

/*
 * The identity map of order `order` on a ref_w x ref_h reference grid
 * (x = X, y = Y): u_q24[0] = cx * 2^24, u_q24[1] = 2^(kx + 24), v alike.
 * Returns SSDA_OK, SSDA_ERR_NULL, SSDA_ERR_SIZE (zero size) or
 * SSDA_ERR_ARG (order not 1..3); *poly written on success only.
 */
int ssda_poly_init(ssda_poly_t *poly, uint16_t ref_w, uint16_t ref_h, uint8_t order);

/*
 * Evaluate the map at reference pixel (x, y), which may lie up to one
 * grid's width or height outside the grid (|X - cx| <= 2^(kx+1), likewise
 * y): *u_q8, *v_q8 = floor(256 * moving x), floor(256 * moving y), exact
 * (see the top of this file).
 * Returns SSDA_OK, or without writing: SSDA_ERR_NULL, SSDA_ERR_ARG (order
 * or scales out of range), SSDA_ERR_SIZE ((x, y) outside that domain),
 * SSDA_ERR_OVERFLOW (a result outside int32_t: a map 8 million px away).
 */
int ssda_poly_eval(const ssda_poly_t *poly, int32_t x, int32_t y, int32_t *u_q8,
                   int32_t *v_q8);

/* A control-point pair: the same feature in the reference and the moving
   image, px in Q23.8 (sub-pixel). */
typedef struct {
    int32_t ref_x_q8, ref_y_q8;
    int32_t mov_x_q8, mov_y_q8;
} ssda_poly_pair_t;

/* Fit options. A zero-filled struct means order 2, rejection bound 2 px. */
typedef struct {
    uint8_t order;           /* 1..3; 0 = 2 (the seed's choice) */
    uint32_t max_residual_q8; /* rejection bound, px Q24.8; 0 = 512 (2 px);
                                UINT32_MAX = no rejection */
} ssda_poly_fit_config_t;

/* Default rejection bound: 2 px, on the leave-one-out statistic s of a
   pair (poly.h, REJECTION: its residual / sqrt(1 - leverage), whose spread
   under noise is the noise's, at any leverage). The seed's Fig. 9 pairs fit
   within 0.6 px at order 1 or 2 once its one misread pair (20 px off) is
   dropped; correlation peaks on textured windows land within a few tenths
   of a pixel; a peak misplaced by a repeated pattern is off by a window or
   more. */
#define SSDA_POLY_DEFAULT_MAX_RESIDUAL_Q8 512u

/* Outcome of a fit. */
typedef struct {
    uint32_t rms_q8;      /* RMS residual over the pairs used, px Q24.8 */
    uint32_t max_q8;      /* largest residual of a pair used */
    uint32_t cond;        /* conditioning estimate of the normal matrix of
                             the pairs used: (largest / smallest Cholesky
                             pivot)^2, a lower bound of its condition number
                             (saturates at UINT32_MAX) */
    uint16_t used;        /* pairs in the final fit */
    uint16_t rejected;    /* pairs dropped as outliers */
    uint16_t max_leverage_q15; /* largest leverage h of a used pair, Q1.15
                             (32768 = 1): the share of that pair's own
                             error that the map follows at its position */
    uint8_t refinements;  /* iterative-refinement steps taken (1..4) */
    bool within_bound;    /* every used pair's leave-one-out statistic (see
                             REJECTION) <= the bound, hence every residual
                             too (false: rejection stopped at the minimum
                             of pairs) */
    bool weak;            /* the map is weakly determined: fewer than
                             SSDA_POLY_WEAK_PAIRS(terms) pairs used, or a
                             leverage above SSDA_POLY_WEAK_LEVERAGE_Q15; an
                             outlier there can pass the rejection: warn */
} ssda_poly_fit_result_t;

/* A fit is weakly determined (result.weak) below 2 pairs per term (the mean
   leverage terms / used is then above 1/2) ... */
#define SSDA_POLY_WEAK_PAIRS(terms) (2u * (uint32_t)(terms))
/* ... or when a pair's leverage exceeds 0.8: the map then follows more
   than 80 % of that pair's own error, and an outlier there shows only
   sqrt(1 - h) < 45 % of its offset to the rejection (it must be off by
   more than 2.2 times the bound to be dropped). */
#define SSDA_POLY_WEAK_LEVERAGE_Q15 26214u

/* Work bytes ssda_poly_fit needs for n pairs (one flag per pair). */
#define SSDA_POLY_FIT_WORK_SIZE(n) ((size_t)(n))

/*
 * Least-squares fit of the map from the reference to the moving image,
 * with outlier rejection.
 *
 * METHOD. The displacement (moving - reference position) is fitted, in the
 * normalised terms of the pair's reference position (Q2.30, exact xn, yn;
 * products rounded to Q30). The normal equations G c = r are accumulated
 * exactly in 128-bit integers, divided by the number of pairs (G / n:
 * entries <= 1, Q60), and solved by a fixed-point Cholesky factorisation
 * (pivots in Q2.30), then improved by iterative refinement: the residual
 * r - G c is computed exactly from the exact G and r, and its correction
 * solved with the same factor, until the correction is 0 in Q24 or after
 * 4 steps. Cholesky rather than QR: the normal matrix of at most 10 terms
 * is small and, on centred scaled coordinates, well conditioned (the
 * seed's 4 x 4 cell centres, 1000 x 800 to 20 000 x 2 000 grids: cond 5-9
 * at order 1, 50-130 at order 2, 800-3200 at order 3), and
 * exact integer sums plus refinement recover what squaring the condition
 * number costs: the coefficients equal the exact least-squares solution to
 * within a few units of Q24 while cond * 2^-28 << 1 (tests: against a
 * QR fit in 64-bit reference arithmetic, order 3, cond up to 10^4).
 *
 * REJECTION, by the leave-one-out statistic. After each fit every used
 * pair i gets its residual r_i (the distance between its mapped reference
 * position and its moving position) and its leverage h_i = phi_i^T G^-1
 * phi_i (phi_i its terms, G the normal matrix of the used pairs; 0 < h_i
 * <= 1, sum h_i = terms). Least squares gives exactly:
 *     RSS - RSS without i = r_i^2 / (1 - h_i),
 * the fall of the sum of squared residuals when pair i is left out, and
 * r_i / (1 - h_i) is the pair's distance to the map fitted without it.
 * The pair with the largest s_i = r_i / sqrt(1 - h_i) (ties: the lowest
 * index) is dropped and the map refitted, while that s_i exceeds
 * cfg->max_residual_q8 and more than SSDA_POLY_TERMS(order) + 1 pairs are
 * used. Why s_i: (a) it is the likelihood-ratio choice of the one pair
 * that is off the map (the mean-shift outlier model: the pair whose
 * removal explains the most of the squared residuals); the largest raw
 * residual is not: a pair of high leverage pulls the map to itself and
 * keeps a small residual (r_i = (1 - h_i) times its distance to the map
 * of the others), while good pairs near it take the error. (b) Under
 * noise of sigma px on good pairs every s_i has the same spread sigma
 * whatever its leverage (r_i has sigma sqrt(1 - h_i), the deleted
 * residual r_i / (1 - h_i) has sigma / sqrt(1 - h_i), which would drop
 * good pairs of high leverage), so the bound means the same everywhere.
 * A pair off the map by e px has s_i = e sqrt(1 - h_i) when it is the
 * only outlier: it is dropped when e > bound / sqrt(1 - h_i) (see weak).
 * In fixed point: h_i = |L^-1 phi_i|^2 / used from the Cholesky factor L
 * (Q30) of G / used by forward substitution (Q30, 128-bit sums), to within
 * about cond * 2^-30; a pair with 1 - h_i < 2^-16 cannot be judged (the
 * map passes through it) and is kept. s_i^2 = r_i^2 2^60 / (2^60 - h_i)
 * in 128 bits (r_i^2 < 2^64 in Q16, so s_i^2 < 2^80); the bound's square
 * is below 2^64. UINT32_MAX as the bound: no rejection.
 * Cost per round: one fit, then per used pair O(terms^2) 64 x 64-bit
 * multiplications and terms + 2 128-bit divisions; at most
 * n - terms - 1 rounds. Measured on the Cortex-M4 (-O2, 16 pairs, order
 * 2, no pair dropped): 1.76 M instructions (0.97 M with the raw-residual
 * rule), stack 3.7 KB (3.4 KB); docs/registration.md.
 *
 *   pairs, n:  the pairs; n <= 16384 (the exact sums' bound). Reference
 *              positions must lie within the grid's domain (|X - cx| <=
 *              2^kx, likewise y).
 *   ref_w, ref_h: the reference grid (sets cx, cy, kx, ky).
 *   cfg:       options (NULL = defaults).
 *   poly:      the map (on success).
 *   residual_q8: NULL or n entries: each pair's residual under the final
 *              map, used or not, px Q24.8 (saturated at UINT32_MAX).
 *   used:      NULL or n flags: 1 for the pairs of the final fit.
 *   result:    NULL or the fit's summary.
 *   work, work_size: SSDA_POLY_FIT_WORK_SIZE(n) bytes.
 * Returns SSDA_OK, or with no output written:
 *   SSDA_ERR_NULL    pairs, poly or work NULL
 *   SSDA_ERR_ARG     order not 0..3; a reference position outside the domain
 *   SSDA_ERR_SIZE    zero grid size; fewer pairs than terms or more than
 *                    16384, or pairs that do
 *                    not determine the map (on a line, or too few distinct
 *                    positions: a Cholesky pivot below 2^-12 of its
 *                    diagonal, i.e. cond beyond about 10^7)
 *   SSDA_ERR_BUFFER  work_size below SSDA_POLY_FIT_WORK_SIZE(n)
 *   SSDA_ERR_OVERFLOW a coefficient beyond 2^39 px (not a real map)
 * Cost: per fit O(n * terms^2) multiplications and O(terms^3) 128-bit
 * divisions; at most n - terms - 1 refits.
 */
int ssda_poly_fit(const ssda_poly_pair_t *pairs, size_t n, uint16_t ref_w, uint16_t ref_h,
                  const ssda_poly_fit_config_t *cfg, ssda_poly_t *poly,
                  uint32_t *residual_q8, uint8_t *used, ssda_poly_fit_result_t *result,
                  void *work, size_t work_size);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_POLY_H */
