/* test_signal.c - synthetic voices with exactly known f0 (see header). */
#include "test_signal.h"

/* ---- self-contained math ---- */

/* sin on [-pi/4, pi/4] by its Taylor series (terms to x^17). */
static double sin_core(double x)
{
    double x2 = x * x, term = x, sum = x;
    int k;
    for (k = 1; k <= 8; k++) {
        term *= -x2 / (double)((2 * k) * (2 * k + 1));
        sum += term;
    }
    return sum;
}

static double cos_core(double x)
{
    double x2 = x * x, term = 1.0, sum = 1.0;
    int k;
    for (k = 1; k <= 8; k++) {
        term *= -x2 / (double)((2 * k - 1) * (2 * k));
        sum += term;
    }
    return sum;
}

double test_sin(double x)
{
    /* reduce to x = q * pi/2 + r, |r| <= pi/4 */
    double q = x / (TEST_PI / 2.0);
    long long qi = (long long)(q >= 0.0 ? q + 0.5 : q - 0.5);
    double r = x - (double)qi * (TEST_PI / 2.0);
    switch ((int)(qi & 3)) {
    case 0: return sin_core(r);
    case 1: return cos_core(r);
    case 2: return -sin_core(r);
    default: return -cos_core(r);
    }
}

double test_cos(double x)
{
    return test_sin(x + TEST_PI / 2.0);
}

double test_exp(double x)
{
    /* exp(x) = exp(x / 2^k)^(2^k) with |x / 2^k| <= 1/16 */
    int k = 0, i;
    double term = 1.0, sum = 1.0;
    while (x > 0.0625 || x < -0.0625) {
        x /= 2.0;
        k++;
    }
    for (i = 1; i <= 12; i++) {
        term *= x / (double)i;
        sum += term;
    }
    while (k-- > 0) {
        sum *= sum;
    }
    return sum;
}

double test_log(double x)
{
    /* Newton on exp(y) = x, after scaling x into [0.5, 2) by powers of 2. */
    const double ln2 = 0.69314718055994530942;
    double y = 0.0;
    int e = 0, i;
    if (x <= 0.0) {
        return -1e300;
    }
    while (x >= 2.0) {
        x /= 2.0;
        e++;
    }
    while (x < 0.5) {
        x *= 2.0;
        e--;
    }
    for (i = 0; i < 40; i++) {
        y = y - 1.0 + x / test_exp(y);
    }
    return y + (double)e * ln2;
}

double test_sqrt(double x)
{
    double y = x > 1.0 ? x : 1.0;
    int i;
    if (x <= 0.0) {
        return 0.0;
    }
    for (i = 0; i < 80; i++) {
        y = 0.5 * (y + x / y);
    }
    return y;
}

double test_atan2(double y, double x)
{
    /* atan(z) for |z| <= 1 by halving the angle 3 times, then Taylor. */
    double z, a, z2, term, sum;
    int k, swap = 0;
    if (x == 0.0 && y == 0.0) {
        return 0.0;
    }
    if ((y >= 0.0 ? y : -y) > (x >= 0.0 ? x : -x)) {
        z = x / y;
        swap = 1;
    } else {
        z = y / x;
    }
    for (k = 0; k < 3; k++) {
        z = z / (1.0 + test_sqrt(1.0 + z * z));
    }
    z2 = z * z;
    term = z;
    sum = z;
    for (k = 1; k <= 12; k++) {
        term *= -z2;
        sum += term / (double)(2 * k + 1);
    }
    a = 8.0 * sum; /* atan of the unreduced ratio, in [-pi/4, pi/4] */
    if (swap) {
        a = (y > 0.0 ? TEST_PI / 2.0 : -TEST_PI / 2.0) - a;
    } else if (x < 0.0) {
        a += (y >= 0.0 ? TEST_PI : -TEST_PI);
    }
    return a;
}

double test_cents(double f, double ref)
{
    return 1200.0 * test_log(f / ref) / 0.69314718055994530942;
}

/* ---- voices ---- */

void test_voice_sine(test_voice_t *v, double f0_hz, double amplitude)
{
    test_voice_t z = {0};
    z.f0_hz = f0_hz;
    z.amplitude = amplitude;
    z.harmonics = 1u;
    *v = z;
}

static void set_formants(test_voice_t *v, const double *f, const double *b, uint32_t n)
{
    uint32_t i;
    v->n_formants = n;
    for (i = 0; i < n; i++) {
        v->formant_hz[i] = f[i];
        v->bandwidth_hz[i] = b[i];
    }
}

void test_voice_vowel_a(test_voice_t *v, double f0_hz, double amplitude)
{
    static const double f[3] = {730.0, 1090.0, 2440.0}, b[3] = {90.0, 110.0, 170.0};
    test_voice_t z = {0};
    z.f0_hz = f0_hz;
    z.amplitude = amplitude;
    set_formants(&z, f, b, 3u);
    *v = z;
}

void test_voice_vowel_i(test_voice_t *v, double f0_hz, double amplitude)
{
    static const double f[3] = {270.0, 2290.0, 3010.0}, b[3] = {60.0, 100.0, 150.0};
    test_voice_t z = {0};
    z.f0_hz = f0_hz;
    z.amplitude = amplitude;
    set_formants(&z, f, b, 3u);
    *v = z;
}

/* Complex response of the resonator cascade at frequency hz:
   prod_k (1 - 2 r cos(th) + r^2) / (1 - 2 r cos(th) e^-jw + r^2 e^-2jw),
   normalised to gain 1 at 0 Hz. */
static void formant_response(const test_voice_t *v, double hz, uint32_t rate,
                             double *re, double *im)
{
    double w = 2.0 * TEST_PI * hz / (double)rate;
    double c1 = test_cos(w), s1 = test_sin(w), c2 = test_cos(2.0 * w), s2 = test_sin(2.0 * w);
    double hr = 1.0, hi = 0.0;
    uint32_t k;
    for (k = 0; k < v->n_formants; k++) {
        double r = test_exp(-TEST_PI * v->bandwidth_hz[k] / (double)rate);
        double a1 = -2.0 * r * test_cos(2.0 * TEST_PI * v->formant_hz[k] / (double)rate);
        double a2 = r * r;
        double g = 1.0 + a1 + a2;
        /* denominator 1 + a1 e^-jw + a2 e^-2jw */
        double dr = 1.0 + a1 * c1 + a2 * c2, di = -(a1 * s1 + a2 * s2);
        double m = dr * dr + di * di;
        /* multiply (hr + j hi) by g / (dr + j di) */
        double nr = (hr * dr + hi * di) * g / m, ni = (hi * dr - hr * di) * g / m;
        hr = nr;
        hi = ni;
    }
    *re = hr;
    *im = hi;
}

double test_voice_f0_at(const test_voice_t *v, double t_s)
{
    if (v->vibrato_hz <= 0.0) {
        return v->f0_hz;
    }
    return v->f0_hz * (1.0 + v->vibrato_depth * test_sin(2.0 * TEST_PI * v->vibrato_hz * t_s));
}

/* Phase of the fundamental at time t: 2 pi * integral of f0. */
static double voice_phase(const test_voice_t *v, double t_s)
{
    double ph = v->phase + 2.0 * TEST_PI * v->f0_hz * t_s;
    if (v->vibrato_hz > 0.0) {
        ph += v->f0_hz * v->vibrato_depth / v->vibrato_hz *
              (1.0 - test_cos(2.0 * TEST_PI * v->vibrato_hz * t_s));
    }
    return ph;
}

static int16_t to_i16(double s)
{
    double r = s >= 0.0 ? s + 0.5 : s - 0.5;
    if (r > 32767.0) {
        return 32767;
    }
    if (r < -32768.0) {
        return -32768;
    }
    return (int16_t)(long)r;
}

#define MAX_HARMONICS 64

void test_signal_voice(int16_t *out, uint32_t n, uint32_t start, uint32_t rate,
                       const test_voice_t *v)
{
    /* Harmonic amplitudes and phases at the centre f0 (the formants move
       little under vibrato; amplitudes fixed keeps the f0 exact). */
    double amp[MAX_HARMONICS], phs[MAX_HARMONICS], cph[MAX_HARMONICS], sph[MAX_HARMONICS];
    double total = 0.0;
    double fmax = v->f0_hz * (1.0 + (v->vibrato_hz > 0.0 ? v->vibrato_depth : 0.0));
    uint32_t nh = v->harmonics, h, i;
    if (nh == 0u) {
        nh = (uint32_t)(0.45 * (double)rate / fmax);
    }
    if (nh > MAX_HARMONICS) {
        nh = MAX_HARMONICS;
    }
    if (nh == 0u) {
        nh = 1u;
    }
    for (h = 0; h < nh; h++) {
        double re, im;
        formant_response(v, v->f0_hz * (double)(h + 1u), rate, &re, &im);
        amp[h] = (h + 1u < v->first_harmonic) ? 0.0 : test_sqrt(re * re + im * im);
        phs[h] = test_atan2(im, re);
        total += amp[h];
    }
    for (h = 0; h < nh; h++) {
        cph[h] = test_cos(phs[h]);
        sph[h] = test_sin(phs[h]);
    }
    for (i = 0; i < n; i++) {
        double t = (double)(start + i) / (double)rate;
        double ph = voice_phase(v, t), s = 0.0;
        /* sin and cos of h * ph by the Chebyshev recurrence
           f((h + 1) ph) = 2 cos(ph) f(h ph) - f((h - 1) ph): one sin/cos
           per sample instead of one per harmonic (fast on soft-float targets) */
        double c1 = test_cos(ph), s1 = test_sin(ph);
        double sp = 0.0, cp = 1.0, sh = s1, ch = c1; /* h = 0 and h = 1 */
        for (h = 0; h < nh; h++) {
            double sn, cn;
            s += amp[h] * (sh * cph[h] + ch * sph[h]); /* sin(h ph + phase_h) */
            sn = 2.0 * c1 * sh - sp;
            cn = 2.0 * c1 * ch - cp;
            sp = sh;
            cp = ch;
            sh = sn;
            ch = cn;
        }
        out[i] = to_i16(s * v->amplitude / total);
    }
}

/* ---- noise, gain, squares ---- */

static double gauss(test_rng_t *r)
{
    /* sum of 4 uniforms on [-0.5, 0.5): variance 4/12 -> scale to 1 */
    double s = 0.0;
    int k;
    for (k = 0; k < 4; k++) {
        s += (double)test_rng_next(r) / 4294967296.0 - 0.5;
    }
    return s * 1.7320508075688772;
}

double test_signal_rms(const int16_t *x, uint32_t n)
{
    double acc = 0.0;
    uint32_t i;
    for (i = 0; i < n; i++) {
        acc += (double)x[i] * (double)x[i];
    }
    return n > 0u ? test_sqrt(acc / (double)n) : 0.0;
}

void test_signal_noise(int16_t *x, uint32_t n, double rms, test_rng_t *r)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        x[i] = to_i16(rms * gauss(r));
    }
}

void test_signal_add_noise(int16_t *x, uint32_t n, double snr_db, test_rng_t *r)
{
    double rms = test_signal_rms(x, n) * test_exp(-snr_db / 20.0 * 2.302585092994046);
    uint32_t i;
    for (i = 0; i < n; i++) {
        x[i] = to_i16((double)x[i] + rms * gauss(r));
    }
}

void test_signal_gain_clip(int16_t *x, uint32_t n, double gain)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        x[i] = to_i16((double)x[i] * gain);
    }
}

void test_signal_square(int16_t *x, uint32_t n, uint32_t period, uint32_t start,
                        int16_t high, int16_t low)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        x[i] = ((start + i) % period) < period / 2u ? high : low;
    }
}
