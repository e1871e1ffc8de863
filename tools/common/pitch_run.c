/* pitch_run.c - whole-signal f0 tracks through ssda_pitch, reference CSVs, scores. */
#include "pitch_run.h"
#include "tool_err.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void pitch_track_free(pitch_track_t *tr)
{
    free(tr->t);
    free(tr->t_frame);
    free(tr->f0);
    free(tr->f0_raw);
    free(tr->confidence_q15);
    free(tr->voiced);
    memset(tr, 0, sizeof *tr);
}

static int track_grow(pitch_track_t *tr, size_t cap)
{
    double *t = realloc(tr->t, cap * sizeof *t);
    if (t != NULL) {
        tr->t = t;
    }
    double *tf = realloc(tr->t_frame, cap * sizeof *tf);
    if (tf != NULL) {
        tr->t_frame = tf;
    }
    double *f = realloc(tr->f0, cap * sizeof *f);
    if (f != NULL) {
        tr->f0 = f;
    }
    double *fr = realloc(tr->f0_raw, cap * sizeof *fr);
    if (fr != NULL) {
        tr->f0_raw = fr;
    }
    uint16_t *c = realloc(tr->confidence_q15, cap * sizeof *c);
    if (c != NULL) {
        tr->confidence_q15 = c;
    }
    uint8_t *v = realloc(tr->voiced, cap * sizeof *v);
    if (v != NULL) {
        tr->voiced = v;
    }
    return t != NULL && tf != NULL && f != NULL && fr != NULL && c != NULL && v != NULL ? 0
                                                                                     : -1;
}

/* Rates above 48 kHz: groups of factor samples averaged (rounded half away
   from zero) into *out (malloc'ed, n / factor samples). Returns 0 or -1. */
static int decimate(const int16_t *x, size_t n, uint32_t factor, int16_t **out, size_t *len)
{
    size_t i, k;
    int16_t *dec;
    *len = n / factor;
    dec = malloc((*len + 1u) * sizeof *dec);
    if (dec == NULL) {
        return -1;
    }
    for (i = 0; i < *len; i++) {
        long s = 0;
        for (k = 0; k < factor; k++) {
            s += x[i * factor + k];
        }
        dec[i] = (int16_t)(s >= 0 ? (s + (long)factor / 2) / (long)factor
                                  : -((-s + (long)factor / 2) / (long)factor));
    }
    *out = dec;
    return 0;
}

/* One estimate appended to tr (grown as needed). Returns 0 or -1. */
static int append_estimate(pitch_track_t *tr, size_t *cap, const ssda_pitch_estimate_t *est,
                           uint32_t arate)
{
    size_t i = tr->n;
    if (i == *cap) {
        *cap *= 2u;
        if (track_grow(tr, *cap) != 0) {
            return -1;
        }
    }
    /* est.center is frame * hop + (its offset) mod 2^32: keep the offset
       exact and add the frame start in double (long files) */
    tr->t[i] = ((double)est->frame * tr->info.hop +
                (double)(uint32_t)(est->center - est->frame * tr->info.hop)) /
               arate;
    tr->t_frame[i] = ((double)est->frame * tr->info.hop + tr->info.span / 2.0) / arate;
    tr->f0_raw[i] = est->f0_q16 / 65536.0;
    tr->f0[i] = est->voiced ? tr->f0_raw[i] : 0.0;
    tr->voiced[i] = est->voiced ? 1u : 0u;
    tr->confidence_q15[i] = est->confidence_q15;
    tr->diffs += est->diffs;
    tr->analysed += est->silent ? 0u : 1u;
    tr->n++;
    return 0;
}

/* Push sig[0..len-1] through an initialised job into tr. Returns 0 or -1. */
static int push_all(ssda_pitch_t *p, const int16_t *sig, size_t len, uint32_t arate,
                    progress_t *prog, pitch_track_t *tr, char *err, size_t errlen)
{
    ssda_pitch_estimate_t est;
    size_t pos = 0, used, cap = (len - tr->info.span) / tr->info.hop + 2u;
    int e;
    if (track_grow(tr, cap) != 0) {
        tool_set_err(err, errlen, "out of memory");
        return -1;
    }
    while (pos < len) {
        e = ssda_pitch_push(p, sig + pos, len - pos, &used, &est);
        if (e < 0) {
            tool_set_err(err, errlen, "pitch search failed: %s", ssda_strerror(e));
            return -1;
        }
        pos += used;
        if (e == 1 && append_estimate(tr, &cap, &est, arate) != 0) {
            tool_set_err(err, errlen, "out of memory");
            return -1;
        }
        if (e == 1 && prog != NULL) {
            progress_update(prog, pos);
        }
    }
    return 0;
}

int pitch_run(const int16_t *x, size_t n, uint32_t rate, const ssda_pitch_config_t *cfg,
              progress_t *prog, pitch_track_t *out, char *err, size_t errlen)
{
    pitch_track_t tr;
    ssda_pitch_config_t c = *cfg;
    ssda_pitch_t p;
    int16_t *dec = NULL;
    const int16_t *sig = x;
    void *buf = NULL;
    size_t bytes, len = n;
    uint32_t factor = 1, arate = rate;
    int e, rc = -1;

    memset(&tr, 0, sizeof tr);
    if (rate < SSDA_PITCH_RATE_MIN) {
        tool_set_err(err, errlen, "sample rate %u Hz is below the %u Hz the pitch search needs",
                     rate, SSDA_PITCH_RATE_MIN);
        return -1;
    }
    if (rate > SSDA_PITCH_RATE_MAX) { /* average groups of samples down to <= 48 kHz */
        factor = (rate + SSDA_PITCH_RATE_MAX - 1u) / SSDA_PITCH_RATE_MAX;
        arate = (uint32_t)((rate + factor / 2u) / factor);
        if (decimate(x, n, factor, &dec, &len) != 0) {
            tool_set_err(err, errlen, "out of memory");
            return -1;
        }
        sig = dec;
    }
    c.sample_rate_hz = arate;
    e = ssda_pitch_buffer_size(&c, &bytes);
    if (e != SSDA_OK) {
        tool_set_err(err, errlen, "pitch settings refused at %u Hz: %s (f0 range must satisfy "
                     "10 <= fmin < fmax <= rate/4)", arate, ssda_strerror(e));
        goto done;
    }
    buf = malloc(bytes);
    if (buf == NULL || ssda_pitch_init(&p, &c, buf, bytes) != SSDA_OK ||
        ssda_pitch_get_info(&p, &tr.info) != SSDA_OK) {
        tool_set_err(err, errlen, buf == NULL ? "out of memory" : "pitch settings refused");
        goto done;
    }
    if (len < tr.info.span) {
        tool_set_err(err, errlen, "signal too short: %.3f s, one analysis needs %.3f s (lower "
                     "--fmin to shorten it)", (double)len / arate, (double)tr.info.span / arate);
        goto done;
    }
    if (push_all(&p, sig, len, arate, prog, &tr, err, errlen) != 0) {
        goto done;
    }
    /* the full search on the frames analysed (silent ones are never searched) */
    tr.full_diffs = (uint64_t)tr.analysed * (tr.info.lag_max - tr.info.lag_min + 3u) *
                    tr.info.frame_len;
    tr.decimation = factor;
    tr.input_rate = rate;
    *out = tr;
    memset(&tr, 0, sizeof tr);
    rc = 0;
done:
    pitch_track_free(&tr);
    free(buf);
    free(dec);
    return rc;
}

/* ---- scoring ---- */

void pitch_score(const pitch_track_t *tr, const double *rt, const double *rf, size_t rn,
                 pitch_score_t *out)
{
    size_t i, j = 0, vde = 0, gross = 0, fine = 0;
    double cents = 0.0;
    memset(out, 0, sizeof *out);
    for (i = 0; i < tr->n; i++) {
        double t = tr->t[i], ref;
        int ref_voiced, est_voiced = tr->voiced[i] != 0;
        if (rn < 2 || t < rt[0] || t > rt[rn - 1]) {
            continue;
        }
        while (j + 1 < rn && rt[j + 1] < t) {
            j++;
        }
        if (j + 1 >= rn) {
            continue;
        }
        ref_voiced = rf[j] > 0.0 && rf[j + 1] > 0.0;
        ref = ref_voiced ? rf[j] + (rf[j + 1] - rf[j]) * (rt[j + 1] > rt[j]
                                                              ? (t - rt[j]) / (rt[j + 1] - rt[j])
                                                              : 0.0)
                         : 0.0;
        out->frames++;
        if (ref_voiced != est_voiced) {
            vde++;
        }
        if (ref_voiced && est_voiced) {
            double e = fabs(tr->f0[i] - ref) / ref;
            out->both_voiced++;
            if (e > 0.2) {
                gross++;
            } else {
                fine++;
                cents += fabs(1200.0 * log2(tr->f0[i] / ref));
            }
        }
    }
    out->vde = out->frames ? (double)vde / (double)out->frames : 0.0;
    out->gpe = out->both_voiced ? (double)gross / (double)out->both_voiced : 0.0;
    out->fpe_cents = fine ? cents / (double)fine : 0.0;
}
