/*
 * register.c - control points per grid cell (register.h): the most
 * textured window, its match in the moving image, a sub-pixel peak.
 * Streamed sources read through plates planned per cell (the windows'
 * rectangle, the search area), so that every row is read once.
 */
#include <string.h>
#include "ssda/register.h"
#include "wide.h"
#include "stream_internal.h"
#include "fixmath.h"

/* A resolved configuration. */
typedef struct {
    uint32_t gx, gy, win, search, step;
    uint8_t metric;
    int32_t min_rho_q30;
    uint32_t min_texture;
    int32_t off_x, off_y;
    uint32_t bpp;
} reg_cfg_t;

/* Work buffer parts. */
typedef struct {
    uint8_t *win;    /* win x win, packed */
    uint8_t *area;   /* up to search x search, packed */
    void *match;     /* the search's own work */
    size_t match_size;
} reg_work_t;

static int resolve(const ssda_register_config_t *in, const ssda_source_t *ref, reg_cfg_t *c)
{
    ssda_register_config_t z;
    const ssda_register_config_t *cfg = in;
    if (cfg == NULL) {
        (void)memset(&z, 0, sizeof z);
        cfg = &z;
    }
    c->gx = cfg->grid_x != 0u ? cfg->grid_x : SSDA_REGISTER_DEFAULT_GRID;
    c->gy = cfg->grid_y != 0u ? cfg->grid_y : SSDA_REGISTER_DEFAULT_GRID;
    c->win = cfg->window != 0u ? cfg->window : SSDA_REGISTER_DEFAULT_WINDOW;
    c->search = cfg->search != 0u ? cfg->search : SSDA_REGISTER_DEFAULT_SEARCH;
    c->step = cfg->step != 0u ? cfg->step : (c->win / 4u > 0u ? c->win / 4u : 1u);
    c->metric = cfg->metric;
    c->min_rho_q30 = cfg->min_rho_q30 != 0 ? cfg->min_rho_q30 : SSDA_REGISTER_DEFAULT_MIN_RHO_Q30;
    c->bpp = ref->cfg.format;
    c->min_texture = cfg->min_texture != 0u ? cfg->min_texture : (c->bpp == 1u ? 4u : 1024u);
    c->off_x = cfg->offset_x;
    c->off_y = cfg->offset_y;
    if (c->gx > 256u || c->gy > 256u || c->win < 2u || c->win > 255u || c->search < c->win ||
        c->search > 1024u || c->metric > (uint8_t)SSDA_REGISTER_SAD || c->min_rho_q30 < 0 ||
        c->off_x < -65535 || c->off_x > 65535 || c->off_y < -65535 || c->off_y > 65535) {
        return SSDA_ERR_ARG;
    }
    return SSDA_OK;
}

/* A span of n px at (x, y) of s: the image's own pixels in RAM, else
   through the plate planned for the rectangle being read (a miss moves it
   as planned). */
static int fetch(ssda_source_t *s, uint32_t x, uint32_t y, uint32_t n, const uint8_t **px)
{
    if (s->view != NULL) {
        *px = s->view + (size_t)y * s->cfg.stride + (size_t)x * s->cfg.format;
        return SSDA_OK;
    }
    return ssda__stream_fetch(s, x, y, n, px);
}

/* Shape a streamed source's plate (in RAM: nothing) for the w x h
   rectangle at (x, y) read next: as wide as it (the job checked that
   `rows` rows of that width fit), as many rows as fit, its starts on a
   lattice of q rows from y. */
static void plan_plate(ssda_source_t *s, uint32_t x, uint32_t y, uint32_t w, uint32_t h,
                       uint32_t rows, uint32_t q)
{
    ssda_rect_t r;
    if (s->view != NULL) {
        return;
    }
    r.x = (uint16_t)x; /* inside the image: < 2^16 */
    r.y = (uint16_t)y;
    r.width = (uint16_t)w;
    r.height = (uint16_t)h;
    (void)ssda__stream_plate_shape(s, &r, w, rows, q, 0u); /* fits: checked */
}

/* Copy the w x h rectangle at (x, y) of s into dst (packed rows). */
static int copy_rect(ssda_source_t *s, uint32_t x, uint32_t y, uint32_t w, uint32_t h,
                     uint8_t *dst)
{
    const size_t row = (size_t)w * s->cfg.format;
    uint32_t r;
    for (r = 0u; r < h; r++) {
        const uint8_t *px;
        const int err = fetch(s, x, y + r, w, &px);
        if (err != SSDA_OK) {
            return err;
        }
        (void)memcpy(dst + (size_t)r * row, px, row);
    }
    return SSDA_OK;
}

/* n sum v^2 - (sum v)^2 of the win x win window at (x, y): exact (n <=
   65025, sum v < 2^32, sum v^2 < 2^48; the result < 2^64 + fits 128). */
static int window_spread(ssda_source_t *s, uint32_t x, uint32_t y, uint32_t win, ssda__i128_t *out)
{
    uint64_t s1 = 0u, s2 = 0u; /* < 65025 * 65535 < 2^32, < 65025 * 65535^2 < 2^48 */
    uint32_t r, i;
    for (r = 0u; r < win; r++) {
        const uint8_t *px;
        const int err = fetch(s, x, y + r, win, &px);
        if (err != SSDA_OK) {
            return err;
        }
        for (i = 0u; i < win; i++) {
            const uint32_t v = s->cfg.format == (uint8_t)SSDA_PIX_U8
                                   ? (uint32_t)px[i]
                                   : (uint32_t)((const uint16_t *)(const void *)px)[i];
            s1 += v;
            s2 += (uint64_t)v * v;
        }
    }
    *out = ssda__w_sub(ssda__w_mul64((int64_t)win * (int64_t)win, (int64_t)s2),
                       ssda__w_mul64((int64_t)s1, (int64_t)s1));
    return SSDA_OK;
}

/* The search area of the window with top-left (wx, wy): search x search
   px centred on the window's centre moved by the offset (its top-left
   moves with the window's), as [x0, x1) x [y0, y1) before clipping. */
static void area_of(const reg_cfg_t *c, uint32_t wx, uint32_t wy, int64_t *a)
{
    const uint32_t half = (c->search - c->win) / 2u;
    const int64_t margin = (int64_t)half;
    a[0] = (int64_t)wx + c->off_x - margin;
    a[1] = (int64_t)wy + c->off_y - margin;
    a[2] = a[0] + c->search;
    a[3] = a[1] + c->search;
}

/* The most textured window of one kind so far: n^2 * variance, top-left,
   and its pixels (kept in px, so that the window is not read again). */
typedef struct {
    ssda__i128_t v;
    uint32_t x, y;
    bool any;
    uint8_t *px;
} best_t;

/* Take the window at (x, y), of spread v, if it beats b (ties: the first,
   in raster order). Its rows are in the plate still (the spread was just
   taken from them): copying them reads nothing. */
static int keep_better(ssda_source_t *s, uint32_t win, best_t *b, uint32_t x, uint32_t y,
                       const ssda__i128_t *v)
{
    if (b->any && !ssda__w_lt(b->v, *v)) {
        return SSDA_OK;
    }
    b->v = *v;
    b->x = x;
    b->y = y;
    b->any = true;
    return copy_rect(s, x, y, win, win, b->px);
}

/* The most textured window of the cell [x0, x1) x [y0, y1): top-left in
   *bx, *by, its n^2 * variance in *best, its pixels in w->win. Windows
   whose whole search area lies in the moving image (mw x mh) come first:
   a match at the clipped edge of an area could not tell a window half
   outside the image; only when no window has such an area are the others
   taken (kept meanwhile in w->area, which holds a window). One sweep down
   the lattice, so a streamed reference's plate slides down once. */
static int most_textured(ssda_source_t *s, const reg_cfg_t *c, const uint32_t *cell,
                         uint32_t mw, uint32_t mh, const reg_work_t *w, uint32_t *bx,
                         uint32_t *by, ssda__i128_t *best)
{
    best_t in, all;
    uint32_t x, y;
    (void)memset(&in, 0, sizeof in);
    (void)memset(&all, 0, sizeof all);
    in.px = w->win;
    all.px = w->area;
    for (y = cell[2]; y + c->win <= cell[3]; y += c->step) {
        for (x = cell[0]; x + c->win <= cell[1]; x += c->step) {
            int64_t a[4];
            ssda__i128_t v;
            int err;
            area_of(c, x, y, a);
            err = window_spread(s, x, y, c->win, &v);
            if (err == SSDA_OK && a[0] >= 0 && a[1] >= 0 && a[2] <= (int64_t)mw &&
                a[3] <= (int64_t)mh) {
                err = keep_better(s, c->win, &in, x, y, &v);
            }
            if (err == SSDA_OK && !in.any) { /* the others matter only until then */
                err = keep_better(s, c->win, &all, x, y, &v);
            }
            if (err != SSDA_OK) {
                return err;
            }
        }
    }
    if (!in.any) {
        (void)memcpy(w->win, w->area, (size_t)c->win * c->win * c->bpp);
        in = all;
    }
    *bx = in.x;
    *by = in.y;
    *best = in.v;
    return SSDA_OK;
}

/* round(128 (a - b) / den) clamped to [-128, 128] (Q8 px), 0 when den is
   0: the vertex of a fit through (-1, a), (0, m), (1, b). */
static int32_t vertex_q8(int64_t a, int64_t b, int64_t den)
{
    ssda__i128_t q;
    int64_t v;
    if (den == 0) {
        return 0;
    }
    q = ssda__w_div_round(ssda__w_mul64(a - b, 128), ssda__w_i64(den));
    v = ssda__w_fits64(q) ? ssda__i128_to64(q) : 0;
    v = v > 128 ? 128 : (v < -128 ? -128 : v);
    return (int32_t)v;
}

/* Sub-pixel offset of a SAD minimum m between neighbours a and b: the
   equiangular (V-shaped) fit, which suits absolute differences (a
   parabola, right for squared differences and correlation, biases SAD
   peaks toward the integer): (a - b) / (2 (max(a, b) - m)). */
static int32_t sad_vertex_q8(int64_t a, int64_t m, int64_t b)
{
    return vertex_q8(a, b, (a > b ? a : b) - m); /* |.| < 2^48 */
}

/* SAD at (x, y) of the area, or -1 outside its placements. */
static int64_t sad_or_none(const ssda_view_t *area, const ssda_view_t *win, int64_t x, int64_t y)
{
    uint64_t sad;
    if (x < 0 || y < 0 || x + win->width > area->width || y + win->height > area->height) {
        return -1;
    }
    (void)ssda_sad_at(area, win, (uint16_t)x, (uint16_t)y, &sad);
    return (int64_t)sad; /* < 2^48 */
}

/* What a search found: the best placement, sub-pixel offsets, scores. */
typedef struct {
    uint32_t bx, by;
    int32_t ox, oy;
    int32_t rho_q30;
    uint64_t sad, ops;
} found_t;

/* A neighbour's rho, or RHO_NONE (beyond any rho, |rho| <= 2^30) outside
   the area's placements (SSDA_NCC_NONE in the neighbourhood result). */
#define RHO_NONE ((int64_t)-4294967296)
static int64_t rho_or_none(int32_t v)
{
    return v == SSDA_NCC_NONE ? RHO_NONE : (int64_t)v;
}

/* The correlation search: ssda_ncc_match with the 3 x 3 neighbourhood,
   parabolic sub-pixel offsets (on rho: its peak, also of a negative one). */
static void match_ncc(const ssda_view_t *area, const ssda_view_t *win, const reg_work_t *w,
                      uint8_t metric, found_t *f)
{
    ssda_ncc_config_t nc;
    ssda_ncc_result_t res;
    int64_t l, r, u, d, m;
    (void)memset(&nc, 0, sizeof nc);
    nc.metric = metric == (uint8_t)SSDA_REGISTER_NCC ? (uint8_t)SSDA_NCC_RHO : (uint8_t)SSDA_NCC_ABS;
    nc.flags = SSDA_NCC_AROUND;
    nc.work = w->match;
    nc.work_size = w->match_size;
    (void)ssda_ncc_match(area, win, &nc, &res); /* arguments checked by the caller */
    f->bx = res.x;
    f->by = res.y;
    f->rho_q30 = res.rho_q30;
    f->ops = res.pixel_ops;
    m = res.rho_q30;
    l = rho_or_none(res.around_q30[3]);
    r = rho_or_none(res.around_q30[5]);
    u = rho_or_none(res.around_q30[1]);
    d = rho_or_none(res.around_q30[7]);
    /* |rho| < 2^31: the sums below fit easily */
    f->ox = l != RHO_NONE && r != RHO_NONE ? vertex_q8(l, r, l - 2 * m + r) : 0;
    f->oy = u != RHO_NONE && d != RHO_NONE ? vertex_q8(u, d, u - 2 * m + d) : 0;
}

/* The SSDA search: the exact SAD minimum, equiangular sub-pixel offsets,
   and rho measured there. */
static void match_sad(const ssda_view_t *area, const ssda_view_t *win, const reg_work_t *w,
                      found_t *f)
{
    ssda_match_config_t mc;
    ssda_match_result_t res;
    int64_t s0, l, r, u, d;
    (void)memset(&mc, 0, sizeof mc);
    mc.flags = SSDA_MATCH_BOUNDS;
    mc.work = w->match;
    mc.work_size = w->match_size;
    (void)ssda_match(area, win, &mc, &res); /* arguments checked by the caller */
    f->bx = res.x;
    f->by = res.y;
    f->sad = res.sad;
    f->ops = res.pixel_ops;
    (void)ssda_ncc_at(area, win, res.x, res.y, &f->rho_q30);
    s0 = (int64_t)res.sad;
    l = sad_or_none(area, win, (int64_t)res.x - 1, res.y);
    r = sad_or_none(area, win, (int64_t)res.x + 1, res.y);
    u = sad_or_none(area, win, res.x, (int64_t)res.y - 1);
    d = sad_or_none(area, win, res.x, (int64_t)res.y + 1);
    f->ox = l >= 0 && r >= 0 ? sad_vertex_q8(l, s0, r) : 0;
    f->oy = u >= 0 && d >= 0 ? sad_vertex_q8(u, s0, d) : 0;
}

/* The status of a match (register.h, step 5). */
static ssda_register_status_t status_of(const reg_cfg_t *c, const ssda_view_t *area,
                                        const found_t *f)
{
    const int64_t rho = f->rho_q30;
    if (c->metric != (uint8_t)SSDA_REGISTER_SAD &&
        (c->metric == (uint8_t)SSDA_REGISTER_NCC ? rho : (rho < 0 ? -rho : rho)) <=
            (int64_t)c->min_rho_q30) {
        return SSDA_REGISTER_LOW_RHO;
    }
    if (f->bx == 0u || f->by == 0u || f->bx + c->win == area->width ||
        f->by + c->win == area->height) {
        return SSDA_REGISTER_BORDER;
    }
    return SSDA_REGISTER_OK;
}

/* One cell: fills *pt. */
static int cell(ssda_source_t *ref, ssda_source_t *mov, const reg_cfg_t *c, reg_work_t *w,
                uint32_t i, uint32_t j, ssda_register_point_t *pt)
{
    const uint32_t rw = ref->cfg.width, rh = ref->cfg.height;
    const uint32_t x0 = SSDA_DIV32(i * rw, c->gx), x1 = SSDA_DIV32((i + 1u) * rw, c->gx);
    const uint32_t y0 = SSDA_DIV32(j * rh, c->gy), y1 = SSDA_DIV32((j + 1u) * rh, c->gy);
    const int64_t n2 = (int64_t)c->win * c->win * c->win * c->win;
    const uint32_t cell_box[4] = {x0, x1, y0, y1};
    uint32_t wx = x0, wy = y0;
    found_t f;
    int64_t ax0, ay0, ax1, ay1;
    uint32_t aw, ah;
    ssda__i128_t spread = {0u, 0u}; /* hi, lo */
    ssda_view_t av, wv;
    int err;
    (void)memset(pt, 0, sizeof *pt);
    pt->cell_x = (uint16_t)i;
    pt->cell_y = (uint16_t)j;
    {
        /* the windows' rectangle: lattice columns and rows of the cell
           (cells hold a window, checked), read in bands of win rows */
        const uint32_t span_x = SSDA_DIV32(x1 - x0 - c->win, c->step) * c->step + c->win;
        const uint32_t span_y = SSDA_DIV32(y1 - y0 - c->win, c->step) * c->step + c->win;
        plan_plate(ref, x0, y0, span_x, span_y, c->win, c->step);
    }
    err = most_textured(ref, c, cell_box, mov->cfg.width, mov->cfg.height, w, &wx, &wy, &spread);
    if (err != SSDA_OK) {
        return err;
    }
    {
        /* texture = spread / n^2 (grey^2), saturated */
        const ssda__i128_t t = ssda__w_div_floor(spread, ssda__w_i64(n2));
        pt->texture = t.hi != 0u || t.lo > UINT32_MAX ? UINT32_MAX : (uint32_t)t.lo;
    }
    {
        /* centre = top-left + (win - 1) / 2, Q8: < 2^25 */
        const uint32_t rx = (2u * wx + c->win - 1u) * 128u, ry = (2u * wy + c->win - 1u) * 128u;
        pt->pair.ref_x_q8 = (int32_t)rx;
        pt->pair.ref_y_q8 = (int32_t)ry;
    }
    pt->pair.mov_x_q8 = pt->pair.ref_x_q8;
    pt->pair.mov_y_q8 = pt->pair.ref_y_q8;
    if (ssda__w_lt(spread, ssda__w_mul64(n2, (int64_t)c->min_texture))) {
        pt->status = (uint8_t)SSDA_REGISTER_FLAT;
        return SSDA_OK;
    }
    /* the area: search x search centred on the window's centre + offset
       (its top-left moves with the window's), clipped to the image */
    {
        int64_t a[4];
        area_of(c, wx, wy, a);
        ax0 = a[0];
        ay0 = a[1];
        ax1 = a[2];
        ay1 = a[3];
    }
    ax0 = ax0 < 0 ? 0 : ax0;
    ay0 = ay0 < 0 ? 0 : ay0;
    ax1 = ax1 > (int64_t)mov->cfg.width ? (int64_t)mov->cfg.width : ax1;
    ay1 = ay1 > (int64_t)mov->cfg.height ? (int64_t)mov->cfg.height : ay1;
    if (ax1 - ax0 < (int64_t)c->win || ay1 - ay0 < (int64_t)c->win) {
        pt->status = (uint8_t)SSDA_REGISTER_OUTSIDE;
        return SSDA_OK;
    }
    aw = (uint32_t)ax1 - (uint32_t)ax0; /* 0 <= ax0 < ax1 <= 65535 */
    ah = (uint32_t)ay1 - (uint32_t)ay0;
    /* the area, row by row through a plate of as many of its rows as fit */
    plan_plate(mov, (uint32_t)ax0, (uint32_t)ay0, aw, ah, 1u, ah);
    err = copy_rect(mov, (uint32_t)ax0, (uint32_t)ay0, aw, ah, w->area);
    if (err != SSDA_OK) {
        return err;
    }
    (void)ssda_view_init(&wv, w->win, (uint16_t)c->win, (uint16_t)c->win, c->win * c->bpp,
                         (ssda_pixfmt_t)c->bpp);
    (void)ssda_view_init(&av, w->area, (uint16_t)aw, (uint16_t)ah, aw * c->bpp,
                         (ssda_pixfmt_t)c->bpp);
    (void)memset(&f, 0, sizeof f);
    if (c->metric == (uint8_t)SSDA_REGISTER_SAD) {
        match_sad(&av, &wv, w, &f);
    } else {
        match_ncc(&av, &wv, w, c->metric, &f);
    }
    pt->sad = f.sad;
    pt->rho_q30 = f.rho_q30;
    pt->pixel_ops = f.ops;
    {
        /* the matched centre, Q8: < 2^25 */
        const int64_t mx = (2 * (ax0 + (int64_t)f.bx) + (int64_t)c->win - 1) * 128 + f.ox;
        const int64_t my = (2 * (ay0 + (int64_t)f.by) + (int64_t)c->win - 1) * 128 + f.oy;
        pt->pair.mov_x_q8 = (int32_t)mx;
        pt->pair.mov_y_q8 = (int32_t)my;
    }
    pt->status = (uint8_t)status_of(c, &av, &f);
    return SSDA_OK;
}

int ssda_register_points(ssda_source_t *ref, ssda_source_t *mov,
                         const ssda_register_config_t *cfg, ssda_register_point_t *out,
                         size_t out_count, size_t *accepted, void *work, size_t work_size)
{
    reg_cfg_t c;
    reg_work_t w;
    size_t ok = 0u, winb, areab;
    uint32_t i, j;
    int err;
    if (ref == NULL || mov == NULL || out == NULL || work == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(ref) || !ssda__stream_ready(mov)) {
        return SSDA_ERR_STATE;
    }
    if (ref->cfg.format != mov->cfg.format) {
        return SSDA_ERR_FORMAT;
    }
    err = resolve(cfg, ref, &c);
    if (err != SSDA_OK) {
        return err;
    }
    if (ssda__stream_plates_clash(ref, mov)) {
        return SSDA_ERR_ARG;
    }
    if (SSDA_DIV32(ref->cfg.width, c.gx) < c.win || SSDA_DIV32(ref->cfg.height, c.gy) < c.win ||
        out_count < (size_t)c.gx * c.gy) {
        return SSDA_ERR_SIZE;
    }
    winb = SSDA_REGISTER_ALIGN8_((size_t)c.win * c.win * c.bpp);
    areab = SSDA_REGISTER_ALIGN8_((size_t)c.search * c.search * c.bpp);
    if (work_size < SSDA_REGISTER_WORK_SIZE(c.win, c.search, c.bpp) ||
        (((uintptr_t)work) & 7u) != 0u) {
        return SSDA_ERR_BUFFER;
    }
    /* the plates that bound the reads (register.h): a band of win rows of
       the widest cell (SSDA_REGISTER_REF_SIZE; a narrower cell's plate is
       no larger: only a plate as wide as the image may take the image's
       shorter stride as pitch, and with cells of two widths neither is),
       a row of the search area (SSDA_REGISTER_MOV_SIZE) */
    if (!ssda__stream_holds(ref, SSDA_DIV32(ref->cfg.width + c.gx - 1u, c.gx), c.win, 0u) ||
        !ssda__stream_holds(mov, c.search < mov->cfg.width ? c.search : mov->cfg.width, 1u, 0u)) {
        return SSDA_ERR_BUFFER;
    }
    w.win = (uint8_t *)work;
    w.area = w.win + winb;
    w.match = w.area + areab;
    w.match_size = work_size - winb - areab;
    for (j = 0u; j < c.gy; j++) {
        for (i = 0u; i < c.gx; i++) {
            ssda_register_point_t *pt = &out[(size_t)j * c.gx + i];
            err = cell(ref, mov, &c, &w, i, j, pt);
            if (err != SSDA_OK) {
                return err;
            }
            ok += pt->status == (uint8_t)SSDA_REGISTER_OK ? 1u : 0u;
        }
    }
    if (accepted != NULL) {
        *accepted = ok;
    }
    return SSDA_OK;
}
