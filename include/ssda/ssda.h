/*
 * ssda.h - common definitions of the ssda library: version, error codes and
 * the feature switches (config.h). Every feature header includes it;
 * include the headers of the features you use (view.h, match.h, track.h,
 * grad.h, stream.h, pitch.h).
 *
 * The library is freestanding C99: integer and fixed-point only, no heap,
 * no I/O. Every buffer is owned by the caller; SSDA_*_SIZE() macros give
 * the bytes each one needs.
 */
#ifndef SSDA_SSDA_H
#define SSDA_SSDA_H

#include <stddef.h>
#include <stdint.h>
#include <stdbool.h>

#include "ssda/config.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Version as 0xMMmmpppp: major, minor, patch (littlefs style). */
#define SSDA_VERSION_MAJOR 0
#define SSDA_VERSION_MINOR 1
#define SSDA_VERSION_PATCH 0
#define SSDA_VERSION                                                   \
    ((uint32_t)(((uint32_t)SSDA_VERSION_MAJOR << 24) |                 \
                ((uint32_t)SSDA_VERSION_MINOR << 16) |                 \
                (uint32_t)SSDA_VERSION_PATCH))

/*
 * Error codes. Every function that can fail returns 0 (SSDA_OK) or one of
 * these negative values. Errors returned by caller callbacks (for example
 * an image source's read()) must be negative and are passed back unchanged,
 * so they may collide with these values only if the caller chooses so.
 * On any error, the function's outputs are left untouched.
 */
enum ssda_error {
    SSDA_OK           = 0,
    SSDA_ERR_NULL     = -1,  /* a required pointer argument is NULL */
    SSDA_ERR_ARG      = -2,  /* a parameter is out of its documented range */
    SSDA_ERR_SIZE     = -3,  /* zero or inconsistent dimensions (e.g. window larger than area) */
    SSDA_ERR_FORMAT   = -4,  /* unknown pixel format, or formats that must agree differ */
    SSDA_ERR_STRIDE   = -5,  /* row stride too small or misaligned for the pixel format */
    SSDA_ERR_OVERFLOW = -6,  /* a result could not be represented exactly */
    SSDA_ERR_BUFFER   = -7,  /* a caller buffer or arena is smaller than its SSDA_*_SIZE() */
    SSDA_ERR_IO       = -8,  /* an I/O layer failed without a code of its own */
    SSDA_ERR_STATE    = -9,  /* call made in the wrong state (e.g. object not initialised) */
    SSDA_ERR_UNSUPPORTED = -10 /* a feature left out of this build (SSDA_CFG_NO_*, ssda/config.h) */
};

/* A short, constant, English name for an error code ("ok", "null pointer", ...). */
const char *ssda_strerror(int err);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_SSDA_H */
