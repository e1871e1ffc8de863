/*
 * pitch_min.c - the pitch in its minimal configuration (test pitch_min):
 * the library's sources compiled with every SSDA_CFG_NO_PITCH_* switch
 * (no low-pass, tracking, full search, parabola or push intake), as the
 * minimal core of tools/budget.sh. Its frame-at-a-time entry must give the
 * brute-force reference's estimate on every frame (tests/support/
 * test_pitch_ref.c, written from pitch.h alone), with early exit doing
 * less work than the plain AMDF, and everything left out must be refused
 * with its outputs untouched. Exit 0 on success.
 * Built twice: pitch_min (the octave and below-range checks compiled in;
 * the reduced definitions still accepted and checked) and pitch_min_reduced
 * (SSDA_CFG_NO_PITCH_OCTAVE and SSDA_CFG_NO_PITCH_BELOW_RANGE too: only the
 * reduced definition is accepted).
 */
#include <stdio.h>
#include <string.h>

#include "ssda/pitch.h"
#include "test_pitch_ref.h"
#include "test_signal.h"

#if !defined(SSDA_CFG_NO_PITCH_PUSH) || !defined(SSDA_CFG_NO_PITCH_FILTER) || \
    !defined(SSDA_CFG_NO_PITCH_TRACK) || !defined(SSDA_CFG_NO_PITCH_FULL) ||   \
    !defined(SSDA_CFG_NO_PITCH_PARABOLIC)
#error "pitch_min must be built with every SSDA_CFG_NO_PITCH_* switch"
#endif

#if defined(SSDA_CFG_NO_PITCH_OCTAVE) != defined(SSDA_CFG_NO_PITCH_BELOW_RANGE)
#error "pitch_min_reduced leaves out both checks"
#endif
#ifdef SSDA_CFG_NO_PITCH_OCTAVE
#define REDUCED (SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE) /* required */
#else
#define REDUCED 0u
#endif

#define SIG_N 20000u

static int16_t g_sig[SIG_N];
static unsigned g_failed;

static void check(int ok, const char *what)
{
    if (!ok) {
        g_failed++;
        printf("FAILED %s\n", what);
    }
}

/* A vowel with vibrato and noise, a silent gap, then noise alone (the
   global-minimum fallback). */
static void make_signal(uint32_t rate)
{
    test_voice_t v;
    test_rng_t r;
    test_voice_vowel_a(&v, 180.0, 9000.0);
    v.vibrato_hz = 5.0;
    v.vibrato_depth = 0.04;
    test_signal_voice(g_sig, SIG_N, 0u, rate, &v);
    test_rng_seed(&r, 7u);
    test_signal_add_noise(g_sig, SIG_N, 40.0, &r);
    memset(g_sig + 9000, 0, 2000u * sizeof g_sig[0]);
    test_signal_add_noise(g_sig + 15000, 5000u, 3000.0, &r);
}

/* Every frame of cfg over the signal against the reference. */
static void compare(const ssda_pitch_config_t *cfg, const char *name)
{
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    ssda_pitch_estimate_t e;
    test_pitch_ref_cfg_t rc;
    test_pitch_ref_t r;
    uint32_t f, bad = 0u, voiced = 0u, frames;
    uint64_t diffs = 0u, plain = 0u;
    if (ssda_pitch_init(&p, cfg, NULL, 0u) != SSDA_OK ||
        ssda_pitch_get_info(&p, &info) != SSDA_OK) {
        check(0, name);
        return;
    }
    rc = test_pitch_ref_cfg_of(&info);
    frames = (SIG_N - info.span) / info.hop + 1u;
    for (f = 0u; f < frames; f++) {
        const int16_t *x = g_sig + f * info.hop;
        if (ssda_pitch_frame(&p, x, &e) != SSDA_OK) {
            bad++;
            continue;
        }
        test_pitch_reference(x, &rc, &r);
        if (e.frame != f || e.lag != r.lag || e.period_q16 != r.period_q16 ||
            e.f0_q16 != r.f0_q16 || e.confidence_q15 != r.confidence_q15 ||
            e.voiced != r.voiced || e.dip != r.dip || e.silent != r.silent ||
            e.center != f * info.hop + (r.silent ? info.span / 2u : (info.frame_len + r.lag) / 2u)) {
            bad++;
        }
        voiced += e.voiced ? 1u : 0u;
        diffs += e.diffs;
        plain += r.silent ? 0u : info.full_diffs;
    }
    if (bad != 0u || voiced == 0u || diffs >= plain) {
        printf("%s: %u of %u frames differ from the reference, %u voiced, "
               "%llu differences (plain AMDF %llu)\n", name, bad, frames, voiced,
               (unsigned long long)diffs, (unsigned long long)plain);
        check(0, name);
    }
}

static void check_refusals(void)
{
    static const uint8_t left_out[] = {REDUCED, SSDA_PITCH_NO_FILTER | REDUCED | SSDA_PITCH_TRACK,
                                       SSDA_PITCH_NO_FILTER | REDUCED | SSDA_PITCH_FULL,
                                       SSDA_PITCH_NO_FILTER | REDUCED | SSDA_PITCH_PARABOLIC
#ifdef SSDA_CFG_NO_PITCH_OCTAVE
                                       , /* the full definition, or half of it */
                                       SSDA_PITCH_NO_FILTER,
                                       SSDA_PITCH_NO_FILTER | SSDA_PITCH_NO_OCTAVE,
                                       SSDA_PITCH_NO_FILTER | SSDA_PITCH_NO_BELOW_RANGE
#endif
    };
    ssda_pitch_config_t cfg;
    ssda_pitch_t p;
    ssda_pitch_estimate_t e, poison;
    size_t bytes = 12345u, used = 777u;
    uint32_t i;
    memset(&cfg, 0, sizeof cfg);
    memset(&poison, 0xA5, sizeof poison);
    cfg.sample_rate_hz = 16000u;
    for (i = 0u; i < sizeof left_out; i++) {
        cfg.flags = left_out[i];
        check(ssda_pitch_init(&p, &cfg, NULL, 0u) == SSDA_ERR_UNSUPPORTED,
              "a left-out option (the low-pass by default) is refused");
    }
    cfg.flags = SSDA_PITCH_NO_FILTER | REDUCED;
    check(ssda_pitch_buffer_size(&cfg, &bytes) == SSDA_ERR_UNSUPPORTED && bytes == 12345u,
          "no buffer size without the push intake");
    check(ssda_pitch_init(&p, &cfg, NULL, 0u) == SSDA_OK, "init needs no buffer");
    e = poison;
    check(ssda_pitch_push(&p, g_sig, 100u, &used, &e) == SSDA_ERR_UNSUPPORTED && used == 777u &&
              memcmp(&e, &poison, sizeof e) == 0,
          "push is refused, nothing written");
    check(ssda_pitch_init(NULL, &cfg, NULL, 0u) == SSDA_ERR_NULL, "init: NULL state");
}

int main(void)
{
    ssda_pitch_config_t cfg;
    make_signal(16000u);
    check_refusals();
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = 16000u;
    cfg.flags = SSDA_PITCH_NO_FILTER | REDUCED;
    compare(&cfg, "16 kHz, defaults");
#ifndef SSDA_CFG_NO_PITCH_OCTAVE
    /* the reduced definitions, accepted by every build */
    cfg.flags = SSDA_PITCH_NO_FILTER | SSDA_PITCH_NO_OCTAVE;
    compare(&cfg, "16 kHz, defaults, no octave check");
    cfg.flags = SSDA_PITCH_NO_FILTER | SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE;
    compare(&cfg, "16 kHz, defaults, no octave or below-range check");
    cfg.flags = SSDA_PITCH_NO_FILTER;
#endif
    cfg.f0_min_hz = 70u;
    cfg.f0_max_hz = 400u;
    cfg.frame_len = 200u;
    cfg.hop = 150u;
    cfg.chunk = 7u;
    cfg.threshold_q15 = 12000u;
    cfg.voicing_q15 = 8000u;
    compare(&cfg, "16 kHz, 70..400 Hz, K 200, chunk 7");
    return g_failed == 0u ? 0 : 1;
}
