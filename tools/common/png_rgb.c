/* png_rgb.c - PNG to interleaved RGB with libpng, samples as stored
   (png_io.h, "colour"). */
#include "png_io.h"
#include "tool_err.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    char msg[160];
} rgb_err_t;

static void on_error(png_structp png, png_const_charp text)
{
    rgb_err_t *e = (rgb_err_t *)png_get_error_ptr(png);
    if (e != NULL) {
        snprintf(e->msg, sizeof e->msg, "%s", text);
    }
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp text)
{
    (void)png;
    (void)text;
}

/* State the setjmp-protected part touches, kept outside its frame. */
typedef struct {
    FILE *fp;
    png_structp png;
    png_infop info;
    png_bytepp rows; /* every decoded row (interlaced or not: simple) */
    size_t nrows;
    rgb_image_t out;
    rgb_err_t e;
    png_source_info_t src;
    char why[200];
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
    double need;
    if (setjmp(png_jmpbuf(r->png))) {
        return -1;
    }
    png_init_io(r->png, r->fp);
    png_set_sig_bytes(r->png, 8);
    png_set_user_limits(r->png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    png_read_info(r->png, r->info);
    png_get_IHDR(r->png, r->info, &w, &h, &bit_depth, &color_type, &interlace, NULL, NULL);
    r->src.source_bits = (uint32_t)bit_depth;
    r->src.color_type = color_type;
    r->src.was_color = (color_type & PNG_COLOR_MASK_COLOR) != 0;
    r->src.had_alpha = (color_type & PNG_COLOR_MASK_ALPHA) != 0 ||
                       png_get_valid(r->png, r->info, PNG_INFO_tRNS) != 0;
    snprintf(r->src.description, sizeof r->src.description, "%d-bit %s", bit_depth,
             color_type == PNG_COLOR_TYPE_PALETTE ? "palette"
             : (color_type & PNG_COLOR_MASK_COLOR) != 0
                 ? ((color_type & PNG_COLOR_MASK_ALPHA) != 0 ? "RGBA" : "RGB")
                 : ((color_type & PNG_COLOR_MASK_ALPHA) != 0 ? "gray+alpha" : "gray"));
    if (w > SSDA_MAX_DIM || h > SSDA_MAX_DIM) {
        snprintf(r->why, sizeof r->why,
                 "image is %lu x %lu pixels; the largest accepted is 65535 x 65535",
                 (unsigned long)w, (unsigned long)h);
        return -1;
    }
    if (color_type == PNG_COLOR_TYPE_PALETTE) {
        png_set_palette_to_rgb(r->png);
    }
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) {
        png_set_expand_gray_1_2_4_to_8(r->png);
    }
    (void)png_set_interlace_handling(r->png);
    png_read_update_info(r->png, r->info);
    channels = png_get_channels(r->png, r->info);
    bits = png_get_bit_depth(r->png, r->info);
    rowbytes = png_get_rowbytes(r->png, r->info);
    need = (double)w * h * 3.0 * (bits == 16 ? 2.0 : 1.0) + (double)rowbytes * h;
    if (need > (double)PNG_IO_MAX_BYTES) {
        snprintf(r->why, sizeof r->why, "image is %lu x %lu pixels; decoding it needs %.0f MB, "
                 "more than the %lu MB limit", (unsigned long)w, (unsigned long)h, need / 1e6,
                 (unsigned long)(PNG_IO_MAX_BYTES / 1000000u));
        return -1;
    }
    r->out.pixels = malloc((size_t)w * h * 3u * (bits == 16 ? 2u : 1u));
    r->rows = calloc(h, sizeof *r->rows);
    if (r->out.pixels == NULL || r->rows == NULL) {
        snprintf(r->why, sizeof r->why, "out of memory for %lu x %lu pixels", (unsigned long)w,
                 (unsigned long)h);
        return -1;
    }
    r->nrows = h;
    for (y = 0; y < h; y++) {
        if ((r->rows[y] = malloc(rowbytes)) == NULL) {
            snprintf(r->why, sizeof r->why, "out of memory");
            return -1;
        }
    }
    png_read_image(r->png, r->rows);
    png_read_end(r->png, NULL);
    r->out.width = w;
    r->out.height = h;
    r->out.bits = (uint8_t)bits;
    r->out.stride = w * 3u * (bits == 16 ? 2u : 1u);
    for (y = 0; y < h; y++) {
        row_to_rgb(r->rows[y], w, channels, bits, (uint8_t *)r->out.pixels + (size_t)y * r->out.stride);
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
    png_byte sig[8];
    size_t got, y;
    int rc = -1;
    if (r == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", path);
        return -1;
    }
    r->fp = fopen(path, "rb");
    if (r->fp == NULL) {
        tool_set_err(err, errlen, "cannot open '%s': %s", path, strerror(errno));
        goto done;
    }
    got = fread(sig, 1, sizeof sig, r->fp);
    if (got == 0) {
        tool_set_err(err, errlen, "'%s' is empty, not a PNG file", path);
        goto done;
    }
    if (got < sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        tool_set_err(err, errlen, "'%s' is not a PNG file (bad signature)", path);
        goto done;
    }
    r->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r->e, on_error, on_warning);
    if (r->png == NULL || (r->info = png_create_info_struct(r->png)) == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", path);
        goto done;
    }
    if (read_protected(r) != 0) {
        if (r->why[0] != '\0') {
            tool_set_err(err, errlen, "'%s': %s", path, r->why);
        } else {
            const char *m = strcmp(r->e.msg, "Read Error") == 0 ? "file ends early"
                            : r->e.msg[0] != '\0'            ? r->e.msg
                                                             : "libpng error";
            tool_set_err(err, errlen, "'%s': corrupt or truncated PNG (%s)", path, m);
        }
        goto done;
    }
    *img = r->out;
    memset(&r->out, 0, sizeof r->out);
    if (info != NULL) {
        *info = r->src;
    }
    rc = 0;
done:
    if (r->rows != NULL) {
        for (y = 0; y < r->nrows; y++) {
            free(r->rows[y]);
        }
        free(r->rows);
    }
    if (r->png != NULL) {
        png_destroy_read_struct(&r->png, r->info != NULL ? &r->info : NULL, NULL);
    }
    if (r->fp != NULL) {
        fclose(r->fp);
    }
    free(r->out.pixels);
    free(r);
    return rc;
}
