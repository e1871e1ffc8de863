/* kl_internal.h - internal: shared parts of the K-L transform (kl.h). */
#ifndef SSDA_KL_INTERNAL_H
#define SSDA_KL_INTERNAL_H

#include "ssda/kl.h"
#include "state.h"
#include "wide.h"


/* 1.0 in Q30. */
#define SSDA__ONE_Q30_KL 1073741824

/* The largest gain, output steps per sample step, Q16: 4096. */
#define SSDA__KL_GAIN_CAP_Q16 268435456u

/* Jacobi sweeps at most (a 3 x 3 matrix needs 4 to 6 in practice). */
#define SSDA__KL_MAX_SWEEPS 12u

/*
 * Diagonalise the symmetric Q30 matrix a (entries of magnitude < 2^32) in
 * place by cyclic Jacobi rotations; v receives the rotations' product
 * (columns: eigenvectors, Q30). Returns the sweeps run (1..12).
 */
SSDA_INTERNAL uint32_t ssda__kl_jacobi(int64_t a[3][3], int64_t v[3][3]);

/*
 * Eigenvectors and eigenvalues of the symmetric Q30 matrix a (destroyed):
 * Jacobi, then rows ordered by decreasing eigenvalue (ties: lower index),
 * renormalised to unit length, largest-magnitude component positive (ties:
 * the first); eigenvalues clamped at 0. Returns the sweeps run.
 */
SSDA_INTERNAL uint32_t ssda__kl_eigen(int64_t a[3][3], int32_t vec_q30[3][3],
                                      int64_t lambda_q30[3]);

/*
 * The per-pixel plan of kl (w, b, shift) for its range mode, from its
 * vectors, zvar_q16, out_max, nsigma and format, and the exact band means
 * sum / count (sum of acc).
 */
SSDA_INTERNAL void ssda__kl_plan(ssda_kl_t *kl, const uint64_t sum[3]);

#endif /* SSDA_KL_INTERNAL_H */
