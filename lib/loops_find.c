/* loops_find.c - ssda_loops_find (loops.h): open branches pruned, regions
   filled, filtered, traced and resampled. */
#include "loops_internal.h"
#include "edge_internal.h"
#include "fixmath.h"

#include <string.h>

#define AREA_MAX_LIMIT (1u << 20) /* keeps every accumulator below */

/* Resolved settings. */
typedef struct {
    int32_t grey_min;      /* -1: none */
    uint32_t shape_max, area_min, area_max, log2n;
} plan_t;

/* One region's sums while it is filled. */
typedef struct {
    uint32_t area, x0, y0, x1, y1;
    uint64_t sx, sy, sg;   /* sums of x, y, grey: < 2^20 * 2^16 */
    bool border, remainder, overflow;
} fill_t;

static bool prunable(const uint16_t *map, uint32_t w, uint32_t h, uint32_t x, uint32_t y)
{
    const uint32_t c = ssda__ring_class(ssda__edge_ring(map, w, h, x, y));
    return c == (uint32_t)SSDA_EDGE_END || c == (uint32_t)SSDA_EDGE_ISOLATED;
}

/* Delete the ends found around (x, y) (just deleted), following chains on
   a stack of packed (y << 16 | x); returns deletions, sets *full when the
   stack could not hold a pixel (a later pass finds it). */
static uint32_t prune_from(uint16_t *map, uint32_t w, uint32_t h, uint32_t x, uint32_t y,
                           uint32_t *stack, uint32_t cap, bool *full)
{
    uint32_t top, n = 0u, k;
    stack[0] = (y << 16) | x;
    top = 1u;
    while (top > 0u) {
        uint32_t p;
        int32_t px, py;
        top--;
        p = stack[top];
        {
            const uint32_t ux = p & 0xFFFFu, uy = p >> 16;
            px = (int32_t)ux;
            py = (int32_t)uy;
        }
        for (k = 0u; k < 8u; k++) {
            const int32_t qx = px + ssda__ring_dx[k], qy = py + ssda__ring_dy[k];
            uint16_t *q;
            if (qx < 0 || qy < 0 || (uint32_t)qx >= w || (uint32_t)qy >= h) {
                continue;
            }
            q = map + (size_t)(uint32_t)qy * w + (uint32_t)qx;
            if ((*q & SSDA_EDGE_ON) != 0u && prunable(map, w, h, (uint32_t)qx, (uint32_t)qy)) {
                *q = (uint16_t)(*q & ~SSDA_EDGE_ON);
                n++;
                if (top < cap) {
                    stack[top] = ((uint32_t)qy << 16) | (uint32_t)qx;
                    top++;
                } else {
                    *full = true;
                }
            }
        }
    }
    return n;
}

/* Remove every open branch: passes until one neither deletes past a full
   stack. Returns pixels removed. */
static uint32_t prune(uint16_t *map, uint32_t w, uint32_t h, uint32_t *stack, uint32_t cap)
{
    uint32_t x, y, n = 0u; /* <= w * h */
    bool full;
    do {
        full = false;
        for (y = 0u; y < h; y++) {
            for (x = 0u; x < w; x++) {
                uint16_t *p = map + (size_t)y * w + x;
                if ((*p & SSDA_EDGE_ON) != 0u && prunable(map, w, h, x, y)) {
                    *p = (uint16_t)(*p & ~SSDA_EDGE_ON);
                    n += 1u + prune_from(map, w, h, x, y, stack, cap, &full);
                }
            }
        }
    } while (full);
    return n;
}

/* Fill the region of (x, y) (not ON, not SEEN) breadth-first; every pixel
   queued gets SEEN and MARK. The queue keeps them all (tail = count). */
static uint32_t fill(uint16_t *map, const ssda_view_t *img, uint32_t x, uint32_t y,
                     uint32_t *queue, uint32_t cap, fill_t *f)
{
    const uint32_t w = img->width, h = img->height;
    uint32_t head = 0u, tail, k;
    (void)memset(f, 0, sizeof *f);
    f->x0 = x;
    f->y0 = y;
    f->x1 = x;
    f->y1 = y;
    queue[0] = (y << 16) | x;
    tail = 1u;
    map[(size_t)y * w + x] |= (uint16_t)(SSDA__EDGE_SEEN | SSDA__EDGE_MARK);
    while (head < tail) {
        const uint32_t p = queue[head];
        const uint32_t px = p & 0xFFFFu, py = p >> 16;
        head++;
        f->area++;
        f->sx += px;
        f->sy += py;
        f->sg += ssda_view_row(img, py)[px];
        f->x0 = px < f->x0 ? px : f->x0;
        f->x1 = px > f->x1 ? px : f->x1;
        f->y1 = py > f->y1 ? py : f->y1; /* y0: the seed, the first row */
        f->border = f->border || px == 0u || py == 0u || px + 1u == w || py + 1u == h;
        for (k = 0u; k < 8u; k += 2u) { /* 4-neighbours */
            const int32_t qx = (int32_t)px + ssda__ring_dx[k];
            const int32_t qy = (int32_t)py + ssda__ring_dy[k];
            uint16_t *q;
            if (qx < 0 || qy < 0 || (uint32_t)qx >= w || (uint32_t)qy >= h) {
                continue;
            }
            q = map + (size_t)(uint32_t)qy * w + (uint32_t)qx;
            if ((*q & (SSDA_EDGE_ON | SSDA__EDGE_MARK)) != 0u) {
                continue;
            }
            if ((*q & SSDA__EDGE_SEEN) != 0u) {
                f->remainder = true; /* a region an earlier fill could not finish */
            } else if (tail < cap) {
                *q = (uint16_t)(*q | SSDA__EDGE_SEEN | SSDA__EDGE_MARK);
                queue[tail] = ((uint32_t)qy << 16) | (uint32_t)qx;
                tail++;
            } else {
                f->overflow = true;
            }
        }
    }
    return tail;
}

/* Which filter drops a filled region (0 = none, it is a loop); perimeter
   from the traced boundary. Counts into st. */
static bool keep(const plan_t *pl, const fill_t *f, uint64_t len_q16, ssda_loops_stats_t *st)
{
    const uint64_t p_q8 = len_q16 >> 8; /* < 2^30 for area <= 2^20 */
    if (f->border) {
        st->border++;
        return false;
    }
    if (f->overflow || f->remainder || f->area > pl->area_max) {
        st->too_large++;
        return false;
    }
    if (f->area < pl->area_min) {
        st->too_small++;
        return false;
    }
    if (pl->grey_min >= 0 && f->sg < (uint64_t)(uint32_t)pl->grey_min * f->area) {
        st->too_dark++;
        return false;
    }
    /* perimeter^2 / area <= shape_max, in Q16: p_q8^2 <= shape_max area 2^16 */
    if (p_q8 * p_q8 > ((uint64_t)pl->shape_max * f->area) << 16) {
        st->too_long++;
        return false;
    }
    return true;
}

static void write_loop(const fill_t *f, uint64_t len_q16, ssda_loop_t *lp)
{
    lp->area = f->area;
    lp->cx_q8 = (int32_t)SSDA_DIV64_32(f->sx << 8, f->area); /* < 2^24 */
    lp->cy_q8 = (int32_t)SSDA_DIV64_32(f->sy << 8, f->area);
    lp->mean_q8 = SSDA_DIV64_32(f->sg << 8, f->area);
    lp->perimeter_q8 = (uint32_t)(len_q16 >> 8);
    lp->x0 = (uint16_t)f->x0;
    lp->y0 = (uint16_t)f->y0;
    lp->x1 = (uint16_t)f->x1;
    lp->y1 = (uint16_t)f->y1;
}

/* Check the arguments and resolve the settings; SSDA_OK or an error. */
static int plan(const uint16_t *map, const ssda_view_t *img, const ssda_loops_config_t *cfg,
                const void *work, size_t work_size, const ssda_loop_t *loops,
                uint32_t max_loops, const ssda_point_q8_t *points, size_t points_size,
                const uint32_t *n_loops, plan_t *pl)
{
    static const ssda_loops_config_t defaults;
    const ssda_loops_config_t *c = cfg != NULL ? cfg : &defaults;
    int err;
    if (map == NULL || img == NULL || work == NULL || n_loops == NULL ||
        (max_loops > 0u && (loops == NULL || points == NULL))) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(img);
    if (err != SSDA_OK) {
        return err;
    }
    if (img->format != (uint8_t)SSDA_PIX_U8) {
        return SSDA_ERR_FORMAT;
    }
    if (img->width < SSDA_EDGE_MIN_DIM || img->height < SSDA_EDGE_MIN_DIM) {
        return SSDA_ERR_SIZE;
    }
    pl->grey_min = c->grey_min == 0 ? SSDA_LOOPS_DEFAULT_GREY : (int32_t)c->grey_min;
    pl->shape_max = c->shape_max != 0u ? c->shape_max : SSDA_LOOPS_DEFAULT_SHAPE;
    pl->area_min = c->area_min != 0u ? c->area_min : SSDA_LOOPS_DEFAULT_AREA_MIN;
    pl->area_max = c->area_max != 0u ? c->area_max : SSDA_LOOPS_DEFAULT_AREA_MAX;
    pl->log2n = ssda__samples_log2(c->samples != 0u ? c->samples : SSDA_LOOPS_DEFAULT_SAMPLES);
    if ((pl->grey_min < 0 && pl->grey_min != SSDA_LOOPS_GREY_ANY) || pl->grey_min > 255 ||
        pl->area_max > AREA_MAX_LIMIT || pl->area_min > pl->area_max || pl->log2n == 0u) {
        return SSDA_ERR_ARG;
    }
    if (work_size < SSDA_LOOPS_WORK_SIZE(pl->area_max) ||
        (max_loops > 0u && points_size < SSDA_LOOPS_POINTS_SIZE(max_loops, 1u << pl->log2n))) {
        return SSDA_ERR_BUFFER;
    }
    if ((((uintptr_t)map) & 1u) != 0u || (((uintptr_t)work) & 3u) != 0u || /* D10 */
        (((uintptr_t)points) & 3u) != 0u) {
        return SSDA_ERR_STRIDE;
    }
    return SSDA_OK;
}

int ssda_loops_find(uint16_t *map, const ssda_view_t *img, const ssda_loops_config_t *cfg,
                    void *work, size_t work_size, ssda_loop_t *loops, uint32_t max_loops,
                    ssda_point_q8_t *points, size_t points_size, uint32_t *n_loops,
                    ssda_loops_stats_t *stats)
{
    uint32_t *queue = (uint32_t *)work;
    ssda_loops_stats_t st;
    ssda__member_t set;
    plan_t pl;
    uint32_t x, y, cap, w, h;
    int err = plan(map, img, cfg, work, work_size, loops, max_loops, points, points_size,
                   n_loops, &pl);
    if (err != SSDA_OK) {
        return err;
    }
    w = img->width;
    h = img->height;
    cap = pl.area_max + 1u;
    (void)memset(&st, 0, sizeof st);
    st.pruned = prune(map, w, h, queue, cap);
    set.mask = NULL;
    set.map = map;
    set.stride = w;
    set.w = w;
    set.h = h;
    set.bit = SSDA__EDGE_MARK;
    for (y = 0u; y < h; y++) {
        for (x = 0u; x < w; x++) {
            fill_t f;
            uint32_t n, i;
            if ((map[(size_t)y * w + x] & (SSDA_EDGE_ON | SSDA__EDGE_SEEN)) != 0u) {
                continue;
            }
            n = fill(map, img, x, y, queue, cap, &f);
            st.regions++;
            if (!f.border && !f.overflow && !f.remainder && f.area <= pl.area_max &&
                f.area >= pl.area_min) {
                const uint64_t len = ssda__trace_length(&set, x, y);
                if (keep(&pl, &f, len, &st)) {
                    if (st.loops < max_loops) {
                        ssda_loop_t *lp = &loops[st.loops];
                        write_loop(&f, len, lp);
                        lp->contour = points + ((size_t)st.loops << pl.log2n);
                        ssda__trace_sample(&set, x, y, len, pl.log2n, lp->contour);
                    }
                    st.loops++;
                }
            } else {
                (void)keep(&pl, &f, 0u, &st); /* counts the reason */
            }
            for (i = 0u; i < n; i++) {
                map[(size_t)(queue[i] >> 16) * w + (queue[i] & 0xFFFFu)] &=
                    (uint16_t)~SSDA__EDGE_MARK;
            }
        }
    }
    for (x = 0u; x < w * h; x++) { /* private bits back to 0 */
        map[x] = (uint16_t)(map[x] & ~SSDA__EDGE_PRIVATE);
    }
    st.dropped = st.loops > max_loops ? st.loops - max_loops : 0u;
    *n_loops = st.loops < max_loops ? st.loops : max_loops;
    if (stats != NULL) {
        *stats = st;
    }
    return SSDA_OK;
}
