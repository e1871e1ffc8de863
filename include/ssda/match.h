/*
 * match.h - SSDA template search: find where window W (L x M) best fits in a
 * search area S (L' x M' >= L x M) by the sum of absolute differences (SAD),
 * abandoning a position as soon as its partial sum shows it cannot win.
 *
 * Seed: Onoe, Maeda, Saito 1976 (SSDA with automatic thresholds), sections 2
 * and 4; Barnea & Silverman 1972 for the fixed and increasing thresholds.
 *
 * Positions: (x, y) is the top-left of the window placement in the area,
 * 0-based, x right, y down; 0 <= x <= L'-L, 0 <= y <= M'-M.
 *
 * TIE RULE: the best position has the smallest SAD; among equal SADs the
 * smallest y, then the smallest x (with SSDA_MATCH_TIE_NEAREST: the one
 * nearest to the prediction first, as tracking does). In the exact modes
 * (SSDA_THRESHOLD_AUTO and SSDA_THRESHOLD_NONE with the raster or predict
 * scan) every scan, pixel order, bound option and kernel returns the same
 * (x, y, sad), and the same quality (SSDA_MATCH_UNIQUE, SSDA_MATCH_SUBPIXEL).
 *
 * Overflow: widths and heights are at most 65535, samples at most 65535, so
 * one window row's SAD is at most 65535 * 65535 = 4 294 836 225 < 2^32 and is
 * summed in uint32_t; a whole window's SAD is at most 65535^3 < 2^48 and is
 * summed in uint64_t. Every call is exact at every accepted size.
 */
#ifndef SSDA_MATCH_H
#define SSDA_MATCH_H

#include "ssda/view.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Threshold mode: how a position's partial SAD is cut. */
typedef enum {
    /* Onoe-Saito automatic constant threshold: the first position is summed
       in full and its SAD becomes the threshold; each later position that
       completes with a better SAD lowers it. Always the true minimum. */
    SSDA_THRESHOLD_AUTO = 0,
    /* Brute force: every position summed in full (the reference). */
    SSDA_THRESHOLD_NONE = 1,
    /* Constant threshold T = fixed_threshold: a position is cut once its
       partial SAD exceeds T. If any position completes, the best completed
       one is the true minimum (exact). If every position is cut, the result
       is the position that summed the most pixels before its cut (the
       paper's fallback), ties by the smallest lower bound of its SAD known
       at the cut (partial SAD plus, with bounds, the bound of the rows not
       summed), then by the tie rule; flagged not exact, completed 0, and
       reported with its full SAD (summed once more: L x M pixel ops). A
       position rejected by its bound before any pixel was summed counts 0
       pixels: it is the fallback only when every position was rejected so,
       and then the one with the smallest bound. */
    SSDA_THRESHOLD_FIXED = 2,
    /* Barnea-Silverman increasing threshold, eq. 3:
       T(r) = lambda * (r + K * sqrt(r)), r = pixels summed so far.
       May miss the minimum: result always flagged not exact. All-cut
       fallback as SSDA_THRESHOLD_FIXED. */
    SSDA_THRESHOLD_RAMP = 3,
    /* Automatic increasing threshold, eq. 4: after a completed SAD T_i,
       T(r) = min(T_i, T_i / (L*M) * (r + K * sqrt(r))). Faster than AUTO,
       may miss the minimum: flagged not exact. */
    SSDA_THRESHOLD_AUTO_RAMP = 4
} ssda_threshold_t;

/* Order in which positions are visited. */
typedef enum {
    /* Rows of positions top to bottom, each left to right. */
    SSDA_SCAN_RASTER = 0,
    /* Square rings outward from the predicted position (predict_x,
       predict_y), clamped into range, so a good prediction sets a low
       threshold at once (the seed's prediction, Table 3). Exact with AUTO. */
    SSDA_SCAN_PREDICT = 1,
    /* Coarse-to-fine (Hall et al., as in the seed): positions on a grid of
       coarse_step, keep the best two, then from each move 1 px up, down,
       left or right to the best neighbour until none improves; the better of
       the two wins. Fast, may miss the minimum: flagged not exact. */
    SSDA_SCAN_COARSE = 2
} ssda_scan_t;

/* Order in which the rows of a window are summed at each position. */
typedef enum {
    SSDA_ORDER_ROWS = 0,       /* rows 0, 1, ..., M-1 */
    /* A fixed decorrelated permutation of rows: row k*s mod M for
       k = 0..M-1, with s the largest step <= 0.618*M coprime to M (golden-
       ratio stride; M = 16 gives 0, 9, 2, 11, 4, ...). Neighbouring,
       correlated rows are not summed one after another, so a bad position is
       cut sooner (the seed's random visiting order, made deterministic).
       Exact with AUTO. */
    SSDA_ORDER_SPREAD = 1
} ssda_order_t;

/*
 * Flag: successive-elimination bounds (Li & Salari's SEA in the multilevel
 * form of Gao et al.). The window's rows are taken in groups of G = 4
 * (G = 1 for 16-bit windows wider than 16384 px, G = M for windows of fewer
 * than 4 rows; a last partial group is left out). With A_k(x, y) the sum of the area pixels under group k and W_k the
 * window's, the triangle inequality gives, at every position,
 *     sum_k |A_k(x, y) - W_k| <= SAD(x, y),
 * so a position is rejected from G-row sums alone, at one operation per group,
 * before its pixels are touched. In row order the bound of the groups not yet
 * started is added to the partial SAD after every row, so positions are cut
 * sooner too. Exact: it never rejects a position that could win. The sums
 * come from sliding sums built once per search in the work buffer (counted
 * in pixel_ops: one op per pixel added or removed in a sliding sum, and one
 * per group term of a bound). Ignored by SSDA_THRESHOLD_NONE (the reference).
 *
 * With bounds, every mode also cuts a position as soon as it provably cannot
 * beat the best completed position (by the tie rule); this never changes
 * which position wins once one has completed. Without bounds, FIXED and RAMP
 * are the paper's algorithms unchanged.
 */
#define SSDA_MATCH_BOUNDS 0x01u

/*
 * Flag: the tie rule of tracking. Among equal SADs the position nearest to
 * the prediction (predict_x, predict_y), clamped into the range as the
 * PREDICT scan clamps it, wins: the smallest (x - px)^2 + (y - py)^2, then
 * the smallest y, then the smallest x. Any scan; the exact modes still
 * return the minimum (it only decides between equal SADs). Cost: on equal
 * SADs, two squared distances.
 */
#define SSDA_MATCH_TIE_NEAREST 0x02u

/*
 * Flag: uniqueness, exact. Besides the best position, the best SAD among
 * positions outside the (2R+1) x (2R+1) square centred on it (R =
 * unique_radius) is found whenever it is at most unique_q8 / 256 times the
 * best SAD (floor(unique_q8 * sad / 256)); result.unique_q8 is then
 * floor(256 * that SAD / sad), in 256 .. unique_q8 (256 when both are 0),
 * else SSDA_MATCH_UNIQUE_NONE: no other minimum comes that close.
 * How: positions are cut at the ratio times the best SAD instead of the best
 * SAD, so every position within the ratio is summed in full, and the
 * (2R+1)^2 + 1 smallest completed positions are kept in the work buffer (at
 * most (2R+1)^2 of them lie in the square, so the best outside it is always
 * kept). Cost: the positions within the ratio are summed in full instead of
 * being cut after a few rows (about 10 % more pixel_ops on textured image
 * pairs, docs/tracking.md). Exact modes only (AUTO or NONE; raster or
 * predict scan); needs SSDA_MATCH_UNIQUE_WORK bytes of work buffer (after
 * the bounds tables: SSDA_MATCH_WORK_SIZE_UNIQUE).
 */
#define SSDA_MATCH_UNIQUE 0x04u
/* result.unique_q8 when no position outside the square is within the ratio */
#define SSDA_MATCH_UNIQUE_NONE 0xFFFFu
/* Defaults, chosen from data (docs/tracking.md): ratio 1.10 in Q8.8
   (282 / 256 = 1.1016) and radius 2 (a 5 x 5 square). */
#define SSDA_MATCH_DEFAULT_UNIQUE_Q8 282u
#define SSDA_MATCH_DEFAULT_UNIQUE_RADIUS 2u
/* The largest radius, and the bytes of the list of the smallest completed
   positions: (2 * 2 + 1)^2 + 1 = 26 entries of 16 bytes. */
#define SSDA_MATCH_MAX_UNIQUE_RADIUS 2u
#define SSDA_MATCH_UNIQUE_WORK 416u

/*
 * Flag: sub-pixel position. After the search, the SADs l, c, r of the best
 * position and its two neighbours on each axis (from the search when it
 * summed them in full, else summed now) give an equiangular (V-shaped) fit:
 *     offset = (l - r) / (2 (max(l, r) - c)),  |offset| <= 1/2 px,
 * the exact minimum of a symmetric V through the three points (a SAD, a sum
 * of absolute differences, grows linearly on each side of its minimum; a
 * parabola suits squared differences and pulls SAD estimates toward whole
 * pixels). result.sub_x_q8, sub_y_q8: the offset in Q8.8 px (-128 .. 128),
 * rounded half away from zero; 0 on an axis where the best position is on
 * the border of the range (no neighbour) or all three SADs are equal, and
 * 0 on both axes when c = 0: an exact match lies at its whole-pixel
 * placement (the neighbours' SADs then differ only through the window's
 * border pixels, which gave identical frames fractions up to 0.4 px).
 * Exact modes only. Cost: at most 4 window SADs.
 */
#define SSDA_MATCH_SUBPIXEL 0x08u

/*
 * Flag: multilevel block bounds (Gao et al.'s multilevel successive
 * elimination), with SSDA_MATCH_BOUNDS (alone: SSDA_ERR_ARG). Level l splits
 * the window into 2^l x 2^l blocks of (L >> l) x (M >> l) pixels (right and
 * bottom remainders left out), l = 1 .. SSDA_MATCH_BLOCK_LEVELS; with B_b(x, y)
 * the sum of the area pixels under block b and W_b the window's,
 *     sum_b |B_b(x, y) - W_b| <= SAD(x, y),
 * and a finer level's bound is at least as tight when the block sides are
 * even. A position is tested level after level, coarsest first (2^(2l)
 * operations each), before its pixels; a level is used when both block
 * sides are at least 16 px and a block's sum fits in 32 bits (16-bit
 * windows: (L >> l) * (M >> l) <= 65537), so windows narrower or lower than
 * 32 px use none (the search is then SSDA_MATCH_BOUNDS's, or the one below). Block sums come
 * from the area's integral image in the work buffer (uint32_t modulo 2^32:
 * a block's sum is exact when it fits 32 bits).
 * With AUTO and the raster scan: a first pass computes every position's
 * coarsest bound into the work buffer (in place of the row groups) and
 * keeps, in each of 4 x 4 tiles of the positions, the 8 smallest; of
 * these, the one with the smallest finest-level bound is a candidate, and
 * the 16 candidates are summed first, best first, so the threshold is low
 * from the start; then the raster scan visits the others (each position
 * once), rejecting from the stored bound, then by the next level only
 * (finer ones cost more than they reject), and in row order that level's
 * rows of blocks serve as the row groups of SSDA_MATCH_BOUNDS.
 * Other scans and modes test the levels before the row groups.
 * Windows with no side above 64 px, or a side below 32 px (no level), with
 * AUTO, the raster scan, no SSDA_MATCH_UNIQUE, row order, pixels in memory
 * (ssda_match) and every SAD below 2^32 - 1 (L * M * maxval; 16-bit:
 * L * M <= 65536) use no level either: every position's
 * SSDA_MATCH_BOUNDS bound is computed at once into the levels' room (one
 * op per group term), the position of the smallest bound in each of 4 x 4
 * tiles of the positions is summed first, smallest first, and then in
 * raster order only the positions whose bound does not exceed the best SAD
 * so far are evaluated (there cheaper than the levels: issue 18,
 * docs/benchmarks.md).
 * Exact as SSDA_MATCH_BOUNDS: every result field but pixel_ops, positions
 * and completed is that of the search without the flag (FIXED and RAMP's
 * all-cut fallback: the bound at a rejection is the level's). pixel_ops
 * counts the work: 2 per area pixel for the integral image, L * M per level
 * for the window's block sums, 1 per block term of a bound (the coarsest
 * level once per position, in the first pass). Needs
 * SSDA_MATCH_WORK_SIZE_BLOCKS(...) bytes of work buffer.
 */
#define SSDA_MATCH_BLOCKS 0x10u
/* The finest block level: 2^4 x 2^4 = 256 blocks. */
#define SSDA_MATCH_BLOCK_LEVELS 4u
/* The window's block sums of levels 1..4 (4 + 16 + 64 + 256 entries), the
   raster scan's kept positions (16 tiles x 8, 3 entries each) and 16 first
   candidates (3 entries each), and the terms of up to 16 rows of blocks,
   uint32_t. */
#define SSDA_MATCH_BLOCK_SUMS 788u
#define SSDA_MATCH_BLOCK_ROWS 16u

/* Bytes of work buffer that SSDA_MATCH_BOUNDS needs for an area of
   area_w x area_h and a window of win_w x win_h (win_* <= area_*). Where
   size_t is 32 bits the macro wraps for jobs needing 4 GB or more (areas
   near 65535 x 65535); the library checks the size in 64 bits and refuses
   such a job with SSDA_ERR_BUFFER whatever the buffer. */
#define SSDA_MATCH_WORK_SIZE(area_w, area_h, win_w, win_h)                   \
    (((((size_t)(area_w) - (size_t)(win_w)) + 1u) * (size_t)(area_h) +       \
      2u * (size_t)(win_h)) * sizeof(uint32_t))

/* Bytes of work buffer for SSDA_MATCH_BOUNDS and SSDA_MATCH_UNIQUE together
   (the bounds tables rounded up to 8 bytes, then the list; enough for either
   flag alone too). Wraps like SSDA_MATCH_WORK_SIZE. */
#define SSDA_MATCH_WORK_SIZE_UNIQUE(area_w, area_h, win_w, win_h)            \
    (((SSDA_MATCH_WORK_SIZE(area_w, area_h, win_w, win_h) + 7u) & ~(size_t)7u) + \
     (size_t)SSDA_MATCH_UNIQUE_WORK)

/* Bytes of work buffer for SSDA_MATCH_BLOCKS (with SSDA_MATCH_BOUNDS, and
   SSDA_MATCH_UNIQUE if wanted): the bounds tables and the list as above,
   then the area's integral image, (area_w + 1) x (area_h + 1) uint32_t,
   and the window's block sums. Wraps like SSDA_MATCH_WORK_SIZE. */
#define SSDA_MATCH_WORK_SIZE_BLOCKS(area_w, area_h, win_w, win_h)            \
    (SSDA_MATCH_WORK_SIZE_UNIQUE(area_w, area_h, win_w, win_h) +             \
     (((size_t)(area_w) + 1u) * ((size_t)(area_h) + 1u) +                    \
      (size_t)SSDA_MATCH_BLOCK_SUMS) * sizeof(uint32_t))

/* Default K (safety factor of eqs. 3 and 4) in Q8.8: 2.0, the seed's value. */
#define SSDA_DEFAULT_K_Q8 512u
/* Default coarse grid step in pixels (the seed's 8). */
#define SSDA_DEFAULT_COARSE_STEP 8u

/*
 * Search options. A zero-filled struct is valid: AUTO threshold, raster scan,
 * row order, no bounds (exact brute-force result with early exit).
 */
typedef struct {
    uint8_t threshold;        /* ssda_threshold_t */
    uint8_t scan;             /* ssda_scan_t */
    uint8_t order;            /* ssda_order_t */
    uint8_t flags;            /* SSDA_MATCH_BOUNDS | _TIE_NEAREST | _UNIQUE | _SUBPIXEL | _BLOCKS */
    uint16_t k_q8;            /* K of eqs. 3/4, Q8.8, 0..65535 (0 = SSDA_DEFAULT_K_Q8) */
    uint16_t coarse_step;     /* SSDA_SCAN_COARSE grid step, px (0 = 8) */
    uint32_t lambda_q8;       /* RAMP: lambda of eq. 3, SAD units per pixel, Q24.8 */
    uint64_t fixed_threshold; /* FIXED: T, SAD units */
    int32_t predict_x;        /* PREDICT, TIE_NEAREST: predicted top-left x in area */
    int32_t predict_y;        /*   coordinates; any value, clamped into the range */
    uint16_t unique_q8;       /* UNIQUE: ratio, Q8.8, 257 .. 1024 (0 = 282, 1.10) */
    uint8_t unique_radius;    /* UNIQUE: square radius R, 1 or 2 (0 = 2) */
    void *work;               /* BOUNDS: caller buffer, 4-byte aligned, >=
                                 SSDA_MATCH_WORK_SIZE(...) bytes; UNIQUE: 8-byte
                                 aligned, >= SSDA_MATCH_UNIQUE_WORK bytes, or with
                                 BOUNDS >= SSDA_MATCH_WORK_SIZE_UNIQUE(...);
                                 BLOCKS: >= SSDA_MATCH_WORK_SIZE_BLOCKS(...) */
    size_t work_size;         /* bytes of work; else unused */
} ssda_match_config_t;

/*
 * Private (read no field): a search resolved once, as CMSIS-DSP's instance
 * structs are: the options checked, defaults and derived values filled in
 * for one window size, so that jobs running many searches (tracking, push
 * mode) check nothing per window. It lives in their state (ssda_push_t).
 */
typedef struct {
    uint64_t fixed_cut;   /* FIXED: T + 1 (cut when partial > T); else UINT64_MAX */
    void *work;           /* SSDA_MATCH_BOUNDS: the caller's work buffer */
    uint32_t lambda_q8;   /* RAMP: lambda of eq. 3 */
    uint32_t row_step;    /* row order: row r is followed by r + row_step (mod M) */
    uint16_t k_q8;        /* K of eqs. 3/4 (default resolved) */
    uint16_t coarse_step; /* SSDA_SCAN_COARSE grid step (default resolved) */
    uint8_t threshold;    /* ssda_threshold_t */
    uint8_t scan;         /* ssda_scan_t */
    uint8_t flags;        /* SSDA_MATCH_* flags as given */
    uint8_t unique_radius; /* SSDA_MATCH_UNIQUE: R (resolved); 0 = no uniqueness */
    uint16_t unique_q8;   /* SSDA_MATCH_UNIQUE: the ratio (resolved) */
    void *list;           /* SSDA_MATCH_UNIQUE: the list, in the work buffer */
} ssda_match_plan_t;

/* Outcome of one search. */
typedef struct {
    uint64_t sad;        /* full SAD at (x, y), in every mode (an all-cut
                            fallback's too: completed == 0, exact false) */
    uint64_t pixel_ops;  /* absolute differences computed, plus bound work
                            (and the fallback's full SAD) */
    uint32_t positions;  /* position evaluations (raster and predict scans visit
                            each position once; coarse may revisit) */
    uint32_t completed;  /* positions whose SAD was summed over all pixels */
    uint16_t x;          /* best top-left column in the area */
    uint16_t y;          /* best top-left row in the area */
    int16_t sub_x_q8;    /* SSDA_MATCH_SUBPIXEL: the minimum lies at x + sub_x_q8 / 256 */
    int16_t sub_y_q8;    /*   and y + sub_y_q8 / 256 (-128 .. 128); else 0 */
    uint16_t unique_q8;  /* SSDA_MATCH_UNIQUE: see the flag; else SSDA_MATCH_UNIQUE_NONE */
    bool exact;          /* true: (x, y, sad) is the true minimum by the tie rule */
} ssda_match_result_t;

/*
 * Search *window over *area: ssda_match_search with its state (280 bytes on
 * 32-bit targets) on this function's stack frame; worst-case stack 616
 * bytes on the Cortex-M4F at -Os (docs/target.md).
 *   area, window: valid views of the same pixel format; window no larger
 *                 than area in either dimension. Not modified.
 *   cfg:          options; NULL means all defaults (AUTO, raster, rows).
 *   result:       written on success only.
 * Returns SSDA_OK, or without writing *result:
 *   SSDA_ERR_NULL     area, window or result NULL; bounds or uniqueness
 *                     requested with a NULL work buffer
 *   SSDA_ERR_SIZE/_STRIDE/_FORMAT  invalid views (see ssda_view_check);
 *                     SSDA_ERR_SIZE also when the window is larger than the area
 *   SSDA_ERR_FORMAT   area and window formats differ
 *   SSDA_ERR_ARG      unknown threshold/scan/order/flags value, or RAMP with
 *                     lambda_q8 == 0; UNIQUE or SUBPIXEL with a threshold
 *                     other than AUTO and NONE or with the COARSE scan;
 *                     unique_q8 not 0 and outside 257 .. 1024; unique_radius > 2;
 *                     BLOCKS without BOUNDS
 *   SSDA_ERR_BUFFER   bounds, blocks or uniqueness requested with work_size below
 *                     what they need (macros above), or a misaligned work buffer
 *   SSDA_ERR_UNSUPPORTED  UNIQUE or SUBPIXEL in a build without them
 *                     (SSDA_CFG_NO_UNIQUE, SSDA_CFG_NO_SUBPIXEL)
 */
int ssda_match(const ssda_view_t *area, const ssda_view_t *window,
               const ssda_match_config_t *cfg, ssda_match_result_t *result);

/*
 * A search's working state held by the caller (ssda_match_search): the
 * resolved options, the two row sources and the search engine (the best
 * positions so far, counters, the bound tables' addresses), which
 * ssda_match keeps on its own stack. Caller-allocated: static storage, a
 * member of a job's struct, or a stack with the room; no initialisation;
 * reusable for any number of searches one after another, its contents
 * meaningless between them (nothing to validate, nothing to release). One
 * state per search running at the same time (threads, interrupts).
 * Fields private: only its size matters, sizeof(ssda_match_state_t):
 * SSDA_MATCH_STATE_PTRS pointers and SSDA_MATCH_STATE_WORDS 64-bit words
 * (280 bytes on 32-bit targets, 368 on 64-bit hosts), aligned as both; the
 * library checks at compile time that its state fits (lib/match_engine.c).
 */
#define SSDA_MATCH_STATE_PTRS 22u
#define SSDA_MATCH_STATE_WORDS 24u
typedef struct {
    void *ptrs_[SSDA_MATCH_STATE_PTRS];       /* private */
    uint64_t words_[SSDA_MATCH_STATE_WORDS];  /* private */
} ssda_match_state_t;

/*
 * ssda_match with its working state in *state instead of on the stack: the
 * same validation, errors and results (bit-identical: the same code runs).
 * Worst-case stack at -Os (tools/budget.sh, docs/target.md): 320 bytes on
 * the Cortex-M4F (and the other Armv7-M/Armv8-M cores, where the call into
 * the engine is a tail call), more on the M0+ (no tail call there); about
 * half of ssda_match's.
 * Issue 18's 320-byte goal is met by this entry only. For small stacks (an
 * RTOS task, an interrupt-driven job) with the state in static storage.
 *   state:        caller storage, any contents; overwritten by the search
 *                 on success, untouched on every error listed below. Must
 *                 not be in use by another search at the same time.
 *   area, window, cfg, result: as ssda_match (result written on success only).
 * Returns what ssda_match returns; also SSDA_ERR_NULL when state is NULL
 * (nothing written).
 */
int ssda_match_search(ssda_match_state_t *state, const ssda_view_t *area,
                      const ssda_view_t *window, const ssda_match_config_t *cfg,
                      ssda_match_result_t *result);

/*
 * Full SAD of the window placed at (x, y) of the area, no early exit: the
 * reference for tests and tools. Same validation as ssda_match; also
 * SSDA_ERR_SIZE if the placement does not fit. *sad written on success only.
 */
int ssda_sad_at(const ssda_view_t *area, const ssda_view_t *window,
                uint16_t x, uint16_t y, uint64_t *sad);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_MATCH_H */
