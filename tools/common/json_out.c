/* json_out.c - JSON through cJSON: exact numbers, one layout, atomic files. */
#include "json_out.h"
#include "atomic_file.h"
#include "tool_err.h"

#include <errno.h>
#include <inttypes.h>
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

cJSON *json_out_u64(uint64_t v)
{
    char buf[24];
    snprintf(buf, sizeof buf, "%" PRIu64, v);
    return cJSON_CreateRaw(buf);
}

cJSON *json_out_i64(int64_t v)
{
    char buf[24];
    snprintf(buf, sizeof buf, "%" PRId64, v);
    return cJSON_CreateRaw(buf);
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
