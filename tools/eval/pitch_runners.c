/* pitch_runners.c - estimators over whole signals (see header). */
#include "pitch_runners.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#ifdef HAVE_AUBIO
#include <aubio/aubio.h>
#endif

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int run_ssda(const int16_t *x, size_t n, const ssda_pitch_config_t *cfg, run_t *out,
             char *err, size_t errlen)
{
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    size_t bytes, used = 0, cap, count = 0;
    int16_t *buf;
    frame_t *fr;
    double t0;
    int rc = ssda_pitch_buffer_size(cfg, &bytes);
    if (rc != SSDA_OK) {
        snprintf(err, errlen, "ssda pitch config: %s", ssda_strerror(rc));
        return -1;
    }
    buf = malloc(bytes);
    if (buf == NULL || (rc = ssda_pitch_init(&p, cfg, buf, bytes)) != SSDA_OK) {
        snprintf(err, errlen, "ssda_pitch_init: %s", buf ? ssda_strerror(rc) : "out of memory");
        free(buf);
        return -1;
    }
    ssda_pitch_get_info(&p, &info);
    cap = n / info.hop + 2;
    fr = calloc(cap, sizeof *fr);
    if (fr == NULL) {
        free(buf);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    t0 = cpu_now();
    while (used < n) {
        ssda_pitch_estimate_t e;
        size_t took;
        int r = ssda_pitch_push(&p, x + used, n - used, &took, &e);
        used += took;
        if (r == 1 && count < cap) {
            fr[count].t_s = (double)e.center / info.sample_rate_hz;
            fr[count].f0_hz = e.f0_q16 / 65536.0;
            fr[count].voiced = e.voiced;
            fr[count].diffs = e.diffs;
            fr[count].conf = e.confidence_q15 / 32768.0;
            count++;
        } else if (r < 0) {
            snprintf(err, errlen, "ssda_pitch_push: %s", ssda_strerror(r));
            free(fr);
            free(buf);
            return -1;
        }
    }
    out->cpu_s = cpu_now() - t0;
    out->fr = fr;
    out->n = count;
    free(buf);
    return 0;
}

int have_aubio(void)
{
#ifdef HAVE_AUBIO
    return 1;
#else
    return 0;
#endif
}

int run_aubio(const char *method, const int16_t *x, size_t n, uint32_t rate,
              uint32_t bufsize, uint32_t hop, run_t *out)
{
#ifdef HAVE_AUBIO
    aubio_pitch_t *o = new_aubio_pitch(method, bufsize, hop, rate);
    fvec_t *in = new_fvec(hop), *res = new_fvec(1);
    size_t blocks = n / hop, i, count = 0;
    frame_t *fr = calloc(blocks + 1, sizeof *fr);
    double t0, tol;
    if (o == NULL || in == NULL || res == NULL || fr == NULL) {
        free(fr);
        return -1;
    }
    aubio_pitch_set_unit(o, "Hz");
    tol = aubio_pitch_get_tolerance(o);
    t0 = cpu_now();
    for (i = 0; i < blocks; i++) {
        uint32_t j;
        double f0, conf;
        for (j = 0; j < hop; j++) {
            in->data[j] = (smpl_t)(x[i * hop + j] / 32768.0);
        }
        aubio_pitch_do(o, in, res);
        f0 = res->data[0];
        conf = aubio_pitch_get_confidence(o);
        if ((i + 1) * hop < bufsize) {
            continue; /* buffer still holds the initial zeros */
        }
        /* the same convention as ssda's: the centre of the samples the
           chosen lag compares, buffer start + (W + lag) / 2, W = bufsize / 2 */
        fr[count].t_s = ((double)(i + 1) * hop - bufsize +
                         (bufsize / 2.0 + (f0 > 0.0 ? rate / f0 : bufsize / 2.0)) / 2.0) / rate;
        fr[count].f0_hz = f0 > 0.0 ? f0 : 0.0;
        fr[count].voiced = f0 > 0.0 && conf >= 1.0 - tol;
        fr[count].diffs = 0;
        fr[count].conf = conf;
        count++;
    }
    out->cpu_s = cpu_now() - t0;
    out->fr = fr;
    out->n = count;
    del_aubio_pitch(o);
    del_fvec(in);
    del_fvec(res);
    return 0;
#else
    (void)method; (void)x; (void)n; (void)rate; (void)bufsize; (void)hop; (void)out;
    return -1;
#endif
}

void run_free(run_t *r)
{
    free(r->fr);
    r->fr = NULL;
    r->n = 0;
}
