/* stream_match.c - one SSDA search with the area and/or the window streamed:
   checks, plate shapes for the scan, then the engine over row sources. */
#include "stream_internal.h"

/* Rows of the area's smallest accepted plate (as wide as the area): a
   raster scan revisits a band of window-height rows moving down, the other
   scans jump around the whole area. Any smaller plate would re-read rows
   without bound (issue 22: 3.9 GB read for a 131 KB area), so a job is
   refused below it: every byte is then read at most twice (once more when
   the raster scan starts again from the top after building the bounds). */
static uint32_t area_rows(const ssda_match_config_t *cfg, const ssda_rect_t *a,
                          const ssda_rect_t *w)
{
    return cfg->scan == (uint8_t)SSDA_SCAN_RASTER ? w->height : a->height;
}

/* Shape the plates of the streamed operands for the search: the raster
   scan revisits a band of window-height rows moving down; the other scans
   jump around the whole area. */
static void shape_plates(ssda_source_t *area, const ssda_rect_t *ar, ssda_source_t *window,
                         const ssda_rect_t *wr, const ssda_match_config_t *cfg)
{
    if (area->view == NULL) {
        const bool raster = cfg->scan == (uint8_t)SSDA_SCAN_RASTER;
        (void)ssda__stream_plate_shape(area, ar, ar->width, area_rows(cfg, ar, wr), 1u, 0u);
        /* A raster scan's band of window-height rows moves down one row at
           a time: a plate with spare rows jumps by them (rows needed are
           read once, each slide copies the band's rows in the arena). */
        if (raster) { /* ph >= window height: checked by the caller */
            area->plate.qy = (uint16_t)(area->plate.ph - wr->height + 1u);
        }
    }
    if (window->view == NULL) {
        (void)ssda__stream_plate_shape(window, wr, wr->width, wr->height, 0u, 0u);
    }
}

int ssda_stream_match(ssda_source_t *area, const ssda_rect_t *area_rect,
                      ssda_source_t *window, const ssda_rect_t *window_rect,
                      const ssda_match_config_t *cfg, ssda_match_result_t *result)
{
    ssda_match_plan_t plan;
    ssda_rect_t ar, wr;
    ssda__rows_t a, w;
    int err;

    if (area == NULL || window == NULL || result == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__stream_ready(area) || !ssda__stream_ready(window)) {
        return SSDA_ERR_STATE;
    }
    if (ssda__stream_plates_clash(area, window)) {
        return SSDA_ERR_ARG;
    }
    err = ssda__stream_rect(area, area_rect, &ar);
    if (err == SSDA_OK) {
        err = ssda__stream_rect(window, window_rect, &wr);
    }
    if (err != SSDA_OK) {
        return err;
    }
    if (area->cfg.format != window->cfg.format) {
        return SSDA_ERR_FORMAT;
    }
    if (wr.width > ar.width || wr.height > ar.height) {
        return SSDA_ERR_SIZE;
    }
    if (cfg == NULL) {
        cfg = &ssda__match_defaults;
    }
    err = ssda__match_plan(cfg, ar.width, ar.height, wr.width, wr.height, &plan);
    if (err != SSDA_OK) {
        return err;
    }
    if (!ssda__stream_holds(area, ar.width, area_rows(cfg, &ar, &wr), 0u) ||
        !ssda__stream_holds(window, wr.width, wr.height, 0u)) {
        return SSDA_ERR_BUFFER;
    }
    shape_plates(area, &ar, window, &wr, cfg);
    ssda__stream_rows(&a, area, &ar);
    ssda__stream_rows(&w, window, &wr);
    return ssda__match_rows(&a, &w, &plan, cfg->predict_x, cfg->predict_y, result);
}
