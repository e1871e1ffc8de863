/*
 * track_tab.c - the bound tables shared by the searches of a tracking call
 * (track_tab.h): built row by row from vertical sums of 4 pixels, kept while
 * the grid moves down, read by the engine (SSDA__MATCH_TAB).
 */
#include <string.h>

#include "track_tab.h"
#include "match_pre.h"
#include "kernel/kernels.h"

#ifndef SSDA_CFG_NO_BOUNDS

/* The state fits before the tables (a negative array size otherwise). */
typedef char ssda__track_tab_head_fits[sizeof(ssda__track_tab_t) <= SSDA__TRACK_TAB_HEAD ? 1 : -1];

/* Bytes of the per-window work (SSDA_TRACK_WORK_SIZE, rounded up to 8) and
   of the whole buffer with shared tables (SSDA_TRACK_WORK_SIZE_SHARED), in
   64 bits: sizes up to 65535 never wrap here. */
static uint64_t per_window_bytes(const ssda_track_grid_t *g)
{
    const uint64_t bounds = (((uint64_t)g->search_w - g->win_w + 1u) * g->search_h +
                             2u * (uint64_t)g->win_h) * sizeof(uint32_t);
    return ((bounds + 7u) & ~(uint64_t)7u) + SSDA_MATCH_UNIQUE_WORK;
}

uint64_t ssda__track_tab_size(const ssda_track_grid_t *g, uint32_t first_w)
{
    const uint64_t rows = g->search_h > 3u ? (uint64_t)g->search_h - 3u : 0u;
    return ((per_window_bytes(g) + 7u) & ~(uint64_t)7u) + SSDA__TRACK_TAB_HEAD +
           ((2u * rows + 1u) * first_w + ((uint64_t)g->win_w / 4u) * (g->win_h / 4u)) *
               sizeof(uint32_t);
}

ssda__track_tab_t *ssda__track_tab_init(const ssda_track_plan_t *plan, uint32_t col0,
                                        uint32_t col1, uint32_t first_x)
{
    const ssda_track_grid_t *g = &plan->grid;
    const uint32_t hx = ((uint32_t)g->search_w - g->win_w) / 2u;
    uint8_t *head = (uint8_t *)plan->match.work +
                    (size_t)((per_window_bytes(g) + 7u) & ~(uint64_t)7u);
    ssda__track_tab_t *t = (ssda__track_tab_t *)(void *)head;
    uint32_t *base = (uint32_t *)(void *)(head + SSDA__TRACK_TAB_HEAD);
    const size_t rows = plan->tab_rows;
    uint32_t col, first_ax = 0u, last_ax = 0u;
    bool any = false;
    for (col = col0; col < col1; col++) { /* the columns inside FIRST horizontally */
        const uint32_t wx = g->roi_x + col * g->step_x; /* < 65536 */
        if (wx >= hx && wx - hx + g->search_w <= plan->first_w) {
            if (!any) {
                first_ax = wx - hx;
            }
            last_ax = wx - hx;
            any = true;
        }
    }
    t->g = base;
    t->b = base + rows * plan->first_w;
    t->v = t->b + rows * plan->first_w;
    t->wblk = t->v + plan->first_w;
    t->cap = plan->tab_rows;
    t->need = plan->tab_rows;
    t->blocks = (g->win_w & 3u) == 0u && g->win_w <= 1024u;
    /* V spans the areas' columns: last_ax - first_ax + search_w <= first_w */
    t->vlen = any ? last_ax - first_ax + g->search_w : 0u;
    t->npos = any ? t->vlen - g->win_w + 1u : 0u;
    t->pitch = t->blocks ? t->vlen - 3u : t->npos;
    t->x_lo = first_ax - (any ? first_x : 0u);
    t->y_lo = 0u;
    t->y_end = 0u;
    t->v_row = UINT32_MAX;
    return t;
}

/* v[i] += row y's pixel x_lo + i (add) or -= it (modulo 2^32: the sums
   end exact), i < vlen: one op a pixel. */
static int v_add(const ssda__track_tab_t *t, const ssda__rows_t *first, uint32_t y, bool add)
{
    const uint8_t *p;
    uint32_t *v = t->v;
    int err = ssda__rows_get(first, t->x_lo, y, t->vlen, &p);
    if (err != SSDA_OK) {
        return err;
    }
    ssda__pre_vstep(v, p, first->format == (uint8_t)SSDA_PIX_U8, t->vlen, add);
    return SSDA_OK;
}

/* v = the vertical sums of rows y .. y + 3 (<= 4 * 65535 < 2^18): from
   v of row y - 1 when held (2 ops a pixel), else from scratch (4). */
static int v_row(ssda__track_tab_t *t, const ssda__rows_t *first, uint32_t y, uint64_t *ops)
{
    int err;
    if (t->v_row != UINT32_MAX && t->v_row + 1u == y) {
#if defined(SSDA_KERNEL_sse2)
        if (first->base != NULL) { /* rows in memory: both rows in one pass */
            const size_t at = (size_t)t->x_lo * first->format;
            ssda__vslide(t->v, first->base + (size_t)(y + 3u) * first->stride + at,
                         first->base + (size_t)(y - 1u) * first->stride + at, t->vlen,
                         first->format == (uint8_t)SSDA_PIX_U8);
            *ops += 2u * (uint64_t)t->vlen;
            t->v_row = y;
            return SSDA_OK;
        }
#endif
        err = v_add(t, first, y + 3u, true);
        if (err == SSDA_OK) {
            err = v_add(t, first, y - 1u, false);
        }
        *ops += 2u * (uint64_t)t->vlen;
    } else {
        (void)memset(t->v, 0, (size_t)t->vlen * sizeof(uint32_t));
        uint32_t j;
        err = SSDA_OK;
        for (j = 0u; j < 4u && err == SSDA_OK; j++) {
            err = v_add(t, first, y + j, true);
        }
        *ops += 4u * (uint64_t)t->vlen;
    }
    t->v_row = err == SSDA_OK ? y : UINT32_MAX;
    return err;
}

/* Row y of the tables into slot s, from the prefix sums p[k] = v[0] + ...
   + v[k - 1] modulo 2^32, k = 0 .. vlen (one op an entry), written first
   in g's slot and the 4 (blocks) or L entries after it: the next slots,
   not built yet (rows are built in ascending slots), or for the last slot
   the tables' slack. With one slot (search_h = 4) and areas over FIRST's
   whole width there is none: p[vlen] is b's first entry, which the b loop
   writes first, so p[vlen] is read before it (ssda__tab_row's contract;
   test_track_shared's one-row, whole-width case). Then b[i] = p[i + 4] -
   p[i] (4 vertical sums, < 2^20) and g[i] = p[i + L] - p[i] in place,
   ascending (it reads only entries not yet replaced; L of them, <= 4 * L
   * 65535 < 2^32 with L <= 16384 for 16-bit samples): differences of sums
   modulo 2^32, exact since the true sums are below 2^32; one op an entry.
   Five ops a pixel with v's two, where sliding sums for g and b took six
   (issue 18). pitch, npos >= 1: an area is searched (vlen >= search_w >=
   win_w), and blocks need win_w >= 4. On x86 the kernels' row
   (ssda__tab_row, the same loops; AVX2 where the processor has it),
   elsewhere the loops here. */
#if defined(SSDA_KERNEL_sse2)
static int build_row(ssda__track_tab_t *t, const ssda__rows_t *first, uint32_t L, uint32_t y,
                     uint32_t s, uint64_t *ops)
{
    const uint32_t pitch = t->pitch, vlen = t->vlen;
    uint32_t *p = t->g + (size_t)s * pitch;
    uint32_t *b = t->blocks ? t->b + (size_t)s * pitch : NULL;
    int err = v_row(t, first, y, ops);
    if (err != SSDA_OK) {
        return err;
    }
    /* x86: the kernels' row (AVX2 where the processor has it: the prefix
       sums in vectors; issue 18) */
    ssda__tab_row(p, b, t->v, vlen, L);
    *ops += (uint64_t)vlen + (b != NULL ? pitch : 0u) + t->npos;
    return SSDA_OK;
}
#else
static int build_row(ssda__track_tab_t *t, const ssda__rows_t *first, uint32_t L, uint32_t y,
                     uint32_t s, uint64_t *ops)
{
    /* the fields in locals: the stores below could alias them */
    const uint32_t *v = t->v;
    const uint32_t npos = t->npos, pitch = t->pitch, vlen = t->vlen;
    uint32_t *p = t->g + (size_t)s * pitch;
    const uint32_t *ahead = p + L; /* size_t indices below: loops that vectorise */
    uint32_t sum = 0u;
    size_t i;
    int err = v_row(t, first, y, ops);
    if (err != SSDA_OK) {
        return err;
    }
    p[0] = 0u;
    for (i = 0u; i < vlen; i++) {
        sum += v[i]; /* modulo 2^32 */
        p[i + 1u] = sum;
    }
    *ops += vlen;
    /* sum = p[vlen]; pitch, npos >= 1 (an area is searched: vlen >= search_w
       >= win_w, and blocks need win_w >= 4) */
    if (t->blocks) {
        uint32_t *b = t->b + (size_t)s * pitch;
        const uint32_t *p4 = p + 4;
        for (i = 0u; i + 1u < pitch; i++) {
            b[i] = p4[i] - p[i];
        }
        b[pitch - 1u] = sum - p[pitch - 1u]; /* p4[pitch - 1] = p[vlen] */
        *ops += pitch;
    }
    for (i = 0u; i + 1u < npos; i++) {
        p[i] = ahead[i] - p[i];
    }
    p[npos - 1u] = sum - p[npos - 1u]; /* ahead[npos - 1] = p[vlen] */
    *ops += npos;
    return SSDA_OK;
}
#endif

/* Rows y .. y + need - 1 present: those held kept (moved to the front when
   the tables are full), the others built. */
static int tab_rows(ssda__track_tab_t *t, const ssda__rows_t *first, uint32_t L, uint32_t y,
                    uint64_t *ops)
{
    const uint32_t end = y + t->need; /* <= FIRST's height */
    uint32_t r;
    if (y < t->y_lo || y > t->y_end) {
        t->y_lo = y; /* nothing to keep */
        t->y_end = y;
    }
    if (end > t->y_lo + t->cap) {
        const size_t row = (size_t)t->pitch * sizeof(uint32_t);
        for (r = y; r < t->y_end; r++) { /* ascending: a row never onto one not yet moved */
            const size_t to = ((size_t)r - y) * t->pitch;
            const size_t from = ((size_t)r - t->y_lo) * t->pitch;
            (void)memcpy(t->g + to, t->g + from, row);
            if (t->blocks) {
                (void)memcpy(t->b + to, t->b + from, row);
            }
        }
        t->y_lo = y;
    }
    for (r = t->y_end; r < end; r++) {
        int err = build_row(t, first, L, r, r - t->y_lo, ops);
        if (err != SSDA_OK) {
            t->y_end = r;
            return err;
        }
        t->y_end = r + 1u;
    }
    return SSDA_OK;
}

int ssda__track_tab_area(ssda__track_tab_t *t, const ssda__rows_t *first, uint32_t L,
                         uint32_t ax, uint32_t y, uint64_t *ops)
{
    ssda__match_tab_t *mt = &t->mt;
    int err = tab_rows(t, first, L, y, ops);
    if (err != SSDA_OK) {
        return err;
    }
    mt->g = t->g + (size_t)(y - t->y_lo) * t->pitch + (ax - t->x_lo);
    mt->b = t->blocks ? t->b + (size_t)(y - t->y_lo) * t->pitch + (ax - t->x_lo) : NULL;
    mt->wblk = t->wblk;
    mt->pitch = t->pitch;
    return SSDA_OK;
}

#else
/* no bounds compiled in: no shared tables (a unit must declare something) */
typedef int ssda__track_tab_none_t;
#endif /* SSDA_CFG_NO_BOUNDS */
