/* img_out.c - PNG stacks, flicker GIFs and composites (img_out.h). */
#include "img_out.h"

#include <gif_lib.h>
#include <png.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static void set_msg(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (err == NULL || errlen == 0) {
        return;
    }
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

/* ---- PNG ---- */

typedef struct {
    jmp_buf jb;
    char msg[160];
} png_ectx_t;

static void on_error(png_structp png, png_const_charp msg)
{
    png_ectx_t *e = (png_ectx_t *)png_get_error_ptr(png);
    snprintf(e->msg, sizeof e->msg, "%s", msg);
    longjmp(e->jb, 1);
}

static void on_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* The rows, interleaved; volatile-free: everything set before setjmp. */
static int write_rows(png_structp png, png_infop info, FILE *fp, const gray_image_t *const *ch,
                      int n, unsigned char *row, png_ectx_t *e)
{
    static const int types[5] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB,
                                 PNG_COLOR_TYPE_RGB_ALPHA};
    static const int map2[3] = {0, 1, 0};
    const int bits = ch[0]->bits, out_ch = n == 2 ? 3 : n;
    uint32_t x, y;
    int c;
    if (setjmp(e->jb) != 0) {
        return -1;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, ch[0]->width, ch[0]->height, bits, types[n], PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < ch[0]->height; y++) {
        for (x = 0; x < ch[0]->width; x++) {
            for (c = 0; c < out_ch; c++) {
                const gray_image_t *img = ch[n == 2 ? map2[c] : c];
                const uint32_t v = gray_image_get(img, x, y);
                const size_t at = ((size_t)x * (size_t)out_ch + (size_t)c) * (bits == 16 ? 2u : 1u);
                if (bits == 16) { /* PNG is big-endian */
                    row[at] = (unsigned char)(v >> 8);
                    row[at + 1] = (unsigned char)v;
                } else {
                    row[at] = (unsigned char)v;
                }
            }
        }
        png_write_row(png, row);
    }
    png_write_end(png, info);
    return 0;
}

int img_write_png(FILE *fp, const gray_image_t *const *ch, int n, char *err, size_t errlen)
{
    png_ectx_t e;
    png_structp png;
    png_infop info = NULL;
    unsigned char *row;
    int i, rc;
    if (n < 1 || n > 4) {
        set_msg(err, errlen, "a PNG holds 1 to 4 channels, not %d", n);
        return -1;
    }
    for (i = 1; i < n; i++) {
        if (ch[i]->width != ch[0]->width || ch[i]->height != ch[0]->height ||
            ch[i]->bits != ch[0]->bits) {
            set_msg(err, errlen, "channels differ in size or depth");
            return -1;
        }
    }
    memset(&e, 0, sizeof e);
    row = malloc((size_t)ch[0]->width * 4u * 2u);
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &e, on_error, on_warning);
    if (row == NULL || png == NULL || (info = png_create_info_struct(png)) == NULL) {
        set_msg(err, errlen, "out of memory");
        rc = -1;
    } else {
        rc = write_rows(png, info, fp, ch, n, row, &e);
        if (rc != 0) {
            set_msg(err, errlen, "%s", e.msg);
        }
    }
    if (png != NULL) {
        png_destroy_write_struct(&png, info != NULL ? &info : NULL);
    }
    free(row);
    return rc;
}

/* ---- display copies ---- */

int img_display8(const gray_image_t *img, gray_image_t *out)
{
    uint32_t x, y, lo = 0, hi = 65535;
    if (gray_image_alloc(out, img->width, img->height, 8) != 0) {
        return -1;
    }
    if (img->bits == 16) {
        uint32_t *hist = calloc(65536u, sizeof *hist);
        const uint64_t total = (uint64_t)img->width * img->height;
        uint64_t acc = 0;
        uint32_t v;
        if (hist == NULL) {
            gray_image_free(out);
            return -1;
        }
        for (y = 0; y < img->height; y++) {
            for (x = 0; x < img->width; x++) {
                hist[gray_image_get(img, x, y)]++;
            }
        }
        for (v = 0; v < 65536u; v++) { /* 0.5th percentile */
            acc += hist[v];
            if (acc * 200u >= total) {
                lo = v;
                break;
            }
        }
        acc = 0;
        for (v = 65536u; v-- > 0;) { /* 99.5th */
            acc += hist[v];
            if (acc * 200u >= total) {
                hi = v;
                break;
            }
        }
        free(hist);
        hi = hi > lo ? hi : lo + 1u;
    }
    for (y = 0; y < img->height; y++) {
        uint8_t *row = (uint8_t *)out->pixels + (size_t)y * out->stride;
        for (x = 0; x < img->width; x++) {
            const uint32_t v = gray_image_get(img, x, y);
            if (img->bits == 16) {
                const uint32_t c = v < lo ? 0u : (v > hi ? 255u : (v - lo) * 255u / (hi - lo));
                row[x] = (uint8_t)c;
            } else {
                row[x] = (uint8_t)v;
            }
        }
    }
    return 0;
}

/* ---- GIF ---- */

static int gif_put(GifFileType *g, const GifByteType *buf, int len)
{
    FILE *fp = (FILE *)g->UserData;
    return (int)fwrite(buf, 1, (size_t)len, fp);
}

int img_write_flicker_gif(FILE *fp, const gray_image_t *const *frames, int n, int delay_cs,
                          char *err, size_t errlen)
{
    GifColorType colors[256];
    ColorMapObject *map;
    GifFileType *g;
    int i, e = 0, rc = -1;
    uint32_t y;
    if (n < 1 || n > 16) {
        set_msg(err, errlen, "a flicker view takes 1 to 16 frames, not %d", n);
        return -1;
    }
    for (i = 0; i < n; i++) {
        if (frames[i]->bits != 8 || frames[i]->width != frames[0]->width ||
            frames[i]->height != frames[0]->height) {
            set_msg(err, errlen, "flicker frames differ in size or are not 8-bit");
            return -1;
        }
    }
    for (i = 0; i < 256; i++) {
        colors[i].Red = colors[i].Green = colors[i].Blue = (GifByteType)i;
    }
    map = GifMakeMapObject(256, colors);
    g = EGifOpen(fp, gif_put, &e);
    if (map == NULL || g == NULL) {
        set_msg(err, errlen, "cannot start the GIF: %s", GifErrorString(e));
        GifFreeMapObject(map);
        if (g != NULL) {
            EGifCloseFile(g, &e);
        }
        return -1;
    }
    EGifSetGifVersion(g, true);
    if (EGifPutScreenDesc(g, (int)frames[0]->width, (int)frames[0]->height, 8, 0, map) !=
        GIF_OK) {
        goto done;
    }
    {
        /* loop forever: the NETSCAPE2.0 application extension */
        static const GifByteType loop[3] = {1, 0, 0};
        if (EGifPutExtensionLeader(g, APPLICATION_EXT_FUNC_CODE) != GIF_OK ||
            EGifPutExtensionBlock(g, 11, "NETSCAPE2.0") != GIF_OK ||
            EGifPutExtensionBlock(g, 3, loop) != GIF_OK || EGifPutExtensionTrailer(g) != GIF_OK) {
            goto done;
        }
    }
    for (i = 0; i < n; i++) {
        GraphicsControlBlock gcb;
        GifByteType ext[4];
        memset(&gcb, 0, sizeof gcb);
        gcb.DelayTime = delay_cs;
        gcb.TransparentColor = NO_TRANSPARENT_COLOR;
        EGifGCBToExtension(&gcb, ext);
        if (EGifPutExtension(g, GRAPHICS_EXT_FUNC_CODE, 4, ext) != GIF_OK ||
            EGifPutImageDesc(g, 0, 0, (int)frames[i]->width, (int)frames[i]->height, false,
                             NULL) != GIF_OK) {
            goto done;
        }
        for (y = 0; y < frames[i]->height; y++) {
            GifPixelType *row = (GifPixelType *)frames[i]->pixels + (size_t)y * frames[i]->stride;
            if (EGifPutLine(g, row, (int)frames[i]->width) != GIF_OK) {
                goto done;
            }
        }
    }
    rc = 0;
done:
    if (rc != 0) {
        set_msg(err, errlen, "cannot write the GIF: %s", GifErrorString(g->Error));
    }
    if (EGifCloseFile(g, &e) != GIF_OK && rc == 0) {
        set_msg(err, errlen, "cannot finish the GIF: %s", GifErrorString(e));
        rc = -1;
    }
    GifFreeMapObject(map);
    return rc;
}

/* ---- composites ---- */

int img_checkerboard(const gray_image_t *a, const gray_image_t *b, uint32_t tile,
                     gray_image_t *out)
{
    uint32_t x, y;
    if (gray_image_alloc(out, a->width, a->height, 8) != 0) {
        return -1;
    }
    for (y = 0; y < a->height; y++) {
        uint8_t *row = (uint8_t *)out->pixels + (size_t)y * out->stride;
        for (x = 0; x < a->width; x++) {
            const gray_image_t *s = ((x / tile) + (y / tile)) % 2u == 0u ? a : b;
            row[x] = (uint8_t)gray_image_get(s, x, y);
        }
    }
    return 0;
}

int img_difference(const gray_image_t *a, const gray_image_t *b, gray_image_t *out)
{
    uint32_t x, y, top = 16;
    if (gray_image_alloc(out, a->width, a->height, 8) != 0) {
        return -1;
    }
    for (y = 0; y < a->height; y++) {
        for (x = 0; x < a->width; x++) {
            const int d = (int)gray_image_get(a, x, y) - (int)gray_image_get(b, x, y);
            const uint32_t m = (uint32_t)(d < 0 ? -d : d);
            top = m > top ? m : top;
        }
    }
    for (y = 0; y < a->height; y++) {
        uint8_t *row = (uint8_t *)out->pixels + (size_t)y * out->stride;
        for (x = 0; x < a->width; x++) {
            const int d = (int)gray_image_get(a, x, y) - (int)gray_image_get(b, x, y);
            row[x] = (uint8_t)((uint32_t)(d < 0 ? -d : d) * 255u / top);
        }
    }
    return 0;
}
