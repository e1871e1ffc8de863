/* cmd_match.c - `ssda match SEARCH.png WINDOW.png`: one SSDA template search. */
#include "cli.h"
#include "json_out.h"
#include "progress.h"

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
    "  --threshold MODE  how partial sums are cut (default auto):\n"
    "                      auto           automatic constant threshold: exact, fast\n"
    "                      none           every position summed in full (reference)\n"
    "                      fixed:T        constant threshold T (SAD units); exact if\n"
    "                                     any position completes\n"
    "                      ramp:LAMBDA[:K]  Barnea-Silverman T(r) = LAMBDA (r + K sqrt r),\n"
    "                                     LAMBDA in SAD units per pixel, K default 2\n"
    "                      auto-ramp[:K]  automatic increasing threshold (eq. 4)\n"
    "  --scan ORDER      raster (default), predict (rings out from --predict),\n"
    "                    coarse (8 px grid, then 1 px descent; may miss the minimum)\n"
    "  --predict X,Y     predicted top-left (implies --scan predict)\n"
    "  --order ROWS      rows (default) or spread (decorrelated row order)\n"
    "  --no-bounds       no successive-elimination bounds (default: bounds on;\n"
    "                    exact either way, bounds skip more work)\n"
    "  --coarse-step N   grid step of --scan coarse, px (default 8)\n"
    "  --json            print one JSON object instead of text (stdout; no FILE:\n"
    "                    redirect it):\n"
    "                    {\"x\",\"y\",\"sad\",\"exact\",\"positions\",\"completed\",\"pixel_ops\",...}\n"
    "  -h, --help        this text\n"
    "\n"
    "Exit codes: 0 ok, 1 bad input, 2 usage.\n";

/* The --json object, one line on stdout (docs/cli.md). */
static int print_json(const ssda_match_result_t *res, const gray_image_t *s_img,
                      const gray_image_t *w_img, uint64_t brute, const char *tname,
                      const char *scan, double secs)
{
    cJSON *doc = json_out_object();
    int rc;
    cJSON_AddNumberToObject(doc, "x", res->x);
    cJSON_AddNumberToObject(doc, "y", res->y);
    json_out_add_u64(doc, "sad", res->sad);
    cJSON_AddBoolToObject(doc, "exact", res->exact);
    json_out_add_u64(doc, "positions", res->positions);
    json_out_add_u64(doc, "completed", res->completed);
    json_out_add_u64(doc, "pixel_ops", res->pixel_ops);
    json_out_add_u64(doc, "brute_force_ops", brute);
    cJSON_AddNumberToObject(doc, "search_w", s_img->width);
    cJSON_AddNumberToObject(doc, "search_h", s_img->height);
    cJSON_AddNumberToObject(doc, "window_w", w_img->width);
    cJSON_AddNumberToObject(doc, "window_h", w_img->height);
    cJSON_AddNumberToObject(doc, "bits", s_img->bits);
    cJSON_AddStringToObject(doc, "threshold", tname);
    cJSON_AddStringToObject(doc, "scan", scan);
    json_out_add_fixed(doc, "time_s", secs, 6);
    rc = json_out_print(stdout, doc, NULL);
    cJSON_Delete(doc);
    return rc == 0 ? CLI_OK : cli_input_error("match", "out of memory for the JSON");
}

int cmd_match(int argc, char **argv)
{
    cli_args_t a;
    ssda_match_config_t cfg;
    ssda_match_result_t res;
    ssda_view_t area, win;
    gray_image_t s_img = {0}, w_img = {0};
    const char *v;
    int json = 0, have_predict = 0, scan_given = 0, rc;
    int32_t px = 0, py = 0;
    uint32_t u;
    double t0, secs;
    void *work = NULL;
    char tname[64];
    uint64_t npos, brute;

    memset(&cfg, 0, sizeof cfg);
    cfg.flags = SSDA_MATCH_BOUNDS; /* exact, and the least work on a host */
    cli_args_begin(&a, "match", argc, argv);
    while (cli_next(&a)) {
        if (cli_flag(&a, "--help") || cli_flag(&a, "-h")) {
            fputs(help, stdout);
            return CLI_OK;
        } else if (cli_flag(&a, "--json")) {
            json = 1;
        } else if (cli_flag(&a, "--bounds")) {
            cfg.flags |= SSDA_MATCH_BOUNDS;
        } else if (cli_flag(&a, "--no-bounds")) {
            cfg.flags &= (uint8_t)~SSDA_MATCH_BOUNDS;
        } else if (cli_flag(&a, "--quiet")) {
            /* one search: nothing to silence */
        } else if (cli_opt(&a, "--threshold", &v)) {
            if (v != NULL && cli_parse_threshold(v, &cfg) != 0) {
                return cli_usage_error(a.cmd, "bad --threshold '%s' (auto, none, fixed:T, "
                                       "ramp:LAMBDA[:K], auto-ramp[:K])", v);
            }
        } else if (cli_opt(&a, "--scan", &v)) {
            if (v != NULL && cli_parse_scan(v, &cfg) != 0) {
                return cli_usage_error(a.cmd, "bad --scan '%s' (raster, predict, coarse)", v);
            }
            scan_given = 1;
        } else if (cli_opt(&a, "--order", &v)) {
            if (v != NULL && cli_parse_order(v, &cfg) != 0) {
                return cli_usage_error(a.cmd, "bad --order '%s' (rows, spread)", v);
            }
        } else if (cli_opt(&a, "--predict", &v)) {
            if (v != NULL && cli_parse_pair(v, -65535, 65535, &px, &py) != 0) {
                return cli_usage_error(a.cmd, "bad --predict '%s' (want X,Y)", v);
            }
            have_predict = 1;
        } else if (cli_opt(&a, "--coarse-step", &v)) {
            if (v != NULL && cli_parse_u32(v, 1, 65535, &u) != 0) {
                return cli_usage_error(a.cmd, "bad --coarse-step '%s' (1..65535)", v);
            }
            cfg.coarse_step = (uint16_t)u;
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
    if (a.npos > 2 && json && a.pos[2][0] != '-') {
        /* often "--json FILE" as track and compare take it */
        return cli_usage_error(a.cmd, "unexpected argument '%s' (match --json prints to "
                               "stdout; redirect it: --json > FILE)", a.pos[2]);
    }
    if (cli_positionals(&a, 2, "need SEARCH.png and WINDOW.png") != CLI_OK) {
        return CLI_USAGE;
    }
    if (have_predict) {
        if (scan_given && cfg.scan != SSDA_SCAN_PREDICT) {
            return cli_usage_error(a.cmd, "--predict needs --scan predict");
        }
        cfg.scan = SSDA_SCAN_PREDICT;
        cfg.predict_x = px;
        cfg.predict_y = py;
    } else if (cfg.scan == SSDA_SCAN_PREDICT) {
        return cli_usage_error(a.cmd, "--scan predict needs --predict X,Y");
    }

    if (cli_load_png_pair(a.cmd, a.pos[0], a.pos[1], &s_img, &w_img) != 0) {
        return CLI_INPUT;
    }
    rc = CLI_INPUT;
    if (w_img.width > s_img.width || w_img.height > s_img.height) {
        cli_input_error(a.cmd, "window '%s' (%u x %u) is larger than search image '%s' (%u x %u)",
                        a.pos[1], w_img.width, w_img.height, a.pos[0], s_img.width,
                        s_img.height);
        goto done;
    }
    if (gray_image_view(&s_img, &area) != SSDA_OK || gray_image_view(&w_img, &win) != SSDA_OK) {
        cli_input_error(a.cmd, "internal error: bad image view");
        goto done;
    }
    if (cfg.flags & SSDA_MATCH_BOUNDS) {
        cfg.work_size = SSDA_MATCH_WORK_SIZE(s_img.width, s_img.height, w_img.width,
                                             w_img.height);
        work = malloc(cfg.work_size);
        if (work == NULL) {
            cli_input_error(a.cmd, "out of memory for the bounds buffer (%zu bytes)",
                            cfg.work_size);
            goto done;
        }
        cfg.work = work;
    }
    t0 = progress_now();
    rc = ssda_match(&area, &win, &cfg, &res);
    secs = progress_now() - t0;
    if (rc != SSDA_OK) {
        cli_input_error(a.cmd, "search failed: %s", ssda_strerror(rc));
        rc = CLI_INPUT;
        goto done;
    }
    rc = CLI_OK;
    cli_threshold_name(&cfg, tname, sizeof tname);
    npos = (uint64_t)(s_img.width - w_img.width + 1) * (s_img.height - w_img.height + 1);
    brute = npos * w_img.width * w_img.height;
    if (json) {
        rc = print_json(&res, &s_img, &w_img, brute, tname, cli_scan_name(&cfg), secs);
    } else {
        printf("best match: x=%u y=%u  (top-left of %s in %s)\n", res.x, res.y, a.pos[1],
               a.pos[0]);
        printf("SAD:        %llu  (%s)\n", (unsigned long long)res.sad,
               res.exact ? "exact: the true minimum"
                         : "not guaranteed to be the true minimum with this mode");
        printf("work:       %llu pixel ops = %.2f %% of brute force (%llu); %u of %llu "
               "positions visited, %u summed in full\n",
               (unsigned long long)res.pixel_ops,
               brute > 0 ? 100.0 * (double)res.pixel_ops / (double)brute : 0.0,
               (unsigned long long)brute, res.positions, (unsigned long long)npos,
               res.completed);
        printf("mode:       threshold %s, scan %s, %u-bit, %.3f ms\n", tname,
               cli_scan_name(&cfg), s_img.bits, secs * 1e3);
    }
done:
    free(work);
    gray_image_free(&s_img);
    gray_image_free(&w_img);
    return rc;
}
