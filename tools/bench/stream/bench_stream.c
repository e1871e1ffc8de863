/*
 * bench_stream.c - the issue-3 benchmark: the seed's grid tracking job
 * (16 x 16 windows, 32 x 32 search areas, step 16) with both images
 * streamed from files through a pread() callback, inside library arenas of
 * a few sizes, against the same job on the images in RAM.
 *
 * The PNGs are decoded once (tools/common/png_io) and written as raw pixels
 * (raster, or tiled with --tile) into temporary files, which the sources
 * then read; the files are read once before timing, so the figures measure
 * the library and the system calls through the page cache, not the disk.
 *
 * For each total arena (split between FIRST's and SECOND's plates so that
 * both hold a strip of the same grid columns):
 *   - peak library RAM: the arena, the bounds work buffer, and the stack the
 *     library used (measured on a painted thread stack, with a memcpy read
 *     callback so that pread's own frames are not counted; host x86-64);
 *   - bytes read / bytes of the union of the search areas and windows of
 *     every window whose area lies inside FIRST (the job's footprint);
 *   - read() calls; wall time relative to ssda_track in RAM (best of
 *     --reps); how many vectors equal the in-RAM ones.
 * Prints Markdown.
 *
 * Usage: ssda-bench-stream [--reps N] [--mask V] [--arenas A,B,..]
 *                          [--tile WxH] [--read-size N] [--predict none|left|median]
 *                          [--no-bounds] [--tmpdir DIR] FIRST.png SECOND.png
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, pread, mkstemp */
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "png_io.h"
#include "ssda/stream.h"
#include "ssda/track.h"

#define MAX_ARENAS 8
#define STACK_BYTES (1u << 20)
#define PAINT 0xA5u

typedef struct {
    const char *path;   /* temporary raw file */
    int fd;
    const uint8_t *ram; /* the same bytes in RAM (for the stack run) */
    size_t size;
} raw_file_t;

typedef struct {
    uint32_t tile_w, tile_h; /* 0: raster */
    uint32_t read_size;
} layout_opt_t;

/* Aligned heap block (C99 has no aligned_alloc): NULL on failure. */
static void *alloc_aligned(size_t align, size_t size)
{
    void *p = NULL;
    return posix_memalign(&p, align, size != 0u ? size : align) == 0 ? p : NULL;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* CPU time of this process (user + system: pread's kernel time counts),
   which other processes' load does not inflate. */
static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- file-backed and RAM-backed read callbacks ---------------------- */

static int file_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    const raw_file_t *f = (const raw_file_t *)ctx;
    uint8_t *p = (uint8_t *)buf;
    while (size > 0u) {
        ssize_t n = pread(f->fd, p, size, (off_t)off);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            /* past the end (alignment slack) reads as zeros */
            if (n == 0) {
                memset(p, 0, size);
                return 0;
            }
            return SSDA_ERR_IO;
        }
        p += n;
        off += (uint32_t)n;
        size -= (uint32_t)n;
    }
    return 0;
}

static int ram_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    const raw_file_t *f = (const raw_file_t *)ctx;
    size_t have = off < f->size ? f->size - off : 0u;
    size_t n = size < have ? size : have;
    memcpy(buf, f->ram + off, n);
    memset((uint8_t *)buf + n, 0, size - n);
    return 0;
}

/* ---- raw files -------------------------------------------------------- */

/* Store img raw (raster, or tiled tile_w x tile_h, tiles full size) in a
   new temporary file and in *ram. Returns 0 or -1. */
static int write_raw(const gray_image_t *img, const layout_opt_t *lay, const char *dir,
                     raw_file_t *f, uint8_t **ram)
{
    const uint32_t bpp = img->bits / 8u;
    char *path = malloc(strlen(dir) + 32);
    uint8_t *bytes;
    size_t size;
    if (path == NULL) {
        return -1;
    }
    sprintf(path, "%s/ssda-stream-XXXXXX", dir);
    if (lay->tile_w != 0u) {
        uint32_t across = (img->width + lay->tile_w - 1u) / lay->tile_w;
        uint32_t down = (img->height + lay->tile_h - 1u) / lay->tile_h;
        size = (size_t)across * down * lay->tile_w * lay->tile_h * bpp;
        bytes = calloc(size, 1);
        if (bytes == NULL) {
            return -1;
        }
        for (uint32_t y = 0; y < img->height; y++) {
            for (uint32_t x = 0; x < img->width; x++) {
                size_t t = (size_t)(y / lay->tile_h) * across + x / lay->tile_w;
                size_t off = (t * lay->tile_h + y % lay->tile_h) * lay->tile_w + x % lay->tile_w;
                memcpy(bytes + off * bpp,
                       (const uint8_t *)img->pixels + (size_t)y * img->stride + (size_t)x * bpp, bpp);
            }
        }
    } else {
        size = (size_t)img->stride * img->height;
        bytes = malloc(size);
        if (bytes == NULL) {
            return -1;
        }
        memcpy(bytes, img->pixels, size);
    }
    f->fd = mkstemp(path);
    if (f->fd < 0 || write(f->fd, bytes, size) != (ssize_t)size) {
        fprintf(stderr, "bench-stream: cannot write %s: %s\n", path, strerror(errno));
        return -1;
    }
    f->path = path;
    f->ram = bytes;
    f->size = size;
    *ram = bytes;
    return 0;
}

/* ---- the job ---------------------------------------------------------- */

typedef struct {
    const ssda_track_config_t *cfg;
    const gray_image_t *img[2];
    raw_file_t *file[2];
    const layout_opt_t *lay;
    void *arena[2];
    size_t arena_size[2];
    ssda_track_vector_t *out;
    size_t count;
    bool from_ram;          /* memcpy callback instead of pread */
    const ssda_view_t *views; /* stack run of ssda_track in RAM */
    ssda_source_stats_t st[2];
    int err;
} job_t;

static int init_source(ssda_source_t *s, const job_t *j, int i)
{
    ssda_source_config_t c;
    memset(&c, 0, sizeof c);
    c.read = j->from_ram ? ram_read : file_read;
    c.context = j->file[i];
    c.width = (uint16_t)j->img[i]->width;
    c.height = (uint16_t)j->img[i]->height;
    c.format = (uint8_t)(j->img[i]->bits / 8u);
    c.layout = j->lay->tile_w != 0u ? SSDA_LAYOUT_TILED : SSDA_LAYOUT_RASTER;
    c.tile_w = (uint16_t)j->lay->tile_w;
    c.tile_h = (uint16_t)j->lay->tile_h;
    c.read_size = j->lay->read_size;
    c.arena = j->arena[i];
    c.arena_size = j->arena_size[i];
    return ssda_source_init(s, &c);
}

static void run_stream(job_t *j)
{
    ssda_source_t s[2];
    j->err = init_source(&s[0], j, 0);
    if (j->err == SSDA_OK) {
        j->err = init_source(&s[1], j, 1);
    }
    if (j->err == SSDA_OK) {
        j->err = ssda_stream_track(&s[0], &s[1], j->cfg, j->out, j->count, NULL);
    }
    j->st[0] = s[0].stats;
    j->st[1] = s[1].stats;
}

static void *stream_thread(void *arg)
{
    job_t *j = (job_t *)arg;
    if (j->views != NULL) { /* the in-RAM job, for comparison */
        j->err = ssda_track(&j->views[0], &j->views[1], j->cfg, j->out, j->count, NULL);
    } else {
        run_stream(j);
    }
    return NULL;
}

/* Deepest stack the job reached on a painted thread stack, in bytes. */
static size_t stack_used(job_t *j)
{
    uint8_t *stack = alloc_aligned(4096, STACK_BYTES);
    pthread_attr_t attr;
    pthread_t t;
    size_t i = 0;
    if (stack == NULL) {
        return 0;
    }
    memset(stack, PAINT, STACK_BYTES);
    pthread_attr_init(&attr);
    pthread_attr_setstack(&attr, stack, STACK_BYTES);
    if (pthread_create(&t, &attr, stream_thread, j) != 0) {
        free(stack);
        return 0;
    }
    pthread_join(t, NULL);
    while (i < STACK_BYTES && stack[i] == PAINT) {
        i++;
    }
    free(stack);
    return STACK_BYTES - i;
}

/* Baseline: the same thread running nothing but the thread start. */
static void *empty_thread(void *arg)
{
    (void)arg;
    return NULL;
}

static size_t stack_baseline(void)
{
    uint8_t *stack = alloc_aligned(4096, STACK_BYTES);
    pthread_attr_t attr;
    pthread_t t;
    size_t i = 0;
    memset(stack, PAINT, STACK_BYTES);
    pthread_attr_init(&attr);
    pthread_attr_setstack(&attr, stack, STACK_BYTES);
    pthread_create(&t, &attr, empty_thread, NULL);
    pthread_join(t, NULL);
    while (i < STACK_BYTES && stack[i] == PAINT) {
        i++;
    }
    free(stack);
    return STACK_BYTES - i;
}

/* Bytes of the union of the search areas (in FIRST) and windows (in
   SECOND) of every window whose area lies inside FIRST. */
static uint64_t footprint(const ssda_track_grid_t *g, uint32_t fw, uint32_t fh, uint32_t bpp)
{
    const uint32_t hx = (g->search_w - g->win_w) / 2u, hy = (g->search_h - g->win_h) / 2u;
    uint8_t *fa = calloc((size_t)fw * fh, 1), *sw = calloc((size_t)fw * fh, 1);
    uint64_t n = 0;
    for (uint32_t r = 0; r < g->rows; r++) {
        for (uint32_t c = 0; c < g->cols; c++) {
            uint32_t wx = g->roi_x + c * g->step_x, wy = g->roi_y + r * g->step_y;
            if (wx < hx || wy < hy || wx - hx + g->search_w > fw || wy - hy + g->search_h > fh) {
                continue;
            }
            for (uint32_t y = 0; y < g->search_h; y++) {
                memset(fa + (size_t)(wy - hy + y) * fw + (wx - hx), 1, g->search_w);
            }
            for (uint32_t y = 0; y < g->win_h; y++) {
                memset(sw + (size_t)(wy + y) * fw + wx, 1, g->win_w);
            }
        }
    }
    for (size_t i = 0; i < (size_t)fw * fh; i++) {
        n += fa[i] + sw[i];
    }
    free(fa);
    free(sw);
    return n * bpp;
}

/* Split a total arena: the largest strip of grid columns whose plates
   (FIRST: strip x search_h, SECOND: strip x win_h) both fit; FIRST gets
   exactly its plate, SECOND the rest. Returns the strip's columns (0 when
   not even one column fits: then 2/3 : 1/3). */
static uint32_t split_arena(size_t total, const ssda_track_grid_t *g, const layout_opt_t *lay,
                            uint32_t fw, uint8_t fmt, size_t *a0, size_t *a1)
{
    const uint8_t L = lay->tile_w != 0u ? SSDA_LAYOUT_TILED : SSDA_LAYOUT_RASTER;
    uint32_t k = 0;
    *a0 = (total * 2u / 3u) & ~(size_t)3u;
    *a1 = (total - *a0) & ~(size_t)3u;
    while (k < g->cols) {
        size_t w0 = SSDA_STREAM_STRIP_W(k + 1u, g->step_x, g->search_w);
        size_t f0, f1;
        if (w0 > fw) {
            w0 = fw;
        }
        f0 = SSDA_SOURCE_SIZE(L, w0, g->search_h, fmt, lay->read_size, lay->tile_w);
        f1 = SSDA_SOURCE_SIZE(L, SSDA_STREAM_STRIP_W(k + 1u, g->step_x, g->win_w), g->win_h, fmt,
                              lay->read_size, lay->tile_w);
        if (f0 + f1 > total) {
            break;
        }
        k++;
        *a0 = f0;
        *a1 = (total - f0) & ~(size_t)3u;
    }
    return k;
}

static size_t parse_list(const char *s, size_t *v, size_t max)
{
    size_t n = 0;
    while (*s != '\0' && n < max) {
        char *end;
        v[n++] = strtoul(s, &end, 10);
        if (*end == 'K' || *end == 'k') {
            v[n - 1] *= 1024u;
            end++;
        }
        s = *end == ',' ? end + 1 : end;
        if (end == s && *s != '\0') {
            break;
        }
    }
    return n;
}

/* The benchmark's options. */
typedef struct {
    const char *paths[2];
    const char *tmpdir;
    size_t arenas[MAX_ARENAS];
    size_t n_arenas;
    int reps, use_mask, bounds;
    uint16_t mask;
    uint8_t predict;
    layout_opt_t lay;
} bench_opts_t;

/* Everything the runs share. */
typedef struct {
    bench_opts_t o;
    gray_image_t img[2];
    raw_file_t file[2];
    uint8_t *ram[2];
    ssda_view_t v[2];
    ssda_track_config_t cfg;
    ssda_track_grid_t grid;
    ssda_track_vector_t *ref, *out;
    ssda_track_stats_t ref_st;
    uint32_t *work;
    size_t work_size, base_stack, ram_stack;
    uint64_t union_bytes;
    double t_ram, c_ram; /* best in-RAM wall and CPU time over every arena's runs */
} bench_t;

/* Returns 0, or 2 after a usage message. */
static int parse_options(int argc, char **argv, bench_opts_t *o)
{
    int npaths = 0;
    memset(o, 0, sizeof *o);
    o->tmpdir = getenv("TMPDIR") != NULL ? getenv("TMPDIR") : "/tmp";
    o->arenas[0] = 4096;
    o->arenas[1] = 16384;
    o->arenas[2] = 65536;
    o->n_arenas = 3;
    o->reps = 5;
    o->bounds = 1;
    o->predict = SSDA_TRACK_PREDICT_LEFT; /* median needs a band of the whole grid width */
    o->lay.read_size = 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
            o->reps = atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--mask") && i + 1 < argc) {
            o->use_mask = 1;
            o->mask = (uint16_t)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--arenas") && i + 1 < argc) {
            o->n_arenas = parse_list(argv[++i], o->arenas, MAX_ARENAS);
        } else if (!strcmp(argv[i], "--tile") && i + 1 < argc) {
            if (sscanf(argv[++i], "%ux%u", &o->lay.tile_w, &o->lay.tile_h) != 2 ||
                !o->lay.tile_w || !o->lay.tile_h) {
                fprintf(stderr, "bench-stream: --tile WxH\n");
                return 2;
            }
        } else if (!strcmp(argv[i], "--read-size") && i + 1 < argc) {
            o->lay.read_size = (uint32_t)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--predict") && i + 1 < argc) {
            i++;
            o->predict = !strcmp(argv[i], "none")   ? SSDA_TRACK_PREDICT_NONE
                         : !strcmp(argv[i], "left") ? SSDA_TRACK_PREDICT_LEFT
                                                    : SSDA_TRACK_PREDICT_MEDIAN;
        } else if (!strcmp(argv[i], "--no-bounds")) {
            o->bounds = 0;
        } else if (!strcmp(argv[i], "--tmpdir") && i + 1 < argc) {
            o->tmpdir = argv[++i];
        } else if (argv[i][0] != '-' && npaths < 2) {
            o->paths[npaths++] = argv[i];
        } else {
            fprintf(stderr,
                    "usage: %s [--reps N] [--mask V] [--arenas A,B,..] [--tile WxH] [--read-size N]\n"
                    "          [--predict none|left|median] [--no-bounds] [--tmpdir DIR] FIRST.png SECOND.png\n",
                    argv[0]);
            return 2;
        }
    }
    if (npaths != 2) {
        fprintf(stderr, "bench-stream: two PNG files needed (FIRST SECOND)\n");
        return 2;
    }
    return 0;
}

/* Read both images, write their raw files, set up the grid, the reference
   vectors (in RAM) and the in-RAM job's stack. Returns 0 or 1. */
static int setup(bench_t *b)
{
    char err[256];
    for (int i = 0; i < 2; i++) {
        if (png_read_gray(b->o.paths[i], PNG_GRAY_NATIVE, &b->img[i], NULL, err, sizeof err) != 0) {
            fprintf(stderr, "bench-stream: %s\n", err);
            return 1;
        }
        if (gray_image_view(&b->img[i], &b->v[i]) != SSDA_OK ||
            write_raw(&b->img[i], &b->o.lay, b->o.tmpdir, &b->file[i], &b->ram[i]) != 0) {
            return 1;
        }
    }
    if (b->img[0].bits != b->img[1].bits) {
        fprintf(stderr, "bench-stream: images of different depths\n");
        return 1;
    }
    memset(&b->cfg, 0, sizeof b->cfg); /* 16 x 16 windows, 32 x 32 areas, step 16 */
    b->cfg.flags = SSDA_TRACK_NO_FLAT | SSDA_TRACK_NO_SUBPIXEL; /* the search's reads alone */
    b->cfg.predict = b->o.predict;
    b->cfg.match.threshold = SSDA_THRESHOLD_AUTO;
    b->cfg.match.scan = SSDA_SCAN_PREDICT;
    if (b->o.use_mask) {
        b->cfg.flags |= SSDA_TRACK_MASK;
        b->cfg.mask_value = b->o.mask;
    }
    if (b->o.bounds) {
        b->work_size = SSDA_TRACK_WORK_SIZE(32, 32, 16, 16);
        b->work = malloc(b->work_size);
        b->cfg.match.flags = SSDA_MATCH_BOUNDS;
        b->cfg.match.work = b->work;
        b->cfg.match.work_size = b->work_size;
    }
    if (ssda_track_grid(&b->cfg, (uint16_t)b->img[1].width, (uint16_t)b->img[1].height,
                        &b->grid) != SSDA_OK) {
        fprintf(stderr, "bench-stream: images too small for the grid\n");
        return 1;
    }
    b->ref = calloc(b->grid.count, sizeof *b->ref);
    b->out = calloc(b->grid.count, sizeof *b->out);
    b->union_bytes = footprint(&b->grid, b->img[0].width, b->img[0].height, b->img[0].bits / 8u);
    /* in RAM: the reference vectors; timed below, interleaved with the
       streamed runs so that both see the same machine load */
    if (ssda_track(&b->v[0], &b->v[1], &b->cfg, b->ref, b->grid.count, &b->ref_st) != SSDA_OK) {
        fprintf(stderr, "bench-stream: ssda_track failed\n");
        return 1;
    }
    b->base_stack = stack_baseline();
    {
        job_t j;
        memset(&j, 0, sizeof j);
        j.cfg = &b->cfg;
        j.views = b->v;
        j.out = b->out;
        j.count = b->grid.count;
        b->ram_stack = stack_used(&j);
        b->ram_stack = b->ram_stack > b->base_stack ? b->ram_stack - b->base_stack : 0u;
    }
    return 0;
}

static void print_header(const bench_t *b)
{
    const bench_opts_t *o = &b->o;
    const ssda_track_grid_t *g = &b->grid;
    printf("## Streamed grid tracking: %s -> %s\n\n", o->paths[0], o->paths[1]);
    printf("%ux%u, %u-bit, %s layout%s, read granularity %u B; grid %ux%u windows of %ux%u in "
           "%ux%u areas, step %u; `auto` + %s prediction%s%s. %u windows searched.\n"
           "Union of the areas and windows of windows whose area lies inside FIRST: %.2f MB. "
           "Times: best of %d runs of each, alternating with the in-RAM job (ssda_track); ratios to "
           "the in-RAM runs of the same loop.\n\n",
           b->img[0].width, b->img[0].height, b->img[0].bits, o->lay.tile_w ? "tiled" : "raster",
           o->lay.tile_w ? " (tiles below)" : "", o->lay.read_size, g->cols, g->rows, g->win_w,
           g->win_h, g->search_w, g->search_h, g->step_x,
           o->predict == SSDA_TRACK_PREDICT_NONE
               ? "no"
               : (o->predict == SSDA_TRACK_PREDICT_LEFT ? "left" : "median"),
           o->bounds ? " + bounds" : "", o->use_mask ? ", fill value masked" : "", b->ref_st.ok,
           b->union_bytes / 1e6, o->reps);
    if (o->lay.tile_w) {
        printf("Tiles: %ux%u.\n\n", o->lay.tile_w, o->lay.tile_h);
    }
    printf("| arena (FIRST + SECOND) | strip | work buffer | stack | peak library RAM | bytes read | "
           "read() calls | amplification | wall time | vs RAM | CPU time vs RAM | "
           "vs RAM, memcpy device | vectors equal |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

/* Best times of reps runs: the in-RAM job and the streamed one (pread,
   then a memcpy device: the library without the system calls) alternating,
   so that all see the same machine load. t[]: RAM wall, RAM CPU, streamed
   wall, streamed CPU, memcpy-device wall. */
static void time_runs(bench_t *b, job_t *j, double t[5])
{
    for (int k = 0; k < 5; k++) {
        t[k] = 1e30;
    }
    for (int r = 0; r < b->o.reps; r++) {
        double t0 = now_s(), c0 = cpu_s();
        (void)ssda_track(&b->v[0], &b->v[1], &b->cfg, b->ref, b->grid.count, NULL);
        t0 = now_s() - t0;
        c0 = cpu_s() - c0;
        t[0] = t0 < t[0] ? t0 : t[0];
        t[1] = c0 < t[1] ? c0 : t[1];
        t0 = now_s();
        c0 = cpu_s();
        run_stream(j);
        t0 = now_s() - t0;
        c0 = cpu_s() - c0;
        t[2] = t0 < t[2] ? t0 : t[2];
        t[3] = c0 < t[3] ? c0 : t[3];
        j->from_ram = true;
        t0 = now_s();
        run_stream(j);
        t0 = now_s() - t0;
        t[4] = t0 < t[4] ? t0 : t[4];
        j->from_ram = false;
    }
}

/* One arena's row of the table. */
static void bench_arena(bench_t *b, size_t arena)
{
    job_t j;
    size_t stack, equal = 0;
    uint32_t k;
    double t[5];
    uint64_t bytes, calls;
    memset(&j, 0, sizeof j);
    j.cfg = &b->cfg;
    j.img[0] = &b->img[0];
    j.img[1] = &b->img[1];
    j.file[0] = &b->file[0];
    j.file[1] = &b->file[1];
    j.lay = &b->o.lay;
    j.out = b->out;
    j.count = b->grid.count;
    k = split_arena(arena, &b->grid, &b->o.lay, b->img[0].width, (uint8_t)(b->img[0].bits / 8u),
                    &j.arena_size[0], &j.arena_size[1]);
    j.arena[0] = alloc_aligned(64, (j.arena_size[0] + 63u) & ~(size_t)63u);
    j.arena[1] = alloc_aligned(64, (j.arena_size[1] + 63u) & ~(size_t)63u);
    run_stream(&j); /* warm the page cache, then time */
    if (j.err != SSDA_OK) {
        printf("| %zu | - | - | - | - | - | - | - | error: %s | - | - | - | - |\n", arena,
               ssda_strerror(j.err));
        free(j.arena[0]);
        free(j.arena[1]);
        return;
    }
    time_runs(b, &j, t);
    b->t_ram = t[0] < b->t_ram ? t[0] : b->t_ram;
    b->c_ram = t[1] < b->c_ram ? t[1] : b->c_ram;
    bytes = j.st[0].bytes_read + j.st[1].bytes_read;
    calls = j.st[0].reads + j.st[1].reads;
    for (size_t i = 0; i < b->grid.count; i++) {
        equal += b->ref[i].status == b->out[i].status && b->ref[i].dx == b->out[i].dx &&
                 b->ref[i].dy == b->out[i].dy && b->ref[i].sad == b->out[i].sad &&
                 b->ref[i].exact == b->out[i].exact;
    }
    j.from_ram = true;
    stack = stack_used(&j);
    stack = stack > b->base_stack ? stack - b->base_stack : 0u;
    printf("| %zu B (%zu + %zu) | %u cols | %zu B | %zu B | %zu B | %.2f MB | %llu | %.3f | "
           "%.1f ms | %.2fx | %.2fx | %.2fx | %zu / %u |\n",
           arena, j.arena_size[0], j.arena_size[1], k, b->work_size, stack,
           arena + b->work_size + stack, bytes / 1e6, (unsigned long long)calls,
           (double)bytes / (double)b->union_bytes, t[2] * 1e3, t[2] / t[0], t[3] / t[1],
           t[4] / t[0], equal, b->grid.count);
    fflush(stdout);
    free(j.arena[0]);
    free(j.arena[1]);
}

int main(int argc, char **argv)
{
    static bench_t b;
    int rc = parse_options(argc, argv, &b.o);
    if (rc != 0) {
        return rc;
    }
    if (setup(&b) != 0) {
        return 1;
    }
    b.t_ram = b.c_ram = 1e30;
    print_header(&b);
    for (size_t a = 0; a < b.o.n_arenas; a++) {
        bench_arena(&b, b.o.arenas[a]);
    }
    printf("\nIn RAM (ssda_track on the decoded images): %.1f ms wall, %.1f ms CPU, %zu B of work "
           "buffer, %zu B of stack.\n", b.t_ram * 1e3, b.c_ram * 1e3, b.work_size, b.ram_stack);
    printf("Stack: host x86-64, measured on a painted thread stack with a memcpy read "
           "callback (the library's frames plus a trivial callback).\n");
    for (int i = 0; i < 2; i++) {
        close(b.file[i].fd);
        unlink(b.file[i].path);
        free(b.ram[i]);
        gray_image_free(&b.img[i]);
    }
    free(b.ref);
    free(b.out);
    free(b.work);
    return 0;
}
