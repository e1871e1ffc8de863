/*
 * test_pitch_config.c - configuration of the pitch stream: defaults, the
 * buffer-size macro against a closed form, every rejected configuration
 * with its error code and the state left untouched, and API misuse.
 */
#include <string.h>

#include "unity.h"
#include "ssda/pitch.h"

/* sizes compared as uint32_t (Unity 2.4.3 has no size_t assertion) */
#define ASSERT_SIZE(expected, actual) TEST_ASSERT_EQUAL_UINT32((uint32_t)(expected), (uint32_t)(actual))

void setUp(void) {}
void tearDown(void) {}

static int16_t g_buf[8192u + 4800u + 2u];

static ssda_pitch_config_t base(void)
{
    ssda_pitch_config_t c;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = 16000u;
    return c;
}

static void test_zero_config_takes_the_documented_defaults(void)
{
    ssda_pitch_config_t c = base();
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    TEST_ASSERT_EQUAL_UINT32(16000u, info.sample_rate_hz);
    TEST_ASSERT_EQUAL_UINT32(16000u / 1000u, info.lag_min);    /* floor(rate / 1000 Hz) */
    TEST_ASSERT_EQUAL_UINT32(16000u / 50u, info.lag_max);      /* ceil(rate / 50 Hz) */
    TEST_ASSERT_EQUAL_UINT32(320u, info.frame_len);            /* K = lag_max */
    TEST_ASSERT_EQUAL_UINT32(80u, info.hop);                   /* K / 4 */
    TEST_ASSERT_EQUAL_UINT32(320u + 320u + 1u, info.span);
    TEST_ASSERT_EQUAL_UINT32(32u, info.chunk);
    TEST_ASSERT_EQUAL_UINT32((320u - 16u + 1u) * 320u, info.full_diffs);
    TEST_ASSERT_EQUAL_UINT16(SSDA_PITCH_DEFAULT_THRESHOLD_Q15, info.threshold_q15);
    TEST_ASSERT_EQUAL_UINT16(info.threshold_q15, info.voicing_q15);
    TEST_ASSERT_EQUAL_UINT16(SSDA_PITCH_DEFAULT_SILENCE_MAD, info.silence_mad);
    TEST_ASSERT_EQUAL_UINT16(1000u, info.lowpass_hz);           /* f0_max */
    /* a = 2 pi 1000 / (16000 + 2 pi 1000) = 0.28197 -> 9240 in Q15 */
    TEST_ASSERT_EQUAL_UINT16(9240u, info.lowpass_q15);
}

static void test_explicit_fields_are_kept(void)
{
    ssda_pitch_config_t c = base();
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    c.sample_rate_hz = 44100u;
    c.f0_min_hz = 80u;
    c.f0_max_hz = 700u;
    c.frame_len = 1024u;
    c.hop = 441u;
    c.threshold_q15 = 5000u;
    c.voicing_q15 = 4000u;
    c.silence_mad = 3u;
    c.chunk = 100u;
    c.lowpass_hz = 2000u;
    c.flags = SSDA_PITCH_TRACK | SSDA_PITCH_PARABOLIC;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    TEST_ASSERT_EQUAL_UINT32(44100u / 700u, info.lag_min);
    TEST_ASSERT_EQUAL_UINT32((44100u + 79u) / 80u, info.lag_max);
    TEST_ASSERT_EQUAL_UINT32(1024u, info.frame_len);
    TEST_ASSERT_EQUAL_UINT32(441u, info.hop);
    TEST_ASSERT_EQUAL_UINT32(1024u + 552u + 1u, info.span);
    TEST_ASSERT_EQUAL_UINT32(100u, info.chunk);
    TEST_ASSERT_EQUAL_UINT16(5000u, info.threshold_q15);
    TEST_ASSERT_EQUAL_UINT16(4000u, info.voicing_q15);
    TEST_ASSERT_EQUAL_UINT16(3u, info.silence_mad);
    TEST_ASSERT_EQUAL_UINT16(2000u, info.lowpass_hz);
    TEST_ASSERT_EQUAL_UINT8(SSDA_PITCH_TRACK | SSDA_PITCH_PARABOLIC, info.flags);
    c.flags = SSDA_PITCH_NO_FILTER;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    TEST_ASSERT_EQUAL_UINT16(0u, info.lowpass_hz);
    TEST_ASSERT_EQUAL_UINT16(0u, info.lowpass_q15);
}

static void test_small_lag_range_defaults_to_the_minimum_frame(void)
{
    ssda_pitch_config_t c = base();
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    c.sample_rate_hz = 8000u;
    c.f0_min_hz = 1500u;  /* lag_max = 6 < 16 */
    c.f0_max_hz = 2000u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    TEST_ASSERT_EQUAL_UINT32(6u, info.lag_max);
    TEST_ASSERT_EQUAL_UINT32(SSDA_PITCH_FRAME_MIN, info.frame_len);
    TEST_ASSERT_EQUAL_UINT32(16u, info.chunk); /* the default 32 capped at K */
}

static void test_buffer_size_macro_matches_function_and_closed_form(void)
{
    static const uint32_t rates[] = {8000u, 11025u, 16000u, 22050u, 44100u, 48000u};
    static const uint16_t f0s[] = {0u, 10u, 37u, 50u, 199u};
    static const uint16_t frames[] = {0u, 16u, 1000u, 8192u};
    uint32_t i, j, k;
    for (i = 0; i < sizeof rates / sizeof rates[0]; i++) {
        for (j = 0; j < sizeof f0s / sizeof f0s[0]; j++) {
            for (k = 0; k < sizeof frames / sizeof frames[0]; k++) {
                ssda_pitch_config_t c = base();
                size_t bytes = 0;
                uint32_t f0 = f0s[j] ? f0s[j] : 50u;
                uint32_t lag_max = (rates[i] + f0 - 1u) / f0;
                uint32_t kk = frames[k] ? frames[k] : (lag_max > 16u ? lag_max : 16u);
                c.sample_rate_hz = rates[i];
                c.f0_min_hz = f0s[j];
                c.frame_len = frames[k];
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_buffer_size(&c, &bytes));
                ASSERT_SIZE((kk + lag_max + 1u) * 2u, bytes);
                ASSERT_SIZE(bytes, SSDA_PITCH_BUFFER_SIZE(rates[i], f0s[j], frames[k]));
            }
        }
    }
    /* the example in the header: 44.1 kHz, f0_min 50, default K */
    ASSERT_SIZE(3530u, SSDA_PITCH_BUFFER_SIZE(44100u, 50u, 0u));
}

/* init with c must fail with err and leave the state and the size untouched */
static void expect_rejected(const ssda_pitch_config_t *c, int err)
{
    ssda_pitch_t p, before;
    size_t bytes = 12345u;
    memset(&p, 0xA5, sizeof p);
    before = p;
    TEST_ASSERT_EQUAL_INT(err, ssda_pitch_init(&p, c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    if (err != SSDA_ERR_BUFFER) {
        TEST_ASSERT_EQUAL_INT(err, ssda_pitch_buffer_size(c, &bytes));
        ASSERT_SIZE(12345u, bytes);
    }
}

static void test_bad_configurations_are_rejected_with_the_right_error(void)
{
    ssda_pitch_config_t c;
    c = base(); c.sample_rate_hz = 0u;      expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.sample_rate_hz = 7999u;   expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.sample_rate_hz = 48001u;  expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.f0_min_hz = 9u;           expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.f0_max_hz = 4001u;        expect_rejected(&c, SSDA_ERR_ARG); /* > rate / 4 */
    c = base(); c.f0_min_hz = 300u; c.f0_max_hz = 300u; expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.f0_min_hz = 1000u;        expect_rejected(&c, SSDA_ERR_ARG); /* = default max */
    c = base(); c.f0_max_hz = 40u;          expect_rejected(&c, SSDA_ERR_ARG); /* < default min */
    c = base(); c.threshold_q15 = 32768u;   expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.voicing_q15 = 40000u;     expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.lowpass_hz = 4001u;       expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.flags = 0x40u;            expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.flags = 0x80u;            expect_rejected(&c, SSDA_ERR_ARG);
    c = base(); c.frame_len = 15u;          expect_rejected(&c, SSDA_ERR_SIZE);
    c = base(); c.frame_len = 8193u;        expect_rejected(&c, SSDA_ERR_SIZE);
    c = base(); c.frame_len = 100u; c.chunk = 101u; expect_rejected(&c, SSDA_ERR_SIZE);
    c = base(); c.chunk = 321u;             expect_rejected(&c, SSDA_ERR_SIZE); /* > default K */
}

static void test_limits_themselves_are_accepted(void)
{
    ssda_pitch_config_t c = base();
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    c.sample_rate_hz = 48000u; c.f0_min_hz = 10u; c.f0_max_hz = 12000u;
    c.frame_len = 8192u; c.chunk = 8192u; c.threshold_q15 = 32767u; c.voicing_q15 = 32767u;
    c.lowpass_hz = 12000u; c.silence_mad = 65535u; c.hop = 65535u;
    c.flags = SSDA_PITCH_TRACK | SSDA_PITCH_FULL | SSDA_PITCH_NO_FILTER | SSDA_PITCH_PARABOLIC |
              SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    TEST_ASSERT_EQUAL_UINT32(4u, info.lag_min);
    TEST_ASSERT_EQUAL_UINT32(4800u, info.lag_max);
    TEST_ASSERT_EQUAL_UINT32(8192u + 4800u + 1u, info.span);
    c = base();
    c.sample_rate_hz = 8000u; c.f0_min_hz = 10u; c.f0_max_hz = 2000u; c.frame_len = 16u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, sizeof g_buf));
}

static void test_buffer_too_small_or_misaligned_is_rejected(void)
{
    ssda_pitch_config_t c = base();
    size_t need = SSDA_PITCH_BUFFER_SIZE(16000u, 0u, 0u);
    ssda_pitch_t p, before;
    memset(&p, 0x5A, sizeof p);
    before = p;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_pitch_init(&p, &c, g_buf, need - 1u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                          ssda_pitch_init(&p, &c, (uint8_t *)g_buf + 1, need + 2u));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, need));
}

static void test_null_arguments_and_uninitialised_state(void)
{
    ssda_pitch_config_t c = base();
    ssda_pitch_t p, before;
    ssda_pitch_estimate_t e, e_before;
    ssda_pitch_info_t info;
    size_t used = 777u, bytes;
    int16_t x[4] = {0};
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_init(NULL, &c, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_init(&p, NULL, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_init(&p, &c, NULL, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_buffer_size(NULL, &bytes));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_buffer_size(&c, NULL));

    /* a zeroed state was never initialised */
    memset(&p, 0, sizeof p);
    memset(&e, 0x33, sizeof e);
    e_before = e;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_pitch_push(&p, x, 4u, &used, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_pitch_reset(&p));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_pitch_get_info(&p, &info));
    ASSERT_SIZE(777u, used);
    TEST_ASSERT_EQUAL_MEMORY(&e_before, &e, sizeof e);

    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &c, g_buf, sizeof g_buf));
    before = p;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_push(NULL, x, 4u, &used, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_push(&p, NULL, 4u, &used, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_push(&p, x, 4u, NULL, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_push(&p, x, 4u, &used, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_reset(NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_get_info(NULL, &info));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_get_info(&p, NULL));
    ASSERT_SIZE(777u, used);
    TEST_ASSERT_EQUAL_MEMORY(&e_before, &e, sizeof e);
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p); /* nothing consumed */

    /* an empty push is fine, even with no samples pointer */
    TEST_ASSERT_EQUAL_INT(0, ssda_pitch_push(&p, NULL, 0u, &used, &e));
    ASSERT_SIZE(0u, used);
    TEST_ASSERT_EQUAL_MEMORY(&e_before, &e, sizeof e);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_zero_config_takes_the_documented_defaults);
    RUN_TEST(test_explicit_fields_are_kept);
    RUN_TEST(test_small_lag_range_defaults_to_the_minimum_frame);
    RUN_TEST(test_buffer_size_macro_matches_function_and_closed_form);
    RUN_TEST(test_bad_configurations_are_rejected_with_the_right_error);
    RUN_TEST(test_limits_themselves_are_accepted);
    RUN_TEST(test_buffer_too_small_or_misaligned_is_rejected);
    RUN_TEST(test_null_arguments_and_uninitialised_state);
    return UNITY_END();
}
