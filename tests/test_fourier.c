/*
 * test_fourier.c - Fourier descriptors and their matching (include/ssda/
 * fourier.h) against double-precision references computed here: the DFT
 * of the samples; contours against themselves scaled, turned and
 * re-started (the parameters must come back); the seed's E^2 minimised in
 * double over a fine grid of alpha for unrelated shapes; the fixed-scale
 * match likewise; the internal E^2 bound never above E^2.
 */
#include <string.h>
#include "unity.h"
#include "ssda/fourier.h"
#include "fourier_internal.h"
#include "test_rng.h"
#include "test_signal.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef SSDA_TEST_SMALL
#define TRIALS 6u
#define REF_GRID 1024u
#else
#define TRIALS 40u
#define REF_GRID 4096u
#endif
#define N 64u
#define M 10u

typedef struct {
    double re, im;
} cplx_t;

/* A band-limited closed curve u(t) = sum_{|n| <= 6} c_n exp(2 pi i n t). */
typedef struct {
    cplx_t c[13];
} curve_t;

static double frand(test_rng_t *r, double lo, double hi)
{
    return lo + (hi - lo) * (double)test_rng_next(r) / 4294967296.0;
}

static void random_curve(test_rng_t *r, curve_t *cv)
{
    int n;
    for (n = 0; n < 13; n++) {
        /* n = n - 6 here: a dominant n = 1 and strong low harmonics */
        const double amp = n == 7 ? frand(r, 15.0, 30.0) : frand(r, 0.0, 12.0) / (1.0 + (n > 7 ? n - 7 : 7 - n));
        const double ph = frand(r, 0.0, 2.0 * TEST_PI);
        cv->c[n].re = amp * test_cos(ph);
        cv->c[n].im = amp * test_sin(ph);
    }
}

static cplx_t curve_at(const curve_t *cv, double t)
{
    cplx_t u = {0.0, 0.0};
    int n;
    for (n = -6; n <= 6; n++) {
        const double a = 2.0 * TEST_PI * n * t, c = test_cos(a), s = test_sin(a);
        u.re += cv->c[n + 6].re * c - cv->c[n + 6].im * s;
        u.im += cv->c[n + 6].re * s + cv->c[n + 6].im * c;
    }
    return u;
}

static int32_t q8(double v)
{
    return (int32_t)(v >= 0 ? v * 256.0 + 0.5 : v * 256.0 - 0.5);
}

/* samples of s exp(i phi) u(t_k + tau) + (ox, oy) */
static void sample(const curve_t *cv, double s, double phi, double tau, double ox, double oy,
                   ssda_point_q8_t *p)
{
    uint32_t k;
    const double c = test_cos(phi), sn = test_sin(phi);
    for (k = 0u; k < N; k++) {
        const cplx_t u = curve_at(cv, (double)k / N + tau);
        p[k].x_q8 = q8(s * (c * u.re - sn * u.im) + ox);
        p[k].y_q8 = q8(s * (sn * u.re + c * u.im) + oy);
    }
}

static double wrap_deg(double d)
{
    while (d > 180.0) {
        d -= 360.0;
    }
    while (d < -180.0) {
        d += 360.0;
    }
    return d;
}

static double turns_deg(uint32_t t)
{
    return (double)t * 360.0 / 4294967296.0;
}

static void test_descriptors_equal_the_dft(void)
{
    test_rng_t r;
    ssda_point_q8_t p[N];
    ssda_fd_t fd;
    uint32_t trial, k;
    int n;
    test_rng_seed(&r, 1u);
    for (trial = 0u; trial < TRIALS; trial++) {
        double umax = 0.0, energy = 0.0;
        for (k = 0u; k < N; k++) { /* any points, up to the coordinate limit */
            const uint32_t lim = trial == 0u ? (1u << 24) - 1u : test_rng_range(&r, 256u, 1u << 20);
            p[k].x_q8 = (int32_t)test_rng_range(&r, 0u, 2u * lim) - (int32_t)lim;
            p[k].y_q8 = (int32_t)test_rng_range(&r, 0u, 2u * lim) - (int32_t)lim;
            umax = (double)lim > umax ? (double)lim : umax;
        }
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, M, &fd));
        TEST_ASSERT_EQUAL_UINT32(M, fd.order);
        for (n = -(int)M; n <= (int)M; n++) {
            double re = 0.0, im = 0.0, tol;
            const ssda_fd_coef_t *got;
            if (n == 0) {
                continue;
            }
            for (k = 0u; k < N; k++) {
                const double a = -2.0 * TEST_PI * n * (double)k / N;
                re += p[k].x_q8 * test_cos(a) - p[k].y_q8 * test_sin(a);
                im += p[k].x_q8 * test_sin(a) + p[k].y_q8 * test_cos(a);
            }
            re /= N;
            im /= N;
            energy += re * re + im * im;
            got = n > 0 ? &fd.pos[n - 1] : &fd.neg[-n - 1];
            tol = 1.0 + 1.3e-4 * umax; /* rounding + the Q15 table's 2 LSB */
            TEST_ASSERT_DOUBLE_WITHIN(tol, re, (double)got->re_q8);
            TEST_ASSERT_DOUBLE_WITHIN(tol, im, (double)got->im_q8);
        }
        TEST_ASSERT_DOUBLE_WITHIN(energy * 1e-3 + 64.0 * umax, energy, (double)fd.energy_q16);
    }
}

static void test_self_match_returns_the_transform(void)
{
    test_rng_t r;
    ssda_point_q8_t pa[N], pb[N];
    ssda_fd_t a, b;
    ssda_fd_match_t m;
    uint32_t trial;
    test_rng_seed(&r, 2u);
    for (trial = 0u; trial < TRIALS; trial++) {
        curve_t cv;
        const double s = frand(&r, 0.5, 2.0);
        const double phi = trial == 0u ? 0.0 : frand(&r, 0.0, 2.0 * TEST_PI);
        const double tau = trial == 1u ? 0.0 : frand(&r, 0.0, 1.0);
        random_curve(&r, &cv);
        sample(&cv, 1.0, 0.0, 0.0, 300.0, 200.0, pa);
        sample(&cv, s, phi, tau, frand(&r, 100.0, 900.0), frand(&r, 100.0, 900.0), pb);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(pa, N, M, &a));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(pb, N, M, &b));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&a, &b, &m));
        TEST_ASSERT_DOUBLE_WITHIN(s * 5e-4, s, m.s_q16 / 65536.0);
        /* the samples' Q8 rounding moves phi and alpha by up to ~0.02 degree */
        TEST_ASSERT_DOUBLE_WITHIN(0.06, 0.0, wrap_deg(turns_deg(m.phi) - phi * 180.0 / TEST_PI));
        TEST_ASSERT_DOUBLE_WITHIN(0.06, 0.0, wrap_deg(turns_deg(m.alpha) - tau * 360.0));
        TEST_ASSERT_TRUE(m.e2_q16 < 66u); /* < 1e-3: rounding of the samples only */
        /* the same with scale and rotation given */
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match_fixed(&a, &b, (uint32_t)(s * 65536.0 + 0.5),
                                                           (uint32_t)(phi / (2.0 * TEST_PI) *
                                                                      4294967296.0),
                                                           &m));
        TEST_ASSERT_DOUBLE_WITHIN(0.06, 0.0, wrap_deg(turns_deg(m.alpha) - tau * 360.0));
        TEST_ASSERT_TRUE(m.e2_q16 < 66u);
    }
}

/* Double-precision reference of the match on descriptors a, b: the best
   alpha on a fine grid refined by golden sections of |Z|^2 (free) or
   Re(exp(i phi) Z) (fixed). */
typedef struct {
    double s, phi, alpha, e2, second; /* second: the next local maximum's score */
} ref_match_t;

static cplx_t z_at(const ssda_fd_t *a, const ssda_fd_t *b, double alpha)
{
    cplx_t z = {0.0, 0.0};
    uint32_t n, j;
    for (n = 1u; n <= a->order; n++) {
        for (j = 0u; j < 2u; j++) {
            const ssda_fd_coef_t *ca = j == 0u ? &a->pos[n - 1u] : &a->neg[n - 1u];
            const ssda_fd_coef_t *cb = j == 0u ? &b->pos[n - 1u] : &b->neg[n - 1u];
            const double k = j == 0u ? (double)n : -(double)n;
            const double cr = (double)cb->re_q8 * ca->re_q8 + (double)cb->im_q8 * ca->im_q8;
            const double ci = (double)cb->re_q8 * ca->im_q8 - (double)cb->im_q8 * ca->re_q8;
            const double c = test_cos(k * alpha), s = test_sin(k * alpha);
            z.re += cr * c - ci * s;
            z.im += cr * s + ci * c;
        }
    }
    return z;
}

static double energy(const ssda_fd_t *f)
{
    double e = 0.0;
    uint32_t n;
    for (n = 0u; n < f->order; n++) {
        e += (double)f->pos[n].re_q8 * f->pos[n].re_q8 + (double)f->pos[n].im_q8 * f->pos[n].im_q8;
        e += (double)f->neg[n].re_q8 * f->neg[n].re_q8 + (double)f->neg[n].im_q8 * f->neg[n].im_q8;
    }
    return e;
}

static double ref_score(const ssda_fd_t *a, const ssda_fd_t *b, double alpha, int fixed,
                        double phi)
{
    const cplx_t z = z_at(a, b, alpha);
    if (fixed) {
        return z.re * test_cos(phi) - z.im * test_sin(phi);
    }
    return z.re * z.re + z.im * z.im;
}

static ref_match_t reference(const ssda_fd_t *a, const ssda_fd_t *b, int fixed, double s_fix,
                             double phi_fix)
{
    static double g[REF_GRID];
    const double step = 2.0 * TEST_PI / REF_GRID;
    ref_match_t r;
    double best = -1e300, lo, hi;
    uint32_t j, bj = 0u;
    cplx_t z;
    const double ea = energy(a), eb = energy(b);
    r.second = -1e300;
    for (j = 0u; j < REF_GRID; j++) {
        g[j] = ref_score(a, b, j * step, fixed, phi_fix);
    }
    for (j = 0u; j < REF_GRID; j++) {
        const double p = g[(j + REF_GRID - 1u) % REF_GRID], nx = g[(j + 1u) % REF_GRID];
        if (g[j] >= p && g[j] > nx) {
            if (g[j] > best) {
                r.second = best;
                best = g[j];
                bj = j;
            } else if (g[j] > r.second) {
                r.second = g[j];
            }
        }
    }
    lo = (bj - 1.0) * step;
    hi = (bj + 1.0) * step;
    for (j = 0u; j < 80u; j++) { /* golden section */
        const double m1 = hi - (hi - lo) * 0.6180339887, m2 = lo + (hi - lo) * 0.6180339887;
        if (ref_score(a, b, m1, fixed, phi_fix) < ref_score(a, b, m2, fixed, phi_fix)) {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    r.alpha = 0.5 * (lo + hi);
    z = z_at(a, b, r.alpha);
    if (fixed) {
        const double re = z.re * test_cos(phi_fix) - z.im * test_sin(phi_fix);
        r.s = s_fix;
        r.phi = phi_fix;
        r.e2 = (eb + s_fix * s_fix * ea - 2.0 * s_fix * re) / eb;
    } else {
        const double mag2 = z.re * z.re + z.im * z.im;
        r.s = test_sqrt(mag2) / ea;
        r.phi = -test_atan2(z.im, z.re);
        r.e2 = 1.0 - mag2 / (ea * eb);
        r.second /= best;
    }
    return r;
}

static void test_unrelated_shapes_match_the_double_reference(void)
{
    test_rng_t r;
    ssda_point_q8_t pa[N], pb[N];
    ssda_fd_t a, b;
    ssda_fd_match_t m;
    uint32_t trial, checked_angles = 0u;
    test_rng_seed(&r, 3u);
    for (trial = 0u; trial < TRIALS; trial++) {
        curve_t ca, cb;
        ref_match_t ref;
        random_curve(&r, &ca);
        random_curve(&r, &cb);
        sample(&ca, 1.0, 0.0, 0.0, 500.0, 500.0, pa);
        sample(&cb, frand(&r, 0.5, 2.0), frand(&r, 0.0, 6.28), 0.0, 500.0, 500.0, pb);
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(pa, N, M, &a));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(pb, N, M, &b));
        TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&a, &b, &m));
        ref = reference(&a, &b, 0, 0.0, 0.0);
        TEST_ASSERT_DOUBLE_WITHIN(2e-4, ref.e2, m.e2_q16 / 65536.0);
        TEST_ASSERT_DOUBLE_WITHIN(ref.s * 1e-3, ref.s, m.s_q16 / 65536.0);
        if (ref.second < 0.98) { /* a clear optimum: the same alpha and phi */
            TEST_ASSERT_DOUBLE_WITHIN(0.2, 0.0, wrap_deg(turns_deg(m.alpha) - ref.alpha * 180.0 / TEST_PI));
            TEST_ASSERT_DOUBLE_WITHIN(0.2, 0.0, wrap_deg(turns_deg(m.phi) - ref.phi * 180.0 / TEST_PI));
            checked_angles++;
        }
        TEST_ASSERT_TRUE(ssda__fd_e2_bound(&a, &b) <= m.e2_q16);
        /* fixed scale and rotation: any given pair */
        {
            const double s = frand(&r, 0.5, 2.0), phi = frand(&r, 0.0, 6.28);
            const uint32_t s_q16 = (uint32_t)(s * 65536.0);
            const uint32_t phi_t = (uint32_t)(phi / (2.0 * TEST_PI) * 4294967296.0);
            ref = reference(&a, &b, 1, s_q16 / 65536.0, phi_t * (2.0 * TEST_PI / 4294967296.0));
            TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match_fixed(&a, &b, s_q16, phi_t, &m));
            TEST_ASSERT_DOUBLE_WITHIN(1e-3 * (ref.e2 > 1.0 ? ref.e2 : 1.0), ref.e2,
                                      m.e2_q16 / 65536.0);
            TEST_ASSERT_EQUAL_UINT32(s_q16, m.s_q16);
            TEST_ASSERT_EQUAL_UINT32(phi_t, m.phi);
            TEST_ASSERT_TRUE(ssda__fd_fixed_bound(&a, &b, s_q16) <= m.e2_q16);
        }
    }
    TEST_ASSERT_TRUE(checked_angles * 4u >= TRIALS); /* most random pairs have one clear optimum */
}

static void test_circle_and_limits(void)
{
    ssda_point_q8_t p[N];
    ssda_fd_t a, b;
    ssda_fd_match_t m;
    uint32_t k;
    /* a circle: only a_1; any alpha with phi + alpha fixed; s and E^2 exact */
    for (k = 0u; k < N; k++) {
        const double t = 2.0 * TEST_PI * k / N;
        p[k].x_q8 = q8(100.0 + 20.0 * test_cos(t));
        p[k].y_q8 = q8(100.0 + 20.0 * test_sin(t));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, M, &a));
    for (k = 0u; k < N; k++) {
        const double t = 2.0 * TEST_PI * k / N;
        p[k].x_q8 = q8(40.0 * test_cos(t + 1.0));
        p[k].y_q8 = q8(40.0 * test_sin(t + 1.0));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, 0u, &b)); /* 0: order 10 */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&a, &b, &m));
    TEST_ASSERT_DOUBLE_WITHIN(2e-3, 2.0, m.s_q16 / 65536.0);
    TEST_ASSERT_DOUBLE_WITHIN(0.05, 0.0, wrap_deg(turns_deg(m.phi + m.alpha) - 57.29578));
    TEST_ASSERT_TRUE(m.e2_q16 < 66u);
    /* the largest order a sample count allows: 16 with 64 samples */
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, SSDA_FD_MAX_ORDER, &b));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, 8u, 3u, &b));
}

/* The fixed match of a contour with one about 300 times smaller: A / B
   between 2^16 and 2^17, E^2 >= (s sqrt(A / B) - 1)^2 (|Re Z| <= sqrt(A B))
   is far above 2^16 and must saturate; the ratio A / B in Q16 (2^32 to
   2^33) came back modulo 2^32 and E^2 as about 0.2 of its value. */
static void test_fixed_match_of_far_sizes_saturates(void)
{
    ssda_point_q8_t p[N];
    ssda_fd_t a, b;
    ssda_fd_match_t m;
    double ab, lower;
    uint32_t k;
    for (k = 0u; k < N; k++) {
        const double t = 2.0 * TEST_PI * k / N;
        p[k].x_q8 = q8(1500.0 + 1000.0 * test_cos(t));
        p[k].y_q8 = q8(1500.0 + 1000.0 * test_sin(t));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, M, &a));
    for (k = 0u; k < N; k++) {
        const double t = 2.0 * TEST_PI * k / N;
        p[k].x_q8 = q8(50.0 + 3.3 * test_cos(t));
        p[k].y_q8 = q8(50.0 + 3.3 * test_sin(t));
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, M, &b));
    ab = (double)a.energy_q16 / (double)b.energy_q16;
    TEST_ASSERT_TRUE(ab > 65536.0 && ab < 131072.0);
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match_fixed(&a, &b, 65536u, 0u, &m));
    lower = (test_sqrt(ab) - 1.0) * (test_sqrt(ab) - 1.0) * 65536.0;
    TEST_ASSERT_TRUE(lower > 4294967295.0);
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, m.e2_q16);
    /* the E^2 bound agrees: it may not exceed E^2, and here E^2 saturates */
    TEST_ASSERT_TRUE(ssda__fd_fixed_bound(&a, &b, 65536u) <= m.e2_q16);
}

static void test_errors_change_nothing(void)
{
    ssda_point_q8_t p[N];
    ssda_fd_t a, b, poison_fd;
    ssda_fd_match_t m, poison_m;
    uint32_t k;
    for (k = 0u; k < N; k++) {
        p[k].x_q8 = (int32_t)(k * 100u);
        p[k].y_q8 = (int32_t)(k * k);
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, M, &a));
    memset(&poison_fd, 0x4D, sizeof poison_fd);
    b = poison_fd;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_fd_compute(NULL, N, M, &b));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_fd_compute(p, N, M, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, 48u, M, &b));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, 4u, 1u, &b));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, 16u, 8u, &b)); /* 2M >= n */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, N, 17u, &b));
    p[5].x_q8 = 1 << 24;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, N, M, &b));
    p[5].x_q8 = 0;
    p[6].y_q8 = -(1 << 24);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_compute(p, N, M, &b));
    TEST_ASSERT_EQUAL_MEMORY(&poison_fd, &b, sizeof b);
    /* the largest coordinates accepted: the sums still fit */
    for (k = 0u; k < N; k++) { /* square waves: every odd order */
        p[k].x_q8 = k < N / 2u ? (1 << 24) - 1 : -(1 << 24) + 1;
        p[k].y_q8 = ((k + N / 4u) % N) < N / 2u ? (1 << 24) - 1 : -(1 << 24) + 1;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, M, &b));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&a, &b, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_match(&b, &b, &m));
    TEST_ASSERT_TRUE(m.e2_q16 < 8u);
    TEST_ASSERT_DOUBLE_WITHIN(1e-3, 1.0, m.s_q16 / 65536.0);

    memset(&poison_m, 0x3A, sizeof poison_m);
    m = poison_m;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_fd_match(NULL, &b, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_fd_match(&a, NULL, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_fd_match(&a, &b, NULL));
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, 5u, &b));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match(&a, &b, &m)); /* orders differ */
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match_fixed(&a, &b, 65536u, 0u, &m));
    for (k = 0u; k < N; k++) { /* all samples equal: no energy */
        p[k].x_q8 = 512;
        p[k].y_q8 = 512;
    }
    TEST_ASSERT_EQUAL_INT(SSDA_OK, ssda_fd_compute(p, N, M, &b));
    TEST_ASSERT_TRUE(b.energy_q16 == 0u);
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match(&a, &b, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match(&b, &a, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match_fixed(&a, &a, 0u, 0u, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match_fixed(&a, &a, (1u << 24) + 1u, 0u, &m));
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_NULL, ssda_fd_match_fixed(&a, &a, 65536u, 0u, NULL));
    a.order = 0u;
    TEST_ASSERT_EQUAL_INT(SSDA_ERR_ARG, ssda_fd_match(&a, &a, &m));
    TEST_ASSERT_EQUAL_MEMORY(&poison_m, &m, sizeof m);
}

static uint32_t bits64(uint64_t v)
{
    uint32_t n = 0u;
    while (v != 0u) {
        n++;
        v >>= 1;
    }
    return n;
}

/* ssda__ratio_q16 against plain 64-bit division where that is exact: den
   below 2^32 (no narrowing) and num 2^(exp2 + 16) an integer below 2^64;
   quotients of 2^30 to 2^34, about the saturation at 2^32. */
static void ratio_vs_integer_division(void)
{
    test_rng_t r;
    uint32_t t;
    test_rng_seed(&r, 0x5A71u);
    for (t = 0u; t < 200000u; t++) {
        const uint32_t den = (test_rng_next(&r) >> (test_rng_next(&r) % 32u)) | 1u;
        const uint64_t q = ((uint64_t)test_rng_next(&r) << 2) | (test_rng_next(&r) & 3u);
        const int32_t e = (int32_t)(test_rng_next(&r) % 12u) - 6; /* exp2 + 16 */
        uint64_t scaled, num, exact;
        uint32_t want;
        if (q < ((uint64_t)1u << 30) || bits64(q) + bits64(den) > 63u) {
            continue;
        }
        scaled = q * den + test_rng_next(&r) % den; /* < 2^63 */
        if (e >= 0) {
            num = scaled >> (uint32_t)e; /* num 2^e <= scaled: exact below 2^64 */
            exact = (num << (uint32_t)e) / den;
        } else {
            num = scaled;
            exact = (num >> (uint32_t)(-e)) / den; /* floor(floor(a / b) / c) = floor(a / bc) */
        }
        want = exact > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)exact;
        TEST_ASSERT_EQUAL_UINT32(want, ssda__ratio_q16(num, e - 16, den));
    }
}

static void test_ratio_helpers(void)
{
    /* floor(num 2^e 2^16 / den), saturated */
    TEST_ASSERT_EQUAL_UINT32(65536u, ssda__ratio_q16(7u, 0, 7u));
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__ratio_q16(0u, 10, 7u));
    TEST_ASSERT_EQUAL_UINT32(32768u, ssda__ratio_q16(1u, -1, 1u));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, ssda__ratio_q16(1u, 20, 1u));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, ssda__ratio_q16(UINT64_MAX, 0, 1u));
    TEST_ASSERT_EQUAL_UINT32(65535u, ssda__ratio_q16(UINT64_MAX, -64, 1u)); /* 2^16 - 2^-48 */
    TEST_ASSERT_EQUAL_UINT32(0u, ssda__ratio_q16(UINT64_MAX, -90, 1u));
    TEST_ASSERT_EQUAL_UINT32(65536u, ssda__ratio_q16((uint64_t)3u << 60, 0, (uint64_t)3u << 60));
    TEST_ASSERT_EQUAL_UINT32(21845u, ssda__ratio_q16(1u << 20, 0, 3u << 20)); /* 1/3 */
    /* quotients of 2^32 to 2^33 saturate too (they wrapped modulo 2^32) */
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, ssda__ratio_q16(((uint64_t)1u << 32) + 5u, 0, 1u << 16));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, ssda__ratio_q16((uint64_t)3u << 31, 0, 1u << 16));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, ssda__ratio_q16((uint64_t)1u << 32, -16, 1u));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFEu, ssda__ratio_q16(0xFFFFFFFEu, 0, 1u << 16));
    ratio_vs_integer_division();
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, ssda__mulshr_sat(0xFFFFFFFFu, 0xFFFFFFFFu, 16u));
    TEST_ASSERT_EQUAL_UINT32(6u, ssda__mulshr_sat(3u, 4u, 1u));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_descriptors_equal_the_dft);
    RUN_TEST(test_self_match_returns_the_transform);
    RUN_TEST(test_unrelated_shapes_match_the_double_reference);
    RUN_TEST(test_circle_and_limits);
    RUN_TEST(test_errors_change_nothing);
    RUN_TEST(test_ratio_helpers);
    RUN_TEST(test_fixed_match_of_far_sizes_saturates);
    return UNITY_END();
}
