/* kl_acc.c - exact band statistics of a 3-band image (kl.h). */
#include "kl_internal.h"

#include "fixmath.h"

#include <string.h>

int ssda_kl_acc_init(ssda_kl_acc_t *acc, const ssda_kl_acc_config_t *cfg)
{
    ssda_kl_acc_config_t c;
    if (acc == NULL) {
        return SSDA_ERR_NULL;
    }
    if (cfg != NULL) {
        c = *cfg;
    } else {
        (void)memset(&c, 0, sizeof c);
    }
    if (c.format == 0u) {
        c.format = (uint8_t)SSDA_PIX_U8;
    }
    if (c.format != (uint8_t)SSDA_PIX_U8 && c.format != (uint8_t)SSDA_PIX_U16) {
        return SSDA_ERR_FORMAT;
    }
    if ((c.flags & (uint8_t)~SSDA_KL_MASK_NODATA) != 0u ||
        (c.format == (uint8_t)SSDA_PIX_U8 && c.nodata > 255u)) {
        return SSDA_ERR_ARG;
    }
    (void)memset(acc, 0, sizeof *acc);
    acc->format = c.format;
    acc->flags = c.flags;
    acc->nodata = c.nodata;
    acc->magic = SSDA__MAGIC_KL_ACC;
    return SSDA_OK;
}

/* Sums of one row (a partial accumulator, added to acc on success). */
typedef struct {
    uint64_t sum[3];
    uint64_t sum_xy[6];
    uint32_t count, masked;
} row_sums_t;

/* 8-bit row: per-row sums fit 32 bits (<= 65535 * 255^2 < 2^32). */
static void sums_u8(const ssda_kl_acc_t *acc, const ssda_kl_row_t *row, uint32_t width,
                    row_sums_t *rs)
{
    const uint8_t *p0 = (const uint8_t *)row->band[0];
    const uint8_t *p1 = (const uint8_t *)row->band[1];
    const uint8_t *p2 = (const uint8_t *)row->band[2];
    const bool mask = (acc->flags & SSDA_KL_MASK_NODATA) != 0u;
    uint32_t s0 = 0u, s1 = 0u, s2 = 0u;                             /* < 2^24 */
    uint32_t q00 = 0u, q01 = 0u, q02 = 0u, q11 = 0u, q12 = 0u, q22 = 0u; /* < 2^32 */
    uint32_t i, n = 0u;
    size_t o = 0u;
    for (i = 0u; i < width; i++, o += row->step) {
        const uint32_t a = p0[o], b = p1[o], c = p2[o];
        if (mask && a == acc->nodata && b == acc->nodata && c == acc->nodata) {
            continue;
        }
        n++;
        s0 += a;
        s1 += b;
        s2 += c;
        q00 += a * a;
        q01 += a * b;
        q02 += a * c;
        q11 += b * b;
        q12 += b * c;
        q22 += c * c;
    }
    rs->sum[0] = s0;
    rs->sum[1] = s1;
    rs->sum[2] = s2;
    rs->sum_xy[0] = q00;
    rs->sum_xy[1] = q01;
    rs->sum_xy[2] = q02;
    rs->sum_xy[3] = q11;
    rs->sum_xy[4] = q12;
    rs->sum_xy[5] = q22;
    rs->count = n;
    rs->masked = width - n;
}

/* 16-bit row: band sums < 2^32 per row, products summed in 64 bits. */
static void sums_u16(const ssda_kl_acc_t *acc, const ssda_kl_row_t *row, uint32_t width,
                     row_sums_t *rs)
{
    const uint16_t *p0 = (const uint16_t *)row->band[0];
    const uint16_t *p1 = (const uint16_t *)row->band[1];
    const uint16_t *p2 = (const uint16_t *)row->band[2];
    const bool mask = (acc->flags & SSDA_KL_MASK_NODATA) != 0u;
    uint32_t i, n = 0u;
    size_t o = 0u;
    (void)memset(rs, 0, sizeof *rs);
    for (i = 0u; i < width; i++, o += row->step) {
        const uint32_t a = p0[o], b = p1[o], c = p2[o];
        if (mask && a == acc->nodata && b == acc->nodata && c == acc->nodata) {
            continue;
        }
        const uint32_t aa = a * a, ab = a * b, ac = a * c; /* each < 2^32 */
        const uint32_t bb = b * b, bc = b * c, cc = c * c;
        n++;
        rs->sum[0] += a;
        rs->sum[1] += b;
        rs->sum[2] += c;
        rs->sum_xy[0] += aa;
        rs->sum_xy[1] += ab;
        rs->sum_xy[2] += ac;
        rs->sum_xy[3] += bb;
        rs->sum_xy[4] += bc;
        rs->sum_xy[5] += cc;
    }
    rs->count = n;
    rs->masked = width - n;
}

static void add_sums(ssda_kl_acc_t *acc, const row_sums_t *rs)
{
    uint32_t k;
    for (k = 0u; k < 3u; k++) {
        acc->sum[k] += rs->sum[k]; /* < 2^32 * 65535 < 2^48 */
    }
    for (k = 0u; k < 6u; k++) {
        acc->sum_xy[k] += rs->sum_xy[k]; /* < 2^32 * 65535^2 < 2^64 */
    }
    acc->count += rs->count; /* checked below 2^32 by the caller */
    acc->masked = acc->masked > UINT32_MAX - rs->masked ? UINT32_MAX : acc->masked + rs->masked;
}

static void row_sums(const ssda_kl_acc_t *acc, const ssda_kl_row_t *row, uint32_t width,
                     row_sums_t *rs)
{
    if (acc->format == (uint8_t)SSDA_PIX_U8) {
        sums_u8(acc, row, width, rs);
    } else {
        sums_u16(acc, row, width, rs);
    }
}

int ssda_kl_acc_add_row(ssda_kl_acc_t *acc, const ssda_kl_row_t *row, uint32_t width)
{
    row_sums_t rs;
    if (acc == NULL || row == NULL || row->band[0] == NULL || row->band[1] == NULL ||
        row->band[2] == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(acc->magic, SSDA__MAGIC_KL_ACC)) {
        return SSDA_ERR_STATE;
    }
    if (width == 0u || width > SSDA_MAX_DIM) {
        return SSDA_ERR_SIZE;
    }
    if (row->step == 0u) {
        return SSDA_ERR_ARG;
    }
    if ((uint64_t)acc->count + width > UINT32_MAX) {
        return SSDA_ERR_OVERFLOW;
    }
    row_sums(acc, row, width, &rs);
    add_sums(acc, &rs);
    return SSDA_OK;
}

int ssda_kl_acc_add_source(ssda_kl_acc_t *acc, ssda_source_t *src, const ssda_rect_t *rect,
                           uint32_t channels)
{
    ssda_kl_acc_t work;
    ssda_rect_t r;
    uint32_t y;
    size_t bpp;
    if (acc == NULL || src == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(acc->magic, SSDA__MAGIC_KL_ACC) || src->cfg.width == 0u) {
        return SSDA_ERR_STATE;
    }
    if (src->cfg.format != acc->format) {
        return SSDA_ERR_FORMAT;
    }
    if (channels != 3u && channels != 4u) {
        return SSDA_ERR_ARG;
    }
    if (SSDA_MOD32((uint32_t)src->cfg.width, channels) != 0u) {
        return SSDA_ERR_SIZE;
    }
    if (rect != NULL) {
        r = *rect;
    } else {
        r.x = 0u;
        r.y = 0u;
        r.width = (uint16_t)SSDA_DIV32((uint32_t)src->cfg.width, channels);
        r.height = src->cfg.height;
    }
    if (r.width == 0u || r.height == 0u ||
        ((uint32_t)r.x + r.width) * channels > src->cfg.width ||
        (uint32_t)r.y + r.height > src->cfg.height) {
        return SSDA_ERR_SIZE;
    }
    if ((uint64_t)acc->count + (uint64_t)r.width * r.height > UINT32_MAX) {
        return SSDA_ERR_OVERFLOW;
    }
    work = *acc;
    bpp = (uint32_t)acc->format;
    for (y = r.y; y < (uint32_t)r.y + r.height; y++) {
        const uint8_t *px = NULL;
        ssda_kl_row_t row;
        row_sums_t rs;
        const int err = ssda_source_row(src, (uint32_t)r.x * channels, y,
                                         (uint32_t)r.width * channels, &px);
        if (err != SSDA_OK) {
            return err;
        }
        row.band[0] = px;
        row.band[1] = px + bpp;
        row.band[2] = px + (bpp + bpp);
        row.step = channels;
        row_sums(&work, &row, r.width, &rs);
        add_sums(&work, &rs);
    }
    *acc = work;
    return SSDA_OK;
}
