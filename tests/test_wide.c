/*
 * test_wide.c - the 128/192-bit helpers of lib/wide.c (the correlation
 * search's exact comparisons) against an independent schoolbook product in
 * 16-bit limbs written here: random and extreme operands, comparisons,
 * the 128-by-64 division and bit lengths.
 */
#include "unity.h"
#include "wide.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

/* out[0..na+nb) = a * b, little-endian 16-bit limbs */
static void ref_mul(const uint16_t *a, int na, const uint16_t *b, int nb, uint16_t *out)
{
    int i, j;
    for (i = 0; i < na + nb; i++) {
        out[i] = 0;
    }
    for (i = 0; i < na; i++) {
        uint32_t carry = 0;
        for (j = 0; j < nb; j++) {
            uint32_t t = (uint32_t)a[i] * b[j] + out[i + j] + carry;
            out[i + j] = (uint16_t)t;
            carry = t >> 16;
        }
        out[i + nb] = (uint16_t)carry;
    }
}

static void limbs(uint64_t v, uint16_t *out)
{
    int i;
    for (i = 0; i < 4; i++) {
        out[i] = (uint16_t)(v >> (16 * i));
    }
}

static uint64_t word(const uint16_t *l)
{
    return (uint64_t)l[0] | ((uint64_t)l[1] << 16) | ((uint64_t)l[2] << 32) | ((uint64_t)l[3] << 48);
}

static uint64_t rand64(test_rng_t *r)
{
    uint64_t v = ((uint64_t)test_rng_next(r) << 32) | test_rng_next(r);
    switch (test_rng_range(r, 0, 5)) {
    case 0: return v >> test_rng_range(r, 0, 63);
    case 1: return UINT64_MAX - (v & 0xFFu);
    case 2: return v & 0xFFFFFFFFu;
    default: return v;
    }
}

static void test_products_against_schoolbook(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 21u);
    for (t = 0; t < 20000u; t++) {
        uint64_t a = rand64(&r), b = rand64(&r), c = rand64(&r);
        uint16_t la[8], lb[4], lc[4], p[8], q[12];
        ssda__u128_t ab = ssda__mul_64x64(a, b), ab2 = ssda__mul_64x64_parts(a, b);
        ssda__u192_t abc;
        limbs(a, la);
        limbs(b, lb);
        limbs(c, lc);
        ref_mul(la, 4, lb, 4, p);
        TEST_ASSERT_EQUAL_UINT64(word(p), ab.lo);
        TEST_ASSERT_EQUAL_UINT64(word(p + 4), ab.hi);
        TEST_ASSERT_EQUAL_UINT64(ab.lo, ab2.lo);
        TEST_ASSERT_EQUAL_UINT64(ab.hi, ab2.hi);
        abc = ssda__mul_128x64(ab, c);
        ref_mul(p, 8, lc, 4, q);
        TEST_ASSERT_EQUAL_UINT64(word(q), abc.w0);
        TEST_ASSERT_EQUAL_UINT64(word(q + 4), abc.w1);
        TEST_ASSERT_EQUAL_UINT64(word(q + 8), abc.w2);
    }
}

static void test_extremes(void)
{
    ssda__u128_t m = ssda__mul_64x64(UINT64_MAX, UINT64_MAX);
    ssda__u192_t w = ssda__mul_128x64(m, UINT64_MAX);
    /* (2^64 - 1)^2 = 2^128 - 2^65 + 1 */
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX - 1u, m.hi);
    TEST_ASSERT_EQUAL_UINT64(1u, m.lo);
    /* (2^64 - 1)^3 = 2^192 - 3 * 2^128 + 3 * 2^64 - 1 */
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX - 2u, w.w2);
    TEST_ASSERT_EQUAL_UINT64(2u, w.w1);
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, w.w0);
    m = ssda__mul_64x64_parts(UINT64_MAX, UINT64_MAX);
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX - 1u, m.hi);
    TEST_ASSERT_EQUAL_UINT64(1u, m.lo);
}

static void test_compare_and_divide(void)
{
    test_rng_t r;
    uint32_t t;
    ssda__u192_t a = {1, 2, 3}, b = {1, 2, 3};
    ssda__u128_t x = {5, 6}, y = {5, 6};
    TEST_ASSERT_EQUAL_INT(0, ssda__cmp_192(&a, &b));
    TEST_ASSERT_EQUAL_INT(0, ssda__cmp_128(x, y));
    b.w0 = 4;
    TEST_ASSERT_EQUAL_INT(-1, ssda__cmp_192(&a, &b));
    TEST_ASSERT_EQUAL_INT(1, ssda__cmp_192(&b, &a));
    b.w1 = 1;
    TEST_ASSERT_EQUAL_INT(1, ssda__cmp_192(&a, &b));
    b.w2 = 2;
    TEST_ASSERT_EQUAL_INT(-1, ssda__cmp_192(&a, &b));
    y.lo = 7;
    TEST_ASSERT_EQUAL_INT(-1, ssda__cmp_128(x, y));
    y.hi = 4;
    TEST_ASSERT_EQUAL_INT(1, ssda__cmp_128(x, y));
    test_rng_seed(&r, 22u);
    for (t = 0; t < 5000u; t++) {
        /* n = q d + rem with rem < d: the quotient must come back */
        uint64_t d = rand64(&r) | 1u, q = rand64(&r), rem = rand64(&r) % d;
        ssda__u128_t n = ssda__mul_64x64(q, d);
        n.lo += rem;
        n.hi += n.lo < rem ? 1u : 0u;
        TEST_ASSERT_EQUAL_UINT64(q, ssda__div_128_64(n, d));
    }
}

static void test_bit_length(void)
{
    uint32_t i;
    TEST_ASSERT_EQUAL_UINT32(0, ssda__bitlen64(0));
    for (i = 0; i < 64u; i++) {
        TEST_ASSERT_EQUAL_UINT32(i + 1u, ssda__bitlen64((uint64_t)1u << i));
        TEST_ASSERT_EQUAL_UINT32(i + 1u, ssda__bitlen64(((uint64_t)1u << i) | 1u));
    }
    TEST_ASSERT_EQUAL_UINT32(64, ssda__bitlen64(UINT64_MAX));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_products_against_schoolbook);
    RUN_TEST(test_extremes);
    RUN_TEST(test_compare_and_divide);
    RUN_TEST(test_bit_length);
    return UNITY_END();
}
