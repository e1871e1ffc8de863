/* fourier_match.c - the seed's matching of two descriptor sets (eqs. 7-12,
   fourier.h): Z(alpha) = sum conj(b_n) a_n exp(i n alpha), its maxima over
   alpha, and s, phi and E^2 from them. */
#include "fourier_internal.h"
#include "fixmath.h"
#include "fixtrig.h"

#define TERMS (2u * SSDA_FD_MAX_ORDER)
#define GRID_LOG2 7u                     /* 128 grid points over a turn */
#define GRID (1u << GRID_LOG2)
#define CELL 0x02000000u                 /* one grid step, turns: 2^(32 - 7) */
#define BISECTIONS 20u
#define PEAKS 3u
#define C_BITS 27u                       /* |c_n| components below 2^27 */

/* The terms c_k exp(i k alpha), k = +-1..+-M, with c_k scaled by 2^-shift. */
typedef struct {
    int32_t re[TERMS], im[TERMS];
    int32_t k[TERMS];
    uint32_t count;
    uint32_t shift;  /* c_true = c 2^shift (Q16 px^2) */
} zpoly_t;

/* Z and W = sum k c_k exp(i k alpha) at one alpha: |Z| < 2^48, |W| < 2^52. */
typedef struct {
    int64_t zr, zi, wr, wi;
} zval_t;

static void zpoly_build(const ssda_fd_t *a, const ssda_fd_t *b, zpoly_t *p)
{
    int64_t cr[TERMS], ci[TERMS];
    uint64_t big = 0u;
    uint32_t n, j, len;
    for (n = 0u; n < a->order; n++) {
        for (j = 0u; j < 2u; j++) {
            const uint32_t t = 2u * n + j;
            const ssda_fd_coef_t *ca = (j == 0u) ? &a->pos[n] : &a->neg[n];
            const ssda_fd_coef_t *cb = (j == 0u) ? &b->pos[n] : &b->neg[n];
            const int64_t ar = ca->re_q8, ai = ca->im_q8;
            const int64_t br = cb->re_q8, bi = cb->im_q8;
            /* conj(b) a = (br ar + bi ai) + i (br ai - bi ar): |.| < 2^49 */
            cr[t] = br * ar + bi * ai;
            ci[t] = br * ai - bi * ar;
            p->k[t] = j == 0u ? (int32_t)n + 1 : -((int32_t)n + 1);
            big = ssda__abs64(cr[t]) > big ? ssda__abs64(cr[t]) : big;
            big = ssda__abs64(ci[t]) > big ? ssda__abs64(ci[t]) : big;
        }
    }
    p->count = 2u * a->order;
    len = ssda__bitlen64(big);
    p->shift = len > C_BITS ? len - C_BITS : 0u;
    for (j = 0u; j < p->count; j++) {
        p->re[j] = (int32_t)ssda__asr64(cr[j], p->shift);
        p->im[j] = (int32_t)ssda__asr64(ci[j], p->shift);
    }
}

static zval_t zpoly_eval(const zpoly_t *p, uint32_t alpha)
{
    zval_t v = {0, 0, 0, 0};
    uint32_t j;
    for (j = 0u; j < p->count; j++) {
        const uint32_t turn = (uint32_t)p->k[j] * alpha; /* k alpha mod one turn */
        const int64_t cs = ssda__cos_q15(turn), sn = ssda__sin_q15(turn);
        const int64_t r = p->re[j] * cs - p->im[j] * sn; /* < 2^43 */
        const int64_t i = p->re[j] * sn + p->im[j] * cs;
        v.zr += r;
        v.zi += i;
        v.wr += r * p->k[j];
        v.wi += i * p->k[j];
    }
    return v;
}

/* |Z|^2 scaled: (Z / 2^18)^2, < 2^61. */
static uint64_t power(const zval_t *v)
{
    const int64_t r = ssda__asr64(v->zr, 18u), i = ssda__asr64(v->zi, 18u);
    const int64_t r2 = r * r, i2 = i * i;
    return (uint64_t)r2 + (uint64_t)i2;
}

/* Sign of d|Z|^2 / d alpha = 2 (Zi Wr - Zr Wi): > 0 while |Z| grows. */
static bool rising_power(const zval_t *v)
{
    const int64_t zr = ssda__asr64(v->zr, 18u), zi = ssda__asr64(v->zi, 18u);
    const int64_t wr = ssda__asr64(v->wr, 22u), wi = ssda__asr64(v->wi, 22u);
    return zi * wr - zr * wi > 0; /* each product < 2^60 */
}

/* Sign of d Re(Z) / d alpha = -Wi (the fixed match rotates c first). */
static bool rising_real(const zval_t *v)
{
    return v->wi < 0;
}

/* Score of alpha: |Z|^2 (free) or Re Z (fixed, offset to stay unsigned). */
static uint64_t score(const zpoly_t *p, uint32_t alpha, bool fixed)
{
    const zval_t v = zpoly_eval(p, alpha);
    if (fixed) {
        const int64_t lifted = v.zr + 4611686018427387904LL; /* + 2^62: |Z| < 2^48 */
        return (uint64_t)lifted;
    }
    return power(&v);
}

/* Refine a grid maximum at cell j by bisection of the derivative's sign in
   [alpha_(j-1), alpha_(j+1)]; the grid point if that interval does not
   bracket a sign change from rising to falling. */
static uint32_t refine(const zpoly_t *p, uint32_t j, bool fixed)
{
    uint32_t lo = (j - 1u) * CELL, width = 2u * CELL, i;
    zval_t vl = zpoly_eval(p, lo), vh = zpoly_eval(p, lo + width);
    const bool rl = fixed ? rising_real(&vl) : rising_power(&vl);
    const bool rh = fixed ? rising_real(&vh) : rising_power(&vh);
    if (!rl || rh) {
        return j * CELL;
    }
    for (i = 0u; i < BISECTIONS; i++) {
        const zval_t vm = zpoly_eval(p, lo + width / 2u);
        width /= 2u;
        if (fixed ? rising_real(&vm) : rising_power(&vm)) {
            lo += width;
        }
    }
    return lo + width / 2u;
}

/* Scores at the GRID points alpha_j = j / GRID turn: there k alpha_j is a
   whole number of grid steps, so exp(i k alpha_j) comes from one table of
   GRID entries (no interpolation, no per-term cos/sin). */
static void grid_scores(const zpoly_t *p, bool fixed, uint64_t *g)
{
    int32_t tc[GRID], ts[GRID];
    uint32_t j, t;
    for (j = 0u; j < GRID; j++) {
        tc[j] = ssda__cos_q15(j * CELL);
        ts[j] = ssda__sin_q15(j * CELL);
    }
    for (j = 0u; j < GRID; j++) {
        zval_t v = {0, 0, 0, 0};
        for (t = 0u; t < p->count; t++) {
            const uint32_t m = ((uint32_t)p->k[t] * j) & (GRID - 1u);
            v.zr += (int64_t)p->re[t] * tc[m] - (int64_t)p->im[t] * ts[m];
            v.zi += (int64_t)p->re[t] * ts[m] + (int64_t)p->im[t] * tc[m];
        }
        if (fixed) {
            const int64_t lifted = v.zr + 4611686018427387904LL; /* + 2^62: |Z| < 2^48 */
            g[j] = (uint64_t)lifted;
        } else {
            g[j] = power(&v);
        }
    }
}

/* The alpha maximising the score: grid scan, the PEAKS best local maxima
   refined, the best refined kept (ties: the smaller alpha). */
static uint32_t best_alpha(const zpoly_t *p, bool fixed)
{
    uint64_t g[GRID];
    uint32_t peak[PEAKS], npeak = 0u, j, i, best_alpha = 0u;
    uint64_t best = 0u;
    grid_scores(p, fixed, g);
    for (j = 0u; j < GRID; j++) { /* local maxima, kept best first */
        const uint64_t prev = g[(j + GRID - 1u) & (GRID - 1u)], next = g[(j + 1u) & (GRID - 1u)];
        if (g[j] >= prev && g[j] > next) {
            uint32_t at = npeak < PEAKS ? npeak : PEAKS;
            while (at > 0u && g[peak[at - 1u]] < g[j]) {
                at--;
            }
            if (at < PEAKS) {
                for (i = (npeak < PEAKS ? npeak : PEAKS - 1u); i > at; i--) {
                    peak[i] = peak[i - 1u];
                }
                peak[at] = j;
                npeak = npeak < PEAKS ? npeak + 1u : PEAKS;
            }
        }
    }
    if (npeak == 0u) { /* a flat score (a circle): any alpha */
        return 0u;
    }
    for (i = 0u; i < npeak; i++) {
        const uint32_t al = refine(p, peak[i], fixed);
        const uint64_t sc = score(p, al, fixed);
        if (i == 0u || sc > best || (sc == best && al < best_alpha)) {
            best = sc;
            best_alpha = al;
        }
    }
    return best_alpha;
}

/* |Z| of a value, scaled like Z (isqrt after narrowing to 31 bits). */
static uint64_t magnitude(const zval_t *v, int32_t *exp2)
{
    const uint64_t m = ssda__abs64(v->zr) > ssda__abs64(v->zi) ? ssda__abs64(v->zr)
                                                              : ssda__abs64(v->zi);
    const uint32_t len = ssda__bitlen64(m);
    const uint32_t t = len > 31u ? len - 31u : 0u;
    const int64_t r = ssda__asr64(v->zr, t), i = ssda__asr64(v->zi, t);
    *exp2 = (int32_t)t;
    const int64_t r2 = r * r, i2 = i * i; /* < 2^62 each */
    return ssda__isqrt64((uint64_t)r2 + (uint64_t)i2);
}

static int check(const ssda_fd_t *a, const ssda_fd_t *b, const ssda_fd_match_t *m)
{
    if (a == NULL || b == NULL || m == NULL) {
        return SSDA_ERR_NULL;
    }
    if (a->order != b->order || a->order == 0u || a->order > SSDA_FD_MAX_ORDER ||
        a->energy_q16 == 0u || b->energy_q16 == 0u) {
        return SSDA_ERR_ARG;
    }
    return SSDA_OK;
}

int ssda_fd_match(const ssda_fd_t *a, const ssda_fd_t *b, ssda_fd_match_t *m)
{
    zpoly_t p;
    zval_t v;
    uint32_t alpha, s, r2, q;
    int32_t e;
    uint64_t mag;
    const int err = check(a, b, m);
    if (err != SSDA_OK) {
        return err;
    }
    zpoly_build(a, b, &p);
    alpha = best_alpha(&p, false);
    v = zpoly_eval(&p, alpha);
    mag = magnitude(&v, &e);
    /* |Z_true| = mag 2^(e + shift - 15) in Q16 px^2; s = |Z| / A (eq. 9) */
    s = ssda__ratio_q16(mag, e + (int32_t)p.shift - 15, a->energy_q16);
    r2 = ssda__ratio_q16(mag, e + (int32_t)p.shift - 15, b->energy_q16);
    q = ssda__mulshr_sat(s, r2, 16u); /* |Z|^2 / (A B), Q16 */
    m->s_q16 = s;
    m->phi = (uint32_t)0u - ssda__atan2(v.zi, v.zr); /* -arg Z (eq. 10) */
    m->alpha = alpha;
    m->e2_q16 = q >= 65536u ? 0u : 65536u - q;
    return SSDA_OK;
}

int ssda_fd_match_fixed(const ssda_fd_t *a, const ssda_fd_t *b, uint32_t s_q16, uint32_t phi,
                        ssda_fd_match_t *m)
{
    zpoly_t p;
    zval_t v;
    uint32_t alpha, j, t1, t2;
    uint64_t e2;
    const int32_t cs = ssda__cos_q15(phi), sn = ssda__sin_q15(phi);
    const int err = check(a, b, m);
    if (err != SSDA_OK) {
        return err;
    }
    if (s_q16 == 0u || s_q16 > (1u << 24)) {
        return SSDA_ERR_ARG;
    }
    zpoly_build(a, b, &p);
    for (j = 0u; j < p.count; j++) { /* c exp(i phi): Re of the sum is the cross term */
        const int64_t r = (int64_t)p.re[j] * cs - (int64_t)p.im[j] * sn;
        const int64_t i = (int64_t)p.re[j] * sn + (int64_t)p.im[j] * cs;
        p.re[j] = (int32_t)ssda__asr64(r, 15u); /* |.| < 2^27.5 */
        p.im[j] = (int32_t)ssda__asr64(i, 15u);
    }
    alpha = best_alpha(&p, true);
    v = zpoly_eval(&p, alpha);
    /* E^2 = (B + s^2 A - 2 s R) / B with R = Re(exp(i phi) Z) */
    t1 = ssda__mulshr_sat(ssda__mulshr_sat(s_q16, s_q16, 16u),
                          ssda__ratio_q16(a->energy_q16, 0, b->energy_q16), 16u);
    t2 = ssda__mulshr_sat(2u * s_q16,
                          ssda__ratio_q16(ssda__abs64(v.zr), (int32_t)p.shift - 15,
                                          b->energy_q16),
                          16u);
    e2 = 65536u + (uint64_t)t1;
    if (v.zr >= 0) {
        e2 = e2 > t2 ? e2 - t2 : 0u;
    } else {
        e2 += t2;
    }
    m->s_q16 = s_q16;
    m->phi = phi;
    m->alpha = alpha;
    m->e2_q16 = e2 > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)e2;
    return SSDA_OK;
}
