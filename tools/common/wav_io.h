/*
 * wav_io.h - read an audio file as mono int16 samples (host only).
 *
 * Reading is done by libsndfile, so every format it knows works: WAV
 * (8/16/24/32-bit PCM, 32/64-bit float, A-law, mu-law), AIFF, FLAC, OGG, ...
 * Several channels are mixed down to one by averaging. Samples are scaled so
 * that full scale is -32768..32767: 16-bit PCM comes through bit-exact,
 * wider formats and mixed channels are rounded to the nearest int16 (halves
 * up), and float samples beyond +-1.0 are clipped (and counted, see
 * wav_read_mono_i16_ex); a NaN sample (after mixing) reads as 0 and is
 * counted with the clipped ones.
 */
#ifndef SSDA_WAV_IO_H
#define SSDA_WAV_IO_H

#include <stddef.h>
#include <stdint.h>

/* What the file held before conversion (for messages and checks). */
typedef struct {
    uint32_t channels;      /* channels in the file (mixed down to 1) */
    uint32_t source_bits;   /* 8, 16, 24, 32 for PCM; 32/64 for float; 0 if unknown */
    int is_float;           /* 1 for float/double sample formats */
    size_t clipped;         /* samples clipped to -32768..32767 after mixing, or NaN (read as 0) */
    char format_name[64];   /* libsndfile's name of the major format, e.g. "WAV (Microsoft)" */
} wav_info_t;

/*
 * Read the whole file at path as mono int16.
 *   samples: receives a malloc'ed array of *count samples; the caller frees
 *            it with free(). Untouched on error.
 *   count:   number of mono samples (frames) read, >= 1.
 *   rate:    sample rate of the file in Hz, >= 1.
 *   err:     on error, a one-line English message naming the file and the
 *            reason ("cannot open 'x.wav': File contains data in an unknown
 *            format."); may be NULL when errlen is 0.
 * Returns 0 on success, -1 on error (unreadable or unknown format, no audio
 * frames, out of memory, read error).
 */
int wav_read_mono_i16(const char *path, int16_t **samples, size_t *count,
                      uint32_t *rate, char *err, size_t errlen);

/* As wav_read_mono_i16, also filling *info (may be NULL). */
int wav_read_mono_i16_ex(const char *path, int16_t **samples, size_t *count,
                         uint32_t *rate, wav_info_t *info, char *err, size_t errlen);

#endif /* SSDA_WAV_IO_H */
