/*
 * kl.h - the Karhunen-Loeve transform of a 3-band (colour) image, in
 * integers: band statistics accumulated exactly over a streamed image, the
 * eigenvectors of their correlation (or covariance) matrix by a fixed-point
 * Jacobi method, and the per-pixel transform into three decorrelated
 * feature images Z1, Z2, Z3.
 *
 * Seed: Fujimoto and Tanaka, colour aerial photograph segmentation by the
 * K-L transform and Gaussian-mixture histogram models (../shared/seeds/004,
 * section 2.2, eqs. 2.2-2.4): the band means are removed, the 3 x 3 matrix
 * of correlation coefficients between the bands is formed, and its
 * eigenvectors, ordered by eigenvalue, are the rows of the transform
 * Z = V (Y - mean). Z1 is about the mean brightness (eq. 2.4), Z2 and Z3
 * colour differences. The features are NOT divided by the bands' standard
 * deviations, in either mode (as the seed: eq. 2.3 applies the correlation
 * eigenvectors to the mean-removed values).
 *
 * FLOW: ssda_kl_acc_init; rows with ssda_kl_acc_add_row (pushed) or
 * ssda_kl_acc_add_source (read through a stream source, stream.h);
 * ssda_kl_solve (matrix, eigenvectors, eigenvalues, the per-pixel plan);
 * ssda_kl_transform_row per row, as often as wanted (a second pass over the
 * image). Design and figures: docs/segmentation.md.
 *
 * EXACT SUMS (ssda_kl_acc_t; worst cases, tested at them): n pixels
 * < 2^32 (the accumulator refuses rows beyond), sum of a band < n 65535
 * < 2^48, sum of a product of two bands < n 65535^2 < 2^64. The centred
 * matrix C_kl = n sum(x_k x_l) - sum(x_k) sum(x_l) = n^2 cov(k, l) is formed
 * exactly in 128 bits.
 *
 * MATRIX (ssda_kl_t.matrix_q30): correlation: r_kl = C_kl / sqrt(C_kk C_ll)
 * in Q30 (diagonal exactly 1.0; a constant band has r = 0 to the others);
 * covariance: C scaled by a power of two so that its largest diagonal entry
 * lies in [0.5, 1.0) (eigenvectors do not depend on the scale).
 * Rounding: for each pair the two variances are scaled by powers of two to
 * 61-62 bits (relative error < 2^-59, however unequal they are) and C_kl
 * by the root of those powers, so each r_kl is within 1 Q30 step of the
 * exact ratio (tests/test_kl.c, a band of variance 2^-12 beside one of
 * 2^30: measured 0.47 steps).
 *
 * EIGENVECTORS (ssda_kl_t.vec_q30): cyclic Jacobi rotations on the Q30
 * matrix (entries held in 64 bits), rotation tangent and cosine in Q30 from
 * an integer square root, until every off-diagonal entry is 0 or 12 sweeps
 * have run; then each vector is renormalised to unit length. Rows are
 * sorted by decreasing eigenvalue (ties: the lower original index first) and
 * each row's largest-magnitude component is made positive (ties: the first),
 * which is the sign convention of the seed's eq. 2.3. The seed prints each
 * row scaled to unit L1 norm (sum of |v| = 1); vec_q30 rows have unit L2
 * norm. Precision (tests/test_kl.c, against a 64-bit reference closed-form
 * eigen-solver on 20 000 random matrices of rank 1 to 3 and on degenerate
 * ones, the matrix taken as exact): eigenvalues within 2^-26 of the
 * largest; eigenvector components within 2^-26 lambda_1 / gap, gap the
 * distance to the nearest other eigenvalue (measured worst: 2^-27.9; a
 * vector of a repeated eigenvalue is any unit vector of its plane). The
 * seed's eq. 2.2 gives eq. 2.3's first row to its printed 4 decimals and
 * the other two within 2.5e-4: that matrix is itself printed to 4
 * decimals, which moves the two small eigenvectors (gap 0.066) that much.
 *
 * FEATURE IMAGES (ssda_kl_transform_row): each feature k is written as
 *     z_k = clamp(floor(mid + g_k * sum_j v_kj (x_j - m_j) + 1/2), 0, out_max),
 *     mid = out_max / 2,
 * v the unit eigenvectors, m the exact band means, and the gain g_k chosen
 * at solve time by the range mode:
 *     SSDA_KL_RANGE_SIGMA (default): g_k = (out_max / 2) / (nsigma sd_k),
 *         sd_k the standard deviation of Z_k over the accumulated pixels:
 *         mean +- nsigma sd maps onto [0, out_max]; values beyond clamp
 *         (the histogram models live in the middle anyway);
 *     SSDA_KL_RANGE_FULL: g_k = (out_max / 2) / (M sum_j |v_kj|), M the
 *         largest sample (255 or 65535): no pixel can clamp.
 * g_k is capped so that g_k max_j |v_kj| <= gain_max: a step of one sample
 * in any one band moves z_k by at most gain_max steps (default and largest
 * 4096: a nearly constant feature). With 8-bit input a cap of 1 keeps
 * feature histograms without combs: the features of integer samples take
 * values on a lattice, and bins finer than one band's step leave regular
 * gaps that a mixture fit reads as spikes (ssda segment's default). The weights are integers (|w| <= 2^20 for 8-bit input, int32
 * arithmetic, 9 multiply-adds per pixel; 16-bit input uses int64
 * multiply-adds), and every z_k is within 1 of the formula above
 * (tests/test_kl.c, against the formula in 64-bit reference arithmetic).
 * Masked pixels (nodata, below) are written as SSDA_KL_NODATA.
 *
 * NODATA: with SSDA_KL_MASK_NODATA a pixel whose three samples all equal
 * cfg.nodata is left out of the statistics and written as SSDA_KL_NODATA
 * (the Landsat scenes' zero fill, say).
 *
 * The library never allocates; structs are the caller's. Not thread-safe per
 * object; different objects may be used at once.
 */
#ifndef SSDA_KL_H
#define SSDA_KL_H

#include "ssda/stream.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Value written for masked pixels in feature images. out_max is below it. */
#define SSDA_KL_NODATA 0xFFFFu

/* Matrix diagonalised. */
typedef enum {
    SSDA_KL_CORRELATION = 0, /* correlation coefficients (the seed's eq. 2.2) */
    SSDA_KL_COVARIANCE = 1   /* covariance (principal components) */
} ssda_kl_matrix_t;

/* How features are scaled into 0..out_max (see the top of this file). */
typedef enum {
    SSDA_KL_RANGE_SIGMA = 0, /* mean +- nsigma standard deviations */
    SSDA_KL_RANGE_FULL = 1   /* every possible pixel value, no clamping */
} ssda_kl_range_t;

/* Flags. */
#define SSDA_KL_MASK_NODATA 0x01u /* skip pixels whose three samples all equal nodata */

/* Accumulator configuration. Zero means the documented default. */
typedef struct {
    uint8_t format;   /* sample format: SSDA_PIX_U8 or SSDA_PIX_U16 (0 = U8) */
    uint8_t flags;    /* SSDA_KL_MASK_NODATA */
    uint16_t nodata;  /* the masked sample value (with SSDA_KL_MASK_NODATA) */
} ssda_kl_acc_config_t;

/* Exact band statistics. Fields may be read; fill only through the
   functions below. */
typedef struct {
    uint64_t sum[3];       /* sum of band k over counted pixels, < 2^48 */
    uint64_t sum_xy[6];    /* sum of products: 00, 01, 02, 11, 12, 22; < 2^64 */
    uint32_t count;        /* pixels counted, < 2^32 */
    uint32_t masked;       /* nodata pixels skipped (saturates at 2^32 - 1) */
    uint8_t format;        /* resolved config */
    uint8_t flags;
    uint16_t nodata;
    uint32_t magic;        /* private: set by ssda_kl_acc_init */
} ssda_kl_acc_t;

/* One row of a 3-band image: the samples of band k of pixel i are at
   band[k][i * step] (uint8_t or uint16_t elements as the format says).
   Interleaved RGB: band = {row, row + 1, row + 2}, step 3 (RGBA: step 4);
   planar: three row pointers, step 1. */
typedef struct {
    const void *band[3];
    uint32_t step;  /* samples from one pixel to the next, >= 1 */
} ssda_kl_row_t;

/*
 * Start an accumulator. cfg NULL = defaults (8-bit, no mask).
 * Returns SSDA_OK, SSDA_ERR_NULL (acc NULL), SSDA_ERR_FORMAT (format not
 * U8/U16), SSDA_ERR_ARG (unknown flags, or a nodata above the format's
 * maximum); *acc untouched on error.
 */
int ssda_kl_acc_init(ssda_kl_acc_t *acc, const ssda_kl_acc_config_t *cfg);

/*
 * Add width pixels of one row. Cost: 9 multiply-adds per pixel (32-bit for
 * 8-bit samples, summed per row and then added to the 64-bit sums).
 * Returns SSDA_OK, or with *acc untouched: SSDA_ERR_NULL (acc, row or a band
 * pointer NULL), SSDA_ERR_STATE (acc not initialised), SSDA_ERR_SIZE (width
 * 0 or above 65535), SSDA_ERR_ARG (step 0), SSDA_ERR_OVERFLOW (the count
 * would reach 2^32 pixels).
 */
int ssda_kl_acc_add_row(ssda_kl_acc_t *acc, const ssda_kl_row_t *row, uint32_t width);

/*
 * Add the pixels of a rectangle (NULL = whole) of an interleaved image held
 * by a stream source (stream.h): the source's samples are the image's
 * channels, so a W x H RGB image is a source of width 3 W (channels 3) or
 * 4 W (channels 4, the fourth ignored), in acc's format. Rows are fetched
 * with ssda_source_row, top to bottom (arena: a plate one rectangle row
 * wide, SSDA_SOURCE_SIZE(.., channels * rect width, 1, ..), reads each row
 * once). rect is in pixels, not samples.
 * Returns SSDA_OK or: SSDA_ERR_NULL, SSDA_ERR_STATE (acc or source not
 * initialised), SSDA_ERR_FORMAT (source format differs from acc's),
 * SSDA_ERR_ARG (channels not 3 or 4), SSDA_ERR_SIZE (source width not a
 * multiple of channels, rect empty or outside), SSDA_ERR_OVERFLOW (as
 * add_row; checked before any read), SSDA_ERR_BUFFER (arena too small for a
 * row), or a read() error unchanged. On any error *acc is untouched (rows
 * read before a failed read are not counted).
 */
int ssda_kl_acc_add_source(ssda_kl_acc_t *acc, ssda_source_t *src, const ssda_rect_t *rect,
                           uint32_t channels);

/* Options of ssda_kl_solve. Zero means the documented default. */
typedef struct {
    uint8_t matrix;    /* ssda_kl_matrix_t (0 = correlation, the seed) */
    uint8_t range;     /* ssda_kl_range_t (0 = sigma) */
    uint8_t nsigma;    /* SIGMA range: mean +- nsigma sd fills 0..out_max, 1..16 (0 = 4) */
    uint16_t out_max;  /* largest feature value, 1..65534 (0 = 1023, about the
                          seed's 1000 histogram bins) */
    uint32_t gain_max_q16; /* largest move of z_k for a one-sample step of one
                              band, output steps, Q16, 1..4096 2^16 (0 = 4096) */
} ssda_kl_config_t;

/* A solved transform. Public fields may be read; the plan is private. */
typedef struct {
    int32_t matrix_q30[3][3]; /* the matrix diagonalised (see the top), Q30 */
    int32_t vec_q30[3][3];    /* row k: unit eigenvector of eigenvalue k, Q30 */
    uint64_t lambda_q16[3];   /* eigenvalues, decreasing, Q16: correlation:
                                 unitless (they sum to 3 when no band is
                                 constant); covariance: sample units^2 */
    uint64_t zvar_q16[3];     /* variance of Z_k = v_k . (x - m) over the
                                 counted pixels, sample units^2, Q16 */
    uint32_t mean_q8[3];      /* band means, sample units, Q8, rounded */
    uint32_t count;           /* pixels the statistics came from */
    uint32_t sweeps;          /* Jacobi sweeps run (1..12) */
    uint16_t out_max;         /* resolved options */
    uint32_t gain_max_q16;
    uint8_t matrix, range, nsigma;
    uint8_t format;           /* input sample format, from the accumulator */
    uint8_t flags;            /* mask flag and value, from the accumulator */
    uint16_t nodata;
    /* private: the per-pixel plan, z = (sum_j w_kj (x_j - c) + b_k) >> shift */
    int32_t w[3][3];
    int64_t b[3];
    uint32_t shift;
    uint32_t magic;
} ssda_kl_t;

/*
 * Solve: from the statistics, the matrix, its eigenvectors and eigenvalues,
 * the Z variances, and the per-pixel plan. acc is not changed (solve again
 * with other options at will).
 * Returns SSDA_OK, or with *kl untouched: SSDA_ERR_NULL, SSDA_ERR_STATE (acc
 * not initialised), SSDA_ERR_SIZE (no pixel counted), SSDA_ERR_ARG (unknown
 * matrix or range, nsigma above 16, out_max above 65534, gain_max_q16 above
 * 4096 2^16).
 */
int ssda_kl_solve(const ssda_kl_acc_t *acc, const ssda_kl_config_t *cfg, ssda_kl_t *kl);

/*
 * Transform one row of width pixels (same format and flags as the
 * accumulator) into up to three feature rows: out[k] (uint16_t, width
 * elements) receives z_k, or is skipped when NULL. Masked pixels become
 * SSDA_KL_NODATA. clamped (may be NULL) has the count of values clamped to
 * 0 or out_max added to it (<= 3 width per call).
 * Returns SSDA_OK, SSDA_ERR_NULL (kl, row or a band pointer NULL),
 * SSDA_ERR_STATE (kl not solved), SSDA_ERR_SIZE (width 0 or above 65535),
 * SSDA_ERR_ARG (step 0); nothing written on error.
 */
int ssda_kl_transform_row(const ssda_kl_t *kl, const ssda_kl_row_t *row, uint32_t width,
                          uint16_t *const out[3], uint32_t *clamped);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_KL_H */
