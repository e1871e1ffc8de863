/*
 * match_rows.h - internal: the search engine over abstract row sources, so
 * the same code serves images in RAM (ssda_match) and block-streamed images
 * (stream layer): kernels always run on contiguous row spans, never a
 * callback per pixel.
 */
#ifndef SSDA_MATCH_ROWS_H
#define SSDA_MATCH_ROWS_H

#include "ssda/match.h"
#include "compiler.h"

/*
 * Fetch pixels x .. x+n-1 of row y (all inside the image) as a contiguous
 * span: on success store its address in *px and return SSDA_OK. The span
 * stays valid until the next fetch on the same source. Any negative return
 * is an error and is passed back unchanged by the engine.
 */
typedef int (*ssda__row_fetch_fn)(void *ctx, uint32_t x, uint32_t y, uint32_t n,
                                 const uint8_t **px);

typedef struct {
    const uint8_t *base;     /* in RAM: pixel (0, 0); NULL means use fetch */
    uint32_t stride;         /* in RAM: bytes between rows */
    ssda__row_fetch_fn fetch; /* when base == NULL */
    void *ctx;               /* passed to fetch */
    uint16_t width;          /* pixels */
    uint16_t height;         /* rows */
    uint8_t format;          /* ssda_pixfmt_t */
} ssda__rows_t;

/* A row source over a valid in-memory view. */
SSDA_INTERNAL void ssda__rows_from_view(ssda__rows_t *rows, const ssda_view_t *view);

/* Pixels x .. x+n-1 of row y of src: direct for RAM, else through fetch. */
static inline int ssda__rows_get(const ssda__rows_t *src, uint32_t x, uint32_t y,
                                uint32_t n, const uint8_t **px)
{
    if (src->base != NULL) {
        *px = src->base + (size_t)y * src->stride + (size_t)x * src->format;
        return SSDA_OK;
    }
    return src->fetch(src->ctx, x, y, n, px);
}

/* Check a configuration against area/window geometry: SSDA_OK or the error
   ssda_match documents for it (no pointers other than cfg are touched). */
SSDA_INTERNAL int ssda__match_check_config(const ssda_match_config_t *cfg, uint32_t area_w,
                            uint32_t area_h, uint32_t win_w, uint32_t win_h);

/*
 * ssda_match over row sources (geometry and formats already validated by the
 * caller; cfg already checked by ssda__match_check_config, never NULL).
 * Returns SSDA_OK, a fetch error unchanged, or SSDA_ERR_UNSUPPORTED for
 * 16-bit rows in a build with SSDA_CFG_NO_U16; *result written on success only.
 */
SSDA_INTERNAL int ssda__match_rows(const ssda__rows_t *area, const ssda__rows_t *window,
                    const ssda_match_config_t *cfg, ssda_match_result_t *result);

#endif /* SSDA_MATCH_ROWS_H */
