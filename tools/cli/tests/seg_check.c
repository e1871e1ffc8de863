/*
 * seg_check.c - checks of `ssda segment` outputs against known answers:
 *   ari LABELS.png TRUTH.png MIN
 *       the adjusted Rand index of the labels against the truth, over the
 *       pixels whose truth is not 0, is at least MIN; where the truth is 0
 *       (nodata) the labels must be 0.
 *   json FILE FEATURES K [MEAN...]
 *       FILE parses; it has FEATURES features, the first with K
 *       components; in every feature the component pixels, the unlabelled
 *       ones and the masked ones add up to width x height, weights sum to
 *       1, means rise; with MEAN values, the first feature's mean_value of
 *       component k is within 2 % (+ 1) of MEAN k. With a "kl" part: unit
 *       vectors, eigenvalues decreasing, rows of vectors_l1 summing to 1 in
 *       absolute value.
 *   png FILE W H
 *       FILE is a PNG of W x H pixels.
 * Exit status 0 when the check holds, 1 (with a message) otherwise.
 */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "png_io.h"

static int fail(const char *fmt, const char *a, double v)
{
    fprintf(stderr, "seg_check: ");
    fprintf(stderr, fmt, a, v);
    fputc('\n', stderr);
    return 1;
}

static double comb2(double n)
{
    return n * (n - 1.0) / 2.0;
}

static int ari(const char *lp, const char *tp, double min)
{
    static double table[256][256];
    double a[256] = {0}, b[256] = {0}, sum_ij = 0.0, sum_a = 0.0, sum_b = 0.0, n = 0.0, idx;
    gray_image_t l = {0}, t = {0};
    char err[512];
    uint32_t x, y, i, j;
    if (png_read_gray(lp, PNG_GRAY_8, &l, NULL, err, sizeof err) != 0 ||
        png_read_gray(tp, PNG_GRAY_8, &t, NULL, err, sizeof err) != 0) {
        return fail("%s (%g)", err, 0);
    }
    if (l.width != t.width || l.height != t.height) {
        return fail("%s: size differs from the truth (%g)", lp, 0);
    }
    memset(table, 0, sizeof table);
    for (y = 0; y < l.height; y++) {
        for (x = 0; x < l.width; x++) {
            const uint32_t lv = gray_image_get(&l, x, y), tv = gray_image_get(&t, x, y);
            if (tv == 0) {
                if (lv != 0) {
                    return fail("%s: a nodata pixel is labelled %g", lp, lv);
                }
                continue;
            }
            table[lv][tv] += 1.0;
            n += 1.0;
        }
    }
    for (i = 0; i < 256; i++) {
        for (j = 0; j < 256; j++) {
            sum_ij += comb2(table[i][j]);
            a[i] += table[i][j];
            b[j] += table[i][j];
        }
    }
    for (i = 0; i < 256; i++) {
        sum_a += comb2(a[i]);
        sum_b += comb2(b[i]);
    }
    {
        const double expected = sum_a * sum_b / comb2(n), top = 0.5 * (sum_a + sum_b);
        idx = (sum_ij - expected) / (top - expected);
    }
    gray_image_free(&l);
    gray_image_free(&t);
    printf("ARI %s: %.4f\n", lp, idx);
    return idx >= min ? 0 : fail("%s: adjusted Rand index %.4f below the minimum", lp, idx);
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET)) {
        return NULL;
    }
    buf = malloc((size_t)n + 1);
    if (buf != NULL && fread(buf, 1, (size_t)n, f) == (size_t)n) {
        buf[n] = '\0';
    } else {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    return buf;
}

static double num(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static int check_kl(const cJSON *kl)
{
    const cJSON *vec = cJSON_GetObjectItemCaseSensitive(kl, "vectors");
    const cJSON *l1 = cJSON_GetObjectItemCaseSensitive(kl, "vectors_l1");
    const cJSON *lam = cJSON_GetObjectItemCaseSensitive(kl, "eigenvalues");
    int k, j;
    if (cJSON_GetArraySize(vec) != 3 || cJSON_GetArraySize(l1) != 3 || cJSON_GetArraySize(lam) != 3) {
        return fail("%s: K-L part incomplete (%g)", "json", 0);
    }
    for (k = 0; k < 3; k++) {
        double n2 = 0.0, s1 = 0.0;
        for (j = 0; j < 3; j++) {
            const double v = cJSON_GetArrayItem(cJSON_GetArrayItem(vec, k), j)->valuedouble;
            n2 += v * v;
            s1 += fabs(cJSON_GetArrayItem(cJSON_GetArrayItem(l1, k), j)->valuedouble);
        }
        if (fabs(n2 - 1.0) > 1e-6 || fabs(s1 - 1.0) > 1e-6) {
            return fail("%s: K-L row %g not unit", "json", k);
        }
        if (k > 0 && cJSON_GetArrayItem(lam, k)->valuedouble >
                         cJSON_GetArrayItem(lam, k - 1)->valuedouble) {
            return fail("%s: eigenvalue %g out of order", "json", k);
        }
    }
    return 0;
}

static int check_feature(const cJSON *root, const cJSON *f, int want_k, char **means, int nmeans)
{
    const cJSON *comps = cJSON_GetObjectItemCaseSensitive(f, "components"), *c;
    const double total = num(root, "width") * num(root, "height");
    double pixels = num(f, "unlabelled_pixels") + num(root, "masked_pixels");
    double wsum = 0.0, last = -1e300;
    int k = 0;
    if (want_k > 0 && cJSON_GetArraySize(comps) != want_k) {
        return fail("%s: %g components", "json", cJSON_GetArraySize(comps));
    }
    cJSON_ArrayForEach(c, comps) {
        const double mean = num(c, "mean");
        pixels += num(c, "pixels");
        wsum += num(c, "weight");
        if (!(mean >= last) || !(num(c, "sigma") > 0.0)) {
            return fail("%s: component %g unsorted or without sigma", "json", k + 1);
        }
        last = mean;
        if (k < nmeans) {
            const double want = atof(means[k]), got = num(c, "mean_value");
            if (!(fabs(got - want) <= 0.02 * fabs(want) + 1.0)) {
                return fail("%s: mean_value %g off", "json", got);
            }
        }
        k++;
    }
    if (fabs(pixels - total) > 0.5) {
        return fail("%s: pixels add up to %g", "json", pixels);
    }
    if (fabs(wsum - 1.0) > 1e-3) {
        return fail("%s: weights sum to %g", "json", wsum);
    }
    return 0;
}

static int json(const char *path, int nfeat, int k, char **means, int nmeans)
{
    char *text = slurp(path);
    cJSON *root = text != NULL ? cJSON_Parse(text) : NULL;
    const cJSON *feats, *f, *kl;
    int i = 0, rc = 0;
    free(text);
    if (root == NULL) {
        return fail("%s: not JSON (%g)", path, 0);
    }
    feats = cJSON_GetObjectItemCaseSensitive(root, "features");
    if (cJSON_GetArraySize(feats) != nfeat) {
        rc = fail("%s: %g features", path, cJSON_GetArraySize(feats));
    }
    kl = cJSON_GetObjectItemCaseSensitive(root, "kl");
    if (rc == 0 && kl != NULL) {
        rc = check_kl(kl);
    }
    cJSON_ArrayForEach(f, feats) {
        if (rc == 0) {
            rc = check_feature(root, f, i == 0 ? k : 0, means, i == 0 ? nmeans : 0);
        }
        i++;
    }
    cJSON_Delete(root);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc == 5 && strcmp(argv[1], "ari") == 0) {
        return ari(argv[2], argv[3], atof(argv[4]));
    }
    if (argc >= 5 && strcmp(argv[1], "json") == 0) {
        return json(argv[2], atoi(argv[3]), atoi(argv[4]), argv + 5, argc - 5);
    }
    if (argc == 5 && strcmp(argv[1], "png") == 0) {
        gray_image_t g = {0};
        char err[512];
        int rc;
        if (png_read_gray(argv[2], PNG_GRAY_NATIVE, &g, NULL, err, sizeof err) != 0) {
            return fail("%s (%g)", err, 0);
        }
        rc = g.width == (uint32_t)atoi(argv[3]) && g.height == (uint32_t)atoi(argv[4]) ? 0
             : fail("%s: size %g", argv[2], g.width);
        gray_image_free(&g);
        return rc;
    }
    fprintf(stderr, "usage: seg_check ari L T MIN | json F NFEAT K [MEAN...] | png F W H\n");
    return 2;
}
