/* symreg_internal.h - shared by lib/symreg*.c. */
#ifndef SSDA_SYMREG_INTERNAL_H
#define SSDA_SYMREG_INTERNAL_H

#include "compiler.h"

#include "ssda/symreg.h"

#define SSDA__NONE 0xFFFFu

/* A REF loop's partner in a pair set. */
typedef struct {
    uint16_t mov;    /* MOV loop, or SSDA__NONE */
    uint16_t pad;
    uint32_t e2;     /* its fixed-match E^2, Q16 */
} ssda__partner_t;

/* Eq. 16: MOV = s R(phi) (REF - (rx, ry)) + (mx, my); centroids Q8. */
SSDA_INTERNAL void ssda__symreg_similarity(uint32_t s_q16, uint32_t phi, int32_t rx, int32_t ry, int32_t mx,
                             int32_t my, ssda_symreg_affine_t *t);

/* Eqs. 14-15: sqrt|ae - bd| (Q16) and the mean rotation of the two axes. */
SSDA_INTERNAL void ssda__symreg_scale_rot(const ssda_symreg_affine_t *t, uint32_t *s_q16, uint32_t *phi);

/* Map (x, y) Q8 by t, in 64 bits (no saturation; |result| < 2^56). */
SSDA_INTERNAL void ssda__symreg_map(const ssda_symreg_affine_t *t, int32_t x, int32_t y, int64_t *u,
                      int64_t *v);

/* Eq. 17: least squares over the pairs of set (n_ref entries); false when
   fewer than 3 pairs, collinear, or a coefficient out of range. */
SSDA_INTERNAL bool ssda__symreg_fit(const ssda_loop_t *ref, const ssda_loop_t *mov,
                      const ssda__partner_t *set, uint32_t n_ref, ssda_symreg_affine_t *t);

/* |MOV centroid - t(REF centroid)|, Q8 px, saturated. */
SSDA_INTERNAL uint32_t ssda__symreg_resid(const ssda_symreg_affine_t *t, const ssda_loop_t *r,
                            const ssda_loop_t *m);

#endif /* SSDA_SYMREG_INTERNAL_H */
