/*
 * poly_fit.c - least-squares fit of a polynomial map with outlier
 * rejection by the leave-one-out statistic r / sqrt(1 - h) (method and
 * bounds in poly.h): exact 128-bit normal equations,
 * fixed-point Cholesky, iterative refinement against the exact sums.
 */
#include <string.h>
#include "poly_internal.h"
#include "fixmath.h"

/* Most pairs a fit takes: keeps every exact sum below 2^127 (bounds at
   each sum below). */
#define FIT_MAX_PAIRS 16384u
/* Largest |displacement coefficient|, Q24: 2^24 px. */
#define FIT_MAX_COEF ((int64_t)1 << 48)
#define FIT_MAX_STEPS 4u
#define TRI(i, j) ((i) * ((i) + 1u) / 2u + (j)) /* packed lower triangle, j <= i */
#define TRI_SIZE (SSDA_POLY_MAX_TERMS * (SSDA_POLY_MAX_TERMS + 1u) / 2u)

/* Exact sums over the used pairs (n <= 2^14, |phi| <= 2^30, |d| < 2^32):
   g <= 2^14 * 2^60 = 2^74, r <= 2^14 * 2^62 = 2^76. */
typedef struct {
    ssda__i128_t g[TRI_SIZE];                /* sum phi_s phi_t, Q60 */
    ssda__i128_t r[2][SSDA_POLY_MAX_TERMS];  /* sum phi_s d, Q38 (x, y) */
    uint32_t count;
} sums_t;

/* The factor and the solution. */
typedef struct {
    int64_t l[TRI_SIZE];                  /* Cholesky factor of the mean sums, Q30 */
    ssda__i128_t c[2][SSDA_POLY_MAX_TERMS];  /* displacement coefficients, Q24 */
    uint32_t cond;
    uint8_t steps;
} solve_t;

static const ssda__i128_t W_ONE = {0u, 1u}; /* hi, lo */

/* floor((p + 2^(n-1)) / 2^n): p rounded to n fewer fraction bits. */
static int64_t round_shift(int64_t p, uint32_t n)
{
    const ssda__i128_t half = ssda__u128_shl(W_ONE, n - 1u);
    return ssda__i128_to64(ssda__w_sar(ssda__w_add(ssda__w_i64(p), half), n));
}

/* Normalised terms of a pair's reference position, Q30. False if it lies
   outside the domain. */
static bool terms_of(const ssda_poly_t *p, const ssda_poly_pair_t *pr, int64_t *phi)
{
    /* |ref - c * 256| <= 2^(k+8) inside; xn = that / 2^(k+8), exact in Q30 */
    const int64_t dx = (int64_t)pr->ref_x_q8 - (int64_t)p->cx * 256;
    const int64_t dy = (int64_t)pr->ref_y_q8 - (int64_t)p->cy * 256;
    const int64_t lim_x = ssda__pow2((uint32_t)p->kx + 8u), lim_y = ssda__pow2((uint32_t)p->ky + 8u);
    int64_t x, y;
    if (dx < -lim_x || dx > lim_x || dy < -lim_y || dy > lim_y) {
        return false;
    }
    x = dx * ssda__pow2(22u - (uint32_t)p->kx);
    y = dy * ssda__pow2(22u - (uint32_t)p->ky);
    phi[0] = ssda__pow2(30u);
    phi[1] = x;
    phi[2] = y;
    /* products of two Q30 values <= 2^60, rounded back to Q30 */
    phi[3] = round_shift(x * x, 30u);
    phi[4] = round_shift(x * y, 30u);
    phi[5] = round_shift(y * y, 30u);
    phi[6] = round_shift(phi[3] * x, 30u);
    phi[7] = round_shift(phi[3] * y, 30u);
    phi[8] = round_shift(x * phi[5], 30u);
    phi[9] = round_shift(phi[5] * y, 30u);
    return true;
}

/* Add or remove a pair in the sums: exact, so removing a pair leaves the
   sums of the others. */
static void sums_update(sums_t *s, const ssda_poly_pair_t *pr, const int64_t *phi, uint32_t m,
                        bool add)
{
    const int64_t d[2] = {(int64_t)pr->mov_x_q8 - pr->ref_x_q8,
                          (int64_t)pr->mov_y_q8 - pr->ref_y_q8}; /* |d| < 2^32 */
    uint32_t i, j, a;
    for (i = 0u; i < m; i++) {
        for (j = 0u; j <= i; j++) {
            const ssda__i128_t v = ssda__w_mul64(phi[i], phi[j]); /* <= 2^60 */
            s->g[TRI(i, j)] = add ? ssda__w_add(s->g[TRI(i, j)], v) : ssda__w_sub(s->g[TRI(i, j)], v);
        }
        for (a = 0u; a < 2u; a++) {
            const ssda__i128_t v = ssda__w_mul64(phi[i], d[a]); /* < 2^62 */
            s->r[a][i] = add ? ssda__w_add(s->r[a][i], v) : ssda__w_sub(s->r[a][i], v);
        }
    }
    s->count = add ? s->count + 1u : s->count - 1u;
}

/* |v| <= 2^e. */
static bool w_small(ssda__i128_t v, uint32_t e)
{
    const ssda__i128_t lim = ssda__u128_shl(W_ONE, e);
    return !ssda__w_lt(lim, v) && !ssda__w_lt(v, ssda__w_neg(lim));
}

/* Cholesky factor of G / count in Q30; SSDA_ERR_SIZE when a pivot^2 is
   below 2^-24 of its diagonal (the terms are nearly dependent). Sums in
   128 bits: |l| <= 2^31 is checked, so each product is below 2^62. */
static int factor(const sums_t *s, uint32_t m, solve_t *out)
{
    const ssda__i128_t n = ssda__w_i64((int64_t)s->count);
    uint64_t pmax = 0u, pmin = UINT64_MAX;
    uint32_t i, j, k;
    for (j = 0u; j < m; j++) {
        /* the mean diagonal (<= 2^60) minus the squares of the row so far:
           the pivot^2 (Schur complement), >= 0 up to rounding */
        const ssda__i128_t diag = ssda__w_div_round(s->g[TRI(j, j)], n);
        ssda__i128_t piv = diag;
        int64_t lj;
        for (k = 0u; k < j; k++) {
            piv = ssda__w_sub(piv, ssda__w_mul64(out->l[TRI(j, k)], out->l[TRI(j, k)]));
        }
        if (ssda__w_neg_p(piv) || !ssda__w_lt(ssda__w_sar(diag, 24u), piv)) {
            return SSDA_ERR_SIZE;
        }
        /* 0 < piv <= diag <= 2^60 */
        lj = (int64_t)ssda__isqrt64(piv.lo);
        out->l[TRI(j, j)] = lj;
        pmax = piv.lo > pmax ? piv.lo : pmax;
        pmin = piv.lo < pmin ? piv.lo : pmin;
        for (i = j + 1u; i < m; i++) {
            ssda__i128_t num = ssda__w_div_round(s->g[TRI(i, j)], n); /* |.| <= 2^60 */
            ssda__i128_t q;
            for (k = 0u; k < j; k++) {
                num = ssda__w_sub(num, ssda__w_mul64(out->l[TRI(i, k)], out->l[TRI(j, k)]));
            }
            q = ssda__w_div_round(num, ssda__w_i64(lj));
            if (!w_small(q, 31u)) { /* true factor: |l_ij| <= sqrt(mean_ii) <= 2^30 */
                return SSDA_ERR_SIZE;
            }
            out->l[TRI(i, j)] = ssda__i128_to64(q);
        }
    }
    {
        const ssda__i128_t q = ssda__w_div_floor(ssda__w_i64((int64_t)pmax), ssda__w_i64((int64_t)pmin));
        out->cond = q.hi != 0u || q.lo > UINT32_MAX ? UINT32_MAX : (uint32_t)q.lo;
    }
    return SSDA_OK;
}

/* Solve (L L^T) x = b: b in Q84 (mean sums scaled by 2^46), x in Q24.
   SSDA_ERR_OVERFLOW when an intermediate leaves its bound (|z| <= 2^90,
   |x| <= 2^48: a map no image pair has). */
static int solve(const int64_t *l, uint32_t m, const ssda__i128_t *b, ssda__i128_t *x)
{
    ssda__i128_t z[SSDA_POLY_MAX_TERMS];
    uint32_t i, k;
    for (i = 0u; i < m; i++) {
        ssda__i128_t acc = b[i]; /* |b| <= 2^124 */
        for (k = 0u; k < i; k++) { /* |l| <= 2^31, |z| <= 2^90: < 2^121 each */
            acc = ssda__w_sub(acc, ssda__w_mul(z[k], l[TRI(i, k)]));
        }
        z[i] = ssda__w_div_round(acc, ssda__w_i64(l[TRI(i, i)])); /* Q54 */
        if (!w_small(z[i], 90u)) {
            return SSDA_ERR_OVERFLOW;
        }
    }
    i = m;
    while (i > 0u) {
        ssda__i128_t acc;
        i--;
        acc = z[i];
        for (k = i + 1u; k < m; k++) { /* |x| <= 2^48: < 2^79 each */
            acc = ssda__w_sub(acc, ssda__w_mul(x[k], l[TRI(k, i)]));
        }
        x[i] = ssda__w_div_round(acc, ssda__w_i64(l[TRI(i, i)]));
        if (!w_small(x[i], 48u)) {
            return SSDA_ERR_OVERFLOW;
        }
    }
    return SSDA_OK;
}

/* Fit the displacement to the sums: a first solve, then refinement
   against the exact residual r * 2^46 - G c (|r| 2^46 <= 2^122,
   |G c| <= 10 * 2^74 * 2^48 < 2^126). */
static int fit_sums(const sums_t *s, uint32_t m, solve_t *out)
{
    const ssda__i128_t n = ssda__w_i64((int64_t)s->count);
    uint32_t a, i, k, step;
    int err = factor(s, m, out);
    if (err != SSDA_OK) {
        return err;
    }
    out->steps = 0u;
    for (a = 0u; a < 2u; a++) {
        ssda__i128_t b[SSDA_POLY_MAX_TERMS], dx[SSDA_POLY_MAX_TERMS];
        for (i = 0u; i < m; i++) {
            out->c[a][i] = ssda__w_i64(0);
        }
        for (step = 0u; step <= FIT_MAX_STEPS; step++) {
            bool moved = false;
            for (i = 0u; i < m; i++) {
                ssda__i128_t e = ssda__u128_shl(s->r[a][i], 46u);
                for (k = 0u; k < m; k++) {
                    const ssda__i128_t g = i >= k ? s->g[TRI(i, k)] : s->g[TRI(k, i)];
                    e = ssda__w_sub(e, ssda__w_mul(g, ssda__i128_to64(out->c[a][k])));
                }
                b[i] = ssda__w_div_round(e, n);
            }
            err = solve(out->l, m, b, dx);
            if (err != SSDA_OK) {
                return err;
            }
            for (i = 0u; i < m; i++) {
                moved = moved || !ssda__w_zero_p(dx[i]);
                out->c[a][i] = ssda__w_add(out->c[a][i], dx[i]);
                if (!w_small(out->c[a][i], 48u)) {
                    return SSDA_ERR_OVERFLOW;
                }
            }
            if (step > out->steps) {
                out->steps = (uint8_t)step; /* refinement steps: the solves after the first */
            }
            if (!moved) {
                break;
            }
        }
    }
    return SSDA_OK;
}

/* Residual of pair pr (terms phi) under the displacement c, px Q24.8,
   saturated; *sq receives its square (Q16, saturated). */
static uint32_t residual_of(const solve_t *sv, uint32_t m, const ssda_poly_pair_t *pr,
                            const int64_t *phi, uint64_t *sq)
{
    const int64_t d[2] = {(int64_t)pr->mov_x_q8 - pr->ref_x_q8,
                          (int64_t)pr->mov_y_q8 - pr->ref_y_q8};
    uint64_t e2 = 0u;
    uint32_t a, t;
    for (a = 0u; a < 2u; a++) {
        ssda__i128_t f = ssda__u128_shl(W_ONE, 45u); /* Q54 -> Q8: + 2^45, floor / 2^46 */
        for (t = 0u; t < m; t++) { /* |phi| <= 2^30, |c| <= 2^48 */
            f = ssda__w_add(f, ssda__w_mul(sv->c[a][t], phi[t]));
        }
        f = ssda__w_sub(ssda__w_sar(f, 46u), ssda__w_i64(d[a]));
        if (!w_small(f, 31u)) {
            *sq = UINT64_MAX;
            return UINT32_MAX;
        }
        {
            const uint64_t e = ssda__w_neg_p(f) ? ssda__w_neg(f).lo : f.lo; /* <= 2^31 */
            e2 += e * e; /* <= 2^63 */
        }
    }
    *sq = e2;
    return ssda__isqrt64(e2);
}

/* Leverage of a pair with terms phi: h = phi^T G^-1 phi for the used
   pairs' sums G, from the factor L of G / count: h = |L^-1 phi|^2 / count,
   Q60 (1 = 2^60). Forward substitution z = L^-1 phi in Q30: exact |z|^2 =
   count h <= count <= 2^14, so |z| <= 2^37; a |z| beyond 2^40 (rounding
   of a factor near singular) returns 2^60 (leverage 1: cannot be judged).
   Bounds: each sum |phi 2^30 - sum l z| <= 2^60 + 9 * 2^31 * 2^40 < 2^75;
   sum z^2 <= 10 * 2^80 < 2^84. */
static ssda__i128_t leverage_of(const solve_t *sv, uint32_t m, uint32_t count, const int64_t *phi)
{
    int64_t z[SSDA_POLY_MAX_TERMS];
    ssda__i128_t q = {0u, 0u}; /* hi, lo */
    uint32_t j, k;
    for (j = 0u; j < m; j++) {
        ssda__i128_t acc = ssda__u128_shl(ssda__w_i64(phi[j]), 30u); /* Q60 */
        ssda__i128_t zj;
        for (k = 0u; k < j; k++) {
            acc = ssda__w_sub(acc, ssda__w_mul64(sv->l[TRI(j, k)], z[k]));
        }
        zj = ssda__w_div_round(acc, ssda__w_i64(sv->l[TRI(j, j)])); /* l_jj >= 1 */
        if (!w_small(zj, 40u)) {
            return ssda__u128_shl(W_ONE, 60u);
        }
        z[j] = ssda__i128_to64(zj);
        q = ssda__w_add(q, ssda__w_mul64(z[j], z[j]));
    }
    return ssda__w_div_round(q, ssda__w_i64((int64_t)count));
}

/* A pair can be judged while 1 - h >= 2^-16 (2^44 in Q60). */
#define FIT_MIN_ONE_MINUS_H_LOG2 44u

/* The verdict on the used pairs under the current fit. */
typedef struct {
    ssda__i128_t stat;  /* largest r^2 / (1 - h), px^2 Q16 (< 2^124 / 2^44 = 2^80) */
    size_t at;          /* its pair (ties: the lowest index) */
    ssda__i128_t lev;   /* largest leverage, Q60 */
} verdict_t;

/* Judge every used pair by r^2 / (1 - h): how much the sum of squared
   residuals falls when the pair is left out (exact identity of least
   squares; r the pair's residual, h its leverage). A pair with 1 - h below
   2^-16 cannot be judged (the map passes through it): statistic 0. */
static void judge_pairs(const ssda_poly_t *p, const ssda_poly_pair_t *pairs, size_t n,
                        const uint8_t *flags, const solve_t *sv, uint32_t m, uint32_t count,
                        verdict_t *v)
{
    const ssda__i128_t one = ssda__u128_shl(W_ONE, 60u);
    const ssda__i128_t floor_1h = ssda__u128_shl(W_ONE, FIT_MIN_ONE_MINUS_H_LOG2);
    size_t k;
    v->stat = ssda__w_i64(-1);
    v->at = 0u;
    v->lev = ssda__w_i64(0);
    for (k = 0u; k < n; k++) {
        int64_t phi[SSDA_POLY_MAX_TERMS];
        uint64_t sq;
        ssda__i128_t h, one_minus, s = {0u, 0u}; /* hi, lo */
        if (flags[k] == 0u) {
            continue;
        }
        (void)terms_of(p, &pairs[k], phi); /* checked when the pair was added */
        (void)residual_of(sv, m, &pairs[k], phi, &sq);
        h = leverage_of(sv, m, count, phi);
        v->lev = ssda__w_lt(v->lev, h) ? h : v->lev;
        one_minus = ssda__w_sub(one, h);
        if (!ssda__w_lt(one_minus, floor_1h)) {
            const ssda__i128_t e2 = {0u, sq}; /* hi, lo; < 2^64 */
            /* < 2^124 / 2^44 */
            s = ssda__w_div_floor(ssda__u128_shl(e2, 60u), one_minus);
        }
        if (ssda__w_lt(v->stat, s)) {
            v->stat = s;
            v->at = k;
        }
    }
}

/* Outputs of a finished fit: coefficients (displacement + identity),
   residuals, flags and the summary. */
static void write_out(const ssda_poly_t *dom, const ssda_poly_pair_t *pairs, size_t n,
                      const uint8_t *flags, const solve_t *sv, uint32_t m, const verdict_t *vd,
                      bool within, uint16_t rejected, ssda_poly_t *poly, uint32_t *residual_q8,
                      uint8_t *used, ssda_poly_fit_result_t *result)
{
    ssda_poly_fit_result_t res;
    ssda__i128_t sum = {0u, 0u}; /* hi, lo; <= n * 2^63 < 2^77 */
    uint32_t t;
    size_t k;
    ssda_poly_t p;
    (void)memset(&res, 0, sizeof res);
    p = *dom;
    for (t = 0u; t < m; t++) {
        p.u_q24[t] = ssda__i128_to64(sv->c[0][t]);
        p.v_q24[t] = ssda__i128_to64(sv->c[1][t]);
    }
    /* x = X + dx: X = cx + 2^kx xn (|c| <= 2^48: no overflow) */
    p.u_q24[0] += (int64_t)p.cx * ssda__pow2(24u);
    p.u_q24[1] += ssda__pow2((uint32_t)p.kx + 24u);
    p.v_q24[0] += (int64_t)p.cy * ssda__pow2(24u);
    p.v_q24[2] += ssda__pow2((uint32_t)p.ky + 24u);
    for (k = 0u; k < n; k++) {
        int64_t phi[SSDA_POLY_MAX_TERMS];
        uint64_t sq;
        uint32_t r;
        (void)terms_of(dom, &pairs[k], phi);
        r = residual_of(sv, m, &pairs[k], phi, &sq);
        if (residual_q8 != NULL) {
            residual_q8[k] = r;
        }
        if (used != NULL) {
            used[k] = flags[k];
        }
        if (flags[k] != 0u) {
            res.used++;
            res.max_q8 = r > res.max_q8 ? r : res.max_q8;
            const ssda__i128_t w = {0u, sq}; /* hi, lo */
            sum = ssda__w_add(sum, w);
        }
    }
    {
        /* the mean of squares of at most 2^63 each: < 2^64 */
        const ssda__i128_t mean = ssda__w_div_round(sum, ssda__w_i64((int64_t)res.used));
        res.rms_q8 = mean.hi != 0u ? UINT32_MAX : ssda__isqrt64(mean.lo);
    }
    res.cond = sv->cond;
    res.rejected = rejected;
    res.refinements = sv->steps;
    res.within_bound = within;
    {
        /* Q60 -> Q15, rounded; a rounded leverage may pass 1 by a few units */
        const ssda__i128_t l15 = ssda__w_sar(ssda__w_add(vd->lev, ssda__u128_shl(W_ONE, 44u)), 45u);
        res.max_leverage_q15 = ssda__w_lt(ssda__w_i64(32768), l15) ? 32768u : (uint16_t)l15.lo;
    }
    res.weak = (uint32_t)res.used < SSDA_POLY_WEAK_PAIRS(m) ||
               res.max_leverage_q15 > SSDA_POLY_WEAK_LEVERAGE_Q15;
    *poly = p;
    if (result != NULL) {
        *result = res;
    }
}

int ssda_poly_fit(const ssda_poly_pair_t *pairs, size_t n, uint16_t ref_w, uint16_t ref_h,
                  const ssda_poly_fit_config_t *cfg, ssda_poly_t *poly,
                  uint32_t *residual_q8, uint8_t *used, ssda_poly_fit_result_t *result,
                  void *work, size_t work_size)
{
    const uint8_t order = cfg != NULL && cfg->order != 0u ? cfg->order : 2u;
    const uint32_t bound = cfg != NULL && cfg->max_residual_q8 != 0u
                               ? cfg->max_residual_q8 : SSDA_POLY_DEFAULT_MAX_RESIDUAL_Q8;
    uint8_t *flags = (uint8_t *)work;
    ssda_poly_t dom;
    sums_t sums;
    solve_t sv;
    verdict_t vd;
    ssda__i128_t b2;
    bool within;
    uint32_t m;
    uint16_t rejected = 0u;
    size_t k;
    int err;
    if (pairs == NULL || poly == NULL || work == NULL) {
        return SSDA_ERR_NULL;
    }
    if (order > SSDA_POLY_MAX_ORDER) {
        return SSDA_ERR_ARG;
    }
    err = ssda_poly_init(&dom, ref_w, ref_h, order);
    if (err != SSDA_OK) {
        return err;
    }
    m = SSDA_POLY_TERMS(order);
    if (n < m || n > FIT_MAX_PAIRS) {
        return SSDA_ERR_SIZE;
    }
    if (work_size < SSDA_POLY_FIT_WORK_SIZE(n)) {
        return SSDA_ERR_BUFFER;
    }
    (void)memset(&sums, 0, sizeof sums);
    (void)memset(&sv, 0, sizeof sv);
    {
        /* no bound: every statistic (< 2^80) is within 2^80 */
        const ssda__i128_t bb = {0u, (uint64_t)bound * bound}; /* hi, lo; < 2^64 */
        b2 = bound == UINT32_MAX ? ssda__u128_shl(W_ONE, 80u) : bb;
    }
    for (k = 0u; k < n; k++) {
        int64_t phi[SSDA_POLY_MAX_TERMS];
        if (!terms_of(&dom, &pairs[k], phi)) {
            return SSDA_ERR_ARG;
        }
        sums_update(&sums, &pairs[k], phi, m, true);
        flags[k] = 1u;
    }
    for (;;) {
        err = fit_sums(&sums, m, &sv);
        if (err != SSDA_OK) {
            return err;
        }
        judge_pairs(&dom, pairs, n, flags, &sv, m, sums.count, &vd);
        /* bound^2 < 2^64 */
        within = !ssda__w_lt(b2, vd.stat);
        if (within || sums.count <= m + 1u) {
            break;
        }
        {
            int64_t phi[SSDA_POLY_MAX_TERMS];
            (void)terms_of(&dom, &pairs[vd.at], phi);
            sums_update(&sums, &pairs[vd.at], phi, m, false);
        }
        flags[vd.at] = 0u;
        rejected++;
    }
    write_out(&dom, pairs, n, flags, &sv, m, &vd, within, rejected, poly, residual_q8, used, result);
    return SSDA_OK;
}
