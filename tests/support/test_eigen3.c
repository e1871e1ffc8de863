/* test_eigen3.c - closed-form symmetric 3 x 3 eigen-solver (test_eigen3.h). */
#include "test_eigen3.h"

#include <math.h>

#define PI 3.14159265358979323846

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void eigenvalues(const double a[3][3], double l[3])
{
    const double p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    double p2, p, b[3][3], r, phi, det;
    int i, j;
    if (p1 == 0.0) {
        l[0] = a[0][0];
        l[1] = a[1][1];
        l[2] = a[2][2];
    } else {
        p2 = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) +
             (a[2][2] - q) * (a[2][2] - q) + 2.0 * p1;
        p = sqrt(p2 / 6.0);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                b[i][j] = (a[i][j] - (i == j ? q : 0.0)) / p;
            }
        }
        det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
              b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
              b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
        r = det / 2.0;
        phi = r <= -1.0 ? PI / 3.0 : r >= 1.0 ? 0.0 : acos(r) / 3.0;
        l[0] = q + 2.0 * p * cos(phi);
        l[2] = q + 2.0 * p * cos(phi + 2.0 * PI / 3.0);
        l[1] = 3.0 * q - l[0] - l[2];
    }
    /* decreasing */
    for (i = 0; i < 3; i++) {
        for (j = i + 1; j < 3; j++) {
            if (l[j] > l[i]) {
                const double t = l[i];
                l[i] = l[j];
                l[j] = t;
            }
        }
    }
}

void test_eigen3(const double a[3][3], double lambda[3], double vec[3][3])
{
    int k, i, j;
    eigenvalues(a, lambda);
    for (k = 0; k < 3; k++) {
        double m[3][3], best[3] = {0, 0, 0}, bn = -1.0, big = 0.0;
        int kb = 0;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                m[i][j] = a[i][j] - (i == j ? lambda[k] : 0.0);
            }
        }
        for (i = 0; i < 3; i++) {
            double c[3];
            cross(m[i], m[(i + 1) % 3], c);
            if (dot(c, c) > bn) {
                bn = dot(c, c);
                best[0] = c[0];
                best[1] = c[1];
                best[2] = c[2];
            }
        }
        bn = sqrt(bn);
        for (i = 0; i < 3; i++) {
            vec[k][i] = bn > 0.0 ? best[i] / bn : (i == k ? 1.0 : 0.0);
            if (fabs(vec[k][i]) > big + 1e-12) {
                big = fabs(vec[k][i]);
                kb = i;
            }
        }
        if (vec[k][kb] < 0.0) {
            for (i = 0; i < 3; i++) {
                vec[k][i] = -vec[k][i];
            }
        }
    }
}
