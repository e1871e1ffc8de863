/*
 * test_cov_push.c - push mode at the corners the main push tests leave out
 * (found by branch coverage, tools/coverage.sh): every refusal of the init
 * functions with the job untouched and nothing read, a NULL row, default
 * tracking options with no stats, and grids whose windows are all EDGE
 * with either image pushed. References: ssda_match / ssda_track in RAM,
 * brute force (test_best), documented error codes.
 */
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "test_image.h"
#include "test_push.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

#define IW 72u
#define IH 60u
static uint8_t g_first[IH][IW], g_second[IH][IW];
static uint8_t g_small[12][12];
static uint8_t g_dev[IW * IH + 64u];
static uint32_t g_arena[512];
static uint32_t g_ring[2048]; /* 8 KB */
static test_source_t g_t;
#define MAX_WIN 64u
static ssda_track_vector_t g_want[MAX_WIN], g_got[MAX_WIN];

static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u8(&g_first[0][0], IW, IH, IW, &r);
    for (y = 0; y < IH; y++) {
        for (x = 0; x < IW; x++) {
            g_second[y][x] = g_first[(y + 1u) % IH][(x + 2u) % IW];
        }
    }
    memset(g_small, 40, sizeof g_small);
}

static ssda_view_t view_of(uint8_t (*img)[IW])
{
    ssda_view_t v;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, img, IW, IH, IW, SSDA_PIX_U8));
    return v;
}

/* v streamed from g_dev (raster, read_size 4) with an arena of arena bytes. */
static void make_streamed(ssda_source_t *s, const ssda_view_t *v, size_t arena)
{
    ssda_source_config_t c;
    test_source_init(&g_t, g_dev, sizeof g_dev, 4u);
    c = test_source_config(&g_t, v, SSDA_LAYOUT_RASTER, 0, 0, 0u, 0u, 0u, 4u, g_arena, arena);
    test_source_store(&g_t, &c, v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(s, &c));
}

static void test_match_init_refusals_leave_the_job_untouched(void)
{
    ssda_view_t wv = view_of(g_second);
    ssda_source_t win, narrow;
    ssda_push_t p, before;
    ssda_match_result_t res;
    const ssda_rect_t wr = {10, 10, 12, 9};
    ssda_rect_t ar;
    make_images(1u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&win, &wv));
    memset(&p, 0x66, sizeof p);
    before = p;
    /* zero height; empty area rectangles; an area leaving the image */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, 0, 1, NULL, &win, &wr, NULL, &res, g_ring, sizeof g_ring));
    ar.x = 0;
    ar.y = 0;
    ar.width = 0;
    ar.height = 20;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 1, &ar, &win, &wr, NULL, &res, g_ring, sizeof g_ring));
    ar.width = 20;
    ar.height = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 1, &ar, &win, &wr, NULL, &res, g_ring, sizeof g_ring));
    ar.height = 20;
    ar.x = (uint16_t)(IW - 19u); /* one column beyond the right edge */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 1, &ar, &win, &wr, NULL, &res, g_ring, sizeof g_ring));
    /* the window rectangle leaves its source */
    ar.x = 5;
    {
        ssda_rect_t out = wr;
        out.y = (uint16_t)(IH - 8u);
        TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 1, &ar, &win, &out, NULL, &res, g_ring, sizeof g_ring));
    }
    /* window wider than the area, as tall */
    ar.width = 11;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 1, &ar, &win, &wr, NULL, &res, g_ring, sizeof g_ring));
    ar.width = 20;
    /* window as wide as allowed but taller than the area */
    ar.height = 8;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_match(&p, IW, IH, 1, &ar, &win, &wr, NULL, &res, g_ring, sizeof g_ring));
    /* a streamed window whose arena is one byte short of the whole window
       (its minimum since issue 22: it is read once) */
    ar.height = 20;
    make_streamed(&narrow, &wv, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 12u, 9u, 1u, 4u, 0u) - 1u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, test_push_init_match(&p, IW, IH, 1, &ar, &narrow, &wr, NULL, &res, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads);
    /* with that byte it runs, and finds the window where it was cut */
    make_streamed(&narrow, &wv, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 12u, 9u, 1u, 4u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, 1, &ar, &narrow, &wr, NULL, &res, g_ring, sizeof g_ring));
    {
        uint32_t y, bx, by;
        uint64_t bs;
        ssda_view_t av, w;
        int n = 0;
        for (y = 0; y < IH; y++) {
            n += ssda_push_row(&p, g_first[y]);
        }
        TEST_ASSERT_EQUAL_INT(1, n);
        av = view_of(g_first);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&av, &av, ar.x, ar.y, ar.width, ar.height));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&w, &wv, wr.x, wr.y, wr.width, wr.height));
        test_best(&av, &w, &bx, &by, &bs);
        TEST_ASSERT_EQUAL_UINT32(bx, res.x);
        TEST_ASSERT_EQUAL_UINT32(by, res.y);
        TEST_ASSERT_EQUAL_UINT64(bs, res.sad);
    }
}

static void test_track_init_refusals_leave_the_job_untouched(void)
{
    ssda_view_t sv = view_of(g_second);
    ssda_source_t other, narrow;
    ssda_push_t p, before;
    make_images(2u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&other, &sv));
    memset(&p, 0x5D, sizeof p);
    before = p;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_track(NULL, IW, IH, 1, 0, &other, NULL, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_track(&p, IW, IH, 1, 0, NULL, NULL, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, test_push_init_track(&p, IW, IH, 1, 0, &other, NULL, g_got, MAX_WIN, NULL, NULL, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, test_push_init_track(&p, IW, IH, 3, 0, &other, NULL, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, test_push_init_track(&p, IW, IH, 2, 0, &other, NULL, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_track(&p, 0, IH, 1, 0, &other, NULL, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, test_push_init_track(&p, IW, 0, 1, 0, &other, NULL, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    /* pushing FIRST, the streamed SECOND must hold a 16-px window row */
    make_streamed(&narrow, &sv, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 16u, 1u, 1u, 4u, 0u) - 1u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, test_push_init_track(&p, IW, IH, 1, SSDA_PUSH_FIRST, &narrow, NULL, g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads);
}

/* A NULL row is refused and the job goes on as if it had not been made. */
static void test_null_row_changes_nothing(void)
{
    ssda_view_t wv = view_of(g_second), fv = view_of(g_first);
    ssda_source_t win;
    ssda_push_t p;
    ssda_match_result_t res, want;
    const ssda_rect_t wr = {30, 20, 10, 10};
    uint32_t y;
    int n = 0;
    make_images(3u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&win, &wv));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_match(&p, IW, IH, 1, NULL, &win, &wr, NULL, &res, g_ring, sizeof g_ring));
    for (y = 0; y < IH; y++) {
        if (y == 7u || y == IH - 1u) {
            TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_push_row(&p, NULL));
        }
        n += ssda_push_row(&p, g_first[y]);
    }
    TEST_ASSERT_EQUAL_INT(1, n);
    {
        ssda_view_t w;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&w, &wv, wr.x, wr.y, wr.width, wr.height));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&fv, &w, NULL, &want));
    }
    TEST_ASSERT_EQUAL_UINT64(want.sad, res.sad);
    TEST_ASSERT_EQUAL_UINT32(want.x, res.x);
    TEST_ASSERT_EQUAL_UINT32(want.y, res.y);
    TEST_ASSERT_EQUAL_UINT64(want.pixel_ops, res.pixel_ops);
    /* the window moved by (-2, -1) from FIRST */
    TEST_ASSERT_EQUAL_UINT32(wr.x + 2u, res.x);
    TEST_ASSERT_EQUAL_UINT32(wr.y + 1u, res.y);
}

static bool same_vector(const ssda_track_vector_t *a, const ssda_track_vector_t *b)
{
    return a->sad == b->sad && a->dx == b->dx && a->dy == b->dy && a->x == b->x &&
           a->y == b->y && a->status == b->status && a->exact == b->exact;
}

/* Push the rows of `pushed` (w x h, stride IW or 12) and count grid rows. */
static int push_all(ssda_push_t *p, const uint8_t *pushed, uint32_t h, uint32_t stride)
{
    uint32_t y;
    int n = 0;
    for (y = 0; y < h; y++) {
        int r = ssda_push_row(p, pushed + (size_t)y * stride);
        TEST_ASSERT_TRUE(r >= 0);
        n += r;
    }
    return n;
}

/* Default options (cfg NULL), no stats: ssda_track's vectors, either role. */
static void test_track_defaults_without_stats(void)
{
    ssda_view_t fv = view_of(g_first), sv = view_of(g_second);
    ssda_source_t other;
    ssda_push_t p;
    ssda_track_grid_t g;
    uint32_t k, role;
    make_images(4u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(NULL, IW, IH, &g));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, NULL, g_want, MAX_WIN, NULL));
    for (role = 0; role < 2u; role++) {
        const bool first = role == SSDA_PUSH_FIRST;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&other, first ? &sv : &fv));
        memset(g_got, 0x21, sizeof g_got);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, 1, (uint8_t)role, &other, NULL,
                                                            g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
        TEST_ASSERT_EQUAL_INT((int)g.rows, push_all(&p, first ? &g_first[0][0] : &g_second[0][0], IH, IW));
        for (k = 0; k < g.count; k++) {
            TEST_ASSERT_TRUE(same_vector(&g_want[k], &g_got[k]));
        }
    }
    /* SECOND(x, y) = FIRST(x + 2, y + 1): motion (-2, -1) where inside */
    TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_OK, g_got[g.cols + 1u].status);
    TEST_ASSERT_EQUAL_INT32(-2, g_got[g.cols + 1u].dx);
    TEST_ASSERT_EQUAL_INT32(-1, g_got[g.cols + 1u].dy);
}

/* FIRST smaller than any search area: every window is EDGE, whichever
   image is pushed; grid rows are still reported, nothing is read. */
static void test_track_all_edge_either_role(void)
{
    ssda_view_t sv = view_of(g_second), small;
    ssda_source_t other;
    ssda_push_t p;
    ssda_track_stats_t st;
    ssda_track_grid_t g;
    uint32_t k;
    make_images(5u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&small, g_small, 12, 12, 12, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(NULL, IW, IH, &g));
    /* FIRST (small) pushed, SECOND streamed */
    make_streamed(&other, &sv, sizeof g_arena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, 12, 12, 1, SSDA_PUSH_FIRST, &other, NULL,
                                                        g_got, MAX_WIN, &st, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT((int)g.rows, push_all(&p, &g_small[0][0], 12, 12));
    TEST_ASSERT_EQUAL_UINT32(g.count, st.edge);
    TEST_ASSERT_EQUAL_UINT64(0u, g_t.reads);
    /* SECOND pushed, FIRST (small) in RAM */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&other, &small));
    memset(g_got, 0x21, sizeof g_got);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, 1, SSDA_PUSH_SECOND, &other, NULL,
                                                        g_got, MAX_WIN, NULL, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT((int)g.rows, push_all(&p, &g_second[0][0], IH, IW));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&small, &sv, NULL, g_want, MAX_WIN, &st));
    TEST_ASSERT_EQUAL_UINT32(g.count, st.edge);
    for (k = 0; k < g.count; k++) {
        TEST_ASSERT_EQUAL_UINT8(SSDA_TRACK_EDGE, g_got[k].status);
        TEST_ASSERT_TRUE(same_vector(&g_want[k], &g_got[k]));
    }
}

/* Pushing FIRST with SECOND streamed through its smallest plate (a band of
   windows as wide as the grid, since issue 22; read_size 4, so one read
   per row): a read failing at any point stops the job with its code, later
   pushes are SSDA_ERR_STATE, the windows solved before it are ssda_track's,
   and stats stay untouched. */
static void test_fetch_mode_failure_anywhere_stops_tracking(void)
{
    ssda_view_t fv = view_of(g_first), sv = view_of(g_second);
    ssda_source_t other;
    ssda_push_t p;
    ssda_track_stats_t st, poison;
    ssda_track_grid_t g;
    const size_t arena = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, IW, 16u, 1u, 4u, 0u);
    uint64_t reads, k, step;
    uint32_t y, i;
    make_images(6u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track_grid(NULL, IW, IH, &g));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_track(&fv, &sv, NULL, g_want, MAX_WIN, NULL));
    make_streamed(&other, &sv, arena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, 1, SSDA_PUSH_FIRST, &other, NULL,
                                                        g_got, MAX_WIN, &st, g_ring, sizeof g_ring));
    TEST_ASSERT_EQUAL_INT((int)g.rows, push_all(&p, &g_first[0][0], IH, IW));
    for (i = 0; i < g.count; i++) {
        TEST_ASSERT_TRUE(same_vector(&g_want[i], &g_got[i]));
    }
    reads = g_t.reads;
    TEST_ASSERT_TRUE(reads > 20u);
    step = reads / 40u + 1u;
    memset(&poison, 0x21, sizeof poison);
    for (k = 0; k < reads; k += step) {
        int failed = 0;
        make_streamed(&other, &sv, arena);
        g_t.fail_at_read = (int64_t)k;
        g_t.fail_code = -6000 - (int)k;
        st = poison;
        memset(g_got, 0x33, sizeof g_got);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, test_push_init_track(&p, IW, IH, 1, SSDA_PUSH_FIRST, &other, NULL,
                                                            g_got, MAX_WIN, &st, g_ring, sizeof g_ring));
        for (y = 0; y < IH; y++) {
            int n = ssda_push_row(&p, g_first[y]);
            if (failed) {
                TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, n);
            } else if (n < 0) {
                TEST_ASSERT_EQUAL_INT(-6000 - (int)k, n);
                failed = 1;
            }
        }
        TEST_ASSERT_EQUAL_INT(1, failed);
        TEST_ASSERT_EQUAL_MEMORY(&poison, &st, sizeof st);
        /* the grid rows completed before the failure hold ssda_track's vectors */
        for (i = 0; i < g.count && g_got[i].status <= SSDA_TRACK_EDGE; i++) {
            TEST_ASSERT_TRUE(same_vector(&g_want[i], &g_got[i]));
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_match_init_refusals_leave_the_job_untouched);
    RUN_TEST(test_track_init_refusals_leave_the_job_untouched);
    RUN_TEST(test_null_row_changes_nothing);
    RUN_TEST(test_track_defaults_without_stats);
    RUN_TEST(test_track_all_edge_either_role);
    RUN_TEST(test_fetch_mode_failure_anywhere_stops_tracking);
    return UNITY_END();
}
