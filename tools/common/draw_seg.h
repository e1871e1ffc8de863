/*
 * draw_seg.h - pictures of a segmentation, drawn with cairo (host only):
 *   - histograms with their fitted Gaussian components and the sum, one
 *     panel per feature (the seed's Figs. 2.3-2.5);
 *   - colour-coded label images, one panel per feature, each with a legend.
 * Written as RGB PNG to an open stream (the caller commits it atomically).
 */
#ifndef SSDA_DRAW_SEG_H
#define SSDA_DRAW_SEG_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* One feature's histogram and mixture. */
typedef struct {
    const char *title;     /* panel title */
    const uint32_t *hist;  /* bins counts */
    uint32_t bins;
    uint32_t count;        /* components */
    const double *weight;  /* per component: share of total */
    const double *mean;    /* bins */
    const double *sigma;   /* bins */
    double total;          /* pixels in the histogram */
} draw_hist_panel_t;

/* Histogram panels stacked vertically, x zoomed to the occupied bins.
   Returns 0, or -1 with a message in err. */
int draw_hist_to(FILE *fp, const char *name, const char *title, const draw_hist_panel_t *p,
                 size_t n, char *err, size_t errlen);

/* One feature's labels. */
typedef struct {
    const char *title;
    const uint8_t *labels;       /* width x height, 0..count */
    const uint8_t *contour;      /* nonzero: a contour pixel (drawn white); NULL */
    const uint8_t *nodata;       /* nonzero: masked (drawn black); NULL */
    uint32_t count;              /* components: labels 1..count */
    const char *const *legend;   /* count + 1 lines, [0] for label 0 */
} draw_label_panel_t;

/* Label panels side by side, each scaled to about 700 px wide at most,
   with its legend below. Returns 0 or -1 (message in err). */
int draw_labels_to(FILE *fp, const char *name, const char *title, uint32_t width,
                   uint32_t height, const draw_label_panel_t *p, size_t n, char *err,
                   size_t errlen);

/* The colour of label k (1..16; 0: unlabelled grey), components in the
   histogram plot use the same. */
void draw_label_rgb(uint32_t k, double rgb[3]);

#endif /* SSDA_DRAW_SEG_H */
