/*
 * test_signal.h - synthetic audio with exactly known f0, for the pitch
 * tests and the pitch evaluation (tools/eval). Host double arithmetic with
 * its own sin/exp/sqrt (no libm needed, so it runs on bare targets too).
 * Output is int16, rounded to nearest and saturated.
 */
#ifndef SSDA_TEST_SIGNAL_H
#define SSDA_TEST_SIGNAL_H
#include <stdint.h>
#include "test_rng.h"

#define TEST_PI 3.14159265358979323846

/* A periodic voice: sum of harmonics h = 1..H of f0(t) with amplitudes and
   phases from a band-limited pulse train passed through formant resonators
   (the steady-state response of the filter, so the f0 is exact). */
typedef struct {
    double f0_hz;          /* fundamental; the centre f0 when vibrato is on */
    double vibrato_hz;     /* vibrato rate (0 = none) */
    double vibrato_depth;  /* relative f0 swing: f0(t) = f0 (1 + depth sin(2 pi v t)) */
    double amplitude;      /* sum of harmonic amplitudes, so |x| <= amplitude */
    uint32_t harmonics;    /* 1 = pure sine; 0 = every harmonic below 0.45 rate */
    uint32_t first_harmonic; /* lowest harmonic present: 0 or 1 = the fundamental,
                                2 = a missing fundamental */
    uint32_t n_formants;   /* 0..4 resonators (0 = flat spectrum, a pulse train) */
    double formant_hz[4];  /* centre frequencies */
    double bandwidth_hz[4];/* -3 dB bandwidths */
    double phase;          /* initial phase of the fundamental, radians */
} test_voice_t;

/* Standard voices. */
void test_voice_sine(test_voice_t *v, double f0_hz, double amplitude);
/* Vowel /a/-like: formants 730, 1090, 2440 Hz (bandwidths 90, 110, 170). */
void test_voice_vowel_a(test_voice_t *v, double f0_hz, double amplitude);
/* Vowel /i/-like: formants 270, 2290, 3010 Hz (strong low F1 near 2 f0). */
void test_voice_vowel_i(test_voice_t *v, double f0_hz, double amplitude);

/* Write n samples of voice v at rate, starting at sample index `start` of
   the voice (so a long signal can be made in pieces). */
void test_signal_voice(int16_t *out, uint32_t n, uint32_t start, uint32_t rate,
                       const test_voice_t *v);

/* The voice's instantaneous f0 at time t = sample / rate (seconds). */
double test_voice_f0_at(const test_voice_t *v, double t_s);

/* Add white Gaussian-like noise (sum of 4 uniforms) at snr_db relative to
   the RMS of x over its n samples. Saturates. */
void test_signal_add_noise(int16_t *x, uint32_t n, double snr_db, test_rng_t *r);

/* Noise alone with the given RMS (LSB). */
void test_signal_noise(int16_t *x, uint32_t n, double rms, test_rng_t *r);

/* Multiply by gain and clip to -32768..32767 (hard clipping). */
void test_signal_gain_clip(int16_t *x, uint32_t n, double gain);

/* Square wave: `high` for the first half of every period, `low` for the
   rest (integer period >= 2, starting at phase offset `start`). */
void test_signal_square(int16_t *x, uint32_t n, uint32_t period, uint32_t start,
                        int16_t high, int16_t low);

/* RMS of x (LSB). */
double test_signal_rms(const int16_t *x, uint32_t n);

/* Cents between two frequencies: 1200 log2(f / ref). */
double test_cents(double f, double ref);

/* Self-contained math (accurate to ~1e-15 relative on the ranges used). */
double test_sin(double x);
double test_cos(double x);
double test_exp(double x);
double test_log(double x);
double test_sqrt(double x);
double test_atan2(double y, double x);

#endif
