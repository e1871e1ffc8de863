/*
 * relax_internal.h - internal: a vector grid of ssda/relax.h, checked and
 * read (shared by the relaxation labelling and the median test).
 */
#ifndef SSDA_RELAX_INTERNAL_H
#define SSDA_RELAX_INTERNAL_H

#include "compiler.h"

#include "ssda/relax.h"

typedef struct {
    const uint8_t *dx, *dy, *status; /* vector 0's fields */
    size_t stride;
    uint32_t cols, rows, n;          /* n = cols * rows <= 65535^2 */
    uint32_t scale;                  /* 2^(8 - frac_bits): to Q8 */
} ssda__relax_t;

/* Check grid and the output array (SSDA_ERR_NULL/_SIZE/_ARG/_BUFFER as
   ssda/relax.h documents, every valid component in range) and fill *g. */
SSDA_INTERNAL int ssda__relax_open(const ssda_relax_grid_t *grid, const ssda_relax_vector_t *out,
                                   size_t out_count, ssda__relax_t *g);

/* Vector k in Q8 px (|.| <= 2^23); false when it is not valid. */
SSDA_INTERNAL bool ssda__relax_get(const ssda__relax_t *g, size_t k, int32_t *x, int32_t *y);

/* floor-toward-zero n / d for d > 0 and |n| / d < 2^32, without a 64-bit
   division routine on cores that lack a divide instruction. */
SSDA_INTERNAL int64_t ssda__relax_div(int64_t n, uint32_t d);

#endif /* SSDA_RELAX_INTERNAL_H */
