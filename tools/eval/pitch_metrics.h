/* pitch_metrics.h - frame-level pitch metrics against a reference. */
#ifndef SSDA_EVAL_PITCH_METRICS_H
#define SSDA_EVAL_PITCH_METRICS_H
#include <stddef.h>
#include <stdint.h>

/* One frame of an estimator's output, with the reference at its centre. */
typedef struct {
    double t_s;       /* frame centre */
    double f0_hz;     /* estimate (may be > 0 even when not voiced) */
    int voiced;       /* the estimator's voicing decision */
    double ref_hz;    /* reference at t_s, 0 = unvoiced */
    uint32_t diffs;   /* absolute differences (ssda only) */
    double conf;      /* the estimator's confidence, 0..1 */
} frame_t;

typedef struct {
    size_t frames;        /* all frames */
    size_t both_voiced;   /* voiced in reference and estimate */
    size_t ref_voiced;
    size_t gross;         /* > 20 % off, among both_voiced */
    size_t gross_raw;     /* > 20 % off (or no f0), among ref_voiced, ignoring voicing */
    size_t voicing_err;   /* voicing decision differs */
    double fpe_mean_abs;  /* mean |cents| over both_voiced non-gross frames */
    double fpe_sd;        /* standard deviation of cents, same frames */
    double fpe_bias;      /* mean cents, same frames */
    double diffs_voiced;  /* mean absolute differences per ref-voiced frame */
    double diffs_all;     /* mean absolute differences per frame */
} metrics_t;

/* Accumulating form: metrics_add() over several files, then metrics_done(). */
typedef struct {
    metrics_t m;
    double sum_c, sum_c2, sum_abs, sum_dv, sum_da;
    size_t fine;
} metrics_acc_t;

void metrics_add(metrics_acc_t *acc, const frame_t *frames, size_t n);
metrics_t metrics_done(const metrics_acc_t *acc);

#endif
