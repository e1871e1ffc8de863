/* fixtrig.c - table sine/cosine, CORDIC atan2 and signed shifts (fixtrig.h). */
#include "fixtrig.h"

int32_t ssda__sin_q15(uint32_t angle)
{
    /* round(32768 sin(k pi / 256)), k = 0..128: a quarter wave in 128 steps. */
    static const uint16_t sin_quarter[129] = {
        0u, 402u, 804u, 1206u, 1608u, 2009u, 2411u, 2811u, 3212u, 3612u, 4011u, 4410u, 4808u,
        5205u, 5602u, 5998u, 6393u, 6787u, 7180u, 7571u, 7962u, 8351u, 8740u, 9127u, 9512u,
        9896u, 10279u, 10660u, 11039u, 11417u, 11793u, 12167u, 12540u, 12910u, 13279u, 13646u,
        14010u, 14373u, 14733u, 15091u, 15447u, 15800u, 16151u, 16500u, 16846u, 17190u, 17531u,
        17869u, 18205u, 18538u, 18868u, 19195u, 19520u, 19841u, 20160u, 20475u, 20788u, 21097u,
        21403u, 21706u, 22006u, 22302u, 22595u, 22884u, 23170u, 23453u, 23732u, 24008u, 24279u,
        24548u, 24812u, 25073u, 25330u, 25583u, 25833u, 26078u, 26320u, 26557u, 26791u, 27020u,
        27246u, 27467u, 27684u, 27897u, 28106u, 28311u, 28511u, 28707u, 28899u, 29086u, 29269u,
        29448u, 29622u, 29792u, 29957u, 30118u, 30274u, 30425u, 30572u, 30715u, 30853u, 30986u,
        31114u, 31238u, 31357u, 31471u, 31581u, 31686u, 31786u, 31881u, 31972u, 32058u, 32138u,
        32214u, 32286u, 32352u, 32413u, 32470u, 32522u, 32568u, 32610u, 32647u, 32679u, 32706u,
        32729u, 32746u, 32758u, 32766u, 32768u};
    /* 2 bits of quadrant, 7 of table step, 23 of interpolation fraction */
    const uint32_t quadrant = angle >> 30;
    uint32_t in_quarter = angle & 0x3FFFFFFFu;
    uint32_t idx, frac, lo, hi, v;
    if ((quadrant & 1u) != 0u) {
        in_quarter = 0x40000000u - in_quarter; /* mirror: sin(pi/2 + t) = sin(pi/2 - t) */
    }
    idx = in_quarter >> 23;                 /* 0..128 */
    frac = in_quarter & 0x7FFFFFu;
    lo = sin_quarter[idx];
    hi = idx < 128u ? sin_quarter[idx + 1u] : lo;
    /* the table rises, hi - lo <= 402 < 2^9: (hi - lo) * frac < 2^32 */
    v = lo + (((hi - lo) * frac + 0x400000u) >> 23);
    return quadrant >= 2u ? -(int32_t)v : (int32_t)v;
}

int32_t ssda__cos_q15(uint32_t angle)
{
    return ssda__sin_q15(angle + 0x40000000u);
}

uint64_t ssda__abs64(int64_t v)
{
    return v < 0 ? (uint64_t)0u - (uint64_t)v : (uint64_t)v;
}

uint32_t ssda__bitlen64(uint64_t v)
{
    uint32_t n = 0u;
    uint64_t r = v;
    while (r != 0u) {
        n++;
        r >>= 1;
    }
    return n;
}

int64_t ssda__asr64(int64_t v, uint32_t s)
{
    uint64_t m;
    if (v >= 0) {
        m = (uint64_t)v >> s;
        return (int64_t)m;
    }
    /* floor(v / 2^s) = -(floor((-v - 1) / 2^s)) - 1 for v < 0 */
    m = (uint64_t)(-(v + 1)) >> s;
    return -(int64_t)m - 1;
}

int64_t ssda__rshr64(int64_t v, uint32_t s)
{
    const uint32_t s1 = s - 1u;
    const uint64_t half = (uint64_t)1u << s1;
    const uint64_t m = (ssda__abs64(v) + half) >> s;
    return v < 0 ? -(int64_t)m : (int64_t)m;
}

/* floor(v / 2^s) for int32_t, as ssda__asr64. */
static int32_t asr32(int32_t v, uint32_t s)
{
    return (int32_t)ssda__asr64((int64_t)v, s);
}

uint32_t ssda__atan2(int64_t y, int64_t x)
{
    /* round(2^32 atan(2^-i) / (2 pi)), i = 0..27. */
    static const uint32_t atan_turns[28] = {
        536870912u, 316933406u, 167458907u, 85004756u, 42667331u, 21354465u, 10679838u,
        5340245u, 2670163u, 1335087u, 667544u, 333772u, 166886u, 83443u, 41722u, 20861u,
        10430u, 5215u, 2608u, 1304u, 652u, 326u, 163u, 81u, 41u, 20u, 10u, 5u};
    const uint64_t m = ssda__abs64(x) > ssda__abs64(y) ? ssda__abs64(x) : ssda__abs64(y);
    const uint32_t len = ssda__bitlen64(m);
    uint32_t angle = 0u;
    int32_t cx, cy;
    uint32_t i;
    if (m == 0u) {
        return 0u;
    }
    /* scale so that the larger |component| is in [2^28, 2^29): the vector
       is then below 2^29.5 and its CORDIC growth (1.65) below 2^31 */
    if (len > 29u) {
        cx = (int32_t)ssda__asr64(x, len - 29u);
        cy = (int32_t)ssda__asr64(y, len - 29u);
    } else {
        const uint32_t up = 29u - len;
        const uint64_t fu = (uint64_t)1u << up; /* < 2^29 */
        const int64_t f = (int64_t)fu;
        cx = (int32_t)(x * f);
        cy = (int32_t)(y * f);
    }
    if (cx < 0) { /* rotate by half a turn into the right half plane */
        cx = -cx;
        cy = -cy;
        angle = SSDA__TURN_HALF;
    }
    for (i = 0u; i < 28u; i++) {
        const int32_t dx = asr32(cy, i);
        const int32_t dy = asr32(cx, i);
        if (cy > 0) { /* rotate clockwise: the angle so far grows */
            cx += dx;
            cy -= dy;
            angle += atan_turns[i];
        } else {
            cx -= dx;
            cy += dy;
            angle -= atan_turns[i];
        }
    }
    return angle;
}
