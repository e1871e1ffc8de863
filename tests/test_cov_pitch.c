/*
 * test_cov_pitch.c - the pitch extractor at the corners the main pitch
 * tests leave out (found by branch coverage, tools/coverage.sh): resolving
 * defaults when lag_max is below the smallest frame, the resolver's NULL
 * checks, f0 conversion at its saturation, an octave check whose last
 * candidate lag is lag_max, and a frame with n(t) = 1 at every lag
 * (confidence 0). References: the closed forms written in pitch.h and the
 * brute-force rule of tests/support/test_pitch_ref.c.
 */
#include <string.h>
#include "unity.h"
#include "ssda/pitch.h"
#include "pitch_internal.h"
#include "test_pitch_ref.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

static int16_t g_x[400];
static int16_t g_buf[400];

/* f0_min 600 Hz at 8 kHz: lag_max = ceil(8000 / 600) = 14 < 16, so the
   default K is the smallest frame, 16 (pitch.h: max(16, lag_max)). */
static void test_defaults_when_lag_max_is_below_the_smallest_frame(void)
{
    ssda_pitch_config_t c;
    ssda_pitch_info_t info;
    ssda_pitch_t p;
    size_t bytes = 0;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = 8000u;
    c.f0_min_hz = 600u;
    c.f0_max_hz = 2000u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_buffer_size(&c, &bytes));
    TEST_ASSERT_EQUAL_UINT32((16u + 14u + 1u) * 2u, (uint32_t)bytes);
    TEST_ASSERT_EQUAL_UINT32(SSDA_PITCH_BUFFER_SIZE(8000u, 600u, 0u), (uint32_t)bytes);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, bytes));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    TEST_ASSERT_EQUAL_UINT32(4u, info.lag_min);   /* floor(8000 / 2000) */
    TEST_ASSERT_EQUAL_UINT32(14u, info.lag_max);
    TEST_ASSERT_EQUAL_UINT32(16u, info.frame_len);
    TEST_ASSERT_EQUAL_UINT32(31u, info.span);
    TEST_ASSERT_EQUAL_UINT32(4u, info.hop);       /* max(1, K / 4) */
    TEST_ASSERT_EQUAL_UINT32(16u, info.chunk);    /* 32, or K if smaller */
    TEST_ASSERT_EQUAL_UINT32((14u - 4u + 1u) * 16u, info.full_diffs);
    /* and with the default f0_min (50 Hz): lag_max 160 = K */
    c.f0_min_hz = 0u;
    c.f0_max_hz = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(&c, &info));
    TEST_ASSERT_EQUAL_UINT32(160u, info.lag_max);
    TEST_ASSERT_EQUAL_UINT32(160u, info.frame_len);
    TEST_ASSERT_EQUAL_UINT32(8u, info.lag_min);   /* floor(8000 / 1000) */
    TEST_ASSERT_EQUAL_UINT32(40u, info.hop);
    TEST_ASSERT_EQUAL_UINT32(SSDA_PITCH_BUFFER_SIZE(8000u, 0u, 0u), info.span * 2u);
}

static void test_resolve_refuses_null_with_info_untouched(void)
{
    ssda_pitch_config_t c;
    ssda_pitch_info_t info, poison;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = 16000u;
    memset(&poison, 0x3A, sizeof poison);
    info = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda__pitch_resolve(NULL, &info));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda__pitch_resolve(&c, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &info, sizeof info);
}

/* f0_q16 = floor(((rate << 32) + floor(period / 2)) / period), at most
   UINT32_MAX: exact for representable values, saturated above. */
static void test_f0_conversion_closed_form_and_saturation(void)
{
    /* 8000 Hz / 20 samples = 400 Hz exactly */
    TEST_ASSERT_EQUAL_UINT32(400u << 16, ssda__pitch_f0_q16(8000u, 20u << 16));
    /* 48000 / 3.5 = 13714.2857...: Q16 = floor(13714.2857 * 65536 + 1/2) */
    TEST_ASSERT_EQUAL_UINT32(898779429u, ssda__pitch_f0_q16(48000u, 229376u)); /* 898779428.57 + 1/2 */
    /* the last period that fits: (rate << 32) / p <= 2^32 - 1 needs
       p > rate (plus rounding); below it the value saturates */
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, ssda__pitch_f0_q16(48000u, 1u));
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, ssda__pitch_f0_q16(48000u, 48000u));
    TEST_ASSERT_EQUAL_UINT32((uint32_t)(((uint64_t)48000u << 32) / 48001u +
                                        ((((uint64_t)48000u << 32) % 48001u) >= 24001u ? 1u : 0u)),
                             ssda__pitch_f0_q16(48000u, 48001u));
}

/* One frame (span samples of x) through a stream; compared with the
   brute-force reference field by field. */
static void analyse_one_frame(const ssda_pitch_config_t *c, const int16_t *x,
                              ssda_pitch_estimate_t *est, test_pitch_ref_t *ref)
{
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    test_pitch_ref_cfg_t rc;
    size_t used = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    TEST_ASSERT_EQUAL_INT(1, ssda_pitch_push(&p, x, info.span, &used, est));
    TEST_ASSERT_EQUAL_UINT32(info.span, (uint32_t)used);
    rc = test_pitch_ref_cfg_of(&info);
    test_pitch_reference(x, &rc, ref);
    TEST_ASSERT_EQUAL_UINT32(ref->lag, est->lag);
    TEST_ASSERT_EQUAL_UINT32(ref->period_q16, est->period_q16);
    TEST_ASSERT_EQUAL_UINT32(ref->f0_q16, est->f0_q16);
    TEST_ASSERT_EQUAL_UINT16(ref->confidence_q15, est->confidence_q15);
    TEST_ASSERT_EQUAL(ref->voiced, est->voiced);
    TEST_ASSERT_EQUAL(ref->dip, est->dip);
    TEST_ASSERT_EQUAL(ref->silent, est->silent);
}

/* 8 kHz, lag_max 80: a 100 Hz tone (period 80) whose second harmonic
   (period 40) dominates. The first dip is at 40 (n about 0.2: the weak
   fundamental does not cancel there); the octave check's k = 2 candidates
   round(2 P) - 1 .. + 1 reach lag_max and find n(80) near 0, so the
   estimate moves to the true period, 80. */
static void test_octave_check_candidates_at_lag_max(void)
{
    ssda_pitch_config_t c;
    ssda_pitch_estimate_t est;
    test_pitch_ref_t ref;
    uint32_t i, flags;
    for (i = 0; i < 161u; i++) {
        double v = 10000.0 * test_sin(2.0 * TEST_PI * i / 40.0) +
                   3000.0 * test_sin(2.0 * TEST_PI * i / 80.0 + 0.3);
        g_x[i] = (int16_t)(v >= 0.0 ? v + 0.5 : v - 0.5);
    }
    for (flags = 0; flags < 2u; flags++) {
        memset(&c, 0, sizeof c);
        c.sample_rate_hz = 8000u;
        c.f0_min_hz = 100u; /* lag_max 80 */
        c.frame_len = 80u;
        c.flags = (uint8_t)(SSDA_PITCH_NO_FILTER | (flags != 0u ? SSDA_PITCH_FULL : 0u));
        analyse_one_frame(&c, g_x, &est, &ref);
        TEST_ASSERT_EQUAL_UINT32(40u, ref.first_dip);
        TEST_ASSERT_EQUAL_UINT32(80u, est.lag);
        TEST_ASSERT_TRUE(est.voiced);
        TEST_ASSERT_TRUE(est.dip);
    }
}

/* Frame: K = 16 samples alternating +-1000 (mean 0), then zeros, with
   lag_min - 1 = 19 >= K: every x[i + t] is 0, so d(t) = A = s(t) and
   n(t) = 1 at every lag. No run, no dip: t = lag_min (smallest n, ties the
   smaller lag), unvoiced, confidence 32767 - min(32767, 32768) = 0,
   period exactly 20 (a = b = c: no offset), f0 = 8000 / 20 = 400 Hz. */
static void test_flat_normalised_difference_gives_zero_confidence(void)
{
    ssda_pitch_config_t c;
    ssda_pitch_estimate_t est;
    test_pitch_ref_t ref;
    uint32_t i;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = 8000u;
    c.f0_min_hz = 100u; /* lag_max 80 */
    c.f0_max_hz = 400u; /* lag_min 20 */
    c.frame_len = 16u;
    c.flags = SSDA_PITCH_NO_FILTER;
    memset(g_x, 0, sizeof g_x);
    for (i = 0; i < 16u; i++) {
        g_x[i] = (int16_t)((i & 1u) != 0u ? -1000 : 1000);
    }
    analyse_one_frame(&c, g_x, &est, &ref);
    TEST_ASSERT_FALSE(est.silent);
    TEST_ASSERT_FALSE(est.voiced);
    TEST_ASSERT_FALSE(est.dip);
    TEST_ASSERT_EQUAL_UINT16(0u, est.confidence_q15);
    TEST_ASSERT_EQUAL_UINT32(20u, est.lag);
    TEST_ASSERT_EQUAL_UINT32(20u << 16, est.period_q16);
    TEST_ASSERT_EQUAL_UINT32(400u << 16, est.f0_q16);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_defaults_when_lag_max_is_below_the_smallest_frame);
    RUN_TEST(test_resolve_refuses_null_with_info_untouched);
    RUN_TEST(test_f0_conversion_closed_form_and_saturation);
    RUN_TEST(test_octave_check_candidates_at_lag_max);
    RUN_TEST(test_flat_normalised_difference_gives_zero_confidence);
    return UNITY_END();
}
