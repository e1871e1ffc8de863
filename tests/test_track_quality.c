/*
 * test_track_quality.c - what a tracking unit reads besides the vector
 * (issue 15): the tie rule nearest to the prediction, the FLAT texture test,
 * AT_LIMIT, uniqueness (AMBIGUOUS and unique_q8) and the sub-pixel fit, all
 * against an independent reference tracker written here from track.h's
 * definitions (full SAD surfaces, no early exit), in every exact mode, scan,
 * row order, bound option and prediction; sub-pixel accuracy on known
 * fractional shifts; the fit on SADs beyond 2^31; argument errors.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/track.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#define IMG 96u
#ifdef SSDA_TEST_SMALL
#define SEEDS 3u
#else
#define SEEDS 6u
#endif
#define MAXWIN 128u
#define NPOS (33u * 33u)

static uint16_t g_first[IMG * IMG];
static uint16_t g_second[IMG * IMG];
static uint64_t g_work[(SSDA_TRACK_WORK_SIZE(40, 40, 16, 16) + 7u) / 8u];
static ssda_track_vector_t g_out[MAXWIN];
static ssda_track_vector_t g_ref[MAXWIN];
static uint64_t g_surface[NPOS];

/* ---- the reference tracker ------------------------------------------------ */

typedef struct {
    const ssda_view_t *first, *second;
    const ssda_track_config_t *cfg;
    ssda_track_grid_t g;
    uint32_t flat_q8;  /* 0: no flat test */
    uint32_t uq8;      /* 0: no uniqueness */
    uint32_t urad;
    bool subpixel;
} ref_t;

static uint32_t px_at(const ssda_view_t *v, uint32_t x, uint32_t y)
{
    return test_px(v, x, y);
}

/* Mean absolute deviation from the mean rounded down, Q8 (track.h). */
static uint32_t ref_mad_q8(const ssda_view_t *v, uint32_t x0, uint32_t y0, uint32_t w, uint32_t h)
{
    uint64_t sum = 0, dev = 0, n = (uint64_t)w * h, m;
    uint32_t x, y;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            sum += px_at(v, x0 + x, y0 + y);
        }
    }
    m = sum / n;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint64_t p = px_at(v, x0 + x, y0 + y);
            dev += p > m ? p - m : m - p;
        }
    }
    return (uint32_t)((dev * 256u) / n);
}

static int32_t med3(int32_t a, int32_t b, int32_t c)
{
    int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    return c < lo ? lo : (c > hi ? hi : c);
}

/* The prediction of track.h from the OK vectors solved so far. */
static void ref_predict(const ref_t *r, const ssda_track_vector_t *out, uint32_t col,
                        uint32_t row, int32_t *pdx, int32_t *pdy)
{
    const uint32_t cols = r->g.cols;
    const ssda_track_vector_t *cand[4] = {NULL, NULL, NULL, NULL}, *ok[3];
    uint32_t n = 0, i, k = row * cols + col;
    if (col > 0) {
        cand[0] = &out[k - 1];
    }
    if (row > 0) {
        cand[1] = &out[k - cols];
        if (col + 1 < cols) {
            cand[2] = &out[k - cols + 1];
        }
        if (col > 0) {
            cand[3] = &out[k - cols - 1];
        }
    }
    *pdx = 0;
    *pdy = 0;
    if (r->cfg->predict == SSDA_TRACK_PREDICT_LEFT) {
        const ssda_track_vector_t *v = col > 0 ? cand[0] : cand[1];
        if (v != NULL && v->status == SSDA_TRACK_OK) {
            *pdx = v->dx;
            *pdy = v->dy;
        }
        return;
    }
    if (r->cfg->predict == SSDA_TRACK_PREDICT_NONE) {
        return;
    }
    for (i = 0; i < 4 && n < 3; i++) {
        if (cand[i] != NULL && cand[i]->status == SSDA_TRACK_OK) {
            ok[n++] = cand[i];
        }
    }
    if (n == 3) {
        *pdx = med3(ok[0]->dx, ok[1]->dx, ok[2]->dx);
        *pdy = med3(ok[0]->dy, ok[1]->dy, ok[2]->dy);
    } else if (n > 0) {
        *pdx = ok[0]->dx;
        *pdy = ok[0]->dy;
    }
}

static uint32_t clampu(int32_t v, uint32_t n)
{
    return v < 0 ? 0u : ((uint32_t)v >= n ? n - 1u : (uint32_t)v);
}

/* V fit of match.h: 128 |l - r| / (max(l, r) - c), rounded half away from 0;
   0 for an exact match (c = 0). */
static int32_t ref_vfit(uint64_t l, uint64_t c, uint64_t r)
{
    uint64_t den = (l > r ? l : r) - c, num = l > r ? l - r : r - l, q;
    if (den == 0 || c == 0) {
        return 0;
    }
    q = (256u * num + den) / (2u * den);
    return l >= r ? (int32_t)q : -(int32_t)q;
}

static bool ref_masked(const ref_t *r, const ssda_view_t *v, uint32_t x0, uint32_t y0,
                       uint32_t w, uint32_t h)
{
    uint32_t x, y;
    if ((r->cfg->flags & SSDA_TRACK_MASK) == 0) {
        return false;
    }
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            if (px_at(v, x0 + x, y0 + y) == r->cfg->mask_value) {
                return true;
            }
        }
    }
    return false;
}

static void ref_search(const ref_t *r, ssda_track_vector_t *v, uint32_t wx, uint32_t wy,
                       int32_t pdx, int32_t pdy)
{
    const ssda_track_grid_t *g = &r->g;
    const uint32_t hx = (g->search_w - g->win_w) / 2u, hy = (g->search_h - g->win_h) / 2u;
    const uint32_t nx = g->search_w - g->win_w + 1u, ny = g->search_h - g->win_h + 1u;
    const uint32_t cx = clampu((int32_t)hx - pdx, nx), cy = clampu((int32_t)hy - pdy, ny);
    ssda_view_t area, win;
    uint32_t x, y, bx = 0, by = 0;
    uint64_t best = UINT64_MAX, bd = 0;
    TEST_ASSERT_TRUE(nx * ny <= NPOS);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&win, r->second, (uint16_t)wx, (uint16_t)wy,
                                                 g->win_w, g->win_h));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&area, r->first, (uint16_t)(wx - hx),
                                                 (uint16_t)(wy - hy), g->search_w, g->search_h));
    for (y = 0; y < ny; y++) {
        for (x = 0; x < nx; x++) {
            uint64_t s = test_sad(&area, &win, x, y);
            uint64_t d = (uint64_t)((int64_t)x - cx) * (uint64_t)((int64_t)x - cx) +
                         (uint64_t)((int64_t)y - cy) * (uint64_t)((int64_t)y - cy);
            g_surface[y * nx + x] = s;
            /* raster order: a later position wins only if strictly better
               by (sad, distance); equal distance keeps the earlier (y, x) */
            if (s < best || (s == best && d < bd)) {
                best = s;
                bd = d;
                bx = x;
                by = y;
            }
        }
    }
    v->sad = best;
    v->dx = (int32_t)hx - (int32_t)bx;
    v->dy = (int32_t)hy - (int32_t)by;
    v->exact = true;
    v->sub_dx_q8 = v->dx * 256;
    v->sub_dy_q8 = v->dy * 256;
    if (r->subpixel && bx > 0 && bx + 1 < nx) {
        v->sub_dx_q8 -= ref_vfit(g_surface[by * nx + bx - 1], best, g_surface[by * nx + bx + 1]);
    }
    if (r->subpixel && by > 0 && by + 1 < ny) {
        v->sub_dy_q8 -= ref_vfit(g_surface[(by - 1) * nx + bx], best, g_surface[(by + 1) * nx + bx]);
    }
    v->unique_q8 = SSDA_MATCH_UNIQUE_NONE;
    if (r->uq8 != 0) {
        uint64_t lim = (best * r->uq8) / 256u, s2 = UINT64_MAX;
        for (y = 0; y < ny; y++) {
            for (x = 0; x < nx; x++) {
                uint32_t ddx = x > bx ? x - bx : bx - x, ddy = y > by ? y - by : by - y;
                if ((ddx > r->urad || ddy > r->urad) && g_surface[y * nx + x] <= lim &&
                    g_surface[y * nx + x] < s2) {
                    s2 = g_surface[y * nx + x];
                }
            }
        }
        if (s2 != UINT64_MAX) {
            v->unique_q8 = (uint16_t)(best == 0 ? 256u : (s2 * 256u) / best);
        }
    }
    v->status = SSDA_TRACK_OK;
    if ((nx > 1 && (bx == 0 || bx == nx - 1)) || (ny > 1 && (by == 0 || by == ny - 1))) {
        v->status = SSDA_TRACK_AT_LIMIT;
    } else if (v->unique_q8 != SSDA_MATCH_UNIQUE_NONE) {
        v->status = SSDA_TRACK_AMBIGUOUS;
    }
}

static void ref_track(ref_t *r, ssda_track_vector_t *out)
{
    const ssda_track_grid_t *g = &r->g;
    const uint32_t hx = (g->search_w - g->win_w) / 2u, hy = (g->search_h - g->win_h) / 2u;
    uint32_t row, col;
    for (row = 0; row < g->rows; row++) {
        for (col = 0; col < g->cols; col++) {
            ssda_track_vector_t *v = &out[row * g->cols + col];
            uint32_t wx = g->roi_x + col * g->step_x, wy = g->roi_y + row * g->step_y;
            int32_t pdx, pdy;
            memset(v, 0, sizeof *v);
            v->x = (uint16_t)wx;
            v->y = (uint16_t)wy;
            v->unique_q8 = SSDA_MATCH_UNIQUE_NONE;
            v->status = SSDA_TRACK_EDGE;
            if (wx < hx || wy < hy || wx - hx + g->search_w > r->first->width ||
                wy - hy + g->search_h > r->first->height) {
                continue;
            }
            v->status = SSDA_TRACK_MASKED;
            if (ref_masked(r, r->second, wx, wy, g->win_w, g->win_h)) {
                continue;
            }
            if (r->flat_q8 != 0) {
                v->texture_q8 = ref_mad_q8(r->second, wx, wy, g->win_w, g->win_h);
                if (v->texture_q8 < r->flat_q8) {
                    v->status = SSDA_TRACK_FLAT;
                    continue;
                }
            }
            if (ref_masked(r, r->first, wx - hx, wy - hy, g->search_w, g->search_h)) {
                continue;
            }
            ref_predict(r, out, col, row, &pdx, &pdy);
            ref_search(r, v, wx, wy, pdx, pdy);
        }
    }
}

/* ---- scenes ------------------------------------------------------------- */

/* A grid of 16-px cells, each of one kind, in both images (16-bit samples
   up to maxv): textured cells whose content moved by a per-cell shift
   (some at +-8, the limit), constant cells (every placement ties), cells
   of small noise around a level (flat by texture), vertical stripes of
   period 4 (equal minima 4 px apart: ambiguous), horizontal ramps (every
   vertical shift nearly ties). */
static void make_scene(test_rng_t *rng, uint32_t maxv)
{
    uint32_t cx, cy, x, y;
    test_fill_texture_u16(g_first, IMG, IMG, IMG, maxv, rng);
    memcpy(g_second, g_first, sizeof g_second);
    for (cy = 0; cy < IMG / 16u; cy++) {
        for (cx = 0; cx < IMG / 16u; cx++) {
            uint32_t kind = test_rng_range(rng, 0, 7);
            int32_t dx = (int32_t)test_rng_range(rng, 0, 16) - 8;
            int32_t dy = (int32_t)test_rng_range(rng, 0, 16) - 8;
            uint32_t level = test_rng_range(rng, 2, maxv - 2);
            for (y = cy * 16u; y < cy * 16u + 16u; y++) {
                for (x = cx * 16u; x < cx * 16u + 16u; x++) {
                    int32_t sx = (int32_t)x - dx, sy = (int32_t)y - dy;
                    uint32_t a, b;
                    switch (kind) {
                    case 0: a = b = level; break;
                    case 1:
                        a = level + test_rng_range(rng, 0, 2) - 1u;
                        b = level + test_rng_range(rng, 0, 2) - 1u;
                        break;
                    case 2: a = b = (x % 4u) < 2u ? level / 2u : level; break;
                    case 3: a = b = (x * maxv) / IMG; break;
                    default:
                        a = g_first[y * IMG + x];
                        b = sx >= 0 && sy >= 0 && sx < (int32_t)IMG && sy < (int32_t)IMG
                                ? g_first[(uint32_t)sy * IMG + (uint32_t)sx]
                                : a;
                        break;
                    }
                    if (kind < 4u) {
                        g_first[y * IMG + x] = (uint16_t)a;
                    }
                    g_second[y * IMG + x] = (uint16_t)b;
                }
            }
        }
    }
}

static void narrow(uint32_t maxv)
{
    /* an 8-bit copy in place: the views then read the low byte stride */
    uint32_t i;
    (void)maxv;
    for (i = 0; i < IMG * IMG; i++) {
        ((uint8_t *)g_first)[i] = (uint8_t)g_first[i];
        ((uint8_t *)g_second)[i] = (uint8_t)g_second[i];
    }
}

static void compare(const ssda_track_vector_t *want, const ssda_track_vector_t *got, uint32_t n,
                    const char *what)
{
    uint32_t k;
    for (k = 0; k < n; k++) {
        const ssda_track_vector_t *a = &want[k], *b = &got[k];
        char msg[200];
        snprintf(msg, sizeof msg, "%s: window %u (%u,%u) status %u/%u d (%d,%d)/(%d,%d) sub (%d,%d)/(%d,%d) "
                 "sad %llu/%llu tex %u/%u uniq %u/%u",
                 what, (unsigned)k, a->x, a->y, a->status, b->status, (int)a->dx, (int)a->dy,
                 (int)b->dx, (int)b->dy, (int)a->sub_dx_q8, (int)a->sub_dy_q8, (int)b->sub_dx_q8,
                 (int)b->sub_dy_q8, (unsigned long long)a->sad, (unsigned long long)b->sad,
                 (unsigned)a->texture_q8, (unsigned)b->texture_q8, a->unique_q8, b->unique_q8);
        TEST_ASSERT_EQUAL_UINT8_MESSAGE(a->status, b->status, msg);
        TEST_ASSERT_EQUAL_UINT16_MESSAGE(a->x, b->x, msg);
        TEST_ASSERT_EQUAL_UINT16_MESSAGE(a->y, b->y, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(a->texture_q8, b->texture_q8, msg);
        if (a->status == SSDA_TRACK_OK || a->status == SSDA_TRACK_AMBIGUOUS ||
            a->status == SSDA_TRACK_AT_LIMIT) {
            TEST_ASSERT_EQUAL_INT32_MESSAGE(a->dx, b->dx, msg);
            TEST_ASSERT_EQUAL_INT32_MESSAGE(a->dy, b->dy, msg);
            TEST_ASSERT_EQUAL_UINT64_MESSAGE(a->sad, b->sad, msg);
            TEST_ASSERT_EQUAL_INT32_MESSAGE(a->sub_dx_q8, b->sub_dx_q8, msg);
            TEST_ASSERT_EQUAL_INT32_MESSAGE(a->sub_dy_q8, b->sub_dy_q8, msg);
            TEST_ASSERT_EQUAL_UINT16_MESSAGE(a->unique_q8, b->unique_q8, msg);
            TEST_ASSERT_TRUE_MESSAGE(b->exact, msg);
        } else {
            TEST_ASSERT_EQUAL_INT32_MESSAGE(0, b->dx, msg);
            TEST_ASSERT_EQUAL_INT32_MESSAGE(0, b->sub_dx_q8, msg);
            TEST_ASSERT_EQUAL_UINT16_MESSAGE(SSDA_MATCH_UNIQUE_NONE, b->unique_q8, msg);
            TEST_ASSERT_FALSE_MESSAGE(b->exact, msg);
        }
    }
}

/* Every exact mode, scan, order, bound option and prediction gives the
   reference's vectors, statuses and quality on scenes full of ties, flat
   cells, stripes, ramps and motions at the limit; 8- and 16-bit. */
static void test_quality_equals_reference_in_every_exact_mode(void)
{
    static const uint16_t ratios[3] = {0, 300, 1024};
    uint32_t seen[7] = {0};
    uint32_t seed;
    for (seed = 1; seed <= SEEDS; seed++) {
        test_rng_t rng;
        bool u8 = (seed % 2u) == 0u;
        uint32_t maxv = u8 ? 255u : (seed % 3u ? 4095u : 65535u);
        ssda_view_t a, b;
        ssda_track_config_t cfg;
        ref_t r;
        uint32_t variant, k;
        test_rng_seed(&rng, seed * 7919u);
        make_scene(&rng, maxv);
        if (u8) {
            narrow(maxv);
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first, IMG, IMG, u8 ? IMG : 2u * IMG,
                                                      u8 ? SSDA_PIX_U8 : SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_second, IMG, IMG, u8 ? IMG : 2u * IMG,
                                                      u8 ? SSDA_PIX_U8 : SSDA_PIX_U16));
        memset(&cfg, 0, sizeof cfg);
        cfg.flags = SSDA_TRACK_UNIQUE;
        cfg.unique_q8 = ratios[seed % 3u];
        cfg.unique_radius = (uint8_t)(seed % 3u);
        cfg.flat_q8 = seed % 4u == 0u ? 600u : 0u;
        cfg.step_x = seed % 2u ? 16u : 11u;
        cfg.step_y = seed % 2u ? 16u : 13u;
        cfg.search_w = seed % 5u == 0u ? 40u : 0u;
        cfg.match.work = g_work;
        cfg.match.work_size = sizeof g_work;
        memset(&r, 0, sizeof r);
        r.first = &a;
        r.second = &b;
        r.cfg = &cfg;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&cfg, IMG, IMG, &r.g));
        TEST_ASSERT_TRUE(r.g.count <= MAXWIN);
        r.flat_q8 = cfg.flat_q8 != 0u ? cfg.flat_q8 : SSDA_TRACK_DEFAULT_FLAT_Q8;
        r.uq8 = cfg.unique_q8 != 0u ? cfg.unique_q8 : SSDA_MATCH_DEFAULT_UNIQUE_Q8;
        r.urad = cfg.unique_radius != 0u ? cfg.unique_radius : SSDA_MATCH_DEFAULT_UNIQUE_RADIUS;
        r.subpixel = true;
        /* threshold x bounds x order x prediction (none/raster, none/predict
           scan, left, median) */
        for (variant = 0; variant < 32u; variant++) {
            char what[64];
            uint8_t predict = (uint8_t)(variant >> 3);
            cfg.match.threshold = (variant & 1u) ? SSDA_THRESHOLD_NONE : SSDA_THRESHOLD_AUTO;
            cfg.match.flags = (variant & 2u) ? SSDA_MATCH_BOUNDS : 0u;
            cfg.match.order = (variant & 4u) ? SSDA_ORDER_SPREAD : SSDA_ORDER_ROWS;
            cfg.match.scan = predict == 1u ? SSDA_SCAN_PREDICT : SSDA_SCAN_RASTER;
            cfg.predict = predict >= 2u ? (uint8_t)(predict - 1u) : SSDA_TRACK_PREDICT_NONE;
            if (variant % 8u == 0u) { /* the reference once per prediction mode */
                ref_track(&r, g_ref);
            }
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, MAXWIN, NULL));
            snprintf(what, sizeof what, "seed %u variant %u", (unsigned)seed, (unsigned)variant);
            compare(g_ref, g_out, r.g.count, what);
        }
        for (k = 0; k < r.g.count; k++) {
            seen[g_ref[k].status]++;
        }
    }
    /* the scenes exercise every status the quality decides */
    TEST_ASSERT_TRUE(seen[SSDA_TRACK_OK] > 0u);
    TEST_ASSERT_TRUE(seen[SSDA_TRACK_FLAT] > 0u);
    TEST_ASSERT_TRUE(seen[SSDA_TRACK_AMBIGUOUS] > 0u);
    TEST_ASSERT_TRUE(seen[SSDA_TRACK_AT_LIMIT] > 0u);
}

/* Boundaries, on one row: a 1 x 1 window of 0 over a 16-bit row, so each
   placement's SAD is the row's sample there. */
static void row_match(const uint16_t *row, uint32_t n, uint8_t flags, uint16_t uq8,
                      ssda_match_result_t *res)
{
    static const uint16_t zero = 0;
    ssda_view_t area, win;
    ssda_match_config_t cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.flags = flags;
    cfg.unique_q8 = uq8;
    cfg.work = g_work;
    cfg.work_size = sizeof g_work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, row, (uint16_t)n, 1, 2u * n, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, &zero, 1, 1, 2, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, res));
}

/* Uniqueness: within the ratio means sad2 <= floor(ratio * best); the
   neighbourhood is a square of radius R (2 by default). */
static void test_uniqueness_boundaries(void)
{
    uint16_t row[7] = {1000, 1000, 256, 1000, 1000, 282, 1000};
    ssda_match_result_t res;
    row_match(row, 7, SSDA_MATCH_UNIQUE, 282, &res); /* 282 <= 256 * 282 / 256 */
    TEST_ASSERT_EQUAL_UINT16(2, res.x);
    TEST_ASSERT_EQUAL_UINT16(282, res.unique_q8);
    row[5] = 283;
    row_match(row, 7, SSDA_MATCH_UNIQUE, 282, &res);
    TEST_ASSERT_EQUAL_UINT16(SSDA_MATCH_UNIQUE_NONE, res.unique_q8);
    row_match(row, 7, SSDA_MATCH_UNIQUE, 0, &res); /* default 282 */
    TEST_ASSERT_EQUAL_UINT16(SSDA_MATCH_UNIQUE_NONE, res.unique_q8);
    row_match(row, 7, SSDA_MATCH_UNIQUE, 284, &res); /* 283 <= 284: ratio 283/256 */
    TEST_ASSERT_EQUAL_UINT16(283, res.unique_q8);
    row[5] = 1000;
    row[4] = 260; /* distance 2: inside the 5 x 5 neighbourhood, outside 3 x 3 */
    row_match(row, 7, SSDA_MATCH_UNIQUE, 300, &res);
    TEST_ASSERT_EQUAL_UINT16(SSDA_MATCH_UNIQUE_NONE, res.unique_q8);
    {
        ssda_view_t area, win;
        ssda_match_config_t cfg;
        static const uint16_t zero = 0;
        memset(&cfg, 0, sizeof cfg);
        cfg.flags = SSDA_MATCH_UNIQUE;
        cfg.unique_q8 = 300;
        cfg.unique_radius = 1;
        cfg.work = g_work;
        cfg.work_size = sizeof g_work;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, row, 7, 1, 14, SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, &zero, 1, 1, 2, SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&area, &win, &cfg, &res));
        TEST_ASSERT_EQUAL_UINT16(260, res.unique_q8); /* floor(256 * 260 / 256) */
    }
    /* a perfect match and another one: ratio 1.0 */
    row[2] = 0;
    row[6] = 0;
    row_match(row, 7, SSDA_MATCH_UNIQUE, 0, &res);
    TEST_ASSERT_EQUAL_UINT64(0, res.sad);
    TEST_ASSERT_EQUAL_UINT16(256, res.unique_q8);
}

/* The flat test: FLAT when the mean absolute deviation is below the level
   (a window half m, half m + 2 deviates by exactly 1.0 = 256 in Q8). */
static void test_flat_boundary(void)
{
    ssda_view_t a, b;
    ssda_track_config_t cfg;
    uint32_t x, y;
    for (y = 0; y < 48; y++) {
        for (x = 0; x < 48; x++) {
            g_second[y * 48 + x] = (uint16_t)(1000u + ((x + y) % 2u) * 2u);
            g_first[y * 48 + x] = g_second[y * 48 + x];
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, g_first, 48, 48, 96, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, g_second, 48, 48, 96, SSDA_PIX_U16));
    memset(&cfg, 0, sizeof cfg);
    cfg.roi_x = 16;
    cfg.roi_y = 16;
    cfg.roi_w = 16;
    cfg.roi_h = 16;
    cfg.flat_q8 = 256;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, MAXWIN, NULL));
    TEST_ASSERT_EQUAL_UINT32(256, g_out[0].texture_q8);
    TEST_ASSERT_TRUE(g_out[0].status != SSDA_TRACK_FLAT); /* not below the level */
    cfg.flat_q8 = 257;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, MAXWIN, NULL));
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_FLAT, g_out[0].status);
    TEST_ASSERT_EQUAL_UINT32(256, g_out[0].texture_q8);
    TEST_ASSERT_EQUAL_INT32(0, g_out[0].dx);
    cfg.flags = SSDA_TRACK_NO_FLAT; /* no test: searched, texture not measured */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, MAXWIN, NULL));
    TEST_ASSERT_TRUE(g_out[0].status != SSDA_TRACK_FLAT);
    TEST_ASSERT_EQUAL_UINT32(0, g_out[0].texture_q8);
}

/* Known fractional motion: SECOND(x, y) = FIRST(x - u, y - v) by bilinear
   interpolation of a smooth texture (rounded to whole grey levels). Every
   OK window's sub-pixel vector lies within 0.3 px of (u, v) on each axis,
   and the sub-pixel vectors are nearer on average than the whole ones. */
static void test_subpixel_on_known_fractional_shift(void)
{
    static const double shifts[3][2] = {{2.3, -1.6}, {-0.5, 0.25}, {4.75, 3.1}};
    uint8_t *f = (uint8_t *)g_first, *s = (uint8_t *)g_second;
    uint32_t i;
    for (i = 0; i < 3; i++) {
        const double u = shifts[i][0], v = shifts[i][1];
        test_rng_t rng;
        ssda_view_t a, b;
        ssda_track_config_t cfg;
        ssda_track_grid_t g;
        double err_sub = 0, err_whole = 0;
        uint32_t x, y, k, ok = 0;
        test_rng_seed(&rng, 99u + i);
        test_fill_texture_u8(f, IMG, IMG, IMG, &rng);
        for (y = 0; y < IMG; y++) {
            for (x = 0; x < IMG; x++) {
                double sx = x - u, sy = y - v, tx, ty, val;
                int32_t x0, y0;
                sx = sx < 0 ? 0 : (sx > IMG - 1.001 ? IMG - 1.001 : sx);
                sy = sy < 0 ? 0 : (sy > IMG - 1.001 ? IMG - 1.001 : sy);
                x0 = (int32_t)sx;
                y0 = (int32_t)sy;
                tx = sx - x0;
                ty = sy - y0;
                val = f[y0 * IMG + x0] * (1 - tx) * (1 - ty) + f[y0 * IMG + x0 + 1] * tx * (1 - ty) +
                      f[(y0 + 1) * IMG + x0] * (1 - tx) * ty + f[(y0 + 1) * IMG + x0 + 1] * tx * ty;
                s[y * IMG + x] = (uint8_t)(val + 0.5);
            }
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, f, IMG, IMG, IMG, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, s, IMG, IMG, IMG, SSDA_PIX_U8));
        memset(&cfg, 0, sizeof cfg);
        cfg.predict = SSDA_TRACK_PREDICT_MEDIAN;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&cfg, IMG, IMG, &g));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, MAXWIN, NULL));
        for (k = 0; k < g.count; k++) {
            const ssda_track_vector_t *w = &g_out[k];
            double sdx = w->sub_dx_q8 / 256.0, sdy = w->sub_dy_q8 / 256.0;
            if (w->status != SSDA_TRACK_OK) {
                continue;
            }
            ok++;
            TEST_ASSERT_DOUBLE_WITHIN(0.3, u, sdx);
            TEST_ASSERT_DOUBLE_WITHIN(0.3, v, sdy);
            err_sub += (sdx - u) * (sdx - u) + (sdy - v) * (sdy - v);
            err_whole += (w->dx - u) * (w->dx - u) + (w->dy - v) * (w->dy - v);
        }
        TEST_ASSERT_TRUE(ok >= 9u); /* the 4 x 4 inner windows of the 6 x 6 grid, most of them */
        TEST_ASSERT_TRUE(err_sub < 0.5 * err_whole);
    }
}

/* The V fit on SADs beyond 2^31 (the fit scales them down): a 1 x 40000
   16-bit window of 0 over three columns of 65535, 1000 and 30000. */
static void test_subpixel_fit_on_large_sads(void)
{
    static uint16_t area[3 * 40000], win[40000];
    const uint64_t l = 40000ull * 65535u, c = 40000ull * 1000u, r = 40000ull * 30000u;
    ssda_view_t av, wv;
    ssda_match_config_t cfg;
    ssda_match_result_t res;
    uint64_t want;
    uint32_t y;
    for (y = 0; y < 40000u; y++) {
        area[3 * y] = 65535u;
        area[3 * y + 1] = 1000u;
        area[3 * y + 2] = 30000u;
        win[y] = 0;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&av, area, 3, 40000, 6, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&wv, win, 1, 40000, 2, SSDA_PIX_U16));
    memset(&cfg, 0, sizeof cfg);
    cfg.flags = SSDA_MATCH_SUBPIXEL;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&av, &wv, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(1, res.x);
    TEST_ASSERT_EQUAL_UINT64(c, res.sad);
    TEST_ASSERT_TRUE(l - c >= 0x80000000ull); /* the scaled path */
    want = (256u * (l - r) + (l - c)) / (2u * (l - c));
    TEST_ASSERT_INT_WITHIN(1, (int32_t)want, res.sub_x_q8);
    TEST_ASSERT_EQUAL_INT16(0, res.sub_y_q8); /* one row of placements: no fit */
}

/* Outside the exact modes (here the coarse scan, without prediction) the
   fit is not asked for: the sub-pixel vector is the whole one. */
static void test_no_fit_outside_the_exact_modes(void)
{
    uint8_t *f = (uint8_t *)g_first, *s = (uint8_t *)g_second;
    test_rng_t rng;
    ssda_view_t a, b;
    ssda_track_config_t cfg;
    ssda_track_grid_t g;
    uint32_t i, k, searched = 0;
    test_rng_seed(&rng, 5u);
    test_fill_texture_u8(f, IMG, IMG, IMG, &rng);
    for (i = 0; i < IMG * IMG; i++) {
        s[i] = i % IMG >= 2u ? f[i - 2u] : f[i];
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&a, f, IMG, IMG, IMG, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&b, s, IMG, IMG, IMG, SSDA_PIX_U8));
    for (i = 0; i < 2u; i++) {
        memset(&cfg, 0, sizeof cfg);
        cfg.match.scan = i ? SSDA_SCAN_RASTER : SSDA_SCAN_COARSE;
        cfg.match.threshold = i ? SSDA_THRESHOLD_AUTO_RAMP : SSDA_THRESHOLD_AUTO;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&cfg, IMG, IMG, &g));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &cfg, g_out, MAXWIN, NULL));
        for (k = 0; k < g.count; k++) {
            if (g_out[k].status == SSDA_TRACK_OK || g_out[k].status == SSDA_TRACK_AT_LIMIT) {
                searched++;
                TEST_ASSERT_EQUAL_INT32(256 * g_out[k].dx, g_out[k].sub_dx_q8);
                TEST_ASSERT_EQUAL_INT32(256 * g_out[k].dy, g_out[k].sub_dy_q8);
            }
        }
    }
    TEST_ASSERT_TRUE(searched > 0u);
}

/* Errors: nothing written. */
static void test_quality_argument_errors(void)
{
    static const uint8_t px[4] = {1, 2, 3, 4};
    ssda_view_t area, win;
    ssda_match_config_t cfg;
    ssda_match_result_t res;
    ssda_track_config_t tc;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&area, px, 4, 1, 4, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&win, px, 1, 1, 1, SSDA_PIX_U8));
    memset(&cfg, 0, sizeof cfg);
    memset(&res, 0x5A, sizeof res);
    cfg.flags = SSDA_MATCH_UNIQUE; /* no work buffer */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_match(&area, &win, &cfg, &res));
    cfg.work = g_work;
    cfg.work_size = SSDA_MATCH_UNIQUE_WORK - 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_match(&area, &win, &cfg, &res));
    cfg.work_size = SSDA_MATCH_UNIQUE_WORK;
    cfg.work = (uint8_t *)g_work + 4; /* 8-byte alignment */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_match(&area, &win, &cfg, &res));
    cfg.work = g_work;
    cfg.unique_q8 = 256; /* a ratio must exceed 1 */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&area, &win, &cfg, &res));
    cfg.unique_q8 = 1025;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&area, &win, &cfg, &res));
    cfg.unique_q8 = 0;
    cfg.unique_radius = 3;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&area, &win, &cfg, &res));
    cfg.unique_radius = 0;
    cfg.flags = SSDA_MATCH_SUBPIXEL;
    cfg.threshold = SSDA_THRESHOLD_FIXED; /* exact modes only */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&area, &win, &cfg, &res));
    cfg.threshold = SSDA_THRESHOLD_AUTO;
    cfg.scan = SSDA_SCAN_COARSE;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_match(&area, &win, &cfg, &res));
    TEST_ASSERT_EQUAL_UINT16(0x5A5A, res.x); /* untouched */
    memset(&tc, 0, sizeof tc);
    tc.win_w = tc.win_h = 1;
    tc.flags = SSDA_TRACK_UNIQUE; /* no work buffer */
    memset(g_out, 0x5A, sizeof g_out);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_track(&area, &area, &tc, g_out, MAXWIN, NULL));
    tc.flags = 0x80;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_track(&area, &area, &tc, g_out, MAXWIN, NULL));
    TEST_ASSERT_EQUAL_UINT8(0x5A, g_out[0].status);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_quality_equals_reference_in_every_exact_mode);
    RUN_TEST(test_uniqueness_boundaries);
    RUN_TEST(test_flat_boundary);
    RUN_TEST(test_subpixel_on_known_fractional_shift);
    RUN_TEST(test_subpixel_fit_on_large_sads);
    RUN_TEST(test_no_fit_outside_the_exact_modes);
    RUN_TEST(test_quality_argument_errors);
    return UNITY_END();
}
