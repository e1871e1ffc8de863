/*
 * test_symbolic_limits.c - seed 001's stages at their limits: edges ending
 * on the map's border, gap closings refused for each of their reasons, a
 * pruning stack that overflows, descriptors and matches at the extremes of
 * their formats, transforms whose coefficients cannot be represented, and
 * the argument checks the other tests leave out. Each case states the
 * expected behaviour from the headers.
 */
#include <string.h>
#include "unity.h"
#include "ssda/edge.h"
#include "ssda/fourier.h"
#include "ssda/loops.h"
#include "ssda/symreg.h"
#include "edge_internal.h"
#include "fourier_internal.h"
#include "symreg_internal.h"

void setUp(void) {}
void tearDown(void) {}

#define W 40u
#define H 32u

static uint16_t g_map[W * H];
static uint32_t g_work[512];

static bool on(int x, int y)
{
    return (g_map[(uint32_t)y * W + (uint32_t)x] & SSDA_EDGE_ON) != 0u;
}

static void hline(uint32_t y, uint32_t x0, uint32_t x1, uint32_t s)
{
    uint32_t x;
    for (x = x0; x <= x1; x++) {
        g_map[y * W + x] = (uint16_t)(s | (SSDA_EDGE_DIR_H << 8) | SSDA_EDGE_ON);
    }
}

static void vline(uint32_t x, uint32_t y0, uint32_t y1)
{
    uint32_t y;
    for (y = y0; y <= y1; y++) {
        g_map[y * W + x] = SSDA_EDGE_ON;
    }
}

/* Edges that end on the map's border: extension and T rays look outside
   (outside counts as OFF, strength 0) and stop. */
static void test_edges_at_the_border(void)
{
    ssda_edge_stats_t st;
    uint32_t x;
    memset(g_map, 0, sizeof g_map);
    hline(0u, 0u, 12u, 40u); /* along the top row from the left corner */
    for (x = 13u; x < W; x++) {
        g_map[x] = (uint16_t)(40u | (SSDA_EDGE_DIR_H << 8)); /* strong, not ON */
    }
    vline(W - 1u, 10u, 20u);  /* on the right column */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, NULL, g_work, sizeof g_work,
                                                    &st));
    for (x = 0u; x < W; x++) { /* the top edge grew to the right corner, no further */
        TEST_ASSERT_TRUE(on((int)x, 0));
    }
    TEST_ASSERT_TRUE(st.extended >= 1u);
    TEST_ASSERT_TRUE(on((int)W - 1, 10) && on((int)W - 1, 20));
}

/* (e): facing ends 8 px apart along x and 4 px across (angle sum 53 deg,
   triangle 8.9 * (4 + 4) / 4 = 17.9 px^2): an I by default (<= 20 px^2),
   none with i_area_max 1; parallel lines make no V, the rays meet nothing. */
static void test_i_closing_by_area(void)
{
    ssda_edge_refine_config_t c;
    ssda_edge_stats_t st;
    memset(&c, 0, sizeof c);
    c.extend_min = 255u;
    memset(g_map, 0, sizeof g_map);
    hline(10u, 2u, 14u, 0u);
    hline(14u, 22u, 36u, 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work, &st));
    TEST_ASSERT_EQUAL_UINT32(1u, st.closed_i);
    TEST_ASSERT_TRUE(on(18, 12));
    c.i_area_max = 1u;
    memset(g_map, 0, sizeof g_map);
    hline(10u, 2u, 14u, 0u);
    hline(14u, 22u, 36u, 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.closed_i + st.closed_t + st.closed_v);
    TEST_ASSERT_FALSE(on(18, 12));
}

/* The ring helpers on hand-made codes. */
static void test_ring_helpers(void)
{
    /* chain_next needs a connection point entered from a set neighbour */
    TEST_ASSERT_EQUAL_UINT32(8u, ssda__chain_next(0x01u, 0u));        /* an end */
    TEST_ASSERT_EQUAL_UINT32(8u, ssda__chain_next(0x11u, 2u));        /* back not set */
    TEST_ASSERT_EQUAL_UINT32(4u, ssda__chain_next(0x11u, 0u));        /* E in, W out */
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__chain_next(0x03u | 0x40u, 6u)); /* S in; E NE: E */
    TEST_ASSERT_EQUAL_UINT32(8u, ssda__chain_next(0x07u | 0x40u, 6u)); /* E NE N: a 2 x 2 */
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__end_exit(0x03u));              /* E NE: E */
    TEST_ASSERT_EQUAL_UINT32(1u, ssda__end_exit(0x02u));              /* NE alone */
    TEST_ASSERT_EQUAL_UINT32(SSDA_EDGE_BRANCH, ssda__ring_class(0xFFu));
}

/* A chain of spurs deeper than the pruning stack: later passes finish it. */
static void test_pruning_with_a_small_stack(void)
{
    static uint8_t img[H][W];
    ssda_loops_config_t c;
    ssda_loops_stats_t st;
    ssda_view_t v;
    ssda_loop_t loops[1];
    ssda_point_q8_t pts[8];
    uint32_t n, x;
    memset(g_map, 0, sizeof g_map);
    memset(img, 100, sizeof img);
    for (x = 4u; x < 36u; x++) { /* a comb: a line with a tooth every other pixel */
        g_map[20u * W + x] = SSDA_EDGE_ON;
        if ((x & 1u) == 0u) {
            g_map[19u * W + x] = SSDA_EDGE_ON;
            g_map[18u * W + x] = SSDA_EDGE_ON;
        }
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, img, W, H, W, SSDA_PIX_U8));
    memset(&c, 0, sizeof c);
    c.area_max = 100u; /* work within g_work */
    c.area_min = 1u;
    c.area_max = 1u; /* work for 2 entries: the stack fills at once */
    c.samples = 8u;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_loops_find(g_map, &v, &c, g_work, SSDA_LOOPS_WORK_SIZE(1u),
                                                   loops, 1u, pts, sizeof pts, &n, &st));
    for (x = 0u; x < W * H; x++) {
        TEST_ASSERT_EQUAL_HEX16(0, g_map[x] & SSDA_EDGE_ON); /* all of it was open */
    }
    TEST_ASSERT_EQUAL_UINT32(0u, n);
}

/* Descriptors and matches at the ends of their formats. */
static void test_fourier_extremes(void)
{
    ssda_point_q8_t p[16];
    ssda_fd_t a, b, tiny, big;
    ssda_fd_match_t m;
    uint32_t k;
    static const int8_t sq[16][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {4, 1}, {4, 2},
                                     {4, 3}, {4, 4}, {3, 4}, {2, 4}, {1, 4}, {0, 4}, {0, 3},
                                     {0, 2}, {0, 1}}; /* a square's boundary, 16 steps */
    for (k = 0u; k < 16u; k++) { /* a tiny square: coefficients of a few Q8 LSB */
        p[k].x_q8 = sq[k][0] * 2;
        p[k].y_q8 = sq[k][1] * 2 - 3;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, 16u, 3u, &tiny));
    TEST_ASSERT_TRUE(tiny.energy_q16 > 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&tiny, &tiny, &m));
    TEST_ASSERT_TRUE(m.e2_q16 < 16384u); /* a few LSB per coefficient: coarse, but valid */
    for (k = 0u; k < 16u; k++) { /* the same, 500000 times larger */
        p[k].x_q8 = sq[k][0] * 1000000 - 8000000;
        p[k].y_q8 = sq[k][1] * 1000000;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, 16u, 3u, &big));
    /* bound with a ratio beyond Q16 (sum / A saturates): still <= E^2 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&tiny, &big, &m));
    TEST_ASSERT_TRUE(ssda__fd_e2_bound(&tiny, &big) <= m.e2_q16);
    TEST_ASSERT_TRUE(ssda__fd_e2_bound(&big, &tiny) <= 65535u);
    /* fixed: a square turned half a turn is itself started half way round
       (alpha takes the turn); a huge scale saturates E^2 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&big, &big, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match_fixed(&big, &big, 65536u, m.phi + 0x80000000u,
                                                       &m));
    TEST_ASSERT_TRUE(m.e2_q16 < 66u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match_fixed(&big, &tiny, 1u << 24, 0u, &m));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, m.e2_q16);
    /* coordinates at and beyond the limits, on each side */
    p[3].x_q8 = -(1 << 24);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, 16u, 3u, &a));
    p[3].x_q8 = 0;
    p[4].y_q8 = 1 << 24;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, 16u, 3u, &a));
    /* orders beyond the maximum, even when equal */
    a = big;
    b = big;
    a.order = SSDA_FD_MAX_ORDER + 1u;
    b.order = SSDA_FD_MAX_ORDER + 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match(&a, &b, &m));
}

/* Transforms whose coefficients do not fit, and saturating residuals. */
static void test_affine_limits(void)
{
    ssda_loop_t r[3], m[3];
    ssda__partner_t set[3];
    ssda_symreg_affine_t t;
    uint32_t i;
    int32_t u, v;
    memset(r, 0, sizeof r);
    memset(m, 0, sizeof m);
    for (i = 0u; i < 3u; i++) {
        set[i].mov = (uint16_t)i;
        set[i].e2 = 0u;
    }
    /* REF centroids 1/256 px apart, MOV ones 10^6 px apart: a scale of 2^28 */
    r[0].cx_q8 = 0;
    r[0].cy_q8 = 0;
    r[1].cx_q8 = 1;
    r[1].cy_q8 = 0;
    r[2].cx_q8 = 0;
    r[2].cy_q8 = 1;
    m[1].cx_q8 = 256000000;
    m[2].cy_q8 = 256000000;
    TEST_ASSERT_FALSE(ssda__symreg_fit(r, m, set, 3u, &t));
    /* a translation beyond int32 Q8 (MOV at -2^31 + 1 px, REF far away) */
    r[1].cx_q8 = 256000;
    r[2].cy_q8 = 256000;
    m[0].cx_q8 = -2147483647;
    m[1].cx_q8 = -2147483647 + 256000;
    m[1].cy_q8 = 0;
    m[2].cx_q8 = -2147483647;
    m[2].cy_q8 = 256000;
    for (i = 0u; i < 3u; i++) {
        r[i].cx_q8 += 2000000000;
    }
    TEST_ASSERT_FALSE(ssda__symreg_fit(r, m, set, 3u, &t));
    /* residuals and applied points saturate */
    memset(&t, 0, sizeof t);
    t.a_q16 = 0x7FFFFFFF;
    t.e_q16 = 0x7FFFFFFF;
    r[0].cx_q8 = 0x7FFFFFFF;
    r[0].cy_q8 = 0x7FFFFFFF;
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, ssda__symreg_resid(&t, &r[0], &m[0]));
    t.a_q16 = -0x7FFFFFFF;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg_apply(&t, 0x7FFFFFFF, 0, &u, &v));
    TEST_ASSERT_EQUAL_INT32(-0x7FFFFFFF, u);
    /* eq. 16 with a scale near 2^16 and half a turn: clamped coefficients */
    ssda__symreg_similarity(0xFFFFFFFFu, 0x80000000u, 0, 0, 0, 0, &t);
    TEST_ASSERT_EQUAL_INT32(-0x7FFFFFFF, t.a_q16);
}

/* Argument checks of ssda_symreg not covered elsewhere; a list of one
   nucleus; fewer pairs asked for than found. */
static void test_symreg_arguments(void)
{
    ssda_loop_t l[4];
    ssda_fd_t f[4];
    ssda_point_q8_t p[4][16];
    ssda_symreg_config_t c;
    ssda_symreg_result_t res;
    ssda_symreg_pair_t pair;
    uint32_t i, k;
    static const int32_t place[4][2] = {{20, 20}, {90, 25}, {30, 80}, {85, 90}};
    for (i = 0u; i < 4u; i++) { /* four different shapes */
        for (k = 0u; k < 16u; k++) {
            const int32_t r = 8 + (int32_t)((k * (i + 2u)) % 5u);
            static const int8_t dir[16][2] = {{4, 0}, {4, 1}, {3, 3}, {1, 4}, {0, 4}, {-1, 4},
                                              {-3, 3}, {-4, 1}, {-4, 0}, {-4, -1}, {-3, -3},
                                              {-1, -4}, {0, -4}, {1, -4}, {3, -3}, {4, -1}};
            p[i][k].x_q8 = (place[i][0] + dir[k][0] * r / 4) * 256;
            p[i][k].y_q8 = (place[i][1] + dir[k][1] * r / 4) * 256;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p[i], 16u, 4u, &f[i]));
        memset(&l[i], 0, sizeof l[i]);
        l[i].cx_q8 = place[i][0] * 256;
        l[i].cy_q8 = place[i][1] * 256;
        l[i].area = 200u;
        l[i].contour = p[i];
    }
    memset(&c, 0, sizeof c);
    c.nuclei = 1u;
    c.min_pairs = 3u; /* four loops only */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_symreg(l, f, 4u, l, f, 4u, &c, g_work, sizeof g_work,
                                               &pair, 1u, &res));
    TEST_ASSERT_EQUAL_UINT32(4u, res.pairs);         /* an image against itself */
    TEST_ASSERT_EQUAL_UINT32(1u, res.nuclei);
    TEST_ASSERT_EQUAL_UINT16(0u, pair.ref);          /* one written */
    TEST_ASSERT_DOUBLE_WITHIN(1e-3, 1.0, res.affine.a_q16 / 65536.0);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg(l, NULL, 4u, l, f, 4u, NULL, g_work,
                                                    sizeof g_work, NULL, 0u, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_symreg(l, f, 4u, NULL, f, 4u, NULL, g_work,
                                                    sizeof g_work, NULL, 0u, &res));
    memset(&c, 0, sizeof c);
    c.scale_max_q16 = 0x100001u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(l, f, 4u, l, f, 4u, &c, g_work,
                                                   sizeof g_work, NULL, 0u, &res));
    memset(&c, 0, sizeof c);
    c.area_ratio_q8 = 65537u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(l, f, 4u, l, f, 4u, &c, g_work,
                                                   sizeof g_work, NULL, 0u, &res));
    memset(&c, 0, sizeof c);
    c.shear_q16 = 65537u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(l, f, 4u, l, f, 4u, &c, g_work,
                                                   sizeof g_work, NULL, 0u, &res));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(l, f, 4u, l, f, SSDA_SYMREG_MAX_LOOPS + 1u,
                                                   NULL, g_work, sizeof g_work, NULL, 0u, &res));
    f[2].order = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(l, f, 4u, l, f, 4u, NULL, g_work,
                                                   sizeof g_work, NULL, 0u, &res));
    f[2].order = SSDA_FD_MAX_ORDER + 1u;
    f[0].order = SSDA_FD_MAX_ORDER + 1u;
    f[1].order = SSDA_FD_MAX_ORDER + 1u;
    f[3].order = SSDA_FD_MAX_ORDER + 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(l, f, 4u, l, f, 4u, NULL, g_work,
                                                   sizeof g_work, NULL, 0u, &res));
    /* MOV only */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_symreg(NULL, NULL, 0u, l, f, 4u, NULL, g_work,
                                                   sizeof g_work, NULL, 0u, &res));
}

/* Argument checks of the edge and loop calls not covered elsewhere. */
static void test_edge_and_loop_arguments(void)
{
    static uint8_t img[H][W];
    ssda_view_t v;
    ssda_loops_config_t c;
    ssda_loop_t loops[2];
    ssda_point_q8_t pts[2 * 64];
    uint32_t n;
    memset(img, 0, sizeof img);
    memset(g_map, 0, sizeof g_map);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_edge_refine(g_map, W, 4u, NULL, g_work,
                                                         sizeof g_work, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE,
                          ssda_edge_refine((uint16_t *)(void *)((uint8_t *)g_map + 1), W, H - 1u,
                                           NULL, g_work, sizeof g_work, NULL));
    {
        ssda_edge_refine_config_t rc;
        memset(&rc, 0, sizeof rc);
        rc.fit_len = 16u; /* the largest accepted */
        hline(5u, 5u, 30u, 0u);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &rc, g_work, sizeof g_work,
                                                        NULL));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, img, W, H, W, SSDA_PIX_U8));
    memset(&c, 0, sizeof c);
    c.area_max = 100u; /* work within g_work */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_find(g_map, NULL, &c, g_work, sizeof g_work,
                                                        loops, 2u, pts, sizeof pts, &n, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_find(g_map, &v, &c, g_work, sizeof g_work,
                                                        loops, 2u, NULL, sizeof pts, &n, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_loops_find(g_map, &v, &c, NULL, sizeof g_work,
                                                        loops, 2u, pts, sizeof pts, &n, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE,
                          ssda_loops_find(g_map, &v, &c, g_work, sizeof g_work, loops, 1u,
                                          (ssda_point_q8_t *)(void *)((uint8_t *)pts + 2),
                                          sizeof pts - 4u, &n, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE,
                          ssda_loops_find((uint16_t *)(void *)((uint8_t *)g_map + 1), &v, &c,
                                          g_work, sizeof g_work, loops, 2u, pts, sizeof pts, &n,
                                          NULL));
    v.height = 4u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_loops_find(g_map, &v, &c, g_work, sizeof g_work,
                                                        loops, 2u, pts, sizeof pts, &n, NULL));
    v.height = H;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_loops_contour(&v, 0u, H, 8u, pts, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_edges_at_the_border);
    RUN_TEST(test_i_closing_by_area);
    RUN_TEST(test_ring_helpers);
    RUN_TEST(test_pruning_with_a_small_stack);
    RUN_TEST(test_fourier_extremes);
    RUN_TEST(test_affine_limits);
    RUN_TEST(test_symreg_arguments);
    RUN_TEST(test_edge_and_loop_arguments);
    return UNITY_END();
}
