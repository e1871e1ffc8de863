/*
 * ncc_search.c - the correlation search of ssda_ncc_match: sliding sums of
 * the area per group of window rows, one position after another in raster
 * order (the predicted one first), products summed group by group with the
 * exact early exit of ncc.h, and the best kept by the tie rule.
 */
#include <string.h>

#include "ncc_internal.h"
#include "kernel/kernels.h"
#include "fixmath.h"
#include "wide.h"

/* Positions whose bound cannot be tested in 64 bits keep going: the largest
   dot product of any placement is below 2^48 (n * m^2). */
#define DOT_LIMIT ((uint64_t)1u << 48)

typedef struct {
    const ssda_view_t *area;
    const ssda_view_t *win;
    ssda__ncc_win_t w;
    uint32_t L, M;          /* window width and height */
    uint32_t G, ng;         /* rows per group, groups */
    uint32_t x0, x1, y0, y1; /* positions scanned: a rectangle (inclusive) */
    uint32_t tw;            /* table width x1 - x0 + 1 */
    uint32_t px, py;        /* predicted position (clamped) */
    uint32_t r2;            /* SSDA_NCC_DISK: radius^2 (< 2^32) */
    uint32_t d;             /* floor(Sw / n): the window's integer mean */
    uint64_t inv_n;         /* floor(2^32 / n): placement means by a product */
    bool u8, abs, full, pred, disk;
    uint64_t *wsaa;         /* [i]: area sum of squares under the window at
                               (x0 + i, y), <= n * m^2 < 2^48 */
    uint32_t *wsa;          /* the sums, <= n * m < 2^32 */
    uint64_t *ring2;        /* [slot * tw + i]: L-wide sums of squares of the
                               area rows y .. y + M (< 2^48), row yy in slot
                               yy mod (M + 1) */
    uint32_t *ring1;        /*   and sums (< 2^32) */
    uint32_t slot0;         /* the slot of row y */
    uint64_t *ew_rest;      /* [g]: sum of (W - d)^2 over the rows after group
                               g, <= n * m^2 < 2^48 */
    uint64_t *sw_rest;      /* [g]: window sum over those rows, < 2^32 */
    ssda__ncc_key_t best;
    uint32_t bx, by;
    bool have;
    uint64_t beta;          /* floor(num_b^2 / var_b) <= var_w < 2^62; 0: no cuts */
    uint64_t ops;           /* pixel operations, < 2^64 for any accepted job */
    uint32_t positions, completed;
} engine_t;

/* Lay the tables out in the work buffer (8-byte arrays first). */
static void layout(engine_t *e, uint64_t *q)
{
    uint32_t *p;
    const size_t r = ((size_t)e->M + 1u) * e->tw;
    e->wsaa = q;
    e->ring2 = q + e->tw;
    e->ew_rest = q + e->tw + r;
    e->sw_rest = e->ew_rest + e->ng;
    p = (uint32_t *)(void *)(e->sw_rest + e->ng);
    e->wsa = p;
    e->ring1 = p + e->tw;
}

/* Rows of group g (the last may be short). */
static uint32_t group_rows(const engine_t *e, uint32_t g)
{
    const uint32_t top = g * e->G;
    return e->M - top < e->G ? e->M - top : e->G;
}

/* The window's sums over the rows after each group, and its mean. */
static void window_rest(engine_t *e)
{
    uint32_t g = e->ng;
    uint64_t ss = 0u; /* sum of squares of the rows below, < 2^48 */
    uint32_t s = 0u;  /* their sum, < 2^32 */
    uint32_t n_rest = 0u;
    e->d = e->w.sw / e->w.n; /* setup only */
    e->inv_n = ((uint64_t)1u << 32) / e->w.n;
    while (g > 0u) {
        uint32_t r;
        g--;
        /* rows after group g: E = sum W^2 - 2 d sum W + d^2 n_R >= 0 */
        e->sw_rest[g] = s;
        e->ew_rest[g] = ss + (uint64_t)e->d * e->d * n_rest - 2u * (uint64_t)e->d * s;
        for (r = 0u; r < group_rows(e, g); r++) {
            const uint8_t *p = ssda_view_row(e->win, g * e->G + r);
            uint32_t i;
            for (i = 0u; i < e->L; i++) {
                const uint32_t v = e->u8 ? p[i] : ((const uint16_t *)(const void *)p)[i];
                const uint32_t sq = v * v; /* < 2^32 */
                s += v;
                ss += sq;
            }
        }
        n_rest += group_rows(e, g) * e->L;
    }
    e->ops += 2u * (uint64_t)e->w.n;
}

/* L-wide sums and sums of squares of n + L - 1 samples from p, sliding:
   s[i] = p[i] + ... + p[i + L - 1] (< 2^32), ss likewise (< 2^48). */
static void window_sums_u8(const uint8_t *p, uint32_t L, uint32_t n, uint32_t *s, uint64_t *ss)
{
    uint32_t a = 0u, i;
    uint64_t q = 0u;
    for (i = 0u; i < L; i++) {
        const uint32_t sq = (uint32_t)p[i] * p[i];
        a += p[i];
        q += sq;
    }
    s[0] = a;
    ss[0] = q;
    for (i = 1u; i < n; i++) {
        const uint32_t in = p[i + L - 1u];
        const uint32_t out = p[i - 1u];
        const uint32_t in2 = in * in;
        const uint32_t out2 = out * out;
        a = a + in - out;
        q = q + in2 - out2; /* the sum holds out^2: no wrap */
        s[i] = a;
        ss[i] = q;
    }
}

#ifndef SSDA_CFG_NO_U16
static void window_sums_u16(const uint16_t *p, uint32_t L, uint32_t n, uint32_t *s, uint64_t *ss)
{
    uint32_t a = 0u, i;
    uint64_t q = 0u;
    for (i = 0u; i < L; i++) {
        const uint32_t sq = (uint32_t)p[i] * p[i]; /* < 2^32 */
        a += p[i];
        q += sq;
    }
    s[0] = a;
    ss[0] = q;
    for (i = 1u; i < n; i++) {
        const uint32_t in = p[i + L - 1u];
        const uint32_t out = p[i - 1u];
        const uint32_t in2 = in * in; /* < 2^32 */
        const uint32_t out2 = out * out;
        a = a + in - out;
        q = q + in2 - out2; /* the sum holds out^2: no wrap */
        s[i] = a;
        ss[i] = q;
    }
}
#endif

/* Area row yy's sums into its ring slot. */
static void ring_row(engine_t *e, uint32_t yy)
{
    const size_t off = (size_t)(yy % (e->M + 1u)) * e->tw;
    const uint8_t *p = ssda_view_row(e->area, yy) + (size_t)e->x0 * ssda_view_bpp(e->area);
#ifndef SSDA_CFG_NO_U16
    if (!e->u8) {
        window_sums_u16((const uint16_t *)(const void *)p, e->L, e->tw, e->ring1 + off,
                        e->ring2 + off);
    } else
#endif
    {
        window_sums_u8(p, e->L, e->tw, e->ring1 + off, e->ring2 + off);
    }
    e->ops += 2u * ((uint64_t)e->L + 2u * ((uint64_t)e->tw - 1u));
}

/* Window sums for the positions of row y0, from scratch. */
static void tables_init(engine_t *e)
{
    uint32_t r, i;
    (void)memset(e->wsa, 0, (size_t)e->tw * sizeof *e->wsa);
    (void)memset(e->wsaa, 0, (size_t)e->tw * sizeof *e->wsaa);
    for (r = 0u; r < e->M; r++) {
        const size_t off = (size_t)((e->y0 + r) % (e->M + 1u)) * e->tw;
        ring_row(e, e->y0 + r);
        for (i = 0u; i < e->tw; i++) {
            e->wsa[i] += e->ring1[off + i];
            e->wsaa[i] += e->ring2[off + i];
        }
    }
    e->slot0 = e->y0 % (e->M + 1u);
    e->ops += 2u * (uint64_t)e->M * e->tw;
}

/* Slide the window sums one row down (positions of row y to those of
   y + 1): area row y + M, summed now, in; row y out. */
static void tables_slide(engine_t *e, uint32_t y)
{
    const size_t out = (size_t)e->slot0 * e->tw; /* row y */
    /* row y + M goes to the slot of row y - 1, just before row y's */
    const size_t in = (size_t)(e->slot0 == 0u ? e->M : e->slot0 - 1u) * e->tw;
    uint32_t i;
    ring_row(e, y + e->M);
    for (i = 0u; i < e->tw; i++) {
        e->wsa[i] = e->wsa[i] + e->ring1[in + i] - e->ring1[out + i];
        e->wsaa[i] = e->wsaa[i] + e->ring2[in + i] - e->ring2[out + i];
    }
    e->slot0 = e->slot0 == e->M ? 0u : e->slot0 + 1u;
    e->ops += 4u * (uint64_t)e->tw;
}

/* Keep (x, y) if it beats the best by rho, then by the tie rule. */
static void offer(engine_t *e, const ssda__ncc_key_t *k, uint32_t x, uint32_t y)
{
    if (e->have) {
        const int c = ssda__ncc_cmp(k, &e->best, e->abs);
        if (c < 0 || (c == 0 && (y > e->by || (y == e->by && x > e->bx)))) {
            return;
        }
    }
    e->best = *k;
    e->bx = x;
    e->by = y;
    e->have = true;
    e->beta = 0u;
    if (!e->full && (k->num > 0 || (e->abs && k->num < 0))) {
        /* num^2 / var = rho^2 var_w <= var_w < 2^62: the quotient fits */
        const uint64_t m = k->num < 0 ? (uint64_t)(-k->num) : (uint64_t)k->num;
        e->beta = ssda__div_128_64(ssda__mul_64x64(m, m), k->var);
    }
}

/* Upper bound of sqrt(a * b) without a root: (a k + b / k) / 2 for k a
   power of two near sqrt(b / a), rounded up: at most 1.25 sqrt(ab) + 1
   (sqrt(a b) for a or b zero is 0; the bound then is a loose b / 2^k, valid
   all the same), < 2^50 for a, b < 2^49. */
static uint64_t amgm(uint64_t a, uint64_t b)
{
    const uint32_t la = ssda__bitlen64(a);
    const uint32_t lb = ssda__bitlen64(b);
    uint32_t k;       /* |log2 of the power of two|, <= 32 */
    uint64_t round;   /* 2^k - 1: the shifted-out part, to round up */
    if (lb >= la) {
        k = (lb - la) / 2u;
        round = ((uint64_t)1u << k) - 1u;
        return ((a << k) + ((b + round) >> k) + 1u) >> 1;
    }
    k = (la - lb) / 2u;
    round = ((uint64_t)1u << k) - 1u;
    return (((a + round) >> k) + (b << k) + 1u) >> 1;
}

/* The state of one position during its products. */
typedef struct {
    uint64_t dot;       /* products summed so far, < 2^48 */
    uint64_t saa_done;  /* area sum of squares of the groups summed, < 2^48 */
    uint32_t sa_done;   /* their sum, < 2^32 */
    uint32_t sa;        /* the placement's sum, < 2^32 */
    uint64_t saa;       /* and sum of squares, < 2^48 */
    uint32_t c;         /* its integer mean (any value keeps the bound valid) */
    ssda__u128_t zsq;   /* beta * var: the square of the num to reach */
} pos_t;

/* After group g of the position at table column i: can it still win? */
static bool cut_after(engine_t *e, pos_t *p, uint32_t g, uint32_t i)
{
    const uint32_t rows_left = e->M - (g + 1u) * e->G;
    const uint64_t n_r = (uint64_t)rows_left * e->L;     /* < 2^16 */
    uint64_t saa_r, ea, b, sasw, m, cw, ds, cdn;
    uint32_t sa_r, r;
    uint32_t slot = e->slot0 + g * e->G; /* < 2 (M + 1): one wrap at most */
    int64_t base, ub, lb;
    if (slot > e->M) {
        slot -= e->M + 1u;
    }
    /* the area sums of group g's rows, from the ring */
    for (r = 0u; r < e->G; r++) {
        const size_t off = (size_t)slot * e->tw + i;
        p->sa_done += e->ring1[off];
        p->saa_done += e->ring2[off];
        slot = slot == e->M ? 0u : slot + 1u;
    }
    e->ops += 2u * (uint64_t)e->G;
    sa_r = p->sa - p->sa_done;
    saa_r = p->saa - p->saa_done;
    /* sum over R of (S - c)^2, exact: each term < 2^49 */
    ea = saa_r + (uint64_t)p->c * p->c * n_r - 2u * (uint64_t)p->c * sa_r;
    b = amgm(ea, e->ew_rest[g]);
    /* sum_R S W = c Sw_R + d Sa_R - c d n_R + sum_R (S - c)(W - d), |.| <= b;
       every term < 2^50, so base and both bounds fit int64 */
    cw = (uint64_t)p->c * e->sw_rest[g];
    ds = (uint64_t)e->d * sa_r;
    cdn = (uint64_t)p->c * e->d * n_r;
    base = (int64_t)p->dot + (int64_t)cw + (int64_t)ds - (int64_t)cdn;
    ub = base + (int64_t)b;
    lb = base - (int64_t)b;
    e->ops++;
    sasw = (uint64_t)p->sa * e->w.sw;
    /* ub >= the true dot >= 0 (b >= |sum_R (S - c)(W - d)|). A bound at or
       above 2^48, more than any dot, cannot cut: keep going (defensive;
       1.25 times the Cauchy-Schwarz bound is not known to get there). */
    if ((uint64_t)ub >= DOT_LIMIT) {
        return false;
    }
    /* m: the largest num (|num| for abs) the position can still reach */
    m = 0u;
    if ((uint64_t)ub * e->w.n >= sasw) {
        m = (uint64_t)ub * e->w.n - sasw; /* n * ub < 2^16 * 2^48 */
    } else if (!e->abs) {
        return true; /* num < 0 < the best's */
    } else {
        /* num < 0: the other side bounds |num| */
    }
    if (e->abs) {
        /* -num <= Sa Sw - n lb, with lb <= the true dot < 2^48 */
        if (lb < 0) {
            return false; /* unbounded here: keep going */
        }
        if ((uint64_t)lb * e->w.n < sasw) {
            const uint64_t m2 = sasw - (uint64_t)lb * e->w.n;
            m = m2 > m ? m2 : m;
        }
    }
    return ssda__cmp_128(ssda__mul_64x64(m, m), p->zsq) < 0;
}

/* The products of position (x, y) group by group; false when cut. */
static bool sum_products(engine_t *e, pos_t *p, uint32_t x, uint32_t y, uint32_t i)
{
    const uint32_t bpp = ssda_view_bpp(e->area);
    const bool check = e->beta != 0u;
    uint32_t g;
    for (g = 0u; g < e->ng; g++) {
        const uint32_t top = g * e->G;
        const uint32_t rows = group_rows(e, g);
        const uint8_t *a = ssda_view_row(e->area, y + top) + (size_t)x * bpp;
        const uint8_t *w = ssda_view_row(e->win, top);
        if (e->u8) {
            p->dot += ssda__dot_u8(a, e->area->stride, w, e->win->stride, e->L, rows);
        } else {
            p->dot += ssda__dot_u16((const uint16_t *)(const void *)a, e->area->stride,
                                    (const uint16_t *)(const void *)w, e->win->stride,
                                    e->L, rows);
        }
        e->ops += (uint64_t)rows * e->L;
        if (check && g + 1u < e->ng && cut_after(e, p, g, i)) {
            return false;
        }
    }
    return true;
}

/* Evaluate (x, y) whose sums are sa, saa; i: its table column. */
static void evaluate(engine_t *e, uint32_t x, uint32_t y, uint32_t sa, uint64_t saa, uint32_t i)
{
    pos_t p;
    ssda__ncc_key_t k;
    e->positions++;
    k.var = (uint64_t)e->w.n * saa - (uint64_t)sa * sa; /* < 2^62, >= 0 */
    k.num = 0;
    if (k.var != 0u) {
        p.dot = 0u;
        p.sa_done = 0u;
        p.saa_done = 0u;
        p.sa = sa;
        p.saa = saa;
        p.c = (uint32_t)(((uint64_t)sa * e->inv_n) >> 32); /* <= sa / n <= m */
        p.zsq = ssda__mul_64x64(e->beta, k.var); /* unused when beta = 0 */
        if (!sum_products(e, &p, x, y, i)) {
            return;
        }
        e->completed++;
        k.num = ssda__ncc_num(e->w.n, p.dot, sa, e->w.sw);
    }
    offer(e, &k, x, y);
}

/* The x range of the positions scanned on row y (y0 <= y <= y1, so
   |y - py| <= radius with SSDA_NCC_DISK: the range is never empty). */
static void row_span(const engine_t *e, uint32_t y, uint32_t *xa, uint32_t *xb)
{
    const uint32_t dy = y > e->py ? y - e->py : e->py - y;
    *xa = e->x0;
    *xb = e->x1;
    if (e->disk) {
        const uint32_t h = ssda__isqrt64((uint64_t)e->r2 - (uint64_t)dy * dy);
        if (e->px - e->x0 > h) {
            *xa = e->px - h;
        }
        if (e->x1 - e->px > h) {
            *xb = e->px + h;
        }
    }
}

static void scan(engine_t *e)
{
    uint32_t y;
    tables_init(e);
    for (y = e->y0; y <= e->y1; y++) {
        uint32_t xa, xb, x;
        if (y != e->y0) {
            tables_slide(e, y - 1u);
        }
        row_span(e, y, &xa, &xb);
        for (x = xa; x <= xb; x++) {
            const uint32_t i = x - e->x0;
            if (e->pred && x == e->px && y == e->py) {
                continue; /* evaluated first */
            }
            evaluate(e, x, y, e->wsa[i], e->wsaa[i], i);
        }
    }
}

static uint32_t clamp_pos(int32_t v, uint32_t n)
{
    if (v < 0) {
        return 0u;
    }
    return (uint32_t)v >= n ? n - 1u : (uint32_t)v;
}

/* Resolve the geometry and options of one search. */
static void setup(engine_t *e, const ssda_view_t *area, const ssda_view_t *window,
                  const ssda_ncc_config_t *cfg)
{
    const uint32_t nx = (uint32_t)area->width - window->width + 1u;
    const uint32_t ny = (uint32_t)area->height - window->height + 1u;
    (void)memset(e, 0, sizeof *e);
    e->area = area;
    e->win = window;
    e->L = window->width;
    e->M = window->height;
    e->G = (63u + e->L) / e->L; /* setup only */
    if (e->G > e->M) {
        e->G = e->M;
    }
    e->ng = (e->M + e->G - 1u) / e->G;
    e->u8 = area->format == (uint8_t)SSDA_PIX_U8;
    e->abs = cfg->metric == (uint8_t)SSDA_NCC_ABS;
    e->full = (cfg->flags & SSDA_NCC_FULL) != 0u;
    e->disk = (cfg->flags & SSDA_NCC_DISK) != 0u;
    e->pred = e->disk || (cfg->flags & SSDA_NCC_PREDICT) != 0u;
    e->px = clamp_pos(cfg->predict_x, nx);
    e->py = clamp_pos(cfg->predict_y, ny);
    e->x1 = nx - 1u;
    e->y1 = ny - 1u;
    if (e->disk) {
        const uint32_t r = cfg->radius;
        e->r2 = r * r;
        e->x0 = e->px > r ? e->px - r : 0u;
        e->y0 = e->py > r ? e->py - r : 0u;
        e->x1 = nx - 1u - e->px > r ? e->px + r : nx - 1u;
        e->y1 = ny - 1u - e->py > r ? e->py + r : ny - 1u;
    }
    e->tw = e->x1 - e->x0 + 1u;
    layout(e, (uint64_t *)cfg->work); /* 8-byte aligned (checked) */
}

/* rho of the 8 neighbours of the best position (SSDA_NCC_AROUND). */
static void around(engine_t *e, ssda_ncc_result_t *res)
{
    const uint32_t nx = (uint32_t)e->area->width - e->L + 1u;
    const uint32_t ny = (uint32_t)e->area->height - e->M + 1u;
    uint32_t j, i;
    for (j = 0u; j < 3u; j++) {
        for (i = 0u; i < 3u; i++) {
            const uint32_t x = e->bx + i; /* x + 1: 0 means outside */
            const uint32_t y = e->by + j;
            int32_t *out = &res->around_q30[j * 3u + i];
            ssda__ncc_key_t k;
            if (x == 0u || y == 0u || x > nx || y > ny) {
                *out = SSDA_NCC_NONE;
            } else if (i == 1u && j == 1u) {
                *out = res->rho_q30;
            } else {
                ssda__ncc_place(e->area, e->win, &e->w, x - 1u, y - 1u, &k, &e->ops);
                *out = ssda__ncc_rho_q30(&k, e->w.var_w);
            }
        }
    }
}

void ssda__ncc_search(const ssda_view_t *area, const ssda_view_t *window,
                      const ssda_ncc_config_t *cfg, ssda_ncc_result_t *result)
{
    engine_t e;
    ssda_ncc_result_t res;
    setup(&e, area, window, cfg);
    ssda__ncc_window(window, &e.w, &e.ops);
    (void)memset(&res, 0, sizeof res);
    if (e.w.var_w == 0u) {
        /* flat window: rho = 0 everywhere; the first position scanned by the
           tie rule wins, found without reading the area */
        uint32_t xb = 0u;
        e.by = e.y0;
        row_span(&e, e.by, &e.bx, &xb);
        res.flags = SSDA_NCC_FLAT_WINDOW;
    } else {
        window_rest(&e);
        if (e.pred) {
            ssda__ncc_key_t k;
            e.positions++;
            ssda__ncc_place(area, window, &e.w, e.px, e.py, &k, &e.ops);
            e.completed += k.var != 0u ? 1u : 0u;
            offer(&e, &k, e.px, e.py);
        }
        scan(&e);
        res.rho_q30 = ssda__ncc_rho_q30(&e.best, e.w.var_w);
    }
    res.x = (uint16_t)e.bx;
    res.y = (uint16_t)e.by;
    if ((cfg->flags & SSDA_NCC_AROUND) != 0u) {
        around(&e, &res);
    }
    res.positions = e.positions;
    res.completed = e.completed;
    res.pixel_ops = e.ops;
    *result = res;
}
