/* match_quality.c - uniqueness and the sub-pixel fit of a search (see
   match_quality.h). */
#include "match_quality.h"
#include "kernel/kernels.h"
#include "fixmath.h"

#ifndef SSDA_CFG_NO_UNIQUE
uint64_t ssda__mul_q8(uint64_t v, uint16_t q8)
{
    /* v = vh 2^16 + vl: vh * q8 < 2^32 * 2^11 (< 2^59 shifted), vl * q8 < 2^27 */
    const uint64_t hi = ssda__mul_u32_u16((uint32_t)(v >> 16), q8);
    const uint32_t lo = (uint32_t)(v & 0xFFFFu) * q8; /* < 2^27: 32-bit */
    return ((hi << 16) + lo) >> 8;
}

uint16_t ssda__ratio_q8(uint64_t s, uint64_t b)
{
    uint64_t num = s << 8; /* <= 4 b * 256 < 2^58 */
    uint32_t q = 0u;       /* < 2^11 */
    uint32_t i;
    if (b == 0u) {
        return 256u;
    }
    for (i = 0u; i < 11u; i++) {
        const uint32_t bit = 10u - i; /* quotient bits, highest first */
        if ((b << bit) <= num) {      /* b << 10 < 2^58 */
            num -= b << bit;
            q |= 1u << bit;
        }
    }
    return (uint16_t)q;
}

#endif

#ifndef SSDA_CFG_NO_SUBPIXEL
int16_t ssda__vfit_q8(uint64_t l, uint64_t c, uint64_t r)
{
    uint64_t den = (l > r ? l : r) - c; /* >= |l - r|: c is the smallest */
    uint64_t num = l > r ? l - r : r - l;
    uint32_t q;
    if (c == 0u) {
        return 0; /* an exact match: the neighbours' asymmetry is the
                     window's border, not a fraction (see match.h) */
    }
    while (den >= 0x80000000u) {
        den >>= 1;
        num >>= 1;
    }
    if (den == 0u) {
        return 0;
    }
    /* round(128 num / den) = floor((256 num + den) / (2 den)): 256 num <
       2^39, 2 den < 2^32; the quotient <= 128 */
    q = SSDA_DIV64_32((num << 8) + den, (uint32_t)(2u * den));
    return (int16_t)(l >= r ? (int32_t)q : -(int32_t)q);
}

#endif

#ifndef SSDA_CFG_NO_UNIQUE
uint16_t ssda__unique_q8(const ssda__cand_t *list, uint32_t n, const ssda__cand_t *best,
                         uint16_t q8, uint32_t rad)
{
    const uint64_t lim = ssda__mul_q8(best->sad, q8); /* within the ratio: <= lim */
    uint32_t i;
    for (i = 0u; i < n && list[i].sad <= lim; i++) {
        const uint32_t ddx = list[i].x > best->x ? list[i].x - best->x : best->x - list[i].x;
        const uint32_t ddy = list[i].y > best->y ? list[i].y - best->y : best->y - list[i].y;
        if (ddx > rad || ddy > rad) {
            return ssda__ratio_q8(list[i].sad, best->sad);
        }
    }
    return (uint16_t)SSDA_MATCH_UNIQUE_NONE;
}
#endif

int ssda__sad_full(const ssda__rows_t *area, const ssda__rows_t *win, uint32_t x, uint32_t y,
                   uint64_t *ops, uint64_t *sad)
{
    uint64_t total = 0u; /* <= 65535^3 */
    uint32_t i, pixels;
    for (i = 0u; i < win->height; i++) {
        const uint8_t *ap;
        const uint8_t *wp;
        int err = ssda__rows_get(area, x, y + i, win->width, &ap);
        if (err == SSDA_OK) {
            err = ssda__rows_get(win, 0u, i, win->width, &wp);
        }
        if (err != SSDA_OK) {
            return err;
        }
#ifndef SSDA_CFG_NO_U16
        if (area->format != (uint8_t)SSDA_PIX_U8) {
            total += ssda__sad_row_u16((const uint16_t *)(const void *)ap,
                                       (const uint16_t *)(const void *)wp, win->width);
            continue;
        }
#endif
        total += ssda__sad_row_u8(ap, wp, win->width);
    }
    pixels = (uint32_t)win->width * win->height; /* < 2^32 */
    *ops += pixels;
    *sad = total;
    return SSDA_OK;
}

#ifndef SSDA_CFG_NO_SUBPIXEL
/* SAD of position (x, y): from the list when the search summed it in full,
   else summed now (L x M pixels added to *ops). */
static int sad_of(const ssda__rows_t *area, const ssda__rows_t *win, const ssda__cand_t *list,
                  uint32_t n, uint32_t x, uint32_t y, uint64_t *ops, uint64_t *sad)
{
    uint32_t i;
    for (i = 0u; i < n; i++) {
        if (list[i].x == x && list[i].y == y) {
            *sad = list[i].sad;
            return SSDA_OK;
        }
    }
    return ssda__sad_full(area, win, x, y, ops, sad);
}

/* The fit along one axis: neighbours (x0, y0) and (x1, y1) of best. */
static int fit_axis(const ssda__rows_t *area, const ssda__rows_t *win, const ssda__cand_t *list,
                    uint32_t n, const ssda__cand_t *best, uint32_t x0, uint32_t y0, uint32_t x1,
                    uint32_t y1, uint64_t *ops, int16_t *out)
{
    uint64_t a, b;
    int err = sad_of(area, win, list, n, x0, y0, ops, &a);
    if (err == SSDA_OK) {
        err = sad_of(area, win, list, n, x1, y1, ops, &b);
    }
    if (err == SSDA_OK) {
        *out = ssda__vfit_q8(a, best->sad, b);
    }
    return err;
}

int ssda__subpixel(const ssda__rows_t *area, const ssda__rows_t *win, const ssda__cand_t *list,
                   uint32_t n, const ssda__cand_t *best, uint32_t nx, uint32_t ny,
                   uint64_t *ops, int16_t *sub_x_q8, int16_t *sub_y_q8)
{
    const uint32_t bx = best->x, by = best->y;
    int err = SSDA_OK;
    *sub_x_q8 = 0;
    *sub_y_q8 = 0;
    if (bx > 0u && bx + 1u < nx) {
        err = fit_axis(area, win, list, n, best, bx - 1u, by, bx + 1u, by, ops, sub_x_q8);
    }
    if (err == SSDA_OK && by > 0u && by + 1u < ny) {
        err = fit_axis(area, win, list, n, best, bx, by - 1u, bx, by + 1u, ops, sub_y_q8);
    }
    return err;
}
#endif
