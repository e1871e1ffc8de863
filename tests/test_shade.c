/*
 * test_shade.c - the shading function against its definition in shade.h
 * computed here in double precision (exact cosines and sines), the
 * average over several images, the centre of a known shading, the
 * correction against a direct formula, the worst-case sums, and the
 * state machine's errors.
 */
#include <string.h>
#include "unity.h"
#include "state.h"
#include "ssda/shade.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#define PI 3.14159265358979323846
#define MW 97u
#define MH 61u

static uint16_t g_img[4][MH][MW];

static void push_image(ssda_shade_t *sh, uint16_t img[MH][MW], uint32_t w, uint32_t h, uint8_t format)
{
    uint32_t y, x;
    for (y = 0; y < h; y++) {
        if (format == SSDA_PIX_U8) {
            uint8_t r8[MW];
            for (x = 0; x < w; x++) r8[x] = (uint8_t)img[y][x];
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(sh, r8));
        } else {
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(sh, img[y]));
        }
    }
}

/* K_pq from the definition, double, over images 0..n-1 (w x h of g_img). */
static void k_double(uint32_t n, uint32_t w, uint32_t h, double k[9])
{
    uint32_t i, x, y, p, q;
    for (p = 0; p < 9; p++) k[p] = 0;
    for (i = 0; i < n; i++) {
        for (y = 0; y < h; y++) {
            const double gy[3] = {1.0, test_cos(2 * PI * y / h), test_sin(2 * PI * y / h)};
            for (x = 0; x < w; x++) {
                const double fx[3] = {1.0, test_cos(2 * PI * x / w), test_sin(2 * PI * x / w)};
                for (p = 0; p < 3; p++)
                    for (q = 0; q < 3; q++) k[p * 3 + q] += g_img[i][y][x] * fx[p] * gy[q];
            }
        }
    }
    for (p = 0; p < 3; p++)
        for (q = 0; q < 3; q++) k[p * 3 + q] *= (p ? 2.0 : 1.0) * (q ? 2.0 : 1.0) / ((double)n * w * h);
}

static double s_double(const double k[9], uint32_t w, uint32_t h, uint32_t x, uint32_t y)
{
    const double gy[3] = {1.0, test_cos(2 * PI * y / h), test_sin(2 * PI * y / h)};
    const double fx[3] = {1.0, test_cos(2 * PI * x / w), test_sin(2 * PI * x / w)};
    double s = 0;
    unsigned p, q;
    for (p = 0; p < 3; p++)
        for (q = 0; q < 3; q++) s += k[p * 3 + q] * fx[p] * gy[q];
    return s;
}

/* Random scenes of both formats and odd sizes: S equals the double
   definition within 0.02 grey (8-bit) / 5 grey (16-bit, 1/13000 of range)
   everywhere, K within 1/64 grey of it. */
static void test_matches_double_definition(void)
{
    test_rng_t r;
    int trial;
    test_rng_seed(&r, 0x53484144u);
    for (trial = 0; trial < 8; trial++) {
        const uint8_t format = (uint8_t)(1 + trial % 2);
        const uint32_t w = test_rng_range(&r, 3, MW), h = test_rng_range(&r, 3, MH);
        const uint32_t n = 1 + trial % 3, maxv = format == SSDA_PIX_U8 ? 255 : 65535;
        ssda_shade_t sh;
        double k[9];
        uint32_t i, x, y, p;
        for (i = 0; i < n; i++)
            for (y = 0; y < h; y++)
                for (x = 0; x < w; x++) g_img[i][y][x] = (uint16_t)test_rng_range(&r, 0, maxv);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, (uint16_t)w, (uint16_t)h, format));
        for (i = 0; i < n; i++) push_image(&sh, g_img[i], w, h, format);
        TEST_ASSERT_EQUAL_UINT16(n, sh.images);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MAX));
        k_double(n, w, h, k);
        for (p = 0; p < 9; p++) {
            TEST_ASSERT_TRUE(sh.k_q8[p] / 256.0 > k[p] - maxv / 16384.0 - 1.0 / 64 &&
                             sh.k_q8[p] / 256.0 < k[p] + maxv / 16384.0 + 1.0 / 64);
        }
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                int32_t s;
                const double want = s_double(k, w, h, x, y), tol = format == SSDA_PIX_U8 ? 0.02 : 5.0;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_eval(&sh, x, y, &s));
                TEST_ASSERT_TRUE(s / 256.0 > want - tol && s / 256.0 < want + tol);
            }
        }
    }
}

/* A shading inside the model, off-centre (the seed's sun spot), on
   textured scenes: S recovers it (the scenes' own low frequencies average
   out over the images only partly, so loosely), the centre is its peak,
   and the correction flattens it. With mode MIN the dark corner. */
static void test_known_shading_centre_and_correction(void)
{
    test_rng_t r;
    const uint32_t w = MW, h = MH, x0 = 60, y0 = 22;
    ssda_shade_t sh;
    uint32_t i, x, y;
    double lo_before = 1e9, hi_before = -1e9, lo_after = 1e9, hi_after = -1e9;
    test_rng_seed(&r, 9);
    for (i = 0; i < 3; i++) {
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                const double shade = 40.0 * test_cos(2 * PI * ((double)x - x0) / w) +
                                     25.0 * test_cos(2 * PI * ((double)y - y0) / h);
                g_img[i][y][x] = (uint16_t)(120.0 + shade + (double)test_rng_range(&r, 0, 40));
            }
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, w, h, SSDA_PIX_U8));
    for (i = 0; i < 3; i++) push_image(&sh, g_img[i], w, h, SSDA_PIX_U8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MAX));
    TEST_ASSERT_UINT32_WITHIN(2, x0, sh.centre_x);
    TEST_ASSERT_UINT32_WITHIN(2, y0, sh.centre_y);
    /* the centre is the maximum of S over every pixel */
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            int32_t s;
            (void)ssda_shade_eval(&sh, x, y, &s);
            TEST_ASSERT_TRUE(s <= sh.centre_q8);
        }
    }
    /* corrected rows: the direct formula, and the shading gone (the mean
       of each column band flat within 4 grey, it was 130 apart) */
    for (y = 0; y < h; y++) {
        uint8_t in[MW], out[MW];
        for (x = 0; x < w; x++) in[x] = (uint8_t)g_img[0][y][x];
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_apply_row(&sh, y, in, out));
        for (x = 0; x < w; x++) {
            int32_t s, t;
            (void)ssda_shade_eval(&sh, x, y, &s);
            t = in[x] * 256 - s + sh.centre_q8 + 128;
            TEST_ASSERT_EQUAL_UINT8(t < 0 ? 0 : (t / 256 > 255 ? 255 : t / 256), out[x]);
        }
    }
    for (x = 0; x + 8 <= w; x += 8) {
        double before = 0, after = 0;
        for (y = 0; y < h; y++) {
            uint8_t in[MW], out[MW];
            uint32_t k;
            for (k = 0; k < w; k++) in[k] = (uint8_t)((g_img[0][y][k] + g_img[1][y][k] + g_img[2][y][k]) / 3);
            (void)ssda_shade_apply_row(&sh, y, in, out);
            for (k = x; k < x + 8; k++) {
                before += in[k];
                after += out[k];
            }
        }
        before /= 8.0 * h;
        after /= 8.0 * h;
        lo_before = before < lo_before ? before : lo_before;
        hi_before = before > hi_before ? before : hi_before;
        lo_after = after < lo_after ? after : lo_after;
        hi_after = after > hi_after ? after : hi_after;
    }
    TEST_ASSERT_TRUE(hi_before - lo_before > 60.0);
    TEST_ASSERT_TRUE(hi_after - lo_after < 4.0);
    /* the dark corner: the minimum of S, opposite the peak */
    {
        ssda_shade_t sh2 = sh;
        sh2.magic = SSDA__MAGIC_SHADE_OPEN; /* refinish from the same sums */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh2, SSDA_SHADE_CENTRE_MIN));
        TEST_ASSERT_UINT32_WITHIN(2, (x0 + w / 2) % w, sh2.centre_x);
        TEST_ASSERT_UINT32_WITHIN(2, (y0 + h / 2) % h, sh2.centre_y);
        TEST_ASSERT_TRUE(sh2.centre_q8 < sh.centre_q8 - 100 * 256);
    }
    /* a centre set by the caller */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_set_centre(&sh, 3, 4));
    {
        int32_t s;
        (void)ssda_shade_eval(&sh, 3, 4, &s);
        TEST_ASSERT_EQUAL_INT32(s, sh.centre_q8);
    }
}

/* The basis functions themselves, through K: a 16-bit image 0 but for one
   full-scale column x0 has K_10 = 2 A cos(2 pi x0 / w) / w and K_20 the
   same with sin (A = 65535; g_0 = 1 exactly), and one full-scale row y0
   K_01, K_02 alike in y. shade.h: f, g are the sine of a phase within
   2^-31 turn of the true one, from a polynomial within 0.03 LSB of Q15,
   rounded to Q15: within 0.53 LSB (0.55 here, the phase's part
   included), so K is within 2 A / w * 0.55 / 32768 grey of the double
   value plus the rounding of K to Q8 (1/512 grey), at every column of
   every width. (The sine once used 14 bits of the phase in a quarter turn:
   up to 3.6 LSB off, which this test showed at many widths.) */
static void test_basis_within_half_lsb(void)
{
#ifndef SSDA_TEST_SMALL
    const uint32_t wstep = 1;
#else
    const uint32_t wstep = 7;
#endif
    uint16_t row[MW];
    uint32_t n, i, j, axis;
    for (axis = 0; axis < 2; axis++) {
        for (n = 3; n <= MW; n += wstep) {
            for (i = 0; i < n; i++) {
                const uint32_t w = axis == 0 ? n : 3, h = axis == 0 ? 3 : n;
                const double a = 65535.0, ph = 2 * PI * i / n;
                const double tol = 2.0 * a / n * 0.55 / 32768.0 + 1.0 / 512 + 1e-9;
                ssda_shade_t sh;
                int32_t kc, ks;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, (uint16_t)w, (uint16_t)h, SSDA_PIX_U16));
                for (j = 0; j < h; j++) {
                    uint32_t x;
                    for (x = 0; x < w; x++) {
                        row[x] = (uint16_t)((axis == 0 ? x : j) == i ? 65535u : 0u);
                    }
                    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&sh, row));
                }
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MAX));
                kc = sh.k_q8[axis == 0 ? 3 : 1]; /* K_10 or K_01 */
                ks = sh.k_q8[axis == 0 ? 6 : 2]; /* K_20 or K_02 */
                TEST_ASSERT_DOUBLE_WITHIN(tol, 2.0 * a / n * test_cos(ph), kc / 256.0);
                TEST_ASSERT_DOUBLE_WITHIN(tol, 2.0 * a / n * test_sin(ph), ks / 256.0);
            }
        }
    }
}

/* Largest sums: all-max 16-bit images of the widest and the tallest shape
   (65535 x 3 and 3 x 65535), several of them: K_00 = 65535 exactly, the
   others 0 within rounding; in place correction returns the level. */
static void test_worst_case(void)
{
#ifndef SSDA_TEST_SMALL
    const uint32_t big = 65535, n = 3;
#else
    const uint32_t big = 4001, n = 2;
#endif
    static uint16_t row[65535];
    ssda_shade_t sh;
    uint32_t i, y, p;
    for (i = 0; i < big; i++) row[i] = 65535;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, (uint16_t)big, 3, SSDA_PIX_U16));
    for (i = 0; i < n * 3; i++) TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&sh, row));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MAX));
    TEST_ASSERT_EQUAL_INT32(65535 * 256, sh.k_q8[0]);
    for (p = 1; p < 9; p++) TEST_ASSERT_INT32_WITHIN(2 * 256, 0, sh.k_q8[p]);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_apply_row(&sh, 1, row, row));
    for (i = 0; i < big; i += 97) TEST_ASSERT_UINT16_WITHIN(3, 65535, row[i]);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, 3, (uint16_t)big, SSDA_PIX_U16));
    for (i = 0; i < 3; i++) row[i] = 65535;
    for (y = 0; y < n * big; y++) TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&sh, row));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MAX));
    TEST_ASSERT_EQUAL_INT32(65535 * 256, sh.k_q8[0]);
}

static void test_errors_and_states(void)
{
    ssda_shade_t sh, poison;
    int32_t s;
    uint8_t row[8] = {0};
    memset(&poison, 0x5A, sizeof poison);
    sh = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_init(NULL, 4, 4, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_shade_init(&sh, 2, 4, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_shade_init(&sh, 4, 2, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_shade_init(&sh, 4, 4, 3));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &sh, sizeof sh);
    memset(&sh, 0, sizeof sh);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_add_row(&sh, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_finish(&sh, 0));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, 4, 3, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_add_row(NULL, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_add_row(&sh, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_finish(NULL, 0));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_finish(&sh, 0)); /* no image */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_eval(&sh, 0, 0, &s));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_apply_row(&sh, 0, row, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_set_centre(&sh, 0, 0));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&sh, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_finish(&sh, 0)); /* partial image */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&sh, row));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&sh, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_shade_finish(&sh, 2));
    {
        /* a complete image and part of the next: refused, nothing changes */
        ssda_shade_t part = sh, before;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&part, row));
        before = part;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_finish(&part, 0));
        TEST_ASSERT_EQUAL_MEMORY(&before, &part, sizeof part);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, 0));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_finish(&sh, 0)); /* twice */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_add_row(&sh, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_eval(NULL, 0, 0, &s));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_eval(&sh, 0, 0, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_shade_eval(&sh, 4, 0, &s));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_shade_eval(&sh, 0, 3, &s));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_apply_row(NULL, 0, row, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_apply_row(&sh, 0, NULL, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_apply_row(&sh, 0, row, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_shade_apply_row(&sh, 3, row, row));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_shade_set_centre(NULL, 0, 0));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_shade_set_centre(&sh, 4, 0));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_shade_set_centre(&sh, 0, 3));
    /* a flat image: S is flat, the correction changes nothing */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_apply_row(&sh, 1, row, row));
    TEST_ASSERT_EACH_EQUAL_UINT8(0, row, 4);
    /* 65535 images: the count is full */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, 4, 3, SSDA_PIX_U8));
    sh.images = 65535;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_shade_add_row(&sh, row));
}

/* Clamping: with the maximum as centre, I - S + S(centre) >= I, so a
   255 row stays 255 (the sum above it clamped); with the minimum, a 0 row
   stays 0. The step image makes S vary by ~200 grey. */
static void test_clamp(void)
{
    ssda_shade_t sh;
    uint32_t y, x;
    uint8_t in[8], out[8];
    int32_t s0, s7;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_init(&sh, 8, 8, SSDA_PIX_U8));
    for (y = 0; y < 8; y++) {
        for (x = 0; x < 8; x++) in[x] = (uint8_t)(x < 4 ? 250 : 5);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_add_row(&sh, in));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MAX));
    (void)ssda_shade_eval(&sh, 1, 0, &s0);
    (void)ssda_shade_eval(&sh, 6, 0, &s7);
    TEST_ASSERT_TRUE(s0 - s7 > 150 * 256);
    memset(in, 255, sizeof in);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_apply_row(&sh, 2, in, out));
    TEST_ASSERT_EACH_EQUAL_UINT8(255, out, 8);
    sh.magic = SSDA__MAGIC_SHADE_OPEN;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_finish(&sh, SSDA_SHADE_CENTRE_MIN));
    memset(in, 0, sizeof in);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_shade_apply_row(&sh, 2, in, out));
    TEST_ASSERT_EACH_EQUAL_UINT8(0, out, 8);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_matches_double_definition);
    RUN_TEST(test_known_shading_centre_and_correction);
    RUN_TEST(test_basis_within_half_lsb);
    RUN_TEST(test_worst_case);
    RUN_TEST(test_errors_and_states);
    RUN_TEST(test_clamp);
    return UNITY_END();
}
