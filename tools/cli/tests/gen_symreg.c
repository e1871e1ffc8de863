/*
 * gen_symreg.c - inputs and checks for the `ssda symreg` and `ssda shape`
 * CLI tests (symreg_test.sh):
 *   gen_symreg scene REF.png MOV.png [--angle DEG] [--scale S] [--gain G]
 *              [--shift X,Y] [--size N] [--seed N] [--flat]
 *       shapes on a textured ground; MOV drawn from the same geometry
 *       through the similarity REF -> MOV (about the centre, then shifted)
 *       with a brightness gain; prints the true affine "a b c d e f".
 *       --flat: no shapes at all (nothing to register).
 *   gen_symreg silhouette OUT.png [--angle DEG] [--scale S] [--size N] [--empty]
 *       a white star-like object on black, turned and scaled about its centre.
 *   gen_symreg check-affine OUT.json a b c d e f TOL
 *       the JSON has the documented fields, and its affine maps REF's
 *       corners (size from the JSON's pairs' frame: --size of scene) within
 *       TOL px of the true one; the size is the last argument.
 *   gen_symreg check-shape OUT.json S PHI_DEG TOL_S_REL TOL_PHI_DEG
 * Exit 0 when the check passes (or the file was written), 1 otherwise.
 */
#define _USE_MATH_DEFINES
#include <cjson/cJSON.h>
#include <math.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SHAPES 40

typedef struct {
    int kind;
    double cx, cy, a, b, c, s, grey;
} shape_t;

static shape_t g_sh[SHAPES];
static int g_nsh;

static uint32_t rng(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static double frand(uint32_t *s, double lo, double hi)
{
    return lo + (hi - lo) * (rng(s) / 4294967296.0);
}

static int write_gray(const char *path, const uint8_t *px, uint32_t w, uint32_t h)
{
    FILE *f = fopen(path, "wb");
    png_structp png;
    png_infop info;
    uint32_t y;
    if (f == NULL) {
        return 1;
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        fclose(f);
        return 1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < h; y++) {
        png_write_row(png, (png_const_bytep)(px + (size_t)y * w));
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return fclose(f) != 0;
}

static double ground(double x, double y)
{
    return 90.0 + 10.0 * sin(x * 0.11 + y * 0.04) + 8.0 * cos(y * 0.13 - x * 0.05);
}

static double value_at(double x, double y)
{
    double v = ground(x, y);
    int i;
    for (i = 0; i < g_nsh; i++) {
        const shape_t *s = &g_sh[i];
        const double dx = x - s->cx, dy = y - s->cy;
        const double u = s->c * dx + s->s * dy, w = -s->s * dx + s->c * dy;
        if (s->kind == 0 ? (fabs(u) < s->a && fabs(w) < s->b)
                         : (u * u / (s->a * s->a) + w * w / (s->b * s->b) < 1.0)) {
            v = s->grey;
        }
    }
    return v;
}

static void render(uint8_t *img, uint32_t n, const double Ainv[6], double gain)
{
    uint32_t x, y;
    int i, j;
    for (y = 0; y < n; y++) {
        for (x = 0; x < n; x++) {
            double acc = 0.0, v;
            for (j = -1; j <= 1; j++) {
                for (i = -1; i <= 1; i++) {
                    const double u = x + i / 3.0, w = y + j / 3.0;
                    acc += value_at(Ainv[0] * u + Ainv[1] * w + Ainv[2],
                                    Ainv[3] * u + Ainv[4] * w + Ainv[5]);
                }
            }
            v = gain * acc / 9.0;
            img[(size_t)y * n + x] = (uint8_t)(v > 255.0 ? 255.0 : v + 0.5);
        }
    }
}

static int cmd_scene(int argc, char **argv)
{
    double deg = 0, scale = 1, gain = 1, tx = 0, ty = 0, A[6], Ainv[6], c, s, h;
    uint32_t n = 256, seed = 7;
    int i, flat = 0;
    uint8_t *ref, *mov;
    for (i = 4; i < argc; i++) {
        if (!strcmp(argv[i], "--angle") && i + 1 < argc) {
            deg = atof(argv[++i]);
        } else if (!strcmp(argv[i], "--scale") && i + 1 < argc) {
            scale = atof(argv[++i]);
        } else if (!strcmp(argv[i], "--gain") && i + 1 < argc) {
            gain = atof(argv[++i]);
        } else if (!strcmp(argv[i], "--shift") && i + 1 < argc) {
            if (sscanf(argv[++i], "%lf,%lf", &tx, &ty) != 2) {
                return 1;
            }
        } else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            n = (uint32_t)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--seed") && i + 1 < argc) {
            seed = (uint32_t)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--flat")) {
            flat = 1;
        } else {
            fprintf(stderr, "gen_symreg scene: bad argument '%s'\n", argv[i]);
            return 1;
        }
    }
    g_nsh = flat ? 0 : SHAPES * (int)(n * n) / (256 * 256);
    g_nsh = g_nsh > SHAPES ? SHAPES : g_nsh;
    for (i = 0; i < g_nsh; i++) {
        const double ang = frand(&seed, 0, M_PI);
        g_sh[i].kind = (int)(rng(&seed) & 1u);
        g_sh[i].cx = frand(&seed, 14, n - 14.0);
        g_sh[i].cy = frand(&seed, 14, n - 14.0);
        g_sh[i].a = frand(&seed, 5, 10);
        g_sh[i].b = frand(&seed, 4, 9);
        g_sh[i].c = cos(ang);
        g_sh[i].s = sin(ang);
        g_sh[i].grey = frand(&seed, 150, 220);
    }
    c = cos(deg * M_PI / 180.0);
    s = sin(deg * M_PI / 180.0);
    h = n / 2.0;
    /* REF -> MOV: turn by deg (+x towards +y) and scale about the centre, shift */
    A[0] = scale * c;
    A[1] = -scale * s;
    A[3] = scale * s;
    A[4] = scale * c;
    A[2] = h + tx - (A[0] * h + A[1] * h);
    A[5] = h + ty - (A[3] * h + A[4] * h);
    Ainv[0] = c / scale;
    Ainv[1] = s / scale;
    Ainv[3] = -s / scale;
    Ainv[4] = c / scale;
    Ainv[2] = -(Ainv[0] * A[2] + Ainv[1] * A[5]);
    Ainv[5] = -(Ainv[3] * A[2] + Ainv[4] * A[5]);
    ref = malloc((size_t)n * n);
    mov = malloc((size_t)n * n);
    {
        const double id[6] = {1, 0, 0, 0, 1, 0};
        render(ref, n, id, 1.0);
    }
    render(mov, n, Ainv, gain);
    if (write_gray(argv[2], ref, n, n) || write_gray(argv[3], mov, n, n)) {
        return 1;
    }
    free(ref);
    free(mov);
    printf("%.9f %.9f %.6f %.9f %.9f %.6f\n", A[0], A[1], A[2], A[3], A[4], A[5]);
    return 0;
}

static int cmd_silhouette(int argc, char **argv)
{
    double deg = 0, scale = 1;
    uint32_t n = 200, x, y;
    int i, empty = 0;
    uint8_t *img;
    for (i = 3; i < argc; i++) {
        if (!strcmp(argv[i], "--angle") && i + 1 < argc) {
            deg = atof(argv[++i]);
        } else if (!strcmp(argv[i], "--scale") && i + 1 < argc) {
            scale = atof(argv[++i]);
        } else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            n = (uint32_t)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--empty")) {
            empty = 1;
        } else {
            return 1;
        }
    }
    img = calloc((size_t)n * n, 1);
    for (y = 0; y < n && !empty; y++) {
        for (x = 0; x < n; x++) {
            /* supersampled star: r(t) = 28 (1 + 0.3 cos 3t + 0.1 sin 5t) */
            int hits = 0, i2, j2;
            for (j2 = 0; j2 < 4; j2++) {
                for (i2 = 0; i2 < 4; i2++) {
                    const double px = x + (i2 + 0.5) / 4.0 - n / 2.0;
                    const double py = y + (j2 + 0.5) / 4.0 - n / 2.0;
                    const double ca = cos(-deg * M_PI / 180.0), sa = sin(-deg * M_PI / 180.0);
                    const double u = (ca * px - sa * py) / scale, v = (sa * px + ca * py) / scale;
                    const double t = atan2(v, u), r = sqrt(u * u + v * v);
                    hits += r < 28.0 * (1.0 + 0.3 * cos(3 * t) + 0.1 * sin(5 * t + 0.4));
                }
            }
            img[(size_t)y * n + x] = (uint8_t)(hits >= 8 ? 255 : 0);
        }
    }
    i = write_gray(argv[2], img, n, n);
    free(img);
    return i;
}

static cJSON *load_json(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long len;
    cJSON *j;
    if (f == NULL) {
        return NULL;
    }
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = calloc((size_t)len + 1, 1);
    if (fread(buf, 1, (size_t)len, f) != (size_t)len) {
        len = -1;
    }
    fclose(f);
    j = len < 0 ? NULL : cJSON_Parse(buf);
    free(buf);
    return j;
}

static int check_affine(int argc, char **argv)
{
    cJSON *j, *af, *pairs, *p;
    double T[6], A[6], tol, worst = 0;
    int i, n;
    if (argc < 11) {
        return 1;
    }
    for (i = 0; i < 6; i++) {
        T[i] = atof(argv[3 + i]);
    }
    tol = atof(argv[9]);
    n = atoi(argv[10]);
    if ((j = load_json(argv[2])) == NULL) {
        fprintf(stderr, "check-affine: cannot parse '%s'\n", argv[2]);
        return 1;
    }
    af = cJSON_GetObjectItem(j, "affine");
    pairs = cJSON_GetObjectItem(j, "pairs");
    if (!cJSON_IsArray(af) || cJSON_GetArraySize(af) != 6 || !cJSON_IsArray(pairs) ||
        cJSON_GetArraySize(pairs) < 3 || !cJSON_IsNumber(cJSON_GetObjectItem(j, "loops_ref")) ||
        !cJSON_IsNumber(cJSON_GetObjectItem(j, "loops_mov")) ||
        !cJSON_IsNumber(cJSON_GetObjectItem(j, "rms"))) {
        fprintf(stderr, "check-affine: fields missing\n");
        return 1;
    }
    cJSON_ArrayForEach(p, pairs)
    {
        const char *need[] = {"s", "phi_deg", "e2"};
        int k;
        if (cJSON_GetArraySize(cJSON_GetObjectItem(p, "ref")) != 2 ||
            cJSON_GetArraySize(cJSON_GetObjectItem(p, "mov")) != 2) {
            fprintf(stderr, "check-affine: a pair lacks its centroids\n");
            return 1;
        }
        for (k = 0; k < 3; k++) {
            if (!cJSON_IsNumber(cJSON_GetObjectItem(p, need[k]))) {
                fprintf(stderr, "check-affine: a pair lacks %s\n", need[k]);
                return 1;
            }
        }
    }
    for (i = 0; i < 6; i++) {
        A[i] = cJSON_GetArrayItem(af, i)->valuedouble;
    }
    for (i = 0; i < 4; i++) {
        const double x = (i & 1) ? n - 1.0 : 0.0, y = (i & 2) ? n - 1.0 : 0.0;
        const double ex = A[0] * x + A[1] * y + A[2] - (T[0] * x + T[1] * y + T[2]);
        const double ey = A[3] * x + A[4] * y + A[5] - (T[3] * x + T[4] * y + T[5]);
        worst = fmax(worst, sqrt(ex * ex + ey * ey));
    }
    cJSON_Delete(j);
    if (worst > tol) {
        fprintf(stderr, "check-affine: corner error %.3f px > %.3f\n", worst, tol);
        return 1;
    }
    return 0;
}

static int check_shape(int argc, char **argv)
{
    cJSON *j;
    double s, phi, d;
    if (argc < 7 || (j = load_json(argv[2])) == NULL) {
        return 1;
    }
    s = cJSON_GetObjectItem(j, "s") ? cJSON_GetObjectItem(j, "s")->valuedouble : -1;
    phi = cJSON_GetObjectItem(j, "phi_deg") ? cJSON_GetObjectItem(j, "phi_deg")->valuedouble : 1e9;
    if (!cJSON_IsNumber(cJSON_GetObjectItem(j, "alpha")) ||
        !cJSON_IsNumber(cJSON_GetObjectItem(j, "e2"))) {
        fprintf(stderr, "check-shape: alpha or e2 missing\n");
        return 1;
    }
    cJSON_Delete(j);
    d = fmod(phi - atof(argv[4]) + 540.0, 360.0) - 180.0;
    if (fabs(s / atof(argv[3]) - 1.0) > atof(argv[5]) || fabs(d) > atof(argv[6])) {
        fprintf(stderr, "check-shape: s %.5f phi %.3f, expected %s %s\n", s, phi, argv[3],
                argv[4]);
        return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 4 && !strcmp(argv[1], "scene")) {
        return cmd_scene(argc, argv);
    }
    if (argc >= 3 && !strcmp(argv[1], "silhouette")) {
        return cmd_silhouette(argc, argv);
    }
    if (argc >= 3 && !strcmp(argv[1], "check-affine")) {
        return check_affine(argc, argv);
    }
    if (argc >= 3 && !strcmp(argv[1], "check-shape")) {
        return check_shape(argc, argv);
    }
    fprintf(stderr, "usage: gen_symreg scene|silhouette|check-affine|check-shape ...\n");
    return 2;
}
