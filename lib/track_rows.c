/*
 * track_rows.c - grid tracking over row sources: window statuses (edge,
 * mask, texture), prediction from solved neighbours, one ssda__match_rows per
 * window on sub-sources of the two images.
 */
#include "track_rows.h"
#include "track_tab.h"
#include "fixmath.h"
#include "kernel/kernels.h"

const ssda__track_origin_t ssda__track_origin_whole = {0u, 0u, 0u, 0u};

static int check_rows(const ssda__rows_t *r)
{
    if (r->format != (uint8_t)SSDA_PIX_U8 && r->format != (uint8_t)SSDA_PIX_U16) {
        return SSDA_ERR_FORMAT;
    }
    if (r->width == 0u || r->height == 0u) {
        return SSDA_ERR_SIZE;
    }
    if (r->base == NULL) {
        return r->fetch == NULL ? SSDA_ERR_NULL : SSDA_OK;
    }
    if (r->stride < (uint32_t)r->width * r->format || (r->stride % r->format) != 0u ||
        (r->format == (uint8_t)SSDA_PIX_U16 && (((uintptr_t)r->base) & 1u) != 0u)) {
        return SSDA_ERR_STRIDE;
    }
    return SSDA_OK;
}

/* What a pass over a rectangle's pixels found. */
typedef struct {
    uint32_t bright; /* pixels > threshold, <= 65535^2 < 2^32 */
    uint64_t sum;    /* the flat test: sum of the pixels, <= 65535^3 < 2^48 */
    bool masked;     /* some pixel == mask value */
} scan_t;

/* Span loops: plain, so that compilers vectorise them. */
/* Compared in the samples' own width (v out of their range: no hit), so
   that the loops vectorise 16 or 8 samples at a time (issue 18: the mask
   test was 8 % of a GOES-16 tracking window's instructions). */
static bool has_value_u8(const uint8_t *p, uint32_t n, uint32_t v)
{
    const uint8_t t = (uint8_t)v;
    uint8_t hit = 0u;
    size_t i;
    if (v > 255u) {
        return false;
    }
    for (i = 0u; i < n; i++) {
        hit |= (uint8_t)(p[i] == t ? 1u : 0u);
    }
    return hit != 0u;
}

/* Sum of (p[i] == t) over a span of n, a constant where inlined below (the
   seed's 16- and 32-px rows: straight vector code, no loop set-up). */
static SSDA_ALWAYS_INLINE uint16_t hits_u16(const uint16_t *p, size_t n, uint16_t t)
{
    uint16_t hit = 0u;
    size_t i;
    for (i = 0u; i < n; i++) {
        hit |= (uint16_t)(p[i] == t ? 1u : 0u);
    }
    return hit;
}

static bool has_value_u16(const uint16_t *p, uint32_t n, uint32_t v)
{
    const uint16_t t = (uint16_t)v;
    if (v > 65535u) {
        return false;
    }
    if (n == 16u) {
        return hits_u16(p, 16u, t) != 0u;
    }
    if (n == 32u) {
        return hits_u16(p, 32u, t) != 0u;
    }
    return hits_u16(p, n, t) != 0u;
}

/* Whether a view in RAM holds the value v anywhere: the mask test above,
   row by row (ssda_composite's SSDA_COMPOSITE_MASK uses it, so that the
   composite matching and the grid tracking mask by the same test). */
bool ssda__view_holds(const ssda_view_t *view, uint32_t v)
{
    const uint8_t *row = (const uint8_t *)view->data;
    uint32_t y;
    for (y = 0u; y < view->height; y++, row += view->stride) {
        if (view->format == (uint8_t)SSDA_PIX_U8 ? has_value_u8(row, view->width, v)
                                                 : has_value_u16((const uint16_t *)(const void *)row,
                                                                 view->width, v)) {
            return true;
        }
    }
    return false;
}

/* Pixels > thr in a span: <= n <= 65535. */
static uint32_t count_above_u8(const uint8_t *p, uint32_t n, uint32_t thr)
{
    uint32_t i, c = 0u;
    for (i = 0u; i < n; i++) {
        c += p[i] > thr ? 1u : 0u;
    }
    return c;
}

static uint32_t count_above_u16(const uint16_t *p, uint32_t n, uint32_t thr)
{
    uint32_t i, c = 0u;
    for (i = 0u; i < n; i++) {
        c += p[i] > thr ? 1u : 0u;
    }
    return c;
}

/* Sum of a span: <= 65535 * 65535 < 2^32. */
static uint32_t sum_u8(const uint8_t *p, uint32_t n)
{
    uint32_t i, c = 0u;
    for (i = 0u; i < n; i++) {
        c += p[i];
    }
    return c;
}

static uint32_t sum_u16(const uint16_t *p, uint32_t n)
{
    uint32_t i, c = 0u;
    for (i = 0u; i < n; i++) {
        c += p[i];
    }
    return c;
}

/* Sum of |p - m| over a span, m <= 65535: <= 65535 * 65535 < 2^32. */
static uint32_t absdev_u8(const uint8_t *p, uint32_t n, uint32_t m)
{
    uint32_t i, c = 0u;
    for (i = 0u; i < n; i++) {
        c += p[i] > m ? p[i] - m : m - p[i];
    }
    return c;
}

static uint32_t absdev_u16(const uint16_t *p, uint32_t n, uint32_t m)
{
    uint32_t i, c = 0u;
    for (i = 0u; i < n; i++) {
        c += p[i] > m ? p[i] - m : m - p[i];
    }
    return c;
}

#if !defined(SSDA_KERNEL_sse2)
/* The mask test alone over rows in memory of 16 or 32 16-bit samples (the
   seed's windows and areas): the comparisons of every row OR-ed into 16
   lanes, reduced once at the end, where the row loop reduced and tested
   each row (issue 18: the mask test was a tenth of a GOES-16 tracking
   window's time). True when no sample equals t. */
static bool mask_free_u16(const ssda__rows_t *src, uint32_t n, uint16_t t)
{
    uint16_t acc[16] = {0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u};
    uint16_t any = 0u;
    uint32_t y;
    size_t i;
    for (y = 0u; y < src->height; y++) {
        const uint16_t *q =
            (const uint16_t *)(const void *)(src->base + (size_t)y * src->stride);
        for (i = 0u; i < 16u; i++) {
            acc[i] |= (uint16_t)(q[i] == t ? 1u : 0u);
        }
        if (n == 32u) {
            for (i = 0u; i < 16u; i++) {
                acc[i] |= (uint16_t)(q[16u + i] == t ? 1u : 0u);
            }
        }
    }
    for (i = 0u; i < 16u; i++) {
        any |= acc[i];
    }
    return any == 0u;
}
#endif

/* mask_free_u16, on x86 the kernels' (ssda__any_u16: AVX2 where the
   processor has it; issue 18). */
static inline bool mask_free(const ssda__rows_t *src, uint32_t n, uint16_t t)
{
#if defined(SSDA_KERNEL_sse2)
    return ssda__any_u16(src->base, src->stride, n, src->height, t) == 0u;
#else
    return mask_free_u16(src, n, t);
#endif
}

/* Over all rows of src, one span per row: look for the mask value (if
   mask), count pixels above the texture threshold (if texture), sum the
   pixels (if sum). Stops at the first row holding the mask value (the
   status is then decided). Returns SSDA_OK or a fetch error. */
static int scan_pixels(const ssda__rows_t *src, const ssda_track_plan_t *p, bool mask,
                       bool texture, bool sum, scan_t *s, uint64_t *pixels_read)
{
    const uint32_t n = src->width;
    const bool u8 = src->format == (uint8_t)SSDA_PIX_U8;
    uint32_t y;
    s->bright = 0u;
    s->sum = 0u;
    s->masked = false;
    if (mask && !texture && !sum && !u8 && src->base != NULL && (n == 16u || n == 32u) &&
        mask_free(src, n, p->mask_value)) {
        /* the loop below would read every row and find nothing; with a hit
           it finds the row, and counts the rows up to it */
        *pixels_read += (uint64_t)n * src->height;
        return SSDA_OK;
    }
    for (y = 0u; y < src->height && !s->masked; y++) {
        const uint8_t *px;
        const uint16_t *q;
        int err = ssda__rows_get(src, 0u, y, n, &px);
        if (err != SSDA_OK) {
            return err;
        }
        q = (const uint16_t *)(const void *)px;
        if (mask) {
            s->masked = u8 ? has_value_u8(px, n, p->mask_value)
                           : has_value_u16(q, n, p->mask_value);
        }
        if (texture) {
            s->bright += u8 ? count_above_u8(px, n, p->texture_threshold)
                            : count_above_u16(q, n, p->texture_threshold);
        }
        if (sum) {
            s->sum += u8 ? sum_u8(px, n) : sum_u16(q, n);
        }
        *pixels_read += n;
    }
    return SSDA_OK;
}

/* The window's texture (track.h): floor(256 * sum |p - m| / n) with m the
   mean rounded down, from a second pass. n < 2^32; the deviation sum
   <= 65535 * n < 2^48, shifted < 2^56; the quotient <= 65535 * 256. */
static int texture_q8(const ssda__rows_t *win, uint64_t sum, uint32_t *out,
                      uint64_t *pixels_read)
{
    const uint32_t n = (uint32_t)win->width * win->height;
    /* n >= 1: windows are at least 1 x 1 */
    const uint32_t m = SSDA_DIV64_32(sum, n); /* NOLINT(clang-analyzer-core.DivideZero) */
    uint64_t dev = 0u;
    uint32_t y;
    for (y = 0u; y < win->height; y++) {
        const uint8_t *px;
        int err = ssda__rows_get(win, 0u, y, win->width, &px);
        if (err != SSDA_OK) {
            return err;
        }
        dev += win->format == (uint8_t)SSDA_PIX_U8
                   ? absdev_u8(px, win->width, m)
                   : absdev_u16((const uint16_t *)(const void *)px, win->width, m);
        *pixels_read += win->width;
    }
    *out = SSDA_DIV64_32(dev << 8, n);
    return SSDA_OK;
}

static void add_sat(uint64_t *acc, uint64_t v)
{
    *acc = v > UINT64_MAX - *acc ? UINT64_MAX : *acc + v;
}

static int32_t med3(int32_t a, int32_t b, int32_t c)
{
    int32_t lo = a < b ? a : b;
    int32_t hi = a < b ? b : a;
    return c < lo ? lo : (c > hi ? hi : c);
}

/* Predicted vector of window (col, row) from the solved entries of out:
   every column left of the strip, and the strip's windows solved before
   this one; col1 (the strip's end) and beyond are not solved yet. */
static void predict(const ssda_track_plan_t *p, const ssda_track_vector_t *out,
                    uint32_t col, uint32_t row, uint32_t col1, int32_t *pdx, int32_t *pdy)
{
    const uint32_t cols = p->grid.cols;
    const size_t k = (size_t)row * cols + col;
    const ssda_track_vector_t *cand[4];
    const ssda_track_vector_t *ok[3];
    uint32_t n = 0u, i;
    cand[0] = col > 0u ? &out[k - 1u] : NULL;                            /* left */
    cand[1] = row > 0u ? &out[k - cols] : NULL;                          /* up */
    cand[2] = row > 0u && col + 1u < col1 ? &out[k - cols + 1u] : NULL;  /* up-right */
    cand[3] = row > 0u && col > 0u ? &out[k - cols - 1u] : NULL;         /* up-left */
    *pdx = 0;
    *pdy = 0;
    if (p->predict == (uint8_t)SSDA_TRACK_PREDICT_LEFT) {
        const ssda_track_vector_t *v = col > 0u ? cand[0] : cand[1];
        if (v != NULL && v->status == (uint8_t)SSDA_TRACK_OK) {
            *pdx = v->dx;
            *pdy = v->dy;
        }
        return;
    }
    for (i = 0u; i < 4u && n < 3u; i++) {
        if (cand[i] != NULL && cand[i]->status == (uint8_t)SSDA_TRACK_OK) {
            ok[n] = cand[i];
            n++;
        }
    }
    if (n == 3u) {
        *pdx = med3(ok[0]->dx, ok[1]->dx, ok[2]->dx);
        *pdy = med3(ok[0]->dy, ok[1]->dy, ok[2]->dy);
    } else if (n > 0u) {
        *pdx = ok[0]->dx;
        *pdy = ok[0]->dy;
    } else {
        /* no solved neighbour: the prediction stays (0, 0) */
    }
}

/* The tests on the window alone (mask, the seed's exclusion, flat), which
   may decide its status before FIRST is read: *decided is then true. */
static int window_tests(const ssda__rows_t *win, const ssda_track_plan_t *p,
                        ssda_track_vector_t *v, ssda_track_stats_t *st, bool *decided)
{
    const bool mask = (p->flags & SSDA_TRACK_MASK) != 0u;
    const bool texture = (p->flags & SSDA_TRACK_EXCLUDE) != 0u;
    const uint32_t pixels = (uint32_t)win->width * win->height; /* < 2^32 */
    scan_t s;
    int err;
    *decided = false;
    if (!mask && !texture && p->flat_q8 == 0u) {
        return SSDA_OK;
    }
    err = scan_pixels(win, p, mask, texture, p->flat_q8 != 0u, &s, &st->check_pixels);
    if (err != SSDA_OK) {
        return err;
    }
    *decided = true;
    if (s.masked) {
        v->status = (uint8_t)SSDA_TRACK_MASKED;
        return SSDA_OK;
    }
    /* dark = pixels - bright < min_count  <=>  bright > pixels - min_count
       (min_count <= pixels / 2 when texture is on, so no wrap) */
    if (texture &&
        (s.bright < p->texture_min_count || s.bright > pixels - p->texture_min_count)) {
        v->status = (uint8_t)SSDA_TRACK_EXCLUDED;
        return SSDA_OK;
    }
    if (p->flat_q8 != 0u) {
        err = texture_q8(win, s.sum, &v->texture_q8, &st->check_pixels);
        if (err != SSDA_OK) {
            return err;
        }
        if (v->texture_q8 < p->flat_q8) {
            v->status = (uint8_t)SSDA_TRACK_FLAT;
            return SSDA_OK;
        }
    }
    *decided = false;
    return SSDA_OK;
}

/* Whether a placement lies on the border of the range along an axis with
   n placements (an axis with one placement has no border). */
static bool on_border(uint32_t pos, uint32_t n)
{
    return n > 1u && (pos == 0u || pos == n - 1u);
}

/* The vector and status of a searched window from its search result. */
static void searched(const ssda_track_grid_t *g, const ssda_match_result_t *res,
                     ssda_track_vector_t *v)
{
    const uint32_t hx = ((uint32_t)g->search_w - g->win_w) / 2u;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    v->sad = res->sad;
    v->dx = (int32_t)hx - (int32_t)res->x;
    v->dy = (int32_t)hy - (int32_t)res->y;
    /* |dx| <= 65535: 256 dx fits; the offset is at most 128 */
    v->sub_dx_q8 = v->dx * 256 - res->sub_x_q8;
    v->sub_dy_q8 = v->dy * 256 - res->sub_y_q8;
    v->unique_q8 = res->unique_q8;
    v->exact = res->exact;
    if (on_border(res->x, (uint32_t)g->search_w - g->win_w + 1u) ||
        on_border(res->y, (uint32_t)g->search_h - g->win_h + 1u)) {
        v->status = (uint8_t)SSDA_TRACK_AT_LIMIT;
    } else if (res->unique_q8 != SSDA_MATCH_UNIQUE_NONE) {
        v->status = (uint8_t)SSDA_TRACK_AMBIGUOUS;
    } else {
        v->status = (uint8_t)SSDA_TRACK_OK;
    }
}

static void vector_init(ssda_track_vector_t *v, uint32_t wx, uint32_t wy)
{
    v->sad = 0u;
    v->dx = 0;
    v->dy = 0;
    v->sub_dx_q8 = 0;
    v->sub_dy_q8 = 0;
    v->texture_q8 = 0u;
    v->x = (uint16_t)wx;
    v->y = (uint16_t)wy;
    v->unique_q8 = (uint16_t)SSDA_MATCH_UNIQUE_NONE;
    v->exact = false;
    v->status = (uint8_t)SSDA_TRACK_EDGE;
}

#ifndef SSDA_CFG_NO_BOUNDS
/* The shared tables' rows for the area at source (ax, ay), their work
   counted. Out of line: its locals stay off the search's call chain. */
static SSDA_NOINLINE int tab_area(ssda__track_tab_t *tab, const ssda__rows_t *first,
                                  const ssda_track_grid_t *g, uint32_t ax, uint32_t ay,
                                  ssda_track_stats_t *st)
{
    uint64_t built = 0u;
    int err = ssda__track_tab_area(tab, first, g->win_w, ax, ay, &built);
    add_sat(&st->pixel_ops, built);
    return err;
}
#endif

/* Status and vector of window k; when no test decides it, the search. */
static int solve_window(const ssda__rows_t *first, const ssda__rows_t *second,
                        const ssda_track_plan_t *p, ssda_track_vector_t *out, uint32_t col,
                        uint32_t row, uint32_t col1, const ssda__track_origin_t *o,
                        ssda__track_tab_t *tab, ssda_track_vector_t *v,
                        ssda_track_stats_t *st)
{
    const ssda_track_grid_t *g = &p->grid;
    const uint32_t hx = ((uint32_t)g->search_w - g->win_w) / 2u;
    const uint32_t hy = ((uint32_t)g->search_h - g->win_h) / 2u;
    const uint32_t wx = g->roi_x + col * g->step_x; /* < second width <= 65535 */
    const uint32_t wy = g->roi_y + row * g->step_y;
    ssda__rows_t win, area;
    ssda_match_result_t res;
    int32_t pdx = 0, pdy = 0; /* predicted motion: none */
    bool decided;
    int err;

    vector_init(v, wx, wy);
    if (wx < hx || wy < hy || wx - hx + g->search_w > p->first_w ||
        wy - hy + g->search_h > p->first_h) {
        return SSDA_OK;
    }
    ssda__rows_sub(&win, second, wx - o->second_x, wy - o->second_y, g->win_w, g->win_h);
    ssda__rows_sub(&area, first, wx - hx - o->first_x, wy - hy - o->first_y, g->search_w,
                   g->search_h);
    err = window_tests(&win, p, v, st, &decided);
    if (err != SSDA_OK || decided) {
        return err;
    }
    if ((p->flags & SSDA_TRACK_MASK) != 0u) {
        scan_t s;
        err = scan_pixels(&area, p, true, false, false, &s, &st->check_pixels);
        if (err != SSDA_OK) {
            return err;
        }
        if (s.masked) {
            v->status = (uint8_t)SSDA_TRACK_MASKED;
            return SSDA_OK;
        }
    }
    if (p->predict != (uint8_t)SSDA_TRACK_PREDICT_NONE) {
        predict(p, out, col, row, col1, &pdx, &pdy);
    }
    /* the predicted placement (zero motion without prediction): where a
       PREDICT scan starts and what the tie rule is nearest to; |pd| <=
       65535: no overflow; the engine clamps */
#ifndef SSDA_CFG_NO_BOUNDS
    if (tab != NULL) { /* shared tables: this area's rows built or kept */
        err = tab_area(tab, first, g, wx - hx - o->first_x, wy - hy - o->first_y, st);
        if (err != SSDA_OK) {
            return err;
        }
    }
#else
    (void)tab; /* no bounds: no tables */
#endif
    err = ssda__match_rows(&area, &win, &p->match, (int32_t)hx - pdx, (int32_t)hy - pdy, &res);
    if (err != SSDA_OK) {
        return err;
    }
    searched(g, &res, v);
    add_sat(&st->pixel_ops, res.pixel_ops);
    add_sat(&st->positions, res.positions);
    add_sat(&st->completed, res.completed);
    return SSDA_OK;
}

static void stats_zero(ssda_track_stats_t *st)
{
    st->pixel_ops = 0u;
    st->positions = 0u;
    st->completed = 0u;
    st->check_pixels = 0u;
    st->windows = 0u;
    st->ok = 0u;
    st->excluded = 0u;
    st->masked = 0u;
    st->edge = 0u;
    st->flat = 0u;
    st->ambiguous = 0u;
    st->at_limit = 0u;
}

/* Solve columns col0 .. col1-1 of one grid row; up-right neighbours at
   columns >= ur_end are not solved yet. Same returns as ssda__track_part. */
static int solve_run(const ssda__rows_t *first, const ssda__rows_t *second,
                     const ssda_track_plan_t *plan, uint32_t row, uint32_t col0, uint32_t col1,
                     uint32_t ur_end, const ssda__track_origin_t *origin,
                     ssda__track_tab_t *tab, ssda_track_vector_t *out, ssda_track_stats_t *acc)
{
    uint32_t col;
    for (col = col0; col < col1; col++) {
        ssda_track_vector_t v;
        int err = solve_window(first, second, plan, out, col, row, ur_end, origin, tab, &v,
                               acc);
        if (err != SSDA_OK) {
            return err;
        }
        out[(size_t)row * plan->grid.cols + col] = v;
        acc->windows++;
        switch (v.status) {
        case SSDA_TRACK_OK: acc->ok++; break;
        case SSDA_TRACK_EXCLUDED: acc->excluded++; break;
        case SSDA_TRACK_MASKED: acc->masked++; break;
        case SSDA_TRACK_FLAT: acc->flat++; break;
        case SSDA_TRACK_AMBIGUOUS: acc->ambiguous++; break;
        case SSDA_TRACK_AT_LIMIT: acc->at_limit++; break;
        default: acc->edge++; break;
        }
    }
    return SSDA_OK;
}

int ssda__track_part(const ssda__rows_t *first, const ssda__rows_t *second,
                     const ssda_track_plan_t *plan, uint32_t col0, uint32_t col1,
                     uint32_t row0, uint32_t row1, const ssda__track_origin_t *origin,
                     ssda_track_vector_t *out, ssda_track_stats_t *acc)
{
    ssda__track_tab_t *t = NULL; /* shared tables, kept from grid row to grid row */
    uint32_t row;
#ifndef SSDA_CFG_NO_BOUNDS
    if (plan->tab_rows != 0u) {
        t = ssda__track_tab_init(plan, col0, col1, origin->first_x);
    }
#endif
    for (row = row0; row < row1; row++) {
        int err = solve_run(first, second, plan, row, col0, col1, col1, origin, t, out, acc);
        if (err != SSDA_OK) {
            return err;
        }
    }
    return SSDA_OK;
}

int ssda__track_span(const ssda__rows_t *first, const ssda__rows_t *second,
                     const ssda_track_plan_t *plan, uint32_t row, uint32_t col0, uint32_t col1,
                     ssda_track_vector_t *out, ssda_track_stats_t *acc)
{
    ssda__track_tab_t *t = NULL;
#ifndef SSDA_CFG_NO_BOUNDS
    if (plan->tab_rows != 0u) {
        t = ssda__track_tab_init(plan, col0, col1, 0u);
    }
#endif
    return solve_run(first, second, plan, row, col0, col1, plan->grid.cols,
                     &ssda__track_origin_whole, t, out, acc);
}

int ssda__track_prepare(const ssda__rows_t *first, const ssda__rows_t *second,
                        const ssda_track_config_t *cfg, size_t out_count,
                        ssda_track_plan_t *plan)
{
    int err;
    if (first->format != second->format) {
        return SSDA_ERR_FORMAT;
    }
    err = ssda__track_plan(cfg != NULL ? cfg : &ssda__track_defaults, second->format,
                           first->width, first->height, second->width, second->height, plan);
    if (err == SSDA_OK && !ssda__track_out_fits(plan->grid.count, out_count)) {
        err = SSDA_ERR_BUFFER;
    }
    return err;
}

int ssda__track_run(const ssda__rows_t *first, const ssda__rows_t *second,
                    const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                    size_t out_count, ssda_track_stats_t *stats)
{
    ssda_track_plan_t plan;
    ssda_track_stats_t st;
    int err = ssda__track_prepare(first, second, cfg, out_count, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    stats_zero(&st);
    err = ssda__track_strip(first, second, &plan, 0u, plan.grid.cols, out, &st);
    if (err == SSDA_OK && stats != NULL) {
        *stats = st;
    }
    return err;
}

int ssda__track_rows(const ssda__rows_t *first, const ssda__rows_t *second,
                     const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                     size_t out_count, ssda_track_stats_t *stats)
{
    int err;
    if (first == NULL || second == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    err = check_rows(first);
    if (err == SSDA_OK) {
        err = check_rows(second);
    }
    if (err != SSDA_OK) {
        return err;
    }
    return ssda__track_run(first, second, cfg, out, out_count, stats);
}
