/*
 * parallel.h - split a tool's independent jobs (grid windows, searches)
 * across POSIX threads (host only; the library stays single-threaded and
 * reentrant: each job uses its own buffers).
 *
 * Jobs are handed out one at a time from a shared counter, so a slow job
 * never holds a fixed share of the others back; each job writes only its
 * own result slot (index i), so the output is identical for any thread
 * count. Totals are formed afterwards, in index order, by the caller.
 */
#ifndef SSDA_PARALLEL_H
#define SSDA_PARALLEL_H

#include <stdint.h>

/* Most threads a tool starts (more gain nothing on the hosts we know). */
#define PARALLEL_MAX_THREADS 256u

/* Processors online (sysconf), 1..PARALLEL_MAX_THREADS. */
unsigned parallel_cores(void);

/*
 * Take "--threads N" (or "--threads=N") out of argv[1..*argc-1], shifting
 * the rest down and decrementing *argc, so the command's own parser never
 * sees it. N: 1..PARALLEL_MAX_THREADS, or 0 = parallel_cores(). *threads
 * is parallel_cores() when the option is absent. Returns 0, or 2 (usage)
 * after a message on stderr naming cmd for a missing or bad N.
 */
int parallel_take_threads(const char *cmd, int *argc, char **argv, unsigned *threads);

/* One job: index i of 0..n-1, run by worker w of 0..threads-1. */
typedef void (*parallel_job_fn)(void *ctx, uint32_t i, unsigned worker);

/* Called under the pool's lock after each job with the count done so far
   (for a progress bar); may be NULL. */
typedef void (*parallel_done_fn)(void *ctx, uint32_t done);

/*
 * Run job(ctx, i, w) for every i in 0..n-1 on min(threads, n) threads
 * (the calling thread is worker 0; threads <= 1 runs everything in order
 * on it). Returns when all jobs are done: 0, or -1 if a thread could not
 * be started (the jobs then all ran on the threads that did start).
 */
int parallel_for(uint32_t n, unsigned threads, parallel_job_fn job, parallel_done_fn done,
                 void *ctx);

#endif /* SSDA_PARALLEL_H */
