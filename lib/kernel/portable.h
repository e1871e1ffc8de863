/*
 * portable.h - reference inner loops in plain C99, as static inline
 * functions: used by kernel_portable.c, by accelerated kernels for the loops
 * they do not speed up, and by tests as the bit-exact reference.
 */
#ifndef SSDA_KERNEL_PORTABLE_H
#define SSDA_KERNEL_PORTABLE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

static inline uint32_t ssda__portable_sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 255 * 65535 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (a[i] > b[i]) ? (uint32_t)a[i] - b[i] : (uint32_t)b[i] - a[i];
    }
    return sum;
}

static inline uint32_t ssda__portable_sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65535 * 65535 < 2^32 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (a[i] > b[i]) ? (uint32_t)a[i] - b[i] : (uint32_t)b[i] - a[i];
    }
    return sum;
}

/* The rows loops of kernels.h (ssda__sad_rows_u8/u16) over a set's row
   function: rows summed into *sum (< 2^32: the caller's condition) until
   `rows` are done or the sum reaches limit; returns the rows summed. */
static inline uint32_t ssda__portable_rows_u8(uint32_t (*row)(const uint8_t *, const uint8_t *,
                                                              uint32_t),
                                              const uint8_t *a, size_t astride, const uint8_t *b,
                                              size_t bstride, uint32_t n, uint32_t rows,
                                              uint32_t limit, uint32_t *sum)
{
    uint32_t s = *sum;
    uint32_t r = 0u;
    do {
        s += row(a + r * astride, b + r * bstride, n);
        r++;
    } while (r < rows && s < limit);
    *sum = s;
    return r;
}

/* The same for 16-bit rows (strides in bytes). */
static inline uint32_t ssda__portable_rows_u16(uint32_t (*row)(const uint16_t *, const uint16_t *,
                                                               uint32_t),
                                               const uint16_t *a, size_t astride, const uint16_t *b,
                                               size_t bstride, uint32_t n, uint32_t rows,
                                               uint32_t limit, uint32_t *sum)
{
    const uint8_t *pa = (const uint8_t *)(const void *)a;
    const uint8_t *pb = (const uint8_t *)(const void *)b;
    uint32_t s = *sum;
    uint32_t r = 0u;
    do {
        s += row((const uint16_t *)(const void *)(pa + r * astride),
                 (const uint16_t *)(const void *)(pb + r * bstride), n);
        r++;
    } while (r < rows && s < limit);
    *sum = s;
    return r;
}

/* Sum of |a[i] - b[i]| over pixels lo .. hi - 1 of a 16-bit row, for
   ssda__portable_sad16_rows_u16: its own loop, so that the sets' row
   functions keep their inlined ssda__portable_sad_row_u16 (a third caller
   made GCC call it out of line on the Cortex-M4: +16 B of stack). */
static inline uint32_t ssda__portable_sad16_part(const uint8_t *a, const uint8_t *b,
                                                 uint32_t lo, uint32_t hi)
{
    const uint16_t *p = (const uint16_t *)(const void *)a;
    const uint16_t *q = (const uint16_t *)(const void *)b;
    uint32_t s = 0u, i; /* <= 16 * 65535 */
    for (i = lo; i < hi; i++) {
        s += p[i] > q[i] ? (uint32_t)p[i] - q[i] : (uint32_t)q[i] - p[i];
    }
    return s;
}

/* ssda__sad16_rows_u16 (kernels.h), the reference: a row at a time. */
static inline uint32_t ssda__portable_sad16_rows_u16(const uint16_t *a, size_t astride,
                                                     const uint16_t *b, size_t bstride,
                                                     uint32_t rows, const uint32_t *limit,
                                                     uint32_t *sum)
{
    const uint8_t *pa = (const uint8_t *)(const void *)a;
    const uint8_t *pb = (const uint8_t *)(const void *)b;
    uint32_t s = ssda__portable_sad16_part(pa, pb, 0u, 8u); /* < 2^32: the caller's */
    size_t oa = 0u, ob = 0u;
    uint32_t r;
    if (s >= limit[0]) {
        *sum = s;
        return 8u;
    }
    s += ssda__portable_sad16_part(pa, pb, 8u, 16u);
    r = 0u;
    while (s < limit[r < 16u ? r / 4u : 4u] && r + 1u < rows) {
        oa += astride;
        ob += bstride;
        s += ssda__portable_sad16_part(pa + oa, pb + ob, 0u, 16u);
        r++;
    }
    *sum = s;
    return 16u * (r + 1u); /* <= 16 * 4096 */
}

static inline uint32_t ssda__portable_absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65535 * 65535 < 2^32 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        /* int32_t difference: -65535..65535, no overflow */
        int32_t d = (int32_t)a[i] - (int32_t)b[i];
        sum += (d < 0) ? (uint32_t)(-d) : (uint32_t)d;
    }
    return sum;
}

/* Products of one row (correlation): n <= 65536 pixels, so the 8-bit sum
   <= 65536 * 255^2 < 2^32 and the 16-bit one <= 65536 * 65535^2 < 2^48. */
static inline uint32_t ssda__portable_dot_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65536 * 65025 < 2^32 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (uint32_t)a[i] * b[i];
    }
    return sum;
}

static inline uint64_t ssda__portable_dot_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    uint64_t sum = 0u; /* <= 65536 * 65535^2 < 2^48 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (uint64_t)((uint32_t)a[i] * b[i]); /* one product < 2^32 */
    }
    return sum;
}

/* ssda__refine4 (kernels.h), the reference: signed differences (block
   sums < 2^20, group sums < 2^31), no compare and branch. */
static inline uint32_t ssda__portable_refine4(const uint32_t *b, const uint32_t *g, size_t down,
                                              const uint32_t *wgrp, const uint32_t *wblk,
                                              uint32_t rest, uint32_t cut, uint32_t *term_out,
                                              uint32_t *groups)
{
    uint32_t k;
    size_t o = 0u; /* group k's row */
    for (k = 0u; k < 4u; k++) {
        const uint32_t *w = &wblk[(size_t)4u * k];
        const int32_t dg = (int32_t)g[o] - (int32_t)wgrp[k];
        const int32_t d0 = (int32_t)b[o] - (int32_t)w[0];
        const int32_t d1 = (int32_t)b[o + 4u] - (int32_t)w[1];
        const int32_t d2 = (int32_t)b[o + 8u] - (int32_t)w[2];
        const int32_t d3 = (int32_t)b[o + 12u] - (int32_t)w[3];
        const uint32_t s = (uint32_t)(d0 < 0 ? -d0 : d0) + (uint32_t)(d1 < 0 ? -d1 : d1) +
                           (uint32_t)(d2 < 0 ? -d2 : d2) + (uint32_t)(d3 < 0 ? -d3 : d3);
        rest = rest - (uint32_t)(dg < 0 ? -dg : dg) + s; /* s >= the group's term */
        term_out[k] = s;
        if (rest >= cut) {
            *groups = k + 1u;
            return rest;
        }
        o += down;
    }
    *groups = 4u;
    return rest;
}

/* ssda__bounds4 (kernels.h), the reference. */
static inline void ssda__portable_bounds4(uint32_t *p, const uint32_t *g, size_t down,
                                          const uint32_t *w, uint32_t n)
{
    const int32_t w0 = (int32_t)w[0], w1 = (int32_t)w[1], w2 = (int32_t)w[2], w3 = (int32_t)w[3];
    const uint32_t *g1 = &g[down], *g2 = &g1[down], *g3 = &g2[down];
    size_t i;
    for (i = 0u; i < n; i++) {
        const int32_t d0 = (int32_t)g[i] - w0, d1 = (int32_t)g1[i] - w1;
        const int32_t d2 = (int32_t)g2[i] - w2, d3 = (int32_t)g3[i] - w3;
        p[i] = (uint32_t)(d0 < 0 ? -d0 : d0) + (uint32_t)(d1 < 0 ? -d1 : d1) +
               (uint32_t)(d2 < 0 ? -d2 : d2) + (uint32_t)(d3 < 0 ? -d3 : d3);
    }
}

/* ssda__bounds4_open (kernels.h), the reference. */
static inline void ssda__portable_bounds4_open(uint32_t *p, const uint32_t *g, size_t gstride,
                                               size_t down, const uint32_t *w, uint32_t nx,
                                               uint32_t rows, uint32_t s, uint32_t *open)
{
    const int32_t w0 = (int32_t)w[0], w1 = (int32_t)w[1], w2 = (int32_t)w[2], w3 = (int32_t)w[3];
    uint32_t y, x;
    for (y = 0u; y < rows; y++) { /* ssda__portable_bounds4 in its own loop (a second caller
                                     made GCC call it out of line on the Cortex-M4) */
        const uint32_t *g0 = g + (size_t)y * gstride;
        const uint32_t *g1 = &g0[down], *g2 = &g1[down], *g3 = &g2[down];
        uint32_t m = 0u;
        for (x = 0u; x < nx; x++) {
            const int32_t d0 = (int32_t)g0[x] - w0, d1 = (int32_t)g1[x] - w1;
            const int32_t d2 = (int32_t)g2[x] - w2, d3 = (int32_t)g3[x] - w3;
            p[x] = (uint32_t)(d0 < 0 ? -d0 : d0) + (uint32_t)(d1 < 0 ? -d1 : d1) +
                   (uint32_t)(d2 < 0 ? -d2 : d2) + (uint32_t)(d3 < 0 ? -d3 : d3);
            m |= (p[x] <= s ? 1u : 0u) << x;
        }
        open[y] = m;
        p += nx;
    }
}

/* ssda__tab_row (kernels.h), the reference: size_t indices, loops that
   vectorise. */
static inline void ssda__portable_tab_row(uint32_t *p, uint32_t *b, const uint32_t *v,
                                          uint32_t vlen, uint32_t L)
{
    const uint32_t npos = vlen - L + 1u; /* >= 1 */
    const uint32_t *ahead = p + L;
    uint32_t sum = 0u;
    size_t i;
    p[0] = 0u;
    for (i = 0u; i < vlen; i++) {
        sum += v[i]; /* modulo 2^32 */
        p[i + 1u] = sum;
    }
    /* sum = p[vlen], which b[0] may overwrite */
    if (b != NULL) {
        const uint32_t pitch = vlen - 3u; /* >= 1 */
        const uint32_t *p4 = p + 4;
        for (i = 0u; i + 1u < pitch; i++) {
            b[i] = p4[i] - p[i];
        }
        b[pitch - 1u] = sum - p[pitch - 1u]; /* p4[pitch - 1] = p[vlen] */
    }
    for (i = 0u; i + 1u < npos; i++) {
        p[i] = ahead[i] - p[i];
    }
    p[npos - 1u] = sum - p[npos - 1u]; /* ahead[npos - 1] = p[vlen] */
}

/* ssda__vslide (kernels.h), the reference. */
static inline void ssda__portable_vslide(uint32_t *v, const uint8_t *add, const uint8_t *sub,
                                         uint32_t n, bool u8)
{
    size_t i;
    if (u8) {
        for (i = 0u; i < n; i++) {
            v[i] += (uint32_t)add[i] - sub[i]; /* modulo 2^32 */
        }
    } else {
        const uint16_t *a = (const uint16_t *)(const void *)add;
        const uint16_t *b = (const uint16_t *)(const void *)sub;
        for (i = 0u; i < n; i++) {
            v[i] += (uint32_t)a[i] - b[i];
        }
    }
}

/* ssda__blocks16 (kernels.h), the reference. */
static inline void ssda__portable_blocks16(const uint8_t *w, size_t stride, bool u8,
                                           uint32_t *wblk, uint32_t *wgrp)
{
    uint32_t k, r, c, i;
    for (k = 0u; k < 4u; k++) {
        uint32_t g = 0u;
        for (c = 0u; c < 4u; c++) {
            uint32_t b = 0u;
            for (r = 4u * k; r < 4u * k + 4u; r++) {
                const uint8_t *p = w + (size_t)r * stride;
                for (i = 4u * c; i < 4u * c + 4u; i++) {
                    b += u8 ? p[i] : ((const uint16_t *)(const void *)p)[i];
                }
            }
            wblk[4u * k + c] = b;
            g += b;
        }
        wgrp[k] = g;
    }
}

/* ssda__any_u16 (kernels.h), the reference: the comparisons OR-ed, one
   test at the end. */
static inline uint32_t ssda__portable_any_u16(const uint8_t *p, size_t stride, uint32_t n,
                                              uint32_t rows, uint16_t t)
{
    uint32_t hit = 0u, r, i;
    for (r = 0u; r < rows; r++) {
        const uint16_t *q = (const uint16_t *)(const void *)(p + (size_t)r * stride);
        for (i = 0u; i < n; i++) {
            hit |= q[i] == t ? 1u : 0u;
        }
    }
    return hit;
}

#endif /* SSDA_KERNEL_PORTABLE_H */
