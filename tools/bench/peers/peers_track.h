/*
 * peers_track.h - grid tracking side by side: ssda's exact SSDA (automatic
 * threshold, median prediction, bounds) and its brute force (`none`, the
 * same SIMD kernel) against OpenCV matchTemplate (TM_SQDIFF and
 * TM_CCOEFF_NORMED) on the same windows and areas.
 */
#ifndef SSDA_PEERS_TRACK_H
#define SSDA_PEERS_TRACK_H

#include <stdio.h>

#include "cv_peer.h"
#include "ssda/view.h"

/* An image pair as both libraries get it. */
typedef struct {
    const char *name;                 /* row label, e.g. "GOES-16" */
    const char *description;          /* one line for the section header */
    ssda_view_t first, second;        /* FIRST (earlier), SECOND (later) */
    cv_peer_image_t *cv_first;        /* the same images for OpenCV */
    cv_peer_image_t *cv_second;
    int use_mask;                     /* 1: windows touching mask_value are */
    uint16_t mask_value;              /*    left out for every method */
    int synthetic_truth;              /* 1: made by synth_moved: known motion */
} peers_pair_t;

/* Track win x win windows (step win) in the 2 win x 2 win area centred on
   each, over the whole SECOND image; time every method reps times,
   interleaved, and print a Markdown section. Ratios go to ratios (may be
   NULL). Returns 0, or -1 on an error (message on stderr). */
int peers_track(const peers_pair_t *pair, unsigned win, int reps, FILE *ratios);

#endif /* SSDA_PEERS_TRACK_H */
