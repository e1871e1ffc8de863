/* parallel.c - a tool's jobs across POSIX threads (see parallel.h). */
#define _POSIX_C_SOURCE 200809L
#include "parallel.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

unsigned parallel_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1) {
        return 1u;
    }
    return n > (long)PARALLEL_MAX_THREADS ? PARALLEL_MAX_THREADS : (unsigned)n;
}

/* "N" as 0..PARALLEL_MAX_THREADS (0: the cores); -1 if it is not one. */
static long parse_count(const char *s)
{
    char *end;
    long v;
    if (s == NULL || *s < '0' || *s > '9') {
        return -1;
    }
    v = strtol(s, &end, 10);
    return (*end != '\0' || v > (long)PARALLEL_MAX_THREADS) ? -1 : v;
}

int parallel_take_threads(const char *cmd, int *argc, char **argv, unsigned *threads)
{
    int i = 1;
    *threads = parallel_cores();
    while (i < *argc) {
        const char *val = NULL;
        int used;
        long v;
        if (strcmp(argv[i], "--") == 0) {
            break; /* operands from here on */
        }
        if (strcmp(argv[i], "--threads") == 0) {
            val = i + 1 < *argc ? argv[i + 1] : NULL;
            used = 2;
        } else if (strncmp(argv[i], "--threads=", 10) == 0) {
            val = argv[i] + 10;
            used = 1;
        } else {
            i++;
            continue;
        }
        if ((v = parse_count(val)) < 0) {
            fprintf(stderr, "ssda %s: --threads needs a count 0..%u (0: all %u cores)\n", cmd,
                    PARALLEL_MAX_THREADS, parallel_cores());
            return 2;
        }
        *threads = v == 0 ? parallel_cores() : (unsigned)v;
        memmove(argv + i, argv + i + used, (size_t)(*argc - i - used + 1) * sizeof *argv);
        *argc -= used;
    }
    return 0;
}

typedef struct {
    pthread_mutex_t lock;
    uint32_t next, done, n;
    parallel_job_fn job;
    parallel_done_fn on_done;
    void *ctx;
} pool_t;

typedef struct {
    pool_t *pool;
    unsigned worker;
} worker_t;

static void *work(void *arg)
{
    const worker_t *w = arg;
    pool_t *p = w->pool;
    for (;;) {
        uint32_t i;
        pthread_mutex_lock(&p->lock);
        i = p->next < p->n ? p->next++ : p->n;
        pthread_mutex_unlock(&p->lock);
        if (i >= p->n) {
            return NULL;
        }
        p->job(p->ctx, i, w->worker);
        pthread_mutex_lock(&p->lock);
        p->done++;
        if (p->on_done != NULL) {
            p->on_done(p->ctx, p->done);
        }
        pthread_mutex_unlock(&p->lock);
    }
}

int parallel_for(uint32_t n, unsigned threads, parallel_job_fn job, parallel_done_fn done,
                 void *ctx)
{
    pool_t p;
    pthread_t tid[PARALLEL_MAX_THREADS];
    worker_t w[PARALLEL_MAX_THREADS];
    unsigned t, started = 1u;
    int rc = 0;
    if (threads > PARALLEL_MAX_THREADS) {
        threads = PARALLEL_MAX_THREADS;
    }
    if (threads > n) {
        threads = n;
    }
    memset(&p, 0, sizeof p);
    p.n = n;
    p.job = job;
    p.on_done = done;
    p.ctx = ctx;
    pthread_mutex_init(&p.lock, NULL);
    for (t = 0; t < PARALLEL_MAX_THREADS && t < (threads ? threads : 1u); t++) {
        w[t].pool = &p;
        w[t].worker = t;
    }
    for (t = 1; t < threads; t++) {
        if (pthread_create(&tid[t], NULL, work, &w[t]) != 0) {
            rc = -1;
            break;
        }
        started++;
    }
    (void)work(&w[0]);
    for (t = 1; t < started; t++) {
        pthread_join(tid[t], NULL);
    }
    pthread_mutex_destroy(&p.lock);
    return rc;
}
