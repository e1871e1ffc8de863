/* stream_source.c - source configuration: validation, geometry, defaults;
   sources and their rectangles as row sources. */
#include <string.h>
#include "stream_internal.h"
#include "fixmath.h"

/* *out = a * b + c if that fits 32 bits (device addresses are 32-bit).
   b >= 1: every call passes a stride, tile height or tile stride, each
   checked to be >= 1 before. */
static bool mul_add(uint32_t a, uint32_t b, uint32_t c, uint32_t *out)
{
    if (a > SSDA_DIV32(UINT32_MAX - c, b)) {
        return false;
    }
    *out = a * b + c;
    return true;
}

/* Pointers, pixel format, layout and read size (its default resolved):
   SSDA_OK or the documented error. */
static int check_device(ssda_source_config_t *c)
{
    const uint32_t bpp = c->format; /* 1 or 2 once checked: "% bpp" is a mask */
    if (c->read == NULL || c->arena == NULL) {
        return SSDA_ERR_NULL;
    }
    if (c->format != (uint8_t)SSDA_PIX_U8 && c->format != (uint8_t)SSDA_PIX_U16) {
        return SSDA_ERR_FORMAT;
    }
    if (c->read_size == 0u) {
        c->read_size = 1u;
    }
    if (c->layout > (uint8_t)SSDA_LAYOUT_TILED || c->read_size > SSDA_STREAM_MAX_READ_SIZE ||
        (c->read_size != 1u && (c->read_size & (bpp - 1u)) != 0u)) {
        return SSDA_ERR_ARG;
    }
    /* Features left out of this build (include/ssda/config.h). */
#ifdef SSDA_CFG_NO_U16
    if (c->format != (uint8_t)SSDA_PIX_U8) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
#ifdef SSDA_CFG_NO_TILED
    if (c->layout == (uint8_t)SSDA_LAYOUT_TILED) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
#ifdef SSDA_CFG_NO_READ_SIZE
    if (c->read_size != 1u) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
    return SSDA_OK;
}

/* *extent = bytes from the image's first stored byte to its last, rows of
   row_bytes (tile_stride's default resolved): SSDA_OK, SSDA_ERR_SIZE (not
   below 2^32) or SSDA_ERR_STRIDE. */
static int image_extent(ssda_source_config_t *c, uint32_t row_bytes, uint32_t *extent)
{
    if (STREAM_LAYOUT(c) == (uint8_t)SSDA_LAYOUT_TILED) {
        const uint32_t bpp = c->format;
        /* tiles <= 65535^2 < 2^32 */
        uint32_t tiles = SSDA_DIV32((uint32_t)c->width + c->tile_w - 1u, c->tile_w) *
                         SSDA_DIV32((uint32_t)c->height + c->tile_h - 1u, c->tile_h);
        uint32_t tile_bytes;
        if (!mul_add(c->tile_h - 1u, c->stride, row_bytes, &tile_bytes) ||
            (c->tile_stride == 0u && !mul_add(c->stride, c->tile_h, 0u, &c->tile_stride))) {
            return SSDA_ERR_SIZE;
        }
        if ((c->tile_stride & (bpp - 1u)) != 0u || c->tile_stride < tile_bytes) {
            return SSDA_ERR_STRIDE;
        }
        return mul_add(tiles - 1u, c->tile_stride, tile_bytes, extent) ? SSDA_OK : SSDA_ERR_SIZE;
    }
    return mul_add(c->height - 1u, c->stride, row_bytes, extent) ? SSDA_OK : SSDA_ERR_SIZE;
}

/* Resolve defaults in *c and check it; SSDA_OK or the documented error.
   32-bit arithmetic only (no 64-bit division on small cores). */
static int check_config(ssda_source_config_t *c)
{
    uint32_t bpp, row_bytes, extent, last;
    int err = check_device(c);
    if (err != SSDA_OK) {
        return err;
    }
    bpp = c->format; /* 1 or 2: "% bpp" below is a mask, no division routine */
    if (c->width == 0u || c->height == 0u) {
        return SSDA_ERR_SIZE;
    }
    if (STREAM_LAYOUT(c) == (uint8_t)SSDA_LAYOUT_TILED) {
        if (c->tile_w == 0u || c->tile_h == 0u) {
            return SSDA_ERR_SIZE;
        }
        row_bytes = (uint32_t)c->tile_w * bpp;
    } else {
        row_bytes = (uint32_t)c->width * bpp;
    }
    if (c->stride == 0u) {
        c->stride = row_bytes;
    }
    if ((c->offset & (bpp - 1u)) != 0u || (c->stride & (bpp - 1u)) != 0u || c->stride < row_bytes) {
        return SSDA_ERR_STRIDE;
    }
    err = image_extent(c, row_bytes, &extent);
    if (err != SSDA_OK) {
        return err;
    }
    /* Every read stays inside [offset, offset + extent) widened to
       read_size multiples, which must lie below 2^32: the last byte, and
       the last byte of its granule, are addressable. */
    if (c->offset > UINT32_MAX - (extent - 1u)) {
        return SSDA_ERR_SIZE;
    }
    last = c->offset + (extent - 1u);
    if (last - SSDA_MOD32(last, STREAM_READ_SIZE(c)) > UINT32_MAX - (STREAM_READ_SIZE(c) - 1u)) {
        return SSDA_ERR_SIZE;
    }
    if ((((uintptr_t)c->arena) & 3u) != 0u ||
        c->arena_size < SSDA_SOURCE_SIZE(STREAM_LAYOUT(c), 1u, 1u, c->format, STREAM_READ_SIZE(c),
                                         c->tile_w)) {
        return SSDA_ERR_BUFFER;
    }
    return SSDA_OK;
}

int ssda_source_init(ssda_source_t *src, const ssda_source_config_t *cfg)
{
    ssda_source_config_t c;
    ssda_rect_t all;
    int err;
    if (src == NULL || cfg == NULL) {
        return SSDA_ERR_NULL;
    }
    c = *cfg;
    err = check_config(&c);
    if (err != SSDA_OK) {
        return err;
    }
    /* Checked: *src is filled in place from here (no copy of the whole
       source on the stack). */
    (void)memset(src, 0, sizeof *src);
    src->cfg = c;
    all.x = 0u;
    all.y = 0u;
    all.width = c.width;
    all.height = c.height;
    /* Default plate: whole rows if one fits, as many rows as fit. A 1 x 1
       plate fits (checked above), so this cannot fail. */
    (void)ssda__stream_plate_plan(src, &all, 1u, 1u, 0u, 0u, &src->plate);
    src->magic = SSDA__MAGIC_SOURCE;
    return SSDA_OK;
}

int ssda_source_init_view(ssda_source_t *src, const ssda_view_t *view)
{
    int err;
    if (src == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(view);
    if (err != SSDA_OK) {
        return err;
    }
#ifdef SSDA_CFG_NO_U16
    if (view->format != (uint8_t)SSDA_PIX_U8) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
    (void)memset(src, 0, sizeof *src);
    src->view = (const uint8_t *)view->data;
    src->cfg.stride = view->stride;
    src->cfg.width = view->width;
    src->cfg.height = view->height;
    src->cfg.format = view->format;
    src->magic = SSDA__MAGIC_SOURCE;
    return SSDA_OK;
}

int ssda__stream_rect(const ssda_source_t *s, const ssda_rect_t *in, ssda_rect_t *out)
{
    if (in == NULL) {
        out->x = 0u;
        out->y = 0u;
        out->width = s->cfg.width;
        out->height = s->cfg.height;
        return SSDA_OK;
    }
    if (in->width == 0u || in->height == 0u ||
        (uint32_t)in->x + in->width > s->cfg.width ||
        (uint32_t)in->y + in->height > s->cfg.height) {
        return SSDA_ERR_SIZE;
    }
    *out = *in;
    return SSDA_OK;
}

int ssda_source_row(ssda_source_t *src, uint32_t x, uint32_t y, uint32_t n,
                    const uint8_t **px)
{
    ssda_rect_t all;
    if (src == NULL || px == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(src)) {
        return SSDA_ERR_STATE;
    }
    if (n == 0u || x >= src->cfg.width || n > src->cfg.width - x || y >= src->cfg.height) {
        return SSDA_ERR_SIZE;
    }
    if (src->view != NULL) {
        *px = src->view + (size_t)y * src->cfg.stride + (size_t)x * src->cfg.format;
        return SSDA_OK;
    }
    (void)ssda__stream_rect(src, NULL, &all);
    if (n > src->plate.pw) {
        /* reshape for this width: whole rows if they fit, else n px */
        int err = ssda__stream_plate_shape(src, &all, n, 1u, 0u, 0u);
        if (err != SSDA_OK) {
            return err;
        }
    }
    src->plate.region = all;
    src->plate.qy = src->plate.ph; /* a miss jumps a whole plate: reading in order is read once */
    return ssda__stream_fetch(src, x, y, n, px);
}

/* A streamed source as a row source's fetch (ctx: the source). */
static int rows_fetch(void *ctx, uint32_t x, uint32_t y, uint32_t n, const uint8_t **px)
{
    ssda_source_t *s = ctx;
    return ssda__stream_fetch(s, x, y, n, px);
}

void ssda__stream_rows(ssda__rows_t *rows, ssda_source_t *s, const ssda_rect_t *r)
{
    const ssda_source_config_t *c = &s->cfg;
    if (s->view != NULL) {
        ssda__rows_mem(rows, s->view, c->stride, c->width, c->height, c->format);
    } else {
        ssda__rows_dev(rows, rows_fetch, s, c->width, c->height, c->format);
    }
    if (r != NULL) {
        ssda__rows_sub(rows, rows, r->x, r->y, r->width, r->height);
    }
}
