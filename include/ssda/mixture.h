/*
 * mixture.h - Gaussian-mixture models of a 1-D histogram, in fixed point:
 * the seed's coordinate search and EM, the number of components given or
 * chosen by BIC, and a look-up table from feature value to component
 * label so that labelling an image is one read per pixel.
 *
 * Seed: Fujimoto and Tanaka (../shared/seeds/004, section 2.2, eq. 2.5 and
 * Figs. 2.2.1-2.2.3): the histogram of each K-L feature image is modelled as
 *     h(z) ~ sum_k MM1_k exp(-(z - MM2_k)^2 / MM3_k)
 * (the minus sign of the exponent is lost in print), the parameters fitted
 * by stepping each one in turn while the squared error, counted only within
 * +-2 "standard deviations" of each component (a window fixed at the
 * start), decreases, over and over until no parameter improves; 6, 5 and 4
 * components for Z1, Z2, Z3. A region is the pixels within +-2 sigma of a
 * component. The seed calls sqrt(MM3) the standard deviation; with its
 * model that is sqrt(2) sigma. This library uses the usual
 * a exp(-(z - mu)^2 / (2 sigma^2)) and true sigma everywhere (the windows
 * and bands are +-2 sigma; SSDA_MIX_SEARCH_WINDOW and the band argument of
 * ssda_mix_lut set them). Design and measurements: docs/segmentation.md.
 *
 * UNITS AND FORMATS. A histogram is `bins` uint32_t counts (2..4096 bins,
 * total below 2^32); bin z holds the feature values of bin index z. Means
 * and sigmas are in bins, Q16 (mean_q16 in [0, (bins - 1) 2^16]); weights
 * are shares of the histogram's total, Q16 (they sum to 65536 up to the
 * rounding of each). Log-likelihoods and BIC are in nats, Q16, int64.
 *
 * THE DENSITY, as evaluated (all fits, the log-likelihood and the labels):
 *     p(z) = sum_k w_k / (sigma_k sqrt(2 pi)) exp(-(z - mu_k)^2 / (2 sigma_k^2))
 * at bin centres (z an integer), computed in the log domain: per component
 * s_k = ln(w_k / sigma_k) - q_k(z) with q_k(z) = ((z - mu_k) / (sqrt2
 * sigma_k))^2 (Q16: the ratio in Q16 from a 24-bit reciprocal, relative
 * error < 2^-22, truncated, then squared: q within 4 sqrt(q) + 2 Q16 steps,
 * q in nats, so 2^-12 relative near q = 1 and 0.008 nats at the cap;
 * capped at 16384 nats; tests/test_mixture.c), then
 * ln p = max s + ln(sum exp(s_k - max s)) - ln sqrt(2 pi).
 * exp(-x) in Q30 within 2 steps, ln in Q24 within 1 step (lib/fixexp.c,
 * tests/test_fixexp.c against libm).
 *
 * EM (SSDA_MIX_FIT_EM): on the histogram, each bin weighted by its count:
 * O(bins x components) per iteration (empty bins skipped). Responsibilities
 * in Q30; per-component sums in 64 bits (count Q8 < 2^40, first moment
 * < 2^52, second moment about the old mean < 2^64); the new mean and
 * variance from 128-bit quotients. Sigma is floored at sigma_min (a
 * histogram of integers has no narrower component). A component whose
 * weight reaches 0 stays at weight 0. Stops when an iteration moves no
 * mean and no sigma by more than tol of its sigma, and no weight by more
 * than tol (tol_q24 / 2^24), or after max_iter iterations; the model
 * returned is the one whose log-likelihood was measured last. (A stop on
 * the log-likelihood's gain would end early: near a ridge the gain per
 * iteration is smaller than the rounding of the fixed-point sum.)
 *
 * SEARCH (SSDA_MIX_FIT_SEARCH, the seed's Fig. 2.2.1): parameters height
 * a_k, mean, sigma; the histogram is scaled by a power of two to a peak
 * below 2^16 first (heights in Q8 of those counts). Each component's
 * window is the bins within +-2 sigma of it as initialised, fixed from
 * then on; the error of a trial is the squared difference between the
 * histogram and the whole model (every component) summed over the window
 * of the component being changed (64 bits: model values capped at 2^26 in
 * Q8, differences below 2^26, 4096 bins). Each parameter is stepped by
 * +step while the error falls, else by -step while it falls (the seed's
 * FTRY), then the next parameter; cycles over all parameters repeat until
 * none improves. The seed stops there (SSDA_MIX_SEED_STEPS); by default
 * the steps are then halved and the cycles resumed, 6 times, which finds
 * the minimum the fixed steps straddle. Steps start at height/16, sigma/8
 * (mean) and sigma/16 (sigma) of each component's initial values, at least
 * 1 LSB. Parameters are kept in height [1, 2^25], mean [0, bins - 1],
 * sigma [sigma_min, bins]. Weights are then w_k ~ a_k sigma_k sqrt(2 pi),
 * normalised to sum 1 (the seed's fit is of heights, not a density).
 *
 * INITIALISATION (no interactive step, deterministic):
 *   SSDA_MIX_INIT_PEAKS (default): the seed's manual procedure made
 *     automatic: on the residual smoothed over 5 bins (a histogram of
 *     integer samples can be a comb of fuller and emptier bins), take the
 *     highest bin (ties: the lowest bin), its mean height and half width at
 *     half height (interpolated; sigma = FWHM / 2.3548, twice the one-sided
 *     width if the other side meets the histogram's end), subtract that
 *     Gaussian from the residual, and repeat; shoulders of a peak become the
 *     next components. A start of FWHM at most 6 bins (sigma <= 2.55 bins:
 *     the 5-bin mean's own width and one bin) is narrower than the 5-bin
 *     mean resolves and its height falls short (a saturation spike in one
 *     bin: a fifth of it), so most of it stays in the residual: no later
 *     start is taken within 2 bins of it (the next highest bin elsewhere
 *     is), else starts would pile onto one spike at one mean and sigma,
 *     which EM cannot pull apart. Near a wider start the residual is of
 *     another width (a narrower top, a base) and may take a start. If the
 *     residual runs out (no positive 5-bin mean left outside those bins)
 *     the quantile start is used for every component.
 *   SSDA_MIX_INIT_QUANTILES: K slices of equal count along the histogram,
 *     each slice's mean, standard deviation and share.
 *
 * NUMBER OF COMPONENTS: given (components 1..16), or chosen (components 0)
 * as the K in 1..max_components of least BIC = -2 ln L + (3K - 1) ln N
 * (ties: the smaller K), each K fitted by EM from its own initialisation;
 * the search fit then starts from the same initialisation as that K's EM.
 * A K > 1 whose EM fit holds two copies (means and sigmas within 1/16 of
 * the larger sigma of each other: EM moves such a pair alike, and their
 * sum is one Gaussian) is not chosen: it is a fit of fewer components.
 *
 * LABELS: components are sorted by increasing mean (ties: the order
 * found); label k + 1 is component k; 0 is "none".
 *   SSDA_MIX_LABEL_BAND (the seed): z gets a label when it lies within
 *     band sigmas of that component's mean (|z - mu| <= band sigma); of
 *     several, the most likely (largest s_k, ties: the lower label); none: 0.
 *   SSDA_MIX_LABEL_LIKELY: the most likely component always.
 *
 * Reentrant; every buffer is the caller's. Outputs are written on success
 * only.
 */
#ifndef SSDA_MIXTURE_H
#define SSDA_MIXTURE_H

#include "ssda/ssda.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SSDA_MIX_MAX_BINS 4096u
#define SSDA_MIX_MIN_BINS 2u
#define SSDA_MIX_MAX_COMPONENTS 16u

/* Defaults. */
#define SSDA_MIX_DEFAULT_MAX_COMPONENTS 8u
#define SSDA_MIX_DEFAULT_MAX_ITER 500u
#define SSDA_MIX_DEFAULT_SIGMA_MIN_Q16 32768u /* 0.5 bin */
#define SSDA_MIX_DEFAULT_TOL_Q24 1024u        /* 2^-14, about 6e-5 */
#define SSDA_MIX_DEFAULT_BAND_Q8 512u         /* +-2 sigma, the seed's band */
/* The search's error window: +-2 sigma of each initial component. */
#define SSDA_MIX_SEARCH_WINDOW 2u
/* Step halvings after the seed's stop (unless SSDA_MIX_SEED_STEPS). */
#define SSDA_MIX_SEARCH_HALVINGS 6u

typedef enum {
    SSDA_MIX_FIT_EM = 0,    /* expectation-maximisation on the histogram */
    SSDA_MIX_FIT_SEARCH = 1 /* the seed's coordinate search */
} ssda_mix_fit_t;

typedef enum {
    SSDA_MIX_INIT_PEAKS = 0,    /* peaks and shoulders of the residual */
    SSDA_MIX_INIT_QUANTILES = 1 /* slices of equal count */
} ssda_mix_init_t;

typedef enum {
    SSDA_MIX_LABEL_BAND = 0,  /* within +-band sigma (the seed) */
    SSDA_MIX_LABEL_LIKELY = 1 /* the most likely component */
} ssda_mix_rule_t;

/* Flags. */
#define SSDA_MIX_SEED_STEPS 0x01u /* search: stop where the seed stops (fixed steps) */

/* Fit configuration. Zero means the documented default. */
typedef struct {
    uint8_t components;     /* K, 1..16; 0 = choose by BIC up to max_components */
    uint8_t max_components; /* with components 0: 1..16 (0 = 8) */
    uint8_t fit;            /* ssda_mix_fit_t (0 = EM) */
    uint8_t init;           /* ssda_mix_init_t (0 = peaks) */
    uint8_t flags;          /* SSDA_MIX_SEED_STEPS */
    uint16_t max_iter;      /* EM iterations, or search cycles, per fit (0 = 500) */
    uint32_t sigma_min_q16; /* smallest sigma, bins Q16, 1..bins 2^16 (0 = 0.5 bin) */
    uint32_t tol_q24;       /* EM stop: the largest move of a mean or sigma (in
                               sigmas) or of a weight in one iteration, Q24
                               (0 = 1024: 2^-14, about 6e-5) */
} ssda_mix_config_t;

/* One component. */
typedef struct {
    uint32_t weight_q16; /* share of the histogram's pixels, Q16 */
    uint32_t mean_q16;   /* bins, Q16 */
    uint32_t sigma_q16;  /* standard deviation, bins, Q16 */
} ssda_mix_component_t;

/* A fitted model. */
typedef struct {
    ssda_mix_component_t comp[SSDA_MIX_MAX_COMPONENTS]; /* sorted by mean */
    int64_t loglik_q16;  /* sum over bins of h(z) ln p(z), nats Q16 (< 0 for p < 1) */
    int64_t bic_q16;     /* -2 loglik + (3 count - 1) ln(total), nats Q16 */
    uint32_t count;      /* components, 1..16 */
    uint32_t bins;       /* histogram bins */
    uint32_t total;      /* pixels in the histogram */
    uint32_t iterations; /* EM iterations or search cycles run by the final fit */
    uint8_t fit;         /* ssda_mix_fit_t used */
} ssda_mix_model_t;

/* Work buffer bytes for a histogram of `bins` bins (8-byte aligned): a
   fixed part (trial model, per-component sums) and 4 bytes per bin. */
#define SSDA_MIX_WORK_FIXED 2048u
#define SSDA_MIX_WORK_SIZE(bins) ((size_t)SSDA_MIX_WORK_FIXED + 4u * (size_t)(bins))

/*
 * Count values into a histogram: hist[v >> shift] += 1 for each of the n
 * values with (v >> shift) < bins; others (SSDA_KL_NODATA, out of range)
 * are skipped and, if skipped is not NULL, added to *skipped (saturating).
 * The caller keeps the total below 2^32 (one image of at most 65535 x
 * 65535 pixels). Returns SSDA_OK, SSDA_ERR_NULL (hist or values NULL),
 * SSDA_ERR_SIZE (bins 0 or above 4096), SSDA_ERR_ARG (shift above 15).
 */
int ssda_mix_hist_add(uint32_t *hist, uint32_t bins, const uint16_t *values, uint32_t n,
                      uint32_t shift, uint32_t *skipped);

/*
 * Fit a mixture to hist (bins counts; not changed). work: SSDA_MIX_WORK_SIZE(
 * bins) bytes, 8-byte aligned, scratch only. *model written on success.
 * Cost: EM, bins x K per iteration (K = 1..max for automatic K, each
 * fitted); search, window x K per trial step.
 * Returns SSDA_OK, or with *model untouched: SSDA_ERR_NULL (hist, work or
 * model NULL), SSDA_ERR_SIZE (bins outside 2..4096, or an empty histogram),
 * SSDA_ERR_ARG (components or max_components above 16, unknown fit, init
 * or flags, sigma_min_q16 above bins 2^16), SSDA_ERR_BUFFER (work short or
 * misaligned), SSDA_ERR_OVERFLOW (counts summing to 2^32 or more).
 */
int ssda_mix_fit(const uint32_t *hist, uint32_t bins, const ssda_mix_config_t *cfg, void *work,
                 size_t work_size, ssda_mix_model_t *model);

/*
 * Label look-up table: lut[z] for z < model->bins receives the label of
 * bin z by the rule (ssda_mix_rule_t), band_q8 sigmas wide for
 * SSDA_MIX_LABEL_BAND (Q8, 1..4096, 0 = 2.0). lut has model->bins bytes.
 * Returns SSDA_OK, SSDA_ERR_NULL, SSDA_ERR_ARG (unknown rule, band above
 * 16 sigma, a model with count 0 or above 16, bins outside 2..4096, or a
 * component of sigma 0 among the first count).
 */
int ssda_mix_lut(const ssda_mix_model_t *model, uint8_t rule, uint32_t band_q8, uint8_t *lut);

/*
 * Label n feature values: labels[i] = lut[v >> shift] if that is < bins,
 * else 0 (nodata, out of range). One shift and one read per pixel.
 * Returns SSDA_OK, SSDA_ERR_NULL, SSDA_ERR_SIZE (bins 0 or above 4096),
 * SSDA_ERR_ARG (shift above 15).
 */
int ssda_mix_label_row(const uint8_t *lut, uint32_t bins, const uint16_t *values, uint32_t n,
                       uint32_t shift, uint8_t *labels);

/*
 * The seed's per-component areas: pixels[k] = the count of hist within
 * band_q8 sigmas of component k (bands may overlap, as the seed's
 * extractions do); model->count entries written. hist must have
 * model->bins bins.
 * Returns SSDA_OK, SSDA_ERR_NULL, SSDA_ERR_ARG (as ssda_mix_lut).
 */
int ssda_mix_band_pixels(const ssda_mix_model_t *model, const uint32_t *hist, uint32_t band_q8,
                         uint32_t *pixels);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_MIXTURE_H */
