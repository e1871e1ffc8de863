/*
 * fixtrig.h - internal fixed-point trigonometry and signed shifts for the
 * symbolic registration (edge directions, Fourier descriptors, affine
 * angles). Angles are "turns": uint32_t, 2^32 per full turn (so angle
 * arithmetic wraps exactly modulo one turn); 0 = +x, a quarter turn
 * (2^30) = +y. Integers only, no division.
 */
#ifndef SSDA_FIXTRIG_H
#define SSDA_FIXTRIG_H

#include "compiler.h"

#include <stdint.h>

/* One Q15 unit (1.0) and a half turn. */
#define SSDA__Q15_ONE 32768
#define SSDA__TURN_HALF 0x80000000u

/* cos and sin of angle in Q15, in [-32768, 32768]: a 129-entry quarter-wave
   table (512 steps per turn) linearly interpolated; |error| <= 2 LSB
   (6.1e-5) against the exact value (tests/test_fixtrig.c checks every
   2^20-th angle against a floating-point reference in the tests). */
SSDA_INTERNAL int32_t ssda__cos_q15(uint32_t angle);
SSDA_INTERNAL int32_t ssda__sin_q15(uint32_t angle);

/* Angle of the vector (x, y) in turns (CORDIC, 28 iterations after the
   larger component is scaled to 2^28..2^29): |error| < 2^-22 turn
   (8.6e-5 degrees).
   (0, 0) gives 0. Any int64 input (INT64_MIN included). */
SSDA_INTERNAL uint32_t ssda__atan2(int64_t y, int64_t x);

/* floor(v / 2^s) for any v and s in 0..63, without a signed shift
   (implementation-defined in C99 for negative v). */
SSDA_INTERNAL int64_t ssda__asr64(int64_t v, uint32_t s);
/* v / 2^s rounded to nearest, halves away from zero; s in 1..62 and
   |v| < 2^63 - 2^(s-1). */
SSDA_INTERNAL int64_t ssda__rshr64(int64_t v, uint32_t s);
/* |v| as uint64_t (INT64_MIN gives 2^63). */
SSDA_INTERNAL uint64_t ssda__abs64(int64_t v);
/* Bits needed for v: 0 for 0, else floor(log2 v) + 1. */
SSDA_INTERNAL uint32_t ssda__bitlen64(uint64_t v);

#endif /* SSDA_FIXTRIG_H */
