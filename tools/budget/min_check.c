/*
 * min_check.c - the minimal cores at work: linked against ssda_min (the
 * library with every SSDA_CFG_NO_* switch of include/ssda/config.h) and run
 * on QEMU's mps2-an386 by tools/budget.sh, so the minimal rows of the
 * budget table measure code that works, not just code that links.
 *
 * Checks, each against an independent reference computed here:
 *   - the search core (exact AUTO and brute force, raster scan, row order,
 *     8-bit views) returns the brute-force minimum by the tie rule, from
 *     ssda_sad_at at every position;
 *   - every feature left out returns SSDA_ERR_UNSUPPORTED and leaves the
 *     result untouched;
 *   - the pitch core finds the period of a 200 Hz vowel at 16 kHz (80
 *     samples) from whole frames and refuses the options left out (the
 *     push intake among them);
 *   - a raster 8-bit source read through a callback gives the streamed
 *     search the same answer as the in-RAM search, and the tiled layout,
 *     granular reads and 16-bit sources are refused.
 * Built with MIN_CHECK_PITCH_ONLY against the pitch cores whose
 * configuration is fixed at compile time (SSDA_CFG_PITCH_FIXED: 16 kHz,
 * defaults, tools/budget/CMakeLists.txt), only the pitch checks run, and
 * another configuration (8 kHz) is refused too.
 * Prints "MINCHECK <checks> <failures>" and exits 1 on any failure.
 */
#include <stdio.h>
#include <string.h>

#include "ssda/pitch.h"
#ifndef MIN_CHECK_PITCH_ONLY
#include "ssda/match.h"
#include "ssda/stream.h"
#endif
#include "jobs.h"
#include "test_signal.h"

#define AREA 32u
#define WIN 12u

static unsigned g_checks, g_failed;

static void check(int ok, const char *what)
{
    g_checks++;
    if (!ok) {
        g_failed++;
        printf("FAILED %s\n", what);
    }
}

#ifndef MIN_CHECK_PITCH_ONLY
static uint8_t g_area[AREA * AREA];
static uint8_t g_win[WIN * WIN];

/* Brute force over every placement with ssda_sad_at: smallest SAD, then
   smallest y, then smallest x (the tie rule). */
static void brute(const ssda_view_t *a, const ssda_view_t *w, ssda_match_result_t *r)
{
    uint16_t x, y;
    r->sad = UINT64_MAX;
    for (y = 0u; y + w->height <= a->height; y++) {
        for (x = 0u; x + w->width <= a->width; x++) {
            uint64_t s;
            if (ssda_sad_at(a, w, x, y, &s) == SSDA_OK && s < r->sad) {
                r->sad = s;
                r->x = x;
                r->y = y;
            }
        }
    }
}

static void check_search(void)
{
    ssda_view_t a, w, a16;
    ssda_match_config_t cfg;
    ssda_match_result_t got, ref, sentinel;
    static uint32_t work[1024];
    static uint16_t area16[4u * 4u];
    uint32_t seed = 7u, i, y;
    jobs_texture_u8(g_area, AREA, AREA, 11u);
    for (y = 0u; y < WIN; y++) { /* the window at (9, 5), with noise */
        for (i = 0u; i < WIN; i++) {
            int v = g_area[(5u + y) * AREA + 9u + i] + (int)(jobs_rand(&seed) % 7u) - 3;
            g_win[y * WIN + i] = (uint8_t)(v < 0 ? 0 : (v > 255 ? 255 : v));
        }
    }
    (void)ssda_view_init(&a, g_area, AREA, AREA, AREA, SSDA_PIX_U8);
    (void)ssda_view_init(&w, g_win, WIN, WIN, WIN, SSDA_PIX_U8);
    brute(&a, &w, &ref);

    check(ssda_match(&a, &w, NULL, &got) == SSDA_OK && got.exact &&
              got.sad == ref.sad && got.x == ref.x && got.y == ref.y,
          "search: auto raster = brute force");
    memset(&cfg, 0, sizeof cfg);
    cfg.threshold = SSDA_THRESHOLD_NONE;
    check(ssda_match(&a, &w, &cfg, &got) == SSDA_OK && got.exact &&
              got.sad == ref.sad && got.x == ref.x && got.y == ref.y,
          "search: brute-force mode = brute force");

    /* Left out: refused, result untouched. */
    memset(&sentinel, 0x5a, sizeof sentinel);
    for (i = 0u; i < 7u; i++) {
        memset(&cfg, 0, sizeof cfg);
        cfg.lambda_q8 = 256u;
        cfg.work = work;
        cfg.work_size = sizeof work;
        switch (i) {
        case 0: cfg.threshold = SSDA_THRESHOLD_RAMP; break;
        case 1: cfg.threshold = SSDA_THRESHOLD_AUTO_RAMP; break;
        case 2: cfg.threshold = SSDA_THRESHOLD_FIXED; break;
        case 3: cfg.scan = SSDA_SCAN_PREDICT; break;
        case 4: cfg.scan = SSDA_SCAN_COARSE; break;
        case 5: cfg.order = SSDA_ORDER_SPREAD; break;
        default: cfg.flags = SSDA_MATCH_BOUNDS; break;
        }
        got = sentinel;
        check(ssda_match(&a, &w, &cfg, &got) == SSDA_ERR_UNSUPPORTED &&
                  memcmp(&got, &sentinel, sizeof got) == 0,
              "search: a left-out option is refused");
    }
    (void)ssda_view_init(&a16, area16, 4u, 4u, 8u, SSDA_PIX_U16);
    got = sentinel;
    check(ssda_match(&a16, &a16, NULL, &got) == SSDA_ERR_UNSUPPORTED &&
              memcmp(&got, &sentinel, sizeof got) == 0,
          "search: 16-bit views are refused");
}

#endif

static int16_t g_sig[4000];

static void check_pitch(void)
{
    ssda_pitch_config_t cfg;
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    ssda_pitch_estimate_t est, poison;
    test_voice_t v;
    size_t used = 777u, bytes = 777u;
    uint32_t at;
    unsigned frames = 0u, right = 0u;
    static const uint8_t refused[] = {0u, SSDA_PITCH_TRACK, SSDA_PITCH_FULL, SSDA_PITCH_PARABOLIC};
    uint32_t i;
    memset(&cfg, 0, sizeof cfg);
    memset(&poison, 0xA5, sizeof poison);
    cfg.sample_rate_hz = 16000u;
    for (i = 0u; i < sizeof refused; i++) {
        cfg.flags = (uint8_t)(refused[i] | (i == 0u ? 0u : SSDA_PITCH_NO_FILTER));
        check(ssda_pitch_init(&p, &cfg, NULL, 0u) == SSDA_ERR_UNSUPPORTED,
              "pitch: a left-out option (the low-pass by default) is refused");
    }
#ifdef SSDA_CFG_PITCH_FIXED
    cfg.flags = (uint8_t)(SSDA_CFG_PITCH_FIXED_FLAGS);
    cfg.sample_rate_hz = 8000u;
    check(ssda_pitch_init(&p, &cfg, NULL, 0u) == SSDA_ERR_UNSUPPORTED,
          "pitch: another configuration than the fixed one is refused");
    cfg.sample_rate_hz = 16000u;
#else
    cfg.flags = SSDA_PITCH_NO_FILTER;
#endif
    check(ssda_pitch_init(&p, &cfg, NULL, 0u) == SSDA_OK &&
              ssda_pitch_get_info(&p, &info) == SSDA_OK,
          "pitch: the core initialises, without a buffer");
    est = poison;
    check(ssda_pitch_push(&p, g_sig, 100u, &used, &est) == SSDA_ERR_UNSUPPORTED &&
              ssda_pitch_buffer_size(&cfg, &bytes) == SSDA_ERR_UNSUPPORTED &&
              used == 777u && bytes == 777u && memcmp(&est, &poison, sizeof est) == 0,
          "pitch: no push intake (whole frames only), nothing written");
    test_voice_vowel_a(&v, 200.0, 12000.0);
    test_signal_voice(g_sig, 4000u, 0u, 16000u, &v);
    for (at = 0u; at + info.span <= 4000u; at += info.hop) {
        if (ssda_pitch_frame(&p, g_sig + at, &est) == SSDA_OK) {
            frames++;
            /* period 80 samples: the lag within one sample, voiced */
            if (est.voiced && est.lag >= 79u && est.lag <= 81u &&
                est.period_q16 > (79u << 16) && est.period_q16 < (81u << 16)) {
                right++;
            }
        }
    }
    check(frames > 10u && right == frames, "pitch: 200 Hz vowel, every frame voiced at lag 80");
}

#ifndef MIN_CHECK_PITCH_ONLY
/* A device in RAM for the source's read callback. */
static int read_mem(void *ctx, uint32_t offset, void *buffer, uint32_t size)
{
    if ((size_t)offset + size > sizeof g_area) {
        return -100;
    }
    memcpy(buffer, (const uint8_t *)ctx + offset, size);
    return 0;
}

static void check_stream(void)
{
    static uint32_t arena_a[256];
    ssda_source_config_t c;
    ssda_source_t sa, sw;
    ssda_view_t a, w;
    ssda_match_result_t got, ref;
    memset(&c, 0, sizeof c);
    c.read = read_mem;
    c.context = g_area;
    c.arena = arena_a;
    c.arena_size = sizeof arena_a; /* 1 KiB: the 32 x 32 area in plates */
    c.width = AREA;
    c.height = AREA;
    c.format = SSDA_PIX_U8;
    check(ssda_source_init(&sa, &c) == SSDA_OK, "stream: raster 8-bit source");
    c.layout = SSDA_LAYOUT_TILED;
    c.tile_w = 8u;
    c.tile_h = 8u;
    check(ssda_source_init(&sw, &c) == SSDA_ERR_UNSUPPORTED, "stream: tiled refused");
    c.layout = SSDA_LAYOUT_RASTER;
    c.read_size = 4u;
    check(ssda_source_init(&sw, &c) == SSDA_ERR_UNSUPPORTED, "stream: granular reads refused");
    c.read_size = 0u;
    c.format = SSDA_PIX_U16;
    c.width = AREA / 2u;
    check(ssda_source_init(&sw, &c) == SSDA_ERR_UNSUPPORTED, "stream: 16-bit refused");

    (void)ssda_view_init(&w, g_win, WIN, WIN, WIN, SSDA_PIX_U8);
    (void)ssda_source_init_view(&sw, &w);
    (void)ssda_view_init(&a, g_area, AREA, AREA, AREA, SSDA_PIX_U8);
    (void)ssda_match(&a, &w, NULL, &ref);
    check(ssda_stream_match(&sa, NULL, &sw, NULL, NULL, &got) == SSDA_OK &&
              got.sad == ref.sad && got.x == ref.x && got.y == ref.y && got.exact,
          "stream: streamed search = in-RAM search");
}

#endif

int main(void)
{
#ifndef MIN_CHECK_PITCH_ONLY
    check_search();
#endif
    check_pitch();
#ifndef MIN_CHECK_PITCH_ONLY
    check_stream();
#endif
    printf("MINCHECK %u %u\n", g_checks, g_failed);
    return g_failed != 0u;
}
