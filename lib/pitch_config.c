/* pitch_config.c - checking a pitch configuration and resolving its
   defaults (shared by ssda_pitch_init and ssda_pitch_buffer_size). */
#include "pitch_internal.h"
#include "fixmath.h"

#define KNOWN_FLAGS                                                              \
    (SSDA_PITCH_TRACK | SSDA_PITCH_FULL | SSDA_PITCH_NO_FILTER | SSDA_PITCH_PARABOLIC | \
     SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE)

#ifndef SSDA_CFG_PITCH_FIXED
/* Whether every flag asks for a feature this build has (include/ssda/config.h). */
static bool flags_built(uint32_t flags)
{
    bool ok = true;
#ifdef SSDA_CFG_NO_PITCH_FILTER
    ok = ok && (flags & SSDA_PITCH_NO_FILTER) != 0u;
#endif
#ifdef SSDA_CFG_NO_PITCH_TRACK
    ok = ok && (flags & SSDA_PITCH_TRACK) == 0u;
#endif
#ifdef SSDA_CFG_NO_PITCH_FULL
    ok = ok && (flags & SSDA_PITCH_FULL) == 0u;
#endif
#ifdef SSDA_CFG_NO_PITCH_PARABOLIC
    ok = ok && (flags & SSDA_PITCH_PARABOLIC) == 0u;
#endif
#ifdef SSDA_CFG_NO_PITCH_OCTAVE
    ok = ok && (flags & SSDA_PITCH_NO_OCTAVE) != 0u;
#endif
#ifdef SSDA_CFG_NO_PITCH_BELOW_RANGE
    ok = ok && (flags & SSDA_PITCH_NO_BELOW_RANGE) != 0u;
#endif
    (void)flags;
    return ok;
}
#endif

#ifdef SSDA_CFG_PITCH_FIXED
/* The fixed configuration (pitch.h), checked here as ssda__pitch_resolve
   checks a configuration at run time: a build whose setting it would
   refuse does not compile (an array of negative size). The check of a
   configuration against it is inline, in pitch_internal.h. */
#define FIXED_OK(cond) ((cond) ? 1 : -1)
typedef char ssda__pitch_fixed_rate[FIXED_OK(SSDA_PITCH_FIXED_RATE >= SSDA_PITCH_RATE_MIN &&
                                             SSDA_PITCH_FIXED_RATE <= SSDA_PITCH_RATE_MAX)];
typedef char ssda__pitch_fixed_f0_range[FIXED_OK(
    SSDA_PITCH_FIXED_F0_MIN >= SSDA_PITCH_F0_LOWEST &&
    SSDA_PITCH_FIXED_F0_MAX <= SSDA_PITCH_FIXED_RATE / 4u &&
    SSDA_PITCH_FIXED_F0_MIN < SSDA_PITCH_FIXED_F0_MAX)];
typedef char ssda__pitch_fixed_thresholds[FIXED_OK(SSDA_PITCH_FIXED_THRESHOLD <= 32767u &&
                                                   SSDA_PITCH_FIXED_VOICING <= 32767u)];
typedef char ssda__pitch_fixed_lowpass[FIXED_OK(
    (uint32_t)(SSDA_CFG_PITCH_FIXED_LOWPASS_HZ) <= SSDA_PITCH_FIXED_RATE / 4u)];
typedef char ssda__pitch_fixed_flags_known[FIXED_OK((SSDA_PITCH_FIXED_FLAGS & ~KNOWN_FLAGS) == 0u)];
typedef char ssda__pitch_fixed_frame_len[FIXED_OK(SSDA_PITCH_FIXED_K >= SSDA_PITCH_FRAME_MIN &&
                                                  SSDA_PITCH_FIXED_K <= SSDA_PITCH_FRAME_MAX)];
typedef char ssda__pitch_fixed_chunk[FIXED_OK(
    (uint32_t)(SSDA_CFG_PITCH_FIXED_CHUNK) <= SSDA_PITCH_FIXED_K)];
/* each setting fits its field of ssda_pitch_config_t, as written: the
   checks above see it cut to 32 bits, so a wider value (negative, or
   beyond 2^32) is refused here, before a cut could make it valid */
typedef char ssda__pitch_fixed_fields[FIXED_OK(
    (uint64_t)(SSDA_CFG_PITCH_FIXED_RATE_HZ) == SSDA_PITCH_FIXED_RATE &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_F0_MIN_HZ) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_F0_MAX_HZ) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_FRAME_LEN) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_HOP) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_THRESHOLD_Q15) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_VOICING_Q15) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_SILENCE_MAD) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_CHUNK) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_LOWPASS_HZ) <= 65535u &&
    (uint64_t)(SSDA_CFG_PITCH_FIXED_FLAGS) <= 255u)];
/* the flags ask for features this build has (flags_built, at compile time) */
#ifdef SSDA_CFG_NO_PITCH_FILTER
typedef char ssda__pitch_fixed_no_filter[FIXED_OK((SSDA_PITCH_FIXED_FLAGS & SSDA_PITCH_NO_FILTER) != 0u)];
#endif
#ifdef SSDA_CFG_NO_PITCH_TRACK
typedef char ssda__pitch_fixed_no_track[FIXED_OK((SSDA_PITCH_FIXED_FLAGS & SSDA_PITCH_TRACK) == 0u)];
#endif
#ifdef SSDA_CFG_NO_PITCH_FULL
typedef char ssda__pitch_fixed_no_full[FIXED_OK((SSDA_PITCH_FIXED_FLAGS & SSDA_PITCH_FULL) == 0u)];
#endif
#ifdef SSDA_CFG_NO_PITCH_PARABOLIC
typedef char ssda__pitch_fixed_no_parabolic[FIXED_OK((SSDA_PITCH_FIXED_FLAGS & SSDA_PITCH_PARABOLIC) == 0u)];
#endif
#ifdef SSDA_CFG_NO_PITCH_OCTAVE
typedef char ssda__pitch_fixed_no_octave[FIXED_OK((SSDA_PITCH_FIXED_FLAGS & SSDA_PITCH_NO_OCTAVE) != 0u)];
#endif
#ifdef SSDA_CFG_NO_PITCH_BELOW_RANGE
typedef char ssda__pitch_fixed_no_below_range[FIXED_OK((SSDA_PITCH_FIXED_FLAGS & SSDA_PITCH_NO_BELOW_RANGE) != 0u)];
#endif

#else
int ssda__pitch_resolve(const ssda_pitch_config_t *cfg, ssda_pitch_info_t *info)
{
    ssda_pitch_info_t r;
    uint32_t rate, f0_min, f0_max;

    if (cfg == NULL || info == NULL) {
        return SSDA_ERR_NULL;
    }
    rate = cfg->sample_rate_hz;
    if (rate < SSDA_PITCH_RATE_MIN || rate > SSDA_PITCH_RATE_MAX) {
        return SSDA_ERR_ARG;
    }
    f0_min = SSDA_PITCH_F0_MIN_(cfg->f0_min_hz);
    f0_max = cfg->f0_max_hz != 0u ? cfg->f0_max_hz : SSDA_PITCH_DEFAULT_F0_MAX;
    /* f0_max <= rate / 4 keeps lag_min >= 4; f0_min >= 10 keeps
       lag_max <= 4800, so span <= 8192 + 4800 + 1. */
    if (f0_min < SSDA_PITCH_F0_LOWEST || f0_max > rate / 4u || f0_min >= f0_max) {
        return SSDA_ERR_ARG;
    }
    if (cfg->threshold_q15 > 32767u || cfg->voicing_q15 > 32767u ||
        cfg->lowpass_hz > rate / 4u || (cfg->flags & ~KNOWN_FLAGS) != 0u) {
        return SSDA_ERR_ARG;
    }
    if (!flags_built(cfg->flags)) {
        return SSDA_ERR_UNSUPPORTED;
    }

    r.sample_rate_hz = rate;
    r.lag_min = SSDA_DIV32(rate, f0_max);
    /* SSDA_PITCH_LAG_MAX and SSDA_PITCH_FRAME_LEN of pitch.h, with f0_min
       resolved, through SSDA_DIV32 */
    r.lag_max = SSDA_DIV32(rate + f0_min - 1u, f0_min);
    r.frame_len = cfg->frame_len != 0u ? cfg->frame_len
                  : (r.lag_max > SSDA_PITCH_FRAME_MIN ? r.lag_max : SSDA_PITCH_FRAME_MIN);
    if (r.frame_len < SSDA_PITCH_FRAME_MIN || r.frame_len > SSDA_PITCH_FRAME_MAX) {
        return SSDA_ERR_SIZE;
    }
    if (cfg->chunk > r.frame_len) {
        return SSDA_ERR_SIZE;
    }
    r.chunk = cfg->chunk != 0u ? cfg->chunk
              : (SSDA_PITCH_DEFAULT_CHUNK < r.frame_len ? SSDA_PITCH_DEFAULT_CHUNK : r.frame_len);
    r.hop = cfg->hop != 0u ? cfg->hop : r.frame_len / 4u; /* K >= 16: max(1, K / 4) = K / 4 */
    r.span = r.frame_len + r.lag_max + 1u;
    /* <= 4800 * 8192 < 2^26 */
    r.full_diffs = (r.lag_max - r.lag_min + 1u) * r.frame_len;
    r.threshold_q15 = cfg->threshold_q15 != 0u ? cfg->threshold_q15
                                               : (uint16_t)SSDA_PITCH_DEFAULT_THRESHOLD_Q15;
    r.voicing_q15 = cfg->voicing_q15 != 0u ? cfg->voicing_q15 : r.threshold_q15;
    r.silence_mad = cfg->silence_mad != 0u ? cfg->silence_mad
                                           : (uint16_t)SSDA_PITCH_DEFAULT_SILENCE_MAD;
    r.lowpass_hz = 0u;
    r.lowpass_q15 = 0u;
#ifndef SSDA_CFG_NO_PITCH_FILTER
    if ((cfg->flags & SSDA_PITCH_NO_FILTER) == 0u) {
        r.lowpass_hz = (uint16_t)(cfg->lowpass_hz != 0u ? cfg->lowpass_hz : f0_max);
        r.lowpass_q15 = ssda__pitch_lowpass_coef_q15(r.lowpass_hz, rate);
    }
#endif
    r.flags = cfg->flags;
    *info = r;
    return SSDA_OK;
}
#endif /* SSDA_CFG_PITCH_FIXED */
