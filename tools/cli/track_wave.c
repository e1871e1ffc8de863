/* track_wave.c - grid tracking on several threads as a wavefront of rows
   (track_wave.h). */
#include "track_wave.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "parallel.h"

/* Grid columns per ssda_track_row call. Every grid row is cut into bands
   of band_cols(cols) columns from column 0 (the last band may be
   narrower): a partition fixed by the grid alone, never by the thread
   count, a progress bar or timing. With shared bound tables (a work buffer
   of SSDA_TRACK_WORK_SIZE_SHARED) each call builds the tables of its
   band's search areas and counts that work in pixel_ops, so this fixed
   partition is what makes the counts the same for any --threads N. Wider
   bands share the tables over more windows (an area overlaps its
   neighbours' by search_w - step_x columns, built again in the next band);
   narrower ones let the row below start sooner (it waits for the band
   holding its up-right neighbour, so N threads need about 2 N bands a
   row) and keep a band's tables in cache. About 16 bands a row, 8 to 16
   columns each. On the GOES-16 pair (156 columns, 11 interleaved runs at
   load 5, tracking processor time on one thread) bands of 8, 10, 16 and
   32 columns were within 0.5 % of each other, 4 columns +2 %, whole grid
   rows +7 % (tables of 2500 px rows out of cache). */
static uint32_t band_cols(uint32_t cols)
{
    const uint32_t k = (cols + 15u) / 16u;
    return k < 8u ? 8u : k > 16u ? 16u : k;
}

typedef struct {
    const ssda_view_t *a, *b;
    const ssda_track_config_t *cfg;
    const ssda_track_grid_t *g;
    ssda_track_vector_t *out;
    progress_t *prog;
    pthread_mutex_t lock;
    pthread_cond_t moved;
    uint32_t band;      /* columns per call: band_cols(g->cols) */
    uint32_t *done;     /* columns solved per grid row */
    uint32_t next_row;  /* the next row a worker takes */
    uint32_t rows_done;
    int err;            /* the first error, SSDA_OK until then */
} wave_t;

typedef struct {
    wave_t *w;
    ssda_track_stats_t stats;
    int caller; /* the caller's thread: runs on the caller's work buffer */
} worker_t;

/* Columns of row r that may be solved now: all of them for the first row
   or without prediction; else up to one short of what the row above has
   solved (the last needs its up-right neighbour), or all once it is done. */
static uint32_t limit_of(const wave_t *w, uint32_t r)
{
    const uint32_t cols = w->g->cols;
    uint32_t above;
    if (r == 0u || w->cfg->predict == SSDA_TRACK_PREDICT_NONE) {
        return cols;
    }
    above = w->done[r - 1u];
    return above == cols ? cols : above > 0u ? above - 1u : 0u;
}

/* Row r band by band; a band starts once every column of it may be solved
   (its end, not how far the row above happens to be, fixes the call). */
static void solve_row(worker_t *k, uint32_t r, ssda_track_config_t *cfg)
{
    wave_t *w = k->w;
    uint32_t col = 0u;
    while (col < w->g->cols) {
        const uint32_t end = w->g->cols - col > w->band ? col + w->band : w->g->cols;
        int e;
        pthread_mutex_lock(&w->lock);
        while ((e = w->err) == SSDA_OK && limit_of(w, r) < end) {
            pthread_cond_wait(&w->moved, &w->lock);
        }
        pthread_mutex_unlock(&w->lock);
        if (e != SSDA_OK) {
            return;
        }
        e = ssda_track_row(w->a, w->b, cfg, r, col, end, w->out, w->g->count, &k->stats);
        pthread_mutex_lock(&w->lock);
        if (e != SSDA_OK && w->err == SSDA_OK) {
            w->err = e;
        }
        w->done[r] = end;
        if (end == w->g->cols) {
            w->rows_done++;
            if (w->prog != NULL) {
                progress_update(w->prog, w->rows_done);
            }
        }
        pthread_cond_broadcast(&w->moved);
        pthread_mutex_unlock(&w->lock);
        if (e != SSDA_OK) {
            return;
        }
        col = end;
    }
}

static void *worker_main(void *arg)
{
    worker_t *k = arg;
    wave_t *w = k->w;
    ssda_track_config_t cfg = *w->cfg;
    void *work = NULL;
    /* the caller's thread uses the caller's buffer, the others a copy; a
       thread that cannot have one leaves its rows to the others (the
       caller's thread always runs), like one that cannot start: the bands,
       and so the output, stay the same (shared tables can take megabytes
       a thread on wide images) */
    if (cfg.match.work != NULL && !k->caller) {
        if ((work = malloc(cfg.match.work_size)) == NULL) {
            return NULL;
        }
        cfg.match.work = work;
    }
    for (;;) {
        uint32_t r;
        pthread_mutex_lock(&w->lock);
        r = w->next_row < w->g->rows && w->err == SSDA_OK ? w->next_row++ : UINT32_MAX;
        pthread_mutex_unlock(&w->lock);
        if (r == UINT32_MAX) {
            break;
        }
        solve_row(k, r, &cfg);
    }
    free(work);
    return NULL;
}

void track_stats_add(ssda_track_stats_t *t, const ssda_track_stats_t *s)
{
    t->pixel_ops += s->pixel_ops;
    t->positions += s->positions;
    t->completed += s->completed;
    t->check_pixels += s->check_pixels;
    t->windows += s->windows;
    t->ok += s->ok;
    t->excluded += s->excluded;
    t->masked += s->masked;
    t->edge += s->edge;
    t->flat += s->flat;
    t->ambiguous += s->ambiguous;
    t->at_limit += s->at_limit;
}

int track_wave(const ssda_view_t *a, const ssda_view_t *b, const ssda_track_config_t *cfg,
               const ssda_track_grid_t *g, unsigned threads, ssda_track_vector_t *out,
               ssda_track_stats_t *stats, progress_t *prog)
{
    wave_t w;
    worker_t k[PARALLEL_MAX_THREADS];
    pthread_t tid[PARALLEL_MAX_THREADS];
    unsigned n = threads < 1u ? 1u : threads, started = 1u, i;
    if (n > PARALLEL_MAX_THREADS) {
        n = PARALLEL_MAX_THREADS;
    }
    if (n > g->rows) {
        n = g->rows; /* a thread per row at most (g->rows >= 1) */
    }
    memset(&w, 0, sizeof w);
    w.a = a;
    w.b = b;
    w.cfg = cfg;
    w.g = g;
    w.band = band_cols(g->cols);
    w.out = out;
    w.prog = prog;
    w.err = SSDA_OK;
    if ((w.done = calloc(g->rows, sizeof *w.done)) == NULL) {
        return SSDA_ERR_BUFFER;
    }
    pthread_mutex_init(&w.lock, NULL);
    pthread_cond_init(&w.moved, NULL);
    memset(k, 0, sizeof k[0] * n);
    for (i = 0; i < n; i++) {
        k[i].w = &w;
    }
    k[0].caller = 1;
    /* a thread that cannot start leaves its rows to the others */
    for (i = 1; i < n && pthread_create(&tid[i], NULL, worker_main, &k[i]) == 0; i++) {
        started++;
    }
    worker_main(&k[0]);
    for (i = 1; i < started; i++) {
        pthread_join(tid[i], NULL);
    }
    memset(stats, 0, sizeof *stats);
    for (i = 0; i < started; i++) {
        track_stats_add(stats, &k[i].stats);
    }
    pthread_cond_destroy(&w.moved);
    pthread_mutex_destroy(&w.lock);
    free(w.done);
    return w.err;
}
