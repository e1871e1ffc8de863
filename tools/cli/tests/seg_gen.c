/*
 * seg_gen.c - inputs of the `ssda segment` tests, with known regions:
 *   scene KIND OUT.png TRUTH.png [--bits 8|16] [--nodata]
 *       a 120 x 90 RGB image of three regions (an ellipse, a band, the
 *       rest) and their labels 1..3 in TRUTH.png (0 where --nodata put a
 *       zero corner). KIND: brightness (three grays, dark to light: Z1
 *       separates them) or hue (reddish, neutral, bluish of equal
 *       brightness: Z2 separates them). Noise: sd 4 (8-bit scale).
 *   mixture OUT.png [WxH]: a 128 x 128 (W x H) gray image whose values are
 *       drawn from 0.3 N(50, 6) + 0.5 N(120, 10) + 0.2 N(200, 5).
 *   blank OUT.png: a 16 x 8 RGB image of zeros (all nodata with --nodata 0).
 * Exit status 0, or 2 on a bad command line.
 */
#include <math.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define W 120u
#define H 90u

static uint32_t g_state = 0x12345678u;

static double uniform(void)
{
    g_state ^= g_state << 13;
    g_state ^= g_state >> 17;
    g_state ^= g_state << 5;
    return ((double)g_state + 0.5) / 4294967296.0;
}

static double normal(void)
{
    return sqrt(-2.0 * log(uniform())) * cos(2.0 * PI * uniform());
}

static int die(const char *msg)
{
    fprintf(stderr, "seg_gen: %s\n", msg);
    exit(2);
}

static void write_png(const char *path, uint32_t w, uint32_t h, int bits, int color, uint8_t *data)
{
    FILE *f = fopen(path, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    const size_t rowbytes = (size_t)w * (color ? 3u : 1u) * (bits == 16 ? 2u : 1u);
    uint32_t y;
    if (f == NULL || png == NULL || info == NULL || setjmp(png_jmpbuf(png))) {
        die("cannot write a PNG");
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, bits, color ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < h; y++) {
        png_write_row(png, data + (size_t)y * rowbytes);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

/* Region of pixel (x, y): 1 inside the ellipse, 2 in the diagonal band, 3 else. */
static uint8_t region(uint32_t x, uint32_t y)
{
    const double ex = ((double)x - 40.0) / 28.0, ey = ((double)y - 45.0) / 22.0;
    if (ex * ex + ey * ey <= 1.0) {
        return 1;
    }
    return fabs((double)x - 1.2 * (double)y - 30.0) < 14.0 ? 2 : 3;
}

static void scene(const char *kind, const char *out, const char *truth, int bits, int nodata)
{
    static const double bright[3][3] = {{60, 60, 60}, {130, 130, 130}, {200, 200, 200}};
    static const double hue[3][3] = {{160, 115, 95}, {125, 125, 125}, {95, 125, 165}};
    const double(*c)[3] = strcmp(kind, "hue") == 0 ? hue : bright;
    uint8_t *img = malloc((size_t)W * H * 6u), *lab = malloc((size_t)W * H);
    uint32_t x, y, k;
    if (strcmp(kind, "hue") != 0 && strcmp(kind, "brightness") != 0) {
        die("scene KIND: brightness or hue");
    }
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            const size_t i = (size_t)y * W + x;
            const uint8_t r = region(x, y);
            const int zero = nodata && x + y < 20u;
            lab[i] = zero ? 0 : r;
            for (k = 0; k < 3; k++) {
                double v = zero ? 0.0 : c[r - 1][k] + 4.0 * normal();
                v = v < 1.0 && !zero ? 1.0 : v > 255.0 ? 255.0 : v;
                if (bits == 16) {
                    const uint32_t s = (uint32_t)lround(v * 257.0);
                    img[2 * (3 * i + k)] = (uint8_t)(s >> 8);
                    img[2 * (3 * i + k) + 1] = (uint8_t)(s & 0xffu);
                } else {
                    img[3 * i + k] = (uint8_t)lround(v);
                }
            }
        }
    }
    write_png(out, W, H, bits, 1, img);
    write_png(truth, W, H, 8, 0, lab);
    free(img);
    free(lab);
}

static void mixture(const char *out, uint32_t width, uint32_t height)
{
    static const double w[3] = {0.3, 0.5, 0.2}, m[3] = {50, 120, 200}, s[3] = {6, 10, 5};
    uint8_t *img = malloc((size_t)width * height);
    uint32_t i, j;
    if (img == NULL) {
        die("mixture: out of memory");
    }
    for (i = 0; i < width * height; i++) {
        const double u = uniform();
        double v;
        j = u < w[0] ? 0 : u < w[0] + w[1] ? 1 : 2;
        v = m[j] + s[j] * normal();
        img[i] = (uint8_t)(v < 0.0 ? 0.0 : v > 255.0 ? 255.0 : lround(v));
    }
    write_png(out, width, height, 8, 0, img);
    free(img);
}

int main(int argc, char **argv)
{
    if (argc >= 5 && strcmp(argv[1], "scene") == 0) {
        int bits = 8, nodata = 0, i;
        for (i = 5; i < argc; i++) {
            if (strcmp(argv[i], "--bits") == 0 && i + 1 < argc) {
                bits = atoi(argv[++i]);
            } else if (strcmp(argv[i], "--nodata") == 0) {
                nodata = 1;
            } else {
                die("scene: unknown option");
            }
        }
        scene(argv[2], argv[3], argv[4], bits == 16 ? 16 : 8, nodata);
    } else if ((argc == 3 || argc == 4) && strcmp(argv[1], "mixture") == 0) {
        unsigned w = 128u, h = 128u;
        if (argc == 4 && (sscanf(argv[3], "%ux%u", &w, &h) != 2 || w == 0u || h == 0u)) {
            die("mixture: size WxH");
        }
        mixture(argv[2], w, h);
    } else if (argc == 3 && strcmp(argv[1], "blank") == 0) {
        uint8_t img[16 * 8 * 3];
        memset(img, 0, sizeof img);
        write_png(argv[2], 16, 8, 8, 1, img);
    } else {
        die("usage: seg_gen scene KIND OUT TRUTH [--bits 16] [--nodata] | mixture OUT [WxH] | blank OUT");
    }
    return 0;
}
