/* kl_solve.c - the K-L transform from exact band statistics: the matrix,
   its eigenvectors and eigenvalues, the Z variances (kl.h). */
#include "kl_internal.h"

#include <string.h>

#include "fixmath.h"

/* The centred matrix C = n sum(xy) - sum(x) sum(y) (= n^2 cov), exact:
   magnitudes (< 2^96) and signs. */
typedef struct {
    ssda__u128_t mag[3][3];
    bool neg[3][3];
    uint32_t top_bits; /* bits of the largest diagonal entry, 0 if all zero */
} centred_t;

static void centre(const ssda_kl_acc_t *acc, centred_t *c)
{
    /* index of the product sum of bands k, l in sum_xy (00 01 02 11 12 22) */
    static const uint8_t k_pair[3][3] = {{0u, 1u, 2u}, {1u, 3u, 4u}, {2u, 4u, 5u}};
    uint32_t k, l;
    c->top_bits = 0u;
    for (k = 0u; k < 3u; k++) {
        for (l = 0u; l < 3u; l++) {
            const ssda__u128_t p = ssda__mul_64x64(acc->count, acc->sum_xy[k_pair[k][l]]);
            const ssda__u128_t q = ssda__mul_64x64(acc->sum[k], acc->sum[l]);
            c->neg[k][l] = ssda__cmp_128(p, q) < 0;
            c->mag[k][l] = c->neg[k][l] ? ssda__u128_sub(q, p) : ssda__u128_sub(p, q);
        }
        if (ssda__u128_bits(c->mag[k][k]) > c->top_bits) {
            c->top_bits = ssda__u128_bits(c->mag[k][k]);
        }
    }
}

/* |C| scaled by 2^-e (a left shift for e < 0), as a 64-bit magnitude;
   every entry is at most the largest diagonal one (Cauchy-Schwarz). */
static uint64_t scaled(ssda__u128_t m, int32_t e)
{
    const int32_t left = -e;
    return e >= 0 ? ssda__u128_shr(m, (uint32_t)e).lo : ssda__u128_shl(m, (uint32_t)left).lo;
}

/* Covariance in Q30: C 2^-e with e such that the largest diagonal entry
   lies in [2^29, 2^30). Returns e. */
static int32_t covariance_q30(const centred_t *c, int64_t a[3][3])
{
    const int32_t e = (int32_t)c->top_bits - 30;
    uint32_t k, l;
    for (k = 0u; k < 3u; k++) {
        for (l = 0u; l < 3u; l++) {
            const int64_t m = (int64_t)scaled(c->mag[k][l], e); /* <= 2^30 */
            a[k][l] = c->neg[k][l] ? -m : m;
        }
    }
    return e;
}

/* Correlation coefficients in Q30: r = C_kl / sqrt(C_kk C_ll) rounded,
   each pair scaled on its own (a band of small variance beside one of large
   variance keeps its bits); a constant band correlates 0. */
static int64_t correlation_pair(const centred_t *c, uint32_t k, uint32_t l)
{
    /* C_kk 2^-ek in [2^61, 2^62), C_ll 2^-el in [2^60, 2^62) with ek + el
       even, so that C_kl is scaled by 2^-(ek + el) / 2 exactly as the root
       of their product: |C_kl| <= sqrt(C_kk C_ll) (Cauchy-Schwarz) keeps it
       below 2^62 (bits of C <= 96: ek, el in -62..35) */
    const int32_t ek = (int32_t)ssda__u128_bits(c->mag[k][k]) - 62;
    int32_t el = (int32_t)ssda__u128_bits(c->mag[l][l]) - 62;
    uint64_t dk, dl, den;
    ssda__u128_t num;
    int64_t r;
    if ((((uint32_t)ek ^ (uint32_t)el) & 1u) != 0u) { /* ek + el odd */
        el++;
    }
    dk = scaled(c->mag[k][k], ek);
    dl = scaled(c->mag[l][l], el);
    /* relative errors of the truncations < 2^-59: within 1 Q30 step */
    den = ssda__u128_isqrt(ssda__mul_64x64(dk, dl)); /* < 2^62 */
    num = ssda__u128_shl(ssda__u128_from(scaled(c->mag[k][l], (ek + el) / 2)), 30u);
    num = ssda__u128_add(num, ssda__u128_from(den >> 1));
    r = (int64_t)ssda__u128_div(num, ssda__u128_from(den)).lo;
    if (r > SSDA__ONE_Q30_KL) {
        r = SSDA__ONE_Q30_KL; /* floor of the root can push |r| past 1 */
    }
    return c->neg[k][l] ? -r : r;
}

static void correlation_q30(const centred_t *c, int64_t a[3][3])
{
    uint32_t k, l;
    for (k = 0u; k < 3u; k++) {
        for (l = 0u; l < 3u; l++) {
            int64_t r = 0;
            if (k == l) {
                r = SSDA__ONE_Q30_KL;
            } else if (ssda__u128_bits(c->mag[k][k]) == 0u ||
                       ssda__u128_bits(c->mag[l][l]) == 0u) {
                r = 0; /* a constant band */
            } else {
                r = correlation_pair(c, k, l);
            }
            a[k][l] = r;
        }
    }
}

/* round(x 2^(e + 16) / n^2): an entry x of the scaled covariance matrix
   (the exact C = n^2 cov scaled by 2^-e) in sample units^2, Q16. */
static uint64_t cov_q16(uint64_t x, int32_t e, uint32_t n)
{
    ssda__u128_t num = ssda__u128_from(x);     /* < 2^34 */
    ssda__u128_t den = ssda__mul_64x64(n, n); /* < 2^64 */
    const int32_t up = e + 16;
    if (up >= 0) {
        num = ssda__u128_shl(num, (uint32_t)up); /* e <= 66: < 2^116 */
    } else {
        const int32_t down = -up;
        den = ssda__u128_shl(den, (uint32_t)down); /* e >= -30: < 2^78 */
    }
    num = ssda__u128_add(num, ssda__u128_shr(den, 1u));
    return ssda__u128_sat64(ssda__u128_div(num, den));
}

/* v . (a v) for a symmetric matrix and a unit Q30 vector, in a's units
   (>= 0 for a covariance matrix; rounding clamps at 0). a is not changed
   (C99 has no const two-dimensional array parameters). */
static uint64_t quad_form(int64_t a[3][3], const int32_t v[3])
{
    int64_t s = 0;
    uint32_t k, l;
    for (k = 0u; k < 3u; k++) {
        int64_t t = 0;
        for (l = 0u; l < 3u; l++) {
            t += ssda__round_shift(a[k][l] * v[l], 30u); /* |a v| <= 2^60 */
        }
        s += ssda__round_shift(t * v[k], 30u); /* |t| <= 3 2^30 */
    }
    return s < 0 ? 0u : (uint64_t)s;
}

/* Column `col` of v as a unit row, signed so its largest-magnitude
   component (the first of equals) is positive. */
static void unit_row(int64_t v[3][3], uint32_t col, int32_t out[3])
{
    uint64_t norm2 = 0u, big = 0u, nrm;
    uint32_t k, kbig = 0u;
    bool flip;
    for (k = 0u; k < 3u; k++) {
        const uint64_t m = (uint64_t)(v[k][col] < 0 ? -v[k][col] : v[k][col]); /* ~2^30 */
        norm2 += m * m;                                                        /* < 2^62 */
    }
    /* about 2^30: V starts as the identity and each rotation keeps a
       column's norm within a few 2^-30 of 1 */
    nrm = ssda__isqrt64(norm2);
    for (k = 0u; k < 3u; k++) {
        const uint64_t m = (uint64_t)(v[k][col] < 0 ? -v[k][col] : v[k][col]);
        const uint64_t u = SSDA_DIV64_32((m << 30) + (nrm >> 1), (uint32_t)nrm);
        out[k] = (int32_t)(v[k][col] < 0 ? -(int64_t)u : (int64_t)u);
        if (u > big) {
            big = u;
            kbig = k;
        }
    }
    flip = out[kbig] < 0;
    for (k = 0u; k < 3u; k++) {
        out[k] = flip ? -out[k] : out[k];
    }
}

/* Eigenvalue order: decreasing, ties to the lower index (stable). */
static void order(int64_t a[3][3], uint32_t idx[3])
{
    uint32_t i, j;
    for (i = 0u; i < 3u; i++) {
        idx[i] = i;
    }
    for (i = 1u; i < 3u; i++) {
        for (j = i; j > 0u && a[idx[j]][idx[j]] > a[idx[j - 1u]][idx[j - 1u]]; j--) {
            const uint32_t t = idx[j];
            idx[j] = idx[j - 1u];
            idx[j - 1u] = t;
        }
    }
}

static int check_config(const ssda_kl_config_t *cfg, ssda_kl_config_t *c)
{
    if (cfg != NULL) {
        *c = *cfg;
    } else {
        (void)memset(c, 0, sizeof *c);
    }
    if (c->matrix > (uint8_t)SSDA_KL_COVARIANCE || c->range > (uint8_t)SSDA_KL_RANGE_FULL ||
        c->nsigma > 16u || c->out_max >= SSDA_KL_NODATA || c->gain_max_q16 > SSDA__KL_GAIN_CAP_Q16) {
        return SSDA_ERR_ARG;
    }
    c->gain_max_q16 = c->gain_max_q16 == 0u ? SSDA__KL_GAIN_CAP_Q16 : c->gain_max_q16;
    c->nsigma = c->nsigma == 0u ? 4u : c->nsigma;
    c->out_max = c->out_max == 0u ? 1023u : c->out_max;
    return SSDA_OK;
}

uint32_t ssda__kl_eigen(int64_t a[3][3], int32_t vec_q30[3][3], int64_t lambda_q30[3])
{
    int64_t v[3][3];
    uint32_t idx[3], k;
    const uint32_t sweeps = ssda__kl_jacobi(a, v);
    order(a, idx);
    for (k = 0u; k < 3u; k++) {
        lambda_q30[k] = a[idx[k]][idx[k]] < 0 ? 0 : a[idx[k]][idx[k]];
        unit_row(v, idx[k], vec_q30[k]);
    }
    return sweeps;
}

/* The eigen-decomposition into kl: vectors, eigenvalues, Z variances. */
static void decompose(const ssda_kl_acc_t *acc, const ssda_kl_config_t *c, ssda_kl_t *kl)
{
    centred_t cm;
    int64_t cov[3][3], a[3][3], lam[3];
    uint32_t k, l;
    int32_t e;
    centre(acc, &cm);
    e = covariance_q30(&cm, cov);
    if (c->matrix == (uint8_t)SSDA_KL_CORRELATION) {
        correlation_q30(&cm, a);
    } else {
        (void)memcpy(a, cov, sizeof a);
    }
    for (k = 0u; k < 3u; k++) {
        for (l = 0u; l < 3u; l++) {
            kl->matrix_q30[k][l] = (int32_t)a[k][l];
        }
    }
    kl->sweeps = ssda__kl_eigen(a, kl->vec_q30, lam);
    for (k = 0u; k < 3u; k++) {
        kl->lambda_q16[k] = c->matrix == (uint8_t)SSDA_KL_CORRELATION
                                ? (uint64_t)ssda__round_shift(lam[k], 14u)
                                : cov_q16((uint64_t)lam[k], e, acc->count);
        kl->zvar_q16[k] = cov_q16(quad_form(cov, kl->vec_q30[k]), e, acc->count);
    }
}

int ssda_kl_solve(const ssda_kl_acc_t *acc, const ssda_kl_config_t *cfg, ssda_kl_t *kl)
{
    ssda_kl_config_t c;
    ssda_kl_t out;
    uint32_t k;
    int err;
    if (acc == NULL || kl == NULL) {
        return SSDA_ERR_NULL;
    }
    if (!ssda__valid(acc->magic, SSDA__MAGIC_KL_ACC)) {
        return SSDA_ERR_STATE;
    }
    if (acc->count == 0u) {
        return SSDA_ERR_SIZE;
    }
    err = check_config(cfg, &c);
    if (err != SSDA_OK) {
        return err;
    }
    (void)memset(&out, 0, sizeof out);
    out.count = acc->count;
    out.out_max = c.out_max;
    out.gain_max_q16 = c.gain_max_q16;
    out.matrix = c.matrix;
    out.range = c.range;
    out.nsigma = c.nsigma;
    out.format = acc->format;
    out.flags = acc->flags;
    out.nodata = acc->nodata;
    for (k = 0u; k < 3u; k++) {
        /* sum 256 < 2^56, mean < 2^24 */
        out.mean_q8[k] = SSDA_DIV64_32((acc->sum[k] << 8) + (acc->count >> 1), acc->count);
    }
    decompose(acc, &c, &out);
    ssda__kl_plan(&out, acc->sum);
    out.magic = SSDA__MAGIC_KL;
    *kl = out;
    return SSDA_OK;
}
