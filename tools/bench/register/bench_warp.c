/*
 * bench_warp.c - a warp of an image far larger than the memory given to it:
 * a W x H 8-bit texture (20 000 x 2 000 by default) is written to a raw
 * temp file and warped through a 2nd-order map (rotation 0.25 deg, scale
 * 1.003, shift (17.3, -9.6) px, a 2 px bow) from a streamed source whose
 * arena plus the warp's segment buffer stay within the budget (32 KB by
 * default), and again from RAM. Prints the plan, bytes read, CPU times and
 * the share of output pixels equal to the in-RAM warp (the goal: 100 %).
 *   ssda-bench-warp [--width W] [--height H] [--budget BYTES] [--order N]
 *                   [--resample nearest|bilinear] [--reps N] [--tmpdir DIR]
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, pread, mkstemp */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "ssda/warp.h"

typedef struct {
    int fd;
} file_dev_t;

static int file_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    const file_dev_t *d = (const file_dev_t *)ctx;
    ssize_t got = pread(d->fd, buf, size, (off_t)off);
    return got == (ssize_t)size ? 0 : SSDA_ERR_IO;
}

typedef struct {
    uint8_t *out;
    uint32_t width;
} out_t;

static int put(void *ctx, uint32_t x, uint32_t y, uint32_t n, const void *px)
{
    out_t *o = (out_t *)ctx;
    memcpy(o->out + (size_t)y * o->width + x, px, n);
    return 0;
}

static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static uint32_t xs(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* Smooth random texture: random values, two passes of a 3-tap box along
   rows and columns (in place, row by row). */
static void texture(uint8_t *img, uint32_t w, uint32_t h)
{
    uint32_t s = 12345u, x, y;
    for (size_t i = 0; i < (size_t)w * h; i++) {
        img[i] = (uint8_t)(xs(&s) >> 24);
    }
    for (int pass = 0; pass < 2; pass++) {
        for (y = 0; y < h; y++) {
            uint8_t *r = img + (size_t)y * w;
            uint32_t prev = r[0];
            for (x = 1; x + 1 < w; x++) {
                uint32_t cur = r[x];
                r[x] = (uint8_t)((prev + cur + r[x + 1]) / 3u);
                prev = cur;
            }
        }
        for (y = 1; y + 1 < h; y++) {
            uint8_t *a = img + (size_t)(y - 1) * w, *b = a + w, *c = b + w;
            for (x = 0; x < w; x++) {
                b[x] = (uint8_t)((a[x] + b[x] + c[x]) / 3u);
            }
        }
    }
}

static int64_t q24(double v)
{
    return (int64_t)(v * 16777216.0 + (v >= 0 ? 0.5 : -0.5));
}

int main(int argc, char **argv)
{
    uint32_t W = 20000, H = 2000, budget = 32768, order = 2, reps = 3;
    uint8_t resample = SSDA_WARP_NEAREST;
    const char *tmpdir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--width") && v) { W = (uint32_t)atoi(v); i++; }
        else if (!strcmp(a, "--height") && v) { H = (uint32_t)atoi(v); i++; }
        else if (!strcmp(a, "--budget") && v) { budget = (uint32_t)atoi(v) * (strchr(v, 'K') ? 1024u : 1u); i++; }
        else if (!strcmp(a, "--order") && v) { order = (uint32_t)atoi(v); i++; }
        else if (!strcmp(a, "--reps") && v) { reps = (uint32_t)atoi(v); i++; }
        else if (!strcmp(a, "--tmpdir") && v) { tmpdir = v; i++; }
        else if (!strcmp(a, "--resample") && v) { resample = !strcmp(v, "bilinear"); i++; }
        else { fprintf(stderr, "usage: see the top of bench_warp.c\n"); return 2; }
    }
    if (W < 16 || W > 65535 || H < 16 || H > 65535 || order < 1 || order > 3) {
        fprintf(stderr, "bad size or order\n");
        return 2;
    }
    uint8_t *src = malloc((size_t)W * H), *ref = malloc((size_t)W * H), *out = malloc((size_t)W * H);
    if (!src || !ref || !out) { fprintf(stderr, "out of memory\n"); return 1; }
    texture(src, W, H);
    char path[4096];
    snprintf(path, sizeof path, "%s/ssda-bench-warp-XXXXXX", tmpdir);
    int fd = mkstemp(path);
    if (fd < 0 || write(fd, src, (size_t)W * H) != (ssize_t)((size_t)W * H)) {
        fprintf(stderr, "cannot write %s: %s\n", path, strerror(errno));
        return 1;
    }
    unlink(path);

    /* the map on the output grid (= the source's size), in pixel units,
       converted to the normalised Q24 coefficients */
    ssda_poly_t map;
    ssda_poly_init(&map, (uint16_t)W, (uint16_t)H, (uint8_t)order);
    {
        const double th = 0.25 * 3.14159265358979 / 180.0, s = 1.003;
        const double sx = (double)(1u << map.kx), sy = (double)(1u << map.ky);
        const double c = s * 0.99999048, sn = s * th; /* cos, sin(0.25 deg) */
        /* about the centre: x = cx + 17.3 + c dX - sn dY, y = cy - 9.6 + sn dX + c dY */
        map.u_q24[0] = q24(map.cx + 17.3);
        map.u_q24[1] = q24(c * sx);
        map.u_q24[2] = q24(-sn * sy);
        map.v_q24[0] = q24(map.cy - 9.6);
        map.v_q24[1] = q24(sn * sx);
        map.v_q24[2] = q24(c * sy);
        if (order >= 2) {
            map.v_q24[3] = q24(2.0); /* a 2 px bow across the width */
        }
    }

    /* in RAM */
    ssda_view_t view;
    ssda_source_t ram;
    ssda_view_init(&view, src, (uint16_t)W, (uint16_t)H, W, SSDA_PIX_U8);
    ssda_source_init_view(&ram, &view);
    uint8_t *rowbuf = malloc(W);
    out_t o_ref = {ref, W}, o_out = {out, W};
    ssda_warp_config_t wc;
    memset(&wc, 0, sizeof wc);
    wc.map = &map;
    wc.sink = put;
    wc.resample = resample;
    wc.row = rowbuf;
    wc.row_size = W;
    double t_ram = 1e30, t_str = 1e30;
    ssda_warp_t job;
    for (uint32_t r = 0; r < reps; r++) {
        wc.context = &o_ref;
        if (ssda_warp_init(&job, &wc, &ram) != SSDA_OK) { fprintf(stderr, "init failed\n"); return 1; }
        double t0 = cpu_s();
        if (ssda_warp_run(&job, NULL) != SSDA_OK) { fprintf(stderr, "run failed\n"); return 1; }
        double t = cpu_s() - t0;
        t_ram = t < t_ram ? t : t_ram;
    }

    /* streamed: find the arena whose plan's tile leaves room for the segment
       buffer inside the budget */
    ssda_source_config_t sc;
    memset(&sc, 0, sizeof sc);
    file_dev_t dev = {fd};
    sc.read = file_read;
    sc.context = &dev;
    sc.width = (uint16_t)W;
    sc.height = (uint16_t)H;
    sc.format = SSDA_PIX_U8;
    ssda_warp_plan_t plan;
    size_t arena_size = budget;
    for (int it = 0; it < 32; it++) {
        sc.arena_size = arena_size;
        ssda_warp_plan(&map, resample, &sc, 0, 0, &plan);
        if (arena_size + plan.row_size <= budget) break;
        arena_size = budget - plan.row_size < arena_size - 64 ? budget - plan.row_size : arena_size - 64;
    }
    uint32_t *arena = malloc(arena_size + 4);
    sc.arena = arena;
    sc.arena_size = arena_size;
    ssda_source_t str;
    if (ssda_source_init(&str, &sc) != SSDA_OK) { fprintf(stderr, "source init failed\n"); return 1; }
    wc.row_size = plan.row_size;
    wc.context = &o_out;
    ssda_warp_stats_t st;
    for (uint32_t r = 0; r < reps; r++) {
        memset(out, 0, (size_t)W * H);
        memset(&str.stats, 0, sizeof str.stats);
        if (ssda_warp_init(&job, &wc, &str) != SSDA_OK) { fprintf(stderr, "init failed\n"); return 1; }
        double t0 = cpu_s();
        int err = ssda_warp_run(&job, &st);
        double t = cpu_s() - t0;
        if (err != SSDA_OK) { fprintf(stderr, "run failed: %s\n", ssda_strerror(err)); return 1; }
        t_str = t < t_str ? t : t_str;
    }
    size_t same = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) same += out[i] == ref[i];
    double load = 0;
    FILE *la = fopen("/proc/loadavg", "r");
    if (la) { if (fscanf(la, "%lf", &load) != 1) load = 0; fclose(la); }
    printf("| warp | %u x %u px, order %u, %s |\n|---|---|\n", W, H, order, resample ? "bilinear" : "nearest");
    printf("| budget | %u B: arena %zu B + segment buffer %zu B = %zu B |\n", budget, arena_size,
           plan.row_size, arena_size + plan.row_size);
    printf("| tile, plate | %u x %u px tiles, plate %u x %u px (band %u rows), read-once plan %s |\n",
           plan.tile_w, plan.tile_h, plan.plate_w, plan.plate_h, plan.band, plan.fits ? "fits" : "does not fit");
    printf("| bytes read | %llu (%.3f x the %u-byte source), %llu reads, %llu plate moves |\n",
           (unsigned long long)str.stats.bytes_read, (double)str.stats.bytes_read / ((double)W * H),
           W * H, (unsigned long long)str.stats.reads, (unsigned long long)st.moves);
    printf("| output equal to the in-RAM warp | %.4f %% (%zu of %zu px) |\n", 100.0 * same / ((double)W * H),
           same, (size_t)W * H);
    printf("| CPU time (best of %u) | streamed %.3f s, in RAM %.3f s (%.1f ns/px) |\n", reps, t_str, t_ram,
           t_ram * 1e9 / ((double)W * H));
    printf("| load average | %.2f |\n", load);
    close(fd);
    free(src); free(ref); free(out); free(rowbuf); free(arena);
    return same == (size_t)W * H ? 0 : 1;
}
