/*
 * img_out.h - the registration tool's pictures (host only): multi-channel
 * PNG stacks, the seed's flicker view as an animated GIF (giflib), a
 * checkerboard and a difference composite; all written to a FILE * so that
 * the caller's all-or-nothing outputs (cli_outputs_open) hold them.
 */
#ifndef SSDA_IMG_OUT_H
#define SSDA_IMG_OUT_H

#include <stddef.h>
#include <stdio.h>
#include "png_io.h"

/*
 * Write n images of one size and depth (8 or 16 bits) as one PNG:
 *   n = 1: gray;  n = 2: RGB = (ch0, ch1, ch0) (the usual false colour of a
 *   band pair: where they differ, green or magenta);  n = 3: RGB;
 *   n = 4: RGBA (the 4th band as alpha).
 * Returns 0, or -1 with a message in err.
 */
int img_write_png(FILE *fp, const gray_image_t *const *ch, int n, char *err, size_t errlen);

/* An 8-bit copy of img for viewing: 8-bit images as they are; 16-bit ones
   stretched linearly from their 0.5th to their 99.5th percentile (raw
   12-bit counts, or 16-bit data using part of its range, would look
   black). Returns 0 or -1 (out of memory). */
int img_display8(const gray_image_t *img, gray_image_t *out);

/*
 * The flicker view: an animated GIF showing the frames in turn, looping
 * forever, each for delay_cs hundredths of a second (the seed alternated
 * two images 15 times a second: 7 cs, GIF's nearest). Frames: 8-bit, one
 * size, at most 16. Returns 0, or -1 with a message in err.
 */
int img_write_flicker_gif(FILE *fp, const gray_image_t *const *frames, int n, int delay_cs,
                          char *err, size_t errlen);

/* a and b (8-bit, one size) in alternate square tiles of `tile` px,
   starting with a at the top left. Returns 0 or -1 (out of memory). */
int img_checkerboard(const gray_image_t *a, const gray_image_t *b, uint32_t tile,
                     gray_image_t *out);

/* |a - b| (8-bit, one size), stretched so that the largest difference of
   the image (at least 16) is 255. Returns 0 or -1. */
int img_difference(const gray_image_t *a, const gray_image_t *b, gray_image_t *out);

#endif /* SSDA_IMG_OUT_H */
