/* pitch_synth.h - the synthetic evaluation set: a "song" of sung notes
   (vowels and sines, vibrato, different loudness) separated by silence and
   breath noise, with the exact f0 of every sample, at a chosen SNR. */
#ifndef SSDA_EVAL_PITCH_SYNTH_H
#define SSDA_EVAL_PITCH_SYNTH_H
#include <stddef.h>
#include <stdint.h>

typedef struct {
    int16_t *x;        /* samples */
    double *f0;        /* exact f0 per sample, 0 = unvoiced */
    size_t n;
    uint32_t rate;
} synth_song_t;

/* notes: how many notes; snr_db: white noise relative to the RMS of the
   voiced parts (>= 100 means none); bright: 0 = vowels /a/, /i/ and sines,
   1 = band-limited pulse trains with a flat spectrum up to 0.45 rate (no
   formants: the hardest case for time-domain difference functions).
   Returns 0 or -1 (out of memory). */
int synth_song(synth_song_t *s, uint32_t rate, uint32_t notes, double snr_db, int bright,
               uint32_t seed);
void synth_song_free(synth_song_t *s);
/* Exact f0 at time t (0 outside or unvoiced). */
double synth_song_f0_at(const synth_song_t *s, double t_s);

#endif
