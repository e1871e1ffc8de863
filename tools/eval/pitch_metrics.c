/* pitch_metrics.c - GPE, FPE, VDE and work per frame. */
#include "pitch_metrics.h"

#include <math.h>
#include <string.h>

void metrics_add(metrics_acc_t *acc, const frame_t *fr, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        int rv = fr[i].ref_hz > 0.0;
        int ev = fr[i].voiced && fr[i].f0_hz > 0.0;
        acc->m.frames++;
        acc->sum_da += fr[i].diffs;
        if (rv != ev) {
            acc->m.voicing_err++;
        }
        if (rv) {
            acc->m.ref_voiced++;
            acc->sum_dv += fr[i].diffs;
            if (!(fr[i].f0_hz > 0.0) || fabs(fr[i].f0_hz / fr[i].ref_hz - 1.0) > 0.2) {
                acc->m.gross_raw++;
            }
        }
        if (rv && ev) {
            double c = 1200.0 * log2(fr[i].f0_hz / fr[i].ref_hz);
            acc->m.both_voiced++;
            if (fabs(fr[i].f0_hz / fr[i].ref_hz - 1.0) > 0.2) {
                acc->m.gross++;
            } else {
                acc->fine++;
                acc->sum_c += c;
                acc->sum_c2 += c * c;
                acc->sum_abs += fabs(c);
            }
        }
    }
}

metrics_t metrics_done(const metrics_acc_t *acc)
{
    metrics_t m = acc->m;
    if (acc->fine > 0) {
        double mean = acc->sum_c / (double)acc->fine;
        double var = acc->sum_c2 / (double)acc->fine - mean * mean;
        m.fpe_bias = mean;
        m.fpe_mean_abs = acc->sum_abs / (double)acc->fine;
        m.fpe_sd = var > 0.0 ? sqrt(var) : 0.0;
    }
    m.diffs_voiced = m.ref_voiced ? acc->sum_dv / (double)m.ref_voiced : 0.0;
    m.diffs_all = m.frames ? acc->sum_da / (double)m.frames : 0.0;
    return m;
}
