/* png_rgb.c - PNG to interleaved RGB with libpng, samples as stored
   (png_io.h, "colour"); the libpng steps it shares with png_io.c are in
   png_read.c. */
#include "png_io.h"
#include "png_read.h"
#include "tool_err.h"

#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

/* State the setjmp-protected part touches, kept outside its frame. */
typedef struct {
    pngread_t b; /* file, libpng structs, error texts, every decoded row */
    rgb_image_t out;
    png_source_info_t src;
} rgb_reader_t;

/* One decoded row (1..4 channels, 8 or 16-bit big-endian) to RGB. */
static void row_to_rgb(const png_byte *in, uint32_t width, int channels, int bits, void *out)
{
    const size_t bps = bits == 16 ? 2u : 1u;
    uint32_t x;
    int k;
    for (x = 0; x < width; x++) {
        const png_byte *p = in + (size_t)x * (size_t)channels * bps;
        for (k = 0; k < 3; k++) {
            /* gray (+alpha): the one band three times; colour: R, G, B */
            const png_byte *s = p + (channels >= 3 ? (size_t)k * bps : 0u);
            if (bits == 16) {
                ((uint16_t *)out)[3u * x + (uint32_t)k] = (uint16_t)((s[0] << 8) | s[1]);
            } else {
                ((uint8_t *)out)[3u * x + (uint32_t)k] = s[0];
            }
        }
    }
}

static int read_protected(rgb_reader_t *r)
{
    png_uint_32 w, h, y;
    int bit_depth, color_type, interlace, channels, bits;
    size_t rowbytes;
    if (setjmp(png_jmpbuf(r->b.png))) {
        return -1;
    }
    if (pngread_header(&r->b, &w, &h, &bit_depth, &color_type, &interlace, &r->src) != 0) {
        return -1;
    }
    (void)png_set_interlace_handling(r->b.png);
    png_read_update_info(r->b.png, r->b.info);
    channels = png_get_channels(r->b.png, r->b.info);
    bits = png_get_bit_depth(r->b.png, r->b.info);
    rowbytes = png_get_rowbytes(r->b.png, r->b.info);
    if (pngread_check_size(&r->b, &r->src, w, h, 3u * (bits == 16 ? 2u : 1u),
                            (double)rowbytes * (double)h) != 0) {
        return -1;
    }
    r->out.pixels = malloc((size_t)w * h * 3u * (bits == 16 ? 2u : 1u));
    if (r->out.pixels == NULL) {
        snprintf(r->b.why, sizeof r->b.why, "out of memory for %lu x %lu pixels",
                 (unsigned long)w, (unsigned long)h);
        return -1;
    }
    if (pngread_rows(&r->b, h, rowbytes) != 0) {
        return -1;
    }
    png_read_end(r->b.png, NULL);
    r->out.width = w;
    r->out.height = h;
    r->out.bits = (uint8_t)bits;
    r->out.stride = w * 3u * (bits == 16 ? 2u : 1u);
    for (y = 0; y < h; y++) {
        row_to_rgb(r->b.rows[y], w, channels, bits,
                   (uint8_t *)r->out.pixels + (size_t)y * r->out.stride);
    }
    return 0;
}

void rgb_image_free(rgb_image_t *img)
{
    free(img->pixels);
    memset(img, 0, sizeof *img);
}

int png_read_rgb(const char *path, rgb_image_t *img, png_source_info_t *info, char *err,
                 size_t errlen)
{
    rgb_reader_t *r = calloc(1, sizeof *r);
    int rc = -1;
    if (r == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", path);
        return -1;
    }
    if (pngread_open(&r->b, path, err, errlen) != 0) {
        goto done;
    }
    if (read_protected(r) != 0) {
        pngread_fail(&r->b, path, err, errlen);
        goto done;
    }
    *img = r->out;
    memset(&r->out, 0, sizeof r->out);
    if (info != NULL) {
        *info = r->src;
    }
    rc = 0;
done:
    pngread_close(&r->b);
    free(r->out.pixels);
    free(r);
    return rc;
}
