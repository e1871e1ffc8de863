/*
 * test_wide128.c - the 128-bit sums, shifts, quotients and roots of
 * lib/wide.c (used by the K-L transform and the mixture fits), by
 * identities that hold on every target (no __int128 needed): products
 * against a schoolbook product in 16-bit digits, q * d + r == n with r < d
 * for divisions, r^2 <= a < (r + 1)^2 for square roots, shifts inverse to
 * each other, and the symmetric rounding shift against its definition.
 */
#include "unity.h"
#include "wide.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef SSDA_TEST_SMALL
#define RANDOM 300u
#else
#define RANDOM 20000u
#endif

static uint64_t rand64(test_rng_t *r)
{
    const uint64_t v = ((uint64_t)test_rng_next(r) << 32) | test_rng_next(r);
    return v >> (test_rng_next(r) % 64u);
}

static ssda__u128_t rand128(test_rng_t *r)
{
    ssda__u128_t v;
    v.hi = rand64(r);
    v.lo = ((uint64_t)test_rng_next(r) << 32) | test_rng_next(r);
    if (test_rng_next(r) % 3u == 0u) {
        v.hi = 0u;
        v.lo = rand64(r);
    }
    return v;
}

static void assert_eq(ssda__u128_t a, ssda__u128_t b)
{
    TEST_ASSERT_EQUAL_HEX64(a.hi, b.hi);
    TEST_ASSERT_EQUAL_HEX64(a.lo, b.lo);
}

/* a * b by 16-bit digits, schoolbook, as a reference */
static ssda__u128_t mul_ref(uint64_t a, uint64_t b)
{
    uint32_t d[8] = {0};
    uint32_t i, j;
    ssda__u128_t r;
    for (i = 0; i < 4u; i++) {
        uint32_t carry = 0u;
        for (j = 0; j < 4u; j++) {
            const uint32_t t = (uint32_t)((a >> (16u * i)) & 0xFFFFu) *
                               (uint32_t)((b >> (16u * j)) & 0xFFFFu);
            /* d + t + carry < 2^16 + 2^32 - 2^17 + 1 + 2^16: fits 32 bits after splitting */
            const uint64_t s = (uint64_t)d[i + j] + t + carry;
            d[i + j] = (uint32_t)(s & 0xFFFFu);
            carry = (uint32_t)(s >> 16);
        }
        for (j = i + 4u; j < 8u && carry != 0u; j++) {
            const uint32_t s = d[j] + carry;
            d[j] = s & 0xFFFFu;
            carry = s >> 16;
        }
    }
    r.lo = (uint64_t)d[0] | ((uint64_t)d[1] << 16) | ((uint64_t)d[2] << 32) | ((uint64_t)d[3] << 48);
    r.hi = (uint64_t)d[4] | ((uint64_t)d[5] << 16) | ((uint64_t)d[6] << 32) | ((uint64_t)d[7] << 48);
    return r;
}

static void test_mul(void)
{
    test_rng_t r;
    uint32_t i;
    assert_eq(mul_ref(UINT64_MAX, UINT64_MAX), ssda__mul_64x64(UINT64_MAX, UINT64_MAX));
    TEST_ASSERT_EQUAL_HEX64(UINT64_MAX - 1u, ssda__mul_64x64(UINT64_MAX, UINT64_MAX).hi);
    TEST_ASSERT_EQUAL_HEX64(1u, ssda__mul_64x64(UINT64_MAX, UINT64_MAX).lo);
    test_rng_seed(&r, 11u);
    for (i = 0; i < RANDOM; i++) {
        const uint64_t a = rand64(&r), b = rand64(&r);
        assert_eq(mul_ref(a, b), ssda__mul_64x64(a, b));
    }
}

static void test_add_sub_shift_cmp(void)
{
    test_rng_t r;
    uint32_t i;
    test_rng_seed(&r, 12u);
    for (i = 0; i < RANDOM; i++) {
        const ssda__u128_t a = rand128(&r), b = rand128(&r);
        const uint32_t s = test_rng_next(&r) % 128u;
        const ssda__u128_t sum = ssda__u128_add(a, b);
        assert_eq(a, ssda__u128_sub(sum, b));
        TEST_ASSERT_EQUAL_INT(0, ssda__cmp_128(a, a));
        TEST_ASSERT_EQUAL_INT(-ssda__cmp_128(a, b), ssda__cmp_128(b, a));
        if (ssda__u128_bits(a) + s <= 128u) {
            assert_eq(a, ssda__u128_shr(ssda__u128_shl(a, s), s));
            TEST_ASSERT_EQUAL_UINT32(a.hi == 0u && a.lo == 0u ? 0u : ssda__u128_bits(a) + s,
                                     ssda__u128_bits(ssda__u128_shl(a, s)));
        }
        /* shr then shl clears exactly the low s bits */
        {
            const ssda__u128_t back = ssda__u128_shl(ssda__u128_shr(a, s), s);
            const ssda__u128_t low = ssda__u128_sub(a, back);
            TEST_ASSERT_TRUE(ssda__u128_bits(low) <= s);
        }
    }
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, ssda__u128_sat64(ssda__u128_shl(ssda__u128_from(1u), 64u)));
    TEST_ASSERT_EQUAL_UINT64(5u, ssda__u128_sat64(ssda__u128_from(5u)));
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__bitlen64(0u));
    TEST_ASSERT_EQUAL_UINT32(64u, ssda__bitlen64(UINT64_MAX));
}

static void check_div(ssda__u128_t n, ssda__u128_t d)
{
    const ssda__u128_t q = ssda__u128_div(n, d);
    ssda__u128_t prod, rem;
    /* q * d without overflow: q < 2^(bits(n) - bits(d) + 1) */
    TEST_ASSERT_TRUE(q.hi == 0u || d.hi == 0u);
    if (q.hi == 0u) {
        prod = ssda__mul_64x64(q.lo, d.lo);
        prod.hi += q.lo * d.hi;
    } else {
        prod = ssda__mul_64x64(q.hi, d.lo);
        prod.hi = prod.lo;
        prod.lo = 0u;
        prod = ssda__u128_add(prod, ssda__mul_64x64(q.lo, d.lo));
    }
    TEST_ASSERT_TRUE(ssda__cmp_128(prod, n) <= 0);
    rem = ssda__u128_sub(n, prod);
    TEST_ASSERT_TRUE(ssda__cmp_128(rem, d) < 0);
}

static void test_div(void)
{
    test_rng_t r;
    uint32_t i;
    ssda__u128_t top, big;
    top.hi = UINT64_MAX;
    top.lo = UINT64_MAX;
    big.hi = (uint64_t)1u << 63;
    big.lo = 1u;
    check_div(top, ssda__u128_from(1u));
    check_div(top, top);
    check_div(top, big);          /* a divisor >= 2^127: the carry path */
    check_div(big, top);
    check_div(ssda__u128_from(0u), ssda__u128_from(3u));
    assert_eq(top, ssda__u128_div(ssda__u128_from(7u), ssda__u128_from(0u)));
    test_rng_seed(&r, 13u);
    for (i = 0; i < RANDOM; i++) {
        ssda__u128_t d = rand128(&r);
        if (d.hi == 0u && d.lo == 0u) {
            d.lo = 1u;
        }
        check_div(rand128(&r), d);
    }
}

static void check_isqrt(ssda__u128_t a)
{
    const uint64_t s = ssda__u128_isqrt(a);
    TEST_ASSERT_TRUE(ssda__cmp_128(ssda__mul_64x64(s, s), a) <= 0);
    if (s != UINT64_MAX) {
        TEST_ASSERT_TRUE(ssda__cmp_128(ssda__mul_64x64(s + 1u, s + 1u), a) > 0);
    }
}

static void test_isqrt(void)
{
    test_rng_t r;
    uint32_t i;
    ssda__u128_t top;
    top.hi = UINT64_MAX;
    top.lo = UINT64_MAX;
    check_isqrt(top);
    TEST_ASSERT_EQUAL_HEX64(UINT64_MAX, ssda__u128_isqrt(top));
    TEST_ASSERT_EQUAL_HEX64(0u, ssda__u128_isqrt(ssda__u128_from(0u)));
    for (i = 1u; i < 300u; i++) {
        check_isqrt(ssda__u128_from(i));
        check_isqrt(ssda__mul_64x64(i, i));
        check_isqrt(ssda__u128_sub(ssda__mul_64x64((uint64_t)i << 40, (uint64_t)i << 40),
                                   ssda__u128_from(1u)));
    }
    test_rng_seed(&r, 14u);
    for (i = 0; i < RANDOM; i++) {
        check_isqrt(rand128(&r));
    }
}

static void test_round_shift(void)
{
    test_rng_t r;
    uint32_t i;
    TEST_ASSERT_EQUAL_INT64(1, ssda__round_shift(1, 1));   /* 0.5 -> 1 */
    TEST_ASSERT_EQUAL_INT64(-1, ssda__round_shift(-1, 1)); /* -0.5 -> -1 */
    TEST_ASSERT_EQUAL_INT64(0, ssda__round_shift(-1, 2));
    TEST_ASSERT_EQUAL_INT64(-2, ssda__round_shift(-6, 2)); /* -1.5 -> -2 */
    TEST_ASSERT_EQUAL_INT64(-((int64_t)1 << 60), ssda__round_shift(INT64_MIN, 3));
    TEST_ASSERT_EQUAL_INT64((int64_t)1 << 60, ssda__round_shift(INT64_MAX, 3));
    test_rng_seed(&r, 15u);
    for (i = 0; i < RANDOM; i++) {
        /* |v| < 2^62: q 2^s, up to |v| + 2^(s-1), stays in range */
        const int64_t v = (int64_t)(rand64(&r) >> 2) * ((test_rng_next(&r) & 1u) != 0u ? -1 : 1);
        const uint32_t s = 1u + test_rng_next(&r) % 62u;
        const int64_t q = ssda__round_shift(v, s);
        const int64_t back = q * ((int64_t)1 << s); /* |q| 2^s <= |v| + 2^(s-1) */
        TEST_ASSERT_EQUAL_INT64(-q, ssda__round_shift(-v, s));
        /* |v - q 2^s| <= 2^(s-1), with equality rounding away from zero */
        if (v >= 0) {
            TEST_ASSERT_TRUE(v - back <= ((int64_t)1 << (s - 1u)) - 1 && back - v <= ((int64_t)1 << (s - 1u)));
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_mul);
    RUN_TEST(test_add_sub_shift_cmp);
    RUN_TEST(test_div);
    RUN_TEST(test_isqrt);
    RUN_TEST(test_round_shift);
    return UNITY_END();
}
