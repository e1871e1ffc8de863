/*
 * poly_internal.h - internal: the exact integer form of a polynomial map
 * (poly.h) and its forward differences along a row, shared by the
 * evaluation, the fit and the warp.
 */
#ifndef SSDA_POLY_INTERNAL_H
#define SSDA_POLY_INTERNAL_H

#include "ssda/poly.h"
#include "wide.h"

/* Exponents of xn (i) and yn (j) of each term, in poly.h's order. */
SSDA_INTERNAL extern const uint8_t ssda__poly_ex[SSDA_POLY_MAX_TERMS];
SSDA_INTERNAL extern const uint8_t ssda__poly_ey[SSDA_POLY_MAX_TERMS];

/* Domain of a ref_w x ref_h grid: centre and power-of-two scale, one axis. */
SSDA_INTERNAL void ssda__poly_domain(uint32_t size, int32_t *centre, uint8_t *k);

/* A map's order and scales are in range (a zero-filled map is not). */
SSDA_INTERNAL bool ssda__poly_valid(const ssda_poly_t *p);

/* P(x, y) = 2^64 * 256 * (moving x or y) exactly, for coefficients c (the
   map's u_q24 or v_q24), at dx = X - cx, dy = Y - cy with
   |dx| <= 2^(kx+1) + 3, |dy| <= 2^(ky+1) + 3: every term is below 2^118,
   the sum below 2^122. */
SSDA_INTERNAL ssda__i128_t ssda__poly_p(const ssda_poly_t *p, const int64_t *c, int32_t dx,
                                     int32_t dy);

/* Forward differences of P along a row: d[0] = P(x0), d[k] = the k-th
   difference at x0 (d[3] constant: the row is a cubic in x). */
typedef struct {
    ssda__i128_t d[4];
} ssda__poly_fd_t;

/* Start the differences of coefficients c at (dx0, dy): from P at
   dx0 .. dx0 + 3, so stepping them gives P exactly. */
SSDA_INTERNAL void ssda__poly_fd_start(const ssda_poly_t *p, const int64_t *c, int32_t dx0,
                                       int32_t dy, ssda__poly_fd_t *fd);

/* P(x0 + 1) from P(x0): three 128-bit additions (exact). */
static inline void ssda__poly_fd_step(ssda__poly_fd_t *fd)
{
    fd->d[0] = ssda__w_add(fd->d[0], fd->d[1]);
    fd->d[1] = ssda__w_add(fd->d[1], fd->d[2]);
    fd->d[2] = ssda__w_add(fd->d[2], fd->d[3]);
}

#endif /* SSDA_POLY_INTERNAL_H */
