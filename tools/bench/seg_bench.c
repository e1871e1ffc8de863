/*
 * seg_bench.c - ssda-bench-segment: parameter errors of the two mixture fits
 * (EM and the seed's coordinate search) on sampled mixtures with known
 * parameters, from the same start, and their time per fit. A benchmark
 * (tools/bench-segment.sh prints its table), not a test.
 *   ssda-bench-segment [--reps R] [--samples N]
 * Each case: R histograms of N samples (1024 bins, deterministic seeds); K =
 * the true number of components; components matched to the truth by rank of
 * mean (both sorted). Errors: |w - w0|, |mu - mu0| / sd0, |sd - sd0| / sd0,
 * averaged over components and repetitions; the log-likelihood of the fit
 * minus that of the true parameters (bin-centre densities, nats per 1000
 * pixels: >= 0 means the fit explains the histogram at least as well as
 * the truth); time: median per fit. A second table: the K that BIC chooses
 * (components 0, EM, up to 8) on the same histograms, against the true K.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ssda/mixture.h"

#define BINS 1024u
#define MAXK 8

typedef struct {
    const char *name, *note;
    int k;
    double w[MAXK], mu[MAXK], sd[MAXK];
} mix_case_t;

static const mix_case_t k_cases[] = {
    {"separated", "3 components 6 sd or more apart", 3,
     {0.3, 0.4, 0.3}, {250, 500, 750}, {25, 40, 30}},
    {"touching", "3 components 2.7 to 3.5 sd apart", 3,
     {0.35, 0.35, 0.3}, {400, 482, 600}, {30, 30, 40}},
    {"seed-like", "6 components of the seed's Z1 kind", 6,
     {0.10, 0.20, 0.15, 0.30, 0.15, 0.10}, {300, 380, 430, 500, 600, 700},
     {20, 25, 15, 40, 30, 50}},
    {"overlapping", "2 components 1 sd apart", 2,
     {0.6, 0.4}, {500, 530}, {30, 20}},
    {"buried", "a small component inside a large one (the seed's Z1 model 2)", 2,
     {0.85, 0.15}, {500, 520}, {50, 10}},
};
#define NCASES (sizeof k_cases / sizeof k_cases[0])

static uint32_t g_s;

static double uniform(void)
{
    g_s ^= g_s << 13;
    g_s ^= g_s >> 17;
    g_s ^= g_s << 5;
    return ((double)g_s + 0.5) / 4294967296.0;
}

static double normal(void)
{
    return sqrt(-2.0 * log(uniform())) * cos(6.283185307179586 * uniform());
}

static void sample(const mix_case_t *c, uint32_t n, uint32_t *hist)
{
    uint32_t i;
    memset(hist, 0, BINS * sizeof *hist);
    for (i = 0; i < n; i++) {
        double u = uniform(), acc = 0.0, x;
        int j = 0;
        while (j + 1 < c->k && u > acc + c->w[j]) {
            acc += c->w[j];
            j++;
        }
        x = floor(c->mu[j] + c->sd[j] * normal() + 0.5);
        if (x >= 0.0 && x < BINS) {
            hist[(uint32_t)x]++;
        }
    }
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

typedef struct {
    double ew, em, es; /* summed errors */
    double gap;        /* summed log-likelihood gaps, nats per 1000 pixels */
    double *times;
    int n;             /* components x reps accumulated */
    int fails;
} score_t;

/* The automatic K on one case: how often each K was chosen, and times. */
typedef struct {
    int chosen[17];
    double *times;
    int fails;
} auto_t;

static void print_auto(const mix_case_t *c, auto_t *a, int reps)
{
    int k, first = 1;
    qsort(a->times, (size_t)reps, sizeof(double), cmp_double);
    printf("| %s | %d | ", c->name, c->k);
    for (k = 1; k <= 16; k++) {
        if (a->chosen[k] > 0) {
            printf("%s%d: %d of %d", first ? "" : ", ", k, a->chosen[k], reps);
            first = 0;
        }
    }
    if (a->fails > 0) {
        printf("%sfailed: %d", first ? "" : ", ", a->fails);
    }
    printf(" | %.2f ms |\n", 1e3 * a->times[reps / 2]);
}

/* The log-likelihood of the true parameters on the histogram. */
static double true_loglik(const mix_case_t *c, const uint32_t *hist)
{
    double ll = 0.0;
    uint32_t z;
    int j;
    for (z = 0; z < BINS; z++) {
        double p = 0.0;
        if (hist[z] == 0u) {
            continue;
        }
        for (j = 0; j < c->k; j++) {
            const double t = (z - c->mu[j]) / c->sd[j];
            p += c->w[j] / (c->sd[j] * 2.5066282746310002) * exp(-0.5 * t * t);
        }
        ll += hist[z] * log(p);
    }
    return ll;
}

static void score(const mix_case_t *c, const ssda_mix_model_t *m, double ll0, score_t *s)
{
    int j;
    s->gap += ((double)m->loglik_q16 / 65536.0 - ll0) / (m->total / 1000.0);
    for (j = 0; j < c->k; j++) {
        s->ew += fabs(m->comp[j].weight_q16 / 65536.0 - c->w[j]);
        s->em += fabs(m->comp[j].mean_q16 / 65536.0 - c->mu[j]) / c->sd[j];
        s->es += fabs(m->comp[j].sigma_q16 / 65536.0 - c->sd[j]) / c->sd[j];
        s->n++;
    }
}

int main(int argc, char **argv)
{
    static uint32_t hist[BINS];
    static uint64_t work[(SSDA_MIX_WORK_SIZE(BINS) + 7) / 8];
    static auto_t autok[NCASES];
    int reps = 10, i, r;
    uint32_t samples = 200000;
    size_t ci;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--reps") == 0 && i + 1 < argc) {
            reps = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--samples") == 0 && i + 1 < argc) {
            samples = (uint32_t)atoi(argv[++i]);
        } else {
            fprintf(stderr, "usage: ssda-bench-segment [--reps R] [--samples N]\n");
            return 2;
        }
    }
    if (reps < 1 || samples < 100) {
        fprintf(stderr, "ssda-bench-segment: --reps >= 1, --samples >= 100\n");
        return 2;
    }
    printf("Parameter errors of the two fits on sampled mixtures (%d histograms of %u samples "
           "per case, %u bins, K = the true K, the same peaks start):\n\n", reps, samples, BINS);
    printf("| case | fit | weight error | mean error (sd) | sd error (sd) | log-likelihood - "
           "truth's (nats / 1000 px) | median time per fit |\n"
           "|---|---|---:|---:|---:|---:|---:|\n");
    for (ci = 0; ci < NCASES; ci++) {
        const mix_case_t *c = &k_cases[ci];
        score_t s[2];
        memset(s, 0, sizeof s);
        s[0].times = calloc((size_t)reps, sizeof(double));
        s[1].times = calloc((size_t)reps, sizeof(double));
        autok[ci].times = calloc((size_t)reps, sizeof(double));
        for (r = 0; r < reps; r++) {
            int f;
            g_s = 0x9E3779B9u ^ (uint32_t)(r * 7919 + (int)ci * 104729);
            double ll0;
            sample(c, samples, hist);
            ll0 = true_loglik(c, hist);
            for (f = 0; f < 2; f++) { /* interleaved: EM, search */
                ssda_mix_config_t cfg;
                ssda_mix_model_t m;
                double t0;
                memset(&cfg, 0, sizeof cfg);
                cfg.components = (uint8_t)c->k;
                cfg.fit = f == 0 ? SSDA_MIX_FIT_EM : SSDA_MIX_FIT_SEARCH;
                t0 = now();
                if (ssda_mix_fit(hist, BINS, &cfg, work, sizeof work, &m) != SSDA_OK) {
                    s[f].fails++;
                    continue;
                }
                s[f].times[r] = now() - t0;
                score(c, &m, ll0, &s[f]);
            }
            { /* then K by BIC on the same histogram */
                ssda_mix_config_t cfg;
                ssda_mix_model_t m;
                double t0;
                memset(&cfg, 0, sizeof cfg);
                t0 = now();
                if (ssda_mix_fit(hist, BINS, &cfg, work, sizeof work, &m) != SSDA_OK) {
                    autok[ci].fails++;
                } else {
                    autok[ci].times[r] = now() - t0;
                    autok[ci].chosen[m.count]++;
                }
            }
        }
        for (i = 0; i < 2; i++) {
            qsort(s[i].times, (size_t)reps, sizeof(double), cmp_double);
            printf("| %s (%s) | %s | %.4f | %.3f | %.3f | %+.3f | %.2f ms |\n", c->name, c->note,
                   i == 0 ? "EM" : "seed's search", s[i].ew / s[i].n, s[i].em / s[i].n,
                   s[i].es / s[i].n, s[i].gap / reps, 1e3 * s[i].times[reps / 2]);
            free(s[i].times);
        }
    }
    printf("\nThe number of components chosen by BIC (components auto: EM for each K in "
           "1..8, least BIC) on the same histograms:\n\n"
           "| case | true K | K chosen | median time per automatic fit |\n|---|---:|---|---:|\n");
    for (ci = 0; ci < NCASES; ci++) {
        print_auto(&k_cases[ci], &autok[ci], reps);
        free(autok[ci].times);
    }
    return 0;
}
