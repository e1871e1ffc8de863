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
 * whole grid) on `threads` threads (the caller's thread included). Rows are
 * taken in turn; row r solves column c once row r-1 has solved c+1 (with no
 * prediction rows are independent), so vectors, statuses and the counts in
 * *stats are those of one ssda_track call for any thread count. Each thread
 * gets its own copy of cfg->match.work (cfg->match.work_size bytes).
 * prog (may be NULL) is advanced by whole rows. Returns an ssda error code
 * (SSDA_ERR_BUFFER when a work buffer cannot be allocated).
 */
int track_wave(const ssda_view_t *a, const ssda_view_t *b, const ssda_track_config_t *cfg,
               const ssda_track_grid_t *g, unsigned threads, ssda_track_vector_t *out,
               ssda_track_stats_t *stats, progress_t *prog);

/* *t += *s, field by field (counts of parts of one grid). */
void track_stats_add(ssda_track_stats_t *t, const ssda_track_stats_t *s);

#endif /* SSDA_TRACK_WAVE_H */
