/*
 * pitch_search.c - choosing the lag of one frame: the first dip run of the
 * normalised AMDF under the threshold, else its global minimum, with SSDA
 * early exit that leaves the choice exactly as a full search makes it
 * (the rule and the argument are in include/ssda/pitch.h).
 */
#include "pitch_internal.h"
#include "fixmath.h"

#define NO_BOUND UINT32_MAX /* larger than any sum (K * 65535 < 2^29) */

/* One lag's value: d exact when `exact`, else a lower bound of d that is
   above the bound the lag was cut at. s = A + B(lag) > 0. */
typedef struct {
    uint32_t d;
    uint32_t s;
    bool exact;
} lag_value_t;

typedef struct {
    const ssda_pitch_info_t *info;
    const int16_t *x;
    int32_t mean;     /* m */
    uint32_t level;   /* A */
    /* Absolute differences so far. Lags summed: the scan and its extras
       <= lag_max - lag_min + 6 (< 4 810); the octave check <= 3 per multiple
       k P <= lag_max + 1 plus 2 per move, and a move takes P to at least
       2 P - 1.5 (P >= 3.5: at most 12 moves, sum of 1/P < 0.7), so it adds
       < 3 * 4 801 * 0.7 + 3 * 13 + 2 * 12 < 10 200.
       Under 15 010 lags of K <= 8192: < 2^27. */
    uint32_t diffs;
} frame_t;

/* n(p) < n(q), exactly: d_p * s_q < d_q * s_p (products < 2^59). */
static bool n_less(const lag_value_t *p, const lag_value_t *q)
{
    return (uint64_t)p->d * q->s < (uint64_t)q->d * p->s;
}

/* n <= q15 / 32768, exactly. */
static bool n_at_most_q15(const lag_value_t *v, uint32_t q15)
{
    return ((uint64_t)v->d << 15) <= (uint64_t)q15 * v->s;
}

/* Largest d with d / s <= threshold: floor(q15 * s / 32768) < s. */
static uint32_t threshold_bound(uint32_t q15, uint32_t s)
{
    return (uint32_t)(((uint64_t)q15 * s) >> 15);
}

/* Largest d at scale s that still wins against best: n < n(best) for a lag
   after best's, n <= n(best) for one before it (ties go to the smaller lag).
   Returns false when no d >= 0 can win. The result is <= s < 2^30. */
static bool best_bound(const lag_value_t *best, bool after, uint32_t s, uint32_t *bound)
{
    uint64_t p = (uint64_t)best->d * s; /* < 2^59 */
    if (after) {
        if (p == 0u) {
            return false;
        }
        p -= 1u;
    }
    *bound = SSDA_DIV64_32(p, best->s); /* <= s < 2^30 */
    return true;
}

/* Sum one lag, cut above bound. Rejected for free when the lower bound
   |A - B(lag)| <= d(lag) is already above bound. */
static lag_value_t evaluate(frame_t *f, uint32_t lag, uint32_t s, uint32_t bound)
{
    lag_value_t v;
    uint32_t b = s - f->level;
    uint32_t lower = f->level > b ? f->level - b : b - f->level;
    v.s = s;
    if (lower > bound) {
        v.d = lower;
        v.exact = false;
        return v;
    }
    v.d = ssda_pitch_amdf_lag(f->x, f->info->frame_len, lag, f->info->chunk, bound,
                              &v.exact, &f->diffs);
    return v;
}

/* Make v exact (re-sum without a bound) for the interpolation. */
static void make_exact(frame_t *f, uint32_t lag, lag_value_t *v)
{
    if (!v->exact) {
        *v = evaluate(f, lag, v->s, NO_BOUND);
    }
}

/* |x[i] - m| for the sliding sum B(lag) = sum_{i<K} |x[lag + i] - m|. */
static uint32_t abs_dev(int16_t x, int32_t mean)
{
    int32_t v = (int32_t)x - mean;
    return v < 0 ? (uint32_t)(-v) : (uint32_t)v;
}

/* The value of any lag, with its scale computed directly. */
static lag_value_t value_at(frame_t *f, uint32_t lag, uint32_t bound)
{
    uint32_t s = f->level + ssda_pitch_level(f->x + lag, f->info->frame_len, f->mean);
    return evaluate(f, lag, s, bound);
}

/* Sub-sample period of the dip at lag, from exact neighbour values. */
static uint32_t period_q16_of(const frame_t *f, uint32_t lag, const lag_value_t *left,
                              const lag_value_t *mid, const lag_value_t *right)
{
    int32_t delta = ssda_pitch_interp_q16(ssda_pitch_norm_q20(left->d, left->s),
                                          ssda_pitch_norm_q20(mid->d, mid->s),
                                          ssda_pitch_norm_q20(right->d, right->s),
                                          SSDA_PITCH_HAS_PARABOLIC(f->info->flags));
    /* lag <= 4800: 65536 * lag + delta < 2^29 */
    return (uint32_t)((int32_t)(lag << 16) + delta);
}

/* The interpolated minimum of the dip through a, b, c (Q20): b - |a - c| / 2
   for the V fit, b - (a - c)^2 / (8 (a - 2b + c)) for the parabola; >= 0. */
static uint32_t dip_floor_q20(const frame_t *f, const lag_value_t *left, const lag_value_t *mid,
                              const lag_value_t *right)
{
    uint32_t a = ssda_pitch_norm_q20(left->d, left->s);
    uint32_t b = ssda_pitch_norm_q20(mid->d, mid->s);
    uint32_t c = ssda_pitch_norm_q20(right->d, right->s);
    uint32_t diff = a > c ? a - c : c - a; /* <= 2^20 */
    uint32_t drop;
    if (SSDA_PITCH_HAS_PARABOLIC(f->info->flags)) {
        /* |8 (a - 2b + c)| <= 2^24; (a - c)^2 <= 2^40; a saturated
           quotient (> b) gives 0 as the exact one would */
        int32_t den = 8 * ((int32_t)a - 2 * (int32_t)b + (int32_t)c);
        drop = den > 0 ? ssda_div64_32((uint64_t)diff * diff, (uint32_t)den) : 0u;
    } else {
        drop = diff / 2u;
    }
    return b > drop ? b - drop : 0u;
}

/*
 * Octave check (see pitch.h): with P the sub-sample period of the chosen
 * dip and F its interpolated floor, look at the lags round(k P) - 1 .. + 1
 * for k = 2, 3, ... up to lag_max; if the smallest n there is below F by
 * more than the margin (in Q20: nq(m) + margin < F), the dip was a fraction
 * of the period: move to that lag and check again. Comparing with the
 * floor, not with n at the integer lag, keeps a dip that is only shallow
 * because the period falls between two lags. Only lags that could pass are
 * summed in full (the bound comes from the test itself): still exact.
 * Returns true and the new lag and value when it moves.
 */
static bool octave_up(frame_t *f, uint32_t period_q16, uint32_t floor_q20,
                      uint32_t *new_lag, lag_value_t *new_v)
{
    /* threshold / 3 as (t * 43691) >> 17, exact for every t < 2^16 (checked
       exhaustively): cores without a divide instruction would call the
       runtime's division routine for a constant 3 */
    const uint32_t margin_q20 = (((uint32_t)f->info->threshold_q15 * 43691u) >> 17) << 5;
    const bool full = SSDA_PITCH_HAS_FULL(f->info->flags);
    uint32_t k, limit;
    if (floor_q20 <= margin_q20) {
        return false; /* nothing can be deeper by the margin */
    }
    limit = floor_q20 - margin_q20; /* wanted: nq < limit */
    k = 2u;
    for (;;) { /* multiples k of the period until k * period passes lag_max */
        /* k * period_q16 <= 1200 * 2^29 < 2^40 */
        uint32_t c = (uint32_t)(((uint64_t)k * period_q16 + 32768u) >> 16);
        uint32_t lag, found_lag = 0u;
        lag_value_t found_v = {0u, 1u, false};
        if (c - 1u > f->info->lag_max) {
            return false;
        }
        for (lag = c - 1u; lag <= c + 1u && lag <= f->info->lag_max; lag++) {
            uint32_t s = f->level + ssda_pitch_level(f->x + lag, f->info->frame_len, f->mean);
            /* largest d with floor(2^20 d / s) < limit; limit * s < 2^50 */
            uint32_t bound = (uint32_t)(((uint64_t)limit * s - 1u) >> 20);
            lag_value_t v = evaluate(f, lag, s, full ? NO_BOUND : bound);
            if (v.exact && (found_lag == 0u || n_less(&v, &found_v))) {
                found_lag = lag;
                found_v = v;
            }
        }
        if (found_lag != 0u && ssda_pitch_norm_q20(found_v.d, found_v.s) < limit) {
            *new_lag = found_lag;
            *new_v = found_v;
            return true;
        }
        k++;
    }
}

static void silent_estimate(ssda_pitch_estimate_t *est)
{
    est->lag = 0u;
    est->period_q16 = 0u;
    est->f0_q16 = 0u;
    est->diffs = 0u;
    est->confidence_q15 = 0u;
    est->voiced = false;
    est->dip = false;
    est->silent = true;
}

void ssda_pitch_analyze(const ssda_pitch_info_t *info, const int16_t *x,
                        uint32_t predict_lag, ssda_pitch_estimate_t *est)
{
    const uint32_t k = info->frame_len;
    const uint32_t lag_min = info->lag_min, lag_max = info->lag_max;
    const bool full = SSDA_PITCH_HAS_FULL(info->flags);
    const uint32_t thr = info->threshold_q15;
    frame_t f;
    int32_t mean;
    uint32_t b_sum, lag, pred = 0u;
    uint32_t period, n_q15;
    lag_value_t prev, cur, pred_v;
    /* The best lag so far (global-minimum fallback), with its neighbours. */
    lag_value_t best = {0u, 1u, false}, best_left = {0u, 1u, false}, best_right = {0u, 1u, false};
    uint32_t best_lag = 0u;
    bool best_need_right = false;
    /* The open run under the threshold: its minimum and neighbours. */
    lag_value_t run = {0u, 1u, false}, run_left = {0u, 1u, false}, run_right = {0u, 1u, false};
    uint32_t run_lag = 0u;
    bool in_run = false, run_need_right = false, run_armed = false;
    /* Armed: a peak n > rearm was seen since the last run began (at the
       start: n(lag_min - 1) > threshold), so the next run is a real dip. */
    const uint32_t rearm = ssda_pitch_rearm_q15(thr);
    bool armed;
    /* The chosen lag. */
    uint32_t t_lag = 0u;
    lag_value_t t_left = {0u, 1u, false}, t_mid = {0u, 1u, false}, t_right = {0u, 1u, false};
    bool found = false;

    f.info = info;
    f.x = x;
    f.diffs = 0u;
    mean = ssda_pitch_mean(x, k);
    f.mean = mean;
    f.level = ssda_pitch_level(x, k, mean);
    /* silence_mad * K <= 65535 * 8192 < 2^30 */
    if (f.level < (uint32_t)info->silence_mad * k) {
        silent_estimate(est);
        return;
    }
    /* From here A >= K >= 16, so every s(lag) >= A > 0. */

    if (!full && SSDA_PITCH_HAS_TRACK(info->flags) &&
        predict_lag >= lag_min && predict_lag <= lag_max) {
        /* The seed's prediction: sum the predicted lag first, in full; its
           value becomes the best so far and tightens every later bound. */
        pred = predict_lag;
        pred_v = evaluate(&f, pred, f.level + ssda_pitch_level(x + pred, k, mean), NO_BOUND);
        best = pred_v;
        best_lag = pred;
    } else {
        pred_v = best;
    }

    /* lag_min - 1 is only a neighbour and the first arming test: needed
       exactly when n <= threshold. */
    b_sum = ssda_pitch_level(x + lag_min - 1u, k, mean);
    prev = evaluate(&f, lag_min - 1u, f.level + b_sum,
                    full ? NO_BOUND : threshold_bound(thr, f.level + b_sum));
    armed = !(prev.exact && n_at_most_q15(&prev, thr));

    for (lag = lag_min; lag <= lag_max + 1u; lag++) {
        const bool candidate = lag <= lag_max;
        uint32_t s;
        /* Slide B: drop x[lag - 1], add x[lag - 1 + K]. B stays <= K * 65535. */
        b_sum = b_sum - abs_dev(x[lag - 1u], mean) + abs_dev(x[lag - 1u + k], mean);
        s = f.level + b_sum;

        if (lag == pred) {
            cur = pred_v;
        } else {
            uint32_t bound = NO_BOUND;
            if (!full) {
                /* Exact when n <= threshold; when not armed, also exact up
                   to the re-arming level, so a cut proves n > rearm. */
                bound = threshold_bound(armed || !candidate ? thr : rearm, s);
                if (candidate) {
                    uint32_t bb;
                    if (best_lag == 0u) {
                        bound = NO_BOUND; /* first candidate: summed in full (Fig. 9) */
                    } else if (best_bound(&best, lag > best_lag, s, &bb) && bb > bound) {
                        bound = bb;
                    } else {
                        /* the threshold's bound is the tighter one */
                    }
                }
            }
            cur = evaluate(&f, lag, s, bound);
        }

        /* Neighbours wanted by the best lag and by the run minimum. */
        if (best_need_right) {
            best_right = cur;
            best_need_right = false;
        }
        if (run_need_right) {
            run_right = cur;
            run_need_right = false;
        }

        if (candidate && cur.exact) {
            bool better;
            if (best_lag == 0u) {
                better = true;
            } else if (lag > best_lag) {
                better = n_less(&cur, &best);
            } else {
                better = !n_less(&best, &cur); /* before best: ties win */
            }
            if (better && lag != best_lag) {
                best = cur;
                best_lag = lag;
                best_left = prev;
                best_need_right = true;
            } else if (lag == best_lag) {
                best_left = prev; /* the predicted lag, reached by the scan */
                best_need_right = true;
            } else {
                /* not better: the best lag stays */
            }
        }

        if (candidate && cur.exact && n_at_most_q15(&cur, thr)) {
            if (!in_run) {
                run_armed = armed; /* the run uses up the arming */
                armed = false;
            }
            if (!in_run || n_less(&cur, &run)) {
                run = cur;
                run_lag = lag;
                run_left = prev;
                run_need_right = true;
            }
            in_run = true;
        } else if (in_run) {
            /* The run ended at lag - 1. It is a dip if it was entered from a
               peak, and its minimum is not a lag_max that still falls. */
            bool valid = run_armed && (run_lag != lag_max || !n_less(&run_right, &run));
            in_run = false;
            if (valid && !found) {
                found = true;
                t_lag = run_lag;
                t_left = run_left;
                t_mid = run;
                t_right = run_right;
                if (!full) {
                    break; /* no later lag can change the choice */
                }
            }
        } else {
            /* outside a run, and still outside */
        }
        if (!in_run && !armed && candidate && !(cur.exact && n_at_most_q15(&cur, rearm))) {
            armed = true; /* n > rearm: exact, or cut at a bound >= rearm's */
        }
        prev = cur;
    }

    if (!found) {
        t_lag = best_lag;
        t_left = best_left;
        t_mid = best;
        t_right = best_right;
    }
    /* Interpolation needs both neighbours exactly. */
    make_exact(&f, t_lag - 1u, &t_left);
    make_exact(&f, t_lag + 1u, &t_right);
    period = period_q16_of(&f, t_lag, &t_left, &t_mid, &t_right);
    while (found && octave_up(&f, period, dip_floor_q20(&f, &t_left, &t_mid, &t_right),
                              &t_lag, &t_mid)) {
        t_left = value_at(&f, t_lag - 1u, NO_BOUND);
        t_right = value_at(&f, t_lag + 1u, NO_BOUND);
        period = period_q16_of(&f, t_lag, &t_left, &t_mid, &t_right);
    }
    est->lag = t_lag;
    est->period_q16 = period;
    est->f0_q16 = ssda_pitch_f0_q16(info->sample_rate_hz, est->period_q16);
    n_q15 = ssda_div64_32((uint64_t)t_mid.d << 15, t_mid.s); /* d <= s: 0..32768 */
    est->confidence_q15 = (uint16_t)(n_q15 >= 32767u ? 0u : 32767u - n_q15);
    est->voiced = found && n_at_most_q15(&t_mid, info->voicing_q15);
    est->dip = found;
    est->silent = false;
    est->diffs = f.diffs;
}
