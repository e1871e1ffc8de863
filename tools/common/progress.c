/* progress.c - stderr progress bar, terminal only. */
#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

#define PROGRESS_DELAY_S 0.4   /* runs shorter than this never show a bar */
#define PROGRESS_PERIOD_S 0.1  /* redraw period */
#define PROGRESS_WIDTH 30      /* bar cells */

double progress_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void progress_begin(progress_t *p, const char *label, uint64_t total, int quiet)
{
    p->enabled = !quiet && isatty(STDERR_FILENO);
    p->drawn = 0;
    p->label = label;
    p->total = total > 0 ? total : 1;
    p->t_start = p->t_last = progress_now();
}

void progress_update(progress_t *p, uint64_t done)
{
    double now, frac, eta;
    int cells, i;
    char bar[PROGRESS_WIDTH + 1];

    if (!p->enabled) {
        return;
    }
    now = progress_now();
    if (now - p->t_start < PROGRESS_DELAY_S || now - p->t_last < PROGRESS_PERIOD_S) {
        return;
    }
    p->t_last = now;
    if (done > p->total) {
        done = p->total;
    }
    frac = (double)done / (double)p->total;
    cells = (int)(frac * PROGRESS_WIDTH + 0.5);
    for (i = 0; i < PROGRESS_WIDTH; i++) {
        bar[i] = i < cells ? '#' : '.';
    }
    bar[PROGRESS_WIDTH] = '\0';
    eta = frac > 0.0 ? (now - p->t_start) * (1.0 - frac) / frac : 0.0;
    fprintf(stderr, "\r%s [%s] %3d%%  %llu/%llu  eta %.0fs \033[K", p->label, bar,
            (int)(frac * 100.0), (unsigned long long)done, (unsigned long long)p->total, eta);
    fflush(stderr);
    p->drawn = 1;
}

void progress_end(progress_t *p)
{
    if (p->enabled && p->drawn) {
        fputs("\r\033[K", stderr);
        fflush(stderr);
    }
    p->drawn = 0;
}
