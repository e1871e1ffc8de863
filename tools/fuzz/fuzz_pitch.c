/*
 * fuzz_pitch.c - the pitch stream (include/ssda/pitch.h) with configs and
 * sample streams from the fuzzer's bytes.
 *   - init accepts exactly the configs the header allows (else the error
 *     class it names, state untouched); ssda_pitch_buffer_size equals
 *     SSDA_PITCH_BUFFER_SIZE, and one byte less is refused;
 *   - the stream pushed in one go and in fuzzed chunks (0 allowed) gives
 *     identical estimates; so does a reset and a second pass;
 *   - toggling SSDA_PITCH_FULL and SSDA_PITCH_TRACK changes only `diffs`;
 *   - every estimate equals the brute-force reference of the definition
 *     (tests/support/test_pitch_ref.c) on its frame's samples, filtered
 *     here by the header's input-filter formulas.
 */
#include <string.h>

#include "fuzz_input.h"
#include "ssda/pitch.h"
#include "test_pitch_ref.h"

#define MAX_SAMPLES 24000u
#define MAX_EST 64u
#define WORK_BUDGET 4000000u /* absolute differences per pass, roughly */

static int16_t g_sig[MAX_SAMPLES], g_filt[MAX_SAMPLES];
static int16_t g_buf[8192u + 4800u + 1u + 8u];
static ssda_pitch_estimate_t g_ref[MAX_EST], g_got[MAX_EST];

static uint32_t next_rand(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* Push n samples in pieces of sizes[k % nsizes]; at most MAX_EST estimates. */
static uint32_t run(ssda_pitch_t *p, const int16_t *x, uint32_t n, const uint32_t *sizes,
                    uint32_t nsizes, ssda_pitch_estimate_t *out)
{
    uint32_t used = 0, count = 0, k = 0;
    while (used < n && count < MAX_EST) {
        uint32_t piece = sizes[k++ % nsizes], given = 0;
        if (piece > n - used) {
            piece = n - used;
        }
        do {
            size_t took = 0x7777u;
            int r = ssda_pitch_push(p, piece ? x + used + given : NULL, piece - given, &took,
                                    &out[count]);
            FUZZ_CHECK(r == 0 || r == 1);
            FUZZ_CHECK(took <= piece - given);
            FUZZ_CHECK(r == 1 || took == piece - given);
            given += (uint32_t)took;
            if (r == 1) {
                FUZZ_CHECK(out[count].frame == count);
                if (++count == MAX_EST) {
                    break;
                }
            }
        } while (given < piece);
        used += given;
        if (given < piece) {
            break;
        }
    }
    return count;
}

static void same_estimate(const ssda_pitch_estimate_t *a, const ssda_pitch_estimate_t *b,
                          int with_diffs)
{
    FUZZ_CHECK(a->frame == b->frame && a->center == b->center && a->lag == b->lag);
    FUZZ_CHECK(a->period_q16 == b->period_q16 && a->f0_q16 == b->f0_q16);
    FUZZ_CHECK(a->confidence_q15 == b->confidence_q15 && a->voiced == b->voiced &&
               a->dip == b->dip && a->silent == b->silent);
    FUZZ_CHECK(!with_diffs || a->diffs == b->diffs);
}

/* The input filter as pitch.h writes it: two poles, y += trunc(a (32768 in
   - y) / 32768), output floor((y2 + 16384) / 32768), states primed with
   32768 * the first sample. */
static void filter(const int16_t *x, int16_t *y, uint32_t n, uint32_t a)
{
    int64_t y1 = (int64_t)x[0] * 32768, y2 = y1;
    uint32_t i;
    for (i = 0; i < n; i++) {
        int64_t v;
        y1 += (int64_t)a * ((int64_t)x[i] * 32768 - y1) / 32768;
        y2 += (int64_t)a * (y1 - y2) / 32768;
        v = y2 + 16384;
        v = v >= 0 ? v / 32768 : -((-v + 32767) / 32768);
        y[i] = (int16_t)v;
    }
}

static void read_config(fuzz_in_t *in, ssda_pitch_config_t *cfg)
{
    static const uint32_t rates[] = {8000u, 11025u, 16000u, 22050u, 44100u, 48000u};
    memset(cfg, 0, sizeof *cfg);
    cfg->sample_rate_hz = fuzz_u8(in) < 224u ? rates[fuzz_range(in, 0, 5)]
                                             : fuzz_range(in, 7000, 50000);
    cfg->f0_min_hz = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 5, 400));
    cfg->f0_max_hz = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 20, 13000));
    cfg->frame_len = (uint16_t)(fuzz_u8(in) & 1u ? 0u
                                : fuzz_one_in(in, 8) ? fuzz_u16(in) : fuzz_range(in, 10, 700));
    cfg->hop = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 1, 1500));
    cfg->threshold_q15 = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, 32768));
    cfg->voicing_q15 = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, 32768));
    cfg->silence_mad = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_u16(in) % 3000u);
    cfg->chunk = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 1, 800));
    cfg->lowpass_hz = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 1, 13000));
    cfg->flags = (uint8_t)(fuzz_one_in(in, 32) ? fuzz_u8(in) : fuzz_u8(in) & 63u);
}

/* Init accepts exactly the configs the header allows. Returns 1 with p
   initialised (*bytes of g_buf) for a valid config, else 0 (checked). */
static int check_init(const ssda_pitch_config_t *cfg, ssda_pitch_t *p, ssda_pitch_info_t *info,
                      size_t *bytes)
{
    uint32_t rate = cfg->sample_rate_hz;
    uint32_t f0min = cfg->f0_min_hz ? cfg->f0_min_hz : 50u;
    uint32_t f0max = cfg->f0_max_hz ? cfg->f0_max_hz : 1000u;
    uint32_t lagmax = (rate + f0min - 1u) / f0min, K, arg_bad, size_bad;
    ssda_pitch_t poison_p;
    int rc;
    /* validity by the header (ARG-class and SIZE-class rules) */
    arg_bad = rate < 8000u || rate > 48000u || f0min < 10u || f0max > rate / 4u ||
              f0min >= f0max || cfg->threshold_q15 > 32767u || cfg->voicing_q15 > 32767u ||
              cfg->lowpass_hz > rate / 4u || (cfg->flags & ~63u) != 0u;
    K = cfg->frame_len ? cfg->frame_len : (lagmax > 16u ? lagmax : 16u);
    size_bad = (cfg->frame_len != 0u && (cfg->frame_len < 16u || cfg->frame_len > 8192u)) ||
               cfg->chunk > K;
    memset(&poison_p, 0x6E, sizeof poison_p);
    *p = poison_p;
    *bytes = 0;
    rc = ssda_pitch_buffer_size(cfg, bytes);
    if (arg_bad || size_bad) {
        FUZZ_CHECK(rc == SSDA_ERR_ARG || rc == SSDA_ERR_SIZE);
        FUZZ_CHECK(!size_bad || arg_bad || rc == SSDA_ERR_SIZE);
        FUZZ_CHECK(!arg_bad || size_bad || rc == SSDA_ERR_ARG);
        FUZZ_CHECK(*bytes == 0u);
        FUZZ_CHECK(ssda_pitch_init(p, cfg, g_buf, sizeof g_buf) == rc);
        FUZZ_CHECK(memcmp(p, &poison_p, sizeof *p) == 0);
        return 0;
    }
    FUZZ_CHECK(rc == SSDA_OK &&
               *bytes == SSDA_PITCH_BUFFER_SIZE(rate, cfg->f0_min_hz, cfg->frame_len) &&
               *bytes <= sizeof g_buf);
    FUZZ_CHECK(ssda_pitch_init(p, cfg, g_buf, *bytes - 1u) == SSDA_ERR_BUFFER);
    FUZZ_CHECK(ssda_pitch_init(p, cfg, (uint8_t *)g_buf + 1, *bytes) == SSDA_ERR_BUFFER);
    FUZZ_CHECK(memcmp(p, &poison_p, sizeof *p) == 0);
    FUZZ_CHECK(ssda_pitch_init(p, cfg, g_buf, *bytes) == SSDA_OK);
    FUZZ_CHECK(ssda_pitch_get_info(p, info) == SSDA_OK);
    FUZZ_CHECK(info->frame_len == K && info->lag_max == lagmax && info->lag_min == rate / f0max);
    FUZZ_CHECK(info->span == K + lagmax + 1u && info->hop >= 1u);
    FUZZ_CHECK(info->chunk >= 1u && info->chunk <= K);
    return 1;
}

/* A signal into g_sig: a fuzzed period repeated, scaled, with noise and
   silence, as many frames as the work budget allows. Returns its length. */
static uint32_t make_signal(fuzz_in_t *in, const ssda_pitch_info_t *info)
{
    int16_t pattern[64];
    uint32_t period = fuzz_range(in, 1, 64), i, amp_shift, seed, stretch, noise, quiet_at;
    uint32_t quiet_len, frames, n;
    for (i = 0; i < period; i++) {
        pattern[i] = (int16_t)fuzz_u16(in);
    }
    amp_shift = fuzz_range(in, 0, 15);
    seed = fuzz_u32(in) | 1u;
    stretch = fuzz_range(in, 1, 40);
    noise = fuzz_range(in, 0, 15);
    quiet_at = fuzz_u16(in);
    quiet_len = fuzz_u16(in) % 4000u;
    frames = fuzz_range(in, 1, 12);
    /* keep the work bounded: full_diffs per frame, several passes */
    while (frames > 1u && (uint64_t)frames * info->full_diffs > WORK_BUDGET) {
        frames--;
    }
    if ((uint64_t)info->full_diffs > WORK_BUDGET) {
        frames = 0; /* too slow to analyse: only buffer filling is tested */
    }
    n = info->span + (frames > 0u ? (frames - 1u) * info->hop : 0u) + fuzz_range(in, 0, 50);
    if (frames == 0u) {
        n = info->span - 1u;
    }
    n = n > MAX_SAMPLES ? MAX_SAMPLES : n;
    for (i = 0; i < n; i++) {
        int32_t v = pattern[(i / stretch) % period] >> amp_shift;
        if (noise) {
            v += (int32_t)(next_rand(&seed) % (2u * noise + 1u)) - (int32_t)noise;
        }
        if (i >= quiet_at && i < quiet_at + quiet_len) {
            v = 0;
        }
        g_sig[i] = (int16_t)(v > 32767 ? 32767 : v < -32768 ? -32768 : v);
    }
    return n;
}

/* Push sizes (0 allowed, not only zeros). */
static uint32_t read_sizes(fuzz_in_t *in, uint32_t sizes[16])
{
    uint32_t nsizes = fuzz_range(in, 1, 16), i;
    for (i = 0; i < nsizes; i++) {
        sizes[i] = fuzz_one_in(in, 4) ? fuzz_range(in, 0, 3) : fuzz_range(in, 0, 2000);
    }
    for (i = 0; i < nsizes && sizes[i] == 0u; i++) {
    }
    if (i == nsizes) { /* only empty pushes would never end */
        sizes[0] = 1u;
    }
    return nsizes;
}

/* Every estimate against the brute-force reference of the definition. */
static void check_definition(const ssda_pitch_info_t *info, uint32_t n, uint32_t n_ref)
{
    const test_pitch_ref_cfg_t rc_ = test_pitch_ref_cfg_of(info);
    const int16_t *x = g_sig;
    uint32_t i;
    if (info->lowpass_q15 != 0u) {
        filter(g_sig, g_filt, n, info->lowpass_q15);
        x = g_filt;
    }
    for (i = 0; i < n_ref; i++) {
        test_pitch_ref_t r;
        uint32_t start = i * info->hop;
        test_pitch_reference(x + start, &rc_, &r);
        FUZZ_CHECK(g_ref[i].silent == r.silent && g_ref[i].voiced == r.voiced &&
                   g_ref[i].dip == r.dip);
        FUZZ_CHECK(g_ref[i].lag == r.lag && g_ref[i].period_q16 == r.period_q16 &&
                   g_ref[i].f0_q16 == r.f0_q16);
        FUZZ_CHECK(g_ref[i].confidence_q15 == r.confidence_q15);
        FUZZ_CHECK(g_ref[i].center == start + (r.silent ? info->span / 2u
                                                        : (info->frame_len + r.lag) / 2u));
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint32_t whole = MAX_SAMPLES;
    static const uint8_t toggles[] = {SSDA_PITCH_FULL, SSDA_PITCH_TRACK,
                                      SSDA_PITCH_FULL | SSDA_PITCH_TRACK};
    fuzz_in_t in = {data, size};
    ssda_pitch_config_t cfg, c2;
    ssda_pitch_info_t info;
    ssda_pitch_t p, p2;
    uint32_t n, i, sizes[16], nsizes, n_ref, n_got;
    size_t bytes = 0;

    read_config(&in, &cfg);
    if (!check_init(&cfg, &p, &info, &bytes)) {
        return 0;
    }
    n = make_signal(&in, &info);
    nsizes = read_sizes(&in, sizes);
    /* one go, fuzzed chunks, after a reset: identical */
    n_ref = run(&p, g_sig, n, &whole, 1u, g_ref);
    FUZZ_CHECK(ssda_pitch_reset(&p) == SSDA_OK);
    n_got = run(&p, g_sig, n, sizes, nsizes, g_got);
    FUZZ_CHECK(n_got == n_ref);
    for (i = 0; i < n_ref; i++) {
        same_estimate(&g_ref[i], &g_got[i], 1);
    }
    if (n_ref == 0u) {
        return 0;
    }
    /* other modes: only the work differs */
    c2 = cfg;
    c2.flags = (uint8_t)(cfg.flags ^ toggles[fuzz_range(&in, 0, 2)]);
    FUZZ_CHECK(ssda_pitch_init(&p2, &c2, g_buf, bytes) == SSDA_OK);
    n_got = run(&p2, g_sig, n, sizes, nsizes, g_got);
    FUZZ_CHECK(n_got == n_ref);
    for (i = 0; i < n_ref; i++) {
        same_estimate(&g_ref[i], &g_got[i], 0);
    }
    check_definition(&info, n, n_ref);
    return 0;
}
