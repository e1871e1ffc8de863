/*
 * pitch.h - streaming pitch (f0) extraction with the average magnitude
 * difference function (AMDF) and SSDA early exit, in integers only.
 *
 * Seed: Onoe, Maeda, Saito 1976, appendix: Y_j = sum_i |X_i - X_(i-j)|, the
 * pitch period is the lag of its dip, and SSDA applies: a lag's sum is
 * abandoned once it passes a threshold, which also bounds every sum.
 * Design, measurements and the reasons behind each rule: docs/pitch.md.
 *
 * THE DEFINITION (one frame x[0 .. span-1], span = K + lag_max + 1):
 *   m    = floor((sum_{i<K} (x[i] + 32768) + floor(K/2)) / K) - 32768
 *   A    = sum_{i<K} |x[i] - m|                 the frame's own level
 *   d(t) = sum_{i<K} |x[i] - x[i+t]|            the AMDF
 *   s(t) = A + sum_{i<K} |x[i+t] - m|           d(t) <= s(t)
 *   n(t) = d(t) / s(t) in [0, 1]                normalised (0 = periodic)
 * for lags t in [lag_min - 1, lag_max + 1] and t = floor(lag_min / 2);
 * thr = threshold_q15 / 32768,
 * rearm = min(32767, 3 * threshold_q15 / 2) / 32768 (integer division).
 * Silent when A < silence_mad * K: no search, lag 0. Otherwise:
 *  1. Runs: maximal intervals of lags in [lag_min, lag_max] with n <= thr.
 *     A run's minimum is its lag of smallest n (ties: the smaller lag).
 *  2. A run is a dip when (a) a peak precedes it: some lag with n > rearm
 *     lies between the start of the previous run (or lag_min - 1) and it;
 *     for the first run n(lag_min - 1) > thr also counts, and so does
 *     n(floor(lag_min / 2)) > rearm (the half-period peak of a period just
 *     above lag_min, whose dip has begun by lag_min - 1); and (b) its
 *     minimum is not lag_max with n(lag_max + 1) < n(lag_max), nor lag_min
 *     with n(lag_min - 1) < n(lag_min). (a) rejects the tail of the lag-0
 *     dip and wiggles around thr; (b) a dip below f0_min, and the tail of
 *     a dip above f0_max (e.g. a strong 2nd harmonic's).
 *  3. t = the minimum of the first dip (YIN's idea: the first dip, not the
 *     global minimum, so no sub-octave errors as 2T, 3T, ... of plain AMDF).
 *  4. Octave check (against octave-up errors when a harmonic dominates):
 *     with P the sub-sample period at t (below) and F = b - |a - c| / 2
 *     (V fit) or b - (a - c)^2 / (8 (a - 2b + c)) (parabola, 0 drop if
 *     flat), floored at 0, from the Q20 values below: for k = 2, 3, ...
 *     while round(k P) - 1 <= lag_max, m = the lag of smallest n among
 *     round(k P) - 1 .. + 1 (within lag_max; ties: smaller); if
 *     nq(m) + margin < F with margin = (threshold_q15 / 3) << 5, then
 *     t = m and the check starts again from k = 2. round(v) =
 *     floor(v + 1/2) on the Q16 value.
 *  5. No dip: t = the lag in [lag_min, lag_max] of smallest n (ties:
 *     smaller), and the frame is unvoiced.
 *  6. Below the range (a tone above f0_max: its first dip in range is at a
 *     multiple of its period): with P and F of the final t, the frame is
 *     unvoiced when P < lag_min - 1/2, or when P < 2 lag_min and for some
 *     k >= 2 with c = round(P / k), 3 <= c < lag_min and P / k < lag_min,
 *     a lag u in c - 1 .. c + 1 with n(u - 1) >= n(u) <= n(u + 1) has its
 *     interpolated floor (F's formula on nq(u - 1), nq(u), nq(u + 1))
 *     <= F + margin / 2: the period is P / k, shorter than the range
 *     allows. lag, f0 and dip still describe the dip in range.
 * Sub-sample period through a, b, c = nq(t - 1), nq(t), nq(t + 1) with
 * nq(u) = floor(2^20 d(u) / s(u)):
 *   den = 2 (max(a, c) - b)  default: a V, the shape of an absolute-
 *                            difference dip (exact for it)
 *   den = 2 (a - 2b + c)     SSDA_PITCH_PARABOLIC: a parabola (the shape of
 *                            a squared-difference dip, as in YIN)
 *   delta_q16 = round_half_away(65536 (a - c) / den), 0 if den <= 0,
 *               clamped to [-32768, 32768];
 *   period_q16 = 65536 t + delta_q16;
 *   f0_q16 = floor(((rate << 32) + floor(period_q16 / 2)) / period_q16);
 *   confidence_q15 = 32767 - min(32767, floor(32768 n(t))).
 * Voiced: a dip was found, n(t) <= voicing_q15 / 32768, and step 6 does
 * not find the period below the range.
 * REDUCED DEFINITIONS (opt-in flags; every build gives the same estimate
 * for a configuration it accepts):
 *   SSDA_PITCH_NO_OCTAVE       step 4 is skipped: t is the first dip's
 *                              minimum as found in step 3. A harmonic that
 *                              dominates the fundamental can then read an
 *                              octave (or more) high.
 *   SSDA_PITCH_NO_BELOW_RANGE  step 6 is skipped: voiced = a dip was found
 *                              and n(t) <= voicing. A tone above f0_max then
 *                              reads, voiced, at a multiple of its period.
 * For a source whose f0 is known to lie well inside [f0_min, f0_max] with a
 * fundamental that is not much weaker than its harmonics (a tuner for one
 * instrument, a sine or a whistle), the estimates rarely differ; measured
 * on speech, singing and synthetic songs in docs/pitch.md. The compile
 * switches SSDA_CFG_NO_PITCH_OCTAVE and SSDA_CFG_NO_PITCH_BELOW_RANGE
 * (include/ssda/config.h) leave the checks' code out; such a build refuses
 * configurations without the matching flag (SSDA_ERR_UNSUPPORTED).
 * All comparisons of n are exact (cross-multiplied), except those written
 * with nq.
 *
 * EXACTNESS: lag, period_q16, f0_q16, confidence_q15, voiced, dip and
 * silent are bit-identical to the definition evaluated with every d summed
 * in full, in every mode (early exit, SSDA_PITCH_FULL, SSDA_PITCH_TRACK),
 * for every chunk size, kernel set and push pattern; only `diffs` differs.
 * tests/test_pitch_exact.c checks this against a brute-force reference.
 * Why early exit keeps it exact:
 *   - floor(lag_min / 2) is summed first (only when n(lag_min - 1) <= thr,
 *     cut above rearm); then lags are scanned upwards from lag_min - 1,
 *     each summed in chunks and
 *     cut once its partial sum passes its bound: the largest d with
 *     n <= thr (n <= rearm while no peak has been seen since the last run),
 *     or the largest d that still beats the best lag so far (the seed's
 *     automatic threshold, Fig. 9), whichever is larger. So every lag that
 *     can be in a run, prove a peak, or become the global minimum is summed
 *     in full, and a cut lag is known to be above all three;
 *   - |A - (s(t) - A)| <= d(t) rejects some lags before any difference;
 *   - the scan stops at the end of the first dip: later lags cannot change
 *     t except through the octave check, which sums its own lags with the
 *     bound of its own test (nq < F - margin);
 *   - with SSDA_PITCH_TRACK the previous voiced lag is summed first and
 *     becomes the best so far (the seed's prediction): it only tightens
 *     bounds, the rule depends on n alone;
 *   - t - 1 and t + 1 are re-summed in full when they were cut.
 *
 * OVERFLOW (proven by the limits below; each bound tested at full scale):
 *   |x[i] - x[i+t]| <= 65535, |x - m| <= 65535, K <= 8192:
 *   d(t) <= 8192 * 65535 < 2^29, s(t) < 2^30 (uint32_t); cross products
 *   d * s < 2^59 and 2^20 d < 2^49 (uint64_t). The seed's point holds too:
 *   a partial sum never exceeds its bound by more than one chunk
 *   (chunk * 65535), so the early exit itself bounds the accumulator.
 *
 * INPUT FILTER: unless SSDA_PITCH_NO_FILTER, pushed samples pass two
 * cascaded one-pole low-pass filters (Ross et al.'s AMDF extractor filtered
 * at 900 Hz): high harmonics of bright sources otherwise spoil the dip at
 * integer lags near a fractional period. Per pole, y in Q15:
 *   y += trunc(a (32768 in - y) / 32768)        (int64 product)
 *   a  = round(32768 w / (1 + w)), w = 2 pi lowpass_hz / rate
 *        (2 pi taken as 411775 / 65536)
 * the analysed sample is floor((y2 + 16384) / 32768), and both states start
 * at 32768 * (first sample after init/reset). y is a convex combination of
 * inputs: |y| <= 2^30, the output is int16. The definition above applies to
 * the filtered samples.
 *
 * TIME: estimate f (from 0 after init/reset) analyses stream samples
 * [f hop, f hop + span); lag t compares [f hop, f hop + K + t), so the
 * estimate belongs to their centre f hop + (K + t) / 2 (est->center).
 * LATENCY: the estimate is returned by the push that brings its last
 * sample, f hop + span - 1, that is span - 1 - (K + t) / 2 = K / 2 + lag_max
 * - t / 2 samples after its centre (with the default K = lag_max, 1.5
 * lag_max - t / 2: 28 ms for 220 Hz at 48 kHz with f0_min = 50 Hz), plus the
 * input low-pass's delay (about 14 samples at its default corner), which
 * center does not include. A higher f0_min (a shorter lag_max) shortens it.
 */
#ifndef SSDA_PITCH_H
#define SSDA_PITCH_H

#include "ssda/ssda.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Accepted ranges. */
#define SSDA_PITCH_RATE_MIN 8000u     /* sample rate, Hz */
#define SSDA_PITCH_RATE_MAX 48000u
#define SSDA_PITCH_F0_LOWEST 10u      /* smallest accepted f0_min_hz */
#define SSDA_PITCH_FRAME_MIN 16u      /* K, samples */
#define SSDA_PITCH_FRAME_MAX 8192u

/* Defaults (used where a config field is 0). */
#define SSDA_PITCH_DEFAULT_F0_MIN 50u           /* Hz */
#define SSDA_PITCH_DEFAULT_F0_MAX 1000u         /* Hz */
#define SSDA_PITCH_DEFAULT_THRESHOLD_Q15 9830u  /* 0.30 */
#define SSDA_PITCH_DEFAULT_SILENCE_MAD 16u      /* mean |x - m| in LSB, about -66 dBFS */
#define SSDA_PITCH_DEFAULT_CHUNK 32u            /* samples between early-exit tests */

/* Flags. */
#define SSDA_PITCH_TRACK     0x01u /* predict from the previous voiced lag (less work, same results) */
#define SSDA_PITCH_FULL      0x02u /* no early exit: every lag summed in full (the reference) */
#define SSDA_PITCH_NO_FILTER 0x04u /* analyse the samples as pushed, without the low-pass */
#define SSDA_PITCH_PARABOLIC 0x08u /* parabolic instead of V-shaped sub-sample fit */
/* Reduced definitions (change results; see "REDUCED DEFINITIONS" above): */
#define SSDA_PITCH_NO_OCTAVE 0x10u /* skip step 4, the octave check */
#define SSDA_PITCH_NO_BELOW_RANGE 0x20u /* skip step 6, the below-range check */

/* Internal: f0_min after defaulting. */
#define SSDA_PITCH_F0_MIN_(f0_min_hz) \
    ((uint32_t)(f0_min_hz) != 0u ? (uint32_t)(f0_min_hz) : SSDA_PITCH_DEFAULT_F0_MIN)

/* Largest lag searched, samples: ceil(rate / f0_min) (f0_min 0 = default). */
#define SSDA_PITCH_LAG_MAX(rate_hz, f0_min_hz)                                   \
    (((uint32_t)(rate_hz) + SSDA_PITCH_F0_MIN_(f0_min_hz) - 1u) / SSDA_PITCH_F0_MIN_(f0_min_hz))

/* K after defaulting: frame_len, or max(16, lag_max) when 0. */
#define SSDA_PITCH_FRAME_LEN(rate_hz, f0_min_hz, frame_len)                      \
    ((uint32_t)(frame_len) != 0u ? (uint32_t)(frame_len)                         \
     : SSDA_PITCH_LAG_MAX(rate_hz, f0_min_hz) > SSDA_PITCH_FRAME_MIN             \
         ? SSDA_PITCH_LAG_MAX(rate_hz, f0_min_hz) : SSDA_PITCH_FRAME_MIN)

/* Samples analysed per estimate: K + lag_max + 1. */
#define SSDA_PITCH_SPAN(rate_hz, f0_min_hz, frame_len)                           \
    (SSDA_PITCH_FRAME_LEN(rate_hz, f0_min_hz, frame_len) +                       \
     SSDA_PITCH_LAG_MAX(rate_hz, f0_min_hz) + 1u)

/* Bytes of sample buffer for ssda_pitch_init, from the config's
   sample_rate_hz, f0_min_hz and frame_len (zeros mean defaults, as there).
   Example: 44100 Hz, f0_min 50, default K = 882: 1765 samples, 3530 bytes. */
#define SSDA_PITCH_BUFFER_SIZE(rate_hz, f0_min_hz, frame_len) \
    ((size_t)SSDA_PITCH_SPAN(rate_hz, f0_min_hz, frame_len) * sizeof(int16_t))

/*
 * Fixed configuration (include/ssda/config.h: SSDA_CFG_PITCH_FIXED, for a
 * firmware with one configuration, a tuner say). The build is given one
 * configuration, SSDA_CFG_PITCH_FIXED_<FIELD> per field of
 * ssda_pitch_config_t (RATE_HZ required; an unset field is 0, its
 * default); its resolved parameters are constants checked when the
 * library compiles (an invalid one does not compile), and ssda_pitch_init
 * and ssda_pitch_buffer_size accept that configuration only: every field
 * equal to the fixed one, a zero standing for its default and the default
 * for a zero. Anything else returns SSDA_ERR_UNSUPPORTED (also a
 * configuration the full build refuses with SSDA_ERR_ARG or
 * SSDA_ERR_SIZE). What it accepts gives the full build's estimates, bit
 * for bit. SSDA_PITCH_CONFIG_FIXED initialises an ssda_pitch_config_t to
 * it, SSDA_PITCH_BUFFER_SIZE_FIXED is its buffer size.
 */
#ifdef SSDA_CFG_PITCH_FIXED
#ifndef SSDA_CFG_PITCH_FIXED_RATE_HZ
#error "SSDA_CFG_PITCH_FIXED needs SSDA_CFG_PITCH_FIXED_RATE_HZ (include/ssda/config.h)"
#endif
#ifndef SSDA_CFG_PITCH_FIXED_F0_MIN_HZ
#define SSDA_CFG_PITCH_FIXED_F0_MIN_HZ 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_F0_MAX_HZ
#define SSDA_CFG_PITCH_FIXED_F0_MAX_HZ 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_FRAME_LEN
#define SSDA_CFG_PITCH_FIXED_FRAME_LEN 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_HOP
#define SSDA_CFG_PITCH_FIXED_HOP 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_THRESHOLD_Q15
#define SSDA_CFG_PITCH_FIXED_THRESHOLD_Q15 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_VOICING_Q15
#define SSDA_CFG_PITCH_FIXED_VOICING_Q15 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_SILENCE_MAD
#define SSDA_CFG_PITCH_FIXED_SILENCE_MAD 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_CHUNK
#define SSDA_CFG_PITCH_FIXED_CHUNK 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_LOWPASS_HZ
#define SSDA_CFG_PITCH_FIXED_LOWPASS_HZ 0u
#endif
#ifndef SSDA_CFG_PITCH_FIXED_FLAGS
#define SSDA_CFG_PITCH_FIXED_FLAGS 0u
#endif
#define SSDA_PITCH_CONFIG_FIXED                                                  \
    {(uint32_t)(SSDA_CFG_PITCH_FIXED_RATE_HZ), (uint16_t)(SSDA_CFG_PITCH_FIXED_F0_MIN_HZ), \
     (uint16_t)(SSDA_CFG_PITCH_FIXED_F0_MAX_HZ), (uint16_t)(SSDA_CFG_PITCH_FIXED_FRAME_LEN), \
     (uint16_t)(SSDA_CFG_PITCH_FIXED_HOP), (uint16_t)(SSDA_CFG_PITCH_FIXED_THRESHOLD_Q15), \
     (uint16_t)(SSDA_CFG_PITCH_FIXED_VOICING_Q15), (uint16_t)(SSDA_CFG_PITCH_FIXED_SILENCE_MAD), \
     (uint16_t)(SSDA_CFG_PITCH_FIXED_CHUNK), (uint16_t)(SSDA_CFG_PITCH_FIXED_LOWPASS_HZ), \
     (uint8_t)(SSDA_CFG_PITCH_FIXED_FLAGS)}
#define SSDA_PITCH_BUFFER_SIZE_FIXED                                             \
    SSDA_PITCH_BUFFER_SIZE(SSDA_CFG_PITCH_FIXED_RATE_HZ, SSDA_CFG_PITCH_FIXED_F0_MIN_HZ, \
                           SSDA_CFG_PITCH_FIXED_FRAME_LEN)
#endif

/*
 * Configuration. A zero field means its default; sample_rate_hz is required.
 */
typedef struct {
    uint32_t sample_rate_hz; /* 8000..48000 */
    uint16_t f0_min_hz;      /* lowest f0 searched, Hz: >= 10, < f0_max (0 = 50).
                                Sets lag_max = ceil(rate / f0_min) */
    uint16_t f0_max_hz;      /* highest f0 searched, Hz: <= rate / 4 (0 = 1000).
                                Sets lag_min = floor(rate / f0_max) >= 4 */
    uint16_t frame_len;      /* K, samples per difference sum: 16..8192 (0 = lag_max,
                                i.e. one period of f0_min as in YIN, at least 16) */
    uint16_t hop;            /* samples between estimates: >= 1 (0 = max(1, K / 4)) */
    uint16_t threshold_q15;  /* dip threshold on n, Q15: 1..32767 (0 = 0.30,
                                SSDA_PITCH_DEFAULT_THRESHOLD_Q15) */
    uint16_t voicing_q15;    /* voiced iff n(t*) <= this, Q15: 1..32767 (0 = threshold_q15) */
    uint16_t silence_mad;    /* silent iff mean |x - m| over the K samples < this, LSB:
                                1..65535 (0 = 16; 1 = only constant frames).
                                For a sine of peak a, mean |x - m| = 2a / pi:
                                16 gates sines below about 25 LSB peak, measured
                                after the input low-pass (which attenuates tones
                                towards its corner) */
    uint16_t chunk;          /* samples summed between early-exit tests: 1..K (0 = 32,
                                or K if smaller). Changes work only, not results */
    uint16_t lowpass_hz;     /* cutoff of the input low-pass, Hz: 1..rate / 4
                                (0 = f0_max); see "Input filter" above */
    uint8_t flags;           /* SSDA_PITCH_TRACK | SSDA_PITCH_FULL | SSDA_PITCH_NO_FILTER
                                | SSDA_PITCH_PARABOLIC | SSDA_PITCH_NO_OCTAVE
                                | SSDA_PITCH_NO_BELOW_RANGE */
} ssda_pitch_config_t;

/* The resolved parameters (every default filled in). */
typedef struct {
    uint32_t sample_rate_hz;
    uint32_t lag_min;        /* floor(rate / f0_max), samples, >= 4 */
    uint32_t lag_max;        /* ceil(rate / f0_min), samples, <= 4800 */
    uint32_t frame_len;      /* K */
    uint32_t hop;            /* samples between estimates */
    uint32_t span;           /* K + lag_max + 1: samples per estimate */
    uint32_t chunk;          /* samples between early-exit tests */
    uint32_t full_diffs;     /* (lag_max - lag_min + 1) * K: absolute differences
                                one frame of plain full-search AMDF computes */
    uint16_t threshold_q15;
    uint16_t voicing_q15;
    uint16_t silence_mad;
    uint16_t lowpass_hz;     /* 0 when SSDA_PITCH_NO_FILTER */
    uint16_t lowpass_q15;    /* the filter's coefficient a, Q15 (0 = no filter) */
    uint8_t flags;
} ssda_pitch_info_t;

/* One estimate (per hop). */
typedef struct {
    uint32_t frame;          /* estimate number since init/reset: covers stream
                                samples [frame * hop, frame * hop + span) */
    uint32_t center;         /* stream sample at the centre of the samples the
                                chosen lag compares: frame * hop + (K + lag) / 2
                                (frame * hop + span / 2 when silent), mod 2^32 */
    uint32_t lag;            /* t*, samples; 0 when silent */
    uint32_t period_q16;     /* period, samples, Q16.16; 0 when silent */
    uint32_t f0_q16;         /* rate / period, Hz, Q16.16; 0 when silent */
    uint32_t diffs;          /* absolute differences computed for this frame
                                (work; the only field that depends on the mode) */
    uint16_t confidence_q15; /* 1 - n(t*), Q15, 0..32767; 0 when silent. An
                                unvoiced frame can score high: with no dip found
                                t* is the global minimum (e.g. a period outside
                                f0_min..f0_max); decide by voiced, not by this */
    bool voiced;             /* not silent and n(t*) <= voicing threshold */
    bool dip;                /* t* is the minimum of a dip run under the threshold
                                (false: global-minimum fallback, or silent) */
    bool silent;             /* level below silence_mad: no search was made */
} ssda_pitch_estimate_t;

/* Private: one lag's AMDF value in 8 bytes: bits 0..30 of d the sum (or,
   when cut, a lower bound above the cut), bit 31 set when exact; s the
   scale A + B(lag). */
typedef struct {
    uint32_t d;
    uint32_t s;
} ssda_pitch_lag_value_t;

/* Private: a lag with the values of its two neighbours (v[0] at lag - 1,
   v[1] at lag, v[2] at lag + 1). */
typedef struct {
    ssda_pitch_lag_value_t v[3];
    uint32_t lag;
} ssda_pitch_dip_t;

/* Private: the working state of one frame's analysis (the frame and its
   level, the scan's previous and current lag, the best lag so far, the
   open dip run and the chosen lag, each with its neighbours). It lives
   in ssda_pitch_t, not on the stack, so that ssda_pitch_push needs little
   stack (docs/target.md). */
typedef struct {
    const ssda_pitch_info_t *info;
    const int16_t *x;        /* the frame */
    int32_t mean;            /* m */
    uint32_t level;          /* A */
    uint32_t diffs;          /* absolute differences so far */
    ssda_pitch_lag_value_t at[2]; /* the scan: previous lag, current lag */
    ssda_pitch_lag_value_t pred;
    ssda_pitch_dip_t best, run, t;
} ssda_pitch_work_t;

/* The stream state. Caller-allocated; fields are private (read them through
   ssda_pitch_get_info). A state that ssda_pitch_init never filled (zeroed,
   or garbage without its magic value) is refused with SSDA_ERR_STATE; a
   copy of an initialised state, or one whose buffer has gone, is not
   detectable: the buffer must outlive the state's use. */
typedef struct {
    ssda_pitch_info_t info;
    int16_t *buf;            /* caller buffer of info.span samples */
    uint32_t fill;           /* valid samples in buf */
    uint32_t skip;           /* input samples still to drop (when hop > span) */
    uint32_t frame;          /* number of the next estimate */
    uint32_t predict_lag;    /* SSDA_PITCH_TRACK: last voiced lag, 0 = none */
    int32_t lp1_q15;         /* low-pass states, samples * 2^15, within +-2^30 */
    int32_t lp2_q15;
    bool lp_primed;          /* states start at the first sample (no start-up step) */
    uint32_t magic;          /* set by ssda_pitch_init */
    ssda_pitch_work_t work;  /* scratch of each analysis */
} ssda_pitch_t;

/*
 * Bytes of buffer the config needs (the value of SSDA_PITCH_BUFFER_SIZE),
 * after checking the config as ssda_pitch_init does.
 * Returns SSDA_OK and writes *bytes, or an error of ssda_pitch_init (other
 * than SSDA_ERR_BUFFER) with *bytes untouched. Built with
 * SSDA_CFG_NO_PITCH_PUSH (no buffer needed): SSDA_ERR_UNSUPPORTED.
 */
int ssda_pitch_buffer_size(const ssda_pitch_config_t *cfg, size_t *bytes);

/*
 * Start a stream.
 *   p:       state to initialise (caller-owned; written on success only).
 *   cfg:     configuration, copied (not kept).
 *   buffer:  caller buffer of >= SSDA_PITCH_BUFFER_SIZE(...) bytes, 2-byte
 *            aligned; owned by the stream until the caller stops using p.
 * Returns SSDA_OK, or with *p untouched:
 *   SSDA_ERR_NULL    p, cfg or buffer NULL
 *   SSDA_ERR_ARG     sample rate outside 8000..48000; f0_min < 10,
 *                    f0_max > rate / 4, or f0_min >= f0_max (after defaults);
 *                    threshold_q15 or voicing_q15 > 32767; lowpass_hz >
 *                    rate / 4; unknown flags
 *   SSDA_ERR_SIZE    frame_len outside 16..8192; chunk > frame_len
 *   SSDA_ERR_BUFFER  buffer_size too small, or buffer not 2-byte aligned
 *   SSDA_ERR_UNSUPPORTED  a flag asks for a feature this build left out
 *                    (include/ssda/config.h: SSDA_CFG_NO_PITCH_TRACK, _FULL,
 *                    _PARABOLIC), or omits one the build requires
 *                    (SSDA_CFG_NO_PITCH_FILTER: SSDA_PITCH_NO_FILTER;
 *                    SSDA_CFG_NO_PITCH_OCTAVE: SSDA_PITCH_NO_OCTAVE;
 *                    SSDA_CFG_NO_PITCH_BELOW_RANGE: SSDA_PITCH_NO_BELOW_RANGE);
 *                    built with SSDA_CFG_PITCH_FIXED, any configuration
 *                    but the fixed one ("Fixed configuration" above), in
 *                    place of SSDA_ERR_ARG and SSDA_ERR_SIZE too
 * Built with SSDA_CFG_NO_PITCH_PUSH, buffer and buffer_size are not used
 * (buffer may be NULL; ssda_pitch_frame takes the frames).
 */
int ssda_pitch_init(ssda_pitch_t *p, const ssda_pitch_config_t *cfg,
                    void *buffer, size_t buffer_size);

/*
 * Feed samples. Consumes samples until one estimate is ready or all count
 * samples are used, whichever comes first; call again with the rest.
 *   samples:  count int16 samples (may be NULL when count is 0), not kept.
 *   consumed: receives how many samples were taken (<= count).
 *   est:      receives the estimate when 1 is returned; else untouched.
 * Estimates do not depend on how the stream is cut into calls.
 * Built with SSDA_CFG_NO_PITCH_PUSH: returns SSDA_ERR_UNSUPPORTED, nothing
 * consumed or written (use ssda_pitch_frame).
 * Returns 1 (estimate written), 0 (all samples taken, no estimate yet), or
 * with nothing consumed and *consumed, *est untouched:
 *   SSDA_ERR_NULL   p, consumed or est NULL, or samples NULL with count > 0
 *   SSDA_ERR_STATE  p not initialised by ssda_pitch_init
 */
int ssda_pitch_push(ssda_pitch_t *p, const int16_t *samples, size_t count,
                    size_t *consumed, ssda_pitch_estimate_t *est);

/*
 * Analyse one frame given whole (the frame-at-a-time entry, for a caller
 * that holds its signal in memory, or a firmware built with
 * SSDA_CFG_NO_PITCH_PUSH): x holds the info.span samples of the stream's
 * next estimate, number f = est->frame, i.e. stream samples [f hop,
 * f hop + span), so the caller steps through its signal by hop samples.
 * The estimate is bit-identical to the one ssda_pitch_push returns for the
 * same samples (every field, diffs included); the prediction
 * (SSDA_PITCH_TRACK) is carried to the next frame as push carries it.
 * The input low-pass runs over the continuous stream, not per frame, so a
 * stream with the low-pass is refused: set SSDA_PITCH_NO_FILTER. Use one
 * entry per stream (this one does not touch push's buffered samples).
 *   x:   info.span samples, read only, not kept.
 *   est: receives the estimate on success; else untouched.
 * Returns SSDA_OK, or with *est and the stream untouched:
 *   SSDA_ERR_NULL   p, x or est NULL
 *   SSDA_ERR_STATE  p not initialised by ssda_pitch_init
 *   SSDA_ERR_ARG    the stream has the input low-pass (no SSDA_PITCH_NO_FILTER)
 */
int ssda_pitch_frame(ssda_pitch_t *p, const int16_t *x, ssda_pitch_estimate_t *est);

/*
 * Forget buffered samples and the prediction; the next estimate is number
 * 0 again. Config and buffer are kept.
 * Returns SSDA_OK, SSDA_ERR_NULL or SSDA_ERR_STATE.
 */
int ssda_pitch_reset(ssda_pitch_t *p);

/*
 * The resolved parameters of an initialised stream.
 * Returns SSDA_OK, SSDA_ERR_NULL or SSDA_ERR_STATE (*info untouched).
 */
int ssda_pitch_get_info(const ssda_pitch_t *p, ssda_pitch_info_t *info);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_PITCH_H */
