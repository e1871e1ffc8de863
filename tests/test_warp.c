/*
 * test_warp.c - the warp against ssda_poly_eval at every output pixel
 * (coordinate images make the sampled position visible: nearest gives the
 * source index, bilinear on a ramp gives 256 * u exactly), the identity,
 * the seed's nearest rule against a direct per-pixel resampler written
 * here, streamed sources of every layout and arena size against the same
 * warp in RAM (identical output), the plan's bounds against the rows and
 * columns each segment really samples, the order of the segments, and
 * errors (sink and read failures passed back).
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/warp.h"
#include "test_image.h"
#include "test_rng.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#ifndef SSDA_TEST_SMALL
#define SCALE 1
#else
#define SCALE 3 /* emulated boards: a third of the trials */
#endif

#define SW 200u /* source */
#define SH 150u
#define OW 180u /* output (the map's grid) */
#define OH 140u

static uint16_t g_src16[SH][SW];
static uint8_t g_src8[SH][SW];
static uint16_t g_out[OH][OW], g_ref[OH][OW];
static uint16_t g_rowbuf[OW];
static uint8_t g_dev[SW * SH * 2u * 5u / 4u];
static uint32_t g_arena[4096];
static test_source_t g_t;

/* The sink: store the segment, count calls, check the order. */
typedef struct {
    uint16_t (*img)[OW];
    uint8_t format;
    uint32_t calls;
    int32_t last_x, last_y;
    int fail_at;           /* call index to fail with -77, or -1 */
    int order_ok;
    uint32_t tile_w;
} sink_t;

static int sink(void *ctx, uint32_t x, uint32_t y, uint32_t n, const void *px)
{
    sink_t *s = (sink_t *)ctx;
    uint32_t i;
    if ((int)s->calls == s->fail_at) {
        return -77;
    }
    /* strips left to right; within a strip rows go down (tiles in order) */
    if (s->calls > 0u) {
        const int same_strip = (int32_t)x == s->last_x;
        if (!(same_strip ? (int32_t)y == s->last_y + 1 : ((int32_t)x > s->last_x && y == 0u))) {
            s->order_ok = 0;
        }
    }
    s->last_x = (int32_t)x;
    s->last_y = (int32_t)y;
    s->calls++;
    for (i = 0; i < n; i++) {
        s->img[y][x + i] = s->format == SSDA_PIX_U8 ? ((const uint8_t *)px)[i]
                                                     : ((const uint16_t *)px)[i];
    }
    return 0;
}

static void view_of(ssda_view_t *v, uint8_t format)
{
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(v, format == SSDA_PIX_U8 ? (void *)g_src8 : (void *)g_src16,
                                                  SW, SH, SW * format, (ssda_pixfmt_t)format));
}

static void run_warp(ssda_source_t *src, const ssda_poly_t *map, uint8_t resample, uint16_t fill,
                     uint16_t tw, uint16_t th, uint16_t (*img)[OW], ssda_warp_stats_t *st)
{
    ssda_warp_config_t c;
    ssda_warp_t job;
    sink_t s = {img, src->cfg.format, 0, -1, -1, -1, 1, 0};
    memset(&c, 0, sizeof c);
    c.map = map;
    c.sink = sink;
    c.context = &s;
    c.row = g_rowbuf;
    c.row_size = sizeof g_rowbuf;
    c.tile_w = tw;
    c.tile_h = th;
    c.fill = fill;
    c.resample = resample;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_init(&job, &c, src));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_run(&job, st));
    TEST_ASSERT_EQUAL_UINT32((OW + job.tile_w - 1u) / job.tile_w * OH, s.calls);
    TEST_ASSERT_TRUE(s.order_ok);
}

/* A random smooth map from the OW x OH grid into the source: a shift of up
   to +-30 px (part of the output then falls outside: fill), rotation and
   scale of a few percent, curvature of a few px. */
static int64_t rand_amp(test_rng_t *r, int64_t amp)
{
    const uint64_t v = ((uint64_t)test_rng_next(r) << 32) | test_rng_next(r);
    return (int64_t)(v % (uint64_t)(2 * amp)) - amp;
}

static void random_map(test_rng_t *r, uint8_t order, ssda_poly_t *p)
{
    unsigned t;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(p, OW, OH, order));
    for (t = 0; t < SSDA_POLY_TERMS(order); t++) {
        const int64_t amp = t == 0 ? ((int64_t)30 << 24) : t < 3 ? ((int64_t)6 << 24) : ((int64_t)4 << 24);
        p->u_q24[t] += rand_amp(r, amp);
        p->v_q24[t] += rand_amp(r, amp);
    }
}

/* floor(v / 256) */
static int32_t fl256(int32_t v)
{
    return v >= 0 ? v / 256 : -((-v + 255) / 256);
}

/* Coordinate images: nearest on x-index (y-index) images returns the
   sampled column (row); bilinear on 256 * x (256 * y) returns u (v) in Q8.
   Both checked at every output pixel against ssda_poly_eval. */
static void test_exact_against_eval(void)
{
    test_rng_t r;
    int trial;
    ssda_view_t v;
    test_rng_seed(&r, 0x57415250u);
    view_of(&v, SSDA_PIX_U16);
    for (trial = 0; trial < 24 / SCALE; trial++) {
        const uint8_t order = (uint8_t)(1 + trial % 3);
        const uint8_t resample = (uint8_t)((trial / 3) % 2);
        const int axis = (trial / 6) % 2;
        ssda_poly_t map;
        ssda_source_t src;
        uint32_t x, y;
        random_map(&r, order, &map);
        for (y = 0; y < SH; y++) {
            for (x = 0; x < SW; x++) {
                const uint32_t c = axis == 0 ? x : y;
                g_src16[y][x] = (uint16_t)(resample == SSDA_WARP_NEAREST ? c : c * 256u);
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&src, &v));
        run_warp(&src, &map, resample, 0xFFFF, (uint16_t)(trial % 4 == 0 ? 37 : 0), 0, g_out, NULL);
        for (y = 0; y < OH; y++) {
            for (x = 0; x < OW; x++) {
                int32_t u, w;
                int64_t q, lim;
                uint16_t want;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_eval(&map, (int32_t)x, (int32_t)y, &u, &w));
                q = axis == 0 ? u : w;
                if (resample == SSDA_WARP_NEAREST) {
                    const int64_t iu = fl256(u + 128), iv = fl256(w + 128);
                    const int inside = iu >= 0 && iu < (int64_t)SW && iv >= 0 && iv < (int64_t)SH;
                    want = inside ? (uint16_t)(axis == 0 ? iu : iv) : 0xFFFF;
                } else {
                    const int inside = u >= 0 && u <= (int32_t)(SW - 1) * 256 && w >= 0 &&
                                       w <= (int32_t)(SH - 1) * 256;
                    lim = q;
                    want = inside ? (uint16_t)lim : 0xFFFF;
                }
                if (g_out[y][x] != want) {
                    char msg[80];
                    snprintf(msg, sizeof msg, "trial %d order %u resample %u at (%u, %u)", trial, order,
                             resample, (unsigned)x, (unsigned)y);
                    TEST_ASSERT_EQUAL_UINT16_MESSAGE(want, g_out[y][x], msg);
                }
            }
        }
    }
}

/* The identity map copies the image (both rules); a shift by whole pixels
   shifts it. */
static void test_identity_and_shift(void)
{
    test_rng_t r;
    ssda_view_t v;
    ssda_source_t src;
    ssda_poly_t map;
    uint32_t x, y;
    uint8_t rs;
    test_rng_seed(&r, 5);
    test_fill_texture_u8(&g_src8[0][0], SW, SH, SW, &r);
    view_of(&v, SSDA_PIX_U8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&src, &v));
    for (rs = 0; rs < 2; rs++) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&map, OW, OH, 2));
        map.u_q24[0] += (int64_t)7 << 24;
        map.v_q24[0] -= (int64_t)3 << 24;
        run_warp(&src, &map, rs, 200, 0, 0, g_out, NULL);
        for (y = 0; y < OH; y++) {
            for (x = 0; x < OW; x++) {
                const int sy = (int)y - 3;
                TEST_ASSERT_EQUAL_UINT16(sy < 0 ? 200 : g_src8[sy][x + 7], g_out[y][x]);
            }
        }
    }
}

/* The source's last column and row, and the fill count: a source of
   exactly the output's size (OW x OH, a window of the image) under the
   identity map gives the source back with both rules, bilinear too at
   u = 256 (w - 1), v = 256 (h - 1) (warp.h: defined there, the weight-0
   pixel not read), and no pixel filled; under a shift of (2.5, -1.25) px
   stats.filled is the number of output pixels whose (u, v) the rule of
   warp.h puts outside the source, counted here. */
static void test_edges_and_fill_count(void)
{
    test_rng_t r;
    ssda_view_t v;
    ssda_source_t src;
    ssda_poly_t map;
    ssda_warp_stats_t st;
    uint32_t x, y;
    uint8_t rs;
    test_rng_seed(&r, 6);
    test_fill_texture_u8(&g_src8[0][0], SW, SH, SW, &r);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_src8, OW, OH, SW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&src, &v));
    for (rs = 0; rs < 2; rs++) {
        uint64_t want = 0;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&map, OW, OH, 1));
        memset(&st, 0xA5, sizeof st);
        run_warp(&src, &map, rs, 7, 0, 0, g_out, &st);
        for (y = 0; y < OH; y++) {
            for (x = 0; x < OW; x++) {
                TEST_ASSERT_EQUAL_UINT16(g_src8[y][x], g_out[y][x]);
            }
        }
        TEST_ASSERT_EQUAL_UINT64(0, st.filled);
        map.u_q24[0] += (int64_t)5 << 23;  /* + 2.5 px */
        map.v_q24[0] -= (int64_t)5 << 22;  /* - 1.25 px */
        run_warp(&src, &map, rs, 7, 0, 0, g_out, &st);
        for (y = 0; y < OH; y++) {
            for (x = 0; x < OW; x++) {
                const int32_t u = (int32_t)x * 256 + 640, w = (int32_t)y * 256 - 320;
                const bool out = rs == SSDA_WARP_BILINEAR
                                     ? (u < 0 || w < 0 || u > (int32_t)(OW - 1) * 256 || w > (int32_t)(OH - 1) * 256)
                                     : (fl256(u + 128) < 0 || fl256(w + 128) < 0 || fl256(u + 128) >= (int32_t)OW ||
                                        fl256(w + 128) >= (int32_t)OH);
                want += out ? 1u : 0u;
                if (out) {
                    TEST_ASSERT_EQUAL_UINT16(7, g_out[y][x]);
                }
            }
        }
        TEST_ASSERT_TRUE(want > 0u);
        TEST_ASSERT_EQUAL_UINT64(want, st.filled);
    }
}

/* Nearest and bilinear against a direct resampler written from the rule
   in warp.h, on textured 8- and 16-bit images. */
static void test_against_direct_resampler(void)
{
    test_rng_t r;
    int trial;
    test_rng_seed(&r, 77);
    for (trial = 0; trial < 8; trial++) {
        const uint8_t format = (uint8_t)(1 + trial % 2);
        const uint8_t rs = (uint8_t)((trial / 2) % 2);
        ssda_view_t v;
        ssda_source_t src;
        ssda_poly_t map;
        uint32_t x, y;
        test_fill_texture_u16(&g_src16[0][0], SW, SH, SW, 65535, &r);
        test_fill_texture_u8(&g_src8[0][0], SW, SH, SW, &r);
        view_of(&v, format);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&src, &v));
        random_map(&r, (uint8_t)(1 + trial % 3), &map);
        run_warp(&src, &map, rs, 9, 0, 0, g_out, NULL);
        for (y = 0; y < OH; y++) {
            for (x = 0; x < OW; x++) {
                int32_t u, w;
                uint32_t want = 9;
                (void)ssda_poly_eval(&map, (int32_t)x, (int32_t)y, &u, &w);
                if (rs == SSDA_WARP_NEAREST) {
                    const int32_t i = fl256(u + 128), j = fl256(w + 128);
                    if (i >= 0 && j >= 0 && i < (int32_t)SW && j < (int32_t)SH) {
                        want = test_px(&v, (uint32_t)i, (uint32_t)j);
                    }
                } else if (u >= 0 && w >= 0 && u <= (int32_t)(SW - 1) * 256 && w <= (int32_t)(SH - 1) * 256) {
                    const uint32_t i = (uint32_t)u >> 8, j = (uint32_t)w >> 8, a = (uint32_t)u & 255, b = (uint32_t)w & 255;
                    const uint32_t i1 = a ? i + 1 : i, j1 = b ? j + 1 : j;
                    const uint64_t s = (uint64_t)test_px(&v, i, j) * (256 - a) * (256 - b) +
                                       (uint64_t)test_px(&v, i1, j) * a * (256 - b) +
                                       (uint64_t)test_px(&v, i, j1) * (256 - a) * b +
                                       (uint64_t)test_px(&v, i1, j1) * a * b;
                    want = (uint32_t)((s + 32768) >> 16);
                }
                TEST_ASSERT_EQUAL_UINT16(want, g_out[y][x]);
            }
        }
    }
}

typedef struct {
    uint8_t layout;
    uint16_t tile_w, tile_h;
    uint32_t read_size;
} geo_t;

static const geo_t k_geos[] = {
    {SSDA_LAYOUT_RASTER, 0, 0, 1},
    {SSDA_LAYOUT_RASTER, 0, 0, 64},
    {SSDA_LAYOUT_TILED, 32, 16, 1},
    {SSDA_LAYOUT_TILED, 24, 10, 16},
};

static void stream_source(ssda_source_t *src, const geo_t *g, uint8_t format, size_t arena)
{
    ssda_view_t v;
    ssda_source_config_t c;
    const uint32_t row = g->layout == SSDA_LAYOUT_TILED ? g->tile_w * format : SW * format;
    view_of(&v, format);
    test_source_init(&g_t, g_dev, sizeof g_dev, g->read_size);
    c = test_source_config(&g_t, &v, g->layout, g->tile_w, g->tile_h, 0u, row, 0u, g->read_size,
                           g_arena, arena);
    test_source_store(&g_t, &c, &v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(src, &c));
}

/* Streamed sources (every layout, arenas from the minimum to the whole
   image, chosen and forced tiles) give the output of the in-RAM warp. */
static void test_streamed_equals_ram(void)
{
    test_rng_t r;
    int trial;
    size_t gi;
    test_rng_seed(&r, 0x5354524Du);
    for (trial = 0; trial < 12 / SCALE; trial++) {
        const uint8_t format = (uint8_t)(1 + trial % 2);
        const uint8_t rs = (uint8_t)((trial / 2) % 2);
        ssda_view_t v;
        ssda_source_t ram;
        ssda_poly_t map;
        test_fill_texture_u16(&g_src16[0][0], SW, SH, SW, 65535, &r);
        test_fill_texture_u8(&g_src8[0][0], SW, SH, SW, &r);
        random_map(&r, (uint8_t)(1 + trial % 3), &map);
        view_of(&v, format);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ram, &v));
        run_warp(&ram, &map, rs, 3, 0, 0, g_ref, NULL);
        for (gi = 0; gi < sizeof k_geos / sizeof k_geos[0]; gi++) {
            static const size_t arenas[] = {0, 700, 3000, 9000, sizeof g_arena};
            size_t ai;
            for (ai = 0; ai < sizeof arenas / sizeof arenas[0]; ai++) {
                ssda_source_t src;
                ssda_warp_stats_t st;
                size_t a = arenas[ai];
                if (a == 0) { /* the minimum: a 2 x 2 (bilinear) or 1 x 1 plate */
                    a = SSDA_SOURCE_SIZE(k_geos[gi].layout, rs ? 2 : 1, rs ? 2 : 1, format,
                                         k_geos[gi].read_size, k_geos[gi].tile_w);
                }
                stream_source(&src, &k_geos[gi], format, a);
                memset(g_out, 0xEE, sizeof g_out);
                run_warp(&src, &map, rs, 3, (uint16_t)(ai == 2 ? 50 : 0), (uint16_t)(ai == 2 ? 33 : 0), g_out, &st);
                TEST_ASSERT_EQUAL_MEMORY(g_ref, g_out, sizeof g_out);
                TEST_ASSERT_EQUAL_UINT64(0, g_t.contract_violations);
            }
        }
    }
}

/* With the plan's arena a warp reads about the source once (the strips'
   overlap and shear aside), and the plan's band bounds every segment. */
static void test_plan_bounds_and_reads(void)
{
    test_rng_t r;
    int trial;
    test_rng_seed(&r, 0x504C414Eu);
    for (trial = 0; trial < 30 / SCALE; trial++) {
        const uint8_t rs = (uint8_t)(trial % 2);
        const uint16_t tw = (uint16_t)(trial % 3 == 0 ? 0 : test_rng_range(&r, 16, OW));
        ssda_poly_t map;
        ssda_warp_plan_t plan;
        ssda_source_config_t c;
        uint32_t x0, y, x;
        random_map(&r, (uint8_t)(1 + trial % 3), &map);
        memset(&c, 0, sizeof c);
        c.width = SW;
        c.height = SH;
        c.format = SSDA_PIX_U8;
        c.arena_size = trial % 3 == 0 ? 4000u : 0u;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_plan(&map, rs, &c, tw, 0, &plan));
        TEST_ASSERT_TRUE(plan.tile_w >= 1 && plan.tile_w <= OW && plan.tile_h >= 1 && plan.tile_h <= OH);
        TEST_ASSERT_TRUE(plan.plate_h <= SH && plan.plate_w <= SW);
        TEST_ASSERT_EQUAL_UINT32(plan.row_size, plan.tile_w);
        if (c.arena_size != 0u) {
            TEST_ASSERT_TRUE(!plan.fits || plan.arena_size <= c.arena_size);
        }
        /* every segment of every tile: the rows it samples <= band; every
           tile's columns <= plate_w */
        for (x0 = 0; x0 < OW; x0 += plan.tile_w) {
            const uint32_t n = OW - x0 < plan.tile_w ? OW - x0 : plan.tile_w;
            uint32_t y0;
            for (y0 = 0; y0 < OH; y0 += plan.tile_h) {
                const uint32_t m = OH - y0 < plan.tile_h ? OH - y0 : plan.tile_h;
                int32_t cmin = INT32_MAX, cmax = INT32_MIN;
                for (y = y0; y < y0 + m; y++) {
                    int32_t rmin = INT32_MAX, rmax = INT32_MIN;
                    for (x = x0; x < x0 + n; x++) {
                        int32_t u, w, i0, i1, j0, j1;
                        (void)ssda_poly_eval(&map, (int32_t)x, (int32_t)y, &u, &w);
                        if (rs) {
                            i0 = fl256(u); i1 = i0 + 1; j0 = fl256(w); j1 = j0 + 1;
                        } else {
                            i0 = i1 = fl256(u + 128); j0 = j1 = fl256(w + 128);
                        }
                        rmin = j0 < rmin ? j0 : rmin;
                        rmax = j1 > rmax ? j1 : rmax;
                        cmin = i0 < cmin ? i0 : cmin;
                        cmax = i1 > cmax ? i1 : cmax;
                    }
                    TEST_ASSERT_TRUE(rmax - rmin + 1 <= (int32_t)plan.band || plan.band == SH);
                }
                TEST_ASSERT_TRUE(cmax - cmin + 1 <= (int32_t)plan.plate_w || plan.plate_w == SW);
            }
        }
    }
}

/* Bytes read with the plan's arena: within 1.6x the source on the whole
   range of maps above (strip overlap and shear), far more with the
   minimum arena (same output, checked above). */
static void test_reads_with_plan_arena(void)
{
    test_rng_t r;
    int trial;
    test_rng_seed(&r, 0x52454144u);
    for (trial = 0; trial < 6; trial++) {
        ssda_poly_t map;
        ssda_warp_plan_t plan;
        ssda_source_t src;
        ssda_source_config_t c;
        ssda_view_t v;
        random_map(&r, (uint8_t)(1 + trial % 3), &map);
        view_of(&v, SSDA_PIX_U8);
        memset(&c, 0, sizeof c);
        c.width = SW;
        c.height = SH;
        c.format = SSDA_PIX_U8;
        c.arena_size = 2400u; /* the whole source is 30 000 B */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_plan(&map, SSDA_WARP_BILINEAR, &c, 0, 0, &plan));
        TEST_ASSERT_TRUE(plan.fits);
        stream_source(&src, &k_geos[0], SSDA_PIX_U8, 2400u);
        run_warp(&src, &map, SSDA_WARP_BILINEAR, 0, 0, 0, g_out, NULL);
        TEST_ASSERT_TRUE(g_t.bytes_read <= (uint64_t)(SW * SH * 16 / 10));
    }
}

static int g_sink_calls;
static int counting_sink(void *ctx, uint32_t x, uint32_t y, uint32_t n, const void *px)
{
    (void)ctx; (void)x; (void)y; (void)n; (void)px;
    g_sink_calls++;
    return g_sink_calls == 3 ? -55 : 0;
}

static void test_errors(void)
{
    ssda_view_t v;
    ssda_source_t src, zero;
    ssda_poly_t map;
    ssda_warp_config_t c;
    ssda_warp_t job, poison;
    ssda_warp_plan_t plan;
    ssda_source_config_t sc;
    view_of(&v, SSDA_PIX_U16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&src, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&map, OW, OH, 1));
    memset(&c, 0, sizeof c);
    c.map = &map;
    c.sink = counting_sink;
    c.row = g_rowbuf;
    c.row_size = sizeof g_rowbuf;
    memset(&poison, 0x5A, sizeof poison);
    job = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_init(NULL, &c, &src));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_init(&job, NULL, &src));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_init(&job, &c, NULL));
    c.map = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_init(&job, &c, &src));
    c.map = &map;
    c.sink = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_init(&job, &c, &src));
    c.sink = counting_sink;
    c.row = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_init(&job, &c, &src));
    c.row = g_rowbuf;
    memset(&zero, 0, sizeof zero);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_warp_init(&job, &c, &zero));
    c.resample = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
    c.resample = 0;
    c.tile_w = OW + 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
    c.tile_w = 0;
    c.tile_h = OH + 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
    c.tile_h = 0;
    map.order = 5;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
    map.order = 1;
    /* a map whose centre or scale no longer covers its grid (poly.h: the
       grid lies within |X - cx| <= 2^kx): refused. Accepted before, its
       cubic terms wrapped the 128-bit form and the tile bounds overflowed
       int64 (UBSan: signed overflow in warp.c). */
    {
        ssda_poly_t bad = map;
        ssda_source_config_t geo;
        memset(&geo, 0, sizeof geo);
        geo.width = SW;
        geo.height = SH;
        geo.format = SSDA_PIX_U16;
        c.map = &bad;
        bad.cx = 0; /* OW - 1 = 179 > 2^kx = 128 */
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_plan(&bad, 0, &geo, 0, 0, &plan));
        bad = map;
        bad.kx = 6; /* 2^6 < 90 */
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
        bad = map;
        bad.cy = OH + 200;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
        bad = map;
        bad.ref_h = (uint16_t)(2u * OH + 1u); /* rows beyond cy + 2^ky */
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_plan(&bad, 0, &geo, 0, 0, &plan));
        bad = map;
        bad.cx -= 30; /* moved, but every column still within 2^kx = 128 */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_plan(&bad, 0, &geo, 0, 0, &plan));
        bad.cx = map.cx + 39; /* 129: column 0 leaves the domain */
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_plan(&bad, 0, &geo, 0, 0, &plan));
        TEST_ASSERT_EQUAL_MEMORY(&poison, &job, sizeof job);
        c.map = &map;
    }
    c.row_size = OW * 2 - 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_warp_init(&job, &c, &src));
    c.row_size = sizeof g_rowbuf - 1;
    c.row = (uint8_t *)g_rowbuf + 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_warp_init(&job, &c, &src));
    c.row = g_rowbuf;
    c.row_size = sizeof g_rowbuf;
    /* 8-bit source: fill above 255 */
    view_of(&v, SSDA_PIX_U8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&src, &v));
    c.fill = 256;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_init(&job, &c, &src));
    c.fill = 255;
    /* a streamed source below a 2 x 2 plate for bilinear */
    stream_source(&src, &k_geos[0], SSDA_PIX_U8, 4);
    c.resample = SSDA_WARP_BILINEAR;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_warp_init(&job, &c, &src));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &job, sizeof job);
    /* run errors */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_run(NULL, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_warp_run(&job, NULL));
    /* the sink's error stops the run after its third segment */
    c.resample = SSDA_WARP_NEAREST;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_init(&job, &c, &src));
    g_sink_calls = 0;
    TEST_ASSERT_EQUAL_INT(-55, ssda_warp_run(&job, NULL));
    TEST_ASSERT_EQUAL_INT(3, g_sink_calls);
    /* a failed read is passed back unchanged; the job runs again after */
    stream_source(&src, &k_geos[0], SSDA_PIX_U8, 1000);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_init(&job, &c, &src));
    g_t.fail_at_read = 2;
    g_t.fail_code = -33;
    g_sink_calls = -1000000;
    TEST_ASSERT_EQUAL_INT(-33, ssda_warp_run(&job, NULL));
    g_t.fail_at_read = -1;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_run(&job, NULL));
    /* plan errors */
    memset(&sc, 0, sizeof sc);
    sc.width = SW;
    sc.height = SH;
    sc.format = SSDA_PIX_U8;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_plan(NULL, 0, &sc, 0, 0, &plan));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_plan(&map, 0, NULL, 0, 0, &plan));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_warp_plan(&map, 0, &sc, 0, 0, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_warp_plan(&map, 2, &sc, 0, 0, &plan));
    sc.format = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_warp_plan(&map, 0, &sc, 0, 0, &plan));
    sc.format = SSDA_PIX_U8;
    sc.width = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_warp_plan(&map, 0, &sc, 0, 0, &plan));
    sc.width = SW;
    sc.layout = SSDA_LAYOUT_TILED;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_warp_plan(&map, 0, &sc, 0, 0, &plan));
}

/* An arena too small for any tile: the plan says so (fits = false, the
   smallest tile) and the warp still gives the in-RAM output. */
static void test_tiny_arena_plan(void)
{
    ssda_poly_t map;
    ssda_source_config_t c;
    ssda_warp_plan_t plan;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_poly_init(&map, OW, OH, 1));
    map.u_q24[2] += (int64_t)1 << 30; /* a strong shear: 0.5 px per row */
    memset(&c, 0, sizeof c);
    c.width = SW;
    c.height = SH;
    c.format = SSDA_PIX_U8;
    c.arena_size = 64;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_plan(&map, SSDA_WARP_NEAREST, &c, 0, 0, &plan));
    TEST_ASSERT_FALSE(plan.fits);
    TEST_ASSERT_EQUAL_UINT16(SSDA_WARP_MIN_TILE, plan.tile_w);
    TEST_ASSERT_EQUAL_UINT16(SSDA_WARP_MIN_TILE, plan.tile_h);
    /* no arena given: whole rows */
    c.arena_size = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_warp_plan(&map, SSDA_WARP_NEAREST, &c, 0, 0, &plan));
    TEST_ASSERT_EQUAL_UINT16(OW, plan.tile_w);
    TEST_ASSERT_EQUAL_UINT16(OH, plan.tile_h);
    TEST_ASSERT_FALSE(plan.fits);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exact_against_eval);
    RUN_TEST(test_identity_and_shift);
    RUN_TEST(test_edges_and_fill_count);
    RUN_TEST(test_against_direct_resampler);
    RUN_TEST(test_streamed_equals_ram);
    RUN_TEST(test_plan_bounds_and_reads);
    RUN_TEST(test_reads_with_plan_arena);
    RUN_TEST(test_errors);
    RUN_TEST(test_tiny_arena_plan);
    return UNITY_END();
}
