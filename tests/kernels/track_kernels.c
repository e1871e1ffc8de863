/*
 * track_kernels.c - tracking's results and counts as text, for comparing
 * kernel sets (tests/CMakeLists.txt: track_kernels_equal). The program is
 * built twice from the library's sources: with the build's kernel set and
 * with the portable one (kernel/kernel_portable.c, whose engine takes the
 * loops that run on the Cortex-M targets). x86's set has its own paths
 * around its kernels (shared tables' rows and vertical sums, the window's
 * block sums, the 16-bit rows of a placement, the predict scan's bound
 * pass, the mask test), each with its own pixel_ops accounting: the two
 * programs must print the same lines, every vector field (status, motion,
 * sub-pixel motion, SAD, exact flag, uniqueness, texture) and every count
 * (pixel_ops, positions, completed, check_pixels, statuses) of ssda_track
 * over grids of 16 x 16..19 windows (the kernels' case) and others, 8 and
 * 16-bit, shared and per-window tables, every prediction, masks and
 * uniqueness, on textured, low-contrast (ties, partial sums meeting the cut
 * levels) and extreme data. Prints one line a search and the number of
 * searches; exits 1 on an error of the library.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "ssda/track.h"
#include "ssda/view.h"
#include "test_rng.h"

#define IW 104u
#define IH 88u
#define MAX_WIN 1200u
static uint16_t g_a16[IH * IW], g_b16[IH * IW];
static uint8_t g_a8[IH * IW], g_b8[IH * IW];
static uint64_t g_work[(256u * 1024u) / 8u];
static ssda_track_vector_t g_vec[MAX_WIN];

typedef struct {
    uint16_t win_w, win_h, search_w, search_h, step_x, step_y;
} geom_t;

static const geom_t k_geoms[] = {
    {16, 16, 32, 32, 8, 8},    /* the seed's, overlapping windows */
    {16, 16, 32, 32, 16, 16},  /* the seed's */
    {16, 17, 28, 27, 11, 7},   /* rows after the 4 groups */
    {16, 19, 30, 33, 9, 10},
    {16, 18, 40, 34, 12, 9},
    {20, 16, 36, 32, 10, 10},  /* 4 groups, 5 blocks a row: no quad */
    {12, 8, 20, 17, 7, 5},     /* 2 groups */
    {16, 16, 47, 40, 15, 13},  /* 32 x 25 placements: the masks full */
    {16, 16, 56, 24, 24, 12},  /* 41 placements a row: no masks */
    {6, 5, 14, 11, 5, 4},      /* no blocks */
};
#define NGEOMS (sizeof k_geoms / sizeof k_geoms[0])

/* kind 0: SECOND = FIRST moved (varying) plus noise; 1: values 0..3
   (ties; sums that meet the cut levels); 2: extreme values; 3: as 0 with
   the mask value in patches of both. */
/* FIRST's texture: random samples smoothed by two 3 x 3 box passes
   (wrapping at the edges). */
static void fill_texture(test_rng_t *r)
{
    static uint32_t t[IH * IW];
    uint32_t x, y, pass;
    for (x = 0; x < IW * IH; x++) {
        g_a16[x] = (uint16_t)test_rng_range(r, 0, 65535);
    }
    for (pass = 0; pass < 2u; pass++) {
        for (y = 0; y < IH; y++) {
            for (x = 0; x < IW; x++) {
                uint32_t s = 0u, i, j;
                for (j = 0; j < 3u; j++) {
                    for (i = 0; i < 3u; i++) {
                        s += g_a16[((y + IH + j - 1u) % IH) * IW + (x + IW + i - 1u) % IW];
                    }
                }
                t[y * IW + x] = s / 9u;
            }
        }
        for (x = 0; x < IW * IH; x++) {
            g_a16[x] = (uint16_t)t[x];
        }
    }
}

static void make_images(uint32_t seed, uint32_t kind)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    fill_texture(&r);
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            const uint32_t mx = (x / 11u + y / 13u) % 5u, my = (x / 17u + y / 7u) % 5u;
            const uint32_t sx = (x + IW + 2u - mx) % IW, sy = (y + IH + 2u - my) % IH;
            uint32_t a = g_a16[y * IW + x];
            uint32_t b = g_a16[sy * IW + sx] + test_rng_range(&r, 0, 600);
            if (kind == 1u) {
                a = test_rng_range(&r, 0, 3);
                b = test_rng_range(&r, 0, 3);
            } else if (kind == 2u) {
                a = test_rng_range(&r, 0, 9) == 0u ? 0u : 65535u;
                if (((x / 3u) + (y / 2u)) % 2u == 0u && y > IH / 2u) {
                    a = 65535u - a;
                }
                b = test_rng_range(&r, 0, 7) == 0u ? 0u : 65535u;
            }
            g_a16[y * IW + x] = (uint16_t)a;
            g_b16[y * IW + x] = (uint16_t)(b > 65535u ? 65535u : b);
        }
    }
    for (x = 0; x < IW * IH; x++) {
        const bool small = kind == 1u;
        g_a8[x] = (uint8_t)(small ? g_a16[x] : (uint32_t)g_a16[x] >> 8);
        g_b8[x] = (uint8_t)(small ? g_b16[x] : (uint32_t)g_b16[x] >> 8);
        if (kind == 3u) { /* the mask value only in the patches */
            g_a16[x] = g_a16[x] == 4095u ? 4096u : g_a16[x];
            g_b16[x] = g_b16[x] == 4095u ? 4096u : g_b16[x];
            g_a8[x] = g_a8[x] == 200u ? 201u : g_a8[x];
            g_b8[x] = g_b8[x] == 200u ? 201u : g_b8[x];
        }
    }
    if (kind == 3u) {
        for (y = 30; y < 34; y++) {
            for (x = 40; x < 45; x++) {
                g_a16[y * IW + x] = 4095u;
                g_a8[y * IW + x] = 200u;
                g_b16[(y + 20u) * IW + x + 30u] = 4095u;
                g_b8[(y + 20u) * IW + x + 30u] = 200u;
            }
        }
    }
}

/* FNV-1a, 64 bits, over v's bytes. */
static uint64_t fnv(uint64_t h, uint64_t v, uint32_t bytes)
{
    uint32_t i;
    for (i = 0; i < bytes; i++) {
        h ^= (v >> (8u * i)) & 0xFFu;
        h *= 0x100000001B3ull;
    }
    return h;
}

static uint64_t vectors_hash(uint32_t n)
{
    uint64_t h = 0xCBF29CE484222325ull;
    uint32_t k;
    for (k = 0; k < n; k++) {
        const ssda_track_vector_t *v = &g_vec[k];
        h = fnv(h, v->sad, 8u);
        h = fnv(h, (uint32_t)v->dx, 4u);
        h = fnv(h, (uint32_t)v->dy, 4u);
        h = fnv(h, (uint32_t)v->sub_dx_q8, 4u);
        h = fnv(h, (uint32_t)v->sub_dy_q8, 4u);
        h = fnv(h, v->texture_q8, 4u);
        h = fnv(h, v->x, 2u);
        h = fnv(h, v->y, 2u);
        h = fnv(h, v->unique_q8, 2u);
        h = fnv(h, v->status, 1u);
        h = fnv(h, v->exact ? 1u : 0u, 1u);
    }
    return h;
}

/* One search of the grid: its line. Returns 0, or 1 on an error. */
static int run(uint32_t kind, uint32_t gi, uint32_t wide, uint32_t mode, uint32_t shared)
{
    static const uint8_t k_pred[] = {SSDA_TRACK_PREDICT_MEDIAN, SSDA_TRACK_PREDICT_LEFT,
                                     SSDA_TRACK_PREDICT_NONE, SSDA_TRACK_PREDICT_MEDIAN};
    const geom_t *g = &k_geoms[gi];
    ssda_view_t a, b;
    ssda_track_config_t c;
    ssda_track_stats_t s;
    ssda_track_grid_t grid;
    int err;
    if ((wide != 0u ? ssda_view_init(&a, g_a16, IW, IH, IW * 2u, SSDA_PIX_U16)
                    : ssda_view_init(&a, g_a8, IW, IH, IW, SSDA_PIX_U8)) != SSDA_OK ||
        (wide != 0u ? ssda_view_init(&b, g_b16, IW, IH, IW * 2u, SSDA_PIX_U16)
                    : ssda_view_init(&b, g_b8, IW, IH, IW, SSDA_PIX_U8)) != SSDA_OK) {
        printf("case %u %u %u %u %u: bad views\n", kind, gi, wide, mode, shared);
        return 1;
    }
    memset(&c, 0, sizeof c);
    c.win_w = g->win_w;
    c.win_h = g->win_h;
    c.search_w = g->search_w;
    c.search_h = g->search_h;
    c.step_x = g->step_x;
    c.step_y = g->step_y;
    c.predict = k_pred[mode];
    c.flags = SSDA_TRACK_NO_FLAT;
    if (kind == 3u) {
        c.flags |= SSDA_TRACK_MASK;
        c.mask_value = wide != 0u ? 4095u : 200u;
    }
    if (mode == 3u) {
        c.flags |= SSDA_TRACK_UNIQUE;
    }
    c.match.flags = SSDA_MATCH_BOUNDS;
    c.match.work = g_work;
    c.match.work_size =
        shared != 0u
            ? SSDA_TRACK_WORK_SIZE_SHARED(IW, g->search_w, g->search_h, g->win_w, g->win_h)
            : SSDA_TRACK_WORK_SIZE(g->search_w, g->search_h, g->win_w, g->win_h);
    if (c.match.work_size > sizeof g_work || ssda_track_grid(&c, IW, IH, &grid) != SSDA_OK ||
        grid.count > MAX_WIN) {
        printf("case %u %u %u %u %u: bad setup\n", kind, gi, wide, mode, shared);
        return 1;
    }
    memset(g_vec, 0, sizeof g_vec);
    err = ssda_track(&a, &b, &c, g_vec, MAX_WIN, &s);
    printf("case %u %u %u %u %u: err %d ops %llu pos %llu done %llu check %llu"
           " ok %u masked %u amb %u limit %u vec %016llx\n",
           kind, gi, wide, mode, shared, err, (unsigned long long)s.pixel_ops,
           (unsigned long long)s.positions, (unsigned long long)s.completed,
           (unsigned long long)s.check_pixels, s.ok, s.masked, s.ambiguous, s.at_limit,
           (unsigned long long)vectors_hash(grid.count));
    return err != SSDA_OK ? 1 : 0;
}

/* argv[1]: the file for the results (tests/config/compare_runs.cmake) */
int main(int argc, char **argv)
{
    uint32_t kind, gi, wide, mode, shared, n = 0u;
    int bad = 0;
    if (argc != 2 || freopen(argv[1], "w", stdout) == NULL) {
        fprintf(stderr, "usage: track_kernels RESULTS_FILE\n");
        return 2;
    }
    for (kind = 0; kind < 4u; kind++) {
        make_images(900u + kind, kind);
        for (gi = 0; gi < NGEOMS; gi++) {
            for (wide = 0; wide < 2u; wide++) {
                for (mode = 0; mode < 4u; mode++) {
                    /* per-window tables once a geometry: the kernels'
                       paths are mostly the shared tables' */
                    for (shared = mode == 0u ? 0u : 1u; shared < 2u; shared++) {
                        bad |= run(kind, gi, wide, mode, shared);
                        n++;
                    }
                }
            }
        }
    }
    printf("%u searches\n", n);
    return bad;
}
