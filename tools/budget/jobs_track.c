/*
 * jobs_track.c - the seed's cloud tracking: 16 x 16 windows on a 7 x 7 grid
 * of a 128 x 128 image, each searched in the 32 x 32 area centred on it.
 * SECOND is FIRST moved by (+3, -2) with +-3 of noise. The exact modes must
 * all return the same vectors, or the run fails.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/track.h"

#define IMG 128u
#define GRID 49u

static uint8_t g_first[IMG * IMG], g_second[IMG * IMG];
/* big enough for the bound tables shared by the windows (the last job) */
static uint32_t g_work[SSDA_TRACK_WORK_SIZE_SHARED(IMG, 32, 32, 16, 16) / 4u];
static ssda_view_t g_first_v, g_second_v;

typedef struct {
    ssda_track_config_t cfg;
    ssda_track_vector_t out[GRID];
    ssda_track_stats_t stats;
    int err;
} track_job_t;

static void track_job(void *ctx)
{
    track_job_t *j = (track_job_t *)ctx;
    j->err = ssda_track(&g_first_v, &g_second_v, &j->cfg, j->out, GRID, &j->stats);
}

/* bounds: 0 none, 1 per-window tables (SSDA_TRACK_WORK_SIZE), 2 shared
   ones (SSDA_TRACK_WORK_SIZE_SHARED) */
static void run(const char *name, uint8_t threshold, uint8_t predict, int bounds,
                const track_job_t *reference)
{
    static track_job_t j;
    uint32_t instr, stack, k;
    memset(&j, 0, sizeof j);
    j.cfg.roi_x = 8u;
    j.cfg.roi_y = 8u;
    j.cfg.roi_w = IMG - 16u;
    j.cfg.roi_h = IMG - 16u;
    j.cfg.predict = predict;
    j.cfg.match.threshold = threshold;
    if (bounds) {
        j.cfg.match.flags = SSDA_MATCH_BOUNDS;
        j.cfg.match.work = g_work;
        j.cfg.match.work_size = bounds == 2 ? sizeof g_work
                                            : SSDA_TRACK_WORK_SIZE(32, 32, 16, 16);
    }
    stack = budget_stack_peak(track_job, &j);
    instr = budget_instructions(track_job, &j);
    if (j.err != SSDA_OK || j.stats.windows != GRID) {
        budget_fail(name);
    }
    for (k = 0; reference != NULL && k < GRID; k++) {
        if (j.out[k].dx != reference->out[k].dx || j.out[k].dy != reference->out[k].dy ||
            j.out[k].sad != reference->out[k].sad) {
            budget_fail(name);
        }
    }
    budget_report(name, instr, GRID, stack, j.stats.pixel_ops);
}

void jobs_track(void)
{
    static track_job_t brute;
    uint32_t x, y, st = 0x54524B31u;
    jobs_texture_u8(g_first, IMG, IMG, 0x53454544u);
    for (y = 0; y < IMG; y++) {
        for (x = 0; x < IMG; x++) {
            /* second(x, y) = first(x - 3, y + 2): motion (+3, -2) */
            uint32_t sx = x >= 3u ? x - 3u : 0u, sy = y + 2u < IMG ? y + 2u : IMG - 1u;
            int32_t v = (int32_t)g_first[sy * IMG + sx] + (int32_t)(jobs_rand(&st) % 7u) - 3;
            g_second[y * IMG + x] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
        }
    }
    (void)ssda_view_init(&g_first_v, g_first, IMG, IMG, IMG, SSDA_PIX_U8);
    (void)ssda_view_init(&g_second_v, g_second, IMG, IMG, IMG, SSDA_PIX_U8);
    run("track.none", SSDA_THRESHOLD_NONE, SSDA_TRACK_PREDICT_NONE, 0, NULL);
    memset(&brute, 0, sizeof brute);
    brute.cfg.roi_x = 8u;
    brute.cfg.roi_y = 8u;
    brute.cfg.roi_w = IMG - 16u;
    brute.cfg.roi_h = IMG - 16u;
    brute.cfg.match.threshold = SSDA_THRESHOLD_NONE;
    track_job(&brute);
    run("track.auto", SSDA_THRESHOLD_AUTO, SSDA_TRACK_PREDICT_NONE, 0, &brute);
    run("track.auto_predict_bounds", SSDA_THRESHOLD_AUTO, SSDA_TRACK_PREDICT_MEDIAN, 1, &brute);
    run("track.auto_predict_bounds_shared", SSDA_THRESHOLD_AUTO, SSDA_TRACK_PREDICT_MEDIAN, 2,
        &brute);
}
