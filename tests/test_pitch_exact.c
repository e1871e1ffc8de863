/*
 * test_pitch_exact.c - the exactness claim of include/ssda/pitch.h: every
 * output but the work counter equals the brute-force full AMDF rule
 * (tests/support/test_pitch_ref.c, int64 arithmetic over full arrays), with
 * early exit, with tracking, with no early exit, and for every chunk size;
 * and the frame-at-a-time entry gives the push intake's estimates.
 */
#include "unity.h"
#include "ssda/pitch.h"
#include "pitch_internal.h"
#include "test_pitch_ref.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define SIG_MAX 24000u
#define EST_MAX 400u

static int16_t g_sig[SIG_MAX];
static int16_t g_buf[8192u + 4800u + 1u];
static ssda_pitch_estimate_t g_est[EST_MAX];
static ssda_pitch_estimate_t g_est2[EST_MAX];

/* The frame-at-a-time entry (ssda_pitch_frame) on the same signal gives
   push's estimates, every field (the work counter too): the two intakes
   agree where both apply (streams without the input low-pass). */
static void check_frame_entry(const ssda_pitch_config_t *cfg, const int16_t *x,
                              const ssda_pitch_estimate_t *pushed, uint32_t count)
{
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    ssda_pitch_estimate_t e;
    uint32_t f;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, cfg, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    for (f = 0; f < count; f++) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_frame(&p, x + f * info.hop, &e));
        TEST_ASSERT_EQUAL_UINT32(pushed[f].frame, e.frame);
        TEST_ASSERT_EQUAL_UINT32(pushed[f].center, e.center);
        TEST_ASSERT_EQUAL_UINT32(pushed[f].lag, e.lag);
        TEST_ASSERT_EQUAL_UINT32(pushed[f].period_q16, e.period_q16);
        TEST_ASSERT_EQUAL_UINT32(pushed[f].f0_q16, e.f0_q16);
        TEST_ASSERT_EQUAL_UINT32(pushed[f].diffs, e.diffs);
        TEST_ASSERT_EQUAL_UINT16(pushed[f].confidence_q15, e.confidence_q15);
        TEST_ASSERT_EQUAL(pushed[f].voiced, e.voiced);
        TEST_ASSERT_EQUAL(pushed[f].dip, e.dip);
        TEST_ASSERT_EQUAL(pushed[f].silent, e.silent);
    }
}

/* Push the whole signal at once, collect every estimate; without the
   input low-pass, the frame entry must give the same ones. */
static uint32_t run_stream(const ssda_pitch_config_t *cfg, const int16_t *x, uint32_t n,
                           ssda_pitch_estimate_t *out)
{
    ssda_pitch_t p;
    size_t used = 0, took;
    uint32_t count = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, cfg, g_buf, sizeof g_buf));
    while (used < n) {
        int r = ssda_pitch_push(&p, x + used, n - used, &took, &out[count]);
        TEST_ASSERT_TRUE(r == 0 || r == 1);
        used += took;
        if (r == 1) {
            TEST_ASSERT_EQUAL_UINT32(count, out[count].frame);
            count++;
            TEST_ASSERT_TRUE(count < EST_MAX);
        }
    }
    if ((cfg->flags & SSDA_PITCH_NO_FILTER) != 0u) {
        check_frame_entry(cfg, x, out, count);
    }
    return count;
}

static void assert_same(const test_pitch_ref_t *r, const ssda_pitch_estimate_t *e);

static int16_t g_filtered[SIG_MAX];
static uint32_t g_octave_moves; /* frames where the reference's octave check moved */

/* The input low-pass as include/ssda/pitch.h defines it, written from that
   text: a = round(32768 w / (1 + w)), w = 2 pi fc / rate (2 pi = 411775 /
   65536); states start at 32768 x[0]; per pole
   y += trunc(a (32768 in - y) / 32768); output floor((y2 + 16384) / 32768). */
static void reference_lowpass(const int16_t *x, int16_t *y, uint32_t n, uint32_t fc,
                              uint32_t rate)
{
    int64_t w = 411775 * (int64_t)fc, den = (int64_t)rate * 65536 + w;
    int64_t a = (w * 32768 + den / 2) / den, y1 = (int64_t)x[0] * 32768, y2 = y1;
    uint32_t i;
    for (i = 0; i < n; i++) {
        int64_t t;
        y1 += a * ((int64_t)x[i] * 32768 - y1) / 32768; /* C99 division truncates */
        y2 += a * (y1 - y2) / 32768;
        t = y2 + 16384;
        y[i] = (int16_t)(t >= 0 ? t / 32768 : -((-t + 32767) / 32768));
    }
}

static test_pitch_ref_t g_refs[EST_MAX];

/* Reference results for every frame the stream of cfg produces from x;
   the input low-pass is applied first unless cfg turns it off. */
static uint32_t reference_frames(const ssda_pitch_config_t *cfg, const int16_t *x, uint32_t n,
                                 test_pitch_ref_t *refs)
{
    ssda_pitch_info_t info;
    test_pitch_ref_cfg_t rc;
    uint32_t count, f;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(cfg, &info));
    rc = test_pitch_ref_cfg_of(&info);
    count = (n - info.span) / info.hop + 1u;
    TEST_ASSERT_TRUE(count <= EST_MAX);
    if ((cfg->flags & SSDA_PITCH_NO_FILTER) == 0u) {
        reference_lowpass(x, g_filtered, n, info.lowpass_hz, info.sample_rate_hz);
        x = g_filtered;
    }
    for (f = 0; f < count; f++) {
        test_pitch_reference(x + f * info.hop, &rc, &refs[f]);
    }
    return count;
}

/* The stream's estimates equal refs; returns the number of voiced frames. */
static uint32_t compare_stream(const ssda_pitch_config_t *cfg, const int16_t *x, uint32_t n,
                               const test_pitch_ref_t *refs, uint32_t nref)
{
    ssda_pitch_info_t info;
    uint32_t count, f, voiced = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(cfg, &info));
    count = run_stream(cfg, x, n, g_est);
    TEST_ASSERT_EQUAL_UINT32(nref, count);
    for (f = 0; f < count; f++) {
        assert_same(&refs[f], &g_est[f]);
        if (g_est[f].silent) {
            TEST_ASSERT_EQUAL_UINT32(0u, g_est[f].diffs);
        } else if ((cfg->flags & SSDA_PITCH_FULL) != 0u) {
            /* every lag of [lag_min - 1, lag_max + 1] summed in full, plus
               whole lags for the octave check (a multiple of K) */
            TEST_ASSERT_TRUE(g_est[f].diffs >= (info.lag_max - info.lag_min + 3u) * info.frame_len);
            TEST_ASSERT_EQUAL_UINT32(0u, g_est[f].diffs % info.frame_len);
            if (!g_est[f].dip) { /* no octave check without a dip */
                TEST_ASSERT_EQUAL_UINT32((info.lag_max - info.lag_min + 3u) * info.frame_len,
                                         g_est[f].diffs);
            }
        }
        voiced += g_est[f].voiced ? 1u : 0u;
        g_octave_moves += (refs[f].first_dip != 0u && refs[f].first_dip != refs[f].lag) ? 1u : 0u;
    }
    return voiced;
}

/* Every estimate equals the reference on its own span of samples. */
static uint32_t check_against_reference(const ssda_pitch_config_t *cfg, const int16_t *x,
                                        uint32_t n)
{
    uint32_t nref = reference_frames(cfg, x, n, g_refs);
    return compare_stream(cfg, x, n, g_refs, nref);
}

/* Reduced-definition flags (SSDA_PITCH_NO_OCTAVE, SSDA_PITCH_NO_BELOW_RANGE)
   that check_all_modes adds to every mode. */
static uint8_t g_reduced;

/* All modes of one config give the reference's results: for each analysed
   signal (filtered or not) and fit (V or parabola), early exit with several
   chunk sizes, tracking, and no early exit. */
static void check_all_modes(ssda_pitch_config_t cfg, const int16_t *x, uint32_t n)
{
    static const uint16_t chunks[] = {0u, 7u, 64u}; /* chunk 1: the random configs */
    static const uint8_t variants[] = {SSDA_PITCH_NO_FILTER, 0u, SSDA_PITCH_PARABOLIC,
                                       SSDA_PITCH_NO_FILTER | SSDA_PITCH_PARABOLIC};
    uint32_t i, j, nref;
    for (i = 0; i < sizeof variants; i++) {
        cfg.flags = (uint8_t)(variants[i] | g_reduced);
        cfg.chunk = 0u;
        nref = reference_frames(&cfg, x, n, g_refs);
        for (j = 0; j < sizeof chunks / sizeof chunks[0]; j++) {
            cfg.chunk = chunks[j];
            cfg.flags = (uint8_t)(variants[i] | g_reduced);
            compare_stream(&cfg, x, n, g_refs, nref);
            cfg.flags = (uint8_t)(variants[i] | g_reduced | SSDA_PITCH_TRACK);
            compare_stream(&cfg, x, n, g_refs, nref);
        }
        cfg.chunk = 0u;
        cfg.flags = (uint8_t)(variants[i] | g_reduced | SSDA_PITCH_FULL);
        compare_stream(&cfg, x, n, g_refs, nref);
        cfg.flags = (uint8_t)(variants[i] | g_reduced | SSDA_PITCH_FULL | SSDA_PITCH_TRACK);
        compare_stream(&cfg, x, n, g_refs, nref);
    }
}

/* The octave case into g_sig[0 .. n): /i/ at 135 Hz with a little vibrato
   and noise at 35 dB SNR, 16 kHz. */
static void make_octave_case(uint32_t n)
{
    test_voice_t v;
    test_rng_t r;
    test_voice_vowel_i(&v, 135.0, 12000.0);
    v.vibrato_hz = 5.0;
    v.vibrato_depth = 0.01;
    test_signal_voice(g_sig, n, 0u, 16000u, &v);
    test_rng_seed(&r, 4u);
    test_signal_add_noise(g_sig, n, 35.0, &r);
}

static void test_vowel_with_vibrato_and_noise_matches_reference(void)
{
    ssda_pitch_config_t cfg = {0};
    test_voice_t v;
    test_rng_t r;
    uint32_t n = 8000u;
    test_voice_vowel_a(&v, 180.0, 12000.0);
    v.vibrato_hz = 5.5;
    v.vibrato_depth = 0.04;
    test_signal_voice(g_sig, n, 0u, 16000u, &v);
    test_rng_seed(&r, 11u);
    test_signal_add_noise(g_sig, n, 20.0, &r);
    cfg.sample_rate_hz = 16000u;
    cfg.hop = 160u;
    check_all_modes(cfg, g_sig, n);
}

static void test_octave_check_matches_reference(void)
{
    /* /i/ at 135 Hz: F1 (270 Hz) on the second harmonic puts the first dip
       at T / 2; the octave check must move to T, in every mode */
    ssda_pitch_config_t cfg = {0};
    uint32_t n = 6000u;
    make_octave_case(n);
    cfg.sample_rate_hz = 16000u;
    cfg.hop = 150u;
    g_octave_moves = 0u;
    cfg.flags = 0u;
    check_against_reference(&cfg, g_sig, n);
    TEST_ASSERT_TRUE(g_octave_moves > 0u); /* the case is really exercised */
    check_all_modes(cfg, g_sig, n);
}

static void test_noise_fallback_matches_reference(void)
{
    ssda_pitch_config_t cfg = {0};
    test_rng_t r;
    uint32_t n = 4000u, voiced;
    test_rng_seed(&r, 5u);
    test_signal_noise(g_sig, n, 3000.0, &r);
    cfg.sample_rate_hz = 8000u;
    cfg.hop = 100u;
    check_all_modes(cfg, g_sig, n);
    cfg.flags = 0u;
    voiced = check_against_reference(&cfg, g_sig, n);
    TEST_ASSERT_EQUAL_UINT32(0u, voiced); /* white noise has no dip under 0.2 */
}

static void test_range_edges_match_reference(void)
{
    /* f0 just inside each end of the range, and just outside it */
    static const double f0s[] = {1000.0, 990.0, 1100.0, 50.5, 48.0};
    ssda_pitch_config_t cfg = {0};
    test_voice_t v;
    uint32_t i, n = 6000u;
    cfg.sample_rate_hz = 8000u;
    cfg.hop = 211u;
    for (i = 0; i < sizeof f0s / sizeof f0s[0]; i++) {
        test_voice_vowel_i(&v, f0s[i], 9000.0);
        test_signal_voice(g_sig, n, 0u, 8000u, &v);
        check_all_modes(cfg, g_sig, n);
    }
}

static void test_thresholds_and_random_configs_match_reference(void)
{
    test_rng_t r;
    uint32_t trial;
    test_rng_seed(&r, 2024u);
    for (trial = 0; trial < 12u; trial++) {
        ssda_pitch_config_t cfg = {0};
        test_voice_t v;
        uint32_t n = 5000u;
        cfg.sample_rate_hz = test_rng_range(&r, 8000u, 12000u);
        cfg.f0_min_hz = (uint16_t)test_rng_range(&r, 60u, 150u);
        cfg.f0_max_hz = (uint16_t)test_rng_range(&r, 300u, 1500u);
        cfg.frame_len = (uint16_t)test_rng_range(&r, 0u, 1u) * (uint16_t)test_rng_range(&r, 16u, 300u);
        cfg.hop = (uint16_t)test_rng_range(&r, 50u, 700u);
        cfg.threshold_q15 = (uint16_t)test_rng_range(&r, 300u, 20000u);
        cfg.voicing_q15 = (uint16_t)test_rng_range(&r, 0u, 20000u);
        cfg.silence_mad = (uint16_t)test_rng_range(&r, 0u, 300u);
        cfg.chunk = (uint16_t)(trial == 0u ? 1u : test_rng_range(&r, 0u, 16u));
        cfg.flags = (uint8_t)test_rng_range(&r, 0u, 63u); /* the reduced definitions too */
        cfg.lowpass_hz = (uint16_t)(test_rng_range(&r, 0u, 1u) * test_rng_range(&r, 100u, 2000u));
        if (trial % 3u == 0u) {
            test_voice_sine(&v, 80.0 + 40.0 * trial, 6000.0);
        } else {
            test_voice_vowel_a(&v, 90.0 + 31.0 * trial, 8000.0);
        }
        v.vibrato_hz = 6.0;
        v.vibrato_depth = 0.02 * (double)(trial % 4u);
        test_signal_voice(g_sig, n, 0u, cfg.sample_rate_hz, &v);
        test_signal_add_noise(g_sig, n, 5.0 + 3.0 * (double)trial, &r);
        /* a silent stretch and a step in the middle */
        {
            uint32_t i;
            for (i = 1500u; i < 1900u; i++) {
                g_sig[i] = (int16_t)((trial & 1u) ? 0 : 3);
            }
        }
        check_against_reference(&cfg, g_sig, n);
    }
}

static void test_modes_differ_only_in_work(void)
{
    ssda_pitch_config_t cfg = {0};
    test_voice_t v;
    uint32_t n = 8000u, c1, c2, f, work_exit = 0, work_full = 0, work_track = 0;
    test_voice_vowel_a(&v, 140.0, 10000.0);
    test_signal_voice(g_sig, n, 0u, 16000u, &v);
    cfg.sample_rate_hz = 16000u;
    cfg.hop = 200u;
    cfg.flags = SSDA_PITCH_FULL;
    c1 = run_stream(&cfg, g_sig, n, g_est);
    cfg.flags = 0u;
    c2 = run_stream(&cfg, g_sig, n, g_est2);
    TEST_ASSERT_EQUAL_UINT32(c1, c2);
    for (f = 0; f < c1; f++) {
        TEST_ASSERT_TRUE(g_est[f].voiced);
        TEST_ASSERT_EQUAL_UINT32(g_est[f].period_q16, g_est2[f].period_q16);
        work_full += g_est[f].diffs;
        work_exit += g_est2[f].diffs;
    }
    cfg.flags = SSDA_PITCH_TRACK;
    c2 = run_stream(&cfg, g_sig, n, g_est2);
    for (f = 0; f < c2; f++) {
        TEST_ASSERT_EQUAL_UINT32(g_est[f].period_q16, g_est2[f].period_q16);
        work_track += g_est2[f].diffs;
    }
    /* The target on a clean voiced signal: at least 2x fewer
       differences than the full search (deterministic counts). */
    TEST_ASSERT_TRUE(work_exit * 2u <= work_full);
    TEST_ASSERT_TRUE(work_track <= work_exit);
}

static void assert_same(const test_pitch_ref_t *r, const ssda_pitch_estimate_t *e)
{
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(r->lag, e->lag, "lag");
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(r->period_q16, e->period_q16, "period_q16");
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(r->f0_q16, e->f0_q16, "f0_q16");
    TEST_ASSERT_EQUAL_UINT16_MESSAGE(r->confidence_q15, e->confidence_q15, "confidence");
    TEST_ASSERT_EQUAL_MESSAGE(r->voiced, e->voiced, "voiced");
    TEST_ASSERT_EQUAL_MESSAGE(r->dip, e->dip, "dip");
    TEST_ASSERT_EQUAL_MESSAGE(r->silent, e->silent, "silent");
}

/* Analyse one frame with every possible predicted lag (and none): the
   prediction may only change the work. */
static void check_every_prediction(const ssda_pitch_config_t *cfg, const int16_t *x)
{
    ssda_pitch_info_t info;
    test_pitch_ref_cfg_t rc;
    test_pitch_ref_t r;
    ssda_pitch_estimate_t e;
    uint32_t pred;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(cfg, &info));
    rc = test_pitch_ref_cfg_of(&info);
    test_pitch_reference(x, &rc, &r);
    for (pred = 0u; pred <= info.lag_max + 2u; pred++) {
        ssda__pitch_analyze(&info, x, pred, &e);
        assert_same(&r, &e);
    }
}

static void test_any_prediction_gives_the_reference_result(void)
{
    ssda_pitch_config_t cfg = {0};
    test_voice_t v;
    test_rng_t r;
    uint32_t i, n = 3000u;
    cfg.sample_rate_hz = 8000u;
    cfg.f0_min_hz = 60u;
    cfg.flags = SSDA_PITCH_TRACK;
    test_rng_seed(&r, 77u);
    /* strong second harmonic: a dip near T/2 that is shallower than the one
       at T, so the first run is not the best lag; several thresholds so the
       first run is sometimes under it and sometimes not */
    test_voice_sine(&v, 110.0, 6000.0);
    v.harmonics = 2u;
    test_signal_voice(g_sig, n, 0u, 8000u, &v);
    test_signal_add_noise(g_sig, n, 25.0, &r);
    for (i = 0; i < 6u; i++) {
        cfg.threshold_q15 = (uint16_t)(1000u + 2500u * i);
        check_every_prediction(&cfg, g_sig + 97u * i);
    }
    /* /i/ at 135 Hz: F1 on the second harmonic, the first dip is at T / 2
       and the octave check must move to T */
    test_voice_vowel_i(&v, 135.0, 12000.0);
    test_signal_voice(g_sig, n, 0u, 8000u, &v);
    test_signal_add_noise(g_sig, n, 30.0, &r);
    cfg.threshold_q15 = 0u;
    for (i = 0; i < 3u; i++) {
        cfg.flags = (uint8_t)(SSDA_PITCH_TRACK | (i == 2u ? SSDA_PITCH_PARABOLIC : 0u));
        check_every_prediction(&cfg, g_sig + 301u * i);
    }
    cfg.flags = SSDA_PITCH_TRACK;
    /* noise: the fallback path */
    test_signal_noise(g_sig, n, 2000.0, &r);
    cfg.threshold_q15 = 0u;
    check_every_prediction(&cfg, g_sig);
}

static void test_ties_go_to_the_smaller_lag(void)
{
    /* A period-25 square wave with one glitch deep inside the frame:
       d(25) = d(50) = d(75) = 2 |glitch| and s equal, so n ties exactly at
       multiples of the period; a threshold of 1/32768 keeps every lag out of
       the runs, so the global minimum decides and must take lag 25. */
    ssda_pitch_config_t cfg = {0};
    ssda_pitch_info_t info;
    test_pitch_ref_cfg_t rc;
    test_pitch_ref_t r;
    ssda_pitch_estimate_t e;
    uint32_t pred, chunk;
    cfg.sample_rate_hz = 8000u;
    cfg.f0_min_hz = 100u;   /* lag_max 80 */
    cfg.f0_max_hz = 400u;   /* lag_min 20 */
    cfg.frame_len = 300u;
    cfg.threshold_q15 = 1u;
    cfg.voicing_q15 = 1u;
    test_signal_square(g_sig, 400u, 25u, 0u, 5000, -5000);
    g_sig[200] = (int16_t)(g_sig[200] + 700);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(&cfg, &info));
    rc = test_pitch_ref_cfg_of(&info);
    test_pitch_reference(g_sig, &rc, &r);
    TEST_ASSERT_EQUAL_UINT32(25u, r.lag); /* the reference itself */
    TEST_ASSERT_FALSE(r.dip);
    TEST_ASSERT_TRUE(test_pitch_ref_d(25u) == test_pitch_ref_d(50u));
    TEST_ASSERT_TRUE(test_pitch_ref_s(25u) == test_pitch_ref_s(50u));
    for (chunk = 1u; chunk <= 300u; chunk += 37u) {
        info.chunk = chunk;
        for (pred = 0u; pred <= info.lag_max; pred += 5u) {
            info.flags = SSDA_PITCH_TRACK;
            ssda__pitch_analyze(&info, g_sig, pred, &e);
            assert_same(&r, &e);
        }
        info.flags = 0u;
        ssda__pitch_analyze(&info, g_sig, 0u, &e);
        assert_same(&r, &e);
    }
}

static void test_runs_after_an_invalid_edge_run_match_reference(void)
{
    /* A low sine: n rises slowly from lag 0, so lag_min sits in a run that
       is only the tail of the lag-0 dip (invalid), and the best lag so far
       is already under the threshold before the real dip at the period.
       The threshold bound alone then decides which lags of the real run are
       summed in full. Noise lifts the real dip towards the threshold. */
    ssda_pitch_config_t cfg = {0};
    test_voice_t v;
    test_rng_t r;
    uint32_t snr, thr, n = 2000u;
    cfg.sample_rate_hz = 8000u;
    cfg.f0_min_hz = 40u;
    test_rng_seed(&r, 99u);
    for (snr = 10u; snr <= 30u; snr += 8u) {
        test_voice_sine(&v, 50.0, 8000.0);
        test_signal_voice(g_sig, n, 0u, 8000u, &v);
        test_signal_add_noise(g_sig, n, (double)snr, &r);
        for (thr = 4000u; thr <= 12000u; thr += 4000u) {
            cfg.threshold_q15 = (uint16_t)thr;
            check_every_prediction(&cfg, g_sig);
        }
    }
}

static void test_a_wiggle_under_the_rearm_level_does_not_arm(void)
{
    /* A 50 Hz sine plus a ripple of period 6: n climbs from lag 0 with
       wiggles, so lag_min starts an invalid run and a second short run
       follows after a lag with threshold < n <= rearm, which is no peak.
       Only lags summed up to the rearm level can tell that. */
    static int16_t ripple[2000];
    ssda_pitch_config_t cfg = {0};
    test_voice_t v;
    uint32_t i;
    cfg.sample_rate_hz = 8000u;
    cfg.f0_min_hz = 40u;
    cfg.flags = SSDA_PITCH_TRACK;
    test_voice_sine(&v, 50.0, 10000.0);
    test_signal_voice(g_sig, 2000u, 0u, 8000u, &v);
    test_voice_sine(&v, 8000.0 / 6.0, 3000.0);
    test_signal_voice(ripple, 2000u, 0u, 8000u, &v);
    for (i = 0; i < 2000u; i++) {
        g_sig[i] = (int16_t)(g_sig[i] + ripple[i]);
    }
    check_every_prediction(&cfg, g_sig);
}

static void test_dip_beyond_lag_max_is_not_a_dip(void)
{
    /* Period 81.5 with lag_max 80: n still falls at lag_max + 1, so the run
       that ends at lag_max is not a dip (f0 below f0_min). */
    ssda_pitch_config_t cfg = {0};
    ssda_pitch_info_t info;
    test_pitch_ref_cfg_t rc;
    test_pitch_ref_t r;
    ssda_pitch_estimate_t e;
    test_voice_t v;
    cfg.sample_rate_hz = 8000u;
    cfg.f0_min_hz = 100u;
    cfg.f0_max_hz = 400u;
    test_voice_sine(&v, 8000.0 / 81.5, 10000.0);
    test_signal_voice(g_sig, 400u, 0u, 8000u, &v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(&cfg, &info));
    rc = test_pitch_ref_cfg_of(&info);
    test_pitch_reference(g_sig, &rc, &r);
    TEST_ASSERT_FALSE(r.dip);
    TEST_ASSERT_EQUAL_UINT32(80u, r.lag);
    ssda__pitch_analyze(&info, g_sig, 0u, &e);
    assert_same(&r, &e);
}

/* Voiced frames of an estimate array. */
static uint32_t count_voiced(const ssda_pitch_estimate_t *e, uint32_t n)
{
    uint32_t f, v = 0u;
    for (f = 0u; f < n; f++) {
        v += e[f].voiced ? 1u : 0u;
    }
    return v;
}

static ssda_pitch_estimate_t g_est_full[EST_MAX];

static void test_reduced_definitions_match_reference(void)
{
    /* The octave case of test_octave_check_matches_reference without step 4:
       the reference of the reduced definition keeps the first dip (T / 2),
       and so must the library, in every mode; with step 4 the lag differs. */
    ssda_pitch_config_t cfg = {0};
    test_voice_t v;
    uint32_t n = 6000u, count, nref, f, moved = 0u;
    make_octave_case(n);
    cfg.sample_rate_hz = 16000u;
    cfg.hop = 150u;
    cfg.flags = SSDA_PITCH_NO_OCTAVE;
    nref = reference_frames(&cfg, g_sig, n, g_refs);
    for (f = 0u; f < nref; f++) {
        TEST_ASSERT_TRUE(g_refs[f].first_dip == 0u || g_refs[f].first_dip == g_refs[f].lag);
    }
    compare_stream(&cfg, g_sig, n, g_refs, nref);
    cfg.flags = 0u;
    count = run_stream(&cfg, g_sig, n, g_est_full);
    cfg.flags = SSDA_PITCH_NO_OCTAVE;
    TEST_ASSERT_EQUAL_UINT32(count, run_stream(&cfg, g_sig, n, g_est));
    for (f = 0u; f < count; f++) {
        moved += g_est[f].lag != g_est_full[f].lag ? 1u : 0u;
    }
    TEST_ASSERT_TRUE(moved > 0u); /* step 4 really is skipped */
    cfg.flags = SSDA_PITCH_PARABOLIC; /* and with the parabola too (review, session 7) */
    TEST_ASSERT_EQUAL_UINT32(count, run_stream(&cfg, g_sig, n, g_est_full));
    cfg.flags = SSDA_PITCH_PARABOLIC | SSDA_PITCH_NO_OCTAVE;
    TEST_ASSERT_EQUAL_UINT32(count, run_stream(&cfg, g_sig, n, g_est));
    for (f = 0u, moved = 0u; f < count; f++) {
        moved += g_est[f].lag != g_est_full[f].lag ? 1u : 0u;
    }
    TEST_ASSERT_TRUE(moved > 0u);
    compare_stream(&cfg, g_sig, n, g_refs, reference_frames(&cfg, g_sig, n, g_refs));
    cfg.flags = SSDA_PITCH_NO_OCTAVE;
    g_reduced = SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE;
    check_all_modes(cfg, g_sig, n);

    /* A 1 500 Hz tone above f0_max = 1 000 Hz: unvoiced by step 6; without
       it the dip at twice its period is voiced, as the reference says. */
    test_voice_sine(&v, 1500.0, 9000.0);
    test_signal_voice(g_sig, n, 0u, 16000u, &v);
    cfg.flags = SSDA_PITCH_NO_BELOW_RANGE;
    TEST_ASSERT_TRUE(check_against_reference(&cfg, g_sig, n) > 0u);
    cfg.flags = 0u;
    count = run_stream(&cfg, g_sig, n, g_est_full);
    TEST_ASSERT_EQUAL_UINT32(0u, count_voiced(g_est_full, count));
    g_reduced = SSDA_PITCH_NO_BELOW_RANGE;
    check_all_modes(cfg, g_sig, n);
    /* Without step 4 alone, step 6 still finds the tone's period below the
       range (its floor F is still computed): unvoiced as with both steps. */
    cfg.flags = SSDA_PITCH_NO_OCTAVE;
    count = run_stream(&cfg, g_sig, n, g_est);
    TEST_ASSERT_EQUAL_UINT32(0u, count_voiced(g_est, count));
    g_reduced = SSDA_PITCH_NO_OCTAVE;
    check_all_modes(cfg, g_sig, n);
    g_reduced = 0u;
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_vowel_with_vibrato_and_noise_matches_reference);
    RUN_TEST(test_octave_check_matches_reference);
    RUN_TEST(test_noise_fallback_matches_reference);
    RUN_TEST(test_range_edges_match_reference);
    RUN_TEST(test_thresholds_and_random_configs_match_reference);
    RUN_TEST(test_modes_differ_only_in_work);
    RUN_TEST(test_any_prediction_gives_the_reference_result);
    RUN_TEST(test_ties_go_to_the_smaller_lag);
    RUN_TEST(test_runs_after_an_invalid_edge_run_match_reference);
    RUN_TEST(test_a_wiggle_under_the_rearm_level_does_not_arm);
    RUN_TEST(test_dip_beyond_lag_max_is_not_a_dip);
    RUN_TEST(test_reduced_definitions_match_reference);
    return UNITY_END();
}
