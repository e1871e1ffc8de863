/*
 * amp_match.c - read amplification of ssda_stream_match against the arena
 * (issue 22): the case, a 65535 x 2 8-bit area and a 46 x 2 window,
 * raster and predicted scans with bounds, stored raster (read size 1) and
 * as 16 x 2 tiles (read size 4096), for arenas from one area row to the
 * read-once size in quarters. Prints the return code, bytes read as a
 * multiple of the area, and read() calls. The device is RAM (memcpy).
 *   build/<dir>/tools/bench/stream/ssda-bench-stream-amp
 * An older library that accepts the small arenas spends about 30 s on each
 * tiled one (a terabyte through memcpy); SSDA_AMP_SKIP_TILED=1 skips them.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ssda/stream.h"

#define AW 65535u
#define AH 2u

static uint8_t g_img[AH][AW];
static uint8_t g_raster[AW * AH];
static uint8_t g_tiles[((AW + 15u) / 16u) * 32u + 4096u];
static uint32_t g_work[SSDA_MATCH_WORK_SIZE(AW, AH, 46, 2) / 4u + 1u];
static uint32_t g_arena[(2u * AW + 20000u) / 4u];

static int read_ram(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    memcpy(buf, (const uint8_t *)ctx + off, size);
    return 0;
}

static void run(uint8_t layout, uint8_t scan, size_t arena, uint32_t quarter)
{
    ssda_source_config_t c;
    ssda_source_t src, win;
    ssda_view_t v, wv;
    ssda_match_config_t m;
    ssda_match_result_t r;
    const char *name = layout == SSDA_LAYOUT_TILED ? "tiled 16x2, read size 4096" : "raster, read size 1";
    int e;
    memset(&c, 0, sizeof c);
    c.read = read_ram;
    c.context = layout == SSDA_LAYOUT_TILED ? (void *)g_tiles : (void *)g_raster;
    c.width = (uint16_t)AW;
    c.height = (uint16_t)AH;
    c.format = SSDA_PIX_U8;
    c.layout = layout;
    if (layout == SSDA_LAYOUT_TILED) {
        c.tile_w = 16u;
        c.tile_h = 2u;
        c.read_size = 4096u;
    }
    c.arena = g_arena;
    c.arena_size = arena;
    if (ssda_view_init(&v, g_img, AW, AH, AW, SSDA_PIX_U8) != SSDA_OK ||
        ssda_view_roi(&wv, &v, 30000u, 0u, 46u, 2u) != SSDA_OK ||
        ssda_source_init(&src, &c) != SSDA_OK || ssda_source_init_view(&win, &wv) != SSDA_OK) {
        printf("init failed\n");
        return;
    }
    memset(&m, 0, sizeof m);
    m.flags = SSDA_MATCH_BOUNDS;
    m.work = g_work;
    m.work_size = sizeof g_work;
    m.scan = scan;
    m.predict_x = 100;
    if (layout == SSDA_LAYOUT_TILED && quarter < 4u && getenv("SSDA_AMP_SKIP_TILED") != NULL) {
        printf("| %s | %s | %zu (%u/4) | skipped | | |\n", name,
               scan == SSDA_SCAN_RASTER ? "raster" : "predict", arena, (unsigned)quarter);
        return;
    }
    e = ssda_stream_match(&src, NULL, &win, NULL, &m, &r);
    printf("| %s | %s | %zu (%u/4) | %s | %.1fx | %llu |\n", name,
           scan == SSDA_SCAN_RASTER ? "raster" : "predict", arena, (unsigned)quarter,
           e == SSDA_OK ? "ok" : ssda_strerror(e), (double)src.stats.bytes_read / (double)(AW * AH),
           (unsigned long long)src.stats.reads);
    (void)fflush(stdout);
}

int main(void)
{
    uint32_t x, y, s = 1u, q;
    uint8_t layout, scan;
    for (y = 0; y < AH; y++) {
        for (x = 0; x < AW; x++) {
            s = s * 1103515245u + 12345u;
            g_img[y][x] = (uint8_t)(s >> 24);
            g_raster[y * AW + x] = g_img[y][x];
            g_tiles[(x / 16u) * 32u + y * 16u + x % 16u] = g_img[y][x];
        }
    }
    printf("| layout | scan | arena, bytes (of the way from one row to read-once) | result | bytes read / area | read() calls |\n");
    printf("|---|---|---|---|---|---|\n");
    for (layout = 0; layout < 2u; layout++) {
        const uint32_t rs = layout == SSDA_LAYOUT_TILED ? 4096u : 1u;
        const size_t lo = SSDA_SOURCE_SIZE(layout, AW, 1u, 1u, rs, 16u);
        const size_t hi = SSDA_SOURCE_SIZE(layout, AW, 2u, 1u, rs, 16u);
        for (scan = 0; scan < 2u; scan++) {
            for (q = 0; q <= 4u; q++) {
                run(layout, scan == 0u ? (uint8_t)SSDA_SCAN_RASTER : (uint8_t)SSDA_SCAN_PREDICT,
                    lo + (hi - lo) * q / 4u, q);
            }
        }
    }
    return 0;
}
