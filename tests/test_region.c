/*
 * test_region.c - isolated-point removal, contours and counts (region.h),
 * streamed row by row, against whole-image brute force written here from
 * the definitions: random label images with few labels and speckle, every
 * small shape (1 x 1, one row, one column, 2 x 2), counters at their top,
 * and every error.
 */
#include <string.h>
#include "unity.h"
#include "ssda/region.h"
#include "test_rng.h"

void setUp(void) {}
void tearDown(void) {}

#define MW 61u
#define MH 29u

static uint8_t g_in[MW * MH], g_out[MW * MH + 1u], g_want[MW * MH];
static uint8_t g_ring[SSDA_REGION_RING_SIZE(MW)];

static int inside(int x, int y, uint32_t w, uint32_t h)
{
    return x >= 0 && y >= 0 && x < (int)w && y < (int)h;
}

/* The definitions, on the whole image. */
static void brute(uint32_t w, uint32_t h, uint8_t op)
{
    int x, y, dx, dy;
    for (y = 0; y < (int)h; y++) {
        for (x = 0; x < (int)w; x++) {
            const uint8_t l = g_in[y * (int)w + x];
            uint32_t hist[256] = {0}, n = 0u, same = 0u, i;
            uint8_t v = l;
            if (op == SSDA_REGION_CLEAN) {
                for (dy = -1; dy <= 1; dy++) {
                    for (dx = -1; dx <= 1; dx++) {
                        if ((dx != 0 || dy != 0) && inside(x + dx, y + dy, w, h)) {
                            const uint8_t nl = g_in[(y + dy) * (int)w + x + dx];
                            hist[nl]++;
                            n++;
                            same += nl == l ? 1u : 0u;
                        }
                    }
                }
                if (n > 0u && same == 0u) {
                    uint32_t best = 0u;
                    for (i = 0; i < 256u; i++) {
                        if (hist[i] > best) {
                            best = hist[i];
                            v = (uint8_t)i;
                        }
                    }
                }
            } else {
                static const int d4[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
                int k, edge = 0;
                for (k = 0; k < 4; k++) {
                    if (inside(x + d4[k][0], y + d4[k][1], w, h) &&
                        g_in[(y + d4[k][1]) * (int)w + x + d4[k][0]] != l) {
                        edge = 1;
                    }
                }
                v = l != 0u && edge ? l : 0u;
            }
            g_want[y * (int)w + x] = v;
        }
    }
}

/* Stream the image through a job; counts into counts. */
static void stream(uint32_t w, uint32_t h, uint8_t op, uint32_t *counts)
{
    ssda_region_config_t cfg;
    ssda_region_t job;
    uint32_t y, written = 0u;
    memset(&cfg, 0, sizeof cfg);
    cfg.width = (uint16_t)w;
    cfg.height = (uint16_t)h;
    cfg.op = op;
    cfg.counts = counts;
    memset(g_out, 0xEE, sizeof g_out);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_region_init(&job, &cfg, g_ring, SSDA_REGION_RING_SIZE(w)));
    for (y = 0; y < h; y++) {
        const int r = ssda_region_push(&job, &g_in[y * w], &g_out[written * w]);
        TEST_ASSERT_EQUAL_INT(y == 0u ? 0 : 1, r);
        written += (uint32_t)r;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_region_push(&job, g_in, g_out));
    TEST_ASSERT_EQUAL_INT(1, ssda_region_flush(&job, &g_out[written * w]));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_region_flush(&job, g_out));
}

static void fill(test_rng_t *r, uint32_t w, uint32_t h, uint32_t labels)
{
    uint32_t x, y;
    /* blocks of a label, then speckle */
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            g_in[y * w + x] = (uint8_t)(((x / 7u) + (y / 5u) * 3u) % labels);
        }
    }
    for (x = 0; x < w * h / 6u; x++) {
        g_in[test_rng_next(r) % (w * h)] = (uint8_t)(test_rng_next(r) % labels);
    }
}

static void test_vs_brute(void)
{
    static const uint32_t shapes[][2] = {{MW, MH}, {1, 1}, {1, MH}, {MW, 1}, {2, 2}, {3, 2},
                                         {17, 3}};
    test_rng_t r;
    uint32_t s, op, rep;
    test_rng_seed(&r, 41u);
    for (s = 0; s < sizeof shapes / sizeof shapes[0]; s++) {
        for (rep = 0; rep < 4u; rep++) {
            const uint32_t w = shapes[s][0], h = shapes[s][1];
            fill(&r, w, h, 2u + rep * 3u);
            for (op = 0; op < 2u; op++) {
                uint32_t counts[256], want[256] = {0}, i;
                memset(counts, 0, sizeof counts);
                brute(w, h, (uint8_t)op);
                stream(w, h, (uint8_t)op, counts);
                TEST_ASSERT_EQUAL_MEMORY(g_want, g_out, w * h);
                TEST_ASSERT_EQUAL_HEX8(0xEEu, g_out[w * h]);
                for (i = 0; i < w * h; i++) {
                    want[g_want[i]]++;
                }
                TEST_ASSERT_EQUAL_MEMORY(want, counts, sizeof want);
            }
        }
    }
}

static void test_known_cases(void)
{
    /* a lone 5 in a field of 2: becomes 2; a 2 x 1 pair survives; a pixel
       between a 1 and a 3 on a border row takes the smaller on a tie */
    static const uint8_t in[3 * 5] = {2, 2, 2, 2, 2,
                                      2, 5, 2, 7, 7,
                                      2, 2, 2, 2, 2};
    static const uint8_t tie[1 * 3] = {1, 9, 3};
    uint32_t counts[256];
    memcpy(g_in, in, sizeof in);
    memset(counts, 0, sizeof counts);
    stream(5u, 3u, SSDA_REGION_CLEAN, counts);
    TEST_ASSERT_EQUAL_UINT8(2u, g_out[1 * 5 + 1]);
    TEST_ASSERT_EQUAL_UINT8(7u, g_out[1 * 5 + 3]);
    TEST_ASSERT_EQUAL_UINT32(13u, counts[2]);
    memcpy(g_in, tie, sizeof tie);
    stream(3u, 1u, SSDA_REGION_CLEAN, NULL);
    TEST_ASSERT_EQUAL_UINT8(1u, g_out[1]);
    /* counters at their top: 15 more reach 2^32 - 1 exactly */
    memcpy(g_in, in, sizeof in);
    memset(counts, 0, sizeof counts);
    counts[2] = UINT32_MAX - 13u;
    counts[7] = UINT32_MAX - 2u;
    stream(5u, 3u, SSDA_REGION_CLEAN, counts);
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, counts[2]);
    TEST_ASSERT_EQUAL_UINT32(UINT32_MAX, counts[7]);
    /* contours of the cleaned picture: the 7 pair's pixels only */
    stream(5u, 3u, SSDA_REGION_CONTOUR, NULL);
    TEST_ASSERT_EQUAL_UINT8(7u, g_out[1 * 5 + 3]);
    TEST_ASSERT_EQUAL_UINT8(2u, g_out[0 * 5 + 3]); /* a 2 above a 7 */
    TEST_ASSERT_EQUAL_UINT8(0u, g_out[0 * 5 + 0]);
}

static void test_errors(void)
{
    ssda_region_config_t cfg;
    ssda_region_t job, zero, poison;
    memset(&cfg, 0, sizeof cfg);
    memset(&zero, 0, sizeof zero);
    memset(&poison, 0x5A, sizeof poison);
    job = poison;
    cfg.width = 4u;
    cfg.height = 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_init(NULL, &cfg, g_ring, 12u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_init(&job, NULL, g_ring, 12u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_init(&job, &cfg, NULL, 12u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_region_init(&job, &cfg, g_ring, 11u));
    cfg.op = 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_region_init(&job, &cfg, g_ring, 12u));
    cfg.op = 0u;
    cfg.width = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_region_init(&job, &cfg, g_ring, 12u));
    cfg.width = 4u;
    cfg.height = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_region_init(&job, &cfg, g_ring, 12u));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &job, sizeof job);
    cfg.height = 2u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_region_push(&zero, g_in, g_out));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_region_flush(&zero, g_out));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_region_init(&job, &cfg, g_ring, 12u));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_push(NULL, g_in, g_out));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_push(&job, NULL, g_out));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_push(&job, g_in, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_flush(NULL, g_out));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_region_flush(&job, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_region_flush(&job, g_out)); /* rows to push */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_vs_brute);
    RUN_TEST(test_known_cases);
    RUN_TEST(test_errors);
    return UNITY_END();
}
