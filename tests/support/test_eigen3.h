/*
 * test_eigen3.h - a double-precision eigen-solver for symmetric 3 x 3
 * matrices, independent of the library's Jacobi: eigenvalues in closed
 * form (the trigonometric solution of the characteristic cubic, Smith
 * 1961), each eigenvector as the largest cross product of two rows of
 * A - lambda I, ordered by decreasing eigenvalue and signed as the library
 * does (largest-magnitude component positive).
 */
#ifndef SSDA_TEST_EIGEN3_H
#define SSDA_TEST_EIGEN3_H

/* a: symmetric. lambda: decreasing. vec[k]: unit eigenvector of lambda[k]
   (meaningless for an eigenvalue repeated within ~1e-9 of the largest). */
void test_eigen3(const double a[3][3], double lambda[3], double vec[3][3]);

#endif
