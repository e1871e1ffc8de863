/* mix_init.c - deterministic starts of the mixture fits (mixture.h,
   "Initialisation"): peaks and shoulders of the residual, or quantiles. */
#include "mix_internal.h"

#include "fixmath.h"

#define INV_FWHM_Q16 27831u /* 1 / (2 sqrt(2 ln 2)) = sigma / FWHM */

/* The residual smoothed over 5 bins (fewer at the ends), times 60: each
   bin of a histogram of integer samples may hold one or two of the values
   they give (a comb), which would end a half width at the first bin. */
static int64_t smooth(const int32_t *r, uint32_t bins, uint32_t z)
{
    const uint32_t lo = z >= 2u ? z - 2u : 0u;
    const uint32_t hi = z + 2u < bins ? z + 2u : bins - 1u;
    int64_t s = 0; /* |r| < 2^17: |s| < 2^20 */
    uint32_t i, n, scale;
    for (i = lo; i <= hi; i++) {
        s += r[i];
    }
    n = (hi - lo) + 1u;
    scale = 60u / n; /* 60 / 3, 4 or 5: exact */
    return s * (int64_t)scale;
}

/* Half width at half height on one side of the smoothed peak at zp
   (height a), Q16 bins, interpolated linearly between the last bin above
   half height and the first at or below it; 0 if the histogram ends
   first. */
static uint32_t half_width(const int32_t *r, uint32_t bins, uint32_t zp, int64_t a, int32_t dir)
{
    uint32_t z = zp;
    int64_t sz = a;
    bool found = false;
    uint32_t width = 0u;
    while (!found && !((dir < 0 && z == 0u) || (dir > 0 && z + 1u >= bins))) {
        const uint32_t next = dir < 0 ? z - 1u : z + 1u;
        const int64_t sn = smooth(r, bins, next);
        if (2 * sn <= a) {
            /* 2 s(z) > a >= 2 s(next): the crossing is frac of the way */
            const int64_t above = (2 * sz) - a;       /* > 0, < 2^23 */
            const int64_t drop = 2 * (sz - sn);       /* >= above */
            const uint32_t dist = dir < 0 ? zp - z : z - zp;
            width = (dist << 16) +
                    (uint32_t)ssda__mix_ratio((uint64_t)above, 16u, (uint64_t)drop); /* <= 2^16 */
            found = true;
        }
        z = next;
        sz = sn;
    }
    return width;
}

/* Subtract a exp(-q) from the residual over every bin. */
static void subtract(int32_t *r, uint32_t bins, const ssda__mix_gauss_t *g, int32_t a)
{
    uint32_t z;
    for (z = 0u; z < bins; z++) {
        const uint64_t v = (uint64_t)(uint32_t)a * ssda__exp_neg_q16(ssda__mix_q(g, z)); /* < 2^46 */
        r[z] -= (int32_t)((v + ((uint64_t)1u << 29)) >> 30);
    }
}

/* Whether bin z is taken by one of the starts found[0..nfound) too narrow
   for the 5-bin mean that measures it: FWHM at most 6 bins (the mean's
   own 5 and one, sigma <= 2.55 bins), and z within 2 bins of its mean (a
   bin), so that z's 5-bin mean holds that start's bin. The height of such
   a start falls short of its peak (a saturation spike in one bin: a fifth
   of it), so that most of the peak stays in the residual; without this
   the next starts land on it again, at the same mean and sigma, which EM
   cannot pull apart. A wider start is measured and subtracted whole: what
   remains where it was is of another width (a narrower top, a base), a
   component EM can separate, and may take a start there. */
static bool taken(const ssda__mix_param_t *found, uint32_t nfound, uint32_t z)
{
    const uint32_t zq = z << 16; /* z < 4096: < 2^28 */
    uint32_t j;
    bool near = false;
    for (j = 0u; j < nfound && !near; j++) {
        const uint32_t m = found[j].mean_q16;
        const uint32_t d = zq > m ? zq - m : m - zq;
        near = found[j].sigma_q16 <= 6u * INV_FWHM_Q16 && d <= (2u << 16);
    }
    return near;
}

/* One peak of the residual, found and measured on the smoothed residual,
   away from the starts already found (found[0..nfound), see taken): its
   parameters into found[nfound], height into *height. false if no such
   height is positive. */
static bool peel(int32_t *r, uint32_t bins, uint32_t sigma_min_q16, ssda__mix_param_t *found,
                 uint32_t nfound, int32_t *height)
{
    ssda__mix_param_t *p = &found[nfound];
    ssda__mix_gauss_t g;
    uint32_t z, zp = 0u, wl, wr, fwhm;
    uint64_t sigma;
    int64_t top = 0;
    int32_t a;
    for (z = 0u; z < bins; z++) {
        const int64_t sz = smooth(r, bins, z);
        if (sz > top && !taken(found, nfound, z)) {
            top = sz;
            zp = z;
        }
    }
    a = (int32_t)(top / 60); /* the mean height around the peak */
    if (a <= 0) {
        return false;
    }
    wl = half_width(r, bins, zp, top, -1);
    wr = half_width(r, bins, zp, top, 1);
    if (wl == 0u && wr == 0u) {
        fwhm = bins << 16; /* flat to both ends */
    } else if (wl == 0u || wr == 0u) {
        fwhm = 2u * (wl + wr); /* one side only */
    } else {
        fwhm = wl + wr;
    }
    /* fwhm <= 2 bins 2^16: sigma <= 0.85 bins */
    sigma = ((uint64_t)fwhm * INV_FWHM_Q16) >> 16;
    if (sigma < sigma_min_q16) {
        sigma = sigma_min_q16;
    }
    p->mean_q16 = zp << 16;
    p->sigma_q16 = (uint32_t)sigma;
    p->n = (uint64_t)(uint32_t)a * sigma; /* area ~ height x sigma, < 2^45 */
    *height = a;
    ssda__mix_prepare(&g, 1u, 1u, p->mean_q16, p->sigma_q16);
    subtract(r, bins, &g, a);
    return true;
}

/* Slices of equal count: per slice the share, mean and deviation. */
static void quantiles(const uint32_t *hist, uint32_t bins, uint32_t total, uint32_t k,
                      uint32_t sigma_min_q16, ssda__mix_param_t *p)
{
    uint64_t n[SSDA__MIX_K], s1[SSDA__MIX_K], s2[SSDA__MIX_K];
    uint64_t cum = 0u;
    uint32_t z, j, last = 0u;
    for (j = 0u; j < SSDA__MIX_K; j++) {
        n[j] = 0u;
        s1[j] = 0u;
        s2[j] = 0u;
    }
    for (z = 0u; z < bins; z++) {
        const uint32_t h = hist[z];
        if (h != 0u) {
            /* the slice of the bin's middle count: cum + h <= total and
               h >= 1 give cum + h/2 < total, so j < k */
            const uint32_t half = h >> 1;
            const uint64_t middle = cum + half;
            j = SSDA_DIV64_32((uint64_t)k * middle, total);
            n[j] += h;
            s1[j] += (uint64_t)h * z;             /* < 2^44 */
            s2[j] += (uint64_t)h * ((uint64_t)z * z); /* < 2^56 */
            cum += h;
            last = z;
        }
    }
    for (j = 0u; j < k; j++) {
        if (n[j] == 0u) {
            /* an empty slice (fewer occupied bins than components) */
            p[j].n = 1u;
            p[j].mean_q16 = last << 16;
            p[j].sigma_q16 = sigma_min_q16;
        } else {
            const uint64_t mean = ssda__mix_ratio(s1[j], 16u, n[j]); /* Q16 */
            const uint64_t e2 = ssda__mix_ratio(s2[j], 32u, n[j]);   /* Q32 */
            const uint64_t m2 = mean * mean;
            uint64_t sd = e2 > m2 ? ssda__isqrt64(e2 - m2) : 0u;
            sd = sd < sigma_min_q16 ? sigma_min_q16 : sd;
            p[j].n = n[j] << 8;
            p[j].mean_q16 = (uint32_t)mean;
            p[j].sigma_q16 = (uint32_t)sd;
            last = (uint32_t)(mean >> 16);
        }
    }
}

/* Heights of the quantile start (for the search): share total / (sigma
   sqrt(2 pi)) in Q8 of the scaled histogram. */
static void heights(uint32_t total, uint32_t hs, uint32_t k, ssda__mix_work_t *w)
{
    uint64_t sum = 0u;
    uint32_t j;
    for (j = 0u; j < k; j++) {
        sum += w->p[j].n;
    }
    for (j = 0u; j < k; j++) {
        /* n total 2^8 / (sum sigma sqrt(2 pi)) with sigma in Q16: the
           height in Q8 is n total 2^24 / (sum sigma_q16 2.5066) */
        const uint64_t num = ssda__mix_ratio(w->p[j].n, 8u, sum) * (total >> hs); /* < 2^40 */
        const uint64_t h = ssda__mix_ratio(num, 16u, ((uint64_t)w->p[j].sigma_q16 * 164274u) >> 16);
        /* within the search's range 1..2^25 */
        w->height_q8[j] = h > 33554432u ? 33554432 : h == 0u ? 1 : (int32_t)h;
    }
}

void ssda__mix_init(const uint32_t *hist, uint32_t bins, uint32_t total, uint32_t hs,
                    const ssda__mix_cfg_t *c, uint32_t k, ssda__mix_work_t *w)
{
    bool ok = c->init == (uint32_t)SSDA_MIX_INIT_PEAKS;
    if (ok) {
        uint32_t z, j;
        for (z = 0u; z < bins; z++) {
            const uint32_t v = hist[z] >> hs; /* < 2^16 */
            w->cache[z] = (int32_t)v;
        }
        for (j = 0u; j < k && ok; j++) {
            int32_t a = 0;
            ok = peel(w->cache, bins, c->sigma_min_q16, w->p, j, &a);
            w->height_q8[j] = a * 256;
        }
    }
    if (!ok) {
        quantiles(hist, bins, total, k, c->sigma_min_q16, w->p);
        heights(total, hs, k, w);
    }
}
