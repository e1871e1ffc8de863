/*
 * track.h - grid tracking: motion vectors between two images by SSDA, the
 * seed's cloud tracking (Onoe, Maeda, Saito 1976, section 3).
 *
 * Windows of win_w x win_h pixels are laid on a grid in the SECOND (later)
 * image; each is searched by ssda_match in the search_w x search_h area of
 * the FIRST (earlier) image centred on it. The seed used 16 x 16 windows on
 * a 7 x 7 grid, each searched in the 32 x 32 area centred on it, on 128 x 128
 * images (grid region starting 8 px in from the border, so that every area
 * fits); those are the defaults here (the grid region defaults to the whole
 * image, so windows near the border get status SSDA_TRACK_EDGE).
 *
 * GEOMETRY (all in pixels, x right, y down, 0-based):
 *   window k = (col, row), k = row * cols + col, has its top-left in SECOND at
 *       wx = roi_x + col * step_x,  wy = roi_y + row * step_y;
 *   its search area in FIRST has its top-left at
 *       ax = wx - hx,  ay = wy - hy,  hx = (search_w - win_w) / 2,
 *                                     hy = (search_h - win_h) / 2 (floor);
 *   if ssda_match finds the best placement at (px, py) of that area, the
 *   window's content came from (ax + px, ay + py) in FIRST, and the vector is
 *       dx = wx - (ax + px) = hx - px,   dy = hy - py:
 *   the MOTION FROM FIRST TO SECOND. The window at (wx, wy) of SECOND
 *   matched best at (wx - dx, wy - dy) of FIRST. dx ranges over
 *   hx - (search_w - win_w) .. hx (-8 .. +8 for 16 in 32), dy likewise.
 *
 * STATUS of each window, decided in this order:
 *   SSDA_TRACK_EDGE      the search area would leave FIRST (no pixel read);
 *   SSDA_TRACK_MASKED    (flag SSDA_TRACK_MASK) the window holds mask_value;
 *   SSDA_TRACK_EXCLUDED  (flag SSDA_TRACK_EXCLUDE) the window has no texture
 *                        by the seed's rule (below);
 *   SSDA_TRACK_FLAT      the window's texture (texture_q8, below) is under
 *                        flat_q8: nothing in it to match (no echo, clear
 *                        sky, nodata); found from the window alone, its
 *                        area is never read (SSDA_TRACK_NO_FLAT: no test);
 *   SSDA_TRACK_MASKED    (flag SSDA_TRACK_MASK) the search area holds
 *                        mask_value (a fill pixel could attract or repel
 *                        the match, so the vector would not be trustworthy);
 *   searched, then:
 *   SSDA_TRACK_AT_LIMIT  the best placement lies on the border of the
 *                        placement range (dx or dy at its extreme, -8 or
 *                        +8 for 16 in 32; an axis with a single placement
 *                        has no border): the true motion may be that or
 *                        larger, so the vector is not trusted;
 *   SSDA_TRACK_AMBIGUOUS (flag SSDA_TRACK_UNIQUE) a placement outside the
 *                        (2R+1) x (2R+1) square around the best has a SAD
 *                        within unique_q8 / 256 of the best one's
 *                        (SSDA_MATCH_UNIQUE): another match about as good;
 *   SSDA_TRACK_OK        the vector can be trusted as far as these tests
 *                        tell.
 * AT_LIMIT, AMBIGUOUS and OK windows are searched (dx, dy, sub_dx_q8,
 * sub_dy_q8, sad, unique_q8, exact valid); the others are not. Only OK
 * vectors feed the prediction of later windows.
 *
 * TEXTURE (texture_q8): the mean absolute deviation of the window's pixels
 * from their mean rounded down, floor(256 * sum |p - m| / n) with
 * m = floor(sum p / n): Q24.8 sample units, <= 65535 * 256. Two passes over
 * the window (2 n pixel reads, in check_pixels). Default level 1.25 sample
 * units (flat_q8 = 320), chosen from data (docs/tracking.md): above the
 * deviation of sensor noise of about 1 grey level, below that of the
 * weakest textures the search still matches. For data whose noise is
 * larger in sample units (16-bit sensors), set flat_q8 to about its
 * noise's deviation; the uniqueness test catches noisy flat windows the
 * level lets through, after a search.
 *
 * TIE RULE: among equal SADs, the placement nearest to the predicted one
 * (SSDA_MATCH_TIE_NEAREST: squared distance, then y, then x), where the
 * prediction is the neighbours' vector (below) or zero motion with
 * SSDA_TRACK_PREDICT_NONE. Where several placements tie, tracking so keeps
 * the motion of its neighbours, or none, instead of the top-left placement
 * (the largest motion, +8, +8 for 16 in 32).
 *
 * SUB-PIXEL MOTION (sub_dx_q8, sub_dy_q8, Q24.8 px, same sign as dx, dy):
 * dx - offset of the equiangular fit of SSDA_MATCH_SUBPIXEL, per axis; 256 *
 * dx where no fit is possible (the border of the range, all three SADs
 * equal), where the window matches exactly (SAD 0), and with SSDA_TRACK_NO_SUBPIXEL or a threshold mode other than
 * AUTO and NONE (the fit needs exact SADs).
 *
 * TEXTURE EXCLUSION (the seed, section 3: windows that are all clear or all
 * cloud are "excluded beforehand automatically by setting a suitable
 * threshold and counting the black or white pixels beyond it"). The paper
 * gives no numbers; this library's rule and defaults are:
 *   bright = number of window pixels > texture_threshold,
 *   dark   = win_w * win_h - bright;
 *   the window is EXCLUDED if bright < texture_min_count or
 *   dark < texture_min_count (fewer than min_count pixels on one side of
 *   the threshold: essentially all dark or all bright).
 *   Defaults: texture_threshold = half the sample range (128 for 8-bit,
 *   32768 for 16-bit; set it for your data, e.g. a cloud/clear level, or
 *   2048 for 12-bit counts); texture_min_count = win_w * win_h / 16 (16 of
 *   256 for the 16 x 16 window), at least 1, at most win_w * win_h / 2: a
 *   default is always valid, and for a 1 x 1 window (no texture to count)
 *   it is 0, so that no window is excluded.
 *
 * PREDICTION (the seed, section 4 and Table 3: "prediction was made so that
 * the motion vector equals that of the neighbouring region"): windows are
 * solved in raster order of the grid (row by row, left to right); each
 * window's search starts at the vector predicted from OK neighbours already
 * solved, through SSDA_SCAN_PREDICT, so a good prediction lowers the
 * automatic threshold at once. In the exact modes (SSDA_THRESHOLD_AUTO,
 * SSDA_THRESHOLD_NONE) prediction changes the work, and which of several
 * equal minima wins (the tie rule above), never the SAD of a vector.
 *
 * The library reads pixels only; nothing is allocated. See docs/tracking.md.
 */
#ifndef SSDA_TRACK_H
#define SSDA_TRACK_H

#include "ssda/match.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Defaults (zero in the config means these). */
#define SSDA_TRACK_DEFAULT_WIN 16u         /* window side, px (the seed's 16) */
/* search side default: twice the window side (32 for 16), capped at
   SSDA_MAX_DIM */
#define SSDA_TRACK_DEFAULT_MIN_COUNT_DIV 16u /* texture_min_count = w*h / 16 */

/* Per-window status. */
typedef enum {
    SSDA_TRACK_OK = 0,       /* searched: vector valid */
    SSDA_TRACK_EXCLUDED = 1, /* textureless window (SSDA_TRACK_EXCLUDE) */
    SSDA_TRACK_MASKED = 2,   /* window or area holds mask_value (SSDA_TRACK_MASK) */
    SSDA_TRACK_EDGE = 3,     /* search area would leave FIRST */
    SSDA_TRACK_FLAT = 4,     /* texture below flat_q8: not searched */
    SSDA_TRACK_AMBIGUOUS = 5, /* another placement within the uniqueness ratio */
    SSDA_TRACK_AT_LIMIT = 6  /* best placement on the border of the range */
} ssda_track_status_t;

/* Prediction of each window's vector from solved neighbours. */
typedef enum {
    /* No prediction: cfg->match.scan is used as given; with
       SSDA_SCAN_PREDICT the rings start at zero motion (area centre). */
    SSDA_TRACK_PREDICT_NONE = 0,
    /* The seed's: the vector of the left neighbour; for the first window
       of a grid row, the one above; zero motion if that one is not OK. */
    SSDA_TRACK_PREDICT_LEFT = 1,
    /* Component-wise median of the OK ones among left, up and up-right
       (up-left replaces up-right when that one is not OK, as in video
       motion-vector prediction): with 3 candidates their median, with 2 or
       1 the first of left, up, up-right, up-left that is OK, with none zero
       motion. Robust against one wrong neighbour. */
    SSDA_TRACK_PREDICT_MEDIAN = 2
} ssda_track_predict_t;

/* Flags. */
#define SSDA_TRACK_EXCLUDE 0x01u /* exclude textureless windows (rule above) */
#define SSDA_TRACK_MASK 0x02u    /* windows/areas holding mask_value are MASKED */
#define SSDA_TRACK_NO_FLAT 0x04u /* no texture test: no window is FLAT */
/* uniqueness test: AMBIGUOUS windows (SSDA_MATCH_UNIQUE; needs match.work,
   SSDA_TRACK_WORK_SIZE bytes, and the AUTO or NONE threshold) */
#define SSDA_TRACK_UNIQUE 0x08u
#define SSDA_TRACK_NO_SUBPIXEL 0x10u /* no sub-pixel fit: sub_d*_q8 = 256 * d* */

/* Default flat level, Q24.8 sample units: mean absolute deviation 1.25. */
#define SSDA_TRACK_DEFAULT_FLAT_Q8 320u

/*
 * Tracking options. A zero-filled struct is valid: 16 x 16 windows, 32 x 32
 * areas, step 16, the whole SECOND image, AUTO threshold with raster scan,
 * no prediction, no exclusion, no mask; the flat test at 1.25, the sub-pixel
 * fit; no uniqueness test (it needs a work buffer: for vectors a tracking
 * unit can trust, set SSDA_TRACK_UNIQUE and match.work, as `ssda track`
 * does).
 */
typedef struct {
    uint16_t win_w, win_h;       /* window size, px (0 = 16) */
    uint16_t search_w, search_h; /* search area size, px, >= window
                                    (0 = twice the window, at most 65535) */
    uint16_t step_x, step_y;     /* grid step, px (0 = the window size) */
    uint16_t roi_x, roi_y;       /* grid region top-left in SECOND, px */
    uint16_t roi_w, roi_h;       /* grid region size, px (0 = to the right /
                                    bottom edge of SECOND) */
    uint8_t predict;             /* ssda_track_predict_t */
    uint8_t flags;               /* SSDA_TRACK_EXCLUDE | SSDA_TRACK_MASK */
    uint16_t mask_value;         /* SSDA_TRACK_MASK: the fill value (GOES: 4095);
                                    <= 255 for 8-bit images */
    uint16_t texture_threshold;  /* SSDA_TRACK_EXCLUDE: brightness level in sample
                                    units, < the format's maximum
                                    (0 = half range: 128 or 32768) */
    uint32_t texture_min_count;  /* SSDA_TRACK_EXCLUDE: pixels needed on each side
                                    of the threshold, 2 * count <= win_w * win_h
                                    (0 = win_w * win_h / 16, at least 1; 0 for a
                                    1 x 1 window: nothing excluded) */
    uint32_t flat_q8;            /* FLAT below this texture, Q24.8 sample units,
                                    <= 65535 * 256 (0 = 320, i.e. 1.25) */
    uint16_t unique_q8;          /* SSDA_TRACK_UNIQUE: ratio, Q8.8, 257 .. 1024
                                    (0 = 282, 1.10) */
    uint8_t unique_radius;       /* SSDA_TRACK_UNIQUE: square radius 1 or 2 (0 = 2) */
    /* Search options for every window (see match.h). predict_x/predict_y
       are ignored (set per window). With a prediction mode other than
       NONE, scan must be RASTER or PREDICT and is run as PREDICT.
       SSDA_MATCH_BOUNDS and SSDA_TRACK_UNIQUE need work >=
       SSDA_TRACK_WORK_SIZE(...) bytes, 8-byte aligned; with
       SSDA_TRACK_WORK_SIZE_SHARED(...) bytes the bounds' tables are
       shared by the windows (faster, same results). The quality flags
       of the search are set by tracking: TIE_NEAREST always, SUBPIXEL and
       UNIQUE from the flags above (flags given here are kept).
       SSDA_MATCH_BLOCKS is refused (SSDA_ERR_ARG): it pays on single
       large searches, not on the small areas of a grid. */
    ssda_match_config_t match;
} ssda_track_config_t;

/* The grid a configuration gives on an image (defaults resolved). */
typedef struct {
    uint32_t count;              /* cols * rows, <= 65535^2 */
    uint16_t cols, rows;         /* windows per grid row / column, >= 1 */
    uint16_t win_w, win_h;
    uint16_t search_w, search_h;
    uint16_t step_x, step_y;
    uint16_t roi_x, roi_y, roi_w, roi_h;
} ssda_track_grid_t;

/*
 * Private (read no field): a tracking configuration resolved once, every
 * default filled in and every option checked, for one pixel format and
 * pair of image sizes; the per-window work only executes it. It lives in the state
 * of push jobs (ssda_push_t).
 */
typedef struct {
    ssda_match_plan_t match;    /* every window's search (scan set for the prediction) */
    ssda_track_grid_t grid;
    uint32_t texture_threshold; /* < the format's maximum */
    uint32_t texture_min_count; /* 1 .. win_w * win_h / 2 (0 for a 1 x 1 window) */
    uint32_t flat_q8;           /* resolved; 0: no flat test */
    uint16_t mask_value;        /* <= the format's maximum */
    uint16_t first_w, first_h;  /* FIRST's size (the EDGE test) */
    uint16_t tab_rows;          /* shared bound tables: rows held (0: none,
                                   each search builds its own) */
    uint8_t predict;            /* ssda_track_predict_t */
    uint8_t flags;              /* SSDA_TRACK_* flags */
} ssda_track_plan_t;

/* Result for one window. "Searched": OK, AMBIGUOUS, AT_LIMIT. */
typedef struct {
    uint64_t sad;    /* searched: SAD at the match (< 2^48); else 0 */
    int32_t dx, dy;  /* searched: motion FIRST -> SECOND, px (see GEOMETRY); else 0 */
    int32_t sub_dx_q8, sub_dy_q8; /* searched: sub-pixel motion, Q24.8 px (SUB-PIXEL
                                     MOTION above); else 0 */
    uint32_t texture_q8; /* the window's texture, Q24.8 (TEXTURE above), once
                            measured (the flat test on, the window tested);
                            else 0 */
    uint16_t x, y;   /* window top-left in SECOND, px */
    uint16_t unique_q8; /* searched with SSDA_TRACK_UNIQUE: the ratio of
                           SSDA_MATCH_UNIQUE (AMBIGUOUS) or
                           SSDA_MATCH_UNIQUE_NONE; else SSDA_MATCH_UNIQUE_NONE */
    uint8_t status;  /* ssda_track_status_t */
    bool exact;      /* searched: ssda_match's exact flag; else false */
} ssda_track_vector_t;

/* Totals over one call. Counts saturate at UINT64_MAX (unreachable in
   practice: it would take decades of computation). */
typedef struct {
    uint64_t pixel_ops;    /* sum of ssda_match pixel_ops over searched windows
                              (the sub-pixel fit's sums included) */
    uint64_t positions;    /* sum of positions evaluated */
    uint64_t completed;    /* sum of positions summed in full */
    uint64_t check_pixels; /* pixels read by the mask, exclusion and flat tests */
    uint32_t windows;      /* grid windows (= grid count) */
    uint32_t ok, excluded, masked, edge; /* windows per status */
    uint32_t flat, ambiguous, at_limit;
} ssda_track_stats_t;

/* Windows along one grid axis: region length len, window side win, step. */
#define SSDA_TRACK_GRID_DIM(len, win, step)                                   \
    (((size_t)(len) >= (size_t)(win))                                         \
         ? (((size_t)(len) - (size_t)(win)) / (size_t)(step) + 1u)            \
         : (size_t)0u)

/* Windows in the grid of a roi_w x roi_h region (explicit, non-zero sizes). */
#define SSDA_TRACK_GRID_COUNT(roi_w, roi_h, win_w, win_h, step_x, step_y)     \
    (SSDA_TRACK_GRID_DIM(roi_w, win_w, step_x) *                              \
     SSDA_TRACK_GRID_DIM(roi_h, win_h, step_y))

/* Bytes of the vector array for that grid. Where size_t is 32 bits this
   wraps for grids of more than about 179 million windows; ssda_track and
   the stream and push jobs refuse such a grid with SSDA_ERR_BUFFER. */
#define SSDA_TRACK_OUT_SIZE(roi_w, roi_h, win_w, win_h, step_x, step_y)       \
    (SSDA_TRACK_GRID_COUNT(roi_w, roi_h, win_w, win_h, step_x, step_y) *      \
     sizeof(ssda_track_vector_t))

/* Bytes of match work buffer SSDA_MATCH_BOUNDS and SSDA_TRACK_UNIQUE need
   (one, reused by every window; 8-byte aligned). SSDA_MATCH_BOUNDS alone
   needs only SSDA_MATCH_WORK_SIZE(search_w, search_h, win_w, win_h) bytes,
   4-byte aligned, as ssda_match. */
#define SSDA_TRACK_WORK_SIZE(search_w, search_h, win_w, win_h)                \
    SSDA_MATCH_WORK_SIZE_UNIQUE(search_w, search_h, win_w, win_h)

/*
 * SHARED BOUND TABLES (issue 18). With SSDA_MATCH_BOUNDS (threshold other
 * than NONE) and a work buffer of at least this many bytes, the searches of
 * one call share their bound tables instead of building them per window:
 * the search areas of neighbouring windows overlap (4 times for 32 x 32
 * areas at step 16). For every FIRST row that a grid row's areas cover, the
 * call builds the sums over win_w x 4 pixels (the bound's row groups) and,
 * when win_w is a multiple of 4 up to 1024, over 4 x 4 pixels at every
 * column of the areas, keeps them while the grid moves down, and every
 * search reads them. The 4 x 4 block sums tighten the bound of each
 * position that passes the group bound, one group of 4 rows at a time
 * (Gao's multilevel successive elimination at 4 x 4 blocks: 16 terms for a
 * 16 x 16 window, one lookup each), so that most such positions are
 * rejected before any absolute difference; not in the RAMP, AUTO_RAMP and
 * FIXED modes, whose results depend on the bound's strength.
 *   first_w: FIRST's width, px; the other sizes as the grid's (resolved).
 * Needs win_h >= 4, and win_w <= 16384 for 16-bit images; otherwise, or with
 * a smaller buffer (down to SSDA_TRACK_WORK_SIZE), every search builds its
 * own tables as before. Results (vectors, SADs, statuses, exact flags,
 * positions, completed) are those without shared tables; stats.pixel_ops
 * counts the tables once (one op per pixel read, per sliding-sum step and
 * per table entry) and the searches' work, so it depends on how the grid
 * is cut into calls:
 * one ssda_track call builds each FIRST row's tables once, an
 * ssda_track_row call (one grid row) builds all its rows. Accumulators:
 * the vertical sums of 4 pixels < 2^18, the 4 x 4 sums < 2^20, the
 * win_w x 4 sums <= 4 * win_w * 65535 < 2^32; these two are differences
 * of the vertical sums' prefix sums along a row, modulo 2^32 (exact: the
 * true sums fit). Layout: the per-window part
 * (SSDA_TRACK_WORK_SIZE rounded up to 8), 160 bytes of state, then uint32_t tables of
 * 2 * (search_h - 3) + 1 rows of first_w entries and the window's
 * (win_w / 4) * (win_h / 4) block sums: 592 944 B for the 2500-px-wide GOES
 * image, 32 x 32 areas; 33 152 B for 128 x 128 images. Wraps like
 * SSDA_MATCH_WORK_SIZE where size_t is 32 bits (the library checks in
 * 64 bits).
 */
#define SSDA_TRACK_WORK_SIZE_SHARED(first_w, search_w, search_h, win_w, win_h)            \
    (((SSDA_TRACK_WORK_SIZE(search_w, search_h, win_w, win_h) + 7u) & ~(size_t)7u) + 160u + \
     ((2u * ((size_t)(search_h) > 3u ? (size_t)(search_h) - 3u : 0u) + 1u) *               \
          (size_t)(first_w) +                                                             \
      ((size_t)(win_w) / 4u) * ((size_t)(win_h) / 4u)) * sizeof(uint32_t))

/*
 * Resolve defaults and lay out the grid of cfg on a SECOND image of
 * width x height pixels (for sizing the vector array before tracking).
 *   cfg:  options; NULL means all defaults.
 *   grid: written on success only.
 * Returns SSDA_OK, or without writing *grid:
 *   SSDA_ERR_NULL  grid NULL
 *   SSDA_ERR_SIZE  width or height 0; search area smaller than the window;
 *                  grid region not inside the image or smaller than the window
 * (Only the geometry is checked here; ssda_track checks everything.)
 */
int ssda_track_grid(const ssda_track_config_t *cfg, uint16_t width, uint16_t height,
                    ssda_track_grid_t *grid);

/*
 * Track the grid of windows of SECOND in FIRST.
 *   first, second: valid views of the same pixel format (sizes may differ:
 *             both share one pixel coordinate system). Not modified.
 *   cfg:       options; NULL means all defaults.
 *   out:       caller array of out_count entries, >= the grid count
 *             (ssda_track_grid or SSDA_TRACK_GRID_COUNT); entry k is window
 *             k = row * cols + col. Entries past the grid are not touched.
 *   stats:     totals, or NULL.
 * Returns SSDA_OK, or without writing out or stats:
 *   SSDA_ERR_NULL     first, second or out NULL; bounds or SSDA_TRACK_UNIQUE
 *                     requested with a NULL work buffer
 *   SSDA_ERR_SIZE/_STRIDE/_FORMAT  invalid views; SSDA_ERR_SIZE also for the
 *                     geometry errors of ssda_track_grid
 *   SSDA_ERR_FORMAT   first and second formats differ
 *   SSDA_ERR_ARG      unknown predict value or flags; mask_value or
 *                     texture_threshold beyond the format's range;
 *                     2 * texture_min_count > win_w * win_h; flat_q8 >
 *                     65535 * 256; COARSE scan with prediction;
 *                     SSDA_TRACK_UNIQUE with a threshold other than AUTO and
 *                     NONE or the COARSE scan; SSDA_MATCH_BLOCKS in
 *                     match.flags; and every SSDA_ERR_ARG of
 *                     ssda_match (unique_q8, unique_radius)
 *   SSDA_ERR_BUFFER   out_count below the grid count; a work buffer below
 *                     what the flags need (SSDA_TRACK_WORK_SIZE with
 *                     SSDA_TRACK_UNIQUE; SSDA_MATCH_WORK_SIZE of the search
 *                     area for SSDA_MATCH_BOUNDS alone) or misaligned
 *   SSDA_ERR_UNSUPPORTED  uniqueness or the sub-pixel fit in a build without
 *                     them (SSDA_CFG_NO_UNIQUE, SSDA_CFG_NO_SUBPIXEL: set
 *                     SSDA_TRACK_NO_SUBPIXEL there)
 * Work: for each window not FLAT, EXCLUDED, MASKED or EDGE, one ssda_match
 * over a search_w x search_h area (and at most 4 window SADs for the
 * sub-pixel fit); 2 window passes for the flat test.
 */
int ssda_track(const ssda_view_t *first, const ssda_view_t *second,
               const ssda_track_config_t *cfg, ssda_track_vector_t *out,
               size_t out_count, ssda_track_stats_t *stats);

/*
 * Track columns col0 .. col1-1 of grid row `row` only: a grid shared among
 * threads (or spread over time) with ssda_track's result. ssda_track solves
 * windows in raster order and window (row, col)'s prediction reads its
 * solved neighbours (row, col-1), (row-1, col-1), (row-1, col) and
 * (row-1, col+1). This call takes every one of them as solved: when it
 * starts, out must hold (row, col0-1) and, in row-1, columns col0-1 .. col1
 * (those inside the grid). Then the part's vectors, statuses, exact flags
 * and work counts are those of ssda_track, and so are the counts summed
 * over parts covering the grid. A wavefront keeps the promise: one worker
 * per grid row (or rows taken in turn), row r solving column c once row
 * r-1 has solved column c+1 (with SSDA_TRACK_PREDICT_NONE every window is
 * independent; with SSDA_TRACK_PREDICT_LEFT only (row, col-1) and, for
 * col 0, (row-1, 0) are read).
 *   first, second, cfg: as ssda_track (cfg NULL = defaults). The work
 *             buffer cfg->match.work is written: each concurrent caller
 *             needs its own. Each call checks its arguments as ssda_track
 *             does (a few hundred operations; a window's search costs far
 *             more).
 *   out:      the whole grid's array (out_count >= the grid count); only
 *             the part's entries row * cols + col0 .. row * cols + col1-1
 *             are written; the neighbours above are read. Concurrent
 *             calls must write disjoint parts.
 *   stats:    the part's counts are ADDED to *stats (zero it first; fields
 *             that add saturate as ssda_track's), or NULL.
 * Returns SSDA_OK, or without writing out or stats: every error of
 * ssda_track, and SSDA_ERR_ARG for row >= grid rows, col0 >= col1 or
 * col1 > grid cols.
 */
int ssda_track_row(const ssda_view_t *first, const ssda_view_t *second,
                   const ssda_track_config_t *cfg, uint32_t row, uint32_t col0, uint32_t col1,
                   ssda_track_vector_t *out, size_t out_count, ssda_track_stats_t *stats);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_TRACK_H */
