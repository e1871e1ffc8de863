/*
 * test_fixmath_div.c - ssda__div64_32 (lib/fixmath.c), the 64-by-32 division
 * that cores without a divide instruction use instead of the runtime
 * library's: against the compiler's 64-bit division, at the extremes of
 * dividend and divisor and on random operands of every magnitude, with the
 * saturation at UINT32_MAX when the quotient needs more than 32 bits; and
 * ssda__mul_u32_u16 and ssda__mul_u32_u32, the 32 x 16 and 32 x 32
 * products without a 64-bit multiply routine, against the compiler's product.
 */
#include "unity.h"
#include "fixmath.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

/* The reference: the compiler's division, saturated as documented. */
static uint32_t ref_div(uint64_t n, uint32_t d)
{
    uint64_t q = n / d;
    return q > UINT32_MAX ? UINT32_MAX : (uint32_t)q;
}

static void check(uint64_t n, uint32_t d)
{
    TEST_ASSERT_EQUAL_HEX32(ref_div(n, d), ssda__div64_32(n, d));
}

static void test_div_extremes(void)
{
    static const uint32_t ds[] = {1u, 2u, 3u, 7u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u,
                                  0xFFFFFFFEu, 0xFFFFFFFFu, 65536u, 65535u};
    size_t i;
    for (i = 0u; i < sizeof ds / sizeof ds[0]; i++) {
        uint32_t d = ds[i];
        uint64_t top = ((uint64_t)d << 32) - 1u; /* the largest n with a 32-bit quotient */
        check(0u, d);
        check(1u, d);
        check(d - 1u, d);
        check(d, d);
        check(top, d);       /* quotient UINT32_MAX, remainder d - 1 */
        check(top + 1u, d);  /* 2^32: saturates */
        check(UINT64_MAX, d);
        check((uint64_t)d * 0xFFFFFFFFu, d); /* exact, the largest multiple */
    }
}

static void test_div_random(void)
{
    test_rng_t r;
    uint32_t i;
    test_rng_seed(&r, 12345u);
    for (i = 0u; i < 20000u; i++) {
        /* divisors and dividends of every bit length, so the carry out of
           the 32-bit remainder (divisor >= 2^31) is taken often */
        uint32_t d = test_rng_next(&r) >> (test_rng_next(&r) % 32u);
        uint64_t n = (((uint64_t)test_rng_next(&r) << 32) | test_rng_next(&r)) >>
                     (test_rng_next(&r) % 64u);
        if (d == 0u) {
            d = 1u;
        }
        check(n, d);
        if ((n >> 32) >= d) {
            check(n % ((uint64_t)d << 32), d); /* the same, brought under 2^32 * d */
        }
    }
}

/* ssda__mul_u32_u16 (two 32-bit partial products) against the compiler's
   64-bit product: extremes and random operands of every size. */
static void test_mul_u32_u16(void)
{
    static const uint32_t as[] = {0u, 1u, 0xFFFFu, 0x10000u, 0xFFFF0000u, 0xFFFFFFFFu};
    static const uint16_t bs[] = {0u, 1u, 2u, 0x8000u, 0xFFFEu, 0xFFFFu};
    test_rng_t r;
    uint32_t i, j;
    for (i = 0; i < 6u; i++) {
        for (j = 0; j < 6u; j++) {
            TEST_ASSERT_EQUAL_UINT64((uint64_t)as[i] * bs[j], ssda__mul_u32_u16(as[i], bs[j]));
        }
    }
    test_rng_seed(&r, 777u);
    for (i = 0; i < 100000u; i++) {
        uint32_t a = test_rng_next(&r) >> (test_rng_next(&r) % 32u);
        uint16_t b = (uint16_t)(test_rng_next(&r) >> (16u + test_rng_next(&r) % 16u));
        TEST_ASSERT_EQUAL_UINT64((uint64_t)a * b, ssda__mul_u32_u16(a, b));
    }
}

/* ssda__mul_u32_u32 (four 16 x 16 products, SSDA_MUL64 on Thumb-1 cores)
   against the compiler's 64-bit product: extremes and random operands of
   every size. */
static void test_mul_u32_u32(void)
{
    static const uint32_t vs[] = {0u, 1u, 2u, 0xFFFFu, 0x10000u, 0x7FFFFFFFu, 0x80000000u,
                                  0xFFFF0000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    test_rng_t r;
    uint32_t i, j;
    for (i = 0; i < 10u; i++) {
        for (j = 0; j < 10u; j++) {
            TEST_ASSERT_EQUAL_UINT64((uint64_t)vs[i] * vs[j], ssda__mul_u32_u32(vs[i], vs[j]));
        }
    }
    test_rng_seed(&r, 778u);
    for (i = 0; i < 100000u; i++) {
        uint32_t a = test_rng_next(&r) >> (test_rng_next(&r) % 32u);
        uint32_t b = test_rng_next(&r) >> (test_rng_next(&r) % 32u);
        TEST_ASSERT_EQUAL_UINT64((uint64_t)a * b, ssda__mul_u32_u32(a, b));
        TEST_ASSERT_EQUAL_UINT64((uint64_t)a * b, SSDA_MUL64(a, b));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_mul_u32_u32);
    RUN_TEST(test_div_extremes);
    RUN_TEST(test_div_random);
    RUN_TEST(test_mul_u32_u16);
    return UNITY_END();
}
