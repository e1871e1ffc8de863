/* relax_grid.c - vector grids of ssda/relax.h: checks and reads. */
#include <string.h>

#include "relax_internal.h"
#include "fixmath.h"

static int32_t read_i32(const void *p)
{
    int32_t v;
    (void)memcpy(&v, p, sizeof v); /* any alignment */
    return v;
}

bool ssda__relax_get(const ssda__relax_t *g, size_t k, int32_t *x, int32_t *y)
{
    const size_t off = k * g->stride;
    if (g->status != NULL && g->status[off] != 0u) {
        return false;
    }
    /* checked at open: |v| * scale <= 2^23 */
    *x = read_i32(g->dx + off) * (int32_t)g->scale;
    *y = read_i32(g->dy + off) * (int32_t)g->scale;
    return true;
}

int64_t ssda__relax_div(int64_t n, uint32_t d)
{
    const uint64_t m = n < 0 ? (uint64_t)(-n) : (uint64_t)n;
    const int64_t q = (int64_t)SSDA_DIV64_32(m, d);
    return n < 0 ? -q : q;
}

int ssda__relax_open(const ssda_relax_grid_t *grid, const ssda_relax_vector_t *out,
                     size_t out_count, ssda__relax_t *g)
{
    uint32_t k;
    int64_t lim;
    if (grid == NULL || out == NULL || grid->dx == NULL || grid->dy == NULL) {
        return SSDA_ERR_NULL;
    }
    if (grid->cols == 0u || grid->rows == 0u) {
        return SSDA_ERR_SIZE;
    }
    if (grid->stride == 0u || grid->frac_bits > 8u) {
        return SSDA_ERR_ARG;
    }
    g->dx = (const uint8_t *)(const void *)grid->dx;
    g->dy = (const uint8_t *)(const void *)grid->dy;
    g->status = grid->status;
    g->stride = grid->stride;
    g->cols = grid->cols;
    g->rows = grid->rows;
    g->n = (uint32_t)grid->cols * grid->rows;
    g->scale = (uint32_t)1u << (8u - grid->frac_bits);
    if ((uint64_t)out_count < g->n) {
        return SSDA_ERR_BUFFER;
    }
    lim = (int64_t)SSDA_RELAX_MAX_Q8 / (int64_t)g->scale;
    for (k = 0u; k < g->n; k++) {
        const size_t off = (size_t)k * g->stride;
        int32_t x, y;
        if (g->status != NULL && g->status[off] != 0u) {
            continue;
        }
        x = read_i32(g->dx + off);
        y = read_i32(g->dy + off);
        if (x > lim || -(int64_t)x > lim || y > lim || -(int64_t)y > lim) {
            return SSDA_ERR_ARG;
        }
    }
    return SSDA_OK;
}
