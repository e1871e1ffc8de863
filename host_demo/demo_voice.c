/* demo_voice.c - a synthetic voice with a known f0 contour. */
#define _POSIX_C_SOURCE 200809L /* fileno */
#include "atomic_file.h"
#include "demo.h"

#include <errno.h>
#include <math.h>
#include <sndfile.h>
#include <stdlib.h>
#include <string.h>

#define VOICE_SECS 3.0
#define TWO_PI 6.283185307179586

/* Phrase A: 0.20-1.30 s, glide 110 -> 180 Hz; hiss 1.30-1.55 s; phrase B:
   1.55-2.70 s, glide 240 -> 160 Hz; both with 5.5 Hz vibrato of +-2.5 %. */
double demo_voice_f0(double t)
{
    double base;
    if (t >= 0.20 && t < 1.30) {
        double s = (t - 0.20) / 1.10;
        base = 110.0 + 70.0 * s * s * (3.0 - 2.0 * s);
    } else if (t >= 1.55 && t < 2.70) {
        base = 240.0 - 80.0 * (t - 1.55) / 1.15;
    } else {
        return 0.0;
    }
    return base * (1.0 + 0.025 * sin(TWO_PI * 5.5 * t));
}

/* Raised-cosine envelope rising over 30 ms after `on` and falling before `off`. */
static double envelope(double t, double on, double off)
{
    const double ramp = 0.03;
    if (t < on || t >= off) {
        return 0.0;
    }
    if (t < on + ramp) {
        return 0.5 - 0.5 * cos(3.141592653589793 * (t - on) / ramp);
    }
    if (t > off - ramp) {
        return 0.5 - 0.5 * cos(3.141592653589793 * (off - t) / ramp);
    }
    return 1.0;
}

int demo_make_voice(uint32_t rate, demo_signal_t *sig)
{
    size_t n = (size_t)(VOICE_SECS * rate), i;
    int16_t *x = malloc(n * sizeof *x);
    double phase = 0.0, prev_noise = 0.0;
    uint32_t s = 12345u;
    if (x == NULL) {
        return -1;
    }
    for (i = 0; i < n; i++) {
        double t = (double)i / rate, f0 = demo_voice_f0(t), v = 0.0, noise;
        s ^= s << 13; /* xorshift white noise, -1..1 */
        s ^= s >> 17;
        s ^= s << 5;
        noise = (s / 2147483648.0) - 1.0;
        if (f0 > 0.0) {
            int k;
            phase += TWO_PI * f0 / rate;
            if (phase > TWO_PI * 1000.0) {
                phase = fmod(phase, TWO_PI);
            }
            for (k = 1; k * f0 < 0.45 * rate && k <= 40; k++) { /* band-limited source */
                v += sin(k * phase) / pow(k, 1.3);
            }
            v *= 0.22 * (envelope(t, 0.20, 1.30) + envelope(t, 1.55, 2.70));
        }
        /* a fricative: high-passed noise between the phrases */
        v += 0.12 * envelope(t, 1.30, 1.55) * (noise - prev_noise);
        v += 0.002 * noise; /* breath floor */
        prev_noise = noise;
        x[i] = (int16_t)lround(fmax(-1.0, fmin(1.0, v)) * 32767.0);
    }
    sig->samples = x;
    sig->count = n;
    sig->rate = rate;
    return 0;
}

int demo_write_wav(const char *path, const demo_signal_t *sig)
{
    SF_INFO info;
    SNDFILE *sf;
    atomic_file_t af;
    memset(&info, 0, sizeof info);
    info.samplerate = (int)sig->rate;
    info.channels = 1;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    if (atomic_file_open(&af, path) != 0) {
        fprintf(stderr, "ssda-demo: cannot create '%s': %s\n", path, strerror(errno));
        return -1;
    }
    /* libsndfile writes to the temp file's descriptor; it closes nothing of ours */
    sf = sf_open_fd(fileno(af.fp), SFM_WRITE, &info, 0);
    if (sf == NULL || sf_write_short(sf, sig->samples, (sf_count_t)sig->count) !=
                          (sf_count_t)sig->count) {
        fprintf(stderr, "ssda-demo: cannot write '%s': %s\n", path, sf_strerror(sf));
        if (sf != NULL) {
            sf_close(sf);
        }
        atomic_file_abort(&af);
        return -1;
    }
    sf_close(sf);
    if (atomic_file_commit(&af) != 0) {
        fprintf(stderr, "ssda-demo: cannot write '%s': %s\n", path, strerror(errno));
        return -1;
    }
    return 0;
}

int demo_write_truth_csv(const char *path, double secs)
{
    atomic_file_t af;
    double t;
    if (atomic_file_open(&af, path) != 0) {
        fprintf(stderr, "ssda-demo: cannot create '%s': %s\n", path, strerror(errno));
        return -1;
    }
    fprintf(af.fp, "time_s,f0_hz\n");
    for (t = 0.0; t < secs; t += 0.005) {
        fprintf(af.fp, "%.3f,%.3f\n", t, demo_voice_f0(t));
    }
    if (atomic_file_commit(&af) != 0) {
        fprintf(stderr, "ssda-demo: cannot write '%s': %s\n", path, strerror(errno));
        return -1;
    }
    return 0;
}
