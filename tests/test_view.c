/* test_view.c - view construction, ROIs and their validation. */
#include <string.h>
#include "unity.h"
#include "ssda/view.h"

void setUp(void) {}
void tearDown(void) {}

static uint16_t g_buf16[64];
static uint8_t g_buf8[64];

static void test_init_accepts_valid_views(void)
{
    ssda_view_t v;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_buf8, 8, 8, 8, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_UINT16(8, v.width);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_buf16, 4, 4, 16, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_UINT32(2, ssda_view_bpp(&v));
}

static void test_init_rejects_bad_views_and_writes_nothing(void)
{
    ssda_view_t v, before;
    v.data = g_buf8; v.stride = 77; v.width = 7; v.height = 7; v.format = SSDA_PIX_U8;
    before = v;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_view_init(NULL, g_buf8, 8, 8, 8, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_view_init(&v, NULL, 8, 8, 8, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_view_init(&v, g_buf8, 0, 8, 8, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_view_init(&v, g_buf8, 8, 0, 8, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_view_init(&v, g_buf8, 8, 8, 7, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_view_init(&v, g_buf16, 4, 4, 7, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_view_init(&v, g_buf16, 4, 4, 9, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE,
                          ssda_view_init(&v, (const uint8_t *)g_buf16 + 1, 4, 4, 8, SSDA_PIX_U16));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_view_init(&v, g_buf8, 8, 8, 8, (ssda_pixfmt_t)3));
    TEST_ASSERT_EQUAL_MEMORY(&before, &v, sizeof v);
}

static void test_roi_points_into_source(void)
{
    ssda_view_t v, r;
    uint32_t i;
    for (i = 0; i < 64; i++) {
        g_buf8[i] = (uint8_t)i;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_buf8, 8, 8, 8, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&r, &v, 2, 3, 4, 5));
    TEST_ASSERT_EQUAL_UINT8(3 * 8 + 2, ssda_view_row(&r, 0)[0]);
    TEST_ASSERT_EQUAL_UINT8(7 * 8 + 5, ssda_view_row(&r, 4)[3]);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_view_roi(&r, &v, 5, 0, 4, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_view_roi(&r, &v, 0, 0, 0, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_view_roi(&r, &v, 0, 8, 1, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_view_roi(NULL, &v, 0, 0, 1, 1));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_view_roi(&r, NULL, 0, 0, 1, 1));
}

static void test_strerror_names_every_code(void)
{
    int e;
    for (e = SSDA_ERR_UNSUPPORTED; e <= SSDA_OK; e++) {
        TEST_ASSERT_NOT_NULL(ssda_strerror(e));
    }
    TEST_ASSERT_EQUAL_STRING("ok", ssda_strerror(SSDA_OK));
    TEST_ASSERT_EQUAL_STRING("error from a callback", ssda_strerror(-1000));
}

/* Rows must stay in the address space: a view whose last byte would pass
   its top is refused (row addresses would wrap to memory before data).
   The addresses are never dereferenced. */
static void test_rows_past_the_address_space_are_refused(void)
{
    ssda_view_t v, before;
    const void *top16 = (const void *)(UINTPTR_MAX - 15u); /* 16 bytes to the top */
    memset(&before, 0x5C, sizeof before);
    v = before;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, top16, 4, 4, 4, SSDA_PIX_U8));
    v = before;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_view_init(&v, top16, 4, 5, 4, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE, ssda_view_init(&v, top16, 17, 1, 17, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_MEMORY(&before, &v, sizeof v);
#if UINTPTR_MAX <= UINT32_MAX
    {
        /* 32-bit targets: a stride of 2^32 - 256 (a bottom-up image given
           a "negative" stride) would put row 1 at data - 256 */
        static uint8_t buf[16];
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STRIDE,
                              ssda_view_init(&v, buf, 1, 2, 0xFFFFFF00u, SSDA_PIX_U8));
        TEST_ASSERT_EQUAL_MEMORY(&before, &v, sizeof v);
    }
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_init_accepts_valid_views);
    RUN_TEST(test_init_rejects_bad_views_and_writes_nothing);
    RUN_TEST(test_roi_points_into_source);
    RUN_TEST(test_rows_past_the_address_space_are_refused);
    RUN_TEST(test_strerror_names_every_code);
    return UNITY_END();
}
