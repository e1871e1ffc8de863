/*
 * test_image.h - image helpers for tests: generated textures and an
 * independent brute-force reference search (written without the library's
 * code, so it can disagree with it).
 */
#ifndef SSDA_TEST_IMAGE_H
#define SSDA_TEST_IMAGE_H
#include <stdint.h>
#include "ssda/view.h"
#include "test_rng.h"

/* Read pixel (x, y) of a view as uint32_t. */
uint32_t test_px(const ssda_view_t *v, uint32_t x, uint32_t y);

/* Full SAD of window at (x, y) of area: straightforward double loop. */
uint64_t test_sad(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y);

/* Brute-force minimum by the tie rule (smallest SAD, then y, then x). */
void test_best(const ssda_view_t *area, const ssda_view_t *win,
               uint32_t *bx, uint32_t *by, uint64_t *bsad);

/* Fill w x h pixels (stride in pixels) with smooth random texture: random
   values low-pass filtered, range 0..maxval. */
void test_fill_texture_u8(uint8_t *p, uint32_t w, uint32_t h, uint32_t stride, test_rng_t *r);
void test_fill_texture_u16(uint16_t *p, uint32_t w, uint32_t h, uint32_t stride,
                           uint32_t maxval, test_rng_t *r);

/* A textured 12-bit w x h image (random values 0..4095, each averaged
   with its right, lower and lower-right neighbours, in place in reading
   order; contiguous rows) into p16, and its 8-bit copy (v >> 4) into p8. */
void test_fill_texture_12bit(uint16_t *p16, uint8_t *p8, uint32_t w, uint32_t h,
                             test_rng_t *r);

/* Views a, b of a pair of w x h images (contiguous rows): the 16-bit pair
   a16, b16 when wide, else the 8-bit pair a8, b8. Asserts success. */
void test_view_pair(int wide, const void *a16, const void *b16, const void *a8, const void *b8,
                    uint16_t w, uint16_t h, ssda_view_t *a, ssda_view_t *b);

#endif
