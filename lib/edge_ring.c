/* edge_ring.c - 3 x 3 ring codes: the seed appendix's classification of
   end, connection and branch points, and the thinning of section 2 (c). */
#include "edge_internal.h"

const int8_t ssda__ring_dx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
const int8_t ssda__ring_dy[8] = {0, -1, -1, -1, 0, 1, 1, 1};

uint32_t ssda__edge_ring(const uint16_t *map, uint32_t w, uint32_t h, uint32_t x, uint32_t y)
{
    uint32_t ring = 0u, k;
    if (x > 0u && y > 0u && x + 1u < w && y + 1u < h) { /* inside: no bound tests */
        const uint32_t ym = y - 1u;
        const uint16_t *up = map + (size_t)ym * w + x;
        const uint16_t *mid = up + w;
        const uint16_t *down = mid + w;
        /* bit k from neighbour k: E, NE, N, NW, W, SW, S, SE */
        const uint32_t on[8] = {mid[1], up[1], up[0], up[-1], mid[-1], down[-1], down[0],
                                down[1]};
        for (k = 0u; k < 8u; k++) {
            if ((on[k] & SSDA_EDGE_ON) != 0u) {
                ring |= 1u << k;
            }
        }
        return ring;
    }
    for (k = 0u; k < 8u; k++) {
        const int32_t nx = (int32_t)x + ssda__ring_dx[k];
        const int32_t ny = (int32_t)y + ssda__ring_dy[k];
        if (nx >= 0 && ny >= 0 && (uint32_t)nx < w && (uint32_t)ny < h &&
            (map[(size_t)ny * w + (uint32_t)nx] & SSDA_EDGE_ON) != 0u) {
            ring |= 1u << k;
        }
    }
    return ring;
}

static bool bit(uint32_t ring, uint32_t k)
{
    return ((ring >> (k & 7u)) & 1u) != 0u;
}

void ssda__ring_info(uint32_t ring, ssda__ring_info_t *info)
{
    /*
     * Facts of every ring code, one byte each (printed by
     * tools/gen_ring_facts.py from the definitions below;
     * tests/test_edge_refine.c checks the classes and the thinning's choices
     * against the appendix written out there):
     *   bits 0-1  cyclic runs of set bits, 3 standing for 3 or more (0xFF: 1)
     *   bit  2    unsuitable: a run of >= 4, or of 3 centred on a diagonal
     *   bit  3    every set 4-neighbour lies in one run (deletion keeps
     *             4-connectivity)
     *   bit  4    the set bits form one 8-connected component within the ring
     *             (runs joined across a clear corner between two set
     *             4-neighbours)
     *   bits 5-7  4-neighbours not set, 0..4
     */
    static const uint8_t ring_facts[256] = {
        0x88u, 0x79u, 0x99u, 0x79u, 0x79u, 0x52u, 0x79u, 0x5Du, 0x99u, 0x6Au, 0x8Au, 0x6Au,
        0x79u, 0x52u, 0x79u, 0x5Du, 0x79u, 0x42u, 0x6Au, 0x42u, 0x52u, 0x33u, 0x52u, 0x36u,
        0x79u, 0x42u, 0x6Au, 0x42u, 0x5Du, 0x36u, 0x5Du, 0x3Du, 0x99u, 0x6Au, 0x8Au, 0x6Au,
        0x6Au, 0x43u, 0x6Au, 0x4Eu, 0x8Au, 0x6Bu, 0x8Bu, 0x6Bu, 0x6Au, 0x43u, 0x6Au, 0x4Eu,
        0x79u, 0x42u, 0x6Au, 0x42u, 0x52u, 0x33u, 0x52u, 0x36u, 0x79u, 0x42u, 0x6Au, 0x42u,
        0x5Du, 0x36u, 0x5Du, 0x3Du, 0x79u, 0x52u, 0x6Au, 0x52u, 0x42u, 0x33u, 0x42u, 0x36u,
        0x6Au, 0x43u, 0x6Bu, 0x43u, 0x42u, 0x33u, 0x42u, 0x36u, 0x52u, 0x33u, 0x43u, 0x33u,
        0x33u, 0x13u, 0x33u, 0x17u, 0x52u, 0x33u, 0x43u, 0x33u, 0x36u, 0x17u, 0x36u, 0x16u,
        0x79u, 0x52u, 0x6Au, 0x52u, 0x42u, 0x33u, 0x42u, 0x36u, 0x6Au, 0x43u, 0x6Bu, 0x43u,
        0x42u, 0x33u, 0x42u, 0x36u, 0x5Du, 0x36u, 0x4Eu, 0x36u, 0x36u, 0x17u, 0x36u, 0x16u,
        0x5Du, 0x36u, 0x4Eu, 0x36u, 0x3Du, 0x16u, 0x3Du, 0x1Du, 0x99u, 0x79u, 0x8Au, 0x79u,
        0x6Au, 0x52u, 0x6Au, 0x5Du, 0x8Au, 0x6Au, 0x8Bu, 0x6Au, 0x6Au, 0x52u, 0x6Au, 0x5Du,
        0x6Au, 0x42u, 0x6Bu, 0x42u, 0x43u, 0x33u, 0x43u, 0x36u, 0x6Au, 0x42u, 0x6Bu, 0x42u,
        0x4Eu, 0x36u, 0x4Eu, 0x3Du, 0x8Au, 0x6Au, 0x8Bu, 0x6Au, 0x6Bu, 0x43u, 0x6Bu, 0x4Eu,
        0x8Bu, 0x6Bu, 0x8Bu, 0x6Bu, 0x6Bu, 0x43u, 0x6Bu, 0x4Eu, 0x6Au, 0x42u, 0x6Bu, 0x42u,
        0x43u, 0x33u, 0x43u, 0x36u, 0x6Au, 0x42u, 0x6Bu, 0x42u, 0x4Eu, 0x36u, 0x4Eu, 0x3Du,
        0x79u, 0x5Du, 0x6Au, 0x5Du, 0x42u, 0x36u, 0x42u, 0x3Du, 0x6Au, 0x4Eu, 0x6Bu, 0x4Eu,
        0x42u, 0x36u, 0x42u, 0x3Du, 0x52u, 0x36u, 0x43u, 0x36u, 0x33u, 0x17u, 0x33u, 0x16u,
        0x52u, 0x36u, 0x43u, 0x36u, 0x36u, 0x16u, 0x36u, 0x1Du, 0x79u, 0x5Du, 0x6Au, 0x5Du,
        0x42u, 0x36u, 0x42u, 0x3Du, 0x6Au, 0x4Eu, 0x6Bu, 0x4Eu, 0x42u, 0x36u, 0x42u, 0x3Du,
        0x5Du, 0x3Du, 0x4Eu, 0x3Du, 0x36u, 0x16u, 0x36u, 0x1Du, 0x5Du, 0x3Du, 0x4Eu, 0x3Du,
        0x3Du, 0x1Du, 0x3Du, 0x1Du};
    const uint32_t f = ring_facts[ring & 0xFFu];
    info->runs = f & 3u;
    info->unsuitable = (f & 4u) != 0u;
    info->keeps4 = (f & 8u) != 0u;
    info->c8 = 2u; /* only "one component or not" is used */
    if ((f & 16u) != 0u) {
        info->c8 = 1u;
    }
    info->bg4 = f >> 5;
}

uint32_t ssda__ring_class(uint32_t ring)
{
    ssda__ring_info_t info;
    ssda__ring_info(ring, &info);
    if (info.runs == 0u) {
        return (uint32_t)SSDA_EDGE_ISOLATED;
    }
    if (info.unsuitable || info.runs >= 3u) {
        return (uint32_t)SSDA_EDGE_BRANCH;
    }
    return info.runs == 1u ? (uint32_t)SSDA_EDGE_END : (uint32_t)SSDA_EDGE_CONN;
}

uint32_t ssda__chain_next(uint32_t ring, uint32_t back)
{
    uint32_t k, start = 8u, len = 0u;
    if (ssda__ring_class(ring) != (uint32_t)SSDA_EDGE_CONN || !bit(ring, back)) {
        return 8u;
    }
    /* the run not containing `back`: walk forward from back's run end */
    k = back;
    while (bit(ring, k)) {
        k = (k + 1u) & 7u;
    }
    while (!bit(ring, k)) {
        k = (k + 1u) & 7u;
    }
    start = k;
    while (bit(ring, start + len)) {
        len++;
    }
    for (k = 0u; k < len; k++) {
        if (((start + k) & 1u) == 0u) {
            return (start + k) & 7u; /* 4-connection first (seed appendix) */
        }
    }
    return (start + len / 2u) & 7u;
}

/* Deletable in thinning stage 1, 2 or 3 (seed Figs. 2-4: deletion keeps
   4-connectivity without a dent; keeps it with a dent; keeps only
   8-connectivity). Never a pixel whose deletion opens a hole (no OFF
   4-neighbour) or splits its neighbours (c8 != 1). */
static bool deletable(uint32_t ring, uint32_t stage)
{
    ssda__ring_info_t info;
    ssda__ring_info(ring, &info);
    if (!info.unsuitable || info.c8 != 1u || info.bg4 == 0u) {
        return false;
    }
    if (stage == 1u) {
        return info.keeps4 && info.bg4 >= 2u;
    }
    if (stage == 2u) {
        return info.keeps4;
    }
    return true;
}

/* One raster pass of a stage; returns deletions. */
static uint32_t thin_pass(uint16_t *map, uint32_t w, uint32_t h, uint32_t stage)
{
    uint32_t x, y, n = 0u;
    for (y = 0u; y < h; y++) {
        uint16_t *row = map + (size_t)y * w;
        for (x = 0u; x < w; x++) {
            if ((row[x] & SSDA_EDGE_ON) != 0u &&
                deletable(ssda__edge_ring(map, w, h, x, y), stage)) {
                row[x] = (uint16_t)(row[x] & ~SSDA_EDGE_ON);
                n++;
            }
        }
    }
    return n;
}

uint32_t ssda__edge_thin(uint16_t *map, uint32_t w, uint32_t h)
{
    uint32_t stage, n, x, y, total = 0u; /* total <= w * h < 2^32 */
    for (stage = 1u; stage <= 3u; stage++) {
        do { /* each pass deletes at least one pixel or ends the stage */
            n = thin_pass(map, w, h, stage);
            total += n;
        } while (n != 0u);
    }
    for (y = 0u; y < h; y++) { /* isolated points (seed Fig. 5) */
        uint16_t *row = map + (size_t)y * w;
        for (x = 0u; x < w; x++) {
            if ((row[x] & SSDA_EDGE_ON) != 0u && ssda__edge_ring(map, w, h, x, y) == 0u) {
                row[x] = (uint16_t)(row[x] & ~SSDA_EDGE_ON);
                total++;
            }
        }
    }
    return total;
}

uint32_t ssda__edge_line(uint16_t *map, uint32_t w, int32_t x0, int32_t y0, int32_t x1,
                         int32_t y1)
{
    const int32_t dx = x1 > x0 ? x1 - x0 : x0 - x1;
    const int32_t dy = y1 > y0 ? y0 - y1 : y1 - y0; /* -|y1 - y0| */
    int32_t sx = -1, sy = -1;
    int32_t err = dx + dy, x = x0, y = y0;
    uint32_t set = 0u;
    if (x1 > x0) {
        sx = 1;
    }
    if (y1 > y0) {
        sy = 1;
    }
    for (;;) { /* Bresenham, 8-connected; ends at (x1, y1) */
        uint16_t *p = map + (size_t)(uint32_t)y * w + (uint32_t)x;
        const int32_t e2 = 2 * err;
        if ((*p & SSDA_EDGE_ON) == 0u) {
            *p = (uint16_t)(*p | SSDA_EDGE_ON);
            set++;
        }
        if (x == x1 && y == y1) {
            break;
        }
        if (e2 >= dy) {
            err += dy;
            x += sx;
        }
        if (e2 <= dx) {
            err += dx;
            y += sy;
        }
    }
    return set;
}

uint32_t ssda__end_exit(uint32_t ring)
{
    uint32_t k = 0u, len = 0u, i;
    while (((ring >> k) & 1u) == 0u || ((ring >> ((k + 7u) & 7u)) & 1u) != 0u) {
        k++; /* the run's first position (an end has exactly one run) */
    }
    while (((ring >> ((k + len) & 7u)) & 1u) != 0u) {
        len++;
    }
    for (i = 0u; i < len; i++) {
        if (((k + i) & 1u) == 0u) {
            return (k + i) & 7u;
        }
    }
    return (k + len / 2u) & 7u;
}

void ssda__edge_walk(const uint16_t *map, uint32_t w, uint32_t h, uint32_t x, uint32_t y,
                 uint32_t limit, ssda__walk_t *wk)
{
    int32_t cx = (int32_t)x, cy = (int32_t)y;
    uint32_t k = ssda__end_exit(ssda__edge_ring(map, w, h, x, y));
    wk->x[0] = cx;
    wk->y[0] = cy;
    wk->n = 1u;
    wk->stopped = false;
    while (wk->n < limit) {
        uint32_t ring, cls;
        cx += ssda__ring_dx[k];
        cy += ssda__ring_dy[k];
        ring = ssda__edge_ring(map, w, h, (uint32_t)cx, (uint32_t)cy);
        cls = ssda__ring_class(ring);
        if (cls == (uint32_t)SSDA_EDGE_BRANCH) {
            wk->stopped = true; /* the branch point itself is not counted */
            return;
        }
        wk->x[wk->n] = cx;
        wk->y[wk->n] = cy;
        wk->n++;
        if (cls != (uint32_t)SSDA_EDGE_CONN) {
            wk->stopped = true; /* another end: the whole branch is walked */
            return;
        }
        k = ssda__chain_next(ring, (k + 4u) & 7u);
        if (k > 7u) {
            wk->stopped = true;
            return;
        }
    }
}

