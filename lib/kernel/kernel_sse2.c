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
 */
#include <emmintrin.h>

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

const char *ssda__kernel_name(void)
{
    return "sse2";
}
