/*
 * json_out_test.c - tools/common/json_out (the JSON every tool writes):
 * escaping of any key and string (quotes, backslashes, control characters,
 * bytes that are not UTF-8), exact 64-bit integers, fixed decimals and
 * non-finite values, Q8 values and integers against printf, the layout
 * byte for byte, a lazily made array, and an
 * atomic file. Documents are read back with jansson, a different library
 * from the writer's (cJSON). Exit 0 when every check passes.
 *   json_out_test WORKDIR
 */
#include "json_out.h"

#include <jansson.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#define CHECK(cond, ...)                                                                          \
    do {                                                                                          \
        if (!(cond)) {                                                                            \
            fprintf(stderr, "FAIL line %d: ", __LINE__);                                          \
            fprintf(stderr, __VA_ARGS__);                                                         \
            fputc('\n', stderr);                                                                  \
            failures++;                                                                           \
        }                                                                                         \
    } while (0)

/* doc printed by json_out_print into a malloc'ed string. */
static char *print(const cJSON *doc, const json_out_lazy_t *lazy)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    int rc = json_out_print(f, doc, lazy);
    fclose(f);
    if (rc != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}

static json_t *parse(const char *text)
{
    json_error_t e;
    json_t *v = json_loads(text, JSON_REJECT_DUPLICATES, &e);
    CHECK(v != NULL, "not JSON (%s) : %s", e.text, text);
    return v;
}

static void test_strings(void)
{
    static const char nasty[] = "a\"b\\c\n\t\x01 /\xc3\xa9";        /* é */
    static const char bad[] = "x\xff" "y\xc0\xaf" "z\xed\xa0\x80!"; /* invalid, overlong, surrogate */
    cJSON *doc = json_out_object();
    char *text;
    json_t *v;
    json_out_add_string(doc, nasty, nasty);
    json_out_add_string(doc, "bad", bad);
    text = print(doc, NULL);
    v = text != NULL ? parse(text) : NULL;
    if (v != NULL) {
        const char *s = json_string_value(json_object_get(v, nasty));
        CHECK(s != NULL && strcmp(s, nasty) == 0, "key/value '%s' not kept", nasty);
        s = json_string_value(json_object_get(v, "bad"));
        CHECK(s != NULL && strcmp(s, "x\xef\xbf\xbdy\xef\xbf\xbd\xef\xbf\xbdz\xef\xbf\xbd\xef\xbf\xbd"
                                     "\xef\xbf\xbd!") == 0,
              "invalid UTF-8 not replaced by U+FFFD: '%s'", s != NULL ? s : "(none)");
    }
    json_decref(v);
    free(text);
    cJSON_Delete(doc);
}

static void test_numbers(void)
{
    cJSON *doc = json_out_object();
    char *text, want[1024], huge[400];
    json_out_add_u64(doc, "u", UINT64_MAX);
    json_out_add_i64(doc, "i", INT64_MIN);
    json_out_add_u64(doc, "big", (UINT64_C(1) << 53) + 1u); /* not a double */
    json_out_add_fixed(doc, "t", 0.0010204, 6);
    json_out_add_fixed(doc, "nan", NAN, 3);
    json_out_add_fixed(doc, "inf", -INFINITY, 3);
    json_out_add_fixed(doc, "huge", 1e300, 2);
    cJSON_AddNumberToObject(doc, "n", 4294967295.0);
    cJSON_AddNumberToObject(doc, "bad", NAN);
    text = print(doc, NULL);
    snprintf(huge, sizeof huge, "%.2f", 1e300);
    snprintf(want, sizeof want,
             "{\"u\":18446744073709551615,\"i\":-9223372036854775808,\"big\":9007199254740993,"
             "\"t\":0.001020,\"nan\":null,\"inf\":null,\"huge\":%s,\"n\":4294967295,"
             "\"bad\":null}\n", huge);
    CHECK(text != NULL && strcmp(text, want) == 0, "numbers:\n%s\nwant:\n%s",
          text != NULL ? text : "(none)", want);
    free(text);
    cJSON_Delete(doc);
    /* read back (jansson's integers are signed 64-bit: no UINT64_MAX here) */
    doc = json_out_object();
    json_out_add_u64(doc, "big", (UINT64_C(1) << 53) + 1u);
    json_out_add_i64(doc, "min", INT64_MIN);
    text = print(doc, NULL);
    if (text != NULL) {
        json_t *v = parse(text);
        CHECK(json_integer_value(json_object_get(v, "big")) == (json_int_t)((1LL << 53) + 1) &&
                  json_integer_value(json_object_get(v, "min")) == (json_int_t)INT64_MIN,
              "64-bit integers not exact: %s", text);
        json_decref(v);
    }
    free(text);
    cJSON_Delete(doc);
}

/* item's raw text (json_out's numbers are raw items). */
static const char *raw_of(const cJSON *item)
{
    return item != NULL && cJSON_IsRaw(item) ? item->valuestring : "(not raw)";
}

/* json_out_q8 against printf's %.8f of v / 256 (exact while |v| < 2^53),
   and the integers against printf's %llu / %lld. */
static void test_q8_and_integers(void)
{
    static const int64_t edges[] = {0,
                                    1,
                                    -1,
                                    255,
                                    -255,
                                    256,
                                    -256,
                                    INT32_MAX,
                                    INT32_MIN,
                                    (INT64_C(1) << 40) + 129,
                                    -(INT64_C(1) << 40) - 129,
                                    (INT64_C(1) << 53) - 1,
                                    -(INT64_C(1) << 53) + 1};
    char want[64];
    int64_t v;
    size_t i;
    uint64_t x = 0x9e3779b97f4a7c15u;
    for (v = -70000; v <= 70000; v++) {
        cJSON *a = json_out_q8(v), *b = json_out_fixed((double)v / 256.0, 8);
        CHECK(strcmp(raw_of(a), raw_of(b)) == 0, "q8 %lld: %s, printf %s", (long long)v, raw_of(a),
              raw_of(b));
        cJSON_Delete(a);
        cJSON_Delete(b);
    }
    for (i = 0; i < sizeof edges / sizeof edges[0]; i++) {
        cJSON *a = json_out_q8(edges[i]);
        snprintf(want, sizeof want, "%.8f", (double)edges[i] / 256.0);
        CHECK(strcmp(raw_of(a), want) == 0, "q8 %lld: %s, printf %s", (long long)edges[i],
              raw_of(a), want);
        cJSON_Delete(a);
    }
    /* beyond 2^53 by hand: 2^63 / 256 = 2^55; (2^63 - 1) / 256 = 2^55 - 1 + 255 / 256 */
    {
        cJSON *a = json_out_q8(INT64_MIN), *b = json_out_q8(INT64_MAX);
        CHECK(strcmp(raw_of(a), "-36028797018963968.00000000") == 0, "q8 INT64_MIN: %s", raw_of(a));
        CHECK(strcmp(raw_of(b), "36028797018963967.99609375") == 0, "q8 INT64_MAX: %s", raw_of(b));
        cJSON_Delete(a);
        cJSON_Delete(b);
    }
    for (i = 0; i < 20000; i++) { /* xorshift: every digit count, both signs */
        cJSON *u, *s;
        uint64_t w;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        w = x >> (i % 64u);
        u = json_out_u64(w);
        s = json_out_i64((int64_t)w);
        snprintf(want, sizeof want, "%llu", (unsigned long long)w);
        CHECK(strcmp(raw_of(u), want) == 0, "u64: %s, printf %s", raw_of(u), want);
        snprintf(want, sizeof want, "%lld", (long long)(int64_t)w);
        CHECK(strcmp(raw_of(s), want) == 0, "i64: %s, printf %s", raw_of(s), want);
        cJSON_Delete(u);
        cJSON_Delete(s);
    }
}

static cJSON *make_item(void *ctx, size_t i)
{
    cJSON *o = cJSON_CreateObject();
    (void)ctx;
    cJSON_AddNumberToObject(o, "k", (double)i);
    return o;
}

static void test_layout(void)
{
    cJSON *doc = json_out_object(), *rows, *r;
    json_out_lazy_t lazy = {"lazy", 3, make_item, NULL};
    char *text;
    cJSON_AddNumberToObject(doc, "a", 1);
    cJSON_AddStringToObject(doc, "b", "x");
    cJSON_AddItemToObject(doc, "o", cJSON_CreateIntArray((const int[]){1, 2}, 2));
    rows = cJSON_AddArrayToObject(doc, "rows");
    r = cJSON_CreateObject();
    cJSON_AddBoolToObject(r, "t", 1);
    cJSON_AddItemToArray(rows, r);
    cJSON_AddItemToArray(rows, cJSON_CreateObject());
    cJSON_AddArrayToObject(doc, "lazy");
    cJSON_AddArrayToObject(doc, "empty");
    cJSON_AddNullToObject(doc, "z");
    text = print(doc, &lazy);
    CHECK(text != NULL && strcmp(text, "{\"a\":1,\"b\":\"x\",\n"
                                       " \"o\":[1,2],\n"
                                       " \"rows\":[\n  {\"t\":true},\n  {}],\n"
                                       " \"lazy\":[\n  {\"k\":0},\n  {\"k\":1},\n  {\"k\":2}],\n"
                                       " \"empty\":[],\"z\":null}\n") == 0,
          "layout:\n%s", text != NULL ? text : "(none)");
    free(text);
    cJSON_Delete(doc);
    /* a document of scalars is one line */
    doc = json_out_object();
    cJSON_AddNumberToObject(doc, "x", 37);
    json_out_add_fixed(doc, "time_s", 0.5, 6);
    text = print(doc, NULL);
    CHECK(text != NULL && strcmp(text, "{\"x\":37,\"time_s\":0.500000}\n") == 0, "one line: %s",
          text != NULL ? text : "(none)");
    free(text);
    cJSON_Delete(doc);
}

/* Numbers of every kind in one record: whole (both signs, 0, -0, the
   largest below 1e15, 1e15 and beyond), fractional, nested. */
static cJSON *make_numbers(void *ctx, size_t i)
{
    static const double v[] = {0.0, -0.0, 7.0, -5.0, 123456789.0, -2147483648.0, 4294967296.0,
                               999999999999999.0, 1e15, -1e15, 1e300, 1.5, -0.25, 1.0 / 3.0};
    cJSON *o = cJSON_CreateObject(), *a = cJSON_CreateArray(), *n = cJSON_CreateObject();
    size_t k;
    (void)ctx;
    for (k = 0; k < sizeof v / sizeof v[0]; k++) {
        char key[8];
        snprintf(key, sizeof key, "n%u", (unsigned)k);
        cJSON_AddNumberToObject(o, key, v[k] + (double)i);
        cJSON_AddItemToArray(a, cJSON_CreateNumber(-v[k]));
    }
    cJSON_AddNumberToObject(n, "x", 42.0);
    cJSON_AddItemToObject(n, "a", a);
    cJSON_AddItemToObject(o, "nested", n);
    cJSON_AddStringToObject(o, "s", "12");
    return o;
}

/* Lazy records print exactly as cJSON prints them (json_out.c writes whole
   numbers through its own digits; the reference is cJSON's own printing). */
static void test_lazy_numbers_as_cjson(void)
{
    cJSON *doc = json_out_object();
    json_out_lazy_t lazy = {"w", 2, make_numbers, NULL};
    char *text, *want = NULL, *r0, *r1;
    size_t len = 0;
    FILE *f;
    cJSON_AddArrayToObject(doc, "w");
    text = print(doc, &lazy);
    {
        cJSON *e0 = make_numbers(NULL, 0), *e1 = make_numbers(NULL, 1);
        r0 = cJSON_PrintUnformatted(e0);
        r1 = cJSON_PrintUnformatted(e1);
        cJSON_Delete(e0);
        cJSON_Delete(e1);
    }
    f = open_memstream(&want, &len);
    if (f != NULL && r0 != NULL && r1 != NULL) {
        fprintf(f, "{\"w\":[\n  %s,\n  %s]}\n", r0, r1);
        fclose(f);
        CHECK(text != NULL && strcmp(text, want) == 0, "lazy numbers:\n%s\nwant:\n%s",
              text != NULL ? text : "(none)", want);
    } else {
        CHECK(0, "out of memory");
    }
    free(want);
    free(r0);
    free(r1);
    free(text);
    cJSON_Delete(doc);
}

static void test_write(const char *dir)
{
    char path[4096], err[512];
    cJSON *doc = json_out_object();
    json_error_t e;
    json_t *v;
    snprintf(path, sizeof path, "%s/doc.json", dir);
    json_out_add_string(doc, "name", "n\"x");
    CHECK(json_out_write(path, doc, NULL, err, sizeof err) == 0, "write: %s", err);
    v = json_load_file(path, JSON_REJECT_DUPLICATES, &e);
    CHECK(v != NULL && strcmp(json_string_value(json_object_get(v, "name")), "n\"x") == 0,
          "written file: %s", e.text);
    json_decref(v);
    snprintf(path, sizeof path, "%s/no/such/dir/doc.json", dir);
    CHECK(json_out_write(path, doc, NULL, err, sizeof err) != 0 && strstr(err, "doc.json") != NULL,
          "a missing folder was not refused: '%s'", err);
    cJSON_Delete(doc);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: json_out_test WORKDIR\n");
        return 2;
    }
    test_strings();
    test_numbers();
    test_q8_and_integers();
    test_layout();
    test_lazy_numbers_as_cjson();
    test_write(argv[1]);
    if (failures != 0) {
        fprintf(stderr, "%d failure(s)\n", failures);
        return 1;
    }
    printf("json_out: ok\n");
    return 0;
}
