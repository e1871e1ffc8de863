/*
 * test_cov_match.c - the search API and its helpers at the corners the main
 * tests leave out (found by branch coverage, tools/coverage.sh): error
 * names, the wide multiply-shift against a long-multiplication reference,
 * refusals of ssda_match / ssda_sad_at / ssda_view_roi with outputs
 * untouched, a read failing anywhere in a predicted scan, and tracking's
 * RASTER-as-PREDICT rule. References: brute force (test_sad, test_best),
 * closed forms, documented error codes.
 */
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "ssda/track.h"
#include "fixmath.h"
#include "test_image.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

static void test_every_error_code_has_its_own_name(void)
{
    static const int codes[] = {SSDA_OK, SSDA_ERR_NULL, SSDA_ERR_ARG, SSDA_ERR_SIZE,
                                SSDA_ERR_FORMAT, SSDA_ERR_STRIDE, SSDA_ERR_OVERFLOW,
                                SSDA_ERR_BUFFER, SSDA_ERR_IO, SSDA_ERR_STATE,
                                SSDA_ERR_UNSUPPORTED};
    const size_t n = sizeof codes / sizeof codes[0];
    const char *callback = ssda_strerror(-1000);
    const char *unknown = ssda_strerror(5);
    size_t i, j;
    TEST_ASSERT_NOT_NULL(callback);
    TEST_ASSERT_NOT_NULL(unknown);
    /* every negative code outside the enum is "from a callback" */
    TEST_ASSERT_EQUAL_STRING(callback, ssda_strerror(-11));
    TEST_ASSERT_EQUAL_STRING(callback, ssda_strerror(-2147483647 - 1));
    TEST_ASSERT_EQUAL_STRING(unknown, ssda_strerror(2147483647));
    TEST_ASSERT_TRUE(strcmp(callback, unknown) != 0);
    for (i = 0; i < n; i++) {
        const char *s = ssda_strerror(codes[i]);
        TEST_ASSERT_NOT_NULL(s);
        TEST_ASSERT_TRUE(s[0] != '\0');
        TEST_ASSERT_TRUE(strcmp(s, callback) != 0);
        TEST_ASSERT_TRUE(strcmp(s, unknown) != 0);
        for (j = 0; j < i; j++) {
            TEST_ASSERT_TRUE(strcmp(s, ssda_strerror(codes[j])) != 0);
        }
    }
}

/* a * b by schoolbook multiplication in 16-bit limbs (independent of
   fixmath.c's split), then bits 24..87 (lo64) and 88..111 (hi32) of it:
   floor(a * b / 2^24) = hi32 * 2^64 + lo64. */
static void ref_mul_shr24(uint32_t a, uint64_t b, uint64_t *hi32, uint64_t *lo64)
{
    uint32_t x[2] = {a & 0xFFFFu, a >> 16};
    uint32_t y[4] = {(uint32_t)(b & 0xFFFFu), (uint32_t)((b >> 16) & 0xFFFFu),
                     (uint32_t)((b >> 32) & 0xFFFFu), (uint32_t)(b >> 48)};
    uint64_t limb[7] = {0, 0, 0, 0, 0, 0, 0}; /* 16-bit limbs of the product */
    uint64_t carry = 0;
    uint32_t i, j;
    for (i = 0; i < 2; i++) {
        for (j = 0; j < 4; j++) {
            limb[i + j] += (uint64_t)x[i] * y[j];
        }
    }
    for (i = 0; i < 7; i++) {
        limb[i] += carry;
        carry = limb[i] >> 16;
        limb[i] &= 0xFFFFu;
    }
    {
        uint64_t lo = 0, hi = 0;
        uint32_t bit;
        for (bit = 0; bit < 64; bit++) {
            uint32_t b24 = bit + 24u;
            uint64_t one = (limb[b24 / 16u] >> (b24 % 16u)) & 1u;
            lo |= one << bit;
        }
        for (bit = 0; bit < 24; bit++) {
            uint32_t b88 = bit + 88u;
            uint64_t one = b88 / 16u < 7u ? (limb[b88 / 16u] >> (b88 % 16u)) & 1u : 0u;
            hi |= one << bit;
        }
        *lo64 = lo;
        *hi32 = hi;
    }
}

static void test_mul_shr24_is_exact_below_2_56_and_saturates_above(void)
{
    test_rng_t r;
    uint32_t i;
    uint64_t hi, lo;
    test_rng_seed(&r, 77u);
    for (i = 0; i < 2000u; i++) {
        uint32_t a = test_rng_next(&r);
        uint64_t b = ((uint64_t)test_rng_next(&r) << 32 | test_rng_next(&r)) >> (8u + i % 40u);
        if (i == 0u) {
            a = UINT32_MAX;
            b = ((uint64_t)1 << 56) - 1u; /* the largest accepted b */
        }
        ref_mul_shr24(a, b, &hi, &lo);
        TEST_ASSERT_EQUAL_UINT64(0u, hi); /* a < 2^32, b < 2^56: the result fits */
        TEST_ASSERT_EQUAL_UINT64(lo, ssda__mul_shr24(a, b));
    }
    /* b >= 2^56: a * b / 2^24 may not fit; documented to saturate */
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, ssda__mul_shr24(1u, (uint64_t)1 << 56));
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, ssda__mul_shr24(UINT32_MAX, UINT64_MAX));
}

#define AW 20u
#define AH 16u
#define WW 6u
#define WH 5u
static uint8_t g_area[AH][AW];
static uint8_t g_win[WH][WW];
static uint32_t g_work[SSDA_MATCH_WORK_SIZE(AW, AH, WW, WH) / 4u + 1u];
static uint8_t g_dev[AW * AH + 16u];
static uint32_t g_arena[128];
static test_source_t g_t;

static void make_pair(uint32_t seed, uint32_t wx, uint32_t wy, ssda_view_t *av, ssda_view_t *wv)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u8(&g_area[0][0], AW, AH, AW, &r);
    for (y = 0; y < WH; y++) {
        for (x = 0; x < WW; x++) {
            g_win[y][x] = (uint8_t)(g_area[wy + y][wx + x] ^ (x == 2u && y == 1u ? 1u : 0u));
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(av, g_area, AW, AH, AW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(wv, g_win, WW, WH, WW, SSDA_PIX_U8));
}

static void test_search_refusals_leave_outputs_untouched(void)
{
    ssda_view_t av, wv, tall, roi, roi0;
    ssda_match_config_t c;
    ssda_match_result_t res, poison;
    uint64_t sad = 0x1234u;
    static uint16_t area16[AH][AW];
    ssda_view_t a16;
    make_pair(1u, 7u, 4u, &av, &wv);
    memset(&poison, 0x2F, sizeof poison);
    res = poison;
    /* bounds with a misaligned work buffer of the right size */
    memset(&c, 0, sizeof c);
    c.flags = SSDA_MATCH_BOUNDS;
    c.work = (uint8_t *)g_work + 1;
    c.work_size = SSDA_MATCH_WORK_SIZE(AW, AH, WW, WH);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_match(&av, &wv, &c, &res));
    /* a window as narrow as the area allows but one row taller */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&tall, g_area, WW, AH, AW, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&roi, &av, 0, 0, AW, AH - 1u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_match(&roi, &tall, NULL, &res));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
    /* ssda_sad_at: NULL window or output, then a bad pair */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_sad_at(NULL, &wv, 0, 0, &sad));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_sad_at(&av, NULL, 0, 0, &sad));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_sad_at(&av, &wv, 0, 0, NULL));
    memset(area16, 0, sizeof area16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a16, area16, AW, AH, AW * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_sad_at(&a16, &wv, 0, 0, &sad));
    TEST_ASSERT_EQUAL_UINT64(0x1234u, sad);
    /* and where it works it is the brute-force sum: 1 at the cut-out place */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_sad_at(&av, &wv, 7, 4, &sad));
    TEST_ASSERT_EQUAL_UINT64(1u, sad);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_sad_at(&av, &wv, 3, 9, &sad));
    TEST_ASSERT_EQUAL_UINT64(test_sad(&av, &wv, 3, 9), sad);
    /* ssda_view_roi: an empty height is refused, roi untouched */
    memset(&roi0, 0x44, sizeof roi0);
    roi = roi0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_view_roi(&roi, &av, 2, 2, 4, 0));
    TEST_ASSERT_EQUAL_MEMORY(&roi0, &roi, sizeof roi);
}

/* Predicted scan over a streamed area (its minimum since issue 22: the
   whole area, read through a bounce buffer of a row, read_size 4, so one
   read per row). A read failing at any point comes back unchanged with the
   result untouched; the clean run is brute force. */
static void test_predict_scan_read_failure_anywhere(void)
{
    ssda_view_t av, wv;
    ssda_source_config_t sc;
    ssda_source_t as, ws;
    ssda_match_config_t c;
    ssda_match_result_t res, poison;
    uint32_t bx, by, p;
    uint64_t bs, clean_reads, k, step;
    static const int32_t predictions[3][2] = {{0, 0}, {7, 6}, {14, 11}};
    make_pair(2u, 11u, 3u, &av, &wv);
    test_best(&av, &wv, &bx, &by, &bs);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ws, &wv));
    memset(&poison, 0x19, sizeof poison);
    for (p = 0; p < 3u; p++) {
        memset(&c, 0, sizeof c);
        c.scan = SSDA_SCAN_PREDICT;
        c.predict_x = predictions[p][0];
        c.predict_y = predictions[p][1];
        test_source_init(&g_t, g_dev, sizeof g_dev, 4u);
        sc = test_source_config(&g_t, &av, SSDA_LAYOUT_RASTER, 0, 0, 0u, 0u, 0u, 4u, g_arena,
                                SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, AW, AH, 1u, 4u, 0u));
        test_source_store(&g_t, &sc, &av);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&as, &sc));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, NULL, &ws, NULL, &c, &res));
        TEST_ASSERT_EQUAL_UINT32(bx, res.x);
        TEST_ASSERT_EQUAL_UINT32(by, res.y);
        TEST_ASSERT_EQUAL_UINT64(bs, res.sad);
        TEST_ASSERT_TRUE(res.exact);
        clean_reads = g_t.reads;
        TEST_ASSERT_TRUE(clean_reads >= AH);
        step = clean_reads / 60u + 1u;
        for (k = 0; k < clean_reads; k += step) {
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&as, &sc));
            test_source_reset(&g_t);
            g_t.fail_code = -300 - (int)k;
            g_t.fail_at_read = (int64_t)k;
            res = poison;
            TEST_ASSERT_EQUAL_INT(-300 - (int)k, ssda_stream_match(&as, NULL, &ws, NULL, &c, &res));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &res, sizeof res);
            TEST_ASSERT_EQUAL_UINT64(1u, g_t.failures);
        }
    }
}

/* With a prediction mode, tracking runs RASTER as PREDICT: both give the
   same vectors and the same work; AUTO keeps them brute-force exact. */
static void test_track_raster_runs_as_predict(void)
{
    static uint8_t first[48][48], second[48][48];
    static ssda_track_vector_t a[16], b[16];
    ssda_view_t fv, sv;
    ssda_track_config_t c;
    ssda_track_stats_t sa, sb;
    test_rng_t r;
    uint32_t x, y, k;
    test_rng_seed(&r, 3u);
    test_fill_texture_u8(&first[0][0], 48, 48, 48, &r);
    for (y = 0; y < 48u; y++) {
        for (x = 0; x < 48u; x++) {
            second[y][x] = first[(y + 47u) % 48u][(x + 1u) % 48u];
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&fv, first, 48, 48, 48, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&sv, second, 48, 48, 48, SSDA_PIX_U8));
    memset(&c, 0, sizeof c);
    c.win_w = c.win_h = 8;
    c.search_w = c.search_h = 16;
    c.step_x = c.step_y = 8;
    c.roi_x = c.roi_y = 8;
    c.roi_w = c.roi_h = 32;
    c.predict = SSDA_TRACK_PREDICT_LEFT;
    c.match.scan = SSDA_SCAN_RASTER;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, &c, a, 16, &sa));
    c.match.scan = SSDA_SCAN_PREDICT;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, &c, b, 16, &sb));
    TEST_ASSERT_EQUAL_UINT32(16u, sa.ok);
    TEST_ASSERT_EQUAL_UINT64(sa.pixel_ops, sb.pixel_ops);
    TEST_ASSERT_EQUAL_UINT64(sa.positions, sb.positions);
    for (k = 0; k < 16u; k++) {
        ssda_view_t area, win;
        uint32_t bx, by;
        uint64_t bs;
        TEST_ASSERT_EQUAL_INT32(a[k].dx, b[k].dx);
        TEST_ASSERT_EQUAL_INT32(a[k].dy, b[k].dy);
        TEST_ASSERT_EQUAL_UINT64(a[k].sad, b[k].sad);
        /* SECOND(x, y) = FIRST(x + 1, y - 1): motion (-1, +1) */
        TEST_ASSERT_EQUAL_INT32(-1, b[k].dx);
        TEST_ASSERT_EQUAL_INT32(1, b[k].dy);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&area, &fv, (uint16_t)(b[k].x - 4u),
                                                     (uint16_t)(b[k].y - 4u), 16, 16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&win, &sv, b[k].x, b[k].y, 8, 8));
        test_best(&area, &win, &bx, &by, &bs);
        TEST_ASSERT_EQUAL_UINT64(bs, b[k].sad);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_error_code_has_its_own_name);
    RUN_TEST(test_mul_shr24_is_exact_below_2_56_and_saturates_above);
    RUN_TEST(test_search_refusals_leave_outputs_untouched);
    RUN_TEST(test_predict_scan_read_failure_anywhere);
    RUN_TEST(test_track_raster_runs_as_predict);
    return UNITY_END();
}
