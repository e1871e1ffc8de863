/* ncc.c - correlation search: validation, exact rho arithmetic, probes. */
#include "ncc_internal.h"
#include "kernel/kernels.h"
#include "wide.h"
#include "fixmath.h"
#include "view_pair.h"

int ssda__ncc_check_pair(const ssda_view_t *area, const ssda_view_t *window)
{
    int err = ssda__view_check_pair(area, window);
    if (err != SSDA_OK) {
        return err;
    }
    if (window->width > area->width || window->height > area->height ||
        (uint32_t)window->width * window->height > SSDA_NCC_MAX_PIXELS) {
        return SSDA_ERR_SIZE;
    }
    return SSDA_OK;
}

/* Sum and sum of squares of n samples of a row: s <= 65535 * 65535 < 2^32,
   ss <= 65535 * 65535^2 < 2^48 (callers add at most 65536 pixels in all). */
static void row_sums(const uint8_t *p, uint8_t format, uint32_t n, uint32_t *s, uint64_t *ss)
{
    uint32_t i;
    uint32_t a = 0u;
    uint64_t q = 0u;
    if (format == (uint8_t)SSDA_PIX_U8) {
        for (i = 0u; i < n; i++) {
            const uint32_t sq = (uint32_t)p[i] * p[i];
            a += p[i];
            q += sq;
        }
    } else {
        const uint16_t *p16 = (const uint16_t *)(const void *)p;
        for (i = 0u; i < n; i++) {
            const uint32_t sq = (uint32_t)p16[i] * p16[i]; /* < 2^32 */
            a += p16[i];
            q += sq;
        }
    }
    *s += a;
    *ss += q;
}

void ssda__ncc_window(const ssda_view_t *window, ssda__ncc_win_t *w, uint64_t *ops)
{
    uint32_t r;
    w->n = (uint32_t)window->width * window->height;
    w->sw = 0u;
    w->sww = 0u;
    for (r = 0u; r < window->height; r++) {
        row_sums(ssda_view_row(window, r), window->format, window->width, &w->sw, &w->sww);
    }
    /* n * Sww <= 2^16 * 65536 * 65535^2 < 2^64 and >= Sw^2 (Cauchy-Schwarz) */
    w->var_w = (uint64_t)w->n * w->sww - (uint64_t)w->sw * w->sw;
    *ops += 2u * (uint64_t)w->n;
}

int64_t ssda__ncc_num(uint32_t n, uint64_t saw, uint32_t sa, uint32_t sw)
{
    const uint64_t p = (uint64_t)n * saw;  /* <= 2^16 * 2^16 * 65535^2 < 2^64 */
    const uint64_t q = (uint64_t)sa * sw;  /* < 2^64 */
    /* the difference is within +-2^62 (ncc.h), so both casts are exact */
    const uint64_t d = p >= q ? p - q : q - p;
    return p >= q ? (int64_t)d : -(int64_t)d;
}

void ssda__ncc_place(const ssda_view_t *area, const ssda_view_t *window,
                     const ssda__ncc_win_t *w, uint32_t x, uint32_t y,
                     ssda__ncc_key_t *key, uint64_t *ops)
{
    const uint32_t bpp = ssda_view_bpp(area);
    const uint8_t *a = ssda_view_row(area, y) + (size_t)x * bpp;
    uint64_t saw;
    uint64_t saa = 0u; /* <= n * m^2 < 2^48 */
    uint32_t sa = 0u;  /* <= n * m < 2^32 */
    uint32_t r;
    for (r = 0u; r < window->height; r++) {
        row_sums(a + (size_t)r * area->stride, area->format, window->width, &sa, &saa);
    }
    if (area->format == (uint8_t)SSDA_PIX_U8) {
        saw = ssda__dot_u8(a, area->stride, (const uint8_t *)window->data, window->stride,
                           window->width, window->height);
    } else {
        saw = ssda__dot_u16((const uint16_t *)(const void *)a, area->stride,
                            (const uint16_t *)window->data, window->stride, window->width,
                            window->height);
    }
    key->var = (uint64_t)w->n * saa - (uint64_t)sa * sa; /* as var_w */
    key->num = key->var == 0u ? 0 : ssda__ncc_num(w->n, saw, sa, w->sw);
    *ops += 3u * (uint64_t)w->n;
}

/* |v| of a key's num (< 2^62). */
static uint64_t mag(int64_t v)
{
    return v < 0 ? (uint64_t)(-v) : (uint64_t)v;
}

/* The sign of rho (of |rho| when abs): -1, 0 or 1. */
static int rho_sign(int64_t num, bool abs)
{
    if (num == 0) {
        return 0;
    }
    return (num > 0 || abs) ? 1 : -1;
}

int ssda__ncc_cmp(const ssda__ncc_key_t *a, const ssda__ncc_key_t *b, bool abs)
{
    const int sa = rho_sign(a->num, abs);
    const int sb = rho_sign(b->num, abs);
    ssda__u192_t l, r;
    int c;
    if (sa != sb) {
        return sa < sb ? -1 : 1;
    }
    if (sa == 0) {
        return 0;
    }
    /* same sign, both non-zero (so both var > 0): |num_a|^2 * var_b against
       |num_b|^2 * var_a, each < 2^124 * 2^62 */
    l = ssda__mul_128x64(ssda__mul_64x64(mag(a->num), mag(a->num)), b->var);
    r = ssda__mul_128x64(ssda__mul_64x64(mag(b->num), mag(b->num)), a->var);
    c = ssda__cmp_192(&l, &r);
    return sa > 0 ? c : -c;
}

int32_t ssda__ncc_rho_q30(const ssda__ncc_key_t *k, uint64_t var_w)
{
    ssda__u128_t d, n2;
    ssda__u192_t rhs;
    uint32_t q = 0u;
    uint32_t bit;
    if (k->num == 0) {
        return 0; /* a flat side (num != 0 implies var, var_w > 0) */
    }
    /* the largest q with q^2 * var * var_w <= num^2 * 2^60, i.e.
       q = floor(|rho| * 2^30) <= 2^30; products < 2^62 * 2^124 */
    d = ssda__mul_64x64(k->var, var_w);
    n2 = ssda__mul_64x64(mag(k->num), mag(k->num)); /* < 2^124 */
    rhs.w0 = n2.lo << 60;
    rhs.w1 = (n2.hi << 60) | (n2.lo >> 4);
    rhs.w2 = n2.hi >> 4;
    for (bit = (uint32_t)1u << 30; bit != 0u; bit >>= 1) {
        const uint32_t t = q | bit; /* < 2^31 */
        const ssda__u192_t lhs = ssda__mul_128x64(d, (uint64_t)t * t);
        if (ssda__cmp_192(&lhs, &rhs) <= 0) {
            q = t;
        }
    }
    return k->num < 0 ? -(int32_t)q : (int32_t)q;
}

uint64_t ssda__ncc_work_need(uint32_t area_w, uint32_t win_w, uint32_t win_h)
{
    const uint32_t g = SSDA_DIV32(63u + win_w, win_w); /* setup only */
    const uint32_t ng = SSDA_DIV32(win_h + g - 1u, g);
    /* (M + 2) * nx * 12 + ng * 16 < 2^17 * 2^16 * 2^4: no overflow */
    return ((uint64_t)win_h + 2u) * ((uint64_t)area_w - win_w + 1u) * 12u + (uint64_t)ng * 16u;
}

/* Check the options against the geometry (the work size in 64 bits). */
static int check_config(const ssda_ncc_config_t *cfg, const ssda_view_t *area,
                        const ssda_view_t *window)
{
    if (cfg->metric > (uint8_t)SSDA_NCC_ABS ||
        (cfg->flags & (uint8_t)~(SSDA_NCC_FULL | SSDA_NCC_PREDICT | SSDA_NCC_DISK |
                                 SSDA_NCC_AROUND)) != 0u) {
        return SSDA_ERR_ARG;
    }
    if (cfg->work == NULL) {
        return SSDA_ERR_NULL;
    }
    if ((uint64_t)cfg->work_size < ssda__ncc_work_need(area->width, window->width, window->height) ||
        (((uintptr_t)cfg->work) & 7u) != 0u) {
        return SSDA_ERR_BUFFER;
    }
    return SSDA_OK;
}

int ssda_ncc_match(const ssda_view_t *area, const ssda_view_t *window,
                   const ssda_ncc_config_t *cfg, ssda_ncc_result_t *result)
{
    int err;
    if (area == NULL || window == NULL || cfg == NULL || result == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda__ncc_check_pair(area, window);
    if (err == SSDA_OK) {
        err = check_config(cfg, area, window);
    }
    if (err == SSDA_OK) {
        ssda__ncc_search(area, window, cfg, result);
    }
    return err;
}

int ssda_ncc_at(const ssda_view_t *area, const ssda_view_t *window,
                uint16_t x, uint16_t y, int32_t *rho_q30)
{
    ssda__ncc_win_t w;
    ssda__ncc_key_t k;
    uint64_t ops = 0u;
    int err;
    if (area == NULL || window == NULL || rho_q30 == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda__ncc_check_pair(area, window);
    if (err != SSDA_OK) {
        return err;
    }
    if ((uint32_t)x + window->width > area->width ||
        (uint32_t)y + window->height > area->height) {
        return SSDA_ERR_SIZE;
    }
    ssda__ncc_window(window, &w, &ops);
    ssda__ncc_place(area, window, &w, x, y, &k, &ops);
    *rho_q30 = ssda__ncc_rho_q30(&k, w.var_w);
    return SSDA_OK;
}
