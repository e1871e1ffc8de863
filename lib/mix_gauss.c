/* mix_gauss.c - Gaussian components at bin centres and the E-step of the
   mixture fits (mixture.h: "The density, as evaluated"). */
#include "mix_internal.h"

#include <string.h>

#include "fixmath.h"

#define SQRT2_Q30 1518500250u     /* sqrt(2) */
#define LN_SQRT2PI_Q16 60224      /* ln(sqrt(2 pi)) */
#define LN2_Q16_X27 1226505       /* 27 ln 2 in Q16: e values are Q27 */
#define Q_CAP 1073741824u         /* 16384 nats in Q16 */
#define U_CAP 8388608u            /* 128 in Q16: beyond it q is capped */

uint64_t ssda__mix_ratio(uint64_t num, uint32_t s, uint64_t den)
{
    ssda__u128_t n = ssda__u128_shl(ssda__u128_from(num), s);
    const ssda__u128_t d = ssda__u128_from(den);
    n = ssda__u128_add(n, ssda__u128_from(den >> 1));
    return ssda__u128_sat64(ssda__u128_div(n, d));
}

void ssda__mix_prepare(ssda__mix_gauss_t *g, uint64_t n, uint64_t sum, uint32_t mean_q16,
                       uint32_t sigma_q16)
{
    /* sqrt2 sigma in Q46 (sigma_q16 < 2^29): 2^31 <= s2 < 2^60 */
    const uint64_t s2 = (uint64_t)sigma_q16 * SQRT2_Q30;
    const uint32_t b = ssda__bitlen64(s2);
    g->mean_q16 = mean_q16;
    g->ks = b - 23u;
    /* km = 2^(46 + ks) / s2 = 2^(23 + b) / s2 in (2^23, 2^24] */
    g->km = (uint32_t)ssda__u128_div(ssda__u128_shl(ssda__u128_from(1u), 23u + b),
                                     ssda__u128_from(s2)).lo;
    g->active = n != 0u; /* and so sum >= n > 0 */
    g->lw_q16 = 0;
    if (g->active) {
        /* ln(n / sum) - ln(sigma_q16 / 2^16), Q24 (each ln < 45 nats) */
        const int64_t lw = (int64_t)ssda__ln_q24(n) - (int64_t)ssda__ln_q24(sum) -
             (int64_t)ssda__ln_q24(sigma_q16) + (16 * (int64_t)SSDA__LN2_Q24);
        g->lw_q16 = (int32_t)ssda__round_shift(lw, 8u);
    }
}

uint32_t ssda__mix_q(const ssda__mix_gauss_t *g, uint32_t z)
{
    const uint32_t zq = z << 16; /* z < 4096: < 2^28 */
    const uint32_t d = zq > g->mean_q16 ? zq - g->mean_q16 : g->mean_q16 - zq;
    const uint64_t u = ((uint64_t)d * g->km) >> g->ks; /* d / (sqrt2 sigma), Q16 */
    if (u >= U_CAP) {
        return Q_CAP;
    }
    return (uint32_t)((u * u + 32768u) >> 16); /* < 2^30 */
}

void ssda__mix_prepare_all(ssda__mix_work_t *w, uint32_t k)
{
    uint64_t sum = 0u;
    uint32_t j;
    for (j = 0u; j < k; j++) {
        sum += w->p[j].n; /* < 16 2^53 */
    }
    for (j = 0u; j < k; j++) {
        ssda__mix_prepare(&w->g[j], w->p[j].n, sum, w->p[j].mean_q16, w->p[j].sigma_q16);
    }
}

/* Responsibility-weighted sums of bin z (count h) from the Q27 terms e of
   the k components and their sum s (2^27 <= s <= 2^31). */
static void accumulate(ssda__mix_acc_t *acc, const uint32_t *e, uint32_t s, uint32_t k,
                       uint32_t z, uint32_t h)
{
    const uint64_t inv = SSDA_DIV64_32((uint64_t)1u << 58, s); /* 2^27..2^31 */
    uint32_t j;
    for (j = 0u; j < k; j++) {
        const uint64_t r = ((uint64_t)e[j] * inv) >> 28; /* Q30, <= 2^30 */
        const uint64_t hr = ((uint64_t)h * r + 2097152u) >> 22; /* Q8, rounded, < 2^40 */
        const uint32_t d = z > acc[j].c ? z - acc[j].c : acc[j].c - z;
        const uint64_t d2 = (uint64_t)d * d;              /* < 2^24 */
        acc[j].n_q8 += hr;
        acc[j].m1 += hr * z;
        acc[j].m2 += hr * d2;
    }
}

int64_t ssda__mix_estep(const uint32_t *hist, uint32_t bins, const ssda__mix_gauss_t *g,
                        uint32_t k, ssda__mix_acc_t *acc)
{
    int32_t s[SSDA__MIX_K];
    uint32_t e[SSDA__MIX_K];
    int64_t ll = 0; /* |sum| < 2^32 (2^30 + 2^22): fits */
    uint32_t z, j;
    if (acc != NULL) {
        (void)memset(acc, 0, k * sizeof acc[0]);
        for (j = 0u; j < k; j++) {
            acc[j].c = (g[j].mean_q16 + 32768u) >> 16;
        }
    }
    for (z = 0u; z < bins; z++) {
        const uint32_t h = hist[z];
        int32_t smax = 0;
        uint32_t sum = 0u;
        bool any = false;
        int64_t lnp;
        if (h == 0u) {
            continue;
        }
        for (j = 0u; j < k; j++) {
            /* lw in +-2^22, q <= 2^30: s in [-2^30 - 2^22, 2^22] */
            s[j] = g[j].lw_q16 - (int32_t)ssda__mix_q(&g[j], z);
            if (g[j].active && (!any || s[j] > smax)) {
                smax = s[j];
                any = true;
            }
        }
        for (j = 0u; j < k; j++) {
            e[j] = 0u;
            if (g[j].active) {
                const int32_t diff = smax - s[j]; /* in [0, 2^31) */
                e[j] = ssda__exp_neg_q16((uint32_t)diff) >> 3; /* Q27 */
                sum += e[j]; /* the largest is 2^27: 2^27 <= sum <= 2^31 */
            }
        }
        if (!any) {
            continue; /* no component left (every weight 0): nothing to add */
        }
        lnp = (int64_t)smax + ssda__round_shift(ssda__ln_q24(sum), 8u) -
              (LN2_Q16_X27 + LN_SQRT2PI_Q16);
        ll += (int64_t)h * lnp;
        if (acc != NULL) {
            accumulate(acc, e, sum, k, z, h);
        }
    }
    return ll;
}

uint32_t ssda__mix_scale_shift(const uint32_t *hist, uint32_t bins)
{
    uint32_t z, top = 0u, b;
    for (z = 0u; z < bins; z++) {
        top = hist[z] > top ? hist[z] : top;
    }
    b = ssda__bitlen64(top);
    return b > 16u ? b - 16u : 0u;
}
