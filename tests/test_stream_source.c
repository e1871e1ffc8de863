/*
 * test_stream_source.c - sources and their plate cache: configuration
 * checks, row spans equal to the image in RAM over raster and tiled layouts,
 * several strides, offsets, read granularities and arena sizes; read counts;
 * the plate policy (rows kept when it slides); a failed read at every
 * possible read, passed back unchanged with nothing written.
 */
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "stream_internal.h"
#include "test_image.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 70u
#define IH 45u
static uint16_t g_img16[IH][IW];
static uint8_t g_img8[IH][IW];
static uint8_t g_dev[40000];
static uint32_t g_arena[4096]; /* 16 KB, 4-byte aligned */
static test_source_t g_tdev;

/* One storage geometry under test. */
typedef struct {
    uint8_t layout;
    uint16_t tile_w, tile_h;
    uint32_t offset, stride_pad, tile_pad, read_size;
} geometry_t;

static const geometry_t k_geoms[] = {
    {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 0, 1},
    {SSDA_LAYOUT_RASTER, 0, 0, 10, 6, 0, 4},
    {SSDA_LAYOUT_RASTER, 0, 0, 2, 0, 0, 64},
    {SSDA_LAYOUT_RASTER, 0, 0, 512, 34, 0, 512},
    {SSDA_LAYOUT_TILED, 16, 8, 0, 0, 0, 1},
    {SSDA_LAYOUT_TILED, 13, 7, 6, 4, 10, 32},
    {SSDA_LAYOUT_TILED, 64, 64, 0, 0, 0, 1},
    {SSDA_LAYOUT_TILED, 8, 16, 256, 0, 0, 256},
};
#define N_GEOMS (sizeof k_geoms / sizeof k_geoms[0])

static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u16(&g_img16[0][0], IW, IH, IW, 65535u, &r);
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            g_img8[y][x] = (uint8_t)test_rng_range(&r, 0, 255);
        }
    }
}

static ssda_view_t image_view(uint8_t format)
{
    ssda_view_t v;
    if (format == SSDA_PIX_U16) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img16, IW, IH, IW * 2u, SSDA_PIX_U16));
    } else {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img8, IW, IH, IW, SSDA_PIX_U8));
    }
    return v;
}

/* Store the image in geometry g on the device; return its config. */
static ssda_source_config_t setup(const geometry_t *g, uint8_t format, size_t arena_size)
{
    ssda_view_t v = image_view(format);
    uint32_t bpp = format;
    uint32_t row = g->layout == SSDA_LAYOUT_TILED ? g->tile_w * bpp : IW * bpp;
    uint32_t stride = row + g->stride_pad;
    uint32_t tile_stride = g->layout == SSDA_LAYOUT_TILED ? stride * g->tile_h + g->tile_pad : 0u;
    ssda_source_config_t c;
    test_source_init(&g_tdev, g_dev, sizeof g_dev, g->read_size);
    c = test_source_config(&g_tdev, &v, g->layout, g->tile_w, g->tile_h, g->offset, stride,
                           tile_stride, g->read_size, g_arena, arena_size);
    test_source_store(&g_tdev, &c, &v);
    return c;
}

static uint32_t pixel(uint8_t format, uint32_t x, uint32_t y)
{
    return format == SSDA_PIX_U16 ? g_img16[y][x] : g_img8[y][x];
}

static void assert_span(uint8_t format, const uint8_t *px, uint32_t x, uint32_t y, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        uint32_t got = format == SSDA_PIX_U16 ? ((const uint16_t *)(const void *)px)[i] : px[i];
        if (got != pixel(format, x + i, y)) {
            TEST_FAIL_MESSAGE("span pixel differs from the image");
        }
    }
}

/* Widest single-row plate the arena holds, by the public macro. */
static uint32_t widest(const ssda_source_config_t *c)
{
    uint32_t w = 0;
    while (w < IW && SSDA_SOURCE_SIZE(c->layout, w + 1u, 1u, c->format, c->read_size,
                                      c->tile_w) <= c->arena_size) {
        w++;
    }
    return w;
}

static void check_counts(const ssda_source_t *s)
{
    TEST_ASSERT_EQUAL_UINT64(0, g_tdev.contract_violations);
    TEST_ASSERT_EQUAL_UINT64(g_tdev.reads, s->stats.reads);
    TEST_ASSERT_EQUAL_UINT64(g_tdev.bytes_read, s->stats.bytes_read);
}

/* Random spans over every geometry, both formats, four arena sizes. */
static void test_row_spans_equal_the_image(void)
{
    uint32_t gi, fi, ai, k;
    make_images(11u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        for (fi = 1; fi <= 2; fi++) {
            const uint8_t format = (uint8_t)fi;
            const geometry_t *g = &k_geoms[gi];
            size_t sizes[4];
            sizes[0] = SSDA_SOURCE_SIZE(g->layout, 1u, 1u, format, g->read_size, g->tile_w);
            sizes[1] = SSDA_SOURCE_SIZE(g->layout, 20u, 1u, format, g->read_size, g->tile_w);
            sizes[2] = SSDA_SOURCE_SIZE(g->layout, IW, 3u, format, g->read_size, g->tile_w);
            sizes[3] = SSDA_SOURCE_SIZE(g->layout, IW, IH, format, g->read_size, g->tile_w);
            for (ai = 0; ai < 4; ai++) {
                ssda_source_config_t c;
                ssda_source_t s;
                test_rng_t r;
                uint32_t maxw;
                if (sizes[ai] > sizeof g_arena) {
                    continue;
                }
                c = setup(g, format, sizes[ai]);
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
                maxw = widest(&c);
                TEST_ASSERT_TRUE(maxw >= 1u);
                test_rng_seed(&r, 100u + gi * 10u + ai);
                for (k = 0; k < 300; k++) {
                    uint32_t x = test_rng_range(&r, 0, IW - 1u);
                    uint32_t y = test_rng_range(&r, 0, IH - 1u);
                    uint32_t nmax = IW - x < maxw ? IW - x : maxw;
                    uint32_t n = test_rng_range(&r, 1, nmax);
                    const uint8_t *px = NULL;
                    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, x, y, n, &px));
                    if (format == SSDA_PIX_U16) {
                        TEST_ASSERT_EQUAL_UINT(0, ((uintptr_t)px) & 1u);
                    }
                    assert_span(format, px, x, y, n);
                }
                if (maxw < IW) {
                    const uint8_t *px = NULL;
                    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_source_row(&s, 0, 0, maxw + 1u, &px));
                    TEST_ASSERT_NULL(px);
                }
                check_counts(&s);
                TEST_ASSERT_EQUAL_UINT64(300u, s.stats.hits + s.stats.misses);
            }
        }
    }
}

/* A raster image stored at the plate's pitch is read in one call per plate
   load, each byte once; padded rows take one call per row. */
static void test_sequential_rows_read_each_byte_once(void)
{
    static const geometry_t packed = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 0, 1};
    static const geometry_t padded = {SSDA_LAYOUT_RASTER, 0, 0, 0, 2, 0, 1};
    ssda_source_config_t c;
    ssda_source_t s;
    uint32_t y;
    const uint8_t *px;
    make_images(3u);
    c = setup(&packed, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, IW, 4u, 2u, 1u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    for (y = 0; y < IH; y++) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, 0, y, IW, &px));
        assert_span(SSDA_PIX_U16, px, 0, y, IW);
    }
    TEST_ASSERT_EQUAL_UINT64((uint64_t)IW * IH * 2u, s.stats.bytes_read);
    TEST_ASSERT_EQUAL_UINT64((IH + 3u) / 4u, s.stats.reads);
    TEST_ASSERT_EQUAL_UINT64((IH + 3u) / 4u, s.stats.misses);
    check_counts(&s);

    c = setup(&padded, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, IW, 4u, 2u, 1u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    for (y = 0; y < IH; y++) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, 0, y, IW, &px));
        assert_span(SSDA_PIX_U16, px, 0, y, IW);
    }
    TEST_ASSERT_EQUAL_UINT64((uint64_t)IW * IH * 2u, s.stats.bytes_read);
    TEST_ASSERT_EQUAL_UINT64(IH, s.stats.reads);
    check_counts(&s);
}

/* Granularity: every read is widened to read_size (counted as such), and
   one row of a 64-byte-granular device costs at most 2 extra granules. */
static void test_reads_are_widened_to_read_size(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 2, 0, 0, 64};
    ssda_source_config_t c;
    ssda_source_t s;
    const uint8_t *px;
    make_images(4u);
    c = setup(&g, SSDA_PIX_U8, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, IW, 1u, 1u, 64u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, 0, 7, IW, &px));
    assert_span(SSDA_PIX_U8, px, 0, 7, IW);
    TEST_ASSERT_EQUAL_UINT64(1, s.stats.reads);
    TEST_ASSERT_EQUAL_UINT64(0, s.stats.bytes_read % 64u);
    TEST_ASSERT_TRUE(s.stats.bytes_read <= ((IW + 63u) / 64u + 1u) * 64u);
    check_counts(&s);
}

/* Odd granularity (3 bytes) on an 8-bit image. */
static void test_odd_read_size_on_8_bit(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 1, 5, 0, 3};
    ssda_source_config_t c;
    ssda_source_t s;
    test_rng_t r;
    uint32_t k;
    make_images(5u);
    c = setup(&g, SSDA_PIX_U8, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 17u, 2u, 1u, 3u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    test_rng_seed(&r, 9u);
    for (k = 0; k < 200; k++) {
        uint32_t x = test_rng_range(&r, 0, IW - 17u);
        uint32_t y = test_rng_range(&r, 0, IH - 1u);
        const uint8_t *px;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, x, y, 17u, &px));
        assert_span(SSDA_PIX_U8, px, x, y, 17u);
    }
    check_counts(&s);
}

/* Plate policy: on a lattice of 3 rows, sliding down to cover row 8 starts
   at row 3 (keeping rows 3..7, reading 8..10); sliding up to cover row 2
   starts at row 0 (keeping 3..7, reading 0..2). */
static void test_plate_slides_keep_rows(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 2, 0, 1};
    const uint32_t row_bytes = IW * 2u;
    ssda_source_config_t c;
    ssda_source_t s;
    ssda_rect_t all = {0, 0, IW, IH};
    ssda_source_plan_t plan;
    const uint8_t *px;
    uint32_t y;
    make_images(6u);
    c = setup(&g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, IW, 8u, 2u, 1u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__stream_plate_plan(&s, &all, IW, 8u, 3u, 0u, &plan));
    ssda__stream_plate_use(&s, &plan);
    TEST_ASSERT_EQUAL_UINT(8, s.plate.ph);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__stream_plate_fetch(&s, 0, 0, IW, &px)); /* rows 0..7 */
    TEST_ASSERT_EQUAL_UINT64(8u * row_bytes, s.stats.bytes_read);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__stream_fetch(&s, 0, 8, IW, &px)); /* rows 3..10 */
    assert_span(SSDA_PIX_U16, px, 0, 8, IW);
    TEST_ASSERT_EQUAL_UINT(3, s.py0);
    TEST_ASSERT_EQUAL_UINT64(11u * row_bytes, s.stats.bytes_read);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__stream_fetch(&s, 3, 2, 20, &px)); /* up: rows 0..7 */
    assert_span(SSDA_PIX_U16, px, 3, 2, 20);
    TEST_ASSERT_EQUAL_UINT(0, s.py0);
    TEST_ASSERT_EQUAL_UINT64(14u * row_bytes, s.stats.bytes_read);
    for (y = 0; y < 8; y++) { /* every kept row is intact */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__stream_fetch(&s, 0, y, IW, &px));
        assert_span(SSDA_PIX_U16, px, 0, y, IW);
    }
    TEST_ASSERT_EQUAL_UINT64(3, s.stats.misses);
    /* the bottom of the region clamps the start: row 44 -> rows 37..44 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__stream_fetch(&s, 0, 44, IW, &px));
    TEST_ASSERT_EQUAL_UINT(IH - 8u, s.py0);
    assert_span(SSDA_PIX_U16, px, 0, 44, IW);
    check_counts(&s);
}

/* The same random pattern of spans, with read k failing: the call that
   fails returns the callback's code and leaves *px alone; the source then
   recovers and serves correct pixels. Every k, every geometry. */
static void run_pattern_with_failure(const geometry_t *g, uint8_t format, size_t arena,
                                     int64_t fail_at, int64_t fail_after, uint64_t *reads)
{
    ssda_source_config_t c = setup(g, format, arena);
    ssda_source_t s;
    test_rng_t r;
    uint32_t k, maxw, failed = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    maxw = widest(&c);
    g_tdev.fail_code = -1234; /* not an ssda code: must come back unchanged */
    g_tdev.fail_at_read = fail_at;
    g_tdev.fail_after = fail_after;
    test_rng_seed(&r, 77u);
    for (k = 0; k < 60; k++) {
        uint32_t x = test_rng_range(&r, 0, IW - 1u);
        uint32_t y = test_rng_range(&r, 0, IH - 1u);
        uint32_t nmax = IW - x < maxw ? IW - x : maxw;
        uint32_t n = test_rng_range(&r, 1, nmax);
        const uint8_t *px = (const uint8_t *)&failed; /* sentinel */
        uint64_t failures = g_tdev.failures;
        int err = ssda_source_row(&s, x, y, n, &px);
        if (g_tdev.failures != failures) {
            TEST_ASSERT_EQUAL_INT(-1234, err);
            TEST_ASSERT_EQUAL_PTR(&failed, px);
            failed++;
            g_tdev.fail_at_read = -1;
            g_tdev.fail_after = -1;
            err = ssda_source_row(&s, x, y, n, &px); /* recovers */
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, err);
        assert_span(format, px, x, y, n);
    }
    TEST_ASSERT_EQUAL_UINT(fail_at >= 0 || fail_after >= 0 ? 1u : 0u, failed);
    TEST_ASSERT_EQUAL_UINT64(0, g_tdev.contract_violations);
    *reads = g_tdev.reads;
}

static void test_failure_at_every_read(void)
{
    uint32_t gi;
    make_images(8u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        const geometry_t *g = &k_geoms[gi];
        size_t arena = SSDA_SOURCE_SIZE(g->layout, 24u, 4u, 2u, g->read_size, g->tile_w);
        uint64_t total, k, bytes;
        run_pattern_with_failure(g, SSDA_PIX_U16, arena, -1, -1, &total);
        TEST_ASSERT_TRUE(total > 1u);
        bytes = g_tdev.bytes_read;
        for (k = 0; k < total; k++) {
            uint64_t ignored;
            run_pattern_with_failure(g, SSDA_PIX_U16, arena, (int64_t)k, -1, &ignored);
        }
        /* byte budgets: fail the read crossing 1, bytes/2, bytes - 1 */
        for (k = 0; k < 3; k++) {
            uint64_t ignored;
            int64_t budget = k == 0 ? 0 : (k == 1 ? (int64_t)(bytes / 2u) : (int64_t)bytes - 1);
            run_pattern_with_failure(g, SSDA_PIX_U16, arena, -1, budget, &ignored);
        }
    }
}

/* A positive return from read() breaks the contract: SSDA_ERR_IO. */
static int positive_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    (void)ctx;
    (void)off;
    (void)buf;
    (void)size;
    return 3;
}

static void test_positive_read_return_is_io_error(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 0, 1};
    ssda_source_config_t c = setup(&g, SSDA_PIX_U8, 256u);
    ssda_source_t s;
    const uint8_t *px;
    c.read = positive_read;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_IO, ssda_source_row(&s, 0, 0, 4, &px));
}

/* Each configuration error, with *src untouched. */
static void expect_init_error(const ssda_source_config_t *c, int want)
{
    ssda_source_t s, before;
    memset(&s, 0x3C, sizeof s);
    before = s;
    TEST_ASSERT_EQUAL_INT(want, ssda_source_init(&s, c));
    TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
}

static void test_init_rejects_bad_configurations(void)
{
    static const geometry_t raster = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 0, 1};
    static const geometry_t tiles = {SSDA_LAYOUT_TILED, 16, 8, 0, 0, 0, 1};
    ssda_source_config_t ok = setup(&raster, SSDA_PIX_U16, 1024u);
    ssda_source_config_t t = setup(&tiles, SSDA_PIX_U16, 1024u);
    ssda_source_config_t c;
    ssda_source_t s;

    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_source_init(NULL, &ok));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_source_init(&s, NULL));
    c = ok; c.read = NULL; expect_init_error(&c, SSDA_ERR_NULL);
    c = ok; c.arena = NULL; expect_init_error(&c, SSDA_ERR_NULL);
    c = ok; c.format = 3; expect_init_error(&c, SSDA_ERR_FORMAT);
    c = ok; c.format = 0; expect_init_error(&c, SSDA_ERR_FORMAT);
    c = ok; c.layout = 2; expect_init_error(&c, SSDA_ERR_ARG);
    c = ok; c.read_size = 3; expect_init_error(&c, SSDA_ERR_ARG); /* odd for 16-bit */
    c = ok; c.read_size = SSDA_STREAM_MAX_READ_SIZE + 2u; expect_init_error(&c, SSDA_ERR_ARG);
    c = ok; c.width = 0; expect_init_error(&c, SSDA_ERR_SIZE);
    c = ok; c.height = 0; expect_init_error(&c, SSDA_ERR_SIZE);
    c = t; c.tile_w = 0; expect_init_error(&c, SSDA_ERR_SIZE);
    c = t; c.tile_h = 0; expect_init_error(&c, SSDA_ERR_SIZE);
    c = ok; c.stride = IW * 2u - 2u; expect_init_error(&c, SSDA_ERR_STRIDE);
    c = ok; c.stride = IW * 2u + 1u; expect_init_error(&c, SSDA_ERR_STRIDE);
    c = ok; c.offset = 3; expect_init_error(&c, SSDA_ERR_STRIDE);
    c = t; c.stride = 30; expect_init_error(&c, SSDA_ERR_STRIDE); /* < tile_w * 2 */
    c = t; c.tile_stride = 32u * 8u - 2u; expect_init_error(&c, SSDA_ERR_STRIDE);
    c = t; c.tile_stride = 32u * 8u + 1u; expect_init_error(&c, SSDA_ERR_STRIDE);
    /* the image must lie below 2^32 bytes of device */
    c = ok; c.offset = 0xFFFFFF00u; expect_init_error(&c, SSDA_ERR_SIZE);
    c = ok; c.stride = 0x10000000u; c.height = 17; expect_init_error(&c, SSDA_ERR_SIZE);
    c = t; c.tile_stride = 0x40000000u; expect_init_error(&c, SSDA_ERR_SIZE);
    c = ok; c.read_size = 6u; c.width = 64u; c.stride = 0u; c.height = 1u;
    c.offset = 0xFFFFFF7Eu; /* ends at 2^32 - 2, whose 6-byte granule does not fit */
    expect_init_error(&c, SSDA_ERR_SIZE);
    c = ok; c.arena = (uint8_t *)g_arena + 2; expect_init_error(&c, SSDA_ERR_BUFFER);
    c = ok; c.arena_size = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 1u, 1u, 2u, 1u, 0u) - 1u;
    expect_init_error(&c, SSDA_ERR_BUFFER);
    c = t; c.read_size = 64;
    c.arena_size = SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 1u, 1u, 2u, 64u, 16u) - 1u;
    expect_init_error(&c, SSDA_ERR_BUFFER);
    c.arena_size += 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    c = ok; c.read_size = SSDA_STREAM_MAX_READ_SIZE; /* accepted: only its arena is short */
    expect_init_error(&c, SSDA_ERR_BUFFER);
    /* largest accepted image end: exactly 2^32 */
    c = ok; c.height = 1; c.width = 64; c.offset = 0xFFFFFF80u; c.format = 2;
    c.stride = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
}

/* Worst case of the 32-bit device addresses: an image whose last byte is
   the last byte of the address space (offset + extent = 2^32), read through
   a device that maps [2^32 - 4096, 2^32) onto a small buffer. No address
   may wrap; every pixel comes back. Raster and tiled, granular reads. */
static uint8_t g_top[4096];
static int top_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    (void)ctx;
    if (off < 0xFFFFF000u || size > 0u - off) { /* below the window, or wraps */
        return -99;
    }
    memcpy(buf, g_top + (off - 0xFFFFF000u), size);
    return 0;
}

static void test_image_ending_at_the_top_of_the_address_space(void)
{
    static const uint8_t layouts[2] = {SSDA_LAYOUT_RASTER, SSDA_LAYOUT_TILED};
    uint32_t li, x, y;
    make_images(12u);
    for (li = 0; li < 2; li++) {
        ssda_view_t v, sub;
        ssda_source_config_t c;
        ssda_source_t s;
        test_source_t dev;
        uint32_t extent;
        v = image_view(SSDA_PIX_U16);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&sub, &v, 0, 0, 40, 24));
        /* lay the image out at offset 0 of g_top, then slide it to the top */
        test_source_init(&dev, g_top, sizeof g_top, 64u);
        c = test_source_config(&dev, &sub, layouts[li], 16, 8, 0u, 0u, 0u, 64u, g_arena, 2048u);
        test_source_store(&dev, &c, &sub);
        extent = test_source_extent(&c); /* multiple of 64 here */
        memmove(g_top + sizeof g_top - extent, g_top, extent);
        c.read = top_read;
        c.offset = 0u - extent; /* 2^32 - extent */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
        for (y = 0; y < 24; y++) {
            for (x = 0; x < 40; x += 13) {
                const uint8_t *px;
                uint32_t n = 40u - x < 20u ? 40u - x : 20u;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, x, y, n, &px));
                assert_span(SSDA_PIX_U16, px, x, y, n);
            }
        }
        c.offset += 2u; /* one pixel further would pass 2^32 */
        expect_init_error(&c, SSDA_ERR_SIZE);
    }
}

static void test_row_rejects_bad_arguments(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 0, 1};
    ssda_source_config_t c = setup(&g, SSDA_PIX_U8, 1024u);
    ssda_source_t s, zero;
    const uint8_t *px = NULL;
    memset(&zero, 0, sizeof zero);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_source_row(NULL, 0, 0, 1, &px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_source_row(&s, 0, 0, 1, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_source_row(&zero, 0, 0, 1, &px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_source_row(&s, 0, 0, 0, &px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_source_row(&s, IW, 0, 1, &px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_source_row(&s, 1, 0, IW, &px));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_source_row(&s, 0, IH, 1, &px));
    TEST_ASSERT_NULL(px);
    TEST_ASSERT_EQUAL_UINT64(0, g_tdev.reads);
}

/* An in-RAM source: pointers into the view, no reads, no counts. */
static void test_view_source_points_into_the_view(void)
{
    ssda_view_t v, roi;
    ssda_source_t s;
    const uint8_t *px;
    make_images(9u);
    v = image_view(SSDA_PIX_U16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&roi, &v, 5, 6, 30, 20));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&s, &roi));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, 2, 3, 28, &px));
    TEST_ASSERT_EQUAL_PTR(&g_img16[9][7], px);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_source_row(&s, 2, 3, 29, &px));
    TEST_ASSERT_EQUAL_UINT64(0, s.stats.reads + s.stats.hits + s.stats.misses);
    roi.stride = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_source_init_view(&s, &roi));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_source_init_view(NULL, &v));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_source_init_view(&s, NULL));
}

/* Arena macros are enough: a plate of w x h fits in the bytes the macro
   gives (and init accepts them). */
static void test_size_macros_are_sufficient(void)
{
    uint32_t gi, w, h;
    make_images(10u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        const geometry_t *g = &k_geoms[gi];
        for (w = 1; w <= IW; w += 23) {
            for (h = 1; h <= 9; h += 4) {
                size_t need = SSDA_SOURCE_SIZE(g->layout, w, h, 2u, g->read_size, g->tile_w);
                ssda_source_config_t c = setup(g, SSDA_PIX_U16, need);
                ssda_source_t s;
                if (need > sizeof g_arena) {
                    continue;
                }
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
                TEST_ASSERT_TRUE(ssda__stream_plate_fit_h(&s, w, 0u) >= h);
                TEST_ASSERT_TRUE(ssda__stream_plate_fit_w(&s, h, 0u) >= w);
            }
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_row_spans_equal_the_image);
    RUN_TEST(test_sequential_rows_read_each_byte_once);
    RUN_TEST(test_reads_are_widened_to_read_size);
    RUN_TEST(test_odd_read_size_on_8_bit);
    RUN_TEST(test_plate_slides_keep_rows);
    RUN_TEST(test_failure_at_every_read);
    RUN_TEST(test_positive_read_return_is_io_error);
    RUN_TEST(test_init_rejects_bad_configurations);
    RUN_TEST(test_image_ending_at_the_top_of_the_address_space);
    RUN_TEST(test_row_rejects_bad_arguments);
    RUN_TEST(test_view_source_points_into_the_view);
    RUN_TEST(test_size_macros_are_sufficient);
    return UNITY_END();
}
