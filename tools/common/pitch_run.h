/*
 * pitch_run.h - a whole f0 track of an in-memory signal through the
 * library's streaming AMDF pitch (ssda_pitch_*), for the CLI and the demo,
 * and scoring a track against a reference (read by f0_ref.h).
 */
#ifndef SSDA_PITCH_RUN_H
#define SSDA_PITCH_RUN_H

#include <stddef.h>
#include <stdint.h>
#include "f0_ref.h" /* reference tracks (f0_ref_read, f0_csv_read) */
#include "progress.h"
#include "ssda/pitch.h"

/* One analysed signal. Frame i has two time stamps, in seconds:
   t:       the library's centre of the samples its chosen lag compares,
            i * hop + (K + lag) / 2 (the span's centre when silent): the most
            precise, used for scoring and plots, but not always increasing
            (a lag that drops by more than 2 hops between frames steps back);
   t_frame: the centre of the frame's span, i * hop + span / 2: increasing,
            for tables (the CSV's time_s). */
typedef struct {
    double *t;            /* seconds, n entries (malloc'ed) */
    double *t_frame;      /* seconds, n entries */
    double *f0;           /* Hz, 0 when unvoiced */
    double *f0_raw;       /* Hz of the chosen lag even when unvoiced; 0 when silent */
    uint16_t *confidence_q15;
    uint8_t *voiced;      /* 1 voiced, 0 not */
    size_t n;
    uint64_t diffs;       /* absolute differences computed (all frames) */
    size_t analysed;      /* frames searched: not silent (a silent frame costs nothing) */
    uint64_t full_diffs;  /* the full search on those frames: every lag the definition
                             reads, lag_min - 1 .. lag_max + 1, summed over K samples:
                             analysed * (lag_max - lag_min + 3) * K. SSDA_PITCH_FULL
                             computes this, and K more on a frame whose half-period
                             lag its dip rule reads (at most 1 / (lag_max - lag_min
                             + 3) more: 0.3 % at the defaults) */
    ssda_pitch_info_t info;
    uint32_t decimation;  /* input samples averaged per analysed sample (1 = none) */
    uint32_t input_rate;  /* Hz of the signal given */
} pitch_track_t;

/*
 * Analyse x[0..n-1] at rate Hz with cfg (its sample_rate_hz is set here; a
 * rate above 48000 Hz is first reduced by averaging groups of
 * ceil(rate / 48000) samples). prog may be NULL. Returns 0, or -1 with a
 * message in err (rate below 8000 Hz, a config the library refuses, signal
 * shorter than one analysis span, out of memory).
 */
int pitch_run(const int16_t *x, size_t n, uint32_t rate, const ssda_pitch_config_t *cfg,
              progress_t *prog, pitch_track_t *out, char *err, size_t errlen);
void pitch_track_free(pitch_track_t *tr);

/* A track scored against a reference (interpolated linearly to the track's
   frame times; a reference frame next to an unvoiced one counts as unvoiced). */
typedef struct {
    size_t frames;        /* frames inside the reference's time span */
    size_t both_voiced;
    double gpe;           /* share of both-voiced frames off by more than 20 % */
    double vde;           /* share of frames whose voicing decision differs */
    double fpe_cents;     /* mean |error| in cents over both-voiced frames within 20 % */
} pitch_score_t;

void pitch_score(const pitch_track_t *tr, const double *rt, const double *rf, size_t rn,
                 pitch_score_t *out);

#endif /* SSDA_PITCH_RUN_H */
