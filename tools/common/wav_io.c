/* wav_io.c - mono int16 audio reading through libsndfile. */
#include "wav_io.h"
#include "tool_err.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sndfile.h>

static void describe_subtype(int format, wav_info_t *info)
{
    switch (format & SF_FORMAT_SUBMASK) {
    case SF_FORMAT_PCM_S8: case SF_FORMAT_PCM_U8: info->source_bits = 8; break;
    case SF_FORMAT_PCM_16: info->source_bits = 16; break;
    case SF_FORMAT_PCM_24: info->source_bits = 24; break;
    case SF_FORMAT_PCM_32: info->source_bits = 32; break;
    case SF_FORMAT_FLOAT: info->source_bits = 32; info->is_float = 1; break;
    case SF_FORMAT_DOUBLE: info->source_bits = 64; info->is_float = 1; break;
    default: info->source_bits = 0; break;
    }
}

/* One mixed-down sample, full scale +-1.0, to int16 with rounding and clipping. */
static int16_t to_i16(double v, size_t *clipped)
{
    double s;
    if (v != v) { /* NaN (a float file may hold one): 0, counted with the clipped */
        (*clipped)++;
        return 0;
    }
    s = floor(v * 32768.0 + 0.5);
    if (s > 32767.0) {
        (*clipped)++;
        return 32767;
    }
    if (s < -32768.0) {
        (*clipped)++;
        return -32768;
    }
    return (int16_t)s;
}

/* libsndfile words a missing file "System error : No such file or directory."
   and an empty one "Format not recognised.": say what is wrong with the file
   itself first, as the PNG reader does. Returns 0 when it has content. */
static int probe_file(const char *path, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    int c;
    if (f == NULL) {
        tool_set_err(err, errlen, "cannot open '%s': %s", path, strerror(errno));
        return -1;
    }
    errno = 0;
    c = fgetc(f);
    if (c == EOF) {
        if (ferror(f)) { /* e.g. a directory */
            tool_set_err(err, errlen, "cannot read '%s': %s", path, strerror(errno));
        } else {
            tool_set_err(err, errlen, "'%s' is empty, not a sound file", path);
        }
        fclose(f);
        return -1;
    }
    fclose(f);
    return 0;
}

/* Open path with libsndfile and check its header. Returns the handle (sfi
   filled) or NULL with a message in err. */
static SNDFILE *open_checked(const char *path, SF_INFO *sfi, char *err, size_t errlen)
{
    SNDFILE *sf;
    if (probe_file(path, err, errlen) != 0) {
        return NULL;
    }
    memset(sfi, 0, sizeof *sfi);
    sf = sf_open(path, SFM_READ, sfi);
    if (sf == NULL) { /* readable and not empty: the content is the problem */
        char why[256];
        size_t k;
        snprintf(why, sizeof why, "%s", sf_strerror(NULL));
        k = strlen(why);
        while (k > 0 && (why[k - 1] == '.' || why[k - 1] == ' ' || why[k - 1] == '\n')) {
            why[--k] = '\0';
        }
        tool_set_err(err, errlen, "'%s' is not a sound file libsndfile reads (%s)", path, why);
        return NULL;
    }
    if (sfi->channels < 1 || sfi->samplerate < 1) {
        tool_set_err(err, errlen, "'%s': invalid header (%d channels, %d Hz)", path,
                     sfi->channels, sfi->samplerate);
    } else if (sfi->frames <= 0) {
        tool_set_err(err, errlen, "'%s': no audio frames", path);
    } else if ((unsigned long long)sfi->frames >
               (unsigned long long)(SIZE_MAX / sizeof(int16_t))) {
        tool_set_err(err, errlen, "'%s': too long (%lld frames)", path, (long long)sfi->frames);
    } else {
        return sf;
    }
    sf_close(sf);
    return NULL;
}

/* What the file holds, for messages and checks. */
static void describe_file(const SF_INFO *sfi, wav_info_t *inf)
{
    SF_FORMAT_INFO fmt;
    memset(inf, 0, sizeof *inf);
    inf->channels = (uint32_t)sfi->channels;
    describe_subtype(sfi->format, inf);
    memset(&fmt, 0, sizeof fmt);
    fmt.format = sfi->format & SF_FORMAT_TYPEMASK;
    if (sf_command(NULL, SFC_GET_FORMAT_INFO, &fmt, sizeof fmt) == 0 && fmt.name != NULL) {
        snprintf(inf->format_name, sizeof inf->format_name, "%s", fmt.name);
    }
}

enum { BLOCK_FRAMES = 4096 };

/* Every frame of sf mixed to mono int16 into *out (malloc'ed, *done frames).
   The header's frame count is a claim (a 1 KB FLAC may announce 2^36
   frames): the output grows as frames actually arrive. Returns 0 or -1. */
static int read_frames(SNDFILE *sf, size_t frames, size_t nch, int16_t **out, size_t *done,
                       size_t *clipped, const char *path, char *err, size_t errlen)
{
    size_t cap = frames < (size_t)BLOCK_FRAMES ? frames : (size_t)BLOCK_FRAMES;
    double *block = malloc((size_t)BLOCK_FRAMES * nch * sizeof *block);
    int rc = 0;
    *done = 0;
    *out = malloc(cap * sizeof **out);
    if (*out == NULL || block == NULL) {
        tool_set_err(err, errlen, "'%s': out of memory for %zu frames", path, frames);
        rc = -1;
    }
    /* Doubles normalised to +-1.0: 16-bit PCM is divided by exactly 32768,
       so the round trip through to_i16() is bit-exact. */
    sf_command(sf, SFC_SET_NORM_DOUBLE, NULL, SF_TRUE);
    while (rc == 0 && *done < frames) {
        size_t want = frames - *done < BLOCK_FRAMES ? frames - *done : BLOCK_FRAMES, f, c;
        sf_count_t got = sf_readf_double(sf, block, (sf_count_t)want);
        if (got <= 0) {
            break;
        }
        if (*done + (size_t)got > cap) {
            size_t grown = cap > frames / 2u ? frames : 2u * cap;
            int16_t *more = realloc(*out, grown * sizeof *more);
            if (more == NULL) {
                tool_set_err(err, errlen, "'%s': out of memory after %zu frames", path, *done);
                rc = -1;
                break;
            }
            *out = more;
            cap = grown;
        }
        for (f = 0; f < (size_t)got; f++) {
            double acc = 0.0;
            for (c = 0; c < nch; c++) {
                acc += block[f * nch + c];
            }
            (*out)[*done + f] = to_i16(acc / (double)nch, clipped);
        }
        *done += (size_t)got;
    }
    free(block);
    if (rc != 0) {
        free(*out);
        *out = NULL;
    }
    return rc;
}

int wav_read_mono_i16_ex(const char *path, int16_t **samples, size_t *count,
                         uint32_t *rate, wav_info_t *info, char *err, size_t errlen)
{
    SF_INFO sfi;
    SNDFILE *sf;
    wav_info_t inf;
    int16_t *out = NULL;
    size_t done = 0;

    if (path == NULL || samples == NULL || count == NULL || rate == NULL) {
        tool_set_err(err, errlen, "wav_read_mono_i16: NULL argument");
        return -1;
    }
    if ((sf = open_checked(path, &sfi, err, errlen)) == NULL) {
        return -1;
    }
    describe_file(&sfi, &inf);
    if (read_frames(sf, (size_t)sfi.frames, (size_t)sfi.channels, &out, &done, &inf.clipped, path,
                    err, errlen) != 0) {
        sf_close(sf);
        return -1;
    }
    if (sf_error(sf) != SF_ERR_NO_ERROR || done == 0) {
        tool_set_err(err, errlen, "'%s': read error after %zu of %lld frames: %s", path, done,
                     (long long)sfi.frames, sf_strerror(sf));
        free(out);
        sf_close(sf);
        return -1;
    }
    sf_close(sf);
    *samples = out;
    *count = done; /* a truncated file yields the frames that were there */
    *rate = (uint32_t)sfi.samplerate;
    if (info != NULL) {
        *info = inf;
    }
    return 0;
}

int wav_read_mono_i16(const char *path, int16_t **samples, size_t *count,
                      uint32_t *rate, char *err, size_t errlen)
{
    return wav_read_mono_i16_ex(path, samples, count, rate, NULL, err, errlen);
}
