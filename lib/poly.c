/* poly.c - polynomial maps: domain, identity, exact evaluation. */
#include "poly_internal.h"

const uint8_t ssda__poly_ex[SSDA_POLY_MAX_TERMS] = {0u, 1u, 0u, 2u, 1u, 0u, 3u, 2u, 1u, 0u};
const uint8_t ssda__poly_ey[SSDA_POLY_MAX_TERMS] = {0u, 0u, 1u, 0u, 1u, 2u, 0u, 1u, 2u, 3u};

void ssda__poly_domain(uint32_t size, int32_t *centre, uint8_t *k)
{
    const uint32_t c = size / 2u; /* a constant divisor: a shift */
    const uint32_t reach = c > size - 1u - c ? c : size - 1u - c;
    uint8_t kk = 0u;
    while (((uint32_t)1u << kk) < reach) {
        kk++;
    }
    *centre = (int32_t)c;
    *k = kk;
}

bool ssda__poly_valid(const ssda_poly_t *p)
{
    return p->order >= 1u && p->order <= SSDA_POLY_MAX_ORDER && p->kx <= 16u && p->ky <= 16u;
}

int ssda_poly_init(ssda_poly_t *poly, uint16_t ref_w, uint16_t ref_h, uint8_t order)
{
    ssda_poly_t p = {{0}, {0}, 0, 0, 0u, 0u, 0u, 0u, 0u};
    if (poly == NULL) {
        return SSDA_ERR_NULL;
    }
    if (ref_w == 0u || ref_h == 0u) {
        return SSDA_ERR_SIZE;
    }
    if (order < 1u || order > SSDA_POLY_MAX_ORDER) {
        return SSDA_ERR_ARG;
    }
    ssda__poly_domain(ref_w, &p.cx, &p.kx);
    ssda__poly_domain(ref_h, &p.cy, &p.ky);
    p.order = order;
    p.ref_w = ref_w;
    p.ref_h = ref_h;
    p.u_q24[0] = (int64_t)p.cx * ssda__pow2(24u);
    p.u_q24[1] = ssda__pow2((uint32_t)p.kx + 24u);
    p.v_q24[0] = (int64_t)p.cy * ssda__pow2(24u);
    p.v_q24[2] = ssda__pow2((uint32_t)p.ky + 24u);
    *poly = p;
    return SSDA_OK;
}

ssda__i128_t ssda__poly_p(const ssda_poly_t *p, const int64_t *c, int32_t dx, int32_t dy)
{
    const uint32_t terms = SSDA_POLY_TERMS(p->order);
    ssda__i128_t sum = {0u, 0u}; /* hi, lo */
    uint32_t t;
    for (t = 0u; t < terms; t++) {
        const uint32_t i = ssda__poly_ex[t], j = ssda__poly_ey[t];
        /* dx^i dy^j: |.| <= (2^17 + 3)^3 < 2^52 */
        int64_t m = 1;
        uint32_t e;
        for (e = 0u; e < i; e++) {
            m *= dx;
        }
        for (e = 0u; e < j; e++) {
            m *= dy;
        }
        /* |c| < 2^63, |m| < 2^(i (kx+1) + j (ky+1) + 1): the shifted product
           is below 2^(63 + 48 + i + j + 1) <= 2^115 */
        sum = ssda__w_add(sum, ssda__u128_shl(ssda__w_mul64(c[t], m),
                                           48u - i * p->kx - j * p->ky));
    }
    return sum;
}

void ssda__poly_fd_start(const ssda_poly_t *p, const int64_t *c, int32_t dx0, int32_t dy,
                         ssda__poly_fd_t *fd)
{
    const ssda__i128_t p0 = ssda__poly_p(p, c, dx0, dy);
    const ssda__i128_t p1 = ssda__poly_p(p, c, dx0 + 1, dy);
    const ssda__i128_t p2 = ssda__poly_p(p, c, dx0 + 2, dy);
    const ssda__i128_t p3 = ssda__poly_p(p, c, dx0 + 3, dy);
    const ssda__i128_t e1 = ssda__w_sub(p1, p0), e2 = ssda__w_sub(p2, p1), e3 = ssda__w_sub(p3, p2);
    const ssda__i128_t f1 = ssda__w_sub(e2, e1), f2 = ssda__w_sub(e3, e2);
    fd->d[0] = p0;
    fd->d[1] = e1;
    fd->d[2] = f1;
    fd->d[3] = ssda__w_sub(f2, f1);
}

/* floor(P / 2^64) (P's high word, signed) as int32, if it fits. */
static bool poly_q8_of(ssda__i128_t pv, int32_t *out)
{
    const ssda__i128_t q = {ssda__w_neg_p(pv) ? UINT64_MAX : 0u, pv.hi}; /* hi, lo */
    const int64_t v = ssda__i128_to64(q);
    if (v < INT32_MIN || v > INT32_MAX) {
        return false;
    }
    *out = (int32_t)v;
    return true;
}

int ssda_poly_eval(const ssda_poly_t *poly, int32_t x, int32_t y, int32_t *u_q8,
                   int32_t *v_q8)
{
    int64_t dx, dy;
    int32_t u, v;
    if (poly == NULL || u_q8 == NULL || v_q8 == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__poly_valid(poly)) {
        return SSDA_ERR_ARG;
    }
    dx = (int64_t)x - poly->cx;
    dy = (int64_t)y - poly->cy;
    if (dx < -ssda__pow2((uint32_t)poly->kx + 1u) || dx > ssda__pow2((uint32_t)poly->kx + 1u) ||
        dy < -ssda__pow2((uint32_t)poly->ky + 1u) || dy > ssda__pow2((uint32_t)poly->ky + 1u)) {
        return SSDA_ERR_SIZE;
    }
    if (!poly_q8_of(ssda__poly_p(poly, poly->u_q24, (int32_t)dx, (int32_t)dy), &u) ||
        !poly_q8_of(ssda__poly_p(poly, poly->v_q24, (int32_t)dx, (int32_t)dy), &v)) {
        return SSDA_ERR_OVERFLOW;
    }
    *u_q8 = u;
    *v_q8 = v;
    return SSDA_OK;
}
