/*
 * flow_tool.c - helpers of the correlation CLI tests (cli_flow.sh):
 *   flow_tool gain IN.png OUT.png G O       OUT = clamp(G IN + O), 8-bit
 *   flow_tool crop IN.png OUT.png X Y W H   OUT = the W x H rectangle of IN at (X, Y)
 *   flow_tool check FILE.json DX DY MINFRAC [--relaxed] [--changed-min N]
 *     FILE is `ssda flow --json`: at least MINFRAC of the "ok" templates
 *     move by (DX, DY) within 0.5 px (of relax_dx/dy with --relaxed); the
 *     header's counts agree with the list; with --changed-min, at least N
 *     templates say "changed". JSON read with jansson (not the writer's cJSON).
 */
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "png_io.h"

static int gain(int argc, char **argv)
{
    gray_image_t img = {0};
    char err[256];
    double g, o;
    size_t i;
    if (argc != 4 || png_read_gray(argv[0], PNG_GRAY_8, &img, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "flow_tool gain: %s\n", argc == 4 ? err : "usage");
        return 2;
    }
    g = atof(argv[2]);
    o = atof(argv[3]);
    for (i = 0; i < (size_t)img.width * img.height; i++) {
        uint8_t *p = (uint8_t *)img.pixels + i;
        double v = g * *p + o;
        *p = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v + 0.5);
    }
    if (png_write_gray(argv[1], &img, err, sizeof err) != 0) {
        fprintf(stderr, "flow_tool gain: %s\n", err);
        return 1;
    }
    gray_image_free(&img);
    return 0;
}

static int crop(int argc, char **argv)
{
    gray_image_t img = {0}, out = {0};
    char err[256];
    uint32_t x0, y0, w, h, y;
    if (argc != 6 || png_read_gray(argv[0], PNG_GRAY_NATIVE, &img, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "flow_tool crop: %s\n", argc == 6 ? err : "usage");
        return 2;
    }
    x0 = (uint32_t)atoi(argv[2]);
    y0 = (uint32_t)atoi(argv[3]);
    w = (uint32_t)atoi(argv[4]);
    h = (uint32_t)atoi(argv[5]);
    if (x0 + w > img.width || y0 + h > img.height || gray_image_alloc(&out, w, h, img.bits) != 0) {
        fprintf(stderr, "flow_tool crop: rectangle outside the image\n");
        return 2;
    }
    for (y = 0; y < h; y++) {
        memcpy((uint8_t *)out.pixels + (size_t)y * out.stride,
               (uint8_t *)img.pixels + (size_t)(y0 + y) * img.stride + (size_t)x0 * (img.bits / 8u),
               (size_t)w * (img.bits / 8u));
    }
    if (png_write_gray(argv[1], &out, err, sizeof err) != 0) {
        fprintf(stderr, "flow_tool crop: %s\n", err);
        return 1;
    }
    gray_image_free(&img);
    gray_image_free(&out);
    return 0;
}

static int check(int argc, char **argv)
{
    json_error_t je;
    json_t *doc, *list;
    double dx, dy, minfrac;
    size_t i, ok = 0, good = 0, changed = 0, n;
    int relaxed = 0, k;
    long changed_min = -1;
    if (argc < 4) {
        fprintf(stderr, "flow_tool check: usage\n");
        return 2;
    }
    dx = atof(argv[1]);
    dy = atof(argv[2]);
    minfrac = atof(argv[3]);
    for (k = 4; k < argc; k++) {
        if (!strcmp(argv[k], "--relaxed")) {
            relaxed = 1;
        } else if (!strcmp(argv[k], "--changed-min") && k + 1 < argc) {
            changed_min = atol(argv[++k]);
        }
    }
    doc = json_load_file(argv[0], 0, &je);
    if (doc == NULL) {
        fprintf(stderr, "flow_tool check: %s: %s (line %d)\n", argv[0], je.text, je.line);
        return 1;
    }
    list = json_object_get(doc, "templates");
    n = json_array_size(list);
    if (!json_is_array(list) || (size_t)json_integer_value(json_object_get(doc, "count")) != n) {
        fprintf(stderr, "flow_tool check: templates and count disagree\n");
        return 1;
    }
    for (i = 0; i < n; i++) {
        json_t *t = json_array_get(list, i);
        const char *st = json_string_value(json_object_get(t, "status"));
        double x, y;
        if (st == NULL || strcmp(st, "ok") != 0) {
            continue;
        }
        ok++;
        x = json_real_value(json_object_get(t, relaxed ? "relax_dx" : "dx"));
        y = json_real_value(json_object_get(t, relaxed ? "relax_dy" : "dy"));
        good += fabs(x - dx) <= 0.5 && fabs(y - dy) <= 0.5;
        changed += json_is_true(json_object_get(t, "changed"));
    }
    if ((size_t)json_integer_value(json_object_get(doc, "ok")) != ok || ok == 0 ||
        (double)good < minfrac * (double)ok ||
        (changed_min >= 0 && (long)changed < changed_min)) {
        fprintf(stderr, "flow_tool check: %zu of %zu ok templates at (%g, %g) (want %.0f %%), "
                        "%zu changed\n", good, ok, dx, dy, 100.0 * minfrac, changed);
        return 1;
    }
    json_decref(doc);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "gain")) {
        return gain(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "crop")) {
        return crop(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "check")) {
        return check(argc - 2, argv + 2);
    }
    fprintf(stderr, "usage: flow_tool gain IN OUT G O | crop IN OUT X Y W H | "
                    "check FILE DX DY MINFRAC [...]\n");
    return 2;
}
