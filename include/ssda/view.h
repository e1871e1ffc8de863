/*
 * view.h - read-only views of 8-bit and 16-bit grayscale images in memory.
 *
 * A view never owns pixels: it points into a caller buffer with an arbitrary
 * row stride, so a region of interest is a view too (no copy).
 */
#ifndef SSDA_VIEW_H
#define SSDA_VIEW_H

#include "ssda/ssda.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Pixel formats. The value is the number of bytes per pixel. */
typedef enum {
    SSDA_PIX_U8  = 1, /* uint8_t samples, 0..255 */
    SSDA_PIX_U16 = 2  /* uint16_t samples in native byte order, 0..65535 */
} ssda_pixfmt_t;

/* Largest width or height any function accepts, in pixels. */
#define SSDA_MAX_DIM 65535u

typedef struct {
    const void *data;  /* top-left pixel; uint16_t-aligned for SSDA_PIX_U16 */
    uint32_t stride;   /* bytes from one row start to the next; >= width * bpp,
                          a multiple of bpp */
    uint16_t width;    /* pixels per row, 1..SSDA_MAX_DIM */
    uint16_t height;   /* rows, 1..SSDA_MAX_DIM */
    uint8_t format;    /* ssda_pixfmt_t */
} ssda_view_t;

/*
 * Fill *view for a buffer of width x height pixels of the given format whose
 * rows start stride bytes apart.
 * Returns SSDA_OK, SSDA_ERR_NULL (view or data NULL), SSDA_ERR_SIZE (zero
 * width/height), SSDA_ERR_FORMAT (unknown format) or SSDA_ERR_STRIDE
 * (stride < width * bpp, stride not a multiple of bpp, data misaligned, or
 * rows that would run past the end of the address space: the last byte,
 * data + (height - 1) * stride + width * bpp - 1, must be addressable; a
 * bottom-up image needs a view of its top row and a positive stride).
 * *view is written only on success.
 */
int ssda_view_init(ssda_view_t *view, const void *data, uint16_t width,
                   uint16_t height, uint32_t stride, ssda_pixfmt_t format);

/*
 * Make *roi a view of the w x h rectangle of *src whose top-left pixel is
 * (x, y) of src (0-based, x right, y down). No pixels are copied.
 * Returns SSDA_OK, SSDA_ERR_NULL, the errors of ssda_view_check(src), or
 * SSDA_ERR_SIZE if the rectangle is empty or not inside src.
 */
int ssda_view_roi(ssda_view_t *roi, const ssda_view_t *src, uint16_t x,
                  uint16_t y, uint16_t w, uint16_t h);

/* Check a view's invariants (as ssda_view_init). Returns SSDA_OK or an error. */
int ssda_view_check(const ssda_view_t *view);

/* Bytes per pixel of a valid view's format (1 or 2). */
static inline uint32_t ssda_view_bpp(const ssda_view_t *view)
{
    return (uint32_t)view->format;
}

/* Pointer to the first pixel of row y of a valid view (y < height). */
static inline const uint8_t *ssda_view_row(const ssda_view_t *view, uint32_t y)
{
    return (const uint8_t *)view->data + (size_t)y * view->stride;
}

#ifdef __cplusplus
}
#endif

#endif /* SSDA_VIEW_H */
