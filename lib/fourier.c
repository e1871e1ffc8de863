/* fourier.c - Granlund descriptors of a resampled contour (fourier.h, the
   seed's eq. 3), and the fixed-point ratios the matching shares. */
#include "fourier_internal.h"
#include "fixmath.h"
#include "fixtrig.h"
#include "loops_internal.h"

#include <string.h>

#define COORD_LIMIT 16777216 /* 2^24 */

static bool pow2_samples(uint32_t n, uint32_t *log2n)
{
    const uint32_t l = ssda__samples_log2(n);
    *log2n = l;
    return l != 0u;
}

/* a_k for k = +-n: (1/N) sum u_j exp(-2 pi i k j / N), Q8 px. */
static ssda_fd_coef_t coefficient(const ssda_point_q8_t *p, uint32_t log2n, int32_t k)
{
    const uint32_t n = 1u << log2n;
    int64_t re = 0, im = 0; /* |.| < 2^24 * 2^15 * 2^10 * 2 = 2^50 */
    ssda_fd_coef_t c;
    uint32_t j;
    for (j = 0u; j < n; j++) {
        /* angle 2 pi k j / N in turns: (k j mod N) 2^(32 - log2 N), exactly */
        const uint32_t turn = ((uint32_t)k * j) << (32u - log2n);
        const int64_t cs = ssda__cos_q15(turn), sn = ssda__sin_q15(turn);
        const int64_t x = p[j].x_q8, y = p[j].y_q8;
        /* (x + i y)(cos - i sin) */
        re += x * cs + y * sn;
        im += y * cs - x * sn;
    }
    c.re_q8 = (int32_t)ssda__rshr64(re, log2n + 15u);
    c.im_q8 = (int32_t)ssda__rshr64(im, log2n + 15u);
    return c;
}

static uint64_t norm2(const ssda_fd_coef_t *c)
{
    const int64_t r = (int64_t)c->re_q8 * c->re_q8; /* < 2^48 */
    const int64_t i = (int64_t)c->im_q8 * c->im_q8;
    return (uint64_t)r + (uint64_t)i;
}

int ssda_fd_compute(const ssda_point_q8_t *points, uint32_t n, uint32_t order, ssda_fd_t *fd)
{
    const uint32_t m = order != 0u ? order : SSDA_FD_DEFAULT_ORDER;
    ssda_fd_t out;
    uint32_t log2n = 0u, k;
    if (points == NULL || fd == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!pow2_samples(n, &log2n) || m > SSDA_FD_MAX_ORDER || 2u * m >= n) {
        return SSDA_ERR_ARG;
    }
    for (k = 0u; k < n; k++) {
        if (points[k].x_q8 <= -COORD_LIMIT || points[k].x_q8 >= COORD_LIMIT ||
            points[k].y_q8 <= -COORD_LIMIT || points[k].y_q8 >= COORD_LIMIT) {
            return SSDA_ERR_ARG;
        }
    }
    (void)memset(&out, 0, sizeof out);
    out.order = m;
    for (k = 1u; k <= m; k++) {
        out.pos[k - 1u] = coefficient(points, log2n, (int32_t)k);
        out.neg[k - 1u] = coefficient(points, log2n, -(int32_t)k);
        /* |a_k|^2 < 2^49 each, 32 of them */
        out.energy_q16 += norm2(&out.pos[k - 1u]) + norm2(&out.neg[k - 1u]);
    }
    *fd = out;
    return SSDA_OK;
}

uint32_t ssda__ratio_q16(uint64_t num, int32_t exp2, uint64_t den)
{
    const uint32_t dl = ssda__bitlen64(den);
    int32_t e = exp2 + 16;
    uint64_t d = den, nm = num;
    uint32_t nl;
    if (num == 0u) {
        return 0u;
    }
    if (dl > 32u) { /* num / den = num / (d 2^k) */
        const uint32_t k = dl - 32u;
        d = den >> k;
        e -= (int32_t)k;
    }
    nl = ssda__bitlen64(nm);
    if (e >= 0) {
        /* nm 2^e / d >= 2^32 whenever nm 2^e >= 2^(bitlen(d) + 32) */
        if ((int32_t)nl + e > (int32_t)ssda__bitlen64(d) + 32) {
            return 0xFFFFFFFFu;
        }
        const uint32_t k = (uint32_t)e;
        nm <<= k; /* < 2^64: nl + e <= 64 */
    } else if (e <= -64) {
        nm = 0u;
    } else {
        const uint32_t k = (uint32_t)(-e);
        nm >>= k;
    }
    /* the test above leaves quotients in [2^32, 2^33) (nl + e = bitlen(d)
       + 32): nm / d >= 2^32 exactly when nm >= d 2^32 */
    if ((nm >> 32) >= d) {
        return 0xFFFFFFFFu;
    }
    return SSDA_DIV64_32(nm, (uint32_t)d);
}

uint32_t ssda__mulshr_sat(uint32_t a, uint32_t b, uint32_t s)
{
    const uint64_t p = ((uint64_t)a * b) >> s;
    return p > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)p;
}

uint32_t ssda__fd_abs(const ssda_fd_coef_t *c)
{
    return ssda__isqrt64(norm2(c));
}

/* sum |a_n| |b_n| over both orders' signs: < 32 * 2^25 * 2^25 */
static uint64_t abs_products(const ssda_fd_t *a, const ssda_fd_t *b)
{
    uint64_t sum = 0u;
    uint32_t k;
    for (k = 0u; k < a->order; k++) {
        sum += (uint64_t)ssda__fd_abs(&a->pos[k]) * ssda__fd_abs(&b->pos[k]);
        sum += (uint64_t)ssda__fd_abs(&a->neg[k]) * ssda__fd_abs(&b->neg[k]);
    }
    return sum;
}

uint32_t ssda__fd_fixed_bound(const ssda_fd_t *a, const ssda_fd_t *b, uint32_t s_q16)
{
    /* E^2 = 1 + s^2 A / B - 2 s Re(...) / B >= 1 + s^2 A / B - 2 s sum / B:
       the first ratio rounded down, the second up, then 4 LSB off */
    const uint32_t ab = ssda__ratio_q16(a->energy_q16, 0, b->energy_q16);
    const uint64_t t1 = ((uint64_t)ssda__mulshr_sat(s_q16, s_q16, 16u) * ab) >> 16;
    uint64_t t2, e;
    uint32_t sb;
    if (t1 > 0xFFFFFFFFu) {
        return 0xFFFFFFFFu; /* E^2 >= (sqrt(t1) - 1)^2, as ssda_fd_match_fixed */
    }
    sb = ssda__ratio_q16(abs_products(a, b), 0, b->energy_q16);
    {
        const uint64_t s2 = (uint64_t)s_q16 * 2u;
        t2 = ((s2 * ((uint64_t)sb + 1u)) >> 16) + 1u; /* < 2^25 * 2^32 */
    }
    e = 65536u + t1;
    e = e > t2 + 4u ? e - t2 - 4u : 0u;
    return e > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)e;
}

uint32_t ssda__fd_e2_bound(const ssda_fd_t *a, const ssda_fd_t *b)
{
    const uint64_t sum = abs_products(a, b);
    uint32_t r1, r2, q;
    /* E^2 >= 1 - sum^2 / (A B) = 1 - (sum / A)(sum / B); each ratio and
       the product rounded up, so the bound stays below the true one */
    r1 = ssda__ratio_q16(sum, 0, a->energy_q16);
    r2 = ssda__ratio_q16(sum, 0, b->energy_q16);
    r1 = r1 < 0xFFFFFFFFu ? r1 + 1u : r1;
    r2 = r2 < 0xFFFFFFFFu ? r2 + 1u : r2;
    q = ssda__mulshr_sat(r1, r2, 16u);
    return q >= 65535u ? 0u : 65535u - q;
}
