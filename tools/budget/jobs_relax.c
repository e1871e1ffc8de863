/*
 * jobs_relax.c - cleaning a vector grid of the seed 003's size (137
 * templates: a 12 x 12 grid here, 144 vectors) with relaxation labelling
 * (relax.h, eqs. 1-3: 10 and 50 iterations) and with the normalised median
 * test: a smooth rotating field with 10 % outliers. Reported per grid.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/relax.h"

#define COLS 12u
#define ROWS 12u
#define N (COLS * ROWS)

typedef struct {
    int32_t dx, dy; /* Q8 px */
    uint8_t status;
} vec_t;

static vec_t g_field[N];
static ssda_relax_vector_t g_out[N];
static uint32_t g_work[SSDA_RELAX_WORK_SIZE(COLS, ROWS) / 4u + 1u];

typedef struct {
    ssda_relax_grid_t grid;
    ssda_relax_config_t cfg;
    int median;
    int err;
} relax_job_t;

static void relax_job(void *ctx)
{
    relax_job_t *j = (relax_job_t *)ctx;
    if (j->median) {
        j->err |= ssda_relax_median(&j->grid, NULL, g_out, N);
    } else {
        j->err |= ssda_relax_labels(&j->grid, &j->cfg, g_out, N);
    }
}

static void make_field(void)
{
    uint32_t k, st = 0x52454C58u;
    for (k = 0; k < N; k++) {
        /* a slow rotation about the grid centre (about 2 to 5 px) */
        int32_t x = (int32_t)(k % COLS) - 6, y = (int32_t)(k / COLS) - 6;
        g_field[k].dx = 3 * 256 - y * 40;
        g_field[k].dy = 1 * 256 + x * 40;
        g_field[k].status = 0u;
        if (jobs_rand(&st) % 10u == 0u) {
            g_field[k].dx = (int32_t)(jobs_rand(&st) % 4096u) - 2048;
            g_field[k].dy = (int32_t)(jobs_rand(&st) % 4096u) - 2048;
        }
    }
}

static void run(const char *name, int median, uint16_t iterations)
{
    static relax_job_t j;
    uint32_t instr, stack, k, changed = 0u;
    memset(&j, 0, sizeof j);
    j.grid.dx = &g_field[0].dx;
    j.grid.dy = &g_field[0].dy;
    j.grid.status = &g_field[0].status;
    j.grid.stride = sizeof g_field[0];
    j.grid.cols = COLS;
    j.grid.rows = ROWS;
    j.grid.frac_bits = 8u;
    j.cfg.iterations = iterations;
    j.cfg.work = g_work;
    j.cfg.work_size = sizeof g_work;
    j.median = median;
    stack = budget_stack_peak(relax_job, &j);
    instr = budget_instructions(relax_job, &j);
    for (k = 0; k < N; k++) {
        changed += (g_out[k].flags & SSDA_RELAX_CHANGED) != 0u ? 1u : 0u;
    }
    if (j.err != SSDA_OK || changed == 0u) {
        budget_fail(name);
    }
    budget_report(name, instr, 1u, stack, changed);
}

void jobs_relax(void)
{
    make_field();
    run("relax.labels10", 0, 10u);
    run("relax.labels50", 0, 50u);
    run("relax.median", 1, 0u);
}
