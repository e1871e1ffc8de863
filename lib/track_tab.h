/*
 * track_tab.h - internal: the bound tables that the searches of one call of
 * grid tracking share (track.h: SSDA_TRACK_WORK_SIZE_SHARED). The search
 * areas of neighbouring windows overlap (4 times for 32 x 32 areas at step
 * 16), so the sums over L x 4 pixels (the engine's row groups) and over
 * 4 x 4 pixels (its block terms) are built once for each FIRST row the
 * areas of a grid row cover, kept for the next grid row, and read by every
 * search (SSDA__MATCH_TAB, match_rows.h).
 */
#ifndef SSDA_TRACK_TAB_H
#define SSDA_TRACK_TAB_H

#include "ssda/track.h"
#include "match_rows.h"

/*
 * The tables of one call (a part of the grid), and this state, in the work
 * buffer after the per-window part: the state at SSDA__MATCH_TAB_AT (mt,
 * its first member, is where the engine reads the tables' description),
 * the tables SSDA__TRACK_TAB_HEAD bytes further. Rows y_lo .. y_end - 1 of FIRST's row source are held,
 * row y at slot y - y_lo; a row holds the sums at source columns x_lo ..
 * x_lo + pitch - 1 (g: L x 4 pixels, pitch - L + 4 of them used; b: 4 x 4
 * pixels). v is one row of vertical sums of 4 pixels, of row v_row.
 */
typedef struct {
    ssda__match_tab_t mt; /* the next search's view of the tables (first) */
    uint32_t *g, *b, *v, *wblk;
    uint32_t cap;        /* rows the tables hold (plan: tab_rows) */
    uint32_t need;       /* rows a grid row's areas use: search_h - 3 */
    uint32_t vlen;       /* columns of v: the areas' columns, <= FIRST's width */
    uint32_t npos;       /* entries of a g row: vlen - L + 1 placements */
    uint32_t pitch;      /* entries between rows: vlen - 3 with b, else npos */
    uint32_t x_lo;       /* source column of entry 0; pitch 0: no column */
    uint32_t y_lo, y_end;
    uint32_t v_row;      /* row of v; UINT32_MAX: none */
    bool blocks;         /* b is built (win_w a multiple of 4, <= 1024) */
} ssda__track_tab_t;

/* Bytes kept for the state before the tables (track.h's
   SSDA_TRACK_WORK_SIZE_SHARED counts them; checked in track_tab.c). */
#define SSDA__TRACK_TAB_HEAD 160u

/* Bytes of work buffer for shared tables: SSDA_TRACK_WORK_SIZE_SHARED in
   64 bits (never wraps). */
SSDA_INTERNAL uint64_t ssda__track_tab_size(const ssda_track_grid_t *g, uint32_t first_w);

/*
 * The state in the work buffer of a plan whose tab_rows != 0: lay the tables out for columns col0 .. col1-1 of the grid, with FIRST's
 * row source placed by first_x (source column 0 is FIRST's column first_x):
 * the columns cover every area of those grid columns that lies inside
 * FIRST horizontally. No table row is built yet.
 */
SSDA_INTERNAL ssda__track_tab_t *ssda__track_tab_init(const ssda_track_plan_t *plan,
                                                      uint32_t col0, uint32_t col1,
                                                      uint32_t first_x);

/*
 * For a window L pixels wide: make rows y .. y + need - 1 of the source present (y ascending from call
 * to call keeps the rows already built; any other y rebuilds), and fill
 * t->mt for the area whose top-left is source column ax, row y. The work is
 * added to *ops (one per pixel read, per sliding-sum step and per entry of
 * a row). Returns SSDA_OK or a fetch error unchanged.
 */
SSDA_INTERNAL int ssda__track_tab_area(ssda__track_tab_t *t, const ssda__rows_t *first,
                                       uint32_t L, uint32_t ax, uint32_t y, uint64_t *ops);

#endif /* SSDA_TRACK_TAB_H */
