/*
 * check_register.c - checks of `ssda register` outputs, read with other
 * libraries than the tool writes with (jansson for JSON, giflib's decoder,
 * libpng's reader):
 *   check_register map FILE.json TRUTH.txt MAXERR [INDEX]
 *       the JSON's coeffs_x/coeffs_y (registration INDEX of several) map a
 *       grid of REF points (10 %..90 % of the image) within MAXERR px of the
 *       truth; every point has ref_x, ref_y, mov_x, mov_y, rho, residual,
 *       used; rms <= MAXERR
 *   check_register png FILE W H CHANNELS BITS     the PNG's header
 *   check_register gif FILE FRAMES W H            an animated GIF, looping
 *   check_register same A.png B.png               identical pixels
 *   check_register aligned A.png B.png MAXMEAN    mean |A - B| over the inner
 *       80 % of the image (8-bit) at most MAXMEAN grey levels
 * Exit 0 when the check holds, 1 with a message when not.
 */
#include <gif_lib.h>
#include <jansson.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(const char *fmt, const char *a, double v)
{
    fprintf(stderr, "check_register: ");
    fprintf(stderr, fmt, a, v);
    fprintf(stderr, "\n");
    return 1;
}

typedef struct {
    unsigned w, h, channels, bits;
    unsigned char **rows;
} png_img_t;

static int read_png(const char *path, png_img_t *img)
{
    FILE *f = fopen(path, "rb");
    png_structp png;
    png_infop info;
    unsigned y;
    if (f == NULL) {
        return -1;
    }
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    img->w = png_get_image_width(png, info);
    img->h = png_get_image_height(png, info);
    img->channels = png_get_channels(png, info);
    img->bits = png_get_bit_depth(png, info);
    img->rows = malloc(img->h * sizeof *img->rows);
    for (y = 0; y < img->h; y++) {
        img->rows[y] = malloc(png_get_rowbytes(png, info));
    }
    png_read_image(png, img->rows);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    return 0;
}

static void free_png(png_img_t *img)
{
    unsigned y;
    for (y = 0; y < img->h; y++) {
        free(img->rows[y]);
    }
    free(img->rows);
    img->rows = NULL;
}

static double poly(const json_t *c, double X, double Y)
{
    static const int ex[10] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0}, ey[10] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3};
    double s = 0;
    size_t t;
    for (t = 0; t < json_array_size(c) && t < 10; t++) {
        s += json_number_value(json_array_get(c, t)) * pow(X, ex[t]) * pow(Y, ey[t]);
    }
    return s;
}

static int check_map(int argc, char **argv)
{
    json_error_t e;
    json_t *doc = json_load_file(argv[2], 0, &e), *reg, *pts, *cx, *cy;
    double tx[6], ty[6], maxerr = atof(argv[4]), worst = 0, w, h;
    FILE *t = fopen(argv[3], "r");
    size_t k;
    int i, j;
    if (doc == NULL) {
        return fail("%s: not JSON (%g)", argv[2], e.line);
    }
    if (t == NULL) {
        return fail("%s: no truth%g", argv[3], 0);
    }
    for (i = 0; i < 6; i++) {
        if (fscanf(t, "%lf", &tx[i]) != 1) return fail("%s: bad truth%g", argv[3], 0);
    }
    for (i = 0; i < 6; i++) {
        if (fscanf(t, "%lf", &ty[i]) != 1) return fail("%s: bad truth%g", argv[3], 0);
    }
    fclose(t);
    reg = doc;
    if (json_object_get(doc, "registrations") != NULL) {
        reg = json_array_get(json_object_get(doc, "registrations"), argc > 5 ? (size_t)atoi(argv[5]) : 0);
    }
    pts = json_object_get(reg, "points");
    cx = json_object_get(reg, "coeffs_x");
    cy = json_object_get(reg, "coeffs_y");
    if (!json_is_array(pts) || !json_is_array(cx) || !json_is_array(cy) ||
        !json_is_integer(json_object_get(reg, "order")) || !json_is_number(json_object_get(reg, "rms"))) {
        return fail("%s: missing order, points, rms, coeffs_x or coeffs_y%g", argv[2], 0);
    }
    if (json_array_size(cx) != (size_t)((json_integer_value(json_object_get(reg, "order")) + 1) *
                                        (json_integer_value(json_object_get(reg, "order")) + 2) / 2)) {
        return fail("%s: coeffs_x has the wrong number of terms%g", argv[2], 0);
    }
    for (k = 0; k < json_array_size(pts); k++) {
        static const char *const keys[] = {"ref_x", "ref_y", "mov_x", "mov_y", "rho", "residual", "used"};
        json_t *p = json_array_get(pts, k);
        for (i = 0; i < 7; i++) {
            if (json_object_get(p, keys[i]) == NULL) {
                return fail("a point lacks %s%g", keys[i], 0);
            }
        }
    }
    if (json_number_value(json_object_get(reg, "rms")) > maxerr) {
        return fail("%s: rms %g too large", argv[2], json_number_value(json_object_get(reg, "rms")));
    }
    w = json_number_value(json_object_get(reg, "width"));
    h = json_number_value(json_object_get(reg, "height"));
    for (j = 0; j <= 8; j++) {
        for (i = 0; i <= 8; i++) {
            const double X = w * (0.1 + 0.1 * i), Y = h * (0.1 + 0.1 * j);
            const double x = tx[0] + tx[1] * X + tx[2] * Y + tx[3] * X * X + tx[4] * X * Y + tx[5] * Y * Y;
            const double y = ty[0] + ty[1] * X + ty[2] * Y + ty[3] * X * X + ty[4] * X * Y + ty[5] * Y * Y;
            const double d = hypot(poly(cx, X, Y) - x, poly(cy, X, Y) - y);
            worst = d > worst ? d : worst;
        }
    }
    json_decref(doc);
    if (worst > maxerr) {
        return fail("%s: the map is %g px off the truth", argv[2], worst);
    }
    printf("map within %.3f px of the truth\n", worst);
    return 0;
}

static int check_png(char **argv)
{
    png_img_t img;
    if (read_png(argv[2], &img) != 0) {
        return fail("%s: not a PNG%g", argv[2], 0);
    }
    free_png(&img);
    if (img.w != (unsigned)atoi(argv[3]) || img.h != (unsigned)atoi(argv[4]) ||
        img.channels != (unsigned)atoi(argv[5]) || img.bits != (unsigned)atoi(argv[6])) {
        fprintf(stderr, "check_register: %s is %ux%u, %u channels, %u bits\n", argv[2], img.w, img.h,
                img.channels, img.bits);
        return 1;
    }
    return 0;
}

static int check_gif(char **argv)
{
    int e = 0, k, loops = 0;
    GifFileType *g = DGifOpenFileName(argv[2], &e);
    if (g == NULL || DGifSlurp(g) != GIF_OK) {
        return fail("%s: not a GIF%g", argv[2], 0);
    }
    /* the NETSCAPE2.0 block: global, or saved with the first frame */
    for (k = 0; k < g->ExtensionBlockCount; k++) {
        if (g->ExtensionBlocks[k].Function == APPLICATION_EXT_FUNC_CODE) loops = 1;
    }
    for (k = 0; g->ImageCount > 0 && k < g->SavedImages[0].ExtensionBlockCount; k++) {
        if (g->SavedImages[0].ExtensionBlocks[k].Function == APPLICATION_EXT_FUNC_CODE) loops = 1;
    }
    if (g->ImageCount != atoi(argv[3]) || g->SWidth != atoi(argv[4]) || g->SHeight != atoi(argv[5]) || !loops) {
        fprintf(stderr, "check_register: %s: %d frames %dx%d, loop %d\n", argv[2], g->ImageCount, g->SWidth,
                g->SHeight, loops);
        return 1;
    }
    for (k = 0; k < g->ImageCount; k++) {
        GraphicsControlBlock gcb;
        if (DGifSavedExtensionToGCB(g, k, &gcb) != GIF_OK || gcb.DelayTime != 7) {
            DGifCloseFile(g, &e);
            return fail("%s: frame delay not 7 cs%g", argv[2], 0);
        }
    }
    DGifCloseFile(g, &e);
    return 0;
}

static int check_same(char **argv, int aligned)
{
    png_img_t a, b;
    unsigned x, y, bpp;
    double sum = 0;
    size_t n = 0;
    if (read_png(argv[2], &a) != 0 || read_png(argv[3], &b) != 0) {
        return fail("%s: cannot read the PNGs%g", argv[2], 0);
    }
    if (a.w != b.w || a.h != b.h || a.channels != b.channels || a.bits != b.bits) {
        return fail("%s: sizes differ%g", argv[2], 0);
    }
    bpp = a.channels * (a.bits / 8);
    for (y = 0; y < a.h; y++) {
        if (!aligned) {
            if (memcmp(a.rows[y], b.rows[y], (size_t)a.w * bpp) != 0) {
                free_png(&a);
                free_png(&b);
                return fail("%s: pixels differ from the other%g", argv[2], 0);
            }
            continue;
        }
        if (y < a.h / 10 || y >= a.h - a.h / 10) continue;
        for (x = a.w / 10; x < a.w - a.w / 10; x++) {
            sum += fabs((double)a.rows[y][x] - (double)b.rows[y][x]);
            n++;
        }
    }
    free_png(&a);
    free_png(&b);
    if (aligned && sum / (double)n > atof(argv[4])) {
        return fail("%s: mean |A - B| %g", argv[2], sum / (double)n);
    }
    if (aligned) printf("mean |A - B| %.2f\n", sum / (double)n);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 5 && strcmp(argv[1], "map") == 0) return check_map(argc, argv);
    if (argc == 7 && strcmp(argv[1], "png") == 0) return check_png(argv);
    if (argc == 6 && strcmp(argv[1], "gif") == 0) return check_gif(argv);
    if (argc == 4 && strcmp(argv[1], "same") == 0) return check_same(argv, 0);
    if (argc == 5 && strcmp(argv[1], "aligned") == 0) return check_same(argv, 1);
    fprintf(stderr, "usage: see the top of check_register.c\n");
    return 2;
}
