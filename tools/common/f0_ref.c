/* f0_ref.c - reference f0 tracks: time,f0 rows or one f0 per line (f0_ref.h). */
#include "f0_ref.h"
#include "tool_err.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_COLS 8 /* numbers looked at per line; more are not read */

typedef struct {
    double *t, *f0;
    size_t n, cap;
} rows_t;

/* The numbers of one line, separated by commas, semicolons, tabs or
   spaces: their count (up to MAX_COLS), or -1 when a field is not a
   finite number. */
static int split_numbers(char *line, double *v)
{
    int n = 0;
    char *p = line, *end;
    for (;;) {
        while (*p == ',' || *p == ';' || *p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') {
            p++;
        }
        if (*p == '\0') {
            return n;
        }
        errno = 0;
        double x = strtod(p, &end);
        if (end == p || !isfinite(x) ||
            (*end != '\0' && strchr(",; \t\r\n", *end) == NULL)) {
            return -1;
        }
        if (n < MAX_COLS) {
            v[n] = x;
        }
        n++;
        p = end;
    }
}

static int push_row(rows_t *r, double t, double f0)
{
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2u * r->cap : 1024u;
        double *t2 = realloc(r->t, cap * sizeof *t2), *f2;
        if (t2 == NULL) {
            return -1;
        }
        r->t = t2;
        if ((f2 = realloc(r->f0, cap * sizeof *f2)) == NULL) {
            return -1;
        }
        r->f0 = f2;
        r->cap = cap;
    }
    r->t[r->n] = t;
    r->f0[r->n] = f0;
    r->n++;
    return 0;
}

/* One data line's numbers (k of them) as a row: checks what the format
   needs. Returns 0, or -1 with the reason in err. */
static int take_row(rows_t *r, const double *v, int k, double hop_s, const char *path,
                    size_t lineno, char *err, size_t errlen)
{
    double t = hop_s > 0 ? (double)r->n * hop_s : v[0], f0 = hop_s > 0 ? v[0] : v[k > 1];
    if (hop_s > 0 && k != 1) {
        tool_set_err(err, errlen, "'%s' line %zu: %d columns; with --ref-hop each line holds "
                     "one f0 value", path, lineno, k);
        return -1;
    }
    if (hop_s <= 0 && k < 2) {
        tool_set_err(err, errlen, "'%s' line %zu: one column; expected time_s,f0_hz (a file of "
                     "one f0 per line needs --ref-hop SECONDS)", path, lineno);
        return -1;
    }
    if (f0 < 0.0 || t < 0.0) {
        tool_set_err(err, errlen, "'%s' line %zu: negative %s %g", path, lineno,
                     f0 < 0.0 ? "f0" : "time", f0 < 0.0 ? f0 : t);
        return -1;
    }
    if (hop_s <= 0 && r->n > 0 && t <= r->t[r->n - 1]) {
        tool_set_err(err, errlen, "'%s' line %zu: time %g s is not after the previous row's "
                     "%g s (times must increase; is the first column the time?)",
                     path, lineno, t, r->t[r->n - 1]);
        return -1;
    }
    if (push_row(r, t, f0) != 0) {
        tool_set_err(err, errlen, "out of memory reading '%s'", path);
        return -1;
    }
    return 0;
}

/* Every line of f into r. Returns 0 or -1 (message in err). */
static int read_lines(FILE *f, double hop_s, const char *path, rows_t *r, char *err,
                      size_t errlen)
{
    char line[1024];
    size_t lineno = 0;
    int seen_any = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        double v[MAX_COLS];
        char *p = line;
        int k;
        lineno++;
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') {
            p++;
        }
        if (*p == '\0' || *p == '#') {
            continue;
        }
        k = split_numbers(p, v);
        if (k < 0 && !seen_any) {
            seen_any = 1; /* a header line */
            continue;
        }
        seen_any = 1;
        if (k < 0) {
            tool_set_err(err, errlen, "'%s' line %zu: not numbers; expected %s", path, lineno,
                         hop_s > 0 ? "one f0 value (Hz)" : "time_s,f0_hz");
            return -1;
        }
        if (take_row(r, v, k, hop_s, path, lineno, err, errlen) != 0) {
            return -1;
        }
    }
    if (ferror(f)) {
        tool_set_err(err, errlen, "cannot read '%s': %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

int f0_ref_read(const char *path, double hop_s, double **t_out, double **f_out, size_t *n_out,
                char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    rows_t r = {NULL, NULL, 0, 0};
    int rc;
    if (f == NULL) {
        tool_set_err(err, errlen, "cannot open '%s': %s", path, strerror(errno));
        return -1;
    }
    rc = read_lines(f, hop_s, path, &r, err, errlen);
    fclose(f);
    if (rc == 0 && r.n == 0) {
        tool_set_err(err, errlen, "'%s' holds no %s", path,
                     hop_s > 0 ? "f0 values" : "time_s,f0_hz rows");
        rc = -1;
    }
    if (rc != 0) {
        free(r.t);
        free(r.f0);
        return -1;
    }
    *t_out = r.t;
    *f_out = r.f0;
    *n_out = r.n;
    return 0;
}

int f0_csv_read(const char *path, double **t, double **f0, size_t *n, char *err, size_t errlen)
{
    return f0_ref_read(path, 0.0, t, f0, n, err, errlen);
}
