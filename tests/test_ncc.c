/*
 * test_ncc.c - the correlation search (ssda/ncc.h) against independent
 * references (tests/support/test_ncc_ref.c: exhaustive exact integer search,
 * double-precision rho): argmax and tie rule in every mode, 8 and 16 bit,
 * odd window shapes and strides; rho in Q2.30; invariance to gain and
 * offset; inverted contrast; flat windows and areas; the neighbourhood;
 * argument errors leaving the result untouched.
 */
#include <string.h>
#include "unity.h"
#include "ssda/ncc.h"
#include "test_image.h"
#include "test_ncc_ref.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

#define AW 56u
#define AH 44u
#define MAXW 24u
#ifdef SSDA_TEST_SMALL
#define TRIALS 3u
#define FLAG_STEP 3u /* flag sets 0, 3, 6, 9, 12, 15 */
#else
#define TRIALS 60u
#define FLAG_STEP 1u
#endif

static uint8_t g_a8[AH][AW + 3u];
static uint8_t g_w8[MAXW][MAXW + 5u];
static uint16_t g_a16[AH][AW + 3u];
static uint16_t g_w16[MAXW][MAXW + 5u];
/* enough for every window shape used: (win_h + 2) * nx * 12 + groups * 16
   with at most MAXW rows and groups, AW positions per row */
static uint64_t g_work[((MAXW + 2u) * AW * 12u + MAXW * 16u) / 8u + 1u];

static ssda_ncc_config_t config(uint8_t metric, uint8_t flags)
{
    ssda_ncc_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.metric = metric;
    cfg.flags = flags;
    cfg.work = g_work;
    cfg.work_size = sizeof g_work;
    return cfg;
}

/* Window cut from the area at (wx, wy), then changed by gain/offset and noise
   so the match is not perfect. */
static void make_pair(test_rng_t *r, bool u16, uint32_t ww, uint32_t wh, uint32_t wx,
                      uint32_t wy, uint32_t noise, ssda_view_t *av, ssda_view_t *wv)
{
    uint32_t x, y;
    if (u16) {
        test_fill_texture_u16(&g_a16[0][0], AW, AH, AW + 3u, 65535u, r);
        for (y = 0; y < wh; y++) {
            for (x = 0; x < ww; x++) {
                int32_t v = (int32_t)g_a16[wy + y][wx + x] / 2 + 9000 +
                            (int32_t)test_rng_range(r, 0, noise * 256u);
                g_w16[y][x] = (uint16_t)(v > 65535 ? 65535 : v);
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(av, g_a16, AW, AH, (AW + 3u) * 2u, SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(wv, g_w16, (uint16_t)ww, (uint16_t)wh,
                                                      (MAXW + 5u) * 2u, SSDA_PIX_U16));
    } else {
        test_fill_texture_u8(&g_a8[0][0], AW, AH, AW + 3u, r);
        for (y = 0; y < wh; y++) {
            for (x = 0; x < ww; x++) {
                int32_t v = (int32_t)g_a8[wy + y][wx + x] * 3 / 4 + 20 +
                            (int32_t)test_rng_range(r, 0, noise);
                g_w8[y][x] = (uint8_t)(v > 255 ? 255 : v);
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(av, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(wv, g_w8, (uint16_t)ww, (uint16_t)wh,
                                                      MAXW + 5u, SSDA_PIX_U8));
    }
}

static void check_rho(const ssda_view_t *av, const ssda_view_t *wv, uint32_t x, uint32_t y,
                      int32_t rho_q30)
{
    int64_t ref = test_ncc_q30(av, wv, x, y);
    int64_t d = ref - rho_q30;
    TEST_ASSERT_TRUE_MESSAGE(d >= -1 && d <= 1, "rho_q30 against the double reference");
}

/* Every flag combination against the exhaustive reference. */
static void check_all_modes(const ssda_view_t *av, const ssda_view_t *wv, test_rng_t *r)
{
    uint8_t metric, flags;
    const bool flat = test_ncc_key(wv, wv, 0, 0).var == 0u; /* e.g. 1 x 1 */
    for (metric = 0; metric <= SSDA_NCC_ABS; metric++) {
        uint32_t rx = 0, ry = 0, dx = 0, dy = 0;
        const uint32_t nx = av->width - wv->width + 1u, ny = av->height - wv->height + 1u;
        const int32_t px = (int32_t)test_rng_range(r, 0, nx + 4u) - 2;
        const int32_t py = (int32_t)test_rng_range(r, 0, ny + 4u) - 2;
        const uint16_t radius = (uint16_t)test_rng_range(r, 0, 9);
        const int64_t cx = px < 0 ? 0 : (px >= (int32_t)nx ? (int64_t)nx - 1 : (int64_t)px);
        const int64_t cy = py < 0 ? 0 : (py >= (int32_t)ny ? (int64_t)ny - 1 : (int64_t)py);
        test_ncc_best(av, wv, metric == SSDA_NCC_ABS, 0, 0, -1, &rx, &ry);
        test_ncc_best(av, wv, metric == SSDA_NCC_ABS, cx, cy, (int64_t)radius * radius, &dx, &dy);
        for (flags = 0; flags < 16u; flags += FLAG_STEP) {
            ssda_ncc_config_t cfg = config(metric, flags);
            ssda_ncc_result_t res;
            const bool disk = (flags & SSDA_NCC_DISK) != 0u;
            cfg.predict_x = px;
            cfg.predict_y = py;
            cfg.radius = radius;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(av, wv, &cfg, &res));
            TEST_ASSERT_EQUAL_UINT16(disk ? dx : rx, res.x);
            TEST_ASSERT_EQUAL_UINT16(disk ? dy : ry, res.y);
            check_rho(av, wv, res.x, res.y, res.rho_q30);
            TEST_ASSERT_EQUAL_UINT8(flat ? SSDA_NCC_FLAT_WINDOW : 0, res.flags);
            if (!disk && !flat) {
                TEST_ASSERT_EQUAL_UINT32(nx * ny, res.positions);
            }
            TEST_ASSERT_TRUE(res.completed <= res.positions);
            if ((flags & SSDA_NCC_FULL) != 0u) {
                TEST_ASSERT_EQUAL_UINT32(res.positions, res.completed);
            }
        }
    }
}

static void test_argmax_equals_exhaustive_search_8bit(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 11u);
    for (t = 0; t < TRIALS; t++) {
        ssda_view_t av, wv;
        uint32_t ww = test_rng_range(&r, 1, MAXW), wh = test_rng_range(&r, 1, MAXW);
        uint32_t wx = test_rng_range(&r, 0, AW - ww), wy = test_rng_range(&r, 0, AH - wh);
        make_pair(&r, false, ww, wh, wx, wy, test_rng_range(&r, 0, 40), &av, &wv);
        check_all_modes(&av, &wv, &r);
    }
}

static void test_argmax_equals_exhaustive_search_16bit(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 12u);
    for (t = 0; t < TRIALS; t++) {
        ssda_view_t av, wv;
        uint32_t ww = test_rng_range(&r, 1, MAXW), wh = test_rng_range(&r, 1, MAXW);
        uint32_t wx = test_rng_range(&r, 0, AW - ww), wy = test_rng_range(&r, 0, AH - wh);
        make_pair(&r, true, ww, wh, wx, wy, test_rng_range(&r, 0, 40), &av, &wv);
        check_all_modes(&av, &wv, &r);
    }
}

/* Binary images (0 / 255, half of each): a window that is an inverted
   patch of the area has a dot product near 0 at its match, and the
   early-exit bound's lower side (lb) goes below 0 on the way, where |rho|
   must keep the position going. Every mode against the exhaustive search.
   (A planted bug that cut such positions passed every other test: on
   textured images with a mean level lb stays positive.) */
static void test_argmax_inverted_binary_images(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 13u);
    for (t = 0; t < TRIALS; t++) {
        ssda_view_t av, wv;
        const uint32_t ww = test_rng_range(&r, 6, MAXW), wh = test_rng_range(&r, 12, MAXW);
        const uint32_t wx = test_rng_range(&r, 0, AW - ww), wy = test_rng_range(&r, 0, AH - wh);
        uint32_t x, y;
        for (y = 0; y < AH; y++) {
            for (x = 0; x < AW; x++) {
                g_a8[y][x] = (uint8_t)(test_rng_range(&r, 0, 1) * 255u);
            }
        }
        for (y = 0; y < wh; y++) {
            for (x = 0; x < ww; x++) {
                g_w8[y][x] = (uint8_t)(255u - g_a8[wy + y][wx + x]);
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_w8, (uint16_t)ww, (uint16_t)wh,
                                                      MAXW + 5u, SSDA_PIX_U8));
        check_all_modes(&av, &wv, &r);
        {
            ssda_ncc_config_t cfg = config(SSDA_NCC_ABS, 0);
            ssda_ncc_result_t res;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
            TEST_ASSERT_EQUAL_UINT16(wx, res.x);
            TEST_ASSERT_EQUAL_UINT16(wy, res.y);
            TEST_ASSERT_EQUAL_INT32(-SSDA_NCC_ONE_Q30, res.rho_q30);
        }
    }
}

/* A window that is a gain and offset of the area where it was cut matches
   with rho = 1 exactly, at that place; early exit does less work. */
static void test_gain_offset_gives_rho_one_with_less_work(void)
{
    test_rng_t r;
    ssda_view_t av, wv;
    ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, 0);
    ssda_ncc_result_t fast, full;
    uint32_t x, y;
    test_rng_seed(&r, 3u);
    test_fill_texture_u8(&g_a8[0][0], AW, AH, AW + 3u, &r);
    for (y = 0; y < 16u; y++) {
        for (x = 0; x < 16u; x++) {
            g_w8[y][x] = (uint8_t)(g_a8[21u + y][30u + x] / 2u + 100u);
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_w8, 16, 16, MAXW + 5u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &fast));
    cfg.flags = SSDA_NCC_FULL;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &full));
    TEST_ASSERT_EQUAL_UINT16(30, fast.x);
    TEST_ASSERT_EQUAL_UINT16(21, fast.y);
    TEST_ASSERT_EQUAL_UINT16(30, full.x);
    TEST_ASSERT_EQUAL_UINT16(21, full.y);
    /* halving loses the low bit: not exactly linear, so just below 1 */
    TEST_ASSERT_TRUE(fast.rho_q30 > SSDA_NCC_ONE_Q30 - SSDA_NCC_ONE_Q30 / 100);
    TEST_ASSERT_EQUAL_INT32(full.rho_q30, fast.rho_q30);
    TEST_ASSERT_TRUE(fast.completed < full.completed);
    TEST_ASSERT_TRUE(fast.pixel_ops < full.pixel_ops);
    /* an exact affine copy (gain 2, offset 7): rho is exactly 1 */
    for (y = 0; y < 16u; y++) {
        for (x = 0; x < 16u; x++) {
            g_w8[y][x] = (uint8_t)(g_a8[21u + y][30u + x] / 2u);
            g_a8[21u + y][30u + x] = (uint8_t)(g_w8[y][x] * 2u + 7u);
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &full));
    TEST_ASSERT_EQUAL_INT32(SSDA_NCC_ONE_Q30, full.rho_q30);
    TEST_ASSERT_EQUAL_UINT16(30, full.x);
    TEST_ASSERT_EQUAL_UINT16(21, full.y);
}

/* An inverted copy: rho = -1 there; ABS finds it, RHO does not. */
static void test_inverted_contrast_found_by_abs_only(void)
{
    test_rng_t r;
    ssda_view_t av, wv;
    ssda_ncc_config_t cfg = config(SSDA_NCC_ABS, 0);
    ssda_ncc_result_t res;
    uint32_t x, y;
    test_rng_seed(&r, 4u);
    test_fill_texture_u8(&g_a8[0][0], AW, AH, AW + 3u, &r);
    for (y = 0; y < 12u; y++) {
        for (x = 0; x < 10u; x++) {
            g_w8[y][x] = (uint8_t)(255u - g_a8[9u + y][40u + x]);
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_w8, 10, 12, MAXW + 5u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(40, res.x);
    TEST_ASSERT_EQUAL_UINT16(9, res.y);
    TEST_ASSERT_EQUAL_INT32(-SSDA_NCC_ONE_Q30, res.rho_q30);
    cfg.metric = SSDA_NCC_RHO;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_FALSE(res.x == 40u && res.y == 9u);
    TEST_ASSERT_TRUE(res.rho_q30 < SSDA_NCC_ONE_Q30);
}

/* Equal rho at two places: the smaller y, then the smaller x, wins, also
   when the later one is predicted and evaluated first; +rho and -rho tie
   under ABS. */
static void test_tie_rule(void)
{
    ssda_view_t av, wv;
    ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, 0);
    ssda_ncc_result_t res;
    uint32_t x, y;
    test_rng_t r;
    test_rng_seed(&r, 5u);
    memset(g_a8, 50, sizeof g_a8);
    for (y = 0; y < 6u; y++) {
        for (x = 0; x < 6u; x++) {
            g_w8[y][x] = (uint8_t)test_rng_range(&r, 0, 255);
            g_a8[20u + y][30u + x] = g_w8[y][x];         /* later copy */
            g_a8[20u + y][4u + x] = g_w8[y][x];          /* same row, left */
            g_a8[30u + y][2u + x] = (uint8_t)(255u - g_w8[y][x]); /* inverted, below */
            g_a8[5u + y][45u + x] = (uint8_t)(255u - g_w8[y][x]); /* inverted, above */
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_w8, 6, 6, MAXW + 5u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(4, res.x);
    TEST_ASSERT_EQUAL_UINT16(20, res.y);
    cfg.flags = SSDA_NCC_PREDICT;
    cfg.predict_x = 30;
    cfg.predict_y = 20;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(4, res.x);
    TEST_ASSERT_EQUAL_UINT16(20, res.y);
    TEST_ASSERT_EQUAL_INT32(SSDA_NCC_ONE_Q30, res.rho_q30);
    cfg.metric = SSDA_NCC_ABS;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(45, res.x);
    TEST_ASSERT_EQUAL_UINT16(5, res.y);
    TEST_ASSERT_EQUAL_INT32(-SSDA_NCC_ONE_Q30, res.rho_q30);
}

/* A flat window: rho 0 everywhere, the first position scanned, flagged. */
static void test_flat_window(void)
{
    test_rng_t r;
    ssda_view_t av, wv;
    ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, SSDA_NCC_AROUND);
    ssda_ncc_result_t res;
    int32_t rho = 5;
    test_rng_seed(&r, 6u);
    test_fill_texture_u8(&g_a8[0][0], AW, AH, AW + 3u, &r);
    memset(g_w8, 77, sizeof g_w8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_w8, 8, 8, MAXW + 5u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT8(SSDA_NCC_FLAT_WINDOW, res.flags);
    TEST_ASSERT_EQUAL_UINT16(0, res.x);
    TEST_ASSERT_EQUAL_UINT16(0, res.y);
    TEST_ASSERT_EQUAL_INT32(0, res.rho_q30);
    TEST_ASSERT_EQUAL_INT32(SSDA_NCC_NONE, res.around_q30[0]);
    TEST_ASSERT_EQUAL_INT32(0, res.around_q30[8]);
    /* in a disk: its first row, leftmost */
    cfg.flags = SSDA_NCC_DISK;
    cfg.predict_x = 20;
    cfg.predict_y = 10;
    cfg.radius = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(20, res.x);
    TEST_ASSERT_EQUAL_UINT16(7, res.y);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_at(&av, &wv, 3, 4, &rho));
    TEST_ASSERT_EQUAL_INT32(0, rho);
}

/* Flat placements have rho 0 and are decided without products; a window
   anti-correlated with everything but a flat area still returns a flat
   place (rho 0 beats negative rho). */
static void test_flat_area_positions(void)
{
    ssda_view_t av, wv;
    ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, 0);
    ssda_ncc_result_t res;
    uint32_t x, y;
    memset(g_a8, 0, sizeof g_a8);
    for (y = 0; y < 8u; y++) {
        for (x = 0; x < 8u; x++) {
            g_w8[y][x] = (uint8_t)(x < 4u ? 200u : 10u);
        }
    }
    /* a vertical edge dark-to-bright: anti-correlated with the window */
    for (y = 0; y < AH; y++) {
        for (x = 20u; x < AW; x++) {
            g_a8[y][x] = 180u;
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_a8, 30, 20, AW + 3u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_w8, 8, 8, MAXW + 5u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(0, res.x);
    TEST_ASSERT_EQUAL_UINT16(0, res.y);
    TEST_ASSERT_EQUAL_INT32(0, res.rho_q30);
    /* positions straddling the edge are the only ones with products */
    TEST_ASSERT_EQUAL_UINT32(7u * 13u, res.completed);
    /* a flat predicted position: considered, not summed */
    cfg.flags = SSDA_NCC_PREDICT;
    cfg.predict_x = 1;
    cfg.predict_y = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(0, res.x);
    TEST_ASSERT_EQUAL_UINT16(0, res.y);
    TEST_ASSERT_EQUAL_UINT32(7u * 13u, res.completed);
    TEST_ASSERT_EQUAL_UINT32(23u * 13u, res.positions);
    cfg.flags = 0;
    cfg.metric = SSDA_NCC_ABS;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(16, res.x);
    TEST_ASSERT_EQUAL_UINT16(0, res.y);
    TEST_ASSERT_EQUAL_INT32(-SSDA_NCC_ONE_Q30, res.rho_q30);
}

/* The neighbourhood equals ssda_ncc_at at each neighbour. */
static void test_around_matches_probe(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 7u);
    for (t = 0; t < 8u; t++) {
        ssda_view_t av, wv;
        ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, SSDA_NCC_AROUND);
        ssda_ncc_result_t res;
        uint32_t wx = t < 2u ? 0u : test_rng_range(&r, 0, AW - 12u);
        uint32_t wy = t == 1u ? AH - 12u : test_rng_range(&r, 0, AH - 12u);
        uint32_t i, j;
        make_pair(&r, (t & 1u) != 0u, 12, 12, wx, wy, 5, &av, &wv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
        TEST_ASSERT_EQUAL_INT32(res.rho_q30, res.around_q30[4]);
        for (j = 0; j < 3u; j++) {
            for (i = 0; i < 3u; i++) {
                int32_t x = (int32_t)res.x + (int32_t)i - 1, y = (int32_t)res.y + (int32_t)j - 1;
                int32_t rho = 0;
                if (x < 0 || y < 0 || x > (int32_t)(AW - 12u) || y > (int32_t)(AH - 12u)) {
                    TEST_ASSERT_EQUAL_INT32(SSDA_NCC_NONE, res.around_q30[j * 3u + i]);
                    continue;
                }
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_at(&av, &wv, (uint16_t)x, (uint16_t)y, &rho));
                TEST_ASSERT_EQUAL_INT32(rho, res.around_q30[j * 3u + i]);
                check_rho(&av, &wv, (uint32_t)x, (uint32_t)y, rho);
                TEST_ASSERT_TRUE(rho <= res.rho_q30);
            }
        }
    }
}

static void test_ncc_at_against_double_reference(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 8u);
    for (t = 0; t < 40u; t++) {
        ssda_view_t av, wv;
        uint32_t ww = test_rng_range(&r, 1, MAXW), wh = test_rng_range(&r, 1, MAXW);
        uint32_t x = test_rng_range(&r, 0, AW - ww), y = test_rng_range(&r, 0, AH - wh);
        int32_t rho = 0;
        make_pair(&r, (t & 1u) != 0u, ww, wh, test_rng_range(&r, 0, AW - ww),
                  test_rng_range(&r, 0, AH - wh), 30, &av, &wv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_at(&av, &wv, (uint16_t)x, (uint16_t)y, &rho));
        check_rho(&av, &wv, x, y, rho);
    }
}

/* Pairs that reach the bound's edge cases (flat rows left in the window or
   under the placement, dark images whose bound straddles zero), every mode
   against the exhaustive reference. */
static void test_bound_edge_cases(void)
{
    test_rng_t r;
    uint32_t t, x, y;
    test_rng_seed(&r, 13u);
    for (t = 0; t < 6u; t++) {
        ssda_view_t av, wv;
        make_pair(&r, false, 16, 16, test_rng_range(&r, 0, AW - 16u),
                  test_rng_range(&r, 0, AH - 16u), 20, &av, &wv);
        for (y = 0; y < AH; y++) {
            for (x = 0; x < AW; x++) {
                if (t < 2u && (y / 6u) % 2u == 1u) {
                    g_a8[y][x] = 90u; /* flat bands in the area */
                } else if (t >= 4u) {
                    g_a8[y][x] = (uint8_t)(g_a8[y][x] / 16u); /* dark */
                }
            }
        }
        for (y = 0; y < 16u; y++) {
            for (x = 0; x < 16u; x++) {
                if ((t == 2u || t == 3u) && y >= 4u) {
                    g_w8[y][x] = 60u; /* the window flat below its first group */
                } else if (t >= 4u) {
                    g_w8[y][x] = (uint8_t)(g_w8[y][x] / 16u);
                }
            }
        }
        check_all_modes(&av, &wv, &r);
    }
}

/* Bad arguments: an error and an untouched result. */
static void test_errors_leave_result_untouched(void)
{
    ssda_view_t av, wv, w16, big;
    ssda_ncc_config_t cfg = config(SSDA_NCC_RHO, 0);
    ssda_ncc_result_t res, poison;
    int32_t rho = 12345;
    memset(&poison, 0xA5, sizeof poison);
    res = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, g_w8, 8, 8, MAXW + 5u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&w16, g_w16, 8, 8, (MAXW + 5u) * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&big, g_a8, AW, AH, AW + 3u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_match(NULL, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_match(&av, NULL, &cfg, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_match(&av, &wv, NULL, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_match(&av, &wv, &cfg, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_ncc_match(&av, &w16, &cfg, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_ncc_match(&wv, &big, &cfg, &res));
    big.height = 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_ncc_match(&wv, &big, &cfg, &res));
    big.width = 8;
    big.height = 9;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_ncc_match(&wv, &big, &cfg, &res));
    wv.stride = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_ncc_match(&av, &wv, &cfg, &res));
    wv.stride = MAXW + 5u;
    av.format = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_ncc_match(&av, &wv, &cfg, &res));
    av.format = SSDA_PIX_U8;
    cfg.metric = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_ncc_match(&av, &wv, &cfg, &res));
    cfg.metric = 0;
    cfg.flags = 0x10;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_ncc_match(&av, &wv, &cfg, &res));
    cfg.flags = 0;
    cfg.work = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_match(&av, &wv, &cfg, &res));
    cfg.work = (uint8_t *)(void *)g_work + 4;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_ncc_match(&av, &wv, &cfg, &res));
    cfg.work = g_work;
    cfg.work_size = SSDA_NCC_WORK_SIZE(AW, 8, 8) - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_ncc_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
    cfg.work_size = SSDA_NCC_WORK_SIZE(AW, 8, 8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_match(&av, &wv, &cfg, &res));
    /* the probe */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_at(NULL, &wv, 0, 0, &rho));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_at(&av, NULL, 0, 0, &rho));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_ncc_at(&av, &wv, 0, 0, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_ncc_at(&av, &w16, 0, 0, &rho));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_ncc_at(&av, &wv, AW - 7u, 0, &rho));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_ncc_at(&av, &wv, 0, AH - 7u, &rho));
    TEST_ASSERT_EQUAL_INT32(12345, rho);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_ncc_at(&av, &wv, AW - 8u, AH - 8u, &rho));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_argmax_equals_exhaustive_search_8bit);
    RUN_TEST(test_argmax_equals_exhaustive_search_16bit);
    RUN_TEST(test_argmax_inverted_binary_images);
    RUN_TEST(test_gain_offset_gives_rho_one_with_less_work);
    RUN_TEST(test_inverted_contrast_found_by_abs_only);
    RUN_TEST(test_tie_rule);
    RUN_TEST(test_flat_window);
    RUN_TEST(test_flat_area_positions);
    RUN_TEST(test_around_matches_probe);
    RUN_TEST(test_ncc_at_against_double_reference);
    RUN_TEST(test_bound_edge_cases);
    RUN_TEST(test_errors_leave_result_untouched);
    return UNITY_END();
}
