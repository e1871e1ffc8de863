/*
 * test_state.c - the one validity test of the stateful objects (sources,
 * push jobs, pitch streams; lib/state.h): zero-filled ones and ones holding
 * leftover bytes are refused with SSDA_ERR_STATE by every function that
 * takes them, before anything is read or written; initialised ones work.
 */
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "ssda/pitch.h"
#include "test_push.h"

void setUp(void) {}
void tearDown(void) {}

static uint8_t g_img[16 * 16];
static uint32_t g_ring[64];

static const unsigned char k_fill[2] = {0x00u, 0x5Au}; /* zeroed, leftover bytes */

static void test_sources(void)
{
    ssda_view_t v;
    ssda_source_t s, ok;
    ssda_match_result_t res, res0;
    ssda_track_vector_t out[4];
    const uint8_t *px = NULL;
    uint32_t i;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img, 16, 16, 16, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ok, &v));
    for (i = 0; i < 2u; i++) {
        memset(&s, k_fill[i], sizeof s);
        memset(&res, 0x77, sizeof res);
        res0 = res;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_source_row(&s, 0, 0, 4, &px));
        TEST_ASSERT_NULL(px);
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_match(&s, NULL, &ok, NULL, NULL, &res));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_match(&ok, NULL, &s, NULL, NULL, &res));
        TEST_ASSERT_EQUAL_MEMORY(&res0, &res, sizeof res);
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_track(&s, &ok, NULL, out, 4, NULL));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_track(&ok, &s, NULL, out, 4, NULL));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_row(&ok, 0, 0, 4, &px));
    TEST_ASSERT_EQUAL_PTR(g_img, px);
}

static void test_push_jobs(void)
{
    ssda_view_t v;
    ssda_source_t other, junk;
    ssda_push_t p, before;
    ssda_match_result_t res;
    uint32_t i;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_img, 4, 4, 16, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&other, &v));
    for (i = 0; i < 2u; i++) {
        memset(&p, k_fill[i], sizeof p);
        before = p;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_push_row(&p, g_img));
        TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
        /* a job whose other image is not initialised is refused at init */
        memset(&junk, k_fill[i], sizeof junk);
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, test_push_init_match(&p, 16, 16, SSDA_PIX_U8, NULL, &junk, NULL,
                                                                   NULL, &res, g_ring, sizeof g_ring));
        TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, 16, 4, SSDA_PIX_U8, NULL, &other, NULL, NULL,
                                                        &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(0, ssda_push_row(&p, g_img));
}

static void test_pitch_streams(void)
{
    ssda_pitch_t p, before;
    ssda_pitch_info_t info;
    ssda_pitch_estimate_t est;
    size_t used = 99u;
    uint32_t i;
    for (i = 0; i < 2u; i++) {
        memset(&p, k_fill[i], sizeof p);
        before = p;
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_pitch_push(&p, NULL, 0, &used, &est));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_pitch_reset(&p));
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_pitch_get_info(&p, &info));
        TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
        TEST_ASSERT_EQUAL_UINT(99u, used);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sources);
    RUN_TEST(test_push_jobs);
    RUN_TEST(test_pitch_streams);
    return UNITY_END();
}
