/* warp_bounds.c - slope and curvature bounds of a map over its grid: how
   many source rows and columns a piece of the output samples. */
#include "warp_internal.h"

#define BOUND_MAX ((int64_t)0x1000000000000000) /* 2^60 */

static uint64_t mag(int64_t v)
{
    return v < 0 ? (uint64_t)0u - (uint64_t)v : (uint64_t)v;
}

/* ceil(a / 2^n) for a >= 0, saturated at BOUND_MAX. */
static int64_t ceil_shift(ssda__i128_t a, uint32_t n)
{
    const ssda__i128_t one = {0u, 1u}; /* hi, lo */
    const ssda__i128_t q = ssda__w_sar(ssda__w_add(a, ssda__w_sub(ssda__u128_shl(one, n), one)), n);
    return q.hi != 0u || q.lo > (uint64_t)BOUND_MAX ? BOUND_MAX : (int64_t)q.lo;
}

int64_t ssda__warp_slope(const ssda_poly_t *p, const int64_t *c, uint32_t axis, uint32_t s)
{
    const uint32_t terms = SSDA_POLY_TERMS(p->order);
    const uint32_t k = axis == 0u ? p->kx : p->ky;
    ssda__i128_t sum = {0u, 0u}; /* hi, lo */
    uint32_t t;
    for (t = 0u; t < terms; t++) {
        const uint32_t e = axis == 0u ? ssda__poly_ex[t] : ssda__poly_ey[t];
        const ssda__i128_t a = {0u, mag(c[t])}; /* hi, lo */
        /* |c| <= 2^63, e * s < 2^18: < 2^81; ten terms < 2^85 */
        sum = ssda__w_add(sum, ssda__w_mul(a, (int64_t)e * (int64_t)s));
    }
    return ceil_shift(sum, k + 16u);
}

int64_t ssda__warp_curve(const ssda_poly_t *p, const int64_t *c, uint32_t sx, uint32_t sy)
{
    const uint32_t terms = SSDA_POLY_TERMS(p->order);
    const int64_t sx2 = (int64_t)sx * (int64_t)sx, sy2 = (int64_t)sy * (int64_t)sy; /* < 2^32 */
    int64_t sum = 0;
    uint32_t t;
    for (t = 0u; t < terms; t++) {
        const int64_t i = (int64_t)ssda__poly_ex[t], j = (int64_t)ssda__poly_ey[t];
        const ssda__i128_t a = {0u, mag(c[t])}; /* hi, lo */
        /* |c| i(i-1) sx^2 <= 2^63 * 6 * 2^32 < 2^98, over 2^(2k + 19):
           2^-24 (Q24) * 2^8 (Q8) / 8; the parts are rounded up apart */
        const int64_t fx = ceil_shift(ssda__w_mul(a, i * (i > 0 ? i - 1 : 0) * sx2), 2u * p->kx + 19u);
        const int64_t fy = ceil_shift(ssda__w_mul(a, j * (j > 0 ? j - 1 : 0) * sy2), 2u * p->ky + 19u);
        sum += fx + fy; /* each <= 2^60, sum <= 3 * 2^60: saturated */
        if (sum > BOUND_MAX) {
            return BOUND_MAX;
        }
    }
    return sum;
}

uint32_t ssda__warp_band(const ssda_poly_t *p, bool bilinear, uint32_t n, uint32_t h)
{
    /* the v range of a segment: its ends differ by at most the slope, and
       the curve strays from their chord by at most the curvature, each way;
       + 2 for the floors of the ends */
    const int64_t q8 = ssda__warp_slope(p, p->v_q24, 0u, n) +
                       2 * ssda__warp_curve(p, p->v_q24, n, 0u) + 2;
    const int64_t rows = q8 / 256 + 2 + (bilinear ? 1 : 0);
    return rows > (int64_t)h ? h : (uint32_t)rows;
}

uint32_t ssda__warp_span(const ssda_poly_t *p, bool bilinear, uint32_t n, uint32_t m, uint32_t w)
{
    const int64_t q8 = ssda__warp_slope(p, p->u_q24, 0u, n) + ssda__warp_slope(p, p->u_q24, 1u, m) +
                       2 * ssda__warp_curve(p, p->u_q24, n, m) + 2;
    const int64_t cols = q8 / 256 + 2 + (bilinear ? 1 : 0);
    return cols > (int64_t)w ? w : (uint32_t)cols;
}
