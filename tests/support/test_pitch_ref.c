/* test_pitch_ref.c - brute-force pitch reference (see header). */
#include "test_pitch_ref.h"

static int64_t g_d[TEST_PITCH_REF_MAX_LAG + 2u];
static int64_t g_s[TEST_PITCH_REF_MAX_LAG + 2u];

int64_t test_pitch_ref_d(uint32_t lag) { return g_d[lag]; }
int64_t test_pitch_ref_s(uint32_t lag) { return g_s[lag]; }

test_pitch_ref_cfg_t test_pitch_ref_cfg_of(const ssda_pitch_info_t *info)
{
    test_pitch_ref_cfg_t rc;
    rc.rate = info->sample_rate_hz;
    rc.lag_min = info->lag_min;
    rc.lag_max = info->lag_max;
    rc.frame_len = info->frame_len;
    rc.threshold_q15 = info->threshold_q15;
    rc.voicing_q15 = info->voicing_q15;
    rc.silence_mad = info->silence_mad;
    rc.parabolic = (info->flags & SSDA_PITCH_PARABOLIC) != 0u;
    rc.no_octave = (info->flags & SSDA_PITCH_NO_OCTAVE) != 0u;
    rc.no_below_range = (info->flags & SSDA_PITCH_NO_BELOW_RANGE) != 0u;
    return rc;
}

static int64_t floor_div(int64_t a, int64_t b) /* b > 0 */
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

static int64_t iabs(int64_t v) { return v < 0 ? -v : v; }

/* n(p) < n(q) as rationals */
static bool less(uint32_t p, uint32_t q) { return g_d[p] * g_s[q] < g_d[q] * g_s[p]; }

static bool under(uint32_t t, uint32_t q15) { return g_d[t] * 32768 <= (int64_t)q15 * g_s[t]; }

static int64_t q20(uint32_t t) { return (g_d[t] * 1048576) / g_s[t]; }

/* Sub-sample period at lag t (Q16.16), V or parabolic fit. */
static int64_t interp_period(const test_pitch_ref_cfg_t *c, uint32_t t)
{
    int64_t a = q20(t - 1u), b = q20(t), cc = q20(t + 1u), den, num, delta;
    if (c->parabolic) {
        den = 2 * (a - 2 * b + cc);
    } else {
        den = 2 * ((a > cc ? a : cc) - b);
    }
    num = 65536 * (a - cc);
    if (den <= 0) {
        delta = 0;
    } else if (num >= 0) {
        delta = (num + den / 2) / den;
    } else {
        delta = -((-num + den / 2) / den);
    }
    if (delta > 32768) delta = 32768;
    if (delta < -32768) delta = -32768;
    return (int64_t)t * 65536 + delta;
}

/* Interpolated floor of the dip at t (Q20): b - |a - c| / 2 (V) or
   b - (a - c)^2 / (8 (a - 2b + c)) (parabola, 0 drop when flat), >= 0. */
static int64_t dip_floor(const test_pitch_ref_cfg_t *c, uint32_t t)
{
    int64_t a = q20(t - 1u), b = q20(t), cc = q20(t + 1u), drop = 0;
    if (c->parabolic) {
        if (a - 2 * b + cc > 0) {
            drop = (a - cc) * (a - cc) / (8 * (a - 2 * b + cc));
        }
    } else {
        drop = (a > cc ? a - cc : cc - a) / 2;
    }
    return b > drop ? b - drop : 0;
}

/* d and s of one lag, straight from the definition (for lags the scan does
   not cover: the sub-periods of step 6). */
static void lag_values(const int16_t *x, const test_pitch_ref_cfg_t *c, int64_t mean,
                       int64_t level, uint32_t t)
{
    int64_t d = 0, b = 0;
    uint32_t i;
    for (i = 0; i < c->frame_len; i++) {
        d += iabs((int64_t)x[i] - x[i + t]);
        b += iabs((int64_t)x[i + t] - mean);
    }
    g_d[t] = d;
    g_s[t] = level + b;
}

/* Step 6 of pitch.h (below the range): is the period P (Q16) of the chosen
   dip, whose interpolated floor is F (Q20), a multiple of a period shorter
   than lag_min? Each sub-period is checked as written: every lag around it
   summed in full. */
static bool below_range(const int16_t *x, const test_pitch_ref_cfg_t *c, int64_t mean,
                        int64_t level, int64_t period, int64_t floor_q20)
{
    const int64_t limit = floor_q20 + (int64_t)(c->threshold_q15 / 3u) * 32 / 2;
    int64_t k;
    if (period + 32768 < (int64_t)c->lag_min * 65536) {
        return true;
    }
    if (period >= 2 * (int64_t)c->lag_min * 65536) {
        return false;
    }
    for (k = 2;; k++) {
        int64_t cc = (period + k * 32768) / (k * 65536);
        uint32_t u;
        if (cc < 3) {
            return false;
        }
        if (cc >= (int64_t)c->lag_min || period >= k * (int64_t)c->lag_min * 65536) {
            continue;
        }
        for (u = (uint32_t)cc - 2u; u <= (uint32_t)cc + 2u; u++) {
            lag_values(x, c, mean, level, u);
        }
        for (u = (uint32_t)cc - 1u; u <= (uint32_t)cc + 1u; u++) {
            if (!less(u - 1u, u) && !less(u + 1u, u) && dip_floor(c, u) <= limit) {
                return true;
            }
        }
    }
}

void test_pitch_reference(const int16_t *x, const test_pitch_ref_cfg_t *c, test_pitch_ref_t *out)
{
    const int64_t k = c->frame_len;
    int64_t sum = 0, mean, level = 0, period;
    uint32_t t, i, chosen = 0, run_start;
    bool found = false;

    for (i = 0; i < c->frame_len; i++) {
        sum += x[i];
    }
    /* floor((sum(x + 32768) + floor(K/2)) / K) - 32768 = floor((sum + floor(K/2)) / K) */
    mean = floor_div(sum + k / 2, k);
    for (i = 0; i < c->frame_len; i++) {
        level += iabs(x[i] - mean);
    }
    out->first_dip = 0; out->lag = 0; out->period_q16 = 0; out->f0_q16 = 0; out->confidence_q15 = 0;
    out->voiced = false; out->dip = false; out->silent = true;
    if (level < (int64_t)c->silence_mad * k) {
        return;
    }
    for (t = c->lag_min / 2u; t <= c->lag_max + 1u; t++) { /* lag_min / 2: arming */
        /* int32 is enough here (d <= 8192 * 65535 < 2^29, and the lagged
           level likewise) and much faster on 32-bit targets */
        int32_t d = 0, b = 0, m32 = (int32_t)mean;
        for (i = 0; i < c->frame_len; i++) {
            int32_t u = (int32_t)x[i] - x[i + t], w = (int32_t)x[i + t] - m32;
            d += u < 0 ? -u : u;
            b += w < 0 ? -w : w;
        }
        g_d[t] = d;
        g_s[t] = level + b;
    }
    /* Runs of n <= threshold in [lag_min, lag_max]. A run counts when a
       peak n > rearm lies between the previous run and it (for the first
       run, n(lag_min - 1) > threshold or n(lag_min / 2) > rearm is enough),
       and its minimum is neither a lag_max beyond which n still falls nor a
       lag_min below which it still falls. The first such run wins. */
    {
        uint32_t rearm = c->threshold_q15 + c->threshold_q15 / 2u;
        bool peak;
        if (rearm > 32767u) {
            rearm = 32767u;
        }
        /* the first run also counts after n(lag_min / 2) > rearm (the
           half-period peak of a period just above lag_min) */
        peak = !under(c->lag_min - 1u, c->threshold_q15) || !under(c->lag_min / 2u, rearm);
        t = c->lag_min;
        while (t <= c->lag_max && !found) {
            uint32_t m;
            if (!under(t, c->threshold_q15)) {
                if (!under(t, rearm)) {
                    peak = true;
                }
                t++;
                continue;
            }
            run_start = t;
            m = t;
            while (t <= c->lag_max && under(t, c->threshold_q15)) {
                if (less(t, m)) {
                    m = t;
                }
                t++;
            }
            (void)run_start;
            if (peak && (m != c->lag_max || !less(m + 1u, m)) &&
                (m != c->lag_min || !less(m - 1u, m))) {
                chosen = m;
                found = true;
            }
            peak = false;
        }
    }
    if (!found) {
        chosen = c->lag_min;
        for (t = c->lag_min + 1u; t <= c->lag_max; t++) {
            if (less(t, chosen)) {
                chosen = t;
            }
        }
    }
    out->first_dip = found ? chosen : 0u;
    period = interp_period(c, chosen);
    /* Octave check (step 4, unless the reduced definition skips it): a much
       deeper value near a multiple of the period means the dip was a
       fraction of it. */
    if (found && !c->no_octave) {
        int64_t margin = (int64_t)(c->threshold_q15 / 3u) * 32;
        bool moved = true;
        while (moved) {
            uint32_t mult;
            moved = false;
            for (mult = 2u; !moved; mult++) {
                uint32_t centre = (uint32_t)(((int64_t)mult * period + 32768) / 65536), m = 0;
                if (centre - 1u > c->lag_max) {
                    break;
                }
                for (t = centre - 1u; t <= centre + 1u && t <= c->lag_max; t++) {
                    if (m == 0u || less(t, m)) {
                        m = t;
                    }
                }
                if (q20(m) + margin < dip_floor(c, chosen)) {
                    chosen = m;
                    period = interp_period(c, chosen);
                    moved = true;
                }
            }
        }
    }
    out->lag = chosen;
    out->period_q16 = (uint32_t)period;
    out->f0_q16 = (uint32_t)((((int64_t)c->rate << 32) + period / 2) / period);
    {
        int64_t nq15 = g_d[chosen] * 32768 / g_s[chosen];
        out->confidence_q15 = (uint16_t)(nq15 >= 32767 ? 0 : 32767 - nq15);
    }
    {
        /* step 6 overwrites the values of the sub-period lags: F first */
        const int64_t f = found ? dip_floor(c, chosen) : 0;
        const int64_t d = g_d[chosen], sc = g_s[chosen];
        out->voiced = found && under(chosen, c->voicing_q15) &&
                      (c->no_below_range || !below_range(x, c, mean, level, period, f));
        g_d[chosen] = d;
        g_s[chosen] = sc;
    }
    out->dip = found;
    out->silent = false;
}
