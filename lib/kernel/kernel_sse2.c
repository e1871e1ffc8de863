/*
 * kernel_sse2.c - inner loops for x86 and x86-64 with SSE2 (every x86-64).
 * Exact: every function returns the same value as its reference in
 * kernel/portable.h, for every input (tests/test_kernel.c). Unaligned loads
 * throughout, so rows may start anywhere.
 *
 * 8-bit:  PSADBW (_mm_sad_epu8) sums 16 absolute byte differences into two
 *         64-bit lanes per instruction.
 * 16-bit: no 16-bit SAD instruction; |a - b| = (a -sat b) | (b -sat a) with
 *         unsigned saturating subtracts (one of the two is 0), then the eight
 *         16-bit lanes are widened to 32 bits and added. int16 samples are
 *         first mapped to uint16 by flipping the sign bit (x + 32768, order
 *         and differences preserved), then take the same path.
 * Each 32-bit lane holds a part of the total, and the total is <= 65535 *
 * 65535 < 2^32 (kernels.h), so no lane can overflow.
 *
 * Products (correlation), 8-bit: bytes widened to 16-bit lanes, PMADDWD
 * adds pairs of products (<= 2 * 255^2, exact in its signed 32-bit lanes)
 * into 32-bit lanes that together hold the total (< 2^32). 16-bit: PMULLW
 * and PMULHUW give the low and high halves of the exact 32-bit products;
 * the halves are summed apart in 32-bit lanes (each lane <= 16384 halves
 * < 2^16 for n * rows <= 65536 pixels, < 2^30) and joined in 64 bits.
 */
#include <emmintrin.h>
#include <string.h>

#include "kernel/kernels.h"
#include "kernel/portable.h"

#if !defined(__SSE2__)
#error "kernel_sse2.c needs SSE2; use SSDA_KERNEL=portable"
#endif

static inline __m128i load128(const void *p)
{
    return _mm_loadu_si128((const __m128i *)p);
}

/* The sum of the four 32-bit lanes (the caller guarantees it fits). */
static inline uint32_t hsum_u32x4(__m128i v)
{
    v = _mm_add_epi32(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(1, 0, 3, 2)));
    v = _mm_add_epi32(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(2, 3, 0, 1)));
    return (uint32_t)_mm_cvtsi128_si32(v);
}

/* Add the eight |a - b| of unsigned 16-bit lanes to four 32-bit lanes. */
static inline __m128i add_absdiff_u16x8(__m128i acc, __m128i a, __m128i b)
{
    const __m128i zero = _mm_setzero_si128();
    __m128i d = _mm_or_si128(_mm_subs_epu16(a, b), _mm_subs_epu16(b, a));
    acc = _mm_add_epi32(acc, _mm_unpacklo_epi16(d, zero));
    return _mm_add_epi32(acc, _mm_unpackhi_epi16(d, zero));
}

uint32_t ssda__sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    __m128i acc = _mm_setzero_si128(); /* two 64-bit lanes, total <= 255 * 65535 */
    uint32_t i = 0u;
    for (; i + 32u <= n; i += 32u) {
        acc = _mm_add_epi64(acc, _mm_sad_epu8(load128(a + i), load128(b + i)));
        acc = _mm_add_epi64(acc, _mm_sad_epu8(load128(a + i + 16u), load128(b + i + 16u)));
    }
    for (; i + 16u <= n; i += 16u) {
        acc = _mm_add_epi64(acc, _mm_sad_epu8(load128(a + i), load128(b + i)));
    }
    acc = _mm_add_epi64(acc, _mm_unpackhi_epi64(acc, acc));
    return (uint32_t)_mm_cvtsi128_si32(acc) + ssda__portable_sad_row_u8(a + i, b + i, n - i);
}

uint32_t ssda__sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    __m128i acc = _mm_setzero_si128(); /* lanes sum to <= 65535 * 65535 < 2^32 */
    uint32_t i = 0u;
    for (; i + 8u <= n; i += 8u) {
        acc = add_absdiff_u16x8(acc, load128(a + i), load128(b + i));
    }
    return hsum_u32x4(acc) + ssda__portable_sad_row_u16(a + i, b + i, n - i);
}

uint32_t ssda__absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    const __m128i bias = _mm_set1_epi16((short)-32768); /* flips the sign bit */
    __m128i acc = _mm_setzero_si128(); /* lanes sum to <= 65535 * 65535 < 2^32 */
    uint32_t i = 0u;
    for (; i + 8u <= n; i += 8u) {
        acc = add_absdiff_u16x8(acc, _mm_xor_si128(load128(a + i), bias),
                                _mm_xor_si128(load128(b + i), bias));
    }
    return hsum_u32x4(acc) + ssda__portable_absdiff_row_i16(a + i, b + i, n - i);
}

/* Products of 8 byte pairs (widened to 16-bit lanes) added to acc. */
static inline __m128i madd_u8x8(__m128i acc, __m128i a, __m128i b)
{
    const __m128i zero = _mm_setzero_si128();
    return _mm_add_epi32(acc, _mm_madd_epi16(_mm_unpacklo_epi8(a, zero),
                                             _mm_unpacklo_epi8(b, zero)));
}

static inline __m128i load32(const void *p)
{
    int32_t w;
    (void)memcpy(&w, p, sizeof w);
    return _mm_cvtsi32_si128(w);
}

uint32_t ssda__dot_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                      size_t bstride, uint32_t n, uint32_t rows)
{
    __m128i acc = _mm_setzero_si128(); /* 32-bit lanes; their total < 2^32 (kernels.h) */
    const uint32_t n16 = n & ~15u;
    const uint32_t r3 = n & 3u;
    uint32_t tail = 0u, r;
    if (n == 16u) { /* the common window width, straight-line */
        for (r = 0u; r < rows; r++) {
            const __m128i va = load128(a + r * astride);
            const __m128i vb = load128(b + r * bstride);
            acc = madd_u8x8(acc, va, vb);
            acc = madd_u8x8(acc, _mm_unpackhi_epi64(va, va), _mm_unpackhi_epi64(vb, vb));
        }
        return hsum_u32x4(acc);
    }
    for (r = 0u; r < rows; r++) {
        const uint8_t *pa = a + r * astride;
        const uint8_t *pb = b + r * bstride;
        uint32_t i;
        for (i = 0u; i < n16; i += 16u) {
            const __m128i va = load128(pa + i);
            const __m128i vb = load128(pb + i);
            acc = madd_u8x8(acc, va, vb);
            acc = madd_u8x8(acc, _mm_unpackhi_epi64(va, va), _mm_unpackhi_epi64(vb, vb));
        }
        if ((n & 8u) != 0u) {
            acc = madd_u8x8(acc, _mm_loadl_epi64((const __m128i *)(const void *)(pa + i)),
                            _mm_loadl_epi64((const __m128i *)(const void *)(pb + i)));
            i += 8u;
        }
        if ((n & 4u) != 0u) {
            acc = madd_u8x8(acc, load32(pa + i), load32(pb + i));
            i += 4u;
        }
        if (r3 != 0u) { /* at most three: written out, no loop to vectorise */
            tail += (uint32_t)pa[i] * pb[i];
            if (r3 > 1u) {
                tail += (uint32_t)pa[i + 1u] * pb[i + 1u];
                if (r3 > 2u) {
                    tail += (uint32_t)pa[i + 2u] * pb[i + 2u];
                }
            }
        }
    }
    return hsum_u32x4(acc) + tail;
}

uint64_t ssda__dot_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                       size_t bstride, uint32_t n, uint32_t rows)
{
    const __m128i zero = _mm_setzero_si128();
    __m128i lo = zero; /* low halves of the products, lanes < 2^30 */
    __m128i hi = zero; /* high halves, lanes < 2^30 */
    uint64_t tail = 0u;
    uint32_t r;
    for (r = 0u; r < rows; r++) {
        const uint16_t *pa = (const uint16_t *)(const void *)((const uint8_t *)(const void *)a + r * astride);
        const uint16_t *pb = (const uint16_t *)(const void *)((const uint8_t *)(const void *)b + r * bstride);
        uint32_t i = 0u;
        for (; i + 8u <= n; i += 8u) {
            __m128i va = load128(pa + i);
            __m128i vb = load128(pb + i);
            __m128i pl = _mm_mullo_epi16(va, vb);
            __m128i ph = _mm_mulhi_epu16(va, vb);
            lo = _mm_add_epi32(lo, _mm_add_epi32(_mm_unpacklo_epi16(pl, zero),
                                                 _mm_unpackhi_epi16(pl, zero)));
            hi = _mm_add_epi32(hi, _mm_add_epi32(_mm_unpacklo_epi16(ph, zero),
                                                 _mm_unpackhi_epi16(ph, zero)));
        }
        tail += ssda__portable_dot_row_u16(pa + i, pb + i, n - i);
    }
    return ((uint64_t)hsum_u32x4(hi) << 16) + hsum_u32x4(lo) + tail;
}

const char *ssda__kernel_name(void)
{
    return "sse2";
}
