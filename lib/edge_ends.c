/* edge_ends.c - ends of the thinned edges, their fitted directions, and the
   seed's extension along the edge strength (section 2 (d)). */
#include "edge_internal.h"
#include "fixtrig.h"

/* Unit vector (Q14) along the least-squares line of the walked pixels,
   pointing from the last fitted pixel towards the end. */
static void fit_direction(const ssda__walk_t *wk, uint32_t m, int16_t *ux, int16_t *uy)
{
    int32_t sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0; /* |offsets| < 16, m <= 16 */
    int32_t cxx, cxy, cyy, vx, vy, fx, fy;
    uint32_t i, theta;
    for (i = 0u; i < m; i++) {
        const int32_t dx = wk->x[i] - wk->x[0];
        const int32_t dy = wk->y[i] - wk->y[0];
        sx += dx;
        sy += dy;
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
    }
    /* m^2 times the covariances: |.| < 16 * 16 * 256 * 2 */
    cxx = (int32_t)m * sxx - sx * sx;
    cxy = (int32_t)m * sxy - sx * sy;
    cyy = (int32_t)m * syy - sy * sy;
    theta = ssda__atan2((int64_t)2 * cxy, (int64_t)cxx - cyy) >> 1; /* orientation, [0, 1/2) turn */
    fx = ssda__cos_q15(theta) / 2;
    fy = ssda__sin_q15(theta) / 2;
    vx = wk->x[0] - wk->x[m - 1u];
    vy = wk->y[0] - wk->y[m - 1u];
    if (fx * vx + fy * vy < 0) {
        fx = -fx;
        fy = -fy;
    }
    *ux = (int16_t)fx;
    *uy = (int16_t)fy;
}

uint32_t ssda__edge_ends(const uint16_t *map, uint32_t w, uint32_t h, uint32_t spur_min,
                         uint32_t fit_len, ssda__edge_end_t *ends, uint32_t cap)
{
    const uint32_t limit = spur_min > fit_len ? spur_min : fit_len;
    uint32_t x, y, n = 0u; /* n <= w * h */
    ssda__walk_t wk;
    for (y = 0u; y < h; y++) {
        const uint16_t *row = map + (size_t)y * w;
        for (x = 0u; x < w; x++) {
            if ((row[x] & SSDA_EDGE_ON) == 0u ||
                ssda__ring_class(ssda__edge_ring(map, w, h, x, y)) != (uint32_t)SSDA_EDGE_END) {
                continue;
            }
            ssda__edge_walk(map, w, h, x, y, limit, &wk);
            if (wk.n < spur_min || wk.n < 2u) {
                continue; /* a short spur or a speck: not an end (seed section 5) */
            }
            if (n < cap) {
                ends[n].x = (uint16_t)x;
                ends[n].y = (uint16_t)y;
                fit_direction(&wk, wk.n < fit_len ? wk.n : fit_len, &ends[n].ux, &ends[n].uy);
            }
            n++;
        }
    }
    return n;
}

/* Map entry at (x, y), or 0 outside the map. */
static uint16_t at(const uint16_t *map, uint32_t w, uint32_t h, int32_t x, int32_t y)
{
    if (x < 0 || y < 0 || (uint32_t)x >= w || (uint32_t)y >= h) {
        return 0u;
    }
    return map[(size_t)(uint32_t)y * w + (uint32_t)x];
}

/* First step out of an end: the way along the end pixel's edge direction
   that points ahead (positive along the fitted direction), or 8. */
static uint32_t first_step(uint16_t m, const ssda__edge_end_t *e)
{
    const uint32_t d = SSDA_EDGE_DIR(m);
    const int32_t dot = (int32_t)ssda__ring_dx[d] * e->ux + (int32_t)ssda__ring_dy[d] * e->uy;
    /* steps d and d + 4 run along the split line; a line across the
       fitted direction (|cos| < 0.38, 67.5 degrees) gives no way ahead */
    int32_t len = 16384; /* |step| in Q14: 1, or sqrt(2) for a diagonal */
    if ((d & 1u) != 0u) {
        len = 23170;
    }
    if (dot * 8 > len * 3) {
        return d;
    }
    if (-dot * 8 > len * 3) {
        return d + 4u;
    }
    return 8u;
}

/* Extend one end (seed (d) steps [1]-[3]); returns 1 if it grew or joined,
   and sets *joined when it reached another edge. */
static uint32_t extend_one(uint16_t *map, uint32_t w, uint32_t h, const ssda__edge_end_t *e,
                           uint32_t extend_min, uint32_t extend_max, uint32_t *joined)
{
    static const uint32_t order[3] = {0u, 1u, 7u}; /* straight, +45, -45 degrees */
    const uint32_t ring0 = ssda__edge_ring(map, w, h, e->x, e->y);
    int32_t x = (int32_t)e->x, y = (int32_t)e->y;
    uint32_t k = first_step(map[(size_t)e->y * w + e->x], e), steps = 0u;
    while (k < 8u && steps < extend_max) {
        uint32_t best = 8u, best_s = 0u, i;
        for (i = 0u; i < 3u; i++) {
            const uint32_t c = (k + order[i]) & 7u;
            const uint16_t m = at(map, w, h, x + ssda__ring_dx[c], y + ssda__ring_dy[c]);
            if ((m & SSDA_EDGE_ON) != 0u) {
                if (steps == 0u && ((ring0 >> c) & 1u) != 0u) {
                    continue; /* the end's own branch */
                }
                *joined += 1u; /* met another edge */
                return 1u;
            }
            if (best == 8u || SSDA_EDGE_STRENGTH(m) > best_s) { /* ties: listed order */
                best = c;
                best_s = SSDA_EDGE_STRENGTH(m);
            }
        }
        if (best == 8u) {
            break; /* only the end's own branch ahead */
        }
        {
            const uint16_t m = at(map, w, h, x + ssda__ring_dx[best], y + ssda__ring_dy[best]);
            if (best_s < extend_min || SSDA_EDGE_DIR(m) == ((best + 2u) & 3u)) {
                break; /* the edge fades, or runs across the step */
            }
        }
        x += ssda__ring_dx[best];
        y += ssda__ring_dy[best];
        {
            uint16_t *p = map + (size_t)(uint32_t)y * w + (uint32_t)x;
            /* go on along the new pixel's direction, the way closest to the
               step (a perpendicular direction stopped above) */
            const uint32_t d = SSDA_EDGE_DIR(*p);
            const uint32_t turn = (d + 8u - best) & 7u;
            *p = (uint16_t)(*p | SSDA_EDGE_ON);
            k = (turn <= 1u || turn >= 7u) ? d : d + 4u;
        }
        steps++;
    }
    return steps > 0u ? 1u : 0u;
}

void ssda__edge_extend(uint16_t *map, uint32_t w, uint32_t h, const ssda__edge_end_t *ends,
                       uint32_t n, uint32_t extend_min, uint32_t extend_max,
                       uint32_t *extended, uint32_t *joined)
{
    uint32_t i;
    for (i = 0u; i < n; i++) {
        /* an earlier extension may have joined this end already */
        if (ssda__ring_class(ssda__edge_ring(map, w, h, ends[i].x, ends[i].y)) ==
            (uint32_t)SSDA_EDGE_END) {
            *extended += extend_one(map, w, h, &ends[i], extend_min, extend_max, joined);
        }
    }
}
