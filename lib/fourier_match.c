/* fourier_match.c - the seed's matching of two descriptor sets (eqs. 7-12,
   fourier.h): Z(alpha) = sum conj(b_n) a_n exp(i n alpha), its maxima over
   alpha, and s, phi and E^2 from them. */
#include "fourier_internal.h"
#include "fixmath.h"
#include "fixtrig.h"

#define GRID_LOG2 7u                     /* 128 grid points over a turn */
#define GRID (1u << GRID_LOG2)
#define CELL 0x02000000u                 /* one grid step, turns: 2^(32 - 7) */
#define BISECTIONS 20u
#define PEAKS 3u
#define C_BITS 27u                       /* |c_n| components below 2^27 */

/* Z(alpha) = sum_k c_k exp(i k alpha), k = +-1..+-M, with c_k scaled by
   2^-shift, held as the orders' sums and differences: with c_k = r+ + i i+
   and c_-k = r- + i i-, P = r+ + r-, Q = i+ - i-, R = r+ - r-, S = i+ + i-.
   Since cos and sin are exactly even and odd (fixtrig.c's mirrored table),
   the terms k and -k at one alpha sum to
     Re: P cos - Q sin,  Im: R sin + S cos  (W: k (R cos - S sin), k (P sin + Q cos)),
   the same integers as summing them apart, with half the products. */
typedef struct {
    int32_t p[SSDA_FD_MAX_ORDER], q[SSDA_FD_MAX_ORDER];
    int32_t r[SSDA_FD_MAX_ORDER], s[SSDA_FD_MAX_ORDER]; /* |.| < 2^28.5 */
    uint32_t order;
    uint32_t shift; /* c_true = c 2^shift (Q16 px^2) */
} zpoly_t;

/* Z and W = sum k c_k exp(i k alpha) at one alpha: |Z| < 2^48, |W| < 2^52. */
typedef struct {
    int64_t zr, zi, wr, wi;
} zval_t;

/* conj(b_n) a_n for one coefficient pair: |.| < 2^49 each. */
static void cross(const ssda_fd_coef_t *ca, const ssda_fd_coef_t *cb, int64_t *re, int64_t *im)
{
    const int64_t ar = ca->re_q8, ai = ca->im_q8;
    const int64_t br = cb->re_q8, bi = cb->im_q8;
    *re = br * ar + bi * ai;
    *im = br * ai - bi * ar;
}

/* The bits of the largest component of every c_n. */
static uint32_t cross_bits(const ssda_fd_t *a, const ssda_fd_t *b)
{
    uint64_t big = 0u;
    uint32_t n;
    for (n = 0u; n < a->order; n++) {
        int64_t pr, pi, nr, ni;
        cross(&a->pos[n], &b->pos[n], &pr, &pi);
        cross(&a->neg[n], &b->neg[n], &nr, &ni);
        big |= ssda__abs64(pr) | ssda__abs64(pi) | ssda__abs64(nr) | ssda__abs64(ni);
    }
    return ssda__bitlen64(big);
}

/* One c_n scaled by 2^-shift and, for the fixed match (rot != NULL: cos,
   sin Q15), turned by phi: |.| < 2^27.5 either way. */
static void scaled_term(int64_t re, int64_t im, uint32_t shift, const int32_t *rot, int32_t *r,
                        int32_t *i)
{
    int64_t sr = ssda__asr64(re, shift), si = ssda__asr64(im, shift);
    if (rot != NULL) { /* c exp(i phi): Re of the sum is the cross term */
        const int64_t tr = sr * rot[0] - si * rot[1];
        const int64_t ti = sr * rot[1] + si * rot[0];
        sr = ssda__asr64(tr, 15u);
        si = ssda__asr64(ti, 15u);
    }
    *r = (int32_t)sr;
    *i = (int32_t)si;
}

static void zpoly_build(const ssda_fd_t *a, const ssda_fd_t *b, const int32_t *rot, zpoly_t *p)
{
    const uint32_t len = cross_bits(a, b);
    uint32_t n;
    p->order = a->order;
    p->shift = len > C_BITS ? len - C_BITS : 0u;
    for (n = 0u; n < a->order; n++) {
        int64_t re, im;
        int32_t pr, pi, nr, ni;
        cross(&a->pos[n], &b->pos[n], &re, &im);
        scaled_term(re, im, p->shift, rot, &pr, &pi);
        cross(&a->neg[n], &b->neg[n], &re, &im);
        scaled_term(re, im, p->shift, rot, &nr, &ni);
        p->p[n] = pr + nr;
        p->q[n] = pi - ni;
        p->r[n] = pr - nr;
        p->s[n] = pi + ni;
    }
}

static zval_t zpoly_eval(const zpoly_t *p, uint32_t alpha)
{
    zval_t v = {0, 0, 0, 0};
    uint32_t n;
    for (n = 0u; n < p->order; n++) {
        const int64_t k = (int64_t)n + 1;
        const uint32_t turn = (n + 1u) * alpha; /* k alpha mod one turn */
        const int64_t cs = ssda__cos_q15(turn), sn = ssda__sin_q15(turn);
        v.zr += p->p[n] * cs - p->q[n] * sn; /* < 2^44 */
        v.zi += p->r[n] * sn + p->s[n] * cs;
        v.wr += k * (p->r[n] * cs - p->s[n] * sn);
        v.wi += k * (p->p[n] * sn + p->q[n] * cs);
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

/* Score of a value: |Z|^2 (unconstrained) or Re Z (fixed, offset to stay unsigned). */
static uint64_t rank(const zval_t *v, bool fixed)
{
    if (fixed) {
        const int64_t lifted = v->zr + 4611686018427387904LL; /* + 2^62: |Z| < 2^48 */
        return (uint64_t)lifted;
    }
    return power(v);
}

/* Score of alpha. */
static uint64_t score(const zpoly_t *p, uint32_t alpha, bool fixed)
{
    const zval_t v = zpoly_eval(p, alpha);
    return rank(&v, fixed);
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

/* Score at grid point j, alpha_j = j / GRID turn: there k alpha_j is a
   whole number of grid steps, so exp(i k alpha_j) comes from one table of
   GRID entries (Q14: the scan only ranks the grid points). */
static uint64_t grid_score(const zpoly_t *p, bool fixed, uint32_t j)
{
    /* trunc(ssda__sin_q15(m CELL) / 2), m = 0..127: sin in Q14 on the grid;
       cos(m CELL) = sin((m + 32) CELL) */
    static const int16_t grid_sin[GRID] = {
        0, 804, 1606, 2404, 3196, 3981, 4756, 5519, 6270, 7005, 7723, 8423, 9102,
        9760, 10394, 11003, 11585, 12139, 12665, 13160, 13623, 14053, 14449, 14811,
        15137, 15426, 15678, 15893, 16069, 16206, 16305, 16364, 16384, 16364, 16305,
        16206, 16069, 15893, 15678, 15426, 15137, 14811, 14449, 14053, 13623, 13160,
        12665, 12139, 11585, 11003, 10394, 9760, 9102, 8423, 7723, 7005, 6270, 5519,
        4756, 3981, 3196, 2404, 1606, 804, 0, -804, -1606, -2404, -3196, -3981, -4756,
        -5519, -6270, -7005, -7723, -8423, -9102, -9760, -10394, -11003, -11585, -12139,
        -12665, -13160, -13623, -14053, -14449, -14811, -15137, -15426, -15678, -15893,
        -16069, -16206, -16305, -16364, -16384, -16364, -16305, -16206, -16069, -15893,
        -15678, -15426, -15137, -14811, -14449, -14053, -13623, -13160, -12665, -12139,
        -11585, -11003, -10394, -9760, -9102, -8423, -7723, -7005, -6270, -5519, -4756,
        -3981, -3196, -2404, -1606, -804};
    zval_t v = {0, 0, 0, 0};
    uint32_t n;
    for (n = 0u; n < p->order; n++) {
        const uint32_t m = ((n + 1u) * j) & (GRID - 1u);
        const int64_t sn = grid_sin[m], cs = grid_sin[(m + (GRID / 4u)) & (GRID - 1u)];
        v.zr += p->p[n] * cs - p->q[n] * sn; /* < 2^43 each */
        v.zi += p->r[n] * sn + p->s[n] * cs;
    }
    return rank(&v, fixed);
}

/* Keep the PEAKS best (value, then the smaller index) grid maxima. */
static void peak_insert(uint32_t *peak, uint64_t *val, uint32_t *n, uint32_t j, uint64_t v)
{
    uint32_t at = *n, i;
    while (at > 0u && (val[at - 1u] < v || (val[at - 1u] == v && peak[at - 1u] > j))) {
        at--;
    }
    if (at >= PEAKS) {
        return;
    }
    for (i = (*n < PEAKS ? *n : PEAKS - 1u); i > at; i--) {
        peak[i] = peak[i - 1u];
        val[i] = val[i - 1u];
    }
    peak[at] = j;
    val[at] = v;
    *n = *n < PEAKS ? *n + 1u : PEAKS;
}

/* The alpha maximising the score: a scan of the GRID points kept as it
   goes (local maxima: >= the previous point, > the next, cyclically), the
   PEAKS best refined, the best refined kept (ties: the smaller alpha). */
static uint32_t best_alpha(const zpoly_t *p, bool fixed)
{
    uint32_t peak[PEAKS], npeak = 0u, j, i, best_alpha = 0u;
    uint64_t val[PEAKS], first = 0u, second = 0u, prev2 = 0u, prev = 0u, best = 0u;
    for (j = 0u; j < GRID + 2u; j++) {
        uint64_t cur;
        if (j < GRID) {
            cur = grid_score(p, fixed, j);
        } else {
            cur = j == GRID ? first : second; /* wrap round to points 0 and 1 */
        }
        if (j == 0u) {
            first = cur;
        } else if (j == 1u) {
            second = cur;
        } else if (prev >= prev2 && prev > cur) { /* j - 1 is a local maximum */
            peak_insert(peak, val, &npeak, (j - 1u) & (GRID - 1u), prev);
        } else {
            /* not a maximum */
        }
        prev2 = prev;
        prev = cur;
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
    zpoly_build(a, b, NULL, &p);
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
    uint32_t alpha, ab;
    uint64_t e2, t1;
    const int32_t rot[2] = {ssda__cos_q15(phi), ssda__sin_q15(phi)};
    const int err = check(a, b, m);
    if (err != SSDA_OK) {
        return err;
    }
    if (s_q16 == 0u || s_q16 > (1u << 24)) {
        return SSDA_ERR_ARG;
    }
    zpoly_build(a, b, rot, &p);
    alpha = best_alpha(&p, true);
    v = zpoly_eval(&p, alpha);
    /* E^2 = (B + s^2 A - 2 s R) / B with R = Re(exp(i phi) Z). t1 = s^2 A / B
       (Q16); since R <= sqrt(A B), 2 s R / B <= 2 sqrt(t1): when t1 does not
       fit 32 bits, E^2 >= (sqrt(t1) - 1)^2 > 255^2 and saturates. */
    ab = ssda__ratio_q16(a->energy_q16, 0, b->energy_q16);
    t1 = ((uint64_t)ssda__mulshr_sat(s_q16, s_q16, 16u) * ab) >> 16; /* < 2^48 */
    if (ab == 0xFFFFFFFFu || t1 > 0xFFFFFFFFu) {
        e2 = 0xFFFFFFFFu;
    } else {
        const uint64_t s2 = (uint64_t)s_q16 * 2u;
        const uint64_t t2 =
            (s2 * ssda__ratio_q16(ssda__abs64(v.zr), (int32_t)p.shift - 15, b->energy_q16)) >>
            16;
        e2 = 65536u + t1; /* t2 < 2^41 */
        if (v.zr >= 0) {
            e2 = e2 > t2 ? e2 - t2 : 0u;
        } else {
            e2 += t2;
        }
    }
    m->s_q16 = s_q16;
    m->phi = phi;
    m->alpha = alpha;
    m->e2_q16 = e2 > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)e2;
    return SSDA_OK;
}
