/* pitch_amdf.c - the difference function: frame mean and level (one
   lag's AMDF sum with SSDA early exit is inline, in pitch_internal.h). */
#include "pitch_internal.h"

#include "fixmath.h"

int32_t ssda__pitch_mean(const int16_t *x, uint32_t n)
{
    uint32_t sum = 0u; /* sum of x + 32768: <= 8192 * 65535 < 2^30 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (uint32_t)((int32_t)x[i] + 32768);
    }
    /* n = 1..8192 (pitch_internal.h): the frame length */
    return (int32_t)SSDA_DIV32(sum + n / 2u, n) - 32768; /* NOLINT(clang-analyzer-core.DivideZero) */
}

uint32_t ssda__pitch_level(const int16_t *x, uint32_t n, int32_t mean)
{
    uint32_t sum = 0u; /* <= 8192 * 65535 < 2^30 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        int32_t v = (int32_t)x[i] - mean; /* -65535..65535 */
        sum += (v < 0) ? (uint32_t)(-v) : (uint32_t)v;
    }
    return sum;
}
