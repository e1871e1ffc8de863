/* cmd_segment.c - `ssda segment IN.png`: colour segmentation by the K-L
   transform and Gaussian-mixture histogram models (seed 004). The work is
   in segment_run.c; this file parses options and writes the outputs. */
#include "cli.h"
#include "draw_seg.h"
#include "segment_run.h"

#include "json_out.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: ssda segment IN.png [-o LABELS.png] [options]\n"
    "\n"
    "Colour segmentation as Fujimoto and Tanaka's seed (docs/segmentation.md): the\n"
    "K-L transform of the R, G, B bands gives three decorrelated features Z1..Z3\n"
    "(Z1 about the brightness); the histogram of each is modelled as a sum of\n"
    "Gaussians; each pixel is labelled with the component whose +-2 sigma band\n"
    "holds its feature value (label 0: none), isolated points are removed, and\n"
    "every region's area is its pixel count. A gray PNG is its own feature (the\n"
    "histogram part alone). Labels are numbered by increasing mean.\n"
    "\n"
    "outputs (written only if everything succeeds):\n"
    "  -o, --output F      8-bit gray PNG of labels 0..K; with several features,\n"
    "                      one per feature, F with -z1, -z2, -z3 before .png\n"
    "  --json F            per feature: the K-L matrix and vectors, and per\n"
    "                      component weight, mean, sigma, pixels (\"-\": stdout)\n"
    "  --plot F            PNG: each histogram with its fitted components and their\n"
    "                      sum (the seed's Figs. 2.3-2.5)\n"
    "  --picture F         PNG: the labels colour-coded, one panel per feature, with\n"
    "                      legends\n"
    "  --features F        16-bit gray PNG of each feature's values (the histogram\n"
    "                      bins before the shift; nodata 65535), named as -o\n"
    "\n"
    "options:\n"
    "  --components S      auto (by BIC, default), N (every feature) or N1,N2,N3\n"
    "                      (per feature; the seed used 6,5,4); 1..16\n"
    "  --max-components N  automatic choice up to N, 1..16 (default 8)\n"
    "  --fit em|search     EM on the histogram (default), or the seed's coordinate\n"
    "                      search (errors within +-2 sigma of each starting component)\n"
    "  --seed-steps        search: stop where the seed stops (no step halving)\n"
    "  --init peaks|quantiles  start: peaks and shoulders of the residual (default)\n"
    "                      or slices of equal count\n"
    "  --band 1|2|3|all    which features (default all; gray images have one)\n"
    "  --rule band|likely  labels: within +-S sigma of a component (the seed,\n"
    "                      default), or the most likely component everywhere\n"
    "  --band-sigma S      the band's half width in sigmas (default 2)\n"
    "  --matrix correlation|covariance  K-L matrix (default correlation, the seed)\n"
    "  --bins N            histogram bins, 16..4096: K-L features take values\n"
    "                      0..N-1 (mean +- 4 sd; default 1024); 16-bit gray images\n"
    "                      are shifted to at most N bins (8-bit: 256)\n"
    "  --gain-max G        K-L features: a step of one sample in one band moves a\n"
    "                      feature by at most G bins (default 1 for 8-bit input:\n"
    "                      finer bins leave gaps between the values integer samples\n"
    "                      can give; 4096 for 16-bit)\n"
    "  --nodata V          pixels whose bands all equal V are left out (label 0)\n"
    "  --no-clean          keep isolated points\n"
    "  --contours          draw region contours on --picture\n"
    "  -q, --quiet         no summary on stdout\n"
    "  -h, --help          this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

typedef struct {
    seg_opts_t run;
    const char *out, *json, *plot, *picture, *features;
    int quiet;
} seg_cli_t;

static int parse_components(const char *v, seg_opts_t *o)
{
    uint32_t c[3];
    if (strcmp(v, "auto") == 0) {
        o->comps[0] = o->comps[1] = o->comps[2] = 0;
        return 0;
    }
    if (strchr(v, ',') == NULL) {
        if (cli_parse_u32(v, 1, SSDA_MIX_MAX_COMPONENTS, &c[0]) != 0) {
            return -1;
        }
        o->comps[0] = o->comps[1] = o->comps[2] = (uint8_t)c[0];
        return 0;
    }
    if (cli_parse_list_u32(v, 1, SSDA_MIX_MAX_COMPONENTS, c, 3) != 0) {
        return -1;
    }
    o->comps[0] = (uint8_t)c[0];
    o->comps[1] = (uint8_t)c[1];
    o->comps[2] = (uint8_t)c[2];
    return 0;
}

/* One option of the run (the word choices); 1 if taken, -1 on a bad value. */
static int parse_choice(cli_args_t *a, seg_opts_t *o)
{
    const char *v;
    if (cli_opt(a, "--fit", &v)) {
        if (v == NULL || (strcmp(v, "em") != 0 && strcmp(v, "search") != 0)) {
            return v == NULL ? 1 : (cli_usage_error(a->cmd, "bad --fit '%s' (em or search)", v), -1);
        }
        o->fit = strcmp(v, "em") == 0 ? SSDA_MIX_FIT_EM : SSDA_MIX_FIT_SEARCH;
    } else if (cli_opt(a, "--init", &v)) {
        if (v == NULL || (strcmp(v, "peaks") != 0 && strcmp(v, "quantiles") != 0)) {
            return v == NULL ? 1
                             : (cli_usage_error(a->cmd, "bad --init '%s' (peaks or quantiles)", v), -1);
        }
        o->init = strcmp(v, "peaks") == 0 ? SSDA_MIX_INIT_PEAKS : SSDA_MIX_INIT_QUANTILES;
    } else if (cli_opt(a, "--rule", &v)) {
        if (v == NULL || (strcmp(v, "band") != 0 && strcmp(v, "likely") != 0)) {
            return v == NULL ? 1 : (cli_usage_error(a->cmd, "bad --rule '%s' (band or likely)", v), -1);
        }
        o->rule = strcmp(v, "band") == 0 ? SSDA_MIX_LABEL_BAND : SSDA_MIX_LABEL_LIKELY;
    } else if (cli_opt(a, "--matrix", &v)) {
        if (v == NULL || (strcmp(v, "correlation") != 0 && strcmp(v, "covariance") != 0)) {
            return v == NULL ? 1
                             : (cli_usage_error(a->cmd, "bad --matrix '%s' (correlation or "
                                                        "covariance)", v), -1);
        }
        o->matrix = strcmp(v, "correlation") == 0 ? SSDA_KL_CORRELATION : SSDA_KL_COVARIANCE;
    } else if (cli_opt(a, "--band", &v)) {
        uint32_t b = 0;
        if (v != NULL && strcmp(v, "all") != 0 && cli_parse_u32(v, 1, 3, &b) != 0) {
            return cli_usage_error(a->cmd, "bad --band '%s' (1, 2, 3 or all)", v), -1;
        }
        o->band = (int)b;
    } else {
        return 0;
    }
    return 1;
}

/* One option with a number; 1 if taken, -1 on a bad value. */
static int parse_number(cli_args_t *a, seg_cli_t *c)
{
    const char *v;
    uint32_t u = 0;
    double d = 0.0;
    if (cli_opt(a, "--components", &v)) {
        if (v != NULL && parse_components(v, &c->run) != 0) {
            return cli_usage_error(a->cmd, "bad --components '%s' (auto, N or N1,N2,N3; "
                                           "1..16)", v), -1;
        }
    } else if (cli_opt(a, "--max-components", &v)) {
        if (v != NULL && cli_parse_u32(v, 1, SSDA_MIX_MAX_COMPONENTS, &u) != 0) {
            return cli_usage_error(a->cmd, "bad --max-components '%s' (1..16)", v), -1;
        }
        c->run.max_comps = (uint8_t)u;
    } else if (cli_opt(a, "--band-sigma", &v)) {
        if (v != NULL && cli_parse_double(v, 0.01, 16.0, &d) != 0) {
            return cli_usage_error(a->cmd, "bad --band-sigma '%s' (0 < S <= 16)", v), -1;
        }
        c->run.band_q8 = (uint32_t)lround(d * 256.0);
        c->run.band_q8 = c->run.band_q8 == 0 ? 1 : c->run.band_q8;
    } else if (cli_opt(a, "--gain-max", &v)) {
        if (v != NULL && cli_parse_double(v, 1.0 / 65536.0, 4096.0, &c->run.gain_max) != 0) {
            return cli_usage_error(a->cmd, "bad --gain-max '%s' (0 < G <= 4096)", v), -1;
        }
    } else if (cli_opt(a, "--bins", &v)) {
        if (v != NULL && cli_parse_u32(v, 16, SSDA_MIX_MAX_BINS, &c->run.bins) != 0) {
            return cli_usage_error(a->cmd, "bad --bins '%s' (16..4096)", v), -1;
        }
    } else if (cli_opt(a, "--nodata", &v)) {
        if (v != NULL && cli_parse_u32(v, 0, 65535, &c->run.nodata) != 0) {
            return cli_usage_error(a->cmd, "bad --nodata '%s' (0..65535)", v), -1;
        }
        c->run.have_nodata = 1;
    } else {
        return 0;
    }
    return 1;
}

static int parse(int argc, char **argv, cli_args_t *a, seg_cli_t *c)
{
    memset(c, 0, sizeof *c);
    c->run.clean = 1;
    c->run.bins = 1024;
    cli_args_begin(a, "segment", argc, argv);
    while (cli_next(a)) {
        int r;
        if (cli_flag(a, "--help") || cli_flag(a, "-h")) {
            fputs(help, stdout);
            return -1;
        } else if (cli_opt(a, "-o", &c->out) || cli_opt(a, "--output", &c->out) ||
                   cli_opt(a, "--json", &c->json) || cli_opt(a, "--plot", &c->plot) ||
                   cli_opt(a, "--picture", &c->picture) || cli_opt(a, "--features", &c->features)) {
            /* paths */
        } else if (cli_flag(a, "--seed-steps")) {
            c->run.seed_steps = 1;
        } else if (cli_flag(a, "--no-clean")) {
            c->run.clean = 0;
        } else if (cli_flag(a, "--contours")) {
            c->run.contours = 1;
        } else if (cli_flag(a, "--quiet") || cli_flag(a, "-q")) {
            c->quiet = 1;
        } else if ((r = parse_choice(a, &c->run)) != 0 || (r = parse_number(a, c)) != 0) {
            if (r < 0) {
                return CLI_USAGE;
            }
        } else {
            return cli_unknown(a);
        }
        if (a->bad) {
            return CLI_USAGE;
        }
    }
    if (a->bad) {
        return CLI_USAGE;
    }
    if (a->npos != 1) {
        return cli_usage_error(a->cmd, "need one input IN.png");
    }
    if (c->out == NULL && c->json == NULL && c->plot == NULL && c->picture == NULL &&
        c->features == NULL && c->quiet) {
        return cli_usage_error(a->cmd, "nothing to do: give -o, --json, --plot, --picture or "
                                       "--features (or drop --quiet)");
    }
    return CLI_OK;
}

/* ---- outputs ---- */

static const char *feature_name(const seg_result_t *r, const seg_feature_t *f)
{
    static const char *const z[3] = {"Z1", "Z2", "Z3"};
    return r->color ? z[f->index] : "gray";
}

/* path with -z<k> inserted before a final .png (or appended). */
static void feature_path(const char *path, int k, char *buf, size_t len)
{
    const char *dot = strrchr(path, '.');
    if (dot != NULL && strchr(dot, '/') == NULL) {
        snprintf(buf, len, "%.*s-z%d%s", (int)(dot - path), path, k + 1, dot);
    } else {
        snprintf(buf, len, "%s-z%d", path, k + 1);
    }
}

/* One gray PNG per feature: its labels (8-bit) or its values (16-bit). */
static int write_images(cli_outputs_t *out, const char *base, int values, const seg_result_t *r)
{
    int k;
    for (k = 0; k < r->nfeat; k++) {
        char path[1024], err[512];
        gray_image_t g;
        FILE *f;
        if (r->nfeat > 1) {
            feature_path(base, r->feat[k].index, path, sizeof path);
        } else {
            snprintf(path, sizeof path, "%s", base);
        }
        g.pixels = values ? (void *)r->feat[k].values : (void *)r->feat[k].labels;
        g.width = r->width;
        g.height = r->height;
        g.stride = values ? 2u * r->width : r->width;
        g.bits = values ? 16 : 8;
        if ((f = cli_outputs_open(out, path)) == NULL) {
            return CLI_INPUT;
        }
        if (png_write_gray_to(f, path, &g, err, sizeof err) != 0) {
            return cli_input_error(out->cmd, "%s", err);
        }
    }
    return CLI_OK;
}

static cJSON *json_feature(const seg_result_t *r, const seg_feature_t *f)
{
    cJSON *o = cJSON_CreateObject(), *comps = cJSON_CreateArray();
    const ssda_mix_model_t *m = &f->model;
    uint32_t j, inside = 0;
    for (j = 0; j < f->bins; j++) {
        inside += f->hist[j];
    }
    cJSON_AddStringToObject(o, "feature", feature_name(r, f));
    cJSON_AddNumberToObject(o, "bins", f->bins);
    cJSON_AddNumberToObject(o, "bin_shift", f->shift);
    cJSON_AddNumberToObject(o, "gain", f->gain);
    cJSON_AddNumberToObject(o, "offset", f->offset);
    cJSON_AddNumberToObject(o, "pixels", inside);
    cJSON_AddStringToObject(o, "fit", m->fit == SSDA_MIX_FIT_EM ? "em" : "search");
    cJSON_AddNumberToObject(o, "count", m->count);
    cJSON_AddNumberToObject(o, "iterations", m->iterations);
    json_out_add_fixed(o, "loglik", (double)m->loglik_q16 / 65536.0, 5); /* Q16: 5 decimals */
    json_out_add_fixed(o, "bic", (double)m->bic_q16 / 65536.0, 5);
    json_out_add_fixed(o, "fit_seconds", f->fit_secs, 6);
    cJSON_AddNumberToObject(o, "unlabelled_pixels", f->counts[0] - r->masked); /* not nodata */
    for (j = 0; j < m->count; j++) {
        cJSON *c = cJSON_CreateObject();
        const double mean = m->comp[j].mean_q16 / 65536.0, sd = m->comp[j].sigma_q16 / 65536.0;
        cJSON_AddNumberToObject(c, "label", j + 1);
        cJSON_AddNumberToObject(c, "weight", m->comp[j].weight_q16 / 65536.0);
        cJSON_AddNumberToObject(c, "mean", mean);
        cJSON_AddNumberToObject(c, "sigma", sd);
        cJSON_AddNumberToObject(c, "mean_value", (mean - f->offset) / f->gain);
        cJSON_AddNumberToObject(c, "sigma_value", sd / f->gain);
        cJSON_AddNumberToObject(c, "pixels", f->counts[j + 1]);
        cJSON_AddNumberToObject(c, "band_pixels", f->band_pixels[j]);
        cJSON_AddItemToArray(comps, c);
    }
    cJSON_AddItemToObject(o, "components", comps);
    return o;
}

static cJSON *json_matrix(const int32_t m[3][3], int l1)
{
    cJSON *rows = cJSON_CreateArray();
    int k, j;
    for (k = 0; k < 3; k++) {
        double row[3], s = 0.0;
        for (j = 0; j < 3; j++) {
            row[j] = m[k][j] / 1073741824.0;
            s += fabs(row[j]);
        }
        for (j = 0; j < 3 && l1; j++) {
            row[j] /= s;
        }
        cJSON_AddItemToArray(rows, cJSON_CreateDoubleArray(row, 3));
    }
    return rows;
}

/* The K-L part: matrix, eigenvalues, vectors (unit, and scaled as the
   seed prints eq. 2.3), band means, feature sds, counts. */
static cJSON *json_kl(const seg_result_t *r)
{
    cJSON *kl = cJSON_CreateObject();
    double lam[3], mean[3], zsd[3];
    int k;
    for (k = 0; k < 3; k++) {
        lam[k] = (double)r->kl.lambda_q16[k] / 65536.0;
        mean[k] = r->kl.mean_q8[k] / 256.0;
        zsd[k] = sqrt((double)r->kl.zvar_q16[k] / 65536.0);
    }
    cJSON_AddStringToObject(kl, "matrix",
                            r->kl.matrix == SSDA_KL_CORRELATION ? "correlation" : "covariance");
    cJSON_AddItemToObject(kl, "matrix_values", json_matrix(r->kl.matrix_q30, 0));
    cJSON_AddItemToObject(kl, "eigenvalues", cJSON_CreateDoubleArray(lam, 3));
    cJSON_AddItemToObject(kl, "vectors", json_matrix(r->kl.vec_q30, 0));
    cJSON_AddItemToObject(kl, "vectors_l1", json_matrix(r->kl.vec_q30, 1));
    cJSON_AddItemToObject(kl, "band_means", cJSON_CreateDoubleArray(mean, 3));
    cJSON_AddItemToObject(kl, "feature_sd", cJSON_CreateDoubleArray(zsd, 3));
    cJSON_AddNumberToObject(kl, "pixels", r->kl.count);
    cJSON_AddNumberToObject(kl, "clamped_values", r->clamped);
    return kl;
}

static int write_json(FILE *f, const seg_cli_t *c, const char *in, const seg_result_t *r)
{
    cJSON *root = json_out_object(), *feats = cJSON_CreateArray();
    int k, rc;
    if (root == NULL) {
        cJSON_Delete(feats);
        return -1;
    }
    json_out_add_string(root, "input", in);
    cJSON_AddNumberToObject(root, "width", r->width);
    cJSON_AddNumberToObject(root, "height", r->height);
    cJSON_AddStringToObject(root, "kind", r->color ? "rgb" : "gray");
    cJSON_AddNumberToObject(root, "bits", r->bits);
    if (c->run.have_nodata) {
        cJSON_AddNumberToObject(root, "nodata", c->run.nodata);
    }
    cJSON_AddNumberToObject(root, "masked_pixels", r->masked);
    cJSON_AddStringToObject(root, "rule", c->run.rule == SSDA_MIX_LABEL_BAND ? "band" : "likely");
    cJSON_AddNumberToObject(root, "band_sigma", (c->run.band_q8 ? c->run.band_q8 : 512) / 256.0);
    cJSON_AddBoolToObject(root, "clean", c->run.clean);
    json_out_add_fixed(root, "seconds", r->secs, 6);
    if (r->color) {
        cJSON_AddItemToObject(root, "kl", json_kl(r));
    }
    for (k = 0; k < r->nfeat; k++) {
        cJSON_AddItemToArray(feats, json_feature(r, &r->feat[k]));
    }
    cJSON_AddItemToObject(root, "features", feats);
    rc = json_out_print(f, root, NULL);
    cJSON_Delete(root);
    return rc;
}

static int write_plot(FILE *f, const char *path, const char *in, const seg_cli_t *c,
                      const seg_result_t *r)
{
    draw_hist_panel_t p[3];
    double w[3][SSDA_MIX_MAX_COMPONENTS], m[3][SSDA_MIX_MAX_COMPONENTS];
    double s[3][SSDA_MIX_MAX_COMPONENTS];
    char titles[3][160], title[256], err[512];
    int k;
    uint32_t j;
    for (k = 0; k < r->nfeat; k++) {
        const seg_feature_t *ft = &r->feat[k];
        double total = 0.0;
        for (j = 0; j < ft->bins; j++) {
            total += ft->hist[j];
        }
        for (j = 0; j < ft->model.count; j++) {
            w[k][j] = ft->model.comp[j].weight_q16 / 65536.0;
            m[k][j] = ft->model.comp[j].mean_q16 / 65536.0;
            s[k][j] = ft->model.comp[j].sigma_q16 / 65536.0;
        }
        snprintf(titles[k], sizeof titles[k], "%s: %u components (%s), log-likelihood %.6g",
                 feature_name(r, ft), (unsigned)ft->model.count,
                 ft->model.fit == SSDA_MIX_FIT_EM ? "EM" : "seed's search",
                 (double)ft->model.loglik_q16 / 65536.0);
        p[k].title = titles[k];
        p[k].hist = ft->hist;
        p[k].bins = ft->bins;
        p[k].count = ft->model.count;
        p[k].weight = w[k];
        p[k].mean = m[k];
        p[k].sigma = s[k];
        p[k].total = total;
    }
    (void)c;
    snprintf(title, sizeof title, "ssda segment  %s: histograms and Gaussian components",
             cli_basename(in));
    if (draw_hist_to(f, path, title, p, (size_t)r->nfeat, err, sizeof err) != 0) {
        return cli_input_error("segment", "%s", err);
    }
    return CLI_OK;
}

static int write_picture(FILE *f, const char *path, const char *in, const seg_result_t *r)
{
    draw_label_panel_t p[3];
    char lines[3][SSDA_MIX_MAX_COMPONENTS + 1][96], titles[3][96], title[256], err[512];
    const char *legend[3][SSDA_MIX_MAX_COMPONENTS + 1];
    uint8_t *nodata = NULL;
    const double n = (double)r->width * r->height;
    size_t i;
    int k, rc;
    uint32_t j;
    if (r->masked > 0) {
        nodata = malloc((size_t)r->width * r->height);
        for (i = 0; nodata != NULL && i < (size_t)r->width * r->height; i++) {
            nodata[i] = r->feat[0].values[i] == SSDA_KL_NODATA;
        }
    }
    for (k = 0; k < r->nfeat; k++) {
        const seg_feature_t *ft = &r->feat[k];
        snprintf(lines[k][0], sizeof lines[k][0], "0: no component, %.1f %%",
                 100.0 * (ft->counts[0] - r->masked) / n);
        legend[k][0] = lines[k][0];
        for (j = 0; j < ft->model.count; j++) {
            const double mean = ft->model.comp[j].mean_q16 / 65536.0;
            snprintf(lines[k][j + 1], sizeof lines[k][j + 1], "%u: mean %.1f, sd %.1f (bins), %.1f %%",
                     (unsigned)(j + 1), mean, ft->model.comp[j].sigma_q16 / 65536.0,
                     100.0 * ft->counts[j + 1] / n);
            legend[k][j + 1] = lines[k][j + 1];
        }
        snprintf(titles[k], sizeof titles[k], "%s labels", feature_name(r, ft));
        p[k].title = titles[k];
        p[k].labels = ft->labels;
        p[k].contour = ft->contour;
        p[k].nodata = nodata;
        p[k].count = ft->model.count;
        p[k].legend = legend[k];
    }
    snprintf(title, sizeof title, "ssda segment  %s%s", cli_basename(in),
             r->masked > 0 ? "  (nodata: black)" : "");
    rc = draw_labels_to(f, path, title, r->width, r->height, p, (size_t)r->nfeat, err, sizeof err);
    free(nodata);
    return rc != 0 ? cli_input_error("segment", "%s", err) : CLI_OK;
}

static void summary(const seg_cli_t *c, const char *in, const seg_result_t *r)
{
    const double n = (double)r->width * r->height;
    int k;
    uint32_t j;
    printf("%s: %u x %u %s, %u-bit%s", cli_basename(in), r->width, r->height,
           r->color ? "RGB" : "gray", r->bits, r->masked ? "" : "\n");
    if (r->masked) {
        printf(", %u nodata pixels (%.1f %%)\n", r->masked, 100.0 * r->masked / n);
    }
    if (r->color) {
        printf("K-L (%s): eigenvalues %.4g %.4g %.4g\n",
               r->kl.matrix == SSDA_KL_CORRELATION ? "correlation" : "covariance",
               r->kl.lambda_q16[0] / 65536.0, r->kl.lambda_q16[1] / 65536.0,
               r->kl.lambda_q16[2] / 65536.0);
        for (k = 0; k < 3; k++) {
            double l1 = 0.0;
            for (j = 0; j < 3; j++) {
                l1 += fabs(r->kl.vec_q30[k][j] / 1073741824.0);
            }
            printf("  Z%d = %+.4f R %+.4f G %+.4f B  (rows scaled to sum |v| = 1, as the seed)\n",
                   k + 1, r->kl.vec_q30[k][0] / 1073741824.0 / l1,
                   r->kl.vec_q30[k][1] / 1073741824.0 / l1, r->kl.vec_q30[k][2] / 1073741824.0 / l1);
        }
    }
    for (k = 0; k < r->nfeat; k++) {
        const seg_feature_t *f = &r->feat[k];
        printf("%s: %u components (%s, %u %s, %.1f ms), log-likelihood %.6g\n",
               feature_name(r, f), (unsigned)f->model.count,
               f->model.fit == SSDA_MIX_FIT_EM ? "EM" : "search", (unsigned)f->model.iterations,
               f->model.fit == SSDA_MIX_FIT_EM ? "iterations" : "cycles", 1e3 * f->fit_secs,
               (double)f->model.loglik_q16 / 65536.0);
        for (j = 0; j < f->model.count; j++) {
            const ssda_mix_component_t *cp = &f->model.comp[j];
            printf("  %2u: weight %.3f  mean %7.2f  sd %6.2f (bins)  pixels %u (%.1f %%), in +-2 sd "
                   "%u\n", (unsigned)(j + 1), cp->weight_q16 / 65536.0, cp->mean_q16 / 65536.0,
                   cp->sigma_q16 / 65536.0, f->counts[j + 1], 100.0 * f->counts[j + 1] / n,
                   f->band_pixels[j]);
        }
        printf("   0: no component: %u pixels (%.1f %%)\n", f->counts[0] - r->masked,
               100.0 * (f->counts[0] - r->masked) / n);
    }
    (void)c;
}

int cmd_segment(int argc, char **argv)
{
    cli_args_t a;
    seg_cli_t c;
    seg_result_t r;
    cli_outputs_t out;
    FILE *f;
    int rc = parse(argc, argv, &a, &c);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc;
    }
    cli_warn_png_name(a.cmd, "-o", c.out);
    cli_warn_png_name(a.cmd, "--plot", c.plot);
    cli_warn_png_name(a.cmd, "--picture", c.picture);
    cli_warn_png_name(a.cmd, "--features", c.features);
    /* every destination checked before the work (with several features the
       names gain -z1.. -z3 in the same folder) */
    if (cli_output_check(a.cmd, c.out) != 0 || cli_output_check(a.cmd, c.json) != 0 ||
        cli_output_check(a.cmd, c.plot) != 0 || cli_output_check(a.cmd, c.picture) != 0 ||
        cli_output_check(a.cmd, c.features) != 0) {
        return CLI_INPUT;
    }
    if (seg_run(a.cmd, a.pos[0], &c.run, &r) != CLI_OK) {
        seg_result_free(&r);
        return CLI_INPUT;
    }
    cli_outputs_begin(&out, a.cmd);
    rc = CLI_INPUT;
    if (c.out != NULL && write_images(&out, c.out, 0, &r) != CLI_OK) {
        goto done;
    }
    if (c.features != NULL && write_images(&out, c.features, 1, &r) != CLI_OK) {
        goto done;
    }
    if (c.json != NULL && ((f = cli_outputs_open(&out, c.json)) == NULL ||
                           write_json(f, &c, a.pos[0], &r) != 0)) {
        goto done;
    }
    if (c.plot != NULL && ((f = cli_outputs_open(&out, c.plot)) == NULL ||
                           write_plot(f, c.plot, a.pos[0], &c, &r) != CLI_OK)) {
        goto done;
    }
    if (c.picture != NULL && ((f = cli_outputs_open(&out, c.picture)) == NULL ||
                              write_picture(f, c.picture, a.pos[0], &r) != CLI_OK)) {
        goto done;
    }
    if ((rc = cli_outputs_commit(&out)) != CLI_OK) {
        goto done;
    }
    if (!c.quiet && !cli_is_stdout(c.json)) {
        summary(&c, a.pos[0], &r);
    }
done:
    cli_outputs_abort(&out);
    seg_result_free(&r);
    return rc;
}
