/*
 * fuzz_match.c - ssda_match with geometry, strides, depth, pixels and every
 * option taken from the fuzzer's bytes.
 *   Valid inputs: the call succeeds; whenever the result says exact it is
 *   the brute-force minimum of this file (smallest SAD, then y, then x);
 *   AUTO and NONE with the raster or predict scan must say exact; a
 *   completed result's SAD is the full SAD at its position (ssda_sad_at and
 *   the brute force agree); two calls give the same result.
 *   Inputs with one broken rule: the documented error, result untouched.
 */
#include <string.h>

#include "fuzz_input.h"
#include "ssda/match.h"

#define MAX_DIM 40u
#define MAX_PAD 7u /* extra pixels of row stride */
#define BUF_BYTES (MAX_DIM * (MAX_DIM + MAX_PAD) * 2u + 8u)

static uint32_t g_area[BUF_BYTES / 4u];
static uint32_t g_win[BUF_BYTES / 4u];
static uint32_t g_work[(MAX_DIM + 1u) * MAX_DIM + 2u * MAX_DIM + 2u];

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

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in_t in = {data, size};
    ssda_view_t area, win, *pa = &area, *pw = &win;
    ssda_match_config_t cfg;
    ssda_match_result_t res, res2, poison;
    ssda_match_result_t *pres = &res;
    uint32_t bpp = fuzz_u8(&in) & 1u ? 2u : 1u, maxv = bpp == 2u ? 65535u : 255u;
    uint32_t aw = fuzz_range(&in, 1, MAX_DIM), ah = fuzz_range(&in, 1, MAX_DIM);
    uint32_t ww = fuzz_range(&in, 1, aw), wh = fuzz_range(&in, 1, ah);
    uint32_t astride = (aw + fuzz_range(&in, 0, MAX_PAD)) * bpp;
    uint32_t wstride = (ww + fuzz_range(&in, 0, MAX_PAD)) * bpp;
    uint32_t brk = fuzz_range(&in, 0, 2u * BREAK_COUNT), sub = fuzz_u8(&in);
    uint32_t levels = fuzz_range(&in, 1, 256), seed = fuzz_u32(&in) | 1u;
    uint32_t copy = fuzz_u8(&in), x, y, cx, cy;
    uint8_t *abytes = (uint8_t *)g_area, *wbytes = (uint8_t *)g_win;
    int rc, want = SSDA_OK, use_defaults;
    best_t ref;

    if (brk >= BREAK_COUNT) {
        brk = 0; /* most inputs are valid */
    }
    memset(&cfg, 0, sizeof cfg);
    cfg.threshold = (uint8_t)fuzz_range(&in, 0, SSDA_THRESHOLD_AUTO_RAMP);
    cfg.scan = (uint8_t)fuzz_range(&in, 0, SSDA_SCAN_COARSE);
    cfg.order = (uint8_t)fuzz_range(&in, 0, SSDA_ORDER_SPREAD);
    cfg.flags = (uint8_t)(fuzz_u8(&in) & SSDA_MATCH_BOUNDS);
    cfg.k_q8 = (uint16_t)fuzz_u16(&in);
    cfg.coarse_step = (uint16_t)(fuzz_u8(&in) & 1u ? fuzz_range(&in, 0, 12) : fuzz_u16(&in));
    cfg.lambda_q8 = fuzz_u8(&in) & 1u ? fuzz_range(&in, 1, 0x10000u) : fuzz_u32(&in);
    if (cfg.lambda_q8 == 0u) {
        cfg.lambda_q8 = 1u;
    }
    switch (fuzz_u8(&in) & 3u) { /* thresholds near the scale of real SADs, and not */
    case 0: cfg.fixed_threshold = fuzz_u64(&in); break;
    case 1: cfg.fixed_threshold = fuzz_range(&in, 0, 1000); break;
    default: cfg.fixed_threshold = (uint64_t)fuzz_u16(&in) * ww * wh / 256u; break;
    }
    cfg.predict_x = (int32_t)fuzz_u32(&in);
    cfg.predict_y = (int32_t)fuzz_u32(&in);
    if (fuzz_u8(&in) & 1u) { /* mostly near the area */
        cfg.predict_x = cfg.predict_x % (int32_t)(aw + 4u);
        cfg.predict_y = cfg.predict_y % (int32_t)(ah + 4u);
    }
    cfg.work = g_work;
    cfg.work_size = SSDA_MATCH_WORK_SIZE(aw, ah, ww, wh);

    /* pixels: the area, then a window that is a (perturbed) copy of a
       placement or independent */
    memset(g_area, 0xEE, sizeof g_area); /* padding must never matter */
    memset(g_win, 0xEE, sizeof g_win);
    for (y = 0; y < ah; y++) {
        for (x = 0; x < aw; x++) {
            put(abytes, astride, bpp, x, y, sample(&in, &seed, levels, maxv));
        }
    }
    cx = fuzz_range(&in, 0, aw - ww);
    cy = fuzz_range(&in, 0, ah - wh);
    for (y = 0; y < wh; y++) {
        for (x = 0; x < ww; x++) {
            uint32_t v = sample(&in, &seed, levels, maxv);
            if (copy & 1u) {
                const uint8_t *p = abytes + (size_t)(cy + y) * astride + (size_t)(cx + x) * bpp;
                uint16_t w16;
                memcpy(&w16, p, bpp == 2u ? 2u : 1u);
                v = bpp == 2u ? w16 : *p;
                if ((copy & 6u) != 0u && next_rand(&seed) % 8u == 0u) {
                    v = (v + next_rand(&seed) % 5u) % (maxv + 1u);
                }
            }
            put(wbytes, wstride, bpp, x, y, v);
        }
    }
    FUZZ_CHECK(ssda_view_init(&area, abytes, (uint16_t)aw, (uint16_t)ah, astride,
                              (ssda_pixfmt_t)bpp) == SSDA_OK);
    FUZZ_CHECK(ssda_view_init(&win, wbytes, (uint16_t)ww, (uint16_t)wh, wstride,
                              (ssda_pixfmt_t)bpp) == SSDA_OK);

    switch (brk) {
    case BREAK_NULL:
        want = SSDA_ERR_NULL;
        if (sub % 3u == 0u) pa = NULL; else if (sub % 3u == 1u) pw = NULL; else pres = NULL;
        break;
    case BREAK_WINDOW_TOO_BIG: /* a window view one larger than the area */
        want = SSDA_ERR_SIZE;
        if (aw < MAX_DIM && (sub & 1u)) {
            win.width = (uint16_t)(aw + 1u);
            win.stride = (aw + 1u) * bpp;
        } else if (ah < MAX_DIM) {
            win.height = (uint16_t)(ah + 1u);
            win.stride = ww * bpp;
        } else {
            want = SSDA_OK;
        }
        break;
    case BREAK_FORMAT_MISMATCH: /* a valid 1 x 1 window of the other format */
        want = SSDA_ERR_FORMAT;
        win.width = win.height = 1;
        win.stride = 2;
        win.format = (uint8_t)(bpp == 2u ? SSDA_PIX_U8 : SSDA_PIX_U16);
        win.data = wbytes;
        break;
    case BREAK_STRIDE: {
        ssda_view_t *v = sub & 1u ? &area : &win;
        want = SSDA_ERR_STRIDE;
        if ((sub & 6u) == 0u && bpp == 2u) {
            v->data = (const uint8_t *)v->data + 1; /* misaligned 16-bit */
        } else if ((sub & 6u) == 2u && bpp == 2u) {
            v->stride += 1u; /* not a multiple of the pixel */
        } else {
            v->stride = (uint32_t)v->width * bpp - 1u;
        }
        break;
    }
    case BREAK_ZERO_SIZE:
        want = SSDA_ERR_SIZE;
        if (sub & 1u) area.height = 0; else win.width = 0;
        break;
    case BREAK_UNKNOWN_FORMAT:
        want = SSDA_ERR_FORMAT;
        area.format = win.format = (uint8_t)(sub & 1u ? 0u : 3u + sub % 200u);
        break;
    case BREAK_ENUM:
        want = SSDA_ERR_ARG;
        switch (sub % 4u) {
        case 0: cfg.threshold = (uint8_t)(5u + sub % 251u); break;
        case 1: cfg.scan = (uint8_t)(3u + sub % 253u); break;
        case 2: cfg.order = (uint8_t)(2u + sub % 254u); break;
        default: cfg.flags = (uint8_t)(cfg.flags | (2u << (sub % 7u))); break;
        }
        break;
    case BREAK_RAMP_LAMBDA:
        want = SSDA_ERR_ARG;
        cfg.threshold = SSDA_THRESHOLD_RAMP;
        cfg.lambda_q8 = 0;
        break;
    case BREAK_WORK_NULL:
        want = SSDA_ERR_NULL;
        cfg.flags = SSDA_MATCH_BOUNDS;
        cfg.work = NULL;
        break;
    case BREAK_WORK_SHORT:
        want = SSDA_ERR_BUFFER;
        cfg.flags = SSDA_MATCH_BOUNDS;
        if (sub & 1u) cfg.work_size -= 1u; else cfg.work = (uint8_t *)g_work + 1u + sub % 3u;
        break;
    default:
        break;
    }

    /* NULL cfg means the zero config; test that on valid inputs sometimes */
    use_defaults = brk < BREAK_ENUM && (fuzz_u8(&in) & 1u) != 0u;
    if (use_defaults) {
        memset(&cfg, 0, sizeof cfg);
    }
    memset(&poison, 0x5A, sizeof poison);
    res = poison;
    rc = ssda_match(pa, pw, use_defaults ? NULL : &cfg, pres);
    FUZZ_CHECK(rc == want);
    if (want != SSDA_OK) {
        FUZZ_CHECK(memcmp(&res, &poison, sizeof res) == 0);
        return 0;
    }
    res2 = poison; /* no hidden state: the same call, the same result */
    FUZZ_CHECK(ssda_match(&area, &win, &cfg, &res2) == SSDA_OK);
    FUZZ_CHECK(res.sad == res2.sad && res.pixel_ops == res2.pixel_ops &&
               res.positions == res2.positions && res.completed == res2.completed &&
               res.x == res2.x && res.y == res2.y && res.exact == res2.exact);

    ref = brute_force(&area, &win);
    FUZZ_CHECK(res.x + ww <= aw && res.y + wh <= ah);
    FUZZ_CHECK(res.completed <= res.positions);
    if (cfg.scan != SSDA_SCAN_COARSE) {
        FUZZ_CHECK(res.positions <= (aw - ww + 1u) * (ah - wh + 1u));
    }
    if (cfg.scan != SSDA_SCAN_COARSE &&
        (cfg.threshold == SSDA_THRESHOLD_AUTO || cfg.threshold == SSDA_THRESHOLD_NONE)) {
        FUZZ_CHECK(res.exact);
    }
    if (cfg.scan == SSDA_SCAN_COARSE || cfg.threshold == SSDA_THRESHOLD_RAMP ||
        cfg.threshold == SSDA_THRESHOLD_AUTO_RAMP) {
        FUZZ_CHECK(!res.exact);
    }
    if (res.exact) {
        FUZZ_CHECK(res.sad == ref.sad && res.x == ref.x && res.y == ref.y);
    }
    {
        uint64_t at = 0, mine = full_sad(&area, &win, res.x, res.y);
        FUZZ_CHECK(ssda_sad_at(&area, &win, res.x, res.y, &at) == SSDA_OK);
        FUZZ_CHECK(at == mine);
        if (res.completed > 0u) {
            FUZZ_CHECK(res.sad == mine); /* a completed position's full SAD */
            FUZZ_CHECK(res.sad >= ref.sad);
        } else {
            FUZZ_CHECK(res.sad <= mine); /* all cut: the partial sum at the cut */
        }
    }
    return 0;
}
