/* peers_track.c - grid tracking against OpenCV (see header). */
#include "peers_track.h"

#include <stdlib.h>
#include <string.h>

#include "kernel/kernels.h" /* the SIMD row kernel, for the diagnostic row */
#include "peers_util.h"
#include "ssda/track.h"
#include "synth_texture.h"

enum { M_AUTO, M_NONE, M_SQDIFF, M_CCOEFF, M_BARE, M_COUNT };
static const char *const k_names[M_COUNT] = {
    "**ssda `auto` + prediction + bounds**", "ssda `none` (brute-force SAD, same SIMD kernel)",
    "OpenCV `TM_SQDIFF`", "OpenCV `TM_CCOEFF_NORMED`",
    "(diagnostic) brute-force SAD: the row kernel in a bare loop, no engine"};
static const char *const k_short[M_COUNT] = {"ssda auto", "ssda none", "TM_SQDIFF",
                                             "TM_CCOEFF_NORMED", "bare kernel"};

typedef struct {
    ssda_track_config_t cfg_auto, cfg_none;
    ssda_track_vector_t *out;   /* per method: grid.count vectors */
    cv_peer_job_t *jobs;        /* OK windows of the brute-force run */
    uint32_t *job_window;       /* grid index of each job */
    uint16_t *bx, *by;          /* OpenCV results per job */
    size_t count, njobs;
} track_run_t;

/* Brute force over one window with the library's row kernel called
   directly: what the engine's `none` mode costs without its per-row
   bookkeeping (row sources, cut tests, counters). Tie rule as ssda's:
   smallest SAD, then smallest y, then x. */
static void bare_search(const ssda_view_t *first, const ssda_view_t *second,
                        const cv_peer_job_t *j, unsigned win, uint16_t *bx, uint16_t *by)
{
    const uint32_t bpp = ssda_view_bpp(first);
    uint64_t best = UINT64_MAX;
    for (unsigned py = 0; py <= win; py++) {
        for (unsigned px = 0; px <= win; px++) {
            uint64_t sad = 0;
            for (unsigned r = 0; r < win; r++) {
                const uint8_t *a = ssda_view_row(first, j->ay + py + r) + (size_t)(j->ax + px) * bpp;
                const uint8_t *w = ssda_view_row(second, j->wy + r) + (size_t)j->wx * bpp;
                sad += bpp == 1 ? ssda__sad_row_u8(a, w, win)
                                : ssda__sad_row_u16((const uint16_t *)(const void *)a,
                                                   (const uint16_t *)(const void *)w, win);
            }
            if (sad < best) {
                best = sad;
                *bx = (uint16_t)px;
                *by = (uint16_t)py;
            }
        }
    }
}

static double run_timed(const peers_pair_t *p, track_run_t *r, int m, unsigned win,
                        ssda_track_stats_t *st)
{
    ssda_track_vector_t *out = r->out + (size_t)m * r->count;
    double t0, t;
    if (m == M_AUTO || m == M_NONE) {
        int e;
        t0 = peers_now();
        e = ssda_track(&p->first, &p->second, m == M_AUTO ? &r->cfg_auto : &r->cfg_none, out,
                       r->count, st);
        t = peers_now() - t0;
        if (e != SSDA_OK) {
            fprintf(stderr, "ssda_track: %s\n", ssda_strerror(e));
            return -1.0;
        }
        return t;
    }
    t0 = peers_now();
    if (m == M_BARE) {
        for (size_t j = 0; j < r->njobs; j++) {
            bare_search(&p->first, &p->second, &r->jobs[j], win, &r->bx[j], &r->by[j]);
        }
    } else if (cv_peer_match(p->cv_first, p->cv_second, r->jobs, r->njobs, (uint16_t)win,
                             (uint16_t)win, (uint16_t)(2 * win), (uint16_t)(2 * win),
                             m == M_SQDIFF ? CV_PEER_SQDIFF : CV_PEER_CCOEFF_NORMED, r->bx,
                             r->by) != 0) {
        return -1.0;
    }
    t = peers_now() - t0;
    for (size_t j = 0; j < r->njobs; j++) {
        ssda_track_vector_t *v = &out[r->job_window[j]];
        int h = (int)(win / 2); /* (search - win) / 2 */
        v->status = SSDA_TRACK_OK;
        v->dx = h - (int)r->bx[j];
        v->dy = h - (int)r->by[j];
    }
    return t;
}

/* One timed run of method m; vectors land in run->out + m * count (OpenCV:
   converted from the best placement). Returns the wall seconds taken, < 0
   on error; *cpu receives the thread's processor seconds. */
static double run_method(const peers_pair_t *p, track_run_t *r, int m, unsigned win,
                         ssda_track_stats_t *st, double *cpu)
{
    double c0 = peers_cpu_now(), t = run_timed(p, r, m, win, st);
    *cpu = peers_cpu_now() - c0;
    return t;
}

/* The configs (brute force, and auto + prediction + bounds with work) and
   the buffers for a win x win grid in 2win x 2win areas. Returns 0 or -1. */
static int setup_run(const peers_pair_t *p, unsigned win, void *work, size_t work_size,
                     ssda_track_grid_t *grid, track_run_t *r)
{
    ssda_track_config_t base;
    int e;
    memset(&base, 0, sizeof base);
    /* the search alone: every window neither edge nor masked is searched
       (ok or at_limit), no sub-pixel sums */
    base.flags = SSDA_TRACK_NO_FLAT | SSDA_TRACK_NO_SUBPIXEL;
    base.win_w = base.win_h = (uint16_t)win;
    base.search_w = base.search_h = (uint16_t)(2 * win);
    base.step_x = base.step_y = (uint16_t)win;
    if (p->use_mask) {
        base.flags |= SSDA_TRACK_MASK;
        base.mask_value = p->mask_value;
    }
    e = ssda_track_grid(&base, p->second.width, p->second.height, grid);
    if (e != SSDA_OK || work == NULL) {
        fprintf(stderr, "peers: grid %ux%u: %s\n", win, 2 * win,
                e != SSDA_OK ? ssda_strerror(e) : "out of memory");
        return -1;
    }
    r->count = grid->count;
    r->cfg_none = base;
    r->cfg_none.match.threshold = SSDA_THRESHOLD_NONE;
    /* the same prediction as auto, so that equal SADs go to the same
       placement (the tie rule is nearest to the prediction): brute force
       then gives auto's vectors exactly */
    r->cfg_none.match.scan = SSDA_SCAN_PREDICT;
    r->cfg_none.predict = SSDA_TRACK_PREDICT_MEDIAN;
    r->cfg_auto = base;
    r->cfg_auto.match.threshold = SSDA_THRESHOLD_AUTO;
    r->cfg_auto.match.scan = SSDA_SCAN_PREDICT;
    r->cfg_auto.predict = SSDA_TRACK_PREDICT_MEDIAN;
    r->cfg_auto.match.flags = SSDA_MATCH_BOUNDS;
    r->cfg_auto.match.work = work;
    r->cfg_auto.match.work_size = work_size;
    r->out = calloc(r->count * M_COUNT, sizeof *r->out);
    r->jobs = calloc(r->count, sizeof *r->jobs);
    r->job_window = calloc(r->count, sizeof *r->job_window);
    r->bx = calloc(r->count, sizeof *r->bx);
    r->by = calloc(r->count, sizeof *r->by);
    if (r->out == NULL || r->jobs == NULL || r->job_window == NULL || r->bx == NULL ||
        r->by == NULL) {
        fprintf(stderr, "peers: out of memory\n");
        return -1;
    }
    return 0;
}

/* The windows every method searches: those brute force finds OK (not at
   the edge, not touching the fill value). Untimed. Returns 0 or -1. */
static int make_jobs(const peers_pair_t *p, track_run_t *r, unsigned win,
                     ssda_track_stats_t *st_ref)
{
    double cpu;
    if (run_method(p, r, M_NONE, win, st_ref, &cpu) < 0) {
        return -1;
    }
    for (size_t k = 0; k < r->count; k++) {
        const ssda_track_vector_t *v = &r->out[(size_t)M_NONE * r->count + k];
        if (v->status == SSDA_TRACK_OK || v->status == SSDA_TRACK_AT_LIMIT) {
            cv_peer_job_t *j = &r->jobs[r->njobs];
            j->wx = v->x;
            j->wy = v->y;
            j->ax = (uint16_t)(v->x - win / 2);
            j->ay = (uint16_t)(v->y - win / 2);
            r->job_window[r->njobs++] = (uint32_t)k;
        }
    }
    if (r->njobs == 0) {
        fprintf(stderr, "peers: no window to search in %s\n", p->name);
        return -1;
    }
    return 0;
}

/* Interleaved repetitions: a burst of load from elsewhere hits every
   method alike; the median wall and processor time of each method is kept.
   Returns 0 or -1. */
static int time_methods(const peers_pair_t *p, track_run_t *r, unsigned win, int reps,
                        ssda_track_stats_t st[M_COUNT], double med[M_COUNT],
                        double med_cpu[M_COUNT])
{
    double *times = calloc((size_t)reps * M_COUNT * 2u, sizeof *times);
    double *cpu_times = times + (size_t)reps * M_COUNT, cpu;
    int m;
    if (times == NULL) {
        fprintf(stderr, "peers: out of memory\n");
        return -1;
    }
    for (int k = 0; k < reps; k++) {
        for (m = 0; m < M_COUNT; m++) {
            double t = run_method(p, r, m, win, &st[m], &cpu);
            if (t < 0) {
                free(times);
                return -1;
            }
            times[(size_t)m * reps + k] = t;
            cpu_times[(size_t)m * reps + k] = cpu;
        }
    }
    for (m = 0; m < M_COUNT; m++) {
        med[m] = peers_median(times + (size_t)m * reps, (size_t)reps);
        med_cpu[m] = peers_median(cpu_times + (size_t)m * reps, (size_t)reps);
    }
    free(times);
    return 0;
}

/* Every method's vectors against brute force's and, for a synthetic pair,
   the known motion. Returns how many of auto's equal brute force's. */
static uint32_t compare_vectors(const peers_pair_t *p, const track_run_t *r, unsigned win,
                                peers_agree_t vs_ref[M_COUNT], peers_agree_t vs_truth[M_COUNT])
{
    uint32_t identical = 0;
    memset(vs_ref, 0, M_COUNT * sizeof *vs_ref);
    memset(vs_truth, 0, M_COUNT * sizeof *vs_truth);
    for (size_t j = 0; j < r->njobs; j++) {
        size_t k = r->job_window[j];
        const ssda_track_vector_t *ref = &r->out[(size_t)M_NONE * r->count + k];
        const ssda_track_vector_t *au = &r->out[(size_t)M_AUTO * r->count + k];
        int tu = 0, tv = 0;
        identical += au->status == ref->status && au->dx == ref->dx && au->dy == ref->dy &&
                     au->sad == ref->sad;
        if (p->synthetic_truth) {
            synth_moved_field(ref->x + (int)win / 2, ref->y + (int)win / 2, p->second.width,
                              p->second.height, &tu, &tv);
        }
        for (int m = 0; m < M_COUNT; m++) {
            const ssda_track_vector_t *v = &r->out[(size_t)m * r->count + k];
            peers_agree_add(&vs_ref[m], ref->dx, ref->dy, v->dx, v->dy);
            if (p->synthetic_truth) {
                peers_agree_add(&vs_truth[m], tu, tv, v->dx, v->dy);
            }
        }
    }
    return identical;
}

/* The table's rows, one per method. */
static void print_rows(const peers_pair_t *p, const track_run_t *r, unsigned win,
                       const ssda_track_stats_t st[M_COUNT], const double med[M_COUNT],
                       const double med_cpu[M_COUNT], const peers_agree_t vs_ref[M_COUNT],
                       const peers_agree_t vs_truth[M_COUNT])
{
    char buf[96];
    for (int m = 0; m < M_COUNT; m++) {
        printf("| %s | %.2f | %.1fx | %.2f | %.1fx | ", k_names[m], 1e6 * med[m] / (double)r->njobs,
               med[m] / med[M_AUTO], 1e6 * med_cpu[m] / (double)r->njobs, med_cpu[m] / med_cpu[M_AUTO]);
        if (m == M_AUTO || m == M_NONE) {
            printf("%.0f | ", (double)st[m].pixel_ops / (double)(st[m].ok + st[m].at_limit));
        } else if (m == M_BARE) {
            printf("%u | ", (win + 1) * (win + 1) * win * win);
        } else {
            printf("- | ");
        }
        printf("%s |", peers_agree_str(&vs_ref[m], buf, sizeof buf));
        if (p->synthetic_truth) {
            printf(" %s |", peers_agree_str(&vs_truth[m], buf, sizeof buf));
        }
        printf("\n");
    }
}

int peers_track(const peers_pair_t *p, unsigned win, int reps, FILE *ratios)
{
    ssda_track_grid_t grid;
    ssda_track_stats_t st[M_COUNT], st_ref;
    track_run_t r;
    /* the bounds' tables shared by the windows (track.h) */
    size_t work_size = SSDA_TRACK_WORK_SIZE_SHARED(p->first.width, 2 * win, 2 * win, win, win);
    void *work = malloc(work_size);
    double med[M_COUNT], med_cpu[M_COUNT];
    peers_agree_t vs_ref[M_COUNT], vs_truth[M_COUNT];
    uint32_t identical;
    int m, rc = -1;
    char buf[96], group[96];

    memset(&r, 0, sizeof r);
    if (setup_run(p, win, work, work_size, &grid, &r) != 0 || make_jobs(p, &r, win, &st_ref) != 0 ||
        time_methods(p, &r, win, reps, st, med, med_cpu) != 0) {
        goto done;
    }
    identical = compare_vectors(p, &r, win, vs_ref, vs_truth);
    printf("\n### Grid tracking, %ux%u windows in %ux%u areas (step %u): %s\n\n", win, win, 2 * win,
           2 * win, win, p->name);
    printf("%s. %zu windows searched by every method (of %u: %u at the edge, %u touching the "
           "fill value). Time per searched window, median of %d interleaved runs of the whole "
           "grid: wall time, and the thread's processor time (which leaves out waits for a "
           "core on a loaded machine).\n\n",
           p->description, r.njobs, grid.count, st_ref.edge, st_ref.masked, reps);
    printf("| method | us / window | ssda `auto` faster by | CPU us / window | faster by (CPU) "
           "| pixel ops / window | vectors vs brute force (equal / within 1 / within 2 px) |%s\n",
           p->synthetic_truth ? " vs known motion (equal / within 1 / within 2 px) |" : "");
    printf("|---|---:|---:|---:|---:|---:|---:|%s\n", p->synthetic_truth ? "---:|" : "");
    print_rows(p, &r, win, st, med, med_cpu, vs_ref, vs_truth);
    printf("\nssda `auto` vectors identical to brute force in (dx, dy, SAD): %u of %zu%s. "
           "Pixel ops: absolute differences plus bound work (`none`: %u per window). "
           "OpenCV correlates by DFT, so it has no comparable count.\n",
           identical, r.njobs, identical == r.njobs ? "" : " (**NOT EXACT: bug**)",
           (win + 1) * (win + 1) * win * win);
    snprintf(group, sizeof group, "Grid tracking, %ux%u in %ux%u (ssda auto + prediction + bounds)", win,
             win, 2 * win, 2 * win);
    for (m = M_NONE; m < M_BARE; m++) {
        snprintf(buf, sizeof buf, "%s: vs %s", p->name, k_short[m]);
        peers_ratio(ratios, group, buf, med[m] / med[M_AUTO]);
    }
    rc = identical == r.njobs ? 0 : -1;
done:
    free(r.out);
    free(r.jobs);
    free(r.job_window);
    free(r.bx);
    free(r.by);
    free(work);
    return rc;
}
