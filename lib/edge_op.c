/* edge_op.c - the seed's 5 x 5 two-region edge operator and ridge thinning,
   streamed row by row (edge.h). */
#include "ssda/edge.h"

#include <string.h>

#define EDGE_MAGIC 0x45444745u /* "EDGE" */

/* The 25 samples of a window, w[dy + 2][dx + 2]. */
typedef struct {
    uint32_t v[5][5];
} window_t;

/* V(d) and |Sa - Sb| of one direction. */
typedef struct {
    uint32_t score; /* Sa^2 + Sb^2 + 10 * line squares < 2 * 2550^2 + 10 * 5 * 65025 < 2^24 */
    uint32_t diff;  /* |Sa - Sb| <= 2550 */
} split_t;

static split_t split(uint32_t sa, uint32_t sb, uint32_t line_sq)
{
    split_t s;
    s.score = sa * sa + sb * sb + 10u * line_sq;
    s.diff = sa > sb ? sa - sb : sb - sa;
    return s;
}

/* Map entry (strength, direction) of the window's centre pixel. */
static uint16_t operate(const window_t *w)
{
    uint32_t row[5], col[5], anti[9], diag[9]; /* sums of 5 (row, col) or <= 5 samples */
    uint32_t sq_h = 0u, sq_v = 0u, sq_a = 0u, sq_d = 0u;
    uint32_t i, j, best = 0u;
    split_t s[4];
    (void)memset(anti, 0, sizeof anti);
    (void)memset(diag, 0, sizeof diag);
    (void)memset(col, 0, sizeof col);
    for (i = 0u; i < 5u; i++) {
        row[i] = 0u;
        for (j = 0u; j < 5u; j++) {
            const uint32_t p = w->v[i][j];
            row[i] += p;
            col[j] += p;
            anti[i + j] += p;     /* dx + dy + 4 */
            diag[j + 4u - i] += p; /* dx - dy + 4 */
        }
        sq_h += w->v[2][i] * w->v[2][i];
        sq_v += w->v[i][2] * w->v[i][2];
        sq_a += w->v[i][4u - i] * w->v[i][4u - i];
        sq_d += w->v[i][i] * w->v[i][i];
    }
    s[0] = split(row[0] + row[1], row[3] + row[4], sq_h);
    s[1] = split(anti[0] + anti[1] + anti[2] + anti[3], anti[5] + anti[6] + anti[7] + anti[8],
                 sq_a);
    s[2] = split(col[0] + col[1], col[3] + col[4], sq_v);
    s[3] = split(diag[0] + diag[1] + diag[2] + diag[3], diag[5] + diag[6] + diag[7] + diag[8],
                 sq_d);
    for (i = 1u; i < 4u; i++) {
        if (s[i].score > s[best].score) { /* ties keep the smaller d */
            best = i;
        }
    }
    /* floor(diff / 10) = (diff * 6554) >> 16 for diff <= 2550 (the error
       diff * 6e-6 < 0.016 never reaches the next multiple of 0.1) */
    return (uint16_t)(((s[best].diff * 6554u) >> 16) | (best << SSDA_EDGE_DIR_SHIFT));
}

/* Operator over map row y from the ring: rows y-2..y+2, row y - 2 in
   slot `oldest` and the next ones in the following slots (mod 5). */
static void operate_row(const ssda_edge_job_t *job, uint32_t y, uint32_t oldest)
{
    const uint32_t w = job->width;
    uint16_t *out = job->map + (size_t)y * w;
    const uint8_t *rows[5];
    window_t win;
    uint32_t x, i, j, slot = oldest;
    for (i = 0u; i < 5u; i++) {
        rows[i] = job->ring + (size_t)slot * w;
        slot = slot == 4u ? 0u : slot + 1u;
    }
    out[0] = 0u;
    out[1] = 0u;
    out[w - 2u] = 0u;
    out[w - 1u] = 0u;
    for (x = 2u; x + 2u < w; x++) {
        for (i = 0u; i < 5u; i++) {
            for (j = 0u; j < 5u; j++) {
                win.v[i][j] = rows[i][x + j - 2u];
            }
        }
        out[x] = operate(&win);
    }
}

/* Ridge thinning of map row y (rows y - 1 and y + 1 complete). */
static void thin_row(const ssda_edge_job_t *job, uint32_t y)
{
    /* the neighbour across the split line of direction d: (dx, dy) on one
       side, its negation on the other */
    static const int8_t across_dx[4] = {0, 1, 1, 1};
    static const int8_t across_dy[4] = {1, 1, 0, -1};
    const uint32_t w = job->width;
    uint16_t *m = job->map + (size_t)y * w;
    uint32_t x;
    for (x = 2u; x + 2u < w; x++) {
        const uint32_t s = SSDA_EDGE_STRENGTH(m[x]);
        const uint32_t d = SSDA_EDGE_DIR(m[x]);
        /* offsets of the two neighbours across the line; the row stride is w */
        const ptrdiff_t off = (ptrdiff_t)across_dy[d] * (ptrdiff_t)w + across_dx[d];
        const uint16_t *c = m + x;
        const uint16_t n1 = c[off];
        const uint16_t n2 = c[-off];
        const bool beaten = (SSDA_EDGE_STRENGTH(n1) > s && SSDA_EDGE_DIR(n1) == d) ||
                            (SSDA_EDGE_STRENGTH(n2) > s && SSDA_EDGE_DIR(n2) == d);
        if (s >= job->strength_min && !beaten) {
            m[x] = (uint16_t)(m[x] | SSDA_EDGE_ON);
        }
    }
}

int ssda_edge_init(ssda_edge_job_t *job, uint16_t width, uint16_t height,
                   uint8_t strength_min, uint16_t *map, size_t map_size,
                   uint8_t *ring, size_t ring_size)
{
    uint64_t map_bytes;
    uintptr_t m0, r0;
    if (job == NULL || map == NULL || ring == NULL) {
        return SSDA_ERR_NULL;
    }
    if (width < SSDA_EDGE_MIN_DIM || height < SSDA_EDGE_MIN_DIM) {
        return SSDA_ERR_SIZE;
    }
    map_bytes = (uint64_t)width * height * 2u;
    if (map_bytes > (uint64_t)SIZE_MAX || (uint64_t)map_size < map_bytes ||
        ring_size < SSDA_EDGE_RING_SIZE(width)) {
        return SSDA_ERR_BUFFER;
    }
    if ((((uintptr_t)map) & 1u) != 0u) { /* alignment: D10 */
        return SSDA_ERR_STRIDE;
    }
    m0 = (uintptr_t)map;
    r0 = (uintptr_t)ring;
    if (r0 - m0 < (uintptr_t)map_bytes || m0 - r0 < (uintptr_t)SSDA_EDGE_RING_SIZE(width)) {
        return SSDA_ERR_ARG;
    }
    job->map = map;
    job->ring = ring;
    job->width = width;
    job->height = height;
    job->rows_in = 0u;
    job->slot = 0u;
    job->strength_min = SSDA_EDGE_DEFAULT_STRENGTH;
    if (strength_min != 0u) {
        job->strength_min = strength_min;
    }
    job->magic = EDGE_MAGIC;
    return SSDA_OK;
}

int ssda_edge_push(ssda_edge_job_t *job, const uint8_t *row)
{
    uint32_t r, w, h, slot;
    if (job == NULL || row == NULL) {
        return SSDA_ERR_NULL;
    }
    if (job->magic != EDGE_MAGIC || job->rows_in >= job->height) {
        return SSDA_ERR_STATE;
    }
    r = job->rows_in;
    w = job->width;
    h = job->height;
    slot = job->slot;
    (void)memcpy(job->ring + (size_t)slot * w, row, w);
    job->slot = slot == 4u ? 0u : slot + 1u; /* also the slot of row r - 4 */
    job->rows_in = r + 1u;
    if (r < 2u) {
        (void)memset(job->map + (size_t)r * w, 0, (size_t)w * 2u); /* border rows */
    }
    if (r >= 4u) {
        operate_row(job, r - 2u, job->slot);
        if (r >= 5u) {
            thin_row(job, r - 3u);
        }
    }
    if (r + 1u == h) { /* the last row: the bottom border, then its neighbour */
        const size_t last2 = (size_t)h - 2u;
        (void)memset(job->map + last2 * w, 0, (size_t)w * 4u);
        thin_row(job, h - 3u);
    }
    return SSDA_OK;
}

int ssda_edge_detect(const ssda_view_t *img, uint8_t strength_min, uint16_t *map,
                     size_t map_size, uint8_t *ring, size_t ring_size)
{
    ssda_edge_job_t job;
    uint32_t y;
    int err;
    if (img == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(img);
    if (err != SSDA_OK) {
        return err;
    }
    if (img->format != (uint8_t)SSDA_PIX_U8) {
        return SSDA_ERR_FORMAT;
    }
    err = ssda_edge_init(&job, img->width, img->height, strength_min, map, map_size, ring,
                         ring_size);
    for (y = 0u; err == SSDA_OK && y < img->height; y++) {
        err = ssda_edge_push(&job, ssda_view_row(img, y));
    }
    return err;
}
