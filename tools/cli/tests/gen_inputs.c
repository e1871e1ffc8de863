/*
 * gen_inputs.c - makes the CLI tests' input files (no external data):
 *   texture OUT.png [--size WxH] [--seed S] [--shift DX,DY] [--kind K] [--max V]
 *       a smooth deterministic random texture; with --shift the same texture
 *       moved by (DX, DY): OUT(x, y) = T(x - DX, y - DY), the motion from an
 *       unshifted image to this one. Kinds: gray8 (default), gray16, gray1,
 *       gray4, ga8, rgb8, rgba8, rgb16, palette, interlaced. Colour kinds
 *       store R = G = B, so their gray is the same texture.
 *       --max V scales 16-bit samples to 0..V (e.g. 4095 for 12-bit counts).
 *       --fill V,X0,Y0,X1,Y1 sets a rectangle to V (fill pixels).
 *   kinds DIR: one 23 x 17 image per PNG kind (gray 1/2/4/8/16, gray+alpha,
 *       RGB 8/16, RGBA, palette with and without tRNS, interlaced) plus, for
 *       each, NAME.expect.png: the 8- or 16-bit gray the documented
 *       conversion must give, computed here independently.
 *   crop IN.png OUT.png X,Y,W,H: a gray8/16 crop.
 *   wav OUT.wav [--f0 HZ | --glide HZ0:HZ1] [--rate R] [--secs S] [--silence S]
 *       [--channels C] [--format pcm16|pcm24|float] [--jump HZ:S] [--gain G]: a
 *       voiced harmonic signal (peak about 0.6 x G of full scale); with
 *       --silence S, that many seconds of silence first; with --jump, its last
 *       S seconds at HZ (frames off the plot's range).
 *   bad KIND OUT: malformed inputs: empty, text, truncated (a PNG cut inside
 *       its data), crc (IDAT checksum wrong), huge (IHDR 70000 x 8),
 *       toomuch (IHDR 40000 x 40000 16-bit RGBA), wav-empty, wav-text,
 *       wav-header (a RIFF header with no format chunk).
 * Exit status 0, or 2 with a message on a bad command line.
 */
#include <math.h>
#include <png.h>
#include <sndfile.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#define PI 3.14159265358979323846

static int die(const char *msg, const char *arg)
{
    fprintf(stderr, "gen_inputs: %s%s%s\n", msg, arg ? " " : "", arg ? arg : "");
    exit(2);
}

/* ---- texture: value noise on two lattices, bilinear, deterministic ---- */

static uint32_t hash3(int32_t x, int32_t y, uint32_t seed)
{
    uint32_t h = (uint32_t)x * 0x8da6b343u ^ (uint32_t)y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h;
}

static double lattice(int32_t x, int32_t y, uint32_t seed)
{
    return (hash3(x, y, seed) & 0xffffu) / 65535.0;
}

static int32_t floordiv(int32_t a, int32_t b)
{
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/* Noise of cell size c at integer (x, y): exact bilinear interpolation. */
static double noise(int32_t x, int32_t y, int32_t c, uint32_t seed)
{
    int32_t gx = floordiv(x, c), gy = floordiv(y, c);
    double fx = (double)(x - gx * c) / c, fy = (double)(y - gy * c) / c;
    double a = lattice(gx, gy, seed), b = lattice(gx + 1, gy, seed);
    double d = lattice(gx, gy + 1, seed), e = lattice(gx + 1, gy + 1, seed);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (d * (1 - fx) + e * fx) * fy;
}

/* Texture value in 0..1 at integer coordinates. */
static double texture(int32_t x, int32_t y, uint32_t seed)
{
    double v = 0.55 * noise(x, y, 8, seed) + 0.30 * noise(x, y, 3, seed + 1u) +
               0.15 * noise(x, y, 1, seed + 2u);
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

/* Write rows (already in PNG byte layout) with libpng. */
static void write_png(const char *path, uint32_t w, uint32_t h, int bit_depth, int color_type,
                      int interlace, png_bytep *rows, png_colorp palette, int npal,
                      png_bytep trans, int ntrans)
{
    FILE *f = fopen(path, "wb");
    png_structp png;
    png_infop info;
    if (f == NULL) {
        die("cannot create", path);
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        die("libpng failed writing", path);
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, bit_depth, color_type,
                 interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (palette != NULL) {
        png_set_PLTE(png, info, palette, npal);
    }
    if (trans != NULL) {
        png_set_tRNS(png, info, trans, ntrans, NULL);
    }
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

/* rows of w * channels samples of bit_depth (8 or 16) from a value callback */
static png_bytep *alloc_rows(uint32_t w, uint32_t h, int bytes_per_pixel)
{
    png_bytep *rows = calloc(h, sizeof *rows);
    uint32_t y;
    for (y = 0; y < h; y++) {
        rows[y] = calloc((size_t)w * (size_t)bytes_per_pixel + 1u, 1);
    }
    return rows;
}

static void free_rows(png_bytep *rows, uint32_t h)
{
    uint32_t y;
    for (y = 0; y < h; y++) {
        free(rows[y]);
    }
    free(rows);
}

static void put16(png_bytep p, uint32_t v)
{
    p[0] = (png_byte)(v >> 8);
    p[1] = (png_byte)(v & 0xffu);
}

static int cmd_texture(int argc, char **argv)
{
    const char *out = NULL, *kind = "gray8";
    uint32_t w = 96, h = 96, seed = 1, maxv = 65535, x, y;
    int32_t dx = 0, dy = 0;
    int fill = 0;
    uint32_t fv = 0, fx0 = 0, fy0 = 0, fx1 = 0, fy1 = 0;
    int i, bpp, depth, ctype, interlace = 0;
    png_bytep *rows;
    png_color pal[256];
    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
            if (sscanf(argv[++i], "%ux%u", &w, &h) != 2) die("bad --size", argv[i]);
        } else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
            seed = (uint32_t)strtoul(argv[++i], NULL, 10);
        } else if (strcmp(argv[i], "--shift") == 0 && i + 1 < argc) {
            if (sscanf(argv[++i], "%d,%d", &dx, &dy) != 2) die("bad --shift", argv[i]);
        } else if (strcmp(argv[i], "--kind") == 0 && i + 1 < argc) {
            kind = argv[++i];
        } else if (strcmp(argv[i], "--max") == 0 && i + 1 < argc) {
            maxv = (uint32_t)strtoul(argv[++i], NULL, 10);
        } else if (strcmp(argv[i], "--fill") == 0 && i + 1 < argc) {
            if (sscanf(argv[++i], "%u,%u,%u,%u,%u", &fv, &fx0, &fy0, &fx1, &fy1) != 5)
                die("bad --fill", argv[i]);
            fill = 1;
        } else if (out == NULL && argv[i][0] != '-') {
            out = argv[i];
        } else {
            die("texture: bad argument", argv[i]);
        }
    }
    if (out == NULL) die("texture: need OUT.png", NULL);
    if (strcmp(kind, "gray8") == 0) { depth = 8; ctype = PNG_COLOR_TYPE_GRAY; bpp = 1; }
    else if (strcmp(kind, "gray16") == 0) { depth = 16; ctype = PNG_COLOR_TYPE_GRAY; bpp = 2; }
    else if (strcmp(kind, "rgb8") == 0) { depth = 8; ctype = PNG_COLOR_TYPE_RGB; bpp = 3; }
    else if (strcmp(kind, "rgba8") == 0) { depth = 8; ctype = PNG_COLOR_TYPE_RGBA; bpp = 4; }
    else if (strcmp(kind, "ga8") == 0) { depth = 8; ctype = PNG_COLOR_TYPE_GRAY_ALPHA; bpp = 2; }
    else if (strcmp(kind, "rgb16") == 0) { depth = 16; ctype = PNG_COLOR_TYPE_RGB; bpp = 6; }
    else if (strcmp(kind, "palette") == 0) { depth = 8; ctype = PNG_COLOR_TYPE_PALETTE; bpp = 1; }
    else if (strcmp(kind, "interlaced") == 0) { depth = 8; ctype = PNG_COLOR_TYPE_GRAY; bpp = 1; interlace = 1; }
    else return die("texture: unknown --kind", kind);
    rows = alloc_rows(w, h, bpp);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            double t = texture((int32_t)x - dx, (int32_t)y - dy, seed);
            uint32_t v8 = (uint32_t)lround(t * 255.0), v16 = (uint32_t)lround(t * maxv), c;
            png_bytep p = rows[y] + (size_t)x * (size_t)bpp;
            if (fill && x >= fx0 && x <= fx1 && y >= fy0 && y <= fy1) {
                v8 = v16 = fv;
            }
            if (depth == 16) {
                for (c = 0; c < (uint32_t)bpp / 2u; c++) put16(p + 2 * c, v16);
            } else {
                for (c = 0; c < (uint32_t)bpp; c++) p[c] = (png_byte)v8;
                if (ctype == PNG_COLOR_TYPE_RGBA || ctype == PNG_COLOR_TYPE_GRAY_ALPHA)
                    p[bpp - 1] = (png_byte)(x * 7u); /* alpha must be ignored */
            }
        }
    }
    for (i = 0; i < 256; i++) {
        pal[i].red = pal[i].green = pal[i].blue = (png_byte)i;
    }
    write_png(out, w, h, depth, ctype, interlace, rows,
              ctype == PNG_COLOR_TYPE_PALETTE ? pal : NULL, 256, NULL, 0);
    free_rows(rows, h);
    return 0;
}

/* ---- every PNG kind, with the expected gray ---- */

static uint32_t luma(uint32_t r, uint32_t g, uint32_t b)
{
    /* Rec. 601 weights, rounded to nearest; computed in floating point here
       (the tool uses integers): values differ only if the exact product sits
       on .5, which the +500 rounding of the tool resolves upward as here */
    return (uint32_t)floor((0.299 * r + 0.587 * g + 0.114 * b) + 0.5 + 1e-9);
}

static void write_expect(const char *dir, const char *name, uint32_t w, uint32_t h, int bits,
                         const uint32_t *v)
{
    char path[1024];
    png_bytep *rows = alloc_rows(w, h, bits / 8);
    uint32_t x, y;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            if (bits == 16) put16(rows[y] + 2 * x, v[y * w + x]);
            else rows[y][x] = (png_byte)v[y * w + x];
        }
    }
    snprintf(path, sizeof path, "%s/%s.expect.png", dir, name);
    write_png(path, w, h, bits, PNG_COLOR_TYPE_GRAY, 0, rows, NULL, 0, NULL, 0);
    free_rows(rows, h);
}

/* kinds: every image is W_K x H_K; expect receives the gray each pixel
   must read as, computed here independently. */
#define W_K 23u
#define H_K 17u
#define PIX(x, y, k) (hash3((int32_t)(x), (int32_t)(y), 77u + (uint32_t)(k)))

/* gray at 1, 2, 4, 8 bits: scaled to 0..255 (v * 255 / (2^bits - 1)), and 16 */
static void kinds_gray(const char *dir, uint32_t *expect)
{
    char path[1024];
    uint32_t x, y;
    int bits;
    for (bits = 1; bits <= 16; bits *= 2) {
        uint32_t maxv = (1u << bits) - 1u;
        png_bytep *rows = alloc_rows(W_K, H_K, 2);
        for (y = 0; y < H_K; y++) {
            for (x = 0; x < W_K; x++) {
                uint32_t v = PIX(x, y, bits) & maxv;
                if (bits == 16) {
                    put16(rows[y] + 2 * x, v);
                    expect[y * W_K + x] = v;
                } else {
                    uint32_t per = 8u / (uint32_t)bits, slot = x % per;
                    rows[y][x / per] |= (png_byte)(v << (8u - (uint32_t)bits * (slot + 1u)));
                    expect[y * W_K + x] = v * 255u / maxv;
                }
            }
        }
        snprintf(path, sizeof path, "%s/gray%d.png", dir, bits);
        write_png(path, W_K, H_K, bits, PNG_COLOR_TYPE_GRAY, 0, rows, NULL, 0, NULL, 0);
        snprintf(path, sizeof path, "gray%d", bits);
        write_expect(dir, path, W_K, H_K, bits == 16 ? 16 : 8, expect);
        free_rows(rows, H_K);
    }
}

/* gray + alpha, 8-bit: alpha ignored */
static void kinds_gray_alpha(const char *dir, uint32_t *expect)
{
    char path[1024];
    uint32_t x, y;
    png_bytep *rows = alloc_rows(W_K, H_K, 2);
    for (y = 0; y < H_K; y++) for (x = 0; x < W_K; x++) {
        rows[y][2 * x] = (png_byte)PIX(x, y, 20);
        rows[y][2 * x + 1] = (png_byte)(PIX(x, y, 21) & 0x0f); /* nearly transparent */
        expect[y * W_K + x] = rows[y][2 * x];
    }
    snprintf(path, sizeof path, "%s/ga8.png", dir);
    write_png(path, W_K, H_K, 8, PNG_COLOR_TYPE_GRAY_ALPHA, 0, rows, NULL, 0, NULL, 0);
    write_expect(dir, "ga8", W_K, H_K, 8, expect);
    free_rows(rows, H_K);
}

/* RGB 8 and RGBA 8 (alpha ignored), and interlaced RGB 8: luma */
static void kinds_rgb8(const char *dir, uint32_t *expect)
{
    static const char *names[3] = {"rgb8", "rgba8", "interlaced"};
    char path[1024];
    uint32_t x, y;
    int i;
    for (i = 0; i < 3; i++) {
        int ch = i == 1 ? 4 : 3, k0 = i == 2 ? 60 : 30;
        png_bytep *rows = alloc_rows(W_K, H_K, ch);
        for (y = 0; y < H_K; y++) for (x = 0; x < W_K; x++) {
            png_bytep p = rows[y] + (size_t)x * (size_t)ch;
            p[0] = (png_byte)PIX(x, y, k0);
            p[1] = (png_byte)PIX(x, y, k0 + 1);
            p[2] = (png_byte)PIX(x, y, k0 + 2);
            if (ch == 4) p[3] = (png_byte)PIX(x, y, 33);
            expect[y * W_K + x] = luma(p[0], p[1], p[2]);
        }
        snprintf(path, sizeof path, "%s/%s.png", dir, names[i]);
        write_png(path, W_K, H_K, 8, i == 1 ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, i == 2,
                  rows, NULL, 0, NULL, 0);
        write_expect(dir, names[i], W_K, H_K, 8, expect);
        free_rows(rows, H_K);
    }
}

/* RGB 16: luma in 16 bits */
static void kinds_rgb16(const char *dir, uint32_t *expect)
{
    char path[1024];
    uint32_t x, y;
    png_bytep *rows = alloc_rows(W_K, H_K, 6);
    for (y = 0; y < H_K; y++) for (x = 0; x < W_K; x++) {
        uint32_t r = PIX(x, y, 40) & 0xffffu, g = PIX(x, y, 41) & 0xffffu, b = PIX(x, y, 42) & 0xffffu;
        put16(rows[y] + 6 * x, r);
        put16(rows[y] + 6 * x + 2, g);
        put16(rows[y] + 6 * x + 4, b);
        expect[y * W_K + x] = luma(r, g, b);
    }
    snprintf(path, sizeof path, "%s/rgb16.png", dir);
    write_png(path, W_K, H_K, 16, PNG_COLOR_TYPE_RGB, 0, rows, NULL, 0, NULL, 0);
    write_expect(dir, "rgb16", W_K, H_K, 16, expect);
    free_rows(rows, H_K);
}

/* palette, 4-bit indices, with and without tRNS: the entries' luma */
static void kinds_palette(const char *dir, uint32_t *expect)
{
    char path[1024];
    png_color pal[16];
    png_byte trans[16];
    uint32_t x, y;
    int i;
    for (i = 0; i < 16; i++) {
        pal[i].red = (png_byte)(i * 17);
        pal[i].green = (png_byte)(255 - i * 13);
        pal[i].blue = (png_byte)(i * 5 + 40);
        trans[i] = (png_byte)(i * 16);
    }
    for (i = 0; i < 2; i++) {
        png_bytep *rows = alloc_rows(W_K, H_K, 1);
        for (y = 0; y < H_K; y++) for (x = 0; x < W_K; x++) {
            uint32_t k = PIX(x, y, 50) & 15u;
            rows[y][x / 2] |= (png_byte)(k << (x % 2 ? 0 : 4));
            expect[y * W_K + x] = luma(pal[k].red, pal[k].green, pal[k].blue);
        }
        snprintf(path, sizeof path, "%s/%s.png", dir, i ? "palette_trns" : "palette");
        write_png(path, W_K, H_K, 4, PNG_COLOR_TYPE_PALETTE, 0, rows, pal, 16, i ? trans : NULL, 16);
        write_expect(dir, i ? "palette_trns" : "palette", W_K, H_K, 8, expect);
        free_rows(rows, H_K);
    }
}

static int cmd_kinds(int argc, char **argv)
{
    uint32_t *expect = calloc(W_K * H_K, sizeof *expect);
    if (argc != 1) die("kinds: need DIR", NULL);
    kinds_gray(argv[0], expect);
    kinds_gray_alpha(argv[0], expect);
    kinds_rgb8(argv[0], expect);
    kinds_rgb16(argv[0], expect);
    kinds_palette(argv[0], expect);
    free(expect);
    return 0;
}

/* ---- crop ---- */

static int cmd_crop(int argc, char **argv)
{
    FILE *f;
    png_structp png;
    png_infop info;
    png_bytep *rows, *out;
    uint32_t x0, y0, cw, ch, y, w, h;
    int depth, ctype, bpp;
    if (argc != 3 || sscanf(argv[2], "%u,%u,%u,%u", &x0, &y0, &cw, &ch) != 4)
        die("crop: need IN.png OUT.png X,Y,W,H", NULL);
    f = fopen(argv[0], "rb");
    if (f == NULL) die("cannot open", argv[0]);
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) die("cannot read", argv[0]);
    png_init_io(png, f);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, NULL);
    w = png_get_image_width(png, info);
    h = png_get_image_height(png, info);
    depth = png_get_bit_depth(png, info);
    ctype = png_get_color_type(png, info);
    if (ctype != PNG_COLOR_TYPE_GRAY || depth < 8) die("crop: gray 8/16 only", argv[0]);
    if (x0 + cw > w || y0 + ch > h) die("crop: rectangle outside", argv[0]);
    bpp = depth / 8;
    rows = png_get_rows(png, info);
    out = alloc_rows(cw, ch, bpp);
    for (y = 0; y < ch; y++) {
        memcpy(out[y], rows[y0 + y] + (size_t)x0 * (size_t)bpp, (size_t)cw * (size_t)bpp);
    }
    write_png(argv[1], cw, ch, depth, PNG_COLOR_TYPE_GRAY, 0, out, NULL, 0, NULL, 0);
    free_rows(out, ch);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    return 0;
}

/* ---- sound ---- */

static int cmd_wav(int argc, char **argv)
{
    const char *out = NULL, *format = "pcm16";
    double f0a = 200.0, f0b = 200.0, secs = 1.0, silence = 0.0, phase = 0.0;
    double jf = 0.0, jsecs = 0.0; /* --jump F:SECS: the last SECS at f0 F (an outlier) */
    double gain = 1.0;            /* --gain G: amplitude factor (peak about 0.6 x G) */
    int rate = 16000, channels = 1, i, c;
    SF_INFO info;
    SNDFILE *sf;
    float *buf;
    sf_count_t n, k;
    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--f0") == 0 && i + 1 < argc) {
            f0a = f0b = atof(argv[++i]);
        } else if (strcmp(argv[i], "--glide") == 0 && i + 1 < argc) {
            if (sscanf(argv[++i], "%lf:%lf", &f0a, &f0b) != 2) die("bad --glide", argv[i]);
        } else if (strcmp(argv[i], "--jump") == 0 && i + 1 < argc) {
            if (sscanf(argv[++i], "%lf:%lf", &jf, &jsecs) != 2) die("bad --jump", argv[i]);
        } else if (strcmp(argv[i], "--rate") == 0 && i + 1 < argc) {
            rate = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--secs") == 0 && i + 1 < argc) {
            secs = atof(argv[++i]);
        } else if (strcmp(argv[i], "--silence") == 0 && i + 1 < argc) {
            silence = atof(argv[++i]);
        } else if (strcmp(argv[i], "--channels") == 0 && i + 1 < argc) {
            channels = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--gain") == 0 && i + 1 < argc) {
            gain = atof(argv[++i]);
        } else if (strcmp(argv[i], "--format") == 0 && i + 1 < argc) {
            format = argv[++i];
        } else if (out == NULL && argv[i][0] != '-') {
            out = argv[i];
        } else {
            die("wav: bad argument", argv[i]);
        }
    }
    if (out == NULL) die("wav: need OUT.wav", NULL);
    memset(&info, 0, sizeof info);
    info.samplerate = rate;
    info.channels = channels;
    info.format = SF_FORMAT_WAV | (strcmp(format, "pcm24") == 0   ? SF_FORMAT_PCM_24
                                   : strcmp(format, "float") == 0 ? SF_FORMAT_FLOAT
                                                                  : SF_FORMAT_PCM_16);
    n = (sf_count_t)((silence + secs) * rate);
    buf = calloc((size_t)n * (size_t)channels, sizeof *buf);
    for (k = 0; k < n; k++) {
        double t = (double)k / rate - silence, f, v = 0.0;
        int hmn;
        if (t < 0) continue;
        f = t >= secs - jsecs ? jf : f0a + (f0b - f0a) * t / secs;
        phase += 2 * PI * f / rate;
        for (hmn = 1; hmn <= 6; hmn++) { /* a voiced source: harmonics falling 1/h */
            v += sin(hmn * phase) / hmn;
        }
        for (c = 0; c < channels; c++) buf[k * channels + c] = (float)(0.35 * gain * v);
    }
    sf = sf_open(out, SFM_WRITE, &info);
    if (sf == NULL) die("cannot create", out);
    sf_writef_float(sf, buf, n);
    sf_close(sf);
    free(buf);
    return 0;
}

/* ---- malformed files ---- */

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24); p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8); p[3] = (unsigned char)v;
}

/* A PNG signature, an IHDR of w x h (valid CRC), an empty IDAT and IEND. */
static void write_header_only_png(const char *path, uint32_t w, uint32_t h, int depth, int ctype)
{
    unsigned char buf[64];
    FILE *f = fopen(path, "wb");
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    if (f == NULL) die("cannot create", path);
    fwrite(sig, 1, 8, f);
    put32(buf, 13);
    memcpy(buf + 4, "IHDR", 4);
    put32(buf + 8, w);
    put32(buf + 12, h);
    buf[16] = (unsigned char)depth;
    buf[17] = (unsigned char)ctype;
    buf[18] = buf[19] = buf[20] = 0;
    put32(buf + 21, (uint32_t)crc32(0, buf + 4, 17));
    fwrite(buf, 1, 25, f);
    put32(buf, 0); /* an empty IDAT: readers reach the pixel data before failing */
    memcpy(buf + 4, "IDAT", 4);
    put32(buf + 8, (uint32_t)crc32(0, buf + 4, 4));
    fwrite(buf, 1, 12, f);
    fwrite(iend, 1, 12, f);
    fclose(f);
}

/* A valid 64 x 64 texture PNG in memory (via a temp file). */
static unsigned char *valid_png(const char *tmp, size_t *len)
{
    char *args[] = {(char *)tmp, (char *)"--size", (char *)"64x64", (char *)"--seed", (char *)"9"};
    FILE *f;
    unsigned char *data;
    long n;
    cmd_texture(5, args);
    f = fopen(tmp, "rb");
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    data = malloc((size_t)n);
    if (fread(data, 1, (size_t)n, f) != (size_t)n) die("cannot read back", tmp);
    fclose(f);
    remove(tmp);
    *len = (size_t)n;
    return data;
}

static void write_bytes(const char *path, const void *p, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL) die("cannot create", path);
    fwrite(p, 1, n, f);
    fclose(f);
}

static int cmd_bad(int argc, char **argv)
{
    const char *kind, *out;
    char tmp[1100];
    if (argc != 2) die("bad: need KIND OUT", NULL);
    kind = argv[0];
    out = argv[1];
    snprintf(tmp, sizeof tmp, "%s.src.png", out);
    if (strcmp(kind, "empty") == 0 || strcmp(kind, "wav-empty") == 0) {
        write_bytes(out, "", 0);
    } else if (strcmp(kind, "text") == 0 || strcmp(kind, "wav-text") == 0) {
        const char *s = "this is not an image or a sound\n";
        write_bytes(out, s, strlen(s));
    } else if (strcmp(kind, "truncated") == 0) {
        size_t n;
        unsigned char *d = valid_png(tmp, &n);
        write_bytes(out, d, n / 2);
        free(d);
    } else if (strcmp(kind, "crc") == 0) {
        size_t n, i;
        unsigned char *d = valid_png(tmp, &n);
        for (i = 8; i + 8 < n; i++) { /* flip a byte inside the IDAT data */
            if (memcmp(d + i, "IDAT", 4) == 0) {
                d[i + 4 + 10] ^= 0x55u;
                break;
            }
        }
        write_bytes(out, d, n);
        free(d);
    } else if (strcmp(kind, "huge") == 0) {
        write_header_only_png(out, 70000u, 8u, 8, 0);
    } else if (strcmp(kind, "toomuch") == 0) {
        write_header_only_png(out, 40000u, 40000u, 16, 6);
    } else if (strcmp(kind, "wav-header") == 0) {
        static const unsigned char riff[12] = {'R', 'I', 'F', 'F', 4, 0, 0, 0, 'W', 'A', 'V', 'E'};
        write_bytes(out, riff, sizeof riff);
    } else {
        die("bad: unknown kind", kind);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) die("usage: gen_inputs texture|kinds|crop|wav|bad ...", NULL);
    if (strcmp(argv[1], "texture") == 0) return cmd_texture(argc - 2, argv + 2);
    if (strcmp(argv[1], "kinds") == 0) return cmd_kinds(argc - 2, argv + 2);
    if (strcmp(argv[1], "crop") == 0) return cmd_crop(argc - 2, argv + 2);
    if (strcmp(argv[1], "wav") == 0) return cmd_wav(argc - 2, argv + 2);
    if (strcmp(argv[1], "bad") == 0) return cmd_bad(argc - 2, argv + 2);
    return die("unknown command", argv[1]);
}
