/* mix_fit.c - ssda_mix_fit: validation, the number of components by BIC,
   and the model as returned (mixture.h). */
#include "mix_internal.h"

#include <string.h>

static int resolve(const ssda_mix_config_t *cfg, uint32_t bins, ssda__mix_cfg_t *c)
{
    ssda_mix_config_t z;
    if (cfg != NULL) {
        z = *cfg;
    } else {
        (void)memset(&z, 0, sizeof z);
    }
    if (z.components > SSDA__MIX_K || z.max_components > SSDA__MIX_K ||
        z.fit > (uint8_t)SSDA_MIX_FIT_SEARCH || z.init > (uint8_t)SSDA_MIX_INIT_QUANTILES ||
        (z.flags & (uint8_t)~SSDA_MIX_SEED_STEPS) != 0u ||
        (uint64_t)z.sigma_min_q16 > ((uint64_t)bins << 16)) {
        return SSDA_ERR_ARG;
    }
    c->k = z.components;
    c->kmax = z.max_components != 0u ? z.max_components : SSDA_MIX_DEFAULT_MAX_COMPONENTS;
    c->fit = z.fit;
    c->init = z.init;
    c->flags = z.flags;
    c->max_iter = z.max_iter != 0u ? z.max_iter : SSDA_MIX_DEFAULT_MAX_ITER;
    c->sigma_min_q16 = z.sigma_min_q16 != 0u ? z.sigma_min_q16 : SSDA_MIX_DEFAULT_SIGMA_MIN_Q16;
    c->tol_q24 = z.tol_q24 != 0u ? z.tol_q24 : SSDA_MIX_DEFAULT_TOL_Q24;
    return SSDA_OK;
}

/* The BIC of a log-likelihood for k components over total pixels. */
static int64_t bic(int64_t ll, uint32_t k, uint32_t total)
{
    /* ln(total) in Q16 (< 23 nats), (3k - 1) of them */
    const int64_t ln_n = ssda__round_shift((int64_t)ssda__ln_q24(total), 8u);
    const uint32_t params = (3u * k) - 1u;
    return (-2 * ll) + ((int64_t)params * ln_n);
}

/* Components of w->p[0..k) into m: shares, sorted by mean (ties: the
   order found). sum > 0: EM gives every occupied bin's most responsible
   component >= 16 Q8 pixels, the search keeps heights >= 1. */
static void to_model(const ssda__mix_work_t *w, uint32_t k, ssda_mix_model_t *m)
{
    uint64_t sum = 0u;
    uint32_t j, i;
    for (j = 0u; j < k; j++) {
        sum += w->p[j].n;
    }
    for (j = 0u; j < k; j++) {
        ssda_mix_component_t c;
        c.weight_q16 = (uint32_t)ssda__mix_ratio(w->p[j].n, 16u, sum);
        c.mean_q16 = w->p[j].mean_q16;
        c.sigma_q16 = w->p[j].sigma_q16;
        /* insertion: stable, so equal (mean, sigma) keep their order */
        for (i = j; i > 0u && m->comp[i - 1u].mean_q16 > c.mean_q16; i--) {
            m->comp[i] = m->comp[i - 1u];
        }
        m->comp[i] = c;
    }
    for (j = k; j < SSDA__MIX_K; j++) {
        (void)memset(&m->comp[j], 0, sizeof m->comp[j]);
    }
    m->count = k;
}

/* Fit k components (EM from the configured start), into m. */
static void fit_em(const uint32_t *hist, uint32_t bins, uint32_t total, uint32_t hs,
                   const ssda__mix_cfg_t *c, uint32_t k, ssda__mix_work_t *w, ssda_mix_model_t *m)
{
    int64_t ll = 0;
    ssda__mix_init(hist, bins, total, hs, c, k, w);
    m->iterations = ssda__mix_em(hist, bins, c, k, w, &ll);
    to_model(w, k, m);
    m->loglik_q16 = ll;
    m->bic_q16 = bic(ll, k, total);
}

/* Fit k components by the seed's search, into m. */
static void fit_search(const uint32_t *hist, uint32_t bins, uint32_t total, uint32_t hs,
                       const ssda__mix_cfg_t *c, uint32_t k, ssda__mix_work_t *w,
                       ssda_mix_model_t *m)
{
    ssda__mix_init(hist, bins, total, hs, c, k, w);
    m->iterations = ssda__mix_search(hist, bins, hs, c, k, w);
    ssda__mix_prepare_all(w, k);
    m->loglik_q16 = ssda__mix_estep(hist, bins, w->g, k, NULL);
    m->bic_q16 = bic(m->loglik_q16, k, total);
    to_model(w, k, m);
}

/* Whether two components of m are copies: means and sigmas within 1/16
   of the larger sigma of each other. EM cannot pull such a pair apart
   (it moves both alike), and their sum is one Gaussian within a few
   parts in 1000 of its peak: the fit is one of fewer components. */
static bool has_copy(const ssda_mix_model_t *m)
{
    uint32_t i, j;
    bool copy = false;
    for (i = 0u; i < m->count && !copy; i++) {
        for (j = i + 1u; j < m->count && !copy; j++) {
            const ssda_mix_component_t *a = &m->comp[i], *b = &m->comp[j];
            const uint32_t s = a->sigma_q16 > b->sigma_q16 ? a->sigma_q16 : b->sigma_q16;
            const uint32_t dm = a->mean_q16 > b->mean_q16 ? a->mean_q16 - b->mean_q16
                                                          : b->mean_q16 - a->mean_q16;
            const uint32_t ds = a->sigma_q16 > b->sigma_q16 ? a->sigma_q16 - b->sigma_q16
                                                            : b->sigma_q16 - a->sigma_q16;
            copy = dm <= (s >> 4) && ds <= (s >> 4);
        }
    }
    return copy;
}

/* The number of components of least BIC (ties: fewer), by EM; a K whose
   fit holds a copy (has_copy) is not a candidate. */
static uint32_t choose_k(const uint32_t *hist, uint32_t bins, uint32_t total, uint32_t hs,
                         const ssda__mix_cfg_t *c, ssda__mix_work_t *w, ssda_mix_model_t *m)
{
    uint32_t k, best = 1u;
    for (k = 1u; k <= c->kmax; k++) {
        fit_em(hist, bins, total, hs, c, k, w, m);
        if (k == 1u || (m->bic_q16 < w->best.bic_q16 && !has_copy(m))) {
            w->best = *m;
            best = k;
        }
    }
    *m = w->best;
    return best;
}

int ssda_mix_fit(const uint32_t *hist, uint32_t bins, const ssda_mix_config_t *cfg, void *work,
                 size_t work_size, ssda_mix_model_t *model)
{
    ssda__mix_cfg_t c;
    ssda__mix_work_t *w;
    ssda_mix_model_t m;
    uint64_t total = 0u;
    uint32_t z, hs, k;
    int err;
    if (hist == NULL || work == NULL || model == NULL) {
        return SSDA_ERR_NULL;
    }
    if (bins < SSDA_MIX_MIN_BINS || bins > SSDA_MIX_MAX_BINS) {
        return SSDA_ERR_SIZE;
    }
    err = resolve(cfg, bins, &c);
    if (err != SSDA_OK) {
        return err;
    }
    if (work_size < SSDA_MIX_WORK_SIZE(bins) || ((uintptr_t)work & 7u) != 0u) {
        return SSDA_ERR_BUFFER;
    }
    for (z = 0u; z < bins; z++) {
        total += hist[z]; /* < 4096 2^32 */
    }
    if (total == 0u) {
        return SSDA_ERR_SIZE;
    }
    if (total > UINT32_MAX) {
        return SSDA_ERR_OVERFLOW;
    }
    w = (ssda__mix_work_t *)work;
    w->cache = (int32_t *)(void *)((uint8_t *)work + SSDA_MIX_WORK_FIXED);
    hs = ssda__mix_scale_shift(hist, bins);
    (void)memset(&m, 0, sizeof m);
    k = c.k;
    if (k == 0u) {
        k = choose_k(hist, bins, (uint32_t)total, hs, &c, w, &m);
    }
    if (c.fit == (uint32_t)SSDA_MIX_FIT_SEARCH) {
        fit_search(hist, bins, (uint32_t)total, hs, &c, k, w, &m);
    } else if (c.k != 0u) {
        fit_em(hist, bins, (uint32_t)total, hs, &c, k, w, &m);
    } else {
        /* automatic K by EM: m holds the chosen fit */
    }
    m.bins = bins;
    m.total = (uint32_t)total;
    m.fit = (uint8_t)c.fit;
    *model = m;
    return SSDA_OK;
}
