#include "unity.h"
#include "test_image.h"

uint32_t test_px(const ssda_view_t *v, uint32_t x, uint32_t y)
{
    const uint8_t *row = (const uint8_t *)v->data + (uint64_t)y * v->stride;
    if (v->format == SSDA_PIX_U8) {
        return row[x];
    }
    return ((const uint16_t *)(const void *)row)[x];
}

uint64_t test_sad(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y)
{
    uint64_t s = 0;
    uint32_t i, j;
    for (j = 0; j < win->height; j++) {
        for (i = 0; i < win->width; i++) {
            uint32_t a = test_px(area, x + i, y + j), b = test_px(win, i, j);
            s += a > b ? a - b : b - a;
        }
    }
    return s;
}

void test_best(const ssda_view_t *area, const ssda_view_t *win,
               uint32_t *bx, uint32_t *by, uint64_t *bsad)
{
    uint32_t x, y;
    int first = 1;
    for (y = 0; y + win->height <= area->height; y++) {
        for (x = 0; x + win->width <= area->width; x++) {
            uint64_t s = test_sad(area, win, x, y);
            /* raster order visits (y, x) ascending, so strict < keeps the tie rule */
            if (first || s < *bsad) {
                *bsad = s;
                *bx = x;
                *by = y;
                first = 0;
            }
        }
    }
}

/* Pixel i of a u8 (bpp 1) or u16 (bpp 2) buffer. */
static uint32_t px_get(const void *p, uint32_t bpp, size_t i)
{
    return bpp == 1u ? ((const uint8_t *)p)[i] : ((const uint16_t *)p)[i];
}

static void px_set(void *p, uint32_t bpp, size_t i, uint32_t v)
{
    if (bpp == 1u) {
        ((uint8_t *)p)[i] = (uint8_t)v;
    } else {
        ((uint16_t *)p)[i] = (uint16_t)v;
    }
}

/* Random values 0..maxval, then two passes of a 3-tap box blur (horizontal,
   then vertical), each in place in reading order. Every value stays
   <= maxval, so the pixels hold them exactly: no scratch buffer, any size
   (the same pixels as the former 256 x 256 uint32_t scratch version). */
static void smooth_fill(void *p, uint32_t bpp, uint32_t w, uint32_t h, uint32_t stride,
                        uint32_t maxval, test_rng_t *r)
{
    uint32_t i, j;
    for (j = 0; j < h; j++) {
        for (i = 0; i < w; i++) {
            px_set(p, bpp, (size_t)j * stride + i, test_rng_range(r, 0, maxval));
        }
    }
    for (j = 0; j < h; j++) {
        for (i = 1; i + 1 < w; i++) {
            size_t k = (size_t)j * stride + i;
            px_set(p, bpp, k, (px_get(p, bpp, k - 1u) + px_get(p, bpp, k) + px_get(p, bpp, k + 1u)) / 3u);
        }
    }
    for (j = 1; j + 1 < h; j++) {
        for (i = 0; i < w; i++) {
            size_t k = (size_t)j * stride + i;
            px_set(p, bpp, k,
                   (px_get(p, bpp, k - stride) + px_get(p, bpp, k) + px_get(p, bpp, k + stride)) / 3u);
        }
    }
}

void test_fill_texture_u8(uint8_t *p, uint32_t w, uint32_t h, uint32_t stride, test_rng_t *r)
{
    smooth_fill(p, 1u, w, h, stride, 255u, r);
}

void test_fill_texture_u16(uint16_t *p, uint32_t w, uint32_t h, uint32_t stride,
                           uint32_t maxval, test_rng_t *r)
{
    smooth_fill(p, 2u, w, h, stride, maxval, r);
}

void test_fill_texture_12bit(uint16_t *p16, uint8_t *p8, uint32_t w, uint32_t h,
                             test_rng_t *r)
{
    uint32_t x, y;
    for (x = 0; x < w * h; x++) {
        p16[x] = (uint16_t)test_rng_range(r, 0, 4095);
    }
    for (y = 0; y + 1u < h; y++) {
        for (x = 0; x + 1u < w; x++) {
            uint32_t s = (uint32_t)p16[y * w + x] + p16[y * w + x + 1u] + p16[(y + 1u) * w + x] +
                         p16[(y + 1u) * w + x + 1u];
            p16[y * w + x] = (uint16_t)(s / 4u);
        }
    }
    for (x = 0; x < w * h; x++) {
        p8[x] = (uint8_t)(p16[x] >> 4);
    }
}

void test_view_pair(int wide, const void *a16, const void *b16, const void *a8, const void *b8,
                    uint16_t w, uint16_t h, ssda_view_t *a, ssda_view_t *b)
{
    const ssda_pixfmt_t fmt = wide ? SSDA_PIX_U16 : SSDA_PIX_U8;
    const uint32_t stride = wide ? 2u * w : w;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(a, wide ? a16 : a8, w, h, stride, fmt));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(b, wide ? b16 : b8, w, h, stride, fmt));
}
