/*
 * flow_tool.c - helpers of the correlation CLI tests (cli_flow.sh):
 *   flow_tool gain IN.png OUT.png G O       OUT = clamp(G IN + O), 8-bit
 *   flow_tool crop IN.png OUT.png X Y W H   OUT = the W x H rectangle of IN at (X, Y)
 *   flow_tool halfshift IN.png A.png B.png D ROW   A = IN with every value
 *     made even (2 round(0.49 v)); B = A moved right by D + 1 px above row
 *     ROW and by D + 1/2 px from ROW down, B(x) = (A(x-D-1) + A(x-D)) / 2:
 *     there every window has exactly the same SAD at dx = D and D + 1 (a
 *     tie, which the prediction from the rows above breaks toward D + 1
 *     and a search without prediction toward D); 8-bit
 *   flow_tool check FILE.json DX DY MINFRAC [--relaxed] [--changed-min N]
 *     FILE is `ssda flow --json`: at least MINFRAC of the "ok" templates
 *     move by (DX, DY) within 0.5 px (of relax_dx/dy with --relaxed); the
 *     header's counts agree with the list; with --changed-min, at least N
 *     templates say "changed". JSON read with jansson (not the writer's cJSON).
 *   flow_tool track-rho FIRST.png SECOND.png FILE.json sad|ncc|absncc MINOK
 *     FILE is `ssda track --metric ... --json` (8-bit images): every
 *     searched ("ok", "ambiguous", "at_limit") window's rho and sad equal a
 *     double-precision recomputation at its
 *     placement (rho within 1e-6); with ncc/absncc its placement has the
 *     largest rho (|rho|) of the whole search area (brute force in double,
 *     within 1e-9); at least MINOK windows are ok.
 *   flow_tool track-check FILE.json DX DY MINFRAC
 *     at least MINFRAC of the "ok" windows of `ssda track --json` have
 *     exactly (dx, dy) = (DX, DY).
 *   flow_tool shrink IN.png OUT.png N       OUT = IN averaged over N x N blocks
 *     (8-bit, rounded): a pair shifted by k px shrinks to a k / N px motion
 *   flow_tool track-sub FILE.json DX DY TOL MINFRAC [--relaxed [--kept]]
 *     `ssda track --json`: every "ok" window's sub_dx, sub_dy lie within
 *     0.5 px of its dx, dy, and at least MINFRAC of them within TOL px of
 *     (DX, DY) on each axis (relax_dx, relax_dy with --relaxed); with
 *     --kept every window not "changed" has relax_dx, relax_dy equal to
 *     sub_dx, sub_dy (to the 4 decimals printed).
 *   flow_tool track-status FILE.json
 *     FILE is `ssda track --metric ncc|absncc --json`: every searched window
 *     is "at_limit" exactly when its placement lies on the border of the
 *     search range (dx or dy at an extreme of an axis with more than one
 *     placement, track.h's rule), else "ok" (never "ambiguous"); the
 *     "stats" counts equal the windows'. Prints "ok N at_limit N".
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

static int halfshift(int argc, char **argv)
{
    gray_image_t img = {0}, out = {0};
    char err[256];
    uint32_t x, y;
    long d, row;
    if (argc != 5 || png_read_gray(argv[0], PNG_GRAY_8, &img, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "flow_tool halfshift: %s\n", argc == 5 ? err : "usage");
        return 2;
    }
    d = atol(argv[3]);
    row = atol(argv[4]);
    if (d < 0 || d + 2 > (long)img.width || gray_image_alloc(&out, img.width, img.height, 8) != 0) {
        fprintf(stderr, "flow_tool halfshift: bad D\n");
        return 2;
    }
    for (y = 0; y < img.height; y++) {
        uint8_t *a = (uint8_t *)img.pixels + (size_t)y * img.stride;
        for (x = 0; x < img.width; x++) {
            a[x] = (uint8_t)(2 * (int)(0.49 * a[x] + 0.5));
        }
    }
    for (y = 0; y < img.height; y++) {
        const uint8_t *a = (const uint8_t *)img.pixels + (size_t)y * img.stride;
        uint8_t *b = (uint8_t *)out.pixels + (size_t)y * out.stride;
        for (x = 0; x < img.width; x++) {
            long s = (long)x - d - 1; /* B(x) = A(x - d - 1) above ROW */
            long s0 = s < 0 ? 0 : s, s1 = s + 1 < 0 ? 0 : s + 1;
            b[x] = (long)y < row ? a[s0] : (uint8_t)((a[s0] + a[s1]) / 2);
        }
    }
    if (png_write_gray(argv[1], &img, err, sizeof err) != 0 ||
        png_write_gray(argv[2], &out, err, sizeof err) != 0) {
        fprintf(stderr, "flow_tool halfshift: %s\n", err);
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

typedef struct {
    gray_image_t f, s;
    long ww, wh, sw, sh;
} pair_t;

/* rho (double) and SAD of the window at (wx, wy) of SECOND placed at (ax, ay) of FIRST. */
static double rho_at(const pair_t *p, long wx, long wy, long ax, long ay, double *sad)
{
    double n = (double)(p->ww * p->wh), sa = 0, sw = 0, saa = 0, sww = 0, saw = 0, va, vw;
    long i, j;
    *sad = 0;
    for (j = 0; j < p->wh; j++) {
        for (i = 0; i < p->ww; i++) {
            double a = ((const uint8_t *)p->f.pixels)[(size_t)(ay + j) * p->f.stride + (size_t)(ax + i)];
            double w = ((const uint8_t *)p->s.pixels)[(size_t)(wy + j) * p->s.stride + (size_t)(wx + i)];
            sa += a, sw += w, saa += a * a, sww += w * w, saw += a * w;
            *sad += fabs(a - w);
        }
    }
    va = n * saa - sa * sa;
    vw = n * sww - sw * sw;
    return va > 0 && vw > 0 ? (n * saw - sa * sw) / sqrt(va * vw) : 0.0;
}

/* The largest rho (|rho| with absval) of window (wx, wy) over its search area. */
static double best_rho(const pair_t *p, long wx, long wy, int absval)
{
    long hx = (p->sw - p->ww) / 2, hy = (p->sh - p->wh) / 2, x, y;
    double best = -2, sad, r;
    for (y = wy - hy; y <= wy - hy + p->sh - p->wh; y++) {
        for (x = wx - hx; x <= wx - hx + p->sw - p->ww; x++) {
            r = rho_at(p, wx, wy, x, y, &sad);
            r = absval ? fabs(r) : r;
            best = r > best ? r : best;
        }
    }
    return best;
}

static long jint(json_t *o, const char *k)
{
    return (long)json_integer_value(json_object_get(o, k));
}

/* Every ok window of doc against the double recomputation (track-rho). */
static int rho_windows(const pair_t *p, json_t *doc, const char *mode, long min_ok)
{
    json_t *list = json_object_get(doc, "windows");
    size_t i, ok = 0;
    int search = strcmp(mode, "sad") != 0, absval = !strcmp(mode, "absncc");
    for (i = 0; i < json_array_size(list); i++) {
        json_t *t = json_array_get(list, i);
        long x = jint(t, "x"), y = jint(t, "y"), dx = jint(t, "dx"), dy = jint(t, "dy");
        double sad, r, got = json_real_value(json_object_get(t, "rho"));
        const char *st = json_string_value(json_object_get(t, "status"));
        if (strcmp(st, "ok") != 0 && strcmp(st, "ambiguous") != 0 && strcmp(st, "at_limit") != 0) {
            continue;
        }
        ok += strcmp(st, "ok") == 0;
        r = rho_at(p, x, y, x - dx, y - dy, &sad);
        if (json_object_get(t, "rho") == NULL || fabs(r - got) > 1e-6 ||
            (double)jint(t, "sad") != sad ||
            (search && (absval ? fabs(r) : r) < best_rho(p, x, y, absval) - 1e-9)) {
            fprintf(stderr, "flow_tool track-rho: window (%ld, %ld) dx %ld dy %ld: rho %.9f "
                    "(JSON %.6f), sad %.0f (JSON %ld), best %.9f\n", x, y, dx, dy, r, got, sad,
                    jint(t, "sad"), best_rho(p, x, y, absval));
            return 1;
        }
    }
    if ((long)ok < min_ok) {
        fprintf(stderr, "flow_tool track-rho: %zu ok windows (want %ld)\n", ok, min_ok);
        return 1;
    }
    return 0;
}

static int track_rho(int argc, char **argv)
{
    pair_t p = {0};
    json_error_t je;
    json_t *doc = NULL;
    char err[256];
    int rc = 2;
    if (argc == 5 && png_read_gray(argv[0], PNG_GRAY_8, &p.f, NULL, err, sizeof err) == 0 &&
        png_read_gray(argv[1], PNG_GRAY_8, &p.s, NULL, err, sizeof err) == 0 &&
        (doc = json_load_file(argv[2], 0, &je)) != NULL) {
        json_t *grid = json_object_get(doc, "grid");
        p.ww = jint(grid, "window_w"), p.wh = jint(grid, "window_h");
        p.sw = jint(grid, "search_w"), p.sh = jint(grid, "search_h");
        rc = rho_windows(&p, doc, argv[3], atol(argv[4]));
    } else {
        fprintf(stderr, "flow_tool track-rho: usage or unreadable input\n");
    }
    json_decref(doc);
    gray_image_free(&p.f);
    gray_image_free(&p.s);
    return rc;
}

static int track_check(int argc, char **argv)
{
    json_error_t je;
    json_t *doc, *list;
    size_t i, ok = 0, good = 0;
    if (argc != 4 || (doc = json_load_file(argv[0], 0, &je)) == NULL) {
        fprintf(stderr, "flow_tool track-check: usage or unreadable JSON\n");
        return 2;
    }
    list = json_object_get(doc, "windows");
    for (i = 0; i < json_array_size(list); i++) {
        json_t *t = json_array_get(list, i);
        if (strcmp(json_string_value(json_object_get(t, "status")), "ok") == 0) {
            ok++;
            good += jint(t, "dx") == atol(argv[1]) && jint(t, "dy") == atol(argv[2]);
        }
    }
    json_decref(doc);
    if (ok == 0 || (double)good < atof(argv[3]) * (double)ok) {
        fprintf(stderr, "flow_tool track-check: %zu of %zu ok windows at (%s, %s)\n", good, ok,
                argv[1], argv[2]);
        return 1;
    }
    return 0;
}

static int shrink(int argc, char **argv)
{
    gray_image_t img = {0}, out = {0};
    char err[256];
    uint32_t n, x, y, i, j;
    if (argc != 3 || png_read_gray(argv[0], PNG_GRAY_8, &img, NULL, err, sizeof err) != 0 ||
        (n = (uint32_t)atoi(argv[2])) == 0 || img.width < n || img.height < n ||
        gray_image_alloc(&out, img.width / n, img.height / n, 8) != 0) {
        fprintf(stderr, "flow_tool shrink: %s\n", argc == 3 ? err : "usage");
        return 2;
    }
    for (y = 0; y < out.height; y++) {
        for (x = 0; x < out.width; x++) {
            uint32_t sum = 0;
            for (j = 0; j < n; j++) {
                for (i = 0; i < n; i++) {
                    sum += gray_image_get(&img, x * n + i, y * n + j);
                }
            }
            ((uint8_t *)out.pixels)[(size_t)y * out.stride + x] =
                (uint8_t)((sum + n * n / 2u) / (n * n));
        }
    }
    if (png_write_gray(argv[1], &out, err, sizeof err) != 0) {
        fprintf(stderr, "flow_tool shrink: %s\n", err);
        return 1;
    }
    gray_image_free(&img);
    gray_image_free(&out);
    return 0;
}

static int track_sub(int argc, char **argv)
{
    json_error_t je;
    json_t *doc, *list;
    size_t i, ok = 0, good = 0, torn = 0;
    const int relaxed = argc >= 6 && !strcmp(argv[5], "--relaxed");
    const int kept = relaxed && argc == 7 && !strcmp(argv[6], "--kept");
    size_t moved = 0;
    double tol;
    if ((argc != 5 && !(relaxed && (argc == 6 || kept))) ||
        (doc = json_load_file(argv[0], 0, &je)) == NULL) {
        fprintf(stderr, "flow_tool track-sub: usage or unreadable JSON\n");
        return 2;
    }
    tol = atof(argv[3]);
    list = json_object_get(doc, "windows");
    for (i = 0; i < json_array_size(list); i++) {
        json_t *t = json_array_get(list, i);
        double sx, sy;
        if (strcmp(json_string_value(json_object_get(t, "status")), "ok") != 0) {
            continue;
        }
        ok++;
        sx = json_number_value(json_object_get(t, "sub_dx"));
        sy = json_number_value(json_object_get(t, "sub_dy"));
        torn += fabs(sx - (double)jint(t, "dx")) > 0.5 || fabs(sy - (double)jint(t, "dy")) > 0.5;
        if (relaxed) {
            const double rx = json_number_value(json_object_get(t, "relax_dx"));
            const double ry = json_number_value(json_object_get(t, "relax_dy"));
            moved += kept && !json_is_true(json_object_get(t, "changed")) &&
                     (fabs(rx - sx) > 6e-5 || fabs(ry - sy) > 6e-5);
            sx = rx;
            sy = ry;
        }
        good += fabs(sx - atof(argv[1])) <= tol && fabs(sy - atof(argv[2])) <= tol;
    }
    json_decref(doc);
    if (ok == 0 || torn > 0 || moved > 0 || (double)good < atof(argv[4]) * (double)ok) {
        fprintf(stderr, "flow_tool track-sub: %zu of %zu ok windows within %g px of (%s, %s)%s; "
                        "%zu with sub_dx, sub_dy more than 0.5 px from dx, dy; %zu kept "
                        "vectors moved\n",
                good, ok, tol, argv[1], argv[2], relaxed ? " (relaxed)" : "", torn, moved);
        return 1;
    }
    return 0;
}

/* Whether motion d lies at an extreme of the range hx - (n - 1) .. hx of
   an axis with n placements (track.h's GEOMETRY and AT_LIMIT). */
static int at_border(long d, long search, long win)
{
    long n = search - win + 1, h = (search - win) / 2;
    return n > 1 && (d == h || d == h - (n - 1));
}

static int track_status(int argc, char **argv)
{
    json_error_t je;
    json_t *doc, *list, *grid, *st;
    size_t i;
    long ok = 0, lim = 0, bad = 0;
    if (argc != 1 || (doc = json_load_file(argv[0], 0, &je)) == NULL) {
        fprintf(stderr, "flow_tool track-status: usage or unreadable JSON\n");
        return 2;
    }
    list = json_object_get(doc, "windows");
    grid = json_object_get(doc, "grid");
    st = json_object_get(doc, "stats");
    for (i = 0; i < json_array_size(list); i++) {
        json_t *t = json_array_get(list, i);
        const char *s = json_string_value(json_object_get(t, "status"));
        int border = at_border(jint(t, "dx"), jint(grid, "search_w"), jint(grid, "window_w")) ||
                     at_border(jint(t, "dy"), jint(grid, "search_h"), jint(grid, "window_h"));
        if (!strcmp(s, "ok") || !strcmp(s, "at_limit") || !strcmp(s, "ambiguous")) {
            ok += !strcmp(s, "ok");
            lim += !strcmp(s, "at_limit");
            if (strcmp(s, border ? "at_limit" : "ok") != 0) {
                fprintf(stderr, "flow_tool track-status: window (%ld, %ld) dx %ld dy %ld: %s\n",
                        jint(t, "x"), jint(t, "y"), jint(t, "dx"), jint(t, "dy"), s);
                bad++;
            }
        }
    }
    if (jint(st, "ok") != ok || jint(st, "at_limit") != lim || jint(st, "ambiguous") != 0) {
        fprintf(stderr, "flow_tool track-status: stats ok %ld at_limit %ld ambiguous %ld, "
                "windows %ld, %ld, 0\n", jint(st, "ok"), jint(st, "at_limit"),
                jint(st, "ambiguous"), ok, lim);
        bad++;
    }
    json_decref(doc);
    printf("ok %ld at_limit %ld\n", ok, lim);
    return bad != 0;
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "track-status")) {
        return track_status(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "shrink")) {
        return shrink(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "track-sub")) {
        return track_sub(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "gain")) {
        return gain(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "crop")) {
        return crop(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "halfshift")) {
        return halfshift(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "check")) {
        return check(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "track-check")) {
        return track_check(argc - 2, argv + 2);
    }
    if (argc >= 2 && !strcmp(argv[1], "track-rho")) {
        return track_rho(argc - 2, argv + 2);
    }
    fprintf(stderr, "usage: flow_tool gain IN OUT G O | crop IN OUT X Y W H | "
                    "halfshift IN A B D ROW | check FILE DX DY MINFRAC [...] | track-rho FIRST SECOND FILE MODE MINOK | "
                    "track-check FILE DX DY MINFRAC | shrink IN OUT N | "
                    "track-sub FILE DX DY TOL MINFRAC [--relaxed [--kept]] | track-status FILE\n");
    return 2;
}
