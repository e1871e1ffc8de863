/*
 * jobs_composite.c - composite template matching (composite.h) at the
 * seed 003's template size: 20 x 20 templates every 5 px over a 60 x 60
 * region (81 templates; the seed had 137) of a 96 x 96 reference, the
 * origin searched over the whole 96 x 96 next image (5 929 places), the
 * others in their disks. The next image is the reference moved by (3, -2)
 * with a brightness change; every template must find that motion.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/composite.h"

#define IMG 96u
#define TEMPLATES 81u

static uint8_t g_ref[IMG * IMG], g_next[IMG * IMG];
static uint64_t g_work[SSDA_COMPOSITE_WORK_SIZE(IMG, 20) / 8u + 1u];
static ssda_composite_tp_t g_tp[TEMPLATES];

typedef struct {
    ssda_view_t ref, next;
    ssda_composite_config_t cfg;
    ssda_composite_result_t res;
    int err;
} composite_job_t;

static void composite_job(void *ctx)
{
    composite_job_t *j = (composite_job_t *)ctx;
    j->err |= ssda_composite_match(&j->ref, &j->next, &j->cfg, g_tp, TEMPLATES, &j->res);
}

void jobs_composite(void)
{
    static composite_job_t j;
    uint32_t x, y, k, stack, instr, bad = 0u;
    jobs_texture_u8(g_ref, IMG, IMG, 0x434F4D50u);
    for (y = 0; y < IMG; y++) {
        for (x = 0; x < IMG; x++) {
            /* next(x, y) = ref(x - 3, y + 2) * 3/4 + 40 */
            uint32_t sx = x >= 3u ? x - 3u : 0u, sy = y + 2u < IMG ? y + 2u : IMG - 1u;
            g_next[y * IMG + x] = (uint8_t)(g_ref[sy * IMG + sx] * 3u / 4u + 40u);
        }
    }
    memset(&j, 0, sizeof j);
    (void)ssda_view_init(&j.ref, g_ref, IMG, IMG, IMG, SSDA_PIX_U8);
    (void)ssda_view_init(&j.next, g_next, IMG, IMG, IMG, SSDA_PIX_U8);
    j.cfg.roi_x = 18u;
    j.cfg.roi_y = 18u;
    j.cfg.roi_w = 60u;
    j.cfg.roi_h = 60u;
    j.cfg.work = g_work;
    j.cfg.work_size = sizeof g_work;
    stack = budget_stack_peak(composite_job, &j);
    instr = budget_instructions(composite_job, &j);
    for (k = 0; k < TEMPLATES; k++) {
        bad += g_tp[k].status != SSDA_COMPOSITE_OK || g_tp[k].dx != 3 * 256 ||
               g_tp[k].dy != -2 * 256;
    }
    if (j.err != SSDA_OK || bad != 0u || j.res.ok != TEMPLATES) {
        budget_fail("composite.seed");
    }
    budget_report("composite.seed", instr, TEMPLATES, stack, j.res.pixel_ops);
}
