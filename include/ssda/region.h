/*
 * region.h - regions of a label image, streamed by rows: isolated-point
 * removal (3 x 3), contours, and pixel counts per label.
 *
 * Seed: Fujimoto and Tanaka (../shared/seeds/004, section 2.3): each
 * extracted region is cleaned of isolated points, its contour drawn, and
 * its area measured by counting its pixels (area = pixels x the ground
 * area of a pixel). Labels come from mixture.h (ssda_mix_label_row) or
 * anywhere else: 8-bit, 0..255, 0 usually "no component".
 *
 * OPERATIONS (each job does one; chain two jobs for both, row by row):
 *   SSDA_REGION_CLEAN: a pixel none of whose 8 neighbours (those inside
 *     the image) has its label is isolated; it takes the label most
 *     frequent among those neighbours (ties: the smallest label). Every
 *     decision reads the input labels only, so the result does not depend
 *     on the order of the work. A 1 x 1 image is left as it is.
 *   SSDA_REGION_CONTOUR: a pixel of label L != 0 with a 4-neighbour (inside
 *     the image) of another label is on L's contour and keeps L; every
 *     other pixel becomes 0. The image border is not a contour.
 * COUNTS: with cfg.counts set, counts[label] is incremented for every
 * output pixel (256 counters; the caller zeroes them first and keeps the
 * totals below 2^32: one image of at most 65535 x 65535 pixels).
 *
 * STREAMING: rows are pushed top to bottom; output row y is written by the
 * push of row y + 1 (one row of delay), the last one by ssda_region_flush.
 * The job keeps the last three input rows in a caller ring of
 * SSDA_REGION_RING_SIZE(width) bytes. Input and output rows may not
 * overlap the ring; an output row may be the input row just pushed only
 * if the caller no longer needs it (the input is copied into the ring
 * before anything is written).
 */
#ifndef SSDA_REGION_H
#define SSDA_REGION_H

#include "ssda/ssda.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    SSDA_REGION_CLEAN = 0,  /* isolated-point removal */
    SSDA_REGION_CONTOUR = 1 /* contour pixels */
} ssda_region_op_t;

/* Ring bytes for rows of w labels: three rows. */
#define SSDA_REGION_RING_SIZE(w) (3u * (size_t)(w))

/* Job configuration. */
typedef struct {
    uint16_t width;   /* labels per row, 1..65535 */
    uint16_t height;  /* rows, 1..65535 */
    uint8_t op;       /* ssda_region_op_t */
    uint32_t *counts; /* 256 counters, added to for each output pixel; may be NULL */
} ssda_region_config_t;

/* A job. All fields are private. */
typedef struct {
    uint8_t *ring;
    uint32_t *counts;
    uint32_t magic;
    uint16_t width, height;
    uint16_t pushed; /* rows pushed so far */
    uint8_t op;
    uint8_t flushed;
} ssda_region_t;

/*
 * Start a job over a width x height label image. ring: at least
 * SSDA_REGION_RING_SIZE(width) bytes, owned by the caller, kept until the
 * job ends (as is cfg->counts).
 * Returns SSDA_OK, or with *job untouched: SSDA_ERR_NULL (job, cfg or ring
 * NULL), SSDA_ERR_SIZE (width or height 0), SSDA_ERR_ARG (unknown op),
 * SSDA_ERR_BUFFER (ring short).
 */
int ssda_region_init(ssda_region_t *job, const ssda_region_config_t *cfg, void *ring,
                     size_t ring_size);

/*
 * Push the next input row (width labels). For every row after the first,
 * out (width bytes) receives the output row before it and 1 is returned;
 * the first push returns 0 and writes nothing.
 * Returns 0 or 1, or: SSDA_ERR_NULL (job, labels or out NULL),
 * SSDA_ERR_STATE (not initialised, or every row already pushed).
 */
int ssda_region_push(ssda_region_t *job, const uint8_t *labels, uint8_t *out);

/*
 * After the last row: out receives the last output row; returns 1.
 * Returns SSDA_ERR_NULL, or SSDA_ERR_STATE (not initialised, rows still to
 * push, or already flushed).
 */
int ssda_region_flush(ssda_region_t *job, uint8_t *out);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_REGION_H */
