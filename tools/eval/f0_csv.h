/* f0_csv.h - reference f0 tracks: reading `time_s,f0_hz` CSV files (0 =
   unvoiced; CR/LF and a header line tolerated) and sampling them at frame
   times. */
#ifndef SSDA_EVAL_F0_CSV_H
#define SSDA_EVAL_F0_CSV_H
#include <stddef.h>

typedef struct {
    double *t_s;
    double *f0_hz;
    size_t n;
} f0_track_t;

/* Returns 0, or -1 with a message in err (at least 2 rows; the parser is
   f0_csv_read of tools/common/pitch_run.h). The track is malloc'ed. */
int f0_track_read(const char *path, f0_track_t *tr, char *err, size_t errlen);
void f0_track_free(f0_track_t *tr);

/* Reference f0 at time t: linear between two voiced neighbours; when one
   of them is unvoiced, the nearer one decides; 0 outside the track. */
double f0_track_at(const f0_track_t *tr, double t_s);

#endif
