#define _POSIX_C_SOURCE 200809L /* strtok_r */
/*
 * check_outputs.c - checks the `ssda` tool's outputs against known answers
 * for the CLI tests. Each command exits 0 when the check passes, 1 with a
 * message when it fails, 2 on a bad command line.
 *
 *   match-json FILE X|- Y|- SAD|- EXACT(true|false|-)   ("-": not checked)
 *   track-json FILE DX DY MINFRAC [--min-ok N] [--count STATUS N] [--no-ok]
 *       [--searched] [--whole]
 *       --searched: DX, DY and MINFRAC over every searched window (ok,
 *       ambiguous, at_limit), not the ok ones only; --whole: every sub_dx,
 *       sub_dy equals dx, dy
 *       MINFRAC of the ok windows must have exactly (DX, DY); the JSON is
 *       also checked for consistency (grid, statuses, stats).
 *   compare-json FILE MIN_WITHIN1_PCT
 *   pitch-csv FILE --f0 A[:B] --voiced T0:T1 [--glide-secs S0:S1] [--tol REL]
 *       [--silent-before T] [--min-voiced FRAC]
 *   png-same A.png B.png        same gray size, depth and pixels
 *   png-size FILE W H [BITS]
 *   grad-same IN.png OUT.png SHIFT   OUT is the Fig. 8 operator of IN (same
 *       size, border 0), recomputed here in plain C
 */
#include <jansson.h>
#include "png_io.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "check: ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 1;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (f == NULL) return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    if (fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        fclose(f);
        return NULL;
    }
    buf[n] = '\0';
    fclose(f);
    return buf;
}

/* The tools write JSON with cJSON; it is read back here with a different
   library (jansson, strict: one value, valid UTF-8, no duplicate keys). */
static json_t *load_json(const char *path)
{
    json_error_t e;
    json_t *v = json_load_file(path, JSON_REJECT_DUPLICATES, &e);
    if (v == NULL) {
        fail("%s is not valid JSON (line %d, column %d: %s)", path, e.line, e.column, e.text);
    }
    return v;
}

static int num(const json_t *o, const char *key, double *out)
{
    const json_t *v = json_object_get(o, key);
    if (!json_is_number(v)) return -1;
    *out = json_number_value(v);
    return 0;
}

static int check_match(int argc, char **argv)
{
    json_t *j;
    double x, y, sad, pos, comp, ops, brute;
    const json_t *ex;
    int rc = 0;
    if (argc != 5) return 2;
    j = load_json(argv[0]);
    if (j == NULL) return 1;
    ex = json_object_get(j, "exact");
    if (num(j, "x", &x) || num(j, "y", &y) || num(j, "sad", &sad) || num(j, "positions", &pos) ||
        num(j, "completed", &comp) || num(j, "pixel_ops", &ops) ||
        num(j, "brute_force_ops", &brute) || ex == NULL ||
        !json_is_boolean(ex)) {
        rc = fail("match JSON lacks a field");
    } else if ((strcmp(argv[1], "-") != 0 && x != atof(argv[1])) ||
               (strcmp(argv[2], "-") != 0 && y != atof(argv[2]))) {
        rc = fail("match at (%g, %g), expected (%s, %s)", x, y, argv[1], argv[2]);
    } else if (strcmp(argv[3], "-") != 0 && sad != atof(argv[3])) {
        rc = fail("sad %g, expected %s", sad, argv[3]);
    } else if (strcmp(argv[4], "-") != 0 &&
               json_is_true(ex) != (strcmp(argv[4], "true") == 0)) {
        rc = fail("exact is %s, expected %s", json_is_true(ex) ? "true" : "false", argv[4]);
    } else if (comp < 1 || comp > pos || ops <= 0) {
        rc = fail("implausible work counts: positions %g completed %g pixel_ops %g", pos, comp,
                  ops);
    }
    json_decref(j);
    return rc;
}

/* The statuses; the first NSEARCHED were searched and have vectors. */
#define NSTATUS 7
#define NSEARCHED 3
static const char *status_names[NSTATUS] = {"ok", "ambiguous", "at_limit", "flat",
                                           "excluded", "masked", "edge"};

static int g_searched; /* --searched: agreement over every searched window */
static int g_whole;    /* --whole: sub-pixel vectors equal the whole ones */

/* A searched window's vectors: inside the search range, the sub-pixel one
   within half a pixel of the whole one; at_limit exactly when a component
   is at the range's border (an axis with one placement has none). */
static int check_vector(const json_t *w, size_t i, int s, const double geo[4], double wdx,
                        double wdy)
{
    double sw = geo[0], sh = geo[1], ww = geo[2], wh = geo[3], sdx, sdy;
    /* dx ranges over hx - (sw - ww) .. hx */
    double hx = floor((sw - ww) / 2), hy = floor((sh - wh) / 2);
    int border = (sw > ww && (wdx == hx || wdx == hx - (sw - ww))) ||
                 (sh > wh && (wdy == hy || wdy == hy - (sh - wh)));
    if (num(w, "sub_dx", &sdx) || num(w, "sub_dy", &sdy)) {
        return fail("window %zu lacks sub_dx or sub_dy", i);
    }
    if (wdx > hx || wdx < hx - (sw - ww) || wdy > hy || wdy < hy - (sh - wh)) {
        return fail("window %zu vector (%g, %g) outside the search range", i, wdx, wdy);
    }
    if (g_whole && (sdx != wdx || sdy != wdy)) {
        return fail("window %zu sub-pixel (%g, %g), expected (%g, %g)", i, sdx, sdy, wdx, wdy);
    }
    if (fabs(sdx - wdx) > 0.5 || fabs(sdy - wdy) > 0.5) {
        return fail("window %zu sub-pixel (%g, %g) more than 0.5 px from (%g, %g)", i, sdx, sdy,
                    wdx, wdy);
    }
    if (border != (s == 2)) {
        return fail("window %zu (%g, %g) is %s", i, wdx, wdy, status_names[s]);
    }
    return 0;
}

/* One window of a track JSON: its fields, a known status, vectors for the
   searched statuses (others none). Counts the status; *agree when an ok
   vector is (dx, dy). Returns 0 or 1 (said). */

static int check_window(const json_t *w, size_t i, const double geo[4], double dx, double dy,
                        size_t counts[NSTATUS], size_t *agree)
{
    const json_t *st = json_object_get(w, "status");
    double wx, wy, wdx, wdy, sad;
    int k, s = -1;
    if (!json_is_string(st) || num(w, "x", &wx) || num(w, "y", &wy) || num(w, "dx", &wdx) ||
        num(w, "dy", &wdy) || num(w, "sad", &sad)) {
        return fail("window %zu lacks x, y, dx, dy, sad or status", i);
    }
    for (k = 0; k < NSTATUS; k++) {
        if (strcmp(json_string_value(st), status_names[k]) == 0) s = k;
    }
    if (s < 0) {
        return fail("window %zu has unknown status '%s'", i, json_string_value(st));
    }
    counts[s]++;
    if (s < NSEARCHED) {
        if (check_vector(w, i, s, geo, wdx, wdy) != 0) {
            return 1;
        }
        *agree += (s == 0 || g_searched) && wdx == dx && wdy == dy;
    } else if (wdx != 0 || wdy != 0) {
        return fail("window %zu is %s but has a vector", i, json_string_value(st));
    }
    return 0;
}

/* Options after FILE DX DY MINFRAC: --min-ok N, --no-ok, --count STATUS N.
   Returns 0 or 2 (bad command line). */
static int track_options(int argc, char **argv, long *min_ok, long want_count[NSTATUS])
{
    int a;
    for (a = 4; a < argc; a++) {
        if (strcmp(argv[a], "--min-ok") == 0 && a + 1 < argc) {
            *min_ok = atol(argv[++a]);
        } else if (strcmp(argv[a], "--no-ok") == 0) {
            *min_ok = 0;
        } else if (strcmp(argv[a], "--searched") == 0) {
            g_searched = 1;
        } else if (strcmp(argv[a], "--whole") == 0) {
            g_whole = 1;
        } else if (strcmp(argv[a], "--count") == 0 && a + 2 < argc) {
            int k, found = 0;
            for (k = 0; k < NSTATUS; k++) {
                if (strcmp(argv[a + 1], status_names[k]) == 0) {
                    want_count[k] = atol(argv[a + 2]);
                    found = 1;
                }
            }
            if (!found) return 2;
            a += 2;
        } else {
            return 2;
        }
    }
    return 0;
}

/* Status counts: stats agree with the windows, and with --count. */
static int check_counts(const json_t *stats, const size_t counts[NSTATUS],
                        const long want_count[NSTATUS])
{
    double counts_json;
    int a;
    for (a = 0; a < NSTATUS; a++) {
        if (num(stats, status_names[a], &counts_json) || counts_json != (double)counts[a]) {
            return fail("stats.%s disagrees with the windows (%zu)", status_names[a], counts[a]);
        }
        if (want_count[a] >= 0 && (long)counts[a] != want_count[a]) {
            return fail("%zu %s windows, expected %ld", counts[a], status_names[a], want_count[a]);
        }
    }
    return 0;
}

static int check_track(int argc, char **argv)
{
    json_t *j;
    const json_t *wins, *stats, *grid;
    double dx, dy, minfrac, cols, rows, geo[4], v;
    size_t counts[NSTATUS] = {0}, agree = 0, i;
    long min_ok = 1, want_count[NSTATUS] = {-1, -1, -1, -1, -1, -1, -1};
    int rc = 0;
    if (argc < 4 || track_options(argc, argv, &min_ok, want_count) != 0) return 2;
    dx = atof(argv[1]);
    dy = atof(argv[2]);
    minfrac = atof(argv[3]);
    j = load_json(argv[0]);
    if (j == NULL) return 1;
    wins = json_object_get(j, "windows");
    stats = json_object_get(j, "stats");
    grid = json_object_get(j, "grid");
    if (wins == NULL || !json_is_array(wins) || stats == NULL || grid == NULL ||
        num(grid, "cols", &cols) || num(grid, "rows", &rows) || num(grid, "search_w", &geo[0]) ||
        num(grid, "search_h", &geo[1]) || num(grid, "window_w", &geo[2]) ||
        num(grid, "window_h", &geo[3]) || num(stats, "pixel_ops", &v) ||
        num(stats, "bytes_read", &v)) {
        rc = fail("track JSON lacks windows, grid or stats fields");
    } else if ((double)json_array_size(wins) != cols * rows) {
        rc = fail("%zu windows, grid says %g x %g", json_array_size(wins), cols, rows);
    }
    for (i = 0; rc == 0 && i < json_array_size(wins); i++) {
        rc = check_window(json_array_get(wins, i), i, geo, dx, dy, counts, &agree);
    }
    rc = rc == 0 ? check_counts(stats, counts, want_count) : rc;
    {
        /* the windows the agreement is over: ok, or every searched one */
        const size_t base = g_searched ? counts[0] + counts[1] + counts[2] : counts[0];
        if (rc == 0 && (long)base < min_ok) {
            rc = fail("only %zu %s windows, expected at least %ld", base,
                      g_searched ? "searched" : "ok", min_ok);
        } else if (rc == 0 && base > 0 && (double)agree < minfrac * (double)base) {
            rc = fail("%zu of %zu %s windows found (%g, %g); wanted %.0f %%", agree, base,
                      g_searched ? "searched" : "ok", dx, dy, 100 * minfrac);
        }
    }
    json_decref(j);
    return rc;
}

static int check_compare(int argc, char **argv)
{
    json_t *j;
    const json_t *cmp, *wins;
    double w0, w1, w2, n, p1;
    size_t i, mine[3] = {0, 0, 0}, ok = 0;
    int rc = 0;
    if (argc != 2) return 2;
    j = load_json(argv[0]);
    if (j == NULL) return 1;
    cmp = json_object_get(j, "compare");
    wins = json_object_get(j, "windows");
    if (cmp == NULL || wins == NULL || num(cmp, "within_0", &w0) || num(cmp, "within_1", &w1) ||
        num(cmp, "within_2", &w2) || num(cmp, "windows", &n) || num(cmp, "within_1_pct", &p1) ||
        num(cmp, "ncc_time_s", &n) || num(cmp, "windows", &n)) {
        rc = fail("compare JSON lacks fields");
        goto done;
    }
    for (i = 0; i < json_array_size(wins); i++) {
        const json_t *w = json_array_get(wins, i), *st = json_object_get(w, "status");
        double dx, dy, rx, ry, d;
        if (strcmp(json_string_value(st), "ok") != 0) continue;
        if (num(w, "dx", &dx) || num(w, "dy", &dy) || num(w, "ref_dx", &rx) ||
            num(w, "ref_dy", &ry)) {
            rc = fail("ok window %zu lacks ref_dx/ref_dy", i);
            goto done;
        }
        ok++;
        d = fmax(fabs(dx - rx), fabs(dy - ry));
        if (d <= 0) mine[0]++;
        if (d <= 1) mine[1]++;
        if (d <= 2) mine[2]++;
    }
    if ((double)ok != n || (double)mine[0] != w0 || (double)mine[1] != w1 ||
        (double)mine[2] != w2) {
        rc = fail("compare counts (%g: %g %g %g) disagree with the windows (%zu: %zu %zu %zu)",
                  n, w0, w1, w2, ok, mine[0], mine[1], mine[2]);
    } else if (p1 < atof(argv[1])) {
        rc = fail("within 1 px %.1f %%, expected at least %s %%", p1, argv[1]);
    }
done:
    json_decref(j);
    return rc;
}

static int check_pitch(int argc, char **argv)
{
    char *text, *line, *save = NULL;
    double fa = 0, fb = 0, t0 = 0, t1 = 0, g0 = -1, g1 = -1, tol = 0.03, silent_before = -1;
    double min_voiced = 0.9, prev_t = -1;
    size_t in_span = 0, voiced = 0, good = 0, rows = 0;
    int a, rc = 0;
    if (argc < 1) return 2;
    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--f0") == 0 && a + 1 < argc) {
            if (sscanf(argv[++a], "%lf:%lf", &fa, &fb) != 2) fb = fa = atof(argv[a]);
        } else if (strcmp(argv[a], "--voiced") == 0 && a + 1 < argc) {
            if (sscanf(argv[++a], "%lf:%lf", &t0, &t1) != 2) return 2;
        } else if (strcmp(argv[a], "--glide-secs") == 0 && a + 1 < argc) {
            if (sscanf(argv[++a], "%lf:%lf", &g0, &g1) != 2) return 2;
        } else if (strcmp(argv[a], "--tol") == 0 && a + 1 < argc) {
            tol = atof(argv[++a]);
        } else if (strcmp(argv[a], "--silent-before") == 0 && a + 1 < argc) {
            silent_before = atof(argv[++a]);
        } else if (strcmp(argv[a], "--min-voiced") == 0 && a + 1 < argc) {
            min_voiced = atof(argv[++a]);
        } else {
            return 2;
        }
    }
    if (g0 < 0) { /* constant f0 over the voiced span */
        g0 = t0;
        g1 = t1;
    }
    text = slurp(argv[0]);
    if (text == NULL) return fail("cannot read %s", argv[0]);
    line = strtok_r(text, "\n", &save);
    if (line == NULL || strncmp(line, "time_s,f0_hz,voiced", 19) != 0) {
        rc = fail("CSV header is not time_s,f0_hz,voiced...");
        goto done;
    }
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        double t, f;
        int v;
        if (sscanf(line, "%lf,%lf,%d", &t, &f, &v) != 3 || (v != 0 && v != 1)) {
            rc = fail("bad CSV row '%s'", line);
            goto done;
        }
        rows++;
        if (t <= prev_t) {
            rc = fail("times not increasing at '%s'", line);
            goto done;
        }
        prev_t = t;
        if ((v == 0) != (f == 0.0)) {
            rc = fail("f0 must be 0 exactly when unvoiced: '%s'", line);
            goto done;
        }
        if (silent_before >= 0 && t < silent_before && v) {
            rc = fail("voiced frame in the silence: '%s'", line);
            goto done;
        }
        if (t >= t0 && t <= t1) {
            double want = fa + (fb - fa) * (t - g0) / (g1 - g0);
            in_span++;
            if (v) {
                voiced++;
                if (fabs(f - want) <= tol * want) good++;
            }
        }
    }
    if (rows == 0 || in_span == 0) {
        rc = fail("no frames in %g..%g s", t0, t1);
    } else if ((double)voiced < min_voiced * (double)in_span) {
        rc = fail("%zu of %zu frames voiced in %g..%g s", voiced, in_span, t0, t1);
    } else if ((double)good < 0.95 * (double)voiced) {
        rc = fail("only %zu of %zu voiced frames within %.1f %% of the known f0", good, voiced,
                  100 * tol);
    }
done:
    free(text);
    return rc;
}

static int load_png(const char *path, gray_image_t *img)
{
    char err[512];
    if (png_read_gray(path, PNG_GRAY_NATIVE, img, NULL, err, sizeof err) != 0) {
        fail("%s", err);
        return -1;
    }
    return 0;
}

static int check_png_same(int argc, char **argv)
{
    gray_image_t a, b;
    uint32_t x, y;
    int rc = 0;
    if (argc != 2) return 2;
    if (load_png(argv[0], &a) != 0) return 1;
    if (load_png(argv[1], &b) != 0) return 1;
    if (a.width != b.width || a.height != b.height || a.bits != b.bits) {
        rc = fail("%s is %ux%u %u-bit, %s is %ux%u %u-bit", argv[0], a.width, a.height, a.bits,
                  argv[1], b.width, b.height, b.bits);
    } else {
        for (y = 0; y < a.height && rc == 0; y++) {
            for (x = 0; x < a.width && rc == 0; x++) {
                if (gray_image_get(&a, x, y) != gray_image_get(&b, x, y)) {
                    rc = fail("pixel (%u, %u): %u vs %u", x, y, gray_image_get(&a, x, y),
                              gray_image_get(&b, x, y));
                }
            }
        }
    }
    gray_image_free(&a);
    gray_image_free(&b);
    return rc;
}

static int check_png_size(int argc, char **argv)
{
    gray_image_t a;
    int rc = 0;
    if (argc != 3 && argc != 4) return 2;
    if (load_png(argv[0], &a) != 0) return 1;
    if (a.width != (uint32_t)atoi(argv[1]) || a.height != (uint32_t)atoi(argv[2]) ||
        (argc == 4 && a.bits != (uint32_t)atoi(argv[3]))) {
        rc = fail("%s is %ux%u %u-bit", argv[0], a.width, a.height, a.bits);
    }
    gray_image_free(&a);
    return rc;
}

/* png-max FILE MIN: the largest pixel value is at least MIN. */
static int check_png_max(int argc, char **argv)
{
    gray_image_t a;
    uint32_t x, y, m = 0;
    int rc = 0;
    if (argc != 2) return 2;
    if (load_png(argv[0], &a) != 0) return 1;
    for (y = 0; y < a.height; y++) {
        for (x = 0; x < a.width; x++) {
            m = gray_image_get(&a, x, y) > m ? gray_image_get(&a, x, y) : m;
        }
    }
    if (m < (uint32_t)atol(argv[1])) {
        rc = fail("%s: largest value %u, expected at least %s", argv[0], m, argv[1]);
    }
    gray_image_free(&a);
    return rc;
}

/* png-count FILE LO HI X0 Y0 X1 Y1: print how many pixels of the rectangle
   [X0, X1) x [Y0, Y1) (clipped) have a gray value in LO..HI (RGB is read as
   luma: a colour mark in a legend is counted by its gray level). */
static int check_png_count(int argc, char **argv)
{
    gray_image_t a;
    uint32_t x, y, lo, hi, x0, y0, x1, y1;
    unsigned long n = 0;
    if (argc != 7) return 2;
    lo = (uint32_t)atol(argv[1]);
    hi = (uint32_t)atol(argv[2]);
    x0 = (uint32_t)atol(argv[3]);
    y0 = (uint32_t)atol(argv[4]);
    x1 = (uint32_t)atol(argv[5]);
    y1 = (uint32_t)atol(argv[6]);
    if (load_png(argv[0], &a) != 0) return 1;
    for (y = y0; y < y1 && y < a.height; y++) {
        for (x = x0; x < x1 && x < a.width; x++) {
            uint32_t v = gray_image_get(&a, x, y);
            n += v >= lo && v <= hi;
        }
    }
    printf("%lu\n", n);
    gray_image_free(&a);
    return 0;
}

static int check_grad(int argc, char **argv)
{
    gray_image_t in, out;
    uint32_t x, y, maxv;
    int rc = 0, shift;
    if (argc != 3) return 2;
    shift = atoi(argv[2]); /* negative: E' << -shift */
    if (load_png(argv[0], &in) != 0 || load_png(argv[1], &out) != 0) return 1;
    maxv = gray_image_max(&out);
    if (in.width != out.width || in.height != out.height) {
        rc = fail("grad output %ux%u, input %ux%u", out.width, out.height, in.width, in.height);
    }
    for (y = 0; y < in.height && rc == 0; y++) {
        for (x = 0; x < in.width && rc == 0; x++) {
            long want = 0;
            if (x > 0 && y > 0 && x + 1 < in.width && y + 1 < in.height) {
#define P(dx, dy) ((long)gray_image_get(&in, x + (dx), y + (dy)))
                long a = P(-1, -1), b = P(0, -1), c = P(1, -1), d = P(-1, 0), f = P(1, 0);
                long g = P(-1, 1), h = P(0, 1), i = P(1, 1);
#undef P
                want = labs(a + b + c - g - h - i) + labs(a + d + g - c - f - i);
                want = shift >= 0 ? want >> shift : want << -shift;
                if (want > (long)maxv) want = (long)maxv;
            }
            if ((long)gray_image_get(&out, x, y) != want) {
                rc = fail("grad pixel (%u, %u) = %u, expected %ld", x, y,
                          gray_image_get(&out, x, y), want);
            }
        }
    }
    gray_image_free(&in);
    gray_image_free(&out);
    return rc;
}

int main(int argc, char **argv)
{
    int rc = 2;
    if (argc >= 2) {
        if (strcmp(argv[1], "match-json") == 0) rc = check_match(argc - 2, argv + 2);
        else if (strcmp(argv[1], "track-json") == 0) rc = check_track(argc - 2, argv + 2);
        else if (strcmp(argv[1], "compare-json") == 0) rc = check_compare(argc - 2, argv + 2);
        else if (strcmp(argv[1], "pitch-csv") == 0) rc = check_pitch(argc - 2, argv + 2);
        else if (strcmp(argv[1], "png-same") == 0) rc = check_png_same(argc - 2, argv + 2);
        else if (strcmp(argv[1], "png-size") == 0) rc = check_png_size(argc - 2, argv + 2);
        else if (strcmp(argv[1], "grad-same") == 0) rc = check_grad(argc - 2, argv + 2);
        else if (strcmp(argv[1], "png-max") == 0) rc = check_png_max(argc - 2, argv + 2);
        else if (strcmp(argv[1], "png-count") == 0) rc = check_png_count(argc - 2, argv + 2);
    }
    if (rc == 2) fprintf(stderr, "check_outputs: bad command line\n");
    return rc;
}
