/* edge_refine.c - ssda_edge_refine and ssda_edge_classify (edge.h): the
   seed's 3 x 3 stages (c)-(e) over a whole map. */
#include "edge_internal.h"
#include "fixtrig.h"

#include <string.h>

/* degrees (0..180) to turns */
static uint32_t turns(uint32_t deg)
{
    return deg * 11930465u; /* 2^32 / 360, rounded; 180 * it < 2^32 */
}

static uint32_t or_default(uint32_t v, uint32_t def)
{
    return v != 0u ? v : def;
}

/* Final counts of the ON pixels by class. */
static void count_classes(const uint16_t *map, uint32_t w, uint32_t h, ssda_edge_stats_t *st)
{
    uint32_t x, y;
    st->branch = 0u;
    st->conn = 0u;
    st->end = 0u;
    for (y = 0u; y < h; y++) {
        for (x = 0u; x < w; x++) {
            if ((map[(size_t)y * w + x] & SSDA_EDGE_ON) != 0u) {
                const uint32_t c = ssda__ring_class(ssda__edge_ring(map, w, h, x, y));
                st->branch += c == (uint32_t)SSDA_EDGE_BRANCH ? 1u : 0u;
                st->conn += c == (uint32_t)SSDA_EDGE_CONN ? 1u : 0u;
                st->end += c == (uint32_t)SSDA_EDGE_END ? 1u : 0u;
            }
        }
    }
}

int ssda_edge_refine(uint16_t *map, uint16_t width, uint16_t height,
                     const ssda_edge_refine_config_t *cfg, void *work, size_t work_size,
                     ssda_edge_stats_t *stats)
{
    static const ssda_edge_refine_config_t defaults; /* zero: the seed's values */
    const ssda_edge_refine_config_t *c = cfg != NULL ? cfg : &defaults;
    ssda__edge_end_t *ends = (ssda__edge_end_t *)work;
    ssda__edge_gap_cfg_t gap;
    ssda_edge_stats_t st;
    uint32_t cap, n, spur, fit;
    if (map == NULL || work == NULL) {
        return SSDA_ERR_NULL;
    }
    if (width < SSDA_EDGE_MIN_DIM || height < SSDA_EDGE_MIN_DIM) {
        return SSDA_ERR_SIZE;
    }
    if (work_size < SSDA_EDGE_WORK_SIZE(1)) {
        return SSDA_ERR_BUFFER;
    }
    if ((((uintptr_t)map) & 1u) != 0u || (((uintptr_t)work) & 3u) != 0u) { /* D10 */
        return SSDA_ERR_STRIDE;
    }
    if (c->gap_max > 64u || (c->fit_len != 0u && (c->fit_len < 2u || c->fit_len > 16u)) ||
        c->spur_min > 16u || c->i_angle_deg > 180u || c->v_angle_deg > 180u) {
        return SSDA_ERR_ARG;
    }
    {
        const uint64_t entries = (uint64_t)work_size / SSDA_EDGE_WORK_SIZE(1);
        cap = entries > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)entries;
    }
    spur = or_default(c->spur_min, SSDA_EDGE_DEFAULT_SPUR);
    fit = or_default(c->fit_len, SSDA_EDGE_DEFAULT_FIT);
    gap.gap = (int32_t)or_default(c->gap_max, SSDA_EDGE_DEFAULT_GAP);
    gap.fit = fit;
    gap.i_angle = turns(or_default(c->i_angle_deg, 60u));
    gap.i_area = (int32_t)or_default(c->i_area_max, 20u);
    gap.v_angle = turns(or_default(c->v_angle_deg, 30u));
    (void)memset(&st, 0, sizeof st);

    st.thinned = ssda__edge_thin(map, width, height);                           /* (c) */
    n = ssda__edge_ends(map, width, height, spur, fit, ends, cap);
    st.ends = n;
    st.ends_dropped = n > cap ? n - cap : 0u;
    if (c->extend_min != 255u) {                                                /* (d) */
        ssda__edge_extend(map, width, height, ends, n < cap ? n : cap,
                          or_default(c->extend_min, SSDA_EDGE_DEFAULT_EXTEND),
                          or_default(c->extend_max, 64u), &st.extended, &st.extend_joined);
    }
    if (c->no_close == 0u) {                                                    /* (e) */
        n = ssda__edge_ends(map, width, height, spur, fit, ends, cap);
        ssda__edge_close(map, width, height, ends, n < cap ? n : cap, &gap, &st.closed_t,
                         &st.closed_i, &st.closed_v);
    }
    st.thinned += ssda__edge_thin(map, width, height);
    count_classes(map, width, height, &st);
    if (stats != NULL) {
        *stats = st;
    }
    return SSDA_OK;
}

int ssda_edge_classify(const uint16_t *map, uint16_t width, uint16_t height, uint16_t x,
                       uint16_t y)
{
    if (map == NULL) {
        return SSDA_ERR_NULL;
    }
    if (x >= width || y >= height) {
        return SSDA_ERR_SIZE;
    }
    if ((map[(size_t)y * width + x] & SSDA_EDGE_ON) == 0u) {
        return SSDA_ERR_ARG;
    }
    return (int)ssda__ring_class(ssda__edge_ring(map, width, height, x, y));
}
