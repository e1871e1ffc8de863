/*
 * test_cov_tall_source.c - a plate of more than 65535 rows' worth of arena
 * (found by branch coverage, tools/coverage.sh): a 1 x 65535 packed 8-bit
 * image has a plate pitch of 1 byte, so a 64 KiB arena could hold more
 * rows than any image has. The plate is then the whole image, loaded by
 * ONE read (stream.h: one read per plate load when whole rows are stored
 * at the plate's pitch), and every later row is a hit.
 * Static data: about 192 KiB.
 */
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#define H 65535u
static uint8_t g_img[H];
static uint8_t g_dev[H];
static uint32_t g_arena[(H + 1u + 4u) / 4u]; /* 65536 bytes: room for 65536 rows */
static test_source_t g_t;

static void test_whole_tall_image_in_one_read(void)
{
    ssda_view_t v;
    ssda_source_config_t c;
    ssda_source_t s;
    uint32_t y;
    for (y = 0; y < H; y++) {
        g_img[y] = (uint8_t)(y * 7u + (y >> 8));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img, 1, (uint16_t)H, 1, SSDA_PIX_U8));
    test_source_init(&g_t, g_dev, sizeof g_dev, 1u);
    c = test_source_config(&g_t, &v, SSDA_LAYOUT_RASTER, 0, 0, 0u, 0u, 0u, 1u, g_arena,
                           sizeof g_arena);
    test_source_store(&g_t, &c, &v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&s, &c));
    for (y = 0; y < H; y++) {
        const uint8_t *px = NULL;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, 0u, y, 1u, &px));
        TEST_ASSERT_EQUAL_UINT8(g_img[y], px[0]);
    }
    TEST_ASSERT_EQUAL_UINT64(1u, g_t.reads);
    TEST_ASSERT_EQUAL_UINT64(H, g_t.bytes_read);
    TEST_ASSERT_EQUAL_UINT64(1u, s.stats.misses);
    TEST_ASSERT_EQUAL_UINT64(H - 1u, s.stats.hits);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.contract_violations);
    /* bottom to top again: all hits, no read */
    for (y = H; y-- > 0u;) {
        const uint8_t *px = NULL;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&s, 0u, y, 1u, &px));
        TEST_ASSERT_EQUAL_UINT8(g_img[y], px[0]);
    }
    TEST_ASSERT_EQUAL_UINT64(1u, g_t.reads);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_whole_tall_image_in_one_read);
    return UNITY_END();
}
