/* edge_gap.c - the seed's closing of T, I and V gaps between ends
   (section 2 (e)), independent of the edge strength. */
#include "edge_internal.h"
#include "fixmath.h"
#include "fixtrig.h"

#include <string.h>

#define CONSUMED 0xFFFFu

/* The best closing of one pattern for an end. */
typedef struct {
    bool found;
    uint32_t dist;     /* px, max(|dx|, |dy|) from the end to the candidate */
    uint64_t cost;     /* I: triangle area, Q22 px^2; V: m, Q8 px */
    uint32_t partner;  /* index into ends (I, V) */
    int32_t x, y;      /* T: the edge pixel hit; V: the corner */
} pick_t;

static int32_t iabs32(int32_t v)
{
    return v < 0 ? -v : v;
}

static uint32_t cheb(int32_t dx, int32_t dy)
{
    const int32_t ax = iabs32(dx), ay = iabs32(dy);
    return (uint32_t)(ax > ay ? ax : ay);
}

/* Set (or clear) MARK on the end's own branch: the end, its neighbours and
   the first len pixels of its chain (not targets of its T ray). The walk
   reads ON bits only, so clearing retraces exactly what was set. */
static void mark_branch(uint16_t *map, uint32_t w, uint32_t h, const ssda__edge_end_t *e,
                        uint32_t len, bool set)
{
    ssda__walk_t wk;
    uint32_t i, k;
    ssda__edge_walk(map, w, h, e->x, e->y, len, &wk);
    for (k = 0u; k < 9u; k++) { /* the end's 3 x 3 (its run) */
        const int32_t x = (int32_t)e->x + (k < 8u ? ssda__ring_dx[k] : 0);
        const int32_t y = (int32_t)e->y + (k < 8u ? ssda__ring_dy[k] : 0);
        if (x >= 0 && y >= 0 && (uint32_t)x < w && (uint32_t)y < h) {
            uint16_t *p = map + (size_t)(uint32_t)y * w + (uint32_t)x;
            if ((*p & SSDA_EDGE_ON) != 0u) {
                *p = set ? (uint16_t)(*p | SSDA__EDGE_MARK) : (uint16_t)(*p & ~SSDA__EDGE_MARK);
            }
        }
    }
    for (i = 0u; i < wk.n; i++) {
        uint16_t *p = map + (size_t)(uint32_t)wk.y[i] * w + (uint32_t)wk.x[i];
        *p = set ? (uint16_t)(*p | SSDA__EDGE_MARK) : (uint16_t)(*p & ~SSDA__EDGE_MARK);
    }
}

/* round(a * b / m) for a, b >= 0, m > 0, a * b + m / 2 < 2^32 (no
   division routine on cores without a divide instruction). */
static int32_t scale_round(int32_t a, int32_t b, int32_t m)
{
    const uint32_t mag = (uint32_t)iabs32(a) * (uint32_t)iabs32(b);
    const uint32_t q = SSDA_DIV32(mag + (uint32_t)m / 2u, (uint32_t)m);
    return ((a < 0) != (b < 0)) ? -(int32_t)q : (int32_t)q;
}

/* T: walk a 4-connected digital ray from the end along its direction for
   gap px in the larger axis; the first ON pixel not on the end's own branch. */
static void find_t(const uint16_t *map, uint32_t w, uint32_t h, const ssda__edge_end_t *e,
                   int32_t gap, pick_t *t)
{
    const int32_t ax = iabs32(e->ux), ay = iabs32(e->uy);
    const int32_t m = ax > ay ? ax : ay; /* >= 11585 for a unit vector */
    const int32_t x0 = e->x, y0 = e->y;
    const int32_t x1 = x0 + scale_round(gap, e->ux, m); /* |gap * u| < 2^21 */
    const int32_t y1 = y0 + scale_round(gap, e->uy, m);
    const int32_t dx = iabs32(x1 - x0), dy = iabs32(y1 - y0);
    int32_t sx = -1, sy = -1;
    int32_t x = x0, y = y0, err = dx - dy, i;
    if (x1 > x0) {
        sx = 1;
    }
    if (y1 > y0) {
        sy = 1;
    }
    t->found = false;
    for (i = 0; i < dx + dy; i++) { /* one axis step at a time: 4-connected */
        uint16_t mv;
        if (2 * err > dy - dx) {
            err -= dy;
            x += sx;
        } else {
            err += dx;
            y += sy;
        }
        if (x < 0 || y < 0 || (uint32_t)x >= w || (uint32_t)y >= h) {
            return;
        }
        mv = map[(size_t)(uint32_t)y * w + (uint32_t)x];
        if ((mv & SSDA_EDGE_ON) != 0u && (mv & SSDA__EDGE_MARK) == 0u) {
            t->found = true;
            t->dist = cheb(x - x0, y - y0);
            t->x = x;
            t->y = y;
            return;
        }
    }
}

/* Q14 cross and dot products of (ax, ay) and (bx, by). */
static int64_t cross(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    return ax * by - ay * bx;
}

/* Angle between two vectors, turns in [0, 1/2]. */
static uint32_t angle_between(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    const int64_t c = cross(ax, ay, bx, by);
    return ssda__atan2(c < 0 ? -c : c, ax * bx + ay * by);
}

/* I: ends p, q nearly in line, facing each other. Cost: the area of the
   triangle the two ends make with their lines, |pq| (e_p + e_q) / 4 with
   e the distance of each end from the other's line (Q22 px^2). */
static bool try_i(const ssda__edge_end_t *p, const ssda__edge_end_t *q,
                  const ssda__edge_gap_cfg_t *cfg, uint64_t *cost)
{
    const int64_t vx = (int64_t)q->x - p->x, vy = (int64_t)q->y - p->y;
    const int64_t e_p = cross(p->ux, p->uy, vx, vy);   /* Q14 px */
    const int64_t e_q = cross(q->ux, q->uy, -vx, -vy); /* Q14 px */
    uint64_t len_q8, area;
    if (p->ux * vx + p->uy * vy <= 0 || -(q->ux * vx + q->uy * vy) <= 0) {
        return false; /* not facing each other */
    }
    if (angle_between(p->ux, p->uy, vx, vy) + angle_between(q->ux, q->uy, -vx, -vy) >
        cfg->i_angle) {
        return false;
    }
    {
        const int64_t d2 = vx * vx + vy * vy; /* <= 2 * 64^2 */
        len_q8 = ssda__isqrt64((uint64_t)d2 * 65536u);
    }
    area = len_q8 * (ssda__abs64(e_p) + ssda__abs64(e_q)) / 4u; /* < 2^15 * 2^22 */
    if (area > ((uint64_t)(uint32_t)cfg->i_area << 22)) {
        return false;
    }
    *cost = area;
    return true;
}

/* V: the ends' straight extensions meet ahead of both, each within gap of
   its end, at an angle >= v_angle. Cost: m, the corner's distance from the
   midpoint of the ends (Q8 px); (*cx, *cy) the corner. */
static bool try_v(const ssda__edge_end_t *p, const ssda__edge_end_t *q,
                  const ssda__edge_gap_cfg_t *cfg, uint32_t w, uint32_t h, uint64_t *cost,
                  int32_t *cx, int32_t *cy)
{
    const int64_t vx = (int64_t)q->x - p->x, vy = (int64_t)q->y - p->y;
    const int64_t den = cross(p->ux, p->uy, q->ux, q->uy); /* Q28 */
    const int64_t tn = cross(vx, vy, q->ux, q->uy);        /* t * den, Q14 px */
    const int64_t sn = cross(vx, vy, p->ux, p->uy);        /* s * den */
    uint64_t t_q8, mx, my;
    int64_t xq8, yq8;
    if (den == 0 || angle_between(p->ux, p->uy, q->ux, q->uy) < cfg->v_angle) {
        return false;
    }
    /* t, s > 0: tn, sn have den's sign; t, s <= gap */
    if ((den > 0) != (tn > 0) || (den > 0) != (sn > 0) || tn == 0 || sn == 0 ||
        ssda__abs64(tn) > ssda__abs64(den) * (uint32_t)cfg->gap / 16384u ||
        ssda__abs64(sn) > ssda__abs64(den) * (uint32_t)cfg->gap / 16384u) {
        return false;
    }
    /* t = tn / den px; t_q8 = |tn| 2^22 / |den| < gap 2^8 */
    t_q8 = SSDA_DIV64_32(ssda__abs64(tn) << 22, (uint32_t)ssda__abs64(den));
    xq8 = (int64_t)p->x * 256 + ssda__rshr64((int64_t)t_q8 * p->ux, 14u);
    yq8 = (int64_t)p->y * 256 + ssda__rshr64((int64_t)t_q8 * p->uy, 14u);
    *cx = (int32_t)ssda__rshr64(xq8, 8u);
    *cy = (int32_t)ssda__rshr64(yq8, 8u);
    if (*cx < 0 || *cy < 0 || (uint32_t)*cx >= w || (uint32_t)*cy >= h) {
        return false;
    }
    mx = ssda__abs64(2 * xq8 - ((int64_t)p->x + q->x) * 256); /* 2 (corner - midpoint) */
    my = ssda__abs64(2 * yq8 - ((int64_t)p->y + q->y) * 256);
    *cost = ssda__isqrt64(mx * mx + my * my) / 2u;
    return true;
}

/* Best I and V partners of end i among the ends within gap in x and y
   (ends are in raster order: scan outwards while |dy| <= gap). */
static void find_iv(const uint16_t *map, uint32_t w, uint32_t h, const ssda__edge_end_t *ends,
                    uint32_t n, uint32_t i, const ssda__edge_gap_cfg_t *cfg, pick_t *pi,
                    pick_t *pv)
{
    const ssda__edge_end_t *p = &ends[i];
    uint32_t j = i;
    pi->found = false;
    pv->found = false;
    while (j > 0u && (int32_t)ends[j - 1u].y >= (int32_t)p->y - cfg->gap) {
        j--;
    }
    for (; j < n && (int32_t)ends[j].y <= (int32_t)p->y + cfg->gap; j++) {
        const ssda__edge_end_t *q = &ends[j];
        uint64_t cost;
        int32_t cx, cy;
        if (j == i || q->x == CONSUMED || cheb((int32_t)q->x - p->x, (int32_t)q->y - p->y) >
                                              (uint32_t)cfg->gap) {
            continue;
        }
        if (ssda__ring_class(ssda__edge_ring(map, w, h, q->x, q->y)) !=
            (uint32_t)SSDA_EDGE_END) {
            continue; /* joined meanwhile */
        }
        if (try_i(p, q, cfg, &cost) && (!pi->found || cost < pi->cost)) {
            pi->found = true;
            pi->cost = cost;
            pi->partner = j;
            pi->dist = cheb((int32_t)q->x - p->x, (int32_t)q->y - p->y);
        }
        if (try_v(p, q, cfg, w, h, &cost, &cx, &cy) && (!pv->found || cost < pv->cost)) {
            pv->found = true;
            pv->cost = cost;
            pv->partner = j;
            pv->dist = cheb((int32_t)q->x - p->x, (int32_t)q->y - p->y);
            pv->x = cx;
            pv->y = cy;
        }
    }
}

void ssda__edge_close(uint16_t *map, uint32_t w, uint32_t h, ssda__edge_end_t *ends,
                      uint32_t n, const ssda__edge_gap_cfg_t *cfg, uint32_t *t, uint32_t *i,
                      uint32_t *v)
{
    uint32_t k;
    for (k = 0u; k < n; k++) {
        ssda__edge_end_t *p = &ends[k];
        pick_t pt, pi, pv;
        (void)memset(&pt, 0, sizeof pt); /* every field defined on every path */
        (void)memset(&pi, 0, sizeof pi);
        (void)memset(&pv, 0, sizeof pv);
        if (p->x == CONSUMED ||
            ssda__ring_class(ssda__edge_ring(map, w, h, p->x, p->y)) != (uint32_t)SSDA_EDGE_END) {
            continue;
        }
        mark_branch(map, w, h, p, cfg->fit, true);
        find_t(map, w, h, p, cfg->gap, &pt);
        mark_branch(map, w, h, p, cfg->fit, false);
        find_iv(map, w, h, ends, n, k, cfg, &pi, &pv);
        if (pi.found && pv.found && pi.partner == pv.partner) {
            pi.found = false; /* the same partner both ways: V (seed) */
        }
        /* the nearest candidate wins; ties V, then I, then T */
        if (pv.found && (!pi.found || pv.dist <= pi.dist) && (!pt.found || pv.dist <= pt.dist)) {
            (void)ssda__edge_line(map, w, p->x, p->y, pv.x, pv.y);
            (void)ssda__edge_line(map, w, pv.x, pv.y, ends[pv.partner].x, ends[pv.partner].y);
            ends[pv.partner].x = CONSUMED;
            *v += 1u;
        } else if (pi.found && (!pt.found || pi.dist <= pt.dist)) {
            (void)ssda__edge_line(map, w, p->x, p->y, ends[pi.partner].x, ends[pi.partner].y);
            ends[pi.partner].x = CONSUMED;
            *i += 1u;
        } else if (pt.found) {
            (void)ssda__edge_line(map, w, p->x, p->y, pt.x, pt.y);
            *t += 1u;
        } else {
            continue;
        }
        p->x = CONSUMED;
    }
}
