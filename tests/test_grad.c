/*
 * test_grad.c - the Fig. 8 differential operator against a direct
 * per-pixel implementation written here from the formula, at random and
 * worst-case values, every output format and shift, strides, and errors.
 */
#include <string.h>
#include "unity.h"
#include "ssda/grad.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#define W 37u
#define H 23u
#define OSTRIDE 40u /* output samples per row in the strided tests */

static uint16_t g_src[W * H + 8u];
static uint16_t g_out16[OSTRIDE * H];

/* E' from the formula, letters as in the seed's Fig. 8. */
static uint32_t direct(const ssda_view_t *v, uint32_t x, uint32_t y)
{
    int64_t A = test_px(v, x - 1, y - 1), B = test_px(v, x, y - 1), C = test_px(v, x + 1, y - 1);
    int64_t D = test_px(v, x - 1, y), F = test_px(v, x + 1, y);
    int64_t G = test_px(v, x - 1, y + 1), Hh = test_px(v, x, y + 1), I = test_px(v, x + 1, y + 1);
    int64_t t1 = A + B + C - G - Hh - I;
    int64_t t2 = A + D + G - C - F - I;
    return (uint32_t)((t1 < 0 ? -t1 : t1) + (t2 < 0 ? -t2 : t2));
}

/* Run ssda_grad and compare every output sample (and untouched padding)
   with the direct formula, shifted and saturated as documented. */
static void check(const ssda_view_t *src, uint8_t ofmt, uint8_t shift, uint32_t ostride_px,
                  uint32_t *max_seen)
{
    const uint32_t omax = ofmt == SSDA_PIX_U8 ? 255u : 65535u;
    ssda_grad_out_t out;
    uint32_t sat = 0xDEADu, want_sat = 0, x, y;
    memset(g_out16, 0xEE, sizeof g_out16);
    out.data = g_out16;
    out.size = sizeof g_out16;
    out.stride = ostride_px * ofmt;
    out.format = ofmt;
    out.shift = shift;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_grad(src, &out, &sat));
    for (y = 0; y < src->height - 2u; y++) {
        const uint8_t *row = (const uint8_t *)g_out16 + (size_t)y * ostride_px * ofmt;
        for (x = 0; x < ostride_px; x++) {
            uint32_t got;
            if (ofmt == SSDA_PIX_U8) {
                got = row[x];
            } else {
                got = ((const uint16_t *)(const void *)row)[x];
            }
            if (x < src->width - 2u) {
                uint32_t e = direct(src, x + 1u, y + 1u);
                uint32_t v = e >> shift;
                if (e > *max_seen) {
                    *max_seen = e;
                }
                if (v > omax) {
                    v = omax;
                    want_sat++;
                }
                TEST_ASSERT_EQUAL_UINT32(v, got);
            } else {
                TEST_ASSERT_EQUAL_UINT32(ofmt == SSDA_PIX_U8 ? 0xEEu : 0xEEEEu, got);
            }
        }
    }
    TEST_ASSERT_EQUAL_UINT32(want_sat, sat);
}

static void test_random_u8_and_u16_match_formula(void)
{
    test_rng_t r;
    ssda_view_t v;
    uint32_t i, seen = 0;
    uint8_t shift;
    test_rng_seed(&r, 5);
    /* 8-bit noise, stride wider than the image */
    for (i = 0; i < W * H; i++) {
        ((uint8_t *)g_src)[i] = (uint8_t)test_rng_range(&r, 0, 255);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_src, W - 3u, H, W, SSDA_PIX_U8));
    for (shift = 0; shift < 4u; shift++) {
        check(&v, SSDA_PIX_U16, shift, W - 5u, &seen);
        check(&v, SSDA_PIX_U8, shift, OSTRIDE, &seen);
    }
    /* 16-bit noise */
    for (i = 0; i < W * H; i++) {
        g_src[i] = (uint16_t)test_rng_range(&r, 0, 65535);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_src, W, H, W * 2u, SSDA_PIX_U16));
    for (shift = 0; shift < 12u; shift++) {
        check(&v, SSDA_PIX_U16, shift, W - 2u, &seen);
        check(&v, SSDA_PIX_U8, shift, OSTRIDE, &seen);
    }
}

/* Worst case: a diagonal step, maximum above-left of x + y = k and 0 below,
   gives A = B = D = max, F = H = I = 0, so E' = 4 * max; flat images
   (all 0, all max) give 0. */
static void fill_step(bool u16, uint32_t maxv, uint32_t k)
{
    uint32_t x, y;
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            uint32_t v = x + y < k ? maxv : 0u;
            if (u16) {
                g_src[y * W + x] = (uint16_t)v;
            } else {
                ((uint8_t *)g_src)[y * W + x] = (uint8_t)v;
            }
        }
    }
}

static void test_worst_case_values(void)
{
    ssda_view_t v8, v16;
    ssda_grad_out_t out;
    uint32_t seen, sat, i;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v8, g_src, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v16, g_src, W, H, W * 2u, SSDA_PIX_U16));

    fill_step(false, 255u, 20u);
    seen = 0;
    check(&v8, SSDA_PIX_U16, 0, W - 2u, &seen);
    TEST_ASSERT_EQUAL_UINT32(SSDA_GRAD_MAX(SSDA_PIX_U8), seen);
    TEST_ASSERT_EQUAL_UINT32(1020u, seen);
    check(&v8, SSDA_PIX_U8, 2, W - 2u, &seen); /* the safe shift: 1020 >> 2 = 255 */
    check(&v8, SSDA_PIX_U8, 1, W - 2u, &seen); /* saturates, counted */

    fill_step(true, 65535u, 20u);
    seen = 0;
    check(&v16, SSDA_PIX_U16, 0, W - 2u, &seen);
    TEST_ASSERT_EQUAL_UINT32(SSDA_GRAD_MAX(SSDA_PIX_U16), seen);
    TEST_ASSERT_EQUAL_UINT32(262140u, seen);
    check(&v16, SSDA_PIX_U16, 1, W - 2u, &seen);
    check(&v16, SSDA_PIX_U8, 9, W - 2u, &seen);

    /* at the safe shifts nothing saturates and the maximum reaches the top */
    out.data = g_out16;
    out.size = sizeof g_out16;
    out.stride = 0;
    out.format = SSDA_PIX_U16;
    out.shift = (uint8_t)SSDA_GRAD_SAFE_SHIFT(SSDA_PIX_U16, SSDA_PIX_U16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_grad(&v16, &out, &sat));
    TEST_ASSERT_EQUAL_UINT32(0, sat);
    seen = 0;
    for (i = 0; i < (W - 2u) * (H - 2u); i++) {
        seen = g_out16[i] > seen ? g_out16[i] : seen;
    }
    TEST_ASSERT_EQUAL_UINT32(65535u, seen);
    out.format = SSDA_PIX_U8;
    out.shift = (uint8_t)SSDA_GRAD_SAFE_SHIFT(SSDA_PIX_U16, SSDA_PIX_U8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_grad(&v16, &out, &sat));
    TEST_ASSERT_EQUAL_UINT32(0, sat);
    out.shift = (uint8_t)(out.shift - 1u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_grad(&v16, &out, &sat));
    TEST_ASSERT_TRUE(sat > 0u);

    /* flat all-0 and all-max images: E' = 0 everywhere */
    for (i = 0; i < 2u; i++) {
        fill_step(true, 65535u, i == 0u ? 0u : W + H);
        seen = 0;
        check(&v16, SSDA_PIX_U16, 0, W - 2u, &seen);
        TEST_ASSERT_EQUAL_UINT32(0, seen);
    }
    /* the other sign combination: B, C, F = max, D, G, H = 0 (anti-diagonal) */
    {
        uint32_t x, y;
        for (y = 0; y < H; y++) {
            for (x = 0; x < W; x++) {
                g_src[y * W + x] = (uint16_t)(x > y + 2u ? 65535u : 0u);
            }
        }
        seen = 0;
        check(&v16, SSDA_PIX_U16, 0, W - 2u, &seen);
        TEST_ASSERT_EQUAL_UINT32(262140u, seen);
    }
}

/* 3 x 3 is the smallest input: one output sample. */
static void test_smallest_input(void)
{
    static const uint8_t px[9] = {10, 20, 30, 40, 250, 60, 70, 80, 90};
    ssda_view_t v;
    ssda_grad_out_t out;
    uint16_t o = 0xFFFF;
    /* |10+20+30-70-80-90| + |10+40+70-30-60-90| = 180 + 60 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, px, 3, 3, 3, SSDA_PIX_U8));
    out.data = &o;
    out.size = sizeof o;
    out.stride = 0;
    out.format = SSDA_PIX_U16;
    out.shift = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_grad(&v, &out, NULL));
    TEST_ASSERT_EQUAL_UINT16(240, o);
}

static void test_bad_arguments_write_nothing(void)
{
    ssda_view_t v, bad;
    ssda_grad_out_t out, o;
    uint32_t sat = 77;
    uint8_t before[sizeof g_out16];
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_src, W, H, W * 2u, SSDA_PIX_U16));
    out.data = g_out16;
    out.size = SSDA_GRAD_SIZE(W, H, SSDA_PIX_U16);
    out.stride = 0;
    out.format = SSDA_PIX_U16;
    out.shift = 2;
    memset(g_out16, 0x3C, sizeof g_out16);
    memcpy(before, g_out16, sizeof before);

    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_grad(NULL, &out, &sat));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_grad(&v, NULL, &sat));
    o = out; o.data = NULL;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_grad(&v, &o, &sat));
    bad = v; bad.width = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_grad(&bad, &out, &sat));
    bad = v; bad.height = 2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_grad(&bad, &out, &sat));
    bad = v; bad.stride = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_grad(&bad, &out, &sat));
    bad = v; bad.format = 4;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_grad(&bad, &out, &sat));
    o = out; o.format = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_grad(&v, &o, &sat));
    o = out; o.shift = 32;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_grad(&v, &o, &sat));
    o = out; o.stride = (W - 2u) * 2u - 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_grad(&v, &o, &sat));
    o = out; o.stride = (W - 2u) * 2u + 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_grad(&v, &o, &sat));
    o = out; o.data = (uint8_t *)g_out16 + 1;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_grad(&v, &o, &sat));
    o = out; o.size = SSDA_GRAD_SIZE(W, H, SSDA_PIX_U16) - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_grad(&v, &o, &sat));
    /* a stride of 2^31: (H - 3) rows of it pass 2^32 bytes, which a 32-bit
       size_t would wrap to a few bytes (checked in 64 bits; nothing written) */
    o = out; o.stride = 0x80000000u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_grad(&v, &o, &sat));
    o = out; o.stride = OSTRIDE * 2u; o.size = SSDA_GRAD_SIZE_STRIDED(W, H, OSTRIDE * 2u, 2u) - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_grad(&v, &o, &sat));
    TEST_ASSERT_EQUAL_MEMORY(before, g_out16, sizeof before);
    TEST_ASSERT_EQUAL_UINT32(77, sat);
    /* the exact sizes are accepted */
    o.size += 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_grad(&v, &o, &sat));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_grad(&v, &out, &sat));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_u8_and_u16_match_formula);
    RUN_TEST(test_worst_case_values);
    RUN_TEST(test_smallest_input);
    RUN_TEST(test_bad_arguments_write_nothing);
    return UNITY_END();
}
