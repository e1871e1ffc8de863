/*
 * test_edge_refine.c - the seed's 3 x 3 stages (include/ssda/edge.h):
 * the appendix's classification of all 256 neighbourhoods against a count
 * of runs written here; thinning that keeps the topology (components of
 * edges and of background counted here before and after) and leaves no
 * deletable unsuitable pixel; extension along the strength; T, I and V
 * closings on drawn maps; errors that change nothing.
 */
#include <string.h>
#include "unity.h"
#include "ssda/edge.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

#define W 48u
#define H 40u

static uint16_t g_map[W * H], g_before[W * H];
static uint32_t g_work[256];
static uint8_t g_seen[(W + 2u) * (H + 2u)];
static uint32_t g_stack[(W + 2u) * (H + 2u)];

static const int ring_dx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
static const int ring_dy[8] = {0, -1, -1, -1, 0, 1, 1, 1};

static bool on(const uint16_t *m, int x, int y)
{
    return x >= 0 && y >= 0 && x < (int)W && y < (int)H && (m[y * (int)W + x] & SSDA_EDGE_ON) != 0u;
}

/* Components of ON pixels (8-connected) or, with background set, of OFF
   pixels (4-connected) on the map padded by one OFF pixel all round. */
static uint32_t components(const uint16_t *m, bool background)
{
    const int pw = (int)W + 2, ph = (int)H + 2;
    uint32_t n = 0u;
    int x, y;
    memset(g_seen, 0, sizeof g_seen);
    for (y = 0; y < ph; y++) {
        for (x = 0; x < pw; x++) {
            uint32_t top = 0u;
            if (g_seen[y * pw + x] || on(m, x - 1, y - 1) == background) {
                continue;
            }
            n++;
            g_seen[y * pw + x] = 1u;
            g_stack[top++] = (uint32_t)(y * pw + x);
            while (top > 0u) {
                const int p = (int)g_stack[--top], px = p % pw, py = p / pw;
                int k;
                for (k = 0; k < 8; k += background ? 2 : 1) {
                    const int qx = px + ring_dx[k], qy = py + ring_dy[k];
                    if (qx < 0 || qy < 0 || qx >= pw || qy >= ph || g_seen[qy * pw + qx] ||
                        on(m, qx - 1, qy - 1) == background) {
                        continue;
                    }
                    g_seen[qy * pw + qx] = 1u;
                    g_stack[top++] = (uint32_t)(qy * pw + qx);
                }
            }
        }
    }
    return n;
}

/* The appendix, written from its text: runs of edge pixels around the ring
   (alpha_i != 0 count); unsuitable: four or more in a row, or three in a
   row with the centre on the diagonal (a 2 x 2 block). */
static int appendix_class(uint32_t ring)
{
    int runs = 0, k, unsuitable = 0;
    if (ring == 0u) {
        return SSDA_EDGE_ISOLATED;
    }
    if (ring == 0xFFu) {
        return SSDA_EDGE_BRANCH;
    }
    for (k = 0; k < 8; k++) {
        if ((ring >> k & 1u) && !(ring >> ((k + 7) % 8) & 1u)) {
            int len = 0;
            while (ring >> ((k + len) % 8) & 1u) {
                len++;
            }
            runs++;
            if (len >= 4 || (len == 3 && ((k + 1) % 2) == 1)) {
                unsuitable = 1;
            }
        }
    }
    if (unsuitable || runs >= 3) {
        return SSDA_EDGE_BRANCH;
    }
    return runs == 1 ? SSDA_EDGE_END : SSDA_EDGE_CONN;
}

static void test_classification_of_every_ring(void)
{
    uint32_t ring;
    int k;
    for (ring = 0u; ring < 256u; ring++) {
        memset(g_map, 0, sizeof g_map);
        g_map[10u * W + 10u] = SSDA_EDGE_ON;
        for (k = 0; k < 8; k++) {
            if (ring >> k & 1u) {
                g_map[(uint32_t)(10 + ring_dy[k]) * W + (uint32_t)(10 + ring_dx[k])] = SSDA_EDGE_ON;
            }
        }
        TEST_ASSERT_EQUAL_INT(appendix_class(ring), ssda_edge_classify(g_map, W, H, 10u, 10u));
    }
    /* named patterns: a straight line, its tip, a T, a 2 x 2 block */
    memset(g_map, 0, sizeof g_map);
    for (k = 0; k < 5; k++) {
        g_map[5u * W + 3u + (uint32_t)k] = SSDA_EDGE_ON;
    }
    g_map[6u * W + 5u] = SSDA_EDGE_ON;
    TEST_ASSERT_EQUAL_INT(SSDA_EDGE_END, ssda_edge_classify(g_map, W, H, 3u, 5u));
    TEST_ASSERT_EQUAL_INT(SSDA_EDGE_CONN, ssda_edge_classify(g_map, W, H, 4u, 5u));
    TEST_ASSERT_EQUAL_INT(SSDA_EDGE_BRANCH, ssda_edge_classify(g_map, W, H, 5u, 5u));
    g_map[0] = SSDA_EDGE_ON; /* a corner of the map: outside counts as OFF */
    TEST_ASSERT_EQUAL_INT(SSDA_EDGE_ISOLATED, ssda_edge_classify(g_map, W, H, 0u, 0u));
    g_map[1] = SSDA_EDGE_ON;
    g_map[W] = SSDA_EDGE_ON;
    g_map[W + 1u] = SSDA_EDGE_ON;
    TEST_ASSERT_EQUAL_INT(SSDA_EDGE_BRANCH, ssda_edge_classify(g_map, W, H, 0u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_classify(NULL, W, H, 0u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_edge_classify(g_map, W, H, W, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_edge_classify(g_map, W, H, 0u, H));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_classify(g_map, W, H, 9u, 9u));
}

static const ssda_edge_refine_config_t thin_only = {255u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 1u};

/* Whether the thinning could still delete (x, y): unsuitable, one
   8-component around it, an OFF 4-neighbour. */
static bool still_deletable(const uint16_t *m, int x, int y)
{
    uint32_t ring = 0u, k, joins = 0u, runs = 0u, bg4 = 0u;
    for (k = 0u; k < 8u; k++) {
        ring |= on(m, x + ring_dx[k], y + ring_dy[k]) ? 1u << k : 0u;
    }
    if (appendix_class(ring) != SSDA_EDGE_BRANCH || ring == 0xFFu) {
        return false;
    }
    for (k = 0u; k < 8u; k++) {
        runs += ((ring >> k & 1u) && !(ring >> ((k + 7u) % 8u) & 1u)) ? 1u : 0u;
        if (k % 2u == 0u) {
            bg4 += (ring >> k & 1u) ? 0u : 1u;
            joins += ((ring >> k & 1u) && !(ring >> (k + 1u) % 8u & 1u) &&
                      (ring >> (k + 2u) % 8u & 1u)) ? 1u : 0u;
        }
    }
    {
        bool unsuitable = false;
        for (k = 0u; k < 8u; k++) {
            if ((ring >> k & 1u) && !(ring >> ((k + 7u) % 8u) & 1u)) {
                uint32_t len = 0u;
                while (len < 8u && (ring >> ((k + len) % 8u) & 1u)) {
                    len++;
                }
                unsuitable = unsuitable || len >= 4u || (len == 3u && (k + 1u) % 2u == 1u);
            }
        }
        if (!unsuitable) {
            return false; /* a branch by its runs, not a thinning target */
        }
    }
    return (joins >= runs ? 1u : runs - joins) == 1u && bg4 > 0u;
}

static void test_thinning_keeps_topology(void)
{
    test_rng_t r;
    uint32_t trial, i, x, y;
    ssda_edge_stats_t st;
    test_rng_seed(&r, 3u);
    for (trial = 0u; trial < 40u; trial++) {
        /* random blobs and lines, some thick, some with holes */
        memset(g_map, 0, sizeof g_map);
        for (i = 0u; i < 6u; i++) {
            const uint32_t cx = test_rng_range(&r, 4u, W - 5u), cy = test_rng_range(&r, 4u, H - 5u);
            const uint32_t rw = test_rng_range(&r, 1u, 6u), rh = test_rng_range(&r, 1u, 6u);
            const bool hollow = (test_rng_next(&r) & 1u) != 0u;
            for (y = cy - (rh < cy ? rh : cy); y <= cy + rh && y < H; y++) {
                for (x = cx - (rw < cx ? rw : cx); x <= cx + rw && x < W; x++) {
                    const bool inner = x + 2u < cx + rw && x > cx - rw + 1u && y + 2u < cy + rh &&
                                       y > cy - rh + 1u;
                    if (!(hollow && inner)) {
                        g_map[y * W + x] = SSDA_EDGE_ON | 0x23u;
                    }
                }
            }
        }
        for (i = 0u; i < 30u; i++) { /* noise pixels */
            g_map[test_rng_range(&r, 0u, W * H - 1u)] = SSDA_EDGE_ON;
        }
        memcpy(g_before, g_map, sizeof g_map);
        {
            const uint32_t fg = components(g_map, false) - 0u, bg = components(g_map, true);
            uint32_t isolated = 0u;
            for (y = 0u; y < H; y++) {
                for (x = 0u; x < W; x++) {
                    uint32_t k, n = 0u;
                    for (k = 0u; k < 8u; k++) {
                        n += on(g_map, (int)x + ring_dx[k], (int)y + ring_dy[k]) ? 1u : 0u;
                    }
                    isolated += (on(g_map, (int)x, (int)y) && n == 0u) ? 1u : 0u;
                }
            }
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &thin_only, g_work,
                                                            sizeof g_work, &st));
            /* isolated points go; every other component and hole stays */
            TEST_ASSERT_EQUAL_UINT32(fg - isolated, components(g_map, false));
            TEST_ASSERT_EQUAL_UINT32(bg, components(g_map, true));
        }
        for (i = 0u; i < W * H; i++) {
            /* only deletions; strength and direction bits untouched */
            TEST_ASSERT_TRUE((g_map[i] & ~SSDA_EDGE_ON) == (g_before[i] & ~SSDA_EDGE_ON));
            TEST_ASSERT_FALSE((g_map[i] & SSDA_EDGE_ON) && !(g_before[i] & SSDA_EDGE_ON));
        }
        for (y = 0u; y < H; y++) {
            for (x = 0u; x < W; x++) {
                if (on(g_map, (int)x, (int)y)) {
                    TEST_ASSERT_FALSE(still_deletable(g_map, (int)x, (int)y));
                }
            }
        }
        TEST_ASSERT_EQUAL_UINT32(0u, st.extended + st.closed_t + st.closed_i + st.closed_v);
    }
}

/* A horizontal run of pixels at row y from x0 to x1 with strength s,
   direction d (ON if on). */
static void run(uint32_t y, uint32_t x0, uint32_t x1, uint32_t s, uint32_t d, bool lit)
{
    uint32_t x;
    for (x = x0; x <= x1; x++) {
        g_map[y * W + x] = (uint16_t)(s | (d << 8) | (lit ? SSDA_EDGE_ON : 0u));
    }
}

static void column(uint32_t x, uint32_t y0, uint32_t y1, uint32_t s, uint32_t d, bool lit)
{
    uint32_t y;
    for (y = y0; y <= y1; y++) {
        g_map[y * W + x] = (uint16_t)(s | (d << 8) | (lit ? SSDA_EDGE_ON : 0u));
    }
}

static void test_extension_follows_the_strength(void)
{
    ssda_edge_stats_t st;
    static const ssda_edge_refine_config_t no_close = {0u, 0u, 0u, 0u, 0u, 0u, 0u, 0u, 1u};
    uint32_t x;
    /* a horizontal edge whose middle is weak (strength 8: not ON after the
       ridge thinning, but >= 3): both ends grow into it and meet */
    memset(g_map, 0, sizeof g_map);
    run(10u, 5u, 15u, 20u, SSDA_EDGE_DIR_H, true);
    run(10u, 16u, 30u, 8u, SSDA_EDGE_DIR_H, false);
    run(10u, 31u, 40u, 20u, SSDA_EDGE_DIR_H, true);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &no_close, g_work,
                                                    sizeof g_work, &st));
    for (x = 5u; x <= 40u; x++) {
        TEST_ASSERT_TRUE(on(g_map, (int)x, 10));
    }
    TEST_ASSERT_EQUAL_UINT32(4u, st.ends);
    TEST_ASSERT_EQUAL_UINT32(1u, st.extend_joined);
    TEST_ASSERT_EQUAL_UINT32(2u, st.end); /* the two far ends remain */
    /* too weak (2 < 3), or running across the step: no extension */
    memset(g_map, 0, sizeof g_map);
    run(10u, 5u, 15u, 20u, SSDA_EDGE_DIR_H, true);
    run(10u, 16u, 20u, 2u, SSDA_EDGE_DIR_H, false);
    run(20u, 5u, 15u, 20u, SSDA_EDGE_DIR_H, true);
    run(20u, 16u, 20u, 9u, SSDA_EDGE_DIR_V, false);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &no_close, g_work,
                                                    sizeof g_work, &st));
    TEST_ASSERT_FALSE(on(g_map, 16, 10));
    TEST_ASSERT_FALSE(on(g_map, 16, 20));
    TEST_ASSERT_EQUAL_UINT32(0u, st.extended);
    /* a spur shorter than 3 px has no end to extend */
    memset(g_map, 0, sizeof g_map);
    column(20u, 5u, 30u, 20u, SSDA_EDGE_DIR_V, true);
    run(15u, 21u, 22u, 20u, SSDA_EDGE_DIR_H, true);
    run(15u, 23u, 35u, 10u, SSDA_EDGE_DIR_H, false);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &no_close, g_work,
                                                    sizeof g_work, &st));
    TEST_ASSERT_FALSE(on(g_map, 23, 15));
}

/* (e) on drawn maps with no strength: T, I and V. */
static void test_t_i_v_closings(void)
{
    ssda_edge_stats_t st;
    uint32_t x, y;
    /* T: a horizontal arm ending 5 px short of a vertical edge */
    memset(g_map, 0, sizeof g_map);
    column(30u, 5u, 35u, 0u, 0u, true);
    run(20u, 8u, 24u, 0u, 0u, true);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, NULL, g_work, sizeof g_work,
                                                    &st));
    for (x = 8u; x <= 30u; x++) {
        TEST_ASSERT_TRUE(on(g_map, (int)x, 20));
    }
    TEST_ASSERT_EQUAL_UINT32(1u, st.closed_t);
    /* beyond the reach (gap_max 4 < 5): nothing */
    {
        ssda_edge_refine_config_t c;
        memset(&c, 0, sizeof c);
        c.gap_max = 4u;
        memset(g_map, 0, sizeof g_map);
        column(30u, 5u, 35u, 0u, 0u, true);
        run(20u, 8u, 24u, 0u, 0u, true);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
        TEST_ASSERT_FALSE(on(g_map, 25, 20));
        TEST_ASSERT_EQUAL_UINT32(0u, st.closed_t + st.closed_i + st.closed_v);
    }
    /* I: two collinear arms 6 px apart */
    memset(g_map, 0, sizeof g_map);
    run(12u, 4u, 18u, 0u, 0u, true);
    run(12u, 25u, 40u, 0u, 0u, true);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, NULL, g_work, sizeof g_work,
                                                    &st));
    for (x = 4u; x <= 40u; x++) {
        TEST_ASSERT_TRUE(on(g_map, (int)x, 12));
    }
    TEST_ASSERT_EQUAL_UINT32(1u, st.closed_i);
    /* V: a right-angle corner missing: arms end at (20, 10) going right
       and (25, 15) going up; their lines meet at (25, 10) */
    memset(g_map, 0, sizeof g_map);
    run(10u, 5u, 20u, 0u, 0u, true);
    column(25u, 15u, 32u, 0u, 0u, true);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, NULL, g_work, sizeof g_work,
                                                    &st));
    for (x = 5u; x <= 25u; x++) {
        TEST_ASSERT_TRUE(on(g_map, (int)x, 10));
    }
    for (y = 10u; y <= 32u; y++) {
        TEST_ASSERT_TRUE(on(g_map, 25, (int)y));
    }
    TEST_ASSERT_EQUAL_UINT32(1u, st.closed_v);
    TEST_ASSERT_EQUAL_UINT32(0u, st.closed_i + st.closed_t);
    /* a V too sharp for v_angle_deg 120: not a V (nor an I or a T) */
    {
        ssda_edge_refine_config_t c;
        memset(&c, 0, sizeof c);
        c.v_angle_deg = 120u;
        memset(g_map, 0, sizeof g_map);
        run(10u, 5u, 20u, 0u, 0u, true);
        column(25u, 15u, 32u, 0u, 0u, true);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
        TEST_ASSERT_EQUAL_UINT32(0u, st.closed_v);
    }
}

static void test_work_limits_and_errors(void)
{
    ssda_edge_stats_t st, poison;
    ssda_edge_refine_config_t c;
    uint32_t i;
    /* ten separate segments, room for four ends */
    memset(g_map, 0, sizeof g_map);
    for (i = 0u; i < 10u; i++) {
        run(3u + 3u * i, 5u, 12u, 0u, 0u, true);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, NULL, g_work,
                                                    SSDA_EDGE_WORK_SIZE(4), &st));
    TEST_ASSERT_EQUAL_UINT32(20u, st.ends);
    TEST_ASSERT_EQUAL_UINT32(16u, st.ends_dropped);

    memset(&poison, 0x5C, sizeof poison);
    st = poison;
    memcpy(g_before, g_map, sizeof g_map);
    memset(&c, 0, sizeof c);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_refine(NULL, W, H, NULL, g_work,
                                                         sizeof g_work, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_refine(g_map, W, H, NULL, NULL,
                                                         sizeof g_work, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_edge_refine(g_map, 4u, H, NULL, g_work,
                                                         sizeof g_work, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_edge_refine(g_map, W, H, NULL, g_work, 7u, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE,
                          ssda_edge_refine(g_map, W, H, NULL, (uint8_t *)g_work + 2,
                                           sizeof g_work - 4u, &st));
    c.gap_max = 65u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
    c.gap_max = 0u;
    c.fit_len = 1u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
    c.fit_len = 17u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
    c.fit_len = 0u;
    c.spur_min = 17u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
    c.spur_min = 0u;
    c.i_angle_deg = 181u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
    c.i_angle_deg = 0u;
    c.v_angle_deg = 181u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_refine(g_map, W, H, &c, g_work, sizeof g_work,
                                                        &st));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    TEST_ASSERT_EQUAL_HEX16_ARRAY(g_before, g_map, W * H);
    /* stats may be NULL */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_refine(g_map, W, H, NULL, g_work, sizeof g_work,
                                                    NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_classification_of_every_ring);
    RUN_TEST(test_thinning_keeps_topology);
    RUN_TEST(test_extension_follows_the_strength);
    RUN_TEST(test_t_i_v_closings);
    RUN_TEST(test_work_limits_and_errors);
    return UNITY_END();
}
