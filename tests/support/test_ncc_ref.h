/*
 * test_ncc_ref.h - independent references for the correlation search
 * (ssda/ncc.h), written without the library's code: rho in double precision
 * by the two-pass textbook formula, and an exhaustive integer search whose
 * comparisons use a schoolbook multi-limb product of its own.
 */
#ifndef SSDA_TEST_NCC_REF_H
#define SSDA_TEST_NCC_REF_H
#include <stdbool.h>
#include <stdint.h>
#include "ssda/view.h"

/* rho of the window at (x, y), two passes (means first), double; 0 when
   either side is flat. */
double test_ncc_rho(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y);

/* Exact integer terms of the placement: num = n Saw - Sa Sw, var = n Saa - Sa^2. */
typedef struct {
    int64_t num;
    uint64_t var;
} test_ncc_key_t;
test_ncc_key_t test_ncc_key(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y);

/* -1, 0, 1 as rho(a) <, =, > rho(b) (|rho| when abs), exactly. */
int test_ncc_cmp(test_ncc_key_t a, test_ncc_key_t b, bool abs);

/* Exhaustive best by rho (|rho|), ties to the smallest y then x, over the
   positions with (x - cx)^2 + (y - cy)^2 <= r2 (all positions when r2 < 0). */
void test_ncc_best(const ssda_view_t *area, const ssda_view_t *win, bool abs,
                   int64_t cx, int64_t cy, int64_t r2, uint32_t *bx, uint32_t *by);

/* trunc(rho * 2^30) from the double reference. */
int64_t test_ncc_q30(const ssda_view_t *area, const ssda_view_t *win, uint32_t x, uint32_t y);

#endif
