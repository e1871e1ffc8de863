/* symreg_affine.c - the affine transforms of the symbolic registration:
   eq. 16 (a similarity from one pair), eqs. 14-15 (its scale and
   rotation), eq. 17 (least squares on centroids). */
#include "symreg_internal.h"
#include "fourier_internal.h"
#include "fixmath.h"
#include "fixtrig.h"

#include <string.h>

#define COEF_MAX 0x7FFFFFFF

void ssda__symreg_map(const ssda_symreg_affine_t *t, int32_t x, int32_t y, int64_t *u,
                      int64_t *v)
{
    /* Q16 * Q8 = Q24, each product < 2^55 */
    *u = ssda__rshr64((int64_t)t->a_q16 * x + (int64_t)t->b_q16 * y, 16u) + t->c_q8;
    *v = ssda__rshr64((int64_t)t->d_q16 * x + (int64_t)t->e_q16 * y, 16u) + t->f_q8;
}

static int32_t clamp32(int64_t v)
{
    return v > COEF_MAX ? COEF_MAX : (v < -COEF_MAX ? -COEF_MAX : (int32_t)v);
}

void ssda__symreg_similarity(uint32_t s_q16, uint32_t phi, int32_t rx, int32_t ry, int32_t mx,
                             int32_t my, ssda_symreg_affine_t *t)
{
    const int64_t c = ssda__rshr64((int64_t)s_q16 * ssda__cos_q15(phi), 15u); /* Q16 */
    const int64_t s = ssda__rshr64((int64_t)s_q16 * ssda__sin_q15(phi), 15u);
    int64_t u, v;
    t->a_q16 = clamp32(c);
    t->b_q16 = clamp32(-s);
    t->d_q16 = clamp32(s);
    t->e_q16 = clamp32(c);
    t->c_q8 = 0;
    t->f_q8 = 0;
    ssda__symreg_map(t, rx, ry, &u, &v);
    t->c_q8 = clamp32((int64_t)mx - u);
    t->f_q8 = clamp32((int64_t)my - v);
}

void ssda__symreg_scale_rot(const ssda_symreg_affine_t *t, uint32_t *s_q16, uint32_t *phi)
{
    const int64_t det = (int64_t)t->a_q16 * t->e_q16 - (int64_t)t->b_q16 * t->d_q16; /* Q32 */
    const uint32_t th1 = ssda__atan2(t->d_q16, t->a_q16);               /* x axis */
    const uint32_t th2 = ssda__atan2(t->e_q16, t->b_q16) - 0x40000000u; /* y axis - 90 deg */
    const uint32_t diff = th2 - th1;                                    /* signed, wrapped */
    *s_q16 = ssda__isqrt64(ssda__abs64(det));
    /* eq. 15: the mean of the two angles, halfway along the shorter way */
    *phi = diff < 0x80000000u ? th1 + diff / 2u : th1 - ((0u - diff) / 2u);
}

/* Sums of the centred pair coordinates (eq. 17's matrix after centring). */
typedef struct {
    int64_t xx, xy, yy, xu, yu, xv, yv; /* |.| < 4096 * 2^48 = 2^60 for |offsets| < 2^24 */
    int64_t mx, my, mu, mv;             /* means, Q8 */
    uint32_t n;
} sums_t;

/* sum / n rounded toward zero (no signed division routine) */
static int64_t mean(int64_t sum, uint32_t n)
{
    const uint32_t q = SSDA_DIV64_32(ssda__abs64(sum), n); /* < 2^31 */
    return sum < 0 ? -(int64_t)q : (int64_t)q;
}

static void centred_sums(const ssda_loop_t *ref, const ssda_loop_t *mov,
                         const ssda__partner_t *set, uint32_t n_ref, sums_t *s)
{
    int64_t sx = 0, sy = 0, su = 0, sv = 0; /* |centroids| < 2^31, 4096 of them */
    uint32_t i;
    (void)memset(s, 0, sizeof *s);
    for (i = 0u; i < n_ref; i++) {
        if (set[i].mov != SSDA__NONE) {
            sx += ref[i].cx_q8;
            sy += ref[i].cy_q8;
            su += mov[set[i].mov].cx_q8;
            sv += mov[set[i].mov].cy_q8;
            s->n++;
        }
    }
    if (s->n < 3u) {
        return;
    }
    s->mx = mean(sx, s->n);
    s->my = mean(sy, s->n);
    s->mu = mean(su, s->n);
    s->mv = mean(sv, s->n);
    for (i = 0u; i < n_ref; i++) {
        if (set[i].mov != SSDA__NONE) {
            const ssda_loop_t *m = &mov[set[i].mov];
            const int64_t dx = ref[i].cx_q8 - s->mx, dy = ref[i].cy_q8 - s->my;
            const int64_t du = m->cx_q8 - s->mu, dv = m->cy_q8 - s->mv;
            s->xx += dx * dx;
            s->xy += dx * dy;
            s->yy += dy * dy;
            s->xu += dx * du;
            s->yu += dy * du;
            s->xv += dx * dv;
            s->yv += dy * dv;
        }
    }
}

/* Narrow values by one common shift so that each is below 2^30. */
static uint32_t narrow(int64_t *v, uint32_t n)
{
    uint64_t big = 0u;
    uint32_t i, len, k;
    for (i = 0u; i < n; i++) {
        big = ssda__abs64(v[i]) > big ? ssda__abs64(v[i]) : big;
    }
    len = ssda__bitlen64(big);
    k = len > 30u ? len - 30u : 0u;
    for (i = 0u; i < n; i++) {
        v[i] = ssda__asr64(v[i], k);
    }
    return k;
}

/* num / det 2^exp2 in Q16, with num's sign; false if out of int32. */
static bool quotient(int64_t num, int32_t exp2, int64_t det, int32_t *out)
{
    const uint32_t q = ssda__ratio_q16(ssda__abs64(num), exp2, (uint64_t)det);
    if (q > (uint32_t)COEF_MAX) {
        return false;
    }
    *out = num < 0 ? -(int32_t)q : (int32_t)q;
    return true;
}

bool ssda__symreg_fit(const ssda_loop_t *ref, const ssda_loop_t *mov,
                      const ssda__partner_t *set, uint32_t n_ref, ssda_symreg_affine_t *t)
{
    sums_t s;
    int64_t x[3], m[4], det, u, v;
    int32_t e;
    ssda_symreg_affine_t r;
    centred_sums(ref, mov, set, n_ref, &s);
    if (s.n < 3u) {
        return false;
    }
    x[0] = s.xx;
    x[1] = s.xy;
    x[2] = s.yy;
    m[0] = s.xu;
    m[1] = s.yu;
    m[2] = s.xv;
    m[3] = s.yv;
    e = (int32_t)narrow(m, 4u) - (int32_t)narrow(x, 3u);
    det = x[0] * x[2] - x[1] * x[1]; /* < 2^60 */
    if (det <= 0 || det <= ssda__asr64(x[0] * x[2], 20u)) {
        return false; /* the centroids are (nearly) on one line */
    }
    /* [xx xy; xy yy] [a; b] = [xu; yu] by Cramer's rule, likewise d, e */
    if (!quotient(m[0] * x[2] - m[1] * x[1], e, det, &r.a_q16) ||
        !quotient(x[0] * m[1] - x[1] * m[0], e, det, &r.b_q16) ||
        !quotient(m[2] * x[2] - m[3] * x[1], e, det, &r.d_q16) ||
        !quotient(x[0] * m[3] - x[1] * m[2], e, det, &r.e_q16)) {
        return false;
    }
    r.c_q8 = 0;
    r.f_q8 = 0;
    ssda__symreg_map(&r, (int32_t)s.mx, (int32_t)s.my, &u, &v);
    if (s.mu - u > COEF_MAX || s.mu - u < -COEF_MAX || s.mv - v > COEF_MAX ||
        s.mv - v < -COEF_MAX) {
        return false;
    }
    r.c_q8 = (int32_t)(s.mu - u);
    r.f_q8 = (int32_t)(s.mv - v);
    *t = r;
    return true;
}

uint32_t ssda__symreg_resid(const ssda_symreg_affine_t *t, const ssda_loop_t *r,
                            const ssda_loop_t *m)
{
    int64_t u, v;
    uint64_t du, dv;
    ssda__symreg_map(t, r->cx_q8, r->cy_q8, &u, &v);
    du = ssda__abs64(u - m->cx_q8);
    dv = ssda__abs64(v - m->cy_q8);
    if (du >= 0x80000000u || dv >= 0x80000000u) {
        return 0xFFFFFFFFu;
    }
    return ssda__isqrt64(du * du + dv * dv);
}

int ssda_symreg_apply(const ssda_symreg_affine_t *t, int32_t x_q8, int32_t y_q8, int32_t *u_q8,
                      int32_t *v_q8)
{
    int64_t u, v;
    if (t == NULL || u_q8 == NULL || v_q8 == NULL) {
        return SSDA_ERR_NULL;
    }
    ssda__symreg_map(t, x_q8, y_q8, &u, &v);
    *u_q8 = clamp32(u);
    *v_q8 = clamp32(v);
    return SSDA_OK;
}
