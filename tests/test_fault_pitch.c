/*
 * test_fault_pitch.c - the pitch stream cut at every place: a short signal
 * pushed in two pieces split at every sample (empty pieces included) and
 * in constant chunks of every size from 1 to its length gives, each time,
 * the estimates of the one-go push (every field), none lost and none added
 * (the count the hop and span give, every sample consumed). Configs: the
 * input filter on, off with prediction, and a hop beyond the span (samples
 * skipped between frames, across piece boundaries). test_pitch_stream.c
 * covers long signals under a few patterns; this covers every cut.
 */
#include <string.h>

#include "unity.h"
#include "ssda/pitch.h"

void setUp(void) {}
void tearDown(void) {}

#define SIG_N 300u
#define EST_MAX 64u
#define RATE 8000u

static int16_t g_sig[SIG_N];
static int16_t g_buf[256];
static ssda_pitch_estimate_t g_ref[EST_MAX], g_got[EST_MAX];

/* A voiced stretch (period 23 samples, two harmonics, integer arithmetic),
   a silent gap, then a lower voiced stretch (period 31) with a ramp. */
static void make_signal(void)
{
    uint32_t i;
    for (i = 0; i < SIG_N; i++) {
        int32_t v;
        if (i < 140u) {
            int32_t p = (int32_t)(i % 23u);
            v = (p < 12 ? p * 1800 : (23 - p) * 1800) - 10000 + ((int32_t)(i % 7u) - 3) * 400;
        } else if (i < 180u) {
            v = 0;
        } else {
            int32_t p = (int32_t)(i % 31u);
            v = (p * 2000 - 31000) / 2 + (int32_t)i * 20;
        }
        g_sig[i] = (int16_t)v;
    }
}

/* Push x[0..n) as pieces [0, cut[0]), [cut[0], cut[1]), ... up to n; one
   call per piece until it is consumed. Returns the estimates. */
static uint32_t push_cuts(const ssda_pitch_config_t *cfg, const uint32_t *cuts, uint32_t ncuts,
                          ssda_pitch_estimate_t *out)
{
    ssda_pitch_t p;
    uint32_t start = 0, count = 0, k, total = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, cfg, g_buf, sizeof g_buf));
    for (k = 0; k <= ncuts; k++) {
        uint32_t end = k < ncuts ? cuts[k] : SIG_N, given = 0;
        do {
            size_t took = 0xFFFFu;
            int r = ssda_pitch_push(&p, g_sig + start + given, end - start - given, &took,
                                    &out[count]);
            TEST_ASSERT_TRUE(r == 0 || r == 1);
            TEST_ASSERT_TRUE(took <= end - start - given);
            given += (uint32_t)took;
            total += (uint32_t)took;
            if (r == 1) {
                count++;
                TEST_ASSERT_TRUE(count < EST_MAX);
            } else {
                TEST_ASSERT_EQUAL_UINT32(end - start, given); /* 0: everything taken */
            }
        } while (given < end - start);
        start = end;
    }
    TEST_ASSERT_EQUAL_UINT32(SIG_N, total);
    return count;
}

static void assert_same(const ssda_pitch_estimate_t *a, const ssda_pitch_estimate_t *b, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        TEST_ASSERT_EQUAL_UINT32(a[i].frame, b[i].frame);
        TEST_ASSERT_EQUAL_UINT32(a[i].center, b[i].center);
        TEST_ASSERT_EQUAL_UINT32(a[i].lag, b[i].lag);
        TEST_ASSERT_EQUAL_UINT32(a[i].period_q16, b[i].period_q16);
        TEST_ASSERT_EQUAL_UINT32(a[i].f0_q16, b[i].f0_q16);
        TEST_ASSERT_EQUAL_UINT32(a[i].diffs, b[i].diffs);
        TEST_ASSERT_EQUAL_UINT16(a[i].confidence_q15, b[i].confidence_q15);
        TEST_ASSERT_EQUAL(a[i].voiced, b[i].voiced);
        TEST_ASSERT_EQUAL(a[i].dip, b[i].dip);
        TEST_ASSERT_EQUAL(a[i].silent, b[i].silent);
    }
}

static void every_cut(const ssda_pitch_config_t *cfg)
{
    static uint32_t cuts[SIG_N];
    ssda_pitch_info_t info;
    ssda_pitch_t p;
    uint32_t n_ref, n, s, c, k, voiced = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_init(&p, cfg, g_buf, sizeof g_buf));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_pitch_get_info(&p, &info));
    n_ref = push_cuts(cfg, NULL, 0u, g_ref);
    /* none lost, none added: frame f covers [f hop, f hop + span) */
    TEST_ASSERT_EQUAL_UINT32((SIG_N - info.span) / info.hop + 1u, n_ref);
    for (k = 0; k < n_ref; k++) {
        TEST_ASSERT_EQUAL_UINT32(k, g_ref[k].frame);
        voiced += g_ref[k].voiced ? 1u : 0u;
    }
    TEST_ASSERT_TRUE(2u * voiced > n_ref); /* the signal exercises the search */
    for (s = 0; s <= SIG_N; s++) { /* two pieces, split at every sample */
        n = push_cuts(cfg, &s, 1u, g_got);
        TEST_ASSERT_EQUAL_UINT32(n_ref, n);
        assert_same(g_ref, g_got, n);
    }
    for (c = 1; c <= SIG_N; c++) { /* constant chunks of every size */
        uint32_t m = 0;
        for (s = c; s < SIG_N; s += c) {
            cuts[m++] = s;
        }
        n = push_cuts(cfg, cuts, m, g_got);
        TEST_ASSERT_EQUAL_UINT32(n_ref, n);
        assert_same(g_ref, g_got, n);
    }
}

static ssda_pitch_config_t config(uint16_t hop, uint8_t flags)
{
    ssda_pitch_config_t c;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = RATE;
    c.f0_min_hz = 200;  /* lag_max 40, K 40: span 81 samples */
    c.f0_max_hz = 1000; /* lag_min 8 */
    c.hop = hop;
    c.chunk = 8;
    c.flags = flags;
    return c;
}

static void test_filtered_stream_every_cut(void)
{
    ssda_pitch_config_t c = config(9, 0u);
    make_signal();
    every_cut(&c);
}

static void test_unfiltered_tracking_stream_every_cut(void)
{
    ssda_pitch_config_t c = config(7, SSDA_PITCH_NO_FILTER | SSDA_PITCH_TRACK);
    make_signal();
    every_cut(&c);
}

static void test_hop_beyond_the_span_every_cut(void)
{
    ssda_pitch_config_t c = config(97, 0u); /* 16 samples skipped after each frame */
    make_signal();
    every_cut(&c);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_filtered_stream_every_cut);
    RUN_TEST(test_unfiltered_tracking_stream_every_cut);
    RUN_TEST(test_hop_beyond_the_span_every_cut);
    return UNITY_END();
}
