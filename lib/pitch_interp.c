/* pitch_interp.c - sub-sample period by integer interpolation (V-shaped or
   parabolic fit), and the period-to-f0 conversion. */
#include "pitch_internal.h"
#include "fixmath.h"

uint32_t ssda__pitch_norm_q20(uint32_t d, uint32_t s)
{
    /* d << 20 < 2^50; the quotient is <= 2^20 */
    return ssda__div64_32((uint64_t)d << 20, s);
}

int32_t ssda__pitch_interp_q16(uint32_t a_q20, uint32_t b_q20, uint32_t c_q20, bool parabolic)
{
    /* a, b, c <= 2^20: |den| <= 2^23 in int32_t, |a - c| <= 2^20, numerator
       65536 * |a - c| <= 2^36 in uint64_t. */
    int32_t a = (int32_t)a_q20, b = (int32_t)b_q20, c = (int32_t)c_q20;
    /* a build without the parabola (SSDA_CFG_NO_PITCH_PARABOLIC) never asks
       for it: its code is left out */
    int32_t den = SSDA_PITCH_HAS_PARABOLIC(parabolic ? SSDA_PITCH_PARABOLIC : 0u)
                      ? 2 * (a - 2 * b + c) : 2 * ((a > c ? a : c) - b);
    uint64_t num = (uint64_t)65536u * (uint32_t)(a > c ? a - c : c - a);
    uint32_t q;
    if (den <= 0) {
        return 0; /* flat or not a minimum: no offset */
    }
    /* round half away from zero; a quotient that saturates is clamped anyway */
    q = ssda__div64_32(num + (uint64_t)(uint32_t)den / 2u, (uint32_t)den);
    if (q > 32768u) {
        q = 32768u;
    }
    return a >= c ? (int32_t)q : -(int32_t)q;
}

uint32_t ssda__pitch_f0_q16(uint32_t rate_hz, uint32_t period_q16)
{
    /* rate << 32 < 2^48; the quotient saturates at UINT32_MAX */
    return ssda__div64_32(((uint64_t)rate_hz << 32) + (uint64_t)period_q16 / 2u, period_q16);
}
