/* region.c - isolated-point removal, contours and label counts over a
   streamed label image (region.h). */
#include "ssda/region.h"

#include "state.h"

#include <string.h>


int ssda_region_init(ssda_region_t *job, const ssda_region_config_t *cfg, void *ring,
                     size_t ring_size)
{
    if (job == NULL || cfg == NULL || ring == NULL) {
        return SSDA_ERR_NULL;
    }
    if (cfg->width == 0u || cfg->height == 0u) {
        return SSDA_ERR_SIZE;
    }
    if (cfg->op > (uint8_t)SSDA_REGION_CONTOUR) {
        return SSDA_ERR_ARG;
    }
    if (ring_size < SSDA_REGION_RING_SIZE(cfg->width)) {
        return SSDA_ERR_BUFFER;
    }
    job->ring = (uint8_t *)ring;
    job->counts = cfg->counts;
    job->width = cfg->width;
    job->height = cfg->height;
    job->op = cfg->op;
    job->pushed = 0u;
    job->flushed = 0u;
    job->magic = SSDA__MAGIC_REGION;
    return SSDA_OK;
}

/* Ring row of image row y. */
static const uint8_t *ring_row(const ssda_region_t *job, uint32_t y)
{
    const uint32_t slot = y % 3u;
    return job->ring + ((size_t)slot * job->width);
}

/* The label most frequent among the n neighbours (ties: the smallest). */
static uint8_t majority(const uint8_t *nb, uint32_t n)
{
    uint8_t best = 0u;
    uint32_t best_count = 0u, i, j;
    for (i = 0u; i < n; i++) {
        uint32_t c = 0u;
        for (j = 0u; j < n; j++) {
            c += nb[j] == nb[i] ? 1u : 0u;
        }
        if (c > best_count || (c == best_count && nb[i] < best)) {
            best = nb[i];
            best_count = c;
        }
    }
    return best;
}

/* Output pixel x of the row whose rows above, at and below are up, mid,
   down (NULL outside the image). */
static uint8_t clean_px(const uint8_t *up, const uint8_t *mid, const uint8_t *down, uint32_t x,
                        uint32_t w)
{
    const uint8_t l = mid[x];
    const uint32_t x0 = x > 0u ? x - 1u : 0u;
    const uint32_t x1 = x + 1u < w ? x + 1u : x;
    uint8_t nb[8];
    uint32_t n = 0u, i;
    const uint8_t *rows[3];
    uint32_t r;
    rows[0] = up;
    rows[1] = mid;
    rows[2] = down;
    for (r = 0u; r < 3u; r++) {
        if (rows[r] != NULL) {
            for (i = x0; i <= x1; i++) {
                if (r != 1u || i != x) {
                    if (rows[r][i] == l) {
                        return l; /* not isolated */
                    }
                    nb[n] = rows[r][i];
                    n++;
                }
            }
        }
    }
    return n == 0u ? l : majority(nb, n);
}

static uint8_t contour_px(const uint8_t *up, const uint8_t *mid, const uint8_t *down,
                          uint32_t x, uint32_t w)
{
    const uint8_t l = mid[x];
    bool edge = (up != NULL && up[x] != l) || (down != NULL && down[x] != l) ||
                (x > 0u && mid[x - 1u] != l) || (x + 1u < w && mid[x + 1u] != l);
    return l != 0u && edge ? l : 0u;
}

/* Write output row y from the ring. */
static void emit(const ssda_region_t *job, uint32_t y, uint8_t *out)
{
    const uint32_t w = job->width;
    const uint8_t *up = y > 0u ? ring_row(job, y - 1u) : NULL;
    const uint8_t *mid = ring_row(job, y);
    const uint8_t *down = y + 1u < job->height ? ring_row(job, y + 1u) : NULL;
    uint32_t x;
    for (x = 0u; x < w; x++) {
        const uint8_t v = job->op == (uint8_t)SSDA_REGION_CLEAN ? clean_px(up, mid, down, x, w)
                                                                : contour_px(up, mid, down, x, w);
        out[x] = v;
        if (job->counts != NULL) {
            job->counts[v]++;
        }
    }
}

int ssda_region_push(ssda_region_t *job, const uint8_t *labels, uint8_t *out)
{
    uint8_t *slot;
    uint32_t index;
    if (job == NULL || labels == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(job->magic, SSDA__MAGIC_REGION) || job->pushed >= job->height) {
        return SSDA_ERR_STATE;
    }
    index = (uint32_t)job->pushed % 3u;
    slot = job->ring + ((size_t)index * job->width);
    (void)memcpy(slot, labels, job->width);
    job->pushed++;
    if (job->pushed == 1u) {
        return 0;
    }
    emit(job, (uint32_t)job->pushed - 2u, out);
    return 1;
}

int ssda_region_flush(ssda_region_t *job, uint8_t *out)
{
    if (job == NULL || out == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(job->magic, SSDA__MAGIC_REGION) || job->pushed != job->height ||
        job->flushed != 0u) {
        return SSDA_ERR_STATE;
    }
    emit(job, (uint32_t)job->height - 1u, out);
    job->flushed = 1u;
    return 1;
}
