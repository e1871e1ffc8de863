/* test_match_both.c - see test_match_both.h. */
#include <string.h>
#include "unity.h"
#include "test_match_both.h"

unsigned long test_match_both_compared;

static ssda_match_state_t g_state; /* one state for every search, as a firmware's static */
static unsigned long g_calls;

void test_match_same_answer(const ssda_match_result_t *a, const ssda_match_result_t *b,
                            const char *msg)
{
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(a->sad, b->sad, msg);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(a->positions, b->positions, msg);
    TEST_ASSERT_EQUAL_UINT16_MESSAGE(a->x, b->x, msg);
    TEST_ASSERT_EQUAL_UINT16_MESSAGE(a->y, b->y, msg);
    TEST_ASSERT_EQUAL_INT16_MESSAGE(a->sub_x_q8, b->sub_x_q8, msg);
    TEST_ASSERT_EQUAL_INT16_MESSAGE(a->sub_y_q8, b->sub_y_q8, msg);
    TEST_ASSERT_EQUAL_UINT16_MESSAGE(a->unique_q8, b->unique_q8, msg);
    TEST_ASSERT_EQUAL_INT_MESSAGE(a->exact, b->exact, msg);
}

void test_match_same_result(const ssda_match_result_t *a, const ssda_match_result_t *b,
                            const char *msg)
{
    test_match_same_answer(a, b, msg);
    TEST_ASSERT_EQUAL_UINT64_MESSAGE(a->pixel_ops, b->pixel_ops, msg);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(a->completed, b->completed, msg);
}

int test_match_both(const ssda_view_t *area, const ssda_view_t *window,
                    const ssda_match_config_t *cfg, ssda_match_result_t *result)
{
    ssda_match_result_t other, poison;
    int e1, e2;
    if (g_calls % 7u == 0u) {
        /* leftover bytes of no search: the state needs no initialisation */
        memset(&g_state, (int)(0x5Au + g_calls), sizeof g_state);
    }
    g_calls++;
    e1 = ssda_match(area, window, cfg, result);
    memset(&poison, 0xC3, sizeof poison);
    other = poison;
    e2 = ssda_match_search(&g_state, area, window, cfg, &other);
    TEST_ASSERT_EQUAL_INT_MESSAGE(e1, e2, "ssda_match and ssda_match_search disagree");
    if (e1 == 0) {
        test_match_same_result(result, &other, "ssda_match_search's result");
        test_match_both_compared++;
    } else {
        TEST_ASSERT_EQUAL_MEMORY(&poison, &other, sizeof other);
    }
    return e1;
}
