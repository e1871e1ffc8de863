/*
 * synth_texture.h - synthetic textured image pairs for benchmarks (host only):
 * cloud-like value noise and a copy of it moved by a smooth, known field.
 *
 * With width = height = n and seeds 1 and 2 these are the same images as the
 * synthetic pair of tools/bench/bench_track.c (same generator, same order of
 * rand() calls), so figures of different benchmarks are comparable.
 * Both use the C library's rand(): the images are reproducible on one C
 * library (glibc here), not across C libraries.
 */
#ifndef SSDA_SYNTH_TEXTURE_H
#define SSDA_SYNTH_TEXTURE_H

#include <stdint.h>

/* Value noise in img[w * h] (rows w bytes apart): bilinearly interpolated
   random grids of cell sizes 128, 64, ..., 2 px with amplitudes 1, 0.6,
   0.36, ..., stretched to 0..255. Returns 0, or -1 when out of memory. */
int synth_texture(uint8_t *img, int w, int h, unsigned seed);

/* second(x, y) = first(x - u, y - v) + noise in -2..+2, clamped to 0..255,
   with u = 3 + 2 sin(2 pi y / h), v = -2 + 2.5 cos(2 pi x / w), rounded per
   pixel (nearest-neighbour warp; the source clamped to the image). The
   motion of the content from first to second is (+u, +v): up to 5 px. */
void synth_moved(const uint8_t *first, uint8_t *second, int w, int h, unsigned seed);

/* The field of synth_moved at pixel (x, y), rounded as it is applied. */
void synth_moved_field(int x, int y, int w, int h, int *u, int *v);

#endif /* SSDA_SYNTH_TEXTURE_H */
