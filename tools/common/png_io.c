/* png_io.c - PNG to gray and gray to PNG with libpng (rules in png_io.h). */
#include "png_io.h"
#include "png_read.h"
#include "tool_err.h"
#include "atomic_file.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    pngread_t b;     /* file, libpng structs, error texts, the rows
                              of an interlaced image */
    png_bytep row;         /* non-interlaced: one decoded row */
    gray_image_t out;
    png_source_info_t src;
} png_reader_t;

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

/* 1 on a little-endian host (16-bit samples then need libpng's swap). */
static int host_little_endian(void)
{
    const uint16_t one = 1u;
    uint8_t first;
    memcpy(&first, &one, 1);
    return first == 1u;
}

/* Decoded rows to gray into r->out: every row at once for an interlaced
   image (passes), else one row at a time; `direct`: the decoded row is
   already the gray row (one channel, the output's depth, host order), so
   libpng writes it into the image, no copy. Inside read_protected's setjmp. */
static int decode_rows(png_reader_t *r, png_uint_32 w, png_uint_32 h, int passes, int channels,
                       int dec_bits, int out_bits, size_t rowbytes, int direct)
{
    size_t y;
    if (direct) {
        for (y = 0; y < h; y++) {
            png_read_row(r->b.png, (png_bytep)r->out.pixels + y * r->out.stride, NULL);
        }
        return 0;
    }
    if (passes > 1) {
        if (pngread_rows(&r->b, h, rowbytes) != 0) {
            return -1;
        }
        for (y = 0; y < h; y++) {
            row_to_gray(r->b.rows[y], w, channels, dec_bits, out_bits,
                        (uint8_t *)r->out.pixels + y * r->out.stride);
        }
        return 0;
    }
    if ((r->row = malloc(rowbytes)) == NULL) {
        snprintf(r->b.why, sizeof r->b.why, "out of memory");
        return -1;
    }
    for (y = 0; y < h; y++) {
        png_read_row(r->b.png, r->row, NULL);
        row_to_gray(r->row, w, channels, dec_bits, out_bits,
                    (uint8_t *)r->out.pixels + y * r->out.stride);
    }
    return 0;
}

/* The libpng part; returns 0 or -1 (message in r->b.ectx or r->b.why). */
static int read_protected(png_reader_t *r, png_gray_depth_t depth)
{
    png_uint_32 w, h;
    int bit_depth, color_type, interlace, passes, channels, dec_bits, out_bits, direct;
    size_t rowbytes;

    if (setjmp(png_jmpbuf(r->b.png))) {
        return -1;
    }
    if (pngread_header(&r->b, &w, &h, &bit_depth, &color_type, &interlace, &r->src) != 0) {
        return -1;
    }
    out_bits = depth == PNG_GRAY_NATIVE ? (bit_depth == 16 ? 16 : 8) : (int)depth;
    /* A plain gray file read at its own depth (the usual input, e.g. the
       16-bit GOES frames): libpng decodes straight into the image, 16-bit
       samples swapped to host order by libpng (the same values as
       row_to_gray's big-endian reading, without a second pass). */
    direct = interlace == PNG_INTERLACE_NONE && color_type == PNG_COLOR_TYPE_GRAY &&
             (bit_depth == 16 ? out_bits == 16 : out_bits == 8);
    if (direct && bit_depth == 16 && host_little_endian()) {
        png_set_swap(r->b.png);
    }
    passes = png_set_interlace_handling(r->b.png);
    png_read_update_info(r->b.png, r->b.info);
    channels = png_get_channels(r->b.png, r->b.info);
    dec_bits = png_get_bit_depth(r->b.png, r->b.info);
    rowbytes = png_get_rowbytes(r->b.png, r->b.info);
    if (direct && (channels != 1 || dec_bits != out_bits ||
                   rowbytes != (size_t)w * (size_t)(out_bits / 8))) {
        snprintf(r->b.why, sizeof r->b.why, "unexpected decoded layout (%d channels, %d bits)",
                 channels, dec_bits); /* cannot happen for gray at its depth */
        return -1;
    }
    if (pngread_check_size(&r->b, &r->src, w, h, out_bits == 16 ? 2u : 1u,
                            (double)rowbytes * (passes > 1 ? (double)h : 1.0)) != 0) {
        return -1;
    }
    if (gray_image_alloc(&r->out, w, h, out_bits) != 0) {
        snprintf(r->b.why, sizeof r->b.why, "out of memory for %lu x %lu pixels",
                 (unsigned long)w, (unsigned long)h);
        return -1;
    }
    if (decode_rows(r, w, h, passes, channels, dec_bits, out_bits, rowbytes, direct) != 0) {
        return -1;
    }
    png_read_end(r->b.png, NULL); /* checks the trailing chunks and IEND */
    return 0;
}

static void reader_release(png_reader_t *r)
{
    free(r->row);
    pngread_close(&r->b);
}

int png_read_gray(const char *path, png_gray_depth_t depth, gray_image_t *img,
                  png_source_info_t *info, char *err, size_t errlen)
{
    png_reader_t *r;
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
    if (pngread_open(&r->b, path, err, errlen) != 0) {
        goto done;
    }
    if (read_protected(r, depth) != 0) {
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
    pngread_err_t ectx;
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

/* An image png_write_gray can write: pixels, 1..65535 a side, 8 or 16 bits. */
static int writable(const gray_image_t *img)
{
    return img != NULL && img->pixels != NULL && img->width != 0 && img->height != 0 &&
           img->width <= SSDA_MAX_DIM && img->height <= SSDA_MAX_DIM &&
           (img->bits == 8 || img->bits == 16);
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
    atomic_file_t af;
    int rc;
    if (!writable(img)) { /* before a temp file is made */
        tool_set_err(err, errlen, "'%s': nothing valid to write", path);
        return -1;
    }
    if (atomic_file_open(&af, path) != 0) {
        tool_set_err(err, errlen, "cannot create '%s': %s", path, atomic_file_strerror(errno));
        return -1;
    }
    rc = png_write_gray_to(af.fp, path, img, err, errlen);
    if (rc == 0 && atomic_file_commit(&af) != 0) { /* releases af either way */
        tool_set_err(err, errlen, "cannot write '%s': %s", path, atomic_file_strerror(errno));
        rc = -1;
    }
    atomic_file_abort(&af); /* after an error: the temp file (a no-op after commit) */
    return rc;
}

int png_write_gray_to(FILE *fp, const char *name, const gray_image_t *img, char *err,
                      size_t errlen)
{
    png_writer_t w;
    int rc = -1;

    memset(&w, 0, sizeof w);
    if (!writable(img)) {
        tool_set_err(err, errlen, "'%s': nothing valid to write", name);
        return -1;
    }
    w.fp = fp;
    w.row = malloc((size_t)img->width * 2u);
    w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w.ectx, pngread_on_error,
                                    pngread_on_warning);
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
