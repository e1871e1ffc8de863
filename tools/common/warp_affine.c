/* warp_affine.c - bilinear resampling through an affine map (warp_affine.h). */
#include "warp_affine.h"

#include <math.h>

static uint32_t get(const gray_image_t *g, uint32_t x, uint32_t y)
{
    return gray_image_get(g, x, y);
}

static void put(gray_image_t *g, uint32_t x, uint32_t y, uint32_t v)
{
    if (g->bits == 8) {
        ((uint8_t *)g->pixels)[(size_t)y * g->stride + x] = (uint8_t)v;
    } else {
        ((uint16_t *)g->pixels)[(size_t)y * (g->stride / 2u) + x] = (uint16_t)v;
    }
}

int warp_affine(const gray_image_t *mov, const double A[6], uint32_t ref_w, uint32_t ref_h,
                uint32_t fill, gray_image_t *out)
{
    uint32_t x, y;
    if (gray_image_alloc(out, ref_w, ref_h, mov->bits) != 0) {
        return -1;
    }
    for (y = 0; y < ref_h; y++) {
        for (x = 0; x < ref_w; x++) {
            const double u = A[0] * x + A[1] * y + A[2], v = A[3] * x + A[4] * y + A[5];
            const double fu = floor(u), fv = floor(v);
            const double tu = u - fu, tv = v - fv;
            uint32_t val = fill;
            if (fu >= 0 && fv >= 0 && fu + 1 < mov->width && fv + 1 < mov->height) {
                const uint32_t ix = (uint32_t)fu, iy = (uint32_t)fv;
                const double p = (1 - tu) * (1 - tv) * get(mov, ix, iy) +
                                 tu * (1 - tv) * get(mov, ix + 1, iy) +
                                 (1 - tu) * tv * get(mov, ix, iy + 1) +
                                 tu * tv * get(mov, ix + 1, iy + 1);
                val = (uint32_t)(p + 0.5);
            }
            put(out, x, y, val);
        }
    }
    return 0;
}
