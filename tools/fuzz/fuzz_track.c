/*
 * fuzz_track.c - ssda_track with image sizes, pixels, grids and options
 * from the fuzzer's bytes, checked against track.h read independently:
 *   - ssda_track_grid agrees with the geometry resolved here (defaults,
 *     SSDA_TRACK_GRID_COUNT), and errors exactly when the geometry is bad;
 *   - an input this file finds valid is accepted, any other is refused with
 *     out and stats untouched; entries past the grid are never written;
 *   - every window's position and status (EDGE, MASKED, EXCLUDED, FLAT, then
 *     searched: AT_LIMIT, AMBIGUOUS, OK) follow the header's rules, the
 *     texture (mean absolute deviation) computed here; windows not
 *     searched carry zeros;
 *   - in the exact modes (AUTO or NONE, no coarse scan) the searched
 *     windows' SADs equal the minimum of a brute-force search of their
 *     areas and their vectors point at a placement with that SAD (checked
 *     for every window while cheap, else for a sample; which of equal
 *     minima wins depends on the neighbours' prediction, tested in
 *     test_track_quality);
 *   - stats count the statuses; a second call gives the same output.
 */
#include <string.h>

#include "fuzz_input.h"
#include "ssda/track.h"

#define MAX_IMG 64u
#define MAX_OUT 4200u
#define BRUTE_BUDGET 3000000u /* pixel comparisons of brute force per input */

static uint16_t g_first[MAX_IMG * MAX_IMG], g_second[MAX_IMG * MAX_IMG];
static ssda_track_vector_t g_out[MAX_OUT + 1u], g_out2[MAX_OUT + 1u];
static uint64_t g_work[((2u * MAX_IMG + 1u) * 2u * MAX_IMG + 8u * MAX_IMG) / 2u + 64u]; /* 8-aligned */

static uint32_t next_rand(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

typedef struct {
    const void *data;
    uint32_t w, h, bpp;
} img_t;

static uint32_t px(const img_t *im, uint32_t x, uint32_t y)
{
    return im->bpp == 1u ? ((const uint8_t *)im->data)[y * im->w + x]
                         : ((const uint16_t *)im->data)[y * im->w + x];
}

static void fill(img_t *im, void *buf, fuzz_in_t *in, uint32_t *seed, uint32_t levels,
                 uint32_t maxv)
{
    uint32_t i, n = im->w * im->h;
    im->data = buf;
    for (i = 0; i < n; i++) {
        uint32_t v = in->n > 0 ? fuzz_u16(in) : next_rand(seed) & 0xFFFFu;
        v = levels <= 1u ? maxv : (v % levels) * (maxv / (levels - 1u));
        if (im->bpp == 1u) {
            ((uint8_t *)buf)[i] = (uint8_t)v;
        } else {
            ((uint16_t *)buf)[i] = (uint16_t)v;
        }
    }
}

/* The geometry of track.h, resolved from its text. */
typedef struct {
    uint32_t win, search, step, start, len, count;
    int ok;
} axis_t;

static axis_t axis(uint32_t win, uint32_t search, uint32_t step, uint32_t start, uint32_t len,
                   uint32_t image)
{
    axis_t a;
    a.win = win ? win : 16u;
    a.search = search ? search : (2u * a.win > 65535u ? 65535u : 2u * a.win);
    a.step = step ? step : a.win;
    a.start = start;
    a.len = len ? len : (start < image ? image - start : 0u);
    a.ok = a.search >= a.win && start < image && start + a.len <= image && a.len >= a.win;
    a.count = a.ok ? (a.len - a.win) / a.step + 1u : 0u;
    return a;
}

static uint64_t sad_at(const img_t *f, const img_t *s, uint32_t ax, uint32_t ay, uint32_t wx,
                       uint32_t wy, uint32_t ww, uint32_t wh)
{
    uint64_t t = 0;
    uint32_t i, j;
    for (j = 0; j < wh; j++) {
        for (i = 0; i < ww; i++) {
            uint32_t p = px(f, ax + i, ay + j), q = px(s, wx + i, wy + j);
            t += p > q ? p - q : q - p;
        }
    }
    return t;
}

static int holds(const img_t *im, uint32_t x0, uint32_t y0, uint32_t w, uint32_t h, uint32_t v)
{
    uint32_t x, y;
    for (y = y0; y < y0 + h; y++) {
        for (x = x0; x < x0 + w; x++) {
            if (px(im, x, y) == v) {
                return 1;
            }
        }
    }
    return 0;
}

/* One input: its images, options and the geometry resolved here. */
typedef struct {
    ssda_track_config_t cfg;
    img_t f, s;
    ssda_view_t fv, sv;
    uint32_t bpp, maxv, out_count, check_every;
    axis_t axx, axy;
    ssda_track_grid_t grid;
    int grc;
    uint32_t pixels, thr, minc; /* window pixels; the texture rule's level and count */
    uint32_t flat;              /* the flat level resolved, Q24.8; 0: no test */
} case_t;

/* The options from the fuzzer's bytes, valid or not. */
static void read_config(fuzz_in_t *in, case_t *c)
{
    ssda_track_config_t *cfg = &c->cfg;
    memset(cfg, 0, sizeof *cfg);
    cfg->win_w = (uint16_t)fuzz_range(in, 0, 24);
    cfg->win_h = (uint16_t)fuzz_range(in, 0, 24);
    cfg->search_w = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, 48));
    cfg->search_h = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, 48));
    cfg->step_x = (uint16_t)fuzz_range(in, 0, 20);
    cfg->step_y = (uint16_t)fuzz_range(in, 0, 20);
    cfg->roi_x = (uint16_t)fuzz_range(in, 0, MAX_IMG);
    cfg->roi_y = (uint16_t)fuzz_range(in, 0, MAX_IMG);
    cfg->roi_w = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, MAX_IMG + 1u));
    cfg->roi_h = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, MAX_IMG + 1u));
    cfg->predict = (uint8_t)fuzz_range(in, 0, 3);       /* 3: invalid */
    cfg->flags = (uint8_t)(fuzz_u8(in) & (fuzz_one_in(in, 16) ? 0xFFu : 0x1Fu));
    cfg->flat_q8 = fuzz_one_in(in, 32) ? 65535u * 256u + 1u
                                       : (fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, 4000));
    cfg->unique_q8 = (uint16_t)(fuzz_one_in(in, 32) ? fuzz_u16(in)
                                : (fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 257, 1024)));
    cfg->unique_radius = (uint8_t)fuzz_range(in, 0, 3); /* 3: invalid */
    cfg->mask_value = (uint16_t)(fuzz_u8(in) & 1u ? fuzz_range(in, 0, 3) * (c->maxv / 3u)
                                                  : fuzz_u16(in));
    cfg->texture_threshold = (uint16_t)(fuzz_u8(in) & 1u ? 0u : fuzz_u16(in) % (c->maxv + 2u));
    cfg->texture_min_count = fuzz_u8(in) & 1u ? 0u : fuzz_range(in, 0, 300);
    cfg->match.threshold = (uint8_t)fuzz_range(in, 0, 5); /* 5: invalid */
    cfg->match.scan = (uint8_t)fuzz_range(in, 0, 2);
    cfg->match.order = (uint8_t)fuzz_range(in, 0, 1);
    cfg->match.flags = (uint8_t)(fuzz_u8(in) & SSDA_MATCH_BOUNDS);
    cfg->match.k_q8 = (uint16_t)fuzz_u16(in);
    cfg->match.coarse_step = (uint16_t)fuzz_range(in, 0, 10);
    cfg->match.lambda_q8 = fuzz_range(in, 0, 5000);
    cfg->match.fixed_threshold = fuzz_u32(in) % 100000u;
    if (cfg->match.flags || (cfg->flags & SSDA_TRACK_UNIQUE)) {
        cfg->match.work = fuzz_one_in(in, 32) ? NULL : g_work;
        /* every size from none to shared tables (SSDA_TRACK_WORK_SIZE_SHARED)
           for the largest image: below it, per-window tables */
        cfg->match.work_size = fuzz_one_in(in, 32) ? 0u : sizeof g_work >> fuzz_range(in, 0, 4);
    }
}

/* Sizes, options and pixels from the fuzzer's bytes. */
static void read_case(fuzz_in_t *in, case_t *c)
{
    uint32_t levels, seed;
    c->bpp = fuzz_u8(in) & 1u ? 2u : 1u;
    c->maxv = c->bpp == 2u ? 65535u : 255u;
    c->f.bpp = c->s.bpp = c->bpp;
    c->f.w = fuzz_range(in, 1, MAX_IMG);
    c->f.h = fuzz_range(in, 1, MAX_IMG);
    if (fuzz_u8(in) & 1u) { /* mostly the same size, as in practice */
        c->s.w = c->f.w;
        c->s.h = c->f.h;
    } else {
        c->s.w = fuzz_range(in, 1, MAX_IMG);
        c->s.h = fuzz_range(in, 1, MAX_IMG);
    }
    read_config(in, c);
    levels = fuzz_range(in, 1, 256);
    seed = fuzz_u32(in) | 1u;
    c->out_count = fuzz_one_in(in, 16) ? fuzz_range(in, 0, 8) : MAX_OUT;
    c->check_every = fuzz_range(in, 1, 8);
    fill(&c->f, g_first, in, &seed, levels, c->maxv);
    fill(&c->s, g_second, in, &seed, levels, c->maxv);
    FUZZ_CHECK(ssda_view_init(&c->fv, g_first, (uint16_t)c->f.w, (uint16_t)c->f.h,
                              c->f.w * c->bpp, (ssda_pixfmt_t)c->bpp) == SSDA_OK);
    FUZZ_CHECK(ssda_view_init(&c->sv, g_second, (uint16_t)c->s.w, (uint16_t)c->s.h,
                              c->s.w * c->bpp, (ssda_pixfmt_t)c->bpp) == SSDA_OK);
}

/* The geometry, and ssda_track_grid's view of it. */
static void check_grid(case_t *c)
{
    const ssda_track_config_t *cfg = &c->cfg;
    const axis_t *axx = &c->axx, *axy = &c->axy;
    c->axx = axis(cfg->win_w, cfg->search_w, cfg->step_x, cfg->roi_x, cfg->roi_w, c->s.w);
    c->axy = axis(cfg->win_h, cfg->search_h, cfg->step_y, cfg->roi_y, cfg->roi_h, c->s.h);
    memset(&c->grid, 0x77, sizeof c->grid);
    c->grc = ssda_track_grid(cfg, (uint16_t)c->s.w, (uint16_t)c->s.h, &c->grid);
    FUZZ_CHECK((c->grc == SSDA_OK) == (axx->ok && axy->ok));
    if (c->grc != SSDA_OK) {
        FUZZ_CHECK(c->grc == SSDA_ERR_SIZE);
        return;
    }
    FUZZ_CHECK(c->grid.cols == axx->count && c->grid.rows == axy->count &&
               c->grid.count == axx->count * axy->count);
    FUZZ_CHECK(c->grid.win_w == axx->win && c->grid.search_w == axx->search &&
               c->grid.step_x == axx->step && c->grid.roi_w == axx->len);
    FUZZ_CHECK(c->grid.win_h == axy->win && c->grid.search_h == axy->search &&
               c->grid.step_y == axy->step && c->grid.roi_h == axy->len);
    FUZZ_CHECK(c->grid.count == SSDA_TRACK_GRID_COUNT(axx->len, axy->len, axx->win, axy->win,
                                                      axx->step, axy->step));
}

/* Is the whole input valid, by the header? */
static int input_valid(case_t *c)
{
    const ssda_track_config_t *cfg = &c->cfg;
    c->pixels = c->axx.win * c->axy.win;
    c->thr = cfg->texture_threshold ? cfg->texture_threshold : (c->maxv + 1u) / 2u;
    /* the default: w*h / 16, at least 1, at most w*h / 2 (0 for one pixel,
       issue 22.2: a default is always valid) */
    c->minc = cfg->texture_min_count ? cfg->texture_min_count
                                     : (c->pixels / 16u > 0u ? c->pixels / 16u
                                                             : (c->pixels / 2u < 1u ? 0u : 1u));
    const int unique = (cfg->flags & SSDA_TRACK_UNIQUE) != 0u;
    const uint64_t need_u = (cfg->match.flags & SSDA_MATCH_BOUNDS)
                                ? (uint64_t)SSDA_TRACK_WORK_SIZE(c->axx.search, c->axy.search,
                                                                 c->axx.win, c->axy.win)
                                : (uint64_t)SSDA_MATCH_UNIQUE_WORK;
    c->flat = (cfg->flags & SSDA_TRACK_NO_FLAT) ? 0u : (cfg->flat_q8 ? cfg->flat_q8 : 320u);
    if (unique && !((cfg->match.threshold == SSDA_THRESHOLD_AUTO ||
                     cfg->match.threshold == SSDA_THRESHOLD_NONE) &&
                    cfg->match.scan != SSDA_SCAN_COARSE &&
                    (cfg->unique_q8 == 0u || (cfg->unique_q8 >= 257u && cfg->unique_q8 <= 1024u)) &&
                    cfg->unique_radius <= 2u && cfg->match.work != NULL &&
                    cfg->match.work_size >= need_u)) {
        return 0;
    }
    return c->grc == SSDA_OK && c->grid.count <= c->out_count && cfg->predict <= 2u &&
           (cfg->flags & ~0x1Fu) == 0u && cfg->flat_q8 <= 65535u * 256u &&
           (!(cfg->flags & SSDA_TRACK_MASK) || cfg->mask_value <= c->maxv) &&
           (!(cfg->flags & SSDA_TRACK_EXCLUDE) || (c->thr < c->maxv && 2u * c->minc <= c->pixels)) &&
           !(cfg->predict != 0u && cfg->match.scan == SSDA_SCAN_COARSE) &&
           cfg->match.threshold <= 4u &&
           !(cfg->match.threshold == SSDA_THRESHOLD_RAMP && cfg->match.lambda_q8 == 0u) &&
           /* bounds alone need their tables only (track.h), with
              SSDA_TRACK_UNIQUE the list too (checked above) */
           !(cfg->match.flags &&
             (cfg->match.work == NULL ||
              cfg->match.work_size <
                  SSDA_MATCH_WORK_SIZE(c->axx.search, c->axy.search, c->axx.win, c->axy.win)));
}

/* The window's texture by track.h: floor(256 * sum |p - m| / n) with
   m = floor(sum p / n). */
static uint32_t texture_q8(const case_t *c, uint32_t wx, uint32_t wy)
{
    uint64_t sum = 0, dev = 0, m;
    uint32_t x, y;
    for (y = 0; y < c->axy.win; y++) {
        for (x = 0; x < c->axx.win; x++) {
            sum += px(&c->s, wx + x, wy + y);
        }
    }
    m = sum / c->pixels;
    for (y = 0; y < c->axy.win; y++) {
        for (x = 0; x < c->axx.win; x++) {
            uint64_t p = px(&c->s, wx + x, wy + y);
            dev += p > m ? p - m : m - p;
        }
    }
    return (uint32_t)(256u * dev / c->pixels);
}

/* The status the header gives the window at (wx, wy), area at (ax, ay),
   before the search: OK stands for "searched". */
static uint32_t expected_status(const case_t *c, uint32_t wx, uint32_t wy, int64_t ax, int64_t ay)
{
    const ssda_track_config_t *cfg = &c->cfg;
    uint32_t want = SSDA_TRACK_OK;
    if (ax < 0 || ay < 0 || ax + c->axx.search > c->f.w || ay + c->axy.search > c->f.h) {
        return SSDA_TRACK_EDGE;
    }
    if ((cfg->flags & SSDA_TRACK_MASK) &&
        holds(&c->s, wx, wy, c->axx.win, c->axy.win, cfg->mask_value)) {
        return SSDA_TRACK_MASKED;
    }
    if (cfg->flags & SSDA_TRACK_EXCLUDE) {
        uint32_t bright = 0, x, y;
        for (y = 0; y < c->axy.win; y++) {
            for (x = 0; x < c->axx.win; x++) {
                bright += px(&c->s, wx + x, wy + y) > c->thr;
            }
        }
        want = bright < c->minc || c->pixels - bright < c->minc ? SSDA_TRACK_EXCLUDED
                                                                : SSDA_TRACK_OK;
    }
    if (want == SSDA_TRACK_OK && c->flat != 0u && texture_q8(c, wx, wy) < c->flat) {
        want = SSDA_TRACK_FLAT;
    }
    if (want == SSDA_TRACK_OK && (cfg->flags & SSDA_TRACK_MASK) &&
        holds(&c->f, (uint32_t)ax, (uint32_t)ay, c->axx.search, c->axy.search,
              cfg->mask_value)) {
        want = SSDA_TRACK_MASKED;
    }
    return want;
}

/* A brute-force search of the area at (ax, ay) for the window at (wx, wy). */
static void check_brute(const case_t *c, const ssda_track_vector_t *v, uint32_t wx, uint32_t wy,
                        int64_t ax, int64_t ay)
{
    uint32_t hx = (c->axx.search - c->axx.win) / 2u, hy = (c->axy.search - c->axy.win) / 2u;
    uint64_t best = UINT64_MAX;
    uint32_t bx = 0, by = 0, x, y;
    for (y = 0; y + c->axy.win <= c->axy.search; y++) {
        for (x = 0; x + c->axx.win <= c->axx.search; x++) {
            uint64_t t = sad_at(&c->f, &c->s, (uint32_t)ax + x, (uint32_t)ay + y, wx, wy,
                                c->axx.win, c->axy.win);
            if (t < best) {
                best = t;
                bx = x;
                by = y;
            }
        }
    }
    FUZZ_CHECK(v->sad == best);
    (void)bx;
    (void)by;
    FUZZ_CHECK(sad_at(&c->f, &c->s, (uint32_t)(ax + (int64_t)hx - v->dx),
                      (uint32_t)(ay + (int64_t)hy - v->dy), wx, wy, c->axx.win,
                      c->axy.win) == best);
}

/* Window k: position, status, a vector inside its area, and in the exact
   modes the brute-force answer (every window while cheap, else a sample). */
static void check_window(const case_t *c, uint32_t k, int exact_mode, uint32_t counts[7])
{
    const ssda_track_vector_t *v = &g_out[k];
    uint32_t wx = c->axx.start + (k % c->grid.cols) * c->axx.step;
    uint32_t wy = c->axy.start + (k / c->grid.cols) * c->axy.step;
    uint32_t hx = (c->axx.search - c->axx.win) / 2u, hy = (c->axy.search - c->axy.win) / 2u;
    int64_t ax = (int64_t)wx - hx, ay = (int64_t)wy - hy;
    uint64_t brute_cost = (uint64_t)(c->axx.search - c->axx.win + 1u) *
                          (c->axy.search - c->axy.win + 1u) * c->pixels;
    FUZZ_CHECK(v->x == wx && v->y == wy);
    uint32_t want = expected_status(c, wx, wy, ax, ay);
    int at_limit;
    FUZZ_CHECK(v->status <= SSDA_TRACK_AT_LIMIT);
    counts[v->status]++;
    if (want != SSDA_TRACK_OK) {
        FUZZ_CHECK(v->status == want);
        FUZZ_CHECK(v->sad == 0 && v->dx == 0 && v->dy == 0 && !v->exact &&
                   v->sub_dx_q8 == 0 && v->sub_dy_q8 == 0);
        /* measured once the window reached the flat test: FLAT, and
           MASKED by its area (the window itself holds no fill) */
        FUZZ_CHECK(v->texture_q8 ==
                   ((want == SSDA_TRACK_FLAT ||
                     (want == SSDA_TRACK_MASKED && c->flat != 0u &&
                      !holds(&c->s, wx, wy, c->axx.win, c->axy.win, c->cfg.mask_value)))
                        ? texture_q8(c, wx, wy)
                        : 0u));
        return;
    }
    FUZZ_CHECK(v->texture_q8 == (c->flat != 0u ? texture_q8(c, wx, wy) : 0u));
    /* searched: AT_LIMIT when on the border of an axis with more than one
       placement, else AMBIGUOUS exactly when the uniqueness test found a
       rival, else OK */
    at_limit = (c->axx.search > c->axx.win &&
                (v->dx == (int32_t)hx ||
                 v->dx == (int32_t)hx - (int32_t)(c->axx.search - c->axx.win))) ||
               (c->axy.search > c->axy.win &&
                (v->dy == (int32_t)hy ||
                 v->dy == (int32_t)hy - (int32_t)(c->axy.search - c->axy.win)));
    if (at_limit) {
        FUZZ_CHECK(v->status == SSDA_TRACK_AT_LIMIT);
    } else if (v->unique_q8 != SSDA_MATCH_UNIQUE_NONE) {
        FUZZ_CHECK((c->cfg.flags & SSDA_TRACK_UNIQUE) && v->status == SSDA_TRACK_AMBIGUOUS);
    } else {
        FUZZ_CHECK(v->status == SSDA_TRACK_OK);
    }
    /* the vector stays inside the area; its SAD is the one there when exact */
    FUZZ_CHECK(v->dx <= (int32_t)hx &&
               v->dx >= (int32_t)hx - (int32_t)(c->axx.search - c->axx.win));
    FUZZ_CHECK(v->dy <= (int32_t)hy &&
               v->dy >= (int32_t)hy - (int32_t)(c->axy.search - c->axy.win));
    if (exact_mode) {
        FUZZ_CHECK(v->exact);
    }
    if (exact_mode && (brute_cost * c->grid.count <= BRUTE_BUDGET || k % c->check_every == 0u) &&
        brute_cost <= BRUTE_BUDGET) {
        check_brute(c, v, wx, wy, ax, ay);
    }
}

/* Stats count the statuses; a second call gives the same output. */
static void check_repeat(const case_t *c, const ssda_track_stats_t *st, const uint32_t counts[7])
{
    ssda_track_stats_t st2;
    uint32_t k;
    FUZZ_CHECK(st->windows == c->grid.count);
    FUZZ_CHECK(st->ok == counts[0] && st->excluded == counts[1] && st->masked == counts[2] &&
               st->edge == counts[3] && st->flat == counts[4] && st->ambiguous == counts[5] &&
               st->at_limit == counts[6]);
    FUZZ_CHECK(st->completed <= st->positions);
    memset(&st2, 0x4D, sizeof st2);
    FUZZ_CHECK(ssda_track(&c->fv, &c->sv, &c->cfg, g_out2, c->out_count, &st2) == SSDA_OK);
    FUZZ_CHECK(st->pixel_ops == st2.pixel_ops && st->positions == st2.positions &&
               st->completed == st2.completed && st->check_pixels == st2.check_pixels &&
               st->windows == st2.windows && st->ok == st2.ok && st->edge == st2.edge);
    for (k = 0; k < c->grid.count; k++) { /* field by field: padding may differ */
        const ssda_track_vector_t *a = &g_out[k], *b = &g_out2[k];
        FUZZ_CHECK(a->sad == b->sad && a->dx == b->dx && a->dy == b->dy && a->x == b->x &&
                   a->y == b->y && a->status == b->status && a->exact == b->exact &&
                   a->sub_dx_q8 == b->sub_dx_q8 && a->sub_dy_q8 == b->sub_dy_q8 &&
                   a->texture_q8 == b->texture_q8 && a->unique_q8 == b->unique_q8);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in_t in = {data, size};
    case_t c;
    ssda_track_stats_t st, poison_st;
    ssda_track_vector_t poison_v;
    uint32_t k, counts[7] = {0, 0, 0, 0, 0, 0, 0};
    int rc, valid, exact_mode;

    memset(&c, 0, sizeof c);
    read_case(&in, &c);
    check_grid(&c);
    valid = input_valid(&c);
    exact_mode = (c.cfg.match.threshold == SSDA_THRESHOLD_AUTO ||
                  c.cfg.match.threshold == SSDA_THRESHOLD_NONE) &&
                 c.cfg.match.scan != SSDA_SCAN_COARSE;
    memset(&poison_v, 0x4D, sizeof poison_v);
    memset(&poison_st, 0x4D, sizeof poison_st);
    for (k = 0; k <= MAX_OUT; k++) {
        g_out[k] = poison_v;
    }
    st = poison_st;
    rc = ssda_track(&c.fv, &c.sv, &c.cfg, g_out, c.out_count, &st);
    if (!valid) { /* refused, out and stats untouched */
        FUZZ_CHECK(rc < 0);
        FUZZ_CHECK(memcmp(&st, &poison_st, sizeof st) == 0);
        for (k = 0; k <= MAX_OUT; k++) {
            FUZZ_CHECK(memcmp(&g_out[k], &poison_v, sizeof poison_v) == 0);
        }
        return 0;
    }
    FUZZ_CHECK(rc == SSDA_OK);
    for (k = c.grid.count; k <= MAX_OUT; k++) {
        FUZZ_CHECK(memcmp(&g_out[k], &poison_v, sizeof poison_v) == 0);
    }
    for (k = 0; k < c.grid.count; k++) {
        check_window(&c, k, exact_mode, counts);
    }
    check_repeat(&c, &st, counts);
    return 0;
}
