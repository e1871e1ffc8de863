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
        sigma = ssda_isqrt64(e2_q32 - d2); /* variance <= bins^2: sigma < 2^28 */
    }
    p->n = a->n_q8;
    p->mean_q16 = (uint32_t)mean_q16;
    p->sigma_q16 = sigma < sigma_min_q16 ? sigma_min_q16 : (uint32_t)sigma;
}

uint32_t ssda__mix_em(const uint32_t *hist, uint32_t bins, uint32_t total,
                      const ssda__mix_cfg_t *c, uint32_t k, ssda__mix_work_t *w,
                      int64_t *loglik)
{
    /* stop when the gain is at most tol 2^-30 nats per pixel: in Q16,
       tol total 2^-14 (< 2^50) */
    const int64_t stop = (int64_t)(((uint64_t)c->tol_q30 * total) >> 14);
    int64_t ll = 0, prev = 0;
    uint32_t it = 0u, j;
    bool done;
    do {
        it++;
        ssda__mix_prepare_all(w, k);
        ll = ssda__mix_estep(hist, bins, w->g, k, w->acc);
        /* when done, w->p is the model whose log-likelihood is ll */
        done = (it > 1u && ll - prev <= stop) || it == c->max_iter;
        if (!done) {
            prev = ll;
            for (j = 0u; j < k; j++) {
                if (w->acc[j].n_q8 != 0u) {
                    m_step(&w->p[j], &w->acc[j], c->sigma_min_q16);
                } else {
                    w->p[j].n = 0u; /* dead: stays at weight 0 */
                }
            }
        }
    } while (!done);
    *loglik = ll;
    return it;
}
