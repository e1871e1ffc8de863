/* img_source.c - a decoded gray image as a library source (img_source.h). */
#include "img_source.h"

#include <string.h>

static int device_read(void *context, uint32_t offset, void *buffer, uint32_t size)
{
    const img_device_t *d = context;
    if ((size_t)offset + size > d->size) {
        return SSDA_ERR_IO; /* a read past the image: the library's bug, said so */
    }
    memcpy(buffer, d->base + offset, size);
    return 0;
}

int img_source_init(ssda_source_t *s, const gray_image_t *img, img_device_t *dev, void *arena,
                    size_t arena_size)
{
    ssda_source_config_t c;
    if (arena == NULL) {
        ssda_view_t v;
        const int err = gray_image_view(img, &v);
        return err != SSDA_OK ? err : ssda_source_init_view(s, &v);
    }
    dev->base = img->pixels;
    dev->size = (size_t)img->stride * img->height;
    memset(&c, 0, sizeof c);
    c.read = device_read;
    c.context = dev;
    c.stride = img->stride;
    c.read_size = 1;
    c.arena = arena;
    c.arena_size = arena_size;
    c.width = (uint16_t)img->width;
    c.height = (uint16_t)img->height;
    c.format = img->bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8;
    c.layout = SSDA_LAYOUT_RASTER;
    return ssda_source_init(s, &c);
}
