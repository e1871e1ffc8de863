/*
 * test_push.h - the push-mode init functions called with their arguments
 * in a row, as the tests were first written: each builds the
 * ssda_push_config_t of stream.h from them and calls the library, so every
 * case (errors included) goes through the public API as a user's code
 * does. Values out of an enum's range (a format of 3, a role of 2) are
 * passed through unchanged, to test their refusal.
 */
#ifndef TEST_PUSH_H
#define TEST_PUSH_H

#include "ssda/stream.h"

static inline ssda_push_config_t test_push_config(uint16_t width, uint16_t height, uint8_t format,
                                                  uint8_t role, ssda_source_t *other,
                                                  const ssda_rect_t *area_rect,
                                                  const ssda_rect_t *window_rect, void *ring,
                                                  size_t ring_size)
{
    ssda_push_config_t c;
    c.width = width;
    c.height = height;
    c.format = (ssda_pixfmt_t)format;
    c.role = (ssda_push_role_t)role;
    c.other = other;
    c.area_rect = area_rect;
    c.window_rect = window_rect;
    c.ring = ring;
    c.ring_size = ring_size;
    return c;
}

static inline int test_push_init_match(ssda_push_t *push, uint16_t width, uint16_t height,
                                       uint8_t format, const ssda_rect_t *area_rect,
                                       ssda_source_t *window, const ssda_rect_t *window_rect,
                                       const ssda_match_config_t *cfg,
                                       ssda_match_result_t *result, void *ring,
                                       size_t ring_size)
{
    ssda_push_config_t c = test_push_config(width, height, format, SSDA_PUSH_FIRST, window,
                                            area_rect, window_rect, ring, ring_size);
    return ssda_push_init_match(push, &c, cfg, result);
}

static inline int test_push_init_track(ssda_push_t *push, uint16_t width, uint16_t height,
                                       uint8_t format, uint8_t role, ssda_source_t *other,
                                       const ssda_track_config_t *cfg, ssda_track_vector_t *out,
                                       size_t out_count, ssda_track_stats_t *stats, void *ring,
                                       size_t ring_size)
{
    ssda_push_config_t c = test_push_config(width, height, format, role, other, NULL, NULL,
                                            ring, ring_size);
    return ssda_push_init_track(push, &c, cfg, out, out_count, stats);
}

#endif /* TEST_PUSH_H */
