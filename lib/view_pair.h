/* view_pair.h - the checks every two-view job shares (the search, the
   correlation search, composite templates). */
#ifndef SSDA_VIEW_PAIR_H
#define SSDA_VIEW_PAIR_H

#include "ssda/view.h"

/* Both views valid (ssda_view_check, a's error first), of one format, and a
   format this build has (SSDA_CFG_NO_U16). Sizes are the caller's to check.
   Returns SSDA_OK, or SSDA_ERR_NULL / _FORMAT / _SIZE / _STRIDE of a view,
   SSDA_ERR_FORMAT for two formats, SSDA_ERR_UNSUPPORTED for 16-bit views
   in a build without them. Inline: each caller's own check keeps the
   code of one function (a call more cost the M0+ search core 24 B). */
static inline int ssda__view_check_pair(const ssda_view_t *a, const ssda_view_t *b)
{
    int err = ssda_view_check(a);
    if (err == SSDA_OK) {
        err = ssda_view_check(b);
    }
    if (err != SSDA_OK) {
        return err;
    }
    if (a->format != b->format) {
        return SSDA_ERR_FORMAT;
    }
#ifdef SSDA_CFG_NO_U16
    if (a->format != (uint8_t)SSDA_PIX_U8) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif
    return SSDA_OK;
}

#endif
