/*
 * fourier.h - Granlund Fourier descriptors of closed contours and their
 * matching with optimal scale, rotation and start point (Ishii and Hattori
 * 1985, seed 001, section 3, eqs. 1-12), in fixed point.
 *
 * DESCRIPTORS (eq. 3). A contour of N points u_k = x_k + i y_k equally
 * spaced along it (ssda/loops.h) has the coefficients
 *     a_n = (1/N) sum_k u_k exp(-2 pi i n k / N),  n = +-1 .. +-M
 * (the trapezoid rule of eq. 3 on the linearly interpolated contour; a_0,
 * the centroid, is left out: translation only moves a_0). Coordinates are
 * pixels with x right and y down, so exp(i phi) turns +x towards +y
 * (clockwise on screen).
 *
 * MATCHING (eqs. 7-12). Contour b is taken as contour a scaled by s,
 * turned by phi and started alpha / (2 pi) of the way round a:
 *     b_n ~ s exp(i (n alpha + phi)) a_n,
 * and (s, phi, alpha) minimise the seed's normalised error
 *     E^2 = sum |b_n - s exp(i (n alpha + phi)) a_n|^2 / sum |b_n|^2
 * (eq. 7 with the seed's model alpha as b and its unknown beta as a).
 * With Z(alpha) = sum conj(b_n) a_n exp(i n alpha): for each alpha the best
 * phi = -arg Z(alpha) (eq. 10) and s = |Z(alpha)| / sum |a_n|^2 (eq. 9),
 * and E^2 = 1 - |Z|^2 / (sum |a_n|^2 sum |b_n|^2); alpha is the root of
 * eq. 12 (d|Z|^2 / d alpha = 0) with the largest |Z|: |Z(alpha)|^2 is
 * scanned at 128 points, the three best local maxima are refined by 20
 * bisections of the sign of eq. 12 (to 2^-20 turn), the best is kept
 * (ties: the smaller alpha).
 *
 * FIXED POINT. Contour samples Q8 px; coefficients Q8 px (int32, |a_n| <=
 * max |u_k|); sums of |a_n|^2 Q16 px^2 (uint64). Angles in turns (uint32,
 * 2^32 = 360 degrees); cos/sin from a 129-entry quarter-wave table (Q15,
 * +-2 LSB), arg by CORDIC (error < 2^-22 turn). Products c_n = conj(b_n) a_n
 * are scaled to 27 bits before the sums (relative error < 2^-26), so s, phi
 * and alpha are limited by the table, not by the word sizes: on the test
 * shapes s agrees with a 64-bit reference within 2^-12 and phi
 * within 0.01 degree (tests/test_fourier.c). s is Q16, E^2 Q16.
 */
#ifndef SSDA_FOURIER_H
#define SSDA_FOURIER_H

#include "ssda/loops.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SSDA_FD_MAX_ORDER 16u
#define SSDA_FD_DEFAULT_ORDER 10u /* the seed's M */

/* A complex coefficient, Q8 px. */
typedef struct {
    int32_t re_q8;
    int32_t im_q8;
} ssda_fd_coef_t;

/* Descriptors of one contour, orders 1..order. */
typedef struct {
    ssda_fd_coef_t pos[SSDA_FD_MAX_ORDER]; /* pos[n - 1] = a_n */
    ssda_fd_coef_t neg[SSDA_FD_MAX_ORDER]; /* neg[n - 1] = a_-n */
    uint64_t energy_q16;                   /* sum |a_n|^2 over n = +-1..+-order, Q16 px^2 */
    uint32_t order;                        /* M, 1..SSDA_FD_MAX_ORDER */
} ssda_fd_t;

/* Result of a match: b ~ s exp(i (n alpha + phi)) a. */
typedef struct {
    uint32_t s_q16;   /* scale, Q16 (65536 = 1): b is s times a */
    uint32_t phi;     /* rotation from a to b, turns (2^32 per turn), from +x
                         towards +y */
    uint32_t alpha;   /* start shift, turns: b's first sample is a's point
                         alpha / 2^32 of the way round */
    uint32_t e2_q16;  /* E^2, Q16: 0 identical, 65536 nothing in common;
                         may exceed 65536 with s and phi fixed */
} ssda_fd_match_t;

/*
 * Descriptors a_1..a_order and a_-1..a_-order of a contour.
 *   points: n contour samples (Q8 px), equally spaced along the contour;
 *           |x|, |y| < 2^24 (65536 px).
 *   n:      a power of two, 8..SSDA_LOOPS_MAX_SAMPLES.
 *   order:  1..SSDA_FD_MAX_ORDER and below n / 2 (0 = SSDA_FD_DEFAULT_ORDER).
 * Accumulators: sum_k u_k cos < 2^24 * 2^15 * 2^10 = 2^49 (int64).
 * Returns SSDA_OK, or without writing *fd: SSDA_ERR_NULL, SSDA_ERR_ARG (n,
 * order or a coordinate out of range).
 */
int ssda_fd_compute(const ssda_point_q8_t *points, uint32_t n, uint32_t order, ssda_fd_t *fd);

/*
 * Best s, phi and alpha taking a to b, and their E^2 (see the top).
 * Both must have the same order. A contour of zero energy (all samples
 * equal) matches nothing: SSDA_ERR_ARG.
 * Returns SSDA_OK, or without writing *m: SSDA_ERR_NULL, SSDA_ERR_ARG
 * (orders differ or out of range, an energy of 0).
 */
int ssda_fd_match(const ssda_fd_t *a, const ssda_fd_t *b, ssda_fd_match_t *m);

/*
 * Best alpha for a given scale and rotation (the seed's matching with
 * "scale and rotation fixed", section 4 [2.2], [2.5]): alpha maximises
 * Re(exp(i phi) Z(alpha)); m->s_q16 and m->phi are the given ones and
 * m->e2_q16 = (sum |b_n - s exp(i (n alpha + phi)) a_n|^2) / sum |b_n|^2,
 * saturated at UINT32_MAX.
 *   s_q16: 1..2^24 (1/65536 .. 256).
 * Errors as ssda_fd_match, plus SSDA_ERR_ARG for s_q16 out of range.
 */
int ssda_fd_match_fixed(const ssda_fd_t *a, const ssda_fd_t *b, uint32_t s_q16, uint32_t phi,
                        ssda_fd_match_t *m);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_FOURIER_H */
