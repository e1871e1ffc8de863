/*
 * jobs_match.c - one 16 x 16 window searched in the 32 x 32 area centred on
 * it (the seed's cloud-tracking geometry), by threshold mode, scan and bounds.
 * Sixteen windows from a smooth texture, each displaced by a slowly varying
 * motion plus +-3 of noise; the prediction for a window is the true motion
 * of the one before it (as a solved neighbour would give). Every exact mode
 * must return the brute-force result, or the run fails.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/match.h"

#define IMG 96u
#define AREA 32u
#define WIN 16u
#define WINDOWS 16u

static uint8_t g_first[IMG * IMG];
static uint8_t g_win[WINDOWS][WIN * WIN];
static ssda_view_t g_area_v[WINDOWS], g_win_v[WINDOWS];
static int32_t g_truth_x[WINDOWS], g_truth_y[WINDOWS];
static uint32_t g_work[SSDA_MATCH_WORK_SIZE_BLOCKS(AREA, AREA, WIN, WIN) / 4u];

typedef struct {
    ssda_match_config_t cfg;
    int predict;                           /* use the previous window's truth */
    uint32_t first, count;                 /* windows to search */
    ssda_match_result_t res[WINDOWS];
    int err;
} match_job_t;

static void match_job(void *ctx)
{
    match_job_t *j = (match_job_t *)ctx;
    uint32_t k;
    for (k = j->first; k < j->first + j->count; k++) {
        if (j->predict) {
            j->cfg.predict_x = k > 0u ? g_truth_x[k - 1u] : (int32_t)((AREA - WIN) / 2u);
            j->cfg.predict_y = k > 0u ? g_truth_y[k - 1u] : (int32_t)((AREA - WIN) / 2u);
        }
        j->err |= ssda_match(&g_area_v[k], &g_win_v[k], &j->cfg, &j->res[k]);
    }
}

static void make_windows(void)
{
    uint32_t k, x, y, st = 0x57494E44u;
    jobs_texture_u8(g_first, IMG, IMG, 0x434C4F55u);
    for (k = 0; k < WINDOWS; k++) {
        uint32_t ax = 8u + (k % 4u) * 16u, ay = 8u + (k / 4u) * 16u;
        /* Motion in -3..3, changing by at most 2 between neighbours. */
        int32_t dx = (int32_t)(k % 4u) - 2 + (int32_t)(k / 8u);
        int32_t dy = 1 - (int32_t)(k / 4u) + (int32_t)((k % 4u) >> 1);
        uint32_t tx = (uint32_t)((int32_t)((AREA - WIN) / 2u) + dx);
        uint32_t ty = (uint32_t)((int32_t)((AREA - WIN) / 2u) + dy);
        g_truth_x[k] = (int32_t)tx;
        g_truth_y[k] = (int32_t)ty;
        for (y = 0; y < WIN; y++) {
            for (x = 0; x < WIN; x++) {
                int32_t v = g_first[(ay + ty + y) * IMG + ax + tx + x];
                v += (int32_t)(jobs_rand(&st) % 7u) - 3;
                g_win[k][y * WIN + x] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
            }
        }
        (void)ssda_view_init(&g_area_v[k], g_first + ay * IMG + ax, AREA, AREA, IMG, SSDA_PIX_U8);
        (void)ssda_view_init(&g_win_v[k], g_win[k], WIN, WIN, WIN, SSDA_PIX_U8);
    }
}

static void run(const char *name, uint8_t threshold, uint8_t scan, int bounds,
                const match_job_t *reference)
{
    static match_job_t j;
    uint32_t instr, stack, k;
    uint64_t ops = 0u;
    memset(&j, 0, sizeof j);
    j.cfg.threshold = threshold;
    j.cfg.scan = scan;
    j.predict = scan == (uint8_t)SSDA_SCAN_PREDICT;
    if (bounds) { /* 2: with SSDA_MATCH_BLOCKS (scan_pre at this size) */
        j.cfg.flags = bounds == 2 ? SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS : SSDA_MATCH_BOUNDS;
        j.cfg.work = g_work;
        j.cfg.work_size = bounds == 2 ? sizeof g_work
                                      : SSDA_MATCH_WORK_SIZE(AREA, AREA, WIN, WIN);
    }
    j.first = 0u;
    j.count = 1u;
    stack = budget_stack_peak(match_job, &j);
    j.count = WINDOWS;
    instr = budget_instructions(match_job, &j);
    for (k = 0; k < WINDOWS; k++) {
        ops += j.res[k].pixel_ops;
        if (reference != NULL &&
            (j.res[k].x != reference->res[k].x || j.res[k].y != reference->res[k].y ||
             j.res[k].sad != reference->res[k].sad || !j.res[k].exact)) {
            budget_fail(name);
        }
    }
    if (j.err != SSDA_OK) {
        budget_fail(name);
    }
    budget_report(name, instr, WINDOWS, stack, ops);
}

void jobs_match(void)
{
    static match_job_t brute;
    make_windows();
    memset(&brute, 0, sizeof brute);
    brute.cfg.threshold = SSDA_THRESHOLD_NONE;
    brute.count = WINDOWS;
    match_job(&brute);
    run("match.none", SSDA_THRESHOLD_NONE, SSDA_SCAN_RASTER, 0, &brute);
    run("match.auto", SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER, 0, &brute);
    run("match.auto_predict", SSDA_THRESHOLD_AUTO, SSDA_SCAN_PREDICT, 0, &brute);
    run("match.auto_bounds", SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER, 1, &brute);
    run("match.auto_blocks", SSDA_THRESHOLD_AUTO, SSDA_SCAN_RASTER, 2, &brute);
    run("match.auto_predict_bounds", SSDA_THRESHOLD_AUTO, SSDA_SCAN_PREDICT, 1, &brute);
}
