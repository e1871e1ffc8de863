/*
 * ncc_internal.h - internal: the exact correlation arithmetic shared by the
 * search (ncc_search.c), its public entry points (ncc.c) and the composite
 * templates. Notation as in ssda/ncc.h: n pixels, num = n*Saw - Sa*Sw,
 * var = n*Saa - Sa^2.
 */
#ifndef SSDA_NCC_INTERNAL_H
#define SSDA_NCC_INTERNAL_H

#include "ssda/ncc.h"
#include "compiler.h"

/* A placement's correlation as an exact rational: rho = num / sqrt(var *
   var_w). var = 0 (flat placement) comes with num = 0 (rho = 0). */
typedef struct {
    int64_t num;  /* |num| <= n^2 m^2 / 4 < 2^62 */
    uint64_t var; /* var_a, < 2^62 */
} ssda__ncc_key_t;

/* The window's sums (m = the largest sample, n <= 65536 pixels). */
typedef struct {
    uint64_t sww;   /* <= n*m^2 < 2^48 */
    uint64_t var_w; /* n*Sww - Sw^2, < 2^62 */
    uint32_t sw;    /* <= n*m < 2^32 */
    uint32_t n;     /* L * M, 1..65536 */
} ssda__ncc_win_t;

/* Validate an area/window pair as ncc.h documents (formats, sizes,
   SSDA_NCC_MAX_PIXELS, SSDA_CFG_NO_U16). */
SSDA_INTERNAL int ssda__ncc_check_pair(const ssda_view_t *area, const ssda_view_t *window);

/* Sums of a valid window; adds 2 * n to *ops. */
SSDA_INTERNAL void ssda__ncc_window(const ssda_view_t *window, ssda__ncc_win_t *w, uint64_t *ops);

/* num from the products and the sums (exact, see the key's range). */
SSDA_INTERNAL int64_t ssda__ncc_num(uint32_t n, uint64_t saw, uint32_t sa, uint32_t sw);

/* The key of the placement at (x, y) (inside the area), summed directly:
   products, sums and squares, 3 * n operations added to *ops. */
SSDA_INTERNAL void ssda__ncc_place(const ssda_view_t *area, const ssda_view_t *window,
                     const ssda__ncc_win_t *w, uint32_t x, uint32_t y,
                     ssda__ncc_key_t *key, uint64_t *ops);

/* Compare two keys of the same window: -1, 0, 1 as rho(a) <, =, > rho(b)
   (|rho| when abs). Exact. */
SSDA_INTERNAL int ssda__ncc_cmp(const ssda__ncc_key_t *a, const ssda__ncc_key_t *b, bool abs);

/* rho in Q2.30 truncated toward zero; 0 when num is 0 (as it is when var
   or var_w is). */
SSDA_INTERNAL int32_t ssda__ncc_rho_q30(const ssda__ncc_key_t *k, uint64_t var_w);

/* The search of ssda_ncc_match (arguments validated by the caller). */
SSDA_INTERNAL void ssda__ncc_search(const ssda_view_t *area, const ssda_view_t *window,
                      const ssda_ncc_config_t *cfg, ssda_ncc_result_t *result);

#endif /* SSDA_NCC_INTERNAL_H */
