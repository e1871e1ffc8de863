/*
 * ncc.h - exact correlation-coefficient search: find where window W (L x M)
 * best fits in a search area S (L' x M' >= L x M) by the zero-mean
 * normalised cross-correlation
 *
 *     rho(x, y) = sum (S - mean S)(W - mean W)
 *                 / sqrt(sum (S - mean S)^2 * sum (W - mean W)^2),
 *
 * sums over the L x M pixels of the window placed with its top-left at
 * (x, y), the same coefficient as OpenCV's TM_CCOEFF_NORMED. It does not
 * change when the brightness of S or W is scaled by a positive gain or
 * shifted by an offset, which the SAD of match.h does.
 *
 * Seeds: 003 (Kanehira et al., relaxation template matching: "normalised
 * correlation" scores the templates) and 002 (Nagao et al.: feature points
 * by the correlation coefficient, |rho| > 0.65 accepted; a negative rho
 * still matches inverted contrast).
 *
 * EXACT, IN INTEGERS. With n = L*M, Sw = sum W, Sa = sum S (under the
 * placement), Saw = sum S*W, and so on:
 *     num   = n*Saw - Sa*Sw           (signed; n^2 times the covariance)
 *     var_a = n*Saa - Sa^2 >= 0,  var_w = n*Sww - Sw^2 >= 0,
 *     rho   = num / sqrt(var_a * var_w).
 * Two positions are compared without a square root or a division: rho1 >
 * rho2 from the signs of num1, num2 and num1^2 * var_a2 against
 * num2^2 * var_a1 (var_w is common), products of up to 186 bits formed and
 * compared exactly (lib/wide.c). No floating point anywhere; results are
 * bit-identical on every target and kernel.
 *
 * FLAT WINDOWS AND AREAS. A placement whose pixels are all equal (var_a = 0)
 * has rho = 0 by definition (its num is 0 too). A flat window (var_w = 0)
 * gives rho = 0 at every position: the search returns the first position
 * of the scan by the tie rule, rho_q30 = 0, and sets SSDA_NCC_FLAT_WINDOW.
 * Nothing is ever divided by zero.
 *
 * TIE RULE: the best position has the largest rho (SSDA_NCC_ABS: the
 * largest |rho|, so +0.5 and -0.5 tie); among equal values the smallest y,
 * then the smallest x. Equal means exactly equal as rationals. Every scan,
 * early-exit setting and kernel returns the same (x, y).
 *
 * EARLY EXIT (exact: never changes the answer; off with SSDA_NCC_FULL).
 * The window's rows are taken in groups of G = SSDA_NCC_GROUP_ROWS(L) rows
 * (about 64 pixels; the last group may be shorter). After each group but
 * the last, the dot product of the rows summed so far, P, plus a
 * Cauchy-Schwarz bound on the rows not yet summed (R) bounds num:
 *     sum_R S*W = c*Sw_R + d*Sa_R - c*d*n_R + sum_R (S - c)(W - d),
 *     |sum_R (S - c)(W - d)| <= sqrt(sum_R (S - c)^2 * sum_R (W - d)^2)
 *                             <= (k * E_s + E_w / k) / 2   for any k > 0,
 * with c and d the integer means of the placement and of the window, E_s
 * and E_w the two sums of squares over R, and k a power of two near
 * sqrt(E_w / E_s) (the arithmetic-geometric mean inequality bounds the
 * square root without taking it; at most 25 % above it, a few % in
 * practice). Sa_R and sum_R S^2 come from sliding sums of the area built
 * row by row (per group of rows and position) in the work buffer. A
 * position is abandoned as soon as the bound shows that even the largest
 * num still possible gives a smaller rho (|rho|) than the best so far,
 * compared in integers as above against floor(num_b^2 / var_a_b), a lower
 * bound of the best's rho^2 * var_w; a position that could tie is never
 * abandoned. Positions whose placement is flat are decided without reading
 * a pixel (rho = 0).
 *
 * SIZES. Windows of at most SSDA_NCC_MAX_PIXELS pixels (any shape, each
 * side <= 65535), areas of any size up to 65535 x 65535, 8- or 16-bit
 * samples. Worst cases (m = 65535, n = 65536), each written beside its
 * accumulator and tested: Sa, Sw <= n*m < 2^32; Saa, Sww, Saw <= n*m^2 <
 * 2^48; n*Saw, Sa*Sw < 2^64; |num|, var_a, var_w <= n^2*m^2/4 < 2^62;
 * num^2 * var_a < 2^186.
 *
 * Positions: (x, y) is the top-left of the window placement in the area,
 * 0-based, x right, y down; 0 <= x <= L'-L, 0 <= y <= M'-M.
 */
#ifndef SSDA_NCC_H
#define SSDA_NCC_H

#include "ssda/view.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest window, in pixels (L * M), of every function in this header. */
#define SSDA_NCC_MAX_PIXELS 65536u

/* rho in Q2.30 (int32_t): 1.0 = 2^30. */
#define SSDA_NCC_ONE_Q30 1073741824
/* around_q30 entries with no position (outside the area's positions). */
#define SSDA_NCC_NONE INT32_MIN

/* What is maximised. */
typedef enum {
    SSDA_NCC_RHO = 0, /* rho: the best positive correlation */
    SSDA_NCC_ABS = 1  /* |rho|: inverted contrast matches too (seed 002) */
} ssda_ncc_metric_t;

/* Flags. */
#define SSDA_NCC_FULL 0x01u    /* no early exit: every position summed in full
                                  (the reference; same answer, more work) */
#define SSDA_NCC_PREDICT 0x02u /* evaluate (predict_x, predict_y) first: a good
                                  prediction sets a high bar at once */
#define SSDA_NCC_DISK 0x04u    /* only positions within `radius` px (Euclidean,
                                  (x-px)^2 + (y-py)^2 <= radius^2) of the
                                  predicted position; implies SSDA_NCC_PREDICT */
#define SSDA_NCC_AROUND 0x08u  /* also report rho at the 8 neighbours of the
                                  best position (for a sub-pixel peak fit) */

/* Rows per early-exit group for windows L px wide: ceil(64 / L), >= 1. */
#define SSDA_NCC_GROUP_ROWS(win_w) ((63u + (size_t)(win_w)) / (size_t)(win_w))
/* Groups of a window of win_w x win_h: ceil(win_h / group rows). */
#define SSDA_NCC_GROUPS(win_w, win_h)                                         \
    (((size_t)(win_h) + SSDA_NCC_GROUP_ROWS(win_w) - 1u) / SSDA_NCC_GROUP_ROWS(win_w))

/* Bytes of work buffer ssda_ncc_match needs for an area area_w px wide
   and a window of win_w x win_h (win_w <= area_w; the area's height does
   not matter): per position of a row of positions, the L-wide sums (4 B)
   and sums of squares (8 B) of win_h + 1 area rows and of the window, and
   per group two window sums (16 B). 3 736 B for 16 x 16 in 32 x 32,
   5 624 B for 20 x 20 in 40 x 40. Where size_t is 32 bits the macro wraps
   only for jobs needing 4 GB or more; the library checks the size in
   64 bits and refuses such a job with SSDA_ERR_BUFFER. */
#define SSDA_NCC_WORK_SIZE(area_w, win_w, win_h)                              \
    (((size_t)(win_h) + 2u) * (((size_t)(area_w) - (size_t)(win_w) + 1u) * 12u) + \
     SSDA_NCC_GROUPS(win_w, win_h) * 16u)

/*
 * Search options. A zero-filled struct with work/work_size set is valid:
 * rho, raster scan, early exit.
 */
typedef struct {
    uint8_t metric;     /* ssda_ncc_metric_t */
    uint8_t flags;      /* SSDA_NCC_FULL | _PREDICT | _DISK | _AROUND */
    uint16_t radius;    /* SSDA_NCC_DISK: px, 0..65535 (0: the predicted
                           position only) */
    int32_t predict_x;  /* SSDA_NCC_PREDICT / _DISK: position in area */
    int32_t predict_y;  /*   coordinates, any value, clamped into range */
    void *work;         /* caller buffer, 8-byte aligned, */
    size_t work_size;   /*   >= SSDA_NCC_WORK_SIZE(...) bytes */
} ssda_ncc_config_t;

/* Result flags. */
#define SSDA_NCC_FLAT_WINDOW 0x01u /* the window's pixels are all equal */

/* Outcome of one search. */
typedef struct {
    uint64_t pixel_ops;    /* products summed, plus sliding-sum and bound work
                              (one per pixel added to or removed from a sliding
                              sum, sums and sums of squares counted apart; one
                              per early-exit test); AROUND's work included */
    uint32_t positions;    /* positions considered (raster: all; disk: those
                              inside) */
    uint32_t completed;    /* positions whose products were summed in full */
    int32_t rho_q30;       /* rho at (x, y), Q2.30, truncated toward zero;
                              signed also with SSDA_NCC_ABS */
    int32_t around_q30[9]; /* SSDA_NCC_AROUND: rho at (x + i - 1, y + j - 1),
                              index j * 3 + i (around_q30[4] = rho_q30);
                              SSDA_NCC_NONE where outside the positions of the
                              area (not limited to the disk). Else not written */
    uint16_t x;            /* best top-left column in the area */
    uint16_t y;            /* best top-left row in the area */
    uint8_t flags;         /* SSDA_NCC_FLAT_WINDOW or 0 */
} ssda_ncc_result_t;

/*
 * Search *window over *area for the largest rho (or |rho|).
 *   area, window: valid views of the same pixel format; window no larger
 *                 than area in either dimension, at most SSDA_NCC_MAX_PIXELS
 *                 pixels. Not modified.
 *   cfg:          options and the work buffer (not NULL).
 *   result:       written on success only.
 * Returns SSDA_OK, or without writing *result:
 *   SSDA_ERR_NULL     area, window, cfg, result or cfg->work NULL
 *   SSDA_ERR_SIZE/_STRIDE/_FORMAT  invalid views (see ssda_view_check);
 *                     SSDA_ERR_SIZE also when the window is larger than the
 *                     area or has more than SSDA_NCC_MAX_PIXELS pixels
 *   SSDA_ERR_FORMAT   area and window formats differ
 *   SSDA_ERR_ARG      unknown metric or flags
 *   SSDA_ERR_BUFFER   work_size below SSDA_NCC_WORK_SIZE, or work not 8-byte
 *                     aligned
 *   SSDA_ERR_UNSUPPORTED  16-bit views in a build with SSDA_CFG_NO_U16
 * Work: every position in range (or in the disk) once; see EARLY EXIT.
 */
int ssda_ncc_match(const ssda_view_t *area, const ssda_view_t *window,
                   const ssda_ncc_config_t *cfg, ssda_ncc_result_t *result);

/*
 * rho of the window placed at (x, y) of the area, Q2.30 truncated toward
 * zero (0 where the placement or the window is flat): the reference for
 * tests and tools, and a probe for sub-pixel fits. No work buffer.
 * Same validation as ssda_ncc_match (without cfg); also SSDA_ERR_SIZE if
 * the placement does not fit. *rho_q30 written on success only.
 */
int ssda_ncc_at(const ssda_view_t *area, const ssda_view_t *window,
                uint16_t x, uint16_t y, int32_t *rho_q30);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_NCC_H */
