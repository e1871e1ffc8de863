/*
 * test_pitch_ref.h - brute-force reference of the pitch rule written in
 * include/ssda/pitch.h, written from that text alone: every d(t) summed in
 * full with int64_t arithmetic into arrays, then the choice made over the
 * arrays. Shares no code with lib/pitch*.c, so it can disagree with them.
 */
#ifndef SSDA_TEST_PITCH_REF_H
#define SSDA_TEST_PITCH_REF_H
#include <stdbool.h>
#include <stdint.h>
#include "ssda/pitch.h"

#define TEST_PITCH_REF_MAX_LAG 4800u

typedef struct {
    uint32_t rate, lag_min, lag_max, frame_len;
    uint32_t threshold_q15, voicing_q15, silence_mad;
    bool parabolic;  /* sub-sample fit: parabola instead of V */
    bool no_octave;  /* reduced definition: step 4 skipped (SSDA_PITCH_NO_OCTAVE) */
    bool no_below_range; /* step 6 skipped (SSDA_PITCH_NO_BELOW_RANGE) */
} test_pitch_ref_cfg_t;

typedef struct {
    uint32_t first_dip;  /* minimum of the first valid run, before the octave check */
    uint32_t lag, period_q16, f0_q16;
    uint16_t confidence_q15;
    bool voiced, dip, silent;
} test_pitch_ref_t;

/* The reference configuration of a resolved pitch job: its lags, frame,
   thresholds, sub-sample fit and reduced steps (the parameters only; no
   rule is shared). */
test_pitch_ref_cfg_t test_pitch_ref_cfg_of(const ssda_pitch_info_t *info);

/* x holds frame_len + lag_max + 1 samples. */
void test_pitch_reference(const int16_t *x, const test_pitch_ref_cfg_t *c, test_pitch_ref_t *out);

/* d(t) and s(t) of the last reference call, t in [lag_min - 1, lag_max + 1]. */
int64_t test_pitch_ref_d(uint32_t lag);
int64_t test_pitch_ref_s(uint32_t lag);

#endif
