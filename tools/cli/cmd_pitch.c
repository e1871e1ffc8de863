/* cmd_pitch.c - `ssda pitch IN.wav`: f0 track by AMDF with SSDA early exit. */
#include "cli.h"
#include "draw.h"
#include "pitch_run.h"
#include "wav_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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
    "                   (default 0.3)\n"
    "  --voicing N      voiced when the dip is at or below N, 0 < N < 1 (default:\n"
    "                   --threshold)\n"
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
    "  --ref REF.csv    a reference track (time_s,f0_hz rows, f0 0 = unvoiced; a\n"
    "                   header line is optional): drawn in the plot and scored\n"
    "                   (GPE, VDE, fine error in cents)\n"
    "  --quiet          no progress bar\n"
    "  -h, --help       this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void write_csv(FILE *f, const pitch_track_t *tr)
{
    size_t i;
    fprintf(f, "time_s,f0_hz,voiced,confidence,center_s\n");
    for (i = 0; i < tr->n && !ferror(f); i++) { /* stop at a closed pipe */
        fprintf(f, "%.6f,%.3f,%d,%.4f,%.6f\n", tr->t_frame[i], tr->f0[i], tr->voiced[i],
                tr->confidence_q15[i] / 32768.0, tr->t[i]);
    }
}

int cmd_pitch(int argc, char **argv)
{
    cli_args_t a;
    cli_outputs_t out;
    FILE *f;
    const char *v, *csv = NULL, *plot = NULL, *ref_path = NULL;
    double fmin = 0, fmax = 0, hop_ms = 10.0, frame_ms = 0, thr = 0, voicing = 0;
    int quiet = 0, full = 0, rc = CLI_INPUT;
    int16_t *x = NULL;
    size_t n = 0, i, nv = 0;
    uint32_t rate = 0;
    wav_info_t winfo;
    ssda_pitch_config_t cfg;
    pitch_track_t tr;
    progress_t prog;
    double *rt = NULL, *rf = NULL, *voiced_f0 = NULL, t0, secs;
    size_t rn = 0;
    char err[512];

    memset(&tr, 0, sizeof tr);
    cli_outputs_begin(&out, "pitch");
    cli_args_begin(&a, "pitch", argc, argv);
    while (cli_next(&a)) {
        if (cli_flag(&a, "--help") || cli_flag(&a, "-h")) {
            fputs(help, stdout);
            return CLI_OK;
        } else if (cli_opt(&a, "--fmin", &v)) {
            if (v != NULL && cli_parse_double(v, 10, 12000, &fmin) != 0) {
                return cli_usage_error(a.cmd, "bad --fmin '%s' (10..12000 Hz)", v);
            }
        } else if (cli_opt(&a, "--fmax", &v)) {
            if (v != NULL && cli_parse_double(v, 11, 12000, &fmax) != 0) {
                return cli_usage_error(a.cmd, "bad --fmax '%s' (11..12000 Hz)", v);
            }
        } else if (cli_opt(&a, "--hop-ms", &v)) {
            if (v != NULL && cli_parse_double(v, 0.01, 10000, &hop_ms) != 0) {
                return cli_usage_error(a.cmd, "bad --hop-ms '%s' (0.01..10000)", v);
            }
        } else if (cli_opt(&a, "--frame-ms", &v)) {
            if (v != NULL && cli_parse_double(v, 0.01, 1000, &frame_ms) != 0) {
                return cli_usage_error(a.cmd, "bad --frame-ms '%s' (0.01..1000)", v);
            }
        } else if (cli_opt(&a, "--threshold", &v)) {
            if (v != NULL && cli_parse_double(v, 0.0001, 0.9999, &thr) != 0) {
                return cli_usage_error(a.cmd, "bad --threshold '%s' (above 0, below 1)", v);
            }
        } else if (cli_opt(&a, "--voicing", &v)) {
            if (v != NULL && cli_parse_double(v, 0.0001, 0.9999, &voicing) != 0) {
                return cli_usage_error(a.cmd, "bad --voicing '%s' (above 0, below 1)", v);
            }
        } else if (cli_flag(&a, "--full")) {
            full = 1;
        } else if (cli_opt(&a, "--csv", &v)) {
            csv = v;
        } else if (cli_opt(&a, "--plot", &v)) {
            plot = v;
        } else if (cli_opt(&a, "--ref", &v)) {
            ref_path = v;
        } else if (cli_flag(&a, "--quiet") || cli_flag(&a, "-q")) {
            quiet = 1;
        } else {
            return cli_unknown(&a);
        }
        if (a.bad) {
            return CLI_USAGE;
        }
    }
    if (a.bad) {
        return CLI_USAGE;
    }
    if (a.npos != 1) {
        return cli_usage_error(a.cmd, "need one sound file");
    }
    /* with the defaults filled in, so that --fmin 3000 alone is a usage
       error too, not a refusal after the file is read */
    if ((fmin > 0 ? fmin : (double)SSDA_PITCH_DEFAULT_F0_MIN) >=
        (fmax > 0 ? fmax : (double)SSDA_PITCH_DEFAULT_F0_MAX)) {
        return cli_usage_error(a.cmd, "--fmin (%g Hz) must be below --fmax (%g Hz%s)",
                               fmin > 0 ? fmin : (double)SSDA_PITCH_DEFAULT_F0_MIN,
                               fmax > 0 ? fmax : (double)SSDA_PITCH_DEFAULT_F0_MAX,
                               fmax > 0 ? "" : ", the default");
    }
    if (cli_is_stdout(csv) && cli_is_stdout(plot)) {
        return cli_usage_error(a.cmd, "--csv and --plot cannot both go to stdout");
    }
    cli_warn_png_name(a.cmd, "--plot", plot);
    if (cli_output_check(a.cmd, csv) != 0 || cli_output_check(a.cmd, plot) != 0) {
        return CLI_INPUT;
    }
    if (wav_read_mono_i16_ex(a.pos[0], &x, &n, &rate, &winfo, err, sizeof err) != 0) {
        return cli_input_error(a.cmd, "%s", err);
    }
    if (ref_path != NULL && f0_csv_read(ref_path, &rt, &rf, &rn, err, sizeof err) != 0) {
        cli_input_error(a.cmd, "%s", err);
        goto done;
    }

    memset(&cfg, 0, sizeof cfg);
    {
        /* the analysed rate (after reducing rates above 48 kHz) sets the sample counts */
        uint32_t f = rate > SSDA_PITCH_RATE_MAX
                         ? (rate + SSDA_PITCH_RATE_MAX - 1u) / SSDA_PITCH_RATE_MAX
                         : 1u;
        double arate = (double)((rate + f / 2u) / f);
        double hop = floor(hop_ms * arate / 1000.0 + 0.5);
        double k = floor(frame_ms * arate / 1000.0 + 0.5);
        if (hop < 1 || hop > 65535) {
            rc = cli_usage_error(a.cmd, "--hop-ms %g is %.0f samples at %.0f Hz (1..65535)",
                                 hop_ms, hop, arate);
            goto done;
        }
        if (frame_ms > 0 && (k < SSDA_PITCH_FRAME_MIN || k > SSDA_PITCH_FRAME_MAX)) {
            rc = cli_usage_error(a.cmd, "--frame-ms %g is %.0f samples at %.0f Hz (%u..%u)",
                                 frame_ms, k, arate, SSDA_PITCH_FRAME_MIN,
                                 SSDA_PITCH_FRAME_MAX);
            goto done;
        }
        if (fmax > arate / 4.0) {
            rc = cli_usage_error(a.cmd, "--fmax %g is above a quarter of the %.0f Hz rate", fmax,
                                 arate);
            goto done;
        }
        cfg.hop = (uint16_t)hop;
        cfg.frame_len = (uint16_t)k;
    }
    cfg.f0_min_hz = (uint16_t)floor(fmin);
    cfg.f0_max_hz = (uint16_t)ceil(fmax);
    cfg.threshold_q15 = (uint16_t)lround(thr * 32768.0);
    cfg.voicing_q15 = (uint16_t)lround(voicing * 32768.0);
    cfg.flags = full ? SSDA_PITCH_FULL : SSDA_PITCH_TRACK;

    progress_begin(&prog, "pitch", n, quiet);
    t0 = progress_now();
    if (pitch_run(x, n, rate, &cfg, &prog, &tr, err, sizeof err) != 0) {
        progress_end(&prog);
        cli_input_error(a.cmd, "'%s': %s", a.pos[0], err);
        goto done;
    }
    secs = progress_now() - t0;
    progress_end(&prog);

    if (csv != NULL) {
        if ((f = cli_outputs_open(&out, csv)) == NULL) {
            goto done;
        }
        write_csv(f, &tr);
    }
    if (plot != NULL) {
        draw_pitch_opts_t po;
        char title[256], sub[256];
        memset(&po, 0, sizeof po);
        snprintf(title, sizeof title, "ssda pitch  %s", cli_basename(a.pos[0]));
        snprintf(sub, sizeof sub,
                 "AMDF with SSDA early exit, f0 %g..%g Hz, hop %.1f ms: work %.1f %% of "
                 "full-search AMDF",
                 fmin > 0 ? fmin : (double)SSDA_PITCH_DEFAULT_F0_MIN,
                 fmax > 0 ? fmax : (double)SSDA_PITCH_DEFAULT_F0_MAX,
                 1000.0 * tr.info.hop / tr.info.sample_rate_hz,
                 tr.full_diffs ? 100.0 * (double)tr.diffs / (double)tr.full_diffs : 0.0);
        po.title = title;
        po.subtitle = sub;
        po.estimate.t = tr.t;
        po.estimate.f0 = tr.f0;
        po.estimate.n = tr.n;
        po.reference.t = rt;
        po.reference.f0 = rf;
        po.reference.n = rn;
        po.samples = x;
        po.sample_count = n;
        po.sample_rate = rate;
        if ((f = cli_outputs_open(&out, plot)) == NULL) {
            goto done;
        }
        if (draw_pitch_to(f, plot, &po, err, sizeof err) != 0) {
            cli_input_error(a.cmd, "%s", err);
            goto done;
        }
    }
    if (cli_outputs_commit(&out) != CLI_OK) {
        goto done;
    }
    if (!cli_is_stdout(csv) && !cli_is_stdout(plot)) {
        voiced_f0 = malloc((tr.n + 1u) * sizeof *voiced_f0);
        if (voiced_f0 == NULL) {
            cli_input_error(a.cmd, "out of memory");
            goto done;
        }
        for (i = 0; i < tr.n; i++) {
            if (tr.voiced[i]) {
                voiced_f0[nv++] = tr.f0[i];
            }
        }
        qsort(voiced_f0, nv, sizeof *voiced_f0, cmp_double);
        printf("%s: %.2f s, %u Hz, %u channel%s (%s)%s\n", a.pos[0], (double)n / rate, rate,
               winfo.channels, winfo.channels == 1 ? "" : "s mixed to mono", winfo.format_name,
               tr.decimation > 1 ? ", analysed at reduced rate" : "");
        printf("frames:  %zu every %.1f ms; %zu voiced (%.1f %%)\n", tr.n,
               1000.0 * tr.info.hop / tr.info.sample_rate_hz, nv,
               tr.n ? 100.0 * (double)nv / (double)tr.n : 0.0);
        if (nv > 0) {
            printf("f0:      median %.1f Hz, 10-90 %% range %.1f .. %.1f Hz\n", voiced_f0[nv / 2],
                   voiced_f0[nv / 10], voiced_f0[(nv * 9) / 10]);
        }
        printf("work:    %llu differences = %.2f %% of full-search AMDF (%llu); %.3f s\n",
               (unsigned long long)tr.diffs,
               tr.full_diffs ? 100.0 * (double)tr.diffs / (double)tr.full_diffs : 0.0,
               (unsigned long long)tr.full_diffs, secs);
        if (rn > 0) {
            pitch_score_t sc;
            pitch_score(&tr, rt, rf, rn, &sc);
            printf("vs %s: GPE %.2f %% (of %zu frames voiced in both), VDE %.2f %%, "
                   "fine error %.1f cents\n",
                   ref_path, 100.0 * sc.gpe, sc.both_voiced, 100.0 * sc.vde, sc.fpe_cents);
        }
        if (csv != NULL) {
            printf("wrote:   %s\n", csv);
        }
        if (plot != NULL) {
            printf("wrote:   %s\n", plot);
        }
    }
    rc = CLI_OK;
done:
    cli_outputs_abort(&out);
    pitch_track_free(&tr);
    free(voiced_f0);
    free(rt);
    free(rf);
    free(x);
    return rc;
}
