/* f0_csv.c - reference f0 CSV reading and sampling. */
#include "f0_csv.h"

#include "pitch_run.h"

#include <stdio.h>
#include <stdlib.h>

int f0_track_read(const char *path, f0_track_t *tr, char *err, size_t errlen)
{
    double *t = NULL, *f = NULL;
    size_t n = 0;
    if (f0_csv_read(path, &t, &f, &n, err, errlen) != 0) { /* tools/common/pitch_run.c */
        return -1;
    }
    if (n < 2) {
        snprintf(err, errlen, "'%s': fewer than 2 rows", path);
        free(t);
        free(f);
        return -1;
    }
    tr->t_s = t;
    tr->f0_hz = f;
    tr->n = n;
    return 0;
}

void f0_track_free(f0_track_t *tr)
{
    free(tr->t_s);
    free(tr->f0_hz);
    tr->t_s = tr->f0_hz = NULL;
    tr->n = 0;
}

double f0_track_at(const f0_track_t *tr, double t)
{
    size_t lo = 0, hi = tr->n - 1;
    double a, b, w;
    if (t < tr->t_s[0] || t > tr->t_s[tr->n - 1]) {
        return 0.0;
    }
    while (hi - lo > 1) { /* t_s[lo] <= t <= t_s[hi] */
        size_t mid = (lo + hi) / 2;
        if (tr->t_s[mid] <= t) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    a = tr->f0_hz[lo];
    b = tr->f0_hz[hi];
    w = tr->t_s[hi] > tr->t_s[lo] ? (t - tr->t_s[lo]) / (tr->t_s[hi] - tr->t_s[lo]) : 0.0;
    if (a > 0.0 && b > 0.0) {
        return a + w * (b - a);
    }
    return w < 0.5 ? a : b;
}
