/*
 * test_track_rows.c - grid tracking over row sources that fetch spans
 * through a callback (as a block-streamed image does): same vectors and
 * statistics as in RAM, spans only inside the image and used only until the
 * next fetch, fetch errors passed back unchanged, argument errors of the
 * row sources.
 */
#include <string.h>
#include "unity.h"
#include "track_rows.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#define IMG 96u
#define NMAX 64u

static uint16_t g_first[IMG * IMG];
static uint16_t g_second[IMG * IMG];
static uint64_t g_work[(SSDA_TRACK_WORK_SIZE(32, 32, 16, 16) + 7u) / 8u];
static ssda_track_vector_t g_ram[NMAX];
static ssda_track_vector_t g_out[NMAX];

/* An emulated streamed image: each fetch copies the span into the source's
   one span buffer (overwriting the previous span, so a caller that kept an
   old span would read wrong pixels), counts fetches and pixels, checks that
   the span lies inside the image, and fails with `fail_code` on fetch
   number `fail_at` (0 = never). */
typedef struct {
    const uint16_t *pixels;
    uint32_t width, height, stride_px;
    uint8_t format;
    uint16_t span[IMG];
    uint32_t fetches, pixels_fetched, fail_at, outside, single;
    int fail_code;
} fake_src_t;

static int fake_fetch(void *ctx, uint32_t x, uint32_t y, uint32_t n, const uint8_t **px)
{
    fake_src_t *s = (fake_src_t *)ctx;
    uint32_t i;
    s->fetches++;
    if (s->fail_at != 0u && s->fetches == s->fail_at) {
        return s->fail_code;
    }
    if (n == 0u || x + n > s->width || y >= s->height) {
        s->outside++;
        return -999;
    }
    if (n == 1u) {
        s->single++;
    }
    s->pixels_fetched += n;
    for (i = 0; i < n; i++) {
        uint16_t v = s->pixels[(size_t)y * s->stride_px + x + i];
        if (s->format == SSDA_PIX_U8) {
            ((uint8_t *)s->span)[i] = (uint8_t)v;
        } else {
            s->span[i] = v;
        }
    }
    *px = (const uint8_t *)s->span;
    return SSDA_OK;
}

static void fake_init(fake_src_t *s, ssda__rows_t *rows, const uint16_t *pixels, uint8_t format)
{
    memset(s, 0, sizeof *s);
    s->pixels = pixels;
    s->width = IMG;
    s->height = IMG;
    s->stride_px = IMG;
    s->format = format;
    memset(rows, 0, sizeof *rows);
    rows->base = NULL;
    rows->fetch = fake_fetch;
    rows->ctx = s;
    rows->width = IMG;
    rows->height = IMG;
    rows->format = format;
}

/* 8-bit copies for the 8-bit runs (the fake source narrows on fetch). */
static uint8_t g_first8[IMG * IMG];
static uint8_t g_second8[IMG * IMG];

/* SECOND = FIRST moved by a field that varies per 16 x 16 block, a fill
   value in one place of each image. */
static void make_pair(void)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, 21);
    test_fill_texture_u16(g_first, IMG, IMG, IMG, 250u, &r);
    for (y = 0; y < IMG; y++) {
        for (x = 0; x < IMG; x++) {
            int32_t dx = (int32_t)((x / 16u) % 3u) - 1, dy = (int32_t)((y / 16u) % 5u) - 2;
            int32_t sx = (int32_t)x - dx, sy = (int32_t)y - dy;
            g_second[y * IMG + x] = (sx >= 0 && sy >= 0 && sx < (int32_t)IMG && sy < (int32_t)IMG)
                                        ? g_first[(uint32_t)sy * IMG + (uint32_t)sx]
                                        : 0u;
        }
    }
    g_first[50u * IMG + 20u] = 255u;
    g_second[70u * IMG + 70u] = 255u;
    for (x = 0; x < IMG * IMG; x++) {
        g_first8[x] = (uint8_t)g_first[x];
        g_second8[x] = (uint8_t)g_second[x];
    }
}

static void assert_same_stats(const ssda_track_stats_t *x, const ssda_track_stats_t *y)
{
    TEST_ASSERT_EQUAL_UINT64(x->pixel_ops, y->pixel_ops);
    TEST_ASSERT_EQUAL_UINT64(x->positions, y->positions);
    TEST_ASSERT_EQUAL_UINT64(x->completed, y->completed);
    TEST_ASSERT_EQUAL_UINT64(x->check_pixels, y->check_pixels);
    TEST_ASSERT_EQUAL_UINT32(x->windows, y->windows);
    TEST_ASSERT_EQUAL_UINT32(x->ok, y->ok);
    TEST_ASSERT_EQUAL_UINT32(x->excluded, y->excluded);
    TEST_ASSERT_EQUAL_UINT32(x->masked, y->masked);
    TEST_ASSERT_EQUAL_UINT32(x->edge, y->edge);
}

static void assert_same(const ssda_track_vector_t *x, const ssda_track_vector_t *y, uint32_t n)
{
    uint32_t k;
    for (k = 0; k < n; k++) {
        TEST_ASSERT_EQUAL_UINT8(x[k].status, y[k].status);
        TEST_ASSERT_EQUAL_INT32(x[k].dx, y[k].dx);
        TEST_ASSERT_EQUAL_INT32(x[k].dy, y[k].dy);
        TEST_ASSERT_EQUAL_UINT64(x[k].sad, y[k].sad);
        TEST_ASSERT_EQUAL_UINT16(x[k].x, y[k].x);
        TEST_ASSERT_EQUAL_UINT16(x[k].y, y[k].y);
        TEST_ASSERT_EQUAL(x[k].exact, y[k].exact);
        TEST_ASSERT_EQUAL_INT32(x[k].sub_dx_q8, y[k].sub_dx_q8);
        TEST_ASSERT_EQUAL_INT32(x[k].sub_dy_q8, y[k].sub_dy_q8);
        TEST_ASSERT_EQUAL_UINT32(x[k].texture_q8, y[k].texture_q8);
        TEST_ASSERT_EQUAL_UINT16(x[k].unique_q8, y[k].unique_q8);
    }
}

/* Configurations exercised: prediction modes, bounds, mask, exclusion,
   overlapping windows. */
static void config_case(ssda_track_config_t *cfg, uint32_t c)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->flags = SSDA_TRACK_MASK | ((c & 1u) ? SSDA_TRACK_EXCLUDE : 0u);
    cfg->mask_value = 255;
    cfg->texture_threshold = 140;
    cfg->predict = (uint8_t)(c % 3u);
    if (c & 2u) {
        cfg->match.flags = SSDA_MATCH_BOUNDS;
        cfg->flags |= SSDA_TRACK_UNIQUE; /* its list after the bounds tables */
        cfg->match.work = g_work;
        cfg->match.work_size = sizeof g_work;
    }
    if (c & 4u) {
        cfg->step_x = 12;
        cfg->step_y = 10;
        cfg->match.order = SSDA_ORDER_SPREAD;
    }
}

static void test_streamed_equals_ram(void)
{
    uint32_t c, fmt;
    make_pair();
    for (fmt = 0; fmt < 2u; fmt++) {
        const uint8_t format = fmt ? SSDA_PIX_U16 : SSDA_PIX_U8;
        for (c = 0; c < 8u; c++) {
            ssda_track_config_t cfg;
            ssda_track_stats_t st_ram, st;
            ssda_track_grid_t g;
            ssda_view_t a, b;
            ssda__rows_t ra, rb;
            fake_src_t fa, fb;
            config_case(&cfg, c);
            if (fmt) {
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_second, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
            } else {
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first8, IMG, IMG, IMG, SSDA_PIX_U8));
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_second8, IMG, IMG, IMG, SSDA_PIX_U8));
            }
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&cfg, IMG, IMG, &g));
            TEST_ASSERT_TRUE(g.count <= NMAX);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_ram, NMAX, &st_ram));
            TEST_ASSERT_TRUE(st_ram.ok > g.count / 3u);
            TEST_ASSERT_TRUE(st_ram.masked > 0u);

            fake_init(&fa, &ra, g_first, format);
            fake_init(&fb, &rb, g_second, format);
            memset(g_out, 0, sizeof g_out);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__track_rows(&ra, &rb, &cfg, g_out, NMAX, &st));
            assert_same(g_ram, g_out, g.count);
            assert_same_stats(&st_ram, &st);
            TEST_ASSERT_EQUAL_UINT32(0, fa.outside + fb.outside);
            /* the mask and texture tests fetch whole window / area rows */
            TEST_ASSERT_EQUAL_UINT32(0, fa.single + fb.single);
            TEST_ASSERT_TRUE(fa.fetches > 0u && fb.fetches > 0u);
        }
    }
}

/* A failing fetch on either image, at any point, is returned unchanged;
   stats are not written, and out holds a prefix of the good result. */
static void test_fetch_errors_pass_through(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st, st0;
    ssda__rows_t ra, rb;
    fake_src_t fa, fb;
    uint32_t side, n, total[2];
    make_pair();
    config_case(&cfg, 3);
    fake_init(&fa, &ra, g_first, SSDA_PIX_U16);
    fake_init(&fb, &rb, g_second, SSDA_PIX_U16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__track_rows(&ra, &rb, &cfg, g_ram, NMAX, NULL));
    total[0] = fa.fetches;
    total[1] = fb.fetches;
    for (side = 0; side < 2u; side++) {
        uint32_t step = total[side] / 40u + 1u;
        for (n = 1; n <= total[side]; n += step) {
            uint32_t k;
            bool written = true;
            fake_init(&fa, &ra, g_first, SSDA_PIX_U16);
            fake_init(&fb, &rb, g_second, SSDA_PIX_U16);
            (side ? &fb : &fa)->fail_at = n;
            (side ? &fb : &fa)->fail_code = -1234;
            memset(g_out, 0xA5, sizeof g_out);
            memset(&st, 0x5A, sizeof st);
            memcpy(&st0, &st, sizeof st);
            TEST_ASSERT_EQUAL_INT(-1234, ssda__track_rows(&ra, &rb, &cfg, g_out, NMAX, &st));
            TEST_ASSERT_EQUAL_MEMORY(&st0, &st, sizeof st);
            for (k = 0; k < NMAX; k++) {
                uint8_t probe[sizeof(ssda_track_vector_t)];
                memset(probe, 0xA5, sizeof probe);
                if (memcmp(&g_out[k], probe, sizeof probe) == 0) {
                    written = false; /* untouched from here on */
                } else {
                    TEST_ASSERT_TRUE(written);
                    assert_same(&g_ram[k], &g_out[k], 1);
                }
            }
        }
    }
}

/* One window with every test and the whole quality (mask, flat test,
   search with uniqueness, the sub-pixel fit's own sums): a fetch that
   fails at any point of it, on either image, comes back unchanged and
   writes nothing. */
static void test_one_window_fails_at_every_fetch(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st, st0;
    ssda__rows_t ra, rb;
    fake_src_t fa, fb;
    uint32_t side, n, total[2], fits;
    make_pair();
    memset(&cfg, 0, sizeof cfg);
    cfg.flags = SSDA_TRACK_MASK | SSDA_TRACK_UNIQUE;
    cfg.mask_value = 255;
    cfg.roi_x = 40;
    cfg.roi_y = 24;
    cfg.roi_w = 16;
    cfg.roi_h = 16;
    cfg.match.work = g_work;
    cfg.match.work_size = sizeof g_work;
    for (fits = 0; fits < 2u; fits++) {
        /* with bounds the search's completed neighbours serve the fit; without
           uniqueness the fit sums all four itself */
        cfg.match.flags = fits ? 0u : SSDA_MATCH_BOUNDS;
        cfg.flags = (uint8_t)(fits ? SSDA_TRACK_MASK : (SSDA_TRACK_MASK | SSDA_TRACK_UNIQUE));
        fake_init(&fa, &ra, g_first, SSDA_PIX_U8);
        fake_init(&fb, &rb, g_second, SSDA_PIX_U8);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__track_rows(&ra, &rb, &cfg, g_ram, NMAX, NULL));
        TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_ram[0].status);
        TEST_ASSERT_TRUE(g_ram[0].texture_q8 > 0u);
        total[0] = fa.fetches;
        total[1] = fb.fetches;
        for (side = 0; side < 2u; side++) {
#ifdef SSDA_TEST_SMALL
            const uint32_t step = total[side] / 60u + 1u; /* emulated boards: a sample */
#else
            const uint32_t step = 1u;
#endif
            for (n = 1; n <= total[side]; n += step) {
                fake_init(&fa, &ra, g_first, SSDA_PIX_U8);
                fake_init(&fb, &rb, g_second, SSDA_PIX_U8);
                (side ? &fb : &fa)->fail_at = n;
                (side ? &fb : &fa)->fail_code = -77;
                memset(g_out, 0xA5, sizeof g_out);
                memset(&st, 0x5A, sizeof st);
                memcpy(&st0, &st, sizeof st);
                TEST_ASSERT_EQUAL_INT(-77, ssda__track_rows(&ra, &rb, &cfg, g_out, NMAX, &st));
                TEST_ASSERT_EQUAL_MEMORY(&st0, &st, sizeof st);
                TEST_ASSERT_EACH_EQUAL_HEX8(0xA5, g_out, sizeof g_out[0]);
            }
        }
    }
}

/* The stream layer's strips: solving the grid in vertical strips of grid
   columns, left to right, gives the whole-grid vectors in exact modes; with
   no prediction or the left predictor also the same work. */
static void test_strips_equal_whole_grid(void)
{
    uint32_t c, width;
    make_pair();
    for (c = 0; c < 8u; c++) {
        for (width = 1; width <= 4u; width++) {
            ssda_track_config_t cfg;
            ssda_track_stats_t st_ram, acc;
            ssda_track_plan_t plan;
            ssda_view_t a, b;
            ssda__rows_t ra, rb;
            fake_src_t fa, fb;
            uint32_t col0;
            config_case(&cfg, c);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_second, IMG, IMG, IMG * 2u, SSDA_PIX_U16));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_ram, NMAX, &st_ram));
            fake_init(&fa, &ra, g_first, SSDA_PIX_U16);
            fake_init(&fb, &rb, g_second, SSDA_PIX_U16);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__track_plan(&cfg, SSDA_PIX_U16, IMG, IMG, IMG, IMG, &plan));
            memset(&acc, 0, sizeof acc);
            memset(g_out, 0xA5, sizeof g_out);
            for (col0 = 0; col0 < plan.grid.cols; col0 += width) {
                uint32_t col1 = col0 + width < plan.grid.cols ? col0 + width : plan.grid.cols;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__track_strip(&ra, &rb, &plan, col0, col1, g_out, &acc));
            }
            assert_same(g_ram, g_out, plan.grid.count);
            TEST_ASSERT_EQUAL_UINT32(st_ram.windows, acc.windows);
            TEST_ASSERT_EQUAL_UINT32(st_ram.ok, acc.ok);
            TEST_ASSERT_EQUAL_UINT32(st_ram.masked, acc.masked);
            TEST_ASSERT_EQUAL_UINT32(st_ram.excluded, acc.excluded);
            TEST_ASSERT_EQUAL_UINT32(st_ram.edge, acc.edge);
            TEST_ASSERT_EQUAL_UINT64(st_ram.check_pixels, acc.check_pixels);
            if (cfg.predict != SSDA_TRACK_PREDICT_MEDIAN) {
                TEST_ASSERT_EQUAL_UINT64(st_ram.pixel_ops, acc.pixel_ops);
                TEST_ASSERT_EQUAL_UINT64(st_ram.positions, acc.positions);
                TEST_ASSERT_EQUAL_UINT64(st_ram.completed, acc.completed);
            }
        }
    }
}

static void test_row_source_argument_errors(void)
{
    ssda_track_config_t cfg;
    ssda_track_stats_t st, st0;
    ssda__rows_t ra, rb, bad;
    fake_src_t fa, fb;
    memset(&cfg, 0, sizeof cfg);
    fake_init(&fa, &ra, g_first, SSDA_PIX_U16);
    fake_init(&fb, &rb, g_second, SSDA_PIX_U16);
    memset(g_out, 0xA5, sizeof g_out);
    memcpy(g_ram, g_out, sizeof g_out);
    memset(&st, 0x5A, sizeof st);
    memcpy(&st0, &st, sizeof st);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda__track_rows(NULL, &rb, &cfg, g_out, NMAX, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda__track_rows(&ra, NULL, &cfg, g_out, NMAX, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda__track_rows(&ra, &rb, &cfg, NULL, NMAX, &st));
    bad = ra; bad.fetch = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda__track_rows(&bad, &rb, &cfg, g_out, NMAX, &st));
    bad = rb; bad.format = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda__track_rows(&ra, &bad, &cfg, g_out, NMAX, &st));
    bad = rb; bad.format = SSDA_PIX_U8;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda__track_rows(&ra, &bad, &cfg, g_out, NMAX, &st));
    bad = rb; bad.height = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda__track_rows(&ra, &bad, &cfg, g_out, NMAX, &st));
    bad = rb; bad.width = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda__track_rows(&ra, &bad, &cfg, g_out, NMAX, &st));
    bad = ra; bad.base = (const uint8_t *)g_first; bad.stride = IMG * 2u - 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda__track_rows(&bad, &rb, &cfg, g_out, NMAX, &st));
    bad.stride = IMG * 2u + 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda__track_rows(&bad, &rb, &cfg, g_out, NMAX, &st));
    bad.stride = IMG * 2u;
    bad.base = (const uint8_t *)g_first + 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda__track_rows(&bad, &rb, &cfg, g_out, NMAX, &st));
    bad.base = (const uint8_t *)g_first;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda__track_rows(&ra, &rb, &cfg, g_out, 35, &st));
    TEST_ASSERT_EQUAL_MEMORY(g_ram, g_out, sizeof g_out);
    TEST_ASSERT_EQUAL_MEMORY(&st0, &st, sizeof st);
    TEST_ASSERT_EQUAL_UINT32(0, fa.fetches + fb.fetches);
    /* a RAM source next to a streamed one is fine */
    bad.stride = IMG * 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda__track_rows(&bad, &rb, NULL, g_out, 36, &st));
    TEST_ASSERT_EQUAL_UINT32(36, st.windows);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_streamed_equals_ram);
    RUN_TEST(test_fetch_errors_pass_through);
    RUN_TEST(test_one_window_fails_at_every_fetch);
    RUN_TEST(test_strips_equal_whole_grid);
    RUN_TEST(test_row_source_argument_errors);
    return UNITY_END();
}
