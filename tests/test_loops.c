/*
 * test_loops.c - closed loops of an edge map (include/ssda/loops.h) on
 * drawn maps whose regions are known here: areas, centroids, means and
 * boxes counted from the drawing, perimeters of rectangles in closed form,
 * contour samples on the region's boundary and equally spaced, the seed's
 * filters one by one, open branches pruned, a region larger than the work
 * refused wherever the raster scan enters it; the whole chain on an image;
 * errors that change nothing.
 */
#include <string.h>
#include "unity.h"
#include "ssda/edge.h"
#include "ssda/loops.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

#define W 64u
#define H 48u
#define MAXL 8u
#define NS 32u

static uint16_t g_map[W * H], g_copy[W * H];
static uint8_t g_img[H][W];
static uint32_t g_work[2048];
static ssda_loop_t g_loops[MAXL];
static ssda_point_q8_t g_pts[MAXL * NS];
static ssda_view_t g_view;

static void clear(uint8_t grey)
{
    memset(g_map, 0, sizeof g_map);
    memset(g_img, grey, sizeof g_img);
    (void)ssda_view_init(&g_view, g_img, W, H, W, SSDA_PIX_U8);
}

/* Outline of the rectangle [x0, x1] x [y0, y1] (ON), inside filled with grey. */
static void rect(uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1, uint8_t grey)
{
    uint32_t x, y;
    for (y = y0; y <= y1; y++) {
        for (x = x0; x <= x1; x++) {
            if (x == x0 || x == x1 || y == y0 || y == y1) {
                g_map[y * W + x] = SSDA_EDGE_ON;
            } else {
                g_img[y][x] = grey;
            }
        }
    }
}

static int find(const ssda_loops_config_t *c, uint32_t *n, ssda_loops_stats_t *st)
{
    return ssda_loops_find(g_map, &g_view, c, g_work, sizeof g_work, g_loops, MAXL, g_pts,
                           sizeof g_pts, n, st);
}

static ssda_loops_config_t cfg_ns(void)
{
    ssda_loops_config_t c;
    memset(&c, 0, sizeof c);
    c.samples = NS;
    return c;
}

static void test_rectangles_known_in_closed_form(void)
{
    ssda_loops_config_t c = cfg_ns();
    ssda_loops_stats_t st;
    uint32_t n, i;
    clear(30u);
    rect(5u, 6u, 16u, 15u, 200u);   /* inside 10 x 8 = 80 px */
    rect(30u, 20u, 45u, 33u, 120u); /* inside 14 x 12 = 168 px */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, find(&c, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(2u, n);
    TEST_ASSERT_EQUAL_UINT32(2u, st.loops);
    TEST_ASSERT_EQUAL_UINT32(80u, g_loops[0].area);
    TEST_ASSERT_EQUAL_UINT32(168u, g_loops[1].area);
    /* centroid of x 6..15, y 7..14: (10.5, 10.5); of 31..44, 21..32: (37.5, 26.5) */
    TEST_ASSERT_EQUAL_INT32(10 * 256 + 128, g_loops[0].cx_q8);
    TEST_ASSERT_EQUAL_INT32(10 * 256 + 128, g_loops[0].cy_q8);
    TEST_ASSERT_EQUAL_INT32(37 * 256 + 128, g_loops[1].cx_q8);
    TEST_ASSERT_EQUAL_INT32(26 * 256 + 128, g_loops[1].cy_q8);
    TEST_ASSERT_EQUAL_UINT32(200u * 256u, g_loops[0].mean_q8);
    TEST_ASSERT_EQUAL_UINT32(120u * 256u, g_loops[1].mean_q8);
    /* the boundary through pixel centres of a w x h block: 2 (w - 1) + 2 (h - 1) */
    TEST_ASSERT_EQUAL_UINT32((2u * 9u + 2u * 7u) * 256u, g_loops[0].perimeter_q8);
    TEST_ASSERT_EQUAL_UINT32((2u * 13u + 2u * 11u) * 256u, g_loops[1].perimeter_q8);
    TEST_ASSERT_EQUAL_UINT16(6u, g_loops[0].x0);
    TEST_ASSERT_EQUAL_UINT16(7u, g_loops[0].y0);
    TEST_ASSERT_EQUAL_UINT16(15u, g_loops[0].x1);
    TEST_ASSERT_EQUAL_UINT16(14u, g_loops[0].y1);
    TEST_ASSERT_TRUE(g_loops[1].contour == g_pts + NS);
    /* samples: on the block's boundary, equally spaced (L / NS apart along
       it), the first at the first pixel, going down the left side first */
    for (i = 0u; i < NS; i++) {
        const ssda_point_q8_t *p = &g_loops[0].contour[i];
        const bool on_side = p->x_q8 == 6 * 256 || p->x_q8 == 15 * 256 ||
                             p->y_q8 == 7 * 256 || p->y_q8 == 14 * 256;
        TEST_ASSERT_TRUE(on_side);
        TEST_ASSERT_TRUE(p->x_q8 >= 6 * 256 && p->x_q8 <= 15 * 256);
        TEST_ASSERT_TRUE(p->y_q8 >= 7 * 256 && p->y_q8 <= 14 * 256);
    }
    TEST_ASSERT_EQUAL_INT32(6 * 256, g_loops[0].contour[0].x_q8);
    TEST_ASSERT_EQUAL_INT32(7 * 256, g_loops[0].contour[0].y_q8);
    /* L = 32 px, 32 samples: one pixel apart: (6, 8), (6, 9), ... */
    TEST_ASSERT_EQUAL_INT32(6 * 256, g_loops[0].contour[1].x_q8);
    TEST_ASSERT_EQUAL_INT32(8 * 256, g_loops[0].contour[1].y_q8);
    TEST_ASSERT_EQUAL_INT32(7 * 256, g_loops[0].contour[8].x_q8); /* along the bottom */
    TEST_ASSERT_EQUAL_INT32(14 * 256, g_loops[0].contour[8].y_q8);
    /* private bits cleared, cycles kept */
    for (i = 0u; i < W * H; i++) {
        TEST_ASSERT_EQUAL_HEX16(0, g_map[i] & 0xF800u);
    }
    TEST_ASSERT_EQUAL_HEX16(SSDA_EDGE_ON, g_map[6u * W + 5u]);
}

static void test_each_filter(void)
{
    ssda_loops_config_t c = cfg_ns();
    ssda_loops_stats_t st;
    uint32_t n;
    clear(30u);
    rect(2u, 2u, 8u, 8u, 200u);     /* 25 px: too small */
    rect(12u, 2u, 24u, 14u, 40u);   /* 121 px, mean 40: too dark */
    rect(28u, 2u, 32u, 40u, 200u);  /* 3 x 37: P^2 / A = 80^2 / 111 = 57.7: too long */
    rect(36u, 2u, 60u, 44u, 200u);  /* 23 x 41 = 943 px: a loop */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, find(&c, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, n);
    TEST_ASSERT_EQUAL_UINT32(943u, g_loops[0].area);
    TEST_ASSERT_EQUAL_UINT32(1u, st.too_small);
    TEST_ASSERT_EQUAL_UINT32(1u, st.too_dark);
    TEST_ASSERT_EQUAL_UINT32(1u, st.too_long);
    TEST_ASSERT_EQUAL_UINT32(0u, st.too_large);
    /* the outside (larger than area_max: each part the raster scan enters
       again after the work filled up is counted) */
    TEST_ASSERT_TRUE(st.border >= 1u);
    /* the filters moved: everything kept but the outside */
    c.area_min = 20u;
    c.grey_min = SSDA_LOOPS_GREY_ANY;
    c.shape_max = 60u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, find(&c, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(4u, n);
    c.area_max = 900u;
    c.grey_min = 41;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, find(&c, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(2u, n);
    TEST_ASSERT_TRUE(st.too_large >= 1u); /* 943 > 900 (perhaps counted twice: see stats) */
    TEST_ASSERT_EQUAL_UINT32(1u, st.too_dark);
    /* max_loops 1: one written, the other counted */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_find(g_map, &g_view, &c, g_work, sizeof g_work,
                                                   g_loops, 1u, g_pts, sizeof g_pts, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, n);
    TEST_ASSERT_EQUAL_UINT32(2u, st.loops);
    TEST_ASSERT_EQUAL_UINT32(1u, st.dropped);
}

static void test_open_branches_pruned(void)
{
    ssda_loops_config_t c = cfg_ns();
    ssda_loops_stats_t st;
    uint32_t n, x, y;
    clear(30u);
    rect(10u, 10u, 30u, 30u, 100u);
    for (x = 14u; x <= 24u; x++) { /* a whisker into the loop, one out of it */
        g_map[20u * W + x] = x < 24u ? (uint16_t)0 : SSDA_EDGE_ON;
    }
    for (y = 14u; y <= 30u; y++) {
        g_map[y * W + 20u] = SSDA_EDGE_ON;
    }
    for (x = 31u; x <= 40u; x++) {
        g_map[15u * W + x] = SSDA_EDGE_ON;
    }
    /* an open "C" that encloses nothing */
    for (y = 5u; y <= 40u; y++) {
        g_map[y * W + 50u] = SSDA_EDGE_ON;
    }
    for (x = 50u; x <= 60u; x++) {
        g_map[5u * W + x] = SSDA_EDGE_ON;
        g_map[40u * W + x] = SSDA_EDGE_ON;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, find(&c, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, n);
    TEST_ASSERT_EQUAL_UINT32(19u * 19u, g_loops[0].area);
    /* whisker y 14..29, the lone pixel, the outer whisker, the C */
    TEST_ASSERT_EQUAL_UINT32(16u + 1u + 10u + 36u + 20u, st.pruned);
    TEST_ASSERT_EQUAL_HEX16(0, g_map[20u * W + 20u] & SSDA_EDGE_ON);
    TEST_ASSERT_EQUAL_HEX16(0, g_map[15u * W + 35u] & SSDA_EDGE_ON);
}

static void test_large_region_refused_everywhere(void)
{
    ssda_loops_config_t c = cfg_ns();
    ssda_loops_stats_t st;
    uint32_t n, x;
    /* a comb-shaped 400 px region (its teeth are entered separately by the
       raster scan) with a work of 101 entries (area_max 100), next to a
       small loop */
    clear(200u);
    rect(2u, 2u, 41u, 30u, 200u);
    for (x = 4u; x < 40u; x += 3u) {
        uint32_t y;
        for (y = 3u; y < 26u; y++) {
            g_map[y * W + x] = SSDA_EDGE_ON;
        }
    }
    rect(45u, 5u, 56u, 16u, 200u);
    c.area_max = 100u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_find(g_map, &g_view, &c, g_work,
                                                   SSDA_LOOPS_WORK_SIZE(100u), g_loops, MAXL,
                                                   g_pts, sizeof g_pts, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, n);
    TEST_ASSERT_EQUAL_UINT32(100u, g_loops[0].area);
    TEST_ASSERT_TRUE(st.too_large >= 1u);
    TEST_ASSERT_EQUAL_UINT32(0u, st.too_small);
}

static void test_contour_of_a_mask(void)
{
    static uint8_t mask[20][24];
    ssda_point_q8_t pts[16], poison[16];
    ssda_view_t v;
    uint32_t per, i;
    memset(mask, 0, sizeof mask);
    memset(&mask[3][5], 1, 9); /* a 9 x 4 block from (5, 3) */
    memset(&mask[4][5], 1, 9);
    memset(&mask[5][5], 1, 9);
    memset(&mask[6][5], 1, 9);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, mask, 24u, 20u, 24u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_contour(&v, 5u, 3u, 16u, pts, &per));
    TEST_ASSERT_EQUAL_UINT32((2u * 8u + 2u * 3u) * 256u, per);
    for (i = 0u; i < 16u; i++) { /* 22 px / 16: every 1.375 px along the sides */
        TEST_ASSERT_TRUE(pts[i].x_q8 == 5 * 256 || pts[i].x_q8 == 13 * 256 ||
                         pts[i].y_q8 == 3 * 256 || pts[i].y_q8 == 6 * 256);
    }
    TEST_ASSERT_EQUAL_INT32(5 * 256, pts[1].x_q8);
    TEST_ASSERT_EQUAL_INT32(3 * 256 + 352, pts[1].y_q8); /* 1.375 px down */
    /* a diagonal step is sqrt 2 long: a 2-pixel diagonal mask */
    memset(mask, 0, sizeof mask);
    mask[2][2] = 1u;
    mask[3][3] = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_contour(&v, 2u, 2u, 8u, pts, &per));
    TEST_ASSERT_EQUAL_UINT32(2u * 92682u / 256u, per);
    TEST_ASSERT_EQUAL_INT32(3 * 256, pts[4].x_q8); /* halfway round: the other pixel */
    TEST_ASSERT_EQUAL_INT32(3 * 256, pts[4].y_q8);
    /* one pixel: every sample at its centre */
    mask[3][3] = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_contour(&v, 2u, 2u, 8u, pts, NULL));
    for (i = 0u; i < 8u; i++) {
        TEST_ASSERT_EQUAL_INT32(2 * 256, pts[i].x_q8);
        TEST_ASSERT_EQUAL_INT32(2 * 256, pts[i].y_q8);
    }
    /* errors */
    memset(poison, 0x6B, sizeof poison);
    memcpy(pts, poison, sizeof pts);
    mask[2][3] = 1u; /* (3, 2) is not first in raster order of its set */
    mask[3][2] = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_loops_contour(&v, 2u, 3u, 8u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_loops_contour(&v, 10u, 10u, 8u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_loops_contour(&v, 2u, 2u, 12u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_loops_contour(&v, 2u, 2u, 4u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_loops_contour(&v, 2u, 2u, 2048u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_loops_contour(&v, 24u, 2u, 8u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_contour(NULL, 2u, 2u, 8u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_contour(&v, 2u, 2u, 8u, NULL, NULL));
    {
        static uint16_t m16[4];
        ssda_view_t v16;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v16, m16, 2u, 2u, 4u, SSDA_PIX_U16));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_loops_contour(&v16, 0u, 0u, 8u, pts, NULL));
        v16.height = 0u;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_loops_contour(&v16, 0u, 0u, 8u, pts, NULL));
    }
    TEST_ASSERT_EQUAL_MEMORY(poison, pts, sizeof pts);
}

/* Shapes whose outer boundary is known in closed form beyond blocks: an L
   (a concave corner is cut by one diagonal step), and a three-pixel
   "roof" whose boundary passes its first pixel twice (the trace must not
   stop there: Jacob's stop is back at the start about to repeat the first
   move). */
static void test_contour_concave_and_revisited(void)
{
    static uint8_t mask[16][16];
    ssda_point_q8_t pts[8];
    ssda_view_t v;
    uint32_t per, y;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, mask, 16u, 16u, 16u, SSDA_PIX_U8));
    /* L: x 1..10 of rows 1..3, x 1..3 of rows 4..10. Through the boundary
       pixels' centres: 9 + 2 + 6 across and back, sqrt 2 round the inner
       corner (4, 3) -> (3, 4), then 6 + 2 + 9 */
    memset(mask, 0, sizeof mask);
    for (y = 1u; y <= 3u; y++) {
        memset(&mask[y][1], 1, 10);
    }
    for (y = 4u; y <= 10u; y++) {
        memset(&mask[y][1], 1, 3);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_contour(&v, 1u, 1u, 8u, pts, &per));
    TEST_ASSERT_EQUAL_UINT32((34u * 65536u + 92682u) >> 8, per);
    /* the first sample at the start, then down the left side: 8 samples
       35.41 / 8 = 4.43 px apart; sample 2 at 8.85 px: (1, 9.85) */
    TEST_ASSERT_EQUAL_INT32(256, pts[0].x_q8);
    TEST_ASSERT_EQUAL_INT32(256, pts[0].y_q8);
    TEST_ASSERT_EQUAL_INT32(256, pts[2].x_q8);
    TEST_ASSERT_INT32_WITHIN(1, (int32_t)(9.8535 * 256.0), pts[2].y_q8);
    /* the roof (5, 5), (4, 6), (6, 6): 4 diagonal steps, start twice */
    memset(mask, 0, sizeof mask);
    mask[5][5] = 1u;
    mask[6][4] = 1u;
    mask[6][6] = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_contour(&v, 5u, 5u, 8u, pts, &per));
    TEST_ASSERT_EQUAL_UINT32(4u * 92682u / 256u, per);
    TEST_ASSERT_EQUAL_INT32(4 * 256, pts[2].x_q8); /* sqrt 2 along: (4, 6) */
    TEST_ASSERT_EQUAL_INT32(6 * 256, pts[2].y_q8);
    TEST_ASSERT_EQUAL_INT32(5 * 256, pts[4].x_q8); /* back at the start */
    TEST_ASSERT_EQUAL_INT32(5 * 256, pts[4].y_q8);
    TEST_ASSERT_EQUAL_INT32(6 * 256, pts[6].x_q8); /* then (6, 6) */
    TEST_ASSERT_EQUAL_INT32(6 * 256, pts[6].y_q8);
}

/* The whole chain on an image: a bright square on a textured background. */
static void test_image_to_loop(void)
{
    static uint8_t ring[SSDA_EDGE_RING_SIZE(W)];
    ssda_loops_config_t c = cfg_ns();
    ssda_loops_stats_t st;
    ssda_edge_stats_t es;
    test_rng_t r;
    uint32_t n, x, y;
    test_rng_seed(&r, 11u);
    for (y = 0u; y < H; y++) {
        for (x = 0u; x < W; x++) {
            const bool in = x >= 20u && x < 40u && y >= 14u && y < 32u; /* 20 x 18 */
            g_img[y][x] = (uint8_t)((in ? 180u : 70u) + test_rng_range(&r, 0u, 6u));
        }
    }
    (void)ssda_view_init(&g_view, g_img, W, H, W, SSDA_PIX_U8);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_detect(&g_view, 0u, g_map, sizeof g_map, ring,
                                                    sizeof ring));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, NULL, g_work, sizeof g_work,
                                                    &es));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, find(&c, &n, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, n);
    /* the square's centre (29.5, 22.5); the region lies inside its edge */
    TEST_ASSERT_INT32_WITHIN(128, 29 * 256 + 128, g_loops[0].cx_q8);
    TEST_ASSERT_INT32_WITHIN(128, 22 * 256 + 128, g_loops[0].cy_q8);
    TEST_ASSERT_TRUE(g_loops[0].area >= 16u * 14u && g_loops[0].area <= 20u * 18u);
    TEST_ASSERT_TRUE(g_loops[0].mean_q8 >= 180u * 256u);
}

static void test_errors_change_nothing(void)
{
    ssda_loops_config_t c = cfg_ns();
    ssda_loops_stats_t st, poison;
    ssda_view_t v16;
    static uint16_t img16[W * H];
    uint32_t n = 77u;
    clear(30u);
    rect(5u, 6u, 16u, 15u, 200u);
    memcpy(g_copy, g_map, sizeof g_map);
    memset(&poison, 0x21, sizeof poison);
    st = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_find(NULL, &g_view, &c, g_work, sizeof g_work,
                                                        g_loops, MAXL, g_pts, sizeof g_pts, &n,
                                                        &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_find(g_map, &g_view, &c, g_work,
                                                        sizeof g_work, NULL, MAXL, g_pts,
                                                        sizeof g_pts, &n, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_find(g_map, &g_view, &c, g_work,
                                                        sizeof g_work, g_loops, MAXL, g_pts,
                                                        sizeof g_pts, NULL, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v16, img16, W, H, W * 2u, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_loops_find(g_map, &v16, &c, g_work,
                                                          sizeof g_work, g_loops, MAXL, g_pts,
                                                          sizeof g_pts, &n, &st));
    c.samples = 48u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, find(&c, &n, &st));
    c = cfg_ns();
    c.area_min = 500u;
    c.area_max = 400u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, find(&c, &n, &st));
    c = cfg_ns();
    c.grey_min = 256;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, find(&c, &n, &st));
    c.grey_min = -2;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, find(&c, &n, &st));
    c = cfg_ns();
    c.area_max = (1u << 20) + 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, find(&c, &n, &st));
    c = cfg_ns();
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_loops_find(g_map, &g_view, &c, g_work,
                                                          SSDA_LOOPS_WORK_SIZE(1000u) - 1u,
                                                          g_loops, MAXL, g_pts, sizeof g_pts,
                                                          &n, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_loops_find(g_map, &g_view, &c, g_work,
                                                          sizeof g_work, g_loops, MAXL, g_pts,
                                                          sizeof g_pts - 1u, &n, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_loops_find(g_map, &g_view, &c,
                                                          (uint8_t *)g_work + 1,
                                                          sizeof g_work - 4u, g_loops, MAXL,
                                                          g_pts, sizeof g_pts, &n, &st));
    g_view.width = 4u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, find(&c, &n, &st));
    g_view.width = W;
    g_view.stride = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, find(&c, &n, &st));
    g_view.stride = W;
    TEST_ASSERT_EQUAL_UINT32(77u, n);
    TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    TEST_ASSERT_EQUAL_HEX16_ARRAY(g_copy, g_map, W * H);
    /* no loops asked for: counted only */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_find(g_map, &g_view, NULL, g_work, sizeof g_work,
                                                   NULL, 0u, NULL, 0u, &n, NULL));
    TEST_ASSERT_EQUAL_UINT32(0u, n);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_rectangles_known_in_closed_form);
    RUN_TEST(test_each_filter);
    RUN_TEST(test_open_branches_pruned);
    RUN_TEST(test_large_region_refused_everywhere);
    RUN_TEST(test_contour_of_a_mask);
    RUN_TEST(test_contour_concave_and_revisited);
    RUN_TEST(test_image_to_loop);
    RUN_TEST(test_errors_change_nothing);
    return UNITY_END();
}
