/* fixexp.c - exp(-x) and ln(v) in fixed point (see fixexp.h). */
#include "fixexp.h"

#include "wide.h"

#define LOG2E_Q30 1549082005u /* log2(e) */
#define LN2_Q32 2977044472u   /* ln(2) */
#define LN2_Q30 744261118     /* ln(2) */
#define ONE_U 1073741824u     /* 1.0 in Q30 */
#define Q30_HALF 536870912    /* 1/2, 1/3, 1/4, 1/5 in Q30, rounded */
#define Q30_THIRD 357913941
#define Q30_QUARTER 268435456
#define Q30_FIFTH 214748365
#define INV3_Q32 1431655765u  /* 1/3 */
#define INV5_Q32 858993459u   /* 1/5 */

/* round(a * b / 2^30) for 0 <= a, b <= 2^30 */
static uint64_t mul_q30(uint64_t a, uint64_t b)
{
    return (a * b + ((uint64_t)1u << 29)) >> 30; /* < 2^60 + 2^29 */
}

uint32_t ssda__exp_neg_q16(uint32_t x_q16)
{
    /* 2^-(i/16) in Q31, i = 0..15. */
    static const uint32_t k_exp2_q31[16] = {
        2147483648u, 2056437387u, 1969251188u, 1885761398u, 1805811301u, 1729250827u,
        1655936265u, 1585730000u, 1518500250u, 1454120821u, 1392470869u, 1333434672u,
        1276901417u, 1222764986u, 1170923762u, 1121280436u};
    /* y = x log2(e) in Q32, rounded: x < 2^32, log2(e) < 2^30.6, product
       < 2^62.6 */
    const uint64_t y = ((uint64_t)x_q16 * LOG2E_Q30 + ((uint64_t)1u << 13)) >> 14;
    const uint64_t n = y >> 32;
    uint64_t g, t, v, half;
    uint32_t i, sh;
    if (n >= 31u) {
        return 0u; /* below 2^-31 */
    }
    i = (uint32_t)(y >> 28) & 15u;
    /* g = (the 28 low fraction bits of y) ln 2 in Q30: < 2^28 * 2^32 / 2^34,
       that is g < ln(2) / 16 */
    g = ((y & 0xFFFFFFFu) * LN2_Q32 + ((uint64_t)1u << 33)) >> 34;
    /* e^-g = 1 - g (1 - g/2 (1 - g/3 (1 - g/4 (1 - g/5)))), each factor in
       [0.95, 1] */
    t = (uint64_t)ONE_U - ((g * INV5_Q32 + ((uint64_t)1u << 31)) >> 32);
    t = (uint64_t)ONE_U - (mul_q30(g, t) >> 2);
    t = (uint64_t)ONE_U - ((mul_q30(g, t) * INV3_Q32 + ((uint64_t)1u << 31)) >> 32);
    t = (uint64_t)ONE_U - (mul_q30(g, t) >> 1);
    t = (uint64_t)ONE_U - mul_q30(g, t);
    /* 2^-(i/16) (Q31) * e^-g (Q30) = Q61, < 2^61; back to Q30 and 2^-n */
    v = (uint64_t)k_exp2_q31[i] * t;
    sh = 30u + (uint32_t)n;
    half = (uint64_t)1u << sh;
    sh++;
    v = (v + half) >> sh;
    return (uint32_t)v;
}

int32_t ssda__ln_q24(uint64_t v)
{
    /* 1 / c_i in Q30 and ln(c_i) in Q30 for c_i = 1 + (2i + 1) / 32. */
    static const uint32_t k_inv_c_q30[16] = {
        1041204193u, 981706811u, 928641578u, 881018933u, 838042399u, 799063683u,
        763549742u,  731058263u, 701219150u, 673720360u, 648296950u, 624722516u,
        602802428u,  582368447u, 563274399u, 545392673u};
    static const uint32_t k_ln_c_q30[16] = {
        33040817u,  96220323u,  155887996u, 212413774u, 266112055u, 317252283u,
        366067135u, 412758919u, 457504636u, 500460037u, 541762891u, 581535654u,
        619887653u, 656916903u, 692711611u, 727351448u};
    const uint32_t bits = ssda__bitlen64(v);
    uint32_t e, m, i, sh;
    uint64_t u;
    int64_t r, s;
    if (bits == 0u) {
        return INT32_MIN;
    }
    e = bits - 1u;
    /* m in [2^31, 2^32): the mantissa of v in Q31 */
    if (e >= 31u) {
        sh = e - 31u;
        m = (uint32_t)(v >> sh);
    } else {
        sh = 31u - e;
        m = (uint32_t)(v << sh);
    }
    i = (m >> 27) & 15u;
    /* r = m / c_i - 1 in Q30: m / c_i in Q61 (< 2^62), rounded to Q30 */
    u = ((uint64_t)m * k_inv_c_q30[i] + ((uint64_t)1u << 30)) >> 31;
    r = (int64_t)u - SSDA__ONE_Q30;
    /* ln(1 + r) = r (1 - r (1/2 - r (1/3 - r (1/4 - r/5)))), |r| < 2^-5 */
    s = Q30_FIFTH;                                        /* 1/5 as the start */
    s = Q30_QUARTER - ssda__round_shift(r * s, 30u);      /* 1/4 - r s */
    s = Q30_THIRD - ssda__round_shift(r * s, 30u);        /* 1/3 - r s */
    s = Q30_HALF - ssda__round_shift(r * s, 30u);         /* 1/2 - r s */
    s = SSDA__ONE_Q30 - ssda__round_shift(r * s, 30u);    /* 1 - r s */
    s = ssda__round_shift(r * s, 30u);                    /* ln(1 + r) */
    /* ln v = e ln 2 + ln c_i + ln(1 + r), in Q30 (< 45 * 2^30), to Q24 */
    s += ((int64_t)e * LN2_Q30) + (int64_t)k_ln_c_q30[i];
    return (int32_t)ssda__round_shift(s, 6u);
}
