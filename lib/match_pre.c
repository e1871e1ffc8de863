/*
 * match_pre.c - a single search's bound tables, every position's group
 * bound at once, and the candidates summed first (match_pre.h).
 */
#include "match_pre.h"

#ifndef SSDA_CFG_NO_BOUNDS

/* |a - b| of two sums below 2^32 */
static SSDA_ALWAYS_INLINE uint32_t absdiff(uint32_t a, uint32_t b)
{
    return a > b ? a - b : b - a;
}

void ssda__pre_vstep(uint32_t *v, const uint8_t *row, bool u8, uint32_t n, bool add)
{
    uint32_t i;
    if (u8) {
        if (add) {
            for (i = 0u; i < n; i++) {
                v[i] += row[i];
            }
        } else {
            for (i = 0u; i < n; i++) {
                v[i] -= row[i];
            }
        }
    } else {
        const uint16_t *q = (const uint16_t *)(const void *)row;
        if (add) {
            for (i = 0u; i < n; i++) {
                v[i] += q[i];
            }
        } else {
            for (i = 0u; i < n; i++) {
                v[i] -= q[i];
            }
        }
    }
}

uint64_t ssda__pre_tables(const uint8_t *base, uint32_t stride, bool u8, uint32_t aw,
                          uint32_t ah, uint32_t L, uint32_t group, uint32_t *g, uint32_t *v)
{
    const uint32_t nx = aw - L + 1u;
    uint32_t y, i;
    uint64_t ops = (uint64_t)group * aw; /* the first vertical sums */
    for (i = 0u; i < aw; i++) {
        v[i] = 0u;
    }
    for (y = 0u; y < group; y++) {
        ssda__pre_vstep(v, base + (size_t)y * stride, u8, aw, true);
    }
    for (y = 0u; y + group <= ah; y++) {
        uint32_t *r = g + (size_t)y * nx;
        uint32_t s = 0u; /* <= group * L * 65535 < 2^32 (match_pre.h) */
        if (y > 0u) { /* v: rows y .. y + group - 1 (<= 4 * 65535) */
            ssda__pre_vstep(v, base + ((size_t)y + group - 1u) * stride, u8, aw, true);
            ssda__pre_vstep(v, base + ((size_t)y - 1u) * stride, u8, aw, false);
            ops += 2u * (uint64_t)aw;
        }
        for (i = 0u; i < L; i++) {
            s += v[i];
        }
        r[0] = s;
        for (i = 1u; i < nx; i++) {
            s += v[i + L - 1u] - v[i - 1u]; /* modulo 2^32: the sum ends exact */
            r[i] = s;
        }
        ops += L + 2u * ((uint64_t)nx - 1u);
    }
    return ops;
}

/* The smallest value in p[x0 .. x1 - 1] (x0 < x1): a loop a compiler
   vectorises. */
static uint32_t row_min(const uint32_t *p, uint32_t x0, uint32_t x1)
{
    uint32_t m = p[x0], x;
    for (x = x0 + 1u; x < x1; x++) {
        m = p[x] < m ? p[x] : m;
    }
    return m;
}

/* Start of tile t of n entries: ceil(t * n / TILES), t <= TILES, n < 2^16. */
static uint32_t tile_start(uint32_t t, uint32_t n)
{
    return (t * n + SSDA__PRE_TILES - 1u) / SSDA__PRE_TILES;
}

/* Row y's bounds into p (nx entries; rows y + k * group of g). */
static void row_bounds(const uint32_t *g, uint32_t pitch, uint32_t group, const uint32_t *w,
                       uint32_t ngroups, uint32_t nx, uint32_t y, uint32_t *p)
{
    const uint32_t *r = g + (size_t)y * pitch;
    const uint32_t w0 = w[0];
    uint32_t x, k;
    /* group after group along the row: loops over contiguous entries. A
       partial bound <= the bound < 2^32 - 1 (match_pre.h) */
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

void ssda__pre_sort(uint32_t n, uint32_t *cx, uint32_t *cy, uint32_t *cb)
{
    uint32_t i, j;
    for (i = 1u; i < n; i++) {
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
}

uint32_t ssda__pre_bounds(const uint32_t *g, uint32_t pitch, uint32_t group, const uint32_t *w,
                          uint32_t ngroups, uint32_t nx, uint32_t ny, uint32_t *pre,
                          uint32_t *rmin, uint32_t *cx, uint32_t *cy, uint32_t *cb)
{
    uint32_t n = 0u, tr, tc, y;
    for (tr = 0u; tr < SSDA__PRE_TILES; tr++) {
        const uint32_t y0 = tile_start(tr, ny), y1 = tile_start(tr + 1u, ny);
        const uint32_t n0 = n; /* this tile row's first candidate */
        for (y = y0; y < y1; y++) {
            uint32_t *p = pre + (size_t)y * nx;
            uint32_t m = UINT32_MAX;
            uint32_t slot = n0;
            row_bounds(g, pitch, group, w, ngroups, nx, y, p);
            /* each tile's smallest, read while the row is in the cache */
            for (tc = 0u; tc < SSDA__PRE_TILES; tc++) {
                const uint32_t x0 = tile_start(tc, nx), x1 = tile_start(tc + 1u, nx);
                uint32_t v;
                if (x0 >= x1) {
                    continue; /* an empty tile: fewer positions than tiles */
                }
                v = row_min(p, x0, x1);
                if (y == y0 || v < cb[slot]) { /* strictly: the first row wins a tie */
                    uint32_t x;
                    for (x = x0; p[x] != v; x++) {
                        /* its first place: v is in the range */
                    }
                    cb[slot] = v;
                    cx[slot] = x;
                    cy[slot] = y;
                }
                m = v < m ? v : m;
                slot++;
            }
            rmin[y] = m;
            n = slot;
        }
    }
    ssda__pre_sort(n, cx, cy, cb);
    return n;
}

#else
/* no bounds compiled in (a unit must declare something) */
typedef int ssda__match_pre_none_t;
#endif /* SSDA_CFG_NO_BOUNDS */
