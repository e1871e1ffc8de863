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

int demo_pitch(const demo_ctx_t *c, const demo_signal_t *sig, int synthetic,
               const char *ref_csv, const char *plot_name, const char *label)
{
    ssda_pitch_config_t cfg;
    pitch_track_t fast, full;
    double *rt = NULL, *rf = NULL, t_fast, t_full;
    size_t rn = 0, i, voiced = 0;
    char err[512], path[1024], sub[256];
    int rc = -1;

    memset(&fast, 0, sizeof fast);
    memset(&full, 0, sizeof full);
    memset(&cfg, 0, sizeof cfg);
    { /* 10 ms at the analysed rate (pitch_run reduces rates above 48 kHz) */
        uint32_t f = (sig->rate + SSDA_PITCH_RATE_MAX - 1u) / SSDA_PITCH_RATE_MAX;
        cfg.hop = (uint16_t)((sig->rate + f / 2u) / f / 100u);
    }
    cfg.flags = SSDA_PITCH_TRACK;
    printf("   input    %s\n", label);

    t_fast = progress_now();
    if (pitch_run(sig->samples, sig->count, sig->rate, &cfg, NULL, &fast, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", err);
        goto done;
    }
    t_fast = progress_now() - t_fast;
    cfg.flags = SSDA_PITCH_FULL;
    t_full = progress_now();
    if (pitch_run(sig->samples, sig->count, sig->rate, &cfg, NULL, &full, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", err);
        goto done;
    }
    t_full = progress_now() - t_full;
    for (i = 0; i < fast.n; i++) {
        voiced += fast.voiced[i];
    }

    if (synthetic) { /* the truth every 5 ms */
        rn = (size_t)((double)sig->count / sig->rate / 0.005) + 1u;
        rt = malloc(rn * sizeof *rt);
        rf = malloc(rn * sizeof *rf);
        if (rt == NULL || rf == NULL) {
            fprintf(stderr, "ssda-demo: out of memory\n");
            goto done;
        }
        for (i = 0; i < rn; i++) {
            rt[i] = 0.005 * (double)i;
            rf[i] = demo_voice_f0(rt[i]);
        }
    } else if (ref_csv != NULL && f0_csv_read(ref_csv, &rt, &rf, &rn, err, sizeof err) != 0) {
        fprintf(stderr, "ssda-demo: %s\n", err);
        goto done;
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
    {
        draw_pitch_opts_t po;
        memset(&po, 0, sizeof po);
        po.title = synthetic ? "ssda-demo: synthetic voice with a known f0" : "ssda-demo: your sound";
        snprintf(sub, sizeof sub, "AMDF with SSDA early exit: %.1f %% of the full search's work%s",
                 full.diffs ? 100.0 * (double)fast.diffs / (double)full.diffs : 0.0,
                 synthetic ? "; blue = true f0" : rn ? "; blue = reference" : "");
        po.subtitle = sub;
        po.estimate.t = fast.t;
        po.estimate.f0 = fast.f0;
        po.estimate.n = fast.n;
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
            goto done;
        }
        printf("   picture  %s  (red: estimate%s)\n", path,
               synthetic ? ", blue: true f0" : rn ? ", blue: reference" : "");
    }
    rc = 0;
done:
    pitch_track_free(&fast);
    pitch_track_free(&full);
    free(rt);
    free(rf);
    return rc;
}
