/*
 * kernel_sse2.c - inner loops for x86 and x86-64 with SSE2 (every x86-64),
 * and AVX2 variants of the SAD rows chosen at run time. Exact: every
 * function returns the same value as its reference in kernel/portable.h,
 * for every input (tests/test_kernel.c tests each variant this processor
 * runs). Unaligned loads throughout, so rows may start anywhere.
 *
 * 8-bit:  PSADBW (_mm_sad_epu8) sums 16 absolute byte differences into two
 *         64-bit lanes per instruction (VPSADBW: 32); an 8-byte block is a
 *         64-bit load whose zero upper half adds nothing.
 * 16-bit: no 16-bit SAD instruction; |a - b| = (a -sat b) | (b -sat a) with
 *         unsigned saturating subtracts (one of the two is 0), then the
 *         16-bit lanes are widened to 32 bits and added. int16 samples are
 *         first mapped to uint16 by flipping the sign bit (x + 32768, order
 *         and differences preserved), then take the same path.
 * Each 32-bit lane holds a part of the total, and the total is <= 65535 *
 * 65535 < 2^32 (kernels.h), so no lane can overflow.
 *
 * Run-time choice: GCC and Clang compile the AVX2 functions with
 * __attribute__((target("avx2"))) (the rest of the library stays plain
 * x86-64), and __builtin_cpu_supports("avx2") reads the processor model
 * that the compiler's runtime fills before main (it checks that the
 * operating system saves the YMM registers too). The read is one load of a
 * word that never changes after start-up, so the public loops test it on
 * every call: no state of ours, nothing to initialise, safe from any
 * thread. Other compilers get the SSE2 variant only.
 *
 * Products (correlation), 8-bit: bytes widened to 16-bit lanes, PMADDWD
 * adds pairs of products (<= 2 * 255^2, exact in its signed 32-bit lanes)
 * into 32-bit lanes that together hold the total (< 2^32). 16-bit: PMULLW
 * and PMULHUW give the low and high halves of the exact 32-bit products;
 * the halves are summed apart in 32-bit lanes (each lane <= 16384 halves
 * < 2^16 for n * rows <= 65536 pixels, < 2^30) and joined in 64 bits.
 */
#include <emmintrin.h>
#if defined(__GNUC__) || defined(__clang__)
#include <immintrin.h>
#endif
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

/* The 16- and 8-byte blocks and the scalar tail of an 8-bit row from
   element i on (n - i < 32), added to acc's two 64-bit lanes. */
static inline uint32_t sad_u8_tail(__m128i acc, const uint8_t *a, const uint8_t *b,
                                   uint32_t i, uint32_t n)
{
    if (n - i >= 16u) {
        acc = _mm_add_epi64(acc, _mm_sad_epu8(load128(a + i), load128(b + i)));
        i += 16u;
    }
    if (n - i >= 8u) { /* upper halves zero: |0 - 0| adds nothing */
        acc = _mm_add_epi64(acc, _mm_sad_epu8(_mm_loadl_epi64((const __m128i *)(const void *)(a + i)),
                                              _mm_loadl_epi64((const __m128i *)(const void *)(b + i))));
        i += 8u;
    }
    acc = _mm_add_epi64(acc, _mm_unpackhi_epi64(acc, acc));
    return (uint32_t)_mm_cvtsi128_si32(acc) + ssda__portable_sad_row_u8(a + i, b + i, n - i);
}

/* The 8- and 4-lane blocks and the scalar tail of a 16-bit row from element
   i on (n - i < 16), lanes mapped through x ^ bias (0: uint16; 0x8000:
   int16 to uint16), added to acc's 32-bit lanes. */
static inline uint32_t sad_16_tail(__m128i acc, const uint16_t *a, const uint16_t *b,
                                   uint32_t i, uint32_t n, __m128i bias)
{
    if (n - i >= 8u) {
        acc = add_absdiff_u16x8(acc, _mm_xor_si128(load128(a + i), bias),
                                _mm_xor_si128(load128(b + i), bias));
        i += 8u;
    }
    if (n - i >= 4u) { /* upper lanes equal (bias ^ bias): |d| = 0 */
        acc = add_absdiff_u16x8(
            acc, _mm_xor_si128(_mm_loadl_epi64((const __m128i *)(const void *)(a + i)), bias),
            _mm_xor_si128(_mm_loadl_epi64((const __m128i *)(const void *)(b + i)), bias));
        i += 4u;
    }
    return hsum_u32x4(acc) + ssda__portable_sad_row_u16(a + i, b + i, n - i);
}

static SSDA_ALWAYS_INLINE uint32_t sse2_sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    __m128i acc = _mm_setzero_si128(); /* two 64-bit lanes, total <= 255 * 65535 */
    uint32_t i = 0u;
    for (; i + 32u <= n; i += 32u) {
        acc = _mm_add_epi64(acc, _mm_sad_epu8(load128(a + i), load128(b + i)));
        acc = _mm_add_epi64(acc, _mm_sad_epu8(load128(a + i + 16u), load128(b + i + 16u)));
    }
    return sad_u8_tail(acc, a, b, i, n);
}

static SSDA_ALWAYS_INLINE uint32_t sse2_sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    __m128i acc = _mm_setzero_si128(); /* lanes sum to <= 65535 * 65535 < 2^32 */
    uint32_t i = 0u;
    for (; i + 16u <= n; i += 16u) {
        acc = add_absdiff_u16x8(acc, load128(a + i), load128(b + i));
        acc = add_absdiff_u16x8(acc, load128(a + i + 8u), load128(b + i + 8u));
    }
    return sad_16_tail(acc, a, b, i, n, _mm_setzero_si128());
}

/* int16 rows as uint16 rows: the sign bit flipped (x + 32768) on both
   sides keeps every difference. */
static inline const uint16_t *as_u16(const int16_t *p)
{
    return (const uint16_t *)(const void *)p;
}

static SSDA_ALWAYS_INLINE uint32_t sse2_absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    const __m128i bias = _mm_set1_epi16((short)-32768); /* flips the sign bit */
    __m128i acc = _mm_setzero_si128(); /* lanes sum to <= 65535 * 65535 < 2^32 */
    uint32_t i = 0u;
    for (; i + 8u <= n; i += 8u) {
        acc = add_absdiff_u16x8(acc, _mm_xor_si128(load128(a + i), bias),
                                _mm_xor_si128(load128(b + i), bias));
    }
    /* fewer than 8 left: the 4-lane block (biased), then the exact scalar
       reference on the remaining 0..3 samples */
    if (n - i >= 4u) {
        acc = add_absdiff_u16x8(
            acc, _mm_xor_si128(_mm_loadl_epi64((const __m128i *)(const void *)(as_u16(a) + i)), bias),
            _mm_xor_si128(_mm_loadl_epi64((const __m128i *)(const void *)(as_u16(b) + i)), bias));
        i += 4u;
    }
    return hsum_u32x4(acc) + ssda__portable_absdiff_row_i16(a + i, b + i, n - i);
}

#if defined(__GNUC__) || defined(__clang__)
/* Compiled for AVX2 whatever the build's -march (the attribute on each). */
static inline __attribute__((target("avx2")))
__m256i load256(const void *p)
{
    return _mm256_loadu_si256((const __m256i *)p);
}

/* The 16 |a - b| of unsigned 16-bit lanes added to eight 32-bit lanes: the
   low and high halves of each 32-bit pair separately. */
static inline __attribute__((target("avx2")))
__m256i add_absdiff_u16x16(__m256i acc, __m256i a, __m256i b)
{
    const __m256i d = _mm256_or_si256(_mm256_subs_epu16(a, b), _mm256_subs_epu16(b, a));
    acc = _mm256_add_epi32(acc, _mm256_and_si256(d, _mm256_set1_epi32(0xFFFF)));
    return _mm256_add_epi32(acc, _mm256_srli_epi32(d, 16));
}

static __attribute__((target("avx2")))
uint32_t avx2_sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    __m256i acc = _mm256_setzero_si256(); /* four 64-bit lanes, total <= 255 * 65535 */
    uint32_t i = 0u;
    for (; i + 64u <= n; i += 64u) {
        acc = _mm256_add_epi64(acc, _mm256_sad_epu8(load256(a + i), load256(b + i)));
        acc = _mm256_add_epi64(acc, _mm256_sad_epu8(load256(a + i + 32u), load256(b + i + 32u)));
    }
    if (n - i >= 32u) {
        acc = _mm256_add_epi64(acc, _mm256_sad_epu8(load256(a + i), load256(b + i)));
        i += 32u;
    }
    return sad_u8_tail(_mm_add_epi64(_mm256_castsi256_si128(acc), _mm256_extracti128_si256(acc, 1)),
                       a, b, i, n);
}

/* A 16-bit row through x ^ bias (see sad_16_tail), 16 lanes at a time. */
static inline __attribute__((target("avx2")))
uint32_t avx2_sad_row_16(const uint16_t *a, const uint16_t *b, uint32_t n, __m128i bias)
{
    const __m256i bias2 = _mm256_broadcastsi128_si256(bias);
    __m256i acc = _mm256_setzero_si256(); /* lanes sum to <= 65535 * 65535 < 2^32 */
    uint32_t i = 0u;
    for (; i + 16u <= n; i += 16u) {
        acc = add_absdiff_u16x16(acc, _mm256_xor_si256(load256(a + i), bias2),
                                 _mm256_xor_si256(load256(b + i), bias2));
    }
    return sad_16_tail(_mm_add_epi32(_mm256_castsi256_si128(acc), _mm256_extracti128_si256(acc, 1)),
                       a, b, i, n, bias);
}

static __attribute__((target("avx2")))
uint32_t avx2_sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    return avx2_sad_row_16(a, b, n, _mm_setzero_si128());
}

static __attribute__((target("avx2")))
uint32_t avx2_absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    /* sad_16_tail's scalar tail reads plain uint16: give the biased part a
       multiple of 4 samples (that tail then empty) and finish the last
       0..3 with the int16 reference */
    const uint32_t n4 = n & ~3u;
    return avx2_sad_row_16(as_u16(a), as_u16(b), n4, _mm_set1_epi16((short)-32768)) +
           ssda__portable_absdiff_row_i16(a + n4, b + n4, n - n4);
}
#endif

/* The rows loops (kernels.h). A 16-pixel row (the seed's windows) is
   straight-line code, its total from one horizontal sum; other widths go
   through the variant's row function. Both variants share the 16-pixel
   code: one 128-bit PSADBW (8-bit) or two 8-lane halves (16-bit) a row,
   where 256-bit registers would cost their setup (see the public loops). */
static SSDA_ALWAYS_INLINE uint32_t sad16_u8(const uint8_t *a, const uint8_t *b)
{
    const __m128i s = _mm_sad_epu8(load128(a), load128(b)); /* two 64-bit lanes */
    return (uint32_t)_mm_cvtsi128_si32(_mm_add_epi64(s, _mm_unpackhi_epi64(s, s)));
}

static SSDA_ALWAYS_INLINE uint32_t sad16_u16(const uint16_t *a, const uint16_t *b)
{
    const __m128i a0 = load128(a), a1 = load128(a + 8), b0 = load128(b), b1 = load128(b + 8);
    const __m128i d0 = _mm_or_si128(_mm_subs_epu16(a0, b0), _mm_subs_epu16(b0, a0));
    const __m128i d1 = _mm_or_si128(_mm_subs_epu16(a1, b1), _mm_subs_epu16(b1, a1));
    const __m128i lo = _mm_set1_epi32(0xFFFF);
    /* each 32-bit lane: four |d| <= 65535, < 2^18 */
    const __m128i v = _mm_add_epi32(_mm_add_epi32(_mm_and_si128(d0, lo), _mm_srli_epi32(d0, 16)),
                                    _mm_add_epi32(_mm_and_si128(d1, lo), _mm_srli_epi32(d1, 16)));
    return hsum_u32x4(v);
}

/* The rows loop over 8-bit rows, row the variant's row function (called
   for widths other than 16: inlined where it is constant). */
static SSDA_ALWAYS_INLINE uint32_t rows_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                                           size_t bstride, uint32_t n, uint32_t rows,
                                           uint32_t limit, uint32_t *sum,
                                           uint32_t (*row)(const uint8_t *, const uint8_t *,
                                                           uint32_t))
{
    uint32_t s = *sum, r = 0u;
    size_t oa = 0u, ob = 0u;
    do {
        s += n == 16u ? sad16_u8(a + oa, b + ob) : row(a + oa, b + ob, n);
        oa += astride;
        ob += bstride;
        r++;
    } while (r < rows && s < limit);
    *sum = s;
    return r;
}

static SSDA_ALWAYS_INLINE uint32_t rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                                            size_t bstride, uint32_t n, uint32_t rows,
                                            uint32_t limit, uint32_t *sum,
                                            uint32_t (*row)(const uint16_t *, const uint16_t *,
                                                            uint32_t))
{
    const uint8_t *pa = (const uint8_t *)(const void *)a;
    const uint8_t *pb = (const uint8_t *)(const void *)b;
    uint32_t s = *sum, r = 0u;
    size_t oa = 0u, ob = 0u;
    do {
        const uint16_t *qa = (const uint16_t *)(const void *)(pa + oa);
        const uint16_t *qb = (const uint16_t *)(const void *)(pb + ob);
        s += n == 16u ? sad16_u16(qa, qb) : row(qa, qb, n);
        oa += astride;
        ob += bstride;
        r++;
    } while (r < rows && s < limit);
    *sum = s;
    return r;
}

static uint32_t sse2_sad_rows_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                                 size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                                 uint32_t *sum)
{
    return rows_u8(a, astride, b, bstride, n, rows, limit, sum, sse2_sad_row_u8);
}

static uint32_t sse2_sad_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                                  size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                                  uint32_t *sum)
{
    return rows_u16(a, astride, b, bstride, n, rows, limit, sum, sse2_sad_row_u16);
}

#if defined(__GNUC__) || defined(__clang__)
static uint32_t avx2_sad_rows_u8(const uint8_t *a, size_t astride, const uint8_t *b,
                                 size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                                 uint32_t *sum)
{
    return rows_u8(a, astride, b, bstride, n, rows, limit, sum, avx2_sad_row_u8);
}

static uint32_t avx2_sad_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                                  size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                                  uint32_t *sum)
{
    return rows_u16(a, astride, b, bstride, n, rows, limit, sum, avx2_sad_row_u16);
}
#endif

/* ssda__sad16_rows_u16 (kernels.h), SSE2: a row at a time, its halves
   from the two 8-lane differences. */
static SSDA_NOINLINE uint32_t sse2_sad16_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                                    size_t bstride, uint32_t rows, const uint32_t *limit,
                                    uint32_t *sum)
{
    const uint8_t *pa = (const uint8_t *)(const void *)a;
    const uint8_t *pb = (const uint8_t *)(const void *)b;
    const __m128i zero = _mm_setzero_si128();
    size_t oa = 0u, ob = 0u;
    uint32_t s, r;
    {
        const __m128i a0 = load128(a), b0 = load128(b);
        const __m128i d0 = _mm_or_si128(_mm_subs_epu16(a0, b0), _mm_subs_epu16(b0, a0));
        s = hsum_u32x4(_mm_add_epi32(_mm_unpacklo_epi16(d0, zero), _mm_unpackhi_epi16(d0, zero)));
    }
    if (s >= limit[0]) {
        *sum = s;
        return 8u;
    }
    s += sse2_sad_row_u16(a + 8, b + 8, 8u);
    r = 0u;
    while (s < limit[r < 16u ? r / 4u : 4u] && r + 1u < rows) {
        oa += astride;
        ob += bstride;
        s += sad16_u16((const uint16_t *)(const void *)(pa + oa),
                       (const uint16_t *)(const void *)(pb + ob));
        r++;
    }
    *sum = s;
    return 16u * (r + 1u);
}

#if defined(__GNUC__) || defined(__clang__)
/* A 16-pixel 16-bit row's |a - b| in eight 32-bit lanes (two |d| <= 65535
   each: < 2^17), whose sum is the row's SAD. */
static inline __attribute__((target("avx2")))
__m256i row16_lanes(const uint8_t *a, const uint8_t *b)
{
    const __m256i x = load256(a), y = load256(b);
    const __m256i d = _mm256_or_si256(_mm256_subs_epu16(x, y), _mm256_subs_epu16(y, x));
    return _mm256_add_epi32(_mm256_and_si256(d, _mm256_set1_epi32(0xFFFF)),
                            _mm256_srli_epi32(d, 16));
}

/* The SADs of 8 rows of 16 16-bit pixels, row j at p + j * astride (q
   likewise), in lanes 0..7 (< 2^20 each): each row's lanes summed by
   horizontal adds, pixels 0-7 and 8-15 apart, then the halves joined. */
static inline __attribute__((target("avx2")))
__m256i rows8_sads(const uint8_t *p, size_t astride, const uint8_t *q, size_t bstride)
{
    __m256i h[4], q0, q1;
    uint32_t j;
    for (j = 0u; j < 4u; j++) { /* two rows at a time: few registers live */
        const __m256i v0 = row16_lanes(p, q);
        const __m256i v1 = row16_lanes(p + astride, q + bstride);
        h[j] = _mm256_hadd_epi32(v0, v1);
        p += 2u * astride;
        q += 2u * bstride;
    }
    /* q0: rows 0-3's sums over pixels 0-7 (low 128 bits) and 8-15 (high);
       q1 the same for rows 4-7 */
    q0 = _mm256_hadd_epi32(h[0], h[1]);
    q1 = _mm256_hadd_epi32(h[2], h[3]);
    return _mm256_add_epi32(_mm256_permute2x128_si256(q0, q1, 0x20),
                            _mm256_permute2x128_si256(q0, q1, 0x31));
}

/* ssda__sad16_rows_u16 (kernels.h), AVX2: eight rows a step with one test.
   The rows' SADs side by side (rows8_sads), their running sums (a prefix
   sum across the lanes, then the low half's total into the high half),
   compared with the rows' limits (unsigned: max == the sum); the first
   row that reaches its limit from the mask. Rows past that row in the step
   are read, never added: the reference's pixels and sum, one
   data-dependent branch a step instead of one a row (issue 18: the rows of
   a GOES-16 window are cut after about 8). The last rows % 8 a row at a
   time. */
static __attribute__((target("avx2")))
uint32_t avx2_sad16_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                             size_t bstride, uint32_t rows, const uint32_t *limit, uint32_t *sum)
{
    const uint8_t *pa = (const uint8_t *)(const void *)a;
    const uint8_t *pb = (const uint8_t *)(const void *)b;
    uint32_t s = hsum_u32x4(_mm256_castsi256_si128(row16_lanes(pa, pb))), r = 0u;
    if (s >= limit[0]) { /* the first 8 pixels of row 0: its low lanes */
        *sum = s;
        return 8u;
    }
    s = 0u;
    for (; rows - r >= 8u; r += 8u) {
        const uint32_t g = r / 4u; /* r is a multiple of 8 */
        const __m256i lim = _mm256_inserti128_si256(
            _mm256_castsi128_si256(_mm_set1_epi32((int)limit[g < 4u ? g : 4u])),
            _mm_set1_epi32((int)limit[g + 1u < 4u ? g + 1u : 4u]), 1);
        __m256i p = rows8_sads(pa, astride, pb, bstride);
        uint32_t run[8], hit;
        p = _mm256_add_epi32(p, _mm256_slli_si256(p, 4));
        p = _mm256_add_epi32(p, _mm256_slli_si256(p, 8));
        /* the low half's total into the high half, then the sum so far */
        p = _mm256_add_epi32(p, _mm256_permute2x128_si256(_mm256_shuffle_epi32(p, 0xFF),
                                                          _mm256_shuffle_epi32(p, 0xFF), 0x08));
        p = _mm256_add_epi32(p, _mm256_set1_epi32((int)s));
        _mm256_storeu_si256((__m256i *)(void *)run, p);
        hit = (uint32_t)_mm256_movemask_ps(
            _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_max_epu32(p, lim), p)));
        if (hit != 0u) {
            const uint32_t j = (uint32_t)__builtin_ctz(hit);
            *sum = run[j];
            return 16u * (r + j + 1u);
        }
        s = run[7];
        pa += 8u * astride;
        pb += 8u * bstride;
    }
    for (; r < rows; r++) { /* rows % 8 left */
        s += hsum_u32x4(_mm_add_epi32(_mm256_castsi256_si128(row16_lanes(pa, pb)),
                                      _mm256_extracti128_si256(row16_lanes(pa, pb), 1)));
        if (s >= limit[r < 16u ? r / 4u : 4u]) {
            *sum = s;
            return 16u * (r + 1u);
        }
        pa += astride;
        pb += bstride;
    }
    *sum = s;
    return 16u * rows;
}
#endif

/* ssda__refine4 (kernels.h): a group's four block sums (every fourth
   entry: b0 b4 b1 b5 and b8 b12 b9 0, then their low halves) gathered into
   one register by unpacks, their differences
   with the window's (signed: < 2^20) made absolute as x ^ m - m with m
   the sign mask, and summed across the lanes. */
static SSDA_NOINLINE uint32_t sse2_refine4(const uint32_t *b, const uint32_t *g, size_t down,
                             const uint32_t *wgrp, const uint32_t *wblk, uint32_t rest,
                             uint32_t cut, uint32_t *term_out, uint32_t *groups)
{
    uint32_t k;
    size_t o = 0u; /* group k's row */
    for (k = 0u; k < 4u; k++) {
        /* no entry past b[12] is read: it may end the table's row */
        const uint32_t *bk = &b[o];
        const __m128i x = _mm_unpacklo_epi32(_mm_loadl_epi64((const __m128i *)(const void *)bk),
                                             _mm_loadl_epi64((const __m128i *)(const void *)&bk[4]));
        const __m128i y = _mm_unpacklo_epi32(_mm_loadl_epi64((const __m128i *)(const void *)&bk[8]),
                                             _mm_cvtsi32_si128((int)bk[12])); /* b8 b12 b9 0 */
        const __m128i d = _mm_sub_epi32(_mm_unpacklo_epi64(x, y), load128(&wblk[(size_t)4u * k]));
        const __m128i m = _mm_srai_epi32(d, 31);
        const uint32_t s = hsum_u32x4(_mm_sub_epi32(_mm_xor_si128(d, m), m));
        const int32_t dg = (int32_t)g[o] - (int32_t)wgrp[k];
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

#if defined(__GNUC__) || defined(__clang__)
/* A group's four block sums b[0], b[4], b[8], b[12] in one register, by
   unpacks (no entry past b[12] is read: it may end the table's row). */
static inline __m128i blocks4(const uint32_t *b)
{
    const __m128i x = _mm_unpacklo_epi32(_mm_loadl_epi64((const __m128i *)(const void *)b),
                                         _mm_loadl_epi64((const __m128i *)(const void *)&b[4]));
    const __m128i y = _mm_unpacklo_epi32(_mm_loadl_epi64((const __m128i *)(const void *)&b[8]),
                                         _mm_cvtsi32_si128((int)b[12]));
    return _mm_unpacklo_epi64(x, y);
}

/* ssda__refine4 (kernels.h), AVX2: the four groups at once, no branch on
   the data. Two groups' block terms a register (VPABSD: block sums <
   2^20), their sums s_k by horizontal adds, the group terms' differences
   (group sums < 2^31: signed) likewise, then rest after each group as a
   prefix sum across the lanes, compared unsigned with cut (max == the
   value); the first group that reaches it from the mask. Every group's
   entries are read (the engine's: the position's 4 groups lie in the
   table) and every s_k is written: the reference's result, groups and
   terms up to the stopping group, without its data-dependent exits
   (issue 18: a GOES-16 window refines about 36 positions). */
static __attribute__((target("avx2")))
uint32_t avx2_refine4(const uint32_t *b, const uint32_t *g, size_t down, const uint32_t *wgrp,
                      const uint32_t *wblk, uint32_t rest, uint32_t cut, uint32_t *term_out,
                      uint32_t *groups)
{
    const __m256i x01 = _mm256_inserti128_si256(_mm256_castsi128_si256(blocks4(b)),
                                                blocks4(&b[down]), 1);
    const __m256i x23 = _mm256_inserti128_si256(_mm256_castsi128_si256(blocks4(&b[2u * down])),
                                                blocks4(&b[3u * down]), 1);
    const __m256i a01 = _mm256_abs_epi32(_mm256_sub_epi32(x01, load256(wblk)));
    const __m256i a23 = _mm256_abs_epi32(_mm256_sub_epi32(x23, load256(&wblk[8])));
    /* [s0 s2 s0 s2 | s1 s3 s1 s3], then s0 s1 s2 s3 */
    const __m256i h = _mm256_hadd_epi32(_mm256_hadd_epi32(a01, a23), _mm256_setzero_si256());
    const __m128i sk = _mm_unpacklo_epi32(_mm256_castsi256_si128(h), _mm256_extracti128_si256(h, 1));
    const __m128i gk = _mm_unpacklo_epi64(
        _mm_unpacklo_epi32(_mm_cvtsi32_si128((int)g[0]), _mm_cvtsi32_si128((int)g[down])),
        _mm_unpacklo_epi32(_mm_cvtsi32_si128((int)g[2u * down]),
                           _mm_cvtsi32_si128((int)g[3u * down])));
    const __m128i tk = _mm_abs_epi32(_mm_sub_epi32(gk, load128(wgrp)));
    __m128i r = _mm_sub_epi32(sk, tk); /* s_k - term_k, modulo 2^32 */
    uint32_t hit, k;
    r = _mm_add_epi32(r, _mm_slli_si128(r, 4));
    r = _mm_add_epi32(r, _mm_slli_si128(r, 8));
    r = _mm_add_epi32(r, _mm_set1_epi32((int)rest));
    _mm_storeu_si128((__m128i *)(void *)term_out, sk);
    hit = (uint32_t)_mm_movemask_ps(
        _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_max_epu32(r, _mm_set1_epi32((int)cut)), r)));
    k = (uint32_t)__builtin_ctz(hit | 8u); /* the first group at cut, else the last */
    *groups = k + 1u;
    /* lane k, by a variable permute (no store and reload) */
    return (uint32_t)_mm_cvtsi128_si32(_mm_castps_si128(
        _mm_permutevar_ps(_mm_castsi128_ps(r), _mm_cvtsi32_si128((int)k))));
}
#endif

/* ssda__bounds4 (kernels.h): 4 (SSE2) or 8 (AVX2) positions a step, the
   absolute values by the sign mask (SSE2) or VPABSD, the last 0..7 by
   the reference. */
static SSDA_NOINLINE void sse2_bounds4(uint32_t *p, const uint32_t *g, size_t down, const uint32_t *w,
                         uint32_t n)
{
    const __m128i w0 = _mm_set1_epi32((int)w[0]), w1 = _mm_set1_epi32((int)w[1]);
    const __m128i w2 = _mm_set1_epi32((int)w[2]), w3 = _mm_set1_epi32((int)w[3]);
    uint32_t i = 0u;
    for (; i + 4u <= n; i += 4u) {
        const __m128i d0 = _mm_sub_epi32(load128(g + i), w0);
        const __m128i d1 = _mm_sub_epi32(load128(g + down + i), w1);
        const __m128i d2 = _mm_sub_epi32(load128(g + 2u * down + i), w2);
        const __m128i d3 = _mm_sub_epi32(load128(g + 3u * down + i), w3);
        const __m128i m0 = _mm_srai_epi32(d0, 31), m1 = _mm_srai_epi32(d1, 31);
        const __m128i m2 = _mm_srai_epi32(d2, 31), m3 = _mm_srai_epi32(d3, 31);
        const __m128i a = _mm_add_epi32(_mm_sub_epi32(_mm_xor_si128(d0, m0), m0),
                                        _mm_sub_epi32(_mm_xor_si128(d1, m1), m1));
        const __m128i b = _mm_add_epi32(_mm_sub_epi32(_mm_xor_si128(d2, m2), m2),
                                        _mm_sub_epi32(_mm_xor_si128(d3, m3), m3));
        _mm_storeu_si128((__m128i *)(void *)(p + i), _mm_add_epi32(a, b));
    }
    ssda__portable_bounds4(p + i, g + i, down, w, n - i);
}

#if defined(__GNUC__) || defined(__clang__)
static __attribute__((target("avx2")))
void avx2_bounds4(uint32_t *p, const uint32_t *g, size_t down, const uint32_t *w, uint32_t n)
{
    const __m256i w0 = _mm256_set1_epi32((int)w[0]), w1 = _mm256_set1_epi32((int)w[1]);
    const __m256i w2 = _mm256_set1_epi32((int)w[2]), w3 = _mm256_set1_epi32((int)w[3]);
    uint32_t i = 0u;
    for (; i + 8u <= n; i += 8u) {
        const __m256i a0 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + i), w0));
        const __m256i a1 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + down + i), w1));
        const __m256i a2 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + 2u * down + i), w2));
        const __m256i a3 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + 3u * down + i), w3));
        _mm256_storeu_si256((__m256i *)(void *)(p + i),
                            _mm256_add_epi32(_mm256_add_epi32(a0, a1), _mm256_add_epi32(a2, a3)));
    }
    ssda__portable_bounds4(p + i, g + i, down, w, n - i);
}
#endif

/* ssda__bounds4_open (kernels.h), SSE2: 4 positions a step, p <= s as
   s >= p by the signed compare of both with the sign bit flipped; the
   last nx % 4 by an overlapping step (the same values written again), or
   the reference for rows under 4 positions. */
static SSDA_NOINLINE void sse2_bounds4_open(uint32_t *p, const uint32_t *g, size_t gstride,
                                            size_t down, const uint32_t *w, uint32_t nx,
                                            uint32_t rows, uint32_t s, uint32_t *open)
{
    const __m128i w0 = _mm_set1_epi32((int)w[0]), w1 = _mm_set1_epi32((int)w[1]);
    const __m128i w2 = _mm_set1_epi32((int)w[2]), w3 = _mm_set1_epi32((int)w[3]);
    const __m128i flip = _mm_set1_epi32((int)0x80000000u);
    const __m128i sf = _mm_xor_si128(_mm_set1_epi32((int)s), flip);
    uint32_t y;
    if (nx < 4u) {
        ssda__portable_bounds4_open(p, g, gstride, down, w, nx, rows, s, open);
        return;
    }
    for (y = 0u; y < rows; y++) {
        const uint32_t *gy = g + (size_t)y * gstride;
        uint32_t m = 0u, i = 0u;
        for (;;) {
            const __m128i d0 = _mm_sub_epi32(load128(gy + i), w0);
            const __m128i d1 = _mm_sub_epi32(load128(gy + down + i), w1);
            const __m128i d2 = _mm_sub_epi32(load128(gy + 2u * down + i), w2);
            const __m128i d3 = _mm_sub_epi32(load128(gy + 3u * down + i), w3);
            const __m128i m0 = _mm_srai_epi32(d0, 31), m1 = _mm_srai_epi32(d1, 31);
            const __m128i m2 = _mm_srai_epi32(d2, 31), m3 = _mm_srai_epi32(d3, 31);
            const __m128i v = _mm_add_epi32(
                _mm_add_epi32(_mm_sub_epi32(_mm_xor_si128(d0, m0), m0),
                              _mm_sub_epi32(_mm_xor_si128(d1, m1), m1)),
                _mm_add_epi32(_mm_sub_epi32(_mm_xor_si128(d2, m2), m2),
                              _mm_sub_epi32(_mm_xor_si128(d3, m3), m3)));
            /* lanes with p > s, inverted */
            const uint32_t over = (uint32_t)_mm_movemask_ps(
                _mm_castsi128_ps(_mm_cmpgt_epi32(_mm_xor_si128(v, flip), sf)));
            _mm_storeu_si128((__m128i *)(void *)(p + i), v);
            m |= (~over & 15u) << i;
            if (i + 4u == nx) {
                break;
            }
            i = i + 8u <= nx ? i + 4u : nx - 4u; /* the last step overlaps */
        }
        open[y] = m;
        p += nx;
    }
}

#if defined(__GNUC__) || defined(__clang__)
/* ssda__bounds4_open (kernels.h), AVX2: 8 positions a step (VPABSD, p <= s
   as min(p, s) == p), the last nx % 8 by an overlapping step; rows under 8
   positions by the SSE2 variant. */
static __attribute__((target("avx2")))
void avx2_bounds4_open(uint32_t *p, const uint32_t *g, size_t gstride, size_t down,
                       const uint32_t *w, uint32_t nx, uint32_t rows, uint32_t s,
                       uint32_t *open)
{
    const __m256i w0 = _mm256_set1_epi32((int)w[0]), w1 = _mm256_set1_epi32((int)w[1]);
    const __m256i w2 = _mm256_set1_epi32((int)w[2]), w3 = _mm256_set1_epi32((int)w[3]);
    const __m256i sv = _mm256_set1_epi32((int)s);
    uint32_t y;
    if (nx < 8u) {
        sse2_bounds4_open(p, g, gstride, down, w, nx, rows, s, open);
        return;
    }
    for (y = 0u; y < rows; y++) {
        uint32_t m = 0u, i = 0u;
        for (;;) {
            const __m256i a0 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + i), w0));
            const __m256i a1 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + down + i), w1));
            const __m256i a2 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + 2u * down + i), w2));
            const __m256i a3 = _mm256_abs_epi32(_mm256_sub_epi32(load256(g + 3u * down + i), w3));
            const __m256i v = _mm256_add_epi32(_mm256_add_epi32(a0, a1), _mm256_add_epi32(a2, a3));
            _mm256_storeu_si256((__m256i *)(void *)(p + i), v);
            m |= (uint32_t)_mm256_movemask_ps(_mm256_castsi256_ps(
                     _mm256_cmpeq_epi32(_mm256_min_epu32(v, sv), v)))
                 << i;
            if (i + 8u == nx) {
                break;
            }
            i = i + 16u <= nx ? i + 8u : nx - 8u; /* the last step overlaps */
        }
        open[y] = m;
        p += nx;
        g += gstride;
    }
}
#endif

/* ssda__tab_row (kernels.h), SSE2: the reference (its difference loops
   vectorise at the build's SSE2). */
static SSDA_NOINLINE void sse2_tab_row(uint32_t *p, uint32_t *b, const uint32_t *v,
                                       uint32_t vlen, uint32_t L)
{
    ssda__portable_tab_row(p, b, v, vlen, L);
}

#if defined(__GNUC__) || defined(__clang__)
/* ssda__tab_row (kernels.h), AVX2: the prefix sums 8 at a time (a prefix
   sum across the lanes, the low half's total into the high half, then the
   running total broadcast from the last lane), the differences 8 at a
   time, the last ones as the reference. Reads p[0 .. vlen - 1] only after
   the prefix pass (p[vlen] from the running total): b may overlay it. */
static __attribute__((target("avx2")))
void avx2_tab_row(uint32_t *p, uint32_t *b, const uint32_t *v, uint32_t vlen, uint32_t L)
{
    const uint32_t npos = vlen - L + 1u; /* >= 1 */
    __m256i run = _mm256_setzero_si256(); /* the sum so far, in every lane */
    uint32_t sum;
    size_t i;
    p[0] = 0u;
    for (i = 0u; i + 8u <= vlen; i += 8u) {
        __m256i x = load256(v + i);
        x = _mm256_add_epi32(x, _mm256_slli_si256(x, 4));
        x = _mm256_add_epi32(x, _mm256_slli_si256(x, 8));
        x = _mm256_add_epi32(x, _mm256_permute2x128_si256(_mm256_shuffle_epi32(x, 0xFF),
                                                          _mm256_shuffle_epi32(x, 0xFF), 0x08));
        x = _mm256_add_epi32(x, run);
        _mm256_storeu_si256((__m256i *)(void *)(p + i + 1u), x);
        run = _mm256_permutevar8x32_epi32(x, _mm256_set1_epi32(7));
    }
    sum = (uint32_t)_mm_cvtsi128_si32(_mm256_castsi256_si128(run));
    for (; i < vlen; i++) {
        sum += v[i]; /* modulo 2^32 */
        p[i + 1u] = sum;
    }
    if (b != NULL) {
        const size_t last = (size_t)vlen - 4u; /* b's last entry: pitch - 1 */
        for (i = 0u; i + 8u <= last; i += 8u) {
            _mm256_storeu_si256((__m256i *)(void *)(b + i),
                                _mm256_sub_epi32(load256(p + 4 + i), load256(p + i)));
        }
        for (; i < last; i++) {
            b[i] = p[i + 4u] - p[i];
        }
        b[last] = sum - p[last]; /* p[last + 4] = p[vlen] */
    }
    for (i = 0u; i + 8u <= (size_t)npos - 1u; i += 8u) { /* in place: p[i + L..] not yet replaced */
        _mm256_storeu_si256((__m256i *)(void *)(p + i),
                            _mm256_sub_epi32(load256(p + L + i), load256(p + i)));
    }
    for (; i + 1u < npos; i++) {
        p[i] = p[i + L] - p[i];
    }
    p[npos - 1u] = sum - p[npos - 1u]; /* p[npos - 1 + L] = p[vlen] */
}
#endif

/* ssda__vslide (kernels.h), SSE2: the reference (it vectorises). */
static SSDA_NOINLINE void sse2_vslide(uint32_t *v, const uint8_t *add, const uint8_t *sub,
                                      uint32_t n, bool u8)
{
    ssda__portable_vslide(v, add, sub, n, u8);
}

#if defined(__GNUC__) || defined(__clang__)
/* ssda__vslide (kernels.h), AVX2: 8 samples widened to 32-bit lanes a
   step, the last n % 8 as the reference. */
static __attribute__((target("avx2")))
void avx2_vslide(uint32_t *v, const uint8_t *add, const uint8_t *sub, uint32_t n, bool u8)
{
    size_t i = 0u;
    if (u8) {
        for (; i + 8u <= n; i += 8u) {
            const __m256i a = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)(add + i)));
            const __m256i b = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)(sub + i)));
            _mm256_storeu_si256((__m256i *)(void *)(v + i),
                                _mm256_add_epi32(load256(v + i), _mm256_sub_epi32(a, b)));
        }
        ssda__portable_vslide(v + i, add + i, sub + i, n - (uint32_t)i, true);
    } else {
        for (; i + 8u <= n; i += 8u) {
            const __m256i a = _mm256_cvtepu16_epi32(load128(add + 2u * i));
            const __m256i b = _mm256_cvtepu16_epi32(load128(sub + 2u * i));
            _mm256_storeu_si256((__m256i *)(void *)(v + i),
                                _mm256_add_epi32(load256(v + i), _mm256_sub_epi32(a, b)));
        }
        ssda__portable_vslide(v + i, add + 2u * i, sub + 2u * i, n - (uint32_t)i, false);
    }
}
#endif

/* ssda__any_u16 (kernels.h), SSE2: the reference. */
static SSDA_NOINLINE uint32_t sse2_any_u16(const uint8_t *p, size_t stride, uint32_t n,
                                           uint32_t rows, uint16_t t)
{
    return ssda__portable_any_u16(p, stride, n, rows, t);
}

#if defined(__GNUC__) || defined(__clang__)
/* ssda__any_u16 (kernels.h), AVX2: 16 samples a compare, the masks OR-ed
   over the rows and tested once; the last n % 16 of each row as the
   reference. */
static __attribute__((target("avx2")))
uint32_t avx2_any_u16(const uint8_t *p, size_t stride, uint32_t n, uint32_t rows, uint16_t t)
{
    const __m256i tv = _mm256_set1_epi16((short)t);
    const uint32_t n16 = n & ~15u;
    __m256i acc = _mm256_setzero_si256();
    uint32_t tail = 0u, r, i;
    if (n == 16u || n == 32u) { /* the seed's windows and areas: no loop in a row */
        for (r = 0u; r < rows; r++) {
            acc = _mm256_or_si256(acc, _mm256_cmpeq_epi16(load256(p), tv));
            if (n == 32u) {
                acc = _mm256_or_si256(acc, _mm256_cmpeq_epi16(load256(p + 32), tv));
            }
            p += stride;
        }
        return (uint32_t)(_mm256_testz_si256(acc, acc) == 0);
    }
    for (r = 0u; r < rows; r++) {
        const uint8_t *q = p + (size_t)r * stride;
        for (i = 0u; i < n16; i += 16u) {
            acc = _mm256_or_si256(acc, _mm256_cmpeq_epi16(load256(q + (size_t)i * 2u), tv));
        }
        tail |= ssda__portable_any_u16(q + (size_t)n16 * 2u, 0u, n - n16, 1u, t);
    }
    return (uint32_t)(_mm256_testz_si256(acc, acc) == 0) | tail;
}
#endif

/* ssda__blocks16 (kernels.h), SSE2: the reference. */
static SSDA_NOINLINE void sse2_blocks16(const uint8_t *w, size_t stride, bool u8, uint32_t *wblk,
                                        uint32_t *wgrp)
{
    ssda__portable_blocks16(w, stride, u8, wblk, wgrp);
}

#if defined(__GNUC__) || defined(__clang__)
/* ssda__blocks16 (kernels.h), AVX2: a row as 16 16-bit lanes (8-bit rows
   widened), its pixel pairs summed into 8 32-bit lanes, 4 rows added (a
   group: lanes < 8 * 65535), then the pairs of each block and the blocks
   of each group by horizontal adds. */
static inline __attribute__((target("avx2")))
__m256i group16_pairs(const uint8_t *w, size_t stride, bool u8)
{
    const __m256i lo = _mm256_set1_epi32(0xFFFF);
    __m256i acc = _mm256_setzero_si256();
    uint32_t r;
    for (r = 0u; r < 4u; r++) {
        const __m256i x = u8 ? _mm256_cvtepu8_epi16(load128(w)) : load256(w);
        acc = _mm256_add_epi32(acc, _mm256_add_epi32(_mm256_and_si256(x, lo),
                                                     _mm256_srli_epi32(x, 16)));
        w += stride;
    }
    return acc;
}

static __attribute__((target("avx2")))
void avx2_blocks16(const uint8_t *w, size_t stride, bool u8, uint32_t *wblk, uint32_t *wgrp)
{
    const __m256i g0 = group16_pairs(w, stride, u8);
    const __m256i g1 = group16_pairs(w + 4u * stride, stride, u8);
    const __m256i g2 = group16_pairs(w + 8u * stride, stride, u8);
    const __m256i g3 = group16_pairs(w + 12u * stride, stride, u8);
    /* [b0 b1 of g0, b0 b1 of g1 | b2 b3 of g0, b2 b3 of g1], g2 g3 alike */
    const __m256i h01 = _mm256_hadd_epi32(g0, g1), h23 = _mm256_hadd_epi32(g2, g3);
    const __m256i s = _mm256_hadd_epi32(h01, h23); /* halves of the groups' sums */
    _mm256_storeu_si256((__m256i *)(void *)wblk, _mm256_permute4x64_epi64(h01, 0xD8));
    _mm256_storeu_si256((__m256i *)(void *)(wblk + 8), _mm256_permute4x64_epi64(h23, 0xD8));
    _mm_storeu_si128((__m128i *)(void *)wgrp,
                     _mm_add_epi32(_mm256_castsi256_si128(s), _mm256_extracti128_si256(s, 1)));
}
#endif

/* 1 where the processor (and the operating system) runs AVX2, else 0. */
static inline uint32_t x86_avx2(void)
{
#if defined(__GNUC__) || defined(__clang__)
    return (uint32_t)(__builtin_cpu_supports("avx2") != 0);
#else
    return 0u;
#endif
}

/* The public loops: SSE2 inline, AVX2 only for rows long enough to gain
   from it. ssda-bench-kernel on an AMD EPYC: rows up to 64 bytes cost the
   call (about 3.3 ns) whatever the width, and the 256-bit setup costs more
   than it saves below 128 bytes or 32 16-bit samples. Short rows (16 px:
   the tracking windows) pay one compare on their length and nothing else;
   long rows index a two-entry table by the processor's AVX2 bit, so no
   branch depends on the processor. */
uint32_t ssda__sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
#if defined(__GNUC__) || defined(__clang__)
    static uint32_t (*const pick[2])(const uint8_t *, const uint8_t *, uint32_t) = {
        sse2_sad_row_u8, avx2_sad_row_u8
    };
    if (n >= 128u) {
        return pick[x86_avx2()](a, b, n);
    }
#endif
    return sse2_sad_row_u8(a, b, n);
}

uint32_t ssda__sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
#if defined(__GNUC__) || defined(__clang__)
    static uint32_t (*const pick[2])(const uint16_t *, const uint16_t *, uint32_t) = {
        sse2_sad_row_u16, avx2_sad_row_u16
    };
    if (n >= 32u) {
        return pick[x86_avx2()](a, b, n);
    }
#endif
    return sse2_sad_row_u16(a, b, n);
}

uint32_t ssda__absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
#if defined(__GNUC__) || defined(__clang__)
    static uint32_t (*const pick[2])(const int16_t *, const int16_t *, uint32_t) = {
        sse2_absdiff_row_i16, avx2_absdiff_row_i16
    };
    if (n >= 32u) {
        return pick[x86_avx2()](a, b, n);
    }
#endif
    return sse2_absdiff_row_i16(a, b, n);
}

/* The rows loops: the variant of the public row loops (AVX2 only for the
   long rows, as there). */
uint32_t ssda__sad_rows_u8(const uint8_t *a, size_t astride, const uint8_t *b, size_t bstride,
                           uint32_t n, uint32_t rows, uint32_t limit, uint32_t *sum)
{
#if defined(__GNUC__) || defined(__clang__)
    if (n >= 128u && x86_avx2() != 0u) {
        return avx2_sad_rows_u8(a, astride, b, bstride, n, rows, limit, sum);
    }
#endif
    return sse2_sad_rows_u8(a, astride, b, bstride, n, rows, limit, sum);
}

uint32_t ssda__sad_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                            size_t bstride, uint32_t n, uint32_t rows, uint32_t limit,
                            uint32_t *sum)
{
#if defined(__GNUC__) || defined(__clang__)
    if (n >= 32u && x86_avx2() != 0u) {
        return avx2_sad_rows_u16(a, astride, b, bstride, n, rows, limit, sum);
    }
#endif
    return sse2_sad_rows_u16(a, astride, b, bstride, n, rows, limit, sum);
}

uint32_t ssda__refine4(const uint32_t *b, const uint32_t *g, size_t down, const uint32_t *wgrp,
                       const uint32_t *wblk, uint32_t rest, uint32_t cut, uint32_t *term_out,
                       uint32_t *groups)
{
#if defined(__GNUC__) || defined(__clang__)
    if (x86_avx2() != 0u) {
        return avx2_refine4(b, g, down, wgrp, wblk, rest, cut, term_out, groups);
    }
#endif
    return sse2_refine4(b, g, down, wgrp, wblk, rest, cut, term_out, groups);
}

uint32_t ssda__sad16_rows_u16(const uint16_t *a, size_t astride, const uint16_t *b,
                              size_t bstride, uint32_t rows, const uint32_t *limit,
                              uint32_t *sum)
{
#if defined(__GNUC__) || defined(__clang__)
    if (x86_avx2() != 0u) {
        return avx2_sad16_rows_u16(a, astride, b, bstride, rows, limit, sum);
    }
#endif
    return sse2_sad16_rows_u16(a, astride, b, bstride, rows, limit, sum);
}

uint32_t ssda__any_u16(const uint8_t *p, size_t stride, uint32_t n, uint32_t rows, uint16_t t)
{
#if defined(__GNUC__) || defined(__clang__)
    if (x86_avx2() != 0u) {
        return avx2_any_u16(p, stride, n, rows, t);
    }
#endif
    return sse2_any_u16(p, stride, n, rows, t);
}

void ssda__blocks16(const uint8_t *w, size_t stride, bool u8, uint32_t *wblk, uint32_t *wgrp)
{
#if defined(__GNUC__) || defined(__clang__)
    if (x86_avx2() != 0u) {
        avx2_blocks16(w, stride, u8, wblk, wgrp);
        return;
    }
#endif
    sse2_blocks16(w, stride, u8, wblk, wgrp);
}

void ssda__vslide(uint32_t *v, const uint8_t *add, const uint8_t *sub, uint32_t n, bool u8)
{
#if defined(__GNUC__) || defined(__clang__)
    if (x86_avx2() != 0u) {
        avx2_vslide(v, add, sub, n, u8);
        return;
    }
#endif
    sse2_vslide(v, add, sub, n, u8);
}

void ssda__tab_row(uint32_t *p, uint32_t *b, const uint32_t *v, uint32_t vlen, uint32_t L)
{
#if defined(__GNUC__) || defined(__clang__)
    if (x86_avx2() != 0u) {
        avx2_tab_row(p, b, v, vlen, L);
        return;
    }
#endif
    sse2_tab_row(p, b, v, vlen, L);
}

void ssda__bounds4_open(uint32_t *p, const uint32_t *g, size_t gstride, size_t down,
                        const uint32_t *w, uint32_t nx, uint32_t rows, uint32_t s,
                        uint32_t *open)
{
#if defined(__GNUC__) || defined(__clang__)
    if (x86_avx2() != 0u) {
        avx2_bounds4_open(p, g, gstride, down, w, nx, rows, s, open);
        return;
    }
#endif
    sse2_bounds4_open(p, g, gstride, down, w, nx, rows, s, open);
}

void ssda__bounds4(uint32_t *p, const uint32_t *g, size_t down, const uint32_t *w, uint32_t n)
{
#if defined(__GNUC__) || defined(__clang__)
    if (n >= 8u && x86_avx2() != 0u) {
        avx2_bounds4(p, g, down, w, n);
        return;
    }
#endif
    sse2_bounds4(p, g, down, w, n);
}

const ssda__kernel_variant_t *ssda__kernel_variant(uint32_t i)
{
    static const ssda__kernel_variant_t x86_variants[] = {
        { "sse2", sse2_sad_row_u8, sse2_sad_row_u16, sse2_absdiff_row_i16, sse2_sad_rows_u8,
          sse2_sad_rows_u16, sse2_refine4, sse2_bounds4, sse2_sad16_rows_u16,
          sse2_bounds4_open, sse2_tab_row, sse2_vslide, sse2_blocks16,
          sse2_any_u16 },
#if defined(__GNUC__) || defined(__clang__)
        { "avx2", avx2_sad_row_u8, avx2_sad_row_u16, avx2_absdiff_row_i16, avx2_sad_rows_u8,
          avx2_sad_rows_u16, avx2_refine4, avx2_bounds4, avx2_sad16_rows_u16,
          avx2_bounds4_open, avx2_tab_row, avx2_vslide, avx2_blocks16,
          avx2_any_u16 },
#endif
    };
    return (i < 1u + x86_avx2()) ? &x86_variants[i] : NULL;
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
