/*
 * config.h - compile-time feature switches (littlefs's LFS_NO_*, nanopb's
 * PB_* style). By default every feature is in and nothing here changes
 * the library. A firmware that needs less defines some of the switches
 * below when it compiles the library, and the code of the features left
 * out is not compiled at all. Three ways, from the simplest:
 *
 *   1. CMake: -DSSDA_CONFIG="SSDA_CFG_NO_RAMP;SSDA_CFG_NO_COARSE" (also
 *      passed to everything that links ssda);
 *   2. your own settings file, kept out of the library's tree (nanopb's and
 *      littlefs's way): compile the library with
 *      -DSSDA_CONFIG_FILE=my_ssda_config.h (the name without quotes, found
 *      on the include path; with CMake, -DSSDA_CONFIG_FILE=/path/to/
 *      my_ssda_config.h adds its directory too), where my_ssda_config.h
 *      holds e.g. `#define SSDA_CFG_NO_RAMP`. It is included first, here;
 *   3. -DSSDA_CFG_NO_RAMP ... on the compiler's command line.
 * Everything that includes the library's headers must see the same
 * switches (CMake passes them on with ssda::ssda).
 *
 * Asking a reduced build at run time for a feature it left out returns
 * SSDA_ERR_UNSUPPORTED (no output written), never a different answer: what
 * a reduced build computes is bit-identical to the full build.
 *
 * The minimal cores measured by tools/budget.sh (docs/target.md) set:
 *   search: all SSDA_CFG_NO_* of the search (exact AUTO and NONE thresholds,
 *           raster scan, row order, 8-bit views; no uniqueness, no sub-pixel
 *           fit, no 32-bit fast path)
 *   pitch:  all SSDA_CFG_NO_PITCH_* but OCTAVE and BELOW_RANGE (AMDF of
 *           whole frames with early exit, voicing, the dip-run choice with
 *           its octave and below-range checks, V-shaped interpolation); and
 *           apart, the reduced core: every SSDA_CFG_NO_PITCH_* (the checks
 *           left out, configurations must ask for the reduced definition);
 *           and both again with SSDA_CFG_PITCH_FIXED (below) at 16 kHz with
 *           the defaults
 *   stream: SSDA_CFG_NO_TILED, SSDA_CFG_NO_READ_SIZE and SSDA_CFG_NO_U16
 *           (raster 8-bit sources read at byte granularity, the plate cache,
 *           the streamed search)
 *
 * Every switch is listed below, commented out, with its meaning: copy the
 * ones you want into your settings file.
 */
#ifndef SSDA_CONFIG_H
#define SSDA_CONFIG_H

/* The user's settings file, if any: SSDA_CONFIG_FILE names it (a bare file
   name or relative path, no quotes; it is made a string here, so it must
   not contain a predefined macro name such as `unix` or `linux`). */
#ifdef SSDA_CONFIG_FILE
#define SSDA_CONFIG_STR2_(x) #x
#define SSDA_CONFIG_STR_(x) SSDA_CONFIG_STR2_(x)
#include SSDA_CONFIG_STR_(SSDA_CONFIG_FILE)
#endif

/* ---- search (match.h, and everything built on it: track.h, stream.h) ---- */

/* No increasing thresholds, SSDA_THRESHOLD_RAMP and SSDA_THRESHOLD_AUTO_RAMP
   (drops the integer square root and the wide multiply). */
/* #define SSDA_CFG_NO_RAMP */

/* No constant threshold SSDA_THRESHOLD_FIXED. With SSDA_CFG_NO_RAMP also the
   all-cut fallback goes. */
/* #define SSDA_CFG_NO_FIXED */

/* No successive-elimination bounds (SSDA_MATCH_BOUNDS). */
/* #define SSDA_CFG_NO_BOUNDS */

/* No coarse-to-fine scan (SSDA_SCAN_COARSE). */
/* #define SSDA_CFG_NO_COARSE */

/* No predicted scan (SSDA_SCAN_PREDICT); tracking then needs
   SSDA_TRACK_PREDICT_NONE. */
/* #define SSDA_CFG_NO_PREDICT */

/* No spread row order (SSDA_ORDER_SPREAD). */
/* #define SSDA_CFG_NO_SPREAD */

/* No 16-bit images in the search and the stream sources (views of
   SSDA_PIX_U16 are still valid views). */
/* #define SSDA_CFG_NO_U16 */

/* No uniqueness (SSDA_MATCH_UNIQUE, SSDA_TRACK_UNIQUE: the list of the
   smallest completed positions and the ratio cut). */
/* #define SSDA_CFG_NO_UNIQUE */

/* No sub-pixel fit (SSDA_MATCH_SUBPIXEL); tracking then needs
   SSDA_TRACK_NO_SUBPIXEL. */
/* #define SSDA_CFG_NO_SUBPIXEL */

/* No 32-bit fast path of the exact search (rows in memory, row order, no
   ramp or fallback, every SAD of the window below 2^32 - 1): every position
   takes the general 64-bit evaluation. The same results and pixel_ops,
   less code, more instructions per position (docs/target.md). */
/* #define SSDA_CFG_NO_FAST_PATH */

/* ---- pitch (pitch.h) ---- */

/* No input low-pass: configurations must set SSDA_PITCH_NO_FILTER. */
/* #define SSDA_CFG_NO_PITCH_FILTER */

/* No lag prediction (SSDA_PITCH_TRACK). */
/* #define SSDA_CFG_NO_PITCH_TRACK */

/* No full reference search (SSDA_PITCH_FULL). */
/* #define SSDA_CFG_NO_PITCH_FULL */

/* V-shaped interpolation only (SSDA_PITCH_PARABOLIC refused). */
/* #define SSDA_CFG_NO_PITCH_PARABOLIC */

/* No octave check (step 4 of pitch.h's definition): configurations must set
   SSDA_PITCH_NO_OCTAVE, the reduced definition this build computes. */
/* #define SSDA_CFG_NO_PITCH_OCTAVE */

/* No below-range check (step 6): configurations must set
   SSDA_PITCH_NO_BELOW_RANGE. */
/* #define SSDA_CFG_NO_PITCH_BELOW_RANGE */

/* No push intake: ssda_pitch_push returns SSDA_ERR_UNSUPPORTED, frames are
   given whole to ssda_pitch_frame (same estimates), and ssda_pitch_init
   needs no buffer. The low-pass needs the continuous stream: a stream
   with it is refused by ssda_pitch_frame, so set SSDA_CFG_NO_PITCH_FILTER
   too. */
/* #define SSDA_CFG_NO_PITCH_PUSH */

/* One configuration, fixed when the library compiles (a tuner, a voice
   firmware: the way of CMSIS-DSP's constant instances). Its fields are
   SSDA_CFG_PITCH_FIXED_<FIELD>, one per field of ssda_pitch_config_t:
   RATE_HZ (required), F0_MIN_HZ, F0_MAX_HZ, FRAME_LEN, HOP, THRESHOLD_Q15,
   VOICING_Q15, SILENCE_MAD, CHUNK, LOWPASS_HZ, FLAGS (unset or 0: the
   default, as in the struct). The resolved parameters (lags, K, span, ...)
   are then constants, checked when the library compiles (a configuration
   the full build refuses does not compile), and the code that resolves a
   configuration at run time is left out. ssda_pitch_init and
   ssda_pitch_buffer_size accept that configuration only (a default given
   as 0 or as its value) and return SSDA_ERR_UNSUPPORTED for any other;
   what they accept gives the full build's estimates, bit for bit. Code for
   what its flags do not use is left out as by the switches above (which
   may be set too). pitch.h: SSDA_PITCH_CONFIG_FIXED initialises a
   configuration to it, SSDA_PITCH_BUFFER_SIZE_FIXED is its buffer size.
   Example (the reduced core of tools/budget.sh, 16 kHz, whole frames):
     #define SSDA_CFG_PITCH_FIXED
     #define SSDA_CFG_PITCH_FIXED_RATE_HZ 16000
     #define SSDA_CFG_PITCH_FIXED_FLAGS (SSDA_PITCH_NO_FILTER | SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE)
     #define SSDA_CFG_NO_PITCH_PUSH */
/* #define SSDA_CFG_PITCH_FIXED */

/* ---- streaming (stream.h) ---- */

/* Raster sources only (SSDA_LAYOUT_TILED refused). */
/* #define SSDA_CFG_NO_TILED */

/* Byte-granular reads only (read_size must be 0 or 1): no bounce buffer.
   With SSDA_CFG_NO_TILED the plate is read straight from the device. */
/* #define SSDA_CFG_NO_READ_SIZE */

#endif /* SSDA_CONFIG_H */
