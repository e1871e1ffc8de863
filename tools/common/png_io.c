/* png_io.c - PNG to gray and gray to PNG with libpng (rules in png_io.h). */
#include "png_io.h"
#include "tool_err.h"
#include "atomic_file.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* libpng reports errors through this; we keep the text and longjmp out. */
typedef struct {
    char msg[160];
} png_err_ctx_t;

static void on_png_error(png_structp png, png_const_charp text)
{
    png_err_ctx_t *ctx = (png_err_ctx_t *)png_get_error_ptr(png);
    if (ctx != NULL) {
        snprintf(ctx->msg, sizeof ctx->msg, "%s", text);
    }
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp text)
{
    (void)png;
    (void)text; /* ancillary-chunk trouble: the pixels are still fine */
}

int gray_image_alloc(gray_image_t *img, uint32_t width, uint32_t height, int bits)
{
    size_t bpp = bits == 16 ? 2u : 1u;
    void *p;
    if (width == 0 || height == 0 || width > SSDA_MAX_DIM || height > SSDA_MAX_DIM ||
        (bits != 8 && bits != 16)) {
        return -1;
    }
    p = calloc((size_t)width * height, bpp);
    if (p == NULL) {
        return -1;
    }
    img->pixels = p;
    img->width = width;
    img->height = height;
    img->stride = (uint32_t)(width * bpp);
    img->bits = (uint8_t)bits;
    return 0;
}

void gray_image_free(gray_image_t *img)
{
    free(img->pixels);
    memset(img, 0, sizeof *img);
}

int gray_image_view(const gray_image_t *img, ssda_view_t *view)
{
    return ssda_view_init(view, img->pixels, (uint16_t)img->width, (uint16_t)img->height,
                          img->stride, img->bits == 16 ? SSDA_PIX_U16 : SSDA_PIX_U8);
}

/* ---- reading ---- */

/* Everything the setjmp-protected part touches lives here, outside its frame. */
typedef struct {
    const char *path;
    FILE *fp;
    png_structp png;
    png_infop info;
    png_bytepp rows;       /* interlaced images: every decoded row */
    size_t nrows;          /* entries of rows */
    png_bytep row;         /* non-interlaced: one decoded row */
    gray_image_t out;
    png_err_ctx_t ectx;
    png_source_info_t src;
    char why[200];         /* our own refusal (sizes), if any */
} png_reader_t;

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

/* One decoded row (channels of 8 or 16-bit big-endian samples) to gray. */
static void row_to_gray(const png_byte *in, uint32_t width, int channels, int in_bits,
                        int out_bits, void *out)
{
    uint32_t x;
    int color = channels >= 3;
    for (x = 0; x < width; x++) {
        const png_byte *p = in + (size_t)x * (size_t)channels * (in_bits == 16 ? 2u : 1u);
        uint32_t v; /* in the source's depth: 0..255 or 0..65535 */
        if (in_bits == 16) {
            uint32_t r = ((uint32_t)p[0] << 8) | p[1];
            if (color) {
                uint32_t g = ((uint32_t)p[2] << 8) | p[3];
                uint32_t b = ((uint32_t)p[4] << 8) | p[5];
                v = (299u * r + 587u * g + 114u * b + 500u) / 1000u; /* <= 65535000+500 */
            } else {
                v = r;
            }
        } else {
            v = color ? (299u * p[0] + 587u * p[1] + 114u * p[2] + 500u) / 1000u : p[0];
        }
        if (out_bits == 16) {
            ((uint16_t *)out)[x] = (uint16_t)(in_bits == 16 ? v : v * 257u);
        } else {
            ((uint8_t *)out)[x] = (uint8_t)(in_bits == 16 ? (v * 255u + 32767u) / 65535u : v);
        }
    }
}

/* Decoded rows to gray into r->out: every row at once for an interlaced
   image (passes), else one row at a time. Inside read_protected's setjmp. */
static int decode_rows(png_reader_t *r, png_uint_32 w, png_uint_32 h, int passes, int channels,
                       int dec_bits, int out_bits, size_t rowbytes)
{
    size_t y;
    if (passes > 1) {
        r->rows = calloc(h, sizeof *r->rows);
        if (r->rows == NULL) {
            snprintf(r->why, sizeof r->why, "out of memory");
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
        for (y = 0; y < h; y++) {
            row_to_gray(r->rows[y], w, channels, dec_bits, out_bits,
                        (uint8_t *)r->out.pixels + y * r->out.stride);
        }
        return 0;
    }
    if ((r->row = malloc(rowbytes)) == NULL) {
        snprintf(r->why, sizeof r->why, "out of memory");
        return -1;
    }
    for (y = 0; y < h; y++) {
        png_read_row(r->png, r->row, NULL);
        row_to_gray(r->row, w, channels, dec_bits, out_bits,
                    (uint8_t *)r->out.pixels + y * r->out.stride);
    }
    return 0;
}

/* What the file holds (for messages), from its header. */
static void describe_source(png_reader_t *r, int bit_depth, int color_type, int interlace)
{
    r->src.source_bits = (uint32_t)bit_depth;
    r->src.color_type = color_type;
    r->src.was_color = (color_type & PNG_COLOR_MASK_COLOR) != 0;
    r->src.had_alpha = (color_type & PNG_COLOR_MASK_ALPHA) != 0 ||
                       png_get_valid(r->png, r->info, PNG_INFO_tRNS) != 0;
    snprintf(r->src.description, sizeof r->src.description, "%d-bit %s%s", bit_depth,
             color_name(color_type), interlace != PNG_INTERLACE_NONE ? ", interlaced" : "");
}

/* Refuse an image whose decoding needs more than PNG_IO_MAX_BYTES. w, h <=
   65535 and rowbytes <= 8 * 65535: each product is checked against the
   cap in double, so no size_t overflow on 64-bit or 32-bit hosts. */
static int check_size(png_reader_t *r, png_uint_32 w, png_uint_32 h, int passes, size_t rowbytes,
                      size_t out_bpp)
{
    double need = (double)w * (double)h * (double)out_bpp +
                  (passes > 1 ? (double)rowbytes * (double)h : (double)rowbytes);
    if (need > (double)PNG_IO_MAX_BYTES) {
        snprintf(r->why, sizeof r->why,
                 "image is %lu x %lu pixels (%s); decoding it needs %.0f MB, more than "
                 "the %lu MB limit",
                 (unsigned long)w, (unsigned long)h, r->src.description, need / 1e6,
                 (unsigned long)(PNG_IO_MAX_BYTES / 1000000u));
        return -1;
    }
    return 0;
}

/* The libpng part; returns 0 or -1 (message in r->ectx or r->why). */
static int read_protected(png_reader_t *r, png_gray_depth_t depth)
{
    png_uint_32 w, h;
    int bit_depth, color_type, interlace, passes, channels, dec_bits, out_bits;
    size_t rowbytes;

    if (setjmp(png_jmpbuf(r->png))) {
        return -1;
    }
    png_init_io(r->png, r->fp);
    png_set_sig_bytes(r->png, 8);
    /* Our own size limit gives a clearer message than libpng's default one. */
    png_set_user_limits(r->png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    png_read_info(r->png, r->info);
    png_get_IHDR(r->png, r->info, &w, &h, &bit_depth, &color_type, &interlace, NULL, NULL);
    describe_source(r, bit_depth, color_type, interlace);
    if (w > SSDA_MAX_DIM || h > SSDA_MAX_DIM) {
        snprintf(r->why, sizeof r->why,
                 "image is %lu x %lu pixels; the largest accepted is 65535 x 65535",
                 (unsigned long)w, (unsigned long)h);
        return -1;
    }
    if (color_type == PNG_COLOR_TYPE_PALETTE) {
        png_set_palette_to_rgb(r->png); /* RGBA when a tRNS chunk exists */
    }
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) {
        png_set_expand_gray_1_2_4_to_8(r->png); /* scaled to 0..255, tRNS not expanded */
    }
    passes = png_set_interlace_handling(r->png);
    png_read_update_info(r->png, r->info);
    channels = png_get_channels(r->png, r->info);
    dec_bits = png_get_bit_depth(r->png, r->info);
    rowbytes = png_get_rowbytes(r->png, r->info);
    out_bits = depth == PNG_GRAY_NATIVE ? (bit_depth == 16 ? 16 : 8) : (int)depth;
    if (check_size(r, w, h, passes, rowbytes, out_bits == 16 ? 2u : 1u) != 0) {
        return -1;
    }
    if (gray_image_alloc(&r->out, w, h, out_bits) != 0) {
        snprintf(r->why, sizeof r->why, "out of memory for %lu x %lu pixels",
                 (unsigned long)w, (unsigned long)h);
        return -1;
    }
    if (decode_rows(r, w, h, passes, channels, dec_bits, out_bits, rowbytes) != 0) {
        return -1;
    }
    png_read_end(r->png, NULL); /* checks the trailing chunks and IEND */
    return 0;
}

static void reader_release(png_reader_t *r)
{
    if (r->rows != NULL) {
        size_t y;
        for (y = 0; y < r->nrows; y++) {
            free(r->rows[y]);
        }
        free(r->rows);
    }
    free(r->row);
    if (r->png != NULL) {
        png_destroy_read_struct(&r->png, r->info != NULL ? &r->info : NULL, NULL);
    }
    if (r->fp != NULL) {
        fclose(r->fp);
    }
}

int png_read_gray(const char *path, png_gray_depth_t depth, gray_image_t *img,
                  png_source_info_t *info, char *err, size_t errlen)
{
    png_reader_t *r;
    png_byte sig[8];
    size_t got;
    int rc = -1;

    if (depth != PNG_GRAY_NATIVE && depth != PNG_GRAY_8 && depth != PNG_GRAY_16) {
        tool_set_err(err, errlen, "'%s': unknown gray depth %d", path, (int)depth);
        return -1;
    }
    r = calloc(1, sizeof *r);
    if (r == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", path);
        return -1;
    }
    r->path = path;
    r->fp = fopen(path, "rb");
    if (r->fp == NULL) {
        tool_set_err(err, errlen, "cannot open '%s': %s", path, strerror(errno));
        goto done;
    }
    errno = 0;
    got = fread(sig, 1, sizeof sig, r->fp);
    if (got == 0 && ferror(r->fp)) { /* e.g. a directory: "Is a directory" */
        tool_set_err(err, errlen, "cannot read '%s': %s", path,
                     strerror(errno != 0 ? errno : EIO));
        goto done;
    }
    if (got == 0) {
        tool_set_err(err, errlen, "'%s' is empty, not a PNG file", path);
        goto done;
    }
    if (got < sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        tool_set_err(err, errlen, "'%s' is not a PNG file (bad signature)", path);
        goto done;
    }
    r->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r->ectx, on_png_error,
                                    on_png_warning);
    if (r->png == NULL || (r->info = png_create_info_struct(r->png)) == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", path);
        goto done;
    }
    if (read_protected(r, depth) != 0) {
        if (r->why[0] != '\0') {
            tool_set_err(err, errlen, "'%s': %s", path, r->why);
        } else {
            /* libpng's fread failure at end of file says just "Read Error" */
            const char *m = strcmp(r->ectx.msg, "Read Error") == 0 ? "file ends early"
                            : r->ectx.msg[0] != '\0'            ? r->ectx.msg
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
    reader_release(r);
    gray_image_free(&r->out);
    free(r);
    return rc;
}

/* ---- writing ---- */

typedef struct {
    FILE *fp;
    png_structp png;
    png_infop info;
    png_bytep row;
    png_err_ctx_t ectx;
    int write_errno;       /* errno of a failed write (ENOSPC, EFBIG), else 0 */
} png_writer_t;

/* libpng's own writer says only "Write Error": keep the reason. */
static void on_png_write(png_structp png, png_bytep data, size_t len)
{
    png_writer_t *w = (png_writer_t *)png_get_io_ptr(png);
    errno = 0;
    if (fwrite(data, 1, len, w->fp) != len) {
        w->write_errno = errno != 0 ? errno : EIO;
        png_error(png, strerror(w->write_errno));
    }
}

static void on_png_flush(png_structp png)
{
    (void)png; /* the commit flushes */
}

static int write_protected(png_writer_t *w, const gray_image_t *img)
{
    uint32_t x, y;
    if (setjmp(png_jmpbuf(w->png))) {
        return -1;
    }
    png_set_write_fn(w->png, w, on_png_write, on_png_flush);
    png_set_IHDR(w->png, w->info, img->width, img->height, img->bits, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(w->png, w->info);
    for (y = 0; y < img->height; y++) {
        const uint8_t *src = (const uint8_t *)img->pixels + (size_t)y * img->stride;
        if (img->bits == 16) {
            const uint16_t *s16 = (const uint16_t *)(const void *)src;
            for (x = 0; x < img->width; x++) { /* PNG is big-endian */
                w->row[2 * x] = (png_byte)(s16[x] >> 8);
                w->row[2 * x + 1] = (png_byte)(s16[x] & 0xffu);
            }
            png_write_row(w->png, w->row);
        } else {
            memcpy(w->row, src, img->width);
            png_write_row(w->png, w->row);
        }
    }
    png_write_end(w->png, NULL);
    return 0;
}

int png_write_gray(const char *path, const gray_image_t *img, char *err, size_t errlen)
{
    png_writer_t w;
    atomic_file_t af;
    int rc = -1;

    memset(&w, 0, sizeof w);
    if (img == NULL || img->pixels == NULL || img->width == 0 || img->height == 0 ||
        img->width > SSDA_MAX_DIM || img->height > SSDA_MAX_DIM ||
        (img->bits != 8 && img->bits != 16)) {
        tool_set_err(err, errlen, "'%s': nothing valid to write", path);
        return -1;
    }
    if (atomic_file_open(&af, path) != 0) {
        tool_set_err(err, errlen, "cannot create '%s': %s", path, atomic_file_strerror(errno));
        return -1;
    }
    w.fp = af.fp;
    w.row = malloc((size_t)img->width * 2u);
    w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w.ectx, on_png_error,
                                    on_png_warning);
    if (w.row == NULL || w.png == NULL || (w.info = png_create_info_struct(w.png)) == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", path);
    } else if (write_protected(&w, img) != 0) {
        tool_set_err(err, errlen, "cannot write '%s': %s", path, w.ectx.msg);
    } else if (atomic_file_commit(&af) != 0) { /* releases af either way */
        tool_set_err(err, errlen, "cannot write '%s': %s", path, atomic_file_strerror(errno));
    } else {
        rc = 0;
    }
    if (w.png != NULL) {
        png_destroy_write_struct(&w.png, w.info != NULL ? &w.info : NULL);
    }
    free(w.row);
    atomic_file_abort(&af); /* after an error: the temp file (a no-op after commit) */
    return rc;
}

int png_write_gray_to(FILE *fp, const char *name, const gray_image_t *img, char *err,
                      size_t errlen)
{
    png_writer_t w;
    int rc = -1;

    memset(&w, 0, sizeof w);
    if (img == NULL || img->pixels == NULL || img->width == 0 || img->height == 0 ||
        img->width > SSDA_MAX_DIM || img->height > SSDA_MAX_DIM ||
        (img->bits != 8 && img->bits != 16)) {
        tool_set_err(err, errlen, "'%s': nothing valid to write", name);
        return -1;
    }
    w.fp = fp;
    w.row = malloc((size_t)img->width * 2u);
    w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w.ectx, on_png_error,
                                    on_png_warning);
    if (w.row == NULL || w.png == NULL || (w.info = png_create_info_struct(w.png)) == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory", name);
    } else if (write_protected(&w, img) != 0) {
        tool_set_err(err, errlen, "cannot write '%s': %s", name, w.ectx.msg);
    } else {
        rc = 0;
    }
    if (w.png != NULL) {
        png_destroy_write_struct(&w.png, w.info != NULL ? &w.info : NULL);
    }
    free(w.row);
    return rc;
}
