/*
 * relax_median.c - the normalised median test with replacement
 * (Westerweel & Scarano 2005; definitions in ssda/relax.h): the baseline
 * the relaxation labelling is measured against.
 */
#include <string.h>

#include "relax_internal.h"

#define DEFAULT_THRESHOLD_Q8 512u /* 2.0 */
#define DEFAULT_EPS_Q8 26u        /* 0.1 px */

/* Median of v[0 .. n-1] (1 <= n <= 8), sorted in place; of an even count the
   mean of the two middle values, rounded toward minus infinity. */
static int32_t median(int32_t *v, uint32_t n)
{
    uint32_t i, j;
    int64_t s, q;
    for (i = 1u; i < n; i++) {
        const int32_t t = v[i];
        for (j = i; j > 0u && v[j - 1u] > t; j--) {
            v[j] = v[j - 1u];
        }
        v[j] = t;
    }
    if ((n & 1u) != 0u) {
        return v[n / 2u];
    }
    s = (int64_t)v[n / 2u - 1u] + v[n / 2u];
    q = s / 2;
    return (int32_t)((s < 0 && q * 2 != s) ? q - 1 : q);
}

/* Is component u0 an outlier against its neighbours' values u[0 .. n-1]?
   (u is reordered.) *um receives their median. */
static bool outlier(int32_t u0, int32_t *u, uint32_t n, uint32_t thr_q8, uint32_t eps_q8,
                    int32_t *um)
{
    int32_t r[8];
    uint32_t i;
    int64_t d;
    *um = median(u, n);
    for (i = 0u; i < n; i++) {
        d = (int64_t)u[i] - *um;
        r[i] = (int32_t)(d < 0 ? -d : d); /* <= 2^24 */
    }
    d = (int64_t)u0 - *um;
    d = d < 0 ? -d : d;
    /* |u0 - u_m| / (r_m + eps) > thr, all Q8: d 2^8 > thr (r_m + eps) */
    return (uint64_t)d * 256u > (uint64_t)thr_q8 * ((uint64_t)(uint32_t)median(r, n) + eps_q8);
}

/* Both components tested: an outlier if either is. */
static bool test_vector(const ssda_relax_vector_t *v, int32_t *xs, int32_t *ys, uint32_t n,
                        uint32_t thr, uint32_t eps, int32_t *mx, int32_t *my)
{
    const bool ox = outlier(v->dx_q8, xs, n, thr, eps, mx);
    const bool oy = outlier(v->dy_q8, ys, n, thr, eps, my);
    return ox || oy;
}

int ssda_relax_median(const ssda_relax_grid_t *grid, const ssda_relax_median_config_t *cfg,
                      ssda_relax_vector_t *out, size_t out_count)
{
    ssda__relax_t g;
    uint32_t thr = DEFAULT_THRESHOLD_Q8, eps = DEFAULT_EPS_Q8, i, j;
    int err = ssda__relax_open(grid, out, out_count, &g);
    if (err != SSDA_OK) {
        return err;
    }
    if (cfg != NULL) {
        thr = cfg->threshold_q8 != 0u ? cfg->threshold_q8 : thr;
        eps = cfg->eps_q8 != 0u ? cfg->eps_q8 : eps;
    }
    for (j = 0u; j < g.rows; j++) {
        for (i = 0u; i < g.cols; i++) {
            const size_t k = (size_t)j * g.cols + i;
            ssda_relax_vector_t v;
            (void)memset(&v, 0, sizeof v);
            if (ssda__relax_get(&g, k, &v.dx_q8, &v.dy_q8)) {
                int32_t xs[8], ys[8], mx, my;
                uint32_t n = 0u;
                int32_t di, dj;
                v.flags = SSDA_RELAX_VALID;
                for (dj = -1; dj <= 1; dj++) {
                    for (di = -1; di <= 1; di++) {
                        const int32_t x = (int32_t)i + di, y = (int32_t)j + dj;
                        if ((di != 0 || dj != 0) && x >= 0 && y >= 0 &&
                            x < (int32_t)g.cols && y < (int32_t)g.rows &&
                            ssda__relax_get(&g, (size_t)y * g.cols + (uint32_t)x, &xs[n], &ys[n])) {
                            n++;
                        }
                    }
                }
                if (n >= 3u && test_vector(&v, xs, ys, n, thr, eps, &mx, &my)) {
                    v.dx_q8 = mx;
                    v.dy_q8 = my;
                    v.flags |= SSDA_RELAX_CHANGED;
                }
            }
            out[k] = v;
        }
    }
    return SSDA_OK;
}
