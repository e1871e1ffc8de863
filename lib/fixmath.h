/* fixmath.h - internal integer helpers: exact, no undefined behaviour. */
#ifndef SSDA_FIXMATH_H
#define SSDA_FIXMATH_H

#include <stdint.h>

#include "compiler.h"

/* floor(sqrt(v)) for any 64-bit v (bitwise method, 32 iterations). */
SSDA_INTERNAL uint32_t ssda__isqrt64(uint64_t v);

/* floor(a * b / 2^24) for a < 2^32, b < 2^56 without a 128-bit product:
   b = bh * 2^24 + bl, so a*b/2^24 = a*bh + a*bl/2^24 (a*bh < 2^64 needs
   bh < 2^32, a*bl < 2^56). Saturates to UINT64_MAX if a*bh would not fit. */
SSDA_INTERNAL uint64_t ssda__mul_shr24(uint32_t a, uint64_t b);

/* a * b exactly (< 2^48) from two 32-bit partial products, a = ah 2^16 + al:
   a * b = (ah b) 2^16 + al b, each below 2^32. No 64-bit multiply routine
   from the runtime library on cores without UMULL (Cortex-M0/M0+/M23),
   where `(uint64_t)a * b` calls __aeabi_lmul. */
static inline uint64_t ssda__mul_u32_u16(uint32_t a, uint16_t b)
{
    const uint32_t hi = (a >> 16) * (uint32_t)b;     /* < 2^32 */
    const uint32_t lo = (a & 0xFFFFu) * (uint32_t)b; /* < 2^32 */
    return ((uint64_t)hi << 16) + lo;
}

/* a * b exactly (< 2^64) from four 16 x 16-bit products, each below 2^32:
   the runtime's 64 x 64 multiply (__aeabi_lmul, 90 B) is not linked on
   cores without UMULL. Use SSDA_MUL64, which takes the compiler's product
   where the core has one. */
SSDA_INTERNAL uint64_t ssda__mul_u32_u32(uint32_t a, uint32_t b);

/* Thumb-1-only cores (Cortex-M0/M0+/M23) have no 32 x 32 -> 64 multiply
   instruction: there SSDA_MUL64 calls the routine above, elsewhere the
   compiler's UMULL. The product is the same. */
#if defined(__ARM_ARCH_ISA_THUMB) && (__ARM_ARCH_ISA_THUMB == 1)
#define SSDA_MUL64(a, b) ssda__mul_u32_u32((a), (b))
#else
#define SSDA_MUL64(a, b) ((uint64_t)(uint32_t)(a) * (uint32_t)(b))
#endif

/* min(floor(n / d), UINT32_MAX) for d > 0, by restoring shift-and-subtract
   in 32-bit words (32 steps): no 64-bit division routine from the runtime
   library, whose generic code costs about 1 KB of flash on cores without
   a divide instruction (Cortex-M0/M0+/M23). Exact: the caller clamps or
   knows the quotient is below 2^32. */
SSDA_INTERNAL uint32_t ssda__div64_32(uint64_t n, uint32_t d);

/* Cores without a 32-bit divide instruction: there the runtime library's
   64-bit division is generic C (large, and no faster than the loop above),
   so hot 64-by-32 divisions take ssda__div64_32; elsewhere the compiler's
   division is used. Either way the quotient is the same. */
#if defined(__ARM_ARCH) && !defined(__ARM_FEATURE_IDIV)
#define SSDA_SOFT_DIV64 1
#define SSDA_DIV64_32(n, d) ssda__div64_32((n), (d))
#else
#define SSDA_SOFT_DIV64 0
#define SSDA_DIV64_32(n, d) ((uint32_t)((uint64_t)(n) / (uint32_t)(d)))
#endif

/* floor(a / b) for a, b below 2^32 (b > 0), for the setup and miss paths:
   on those cores the loop above, so that the 266-byte 32-bit division
   routine of the runtime library is not linked; elsewhere plain `/` (same
   type and value). */
#if SSDA_SOFT_DIV64 && defined(__GNUC__)
/* a divisor fixed at compile time (1 when a feature is left out) folds */
#define SSDA_DIV32(a, b)                                                      \
    (__builtin_constant_p(b) ? (uint32_t)(a) / (uint32_t)(b)                  \
                             : ssda__div64_32((uint64_t)(a), (uint32_t)(b)))
#define SSDA_MOD32(a, b) ((uint32_t)(a) - SSDA_DIV32((a), (b)) * (uint32_t)(b))
#elif SSDA_SOFT_DIV64
#define SSDA_DIV32(a, b) ssda__div64_32((uint64_t)(a), (uint32_t)(b))
#define SSDA_MOD32(a, b) ((uint32_t)(a) - SSDA_DIV32((a), (b)) * (uint32_t)(b))
#else
#define SSDA_DIV32(a, b) ((a) / (b))
#define SSDA_MOD32(a, b) ((a) % (b))
#endif

#endif /* SSDA_FIXMATH_H */
