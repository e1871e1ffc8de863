/* track.c - public grid tracking on images in RAM: views as row sources;
   a whole grid, or part of one grid row (for threads). */
#include <string.h>

#include "track_rows.h"

/* The views' checks of both entries (out NULL counts as an argument
   error too), then the views as row sources. */
static int rows_of_views(const ssda_view_t *first, const ssda_view_t *second,
                         const ssda_track_vector_t *out, ssda__rows_t *a, ssda__rows_t *b)
{
    int err;
    if (first == NULL || second == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(first);
    if (err == SSDA_OK) {
        err = ssda_view_check(second);
    }
    if (err == SSDA_OK) {
        ssda__rows_view(a, first);
        ssda__rows_view(b, second);
    }
    return err;
}

int ssda_track(const ssda_view_t *first, const ssda_view_t *second,
               const ssda_track_config_t *cfg, ssda_track_vector_t *out,
               size_t out_count, ssda_track_stats_t *stats)
{
    ssda__rows_t a, b;
    int err = rows_of_views(first, second, out, &a, &b);
    if (err != SSDA_OK) {
        return err;
    }
    /* checked views: no second check of the row sources. RAM sources never
       fail a fetch: an error here is an argument error, found before
       anything is written. */
    return ssda__track_run(&a, &b, cfg, out, out_count, stats);
}

int ssda_track_row(const ssda_view_t *first, const ssda_view_t *second,
                   const ssda_track_config_t *cfg, uint32_t row, uint32_t col0, uint32_t col1,
                   ssda_track_vector_t *out, size_t out_count, ssda_track_stats_t *stats)
{
    ssda__rows_t a, b;
    ssda_track_plan_t plan;
    ssda_track_stats_t unused;
    int err = rows_of_views(first, second, out, &a, &b);
    if (err == SSDA_OK) {
        err = ssda__track_prepare(&a, &b, cfg, out_count, &plan);
    }
    if (err != SSDA_OK) {
        return err;
    }
    if (row >= plan.grid.rows || col0 >= col1 || col1 > plan.grid.cols) {
        return SSDA_ERR_ARG;
    }
    if (stats == NULL) {
        (void)memset(&unused, 0, sizeof unused);
        stats = &unused;
    }
    /* views in RAM never fail a fetch: nothing below returns an error */
    return ssda__track_span(&a, &b, &plan, row, col0, col1, out, stats);
}
