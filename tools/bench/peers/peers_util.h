/*
 * peers_util.h - what the peer benchmarks share: a monotonic clock,
 * medians, agreement of vectors, and the ratios file the chart is drawn from.
 */
#ifndef SSDA_PEERS_UTIL_H
#define SSDA_PEERS_UTIL_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Wall clock, seconds (CLOCK_MONOTONIC). */
double peers_now(void);

/* Processor time of the calling thread, seconds (CLOCK_THREAD_CPUTIME_ID):
   unlike the wall clock it does not count time the thread spent waiting
   for a core, so it moves less on a loaded machine. */
double peers_cpu_now(void);

/* Median of v[0..n-1] (reorders v). 0 for n == 0. */
double peers_median(double *v, size_t n);

/* Agreement of two vector fields over n windows: counts of windows whose
   vectors are equal, and within 1 and 2 px in both components. */
typedef struct {
    uint32_t n, same, within1, within2;
} peers_agree_t;

void peers_agree_add(peers_agree_t *a, int dx0, int dy0, int dx1, int dy1);

/* "100.0 % / 100.0 % / 100.0 %" (equal / within 1 / within 2) into buf. */
const char *peers_agree_str(const peers_agree_t *a, char *buf, size_t len);

/* Ratios for the chart: one line "group<TAB>label<TAB>value" per ratio
   (value > 1: ssda faster). fp may be NULL (nothing written). */
void peers_ratio(FILE *fp, const char *group, const char *label, double value);

#endif /* SSDA_PEERS_UTIL_H */
