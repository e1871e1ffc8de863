#include "test_image.h"
#include "unity.h"

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

static void smooth_fill(uint32_t *tmp, uint32_t w, uint32_t h, uint32_t maxval, test_rng_t *r)
{
    uint32_t i, j;
    if (w * h > 256u * 256u) { /* caller error in a test: fail loudly */
        TEST_FAIL_MESSAGE("test texture larger than 256 x 256");
    }
    for (i = 0; i < w * h; i++) {
        tmp[i] = test_rng_range(r, 0, maxval);
    }
    /* two passes of a 3-tap horizontal and vertical box blur */
    for (j = 0; j < h; j++) {
        for (i = 1; i + 1 < w; i++) {
            tmp[j * w + i] = (tmp[j * w + i - 1] + tmp[j * w + i] + tmp[j * w + i + 1]) / 3u;
        }
    }
    for (j = 1; j + 1 < h; j++) {
        for (i = 0; i < w; i++) {
            tmp[j * w + i] = (tmp[(j - 1) * w + i] + tmp[j * w + i] + tmp[(j + 1) * w + i]) / 3u;
        }
    }
}

/* Static scratch: tests are single-threaded; 256 x 256 pixels at most
   (small enough for the emulated boards' RAM). */
static uint32_t g_tmp[256u * 256u];

void test_fill_texture_u8(uint8_t *p, uint32_t w, uint32_t h, uint32_t stride, test_rng_t *r)
{
    uint32_t i, j;
    smooth_fill(g_tmp, w, h, 255u, r);
    for (j = 0; j < h; j++) {
        for (i = 0; i < w; i++) {
            p[j * stride + i] = (uint8_t)g_tmp[j * w + i];
        }
    }
}

void test_fill_texture_u16(uint16_t *p, uint32_t w, uint32_t h, uint32_t stride,
                           uint32_t maxval, test_rng_t *r)
{
    uint32_t i, j;
    smooth_fill(g_tmp, w, h, maxval, r);
    for (j = 0; j < h; j++) {
        for (i = 0; i < w; i++) {
            p[j * stride + i] = (uint16_t)g_tmp[j * w + i];
        }
    }
}
