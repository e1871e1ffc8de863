/*
 * bench_register_reads.c - the bytes the control-point search
 * (ssda_register_points) reads from streamed images (issue 17): REF and MOV
 * are read from PNG files into memory devices, then searched with each
 * source streamed in half of each budget (as `ssda register --mem` splits
 * it) and once in RAM; prints per budget each source's bytes read, reads,
 * and bytes read / image bytes, and whether the points equal the in-RAM
 * run's. A budget the search refuses prints the arena each source needs.
 *   ssda-bench-register-reads REF.png MOV.png [--offset X,Y] [--grid N]
 *                             [--window W] [--search S] [--mem B,B,...]
 * Defaults: offset 0,0, the seed's 4 x 4 grid, 20 in 40, budgets
 * 256,4K,64K,1M.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "img_source.h"
#include "png_io.h"
#include "ssda/register.h"

static size_t parse_bytes(const char *s, const char **end)
{
    char *e;
    unsigned long long v = strtoull(s, &e, 10);
    if (*e == 'K' || *e == 'k') {
        v <<= 10;
        e++;
    } else if (*e == 'M' || *e == 'm') {
        v <<= 20;
        e++;
    }
    *end = e;
    return (size_t)v;
}

static void usage(void)
{
    fprintf(stderr, "usage: ssda-bench-register-reads REF.png MOV.png [--offset X,Y] [--grid N]\n"
                    "       [--window W] [--search S] [--mem B,B,...]\n");
    exit(2);
}

int main(int argc, char **argv)
{
    gray_image_t ref, mov;
    ssda_register_config_t cfg;
    const char *mems = "256,4K,64K,1M";
    ssda_register_point_t *want, *got;
    size_t ncell, ws, image_r, image_m;
    void *work;
    char err[256];
    int i;
    if (argc < 3) {
        usage();
    }
    memset(&cfg, 0, sizeof cfg);
    for (i = 3; i < argc; i++) {
        if (i + 1 >= argc) {
            usage();
        }
        if (strcmp(argv[i], "--offset") == 0) {
            int x, y;
            if (sscanf(argv[++i], "%d,%d", &x, &y) != 2) {
                usage();
            }
            cfg.offset_x = x;
            cfg.offset_y = y;
        } else if (strcmp(argv[i], "--grid") == 0) {
            cfg.grid_x = cfg.grid_y = (uint16_t)atoi(argv[++i]);
        } else if (strcmp(argv[i], "--window") == 0) {
            cfg.window = (uint16_t)atoi(argv[++i]);
        } else if (strcmp(argv[i], "--search") == 0) {
            cfg.search = (uint16_t)atoi(argv[++i]);
        } else if (strcmp(argv[i], "--mem") == 0) {
            mems = argv[++i];
        } else {
            usage();
        }
    }
    if (png_read_gray(argv[1], PNG_GRAY_NATIVE, &ref, NULL, err, sizeof err) != 0 ||
        png_read_gray(argv[2], PNG_GRAY_NATIVE, &mov, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    if (ref.bits != mov.bits) {
        fprintf(stderr, "REF and MOV differ in depth\n");
        return 1;
    }
    {
        const uint8_t fmt = ref.bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
        const uint32_t gx = cfg.grid_x ? cfg.grid_x : SSDA_REGISTER_DEFAULT_GRID;
        const uint32_t gy = cfg.grid_y ? cfg.grid_y : SSDA_REGISTER_DEFAULT_GRID;
        ncell = (size_t)gx * gy;
        ws = SSDA_REGISTER_WORK_SIZE(cfg.window ? cfg.window : SSDA_REGISTER_DEFAULT_WINDOW,
                                     cfg.search ? cfg.search : SSDA_REGISTER_DEFAULT_SEARCH, fmt);
    }
    image_r = (size_t)ref.stride * ref.height;
    image_m = (size_t)mov.stride * mov.height;
    want = calloc(ncell, sizeof *want);
    got = calloc(ncell, sizeof *got);
    work = malloc(ws);
    if (want == NULL || got == NULL || work == NULL) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    {
        ssda_source_t sr, sm;
        img_device_t dr, dm;
        int e = img_source_init(&sr, &ref, &dr, NULL, 0);
        if (e == SSDA_OK) {
            e = img_source_init(&sm, &mov, &dm, NULL, 0);
        }
        if (e == SSDA_OK) {
            e = ssda_register_points(&sr, &sm, &cfg, want, ncell, NULL, work, ws);
        }
        if (e != SSDA_OK) {
            fprintf(stderr, "in RAM: %s\n", ssda_strerror(e));
            return 1;
        }
    }
    printf("REF %s: %ux%u, %zu bytes; MOV %s: %zu bytes; offset %d,%d\n", argv[1], ref.width,
           ref.height, image_r, argv[2], image_m, (int)cfg.offset_x, (int)cfg.offset_y);
    {
        const uint8_t fmt = ref.bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
        const size_t nr = SSDA_REGISTER_REF_SIZE(SSDA_LAYOUT_RASTER, ref.width, cfg.grid_x,
                                                 cfg.window, fmt, 1u, 0u);
        const size_t nm = SSDA_REGISTER_MOV_SIZE(SSDA_LAYOUT_RASTER, mov.width, cfg.search, fmt,
                                                 1u, 0u);
        printf("least arenas: REF %zu, MOV %zu bytes (each source gets half of mem: mem >= %zu)\n",
               nr, nm, 2u * (nr > nm ? nr : nm));
    }
    printf("%10s %14s %8s %10s %14s %8s %10s %s\n", "mem", "REF bytes", "x REF", "REF reads",
           "MOV bytes", "x MOV", "MOV reads", "points");
    while (*mems != '\0') {
        const char *end;
        const size_t budget = parse_bytes(mems, &end);
        const size_t half = (budget / 2u) & ~(size_t)3u;
        void *ar = malloc(half > 0 ? half : 4), *am = malloc(half > 0 ? half : 4);
        ssda_source_t sr, sm;
        img_device_t dr, dm;
        int e;
        if (ar == NULL || am == NULL) {
            fprintf(stderr, "out of memory\n");
            return 1;
        }
        e = img_source_init(&sr, &ref, &dr, ar, half);
        if (e == SSDA_OK) {
            e = img_source_init(&sm, &mov, &dm, am, half);
        }
        if (e == SSDA_OK) {
            e = ssda_register_points(&sr, &sm, &cfg, got, ncell, NULL, work, ws);
        }
        if (e != SSDA_OK) {
            printf("%10zu refused: %s\n", budget, ssda_strerror(e));
        } else {
            printf("%10zu %14llu %8.2f %10llu %14llu %8.3f %10llu %s\n", budget,
                   (unsigned long long)sr.stats.bytes_read, (double)sr.stats.bytes_read / image_r,
                   (unsigned long long)sr.stats.reads, (unsigned long long)sm.stats.bytes_read,
                   (double)sm.stats.bytes_read / image_m, (unsigned long long)sm.stats.reads,
                   memcmp(want, got, ncell * sizeof *got) == 0 ? "= in RAM" : "DIFFER");
        }
        free(ar);
        free(am);
        mems = *end == ',' ? end + 1 : end;
        if (end == mems && *end != '\0' && *end != ',') {
            break;
        }
    }
    free(want);
    free(got);
    free(work);
    gray_image_free(&ref);
    gray_image_free(&mov);
    return 0;
}
