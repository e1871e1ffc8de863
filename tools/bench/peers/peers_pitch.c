/*
 * peers_pitch.c - ssda-peers-pitch: ssda's AMDF pitch against aubio's YIN
 * (yin and yinfast) on the same signals and frames, in one process run:
 * processor time per second of audio (median of repeated runs) and the
 * standard accuracy figures (GPE, FPE, VDE).
 *
 * Everything about running the estimators, aligning their frames with the
 * reference and scoring them is tools/eval's (pitch_runners, pitch_metrics,
 * pitch_synth, f0_csv, shared with ssda-eval-pitch); this file only repeats
 * the runs for timing and prints the side-by-side table. The configuration
 * is ssda-eval-pitch's default: f0 50..1000 Hz, hop 5.8 ms, the library's
 * defaults otherwise; aubio gets the same hop and a buffer of 2 K samples
 * (its window and lag range equal to ssda's K), as ssda-eval-pitch does.
 *
 * usage: ssda-peers-pitch [--reps N] [--ratios FILE] [--quick] [audio=ref.csv ...]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "f0_csv.h"
#include "peers_util.h"
#include "pitch_metrics.h"
#include "pitch_runners.h"
#include "pitch_synth.h"
#include "ssda/pitch.h"
#include "wav_io.h"

enum { M_SSDA, M_TRACK, M_FULL, M_YIN, M_YINFAST, M_COUNT };
static const char *const k_names[M_COUNT] = {
    "**ssda AMDF, early exit** (library default)", "ssda AMDF, early exit + tracking",
    "ssda AMDF, no early exit (`SSDA_PITCH_FULL`)", "aubio `yin`", "aubio `yinfast`"};
static const char *const k_short[M_COUNT] = {"ssda", "ssda tracking", "ssda full", "aubio yin",
                                             "aubio yinfast"};

typedef struct {
    const char *name;    /* table label */
    const char *label;   /* chart label */
    metrics_acc_t acc[M_COUNT];
    double cpu[M_COUNT]; /* sum over signals of the median processor time */
    double seconds;      /* audio */
    size_t signals;
} group_t;

typedef double (*ref_fn)(const void *ctx, double t_s);
static double ref_synth(const void *ctx, double t) { return synth_song_f0_at(ctx, t); }
static double ref_csv(const void *ctx, double t) { return f0_track_at(ctx, t); }

static ssda_pitch_config_t make_cfg(uint32_t rate, uint8_t flags)
{
    ssda_pitch_config_t c;
    memset(&c, 0, sizeof c);
    c.sample_rate_hz = rate;
    c.f0_min_hz = 50;
    c.f0_max_hz = 1000;
    c.hop = (uint16_t)lrint(5.8 * rate / 1000.0);
    c.flags = flags;
    return c;
}

static int run_one(int m, const int16_t *x, size_t n, uint32_t rate, const ssda_pitch_info_t *info,
                   run_t *r)
{
    static const uint8_t flags[3] = {0u, SSDA_PITCH_TRACK, SSDA_PITCH_FULL};
    char err[256];
    if (m <= M_FULL) {
        ssda_pitch_config_t cfg = make_cfg(rate, flags[m]);
        if (run_ssda(x, n, &cfg, r, err, sizeof err) != 0) {
            fprintf(stderr, "ssda-peers-pitch: %s\n", err);
            return -1;
        }
        return 0;
    }
    if (run_aubio(m == M_YIN ? "yin" : "yinfast", x, n, rate, 2u * info->frame_len, info->hop, r) !=
        0) {
        fprintf(stderr, "ssda-peers-pitch: aubio failed\n");
        return -1;
    }
    return 0;
}

/* Every method on one signal, reps interleaved runs; adds to the groups. */
static int eval_signal(group_t *const *groups, int ngroups, const int16_t *x, size_t n, uint32_t rate, ref_fn ref,
                       const void *ctx, int reps, size_t *mismatch)
{
    ssda_pitch_config_t cfg = make_cfg(rate, 0u);
    ssda_pitch_info_t info;
    ssda_pitch_t probe;
    size_t bytes;
    int16_t *buf;
    double *times = calloc((size_t)reps * M_COUNT, sizeof *times);
    run_t first[M_COUNT];
    int m, k;

    if (times == NULL || ssda_pitch_buffer_size(&cfg, &bytes) != SSDA_OK ||
        (buf = malloc(bytes)) == NULL) {
        free(times);
        return -1;
    }
    if (ssda_pitch_init(&probe, &cfg, buf, bytes) != SSDA_OK) {
        fprintf(stderr, "ssda-peers-pitch: invalid configuration at %u Hz\n", rate);
        free(buf);
        free(times);
        return -1;
    }
    ssda_pitch_get_info(&probe, &info);
    free(buf);
    memset(first, 0, sizeof first);
    for (k = 0; k < reps; k++) {
        for (m = 0; m < M_COUNT; m++) {
            run_t r;
            if (run_one(m, x, n, rate, &info, &r) != 0) {
                free(times);
                return -1;
            }
            times[(size_t)m * reps + k] = r.cpu_s;
            if (k == 0) {
                first[m] = r;
            } else {
                run_free(&r);
            }
        }
    }
    for (m = 0; m < M_COUNT; m++) {
        double med = peers_median(times + (size_t)m * reps, (size_t)reps);
        for (size_t i = 0; i < first[m].n; i++) {
            first[m].fr[i].ref_hz = ref(ctx, first[m].fr[i].t_s);
        }
        for (int gi = 0; gi < ngroups; gi++) {
            metrics_add(&groups[gi]->acc[m], first[m].fr, first[m].n);
            groups[gi]->cpu[m] += med;
        }
    }
    /* early exit must not change a single estimate */
    for (size_t i = 0; i < first[M_FULL].n; i++) {
        for (m = M_SSDA; m <= M_TRACK; m++) {
            *mismatch += i >= first[m].n || first[m].fr[i].f0_hz != first[M_FULL].fr[i].f0_hz ||
                         first[m].fr[i].voiced != first[M_FULL].fr[i].voiced;
        }
    }
    for (m = 0; m < M_COUNT; m++) {
        run_free(&first[m]);
    }
    for (int gi = 0; gi < ngroups; gi++) {
        groups[gi]->seconds += (double)n / rate;
        groups[gi]->signals++;
    }
    free(times);
    return 0;
}

static void print_group(const group_t *g, FILE *ratios)
{
    char label[160];
    for (int m = 0; m < M_COUNT; m++) {
        metrics_t r = metrics_done(&g->acc[m]);
        double ms = 1000.0 * g->cpu[m] / g->seconds;
        printf("| %s | %s | %.2f | %.1fx | %.2f | %.1f | %.2f |\n", g->name, k_names[m], ms,
               g->cpu[m] / g->cpu[M_SSDA], r.both_voiced ? 100.0 * r.gross / r.both_voiced : 0.0,
               r.fpe_mean_abs, r.frames ? 100.0 * r.voicing_err / r.frames : 0.0);
    }
    for (int m = M_YIN; m <= M_YINFAST; m++) {
        snprintf(label, sizeof label, "%s: vs %s", g->label, k_short[m]);
        peers_ratio(ratios, "Pitch (processor time per second of audio)", label,
                    g->cpu[m] / g->cpu[M_SSDA]);
    }
}

static void print_intro(int reps)
{
    printf("## Pitch: ssda %d.%d.%d vs aubio yin and yinfast\n\n", SSDA_VERSION_MAJOR,
           SSDA_VERSION_MINOR, SSDA_VERSION_PATCH);
    printf("f0 50..1000 Hz, hop 5.8 ms, library defaults otherwise (ssda-eval-pitch's "
           "configuration); aubio with the same hop, a buffer of 2 K samples (K = ssda's "
           "frame, one period of 50 Hz), its default tolerance 0.15; frames aligned by their "
           "centre times and scored against the reference as in tools/eval. Processor time of "
           "the estimator alone, median of %d interleaved runs per signal, summed over the "
           "signals of a row. GPE: share of frames voiced in both with f0 off by > 20 %%; FPE: "
           "mean |error| in cents of the others; VDE: share of frames whose voicing differs.\n\n",
           reps);
    printf("| data | method | CPU ms per s of audio | time relative to ssda default | GPE %% | FPE (cents) | VDE %% |\n");
    printf("|---|---|---:|---:|---:|---:|---:|\n");
}

/* The synthetic songs (clean to 10 dB SNR, dark and bright). Returns 0, 1
   (a method failed) or -1 (out of memory). */
static int run_synthetic(int quick, int reps, FILE *ratios, size_t *mismatch)
{
    static const struct { int bright; double snr; } sets[] = {
        {0, 200.0}, {0, 30.0}, {0, 20.0}, {0, 10.0}, {1, 200.0}, {1, 20.0}};
    group_t synth;
    int rc = 0;
    memset(&synth, 0, sizeof synth);
    synth.name = "synthetic songs (6 x 40 notes, 16 kHz, clean to 10 dB SNR)";
    synth.label = "synthetic songs";
    for (size_t k = 0; k < (quick ? 2u : sizeof sets / sizeof sets[0]); k++) {
        synth_song_t s;
        group_t *gs[1] = {&synth};
        if (synth_song(&s, 16000, quick ? 10 : 40, sets[k].snr, sets[k].bright, 1234u + (uint32_t)k) != 0) {
            fprintf(stderr, "ssda-peers-pitch: out of memory\n");
            return -1;
        }
        if (eval_signal(gs, 1, s.x, s.n, s.rate, ref_synth, &s, reps, mismatch) != 0) {
            rc = 1;
        }
        synth_song_free(&s);
    }
    if (quick) {
        synth.name = "synthetic songs (quick: 2 x 10 notes)";
    }
    print_group(&synth, ratios);
    return rc;
}

/* Each audio=ref.csv recording, then all of them together. Returns 0 or 1. */
static int run_files(char **files, int nfiles, int reps, FILE *ratios, size_t *mismatch)
{
    group_t files_all;
    int rc = 0;
    memset(&files_all, 0, sizeof files_all);
    files_all.name = "**recordings, all**";
    files_all.label = "recordings";
    for (int i = 0; i < nfiles; i++) {
        char *eq = strchr(files[i], '='), err[512];
        const char *base;
        f0_track_t tr;
        int16_t *x;
        size_t n;
        uint32_t rate;
        group_t g;
        group_t *gs[2] = {&g, &files_all};
        *eq = '\0';
        if (wav_read_mono_i16(files[i], &x, &n, &rate, err, sizeof err) != 0 ||
            f0_track_read(eq + 1, &tr, err, sizeof err) != 0) {
            fprintf(stderr, "ssda-peers-pitch: %s\n", err);
            rc = 1;
            continue;
        }
        base = strrchr(files[i], '/') ? strrchr(files[i], '/') + 1 : files[i];
        memset(&g, 0, sizeof g);
        g.name = g.label = base;
        if (eval_signal(gs, 2, x, n, rate, ref_csv, &tr, reps, mismatch) != 0) {
            rc = 1;
        }
        print_group(&g, nfiles == 1 ? ratios : NULL);
        free(x);
        f0_track_free(&tr);
    }
    if (nfiles > 1) {
        print_group(&files_all, ratios);
    }
    return rc;
}

int main(int argc, char **argv)
{
    int reps = 5, quick = 0, nfiles = 0, rc = 0, r;
    const char *ratios_path = NULL;
    FILE *ratios = NULL;
    size_t mismatch = 0;
    char **files = calloc((size_t)argc, sizeof *files);

    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--ratios") && i + 1 < argc) ratios_path = argv[++i];
        else if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (argv[i][0] != '-' && strchr(argv[i], '=') != NULL) files[nfiles++] = argv[i];
        else {
            fprintf(stderr, "usage: ssda-peers-pitch [--reps N] [--ratios FILE] [--quick] "
                            "[audio=ref.csv ...]\n");
            return 2;
        }
    }
    if (quick && reps > 3) {
        reps = 3;
    }
    if (reps < 1 || !have_aubio()) {
        fprintf(stderr, "ssda-peers-pitch: --reps >= 1, and aubio must be compiled in\n");
        return 2;
    }
    if (ratios_path != NULL && (ratios = fopen(ratios_path, "w")) == NULL) {
        perror(ratios_path);
        return 1;
    }
    print_intro(reps);
    if ((r = run_synthetic(quick, reps, ratios, &mismatch)) < 0) {
        return 1;
    }
    rc |= r;
    rc |= run_files(files, nfiles, reps, ratios, &mismatch);
    printf("\nEarly exit and tracking vs no early exit: %zu frames differ%s.\n", mismatch,
           mismatch == 0 ? " (bit-identical estimates, as the library promises)" : " (**BUG**)");
    if (ratios != NULL && fclose(ratios) != 0) {
        perror(ratios_path);
        rc = 1;
    }
    free(files);
    return rc || mismatch ? 1 : 0;
}
