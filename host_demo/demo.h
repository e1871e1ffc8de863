/*
 * demo.h - ssda-demo: the library end to end on the desktop. With no
 * arguments it makes its own inputs with a known answer (a cloud field
 * moved by a known wind, a voice with a known f0 contour), runs grid
 * tracking and pitch through the library, and reports accuracy against the
 * truth and the work the early exit saved. With arguments it does the same
 * on the user's files (without a truth to score against).
 */
#ifndef SSDA_DEMO_H
#define SSDA_DEMO_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "png_io.h"
#include "ssda/pitch.h"
#include "ssda/track.h"

/* ---- terminal ---- */
typedef struct {
    int quiet;           /* --quiet: only errors and the summary line */
    int color;           /* stdout is a terminal: bold headings */
    const char *out_dir; /* output folder */
} demo_ctx_t;

void demo_heading(const demo_ctx_t *c, const char *fmt, ...);
/* "out_dir/name" into buf. */
const char *demo_path(const demo_ctx_t *c, const char *name, char *buf, size_t len);

/* ---- synthetic clouds (demo_clouds.c) ---- */

/* The known wind: a uniform drift plus a Rankine vortex, px per frame. */
typedef struct {
    double u0, v0;        /* drift */
    double cx, cy;        /* vortex centre, px */
    double vmax, radius;  /* vortex peak speed (px/frame) at radius (px) */
} demo_wind_t;

/* Motion at (x, y) of the second image: it came from (x - u, y - v). */
void demo_wind_at(const demo_wind_t *w, double x, double y, double *u, double *v);

/* Make the pair: FIRST = clouds + noise, SECOND = the clouds advected by
   the wind (exactly, the field is procedural), slightly developed, + noise.
   8-bit, width x height. Returns 0 or -1 (out of memory). */
int demo_make_clouds(uint32_t width, uint32_t height, const demo_wind_t *wind,
                     double noise_sigma, gray_image_t *first, gray_image_t *second);

/* ---- synthetic voice (demo_voice.c) ---- */

typedef struct {
    int16_t *samples;     /* malloc'ed */
    size_t count;
    uint32_t rate;        /* Hz */
} demo_signal_t;

/* True f0 at time t (s), 0 where unvoiced (silence or hiss). */
double demo_voice_f0(double t);
/* A 3 s voice at rate Hz: two voiced phrases (glide with vibrato) around an
   unvoiced hiss, with silences. Returns 0 or -1. */
int demo_make_voice(uint32_t rate, demo_signal_t *sig);
/* Write as 16-bit WAV (atomic). Returns 0 or -1 (message printed). */
int demo_write_wav(const char *path, const demo_signal_t *sig);
/* Write the true f0 as time_s,f0_hz rows every 5 ms (atomic). */
int demo_write_truth_csv(const char *path, double secs);

/* ---- the two parts (demo_track.c, demo_pitch.c) ---- */

/* Track FIRST -> SECOND in several modes, print the table and the
   accuracy (against wind when not NULL), write overlay_name into the output
   folder. mask >= 0: fill value. exclude: the seed's texture rule with the
   mean of SECOND as the level. Returns 0 or -1. */
int demo_track(const demo_ctx_t *c, const gray_image_t *first, const gray_image_t *second,
               const demo_wind_t *wind, long mask, uint32_t step, int exclude,
               const char *overlay_name, const char *label);

/* Pitch of a signal; truth from demo_voice_f0 when synthetic, or a reference
   CSV (may be NULL). Prints the results, writes plot_name. Returns 0 or -1. */
int demo_pitch(const demo_ctx_t *c, const demo_signal_t *sig, int synthetic,
               const char *ref_csv, const char *plot_name, const char *label);

/* Colour segmentation (seed 004) of a synthetic aerial scene with known
   regions: K-L transform, mixtures, labels, scores; writes scene.png,
   segment_hist.png and segment_labels.png. Returns 0 or -1. */
int demo_segment(const demo_ctx_t *c);
/* Part 3: registration by closed loops (seed 001) of a synthetic aerial
   pair with a known similarity and gain; writes the inputs and
   symreg_overlay.png. Returns 0, or -1 on failure or when the corners are
   off by 2 px or more. */
int demo_symreg(const demo_ctx_t *c, const char *label_prefix);

#endif /* SSDA_DEMO_H */
