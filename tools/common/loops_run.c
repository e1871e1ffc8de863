/* loops_run.c - edges, loops and descriptors of a host image (loops_run.h). */
#include "loops_run.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ssda/symreg.h"

static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (errlen > 0) {
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

void loops_run_free(loops_run_t *r)
{
    free(r->loops);
    free(r->fds);
    free(r->points);
    free(r->map);
    memset(r, 0, sizeof *r);
}

int loops_run(const gray_image_t *img, const loops_run_cfg_t *cfg, loops_run_t *out, char *err,
              size_t errlen)
{
    const uint32_t w = img->width, h = img->height;
    const uint32_t max_loops = cfg->max_loops ? cfg->max_loops : SSDA_SYMREG_MAX_LOOPS;
    const uint32_t samples = cfg->loops.samples ? cfg->loops.samples : SSDA_LOOPS_DEFAULT_SAMPLES;
    const uint32_t area_max = cfg->loops.area_max ? cfg->loops.area_max
                                                   : SSDA_LOOPS_DEFAULT_AREA_MAX;
    /* ends: one per 16 pixels is far above what edges of real images leave */
    const size_t max_ends = (size_t)w * h / 16u + 64u;
    const size_t edge_work = SSDA_EDGE_WORK_SIZE(max_ends);
    const size_t loop_work = SSDA_LOOPS_WORK_SIZE(area_max);
    loops_run_t r;
    ssda_view_t v;
    uint8_t *ring = NULL;
    void *work = NULL;
    uint32_t i;
    int e;
    memset(out, 0, sizeof *out);
    memset(&r, 0, sizeof r);
    if (img->bits != 8 || gray_image_view(img, &v) != SSDA_OK) {
        return fail(err, errlen, "internal: loops_run needs an 8-bit image");
    }
    r.width = w;
    r.height = h;
    r.samples = samples;
    r.map = malloc(SSDA_EDGE_MAP_SIZE(w, h));
    ring = malloc(SSDA_EDGE_RING_SIZE(w));
    work = malloc(edge_work > loop_work ? edge_work : loop_work);
    r.loops = malloc(sizeof *r.loops * max_loops);
    r.points = malloc(SSDA_LOOPS_POINTS_SIZE(max_loops, samples));
    if (r.map == NULL || ring == NULL || work == NULL || r.loops == NULL || r.points == NULL) {
        free(ring);
        free(work);
        loops_run_free(&r);
        return fail(err, errlen, "out of memory for a %u x %u image", w, h);
    }
    e = ssda_edge_detect(&v, cfg->strength, r.map, SSDA_EDGE_MAP_SIZE(w, h), ring,
                         SSDA_EDGE_RING_SIZE(w));
    if (e == SSDA_OK) {
        e = ssda_edge_refine(r.map, (uint16_t)w, (uint16_t)h, &cfg->refine, work, edge_work,
                             &r.edge_stats);
    }
    if (e == SSDA_OK) {
        e = ssda_loops_find(r.map, &v, &cfg->loops, work, loop_work, r.loops, max_loops,
                            r.points, SSDA_LOOPS_POINTS_SIZE(max_loops, samples), &r.n,
                            &r.loop_stats);
    }
    free(ring);
    free(work);
    if (e != SSDA_OK) {
        loops_run_free(&r);
        return fail(err, errlen, "loop extraction failed: %s", ssda_strerror(e));
    }
    r.fds = malloc(sizeof *r.fds * (r.n ? r.n : 1u));
    if (r.fds == NULL) {
        loops_run_free(&r);
        return fail(err, errlen, "out of memory");
    }
    for (i = 0; i < r.n; i++) {
        e = ssda_fd_compute(r.loops[i].contour, samples, cfg->order, &r.fds[i]);
        if (e != SSDA_OK) {
            loops_run_free(&r);
            return fail(err, errlen, "descriptors: %s", ssda_strerror(e));
        }
    }
    /* what the library needed: buffers sized for the ends and loops found
       (a firmware provisions its own worst case) */
    {
        const size_t ends_work = SSDA_EDGE_WORK_SIZE(r.edge_stats.ends);
        r.lib_bytes = SSDA_EDGE_MAP_SIZE(w, h) + SSDA_EDGE_RING_SIZE(w) +
                      (ends_work > loop_work ? ends_work : loop_work) +
                      (sizeof *r.loops + sizeof *r.fds) * r.n +
                      SSDA_LOOPS_POINTS_SIZE(r.n, samples);
    }
    *out = r;
    return 0;
}
