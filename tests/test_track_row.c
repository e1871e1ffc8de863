/*
 * test_track_row.c - ssda_track_row: a grid solved in parts of grid rows,
 * in any order that keeps its promise (each part's left neighbour and the
 * row above through column col1 solved first), equals ssda_track window for
 * window (vectors, statuses, exact flags, sub-pixel and uniqueness fields)
 * and in the summed work counts, for every prediction and threshold mode,
 * 8 and 16-bit; bad arguments are refused before anything is written.
 */
#include <string.h>
#include "unity.h"
#include "ssda/track.h"
#include "test_image.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 96u
#define IH 80u
#define MAX_WIN 400u
static uint16_t g_a16[IH][IW], g_b16[IH][IW];
static uint8_t g_a8[IH][IW], g_b8[IH][IW];
static uint64_t g_work[(SSDA_TRACK_WORK_SIZE(32, 32, 16, 16) + 7u) / 8u];
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];

/* B = A moved by -2..2 px, varying over the image, plus noise; a flat patch and a periodic one so
   that flat windows and tied SADs (the tie rule reads the prediction)
   occur. */
static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u16(&g_a16[0][0], IW, IH, IW, 3000u, &r);
    for (y = 10; y < 40; y++) {
        for (x = 50; x < 90; x++) {
            g_a16[y][x] = (uint16_t)(((x / 3u + y / 4u) % 3u) * 200u);
        }
    }
    for (y = 50; y < 75; y++) {
        for (x = 5; x < 40; x++) {
            g_a16[y][x] = 900u;
        }
    }
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            /* motion varies over the image, so neighbours disagree and
               the median differs from any one of them */
            uint32_t mx = (x / 10u + y / 12u) % 5u, my = (x / 14u + 2u * y / 10u) % 5u;
            uint32_t sx = (x + IW + 2u - mx) % IW, sy = (y + IH + 2u - my) % IH;
            uint32_t v = g_a16[sy][sx] + test_rng_range(&r, 0, 6);
            g_b16[y][x] = (uint16_t)(v > 65535u ? 65535u : v);
            g_a8[y][x] = (uint8_t)(g_a16[y][x] >> 4);
            g_b8[y][x] = (uint8_t)(g_b16[y][x] >> 4);
        }
    }
}

static void views(bool wide, ssda_view_t *a, ssda_view_t *b)
{
    test_view_pair(wide, g_a16, g_b16, g_a8, g_b8, IW, IH, a, b);
}

static ssda_track_config_t config(uint32_t i)
{
    static const uint8_t modes[4] = {SSDA_THRESHOLD_AUTO, SSDA_THRESHOLD_NONE,
                                     SSDA_THRESHOLD_AUTO_RAMP, SSDA_THRESHOLD_FIXED};
    ssda_track_config_t c;
    memset(&c, 0, sizeof c);
    c.match.threshold = modes[i % 4u];
    c.match.fixed_threshold = 3000u;
    c.predict = (uint8_t)((i / 4u) % 3u);
    c.step_x = 8;
    c.step_y = 6;
    if (i >= 12u) { /* bounds, uniqueness, exclusion; another geometry */
        c.flags = SSDA_TRACK_EXCLUDE;
        if (c.match.threshold == SSDA_THRESHOLD_AUTO || c.match.threshold == SSDA_THRESHOLD_NONE) {
            c.flags |= SSDA_TRACK_UNIQUE;
        }
        c.texture_threshold = 40u;
        c.match.flags = SSDA_MATCH_BOUNDS;
        c.match.work = g_work;
        c.match.work_size = sizeof g_work;
        c.win_w = 12;
        c.win_h = 10;
        c.search_w = 26;
        c.search_h = 21;
        c.step_x = 7;
        c.step_y = 5;
    }
    return c;
}

/* Field by field (the struct has tail padding). */
static void same_vector(const ssda_track_vector_t *a, const ssda_track_vector_t *b)
{
    TEST_ASSERT_EQUAL_UINT64(a->sad, b->sad);
    TEST_ASSERT_EQUAL_INT32(a->dx, b->dx);
    TEST_ASSERT_EQUAL_INT32(a->dy, b->dy);
    TEST_ASSERT_EQUAL_INT32(a->sub_dx_q8, b->sub_dx_q8);
    TEST_ASSERT_EQUAL_INT32(a->sub_dy_q8, b->sub_dy_q8);
    TEST_ASSERT_EQUAL_UINT32(a->texture_q8, b->texture_q8);
    TEST_ASSERT_EQUAL_UINT16(a->x, b->x);
    TEST_ASSERT_EQUAL_UINT16(a->y, b->y);
    TEST_ASSERT_EQUAL_UINT16(a->unique_q8, b->unique_q8);
    TEST_ASSERT_EQUAL_UINT8(a->status, b->status);
    TEST_ASSERT_EQUAL_UINT8(a->exact, b->exact);
}

/* An entry still holding the poison bytes (compared as bytes: the poison
   is not a valid bool). */
static void untouched(const ssda_track_vector_t *poison, const ssda_track_vector_t *v)
{
    TEST_ASSERT_EQUAL_MEMORY(poison, v, sizeof *v);
}

static void same_stats(const ssda_track_stats_t *a, const ssda_track_stats_t *b)
{
    TEST_ASSERT_EQUAL_UINT64(a->pixel_ops, b->pixel_ops);
    TEST_ASSERT_EQUAL_UINT64(a->positions, b->positions);
    TEST_ASSERT_EQUAL_UINT64(a->completed, b->completed);
    TEST_ASSERT_EQUAL_UINT64(a->check_pixels, b->check_pixels);
    TEST_ASSERT_EQUAL_UINT32(a->windows, b->windows);
    TEST_ASSERT_EQUAL_UINT32(a->ok, b->ok);
    TEST_ASSERT_EQUAL_UINT32(a->excluded, b->excluded);
    TEST_ASSERT_EQUAL_UINT32(a->masked, b->masked);
    TEST_ASSERT_EQUAL_UINT32(a->edge, b->edge);
    TEST_ASSERT_EQUAL_UINT32(a->flat, b->flat);
    TEST_ASSERT_EQUAL_UINT32(a->ambiguous, b->ambiguous);
    TEST_ASSERT_EQUAL_UINT32(a->at_limit, b->at_limit);
}

/* Solve the grid in random parts in a random order that keeps the promise
   (a wavefront of rows advancing unevenly, as threads would). */
static void solve_in_parts(const ssda_view_t *a, const ssda_view_t *b,
                           const ssda_track_config_t *c, const ssda_track_grid_t *g,
                           test_rng_t *r, ssda_track_stats_t *st)
{
    uint32_t done[64]; /* columns solved per grid row */
    uint32_t left = g->count;
    memset(done, 0, sizeof done);
    memset(st, 0, sizeof *st);
    TEST_ASSERT_TRUE(g->rows <= 64u);
    memset(g_got, 0x5A, sizeof g_got);
    while (left > 0u) {
        uint32_t row = test_rng_range(r, 0, g->rows - 1u);
        uint32_t limit, n;
        if (done[row] == g->cols) {
            continue;
        }
        /* the row above must hold columns .. col1 (inclusive) */
        limit = row == 0u || done[row - 1u] == g->cols ? g->cols
                : done[row - 1u] > 0u                 ? done[row - 1u] - 1u
                                                      : 0u;
        if (limit <= done[row]) {
            continue;
        }
        n = test_rng_range(r, 1, limit - done[row]);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_row(a, b, c, row, done[row], done[row] + n,
                                                      g_got, MAX_WIN, st));
        done[row] += n;
        left -= n;
    }
}

static void test_parts_in_wavefront_order_equal_one_call(void)
{
    uint32_t i, wide, seed;
    test_rng_t r;
    test_rng_seed(&r, 77u);
    for (seed = 1; seed <= 2u; seed++) {
        make_images(seed);
        for (wide = 0; wide < 2u; wide++) {
            ssda_view_t a, b;
            views(wide != 0u, &a, &b);
            for (i = 0; i < 16u; i++) {
                ssda_track_config_t c = config(i);
                ssda_track_grid_t g;
                ssda_track_stats_t want, got;
                uint32_t k;
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(&c, IW, IH, &g));
                TEST_ASSERT_TRUE(g.count <= MAX_WIN);
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, &c, g_want, MAX_WIN, &want));
                solve_in_parts(&a, &b, &c, &g, &r, &got);
                for (k = 0; k < g.count; k++) {
                    same_vector(&g_want[k], &g_got[k]);
                }
                same_stats(&want, &got);
            }
        }
    }
}

/* One call per whole row, top to bottom, stats NULL: the vectors of
   ssda_track; entries outside the part are never written. */
static void test_whole_rows_and_untouched_entries(void)
{
    ssda_view_t a, b;
    ssda_track_grid_t g;
    ssda_track_stats_t want;
    ssda_track_vector_t poison;
    uint32_t row, k;
    make_images(5u);
    views(false, &a, &b);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(NULL, IW, IH, &g));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&a, &b, NULL, g_want, MAX_WIN, &want));
    memset(&poison, 0x5A, sizeof poison);
    memset(g_got, 0x5A, sizeof g_got);
    /* one part in the middle of row 0 writes only its entries */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_row(&a, &b, NULL, 0u, 1u, 2u, g_got, MAX_WIN, NULL));
    untouched(&poison, &g_got[0]);
    for (k = 2; k < MAX_WIN; k++) {
        untouched(&poison, &g_got[k]);
    }
    for (row = 0; row < g.rows; row++) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK,
                              ssda_track_row(&a, &b, NULL, row, 0u, g.cols, g_got, MAX_WIN, NULL));
    }
    for (k = 0; k < g.count; k++) {
        same_vector(&g_want[k], &g_got[k]);
    }
    for (; k < MAX_WIN; k++) {
        untouched(&poison, &g_got[k]);
    }
}

/* Bad arguments: refused, out and stats untouched. */
static void test_bad_arguments_change_nothing(void)
{
    ssda_view_t a, b, a16, b16;
    ssda_track_grid_t g;
    ssda_track_stats_t st, poison;
    ssda_track_config_t c;
    memset(&c, 0, sizeof c);
    make_images(9u);
    views(false, &a, &b);
    views(true, &a16, &b16);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(NULL, IW, IH, &g));
    memset(&poison, 0x4E, sizeof poison);
    memset(g_got, 0x5A, sizeof g_got);
    st = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_track_row(&a, &b, NULL, g.rows, 0u, 1u, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_track_row(&a, &b, NULL, 0u, 2u, 2u, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_track_row(&a, &b, NULL, 0u, 3u, 1u, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG,
                          ssda_track_row(&a, &b, NULL, 0u, 0u, g.cols + 1u, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                          ssda_track_row(&a, &b, NULL, 0u, 0u, 1u, g_got, g.count - 1u, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_track_row(NULL, &b, NULL, 0u, 0u, 1u, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_track_row(&a, NULL, NULL, 0u, 0u, 1u, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_track_row(&a, &b, NULL, 0u, 0u, 1u, NULL, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_track_row(&a, &b16, NULL, 0u, 0u, 1u, g_got, MAX_WIN, &st));
    c.predict = 9u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_track_row(&a, &b, &c, 0u, 0u, 1u, g_got, MAX_WIN, &st));
    c.predict = 0u;
    c.win_w = 40u;
    c.search_w = 30u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_track_row(&a, &b, &c, 0u, 0u, 1u, g_got, MAX_WIN, &st));
    c.win_w = 0u;
    c.search_w = 0u;
    c.match.flags = SSDA_MATCH_BOUNDS; /* no work buffer */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_track_row(&a, &b, &c, 0u, 0u, 1u, g_got, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
    {
        ssda_track_vector_t pv;
        uint32_t k;
        memset(&pv, 0x5A, sizeof pv);
        for (k = 0; k < MAX_WIN; k++) {
            untouched(&pv, &g_got[k]);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_parts_in_wavefront_order_equal_one_call);
    RUN_TEST(test_whole_rows_and_untouched_entries);
    RUN_TEST(test_bad_arguments_change_nothing);
    return UNITY_END();
}
