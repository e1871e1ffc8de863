/* pitch_runners.h - run one pitch estimator over a whole signal and
   collect its frames (time, f0, voicing, work): ssda's streaming API, and
   aubio's pitch object (yin, yinfast) when aubio is available. */
#ifndef SSDA_EVAL_PITCH_RUNNERS_H
#define SSDA_EVAL_PITCH_RUNNERS_H
#include <stddef.h>
#include <stdint.h>

#include "pitch_metrics.h"
#include "ssda/pitch.h"

typedef struct {
    frame_t *fr;
    size_t n;
    double cpu_s;  /* processor time of the estimator alone */
} run_t;

/* Frame time of an ssda estimate: est.center, the centre of the samples
   its chosen lag compares. */
int run_ssda(const int16_t *x, size_t n, const ssda_pitch_config_t *cfg, run_t *out,
             char *err, size_t errlen);

/* aubio's pitch object, method "yin" or "yinfast", buffer bufsize, the
   given hop, default tolerance (0.15) and silence (-50 dB), as a user gets
   it. Voiced = f0 > 0 and confidence >= 1 - tolerance (YIN found a dip
   under its threshold). Frame time: the same convention as ssda's, buffer
   start + (W + lag) / 2 with W = bufsize / 2 and lag = rate / f0 (W when
   there is no f0); frames whose buffer is not yet full are dropped. Returns -1 when aubio is not
   compiled in. */
int run_aubio(const char *method, const int16_t *x, size_t n, uint32_t rate,
              uint32_t bufsize, uint32_t hop, run_t *out);
int have_aubio(void);

void run_free(run_t *r);

#endif
