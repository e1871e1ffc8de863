/*
 * test_match_both.h - run one search through both entries, ssda_match and
 * ssda_match_search (the state in caller storage), and check that they
 * agree on the return code and on every result field.
 */
#ifndef SSDA_TEST_MATCH_BOTH_H
#define SSDA_TEST_MATCH_BOTH_H
#include "ssda/match.h"

/* ssda_match(area, window, cfg, result), and ssda_match_search on one
   state shared by every call (filled with a new byte pattern every few
   calls, else left as the previous search, of any geometry, left it):
   fails the test unless both return the same code and, on SSDA_OK, the
   same result; on an error, the second result must be left as it was.
   Returns ssda_match's code. */
int test_match_both(const ssda_view_t *area, const ssda_view_t *window,
                    const ssda_match_config_t *cfg, ssda_match_result_t *result);

/* Fails the test unless a and b give the same answer: position, SAD,
   sub-pixel offsets, uniqueness, exact flag and positions searched (the
   work counts, pixel_ops and completed, may differ). */
void test_match_same_answer(const ssda_match_result_t *a, const ssda_match_result_t *b,
                            const char *msg);

/* Fails the test unless a and b hold the same values, field by field. */
void test_match_same_result(const ssda_match_result_t *a, const ssda_match_result_t *b,
                            const char *msg);

/* Calls of test_match_both whose results were compared (both SSDA_OK). */
extern unsigned long test_match_both_compared;

#endif
