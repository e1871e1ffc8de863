/*
 * test_stream_match.c - ssda_stream_match equals ssda_match in RAM, field for
 * field, in every threshold mode, scan, row order and bounds option, with the
 * area, the window or both streamed, over raster and tiled layouts, several
 * strides, offsets, read granularities and arena sizes; reads each byte once
 * when the arena allows; short arenas and bad arguments are refused before
 * any read; a failed read at every possible read comes back unchanged with
 * the result untouched.
 */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "ssda/stream.h"
#include "test_image.h"
#include "test_source.h"

void setUp(void) {}
void tearDown(void) {}

/* Area image (the search area is a rectangle of it) and window image. */
#define AIW 64u
#define AIH 52u
#define WIW 30u
#define WIH 24u
static const ssda_rect_t k_area = {5, 7, 40, 36};
static const ssda_rect_t k_win = {9, 4, 12, 10};

static uint16_t g_a16[AIH][AIW], g_w16[WIH][WIW];
static uint8_t g_a8[AIH][AIW], g_w8[WIH][WIW];
static uint8_t g_adev[24000], g_wdev[8000];
static uint32_t g_aarena[1536], g_warena[512]; /* 6 KB, 2 KB */
static uint32_t g_work[SSDA_MATCH_WORK_SIZE(40, 36, 12, 10) / 4u];
static test_source_t g_ta, g_tw;

typedef struct {
    uint8_t layout;
    uint16_t tile_w, tile_h;
    uint32_t offset, stride_pad, read_size;
} geometry_t;

static const geometry_t k_geoms[] = {
    {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1},
    {SSDA_LAYOUT_RASTER, 0, 0, 6, 10, 16},
    {SSDA_LAYOUT_TILED, 16, 16, 0, 0, 1},
    {SSDA_LAYOUT_TILED, 12, 5, 4, 4, 64},
};
#define N_GEOMS (sizeof k_geoms / sizeof k_geoms[0])

/* Textured area image; the window image holds the area's pixels at a known
   place (plus noise on 8-bit, so the minimum is not zero). */
static void make_images(uint32_t seed)
{
    test_rng_t r;
    uint32_t x, y;
    test_rng_seed(&r, seed);
    test_fill_texture_u16(&g_a16[0][0], AIW, AIH, AIW, 4095u, &r);
    test_fill_texture_u8(&g_a8[0][0], AIW, AIH, AIW, &r);
    for (y = 0; y < WIH; y++) {
        for (x = 0; x < WIW; x++) {
            uint32_t ax = (x + 17u) % AIW, ay = (y + 19u) % AIH;
            g_w16[y][x] = g_a16[ay][ax];
            g_w8[y][x] = (uint8_t)((g_a8[ay][ax] + test_rng_range(&r, 0, 6)) & 0xFFu);
        }
    }
}

static ssda_view_t view_of(uint8_t format, bool area)
{
    ssda_view_t v;
    if (area) {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, format == SSDA_PIX_U16
                                           ? ssda_view_init(&v, g_a16, AIW, AIH, AIW * 2u, SSDA_PIX_U16)
                                           : ssda_view_init(&v, g_a8, AIW, AIH, AIW, SSDA_PIX_U8));
    } else {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, format == SSDA_PIX_U16
                                           ? ssda_view_init(&v, g_w16, WIW, WIH, WIW * 2u, SSDA_PIX_U16)
                                           : ssda_view_init(&v, g_w8, WIW, WIH, WIW, SSDA_PIX_U8));
    }
    return v;
}

/* Store one image on its device and initialise a source over it. */
static void make_source(ssda_source_t *s, bool area, const geometry_t *g, uint8_t format,
                        size_t arena_size)
{
    ssda_view_t v = view_of(format, area);
    test_source_t *dev = area ? &g_ta : &g_tw;
    uint8_t *bytes = area ? g_adev : g_wdev;
    uint32_t size = area ? (uint32_t)sizeof g_adev : (uint32_t)sizeof g_wdev;
    void *arena = area ? (void *)g_aarena : (void *)g_warena;
    uint32_t row = g->layout == SSDA_LAYOUT_TILED ? g->tile_w * format : v.width * format;
    ssda_source_config_t c;
    test_source_init(dev, bytes, size, g->read_size);
    c = test_source_config(dev, &v, g->layout, g->tile_w, g->tile_h, g->offset,
                           row + g->stride_pad, 0u, g->read_size, arena, arena_size);
    test_source_store(dev, &c, &v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(s, &c));
}

/* Field-by-field equality of two results (padding bytes aside). */
static bool same_result(const ssda_match_result_t *a, const ssda_match_result_t *b)
{
    return a->sad == b->sad && a->pixel_ops == b->pixel_ops && a->positions == b->positions &&
           a->completed == b->completed && a->x == b->x && a->y == b->y && a->exact == b->exact;
}

/* The reference: ssda_match on the same rectangles in RAM. */
static int reference(uint8_t format, const ssda_match_config_t *cfg, ssda_match_result_t *res)
{
    ssda_view_t a = view_of(format, true), w = view_of(format, false), ar, wr;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&ar, &a, k_area.x, k_area.y, k_area.width, k_area.height));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wr, &w, k_win.x, k_win.y, k_win.width, k_win.height));
    return ssda_match(&ar, &wr, cfg, res);
}

/* Every option combination: 5 thresholds (FIXED twice: some positions
   complete / every position cut) x 3 scans x 2 orders x bounds. */
#define N_CONFIGS (6u * 3u * 2u * 2u)
static ssda_match_config_t config(uint32_t i, uint64_t min_sad)
{
    static const uint8_t modes[6] = {SSDA_THRESHOLD_AUTO, SSDA_THRESHOLD_NONE,
                                     SSDA_THRESHOLD_FIXED, SSDA_THRESHOLD_FIXED,
                                     SSDA_THRESHOLD_RAMP, SSDA_THRESHOLD_AUTO_RAMP};
    ssda_match_config_t c;
    uint32_t m = i % 6u;
    memset(&c, 0, sizeof c);
    c.threshold = modes[m];
    c.scan = (uint8_t)((i / 6u) % 3u);
    c.order = (uint8_t)((i / 18u) % 2u);
    if ((i / 36u) % 2u != 0u) {
        c.flags = SSDA_MATCH_BOUNDS;
        c.work = g_work;
        c.work_size = sizeof g_work;
    }
    c.fixed_threshold = m == 2u ? 2u * min_sad + 40u : min_sad / 2u;
    c.lambda_q8 = (uint32_t)((min_sad * 256u * 3u) / (2u * 12u * 10u)) + 1u;
    c.predict_x = 11;
    c.predict_y = 13;
    c.coarse_step = 5;
    return c;
}

static uint64_t true_min(uint8_t format)
{
    ssda_match_config_t c;
    ssda_match_result_t r;
    memset(&c, 0, sizeof c);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, reference(format, &c, &r));
    return r.sad;
}

/* Smallest area arena a search accepts (issue 22): a band of window-height
   rows as wide as the area for the raster scan, the whole area for the
   others; `spare` rows more (at most the area's height). */
static size_t area_minimum(const geometry_t *g, uint8_t format, uint8_t scan, uint32_t spare)
{
    uint32_t rows = (scan == SSDA_SCAN_RASTER ? 10u : 36u) + spare;
    return SSDA_SOURCE_SIZE(g->layout, 40u, rows < 36u ? rows : 36u, format, g->read_size,
                            g->tile_w);
}

/* Which operands are streamed: 1 area, 2 window, 3 both. The area's arena
   is its minimum for each configuration's scan plus `spare` rows. */
static void run_equality(uint8_t format, uint32_t which, const geometry_t *g,
                         uint32_t spare, size_t win_arena)
{
    ssda_source_t as, ws;
    ssda_view_t av = view_of(format, true), wv = view_of(format, false);
    uint64_t min_sad = true_min(format);
    uint32_t i;
    if ((which & 2u) != 0u) {
        make_source(&ws, false, g, format, win_arena);
    } else {
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ws, &wv));
    }
    for (i = 0; i < N_CONFIGS; i++) {
        ssda_match_config_t c = config(i, min_sad);
        ssda_match_result_t want, got;
        if ((which & 1u) != 0u) {
            make_source(&as, true, g, format, area_minimum(g, format, c.scan, spare));
        } else {
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&as, &av));
        }
        memset(&want, 0, sizeof want);
        memset(&got, 0, sizeof got);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, reference(format, &c, &want));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
        if (!same_result(&want, &got)) {
            char msg[128];
            snprintf(msg, sizeof msg, "config %u: (%u,%u) sad %llu vs (%u,%u) sad %llu", (unsigned)i,
                     want.x, want.y, (unsigned long long)want.sad, got.x, got.y,
                     (unsigned long long)got.sad);
            TEST_FAIL_MESSAGE(msg);
        }
    }
    TEST_ASSERT_EQUAL_UINT64(0, g_ta.contract_violations + g_tw.contract_violations);
}

static void test_equal_to_ram_in_every_mode_layout_and_arena(void)
{
    uint32_t gi, fi, which, ai;
    make_images(21u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        const geometry_t *g = &k_geoms[gi];
        for (fi = 1; fi <= 2; fi++) {
            const uint8_t f = (uint8_t)fi;
            /* smallest arenas (a raster band of window-height rows, the
               whole area for the other scans; the whole window), two
               spare rows, the whole area; windows with spare bytes */
            static const uint32_t spare[3] = {0u, 2u, 26u};
            size_t w_sizes[3];
            w_sizes[0] = SSDA_SOURCE_SIZE(g->layout, 12u, 10u, f, g->read_size, g->tile_w);
            w_sizes[1] = w_sizes[0] + 4u;
            w_sizes[2] = SSDA_SOURCE_SIZE(g->layout, 12u, 12u, f, g->read_size, g->tile_w);
            for (which = 1; which <= 3; which++) {
                if (gi != 0u && which != 3u) {
                    continue; /* one streamed operand: first layout only */
                }
                for (ai = 0; ai < 3; ai++) {
                    TEST_ASSERT_TRUE(area_minimum(g, f, SSDA_SCAN_PREDICT, 0u) <= sizeof g_aarena);
                    TEST_ASSERT_TRUE(w_sizes[ai] <= sizeof g_warena);
                    run_equality(f, which, g, spare[ai], w_sizes[ai]);
                }
            }
        }
    }
}

/* 16-px-wide windows of 16 to 19 and 22 rows, where the host's fast path
   sums rows in batches and cuts between them: a streamed search (the
   general row-by-row path) must give the same result in RAM in every
   field, pixel_ops and completed included (review, session 7: a batch
   that skipped a cut changed only those two and passed every test). */
static void test_sixteen_wide_windows_count_as_the_general_path(void)
{
    static const uint16_t heights[] = {16u, 17u, 18u, 19u, 22u};
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1};
    uint32_t hi, fi, i;
    make_images(23u);
    for (hi = 0; hi < sizeof heights / sizeof heights[0]; hi++) {
        const ssda_rect_t wr = {9, 2, 16, heights[hi]};
        for (fi = 1; fi <= 2; fi++) {
            const uint8_t f = (uint8_t)fi;
            ssda_view_t a = view_of(f, true), w = view_of(f, false), av, wv;
            ssda_match_config_t c0;
            ssda_match_result_t first;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&av, &a, k_area.x, k_area.y,
                                                         k_area.width, k_area.height));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&wv, &w, wr.x, wr.y, wr.width, wr.height));
            memset(&c0, 0, sizeof c0);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&av, &wv, &c0, &first));
#ifdef SSDA_TEST_SMALL
            for (i = hi; i < N_CONFIGS; i += 4u) { /* a quarter of them on the boards */
#else
            for (i = 0; i < N_CONFIGS; i++) {
#endif
                ssda_match_config_t c = config(i, first.sad);
                ssda_match_result_t want, got;
                ssda_source_t as, ws;
                make_source(&as, true, &g, f, sizeof g_aarena);
                make_source(&ws, false, &g, f, sizeof g_warena);
                memset(&want, 0, sizeof want);
                memset(&got, 0, sizeof got);
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&av, &wv, &c, &want));
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &wr, &c, &got));
                if (!same_result(&want, &got)) {
                    char msg[160];
                    snprintf(msg, sizeof msg,
                             "16 x %u, config %u: ops %llu completed %u vs ops %llu completed %u",
                             (unsigned)heights[hi], (unsigned)i, (unsigned long long)want.pixel_ops,
                             (unsigned)want.completed, (unsigned long long)got.pixel_ops,
                             (unsigned)got.completed);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        }
    }
}

/* Ties everywhere: a flat area and window (every position has SAD 0 or
   the same SAD); the tie rule must survive streaming. */
static void test_ties_survive_streaming(void)
{
    static const geometry_t g = {SSDA_LAYOUT_TILED, 7, 3, 0, 0, 1};
    uint32_t i;
    memset(g_a16, 0, sizeof g_a16);
    memset(g_w16, 0, sizeof g_w16);
    for (i = 0; i < AIW; i++) {
        g_a16[30][i] = 9; /* one bright row makes some positions worse */
    }
    {
        ssda_source_t as, ws;
        make_source(&ws, false, &g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 12u, 10u, 2u, 1u, 7u));
        for (i = 0; i < N_CONFIGS; i++) {
            ssda_match_config_t c = config(i, 0u);
            ssda_match_result_t want, got;
            make_source(&as, true, &g, SSDA_PIX_U16, area_minimum(&g, SSDA_PIX_U16, c.scan, 0u));
            memset(&want, 0, sizeof want);
            memset(&got, 0, sizeof got);
            c.lambda_q8 = 100u;
            TEST_ASSERT_EQUAL_INT(SSDA_OK, reference(SSDA_PIX_U16, &c, &want));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
            TEST_ASSERT_TRUE(same_result(&want, &got));
        }
    }
}

/* Each byte once: the whole area in the arena (any scan), or a band of
   window-height rows for the raster scan; the window in its arena. */
static void test_reads_each_byte_once_when_the_arena_allows(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1};
    const uint64_t area_bytes = 40u * 36u * 2u, win_bytes = 12u * 10u * 2u;
    ssda_source_t as, ws;
    ssda_match_config_t c;
    ssda_match_result_t res;
    uint32_t scan;
    make_images(22u);
    for (scan = 0; scan < 3; scan++) {
        memset(&c, 0, sizeof c);
        c.scan = (uint8_t)scan;
        make_source(&as, true, &g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 40u, 36u, 2u, 1u, 0u));
        make_source(&ws, false, &g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 12u, 10u, 2u, 1u, 0u));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &res));
        TEST_ASSERT_EQUAL_UINT64(area_bytes, as.stats.bytes_read);
        TEST_ASSERT_EQUAL_UINT64(win_bytes, ws.stats.bytes_read);
        TEST_ASSERT_EQUAL_UINT64(36, as.stats.reads); /* one read per row */
    }
    /* raster scan, a band of 10 rows (+ 2 spare): still once (brute force,
       so that every row is needed) */
    memset(&c, 0, sizeof c);
    c.threshold = SSDA_THRESHOLD_NONE;
    make_source(&as, true, &g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 40u, 12u, 2u, 1u, 0u));
    make_source(&ws, false, &g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 12u, 10u, 2u, 1u, 0u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &res));
    TEST_ASSERT_EQUAL_UINT64(area_bytes, as.stats.bytes_read);
    TEST_ASSERT_EQUAL_UINT(12, as.plate.ph);
    /* a repeated search over the same rectangles reads nothing new */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &res));
    TEST_ASSERT_EQUAL_UINT64(win_bytes, ws.stats.bytes_read);
}

/* A failure at read k, for every k a clean run makes, on the area's device
   and then on the window's: the code comes back unchanged, the result is
   untouched; the next search succeeds with the reference result. */
static void failure_sweep(uint32_t cfg_index, const geometry_t *g, size_t aa, size_t wa)
{
    ssda_source_t as, ws;
    ssda_match_result_t want, got, poison;
    ssda_match_config_t c;
    uint64_t n_reads[2], k;
    uint32_t dev;
    make_images(23u);
    c = config(cfg_index, true_min(SSDA_PIX_U16));
    memset(&want, 0, sizeof want);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, reference(SSDA_PIX_U16, &c, &want));
    make_source(&as, true, g, SSDA_PIX_U16, aa);
    make_source(&ws, false, g, SSDA_PIX_U16, wa);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
    n_reads[0] = g_ta.reads;
    n_reads[1] = g_tw.reads;
    TEST_ASSERT_TRUE(n_reads[0] > 0u && n_reads[1] > 0u);
    memset(&poison, 0x6B, sizeof poison);
    for (dev = 0; dev < 2; dev++) {
        for (k = 0; k < n_reads[dev]; k++) {
            test_source_t *t = dev == 0 ? &g_ta : &g_tw;
            make_source(&as, true, g, SSDA_PIX_U16, aa);
            make_source(&ws, false, g, SSDA_PIX_U16, wa);
            t->fail_code = -77 - (int)k;
            t->fail_at_read = (int64_t)k;
            got = poison;
            TEST_ASSERT_EQUAL_INT(-77 - (int)k, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
            TEST_ASSERT_EQUAL_UINT64(1, t->failures);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
            TEST_ASSERT_TRUE(same_result(&want, &got));
        }
    }
}

static void test_failure_at_every_read_leaves_result_untouched(void)
{
    /* AUTO raster with bounds, tiled with granularity, a sliding band of
       12 rows; AUTO predict, raster with granularity, the whole area;
       coarse with spread order, tiled, the whole area. */
    failure_sweep(36u, &k_geoms[3], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 40u, 12u, 2u, 64u, 12u),
                  SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 12u, 10u, 2u, 64u, 12u));
    failure_sweep(6u, &k_geoms[1], SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 40u, 36u, 2u, 16u, 0u),
                  SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 12u, 10u, 2u, 16u, 0u));
    failure_sweep(30u, &k_geoms[2], SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 40u, 36u, 2u, 1u, 16u),
                  SSDA_SOURCE_SIZE(SSDA_LAYOUT_TILED, 12u, 10u, 2u, 1u, 16u));
}

/* An arena below the job's minimum is refused before any read (issue 22:
   the minimum is the plate that reads each byte about once: a band of
   window-height rows as wide as the area for the raster scan, with or
   without bounds; the whole area for the other scans; the whole window). */
static void test_short_arena_is_refused_before_reading(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1};
    ssda_source_t as, ws, view_src;
    ssda_view_t wv;
    ssda_match_config_t c;
    ssda_match_result_t got, poison;
    uint32_t scan, bounds;
    make_images(24u);
    memset(&poison, 0x6B, sizeof poison);
    wv = view_of(SSDA_PIX_U16, false);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&view_src, &wv));
    for (scan = 0; scan < 3u; scan++) {
        for (bounds = 0; bounds < 2u; bounds++) {
            size_t need = area_minimum(&g, SSDA_PIX_U16, (uint8_t)scan, 0u);
            memset(&c, 0, sizeof c);
            c.scan = (uint8_t)scan;
            if (bounds != 0u) {
                c.flags = SSDA_MATCH_BOUNDS;
                c.work = g_work;
                c.work_size = sizeof g_work;
            }
            make_source(&as, true, &g, SSDA_PIX_U16, need - 1u);
            got = poison;
            TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER,
                                  ssda_stream_match(&as, &k_area, &view_src, &k_win, &c, &got));
            TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
            TEST_ASSERT_EQUAL_UINT64(0, g_ta.reads);
            make_source(&as, true, &g, SSDA_PIX_U16, need);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &view_src, &k_win, &c, &got));
        }
    }
    /* a streamed window needs its whole rectangle */
    memset(&c, 0, sizeof c);
    make_source(&as, true, &g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 40u, 36u, 2u, 1u, 0u));
    make_source(&ws, false, &g, SSDA_PIX_U16, SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, 12u, 10u, 2u, 1u, 0u) - 1u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
    TEST_ASSERT_EQUAL_UINT64(0, g_ta.reads + g_tw.reads);
}

/* The bound (issue 22) over layouts, read sizes, scans, bounds, orders,
   threshold modes and every arena from the minimum up to the whole area:
   the area's bytes read are at most AMP_BOUND times those of the same
   search with the whole area in the arena (each byte read once, at the
   layout's granularity), and the window's equal them. */
#define AMP_BOUND 2u
static void test_bytes_read_are_bounded_for_every_accepted_arena(void)
{
    static const uint32_t spares[] = {0u, 1u, 2u, 3u, 5u, 9u, 17u};
    uint32_t gi, i, si;
    double worst = 0.0;
    char msg[96];
    make_images(26u);
    for (gi = 0; gi < N_GEOMS; gi++) {
        const geometry_t *g = &k_geoms[gi];
        const size_t wa = SSDA_SOURCE_SIZE(g->layout, 12u, 10u, 2u, g->read_size, g->tile_w);
#ifdef SSDA_TEST_SMALL
        for (i = gi; i < N_CONFIGS; i += 5u) { /* a fifth of them on the boards */
#else
        for (i = 0; i < N_CONFIGS; i++) {
#endif
            ssda_match_config_t c = config(i, true_min(SSDA_PIX_U16));
            ssda_source_t as, ws;
            ssda_match_result_t res;
            uint64_t once, once_w;
            make_source(&as, true, g, SSDA_PIX_U16, area_minimum(g, SSDA_PIX_U16, c.scan, 26u));
            make_source(&ws, false, g, SSDA_PIX_U16, wa);
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &res));
            once = as.stats.bytes_read;
            once_w = ws.stats.bytes_read;
            for (si = 0; si < sizeof spares / sizeof spares[0]; si++) {
                double amp;
                make_source(&as, true, g, SSDA_PIX_U16, area_minimum(g, SSDA_PIX_U16, c.scan, spares[si]));
                make_source(&ws, false, g, SSDA_PIX_U16, wa);
                TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &res));
                amp = (double)as.stats.bytes_read / (double)once;
                worst = amp > worst ? amp : worst;
                if (as.stats.bytes_read > AMP_BOUND * once || ws.stats.bytes_read != once_w) {
                    snprintf(msg, sizeof msg, "geometry %u config %u spare %u: %llu vs %llu once",
                             (unsigned)gi, (unsigned)i, (unsigned)spares[si],
                             (unsigned long long)as.stats.bytes_read, (unsigned long long)once);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        }
    }
    snprintf(msg, sizeof msg, "worst area amplification %.3f (bound %u)", worst, AMP_BOUND);
    printf("%s\n", msg);
}

/* The case, scaled down: a W x 2 8-bit area, a 46 x 2 window,
   raster scan with bounds, an arena halfway between the old minimum (one
   area row) and a band of the window's height. It read 30 000 times the
   area (60 004 reads of a whole row for W = 65535): now it is refused
   before any read, and the arena that works (the band) reads each byte at
   most twice (bounds, then the scan from the top). */
#define WIDE_W 3000u
static uint8_t g_wide[2][WIDE_W], g_wide_dev[2u * WIDE_W];
static uint32_t g_wide_arena[(2u * WIDE_W) / 4u + 1u];
static uint32_t g_wide_work[SSDA_MATCH_WORK_SIZE(WIDE_W, 2, 46, 2) / 4u];
static void test_small_arena_no_longer_reads_without_bound(void)
{
    test_rng_t r;
    test_source_t dev;
    ssda_view_t v, w;
    ssda_source_t as, ws;
    ssda_source_config_t sc;
    ssda_match_config_t c;
    ssda_match_result_t want, got;
    const size_t half = (SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, WIDE_W, 1u, 1u, 1u, 0u) +
                         SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, WIDE_W, 2u, 1u, 1u, 0u)) / 2u;
    test_rng_seed(&r, 99u);
    test_fill_texture_u8(&g_wide[0][0], WIDE_W, 2u, WIDE_W, &r);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_init(&v, g_wide, WIDE_W, 2u, WIDE_W, SSDA_PIX_U8));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_view_roi(&w, &v, 1234u, 0u, 46u, 2u));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&ws, &w));
    memset(&c, 0, sizeof c);
    c.flags = SSDA_MATCH_BOUNDS;
    c.work = g_wide_work;
    c.work_size = sizeof g_wide_work;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&v, &w, &c, &want));
    test_source_init(&dev, g_wide_dev, sizeof g_wide_dev, 1u);
    sc = test_source_config(&dev, &v, SSDA_LAYOUT_RASTER, 0u, 0u, 0u, WIDE_W, 0u, 1u,
                            g_wide_arena, half);
    test_source_store(&dev, &sc, &v);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&as, &sc));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_BUFFER, ssda_stream_match(&as, NULL, &ws, NULL, &c, &got));
    TEST_ASSERT_EQUAL_UINT64(0, dev.reads);
    sc.arena_size = SSDA_SOURCE_SIZE(SSDA_LAYOUT_RASTER, WIDE_W, 2u, 1u, 1u, 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&as, &sc));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, NULL, &ws, NULL, &c, &got));
    TEST_ASSERT_TRUE(same_result(&want, &got));
    TEST_ASSERT_TRUE(as.stats.bytes_read <= 2u * 2u * WIDE_W);
}

static void test_bad_arguments_are_refused(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1};
    ssda_source_t as, ws, zero, v8src;
    ssda_view_t v8 = view_of(SSDA_PIX_U8, false);
    ssda_match_config_t c;
    ssda_match_result_t got, poison;
    ssda_rect_t r;
    make_images(25u);
    memset(&zero, 0, sizeof zero);
    memset(&poison, 0x6B, sizeof poison);
    memset(&c, 0, sizeof c);
    make_source(&as, true, &g, SSDA_PIX_U16, sizeof g_aarena);
    make_source(&ws, false, &g, SSDA_PIX_U16, sizeof g_warena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init_view(&v8src, &v8));
    got = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_stream_match(NULL, &k_area, &ws, &k_win, &c, &got));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_stream_match(&as, &k_area, NULL, &k_win, &c, &got));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_match(&zero, &k_area, &ws, &k_win, &c, &got));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_STATE, ssda_stream_match(&as, &k_area, &zero, &k_win, &c, &got));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_match(&as, &k_area, &as, &k_area, &c, &got));
    r = k_area; r.width = (uint16_t)(AIW - r.x + 1u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&as, &r, &ws, &k_win, &c, &got));
    r = k_win; r.height = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&as, &k_area, &ws, &r, &c, &got));
    r = k_area; r.height = 9; /* shorter than the window */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_SIZE, ssda_stream_match(&as, &r, &ws, &k_win, &c, &got));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_FORMAT, ssda_stream_match(&as, &k_area, &v8src, &k_win, &c, &got));
    c.threshold = 9;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
    c.threshold = 0;
    c.flags = SSDA_MATCH_BOUNDS;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_stream_match(&as, &k_area, &ws, &k_win, &c, &got));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
    TEST_ASSERT_EQUAL_UINT64(0, g_ta.reads + g_tw.reads);
    /* NULL rectangles mean whole images */
    c.flags = 0;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, NULL, &ws, NULL, &c, &got));
    {
        ssda_view_t a = view_of(SSDA_PIX_U16, true), w = view_of(SSDA_PIX_U16, false);
        ssda_match_result_t want;
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_match(&a, &w, &c, &want));
        TEST_ASSERT_TRUE(same_result(&want, &got));
    }
}

/* Two streamed sources whose arenas overlap would overwrite each other's
   plate and search the wrong pixels (an answer flagged exact): refused
   before any read, result untouched. Halves of one buffer that do not
   overlap are two plates and give the answer of separate arenas. */
static void test_overlapping_arenas_are_refused(void)
{
    static const geometry_t g = {SSDA_LAYOUT_RASTER, 0, 0, 0, 0, 1};
    const size_t half = sizeof g_aarena / 2u;
    ssda_source_t as, ws, other;
    ssda_source_config_t c;
    ssda_match_result_t want, got, poison;
    make_images(31u);
    make_source(&as, true, &g, SSDA_PIX_U16, half);
    make_source(&ws, false, &g, SSDA_PIX_U16, sizeof g_warena);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &ws, &k_win, NULL, &want));
    memset(&poison, 0x5A, sizeof poison);
    c = ws.cfg;
    c.arena = (uint8_t *)g_aarena + half - 4u; /* its first word is the area's last */
    c.arena_size = sizeof g_warena;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&other, &c));
    g_ta.reads = 0;
    g_tw.reads = 0;
    got = poison;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_match(&as, &k_area, &other, &k_win, NULL, &got));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_stream_match(&other, &k_win, &as, &k_win, NULL, &got));
    TEST_ASSERT_EQUAL_MEMORY(&poison, &got, sizeof got);
    TEST_ASSERT_EQUAL_UINT64(0, g_ta.reads + g_tw.reads);
    /* the next word on: two plates in one buffer */
    c.arena = (uint8_t *)g_aarena + half;
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_source_init(&other, &c));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_stream_match(&as, &k_area, &other, &k_win, NULL, &got));
    TEST_ASSERT_TRUE(same_result(&want, &got));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_equal_to_ram_in_every_mode_layout_and_arena);
    RUN_TEST(test_ties_survive_streaming);
    RUN_TEST(test_sixteen_wide_windows_count_as_the_general_path);
    RUN_TEST(test_reads_each_byte_once_when_the_arena_allows);
    RUN_TEST(test_failure_at_every_read_leaves_result_untouched);
    RUN_TEST(test_short_arena_is_refused_before_reading);
    RUN_TEST(test_small_arena_no_longer_reads_without_bound);
    RUN_TEST(test_bytes_read_are_bounded_for_every_accepted_arena);
    RUN_TEST(test_bad_arguments_are_refused);
    RUN_TEST(test_overlapping_arenas_are_refused);
    return UNITY_END();
}
