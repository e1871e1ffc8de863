/*
 * fuzz_match.c - ssda_match with geometry, strides, depth, pixels and every
 * option taken from the fuzzer's bytes.
 *   Valid inputs: the call succeeds; whenever the result says exact it is
 *   the brute-force minimum of this file (smallest SAD, then y, then x);
 *   AUTO and NONE with the raster or predict scan must say exact; a
 *   result's SAD is the full SAD at its position, an all-cut fallback's too
 *   (ssda_sad_at and
 *   the brute force agree); ssda_match_search, on one state reused by
 *   every input, gives the same result.
 *   Inputs with one broken rule: the documented error, result untouched
 *   (and ssda_match_search's state).
 */
#include <string.h>

#include "fuzz_input.h"
#include "ssda/match.h"

#define MAX_DIM 40u
#define MAX_PAD 7u /* extra pixels of row stride */
#define BUF_BYTES (MAX_DIM * (MAX_DIM + MAX_PAD) * 2u + 8u)

static uint32_t g_area[BUF_BYTES / 4u];
static uint32_t g_win[BUF_BYTES / 4u];
static uint32_t g_work[SSDA_MATCH_WORK_SIZE_BLOCKS(MAX_DIM, MAX_DIM, 1u, MAX_DIM) / 4u + 2u];
static ssda_match_state_t g_state; /* ssda_match_search's, reused by every input */
static ssda_match_state_t g_state_before;

/* A simple generator for pixels beyond the input's bytes. */
static uint32_t next_rand(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static uint32_t sample(fuzz_in_t *in, uint32_t *seed, uint32_t levels, uint32_t maxv)
{
    uint32_t v = in->n > 0 ? fuzz_u8(in) * 257u + fuzz_u8(in) : next_rand(seed) & 0xFFFFu;
    return levels <= 1u ? maxv : (v % levels) * (maxv / (levels - 1u));
}

static void put(uint8_t *base, uint32_t stride, uint32_t bpp, uint32_t x, uint32_t y, uint32_t v)
{
    uint8_t *p = base + (size_t)y * stride + (size_t)x * bpp;
    if (bpp == 1u) {
        *p = (uint8_t)v;
    } else {
        uint16_t w = (uint16_t)v;
        memcpy(p, &w, 2);
    }
}

static uint32_t get(const ssda_view_t *v, uint32_t x, uint32_t y)
{
    const uint8_t *p = (const uint8_t *)v->data + (size_t)y * v->stride + (size_t)x * v->format;
    uint16_t w;
    if (v->format == SSDA_PIX_U8) {
        return *p;
    }
    memcpy(&w, p, 2);
    return w;
}

static uint64_t full_sad(const ssda_view_t *a, const ssda_view_t *w, uint32_t x, uint32_t y)
{
    uint64_t s = 0;
    uint32_t i, j;
    for (j = 0; j < w->height; j++) {
        for (i = 0; i < w->width; i++) {
            uint32_t p = get(a, x + i, y + j), q = get(w, i, j);
            s += p > q ? p - q : q - p;
        }
    }
    return s;
}

typedef struct {
    uint64_t sad;
    uint32_t x, y;
} best_t;

/* The reference: every position in raster order, strict improvement only
   (so ties keep the smallest y, then x). */
static best_t brute_force(const ssda_view_t *a, const ssda_view_t *w)
{
    best_t b = {UINT64_MAX, 0, 0};
    uint32_t x, y;
    for (y = 0; y + w->height <= a->height; y++) {
        for (x = 0; x + w->width <= a->width; x++) {
            uint64_t s = full_sad(a, w, x, y);
            if (s < b.sad) {
                b.sad = s;
                b.x = x;
                b.y = y;
            }
        }
    }
    return b;
}

/* The rules a valid input may break, one at a time. */
enum {
    BREAK_NULL = 1,
    BREAK_WINDOW_TOO_BIG,
    BREAK_FORMAT_MISMATCH,
    BREAK_STRIDE,
    BREAK_ZERO_SIZE,
    BREAK_UNKNOWN_FORMAT,
    BREAK_ENUM,
    BREAK_RAMP_LAMBDA,
    BREAK_WORK_NULL,
    BREAK_WORK_SHORT,
    BREAK_COUNT
};

/* One input: geometry, depth, views and options. */
typedef struct {
    ssda_view_t area, win;
    ssda_match_config_t cfg;
    uint32_t bpp, maxv, aw, ah, ww, wh, astride, wstride;
} case_t;

/* The options from the fuzzer's bytes (valid ones; break_rule breaks one). */
static void read_config(fuzz_in_t *in, case_t *c)
{
    ssda_match_config_t *cfg = &c->cfg;
    memset(cfg, 0, sizeof *cfg);
    cfg->threshold = (uint8_t)fuzz_range(in, 0, SSDA_THRESHOLD_AUTO_RAMP);
    cfg->scan = (uint8_t)fuzz_range(in, 0, SSDA_SCAN_COARSE);
    cfg->order = (uint8_t)fuzz_range(in, 0, SSDA_ORDER_SPREAD);
    cfg->flags = (uint8_t)(fuzz_u8(in) & (SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS));
    if (cfg->flags == SSDA_MATCH_BLOCKS) {
        cfg->flags = 0u; /* the block levels need the bounds */
    }
    cfg->k_q8 = (uint16_t)fuzz_u16(in);
    cfg->coarse_step = (uint16_t)(fuzz_u8(in) & 1u ? fuzz_range(in, 0, 12) : fuzz_u16(in));
    cfg->lambda_q8 = fuzz_u8(in) & 1u ? fuzz_range(in, 1, 0x10000u) : fuzz_u32(in);
    if (cfg->lambda_q8 == 0u) {
        cfg->lambda_q8 = 1u;
    }
    switch (fuzz_u8(in) & 3u) { /* thresholds near the scale of real SADs, and not */
    case 0: cfg->fixed_threshold = fuzz_u64(in); break;
    case 1: cfg->fixed_threshold = fuzz_range(in, 0, 1000); break;
    default: cfg->fixed_threshold = (uint64_t)fuzz_u16(in) * c->ww * c->wh / 256u; break;
    }
    cfg->predict_x = (int32_t)fuzz_u32(in);
    cfg->predict_y = (int32_t)fuzz_u32(in);
    if (fuzz_u8(in) & 1u) { /* mostly near the area */
        cfg->predict_x = cfg->predict_x % (int32_t)(c->aw + 4u);
        cfg->predict_y = cfg->predict_y % (int32_t)(c->ah + 4u);
    }
    cfg->work = g_work;
    cfg->work_size = (cfg->flags & SSDA_MATCH_BLOCKS) != 0u
                         ? SSDA_MATCH_WORK_SIZE_BLOCKS(c->aw, c->ah, c->ww, c->wh)
                         : SSDA_MATCH_WORK_SIZE(c->aw, c->ah, c->ww, c->wh);
}

/* Pixels: the area, then a window that is a (perturbed) copy of a placement
   or independent. Padding is 0xEE and must never matter. */
static void fill_pixels(fuzz_in_t *in, case_t *c, uint32_t *seed, uint32_t levels, uint32_t copy)
{
    uint8_t *abytes = (uint8_t *)g_area, *wbytes = (uint8_t *)g_win;
    uint32_t x, y, cx, cy, bpp = c->bpp;
    memset(g_area, 0xEE, sizeof g_area);
    memset(g_win, 0xEE, sizeof g_win);
    for (y = 0; y < c->ah; y++) {
        for (x = 0; x < c->aw; x++) {
            put(abytes, c->astride, bpp, x, y, sample(in, seed, levels, c->maxv));
        }
    }
    cx = fuzz_range(in, 0, c->aw - c->ww);
    cy = fuzz_range(in, 0, c->ah - c->wh);
    for (y = 0; y < c->wh; y++) {
        for (x = 0; x < c->ww; x++) {
            uint32_t v = sample(in, seed, levels, c->maxv);
            if (copy & 1u) {
                const uint8_t *p = abytes + (size_t)(cy + y) * c->astride + (size_t)(cx + x) * bpp;
                uint16_t w16;
                memcpy(&w16, p, bpp == 2u ? 2u : 1u);
                v = bpp == 2u ? w16 : *p;
                if ((copy & 6u) != 0u && next_rand(seed) % 8u == 0u) {
                    v = (v + next_rand(seed) % 5u) % (c->maxv + 1u);
                }
            }
            put(wbytes, c->wstride, bpp, x, y, v);
        }
    }
    FUZZ_CHECK(ssda_view_init(&c->area, abytes, (uint16_t)c->aw, (uint16_t)c->ah, c->astride,
                              (ssda_pixfmt_t)bpp) == SSDA_OK);
    FUZZ_CHECK(ssda_view_init(&c->win, wbytes, (uint16_t)c->ww, (uint16_t)c->wh, c->wstride,
                              (ssda_pixfmt_t)bpp) == SSDA_OK);
}

/* A view broken for BREAK_WINDOW_TOO_BIG or BREAK_STRIDE. Returns the
   error wanted (SSDA_OK when this input cannot break the rule). */
static int break_view(case_t *c, uint32_t brk, uint32_t sub)
{
    if (brk == BREAK_WINDOW_TOO_BIG) { /* a window view one larger than the area */
        if (c->aw < MAX_DIM && (sub & 1u)) {
            c->win.width = (uint16_t)(c->aw + 1u);
            c->win.stride = (c->aw + 1u) * c->bpp;
        } else if (c->ah < MAX_DIM) {
            c->win.height = (uint16_t)(c->ah + 1u);
            c->win.stride = c->ww * c->bpp;
        } else {
            return SSDA_OK;
        }
        return SSDA_ERR_SIZE;
    }
    {
        ssda_view_t *v = sub & 1u ? &c->area : &c->win;
        if ((sub & 6u) == 0u && c->bpp == 2u) {
            v->data = (const uint8_t *)v->data + 1; /* misaligned 16-bit */
        } else if ((sub & 6u) == 2u && c->bpp == 2u) {
            v->stride += 1u; /* not a multiple of the pixel */
        } else {
            v->stride = (uint32_t)v->width * c->bpp - 1u;
        }
    }
    return SSDA_ERR_STRIDE;
}

/* Break rule brk (0: none); the pointers a NULL breaks. Returns the error
   the call must give. */
static int break_rule(case_t *c, uint32_t brk, uint32_t sub, ssda_view_t **pa, ssda_view_t **pw,
                      ssda_match_result_t **pres)
{
    ssda_match_config_t *cfg = &c->cfg;
    switch (brk) {
    case BREAK_NULL:
        if (sub % 3u == 0u) *pa = NULL; else if (sub % 3u == 1u) *pw = NULL; else *pres = NULL;
        return SSDA_ERR_NULL;
    case BREAK_WINDOW_TOO_BIG:
    case BREAK_STRIDE:
        return break_view(c, brk, sub);
    case BREAK_FORMAT_MISMATCH: /* a valid 1 x 1 window of the other format */
        c->win.width = c->win.height = 1;
        c->win.stride = 2;
        c->win.format = (uint8_t)(c->bpp == 2u ? SSDA_PIX_U8 : SSDA_PIX_U16);
        c->win.data = g_win;
        return SSDA_ERR_FORMAT;
    case BREAK_ZERO_SIZE:
        if (sub & 1u) c->area.height = 0; else c->win.width = 0;
        return SSDA_ERR_SIZE;
    case BREAK_UNKNOWN_FORMAT:
        c->area.format = c->win.format = (uint8_t)(sub & 1u ? 0u : 3u + sub % 200u);
        return SSDA_ERR_FORMAT;
    case BREAK_ENUM:
        switch (sub % 4u) {
        case 0: cfg->threshold = (uint8_t)(5u + sub % 251u); break;
        case 1: cfg->scan = (uint8_t)(3u + sub % 253u); break;
        case 2: cfg->order = (uint8_t)(2u + sub % 254u); break;
        default: cfg->flags = (uint8_t)(cfg->flags | (0x20u << (sub % 3u))); break; /* no flag */
        }
        return SSDA_ERR_ARG;
    case BREAK_RAMP_LAMBDA:
        cfg->threshold = SSDA_THRESHOLD_RAMP;
        cfg->lambda_q8 = 0;
        return SSDA_ERR_ARG;
    case BREAK_WORK_NULL:
        cfg->flags = SSDA_MATCH_BOUNDS;
        cfg->work = NULL;
        return SSDA_ERR_NULL;
    case BREAK_WORK_SHORT:
        if ((cfg->flags & SSDA_MATCH_BLOCKS) == 0u || (sub & 2u) != 0u) {
            cfg->flags = SSDA_MATCH_BOUNDS;
            cfg->work_size = SSDA_MATCH_WORK_SIZE(c->aw, c->ah, c->ww, c->wh);
        }
        if (sub & 1u) cfg->work_size -= 1u; else cfg->work = (uint8_t *)g_work + 1u + sub % 3u;
        return SSDA_ERR_BUFFER;
    default:
        return SSDA_OK;
    }
}

/* A valid input's result against the brute force (header above). */
static void check_result(const case_t *c, const ssda_match_result_t *res)
{
    const ssda_match_config_t *cfg = &c->cfg;
    best_t ref = brute_force(&c->area, &c->win);
    uint64_t at = 0, mine;
    FUZZ_CHECK(res->x + c->ww <= c->aw && res->y + c->wh <= c->ah);
    FUZZ_CHECK(res->completed <= res->positions);
    if (cfg->scan != SSDA_SCAN_COARSE) {
        FUZZ_CHECK(res->positions <= (c->aw - c->ww + 1u) * (c->ah - c->wh + 1u));
    }
    if (cfg->scan != SSDA_SCAN_COARSE &&
        (cfg->threshold == SSDA_THRESHOLD_AUTO || cfg->threshold == SSDA_THRESHOLD_NONE)) {
        FUZZ_CHECK(res->exact);
    }
    if (cfg->scan == SSDA_SCAN_COARSE || cfg->threshold == SSDA_THRESHOLD_RAMP ||
        cfg->threshold == SSDA_THRESHOLD_AUTO_RAMP) {
        FUZZ_CHECK(!res->exact);
    }
    if (res->exact) {
        FUZZ_CHECK(res->sad == ref.sad && res->x == ref.x && res->y == ref.y);
    }
    mine = full_sad(&c->area, &c->win, res->x, res->y);
    FUZZ_CHECK(ssda_sad_at(&c->area, &c->win, res->x, res->y, &at) == SSDA_OK);
    FUZZ_CHECK(at == mine);
    /* the full SAD at the position, an all-cut fallback's too (issue 14) */
    FUZZ_CHECK(res->sad == mine);
    FUZZ_CHECK(res->sad >= ref.sad);
    if (res->completed == 0u) {
        FUZZ_CHECK(!res->exact);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in_t in = {data, size};
    case_t c;
    ssda_view_t *pa = &c.area, *pw = &c.win;
    ssda_match_result_t res, res2, poison;
    ssda_match_result_t *pres = &res;
    uint32_t brk, sub, levels, seed, copy;
    int rc, want, use_defaults;

    memset(&c, 0, sizeof c);
    c.bpp = fuzz_u8(&in) & 1u ? 2u : 1u;
    c.maxv = c.bpp == 2u ? 65535u : 255u;
    c.aw = fuzz_range(&in, 1, MAX_DIM);
    c.ah = fuzz_range(&in, 1, MAX_DIM);
    c.ww = fuzz_range(&in, 1, c.aw);
    c.wh = fuzz_range(&in, 1, c.ah);
    c.astride = (c.aw + fuzz_range(&in, 0, MAX_PAD)) * c.bpp;
    c.wstride = (c.ww + fuzz_range(&in, 0, MAX_PAD)) * c.bpp;
    brk = fuzz_range(&in, 0, 2u * BREAK_COUNT);
    sub = fuzz_u8(&in);
    levels = fuzz_range(&in, 1, 256);
    seed = fuzz_u32(&in) | 1u;
    copy = fuzz_u8(&in);
    if (brk >= BREAK_COUNT) {
        brk = 0; /* most inputs are valid */
    }
    read_config(&in, &c);
    fill_pixels(&in, &c, &seed, levels, copy);
    want = break_rule(&c, brk, sub, &pa, &pw, &pres);
    /* NULL cfg means the zero config; test that on valid inputs sometimes */
    use_defaults = brk < BREAK_ENUM && (fuzz_u8(&in) & 1u) != 0u;
    if (use_defaults) {
        memset(&c.cfg, 0, sizeof c.cfg);
    }
    memset(&poison, 0x5A, sizeof poison);
    res = poison;
    rc = ssda_match(pa, pw, use_defaults ? NULL : &c.cfg, pres);
    FUZZ_CHECK(rc == want);
    /* the caller-state entry on the same call, its state left by earlier
       inputs: the same code, the same result; on an error nothing written,
       the state included */
    memcpy(&g_state_before, &g_state, sizeof g_state);
    res2 = poison;
    rc = ssda_match_search(&g_state, pa, pw, use_defaults ? NULL : &c.cfg,
                           pres == NULL ? NULL : &res2);
    FUZZ_CHECK(rc == want);
    if (want != SSDA_OK) {
        FUZZ_CHECK(memcmp(&res, &poison, sizeof res) == 0);
        FUZZ_CHECK(memcmp(&res2, &poison, sizeof res2) == 0);
        FUZZ_CHECK(memcmp(&g_state, &g_state_before, sizeof g_state) == 0);
        return 0;
    }
    FUZZ_CHECK(res.sad == res2.sad && res.pixel_ops == res2.pixel_ops &&
               res.positions == res2.positions && res.completed == res2.completed &&
               res.x == res2.x && res.y == res2.y && res.exact == res2.exact &&
               res.sub_x_q8 == res2.sub_x_q8 && res.sub_y_q8 == res2.sub_y_q8 &&
               res.unique_q8 == res2.unique_q8);
    check_result(&c, &res);
    return 0;
}
