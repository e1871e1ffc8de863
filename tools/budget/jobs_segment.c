/*
 * jobs_segment.c - colour segmentation (kl.h, mixture.h, region.h) on the
 * emulated Cortex-M4: instructions per pixel of the streamed passes (band
 * statistics, the K-L transform into three features, labelling through the
 * look-up table, isolated-point removal) and per fit (K-L solve, an EM
 * iteration and the seed's search on a 256-bin histogram of 4 components).
 * Results are checked against the expected labels of a 4-class image; a
 * mismatch fails the run.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/kl.h"
#include "ssda/mixture.h"
#include "ssda/region.h"

#define SW 256u
#define SH 16u
#define BINS 256u

static uint8_t g_rgb[SW * SH * 3u];
static uint8_t g_class[SW * SH];
static uint16_t g_z[3][SW];
static uint16_t g_z1[SW * SH];
static uint32_t g_hist[BINS];
static uint8_t g_lut[BINS];
static uint8_t g_labels[SW * SH], g_clean[SW * SH];
static uint8_t g_ring[SSDA_REGION_RING_SIZE(SW)];
static uint64_t g_work[(SSDA_MIX_WORK_SIZE(BINS) + 7u) / 8u];

typedef struct {
    ssda_kl_acc_t acc;
    ssda_kl_t kl;
    ssda_mix_model_t model;
    ssda_mix_config_t mc;
    ssda_region_t job;
    uint32_t y;
    int ret;
} seg_job_t;

/* Four gray levels in vertical stripes with noise: Z1 separates them. */
static void make_image(void)
{
    static const uint8_t level[4] = {40, 100, 160, 220};
    uint32_t i, k, st = 0x5E6u;
    for (i = 0; i < SW * SH; i++) {
        const uint32_t c = (i % SW) / (SW / 4u);
        g_class[i] = (uint8_t)c;
        for (k = 0; k < 3u; k++) {
            g_rgb[i * 3u + k] = (uint8_t)(level[c] + (jobs_rand(&st) % 9u) - 4u);
        }
    }
}

static ssda_kl_row_t row_at(uint32_t y)
{
    const uint8_t *p = g_rgb + (size_t)y * SW * 3u;
    ssda_kl_row_t r;
    r.band[0] = p;
    r.band[1] = p + 1;
    r.band[2] = p + 2;
    r.step = 3u;
    return r;
}

static void acc_rows(void *ctx)
{
    seg_job_t *j = (seg_job_t *)ctx;
    uint32_t y;
    for (y = 0; y < SH; y++) {
        const ssda_kl_row_t r = row_at(y);
        j->ret |= ssda_kl_acc_add_row(&j->acc, &r, SW);
    }
}

static void solve(void *ctx)
{
    seg_job_t *j = (seg_job_t *)ctx;
    ssda_kl_config_t kc;
    memset(&kc, 0, sizeof kc);
    kc.out_max = BINS - 1u;
    kc.gain_max_q16 = 65536u;
    j->ret |= ssda_kl_solve(&j->acc, &kc, &j->kl);
}

static void transform_rows(void *ctx)
{
    seg_job_t *j = (seg_job_t *)ctx;
    uint32_t y;
    for (y = 0; y < SH; y++) {
        const ssda_kl_row_t r = row_at(y);
        uint16_t *out[3] = {g_z[0], g_z[1], g_z[2]};
        j->ret |= ssda_kl_transform_row(&j->kl, &r, SW, out, NULL);
        memcpy(g_z1 + y * SW, g_z[0], sizeof g_z[0]);
    }
}

static void fit(void *ctx)
{
    seg_job_t *j = (seg_job_t *)ctx;
    j->ret |= ssda_mix_fit(g_hist, BINS, &j->mc, g_work, sizeof g_work, &j->model);
}

static void label_rows(void *ctx)
{
    seg_job_t *j = (seg_job_t *)ctx;
    uint32_t y;
    for (y = 0; y < SH; y++) {
        j->ret |= ssda_mix_label_row(g_lut, BINS, g_z1 + y * SW, SW, 0u, g_labels + y * SW);
    }
}

static void clean_rows(void *ctx)
{
    seg_job_t *j = (seg_job_t *)ctx;
    uint32_t y, done = 0u;
    for (y = 0; y < SH; y++) {
        const int n = ssda_region_push(&j->job, g_labels + y * SW, g_clean + done * SW);
        done += n > 0 ? (uint32_t)n : 0u;
    }
    j->ret |= ssda_region_flush(&j->job, g_clean + done * SW) == 1 ? 0 : -1;
}

static void report_per(const char *name, budget_job_fn fn, seg_job_t *j, uint32_t units)
{
    const uint32_t n = budget_instructions(fn, j);
    budget_report(name, n, units, 0u, 0u);
}

void jobs_segment(void)
{
    static seg_job_t j;
    ssda_region_config_t rc;
    uint32_t i, stack, iters;
    make_image();
    memset(&j, 0, sizeof j);
    j.ret = ssda_kl_acc_init(&j.acc, NULL);
    stack = budget_stack_peak(acc_rows, &j);
    j.ret |= ssda_kl_acc_init(&j.acc, NULL);
    budget_report("segment.kl_acc", budget_instructions(acc_rows, &j), SW * SH, stack, 0u);
    stack = budget_stack_peak(solve, &j);
    budget_report("segment.kl_solve", budget_instructions(solve, &j), 1u, stack, 0u);
    stack = budget_stack_peak(transform_rows, &j);
    budget_report("segment.kl_transform", budget_instructions(transform_rows, &j), SW * SH, stack,
                  0u);
    memset(g_hist, 0, sizeof g_hist);
    j.ret |= ssda_mix_hist_add(g_hist, BINS, g_z1, SW * SH, 0u, NULL);
    /* EM for exactly 20 iterations (tolerance 0 in effect: 1 LSB), then
       the seed's search; K = 4 */
    memset(&j.mc, 0, sizeof j.mc);
    j.mc.components = 4u;
    j.mc.max_iter = 20u;
    j.mc.tol_q24 = 1u;
    stack = budget_stack_peak(fit, &j);
    i = budget_instructions(fit, &j);
    iters = j.model.iterations;
    budget_report("segment.em_fit", i, iters, stack, 0u);
    j.mc.fit = SSDA_MIX_FIT_SEARCH;
    j.mc.max_iter = 0u;
    stack = budget_stack_peak(fit, &j);
    budget_report("segment.search_fit", budget_instructions(fit, &j), 1u, stack,
                  j.model.iterations);
    j.mc.fit = SSDA_MIX_FIT_EM;
    j.mc.max_iter = 0u;
    j.mc.tol_q24 = 0u;
    fit(&j);
    j.ret |= ssda_mix_lut(&j.model, SSDA_MIX_LABEL_LIKELY, 0u, g_lut);
    stack = budget_stack_peak(label_rows, &j);
    report_per("segment.label", label_rows, &j, SW * SH);
    memset(&rc, 0, sizeof rc);
    rc.width = SW;
    rc.height = SH;
    rc.op = SSDA_REGION_CLEAN;
    j.ret |= ssda_region_init(&j.job, &rc, g_ring, sizeof g_ring);
    stack = budget_stack_peak(clean_rows, &j);
    j.ret |= ssda_region_init(&j.job, &rc, g_ring, sizeof g_ring);
    budget_report("segment.clean", budget_instructions(clean_rows, &j), SW * SH, stack, 0u);
    /* the four stripes are the four labels, in order */
    for (i = 0; i < SW * SH; i++) {
        if (g_clean[i] != (uint8_t)(g_class[i] + 1u)) {
            j.ret = -1;
        }
    }
    if (j.ret != 0 || j.model.count != 4u) {
        budget_fail("segment");
    }
}
