/* peers_search.c - single large searches against OpenCV (see header). */
#include "peers_search.h"

#include <stdlib.h>
#include <string.h>

#include "peers_util.h"
#include "ssda/match.h"
#include "synth_texture.h"

enum { M_BLOCKS, M_BOUNDS, M_AUTO, M_NONE, M_SQDIFF, M_CCOEFF, M_COUNT };
static const char *const k_short[M_COUNT] = {"ssda auto + blocks", "ssda auto + bounds",
                                             "ssda auto", "ssda none", "TM_SQDIFF",
                                             "TM_CCOEFF_NORMED"};
#define NPOS 4

typedef struct {
    ssda_view_t tmpl[NPOS];
    cv_peer_job_t jobs[NPOS];
    ssda_match_config_t cfg[4]; /* M_BLOCKS, M_BOUNDS, M_AUTO, M_NONE */
    uint16_t bx[M_COUNT][NPOS], by[M_COUNT][NPOS];
    uint64_t sad[4][NPOS];      /* ssda's SADs: each exact mode's equals none's */
    uint64_t ops[4];            /* pixel ops of the NPOS searches */
} search_run_t;

static double run_method(const peers_scene_t *s, search_run_t *r, int m, unsigned size)
{
    double t0 = peers_now(), t;
    if (m <= M_NONE) {
        uint64_t ops = 0;
        for (int k = 0; k < NPOS; k++) {
            ssda_match_result_t res;
            int e = ssda_match(&s->image, &r->tmpl[k], &r->cfg[m], &res);
            if (e != SSDA_OK) {
                fprintf(stderr, "ssda_match: %s\n", ssda_strerror(e));
                return -1.0;
            }
            r->bx[m][k] = res.x;
            r->by[m][k] = res.y;
            r->sad[m][k] = res.sad;
            ops += res.pixel_ops;
        }
        t = peers_now() - t0;
        r->ops[m] = ops;
        return t;
    }
    if (cv_peer_match(s->cv_image, s->cv_moved, r->jobs, NPOS, (uint16_t)size, (uint16_t)size,
                      s->image.width, s->image.height,
                      m == M_SQDIFF ? CV_PEER_SQDIFF : CV_PEER_CCOEFF_NORMED, r->bx[m],
                      r->by[m]) != 0) {
        return -1.0;
    }
    return peers_now() - t0;
}

/* run_method, with the thread's processor seconds in *cpu. */
static double run_timed(const peers_scene_t *s, search_run_t *r, int m, unsigned size,
                        double *cpu)
{
    double c0 = peers_cpu_now(), t = run_method(s, r, m, size);
    *cpu = peers_cpu_now() - c0;
    return t;
}

static int one_size(const peers_scene_t *s, unsigned size, int reps, FILE *ratios)
{
    search_run_t r;
    size_t work_size = SSDA_MATCH_WORK_SIZE_BLOCKS(s->image.width, s->image.height, size, size);
    void *work = malloc(work_size);
    double *times = calloc((size_t)reps * M_COUNT * 2u, sizeof *times), med[M_COUNT];
    double *cpus = times + (size_t)reps * M_COUNT, cmed[M_COUNT];
    int m, best = 0, same_sq = 0, same_cc = 0, truth_ok[M_COUNT] = {0}, exact = 1;
    char label[96];

    if (work == NULL || times == NULL) {
        free(work);
        free(times);
        return -1;
    }
    memset(&r, 0, sizeof r);
    for (int k = 0; k < NPOS; k++) {
        unsigned cx = s->moved.width * (k % 2 ? 3u : 1u) / 4u;
        unsigned cy = s->moved.height * (k / 2 ? 3u : 1u) / 4u;
        r.jobs[k].wx = (uint16_t)(cx - size / 2);
        r.jobs[k].wy = (uint16_t)(cy - size / 2);
        ssda_view_roi(&r.tmpl[k], &s->moved, r.jobs[k].wx, r.jobs[k].wy, (uint16_t)size,
                      (uint16_t)size);
    }
    r.cfg[M_BLOCKS].threshold = SSDA_THRESHOLD_AUTO;
    r.cfg[M_BLOCKS].flags = SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS;
    r.cfg[M_BLOCKS].work = work;
    r.cfg[M_BLOCKS].work_size = work_size;
    r.cfg[M_BOUNDS].threshold = SSDA_THRESHOLD_AUTO;
    r.cfg[M_BOUNDS].flags = SSDA_MATCH_BOUNDS;
    r.cfg[M_BOUNDS].work = work;
    r.cfg[M_BOUNDS].work_size = work_size;
    r.cfg[M_AUTO].threshold = SSDA_THRESHOLD_AUTO;
    r.cfg[M_NONE].threshold = SSDA_THRESHOLD_NONE;

    for (int k = 0; k < reps; k++) {
        for (m = 0; m < M_COUNT; m++) {
            double c, t = run_timed(s, &r, m, size, &c);
            if (t < 0) {
                free(work);
                free(times);
                return -1;
            }
            times[(size_t)m * reps + k] = t / NPOS;
            cpus[(size_t)m * reps + k] = c / NPOS;
        }
    }
    for (m = 0; m < M_COUNT; m++) {
        med[m] = peers_median(times + (size_t)m * reps, (size_t)reps);
        cmed[m] = peers_median(cpus + (size_t)m * reps, (size_t)reps);
        best = med[m] < med[best] ? m : best;
    }
    for (int k = 0; k < NPOS; k++) {
        exact &= r.bx[M_BLOCKS][k] == r.bx[M_NONE][k] && r.by[M_BLOCKS][k] == r.by[M_NONE][k] &&
                 r.bx[M_BOUNDS][k] == r.bx[M_NONE][k] && r.by[M_BOUNDS][k] == r.by[M_NONE][k] &&
                 r.bx[M_AUTO][k] == r.bx[M_NONE][k] && r.by[M_AUTO][k] == r.by[M_NONE][k] &&
                 r.sad[M_BLOCKS][k] == r.sad[M_NONE][k] && r.sad[M_BOUNDS][k] == r.sad[M_NONE][k] &&
                 r.sad[M_AUTO][k] == r.sad[M_NONE][k];
        same_sq += r.bx[M_SQDIFF][k] == r.bx[M_NONE][k] && r.by[M_SQDIFF][k] == r.by[M_NONE][k];
        same_cc += r.bx[M_CCOEFF][k] == r.bx[M_NONE][k] && r.by[M_CCOEFF][k] == r.by[M_NONE][k];
        if (s->synthetic_truth) {
            int u, v;
            synth_moved_field(r.jobs[k].wx + (int)size / 2, r.jobs[k].wy + (int)size / 2,
                              s->moved.width, s->moved.height, &u, &v);
            for (m = 0; m < M_COUNT; m++) {
                int ex = abs((int)r.jobs[k].wx - u - (int)r.bx[m][k]);
                int ey = abs((int)r.jobs[k].wy - v - (int)r.by[m][k]);
                truth_ok[m] += ex <= 1 && ey <= 1;
            }
        }
    }
    printf("| %ux%u | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %s | %.2fx | %.2fx | %.2fx | "
           "%.1fx | %.1fx | %d/%d, %d/%d | %.3f | %.3f | %.2fx |",
           size, size, 1e3 * med[M_BLOCKS], 1e3 * med[M_BOUNDS], 1e3 * med[M_AUTO],
           1e3 * med[M_NONE], 1e3 * med[M_SQDIFF], 1e3 * med[M_CCOEFF], k_short[best],
           med[M_SQDIFF] / med[M_BLOCKS], med[M_CCOEFF] / med[M_BLOCKS],
           med[M_SQDIFF] / med[M_BOUNDS], (double)r.ops[M_NONE] / (double)r.ops[M_BLOCKS],
           (double)r.ops[M_NONE] / (double)r.ops[M_BOUNDS], same_sq, NPOS, same_cc, NPOS,
           1e3 * cmed[M_BLOCKS], 1e3 * cmed[M_SQDIFF], cmed[M_SQDIFF] / cmed[M_BLOCKS]);
    if (s->synthetic_truth) {
        printf(" %d/%d, %d/%d, %d/%d |", truth_ok[M_BLOCKS], NPOS, truth_ok[M_SQDIFF], NPOS,
               truth_ok[M_CCOEFF], NPOS);
    }
    printf("%s\n", exact ? "" : " **ssda auto differs from brute force: bug** |");
    snprintf(label, sizeof label, "%s %ux%u: vs TM_SQDIFF", s->name, size, size);
    peers_ratio(ratios, "Single search over a whole image (ssda auto + blocks)", label,
                med[M_SQDIFF] / med[M_BLOCKS]);
    free(work);
    free(times);
    return exact ? 0 : -1;
}

int peers_search(const peers_scene_t *s, const unsigned *sizes, size_t n, int reps, FILE *ratios)
{
    int rc = 0;
    printf("\n### Single searches over %ux%u: %s\n\n", s->image.width, s->image.height, s->name);
    printf("%s. Four templates per size (centred on the quarter points), each searched over "
           "every placement of the whole image; milliseconds per search (wall, and the thread's "
           "processor time in the last three columns), median of %d interleaved runs. ssda `auto` is the raster scan with no prediction (a single "
           "search has none).\n\n",
           s->description, reps);
    printf("| template | ssda `auto` + blocks ms | `auto` + bounds ms | ssda `auto` ms | ssda "
           "`none` ms | `TM_SQDIFF` ms | `TM_CCOEFF_NORMED` ms | fastest | `auto` + blocks vs "
           "`TM_SQDIFF` | vs `TM_CCOEFF_NORMED` | `auto` + bounds vs `TM_SQDIFF` | fewer pixel "
           "ops than `none`: blocks | bounds | OpenCV at brute force's place "
           "(SQDIFF, CCOEFF) | processor ms: `auto` + blocks | `TM_SQDIFF` | `auto` + blocks vs "
           "`TM_SQDIFF`, processor time |%s\n",
           s->synthetic_truth ? " within 1 px of known motion (ssda, SQDIFF, CCOEFF) |" : "");
    printf("|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|%s\n",
           s->synthetic_truth ? "---:|" : "");
    for (size_t k = 0; k < n; k++) {
        if (sizes[k] * 2 > s->image.width || sizes[k] * 2 > s->image.height) {
            continue;
        }
        if (one_size(s, sizes[k], reps, ratios) != 0) {
            rc = -1;
        }
    }
    return rc;
}
