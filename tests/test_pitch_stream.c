/*
 * test_pitch_stream.c - the stream: the same estimates for any push
 * pattern, frames at the documented sample positions (also when the hop
 * exceeds the span), estimate numbering and centre times, reset; the
 * frame-at-a-time entry's refusals.
 */
#include <string.h>

#include "unity.h"
#include "ssda/pitch.h"
#include "pitch_internal.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define SIG_N 12000u
#define EST_MAX 300u

static int16_t g_sig[SIG_N];
static int16_t g_buf[2048];
static ssda_pitch_estimate_t g_ref[EST_MAX], g_got[EST_MAX];

/* Push x in pieces whose sizes come from `sizes` (cycled; 0 allowed). */
static uint32_t push_pattern(const ssda_pitch_config_t *cfg, const int16_t *x, uint32_t n,
                             const uint32_t *sizes, uint32_t nsizes, ssda_pitch_estimate_t *out)
{
    ssda_pitch_t p;
    uint32_t used = 0, count = 0, k = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, cfg, g_buf, sizeof g_buf));
    while (used < n) {
        uint32_t piece = sizes[k++ % nsizes], given;
        if (piece > n - used) {
            piece = n - used;
        }
        given = 0;
        do { /* a piece may hold several estimates: call until it is used up */
            size_t took = 999999u;
            int r = ssda_pitch_push(&p, x + used + given, piece - given, &took, &out[count]);
            TEST_ASSERT_TRUE(r == 0 || r == 1);
            TEST_ASSERT_TRUE(took <= piece - given);
            if (r == 0) {
                TEST_ASSERT_EQUAL_UINT32(piece - given, (uint32_t)took);
            }
            given += (uint32_t)took;
            if (r == 1) {
                count++;
                TEST_ASSERT_TRUE(count < EST_MAX);
            }
        } while (given < piece);
        used += piece;
    }
    return count;
}

static void make_signal(uint32_t rate)
{
    test_voice_t v;
    test_rng_t r;
    test_voice_vowel_a(&v, 165.0, 9000.0);
    v.vibrato_hz = 5.0;
    v.vibrato_depth = 0.03;
    test_signal_voice(g_sig, SIG_N, 0u, rate, &v);
    test_rng_seed(&r, 3u);
    test_signal_add_noise(g_sig, SIG_N, 25.0, &r);
    memset(g_sig + 5000, 0, 1500u * sizeof g_sig[0]); /* a silent gap */
}

static void test_any_push_pattern_gives_the_same_estimates(void)
{
    static const uint32_t whole[] = {SIG_N};
    static const uint32_t ones[] = {1u};
    static const uint32_t sevens[] = {7u};
    static const uint32_t mixed[] = {0u, 1u, 640u, 3u, 0u, 2000u, 129u, 64u};
    static const uint8_t flags[] = {0u, SSDA_PITCH_TRACK, SSDA_PITCH_NO_FILTER};
    uint32_t fi, n_ref, n, i;
    uint32_t rnd[64];
    test_rng_t r;
    test_rng_seed(&r, 17u);
    for (i = 0; i < 64u; i++) {
        rnd[i] = test_rng_range(&r, 0u, 700u);
    }
    make_signal(16000u);
    for (fi = 0; fi < sizeof flags; fi++) {
        ssda_pitch_config_t cfg;
        memset(&cfg, 0, sizeof cfg);
        cfg.sample_rate_hz = 16000u;
        cfg.hop = 97u;
        cfg.flags = flags[fi];
        n_ref = push_pattern(&cfg, g_sig, SIG_N, whole, 1u, g_ref);
        TEST_ASSERT_TRUE(n_ref > 50u);
        n = push_pattern(&cfg, g_sig, SIG_N, ones, 1u, g_got);
        TEST_ASSERT_EQUAL_UINT32(n_ref, n);
        TEST_ASSERT_EQUAL_MEMORY(g_ref, g_got, n * sizeof g_ref[0]);
        n = push_pattern(&cfg, g_sig, SIG_N, sevens, 1u, g_got);
        TEST_ASSERT_EQUAL_UINT32(n_ref, n);
        TEST_ASSERT_EQUAL_MEMORY(g_ref, g_got, n * sizeof g_ref[0]);
        n = push_pattern(&cfg, g_sig, SIG_N, mixed, 8u, g_got);
        TEST_ASSERT_EQUAL_UINT32(n_ref, n);
        TEST_ASSERT_EQUAL_MEMORY(g_ref, g_got, n * sizeof g_ref[0]);
        n = push_pattern(&cfg, g_sig, SIG_N, rnd, 64u, g_got);
        TEST_ASSERT_EQUAL_UINT32(n_ref, n);
        TEST_ASSERT_EQUAL_MEMORY(g_ref, g_got, n * sizeof g_ref[0]);
    }
}

/* Frames sit at f * hop, including hop > span (samples skipped between
   frames); each estimate equals the frame analysis of its own slice. */
static void check_positions(uint32_t hop, uint32_t len)
{
    static const uint32_t pieces[] = {333u};
    ssda_pitch_config_t cfg;
    ssda_pitch_info_t info;
    uint32_t n, f;
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = 16000u;
    cfg.f0_min_hz = 100u;
    cfg.hop = (uint16_t)hop;
    cfg.flags = SSDA_PITCH_NO_FILTER;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__pitch_resolve(&cfg, &info));
    n = push_pattern(&cfg, g_sig, len, pieces, 1u, g_got);
    TEST_ASSERT_EQUAL_UINT32((len - info.span) / hop + 1u, n);
    for (f = 0; f < n; f++) {
        ssda_pitch_estimate_t e;
        ssda__pitch_analyze(&info, g_sig + f * hop, 0u, &e);
        TEST_ASSERT_EQUAL_UINT32(f, g_got[f].frame);
        TEST_ASSERT_EQUAL_UINT32(e.period_q16, g_got[f].period_q16);
        TEST_ASSERT_EQUAL(e.voiced, g_got[f].voiced);
        TEST_ASSERT_EQUAL(e.silent, g_got[f].silent);
        if (e.silent) {
            TEST_ASSERT_EQUAL_UINT32(f * hop + info.span / 2u, g_got[f].center);
        } else {
            TEST_ASSERT_EQUAL_UINT32(f * hop + (info.frame_len + e.lag) / 2u, g_got[f].center);
        }
    }
}

static void test_frames_start_every_hop_even_beyond_the_span(void)
{
    make_signal(16000u);
    check_positions(1u, 321u + 250u); /* every sample (span 321) */
    check_positions(160u, SIG_N);
    check_positions(321u, SIG_N);     /* = span: back to back */
    check_positions(1000u, SIG_N);    /* > span: samples skipped between frames */
}

static void test_push_returns_as_soon_as_an_estimate_is_ready(void)
{
    ssda_pitch_config_t cfg;
    ssda_pitch_info_t info;
    ssda_pitch_t p;
    ssda_pitch_estimate_t e;
    size_t took;
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = 8000u;
    cfg.hop = 50u;
    make_signal(8000u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &cfg, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    /* the first estimate needs span samples, each later one hop more */
    TEST_ASSERT_EQUAL_INT(1, ssda_pitch_push(&p, g_sig, 5000u, &took, &e));
    TEST_ASSERT_EQUAL_UINT32(info.span, (uint32_t)took);
    TEST_ASSERT_EQUAL_INT(1, ssda_pitch_push(&p, g_sig + took, 5000u, &took, &e));
    TEST_ASSERT_EQUAL_UINT32(50u, (uint32_t)took);
    TEST_ASSERT_EQUAL_UINT32(1u, e.frame);
    TEST_ASSERT_EQUAL_INT(0, ssda_pitch_push(&p, g_sig, 49u, &took, &e));
    TEST_ASSERT_EQUAL_UINT32(49u, (uint32_t)took);
}

static void test_reset_starts_over(void)
{
    static const uint32_t pieces[] = {1000u};
    ssda_pitch_config_t cfg;
    ssda_pitch_t p;
    ssda_pitch_estimate_t e;
    size_t took, used = 0;
    uint32_t n, count = 0;
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = 16000u;
    cfg.hop = 200u;
    cfg.flags = SSDA_PITCH_TRACK;
    make_signal(16000u);
    n = push_pattern(&cfg, g_sig, 4000u, pieces, 1u, g_ref);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &cfg, g_buf, sizeof g_buf));
    /* feed unrelated samples, then reset: the state (buffer, filter,
       prediction, numbering) must not leak into the new stream */
    TEST_ASSERT_EQUAL_INT(1, ssda_pitch_push(&p, g_sig + 7000, 3000u, &took, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_reset(&p));
    while (used < 4000u) {
        int r = ssda_pitch_push(&p, g_sig + used, 4000u - used, &took, &g_got[count]);
        used += took;
        count += (r == 1) ? 1u : 0u;
    }
    TEST_ASSERT_EQUAL_UINT32(n, count);
    TEST_ASSERT_EQUAL_MEMORY(g_ref, g_got, n * sizeof g_ref[0]);
}

/* ssda_pitch_frame's refusals change nothing: the estimate stays poisoned
   and the stream's numbering is not advanced. */
static void test_frame_entry_refusals_change_nothing(void)
{
    ssda_pitch_config_t cfg;
    ssda_pitch_t p, blank;
    ssda_pitch_estimate_t e, poison;
    memset(&cfg, 0, sizeof cfg);
    memset(&blank, 0, sizeof blank);
    memset(&poison, 0xA5, sizeof poison);
    cfg.sample_rate_hz = 16000u;
    make_signal(16000u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &cfg, g_buf, sizeof g_buf));
    e = poison;
    /* the low-pass runs over the stream: a filtered stream is refused */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_pitch_frame(&p, g_sig, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_frame(NULL, g_sig, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_frame(&p, NULL, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_frame(&p, g_sig, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_pitch_frame(&blank, g_sig, &e));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &e, sizeof e);
    cfg.flags = SSDA_PITCH_NO_FILTER;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, &cfg, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_pitch_frame(&p, NULL, &e));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_frame(&p, g_sig, &e));
    TEST_ASSERT_EQUAL_UINT32(0u, e.frame); /* the refusal did not count a frame */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_frame(&p, g_sig + 80, &e));
    TEST_ASSERT_EQUAL_UINT32(1u, e.frame);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_frame_entry_refusals_change_nothing);
    RUN_TEST(test_any_push_pattern_gives_the_same_estimates);
    RUN_TEST(test_frames_start_every_hop_even_beyond_the_span);
    RUN_TEST(test_push_returns_as_soon_as_an_estimate_is_ready);
    RUN_TEST(test_reset_starts_over);
    return UNITY_END();
}
