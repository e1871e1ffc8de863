/* view.c - construction and validation of image views. */
#include "ssda/view.h"
#include "fixmath.h"

int ssda_view_check(const ssda_view_t *view)
{
    uint32_t bpp, row;
    uint64_t extent;
    if (view == NULL || view->data == NULL) {
        return SSDA_ERR_NULL;
    }
    if (view->format != (uint8_t)SSDA_PIX_U8 && view->format != (uint8_t)SSDA_PIX_U16) {
        return SSDA_ERR_FORMAT;
    }
    if (view->width == 0u || view->height == 0u) {
        return SSDA_ERR_SIZE;
    }
    bpp = view->format;
    /* width * bpp <= 131070: no overflow in uint32_t. */
    /* stride % bpp as a mask (bpp is 1 or 2): no division routine on small cores */
    if (view->stride < (uint32_t)view->width * bpp || (view->stride & (bpp - 1u)) != 0u) {
        return SSDA_ERR_STRIDE;
    }
    /* uint16_t rows must be aligned; the low address bit is all we need. */
    if (bpp == 2u && (((uintptr_t)view->data) & 1u) != 0u) {
        return SSDA_ERR_STRIDE;
    }
    /* Every row address data + y * stride must stay in the address space:
       on a 32-bit target a stride near 2^32 (a "negative", bottom-up stride
       say) would wrap them to memory before data. The view's bytes,
       (height - 1) * stride + width * bpp < 2^48, end at or below the top. */
    row = (uint32_t)view->width * bpp; /* <= 131070 */
    extent = ssda__mul_u32_u16(view->stride, (uint16_t)(view->height - 1u)) + row;
    if (extent - 1u > (uint64_t)(UINTPTR_MAX - (uintptr_t)view->data)) {
        return SSDA_ERR_STRIDE;
    }
    return SSDA_OK;
}

int ssda_view_init(ssda_view_t *view, const void *data, uint16_t width,
                   uint16_t height, uint32_t stride, ssda_pixfmt_t format)
{
    ssda_view_t v;
    int err;
    if (view == NULL) {
        return SSDA_ERR_NULL;
    }
    v.data = data;
    v.width = width;
    v.height = height;
    v.stride = stride;
    v.format = (uint8_t)format;
    err = ssda_view_check(&v);
    if (err == SSDA_OK) {
        *view = v;
    }
    return err;
}

int ssda_view_roi(ssda_view_t *roi, const ssda_view_t *src, uint16_t x,
                  uint16_t y, uint16_t w, uint16_t h)
{
    int err;
    if (roi == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(src);
    if (err != SSDA_OK) {
        return err;
    }
    if (w == 0u || h == 0u || (uint32_t)x + w > src->width ||
        (uint32_t)y + h > src->height) {
        return SSDA_ERR_SIZE;
    }
    roi->data = ssda_view_row(src, y) + (size_t)x * ssda_view_bpp(src);
    roi->stride = src->stride;
    roi->width = w;
    roi->height = h;
    roi->format = src->format;
    return SSDA_OK;
}
