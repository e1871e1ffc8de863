/*
 * json_out_test.c - tools/common/json_out (the JSON every tool writes):
 * escaping of any key and string (quotes, backslashes, control characters,
 * bytes that are not UTF-8), exact 64-bit integers, fixed decimals and
 * non-finite values, the layout byte for byte, a lazily made array, and an
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
    test_layout();
    test_write(argv[1]);
    if (failures != 0) {
        fprintf(stderr, "%d failure(s)\n", failures);
        return 1;
    }
    printf("json_out: ok\n");
    return 0;
}
