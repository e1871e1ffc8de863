#include "test_ncc_ref.h"

#include "test_image.h"
#include "test_signal.h"

double test_ncc_rho(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y)
{
    double ma = 0.0, mw = 0.0, saw = 0.0, saa = 0.0, sww = 0.0;
    const double n = (double)win->width * win->height;
    uint32_t i, j;
    for (j = 0; j < win->height; j++) {
        for (i = 0; i < win->width; i++) {
            ma += test_px(area, x + i, y + j);
            mw += test_px(win, i, j);
        }
    }
    ma /= n;
    mw /= n;
    for (j = 0; j < win->height; j++) {
        for (i = 0; i < win->width; i++) {
            double a = test_px(area, x + i, y + j) - ma, w = test_px(win, i, j) - mw;
            saw += a * w;
            saa += a * a;
            sww += w * w;
        }
    }
    if (saa <= 0.0 || sww <= 0.0) {
        return 0.0;
    }
    return saw / test_sqrt(saa * sww);
}

test_ncc_key_t test_ncc_key(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y)
{
    uint64_t sa = 0, sw = 0, saa = 0, saw = 0, n = (uint64_t)win->width * win->height;
    uint32_t i, j;
    test_ncc_key_t k;
    for (j = 0; j < win->height; j++) {
        for (i = 0; i < win->width; i++) {
            uint64_t a = test_px(area, x + i, y + j), w = test_px(win, i, j);
            sa += a;
            sw += w;
            saa += a * a;
            saw += a * w;
        }
    }
    k.var = n * saa - sa * sa;
    k.num = n * saw >= sa * sw ? (int64_t)(n * saw - sa * sw) : -(int64_t)(sa * sw - n * saw);
    if (k.var == 0) {
        k.num = 0;
    }
    return k;
}

/* Little-endian 16-bit limbs: out (na + nb limbs) = a * b. */
static void mul_limbs(const uint16_t *a, int na, const uint16_t *b, int nb, uint16_t *out)
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
        for (j = i + nb; carry != 0; j++) {
            uint32_t t = (uint32_t)out[j] + carry;
            out[j] = (uint16_t)t;
            carry = t >> 16;
        }
    }
}

static void to_limbs(uint64_t v, uint16_t *out)
{
    int i;
    for (i = 0; i < 4; i++) {
        out[i] = (uint16_t)(v >> (16 * i));
    }
}

/* |num|^2 * var as 12 limbs. */
static void square_times(uint64_t num, uint64_t var, uint16_t *out)
{
    uint16_t a[4], v[4], sq[8];
    to_limbs(num, a);
    to_limbs(var, v);
    mul_limbs(a, 4, a, 4, sq);
    mul_limbs(sq, 8, v, 4, out);
}

int test_ncc_cmp(test_ncc_key_t a, test_ncc_key_t b, bool abs)
{
    int sa = a.num > 0 ? 1 : (a.num < 0 ? -1 : 0);
    int sb = b.num > 0 ? 1 : (b.num < 0 ? -1 : 0);
    uint16_t l[12], r[12];
    int i;
    if (abs) {
        sa = sa != 0;
        sb = sb != 0;
    }
    if (sa != sb) {
        return sa < sb ? -1 : 1;
    }
    if (sa == 0) {
        return 0;
    }
    square_times(a.num < 0 ? (uint64_t)-a.num : (uint64_t)a.num, b.var, l);
    square_times(b.num < 0 ? (uint64_t)-b.num : (uint64_t)b.num, a.var, r);
    for (i = 11; i >= 0; i--) {
        if (l[i] != r[i]) {
            return (l[i] < r[i] ? -1 : 1) * sa;
        }
    }
    return 0;
}

void test_ncc_best(const ssda_view_t *area, const ssda_view_t *win, bool abs,
                   int64_t cx, int64_t cy, int64_t r2, uint32_t *bx, uint32_t *by)
{
    uint32_t x, y;
    test_ncc_key_t best = {0, 0};
    int first = 1;
    for (y = 0; y + win->height <= area->height; y++) {
        for (x = 0; x + win->width <= area->width; x++) {
            test_ncc_key_t k;
            int64_t dx = (int64_t)x - cx, dy = (int64_t)y - cy;
            if (r2 >= 0 && dx * dx + dy * dy > r2) {
                continue;
            }
            k = test_ncc_key(area, win, x, y);
            /* raster order: strictly better only keeps the tie rule */
            if (first || test_ncc_cmp(k, best, abs) > 0) {
                best = k;
                *bx = x;
                *by = y;
                first = 0;
            }
        }
    }
}

int64_t test_ncc_q30(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y)
{
    return (int64_t)(test_ncc_rho(area, win, x, y) * 1073741824.0);
}
