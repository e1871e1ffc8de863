/*
 * relax.c - relaxation labelling of a vector grid (seed 003, eqs. 1-3; the
 * definitions are in ssda/relax.h).
 *
 * The neighbours' support is not formed as 48 x 48 products per neighbour.
 * It is linear in the likelihoods, so the n neighbours' likelihoods are
 * summed first, sum_k P_k(c'), and
 *     n q(c) = sum_c' r(c, c') sum_k P_k(c');
 * and eq. 3 never clips with 8 sectors and 6 lengths (the largest distance,
 * 4 + 5 steps, gives r = -0.8), so r is linear in the distances too:
 *     n q(c) = T - 0.2 (sum_c' dtheta(c, c') Pn(c') + sum_c' dl(c, c') Pn(c'))
 * with Pn = sum_k P_k and T = sum_c' Pn(c'): an 8 x 8 product over the
 * sectors' sums (lengths >= 1) and a 6 x 6 one over the lengths' sums. The
 * same value, a fiftieth of the work.
 */
#include <string.h>

#include "relax_internal.h"
#include "fixmath.h"
#include "wide.h"

#define NS SSDA_RELAX_SECTORS
#define NL SSDA_RELAX_LENGTHS
#define NC SSDA_RELAX_CLASSES
#define ONE_Q15 32768u
#define STEP_Q15 6554 /* 0.2 in Q15 */
#define P_OWN 17352u  /* 0.53 in Q15, so that 17352 + 47 * 328 = 32768 */
#define P_OTHER 328u  /* 0.01 in Q15 */

/* The work buffer (ssda/relax.h, SSDA_RELAX_WORK_SIZE). */
typedef struct {
    uint16_t *p;        /* [node * 48 + class]: likelihoods, Q15 */
    uint16_t *prev;     /* [col * 48 + class]: row j - 1 before this iteration */
    uint16_t *cur;      /* row j before this iteration */
    uint8_t *cls;       /* [node]: class of the input vector (NC: invalid) */
} relax_mem_t;

/* 1 + q(c) in Q15 (0.2 .. 2.0) for every class, from Pn, the sum of the n
   neighbours' likelihoods (see the file comment). */
static void one_plus_q(const uint32_t *pn, uint32_t n, uint32_t *opq)
{
    /* circular distance between sectors a and b (0..4) at [b - a + 7] */
    static const uint8_t sector_dist[2u * NS - 1u] = {1u, 2u, 3u, 4u, 3u, 2u, 1u, 0u,
                                                      1u, 2u, 3u, 4u, 3u, 2u, 1u};
    /* ceil(2^32 / n) for n = 1..8 neighbours */
    static const uint64_t recip_table[8] = {4294967296u, 2147483648u, 1431655766u,
                                            1073741824u, 858993460u,  715827883u,
                                            613566757u,  536870912u};
    uint32_t sect[NS];   /* per sector, lengths >= 1: <= 8 2^15 */
    uint32_t len[NL];    /* per length class */
    uint32_t dl[NL];     /* sum_c' |l - l'| Pn(c'): <= 5 8 2^15 */
    uint32_t total = 0u; /* <= 8 2^15 (likelihoods sum to at most 2^15) */
    const uint64_t recip = recip_table[n - 1u];
    uint32_t a, l, b;
    for (a = 0u; a < NS; a++) {
        sect[a] = 0u;
    }
    for (l = 0u; l < NL; l++) {
        len[l] = 0u;
        for (a = 0u; a < NS; a++) {
            const uint32_t v = pn[l * NS + a];
            len[l] += v;
            sect[a] += l != 0u ? v : 0u;
        }
        total += len[l];
    }
    for (l = 0u; l < NL; l++) {
        dl[l] = 0u;
        for (b = 0u; b < NL; b++) {
            dl[l] += (l > b ? l - b : b - l) * len[b];
        }
    }
    for (a = 0u; a < NS; a++) {
        uint32_t ang = 0u; /* sum dtheta Pn over lengths >= 1: <= 4 8 2^15 */
        for (b = 0u; b < NS; b++) {
            ang += sector_dist[b + NS - 1u - a] * sect[b];
        }
        for (l = 0u; l < NL; l++) {
            /* n (1 + q) in Q30: n 2^30 + T 2^15 - 6554 d (dtheta is 0 for the
               shortest class), in [0.2 n 2^30, 2 n 2^30] < 2^34; floor to
               Q15, then floor(. / n) through recip (exact below 2^20) */
            const uint64_t d = (uint64_t)(l != 0u ? ang : 0u) + dl[l]; /* <= 9 8 2^15 */
            const uint64_t u = ((uint64_t)n << 30) + ((uint64_t)total << 15) - STEP_Q15 * d;
            opq[l * NS + a] = (uint32_t)(((u >> 15) * recip) >> 32);
        }
    }
}

/* Eqs. 1-2 at node (i, j): old holds the likelihoods before this
   iteration of rows j - 1 (prev) and j (cur); row j + 1 is not updated yet. */
static void update_node(const ssda__relax_t *g, relax_mem_t *m, uint32_t i, uint32_t j)
{
    uint32_t pn[NC]; /* sum of up to 8 likelihoods: <= 8 2^15 */
    uint32_t w[NC];  /* P (1 + q) <= 2^15 * 2^16 */
    uint16_t *p = m->p + ((size_t)j * g->cols + i) * NC;
    uint32_t n = 0u, c, t = 0u, shift, inv;
    int32_t di, dj;
    (void)memset(pn, 0, sizeof pn);
    for (dj = -1; dj <= 1; dj++) {
        for (di = -1; di <= 1; di++) {
            const int32_t x = (int32_t)i + di, y = (int32_t)j + dj;
            const uint16_t *q;
            if ((di == 0 && dj == 0) || x < 0 || y < 0 || x >= (int32_t)g->cols ||
                y >= (int32_t)g->rows || m->cls[(size_t)y * g->cols + (uint32_t)x] >= NC) {
                continue;
            }
            if (dj < 0) {
                q = m->prev + (size_t)(uint32_t)x * NC;
            } else if (dj == 0) {
                q = m->cur + (size_t)(uint32_t)x * NC;
            } else {
                q = m->p + ((size_t)(uint32_t)y * g->cols + (uint32_t)x) * NC;
            }
            for (c = 0u; c < NC; c++) {
                pn[c] += q[c];
            }
            n++;
        }
    }
    if (n == 0u) {
        return; /* no neighbour: q = 0, P unchanged */
    }
    one_plus_q(pn, n, w);
    for (c = 0u; c < NC; c++) {
        w[c] *= p[c];
        t += w[c]; /* sum P (1 + q) <= 2^15 * 2 * 2^15 = 2^31 */
    }
    /* t > 0: 1 + q >= 0.2 (r >= -0.8) and the likelihoods never all vanish
       (the largest keeps at least 2^15 / 48 after each normalisation) */
    /* P(c) <- w(c) 2^15 / t through one division: t and the w scaled into
       [2^30, 2^31], inv = floor(2^61 / t) in [2^30, 2^31] */
    shift = 31u - ssda__bitlen64(t);
    t <<= shift;
    inv = SSDA_DIV64_32((uint64_t)1u << 61, t);
    for (c = 0u; c < NC; c++) {
        p[c] = (uint16_t)(((uint64_t)(w[c] << shift) * inv) >> 46); /* <= 2^15 */
    }
}

/* One synchronous iteration over the grid, rows updated in place; the old
   likelihoods of the row above and of the current row are kept aside. */
static void iterate(const ssda__relax_t *g, relax_mem_t *m)
{
    const size_t row = (size_t)g->cols * NC;
    uint32_t i, j;
    for (j = 0u; j < g->rows; j++) {
        uint16_t *t = m->prev;
        m->prev = m->cur;
        m->cur = t;
        (void)memcpy(m->cur, m->p + j * row, row * sizeof *m->cur);
        for (i = 0u; i < g->cols; i++) {
            if (m->cls[(size_t)j * g->cols + i] < NC) {
                update_node(g, m, i, j);
            }
        }
    }
}

/* The class of a vector (x, y) in Q8 px (|x|, |y| <= 2^23): sector + 8 *
   length class. Sectors are centred on multiples of 45 degrees; their edges
   at 22.5 and 67.5 degrees from an axis are tested as |y| 2^16 against
   |x| tan(angle) 2^16 (27 146 and 158 218: deterministic, and off the true
   edges by less than 10^-5 rad). */
static uint32_t classify(int32_t x, int32_t y, uint32_t step_q8)
{
    const uint64_t ax = (uint64_t)(x < 0 ? -(int64_t)x : (int64_t)x); /* < 2^24 */
    const uint64_t ay = (uint64_t)(y < 0 ? -(int64_t)y : (int64_t)y);
    const uint64_t r2 = ax * ax + ay * ay; /* < 2^49 */
    uint32_t l = 0u, k, sector;
    for (k = 1u; k < NL; k++) { /* k s <= |v|: class k at least */
        const uint64_t edge = (uint64_t)k * step_q8; /* < 2^3 2^26 */
        if (r2 >= edge * edge) {
            l = k;
        }
    }
    /* angle from the x axis within the quadrant: 0, 45 or 90 degrees */
    if ((ay << 16) < ax * 27146u) {
        k = 0u;
    } else if ((ay << 16) < ax * 158218u) {
        k = 1u;
    } else {
        k = 2u;
    }
    if (x >= 0) {
        sector = y >= 0 ? k : (NS - k) % NS;
    } else {
        sector = y >= 0 ? NS / 2u - k : NS / 2u + k;
    }
    return sector + NS * l;
}

/* Length class step s, Q8 px: the caller's, or 2/7 of the mean length of
   the valid vectors (the typical vector in the middle of length class 3),
   at least 1/4 px. */
static uint32_t length_step(const ssda__relax_t *g, uint16_t len_step_q8)
{
    uint64_t sum = 0u; /* lengths < 2^24.5 each, n < 2^32: < 2^57 */
    uint32_t n = 0u, k;
    uint32_t step;
    if (len_step_q8 != 0u) {
        return len_step_q8;
    }
    for (k = 0u; k < g->n; k++) {
        int32_t x, y;
        if (ssda__relax_get(g, k, &x, &y)) {
            const uint64_t ax = (uint64_t)(x < 0 ? -(int64_t)x : (int64_t)x); /* <= 2^23 */
            const uint64_t ay = (uint64_t)(y < 0 ? -(int64_t)y : (int64_t)y);
            sum += ssda__isqrt64(ax * ax + ay * ay);
            n++;
        }
    }
    if (n == 0u) {
        return 64u;
    }
    /* 2 mean / 7 = (2 sum / n) / 7; each quotient below 2^26 */
    step = SSDA_DIV32(SSDA_DIV64_32(2u * sum, n), 7u);
    return step < 64u ? 64u : step;
}

/* Classes and initial likelihoods. */
static void init_labels(const ssda__relax_t *g, relax_mem_t *m, uint32_t step_q8)
{
    uint32_t k, c;
    for (k = 0u; k < g->n; k++) {
        uint16_t *p = m->p + (size_t)k * NC;
        int32_t x, y;
        m->cls[k] = (uint8_t)NC;
        if (!ssda__relax_get(g, k, &x, &y)) {
            continue;
        }
        m->cls[k] = (uint8_t)classify(x, y, step_q8);
        for (c = 0u; c < NC; c++) {
            p[c] = (uint16_t)P_OTHER;
        }
        p[m->cls[k]] = (uint16_t)P_OWN;
    }
}

/* The seed's restored vector at node (i, j): the expectation over the
   classes of the vectors that belong to them, sum P(c) v(c) / sum P(c),
   over the classes present among the node and its valid neighbours, v(c)
   the mean of their vectors of class c. The node's own class is always
   present; if rounding left every such likelihood at 0, the input. */
static void expectation(const ssda__relax_t *g, const relax_mem_t *m, uint32_t i, uint32_t j,
                        int32_t *ox, int32_t *oy)
{
    int64_t lx[9], ly[9];   /* local class sums, < 9 * 2^23 */
    uint32_t lc[9], ln[9];  /* their classes and counts */
    uint32_t nl = 0u, t;
    int64_t nx = 0, ny = 0; /* sum P v: < 9 * 2^15 * 2^23 < 2^42 */
    uint32_t den = 0u;      /* sum P <= 2^15 + 48 */
    const uint16_t *p = m->p + ((size_t)j * g->cols + i) * NC;
    int32_t di, dj;
    for (dj = -1; dj <= 1; dj++) {
        for (di = -1; di <= 1; di++) {
            const int32_t x = (int32_t)i + di, y = (int32_t)j + dj;
            size_t k;
            int32_t vx, vy;
            if (x < 0 || y < 0 || x >= (int32_t)g->cols || y >= (int32_t)g->rows) {
                continue;
            }
            k = (size_t)y * g->cols + (uint32_t)x;
            if (!ssda__relax_get(g, k, &vx, &vy)) {
                continue;
            }
            for (t = 0u; t < nl && lc[t] != m->cls[k]; t++) {
            }
            if (t == nl) {
                lc[t] = m->cls[k];
                lx[t] = 0;
                ly[t] = 0;
                ln[t] = 0u;
                nl++;
            }
            lx[t] += vx;
            ly[t] += vy;
            ln[t]++;
        }
    }
    for (t = 0u; t < nl; t++) {
        const uint32_t w = p[lc[t]];
        nx += ssda__relax_div(lx[t], ln[t]) * w;
        ny += ssda__relax_div(ly[t], ln[t]) * w;
        den += w;
    }
    if (den == 0u) {
        (void)ssda__relax_get(g, (size_t)j * g->cols + i, ox, oy);
        return;
    }
    *ox = (int32_t)ssda__relax_div(nx, den);
    *oy = (int32_t)ssda__relax_div(ny, den);
}

/* Lay out the work buffer (4-byte arrays first). */
static void layout(relax_mem_t *m, uint8_t *b, const ssda__relax_t *g)
{
    m->p = (uint16_t *)(void *)b;
    b += (size_t)g->n * NC * sizeof(uint16_t);
    m->prev = (uint16_t *)(void *)b;
    b += (size_t)g->cols * NC * sizeof(uint16_t);
    m->cur = (uint16_t *)(void *)b;
    b += (size_t)g->cols * NC * sizeof(uint16_t);
    m->cls = b;
}

/* The most likely class of a node (ties to the lowest index). */
static uint32_t best_class(const uint16_t *p)
{
    uint32_t c, b = 0u;
    for (c = 1u; c < NC; c++) {
        if (p[c] > p[b]) {
            b = c;
        }
    }
    return b;
}

static int check_config(const ssda_relax_config_t *cfg, const ssda__relax_t *g)
{
    /* n * 97 + cols * 192 < 2^32 * 2^7: in 64 bits */
    const uint64_t need = (uint64_t)g->n * 97u + (uint64_t)g->cols * 192u;
    if (cfg->iterations > 1000u || (cfg->flags & (uint8_t)~SSDA_RELAX_KEEP) != 0u) {
        return SSDA_ERR_ARG;
    }
    if ((uint64_t)cfg->work_size < need || (((uintptr_t)cfg->work) & 3u) != 0u) {
        return SSDA_ERR_BUFFER;
    }
    return SSDA_OK;
}

int ssda_relax_labels(const ssda_relax_grid_t *grid, const ssda_relax_config_t *cfg,
                      ssda_relax_vector_t *out, size_t out_count)
{
    ssda__relax_t g;
    relax_mem_t m;
    uint32_t step, it, iterations, i, j;
    int err;
    if (cfg == NULL || cfg->work == NULL) {
        return SSDA_ERR_NULL;
    }
    err = ssda__relax_open(grid, out, out_count, &g);
    if (err == SSDA_OK) {
        err = check_config(cfg, &g);
    }
    if (err != SSDA_OK) {
        return err;
    }
    layout(&m, (uint8_t *)cfg->work, &g); /* 4-byte aligned (checked) */
    step = length_step(&g, cfg->len_step_q8);
    init_labels(&g, &m, step);
    iterations = cfg->iterations != 0u ? cfg->iterations : SSDA_RELAX_DEFAULT_ITERATIONS;
    for (it = 0u; it < iterations; it++) {
        iterate(&g, &m);
    }
    for (j = 0u; j < g.rows; j++) {
        for (i = 0u; i < g.cols; i++) {
            const size_t k = (size_t)j * g.cols + i;
            ssda_relax_vector_t v;
            (void)memset(&v, 0, sizeof v);
            if (m.cls[k] < NC) {
                const uint32_t b = best_class(m.p + k * NC);
                v.flags = SSDA_RELAX_VALID;
                v.cls = (uint8_t)b;
                v.p_q15 = m.p[k * NC + b];
                if (b != m.cls[k]) {
                    v.flags |= SSDA_RELAX_CHANGED;
                }
                if ((cfg->flags & SSDA_RELAX_KEEP) != 0u && b == m.cls[k]) {
                    (void)ssda__relax_get(&g, k, &v.dx_q8, &v.dy_q8);
                } else {
                    expectation(&g, &m, i, j, &v.dx_q8, &v.dy_q8);
                }
            }
            out[k] = v;
        }
    }
    return SSDA_OK;
}
