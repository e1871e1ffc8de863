/*
 * jobs.h - the jobs the cycle-count image times on the emulated Cortex-M4.
 * Each family is compiled only when its public header exists (the CMake
 * project defines SSDA_BUDGET_HAVE_<FEATURE>), so features that land later
 * are picked up by tools/budget.sh without edits here.
 */
#ifndef SSDA_BUDGET_JOBS_H
#define SSDA_BUDGET_JOBS_H

#include <stdint.h>

/* A known loop (2 instructions per iteration) to check the method. */
void jobs_calibrate(void);
/* ssda__sad_row_u8/u16, ssda__absdiff_row_i16: instructions per pixel. */
void jobs_kernel(void);
/* ssda_match, 16 x 16 windows in 32 x 32 areas, by mode. */
void jobs_match(void);
/* ssda_track, the seed's 7 x 7 grid on 128 x 128 images. */
void jobs_track(void);
/* ssda_pitch_push, instructions per analysis frame, by mode. */
void jobs_pitch(void);
/* kl.h, mixture.h, region.h: per pixel and per fit. */
void jobs_segment(void);
/* ssda_push_row of push-mode tracking: one row, and a whole frame. */
void jobs_stream(void);
/* Seed 001's chain on a 96 x 96 pair: edges, loops, descriptors, matches,
   registration. */
void jobs_symreg(void);

/* Deterministic test data (xorshift32, smoothed). */
uint32_t jobs_rand(uint32_t *state);
/* w x h 8-bit texture, random values low-passed by two 3 x 3 box filters
   (a cloud-like field with a few pixels of correlation length). */
void jobs_texture_u8(uint8_t *img, uint32_t w, uint32_t h, uint32_t seed);

#endif /* SSDA_BUDGET_JOBS_H */
