/* kernel_portable.c - the portable C kernel set (the reference). */
#include "kernel/kernels.h"
#include "kernel/portable.h"

uint32_t ssda__sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    return ssda__portable_sad_row_u8(a, b, n);
}

uint32_t ssda__sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    return ssda__portable_sad_row_u16(a, b, n);
}

uint32_t ssda__absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    return ssda__portable_absdiff_row_i16(a, b, n);
}

uint32_t ssda__dot_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                      size_t bstride, uint32_t n, uint32_t rows)
{
    uint32_t sum = 0u; /* n * rows <= 65536: < 2^32 (kernels.h) */
    uint32_t r;
    for (r = 0u; r < rows; r++) {
        sum += ssda__portable_dot_row_u8(a + r * astride, b + r * bstride, n);
    }
    return sum;
}

uint64_t ssda__dot_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                       size_t bstride, uint32_t n, uint32_t rows)
{
    uint64_t sum = 0u; /* < 2^48 (kernels.h) */
    uint32_t r;
    for (r = 0u; r < rows; r++) {
        sum += ssda__portable_dot_row_u16(
            (const uint16_t *)(const void *)((const uint8_t *)(const void *)a + r * astride),
            (const uint16_t *)(const void *)((const uint8_t *)(const void *)b + r * bstride), n);
    }
    return sum;
}

/* The rows loops (kernels.h) over this set's row functions. */
uint32_t ssda__sad_rows_u8(const uint8_t *a, size_t astride, const uint8_t *b, size_t bstride,
                           uint32_t n, uint32_t rows, uint32_t limit, uint32_t *sum)
{
    return ssda__portable_rows_u8(ssda__sad_row_u8, a, astride, b, bstride, n, rows, limit, sum);
}

uint32_t ssda__sad_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                            size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                            uint32_t *sum)
{
    return ssda__portable_rows_u16(ssda__sad_row_u16, a, astride, b, bstride, n, rows, limit, sum);
}

uint32_t ssda__refine4(const uint32_t *b, const uint32_t *g, size_t down, const uint32_t *wgrp,
                       const uint32_t *wblk, uint32_t rest, uint32_t cut, uint32_t *term_out,
                       uint32_t *groups)
{
    return ssda__portable_refine4(b, g, down, wgrp, wblk, rest, cut, term_out, groups);
}

void ssda__bounds4(uint32_t *p, const uint32_t *g, size_t down, const uint32_t *w, uint32_t n)
{
    ssda__portable_bounds4(p, g, down, w, n);
}

void ssda__bounds4_open(uint32_t *p, const uint32_t *g, size_t gstride, size_t down,
                        const uint32_t *w, uint32_t nx, uint32_t rows, uint32_t s,
                        uint32_t *open)
{
    ssda__portable_bounds4_open(p, g, gstride, down, w, nx, rows, s, open);
}

uint32_t ssda__any_u16(const uint8_t *p, size_t stride, uint32_t n, uint32_t rows, uint16_t t)
{
    return ssda__portable_any_u16(p, stride, n, rows, t);
}

void ssda__blocks16(const uint8_t *w, size_t stride, bool u8, uint32_t *wblk, uint32_t *wgrp)
{
    ssda__portable_blocks16(w, stride, u8, wblk, wgrp);
}

void ssda__vslide(uint32_t *v, const uint8_t *add, const uint8_t *sub, uint32_t n, bool u8)
{
    ssda__portable_vslide(v, add, sub, n, u8);
}

void ssda__tab_row(uint32_t *p, uint32_t *b, const uint32_t *v, uint32_t vlen, uint32_t L)
{
    ssda__portable_tab_row(p, b, v, vlen, L);
}

uint32_t ssda__sad16_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                              size_t bstride, uint32_t rows, const uint32_t *limit,
                              uint32_t *sum)
{
    return ssda__portable_sad16_rows_u16(a, astride, b, bstride, rows, limit, sum);
}

const char *ssda__kernel_name(void)
{
    return "portable";
}

const ssda__kernel_variant_t *ssda__kernel_variant(uint32_t i)
{
    (void)i; /* no run-time choice: the public loops are the only ones */
    return NULL;
}
