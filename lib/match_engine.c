/*
 * match_engine.c - the SSDA search over row sources: threshold modes, scan
 * strategies, row orders and successive-elimination bounds.
 *
 * One position is evaluated by eval_position(): rows are summed in the
 * configured order with the compiled SAD kernel, and after each row the
 * partial SAD plus the bound of the rows still to sum is compared with the
 * cut level. Scans only decide the order of positions and what the current
 * position has to beat (the reference key).
 */
#include "match_rows.h"
#include "match_quality.h"
#include "match_pre.h"
#include "kernel/kernels.h"
#include "kernel/portable.h"
#include "fixmath.h"
#include "compiler.h"
#include <string.h>

/* 1 when the compiled kernel set's tracking loops (ssda__sad_rows_u16,
   ssda__refine4, ssda__bounds4, kernels.h) are worth their call: the x86
   set's SIMD. Elsewhere the engine runs the same loops inline (portable.h,
   or its own row loop): on the Cortex-M4 a call per loop cost more than it
   saved, and the paths around them cost every bounded search instructions
   and stack (tools/budget.sh, issue 18 session 7). */
#if defined(SSDA_KERNEL_sse2)
#define KERNEL_LOOPS 1
#else
#define KERNEL_LOOPS 0
#endif

/* A candidate ordered by the tie rule: (sad, y, x) lexicographically, or
   (sad, distance to the prediction, y, x) with SSDA_MATCH_TIE_NEAREST. */
typedef ssda__cand_t cand_t;

/* Features compiled in (include/ssda/config.h). */
#if !defined(SSDA_CFG_NO_FIXED) || !defined(SSDA_CFG_NO_RAMP)
#define ENGINE_FALLBACK 1 /* the all-cut fallback of FIXED and RAMP */
#endif

/* The search state, kept small: it lives on the caller's stack under the
   deepest call chain (scan > consider > block_bound). Fields by size, the
   smallest first, so that none pads and the narrow ones stay within the
   short load offsets of Thumb-1 (the Cortex-M0+). */
typedef struct {
    uint16_t L, M;       /* window width and height */
    uint16_t nx, ny;     /* positions per row and per column */
    uint16_t tx, ty;     /* the predicted position clamped into the range */
    uint16_t row_step;   /* row order: r -> r + row_step (mod M) (plan's) */
#ifndef SSDA_CFG_NO_BOUNDS
    uint16_t group;      /* bounds: rows per group (1..4; blocks: M >> level) */
    uint16_t ngroups;    /* bounds: floor(M / group) groups carry a bound term */
    uint16_t gpitch;     /* bounds: entries between rows of gsum (nx, or the
                            shared tables' pitch <= FIRST's width) */
    uint8_t lev_lo, lev_hi; /* blocks: levels lev_lo..lev_hi in use; none when
                               lev_lo > lev_hi */
#endif
#ifndef SSDA_CFG_NO_UNIQUE
    uint8_t nlist, cap;  /* entries in list, its capacity (2R+1)^2 + 1 <= 26 */
#endif
    uint8_t n_best;      /* 0, 1 or 2 valid entries */
    bool u8;             /* 8-bit samples (else 16-bit) */
    /* the plan's flags the per-position path tests, copied at the start
       (one load from the engine, not two through the plan) */
    bool use_ref;        /* positions are cut once they cannot beat ref */
    bool bounds;         /* successive elimination active */
    bool ramp_mode;      /* RAMP or AUTO_RAMP */
    bool tie_near;       /* SSDA_MATCH_TIE_NEAREST */
#ifndef SSDA_CFG_NO_FAST_PATH
    bool fast;           /* positions are evaluated by eval_fast (see there) */
    bool plain_ref;      /* use_ref, no uniqueness list, no TIE_NEAREST */
#ifndef SSDA_CFG_NO_BOUNDS
    bool pre_scan;       /* blocks with no level, AUTO raster: scan_pre */
#endif
#endif
#ifdef ENGINE_FALLBACK
    bool need_fb;        /* FIXED or RAMP: the all-cut fallback may be needed */
    bool have_fb;
#endif
    const ssda__rows_t *area;
    const ssda__rows_t *win;
    const ssda_match_plan_t *plan; /* the resolved options (match_rows.h) */
    const cand_t *ref;   /* what the current position must beat; NULL: nothing */
    cand_t *list;        /* SSDA_MATCH_UNIQUE: the smallest completed positions */
    uint32_t positions;  /* evaluations; raster/predict <= 65535^2 < 2^32 */
    uint32_t completed;
#ifdef ENGINE_FALLBACK
    uint32_t fb_pixels;  /* <= L * M <= 65535^2 < 2^32 */
#endif
#ifndef SSDA_CFG_NO_BOUNDS
    const uint32_t *gsum; /* bounds: area sums over L x group pixels, nx per area
                            row; <= 4 * 16384 * 65535 < 2^32 (see build_bounds) */
    uint32_t *wgrp;      /* bounds: window sums per group, same range */
    uint32_t *term;      /* bounds: group terms of the current position */
    uint32_t nbound;     /* bounds: group_bound32 calls, ngroups ops each
                            (<= positions < 2^32), added to ops by finish */
    const uint32_t *integ; /* blocks: the area's integral image, (aw+1) x (ah+1),
                              modulo 2^32 (block_bound); shared tables (no block
                              levels then): their 4 x 4 sums when tab_refine
                              is on, else NULL */
    uint32_t *wblk;        /* blocks: the window's block sums, level after level;
                              shared tables: the window's 4 x 4 sums */
    const uint32_t *pre; /* fast path, AUTO, no uniqueness list: every position's
                            group bound, nx per row, else NULL. Made by
                            pre_bounds from tracking's shared tables (in the
                            per-window group table's place) or by scan_pre's
                            pre_pass (in the blocks' room) */
    uint32_t *low;       /* blocks, AUTO raster: each position's coarsest-level
                            bound, saturated to 32 bits (a lower bound still),
                            nx per row in the group tables' place; else NULL */
#endif
    cand_t best, second; /* best two completed, by the tie rule */
#ifdef ENGINE_FALLBACK
    cand_t fb;           /* all-cut fallback: most pixels before its cut; its
                            sad is the lower bound known at the cut */
#endif
    uint64_t loose;      /* SSDA_MATCH_UNIQUE: cut level, floor(ratio * best) + 1 */
    uint64_t ops;        /* pixel operations; < 2^64 for any accepted size */
} engine_t;

static uint32_t clamp_pos(int32_t v, uint32_t n)
{
    if (v < 0) {
        return 0u;
    }
    return (uint32_t)v >= n ? n - 1u : (uint32_t)v;
}

/* Squared distance of (x, y) to the prediction clamped into the range:
   < 2 * 2^32 (clamped here: ties are rare, the engine stays small). */
static SSDA_ALWAYS_INLINE uint64_t dist2(const engine_t *e, uint32_t x, uint32_t y)
{
    const uint32_t tx = e->tx, ty = e->ty;
    const uint32_t dx = x > tx ? x - tx : tx - x; /* < 2^16 */
    const uint32_t dy = y > ty ? y - ty : ty - y;
    const uint32_t sx = dx * dx; /* < 2^32: no 64-bit multiply on the M0+ */
    const uint32_t sy = dy * dy;
    return (uint64_t)sx + sy;
}

/* (ax, ay) before (bx, by) by the tie rule, SADs aside: nearer to the
   prediction (SSDA_MATCH_TIE_NEAREST), then smaller y, then smaller x. */
static SSDA_ALWAYS_INLINE bool pos_before(const engine_t *e, uint32_t ax, uint32_t ay,
                                          uint32_t bx, uint32_t by)
{
    if (e->tie_near) {
        const uint64_t da = dist2(e, ax, ay);
        const uint64_t db = dist2(e, bx, by);
        if (da != db) {
            return da < db;
        }
    }
    return ay < by || (ay == by && ax < bx);
}

static bool cand_less(const engine_t *e, const cand_t *a, const cand_t *b)
{
    /* The analyzer takes a fetch returning > 0 (match_rows.h: 0 or < 0) as
       a completed position with its sum unset. */
    if (a->sad != b->sad) { /* NOLINT(clang-analyzer-core.UndefinedBinaryOperatorResult) */
        return a->sad < b->sad;
    }
    return pos_before(e, a->x, a->y, b->x, b->y);
}

#ifndef SSDA_CFG_NO_RAMP
/* sqrt(r) * (r + K sqrt(r)) helper: f(r) = r + K*sqrt(r) in Q16, r < 2^32.
   r * 2^16 < 2^48, K_q8 * sqrt_q8 < 2^16 * 2^24: sum < 2^49. */
static uint64_t ramp_f_q16(const engine_t *e, uint64_t r)
{
    uint64_t sqrt_q8 = ssda__isqrt64(r << 16);
    return (r << 16) + (uint64_t)e->plan->k_q8 * sqrt_q8;
}

/* Threshold of the ramp modes after r pixels (only called when the partial
   sum exceeds the ramp's linear part, which bounds it from below). */
static uint64_t ramp_threshold(const engine_t *e, uint64_t r)
{
    uint64_t f = ramp_f_q16(e, r);
    const uint64_t lm = (uint64_t)e->L * e->M; /* < 2^32 */
    uint64_t t;
    uint32_t frac;
    if (e->plan->threshold == (uint8_t)SSDA_THRESHOLD_RAMP) {
        /* eq. 3: lambda * f(r); lambda Q24.8 times f Q16 -> shift 24 */
        return ssda__mul_shr24(e->plan->lambda_q8, f);
    }
    /* eq. 4: min(T_i, T_i * f(r) / (L*M)) with frac = f / (L*M) in Q16: it
       reaches 1.0 (65536) exactly when f >= L*M * 2^16 (< 2^48); below, the
       quotient is < 2^16, a 64-by-32 division (no 64-bit runtime division on
       cores without a divide instruction; same value everywhere) */
    t = e->best.sad;
    if (f >= (lm << 16)) {
        return t;
    }
    frac = SSDA_DIV64_32(f, (uint32_t)lm);
    /* (t >> 16) * frac < 2^32 * 2^16; (t & 0xFFFF) * frac < 2^32 */
    return (t >> 16) * frac + (((t & 0xFFFFu) * frac) >> 16);
}

/* Lower bound of the ramp after r pixels: its linear part. */
static uint64_t ramp_linear(const engine_t *e, uint64_t r)
{
    if (e->plan->threshold == (uint8_t)SSDA_THRESHOLD_RAMP) {
        return ((uint64_t)e->plan->lambda_q8 * r) >> 8; /* < 2^32 * 2^32 */
    }
    /* floor(t / LM) * r: a completed SAD t <= 65535 * LM, so the quotient
       <= 65535 (a 64-by-32 division, as above) and the product < 2^48 */
    return (uint64_t)SSDA_DIV64_32(e->best.sad, (uint32_t)((uint64_t)e->L * e->M)) * r;
}

/* The ramp cut after `pixels` pixels (kept out of line: a cold path for the
   exact modes, and its 64-bit temporaries stay off eval_position's frame). */
static SSDA_NOINLINE bool ramp_cuts(const engine_t *e, uint64_t v, uint32_t pixels)
{
    return v > ramp_linear(e, pixels) && v > ramp_threshold(e, pixels);
}
#endif

/* Pixels per early-exit test on a placement's first row (a multiple of the
   SIMD widths: 16 bytes of u8, 8 of u16). */
#define SSDA_FIRST_ROW_CHUNK 8u

static uint32_t row_sad(const engine_t *e, const uint8_t *a, const uint8_t *w, uint32_t n)
{
#ifndef SSDA_CFG_NO_U16
    if (!e->u8) {
        return ssda__sad_row_u16((const uint16_t *)(const void *)a,
                                (const uint16_t *)(const void *)w, n);
    }
#else
    (void)e;
#endif
    return ssda__sad_row_u8(a, w, n);
}

#ifdef ENGINE_FALLBACK
/* A position cut after `pixels` pixels, with `low` the lower bound of its
   SAD known at the cut (partial SAD plus the bound of the rows not summed;
   the bound alone for a position rejected before any pixel): keep it if it
   is the fallback so far (most pixels, then the smallest lower bound, then
   the tie rule). A position rejected by its bound counts 0 pixels, so it
   wins only when every position was rejected so (issue 14). */
static void note_cut(engine_t *e, uint32_t x, uint32_t y, uint64_t low, uint32_t pixels)
{
    if (!e->need_fb) {
        return; /* a mode whose first placement always completes */
    }
    if (e->have_fb && pixels == e->fb_pixels) {
        cand_t c;
        c.sad = low;
        c.x = x;
        c.y = y;
        if (!cand_less(e, &c, &e->fb)) {
            return;
        }
    } else if (e->have_fb && pixels < e->fb_pixels) {
        return;
    } else {
        /* the first cut, or one that went further: it becomes the fallback */
    }
    e->fb.sad = low;
    e->fb.x = x;
    e->fb.y = y;
    e->fb_pixels = pixels;
    e->have_fb = true;
}
#define NOTE_CUT(e, x, y, low, pixels) note_cut(e, x, y, low, pixels)
#else
#define NOTE_CUT(e, x, y, low, pixels) ((void)0)
#endif

#ifndef SSDA_CFG_NO_BOUNDS
/* Bound of position (x, y) from its group sums: sum over groups of
   |area group sum - window group sum| <= SAD; <= 65535^3. The terms are kept
   in e->term for the row loop. */
static uint64_t group_bound(engine_t *e, uint32_t x, uint32_t y)
{
    const uint32_t *g = e->gsum + (size_t)y * e->gpitch + x;
    const size_t down = (size_t)e->group * e->gpitch;
    uint64_t rest = 0u;
    uint32_t k;
    for (k = 0u; k < e->ngroups; k++) {
        uint32_t a = g[k * down];
        uint32_t b = e->wgrp[k];
        uint32_t d = a > b ? a - b : b - a;
        e->term[k] = d;
        rest += d;
    }
    e->ops += e->ngroups;
    return rest;
}

/* Tracking's shared tables with 4 x 4 block sums (match_rows.h): a
   position that passed its group bound gets, group after group, the sum of
   its L / 4 block terms |area block sum - window block sum| in place of the
   group's term (never smaller: the triangle inequality, block by block),
   until the bound reaches cut_at. Gao's successive elimination at 4 x 4
   blocks, one lookup per term: cheap because the tables are shared by the
   windows of a grid. A block sum <= 16 * 65535 < 2^20, a group's terms
   <= 256 of them < 2^28 (L <= 1024); the bound stays <= the position's
   SAD. One op per term. */
static uint64_t tab_refine(engine_t *e, uint32_t x, uint32_t y, uint64_t rest, uint64_t cut_at)
{
    const uint32_t nb = (uint32_t)e->L >> 2, pitch = e->gpitch;
    const uint32_t down = 4u * pitch; /* <= 4 * 65535 */
    const uint32_t *b = e->integ + (size_t)y * pitch + x;
    const uint32_t *w = e->wblk;
    uint32_t k, i;
    for (k = 0u; k < e->ngroups; k++) {
        uint32_t s = 0u; /* < 2^28 */
        /* block sums < 2^20: signed differences, no compare and branch */
        if (nb == 4u) { /* 16 to 19 columns: no loop */
            const int32_t d0 = (int32_t)b[0] - (int32_t)w[0], d1 = (int32_t)b[4] - (int32_t)w[1];
            const int32_t d2 = (int32_t)b[8] - (int32_t)w[2], d3 = (int32_t)b[12] - (int32_t)w[3];
            s = (uint32_t)(d0 < 0 ? -d0 : d0) + (uint32_t)(d1 < 0 ? -d1 : d1) +
                (uint32_t)(d2 < 0 ? -d2 : d2) + (uint32_t)(d3 < 0 ? -d3 : d3);
        } else {
            for (i = 0u; i < nb; i++) {
                const int32_t d = (int32_t)b[(size_t)4u * i] - (int32_t)w[i];
                s += (uint32_t)(d < 0 ? -d : d);
            }
        }
        rest = rest - e->term[k] + s; /* s >= term[k] */
        e->term[k] = s;
        b += down;
        w += nb;
        if (rest >= cut_at) {
            const uint32_t terms = (k + 1u) * nb; /* <= M * L / 16 */
            e->ops += terms;
            return rest;
        }
    }
    {
        const uint32_t terms = (uint32_t)e->ngroups * nb;
        e->ops += terms;
    }
    return rest;
}
#endif

#ifndef SSDA_CFG_NO_BOUNDS
/* The smallest side of a block of the multilevel bound (SSDA_MATCH_BLOCKS):
   below it a term costs about as much as the absolute differences it spares
   (docs/benchmarks.md, issue 18). */
#define BLOCK_MIN_SIDE 16u

/* Bound of position (x, y) at block level l (match.h: SSDA_MATCH_BLOCKS):
   sum over the 2^l x 2^l blocks of bw x bh = (L >> l) x (M >> l) pixels of
   |area block sum - window block sum| <= SAD. A block sum is a difference of
   four integral-image entries modulo 2^32, exact since the level is used
   only when bw * bh * maxval < 2^32 (build_blocks). The bound <= 256 terms of
   < 2^32 each < 2^40. Stops after a row of blocks once the bound reaches
   cut_at (a lower bound still). One op per term. */
static uint64_t block_bound(engine_t *e, uint32_t l, uint32_t x, uint32_t y, uint64_t cut_at,
                            uint32_t *rows)
{
    const uint32_t nb = 1u << l;
    const uint32_t bw = (uint32_t)e->L >> l;
    const size_t is = (size_t)e->area->width + 1u;
    const size_t down = (size_t)(e->M >> l) * is;
    const uint32_t *w = e->wblk + (((1u << (2u * l)) - 4u) / 3u); /* after levels 1..l-1 */
    const uint32_t *r0 = e->integ + (size_t)y * is + x;
    uint64_t b = 0u;
    uint32_t i, j;
    for (j = 0u; j < nb; j++) {
        const uint32_t *r1 = r0 + down;
        uint64_t rb = 0u; /* this row of blocks: <= 16 terms < 2^32 */
        uint32_t left = r1[0] - r0[0]; /* column sums modulo 2^32 */
        const uint32_t *c0 = r0, *c1 = r1;
        for (i = 0u; i < nb; i++) {
            uint32_t right, s, t;
            c0 += bw;
            c1 += bw;
            right = *c1 - *c0;
            s = right - left; /* the block's sum, exact */
            t = w[i];
            rb += s > t ? s - t : t - s;
            left = right;
        }
        b += rb;
        w += nb;
        r0 = r1;
        if (rows != NULL) { /* the row of blocks' terms, saturated */
            rows[j] = rb > UINT32_MAX ? UINT32_MAX : (uint32_t)rb;
        }
        if (b >= cut_at) {
            const uint32_t terms = (j + 1u) * nb; /* <= 256 */
            e->ops += terms;
            return b;
        }
    }
    {
        const uint32_t terms = nb * nb; /* <= 256 */
        e->ops += terms;
    }
    return b;
}

/* Position (x, y) rejected by a block level, coarsest first: the bound in
   *low (for the fallback) and true; else false, and without row groups
   (the seeded raster scan) the last level's rows of blocks become the
   groups of the row loop: their terms (saturated to 32 bits) in e->term,
   their sum in *low, e->group rows each. */
static bool blocks_reject(engine_t *e, uint32_t x, uint32_t y, uint64_t cut_at, uint64_t *low)
{
    uint32_t *rows = e->bounds ? NULL : e->term;
    uint32_t l;
    for (l = e->lev_lo; l <= e->lev_hi; l++) {
        const uint64_t b = block_bound(e, l, x, y, cut_at, rows);
        if (b >= cut_at) {
            *low = b;
            return true;
        }
    }
    if (rows != NULL) {
        uint64_t rest = 0u; /* <= 16 terms < 2^32 each */
        uint32_t j;
        e->group = (uint16_t)(e->M >> e->lev_hi);
        e->ngroups = (uint16_t)(1u << e->lev_hi);
        for (j = 0u; j < e->ngroups; j++) {
            rest += rows[j];
        }
        *low = rest;
    }
    return false;
}
#endif

/* The level at which position (x, y) is cut (partial + rest >= it): the
   plan's fixed cut, lowered to what can still beat the reference. */
static SSDA_ALWAYS_INLINE uint64_t cut_level(const engine_t *e, uint32_t x, uint32_t y)
{
    uint64_t cut_at = e->plan->fixed_cut;
    if (e->use_ref && e->ref != NULL) {
        /* A position before ref by the tie rule wins a tie, so it needs
           sad <= ref. With uniqueness (ref is the best: raster or predict
           scan) every position within the ratio of the best completes. */
        const cand_t *ref = e->ref;
        uint64_t lim = e->list != NULL ? e->loose
                       : ref->sad + (pos_before(e, x, y, ref->x, ref->y) ? 1u : 0u);
        if (lim < cut_at) {
            cut_at = lim;
        }
    }
    return cut_at;
}

#ifndef SSDA_CFG_NO_BOUNDS
/* The rows of position (x, y) in the seeded raster scan (AUTO, row order,
   rows in memory): eval_position's loop without what this case does not
   need (fetches, the spread order, the ramp, the fallback, the first-row
   chunks), about 20 % less time on searches that sum many rows (camera.png,
   128 x 128; issue 18). rest is the bound of the last level's rows of
   blocks (groups of e->group rows, terms in e->term), or 0. Returns 1 and
   sets *sad, or 0 when cut. */
static int seeded_rows(engine_t *e, uint32_t x, uint32_t y, uint64_t cut_at, uint64_t rest,
                       uint64_t *sad)
{
    const size_t as = e->area->stride, ws = e->win->stride;
    const uint8_t *a0 = e->area->base + (size_t)y * as + (size_t)x * e->area->format;
    const uint8_t *w0 = e->win->base;
    const uint32_t L = e->L, M = e->M;
    const uint32_t pixels = L * M; /* <= 65535^2 */
    uint64_t partial = 0u;         /* <= 65535^3 */
    uint64_t left = rest;          /* the groups not started */
    uint32_t k = 0u, g = 0u;
    while (k < M) {
        uint32_t end = M;
        if (left != 0u) {
            /* group g starts: its term leaves the bound. left is the sum of
               term[g .. ngroups - 1], so left != 0 implies g < ngroups */
            left -= e->term[g];
            g++;
            end = k + e->group;
        }
        for (; k < end; k++) {
            partial += row_sad(e, a0 + (size_t)k * as, w0 + (size_t)k * ws, L);
            if (partial + left >= cut_at) {
                const uint32_t summed = (k + 1u) * L; /* <= 65535^2 */
                e->ops += summed;
                return 0;
            }
        }
    }
    e->ops += pixels;
    *sad = partial;
    return 1;
}
#endif

#ifndef SSDA_CFG_NO_FAST_PATH
#ifndef SSDA_CFG_NO_BOUNDS
/* group_bound in 32 bits, for eval_fast: the bound <= the window's largest
   SAD < 2^32 - 1 (triangle inequality), each term likewise; read from
   e->pre when every bound is known (pre_bounds, pre_pass). The terms are
   stored (a second pass) only when store is set and the position passes:
   most do not, and tab_refine4 takes the terms itself. */
static uint32_t group_bound32(engine_t *e, uint32_t x, uint32_t y, uint32_t cut_at, bool store)
{
    const uint32_t *g0 = e->gsum + (size_t)y * e->gpitch + x;
    const uint32_t *g = g0;
    const uint32_t down = (uint32_t)e->group * e->gpitch; /* < 2^32 */
    const uint32_t *w = e->wgrp;
    const uint32_t n = e->ngroups;
    uint32_t rest = 0u, k;
    e->nbound++; /* n ops each, added by finish */
    if (e->pre != NULL) { /* every bound known (pre_bounds) */
        rest = e->pre[(size_t)y * e->nx + x];
    } else if (n == 4u) { /* 16..19 rows, the seed's windows: no loop */
        const uint32_t a0 = g[0], a1 = g[down], a2 = g[(size_t)2u * down],
                       a3 = g[(size_t)3u * down];
        rest = (a0 > w[0] ? a0 - w[0] : w[0] - a0) + (a1 > w[1] ? a1 - w[1] : w[1] - a1) +
               (a2 > w[2] ? a2 - w[2] : w[2] - a2) + (a3 > w[3] ? a3 - w[3] : w[3] - a3);
    } else {
        for (k = 0u; k < n; k++) {
            const uint32_t a = *g, b = w[k];
            rest += a > b ? a - b : b - a;
            g += down;
        }
    }
    if (store && rest < cut_at) {
        uint32_t *t = e->term;
        g = g0;
        if (n == 4u) {
            const uint32_t a0 = g[0], a1 = g[down], a2 = g[(size_t)2u * down],
                           a3 = g[(size_t)3u * down];
            t[0] = a0 > w[0] ? a0 - w[0] : w[0] - a0;
            t[1] = a1 > w[1] ? a1 - w[1] : w[1] - a1;
            t[2] = a2 > w[2] ? a2 - w[2] : w[2] - a2;
            t[3] = a3 > w[3] ? a3 - w[3] : w[3] - a3;
        } else {
            for (k = 0u; k < n; k++) {
                const uint32_t a = *g, b = w[k];
                t[k] = a > b ? a - b : b - a;
                g += down;
            }
        }
    }
    return rest;
}

/* tab_refine for eval_fast with 4 groups of 4 blocks (16 x 16 windows:
   shared tables hold blocks only for widths that are multiples of 4; 16..19
   rows), in 32 bits (the bound <= the SAD < 2^32 - 1): the same terms,
   order, exits and count, in the kernels' ssda__refine4 (SSE2 on x86). The
   group terms are taken there, so group_bound32 need not store them. */
#if KERNEL_LOOPS
#define TAB_REFINE4_INLINE SSDA_ALWAYS_INLINE /* x86: the kernel's call only */
#else
#define TAB_REFINE4_INLINE SSDA_NOINLINE
#endif
static TAB_REFINE4_INLINE uint32_t tab_refine4(engine_t *e, uint32_t x, uint32_t y,
                                               uint32_t rest, uint32_t cut_at)
{
    const size_t at = (size_t)y * e->gpitch + x; /* b and g: one pitch */
    uint32_t groups;
#if KERNEL_LOOPS
    rest = ssda__refine4(e->integ + at, e->gsum + at, (size_t)4u * e->gpitch, e->wgrp, e->wblk,
                         rest, cut_at, e->term, &groups);
#else
    rest = ssda__portable_refine4(e->integ + at, e->gsum + at, (size_t)4u * e->gpitch, e->wgrp,
                                  e->wblk, rest, cut_at, e->term, &groups);
#endif
    e->ops += (uint64_t)4u * groups;
    return rest;
}
#endif

/* cut_level for eval_fast, in 32 bits: there fixed_cut is UINT64_MAX
   (FIXED is never fast) and a completed SAD < 2^32 - 1, so the level is
   at most 2^32 - 1; the uniqueness level saturates (a sum never reaches it).
   With SSDA_MATCH_TIE_NEAREST and a reference of SAD s >= 1 the level is s
   or s + 1 by the tie rule: with bounds, s + 1 is returned and *tie set,
   and eval_fast settles the rule only for a position whose bound leaves it
   open (the distances cost more than most positions' whole test; tracking
   always sets the flag). */
static SSDA_ALWAYS_INLINE uint32_t cut_level32(const engine_t *e, uint32_t x, uint32_t y,
                                               bool *tie)
{
    const cand_t *ref = e->ref;
    if (e->plain_ref && ref != NULL) { /* the usual case, tested first */
        return (uint32_t)ref->sad + ((y < ref->y || (y == ref->y && x < ref->x)) ? 1u : 0u);
    }
    if (!e->use_ref || ref == NULL) {
        return UINT32_MAX;
    }
    if (e->list != NULL) {
        return e->loose > UINT32_MAX ? UINT32_MAX : (uint32_t)e->loose;
    }
    if (e->bounds && ref->sad != 0u) {
        *tie = true;
        return (uint32_t)ref->sad + 1u;
    }
    return (uint32_t)ref->sad + (pos_before(e, x, y, ref->x, ref->y) ? 1u : 0u);
}

#if KERNEL_LOOPS
/* Rows of a position added to *partial, stopping after the first row where
   it reaches limit. Returns the rows added. 16-bit rows: the kernels' rows
   loop (a 16-px row in straight-line SSE2); 8-bit rows: a row a call, as
   their PSADBW rows cost less than the loop's call (ssda-peers-match,
   synthetic 32x32 in 64x64: 6.1 -> 6.6 us a window through the kernel). */
static SSDA_ALWAYS_INLINE uint32_t rows_sad(const engine_t *e, const uint8_t *a,
                                            const uint8_t *w, uint32_t n, uint32_t rows,
                                            uint32_t limit, uint32_t *partial)
{
    const size_t as = e->area->stride, ws = e->win->stride;
    uint32_t r = 0u;
#ifndef SSDA_CFG_NO_U16
    if (!e->u8) {
        return ssda__sad_rows_u16((const uint16_t *)(const void *)a, as,
                                  (const uint16_t *)(const void *)w, ws, n, rows, limit,
                                  partial);
    }
#endif
    do {
        *partial += ssda__sad_row_u8(a + r * as, w + r * ws, n);
        r++;
    } while (r < rows && *partial < limit);
    return r;
}
#endif

/* fast_rows' first row, in chunks of SSDA_FIRST_ROW_CHUNK pixels (most
   positions are cut there): partial + rest against cut_at after each chunk.
   Returns true when cut (its pixels counted in e->ops), else false with
   *partial the row's SAD. */
static SSDA_ALWAYS_INLINE bool first_row_cut(engine_t *e, const uint8_t *a, const uint8_t *w,
                                             uint32_t rest, uint32_t cut_at, uint32_t *partial)
{
    const uint32_t L = e->L, fmt = e->area->format;
    uint32_t done = 0u, p = 0u;
    while (done < L) {
        const uint32_t n = L - done < SSDA_FIRST_ROW_CHUNK ? L - done : SSDA_FIRST_ROW_CHUNK;
        p += row_sad(e, a + (size_t)done * fmt, w + (size_t)done * fmt, n);
        done += n;
        if (done < L && p + rest >= cut_at) {
            e->ops += done;
            return true;
        }
    }
    *partial = p;
    if (p + rest >= cut_at) {
        e->ops += L;
        return true;
    }
    return false;
}

#if KERNEL_LOOPS
/* The rows of a position that passed eval_fast's checks: partial + rest
   against cut_at after each row (the first row in chunks), as in
   eval_position. With the kernels' loops (x86) rest is constant between
   the starts of two groups, so the rows from one start to the next go to
   the kernel in one call. rest < cut_at on entry and partial + rest <= the
   position's SAD < 2^32 - 1. Returns 1 and sets *sad, or 0 when cut. */
static SSDA_NOINLINE int fast_rows(engine_t *e, uint32_t x, uint32_t y, uint32_t cut_at,
                                   uint32_t rest, uint64_t *sad)
{
    const uint32_t L = e->L, M = e->M;
    const uint32_t as = e->area->stride, ws = e->win->stride;
    const uint8_t *a = e->area->base + (size_t)y * as + (size_t)x * e->area->format;
    const uint8_t *w = e->win->base;
    uint32_t partial = 0u; /* < 2^32 - 1: e->fast */
    uint32_t k = 0u;
#ifndef SSDA_CFG_NO_BOUNDS
    uint32_t g = 0u, next_start = 0u; /* the next group and its first row */
#endif
    if (L >= 2u * SSDA_FIRST_ROW_CHUNK) {
        /* the first row in chunks: most positions are cut there. Group 0
           starts with it when rest != 0, as in eval_position */
#ifndef SSDA_CFG_NO_BOUNDS
        if (rest != 0u) {
            rest -= e->term[0];
            g = 1u;
            next_start = e->group;
        }
#endif
        if (first_row_cut(e, a, w, rest, cut_at, &partial)) {
            return 0;
        }
        k = 1u;
    }
    while (k < M) { /* the rows from one group start to the next in one call */
        uint32_t end = M, n;
#ifndef SSDA_CFG_NO_BOUNDS
        if (rest != 0u && k == next_start) { /* as in eval_position */
            rest -= e->term[g];
            g++;
            next_start += e->group;
        }
        if (rest != 0u && next_start < M) {
            end = next_start; /* > k: rest changes there */
        }
#endif
        /* partial + rest < cut_at here, so the limit is above partial */
        n = rows_sad(e, a + (size_t)k * as, w + (size_t)k * ws, L, end - k, cut_at - rest,
                     &partial);
        k += n;
        if (partial + rest >= cut_at) {
            const uint32_t summed = k * L; /* <= L * M < 2^32 */
            e->ops += summed;
            return 0;
        }
    }
    {
        const uint32_t summed = M * L; /* < 2^32 */
        e->ops += summed;
    }
    *sad = partial;
    return 1;
}
#else
/* fast_rows without the kernels' loops: a row a call (tools/budget.sh: the
   restructured loop above cost the M4 about 0.5 % more instructions). */
static SSDA_NOINLINE int fast_rows(engine_t *e, uint32_t x, uint32_t y, uint32_t cut_at,
                                   uint32_t rest, uint64_t *sad)
{
    const uint32_t L = e->L;
    const uint32_t as = e->area->stride, ws = e->win->stride;
    const uint8_t *a = e->area->base + (size_t)y * as + (size_t)x * e->area->format;
    const uint8_t *w = e->win->base;
    uint32_t partial = 0u; /* < 2^32 - 1: e->fast */
    uint32_t k;
#ifndef SSDA_CFG_NO_BOUNDS
    uint32_t g = 0u, next_start = 0u; /* the next group and its first row */
#endif
    if (L >= 2u * SSDA_FIRST_ROW_CHUNK) {
        /* the first row in chunks: most positions are cut there. Group 0
           starts with it when rest != 0, as in eval_position */
#ifndef SSDA_CFG_NO_BOUNDS
        if (rest != 0u) {
            rest -= e->term[0];
            g = 1u;
            next_start = e->group;
        }
#endif
        if (first_row_cut(e, a, w, rest, cut_at, &partial)) {
            return 0;
        }
        k = 1u;
    } else {
        k = 0u;
    }
    for (; k < e->M; k++) {
#ifndef SSDA_CFG_NO_BOUNDS
        if (rest != 0u && k == next_start) { /* as in eval_position */
            rest -= e->term[g];
            g++;
            next_start += e->group;
        }
#endif
        partial += row_sad(e, &a[(size_t)k * as], &w[(size_t)k * ws], L);
        if (partial + rest >= cut_at) {
            const uint32_t summed = (k + 1u) * L; /* <= L * M < 2^32 */
            e->ops += summed;
            return 0;
        }
    }
    {
        const uint32_t summed = e->M * L; /* < 2^32 */
        e->ops += summed;
    }
    *sad = partial;
    return 1;
}
#endif

#if KERNEL_LOOPS && !defined(SSDA_CFG_NO_BOUNDS)
/* fast_rows after tab_refine4 (open_quad, eval_fast) for 16-bit windows
   16 pixels wide (4 groups of 4 rows, 16..19 rows), in one kernel call
   (ssda__sad16_rows_u16; the predicted position and the open ones of a
   GOES-16 window: 134 -> 48 million instructions a grid): fast_rows
   checks partial + rest against cut after the first 8 pixels and after
   every row, rest falling by the group's term as each group starts
   (rest - term[0] from row 0). So the limit of the rows of group k is cut
   - (rest - term[0] - .. - term[k]) (> 0: that rest <= rest < cut), and of
   the rows after the 4 groups cut - 0 (rest, from tab_refine4, is the sum
   of the 4 terms; fast_rows stops subtracting once rest is 0, and a term
   of 0 subtracts nothing). The same pixels counted, cuts and SAD. */
static SSDA_NOINLINE int quad_rows_u16(engine_t *e, uint32_t x, uint32_t y, uint32_t cut,
                                       uint32_t rest, uint64_t *sad)
{
    const size_t as = e->area->stride;
    const uint8_t *a = e->area->base + (size_t)y * as + (size_t)x * 2u;
    const uint32_t M = e->M;
    uint32_t limit[5], sum = 0u, k, pixels;
    for (k = 0u; k < 4u; k++) {
        rest -= rest != 0u ? e->term[k] : 0u;
        limit[k] = cut - rest;
    }
    limit[4] = cut - rest; /* rest is 0 here */
    pixels = ssda__sad16_rows_u16((const uint16_t *)(const void *)a, as,
                                  (const uint16_t *)(const void *)e->win->base, e->win->stride,
                                  M, limit, &sum);
    e->ops += pixels; /* <= 16 * 19 */
    if (pixels == 16u * M && sum < limit[M > 16u ? 4u : 3u]) {
        *sad = sum;
        return 1;
    }
    return 0;
}
#endif

/*
 * eval_position for the common exact case (e->fast, set once per search):
 * rows in memory, row order, no ramp, no all-cut fallback, no block levels,
 * and every SAD of the window below 2^32 - 1 (L * M * maxval), so that the
 * partial sum plus the bound of the rows not summed fits 32 bits, and a cut
 * level saturated to 2^32 - 1 decides as the 64-bit one does (a sum that
 * never reaches it). The same steps as eval_position, so the same results
 * and pixel_ops, in fewer instructions: most positions stop at the bound
 * (issue 18: tools/budget.sh, match.auto_predict_bounds on the Cortex-M4).
 */
static SSDA_ALWAYS_INLINE int eval_fast(engine_t *e, uint32_t x, uint32_t y, uint64_t *sad)
{
    bool tie = false;
    uint32_t cut_at = cut_level32(e, x, y, &tie);
    uint32_t rest = 0u; /* the bound, < 2^32 - 1 */
#if KERNEL_LOOPS && !defined(SSDA_CFG_NO_BOUNDS)
    bool rows16 = false; /* quad_rows_u16's case (16-bit, tab_refine4's) */
#endif
    e->positions++;
    if (cut_at == 0u) {
        return 0;
    }
#ifndef SSDA_CFG_NO_BOUNDS
    if (e->bounds) {
        /* 4 groups of 4 blocks: tab_refine4 takes the group terms itself.
           x86 only: on the M4 it made every bounded search's path heavier
           (tools/budget.sh: +6 % instructions) for 0.2 % on tracking */
        const bool quad = KERNEL_LOOPS != 0 && e->integ != NULL && e->L >> 2 == 4u &&
                          e->ngroups == 4u;
#if KERNEL_LOOPS
        rows16 = quad && !e->u8;
#endif
        rest = group_bound32(e, x, y, cut_at, !quad);
        if (rest >= cut_at) {
            return 0;
        }
        if (tie && !pos_before(e, x, y, e->ref->x, e->ref->y)) {
            cut_at--; /* the tie rule (cut_level32): s >= 1 */
            if (rest >= cut_at) {
                return 0;
            }
        }
        if (e->integ != NULL) { /* the bound <= the SAD < 2^32 - 1 */
            rest = quad ? tab_refine4(e, x, y, rest, cut_at)
                        : (uint32_t)tab_refine(e, x, y, rest, cut_at);
            if (rest >= cut_at) {
                return 0;
            }
        }
    }
#endif
#if KERNEL_LOOPS && !defined(SSDA_CFG_NO_BOUNDS)
    if (rows16) { /* tab_refine4 ran: its terms, and rest their sum */
        return quad_rows_u16(e, x, y, cut_at, rest, sad);
    }
#endif
    return fast_rows(e, x, y, cut_at, rest, sad);
}
#endif /* SSDA_CFG_NO_FAST_PATH */

/*
 * Evaluate position (x, y). Returns 1 and sets *sad when the position is
 * summed over all pixels without being cut, 0 when cut, or a fetch error.
 * Longer than the library's ~80 lines on purpose: it is the innermost
 * per-position loop, and the first-row chunk loop moved into a helper
 * (even always inlined, with the partial sum through a pointer) cost 2.3 %
 * more instructions per search on the Cortex-M4 (tools/budget.sh,
 * match.none), for the same results.
 */
static int eval_position(engine_t *e, uint32_t x, uint32_t y, uint64_t *sad)
{
#ifndef SSDA_CFG_NO_RAMP
    const bool ramp = e->ramp_mode &&
                      (e->plan->threshold == (uint8_t)SSDA_THRESHOLD_RAMP || e->n_best > 0u);
#endif
    uint64_t partial = 0u;        /* SAD of the rows summed: <= 65535^3 */
    uint64_t rest = 0u;           /* bound of the groups not started: <= 65535^3 */
    const uint64_t cut_at = cut_level(e, x, y); /* cut once partial + rest >= cut_at */
    uint32_t k, r = 0u;
#ifndef SSDA_CFG_NO_BOUNDS
    uint32_t next_group = 0u;     /* row order: index of the next group to start */
#endif

    e->positions++;
    if (cut_at == 0u) { /* nothing can beat a perfect match before it */
        NOTE_CUT(e, x, y, 0u, 0u);
        return 0;
    }
#ifndef SSDA_CFG_NO_BOUNDS
    if (e->lev_lo <= e->lev_hi && blocks_reject(e, x, y, cut_at, &rest)) {
        NOTE_CUT(e, x, y, rest, 0u);
        return 0;
    }
    if (e->row_step != 1u) {
        rest = 0u; /* spread order: the levels serve as a pre-check only */
    } else if (e->low != NULL && e->area->base != NULL && e->win->base != NULL) {
        return seeded_rows(e, x, y, cut_at, rest, sad);
    } else {
        /* the general loop below */
    }
    if (e->bounds) {
        rest = group_bound(e, x, y);
        if (rest < cut_at && e->integ != NULL && e->lev_lo > e->lev_hi) { /* tab_refine */
            rest = tab_refine(e, x, y, rest, cut_at);
        }
        if (rest >= cut_at) {
            NOTE_CUT(e, x, y, rest, 0u);
            return 0;
        }
        if (e->row_step != 1u) {
            rest = 0u; /* spread order: the bound serves as a pre-check only */
        }
    }
#endif
    for (k = 0u; k < e->M; k++) {
        const uint8_t *ap;
        const uint8_t *wp;
        uint64_t v;
        int err = ssda__rows_get(e->area, x, y + r, e->L, &ap);
        if (err == SSDA_OK) {
            err = ssda__rows_get(e->win, 0u, r, e->L, &wp);
        }
        if (err != SSDA_OK) {
            return err;
        }
#ifndef SSDA_CFG_NO_BOUNDS
        if (rest != 0u && r == next_group * e->group) {
            /* row order: a group leaves the bound when its first row is summed,
               so rest only covers groups with no row in partial. rest is the
               sum of term[next_group .. ngroups - 1]: rest != 0 implies
               next_group < ngroups. */
            rest -= e->term[next_group];
            next_group++;
        }
#endif
        if (k == 0u && e->L >= 2u * SSDA_FIRST_ROW_CHUNK) {
            /* Most placements are cut on their first row: test it in chunks. */
            uint32_t done = 0u;
            while (done < e->L) {
                uint32_t n = e->L - done < SSDA_FIRST_ROW_CHUNK ? e->L - done : SSDA_FIRST_ROW_CHUNK;
                partial += row_sad(e, ap + (size_t)done * e->area->format,
                                   wp + (size_t)done * e->area->format, n);
                e->ops += n;
                done += n;
                if (done < e->L && partial + rest >= cut_at) {
                    NOTE_CUT(e, x, y, partial + rest, done);
                    return 0;
                }
            }
        } else {
            partial += row_sad(e, ap, wp, e->L);
            e->ops += e->L;
        }
        r += e->row_step;
        if (r >= e->M) {
            r -= e->M;
        }
        v = partial + rest;
        if (v >= cut_at) {
            NOTE_CUT(e, x, y, v, (k + 1u) * e->L);
            return 0;
        }
#ifndef SSDA_CFG_NO_RAMP
        if (ramp && ramp_cuts(e, v, (k + 1u) * e->L)) {
            NOTE_CUT(e, x, y, v, (k + 1u) * e->L);
            return 0;
        }
#endif
    }
    *sad = partial;
    return 1;
}

#ifndef SSDA_CFG_NO_UNIQUE
/* Keep c among the cap smallest completed positions, ascending by the tie
   rule (the largest goes when full). (2R+1)^2 + 1 entries always hold the
   best position outside the final winner's square whenever it is within
   the ratio: every such position completes, and at most (2R+1)^2 of the
   entries lie in the square. */
static void list_insert(engine_t *e, const cand_t *c)
{
    uint32_t i = e->nlist;
    if (i == e->cap) {
        if (!cand_less(e, c, &e->list[i - 1u])) {
            return;
        }
        i--;
    } else {
        e->nlist++;
    }
    while (i > 0u && cand_less(e, c, &e->list[i - 1u])) {
        e->list[i] = e->list[i - 1u];
        i--;
    }
    e->list[i] = *c;
}
#endif

static void keep_completed(engine_t *e, uint32_t x, uint32_t y, cand_t *c);

/* Evaluate (x, y) and keep it if it is among the best two. Returns 1 with
   *c filled when the position completed, 0 when cut, or a fetch error. */
static int consider(engine_t *e, uint32_t x, uint32_t y, cand_t *c)
{
#ifndef SSDA_CFG_NO_FAST_PATH
    int done = e->fast ? eval_fast(e, x, y, &c->sad) : eval_position(e, x, y, &c->sad);
#else
    int done = eval_position(e, x, y, &c->sad);
#endif
    if (done <= 0) {
        return done;
    }
    keep_completed(e, x, y, c);
    return 1;
}

/* A completed position (c->sad set) at (x, y): counted, and kept if it is
   among the best two (and in the uniqueness list). */
static void keep_completed(engine_t *e, uint32_t x, uint32_t y, cand_t *c)
{
    e->completed++;
    c->x = x;
    c->y = y;
#ifndef SSDA_CFG_NO_UNIQUE
    if (e->list != NULL) {
        list_insert(e, c);
    }
#endif
    if (e->n_best == 0u || cand_less(e, c, &e->best)) {
        e->second = e->best;
        e->best = *c;
        e->n_best = (uint8_t)(e->n_best < 2u ? e->n_best + 1u : 2u);
#ifndef SSDA_CFG_NO_UNIQUE
        if (e->list != NULL) { /* c->sad < 2^48: the level < 2^50 */
            /* NOLINTNEXTLINE(clang-analyzer-core.CallAndMessage): as in cand_less */
            e->loose = ssda__mul_q8(c->sad, e->plan->unique_q8) + 1u;
        }
#endif
    } else if (e->n_best == 1u || cand_less(e, c, &e->second)) {
        e->second = *c;
        e->n_best = 2u;
    } else {
        /* behind both kept positions */
    }
}

/* Raster, seeded and predict scans (and scan_predict_open outside
   tracking's 4 x 4 case, open_quad): the reference is always the best so
   far. Inlined: its candidate on the scan's frame costs less stack than a
   frame of its own (issue 18). */
static SSDA_ALWAYS_INLINE int consider_best(engine_t *e, uint32_t x, uint32_t y)
{
    cand_t c;
    int err;
#ifndef SSDA_CFG_NO_BOUNDS
    /* with every bound known (e->pre; scan_pre calls consider itself): a
       position whose bound exceeds the best SAD is cut by eval_fast too (its
       cut level is at most that SAD + 1), so it is counted and passed
       without the call */
    if (e->pre != NULL && e->ref != NULL && e->pre[(size_t)y * e->nx + x] > e->ref->sad) {
        e->positions++;
        return SSDA_OK;
    }
#endif
    err = consider(e, x, y, &c);
    if (err > 0) {
        e->ref = &e->best;
    }
    return err < 0 ? err : SSDA_OK;
}

#ifndef SSDA_CFG_NO_BOUNDS
/* SSDA_MATCH_BLOCKS with AUTO raster: candidates summed first so that the
   threshold is low from the start (the raster scan's result does not depend
   on the order in the exact modes). The range of positions is cut into
   SEED_TILES x SEED_TILES tiles and each tile's position of the smallest
   coarsest-level bound (the first in raster order among equal ones) is a
   candidate: spread over the image, so one misleading bound does not
   decide. The pass also stores every position's bound in the table. */
#define SEED_TILES 4u
#define SEED_CANDS 16u /* SEED_TILES^2 */
#define SEED_KEEP 8u   /* per tile, the positions of the smallest coarsest bounds */
#define SEED_KEPT 128u /* SEED_CANDS * SEED_KEEP */
#define SEED_KEPT_WORDS 384u /* 3 * SEED_KEPT: bounds, x, y of the kept positions */
#define SEED_WORDS 432u /* SEED_KEPT_WORDS + 3 * SEED_CANDS: kept, then candidates */

/* Keep (v, x, y) among a tile's SEED_KEEP smallest coarsest bounds,
   ascending, the first in raster order first among equal ones; an unused
   entry has x == UINT32_MAX. */
static SSDA_ALWAYS_INLINE void seed_keep(uint32_t *kb, uint32_t *kx, uint32_t *ky, uint32_t v,
                                         uint32_t x, uint32_t y)
{
    uint32_t j = SEED_KEEP - 1u;
    if (kx[j] != UINT32_MAX && v >= kb[j]) {
        return;
    }
    while (j > 0u && (kx[j - 1u] == UINT32_MAX || kb[j - 1u] > v)) {
        kb[j] = kb[j - 1u];
        kx[j] = kx[j - 1u];
        ky[j] = ky[j - 1u];
        j--;
    }
    kb[j] = v;
    kx[j] = x;
    ky[j] = y;
}

/* The candidates: in each tile, of the kept positions the one with the
   smallest bound at the finest level (the first kept among equal ones). */
static SSDA_NOINLINE void seed_rank(engine_t *e, const uint32_t *keep, uint32_t *cx, uint32_t *cy,
                      uint32_t *cb)
{
    uint32_t i, j;
    for (i = 0u; i < SEED_CANDS; i++) {
        const uint32_t *kx = keep + SEED_KEPT + ((size_t)i * SEED_KEEP);
        const uint32_t *ky = kx + SEED_KEPT;
        cb[i] = UINT32_MAX;
        cx[i] = UINT32_MAX; /* no candidate */
        cy[i] = UINT32_MAX;
        for (j = 0u; j < SEED_KEEP && kx[j] != UINT32_MAX; j++) {
            const uint64_t b = block_bound(e, e->lev_hi, kx[j], ky[j], UINT64_MAX, NULL);
            const uint32_t v = b > UINT32_MAX ? UINT32_MAX : (uint32_t)b;
            if (cx[i] == UINT32_MAX || v < cb[i]) {
                cb[i] = v;
                cx[i] = kx[j];
                cy[i] = ky[j];
            }
        }
    }
}

/* The first pass: every position's coarsest bound into the table, and each
   tile's SEED_KEEP smallest in keep (bounds, then x, then y; SEED_CANDS *
   SEED_KEEP entries each). */
static SSDA_NOINLINE void seed_pass(engine_t *e, uint32_t *keep)
{
    uint32_t x, y, i;
    uint32_t *tab = e->low;
    uint32_t *kx = keep + SEED_KEPT, *ky = kx + SEED_KEPT;
    for (i = 0u; i < SEED_CANDS * SEED_KEEP; i++) {
        keep[i] = UINT32_MAX;
        kx[i] = UINT32_MAX;
        ky[i] = UINT32_MAX;
    }
    for (y = 0u; y < e->ny; y++) {
        /* tile row and column: t * n / SEED_TILES <= p; n < 2^16 */
        const uint32_t ty = SSDA_DIV32(y * SEED_TILES, e->ny);
        uint32_t tx = 0u, next_x = SSDA_DIV32(e->nx + SEED_TILES - 1u, SEED_TILES);
        for (x = 0u; x < e->nx; x++) {
            const uint64_t b = block_bound(e, e->lev_lo, x, y, UINT64_MAX, NULL);
            const uint32_t v = b > UINT32_MAX ? UINT32_MAX : (uint32_t)b;
            if (x == next_x) {
                tx++;
                next_x = SSDA_DIV32((tx + 1u) * e->nx + SEED_TILES - 1u, SEED_TILES);
            }
            *tab = v;
            tab++;
            i = (ty * SEED_TILES + tx) * SEED_KEEP;
            seed_keep(keep + i, kx + i, ky + i, v, x, y);
        }
    }
}

/* Sum the candidates first, smallest bound first. */
static int seed_visit(engine_t *e, uint32_t *cx, uint32_t *cy, uint32_t *cb)
{
    uint32_t i;
    ssda__pre_sort(SEED_CANDS, cx, cy, cb);
    for (i = 0u; i < SEED_CANDS; i++) {
        if (cx[i] != UINT32_MAX) {
            int err = consider_best(e, cx[i], cy[i]);
            if (err != SSDA_OK) {
                return err;
            }
            e->low[(size_t)cy[i] * e->nx + cx[i]] = UINT32_MAX; /* visited */
        }
    }
    return SSDA_OK;
}

/* Position (x, y) with a table entry UINT32_MAX: a candidate visited
   already? (else a bound that saturated) */
static bool seed_visited(const uint32_t *cx, const uint32_t *cy, uint32_t x, uint32_t y)
{
    uint32_t i;
    for (i = 0u; i < SEED_CANDS; i++) {
        if (cx[i] == x && cy[i] == y) {
            return true;
        }
    }
    return false;
}
#endif

/* Out of line: its candidate stays off the engine's frame. */
static SSDA_NOINLINE int scan_raster(engine_t *e)
{
    uint32_t x, y;
    for (y = 0u; y < e->ny; y++) {
        for (x = 0u; x < e->nx; x++) {
            int err = consider_best(e, x, y);
            if (err != SSDA_OK) {
                return err;
            }
        }
    }
    return SSDA_OK;
}

#ifndef SSDA_CFG_NO_BOUNDS
/* The seeded raster scan (SSDA_MATCH_BLOCKS, AUTO): the table and the
   candidates, the candidates summed, then the raster scan rejecting from
   the table. Out of line: its locals stay off the frame of the others. */
static SSDA_NOINLINE int scan_seeded(engine_t *e)
{
    /* the candidates in the work buffer, after the window's block sums */
    uint32_t *keep = e->wblk + ((size_t)SSDA_MATCH_BLOCK_SUMS - SSDA_MATCH_BLOCK_ROWS - SEED_WORDS);
    uint32_t *cb = keep + SEED_KEPT_WORDS;
    uint32_t *cx = cb + SEED_CANDS, *cy = cx + SEED_CANDS;
    const uint32_t *low = e->low;
    uint32_t x, y;
    int err;
    seed_pass(e, keep);
    seed_rank(e, keep, cx, cy, cb);
    /* the positions' pre-check reads the coarsest level from the table;
       then one level more: finer ones cost more than they reject
       (camera.png 128x128 in ssda-peers-match, issue 18) */
    e->lev_lo++;
    if (e->lev_hi > e->lev_lo) {
        e->lev_hi = e->lev_lo;
    }
    err = seed_visit(e, cx, cy, cb);
    for (y = 0u; y < e->ny && err == SSDA_OK; y++) {
        for (x = 0u; x < e->nx && err == SSDA_OK; x++) {
            /* a position whose coarsest bound reaches its cut level is
               rejected here, its terms counted in the first pass */
            const uint32_t v = low[(size_t)y * e->nx + x];
            if (v == UINT32_MAX && seed_visited(cx, cy, x, y)) {
                continue;
            }
            if ((uint64_t)v >= cut_level(e, x, y)) {
                e->positions++;
                continue;
            }
            err = consider_best(e, x, y);
        }
    }
    return err;
}
#endif

#ifndef SSDA_CFG_NO_BOUNDS
/* SSDA_MATCH_BLOCKS's room after the bounds tables and the uniqueness list
   (match.h's layout): the levels' integral image and the window's block
   sums, or scan_pre's bounds. */
static uint32_t *blocks_room(const engine_t *e)
{
    const uint64_t tables = ((((uint64_t)e->nx * e->area->height) + 2u * (uint64_t)e->M) *
                                 sizeof(uint32_t) + 7u) & ~(uint64_t)7u;
    return (uint32_t *)(void *)((uint8_t *)e->plan->work + (size_t)tables +
                                SSDA_MATCH_UNIQUE_WORK);
}

#endif

#if !defined(SSDA_CFG_NO_BOUNDS) && !defined(SSDA_CFG_NO_FAST_PATH)
/* Positions whose bounds scan_pre tests together before looking at any
   one: most runs hold none that the best SAD leaves open. */
#define PRE_RUN 8u

/* scan_pre's bound pass (ssda__pre_bounds): out of line, so that its many
   arguments stay off scan_pre's frame, which lies under consider's.
   Returns the number of candidates. */
static SSDA_NOINLINE uint32_t pre_pass(engine_t *e, uint32_t *pre)
{
    const uint32_t nx = e->nx, ny = e->ny;
    uint32_t *cx = pre + (size_t)nx * ny; /* after the bounds (match.h's room) */
    uint32_t *cy = cx + SSDA__PRE_CANDS;
    const uint32_t n = ssda__pre_bounds(e->gsum, e->gpitch, e->group, e->wgrp, e->ngroups, nx,
                                        ny, pre, cx + SSDA__PRE_CAND_WORDS, cx, cy,
                                        cy + SSDA__PRE_CANDS); /* >= 1: nx, ny >= 1 */
    /* positions x groups: may exceed 2^32 for very large areas */
    e->ops += (uint64_t)nx * ny * e->ngroups;
    e->pre = pre; /* its terms counted: eval_fast's are not (finish) */
    return n;
}

/* A single search with every position's group bound known (e->pre_scan:
   SSDA_MATCH_BLOCKS left to it by pre_first, AUTO raster, eval_fast; the
   group tables from ssda__pre_tables): the bounds at once, each row's
   smallest and the candidate of the smallest bound in each of 16 tiles
   (ssda__pre_bounds), the candidates summed first, smallest first, so that
   the best SAD is near the minimum from the start; then in raster order,
   in the rows whose smallest bound does not exceed the best SAD so far,
   only the positions whose bound does not exceed it go to eval_fast (its cut level
   and tie rule as in the raster scan); the others cannot win. The result
   does not depend on the order (exact modes). A
   visited candidate's entry becomes UINT32_MAX, above every bound (the
   bound <= the SAD < 2^32 - 1: e->fast). Each position counts once. */
static SSDA_NOINLINE int scan_pre(engine_t *e)
{
    const uint32_t nx = e->nx, ny = e->ny;
    uint32_t *pre = blocks_room(e); /* no level: the room is unused */
    const uint32_t *cx = pre + (size_t)nx * ny, *cy = cx + SSDA__PRE_CANDS;
    const uint32_t *rmin = cx + SSDA__PRE_CAND_WORDS;
    uint32_t n = pre_pass(e, pre), i, x, y;
    cand_t c;
    for (i = 0u; i < n; i++) {
        const int err = consider(e, cx[i], cy[i], &c); /* the first completes */
        if (err < 0) {
            return err;
        }
        e->ref = &e->best;
        pre[(size_t)cy[i] * nx + cx[i]] = UINT32_MAX; /* visited */
    }
    for (y = 0u; y < ny; y++) {
        const uint32_t *p = pre + (size_t)y * nx;
        if (rmin[y] > e->best.sad) {
            continue; /* no position of the row can win */
        }
        for (x = 0u; x < nx; x += PRE_RUN) {
            const uint32_t t = (uint32_t)e->best.sad; /* < 2^32 - 1 */
            const uint32_t end = nx - x < PRE_RUN ? nx : x + PRE_RUN;
            uint32_t open = 0u;
            if (end == x + PRE_RUN) {
                for (i = 0u; i < PRE_RUN; i++) { /* no branch: vectorised */
                    open |= p[x + i] <= t ? 1u : 0u;
                }
            } else {
                open = 1u;
            }
            for (i = x; open != 0u && i < end; i++) {
                if (p[i] <= e->best.sad) {
                    const int err = consider(e, i, y, &c);
                    if (err < 0) {
                        return err;
                    }
                }
            }
        }
    }
    e->positions = nx * ny; /* each once: < 2^32 */
    return SSDA_OK;
}
#endif

#ifndef SSDA_CFG_NO_PREDICT

/* Square rings of growing Chebyshev radius around the prediction: the top
   and bottom rows of each ring, then its left and right columns, each
   clipped to the range (a side outside it is skipped whole). One loop, no
   call per side: its frame is the only one between the engine's and
   consider's (issue 18). Coordinates are int32_t: |p| <= 2 * 65535. */
static SSDA_NOINLINE int scan_predict(engine_t *e)
{
    const int32_t nx = (int32_t)e->nx, ny = (int32_t)e->ny;
    const int32_t px = (int32_t)e->tx;
    const int32_t py = (int32_t)e->ty;
    int32_t dmax = px;
    int32_t d;
    int err = consider_best(e, (uint32_t)px, (uint32_t)py);
    if (nx - 1 - px > dmax) {
        dmax = nx - 1 - px;
    }
    if (py > dmax) {
        dmax = py;
    }
    if (ny - 1 - py > dmax) {
        dmax = ny - 1 - py;
    }
    for (d = 1; d <= dmax && err == SSDA_OK; d++) {
        uint32_t side;
        for (side = 0u; side < 4u && err == SSDA_OK; side++) {
            /* top, bottom: the row py -+ d, x in px - d .. px + d; left,
               right: the column px -+ d, y in py - d + 1 .. py + d - 1 */
            const int32_t sgn = (side & 1u) != 0u ? d : -d;
            const int32_t fix = side < 2u ? py + sgn : px + sgn;
            int32_t lo = side < 2u ? px - d : py - d + 1;
            int32_t hi = side < 2u ? px + d : py + d - 1;
            const int32_t fix_n = side < 2u ? ny : nx;
            const int32_t run_n = side < 2u ? nx : ny;
            int32_t i;
            if (fix < 0 || fix >= fix_n) {
                continue;
            }
            if (lo < 0) {
                lo = 0;
            }
            if (hi >= run_n) {
                hi = run_n - 1;
            }
            for (i = lo; i <= hi && err == SSDA_OK; i++) {
                err = consider_best(e, (uint32_t)(side < 2u ? i : fix),
                                       (uint32_t)(side < 2u ? fix : i));
            }
        }
    }
    return err;
}
#endif

#ifndef SSDA_CFG_NO_COARSE
/* Coarse grid, keeping the best two exactly (reference = second best). */
static int scan_coarse_grid(engine_t *e, uint32_t step)
{
    uint32_t x, y;
    for (y = 0u; y < e->ny; y += step) {
        for (x = 0u; x < e->nx; x += step) {
            cand_t c;
            int err;
            e->ref = e->n_best == 2u ? &e->second : NULL;
            err = consider(e, x, y, &c);
            if (err < 0) {
                return err;
            }
        }
    }
    return SSDA_OK;
}

/* From start, move 1 px to the best better neighbour until none improves. */
static SSDA_ALWAYS_INLINE int hill_climb(engine_t *e, const cand_t *start)
{
    cand_t next = *start;
    uint32_t cx = start->x, cy = start->y; /* the current position */
    for (;;) {
        uint32_t i;
        for (i = 0u; i < 4u; i++) {
            /* neighbours up, down, left, right; unsigned wrap-around of
               0 - 1 is out of range too */
            uint32_t nxp = i < 2u ? cx : (i == 2u ? cx - 1u : cx + 1u);
            uint32_t nyp = i >= 2u ? cy : (i == 0u ? cy - 1u : cy + 1u);
            cand_t c;
            int done;
            if (nxp >= e->nx || nyp >= e->ny) {
                continue;
            }
            /* a neighbour must beat the best move so far; ref is cleared
               before next goes out of scope */
            /* cppcheck-suppress autoVariables */
            e->ref = &next;
            done = consider(e, nxp, nyp, &c);
            if (done < 0) {
                e->ref = NULL; /* next dies here */
                return done;
            }
            if (done > 0 && cand_less(e, &c, &next)) {
                next = c;
            }
        }
        if (next.x == cx && next.y == cy) {
            e->ref = NULL; /* next dies here */
            return SSDA_OK;
        }
        cx = next.x;
        cy = next.y;
    }
}

/* The coarse grid, then a climb from the best and, when there were two,
   from the second (as the grid left them). hill_climb is inlined once, in
   the loop: one frame between the engine's and consider's (issue 18). */
static SSDA_NOINLINE int scan_coarse(engine_t *e)
{
    uint32_t step = e->plan->coarse_step;
    cand_t s2;
    uint32_t i, climbs;
    int err = scan_coarse_grid(e, step);
    if (err != SSDA_OK || e->n_best == 0u) {
        return err;
    }
    s2 = e->second; /* the climbs change best and second */
    climbs = e->n_best; /* 1 or 2 */
    for (i = 0u; i < climbs && err == SSDA_OK; i++) {
        err = hill_climb(e, i == 0u ? &e->best : &s2);
    }
    return err;
}
#endif

#ifndef SSDA_CFG_NO_BOUNDS
/* H(x, yy) of every area row yy: the sliding sums of L pixels, nx per row,
   in gsum. H <= L * 65535 <= 65535^2 < 2^32. Adds the work to *ops.
   Returns SSDA_OK or a fetch error. Inlined into build_bounds (its parts
   are split for reading only: one frame, the same code). */
static SSDA_ALWAYS_INLINE int area_row_sums(const engine_t *e, uint32_t *gsum, bool u8,
                                            uint64_t *ops)
{
    const uint32_t ah = e->area->height;
    const uint32_t L = e->L, nx = e->nx;
    uint32_t yy, i;
    for (yy = 0u; yy < ah; yy++) {
        const uint8_t *p;
        uint32_t *h = gsum + (size_t)yy * nx;
        uint32_t s = 0u; /* <= L * 65535 <= 65535^2 < 2^32 */
        int err = ssda__rows_get(e->area, 0u, yy, e->area->width, &p);
        if (err != SSDA_OK) {
            return err;
        }
        if (u8) {
            for (i = 0u; i + 4u <= L; i += 4u) {
                s += (uint32_t)p[i] + p[i + 1u] + p[i + 2u] + p[i + 3u];
            }
            for (; i < L; i++) {
                s += p[i];
            }
            h[0] = s;
            for (i = 1u; i + 2u <= nx; i += 2u) { /* two a step: fewer branches */
                s = s + p[i + L - 1u] - p[i - 1u];
                h[i] = s;
                s = s + p[i + L] - p[i];
                h[i + 1u] = s;
            }
            if (i < nx) {
                h[i] = s + p[i + L - 1u] - p[i - 1u];
            }
        } else {
            const uint16_t *q = (const uint16_t *)(const void *)p;
            for (i = 0u; i < L; i++) {
                s += q[i];
            }
            h[0] = s;
            for (i = 1u; i < nx; i++) {
                s = s + q[i + L - 1u] - q[i - 1u]; /* < 65535^2 + 65535 < 2^32 */
                h[i] = s;
            }
        }
        *ops += L + 2u * ((uint64_t)nx - 1u);
    }
    return SSDA_OK;
}

/* In place, top-down: row yy of gsum (nx per row, ah rows) becomes
   H(yy) + ... + H(yy + group - 1); rows past ah - group are never read
   afterwards. A group sum <= group * L * 65535 (range in build_bounds).
   Adds the work to *ops. */
static SSDA_ALWAYS_INLINE void group_rows(uint32_t *gsum, uint32_t nx, uint32_t ah,
                                          uint32_t group, uint64_t *ops)
{
    uint32_t i, yy;
    for (i = 0u; i < nx; i++) {
        uint32_t *c = gsum + i;
        uint32_t s = 0u; /* a group sum */
        for (yy = 0u; yy < group; yy++) {
            s += c[(size_t)yy * nx];
        }
        for (yy = 0u; yy + group + 1u < ah; yy += 2u) { /* group <= M <= ah; two a step */
            const uint32_t top0 = c[0], top1 = c[nx];
            c[0] = s;
            s = s - top0 + c[(size_t)group * nx];
            c[nx] = s;
            s = s - top1 + c[((size_t)group + 1u) * nx];
            c += nx;
            c += nx;
        }
        if (yy + group < ah) {
            const uint32_t top = *c;
            *c = s;
            s = s - top + c[(size_t)group * nx];
            c += nx;
        }
        *c = s; /* row ah - group */
        *ops += group + 2u * ((uint64_t)ah - group);
    }
}

/* The window's sums over the same groups of rows, in wgrp. Adds the work
   to *ops. Returns SSDA_OK or a fetch error. */
static SSDA_ALWAYS_INLINE int window_groups(const engine_t *e, uint32_t *wgrp, uint32_t group,
                                            uint32_t ngroups, bool u8, uint64_t *ops)
{
    const uint32_t L = e->L;
    uint32_t i, yy;
    for (i = 0u; i < ngroups; i++) {
        uint32_t s = 0u;
        for (yy = i * group; yy < (i + 1u) * group; yy++) {
            const uint8_t *p;
            uint32_t c;
            int err = ssda__rows_get(e->win, 0u, yy, L, &p);
            if (err != SSDA_OK) {
                return err;
            }
            if (u8) {
                for (c = 0u; c < L; c++) {
                    s += p[c];
                }
            } else {
                for (c = 0u; c < L; c++) {
                    s += ((const uint16_t *)(const void *)p)[c];
                }
            }
        }
        wgrp[i] = s;
        *ops += (uint64_t)group * L;
    }
    return SSDA_OK;
}

/* With shared tables holding 4 x 4 block sums: the window's block sums,
   L / 4 per group of 4 rows (tab_refine), and each group's sum from its
   blocks into wgrp. A block sum <= 16 * 65535 < 2^20. Adds the work to
   *ops (the pixels, then nb - 1 additions a group). Returns SSDA_OK or a
   fetch error. */
static SSDA_NOINLINE int window_blocks4(const engine_t *e, uint32_t *wblk, uint32_t *wgrp,
                                        bool u8, uint64_t *ops)
{
    const uint32_t nb = (uint32_t)e->L >> 2;
    uint32_t k, yy, c;
#if KERNEL_LOOPS
    if (nb == 4u && e->ngroups == 4u && e->win->base != NULL) { /* 16 x 16..19 in memory */
        ssda__blocks16(e->win->base, e->win->stride, u8, wblk, wgrp);
        *ops += (uint64_t)4u * (4u * e->L + 3u); /* as the loop below counts */
        return SSDA_OK;
    }
#endif
    for (k = 0u; k < e->ngroups; k++) {
        uint32_t *w = wblk + (size_t)k * nb;
        uint32_t g = 0u; /* the group's sum: <= 4 * L * 65535 < 2^32 (L <= 1024) */
        if (nb == 4u) { /* 16..19 columns, the seed's windows: the sums in locals */
            uint32_t b[4] = {0u, 0u, 0u, 0u}; /* < 2^20 each */
            for (yy = 4u * k; yy < 4u * k + 4u; yy++) {
                const uint8_t *p;
                int err = ssda__rows_get(e->win, 0u, yy, 16u, &p);
                if (err != SSDA_OK) {
                    return err;
                }
                for (c = 0u; c < 4u; c++) {
                    if (u8) {
                        const uint8_t *q = p + (size_t)4u * c;
                        b[c] += (uint32_t)q[0] + q[1] + q[2] + q[3];
                    } else {
                        const uint16_t *q = (const uint16_t *)(const void *)p + (size_t)4u * c;
                        b[c] += (uint32_t)q[0] + q[1] + q[2] + q[3];
                    }
                }
            }
            w[0] = b[0];
            w[1] = b[1];
            w[2] = b[2];
            w[3] = b[3];
            wgrp[k] = b[0] + b[1] + b[2] + b[3];
            *ops += (uint64_t)4u * e->L + 3u;
            continue;
        }
        for (c = 0u; c < nb; c++) {
            w[c] = 0u;
        }
        for (yy = 4u * k; yy < 4u * k + 4u; yy++) {
            const uint8_t *p;
            int err = ssda__rows_get(e->win, 0u, yy, 4u * nb, &p);
            if (err != SSDA_OK) {
                return err;
            }
            if (u8) {
                const uint8_t *q = p;
                for (c = 0u; c < nb; c++) {
                    w[c] += (uint32_t)q[0] + q[1] + q[2] + q[3];
                    q += 4;
                }
            } else {
                const uint16_t *q = (const uint16_t *)(const void *)p;
                for (c = 0u; c < nb; c++) {
                    w[c] += (uint32_t)q[0] + q[1] + q[2] + q[3];
                    q += 4;
                }
            }
        }
        for (c = 0u; c < nb; c++) {
            g += w[c];
        }
        wgrp[k] = g;
        *ops += (uint64_t)4u * e->L + nb - 1u;
    }
    return SSDA_OK;
}

/* The bounds from tracking's shared tables (match_rows.h): the area's
   group sums are read there, only the window's are summed here, with its
   4 x 4 block sums when the tables hold them (tab_refine on: e->integ). */
static int tab_bounds(engine_t *e, ssda__match_tab_t *tab, uint32_t *wgrp, bool u8,
                      uint64_t *ops)
{
    bool refine = tab->b != NULL && !e->ramp_mode;
#ifdef ENGINE_FALLBACK
    /* not with the ramp (its cuts read the bound) nor the all-cut fallback
       (it keeps the position cut latest): the bound's strength would change
       their results */
    refine = refine && !e->need_fb;
#endif
    e->gsum = tab->g;
    e->gpitch = (uint16_t)tab->pitch;
    if (refine) {
        e->integ = tab->b;
        e->wblk = tab->wblk;
        return window_blocks4(e, tab->wblk, wgrp, u8, ops);
    }
    return window_groups(e, wgrp, 4u, e->ngroups, u8, ops);
}

/* Shared tables, fast path, AUTO without the uniqueness list: every
   position's group bound in one pass over the tables (rows of the shared
   table against each window group sum, so the loops run along x and
   vectorise), into the per-window group table's place, which shared tables
   leave unused (nx * ah >= nx * ny entries). The scans then pass the
   positions whose bound exceeds the best SAD without evaluating them
   (consider_best). Counts the nx * ny * ngroups terms here; eval_fast's
   bound calls for the other positions are not counted again (finish). */
#ifndef SSDA_CFG_NO_FAST_PATH
#define OPEN_MAX 32u /* scan_predict_open: positions a row and a column */

#if KERNEL_LOOPS && !defined(SSDA_CFG_NO_PREDICT)
/* scan_predict_open's case with 4 groups of group sums below 2^31 (x86):
   the bound pass is deferred until the predicted position is summed, and
   made with the masks of the positions it leaves open (ssda__bounds4_open:
   one pass, where open_masks read every bound again; issue 18). */
static bool defer_open(const engine_t *e)
{
    return e->plan->scan == (uint8_t)SSDA_SCAN_PREDICT && e->nx <= OPEN_MAX &&
           e->ny <= OPEN_MAX && e->ngroups == 4u && (e->u8 || e->L <= 8191u);
}
#endif

static SSDA_NOINLINE void pre_bounds(engine_t *e)
{
    uint32_t *pre = (uint32_t *)e->plan->work;
    const uint32_t nx = e->nx, ny = e->ny, pitch = e->gpitch;
    /* every group sum (of area and window) below 2^31: 4 * L * 65535 < 2^31
       for L <= 8191 (8-bit: always), so group sums fit int32_t and so do
       their differences */
    const bool small = e->u8 || e->L <= 8191u;
    uint32_t x, y, k;
#if KERNEL_LOOPS && !defined(SSDA_CFG_NO_PREDICT)
    if (defer_open(e)) { /* the predicted position's bound only (counted later) */
        const size_t at = (size_t)e->ty * pitch + e->tx;
        ssda__portable_bounds4(pre + (size_t)e->ty * nx + e->tx, e->gsum + at,
                               (size_t)4u * pitch, e->wgrp, 1u);
        e->pre = pre;
        return;
    }
#endif
    for (y = 0u; y < ny; y++) {
        uint32_t *p = pre + (size_t)y * nx;
        if (e->ngroups == 4u) { /* 16..19 rows, the seed's windows: one pass */
            const uint32_t *g0 = e->gsum + (size_t)y * pitch;
            const uint32_t *g1 = g0 + (size_t)4u * pitch, *g2 = g1 + (size_t)4u * pitch;
            const uint32_t *g3 = g2 + (size_t)4u * pitch;
            const uint32_t w0 = e->wgrp[0], w1 = e->wgrp[1], w2 = e->wgrp[2], w3 = e->wgrp[3];
            size_t i;
            if (small) { /* signed differences: the kernels' row (AVX2 on x86) */
#if KERNEL_LOOPS
                ssda__bounds4(p, g0, (size_t)4u * pitch, e->wgrp, nx);
#else
                ssda__portable_bounds4(p, g0, (size_t)4u * pitch, e->wgrp, nx);
#endif
                continue;
            }
            for (i = 0u; i < nx; i++) { /* the bound < 2^32 - 1 (group_bound32) */
                p[i] = (g0[i] > w0 ? g0[i] - w0 : w0 - g0[i]) +
                       (g1[i] > w1 ? g1[i] - w1 : w1 - g1[i]) +
                       (g2[i] > w2 ? g2[i] - w2 : w2 - g2[i]) +
                       (g3[i] > w3 ? g3[i] - w3 : w3 - g3[i]);
            }
            continue;
        }
        for (k = 0u; k < e->ngroups; k++) {
            const uint32_t *g = e->gsum + ((size_t)y + 4u * (size_t)k) * pitch;
            const uint32_t w = e->wgrp[k];
            if (k == 0u) {
                for (x = 0u; x < nx; x++) {
                    p[x] = g[x] > w ? g[x] - w : w - g[x];
                }
            } else {
                for (x = 0u; x < nx; x++) {
                    p[x] += g[x] > w ? g[x] - w : w - g[x];
                }
            }
        }
    }
    e->ops += (uint64_t)nx * ny * e->ngroups; /* positions x groups: may exceed 2^32 */
    e->pre = pre;
}

/* The predict scan with every bound known (pre_bounds) and at most
   OPEN_MAX positions a row and a column: scan_predict's square rings, in
   the same order, visiting only the positions whose bound does not exceed
   the SAD of the first (bit x of open[y]; the others would be passed by
   consider_best as well, since the best SAD only falls). The same
   positions are evaluated in the same order, so the result, positions and
   completed are scan_predict's, with one compare a position to build the
   masks instead of the ring loop's test of each (GOES-16, 16 x 16 in
   32 x 32: 117 -> 78 million host instructions for the grid; issue 18).
   open: 2 * OPEN_MAX words (a row's mask per row, then a column's per
   column) in the uniqueness list's place, unused here. */
#ifndef SSDA_CFG_NO_PREDICT
/* the masks fit the list's room, which every shared-table buffer has */
typedef char open_masks_fit[(sizeof(uint32_t) * 2u * OPEN_MAX <= SSDA_MATCH_UNIQUE_WORK) ? 1 : -1];

/* Byte offset of the uniqueness list in the work buffer (match.h's layout:
   after the bounds tables, rounded up to 8). */
static size_t open_at(const engine_t *e)
{
    return (((size_t)e->nx * e->area->height + 2u * (size_t)e->M) * sizeof(uint32_t) + 7u) &
           ~(size_t)7u;
}

/* Index of the lowest set bit of m != 0 (a de Bruijn sequence). */
static SSDA_ALWAYS_INLINE uint32_t low_bit(uint32_t m)
{
    static const uint8_t k_pos[32] = {0u,  1u,  28u, 2u,  29u, 14u, 24u, 3u,  30u, 22u, 20u,
                                      15u, 25u, 17u, 4u,  8u,  31u, 27u, 13u, 23u, 21u, 19u,
                                      16u, 7u,  26u, 12u, 18u, 6u,  11u, 5u,  10u, 9u};
    return k_pos[((m & (0u - m)) * 0x077CB531u) >> 27];
}

/* Bits lo .. hi of a word (lo <= hi < 32). */
static SSDA_ALWAYS_INLINE uint32_t bit_span(uint32_t lo, uint32_t hi)
{
    return ((2u << hi) - 1u) & ~((1u << lo) - 1u); /* 2 << 31 wraps to 0: all bits */
}


/* pos_before(e, x, y, best.x, best.y) for open_quad, whose positions lie
   in a range of at most OPEN_MAX a side: squared distances < 2 * 32^2 in
   32 bits, and the rule's terms combined without branches (the tie rule
   was a tenth of the predict scan's instructions on GOES-16). */
static SSDA_ALWAYS_INLINE bool open_before(const engine_t *e, uint32_t x, uint32_t y)
{
    const uint32_t bx = e->best.x, by = e->best.y;
    const int32_t ax = (int32_t)x - (int32_t)e->tx, ay = (int32_t)y - (int32_t)e->ty;
    const int32_t cx = (int32_t)bx - (int32_t)e->tx, cy = (int32_t)by - (int32_t)e->ty;
    const int32_t sa = ax * ax + ay * ay, sb = cx * cx + cy * cy; /* < 2 * 32^2 */
    const uint32_t da = (uint32_t)sa, db = (uint32_t)sb;
    const bool raster = y < by || (y == by && x < bx);
    return e->tie_near ? (da < db) | ((da == db) & raster) : raster;
}

/* consider_best for scan_predict_open with 4 groups of 4 blocks (the
   seed's windows, tab_refine4): eval_fast's steps on what that case
   knows already (a reference, the bound in the table, no list), the same
   cut level, terms, rows and count. Rows in memory: no fetch error. */
static SSDA_ALWAYS_INLINE void open_quad(engine_t *e, uint32_t x, uint32_t y)
{
    const uint32_t s = (uint32_t)e->best.sad; /* < 2^32 - 1: e->fast */
    const uint32_t bound = e->pre[(size_t)y * e->nx + x];
    uint32_t cut, rest;
    cand_t c;
    if (bound > s) {
        return;
    }
    /* cut_level32: s + 1 for a position before the best by the tie rule */
    cut = s + (open_before(e, x, y) ? 1u : 0u);
    if (bound >= cut) { /* also cut == 0 */
        return;
    }
    rest = tab_refine4(e, x, y, bound, cut);
    if (rest >= cut) {
        return;
    }
#if KERNEL_LOOPS
    if (!e->u8 ? quad_rows_u16(e, x, y, cut, rest, &c.sad) != 0
               : fast_rows(e, x, y, cut, rest, &c.sad) != 0) {
        keep_completed(e, x, y, &c);
    }
#else
    if (fast_rows(e, x, y, cut, rest, &c.sad) != 0) {
        keep_completed(e, x, y, &c);
    }
#endif
}

/* The open positions of mask m, ascending: columns of row `fix` (row),
   or rows of column `fix` (column). Each bit visited leaves *left. */
static SSDA_ALWAYS_INLINE int open_run(engine_t *e, uint32_t m, uint32_t fix, bool row,
                                       bool quad, uint32_t *left)
{
    int err = SSDA_OK;
    while (m != 0u && err == SSDA_OK) {
        const uint32_t i = low_bit(m);
        if (quad) {
            open_quad(e, row ? i : fix, row ? fix : i);
        } else {
            err = row ? consider_best(e, i, fix) : consider_best(e, fix, i);
        }
        m &= m - 1u;
        (*left)--;
    }
    return err;
}

/* The open positions in bit masks by row (open[y], bit x) and by column
   (open[OPEN_MAX + x], bit y), built once: a ring's four sides are then
   four masked runs, and the rings stop once no open position is left. */
static SSDA_NOINLINE uint32_t open_masks(const engine_t *e, uint32_t *open)
{
    /* bit x of a word, x < 32 */
    static const uint32_t k_bit[OPEN_MAX] = {
        0x1u,        0x2u,        0x4u,        0x8u,       0x10u,      0x20u,
        0x40u,       0x80u,       0x100u,      0x200u,     0x400u,     0x800u,
        0x1000u,     0x2000u,     0x4000u,     0x8000u,    0x10000u,   0x20000u,
        0x40000u,    0x80000u,    0x100000u,   0x200000u,  0x400000u,  0x800000u,
        0x1000000u,  0x2000000u,  0x4000000u,  0x8000000u, 0x10000000u, 0x20000000u,
        0x40000000u, 0x80000000u};
    const uint32_t s = (uint32_t)e->best.sad; /* < 2^32 - 1: e->fast */
    const uint32_t nx = e->nx, ny = e->ny;
    uint32_t *cols = open + OPEN_MAX;
    const uint32_t *pre = e->pre;
    uint32_t i, left = 0u;
    for (i = 0u; i < nx; i++) {
        cols[i] = 0u;
    }
    for (i = 0u; i < ny; i++) {
        uint32_t m = 0u;
        size_t x;
        for (x = 0u; x < (size_t)nx; x++) { /* a table of bits: the loop vectorises */
            m |= k_bit[x] & (0u - (pre[x] <= s ? 1u : 0u));
        }
        if (i == e->ty) {
            m &= ~k_bit[e->tx]; /* visited first */
        }
        open[i] = m;
        while (m != 0u) { /* few: most bounds exceed s */
            cols[low_bit(m)] |= k_bit[i];
            m &= m - 1u;
            left++;
        }
        pre += nx;
    }
    return left;
}

#if KERNEL_LOOPS
/* open_masks for defer_open's case: the bound pass (pre_bounds' work and
   count) and the row masks at once, then the column masks from them. */
static SSDA_NOINLINE uint32_t open_masks_pass(engine_t *e, uint32_t *open)
{
    uint32_t *pre = (uint32_t *)e->plan->work;
    const uint32_t nx = e->nx, ny = e->ny, pitch = e->gpitch;
    uint32_t *cols = open + OPEN_MAX;
    uint32_t i, left = 0u;
    ssda__bounds4_open(pre, e->gsum, pitch, (size_t)4u * pitch, e->wgrp, nx, ny,
                       (uint32_t)e->best.sad /* < 2^32 - 1: e->fast */, open);
    e->ops += (uint64_t)nx * ny * 4u; /* positions x groups, as pre_bounds */
    open[e->ty] &= ~(1u << e->tx); /* visited first */
    for (i = 0u; i < nx; i++) {
        cols[i] = 0u;
    }
    for (i = 0u; i < ny; i++) {
        uint32_t m = open[i];
        while (m != 0u) { /* few: most bounds exceed s */
            cols[low_bit(m)] |= 1u << i;
            m &= m - 1u;
            left++;
        }
    }
    return left;
}
#endif

static SSDA_NOINLINE int scan_predict_open(engine_t *e, uint32_t *open)
{
    const int32_t nx = (int32_t)e->nx, ny = (int32_t)e->ny;
    const int32_t px = (int32_t)e->tx, py = (int32_t)e->ty;
    const uint32_t *cols = open + OPEN_MAX;
    /* tab_refine4's case, as in eval_fast; on x86 only: on the Cortex-M4
       open_quad saved instructions but cost 64 B of stack (tools/budget.sh) */
    const bool quad = KERNEL_LOOPS != 0 && e->integ != NULL && e->L >> 2 == 4u &&
                      e->ngroups == 4u;
    int32_t d, dmax = px;
    uint32_t left;
    int err = consider_best(e, (uint32_t)px, (uint32_t)py); /* no reference: completes */
    if (err != SSDA_OK) {
        return err;
    }
#if KERNEL_LOOPS
    left = defer_open(e) ? open_masks_pass(e, open) : open_masks(e, open);
#else
    left = open_masks(e, open);
#endif
    dmax = nx - 1 - px > dmax ? nx - 1 - px : dmax;
    dmax = py > dmax ? py : dmax;
    dmax = ny - 1 - py > dmax ? ny - 1 - py : dmax;
    for (d = 1; d <= dmax && left != 0u && err == SSDA_OK; d++) {
        /* top, bottom: rows py -+ d, columns lo .. hi (row_span); left,
           right: columns px -+ d, rows y0 .. y1 (col_span; none when
           y0 > y1: d = 1 on a range one row high). The spans made first:
           fewer values live across the evaluations (the M4F's frame; issue
           18's 320 B). One call site of open_run: one copy of the
           evaluation (flash). */
        const uint32_t row_span =
            bit_span((uint32_t)(px - d < 0 ? 0 : px - d), (uint32_t)(px + d >= nx ? nx - 1 : px + d));
        const int32_t y0 = py - d + 1 < 0 ? 0 : py - d + 1;
        const int32_t y1 = py + d - 1 >= ny ? ny - 1 : py + d - 1;
        const uint32_t col_span = y0 <= y1 ? bit_span((uint32_t)y0, (uint32_t)y1) : 0u;
        uint32_t side;
        for (side = 0u; side < 4u && err == SSDA_OK; side++) {
            const int32_t fix = side < 2u ? (side == 0u ? py - d : py + d)
                                          : (side == 2u ? px - d : px + d);
            const bool row = side < 2u;
            uint32_t m = 0u;
            if (row && fix >= 0 && fix < ny) {
                m = open[fix] & row_span;
            } else if (!row && fix >= 0 && fix < nx) {
                m = cols[fix] & col_span;
            } else {
                /* the side lies outside the range */
            }
            err = open_run(e, m, fix < 0 ? 0u : (uint32_t)fix, row, quad, &left);
        }
    }
    /* every position once, as scan_predict counts them */
    e->positions = (uint32_t)nx * (uint32_t)ny;
    return err;
}
#endif /* SSDA_CFG_NO_PREDICT */
#endif

/* Windows with no side above it search by scan_pre rather than the block
   levels: every bound at once and tile candidates cost less than the levels
   up to 64 x 64 px, more from 80 x 80 on textured photographs
   (docs/benchmarks.md, issue 18 session 6). */
#define PRE_MAX_SIDE 64u

/* SSDA_MATCH_BLOCKS left to scan_pre (engine_setup sets pre_scan when
   eval_fast's conditions hold, which these imply): AUTO, raster scan, no
   uniqueness list, rows in memory in row order, every SAD below 2^32 - 1,
   a window with no level (a side below 2 * BLOCK_MIN_SIDE) or no side
   above PRE_MAX_SIDE. */
static bool pre_first(const engine_t *e)
{
#ifndef SSDA_CFG_NO_FAST_PATH
    const ssda_match_plan_t *plan = e->plan;
    const uint32_t L = e->L, M = e->M;
    return (plan->flags & SSDA_MATCH_BLOCKS) != 0u &&
           plan->threshold == (uint8_t)SSDA_THRESHOLD_AUTO &&
           plan->scan == (uint8_t)SSDA_SCAN_RASTER && (plan->flags & SSDA__MATCH_TAB) == 0u &&
           e->list == NULL && e->row_step == 1u && e->area->base != NULL &&
           e->win->base != NULL && L * M <= (e->u8 ? 16843008u : 65536u) &&
           (L < 2u * BLOCK_MIN_SIDE || M < 2u * BLOCK_MIN_SIDE ||
            (L <= PRE_MAX_SIDE && M <= PRE_MAX_SIDE));
#else
    (void)e;
    return false;
#endif
}

/*
 * Bounds tables. First every area row's sliding sums of L pixels, H(x, yy),
 * then in place the vertical sums of `group` consecutive H (rows yy ..
 * yy+group-1), and the window's sums over the same groups of rows.
 * Ranges: H <= L * 65535 <= 65535^2 < 2^32. A group sum <= group * L * maxval:
 * group = 4 unless 16-bit windows wider than 16384 px, where group = 1.
 */
static SSDA_NOINLINE int build_bounds(engine_t *e)
{
    /* The engine's fields in locals: the stores into the tables below could
       alias them (uint32_t), which would reload them in every iteration. */
    const bool u8 = e->area->format == (uint8_t)SSDA_PIX_U8;
    const uint32_t nx = e->nx;
    uint32_t *work = (uint32_t *)e->plan->work;
    uint32_t *gsum = work;
    uint32_t *wgrp = work + (size_t)nx * e->area->height;
    uint32_t group = (!u8 && e->L > 16384u) ? 1u : 4u;
    uint32_t ngroups;
    uint64_t ops = 0u;
    int err;
    if (group > e->M) {
        group = e->M;
    }
    /* M >= 1: the window height */
    ngroups = SSDA_DIV32(e->M, group); /* NOLINT(clang-analyzer-core.DivideZero) */
    e->group = (uint16_t)group;   /* 1..4 */
    e->ngroups = (uint16_t)ngroups; /* <= M */
    e->gsum = gsum;
    e->gpitch = (uint16_t)nx;
    e->wgrp = wgrp;
    e->term = wgrp + e->M;
    if ((e->plan->flags & SSDA__MATCH_TAB) != 0u && group == 4u) { /* track_tab.c */
        const size_t at = ((((size_t)nx * e->area->height + 2u * (size_t)e->M) *
                             sizeof(uint32_t) + 7u) & ~(size_t)7u) + SSDA_MATCH_UNIQUE_WORK;
        err = tab_bounds(e, (ssda__match_tab_t *)(void *)((uint8_t *)work + at), wgrp, u8,
                         &ops);
        e->ops += ops;
        return err;
    }
#ifndef SSDA_CFG_NO_FAST_PATH
    if (pre_first(e)) { /* scan_pre's case: rows in memory, and room for v */
        uint32_t *v = blocks_room(e) + ((size_t)nx * e->ny + SSDA__PRE_CAND_WORDS + e->ny);
        ops = ssda__pre_tables(e->area->base, e->area->stride, u8, e->area->width,
                               e->area->height, e->L, group, gsum, v);
        err = window_groups(e, wgrp, group, ngroups, u8, &ops);
        e->ops += ops;
        return err;
    }
#endif
    err = area_row_sums(e, gsum, u8, &ops);
    if (err == SSDA_OK) {
        if (group > 1u) {
            group_rows(gsum, nx, e->area->height, group, &ops);
        }
        err = window_groups(e, wgrp, group, ngroups, u8, &ops);
    }
    e->ops += ops;
    return err;
}

/* SSDA_MATCH_BLOCKS: the area's integral image in uint32_t modulo 2^32,
   I(x, y) = sum of the pixels left of x and above y, (aw + 1) x (ah + 1)
   entries at `integ`. A row's running sum <= 65535 * 65535 < 2^32; the
   entries wrap, and a block sum taken from four of them is exact whenever
   the block's true sum < 2^32. Two ops per pixel. */
static SSDA_NOINLINE int build_integral(engine_t *e, uint32_t *integ)
{
    const bool u8 = e->u8;
    const uint32_t aw = e->area->width, ah = e->area->height;
    const size_t is = (size_t)aw + 1u;
    uint32_t x, y;
    for (x = 0u; x <= aw; x++) {
        integ[x] = 0u;
    }
    for (y = 0u; y < ah; y++) {
        const uint8_t *p;
        const uint32_t *up = integ + (size_t)y * is;
        uint32_t *row = integ + ((size_t)y + 1u) * is;
        uint32_t s = 0u; /* <= aw * 65535 < 2^32 */
        int err = ssda__rows_get(e->area, 0u, y, aw, &p);
        if (err != SSDA_OK) {
            return err;
        }
        row[0] = 0u;
        for (x = 0u; x < aw; x++) {
            s += u8 ? p[x] : ((const uint16_t *)(const void *)p)[x];
            row[x + 1u] = up[x + 1u] + s; /* modulo 2^32 */
        }
    }
    {
        const uint32_t pixels = aw * ah; /* < 2^32 */
        e->ops += pixels;
        e->ops += pixels; /* two ops a pixel */
    }
    return SSDA_OK;
}

/* SSDA_MATCH_BLOCKS: the window's block sums of levels lev_lo..lev_hi,
   each summed from its pixels (< 2^32: the level's condition), stored at
   the level's offset (4 + 16 + ... entries before it). L * M ops a level. */
static SSDA_NOINLINE int window_blocks(engine_t *e, uint32_t *wblk)
{
    uint32_t l;
    for (l = e->lev_lo; l <= e->lev_hi; l++) {
        const uint32_t nb = 1u << l, bw = (uint32_t)e->L >> l, bh = (uint32_t)e->M >> l;
        uint32_t *w = wblk + (((1u << (2u * l)) - 4u) / 3u);
        uint32_t i, j, yy, c;
        for (i = 0u; i < nb * nb; i++) {
            w[i] = 0u;
        }
        for (j = 0u; j < nb; j++) {
            for (yy = j * bh; yy < (j + 1u) * bh; yy++) {
                const uint8_t *p;
                int err = ssda__rows_get(e->win, 0u, yy, nb * bw, &p);
                if (err != SSDA_OK) {
                    return err;
                }
                for (c = 0u; c < nb * bw; c++) {
                    /* a block's sum <= bw * bh * maxval < 2^32 */
                    w[j * nb + c / bw] += e->u8 ? p[c] : ((const uint16_t *)(const void *)p)[c];
                }
            }
        }
        {
            const uint32_t pixels = (nb * bw) * (nb * bh); /* <= L * M < 2^32 */
            e->ops += pixels;
        }
    }
    return SSDA_OK;
}

/*
 * SSDA_MATCH_BLOCKS: choose the levels and build their tables after the
 * bounds tables and the uniqueness list (match.h's layout). Level l splits
 * the window into 2^l x 2^l blocks of (L >> l) x (M >> l) pixels, l = 1 ..
 * SSDA_MATCH_BLOCK_LEVELS; it is used when both sides are at least
 * BLOCK_MIN_SIDE and a block's sum fits 32 bits (bw * bh * maxval < 2^32).
 * With no level usable, the search runs as with SSDA_MATCH_BOUNDS alone.
 */
static SSDA_NOINLINE int build_blocks(engine_t *e)
{
    const uint32_t max_px = e->u8 ? 16843009u : 65537u; /* floor((2^32 - 1) / maxval) */
    uint32_t *integ = blocks_room(e);
    uint32_t *wblk;
    uint32_t l;
    int err;
    e->lev_lo = 1u;
    e->lev_hi = 0u;
    for (l = 1u; l <= SSDA_MATCH_BLOCK_LEVELS; l++) {
        const uint32_t bw = (uint32_t)e->L >> l, bh = (uint32_t)e->M >> l; /* <= 32767 */
        if (bw < BLOCK_MIN_SIDE || bh < BLOCK_MIN_SIDE) {
            break;
        }
        if (bw * bh > max_px) {
            e->lev_lo = (uint8_t)(l + 1u);
        } else {
            e->lev_hi = (uint8_t)l;
        }
    }
    if (e->lev_lo > e->lev_hi) {
        return SSDA_OK;
    }
    wblk = integ + ((size_t)e->area->width + 1u) * ((size_t)e->area->height + 1u);
    e->integ = integ;
    e->wblk = wblk;
    err = build_integral(e, integ);
    if (err == SSDA_OK) {
        err = window_blocks(e, wblk);
    }
    return err;
}

#endif

/* The result of a finished scan, with the quality the plan asks for
   (written only when every fetch succeeded). Out of line: its locals stay
   off the frame that holds the engine during the scan. */
static SSDA_NOINLINE int finish(engine_t *e, ssda_match_result_t *result)
{
    const ssda_match_plan_t *plan = e->plan;
    int16_t sx = 0, sy = 0;
    uint16_t uq = (uint16_t)SSDA_MATCH_UNIQUE_NONE;
#ifndef SSDA_CFG_NO_BOUNDS
    if (e->pre == NULL) { /* else counted once for every position */
        e->ops += (uint64_t)e->nbound * e->ngroups;
    }
#endif
#ifdef ENGINE_FALLBACK
    uint64_t fb_sad = 0u; /* the fallback's full SAD: <= 65535^3 */
    if (e->n_best == 0u) { /* FIXED/RAMP, every position cut: have_fb */
        int err = ssda__sad_full(e->area, e->win, e->fb.x, e->fb.y, &e->ops, &fb_sad);
        if (err != SSDA_OK) {
            return err;
        }
    }
#endif
#ifndef SSDA_CFG_NO_SUBPIXEL
    if ((plan->flags & SSDA_MATCH_SUBPIXEL) != 0u) { /* exact modes: some position completed */
#ifndef SSDA_CFG_NO_UNIQUE
        const uint32_t nlist = e->nlist; /* the search's full SADs */
#else
        const uint32_t nlist = 0u;
#endif
        int err = ssda__subpixel(e->area, e->win, e->list, nlist, &e->best, e->nx, e->ny,
                                 &e->ops, &sx, &sy);
        if (err != SSDA_OK) {
            return err;
        }
    }
#endif
#ifndef SSDA_CFG_NO_UNIQUE
    if (e->list != NULL) { /* exact modes too */
        uq = ssda__unique_q8(e->list, e->nlist, &e->best, plan->unique_q8,
                             plan->unique_radius);
    }
#endif
    result->sub_x_q8 = sx;
    result->sub_y_q8 = sy;
    result->unique_q8 = uq;
#ifdef ENGINE_FALLBACK
    if (e->n_best == 0u) {
        /* every position cut (FIXED/RAMP): the paper's fallback, reported
           with its full SAD (summed here; fb.sad is only a lower bound) */
        result->sad = fb_sad;
        result->x = (uint16_t)e->fb.x;
        result->y = (uint16_t)e->fb.y;
        result->exact = false;
    } else
#endif
    {
        result->sad = e->best.sad;
        result->x = (uint16_t)e->best.x;
        result->y = (uint16_t)e->best.y;
        result->exact = plan->scan != (uint8_t)SSDA_SCAN_COARSE &&
                        (plan->threshold == (uint8_t)SSDA_THRESHOLD_AUTO ||
                         plan->threshold == (uint8_t)SSDA_THRESHOLD_NONE ||
                         plan->threshold == (uint8_t)SSDA_THRESHOLD_FIXED);
    }
    result->positions = e->positions;
    result->completed = e->completed;
    result->pixel_ops = e->ops;
    return SSDA_OK;
}

/*
 * The engine set up from its area, win and plan (the fields its caller
 * set; any others are cleared here): geometry, the mode's flags, the bound
 * tables. SSDA_OK or a fetch error. Out of line: its locals stay off the
 * frame under the scan.
 */
static SSDA_NOINLINE int engine_setup(engine_t *e, int32_t predict_x, int32_t predict_y)
{
    const ssda__rows_t *area = e->area;
    const ssda__rows_t *window = e->win;
    const ssda_match_plan_t *plan = e->plan;
    const uint8_t mode = plan->threshold;
    (void)memset(e, 0, sizeof *e);
    e->area = area;
    e->win = window;
    e->plan = plan;
#ifdef SSDA_CFG_NO_U16
    if (area->format != (uint8_t)SSDA_PIX_U8) {
        return SSDA_ERR_UNSUPPORTED;
    }
#endif

    e->L = window->width;
    e->M = window->height;
    e->nx = (uint16_t)(area->width - e->L + 1u); /* 1 .. 65535 */
    e->ny = (uint16_t)(area->height - e->M + 1u);
    e->tx = (uint16_t)clamp_pos(predict_x, e->nx);
    e->ty = (uint16_t)clamp_pos(predict_y, e->ny);

    e->u8 = area->format == (uint8_t)SSDA_PIX_U8;
#ifndef SSDA_CFG_NO_UNIQUE
    if (plan->unique_radius != 0u) {
        const uint32_t side = 2u * plan->unique_radius + 1u; /* 3 or 5 */
        e->list = (cand_t *)plan->list;
        e->cap = (uint8_t)(side * side + 1u);
        e->loose = UINT64_MAX;
    }
#endif
    e->row_step = (uint16_t)plan->row_step; /* < M */
    /* the mode's flags, derived from the plan */
    e->bounds = (plan->flags & SSDA_MATCH_BOUNDS) != 0u && mode != (uint8_t)SSDA_THRESHOLD_NONE;
    e->ramp_mode = mode == (uint8_t)SSDA_THRESHOLD_RAMP || mode == (uint8_t)SSDA_THRESHOLD_AUTO_RAMP;
    e->tie_near = (plan->flags & SSDA_MATCH_TIE_NEAREST) != 0u;
#ifdef ENGINE_FALLBACK
    e->need_fb = mode == (uint8_t)SSDA_THRESHOLD_FIXED || mode == (uint8_t)SSDA_THRESHOLD_RAMP;
#endif
    e->use_ref = mode == (uint8_t)SSDA_THRESHOLD_AUTO ||
                 mode == (uint8_t)SSDA_THRESHOLD_AUTO_RAMP ||
                 (mode != (uint8_t)SSDA_THRESHOLD_NONE &&
                  (e->bounds || plan->scan == (uint8_t)SSDA_SCAN_COARSE));
#ifndef SSDA_CFG_NO_BOUNDS
    e->lev_lo = 1u; /* no block levels */
    if (e->bounds) {
        int err = SSDA_OK;
        if ((plan->flags & SSDA_MATCH_BLOCKS) != 0u && !pre_first(e)) {
            err = build_blocks(e);
        }
        if (e->lev_lo <= e->lev_hi && mode == (uint8_t)SSDA_THRESHOLD_AUTO &&
            plan->scan == (uint8_t)SSDA_SCAN_RASTER) {
            /* the levels and the seed's table take the row groups' place:
               the few positions that pass every level are summed without them */
            e->low = (uint32_t *)plan->work;
            e->term = e->wblk + SSDA_MATCH_BLOCK_SUMS - SSDA_MATCH_BLOCK_ROWS;
            e->bounds = false;
        } else if (err == SSDA_OK) {
            err = build_bounds(e);
        } else {
            /* a fetch error: returned below */
        }
        if (err != SSDA_OK) {
            return err;
        }
    }
#endif
#ifndef SSDA_CFG_NO_FAST_PATH
    e->plain_ref = e->use_ref && e->list == NULL && !e->tie_near;
    /* every SAD of the window < 2^32 - 1: L * M * maxval, with L * M <=
       16843008 (8-bit) or 65536 (16-bit); no 64-bit multiply on the M0+ */
    e->fast = !e->ramp_mode && e->row_step == 1u && area->base != NULL &&
              window->base != NULL && (uint32_t)e->L * e->M <= (e->u8 ? 16843008u : 65536u);
#ifdef ENGINE_FALLBACK
    e->fast = e->fast && !e->need_fb;
#endif
#ifndef SSDA_CFG_NO_BOUNDS
    e->fast = e->fast && e->low == NULL && e->lev_lo > e->lev_hi;
    if (e->fast && e->bounds && e->list == NULL && e->gsum != NULL &&
        e->gsum != (const uint32_t *)plan->work && plan->scan != (uint8_t)SSDA_SCAN_COARSE) {
        pre_bounds(e); /* shared tables (tab_bounds): every bound at once */
    }
    /* pre_first's case (BLOCKS implies BOUNDS, match.c; tracking refuses
       BLOCKS, so no shared tables): with e->fast no level was built, and
       their room holds the bounds (scan_pre) */
    e->pre_scan = e->fast && pre_first(e);
#endif
#endif /* SSDA_CFG_NO_FAST_PATH */
    return SSDA_OK;
}

/*
 * The search on an engine whose area, win and plan are set: its setup, the
 * scan and the result. Inlined into ssda__match_rows (the engine on its
 * frame: one frame, as before the state existed) and ssda__match_state.
 */
static SSDA_ALWAYS_INLINE int engine_go(engine_t *e, int32_t predict_x, int32_t predict_y,
                                        ssda_match_result_t *result)
{
    int err = engine_setup(e, predict_x, predict_y);
    if (err != SSDA_OK) {
        return err;
    }
#if !defined(SSDA_CFG_NO_BOUNDS) && !defined(SSDA_CFG_NO_FAST_PATH)
    if (e->pre_scan) {
        err = scan_pre(e);
    } else
#endif
#ifndef SSDA_CFG_NO_BOUNDS
    if (e->low != NULL) {
        err = scan_seeded(e);
    } else
#endif
#ifndef SSDA_CFG_NO_PREDICT
#if !defined(SSDA_CFG_NO_FAST_PATH) && !defined(SSDA_CFG_NO_BOUNDS)
    if (e->pre != NULL && e->plan->scan == (uint8_t)SSDA_SCAN_PREDICT && e->nx <= OPEN_MAX &&
        e->ny <= OPEN_MAX) {
        /* the uniqueness list's place: list == NULL with pre_bounds */
        err = scan_predict_open(e, (uint32_t *)(void *)((uint8_t *)e->plan->work +
                                                         open_at(e)));
    } else
#endif
    if (e->plan->scan == (uint8_t)SSDA_SCAN_PREDICT) {
        err = scan_predict(e);
    } else
#endif
#ifndef SSDA_CFG_NO_COARSE
    if (e->plan->scan == (uint8_t)SSDA_SCAN_COARSE) {
        err = scan_coarse(e);
    } else
#endif
    {
        err = scan_raster(e);
    }
    /* the else-if chain above is cut by the preprocessor: */
    if (err != SSDA_OK) { /* NOLINT(readability-misleading-indentation) */
        return err;
    }
    return finish(e, result);
}

int ssda__match_rows(const ssda__rows_t *area, const ssda__rows_t *window,
                     const ssda_match_plan_t *plan, int32_t predict_x, int32_t predict_y,
                     ssda_match_result_t *result)
{
    engine_t e; /* cleared by engine_setup */
    e.area = area;
    e.win = window;
    e.plan = plan;
    return engine_go(&e, predict_x, predict_y, result);
}

/* ssda_match_state_t's private layout: match.c's head, then the engine.
   The public struct holds SSDA_MATCH_STATE_PTRS pointers and
   SSDA_MATCH_STATE_WORDS uint64_t, so it is aligned at least as this one
   (pointers and integers of at most 64 bits); a negative array size below
   stops the build if this state outgrows it (then raise the counts in
   include/ssda/match.h: a new pointer needs one more of the first, every 8
   other bytes one more of the second). */
typedef struct {
    ssda__match_head_t head;
    engine_t e;
} match_state_t;

typedef char match_state_fits[(sizeof(match_state_t) <= sizeof(ssda_match_state_t)) ? 1 : -1];

int ssda__match_state(ssda_match_state_t *state, int32_t predict_x, int32_t predict_y,
                      ssda_match_result_t *result)
{
    match_state_t *s = (match_state_t *)(void *)state;
    (void)sizeof(match_state_fits);
    s->e.area = &s->head.area;
    s->e.win = &s->head.win;
    s->e.plan = &s->head.plan;
    /* reached by a tail call from ssda_match_search where the target makes
       them: then this frame is the only one between the caller's and the
       scan's (docs/target.md) */
    return engine_go(&s->e, predict_x, predict_y, result);
}
