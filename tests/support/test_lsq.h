/*
 * test_lsq.h - double-precision references for the polynomial map tests:
 * the map's terms and value from poly.h's definition, and a least-squares
 * fit by Householder QR (written here from the textbook, sharing nothing
 * with lib/poly_fit.c's fixed-point normal equations).
 */
#ifndef SSDA_TEST_LSQ_H
#define SSDA_TEST_LSQ_H
#include <stddef.h>
#include <stdint.h>
#include "ssda/poly.h"

/* The normalised terms (poly.h's order) at reference position (X, Y) px. */
void test_poly_terms(const ssda_poly_t *p, double X, double Y, double *phi);

/* Moving x and y of the map at (X, Y), in double. */
void test_poly_map(const ssda_poly_t *p, double X, double Y, double *x, double *y);

/*
 * Least squares min |A c - b| for A n x m (row-major, n >= m, m <= 10,
 * n <= 1024) by Householder QR. Returns 0, or -1 if A is rank deficient.
 */
int test_lsq_solve(const double *a, const double *b, size_t n, size_t m, double *c);

/* Fit the map of the given order to pairs (those with use[k] != 0, or all
   if use is NULL) in double, on the same domain as ssda_poly_init(ref_w,
   ref_h): *out holds coefficients in double (out_u, out_v, terms of poly.h).
   Returns 0 or -1. */
int test_poly_fit_double(const ssda_poly_pair_t *pairs, size_t n, const uint8_t *use,
                         uint16_t ref_w, uint16_t ref_h, uint8_t order, double *out_u,
                         double *out_v);

#endif
