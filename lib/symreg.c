/* symreg.c - ssda_symreg (symreg.h): nuclei from unconstrained matches, growth of
   each nucleus by the seed's steps [2.1]-[2.5], the largest final set. */
#include "symreg_internal.h"
#include "fourier_internal.h"
#include "fixmath.h"
#include "fixtrig.h"

#include <string.h>

#define ITER_MAX 64u /* [2.2] rounds per nucleus; each must add pairs */
#define PER_REF 2u   /* [1] nuclei from one REF loop at most */

/* A nucleus candidate from [1]. */
typedef struct {
    uint16_t ref, mov;
    uint32_t s_q16, phi, e2;
} nucleus_t;

/* Resolved settings and the inputs. */
typedef struct {
    const ssda_loop_t *ref, *mov;
    const ssda_fd_t *fr, *fm;
    uint32_t n_ref, n_mov, k, min_pairs;
    uint32_t e2_nucleus, e2_grow, e2_final, smin, smax, ratio_q8, reach_q16, reach_min;
    uint32_t resid_max, resid_mean, shear_q16;
} plan_t;

/* The best registration so far. */
typedef struct {
    ssda__partner_t *set;   /* n_ref entries */
    ssda_symreg_affine_t t;
    uint32_t pairs, rms, nucleus;
} best_t;

static uint32_t def(uint32_t v, uint32_t d)
{
    return v != 0u ? v : d;
}

/* area_m / area_r within [lo^2, hi^2] for scales lo, hi (Q16, <= 2^20)? */
static bool area_fits(uint32_t area_r, uint32_t area_m, uint32_t lo_q16, uint32_t hi_q16)
{
    /* area_m 2^32 against area_r s^2: each < 2^20 * 2^40 */
    const uint64_t m = (uint64_t)area_m << 32;
    return m >= (uint64_t)area_r * ((uint64_t)lo_q16 * lo_q16) &&
           m <= (uint64_t)area_r * ((uint64_t)hi_q16 * hi_q16);
}

/* area_m within a factor ratio (Q8) of area_r s^2 (s Q16)? */
static bool area_near(uint32_t area_r, uint32_t area_m, uint32_t s_q16, uint32_t ratio_q8)
{
    uint64_t e; /* expected area, Q16 px: < 2^20 * 2^24 */
    if (s_q16 > 0x100000u) { /* 16.0 */
        return false;
    }
    e = (uint64_t)area_r * (((uint64_t)s_q16 * s_q16) >> 16);
    /* 1/r <= area_m / e <= r, both sides < 2^60 */
    return ((uint64_t)area_m << 16) * ratio_q8 >= e * 256u &&
           ((uint64_t)area_m << 24) <= e * ratio_q8;
}

/* A contour of zero energy (all samples equal: a one-pixel region) matches
   nothing (fourier.h): ssda_fd_match and ssda_fd_match_fixed refuse it and
   the E^2 bounds would divide by its energy. A nucleus never has one. */
static bool matchable(const ssda_fd_t *a, const ssda_fd_t *b)
{
    return a->energy_q16 != 0u && b->energy_q16 != 0u;
}

/* Insert a candidate into the list sorted by E^2 (ties keep the earlier). */
static void nuclei_insert(nucleus_t *list, uint32_t *n, uint32_t k, const nucleus_t *c)
{
    uint32_t at = *n, i;
    while (at > 0u && list[at - 1u].e2 > c->e2) {
        at--;
    }
    if (at >= k) {
        return;
    }
    for (i = (*n < k ? *n : k - 1u); i > at; i--) {
        list[i] = list[i - 1u];
    }
    list[at] = *c;
    *n = *n < k ? *n + 1u : k;
}

/* [1]: the k best pairs by unconstrained-match E^2, at most PER_REF of them from
   any one REF loop (the seed: the same loops recur in many pairs; without
   the cap, a few round loops that match everything fill the list).
   Returns how many. */
static uint32_t find_nuclei(const plan_t *p, nucleus_t *list, ssda_symreg_result_t *res)
{
    uint32_t i, j, n = 0u;
    for (i = 0u; i < p->n_ref; i++) {
        nucleus_t mine[PER_REF];
        uint32_t nm = 0u;
        for (j = 0u; j < p->n_mov; j++) {
            uint32_t limit = n == p->k ? list[n - 1u].e2 : p->e2_nucleus;
            ssda_fd_match_t m;
            nucleus_t c;
            if (nm == PER_REF && mine[PER_REF - 1u].e2 < limit) {
                limit = mine[PER_REF - 1u].e2;
            }
            if (!area_fits(p->ref[i].area, p->mov[j].area, p->smin, p->smax) ||
                !matchable(&p->fr[i], &p->fm[j])) {
                continue;
            }
            if (ssda__fd_e2_bound(&p->fr[i], &p->fm[j]) > limit) {
                res->skipped++; /* cannot enter the lists: no search */
                continue;
            }
            (void)ssda_fd_match(&p->fr[i], &p->fm[j], &m); /* orders checked at entry */
            res->matches++;
            if (m.e2_q16 > limit || m.s_q16 < p->smin || m.s_q16 > p->smax) {
                continue;
            }
            res->candidates++;
            c.ref = (uint16_t)i;
            c.mov = (uint16_t)j;
            c.s_q16 = m.s_q16;
            c.phi = m.phi;
            c.e2 = m.e2_q16;
            nuclei_insert(mine, &nm, PER_REF, &c);
        }
        for (j = 0u; j < nm; j++) {
            nuclei_insert(list, &n, p->k, &mine[j]);
        }
    }
    return n;
}

/* Squared distance between Q8 points, saturated. */
static uint64_t dist2(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    const uint64_t dx = ssda__abs64(ax - bx), dy = ssda__abs64(ay - by);
    if (dx >= 0x80000000u || dy >= 0x80000000u) {
        return UINT64_MAX;
    }
    return dx * dx + dy * dy;
}

/* [2.2]: pair every REF loop from the transform t; the nucleus forced in.
   Returns the pairs found. owner: n_mov entries of scratch. */
static uint32_t grow(const plan_t *p, const nucleus_t *nu, const ssda_symreg_affine_t *t,
                     ssda__partner_t *set, uint16_t *owner)
{
    uint32_t s, phi, i, j, count = 0u;
    int64_t nx, ny;
    ssda__symreg_scale_rot(t, &s, &phi);
    ssda__symreg_map(t, p->ref[nu->ref].cx_q8, p->ref[nu->ref].cy_q8, &nx, &ny);
    for (j = 0u; j < p->n_mov; j++) {
        owner[j] = SSDA__NONE;
    }
    for (i = 0u; i < p->n_ref; i++) {
        int64_t x, y;
        uint64_t r;
        uint32_t best = SSDA__NONE, best_e2 = 0u;
        set[i].mov = SSDA__NONE;
        ssda__symreg_map(t, p->ref[i].cx_q8, p->ref[i].cy_q8, &x, &y);
        /* radius reach_min + reach * distance from the nucleus, Q8 */
        r = p->reach_min + (((uint64_t)ssda__isqrt64(dist2(x, y, nx, ny)) * p->reach_q16) >> 16);
        for (j = 0u; j < p->n_mov; j++) {
            ssda_fd_match_t m;
            const bool forced = i == nu->ref && j == nu->mov;
            if (!forced && (dist2(x, y, p->mov[j].cx_q8, p->mov[j].cy_q8) > r * r ||
                            !area_near(p->ref[i].area, p->mov[j].area, s, p->ratio_q8) ||
                            !matchable(&p->fr[i], &p->fm[j]))) {
                continue;
            }
            if (!forced && ssda__fd_fixed_bound(&p->fr[i], &p->fm[j], s == 0u ? 1u : s) >
                               p->e2_grow) {
                continue; /* cannot pair: no search (SSDA's early exit, in shapes) */
            }
            (void)ssda_fd_match_fixed(&p->fr[i], &p->fm[j], s == 0u ? 1u : s, phi, &m);
            if ((forced || m.e2_q16 <= p->e2_grow) &&
                (best == SSDA__NONE || forced || m.e2_q16 < best_e2)) {
                best = j;
                best_e2 = m.e2_q16;
                if (forced) {
                    break;
                }
            }
        }
        if (best == SSDA__NONE) {
            continue;
        }
        if (owner[best] != SSDA__NONE) { /* taken: the smaller E^2 keeps it */
            ssda__partner_t *o = &set[owner[best]];
            if (i != nu->ref && (owner[best] == nu->ref || o->e2 <= best_e2)) {
                continue;
            }
            o->mov = SSDA__NONE;
            count--;
        }
        owner[best] = (uint16_t)i;
        set[i].mov = (uint16_t)best;
        set[i].e2 = best_e2;
        count++;
    }
    return count;
}

/* Residuals of the set under t: the largest (its REF index) and the sum. */
static void residuals(const plan_t *p, const ssda__partner_t *set, const ssda_symreg_affine_t *t,
                      uint32_t *worst, uint32_t *worst_i, uint64_t *sum, uint64_t *sum2)
{
    uint32_t i;
    *worst = 0u;
    *worst_i = SSDA__NONE;
    *sum = 0u;
    *sum2 = 0u;
    for (i = 0u; i < p->n_ref; i++) {
        if (set[i].mov != SSDA__NONE) {
            const uint32_t r = ssda__symreg_resid(t, &p->ref[i], &p->mov[set[i].mov]);
            *sum += r;                   /* < 4096 * 2^32 */
            *sum2 += (uint64_t)r * r;    /* saturating residuals are refused below */
            if (*worst_i == SSDA__NONE || r > *worst) {
                *worst = r;
                *worst_i = i;
            }
        }
    }
}

/* The seed's assumption of an affine transform with little shear (a view
   from straight above): the mapped x and y axes differ in length by at
   most shear (relative) and meet at 90 degrees within acos(shear). */
static bool little_shear(const ssda_symreg_affine_t *t, uint32_t shear_q16)
{
    /* Q8 coefficients: |.| < 2^13 for scales below 16 (else refused) */
    const int64_t a = ssda__asr64(t->a_q16, 8u), b = ssda__asr64(t->b_q16, 8u);
    const int64_t d = ssda__asr64(t->d_q16, 8u), e = ssda__asr64(t->e_q16, 8u);
    const int64_t s1s = a * a + d * d, s2s = b * b + e * e; /* Q16, >= 0 */
    const uint64_t s1 = (uint64_t)s1s, s2 = (uint64_t)s2s;
    const uint64_t lo = s1 < s2 ? s1 : s2, hi = s1 < s2 ? s2 : s1;
    const uint64_t dot = ssda__abs64(a * b + d * e);
    if (s1 >= ((uint64_t)1 << 42) || s2 >= ((uint64_t)1 << 42) || lo == 0u) {
        return false;
    }
    /* s_hi / s_lo <= 1 + shear  <=>  hi <= lo (1 + shear)^2; and
       |cos| = dot / sqrt(s1 s2) <= shear  <=>  dot^2 <= shear^2 s1 s2 */
    {
        const uint64_t f = (uint64_t)shear_q16 + 65536u;             /* Q16 */
        const uint64_t lo_f = (lo * ((f * f) >> 16)) >> 16;          /* < 2^42 * 2^18 */
        const uint64_t sh2 = ((uint64_t)shear_q16 * shear_q16) >> 16; /* Q16 */
        if (hi > lo_f) {
            return false;
        }
        /* dot^2 < 2^84 would overflow: compare in Q8 of the products */
        return (dot >> 8) * (dot >> 8) <= (((s1 >> 8) * (s2 >> 8)) >> 16) * sh2;
    }
}

/* [2.5]'s fixed matches with the fit's scale and rotation; the REF index
   of the largest E^2 above e2_final, or NONE when all pass (E^2 stored). */
static uint32_t shape_check(const plan_t *p, ssda__partner_t *set, const ssda_symreg_affine_t *t)
{
    uint32_t s, phi, i, worst = SSDA__NONE, worst_e2 = 0u;
    ssda__symreg_scale_rot(t, &s, &phi);
    for (i = 0u; i < p->n_ref; i++) {
        if (set[i].mov != SSDA__NONE) {
            ssda_fd_match_t m;
            (void)ssda_fd_match_fixed(&p->fr[i], &p->fm[set[i].mov], s == 0u ? 1u : s, phi, &m);
            set[i].e2 = m.e2_q16;
            if (m.e2_q16 > p->e2_final && (worst == SSDA__NONE || m.e2_q16 > worst_e2)) {
                worst = i;
                worst_e2 = m.e2_q16;
            }
        }
    }
    return worst;
}

/* [2.3]-[2.5] on the set: true with the final set and its transform and
   RMS, false when the nucleus fails. n: pairs in the set. */
static bool settle(const plan_t *p, const nucleus_t *nu, ssda__partner_t *set, uint32_t n,
                   ssda_symreg_affine_t *t, uint32_t *rms)
{
    uint32_t count = n;
    for (;;) {
        uint32_t worst, worst_i, drop;
        uint64_t sum, sum2;
        if (count < p->min_pairs || !ssda__symreg_fit(p->ref, p->mov, set, p->n_ref, t)) {
            return false;                                                    /* [2.3] */
        }
        residuals(p, set, t, &worst, &worst_i, &sum, &sum2);
        if (worst > p->resid_max || sum > (uint64_t)p->resid_mean * count || /* [2.4] */
            !little_shear(t, p->shear_q16)) {
            drop = worst_i;
        } else {
            drop = shape_check(p, set, t);                                   /* [2.5] */
            if (drop == SSDA__NONE) {
                *rms = ssda__isqrt64(SSDA_DIV64_32(sum2, count) > 0xFFFFFFFFu
                                        ? 0xFFFFFFFFu
                                        : (uint64_t)SSDA_DIV64_32(sum2, count));
                return true;
            }
        }
        if (drop == nu->ref) {
            return false; /* the nucleus itself is wrong */
        }
        set[drop].mov = SSDA__NONE;
        count--;
    }
}

/* One nucleus, [2.1]-[2.5] until [2.2] stops growing; the best kept. */
static void run_nucleus(const plan_t *p, const nucleus_t *nu, uint32_t index,
                        ssda__partner_t *set, uint16_t *owner, best_t *best)
{
    ssda_symreg_affine_t t;
    uint32_t last = 0u, round;
    ssda__symreg_similarity(nu->s_q16, nu->phi, p->ref[nu->ref].cx_q8, p->ref[nu->ref].cy_q8,
                            p->mov[nu->mov].cx_q8, p->mov[nu->mov].cy_q8, &t);     /* [2.1] */
    for (round = 0u; round < ITER_MAX; round++) {
        ssda_symreg_affine_t fit;
        uint32_t rms = 0u, i, pairs = 0u;
        const uint32_t n = grow(p, nu, &t, set, owner);                      /* [2.2] */
        if (n < p->min_pairs || n <= last || !settle(p, nu, set, n, &fit, &rms)) {
            return;
        }
        for (i = 0u; i < p->n_ref; i++) {
            pairs += set[i].mov != SSDA__NONE ? 1u : 0u;
        }
        if (pairs > best->pairs || (pairs == best->pairs && rms < best->rms)) {
            (void)memcpy(best->set, set, (size_t)p->n_ref * sizeof *set);
            best->t = fit;
            best->pairs = pairs;
            best->rms = rms;
            best->nucleus = index;
        }
        last = pairs > last ? pairs : last;
        t = fit;
    }
}

/* Check the arguments and resolve the settings. */
static int plan_init(const ssda_loop_t *ref, const ssda_fd_t *fd_ref, uint32_t n_ref,
                     const ssda_loop_t *mov, const ssda_fd_t *fd_mov, uint32_t n_mov,
                     const ssda_symreg_config_t *cfg, const void *work, size_t work_size,
                     const ssda_symreg_pair_t *pairs, uint32_t max_pairs,
                     const ssda_symreg_result_t *res, plan_t *p)
{
    static const ssda_symreg_config_t defaults;
    const ssda_symreg_config_t *c = cfg != NULL ? cfg : &defaults;
    uint32_t i;
    if (work == NULL || res == NULL || (max_pairs > 0u && pairs == NULL) ||
        (n_ref > 0u && (ref == NULL || fd_ref == NULL)) ||
        (n_mov > 0u && (mov == NULL || fd_mov == NULL))) {
        return SSDA_ERR_NULL;
    }
    p->ref = ref;
    p->mov = mov;
    p->fr = fd_ref;
    p->fm = fd_mov;
    p->n_ref = n_ref;
    p->n_mov = n_mov;
    p->k = def(c->nuclei, SSDA_SYMREG_DEFAULT_NUCLEI);
    p->min_pairs = def(c->min_pairs, SSDA_SYMREG_DEFAULT_MIN_PAIRS);
    p->e2_nucleus = def(c->e2_nucleus_q16, 3277u);   /* 0.05 */
    p->e2_grow = def(c->e2_grow_q16, 16384u);        /* 0.25 */
    p->e2_final = def(c->e2_final_q16, 9830u);       /* 0.15 */
    p->smin = def(c->scale_min_q16, 32768u);         /* 0.5 */
    p->smax = def(c->scale_max_q16, 131072u);        /* 2.0 */
    p->ratio_q8 = def(c->area_ratio_q8, 512u);       /* 2.0 */
    p->reach_q16 = def(c->reach_q16, 6554u);         /* 0.1 */
    p->reach_min = def(c->reach_min_q8, 1024u);      /* 4 px */
    p->resid_max = def(c->resid_max_q8, 768u);       /* 3 px */
    p->resid_mean = def(c->resid_mean_q8, 384u);     /* 1.5 px */
    p->shear_q16 = def(c->shear_q16, 9830u);         /* 0.15 */
    if (n_ref > SSDA_SYMREG_MAX_LOOPS || n_mov > SSDA_SYMREG_MAX_LOOPS || p->min_pairs < 3u ||
        p->e2_final > p->e2_grow || p->smin > p->smax || p->smax > 0x100000u ||
        p->ratio_q8 < 256u || p->ratio_q8 > 65536u || p->shear_q16 > 65536u) {
        return SSDA_ERR_ARG;
    }
    for (i = 0u; i < n_ref + n_mov; i++) {
        const ssda_fd_t *f = i < n_ref ? &fd_ref[i] : &fd_mov[i - n_ref];
        if (f->order != (n_ref > 0u ? fd_ref[0].order : fd_mov[0].order) || f->order == 0u ||
            f->order > SSDA_FD_MAX_ORDER) {
            return SSDA_ERR_ARG;
        }
    }
    if (work_size < SSDA_SYMREG_WORK_SIZE(n_ref, n_mov, p->k)) {
        return SSDA_ERR_BUFFER;
    }
    if ((((uintptr_t)work) & 3u) != 0u) { /* D10 */
        return SSDA_ERR_STRIDE;
    }
    return SSDA_OK;
}

/* The winner's pairs: the unconstrained match of each, the fixed E^2, residuals. */
static uint32_t write_pairs(const plan_t *p, const best_t *b, ssda_symreg_pair_t *pairs,
                            uint32_t max_pairs)
{
    uint32_t i, n = 0u;
    for (i = 0u; i < p->n_ref && n < max_pairs; i++) {
        if (b->set[i].mov != SSDA__NONE) {
            ssda_fd_match_t m;
            ssda_symreg_pair_t *o = &pairs[n];
            n++;
            (void)ssda_fd_match(&p->fr[i], &p->fm[b->set[i].mov], &m);
            o->ref = (uint16_t)i;
            o->mov = b->set[i].mov;
            o->s_q16 = m.s_q16;
            o->phi = m.phi;
            o->e2_q16 = m.e2_q16;
            o->e2_fixed_q16 = b->set[i].e2;
            o->resid_q8 = ssda__symreg_resid(&b->t, &p->ref[i], &p->mov[b->set[i].mov]);
        }
    }
    return n;
}

int ssda_symreg(const ssda_loop_t *ref, const ssda_fd_t *fd_ref, uint32_t n_ref,
                const ssda_loop_t *mov, const ssda_fd_t *fd_mov, uint32_t n_mov,
                const ssda_symreg_config_t *cfg, void *work, size_t work_size,
                ssda_symreg_pair_t *pairs, uint32_t max_pairs, ssda_symreg_result_t *res)
{
    plan_t p;
    ssda_symreg_result_t r;
    nucleus_t *list = (nucleus_t *)work;
    ssda__partner_t *set, *best_set;
    uint16_t *owner;
    best_t best;
    uint32_t n, i;
    int err = plan_init(ref, fd_ref, n_ref, mov, fd_mov, n_mov, cfg, work, work_size, pairs,
                        max_pairs, res, &p);
    if (err != SSDA_OK) {
        return err;
    }
    {
        void *after_list = &list[p.k];
        set = after_list;
    }
    best_set = &set[n_ref];
    {
        void *after_sets = &best_set[n_ref];
        owner = after_sets;
    }
    (void)memset(&r, 0, sizeof r);
    (void)memset(&best, 0, sizeof best);
    best.set = best_set;
    n = find_nuclei(&p, list, &r);                                              /* [1] */
    for (i = 0u; i < n; i++) {                                                  /* [2] */
        /* the seed's rule (a): a nucleus already paired in the best final set
           grows into that set again */
        if (best.pairs == 0u || best_set[list[i].ref].mov != list[i].mov) {
            run_nucleus(&p, &list[i], i, set, owner, &best);
        }
    }
    r.nuclei = n;
    if (best.pairs > 0u) {                                                      /* [3] */
        r.affine = best.t;
        r.pairs = best.pairs;
        r.rms_q8 = best.rms;
        r.best_nucleus = best.nucleus;
        ssda__symreg_scale_rot(&best.t, &r.scale_q16, &r.rotation);
        (void)write_pairs(&p, &best, pairs, max_pairs);
    }
    *res = r;
    return SSDA_OK;
}
