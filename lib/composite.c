/* composite.c - composite template matching (seed 003, section 3; ssda/composite.h). */
#include <string.h>

#include "ssda/composite.h"
#include "ncc_internal.h"
#include "fixmath.h"
#include "view_pair.h"
#include "track_rows.h"

/* The resolved job. */
typedef struct {
    const ssda_view_t *ref;
    const ssda_view_t *next;
    const ssda_composite_config_t *cfg;
    uint32_t tp, step, cols, rows;
    uint32_t roi_x, roi_y;
    uint32_t radius_q8, min_radius;
    uint32_t nx, ny;  /* positions of a template in NEXT */
    uint64_t min_var; /* templates with var below this are FLAT (>= 1) */
    bool mask;        /* SSDA_COMPOSITE_MASK */
} job_t;

/* Defaults and the region; SSDA_ERR_SIZE when it holds no template. */
static int resolve_geometry(job_t *j)
{
    const ssda_composite_config_t *cfg = j->cfg;
    uint32_t roi_w, roi_h;
    j->tp = cfg->tp != 0u ? cfg->tp : SSDA_COMPOSITE_DEFAULT_TP;
    j->step = cfg->step != 0u ? cfg->step : SSDA_COMPOSITE_DEFAULT_STEP;
    j->radius_q8 = cfg->radius_q8 != 0u ? cfg->radius_q8 : SSDA_COMPOSITE_DEFAULT_RADIUS_Q8;
    j->min_radius = cfg->min_radius != 0u ? cfg->min_radius : SSDA_COMPOSITE_DEFAULT_MIN_RADIUS;
    j->roi_x = cfg->roi_x;
    j->roi_y = cfg->roi_y;
    if (j->roi_x >= j->ref->width || j->roi_y >= j->ref->height) {
        return SSDA_ERR_SIZE;
    }
    roi_w = cfg->roi_w != 0u ? cfg->roi_w : j->ref->width - j->roi_x;
    roi_h = cfg->roi_h != 0u ? cfg->roi_h : j->ref->height - j->roi_y;
    if (j->roi_x + roi_w > j->ref->width || j->roi_y + roi_h > j->ref->height ||
        roi_w < j->tp || roi_h < j->tp || j->next->width < j->tp || j->next->height < j->tp) {
        return SSDA_ERR_SIZE;
    }
    j->cols = SSDA_DIV32(roi_w - j->tp, j->step) + 1u; /* setup only */
    j->rows = SSDA_DIV32(roi_h - j->tp, j->step) + 1u;
    j->nx = (uint32_t)j->next->width - j->tp + 1u;
    j->ny = (uint32_t)j->next->height - j->tp + 1u;
    return SSDA_OK;
}

static int resolve(job_t *j, const ssda_view_t *ref, const ssda_view_t *next,
                   const ssda_composite_config_t *cfg, size_t out_count)
{
    uint64_t s;
    int err = ssda__view_check_pair(ref, next);
    if (err != SSDA_OK) {
        return err;
    }
    if (cfg->tp > 256u || cfg->metric > (uint8_t)SSDA_NCC_ABS ||
        (cfg->flags & (uint8_t)~(SSDA_COMPOSITE_SUBPIXEL | SSDA_COMPOSITE_MASK)) != 0u ||
        ((cfg->flags & SSDA_COMPOSITE_MASK) != 0u && ref->format == (uint8_t)SSDA_PIX_U8 &&
         cfg->mask_value > 255u)) {
        return SSDA_ERR_ARG;
    }
    j->mask = (cfg->flags & SSDA_COMPOSITE_MASK) != 0u;
    j->ref = ref;
    j->next = next;
    j->cfg = cfg;
    err = resolve_geometry(j);
    if (err != SSDA_OK) {
        return err;
    }
    if ((uint64_t)out_count < (uint64_t)j->cols * j->rows ||
        (uint64_t)cfg->work_size < ssda__ncc_work_need(next->width, j->tp, j->tp) ||
        (((uintptr_t)cfg->work) & 7u) != 0u) {
        return SSDA_ERR_BUFFER;
    }
    /* std >= min_std  <=>  var >= (min_std_q8 n)^2 / 2^16 (n = T^2 <= 2^16):
       the square < 2^64; at least 1, so flat templates are always FLAT */
    s = (uint64_t)cfg->min_std_q8 * j->tp * j->tp;
    j->min_var = (s * s + 65535u) >> 16;
    j->min_var = j->min_var != 0u ? j->min_var : 1u;
    return SSDA_OK;
}

/* Template k's view in REF. */
static void template_view(const job_t *j, uint32_t k, ssda_view_t *v, uint32_t *x, uint32_t *y)
{
    const uint32_t row = SSDA_DIV32(k, j->cols);
    *x = j->roi_x + (k - row * j->cols) * j->step;
    *y = j->roi_y + row * j->step;
    (void)ssda_view_roi(v, j->ref, (uint16_t)*x, (uint16_t)*y, (uint16_t)j->tp, (uint16_t)j->tp);
}

/* Sub-pixel offset, Q8 in [-128, 128], of the peak of a parabola through
   r_m, r_0, r_p (Q2.30) at -1, 0, +1: 0 where a neighbour is missing or
   the three do not make a peak. r_0 is the best of the search, but a
   neighbour outside the disk (inside its bounding box) may be larger: the
   vertex may then lie far beyond +-1/2 px, so the offset is clamped before
   the division (a quotient of 2^32 or more would differ between the
   divide of the compiler, modulo 2^32, and ssda__div64_32, saturated). */
static int32_t parabola_q8(int32_t rm, int32_t r0, int32_t rp, bool neg)
{
    int64_t a, b, num, den, q;
    if (rm == SSDA_NCC_NONE || rp == SSDA_NCC_NONE) {
        return 0;
    }
    /* Q28 (|.| <= 2^28): a peak of |rho| at a negative rho is a trough */
    a = (int64_t)(neg ? -rm : rm) / 4 - (int64_t)(neg ? -r0 : r0) / 4;
    b = (int64_t)(neg ? -rp : rp) / 4 - (int64_t)(neg ? -r0 : r0) / 4;
    /* offset = (r_m - r_p) / (2 (r_m - 2 r_0 + r_p)) = (a - b) / (2 (a + b)) */
    den = -2 * (a + b); /* > 0 at a peak, <= 2^31 */
    if (den <= 0) {
        return 0;
    }
    num = (b - a) * 256; /* |.| < 2^39 */
    if (num >= 128 * den || -num >= 128 * den) {
        return num >= 0 ? 128 : -128;
    }
    q = num >= 0 ? (int64_t)SSDA_DIV64_32((uint64_t)num, (uint32_t)den)
                 : -(int64_t)SSDA_DIV64_32((uint64_t)-num, (uint32_t)den);
    return (int32_t)q; /* |q| < 128 */
}

/* Search template t (view tv) in NEXT: the whole of it for the origin
   (radius < 0), else the disk around (px, py) of that radius; place gets
   the integer top-left found in NEXT. With the mask, a disk whose area
   holds the mask value is not searched: false (t untouched). */
static bool search(const job_t *j, const ssda_view_t *tv, int64_t px, int64_t py,
                   int64_t radius, ssda_composite_tp_t *t, uint64_t *ops, int64_t *place)
{
    ssda_ncc_config_t c;
    ssda_ncc_result_t res;
    ssda_view_t area = *j->next;
    uint32_t ax = 0u, ay = 0u;
    (void)memset(&c, 0, sizeof c);
    c.metric = j->cfg->metric;
    c.work = j->cfg->work;
    c.work_size = j->cfg->work_size;
    if ((j->cfg->flags & SSDA_COMPOSITE_SUBPIXEL) != 0u) {
        c.flags |= SSDA_NCC_AROUND;
    }
    if (radius >= 0) {
        /* the disk's bounding box in positions, clipped to NEXT */
        const int64_t r = radius;
        const int64_t x0 = px - r < 0 ? 0 : px - r, y0 = py - r < 0 ? 0 : py - r;
        const int64_t x1 = px + r >= (int64_t)j->nx ? (int64_t)j->nx - 1 : px + r;
        const int64_t y1 = py + r >= (int64_t)j->ny ? (int64_t)j->ny - 1 : py + r;
        const int64_t w = x1 - x0 + (int64_t)j->tp; /* <= NEXT's width */
        const int64_t h = y1 - y0 + (int64_t)j->tp;
        ax = (uint32_t)x0;
        ay = (uint32_t)y0;
        (void)ssda_view_roi(&area, j->next, (uint16_t)ax, (uint16_t)ay, (uint16_t)w, (uint16_t)h);
        c.flags |= SSDA_NCC_DISK;
        c.radius = (uint16_t)(r > 65535 ? 65535 : r);
        c.predict_x = (int32_t)(px - x0);
        c.predict_y = (int32_t)(py - y0);
        if (j->mask && ssda__view_holds(&area, j->cfg->mask_value)) {
            return false;
        }
    }
    ssda__ncc_search(&area, tv, &c, &res);
    *ops += res.pixel_ops;
    t->rho_q30 = res.rho_q30;
    place[0] = (int64_t)ax + res.x;
    place[1] = (int64_t)ay + res.y;
    t->dx = (int32_t)((place[0] - t->x) * 256);
    t->dy = (int32_t)((place[1] - t->y) * 256);
    if ((c.flags & SSDA_NCC_AROUND) != 0u) {
        t->dx += parabola_q8(res.around_q30[3], res.around_q30[4], res.around_q30[5],
                             res.rho_q30 < 0);
        t->dy += parabola_q8(res.around_q30[1], res.around_q30[4], res.around_q30[7],
                             res.rho_q30 < 0);
    }
    return true;
}

/* The origin: the OK template of largest variance (ties to the smallest
   k), or UINT32_MAX if none. */
static uint32_t pick_origin(const job_t *j, const ssda_composite_tp_t *out)
{
    uint32_t k, origin = UINT32_MAX;
    uint64_t best = 0u;
    for (k = 0u; k < j->cols * j->rows; k++) {
        if (out[k].status == (uint8_t)SSDA_COMPOSITE_OK && out[k].var > best) {
            best = out[k].var;
            origin = k;
        }
    }
    return origin;
}

/* Pass 1: every template's place, variance and status (MASKED before FLAT,
   as in the grid tracking). */
static void measure(const job_t *j, ssda_composite_tp_t *out, uint64_t *ops)
{
    uint32_t k;
    for (k = 0u; k < j->cols * j->rows; k++) {
        ssda_composite_tp_t *t = &out[k];
        ssda__ncc_win_t w;
        ssda_view_t tv;
        uint32_t x, y;
        template_view(j, k, &tv, &x, &y);
        ssda__ncc_window(&tv, &w, ops);
        (void)memset(t, 0, sizeof *t);
        t->x = (uint16_t)x;
        t->y = (uint16_t)y;
        t->var = w.var_w;
        t->status = (uint8_t)(w.var_w >= j->min_var ? SSDA_COMPOSITE_OK : SSDA_COMPOSITE_FLAT);
        if (j->mask && ssda__view_holds(&tv, j->cfg->mask_value)) {
            t->status = (uint8_t)SSDA_COMPOSITE_MASKED;
        }
    }
}

/* The origin's search over the whole of NEXT (p0: its place there). With
   the mask, an origin whose match holds the mask value is MASKED and the
   next in rank is tried. The origin's index, or UINT32_MAX if none is left. */
static uint32_t search_origin(const job_t *j, ssda_composite_tp_t *out, uint64_t *ops,
                              int64_t *p0)
{
    uint32_t k;
    for (k = pick_origin(j, out); k != UINT32_MAX; k = pick_origin(j, out)) {
        ssda_composite_tp_t *o = &out[k];
        ssda_view_t tv, at;
        uint32_t x, y;
        template_view(j, k, &tv, &x, &y);
        (void)search(j, &tv, 0, 0, -1, o, ops, p0);
        (void)ssda_view_roi(&at, j->next, (uint16_t)p0[0], (uint16_t)p0[1], (uint16_t)j->tp,
                            (uint16_t)j->tp);
        if (!j->mask || !ssda__view_holds(&at, j->cfg->mask_value)) {
            o->origin = 1u;
            return k;
        }
        o->status = (uint8_t)SSDA_COMPOSITE_MASKED;
        o->dx = 0;
        o->dy = 0;
        o->rho_q30 = 0;
    }
    return UINT32_MAX;
}

/* ceil(radius_q8 |v| / 256), at least min_radius: |v| rounded up first. */
static int64_t disk_radius(const job_t *j, int64_t vx, int64_t vy)
{
    const uint64_t ux = (uint64_t)(vx < 0 ? -vx : vx); /* < 2^16 */
    const uint64_t uy = (uint64_t)(vy < 0 ? -vy : vy);
    const uint64_t v2 = ux * ux + uy * uy; /* < 2^33 */
    uint64_t len = ssda__isqrt64(v2);
    uint64_t r;
    if (len * len < v2) {
        len++;
    }
    r = ((uint64_t)j->radius_q8 * len + 255u) >> 8; /* < 2^16 * 2^17 */
    return (int64_t)(r > j->min_radius ? r : j->min_radius);
}

int ssda_composite_match(const ssda_view_t *ref, const ssda_view_t *next,
                         const ssda_composite_config_t *cfg, ssda_composite_tp_t *out,
                         size_t out_count, ssda_composite_result_t *result)
{
    job_t j;
    ssda_composite_result_t res;
    int64_t p0[2] = {0, 0};
    int err;
    if (ref == NULL || next == NULL || cfg == NULL || out == NULL || result == NULL ||
        cfg->work == NULL) {
        return SSDA_ERR_NULL;
    }
    err = resolve(&j, ref, next, cfg, out_count);
    if (err != SSDA_OK) {
        return err;
    }
    (void)memset(&res, 0, sizeof res);
    res.cols = (uint16_t)j.cols;
    res.rows = (uint16_t)j.rows;
    res.count = j.cols * j.rows;
    measure(&j, out, &res.pixel_ops);
    res.origin = search_origin(&j, out, &res.pixel_ops, p0);
    if (res.origin != UINT32_MAX) {
        ssda_composite_tp_t *o = &out[res.origin];
        int64_t place[2], sum = 0; /* sum of rho: |.| < 2^30 * 2^32 */
        uint32_t k;
        ssda_view_t tv;
        uint32_t x, y;
        for (k = 0u; k < res.count; k++) {
            ssda_composite_tp_t *t = &out[k];
            int64_t vx, vy, px, py;
            if (k == res.origin || t->status != (uint8_t)SSDA_COMPOSITE_OK) {
                continue;
            }
            vx = (int64_t)t->x - o->x;
            vy = (int64_t)t->y - o->y;
            px = p0[0] + vx;
            py = p0[1] + vy;
            if (px < 0 || py < 0 || px >= (int64_t)j.nx || py >= (int64_t)j.ny) {
                t->status = (uint8_t)SSDA_COMPOSITE_EDGE;
                continue;
            }
            template_view(&j, k, &tv, &x, &y);
            if (!search(&j, &tv, px, py, disk_radius(&j, vx, vy), t, &res.pixel_ops, place)) {
                t->status = (uint8_t)SSDA_COMPOSITE_MASKED;
            }
        }
        for (k = 0u; k < res.count; k++) {
            if (out[k].status == (uint8_t)SSDA_COMPOSITE_OK) {
                sum += out[k].rho_q30;
                res.ok++;
            }
        }
        res.mean_rho_q30 = (int32_t)(sum >= 0 ? (int64_t)SSDA_DIV64_32((uint64_t)sum, res.ok)
                                             : -(int64_t)SSDA_DIV64_32((uint64_t)-sum, res.ok));
    }
    *result = res;
    return SSDA_OK;
}
