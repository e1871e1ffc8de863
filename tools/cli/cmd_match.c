/* cmd_match.c - `ssda match SEARCH.png WINDOW.png`: one SSDA template search. */
#include "cli.h"
#include "json_out.h"
#include "progress.h"
#include "ssda/ncc.h"

#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: ssda match SEARCH.png WINDOW.png [options]\n"
    "\n"
    "Find where WINDOW fits best in SEARCH: the placement with the smallest sum of\n"
    "absolute differences (SAD), ties to the smallest y then x. Prints the top-left\n"
    "(x, y) of that placement in SEARCH, 0-based, x right, y down.\n"
    "\n"
    "options:\n"
    "  --metric M        sad (default), ncc (the largest correlation coefficient rho:\n"
    "                    brightness and contrast changes do not matter) or absncc (the\n"
    "                    largest |rho|: inverted contrast matches too); exact either way.\n"
    "                    With ncc/absncc only --predict applies of the options below\n"
    "  --threshold MODE  how partial sums are cut (default auto):\n"
    "                      auto           automatic constant threshold: exact, fast\n"
    "                      none           every position summed in full (reference)\n"
    "                      fixed:T        constant threshold T (SAD units); exact if\n"
    "                                     any position completes, else the position\n"
    "                                     that summed the most pixels (the fallback)\n"
    "                      ramp:LAMBDA[:K]  Barnea-Silverman T(r) = LAMBDA (r + K sqrt r),\n"
    "                                     LAMBDA in SAD units per pixel, K default 2\n"
    "                      auto-ramp[:K]  automatic increasing threshold (eq. 4)\n"
    "  --scan ORDER      raster (default), predict (rings out from --predict),\n"
    "                    coarse (8 px grid, then 1 px descent; may miss the minimum)\n"
    "  --predict X,Y     predicted top-left (implies --scan predict)\n"
    "  --order ROWS      rows (default) or spread (decorrelated row order)\n"
    "  --no-bounds       no successive-elimination bounds (default: bounds on, with\n"
    "                    the multilevel block bounds under auto; exact either way,\n"
    "                    bounds skip more work)\n"
    "  --coarse-step N   grid step of --scan coarse, px (default 8)\n"
    "  --json            print one JSON object instead of text (stdout; no FILE:\n"
    "                    redirect it):\n"
    "                    {\"x\",\"y\",\"sad\",\"rho\",\"metric\",\"exact\",\"all_cut\",\"positions\",\n"
    "                    \"completed\",\"pixel_ops\",...}: sad and rho at the best placement\n"
    "                    whatever the metric; sad is always the full SAD at (x, y);\n"
    "                    all_cut: every position was cut (fixed, ramp) and (x, y) is\n"
    "                    the fallback\n"
    "  -h, --help        this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

/* The options as parsed. */
typedef struct {
    ssda_match_config_t cfg;
    const char *search_path, *window_path;
    int json, have_predict, scan_given, sad_option;
    int metric; /* 0 sad, 1 ncc, 2 absncc */
    int32_t px, py;
} match_opts_t;

/* A search as run: the images, the result, its cost. */
typedef struct {
    gray_image_t s_img, w_img;
    ssda_match_result_t res; /* with --metric ncc/absncc: the place, its SAD, the work */
    int32_t rho_q30;         /* rho at the best place, Q2.30 */
    double secs;
} match_job_t;

static void print_help(void)
{
    fputs(help, stdout);
}

/* The current option into opts (a match_opts_t): 1 taken (a->bad set on a bad
   value, said), 0 unknown. */
static int take_option(cli_args_t *a, void *opts)
{
    match_opts_t *o = opts;
    const char *v;
    uint32_t u;
    if (cli_opt(a, "--metric", &v)) {
        if (v != NULL) {
            o->metric = !strcmp(v, "sad") ? 0 : !strcmp(v, "ncc") ? 1 : !strcmp(v, "absncc") ? 2 : -1;
            if (o->metric < 0) {
                a->bad = cli_usage_error(a->cmd, "bad --metric '%s' (sad, ncc, absncc)", v);
            }
        }
    } else if (cli_flag(a, "--json")) {
        o->json = 1;
    } else if (cli_flag(a, "--bounds")) {
        o->cfg.flags |= SSDA_MATCH_BOUNDS;
        o->sad_option = 1;
    } else if (cli_flag(a, "--no-bounds")) {
        o->cfg.flags &= (uint8_t)~SSDA_MATCH_BOUNDS;
        o->sad_option = 1;
    } else if (cli_flag(a, "--quiet")) {
        /* one search: nothing to silence */
    } else if (cli_opt(a, "--threshold", &v)) {
        o->sad_option = 1;
        if (v != NULL && cli_parse_threshold(v, &o->cfg) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --threshold '%s' (auto, none, fixed:T, "
                                     "ramp:LAMBDA[:K], auto-ramp[:K])", v);
        }
    } else if (cli_opt(a, "--scan", &v)) {
        if (v != NULL && cli_parse_scan(v, &o->cfg) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --scan '%s' (raster, predict, coarse)", v);
        }
        o->scan_given = 1;
    } else if (cli_opt(a, "--order", &v)) {
        o->sad_option = 1;
        if (v != NULL && cli_parse_order(v, &o->cfg) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --order '%s' (rows, spread)", v);
        }
    } else if (cli_opt(a, "--predict", &v)) {
        if (v != NULL && cli_parse_pair(v, -65535, 65535, &o->px, &o->py) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --predict '%s' (want X,Y)", v);
        }
        o->have_predict = 1;
    } else if (cli_opt(a, "--coarse-step", &v)) {
        o->sad_option = 1;
        if (v != NULL && cli_parse_u32(v, 1, 65535, &u) != 0) {
            a->bad = cli_usage_error(a->cmd, "bad --coarse-step '%s' (1..65535)", v);
        }
        o->cfg.coarse_step = v != NULL && !a->bad ? (uint16_t)u : o->cfg.coarse_step;
    } else {
        return 0;
    }
    return 1;
}

/* After the loop: the two files, and --predict with --scan. */
static int check_args(const cli_args_t *a, match_opts_t *o)
{
    if (a->npos > 2 && o->json && a->pos[2][0] != '-') {
        /* often "--json FILE" as track and compare take it */
        return cli_usage_error(a->cmd, "unexpected argument '%s' (match --json prints to "
                               "stdout; redirect it: --json > FILE)", a->pos[2]);
    }
    if (cli_positionals(a, 2, "need SEARCH.png and WINDOW.png") != CLI_OK) {
        return CLI_USAGE;
    }
    o->search_path = a->pos[0];
    o->window_path = a->pos[1];
    if (o->metric != 0 && (o->sad_option || (o->scan_given && o->cfg.scan == SSDA_SCAN_COARSE))) {
        return cli_usage_error(a->cmd, "--threshold, --order, --no-bounds, --coarse-step and "
                               "--scan coarse are SAD options (drop them, or --metric sad)");
    }
    if (o->have_predict) {
        if (o->scan_given && o->cfg.scan != SSDA_SCAN_PREDICT) {
            return cli_usage_error(a->cmd, "--predict needs --scan predict");
        }
        o->cfg.scan = SSDA_SCAN_PREDICT;
        o->cfg.predict_x = o->px;
        o->cfg.predict_y = o->py;
    } else if (o->cfg.scan == SSDA_SCAN_PREDICT) {
        return cli_usage_error(a->cmd, "--scan predict needs --predict X,Y");
    }
    return CLI_OK;
}

/* Parse argv. Returns CLI_OK, CLI_USAGE, or -1 after --help. */
static int parse_args(int argc, char **argv, match_opts_t *o)
{
    cli_args_t a;
    int rc;
    memset(o, 0, sizeof *o);
    o->cfg.flags = SSDA_MATCH_BOUNDS; /* exact, and the least work on a host */
    cli_args_begin(&a, "match", argc, argv);
    if ((rc = cli_scan_options(&a, print_help, take_option, o)) != CLI_OK) {
        return rc;
    }
    return check_args(&a, o);
}

/* The correlation search (--metric ncc/absncc); the place, its SAD and the
   work into j->res, rho into j->rho_q30. */
static int run_ncc(const match_opts_t *o, const ssda_view_t *area, const ssda_view_t *win,
                   match_job_t *j)
{
    ssda_ncc_config_t c;
    ssda_ncc_result_t r;
    double t0;
    int e;
    if ((uint32_t)win->width * win->height > SSDA_NCC_MAX_PIXELS) {
        return cli_input_error("match", "window %u x %u: the correlation search takes at most "
                               "%u pixels (256 x 256): crop or reduce '%s', or search by SAD "
                               "(--metric sad, the default; no such limit)", win->width,
                               win->height, SSDA_NCC_MAX_PIXELS, o->window_path);
    }
    memset(&c, 0, sizeof c);
    c.metric = (uint8_t)(o->metric == 2 ? SSDA_NCC_ABS : SSDA_NCC_RHO);
    if (o->have_predict) {
        c.flags = SSDA_NCC_PREDICT;
        c.predict_x = o->px;
        c.predict_y = o->py;
    }
    c.work_size = SSDA_NCC_WORK_SIZE(area->width, win->width, win->height);
    if ((c.work = malloc(c.work_size)) == NULL) {
        return cli_input_error("match", "out of memory (%zu bytes)", c.work_size);
    }
    t0 = progress_now();
    e = ssda_ncc_match(area, win, &c, &r);
    j->secs = progress_now() - t0;
    free(c.work);
    if (e == SSDA_OK && (r.flags & SSDA_NCC_FLAT_WINDOW) != 0u) {
        /* rho is 0 / 0 at every placement: the library's (0, 0) is no answer */
        return cli_input_error("match", "window '%s' is flat (all %u x %u pixels equal): its "
                               "correlation coefficient is undefined, so it fits nowhere "
                               "better than anywhere; --metric sad compares levels",
                               o->window_path, win->width, win->height);
    }
    if (e == SSDA_OK) {
        j->res.x = r.x;
        j->res.y = r.y;
        j->res.positions = r.positions;
        j->res.completed = r.completed;
        j->res.pixel_ops = r.pixel_ops;
        j->res.exact = true;
        j->rho_q30 = r.rho_q30;
        e = ssda_sad_at(area, win, r.x, r.y, &j->res.sad);
    }
    return e == SSDA_OK ? CLI_OK : cli_input_error("match", "search failed: %s", ssda_strerror(e));
}

/* Load both images and search. */
static int run_match(match_opts_t *o, match_job_t *j)
{
    ssda_view_t area, win;
    void *work = NULL;
    double t0;
    int e;
    if (cli_load_png_pair("match", o->search_path, o->window_path, &j->s_img, &j->w_img) != 0) {
        return CLI_INPUT;
    }
    if (j->w_img.width > j->s_img.width || j->w_img.height > j->s_img.height) {
        return cli_input_error("match", "window '%s' (%u x %u) is larger than search image '%s' "
                               "(%u x %u)", o->window_path, j->w_img.width, j->w_img.height,
                               o->search_path, j->s_img.width, j->s_img.height);
    }
    if (gray_image_view(&j->s_img, &area) != SSDA_OK ||
        gray_image_view(&j->w_img, &win) != SSDA_OK) {
        return cli_input_error("match", "internal error: bad image view");
    }
    if (o->metric != 0) {
        return run_ncc(o, &area, &win, j);
    }
    if (o->cfg.flags & SSDA_MATCH_BOUNDS) {
        o->cfg.work_size = SSDA_MATCH_WORK_SIZE(j->s_img.width, j->s_img.height, j->w_img.width,
                                                j->w_img.height);
        if (o->cfg.threshold == SSDA_THRESHOLD_AUTO) {
            /* the block levels too (issue 18): the same result, less work on
               large templates, for an integral image of the scene */
            o->cfg.flags |= SSDA_MATCH_BLOCKS;
            o->cfg.work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(j->s_img.width, j->s_img.height,
                                                           j->w_img.width, j->w_img.height);
        }
        if ((work = malloc(o->cfg.work_size)) == NULL) {
            return cli_input_error("match", "out of memory for the bounds buffer (%zu bytes)",
                                   o->cfg.work_size);
        }
        o->cfg.work = work;
    }
    t0 = progress_now();
    e = ssda_match(&area, &win, &o->cfg, &j->res);
    j->secs = progress_now() - t0;
    free(work);
    o->cfg.work = NULL;
    if (e == SSDA_OK && (uint32_t)win.width * win.height <= SSDA_NCC_MAX_PIXELS) {
        e = ssda_ncc_at(&area, &win, j->res.x, j->res.y, &j->rho_q30); /* rho there too */
    }
    if (e != SSDA_OK) {
        return cli_input_error("match", "search failed: %s", ssda_strerror(e));
    }
    return CLI_OK;
}

/* The --json object, one line on stdout (docs/cli.md). */
static int print_json(const match_opts_t *o, const match_job_t *j, uint64_t brute,
                      const char *tname)
{
    cJSON *doc = json_out_object();
    int rc;
    cJSON_AddNumberToObject(doc, "x", j->res.x);
    cJSON_AddNumberToObject(doc, "y", j->res.y);
    json_out_add_u64(doc, "sad", j->res.sad);
    if ((uint32_t)j->w_img.width * j->w_img.height <= SSDA_NCC_MAX_PIXELS) {
        json_out_add_fixed(doc, "rho", j->rho_q30 / 1073741824.0, 6);
    }
    cJSON_AddStringToObject(doc, "metric", o->metric == 0 ? "sad" : o->metric == 1 ? "ncc" : "absncc");
    cJSON_AddBoolToObject(doc, "exact", j->res.exact);
    cJSON_AddBoolToObject(doc, "all_cut", o->metric == 0 && j->res.completed == 0u);
    json_out_add_u64(doc, "positions", j->res.positions);
    json_out_add_u64(doc, "completed", j->res.completed);
    json_out_add_u64(doc, "pixel_ops", j->res.pixel_ops);
    json_out_add_u64(doc, "brute_force_ops", brute);
    cJSON_AddNumberToObject(doc, "search_w", j->s_img.width);
    cJSON_AddNumberToObject(doc, "search_h", j->s_img.height);
    cJSON_AddNumberToObject(doc, "window_w", j->w_img.width);
    cJSON_AddNumberToObject(doc, "window_h", j->w_img.height);
    cJSON_AddNumberToObject(doc, "bits", j->s_img.bits);
    cJSON_AddStringToObject(doc, "threshold", tname);
    cJSON_AddStringToObject(doc, "scan", cli_scan_name(&o->cfg));
    json_out_add_fixed(doc, "time_s", j->secs, 6);
    rc = json_out_print(stdout, doc, NULL);
    cJSON_Delete(doc);
    return rc == 0 ? CLI_OK : cli_input_error("match", "out of memory for the JSON");
}

static void print_text(const match_opts_t *o, const match_job_t *j, uint64_t npos,
                       uint64_t brute, const char *tname)
{
    const ssda_match_result_t *res = &j->res;
    printf("best match: x=%u y=%u  (top-left of %s in %s)\n", res->x, res->y, o->window_path,
           o->search_path);
    if (o->metric != 0) {
        printf("rho:        %.6f  (exact: the %s correlation coefficient)\n",
               j->rho_q30 / 1073741824.0, o->metric == 2 ? "largest |rho| among the" : "largest");
        printf("SAD there:  %llu\n", (unsigned long long)res->sad);
    } else {
        printf("SAD:        %llu  (%s)\n", (unsigned long long)res->sad,
               res->exact ? "exact: the true minimum"
               : res->completed == 0u
                   ? "full SAD of the fallback: every position was cut, not the minimum"
                   : "not guaranteed to be the true minimum with this mode");
        if ((uint32_t)j->w_img.width * j->w_img.height <= SSDA_NCC_MAX_PIXELS) {
            printf("rho there:  %.6f\n", j->rho_q30 / 1073741824.0);
        }
    }
    printf("work:       %llu pixel ops = %.2f %% of brute force (%llu); %u of %llu "
           "positions visited, %u summed in full\n",
           (unsigned long long)res->pixel_ops,
           brute > 0 ? 100.0 * (double)res->pixel_ops / (double)brute : 0.0,
           (unsigned long long)brute, res->positions, (unsigned long long)npos, res->completed);
    if (o->metric != 0) {
        printf("mode:       %s, correlation search with early exit%s, %u-bit, %.3f ms\n",
               o->metric == 1 ? "ncc" : "absncc", o->have_predict ? " from --predict" : "",
               j->s_img.bits, j->secs * 1e3);
    } else {
        printf("mode:       threshold %s, scan %s, %u-bit, %.3f ms\n", tname,
               cli_scan_name(&o->cfg), j->s_img.bits, j->secs * 1e3);
    }
}

int cmd_match(int argc, char **argv)
{
    match_opts_t o;
    match_job_t j;
    char tname[64];
    uint64_t npos, brute;
    int rc = parse_args(argc, argv, &o);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc; /* -1: --help */
    }
    memset(&j, 0, sizeof j);
    rc = run_match(&o, &j);
    if (rc == CLI_OK) {
        cli_threshold_name(&o.cfg, tname, sizeof tname);
        npos = (uint64_t)(j.s_img.width - j.w_img.width + 1) *
               (j.s_img.height - j.w_img.height + 1);
        brute = npos * j.w_img.width * j.w_img.height;
        if (o.json) {
            rc = print_json(&o, &j, brute, tname);
        } else {
            print_text(&o, &j, npos, brute, tname);
        }
    }
    gray_image_free(&j.s_img);
    gray_image_free(&j.w_img);
    return rc;
}
