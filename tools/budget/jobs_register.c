/* jobs_register.c - band registration on the emulated Cortex-M4 (issue 17):
   instructions per output pixel of the warp (in RAM and streamed), per
   control point, per fit, per pixel of the shading removal. */
#include <string.h>

#include "jobs.h"

#include "budget_timer.h"
#include "ssda/register.h"
#include "ssda/shade.h"
#include "ssda/warp.h"

#define IMG 128u
#define OW 120u
#define OH 64u

static uint8_t g_ref[IMG * IMG], g_mov[IMG * IMG];
static uint8_t g_row[OW];
static uint32_t g_arena[2048 / 4];
static uint64_t g_work[(SSDA_REGISTER_WORK_SIZE(20, 40, 1) + 7u) / 8u];
static uint32_t g_sum;

static int sink(void *ctx, uint32_t x, uint32_t y, uint32_t n, const void *px)
{
    const uint8_t *p = (const uint8_t *)px;
    uint32_t i;
    (void)ctx;
    for (i = 0; i < n; i++) {
        g_sum += p[i] * (x + i + 1u) + y;
    }
    return 0;
}

static int dev_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    (void)ctx;
    memcpy(buf, g_mov + off, size);
    return 0;
}

typedef struct {
    ssda_warp_t job;
    int err;
} warp_job_t;

static void warp_job(void *ctx)
{
    warp_job_t *j = (warp_job_t *)ctx;
    j->err = ssda_warp_run(&j->job, NULL);
}

/* A map of the given order on the OW x OH grid: shift, 2 deg, a bow. */
static void map_of(uint8_t order, ssda_poly_t *p)
{
    (void)ssda_poly_init(p, OW, OH, order);
    p->u_q24[0] += (int64_t)4 << 24;
    p->u_q24[2] -= (int64_t)((1u << p->ky) * 0.035 * 16777216.0);
    p->v_q24[0] += (int64_t)3 << 24;
    p->v_q24[1] += (int64_t)((1u << p->kx) * 0.035 * 16777216.0);
    if (order >= 2u) {
        p->v_q24[3] = (int64_t)1 << 24;
    }
    if (order >= 3u) {
        p->u_q24[6] = (int64_t)1 << 23;
    }
}

static void run_warp(const char *name, uint8_t order, uint8_t resample, int streamed)
{
    static warp_job_t j;
    ssda_poly_t map;
    ssda_source_t src;
    ssda_view_t v;
    ssda_warp_config_t c;
    uint32_t instr, stack;
    map_of(order, &map);
    (void)ssda_view_init(&v, g_mov, IMG, IMG, IMG, SSDA_PIX_U8);
    if (streamed) {
        ssda_source_config_t sc;
        memset(&sc, 0, sizeof sc);
        sc.read = dev_read;
        sc.width = IMG;
        sc.height = IMG;
        sc.format = SSDA_PIX_U8;
        sc.arena = g_arena;
        sc.arena_size = sizeof g_arena;
        (void)ssda_source_init(&src, &sc);
    } else {
        (void)ssda_source_init_view(&src, &v);
    }
    memset(&c, 0, sizeof c);
    c.map = &map;
    c.sink = sink;
    c.row = g_row;
    c.row_size = sizeof g_row;
    c.resample = resample;
    if (ssda_warp_init(&j.job, &c, &src) != SSDA_OK) {
        budget_fail(name);
        return;
    }
    stack = budget_stack_peak(warp_job, &j);
    instr = budget_instructions(warp_job, &j);
    if (j.err != SSDA_OK) {
        budget_fail(name);
    }
    budget_report(name, instr, OW * OH, stack, 0u);
}

typedef struct {
    ssda_source_t ref, mov;
    ssda_register_config_t cfg;
    ssda_register_point_t pts[16];
    size_t ok;
    int err;
} points_job_t;

static void points_job(void *ctx)
{
    points_job_t *j = (points_job_t *)ctx;
    j->err = ssda_register_points(&j->ref, &j->mov, &j->cfg, j->pts, 16, &j->ok, g_work,
                                  sizeof g_work);
}

typedef struct {
    ssda_poly_pair_t pairs[16];
    ssda_poly_t map;
    uint8_t work[16];
    int err;
} fit_job_t;

static void fit_job(void *ctx)
{
    fit_job_t *j = (fit_job_t *)ctx;
    ssda_poly_fit_config_t fc = {2u, 0u};
    j->err = ssda_poly_fit(j->pairs, 16, IMG, IMG, &fc, &j->map, NULL, NULL, NULL, j->work,
                           sizeof j->work);
}

typedef struct {
    ssda_shade_t sh;
    int apply;
    int err;
} shade_job_t;

static void shade_job(void *ctx)
{
    shade_job_t *j = (shade_job_t *)ctx;
    uint32_t y;
    j->err = 0;
    for (y = 0; y < IMG; y++) {
        if (j->apply) {
            j->err |= ssda_shade_apply_row(&j->sh, y, g_ref + y * IMG, g_mov + y * IMG);
        } else {
            j->err |= ssda_shade_add_row(&j->sh, g_ref + y * IMG);
        }
    }
}

void jobs_register(void)
{
    static points_job_t pj;
    static fit_job_t fj;
    static shade_job_t sj;
    ssda_view_t a, b;
    uint32_t x, y, k, instr, stack;
    jobs_texture_u8(g_ref, IMG, IMG, 0x52454731u);
    for (y = 0; y < IMG; y++) { /* mov = ref moved by (+3, +2) */
        for (x = 0; x < IMG; x++) {
            const uint32_t sx = x >= 3u ? x - 3u : 0u, sy = y >= 2u ? y - 2u : 0u;
            g_mov[y * IMG + x] = g_ref[sy * IMG + sx];
        }
    }
    run_warp("reg.warp_nearest_o1", 1u, SSDA_WARP_NEAREST, 0);
    run_warp("reg.warp_bilinear_o1", 1u, SSDA_WARP_BILINEAR, 0);
    run_warp("reg.warp_bilinear_o3", 3u, SSDA_WARP_BILINEAR, 0);
    run_warp("reg.warp_bilinear_o2_stream2k", 2u, SSDA_WARP_BILINEAR, 1);

    (void)ssda_view_init(&a, g_ref, IMG, IMG, IMG, SSDA_PIX_U8);
    (void)ssda_view_init(&b, g_mov, IMG, IMG, IMG, SSDA_PIX_U8);
    (void)ssda_source_init_view(&pj.ref, &a);
    (void)ssda_source_init_view(&pj.mov, &b);
    memset(&pj.cfg, 0, sizeof pj.cfg); /* the seed's: |rho|, 20 in 40, 4 x 4 */
    stack = budget_stack_peak(points_job, &pj);
    instr = budget_instructions(points_job, &pj);
    if (pj.err != SSDA_OK || pj.ok < 12u) {
        budget_fail("reg.points_absncc");
    }
    budget_report("reg.points_absncc", instr, 16u, stack, 0u);
    pj.cfg.metric = SSDA_REGISTER_SAD;
    stack = budget_stack_peak(points_job, &pj);
    instr = budget_instructions(points_job, &pj);
    if (pj.err != SSDA_OK || pj.ok < 12u) {
        budget_fail("reg.points_sad");
    }
    budget_report("reg.points_sad", instr, 16u, stack, 0u);

    for (k = 0; k < 16u; k++) { /* a 4 x 4 lattice moved by (+3, +2), jittered */
        fj.pairs[k].ref_x_q8 = (int32_t)((16u + 32u * (k % 4u)) * 256u + (k * 37u) % 97u);
        fj.pairs[k].ref_y_q8 = (int32_t)((16u + 32u * (k / 4u)) * 256u + (k * 53u) % 89u);
        fj.pairs[k].mov_x_q8 = fj.pairs[k].ref_x_q8 + 3 * 256 + (int32_t)(k % 3u) - 1;
        fj.pairs[k].mov_y_q8 = fj.pairs[k].ref_y_q8 + 2 * 256 + (int32_t)(k % 5u) - 2;
    }
    stack = budget_stack_peak(fit_job, &fj);
    instr = budget_instructions(fit_job, &fj);
    if (fj.err != SSDA_OK) {
        budget_fail("reg.fit_o2_16");
    }
    budget_report("reg.fit_o2_16", instr, 1u, stack, 0u);

    (void)ssda_shade_init(&sj.sh, IMG, IMG, SSDA_PIX_U8);
    sj.apply = 0;
    instr = budget_instructions(shade_job, &sj);
    stack = 0u;
    if (sj.err != 0 || ssda_shade_finish(&sj.sh, SSDA_SHADE_CENTRE_MAX) != SSDA_OK) {
        budget_fail("reg.shade_add");
    }
    budget_report("reg.shade_add", instr, IMG * IMG, stack, 0u);
    sj.apply = 1;
    instr = budget_instructions(shade_job, &sj);
    if (sj.err != 0) {
        budget_fail("reg.shade_apply");
    }
    budget_report("reg.shade_apply", instr, IMG * IMG, 0u, 0u);
}
