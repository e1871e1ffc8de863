/*
 * png_io.h - read any PNG as 8- or 16-bit grayscale, write gray PNGs (host only).
 *
 * Reading accepts every PNG libpng decodes: gray, gray+alpha, RGB, RGBA and
 * palette images, 1, 2, 4, 8 or 16 bits per sample, interlaced or not.
 * Conversion rules (documented in docs/cli.md):
 *   - samples are taken as stored: no gamma, sBIT or colour-profile
 *     correction (a 16-bit PNG holding raw 12-bit counts stays 0..4095);
 *   - 1, 2 and 4-bit gray is scaled to 0..255 (1-bit 1 -> 255, 4-bit 15 -> 255);
 *   - palette entries are looked up to RGB;
 *   - colour becomes Rec. 601 luma in integers, rounded to nearest:
 *         Y = (299 R + 587 G + 114 B + 500) / 1000
 *   - alpha (and tRNS transparency) is ignored: a pixel's colour is used
 *     as if it were opaque;
 *   - the result is 8-bit for sources of 1..8 bits per sample, 16-bit for
 *     16-bit sources, unless a depth is forced (16 -> 8: round(v * 255 / 65535);
 *     8 -> 16: v * 257).
 * Images wider or taller than 65535 pixels, or whose decoding would need more
 * than PNG_IO_MAX_BYTES of memory, are refused with a message.
 */
#ifndef SSDA_PNG_IO_H
#define SSDA_PNG_IO_H

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>
#include <stdio.h>
#include "ssda/view.h"

/* Largest decoded buffer png_read_gray will allocate, in bytes (1 GiB). */
#define PNG_IO_MAX_BYTES ((size_t)1 << 30)

/* A packed grayscale image in host memory (rows stride bytes apart). */
typedef struct {
    void *pixels;      /* malloc'ed; uint8_t or native-order uint16_t samples */
    uint32_t width;    /* 1..65535 */
    uint32_t height;   /* 1..65535 */
    uint32_t stride;   /* bytes per row = width * bytes per pixel */
    uint8_t bits;      /* 8 or 16 */
} gray_image_t;

/* Depth wanted from png_read_gray. */
typedef enum {
    PNG_GRAY_NATIVE = 0, /* 8-bit for <= 8-bit sources, 16-bit for 16-bit sources */
    PNG_GRAY_8 = 8,
    PNG_GRAY_16 = 16
} png_gray_depth_t;

/* What the file held (for messages). */
typedef struct {
    uint32_t source_bits;   /* bits per sample in the file: 1, 2, 4, 8, 16 */
    int color_type;         /* libpng's PNG_COLOR_TYPE_* */
    int had_alpha;          /* 1 if an alpha channel or tRNS chunk was ignored */
    int was_color;          /* 1 if colour was converted to luma */
    char description[48];   /* e.g. "16-bit gray", "8-bit RGBA", "4-bit palette" */
} png_source_info_t;

/*
 * Read path as grayscale of the wanted depth into *img (pixels malloc'ed,
 * release with gray_image_free). info may be NULL. On error returns -1,
 * leaves *img untouched and writes one line naming the file and the reason
 * into err (errlen bytes, may be 0).
 */
int png_read_gray(const char *path, png_gray_depth_t depth, gray_image_t *img,
                  png_source_info_t *info, char *err, size_t errlen);

/*
 * Write img as an 8- or 16-bit gray PNG, atomically (temp file + rename; "-"
 * is stdout). Returns 0, or -1 with a message in err and no file left behind.
 */
int png_write_gray(const char *path, const gray_image_t *img, char *err, size_t errlen);

/* The same into an open stream (e.g. a cli_outputs_t file committed with
   other outputs); name is for messages. Returns 0 or -1 with err. */
int png_write_gray_to(FILE *fp, const char *name, const gray_image_t *img, char *err,
                      size_t errlen);

/* Allocate a zeroed width x height image of 8 or 16 bits. Returns 0 or -1. */
int gray_image_alloc(gray_image_t *img, uint32_t width, uint32_t height, int bits);

/* Free the pixels and zero the struct (safe on a zeroed struct). */
void gray_image_free(gray_image_t *img);

/* A library view of the whole image (no copy). Returns an ssda error code. */
int gray_image_view(const gray_image_t *img, ssda_view_t *view);

/* Sample at (x, y) as an unsigned value, whatever the depth (no bounds check). */
static inline uint32_t gray_image_get(const gray_image_t *img, uint32_t x, uint32_t y)
{
    const uint8_t *row = (const uint8_t *)img->pixels + (size_t)y * img->stride;
    return img->bits == 16 ? ((const uint16_t *)(const void *)row)[x] : row[x];
}

/* Largest sample value of the depth: 255 or 65535. */
static inline uint32_t gray_image_max(const gray_image_t *img)
{
    return img->bits == 16 ? 65535u : 255u;
}

/* ---- colour ---- */

/* A packed interleaved RGB image in host memory: pixel (x, y) band k at
   sample (y * width + x) * 3 + k; rows stride bytes apart. */
typedef struct {
    void *pixels;      /* malloc'ed; uint8_t or native-order uint16_t samples */
    uint32_t width;    /* 1..65535 */
    uint32_t height;   /* 1..65535 */
    uint32_t stride;   /* bytes per row = 3 * width * bytes per sample */
    uint8_t bits;      /* 8 or 16 */
} rgb_image_t;

/*
 * Read path as RGB, samples as stored (no gamma or profile; 16-bit sources
 * stay 16-bit, 1..8-bit ones become 8-bit as png_read_gray scales gray),
 * into *img (release with rgb_image_free). Palette entries are looked up;
 * alpha and tRNS are ignored; a gray PNG gives three equal bands, and
 * info->was_color (if info is not NULL) says which it was. Limits and
 * errors as png_read_gray; *img untouched on error.
 */
int png_read_rgb(const char *path, rgb_image_t *img, png_source_info_t *info, char *err,
                 size_t errlen);

/* Free the pixels and zero the struct (safe on a zeroed struct). */
void rgb_image_free(rgb_image_t *img);

#endif /* SSDA_PNG_IO_H */
