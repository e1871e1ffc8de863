/*
 * jobs_pitch.c - one pitch analysis frame (ssda_pitch_push of one hop that
 * returns an estimate) at 16 kHz with the default configuration (f0
 * 50..1000 Hz: lags 16..320, K = 320, hop = 80). The voice is a vowel /a/
 * at 200 Hz (period 80 samples, tests/support/test_signal.c) with +-64 LSB
 * of noise. Every mode must return the same estimates, or the run fails.
 */
#include "jobs.h"

#include <string.h>

#include "budget_timer.h"
#include "ssda/pitch.h"
#include "test_signal.h"

#define RATE 16000u
#define PERIOD 80u
#define FRAMES 24u
#define SIGNAL (SSDA_PITCH_SPAN(RATE, 0, 0) + FRAMES * 80u)

static int16_t g_signal[SIGNAL];
static int16_t g_buf[SSDA_PITCH_BUFFER_SIZE(RATE, 0, 0) / 2u];
static ssda_pitch_estimate_t g_ref[FRAMES];

typedef struct {
    ssda_pitch_t p;
    ssda_pitch_info_t info;
    const int16_t *next;
    ssda_pitch_estimate_t est;
    int ret;
} pitch_job_t;

static void push_job(void *ctx)
{
    pitch_job_t *j = (pitch_job_t *)ctx;
    size_t used = 0u;
    j->ret = ssda_pitch_push(&j->p, j->next, j->info.hop, &used, &j->est);
    j->next += used;
}

static void make_signal(void)
{
    test_voice_t v;
    uint32_t i, st = 0x564F4943u;
    test_voice_vowel_a(&v, (double)RATE / (double)PERIOD, 12000.0);
    test_signal_voice(g_signal, PERIOD, 0u, RATE, &v); /* one exact period */
    for (i = PERIOD; i < SIGNAL; i++) {
        g_signal[i] = g_signal[i - PERIOD];
    }
    for (i = 0; i < SIGNAL; i++) {
        g_signal[i] = (int16_t)(g_signal[i] + (int32_t)(jobs_rand(&st) % 129u) - 64);
    }
}

/* Initialise a stream and fill it up to its first estimate (not timed). */
static int start(pitch_job_t *j, uint8_t flags)
{
    ssda_pitch_config_t cfg;
    size_t used = 0u;
    memset(&cfg, 0, sizeof cfg);
    cfg.sample_rate_hz = RATE;
    cfg.flags = flags;
    if (ssda_pitch_init(&j->p, &cfg, g_buf, sizeof g_buf) != SSDA_OK ||
        ssda_pitch_get_info(&j->p, &j->info) != SSDA_OK) {
        return -1;
    }
    j->next = g_signal;
    if (ssda_pitch_push(&j->p, j->next, j->info.span, &used, &j->est) != 1) {
        return -1;
    }
    j->next += used;
    return 0;
}

static void run(const char *name, const char *worst_name, uint8_t flags, int is_reference)
{
    static pitch_job_t j;
    uint32_t f, instr = 0u, stack, worst = 0u;
    uint64_t diffs = 0u;
    if (start(&j, flags) != 0) {
        budget_fail(name);
        return;
    }
    stack = budget_stack_peak(push_job, &j);
    if (start(&j, flags) != 0) {
        budget_fail(name);
        return;
    }
    for (f = 0; f < FRAMES; f++) {
        uint32_t n = budget_instructions(push_job, &j);
        instr += n;
        worst = n > worst ? n : worst;
        diffs += j.est.diffs;
        if (j.ret != 1 || !j.est.voiced) {
            budget_fail(name);
        }
        if (is_reference) {
            g_ref[f] = j.est;
        } else if (j.est.lag != g_ref[f].lag || j.est.period_q16 != g_ref[f].period_q16 ||
                   j.est.f0_q16 != g_ref[f].f0_q16) {
            budget_fail(name);
        }
    }
    budget_report(name, instr, FRAMES, stack, diffs);
    budget_report(worst_name, worst, 1u, 0u, 0u);
    if (is_reference) {
        budget_report("pitch.plain_amdf_diffs", 0u, 1u, 0u, j.info.full_diffs);
    }
}

void jobs_pitch(void)
{
    make_signal();
    run("pitch.full", "pitch.full.worst", SSDA_PITCH_FULL, 1);
    run("pitch.early_exit", "pitch.early_exit.worst", 0u, 0);
    run("pitch.early_exit_track", "pitch.early_exit_track.worst", SSDA_PITCH_TRACK, 0);
}
