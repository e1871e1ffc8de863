/* loops_internal.h - boundary tracing shared by lib/loops_*.c. */
#ifndef SSDA_LOOPS_INTERNAL_H
#define SSDA_LOOPS_INTERNAL_H

#include "compiler.h"

#include "ssda/loops.h"

/* Membership of a pixel in the traced set: a map entry with `bit` set
   (16-bit map, stride in entries) or a nonzero mask byte (stride in bytes). */
typedef struct {
    const uint8_t *mask;   /* 8-bit mask, or NULL for the map */
    const uint16_t *map;
    uint32_t stride, w, h;
    uint16_t bit;
} ssda__member_t;

/* Moore tracing of the outer boundary from the set's first pixel in raster
   order (sx, sy), counter-clockwise on screen; Jacob's stop (back at the
   start about to repeat the first move). */
typedef struct {
    const ssda__member_t *set;
    int32_t x, y, sx, sy;
    uint32_t d;      /* direction of the last move (4 = as if arrived heading W) */
    uint32_t first;  /* first move, 8 before it */
    uint32_t steps;
} ssda__tracer_t;

SSDA_INTERNAL void ssda__trace_begin(ssda__tracer_t *t, const ssda__member_t *set, uint32_t sx, uint32_t sy);
/* The next move (ring position 0..7; the tracer moves), or 8 at the end. */
SSDA_INTERNAL uint32_t ssda__trace_step(ssda__tracer_t *t);

/* Boundary length in Q16 px (steps of 1 = 65536 and sqrt 2 = 92682). */
SSDA_INTERNAL uint64_t ssda__trace_length(const ssda__member_t *set, uint32_t sx, uint32_t sy);

/* n (power of two, 2^log2n) samples equally spaced along the boundary of
   length len_q16 (from ssda__trace_length), from the start pixel. */
SSDA_INTERNAL void ssda__trace_sample(const ssda__member_t *set, uint32_t sx, uint32_t sy, uint64_t len_q16,
                        uint32_t log2n, ssda_point_q8_t *out);

/* log2 of a power of two 8..SSDA_LOOPS_MAX_SAMPLES, or 0 if v is not one. */
SSDA_INTERNAL uint32_t ssda__samples_log2(uint32_t v);

#endif /* SSDA_LOOPS_INTERNAL_H */
