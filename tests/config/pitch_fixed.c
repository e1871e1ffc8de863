/*
 * pitch_fixed.c - a firmware whose pitch configuration is fixed when the
 * library compiles (SSDA_CFG_PITCH_FIXED, include/ssda/pitch.h), against
 * the full library given the same configuration at run time.
 *
 * Built in pairs from one set of settings (SSDA_CFG_PITCH_FIXED_*, given
 * with -D by tests/CMakeLists.txt): PITCH_FIXED_SIDE defined, the library's
 * pitch sources compiled with SSDA_CFG_PITCH_FIXED (and the pair's
 * SSDA_CFG_NO_PITCH_* switches); without it, the full library. Each side
 * writes the resolved parameters and every field of every estimate of many
 * random signals (voices, sines, squares, noise, silence, clipping; pushed
 * in random blocks, or given whole to ssda_pitch_frame) to the file
 * argv[1]; test pitch_fixed_<name> runs both and compares the files
 * (compare_runs.cmake). The fixed side also checks
 *   - each estimate against the brute-force reference (tests/support/
 *     test_pitch_ref.c) when the configuration has no low-pass;
 *   - the configurations it accepts: the fixed one, SSDA_PITCH_CONFIG_FIXED,
 *     with each default written as 0 or as its value; and those it refuses:
 *     any field changed gives SSDA_ERR_UNSUPPORTED with the state and the
 *     size untouched, also a 0 in a field whose fixed value is not what 0
 *     stands for;
 *   - the buffer checked as in the full build (SSDA_ERR_BUFFER, SSDA_ERR_NULL),
 *     and ssda_pitch_frame refusing a stream with the low-pass, from a
 *     zeroed state (the state's own copy of the parameters is never read:
 *     the main run also starts from a poisoned state).
 * Exit 0 on success.
 */
#include <stdio.h>
#include <string.h>

#include "ssda/pitch.h"
#include "test_pitch_ref.h"
#include "test_signal.h"

/* The settings as ssda_pitch_config_t fields (0: the default); pitch.h
   defines the same defaults on the fixed side. */
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

#if defined(PITCH_FIXED_SIDE) != defined(SSDA_CFG_PITCH_FIXED)
#error "the fixed side is built with SSDA_CFG_PITCH_FIXED, the full side without"
#endif

#ifdef PITCH_FIXED_SIGNALS
#define SIGNALS PITCH_FIXED_SIGNALS
#else
#define SIGNALS 48u
#endif
#define SIG_MAX 12000u

static int16_t g_sig[SIG_MAX];
static int16_t g_buf[8192u + 4800u + 1u];
static unsigned g_failed;

static void check(int ok, const char *what)
{
    if (!ok) {
        g_failed++;
        printf("FAILED %s\n", what);
    }
}

static ssda_pitch_config_t settings(void)
{
    ssda_pitch_config_t c;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = SSDA_CFG_PITCH_FIXED_RATE_HZ;
    c.f0_min_hz = (uint16_t)(SSDA_CFG_PITCH_FIXED_F0_MIN_HZ);
    c.f0_max_hz = (uint16_t)(SSDA_CFG_PITCH_FIXED_F0_MAX_HZ);
    c.frame_len = (uint16_t)(SSDA_CFG_PITCH_FIXED_FRAME_LEN);
    c.hop = (uint16_t)(SSDA_CFG_PITCH_FIXED_HOP);
    c.threshold_q15 = (uint16_t)(SSDA_CFG_PITCH_FIXED_THRESHOLD_Q15);
    c.voicing_q15 = (uint16_t)(SSDA_CFG_PITCH_FIXED_VOICING_Q15);
    c.silence_mad = (uint16_t)(SSDA_CFG_PITCH_FIXED_SILENCE_MAD);
    c.chunk = (uint16_t)(SSDA_CFG_PITCH_FIXED_CHUNK);
    c.lowpass_hz = (uint16_t)(SSDA_CFG_PITCH_FIXED_LOWPASS_HZ);
    c.flags = (uint8_t)(SSDA_CFG_PITCH_FIXED_FLAGS);
    return c;
}

/* One random signal of n samples: a voice, sine or square in or around the
   f0 range, noise, or near silence, with noise, silent gaps and clipping. */
static uint32_t make_signal(test_rng_t *r, const ssda_pitch_config_t *c)
{
    const uint32_t n = test_rng_range(r, 3000u, SIG_MAX);
    const double lo = c->f0_min_hz != 0u ? c->f0_min_hz : SSDA_PITCH_DEFAULT_F0_MIN;
    const double hi = c->f0_max_hz != 0u ? c->f0_max_hz : SSDA_PITCH_DEFAULT_F0_MAX;
    /* f0 from 0.7 lo to 1.6 hi, log-uniform (exp of a uniform) */
    const double f0 = lo * 0.7 * test_exp(test_log(hi * 1.6 / (lo * 0.7)) *
                                          (double)test_rng_range(r, 0u, 1000u) / 1000.0);
    const double amp = 200.0 + (double)test_rng_range(r, 0u, 20000u);
    const uint32_t kind = test_rng_range(r, 0u, 5u);
    test_voice_t v;
    if (kind <= 2u) {
        if (kind == 0u) {
            test_voice_vowel_a(&v, f0, amp);
        } else if (kind == 1u) {
            test_voice_vowel_i(&v, f0, amp);
        } else {
            test_voice_sine(&v, f0, amp);
        }
        v.vibrato_hz = (double)test_rng_range(r, 0u, 7u);
        v.vibrato_depth = (double)test_rng_range(r, 0u, 6u) / 100.0;
        test_signal_voice(g_sig, n, test_rng_range(r, 0u, 1000u), c->sample_rate_hz, &v);
    } else if (kind == 3u) {
        const uint32_t period = (uint32_t)((double)c->sample_rate_hz / f0) + 2u;
        test_signal_square(g_sig, n, period, test_rng_range(r, 0u, period),
                           (int16_t)amp, (int16_t)-(int32_t)test_rng_range(r, 0u, 30000u));
    } else if (kind == 4u) {
        test_signal_noise(g_sig, n, amp / 4.0, r);
    } else {
        test_signal_noise(g_sig, n, (double)test_rng_range(r, 0u, 8u), r);
    }
    if (kind <= 3u && test_rng_range(r, 0u, 1u) == 1u) {
        test_signal_add_noise(g_sig, n, (double)test_rng_range(r, 0u, 40u), r);
    }
    if (test_rng_range(r, 0u, 3u) == 0u) { /* a silent gap */
        const uint32_t at = test_rng_range(r, 0u, n - 1000u);
        memset(g_sig + at, 0, test_rng_range(r, 100u, 1000u) * sizeof g_sig[0]);
    }
    if (test_rng_range(r, 0u, 5u) == 0u) {
        test_signal_gain_clip(g_sig, n, 4.0);
    }
    return n;
}

static void dump_info(FILE *out, const ssda_pitch_info_t *i)
{
    fprintf(out, "info %lu %lu %lu %lu %lu %lu %lu %lu %u %u %u %u %u %u\n",
            (unsigned long)i->sample_rate_hz, (unsigned long)i->lag_min,
            (unsigned long)i->lag_max, (unsigned long)i->frame_len, (unsigned long)i->hop,
            (unsigned long)i->span, (unsigned long)i->chunk, (unsigned long)i->full_diffs,
            (unsigned)i->threshold_q15, (unsigned)i->voicing_q15, (unsigned)i->silence_mad,
            (unsigned)i->lowpass_hz, (unsigned)i->lowpass_q15, (unsigned)i->flags);
}

static void dump_estimate(FILE *out, const ssda_pitch_estimate_t *e)
{
    fprintf(out, "%lu %lu %lu %lu %lu %lu %u %d %d %d\n", (unsigned long)e->frame,
            (unsigned long)e->center, (unsigned long)e->lag, (unsigned long)e->period_q16,
            (unsigned long)e->f0_q16, (unsigned long)e->diffs, (unsigned)e->confidence_q15,
            (int)e->voiced, (int)e->dip, (int)e->silent);
}

#ifdef PITCH_FIXED_SIDE
/* Without the low-pass, estimate e (of stream samples [frame hop, ...))
   is the brute-force reference's. */
static void check_reference(const ssda_pitch_info_t *info, const ssda_pitch_estimate_t *e)
{
    test_pitch_ref_cfg_t rc = test_pitch_ref_cfg_of(info);
    test_pitch_ref_t r;
    if (info->lowpass_q15 != 0u) {
        return;
    }
    test_pitch_reference(g_sig + e->frame * info->hop, &rc, &r);
    check(e->lag == r.lag && e->period_q16 == r.period_q16 && e->f0_q16 == r.f0_q16 &&
              e->confidence_q15 == r.confidence_q15 && e->voiced == r.voiced &&
              e->dip == r.dip && e->silent == r.silent,
          "an estimate equals the brute-force reference");
}
#else
#define check_reference(info, e) ((void)0)
#endif

/* Both sides take the same intake: ssda_pitch_frame alone when the fixed
   side has no push intake (PITCH_FIXED_BY_FRAME, given to both), else
   push in random blocks for odd signals and for a stream with the
   low-pass, ssda_pitch_frame for even ones. */
#if defined(SSDA_CFG_NO_PITCH_PUSH) && !defined(PITCH_FIXED_BY_FRAME)
#error "a fixed side without the push intake: PITCH_FIXED_BY_FRAME on both sides"
#endif

/* Every estimate of signal number s (n samples). r: the blocks' sizes. */
static void run_signal(FILE *out, ssda_pitch_t *p, const ssda_pitch_info_t *info, uint32_t s,
                       uint32_t n, test_rng_t *r)
{
    ssda_pitch_estimate_t e;
    check(ssda_pitch_reset(p) == SSDA_OK, "reset");
#ifndef PITCH_FIXED_BY_FRAME
    if ((s & 1u) == 1u || info->lowpass_q15 != 0u) {
        uint32_t used = 0u;
        while (used < n) {
            uint32_t block = test_rng_range(r, 1u, 700u);
            size_t took;
            int ret;
            if (block > n - used) {
                block = n - used;
            }
            ret = ssda_pitch_push(p, g_sig + used, block, &took, &e);
            check(ret == 0 || ret == 1, "push");
            if (ret < 0) {
                return;
            }
            used += (uint32_t)took;
            if (ret == 1) {
                dump_estimate(out, &e);
                check_reference(info, &e);
            }
        }
        return;
    }
#endif
    {
        uint32_t at;
        (void)s;
        (void)r;
        for (at = 0u; at + info->span <= n; at += info->hop) {
            check(ssda_pitch_frame(p, g_sig + at, &e) == SSDA_OK, "frame");
            dump_estimate(out, &e);
            check_reference(info, &e);
        }
    }
}

#ifdef PITCH_FIXED_SIDE
/* Whether init accepts c (and then gives the fixed parameters). */
static int accepts(const ssda_pitch_config_t *c, const ssda_pitch_info_t *want)
{
    ssda_pitch_t p;
    ssda_pitch_info_t got;
    return ssda_pitch_init(&p, c, g_buf, sizeof g_buf) == SSDA_OK &&
           ssda_pitch_get_info(&p, &got) == SSDA_OK && memcmp(&got, want, sizeof got) == 0;
}

/* Refused with SSDA_ERR_UNSUPPORTED, the state and the size untouched. */
static int refuses(const ssda_pitch_config_t *c)
{
    ssda_pitch_t p, poison;
    size_t bytes = 4321u;
    int ok;
    memset(&poison, 0x5A, sizeof poison);
    p = poison;
    ok = ssda_pitch_init(&p, c, g_buf, sizeof g_buf) == SSDA_ERR_UNSUPPORTED &&
         memcmp(&p, &poison, sizeof p) == 0;
    /* (a build without the push intake refuses every configuration here) */
    ok = ok && ssda_pitch_buffer_size(c, &bytes) == SSDA_ERR_UNSUPPORTED;
    return ok && bytes == 4321u;
}

/* A 0 stands for the field's default, which pitch.h defines from the
   other fields: where the fixed value is not that default, the 0 is
   another configuration, refused. */
static void check_zeros(const ssda_pitch_info_t *info)
{
    const ssda_pitch_config_t fixed = SSDA_PITCH_CONFIG_FIXED;
    const uint32_t rate = fixed.sample_rate_hz;
    const uint32_t f0_min = fixed.f0_min_hz != 0u ? fixed.f0_min_hz : SSDA_PITCH_DEFAULT_F0_MIN;
    const uint32_t f0_max = fixed.f0_max_hz != 0u ? fixed.f0_max_hz : SSDA_PITCH_DEFAULT_F0_MAX;
    const uint32_t k = SSDA_PITCH_FRAME_LEN(rate, fixed.f0_min_hz, fixed.frame_len);
    const uint32_t thr = fixed.threshold_q15 != 0u ? fixed.threshold_q15
                                                   : SSDA_PITCH_DEFAULT_THRESHOLD_Q15;
    uint32_t i;
    for (i = 0u; i < 9u; i++) {
        ssda_pitch_config_t c = fixed;
        int other;
        switch (i) {
        case 0u: other = f0_min != SSDA_PITCH_DEFAULT_F0_MIN; c.f0_min_hz = 0u; break;
        case 1u: other = f0_max != SSDA_PITCH_DEFAULT_F0_MAX; c.f0_max_hz = 0u; break;
        case 2u: other = k != SSDA_PITCH_FRAME_LEN(rate, fixed.f0_min_hz, 0u); c.frame_len = 0u; break;
        case 3u: other = info->hop != k / 4u; c.hop = 0u; break;
        case 4u: other = thr != SSDA_PITCH_DEFAULT_THRESHOLD_Q15; c.threshold_q15 = 0u; break;
        case 5u: other = info->voicing_q15 != thr; c.voicing_q15 = 0u; break;
        case 6u: other = info->silence_mad != SSDA_PITCH_DEFAULT_SILENCE_MAD; c.silence_mad = 0u; break;
        case 7u: other = info->chunk != (k < 32u ? k : 32u); c.chunk = 0u; break;
        default:
            other = fixed.lowpass_hz != 0u && fixed.lowpass_hz != f0_max;
            c.lowpass_hz = 0u;
            break;
        }
        if (other) {
            check(refuses(&c), "a 0 where the fixed value is not its default is refused");
        }
    }
}

/* ssda_pitch_init's other checks, as in the full build: the buffer (with
   the push intake), NULL, and ssda_pitch_frame on a stream with the
   low-pass, from a zeroed state. */
static void check_buffer(const ssda_pitch_info_t *info)
{
    const ssda_pitch_config_t fixed = SSDA_PITCH_CONFIG_FIXED;
    ssda_pitch_t p, poison;
    ssda_pitch_estimate_t e, e0;
    memset(&poison, 0x5A, sizeof poison);
#ifndef SSDA_CFG_NO_PITCH_PUSH
    p = poison;
    check(ssda_pitch_init(&p, &fixed, g_buf, SSDA_PITCH_BUFFER_SIZE_FIXED - 1u) ==
                  SSDA_ERR_BUFFER && memcmp(&p, &poison, sizeof p) == 0,
          "a buffer one byte short is SSDA_ERR_BUFFER, the state untouched");
    check(ssda_pitch_init(&p, &fixed, (uint8_t *)g_buf + 1, SSDA_PITCH_BUFFER_SIZE_FIXED) ==
                  SSDA_ERR_BUFFER && memcmp(&p, &poison, sizeof p) == 0,
          "a misaligned buffer is SSDA_ERR_BUFFER, the state untouched");
    check(ssda_pitch_init(&p, &fixed, NULL, SSDA_PITCH_BUFFER_SIZE_FIXED) == SSDA_ERR_NULL &&
              memcmp(&p, &poison, sizeof p) == 0,
          "no buffer is SSDA_ERR_NULL");
    check(ssda_pitch_init(&p, &fixed, g_buf, SSDA_PITCH_BUFFER_SIZE_FIXED) == SSDA_OK,
          "a buffer of SSDA_PITCH_BUFFER_SIZE_FIXED bytes is enough");
#else
    p = poison;
    check(ssda_pitch_init(&p, &fixed, NULL, 0u) == SSDA_OK, "no buffer without the push intake");
#endif
    memset(&p, 0, sizeof p);
    memset(g_sig, 0, sizeof g_sig);
    memset(&e, 0x5A, sizeof e);
    e0 = e;
    check(ssda_pitch_init(&p, &fixed, g_buf, sizeof g_buf) == SSDA_OK, "init from a zeroed state");
    if (info->lowpass_q15 != 0u) {
        check(ssda_pitch_frame(&p, g_sig, &e) == SSDA_ERR_ARG && memcmp(&e, &e0, sizeof e) == 0,
              "ssda_pitch_frame refuses a stream with the low-pass");
    } else {
        check(ssda_pitch_frame(&p, g_sig, &e) == SSDA_OK && e.silent && e.frame == 0u,
              "ssda_pitch_frame takes a stream without the low-pass");
    }
}

/* The configurations accepted and refused. */
static void check_acceptance(const ssda_pitch_info_t *info)
{
    const ssda_pitch_config_t fixed = SSDA_PITCH_CONFIG_FIXED;
    const ssda_pitch_config_t base = settings();
    /* each field resolved as pitch.h documents (the fixed values here) */
    const uint32_t f0_max = base.f0_max_hz != 0u ? base.f0_max_hz : SSDA_PITCH_DEFAULT_F0_MAX;
    const uint32_t threshold = info->threshold_q15;
    ssda_pitch_config_t c;
    ssda_pitch_t zeroed;
    uint32_t i;
    check(fixed.sample_rate_hz == base.sample_rate_hz && fixed.f0_min_hz == base.f0_min_hz &&
              fixed.f0_max_hz == base.f0_max_hz && fixed.frame_len == base.frame_len &&
              fixed.hop == base.hop && fixed.threshold_q15 == base.threshold_q15 &&
              fixed.voicing_q15 == base.voicing_q15 && fixed.silence_mad == base.silence_mad &&
              fixed.chunk == base.chunk && fixed.lowpass_hz == base.lowpass_hz &&
              fixed.flags == base.flags,
          "SSDA_PITCH_CONFIG_FIXED holds the settings");
    check(accepts(&fixed, info), "the fixed configuration is accepted");
#ifndef SSDA_CFG_NO_PITCH_PUSH
    {
        size_t bytes = 0u;
        check(ssda_pitch_buffer_size(&fixed, &bytes) == SSDA_OK &&
                  bytes == SSDA_PITCH_BUFFER_SIZE_FIXED && bytes == info->span * sizeof(int16_t),
              "its buffer size");
    }
#endif
    /* every default written out, then every field at its default as 0 */
    c = base;
    c.f0_min_hz = (uint16_t)(base.f0_min_hz != 0u ? base.f0_min_hz : SSDA_PITCH_DEFAULT_F0_MIN);
    c.f0_max_hz = (uint16_t)f0_max;
    c.frame_len = (uint16_t)info->frame_len;
    c.hop = (uint16_t)info->hop;
    c.threshold_q15 = (uint16_t)threshold;
    c.voicing_q15 = info->voicing_q15;
    c.silence_mad = info->silence_mad;
    c.chunk = (uint16_t)info->chunk;
    c.lowpass_hz = (uint16_t)(base.lowpass_hz != 0u ? base.lowpass_hz : f0_max);
    check(accepts(&c, info), "every default written out");
    {
        const uint32_t lag_max = info->lag_max;
        if (c.f0_min_hz == SSDA_PITCH_DEFAULT_F0_MIN) { c.f0_min_hz = 0u; }
        if (c.f0_max_hz == SSDA_PITCH_DEFAULT_F0_MAX) { c.f0_max_hz = 0u; }
        if (c.frame_len == (lag_max > 16u ? lag_max : 16u)) { c.frame_len = 0u; }
        if (c.hop == info->frame_len / 4u) { c.hop = 0u; }
        if (c.threshold_q15 == SSDA_PITCH_DEFAULT_THRESHOLD_Q15) { c.threshold_q15 = 0u; }
        if (c.voicing_q15 == threshold) { c.voicing_q15 = 0u; }
        if (c.silence_mad == SSDA_PITCH_DEFAULT_SILENCE_MAD) { c.silence_mad = 0u; }
        if (c.chunk == (info->frame_len < 32u ? info->frame_len : 32u)) { c.chunk = 0u; }
        if (c.lowpass_hz == f0_max) { c.lowpass_hz = 0u; }
        check(accepts(&c, info), "every default as 0");
    }
    /* any field changed is refused (by 1, or to 0 when that is not its default) */
    for (i = 0u; i < 11u; i++) {
        c = fixed;
        switch (i) {
        case 0u: c.sample_rate_hz += 1u; break;
        case 1u: c.f0_min_hz = (uint16_t)(c.f0_min_hz != 0u ? c.f0_min_hz + 1u : 51u); break;
        case 2u: c.f0_max_hz = (uint16_t)(c.f0_max_hz != 0u ? c.f0_max_hz - 1u : 999u); break;
        case 3u: c.frame_len = (uint16_t)(info->frame_len + 1u); break;
        case 4u: c.hop = (uint16_t)(info->hop + 1u); break;
        case 5u: c.threshold_q15 = (uint16_t)(threshold + 1u); break;
        case 6u: c.voicing_q15 = (uint16_t)(info->voicing_q15 - 1u); break;
        case 7u: c.silence_mad = (uint16_t)(info->silence_mad + 1u); break;
        case 8u: c.chunk = (uint16_t)(info->chunk - 1u); break;
        case 9u: c.lowpass_hz = (uint16_t)((c.lowpass_hz != 0u ? c.lowpass_hz : f0_max) - 1u); break;
        default: c.flags ^= SSDA_PITCH_TRACK; break;
        }
        check(refuses(&c), "a field changed is refused");
    }
    c = fixed;
    c.flags = 0xFFu; /* unknown flags: SSDA_ERR_ARG in the full build */
    check(refuses(&c), "unknown flags are refused");
    check_zeros(info);
    check_buffer(info);
    c = fixed;
    memset(&zeroed, 0, sizeof zeroed);
    check(ssda_pitch_init(&zeroed, NULL, g_buf, sizeof g_buf) == SSDA_ERR_NULL &&
              ssda_pitch_init(NULL, &c, g_buf, sizeof g_buf) == SSDA_ERR_NULL,
          "NULL is SSDA_ERR_NULL");
}
#endif

int main(int argc, char **argv)
{
    const ssda_pitch_config_t cfg = settings();
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    test_rng_t r, blocks;
    FILE *out;
    uint32_t s;
    if (argc != 2 || (out = fopen(argv[1], "w")) == NULL) {
        fprintf(stderr, "usage: pitch_fixed OUTPUT\n");
        return 2;
    }
    memset(&p, 0x5A, sizeof p); /* nothing of it read before init writes it */
    if (ssda_pitch_init(&p, &cfg, g_buf, sizeof g_buf) != SSDA_OK ||
        ssda_pitch_get_info(&p, &info) != SSDA_OK) {
        fprintf(stderr, "FAILED: the settings are refused\n");
        fclose(out);
        return 1;
    }
    dump_info(out, &info);
#ifdef PITCH_FIXED_SIDE
    check_acceptance(&info);
#endif
    test_rng_seed(&r, 20261126u);
    test_rng_seed(&blocks, 4242u);
    for (s = 0u; s < SIGNALS; s++) {
        const uint32_t n = make_signal(&r, &cfg);
        fprintf(out, "signal %lu %lu\n", (unsigned long)s, (unsigned long)n);
        run_signal(out, &p, &info, s, n, &blocks);
    }
    fclose(out);
    return g_failed == 0u ? 0 : 1;
}
