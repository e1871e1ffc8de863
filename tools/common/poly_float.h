/*
 * poly_float.h - polynomial maps (ssda/poly.h) as floating-point
 * coefficients in plain pixel units, for the tools' JSON and for making
 * known maps: x = sum a_t X^i Y^j over the terms 1, X, Y, X^2, X Y, Y^2,
 * X^3, X^2 Y, X Y^2, Y^3 (X, Y: reference pixels, not centred).
 */
#ifndef SSDA_POLY_FLOAT_H
#define SSDA_POLY_FLOAT_H

#include "ssda/poly.h"

/* The map's coefficients in pixel units (terms beyond the order: 0). */
void poly_to_pixel(const ssda_poly_t *p, double *cx, double *cy);

/* A map of the given order on a ref_w x ref_h grid from pixel-unit
   coefficients (the inverse of poly_to_pixel, rounded to Q24). Returns an
   ssda error code. */
int poly_from_pixel(uint16_t ref_w, uint16_t ref_h, uint8_t order, const double *cx,
                    const double *cy, ssda_poly_t *p);

/* The map at (X, Y) in double (from its Q24 coefficients). */
void poly_eval_double(const ssda_poly_t *p, double X, double Y, double *x, double *y);

#endif /* SSDA_POLY_FLOAT_H */
