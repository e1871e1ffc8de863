/* match.c - public search API: validation, the plan of a search, and row
   sources (views, memory, devices, sub-rectangles). */
#include "match_rows.h"
#include "kernel/kernels.h"
#include "fixmath.h"
#include "view_pair.h"

void ssda__rows_mem(ssda__rows_t *rows, const void *base, uint32_t stride, uint32_t w,
                    uint32_t h, uint8_t format)
{
    rows->base = (const uint8_t *)base;
    rows->stride = stride;
    rows->fetch = NULL;
    rows->ctx = NULL;
    rows->x0 = 0u;
    rows->y0 = 0u;
    rows->width = (uint16_t)w;
    rows->height = (uint16_t)h;
    rows->format = format;
}

void ssda__rows_view(ssda__rows_t *rows, const ssda_view_t *view)
{
    /* ssda__rows_mem of the view's fields, written out: a search on views
       links this one constructor only */
    rows->base = (const uint8_t *)view->data;
    rows->stride = view->stride;
    rows->fetch = NULL;
    rows->ctx = NULL;
    rows->x0 = 0u;
    rows->y0 = 0u;
    rows->width = view->width;
    rows->height = view->height;
    rows->format = view->format;
}

void ssda__rows_dev(ssda__rows_t *rows, ssda__row_fetch_fn fetch, void *ctx, uint32_t w,
                    uint32_t h, uint8_t format)
{
    rows->base = NULL;
    rows->stride = 0u;
    rows->fetch = fetch;
    rows->ctx = ctx;
    rows->x0 = 0u;
    rows->y0 = 0u;
    rows->width = (uint16_t)w;
    rows->height = (uint16_t)h;
    rows->format = format;
}

void ssda__rows_sub(ssda__rows_t *sub, const ssda__rows_t *parent, uint32_t x, uint32_t y,
                    uint32_t w, uint32_t h)
{
    *sub = *parent;
    if (parent->base != NULL) {
        sub->base = parent->base + (size_t)y * parent->stride + (size_t)x * parent->format;
    } else {
        sub->x0 = (uint16_t)(parent->x0 + x); /* inside the device image: < 2^16 */
        sub->y0 = (uint16_t)(parent->y0 + y);
    }
    sub->width = (uint16_t)w;
    sub->height = (uint16_t)h;
}

/* Bytes of the bounds tables (SSDA_MATCH_WORK_SIZE in 64 bits: in a 32-bit
   size_t the macro wraps for areas near 65535 x 65535, over 4 GB of work,
   e.g. 32783 x 32768 with a 16 x 16 window gives 128 bytes, and a wrapped
   size would let the tables run past the buffer). (area_w - win_w + 1) *
   area_h < 2^32; the total < 2^35. */
static uint64_t bounds_bytes(uint32_t area_w, uint32_t area_h, uint32_t win_w, uint32_t win_h)
{
    return ((((uint64_t)area_w - win_w + 1u) * area_h) + 2u * (uint64_t)win_h) *
           sizeof(uint32_t);
}

#ifndef SSDA_CFG_NO_BOUNDS
/* Bytes for SSDA_MATCH_BLOCKS (SSDA_MATCH_WORK_SIZE_BLOCKS in 64 bits):
   the bounds tables rounded to 8, the list, the integral image and the
   window's block sums; < 2^36. */
static uint64_t blocks_bytes(uint32_t area_w, uint32_t area_h, uint32_t win_w, uint32_t win_h)
{
    return ((bounds_bytes(area_w, area_h, win_w, win_h) + 7u) & ~(uint64_t)7u) +
           SSDA_MATCH_UNIQUE_WORK +
           (((uint64_t)area_w + 1u) * ((uint64_t)area_h + 1u) + SSDA_MATCH_BLOCK_SUMS) *
               sizeof(uint32_t);
}
#endif

/* The quality options (match.h: SSDA_MATCH_UNIQUE, SSDA_MATCH_SUBPIXEL):
   exact modes only, the ratio and radius in range, the list's room after
   the bounds tables. SSDA_OK or the error ssda_match documents. */
static int check_quality(const ssda_match_config_t *cfg, uint32_t area_w, uint32_t area_h,
                         uint32_t win_w, uint32_t win_h)
{
    const bool unique = (cfg->flags & SSDA_MATCH_UNIQUE) != 0u;
    uint64_t need = SSDA_MATCH_UNIQUE_WORK;
    if ((cfg->flags & (SSDA_MATCH_UNIQUE | SSDA_MATCH_SUBPIXEL)) == 0u) {
        return SSDA_OK;
    }
    if (cfg->scan == (uint8_t)SSDA_SCAN_COARSE ||
        (cfg->threshold != (uint8_t)SSDA_THRESHOLD_AUTO &&
         cfg->threshold != (uint8_t)SSDA_THRESHOLD_NONE) ||
        (unique && ((cfg->unique_q8 != 0u && (cfg->unique_q8 <= 256u || cfg->unique_q8 > 1024u)) ||
                    cfg->unique_radius > SSDA_MATCH_MAX_UNIQUE_RADIUS))) {
        return SSDA_ERR_ARG;
    }
#ifdef SSDA_CFG_NO_SUBPIXEL
    if ((cfg->flags & SSDA_MATCH_SUBPIXEL) != 0u) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
    if (!unique) {
        return SSDA_OK;
    }
#ifdef SSDA_CFG_NO_UNIQUE
    (void)need;
    (void)area_w;
    (void)area_h;
    (void)win_w;
    (void)win_h;
    return SSDA_ERR_UNSUPPORTED;
#else
    if (cfg->work == NULL) {
        return SSDA_ERR_NULL;
    }
    if ((cfg->flags & SSDA_MATCH_BOUNDS) != 0u) {
        need += (bounds_bytes(area_w, area_h, win_w, win_h) + 7u) & ~(uint64_t)7u;
    }
    if ((uint64_t)cfg->work_size < need || (((uintptr_t)cfg->work) & 7u) != 0u) {
        return SSDA_ERR_BUFFER;
    }
    return SSDA_OK;
#endif
}

/* The options against the geometry: SSDA_OK or the error ssda_match
   documents for them. */
static int check_config(const ssda_match_config_t *cfg, uint32_t area_w, uint32_t area_h,
                        uint32_t win_w, uint32_t win_h)
{
    if (cfg->threshold > (uint8_t)SSDA_THRESHOLD_AUTO_RAMP ||
        cfg->scan > (uint8_t)SSDA_SCAN_COARSE || cfg->order > (uint8_t)SSDA_ORDER_SPREAD ||
        (cfg->flags & (uint8_t)~(SSDA_MATCH_BOUNDS | SSDA_MATCH_TIE_NEAREST |
                                 SSDA_MATCH_UNIQUE | SSDA_MATCH_SUBPIXEL |
                                 SSDA_MATCH_BLOCKS)) != 0u ||
        (cfg->flags & (SSDA_MATCH_BOUNDS | SSDA_MATCH_BLOCKS)) == SSDA_MATCH_BLOCKS) {
        return SSDA_ERR_ARG;
    }
    if (cfg->threshold == (uint8_t)SSDA_THRESHOLD_RAMP && cfg->lambda_q8 == 0u) {
        return SSDA_ERR_ARG;
    }
    /* Features left out of this build (include/ssda/config.h). */
#ifdef SSDA_CFG_NO_RAMP
    if (cfg->threshold == (uint8_t)SSDA_THRESHOLD_RAMP ||
        cfg->threshold == (uint8_t)SSDA_THRESHOLD_AUTO_RAMP) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
#ifdef SSDA_CFG_NO_FIXED
    if (cfg->threshold == (uint8_t)SSDA_THRESHOLD_FIXED) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
#ifdef SSDA_CFG_NO_PREDICT
    if (cfg->scan == (uint8_t)SSDA_SCAN_PREDICT) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
#ifdef SSDA_CFG_NO_COARSE
    if (cfg->scan == (uint8_t)SSDA_SCAN_COARSE) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
#ifdef SSDA_CFG_NO_SPREAD
    if (cfg->order == (uint8_t)SSDA_ORDER_SPREAD) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
#ifdef SSDA_CFG_NO_BOUNDS
    (void)area_w; /* the geometry only sizes the bounds' work buffer */
    (void)area_h;
    (void)win_w;
    (void)win_h;
    if ((cfg->flags & SSDA_MATCH_BOUNDS) != 0u) {
        return SSDA_ERR_UNSUPPORTED;
    }
#else
    if ((cfg->flags & SSDA_MATCH_BOUNDS) != 0u) {
        if (cfg->work == NULL) {
            return SSDA_ERR_NULL;
        }
        if ((uint64_t)cfg->work_size < bounds_bytes(area_w, area_h, win_w, win_h) ||
            (((uintptr_t)cfg->work) & (sizeof(uint32_t) - 1u)) != 0u) {
            return SSDA_ERR_BUFFER;
        }
        if ((cfg->flags & SSDA_MATCH_BLOCKS) != 0u &&
            (uint64_t)cfg->work_size < blocks_bytes(area_w, area_h, win_w, win_h)) {
            return SSDA_ERR_BUFFER;
        }
    }
#endif
    return check_quality(cfg, area_w, area_h, win_w, win_h);
}

const ssda_match_config_t ssda__match_defaults; /* all zero */

#ifndef SSDA_CFG_NO_SPREAD
static uint32_t gcd_u32(uint32_t a, uint32_t b)
{
    while (b != 0u) {
        uint32_t t = SSDA_MOD32(a, b); /* setup only: no runtime division on the M0+ */
        a = b;
        b = t;
    }
    return a;
}

/* The spread order's step for M rows: the largest s <= 0.618 M coprime to
   M (golden-ratio stride), at least 1. */
static uint32_t spread_step(uint32_t m)
{
    uint32_t s = (m * 158u) / 256u; /* ~0.618 M; m <= 65535 */
    if (s == 0u) {
        s = 1u;
    }
    while (s > 1u && gcd_u32(s, m) != 1u) {
        s--;
    }
    return s;
}
#endif

int ssda__match_plan(const ssda_match_config_t *cfg, uint32_t area_w, uint32_t area_h,
                     uint32_t win_w, uint32_t win_h, ssda_match_plan_t *plan)
{
    const uint8_t mode = cfg->threshold;
    int err = check_config(cfg, area_w, area_h, win_w, win_h);
    if (err != SSDA_OK) {
        return err;
    }
    plan->threshold = mode;
    plan->scan = cfg->scan;
    plan->work = cfg->work;
    plan->lambda_q8 = cfg->lambda_q8;
    plan->k_q8 = cfg->k_q8 != 0u ? cfg->k_q8 : (uint16_t)SSDA_DEFAULT_K_Q8;
    plan->coarse_step = cfg->coarse_step != 0u ? cfg->coarse_step
                                               : (uint16_t)SSDA_DEFAULT_COARSE_STEP;
    plan->row_step = 1u;
#ifndef SSDA_CFG_NO_SPREAD
    if (cfg->order == (uint8_t)SSDA_ORDER_SPREAD) {
        plan->row_step = spread_step(win_h);
    }
#endif
    plan->flags = cfg->flags;
    plan->fixed_cut = UINT64_MAX;
    if (mode == (uint8_t)SSDA_THRESHOLD_FIXED && cfg->fixed_threshold < UINT64_MAX - 1u) {
        plan->fixed_cut = cfg->fixed_threshold + 1u;
    }
    plan->unique_radius = 0u;
    plan->unique_q8 = 0u;
    plan->list = NULL;
    if ((cfg->flags & SSDA_MATCH_UNIQUE) != 0u) {
        /* the list after the bounds tables, 8-byte aligned (its SADs) */
        size_t off = 0u;
        if ((cfg->flags & SSDA_MATCH_BOUNDS) != 0u) {
            off = (size_t)((bounds_bytes(area_w, area_h, win_w, win_h) + 7u) & ~(uint64_t)7u);
        }
        plan->unique_radius = cfg->unique_radius != 0u ? cfg->unique_radius
                                                       : (uint8_t)SSDA_MATCH_DEFAULT_UNIQUE_RADIUS;
        plan->unique_q8 = cfg->unique_q8 != 0u ? cfg->unique_q8
                                               : (uint16_t)SSDA_MATCH_DEFAULT_UNIQUE_Q8;
        plan->list = (uint8_t *)cfg->work + off;
    }
    return SSDA_OK;
}

/* Validate the pair of views: each valid, same format, window fits. */
static int check_pair(const ssda_view_t *area, const ssda_view_t *window)
{
    int err = ssda__view_check_pair(area, window);
    if (err != SSDA_OK) {
        return err;
    }
    if (window->width > area->width || window->height > area->height) {
        return SSDA_ERR_SIZE;
    }
    return SSDA_OK;
}

int ssda_match_search(ssda_match_state_t *state, const ssda_view_t *area,
                      const ssda_view_t *window, const ssda_match_config_t *cfg,
                      ssda_match_result_t *result)
{
    ssda__match_head_t *head;
    int err;
    if (state == NULL || area == NULL || window == NULL || result == NULL) {
        return SSDA_ERR_NULL;
    }
    err = check_pair(area, window);
    if (err != SSDA_OK) {
        return err;
    }
    if (cfg == NULL) {
        cfg = &ssda__match_defaults;
    }
    /* the plan is written only once the options pass: on error the state
       is untouched */
    head = ssda__match_head(state);
    err = ssda__match_plan(cfg, area->width, area->height, window->width, window->height,
                           &head->plan);
    if (err != SSDA_OK) {
        return err;
    }
    ssda__rows_view(&head->area, area);
    ssda__rows_view(&head->win, window);
    /* a tail call: this frame is gone while the search runs */
    return ssda__match_state(state, cfg->predict_x, cfg->predict_y, result);
}

int ssda_match(const ssda_view_t *area, const ssda_view_t *window,
               const ssda_match_config_t *cfg, ssda_match_result_t *result)
{
    ssda_match_state_t state; /* the search's state on this frame */
    return ssda_match_search(&state, area, window, cfg, result);
}

int ssda_sad_at(const ssda_view_t *area, const ssda_view_t *window,
                uint16_t x, uint16_t y, uint64_t *sad)
{
    uint64_t total = 0u; /* <= 65535^3 < 2^48 */
    uint32_t r;
    int err;
    if (area == NULL || window == NULL || sad == NULL) {
        return SSDA_ERR_NULL;
    }
    err = check_pair(area, window);
    if (err != SSDA_OK) {
        return err;
    }
    if ((uint32_t)x + window->width > area->width ||
        (uint32_t)y + window->height > area->height) {
        return SSDA_ERR_SIZE;
    }
    for (r = 0u; r < window->height; r++) {
        const uint8_t *s = ssda_view_row(area, (uint32_t)y + r) + (size_t)x * area->format;
        const uint8_t *t = ssda_view_row(window, r);
#ifndef SSDA_CFG_NO_U16
        if (area->format != (uint8_t)SSDA_PIX_U8) {
            total += ssda__sad_row_u16((const uint16_t *)(const void *)s,
                                      (const uint16_t *)(const void *)t, window->width);
            continue;
        }
#endif
        total += ssda__sad_row_u8(s, t, window->width);
    }
    *sad = total;
    return SSDA_OK;
}
