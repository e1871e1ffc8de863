/*
 * cv_peer.h - OpenCV's cv::matchTemplate behind a C interface, so that the
 * benchmark drivers stay C99 and only this file pair is C++.
 *
 * matchTemplate accepts 8-bit or 32-bit float images only: 8-bit views are
 * wrapped without a copy, 16-bit views are converted to float32 ONCE by
 * cv_peer_image_new (outside every timed region). The search itself is what
 * a desktop user writes: matchTemplate on the area and window rectangles
 * (Mat headers, no copies) into a reused result Mat, then cv::minMaxLoc
 * (minimum for TM_SQDIFF, maximum for TM_CCOEFF_NORMED).
 */
#ifndef SSDA_CV_PEER_H
#define SSDA_CV_PEER_H

#include <stddef.h>
#include <stdint.h>

#include "ssda/view.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    CV_PEER_SQDIFF = 0,       /* cv::TM_SQDIFF: smallest sum of squared differences */
    CV_PEER_CCOEFF_NORMED = 1 /* cv::TM_CCOEFF_NORMED: largest correlation coefficient */
} cv_peer_method_t;

/* An image as OpenCV gets it (opaque). */
typedef struct cv_peer_image cv_peer_image_t;

/* One search: the window (win_w x win_h at wx, wy of the template image)
   searched in the area (area_w x area_h at ax, ay of the searched image). */
typedef struct {
    uint16_t wx, wy, ax, ay;
} cv_peer_job_t;

/* Single-threaded OpenCV (cv::setNumThreads(1)); call once first. Writes a
   one-line description (version, threads, IPP, SIMD) into info. */
void cv_peer_init(char *info, size_t infolen);

/* Wrap (8-bit) or convert to float32 (16-bit) a view. NULL when out of memory. */
cv_peer_image_t *cv_peer_image_new(const ssda_view_t *v);
void cv_peer_image_free(cv_peer_image_t *img);

/* Run n searches with one method: window of tmpl at (wx, wy), area of img at
   (ax, ay). best_x/best_y[k] receive the best top-left in the area.
   Returns 0, or -1 on an OpenCV exception (message on stderr). */
int cv_peer_match(const cv_peer_image_t *img, const cv_peer_image_t *tmpl,
                  const cv_peer_job_t *jobs, size_t n, uint16_t win_w, uint16_t win_h,
                  uint16_t area_w, uint16_t area_h, int method, uint16_t *best_x,
                  uint16_t *best_y);

/* For TM_CCOEFF_NORMED, untimed: the best placement of one job, its score,
   and the best score outside the 3 x 3 around it (second). Returns 0 or -1. */
int cv_peer_ccoeff_scores(const cv_peer_image_t *img, const cv_peer_image_t *tmpl,
                          const cv_peer_job_t *job, uint16_t win_w, uint16_t win_h,
                          uint16_t area_w, uint16_t area_h, uint16_t *best_x,
                          uint16_t *best_y, double *best, double *second);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_CV_PEER_H */
