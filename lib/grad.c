/* grad.c - the seed's Fig. 8 differential operator over a view. */
#include "ssda/grad.h"

/* Column terms at column k of the three input rows: the top-minus-bottom
   difference and the three-pixel column sum. */
typedef struct {
    int32_t diff; /* top - bottom, in [-65535, 65535] */
    int32_t sum;  /* top + middle + bottom, in [0, 196605] */
} col_t;

static col_t column(const uint8_t *r0, const uint8_t *r1, const uint8_t *r2, bool u16,
                    uint32_t k)
{
    col_t c;
    int32_t a, b, m;
    if (u16) {
        a = ((const uint16_t *)(const void *)r0)[k];
        m = ((const uint16_t *)(const void *)r1)[k];
        b = ((const uint16_t *)(const void *)r2)[k];
    } else {
        a = r0[k];
        m = r1[k];
        b = r2[k];
    }
    c.diff = a - b;
    c.sum = a + m + b;
    return c;
}

static uint32_t abs_i32(int32_t v)
{
    /* |v| <= 196605 here, so negation cannot overflow */
    return v < 0 ? (uint32_t)(-v) : (uint32_t)v;
}

/* E' of one output row; returns how many samples saturated (<= w - 2). */
static uint32_t grad_row(const uint8_t *r0, const uint8_t *r1, const uint8_t *r2, bool u16,
                         uint32_t w, const ssda_grad_out_t *out, uint8_t *dst)
{
    const uint32_t omax = out->format == (uint8_t)SSDA_PIX_U8 ? 255u : 65535u;
    uint32_t sat = 0u;
    uint32_t i;
    col_t c0 = column(r0, r1, r2, u16, 0u);
    col_t c1 = column(r0, r1, r2, u16, 1u);
    for (i = 0u; i + 2u < w; i++) {
        const col_t c2 = column(r0, r1, r2, u16, i + 2u);
        /* A+B+C-G-H-I = sum of the three column differences, |.| <= 196605;
           A+D+G-C-F-I = left column sum - right column sum, |.| <= 196605;
           e = their absolute values added, <= 4 * 65535 = 262140 (see grad.h) */
        const uint32_t e = abs_i32(c0.diff + c1.diff + c2.diff) + abs_i32(c0.sum - c2.sum);
        uint32_t v = e >> out->shift;
        if (v > omax) {
            v = omax;
            sat++;
        }
        if (out->format == (uint8_t)SSDA_PIX_U8) {
            dst[i] = (uint8_t)v;
        } else {
            ((uint16_t *)(void *)dst)[i] = (uint16_t)v;
        }
        c0 = c1;
        c1 = c2;
    }
    return sat;
}

int ssda_grad(const ssda_view_t *src, const ssda_grad_out_t *out, uint32_t *saturated)
{
    uint32_t w, h, obpp, ostride, y;
    uint32_t sat = 0u; /* <= (w-2) * (h-2) <= 65533^2 < 2^32 */
    bool u16;
    int err;
    if (src == NULL || out == NULL || out->data == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(src);
    if (err != SSDA_OK) {
        return err;
    }
    w = src->width;
    h = src->height;
    if (w < 3u || h < 3u) {
        return SSDA_ERR_SIZE;
    }
    if (out->format != (uint8_t)SSDA_PIX_U8 && out->format != (uint8_t)SSDA_PIX_U16) {
        return SSDA_ERR_FORMAT;
    }
    if (out->shift > 31u) {
        return SSDA_ERR_ARG;
    }
    obpp = out->format;
    ostride = out->stride != 0u ? out->stride : (w - 2u) * obpp;
    if (ostride < (w - 2u) * obpp || (ostride % obpp) != 0u ||
        (obpp == 2u && (((uintptr_t)out->data) & 1u) != 0u)) {
        return SSDA_ERR_STRIDE;
    }
    /* SSDA_GRAD_SIZE_STRIDED in 64 bits: in a 32-bit size_t a large stride
       would wrap it (h = 5, stride 2^31: 2^32 + 3 bytes read as 3).
       (h - 3) * stride < 2^16 * 2^32; the total < 2^49. */
    if ((uint64_t)out->size <
        ((uint64_t)h - 3u) * ostride + ((uint64_t)w - 2u) * obpp) {
        return SSDA_ERR_BUFFER;
    }
    u16 = src->format == (uint8_t)SSDA_PIX_U16;
    for (y = 0u; y + 2u < h; y++) {
        uint8_t *dst = (uint8_t *)out->data + (size_t)y * ostride;
        sat += grad_row(ssda_view_row(src, y), ssda_view_row(src, y + 1u),
                        ssda_view_row(src, y + 2u), u16, w, out, dst);
    }
    if (saturated != NULL) {
        *saturated = sat;
    }
    return SSDA_OK;
}
