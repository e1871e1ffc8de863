/*
 * draw.h - pictures of results, drawn with cairo (host only):
 *   - a motion-vector overlay on a grayscale image (arrows scaled for
 *     visibility, coloured by status, a legend with the scale);
 *   - a pitch plot (f0 against time, optionally over a reference track,
 *     with the waveform underneath).
 * Both are written as RGB PNG files atomically (temp file + rename).
 */
#ifndef SSDA_DRAW_H
#define SSDA_DRAW_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "png_io.h"

/* Status of one window's vector; decides its colour and mark. */
typedef enum {
    DRAW_OK = 0,       /* matched: arrow (yellow) */
    DRAW_EXCLUDED = 1, /* too little texture, not searched: grey cross */
    DRAW_MASKED = 2,   /* window holds fill pixels (--mask-value): magenta square */
    DRAW_EDGE = 3,     /* search area leaves the image: orange ring */
    DRAW_FLAT = 4,     /* no texture (below the flat level), not searched: blue-grey dot */
    DRAW_AMBIGUOUS = 5, /* another placement about as good: violet diamond */
    DRAW_AT_LIMIT = 6, /* best placement on the border of the range: red arrow */
    DRAW_STATUS_COUNT = 7
} draw_status_t;

/* One window's vector, in the background image's pixel coordinates. */
typedef struct {
    double x, y;        /* arrow tail: the window's centre */
    double dx, dy;      /* motion in px (x right, y down); DRAW_OK and DRAW_AT_LIMIT */
    int status;         /* draw_status_t */
    int has_truth;      /* 1: tdx, tdy hold the known motion (drawn thin, cyan) */
    double tdx, tdy;
} draw_vector_t;

typedef struct {
    const char *title;     /* first line above the image; NULL for none */
    const char *subtitle;  /* second line (statistics); NULL for none */
    double arrow_scale;    /* drawn arrow length / motion length; 0 = automatic
                              (longest common vector about one grid step) */
    double grid_step;      /* px between window centres (for the automatic scale) */
    const char *truth_label; /* legend text of the reference arrows
                              (NULL = "known motion (truth)") */
    int have_mask;         /* 1: pixels equal to mask_value are ignored when */
    uint32_t mask_value;   /*    stretching the background's contrast */
    unsigned every;        /* > 1: the caller passes only every k-th grid column
                              and row (a dense grid); the legend says so */
} draw_vectors_opts_t;

/* The zoom draw_vectors_to uses for a w x h background (output px per
   image px), so a caller can thin a grid too dense to read. */
double draw_vectors_zoom(uint32_t w, uint32_t h);
/* "st", "nd", "rd" or "th": the ordinal suffix of n (for "every 3rd"). */
const char *ordinal_suffix(unsigned n);

/*
 * Draw the n vectors over bg (contrast-stretched between its 0.5 % and
 * 99.5 % levels; small images enlarged, large ones reduced to fit about
 * 1600 px) and write a PNG to path ("-" = stdout). *scale_used, if not
 * NULL, receives the arrow scale drawn. Returns 0, or -1 with a message in
 * err and no file left.
 */
int draw_vectors_png(const char *path, const gray_image_t *bg, const draw_vector_t *v,
                     size_t n, const draw_vectors_opts_t *opts, double *scale_used,
                     char *err, size_t errlen);
/* The same, written to an open stream (name is for messages); the caller
   owns fp (e.g. an atomic_file_t committed with other outputs). */
int draw_vectors_to(FILE *fp, const char *name, const gray_image_t *bg, const draw_vector_t *v,
                    size_t n, const draw_vectors_opts_t *opts, double *scale_used, char *err,
                    size_t errlen);

/* A pitch track: frames at times t[i] (s) with f0[i] in Hz, 0 = unvoiced. */
typedef struct {
    const double *t;
    const double *f0;
    size_t n;
} draw_track_t;

typedef struct {
    const char *title;          /* NULL for none */
    const char *subtitle;       /* NULL for none */
    draw_track_t estimate;      /* drawn as dots joined within voiced runs */
    draw_track_t reference;     /* n = 0 for none; drawn as a wide pale band */
    const char *reference_label; /* legend text (NULL = "reference") */
    const int16_t *samples;     /* waveform under the plot; NULL for none */
    size_t sample_count;
    uint32_t sample_rate;       /* Hz, needed with samples */
    double fmin, fmax;          /* y range in Hz; 0 = from the data */
} draw_pitch_opts_t;

/* Draw a pitch plot and write it as a PNG. Returns 0 or -1 (message in err). */
int draw_pitch_png(const char *path, const draw_pitch_opts_t *opts, char *err, size_t errlen);
/* The same, written to an open stream (name is for messages). */
int draw_pitch_to(FILE *fp, const char *name, const draw_pitch_opts_t *opts, char *err,
                  size_t errlen);

#endif /* SSDA_DRAW_H */
