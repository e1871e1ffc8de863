/*
 * loops_run.h - the closed-loop chain of seed 001 on a host image: edges
 * (ssda/edge.h), loops (ssda/loops.h) and their Fourier descriptors
 * (ssda/fourier.h), with every library buffer allocated here. Shared by
 * `ssda symreg`, the demo and the benchmarks.
 */
#ifndef SSDA_LOOPS_RUN_H
#define SSDA_LOOPS_RUN_H

#include <stddef.h>
#include <stdint.h>

#include "png_io.h"
#include "ssda/edge.h"
#include "ssda/fourier.h"
#include "ssda/loops.h"

typedef struct {
    uint8_t strength;                 /* ridge threshold (0 = 15) */
    ssda_edge_refine_config_t refine; /* zero = the seed's values */
    ssda_loops_config_t loops;        /* zero = the seed's values */
    uint32_t order;                   /* descriptor order (0 = 10) */
    uint32_t max_loops;               /* loops kept (0 = SSDA_SYMREG_MAX_LOOPS) */
} loops_run_cfg_t;

typedef struct {
    uint32_t width, height, samples;
    uint32_t n;                  /* loops */
    ssda_loop_t *loops;          /* n, malloc'ed */
    ssda_fd_t *fds;              /* n descriptors */
    ssda_point_q8_t *points;     /* the contours */
    uint16_t *map;               /* the final map (loops' cycles ON) */
    ssda_edge_stats_t edge_stats;
    ssda_loops_stats_t loop_stats;
    size_t lib_bytes;            /* bytes of library buffers this image needed: the
                                    map, the ring, the larger work (ends found or
                                    largest loop), loops, contours, descriptors */
} loops_run_t;

/* Run the chain on an 8-bit image. Returns 0, or -1 with a message in err
   (out zeroed). */
int loops_run(const gray_image_t *img, const loops_run_cfg_t *cfg, loops_run_t *out, char *err,
              size_t errlen);

void loops_run_free(loops_run_t *r);

#endif /* SSDA_LOOPS_RUN_H */
