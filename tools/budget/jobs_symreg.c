/*
 * jobs_symreg.c - seed 001's chain on the emulated Cortex-M4: a 96 x 96
 * scene (bright blocks and discs on a smoothed random ground), and the same
 * scene turned a quarter turn (exactly: a pixel permutation) and 25 %
 * darker. Timed: the edge operator, the 3 x 3 stages, the loops, the
 * descriptors of every loop, one free and one fixed Fourier match, and the
 * registration. The registration must find the quarter turn, or the run
 * fails.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/edge.h"
#include "ssda/fourier.h"
#include "ssda/loops.h"
#include "ssda/symreg.h"

#define N 96u
#define MAXL 32u
#define NS 64u

static uint8_t g_img[2][N * N];
static uint16_t g_map[N * N];
static uint8_t g_ring[SSDA_EDGE_RING_SIZE(N)];
static uint32_t g_work[2048];
static ssda_loop_t g_loops[2][MAXL];
static ssda_point_q8_t g_pts[2][MAXL * NS];
static ssda_fd_t g_fd[2][MAXL];
static ssda_symreg_pair_t g_pairs[MAXL];
static uint32_t g_n[2];

typedef struct {
    uint32_t side;
    int err;
    ssda_symreg_result_t res;
    ssda_fd_match_t m;
} job_t;

static void make_scene(void)
{
    static const uint8_t box[][5] = {/* x0, y0, w, h, grey */
                                     {10, 12, 14, 9, 200}, {40, 8, 10, 16, 180},
                                     {66, 14, 18, 11, 220}, {14, 44, 9, 13, 190},
                                     {60, 50, 13, 18, 210}, {30, 72, 20, 10, 170},
                                     {72, 76, 12, 12, 230}};
    static const uint8_t disc[][4] = {{38, 40, 7, 200}, {84, 40, 5, 180}, {12, 84, 6, 215}};
    uint32_t i, x, y;
    jobs_texture_u8(g_img[0], N, N, 0x4C4F4F50u);
    for (i = 0; i < N * N; i++) { /* ground 70..110 */
        g_img[0][i] = (uint8_t)(70u + g_img[0][i] / 6u);
    }
    for (i = 0; i < sizeof box / sizeof box[0]; i++) {
        for (y = box[i][1]; y < (uint32_t)box[i][1] + box[i][3]; y++) {
            for (x = box[i][0]; x < (uint32_t)box[i][0] + box[i][2]; x++) {
                g_img[0][y * N + x] = box[i][4];
            }
        }
    }
    for (i = 0; i < sizeof disc / sizeof disc[0]; i++) {
        const int32_t cx = disc[i][0], cy = disc[i][1], r = disc[i][2];
        for (y = 0; y < N; y++) {
            for (x = 0; x < N; x++) {
                const int32_t dx = (int32_t)x - cx, dy = (int32_t)y - cy;
                if (dx * dx + dy * dy <= r * r) {
                    g_img[0][y * N + x] = disc[i][3];
                }
            }
        }
    }
    /* MOV (x', y') = (N - 1 - y, x): a quarter turn, 3/4 of the brightness */
    for (y = 0; y < N; y++) {
        for (x = 0; x < N; x++) {
            g_img[1][x * N + (N - 1u - y)] = (uint8_t)(g_img[0][y * N + x] * 3u / 4u);
        }
    }
}

static void view(uint32_t side, ssda_view_t *v)
{
    (void)ssda_view_init(v, g_img[side], N, N, N, SSDA_PIX_U8);
}

static void detect_job(void *ctx)
{
    job_t *j = (job_t *)ctx;
    ssda_view_t v;
    view(j->side, &v);
    j->err = ssda_edge_detect(&v, 0u, g_map, sizeof g_map, g_ring, sizeof g_ring);
}

static void refine_job(void *ctx)
{
    job_t *j = (job_t *)ctx;
    j->err = ssda_edge_refine(g_map, N, N, NULL, g_work, sizeof g_work, NULL);
}

static void loops_job(void *ctx)
{
    job_t *j = (job_t *)ctx;
    ssda_view_t v;
    ssda_loops_config_t c;
    memset(&c, 0, sizeof c);
    c.area_min = 40u;
    c.grey_min = SSDA_LOOPS_GREY_ANY;
    view(j->side, &v);
    j->err = ssda_loops_find(g_map, &v, &c, g_work, sizeof g_work, g_loops[j->side], MAXL,
                             g_pts[j->side], sizeof g_pts[j->side], &g_n[j->side], NULL);
}

static void fd_job(void *ctx)
{
    job_t *j = (job_t *)ctx;
    uint32_t i;
    for (i = 0; i < g_n[j->side] && j->err == SSDA_OK; i++) {
        j->err = ssda_fd_compute(g_loops[j->side][i].contour, NS, 10u, &g_fd[j->side][i]);
    }
}

static void match_job(void *ctx)
{
    job_t *j = (job_t *)ctx;
    j->err = ssda_fd_match(&g_fd[0][0], &g_fd[1][0], &j->m);
}

static void match_fixed_job(void *ctx)
{
    job_t *j = (job_t *)ctx;
    j->err = ssda_fd_match_fixed(&g_fd[0][0], &g_fd[1][0], 65536u, 0x40000000u, &j->m);
}

static void symreg_job(void *ctx)
{
    job_t *j = (job_t *)ctx;
    j->err = ssda_symreg(g_loops[0], g_fd[0], g_n[0], g_loops[1], g_fd[1], g_n[1], NULL, g_work,
                         sizeof g_work, g_pairs, MAXL, &j->res);
}

/* The map as the stage before `upto` left it (0: nothing, 1: detected,
   2: refined), so that both runs of a job start alike. */
static void prepare(job_t *j, uint32_t upto)
{
    if (upto >= 1u) {
        detect_job(j);
    }
    if (upto >= 2u) {
        refine_job(j);
    }
}

/* Time one job (stack, then instructions, each from the same start) and
   report it per unit. */
static void timed(const char *name, budget_job_fn fn, job_t *j, uint32_t upto, uint32_t units)
{
    uint32_t stack, instr;
    prepare(j, upto);
    stack = budget_stack_peak(fn, j);
    prepare(j, upto);
    instr = budget_instructions(fn, j);
    if (j->err != SSDA_OK) {
        budget_fail(name);
    }
    budget_report(name, instr, units, stack, 0u);
}

void jobs_symreg(void)
{
    static job_t j;
    uint32_t side;
    make_scene();
    for (side = 0; side < 2u; side++) {
        memset(&j, 0, sizeof j);
        j.side = side;
        timed(side == 0u ? "symreg.edge_detect" : "symreg.edge_detect.mov", detect_job, &j, 0u,
              N * N);
        timed(side == 0u ? "symreg.edge_refine" : "symreg.edge_refine.mov", refine_job, &j, 1u,
              N * N);
        timed(side == 0u ? "symreg.loops_find" : "symreg.loops_find.mov", loops_job, &j, 2u, 1u);
        if (g_n[side] < 3u) {
            budget_fail("symreg.loops_found");
        }
        timed(side == 0u ? "symreg.fd_compute" : "symreg.fd_compute.mov", fd_job, &j, 0u,
              g_n[side]);
    }
    memset(&j, 0, sizeof j);
    timed("symreg.fd_match", match_job, &j, 0u, 1u);
    timed("symreg.fd_match_fixed", match_fixed_job, &j, 0u, 1u);
    timed("symreg.register", symreg_job, &j, 0u, g_n[0] * g_n[1]);
    /* the quarter turn: a ~ 0, b ~ -1, d ~ 1, e ~ 0 (Q16), within 2 % */
    if (j.res.pairs < 3u || j.res.affine.a_q16 > 1311 || j.res.affine.a_q16 < -1311 ||
        j.res.affine.b_q16 > -64225 || j.res.affine.b_q16 < -66847 ||
        j.res.affine.d_q16 < 64225 || j.res.affine.d_q16 > 66847) {
        budget_fail("symreg.quarter_turn");
    }
    budget_report("symreg.pairs", j.res.pairs, 1u, 0u, g_n[0] + g_n[1]);
}
