/*
 * fuzz_stream.c - streamed sources (include/ssda/stream.h) with image
 * geometry, storage layout, strides, read granularity, arena sizes and
 * read failures from the fuzzer's bytes. The device here serves reads from
 * a byte array and aborts on any read outside the contract (misaligned,
 * empty, or beyond the aligned image).
 * One job per input, each against its in-RAM twin:
 *   - ssda_stream_match == ssda_match on the same pixels, field for field;
 *   - ssda_stream_track == ssda_track (vectors, statuses, window counts);
 *   - ssda_source_row spans == the image's pixels;
 *   - push-mode search (ssda_push_init_match / ssda_push_row) == ssda_match.
 * Arenas: below SSDA_SOURCE_SIZE(.., 1, 1, ..) init refuses (SSDA_ERR_BUFFER,
 * source untouched); at or above the job's documented minimum the job
 * succeeds; SSDA_ERR_BUFFER comes only below it, before any read, with
 * the result untouched (below it a job may also succeed: the macros are
 * sufficient sizes, and a raster source whose stride lies within the
 * 4-byte rounding of a row is held at its own stride). A failed read's code
 * comes back unchanged with the result untouched, and the same job on the
 * same sources succeeds right after.
 */
#include <string.h>

#include "fuzz_input.h"
#include "ssda/stream.h"

#define MAX_IMG 48u
#define DEV_BYTES 65536u
#define ARENA_BYTES 32768u
#define MAX_OUT 2400u

typedef struct {
    uint8_t bytes[DEV_BYTES];
    uint32_t size; /* device bytes: the aligned image extent */
    uint32_t rs;
    int64_t fail_at; /* index of the read to fail, -1 never */
    int fail_code;
    uint64_t reads, failures;
} device_t;

static device_t g_dev[2];
static uint32_t g_arena[2][ARENA_BYTES / 4u];
static uint16_t g_img[2][MAX_IMG * MAX_IMG];
static uint32_t g_work[(MAX_IMG + 1u) * MAX_IMG + 2u * MAX_IMG + 8u];
static ssda_track_vector_t g_want[MAX_OUT], g_got[MAX_OUT];
static uint32_t g_ring[(MAX_IMG * 2u + 4u) * MAX_IMG / 4u + 4u];

static uint32_t next_rand(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static int dev_read(void *ctx, uint32_t off, void *buf, uint32_t size)
{
    device_t *d = (device_t *)ctx;
    FUZZ_CHECK(size > 0u && off % d->rs == 0u && size % d->rs == 0u);
    FUZZ_CHECK((uint64_t)off + size <= d->size);
    if ((int64_t)d->reads++ == d->fail_at) {
        d->failures++;
        return d->fail_code;
    }
    memcpy(buf, d->bytes + off, size);
    return 0;
}

/* How one image is stored, and its source's arena. */
typedef struct {
    int streamed;
    ssda_source_config_t cfg;
    size_t init_min;
} store_t;

/* Choose a storage for image i (w x h, bpp) and write it into device i.
   Returns 0 if the choice does not fit the device (then use RAM). */
static int make_store(fuzz_in_t *in, uint32_t i, const ssda_view_t *img, store_t *st)
{
    device_t *d = &g_dev[i];
    ssda_source_config_t *c = &st->cfg;
    uint32_t bpp = img->format, rs, stride, tstride, x, y;
    uint64_t end;
    memset(c, 0, sizeof *c);
    c->read = dev_read;
    c->context = d;
    c->width = img->width;
    c->height = img->height;
    c->format = img->format;
    c->layout = (uint8_t)(fuzz_u8(in) & 1u);
    c->offset = fuzz_range(in, 0, 300) * bpp;
    rs = fuzz_u8(in) % 8u;
    c->read_size = rs == 0u ? 0u : rs == 1u ? 1u : rs == 7u ? 4096u : fuzz_range(in, 1, 24) * bpp;
    d->rs = c->read_size > 1u ? c->read_size : 1u;
    if (c->layout == SSDA_LAYOUT_TILED) {
        c->tile_w = (uint16_t)fuzz_range(in, 1, 20);
        c->tile_h = (uint16_t)fuzz_range(in, 1, 20);
        stride = (c->tile_w + fuzz_range(in, 0, 3)) * bpp;
        tstride = (c->tile_h - 1u) * stride + c->tile_w * bpp + fuzz_range(in, 0, 4) * bpp;
        c->stride = fuzz_u8(in) & 1u ? 0u : stride;
        if (c->stride == 0u) {
            stride = c->tile_w * bpp;
            tstride = (c->tile_h - 1u) * stride + c->tile_w * bpp + fuzz_range(in, 0, 4) * bpp;
        }
        c->tile_stride = fuzz_u8(in) & 1u ? 0u : tstride;
        if (c->tile_stride == 0u) {
            tstride = stride * c->tile_h;
        }
        end = (uint64_t)(((c->width + c->tile_w - 1u) / c->tile_w) *
                         ((c->height + c->tile_h - 1u) / c->tile_h) - 1u) * tstride +
              (uint64_t)(c->tile_h - 1u) * stride + (uint64_t)c->tile_w * bpp;
    } else {
        stride = (c->width + fuzz_range(in, 0, 5)) * bpp;
        c->stride = fuzz_u8(in) & 1u ? 0u : stride;
        if (c->stride == 0u) {
            stride = c->width * bpp;
        }
        tstride = 0;
        end = (uint64_t)(c->height - 1u) * stride + (uint64_t)c->width * bpp;
    }
    end += c->offset;
    end = (end + d->rs - 1u) / d->rs * d->rs;
    if (end > DEV_BYTES) {
        return 0;
    }
    d->size = (uint32_t)end;
    memset(d->bytes, 0xA5, d->size); /* padding: poison */
    for (y = 0; y < c->height; y++) {
        for (x = 0; x < c->width; x++) {
            uint64_t off;
            if (c->layout == SSDA_LAYOUT_TILED) {
                uint32_t across = (c->width + c->tile_w - 1u) / c->tile_w;
                off = c->offset + ((uint64_t)(y / c->tile_h) * across + x / c->tile_w) * tstride +
                      (uint64_t)(y % c->tile_h) * stride + (uint64_t)(x % c->tile_w) * bpp;
            } else {
                off = c->offset + (uint64_t)y * stride + (uint64_t)x * bpp;
            }
            memcpy(d->bytes + off, (const uint8_t *)img->data + (size_t)y * img->stride + x * bpp,
                   bpp);
        }
    }
    c->arena = g_arena[i];
    st->init_min = SSDA_SOURCE_SIZE(c->layout, 1u, 1u, bpp, c->read_size, c->tile_w);
    st->streamed = 1;
    return 1;
}

/* An arena size near the interesting boundaries: init's minimum, the job's
   minimum, or anything up to the whole buffer. */
static size_t pick_arena(fuzz_in_t *in, size_t init_min, size_t job_min)
{
    size_t a;
    switch (fuzz_u8(in) % 8u) {
    case 0: a = init_min - 1u; break;
    case 1: a = init_min; break;
    case 2: a = job_min - 1u; break;
    case 3: a = job_min; break;
    case 4: a = job_min + fuzz_range(in, 0, 64); break;
    case 5: a = ARENA_BYTES; break;
    default: a = job_min + fuzz_range(in, 0, ARENA_BYTES); break;
    }
    return a > ARENA_BYTES ? ARENA_BYTES : a;
}

/* Init source i: streamed (arena as given) or a view. Returns the init
   code; checks the refusal of a short arena. */
static int init_source(ssda_source_t *s, store_t *st, const ssda_view_t *v, size_t arena)
{
    ssda_source_t poison;
    int rc;
    if (!st->streamed) {
        FUZZ_CHECK(ssda_source_init_view(s, v) == SSDA_OK);
        return SSDA_OK;
    }
    st->cfg.arena_size = arena;
    memset(&poison, 0x3B, sizeof poison);
    *s = poison;
    rc = ssda_source_init(s, &st->cfg);
    if (arena < st->init_min) {
        FUZZ_CHECK(rc == SSDA_ERR_BUFFER);
        FUZZ_CHECK(memcmp(s, &poison, sizeof *s) == 0);
    } else {
        FUZZ_CHECK(rc == SSDA_OK);
    }
    return rc;
}

static void same_result(const ssda_match_result_t *a, const ssda_match_result_t *b)
{
    FUZZ_CHECK(a->sad == b->sad && a->pixel_ops == b->pixel_ops && a->positions == b->positions &&
               a->completed == b->completed && a->x == b->x && a->y == b->y &&
               a->exact == b->exact);
}

static void same_vector(const ssda_track_vector_t *a, const ssda_track_vector_t *b)
{
    FUZZ_CHECK(a->sad == b->sad && a->dx == b->dx && a->dy == b->dy && a->x == b->x &&
               a->y == b->y && a->status == b->status && a->exact == b->exact);
}

static void fuzz_match_config(fuzz_in_t *in, ssda_match_config_t *c, uint32_t ww, uint32_t wh,
                              uint32_t aw, uint32_t ah)
{
    memset(c, 0, sizeof *c);
    c->threshold = (uint8_t)fuzz_range(in, 0, 4);
    c->scan = (uint8_t)fuzz_range(in, 0, 2);
    c->order = (uint8_t)fuzz_range(in, 0, 1);
    c->flags = (uint8_t)(fuzz_u8(in) & SSDA_MATCH_BOUNDS);
    c->k_q8 = (uint16_t)fuzz_u16(in);
    c->coarse_step = (uint16_t)fuzz_range(in, 0, 10);
    c->lambda_q8 = fuzz_range(in, 1, 5000);
    c->fixed_threshold = fuzz_u32(in) % ((uint64_t)ww * wh * 64u + 1u);
    c->predict_x = (int32_t)fuzz_range(in, 0, aw + 4u) - 2;
    c->predict_y = (int32_t)fuzz_range(in, 0, ah + 4u) - 2;
    c->work = g_work;
    c->work_size = sizeof g_work;
}

static void fuzz_rect(fuzz_in_t *in, const ssda_view_t *v, ssda_rect_t *r, uint32_t min_w,
                      uint32_t min_h)
{
    r->width = (uint16_t)fuzz_range(in, min_w, v->width);
    r->height = (uint16_t)fuzz_range(in, min_h, v->height);
    r->x = (uint16_t)fuzz_range(in, 0, v->width - r->width);
    r->y = (uint16_t)fuzz_range(in, 0, v->height - r->height);
}

/* Fail read k of device dev (k < 0: none) before the next job. */
static void arm(uint32_t dev, int64_t k, int code)
{
    g_dev[0].fail_at = g_dev[1].fail_at = -1;
    g_dev[dev].fail_at = k;
    g_dev[dev].fail_code = code;
}

static uint64_t total_reads(void)
{
    return g_dev[0].reads + g_dev[1].reads;
}

static void job_match(fuzz_in_t *in, const ssda_view_t *v, store_t *st, int64_t fail_k,
                      uint32_t fail_dev, int code)
{
    ssda_source_t as, ws;
    ssda_rect_t ar, wr;
    ssda_view_t aroi, wroi;
    ssda_match_config_t c;
    ssda_match_result_t want, got, poison;
    size_t need_a, need_w, arena_a, arena_w;
    int rc, ra, rw, short_arena;
    uint64_t before;

    fuzz_rect(in, &v[0], &ar, 1, 1);
    fuzz_rect(in, &v[1], &wr, 1, 1);
    if (wr.width > ar.width) wr.width = ar.width;
    if (wr.height > ar.height) wr.height = ar.height;
    fuzz_match_config(in, &c, wr.width, wr.height, ar.width, ar.height);
    FUZZ_CHECK(ssda_view_roi(&aroi, &v[0], ar.x, ar.y, ar.width, ar.height) == SSDA_OK);
    FUZZ_CHECK(ssda_view_roi(&wroi, &v[1], wr.x, wr.y, wr.width, wr.height) == SSDA_OK);
    FUZZ_CHECK(ssda_match(&aroi, &wroi, &c, &want) == SSDA_OK);

    /* the minimum (issue 22): a band of window-height rows as wide as the
       area for the raster scan, the whole area for the others; the whole
       window */
    need_a = SSDA_SOURCE_SIZE(st[0].cfg.layout, ar.width,
                              c.scan == SSDA_SCAN_RASTER ? wr.height : ar.height, v[0].format,
                              st[0].cfg.read_size, st[0].cfg.tile_w);
    need_w = SSDA_SOURCE_SIZE(st[1].cfg.layout, wr.width, wr.height, v[1].format,
                              st[1].cfg.read_size, st[1].cfg.tile_w);
    arena_a = pick_arena(in, st[0].init_min, need_a);
    arena_w = pick_arena(in, st[1].init_min, need_w);
    ra = init_source(&as, &st[0], &v[0], arena_a);
    rw = init_source(&ws, &st[1], &v[1], arena_w);
    if (ra != SSDA_OK || rw != SSDA_OK) {
        return;
    }
    memset(&poison, 0x6B, sizeof poison);
    got = poison;
    before = total_reads();
    short_arena = (st[0].streamed && arena_a < need_a) || (st[1].streamed && arena_w < need_w);
    arm(fail_dev, fail_k, code);
    rc = ssda_stream_match(&as, &ar, &ws, &wr, &c, &got);
    if (g_dev[fail_dev].failures == 0u && rc == SSDA_ERR_BUFFER) {
        FUZZ_CHECK(short_arena); /* only below the documented size, before any read */
        FUZZ_CHECK(memcmp(&got, &poison, sizeof got) == 0);
        FUZZ_CHECK(total_reads() == before);
        return;
    }
    if (g_dev[fail_dev].failures > 0u) { /* the code may be any value, SSDA_ERR_BUFFER too */
        FUZZ_CHECK(rc == code && g_dev[fail_dev].failures == 1u);
        FUZZ_CHECK(memcmp(&got, &poison, sizeof got) == 0);
        arm(0, -1, 0);
        rc = ssda_stream_match(&as, &ar, &ws, &wr, &c, &got); /* the same sources recover */
    }
    FUZZ_CHECK(rc == SSDA_OK);
    same_result(&want, &got);
    /* one streamed source as both operands: refused */
    if (st[0].streamed) {
        got = poison;
        FUZZ_CHECK(ssda_stream_match(&as, &ar, &as, &wr, &c, &got) == SSDA_ERR_ARG);
        FUZZ_CHECK(memcmp(&got, &poison, sizeof got) == 0);
    }
}

static void job_track(fuzz_in_t *in, const ssda_view_t *v, store_t *st, int64_t fail_k,
                      uint32_t fail_dev, int code)
{
    ssda_source_t fs, ss;
    ssda_track_config_t c;
    ssda_track_grid_t grid;
    ssda_track_stats_t want, got, poison;
    ssda_track_vector_t pv;
    size_t need_f, need_s, arena_f, arena_s;
    uint32_t k;
    int rc, short_arena;
    uint64_t before;

    memset(&c, 0, sizeof c);
    c.win_w = (uint16_t)fuzz_range(in, 1, 16);
    c.win_h = (uint16_t)fuzz_range(in, 1, 16);
    c.search_w = (uint16_t)(c.win_w + fuzz_range(in, 0, 16));
    c.search_h = (uint16_t)(c.win_h + fuzz_range(in, 0, 16));
    c.step_x = (uint16_t)fuzz_range(in, 1, 12);
    c.step_y = (uint16_t)fuzz_range(in, 1, 12);
    c.predict = (uint8_t)fuzz_range(in, 0, 2);
    c.flags = (uint8_t)(fuzz_u8(in) & 3u);
    c.mask_value = (uint16_t)(fuzz_u8(in) & 1u ? 0u : 255u);
    fuzz_match_config(in, &c.match, c.win_w, c.win_h, c.search_w, c.search_h);
    if (c.predict != 0u && c.match.scan == SSDA_SCAN_COARSE) {
        c.match.scan = SSDA_SCAN_RASTER;
    }
    if (ssda_track_grid(&c, v[1].width, v[1].height, &grid) != SSDA_OK ||
        grid.count > MAX_OUT) {
        return;
    }
    if (ssda_track(&v[0], &v[1], &c, g_want, MAX_OUT, &want) != SSDA_OK) {
        return; /* argument errors belong to fuzz_track */
    }
    {
        /* the minimum (issue 22): a band of one grid column's areas and
           windows, or of all columns when the order matters (MEDIAN
           prediction: the tie rule); at least what the library needs */
        const bool full = c.predict == SSDA_TRACK_PREDICT_MEDIAN;
        size_t fw = full ? SSDA_STREAM_STRIP_W(grid.cols, grid.step_x, grid.search_w) : grid.search_w;
        size_t sw = full ? SSDA_STREAM_STRIP_W(grid.cols, grid.step_x, grid.win_w) : grid.win_w;
        fw = fw < v[0].width ? fw : v[0].width;
        sw = sw < v[1].width ? sw : v[1].width;
        need_f = SSDA_SOURCE_SIZE(st[0].cfg.layout, fw, grid.search_h, v[0].format,
                                  st[0].cfg.read_size, st[0].cfg.tile_w);
        need_s = SSDA_SOURCE_SIZE(st[1].cfg.layout, sw, grid.win_h, v[1].format,
                                  st[1].cfg.read_size, st[1].cfg.tile_w);
    }
    arena_f = pick_arena(in, st[0].init_min, need_f);
    arena_s = pick_arena(in, st[1].init_min, need_s);
    if (init_source(&fs, &st[0], &v[0], arena_f) != SSDA_OK ||
        init_source(&ss, &st[1], &v[1], arena_s) != SSDA_OK) {
        return;
    }
    memset(&poison, 0x4E, sizeof poison);
    memset(&pv, 0x4E, sizeof pv);
    for (k = 0; k < MAX_OUT; k++) {
        g_got[k] = pv;
    }
    got = poison;
    before = total_reads();
    short_arena = (st[0].streamed && arena_f < need_f) || (st[1].streamed && arena_s < need_s);
    arm(fail_dev, fail_k, code);
    rc = ssda_stream_track(&fs, &ss, &c, g_got, MAX_OUT, &got);
    if (g_dev[fail_dev].failures == 0u && rc == SSDA_ERR_BUFFER) {
        FUZZ_CHECK(short_arena); /* only below the documented size, before any read */
        FUZZ_CHECK(memcmp(&got, &poison, sizeof got) == 0);
        FUZZ_CHECK(total_reads() == before);
        for (k = 0; k < MAX_OUT; k++) {
            FUZZ_CHECK(memcmp(&g_got[k], &pv, sizeof pv) == 0);
        }
        return;
    }
    if (g_dev[fail_dev].failures > 0u) { /* the code may be any value, SSDA_ERR_BUFFER too */
        FUZZ_CHECK(rc == code && g_dev[fail_dev].failures == 1u);
        FUZZ_CHECK(memcmp(&got, &poison, sizeof got) == 0);
        arm(0, -1, 0);
        rc = ssda_stream_track(&fs, &ss, &c, g_got, MAX_OUT, &got);
    }
    FUZZ_CHECK(rc == SSDA_OK);
    for (k = 0; k < grid.count; k++) {
        same_vector(&g_want[k], &g_got[k]);
    }
    for (; k < MAX_OUT; k++) {
        FUZZ_CHECK(memcmp(&g_got[k], &pv, sizeof pv) == 0);
    }
    FUZZ_CHECK(want.windows == got.windows && want.ok == got.ok && want.excluded == got.excluded &&
               want.masked == got.masked && want.edge == got.edge);
}

static void job_rows(fuzz_in_t *in, const ssda_view_t *v, store_t *st, int64_t fail_k, int code)
{
    ssda_source_t s;
    uint32_t n_spans = fuzz_range(in, 1, 40), i, bpp = v[0].format;
    size_t arena = pick_arena(in, st[0].init_min, st[0].init_min + fuzz_range(in, 0, 400));
    if (init_source(&s, &st[0], &v[0], arena) != SSDA_OK) {
        return;
    }
    arm(0, fail_k, code);
    for (i = 0; i < n_spans; i++) {
        uint32_t y = fuzz_range(in, 0, v[0].height + 1u), x = fuzz_range(in, 0, v[0].width + 1u);
        uint32_t n = fuzz_range(in, 0, v[0].width + 1u);
        const uint8_t *px = (const uint8_t *)(uintptr_t)0x99u;
        int rc = ssda_source_row(&s, x, y, n, &px);
        if (n == 0u || x + n > v[0].width || y >= v[0].height) {
            FUZZ_CHECK(rc == SSDA_ERR_SIZE && px == (const uint8_t *)(uintptr_t)0x99u);
            continue;
        }
        if (g_dev[0].failures > 0u && g_dev[0].fail_at >= 0) { /* once: then disarmed */
            FUZZ_CHECK(rc == code && g_dev[0].failures == 1u);
            FUZZ_CHECK(px == (const uint8_t *)(uintptr_t)0x99u);
            g_dev[0].fail_at = -1;
            continue;
        }
        if (rc == SSDA_ERR_BUFFER) { /* the span is wider than the plate can be */
            FUZZ_CHECK(st[0].streamed &&
                       arena < SSDA_SOURCE_SIZE(st[0].cfg.layout, n, 1u, bpp,
                                                st[0].cfg.read_size, st[0].cfg.tile_w));
            continue;
        }
        FUZZ_CHECK(rc == SSDA_OK);
        FUZZ_CHECK(bpp == 1u || ((uintptr_t)px & 1u) == 0u);
        FUZZ_CHECK(memcmp(px, ssda_view_row(&v[0], y) + (size_t)x * bpp, (size_t)n * bpp) == 0);
    }
}

static void job_push(fuzz_in_t *in, const ssda_view_t *v, store_t *st, int64_t fail_k, int code)
{
    ssda_source_t ws;
    ssda_push_t p, pp;
    ssda_push_config_t pc;
    ssda_rect_t ar, wr;
    ssda_view_t aroi, wroi;
    ssda_match_config_t c;
    ssda_match_result_t want, got, poison;
    size_t ring_need, ring, need_w, arena_w;
    uint32_t y, ran = 0;
    int rc, failed = 0;

    fuzz_rect(in, &v[0], &ar, 1, 1);
    fuzz_rect(in, &v[1], &wr, 1, 1);
    if (wr.width > ar.width) wr.width = ar.width;
    if (wr.height > ar.height) wr.height = ar.height;
    fuzz_match_config(in, &c, wr.width, wr.height, ar.width, ar.height);
    FUZZ_CHECK(ssda_view_roi(&aroi, &v[0], ar.x, ar.y, ar.width, ar.height) == SSDA_OK);
    FUZZ_CHECK(ssda_view_roi(&wroi, &v[1], wr.x, wr.y, wr.width, wr.height) == SSDA_OK);
    FUZZ_CHECK(ssda_match(&aroi, &wroi, &c, &want) == SSDA_OK);
    need_w = SSDA_SOURCE_SIZE(st[1].cfg.layout, wr.width, wr.height, v[1].format,
                              st[1].cfg.read_size, st[1].cfg.tile_w); /* the whole window */
    arena_w = pick_arena(in, st[1].init_min, need_w);
    if (init_source(&ws, &st[1], &v[1], arena_w) != SSDA_OK) {
        return;
    }
    ring_need = SSDA_PUSH_SIZE(ar.width, ar.height, v[0].format);
    ring = fuzz_u8(in) % 4u == 0u ? ring_need - 1u : ring_need + fuzz_range(in, 0, 64);
    if (ring > sizeof g_ring) {
        ring = sizeof g_ring;
    }
    memset(&poison, 0x6B, sizeof poison);
    memset(&pp, 0x2C, sizeof pp);
    p = pp;
    got = poison;
    pc.width = v[0].width;
    pc.height = v[0].height;
    pc.format = (ssda_pixfmt_t)v[0].format;
    pc.role = SSDA_PUSH_FIRST;
    pc.other = &ws;
    pc.area_rect = &ar;
    pc.window_rect = &wr;
    pc.ring = g_ring;
    pc.ring_size = ring;
    rc = ssda_push_init_match(&p, &pc, &c, &got);
    if (rc == SSDA_ERR_BUFFER) { /* only below the documented sizes */
        FUZZ_CHECK(ring < ring_need || (st[1].streamed && arena_w < need_w));
        FUZZ_CHECK(memcmp(&p, &pp, sizeof p) == 0);
        return;
    }
    FUZZ_CHECK(rc == SSDA_OK);
    arm(1, fail_k, code);
    for (y = 0; y < v[0].height; y++) {
        rc = ssda_push_row(&p, ssda_view_row(&v[0], y));
        if (failed) {
            FUZZ_CHECK(rc == SSDA_ERR_STATE);
        } else if (g_dev[1].failures > 0u) {
            FUZZ_CHECK(rc == code && g_dev[1].failures == 1u);
            FUZZ_CHECK(y + 1u == (uint32_t)ar.y + ar.height);
            FUZZ_CHECK(memcmp(&got, &poison, sizeof got) == 0);
            failed = 1;
        } else if (y + 1u == (uint32_t)ar.y + ar.height) {
            FUZZ_CHECK(rc == 1);
            ran = 1;
        } else {
            FUZZ_CHECK(rc == 0);
        }
    }
    FUZZ_CHECK(ssda_push_row(&p, ssda_view_row(&v[0], 0)) == SSDA_ERR_STATE);
    if (!failed) {
        FUZZ_CHECK(ran);
        same_result(&want, &got);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in_t in = {data, size};
    uint32_t bpp = fuzz_u8(&in) & 1u ? 2u : 1u, maxv = bpp == 2u ? 65535u : 255u;
    uint32_t job = fuzz_u8(&in) % 4u, i, levels, seed, fail_dev;
    ssda_view_t v[2];
    store_t st[2];
    int64_t fail_k;
    int code;

    levels = fuzz_range(&in, 1, 256);
    seed = fuzz_u32(&in) | 1u;
    for (i = 0; i < 2u; i++) {
        uint32_t w = fuzz_range(&in, 1, MAX_IMG), h = fuzz_range(&in, 1, MAX_IMG), k;
        if (i == 1u && fuzz_u8(&in) & 1u) { /* same size (tracking pairs) */
            w = v[0].width;
            h = v[0].height;
        }
        for (k = 0; k < w * h; k++) {
            uint32_t r = next_rand(&seed) & 0xFFFFu;
            uint32_t val = levels <= 1u ? maxv : (r % levels) * (maxv / (levels - 1u));
            if (bpp == 1u) {
                ((uint8_t *)g_img[i])[k] = (uint8_t)val;
            } else {
                g_img[i][k] = (uint16_t)val;
            }
        }
        FUZZ_CHECK(ssda_view_init(&v[i], g_img[i], (uint16_t)w, (uint16_t)h, w * bpp,
                                  (ssda_pixfmt_t)bpp) == SSDA_OK);
        memset(&st[i], 0, sizeof st[i]);
        if ((fuzz_u8(&in) % 4u) != 0u && !make_store(&in, i, &v[i], &st[i])) {
            st[i].streamed = 0;
        }
        g_dev[i].reads = g_dev[i].failures = 0;
        g_dev[i].fail_at = -1;
    }
    fail_k = fuzz_u8(&in) & 1u ? -1 : (int64_t)fuzz_range(&in, 0, 300);
    fail_dev = fuzz_u8(&in) & 1u;
    code = -(int)fuzz_range(&in, 1, 100000);
    switch (job) {
    case 0: job_match(&in, v, st, fail_k, fail_dev, code); break;
    case 1: job_track(&in, v, st, fail_k, fail_dev, code); break;
    case 2: job_rows(&in, v, st, fail_k, code); break;
    default: job_push(&in, v, st, fail_k, code); break;
    }
    return 0;
}
