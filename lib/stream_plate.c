/*
 * stream_plate.c - the plate cache of a source: a w x h rectangle of the
 * image held in the arena at a fixed pitch, moved on a miss by the policy
 * written in stream.h, reading only the rows it does not already hold.
 *
 * Arena layout: plate row i at arena + i * pitch, its first pixel `head`
 * bytes in (raster: room for reads aligned down to read_size); tiled sources
 * keep a bounce buffer after the plate, into which runs of tile rows are read
 * and from which the plate's columns are copied.
 */
#include <string.h>
#include "stream_internal.h"

#define RS_ALIGN_DOWN(v, rs) ((v) - (v) % (rs))

static bool tiled(const ssda_source_t *s)
{
    return s->cfg.layout == (uint8_t)SSDA_LAYOUT_TILED;
}

/* Bytes the arena keeps outside the plate rows (tiled: the bounce buffer). */
static size_t reserve(const ssda_source_t *s)
{
    return tiled(s) ? SSDA_STREAM_BOUNCE_MIN(s->cfg.tile_w, s->cfg.format, s->cfg.read_size)
                    : 0u;
}

/* Pitch of a plate w px wide. Raster rows stored at the very pitch the plate
   would use are read several at a time (one read per plate load), so a
   stride within the pitch's rounding is taken as the pitch. */
static size_t pitch_for(const ssda_source_t *s, uint32_t w)
{
    const ssda_source_config_t *c = &s->cfg;
    size_t need, pitch;
    if (tiled(s)) {
        return SSDA_STREAM_TILED_PITCH(w, c->format);
    }
    need = SSDA_STREAM_HEAD(c->format, c->read_size) + (size_t)w * c->format +
           c->read_size - 1u;
    pitch = SSDA_STREAM_RASTER_PITCH(w, c->format, c->read_size);
    return c->stride >= need && c->stride <= pitch ? c->stride : pitch;
}

uint32_t stream_plate_fit_h(const ssda_source_t *s, uint32_t w)
{
    size_t room = s->cfg.arena_size;
    size_t h;
    if (room < reserve(s) || w == 0u) {
        return 0u;
    }
    h = (room - reserve(s)) / pitch_for(s, w);
    return h > SSDA_MAX_DIM ? SSDA_MAX_DIM : (uint32_t)h;
}

uint32_t stream_plate_fit_w(const ssda_source_t *s, uint32_t h)
{
    const ssda_source_config_t *c = &s->cfg;
    size_t room = c->arena_size;
    size_t w, fixed = 0u;
    if (room < reserve(s) || h == 0u) {
        return 0u;
    }
    room = ((room - reserve(s)) / h) & ~(size_t)3u; /* bytes of one row */
    if (!tiled(s)) {
        fixed = SSDA_STREAM_HEAD(c->format, c->read_size) + c->read_size - 1u;
    }
    if (room <= fixed) {
        return 0u;
    }
    w = (room - fixed) / c->format;
    return w > SSDA_MAX_DIM ? SSDA_MAX_DIM : (uint32_t)w;
}

int stream_plate_plan(ssda_source_t *s, const ssda_rect_t *r, uint32_t span,
                      uint32_t rows, uint32_t q)
{
    uint32_t w = r->width;
    uint32_t h = stream_plate_fit_h(s, w);
    size_t pitch;
    if (h < rows) {
        w = stream_plate_fit_w(s, rows);
        if (w >= span) {
            h = rows;
        } else {
            w = span;
            h = stream_plate_fit_h(s, w);
            if (h == 0u) {
                return SSDA_ERR_BUFFER;
            }
        }
    }
    if (h > r->height) {
        h = r->height;
    }
    pitch = pitch_for(s, w);
    /* plate bytes stay below 2^32 so that reads' sizes fit read()'s */
    while ((uint64_t)h * pitch > UINT32_MAX && h > 1u) {
        h--;
    }
    if (w != s->pw || h != s->ph || pitch != s->pitch) {
        s->pw = (uint16_t)w;
        s->ph = (uint16_t)h;
        s->pitch = (uint32_t)pitch;
        s->rows = 0u;
        s->head = tiled(s) ? 0u : (uint32_t)SSDA_STREAM_HEAD(s->cfg.format, s->cfg.read_size);
        s->bounce = (uint32_t)((size_t)h * pitch);
        s->bounce_size = (uint32_t)((s->cfg.arena_size - s->bounce) & ~(size_t)3u);
    }
    s->rx = r->x;
    s->ry = r->y;
    s->rw = r->width;
    s->rh = r->height;
    s->qy = (uint16_t)(q == 0u ? 1u : (q < h ? q : h));
    return SSDA_OK;
}

/* One read of [off, off + len) widened to read_size, into dest so that byte
   off lands at `at`. Counts it. Returns 0 or the callback's error. */
static int read_span(ssda_source_t *s, uint32_t off, uint64_t len, uint8_t *at)
{
    const uint32_t rs = s->cfg.read_size;
    uint32_t lo = RS_ALIGN_DOWN(off, rs);
    uint64_t hi = ((uint64_t)off + len + rs - 1u) / rs * rs; /* <= 2^32, checked at init */
    uint32_t size = (uint32_t)(hi - lo);
    int err;
    s->stats.reads++;
    s->stats.bytes_read += size;
    err = s->cfg.read(s->cfg.context, lo, at - (off - lo), size);
    return err > 0 ? SSDA_ERR_IO : err;
}

/* Raster: read plate rows [a, b), one read per row, or one for all of them
   when rows are stored at the plate's pitch. */
static int load_raster(ssda_source_t *s, uint32_t a, uint32_t b)
{
    const ssda_source_config_t *c = &s->cfg;
    const uint32_t len = (uint32_t)s->pw * c->format;
    const uint32_t per_read = s->pitch == c->stride ? b - a : 1u;
    uint8_t *plate = (uint8_t *)c->arena;
    while (a < b) {
        uint32_t n = per_read < b - a ? per_read : b - a;
        /* inside the image, below 2^32 (checked at init) */
        uint32_t off = c->offset + ((uint32_t)s->py0 + a) * c->stride +
                       (uint32_t)s->px0 * c->format;
        int err = read_span(s, off, (uint64_t)(n - 1u) * c->stride + len,
                            plate + (size_t)a * s->pitch + s->head);
        if (err != SSDA_OK) {
            return err;
        }
        a += n;
    }
    return SSDA_OK;
}

/* Tiled: for each tile row band and tile column the plate covers, read runs
   of tile rows (as many as the bounce buffer holds, columns cx0..cx1 only)
   and copy each row's columns into the plate. */
static int load_tiled(ssda_source_t *s, uint32_t a, uint32_t b)
{
    const ssda_source_config_t *c = &s->cfg;
    const uint32_t tw = c->tile_w, th = c->tile_h, bpp = c->format;
    const uint32_t across = ((uint32_t)c->width + tw - 1u) / tw;
    const uint32_t x_end = (uint32_t)s->px0 + s->pw;
    uint8_t *plate = (uint8_t *)c->arena;
    uint8_t *bounce = plate + s->bounce;
    uint32_t y = (uint32_t)s->py0 + a;
    const uint32_t y_end = (uint32_t)s->py0 + b;
    while (y < y_end) {
        uint32_t ty = y / th;
        uint32_t r0 = y - ty * th;
        uint32_t band = th - r0 < y_end - y ? th - r0 : y_end - y;
        uint32_t tx;
        for (tx = s->px0 / tw; tx * tw < x_end; tx++) {
            uint32_t cx0 = tx * tw > s->px0 ? tx * tw : s->px0;
            uint32_t cx1 = (tx + 1u) * tw < x_end ? (tx + 1u) * tw : x_end;
            uint32_t cw = (cx1 - cx0) * bpp;
            /* bounce_size >= cw + 2 (rs - 1): at least one row per read */
            uint32_t max_rows = (s->bounce_size - 2u * (c->read_size - 1u) - cw) / c->stride + 1u;
            uint32_t r = 0u;
            /* tile address < 2^32, checked at init */
            uint32_t tile = c->offset + (ty * across + tx) * c->tile_stride +
                            (cx0 - tx * tw) * bpp;
            while (r < band) {
                uint32_t n = band - r < max_rows ? band - r : max_rows;
                uint32_t off = tile + (r0 + r) * c->stride;
                uint32_t lead = off % c->read_size;
                uint32_t i;
                int err = read_span(s, off, (uint64_t)(n - 1u) * c->stride + cw, bounce + lead);
                if (err != SSDA_OK) {
                    return err;
                }
                for (i = 0u; i < n; i++) {
                    memcpy(plate + (size_t)(y - s->py0 + r + i) * s->pitch +
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
            start = r0 + (v - r0) / q * q;
        } else if (v + 1u > r0 + cap) {
            uint32_t lift = r0 + (v + 1u - cap - r0 + q - 1u) / q * q;
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
    const uint32_t ph = s->ph;
    uint8_t *plate = (uint8_t *)s->cfg.arena;
    uint32_t a = 0u, b = ph, i;
    int err;
    if (s->rows != 0u && x0 == s->px0) {
        if (y0 > s->py0 && y0 - s->py0 < ph) {
            uint32_t d = y0 - s->py0;
            for (i = 0u; i + d < ph; i++) { /* rows d.. move up to 0.. */
                memcpy(plate + (size_t)i * s->pitch, plate + (size_t)(i + d) * s->pitch, s->pitch);
            }
            a = ph - d;
        } else if (y0 < s->py0 && s->py0 - y0 < ph) {
            uint32_t d = s->py0 - y0;
            for (i = ph; i-- > d;) { /* rows ..ph-1-d move down to ..ph-1 */
                memcpy(plate + (size_t)i * s->pitch, plate + (size_t)(i - d) * s->pitch, s->pitch);
            }
            b = d;
        }
    }
    s->px0 = (uint16_t)x0;
    s->py0 = (uint16_t)y0;
    s->rows = 0u; /* empty until every row is in */
    err = tiled(s) ? load_tiled(s, a, b) : load_raster(s, a, b);
    if (err == SSDA_OK) {
        s->rows = (uint16_t)ph;
    }
    return err;
}

int stream_plate_fetch(ssda_source_t *s, uint32_t x, uint32_t y, uint32_t n,
                       const uint8_t **px)
{
    const bool have = s->rows != 0u;
    uint32_t x0 = s->px0, y0;
    int err;
    if (n > s->pw) {
        return SSDA_ERR_BUFFER;
    }
    s->stats.misses++;
    if (!have || x < x0 || x + n > x0 + s->pw) {
        x0 = place_x(x, s->pw, s->rx, s->rw, s->cfg.width);
    }
    y0 = place_y(y, s->py0, have, s->ph, s->ry, s->rh, s->qy, s->cfg.height);
    err = move(s, x0, y0);
    if (err != SSDA_OK) {
        return err;
    }
    *px = (const uint8_t *)s->cfg.arena + (size_t)(y - y0) * s->pitch + s->head +
          (size_t)(x - x0) * s->cfg.format;
    return SSDA_OK;
}
