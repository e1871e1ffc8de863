/*
 * test_wide_signed.c - the signed 128-bit helpers of lib/wide.h against a second
 * implementation: __int128 where the compiler has it, else values whose
 * results are known in closed form (powers of two, small products).
 */
#include "unity.h"
#include "wide.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

static ssda__i128_t w_of(uint64_t hi, uint64_t lo)
{
    ssda__i128_t v;
    v.hi = hi;
    v.lo = lo;
    return v;
}

#if defined(__SIZEOF_INT128__)
static uint64_t r64(test_rng_t *r)
{
    return ((uint64_t)test_rng_next(r) << 32) | test_rng_next(r);
}

typedef __int128 n128;
static n128 n_of(ssda__i128_t v)
{
    return (n128)(((unsigned __int128)v.hi << 64) | v.lo);
}
static void check(n128 want, ssda__i128_t got)
{
    TEST_ASSERT_EQUAL_HEX64((uint64_t)((unsigned __int128)want >> 64), got.hi);
    TEST_ASSERT_EQUAL_HEX64((uint64_t)want, got.lo);
}

/* Random operands of every size: add, sub, neg, shifts, products and both
   roundings of the quotient, against __int128. */
static void test_against_int128(void)
{
    test_rng_t r;
    int i;
    test_rng_seed(&r, 0x49313238u);
    for (i = 0; i < 20000; i++) {
        const unsigned bits_a = 1 + test_rng_next(&r) % 126, bits_b = 1 + test_rng_next(&r) % 126;
        ssda__i128_t a = ssda__w_sar(w_of(r64(&r), r64(&r)), 127 - bits_a);
        ssda__i128_t b = ssda__w_sar(w_of(r64(&r), r64(&r)), 127 - bits_b);
        const n128 na = n_of(a), nb = n_of(b);
        const uint32_t s = test_rng_next(&r) % 128;
        const int64_t m = (int64_t)r64(&r) >> (test_rng_next(&r) % 63);
        check(na + nb, ssda__w_add(a, b));
        check(na - nb, ssda__w_sub(a, b));
        check(-na, ssda__w_neg(a));
        TEST_ASSERT_EQUAL(na < nb, ssda__w_lt(a, b));
        TEST_ASSERT_EQUAL(na < 0, ssda__w_neg_p(a));
        TEST_ASSERT_EQUAL(na == 0, ssda__w_zero_p(a));
        check((n128)((unsigned __int128)na << s), ssda__u128_shl(a, s));
        check(na >> s, ssda__w_sar(a, s));
        check((n128)(int64_t)a.lo * (int64_t)b.lo, ssda__w_mul64((int64_t)a.lo, (int64_t)b.lo));
        if (bits_a + 64 < 126) {
            check(na * m, ssda__w_mul(a, m));
        }
        if (nb != 0) {
            n128 q = na / nb, rem = na % nb;
            n128 fl = (rem != 0 && ((rem < 0) != (nb < 0))) ? q - 1 : q;
            n128 ar = rem < 0 ? -rem : rem, ab = nb < 0 ? -nb : nb;
            n128 rd = q + (2 * ar >= ab ? ((na < 0) != (nb < 0) ? -1 : 1) : 0);
            check(rd, ssda__w_div_round(a, b));
            if (nb > 0) {
                check(fl, ssda__w_div_floor(a, b));
            }
        }
        TEST_ASSERT_EQUAL(na >= INT64_MIN && na <= INT64_MAX, ssda__w_fits64(a));
        if (ssda__w_fits64(a)) {
            TEST_ASSERT_EQUAL_INT64((int64_t)na, ssda__i128_to64(a));
        }
    }
}
#endif

/* Closed forms, every target. */
static void test_closed_forms(void)
{
    const ssda__i128_t one = w_of(0, 1);
    uint32_t n;
    for (n = 0; n < 128; n++) {
        const ssda__i128_t p = ssda__u128_shl(one, n);
        TEST_ASSERT_EQUAL_HEX64(n >= 64 ? (uint64_t)1 << (n - 64) : 0, p.hi);
        TEST_ASSERT_EQUAL_HEX64(n < 64 ? (uint64_t)1 << n : 0, p.lo);
        /* -2^n >> n = -1; 2^n >> n = 1 (n < 127) */
        if (n < 127) {
            const ssda__i128_t q = ssda__w_sar(p, n);
            TEST_ASSERT_TRUE(q.hi == 0 && q.lo == 1);
        }
        {
            const ssda__i128_t q = ssda__w_sar(ssda__w_neg(p), n);
            TEST_ASSERT_TRUE(q.hi == UINT64_MAX && q.lo == UINT64_MAX);
        }
    }
    /* (2^63)^2 = 2^126, (-2^63) * (2^63 - 1) */
    {
        const ssda__i128_t p = ssda__w_mul64(INT64_MIN, INT64_MIN);
        TEST_ASSERT_EQUAL_HEX64((uint64_t)1 << 62, p.hi);
        TEST_ASSERT_EQUAL_HEX64(0, p.lo);
    }
    /* rounding: 7 / 2 = 4, -7 / 2 = -4, 5 / -2 = -3 (halves away from 0);
       floor(-7 / 2) = -4, floor(-6 / 2) = -3 */
    TEST_ASSERT_EQUAL_INT64(4, ssda__i128_to64(ssda__w_div_round(ssda__w_i64(7), ssda__w_i64(2))));
    TEST_ASSERT_EQUAL_INT64(-4, ssda__i128_to64(ssda__w_div_round(ssda__w_i64(-7), ssda__w_i64(2))));
    TEST_ASSERT_EQUAL_INT64(-3, ssda__i128_to64(ssda__w_div_round(ssda__w_i64(5), ssda__w_i64(-2))));
    TEST_ASSERT_EQUAL_INT64(2, ssda__i128_to64(ssda__w_div_round(ssda__w_i64(7), ssda__w_i64(3))));
    TEST_ASSERT_EQUAL_INT64(-4, ssda__i128_to64(ssda__w_div_floor(ssda__w_i64(-7), ssda__w_i64(2))));
    TEST_ASSERT_EQUAL_INT64(-3, ssda__i128_to64(ssda__w_div_floor(ssda__w_i64(-6), ssda__w_i64(2))));
    TEST_ASSERT_EQUAL_INT64(3, ssda__i128_to64(ssda__w_div_floor(ssda__w_i64(7), ssda__w_i64(2))));
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, ssda__i128_to64(ssda__w_i64(INT64_MIN)));
    TEST_ASSERT_FALSE(ssda__w_fits64(w_of(0, (uint64_t)1 << 63)));
    TEST_ASSERT_FALSE(ssda__w_fits64(w_of(UINT64_MAX, 0)));
    TEST_ASSERT_EQUAL_INT64((int64_t)1 << 62, ssda__pow2(62));
    /* a product past 2^64 in the 128 x 64 multiply: (2^70 + 3) * -5 */
    {
        const ssda__i128_t p = ssda__w_mul(ssda__w_add(ssda__u128_shl(one, 70), ssda__w_i64(3)), -5);
        const ssda__i128_t want = ssda__w_neg(ssda__w_add(ssda__u128_shl(ssda__w_i64(5), 70), ssda__w_i64(15)));
        TEST_ASSERT_TRUE(p.hi == want.hi && p.lo == want.lo);
    }
}

int main(void)
{
    UNITY_BEGIN();
#if defined(__SIZEOF_INT128__)
    RUN_TEST(test_against_int128);
#endif
    RUN_TEST(test_closed_forms);
    return UNITY_END();
}
