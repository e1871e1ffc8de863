/* f0_csv.c - reference f0 CSV reading and sampling. */
#include "f0_csv.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int f0_csv_read(const char *path, f0_track_t *tr, char *err, size_t errlen)
{
    FILE *fp = fopen(path, "r");
    char line[256];
    size_t cap = 0, n = 0, lineno = 0;
    double *t = NULL, *f = NULL;
    if (fp == NULL) {
        snprintf(err, errlen, "cannot open '%s': %s", path, strerror(errno));
        return -1;
    }
    while (fgets(line, sizeof line, fp) != NULL) {
        double a, b;
        lineno++;
        if (sscanf(line, "%lf , %lf", &a, &b) != 2) {
            if (lineno == 1) {
                continue; /* header */
            }
            if (line[0] == '\r' || line[0] == '\n') {
                continue;
            }
            snprintf(err, errlen, "'%s' line %zu: expected time_s,f0_hz", path, lineno);
            free(t);
            free(f);
            fclose(fp);
            return -1;
        }
        if (n == cap) {
            size_t nc = cap ? cap * 2 : 1024;
            double *nt = realloc(t, nc * sizeof *nt), *nf;
            if (nt == NULL) {
                break;
            }
            t = nt;
            nf = realloc(f, nc * sizeof *nf);
            if (nf == NULL) {
                break;
            }
            f = nf;
            cap = nc;
        }
        t[n] = a;
        f[n] = b > 0.0 ? b : 0.0;
        n++;
    }
    fclose(fp);
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
