/* cmd_track.c - `ssda track FIRST.png SECOND.png`: the seed's cloud tracking. */
#include "track_metric.h"
#include "track_run.h"
#include "parallel.h"

#include <stdlib.h>
#include <string.h>

static void help(void)
{
    fputs("usage: ssda track FIRST.png SECOND.png [options]\n"
          "\n"
          "Motion vectors between two images, as in the seed's cloud tracking: windows\n"
          "are laid on a grid in SECOND; each is searched by SSDA in the area of FIRST\n"
          "centred on it. dx, dy = motion from FIRST to SECOND in pixels (x right,\n"
          "y down): the window at (x, y) of SECOND matched best at (x-dx, y-dy) of FIRST.\n"
          "Prints a summary; --json writes every window, --overlay draws them.\n"
          "\n",
          stdout);
    fputs(track_opts_help, stdout);
    fputs("  --threads N       decode the images and track on N threads (default: every\n"
          "                    core, 0 too): grid rows in fixed bands of columns as a\n"
          "                    wavefront, each window solved after its neighbours, so\n"
          "                    the output is the same for any N (not with --mem: one\n"
          "                    thread)\n"
          "  -h, --help        this text\n"
          "\n"
          "JSON: {\"windows\":[{\"x\",\"y\",\"dx\",\"dy\",\"sub_dx\",\"sub_dy\",\"sad\",\"texture\",\n"
          "       \"unique\",\"status\",\"exact\"}...], \"stats\":{\"pixel_ops\",\"check_pixels\",\n"
          "       \"brute_force_ops\",\"ok\",\"flat\",...}, \"grid\",...}\n"
          "status: ok (trust it), flat (no texture, not searched), ambiguous (another\n"
          "match as good), at_limit (best match on the border of the search: the motion\n"
          "may be larger), excluded (--exclude), masked (fill value), edge (area leaves\n"
          "FIRST). dx, dy, sub_dx, sub_dy are valid for ok, ambiguous and at_limit; the\n"
          "summary, its median motion and the overlay's arrows use ok vectors only.\n"
          "Exit codes: 0 ok, 1 bad input, 2 usage.\n",
          stdout);
}

/* --json and --overlay, all or nothing. */
static int write_outputs(const track_opts_t *o, const char *first, const char *second,
                         const track_result_t *r)
{
    cli_outputs_t out;
    FILE *f;
    char title[256], sub[256], tname[64];
    uint64_t brute = track_brute_ops(r);
    int rc = CLI_OK;
    cli_outputs_begin(&out, "track");
    if (o->json_path != NULL && ((f = cli_outputs_open(&out, o->json_path)) == NULL ||
                                 track_write_json("track", f, r, o, NULL, NULL) != 0)) {
        rc = CLI_INPUT;
    }
    if (rc == CLI_OK && o->overlay_path != NULL) {
        cli_threshold_name(&r->cfg.match, tname, sizeof tname);
        snprintf(title, sizeof title, "ssda track  %s -> %s", cli_basename(first),
                 cli_basename(second));
        snprintf(sub, sizeof sub,
                 "window %ux%u, search %ux%u, step %u, threshold %s%s:  %u ok, "
                 "median (%+.2f, %+.2f) px,  work %.1f %% of brute force",
                 r->grid.win_w, r->grid.win_h, r->grid.search_w, r->grid.search_h,
                 r->grid.step_x, tname, o->grad ? ", grad" : "", r->stats.ok,
                 track_median_motion(r, 0), track_median_motion(r, 1),
                 brute ? 100.0 * (double)track_work_ops(r) / (double)brute : 0.0);
        if ((f = cli_outputs_open(&out, o->overlay_path)) == NULL ||
            track_write_overlay("track", f, o->overlay_path, r, o, NULL, NULL, title, sub) != 0) {
            rc = CLI_INPUT;
        }
    }
    rc = rc == CLI_OK ? cli_outputs_commit(&out) : rc;
    cli_outputs_abort(&out);
    return rc;
}

static void print_summary(const track_opts_t *o, const track_result_t *r)
{
    uint64_t brute = track_brute_ops(r);
    char tname[64];
    cli_threshold_name(&r->cfg.match, tname, sizeof tname);
    printf("%u window%s (%u x %u grid; window %ux%u, search %ux%u, step %ux%u)\n", r->grid.count,
           r->grid.count == 1 ? "" : "s", r->grid.cols, r->grid.rows, r->grid.win_w,
           r->grid.win_h, r->grid.search_w, r->grid.search_h, r->grid.step_x, r->grid.step_y);
    printf("status:  %u ok, %u flat, %u ambiguous, %u at_limit, %u excluded, %u masked, "
           "%u edge\n",
           r->stats.ok, r->stats.flat, r->stats.ambiguous, r->stats.at_limit, r->stats.excluded,
           r->stats.masked, r->stats.edge);
    if (r->stats.ok > 0) {
        printf("motion:  median of the %u ok vectors dx=%+.2f dy=%+.2f px (FIRST -> SECOND)\n",
               r->stats.ok, track_median_motion(r, 0), track_median_motion(r, 1));
    }
    if (brute > 0) {
        printf("work:    %llu pixel ops (search %llu + window tests %llu) = %.2f %% of brute "
               "force over the %u windows neither edge nor masked (%llu); threshold %s, "
               "scan %s, %.2f ms\n",
               (unsigned long long)track_work_ops(r), (unsigned long long)r->stats.pixel_ops,
               (unsigned long long)r->stats.check_pixels,
               100.0 * (double)track_work_ops(r) / (double)brute,
               r->stats.windows - r->stats.edge - r->stats.masked, (unsigned long long)brute,
               tname, cli_scan_name(&r->cfg.match), 1e3 * r->secs);
    }
    if (o->have_mem) {
        uint64_t images = (uint64_t)r->first.stride * r->first.height +
                          (uint64_t)r->second.stride * r->second.height;
        printf("memory:  plates of %zu + %zu bytes (--mem %llu); read %llu bytes in %llu "
               "reads = %.2f x the two images\n",
               r->arena_first, r->arena_second, (unsigned long long)o->mem,
               (unsigned long long)r->bytes_read, (unsigned long long)r->reads,
               images ? (double)r->bytes_read / (double)images : 0.0);
    }
    if (r->clean != NULL) {
        printf("cleaning: %s: %u of the %u ok vectors changed (JSON: relax_dx, relax_dy, "
               "changed)\n", o->relax_median ? "normalised median test" : "relaxation labelling",
               r->changed, r->stats.ok);
    }
    if (o->json_path != NULL) {
        printf("wrote:   %s\n", o->json_path);
    }
    if (o->overlay_path != NULL) {
        printf("wrote:   %s\n", o->overlay_path);
    }
}

int cmd_track(int argc, char **argv)
{
    track_opts_t o;
    track_result_t r;
    const char *first, *second;
    unsigned threads;
    int rc = parallel_take_threads("track", &argc, argv, &threads);
    if (rc != 0) {
        return CLI_USAGE;
    }
    cli_set_threads(threads);
    rc = track_parse_args("track", argc, argv, help, &o, &first, &second);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc; /* -1: --help */
    }
    if ((rc = track_run("track", first, second, &o, &r)) != CLI_OK) {
        return rc;
    }
    rc = write_outputs(&o, first, second, &r);
    if (rc == CLI_OK && !cli_is_stdout(o.json_path) && !cli_is_stdout(o.overlay_path)) {
        print_summary(&o, &r);
        track_metric_print(&o, &r);
    }
    track_result_free(&r);
    return rc;
}
