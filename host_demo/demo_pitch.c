/* demo_pitch.c - AMDF pitch with SSDA early exit: accuracy against the truth
   (or a reference), work against the full search, and the plot. */
#include "demo.h"
#include "draw.h"
#include "pitch_run.h"

#include <stdlib.h>
#include <string.h>

/* Every output except the work counter must equal the full search's. */
static int same_track(const pitch_track_t *a, const pitch_track_t *b)
{
    size_t i;
    if (a->n != b->n) {
        return 0;
    }
    for (i = 0; i < a->n; i++) {
        if (a->f0[i] != b->f0[i] || a->voiced[i] != b->voiced[i] ||
            a->confidence_q15[i] != b->confidence_q15[i] || a->f0_raw[i] != b->f0_raw[i]) {
            return 0;
        }
    }
    return 1;
}

/* The reference: the truth every 5 ms (synthetic), or ref_csv (may be
   NULL: none). Returns 0 or -1 (said). */
static int load_reference(const demo_signal_t *sig, int synthetic, const char *ref_csv,
                          double **rt, double **rf, size_t *rn)
{
    char err[512];
    size_t i;
    if (synthetic) {
        *rn = (size_t)((double)sig->count / sig->rate / 0.005) + 1u;
        *rt = malloc(*rn * sizeof **rt);
        *rf = malloc(*rn * sizeof **rf);
        if (*rt == NULL || *rf == NULL) {
            fprintf(stderr, "ssda-demo: out of memory\n");
            return -1;
        }
        for (i = 0; i < *rn; i++) {
            (*rt)[i] = 0.005 * (double)i;
            (*rf)[i] = demo_voice_f0((*rt)[i]);
        }
    } else if (ref_csv != NULL && f0_csv_read(ref_csv, rt, rf, rn, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", err);
        return -1;
    }
    return 0;
}

/* The plot: estimate in red, the truth or reference in blue. */
static int write_plot(const demo_ctx_t *c, const demo_signal_t *sig, int synthetic,
                      const pitch_track_t *fast, const pitch_track_t *full, const double *rt,
                      const double *rf, size_t rn, const char *plot_name)
{
    draw_pitch_opts_t po;
    char err[512], path[1024], sub[256];
    memset(&po, 0, sizeof po);
    po.title = synthetic ? "ssda-demo: synthetic voice with a known f0" : "ssda-demo: your sound";
    snprintf(sub, sizeof sub, "AMDF with SSDA early exit: %.1f %% of the full search's work%s",
             full->diffs ? 100.0 * (double)fast->diffs / (double)full->diffs : 0.0,
             synthetic ? "; blue = true f0" : rn ? "; blue = reference" : "");
    po.subtitle = sub;
    po.estimate.t = fast->t;
    po.estimate.f0 = fast->f0;
    po.estimate.n = fast->n;
    po.reference.t = rt;
    po.reference.f0 = rf;
    po.reference.n = rn;
    po.reference_label = synthetic ? "true f0" : "reference";
    po.samples = sig->samples;
    po.sample_count = sig->count;
    po.sample_rate = sig->rate;
    demo_path(c, plot_name, path, sizeof path);
    if (draw_pitch_png(path, &po, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", err);
        return -1;
    }
    printf("   picture  %s  (red: estimate%s)\n", path,
           synthetic ? ", blue: true f0" : rn ? ", blue: reference" : "");
    return 0;
}

/* One pitch_run with flags, timed (*secs). Returns 0 or -1 (said). */
static int timed_run(const demo_signal_t *sig, ssda_pitch_config_t *cfg, uint8_t flags,
                     pitch_track_t *tr, double *secs)
{
    char err[512];
    cfg->flags = flags;
    *secs = progress_now();
    if (pitch_run(sig->samples, sig->count, sig->rate, cfg, NULL, tr, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", err);
        return -1;
    }
    *secs = progress_now() - *secs;
    return 0;
}

int demo_pitch(const demo_ctx_t *c, const demo_signal_t *sig, int synthetic,
               const char *ref_csv, const char *plot_name, const char *label)
{
    ssda_pitch_config_t cfg;
    pitch_track_t fast, full;
    double *rt = NULL, *rf = NULL, t_fast, t_full;
    size_t rn = 0, i, voiced = 0;
    int rc = -1;

    memset(&fast, 0, sizeof fast);
    memset(&full, 0, sizeof full);
    memset(&cfg, 0, sizeof cfg);
    { /* 10 ms at the analysed rate (pitch_run reduces rates above 48 kHz) */
        uint32_t f = (sig->rate + SSDA_PITCH_RATE_MAX - 1u) / SSDA_PITCH_RATE_MAX;
        cfg.hop = (uint16_t)((sig->rate + f / 2u) / f / 100u);
    }
    printf("   input    %s\n", label);
    if (timed_run(sig, &cfg, SSDA_PITCH_TRACK, &fast, &t_fast) != 0 ||
        timed_run(sig, &cfg, SSDA_PITCH_FULL, &full, &t_full) != 0 ||
        load_reference(sig, synthetic, ref_csv, &rt, &rf, &rn) != 0) {
        goto done;
    }
    for (i = 0; i < fast.n; i++) {
        voiced += fast.voiced[i];
    }
    printf("   frames   %zu estimates every %.0f ms (f0 searched in 50..1000 Hz), %zu voiced\n",
           fast.n, 1000.0 * fast.info.hop / fast.info.sample_rate_hz, voiced);
    if (rn > 0) {
        pitch_score_t sc;
        pitch_score(&fast, rt, rf, rn, &sc);
        printf("   accuracy gross errors (off by > 20 %%) %.1f %% of %zu frames voiced in both; "
               "voicing\n            decisions wrong in %.1f %% of frames; fine error %.1f cents "
               "(%s)\n",
               100.0 * sc.gpe, sc.both_voiced, 100.0 * sc.vde, sc.fpe_cents,
               synthetic ? "against the known f0" : "against the reference");
    }
    /* the full search is the run without early exit, on the same frames */
    printf("   saving   %.1f M of %.1f M differences = %.1f %% of the full search (%.1f ms "
           "vs %.1f ms);\n            %s\n",
           fast.diffs / 1e6, full.diffs / 1e6,
           full.diffs ? 100.0 * (double)fast.diffs / (double)full.diffs : 0.0,
           1e3 * t_fast, 1e3 * t_full,
           same_track(&fast, &full) ? "every estimate identical to the full search (checked)"
                                    : "WARNING: estimates differ from the full search");
    rc = write_plot(c, sig, synthetic, &fast, &full, rt, rf, rn, plot_name);
done:
    pitch_track_free(&fast);
    pitch_track_free(&full);
    free(rt);
    free(rf);
    return rc;
}
