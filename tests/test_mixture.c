/*
 * test_mixture.c - Gaussian-mixture fits of histograms (mixture.h) against
 * independent references:
 *   - EM against a double-precision EM written here from the textbook
 *     formulas, from the same start for the same number of iterations;
 *   - the log-likelihood against the double density of the returned model;
 *   - both fits recover known parameters of sampled mixtures; BIC picks the
 *     true number of well-separated components;
 *   - the seed's search never raises its own window error, and with its
 *     fixed steps stops no later than with halvings;
 *   - look-up tables against the rules evaluated in double, labelling and
 *     histograms against brute force, band areas against direct sums;
 *   - the worst-case histogram (2^32 - 1 pixels in one bin), and every
 *     error with outputs poisoned and checked untouched.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/mixture.h"
#include "mix_internal.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef SSDA_TEST_SMALL
#define SAMPLES 20000u
#define RUNS 3u
#define Q_CASES 20000u
#else
#define SAMPLES 400000u
#define RUNS 12u
#define Q_CASES 200000u
#endif

#define BINS 1024u
#define Q16 65536.0
#define PI 3.14159265358979323846

static uint64_t g_work_mem[(SSDA_MIX_WORK_SIZE(SSDA_MIX_MAX_BINS) + 7u) / 8u];
static uint32_t g_hist[SSDA_MIX_MAX_BINS];

typedef struct {
    double w, mu, sd;
} comp_t;

/* ---- sampled mixtures ---- */

static double uniform(test_rng_t *r)
{
    return ((double)test_rng_next(r) + 0.5) / 4294967296.0;
}

static double normal(test_rng_t *r)
{
    return sqrt(-2.0 * log(uniform(r))) * cos(2.0 * PI * uniform(r));
}

/* n samples of the mixture, rounded to bins (outside: dropped). */
static uint32_t sample(test_rng_t *r, const comp_t *c, uint32_t k, uint32_t n, uint32_t bins)
{
    uint32_t i, kept = 0u;
    memset(g_hist, 0, sizeof g_hist);
    for (i = 0; i < n; i++) {
        double u = uniform(r), acc = 0.0;
        uint32_t j = 0;
        double x;
        while (j + 1u < k && u > acc + c[j].w) {
            acc += c[j].w;
            j++;
        }
        x = floor(c[j].mu + c[j].sd * normal(r) + 0.5);
        if (x >= 0.0 && x < (double)bins) {
            g_hist[(uint32_t)x]++;
            kept++;
        }
    }
    return kept;
}

/* ---- double references ---- */

static double density(const comp_t *c, uint32_t k, double z)
{
    double p = 0.0;
    uint32_t j;
    for (j = 0; j < k; j++) {
        if (c[j].w > 0.0) {
            const double t = (z - c[j].mu) / c[j].sd;
            p += c[j].w / (c[j].sd * sqrt(2.0 * PI)) * exp(-0.5 * t * t);
        }
    }
    return p;
}

/* The log-likelihood of the mixture c (weights normalised to sum 1). */
static double loglik(const comp_t *c_in, uint32_t k, uint32_t bins)
{
    comp_t c[SSDA_MIX_MAX_COMPONENTS];
    double ll = 0.0, sum = 0.0;
    uint32_t z;
    for (z = 0; z < k; z++) {
        sum += c_in[z].w;
    }
    for (z = 0; z < k; z++) {
        c[z] = c_in[z];
        c[z].w /= sum;
    }
    for (z = 0; z < bins; z++) {
        if (g_hist[z] != 0u) {
            ll += (double)g_hist[z] * log(density(c, k, (double)z));
        }
    }
    return ll;
}

static void model_comps(const ssda_mix_model_t *m, comp_t *c)
{
    uint32_t j;
    for (j = 0; j < m->count; j++) {
        c[j].w = m->comp[j].weight_q16 / Q16;
        c[j].mu = m->comp[j].mean_q16 / Q16;
        c[j].sd = m->comp[j].sigma_q16 / Q16;
    }
}

/* The textbook EM on a histogram, `steps` M-steps. */
static void ref_em(comp_t *c, uint32_t k, uint32_t bins, uint32_t steps, double sigma_min)
{
    uint32_t it, z, j;
    for (it = 0; it < steps; it++) {
        double n[SSDA_MIX_MAX_COMPONENTS] = {0}, m1[SSDA_MIX_MAX_COMPONENTS] = {0};
        double m2[SSDA_MIX_MAX_COMPONENTS] = {0}, tot = 0.0;
        for (z = 0; z < bins; z++) {
            double p[SSDA_MIX_MAX_COMPONENTS], s = 0.0;
            if (g_hist[z] == 0u) {
                continue;
            }
            for (j = 0; j < k; j++) {
                const double t = (z - c[j].mu) / c[j].sd;
                p[j] = c[j].w > 0.0 ? c[j].w / c[j].sd * exp(-0.5 * t * t) : 0.0;
                s += p[j];
            }
            for (j = 0; j < k; j++) {
                const double hr = g_hist[z] * p[j] / s;
                n[j] += hr;
                m1[j] += hr * z;
                m2[j] += hr * (double)z * z;
            }
        }
        for (j = 0; j < k; j++) {
            tot += n[j];
        }
        for (j = 0; j < k; j++) {
            if (n[j] > 0.0) {
                double var;
                c[j].w = n[j] / tot;
                c[j].mu = m1[j] / n[j];
                var = m2[j] / n[j] - c[j].mu * c[j].mu;
                c[j].sd = var > sigma_min * sigma_min ? sqrt(var) : sigma_min;
            } else {
                c[j].w = 0.0;
            }
        }
    }
}

static void sort_comps(comp_t *c, uint32_t k)
{
    uint32_t i, j;
    for (i = 1; i < k; i++) {
        for (j = i; j > 0 && c[j - 1u].mu > c[j].mu; j--) {
            const comp_t t = c[j];
            c[j] = c[j - 1u];
            c[j - 1u] = t;
        }
    }
}

static ssda_mix_config_t config(uint8_t k, uint8_t fit)
{
    ssda_mix_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.components = k;
    cfg.fit = fit;
    return cfg;
}

static int fit(uint32_t bins, const ssda_mix_config_t *cfg, ssda_mix_model_t *m)
{
    return ssda_mix_fit(g_hist, bins, cfg, g_work_mem, sizeof g_work_mem, m);
}

/* ---- EM against the double EM ---- */

static void test_work_layout(void)
{
    TEST_ASSERT_TRUE(sizeof(ssda__mix_work_t) <= SSDA_MIX_WORK_FIXED);
}

static void test_em_vs_double(void)
{
    static const comp_t truth[4] = {{0.3, 200.0, 20.0}, {0.2, 300.0, 35.0},
                                    {0.4, 520.0, 15.0}, {0.1, 700.0, 60.0}};
    test_rng_t r;
    uint32_t run;
    double worst_w = 0.0, worst_m = 0.0, worst_s = 0.0;
    test_rng_seed(&r, 31u);
    for (run = 0; run < RUNS; run++) {
        const uint32_t k = 2u + run % 3u, steps = 5u + run * 3u;
        ssda_mix_config_t cfg = config((uint8_t)k, SSDA_MIX_FIT_EM);
        ssda_mix_model_t m;
        ssda__mix_work_t *w = (ssda__mix_work_t *)(void *)g_work_mem;
        ssda__mix_cfg_t c;
        comp_t ref[SSDA_MIX_MAX_COMPONENTS], got[SSDA_MIX_MAX_COMPONENTS];
        uint32_t total, j;
        double lref;
        total = sample(&r, truth, 4u, SAMPLES, BINS);
        cfg.max_iter = (uint16_t)(steps + 1u);
        cfg.tol_q24 = 1u;
        cfg.init = (uint8_t)(run & 1u);
        /* the library's own start, then the double EM from it */
        memset(&c, 0, sizeof c);
        c.init = cfg.init;
        c.sigma_min_q16 = SSDA_MIX_DEFAULT_SIGMA_MIN_Q16;
        w->cache = (int32_t *)(void *)((uint8_t *)g_work_mem + SSDA_MIX_WORK_FIXED);
        ssda__mix_init(g_hist, BINS, total, ssda__mix_scale_shift(g_hist, BINS), &c, k, w);
        {
            double sum = 0.0;
            for (j = 0; j < k; j++) {
                sum += (double)w->p[j].n;
            }
            for (j = 0; j < k; j++) {
                ref[j].w = (double)w->p[j].n / sum;
                ref[j].mu = w->p[j].mean_q16 / Q16;
                ref[j].sd = w->p[j].sigma_q16 / Q16;
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(BINS, &cfg, &m));
        TEST_ASSERT_EQUAL_UINT32(k, m.count);
        /* max_iter E-steps at most (fewer if the gain fell below 2^-30 nats
           per pixel), one M-step fewer */
        TEST_ASSERT_TRUE(m.iterations >= 2u && m.iterations <= steps + 1u);
        ref_em(ref, k, BINS, m.iterations - 1u, 0.5);
        sort_comps(ref, k);
        TEST_ASSERT_EQUAL_UINT32(total, m.total);
        model_comps(&m, got);
        for (j = 0; j < k; j++) {
            /* rounding (Q30 responsibilities, Q8 counts, Q16 results)
               carried through up to 38 iterations, which amplify it the more
               the flatter the likelihood (fewer samples): measured worst
               1.5e-4 in weight with 20 000 samples, 7e-6 with 400 000 */
            const double dw = fabs(ref[j].w - got[j].w), dm = fabs(ref[j].mu - got[j].mu);
            const double ds = fabs(ref[j].sd - got[j].sd);
            worst_w = dw > worst_w ? dw : worst_w;
            worst_m = dm / ref[j].sd > worst_m ? dm / ref[j].sd : worst_m;
            worst_s = ds / ref[j].sd > worst_s ? ds / ref[j].sd : worst_s;
            TEST_ASSERT_DOUBLE_WITHIN(5e-4, ref[j].w, got[j].w);
            TEST_ASSERT_DOUBLE_WITHIN(5e-4 * ref[j].sd + 1e-3, ref[j].mu, got[j].mu);
            TEST_ASSERT_DOUBLE_WITHIN(5e-4 * ref[j].sd + 1e-3, ref[j].sd, got[j].sd);
        }
        /* the log-likelihood reported is that of the returned model, up to
           the Q16 rounding of its weights (<= 2^-17 each: a pixel of
           component j moves by < 2^-17 / w_j, total k total 2^-17) */
        lref = loglik(got, k, BINS);
        {
            const double tol = fabs(lref) * 2e-6 + (double)k * total / 131072.0 + 1.0;
            TEST_ASSERT_DOUBLE_WITHIN(tol, lref, (double)m.loglik_q16 / Q16);
            TEST_ASSERT_DOUBLE_WITHIN(2.0 * tol, -2.0 * lref + (3.0 * k - 1.0) * log((double)total),
                                      (double)m.bic_q16 / Q16);
        }
        /* BIC from the reported log-likelihood: the penalty (3k - 1) ln N
           to the rounding of ln N in Q16 (half a step per parameter) */
        TEST_ASSERT_DOUBLE_WITHIN(0.5 * (3.0 * k - 1.0) + 1.0,
                                  (3.0 * k - 1.0) * log((double)total) * Q16,
                                  (double)(m.bic_q16 + 2 * m.loglik_q16));
    }
    /* (integers: newlib-nano's printf has no floating point) */
    printf("EM vs double: worst weight %u e-6, mean %u e-6 sd, sd %u e-6 sd\n",
           (unsigned)(worst_w * 1e6), (unsigned)(worst_m * 1e6), (unsigned)(worst_s * 1e6));
}

/* ---- recovery of known mixtures, both fits ---- */

static void check_recovery(const comp_t *truth, uint32_t k, const ssda_mix_model_t *m,
                           double tol_w, double tol_sd)
{
    comp_t got[SSDA_MIX_MAX_COMPONENTS];
    uint32_t j;
    TEST_ASSERT_EQUAL_UINT32(k, m->count);
    model_comps(m, got);
    for (j = 0; j < k; j++) {
        /* within tol_sd of each component's sigma */
        TEST_ASSERT_DOUBLE_WITHIN(tol_w, truth[j].w, got[j].w);
        TEST_ASSERT_DOUBLE_WITHIN(tol_sd * truth[j].sd, truth[j].mu, got[j].mu);
        TEST_ASSERT_DOUBLE_WITHIN(tol_sd * truth[j].sd, truth[j].sd, got[j].sd);
    }
}

static void test_recovery(void)
{
    /* sorted by mean, separated by 4 sigma or more */
    static const comp_t truth[3] = {{0.25, 150.0, 12.0}, {0.45, 400.0, 25.0},
                                    {0.30, 620.0, 8.0}};
    test_rng_t r;
    ssda_mix_model_t m;
    ssda_mix_config_t cfg;
    uint32_t fit_kind;
    test_rng_seed(&r, 32u);
    (void)sample(&r, truth, 3u, SAMPLES, BINS);
    for (fit_kind = 0; fit_kind < 2u; fit_kind++) {
        cfg = config(3u, (uint8_t)fit_kind);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(BINS, &cfg, &m));
        TEST_ASSERT_EQUAL_UINT8(fit_kind, m.fit);
        /* EM: the sampling error; search: least squares on heights is
           less efficient, and its weights come from heights and widths */
        check_recovery(truth, 3u, &m, fit_kind == 0u ? 0.01 : 0.03,
                       fit_kind == 0u ? 0.05 : 0.15);
    }
    /* the quantile start reaches the same EM fit */
    cfg = config(3u, SSDA_MIX_FIT_EM);
    cfg.init = SSDA_MIX_INIT_QUANTILES;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(BINS, &cfg, &m));
    check_recovery(truth, 3u, &m, 0.01, 0.05);
    /* BIC chooses 3 of up to 6 */
    cfg = config(0u, SSDA_MIX_FIT_EM);
    cfg.max_components = 6u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(BINS, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(3u, m.count);
    check_recovery(truth, 3u, &m, 0.01, 0.05);
    /* automatic K with the search fit: the search with BIC's K */
    cfg.fit = SSDA_MIX_FIT_SEARCH;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(BINS, &cfg, &m));
    check_recovery(truth, 3u, &m, 0.03, 0.15);
    /* default max_components (8) */
    cfg = config(0u, SSDA_MIX_FIT_EM);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(BINS, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(3u, m.count);
}

/* ---- a saturation spike ---- */

/* Two Gaussian modes and a tenth of the pixels in the last bin (clipped
   counts). The peaks start must seed each of the three once: a 5-bin mean
   measures a fifth of a one-bin spike, and before starts kept off the
   ones already found, K = 3 put two starts on the spike (same mean, same
   sigma: EM never pulled them apart) and none on the mode at 160. */
static void test_spike(void)
{
    static const comp_t truth[3] = {{0.45, 70.0, 10.0}, {0.45, 160.0, 14.0}, {0.10, 255.0, 0.5}};
    static const comp_t modes[2] = {{0.5, 70.0, 10.0}, {0.5, 160.0, 14.0}};
    test_rng_t r;
    ssda_mix_model_t m;
    ssda_mix_config_t cfg;
    ssda__mix_work_t *w = (ssda__mix_work_t *)(void *)g_work_mem;
    ssda__mix_cfg_t c;
    comp_t ref[3], got[3];
    uint32_t total, i, j, k;
    double lref, lgot;
    test_rng_seed(&r, 34u);
    total = sample(&r, modes, 2u, SAMPLES - SAMPLES / 10u, 256u);
    g_hist[255] += SAMPLES / 10u;
    total += SAMPLES / 10u;
    /* the starts, K = 2..6 */
    memset(&c, 0, sizeof c);
    c.init = SSDA_MIX_INIT_PEAKS;
    c.sigma_min_q16 = SSDA_MIX_DEFAULT_SIGMA_MIN_Q16;
    w->cache = (int32_t *)(void *)((uint8_t *)g_work_mem + SSDA_MIX_WORK_FIXED);
    for (k = 2u; k <= 6u; k++) {
        ssda__mix_init(g_hist, 256u, total, ssda__mix_scale_shift(g_hist, 256u), &c, k, w);
        for (i = 0; i < k; i++) {
            for (j = i + 1u; j < k; j++) {
                const double d = fabs(w->p[j].mean_q16 / Q16 - w->p[i].mean_q16 / Q16);
                /* a start of FWHM <= 6 bins: none other within 2 bins */
                const double sd = w->p[i].sigma_q16 / Q16;
                TEST_ASSERT_TRUE_MESSAGE(sd > 6.0 / 2.3548 || d > 2.0, "two starts on one peak");
            }
        }
    }
    /* K = 3 by EM: one component per mode and one on the spike, as the
       double EM from the generating mixture (800 steps) finds them */
    cfg = config(3u, SSDA_MIX_FIT_EM);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(256u, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(3u, m.count);
    model_comps(&m, got);
    for (j = 0; j < 3u; j++) {
        ref[j] = truth[j];
    }
    ref_em(ref, 3u, 256u, 800u, 0.5);
    for (j = 0; j < 3u; j++) {
        TEST_ASSERT_DOUBLE_WITHIN(0.002, ref[j].w, got[j].w);
        TEST_ASSERT_DOUBLE_WITHIN(0.01 * ref[j].sd, ref[j].mu, got[j].mu);
        TEST_ASSERT_DOUBLE_WITHIN(0.01 * ref[j].sd, ref[j].sd, got[j].sd);
    }
    lref = loglik(ref, 3u, 256u);
    lgot = loglik(got, 3u, 256u);
    TEST_ASSERT_TRUE(lgot >= lref - 1e-6 * fabs(lref));
    /* and the generating mixture within the sampling error */
    check_recovery(truth, 3u, &m, 0.01, 0.05);
    /* K = 4..6 by EM: no two components at one mean and sigma (a copy
       adds nothing to the likelihood; the old starts left two to four on
       the spike) */
    for (k = 4u; k <= 6u; k++) {
        cfg = config((uint8_t)k, SSDA_MIX_FIT_EM);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(256u, &cfg, &m));
        TEST_ASSERT_EQUAL_UINT32(k, m.count);
        for (i = 0; i + 1u < k; i++) {
            const double dm = (m.comp[i + 1u].mean_q16 - m.comp[i].mean_q16) / Q16;
            const double ds = fabs((double)m.comp[i + 1u].sigma_q16 - m.comp[i].sigma_q16) / Q16;
            TEST_ASSERT_FALSE_MESSAGE(dm < 0.5 && ds < 0.1, "two components on one peak");
        }
    }
    /* BIC: 3 of up to 8, the same fit */
    cfg = config(0u, SSDA_MIX_FIT_EM);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(256u, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(3u, m.count);
    check_recovery(truth, 3u, &m, 0.01, 0.05);
}

/* ---- the seed's search ---- */

/* The seed's error of a model over one window, in double (scaled counts). */
static double seed_error(const comp_t *c, uint32_t k, double total, uint32_t lo, uint32_t hi,
                         uint32_t hs)
{
    double e = 0.0;
    uint32_t z;
    for (z = lo; z <= hi; z++) {
        const double d = (double)(g_hist[z] >> hs) - total / (double)(1u << hs) *
                                                         density(c, k, (double)z);
        e += d * d;
    }
    return e;
}

static void test_search(void)
{
    static const comp_t truth[4] = {{0.35, 100.0, 10.0}, {0.15, 160.0, 14.0},
                                    {0.40, 300.0, 30.0}, {0.10, 420.0, 9.0}};
    test_rng_t r;
    ssda_mix_model_t seed, refined;
    ssda_mix_config_t cfg;
    comp_t c0[4], c1[4], c2[4];
    ssda__mix_work_t *w = (ssda__mix_work_t *)(void *)g_work_mem;
    ssda__mix_cfg_t c;
    uint32_t total, hs, j, lo = BINS, hi = 0;
    double total_d, sum = 0.0;
    test_rng_seed(&r, 33u);
    total = sample(&r, truth, 4u, SAMPLES, 512u);
    total_d = (double)total;
    hs = ssda__mix_scale_shift(g_hist, 512u);
    /* the start, for the errors before */
    memset(&c, 0, sizeof c);
    c.sigma_min_q16 = SSDA_MIX_DEFAULT_SIGMA_MIN_Q16;
    w->cache = (int32_t *)(void *)((uint8_t *)g_work_mem + SSDA_MIX_WORK_FIXED);
    ssda__mix_init(g_hist, 512u, total, hs, &c, 4u, w);
    for (j = 0; j < 4u; j++) {
        sum += (double)w->p[j].n;
    }
    for (j = 0; j < 4u; j++) {
        const double lo_j = w->p[j].mean_q16 / Q16 - 2.0 * w->p[j].sigma_q16 / Q16;
        const double hi_j = w->p[j].mean_q16 / Q16 + 2.0 * w->p[j].sigma_q16 / Q16;
        c0[j].w = (double)w->p[j].n / sum;
        c0[j].mu = w->p[j].mean_q16 / Q16;
        c0[j].sd = w->p[j].sigma_q16 / Q16;
        lo = lo_j < lo ? (uint32_t)ceil(lo_j < 0.0 ? 0.0 : lo_j) : lo;
        hi = hi_j > hi ? (uint32_t)floor(hi_j > 511.0 ? 511.0 : hi_j) : hi;
    }
    cfg = config(4u, SSDA_MIX_FIT_SEARCH);
    cfg.flags = SSDA_MIX_SEED_STEPS;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(512u, &cfg, &seed));
    cfg.flags = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(512u, &cfg, &refined));
    TEST_ASSERT_TRUE(seed.iterations >= 1u && seed.iterations <= refined.iterations);
    model_comps(&seed, c1);
    model_comps(&refined, c2);
    /* heights x widths normalised: the search fit's density times the
       total is its model of the counts (up to the normalisation of the
       weights, a few per cent): the union of the windows' error falls */
    {
        const double e0 = seed_error(c0, 4u, total_d, lo, hi, hs);
        const double e1 = seed_error(c1, 4u, total_d, lo, hi, hs);
        const double e2 = seed_error(c2, 4u, total_d, lo, hi, hs);
        char msg[120];
        snprintf(msg, sizeof msg, "search: error over the windows %lu at start, %lu seed steps, "
                 "%lu refined (%u, %u cycles)", (unsigned long)e0, (unsigned long)e1,
                 (unsigned long)e2, (unsigned)seed.iterations, (unsigned)refined.iterations);
        printf("%s\n", msg);
        TEST_ASSERT_TRUE(e1 < e0);
        TEST_ASSERT_TRUE(e2 <= e1 * 1.01);
    }
    check_recovery(truth, 4u, &refined, 0.05, 0.25);
}

/* ---- labels ---- */

/* The rule in double: the label of bin z. *margin: how close the decision
   was (the gap between the best and the next eligible score, or the
   distance to a band edge in sigmas). */
static uint8_t ref_label(const ssda_mix_model_t *m, uint8_t rule, double band, uint32_t z,
                         double *margin)
{
    double best = -1e300, second = -1e300, edge = 1e300;
    uint8_t label = 0u;
    uint32_t j;
    for (j = 0; j < m->count; j++) {
        const double w = m->comp[j].weight_q16 / Q16, mu = m->comp[j].mean_q16 / Q16;
        const double sd = m->comp[j].sigma_q16 / Q16;
        const double t = (z - mu) / sd;
        const double s = log(w / sd) - 0.5 * t * t;
        const double dist = fabs(fabs(t) - band);
        edge = dist < edge ? dist : edge;
        if (w <= 0.0 || (rule == SSDA_MIX_LABEL_BAND && fabs(t) > band)) {
            continue;
        }
        if (s > best) {
            second = best;
            best = s;
            label = (uint8_t)(j + 1u);
        } else if (s > second) {
            second = s;
        }
    }
    *margin = best - second;
    if (rule == SSDA_MIX_LABEL_BAND && edge < *margin) {
        *margin = edge;
    }
    return label;
}

static void test_lut(void)
{
    static const comp_t truth[5] = {{0.2, 100.0, 10.0}, {0.2, 125.0, 20.0},
                                    {0.3, 200.0, 5.0},  {0.2, 210.0, 30.0},
                                    {0.1, 400.0, 40.0}};
    static uint8_t lut[BINS];
    static uint8_t labels[BINS];
    static uint16_t values[BINS];
    test_rng_t r;
    ssda_mix_model_t m;
    ssda_mix_config_t cfg = config(5u, SSDA_MIX_FIT_EM);
    uint32_t rule, z, j, close = 0u;
    uint32_t band[4] = {0u, 256u, 768u, 4096u};
    uint32_t px[SSDA_MIX_MAX_COMPONENTS];
    test_rng_seed(&r, 34u);
    (void)sample(&r, truth, 5u, SAMPLES, 512u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(512u, &cfg, &m));
    for (j = 1; j < m.count; j++) {
        TEST_ASSERT_TRUE(m.comp[j - 1u].mean_q16 <= m.comp[j].mean_q16); /* sorted */
    }
    for (rule = 0; rule < 2u; rule++) {
        for (j = 0; j < 4u; j++) {
            const double b = (band[j] == 0u ? 512u : band[j]) / 256.0;
            memset(lut, 0xEE, sizeof lut);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_lut(&m, (uint8_t)rule, band[j], lut));
            for (z = 0; z < 512u; z++) {
                double margin;
                const uint8_t want = ref_label(&m, (uint8_t)rule, b, z, &margin);
                if (want != lut[z]) {
                    /* only where the decision is within rounding */
                    TEST_ASSERT_TRUE(margin < 1e-4);
                    close++;
                }
            }
            TEST_ASSERT_EQUAL_HEX8(0xEEu, lut[512]);
        }
    }
    TEST_ASSERT_TRUE(close < 4u);
    /* label_row: one read per value, out of range and nodata to 0 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_lut(&m, SSDA_MIX_LABEL_LIKELY, 0u, lut));
    for (z = 0; z < BINS; z++) {
        values[z] = (uint16_t)(test_rng_next(&r) % 1100u);
    }
    values[0] = 0xFFFFu;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_label_row(lut, 512u, values, BINS, 1u, labels));
    for (z = 0; z < BINS; z++) {
        const uint32_t b = values[z] >> 1;
        TEST_ASSERT_EQUAL_UINT8(b < 512u ? lut[b] : 0u, labels[z]);
    }
    /* band areas: direct sums */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_band_pixels(&m, g_hist, 0u, px));
    for (j = 0; j < m.count; j++) {
        const double mu = m.comp[j].mean_q16 / Q16, sd = m.comp[j].sigma_q16 / Q16;
        uint32_t n = 0u;
        for (z = 0; z < 512u; z++) {
            n += fabs(z - mu) <= 2.0 * sd ? g_hist[z] : 0u;
        }
        TEST_ASSERT_EQUAL_UINT32(n, px[j]);
    }
}

static void test_hist_add(void)
{
    static uint16_t v[3000];
    static uint32_t h[300];
    uint32_t want[300] = {0}, i, skipped = 5u;
    test_rng_t r;
    test_rng_seed(&r, 35u);
    for (i = 0; i < 3000u; i++) {
        v[i] = (uint16_t)test_rng_next(&r);
        if (i % 3u == 0u) {
            v[i] = (uint16_t)(v[i] % 1200u);
        }
    }
    memset(h, 0, sizeof h);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_hist_add(h, 300u, v, 3000u, 2u, &skipped));
    for (i = 0; i < 3000u; i++) {
        if ((v[i] >> 2) < 300u) {
            want[v[i] >> 2]++;
        }
    }
    TEST_ASSERT_EQUAL_MEMORY(want, h, sizeof h);
    {
        uint32_t n = 0u;
        for (i = 0; i < 300u; i++) {
            n += want[i];
        }
        TEST_ASSERT_EQUAL_UINT32(5u + 3000u - n, skipped);
    }
    skipped = UINT32_MAX - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_hist_add(h, 300u, v, 3000u, 2u, &skipped));
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, skipped);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_hist_add(h, 300u, v, 3000u, 2u, NULL));
}

/* ---- worst cases and degenerate histograms ---- */

static void test_worst_case(void)
{
    ssda_mix_model_t m;
    ssda_mix_config_t cfg;
    uint32_t fit_kind, z;
    /* 2^32 - 1 pixels: one full bin and a neighbour, and a spike at the
       top bin of the largest histogram */
    for (fit_kind = 0; fit_kind < 2u; fit_kind++) {
        memset(g_hist, 0, sizeof g_hist);
        g_hist[100] = 4000000000u;
        g_hist[101] = 294967295u;
        g_hist[SSDA_MIX_MAX_BINS - 1u] = 0u;
        cfg = config(2u, (uint8_t)fit_kind);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_fit(g_hist, SSDA_MIX_MAX_BINS, &cfg, g_work_mem,
                                                    sizeof g_work_mem, &m));
        TEST_ASSERT_EQUAL_UINT32(4294967295u, m.total);
        /* the mean of all pixels lies between the two bins */
        TEST_ASSERT_TRUE(m.comp[0].mean_q16 >= 100u * 65536u);
        TEST_ASSERT_TRUE(m.comp[m.count - 1u].mean_q16 <= 101u * 65536u);
        TEST_ASSERT_TRUE(m.loglik_q16 < 0);
        /* every bin full: 4096 bins of 2^32 / 4096 - 1 */
        for (z = 0; z < SSDA_MIX_MAX_BINS; z++) {
            g_hist[z] = 1048575u;
        }
        cfg = config(fit_kind == 0u ? 16u : 3u, (uint8_t)fit_kind);
        cfg.max_iter = 3u;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_fit(g_hist, SSDA_MIX_MAX_BINS, &cfg, g_work_mem,
                                                    sizeof g_work_mem, &m));
        /* the log-likelihood near -2^32 ln 4096 (2^51 in Q16): as in double */
        {
            comp_t got[SSDA_MIX_MAX_COMPONENTS];
            double lref;
            model_comps(&m, got);
            lref = loglik(got, m.count, SSDA_MIX_MAX_BINS);
            TEST_ASSERT_DOUBLE_WITHIN(fabs(lref) * 2e-6 + m.count * 4294963200.0 / 131072.0, lref,
                                      (double)m.loglik_q16 / Q16);
            TEST_ASSERT_TRUE(lref < -0.9 * 4294963200.0 * log(4096.0));
        }
    }
    /* one occupied bin, more components than bins occupied (quantile
       start with empty slices; dead components) */
    memset(g_hist, 0, sizeof g_hist);
    g_hist[7] = 1000u;
    cfg = config(4u, SSDA_MIX_FIT_EM);
    cfg.init = SSDA_MIX_INIT_QUANTILES;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(16u, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(4u, m.count);
    for (z = 0; z < 4u; z++) {
        TEST_ASSERT_TRUE(m.comp[z].sigma_q16 >= 32768u);
    }
    cfg.init = SSDA_MIX_INIT_PEAKS;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(16u, &cfg, &m)); /* residual runs out: quantiles */
    cfg.fit = SSDA_MIX_FIT_SEARCH;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(16u, &cfg, &m));
    /* a flat histogram to both ends: the peak's width is the histogram's */
    for (z = 0; z < 16u; z++) {
        g_hist[z] = 10u;
    }
    cfg = config(1u, SSDA_MIX_FIT_EM);
    cfg.max_iter = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(16u, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(0u, m.comp[0].mean_q16);
    TEST_ASSERT_EQUAL_UINT32(16u * 27831u, m.comp[0].sigma_q16);
    /* a peak at the right end: one-sided width */
    memset(g_hist, 0, sizeof g_hist);
    g_hist[15] = 100u;
    g_hist[14] = 60u;
    g_hist[13] = 40u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(16u, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(15u * 65536u, m.comp[0].mean_q16);
}

/* Band edges and ties of the label rules on a model made here: bins
   exactly band sigmas from a mean are inside (|z - mu| <= band sigma), and
   of equally likely components the lower label wins (mixture.h). */
static void test_lut_edges_and_ties(void)
{
    static const uint32_t band_q8[3] = {512u, 256u, 384u};
    ssda_mix_model_t m;
    uint8_t lut[32];
    uint32_t px[2], b, z, j, rule;
    memset(&m, 0, sizeof m);
    m.count = 2u;
    m.bins = 32u;
    for (j = 0; j < 2u; j++) {
        m.comp[j].weight_q16 = 32768u;
        m.comp[j].mean_q16 = (10u + 10u * j) << 16; /* 10 and 20 */
        m.comp[j].sigma_q16 = 2u << 16;
    }
    memset(g_hist, 0, sizeof g_hist);
    for (z = 0; z < 32u; z++) {
        g_hist[z] = 1u + z;
    }
    for (b = 0; b < 3u; b++) {
        const double band = band_q8[b] / 256.0;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_lut(&m, SSDA_MIX_LABEL_BAND, band_q8[b], lut));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_band_pixels(&m, g_hist, band_q8[b], px));
        for (j = 0; j < 2u; j++) {
            const double mu = 10.0 + 10.0 * j;
            uint32_t n = 0u;
            for (z = 0; z < 32u; z++) {
                n += fabs((double)z - mu) <= band * 2.0 ? g_hist[z] : 0u;
            }
            TEST_ASSERT_EQUAL_UINT32(n, px[j]);
        }
        for (z = 0; z < 32u; z++) {
            const double d0 = fabs((double)z - 10.0), d1 = fabs((double)z - 20.0);
            /* equal weights and sigmas: the nearer mean is the likelier */
            uint8_t want = 0u;
            if (d0 <= band * 2.0 && (d0 <= d1 || d1 > band * 2.0)) {
                want = 1u;
            } else if (d1 <= band * 2.0) {
                want = 2u;
            }
            TEST_ASSERT_EQUAL_UINT8(want, lut[z]);
        }
    }
    /* the tie at bin 15, both rules: the lower label */
    for (rule = 0; rule < 2u; rule++) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_lut(&m, (uint8_t)rule, 768u, lut));
        TEST_ASSERT_EQUAL_UINT8(1u, lut[15]);
        TEST_ASSERT_EQUAL_UINT8(2u, lut[16]);
    }
}

/* q(z) = ((z - mu) / (sqrt2 sigma))^2 in Q16 against double over sigmas
   from 2^-16 to 4096 bins, any mean and bin: within 4 sqrt(q) + 2 steps
   (mixture.h), and the cap at 16384 nats exactly where it is due. */
static void test_q_vs_double(void)
{
    test_rng_t r;
    uint32_t t;
    double worst = 0.0;
    test_rng_seed(&r, 36u);
    for (t = 0; t < Q_CASES; t++) {
        const uint32_t sigma = 1u + (test_rng_next(&r) >> (test_rng_next(&r) % 32u)) % (4096u << 16);
        const uint32_t mean = test_rng_next(&r) % (4095u << 16);
        const uint32_t z = test_rng_next(&r) % 4096u;
        ssda__mix_gauss_t g;
        double d, ex, got, tol;
        ssda__mix_prepare(&g, 1u, 1u, mean, sigma);
        d = ((double)z * Q16 - mean) / (sqrt(2.0) * sigma);
        ex = d * d * Q16;
        got = (double)ssda__mix_q(&g, z);
        if (ex > 16384.0 * Q16 * 1.001) {
            TEST_ASSERT_EQUAL_UINT32(1073741824u, ssda__mix_q(&g, z));
            continue;
        }
        if (ex > 16384.0 * Q16 * 0.999) {
            continue; /* at the cap: either */
        }
        tol = 4.0 * sqrt(ex / Q16) + 2.0;
        worst = fabs(got - ex) / tol > worst ? fabs(got - ex) / tol : worst;
        TEST_ASSERT_DOUBLE_WITHIN(tol, ex, got);
    }
    printf("q vs double: worst error %u%% of the bound\n", (unsigned)(worst * 100.0));
}

/* Internal paths the public fits reach only on rare data. */
static void test_internal_paths(void)
{
    ssda__mix_work_t *w = (ssda__mix_work_t *)(void *)g_work_mem;
    ssda__mix_cfg_t c;
    ssda__mix_gauss_t g[2];
    ssda_mix_model_t m;
    ssda_mix_config_t cfg;
    uint8_t lut[64];
    uint32_t px[2];
    int64_t ll = 0;
    memset(&c, 0, sizeof c);
    c.max_iter = 5u;
    c.sigma_min_q16 = 4u; /* below 8: steps of sigma / 8 round to 0 */
    w->cache = (int32_t *)(void *)((uint8_t *)g_work_mem + SSDA_MIX_WORK_FIXED);
    memset(g_hist, 0, sizeof g_hist);
    g_hist[2] = 1000u;
    g_hist[3] = 500u;
    /* a component far from every count owns none of it: dead, weight 0 */
    w->p[0].n = 1000u;
    w->p[0].mean_q16 = 2u << 16;
    w->p[0].sigma_q16 = 65536u;
    w->p[1].n = 1u;
    w->p[1].mean_q16 = 60u << 16;
    w->p[1].sigma_q16 = 32768u;
    TEST_ASSERT_TRUE(ssda__mix_em(g_hist, 64u, &c, 2u, w, &ll) >= 2u);
    TEST_ASSERT_EQUAL_UINT64(0u, w->p[1].n);
    /* no component active: nothing is added */
    ssda__mix_prepare(&g[0], 0u, 1u, 0u, 65536u);
    ssda__mix_prepare(&g[1], 0u, 1u, 0u, 65536u);
    TEST_ASSERT_EQUAL_INT64(0, ssda__mix_estep(g_hist, 64u, g, 2u, NULL));
    /* a search window narrower than a bin between two bins, sigma < 8 */
    w->p[0].mean_q16 = (2u << 16) + 32768u;
    w->p[0].sigma_q16 = 4u;
    w->height_q8[0] = 5; /* height / 16 rounds to 0: a step of 1 */
    w->p[1].mean_q16 = 3u << 16;
    w->p[1].sigma_q16 = 65536u;
    w->height_q8[1] = 2000;
    TEST_ASSERT_TRUE(ssda__mix_search(g_hist, 64u, 0u, &c, 2u, w) >= 1u);
    TEST_ASSERT_EQUAL_UINT32(w->lo[0], w->hi[0]);
    /* a model with a zero weight: that component never labels */
    memset(&m, 0, sizeof m);
    m.count = 2u;
    m.bins = 64u;
    m.comp[0].weight_q16 = 0u;
    m.comp[0].mean_q16 = 10u << 16;
    m.comp[0].sigma_q16 = 65536u;
    m.comp[1].weight_q16 = 65536u;
    m.comp[1].mean_q16 = 40u << 16;
    m.comp[1].sigma_q16 = 65536u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_lut(&m, SSDA_MIX_LABEL_LIKELY, 0u, lut));
    TEST_ASSERT_EQUAL_UINT8(2u, lut[10]);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_lut(&m, SSDA_MIX_LABEL_BAND, 0u, lut));
    TEST_ASSERT_EQUAL_UINT8(0u, lut[10]);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_band_pixels(&m, g_hist, 256u * 9u, px));
    TEST_ASSERT_EQUAL_UINT32(1500u, px[0]); /* 2 and 3 are within 9 sigma of 10 */
    TEST_ASSERT_EQUAL_UINT32(0u, px[1]);
    /* one spike and a small sigma floor: the quantile start's height is
       capped at 2^25 for the search */
    memset(g_hist, 0, sizeof g_hist);
    g_hist[30] = 65535u;
    cfg = config(1u, SSDA_MIX_FIT_SEARCH);
    cfg.init = SSDA_MIX_INIT_QUANTILES;
    cfg.sigma_min_q16 = 6554u; /* 0.1 bin */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(64u, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(30u << 16, m.comp[0].mean_q16);
    TEST_ASSERT_TRUE(m.comp[0].sigma_q16 >= 6554u);
    /* a peak at the left end: one-sided width */
    memset(g_hist, 0, sizeof g_hist);
    g_hist[0] = 100u;
    g_hist[1] = 60u;
    g_hist[2] = 40u;
    cfg = config(1u, SSDA_MIX_FIT_EM);
    cfg.max_iter = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, fit(16u, &cfg, &m));
    TEST_ASSERT_EQUAL_UINT32(0u, m.comp[0].mean_q16);
}

static void test_errors(void)
{
    ssda_mix_model_t m, poison;
    ssda_mix_config_t cfg;
    uint8_t lut[16];
    uint16_t v[2] = {1u, 2u};
    uint32_t px[16];
    memset(&poison, 0x5A, sizeof poison);
    memcpy(&m, &poison, sizeof m);
    memset(g_hist, 0, sizeof g_hist);
    g_hist[3] = 5u;
    cfg = config(1u, 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_fit(NULL, 16u, &cfg, g_work_mem, sizeof g_work_mem, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_fit(g_hist, 16u, &cfg, NULL, sizeof g_work_mem, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_fit(g_hist, 16u, &cfg, g_work_mem, sizeof g_work_mem, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, fit(1u, &cfg, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, fit(4097u, &cfg, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, fit(3u, &cfg, &m)); /* empty */
    cfg.components = 17u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, fit(16u, &cfg, &m));
    cfg = config(0u, 0u);
    cfg.max_components = 17u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, fit(16u, &cfg, &m));
    cfg = config(1u, 2u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, fit(16u, &cfg, &m));
    cfg = config(1u, 0u);
    cfg.init = 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, fit(16u, &cfg, &m));
    cfg = config(1u, 0u);
    cfg.flags = 0x02u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, fit(16u, &cfg, &m));
    cfg = config(1u, 0u);
    cfg.sigma_min_q16 = 16u * 65536u + 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, fit(16u, &cfg, &m));
    cfg = config(1u, 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_mix_fit(g_hist, 16u, &cfg, g_work_mem,
                                                        SSDA_MIX_WORK_SIZE(16u) - 1u, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_mix_fit(g_hist, 16u, &cfg,
                                                        (uint8_t *)g_work_mem + 4,
                                                        SSDA_MIX_WORK_SIZE(16u), &m));
    g_hist[4] = 4294967295u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_OVERFLOW, fit(16u, &cfg, &m));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &m, sizeof m);
    g_hist[4] = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_mix_fit(g_hist, 16u, NULL, g_work_mem, SSDA_MIX_WORK_SIZE(16u), &m));
    /* lut, label_row, band_pixels, hist_add */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_lut(NULL, 0u, 0u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_lut(&m, 0u, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_lut(&m, 2u, 0u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_lut(&m, 0u, 4097u, lut));
    poison = m;
    poison.count = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_lut(&poison, 0u, 0u, lut));
    poison.count = 17u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_lut(&poison, 0u, 0u, lut));
    /* a component of sigma 0 has no density (it shifted by 2^32 - 23) */
    poison = m;
    poison.comp[poison.count - 1u].sigma_q16 = 0u;
    memset(lut, 0xA5, sizeof lut);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_lut(&poison, 0u, 0u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_lut(&poison, 1u, 0u, lut));
    TEST_ASSERT_EACH_EQUAL_HEX8(0xA5u, lut, sizeof lut);
    memset(px, 0xA5, sizeof px);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_band_pixels(&poison, g_hist, 0u, px));
    TEST_ASSERT_EACH_EQUAL_HEX32(0xA5A5A5A5u, px, 16u);
    poison = m;
    poison.bins = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_band_pixels(&poison, g_hist, 0u, px));
    poison.bins = 4097u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_band_pixels(&poison, g_hist, 0u, px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_band_pixels(NULL, g_hist, 0u, px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_band_pixels(&m, NULL, 0u, px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_band_pixels(&m, g_hist, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_label_row(NULL, 16u, v, 2u, 0u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_label_row(lut, 16u, NULL, 2u, 0u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_label_row(lut, 16u, v, 2u, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_mix_label_row(lut, 0u, v, 2u, 0u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_mix_label_row(lut, 4097u, v, 2u, 0u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_label_row(lut, 16u, v, 2u, 16u, lut));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_hist_add(NULL, 16u, v, 2u, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_mix_hist_add(px, 16u, NULL, 2u, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_mix_hist_add(px, 0u, v, 2u, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_mix_hist_add(px, 4097u, v, 2u, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_mix_hist_add(px, 16u, v, 2u, 16u, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_work_layout);
    RUN_TEST(test_em_vs_double);
    RUN_TEST(test_recovery);
    RUN_TEST(test_spike);
    RUN_TEST(test_search);
    RUN_TEST(test_lut);
    RUN_TEST(test_lut_edges_and_ties);
    RUN_TEST(test_q_vs_double);
    RUN_TEST(test_hist_add);
    RUN_TEST(test_worst_case);
    RUN_TEST(test_internal_paths);
    RUN_TEST(test_errors);
    return UNITY_END();
}
