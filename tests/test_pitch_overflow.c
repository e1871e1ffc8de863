/*
 * test_pitch_overflow.c - every accumulator of the pitch extractor at its
 * worst case, with full-scale input: +-32767/-32768 square waves with and
 * without DC offsets, K at its maximum (8192), the largest lag range, and
 * the input filter driven between the rails. Results are checked against
 * closed forms and the int64 brute-force reference.
 */
#include <string.h>

#include "unity.h"
#include "ssda/pitch.h"
#include "pitch_internal.h"
#include "test_pitch_ref.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define KMAX 8192u
#define SPAN_MAX (KMAX + 4800u + 1u)

static int16_t g_x[SPAN_MAX];

static void test_amdf_term_at_its_worst_case(void)
{
    /* x alternates +32767 / -32768: at lag 1 every |difference| is 65535,
       so d = K * 65535 = 536 862 720, the largest sum there is. */
    uint32_t diffs = 0, d, bound;
    bool complete;
    test_signal_square(g_x, KMAX + 2u, 2u, 0u, 32767, -32768);
    d = ssda__pitch_amdf_lag(g_x, KMAX, 1u, 32u, UINT32_MAX, &complete, &diffs);
    TEST_ASSERT_TRUE(complete);
    TEST_ASSERT_EQUAL_UINT32(KMAX * 65535u, d);
    TEST_ASSERT_EQUAL_UINT32(KMAX, diffs);
    /* bound exactly at the sum: not cut; one below: cut, and the partial sum
       exceeds the bound by at most one chunk (the seed's overflow argument) */
    diffs = 0;
    d = ssda__pitch_amdf_lag(g_x, KMAX, 1u, KMAX, KMAX * 65535u, &complete, &diffs);
    TEST_ASSERT_TRUE(complete);
    for (bound = 0u; bound < KMAX * 65535u; bound += 65535u * 1000u + 7u) {
        diffs = 0;
        d = ssda__pitch_amdf_lag(g_x, KMAX, 1u, 100u, bound, &complete, &diffs);
        TEST_ASSERT_FALSE(complete);
        TEST_ASSERT_TRUE(d > bound);
        TEST_ASSERT_TRUE(d <= bound + 100u * 65535u);
        TEST_ASSERT_EQUAL_UINT32(0u, diffs % 100u);
    }
    /* lag 2 of the same wave: all differences zero */
    diffs = 0;
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__pitch_amdf_lag(g_x, KMAX, 2u, 32u, 0u, &complete, &diffs));
    TEST_ASSERT_TRUE(complete);
}

static void test_mean_and_level_at_full_scale(void)
{
    uint32_t i;
    /* constant rails */
    for (i = 0; i < KMAX; i++) {
        g_x[i] = -32768;
    }
    TEST_ASSERT_EQUAL_INT32(-32768, ssda__pitch_mean(g_x, KMAX));
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__pitch_level(g_x, KMAX, -32768));
    /* the largest level: every sample 65535 away from the given mean */
    TEST_ASSERT_EQUAL_UINT32(KMAX * 65535u, ssda__pitch_level(g_x, KMAX, 32767));
    for (i = 0; i < KMAX; i++) {
        g_x[i] = 32767;
    }
    TEST_ASSERT_EQUAL_INT32(32767, ssda__pitch_mean(g_x, KMAX));
    /* half and half: the mean floor((sum + K/2) / K) of -32768, 32767 is 0 */
    test_signal_square(g_x, KMAX, 2u, 0u, 32767, -32768);
    TEST_ASSERT_EQUAL_INT32(0, ssda__pitch_mean(g_x, KMAX));
    TEST_ASSERT_EQUAL_UINT32(KMAX / 2u * 32767u + KMAX / 2u * 32768u,
                             ssda__pitch_level(g_x, KMAX, 0));
    /* one odd sample: mean -32768 + round(65535 / K) */
    for (i = 0; i < KMAX; i++) {
        g_x[i] = -32768;
    }
    g_x[17] = 32767;
    TEST_ASSERT_EQUAL_INT32(-32768 + (65535 + (int32_t)KMAX / 2) / (int32_t)KMAX,
                            ssda__pitch_mean(g_x, KMAX));
}

/* Analyse one full-scale frame and compare with the int64 reference. */
static void check_frame(const ssda_pitch_config_t *cfg, const int16_t *x, uint32_t expect_lag)
{
    ssda_pitch_info_t info;
    test_pitch_ref_cfg_t rc;
    test_pitch_ref_t r;
    ssda_pitch_estimate_t e;
    uint32_t pred;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(cfg, &info));
    rc = test_pitch_ref_cfg_of(&info);
    test_pitch_reference(x, &rc, &r);
    TEST_ASSERT_EQUAL_UINT32(expect_lag, r.lag);
    for (pred = 0u; pred <= info.lag_max; pred += info.lag_max / 3u) {
        ssda__pitch_analyze(&info, x, pred, &e);
        TEST_ASSERT_EQUAL_UINT32(r.lag, e.lag);
        TEST_ASSERT_EQUAL_UINT32(r.period_q16, e.period_q16);
        TEST_ASSERT_EQUAL_UINT32(r.f0_q16, e.f0_q16);
        TEST_ASSERT_EQUAL_UINT16(r.confidence_q15, e.confidence_q15);
        TEST_ASSERT_EQUAL(r.voiced, e.voiced);
    }
}

static void test_full_scale_squares_with_dc_offsets_at_max_frame(void)
{
    /* K = 8192 and square waves between the rails, centred and offset:
       d and s reach K * 65535 and about 2 K * 65535, cross products about
       2^58. A square of integer period P has n(P) = 0 exactly: a dip, an
       exact period (the V fit of a symmetric dip gives no offset). */
    static const int16_t highs[] = {32767, 32767, -1, 32767};
    static const int16_t lows[] = {-32768, 0, -32768, 32700};
    ssda_pitch_config_t cfg;
    uint32_t k, flags;
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = 48000u;
    cfg.f0_min_hz = 2000u;  /* lags 4..24: a small range, the largest K */
    cfg.f0_max_hz = 12000u;
    cfg.frame_len = (uint16_t)KMAX;
    cfg.silence_mad = 1u;
    for (flags = 0u; flags < 4u; flags++) {
        cfg.flags = (uint8_t)(SSDA_PITCH_NO_FILTER | (flags & 1u ? SSDA_PITCH_TRACK : 0u) |
                              (flags & 2u ? SSDA_PITCH_FULL : 0u));
        for (k = 0; k < 4u; k++) {
            test_signal_square(g_x, KMAX + 25u, 10u, k, highs[k], lows[k]);
            check_frame(&cfg, g_x, 10u);
        }
        /* period 2: n(lag) at odd lags is 1, the largest d of all */
        test_signal_square(g_x, KMAX + 25u, 2u, 0u, 32767, -32768);
        check_frame(&cfg, g_x, 4u);
    }
}

static void test_largest_geometry_counts_work_exactly(void)
{
    /* 48 kHz, f0 10..12000 Hz, K = 8192: lags 3..4801 (4799 of them) of
       8192 in full mode, 39 313 408 differences: the most one frame counts
       without an octave check (which needs a dip). */
    ssda_pitch_config_t cfg;
    ssda_pitch_info_t info;
    ssda_pitch_estimate_t e;
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = 48000u;
    cfg.f0_min_hz = 10u;
    cfg.f0_max_hz = 12000u;
    cfg.frame_len = (uint16_t)KMAX;
    cfg.flags = SSDA_PITCH_FULL | SSDA_PITCH_NO_FILTER;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(&cfg, &info));
    TEST_ASSERT_EQUAL_UINT32(SPAN_MAX, info.span);
    /* white-ish full-scale noise: no dip, so no octave check either */
    {
        uint32_t i, s = 12345u;
        for (i = 0; i < SPAN_MAX; i++) {
            s = s * 1103515245u + 12345u;
            g_x[i] = (int16_t)((s >> 16) & 1u ? 32767 : -32768);
        }
    }
    ssda__pitch_analyze(&info, g_x, 0u, &e);
    TEST_ASSERT_FALSE(e.dip);
    TEST_ASSERT_EQUAL_UINT32((4800u - 4u + 3u) * KMAX, e.diffs);
    /* the same frame with early exit: identical result, less work */
    {
        ssda_pitch_estimate_t e2;
        info.flags = SSDA_PITCH_NO_FILTER;
        ssda__pitch_analyze(&info, g_x, 0u, &e2);
        TEST_ASSERT_EQUAL_UINT32(e.lag, e2.lag);
        TEST_ASSERT_EQUAL_UINT32(e.period_q16, e2.period_q16);
        TEST_ASSERT_TRUE(e2.diffs < e.diffs);
    }
}

static void test_input_filter_between_the_rails(void)
{
    /* The fastest coefficient (cutoff rate / 4) with a rail-to-rail square
       at the Nyquist rate and full-scale steps: the Q15 states stay inside
       +-2^30 (a convex combination), the output inside int16, and it
       settles at the rails. */
    int32_t y1, y2;
    uint32_t a = ssda__pitch_lowpass_coef_q15(12000u, 48000u), i;
    int16_t out = 0;
    TEST_ASSERT_TRUE(a > 0u && a < 32768u);
    ssda__pitch_lowpass_prime(&y1, &y2, -32768);
    for (i = 0; i < 20000u; i++) {
        int16_t in = (int16_t)((i / 5000u) % 2u ? 32767 : ((i & 1u) ? 32767 : -32768));
        out = ssda__pitch_lowpass(&y1, &y2, a, in);
        TEST_ASSERT_TRUE(y1 >= -1073741824 && y1 <= 32767 * 32768);
        TEST_ASSERT_TRUE(y2 >= -1073741824 && y2 <= 32767 * 32768);
    }
    TEST_ASSERT_EQUAL_INT16(32767, out); /* last 5000 samples at +32767 */
    for (i = 0; i < 5000u; i++) {
        out = ssda__pitch_lowpass(&y1, &y2, a, -32768);
    }
    TEST_ASSERT_EQUAL_INT16(-32768, out);
    /* a constant passes unchanged from the first sample (primed states) */
    ssda__pitch_lowpass_prime(&y1, &y2, 12345);
    TEST_ASSERT_EQUAL_INT16(12345, ssda__pitch_lowpass(&y1, &y2, a, 12345));
}

static void test_interpolation_and_f0_at_their_extremes(void)
{
    /* n values at the ends of Q20: numerator 65536 * 2^20 = 2^36 */
    TEST_ASSERT_EQUAL_INT32(32768, ssda__pitch_interp_q16(1u << 20, 0u, 0u, false));
    TEST_ASSERT_EQUAL_INT32(-32768, ssda__pitch_interp_q16(0u, 0u, 1u << 20, false));
    TEST_ASSERT_EQUAL_INT32(32768, ssda__pitch_interp_q16(1u << 20, 0u, 0u, true));
    TEST_ASSERT_EQUAL_INT32(0, ssda__pitch_interp_q16(1u << 20, 1u << 20, 1u << 20, false));
    /* halfway rounding away from zero: 65536 * 1 / 4 -> 16384, and
       65536 * 1 / 3 = 21845.33 -> 21845 */
    TEST_ASSERT_EQUAL_INT32(16384, ssda__pitch_interp_q16(3u, 1u, 2u, false)); /* (3-2)/(2*2) */
    TEST_ASSERT_EQUAL_INT32(-16384, ssda__pitch_interp_q16(2u, 1u, 3u, false));
    /* f0 from the shortest period (lag 4 - 1/2 at 48 kHz) and the longest
       (lag 4800 + 1/2 at 48 kHz): rate << 32 < 2^48 */
    TEST_ASSERT_EQUAL_UINT32((uint32_t)((48000ull * 65536u * 2u + 3u) / 7u),
                             ssda__pitch_f0_q16(48000u, 7u * 32768u));
    TEST_ASSERT_EQUAL_UINT32((uint32_t)(((48000ull << 32) + 9601u * 32768u / 2u) / (9601u * 32768u)),
                             ssda__pitch_f0_q16(48000u, 9601u * 32768u));
    TEST_ASSERT_EQUAL_UINT32(1u << 20, ssda__pitch_norm_q20(8192u * 65535u, 8192u * 65535u));
}

static void test_full_scale_stream_end_to_end(void)
{
    /* The whole path (filter, stream buffer, analysis) on a rail-to-rail
       square of period 40 at 8 kHz (200 Hz) with DC offsets. */
    static const int16_t highs[] = {32767, 32767, -1};
    static const int16_t lows[] = {-32768, 0, -32768};
    static int16_t buf[SSDA_PITCH_BUFFER_SIZE(8000u, 0u, 0u) / 2u];
    uint32_t k;
    for (k = 0; k < 3u; k++) {
        ssda_pitch_config_t cfg;
        ssda_pitch_t p;
        size_t used = 0, took;
        uint32_t frames = 0;
        memset(&cfg, 0, sizeof cfg);
        cfg.sample_rate_hz = 8000u;
        cfg.flags = SSDA_PITCH_TRACK;
        test_signal_square(g_x, 4000u, 40u, 0u, highs[k], lows[k]);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &cfg, buf, sizeof buf));
        while (used < 4000u) {
            ssda_pitch_estimate_t e;
            int r = ssda_pitch_push(&p, g_x + used, 4000u - used, &took, &e);
            used += took;
            if (r == 1) {
                frames++;
                TEST_ASSERT_TRUE(e.voiced);
                TEST_ASSERT_EQUAL_UINT32(40u, e.lag);
                /* 200 Hz within 1 % (the filtered edges make the dip
                   slightly asymmetric inside a finite window) */
                TEST_ASSERT_UINT32_WITHIN(200u * 65536u / 100u, 200u * 65536u, e.f0_q16);
            }
        }
        TEST_ASSERT_TRUE(frames > 10u);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_amdf_term_at_its_worst_case);
    RUN_TEST(test_mean_and_level_at_full_scale);
    RUN_TEST(test_full_scale_squares_with_dc_offsets_at_max_frame);
    RUN_TEST(test_largest_geometry_counts_work_exactly);
    RUN_TEST(test_input_filter_between_the_rails);
    RUN_TEST(test_interpolation_and_f0_at_their_extremes);
    RUN_TEST(test_full_scale_stream_end_to_end);
    return UNITY_END();
}
