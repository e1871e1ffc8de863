/*
 * jobs_stream.c - push-mode tracking (stream.h): the seed's 7 x 7 grid on a
 * 128 x 128 image whose SECOND frame arrives row by row (a line camera),
 * FIRST in RAM, the ring at its minimum (16 rows of the grid's columns).
 * Timed: one ssda_push_row of a row that completes no grid row (the cost a
 * push pays besides its searches: bookkeeping and copying one row into the
 * ring), and the whole frame per pushed row. The vectors must equal
 * ssda_track's, or the run fails.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/stream.h"

#define IMG 128u
#define GRID 49u
#define IDLE_ROW 45u /* inside grid row 2's band (rows 40..55): solves nothing */

static uint8_t g_first[IMG * IMG], g_second[IMG * IMG];
/* the grid's columns 8..119: 112 px, 16 rows (SSDA_STREAM_STRIP_W(7, 16, 16)) */
static uint32_t g_ring[SSDA_PUSH_SIZE(112u, 16u, SSDA_PIX_U8) / 4u];

typedef struct {
    ssda_source_t first;
    ssda_track_config_t cfg;
    ssda_push_t push;
    ssda_track_vector_t out[GRID];
    ssda_track_stats_t stats;
    uint32_t row0, row1; /* rows the timed job pushes */
    int err;
} push_job_t;

static void push_rows(void *ctx)
{
    push_job_t *j = (push_job_t *)ctx;
    uint32_t y;
    for (y = j->row0; y < j->row1; y++) {
        int r = ssda_push_row(&j->push, g_second + y * IMG);
        if (r < 0) {
            j->err = r;
        }
    }
}

/* A fresh job with rows 0 .. upto-1 pushed; the timed job pushes upto .. end-1. */
static void prepare(push_job_t *j, uint32_t upto, uint32_t end)
{
    ssda_push_config_t pc = {IMG, IMG, SSDA_PIX_U8, SSDA_PUSH_SECOND, NULL, NULL, NULL,
                             g_ring, sizeof g_ring};
    pc.other = &j->first;
    j->err = ssda_push_init_track(&j->push, &pc, &j->cfg, j->out, GRID, &j->stats);
    j->row0 = 0u;
    j->row1 = upto;
    push_rows(j);
    j->row0 = upto;
    j->row1 = end;
}

void jobs_stream(void)
{
    static push_job_t j;
    static ssda_track_vector_t ref[GRID];
    ssda_view_t fv, sv;
    uint32_t x, y, k, st = 0x50555348u, instr, stack;
    /* the grid of jobs_track.c, on its own pair (motion (+2, +1), noise +-3) */
    jobs_texture_u8(g_first, IMG, IMG, 0x50555348u);
    for (y = 0; y < IMG; y++) {
        for (x = 0; x < IMG; x++) {
            uint32_t sx = x >= 2u ? x - 2u : 0u, sy = y >= 1u ? y - 1u : 0u;
            int32_t v = (int32_t)g_first[sy * IMG + sx] + (int32_t)(jobs_rand(&st) % 7u) - 3;
            g_second[y * IMG + x] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
        }
    }
    memset(&j, 0, sizeof j);
    (void)ssda_view_init(&fv, g_first, IMG, IMG, IMG, SSDA_PIX_U8);
    (void)ssda_view_init(&sv, g_second, IMG, IMG, IMG, SSDA_PIX_U8);
    (void)ssda_source_init_view(&j.first, &fv);
    j.cfg.roi_x = 8u;
    j.cfg.roi_y = 8u;
    j.cfg.roi_w = IMG - 16u;
    j.cfg.roi_h = IMG - 16u;
    j.cfg.predict = SSDA_TRACK_PREDICT_LEFT;
    if (ssda_track(&fv, &sv, &j.cfg, ref, GRID, NULL) != SSDA_OK) {
        budget_fail("push.track reference");
    }

    /* one row that solves nothing */
    prepare(&j, IDLE_ROW, IDLE_ROW + 1u);
    instr = budget_instructions(push_rows, &j);
    prepare(&j, IDLE_ROW, IDLE_ROW + 1u);
    stack = budget_stack_peak(push_rows, &j);
    if (j.err != SSDA_OK) {
        budget_fail("push.track_row_idle");
    }
    budget_report("push.track_row_idle", instr, 1u, stack, 0u);

    /* the whole frame */
    prepare(&j, 0u, IMG);
    instr = budget_instructions(push_rows, &j);
    prepare(&j, 0u, IMG);
    stack = budget_stack_peak(push_rows, &j);
    if (j.err != SSDA_OK || j.stats.windows != GRID) {
        budget_fail("push.track_frame");
    }
    for (k = 0; k < GRID; k++) {
        if (j.out[k].dx != ref[k].dx || j.out[k].dy != ref[k].dy || j.out[k].sad != ref[k].sad ||
            j.out[k].status != ref[k].status) {
            budget_fail("push.track_frame vectors");
        }
    }
    budget_report("push.track_frame", instr, IMG, stack, j.stats.pixel_ops);
}
