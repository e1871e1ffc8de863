/*
 * peers_search.h - single large searches side by side: one template
 * searched over a whole image by ssda (automatic threshold with and
 * without bounds, brute force) and by OpenCV matchTemplate, whose
 * correlation by DFT gets cheaper per placement as templates grow.
 */
#ifndef SSDA_PEERS_SEARCH_H
#define SSDA_PEERS_SEARCH_H

#include <stddef.h>
#include <stdio.h>

#include "cv_peer.h"
#include "ssda/view.h"

/* Templates are cut from `moved` and searched in all of `image`. */
typedef struct {
    const char *name;                /* row label, e.g. "camera" */
    const char *description;         /* one line for the section header */
    ssda_view_t image, moved;
    cv_peer_image_t *cv_image;       /* the same images for OpenCV */
    cv_peer_image_t *cv_moved;
    int synthetic_truth;             /* 1: moved = synth_moved(image): known motion */
} peers_scene_t;

/* For each template side in sizes[0..n-1]: four templates (centred on the
   quarter points of `moved`), each searched over the whole image by every
   method, reps interleaved repetitions; prints a Markdown section, ratios
   to ratios (may be NULL). Returns 0, or -1 on an error. */
int peers_search(const peers_scene_t *s, const unsigned *sizes, size_t n, int reps,
                 FILE *ratios);

#endif /* SSDA_PEERS_SEARCH_H */
