/* pitch_interp.c - sub-sample period by integer interpolation (V-shaped or
   parabolic fit), and the period-to-f0 conversion. */
#include "pitch_internal.h"

uint32_t ssda_pitch_norm_q20(uint32_t d, uint32_t s)
{
    /* d << 20 < 2^50 */
    return (uint32_t)(((uint64_t)d << 20) / s);
}

int32_t ssda_pitch_interp_q16(uint32_t a_q20, uint32_t b_q20, uint32_t c_q20, bool parabolic)
{
    /* a, b, c <= 2^20: |den| <= 2^23, |a - c| <= 2^20, numerator
       65536 * (a - c) <= 2^36 in int64_t. */
    int64_t a = (int64_t)a_q20, b = (int64_t)b_q20, c = (int64_t)c_q20;
    int64_t den = parabolic ? 2 * (a - 2 * b + c) : 2 * ((a > c ? a : c) - b);
    int64_t num = 65536 * (a - c);
    int64_t q;
    if (den <= 0) {
        return 0; /* flat or not a minimum: no offset */
    }
    q = (num >= 0) ? (num + den / 2) / den : -((-num + den / 2) / den);
    if (q > 32768) {
        q = 32768;
    } else if (q < -32768) {
        q = -32768;
    }
    return (int32_t)q;
}

uint32_t ssda_pitch_f0_q16(uint32_t rate_hz, uint32_t period_q16)
{
    /* rate << 32 < 2^48 */
    uint64_t q = (((uint64_t)rate_hz << 32) + period_q16 / 2u) / period_q16;
    return q > UINT32_MAX ? UINT32_MAX : (uint32_t)q;
}
