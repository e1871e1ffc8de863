/*
 * pitch_search.c - choosing the lag of one frame: the first dip run of the
 * normalised AMDF under the threshold, else its global minimum, with SSDA
 * early exit that leaves the choice exactly as a full search makes it
 * (the rule and the argument are in include/ssda/pitch.h).
 */
#include "pitch_internal.h"
#include "fixmath.h"
#include "compiler.h"

#include <string.h>

#define NO_BOUND UINT32_MAX /* larger than any sum (K * 65535 < 2^29) */

/* The resolved parameters of the analysis: constants in a build with a
   fixed configuration (pitch_internal.h), so the compiler folds them. */
#define INFO(w) SSDA_PITCH_INFO_OF((w)->info)

/* One lag's value in 8 bytes (pitch.h): bits 0..30 of d hold d (< 2^30),
   exact when bit 31 (LAG_EXACT) is set, else a lower bound of d that is
   above the bound the lag was cut at. s = A + B(lag) > 0. */
typedef ssda_pitch_lag_value_t lag_value_t;

#define LAG_EXACT 0x80000000u

static uint32_t d_of(const lag_value_t *v)
{
    return v->d & ~LAG_EXACT;
}

static bool is_exact(const lag_value_t *v)
{
    return (v->d & LAG_EXACT) != 0u;
}

/* The frame under analysis and the scan's state: the caller's
   ssda_pitch_work_t (pitch.h). diffs: absolute differences so far. Lags
   summed: the scan and its extras <= lag_max - lag_min + 6 (< 4 810); the
   octave check <= 3 per multiple k P <= lag_max + 1 plus 2 per move, and a
   move takes P to at least 2 P - 1.5 (P >= 3.5: at most 12 moves, sum of
   1/P < 0.7), so it adds < 3 * 4 801 * 0.7 + 3 * 13 + 2 * 12 < 10 200.
   Under 15 010 lags of K <= 8192: < 2^27. */
typedef ssda_pitch_work_t frame_t;

/* A lag with its neighbours' values (pitch.h): v[0], v[1], v[2] at lag - 1,
   lag, lag + 1. */
typedef ssda_pitch_dip_t dip_t;

/* n(p) < n(q), exactly: d_p * s_q < d_q * s_p (products < 2^59). */
static bool n_less(const lag_value_t *p, const lag_value_t *q)
{
    return SSDA_MUL64(d_of(p), q->s) < SSDA_MUL64(d_of(q), p->s);
}

/* Largest d with d / s <= threshold: floor(q15 * s / 32768) < s, in 32
   bits (no 64-bit multiply on cores without one): with s = 32768 h + l,
   q15 * s / 32768 = q15 h + q15 l / 32768, where q15 h < 2^15 * 2^15 and
   q15 l < 2^30 (q15 <= 32767, s < 2^30). */
static SSDA_SIZE_NOINLINE uint32_t threshold_bound(uint32_t q15, uint32_t s)
{
    return q15 * (s >> 15) + ((q15 * (s & 0x7FFFu)) >> 15);
}

/* v exact and n <= q15 / 32768: 32768 d <= q15 s, i.e. d <= floor(q15 s /
   32768). A value that is not exact has bit 31 set in d ^ LAG_EXACT, above
   any bound (< s < 2^30). */
static SSDA_SIZE_NOINLINE bool at_most_q15(const lag_value_t *v, uint32_t q15)
{
    return (v->d ^ LAG_EXACT) <= threshold_bound(q15, v->s);
}

/* Largest d at scale s that still wins against best: n < n(best) for a lag
   after best's, n <= n(best) for one before it (ties go to the smaller lag).
   Returns false when no d >= 0 can win. The result is <= s < 2^30. */
static bool best_bound(const lag_value_t *best, bool after, uint32_t s, uint32_t *bound)
{
    uint64_t p = SSDA_MUL64(d_of(best), s); /* < 2^59 */
    if (after) {
        if (p == 0u) {
            return false;
        }
        p -= 1u;
    }
    *bound = SSDA_DIV64_32(p, best->s); /* <= s < 2^30 */
    return true;
}

/* Sum one lag into *v, cut above bound. Rejected at no cost when the lower
   bound |A - B(lag)| <= d(lag) is already above bound. Writes through v
   (no returned struct: each call site would keep a temporary on the
   stack). */
static void evaluate(frame_t *f, uint32_t lag, uint32_t s, uint32_t bound, lag_value_t *v)
{
    uint32_t b = s - f->level;
    uint32_t lower = f->level > b ? f->level - b : b - f->level;
    bool complete;
    v->s = s;
    if (lower > bound) {
        v->d = lower; /* not exact */
        return;
    }
    v->d = ssda__pitch_amdf_lag(f->x, INFO(f)->frame_len, lag, INFO(f)->chunk, bound,
                               &complete, &f->diffs);
    if (complete) {
        v->d |= LAG_EXACT;
    }
}

/* |x[i] - m| for the sliding sum B(lag) = sum_{i<K} |x[lag + i] - m|. */
static uint32_t abs_dev(int16_t x, int32_t mean)
{
    int32_t v = (int32_t)x - mean;
    return v < 0 ? (uint32_t)(-v) : (uint32_t)v;
}

/* The scale s(lag) = A + B(lag), B summed directly (callers pass it to
   evaluate(): no frame between theirs and evaluate's, for the stack). */
static uint32_t scale_at(const frame_t *f, uint32_t lag)
{
    return f->level + ssda__pitch_level(f->x + lag, INFO(f)->frame_len, f->mean);
}

/* nq = floor(2^20 d / s) of t's value v[i] (Q20), i = 0, 1, 2 for lag - 1,
   lag, lag + 1. */
static SSDA_SIZE_NOINLINE uint32_t nq_of(const dip_t *t, uint32_t i)
{
    return ssda__pitch_norm_q20(d_of(&t->v[i]), t->v[i].s);
}

/* Sub-sample period (Q16.16) of the dip through t's three exact values. */
static SSDA_NOINLINE uint32_t period_q16_of(const frame_t *f, const dip_t *t)
{
    int32_t delta = ssda__pitch_interp_q16(nq_of(t, 0u), nq_of(t, 1u), nq_of(t, 2u),
                                          SSDA_PITCH_HAS_PARABOLIC(INFO(f)->flags));
    /* lag <= 4800: 65536 * lag + delta < 2^29 */
    return (uint32_t)((int32_t)(t->lag << 16) + delta);
}

/* The interpolated minimum of the dip through t's three exact values a, b,
   c (Q20): b - |a - c| / 2 for the V fit, b - (a - c)^2 / (8 (a - 2b + c))
   for the parabola; >= 0. (Apart from the period, so that the below-range
   check's chain does not reach the interpolation: stack.) */
static SSDA_NOINLINE uint32_t dip_floor_q20(const frame_t *f, const dip_t *t)
{
    const uint32_t a = nq_of(t, 0u), b = nq_of(t, 1u), c = nq_of(t, 2u);
    const uint32_t diff = a > c ? a - c : c - a; /* <= 2^20 */
    uint32_t drop;
    if (SSDA_PITCH_HAS_PARABOLIC(INFO(f)->flags)) {
        /* |8 (a - 2b + c)| <= 2^24; (a - c)^2 <= 2^40; a saturated
           quotient (> b) gives 0 as the exact one would */
        int32_t den = 8 * ((int32_t)a - 2 * (int32_t)b + (int32_t)c);
        drop = den > 0 ? ssda__div64_32(SSDA_MUL64(diff, diff), (uint32_t)den) : 0u;
    } else {
        drop = diff / 2u;
    }
    return b > drop ? b - drop : 0u;
}

/* The octave margin in Q20: threshold / 3 as (t * 43691) >> 17, exact for
   every t < 2^16 (checked exhaustively): cores without a divide
   instruction would call the runtime's division routine for a constant 3. */
static uint32_t margin_q20_of(const ssda_pitch_info_t *info)
{
    return (((uint32_t)info->threshold_q15 * 43691u) >> 17) << 5;
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
 * Returns the lag it moves to, its value in f->at[0], or 0 when it stays.
 */
static SSDA_NOINLINE uint32_t octave_up(frame_t *f, uint32_t period_q16, uint32_t floor_q20)
{
    const uint32_t margin_q20 = margin_q20_of(INFO(f));
    const bool full = SSDA_PITCH_HAS_FULL(INFO(f)->flags);
    uint32_t k, limit;
    if (floor_q20 <= margin_q20) {
        return 0u; /* nothing can be deeper by the margin */
    }
    limit = floor_q20 - margin_q20; /* wanted: nq < limit */
    k = 2u;
    for (;;) { /* multiples k of the period until k * period passes lag_max */
        /* k * period_q16 <= 1200 * 2^29 < 2^40 */
        uint32_t c = (uint32_t)((SSDA_MUL64(k, period_q16) + 32768u) >> 16);
        uint32_t lag, found_lag = 0u;
        /* the best of the three in f->at[0], each lag in f->at[1]: the
           scan's values are unused by now (kept off the stack) */
        lag_value_t *found_v = &f->at[0];
        lag_value_t *v = &f->at[1];
        if (c - 1u > INFO(f)->lag_max) {
            return 0u;
        }
        for (lag = c - 1u; lag <= c + 1u && lag <= INFO(f)->lag_max; lag++) {
            uint32_t s = scale_at(f, lag);
            /* largest d with floor(2^20 d / s) < limit; limit * s < 2^50 */
            uint32_t bound = (uint32_t)((SSDA_MUL64(limit, s) - 1u) >> 20);
            evaluate(f, lag, s, full ? NO_BOUND : bound, v);
            if (is_exact(v) && (found_lag == 0u || n_less(v, found_v))) {
                found_lag = lag;
                *found_v = *v;
            }
        }
        if (found_lag != 0u && ssda__pitch_norm_q20(d_of(found_v), found_v->s) < limit) {
            return found_lag;
        }
        k++;
    }
}

/*
 * Below-range check (see pitch.h, step 6): a tone above f0_max has its
 * first dip in range at a multiple P of its period (1 500 Hz read 750 Hz).
 * True (unvoiced) when P itself is below lag_min - 1/2. When P < 2 lag_min,
 * look at each sub-period P / k (k >= 2) below lag_min and at least 3
 * samples: lags c - 2 .. c + 2 around c = round(P / k),
 * summed in full; if the interpolated floor at a local minimum among
 * c - 1 .. c + 1 is within half the octave margin of F (nq_floor <= F +
 * margin / 2), the period is shorter than the range allows and the frame
 * is unvoiced. Uses the scan's best lag as scratch (unused by now).
 */
static SSDA_NOINLINE bool below_range(frame_t *f, uint32_t period_q16, uint32_t floor_q20)
{
    const ssda_pitch_info_t *info = INFO(f);
    const uint32_t limit = floor_q20 + margin_q20_of(info) / 2u; /* < 2^21 */
    dip_t *u = &f->best;
    uint32_t k = 2u;
    if (period_q16 + 32768u < info->lag_min << 16) {
        return true; /* the dip itself is more than half a lag below the range */
    }
    if (period_q16 >= (2u * info->lag_min) << 16) { /* lag_min <= 4800: < 2^30 */
        return false; /* every sub-period is in range: the scan saw it */
    }
    for (;;) { /* k = 2, 3, ... while round(P / k) >= 3 */
        /* round(P / k): P < 2 lag_min <= 9600 samples, Q16 < 2^30 */
        const uint32_t c = SSDA_DIV32(period_q16 + (k << 15), k << 16);
        uint32_t lag;
        k++;
        if (c < 3u) {
            return false;
        }
        if (c >= info->lag_min || (uint64_t)period_q16 >= SSDA_MUL64(k - 1u, info->lag_min << 16)) {
            continue; /* P / k in range: a dip there would have been found */
        }
        for (lag = c - 2u; lag <= c + 2u; lag++) {
            u->v[0] = u->v[1];
            u->v[1] = u->v[2];
            evaluate(f, lag, scale_at(f, lag), NO_BOUND, &u->v[2]);
            if (lag >= c && !n_less(&u->v[0], &u->v[1]) && !n_less(&u->v[2], &u->v[1]) &&
                dip_floor_q20(f, u) <= limit) {
                return true;
            }
        }
    }
}

static void silent_estimate(ssda_pitch_estimate_t *est)
{
    /* every field 0 (the caller sets frame and center after), silent set */
    (void)memset(est, 0, sizeof *est);
    est->silent = true;
}

/*
 * The chosen lag refined: exact neighbours, the sub-sample period,
 * the octave check when it is a dip (found; unless SSDA_PITCH_NO_OCTAVE),
 * and the estimate (with the below-range check unless
 * SSDA_PITCH_NO_BELOW_RANGE). Kept out of
 * ssda__pitch_analyze_in (noinline, called last): the scan's locals are off
 * the stack while the octave check sums its lags.
 */
static SSDA_NOINLINE void refine(ssda_pitch_work_t *w, bool found, ssda_pitch_estimate_t *est)
{
    const ssda_pitch_info_t *info = INFO(w);
    /* the chosen lag: the first dip (a copy when the scan went on: full
       search), else the global minimum */
    dip_t *const t = !found ? &w->best : (SSDA_PITCH_HAS_FULL(info->flags) ? &w->t : &w->run);
    uint32_t period, n_q15, i;
    uint32_t floor_q20 = 0u; /* F: read by the checks of steps 4 and 6 only */
    est->dip = found; /* read back below: one register less across the calls */
    uint32_t moved = 0u; /* the lag an octave move went to, 0 before any */
    for (;;) {
        /* Interpolation needs both neighbours exactly: re-summed in full
           when cut (the scale kept), summed anew after an octave move. */
        for (i = 0u; i < 3u; i += 2u) {
            lag_value_t *v = &t->v[i];
            const uint32_t lag = t->lag - 1u + i;
            if (moved != 0u) {
                v->s = scale_at(w, lag);
            }
            if (moved != 0u || !is_exact(v)) {
                evaluate(w, lag, v->s, NO_BOUND, v);
            }
        }
        period = period_q16_of(w, t);
        if (SSDA_PITCH_NEEDS_FLOOR(info->flags)) {
            floor_q20 = dip_floor_q20(w, t);
        }
        moved = (est->dip && SSDA_PITCH_HAS_OCTAVE(info->flags)) ? octave_up(w, period, floor_q20)
                                                                  : 0u;
        if (moved == 0u) {
            break;
        }
        t->lag = moved;
        t->v[1] = w->at[0];
    }
    est->lag = t->lag;
    est->period_q16 = period;
    est->f0_q16 = ssda__pitch_f0_q16(info->sample_rate_hz, period);
    n_q15 = ssda__div64_32((uint64_t)d_of(&t->v[1]) << 15, t->v[1].s); /* d <= s: 0..32768 */
    est->confidence_q15 = (uint16_t)(n_q15 >= 32767u ? 0u : 32767u - n_q15);
    est->voiced = est->dip && at_most_q15(&t->v[1], info->voicing_q15) &&
                  !(SSDA_PITCH_HAS_BELOW_RANGE(info->flags) && below_range(w, period, floor_q20));
    est->silent = false;
    est->diffs = w->diffs;
}

/*
 * Before the scan: the predicted lag (SSDA_PITCH_TRACK: the seed's
 * prediction, summed first, in full; its value becomes the best so far and
 * tightens every later bound), then lag_min - 1 (into w->at[0]) and the
 * first arming test. Returns the predicted lag (0: none) and B(lag_min - 1)
 * in *b_sum.
 */
static SSDA_ALWAYS_INLINE uint32_t scan_start(ssda_pitch_work_t *w, uint32_t predict_lag,
                                              uint32_t rearm, uint32_t *b_sum, bool *armed)
{
    const ssda_pitch_info_t *info = INFO(w);
    const bool full = SSDA_PITCH_HAS_FULL(info->flags);
    const uint32_t thr = info->threshold_q15;
    uint32_t pred = 0u, s;
    if (!full && SSDA_PITCH_HAS_TRACK(info->flags) &&
        predict_lag >= info->lag_min && predict_lag <= info->lag_max) {
        pred = predict_lag;
        evaluate(w, pred, scale_at(w, pred), NO_BOUND, &w->pred);
        w->best.v[1] = w->pred;
        w->best.lag = pred;
    }
    /* lag_min - 1 is only a neighbour and the first arming test: needed
       exactly when n <= threshold. */
    s = scale_at(w, info->lag_min - 1u);
    *b_sum = s - w->level;
    evaluate(w, info->lag_min - 1u, s, full ? NO_BOUND : threshold_bound(thr, s), &w->at[0]);
    *armed = !at_most_q15(&w->at[0], thr);
    if (!*armed) {
        /* lag_min - 1 lies in a dip already: a period just above lag_min
           (f0 just below f0_max), or the lag-0 tail of a slow signal. The
           first has its half-period peak near lag_min / 2, the second stays
           low there. Exact up to rearm; a cut proves n > rearm. */
        const uint32_t half = info->lag_min / 2u; /* >= 2 */
        const uint32_t sh = scale_at(w, half);
        evaluate(w, half, sh, full ? NO_BOUND : threshold_bound(rearm, sh), &w->at[1]);
        *armed = !at_most_q15(&w->at[1], rearm);
    }
    return pred;
}

/* The bound lag is cut at (s: its scale): exact when n <= threshold; when
   not armed, also exact up to the re-arming level, so a cut proves
   n > rearm; for a candidate also whatever still beats the best lag (the
   seed's automatic threshold, Fig. 9; the first candidate in full). */
static SSDA_ALWAYS_INLINE uint32_t lag_bound(const ssda_pitch_work_t *w, uint32_t lag,
                                             uint32_t s, bool candidate, bool armed,
                                             uint32_t rearm)
{
    uint32_t bound = threshold_bound(armed || !candidate ? INFO(w)->threshold_q15 : rearm, s);
    if (candidate) {
        uint32_t bb;
        if (w->best.lag == 0u) {
            bound = NO_BOUND;
        } else if (best_bound(&w->best.v[1], lag > w->best.lag, s, &bb) && bb > bound) {
            bound = bb;
        } else {
            /* the threshold's bound is the tighter one */
        }
    }
    return bound;
}

/* An exact candidate w->at[1] at lag: the new best lag (the global-minimum
   fallback), with its left neighbour, if it beats it by the tie rule
   (smaller n, then smaller lag), or if it is the best lag (the predicted
   lag reached by the scan: its value is already the best's). */
static SSDA_ALWAYS_INLINE void note_best(ssda_pitch_work_t *w, uint32_t lag)
{
    const lag_value_t *cur = &w->at[1];
    const lag_value_t *best = &w->best.v[1];
    if (lag == w->best.lag || w->best.lag == 0u ||
        (lag > w->best.lag ? n_less(cur, best) : !n_less(best, cur))) {
        (void)memcpy(w->best.v, w->at, sizeof w->at);
        w->best.lag = lag;
    }
}

/* The run ended at lag - 1. It is a dip if it was entered from a peak,
   and its minimum is neither a lag_max that still falls (a period beyond
   lag_max) nor a lag_min below which it still falls (the tail of a dip
   below lag_min, e.g. a strong 2nd harmonic's, which may now arm: its
   multiple follows). Returns whether it is. */
static SSDA_ALWAYS_INLINE bool run_is_dip(const ssda_pitch_work_t *w, bool run_armed)
{
    const dip_t *r = &w->run;
    /* the outer neighbour of a minimum at an end of the range (lag_min <
       lag_max always), else the minimum itself (never below itself) */
    uint32_t side = 1u;
    if (r->lag == INFO(w)->lag_max) {
        side = 2u;
    } else if (r->lag == INFO(w)->lag_min) {
        side = 0u;
    } else {
        /* inside the range: no side to test */
    }
    return run_armed && !n_less(&r->v[side], &r->v[1]);
}

/*
 * The scan over lag_min - 1 .. lag_max + 1 of a frame that is not silent
 * (w set up by ssda__pitch_analyze_in): the first valid dip run's minimum in
 * w->run, or w->t when the scan goes on (full search) (returns true),
 * else the global minimum in w->best (false). In *w: the best
 * lag so far (the global-minimum fallback) and the open run under the
 * threshold (its minimum), each with its neighbours; the predicted lag's
 * value; the chosen lag (t). Out of line, so that its locals are gone
 * when refine() runs.
 */
static SSDA_NOINLINE bool scan_lags(ssda_pitch_work_t *w, uint32_t predict_lag)
{
    const ssda_pitch_info_t *info = INFO(w);
    const int16_t *x = w->x;
    const uint32_t k = info->frame_len;
    const uint32_t lag_max = info->lag_max;
    const bool full = SSDA_PITCH_HAS_FULL(info->flags);
    const uint32_t thr = info->threshold_q15;
    const int32_t mean = w->mean;
    const uint32_t rearm = ssda__pitch_rearm_q15(thr);
    lag_value_t *const cur = &w->at[1];
    /* Armed: a peak n > rearm was seen since the last run began (at the
       start: n(lag_min - 1) > threshold, or n(lag_min / 2) > rearm), so
       the next run is a real dip. */
    bool armed;
    bool in_run = false, run_armed = false, found = false;
    uint32_t b_sum, lag;
    const uint32_t pred = scan_start(w, predict_lag, rearm, &b_sum, &armed);

    for (lag = info->lag_min; lag <= lag_max + 1u; lag++) {
        const bool candidate = lag <= lag_max;
        uint32_t s;
        /* Slide B: drop x[lag - 1], add x[lag - 1 + K]. B stays <= K * 65535. */
        b_sum = b_sum - abs_dev(x[lag - 1u], mean) + abs_dev(x[lag - 1u + k], mean);
        s = w->level + b_sum;
        if (lag == pred && SSDA_PITCH_HAS_TRACK(info->flags)) {
            *cur = w->pred;
        } else {
            evaluate(w, lag, s, full ? NO_BOUND : lag_bound(w, lag, s, candidate, armed, rearm),
                     cur);
        }
        /* Right neighbours of the best lag and of the run minimum: the lag
           after theirs (lag_min - 1 and 0 are never theirs). */
        if (w->best.lag + 1u == lag) {
            w->best.v[2] = *cur;
        }
        if (w->run.lag + 1u == lag) {
            w->run.v[2] = *cur;
        }
        if (candidate && is_exact(cur)) {
            note_best(w, lag);
        }
        if (candidate && at_most_q15(cur, thr)) {
            if (!in_run) {
                run_armed = armed; /* the run uses up the arming */
                armed = false;
            }
            if (!in_run || n_less(cur, &w->run.v[1])) {
                (void)memcpy(w->run.v, w->at, sizeof w->at);
                w->run.lag = lag;
            }
            in_run = true;
        } else if (in_run) {
            in_run = false;
            if (!found && run_is_dip(w, run_armed)) {
                found = true;
                if (!full) {
                    break; /* no later lag can change the choice: w->run stays */
                }
                w->t = w->run; /* the scan goes on and may open other runs */
            }
        } else {
            /* outside a run, and still outside */
        }
        if (!in_run && candidate && !at_most_q15(cur, rearm)) {
            armed = true; /* n > rearm: exact, or cut at a bound >= rearm's */
        }
        w->at[0] = *cur;
    }
    return found;
}

void ssda__pitch_analyze_in(ssda_pitch_work_t *w, const ssda_pitch_info_t *info,
                           const int16_t *x, uint32_t predict_lag, ssda_pitch_estimate_t *est)
{
    const uint32_t k = SSDA_PITCH_INFO_OF(info)->frame_len;
    int32_t mean;

    w->info = info;
    w->x = x;
    w->diffs = 0u;
    mean = ssda__pitch_mean(x, k);
    w->mean = mean;
    w->level = ssda__pitch_level(x, k, mean);
    /* silence_mad * K <= 65535 * 8192 < 2^30 */
    if (w->level < (uint32_t)INFO(w)->silence_mad * k) {
        silent_estimate(est);
        return;
    }
    /* From here A >= K >= 16, so every s(lag) >= A > 0. No best lag and no
       run yet (lag 0); the lag values are written before they are read:
       the scan's first candidate, lag_min, is summed in full and becomes
       the best (with its left neighbour, and its right one at the next
       lag, which the scan always reaches); a run's values are written when
       it opens. */
    w->best.lag = 0u;
    w->run.lag = 0u;

    refine(w, scan_lags(w, predict_lag), est);
}

void ssda__pitch_analyze(const ssda_pitch_info_t *info, const int16_t *x,
                        uint32_t predict_lag, ssda_pitch_estimate_t *est)
{
    ssda_pitch_work_t w;
    /* zeroed: every result depends only on values the analysis wrote,
       but it moves some scratch values before writing them (the below-
       range check's window), and those are then not indeterminate */
    (void)memset(&w, 0, sizeof w);
    ssda__pitch_analyze_in(&w, info, x, predict_lag, est);
}
