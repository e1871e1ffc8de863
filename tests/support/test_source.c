#include <string.h>
#include "test_source.h"
#include "unity.h"

void test_source_init(test_source_t *dev, uint8_t *bytes, uint32_t capacity, uint32_t read_size)
{
    memset(dev, 0, sizeof *dev);
    dev->bytes = bytes;
    dev->capacity = capacity;
    dev->size = capacity;
    dev->read_size = read_size != 0u ? read_size : 1u;
    dev->fail_code = SSDA_ERR_IO;
    dev->fail_at_read = -1;
    dev->fail_after = -1;
}

void test_source_reset(test_source_t *dev)
{
    dev->fail_at_read = -1;
    dev->fail_after = -1;
    dev->reads = 0u;
    dev->bytes_read = 0u;
    dev->failures = 0u;
    dev->contract_violations = 0u;
}

int test_source_read(void *context, uint32_t offset, void *buffer, uint32_t size)
{
    test_source_t *dev = (test_source_t *)context;
    uint64_t index = dev->reads++;
    if (size == 0u || offset % dev->read_size != 0u || size % dev->read_size != 0u ||
        (uint64_t)offset + size > dev->size) {
        dev->contract_violations++;
        return SSDA_ERR_IO;
    }
    if ((dev->fail_at_read >= 0 && index == (uint64_t)dev->fail_at_read) ||
        (dev->fail_after >= 0 && dev->bytes_read + size > (uint64_t)dev->fail_after)) {
        dev->failures++;
        /* a failed read may have scribbled on the buffer: make that visible */
        memset(buffer, 0x5A, size);
        return dev->fail_code;
    }
    memcpy(buffer, dev->bytes + offset, size);
    dev->bytes_read += size;
    return 0;
}

/* Resolve the strides as the library documents them. */
static void resolve(const ssda_source_config_t *cfg, uint32_t *stride, uint32_t *tile_stride)
{
    uint32_t bpp = cfg->format;
    uint32_t row = cfg->layout == SSDA_LAYOUT_TILED ? cfg->tile_w * bpp : cfg->width * bpp;
    *stride = cfg->stride != 0u ? cfg->stride : row;
    *tile_stride = cfg->tile_stride != 0u ? cfg->tile_stride : *stride * cfg->tile_h;
}

uint32_t test_source_extent(const ssda_source_config_t *cfg)
{
    uint32_t stride, tile_stride, rs = cfg->read_size > 1u ? cfg->read_size : 1u;
    uint64_t end;
    resolve(cfg, &stride, &tile_stride);
    if (cfg->layout == SSDA_LAYOUT_TILED) {
        uint64_t across = (cfg->width + cfg->tile_w - 1u) / cfg->tile_w;
        uint64_t down = (cfg->height + cfg->tile_h - 1u) / cfg->tile_h;
        end = (across * down - 1u) * tile_stride + (uint64_t)(cfg->tile_h - 1u) * stride +
              (uint64_t)cfg->tile_w * cfg->format;
    } else {
        end = (uint64_t)(cfg->height - 1u) * stride + (uint64_t)cfg->width * cfg->format;
    }
    end += cfg->offset;
    end = (end + rs - 1u) / rs * rs;
    TEST_ASSERT_TRUE_MESSAGE(end <= UINT32_MAX, "test device larger than 4 GB");
    return (uint32_t)end;
}

void test_source_store(test_source_t *dev, const ssda_source_config_t *cfg,
                       const ssda_view_t *img)
{
    uint32_t stride, tile_stride, x, y, bpp = cfg->format;
    resolve(cfg, &stride, &tile_stride);
    dev->size = test_source_extent(cfg);
    TEST_ASSERT_TRUE_MESSAGE(dev->size <= dev->capacity, "test device too small");
    TEST_ASSERT_EQUAL_UINT(cfg->width, img->width);
    TEST_ASSERT_EQUAL_UINT(cfg->height, img->height);
    TEST_ASSERT_EQUAL_UINT(cfg->format, img->format);
    memset(dev->bytes, TEST_SOURCE_POISON, dev->size);
    for (y = 0; y < cfg->height; y++) {
        const uint8_t *src = (const uint8_t *)img->data + (size_t)y * img->stride;
        for (x = 0; x < cfg->width; x++) {
            uint64_t off;
            if (cfg->layout == SSDA_LAYOUT_TILED) {
                uint32_t across = (cfg->width + cfg->tile_w - 1u) / cfg->tile_w;
                uint32_t tx = x / cfg->tile_w, ty = y / cfg->tile_h;
                off = cfg->offset + ((uint64_t)ty * across + tx) * tile_stride +
                      (uint64_t)(y % cfg->tile_h) * stride + (uint64_t)(x % cfg->tile_w) * bpp;
            } else {
                off = cfg->offset + (uint64_t)y * stride + (uint64_t)x * bpp;
            }
            memcpy(dev->bytes + off, src + (size_t)x * bpp, bpp);
        }
    }
}

ssda_source_config_t test_source_config(test_source_t *dev, const ssda_view_t *img,
                                        uint8_t layout, uint16_t tile_w, uint16_t tile_h,
                                        uint32_t offset, uint32_t stride,
                                        uint32_t tile_stride, uint32_t read_size,
                                        void *arena, size_t arena_size)
{
    ssda_source_config_t c;
    memset(&c, 0, sizeof c);
    c.read = test_source_read;
    c.context = dev;
    c.offset = offset;
    c.stride = stride;
    c.tile_stride = tile_stride;
    c.read_size = read_size;
    c.arena = arena;
    c.arena_size = arena_size;
    c.width = img->width;
    c.height = img->height;
    c.tile_w = tile_w;
    c.tile_h = tile_h;
    c.format = img->format;
    c.layout = layout;
    return c;
}
