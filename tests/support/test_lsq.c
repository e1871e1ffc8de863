/* test_lsq.c - double-precision map references (test_lsq.h). */
#include "test_lsq.h"
#include "test_signal.h"

#define LSQ_MAX_N 1024u
#define LSQ_MAX_M 10u

static double pow_i(double v, unsigned e)
{
    double r = 1.0;
    while (e-- > 0u) {
        r *= v;
    }
    return r;
}

void test_poly_terms(const ssda_poly_t *p, double X, double Y, double *phi)
{
    static const unsigned ex[10] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0};
    static const unsigned ey[10] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3};
    const double xn = (X - p->cx) / (double)(1u << p->kx);
    const double yn = (Y - p->cy) / (double)(1u << p->ky);
    unsigned t;
    for (t = 0; t < 10u; t++) {
        phi[t] = pow_i(xn, ex[t]) * pow_i(yn, ey[t]);
    }
}

void test_poly_map(const ssda_poly_t *p, double X, double Y, double *x, double *y)
{
    double phi[10], su = 0.0, sv = 0.0;
    unsigned t, m = (unsigned)SSDA_POLY_TERMS(p->order);
    test_poly_terms(p, X, Y, phi);
    for (t = 0; t < m; t++) {
        su += (double)p->u_q24[t] / 16777216.0 * phi[t];
        sv += (double)p->v_q24[t] / 16777216.0 * phi[t];
    }
    *x = su;
    *y = sv;
}

int test_lsq_solve(const double *a, const double *b, size_t n, size_t m, double *c)
{
    static double r[LSQ_MAX_N * LSQ_MAX_M], q[LSQ_MAX_N];
    size_t i, j, k;
    if (n > LSQ_MAX_N || m > LSQ_MAX_M || n < m) {
        return -1;
    }
    for (i = 0; i < n * m; i++) {
        r[i] = a[i];
    }
    for (i = 0; i < n; i++) {
        q[i] = b[i];
    }
    for (k = 0; k < m; k++) {
        double norm = 0.0, s, vnorm = 0.0;
        for (i = k; i < n; i++) {
            norm += r[i * m + k] * r[i * m + k];
        }
        norm = test_sqrt(norm);
        if (norm == 0.0) {
            return -1;
        }
        s = r[k * m + k] > 0.0 ? -norm : norm; /* the reflection that avoids cancellation */
        r[k * m + k] -= s;                      /* v = x - s e1, stored in column k */
        for (i = k; i < n; i++) {
            vnorm += r[i * m + k] * r[i * m + k];
        }
        for (j = k + 1; j < m; j++) {
            double d = 0.0;
            for (i = k; i < n; i++) {
                d += r[i * m + k] * r[i * m + j];
            }
            d = 2.0 * d / vnorm;
            for (i = k; i < n; i++) {
                r[i * m + j] -= d * r[i * m + k];
            }
        }
        {
            double d = 0.0;
            for (i = k; i < n; i++) {
                d += r[i * m + k] * q[i];
            }
            d = 2.0 * d / vnorm;
            for (i = k; i < n; i++) {
                q[i] -= d * r[i * m + k];
            }
        }
        r[k * m + k] = s; /* R's diagonal */
    }
    for (k = m; k-- > 0;) {
        double v = q[k];
        for (j = k + 1; j < m; j++) {
            v -= r[k * m + j] * c[j];
        }
        if (r[k * m + k] == 0.0) {
            return -1;
        }
        c[k] = v / r[k * m + k];
    }
    return 0;
}

int test_poly_fit_double(const ssda_poly_pair_t *pairs, size_t n, const uint8_t *use,
                         uint16_t ref_w, uint16_t ref_h, uint8_t order, double *out_u,
                         double *out_v)
{
    static double a[LSQ_MAX_N * LSQ_MAX_M], bu[LSQ_MAX_N], bv[LSQ_MAX_N];
    ssda_poly_t dom;
    size_t k, rows = 0;
    const size_t m = SSDA_POLY_TERMS(order);
    if (ssda_poly_init(&dom, ref_w, ref_h, order) != SSDA_OK || n > LSQ_MAX_N) {
        return -1;
    }
    for (k = 0; k < n; k++) {
        double phi[10];
        size_t t;
        if (use != NULL && use[k] == 0u) {
            continue;
        }
        test_poly_terms(&dom, pairs[k].ref_x_q8 / 256.0, pairs[k].ref_y_q8 / 256.0, phi);
        for (t = 0; t < m; t++) {
            a[rows * m + t] = phi[t];
        }
        bu[rows] = pairs[k].mov_x_q8 / 256.0;
        bv[rows] = pairs[k].mov_y_q8 / 256.0;
        rows++;
    }
    if (test_lsq_solve(a, bu, rows, m, out_u) != 0 || test_lsq_solve(a, bv, rows, m, out_v) != 0) {
        return -1;
    }
    return 0;
}
