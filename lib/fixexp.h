/*
 * fixexp.h - internal: exp and ln in fixed point, for the Gaussian-mixture
 * fits (mixture.h). Table plus polynomial, integers only; tested against
 * libm in tests/test_fixexp.c, which states the measured errors.
 */
#ifndef SSDA_FIXEXP_H
#define SSDA_FIXEXP_H

#include <stdint.h>

#include "compiler.h"

/* 1.0 in Q30. */
#define SSDA__ONE_Q30 1073741824

/* ln(2) in Q16 and Q24, rounded. */
#define SSDA__LN2_Q16 45426
#define SSDA__LN2_Q24 11629080

/*
 * exp(-x) in Q30 for x >= 0 given in Q16 nats (x_q16 / 65536), rounded to
 * the nearest Q30 step; 0 once the value is below 2^-31 (x > 21.5).
 * Method: 2^-y with y = x log2(e) in Q32; 2^-(integer part) is a shift,
 * 2^-(top 4 fraction bits) a 16-entry table (Q31), the rest e^-g with
 * g < ln(2) / 16 a degree-5 polynomial (truncation < 2^-36).
 * Error: at most 2 Q30 steps (2^-29) from exp(-x_q16 / 65536), whatever x.
 */
SSDA_INTERNAL uint32_t ssda__exp_neg_q16(uint32_t x_q16);

/*
 * ln(v) in Q24 nats for v >= 1 (ln 0 is returned as INT32_MIN).
 * Method: v = m 2^e with m in [1, 2) (31 bits of m kept), m = c (1 + r)
 * with c the midpoint of one of 16 sub-intervals (tables of 1/c and ln c,
 * Q30), ln(1 + r) a degree-5 series (|r| < 0.031, truncation < 2^-32).
 * Error: at most 1 Q24 step (2^-24) from ln(v), plus the 2^-31 relative
 * truncation of v above 2^32.
 */
SSDA_INTERNAL int32_t ssda__ln_q24(uint64_t v);

#endif /* SSDA_FIXEXP_H */
