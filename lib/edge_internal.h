/* edge_internal.h - shared by the edge and loop stages (lib/edge_*.c,
   lib/loops_*.c): 3 x 3 ring codes, chain steps, private map bits. */
#ifndef SSDA_EDGE_INTERNAL_H
#define SSDA_EDGE_INTERNAL_H

#include "compiler.h"

#include "ssda/edge.h"

/* Private map bits (11-15): zero between public calls. */
#define SSDA__EDGE_MARK 0x0800u    /* a pixel of the current trail or fill */
#define SSDA__EDGE_SEEN 0x1000u    /* visited by an earlier fill */
#define SSDA__EDGE_END 0x2000u     /* an end already consumed by a closing */
#define SSDA__EDGE_PRIVATE 0xF800u

/* Ring positions k = 0..7 around a pixel: E, NE, N, NW, W, SW, S, SE
   (x right, y down; counter-clockwise on screen). Even k: 4-neighbours. */
extern const int8_t ssda__ring_dx[8];
extern const int8_t ssda__ring_dy[8];

/* 8-bit ring code of (x, y): bit k set when the neighbour at k is ON
   (outside the map: OFF). (x, y) must be inside the map. */
SSDA_INTERNAL uint32_t ssda__edge_ring(const uint16_t *map, uint32_t w, uint32_t h, uint32_t x, uint32_t y);

/* Facts about a ring code. */
typedef struct {
    uint32_t runs;       /* cyclic runs of set bits, 0..3 (3: three or more;
                            0 for 0x00, 1 for 0xFF) */
    uint32_t c8;         /* 1: the set bits are one 8-connected component
                            within the ring; 2: not (0x00 gives 2) */
    bool unsuitable;     /* a run of >= 4, or a run of 3 centred on a diagonal */
    bool keeps4;         /* every set 4-neighbour lies in one run */
    uint32_t bg4;        /* 4-neighbours not set, 0..4 */
} ssda__ring_info_t;

SSDA_INTERNAL void ssda__ring_info(uint32_t ring, ssda__ring_info_t *info);

/* The seed's class of a ring code (ssda_edge_class_t). */
SSDA_INTERNAL uint32_t ssda__ring_class(uint32_t ring);

/* The position the chain leaves (x, y) by, coming from ring position
   `back` (the neighbour it came from): the other run must be the only
   one; its 4-neighbour position if it has one, else its middle.
   Returns 0..7, or 8 when (x, y) is an end or a branch. */
SSDA_INTERNAL uint32_t ssda__chain_next(uint32_t ring, uint32_t back);

/* Position of an end's single run to leave it by: its 4-neighbour if it
   has one, else its middle (seed appendix: 4-connection first). ring must
   have exactly one run. */
SSDA_INTERNAL uint32_t ssda__end_exit(uint32_t ring);

/* A walk along a chain from an end. */
#define SSDA__WALK_MAX 16u
typedef struct {
    int32_t x[SSDA__WALK_MAX], y[SSDA__WALK_MAX]; /* the pixels, the end first */
    uint32_t n;    /* pixels walked, 1..limit */
    bool stopped;  /* met a branch point (not counted) or another end */
} ssda__walk_t;

/* Walk from the end (x, y) for up to limit (1..SSDA__WALK_MAX) pixels. */
SSDA_INTERNAL void ssda__edge_walk(const uint16_t *map, uint32_t w, uint32_t h, uint32_t x, uint32_t y,
                     uint32_t limit, ssda__walk_t *wk);

/* (c): thinning stages until no deletion; returns pixels deleted. */
SSDA_INTERNAL uint32_t ssda__edge_thin(uint16_t *map, uint32_t w, uint32_t h);

/* Draw an 8-connected straight line of ON pixels from (x0, y0) to (x1, y1)
   (both inside the map). Returns pixels newly set. */
SSDA_INTERNAL uint32_t ssda__edge_line(uint16_t *map, uint32_t w, int32_t x0, int32_t y0, int32_t x1,
                         int32_t y1);

/* An end for (d) and (e): pixel index and its fitted direction. */
typedef struct {
    uint16_t x, y;   /* pixel; x = 0xFFFF once consumed by a closing */
    int16_t ux, uy;  /* unit vector, Q14, pointing out of the end */
} ssda__edge_end_t;

/* Collect ends (raster order) that have a branch of at least spur_min
   pixels, with their directions fitted over fit_len pixels; at most cap.
   Returns the number found (may exceed cap: only cap are stored). */
SSDA_INTERNAL uint32_t ssda__edge_ends(const uint16_t *map, uint32_t w, uint32_t h, uint32_t spur_min,
                         uint32_t fit_len, ssda__edge_end_t *ends, uint32_t cap);

/* (d): extend each end along the strength. Adds to *extended, *joined. */
SSDA_INTERNAL void ssda__edge_extend(uint16_t *map, uint32_t w, uint32_t h, const ssda__edge_end_t *ends,
                       uint32_t n, uint32_t extend_min, uint32_t extend_max,
                       uint32_t *extended, uint32_t *joined);

/* (e) settings, resolved from ssda_edge_refine_config_t. */
typedef struct {
    int32_t gap;           /* px */
    uint32_t fit;          /* pixels of an end's own branch (not a T target) */
    int32_t i_cos_q14;     /* cos of the largest I angle sum, Q14 */
    uint32_t i_angle;      /* largest I angle sum, turns */
    int32_t i_area;        /* px^2 */
    uint32_t v_angle;      /* smallest V angle, turns */
} ssda__edge_gap_cfg_t;

/* (e): T, I, V closing. Counts by type into t, i, v. */
SSDA_INTERNAL void ssda__edge_close(uint16_t *map, uint32_t w, uint32_t h, ssda__edge_end_t *ends,
                      uint32_t n, const ssda__edge_gap_cfg_t *cfg, uint32_t *t, uint32_t *i,
                      uint32_t *v);

#endif /* SSDA_EDGE_INTERNAL_H */
