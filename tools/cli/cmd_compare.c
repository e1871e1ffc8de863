/* cmd_compare.c - `ssda compare FIRST.png SECOND.png`: the seed's Table 1 on the
   user's images: SSDA vectors against exhaustive normalised cross-correlation. */
#include "ncc_ref.h"
#include "parallel.h"
#include "progress.h"
#include "track_run.h"

#include <stdlib.h>
#include <string.h>

static void help(void)
{
    fputs("usage: ssda compare FIRST.png SECOND.png [track options]\n"
          "\n"
          "Track as `ssda track` does, then search every ok window (only those: flat,\n"
          "ambiguous and at_limit windows are left out of the counts) again by exhaustive\n"
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
    fputs("  --threads N       read the two images and run the NCC reference searches\n"
          "                    on N threads (default: every core, 0 too); the output\n"
          "                    is the same for any N\n"
          "  -h, --help        this text\n"
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

/* The NCC reference of every ok window and how the SSDA vectors compare. */
typedef struct {
    int32_t (*ref)[2];  /* grid.count entries: NCC vectors (ok windows) */
    double (*truth)[2]; /* the same, for the overlay */
    uint32_t within[3]; /* ok windows within 0, 1, 2 px of NCC */
    uint32_t ok;
    double secs;
} ncc_cmp_t;

/* One NCC search per ok window, on parallel_for's threads: each writes
   only its own slots of ref/truth (and a failure flag). */
typedef struct {
    const track_result_t *r;
    ncc_cmp_t *c;
    uint32_t hx, hy;
    int failed;        /* set (never cleared) by any job out of memory */
    progress_t prog;
} ncc_jobs_t;

static void ncc_job(void *ctx, uint32_t k, unsigned worker)
{
    ncc_jobs_t *j = ctx;
    const track_result_t *r = j->r;
    const ssda_track_vector_t *v = &r->vec[k];
    uint32_t bx, by;
    double score;
    (void)worker;
    if (v->status != SSDA_TRACK_OK) {
        return;
    }
    if (ncc_search(&r->first, v->x - j->hx, v->y - j->hy, r->grid.search_w, r->grid.search_h,
                   &r->second, v->x, v->y, r->grid.win_w, r->grid.win_h, &bx, &by,
                   &score) != 0) {
        __atomic_store_n(&j->failed, 1, __ATOMIC_RELAXED);
        return;
    }
    j->c->ref[k][0] = (int32_t)j->hx - (int32_t)bx;
    j->c->ref[k][1] = (int32_t)j->hy - (int32_t)by;
}

static void ncc_done(void *ctx, uint32_t done)
{
    ncc_jobs_t *j = ctx;
    progress_update(&j->prog, done);
}

/* Search every ok window again by exhaustive NCC over the same area, on
   `threads` threads; then count agreement in window order. */
static int ncc_reference(const track_result_t *r, int quiet, unsigned threads, ncc_cmp_t *c)
{
    ncc_jobs_t j;
    uint32_t k;
    double t0;
    memset(&j, 0, sizeof j);
    j.r = r;
    j.c = c;
    j.hx = (r->grid.search_w - r->grid.win_w) / 2u;
    j.hy = (r->grid.search_h - r->grid.win_h) / 2u;
    c->ref = calloc(r->grid.count + 1u, sizeof *c->ref);
    c->truth = calloc(r->grid.count + 1u, sizeof *c->truth);
    if (c->ref == NULL || c->truth == NULL) {
        return cli_input_error("compare", "out of memory");
    }
    progress_begin(&j.prog, "NCC reference", r->grid.count, quiet);
    t0 = progress_now();
    if (parallel_for(r->grid.count, threads, ncc_job, ncc_done, &j) != 0) {
        fprintf(stderr, "ssda compare: note: could not start every thread; ran on fewer\n");
    }
    c->secs = progress_now() - t0;
    progress_end(&j.prog);
    if (j.failed) {
        return cli_input_error("compare", "out of memory");
    }
    for (k = 0; k < r->grid.count; k++) {
        const ssda_track_vector_t *v = &r->vec[k];
        uint32_t d;
        if (v->status != SSDA_TRACK_OK) {
            continue;
        }
        c->truth[k][0] = c->ref[k][0];
        c->truth[k][1] = c->ref[k][1];
        d = (uint32_t)abs(v->dx - c->ref[k][0]);
        d = d > (uint32_t)abs(v->dy - c->ref[k][1]) ? d : (uint32_t)abs(v->dy - c->ref[k][1]);
        c->ok++;
        c->within[2] += d <= 2u;
        c->within[1] += d <= 1u;
        c->within[0] += d == 0u;
    }
    return CLI_OK;
}

/* --json and --overlay, all or nothing. */
static int write_outputs(const track_opts_t *o, const char *first, const char *second,
                         const track_result_t *r, const ncc_cmp_t *c)
{
    cli_outputs_t out;
    FILE *f;
    char title[256], sub[256];
    uint32_t ok = c->ok;
    int rc = CLI_OK;
    cli_outputs_begin(&out, "compare");
    if (o->json_path != NULL &&
        ((f = cli_outputs_open(&out, o->json_path)) == NULL ||
         track_write_json("compare", f, r, o, (const int32_t(*)[2])c->ref,
                          json_compare(ok, c->within, r->secs, c->secs)) != 0)) {
        rc = CLI_INPUT;
    }
    if (rc == CLI_OK && o->overlay_path != NULL) {
        snprintf(title, sizeof title, "ssda compare  %s -> %s", cli_basename(first),
                 cli_basename(second));
        snprintf(sub, sizeof sub,
                 "SSDA vs exhaustive NCC on %u ok windows: within 0 px %.0f %%, 1 px %.0f %%, "
                 "2 px %.0f %%",
                 ok, PCT(c->within[0]), PCT(c->within[1]), PCT(c->within[2]));
        if ((f = cli_outputs_open(&out, o->overlay_path)) == NULL ||
            track_write_overlay("compare", f, o->overlay_path, r, o,
                                (const double(*)[2])c->truth, "NCC reference", title, sub) != 0) {
            rc = CLI_INPUT;
        }
    }
    rc = rc == CLI_OK ? cli_outputs_commit(&out) : rc;
    cli_outputs_abort(&out);
    return rc;
}

static void print_summary(const track_opts_t *o, const track_result_t *r, const ncc_cmp_t *c,
                          unsigned threads)
{
    uint64_t brute = track_brute_ops(r);
    uint32_t ok = c->ok;
    printf("SSDA vs exhaustive normalised cross-correlation on %u ok windows "
           "(of %u: %u flat, %u ambiguous, %u at_limit, %u excluded, %u masked, %u edge left "
           "out; window %ux%u, search %ux%u):\n",
           ok, r->grid.count, r->stats.flat, r->stats.ambiguous, r->stats.at_limit,
           r->stats.excluded, r->stats.masked, r->stats.edge, r->grid.win_w, r->grid.win_h,
           r->grid.search_w, r->grid.search_h);
    printf("  within 0 px: %4u  %5.1f %%\n", c->within[0], PCT(c->within[0]));
    printf("  within 1 px: %4u  %5.1f %%\n", c->within[1], PCT(c->within[1]));
    printf("  within 2 px: %4u  %5.1f %%\n", c->within[2], PCT(c->within[2]));
    printf("time: SSDA %.2f ms (%.2f %% of brute-force pixel ops), NCC %.2f ms",
           1e3 * r->secs, brute ? 100.0 * (double)track_work_ops(r) / (double)brute : 0.0,
           1e3 * c->secs);
    if (threads > 1u) {
        printf(" on %u threads", threads);
    }
    if (r->secs > 0.0 && ok > 0) {
        printf(" (%.0fx the SSDA time)", c->secs / r->secs);
    }
    printf("\n");
    if (o->json_path != NULL) { /* as track reports its files */
        printf("wrote:   %s\n", o->json_path);
    }
    if (o->overlay_path != NULL) {
        printf("wrote:   %s\n", o->overlay_path);
    }
}

int cmd_compare(int argc, char **argv)
{
    track_opts_t o;
    track_result_t r;
    ncc_cmp_t c;
    const char *first, *second;
    unsigned threads;
    int rc = parallel_take_threads("compare", &argc, argv, &threads);
    if (rc != 0) {
        return CLI_USAGE;
    }
    cli_set_threads(threads);
    rc = track_parse_args("compare", argc, argv, help, &o, &first, &second);
    if (rc != CLI_OK) {
        return rc < 0 ? CLI_OK : rc; /* -1: --help */
    }
    if ((rc = track_run("compare", first, second, &o, &r)) != CLI_OK) {
        return rc;
    }
    memset(&c, 0, sizeof c);
    rc = ncc_reference(&r, o.quiet, threads, &c);
    if (rc == CLI_OK) {
        rc = write_outputs(&o, first, second, &r, &c);
    }
    if (rc == CLI_OK && !cli_is_stdout(o.json_path) && !cli_is_stdout(o.overlay_path)) {
        print_summary(&o, &r, &c, threads);
    }
    free(c.ref);
    free(c.truth);
    track_result_free(&r);
    return rc;
}
