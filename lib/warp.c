/*
 * warp.c - the warp job: tiles, the plate, and per-pixel sampling with the
 * map stepped by exact forward differences (warp.h).
 */
#include <string.h>
#include "warp_internal.h"
#include "stream_internal.h"
#include "state.h"


/* Where the sampled pixels are: the plate of a streamed source or the
   whole image in RAM. x0, y0: image position of `base`; pw x ph pixels
   valid (0 x 0: nothing yet). */
typedef struct {
    const uint8_t *base;
    uint32_t pitch;
    uint32_t x0, y0, pw, ph;
    uint64_t x0_q8, y0_q8;   /* x0 * 256, y0 * 256 */
    uint64_t lim_u, lim_v;   /* fast-path limits of (u - x0_q8), (v - y0_q8) */
} cache_t;

/* One tile's state. */
typedef struct {
    ssda_warp_t *job;
    ssda_rect_t region;  /* source rectangle the tile should need */
    bool has_region;
    cache_t c;
    uint64_t filled, moves;
} tile_t;

static void cache_set(cache_t *c, const ssda_source_t *s, bool bilinear)
{
    if (s->view != NULL) {
        c->base = s->view;
        c->pitch = s->cfg.stride;
        c->x0 = 0u;
        c->y0 = 0u;
        c->pw = s->cfg.width;
        c->ph = s->cfg.height;
    } else {
        c->base = (const uint8_t *)s->cfg.arena;
        c->pitch = s->plate.pitch;
        c->x0 = s->px0;
        c->y0 = s->py0;
        c->pw = s->rows != 0u ? s->plate.pw : 0u;
        c->ph = s->rows;
    }
    c->x0_q8 = (uint64_t)c->x0 << 8;
    c->y0_q8 = (uint64_t)c->y0 << 8;
    /* nearest: u + 128 - x0_q8 < pw * 256; bilinear: u - x0_q8 <
       (pw - 1) * 256, so that column i + 1 is in too (likewise rows) */
    if (bilinear) {
        c->lim_u = c->pw > 0u ? (uint64_t)(c->pw - 1u) << 8 : 0u;
        c->lim_v = c->ph > 0u ? (uint64_t)(c->ph - 1u) << 8 : 0u;
    } else {
        c->lim_u = (uint64_t)c->pw << 8;
        c->lim_v = (uint64_t)c->ph << 8;
    }
}

int ssda_warp_init(ssda_warp_t *job, const ssda_warp_config_t *cfg, ssda_source_t *src)
{
    ssda_warp_t j;
    ssda_warp_plan_t plan;
    ssda_source_config_t geo;
    bool bilinear;
    uint8_t format;
    int err;
    if (job == NULL || cfg == NULL || cfg->map == NULL || cfg->sink == NULL || cfg->row == NULL ||
        src == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(src)) {
        return SSDA_ERR_STATE;
    }
    format = src->cfg.format;
    bilinear = cfg->resample == (uint8_t)SSDA_WARP_BILINEAR;
    if (cfg->fill > (format == (uint8_t)SSDA_PIX_U8 ? 255u : 65535u)) {
        return SSDA_ERR_ARG;
    }
    geo = src->cfg;
    geo.arena_size = src->view != NULL ? 0u : src->cfg.arena_size;
    err = ssda_warp_plan(cfg->map, cfg->resample, &geo, cfg->tile_w, cfg->tile_h, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    if (format == (uint8_t)SSDA_PIX_U16 && (((uintptr_t)cfg->row) & 1u) != 0u) {
        return SSDA_ERR_STRIDE;
    }
    if (cfg->row_size < plan.row_size) {
        return SSDA_ERR_BUFFER;
    }
    if (src->view == NULL &&
        src->cfg.arena_size < SSDA_SOURCE_SIZE(src->cfg.layout, bilinear ? 2u : 1u,
                                               bilinear ? 2u : 1u, format, src->cfg.read_size,
                                               src->cfg.tile_w)) {
        return SSDA_ERR_BUFFER;
    }
    (void)memset(&j, 0, sizeof j);
    j.map = *cfg->map;
    j.src = src;
    j.sink = cfg->sink;
    j.context = cfg->context;
    j.row = cfg->row;
    j.tile_w = plan.tile_w;
    j.tile_h = plan.tile_h;
    j.band = plan.band;
    j.fill = cfg->fill;
    j.resample = cfg->resample;
    j.format = format;
    j.magic = SSDA__MAGIC_WARP; /* last (state.h) */
    *job = j;
    return SSDA_OK;
}

/* The high word of P: floor(256 * coordinate), as a signed value. */
static int64_t warp_q8_of(ssda__i128_t p)
{
    const ssda__i128_t h = {ssda__w_neg_p(p) ? UINT64_MAX : 0u, p.hi}; /* hi, lo */
    return ssda__i128_to64(h);
}

/* The source rectangle of tile [x0, x0+n) x [y0, y0+m) of the output: the
   corners' range widened by the curvature bound, in source pixels, clipped
   to the image, at least 2 x 2 for bilinear where the image allows. */
static bool tile_region(const ssda_warp_t *job, uint32_t x0, uint32_t y0, uint32_t n, uint32_t m,
                        ssda_rect_t *r)
{
    const ssda_poly_t *p = &job->map;
    const bool bil = job->resample == (uint8_t)SSDA_WARP_BILINEAR;
    const int64_t sw = job->src->cfg.width, sh = job->src->cfg.height;
    int64_t lo[2] = {0, 0}, hi[2] = {0, 0};
    uint32_t a, k;
    for (a = 0u; a < 2u; a++) {
        const int64_t *c = a == 0u ? p->u_q24 : p->v_q24;
        const int64_t d = ssda__warp_curve(p, c, n - 1u, m - 1u) + 1;
        for (k = 0u; k < 4u; k++) {
            const uint32_t cxk = (k & 1u) != 0u ? x0 + n - 1u : x0;
            const uint32_t cyk = (k & 2u) != 0u ? y0 + m - 1u : y0;
            const int32_t dx = (int32_t)cxk - p->cx;
            const int32_t dy = (int32_t)cyk - p->cy;
            const int64_t q = warp_q8_of(ssda__poly_p(p, c, dx, dy));
            lo[a] = k == 0u || q < lo[a] ? q : lo[a];
            hi[a] = k == 0u || q > hi[a] ? q : hi[a];
        }
        /* nearest rounds (+128); bilinear takes the pixel after as well */
        lo[a] = ssda__warp_px(lo[a] - d + (bil ? 0 : 128));
        hi[a] = ssda__warp_px(hi[a] + d + (bil ? 0 : 128)) + (bil ? 1 : 0);
    }
    if (hi[0] < 0 || hi[1] < 0 || lo[0] >= sw || lo[1] >= sh) {
        return false;
    }
    for (a = 0u; a < 2u; a++) {
        const int64_t lim = a == 0u ? sw : sh;
        lo[a] = lo[a] < 0 ? 0 : lo[a];
        hi[a] = hi[a] >= lim ? lim - 1 : hi[a];
        if (bil && hi[a] == lo[a] && lim > 1) { /* the 2 x 2 neighbourhood */
            if (hi[a] + 1 < lim) {
                hi[a]++;
            } else {
                lo[a]--;
            }
        }
    }
    r->x = (uint16_t)lo[0];
    r->y = (uint16_t)lo[1];
    {
        const int64_t rw = hi[0] - lo[0] + 1, rh = hi[1] - lo[1] + 1; /* 1..65535 */
        r->width = (uint16_t)rw;
        r->height = (uint16_t)rh;
    }
    return true;
}

/* Move the plate so that it holds columns [xa, xb] and rows [ya, yb]
   (inside the image; widths of at most 2): keep the columns if they are
   in, else take the tile region's left edge (or centre the span when the
   plate is narrower than the region); rows top-aligned when moving down,
   bottom-aligned when moving up. */
static int place(tile_t *t, uint32_t xa, uint32_t xb, uint32_t ya, uint32_t yb)
{
    ssda_source_t *s = t->job->src;
    const uint32_t W = s->cfg.width, H = s->cfg.height;
    const uint32_t pw = s->plate.pw, ph = s->plate.ph;
    uint32_t x0 = s->px0, y0;
    int err;
    if (s->rows == 0u || xa < s->px0 || xb >= (uint32_t)s->px0 + pw) {
        const ssda_rect_t *r = &t->region;
        if (t->has_region && pw >= r->width && xa >= r->x && xb < (uint32_t)r->x + r->width) {
            x0 = r->x;
        } else {
            const uint32_t slack = (pw - (xb - xa + 1u)) / 2u;
            x0 = xa > slack ? xa - slack : 0u;
        }
        x0 = x0 > W - pw ? W - pw : x0;
    }
    if (s->rows == 0u || ya >= s->py0) {
        y0 = ya;
    } else {
        y0 = yb + 1u > ph ? yb + 1u - ph : 0u;
    }
    y0 = y0 > H - ph ? H - ph : y0;
    err = ssda__stream_plate_place(s, x0, y0);
    t->moves++;
    cache_set(&t->c, s, t->job->resample == (uint8_t)SSDA_WARP_BILINEAR);
    return err;
}

static uint32_t px_at(const cache_t *c, uint8_t format, uint32_t x, uint32_t y)
{
    const uint8_t *p = c->base + (size_t)(y - c->y0) * c->pitch;
    return format == (uint8_t)SSDA_PIX_U8 ? p[x - c->x0]
                                         : ((const uint16_t *)(const void *)p)[x - c->x0];
}

/* Sample at (uq, vq) (Q8) the slow way: fill outside the source, the plate
   moved when the pixels are not in it. */
static SSDA_NOINLINE int sample_slow(tile_t *t, int64_t uq, int64_t vq, uint32_t *out)
{
    const ssda_warp_t *job = t->job;
    const ssda_source_t *s = job->src;
    const int64_t W = s->cfg.width, H = s->cfg.height;
    uint32_t xa, xb, ya, yb, fx = 0u, fy = 0u;
    if (job->resample == (uint8_t)SSDA_WARP_BILINEAR) {
        if (uq < 0 || vq < 0 || uq > (W - 1) * 256 || vq > (H - 1) * 256) {
            *out = job->fill;
            t->filled++;
            return SSDA_OK;
        }
        const uint64_t uu = (uint64_t)uq, vu = (uint64_t)vq; /* >= 0 here */
        const uint64_t ui = uu >> 8, vi = vu >> 8;
        xa = (uint32_t)ui;
        ya = (uint32_t)vi;
        fx = (uint32_t)uu & 255u;
        fy = (uint32_t)vu & 255u;
        xb = xa + (fx != 0u ? 1u : 0u);
        yb = ya + (fy != 0u ? 1u : 0u);
    } else {
        const int64_t iu = ssda__warp_px(uq + 128), iv = ssda__warp_px(vq + 128);
        if (iu < 0 || iv < 0 || iu >= W || iv >= H) {
            *out = job->fill;
            t->filled++;
            return SSDA_OK;
        }
        xa = (uint32_t)iu;
        xb = xa;
        ya = (uint32_t)iv;
        yb = ya;
    }
    if (xa < t->c.x0 || xb >= t->c.x0 + t->c.pw || ya < t->c.y0 || yb >= t->c.y0 + t->c.ph) {
        const int err = place(t, xa, xb, ya, yb);
        if (err != SSDA_OK) {
            return err;
        }
    }
    if (job->resample == (uint8_t)SSDA_WARP_BILINEAR) {
        const uint32_t p00 = px_at(&t->c, job->format, xa, ya), p01 = px_at(&t->c, job->format, xb, ya);
        const uint32_t p10 = px_at(&t->c, job->format, xa, yb), p11 = px_at(&t->c, job->format, xb, yb);
        *out = (((p00 * (256u - fx) + p01 * fx) * (256u - fy) + (p10 * (256u - fx) + p11 * fx) * fy) +
                32768u) >> 16;
    } else {
        *out = px_at(&t->c, job->format, xa, ya);
    }
    return SSDA_OK;
}

/* Bilinear weights of two neighbours, rounded: <= 65535 * 2^16 + 2^15. */
static inline uint32_t blend(uint32_t p00, uint32_t p01, uint32_t p10, uint32_t p11, uint32_t fx,
                             uint32_t fy)
{
    return (((p00 * (256u - fx) + p01 * fx) * (256u - fy) + (p10 * (256u - fx) + p11 * fx) * fy) +
            32768u) >> 16;
}

/* Before a segment of a streamed source: make the plate cover the rows
   the segment samples (its ends' v widened by the curvature bound), so
   that a row whose v falls along it (a rotation one way) does not move the
   plate once per pixel. Only when they fit the plate; else the pixels
   move it as needed. */
static int segment_rows(tile_t *t, uint32_t x, uint32_t y, uint32_t n, ssda__i128_t v_first)
{
    const ssda_warp_t *job = t->job;
    const ssda_poly_t *p = &job->map;
    const ssda_source_t *s = job->src;
    const bool bil = job->resample == (uint8_t)SSDA_WARP_BILINEAR;
    const int64_t d = ssda__warp_curve(p, p->v_q24, n - 1u, 0u) + 1;
    const int64_t v0 = warp_q8_of(v_first);
    const uint32_t xe = x + n - 1u;
    const int64_t v1 = warp_q8_of(ssda__poly_p(p, p->v_q24, (int32_t)xe - p->cx, (int32_t)y - p->cy));
    int64_t ra = ssda__warp_px((v0 < v1 ? v0 : v1) - d + (bil ? 0 : 128));
    int64_t rb = ssda__warp_px((v0 > v1 ? v0 : v1) + d + (bil ? 0 : 128)) + (bil ? 1 : 0);
    const uint32_t c_end = t->c.y0 + t->c.ph;
    uint32_t xa;
    ra = ra < (int64_t)t->region.y ? (int64_t)t->region.y : ra;
    rb = rb >= (int64_t)t->region.y + t->region.height ? (int64_t)t->region.y + t->region.height - 1 : rb;
    if (s->view != NULL || !t->has_region || ra > rb || rb - ra + 1 > (int64_t)s->plate.ph ||
        (t->c.ph != 0u && ra >= (int64_t)t->c.y0 && rb < (int64_t)c_end)) {
        return SSDA_OK;
    }
    xa = t->c.pw != 0u ? t->c.x0 : t->region.x;
    return place(t, xa, xa, (uint32_t)ra, (uint32_t)rb);
}

/* One output segment: n pixels from output (x, y) into the row buffer. */
static int segment(tile_t *t, uint32_t x, uint32_t y, uint32_t n)
{
    const ssda_warp_t *job = t->job;
    uint8_t *const out = t->job->row;
    const ssda_poly_t *p = &job->map;
    const bool bil = job->resample == (uint8_t)SSDA_WARP_BILINEAR;
    const bool u16 = job->format == (uint8_t)SSDA_PIX_U16;
    const uint32_t order = p->order;
    ssda__poly_fd_t fu, fv;
    uint32_t i;
    ssda__poly_fd_start(p, p->u_q24, (int32_t)x - p->cx, (int32_t)y - p->cy, &fu);
    ssda__poly_fd_start(p, p->v_q24, (int32_t)x - p->cx, (int32_t)y - p->cy, &fv);
    {
        const int err = segment_rows(t, x, y, n, fv.d[0]);
        if (err != SSDA_OK) {
            return err;
        }
    }
    for (i = 0u; i < n; i++) {
        /* offsets from the cache origin, modulo 2^64: a coordinate left of
           or above it wraps to a huge value and takes the slow path */
        const uint64_t a = fu.d[0].hi + (bil ? 0u : 128u) - t->c.x0_q8;
        const uint64_t b = fv.d[0].hi + (bil ? 0u : 128u) - t->c.y0_q8;
        uint32_t v;
        if (a < t->c.lim_u && b < t->c.lim_v) {
            const uint8_t *row = t->c.base + (size_t)(b >> 8) * t->c.pitch;
            const uint32_t col = (uint32_t)(a >> 8);
            if (!bil) {
                v = u16 ? ((const uint16_t *)(const void *)row)[col] : row[col];
            } else if (u16) {
                const uint16_t *r0 = (const uint16_t *)(const void *)row + col;
                const uint16_t *r1 = (const uint16_t *)(const void *)(row + t->c.pitch) + col;
                v = blend(r0[0], r0[1], r1[0], r1[1], (uint32_t)a & 255u, (uint32_t)b & 255u);
            } else {
                const uint8_t *r0 = row + col, *r1 = row + t->c.pitch + col;
                v = blend(r0[0], r0[1], r1[0], r1[1], (uint32_t)a & 255u, (uint32_t)b & 255u);
            }
        } else {
            const int err = sample_slow(t, warp_q8_of(fu.d[0]), warp_q8_of(fv.d[0]), &v);
            if (err != SSDA_OK) {
                return err;
            }
        }
        if (u16) {
            ((uint16_t *)(void *)out)[i] = (uint16_t)v;
        } else {
            out[i] = (uint8_t)v;
        }
        /* the next pixel: P, then its differences (order 1: D2 = D3 = 0) */
        fu.d[0] = ssda__w_add(fu.d[0], fu.d[1]);
        fv.d[0] = ssda__w_add(fv.d[0], fv.d[1]);
        if (order > 1u) {
            fu.d[1] = ssda__w_add(fu.d[1], fu.d[2]);
            fv.d[1] = ssda__w_add(fv.d[1], fv.d[2]);
            if (order > 2u) {
                fu.d[2] = ssda__w_add(fu.d[2], fu.d[3]);
                fv.d[2] = ssda__w_add(fv.d[2], fv.d[3]);
            }
        }
    }
    return job->sink(job->context, x, y, n, out);
}

/* Shape the plate for one tile of a streamed source. */
static void tile_begin(tile_t *t, uint32_t x0, uint32_t y0, uint32_t n, uint32_t m)
{
    ssda_source_t *s = t->job->src;
    const bool bil = t->job->resample == (uint8_t)SSDA_WARP_BILINEAR;
    t->has_region = tile_region(t->job, x0, y0, n, m, &t->region);
    if (s->view == NULL && t->has_region) {
        const uint32_t rows = (uint32_t)t->job->band + 1u < t->region.height
                                  ? (uint32_t)t->job->band + 1u : t->region.height;
        uint32_t span = 1u;
        if (bil && t->region.width > 1u) {
            span = 2u;
        }
        /* the arena holds a span x 2 plate (checked at init): no error */
        (void)ssda__stream_plate_shape(s, &t->region, span, rows, 1u, 0u);
    }
    cache_set(&t->c, s, bil);
}

int ssda_warp_run(ssda_warp_t *job, ssda_warp_stats_t *stats)
{
    tile_t t;
    uint32_t x0, y0, y;
    const uint32_t W = job != NULL ? job->map.ref_w : 0u, H = job != NULL ? job->map.ref_h : 0u;
    if (job == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(job->magic, SSDA__MAGIC_WARP)) {
        return SSDA_ERR_STATE;
    }
    (void)memset(&t, 0, sizeof t);
    t.job = job;
    for (x0 = 0u; x0 < W; x0 += job->tile_w) {
        const uint32_t n = W - x0 < job->tile_w ? W - x0 : job->tile_w;
        for (y0 = 0u; y0 < H; y0 += job->tile_h) {
            const uint32_t m = H - y0 < job->tile_h ? H - y0 : job->tile_h;
            tile_begin(&t, x0, y0, n, m);
            for (y = y0; y < y0 + m; y++) {
                const int err = segment(&t, x0, y, n);
                if (err != SSDA_OK) {
                    return err;
                }
            }
        }
    }
    if (stats != NULL) {
        stats->filled = t.filled;
        stats->moves = t.moves;
    }
    return SSDA_OK;
}
