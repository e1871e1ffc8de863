/*
 * fuzz_seeds.c - the seed corpus, generated (nothing binary is committed).
 * Usage: fuzz_seeds OUTDIR   -> OUTDIR/<target>/seed-NNN for every target.
 *   png:   [choice byte][PNG]: gray 1/2/4/8/16-bit, gray+alpha, RGB, RGBA,
 *          palette (with and without tRNS), interlaced, written with libpng;
 *   wav:   [choice byte][file]: WAV 8/16/24/32-bit PCM, float, double,
 *          A-law, mu-law, IMA/MS ADPCM, stereo, AIFF, AU, FLAC (libsndfile);
 *   cli:   command lines in fuzz_cli.c's layout for every subcommand, with
 *          generated images and sounds or one of the PNG/WAV seeds inside;
 *   match, track, pitch, stream: pseudo-random byte strings (those targets
 *          read any bytes as choices).
 */
#define _POSIX_C_SOURCE 200809L
#include <png.h>
#include <sndfile.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct {
    uint8_t *p;
    size_t n, cap;
} buf_t;

static void put(buf_t *b, const void *data, size_t n)
{
    if (b->n + n > b->cap) {
        b->cap = (b->n + n) * 2u + 256u;
        b->p = realloc(b->p, b->cap);
        if (b->p == NULL) {
            perror("fuzz_seeds");
            exit(1);
        }
    }
    memcpy(b->p + b->n, data, n);
    b->n += n;
}

static void put8(buf_t *b, uint32_t v)
{
    uint8_t c = (uint8_t)v;
    put(b, &c, 1);
}

static void put16(buf_t *b, uint32_t v)
{
    put8(b, v & 0xFFu);
    put8(b, v >> 8);
}

static const char *g_out;

static void save(const char *target, int k, const buf_t *b)
{
    char path[4096];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", g_out, target);
    mkdir(path, 0777);
    snprintf(path, sizeof path, "%s/%s/seed-%03d", g_out, target, k);
    f = fopen(path, "wb");
    if (f == NULL || fwrite(b->p, 1, b->n, f) != b->n || fclose(f) != 0) {
        perror(path);
        exit(1);
    }
}

static uint32_t g_rng = 12345u;
static uint32_t rnd(void)
{
    g_rng ^= g_rng << 13;
    g_rng ^= g_rng >> 17;
    g_rng ^= g_rng << 5;
    return g_rng;
}

/* ---- PNG ---- */
static void png_to_buf(png_structp png, png_bytep data, png_size_t n)
{
    put((buf_t *)png_get_io_ptr(png), data, n);
}

static void png_flush_nothing(png_structp png)
{
    (void)png;
}

/* A w x h PNG of this colour type and depth (pixels: a gradient with noise). */
static void make_png(buf_t *b, uint32_t w, uint32_t h, int color, int depth, int interlace,
                     int trns)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    int channels = color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_PALETTE ? 1
                 : color == PNG_COLOR_TYPE_GRAY_ALPHA ? 2 : color == PNG_COLOR_TYPE_RGB ? 3 : 4;
    size_t rowbytes = ((size_t)w * (size_t)channels * (size_t)depth + 7u) / 8u;
    uint8_t *row = calloc(rowbytes, 1);
    uint32_t x, y;
    int pass, passes;
    if (png == NULL || info == NULL || row == NULL || setjmp(png_jmpbuf(png))) {
        fprintf(stderr, "fuzz_seeds: libpng failed\n");
        exit(1);
    }
    png_set_write_fn(png, b, png_to_buf, png_flush_nothing);
    png_set_IHDR(png, info, w, h, depth, color,
                 interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (color == PNG_COLOR_TYPE_PALETTE) {
        png_color pal[256];
        png_byte alpha[4] = {0, 128, 255, 7};
        int i, n = 1 << depth;
        for (i = 0; i < n; i++) {
            pal[i].red = (png_byte)(i * 37);
            pal[i].green = (png_byte)(i * 91);
            pal[i].blue = (png_byte)(255 - i);
        }
        png_set_PLTE(png, info, pal, n);
        if (trns) {
            png_set_tRNS(png, info, alpha, n < 4 ? n : 4, NULL);
        }
    } else if (trns && (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_RGB)) {
        png_color_16 t;
        memset(&t, 0, sizeof t);
        t.gray = 1;
        t.red = t.green = t.blue = 1;
        png_set_tRNS(png, info, NULL, 0, &t);
    }
    png_write_info(png, info);
    passes = interlace ? png_set_interlace_handling(png) : 1;
    for (pass = 0; pass < passes; pass++) {
        for (y = 0; y < h; y++) {
            for (x = 0; x < rowbytes; x++) {
                row[x] = (uint8_t)((x * 7u + y * 13u) ^ (rnd() & 0x0Fu));
            }
            png_write_row(png, row);
        }
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    free(row);
}

static int seeds_png(int k0)
{
    static const struct {
        int color, depth;
    } kinds[] = {
        {PNG_COLOR_TYPE_GRAY, 1},       {PNG_COLOR_TYPE_GRAY, 2},    {PNG_COLOR_TYPE_GRAY, 4},
        {PNG_COLOR_TYPE_GRAY, 8},       {PNG_COLOR_TYPE_GRAY, 16},   {PNG_COLOR_TYPE_GRAY_ALPHA, 8},
        {PNG_COLOR_TYPE_GRAY_ALPHA, 16}, {PNG_COLOR_TYPE_RGB, 8},    {PNG_COLOR_TYPE_RGB, 16},
        {PNG_COLOR_TYPE_RGBA, 8},       {PNG_COLOR_TYPE_RGBA, 16},   {PNG_COLOR_TYPE_PALETTE, 1},
        {PNG_COLOR_TYPE_PALETTE, 2},    {PNG_COLOR_TYPE_PALETTE, 4}, {PNG_COLOR_TYPE_PALETTE, 8}};
    int k = k0;
    size_t i;
    for (i = 0; i < sizeof kinds / sizeof kinds[0]; i++) {
        int il;
        for (il = 0; il < 2; il++) {
            buf_t b = {0};
            put8(&b, (uint32_t)(i * 5u + (size_t)il) % 12u + 1u); /* depth asked, error length */
            make_png(&b, 1u + (uint32_t)i * 3u % 13u, 1u + (uint32_t)i * 5u % 11u,
                     kinds[i].color, kinds[i].depth, il, (int)(i & 1u));
            save("png", k++, &b);
            free(b.p);
        }
    }
    return k;
}

/* ---- WAV and friends, through a temporary file ---- */
static void make_sound(buf_t *b, int format, int channels, int rate, int frames)
{
    char path[] = "/tmp/ssda-fuzz-seed-XXXXXX";
    int fd = mkstemp(path), i;
    SF_INFO info;
    SNDFILE *sf;
    short *s = malloc(sizeof(short) * (size_t)(frames * channels));
    FILE *f;
    uint8_t chunk[4096];
    size_t n;
    if (fd < 0 || s == NULL) {
        perror("fuzz_seeds");
        exit(1);
    }
    close(fd);
    memset(&info, 0, sizeof info);
    info.samplerate = rate;
    info.channels = channels;
    info.format = format;
    for (i = 0; i < frames * channels; i++) {
        s[i] = (short)(((i / channels) % 40 - 20) * 1500 + (int)(rnd() % 64u));
    }
    sf = sf_open(path, SFM_WRITE, &info);
    if (sf == NULL) {
        fprintf(stderr, "fuzz_seeds: libsndfile cannot write format 0x%x: %s\n", format,
                sf_strerror(NULL));
        unlink(path);
        free(s);
        return;
    }
    sf_writef_short(sf, s, frames);
    sf_close(sf);
    f = fopen(path, "rb");
    while (f != NULL && (n = fread(chunk, 1, sizeof chunk, f)) > 0) {
        put(b, chunk, n);
    }
    if (f != NULL) {
        fclose(f);
    }
    unlink(path);
    free(s);
}

static int seeds_wav(int k0, buf_t *wav16)
{
    static const int formats[] = {
        SF_FORMAT_WAV | SF_FORMAT_PCM_16,  SF_FORMAT_WAV | SF_FORMAT_PCM_U8,
        SF_FORMAT_WAV | SF_FORMAT_PCM_24,  SF_FORMAT_WAV | SF_FORMAT_PCM_32,
        SF_FORMAT_WAV | SF_FORMAT_FLOAT,   SF_FORMAT_WAV | SF_FORMAT_DOUBLE,
        SF_FORMAT_WAV | SF_FORMAT_ULAW,    SF_FORMAT_WAV | SF_FORMAT_ALAW,
        SF_FORMAT_WAV | SF_FORMAT_IMA_ADPCM, SF_FORMAT_WAV | SF_FORMAT_MS_ADPCM,
        SF_FORMAT_AIFF | SF_FORMAT_PCM_16, SF_FORMAT_AU | SF_FORMAT_PCM_16,
        SF_FORMAT_FLAC | SF_FORMAT_PCM_16, SF_FORMAT_WAVEX | SF_FORMAT_PCM_16};
    int k = k0;
    size_t i;
    for (i = 0; i < sizeof formats / sizeof formats[0]; i++) {
        int ch;
        for (ch = 1; ch <= 2; ch++) {
            buf_t b = {0};
            put8(&b, (uint32_t)(i + (size_t)ch) % 7u + 1u);
            make_sound(&b, formats[i], ch, ch == 1 ? 8000 : 16000, 160 + (int)i * 10);
            if (b.n > 1u) {
                save("wav", k++, &b);
            }
            if (i == 0 && ch == 1) {
                put(wav16, b.p + 1, b.n - 1u);
            }
            free(b.p);
        }
    }
    return k;
}

/* ---- CLI command lines (layout: fuzz_cli.c) ---- */

/* A generated PNG: kind 1, then w-1, h-1, bits byte, levels byte. */
static void cli_png(buf_t *b, uint32_t w, uint32_t h, int bits16, uint32_t levels)
{
    put8(b, 1);
    put8(b, w - 1u);
    put8(b, h - 1u);
    put8(b, bits16 ? 1u : 0u);
    put8(b, levels - 1u);
}

static int seeds_cli(int k0, const buf_t *png8, const buf_t *wav16)
{
    int k = k0, cmd;
    for (cmd = 0; cmd < 5; cmd++) {
        int variant;
        for (variant = 0; variant < 4; variant++) {
            buf_t b = {0};
            put8(&b, (uint32_t)cmd);
            if (variant == 0) {
                put8(&b, 0); /* no options */
            } else {
                uint32_t t;
                put8(&b, (uint32_t)variant * 2u);
                for (t = 0; t < (uint32_t)variant * 2u; t++) { /* option, value bytes */
                    put8(&b, t * 3u + (uint32_t)variant);
                    put16(&b, 5u + t);
                    put16(&b, 3u + t);
                    put8(&b, 1u);
                    put8(&b, 1u);
                }
            }
            put8(&b, 0); /* positionals as expected */
            put16(&b, 0x1234u + (uint32_t)variant);
            put16(&b, 0x5678u);
            if (cmd == 4) {
                if (variant == 3) {
                    put8(&b, 0); /* raw WAV bytes */
                    put16(&b, (uint32_t)wav16->n);
                    put(&b, wav16->p, wav16->n);
                } else {
                    uint32_t period = 40u + (uint32_t)variant * 30u, i;
                    put8(&b, 1); /* generated: period, frames, rate, channels, format */
                    put8(&b, period - 1u);
                    put16(&b, 3000u);
                    put8(&b, (uint32_t)variant);
                    put8(&b, 0);
                    put8(&b, 1);
                    for (i = 0; i < period; i++) { /* one period of a sawtooth */
                        put16(&b, (i * 60000u / period) - 30000u);
                    }
                }
                put16(&b, 0);
            } else if (variant == 3) {
                put8(&b, 0); /* raw PNG bytes */
                put16(&b, (uint32_t)png8->n);
                put(&b, png8->p, png8->n);
                cli_png(&b, 8, 8, 0, 200);
            } else {
                cli_png(&b, 40, 36, variant == 1, 256);
                cli_png(&b, 16 + (uint32_t)variant * 8u, 16, variant == 1, 256);
            }
            save("cli", k++, &b);
            free(b.p);
        }
    }
    return k;
}

static void seeds_blobs(const char *target, int count)
{
    int k;
    for (k = 0; k < count; k++) {
        buf_t b = {0};
        size_t n = 32u + (size_t)(rnd() % 1024u), i;
        for (i = 0; i < n; i++) {
            put8(&b, rnd());
        }
        save(target, k, &b);
        free(b.p);
    }
}

int main(int argc, char **argv)
{
    buf_t png8 = {0}, wav16 = {0};
    if (argc != 2) {
        fprintf(stderr, "usage: fuzz_seeds OUTDIR\n");
        return 2;
    }
    g_out = argv[1];
    mkdir(g_out, 0777);
    seeds_png(0);
    make_png(&png8, 12, 10, PNG_COLOR_TYPE_GRAY, 8, 0, 0);
    seeds_wav(0, &wav16);
    seeds_cli(0, &png8, &wav16);
    seeds_blobs("match", 24);
    seeds_blobs("track", 24);
    seeds_blobs("pitch", 24);
    seeds_blobs("stream", 24);
    free(png8.p);
    free(wav16.p);
    return 0;
}
