/*
 * kernel_armv7em.c - inner loops for cores with the ARMv7E-M DSP extension
 * (Cortex-M4, M7, M33, M35P, M55...), through the ACLE intrinsics of
 * <arm_acle.h>. Exact: every function returns the same value as its
 * reference in kernel/portable.h, for every input (tests/test_kernel.c).
 *
 * 8-bit: USADA8 adds the four absolute byte differences of two words to an
 * accumulator in one instruction: 16 pixels = 8 loads + 4 USADA8.
 *
 * 16-bit: there is no 16-bit absolute-difference instruction. Per pair of
 * halfwords (one 32-bit word),
 *     ba = USUB16(b, a)        lanes b - a (mod 2^16)
 *     ab = USUB16(a, b)        lanes a - b (mod 2^16); APSR.GE set per lane
 *                              where a >= b (no borrow)
 *     d  = SEL(ab, ba)         per lane: GE ? a - b : b - a = |a - b|
 * Each lane of d is the exact |a - b| in 0..65535 (the true difference fits
 * 16 unsigned bits once its sign is known). For int16 samples SSUB16 does
 * the same: GE is set where the full-precision a - b >= 0, and the low 16
 * bits of a difference in 0..65535 are that difference. Saturating or
 * halving subtracts (QSUB16, SHSUB16) would be shorter but inexact, so they
 * are not used. The two lanes are then added to the 32-bit sum (UXTAH and an
 * ADD with LSR #16): 7 instructions per 2 pixels with the loads.
 *
 * Products (correlation), 8-bit: a mask spreads bytes 0 and 2 (and, after a
 * shift by 8, bytes 1 and 3) of a word into two halfword lanes (one AND
 * each, the shift folded into it); SMLAD
 * multiplies both lane pairs and adds them to the accumulator. The lanes hold
 * 0..255, so the signed products are the unsigned ones, and the 32-bit sum
 * wraps like uint32_t arithmetic: the total < 2^32 (kernels.h) is exact
 * (SMLAD's Q flag may be set; nothing reads it). 16-bit: no unsigned dual
 * multiply; the portable loop (one UMLAL per pixel).
 *
 * Loads: memcpy of 4 bytes compiles to a single LDR; ARMv7-M and ARMv8-M
 * Mainline allow unaligned LDR, so any pointer alignment works (unaligned
 * words may cost a cycle more on the bus, never an instruction).
 */
#include <string.h>

#include "kernel/kernels.h"
#include "kernel/portable.h"

#if !defined(__ARM_FEATURE_DSP) || !defined(__ARM_FEATURE_SIMD32)
#error "kernel_armv7em.c needs a core with the DSP extension (Cortex-M4/M7/M33); use SSDA_KERNEL=portable"
#endif

#include <arm_acle.h>

static inline uint32_t load_u32(const void *p)
{
    uint32_t w;
    (void)memcpy(&w, p, sizeof w);
    return w;
}

/* |a - b| of both unsigned halfword lanes (see the file comment). */
static inline uint32_t absdiff_u16x2(uint32_t a, uint32_t b)
{
    uint32_t ba = (uint32_t)__usub16(b, a);
    uint32_t ab = (uint32_t)__usub16(a, b); /* GE from a - b: last writer wins */
    return (uint32_t)__sel(ab, ba);
}

/* |a - b| of both signed halfword lanes, as unsigned 16-bit lanes. */
static inline uint32_t absdiff_i16x2(uint32_t a, uint32_t b)
{
    uint32_t ba = (uint32_t)__ssub16((int16x2_t)b, (int16x2_t)a);
    uint32_t ab = (uint32_t)__ssub16((int16x2_t)a, (int16x2_t)b);
    return (uint32_t)__sel(ab, ba);
}

/* The sum of the two unsigned halfword lanes of d (0..131070). */
static inline uint32_t lanes_sum(uint32_t d)
{
    return (d & 0xFFFFu) + (d >> 16);
}

/* The row loops, shared by the public functions and the rows loops. */
static SSDA_ALWAYS_INLINE uint32_t row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 255 * 65535 = 16 711 425 */
    const uint8_t *end16;
    if (n == 16u) { /* the seed's window row: straight-line, 14 instructions */
        sum = __usad8(load_u32(a), load_u32(b));
        sum = __usada8(load_u32(a + 4), load_u32(b + 4), sum);
        sum = __usada8(load_u32(a + 8), load_u32(b + 8), sum);
        return __usada8(load_u32(a + 12), load_u32(b + 12), sum);
    }
    end16 = a + (n & ~15u);
    while (a != end16) {
        sum = __usada8(load_u32(a), load_u32(b), sum);
        sum = __usada8(load_u32(a + 4), load_u32(b + 4), sum);
        sum = __usada8(load_u32(a + 8), load_u32(b + 8), sum);
        sum = __usada8(load_u32(a + 12), load_u32(b + 12), sum);
        a += 16;
        b += 16;
    }
    if ((n & 15u) != 0u) { /* one test on the common path (n = 16, 32, ...) */
        if ((n & 8u) != 0u) {
            sum = __usada8(load_u32(a), load_u32(b), sum);
            sum = __usada8(load_u32(a + 4), load_u32(b + 4), sum);
            a += 8;
            b += 8;
        }
        if ((n & 4u) != 0u) {
            sum = __usada8(load_u32(a), load_u32(b), sum);
            a += 4;
            b += 4;
        }
        sum += ssda__portable_sad_row_u8(a, b, n & 3u);
    }
    return sum;
}

static SSDA_ALWAYS_INLINE uint32_t row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65535 * 65535 = 4 294 836 225 < 2^32 */
    const uint16_t *end8 = a + (n & ~7u);
    while (a != end8) {
        sum += lanes_sum(absdiff_u16x2(load_u32(a), load_u32(b)));
        sum += lanes_sum(absdiff_u16x2(load_u32(a + 2), load_u32(b + 2)));
        sum += lanes_sum(absdiff_u16x2(load_u32(a + 4), load_u32(b + 4)));
        sum += lanes_sum(absdiff_u16x2(load_u32(a + 6), load_u32(b + 6)));
        a += 8;
        b += 8;
    }
    if ((n & 7u) != 0u) { /* one test on the common path (n = 8, 16, ...) */
        if ((n & 4u) != 0u) {
            sum += lanes_sum(absdiff_u16x2(load_u32(a), load_u32(b)));
            sum += lanes_sum(absdiff_u16x2(load_u32(a + 2), load_u32(b + 2)));
            a += 4;
            b += 4;
        }
        if ((n & 2u) != 0u) {
            sum += lanes_sum(absdiff_u16x2(load_u32(a), load_u32(b)));
            a += 2;
            b += 2;
        }
        sum += ssda__portable_sad_row_u16(a, b, n & 1u);
    }
    return sum;
}

uint32_t ssda__sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    return row_u8(a, b, n);
}

uint32_t ssda__sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    return row_u16(a, b, n);
}

uint32_t ssda__absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65535 * 65535 = 4 294 836 225 < 2^32 */
    const int16_t *end8 = a + (n & ~7u);
    while (a != end8) {
        sum += lanes_sum(absdiff_i16x2(load_u32(a), load_u32(b)));
        sum += lanes_sum(absdiff_i16x2(load_u32(a + 2), load_u32(b + 2)));
        sum += lanes_sum(absdiff_i16x2(load_u32(a + 4), load_u32(b + 4)));
        sum += lanes_sum(absdiff_i16x2(load_u32(a + 6), load_u32(b + 6)));
        a += 8;
        b += 8;
    }
    if ((n & 7u) != 0u) { /* one test on the common path (n = 8, 16, ...) */
        if ((n & 4u) != 0u) {
            sum += lanes_sum(absdiff_i16x2(load_u32(a), load_u32(b)));
            sum += lanes_sum(absdiff_i16x2(load_u32(a + 2), load_u32(b + 2)));
            a += 4;
            b += 4;
        }
        if ((n & 2u) != 0u) {
            sum += lanes_sum(absdiff_i16x2(load_u32(a), load_u32(b)));
            a += 2;
            b += 2;
        }
        sum += ssda__portable_absdiff_row_i16(a, b, n & 1u);
    }
    return sum;
}

/* The rows loops (kernels.h) over this set's row functions. */
uint32_t ssda__sad_rows_u8(const uint8_t *a, size_t astride, const uint8_t *b, size_t bstride,
                           uint32_t n, uint32_t rows, uint32_t limit, uint32_t *sum)
{
    return ssda__portable_rows_u8(row_u8, a, astride, b, bstride, n, rows, limit, sum);
}

uint32_t ssda__sad_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                            size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                            uint32_t *sum)
{
    return ssda__portable_rows_u16(row_u16, a, astride, b, bstride, n, rows, limit, sum);
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

/* Products of four byte pairs added to acc (see the file comment). */
static inline uint32_t dot_u8x4(uint32_t a, uint32_t b, uint32_t acc)
{
    const uint32_t lanes = 0x00FF00FFu; /* bytes 0 and 2 as halfword lanes */
    acc = (uint32_t)__smlad((int16x2_t)(a & lanes), (int16x2_t)(b & lanes), (int32_t)acc);
    return (uint32_t)__smlad((int16x2_t)((a >> 8) & lanes), (int16x2_t)((b >> 8) & lanes),
                             (int32_t)acc);
}

uint32_t ssda__dot_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                      size_t bstride, uint32_t n, uint32_t rows)
{
    uint32_t sum = 0u; /* n * rows <= 65536: < 2^32 (kernels.h) */
    uint32_t r;
    for (r = 0u; r < rows; r++) {
        const uint8_t *pa = a + r * astride;
        const uint8_t *pb = b + r * bstride;
        const uint8_t *end4 = pa + (n & ~3u);
        while (pa != end4) {
            sum = dot_u8x4(load_u32(pa), load_u32(pb), sum);
            pa += 4;
            pb += 4;
        }
        sum += ssda__portable_dot_row_u8(pa, pb, n & 3u);
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

const char *ssda__kernel_name(void)
{
    return "armv7em";
}

const ssda__kernel_variant_t *ssda__kernel_variant(uint32_t i)
{
    (void)i; /* no run-time choice: the public loops are the only ones */
    return NULL;
}
