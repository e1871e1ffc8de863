/*
 * pitch_internal.h - the pieces of the pitch extractor, shared between
 * lib/pitch*.c and the tests (not installed).
 */
#ifndef SSDA_PITCH_INTERNAL_H
#define SSDA_PITCH_INTERNAL_H

#include "ssda/pitch.h"
#include "kernel/kernels.h"
#include "compiler.h"

/* Features compiled in (include/ssda/config.h): a flag left out of the
   build reads as clear, so the code behind it is dropped as dead. */
#ifdef SSDA_CFG_NO_PITCH_FULL
#define SSDA_PITCH_HAS_FULL(flags) ((void)(flags), false)
#else
#define SSDA_PITCH_HAS_FULL(flags) (((flags) & SSDA_PITCH_FULL) != 0u)
#endif
#ifdef SSDA_CFG_NO_PITCH_TRACK
#define SSDA_PITCH_HAS_TRACK(flags) ((void)(flags), false)
#else
#define SSDA_PITCH_HAS_TRACK(flags) (((flags) & SSDA_PITCH_TRACK) != 0u)
#endif
#ifdef SSDA_CFG_NO_PITCH_PARABOLIC
#define SSDA_PITCH_HAS_PARABOLIC(flags) ((void)(flags), false)
#else
#define SSDA_PITCH_HAS_PARABOLIC(flags) (((flags) & SSDA_PITCH_PARABOLIC) != 0u)
#endif
/* Steps 4 and 6 of the definition: on unless the reduced definition is
   asked for (a build without them requires the flags, pitch_config.c). */
#ifdef SSDA_CFG_NO_PITCH_OCTAVE
#define SSDA_PITCH_HAS_OCTAVE(flags) ((void)(flags), false)
#else
#define SSDA_PITCH_HAS_OCTAVE(flags) (((flags) & SSDA_PITCH_NO_OCTAVE) == 0u)
#endif
#ifdef SSDA_CFG_NO_PITCH_BELOW_RANGE
#define SSDA_PITCH_HAS_BELOW_RANGE(flags) ((void)(flags), false)
#else
#define SSDA_PITCH_HAS_BELOW_RANGE(flags) (((flags) & SSDA_PITCH_NO_BELOW_RANGE) == 0u)
#endif
/* Either check in use (both read the dip's interpolated floor F). A build
   without one requires its flag (pitch_config.c), so this is false exactly
   when both checks are off. */
#if defined(SSDA_CFG_NO_PITCH_OCTAVE) && defined(SSDA_CFG_NO_PITCH_BELOW_RANGE)
#define SSDA_PITCH_NEEDS_FLOOR(flags) ((void)(flags), false)
#else
#define SSDA_PITCH_NEEDS_FLOOR(flags) \
    (((flags) & (SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE)) != \
     (SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE))
#endif
/* Input low-pass in use (its coefficient is 0 when off). */
#ifdef SSDA_CFG_NO_PITCH_FILTER
#define SSDA_PITCH_FILTERED(info) ((void)(info), false)
#else
#define SSDA_PITCH_FILTERED(info) ((info)->lowpass_q15 != 0u)
#endif

#ifdef SSDA_CFG_PITCH_FIXED
/* The fixed configuration resolved (pitch.h, "Fixed configuration"): the
   same rules as ssda__pitch_resolve, as constant expressions (checked in
   pitch_config.c). SSDA_PITCH_FIXED_*: the settings resolved. */
#define SSDA__PF_OR(v, dflt) ((uint32_t)(v) != 0u ? (uint32_t)(v) : (uint32_t)(dflt))
#define SSDA_PITCH_FIXED_RATE ((uint32_t)(SSDA_CFG_PITCH_FIXED_RATE_HZ))
#define SSDA_PITCH_FIXED_F0_MIN \
    SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_F0_MIN_HZ, SSDA_PITCH_DEFAULT_F0_MIN)
#define SSDA_PITCH_FIXED_F0_MAX \
    SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_F0_MAX_HZ, SSDA_PITCH_DEFAULT_F0_MAX)
#define SSDA_PITCH_FIXED_LAG_MIN (SSDA_PITCH_FIXED_RATE / SSDA_PITCH_FIXED_F0_MAX)
#define SSDA_PITCH_FIXED_LAG_MAX \
    ((SSDA_PITCH_FIXED_RATE + SSDA_PITCH_FIXED_F0_MIN - 1u) / SSDA_PITCH_FIXED_F0_MIN)
#define SSDA_PITCH_FIXED_K_DEFAULT \
    (SSDA_PITCH_FIXED_LAG_MAX > SSDA_PITCH_FRAME_MIN ? SSDA_PITCH_FIXED_LAG_MAX : SSDA_PITCH_FRAME_MIN)
#define SSDA_PITCH_FIXED_K \
    SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_FRAME_LEN, SSDA_PITCH_FIXED_K_DEFAULT)
#define SSDA_PITCH_FIXED_CHUNK_DEFAULT \
    (SSDA_PITCH_DEFAULT_CHUNK < SSDA_PITCH_FIXED_K ? SSDA_PITCH_DEFAULT_CHUNK : SSDA_PITCH_FIXED_K)
#define SSDA_PITCH_FIXED_CHUNK \
    SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_CHUNK, SSDA_PITCH_FIXED_CHUNK_DEFAULT)
#define SSDA_PITCH_FIXED_HOP SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_HOP, SSDA_PITCH_FIXED_K / 4u)
#define SSDA_PITCH_FIXED_SPAN (SSDA_PITCH_FIXED_K + SSDA_PITCH_FIXED_LAG_MAX + 1u)
#define SSDA_PITCH_FIXED_THRESHOLD \
    SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_THRESHOLD_Q15, SSDA_PITCH_DEFAULT_THRESHOLD_Q15)
#define SSDA_PITCH_FIXED_VOICING SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_VOICING_Q15, SSDA_PITCH_FIXED_THRESHOLD)
#define SSDA_PITCH_FIXED_SILENCE \
    SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_SILENCE_MAD, SSDA_PITCH_DEFAULT_SILENCE_MAD)
#define SSDA_PITCH_FIXED_FLAGS ((uint32_t)(SSDA_CFG_PITCH_FIXED_FLAGS))
/* the config's lowpass_hz resolved, and the filter's corner (0: none) */
#define SSDA_PITCH_FIXED_LOWPASS_CFG \
    SSDA__PF_OR(SSDA_CFG_PITCH_FIXED_LOWPASS_HZ, SSDA_PITCH_FIXED_F0_MAX)
#define SSDA_PITCH_FIXED_LOWPASS \
    ((SSDA_PITCH_FIXED_FLAGS & SSDA_PITCH_NO_FILTER) != 0u ? 0u : SSDA_PITCH_FIXED_LOWPASS_CFG)
/* ssda__pitch_lowpass_coef_q15 of it: round(2^15 W / (R + W)), W = 411775
   fc, R = rate << 16 (< 2^49, folded by the compiler; 0 when no filter) */
#define SSDA__PF_W ((uint64_t)411775u * SSDA_PITCH_FIXED_LOWPASS)
#define SSDA__PF_DEN (((uint64_t)SSDA_PITCH_FIXED_RATE << 16) + SSDA__PF_W)
#define SSDA_PITCH_FIXED_LOWPASS_Q15 \
    ((uint16_t)(((SSDA__PF_W << 15) + SSDA__PF_DEN / 2u) / SSDA__PF_DEN))

/* The resolved parameters, read through SSDA_PITCH_INFO_OF(info) wherever
   the analysis or the intake reads them: constants the compiler folds. */
static const ssda_pitch_info_t ssda__pitch_fixed_info = {
    SSDA_PITCH_FIXED_RATE, SSDA_PITCH_FIXED_LAG_MIN, SSDA_PITCH_FIXED_LAG_MAX,
    SSDA_PITCH_FIXED_K, SSDA_PITCH_FIXED_HOP, SSDA_PITCH_FIXED_SPAN, SSDA_PITCH_FIXED_CHUNK,
    (SSDA_PITCH_FIXED_LAG_MAX - SSDA_PITCH_FIXED_LAG_MIN + 1u) * SSDA_PITCH_FIXED_K,
    (uint16_t)SSDA_PITCH_FIXED_THRESHOLD, (uint16_t)SSDA_PITCH_FIXED_VOICING,
    (uint16_t)SSDA_PITCH_FIXED_SILENCE, (uint16_t)SSDA_PITCH_FIXED_LOWPASS,
    SSDA_PITCH_FIXED_LOWPASS_Q15, (uint8_t)SSDA_PITCH_FIXED_FLAGS};
#define SSDA_PITCH_INFO_OF(info) ((void)(info), &ssda__pitch_fixed_info)
#else
#define SSDA_PITCH_INFO_OF(info) (info)
#endif

#ifdef SSDA_CFG_PITCH_FIXED
/* A field v of cfg that resolves to the fixed value: equal to it, or 0
   where the fixed value is the default (both constants: folded). */
#define SSDA__PF_FIELD_IS(v, fixed, dflt) \
    ((uint32_t)(v) == (fixed) || ((v) == 0u && (fixed) == (dflt)))

/* With a fixed configuration: SSDA_OK when cfg is it (every field resolves
   to the fixed one), SSDA_ERR_UNSUPPORTED for any other, SSDA_ERR_NULL.
   Nothing is written: the parameters are ssda__pitch_fixed_info, read
   through SSDA_PITCH_INFO_OF. Inline: one caller (M0+ flash). */
static inline int ssda__pitch_resolve(const ssda_pitch_config_t *cfg, ssda_pitch_info_t *info)
{
    (void)info;
    if (cfg == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!(cfg->sample_rate_hz == SSDA_PITCH_FIXED_RATE &&
          SSDA__PF_FIELD_IS(cfg->f0_min_hz, SSDA_PITCH_FIXED_F0_MIN, SSDA_PITCH_DEFAULT_F0_MIN) &&
          SSDA__PF_FIELD_IS(cfg->f0_max_hz, SSDA_PITCH_FIXED_F0_MAX, SSDA_PITCH_DEFAULT_F0_MAX) &&
          SSDA__PF_FIELD_IS(cfg->frame_len, SSDA_PITCH_FIXED_K, SSDA_PITCH_FIXED_K_DEFAULT) &&
          SSDA__PF_FIELD_IS(cfg->hop, SSDA_PITCH_FIXED_HOP, SSDA_PITCH_FIXED_K / 4u) &&
          SSDA__PF_FIELD_IS(cfg->threshold_q15, SSDA_PITCH_FIXED_THRESHOLD,
                            SSDA_PITCH_DEFAULT_THRESHOLD_Q15) &&
          SSDA__PF_FIELD_IS(cfg->voicing_q15, SSDA_PITCH_FIXED_VOICING,
                            SSDA_PITCH_FIXED_THRESHOLD) &&
          SSDA__PF_FIELD_IS(cfg->silence_mad, SSDA_PITCH_FIXED_SILENCE,
                            SSDA_PITCH_DEFAULT_SILENCE_MAD) &&
          SSDA__PF_FIELD_IS(cfg->chunk, SSDA_PITCH_FIXED_CHUNK, SSDA_PITCH_FIXED_CHUNK_DEFAULT) &&
          SSDA__PF_FIELD_IS(cfg->lowpass_hz, SSDA_PITCH_FIXED_LOWPASS_CFG, SSDA_PITCH_FIXED_F0_MAX) &&
          cfg->flags == SSDA_PITCH_FIXED_FLAGS)) {
        return SSDA_ERR_UNSUPPORTED;
    }
    return SSDA_OK;
}
#else
/* Check cfg and fill *info with every default resolved. Writes *info on
   success only; errors as ssda_pitch_init (never SSDA_ERR_BUFFER). */
SSDA_INTERNAL int ssda__pitch_resolve(const ssda_pitch_config_t *cfg, ssda_pitch_info_t *info);
#endif

/* Re-arming level for a threshold (Q15): threshold * 3 / 2, at most 32767. */
#define ssda__pitch_rearm_q15(thr) \
    ((uint32_t)(thr) + (uint32_t)(thr) / 2u < 32767u ? (uint32_t)(thr) + (uint32_t)(thr) / 2u : 32767u)

/* Low-pass coefficient a = round(32768 * w / (1 + w)), w = 2 pi fc / rate,
   with 2 pi taken as 411775 / 65536; fc <= rate / 4 gives 1..20020. */
SSDA_INTERNAL uint16_t ssda__pitch_lowpass_coef_q15(uint32_t fc_hz, uint32_t rate_hz);

/* One sample through the two low-pass poles (states in Q15, see pitch.h). */
SSDA_INTERNAL int16_t ssda__pitch_lowpass(int32_t *y1_q15, int32_t *y2_q15, uint32_t a_q15, int16_t in);

/* Start both low-pass states at one sample value. */
SSDA_INTERNAL void ssda__pitch_lowpass_prime(int32_t *y1_q15, int32_t *y2_q15, int16_t in);

/* Frame mean as defined in pitch.h:
   floor((sum_{i<n} (x[i] + 32768) + floor(n/2)) / n) - 32768, n = 1..8192.
   The offset sum is <= 8192 * 65535 < 2^30. */
SSDA_INTERNAL int32_t ssda__pitch_mean(const int16_t *x, uint32_t n);

/* sum_{i<n} |x[i] - mean|, n <= 8192, mean in -32768..32767:
   <= 8192 * 65535 < 2^30. */
SSDA_INTERNAL uint32_t ssda__pitch_level(const int16_t *x, uint32_t n, int32_t mean);

/*
 * AMDF term d(lag) = sum_{i<K} |x[i] - x[i + lag]| with SSDA early exit:
 * summed chunk samples at a time (through the kernel set's
 * ssda__absdiff_row_i16), stopping after the first chunk that takes the
 * partial sum above bound.
 *   Returns the sum so far; *complete is true when all K terms were summed
 *   (the result is then exact, whether or not it exceeds bound), false when
 *   cut (the result is then > bound and a lower bound of d).
 *   *diffs is increased by the number of absolute differences computed.
 * Worst case: the partial sum before the last chunk is <= bound, and any
 * sum is <= K * 65535 < 2^29 (K <= 8192).
 * Inline: a frame less under the lag scan (worst-case stack, docs/target.md).
 */
static inline uint32_t ssda__pitch_amdf_lag(const int16_t *x, uint32_t frame_len, uint32_t lag,
                                           uint32_t chunk, uint32_t bound, bool *complete,
                                           uint32_t *diffs)
{
    /* sum <= bound + chunk * 65535 while running, and <= K * 65535 < 2^29
       in any case: no overflow in uint32_t even without the bound. */
    uint32_t sum = 0u;
    uint32_t i = 0u;
    while (i < frame_len) {
        uint32_t n = frame_len - i < chunk ? frame_len - i : chunk;
        sum += ssda__absdiff_row_i16(x + i, x + i + lag, n);
        i += n;
        if (sum > bound) {
            break;
        }
    }
    *diffs += i;
    *complete = (i == frame_len);
    return sum;
}

/*
 * Sub-sample offset of the dip at t*, from the normalised values
 * a = nq(t* - 1), b = nq(t*), c = nq(t* + 1) (Q20, 0..2^20):
 * round_half_away(65536 * (a - c) / den) with den = 2 (max(a, c) - b) (V
 * fit) or 2 (a - 2b + c) (parabolic); 0 if den <= 0; clamped to
 * [-32768, 32768]. Q16.16 samples.
 */
SSDA_INTERNAL int32_t ssda__pitch_interp_q16(uint32_t a_q20, uint32_t b_q20, uint32_t c_q20, bool parabolic);

/* floor(2^20 * d / s), s > 0, d <= s: Q20 in 0..2^20. */
SSDA_INTERNAL uint32_t ssda__pitch_norm_q20(uint32_t d, uint32_t s);

/* f0 in Hz Q16.16 from rate (Hz) and period (samples, Q16.16, > 0):
   floor((rate << 32) / period_q16 + 1/2); saturates at UINT32_MAX. */
SSDA_INTERNAL uint32_t ssda__pitch_f0_q16(uint32_t rate_hz, uint32_t period_q16);

/*
 * Analyse one frame x[0 .. info->span - 1] (the rule in pitch.h).
 *   predict_lag: with SSDA_PITCH_TRACK, a lag to sum first (0 or out of
 *                range = none). Changes work only.
 *   est:         written in full; est->frame and est->center are the
 *                caller's to set after (0 or untouched here).
 */
SSDA_INTERNAL void ssda__pitch_analyze(const ssda_pitch_info_t *info, const int16_t *x,
                        uint32_t predict_lag, ssda_pitch_estimate_t *est);

/* ssda__pitch_analyze with its working state in *w (the stream keeps it in
   ssda_pitch_t; ssda__pitch_analyze puts it on the stack). */
SSDA_INTERNAL void ssda__pitch_analyze_in(ssda_pitch_work_t *w, const ssda_pitch_info_t *info,
                           const int16_t *x, uint32_t predict_lag, ssda_pitch_estimate_t *est);

#endif /* SSDA_PITCH_INTERNAL_H */
