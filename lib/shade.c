/*
 * shade.c - the seed's shading function (shade.h): one-cycle projections
 * accumulated exactly row by row, the function's extremum, the correction.
 */
#include <string.h>
#include "ssda/shade.h"
#include "fixmath.h"
#include "wide.h"
#include "state.h"


/* floor(a * b / 2^30) for |a * b| < 2^62 (shifted as unsigned). */
static int64_t mul_q30(int64_t a, int64_t b)
{
    const int64_t prod = a * b;
    const uint64_t biased = (uint64_t)prod + (uint64_t)4611686018427387904u; /* + 2^62: >= 0 */
    const uint64_t q = biased >> 30;
    return (int64_t)q - (int64_t)4294967296; /* - 2^32 */
}

/* sin(2 pi phase / 2^32) in Q15 ([-32768, 32768]): quarter-wave symmetry
   and an odd 7th-order polynomial in t (t = 1: a quarter turn), fitted
   minimax on [0, 1] (0.02 LSB of Q15 off in 64-bit reference arithmetic; the rounding of the
   Q30 Horner steps adds under 0.01), so within 0.53 LSB of the true sine
   after the final rounding. t takes all 30 bits of the position in the
   quarter (keeping only its top 14 would put it up to 3.6 LSB off). */
static int32_t sin_q15(uint32_t phase)
{
    static const int64_t a1 = 1686624012, a3 = -693522229, a5 = 85292125, a7 = -4652721; /* Q30 */
    const uint32_t quarter = phase >> 30;           /* 0..3 */
    const uint32_t pos = phase & 0x3FFFFFFFu;       /* position in the quarter, Q30 */
    int64_t t = (int64_t)pos;
    int64_t t2, s;
    if ((quarter & 1u) != 0u) {
        t = (int64_t)0x40000000 - t; /* falling quarter: sin(pi - a); 1..2^30 */
    }
    t2 = mul_q30(t, t);                             /* <= 2^30 */
    s = a5 + mul_q30(a7, t2);                       /* Horner: |s| < 2^31, products < 2^62 */
    s = a3 + mul_q30(s, t2);
    s = a1 + mul_q30(s, t2);
    s = mul_q30(s, t);                              /* Q30, 0..2^30 */
    {
        const uint64_t su = (uint64_t)s + 16384u;   /* s >= 0 */
        const uint64_t q15 = su >> 15;              /* <= 2^15 */
        const int32_t r = (int32_t)q15;
        return (quarter & 2u) != 0u ? -r : r;
    }
}

/* The three basis values at phase: 1, cos, sin in Q15. */
static void basis(uint32_t phase, int32_t *b)
{
    b[0] = 32768;
    b[1] = sin_q15(phase + 0x40000000u);
    b[2] = sin_q15(phase);
}

int ssda_shade_init(ssda_shade_t *sh, uint16_t width, uint16_t height, uint8_t format)
{
    ssda_shade_t s;
    if (sh == NULL) {
        return SSDA_ERR_NULL;
    }
    if (width < 3u || height < 3u) {
        return SSDA_ERR_SIZE;
    }
    if (format != (uint8_t)SSDA_PIX_U8 && format != (uint8_t)SSDA_PIX_U16) {
        return SSDA_ERR_FORMAT;
    }
    (void)memset(&s, 0, sizeof s);
    s.width = width;
    s.height = height;
    s.format = format;
    /* round(2^32 / n) < 2^31 for n >= 3 */
    {
        const uint32_t hw = (uint32_t)width / 2u, hh = (uint32_t)height / 2u;
        const uint64_t nw = 0x100000000u + (uint64_t)hw, nh = 0x100000000u + (uint64_t)hh;
        s.step_x = SSDA_DIV64_32(nw, width);
        s.step_y = SSDA_DIV64_32(nh, height);
    }
    s.magic = SSDA__MAGIC_SHADE_OPEN;
    *sh = s;
    return SSDA_OK;
}

static ssda__i128_t load(const uint64_t *w)
{
    ssda__i128_t v;
    v.lo = w[0];
    v.hi = w[1];
    return v;
}

static void store(uint64_t *w, ssda__i128_t v)
{
    w[0] = v.lo;
    w[1] = v.hi;
}

int ssda_shade_add_row(ssda_shade_t *sh, const void *row)
{
    int64_t r[3] = {0, 0, 0}; /* |I f| < 2^31, w of them: < 2^47 */
    int32_t g[3];
    uint32_t x, phase = 0u, p, q;
    if (sh == NULL || row == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(sh->magic, SSDA__MAGIC_SHADE_OPEN) || (sh->images == UINT16_MAX)) {
        return SSDA_ERR_STATE;
    }
    for (x = 0u; x < sh->width; x++) {
        int32_t f[3];
        const int64_t v = sh->format == (uint8_t)SSDA_PIX_U8
                              ? (int64_t)((const uint8_t *)row)[x]
                              : (int64_t)((const uint16_t *)row)[x];
        basis(phase, f);
        r[0] += v * f[0];
        r[1] += v * f[1];
        r[2] += v * f[2];
        phase += sh->step_x;
    }
    basis(sh->step_y * sh->y, g);
    /* acc += r_p g_q: < 2^62 per row; <= 65535 rows of <= 65535 images:
       < 2^94 */
    for (p = 0u; p < 3u; p++) {
        for (q = 0u; q < 3u; q++) {
            store(sh->acc[p * 3u + q],
                  ssda__w_add(load(sh->acc[p * 3u + q]), ssda__w_mul64(r[p], g[q])));
        }
    }
    sh->y++;
    if (sh->y == sh->height) {
        sh->y = 0u;
        sh->images++;
    }
    return SSDA_OK;
}

/* S(x, y) in Q38 (K Q8 * f Q15 * g Q15): |K f g| <= 2^26 * 2^30, nine
   terms < 2^60. Summed as sum_p f_p (sum_q K_pq g_q), the order the rows
   use: the same integer. */
static int64_t s_q38_row(const ssda_shade_t *sh, const int64_t *h, uint32_t x)
{
    int32_t f[3];
    basis(sh->step_x * x, f);
    return h[0] * f[0] + h[1] * f[1] + h[2] * f[2];
}

/* sum_q K_pq g_q(y) for each p, Q23 (<= 3 * 2^26 * 2^15 < 2^43). */
static void row_terms(const ssda_shade_t *sh, uint32_t y, int64_t *h)
{
    int32_t g[3];
    uint32_t p;
    basis(sh->step_y * y, g);
    for (p = 0u; p < 3u; p++) {
        const size_t base = (size_t)p * 3u;
        const int32_t *k = &sh->k_q8[base];
        h[p] = (int64_t)k[0] * g[0] + (int64_t)k[1] * g[1] + (int64_t)k[2] * g[2];
    }
}

/* Q38 -> Q8, rounded (floor of + 2^29): |v| < 2^60, shifted as unsigned. */
static int32_t shade_q8_of(int64_t v)
{
    const int64_t q = mul_q30(v + 0x20000000, 1); /* + 2^29, floor / 2^30 */
    return (int32_t)q;
}

static int32_t s_at(const ssda_shade_t *sh, uint32_t x, uint32_t y)
{
    int64_t h[3];
    row_terms(sh, y, h);
    return shade_q8_of(s_q38_row(sh, h, x));
}

/* Climb from (x, y) to the extremum by steps halving to 1 (sign: +1 for
   the maximum, -1 for the minimum): move to the best of the 8 neighbours
   at the step while it is better (strictly), then halve. */
static void climb(const ssda_shade_t *sh, int32_t sign, uint32_t step, uint32_t *px, uint32_t *py)
{
    uint32_t x = *px, y = *py;
    int64_t best = (int64_t)sign * s_at(sh, x, y);
    while (step > 0u) {
        bool moved = true;
        while (moved) {
            uint32_t k, bx = x, by = y;
            moved = false;
            for (k = 0u; k < 9u; k++) {
                const uint32_t kx = k % 3u, ky = k / 3u;
                const int64_t nx = (int64_t)x + ((int64_t)kx - 1) * (int64_t)step;
                const int64_t ny = (int64_t)y + ((int64_t)ky - 1) * (int64_t)step;
                int64_t v;
                if (nx < 0 || ny < 0 || nx >= (int64_t)sh->width || ny >= (int64_t)sh->height) {
                    continue;
                }
                v = (int64_t)sign * s_at(sh, (uint32_t)nx, (uint32_t)ny);
                if (v > best) {
                    best = v;
                    bx = (uint32_t)nx;
                    by = (uint32_t)ny;
                    moved = true;
                }
            }
            x = bx;
            y = by;
        }
        step /= 2u;
    }
    *px = x;
    *py = y;
}

/* The extremum of S: the best point of a grid of about 32 x 32, then the
   climb. Ties: the first in raster order of the grid. */
static void find_centre(ssda_shade_t *sh, int32_t sign)
{
    const uint32_t sx = sh->width / 32u > 1u ? sh->width / 32u : 1u;
    const uint32_t sy = sh->height / 32u > 1u ? sh->height / 32u : 1u;
    uint32_t x, y, bx = 0u, by = 0u;
    int64_t best = -INT64_MAX;
    for (y = sy / 2u; y < sh->height; y += sy) {
        for (x = sx / 2u; x < sh->width; x += sx) {
            const int64_t v = (int64_t)sign * s_at(sh, x, y);
            if (v > best) {
                best = v;
                bx = x;
                by = y;
            }
        }
    }
    climb(sh, sign, sx > sy ? sx : sy, &bx, &by);
    sh->centre_x = (uint16_t)bx;
    sh->centre_y = (uint16_t)by;
    sh->centre_q8 = s_at(sh, bx, by);
}

int ssda_shade_finish(ssda_shade_t *sh, uint8_t mode)
{
    ssda__i128_t den;
    uint32_t p, q;
    if (sh == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(sh->magic, SSDA__MAGIC_SHADE_OPEN) || sh->images == 0u || sh->y != 0u) {
        return SSDA_ERR_STATE;
    }
    if (mode > (uint8_t)SSDA_SHADE_CENTRE_MIN) {
        return SSDA_ERR_ARG;
    }
    /* K = acc s_p s_q / (n w h 2^22): acc in Q30 grey, K in Q8 */
    den = ssda__u128_shl(ssda__w_mul64((int64_t)sh->images,
                                    (int64_t)sh->width * (int64_t)sh->height), 22u);
    for (p = 0u; p < 3u; p++) {
        for (q = 0u; q < 3u; q++) {
            int64_t s = 1; /* s_p s_q */
            if (p != 0u) {
                s *= 2;
            }
            if (q != 0u) {
                s *= 2;
            }
            /* |acc| <= n w h 65535 2^30, so |K| <= 4 * 65535 * 2^8 < 2^27 */
            sh->k_q8[p * 3u + q] = (int32_t)ssda__i128_to64(
                ssda__w_div_round(ssda__w_mul(load(sh->acc[p * 3u + q]), s), den));
        }
    }
    sh->magic = SSDA__MAGIC_SHADE_DONE;
    find_centre(sh, mode == (uint8_t)SSDA_SHADE_CENTRE_MAX ? 1 : -1);
    return SSDA_OK;
}

int ssda_shade_set_centre(ssda_shade_t *sh, uint16_t x, uint16_t y)
{
    if (sh == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(sh->magic, SSDA__MAGIC_SHADE_DONE)) {
        return SSDA_ERR_STATE;
    }
    if (x >= sh->width || y >= sh->height) {
        return SSDA_ERR_SIZE;
    }
    sh->centre_x = x;
    sh->centre_y = y;
    sh->centre_q8 = s_at(sh, x, y);
    return SSDA_OK;
}

int ssda_shade_eval(const ssda_shade_t *sh, uint32_t x, uint32_t y, int32_t *s_q8)
{
    if (sh == NULL || s_q8 == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(sh->magic, SSDA__MAGIC_SHADE_DONE)) {
        return SSDA_ERR_STATE;
    }
    if (x >= sh->width || y >= sh->height) {
        return SSDA_ERR_SIZE;
    }
    *s_q8 = s_at(sh, x, y);
    return SSDA_OK;
}

int ssda_shade_apply_row(const ssda_shade_t *sh, uint32_t y, const void *in, void *out)
{
    const int32_t max = sh != NULL && sh->format == (uint8_t)SSDA_PIX_U8 ? 255 : 65535;
    int64_t h[3];
    uint32_t x;
    if (sh == NULL || in == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(sh->magic, SSDA__MAGIC_SHADE_DONE)) {
        return SSDA_ERR_STATE;
    }
    if (y >= sh->height) {
        return SSDA_ERR_SIZE;
    }
    row_terms(sh, y, h);
    for (x = 0u; x < sh->width; x++) {
        const bool u8 = sh->format == (uint8_t)SSDA_PIX_U8;
        const int32_t v = u8 ? (int32_t)((const uint8_t *)in)[x] : (int32_t)((const uint16_t *)in)[x];
        /* 256 I - S + S(centre) + 128: |S| < 2^27, so within int32 */
        const int32_t t = v * 256 - shade_q8_of(s_q38_row(sh, h, x)) + sh->centre_q8 + 128;
        const int32_t o = t < 0 ? 0 : (t / 256 > max ? max : t / 256);
        if (u8) {
            ((uint8_t *)out)[x] = (uint8_t)o;
        } else {
            ((uint16_t *)out)[x] = (uint16_t)o;
        }
    }
    return SSDA_OK;
}
