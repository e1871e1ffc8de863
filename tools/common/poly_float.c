/* poly_float.c - pixel-unit coefficients of polynomial maps (poly_float.h). */
#include "poly_float.h"

#include <math.h>
#include <string.h>

static const int ex[10] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0};
static const int ey[10] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3};

static int term_of(int i, int j)
{
    int t;
    for (t = 0; t < 10; t++) {
        if (ex[t] == i && ey[t] == j) {
            return t;
        }
    }
    return -1;
}

static double binom(int n, int k)
{
    static const double b[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    return b[n][k];
}

/* Coefficients of sum c_t (X + sx)^i (Y + sy)^j in powers of X, Y. */
static void shift_basis(const double *c, double sx, double sy, int terms, double *out)
{
    int t, a, b;
    memset(out, 0, 10 * sizeof *out);
    for (t = 0; t < terms; t++) {
        for (a = 0; a <= ex[t]; a++) {
            for (b = 0; b <= ey[t]; b++) {
                out[term_of(a, b)] += c[t] * binom(ex[t], a) * pow(sx, ex[t] - a) *
                                      binom(ey[t], b) * pow(sy, ey[t] - b);
            }
        }
    }
}

void poly_to_pixel(const ssda_poly_t *p, double *cx, double *cy)
{
    const int terms = (int)SSDA_POLY_TERMS(p->order);
    double u[10] = {0}, v[10] = {0};
    int t;
    /* in dX = X - cx: c / 2^24 / 2^(i kx + j ky) */
    for (t = 0; t < terms; t++) {
        const double s = ldexp(1.0, -24 - ex[t] * p->kx - ey[t] * p->ky);
        u[t] = (double)p->u_q24[t] * s;
        v[t] = (double)p->v_q24[t] * s;
    }
    shift_basis(u, -(double)p->cx, -(double)p->cy, terms, cx);
    shift_basis(v, -(double)p->cx, -(double)p->cy, terms, cy);
}

int poly_from_pixel(uint16_t ref_w, uint16_t ref_h, uint8_t order, const double *cx,
                    const double *cy, ssda_poly_t *p)
{
    double u[10], v[10];
    int t, err = ssda_poly_init(p, ref_w, ref_h, order);
    const int terms = (int)SSDA_POLY_TERMS(order);
    if (err != SSDA_OK) {
        return err;
    }
    /* X = dX + cx */
    shift_basis(cx, (double)p->cx, (double)p->cy, terms, u);
    shift_basis(cy, (double)p->cx, (double)p->cy, terms, v);
    for (t = 0; t < terms; t++) {
        const double s = ldexp(1.0, 24 + ex[t] * p->kx + ey[t] * p->ky);
        p->u_q24[t] = (int64_t)llround(u[t] * s);
        p->v_q24[t] = (int64_t)llround(v[t] * s);
    }
    return SSDA_OK;
}

void poly_eval_double(const ssda_poly_t *p, double X, double Y, double *x, double *y)
{
    const double xn = (X - p->cx) / ldexp(1.0, p->kx), yn = (Y - p->cy) / ldexp(1.0, p->ky);
    double su = 0, sv = 0;
    int t;
    for (t = 0; t < (int)SSDA_POLY_TERMS(p->order); t++) {
        const double m = pow(xn, ex[t]) * pow(yn, ey[t]) / 16777216.0;
        su += (double)p->u_q24[t] * m;
        sv += (double)p->v_q24[t] * m;
    }
    *x = su;
    *y = sv;
}
