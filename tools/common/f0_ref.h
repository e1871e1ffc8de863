/*
 * f0_ref.h - reading a reference f0 track (pitch --ref, the evaluations):
 *   time,f0 rows   "time_s,f0_hz[,more columns]": commas, semicolons, tabs
 *                  or spaces between columns; a header line first is
 *                  optional; '#' lines and blank lines are skipped; times in
 *                  seconds, >= 0 and strictly increasing; columns after the
 *                  second are ignored (e.g. a confidence);
 *   f0 per line    with hop_s > 0: one f0 per line, frame i at i * hop_s
 *                  seconds (the format many corpora ship);
 * f0 in Hz, >= 0, 0 = unvoiced. Anything else is refused with the line
 * number and what was expected.
 */
#ifndef SSDA_F0_REF_H
#define SSDA_F0_REF_H

#include <stddef.h>

/* Read path (hop_s 0: time,f0 rows; > 0: one f0 per line). Returns 0 with
   *t and *f0 malloc'ed (*n >= 1 rows), or -1 with a message naming the file
   and the line in err. */
int f0_ref_read(const char *path, double hop_s, double **t, double **f0, size_t *n, char *err,
                size_t errlen);

/* f0_ref_read(path, 0, ...): time,f0 rows. */
int f0_csv_read(const char *path, double **t, double **f0, size_t *n, char *err,
                size_t errlen);

#endif
