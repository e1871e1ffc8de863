/* fourier_internal.h - shared by lib/fourier*.c and lib/symreg*.c. */
#ifndef SSDA_FOURIER_INTERNAL_H
#define SSDA_FOURIER_INTERNAL_H

#include "compiler.h"

#include "ssda/fourier.h"

/* floor(num 2^exp2 2^16 / den) saturated at UINT32_MAX; den > 0, exp2 in
   -64..64. Relative error < 2^-31 from narrowing den to 32 bits. */
SSDA_INTERNAL uint32_t ssda__ratio_q16(uint64_t num, int32_t exp2, uint64_t den);

/* floor(a * b / 2^s) saturated at UINT32_MAX. */
SSDA_INTERNAL uint32_t ssda__mulshr_sat(uint32_t a, uint32_t b, uint32_t s);

/* A lower bound of the unconstrained match's E^2 (Q16) without the search:
   |Z(alpha)| <= sum |a_n| |b_n| (Cauchy-Schwarz per term). Same orders. */
SSDA_INTERNAL uint32_t ssda__fd_e2_bound(const ssda_fd_t *a, const ssda_fd_t *b);

/* A lower bound of ssda_fd_match_fixed's E^2 (Q16) for scale s_q16 (1..2^24)
   and any rotation, without the search. Same orders. */
SSDA_INTERNAL uint32_t ssda__fd_fixed_bound(const ssda_fd_t *a, const ssda_fd_t *b, uint32_t s_q16);

/* |a| for a complex coefficient, Q8 px (isqrt, floor). */
SSDA_INTERNAL uint32_t ssda__fd_abs(const ssda_fd_coef_t *c);

#endif /* SSDA_FOURIER_INTERNAL_H */
