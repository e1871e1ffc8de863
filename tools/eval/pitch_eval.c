/*
 * pitch_eval.c - evaluation of ssda's AMDF pitch against aubio's YIN on the
 * same frames: gross pitch error, fine pitch error, voicing decision error,
 * and work (absolute differences per frame vs a full-search AMDF).
 * Not a test: it prints Markdown tables. See docs/pitch.md.
 *
 * usage: ssda-eval-pitch [options] [audio[=ref.csv] ...]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "f0_csv.h"
#include "kernel/kernels.h"
#include "pitch_metrics.h"
#include "pitch_runners.h"
#include "pitch_synth.h"
#include "ssda/pitch.h"
#include "wav_io.h"

enum { M_SSDA, M_TRACK, M_YIN, M_YINFAST, M_COUNT };
static const char *const k_names[M_COUNT] = {"ssda AMDF (early exit)", "ssda AMDF + tracking",
                                             "aubio yin", "aubio yinfast"};

typedef struct {
    metrics_acc_t acc[M_COUNT];
    double cpu[M_COUNT];
    double seconds;        /* audio duration */
    double full_diffs;     /* per non-silent frame, full search */
    size_t full_checked, full_mismatch;
    int used[M_COUNT];
} group_t;

typedef struct {
    double hop_ms;
    uint16_t f0_min, f0_max, frame_len, chunk;
    double threshold, voicing;
    int synth, full_check, per_file, no_filter, parabolic;
    uint16_t lowpass;
    uint32_t synth_notes, synth_rate;
    int no_octave, no_below_range; /* reduced definitions */
} options_t;

typedef double (*ref_fn)(const void *ctx, double t_s);

static double ref_synth(const void *ctx, double t) { return synth_song_f0_at(ctx, t); }
static double ref_csv(const void *ctx, double t) { return f0_track_at(ctx, t); }

static ssda_pitch_config_t make_cfg(const options_t *o, uint32_t rate, uint8_t flags)
{
    ssda_pitch_config_t c = {0};
    c.sample_rate_hz = rate;
    c.f0_min_hz = o->f0_min;
    c.f0_max_hz = o->f0_max;
    c.frame_len = o->frame_len;
    c.hop = (uint16_t)lrint(o->hop_ms * rate / 1000.0);
    c.chunk = o->chunk;
    c.threshold_q15 = (uint16_t)lrint(o->threshold * 32768.0);
    c.voicing_q15 = (uint16_t)lrint(o->voicing * 32768.0);
    c.lowpass_hz = o->lowpass;
    c.flags = (uint8_t)(flags | (o->no_filter ? SSDA_PITCH_NO_FILTER : 0u) |
                        (o->parabolic ? SSDA_PITCH_PARABOLIC : 0u) |
                        (o->no_octave ? SSDA_PITCH_NO_OCTAVE : 0u) |
                        (o->no_below_range ? SSDA_PITCH_NO_BELOW_RANGE : 0u));
    return c;
}

static void print_header(void)
{
    printf("| data | method | frames | GPE %% | GPE all-voiced %% | FPE mean abs (cents) | FPE sd (cents) "
           "| VDE %% | differences / voiced frame | fewer than full AMDF | CPU ms per s of audio |\n");
    printf("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
}

static void print_group(const char *name, const group_t *g)
{
    int m;
    for (m = 0; m < M_COUNT; m++) {
        metrics_t r;
        if (!g->used[m]) {
            continue;
        }
        r = metrics_done(&g->acc[m]);
        printf("| %s | %s | %zu | %.2f | %.2f | %.1f | %.1f | %.2f | ", name, k_names[m], r.frames,
               r.both_voiced ? 100.0 * r.gross / r.both_voiced : 0.0,
               r.ref_voiced ? 100.0 * r.gross_raw / r.ref_voiced : 0.0, r.fpe_mean_abs, r.fpe_sd,
               r.frames ? 100.0 * r.voicing_err / r.frames : 0.0);
        if (m == M_SSDA || m == M_TRACK) {
            printf("%.0f | %.1fx | ", r.diffs_voiced,
                   r.diffs_voiced > 0 ? g->full_diffs / r.diffs_voiced : 0.0);
        } else {
            printf("- | - | ");
        }
        printf("%.1f |\n", g->seconds > 0 ? 1000.0 * g->cpu[m] / g->seconds : 0.0);
    }
}

static int g_dump = -1; /* method whose gross errors are printed (--dump) */

static void add_run(group_t *g, int m, run_t *r, ref_fn ref, const void *ctx, int first)
{
    size_t i;
    for (i = 0; i < r->n; i++) {
        r->fr[i].ref_hz = ref(ctx, r->fr[i].t_s);
    }
    if (m == g_dump && first) { /* once per signal */
        for (i = 0; i < r->n; i++) {
            const frame_t *f = &r->fr[i];
            int rv = f->ref_hz > 0.0, ev = f->voiced && f->f0_hz > 0.0;
            int gross = rv && (f->f0_hz <= 0.0 || fabs(f->f0_hz / f->ref_hz - 1.0) > 0.2);
            if (gross || rv != ev) {
                fprintf(stderr, "%s t=%.3f ref=%.1f est=%.1f voiced=%d conf=%.3f%s\n", k_names[m],
                        f->t_s, f->ref_hz, f->f0_hz, f->voiced, f->conf, gross ? " GROSS" : "");
            }
        }
    }
    metrics_add(&g->acc[m], r->fr, r->n);
    g->cpu[m] += r->cpu_s;
    g->used[m] = 1;
}

/* Run every method on one signal and add it to the groups given. */
static int eval_signal(const options_t *o, const int16_t *x, size_t n, uint32_t rate,
                       ref_fn ref, const void *ctx, group_t **groups, int ngroups)
{
    ssda_pitch_config_t cfg = make_cfg(o, rate, 0u);
    ssda_pitch_config_t cfg_track = make_cfg(o, rate, SSDA_PITCH_TRACK);
    ssda_pitch_config_t cfg_full = make_cfg(o, rate, SSDA_PITCH_FULL);
    ssda_pitch_info_t info;
    ssda_pitch_t probe;
    char err[256];
    run_t r_ssda, r_track, r_full;
    size_t bytes, i;
    int16_t *probe_buf;
    int gi;

    if (ssda_pitch_buffer_size(&cfg, &bytes) != SSDA_OK || (probe_buf = malloc(bytes)) == NULL ||
        ssda_pitch_init(&probe, &cfg, probe_buf, bytes) != SSDA_OK) {
        fprintf(stderr, "ssda-eval-pitch: invalid pitch configuration for %u Hz\n", rate);
        return -1;
    }
    ssda_pitch_get_info(&probe, &info);
    free(probe_buf);
    if (run_ssda(x, n, &cfg, &r_ssda, err, sizeof err) != 0 ||
        run_ssda(x, n, &cfg_track, &r_track, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-eval-pitch: %s\n", err);
        return -1;
    }
    for (gi = 0; gi < ngroups; gi++) {
        groups[gi]->seconds += (double)n / rate;
        groups[gi]->full_diffs = info.full_diffs;
        add_run(groups[gi], M_SSDA, &r_ssda, ref, ctx, gi == 0);
        add_run(groups[gi], M_TRACK, &r_track, ref, ctx, gi == 0);
    }
    if (o->full_check) {
        if (run_ssda(x, n, &cfg_full, &r_full, err, sizeof err) != 0) {
            fprintf(stderr, "ssda-eval-pitch: %s\n", err);
            return -1;
        }
        for (i = 0; i < r_full.n && i < r_ssda.n; i++) {
            int same = r_full.fr[i].f0_hz == r_ssda.fr[i].f0_hz &&
                       r_full.fr[i].voiced == r_ssda.fr[i].voiced &&
                       r_full.fr[i].f0_hz == r_track.fr[i].f0_hz &&
                       r_full.fr[i].voiced == r_track.fr[i].voiced;
            for (gi = 0; gi < ngroups; gi++) {
                groups[gi]->full_checked++;
                groups[gi]->full_mismatch += same ? 0u : 1u;
            }
        }
        run_free(&r_full);
    }
    if (have_aubio()) {
        static const char *const methods[2] = {"yin", "yinfast"};
        int k;
        for (k = 0; k < 2; k++) {
            run_t r;
            /* same frames: aubio's buffer is 2 W with W = K (its window and lag range) */
            if (run_aubio(methods[k], x, n, rate, 2u * info.frame_len, info.hop, &r) == 0) {
                for (gi = 0; gi < ngroups; gi++) {
                    add_run(groups[gi], M_YIN + k, &r, ref, ctx, gi == 0);
                }
                run_free(&r);
            }
        }
    }
    run_free(&r_ssda);
    run_free(&r_track);
    return 0;
}

static void usage(void)
{
    fprintf(stderr,
            "usage: ssda-eval-pitch [options] [audio[=ref.csv] ...]\n"
            "  audio      any file libsndfile reads; its reference is ref.csv, or else\n"
            "             <audio minus extension>.csv or <...>_f0.csv (time_s,f0_hz; 0 = unvoiced)\n"
            "  --no-synth          skip the synthetic set\n"
            "  --synth-notes N     notes per synthetic song (40)\n"
            "  --synth-rate HZ     synthetic sample rate (16000)\n"
            "  --hop-ms MS         hop in milliseconds (5.8)\n"
            "  --f0-min HZ --f0-max HZ   search range (50, 1000)\n"
            "  --frame N           frame length K (0 = library default)\n"
            "  --chunk N           samples between early-exit tests (0 = default)\n"
            "  --threshold T       dip threshold, 0..1 (0 = library default)\n"
            "  --lowpass HZ        input low-pass cutoff (0 = f0 max); --no-filter: none\n"
            "  --parabolic         parabolic instead of V-shaped sub-sample fit\n"
            "  --no-octave         reduced definition: no octave check (SSDA_PITCH_NO_OCTAVE)\n"
            "  --no-below-range    reduced definition: no below-range check\n"
            "  --voicing V         voicing threshold, 0..1 (0 = the dip threshold)\n"
            "  --no-full-check     skip the no-early-exit run that checks identical results\n"
            "  --per-file          also print a table row set per file\n"
            "  --dump M            list the gross and voicing errors of method M (0 ssda,\n"
            "                      1 ssda + tracking, 2 yin, 3 yinfast) on stderr\n");
}

static int find_ref(const char *audio, char *out, size_t outlen)
{
    static const char *const suffixes[2] = {".csv", "_f0.csv"};
    const char *dot = strrchr(audio, '.');
    size_t base = dot ? (size_t)(dot - audio) : strlen(audio);
    int k;
    for (k = 0; k < 2; k++) {
        FILE *fp;
        snprintf(out, outlen, "%.*s%s", (int)base, audio, suffixes[k]);
        if ((fp = fopen(out, "r")) != NULL) {
            fclose(fp);
            return 0;
        }
    }
    return -1;
}

/* Options into o, audio arguments into files. Returns the count of files,
   or -1 after usage(). */
static int parse_args(int argc, char **argv, options_t *o, char **files)
{
    int i, nfiles = 0;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--no-synth")) o->synth = 0;
        else if (!strcmp(a, "--no-full-check")) o->full_check = 0;
        else if (!strcmp(a, "--per-file")) o->per_file = 1;
        else if (!strcmp(a, "--dump") && i + 1 < argc) g_dump = atoi(argv[++i]);
        else if (!strcmp(a, "--synth-notes") && i + 1 < argc) o->synth_notes = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(a, "--synth-rate") && i + 1 < argc) o->synth_rate = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(a, "--hop-ms") && i + 1 < argc) o->hop_ms = atof(argv[++i]);
        else if (!strcmp(a, "--f0-min") && i + 1 < argc) o->f0_min = (uint16_t)atoi(argv[++i]);
        else if (!strcmp(a, "--f0-max") && i + 1 < argc) o->f0_max = (uint16_t)atoi(argv[++i]);
        else if (!strcmp(a, "--frame") && i + 1 < argc) o->frame_len = (uint16_t)atoi(argv[++i]);
        else if (!strcmp(a, "--chunk") && i + 1 < argc) o->chunk = (uint16_t)atoi(argv[++i]);
        else if (!strcmp(a, "--threshold") && i + 1 < argc) o->threshold = atof(argv[++i]);
        else if (!strcmp(a, "--voicing") && i + 1 < argc) o->voicing = atof(argv[++i]);
        else if (!strcmp(a, "--lowpass") && i + 1 < argc) o->lowpass = (uint16_t)atoi(argv[++i]);
        else if (!strcmp(a, "--no-filter")) o->no_filter = 1;
        else if (!strcmp(a, "--parabolic")) o->parabolic = 1;
        else if (!strcmp(a, "--no-octave")) o->no_octave = 1;
        else if (!strcmp(a, "--no-below-range")) o->no_below_range = 1;
        else if (a[0] == '-') { usage(); return -1; }
        else files[nfiles++] = argv[i];
    }
    return nfiles;
}

/* The synthetic set: vowel songs at several SNRs, bright pulse songs; each
   set's row, then all. Returns 0, 1 (a method failed) or -1 (no memory). */
static int run_synthetic(const options_t *o, group_t *synth_all)
{
    static const struct { int bright; double snr; } sets[] = {
        {0, 200.0}, {0, 30.0}, {0, 20.0}, {0, 10.0}, {1, 200.0}, {1, 20.0}};
    int status = 0;
    for (size_t k = 0; k < sizeof sets / sizeof sets[0]; k++) {
        synth_song_t s;
        group_t g;
        group_t *gs[2] = {&g, synth_all};
        char name[64];
        memset(&g, 0, sizeof g);
        if (synth_song(&s, o->synth_rate, o->synth_notes, sets[k].snr, sets[k].bright,
                       1234u + (uint32_t)k) != 0) {
            fprintf(stderr, "ssda-eval-pitch: out of memory\n");
            return -1;
        }
        if (sets[k].snr >= 100.0) {
            snprintf(name, sizeof name, "synthetic %s, clean", sets[k].bright ? "bright" : "vowels");
        } else {
            snprintf(name, sizeof name, "synthetic %s, %.0f dB SNR",
                     sets[k].bright ? "bright" : "vowels", sets[k].snr);
        }
        if (g_dump >= 0) {
            fprintf(stderr, "== %s\n", name);
        }
        if (eval_signal(o, s.x, s.n, s.rate, ref_synth, &s, gs, 2) != 0) {
            status = 1;
        }
        print_group(name, &g);
        synth_song_free(&s);
    }
    print_group("**synthetic, all**", synth_all);
    return status;
}

/* One recording (audio or audio=ref.csv) into g and real_all. Returns 0,
   1 (a method failed) or 2 (not read: nothing analysed). */
static int run_file(const options_t *o, char *arg, group_t *g, group_t *real_all)
{
    char refpath[4096], err[512];
    char *eq = strchr(arg, '=');
    f0_track_t tr;
    int16_t *x;
    size_t n;
    uint32_t rate;
    group_t *gs[2] = {g, real_all};
    int status = 0;
    if (eq != NULL) {
        *eq = '\0';
        snprintf(refpath, sizeof refpath, "%s", eq + 1);
    } else if (find_ref(arg, refpath, sizeof refpath) != 0) {
        fprintf(stderr, "ssda-eval-pitch: no reference CSV found for '%s' (give audio=ref.csv)\n", arg);
        return 2;
    }
    if (wav_read_mono_i16(arg, &x, &n, &rate, err, sizeof err) != 0 ||
        f0_track_read(refpath, &tr, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-eval-pitch: %s\n", err);
        return 2;
    }
    memset(g, 0, sizeof *g);
    if (eval_signal(o, x, n, rate, ref_csv, &tr, gs, 2) != 0) {
        status = 1;
    }
    free(x);
    f0_track_free(&tr);
    return status;
}

int main(int argc, char **argv)
{
    options_t o = {5.8, 50, 1000, 0, 0, 0.0, 0.0, 1, 1, 0, 0, 0, 0, 40, 16000, 0, 0};
    group_t synth_all, real_all;
    int i, nfiles, status = 0, r;
    char **files = calloc((size_t)argc, sizeof *files);

    memset(&synth_all, 0, sizeof synth_all);
    memset(&real_all, 0, sizeof real_all);
    if ((nfiles = parse_args(argc, argv, &o, files)) < 0) {
        return 2;
    }
    printf("ssda pitch evaluation: f0 %u-%u Hz, hop %.1f ms, threshold %.2f, low-pass %s, "
           "%s fit%s%s, kernel set %s%s\n\n", o.f0_min, o.f0_max, o.hop_ms,
           o.threshold > 0 ? o.threshold : SSDA_PITCH_DEFAULT_THRESHOLD_Q15 / 32768.0,
           o.no_filter ? "off" : o.lowpass ? "as given" : "at f0 max",
           o.parabolic ? "parabolic" : "V", o.no_octave ? ", no octave check" : "",
           o.no_below_range ? ", no below-range check" : "", ssda__kernel_name(),
           have_aubio() ? "" : " (aubio not found: YIN rows missing)");
    print_header();
    if (o.synth && (r = run_synthetic(&o, &synth_all)) != 0) {
        if (r < 0) {
            return 1;
        }
        status = 1;
    }
    for (i = 0; i < nfiles; i++) {
        group_t g;
        char *audio = files[i];
        memset(&g, 0, sizeof g);
        r = run_file(&o, audio, &g, &real_all);
        status = r != 0 ? 1 : status;
        if (r != 2 && (o.per_file || nfiles == 1)) {
            const char *base = strrchr(audio, '/');
            print_group(base ? base + 1 : audio, &g);
        }
    }
    if (nfiles > 1) {
        print_group("**files, all**", &real_all);
    }
    if (o.full_check) {
        printf("\nEarly exit and tracking vs full search (no early exit): %zu of %zu frames differ%s\n",
               synth_all.full_mismatch + real_all.full_mismatch,
               synth_all.full_checked + real_all.full_checked,
               synth_all.full_mismatch + real_all.full_mismatch == 0 ? " (bit-identical, as claimed)" : " (BUG)");
        if (synth_all.full_mismatch + real_all.full_mismatch != 0) {
            status = 1;
        }
    }
    free(files);
    return status;
}
