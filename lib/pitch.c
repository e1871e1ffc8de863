/* pitch.c - the pitch stream: caller buffer, sample intake in any chunk
   sizes, one analysis per hop. */
#include "pitch_internal.h"

#include <string.h>

#include "slide.h"
#include "state.h"

/* The resolved parameters: constants with a fixed configuration
   (pitch_internal.h), folded by the compiler. */
#define INFO(p) SSDA_PITCH_INFO_OF(&(p)->info)

#ifdef SSDA_CFG_NO_PITCH_PUSH
/* No push intake, so no buffer (include/ssda/config.h). */
int ssda_pitch_buffer_size(const ssda_pitch_config_t *cfg, size_t *bytes) /* NOLINT(readability-non-const-parameter) */
{
    (void)cfg;
    (void)bytes;
    return SSDA_ERR_UNSUPPORTED;
}
#else
int ssda_pitch_buffer_size(const ssda_pitch_config_t *cfg, size_t *bytes)
{
    ssda_pitch_info_t info;
    int err;
    if (cfg == NULL || bytes == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda__pitch_resolve(cfg, &info);
    if (err != SSDA_OK) {
        return err;
    }
    *bytes = (size_t)SSDA_PITCH_INFO_OF(&info)->span * sizeof(int16_t);
    return SSDA_OK;
}
#endif

int ssda_pitch_init(ssda_pitch_t *p, const ssda_pitch_config_t *cfg,
                    void *buffer, size_t buffer_size)
{
    int err;
#ifdef SSDA_CFG_NO_PITCH_PUSH
    /* no push intake: the buffer is not used (may be NULL), and nothing is
       checked after the config, which is resolved straight into p->info
       (written on success only; not at all with a fixed configuration,
       whose parameters are constants) */
    (void)buffer_size;
    if (p == NULL || cfg == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda__pitch_resolve(cfg, &p->info);
    if (err != SSDA_OK) {
        return err;
    }
#else
    ssda_pitch_info_t info;
    if (p == NULL || cfg == NULL || buffer == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda__pitch_resolve(cfg, &info);
    if (err != SSDA_OK) {
        return err;
    }
    if (buffer_size / sizeof(int16_t) < SSDA_PITCH_INFO_OF(&info)->span ||
        ((uintptr_t)buffer % sizeof(int16_t)) != 0u) {
        return SSDA_ERR_BUFFER;
    }
#ifndef SSDA_CFG_PITCH_FIXED /* fixed: the parameters are constants, none kept */
    (void)memcpy(&p->info, &info, sizeof info);
#endif
#endif
    p->buf = (int16_t *)buffer;
    p->magic = SSDA__MAGIC_PITCH;
    return ssda_pitch_reset(p);
}

/* SSDA_OK for a state that ssda_pitch_init filled, else SSDA_ERR_NULL
   (p NULL) or SSDA_ERR_STATE. One copy of the test (M0+ flash). */
static SSDA_SIZE_NOINLINE int state_error(const ssda_pitch_t *p)
{
    if (p == NULL) {
        return SSDA_ERR_NULL;
    }
    return ssda__valid(p->magic, SSDA__MAGIC_PITCH) ? SSDA_OK : SSDA_ERR_STATE;
}

int ssda_pitch_reset(ssda_pitch_t *p)
{
    const int err = state_error(p);
    if (err != SSDA_OK) {
        return err;
    }
    p->fill = 0u;
    p->skip = 0u;
    p->frame = 0u;
    p->predict_lag = 0u;
    p->lp1_q15 = 0;
    p->lp2_q15 = 0;
    p->lp_primed = false;
    return SSDA_OK;
}

int ssda_pitch_get_info(const ssda_pitch_t *p, ssda_pitch_info_t *info)
{
    const int err = info == NULL ? SSDA_ERR_NULL : state_error(p);
    if (err != SSDA_OK) {
        return err;
    }
    /* memcpy, linked anyway, not an inline copy of 44 bytes: M0+ flash
       (from the constants with a fixed configuration) */
    (void)memcpy(info, INFO(p), sizeof *info);
    return SSDA_OK;
}

/* One frame x[0 .. span - 1] analysed as estimate number p->frame: its
   number and centre, and the prediction carried to the next frame.
   Inlined: no frame of its own on push's chain (stack). */
static SSDA_ALWAYS_INLINE void analyze_frame(ssda_pitch_t *p, const int16_t *x,
                                             ssda_pitch_estimate_t *est)
{
    ssda__pitch_analyze_in(&p->work, &p->info, x, p->predict_lag, est);
    est->frame = p->frame;
    /* wraps modulo 2^32 by design (unsigned) */
    est->center = p->frame * INFO(p)->hop +
                  (est->silent ? INFO(p)->span / 2u : (INFO(p)->frame_len + est->lag) / 2u);
    p->frame++;
    p->predict_lag = est->voiced ? est->lag : 0u;
}

int ssda_pitch_frame(ssda_pitch_t *p, const int16_t *x, ssda_pitch_estimate_t *est)
{
    if (p == NULL || x == NULL || est == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(p->magic, SSDA__MAGIC_PITCH)) {
        return SSDA_ERR_STATE;
    }
    if (SSDA_PITCH_FILTERED(INFO(p))) {
        return SSDA_ERR_ARG; /* the low-pass runs over the stream, not per frame */
    }
    analyze_frame(p, x, est);
    return SSDA_OK;
}

#ifdef SSDA_CFG_NO_PITCH_PUSH
/* Whole frames only (ssda_pitch_frame): nothing consumed or written. */
int ssda_pitch_push(ssda_pitch_t *p, const int16_t *samples, size_t count, /* NOLINT(readability-non-const-parameter) */
                    size_t *consumed, ssda_pitch_estimate_t *est) /* NOLINT(readability-non-const-parameter) */
{
    (void)p;
    (void)samples;
    (void)count;
    (void)consumed;
    (void)est;
    return SSDA_ERR_UNSUPPORTED;
}
#else
#ifndef SSDA_CFG_NO_PITCH_FILTER
/* Pass n >= 1 samples through the low-pass into out (NULL: filter only).
   Both calls pass n >= 1: a take while used < count, bounded by skip > 0 or
   by span - fill > 0. */
static void filter_samples(ssda_pitch_t *p, const int16_t *in, int16_t *out, size_t n)
{
    size_t i;
    if (!p->lp_primed) {
        ssda__pitch_lowpass_prime(&p->lp1_q15, &p->lp2_q15, in[0]);
        p->lp_primed = true;
    }
    for (i = 0u; i < n; i++) {
        int16_t y = ssda__pitch_lowpass(&p->lp1_q15, &p->lp2_q15, INFO(p)->lowpass_q15, in[i]);
        if (out != NULL) {
            out[i] = y;
        }
    }
}
#else
#define filter_samples(p, in, out, n) ((void)0)
#endif

int ssda_pitch_push(ssda_pitch_t *p, const int16_t *samples, size_t count,
                    size_t *consumed, ssda_pitch_estimate_t *est)
{
    const uint32_t span = p != NULL ? INFO(p)->span : 0u;
    size_t used = 0u;

    if (p == NULL || consumed == NULL || est == NULL || (samples == NULL && count > 0u)) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(p->magic, SSDA__MAGIC_PITCH)) {
        return SSDA_ERR_STATE;
    }
    while (used < count) {
        size_t take;
        if (p->skip > 0u) {
            /* hop > span: samples between two frames are not analysed, but
               still pass through the filter so its state stays continuous */
            take = count - used < p->skip ? count - used : p->skip;
            if (SSDA_PITCH_FILTERED(INFO(p))) {
                filter_samples(p, samples + used, NULL, take);
            }
            p->skip -= (uint32_t)take;
            used += take;
            continue;
        }
        take = count - used < span - p->fill ? count - used : span - p->fill;
        if (SSDA_PITCH_FILTERED(INFO(p))) {
            filter_samples(p, samples + used, p->buf + p->fill, take);
        } else {
            (void)memcpy(p->buf + p->fill, samples + used, take * sizeof(int16_t));
        }
        p->fill += (uint32_t)take;
        used += take;
        if (p->fill == span) {
            analyze_frame(p, p->buf, est);
            if (INFO(p)->hop < span) {
                /* the kept samples slide down by hop */
                p->fill = span - INFO(p)->hop;
                ssda__slide(p->buf, (size_t)INFO(p)->hop * sizeof(int16_t),
                            (size_t)span * sizeof(int16_t));
            } else {
                p->fill = 0u;
                p->skip = INFO(p)->hop - span;
            }
            *consumed = used;
            return 1;
        }
    }
    *consumed = used;
    return 0;
}
#endif /* SSDA_CFG_NO_PITCH_PUSH */
