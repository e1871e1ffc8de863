/* cmd_pitch.c - `ssda pitch IN.wav`: f0 track by AMDF with SSDA early exit. */
#include "cli.h"
#include "draw.h"
#include "pitch_run.h"
#include "wav_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static const char help[] =
    "usage: ssda pitch IN.wav [options]\n"
    "\n"
    "Fundamental frequency (f0) track of a sound file by the average magnitude\n"
    "difference function with SSDA early exit (the seed's appendix). Any format\n"
    "libsndfile reads (WAV, AIFF, FLAC, OGG...); channels are mixed to mono; rates\n"
    "above 48 kHz are reduced by averaging; 8 kHz is the lowest rate accepted.\n"
    "\n"
    "options:\n"
    "  --fmin HZ        lowest f0 searched (default 50)\n"
    "  --fmax HZ        highest f0 searched (default 1000, at most rate/4)\n"
    "  --hop-ms MS      time between estimates (default 10)\n"
    "  --frame-ms MS    samples summed per lag, as time (default one period of fmin)\n"
    "  --threshold N    dip threshold on the normalised difference, 0 < N < 1\n"
    "                   (default 0.3); a frame is voiced only with a dip below it\n"
    "  --voicing N      voiced when the dip is at or below N, 0 < N <= --threshold\n"
    "                   (default: --threshold; above it, it could change nothing)\n"
    "  --silence LEVEL  frames quieter than a sine of this peak are silent, not\n"
    "                   searched: LEVEL in dBFS (-50dB) or in 16-bit sample units\n"
    "                   (100); 0: only constant frames. Default: 40 dB below the\n"
    "                   file's peak, at most the library's -62 dBFS (25)\n"
    "  --full           no early exit: every lag summed in full (the reference;\n"
    "                   same results, more work)\n"
    "  --csv FILE|-     write time_s,f0_hz,voiced,confidence,center_s rows (f0 0 when\n"
    "                   unvoiced; time_s = centre of the frame, center_s = centre of\n"
    "                   the samples its chosen lag compared; confidence = 1 - the\n"
    "                   normalised difference at that lag, 0 when silent: an\n"
    "                   unvoiced frame can score high when no accepted dip was\n"
    "                   found (slow breath or hum with no peak after lag 0, a period\n"
    "                   outside fmin..fmax); select frames by voiced)\n"
    "  --plot OUT.png   draw the f0 track over time, with the waveform\n"
    "  --ref REF.csv    a reference track, drawn in the plot and scored (GPE, VDE,\n"
    "                   fine error in cents): time_s,f0_hz rows (commas, semicolons,\n"
    "                   tabs or spaces; a header line optional; times in seconds,\n"
    "                   increasing; f0 0 = unvoiced)\n"
    "  --ref-hop S      REF holds one f0 per line, frame i at i x S seconds\n"
    "  --quiet          no progress bar\n"
    "  -h, --help       this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

typedef struct {
    const char *sound, *csv, *plot, *ref_path;
    double fmin, fmax, hop_ms, frame_ms, thr, voicing, ref_hop; /* 0: default */
    int have_silence;
    double silence_peak; /* --silence as a sine's peak, 16-bit units */
    int quiet, full;
} pitch_opts_t;

/* One run: its inputs and results (released by job_free). */
typedef struct {
    int16_t *x;
    size_t n;
    uint32_t rate;
    wav_info_t winfo;
    double *rt, *rf; /* reference, rn rows */
    size_t rn;
    ssda_pitch_config_t cfg;
    int silence_relative; /* the gate came from the file's peak */
    pitch_track_t tr;
    double secs;
} pitch_job_t;

static void job_free(pitch_job_t *j)
{
    pitch_track_free(&j->tr);
    free(j->x);
    free(j->rt);
    free(j->rf);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* ---- options ---- */

/* "-50dB", "-50dBFS" (<= 0) or a sample level 0..32767: a sine's peak. */
static int parse_silence(const char *s, double *peak)
{
    char buf[32];
    size_t n = strlen(s);
    double v;
    if (n >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    if (n > 4 && strcmp(buf + n - 4, "dBFS") == 0) {
        buf[n - 4] = '\0';
    } else if (n > 2 && strcmp(buf + n - 2, "dB") == 0) {
        buf[n - 2] = '\0';
    } else {
        return cli_parse_double(buf, 0.0, 32767.0, peak);
    }
    if (cli_parse_double(buf, -200.0, 0.0, &v) != 0) {
        return -1;
    }
    *peak = 32768.0 * pow(10.0, v / 20.0);
    return 0;
}

/* A double option in [lo, hi]: 1 when the current option is name. */
static int opt_double(cli_args_t *a, const char *name, double lo, double hi, const char *range,
                      double *out)
{
    const char *v;
    if (!cli_opt(a, name, &v)) {
        return 0;
    }
    if (v != NULL && cli_parse_double(v, lo, hi, out) != 0) {
        cli_usage_error(a->cmd, "bad %s '%s' (%s)", name, v, range);
        a->bad = 1;
    }
    return 1;
}

static void print_help(void)
{
    fputs(help, stdout);
}

/* The current option into opts (a pitch_opts_t): 1 taken (a->bad set on a bad
   value, said), 0 unknown. */
static int take_option(cli_args_t *a, void *opts)
{
    pitch_opts_t *o = opts;
    const char *v;
    if (opt_double(a, "--fmin", 10, 12000, "10..12000 Hz", &o->fmin) ||
        opt_double(a, "--fmax", 11, 12000, "11..12000 Hz", &o->fmax) ||
        opt_double(a, "--hop-ms", 0.01, 10000, "0.01..10000", &o->hop_ms) ||
        opt_double(a, "--frame-ms", 0.01, 1000, "0.01..1000", &o->frame_ms) ||
        opt_double(a, "--threshold", 0.0001, 0.9999, "above 0, below 1", &o->thr) ||
        opt_double(a, "--voicing", 0.0001, 0.9999, "above 0, below 1", &o->voicing) ||
        opt_double(a, "--ref-hop", 0.0001, 60, "seconds, above 0", &o->ref_hop)) {
        return 1;
    }
    if (cli_opt(a, "--silence", &v)) {
        if (v != NULL && parse_silence(v, &o->silence_peak) != 0) {
            cli_usage_error(a->cmd, "bad --silence '%s' (dBFS as -50dB, or a sample level "
                            "0..32767)", v);
            a->bad = 1;
        }
        o->have_silence = 1;
    } else if (cli_flag(a, "--full")) {
        o->full = 1;
    } else if (cli_opt(a, "--csv", &v)) {
        o->csv = v;
    } else if (cli_opt(a, "--plot", &v)) {
        o->plot = v;
    } else if (cli_opt(a, "--ref", &v)) {
        o->ref_path = v;
    } else if (cli_flag(a, "--quiet") || cli_flag(a, "-q")) {
        o->quiet = 1;
    } else {
        return 0;
    }
    return 1;
}

/* Combinations refused before any file is read (defaults filled in, so
   that --fmin 3000 alone is a usage error too). Returns CLI_OK or CLI_USAGE. */
static int check_options(const char *cmd, const pitch_opts_t *o)
{
    double fmin = o->fmin > 0 ? o->fmin : (double)SSDA_PITCH_DEFAULT_F0_MIN;
    double fmax = o->fmax > 0 ? o->fmax : (double)SSDA_PITCH_DEFAULT_F0_MAX;
    /* in Q15, as the library compares them */
    long thr_q15 = o->thr > 0 ? lround(o->thr * 32768.0) : (long)SSDA_PITCH_DEFAULT_THRESHOLD_Q15;
    if (fmin >= fmax) {
        return cli_usage_error(cmd, "--fmin (%g Hz) must be below --fmax (%g Hz%s)", fmin, fmax,
                               o->fmax > 0 ? "" : ", the default");
    }
    if (lround(o->voicing * 32768.0) > thr_q15) {
        /* a frame needs a dip at or below the threshold to be voiced at all */
        return cli_usage_error(cmd, "--voicing %g is above the dip threshold %.4g%s, so it could "
                               "change nothing (a frame is voiced only with a dip at or below "
                               "the threshold); raise --threshold to accept weaker dips",
                               o->voicing, thr_q15 / 32768.0, o->thr > 0 ? "" : " (the default)");
    }
    if (o->ref_hop > 0 && o->ref_path == NULL) {
        return cli_usage_error(cmd, "--ref-hop needs --ref");
    }
    if (cli_is_stdout(o->csv) && cli_is_stdout(o->plot)) {
        return cli_usage_error(cmd, "--csv and --plot cannot both go to stdout");
    }
    return CLI_OK;
}

/* Parse argv into o. Returns CLI_OK, CLI_USAGE, or -1 after --help. */
static int parse_args(int argc, char **argv, pitch_opts_t *o)
{
    cli_args_t a;
    int rc;
    memset(o, 0, sizeof *o);
    o->hop_ms = 10.0;
    cli_args_begin(&a, "pitch", argc, argv);
    if ((rc = cli_scan_options(&a, print_help, take_option, o)) != CLI_OK) {
        return rc;
    }
    if (cli_positionals(&a, 1, "need one sound file") != CLI_OK) {
        return CLI_USAGE;
    }
    o->sound = a.pos[0];
    return check_options(a.cmd, o);
}

/* ---- the run ---- */

/* Hop, frame length and f0 range in samples at the analysed rate. */
static int configure(const pitch_opts_t *o, uint32_t rate, ssda_pitch_config_t *cfg)
{
    /* the analysed rate (after reducing rates above 48 kHz) sets the sample counts */
    uint32_t f = rate > SSDA_PITCH_RATE_MAX ? (rate + SSDA_PITCH_RATE_MAX - 1u) / SSDA_PITCH_RATE_MAX
                                            : 1u;
    double arate = (double)((rate + f / 2u) / f);
    double hop = floor(o->hop_ms * arate / 1000.0 + 0.5);
    double k = floor(o->frame_ms * arate / 1000.0 + 0.5);
    if (hop < 1 || hop > 65535) {
        return cli_usage_error("pitch", "--hop-ms %g is %.0f samples at %.0f Hz (1..65535)",
                               o->hop_ms, hop, arate);
    }
    if (o->frame_ms > 0 && (k < SSDA_PITCH_FRAME_MIN || k > SSDA_PITCH_FRAME_MAX)) {
        return cli_usage_error("pitch", "--frame-ms %g is %.0f samples at %.0f Hz (%u..%u)",
                               o->frame_ms, k, arate, SSDA_PITCH_FRAME_MIN, SSDA_PITCH_FRAME_MAX);
    }
    if (o->fmax > arate / 4.0) {
        return cli_usage_error("pitch", "--fmax %g is above a quarter of the %.0f Hz rate",
                               o->fmax, arate);
    }
    memset(cfg, 0, sizeof *cfg);
    cfg->hop = (uint16_t)hop;
    cfg->frame_len = (uint16_t)k;
    cfg->f0_min_hz = (uint16_t)floor(o->fmin);
    cfg->f0_max_hz = (uint16_t)ceil(o->fmax);
    cfg->threshold_q15 = (uint16_t)lround(o->thr * 32768.0);
    cfg->voicing_q15 = (uint16_t)lround(o->voicing * 32768.0);
    cfg->flags = o->full ? SSDA_PITCH_FULL : SSDA_PITCH_TRACK;
    return CLI_OK;
}

/* The silence gate as the library's mean absolute deviation (a sine of
   peak a has 2a / pi). Default: a sine 40 dB below the file's peak, at
   most the library's default, so that a quiet clean recording is not
   gated away (peak 100: the gate falls to constant frames only) while a
   normal one keeps the library's gate. */
static uint16_t silence_gate(const pitch_opts_t *o, const int16_t *x, size_t n, int *relative)
{
    double peak = o->silence_peak, mad;
    size_t i;
    *relative = !o->have_silence;
    if (*relative) {
        int32_t m = 0;
        for (i = 0; i < n; i++) {
            int32_t v = x[i] < 0 ? -(int32_t)x[i] : x[i];
            m = v > m ? v : m;
        }
        peak = m * 0.01; /* -40 dB */
    }
    mad = floor(2.0 * peak / PI + 0.5);
    if (*relative && mad > SSDA_PITCH_DEFAULT_SILENCE_MAD) {
        mad = SSDA_PITCH_DEFAULT_SILENCE_MAD;
    }
    return (uint16_t)(mad < 1.0 ? 1.0 : mad > 65535.0 ? 65535.0 : mad);
}

/* Read the sound and the reference, configure and analyse. */
static int analyse(const pitch_opts_t *o, pitch_job_t *j)
{
    char err[512];
    progress_t prog;
    double t0;
    int rc;
    if (wav_read_mono_i16_ex(o->sound, &j->x, &j->n, &j->rate, &j->winfo, err, sizeof err) != 0) {
        return cli_input_error("pitch", "%s", err);
    }
    if (o->ref_path != NULL &&
        f0_ref_read(o->ref_path, o->ref_hop, &j->rt, &j->rf, &j->rn, err, sizeof err) != 0) {
        return cli_input_error("pitch", "%s", err);
    }
    if ((rc = configure(o, j->rate, &j->cfg)) != CLI_OK) {
        return rc;
    }
    j->cfg.silence_mad = silence_gate(o, j->x, j->n, &j->silence_relative);
    progress_begin(&prog, "pitch", j->n, o->quiet);
    t0 = progress_now();
    rc = pitch_run(j->x, j->n, j->rate, &j->cfg, &prog, &j->tr, err, sizeof err);
    j->secs = progress_now() - t0;
    progress_end(&prog);
    if (rc != 0) {
        return cli_input_error("pitch", "'%s': %s", o->sound, err);
    }
    return CLI_OK;
}

/* The share of the full search this run computed: --full is the full search. */
static double work_pct(const pitch_opts_t *o, const pitch_track_t *tr)
{
    uint64_t base = o->full ? tr->diffs : tr->full_diffs;
    return base ? 100.0 * (double)tr->diffs / (double)base : 0.0;
}

/* ---- outputs ---- */

static void write_csv(FILE *f, const pitch_track_t *tr)
{
    size_t i;
    fprintf(f, "time_s,f0_hz,voiced,confidence,center_s\n");
    for (i = 0; i < tr->n && !ferror(f); i++) { /* stop at a closed pipe */
        fprintf(f, "%.6f,%.3f,%d,%.4f,%.6f\n", tr->t_frame[i], tr->f0[i], tr->voiced[i],
                tr->confidence_q15[i] / 32768.0, tr->t[i]);
    }
}

static int write_plot(FILE *f, const pitch_opts_t *o, const pitch_job_t *j)
{
    draw_pitch_opts_t po;
    char title[256], sub[256], err[512];
    memset(&po, 0, sizeof po);
    snprintf(title, sizeof title, "ssda pitch  %s", cli_basename(o->sound));
    snprintf(sub, sizeof sub,
             "AMDF with SSDA early exit, f0 %g..%g Hz, hop %.1f ms: work %.1f %% of the "
             "full search",
             o->fmin > 0 ? o->fmin : (double)SSDA_PITCH_DEFAULT_F0_MIN,
             o->fmax > 0 ? o->fmax : (double)SSDA_PITCH_DEFAULT_F0_MAX,
             1000.0 * j->tr.info.hop / j->tr.info.sample_rate_hz, work_pct(o, &j->tr));
    po.title = title;
    po.subtitle = sub;
    po.estimate.t = j->tr.t;
    po.estimate.f0 = j->tr.f0;
    po.estimate.n = j->tr.n;
    po.reference.t = j->rt;
    po.reference.f0 = j->rf;
    po.reference.n = j->rn;
    po.samples = j->x;
    po.sample_count = j->n;
    po.sample_rate = j->rate;
    if (draw_pitch_to(f, o->plot, &po, err, sizeof err) != 0) {
        return cli_input_error("pitch", "%s", err);
    }
    return CLI_OK;
}

/* --csv and --plot, all or nothing. */
static int write_outputs(const pitch_opts_t *o, const pitch_job_t *j)
{
    cli_outputs_t out;
    FILE *f;
    int rc = CLI_OK;
    cli_outputs_begin(&out, "pitch");
    if (o->csv != NULL) {
        if ((f = cli_outputs_open(&out, o->csv)) == NULL) {
            rc = CLI_INPUT;
        } else {
            write_csv(f, &j->tr);
        }
    }
    if (rc == CLI_OK && o->plot != NULL) {
        rc = (f = cli_outputs_open(&out, o->plot)) == NULL ? CLI_INPUT : write_plot(f, o, j);
    }
    rc = rc == CLI_OK ? cli_outputs_commit(&out) : rc;
    cli_outputs_abort(&out);
    return rc;
}

/* ---- summary ---- */

/* Voiced frames of a track. */
static size_t track_voiced(const pitch_track_t *tr)
{
    size_t i, nv = 0;
    for (i = 0; i < tr->n; i++) {
        nv += tr->voiced[i] != 0u;
    }
    return nv;
}

/* The score against --ref, and warnings when it cannot mean much. */
static void print_score(const pitch_opts_t *o, const pitch_job_t *j)
{
    pitch_score_t sc;
    double dur = (double)j->n / j->rate, last = j->rt[j->rn - 1];
    pitch_score(&j->tr, j->rt, j->rf, j->rn, &sc);
    printf("vs %s: GPE %.2f %% (of %zu frames voiced in both), VDE %.2f %%, fine error %.1f "
           "cents\n", o->ref_path, 100.0 * sc.gpe, sc.both_voiced, 100.0 * sc.vde,
           sc.fpe_cents);
    if (o->ref_hop <= 0 && last > 10.0 * dur + 10.0 && last / 1000.0 <= 2.0 * dur + 1.0) {
        fprintf(stderr, "ssda pitch: warning: '%s' runs to time %g while the sound lasts "
                "%.2f s: its times look like milliseconds (they must be seconds)\n",
                o->ref_path, last, dur);
    }
    if (sc.frames == 0) {
        fprintf(stderr, "ssda pitch: warning: '%s' (%g..%g s) does not overlap the track's "
                "frames (%.2f s of sound): nothing was scored\n", o->ref_path, j->rt[0], last,
                dur);
    } else if (sc.both_voiced == 0 && track_voiced(&j->tr) == 0) {
        /* the track, not the reference, has nothing voiced: say what to try */
        fprintf(stderr, "ssda pitch: warning: no frame of the track is voiced (%zu of %zu "
                "frames silent), so GPE and fine error mean nothing: try a lower --silence "
                "(a quiet recording), a higher --threshold (weak periodicity) or --fmin, "
                "--fmax around the f0 in '%s'\n", j->tr.n - j->tr.analysed, j->tr.n,
                o->ref_path);
    } else if (sc.both_voiced == 0) {
        fprintf(stderr, "ssda pitch: warning: no frame is voiced in both the track and '%s' "
                "(of %zu frames compared): GPE and fine error mean nothing; check its columns "
                "(time_s,f0_hz) and units\n", o->ref_path, sc.frames);
    }
}

static void print_summary(const pitch_opts_t *o, const pitch_job_t *j)
{
    const pitch_track_t *tr = &j->tr;
    double *v = malloc((tr->n + 1u) * sizeof *v), gate = j->cfg.silence_mad * PI / 2.0;
    size_t i, nv = 0;
    for (i = 0; v != NULL && i < tr->n; i++) {
        if (tr->voiced[i]) {
            v[nv++] = tr->f0[i];
        }
    }
    qsort(v, nv, sizeof *v, cmp_double);
    printf("%s: %.2f s, %u Hz, %u channel%s (%s)%s\n", o->sound, (double)j->n / j->rate,
           j->rate, j->winfo.channels, j->winfo.channels == 1 ? "" : "s mixed to mono",
           j->winfo.format_name, tr->decimation > 1 ? ", analysed at reduced rate" : "");
    printf("frames:  %zu every %.1f ms; %zu voiced (%.1f %%), %zu silent (below a sine of "
           "peak %.0f, %.1f dBFS%s)\n",
           tr->n, 1000.0 * tr->info.hop / tr->info.sample_rate_hz, nv,
           tr->n ? 100.0 * (double)nv / (double)tr->n : 0.0, tr->n - tr->analysed, gate,
           20.0 * log10(gate / 32768.0),
           !j->silence_relative                                    ? "; --silence"
           : j->cfg.silence_mad < SSDA_PITCH_DEFAULT_SILENCE_MAD ? "; 40 dB below this file's peak"
                                                                   : "");
    if (nv > 0) {
        printf("f0:      median %.1f Hz, 10-90 %% range %.1f .. %.1f Hz\n", v[nv / 2], v[nv / 10],
               v[(nv * 9) / 10]);
    }
    printf("work:    %llu differences = %.2f %% of the full search (%llu: every lag summed on "
           "the %zu analysed frames%s); %.3f s\n",
           (unsigned long long)tr->diffs, work_pct(o, tr),
           (unsigned long long)(o->full ? tr->diffs : tr->full_diffs), tr->analysed,
           o->full ? ", this run" : "", j->secs);
    if (j->rn > 0) {
        print_score(o, j);
    }
    if (o->csv != NULL) {
        printf("wrote:   %s\n", o->csv);
    }
    if (o->plot != NULL) {
        printf("wrote:   %s\n", o->plot);
    }
    free(v);
}

int cmd_pitch(int argc, char **argv)
{
    pitch_opts_t o;
    pitch_job_t j;
    int rc = parse_args(argc, argv, &o);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc; /* -1: --help */
    }
    cli_warn_png_name("pitch", "--plot", o.plot);
    if (cli_output_check("pitch", o.csv) != 0 || cli_output_check("pitch", o.plot) != 0) {
        return CLI_INPUT;
    }
    memset(&j, 0, sizeof j);
    rc = analyse(&o, &j);
    if (rc == CLI_OK) {
        rc = write_outputs(&o, &j);
    }
    if (rc == CLI_OK && !cli_is_stdout(o.csv) && !cli_is_stdout(o.plot)) {
        print_summary(&o, &j);
    }
    job_free(&j);
    return rc;
}
