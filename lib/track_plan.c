/* track_plan.c - grid layout and configuration checks of grid tracking. */
#include "track_rows.h"
#include "track_tab.h"

const ssda_track_config_t ssda__track_defaults; /* all zero */

/* One axis of the grid: window, search, step and region along it. */
typedef struct {
    uint32_t win, search, step, start, len, count;
} axis_t;

static int resolve_axis(axis_t *a, uint16_t win, uint16_t search, uint16_t step,
                        uint16_t start, uint16_t len, uint32_t image)
{
    a->win = win != 0u ? win : SSDA_TRACK_DEFAULT_WIN;
    if (search != 0u) {
        a->search = search;
    } else {
        a->search = 2u * a->win <= SSDA_MAX_DIM ? 2u * a->win : SSDA_MAX_DIM;
    }
    a->step = step != 0u ? step : a->win;
    a->start = start;
    if (image == 0u || a->search < a->win || start >= image) {
        return SSDA_ERR_SIZE;
    }
    a->len = len != 0u ? len : image - start;
    if (start + a->len > image || a->len < a->win) {
        return SSDA_ERR_SIZE;
    }
    a->count = (a->len - a->win) / a->step + 1u; /* <= 65535 */
    return SSDA_OK;
}

static int resolve_grid(const ssda_track_config_t *cfg, uint32_t width, uint32_t height,
                        ssda_track_grid_t *grid)
{
    axis_t a; /* one axis at a time: x, then y (every value <= 65535) */
    uint32_t cols;
    int err = resolve_axis(&a, cfg->win_w, cfg->search_w, cfg->step_x, cfg->roi_x,
                           cfg->roi_w, width);
    if (err != SSDA_OK) {
        return err;
    }
    cols = a.count;
    grid->cols = (uint16_t)a.count;
    grid->win_w = (uint16_t)a.win;
    grid->search_w = (uint16_t)a.search;
    grid->step_x = (uint16_t)a.step;
    grid->roi_x = (uint16_t)a.start;
    grid->roi_w = (uint16_t)a.len;
    err = resolve_axis(&a, cfg->win_h, cfg->search_h, cfg->step_y, cfg->roi_y,
                       cfg->roi_h, height);
    if (err != SSDA_OK) {
        return err;
    }
    grid->rows = (uint16_t)a.count;
    grid->count = cols * a.count; /* <= 65535^2 < 2^32 */
    grid->win_h = (uint16_t)a.win;
    grid->search_h = (uint16_t)a.search;
    grid->step_y = (uint16_t)a.step;
    grid->roi_y = (uint16_t)a.start;
    grid->roi_h = (uint16_t)a.len;
    return SSDA_OK;
}

int ssda_track_grid(const ssda_track_config_t *cfg, uint16_t width, uint16_t height,
                    ssda_track_grid_t *grid)
{
    ssda_track_grid_t g;
    int err;
    if (grid == NULL) {
        return SSDA_ERR_NULL;
    }
    err = resolve_grid(cfg != NULL ? cfg : &ssda__track_defaults, width, height, &g);
    if (err == SSDA_OK) {
        *grid = g;
    }
    return err;
}

/* The quality flags of every window's search: the tie rule toward the
   prediction always; uniqueness when asked (ssda__match_plan refuses it
   outside the exact modes); the sub-pixel fit unless turned off, in the
   exact modes only (the fit needs exact SADs: elsewhere sub = whole). */
static void set_quality(const ssda_track_config_t *cfg, ssda_match_config_t *m)
{
    m->flags |= SSDA_MATCH_TIE_NEAREST;
    if ((cfg->flags & SSDA_TRACK_UNIQUE) != 0u) {
        m->flags |= SSDA_MATCH_UNIQUE;
        m->unique_q8 = cfg->unique_q8;
        m->unique_radius = cfg->unique_radius;
    }
    if ((cfg->flags & SSDA_TRACK_NO_SUBPIXEL) == 0u && m->scan != (uint8_t)SSDA_SCAN_COARSE &&
        (m->threshold == (uint8_t)SSDA_THRESHOLD_AUTO ||
         m->threshold == (uint8_t)SSDA_THRESHOLD_NONE)) {
        m->flags |= SSDA_MATCH_SUBPIXEL;
    }
}

int ssda__track_plan(const ssda_track_config_t *cfg, uint8_t format, uint32_t first_w,
                     uint32_t first_h, uint32_t second_w, uint32_t second_h,
                     ssda_track_plan_t *plan)
{
    const uint32_t maxval = format == (uint8_t)SSDA_PIX_U8 ? 255u : 65535u;
    /* built in *plan directly (no copy of a plan on the stack): on error it
       is scratch, which every caller discards */
    ssda_match_config_t match; /* the search of every window */
    uint32_t pixels; /* win_w * win_h <= 65535^2 < 2^32 */
    int err = resolve_grid(cfg, second_w, second_h, &plan->grid);
    if (err != SSDA_OK) {
        return err;
    }
    if (cfg->predict > (uint8_t)SSDA_TRACK_PREDICT_MEDIAN ||
        (cfg->flags & (uint8_t)~(SSDA_TRACK_EXCLUDE | SSDA_TRACK_MASK | SSDA_TRACK_NO_FLAT |
                                 SSDA_TRACK_UNIQUE | SSDA_TRACK_NO_SUBPIXEL)) != 0u ||
        cfg->flat_q8 > 65535u * 256u || (cfg->match.flags & SSDA_MATCH_BLOCKS) != 0u) {
        return SSDA_ERR_ARG;
    }
    plan->predict = cfg->predict;
    plan->flags = cfg->flags;
    plan->mask_value = cfg->mask_value;
    plan->first_w = (uint16_t)first_w;
    plan->first_h = (uint16_t)first_h;
    if ((plan->flags & SSDA_TRACK_MASK) != 0u && plan->mask_value > maxval) {
        return SSDA_ERR_ARG;
    }
    pixels = (uint32_t)plan->grid.win_w * plan->grid.win_h;
    plan->texture_threshold = cfg->texture_threshold != 0u ? cfg->texture_threshold
                                                       : (maxval + 1u) / 2u;
    plan->texture_min_count = cfg->texture_min_count;
    if (plan->texture_min_count == 0u) {
        /* the default is always valid: w*h / 16, at least 1, at most w*h / 2
           (0 for a 1-pixel window, which has no texture: nothing excluded) */
        plan->texture_min_count = pixels / SSDA_TRACK_DEFAULT_MIN_COUNT_DIV;
        if (plan->texture_min_count == 0u) {
            plan->texture_min_count = pixels / 2u < 1u ? pixels / 2u : 1u;
        }
    } else if (plan->texture_min_count > pixels / 2u &&
               (plan->flags & SSDA_TRACK_EXCLUDE) != 0u) {
        return SSDA_ERR_ARG;
    } else {
        /* given and valid (or unused without SSDA_TRACK_EXCLUDE) */
    }
    if ((plan->flags & SSDA_TRACK_EXCLUDE) != 0u && plan->texture_threshold >= maxval) {
        return SSDA_ERR_ARG;
    }
    plan->flat_q8 = 0u;
    if ((plan->flags & SSDA_TRACK_NO_FLAT) == 0u) {
        plan->flat_q8 = cfg->flat_q8 != 0u ? cfg->flat_q8 : SSDA_TRACK_DEFAULT_FLAT_Q8;
    }
    match = cfg->match;
    set_quality(cfg, &match);
    if (plan->predict != (uint8_t)SSDA_TRACK_PREDICT_NONE) {
        if (match.scan == (uint8_t)SSDA_SCAN_COARSE) {
            return SSDA_ERR_ARG;
        }
        if (match.scan == (uint8_t)SSDA_SCAN_RASTER) {
            match.scan = (uint8_t)SSDA_SCAN_PREDICT;
        }
    }
    err = ssda__match_plan(&match, plan->grid.search_w, plan->grid.search_h,
                           plan->grid.win_w, plan->grid.win_h, &plan->match);
    plan->tab_rows = 0u;
#ifndef SSDA_CFG_NO_BOUNDS
    /* shared bound tables (track.h): the engine's groups of 4 rows, and a
       buffer for them */
    if (err == SSDA_OK && (match.flags & SSDA_MATCH_BOUNDS) != 0u &&
        match.threshold != (uint8_t)SSDA_THRESHOLD_NONE && plan->grid.win_h >= 4u &&
        (maxval == 255u || plan->grid.win_w <= 16384u) &&
        (uint64_t)match.work_size >= ssda__track_tab_size(&plan->grid, first_w)) {
        plan->tab_rows = (uint16_t)(plan->grid.search_h - 3u);
        plan->match.flags |= (uint8_t)SSDA__MATCH_TAB; /* the engine reads them */
    }
#endif
    return err;
}
