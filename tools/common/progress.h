/*
 * progress.h - a one-line progress bar on stderr for long runs (host only).
 *
 * Drawn only when stderr is a terminal and the caller did not ask for quiet,
 * and only once a run has lasted a moment (short runs never flicker). The
 * line is erased when the run finishes, so normal output stays clean.
 */
#ifndef SSDA_PROGRESS_H
#define SSDA_PROGRESS_H

#include <stdint.h>

typedef struct {
    int enabled;        /* 1: stderr is a terminal and not quiet */
    int drawn;          /* 1: something is on the line now */
    const char *label;  /* shown before the bar, e.g. "tracking" */
    uint64_t total;     /* units of work in the run (>= 1) */
    double t_start;     /* seconds, monotonic */
    double t_last;      /* last redraw */
} progress_t;

/* Start a run of total units. quiet = 1 disables the bar. */
void progress_begin(progress_t *p, const char *label, uint64_t total, int quiet);
/* done units finished so far (0..total). Redraws at most ten times a second. */
void progress_update(progress_t *p, uint64_t done);
/* Erase the bar. */
void progress_end(progress_t *p);

/* Seconds on a monotonic clock (for timings printed by the tools). */
double progress_now(void);

#endif /* SSDA_PROGRESS_H */
