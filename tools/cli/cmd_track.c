/* cmd_track.c - `ssda track FIRST.png SECOND.png`: the seed's cloud tracking. */
#include "track_run.h"

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
    fputs("  -h, --help        this text\n"
          "\n"
          "JSON: {\"windows\":[{\"x\",\"y\",\"dx\",\"dy\",\"sad\",\"status\",\"exact\"}...],\n"
          "       \"stats\":{\"pixel_ops\",\"bytes_read\",\"brute_force_ops\",...}, \"grid\",...}\n"
          "status: ok, excluded (no texture), masked (fill value), edge (area leaves FIRST).\n"
          "Exit codes: 0 ok, 1 bad input, 2 usage.\n",
          stdout);
}

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* Median of the OK windows' dx (axis 0) or dy (axis 1). */
static int32_t median_component(const track_result_t *r, int axis)
{
    int32_t *v = malloc((r->grid.count + 1u) * sizeof *v), m = 0;
    uint32_t k, n = 0;
    if (v == NULL) {
        return 0;
    }
    for (k = 0; k < r->grid.count; k++) {
        if (r->vec[k].status == SSDA_TRACK_OK) {
            v[n++] = axis == 0 ? r->vec[k].dx : r->vec[k].dy;
        }
    }
    if (n > 0) {
        qsort(v, n, sizeof *v, cmp_i32);
        m = v[n / 2];
    }
    free(v);
    return m;
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
                 "median motion (%+d, %+d) px,  work %.1f %% of brute force",
                 r->grid.win_w, r->grid.win_h, r->grid.search_w, r->grid.search_h,
                 r->grid.step_x, tname, o->grad ? ", grad" : "", r->stats.ok,
                 (int)median_component(r, 0), (int)median_component(r, 1),
                 brute ? 100.0 * (double)r->stats.pixel_ops / (double)brute : 0.0);
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
    printf("status:  %u ok, %u excluded, %u masked, %u edge\n", r->stats.ok, r->stats.excluded,
           r->stats.masked, r->stats.edge);
    if (r->stats.ok > 0) {
        printf("motion:  median dx=%+d dy=%+d px (FIRST -> SECOND)\n",
               (int)median_component(r, 0), (int)median_component(r, 1));
        printf("work:    %llu pixel ops = %.2f %% of brute force (%llu); threshold %s, "
               "scan %s, %.2f ms\n",
               (unsigned long long)r->stats.pixel_ops,
               brute ? 100.0 * (double)r->stats.pixel_ops / (double)brute : 0.0,
               (unsigned long long)brute, tname, cli_scan_name(&r->cfg.match), 1e3 * r->secs);
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
    int rc = track_parse_args("track", argc, argv, help, &o, &first, &second);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc; /* -1: --help */
    }
    if ((rc = track_run("track", first, second, &o, &r)) != CLI_OK) {
        return rc;
    }
    rc = write_outputs(&o, first, second, &r);
    if (rc == CLI_OK && !cli_is_stdout(o.json_path) && !cli_is_stdout(o.overlay_path)) {
        print_summary(&o, &r);
    }
    track_result_free(&r);
    return rc;
}
