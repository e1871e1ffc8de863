/*
 * draw_loops.h - the overlay of `ssda symreg` (cairo): REF and MOV side by
 * side, every loop's contour on each, matched pairs in one colour per pair
 * and joined by a line from REF's centroid to MOV's; unmatched loops thin
 * and grey. Written atomically.
 */
#ifndef SSDA_DRAW_LOOPS_H
#define SSDA_DRAW_LOOPS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "png_io.h"
#include "ssda/loops.h"

typedef struct {
    const gray_image_t *img;   /* 8-bit */
    const ssda_loop_t *loops;
    uint32_t n;
    uint32_t samples;          /* contour points per loop */
    const char *label;         /* "REF a.png" */
} draw_loops_side_t;

typedef struct {
    uint32_t ref, mov;         /* loop indices of a matched pair */
} draw_loops_pair_t;

/* Draw into an open stream (name for messages). Returns 0 or -1 with err. */
int draw_loops_to(FILE *fp, const char *name, const draw_loops_side_t *ref,
                  const draw_loops_side_t *mov, const draw_loops_pair_t *pairs,
                  uint32_t n_pairs, const char *title, const char *subtitle, char *err,
                  size_t errlen);

/* Draw to path ("-" = stdout). title/subtitle may be NULL. Returns 0 or -1
   with a message in err; no file is left on failure. */
int draw_loops_png(const char *path, const draw_loops_side_t *ref, const draw_loops_side_t *mov,
                   const draw_loops_pair_t *pairs, uint32_t n_pairs, const char *title,
                   const char *subtitle, char *err, size_t errlen);

#endif /* SSDA_DRAW_LOOPS_H */
