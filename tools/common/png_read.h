/* png_read.h - the libpng steps png_io.c (gray) and png_rgb.c (colour)
   share: the error callbacks, opening a file and checking its signature,
   reading and describing the header, the message of a failed read.
   Internal to tools/common (host only). */
#ifndef SSDA_PNG_READ_H
#define SSDA_PNG_READ_H

#include <png.h>
#include <stddef.h>
#include <stdio.h>

#include "png_io.h"

/* libpng reports errors through pngread_on_error: the text is kept here (the
   error pointer of the struct) and it longjmps to the caller's setjmp. */
typedef struct {
    char msg[160];
} pngread_err_t;

void pngread_on_error(png_structp png, png_const_charp text);
/* Ancillary-chunk trouble: ignored, the pixels are still fine. */
void pngread_on_warning(png_structp png, png_const_charp text);

/* An open PNG being read: what the setjmp-protected part touches lives
   outside its frame, in the caller's struct. */
typedef struct {
    FILE *fp;
    png_structp png;
    png_infop info;
    pngread_err_t ectx;
    char why[200];   /* our own refusal (sizes, memory), if any */
    png_bytepp rows; /* pngread_rows: every decoded row */
    size_t nrows;    /* entries of rows */
} pngread_t;

/* Open path, check the PNG signature, create the read and info structs
   (b zeroed by the caller). Returns 0, or -1 with a message naming path in
   err; pngread_close(b) is needed either way. */
int pngread_open(pngread_t *b, const char *path, char *err, size_t errlen);

/* Inside the caller's setjmp(png_jmpbuf(b->png)): read the header into
   *w, *h, *bit_depth, *color_type, *interlace, describe the file in *src,
   refuse sides over 65535 (b->why), expand palettes to RGB and 1, 2, 4-bit
   gray to 8 bits. Returns 0 or -1. */
int pngread_header(pngread_t *b, png_uint_32 *w, png_uint_32 *h, int *bit_depth,
                    int *color_type, int *interlace, png_source_info_t *src);

/* Refuse (b->why, -1) an image whose decoding needs more than
   PNG_IO_MAX_BYTES: w * h * out_bpp output bytes plus buffer_bytes of
   decoded rows. Products in double: no size_t overflow on any host. */
int pngread_check_size(pngread_t *b, const png_source_info_t *src, png_uint_32 w,
                        png_uint_32 h, size_t out_bpp, double buffer_bytes);

/* Inside the caller's setjmp: decode the whole image (any interlacing)
   into b->rows, h rows of rowbytes. Returns 0 or -1 (out of memory in
   b->why). */
int pngread_rows(pngread_t *b, png_uint_32 h, size_t rowbytes);

/* The message of a failed read into err: b->why, or libpng's error. */
void pngread_fail(const pngread_t *b, const char *path, char *err, size_t errlen);

/* Free the rows, destroy the structs, close the file (safe after any
   failure). */
void pngread_close(pngread_t *b);

#endif /* SSDA_PNG_READ_H */
