/* peers_util.c - clock, medians, agreement and ratio lines (see header). */
#include "peers_util.h"

#include <stdlib.h>
#include <time.h>

double peers_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double peers_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

double peers_median(double *v, size_t n)
{
    if (n == 0) {
        return 0.0;
    }
    qsort(v, n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void peers_agree_add(peers_agree_t *a, int dx0, int dy0, int dx1, int dy1)
{
    int ex = abs(dx0 - dx1), ey = abs(dy0 - dy1);
    a->n++;
    a->same += ex == 0 && ey == 0;
    a->within1 += ex <= 1 && ey <= 1;
    a->within2 += ex <= 2 && ey <= 2;
}

const char *peers_agree_str(const peers_agree_t *a, char *buf, size_t len)
{
    double n = a->n ? (double)a->n : 1.0;
    snprintf(buf, len, "%.1f %% / %.1f %% / %.1f %%", 100.0 * a->same / n, 100.0 * a->within1 / n,
             100.0 * a->within2 / n);
    return buf;
}

void peers_ratio(FILE *fp, const char *group, const char *label, double value)
{
    if (fp != NULL) {
        fprintf(fp, "%s\t%s\t%.6g\n", group, label, value);
    }
}
