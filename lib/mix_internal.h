/* mix_internal.h - internal: shared parts of the Gaussian-mixture fits
   (mixture.h): components prepared for evaluation, the E-step, the work
   buffer's layout, and the fits themselves. */
#ifndef SSDA_MIX_INTERNAL_H
#define SSDA_MIX_INTERNAL_H

#include "ssda/mixture.h"
#include "fixexp.h"
#include "wide.h"

#define SSDA__MIX_K SSDA_MIX_MAX_COMPONENTS

/* A component's parameters while fitting. */
typedef struct {
    uint64_t n;         /* weight numerator: EM, pixels in Q8 (< 2^40); search,
                           height Q8 x sigma Q16 (< 2^53); shares are n / sum n */
    uint32_t mean_q16;  /* bins, Q16, < 2^28 */
    uint32_t sigma_q16; /* bins, Q16, sigma_min..bins 2^16 */
} ssda__mix_param_t;

/* A component prepared for evaluation at bin centres. */
typedef struct {
    uint32_t mean_q16;
    uint32_t km;    /* 2^16 / (sqrt2 sigma_q16) = km 2^-ks, km in (2^23, 2^24] */
    uint32_t ks;
    int32_t lw_q16; /* ln(share / sigma in bins), nats Q16 */
    bool active;    /* share > 0 */
} ssda__mix_gauss_t;

/* One EM iteration's sums for a component. */
typedef struct {
    uint64_t n_q8; /* sum h r, pixels Q8: < 2^40 */
    uint64_t m1;   /* sum h r z: < 2^52 */
    uint64_t m2;   /* sum h r (z - c)^2: < 2^64 */
    uint32_t c;    /* centre bin of m2: the mean at the E-step, rounded */
} ssda__mix_acc_t;

/* The resolved configuration. */
typedef struct {
    uint32_t k, kmax, fit, init, flags, max_iter;
    uint32_t sigma_min_q16, tol_q24;
} ssda__mix_cfg_t;

/* The work buffer: this fixed part (<= SSDA_MIX_WORK_FIXED bytes, checked
   by tests/test_mixture.c), then one int32_t per bin at offset
   SSDA_MIX_WORK_FIXED (residual or model cache). */
typedef struct {
    ssda_mix_model_t best;             /* automatic K: the best so far */
    ssda__mix_param_t p[SSDA__MIX_K];  /* the fit's parameters */
    ssda__mix_gauss_t g[SSDA__MIX_K];  /* prepared components */
    ssda__mix_acc_t acc[SSDA__MIX_K];  /* EM sums */
    int32_t height_q8[SSDA__MIX_K];    /* search: heights, Q8 of the scaled histogram */
    uint32_t lo[SSDA__MIX_K], hi[SSDA__MIX_K]; /* search: fixed error windows */
    int32_t *cache;                    /* the per-bin part */
} ssda__mix_work_t;

/* Prepare component g from its share n / sum (n > 0, else inactive), mean
   and sigma. */
SSDA_INTERNAL void ssda__mix_prepare(ssda__mix_gauss_t *g, uint64_t n, uint64_t sum,
                                     uint32_t mean_q16, uint32_t sigma_q16);

/* q(z) = ((z - mean) / (sqrt2 sigma))^2 in nats Q16, capped at 2^30. */
SSDA_INTERNAL uint32_t ssda__mix_q(const ssda__mix_gauss_t *g, uint32_t z);

/* One pass over hist: returns sum h(z) ln p(z) (nats Q16) for the k
   prepared components; with acc != NULL also fills acc[] (zeroed here,
   acc[j].c set from g[j].mean_q16). */
SSDA_INTERNAL int64_t ssda__mix_estep(const uint32_t *hist, uint32_t bins,
                                      const ssda__mix_gauss_t *g, uint32_t k, ssda__mix_acc_t *acc);

/* Prepare w->g[0..k) from w->p[0..k). */
SSDA_INTERNAL void ssda__mix_prepare_all(ssda__mix_work_t *w, uint32_t k);

/* Initial parameters w->p[0..k) (and w->height_q8 for the search). hs: the
   histogram's scale shift (h >> hs < 2^16). */
SSDA_INTERNAL void ssda__mix_init(const uint32_t *hist, uint32_t bins, uint32_t total, uint32_t hs,
                                  const ssda__mix_cfg_t *c, uint32_t k, ssda__mix_work_t *w);

/* EM from w->p[0..k): returns the iterations (E-steps) run and sets
   *loglik to the log-likelihood of the final w->p. */
SSDA_INTERNAL uint32_t ssda__mix_em(const uint32_t *hist, uint32_t bins, const ssda__mix_cfg_t *c,
                                    uint32_t k, ssda__mix_work_t *w, int64_t *loglik);

/* The seed's coordinate search from w->p / w->height_q8; leaves the final
   parameters in w->p (n = height x sigma); returns the cycles run. */
SSDA_INTERNAL uint32_t ssda__mix_search(const uint32_t *hist, uint32_t bins, uint32_t hs,
                                        const ssda__mix_cfg_t *c, uint32_t k, ssda__mix_work_t *w);

/* h >> hs < 2^16 for every bin. */
SSDA_INTERNAL uint32_t ssda__mix_scale_shift(const uint32_t *hist, uint32_t bins);

/* round(num 2^s / den) for den > 0 (128-bit quotient, saturated to 64). */
SSDA_INTERNAL uint64_t ssda__mix_ratio(uint64_t num, uint32_t s, uint64_t den);

#endif /* SSDA_MIX_INTERNAL_H */
