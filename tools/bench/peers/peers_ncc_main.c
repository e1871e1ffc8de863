/*
 * peers_ncc_main.c - ssda-peers-ncc: the exact correlation search
 * (ssda/ncc.h) against OpenCV's TM_CCOEFF_NORMED, and the three criteria
 * (SAD, rho, OpenCV) on pairs with a known motion and a brightness change.
 * Not a test; prints Markdown tables (docs/correlation.md).
 *
 *   ssda-peers-ncc [--reps N] [--pair FIRST.png SECOND.png]... [--image IMG.png]...
 *
 * 1. Agreement and time, tracking geometry (windows of SECOND at step =
 *    window size, each searched in the area twice its size centred on it in
 *    FIRST), on each --pair and on the synthetic pair: the share of windows
 *    where ssda's best equals OpenCV's, over all windows and over those
 *    where OpenCV's best beats its second best (outside the best's 3 x 3)
 *    by at least MARGIN; time per window (single thread, interleaved
 *    repetitions, medians) of ssda with early exit (raster), ssda with
 *    early exit and the left neighbour's vector as prediction, ssda in full,
 *    and OpenCV (matchTemplate + minMaxLoc into a reused Mat; 16-bit images
 *    converted to float once, untimed). Flat windows (no variance) and, for
 *    16-bit pairs, windows or areas holding 4095 (GOES fill) are left out.
 * 2. Brightness: each --image (and the synthetic texture) moved by
 *    (2.6, -1.4) px (bilinear), times a gain g plus an offset o, plus noise
 *    in -2..2, clamped to 0..255; the share of 16 x 16 windows (in 32 x 32
 *    areas) whose vector is within 1 px of the motion in both components,
 *    for SAD (ssda_match), rho (ssda_ncc_match) and OpenCV.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cv_peer.h"
#include "peers_util.h"
#include "png_io.h"
#include "ssda/match.h"
#include "ssda/ncc.h"
#include "synth_texture.h"

#define MARGIN 0.01
#define MAX_INPUTS 8

typedef struct {
    ssda_view_t first, second;
    cv_peer_image_t *cv_first, *cv_second;
    const char *name;
} pair_t;

typedef struct {
    cv_peer_job_t *jobs;
    size_t n;
} jobs_t;

/* timed methods: ssda early exit, + prediction, ssda full, OpenCV */
enum { T_EARLY, T_PREDICT, T_FULL, T_CV, T_COUNT };

static uint32_t px_at(const ssda_view_t *v, uint32_t x, uint32_t y)
{
    const uint8_t *r = ssda_view_row(v, y);
    return v->format == SSDA_PIX_U8 ? r[x] : ((const uint16_t *)(const void *)r)[x];
}

/* Window (w x w at wx, wy of second) usable: not flat, and for 16-bit no
   4095 in it or in its area. */
static int usable(const pair_t *p, const cv_peer_job_t *j, unsigned w)
{
    uint32_t x, y, first = px_at(&p->second, j->wx, j->wy);
    int flat = 1;
    for (y = 0; y < w; y++) {
        for (x = 0; x < w; x++) {
            uint32_t v = px_at(&p->second, j->wx + x, j->wy + y);
            flat &= v == first;
            if (p->second.format == SSDA_PIX_U16 && v == 4095u) {
                return 0;
            }
        }
    }
    if (p->first.format == SSDA_PIX_U16) {
        for (y = 0; y < 2u * w; y++) {
            for (x = 0; x < 2u * w; x++) {
                if (px_at(&p->first, j->ax + x, j->ay + y) == 4095u) {
                    return 0;
                }
            }
        }
    }
    return !flat;
}

static jobs_t make_jobs(const pair_t *p, unsigned w)
{
    jobs_t j = {NULL, 0};
    unsigned h = w / 2u, wx, wy;
    size_t cap = (size_t)(p->second.width / w + 1u) * (p->second.height / w + 1u);
    j.jobs = calloc(cap, sizeof *j.jobs);
    for (wy = h; j.jobs != NULL && wy + w + h <= p->second.height && wy + w + h <= p->first.height;
         wy += w) {
        for (wx = h; wx + w + h <= p->second.width && wx + w + h <= p->first.width; wx += w) {
            cv_peer_job_t jb = {(uint16_t)wx, (uint16_t)wy, (uint16_t)(wx - h), (uint16_t)(wy - h)};
            if (usable(p, &jb, w)) {
                j.jobs[j.n++] = jb;
            }
        }
    }
    return j;
}

/* rho of the window of job j placed at (px, py) of its area, in double
   precision by the two-pass formula (the referee when ssda and OpenCV differ). */
static double rho_double(const pair_t *p, const cv_peer_job_t *j, unsigned w, unsigned px,
                         unsigned py)
{
    double ma = 0, mw = 0, sab = 0, saa = 0, sww = 0;
    unsigned x, y;
    for (y = 0; y < w; y++) {
        for (x = 0; x < w; x++) {
            ma += px_at(&p->first, j->ax + px + x, j->ay + py + y);
            mw += px_at(&p->second, j->wx + x, j->wy + y);
        }
    }
    ma /= (double)(w * w);
    mw /= (double)(w * w);
    for (y = 0; y < w; y++) {
        for (x = 0; x < w; x++) {
            double a = px_at(&p->first, j->ax + px + x, j->ay + py + y) - ma;
            double b = px_at(&p->second, j->wx + x, j->wy + y) - mw;
            sab += a * b;
            saa += a * a;
            sww += b * b;
        }
    }
    return saa > 0 && sww > 0 ? sab / sqrt(saa * sww) : 0.0;
}

/* One timed pass of method m over all jobs; best places into bx, by. */
static double timed_pass(const pair_t *p, const jobs_t *j, unsigned w, int m, void *work,
                         size_t work_size, uint16_t *bx, uint16_t *by, uint64_t *ops)
{
    double t0 = peers_now();
    size_t k;
    if (m == T_CV) {
        if (cv_peer_match(p->cv_first, p->cv_second, j->jobs, j->n, (uint16_t)w, (uint16_t)w,
                          (uint16_t)(2u * w), (uint16_t)(2u * w), CV_PEER_CCOEFF_NORMED, bx,
                          by) != 0) {
            return -1.0;
        }
        return peers_now() - t0;
    }
    *ops = 0;
    for (k = 0; k < j->n; k++) {
        ssda_view_t area, win;
        ssda_ncc_config_t cfg;
        ssda_ncc_result_t r;
        memset(&cfg, 0, sizeof cfg);
        cfg.work = work;
        cfg.work_size = work_size;
        cfg.flags = m == T_FULL ? SSDA_NCC_FULL : 0u;
        if (m == T_PREDICT) {
            /* the previous window's vector, as a solved neighbour gives it */
            cfg.flags = SSDA_NCC_PREDICT;
            cfg.predict_x = k > 0 ? bx[k - 1] : (int32_t)(w / 2u);
            cfg.predict_y = k > 0 ? by[k - 1] : (int32_t)(w / 2u);
        }
        (void)ssda_view_roi(&area, &p->first, j->jobs[k].ax, j->jobs[k].ay, (uint16_t)(2u * w),
                            (uint16_t)(2u * w));
        (void)ssda_view_roi(&win, &p->second, j->jobs[k].wx, j->jobs[k].wy, (uint16_t)w,
                            (uint16_t)w);
        if (ssda_ncc_match(&area, &win, &cfg, &r) != SSDA_OK) {
            return -1.0;
        }
        bx[k] = r.x;
        by[k] = r.y;
        *ops += r.pixel_ops;
    }
    return peers_now() - t0;
}

static int agreement_and_time(const pair_t *p, unsigned w, int reps)
{
    jobs_t j = make_jobs(p, w);
    size_t work_size = SSDA_NCC_WORK_SIZE(2u * w, w, w), k;
    void *work = malloc(work_size);
    uint16_t *bx = calloc(j.n * T_COUNT * 2u + 1u, sizeof *bx), *by = bx + j.n * T_COUNT;
    double *times = calloc((size_t)reps * T_COUNT + 1u, sizeof *times), med[T_COUNT];
    uint64_t ops[T_COUNT] = {0};
    size_t margin_n = 0, margin_same = 0, all_same = 0, m, differ = 0, ssda_right = 0;
    int rep;
    if (j.jobs == NULL || work == NULL || bx == NULL || times == NULL || j.n == 0) {
        fprintf(stderr, "peers-ncc: no windows or out of memory\n");
        return -1;
    }
    for (rep = 0; rep < reps; rep++) {
        for (m = 0; m < T_COUNT; m++) {
            double t = timed_pass(p, &j, w, (int)m, work, work_size, bx + m * j.n, by + m * j.n,
                                  &ops[m]);
            if (t < 0) {
                return -1;
            }
            times[m * (size_t)reps + (size_t)rep] = t / (double)j.n;
        }
    }
    for (m = 0; m < T_COUNT; m++) {
        med[m] = peers_median(times + m * (size_t)reps, (size_t)reps);
    }
    for (k = 0; k < j.n; k++) {
        uint16_t cx, cy;
        double best, second;
        int same;
        for (m = 1; m < T_CV; m++) { /* every ssda setting must agree with the full search */
            if (bx[m * j.n + k] != bx[k] || by[m * j.n + k] != by[k]) {
                fprintf(stderr, "peers-ncc: ssda settings disagree at window %zu\n", k);
                return -1;
            }
        }
        if (cv_peer_ccoeff_scores(p->cv_first, p->cv_second, &j.jobs[k], (uint16_t)w,
                                  (uint16_t)w, (uint16_t)(2u * w), (uint16_t)(2u * w), &cx, &cy,
                                  &best, &second) != 0) {
            return -1;
        }
        same = cx == bx[k] && cy == by[k];
        all_same += (size_t)same;
        if (!same) {
            differ++;
            ssda_right += rho_double(p, &j.jobs[k], w, bx[k], by[k]) >=
                          rho_double(p, &j.jobs[k], w, cx, cy);
        }
        if (best - second >= MARGIN) {
            margin_n++;
            margin_same += (size_t)same;
        }
    }
    printf("| %s | %ux%u in %ux%u | %zu | %.1f %% | %zu (%.0f %%): **%.1f %%** |", p->name, w, w,
           2u * w, 2u * w, j.n, 100.0 * (double)all_same / (double)j.n, margin_n,
           100.0 * (double)margin_n / (double)j.n,
           margin_n ? 100.0 * (double)margin_same / (double)margin_n : 0.0);
    for (m = 0; m < T_COUNT; m++) {
        printf(" %.2f |", med[m] * 1e6);
    }
    printf(" **%.2fx** / %.2fx | %.0f / %.0f | %zu of %zu |\n", med[T_CV] / med[T_EARLY],
           med[T_CV] / med[T_PREDICT], (double)ops[T_EARLY] / (double)j.n,
           (double)ops[T_FULL] / (double)j.n, ssda_right, differ);
    fflush(stdout);
    free(j.jobs);
    free(work);
    free(bx);
    free(times);
    return 0;
}

/* ---- brightness robustness ---- */

/* out = clamp(g * in(x - 2.6, y + 1.4) + o + noise), bilinear. */
static void moved_bright(const uint8_t *in, uint8_t *out, int w, int h, double g, double o,
                         unsigned seed)
{
    int x, y;
    srand(seed);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            double u = x - 2.6, v = y + 1.4, a, b, s;
            int i = (int)u, k = (int)v;
            if (u < 0) {
                i--;
            }
            a = u - i;
            b = v - k;
            if (i < 0 || k < 0 || i + 1 >= w || k + 1 >= h) {
                s = 128.0;
            } else {
                s = (1 - a) * (1 - b) * in[k * w + i] + a * (1 - b) * in[k * w + i + 1] +
                    (1 - a) * b * in[(k + 1) * w + i] + a * b * in[(k + 1) * w + i + 1];
            }
            s = g * s + o + (double)(rand() % 5 - 2);
            out[y * w + x] = (uint8_t)(s < 0 ? 0 : s > 255 ? 255 : s + 0.5);
        }
    }
}

static void brightness(const char *name, const uint8_t *img, int w, int h)
{
    static const double gains[] = {0.7, 0.85, 1.0, 1.2, 1.4};
    static const double offsets[] = {-30.0, 0.0, 30.0};
    uint8_t *next = malloc((size_t)w * (size_t)h);
    cv_peer_image_t *cf, *cs;
    ssda_view_t fv, sv;
    uint64_t work[SSDA_NCC_WORK_SIZE(32, 16, 16) / 8 + 1];
    uint32_t mwork[SSDA_MATCH_WORK_SIZE(32, 32, 16, 16) / 4];
    size_t gi, oi;
    if (next == NULL) {
        return;
    }
    (void)ssda_view_init(&fv, img, (uint16_t)w, (uint16_t)h, (uint32_t)w, SSDA_PIX_U8);
    (void)ssda_view_init(&sv, next, (uint16_t)w, (uint16_t)h, (uint32_t)w, SSDA_PIX_U8);
    cf = cv_peer_image_new(&fv);
    for (gi = 0; gi < sizeof gains / sizeof gains[0]; gi++) {
        for (oi = 0; oi < sizeof offsets / sizeof offsets[0]; oi++) {
            unsigned hits[3] = {0, 0, 0}, n = 0, wx, wy;
            moved_bright(img, next, w, h, gains[gi], offsets[oi], 7u);
            cs = cv_peer_image_new(&sv);
            for (wy = 16; wy + 32 <= (unsigned)h; wy += 16) {
                for (wx = 16; wx + 32 <= (unsigned)w; wx += 16) {
                    cv_peer_job_t jb = {(uint16_t)wx, (uint16_t)wy, (uint16_t)(wx - 8),
                                        (uint16_t)(wy - 8)};
                    ssda_view_t area, win;
                    ssda_match_config_t mc;
                    ssda_match_result_t mr;
                    ssda_ncc_config_t nc;
                    ssda_ncc_result_t nr;
                    uint16_t cx, cy;
                    int dx[3], dy[3], m;
                    pair_t tmp;
                    tmp.first = fv;
                    tmp.second = sv;
                    if (!usable(&tmp, &jb, 16)) {
                        continue;
                    }
                    (void)ssda_view_roi(&area, &fv, jb.ax, jb.ay, 32, 32);
                    (void)ssda_view_roi(&win, &sv, jb.wx, jb.wy, 16, 16);
                    memset(&mc, 0, sizeof mc);
                    mc.flags = SSDA_MATCH_BOUNDS;
                    mc.work = mwork;
                    mc.work_size = sizeof mwork;
                    memset(&nc, 0, sizeof nc);
                    nc.work = work;
                    nc.work_size = sizeof work;
                    if (ssda_match(&area, &win, &mc, &mr) != SSDA_OK ||
                        ssda_ncc_match(&area, &win, &nc, &nr) != SSDA_OK ||
                        cv_peer_match(cf, cs, &jb, 1, 16, 16, 32, 32, CV_PEER_CCOEFF_NORMED, &cx,
                                      &cy) != 0) {
                        continue;
                    }
                    dx[0] = 8 - mr.x;
                    dy[0] = 8 - mr.y;
                    dx[1] = 8 - nr.x;
                    dy[1] = 8 - nr.y;
                    dx[2] = 8 - cx;
                    dy[2] = 8 - cy;
                    for (m = 0; m < 3; m++) {
                        /* within 1 px of (2.6, -1.4): dx in {2, 3}, dy in {-2, -1} */
                        hits[m] += (dx[m] == 2 || dx[m] == 3) && (dy[m] == -2 || dy[m] == -1);
                    }
                    n++;
                }
            }
            cv_peer_image_free(cs);
            printf("| %s | %.2f | %+.0f | %u | %.1f %% | **%.1f %%** | %.1f %% |\n", name,
                   gains[gi], offsets[oi], n, 100.0 * hits[0] / (n ? n : 1),
                   100.0 * hits[1] / (n ? n : 1), 100.0 * hits[2] / (n ? n : 1));
            fflush(stdout);
        }
    }
    cv_peer_image_free(cf);
    free(next);
}

static int load(const char *path, gray_image_t *img, int depth)
{
    char err[256];
    if (png_read_gray(path, (png_gray_depth_t)depth, img, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "peers-ncc: %s\n", err);
        return -1;
    }
    return 0;
}

/* The load average (1 minute), from /proc/loadavg; -1 when unknown. */
static double load_average(void)
{
    FILE *f = fopen("/proc/loadavg", "r");
    double v = -1.0;
    if (f != NULL) {
        if (fscanf(f, "%lf", &v) != 1) {
            v = -1.0;
        }
        fclose(f);
    }
    return v;
}

static const char *base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

int main(int argc, char **argv)
{
    const char *pairs[MAX_INPUTS][2], *images[MAX_INPUTS];
    int npairs = 0, nimages = 0, reps = 7, i;
    unsigned wins[] = {16, 20, 32};
    char info[256];
    uint8_t *syn1, *syn2;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
            reps = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--pair") && i + 2 < argc && npairs < MAX_INPUTS) {
            pairs[npairs][0] = argv[i + 1];
            pairs[npairs][1] = argv[i + 2];
            npairs++;
            i += 2;
        } else if (!strcmp(argv[i], "--image") && i + 1 < argc && nimages < MAX_INPUTS) {
            images[nimages++] = argv[++i];
        } else {
            fprintf(stderr, "usage: ssda-peers-ncc [--reps N] [--pair FIRST.png SECOND.png]... "
                            "[--image IMG.png]...\n");
            return 2;
        }
    }
    if (reps < 1) {
        reps = 1;
    }
    cv_peer_init(info, sizeof info);
    printf("%s; %d repetitions, interleaved, medians; load average %.2f at the start\n\n", info,
           reps, load_average());
    printf("| pair | geometry | windows | same best as OpenCV | OpenCV's best beats its second by "
           ">= %.2f: same best | ssda early exit, us/window | + prediction | ssda full | OpenCV "
           "| OpenCV / ssda (early, + prediction) | pixel ops / window (early, full) | where they "
           "differ, double-precision rho favours ssda |\n",
           MARGIN);
    printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    syn1 = malloc(1024 * 1024);
    syn2 = malloc(1024 * 1024);
    if (syn1 == NULL || syn2 == NULL || synth_texture(syn1, 1024, 1024, 1) != 0) {
        return 1;
    }
    synth_moved(syn1, syn2, 1024, 1024, 2);
    for (i = -1; i < npairs; i++) {
        gray_image_t a = {0}, b = {0};
        pair_t p;
        size_t wi;
        memset(&p, 0, sizeof p);
        if (i < 0) {
            (void)ssda_view_init(&p.first, syn1, 1024, 1024, 1024, SSDA_PIX_U8);
            (void)ssda_view_init(&p.second, syn2, 1024, 1024, 1024, SSDA_PIX_U8);
            p.name = "synthetic 1024x1024";
        } else {
            if (load(pairs[i][0], &a, PNG_GRAY_NATIVE) != 0 ||
                load(pairs[i][1], &b, a.bits == 16 ? PNG_GRAY_16 : PNG_GRAY_8) != 0) {
                return 1;
            }
            (void)gray_image_view(&a, &p.first);
            (void)gray_image_view(&b, &p.second);
            p.name = base_name(pairs[i][0]);
        }
        p.cv_first = cv_peer_image_new(&p.first);
        p.cv_second = cv_peer_image_new(&p.second);
        for (wi = 0; wi < sizeof wins / sizeof wins[0]; wi++) {
            if (agreement_and_time(&p, wins[wi], reps) != 0) {
                return 1;
            }
        }
        cv_peer_image_free(p.cv_first);
        cv_peer_image_free(p.cv_second);
        gray_image_free(&a);
        gray_image_free(&b);
    }
    printf("\n| image | gain | offset | windows | SAD within 1 px | rho within 1 px | OpenCV "
           "within 1 px |\n|---|---:|---:|---:|---:|---:|---:|\n");
    if (synth_texture(syn2, 512, 512, 3) == 0) {
        brightness("synthetic 512x512", syn2, 512, 512);
    }
    for (i = 0; i < nimages; i++) {
        gray_image_t a = {0};
        if (load(images[i], &a, PNG_GRAY_8) != 0) {
            return 1;
        }
        brightness(base_name(images[i]), a.pixels, (int)a.width, (int)a.height);
        gray_image_free(&a);
    }
    printf("\nload average %.2f at the end\n", load_average());
    free(syn1);
    free(syn2);
    return 0;
}
