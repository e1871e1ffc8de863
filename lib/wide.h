/*
 * wide.h - internal: unsigned 128-bit integers from two 64-bit halves, for
 * the few exact sums and quotients that do not fit 64 bits (the K-L
 * transform's n * sum(xy) - sum(x) sum(y), the mixture's moments). Used on
 * setup paths only (once per image or per fit iteration and component),
 * never per pixel. Everything is exact; nothing here allocates.
 */
#ifndef SSDA_WIDE_H
#define SSDA_WIDE_H

#include <stdint.h>

typedef struct {
    uint64_t hi;
    uint64_t lo;
} ssda__u128_t;

/* v as a 128-bit value. */
ssda__u128_t ssda__u128_from(uint64_t v);
/* a * b exactly (< 2^128), from four 32 x 32 -> 64 partial products. */
ssda__u128_t ssda__u128_mul64(uint64_t a, uint64_t b);
/* a + b and a - b modulo 2^128. */
ssda__u128_t ssda__u128_add(ssda__u128_t a, ssda__u128_t b);
ssda__u128_t ssda__u128_sub(ssda__u128_t a, ssda__u128_t b);
/* -1, 0, 1 as a < b, a == b, a > b. */
int ssda__u128_cmp(ssda__u128_t a, ssda__u128_t b);
/* a << s and a >> s for s in 0..127 (bits shifted out are lost). */
ssda__u128_t ssda__u128_shl(ssda__u128_t a, uint32_t s);
ssda__u128_t ssda__u128_shr(ssda__u128_t a, uint32_t s);
/* Number of significant bits: 0 for 0, 128 for values >= 2^127. */
uint32_t ssda__u128_bits(ssda__u128_t a);
/* floor(n / d) for d > 0 (restoring division, one bit per step, up to 128
   steps); a zero d gives all ones. */
ssda__u128_t ssda__u128_div(ssda__u128_t n, ssda__u128_t d);
/* floor(sqrt(a)) (< 2^64), bitwise. */
uint64_t ssda__u128_isqrt(ssda__u128_t a);
/* min(a, 2^64 - 1). */
uint64_t ssda__u128_sat64(ssda__u128_t a);

/* Number of significant bits of a 64-bit value (0 for 0). */
uint32_t ssda__bits64(uint64_t v);

/* round(v / 2^s) with halves away from zero, for s in 1..62: symmetric in
   sign (round(-v) = -round(v)), so results do not depend on which way a
   vector points; no right shift of a negative value. */
int64_t ssda__round_shift(int64_t v, uint32_t s);

#endif /* SSDA_WIDE_H */
