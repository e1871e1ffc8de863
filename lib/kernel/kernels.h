/*
 * kernels.h - the library's inner loops. Exactly one implementation file,
 * kernel/kernel_<name>.c, is linked, chosen at configure time (SSDA_KERNEL:
 * portable, sse2, armv7em). Every implementation returns the exact sum,
 * bit-identical to the reference in kernel/portable.h; an implementation that
 * does not accelerate a loop calls the portable inline for it.
 */
#ifndef SSDA_KERNEL_KERNELS_H
#define SSDA_KERNEL_KERNELS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "compiler.h"

/* Sum of |a[i] - b[i]| for i < n, n <= 65535.
   Worst case 255 * 65535 = 16 711 425 < 2^32. */
SSDA_INTERNAL uint32_t ssda__sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n);

/* Sum of |a[i] - b[i]| for i < n, n <= 65535.
   Worst case 65535 * 65535 = 4 294 836 225 < 2^32 - 1. */
SSDA_INTERNAL uint32_t ssda__sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n);

/* The SAD rows of a placement, cut as the engine cuts them: rows of n
   pixels (row r of a at a + r * astride bytes, of b likewise) added one
   after another to *sum, stopping after the first row at which *sum
   reaches limit. Returns the rows added (1 .. rows, rows >= 1): rows when
   the limit was never reached after a row before the last; the caller
   compares *sum with limit. The caller guarantees that *sum stays below
   2^32 (the engine's fast path: every SAD of the window < 2^32 - 1). The
   same sums as ssda__sad_row_u8/u16 row by row; one call for several rows
   (issue 18: a call per 16-pixel row cost more than the row). */
SSDA_INTERNAL uint32_t ssda__sad_rows_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                                         size_t bstride, uint32_t n, uint32_t rows,
                                         uint32_t limit, uint32_t *sum);
SSDA_INTERNAL uint32_t ssda__sad_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                                          size_t bstride, uint32_t n, uint32_t rows,
                                          uint32_t limit, uint32_t *sum);

/* Tracking's 4 x 4 block terms for a 16-column window of 4 groups of 4
   rows (the engine's tab_refine4): for group k = 0, 1, ... the sum s_k of
   |b[k * down + 4 j] - wblk[4 k + j]|, j < 4 (block sums < 2^20), replaces
   the group's term |g[k * down] - wgrp[k]| (group sums < 2^31) in rest:
   rest = rest - term + s_k, term_out[k] = s_k, stopping after the first
   group at which rest reaches cut. Returns rest (< 2^32: the caller's
   bound, at most the SAD) and sets *groups to the groups done (1..4).
   The entries of all 4 groups must be readable (a variant may sum them
   all and pick the stopping group after), and term_out[k] for k >= the
   groups done may be written too. */
SSDA_INTERNAL uint32_t ssda__refine4(const uint32_t *b, const uint32_t *g, size_t down,
                                     const uint32_t *wgrp, const uint32_t *wblk, uint32_t rest,
                                     uint32_t cut, uint32_t *term_out, uint32_t *groups);

/* One row of tracking's group bounds (the engine's pre_bounds, 4 groups):
   p[i] = sum over k < 4 of |g[i + k * down] - w[k]|, i < n, with every g
   and w below 2^31 (signed differences) and every p[i] below 2^32 (the
   caller's: a bound <= a SAD). p must not overlap g. */
SSDA_INTERNAL void ssda__bounds4(uint32_t *p, const uint32_t *g, size_t down, const uint32_t *w,
                                 uint32_t n);

/* Tracking's rows of one 16-pixel-wide placement (the engine's 4 x 4 block
   case, 16-bit samples): rows 0 .. rows-1 of 16 pixels (row r of a at
   a + r * astride bytes, of b likewise) summed in order from 0, each row's
   running sum checked against the limit of its group of 4 rows,
   limit[r / 4] for r < 16 and limit[4] for r >= 16; the first 8 pixels of
   row 0 are checked against limit[0] first. Returns the pixels summed up
   to the first check that reaches its limit (8, or 16 (r + 1)), else
   16 rows, and sets *sum to the running sum there. rows >= 1, and the
   sum of all rows below 2^32 (16 rows * 65535 each: rows <= 4096). */
SSDA_INTERNAL uint32_t ssda__sad16_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                                            size_t bstride, uint32_t rows, const uint32_t *limit,
                                            uint32_t *sum);

/* Tracking's group bounds of a whole area for its predict scan (the
   engine's scan_predict_open, 4 groups): for y < rows, row y of p (nx
   entries at p + y * nx) is ssda__bounds4 of g + y * gstride (groups
   `down` entries apart), and bit x of open[y] is set when p[y * nx + x]
   <= s. nx <= 32; the ranges of ssda__bounds4. */
SSDA_INTERNAL void ssda__bounds4_open(uint32_t *p, const uint32_t *g, size_t gstride,
                                      size_t down, const uint32_t *w, uint32_t nx,
                                      uint32_t rows, uint32_t s, uint32_t *open);

/* One row of tracking's shared tables (track_tab.c) from its vertical
   sums v[0 .. vlen-1]: first the prefix sums p[k] = v[0] + .. + v[k-1]
   modulo 2^32 into p[0 .. vlen] (vlen + 1 entries), then, when b is not
   NULL, b[i] = p[i + 4] - p[i] for i < vlen - 3 (the 4 x 4 sums), then in
   place p[i] = p[i + L] - p[i] for i <= vlen - L (the L x 4 sums),
   ascending, all modulo 2^32. p[vlen] is read once, before b is written:
   b may begin at p + vlen (the tables' one-slot layout). 1 <= L <= vlen,
   and vlen >= 4 with b. */
SSDA_INTERNAL void ssda__tab_row(uint32_t *p, uint32_t *b, const uint32_t *v, uint32_t vlen,
                                 uint32_t L);

/* Tracking's vertical sums slid down a row (track_tab.c): v[i] = v[i] +
   add[i] - sub[i] modulo 2^32 for i < n, samples of 8 bits (u8) or 16
   bits (add and sub then 2-byte aligned). */
SSDA_INTERNAL void ssda__vslide(uint32_t *v, const uint8_t *add, const uint8_t *sub, uint32_t n,
                                bool u8);

/* Tracking's window sums for its 4 x 4 block terms (the engine's
   window_blocks4, 16 x 16..19 windows): over rows 0..15 of 16 pixels (row
   r at w + r * stride bytes; 8-bit samples when u8, else 16-bit),
   wblk[4 k + c] = the sum of the 4 x 4 block of rows 4k..4k+3 and columns
   4c..4c+3 (< 16 * 65535 < 2^20), and wgrp[k] = wblk[4k] + .. +
   wblk[4k + 3] (< 2^22), k, c < 4. */
SSDA_INTERNAL void ssda__blocks16(const uint8_t *w, size_t stride, bool u8, uint32_t *wblk,
                                  uint32_t *wgrp);

/* Tracking's mask test (track_rows.c): 1 when some sample of rows 0 ..
   rows-1 of n 16-bit samples (row r at p + r * stride bytes) equals t,
   else 0. */
SSDA_INTERNAL uint32_t ssda__any_u16(const uint8_t *p, size_t stride, uint32_t n, uint32_t rows,
                                     uint16_t t);

/* AMDF term: sum of |a[i] - b[i]| for int16 samples, i < n, n <= 65535.
   Each |difference| <= 65535, so the worst case is 65535 * 65535 < 2^32. */
SSDA_INTERNAL uint32_t ssda__absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n);

/* Correlation (ncc.h): sum of a[i] * b[i] over `rows` rows of n pixels,
   row r of a at a + r * astride bytes (b likewise), n * rows <= 65536.
   8-bit worst case 65536 * 255^2 = 4 261 478 400 < 2^32; 16-bit
   65536 * 65535^2 < 2^48. */
SSDA_INTERNAL uint32_t ssda__dot_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                      size_t bstride, uint32_t n, uint32_t rows);
SSDA_INTERNAL uint64_t ssda__dot_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                       size_t bstride, uint32_t n, uint32_t rows);

/* Name of the compiled kernel set ("portable", "sse2", "armv7em"). */
SSDA_INTERNAL const char *ssda__kernel_name(void);

/* The SAD row loops of one variant of the compiled set. A set may hold
   several (the x86 set: SSE2, and AVX2 chosen at run time where the
   processor has it); the functions above call the one this processor
   runs best. Every variant returns the portable reference's value. */
typedef struct {
    const char *name;
    uint32_t (*sad_row_u8)(const uint8_t *a, const uint8_t *b, uint32_t n);
    uint32_t (*sad_row_u16)(const uint16_t *a, const uint16_t *b, uint32_t n);
    uint32_t (*absdiff_row_i16)(const int16_t *a, const int16_t *b, uint32_t n);
    uint32_t (*sad_rows_u8)(const uint8_t *a, size_t astride, const uint8_t *b, size_t bstride,
                            uint32_t n, uint32_t rows, uint32_t limit, uint32_t *sum);
    uint32_t (*sad_rows_u16)(const uint16_t *a, size_t astride, const uint16_t *b,
                             size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                             uint32_t *sum);
    uint32_t (*refine4)(const uint32_t *b, const uint32_t *g, size_t down, const uint32_t *wgrp,
                        const uint32_t *wblk, uint32_t rest, uint32_t cut, uint32_t *term_out,
                        uint32_t *groups);
    void (*bounds4)(uint32_t *p, const uint32_t *g, size_t down, const uint32_t *w, uint32_t n);
    uint32_t (*sad16_rows_u16)(const uint16_t *a, size_t astride, const uint16_t *b,
                               size_t bstride, uint32_t rows, const uint32_t *limit,
                               uint32_t *sum);
    void (*bounds4_open)(uint32_t *p, const uint32_t *g, size_t gstride, size_t down,
                         const uint32_t *w, uint32_t nx, uint32_t rows, uint32_t s,
                         uint32_t *open);
    void (*tab_row)(uint32_t *p, uint32_t *b, const uint32_t *v, uint32_t vlen, uint32_t L);
    void (*vslide)(uint32_t *v, const uint8_t *add, const uint8_t *sub, uint32_t n, bool u8);
    void (*blocks16)(const uint8_t *w, size_t stride, bool u8, uint32_t *wblk, uint32_t *wgrp);
    uint32_t (*any_u16)(const uint8_t *p, size_t stride, uint32_t n, uint32_t rows, uint16_t t);
} ssda__kernel_variant_t;

/* Variant i (0 .. count-1) of the variants this processor can run, in
   order of preference from the plainest; NULL for i >= count. A set
   without a run-time choice (portable, armv7em) has none: count 0, its
   public loops are its only ones. For tests (each variant against the
   reference) and benchmarks. */
SSDA_INTERNAL const ssda__kernel_variant_t *ssda__kernel_variant(uint32_t i);

#endif /* SSDA_KERNEL_KERNELS_H */
