/*
 * jobs_ncc.c - the correlation search (ncc.h) on the seed geometries: 16 x 16
 * windows in 32 x 32 areas (cloud tracking) and 20 x 20 in 40 x 40 (seed
 * 002's feature points, seed 003's templates), sixteen windows each from a
 * smooth texture with a brightness change (window = 3/4 area + 20, plus
 * noise), by early-exit setting. Every run must return the full search's
 * places, or the run fails.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/ncc.h"

#define IMG 128u
#define WINDOWS 16u
#define MAXW 20u
#define MAXA 40u

static uint8_t g_first[IMG * IMG];
static uint8_t g_win[WINDOWS][MAXW * MAXW];
static ssda_view_t g_area_v[WINDOWS], g_win_v[WINDOWS];
static int32_t g_truth_x[WINDOWS], g_truth_y[WINDOWS];
static uint64_t g_work[SSDA_NCC_WORK_SIZE(MAXA, MAXW, MAXW) / 8u + 1u];

typedef struct {
    ssda_ncc_config_t cfg;
    int predict;
    uint32_t count;
    ssda_ncc_result_t res[WINDOWS];
    int err;
} ncc_job_t;

static void ncc_job(void *ctx)
{
    ncc_job_t *j = (ncc_job_t *)ctx;
    uint32_t k;
    for (k = 0; k < j->count; k++) {
        if (j->predict) {
            j->cfg.predict_x = k > 0u ? g_truth_x[k - 1u] : g_truth_x[0];
            j->cfg.predict_y = k > 0u ? g_truth_y[k - 1u] : g_truth_y[0];
        }
        j->err |= ssda_ncc_match(&g_area_v[k], &g_win_v[k], &j->cfg, &j->res[k]);
    }
}

static void make_windows(uint32_t win, uint32_t area)
{
    uint32_t k, x, y, st = 0x4E434331u;
    const int32_t half = (int32_t)((area - win) / 2u);
    jobs_texture_u8(g_first, IMG, IMG, 0x434C4F55u);
    for (k = 0; k < WINDOWS; k++) {
        uint32_t ax = 4u + (k % 4u) * 30u, ay = 4u + (k / 4u) * 30u;
        int32_t dx = (int32_t)(k % 4u) - 2 + (int32_t)(k / 8u);
        int32_t dy = 1 - (int32_t)(k / 4u) + (int32_t)((k % 4u) >> 1);
        uint32_t tx = (uint32_t)(half + dx), ty = (uint32_t)(half + dy);
        g_truth_x[k] = (int32_t)tx;
        g_truth_y[k] = (int32_t)ty;
        for (y = 0; y < win; y++) {
            for (x = 0; x < win; x++) {
                int32_t v = (int32_t)g_first[(ay + ty + y) * IMG + ax + tx + x] * 3 / 4 + 20;
                v += (int32_t)(jobs_rand(&st) % 7u) - 3;
                g_win[k][y * win + x] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
            }
        }
        (void)ssda_view_init(&g_area_v[k], g_first + ay * IMG + ax, (uint16_t)area,
                             (uint16_t)area, IMG, SSDA_PIX_U8);
        (void)ssda_view_init(&g_win_v[k], g_win[k], (uint16_t)win, (uint16_t)win, win,
                             SSDA_PIX_U8);
    }
}

static void run(const char *name, uint8_t flags, const ncc_job_t *reference)
{
    static ncc_job_t j;
    uint32_t instr, stack, k;
    uint64_t ops = 0u;
    memset(&j, 0, sizeof j);
    j.cfg.flags = flags;
    j.cfg.work = g_work;
    j.cfg.work_size = sizeof g_work;
    j.predict = (flags & SSDA_NCC_PREDICT) != 0u;
    j.count = 1u;
    stack = budget_stack_peak(ncc_job, &j);
    j.count = WINDOWS;
    instr = budget_instructions(ncc_job, &j);
    for (k = 0; k < WINDOWS; k++) {
        ops += j.res[k].pixel_ops;
        if (reference != NULL && (j.res[k].x != reference->res[k].x ||
                                  j.res[k].y != reference->res[k].y ||
                                  j.res[k].rho_q30 != reference->res[k].rho_q30)) {
            budget_fail(name);
        }
    }
    if (j.err != SSDA_OK) {
        budget_fail(name);
    }
    budget_report(name, instr, WINDOWS, stack, ops);
}

static void geometry(const char *prefix, uint32_t win, uint32_t area)
{
    static ncc_job_t full;
    char name[40];
    const size_t n = strlen(prefix);
    make_windows(win, area);
    memset(&full, 0, sizeof full);
    full.cfg.flags = SSDA_NCC_FULL;
    full.cfg.work = g_work;
    full.cfg.work_size = sizeof g_work;
    full.count = WINDOWS;
    ncc_job(&full);
    memcpy(name, prefix, n);
    memcpy(name + n, ".full", 6);
    run(name, SSDA_NCC_FULL, &full);
    memcpy(name + n, ".early", 7);
    run(name, 0u, &full);
    memcpy(name + n, ".early_predict", 15);
    run(name, SSDA_NCC_PREDICT, &full);
}

void jobs_ncc(void)
{
    geometry("ncc16", 16u, 32u);
    geometry("ncc20", 20u, 40u);
}
