/*
 * wav_io_check.c - checks tools/common/wav_io against files written here
 * with libsndfile: 8/16/24-bit PCM and float WAV, FLAC, stereo mixed down,
 * rounding and clipping, sample rate, and the error messages. Registered
 * with CTest when tests are built (host only). Exit status 0 = all passed.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sndfile.h>

#include "wav_io.h"

static int g_failures;

#define CHECK(cond, ...)                                                  \
    do {                                                                  \
        if (!(cond)) {                                                    \
            fprintf(stderr, "wav_io_check:%d: ", __LINE__);               \
            fprintf(stderr, __VA_ARGS__);                                 \
            fputc('\n', stderr);                                          \
            g_failures++;                                                 \
        }                                                                 \
    } while (0)

/* Write frames x channels samples in the given format from doubles (float
   files), shorts or ints (PCM files: written as integers, because
   libsndfile scales doubles to PCM by 2^15 - 1 but reads PCM back by 2^15). */
static int write_file(const char *path, int format, int channels, int rate, const double *xd,
                      const short *xs, const int *xi, sf_count_t frames)
{
    SF_INFO info;
    SNDFILE *sf;
    memset(&info, 0, sizeof info);
    info.samplerate = rate;
    info.channels = channels;
    info.format = format;
    if (!sf_format_check(&info)) {
        return -1;
    }
    sf = sf_open(path, SFM_WRITE, &info);
    if (sf == NULL) {
        return -1;
    }
    sf_command(sf, SFC_SET_CLIPPING, NULL, SF_FALSE);
    if (xd != NULL) {
        sf_writef_double(sf, xd, frames);
    } else if (xs != NULL) {
        sf_writef_short(sf, xs, frames);
    } else if (xi != NULL) {
        sf_writef_int(sf, xi, frames);
    }
    sf_close(sf);
    return 0;
}

static void check_pcm16_bit_exact(const char *dir)
{
    static const short v[] = {0, 1, -1, 32767, -32768, 12345, -23456, 7};
    char path[512], err[256];
    int16_t *got = NULL;
    size_t n = 0, i;
    uint32_t rate = 0;
    wav_info_t info;
    snprintf(path, sizeof path, "%s/pcm16.wav", dir);
    CHECK(write_file(path, SF_FORMAT_WAV | SF_FORMAT_PCM_16, 1, 22050, NULL, v, NULL, 8) == 0,
          "write %s", path);
    CHECK(wav_read_mono_i16_ex(path, &got, &n, &rate, &info, err, sizeof err) == 0, "%s", err);
    CHECK(n == 8 && rate == 22050, "n %zu rate %u", n, rate);
    CHECK(info.channels == 1 && info.source_bits == 16 && !info.is_float && info.clipped == 0,
          "info %u %u %d %zu", info.channels, info.source_bits, info.is_float, info.clipped);
    for (i = 0; i < n && i < 8; i++) {
        CHECK(got[i] == v[i], "pcm16[%zu] %d != %d", i, got[i], v[i]);
    }
    free(got);
}

static void check_pcm24_rounding_and_pcm8(const char *dir)
{
    /* 24-bit values k / 2^23: to int16 = round(k / 256), halves up */
    static const int32_t k24[] = {256 * 100 + 127, 256 * 100 + 128, -256 * 100 - 128,
                                  -256 * 100 - 129, 8388607, -8388608};
    static const int16_t want24[] = {100, 101, -100, -101, 32767, -32768};
    int xi[6];
    short xs[4];
    char path[512], err[256];
    int16_t *got = NULL;
    size_t n = 0, i;
    uint32_t rate = 0;
    for (i = 0; i < 6; i++) {
        xi[i] = (int)((unsigned)k24[i] << 8); /* libsndfile ints are left-justified */
    }
    snprintf(path, sizeof path, "%s/pcm24.wav", dir);
    CHECK(write_file(path, SF_FORMAT_WAV | SF_FORMAT_PCM_24, 1, 48000, NULL, NULL, xi, 6) == 0,
          "write %s", path);
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, err, sizeof err) == 0, "%s", err);
    for (i = 0; i < n && i < 6; i++) {
        CHECK(got[i] == want24[i], "pcm24[%zu] %d != %d", i, got[i], want24[i]);
    }
    free(got);
    /* 8-bit (unsigned in WAV): k / 128 -> k * 256 */
    for (i = 0; i < 4; i++) {
        xs[i] = (short)(((int)i * 40 - 70) * 256);
    }
    snprintf(path, sizeof path, "%s/pcm8.wav", dir);
    CHECK(write_file(path, SF_FORMAT_WAV | SF_FORMAT_PCM_U8, 1, 8000, NULL, xs, NULL, 4) == 0,
          "write %s", path);
    got = NULL;
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, err, sizeof err) == 0, "%s", err);
    for (i = 0; i < n && i < 4; i++) {
        CHECK(got[i] == ((int)i * 40 - 70) * 256, "pcm8[%zu] %d", i, got[i]);
    }
    free(got);
}

static void check_float_clipping_and_stereo(const char *dir)
{
    /* float samples beyond +-1 clip and are counted */
    static const double xf[] = {0.5, -1.0, 1.5, -2.0, 0.25};
    static const int16_t wantf[] = {16384, -32768, 32767, -32768, 8192};
    /* stereo: the mean of the channels, halves rounded up */
    static const short xs[] = {1000, 3000, 1, 2, -1, -2, 32767, 32767};
    static const int16_t wants[] = {2000, 2, -1, 32767};
    char path[512], err[256];
    int16_t *got = NULL;
    size_t n = 0, i;
    uint32_t rate = 0;
    wav_info_t info;
    snprintf(path, sizeof path, "%s/float.wav", dir);
    CHECK(write_file(path, SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, 44100, xf, NULL, NULL, 5) == 0,
          "write %s", path);
    CHECK(wav_read_mono_i16_ex(path, &got, &n, &rate, &info, err, sizeof err) == 0, "%s", err);
    CHECK(info.is_float && info.source_bits == 32 && info.clipped == 2, "float info %d %u %zu",
          info.is_float, info.source_bits, info.clipped);
    for (i = 0; i < n && i < 5; i++) {
        CHECK(got[i] == wantf[i], "float[%zu] %d != %d", i, got[i], wantf[i]);
    }
    free(got);
    snprintf(path, sizeof path, "%s/stereo.wav", dir);
    CHECK(write_file(path, SF_FORMAT_WAV | SF_FORMAT_PCM_16, 2, 16000, NULL, xs, NULL, 4) == 0,
          "write %s", path);
    got = NULL;
    CHECK(wav_read_mono_i16_ex(path, &got, &n, &rate, &info, err, sizeof err) == 0, "%s", err);
    CHECK(n == 4 && info.channels == 2, "stereo n %zu channels %u", n, info.channels);
    for (i = 0; i < n && i < 4; i++) {
        CHECK(got[i] == wants[i], "stereo[%zu] %d != %d", i, got[i], wants[i]);
    }
    free(got);
}

/* A float file holding NaN (found by fuzz_wav: the conversion to int16 was
   undefined): NaN reads as 0 and is counted; infinities clip. */
static void check_float_nan(const char *dir)
{
    const double nan = strtod("nan", NULL), inf = strtod("inf", NULL);
    const double xf[] = {0.5, nan, -nan, inf, -inf, 0.25};
    static const int16_t want[] = {16384, 0, 0, 32767, -32768, 8192};
    char path[512], err[256];
    int16_t *got = NULL;
    size_t n = 0, i;
    uint32_t rate = 0;
    wav_info_t info;
    snprintf(path, sizeof path, "%s/nan.wav", dir);
    CHECK(write_file(path, SF_FORMAT_WAV | SF_FORMAT_FLOAT, 1, 8000, xf, NULL, NULL, 6) == 0,
          "write %s", path);
    CHECK(wav_read_mono_i16_ex(path, &got, &n, &rate, &info, err, sizeof err) == 0, "%s", err);
    CHECK(n == 6 && info.clipped == 4, "nan: n %zu clipped %zu", n, info.clipped);
    for (i = 0; i < n && i < 6; i++) {
        CHECK(got[i] == want[i], "nan[%zu] %d != %d", i, got[i], want[i]);
    }
    free(got);
}

static void check_flac(const char *dir)
{
    static const short v[] = {3, -3, 30000, -30000};
    char path[512], err[256];
    int16_t *got = NULL;
    size_t n = 0, i;
    uint32_t rate = 0;
    snprintf(path, sizeof path, "%s/a.flac", dir);
    if (write_file(path, SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 1, 32000, NULL, v, NULL, 4) != 0) {
        printf("wav_io_check: this libsndfile cannot write FLAC, skipped\n");
        return;
    }
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, err, sizeof err) == 0, "%s", err);
    CHECK(n == 4 && rate == 32000, "flac n %zu rate %u", n, rate);
    for (i = 0; i < n && i < 4; i++) {
        CHECK(got[i] == v[i], "flac[%zu] %d != %d", i, got[i], v[i]);
    }
    free(got);
}

/* A FLAC whose STREAMINFO claims 2^36 - 1 frames but holds 4 (found by
   fuzz_wav: the reader allocated the claimed length up front, 128 GiB
   here, and failed): the frames that are there are read. */
static void check_lying_frame_count(const char *dir)
{
    static const short v[] = {3, -3, 30000, -30000};
    char path[512], err[256];
    int16_t *got = NULL;
    size_t n = 0, i;
    uint32_t rate = 0;
    unsigned char head[26];
    FILE *f;
    snprintf(path, sizeof path, "%s/lying.flac", dir);
    CHECK(write_file(path, SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 1, 8000, NULL, v, NULL, 4) == 0,
          "write %s", path);
    /* "fLaC", a block header, then STREAMINFO: the total sample count is
       the low 36 bits of bytes 18..25 of the file */
    f = fopen(path, "r+b");
    CHECK(f != NULL && fread(head, 1, sizeof head, f) == sizeof head &&
          memcmp(head, "fLaC", 4) == 0 && (head[4] & 0x7F) == 0, "%s: no STREAMINFO", path);
    if (f == NULL) {
        return;
    }
    head[21] |= 0x0F;
    memset(head + 22, 0xFF, 4);
    CHECK(fseek(f, 0, SEEK_SET) == 0 && fwrite(head, 1, sizeof head, f) == sizeof head,
          "patch %s", path);
    fclose(f);
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, err, sizeof err) == 0, "%s", err);
    CHECK(n == 4, "lying FLAC: %zu frames", n);
    for (i = 0; i < n && i < 4; i++) {
        CHECK(got[i] == v[i], "lying[%zu] %d != %d", i, got[i], v[i]);
    }
    free(got);
}

static void check_errors(const char *dir)
{
    char path[512], err[256];
    int16_t *got = (int16_t *)&g_failures; /* must stay untouched */
    size_t n = 77;
    uint32_t rate = 77;
    FILE *fp;
    snprintf(path, sizeof path, "%s/missing.wav", dir);
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, err, sizeof err) == -1, "missing accepted");
    CHECK(strstr(err, "missing.wav") != NULL, "message lacks the name: %s", err);
    snprintf(path, sizeof path, "%s/text.wav", dir);
    fp = fopen(path, "w");
    if (fp != NULL) {
        fputs("time_s,f0_hz\n0.0,100\n", fp);
        fclose(fp);
    }
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, err, sizeof err) == -1, "text accepted");
    CHECK(strstr(err, "text.wav") != NULL, "message lacks the name: %s", err);
    snprintf(path, sizeof path, "%s/empty.wav", dir);
    CHECK(write_file(path, SF_FORMAT_WAV | SF_FORMAT_PCM_16, 1, 8000, NULL, NULL, NULL, 0) == 0,
          "write empty");
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, err, sizeof err) == -1, "empty accepted");
    CHECK(strstr(err, "no audio frames") != NULL, "empty: %s", err);
    CHECK(got == (int16_t *)&g_failures && n == 77 && rate == 77, "outputs written on error");
    CHECK(wav_read_mono_i16(NULL, &got, &n, &rate, err, sizeof err) == -1, "NULL path accepted");
    CHECK(wav_read_mono_i16(path, &got, &n, &rate, NULL, 0) == -1, "no error buffer: crash?");
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    check_pcm16_bit_exact(dir);
    check_pcm24_rounding_and_pcm8(dir);
    check_float_clipping_and_stereo(dir);
    check_float_nan(dir);
    check_flac(dir);
    check_lying_frame_count(dir);
    check_errors(dir);
    if (g_failures != 0) {
        fprintf(stderr, "wav_io_check: %d failure(s)\n", g_failures);
        return 1;
    }
    printf("wav_io_check: all passed\n");
    return 0;
}
