/*
 * gen_register.c - inputs for the `ssda register` CLI tests:
 *   gen_register DIR
 * writes into DIR:
 *   ref.png      320 x 240 8-bit smooth random texture
 *   mov.png      ref seen through a known 2nd-order map (shift, rotation,
 *                scale and a bow), sampled bicubically from the same field
 *   ref16.png, mov16.png  ref and mov as 16-bit (12-bit counts x 16)
 *   inv.png      mov with inverted contrast
 *   flat.png     a constant image of ref's size
 *   tiny.png     16 x 12
 *   truth.txt    the map, pixel units: two lines of 6 coefficients (x, y),
 *                terms 1, X, Y, X^2, XY, Y^2 (REF pixel -> MOV pixel)
 * Its own PNG writer (libpng) and sampler: nothing from the library.
 */
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define PAD 12

static double field[H + 2 * PAD][W + 2 * PAD];

static unsigned xs(unsigned *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static void make_field(void)
{
    static double tmp[H + 2 * PAD][W + 2 * PAD];
    unsigned s = 2024;
    int x, y, k, pass;
    for (y = 0; y < H + 2 * PAD; y++)
        for (x = 0; x < W + 2 * PAD; x++) field[y][x] = xs(&s) / 4294967296.0;
    for (pass = 0; pass < 3; pass++) {
        for (y = 0; y < H + 2 * PAD; y++)
            for (x = 0; x < W + 2 * PAD; x++) {
                double a = 0;
                for (k = -3; k <= 3; k++) {
                    int xx = x + k < 0 ? 0 : (x + k >= W + 2 * PAD ? W + 2 * PAD - 1 : x + k);
                    a += field[y][xx];
                }
                tmp[y][x] = a / 7;
            }
        for (y = 0; y < H + 2 * PAD; y++)
            for (x = 0; x < W + 2 * PAD; x++) {
                double a = 0;
                for (k = -3; k <= 3; k++) {
                    int yy = y + k < 0 ? 0 : (y + k >= H + 2 * PAD ? H + 2 * PAD - 1 : y + k);
                    a += tmp[yy][x];
                }
                field[y][x] = a / 7;
            }
    }
}

static double cubic(double p0, double p1, double p2, double p3, double t)
{
    return p1 + 0.5 * t * (p2 - p0 + t * (2 * p0 - 5 * p1 + 4 * p2 - p3 + t * (3 * (p1 - p2) + p3 - p0)));
}

/* the texture at (x, y), grey 0..255 (clamped into the padded field) */
static double tex(double x, double y)
{
    double col[4], v;
    int ix, iy, j;
    x += PAD;
    y += PAD;
    x = x < 1 ? 1 : (x > W + 2 * PAD - 3 ? W + 2 * PAD - 3 : x);
    y = y < 1 ? 1 : (y > H + 2 * PAD - 3 ? H + 2 * PAD - 3 : y);
    ix = (int)x;
    iy = (int)y;
    for (j = 0; j < 4; j++) {
        const double *r = field[iy - 1 + j];
        col[j] = cubic(r[ix - 1], r[ix], r[ix + 1], r[ix + 2], x - ix);
    }
    v = 128 + (cubic(col[0], col[1], col[2], col[3], y - iy) - 0.5) * 1400;
    return v < 0 ? 0 : (v > 255 ? 255 : v);
}

/* The map REF -> MOV, pixel units. */
static const double cxs[6] = {7.3, 1.004, -0.0087, 2.0e-5, -1.0e-5, 1.5e-5};
static const double cys[6] = {-4.6, 0.0087, 1.004, -1.2e-5, 2.2e-5, 0.5e-5};

static void map(double X, double Y, double *x, double *y)
{
    *x = cxs[0] + cxs[1] * X + cxs[2] * Y + cxs[3] * X * X + cxs[4] * X * Y + cxs[5] * Y * Y;
    *y = cys[0] + cys[1] * X + cys[2] * Y + cys[3] * X * X + cys[4] * X * Y + cys[5] * Y * Y;
}

static int write_png(const char *dir, const char *name, int w, int h, int bits, const unsigned *px)
{
    char path[4096];
    FILE *f;
    png_structp png;
    png_infop info;
    unsigned char *row = malloc((size_t)w * 2);
    int x, y;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    if (f == NULL || png == NULL || info == NULL || row == NULL || setjmp(png_jmpbuf(png))) {
        fprintf(stderr, "gen_register: cannot write %s\n", path);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, bits, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            unsigned v = px[(size_t)y * w + x];
            if (bits == 16) {
                row[2 * x] = (unsigned char)(v >> 8);
                row[2 * x + 1] = (unsigned char)v;
            } else {
                row[x] = (unsigned char)v;
            }
        }
        png_write_row(png, row);
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    fclose(f);
    free(row);
    return 0;
}

int main(int argc, char **argv)
{
    static unsigned ref[W * H], ref16[W * H], mov[W * H], mov16[W * H], inv[W * H], flat[W * H], tiny[16 * 12];
    char path[4096];
    FILE *t;
    int x, y, k;
    if (argc != 2) {
        fprintf(stderr, "usage: gen_register DIR\n");
        return 2;
    }
    make_field();
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            /* MOV(x, y) holds the texture of the REF point mapping there:
               invert the map by fixed-point iteration (near the identity) */
            double X = x, Y = y, u, v;
            int it;
            for (it = 0; it < 30; it++) {
                map(X, Y, &u, &v);
                X -= u - x;
                Y -= v - y;
            }
            ref[y * W + x] = (unsigned)lround(tex(x, y));
            ref16[y * W + x] = (unsigned)lround(tex(x, y) * 16.0);
            mov[y * W + x] = (unsigned)lround(tex(X, Y));
            mov16[y * W + x] = (unsigned)lround(tex(X, Y) * 16.0);
            inv[y * W + x] = 255u - mov[y * W + x];
            flat[y * W + x] = 90;
        }
    }
    for (k = 0; k < 16 * 12; k++) tiny[k] = (unsigned)(k * 7 % 256);
    if (write_png(argv[1], "ref.png", W, H, 8, ref) || write_png(argv[1], "mov.png", W, H, 8, mov) ||
        write_png(argv[1], "mov16.png", W, H, 16, mov16) || write_png(argv[1], "ref16.png", W, H, 16, ref16) || write_png(argv[1], "inv.png", W, H, 8, inv) ||
        write_png(argv[1], "flat.png", W, H, 8, flat) || write_png(argv[1], "tiny.png", 16, 12, 8, tiny)) {
        return 1;
    }
    snprintf(path, sizeof path, "%s/truth.txt", argv[1]);
    t = fopen(path, "w");
    if (t == NULL) {
        return 1;
    }
    for (k = 0; k < 6; k++) fprintf(t, "%.10g%c", cxs[k], k == 5 ? '\n' : ' ');
    for (k = 0; k < 6; k++) fprintf(t, "%.10g%c", cys[k], k == 5 ? '\n' : ' ');
    fclose(t);
    return 0;
}
