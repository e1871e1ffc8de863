/*
 * test_pitch_accuracy.c - estimates against the exactly known f0 of
 * synthetic signals: sines at several rates, vowels (pulse trains through
 * formant resonators), a missing fundamental, vibrato, noise at several
 * SNRs, clipping, DC offsets, silence, DC and white noise.
 * The true f0 is taken at each estimate's centre time (est.center).
 */
#include <string.h>

#include "unity.h"
#include "ssda/pitch.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define SIG_MAX 16000u

static int16_t g_sig[SIG_MAX];
static int16_t g_buf[4096];

typedef struct {
    uint32_t frames, voiced, silent, gross; /* gross: voiced and > 20 % off */
    double max_abs_cents;                   /* over voiced, non-gross frames */
} stats_t;

static double f0_of(const ssda_pitch_estimate_t *e) { return (double)e->f0_q16 / 65536.0; }

/* Stream the signal; compare every estimate with v's f0 at its centre. */
static stats_t run(const ssda_pitch_config_t *cfg, const int16_t *x, uint32_t n,
                   const test_voice_t *v)
{
    ssda_pitch_t p;
    stats_t st;
    size_t used = 0, took;
    memset(&st, 0, sizeof st);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, cfg, g_buf, sizeof g_buf));
    while (used < n) {
        ssda_pitch_estimate_t e;
        int r = ssda_pitch_push(&p, x + used, n - used, &took, &e);
        used += took;
        if (r != 1) {
            continue;
        }
        st.frames++;
        st.silent += e.silent ? 1u : 0u;
        if (e.silent) {
            TEST_ASSERT_FALSE(e.voiced);
            TEST_ASSERT_EQUAL_UINT32(0u, e.f0_q16);
            TEST_ASSERT_EQUAL_UINT32(0u, e.diffs);
        }
        if (e.voiced && v != NULL) {
            double truth = test_voice_f0_at(v, (double)e.center / cfg->sample_rate_hz);
            double c = test_cents(f0_of(&e), truth);
            double ac = c < 0 ? -c : c;
            st.voiced++;
            if (f0_of(&e) > 1.2 * truth || f0_of(&e) < 0.8 * truth) {
                st.gross++;
            } else if (ac > st.max_abs_cents) {
                st.max_abs_cents = ac;
            }
        } else if (e.voiced) {
            st.voiced++;
        }
    }
    return st;
}

static ssda_pitch_config_t config(uint32_t rate, uint8_t flags)
{
    ssda_pitch_config_t c;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = rate;
    c.flags = flags;
    return c;
}

static void test_sines_at_several_rates(void)
{
    static const uint32_t rates[] = {8000u, 16000u, 44100u, 48000u};
    static const double f0s[] = {55.0, 110.0, 233.08, 440.0, 987.77};
    uint32_t i, j;
    for (i = 0; i < 4u; i++) {
        for (j = 0; j < 5u; j++) {
            test_voice_t v;
            ssda_pitch_config_t c = config(rates[i], 0u);
            uint32_t n = rates[i] / 8u; /* 0.125 s */
            stats_t st;
            c.f0_max_hz = 1100u;
            test_voice_sine(&v, f0s[j], 12000.0);
            test_signal_voice(g_sig, n, 0u, rates[i], &v);
            st = run(&c, g_sig, n, &v);
            TEST_ASSERT_TRUE(st.frames >= 3u);
            TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
            TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
            TEST_ASSERT_TRUE(st.max_abs_cents < 3.0);
            /* the parabolic fit is less exact on the V-shaped AMDF dip */
            c.flags = SSDA_PITCH_PARABOLIC;
            st = run(&c, g_sig, n, &v);
            TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
            TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
            TEST_ASSERT_TRUE(st.max_abs_cents < 25.0);
        }
    }
}

static void test_vowels_have_no_octave_errors(void)
{
    static const double f0s[] = {70.0, 98.0, 135.0, 196.0, 262.0, 415.0, 659.0, 880.0};
    uint32_t j, kind;
    for (kind = 0; kind < 2u; kind++) {
        for (j = 0; j < sizeof f0s / sizeof f0s[0]; j++) {
            test_voice_t v;
            ssda_pitch_config_t c = config(16000u, SSDA_PITCH_TRACK);
            stats_t st;
            if (kind == 0u) {
                test_voice_vowel_a(&v, f0s[j], 14000.0);
            } else {
                test_voice_vowel_i(&v, f0s[j], 14000.0); /* F1 270 Hz near 2 f0 at 135 Hz */
            }
            test_signal_voice(g_sig, 6000u, 0u, 16000u, &v);
            st = run(&c, g_sig, 6000u, &v);
            TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
            TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
            TEST_ASSERT_TRUE(st.max_abs_cents < 5.0);
        }
    }
}

static void test_missing_fundamental_and_bright_pulses(void)
{
    test_voice_t v;
    ssda_pitch_config_t c = config(16000u, 0u);
    stats_t st;
    /* harmonics 1..24 of 180 Hz with a flat spectrum (a bright pulse train) */
    test_voice_vowel_a(&v, 180.0, 14000.0);
    v.n_formants = 0u;
    v.harmonics = 24u;
    test_signal_voice(g_sig, 6000u, 0u, 16000u, &v);
    st = run(&c, g_sig, 6000u, &v);
    TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
    TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
    /* harmonics 2..8 only: the waveform still repeats at 1 / f0 */
    test_voice_vowel_a(&v, 180.0, 14000.0);
    v.harmonics = 8u;
    v.first_harmonic = 2u;
    test_signal_voice(g_sig, 6000u, 0u, 16000u, &v);
    st = run(&c, g_sig, 6000u, &v);
    TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
    TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
}

static void test_vibrato_is_followed(void)
{
    test_voice_t v;
    ssda_pitch_config_t c = config(16000u, SSDA_PITCH_TRACK);
    stats_t st;
    c.hop = 80u;
    test_voice_vowel_a(&v, 220.0, 12000.0);
    v.vibrato_hz = 5.5;
    v.vibrato_depth = 0.05; /* +-5 %, nearly a semitone */
    test_signal_voice(g_sig, SIG_MAX, 0u, 16000u, &v);
    st = run(&c, g_sig, SIG_MAX, &v);
    TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
    TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
    TEST_ASSERT_TRUE(st.max_abs_cents < 12.0);
}

static void test_noise_at_several_snrs(void)
{
    static const double snrs[] = {30.0, 20.0, 10.0};
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        test_voice_t v;
        test_rng_t r;
        ssda_pitch_config_t c = config(16000u, 0u);
        stats_t st;
        test_voice_vowel_a(&v, 180.0, 10000.0);
        test_signal_voice(g_sig, 8000u, 0u, 16000u, &v);
        test_rng_seed(&r, 100u + k);
        test_signal_add_noise(g_sig, 8000u, snrs[k], &r);
        st = run(&c, g_sig, 8000u, &v);
        TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
        if (snrs[k] >= 20.0) {
            TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
            TEST_ASSERT_TRUE(st.max_abs_cents < 10.0);
        } else {
            TEST_ASSERT_TRUE(st.voiced * 10u >= st.frames * 8u); /* >= 80 % voiced */
            TEST_ASSERT_TRUE(st.max_abs_cents < 25.0);
        }
    }
}

static void test_clipping_and_dc_offset_keep_the_pitch(void)
{
    test_voice_t v;
    ssda_pitch_config_t c = config(16000u, 0u);
    stats_t st;
    uint32_t i;
    test_voice_vowel_a(&v, 147.0, 12000.0);
    test_signal_voice(g_sig, 8000u, 0u, 16000u, &v);
    test_signal_gain_clip(g_sig, 8000u, 6.0); /* hard clipped, nearly a square */
    st = run(&c, g_sig, 8000u, &v);
    TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
    TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
    TEST_ASSERT_TRUE(st.max_abs_cents < 10.0);
    /* +20000 offset: the top of the waveform saturates at 32767 */
    test_signal_voice(g_sig, 8000u, 0u, 16000u, &v);
    for (i = 0; i < 8000u; i++) {
        int32_t s = g_sig[i] + 20000;
        g_sig[i] = (int16_t)(s > 32767 ? 32767 : s);
    }
    st = run(&c, g_sig, 8000u, &v);
    TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
    TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
    TEST_ASSERT_TRUE(st.max_abs_cents < 10.0);
}

static void test_silence_dc_and_noise_are_not_voiced(void)
{
    static const uint8_t flags[] = {0u, SSDA_PITCH_NO_FILTER};
    uint32_t k;
    for (k = 0; k < 2u; k++) {
        ssda_pitch_config_t c = config(16000u, flags[k]);
        test_rng_t r;
        stats_t st;
        memset(g_sig, 0, 4000u * sizeof g_sig[0]);
        st = run(&c, g_sig, 4000u, NULL);
        TEST_ASSERT_TRUE(st.frames > 0u);
        TEST_ASSERT_EQUAL_UINT32(st.frames, st.silent);
        /* constant -32768 and +12345: no deviation from the mean at all */
        test_signal_square(g_sig, 4000u, 2u, 0u, -32768, -32768);
        st = run(&c, g_sig, 4000u, NULL);
        TEST_ASSERT_EQUAL_UINT32(st.frames, st.silent);
        test_signal_square(g_sig, 4000u, 2u, 0u, 12345, 12345);
        st = run(&c, g_sig, 4000u, NULL);
        TEST_ASSERT_EQUAL_UINT32(st.frames, st.silent);
        /* very quiet noise (rms 4 LSB) is below the silence level */
        test_rng_seed(&r, 8u);
        test_signal_noise(g_sig, 4000u, 4.0, &r);
        st = run(&c, g_sig, 4000u, NULL);
        TEST_ASSERT_EQUAL_UINT32(st.frames, st.silent);
        /* loud white noise is analysed but has no dip under the threshold */
        test_signal_noise(g_sig, 8000u, 5000.0, &r);
        st = run(&c, g_sig, 8000u, NULL);
        TEST_ASSERT_EQUAL_UINT32(0u, st.silent);
        TEST_ASSERT_EQUAL_UINT32(0u, st.voiced);
    }
}

/* Tones just below f0_max (default 1000 Hz): their period lies just above
   lag_min, so lag_min - 1 is inside their dip already; the half-period peak
   near lag_min / 2 arms the first dip (without it the dip at twice the
   period won: 925..1000 Hz read an octave low at 48 kHz). And a tone an
   octave lower whose strong 2nd harmonic puts a dip just below lag_min,
   which now arms, is still read at its own period: a run whose minimum is
   lag_min while n still falls is no dip (without that rule it read about
   1010 Hz). Against the known f0. */
static void test_tones_just_below_f0_max(void)
{
    static const uint32_t rates[] = {16000u, 44100u, 48000u};
    static const double f0s[] = {925.0, 950.0, 975.0, 990.0, 1000.0};
    uint32_t i, j, t;
    for (i = 0; i < 6u; i++) { /* early exit, then every lag in full */
        for (j = 0; j < 5u; j++) {
            test_voice_t v;
            ssda_pitch_config_t c = config(rates[i % 3u], i < 3u ? 0u : SSDA_PITCH_FULL);
            uint32_t n = rates[i % 3u] / 8u; /* 0.125 s */
            stats_t st;
            test_voice_sine(&v, f0s[j], 12000.0);
            test_signal_voice(g_sig, n, 0u, rates[i % 3u], &v);
            st = run(&c, g_sig, n, &v);
            TEST_ASSERT_TRUE(st.frames >= 3u);
            TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
            TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
            TEST_ASSERT_TRUE(st.max_abs_cents < 3.0);
        }
    }
    for (i = 0; i < 3u; i++) {
        /* 520 Hz: its 2nd harmonic (period just below lag_min) 17 dB over
           the fundamental, no low-pass (it would take the harmonic out) */
        test_voice_t v;
        ssda_pitch_config_t c = config(rates[i], SSDA_PITCH_NO_FILTER);
        uint32_t n = rates[i] / 8u;
        stats_t st;
        const double w = 2.0 * 3.14159265358979 * 520.0 / rates[i];
        test_voice_sine(&v, 520.0, 1.0); /* the truth for run() */
        for (t = 0; t < n; t++) {
            g_sig[t] = (int16_t)(1500.0 * test_sin(w * t) + 11000.0 * test_sin(2.0 * w * t + 0.5));
        }
        st = run(&c, g_sig, n, &v);
        TEST_ASSERT_TRUE(st.frames >= 3u);
        TEST_ASSERT_EQUAL_UINT32(st.frames, st.voiced);
        TEST_ASSERT_EQUAL_UINT32(0u, st.gross);
    }
}

/* Tones just above f0_max (default 1000 Hz), and far above it: their
   period is shorter than lag_min, so the first dip in range is at a
   multiple of it (1500 Hz read 750 Hz, 2500 Hz read 833 Hz, voiced). A
   period below the range must not be reported as its multiple: every frame
   is unvoiced (issue 14, item 11). Early exit and every lag in full, with
   and without the low-pass filter. */
static void test_tones_above_f0_max_are_unvoiced(void)
{
    static const uint32_t rates[] = {16000u, 44100u, 48000u};
    static const double f0s[] = {1020.0, 1050.0, 1100.0, 1500.0, 1990.0, 2500.0, 3700.0};
    uint32_t i, j;
    for (i = 0; i < 9u; i++) {
        static const uint8_t flags[] = {0u, SSDA_PITCH_FULL, SSDA_PITCH_NO_FILTER};
        for (j = 0; j < 7u; j++) {
            test_voice_t v;
            ssda_pitch_config_t c = config(rates[i % 3u], flags[i / 3u]);
            uint32_t n = rates[i % 3u] / 8u; /* 0.125 s */
            stats_t st;
            if ((double)rates[i % 3u] / f0s[j] >= (double)(rates[i % 3u] / 1000u) - 0.5) {
                continue; /* within half a lag of lag_min: read as itself (1020 Hz at 16 kHz) */
            }
            test_voice_sine(&v, f0s[j], 12000.0);
            test_signal_voice(g_sig, n, 0u, rates[i % 3u], &v);
            st = run(&c, g_sig, n, NULL);
            TEST_ASSERT_TRUE(st.frames >= 3u);
            TEST_ASSERT_EQUAL_UINT32(0u, st.silent);
            if (st.voiced != 0u) {
                char msg[64];
                (void)snprintf(msg, sizeof msg, "%.0f Hz at %u Hz, flags %u", f0s[j],
                               (unsigned)rates[i % 3u], (unsigned)flags[i / 3u]);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sines_at_several_rates);
    RUN_TEST(test_tones_just_below_f0_max);
    RUN_TEST(test_tones_above_f0_max_are_unvoiced);
    RUN_TEST(test_vowels_have_no_octave_errors);
    RUN_TEST(test_missing_fundamental_and_bright_pulses);
    RUN_TEST(test_vibrato_is_followed);
    RUN_TEST(test_noise_at_several_snrs);
    RUN_TEST(test_clipping_and_dc_offset_keep_the_pitch);
    RUN_TEST(test_silence_dc_and_noise_are_not_voiced);
    return UNITY_END();
}
