/*
 * stream_plate.c - the plate cache of a source: a w x h rectangle of the
 * image held in the arena at a fixed pitch, moved on a miss by the policy
 * written in stream.h, reading only the rows it does not already hold.
 *
 * Arena layout: plate row i at arena + i * pitch (rows 4-byte aligned),
 * then the bounce buffer. Raster rows with read_size 1 are read straight
 * into the plate (several rows per read when they are stored at the
 * plate's pitch). Every other read (widened to read_size, or a run of tile
 * rows) lands in the bounce buffer, and its pixels are copied into the
 * plate: the plate itself never holds alignment slack.
 */
#include <string.h>
#include "stream_internal.h"
#include "fixmath.h"
#include "slide.h"

static bool tiled(const ssda_source_t *s)
{
    return STREAM_LAYOUT(&s->cfg) == (uint8_t)SSDA_LAYOUT_TILED;
}

/* Arena bytes a plan may use: all of it, up to 2^31 (so that every read's
   size, widened, fits 32 bits). */
static size_t room_of(const ssda_source_t *s)
{
    return s->cfg.arena_size < 0x80000000u ? s->cfg.arena_size : 0x80000000u;
}

/* Smallest bounce buffer of a plate w px wide (0: reads go to the plate). */
static size_t bounce_min(const ssda_source_t *s, uint32_t w)
{
    const ssda_source_config_t *c = &s->cfg;
    return SSDA_STREAM_BOUNCE(STREAM_LAYOUT(c), w, c->format, STREAM_READ_SIZE(c), c->tile_w);
}

/* Pitch of a plate w px wide. Raster rows read straight into the plate at
   the very pitch they are stored at are read several at a time (one read
   per plate load), so a stride within the pitch's rounding is taken. */
static size_t pitch_for(const ssda_source_t *s, uint32_t w)
{
    const ssda_source_config_t *c = &s->cfg;
    size_t pitch = SSDA_STREAM_PITCH(w, c->format);
    if (bounce_min(s, w) == 0u && c->stride >= (size_t)w * c->format && c->stride <= pitch) {
        return c->stride;
    }
    return pitch;
}

/* Arena bytes of a w x h plate and its smallest bounce buffer. */
static size_t plate_bytes(const ssda_source_t *s, uint32_t w, uint32_t h)
{
    return (size_t)h * pitch_for(s, w) + bounce_min(s, w);
}

uint32_t ssda__stream_plate_fit_h(const ssda_source_t *s, uint32_t w, size_t extra)
{
    size_t room = room_of(s);
    size_t h;
    if (w == 0u) { /* LCOV_EXCL_BR_LINE callers pass w >= 1; guards the division by pitch_for(s, 0) = 0 */
        return 0u; /* LCOV_EXCL_LINE (the guard above) */
    }
    if (room < extra || room - extra < bounce_min(s, w)) {
        return 0u;
    }
    h = SSDA_DIV32(room - extra - bounce_min(s, w), pitch_for(s, w));
    return h > SSDA_MAX_DIM ? SSDA_MAX_DIM : (uint32_t)h;
}

uint32_t ssda__stream_plate_fit_w(const ssda_source_t *s, uint32_t h, size_t extra)
{
    const ssda_source_config_t *c = &s->cfg;
    const size_t rows = (size_t)h + (tiled(s) || STREAM_READ_SIZE(c) == 1u ? 0u : 1u);
    const size_t fixed = (tiled(s) ? bounce_min(s, 1u) : 2u * ((size_t)STREAM_READ_SIZE(c) - 1u)) + 3u;
    size_t room = room_of(s);
    size_t w;
    if (h == 0u) { /* LCOV_EXCL_BR_LINE callers pass h >= 1; guards the division by rows * format = 0 */
        return 0u; /* LCOV_EXCL_LINE (the guard above) */
    }
    if (room < extra) {
        return 0u;
    }
    room -= extra;
    /* a width whose rounded rows surely fit, then up to the last that fits */
    w = room > fixed + 3u * rows ? SSDA_DIV32(room - fixed - 3u * rows, rows * c->format) : 0u;
    if (w > SSDA_MAX_DIM) {
        w = SSDA_MAX_DIM;
    }
    while (w < SSDA_MAX_DIM && plate_bytes(s, (uint32_t)w + 1u, h) <= room) {
        w++;
    }
    while (w > 0u && plate_bytes(s, (uint32_t)w, h) > room) {
        w--;
    }
    return (uint32_t)w;
}

int ssda__stream_plate_plan(ssda_source_t *s, const ssda_rect_t *r, uint32_t span,
                            uint32_t rows, uint32_t q, size_t extra, ssda_source_plan_t *plan)
{
    uint32_t w = r->width;
    uint32_t h = ssda__stream_plate_fit_h(s, w, extra);
    size_t pitch;
    if (h < rows) {
        w = ssda__stream_plate_fit_w(s, rows, extra);
        if (w >= span) {
            h = rows;
        } else {
            w = span;
            h = ssda__stream_plate_fit_h(s, w, 0u);
            if (h == 0u) {
                return SSDA_ERR_BUFFER;
            }
        }
    }
    if (h > r->height) {
        h = r->height;
    }
    pitch = pitch_for(s, w); /* h * pitch <= room_of(s) <= 2^31 */
    /* pitch_for depends on w and the source's fixed config only: the same
       w gives the same pitch, so a plate planned into the source keeps its
       pixels when its shape holds (the plan reads only s->cfg before) */
    if (plan == &s->plate && (w != s->plate.pw || h != s->plate.ph)) {
        s->rows = 0u;
    }
    plan->pw = (uint16_t)w;
    plan->ph = (uint16_t)h;
    plan->pitch = (uint32_t)pitch;
    plan->bounce = (uint32_t)((size_t)h * pitch);
    plan->bounce_size = bounce_min(s, w) == 0u
                            ? 0u
                            : (uint32_t)((room_of(s) - plan->bounce) & ~(size_t)3u);
    plan->region = *r;
    plan->qy = (uint16_t)(q == 0u ? 1u : (q < h ? q : h));
    return SSDA_OK;
}

/* One read of [off, off + len) widened to read_size, so that byte off lands
   at `at`. Counts it. Returns 0 or the callback's error. len <= 2^31 (a
   plate or bounce buffer) and read_size <= 2^16: the sum cannot wrap, and
   the widened end stays below 2^32 (checked at init). */
static int read_span(ssda_source_t *s, uint32_t off, uint32_t len, uint8_t *at)
{
    const uint32_t rs = STREAM_READ_SIZE(&s->cfg);
    const uint32_t lead = SSDA_MOD32(off, rs);
    const uint32_t lo = off - lead;
    const uint32_t size = SSDA_DIV32(lead + len + rs - 1u, rs) * rs;
    int err;
    s->stats.reads++;
    s->stats.bytes_read += size;
    err = s->cfg.read(s->cfg.context, lo, at - (off - lo), size);
    return err > 0 ? SSDA_ERR_IO : err;
}

/* Raster, read_size 1: plate rows [a, b) straight into the plate, one read
   per row, or one for all of them when rows are stored at the pitch. */
static int load_direct(ssda_source_t *s, uint32_t a, uint32_t b)
{
    const ssda_source_config_t *c = &s->cfg;
    const uint32_t len = (uint32_t)s->plate.pw * c->format;
    const uint32_t per_read = s->plate.pitch == c->stride ? b - a : 1u;
    uint8_t *plate = (uint8_t *)c->arena;
    while (a < b) {
        uint32_t n = per_read < b - a ? per_read : b - a;
        /* inside the image, below 2^32 (checked at init) */
        uint32_t off = c->offset + ((uint32_t)s->py0 + a) * c->stride +
                       (uint32_t)s->px0 * c->format;
        int err = read_span(s, off, (n - 1u) * c->stride + len, plate + (size_t)a * s->plate.pitch);
        if (err != SSDA_OK) {
            return err;
        }
        a += n;
    }
    return SSDA_OK;
}

#if !defined(SSDA_CFG_NO_TILED) || !defined(SSDA_CFG_NO_READ_SIZE)
/* Through the bounce buffer: for each band of rows inside one tile row and
   each tile column the plate covers (raster: the image is one tile), read
   runs of rows of columns cx0..cx1 (as many rows as the bounce buffer
   holds; raster rows only when they are whole, so that no gap between
   them is read) and copy each row's pixels into the plate. */
static int load_bounced(ssda_source_t *s, uint32_t a, uint32_t b)
{
    const ssda_source_config_t *c = &s->cfg;
    const bool t = tiled(s);
    const uint32_t bpp = c->format;
    const uint32_t tw = t ? c->tile_w : c->width;
    const uint32_t th = t ? c->tile_h : c->height;
    const uint32_t across = t ? SSDA_DIV32((uint32_t)c->width + tw - 1u, tw) : 1u;
    const uint32_t x_end = (uint32_t)s->px0 + s->plate.pw;
    const uint32_t y_end = (uint32_t)s->py0 + b;
    uint8_t *plate = (uint8_t *)c->arena;
    uint8_t *bounce = plate + s->plate.bounce;
    uint32_t y = (uint32_t)s->py0 + a;
    while (y < y_end) {
        uint32_t ty = SSDA_DIV32(y, th);
        uint32_t r0 = y - ty * th;
        uint32_t band = th - r0 < y_end - y ? th - r0 : y_end - y;
        uint32_t tx;
        for (tx = SSDA_DIV32(s->px0, tw); tx * tw < x_end; tx++) {
            uint32_t cx0 = tx * tw > s->px0 ? tx * tw : s->px0;
            uint32_t cx1 = (tx + 1u) * tw < x_end ? (tx + 1u) * tw : x_end;
            uint32_t cw = (cx1 - cx0) * bpp;
            /* bounce_size >= cw + 2 (rs - 1): at least one row per read */
            uint32_t max_rows = !t && cw != c->stride
                                    ? 1u
                                    : SSDA_DIV32(s->plate.bounce_size - 2u * (STREAM_READ_SIZE(c) - 1u) - cw, c->stride) + 1u;
            uint32_t r = 0u;
            /* address < 2^32, checked at init */
            uint32_t base = c->offset + (ty * across + tx) * c->tile_stride + (cx0 - tx * tw) * bpp;
            while (r < band) {
                uint32_t n = band - r < max_rows ? band - r : max_rows;
                uint32_t off = base + (r0 + r) * c->stride;
                uint32_t lead = SSDA_MOD32(off, STREAM_READ_SIZE(c));
                uint32_t i;
                int err = read_span(s, off, (n - 1u) * c->stride + cw, bounce + lead);
                if (err != SSDA_OK) {
                    return err;
                }
                for (i = 0u; i < n; i++) {
                    (void)memcpy(plate + (size_t)(y - s->py0 + r + i) * s->plate.pitch +
                                     (size_t)(cx0 - s->px0) * bpp,
                                 bounce + lead + (size_t)i * c->stride, cw);
                }
                r += n;
            }
        }
        y += band;
    }
    return SSDA_OK;
}

#endif

/* Where a plate of cap px starts to cover the span at column v: at the
   region's left edge if it is as wide as the region, else at v, kept inside
   the region [r0, r0 + rlen) and the image. */
static uint32_t place_x(uint32_t v, uint32_t cap, uint32_t r0, uint32_t rlen, uint32_t img)
{
    uint32_t start = v;
    if (v - r0 < rlen) {
        if (cap >= rlen) {
            return r0;
        }
        if (start > r0 + rlen - cap) {
            start = r0 + rlen - cap;
        }
    }
    return start > img - cap ? img - cap : start;
}

/* Where a plate of cap rows starts to cover row v. Starts lie on the
   lattice r0 + k * q of the region (q = rows between the bands a job
   visits: a grid step, or the slack of a raster scan's band): moving down
   (or into an empty plate) to the first lattice start that covers v, which
   keeps the most rows above; moving up to the last one at or above v. */
static uint32_t place_y(uint32_t v, uint32_t cur, bool have, uint32_t cap, uint32_t r0,
                        uint32_t rlen, uint32_t q, uint32_t img)
{
    uint32_t start = v;
    if (v - r0 < rlen) {
        if (cap >= rlen) {
            return r0;
        }
        if (have && v < cur) {
            start = r0 + SSDA_DIV32(v - r0, q) * q;
        } else if (v + 1u > r0 + cap) {
            uint32_t lift = r0 + SSDA_DIV32(v + 1u - cap - r0 + q - 1u, q) * q;
            start = lift < v ? lift : v;
        } else {
            start = r0;
        }
        if (start > r0 + rlen - cap) {
            start = r0 + rlen - cap;
        }
    }
    return start > img - cap ? img - cap : start;
}

/* Move the plate to (x0, y0): keep the rows it already holds when the
   columns stay, read the others. */
static int move(ssda_source_t *s, uint32_t x0, uint32_t y0)
{
    const uint32_t ph = s->plate.ph;
    uint8_t *plate = (uint8_t *)s->cfg.arena;
    uint32_t a = 0u, b = ph;
    int err;
    if (s->rows != 0u && x0 == s->px0) {
        if (y0 > s->py0 && y0 - s->py0 < ph) {
            uint32_t d = y0 - s->py0;
            /* rows d.. move up to 0.. */
            ssda__slide(plate, (size_t)d * s->plate.pitch, (size_t)ph * s->plate.pitch);
            a = ph - d;
        } else if (y0 < s->py0 && s->py0 - y0 < ph) {
            uint32_t d = s->py0 - y0;
            uint32_t i = ph;
            while (i > d) { /* rows ..ph-1-d move down to ..ph-1 */
                i--;
                (void)memcpy(plate + (size_t)i * s->plate.pitch, plate + (size_t)(i - d) * s->plate.pitch, s->plate.pitch);
            }
            b = d;
        } else {
            /* no row in common: every row is read */
        }
    }
    s->px0 = (uint16_t)x0;
    s->py0 = (uint16_t)y0;
    s->rows = 0u; /* empty until every row is in */
#if defined(SSDA_CFG_NO_TILED) && defined(SSDA_CFG_NO_READ_SIZE)
    err = load_direct(s, a, b); /* no bounce buffer in this build */
#else
    err = s->plate.bounce_size != 0u ? load_bounced(s, a, b) : load_direct(s, a, b);
#endif
    if (err == SSDA_OK) {
        s->rows = (uint16_t)ph;
    }
    return err;
}

int ssda__stream_plate_place(ssda_source_t *s, uint32_t x0, uint32_t y0)
{
    if (s->rows != 0u && s->px0 == x0 && s->py0 == y0) {
        s->stats.hits++;
        return SSDA_OK;
    }
    s->stats.misses++;
    return move(s, x0, y0);
}

int ssda__stream_plate_fetch(ssda_source_t *s, uint32_t x, uint32_t y, uint32_t n,
                       const uint8_t **px)
{
    const bool have = s->rows != 0u;
    uint32_t x0 = s->px0, y0;
    int err;
    if (n > s->plate.pw) {
        return SSDA_ERR_BUFFER;
    }
    s->stats.misses++;
    if (!have || x < x0 || x + n > x0 + s->plate.pw) {
        x0 = place_x(x, s->plate.pw, s->plate.region.x, s->plate.region.width, s->cfg.width);
    }
    y0 = place_y(y, s->py0, have, s->plate.ph, s->plate.region.y, s->plate.region.height, s->plate.qy, s->cfg.height);
    err = move(s, x0, y0);
    if (err != SSDA_OK) {
        return err;
    }
    *px = (const uint8_t *)s->cfg.arena + (size_t)(y - y0) * s->plate.pitch +
          (size_t)(x - x0) * s->cfg.format;
    return SSDA_OK;
}
