/*
 * edge.h - the edge stage of closed-loop registration (Ishii and Hattori
 * 1985, seed 001, section 2 (a)-(e)): a 5 x 5 two-region edge operator in
 * four directions, ridge thinning, 3 x 3 end / connection / branch
 * classification, extension of ends along the edge strength, and closing
 * of T, I and V gaps. ssda/loops.h takes the refined map to closed loops.
 *
 * THE MAP. One uint16_t per pixel, rows of `width` entries (no padding),
 * owned by the caller (SSDA_EDGE_MAP_SIZE bytes):
 *   bits 0-7   strength: floor(|mean(a) - mean(b)|), 0..255 grey levels
 *   bits 8-9   direction d of the split line (SSDA_EDGE_DIR_*)
 *   bit  10    SSDA_EDGE_ON: an edge pixel
 *   bits 11-15 private to ssda_edge_refine and ssda_loops_find; 0 between
 *              calls.
 * The two outermost rows and columns have no full 5 x 5 window: strength 0,
 * direction 0, never ON.
 *
 * THE OPERATOR (seed Fig. 1, reconstructed: the figure is not legible in
 * our copy). The 5 x 5 window around a pixel is split by a line through its
 * centre in one of four directions; the five pixels on the line are left
 * out, so each side holds ten:
 *   d = 0  line along x (horizontal edge)    a: dy < 0,      b: dy > 0
 *   d = 1  line along (1, -1) ("/" on screen) a: dx + dy < 0, b: dx + dy > 0
 *   d = 2  line along y (vertical edge)      a: dx < 0,      b: dx > 0
 *   d = 3  line along (1, 1)  ("\" on screen) a: dx < dy,     b: dx > dy
 * (x right, y down). The direction is the d whose two sides have the
 * smallest sum of variances, i.e. the largest
 *   V(d) = Sa^2 + Sb^2 + 10 * (sum of squares of the 5 line pixels)
 * (the 20-pixel variance sum is 10 Q25 minus V(d), Q25 the window's sum of
 * squares, all over 10); ties go to the smallest d. The strength is
 * floor(|Sa - Sb| / 10) of that d: the difference of the two sides' means.
 * Exact integers: Sa, Sb <= 2550, V(d) < 2^25.
 *
 * THINNING OF RIDGES (seed (b)). A pixel of strength >= strength_min
 * (seed: 15) is ON unless one of its two 8-neighbours across its split line
 * (the neighbours at +-90 degrees to the line) is strictly stronger and has
 * the same direction.
 *
 * STREAMING. ssda_edge_init + one ssda_edge_push per image row: the job
 * keeps the last five rows in a caller ring (SSDA_EDGE_RING_SIZE), writes
 * map row y - 2 after row y is pushed and thins it one row later, so the
 * image itself need not be in memory. ssda_edge_detect does the same from a
 * view. Then ssda_edge_refine does the 3 x 3 stages on the whole map.
 */
#ifndef SSDA_EDGE_H
#define SSDA_EDGE_H

#include "ssda/view.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SSDA_EDGE_STRENGTH_MASK 0x00FFu
#define SSDA_EDGE_DIR_SHIFT 8u
#define SSDA_EDGE_DIR_MASK 0x0300u
#define SSDA_EDGE_ON 0x0400u
#define SSDA_EDGE_DIR_H 0u    /* split line along x */
#define SSDA_EDGE_DIR_D45 1u  /* along (1, -1) */
#define SSDA_EDGE_DIR_V 2u    /* along y */
#define SSDA_EDGE_DIR_D135 3u /* along (1, 1) */

/* Strength and direction of a map entry. */
#define SSDA_EDGE_STRENGTH(m) ((uint32_t)(m) & SSDA_EDGE_STRENGTH_MASK)
#define SSDA_EDGE_DIR(m) (((uint32_t)(m) & SSDA_EDGE_DIR_MASK) >> SSDA_EDGE_DIR_SHIFT)

/* The seed's thresholds (section 5). */
#define SSDA_EDGE_DEFAULT_STRENGTH 15u /* ridge thinning */
#define SSDA_EDGE_DEFAULT_EXTEND 3u    /* extension along the strength */
#define SSDA_EDGE_DEFAULT_SPUR 3u      /* branches shorter than this have no end */
#define SSDA_EDGE_DEFAULT_GAP 10u      /* T, I, V closing reach, px in x and y */
#define SSDA_EDGE_DEFAULT_FIT 5u       /* pixels fitted for an end's direction */

/* Bytes of the map and of the push job's ring for a w x h image. */
#define SSDA_EDGE_MAP_SIZE(w, h) ((size_t)(w) * (size_t)(h) * 2u)
#define SSDA_EDGE_RING_SIZE(w) ((size_t)(w) * 5u)

/* Smallest image the operator accepts: 5 x 5. */
#define SSDA_EDGE_MIN_DIM 5u

/* A streamed operator job. All fields are private: set by ssda_edge_init,
   advanced by ssda_edge_push. */
typedef struct {
    uint16_t *map;         /* the caller's map */
    uint8_t *ring;         /* the caller's 5-row ring */
    uint32_t width, height;
    uint32_t rows_in;      /* rows pushed so far */
    uint32_t slot;         /* ring slot of the next row */
    uint32_t strength_min; /* 1..255 */
    uint32_t magic;        /* set by init: detects an uninitialised job */
} ssda_edge_job_t;

/*
 * Start a streamed run of the operator and the ridge thinning.
 *   width, height: image size, 5..SSDA_MAX_DIM each.
 *   strength_min:  ridge threshold, 1..255 (0 = SSDA_EDGE_DEFAULT_STRENGTH).
 *   map:           SSDA_EDGE_MAP_SIZE(width, height) bytes, uint16_t-aligned;
 *                  written by the pushes (contents on entry ignored).
 *   ring:          SSDA_EDGE_RING_SIZE(width) bytes; must not overlap map.
 * Both buffers stay the caller's and must live until the last push.
 * Returns SSDA_OK, or without writing *job:
 *   SSDA_ERR_NULL   job, map or ring NULL
 *   SSDA_ERR_SIZE   width or height below 5
 *   SSDA_ERR_BUFFER map_size or ring_size below its SSDA_EDGE_*_SIZE, or
 *                   the map does not fit a 32-bit size_t
 *   SSDA_ERR_STRIDE map not uint16_t-aligned
 *   SSDA_ERR_ARG    ring overlaps map
 */
int ssda_edge_init(ssda_edge_job_t *job, uint16_t width, uint16_t height,
                   uint8_t strength_min, uint16_t *map, size_t map_size,
                   uint8_t *ring, size_t ring_size);

/*
 * Push the next image row (width 8-bit samples; may be reused by the
 * caller after the call). After the height-th push the map is complete.
 * Cost: about 60 additions and 25 multiplications per pixel.
 * Returns SSDA_OK, SSDA_ERR_NULL (job or row NULL), SSDA_ERR_STATE (job
 * not initialised, or all rows already pushed; nothing changes).
 */
int ssda_edge_push(ssda_edge_job_t *job, const uint8_t *row);

/*
 * The operator and the ridge thinning on a whole 8-bit view: ssda_edge_init
 * and one push per row. Errors as ssda_edge_init, plus the view's errors
 * (ssda_view_check), SSDA_ERR_FORMAT for a 16-bit view (scale it to 8 bits
 * first), SSDA_ERR_SIZE for a view below 5 x 5. Every check happens
 * before the first row: on error nothing is written.
 */
int ssda_edge_detect(const ssda_view_t *img, uint8_t strength_min, uint16_t *map,
                     size_t map_size, uint8_t *ring, size_t ring_size);

/* Settings of ssda_edge_refine. Zero-filled = the seed's values. */
typedef struct {
    uint8_t extend_min;   /* (d) extension continues onto pixels of strength
                             >= this (0 = 3; 255 = no extension) */
    uint8_t spur_min;     /* an end whose branch is shorter than this (px,
                             to a branch point or to another end) is not
                             extended or joined (0 = 3) */
    uint8_t gap_max;      /* (e) T, I, V reach: px in x and in y (0 = 10;
                             at most 64) */
    uint8_t fit_len;      /* pixels fitted for an end's direction, 2..16
                             (0 = 5) */
    uint8_t extend_max;   /* (d) longest extension, px (0 = 64) */
    uint8_t i_angle_deg;  /* I: largest sum of the two ends' angles to the
                             line joining them, degrees (0 = 60) */
    uint8_t i_area_max;   /* I: largest triangle area, px^2 (0 = 20) */
    uint8_t v_angle_deg;  /* V: smallest angle of the V, degrees (0 = 30) */
    uint8_t no_close;     /* 1: skip (e) (T, I, V closing) */
} ssda_edge_refine_config_t;

/* What ssda_edge_refine did. */
typedef struct {
    uint32_t thinned;        /* pixels deleted by the 3 x 3 thinning (both passes) */
    uint32_t ends;           /* ends found before the extension */
    uint32_t ends_dropped;   /* ends beyond the work buffer: not extended or joined */
    uint32_t extended;       /* ends extended by (d) */
    uint32_t extend_joined;  /* of these, extensions that reached another edge */
    uint32_t closed_t, closed_i, closed_v; /* (e) closings by type */
    uint32_t branch, conn, end; /* final classification counts (ON pixels) */
} ssda_edge_stats_t;

/* Bytes of ssda_edge_refine's work buffer for up to max_ends ends (8 bytes
   each). Ends beyond it are counted in ends_dropped. */
#define SSDA_EDGE_WORK_SIZE(max_ends) ((size_t)(max_ends) * 8u)

/*
 * The seed's 3 x 3 stages on a map from ssda_edge_detect / the push job:
 *  (c) thinning by 3 x 3 patterns in three stages (deletions that keep
 *      4-connectivity without a dent, then with a dent, then keeping only
 *      8-connectivity), isolated points removed, until no "unsuitable"
 *      pattern (a 2 x 2 block, four ring neighbours in a row) can go;
 *  (d) each end (one run of ON pixels around it) is extended along the
 *      strongest of the three pixels at -45, 0, +45 degrees to its edge
 *      direction while their strength is >= extend_min and their direction
 *      is not perpendicular to the step, until it meets another edge;
 *  (e) T: an end's straight extension (direction fitted over fit_len
 *      pixels) meets an edge within gap_max; I: two ends nearly in line
 *      (angle sum, triangle area); V: two ends whose extensions meet
 *      ahead of both within gap_max at an angle >= v_angle_deg (the V
 *      preferred when the same partner also makes an I). Of an end's
 *      candidates the nearest wins; the gap is drawn as straight lines;
 *  then (c) once more.
 * Ends are processed in raster order; every tie rule is documented in
 * docs/symbolic.md. The map keeps strength and direction; ON bits change.
 *   work: SSDA_EDGE_WORK_SIZE(max_ends) bytes, 4-byte aligned; scratch.
 *   stats: may be NULL.
 * Returns SSDA_OK, or without changing the map:
 *   SSDA_ERR_NULL   map or work NULL
 *   SSDA_ERR_SIZE   width or height below 5
 *   SSDA_ERR_BUFFER work_size below SSDA_EDGE_WORK_SIZE(1)
 *   SSDA_ERR_STRIDE map or work misaligned
 *   SSDA_ERR_ARG    a cfg field out of range
 */
int ssda_edge_refine(uint16_t *map, uint16_t width, uint16_t height,
                     const ssda_edge_refine_config_t *cfg, void *work, size_t work_size,
                     ssda_edge_stats_t *stats);

/* 3 x 3 classes of an ON pixel (seed appendix). */
typedef enum {
    SSDA_EDGE_ISOLATED = 0, /* no ON neighbour */
    SSDA_EDGE_END = 1,      /* one run of ON pixels around it */
    SSDA_EDGE_CONN = 2,     /* two runs */
    SSDA_EDGE_BRANCH = 3    /* three or more, or an unsuitable pattern */
} ssda_edge_class_t;

/*
 * Class of the pixel (x, y) of a map (its ON neighbours in 3 x 3; pixels
 * outside the map count as OFF). Returns an ssda_edge_class_t (>= 0) for an
 * ON pixel, or SSDA_ERR_NULL (map NULL), SSDA_ERR_SIZE ((x, y) outside the
 * map), SSDA_ERR_ARG (the pixel is not ON).
 */
int ssda_edge_classify(const uint16_t *map, uint16_t width, uint16_t height, uint16_t x,
                       uint16_t y);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_EDGE_H */
