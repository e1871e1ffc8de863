/*
 * config.h - compile-time feature switches (littlefs's LFS_NO_*, nanopb's
 * PB_* style). By default every feature is in and nothing here changes
 * the library. A firmware that needs less defines some of the switches
 * below when it compiles the library (with CMake:
 * -DSSDA_CONFIG="SSDA_CFG_NO_RAMP;SSDA_CFG_NO_COARSE", which also passes
 * them to everything that links ssda), and the code of the features left
 * out is not compiled at all.
 *
 * Asking a reduced build at run time for a feature it left out returns
 * SSDA_ERR_UNSUPPORTED (no output written), never a different answer: what
 * a reduced build computes is bit-identical to the full build.
 *
 * The minimal cores measured by tools/budget.sh (docs/target.md) set:
 *   search: all SSDA_CFG_NO_* of the search (exact AUTO and NONE thresholds,
 *           raster scan, row order, 8-bit views)
 *   pitch:  all SSDA_CFG_NO_PITCH_* (streamed AMDF with early exit,
 *           voicing, the dip-run choice and its octave check, V-shaped
 *           interpolation)
 *   stream: SSDA_CFG_NO_TILED, SSDA_CFG_NO_READ_SIZE and SSDA_CFG_NO_U16
 *           (raster 8-bit sources read at byte granularity, the plate cache,
 *           the streamed search)
 */
#ifndef SSDA_CONFIG_H
#define SSDA_CONFIG_H

/* ---- search (match.h, and everything built on it: track.h, stream.h) ---- */

/* SSDA_CFG_NO_RAMP: no increasing thresholds, SSDA_THRESHOLD_RAMP and
   SSDA_THRESHOLD_AUTO_RAMP (drops the integer square root and the wide
   multiply). */
/* SSDA_CFG_NO_FIXED: no constant threshold SSDA_THRESHOLD_FIXED. With
   SSDA_CFG_NO_RAMP also the all-cut fallback goes. */
/* SSDA_CFG_NO_BOUNDS: no successive-elimination bounds (SSDA_MATCH_BOUNDS). */
/* SSDA_CFG_NO_COARSE: no coarse-to-fine scan (SSDA_SCAN_COARSE). */
/* SSDA_CFG_NO_PREDICT: no predicted scan (SSDA_SCAN_PREDICT); tracking then
   needs SSDA_TRACK_PREDICT_NONE. */
/* SSDA_CFG_NO_SPREAD: no spread row order (SSDA_ORDER_SPREAD). */
/* SSDA_CFG_NO_U16: no 16-bit images in the search and the stream sources
   (views of SSDA_PIX_U16 are still valid views). */

/* ---- pitch (pitch.h) ---- */

/* SSDA_CFG_NO_PITCH_FILTER: no input low-pass: configurations must set
   SSDA_PITCH_NO_FILTER. */
/* SSDA_CFG_NO_PITCH_TRACK: no lag prediction (SSDA_PITCH_TRACK). */
/* SSDA_CFG_NO_PITCH_FULL: no full reference search (SSDA_PITCH_FULL). */
/* SSDA_CFG_NO_PITCH_PARABOLIC: V-shaped interpolation only
   (SSDA_PITCH_PARABOLIC refused). */

/* ---- streaming (stream.h) ---- */

/* SSDA_CFG_NO_TILED: raster sources only (SSDA_LAYOUT_TILED refused). */
/* SSDA_CFG_NO_READ_SIZE: byte-granular reads only (read_size must be 0 or
   1): no bounce buffer. With SSDA_CFG_NO_TILED the plate is read straight
   from the device. */

#endif /* SSDA_CONFIG_H */
