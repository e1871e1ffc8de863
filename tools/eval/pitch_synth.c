/* pitch_synth.c - synthetic song with exact f0 (see header). Voices come
   from tests/support/test_signal.c, so tests and evaluation share them. */
#include "pitch_synth.h"

#include <math.h>
#include <stdlib.h>

#include "test_rng.h"
#include "test_signal.h"

static double uniform(test_rng_t *r)
{
    return (double)test_rng_next(r) / 4294967296.0;
}

int synth_song(synth_song_t *s, uint32_t rate, uint32_t notes, double snr_db, int bright,
               uint32_t seed)
{
    test_rng_t r;
    size_t cap = (size_t)notes * (size_t)(0.9 * rate) + rate, pos = 0, i;
    double voiced_energy = 0.0;
    size_t voiced_n = 0;
    uint32_t k;

    s->x = calloc(cap, sizeof *s->x);
    s->f0 = calloc(cap, sizeof *s->f0);
    s->rate = rate;
    if (s->x == NULL || s->f0 == NULL) {
        synth_song_free(s);
        return -1;
    }
    test_rng_seed(&r, seed);
    pos = (size_t)(0.2 * rate); /* lead-in silence */
    for (k = 0; k < notes; k++) {
        test_voice_t v;
        double f0 = 70.0 * pow(800.0 / 70.0, uniform(&r)); /* log-uniform 70..800 Hz */
        double amp = 8000.0 * pow(2.0, uniform(&r));       /* 8000..16000 */
        size_t len = (size_t)((0.3 + 0.3 * uniform(&r)) * rate);
        size_t gap = (size_t)((0.1 + 0.15 * uniform(&r)) * rate);
        uint32_t kind = test_rng_range(&r, 0u, 3u);
        if (bright) {
            test_voice_vowel_a(&v, f0, amp);
            v.n_formants = 0u; /* flat harmonic spectrum */
        } else if (kind == 0u || kind == 3u) {
            test_voice_vowel_a(&v, f0, amp);
        } else if (kind == 1u) {
            test_voice_vowel_i(&v, f0, amp);
        } else {
            test_voice_sine(&v, f0, amp);
        }
        v.vibrato_hz = 4.5 + 2.0 * uniform(&r);
        /* half the notes steady, half with vibrato up to +-6 % (a semitone) */
        v.vibrato_depth = test_rng_range(&r, 0u, 1u) ? 0.06 * uniform(&r) : 0.0;
        v.phase = 2.0 * 3.14159265358979 * uniform(&r);
        if (pos + len + gap >= cap) {
            break;
        }
        test_signal_voice(s->x + pos, (uint32_t)len, 0u, rate, &v);
        /* 10 ms fade in and out so notes start and end like sung ones */
        {
            size_t fade = rate / 100u;
            for (i = 0; i < fade && i < len; i++) {
                double g = (double)i / (double)fade;
                s->x[pos + i] = (int16_t)lrint(s->x[pos + i] * g);
                s->x[pos + len - 1 - i] = (int16_t)lrint(s->x[pos + len - 1 - i] * g);
            }
        }
        for (i = 0; i < len; i++) {
            s->f0[pos + i] = test_voice_f0_at(&v, (double)i / rate);
            voiced_energy += (double)s->x[pos + i] * s->x[pos + i];
        }
        voiced_n += len;
        pos += len;
        /* gap: silence or breath-like noise at about -40 dB of the note */
        if (test_rng_range(&r, 0u, 1u) == 1u) {
            test_signal_noise(s->x + pos, (uint32_t)gap, amp * 0.01, &r);
        }
        pos += gap;
    }
    s->n = pos;
    if (snr_db < 100.0 && voiced_n > 0) {
        double rms = sqrt(voiced_energy / (double)voiced_n) * pow(10.0, -snr_db / 20.0);
        for (i = 0; i < s->n; i++) {
            double v = s->x[i] + rms * (uniform(&r) + uniform(&r) + uniform(&r) + uniform(&r) - 2.0) * 1.7320508;
            s->x[i] = (int16_t)(v > 32767.0 ? 32767 : v < -32768.0 ? -32768 : lrint(v));
        }
    }
    return 0;
}

void synth_song_free(synth_song_t *s)
{
    free(s->x);
    free(s->f0);
    s->x = NULL;
    s->f0 = NULL;
    s->n = 0;
}

double synth_song_f0_at(const synth_song_t *s, double t_s)
{
    double p = t_s * s->rate;
    if (p < 0.0 || p >= (double)s->n) {
        return 0.0;
    }
    return s->f0[(size_t)p];
}
