/*
 * register.h - control points for the registration of two images (bands
 * of one scene from different cameras, or two dates): one point per cell of
 * a grid over the reference, found by correlation or by SSDA, sub-pixel,
 * ready for ssda_poly_fit (poly.h) and ssda_warp (warp.h).
 * A wrong point (a chance match) is left to the fit: ssda_poly_fit drops
 * pairs by their leave-one-out statistic, so that a wrong point at a
 * corner (high leverage) does not bend the map to itself, and flags a map
 * the points fix weakly (result.weak: say so to the user).
 *
 * Seed: Nagao et al. 1975, section 3.2: the reference (1000 x 800) is cut
 * into 4 x 4 parts and one feature point is taken from each; a 20 x 20
 * window X around it is searched in a 40 x 40 area Y of the other image by
 * the correlation coefficient rho, and the pair is accepted when
 * |rho| > 0.65 (a negative rho still matches: bands whose contrast is
 * inverted); SSDA was 10-20x faster but less accurate across bands.
 *
 * METHOD, per cell (cells: the reference split into grid_x x grid_y parts,
 * cell i spanning columns floor(i w / grid_x) .. floor((i+1) w / grid_x) - 1,
 * rows alike):
 *  1. the most textured window: among window positions on a lattice of
 *     `step` px inside the cell, the one whose pixels have the largest
 *     variance (n sum v^2 - (sum v)^2, exact; ties: the first in raster
 *     order); below min_texture the cell is FLAT;
 *  2. its search area in the moving image: search x search px centred on
 *     the window's centre moved by (offset_x, offset_y), clipped to the
 *     image (narrower than the window: OUTSIDE);
 *  3. the best placement: the largest |rho| (SSDA_REGISTER_ABSNCC, the
 *     seed's rule: inverted contrast matches too) or rho (NCC), exact
 *     (ssda_ncc_match, ncc.h), or the exact SAD minimum (SSDA_REGISTER_SAD:
 *     ssda_match, automatic threshold, bounds; rho is then measured at the
 *     minimum, ssda_ncc_at, and reported, not used);
 *  4. sub-pixel: on each axis through the score at the best placement and
 *     its two neighbours: correlation, a parabola, offset
 *     (s(-1) - s(+1)) / (2 (s(-1) - 2 s(0) + s(+1))); SAD, the equiangular
 *     (V) fit, (s(-1) - s(+1)) / (2 (max(s(-1), s(+1)) - s(0))), which
 *     suits absolute differences; clamped to +-1/2 px, in Q8 (none on an
 *     axis where a neighbour is outside the area);
 *  5. status: LOW_RHO when the correlation metrics' |rho| (NCC: rho) is
 *     not above min_rho; else BORDER when the best placement touches the
 *     edge of the search area (the true match may lie beyond it); else OK.
 * The pair is (window centre in the reference, matched centre in the
 * moving image): centre = top-left + (window - 1) / 2 px.
 *
 * STREAMING: both images are sources (stream.h), in RAM or streamed; each
 * streamed source's plate is planned for what the cell reads next (issue 17
 * item 1; the tracking engine's rule of issue 22). The reference's plate
 * is shaped to the cell's windows (their bounding rectangle), as wide as
 * it and sliding down the window lattice: the windows' spreads are taken
 * from it and the best window's pixels kept as it goes, so each of those
 * rows is read once. The moving image's plate is shaped to the cell's
 * search area, as many rows as fit, so each area row is read once. Arenas
 * (SSDA_REGISTER_REF_SIZE, SSDA_REGISTER_MOV_SIZE below): the reference
 * needs a band of `window` rows as wide as the widest cell, the moving
 * image one row of the search area; below that the search is refused
 * (SSDA_ERR_BUFFER) before any read. For every accepted arena:
 *   reference: bytes read = the sum over cells of the windows' rectangle
 *     (at most the image's bytes once), the same for every arena (tiled:
 *     up to the tile rows below);
 *   moving image: bytes read <= the sum over the cells searched of their
 *     (clipped) areas, at most grid_x * grid_y * search^2 px (the seed's
 *     defaults on 1000 x 800: 0.032x the image), less when a plate still
 *     holds rows of the area before;
 * both plus each read's alignment: 2 (read_size - 1) bytes per read
 * (stats.reads) and, tiled, the rest of the tile rows a run of rows spans.
 * So more memory never reads more bytes of a raster source (it only takes
 * fewer, longer reads); a tiled one's longer runs may span more of the
 * tile rows, within the bound. On the 1280 x 960 16-bit MicaSense bands
 * the reference read 1.00x its bytes at every arena from its least (12 800
 * bytes) to 8 MB, against 43x to 1337x before (docs/registration.md). The
 * results do not depend on the arena.
 */
#ifndef SSDA_REGISTER_H
#define SSDA_REGISTER_H

#include "ssda/ncc.h"
#include "ssda/poly.h"
#include "ssda/stream.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How a window is matched. */
typedef enum {
    SSDA_REGISTER_ABSNCC = 0, /* |rho|: the seed's rule (inverted contrast
                                 matches too) */
    SSDA_REGISTER_NCC = 1,    /* rho: positive correlation only */
    SSDA_REGISTER_SAD = 2     /* SSDA: the exact minimum of the SAD */
} ssda_register_metric_t;

/* What became of a cell. */
typedef enum {
    SSDA_REGISTER_OK = 0,      /* accepted */
    SSDA_REGISTER_FLAT = 1,    /* no window with texture >= min_texture */
    SSDA_REGISTER_LOW_RHO = 2, /* |rho| (rho for NCC) not above min_rho */
    SSDA_REGISTER_BORDER = 3,  /* best placement on the edge of the area */
    SSDA_REGISTER_OUTSIDE = 4  /* the search area leaves the moving image */
} ssda_register_status_t;

/* Defaults: the seed's 4 x 4 grid, 20 x 20 window, 40 x 40 area, 0.65. */
#define SSDA_REGISTER_DEFAULT_GRID 4u
#define SSDA_REGISTER_DEFAULT_WINDOW 20u
#define SSDA_REGISTER_DEFAULT_SEARCH 40u
#define SSDA_REGISTER_DEFAULT_MIN_RHO_Q30 697932186 /* 0.65 in Q2.30 */

/* Options. A zero-filled struct means the seed's defaults: |rho| > 0.65,
   20 x 20 in 40 x 40, 4 x 4 cells. */
typedef struct {
    uint16_t grid_x, grid_y; /* cells across and down, 1..256; 0 = 4 */
    uint16_t window;         /* window side, px, 2..255; 0 = 20 */
    uint16_t search;         /* search area side, px, window..1024; 0 = 40 */
    uint16_t step;           /* texture lattice, px; 0 = window / 4 (>= 1) */
    uint8_t metric;          /* ssda_register_metric_t */
    int32_t min_rho_q30;     /* acceptance, Q2.30; 0 = 0.65 */
    uint32_t min_texture;    /* variance below which a window is flat,
                                (grey levels)^2 * n^2 / n^2 = grey^2;
                                0 = 4 (8-bit) or 1024 (16-bit) */
    int32_t offset_x;        /* expected displacement moving - reference, px */
    int32_t offset_y;
} ssda_register_config_t;

/* One cell's control point. */
typedef struct {
    ssda_poly_pair_t pair;   /* reference and moving centres, px Q23.8 */
    int32_t rho_q30;         /* rho at the match, Q2.30 (SSDA: measured at
                                the SAD minimum); 0 when flat or outside */
    uint64_t sad;            /* SAD at the match (SSDA), else 0 */
    uint64_t pixel_ops;      /* the search's work (pixel_ops of ssda_match
                                or ssda_ncc_match) */
    uint32_t texture;        /* the window's variance, grey^2 (saturated) */
    uint16_t cell_x, cell_y;
    uint8_t status;          /* ssda_register_status_t */
} ssda_register_point_t;

/* Work bytes for a window of `window` px and an area of `search` px
   (0 = the defaults 20 and 40, as in the config; format: bytes per pixel):
   the window and the area, and the larger of the two searches' work
   buffers. */
#define SSDA_REGISTER_ALIGN8_(n) ((((size_t)(n)) + 7u) & ~(size_t)7u)
#define SSDA_REGISTER_WINDOW_(w) ((size_t)(w) != 0u ? (size_t)(w) : (size_t)SSDA_REGISTER_DEFAULT_WINDOW)
#define SSDA_REGISTER_SEARCH_(s) ((size_t)(s) != 0u ? (size_t)(s) : (size_t)SSDA_REGISTER_DEFAULT_SEARCH)
#define SSDA_REGISTER_WORK_SIZE(window, search, format)                        \
    SSDA_REGISTER_WORK_SIZE_(SSDA_REGISTER_WINDOW_(window), SSDA_REGISTER_SEARCH_(search), format)
#define SSDA_REGISTER_WORK_SIZE_(win, area, format)                            \
    (SSDA_REGISTER_ALIGN8_((win) * (win) * (size_t)(format)) +                 \
     SSDA_REGISTER_ALIGN8_((area) * (area) * (size_t)(format)) +               \
     (SSDA_MATCH_WORK_SIZE(area, area, win, win) > SSDA_NCC_WORK_SIZE(area, win, win) \
          ? SSDA_MATCH_WORK_SIZE(area, area, win, win)                        \
          : SSDA_NCC_WORK_SIZE(area, win, win)))

/* Widest cell of a grid of grid_x cells across `width` px: ceil(width /
   grid_x) (grid_x 0 = 4). */
#define SSDA_REGISTER_GRID_(g) ((size_t)(g) != 0u ? (size_t)(g) : (size_t)SSDA_REGISTER_DEFAULT_GRID)
#define SSDA_REGISTER_CELL_W(width, grid_x)                                    \
    (((size_t)(width) + SSDA_REGISTER_GRID_(grid_x) - 1u) / SSDA_REGISTER_GRID_(grid_x))

/* Least arena of a streamed reference `width` px wide (stream.h's
   SSDA_SOURCE_SIZE with the source's layout, format, read_size, tile_w): a
   band of `window` rows (0 = 20) of the widest cell. (With one cell across,
   a raster source read at byte granularity whose rows are not a multiple
   of 4 bytes may need up to 3 bytes a row less: its plate keeps the
   image's stride.) */
#define SSDA_REGISTER_REF_SIZE(layout, width, grid_x, window, format, read_size, tile_w) \
    SSDA_SOURCE_SIZE(layout, SSDA_REGISTER_CELL_W(width, grid_x), SSDA_REGISTER_WINDOW_(window), \
                     format, read_size, tile_w)

/* Least arena of a streamed moving image `width` px wide: one row of the
   search area (search 0 = 40), or of the image when narrower. */
#define SSDA_REGISTER_MOV_SIZE(layout, width, search, format, read_size, tile_w) \
    SSDA_SOURCE_SIZE(layout,                                                    \
                     SSDA_REGISTER_SEARCH_(search) < (size_t)(width)             \
                         ? SSDA_REGISTER_SEARCH_(search) : (size_t)(width),      \
                     1u, format, read_size, tile_w)

/*
 * Find a control point in every cell (see METHOD).
 *   ref, mov:  initialised sources of the same format (in RAM or streamed;
 *              two streamed sources need arenas that do not overlap).
 *   cfg:       options (NULL = defaults).
 *   out, out_count: grid_x * grid_y points, raster order of the cells
 *              (all written on success, accepted or not).
 *   accepted:  NULL or the number of OK points.
 *   work, work_size: SSDA_REGISTER_WORK_SIZE(window, search, format) bytes
 *              (cfg's window and search, 0 or not; NULL cfg: 0, 0),
 *              8-byte aligned.
 * Returns SSDA_OK, or with out untouched:
 *   SSDA_ERR_NULL    ref, mov, out or work NULL
 *   SSDA_ERR_STATE   a source not initialised
 *   SSDA_ERR_FORMAT  formats differ
 *   SSDA_ERR_ARG     options out of range; one streamed source twice or
 *                    overlapping arenas
 *   SSDA_ERR_SIZE    a cell smaller than the window (grid too fine), or
 *                    out_count below grid_x * grid_y
 *   SSDA_ERR_BUFFER  work_size short or misaligned; a streamed reference's
 *                    arena below SSDA_REGISTER_REF_SIZE or a streamed
 *                    moving image's below SSDA_REGISTER_MOV_SIZE (nothing
 *                    read: below them the reads would not be bounded)
 *   SSDA_ERR_UNSUPPORTED  16-bit images in a build with SSDA_CFG_NO_U16
 * or a read() error unchanged (then out holds the cells done before it).
 */
int ssda_register_points(ssda_source_t *ref, ssda_source_t *mov,
                         const ssda_register_config_t *cfg, ssda_register_point_t *out,
                         size_t out_count, size_t *accepted, void *work, size_t work_size);

#ifdef __cplusplus
}
#endif

#endif /* SSDA_REGISTER_H */
