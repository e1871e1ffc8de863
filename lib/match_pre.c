/*
 * match_pre.c - every position's group bound at once, and the candidates
 * of a single search summed first (match_pre.h).
 */
#include "match_pre.h"

#ifndef SSDA_CFG_NO_BOUNDS

/* |a - b| of two sums below 2^32 */
static SSDA_ALWAYS_INLINE uint32_t absdiff(uint32_t a, uint32_t b)
{
    return a > b ? a - b : b - a;
}

void ssda__pre_groups(const uint32_t *g, uint32_t pitch, uint32_t group, const uint32_t *w,
                      uint32_t ngroups, uint32_t nx, uint32_t ny, uint32_t *pre)
{
    uint32_t x, y, k;
    for (y = 0u; y < ny; y++) {
        uint32_t *p = pre + (size_t)y * nx;
        const uint32_t *r = g + (size_t)y * pitch;
        const uint32_t w0 = w[0];
        /* group after group along the row: loops over contiguous entries.
           A partial bound <= the bound < 2^32 - 1 (match_pre.h) */
        for (x = 0u; x < nx; x++) {
            p[x] = absdiff(r[x], w0);
        }
        for (k = 1u; k < ngroups; k++) {
            const uint32_t wk = w[k];
            r = g + ((size_t)y + (size_t)k * group) * pitch;
            for (x = 0u; x < nx; x++) {
                p[x] += absdiff(r[x], wk);
            }
        }
    }
}

/* The first entry of the smallest value in p[x0 .. x1 - 1] (x0 < x1): its
   value in *v, its index returned. The minimum first (a loop a compiler
   vectorises), then its place. */
static uint32_t row_min(const uint32_t *p, uint32_t x0, uint32_t x1, uint32_t *v)
{
    uint32_t m = p[x0], x;
    for (x = x0 + 1u; x < x1; x++) {
        m = p[x] < m ? p[x] : m;
    }
    *v = m;
    for (x = x0; p[x] != m; x++) {
        /* m is in the range */
    }
    return x;
}

/* Start of tile t of n entries: ceil(t * n / TILES), t <= TILES, n < 2^16. */
static uint32_t tile_start(uint32_t t, uint32_t n)
{
    return (t * n + SSDA__PRE_TILES - 1u) / SSDA__PRE_TILES;
}

uint32_t ssda__pre_seeds(const uint32_t *pre, uint32_t nx, uint32_t ny, uint32_t *cx,
                         uint32_t *cy, uint32_t *cb)
{
    uint32_t n = 0u, tr, tc, y, i, j;
    for (tr = 0u; tr < SSDA__PRE_TILES; tr++) {
        const uint32_t y0 = tile_start(tr, ny), y1 = tile_start(tr + 1u, ny);
        for (tc = 0u; tc < SSDA__PRE_TILES; tc++) {
            const uint32_t x0 = tile_start(tc, nx), x1 = tile_start(tc + 1u, nx);
            bool any = false;
            if (x0 >= x1 || y0 >= y1) {
                continue; /* an empty tile: fewer positions than tiles */
            }
            for (y = y0; y < y1; y++) {
                uint32_t v;
                const uint32_t x = row_min(pre + (size_t)y * nx, x0, x1, &v);
                if (!any || v < cb[n]) { /* strictly: the first row wins a tie */
                    cb[n] = v;
                    cx[n] = x;
                    cy[n] = y;
                    any = true;
                }
            }
            n++;
        }
    }
    for (i = 1u; i < n; i++) { /* by bound, stable: insertion */
        for (j = i; j > 0u && cb[j] < cb[j - 1u]; j--) {
            uint32_t t = cb[j];
            cb[j] = cb[j - 1u];
            cb[j - 1u] = t;
            t = cx[j];
            cx[j] = cx[j - 1u];
            cx[j - 1u] = t;
            t = cy[j];
            cy[j] = cy[j - 1u];
            cy[j - 1u] = t;
        }
    }
    return n;
}

#else
/* no bounds compiled in (a unit must declare something) */
typedef int ssda__match_pre_none_t;
#endif /* SSDA_CFG_NO_BOUNDS */
