/* json_out.c - JSON through cJSON: exact numbers, one layout, atomic files. */
#include "json_out.h"
#include "atomic_file.h"
#include "tool_err.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- allocation failures ---- */

static int failed_alloc; /* a cJSON allocation failed: documents may lack members */

static void *counting_malloc(size_t n)
{
    void *p = malloc(n);
    if (p == NULL) {
        failed_alloc = 1;
    }
    return p;
}

cJSON *json_out_object(void)
{
    static int hooked;
    if (!hooked) {
        cJSON_Hooks h;
        h.malloc_fn = counting_malloc;
        h.free_fn = free;
        cJSON_InitHooks(&h);
        hooked = 1;
    }
    return cJSON_CreateObject();
}

/* ---- numbers ---- */

cJSON *json_out_fixed(double v, int decimals)
{
    char buf[352]; /* DBL_MAX has 309 integer digits; sign, point, 17 decimals */
    if (!isfinite(v)) {
        return cJSON_CreateNull();
    }
    decimals = decimals < 0 ? 0 : decimals > 17 ? 17 : decimals;
    snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return cJSON_CreateRaw(buf);
}

/* The digits of v before end (no terminator written); returns the first.
   Plain division: snprintf's format parsing cost more than the digits in
   `ssda track --json` (a few numbers per window, 14 508 windows on GOES). */
static char *digits(uint64_t v, char *end)
{
    do {
        *--end = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    return end;
}

/* -magnitude when neg (magnitude <= 2^63), as printf's %d / %u print it. */
static cJSON *raw_integer(uint64_t magnitude, int neg)
{
    char buf[24], *p;
    buf[sizeof buf - 1] = '\0';
    p = digits(magnitude, buf + sizeof buf - 1);
    if (neg) {
        *--p = '-';
    }
    return cJSON_CreateRaw(p);
}

cJSON *json_out_u64(uint64_t v)
{
    return raw_integer(v, 0);
}

cJSON *json_out_i64(int64_t v)
{
    /* the magnitude in unsigned arithmetic: INT64_MIN has no positive twin */
    return raw_integer(v < 0 ? 0u - (uint64_t)v : (uint64_t)v, v < 0);
}

cJSON *json_out_q8(int64_t v_q8)
{
    /* v / 256 = whole + frac / 256, and frac / 256 = frac * 390625 / 10^8:
       exactly 8 decimals (printf prints the same digits, the value being
       exact in binary and in 8 decimals). A negative value keeps its sign
       even when whole is 0 ("-0.00390625"); 0 is "0.00000000". */
    const int neg = v_q8 < 0;
    const uint64_t m = neg ? 0u - (uint64_t)v_q8 : (uint64_t)v_q8;
    char buf[32], *p = buf + sizeof buf - 1;
    uint32_t frac = (uint32_t)(m & 255u) * 390625u, i;
    *p = '\0';
    for (i = 0; i < 8u; i++) {
        *--p = (char)('0' + frac % 10u);
        frac /= 10u;
    }
    *--p = '.';
    p = digits(m >> 8, p);
    if (neg) {
        *--p = '-';
    }
    return cJSON_CreateRaw(p);
}

/* ---- strings ---- */

/* Length of the well-formed UTF-8 sequence at s (RFC 3629: no overlong
   forms, no surrogates, nothing above U+10FFFF), or 0. */
static size_t utf8_len(const unsigned char *s)
{
    size_t n, i;
    unsigned long c;
    if (s[0] < 0x80u) {
        return 1;
    }
    n = s[0] >= 0xf0u ? 4 : s[0] >= 0xe0u ? 3 : s[0] >= 0xc0u ? 2 : 0;
    if (n == 0 || s[0] > 0xf4u) {
        return 0;
    }
    c = s[0] & (0x7fu >> n);
    for (i = 1; i < n; i++) {
        if ((s[i] & 0xc0u) != 0x80u) {
            return 0;
        }
        c = (c << 6) | (s[i] & 0x3fu);
    }
    if ((n == 2 && c < 0x80u) || (n == 3 && c < 0x800u) || (n == 4 && c < 0x10000u) ||
        (c >= 0xd800u && c <= 0xdfffu) || c > 0x10ffffu) {
        return 0;
    }
    return n;
}

cJSON *json_out_string(const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    size_t n = strlen(s), o = 0, k;
    char *buf = malloc(3 * n + 1); /* a bad byte (1) becomes U+FFFD (3) */
    cJSON *item;
    if (buf == NULL) {
        failed_alloc = 1;
        return NULL;
    }
    while (*p != '\0') {
        if ((k = utf8_len(p)) == 0) {
            memcpy(buf + o, "\xef\xbf\xbd", 3);
            o += 3;
            p++;
        } else {
            memcpy(buf + o, p, k);
            o += k;
            p += k;
        }
    }
    buf[o] = '\0';
    item = cJSON_CreateString(buf);
    free(buf);
    return item;
}

/* Add item (may be NULL: out of memory) to obj. */
static cJSON *add(cJSON *obj, const char *name, cJSON *item)
{
    if (item != NULL && !cJSON_AddItemToObject(obj, name, item)) {
        cJSON_Delete(item);
        item = NULL;
    }
    if (item == NULL) {
        failed_alloc = 1;
    }
    return item;
}

cJSON *json_out_add_string(cJSON *obj, const char *name, const char *s)
{
    return add(obj, name, json_out_string(s));
}

cJSON *json_out_add_fixed(cJSON *obj, const char *name, double v, int decimals)
{
    return add(obj, name, json_out_fixed(v, decimals));
}

cJSON *json_out_add_q8(cJSON *obj, const char *name, int64_t v_q8)
{
    return add(obj, name, json_out_q8(v_q8));
}

cJSON *json_out_add_u64(cJSON *obj, const char *name, uint64_t v)
{
    return add(obj, name, json_out_u64(v));
}

cJSON *json_out_add_i64(cJSON *obj, const char *name, int64_t v)
{
    return add(obj, name, json_out_i64(v));
}

/* ---- printing ---- */

/* One value, compact. Returns 0 or -1 (ENOMEM). */
static int put_compact(FILE *f, const cJSON *v)
{
    char *s = cJSON_PrintUnformatted(v);
    if (s == NULL) {
        errno = ENOMEM;
        return -1;
    }
    fputs(s, f);
    cJSON_free(s);
    return 0;
}

/* "key": escaped as a string value is. */
static int put_key(FILE *f, const char *key)
{
    cJSON *k = json_out_string(key);
    int rc = k != NULL ? put_compact(f, k) : -1;
    cJSON_Delete(k);
    if (rc == 0) {
        fputc(':', f);
    } else {
        errno = ENOMEM;
    }
    return rc;
}

static int is_container(const cJSON *v)
{
    return cJSON_IsObject(v) || cJSON_IsArray(v);
}

/* A whole number's digits, as "%1.15g" prints it for |v| < 1e15. */
static char *whole_text(double v)
{
    char buf[24], *p = buf + sizeof buf, *out;
    unsigned long long u = (unsigned long long)(v < 0.0 ? -v : v);
    size_t n;
    *--p = '\0';
    do {
        *--p = (char)('0' + (int)(u % 10u));
        u /= 10u;
    } while (u != 0u);
    if (v < 0.0) {
        *--p = '-';
    }
    n = (size_t)(buf + sizeof buf - p);
    if ((out = malloc(n)) != NULL) { /* cJSON_Delete frees it (free hook) */
        memcpy(out, p, n);
    }
    return out;
}

/* cJSON 1.7.15 prints every number through "%1.15g" and a sscanf round
   trip, most of the JSON time of a tracking run's window records; whole
   numbers below 1e15 (not -0) are turned into raw text of the same digits
   first, so the bytes written are the same. */
static void whole_numbers_raw(cJSON *v)
{
    cJSON *c;
    for (c = v->child; c != NULL; c = c->next) {
        if (cJSON_IsNumber(c)) {
            double d = c->valuedouble;
            char *text;
            if (d == floor(d) && fabs(d) < 1e15 && !(d == 0.0 && signbit(d)) &&
                (text = whole_text(d)) != NULL) {
                c->type = cJSON_Raw;
                c->valuestring = text;
            }
        } else if (is_container(c)) {
            whole_numbers_raw(c);
        }
    }
}

/* An array whose first element is an object: one element per line. */
static int put_rows(FILE *f, const cJSON *arr)
{
    const cJSON *e;
    int rc = 0;
    fputc('[', f);
    for (e = arr->child; e != NULL && rc == 0 && !ferror(f); e = e->next) {
        fputs(e != arr->child ? ",\n  " : "\n  ", f);
        rc = put_compact(f, e);
    }
    fputc(']', f);
    return rc;
}

static int put_lazy(FILE *f, const json_out_lazy_t *lazy)
{
    size_t i;
    int rc = 0;
    fputc('[', f);
    for (i = 0; i < lazy->count && rc == 0 && !ferror(f); i++) { /* stop at a closed pipe */
        cJSON *e = lazy->item(lazy->ctx, i);
        if (e != NULL) {
            whole_numbers_raw(e);
        }
        fputs(i > 0 ? ",\n  " : "\n  ", f);
        rc = e != NULL ? put_compact(f, e) : -1;
        cJSON_Delete(e);
    }
    fputc(']', f);
    if (rc != 0) {
        errno = ENOMEM;
    }
    return rc;
}

/* One member's value, in the layout of json_out_print. */
static int put_member(FILE *f, const cJSON *m, const json_out_lazy_t *lazy)
{
    if (lazy != NULL && cJSON_IsArray(m) && strcmp(m->string, lazy->name) == 0) {
        return put_lazy(f, lazy);
    }
    if (cJSON_IsArray(m) && cJSON_IsObject(m->child)) {
        return put_rows(f, m);
    }
    return put_compact(f, m);
}

int json_out_print(FILE *f, const cJSON *doc, const json_out_lazy_t *lazy)
{
    const cJSON *m;
    int rc = 0;
    if (failed_alloc || doc == NULL) {
        errno = ENOMEM;
        return -1;
    }
    if (!cJSON_IsObject(doc)) {
        rc = put_compact(f, doc);
    } else {
        fputc('{', f);
        for (m = doc->child; m != NULL && rc == 0 && !ferror(f); m = m->next) {
            if (m != doc->child) {
                fputs(is_container(m) ? ",\n " : ",", f);
            }
            rc = put_key(f, m->string);
            rc = rc == 0 ? put_member(f, m, lazy) : rc;
        }
        fputc('}', f);
    }
    fputc('\n', f);
    if (rc != 0) {
        errno = ENOMEM;
    }
    return rc;
}

int json_out_write(const char *path, const cJSON *doc, const json_out_lazy_t *lazy, char *err,
                   size_t errlen)
{
    atomic_file_t af;
    if (atomic_file_open(&af, path) != 0) {
        tool_set_err(err, errlen, "cannot create '%s': %s", path, atomic_file_strerror(errno));
        return -1;
    }
    if (json_out_print(af.fp, doc, lazy) != 0) {
        tool_set_err(err, errlen, "cannot write '%s': out of memory", path);
        atomic_file_abort(&af);
        return -1;
    }
    if (atomic_file_commit(&af) != 0) { /* write errors too */
        tool_set_err(err, errlen, "cannot write '%s': %s", path, atomic_file_strerror(errno));
        return -1;
    }
    return 0;
}
