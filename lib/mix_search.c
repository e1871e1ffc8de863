/* mix_search.c - the seed's coordinate search for a Gaussian mixture
   (Fujimoto and Tanaka, Figs. 2.2.1-2.2.3; mixture.h, "Search"). */
#include "mix_internal.h"

#include "fixmath.h"

#define MODEL_CAP 67108864u  /* 2^26: model values in Q8, capped */
#define HEIGHT_MAX 33554432  /* 2^25: heights in Q8 */

/* The search's state: the scaled histogram and each component's steps. */
typedef struct {
    const uint32_t *hist;
    uint32_t bins, hs, k;
    uint32_t sigma_min_q16;
    ssda__mix_work_t *w;
    uint32_t step[SSDA__MIX_K][3]; /* height Q8, mean Q16, sigma Q16 */
} search_t;

/* Component j's height a exp(-q(z)) at bin z, Q8 (a < 2^25: < 2^25). */
static uint32_t comp_at(const ssda__mix_gauss_t *g, int32_t a, uint32_t z)
{
    const uint64_t v = (uint64_t)(uint32_t)a * ssda__exp_neg_q16(ssda__mix_q(g, z));
    return (uint32_t)((v + ((uint64_t)1u << 29)) >> 30);
}

/* The model of every component but j over j's window, into the cache. */
static void cache_rest(search_t *s, uint32_t j)
{
    ssda__mix_work_t *w = s->w;
    uint32_t z, i;
    for (z = w->lo[j]; z <= w->hi[j]; z++) {
        uint32_t m = 0u; /* <= 15 2^25 < 2^29 */
        for (i = 0u; i < s->k; i++) {
            if (i != j) {
                m += comp_at(&w->g[i], w->height_q8[i], z);
            }
        }
        w->cache[z] = (int32_t)m;
    }
}

/* The seed's error for component j at trial parameters: the squared
   difference of histogram and model over j's window. Differences < 2^26,
   squares < 2^52, at most 4096 of them: < 2^64. */
static uint64_t window_error(const search_t *s, uint32_t j, int32_t a, uint32_t mean_q16,
                             uint32_t sigma_q16)
{
    const ssda__mix_work_t *w = s->w;
    ssda__mix_gauss_t g;
    uint64_t e = 0u;
    uint32_t z;
    ssda__mix_prepare(&g, 1u, 1u, mean_q16, sigma_q16);
    for (z = w->lo[j]; z <= w->hi[j]; z++) {
        const uint32_t target = (s->hist[z] >> s->hs) << 8; /* < 2^24 */
        const uint32_t m = (uint32_t)w->cache[z] + comp_at(&g, a, z);
        const int64_t diff = (int64_t)(m > MODEL_CAP ? MODEL_CAP : m) - (int64_t)target;
        const uint64_t d = (uint64_t)(diff < 0 ? -diff : diff); /* < 2^26 */
        e += d * d;
    }
    return e;
}

/* Parameter `which` (0 height, 1 mean, 2 sigma) of component j, clamped. */
static uint32_t clamp_param(const search_t *s, uint32_t which, int64_t v)
{
    const uint32_t top_mean = (s->bins - 1u) << 16; /* < 2^28 */
    const uint32_t top_sigma = s->bins << 16;       /* <= 2^28 */
    int64_t lo = 1, hi = HEIGHT_MAX; /* heights >= 1: never a weight of 0 */
    if (which == 1u) {
        hi = (int64_t)top_mean;
    } else if (which == 2u) {
        lo = (int64_t)s->sigma_min_q16;
        hi = (int64_t)top_sigma;
    } else {
        /* height: the defaults above */
    }
    return (uint32_t)(v < lo ? lo : v > hi ? hi : v);
}

static uint32_t get_param(const search_t *s, uint32_t j, uint32_t which)
{
    const ssda__mix_work_t *w = s->w;
    uint32_t v = w->p[j].sigma_q16;
    if (which == 0u) {
        v = (uint32_t)w->height_q8[j];
    } else if (which == 1u) {
        v = w->p[j].mean_q16;
    } else {
        /* sigma, above */
    }
    return v;
}

static uint64_t error_with(const search_t *s, uint32_t j, uint32_t which, uint32_t v)
{
    const ssda__mix_work_t *w = s->w;
    int32_t a = w->height_q8[j];
    uint32_t mean = w->p[j].mean_q16, sigma = w->p[j].sigma_q16;
    if (which == 0u) {
        a = (int32_t)v;
    } else if (which == 1u) {
        mean = v;
    } else {
        sigma = v;
    }
    return window_error(s, j, a, mean, sigma);
}

static void set_param(search_t *s, uint32_t j, uint32_t which, uint32_t v)
{
    ssda__mix_work_t *w = s->w;
    if (which == 0u) {
        w->height_q8[j] = (int32_t)v;
    } else if (which == 1u) {
        w->p[j].mean_q16 = v;
    } else {
        w->p[j].sigma_q16 = v;
    }
    ssda__mix_prepare(&w->g[j], 1u, 1u, w->p[j].mean_q16, w->p[j].sigma_q16);
}

/* Step one parameter up while the error falls; if the first step up does
   not lower it, down while it falls (the seed's FTRY). true if it moved. */
static bool step_param(search_t *s, uint32_t j, uint32_t which)
{
    const int64_t step = (int64_t)s->step[j][which];
    uint32_t cur = get_param(s, j, which);
    uint64_t best = error_with(s, j, which, cur);
    bool moved = false;
    int32_t dir;
    for (dir = 1; dir >= -1 && !moved; dir -= 2) {
        bool falling = true;
        while (falling) {
            const uint32_t trial = clamp_param(s, which, (int64_t)cur + (dir * step));
            const uint64_t e = trial == cur ? best : error_with(s, j, which, trial);
            falling = e < best;
            if (falling) {
                best = e;
                cur = trial;
                moved = true;
            }
        }
    }
    if (moved) {
        set_param(s, j, which, cur);
    }
    return moved;
}

/* The fixed windows: bins within +-2 sigma of each initial component. */
static void windows(search_t *s)
{
    ssda__mix_work_t *w = s->w;
    uint32_t j;
    for (j = 0u; j < s->k; j++) {
        const uint64_t half = (uint64_t)w->p[j].sigma_q16 * SSDA_MIX_SEARCH_WINDOW;
        const uint64_t m = w->p[j].mean_q16;
        const uint64_t lo = m > half ? m - half : 0u;
        const uint64_t hi = m + half;
        w->lo[j] = (uint32_t)((lo + 65535u) >> 16);
        w->hi[j] = (uint32_t)(hi >> 16) >= s->bins ? s->bins - 1u : (uint32_t)(hi >> 16);
        if (w->lo[j] > w->hi[j]) {
            w->lo[j] = w->hi[j]; /* narrower than a bin: its nearest bin */
        }
    }
}

static void start_steps(search_t *s)
{
    const ssda__mix_work_t *w = s->w;
    uint32_t j;
    for (j = 0u; j < s->k; j++) {
        const uint32_t a = (uint32_t)w->height_q8[j] >> 4;  /* height / 16 */
        const uint32_t m = w->p[j].sigma_q16 >> 3;           /* sigma / 8 */
        const uint32_t g = w->p[j].sigma_q16 >> 4;           /* sigma / 16 */
        s->step[j][0] = a == 0u ? 1u : a;
        s->step[j][1] = m == 0u ? 1u : m;
        s->step[j][2] = g == 0u ? 1u : g;
    }
}

/* One cycle over every parameter of every component; true if any moved. */
static bool cycle(search_t *s)
{
    bool any = false;
    uint32_t j, which;
    for (j = 0u; j < s->k; j++) {
        cache_rest(s, j);
        for (which = 0u; which < 3u; which++) {
            if (step_param(s, j, which)) {
                any = true;
            }
        }
    }
    return any;
}

uint32_t ssda__mix_search(const uint32_t *hist, uint32_t bins, uint32_t hs,
                          const ssda__mix_cfg_t *c, uint32_t k, ssda__mix_work_t *w)
{
    search_t s;
    uint32_t cycles = 0u, halvings = 0u, j, which;
    s.hist = hist;
    s.bins = bins;
    s.hs = hs;
    s.k = k;
    s.sigma_min_q16 = c->sigma_min_q16;
    s.w = w;
    for (j = 0u; j < k; j++) {
        set_param(&s, j, 2u, w->p[j].sigma_q16);
    }
    windows(&s);
    start_steps(&s);
    while (cycles < c->max_iter) {
        cycles++;
        if (!cycle(&s)) {
            if ((c->flags & SSDA_MIX_SEED_STEPS) != 0u || halvings == SSDA_MIX_SEARCH_HALVINGS) {
                break;
            }
            halvings++;
            for (j = 0u; j < k; j++) {
                for (which = 0u; which < 3u; which++) {
                    s.step[j][which] = s.step[j][which] > 1u ? s.step[j][which] >> 1 : 1u;
                }
            }
        }
    }
    for (j = 0u; j < k; j++) {
        /* area ~ height x sigma (< 2^25 2^28) */
        w->p[j].n = (uint64_t)(uint32_t)w->height_q8[j] * w->p[j].sigma_q16;
    }
    return cycles;
}
