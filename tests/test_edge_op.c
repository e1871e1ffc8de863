/*
 * test_edge_op.c - the 5 x 5 two-region edge operator and the ridge
 * thinning of include/ssda/edge.h against a reference written here from
 * the header's definition: for each direction the two ten-pixel regions by
 * the sign of the line function, their sums of squared deviations (10x,
 * exact), the smallest sum's direction (ties: smaller d), the strength
 * floor(|mean a - mean b|); then the thinning rule. Streaming equals the
 * one-shot call; every error leaves the outputs unchanged.
 */
#include <string.h>
#include "unity.h"
#include "ssda/edge.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#define W 41u
#define H 29u

static uint8_t g_img[H][W];
static uint16_t g_map[W * H], g_ref[W * H];
static uint8_t g_ring[SSDA_EDGE_RING_SIZE(W)];

/* side of (dx, dy) for direction d: -1 region a, +1 region b, 0 the line */
static int side(uint32_t d, int dx, int dy)
{
    int v;
    switch (d) {
    case 0: v = dy; break;
    case 1: v = dx + dy; break;
    case 2: v = dx; break;
    default: v = dx - dy; break;
    }
    return v < 0 ? -1 : (v > 0 ? 1 : 0);
}

static uint16_t reference_pixel(uint32_t x, uint32_t y)
{
    int64_t best_ss = 0, best_diff = 0;
    uint32_t d, best = 0u;
    for (d = 0u; d < 4u; d++) {
        int64_t sa = 0, sb = 0, qa = 0, qb = 0, na = 0, nb = 0, ss, diff;
        int dx, dy;
        for (dy = -2; dy <= 2; dy++) {
            for (dx = -2; dx <= 2; dx++) {
                const int64_t p = g_img[(int)y + dy][(int)x + dx];
                const int s = side(d, dx, dy);
                if (s < 0) {
                    sa += p;
                    qa += p * p;
                    na++;
                } else if (s > 0) {
                    sb += p;
                    qb += p * p;
                    nb++;
                }
            }
        }
        TEST_ASSERT_EQUAL_INT64(10, na);
        TEST_ASSERT_EQUAL_INT64(10, nb);
        /* 10 x (sum of squared deviations of a + of b) */
        ss = 10 * qa - sa * sa + 10 * qb - sb * sb;
        diff = sa > sb ? sa - sb : sb - sa;
        if (d == 0u || ss < best_ss) {
            best_ss = ss;
            best_diff = diff;
            best = d;
        }
    }
    return (uint16_t)((uint32_t)(best_diff / 10) | (best << 8));
}

/* The reference map: operator, then thinning with threshold t. */
static void reference_map(uint32_t t)
{
    static const int across[4][2] = {{0, 1}, {1, 1}, {1, 0}, {1, -1}};
    uint32_t x, y;
    memset(g_ref, 0, sizeof g_ref);
    for (y = 2u; y + 2u < H; y++) {
        for (x = 2u; x + 2u < W; x++) {
            g_ref[y * W + x] = reference_pixel(x, y);
        }
    }
    for (y = 2u; y + 2u < H; y++) {
        for (x = 2u; x + 2u < W; x++) {
            const uint32_t m = g_ref[y * W + x];
            const uint32_t s = m & 0xFFu, d = (m >> 8) & 3u;
            int k, beaten = 0;
            for (k = -1; k <= 1; k += 2) {
                const uint32_t n = g_ref[(y + (uint32_t)(k * across[d][1])) * W + x +
                                         (uint32_t)(k * across[d][0])];
                if ((n & 0xFFu) > s && ((n >> 8) & 3u) == d) {
                    beaten = 1;
                }
            }
            if (s >= t && !beaten) {
                g_ref[y * W + x] = (uint16_t)(m | SSDA_EDGE_ON);
            }
        }
    }
}

static void detect_and_compare(uint8_t t)
{
    ssda_view_t v;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img, W, H, W, SSDA_PIX_U8));
    memset(g_map, 0xA5, sizeof g_map);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_detect(&v, t, g_map, sizeof g_map, g_ring,
                                                    sizeof g_ring));
    reference_map(t != 0u ? t : SSDA_EDGE_DEFAULT_STRENGTH);
    TEST_ASSERT_EQUAL_HEX16_ARRAY(g_ref, g_map, W * H);
}

static void test_random_textures_match_reference(void)
{
    test_rng_t r;
    uint32_t i, x, y;
    test_rng_seed(&r, 5u);
    for (i = 0u; i < 6u; i++) {
        if (i % 2u == 0u) {
            test_fill_texture_u8(&g_img[0][0], W, H, W, &r);
        } else { /* raw noise: many ties and direction changes */
            for (y = 0u; y < H; y++) {
                for (x = 0u; x < W; x++) {
                    g_img[y][x] = (uint8_t)test_rng_range(&r, 0u, i < 4u ? 255u : 3u);
                }
            }
        }
        detect_and_compare((uint8_t)(i * 7u));
    }
}

/* Steps of every contrast 0..255, at four orientations: the strength's
   floor(|Sa - Sb| / 10) over its whole range, and the worst case of
   every sum (255 against 0). */
static void test_steps_of_every_contrast(void)
{
    uint32_t c, x, y, o;
    for (o = 0u; o < 4u; o++) {
        for (c = 0u; c < 256u; c += 1u + (c % 7u)) {
            for (y = 0u; y < H; y++) {
                for (x = 0u; x < W; x++) {
                    const int v = o == 0u ? (int)y - 14 : o == 1u ? (int)x - 20
                                  : o == 2u ? (int)x + (int)y - 34 : (int)x - (int)y - 6;
                    g_img[y][x] = (uint8_t)(v >= 0 ? c : 0u);
                }
            }
            detect_and_compare(1u);
        }
    }
    /* a checkerboard of 0 and 255: the largest squares and score */
    for (y = 0u; y < H; y++) {
        for (x = 0u; x < W; x++) {
            g_img[y][x] = (uint8_t)(((x + y) & 1u) != 0u ? 255u : 0u);
        }
    }
    detect_and_compare(1u);
}

static void test_push_equals_detect_and_border(void)
{
    ssda_edge_job_t job;
    test_rng_t r;
    uint32_t y, x;
    static uint16_t streamed[W * H];
    test_rng_seed(&r, 9u);
    test_fill_texture_u8(&g_img[0][0], W, H, W, &r);
    detect_and_compare(0u);
    memset(streamed, 0x5A, sizeof streamed);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_init(&job, W, H, 0u, streamed, sizeof streamed,
                                                  g_ring, sizeof g_ring));
    for (y = 0u; y < H; y++) {
        uint8_t row[W];
        memcpy(row, g_img[y], W);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_push(&job, row));
        memset(row, 0xFF, W); /* the caller may reuse its row */
    }
    TEST_ASSERT_EQUAL_HEX16_ARRAY(g_map, streamed, W * H);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_edge_push(&job, g_img[0]));
    for (x = 0u; x < W; x++) { /* the two outermost rows and columns are 0 */
        TEST_ASSERT_EQUAL_HEX16(0, g_map[x]);
        TEST_ASSERT_EQUAL_HEX16(0, g_map[W + x]);
        TEST_ASSERT_EQUAL_HEX16(0, g_map[(H - 1u) * W + x]);
        TEST_ASSERT_EQUAL_HEX16(0, g_map[(H - 2u) * W + x]);
    }
    for (y = 0u; y < H; y++) {
        TEST_ASSERT_EQUAL_HEX16(0, g_map[y * W + 1u]);
        TEST_ASSERT_EQUAL_HEX16(0, g_map[y * W + W - 2u]);
    }
}

static void test_smallest_image_and_strided_view(void)
{
    static uint8_t big[7][16];
    static uint16_t m[5 * 5], want[5 * 5];
    ssda_view_t v;
    uint32_t x, y;
    for (y = 0u; y < 7u; y++) {
        for (x = 0u; x < 16u; x++) {
            big[y][x] = (uint8_t)(x * 37u + y * 11u);
        }
    }
    /* a 5 x 5 roi of a strided buffer: only its centre pixel has a window */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, &big[1][3], 5u, 5u, 16u, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_edge_detect(&v, 1u, m, sizeof m, g_ring, sizeof g_ring));
    memset(g_img, 0, sizeof g_img);
    for (y = 0u; y < 5u; y++) {
        for (x = 0u; x < 5u; x++) {
            g_img[y][x] = big[1u + y][3u + x];
        }
    }
    memset(want, 0, sizeof want);
    want[12] = reference_pixel(2u, 2u);
    if ((want[12] & 0xFFu) >= 1u) {
        want[12] |= SSDA_EDGE_ON;
    }
    TEST_ASSERT_EQUAL_HEX16_ARRAY(want, m, 25u);
}

static void test_errors_change_nothing(void)
{
    ssda_edge_job_t job, poison;
    ssda_view_t v, v16;
    static uint16_t img16[W * H];
    memset(&poison, 0x3C, sizeof poison);
    job = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_init(NULL, W, H, 0u, g_map, sizeof g_map,
                                                       g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_init(&job, W, H, 0u, NULL, sizeof g_map,
                                                       g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_init(&job, W, H, 0u, g_map, sizeof g_map,
                                                       NULL, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_edge_init(&job, 4u, H, 0u, g_map, sizeof g_map,
                                                       g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_edge_init(&job, W, 4u, 0u, g_map, sizeof g_map,
                                                       g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_edge_init(&job, W, H, 0u, g_map,
                                                         sizeof g_map - 1u, g_ring,
                                                         sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_edge_init(&job, W, H, 0u, g_map, sizeof g_map,
                                                         g_ring, sizeof g_ring - 1u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE,
                          ssda_edge_init(&job, 5u, 5u, 0u, (uint16_t *)(void *)((uint8_t *)g_map + 1),
                                         sizeof g_map - 2u, g_ring, sizeof g_ring));
    /* the ring inside the map, or the map inside the ring */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_init(&job, W, H, 0u, g_map, sizeof g_map,
                                                      (uint8_t *)g_map + 64, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_edge_init(&job, 5u, 5u, 0u,
                                                      (uint16_t *)(void *)(g_ring + 2), 50u,
                                                      g_ring, 25u));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &job, sizeof job);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_push(NULL, g_img[0]));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_push(&job, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_edge_push(&job, g_img[0])); /* never initialised */
    TEST_ASSERT_EQUAL_MEMORY(&poison, &job, sizeof job);

    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img, W, H, W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v16, img16, W, H, W * 2u, SSDA_PIX_U16));
    memset(g_map, 0x77, sizeof g_map);
    memcpy(g_ref, g_map, sizeof g_map);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_edge_detect(NULL, 0u, g_map, sizeof g_map, g_ring,
                                                         sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_edge_detect(&v16, 0u, g_map, sizeof g_map,
                                                           g_ring, sizeof g_ring));
    v.width = 0u; /* an invalid view */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_edge_detect(&v, 0u, g_map, sizeof g_map, g_ring,
                                                         sizeof g_ring));
    v.width = W;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_edge_detect(&v, 0u, g_map, 8u, g_ring,
                                                           sizeof g_ring));
    TEST_ASSERT_EQUAL_HEX16_ARRAY(g_ref, g_map, W * H);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_textures_match_reference);
    RUN_TEST(test_steps_of_every_contrast);
    RUN_TEST(test_push_equals_detect_and_border);
    RUN_TEST(test_smallest_image_and_strided_view);
    RUN_TEST(test_errors_change_nothing);
    return UNITY_END();
}
