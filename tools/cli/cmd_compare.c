/* cmd_compare.c - `ssda compare FIRST.png SECOND.png`: the seed's Table 1 on the
   user's images: SSDA vectors against exhaustive normalised cross-correlation. */
#include "ncc_ref.h"
#include "progress.h"
#include "track_run.h"

#include <stdlib.h>
#include <string.h>

static void help(void)
{
    fputs("usage: ssda compare FIRST.png SECOND.png [track options]\n"
          "\n"
          "Track as `ssda track` does, then search every ok window again by exhaustive\n"
          "normalised cross-correlation (NCC, the maximum the seed's FFT correlation\n"
          "finds) over the same area of the same (pre-processed) images. Prints the share\n"
          "of windows whose SSDA vector is within 0, 1 and 2 px of the NCC vector\n"
          "(largest of |ddx|, |ddy|) and the time of each method (the seed's Table 1).\n"
          "--json adds ref_dx, ref_dy to each window and a \"compare\" object;\n"
          "--overlay draws the NCC vectors as thin cyan arrows on top of the yellow\n"
          "SSDA ones (a cyan core where both agree).\n"
          "\n",
          stdout);
    fputs(track_opts_help, stdout);
    fputs("  -h, --help        this text\n"
          "\nExit codes: 0 ok, 1 bad input, 2 usage.\n",
          stdout);
}

#define PCT(n) (ok ? 100.0 * (double)(n) / (double)ok : 0.0)

/* {"compare":{...}}: the members compare adds to track's JSON. */
static cJSON *json_compare(uint32_t ok, const uint32_t within[3], double ssda_secs,
                           double ncc_secs)
{
    cJSON *extra = cJSON_CreateObject();
    cJSON *c = cJSON_AddObjectToObject(extra, "compare");
    cJSON_AddStringToObject(c, "reference", "ncc");
    cJSON_AddNumberToObject(c, "windows", ok);
    cJSON_AddNumberToObject(c, "within_0", within[0]);
    cJSON_AddNumberToObject(c, "within_1", within[1]);
    cJSON_AddNumberToObject(c, "within_2", within[2]);
    json_out_add_fixed(c, "within_0_pct", PCT(within[0]), 2);
    json_out_add_fixed(c, "within_1_pct", PCT(within[1]), 2);
    json_out_add_fixed(c, "within_2_pct", PCT(within[2]), 2);
    json_out_add_fixed(c, "ssda_time_s", ssda_secs, 6);
    json_out_add_fixed(c, "ncc_time_s", ncc_secs, 6);
    return extra;
}

int cmd_compare(int argc, char **argv)
{
    cli_args_t a;
    cli_outputs_t out;
    FILE *f;
    track_opts_t o;
    track_result_t r;
    int32_t (*ref)[2] = NULL;
    double (*truth)[2] = NULL;
    uint32_t k, within[3] = {0, 0, 0}, hx, hy, ok = 0;
    double t0, ncc_secs;
    progress_t prog;
    int rc;
    char title[256], sub[256];

    track_opts_init(&o);
    cli_args_begin(&a, "compare", argc, argv);
    while (cli_next(&a)) {
        if (cli_flag(&a, "--help") || cli_flag(&a, "-h")) {
            help();
            return CLI_OK;
        }
        if (!track_opts_take(&a, &o)) {
            return cli_unknown(&a);
        }
        if (a.bad) {
            return CLI_USAGE;
        }
    }
    if (a.bad) {
        return CLI_USAGE;
    }
    if ((rc = track_check_positionals(&a, &o)) != CLI_OK) {
        return rc;
    }
    if (cli_is_stdout(o.overlay_path) && cli_is_stdout(o.json_path)) {
        return cli_usage_error(a.cmd, "--json and --overlay cannot both go to stdout");
    }
    cli_warn_png_name(a.cmd, "--overlay", o.overlay_path);
    if (cli_output_check(a.cmd, o.json_path) != 0 ||
        cli_output_check(a.cmd, o.overlay_path) != 0) {
        return CLI_INPUT;
    }
    cli_outputs_begin(&out, a.cmd);
    rc = track_run(a.cmd, a.pos[0], a.pos[1], &o, &r);
    if (rc != CLI_OK) {
        return rc;
    }
    ref = calloc(r.grid.count + 1u, sizeof *ref);
    truth = calloc(r.grid.count + 1u, sizeof *truth);
    if (ref == NULL || truth == NULL) {
        rc = cli_input_error(a.cmd, "out of memory");
        goto done;
    }
    hx = (r.grid.search_w - r.grid.win_w) / 2u;
    hy = (r.grid.search_h - r.grid.win_h) / 2u;
    progress_begin(&prog, "NCC reference", r.grid.count, o.quiet);
    t0 = progress_now();
    for (k = 0; k < r.grid.count; k++) {
        const ssda_track_vector_t *v = &r.vec[k];
        uint32_t bx, by, d;
        double score;
        int32_t ddx, ddy;
        if (v->status != SSDA_TRACK_OK) {
            continue;
        }
        if (ncc_search(&r.first, v->x - hx, v->y - hy, r.grid.search_w, r.grid.search_h,
                       &r.second, v->x, v->y, r.grid.win_w, r.grid.win_h, &bx, &by,
                       &score) != 0) {
            progress_end(&prog);
            rc = cli_input_error(a.cmd, "out of memory");
            goto done;
        }
        ref[k][0] = (int32_t)hx - (int32_t)bx;
        ref[k][1] = (int32_t)hy - (int32_t)by;
        truth[k][0] = ref[k][0];
        truth[k][1] = ref[k][1];
        ddx = abs(v->dx - ref[k][0]);
        ddy = abs(v->dy - ref[k][1]);
        d = (uint32_t)(ddx > ddy ? ddx : ddy);
        ok++;
        if (d <= 2u) {
            within[2]++;
            if (d <= 1u) {
                within[1]++;
                if (d == 0u) {
                    within[0]++;
                }
            }
        }
        progress_update(&prog, k + 1u);
    }
    ncc_secs = progress_now() - t0;
    progress_end(&prog);

    if (o.json_path != NULL) {
        if ((f = cli_outputs_open(&out, o.json_path)) == NULL ||
            track_write_json(a.cmd, f, &r, &o, (const int32_t(*)[2])ref,
                             json_compare(ok, within, r.secs, ncc_secs)) != 0) {
            rc = CLI_INPUT;
            goto done;
        }
    }
    if (o.overlay_path != NULL) {
        snprintf(title, sizeof title, "ssda compare  %s -> %s", cli_basename(a.pos[0]),
                 cli_basename(a.pos[1]));
        snprintf(sub, sizeof sub,
                 "SSDA vs exhaustive NCC on %u windows: within 0 px %.0f %%, 1 px %.0f %%, "
                 "2 px %.0f %%",
                 ok, PCT(within[0]), PCT(within[1]), PCT(within[2]));
        if ((f = cli_outputs_open(&out, o.overlay_path)) == NULL ||
            track_write_overlay(a.cmd, f, o.overlay_path, &r, &o, (const double(*)[2])truth,
                                "NCC reference", title, sub) != 0) {
            rc = CLI_INPUT;
            goto done;
        }
    }
    if ((rc = cli_outputs_commit(&out)) != CLI_OK) {
        goto done;
    }
    if (!cli_is_stdout(o.json_path) && !cli_is_stdout(o.overlay_path)) {
        uint64_t brute = track_brute_ops(&r);
        printf("SSDA vs exhaustive normalised cross-correlation on %u ok windows "
               "(of %u; window %ux%u, search %ux%u):\n",
               ok, r.grid.count, r.grid.win_w, r.grid.win_h, r.grid.search_w,
               r.grid.search_h);
        printf("  within 0 px: %4u  %5.1f %%\n", within[0], PCT(within[0]));
        printf("  within 1 px: %4u  %5.1f %%\n", within[1], PCT(within[1]));
        printf("  within 2 px: %4u  %5.1f %%\n", within[2], PCT(within[2]));
        printf("time: SSDA %.2f ms (%.2f %% of brute-force pixel ops), NCC %.2f ms",
               1e3 * r.secs, brute ? 100.0 * (double)r.stats.pixel_ops / (double)brute : 0.0,
               1e3 * ncc_secs);
        if (r.secs > 0.0 && ok > 0) {
            printf(" (%.0fx the SSDA time)", ncc_secs / r.secs);
        }
        printf("\n");
        if (o.json_path != NULL) { /* as track reports its files */
            printf("wrote:   %s\n", o.json_path);
        }
        if (o.overlay_path != NULL) {
            printf("wrote:   %s\n", o.overlay_path);
        }
    }
done:
    cli_outputs_abort(&out);
    free(ref);
    free(truth);
    track_result_free(&r);
    return rc;
}
