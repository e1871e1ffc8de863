/* pitch_filter.c - the input low-pass: two cascaded integer one-pole
   filters (definition and bounds in include/ssda/pitch.h). */
#include "pitch_internal.h"

#define TWO_PI_Q16 411775u /* 2 pi * 65536, rounded */

uint16_t ssda__pitch_lowpass_coef_q15(uint32_t fc_hz, uint32_t rate_hz)
{
    /* a = W / (R + W) with W = 2 pi fc, R = rate, both scaled by 65536:
       W <= 411775 * 12000 < 2^33, R * 65536 <= 48000 * 65536 < 2^32. */
    uint64_t w = (uint64_t)TWO_PI_Q16 * fc_hz;
    uint64_t den = ((uint64_t)rate_hz << 16) + w;
    /* round(2^15 W / (R + W)) <= 32768 < 2^16: 16 restoring steps, so no
       64-bit division routine is linked; den << 15 < 2^49 */
    uint64_t num = (w << 15) + den / 2u;
    uint64_t step = den << 15;
    uint32_t q = 0u;
    uint32_t bit = 0x8000u;
    while (bit != 0u) {
        if (num >= step) {
            num -= step;
            q |= bit;
        }
        step >>= 1;
        bit >>= 1;
    }
    return (uint16_t)q;
}

/* y += trunc(a * (32768 * in - y) / 32768): a convex step towards the
   input, so y stays within [-2^30, 32767 * 2^15]. */
static int32_t pole(int32_t y_q15, uint32_t a_q15, int32_t in_q15)
{
    int64_t e = (int64_t)in_q15 - y_q15;       /* |e| <= 2^31 */
    return y_q15 + (int32_t)(((int64_t)a_q15 * e) / 32768); /* |a e| <= 2^46 */
}

int16_t ssda__pitch_lowpass(int32_t *y1_q15, int32_t *y2_q15, uint32_t a_q15, int16_t in)
{
    int32_t v;
    *y1_q15 = pole(*y1_q15, a_q15, (int32_t)in * 32768);
    *y2_q15 = pole(*y2_q15, a_q15, *y1_q15);
    /* floor((y2 + 16384) / 32768) without shifting a negative value */
    v = *y2_q15 + 16384;
    v = (v >= 0) ? v / 32768 : -((-v + 32767) / 32768);
    return (int16_t)v;
}

void ssda__pitch_lowpass_prime(int32_t *y1_q15, int32_t *y2_q15, int16_t in)
{
    *y1_q15 = (int32_t)in * 32768; /* |in * 32768| <= 2^30 */
    *y2_q15 = *y1_q15;
}
