/*
 * track_wave.h - grid tracking in RAM on several threads with ssda_track's
 * exact result: a wavefront of grid rows over ssda_track_row.
 */
#ifndef SSDA_TRACK_WAVE_H
#define SSDA_TRACK_WAVE_H

#include "progress.h"
#include "ssda/track.h"

/*
 * Track grid g of cfg over views a (FIRST) and b (SECOND) into out (the
 * whole grid) on `threads` threads (the caller's thread included; 1 runs
 * everything on it, in order). Every grid row is solved as fixed bands of
 * columns, one ssda_track_row call each (the same calls for any thread
 * count); rows are taken in turn, and a band of row r starts once row r-1
 * has solved the column right of the band's end (with no prediction rows
 * are independent). Vectors, statuses and exact flags are those of one
 * ssda_track call; so are the counts in *stats, except pixel_ops with
 * shared bound tables (cfg->match.work_size >= SSDA_TRACK_WORK_SIZE_SHARED):
 * each call builds the tables of its band, so pixel_ops counts the tables
 * of these calls, which the fixed bands make the same for any thread count.
 * The caller's thread runs on cfg->match.work; each other thread on its
 * own copy (cfg->match.work_size bytes), or, when that cannot be
 * allocated, not at all (the others take its rows: the same output).
 * prog (may be NULL) is advanced by whole rows. Returns an ssda error code
 * (SSDA_ERR_BUFFER when the progress table cannot be allocated).
 */
int track_wave(const ssda_view_t *a, const ssda_view_t *b, const ssda_track_config_t *cfg,
               const ssda_track_grid_t *g, unsigned threads, ssda_track_vector_t *out,
               ssda_track_stats_t *stats, progress_t *prog);

/* *t += *s, field by field (counts of parts of one grid). */
void track_stats_add(ssda_track_stats_t *t, const ssda_track_stats_t *s);

#endif /* SSDA_TRACK_WAVE_H */
