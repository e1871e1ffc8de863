/* png_read.c - libpng reading steps shared by png_io.c and png_rgb.c
   (png_read.h). */
#include "png_read.h"
#include "tool_err.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

void pngread_on_error(png_structp png, png_const_charp text)
{
    pngread_err_t *ctx = (pngread_err_t *)png_get_error_ptr(png);
    if (ctx != NULL) {
        snprintf(ctx->msg, sizeof ctx->msg, "%s", text);
    }
    png_longjmp(png, 1);
}

void pngread_on_warning(png_structp png, png_const_charp text)
{
    (void)png;
    (void)text;
}

int pngread_open(pngread_t *b, const char *path, char *err, size_t errlen)
{
    png_byte sig[8];
    size_t got;
    b->fp = fopen(path, "rb");
    if (b->fp == NULL) {
        tool_set_err(err, errlen, "cannot open '%s': %s", path, strerror(errno));
        return -1;
    }
    errno = 0;
    got = fread(sig, 1, sizeof sig, b->fp);
    if (got == 0 && ferror(b->fp)) { /* e.g. a directory: "Is a directory" */
        tool_set_err(err, errlen, "cannot read '%s': %s", path,
                     strerror(errno != 0 ? errno : EIO));
        return -1;
    }
    if (got == 0) {
        tool_set_err(err, errlen, "'%s' is empty, not a PNG file", path);
        return -1;
    }
    if (got < sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        tool_set_err(err, errlen, "'%s' is not a PNG file (bad signature)", path);
        return -1;
    }
    b->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &b->ectx, pngread_on_error,
                                    pngread_on_warning);
    if (b->png == NULL || (b->info = png_create_info_struct(b->png)) == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", path);
        return -1;
    }
    return 0;
}

static const char *color_name(int color_type)
{
    switch (color_type) {
    case PNG_COLOR_TYPE_GRAY: return "gray";
    case PNG_COLOR_TYPE_GRAY_ALPHA: return "gray+alpha";
    case PNG_COLOR_TYPE_RGB: return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA: return "RGBA";
    case PNG_COLOR_TYPE_PALETTE: return "palette";
    default: return "unknown";
    }
}

int pngread_header(pngread_t *b, png_uint_32 *w, png_uint_32 *h, int *bit_depth,
                    int *color_type, int *interlace, png_source_info_t *src)
{
    png_init_io(b->png, b->fp);
    png_set_sig_bytes(b->png, 8);
    /* Our own size limit gives a clearer message than libpng's default one. */
    png_set_user_limits(b->png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    png_read_info(b->png, b->info);
    png_get_IHDR(b->png, b->info, w, h, bit_depth, color_type, interlace, NULL, NULL);
    src->source_bits = (uint32_t)*bit_depth;
    src->color_type = *color_type;
    src->was_color = (*color_type & PNG_COLOR_MASK_COLOR) != 0;
    src->had_alpha = (*color_type & PNG_COLOR_MASK_ALPHA) != 0 ||
                     png_get_valid(b->png, b->info, PNG_INFO_tRNS) != 0;
    snprintf(src->description, sizeof src->description, "%d-bit %s%s", *bit_depth,
             color_name(*color_type), *interlace != PNG_INTERLACE_NONE ? ", interlaced" : "");
    if (*w > SSDA_MAX_DIM || *h > SSDA_MAX_DIM) {
        snprintf(b->why, sizeof b->why,
                 "image is %lu x %lu pixels; the largest accepted is 65535 x 65535",
                 (unsigned long)*w, (unsigned long)*h);
        return -1;
    }
    if (*color_type == PNG_COLOR_TYPE_PALETTE) {
        png_set_palette_to_rgb(b->png); /* RGBA when a tRNS chunk exists */
    }
    if (*color_type == PNG_COLOR_TYPE_GRAY && *bit_depth < 8) {
        png_set_expand_gray_1_2_4_to_8(b->png); /* scaled to 0..255, tRNS not expanded */
    }
    return 0;
}

int pngread_check_size(pngread_t *b, const png_source_info_t *src, png_uint_32 w,
                        png_uint_32 h, size_t out_bpp, double buffer_bytes)
{
    double need = (double)w * (double)h * (double)out_bpp + buffer_bytes;
    if (need > (double)PNG_IO_MAX_BYTES) {
        snprintf(b->why, sizeof b->why,
                 "image is %lu x %lu pixels (%s); decoding it needs %.0f MB, more than "
                 "the %lu MB limit",
                 (unsigned long)w, (unsigned long)h, src->description, need / 1e6,
                 (unsigned long)(PNG_IO_MAX_BYTES / 1000000u));
        return -1;
    }
    return 0;
}

int pngread_rows(pngread_t *b, png_uint_32 h, size_t rowbytes)
{
    size_t y;
    b->rows = calloc(h, sizeof *b->rows);
    if (b->rows == NULL) {
        snprintf(b->why, sizeof b->why, "out of memory");
        return -1;
    }
    b->nrows = h;
    for (y = 0; y < h; y++) {
        if ((b->rows[y] = malloc(rowbytes)) == NULL) {
            snprintf(b->why, sizeof b->why, "out of memory");
            return -1;
        }
    }
    png_read_image(b->png, b->rows);
    return 0;
}

void pngread_fail(const pngread_t *b, const char *path, char *err, size_t errlen)
{
    if (b->why[0] != '\0') {
        tool_set_err(err, errlen, "'%s': %s", path, b->why);
    } else {
        /* libpng's fread failure at end of file says just "Read Error" */
        const char *m = strcmp(b->ectx.msg, "Read Error") == 0 ? "file ends early"
                        : b->ectx.msg[0] != '\0'            ? b->ectx.msg
                                                            : "libpng error";
        tool_set_err(err, errlen, "'%s': corrupt or truncated PNG (%s)", path, m);
    }
}

void pngread_close(pngread_t *b)
{
    if (b->rows != NULL) {
        size_t y;
        for (y = 0; y < b->nrows; y++) {
            free(b->rows[y]);
        }
        free(b->rows);
        b->rows = NULL;
    }
    if (b->png != NULL) {
        png_destroy_read_struct(&b->png, b->info != NULL ? &b->info : NULL, NULL);
    }
    if (b->fp != NULL) {
        fclose(b->fp);
        b->fp = NULL;
    }
}
