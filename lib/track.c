/* track.c - public grid tracking on images in RAM: views as row sources. */
#include "track_rows.h"

int ssda_track(const ssda_view_t *first, const ssda_view_t *second,
               const ssda_track_config_t *cfg, ssda_track_vector_t *out,
               size_t out_count, ssda_track_stats_t *stats)
{
    ssda__rows_t a, b;
    int err;
    if (first == NULL || second == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(first);
    if (err == SSDA_OK) {
        err = ssda_view_check(second);
    }
    if (err != SSDA_OK) {
        return err;
    }
    ssda__rows_view(&a, first);
    ssda__rows_view(&b, second);
    /* checked views: no second check of the row sources. RAM sources never
       fail a fetch: an error here is an argument error, found before
       anything is written. */
    return ssda__track_run(&a, &b, cfg, out, out_count, stats);
}
