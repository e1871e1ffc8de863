/*
 * median_test.c - tools/common/median (the tools' median motion) against a
 * sort: random arrays of every length 0..300 and some long ones, values
 * from a few (many ties) to the whole int32 range, sorted, reversed and
 * constant inputs. Exit 0 when every median equals the sort's.
 *   median_test
 */
#include "median.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp_i32(const void *a, const void *b)
{
    const int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* The median a sort gives, as the tool computed it before (doubles). */
static double sorted_median(const int32_t *v, size_t n)
{
    int32_t *s;
    double m;
    if (n == 0u) {
        return 0.0;
    }
    s = malloc(n * sizeof *s);
    memcpy(s, v, n * sizeof *s);
    qsort(s, n, sizeof *s, cmp_i32);
    m = n % 2u ? s[n / 2u] / 256.0 : 0.5 * (s[n / 2u - 1u] / 256.0 + s[n / 2u] / 256.0);
    free(s);
    return m;
}

static uint64_t rng = 0x2545f4914f6cdd1du;

static uint32_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)(rng >> 32);
}

static int failures;

static void check(const int32_t *v, size_t n, const char *what)
{
    int32_t *w = malloc((n + 1u) * sizeof *w);
    double got, want = sorted_median(v, n);
    memcpy(w, v, n * sizeof *w);
    got = median_q8(w, n);
    if (got != want) {
        fprintf(stderr, "FAIL %s, n = %zu: %.8f, sort gives %.8f\n", what, n, got, want);
        failures++;
    }
    free(w);
}

int main(void)
{
    static const uint32_t spans[] = {1u, 2u, 3u, 17u, 512u, 65536u, 0u}; /* 0: any int32 */
    static int32_t v[100001];
    size_t n, s, i;
    for (s = 0; s < sizeof spans / sizeof spans[0]; s++) {
        for (n = 0; n <= 300u; n++) {
            for (i = 0; i < n; i++) {
                v[i] = spans[s] != 0u ? (int32_t)(next() % spans[s]) - (int32_t)(spans[s] / 2u)
                                      : (int32_t)next();
            }
            check(v, n, "random");
        }
        for (i = 0; i < 100001u; i++) {
            v[i] = spans[s] != 0u ? (int32_t)(next() % spans[s]) : (int32_t)next();
        }
        check(v, 100000u, "random, long");
        check(v, 100001u, "random, long");
    }
    for (n = 1; n <= 64u; n++) {
        for (i = 0; i < n; i++) {
            v[i] = (int32_t)i * 37 - 900;
        }
        check(v, n, "ascending");
        for (i = 0; i < n; i++) {
            v[i] = 900 - (int32_t)i * 37;
        }
        check(v, n, "descending");
        for (i = 0; i < n; i++) {
            v[i] = INT32_MIN + (int32_t)(i % 3u); /* the least values */
        }
        check(v, n, "extremes");
        for (i = 0; i < n; i++) {
            v[i] = i % 2u ? INT32_MAX : INT32_MIN;
        }
        check(v, n, "alternating extremes");
    }
    if (failures != 0) {
        fprintf(stderr, "%d failure(s)\n", failures);
        return 1;
    }
    printf("median: ok\n");
    return 0;
}
