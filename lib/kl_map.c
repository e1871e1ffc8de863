/* kl_map.c - the per-pixel K-L transform into feature values (kl.h):
   integer weights planned once, then 9 multiply-adds per pixel. */
#include "kl_internal.h"

#include "fixmath.h"

/* Bounds of the plan. 8-bit input: |w| <= 2^21 and |x - 128| <= 128 give
   |sum w (x - c)| <= 3 2^28, |b| <= 2^30, so the int32 sum stays below
   2^31. 16-bit input (int64 sums): |w| <= 2^30, |x - 32768| <= 2^15,
   |b| <= 2^60. */
#define W_MAX_U8 2097152                 /* 2^21 */
#define B_MAX_U8 1073741824              /* 2^30 */
#define W_MAX_U16 1073741824             /* 2^30 */
#define B_MAX_U16 1152921504606846976LL  /* 2^60 */

/* The gain g_k = num / den of feature k (kl.h), capped at gain_max. */
static void gain(const ssda_kl_t *kl, uint32_t k, uint64_t *num, uint64_t *den)
{
    uint64_t top = 65535u, vmax = 0u; /* the largest |v_kj|, Q30: >= 2^30 / sqrt(3) */
    uint32_t j;
    for (j = 0u; j < 3u; j++) {
        const uint64_t m = (uint64_t)(kl->vec_q30[k][j] < 0 ? -(int64_t)kl->vec_q30[k][j]
                                                           : (int64_t)kl->vec_q30[k][j]);
        vmax = m > vmax ? m : vmax;
    }
    if (kl->format == (uint8_t)SSDA_PIX_U8) {
        top = 255u;
    }
    if (kl->range == (uint8_t)SSDA_KL_RANGE_SIGMA) {
        /* sd = sqrt(zvar_q16 / 2^16) in Q24: zvar_q16 < 2^50, sd_q24 < 2^49 */
        const uint64_t sd_q24 =
            ssda__u128_isqrt(ssda__u128_shl(ssda__u128_from(kl->zvar_q16[k]), 32u));
        *num = (uint64_t)kl->out_max << 24; /* < 2^40 */
        *den = sd_q24 * 2u * kl->nsigma;    /* < 2^54 */
    } else {
        uint64_t l1 = 0u; /* sum |v| in Q30, < 2^32 */
        for (j = 0u; j < 3u; j++) {
            l1 += (uint64_t)(kl->vec_q30[k][j] < 0 ? -(int64_t)kl->vec_q30[k][j]
                                                   : (int64_t)kl->vec_q30[k][j]);
        }
        *num = (uint64_t)kl->out_max << 30; /* < 2^46 */
        *den = l1 * 2u * top;               /* < 2^49 */
    }
    /* g vmax > gain_max: a step of one band would move z more than gain_max
       steps. num 2^16 vmax < 2^92, gain_max den 2^30 < 2^112 */
    if (*den == 0u ||
        ssda__cmp_128(ssda__mul_64x64(*num << 16, vmax),
                       ssda__u128_shl(ssda__mul_64x64(kl->gain_max_q16, *den), 30u)) > 0) {
        *num = (uint64_t)kl->gain_max_q16 << 30; /* g = gain_max / vmax */
        *den = vmax << 16;
    }
}

/* round(|v| num 2^sh / (den 2^30)) with v's sign: |v| num < 2^76, sh <= 46 */
static int64_t weight(int32_t v, uint64_t num, uint64_t den, uint32_t sh)
{
    const uint64_t mag = (uint64_t)(v < 0 ? -(int64_t)v : (int64_t)v);
    const ssda__u128_t d = ssda__u128_shl(ssda__u128_from(den), 30u);
    ssda__u128_t n = ssda__u128_shl(ssda__mul_64x64(mag, num), sh);
    int64_t w;
    n = ssda__u128_add(n, ssda__u128_shr(d, 1u));
    w = (int64_t)ssda__u128_sat64(ssda__u128_div(n, d));
    return v < 0 ? -w : w;
}

/* Try the plan at shift sh: false if a weight or offset exceeds its bound. */
static bool plan_at(ssda_kl_t *kl, const uint64_t num[3], const uint64_t den[3],
                    const int64_t dm_q16[3], uint32_t sh)
{
    const bool u8 = kl->format == (uint8_t)SSDA_PIX_U8;
    int64_t wmax = W_MAX_U16, bmax = B_MAX_U16;
    const uint32_t sh1 = sh - 1u;
    uint32_t k, j;
    if (u8) {
        wmax = W_MAX_U8;
        bmax = B_MAX_U8;
    }
    for (k = 0u; k < 3u; k++) {
        int64_t s = 0; /* sum w (m - c) in Q16: |w| 2^31 each, < 1.5 2^62 */
        for (j = 0u; j < 3u; j++) {
            const int64_t w = weight(kl->vec_q30[k][j], num[k], den[k], sh);
            if (w > wmax || w < -wmax) {
                return false;
            }
            kl->w[k][j] = (int32_t)w;
            s += w * dm_q16[j];
        }
        /* b = (mid + 1/2) 2^sh - sum w (m - c): mid + 1/2 = (out_max + 1) / 2 */
        const uint64_t mid = ((uint64_t)kl->out_max + 1u) << sh1; /* < 2^62 */
        kl->b[k] = (int64_t)mid - ssda__round_shift(s, 16u);
        /* |sum w (m - c)| <= 3 wmax 2^15 (16-bit) or 3 wmax 2^7 (8-bit) is
           below bmax: b can pass its bound upwards only */
        if (kl->b[k] > bmax) {
            return false;
        }
    }
    kl->shift = sh;
    return true;
}

void ssda__kl_plan(ssda_kl_t *kl, const uint64_t sum[3])
{
    const bool u8 = kl->format == (uint8_t)SSDA_PIX_U8;
    int64_t c_q16 = 2147483648LL; /* the centre 32768 in Q16 */
    uint64_t num[3], den[3];
    int64_t dm_q16[3];
    uint32_t k, sh = 46u;
    if (u8) {
        c_q16 = 8388608; /* 128 in Q16 */
        sh = 30u;
    }
    for (k = 0u; k < 3u; k++) {
        /* the mean in Q16 (sum < 2^48: sum 2^16 < 2^64, mean < 2^32) minus
           the centre */
        const uint64_t n = sum[k] << 16;
        dm_q16[k] = (int64_t)SSDA_DIV64_32(n + (kl->count >> 1), kl->count) - c_q16;
        gain(kl, k, &num[k], &den[k]);
    }
    /* the largest shift whose weights and offsets fit. It ends: with
       g <= 2^12 and |v| <= 1, |w| <= 2^(12 + sh) fits at sh = 9 (8-bit,
       wmax 2^21) and sh = 18 (16-bit, wmax 2^30), where b <= 2^16 2^(sh-1)
       + 3 wmax 2^7 (or 2^15) is within bmax; so each z is within 1 of the
       exact formula (docs/segmentation.md) */
    while (!plan_at(kl, num, den, dm_q16, sh)) {
        sh--;
    }
}

/* z from the plan's sum, clamped to 0..out_max; counts clamps. */
static uint16_t clamp_z(int64_t acc, uint32_t sh, uint32_t out_max, uint32_t *clamped)
{
    uint64_t z;
    if (acc < 0) {
        (*clamped)++;
        return 0u;
    }
    z = (uint64_t)acc >> sh;
    if (z > out_max) {
        (*clamped)++;
        return (uint16_t)out_max;
    }
    return (uint16_t)z;
}

static uint32_t row_u8(const ssda_kl_t *kl, const ssda_kl_row_t *row, uint32_t width,
                       uint16_t *const out[3])
{
    const uint8_t *p0 = (const uint8_t *)row->band[0];
    const uint8_t *p1 = (const uint8_t *)row->band[1];
    const uint8_t *p2 = (const uint8_t *)row->band[2];
    const bool mask = (kl->flags & SSDA_KL_MASK_NODATA) != 0u;
    uint32_t i, k, clamped = 0u;
    size_t o = 0u;
    int32_t b[3];
    for (k = 0u; k < 3u; k++) {
        b[k] = (int32_t)kl->b[k]; /* |b| <= 2^30 (plan bound) */
    }
    for (i = 0u; i < width; i++, o += row->step) {
        const int32_t x0 = (int32_t)p0[o] - 128, x1 = (int32_t)p1[o] - 128;
        const int32_t x2 = (int32_t)p2[o] - 128;
        const bool masked = mask && p0[o] == kl->nodata && p1[o] == kl->nodata &&
                            p2[o] == kl->nodata;
        for (k = 0u; k < 3u; k++) {
            if (out[k] != NULL) {
                /* |sum| <= 3 2^21 2^7 + 2^30 < 2^31 */
                const int32_t acc = kl->w[k][0] * x0 + kl->w[k][1] * x1 + kl->w[k][2] * x2 + b[k];
                out[k][i] = masked ? (uint16_t)SSDA_KL_NODATA
                                   : clamp_z(acc, kl->shift, kl->out_max, &clamped);
            }
        }
    }
    return clamped;
}

static uint32_t row_u16(const ssda_kl_t *kl, const ssda_kl_row_t *row, uint32_t width,
                        uint16_t *const out[3])
{
    const uint16_t *p0 = (const uint16_t *)row->band[0];
    const uint16_t *p1 = (const uint16_t *)row->band[1];
    const uint16_t *p2 = (const uint16_t *)row->band[2];
    const bool mask = (kl->flags & SSDA_KL_MASK_NODATA) != 0u;
    uint32_t i, k, clamped = 0u;
    size_t o = 0u;
    for (i = 0u; i < width; i++, o += row->step) {
        const int64_t x0 = (int64_t)p0[o] - 32768, x1 = (int64_t)p1[o] - 32768;
        const int64_t x2 = (int64_t)p2[o] - 32768;
        const bool masked = mask && p0[o] == kl->nodata && p1[o] == kl->nodata &&
                            p2[o] == kl->nodata;
        for (k = 0u; k < 3u; k++) {
            if (out[k] != NULL) {
                /* |sum| <= 3 2^30 2^15 + 2^60 */
                const int64_t acc = kl->w[k][0] * x0 + kl->w[k][1] * x1 + kl->w[k][2] * x2 + kl->b[k];
                out[k][i] = masked ? (uint16_t)SSDA_KL_NODATA
                                   : clamp_z(acc, kl->shift, kl->out_max, &clamped);
            }
        }
    }
    return clamped;
}

int ssda_kl_transform_row(const ssda_kl_t *kl, const ssda_kl_row_t *row, uint32_t width,
                          uint16_t *const out[3], uint32_t *clamped)
{
    uint32_t n;
    if (kl == NULL || row == NULL || out == NULL || row->band[0] == NULL ||
        row->band[1] == NULL || row->band[2] == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(kl->magic, SSDA__MAGIC_KL)) {
        return SSDA_ERR_STATE;
    }
    if (width == 0u || width > SSDA_MAX_DIM) {
        return SSDA_ERR_SIZE;
    }
    if (row->step == 0u) {
        return SSDA_ERR_ARG;
    }
    n = kl->format == (uint8_t)SSDA_PIX_U8 ? row_u8(kl, row, width, out)
                                           : row_u16(kl, row, width, out);
    if (clamped != NULL) {
        *clamped = *clamped > UINT32_MAX - n ? UINT32_MAX : *clamped + n;
    }
    return SSDA_OK;
}
