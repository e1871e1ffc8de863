/*
 * track_metric.h - `ssda track --metric sad|ncc|absncc` (and compare): the
 * correlation coefficient rho of every searched window, and with ncc or
 * absncc the vectors of the exact correlation search (ssda/ncc.h) instead
 * of SAD's. A path of its own after the grid tracking: ssda_track decides
 * the grid and the statuses that do not depend on the metric (edge,
 * masked, excluded, flat) and finds the SAD vectors; each searched window
 * (ok, ambiguous, at_limit) is then searched again by ssda_ncc_match over
 * the same area of FIRST, starting at SAD's placement (SSDA_NCC_PREDICT:
 * a good first bar for the early exit; the answer does not depend on it),
 * and that search decides its status: at_limit when its best placement
 * lies on the border of the range (track.h's rule), else ok. ambiguous is
 * not computed for the correlation: the search keeps no second best (the
 * early exit abandons placements that cannot beat the best), see
 * docs/cli.md.
 */
#ifndef SSDA_TRACK_METRIC_H
#define SSDA_TRACK_METRIC_H

#include "track_run.h"

/* track_opts_t.metric: TRACK_METRIC_NONE = --metric not given (no rho). */
enum { TRACK_METRIC_NONE = 0, TRACK_METRIC_SAD, TRACK_METRIC_NCC, TRACK_METRIC_ABSNCC };

/* "sad", "ncc", "absncc" -> TRACK_METRIC_*, or -1. */
int track_metric_parse(const char *name);
/* TRACK_METRIC_* -> "sad", "ncc", "absncc" ("sad" for NONE). */
const char *track_metric_name(int metric);

/* After the tracking: rho of every searched window at its placement; with
   ncc or absncc each searched window's dx, dy, sub_dx_q8, sub_dy_q8, sad
   (SAD at the new placement), unique_q8 (SSDA_MATCH_UNIQUE_NONE), exact
   (true) and status (AT_LIMIT when the correlation's best is on the border
   of the range, else OK) from the correlation search, and r->stats' ok,
   ambiguous (0) and at_limit counted again. Fills r->rho_q30 (grid.count
   entries, INT32_MIN where not searched), r->metric_secs, r->metric_ops.
   Nothing without --metric. Returns CLI_OK, CLI_USAGE (a window too large
   for the correlation search) or CLI_INPUT (out of memory, a refused
   search). */
int track_metric_apply(const char *cmd, const track_opts_t *o, track_result_t *r);

/* JSON: the window's "rho" (number, 6 decimals) when computed. */
void track_metric_json_window(cJSON *item, const track_result_t *r, size_t k);
/* JSON: "metric" in "options"; "metric_pixel_ops", "metric_time_s" in "stats". */
void track_metric_json_options(cJSON *opt, const track_opts_t *o);
void track_metric_json_stats(cJSON *st, const track_opts_t *o, const track_result_t *r);
/* Summary line: the metric, the median rho of the ok windows, the time. */
void track_metric_print(const track_opts_t *o, const track_result_t *r);

#endif /* SSDA_TRACK_METRIC_H */
