/*
 * test_kernel.c - the compiled kernel set (portable, sse2 or armv7em: see
 * ssda__kernel_name()) against the reference loops of kernel/portable.h and an
 * independent 64-bit reference written here: random rows of every length
 * 0..MAX_LEN at every pointer misalignment, lane patterns that exercise both
 * signs of a - b within one machine word, and the accumulator worst cases
 * (65535 differences of 255 for 8-bit, of 65535 for 16-bit and int16).
 *
 * The host build tests its SIMD set (sse2 on x86), every variant of it the
 * processor runs (ssda__kernel_variant: SSE2, and AVX2 where the processor
 * has it) as well as the run-time choice; the QEMU builds test the armv7em
 * set (mps2-an386, mps2-an500) and the portable set (mps2-an385).
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "kernel/kernels.h"
#include "kernel/portable.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

/* Longest random row; covers every unrolled block size plus all tails. */
#define MAX_LEN 200u
/* Misalignments tried for each pointer, in elements (bytes for 8-bit). */
#define MAX_OFF 4u
/* The longest row the kernels accept (kernels.h). */
#define N_MAX 65535u

/* Two rows of N_MAX + 1 16-bit elements: room for the worst cases at a
   misaligned start (256 KiB; reused as bytes and as int16_t). */
static uint16_t g_big[2u * (N_MAX + 1u)];
static uint8_t g_a8[MAX_LEN + MAX_OFF], g_b8[MAX_LEN + MAX_OFF];
static uint16_t g_a16[MAX_LEN + MAX_OFF], g_b16[MAX_LEN + MAX_OFF];
static int16_t g_ai16[MAX_LEN + MAX_OFF], g_bi16[MAX_LEN + MAX_OFF];

/* Independent references: signed 64-bit differences, no shortcuts. */
static uint64_t ref_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint64_t s = 0;
    uint32_t i;
    for (i = 0; i < n; i++) {
        int64_t d = (int64_t)a[i] - (int64_t)b[i];
        s += (uint64_t)(d < 0 ? -d : d);
    }
    return s;
}

static uint64_t ref_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    uint64_t s = 0;
    uint32_t i;
    for (i = 0; i < n; i++) {
        int64_t d = (int64_t)a[i] - (int64_t)b[i];
        s += (uint64_t)(d < 0 ? -d : d);
    }
    return s;
}

static uint64_t ref_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    uint64_t s = 0;
    uint32_t i;
    for (i = 0; i < n; i++) {
        int64_t d = (int64_t)a[i] - (int64_t)b[i];
        s += (uint64_t)(d < 0 ? -d : d);
    }
    return s;
}

/* A sample in 0..maxval: the extremes half of the time, so that words
   holding max and 0 side by side (both signs of a - b) are common. */
static uint32_t sample(test_rng_t *r, uint32_t maxval)
{
    switch (test_rng_next(r) & 3u) {
    case 0:
        return 0u;
    case 1:
        return maxval;
    default:
        return test_rng_range(r, 0u, maxval);
    }
}

/* want against the public loop (the variant this processor runs) and
   against every variant of the set it can run (x86: SSE2 and AVX2). */
static void check_sad_row_u8(uint64_t want, const uint8_t *a, const uint8_t *b, uint32_t n)
{
    const ssda__kernel_variant_t *k;
    uint32_t v;
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(want, ssda__sad_row_u8(a, b, n), ssda__kernel_name());
    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(want, k->sad_row_u8(a, b, n), k->name);
    }
}

static void check_sad_row_u16(uint64_t want, const uint16_t *a, const uint16_t *b, uint32_t n)
{
    const ssda__kernel_variant_t *k;
    uint32_t v;
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(want, ssda__sad_row_u16(a, b, n), ssda__kernel_name());
    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(want, k->sad_row_u16(a, b, n), k->name);
    }
}

static void check_absdiff_row_i16(uint64_t want, const int16_t *a, const int16_t *b, uint32_t n)
{
    const ssda__kernel_variant_t *k;
    uint32_t v;
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(want, ssda__absdiff_row_i16(a, b, n), ssda__kernel_name());
    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(want, k->absdiff_row_i16(a, b, n), k->name);
    }
}

/* The variants: none for a set without a run-time choice, else the first
   named like the set; no gaps; on an x86 host whose processor has AVX2,
   the AVX2 variant is among them (so the checks above run it). */
static void test_kernel_variants_listed(void)
{
    uint32_t v = 0u;
    if (ssda__kernel_variant(0u) != NULL) {
        TEST_ASSERT_EQUAL_STRING(ssda__kernel_name(), ssda__kernel_variant(0u)->name);
    }
    while (ssda__kernel_variant(v) != NULL) {
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->sad_row_u8);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->sad_row_u16);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->absdiff_row_i16);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->sad_rows_u8);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->sad_rows_u16);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->refine4);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->bounds4);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->sad16_rows_u16);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->bounds4_open);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->tab_row);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->vslide);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->blocks16);
        TEST_ASSERT_NOT_NULL(ssda__kernel_variant(v)->any_u16);
        v++;
    }
    TEST_ASSERT_NULL(ssda__kernel_variant(v + 1u));
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(SSDA_TEST_SMALL)
    if (ssda__kernel_name()[0] == 's') {
        /* the count a run expects (tests/CMakeLists.txt: test_kernel_no_avx2
           under an emulated processor without AVX2), when it sets one */
        const char *want = getenv("SSDA_TEST_VARIANTS");
        TEST_ASSERT_EQUAL_UINT32(__builtin_cpu_supports("avx2") ? 2u : 1u, v);
        if (want != NULL) {
            TEST_ASSERT_EQUAL_UINT32((uint32_t)strtoul(want, NULL, 10), v);
        }
        if (v == 2u) {
            TEST_ASSERT_EQUAL_STRING("avx2", ssda__kernel_variant(1u)->name);
        }
    }
#endif
}

static void test_kernel_name_is_known(void)
{
    const char *name = ssda__kernel_name();
    TEST_ASSERT_NOT_NULL(name);
#ifdef SSDA_EXPECT_KERNEL
    /* Cross builds: the configure-time choice is the set that got linked. */
    TEST_ASSERT_EQUAL_STRING(SSDA_EXPECT_KERNEL, name);
#else
    TEST_ASSERT_TRUE(name[0] == 'p' || name[0] == 's' || name[0] == 'a');
#endif
}

static void test_sad_u8_random_every_length_and_alignment(void)
{
    test_rng_t r;
    uint32_t i, oa, ob, n;
    test_rng_seed(&r, 0x5AD08u);
    for (i = 0; i < MAX_LEN + MAX_OFF; i++) {
        g_a8[i] = (uint8_t)sample(&r, 255u);
        g_b8[i] = (uint8_t)sample(&r, 255u);
    }
    for (oa = 0; oa < MAX_OFF; oa++) {
        for (ob = 0; ob < MAX_OFF; ob++) {
            for (n = 0; n <= MAX_LEN; n++) {
                const uint8_t *a = g_a8 + oa, *b = g_b8 + ob;
                uint64_t want = ref_u8(a, b, n);
                TEST_ASSERT_EQUAL_UINT64(want, ssda__portable_sad_row_u8(a, b, n));
                check_sad_row_u8(want, a, b, n);
            }
        }
    }
}

static void test_sad_u16_random_every_length_and_alignment(void)
{
    test_rng_t r;
    uint32_t i, oa, ob, n;
    test_rng_seed(&r, 0x5AD16u);
    for (i = 0; i < MAX_LEN + MAX_OFF; i++) {
        g_a16[i] = (uint16_t)sample(&r, 65535u);
        g_b16[i] = (uint16_t)sample(&r, 65535u);
    }
    for (oa = 0; oa < MAX_OFF; oa++) {
        for (ob = 0; ob < MAX_OFF; ob++) {
            for (n = 0; n <= MAX_LEN; n++) {
                const uint16_t *a = g_a16 + oa, *b = g_b16 + ob;
                uint64_t want = ref_u16(a, b, n);
                TEST_ASSERT_EQUAL_UINT64(want, ssda__portable_sad_row_u16(a, b, n));
                check_sad_row_u16(want, a, b, n);
            }
        }
    }
}

static void test_absdiff_i16_random_every_length_and_alignment(void)
{
    test_rng_t r;
    uint32_t i, oa, ob, n;
    test_rng_seed(&r, 0xA3DF16u);
    for (i = 0; i < MAX_LEN + MAX_OFF; i++) {
        g_ai16[i] = (int16_t)((int32_t)sample(&r, 65535u) - 32768);
        g_bi16[i] = (int16_t)((int32_t)sample(&r, 65535u) - 32768);
    }
    for (oa = 0; oa < MAX_OFF; oa++) {
        for (ob = 0; ob < MAX_OFF; ob++) {
            for (n = 0; n <= MAX_LEN; n++) {
                const int16_t *a = g_ai16 + oa, *b = g_bi16 + ob;
                uint64_t want = ref_i16(a, b, n);
                TEST_ASSERT_EQUAL_UINT64(want, ssda__portable_absdiff_row_i16(a, b, n));
                check_absdiff_row_i16(want, a, b, n);
            }
        }
    }
}

/* Within each pair of lanes, a - b is +max in one and -max in the other,
   in both arrangements: a wrong lane select or sign test shows at once. */
static void test_lanes_of_opposite_sign(void)
{
    uint32_t i, n;
    for (i = 0; i < MAX_LEN; i++) {
        uint32_t hi = ((i >> 1) & 1u) ^ (i & 1u); /* 0 1 1 0 0 1 1 0 ... */
        g_a8[i] = hi ? 255u : 0u;
        g_b8[i] = hi ? 0u : 255u;
        g_a16[i] = hi ? 65535u : 0u;
        g_b16[i] = hi ? 0u : 65535u;
        g_ai16[i] = hi ? INT16_MAX : INT16_MIN;
        g_bi16[i] = hi ? INT16_MIN : INT16_MAX;
    }
    for (n = 0; n <= MAX_LEN; n++) {
        check_sad_row_u8(255u * n, g_a8, g_b8, n);
        check_sad_row_u16(65535u * n, g_a16, g_b16, n);
        check_absdiff_row_i16(65535u * n, g_ai16, g_bi16, n);
        /* One lane equal, the other maximal. */
        check_sad_row_u16((uint32_t)ref_u16(g_a16, g_a16 + 1, n), g_a16, g_a16 + 1, n);
        check_absdiff_row_i16((uint32_t)ref_i16(g_ai16, g_ai16 + 1, n), g_ai16, g_ai16 + 1, n);
    }
}

/* Fill g_big's two rows: first row all x, second all y (16-bit lanes). */
static void fill_big(uint16_t x, uint16_t y)
{
    uint32_t i;
    for (i = 0; i <= N_MAX; i++) {
        g_big[i] = x;
        g_big[N_MAX + 1u + i] = y;
    }
}

/* 65535 differences of 255: 16 711 425, the 8-bit row's worst case; aligned
   and misaligned, both signs. */
static void test_sad_u8_worst_case(void)
{
    const uint32_t want = 255u * N_MAX;
    const uint8_t *bytes = (const uint8_t *)g_big;
    uint32_t off;
    fill_big(0xFFFFu, 0x0000u); /* bytes: 2 * 65536 of 255, then of 0 */
    for (off = 0; off < 4u; off++) {
        const uint8_t *hi = bytes + off, *lo = bytes + 2u * (N_MAX + 1u) + off;
        TEST_ASSERT_EQUAL_UINT32(want, ssda__portable_sad_row_u8(hi, lo, N_MAX));
        check_sad_row_u8(want, hi, lo, N_MAX);
        check_sad_row_u8(want, lo, hi, N_MAX);
    }
}

/* 65535 differences of 65535: 4 294 836 225 = 2^32 - 131071, the u16 row's
   worst case (above 2^31: no signed 32-bit lane may hold it). */
static void test_sad_u16_worst_case(void)
{
    const uint32_t want = 65535u * N_MAX;
    uint32_t off;
    fill_big(65535u, 0u);
    for (off = 0; off < 2u; off++) {
        const uint16_t *hi = g_big + off, *lo = g_big + N_MAX + 1u + off;
        TEST_ASSERT_EQUAL_UINT64((uint64_t)65535u * 65535u, want);
        TEST_ASSERT_EQUAL_UINT32(want, ssda__portable_sad_row_u16(hi, lo, N_MAX));
        check_sad_row_u16(want, hi, lo, N_MAX);
        check_sad_row_u16(want, lo, hi, N_MAX);
    }
}

/* 65535 differences of 32767 - (-32768) = 65535: the AMDF worst case. */
static void test_absdiff_i16_worst_case(void)
{
    const uint32_t want = 65535u * N_MAX;
    /* int16_t and uint16_t may alias: 0x7FFF is INT16_MAX, 0x8000 INT16_MIN. */
    const int16_t *rows = (const int16_t *)(const void *)g_big;
    uint32_t off;
    fill_big(0x7FFFu, 0x8000u);
    TEST_ASSERT_EQUAL_INT16(INT16_MAX, rows[0]);
    TEST_ASSERT_EQUAL_INT16(INT16_MIN, rows[N_MAX + 1u]);
    for (off = 0; off < 2u; off++) {
        const int16_t *hi = rows + off, *lo = rows + N_MAX + 1u + off;
        TEST_ASSERT_EQUAL_UINT32(want, ssda__portable_absdiff_row_i16(hi, lo, N_MAX));
        check_absdiff_row_i16(want, hi, lo, N_MAX);
        check_absdiff_row_i16(want, lo, hi, N_MAX);
    }
}

/* Long random rows at the maximum length, against the 64-bit reference. */
static void test_long_random_rows(void)
{
    const uint8_t *bytes = (const uint8_t *)g_big;
    const int16_t *rows = (const int16_t *)(const void *)g_big;
    test_rng_t r;
    uint32_t i;
    test_rng_seed(&r, 0x10C0u);
    for (i = 0; i < 2u * (N_MAX + 1u); i++) {
        g_big[i] = (uint16_t)sample(&r, 65535u);
    }
    check_sad_row_u8(ref_u8(bytes + 1, bytes + 70001u, N_MAX), bytes + 1, bytes + 70001u, N_MAX);
    check_sad_row_u16(ref_u16(g_big + 1, g_big + N_MAX + 1u, N_MAX), g_big + 1, g_big + N_MAX + 1u, N_MAX);
    check_absdiff_row_i16(ref_i16(rows, rows + N_MAX + 2u, N_MAX), rows, rows + N_MAX + 2u, N_MAX);
}

/* Products (correlation kernels): sum over rows of sum a[i] b[i], 64-bit. */
static uint64_t ref_dot(const void *a, size_t as, const void *b, size_t bs, uint32_t n,
                        uint32_t rows, int u16)
{
    uint64_t s = 0;
    uint32_t r, i;
    for (r = 0; r < rows; r++) {
        for (i = 0; i < n; i++) {
            if (u16) {
                s += (uint64_t)((const uint16_t *)(const void *)((const uint8_t *)a + r * as))[i] *
                     ((const uint16_t *)(const void *)((const uint8_t *)b + r * bs))[i];
            } else {
                s += (uint64_t)((const uint8_t *)a + r * as)[i] * ((const uint8_t *)b + r * bs)[i];
            }
        }
    }
    return s;
}

static void test_dot_random_every_length_alignment_and_rows(void)
{
    const uint8_t *bytes = (const uint8_t *)g_big;
    test_rng_t r;
    uint32_t i, oa, ob, n, rows;
    test_rng_seed(&r, 0xD07u);
    for (i = 0; i < 2u * (N_MAX + 1u); i++) {
        g_big[i] = (uint16_t)sample(&r, 65535u);
    }
    for (oa = 0; oa < MAX_OFF; oa++) {
        for (ob = 0; ob < MAX_OFF; ob += 3u) {
            for (n = 0; n <= MAX_LEN; n++) {
                for (rows = 1; rows <= 3u; rows += 2u) {
                    const uint8_t *a8 = bytes + oa, *b8 = bytes + 1000u + ob;
                    const uint16_t *a16 = g_big + 3000u + oa, *b16 = g_big + 9000u + ob;
                    TEST_ASSERT_EQUAL_UINT64_MESSAGE(ref_dot(a8, 233, b8, 301, n, rows, 0),
                                                     ssda__dot_u8(a8, 233, b8, 301, n, rows),
                                                     ssda__kernel_name());
                    TEST_ASSERT_EQUAL_UINT64_MESSAGE(ref_dot(a16, 466, b16, 602, n, rows, 1),
                                                     ssda__dot_u16(a16, 466, b16, 602, n, rows),
                                                     ssda__kernel_name());
                }
            }
        }
    }
}

/* 65536 products of 255 * 255 (4 261 478 400, just under 2^32) and of
   65535 * 65535 (just under 2^48), in the shapes 32768 x 2 and 65535 x 1. */
static void test_dot_worst_case(void)
{
    const uint8_t *bytes = (const uint8_t *)g_big;
    fill_big(0xFFFFu, 0xFFFFu);
    TEST_ASSERT_EQUAL_UINT32(65536u * 65025u, ssda__dot_u8(bytes, 32768, bytes + 65536u, 32768, 32768, 2));
    TEST_ASSERT_EQUAL_UINT32(65535u * 65025u, ssda__dot_u8(bytes + 1, 0, bytes + 3, 0, 65535, 1));
    TEST_ASSERT_EQUAL_UINT64(65536ull * 65535u * 65535u,
                             ssda__dot_u16(g_big, 65536, g_big + 1, 65536, 32768, 2));
    TEST_ASSERT_EQUAL_UINT64(65535ull * 65535u * 65535u,
                             ssda__dot_u16(g_big + 1, 0, g_big, 0, 65535, 1));
}

/* The rows loops (ssda__sad_rows_u8/u16) against the reference row by
   row: rows of n pixels at byte strides through one buffer (rows overlap,
   as the rows of an image's areas do), stopping after the first row whose
   running sum reaches the limit; every variant. */
#define ROWS_MAX 6u
static uint8_t g_rows8[MAX_LEN * ROWS_MAX * 2u + 64u];
static uint16_t g_rows16[MAX_LEN * ROWS_MAX * 2u + 64u];

static void check_rows(bool u16, const void *a, size_t as, const void *b, size_t bs, uint32_t n,
                       uint32_t rows, uint32_t limit, uint32_t start)
{
    const ssda__kernel_variant_t *k;
    uint32_t want = start, want_rows = 0u, got = start, got_rows, v;
    do { /* the reference: rows one by one */
        const uint8_t *pa = (const uint8_t *)a + want_rows * as;
        const uint8_t *pb = (const uint8_t *)b + want_rows * bs;
        want += (uint32_t)(u16 ? ref_u16((const uint16_t *)(const void *)pa,
                                         (const uint16_t *)(const void *)pb, n)
                               : ref_u8(pa, pb, n));
        want_rows++;
    } while (want_rows < rows && want < limit);
    got_rows = u16 ? ssda__sad_rows_u16(a, as, b, bs, n, rows, limit, &got)
                   : ssda__sad_rows_u8(a, as, b, bs, n, rows, limit, &got);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_rows, got_rows, ssda__kernel_name());
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, ssda__kernel_name());
    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
        got = start;
        got_rows = u16 ? k->sad_rows_u16(a, as, b, bs, n, rows, limit, &got)
                       : k->sad_rows_u8(a, as, b, bs, n, rows, limit, &got);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_rows, got_rows, k->name);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, k->name);
    }
}

static void test_sad_rows_random(void)
{
    test_rng_t r;
    uint32_t i, n, rows, t;
    test_rng_seed(&r, 0x5AD5u);
    for (i = 0; i < sizeof g_rows8; i++) {
        g_rows8[i] = (uint8_t)sample(&r, 255u);
    }
    for (i = 0; i < sizeof g_rows16 / sizeof g_rows16[0]; i++) {
        g_rows16[i] = (uint16_t)sample(&r, 65535u);
    }
    for (n = 0u; n <= MAX_LEN; n += (n < 40u ? 1u : 13u)) {
        for (rows = 1u; rows <= ROWS_MAX; rows++) {
            for (t = 0u; t < 6u; t++) {
                /* strides of n or more pixels, odd offsets: unaligned rows */
                const uint32_t oa = test_rng_range(&r, 0u, 7u), ob = test_rng_range(&r, 0u, 7u);
                const uint32_t sa = n + test_rng_range(&r, 0u, 5u);
                const uint32_t sb = n + test_rng_range(&r, 0u, 5u);
                const uint32_t start = t == 0u ? 0u : test_rng_range(&r, 0u, 100000u);
                /* limits: reached at once, never, or somewhere in between */
                const uint32_t limit = t == 1u ? 0u
                                       : t == 2u ? UINT32_MAX
                                                 : start + test_rng_range(&r, 0u, n * rows * 200u);
                check_rows(false, g_rows8 + oa, sa, g_rows8 + MAX_LEN * ROWS_MAX + ob, sb, n,
                           rows, limit, start);
                check_rows(true, g_rows16 + oa, 2u * sa, g_rows16 + MAX_LEN * ROWS_MAX + ob,
                           2u * sb, n, rows, limit > UINT32_MAX / 256u ? limit : limit * 200u,
                           start);
            }
        }
    }
}

/* The largest sums the callers allow: 65536 pixels of the largest
   difference, 4096 rows of 16 (stride 0: one row read again). */
static void test_sad_rows_worst_case(void)
{
    uint32_t i;
    for (i = 0; i < 16u; i++) {
        g_rows16[i] = 65535u;
        g_rows16[16u + i] = 0u;
        g_rows8[i] = 255u;
        g_rows8[16u + i] = 0u;
    }
    check_rows(true, g_rows16, 0u, g_rows16 + 16, 0u, 16u, 4096u, UINT32_MAX, 0u);
    check_rows(true, g_rows16 + 16, 0u, g_rows16, 0u, 16u, 4096u, 4294901760u, 0u);
    check_rows(false, g_rows8, 0u, g_rows8 + 16, 0u, 16u, 65535u, UINT32_MAX, 0u);
}

/* ssda__refine4 against kernels.h's definition summed in 64 bits, and
   every variant against the reference, on random sums in the stated ranges
   (block sums < 2^20, group sums < 2^31, rest and every step of it below
   2^32), strides and cut levels that stop it after each group. */
static uint32_t g_tab_b[4u * 64u + 16u], g_tab_g[4u * 64u + 16u];

/* kernels.h's ssda__refine4, written from its comment: 64-bit sums. */
static uint32_t refine4_definition(const uint32_t *b, const uint32_t *g, size_t down,
                                   const uint32_t *wgrp, const uint32_t *wblk, uint32_t rest,
                                   uint32_t cut, uint32_t *term_out, uint32_t *groups)
{
    int64_t r = rest;
    uint32_t k, j;
    for (k = 0u; k < 4u; k++) {
        int64_t s = 0, term = (int64_t)g[k * down] - (int64_t)wgrp[k];
        for (j = 0u; j < 4u; j++) {
            const int64_t d = (int64_t)b[k * down + 4u * j] - (int64_t)wblk[4u * k + j];
            s += d < 0 ? -d : d;
        }
        r = r - (term < 0 ? -term : term) + s;
        TEST_ASSERT_TRUE(r >= 0 && r <= (int64_t)UINT32_MAX); /* the contract's range */
        term_out[k] = (uint32_t)s;
        if (r >= (int64_t)cut) {
            break;
        }
    }
    *groups = k < 4u ? k + 1u : 4u;
    return (uint32_t)r;
}

static void check_refine4(const uint32_t *b, const uint32_t *g, size_t down,
                          const uint32_t *wgrp, const uint32_t *wblk, uint32_t rest, uint32_t cut)
{
    const ssda__kernel_variant_t *k;
    uint32_t want_t[4] = {0u, 0u, 0u, 0u}, got_t[4] = {0u, 0u, 0u, 0u};
    uint32_t want_n = 0u, got_n = 0u, v, i;
    const uint32_t want = refine4_definition(b, g, down, wgrp, wblk, rest, cut, want_t, &want_n);
    uint32_t got = ssda__portable_refine4(b, g, down, wgrp, wblk, rest, cut, got_t, &got_n);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, "reference");
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_n, got_n, "reference");
    for (i = 0u; i < want_n; i++) {
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_t[i], got_t[i], "reference");
    }
    got = ssda__refine4(b, g, down, wgrp, wblk, rest, cut, got_t, &got_n);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, ssda__kernel_name());
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_n, got_n, ssda__kernel_name());
    TEST_ASSERT_TRUE(want_n >= 1u && want_n <= 4u);
    for (i = 0u; i < want_n; i++) {
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_t[i], got_t[i], ssda__kernel_name());
    }
    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
        got_n = 0u;
        got = k->refine4(b, g, down, wgrp, wblk, rest, cut, got_t, &got_n);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, k->name);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_n, got_n, k->name);
        for (i = 0u; i < want_n; i++) {
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_t[i], got_t[i], k->name);
        }
    }
}

static void test_refine4_random(void)
{
    test_rng_t r;
    uint32_t i, t, wgrp[4], wblk[16];
    test_rng_seed(&r, 0x4EF14Eu);
    for (t = 0u; t < 2000u; t++) {
        const uint32_t bmax = t % 3u == 0u ? (1u << 20) - 1u : 4095u * 16u;
        const uint32_t gmax = t % 3u == 0u ? 0x7FFFFFFFu : 4095u * 64u;
        const size_t down = 16u + test_rng_range(&r, 0u, 48u); /* a row pitch */
        const uint32_t at = test_rng_range(&r, 0u, 15u);
        uint32_t rest, cut;
        for (i = 0u; i < sizeof g_tab_b / sizeof g_tab_b[0]; i++) {
            g_tab_b[i] = test_rng_range(&r, 0u, bmax);
            g_tab_g[i] = test_rng_range(&r, 0u, gmax);
        }
        for (i = 0u; i < 4u; i++) { /* terms below 2^29: rest below 2^31 */
            const uint32_t gi = g_tab_g[at + i * down];
            const uint32_t d = test_rng_range(&r, 0u, gmax < (1u << 29) ? gmax : (1u << 29) - 1u);
            wgrp[i] = test_rng_range(&r, 0u, 1u) != 0u ? (gi > d ? gi - d : 0u)
                                                      : (gmax - gi > d ? gi + d : gmax);
        }
        for (i = 0u; i < 16u; i++) {
            wblk[i] = test_rng_range(&r, 0u, bmax);
        }
        /* rest: the sum of the group terms, as the engine passes it */
        rest = 0u;
        for (i = 0u; i < 4u; i++) {
            const uint32_t a = g_tab_g[at + i * down];
            rest += a > wgrp[i] ? a - wgrp[i] : wgrp[i] - a;
        }
        cut = t % 4u == 0u ? UINT32_MAX : rest + test_rng_range(&r, 0u, 4u * bmax);
        check_refine4(g_tab_b + at, g_tab_g + at, down, wgrp, wblk, rest, cut);
    }
}

/* ssda__bounds4 against its reference: random sums below 2^31 (bounds
   below 2^32), every row length 0..70 and a few strides; every variant. */
static uint32_t g_bnd_g[4u * 96u + 80u], g_bnd_want[80], g_bnd_got[80];

static void test_bounds4_random(void)
{
    test_rng_t r;
    uint32_t i, n, t, w[4];
    const ssda__kernel_variant_t *k;
    test_rng_seed(&r, 0xB0D4u);
    for (t = 0u; t < 40u; t++) {
        const uint32_t gmax = t % 2u == 0u ? 0x3FFFFFFFu : 4095u * 64u; /* 4 terms < 2^32 */
        const size_t down = 80u + test_rng_range(&r, 0u, 16u);
        for (i = 0u; i < sizeof g_bnd_g / sizeof g_bnd_g[0]; i++) {
            g_bnd_g[i] = test_rng_range(&r, 0u, gmax);
        }
        for (i = 0u; i < 4u; i++) {
            w[i] = test_rng_range(&r, 0u, gmax);
        }
        for (n = 0u; n <= 70u; n++) {
            const uint32_t at = test_rng_range(&r, 0u, 9u);
            ssda__portable_bounds4(g_bnd_want, g_bnd_g + at, down, w, n);
            for (i = 0u; i < n; i++) { /* the reference against the definition */
                uint64_t want = 0u;
                uint32_t q;
                for (q = 0u; q < 4u; q++) {
                    const uint32_t a = g_bnd_g[at + i + q * down];
                    want += a > w[q] ? a - w[q] : w[q] - a;
                }
                TEST_ASSERT_EQUAL_UINT64(want, g_bnd_want[i]);
            }
            g_bnd_got[n] = 0xDEADu; /* nothing past n written */
            ssda__bounds4(g_bnd_got, g_bnd_g + at, down, w, n);
            TEST_ASSERT_EQUAL_UINT32(0xDEADu, g_bnd_got[n]);
            if (n == 0u) {
                continue; /* nothing written: checked above */
            }
            TEST_ASSERT_EQUAL_UINT32_ARRAY(g_bnd_want, g_bnd_got, n);
            for (i = 0u; (k = ssda__kernel_variant(i)) != NULL; i++) {
                (void)memset(g_bnd_got, 0, sizeof g_bnd_got);
                k->bounds4(g_bnd_got, g_bnd_g + at, down, w, n);
                TEST_ASSERT_EQUAL_UINT32_ARRAY_MESSAGE(g_bnd_want, g_bnd_got, n, k->name);
            }
        }
    }
}

/* ssda__tab_row against its definition (window sums of v in 64 bits,
   modulo 2^32) and the reference, and every variant against the
   reference entry for entry (the prefix sums it leaves past the L x 4
   sums included): row lengths 1..80 (vector steps and tails), every L up
   to 20 and the whole row, with and without b, b apart or overlaying
   p[vlen] (the tables' one-slot layout), small sums and sums that wrap. */
#define TR_MAX 80u
static uint32_t g_tr_v[TR_MAX], g_tr_want[3u * TR_MAX + 8u], g_tr_got[3u * TR_MAX + 8u];

static void run_tab_row(void (*f)(uint32_t *, uint32_t *, const uint32_t *, uint32_t, uint32_t),
                        uint32_t *buf, uint32_t vlen, uint32_t L, uint32_t layout)
{
    /* layout 0: no b; 1: b after a gap; 2: b at p + vlen */
    uint32_t *b = layout == 0u ? NULL : buf + vlen + (layout == 1u ? 3u : 0u);
    (void)memset(buf, 0x5C, (3u * TR_MAX + 8u) * sizeof(uint32_t));
    f(buf, b, g_tr_v, vlen, L);
}

static void portable_tab_row(uint32_t *p, uint32_t *b, const uint32_t *v, uint32_t vlen,
                             uint32_t L)
{
    ssda__portable_tab_row(p, b, v, vlen, L);
}

static void test_tab_row_random(void)
{
    const ssda__kernel_variant_t *k;
    test_rng_t r;
    uint32_t vlen, L, layout, t, i, v;
    test_rng_seed(&r, 0x7AB5u);
    for (t = 0u; t < 2u; t++) {
        for (i = 0u; i < TR_MAX; i++) { /* vertical sums (< 2^18), or any word */
            g_tr_v[i] = t == 0u ? test_rng_range(&r, 0u, 4u * 65535u) : test_rng_next(&r);
        }
        for (vlen = 1u; vlen <= TR_MAX; vlen++) {
            for (L = 1u; L <= vlen; L = L < 20u ? L + 1u : (L < vlen ? vlen : L + 1u)) {
                for (layout = 0u; layout < 3u; layout++) {
                    uint32_t *b;
                    if (layout != 0u && vlen < 4u) {
                        continue;
                    }
                    run_tab_row(portable_tab_row, g_tr_want, vlen, L, layout);
                    b = layout == 0u ? NULL : g_tr_want + vlen + (layout == 1u ? 3u : 0u);
                    for (i = 0u; i + L <= vlen; i++) { /* the definition */
                        uint64_t w = 0u;
                        uint32_t j;
                        for (j = 0u; j < L; j++) {
                            w += g_tr_v[i + j];
                        }
                        TEST_ASSERT_EQUAL_UINT32((uint32_t)w, g_tr_want[i]);
                    }
                    for (i = 0u; b != NULL && i + 4u <= vlen; i++) {
                        const uint64_t w = (uint64_t)g_tr_v[i] + g_tr_v[i + 1u] +
                                           g_tr_v[i + 2u] + g_tr_v[i + 3u];
                        TEST_ASSERT_EQUAL_UINT32((uint32_t)w, b[i]);
                    }
                    run_tab_row(ssda__tab_row, g_tr_got, vlen, L, layout);
                    TEST_ASSERT_EQUAL_UINT32_ARRAY(g_tr_want, g_tr_got, 3u * TR_MAX + 8u);
                    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
                        run_tab_row(k->tab_row, g_tr_got, vlen, L, layout);
                        TEST_ASSERT_EQUAL_UINT32_ARRAY_MESSAGE(g_tr_want, g_tr_got,
                                                               3u * TR_MAX + 8u, k->name);
                    }
                }
            }
        }
    }
}

/* ssda__vslide against its definition (v + add - sub in 64 bits, modulo
   2^32) and the reference, every variant against the reference: 8 and
   16-bit rows of every length 0..40 at odd offsets, vertical sums that
   stay in range and ones that wrap; nothing past n written. */
static uint32_t g_vs_v[48], g_vs_want[48], g_vs_got[48];
static uint16_t g_vs_16[2u * 48u + 8u];

static void test_vslide_random(void)
{
    const ssda__kernel_variant_t *k;
    test_rng_t r;
    uint32_t n, t, i, v, u8;
    test_rng_seed(&r, 0x5713u);
    for (t = 0u; t < 8u; t++) {
        for (i = 0u; i < sizeof g_vs_16 / sizeof g_vs_16[0]; i++) {
            g_vs_16[i] = (uint16_t)test_rng_range(&r, 0u, 65535u);
        }
        for (i = 0u; i < 48u; i++) {
            g_vs_v[i] = t % 2u == 0u ? test_rng_range(&r, 0u, 4u * 65535u) : test_rng_next(&r);
        }
        for (u8 = 0u; u8 < 2u; u8++) {
            for (n = 0u; n <= 40u; n++) {
                const uint32_t oa = test_rng_range(&r, 0u, 3u), ob = test_rng_range(&r, 0u, 3u);
                /* rows of n samples: 16-bit at 2-byte offsets, 8-bit at odd ones */
                const uint8_t *add = u8 != 0u ? (const uint8_t *)g_vs_16 + 1u + oa
                                              : (const uint8_t *)(g_vs_16 + oa);
                const uint8_t *sub = u8 != 0u ? (const uint8_t *)(g_vs_16 + 48u) + 1u + ob
                                              : (const uint8_t *)(g_vs_16 + 48u + ob);
                for (i = 0u; i < 48u; i++) {
                    uint64_t a = 0u, b = 0u;
                    if (i < n) {
                        a = u8 != 0u ? add[i] : ((const uint16_t *)(const void *)add)[i];
                        b = u8 != 0u ? sub[i] : ((const uint16_t *)(const void *)sub)[i];
                    }
                    g_vs_want[i] = (uint32_t)((uint64_t)g_vs_v[i] + a + (1ull << 32) - b);
                }
                (void)memcpy(g_vs_got, g_vs_v, sizeof g_vs_got);
                ssda__portable_vslide(g_vs_got, add, sub, n, u8 != 0u);
                TEST_ASSERT_EQUAL_UINT32_ARRAY(g_vs_want, g_vs_got, 48u);
                (void)memcpy(g_vs_got, g_vs_v, sizeof g_vs_got);
                ssda__vslide(g_vs_got, add, sub, n, u8 != 0u);
                TEST_ASSERT_EQUAL_UINT32_ARRAY(g_vs_want, g_vs_got, 48u);
                for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
                    (void)memcpy(g_vs_got, g_vs_v, sizeof g_vs_got);
                    k->vslide(g_vs_got, add, sub, n, u8 != 0u);
                    TEST_ASSERT_EQUAL_UINT32_ARRAY_MESSAGE(g_vs_want, g_vs_got, 48u, k->name);
                }
            }
        }
    }
}

/* ssda__blocks16 against block sums from the definition (each pixel added
   to its block, 64 bits) and the reference, every variant: 8 and 16-bit
   windows at odd offsets and strides, random and all-maximum pixels (the
   largest sums: 16 * 65535 a block). */
static uint16_t g_bl16[16u * 24u + 8u];

static void test_blocks16_random(void)
{
    const ssda__kernel_variant_t *k;
    test_rng_t r;
    uint32_t t, i, v, u8;
    test_rng_seed(&r, 0xB16u);
    for (t = 0u; t < 40u; t++) {
        for (i = 0u; i < sizeof g_bl16 / sizeof g_bl16[0]; i++) {
            g_bl16[i] = t == 0u ? 65535u : (uint16_t)test_rng_range(&r, 0u, 65535u);
        }
        for (u8 = 0u; u8 < 2u; u8++) {
            /* 16 rows of 16 samples, strides of 16 to 23 samples (bytes when u8) */
            const size_t stride = (16u + test_rng_range(&r, 0u, 7u)) * (u8 != 0u ? 1u : 2u);
            const uint8_t *w = u8 != 0u ? (const uint8_t *)g_bl16 + test_rng_range(&r, 0u, 7u)
                                        : (const uint8_t *)(g_bl16 + test_rng_range(&r, 0u, 7u));
            uint64_t want_b[16] = {0u}, want_g[4] = {0u};
            uint32_t wb[16], wg[4], gb[16], gg[4], row, col;
            for (row = 0u; row < 16u; row++) {
                for (col = 0u; col < 16u; col++) {
                    const uint8_t *p = w + row * stride;
                    const uint64_t px = u8 != 0u ? p[col] : ((const uint16_t *)(const void *)p)[col];
                    want_b[4u * (row / 4u) + col / 4u] += px;
                    want_g[row / 4u] += px;
                }
            }
            ssda__portable_blocks16(w, stride, u8 != 0u, wb, wg);
            for (i = 0u; i < 16u; i++) {
                TEST_ASSERT_EQUAL_UINT64(want_b[i], wb[i]);
            }
            for (i = 0u; i < 4u; i++) {
                TEST_ASSERT_EQUAL_UINT64(want_g[i], wg[i]);
            }
            ssda__blocks16(w, stride, u8 != 0u, gb, gg);
            TEST_ASSERT_EQUAL_UINT32_ARRAY(wb, gb, 16u);
            TEST_ASSERT_EQUAL_UINT32_ARRAY(wg, gg, 4u);
            for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
                (void)memset(gb, 0, sizeof gb);
                (void)memset(gg, 0, sizeof gg);
                k->blocks16(w, stride, u8 != 0u, gb, gg);
                TEST_ASSERT_EQUAL_UINT32_ARRAY_MESSAGE(wb, gb, 16u, k->name);
                TEST_ASSERT_EQUAL_UINT32_ARRAY_MESSAGE(wg, gg, 4u, k->name);
            }
        }
    }
}

/* ssda__any_u16 against a search sample by sample: every width 0..40 and
   1..5 rows at odd strides, the value absent, or planted once at every
   position in turn (each lane of a vector step and of the tail). */
static uint16_t g_any[5u * 48u + 8u];

static void check_any(const uint8_t *p, size_t stride, uint32_t n, uint32_t rows, uint16_t t)
{
    const ssda__kernel_variant_t *k;
    uint32_t want = 0u, r, i, v;
    for (r = 0u; r < rows; r++) {
        for (i = 0u; i < n; i++) {
            want |= ((const uint16_t *)(const void *)(p + r * stride))[i] == t ? 1u : 0u;
        }
    }
    TEST_ASSERT_EQUAL_UINT32(want, ssda__portable_any_u16(p, stride, n, rows, t));
    TEST_ASSERT_EQUAL_UINT32(want, ssda__any_u16(p, stride, n, rows, t));
    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, k->any_u16(p, stride, n, rows, t), k->name);
    }
}

static void test_any_u16_every_position(void)
{
    test_rng_t r;
    uint32_t n, rows, i, pos;
    test_rng_seed(&r, 0xA11u);
    for (n = 0u; n <= 40u; n++) {
        for (rows = 1u; rows <= 5u; rows++) {
            const size_t stride = 2u * (n + test_rng_range(&r, 0u, 7u));
            const uint8_t *p = (const uint8_t *)(g_any + test_rng_range(&r, 0u, 7u));
            for (i = 0u; i < sizeof g_any / sizeof g_any[0]; i++) {
                g_any[i] = (uint16_t)test_rng_range(&r, 1u, 65535u); /* never 0 */
            }
            check_any(p, stride, n, rows, 0u);
            for (pos = 0u; pos < n * rows; pos++) { /* 0 planted at each sample */
                uint16_t *q = (uint16_t *)(void *)(g_any + ((size_t)(p - (const uint8_t *)g_any) +
                                                            (pos / n) * stride) / 2u) + pos % n;
                const uint16_t keep = *q;
                *q = 0u;
                check_any(p, stride, n, rows, 0u);
                *q = keep;
            }
        }
    }
}

/* ssda__bounds4_open against its definition (64-bit sums, the mask from
   them), the reference and every variant: every row length 1..32 (the
   vector steps, the overlapping last step, the scalar rows), 1..5 rows,
   strides between rows and groups, thresholds at, above and below
   bounds of the area; nothing past each row's nx entries written. */
#define BO_ROWS 5u
static uint32_t g_bo_g[BO_ROWS * 40u + 4u * 200u + 64u];
static uint32_t g_bo_want[BO_ROWS * 33u], g_bo_got[BO_ROWS * 33u + 1u];

static void test_bounds4_open_random(void)
{
    const ssda__kernel_variant_t *k;
    test_rng_t r;
    uint32_t i, nx, rows, t, v;
    uint32_t w[4], want_m[BO_ROWS], got_m[BO_ROWS];
    test_rng_seed(&r, 0xB40u);
    for (t = 0u; t < 3u; t++) {
        const uint32_t gmax = t == 0u ? 0x3FFFFFFFu : 4095u * 64u; /* 4 terms < 2^32 */
        for (i = 0u; i < sizeof g_bo_g / sizeof g_bo_g[0]; i++) {
            g_bo_g[i] = test_rng_range(&r, 0u, gmax);
        }
        for (i = 0u; i < 4u; i++) {
            w[i] = test_rng_range(&r, 0u, gmax);
        }
        for (nx = 1u; nx <= 32u; nx++) {
            for (rows = 1u; rows <= BO_ROWS; rows++) {
                const size_t gstride = nx + test_rng_range(&r, 0u, 7u);
                const size_t down = BO_ROWS * 40u + test_rng_range(&r, 0u, 9u);
                const uint32_t *g = g_bo_g + test_rng_range(&r, 0u, 3u);
                uint32_t s, x, y;
                for (y = 0u; y < rows; y++) { /* the definition */
                    for (x = 0u; x < nx; x++) {
                        uint64_t b = 0u;
                        uint32_t q;
                        for (q = 0u; q < 4u; q++) {
                            const uint32_t a = g[y * gstride + x + q * down];
                            b += a > w[q] ? a - w[q] : w[q] - a;
                        }
                        TEST_ASSERT_TRUE(b <= UINT32_MAX);
                        g_bo_want[y * nx + x] = (uint32_t)b;
                    }
                }
                /* s: one of the bounds (equal ones set their bit), 0, or all */
                s = t == 2u ? UINT32_MAX
                            : g_bo_want[test_rng_range(&r, 0u, rows * nx - 1u)] -
                                  test_rng_range(&r, 0u, 1u);
                for (y = 0u; y < rows; y++) {
                    want_m[y] = 0u;
                    for (x = 0u; x < nx; x++) {
                        want_m[y] |= (g_bo_want[y * nx + x] <= s ? 1u : 0u) << x;
                    }
                }
                (void)memset(g_bo_got, 0xA5, sizeof g_bo_got);
                ssda__portable_bounds4_open(g_bo_got, g, gstride, down, w, nx, rows, s, got_m);
                TEST_ASSERT_EQUAL_UINT32_ARRAY(g_bo_want, g_bo_got, rows * nx);
                TEST_ASSERT_EQUAL_UINT32_ARRAY(want_m, got_m, rows);
                (void)memset(g_bo_got, 0xA5, sizeof g_bo_got);
                ssda__bounds4_open(g_bo_got, g, gstride, down, w, nx, rows, s, got_m);
                TEST_ASSERT_EQUAL_UINT32_ARRAY(g_bo_want, g_bo_got, rows * nx);
                TEST_ASSERT_EQUAL_UINT32_ARRAY(want_m, got_m, rows);
                TEST_ASSERT_EQUAL_UINT32(0xA5A5A5A5u, g_bo_got[rows * nx]);
                for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
                    (void)memset(g_bo_got, 0xA5, sizeof g_bo_got);
                    k->bounds4_open(g_bo_got, g, gstride, down, w, nx, rows, s, got_m);
                    TEST_ASSERT_EQUAL_UINT32_ARRAY_MESSAGE(g_bo_want, g_bo_got, rows * nx,
                                                           k->name);
                    TEST_ASSERT_EQUAL_UINT32_ARRAY_MESSAGE(want_m, got_m, rows, k->name);
                    TEST_ASSERT_EQUAL_UINT32_MESSAGE(0xA5A5A5A5u, g_bo_got[rows * nx], k->name);
                }
            }
        }
    }
}

/* ssda__sad16_rows_u16 against kernels.h's definition (64-bit sums, a row
   at a time from ref_u16), the reference and every variant: rows 1 .. 24
   (steps of 8 and their remainders, the groups of 4 and the rows after
   16), unaligned rows at random strides, limits that stop it at the first
   8 pixels, at each row, or never. */
#define S16_ROWS 24u
static uint16_t g_s16[S16_ROWS * 40u + 64u];

static uint32_t sad16_rows_definition(const uint16_t *a, size_t as, const uint16_t *b,
                                      size_t bs, uint32_t rows, const uint32_t *limit,
                                      uint32_t *sum)
{
    uint64_t s = ref_u16(a, b, 8u);
    uint32_t r;
    if (s >= limit[0]) {
        *sum = (uint32_t)s;
        return 8u;
    }
    for (r = 0u; r < rows; r++) {
        if (r > 0u) {
            s += ref_u16(a + r * (as / 2u), b + r * (bs / 2u), 8u);
        }
        s += ref_u16(a + r * (as / 2u) + 8u, b + r * (bs / 2u) + 8u, 8u);
        TEST_ASSERT_TRUE(s <= UINT32_MAX); /* the contract */
        if (s >= limit[r < 16u ? r / 4u : 4u]) {
            break;
        }
    }
    *sum = (uint32_t)s;
    return 16u * (r < rows ? r + 1u : rows);
}

static void check_sad16_rows(const uint16_t *a, size_t as, const uint16_t *b, size_t bs,
                             uint32_t rows, const uint32_t *limit)
{
    const ssda__kernel_variant_t *k;
    uint32_t want_sum = 0u, got_sum = 0u, v;
    const uint32_t want = sad16_rows_definition(a, as, b, bs, rows, limit, &want_sum);
    uint32_t got = ssda__portable_sad16_rows_u16(a, as, b, bs, rows, limit, &got_sum);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, "reference");
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_sum, got_sum, "reference");
    got_sum = 0u;
    got = ssda__sad16_rows_u16(a, as, b, bs, rows, limit, &got_sum);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, ssda__kernel_name());
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_sum, got_sum, ssda__kernel_name());
    for (v = 0u; (k = ssda__kernel_variant(v)) != NULL; v++) {
        got_sum = 0u;
        got = k->sad16_rows_u16(a, as, b, bs, rows, limit, &got_sum);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want, got, k->name);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(want_sum, got_sum, k->name);
    }
}

static void test_sad16_rows_random(void)
{
    test_rng_t r;
    uint32_t i, rows, t;
    test_rng_seed(&r, 0x5AD16u);
    for (rows = 1u; rows <= S16_ROWS; rows++) {
        for (t = 0u; t < 40u; t++) {
            const uint32_t vmax = t % 2u == 0u ? 65535u : 300u;
            const size_t as = 2u * (16u + test_rng_range(&r, 0u, 3u));
            const size_t bs = 2u * (16u + test_rng_range(&r, 0u, 3u));
            const uint16_t *a = g_s16 + test_rng_range(&r, 0u, 7u);
            const uint16_t *b = a + test_rng_range(&r, 1u, 9u);
            uint32_t limit[5], row_sum[S16_ROWS], run = 0u, stop;
            for (i = 0u; i < sizeof g_s16 / sizeof g_s16[0]; i++) {
                g_s16[i] = (uint16_t)test_rng_range(&r, 0u, vmax);
            }
            for (i = 0u; i < rows; i++) { /* the running sums after each row */
                run += (uint32_t)ref_u16(a + i * (as / 2u), b + i * (bs / 2u), 16u);
                row_sum[i] = run;
            }
            /* every limit above all sums, then one near a chosen row's sum:
               at it, just below (stops there or before) or just above */
            for (i = 0u; i < 5u; i++) {
                limit[i] = t % 8u == 1u ? 0u : run + 1u + test_rng_range(&r, 0u, 5u);
            }
            stop = test_rng_range(&r, 0u, rows - 1u);
            if (t % 8u > 1u) {
                const uint32_t g = stop < 16u ? stop / 4u : 4u;
                limit[g] = row_sum[stop] + test_rng_range(&r, 0u, 2u) - 1u;
            }
            if (t % 8u == 7u) { /* the first 8 pixels' own check */
                limit[0] = (uint32_t)ref_u16(a, b, 8u) - (t % 16u == 7u ? 0u : 1u);
            }
            check_sad16_rows(a, as, b, bs, rows, limit);
        }
    }
}

/* The largest sum the contract allows: 4096 rows of 16 differences of
   65535 (stride 0: one row read again), 4 294 901 760 (above 2^31: the
   unsigned compares), with the last limit at it and just above. */
static void test_sad16_rows_worst_case(void)
{
    uint32_t limit[5] = {UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX};
    uint32_t i;
    for (i = 0u; i < 16u; i++) {
        g_s16[i] = 65535u;
        g_s16[16u + i] = 0u;
    }
    check_sad16_rows(g_s16, 0u, g_s16 + 16, 0u, 4096u, limit);
    limit[4] = 4294901760u;
    check_sad16_rows(g_s16, 0u, g_s16 + 16, 0u, 4096u, limit);
    limit[4] = 4294901760u - 16u * 65535u; /* the row before */
    check_sad16_rows(g_s16 + 16, 0u, g_s16, 0u, 4096u, limit);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_kernel_name_is_known);
    RUN_TEST(test_kernel_variants_listed);
    RUN_TEST(test_sad_u8_random_every_length_and_alignment);
    RUN_TEST(test_sad_u16_random_every_length_and_alignment);
    RUN_TEST(test_absdiff_i16_random_every_length_and_alignment);
    RUN_TEST(test_lanes_of_opposite_sign);
    RUN_TEST(test_sad_u8_worst_case);
    RUN_TEST(test_sad_u16_worst_case);
    RUN_TEST(test_absdiff_i16_worst_case);
    RUN_TEST(test_long_random_rows);
    RUN_TEST(test_sad_rows_random);
    RUN_TEST(test_sad_rows_worst_case);
    RUN_TEST(test_refine4_random);
    RUN_TEST(test_bounds4_random);
    RUN_TEST(test_bounds4_open_random);
    RUN_TEST(test_tab_row_random);
    RUN_TEST(test_vslide_random);
    RUN_TEST(test_blocks16_random);
    RUN_TEST(test_any_u16_every_position);
    RUN_TEST(test_sad16_rows_random);
    RUN_TEST(test_sad16_rows_worst_case);
    RUN_TEST(test_dot_random_every_length_alignment_and_rows);
    RUN_TEST(test_dot_worst_case);
    return UNITY_END();
}
