/* loops_trace.c - outer boundaries: Moore tracing and equal-arc resampling
   (loops.h), and ssda_loops_contour. */
#include "loops_internal.h"
#include "edge_internal.h"
#include "fixmath.h"

#define STEP_Q16 65536u   /* a 4-neighbour step, Q16 px */
#define DIAG_Q16 92682u   /* sqrt(2) in Q16, rounded */

static bool member(const ssda__member_t *s, int32_t x, int32_t y)
{
    if (x < 0 || y < 0 || (uint32_t)x >= s->w || (uint32_t)y >= s->h) {
        return false;
    }
    if (s->map != NULL) {
        return (s->map[(size_t)(uint32_t)y * s->stride + (uint32_t)x] & s->bit) != 0u;
    }
    return s->mask != NULL && s->mask[(size_t)(uint32_t)y * s->stride + (uint32_t)x] != 0u;
}

void ssda__trace_begin(ssda__tracer_t *t, const ssda__member_t *set, uint32_t sx, uint32_t sy)
{
    t->set = set;
    t->x = (int32_t)sx;
    t->y = (int32_t)sy;
    t->sx = (int32_t)sx;
    t->sy = (int32_t)sy;
    t->d = 4u;
    t->first = 8u;
    t->steps = 0u;
}

uint32_t ssda__trace_step(ssda__tracer_t *t)
{
    /* sweep counter-clockwise from the neighbour after the last outside
       one: (d + 7) after a 4-neighbour move, (d + 6) after a diagonal */
    const uint32_t start = (t->d + (((t->d & 1u) == 0u) ? 7u : 6u)) & 7u;
    uint32_t i, k = 8u;
    for (i = 0u; i < 8u; i++) {
        const uint32_t c = (start + i) & 7u;
        if (member(t->set, t->x + ssda__ring_dx[c], t->y + ssda__ring_dy[c])) {
            k = c;
            break;
        }
    }
    if (k == 8u || (t->steps > 0u && t->x == t->sx && t->y == t->sy && k == t->first)) {
        return 8u;
    }
    if (t->first == 8u) {
        t->first = k;
    }
    t->x += ssda__ring_dx[k];
    t->y += ssda__ring_dy[k];
    t->d = k;
    t->steps++;
    return k;
}

uint64_t ssda__trace_length(const ssda__member_t *set, uint32_t sx, uint32_t sy)
{
    ssda__tracer_t t;
    uint64_t len = 0u; /* < 2^16 * 2^16 * 8 steps of < 2^17 */
    uint32_t k;
    ssda__trace_begin(&t, set, sx, sy);
    for (k = ssda__trace_step(&t); k < 8u; k = ssda__trace_step(&t)) {
        len += ((k & 1u) != 0u) ? DIAG_Q16 : STEP_Q16;
    }
    return len;
}

/* floor(v * 256 / len) for v < len <= DIAG_Q16: the Q8 part of a step */
static int32_t along_q8(uint32_t v, uint32_t len)
{
    const uint32_t v8 = v << 8; /* < 2^25 */
    uint32_t q = v >> 8;
    if (len != STEP_Q16) {
        q = SSDA_DIV32(v8, len);
    }
    return (int32_t)q;
}

void ssda__trace_sample(const ssda__member_t *set, uint32_t sx, uint32_t sy, uint64_t len_q16,
                        uint32_t log2n, ssda_point_q8_t *out)
{
    const uint32_t n = 1u << log2n;
    ssda__tracer_t t;
    uint64_t at = 0u; /* arc length at the start of the current step */
    uint32_t i = 0u, k;
    ssda__trace_begin(&t, set, sx, sy);
    for (k = ssda__trace_step(&t); k < 8u && i < n; k = ssda__trace_step(&t)) {
        const uint32_t len = ((k & 1u) != 0u) ? DIAG_Q16 : STEP_Q16;
        const int32_t x0 = t.x - ssda__ring_dx[k], y0 = t.y - ssda__ring_dy[k];
        /* samples i with i L / n inside [at, at + len) */
        while (i < n && ((uint64_t)i * len_q16 >> log2n) < at + len) {
            const uint32_t f = (uint32_t)(((uint64_t)i * len_q16 >> log2n) - at);
            const int32_t a = along_q8(f, len);
            out[i].x_q8 = x0 * 256 + ssda__ring_dx[k] * a;
            out[i].y_q8 = y0 * 256 + ssda__ring_dy[k] * a;
            i++;
        }
        at += len;
    }
    for (; i < n; i++) { /* a single pixel (no step) */
        out[i].x_q8 = (int32_t)sx * 256;
        out[i].y_q8 = (int32_t)sy * 256;
    }
}

uint32_t ssda__samples_log2(uint32_t v)
{
    uint32_t l = 0u, r = v;
    if (v < 8u || v > SSDA_LOOPS_MAX_SAMPLES || (v & (v - 1u)) != 0u) {
        return 0u;
    }
    while (r > 1u) {
        r >>= 1;
        l++;
    }
    return l;
}

int ssda_loops_contour(const ssda_view_t *mask, uint16_t x, uint16_t y, uint32_t samples,
                       ssda_point_q8_t *points, uint32_t *perimeter_q8)
{
    ssda__member_t set;
    uint32_t log2n, k;
    uint64_t len;
    int err;
    if (mask == NULL || points == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda_view_check(mask);
    if (err != SSDA_OK) {
        return err;
    }
    if (mask->format != (uint8_t)SSDA_PIX_U8) {
        return SSDA_ERR_FORMAT;
    }
    if (x >= mask->width || y >= mask->height) {
        return SSDA_ERR_SIZE;
    }
    set.mask = (const uint8_t *)mask->data;
    set.map = NULL;
    set.stride = mask->stride;
    set.w = mask->width;
    set.h = mask->height;
    set.bit = 0u;
    log2n = ssda__samples_log2(samples);
    if (log2n == 0u || !member(&set, x, y)) {
        return SSDA_ERR_ARG;
    }
    for (k = 1u; k <= 4u; k++) { /* NE, N, NW, W: before (x, y) in raster order */
        if (member(&set, (int32_t)x + ssda__ring_dx[k], (int32_t)y + ssda__ring_dy[k])) {
            return SSDA_ERR_ARG;
        }
    }
    len = ssda__trace_length(&set, x, y);
    ssda__trace_sample(&set, x, y, len, log2n, points);
    if (perimeter_q8 != NULL) {
        *perimeter_q8 = (len >> 8) > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)(len >> 8);
    }
    return SSDA_OK;
}
