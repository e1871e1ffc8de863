/* mix_em.c - EM of a Gaussian mixture on a histogram (mixture.h). */
#include "mix_internal.h"

#include "fixmath.h"

/* The M-step of component j from its sums (n_q8 > 0). */
static void m_step(ssda__mix_param_t *p, const ssda__mix_acc_t *a, uint32_t sigma_min_q16)
{
    /* mean = m1 / n in Q16 (m1 2^16 < 2^68) */
    const uint64_t mean_q16 = ssda__mix_ratio(a->m1, 16u, a->n_q8);
    /* E[(z - c)^2] in Q32 (m2 2^32 < 2^96), minus (mean - c)^2 */
    const uint64_t e2_q32 = ssda__mix_ratio(a->m2, 32u, a->n_q8);
    const uint64_t cq = (uint64_t)a->c << 16;
    const uint64_t dm = mean_q16 > cq ? mean_q16 - cq : cq - mean_q16; /* < 2^28 */
    const uint64_t d2 = dm * dm;
    uint64_t sigma = 0u;
    if (e2_q32 > d2) {
        sigma = ssda__isqrt64(e2_q32 - d2); /* variance <= bins^2: sigma < 2^28 */
    }
    p->n = a->n_q8;
    p->mean_q16 = (uint32_t)mean_q16;
    p->sigma_q16 = sigma < sigma_min_q16 ? sigma_min_q16 : (uint32_t)sigma;
}

/* |a - b| */
static uint64_t dist(uint64_t a, uint64_t b)
{
    return a > b ? a - b : b - a;
}

/* Did component j move by more than tol (Q24): its mean or sigma by more
   than tol of its sigma, or its share by more than tol? */
static bool moved(const ssda__mix_param_t *before, uint64_t sum_before,
                  const ssda__mix_param_t *after, uint64_t sum_after, uint32_t tol_q24)
{
    /* |d| 2^24 < 2^52 and tol sigma < 2^52 */
    const uint64_t limit = (uint64_t)tol_q24 * after->sigma_q16;
    const uint64_t share0 = ssda__mix_ratio(before->n, 24u, sum_before); /* <= 2^24 */
    const uint64_t share1 = ssda__mix_ratio(after->n, 24u, sum_after);
    return (dist(before->mean_q16, after->mean_q16) << 24) > limit ||
           (dist(before->sigma_q16, after->sigma_q16) << 24) > limit ||
           dist(share0, share1) > tol_q24;
}

static uint64_t sum_n(const ssda__mix_param_t *p, uint32_t k)
{
    uint64_t s = 0u;
    uint32_t j;
    for (j = 0u; j < k; j++) {
        s += p[j].n; /* < 16 2^53 */
    }
    return s;
}

/* The M-step of every component; true if none moved by more than tol. */
static bool m_steps(ssda__mix_work_t *w, uint32_t k, const ssda__mix_cfg_t *c)
{
    ssda__mix_param_t before[SSDA__MIX_K];
    const uint64_t sum0 = sum_n(w->p, k);
    uint64_t sum1;
    bool settled = true;
    uint32_t j;
    for (j = 0u; j < k; j++) {
        before[j] = w->p[j];
        if (w->acc[j].n_q8 != 0u) {
            m_step(&w->p[j], &w->acc[j], c->sigma_min_q16);
        } else {
            w->p[j].n = 0u; /* dead: stays at weight 0 */
        }
    }
    sum1 = sum_n(w->p, k);
    for (j = 0u; j < k; j++) {
        if (moved(&before[j], sum0, &w->p[j], sum1, c->tol_q24)) {
            settled = false;
        }
    }
    return settled;
}

uint32_t ssda__mix_em(const uint32_t *hist, uint32_t bins, const ssda__mix_cfg_t *c, uint32_t k,
                      ssda__mix_work_t *w, int64_t *loglik)
{
    int64_t ll = 0;
    uint32_t it = 0u;
    bool settled = false, done;
    do {
        it++;
        ssda__mix_prepare_all(w, k);
        ll = ssda__mix_estep(hist, bins, w->g, k, w->acc);
        /* when done, w->p is the model whose log-likelihood is ll */
        done = settled || it == c->max_iter;
        if (!done) {
            settled = m_steps(w, k, c);
        }
    } while (!done);
    *loglik = ll;
    return it;
}
