/* cmd_flow.c - `ssda flow REF.png NEXT.png`: composite template matching
   (seed 003) and the cleaning of its vector field. */
#include "cli.h"
#include "draw.h"
#include "json_out.h"
#include "progress.h"
#include "track_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ssda/composite.h"
#include "ssda/relax.h"

static const char help[] =
    "usage: ssda flow REF.png NEXT.png [options]\n"
    "\n"
    "Motion vectors by composite template matching (the seed 003's method for sea-surface\n"
    "flow): templates of T x T px every S px in a region of REF, ranked by their standard\n"
    "deviation; the first (the origin) is searched over the whole of NEXT, every other one\n"
    "only in a circle around the origin's match plus its position relative to the origin,\n"
    "of radius F times that distance (at least R px). The criterion is the correlation\n"
    "coefficient (exact, in integers): brightness and contrast changes do not matter.\n"
    "Vectors are the motion REF -> NEXT in px (x right, y down).\n"
    "\n"
    "options:\n"
    "  --tp T             template side, px (default 20, the seed's; 2..256)\n"
    "  --tp-step S        spacing of the templates, px (default 5, the seed's)\n"
    "  --region X,Y,W,H   template region in REF (default: the whole image)\n"
    "  --radius F         circle radius per px of distance from the origin (default 0.25)\n"
    "  --min-radius R     smallest circle radius, px (default 3)\n"
    "  --min-std V        skip templates whose standard deviation is below V (sample\n"
    "                     units; default: only flat ones)\n"
    "  --mask-value V     V is fill (no data; GOES-16: 4095): templates holding it, or\n"
    "                     whose search area in NEXT holds it, are 'masked' (not matched);\n"
    "                     an origin whose match holds it is masked and the next in rank\n"
    "                     becomes the origin; the overlay's contrast leaves V out\n"
    "  --metric M         ncc (default: the largest rho) or absncc (the largest |rho|:\n"
    "                     inverted contrast matches too)\n"
    "  --subpixel         parabolic sub-pixel vectors\n"
    "  --relax N          clean the field by relaxation labelling, N iterations (the\n"
    "                     seed's section 4; 0 = no cleaning, the default)\n"
    "  --relax-keep       with --relax: keep vectors whose most likely class is their own\n"
    "  --relax-median     clean by the normalised median test (Westerweel & Scarano) instead\n"
    "  --json FILE        every template as JSON (\"-\" = stdout): x, y, status (ok, flat,\n"
    "                     edge, masked), dx, dy,\n"
    "                     rho, std; with cleaning also relax_dx, relax_dy, changed\n"
    "  --overlay FILE.png REF with the vectors: yellow as matched, pink those the\n"
    "                     cleaning changed, cyan as cleaned\n"
    "  -q, --quiet        no summary\n"
    "  -h, --help         this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

typedef struct {
    ssda_composite_config_t cfg;
    const char *ref_path, *next_path, *json_path, *overlay_path;
    uint32_t relax;        /* iterations, 0 = none */
    int keep, median, quiet;
} flow_opts_t;

typedef struct {
    gray_image_t ref, next;
    ssda_composite_tp_t *tp;
    ssda_composite_result_t res;
    ssda_relax_vector_t *clean; /* NULL without cleaning */
    uint32_t changed;
    uint32_t side;              /* T, px */
    size_t count;               /* templates in the grid */
    double secs;
} flow_run_t;

static void print_help(void)
{
    fputs(help, stdout);
}

/* The current option into opts (a flow_opts_t): 1 taken (a->bad set on a
   bad value), 0 unknown. */
static int take_option(cli_args_t *a, void *opts)
{
    flow_opts_t *o = opts;
    const char *v;
    uint32_t u, r[4];
    double d;
    if (cli_opt(a, "--tp", &v)) {
        if (v != NULL && cli_parse_u32(v, 2, 256, &u) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --tp '%s' (2..256)", v);
        }
        o->cfg.tp = (uint16_t)u;
    } else if (cli_opt(a, "--tp-step", &v)) {
        if (v != NULL && cli_parse_u32(v, 1, 65535, &u) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --tp-step '%s' (1..65535)", v);
        }
        o->cfg.step = (uint16_t)u;
    } else if (cli_opt(a, "--region", &v)) {
        if (v != NULL && cli_parse_list_u32(v, 0, 65535, r, 4) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --region '%s' (want X,Y,W,H)", v);
        }
        o->cfg.roi_x = (uint16_t)r[0];
        o->cfg.roi_y = (uint16_t)r[1];
        o->cfg.roi_w = (uint16_t)r[2];
        o->cfg.roi_h = (uint16_t)r[3];
    } else if (cli_opt(a, "--radius", &v)) {
        if (v != NULL && cli_parse_double(v, 1.0 / 256.0, 255.0, &d) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --radius '%s' (0.004..255)", v);
        }
        o->cfg.radius_q8 = (uint16_t)lround(d * 256.0);
    } else if (cli_opt(a, "--min-radius", &v)) {
        if (v != NULL && cli_parse_u32(v, 1, 65535, &u) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --min-radius '%s' (1..65535)", v);
        }
        o->cfg.min_radius = (uint16_t)u;
    } else if (cli_opt(a, "--min-std", &v)) {
        if (v != NULL && cli_parse_double(v, 0.0, 255.0, &d) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --min-std '%s' (0..255)", v);
        }
        o->cfg.min_std_q8 = (uint16_t)lround(d * 256.0);
    } else if (cli_opt(a, "--metric", &v)) {
        if (v != NULL && strcmp(v, "ncc") != 0 && strcmp(v, "absncc") != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --metric '%s' (ncc, absncc)", v);
        }
        o->cfg.metric = (uint8_t)(v != NULL && strcmp(v, "absncc") == 0 ? SSDA_NCC_ABS : SSDA_NCC_RHO);
    } else if (cli_opt(a, "--mask-value", &v)) {
        if (v != NULL && cli_parse_u32(v, 0, 65535, &u) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --mask-value '%s' (0..65535)", v);
        }
        o->cfg.flags |= SSDA_COMPOSITE_MASK;
        o->cfg.mask_value = (uint16_t)u;
    } else if (cli_flag(a, "--subpixel")) {
        o->cfg.flags |= SSDA_COMPOSITE_SUBPIXEL;
    } else if (cli_opt(a, "--relax", &v)) {
        if (v != NULL && cli_parse_u32(v, 0, 1000, &o->relax) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --relax '%s' (0..1000 iterations)", v);
        }
    } else if (cli_flag(a, "--relax-keep")) {
        o->keep = 1;
    } else if (cli_flag(a, "--relax-median")) {
        o->median = 1;
    } else if (cli_opt(a, "--json", &v)) {
        o->json_path = v;
    } else if (cli_opt(a, "--overlay", &v)) {
        o->overlay_path = v;
    } else if (cli_flag(a, "--quiet") || cli_flag(a, "-q")) {
        o->quiet = 1;
    } else {
        return 0;
    }
    return 1;
}

/* Options and positionals; CLI_OK, CLI_USAGE (said), or -1 after --help. */
static int parse(int argc, char **argv, flow_opts_t *o)
{
    cli_args_t a;
    int rc;
    memset(o, 0, sizeof *o);
    cli_args_begin(&a, "flow", argc, argv);
    if ((rc = cli_scan_options(&a, print_help, take_option, o)) != CLI_OK) {
        return rc;
    }
    if (cli_positionals(&a, 2, "need REF.png and NEXT.png") != CLI_OK) {
        return CLI_USAGE;
    }
    if (o->keep && o->relax == 0u) {
        return cli_usage_error(a.cmd, "--relax-keep needs --relax N");
    }
    if (o->median && o->relax != 0u) {
        return cli_usage_error(a.cmd, "give --relax N or --relax-median, not both");
    }
    o->ref_path = a.pos[0];
    o->next_path = a.pos[1];
    cli_warn_png_name(a.cmd, "--overlay", o->overlay_path);
    return CLI_OK;
}

/* The products the search will sum at most: the origin over the whole of
   NEXT, every other template over its circle (the origin taken at the
   region's centre), T^2 per position. Within 30 % of the pixel_ops
   reported on the PIV pair. */
static double flow_work(const ssda_composite_config_t *c, uint32_t tp, uint32_t step,
                        uint32_t rw, uint32_t rh, uint32_t nw, uint32_t nh)
{
    const double positions = (double)(nw - tp + 1u) * (double)(nh - tp + 1u);
    const double f = (c->radius_q8 != 0u ? c->radius_q8 : SSDA_COMPOSITE_DEFAULT_RADIUS_Q8) / 256.0;
    const double rmin = c->min_radius != 0u ? c->min_radius : SSDA_COMPOSITE_DEFAULT_MIN_RADIUS;
    const double cx = (rw - tp) / 2.0, cy = (rh - tp) / 2.0;
    double sum = positions;
    uint32_t x, y;
    for (y = 0; y + tp <= rh; y += step) {
        for (x = 0; x + tp <= rw; x += step) {
            double r = ceil(f * hypot(x - cx, y - cy));
            r = r > rmin ? r : rmin;
            sum += fmin(3.14159265 * r * r, positions);
        }
    }
    return sum * tp * tp;
}

/* The composite matching and the cleaning; CLI_OK or CLI_INPUT (said). */
static int run(const flow_opts_t *o, flow_run_t *r)
{
    ssda_view_t rv, nv;
    ssda_composite_config_t cfg = o->cfg;
    const uint32_t tp = cfg.tp != 0u ? cfg.tp : SSDA_COMPOSITE_DEFAULT_TP;
    void *work;
    r->side = tp;
    double t0;
    int err;
    if (cli_load_png_pair("flow", o->ref_path, o->next_path, &r->ref, &r->next) != 0) {
        return CLI_INPUT;
    }
    if ((cfg.flags & SSDA_COMPOSITE_MASK) != 0u && cfg.mask_value > gray_image_max(&r->ref)) {
        /* as ssda track says it */
        return cli_usage_error("flow", "--mask-value %u is beyond these %u-bit images",
                               cfg.mask_value, gray_image_max(&r->ref) == 255 ? 8 : 16);
    }
    if (gray_image_view(&r->ref, &rv) != SSDA_OK || gray_image_view(&r->next, &nv) != SSDA_OK ||
        r->next.width < tp) {
        return cli_input_error("flow", "NEXT (%u px wide) is narrower than a template", r->next.width);
    }
    {
        /* the template grid, to size the array (the library checks it all) */
        const uint32_t step = cfg.step != 0u ? cfg.step : SSDA_COMPOSITE_DEFAULT_STEP;
        const uint32_t rw = cfg.roi_w != 0u ? cfg.roi_w : (cfg.roi_x < r->ref.width ? r->ref.width - cfg.roi_x : 0u);
        const uint32_t rh = cfg.roi_h != 0u ? cfg.roi_h : (cfg.roi_y < r->ref.height ? r->ref.height - cfg.roi_y : 0u);
        r->count = SSDA_COMPOSITE_DIM(rw, tp, step) * SSDA_COMPOSITE_DIM(rh, tp, step);
        if (r->count > 0u && rw <= r->ref.width && rh <= r->ref.height && r->next.height >= tp) {
            /* one library call, no progress: say beforehand when it is long */
            const double ops = flow_work(&cfg, tp, step, rw, rh, r->next.width, r->next.height);
            if (ops > 1e11) {
                fprintf(stderr, "ssda flow: note: %zu templates, up to %.1e pixel operations "
                        "(about %.0f min at 3e9 a second): --region X,Y,W,H, a larger "
                        "--tp-step or a smaller --radius cost less\n",
                        r->count, ops, ops / 3e9 / 60.0);
            }
        }
    }
    cfg.work_size = SSDA_COMPOSITE_WORK_SIZE(r->next.width, tp);
    work = malloc(cfg.work_size);
    r->tp = calloc(r->count + 1u, sizeof *r->tp);
    if (work == NULL || r->tp == NULL) {
        free(work);
        return cli_input_error("flow", "out of memory");
    }
    cfg.work = work;
    t0 = progress_now();
    err = ssda_composite_match(&rv, &nv, &cfg, r->tp, r->count, &r->res);
    r->secs = progress_now() - t0;
    free(work);
    if (err != SSDA_OK) {
        return cli_input_error("flow", "%s: the region (--region, default the whole of REF) "
                               "must lie inside REF and hold at least one %u x %u template",
                               ssda_strerror(err), tp, tp);
    }
    return CLI_OK;
}

/* --relax N or --relax-median on the template grid. */
static int clean(const flow_opts_t *o, flow_run_t *r)
{
    ssda_relax_grid_t g;
    uint32_t k;
    int err;
    if (o->relax == 0u && !o->median) {
        return CLI_OK;
    }
    r->clean = calloc(r->res.count, sizeof *r->clean);
    if (r->clean == NULL) {
        return cli_input_error("flow", "out of memory");
    }
    memset(&g, 0, sizeof g);
    g.dx = &r->tp[0].dx;
    g.dy = &r->tp[0].dy;
    g.status = &r->tp[0].status;
    g.stride = sizeof r->tp[0];
    g.cols = r->res.cols;
    g.rows = r->res.rows;
    g.frac_bits = 8;
    err = relax_field(&g, o->relax, o->median, o->keep, r->clean, r->res.count);
    if (err != SSDA_OK) {
        return cli_input_error("flow", "cleaning failed: %s", ssda_strerror(err));
    }
    for (k = 0; k < r->res.count; k++) {
        r->changed += (r->clean[k].flags & SSDA_RELAX_CHANGED) != 0u;
    }
    return CLI_OK;
}

static const char *status_name(uint8_t s)
{
    return s == SSDA_COMPOSITE_OK       ? "ok"
           : s == SSDA_COMPOSITE_FLAT   ? "flat"
           : s == SSDA_COMPOSITE_MASKED ? "masked"
                                        : "edge";
}

/* Template k of the "templates" array (made while printing). */
static cJSON *template_item(void *ctx, size_t k)
{
    const flow_run_t *r = ctx;
    const ssda_composite_tp_t *t = &r->tp[k];
    cJSON *item = cJSON_CreateObject();
    if (item == NULL) {
        return NULL;
    }
    cJSON_AddNumberToObject(item, "x", t->x);
    cJSON_AddNumberToObject(item, "y", t->y);
    cJSON_AddStringToObject(item, "status", status_name(t->status));
    if (t->status == SSDA_COMPOSITE_OK) {
        json_out_add_fixed(item, "dx", t->dx / 256.0, 4);
        json_out_add_fixed(item, "dy", t->dy / 256.0, 4);
        json_out_add_fixed(item, "rho", t->rho_q30 / 1073741824.0, 6);
    }
    /* var = n^2 times the variance, n = T^2 */
    json_out_add_fixed(item, "std", sqrt((double)t->var) / ((double)r->side * r->side), 3);
    if (t->origin) {
        cJSON_AddTrueToObject(item, "origin");
    }
    if (r->clean != NULL && (r->clean[k].flags & SSDA_RELAX_VALID) != 0u) {
        json_out_add_fixed(item, "relax_dx", r->clean[k].dx_q8 / 256.0, 4);
        json_out_add_fixed(item, "relax_dy", r->clean[k].dy_q8 / 256.0, 4);
        cJSON_AddBoolToObject(item, "changed", (r->clean[k].flags & SSDA_RELAX_CHANGED) != 0u);
    }
    return item;
}

static uint32_t count_masked(const flow_run_t *r)
{
    uint32_t k, n = 0;
    for (k = 0; k < r->res.count; k++) {
        n += r->tp[k].status == SSDA_COMPOSITE_MASKED;
    }
    return n;
}

static cJSON *json_doc(const flow_opts_t *o, const flow_run_t *r)
{
    cJSON *doc = json_out_object(), *reg;
    const ssda_composite_config_t *c = &o->cfg;
    if (doc == NULL) {
        return NULL;
    }
    json_out_add_string(doc, "ref", o->ref_path);
    json_out_add_string(doc, "next", o->next_path);
    cJSON_AddNumberToObject(doc, "width", r->ref.width);
    cJSON_AddNumberToObject(doc, "height", r->ref.height);
    cJSON_AddNumberToObject(doc, "bits", r->ref.bits);
    cJSON_AddNumberToObject(doc, "tp", r->side);
    cJSON_AddNumberToObject(doc, "tp_step", c->step != 0u ? c->step : SSDA_COMPOSITE_DEFAULT_STEP);
    reg = cJSON_AddObjectToObject(doc, "region");
    if (reg != NULL) {
        cJSON_AddNumberToObject(reg, "x", c->roi_x);
        cJSON_AddNumberToObject(reg, "y", c->roi_y);
        cJSON_AddNumberToObject(reg, "w", c->roi_w != 0u ? c->roi_w : r->ref.width - c->roi_x);
        cJSON_AddNumberToObject(reg, "h", c->roi_h != 0u ? c->roi_h : r->ref.height - c->roi_y);
    }
    if ((c->flags & SSDA_COMPOSITE_MASK) != 0u) {
        cJSON_AddNumberToObject(doc, "mask_value", c->mask_value);
    } else {
        cJSON_AddNullToObject(doc, "mask_value");
    }
    cJSON_AddStringToObject(doc, "metric", c->metric == SSDA_NCC_ABS ? "absncc" : "ncc");
    json_out_add_fixed(doc, "radius", (c->radius_q8 != 0u ? c->radius_q8 : 64u) / 256.0, 4);
    cJSON_AddNumberToObject(doc, "min_radius", c->min_radius != 0u ? c->min_radius : 3u);
    cJSON_AddNumberToObject(doc, "cols", r->res.cols);
    cJSON_AddNumberToObject(doc, "rows", r->res.rows);
    cJSON_AddNumberToObject(doc, "count", r->res.count);
    cJSON_AddNumberToObject(doc, "ok", r->res.ok);
    cJSON_AddNumberToObject(doc, "masked", count_masked(r));
    if (r->res.origin != UINT32_MAX) {
        cJSON_AddNumberToObject(doc, "origin", r->res.origin);
    } else {
        cJSON_AddNullToObject(doc, "origin");
    }
    json_out_add_fixed(doc, "mean_rho", r->res.mean_rho_q30 / 1073741824.0, 6);
    cJSON_AddStringToObject(doc, "cleaning", r->clean == NULL ? "none" : o->median ? "median" : "relax");
    if (r->clean != NULL) {
        cJSON_AddNumberToObject(doc, "relax_iterations", o->median ? 0 : o->relax);
        cJSON_AddNumberToObject(doc, "changed", r->changed);
    }
    json_out_add_u64(doc, "pixel_ops", r->res.pixel_ops);
    json_out_add_fixed(doc, "time_s", r->secs, 6);
    cJSON_AddArrayToObject(doc, "templates");
    return doc;
}

/* The overlay: matched vectors (yellow; pink where the cleaning changed
   them) and the cleaned ones as the second set of arrows (cyan). */
static int write_overlay(FILE *fp, const flow_opts_t *o, const flow_run_t *r)
{
    draw_vector_t *v = calloc(r->res.count + 1u, sizeof *v);
    draw_vectors_opts_t d;
    char title[512], sub[256], err[256];
    uint32_t k;
    int rc;
    if (v == NULL) {
        return cli_input_error("flow", "out of memory");
    }
    for (k = 0; k < r->res.count; k++) {
        const ssda_composite_tp_t *t = &r->tp[k];
        v[k].x = t->x + r->side / 2.0;
        v[k].y = t->y + r->side / 2.0;
        v[k].dx = t->dx / 256.0;
        v[k].dy = t->dy / 256.0;
        v[k].status = t->status == SSDA_COMPOSITE_OK       ? DRAW_OK
                      : t->status == SSDA_COMPOSITE_FLAT   ? DRAW_FLAT
                      : t->status == SSDA_COMPOSITE_MASKED ? DRAW_MASKED
                                                           : DRAW_EDGE;
        if (r->clean != NULL && (r->clean[k].flags & SSDA_RELAX_VALID) != 0u) {
            v[k].has_truth = 1;
            v[k].tdx = r->clean[k].dx_q8 / 256.0;
            v[k].tdy = r->clean[k].dy_q8 / 256.0;
            if ((r->clean[k].flags & SSDA_RELAX_CHANGED) != 0u) {
                v[k].status = DRAW_CHANGED;
            }
        }
    }
    memset(&d, 0, sizeof d);
    snprintf(title, sizeof title, "%s -> %s: %u templates of %u px, mean rho %.3f",
             cli_basename(o->ref_path), cli_basename(o->next_path), r->res.ok, r->side,
             r->res.mean_rho_q30 / 1073741824.0);
    snprintf(sub, sizeof sub, "%s", r->clean == NULL ? "no cleaning"
                                    : o->median ? "cleaned by the normalised median test"
                                                : "cleaned by relaxation labelling");
    d.title = title;
    d.subtitle = sub;
    d.grid_step = o->cfg.step != 0u ? o->cfg.step : SSDA_COMPOSITE_DEFAULT_STEP;
    d.have_mask = (o->cfg.flags & SSDA_COMPOSITE_MASK) != 0u; /* contrast without fill */
    d.mask_value = o->cfg.mask_value;
    d.truth_label = o->median ? "after the median test" : "after relaxation";
    rc = draw_vectors_to(fp, o->overlay_path, &r->ref, v, r->res.count, &d, NULL, err, sizeof err);
    free(v);
    return rc == 0 ? CLI_OK : cli_input_error("flow", "%s", err);
}

static void summary(const flow_opts_t *o, const flow_run_t *r)
{
    const ssda_composite_tp_t *t = r->res.origin != UINT32_MAX ? &r->tp[r->res.origin] : NULL;
    printf("templates: %u of %u x %u px every %u px (%u x %u), %u matched\n", r->res.count,
           r->side, r->side, o->cfg.step != 0u ? o->cfg.step : SSDA_COMPOSITE_DEFAULT_STEP,
           r->res.cols, r->res.rows, r->res.ok);
    if ((o->cfg.flags & SSDA_COMPOSITE_MASK) != 0u) {
        printf("masked:    %u templates (value %u in the template, its search area or the "
               "origin's match)\n", count_masked(r), o->cfg.mask_value);
    }
    if (t != NULL) {
        printf("origin:    template %u at (%u, %u), moved (%.2f, %.2f) px, rho %.4f\n",
               r->res.origin, t->x, t->y, t->dx / 256.0, t->dy / 256.0,
               t->rho_q30 / 1073741824.0);
    } else {
        printf("origin:    none (every template is flat%s)\n",
               (o->cfg.flags & SSDA_COMPOSITE_MASK) != 0u ? " or masked" : "");
    }
    printf("set score: mean rho %.4f; %llu pixel ops, %.3f s\n", r->res.mean_rho_q30 / 1073741824.0,
           (unsigned long long)r->res.pixel_ops, r->secs);
    if (r->clean != NULL) {
        printf("cleaning:  %s: %u of %u vectors changed\n",
               o->median ? "normalised median test" : "relaxation labelling", r->changed, r->res.ok);
    }
}

int cmd_flow(int argc, char **argv)
{
    flow_opts_t o;
    flow_run_t r;
    cli_outputs_t out;
    FILE *f;
    int rc = parse(argc, argv, &o);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc;
    }
    memset(&r, 0, sizeof r);
    rc = run(&o, &r);
    if (rc == CLI_OK) {
        rc = clean(&o, &r);
    }
    cli_outputs_begin(&out, "flow");
    if (rc == CLI_OK && o.json_path != NULL) {
        cJSON *doc = json_doc(&o, &r);
        json_out_lazy_t lazy = {"templates", r.res.count, template_item, &r};
        if (doc == NULL || (f = cli_outputs_open(&out, o.json_path)) == NULL ||
            json_out_print(f, doc, &lazy) != 0) {
            rc = CLI_INPUT;
        }
        cJSON_Delete(doc);
    }
    if (rc == CLI_OK && o.overlay_path != NULL) {
        rc = (f = cli_outputs_open(&out, o.overlay_path)) == NULL ? CLI_INPUT
                                                                   : write_overlay(f, &o, &r);
    }
    rc = rc == CLI_OK ? cli_outputs_commit(&out) : rc;
    cli_outputs_abort(&out);
    if (rc == CLI_OK && !o.quiet && (o.json_path == NULL || strcmp(o.json_path, "-") != 0)) {
        summary(&o, &r);
    }
    free(r.tp);
    free(r.clean);
    gray_image_free(&r.ref);
    gray_image_free(&r.next);
    return rc;
}
