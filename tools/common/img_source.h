/*
 * img_source.h - a decoded gray image as a library source: in RAM (a view)
 * or block-streamed through a read callback over its pixels, as a device
 * would be read, so that --mem and the benchmarks measure the library's
 * plates and reads.
 */
#ifndef SSDA_IMG_SOURCE_H
#define SSDA_IMG_SOURCE_H

#include <stddef.h>
#include <stdint.h>

#include "png_io.h"
#include "ssda/stream.h"

/* The "device" a streamed source reads: the image's packed pixels. */
typedef struct {
    const uint8_t *base;
    size_t size; /* bytes */
} img_device_t;

/*
 * Make *s a source over img: with arena NULL a view of the pixels (dev
 * unused), else raster rows read through dev within arena_size bytes of
 * plates. img and dev must outlive s. Returns an ssda error code
 * (ssda_source_init's, e.g. SSDA_ERR_BUFFER for an arena below one row).
 */
int img_source_init(ssda_source_t *s, const gray_image_t *img, img_device_t *dev, void *arena,
                    size_t arena_size);

#endif /* SSDA_IMG_SOURCE_H */
