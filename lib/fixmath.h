/* fixmath.h - internal integer helpers: exact, no undefined behaviour. */
#ifndef SSDA_FIXMATH_H
#define SSDA_FIXMATH_H

#include <stdint.h>

/* floor(sqrt(v)) for any 64-bit v (bitwise method, 32 iterations). */
uint32_t ssda_isqrt64(uint64_t v);

/* floor(a * b / 2^24) for a < 2^32, b < 2^56 without a 128-bit product:
   b = bh * 2^24 + bl, so a*b/2^24 = a*bh + a*bl/2^24 (a*bh < 2^64 needs
   bh < 2^32, a*bl < 2^56). Saturates to UINT64_MAX if a*bh would not fit. */
uint64_t ssda_mul_shr24(uint32_t a, uint64_t b);

#endif /* SSDA_FIXMATH_H */
