/* warp_plan.c - the tile and plate of a warp (ssda_warp_plan). */
#include "warp_internal.h"

/* Geometry a plan needs from a source config. */
typedef struct {
    uint32_t w, h;          /* source size */
    uint32_t out_w, out_h;  /* output size (the map's grid) */
    uint8_t format, layout;
    uint32_t read_size, tile_w;
    bool bilinear;
} plan_geo_t;

/* Arena bytes of a read-once plate for n x m tiles. */
static size_t need_of(const ssda_poly_t *map, const plan_geo_t *g, uint32_t n, uint32_t m,
                      uint32_t *pw, uint32_t *ph, uint32_t *band)
{
    const uint32_t b = ssda__warp_band(map, g->bilinear, n, g->h);
    const uint32_t w = ssda__warp_span(map, g->bilinear, n, m, g->w);
    const uint32_t h = b + 1u < g->h ? b + 1u : g->h; /* one spare row */
    *pw = w;
    *ph = h;
    *band = b;
    return SSDA_SOURCE_SIZE(g->layout, w, h, g->format, g->read_size, g->tile_w);
}

/* The widest tile width for tiles m rows high whose plate fits `room`,
   0 if not even the narrowest does. Plates widen with the tile. */
static uint32_t widest(const ssda_poly_t *map, const plan_geo_t *g, uint32_t m, size_t room)
{
    uint32_t lo = g->out_w < SSDA_WARP_MIN_TILE ? g->out_w : SSDA_WARP_MIN_TILE;
    uint32_t hi = g->out_w, pw, ph, band;
    if (need_of(map, g, lo, m, &pw, &ph, &band) > room) {
        return 0u;
    }
    while (lo < hi) { /* need(lo) fits; find the last width that fits */
        const uint32_t mid = lo + (hi - lo + 1u) / 2u;
        if (need_of(map, g, mid, m, &pw, &ph, &band) <= room) {
            lo = mid;
        } else {
            hi = mid - 1u;
        }
    }
    return lo;
}

/* Choose the tile (see ssda_warp_plan). */
static void choose(const ssda_poly_t *map, const plan_geo_t *g, size_t room, uint32_t *n,
                   uint32_t *m)
{
    const uint32_t min_h = g->out_h < SSDA_WARP_MIN_TILE ? g->out_h : SSDA_WARP_MIN_TILE;
    uint32_t th = g->out_h;
    for (;;) {
        const uint32_t tw = widest(map, g, th, room);
        if (tw != 0u) {
            *n = tw;
            *m = th;
            return;
        }
        if (th <= min_h) {
            break;
        }
        th = th / 2u > min_h ? th / 2u : min_h;
    }
    *n = g->out_w < SSDA_WARP_MIN_TILE ? g->out_w : SSDA_WARP_MIN_TILE;
    *m = min_h;
}

/* The map's grid lies inside its domain on one axis: |X - c| <= 2^k for
   X = 0 .. size - 1 (true of every map from ssda_poly_init or
   ssda_poly_fit). The row stepping and the tile bounds rely on it: beyond
   it the 128-bit integer form of the map (poly_internal.h) can wrap. */
static bool grid_in_domain(uint32_t size, int32_t c, uint32_t k)
{
    const int64_t reach = ssda__pow2(k);
    return size > 0u && (int64_t)c >= -reach && (int64_t)c <= reach &&
           (int64_t)size - 1 - (int64_t)c <= reach && (int64_t)size - 1 - (int64_t)c >= -reach;
}

int ssda_warp_plan(const ssda_poly_t *map, uint8_t resample, const ssda_source_config_t *src,
                   uint16_t tile_w, uint16_t tile_h, ssda_warp_plan_t *plan)
{
    plan_geo_t g;
    ssda_warp_plan_t out;
    uint32_t n, m, pw, ph, band;
    if (map == NULL || src == NULL || plan == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__poly_valid(map) || !grid_in_domain(map->ref_w, map->cx, map->kx) ||
        !grid_in_domain(map->ref_h, map->cy, map->ky) ||
        resample > (uint8_t)SSDA_WARP_BILINEAR || tile_w > map->ref_w || tile_h > map->ref_h) {
        return SSDA_ERR_ARG;
    }
    if (src->format != (uint8_t)SSDA_PIX_U8 && src->format != (uint8_t)SSDA_PIX_U16) {
        return SSDA_ERR_FORMAT;
    }
    if (src->width == 0u || src->height == 0u ||
        (src->layout == (uint8_t)SSDA_LAYOUT_TILED && src->tile_w == 0u)) {
        return SSDA_ERR_SIZE;
    }
    g.w = src->width;
    g.h = src->height;
    g.out_w = map->ref_w;
    g.out_h = map->ref_h;
    g.format = src->format;
    g.layout = src->layout;
    g.read_size = src->read_size;
    g.tile_w = src->tile_w;
    g.bilinear = resample == (uint8_t)SSDA_WARP_BILINEAR;
    if (tile_w != 0u && tile_h != 0u) {
        n = tile_w;
        m = tile_h;
    } else if (src->arena_size == 0u) {
        n = tile_w != 0u ? tile_w : g.out_w;
        m = tile_h != 0u ? tile_h : g.out_h;
    } else {
        choose(map, &g, src->arena_size, &n, &m);
        if (tile_w != 0u) {
            n = tile_w;
        }
        if (tile_h != 0u) {
            m = tile_h;
        }
    }
    out.arena_size = need_of(map, &g, n, m, &pw, &ph, &band);
    out.tile_w = (uint16_t)n;
    out.tile_h = (uint16_t)m;
    out.plate_w = (uint16_t)pw;
    out.plate_h = (uint16_t)ph;
    out.band = (uint16_t)band;
    out.row_size = SSDA_WARP_ROW_SIZE(n, g.format);
    out.fits = src->arena_size != 0u && out.arena_size <= src->arena_size;
    *plan = out;
    return SSDA_OK;
}
