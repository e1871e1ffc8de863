/* json_mini.c - recursive-descent JSON reader (tests only). */
#include "json_mini.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *s;
    size_t i;
    int bad;
} cursor_t;

static void skip_ws(cursor_t *c)
{
    while (c->s[c->i] == ' ' || c->s[c->i] == '\n' || c->s[c->i] == '\r' || c->s[c->i] == '\t') {
        c->i++;
    }
}

static int parse_value(cursor_t *c, json_value_t *v, int depth);

static char *parse_string_raw(cursor_t *c)
{
    size_t start, n = 0;
    char *out;
    if (c->s[c->i] != '"') {
        c->bad = 1;
        return NULL;
    }
    start = ++c->i;
    while (c->s[c->i] != '"') {
        unsigned char ch = (unsigned char)c->s[c->i];
        if (ch == '\0' || ch < 0x20) {
            c->bad = 1;
            return NULL;
        }
        if (ch == '\\') {
            c->i++;
            if (strchr("\"\\/bfnrtu", c->s[c->i]) == NULL || c->s[c->i] == '\0') {
                c->bad = 1;
                return NULL;
            }
            if (c->s[c->i] == 'u') {
                int k;
                for (k = 1; k <= 4; k++) {
                    if (strchr("0123456789abcdefABCDEF", c->s[c->i + k]) == NULL ||
                        c->s[c->i + k] == '\0') {
                        c->bad = 1;
                        return NULL;
                    }
                }
                c->i += 4;
            }
        }
        c->i++;
        n++;
    }
    out = malloc(c->i - start + 1);
    memcpy(out, c->s + start, c->i - start); /* escapes kept as written (tests need none) */
    out[c->i - start] = '\0';
    c->i++;
    (void)n;
    return out;
}

static int parse_number(cursor_t *c, json_value_t *v)
{
    size_t start = c->i;
    char *end;
    if (c->s[c->i] == '-') c->i++;
    if (c->s[c->i] == '0') {
        c->i++;
    } else if (c->s[c->i] >= '1' && c->s[c->i] <= '9') {
        while (c->s[c->i] >= '0' && c->s[c->i] <= '9') c->i++;
    } else {
        return -1;
    }
    if (c->s[c->i] == '.') {
        c->i++;
        if (!(c->s[c->i] >= '0' && c->s[c->i] <= '9')) return -1;
        while (c->s[c->i] >= '0' && c->s[c->i] <= '9') c->i++;
    }
    if (c->s[c->i] == 'e' || c->s[c->i] == 'E') {
        c->i++;
        if (c->s[c->i] == '+' || c->s[c->i] == '-') c->i++;
        if (!(c->s[c->i] >= '0' && c->s[c->i] <= '9')) return -1;
        while (c->s[c->i] >= '0' && c->s[c->i] <= '9') c->i++;
    }
    v->type = JSON_NUMBER;
    v->number = strtod(c->s + start, &end);
    return 0;
}

static int push_item(json_value_t *parent, json_value_t *item)
{
    json_value_t *n = realloc(parent->items, (parent->count + 1) * sizeof *n);
    if (n == NULL) return -1;
    parent->items = n;
    parent->items[parent->count++] = *item;
    return 0;
}

static int parse_container(cursor_t *c, json_value_t *v, int depth, int object)
{
    v->type = object ? JSON_OBJECT : JSON_ARRAY;
    c->i++;
    skip_ws(c);
    if (c->s[c->i] == (object ? '}' : ']')) {
        c->i++;
        return 0;
    }
    for (;;) {
        json_value_t item;
        char *key = NULL;
        memset(&item, 0, sizeof item);
        skip_ws(c);
        if (object) {
            key = parse_string_raw(c);
            if (key == NULL) return -1;
            skip_ws(c);
            if (c->s[c->i] != ':') {
                free(key);
                return -1;
            }
            c->i++;
        }
        if (parse_value(c, &item, depth + 1) != 0) {
            free(key);
            json_free(&item);
            return -1;
        }
        item.key = key;
        if (push_item(v, &item) != 0) return -1;
        skip_ws(c);
        if (c->s[c->i] == ',') {
            c->i++;
            continue;
        }
        if (c->s[c->i] == (object ? '}' : ']')) {
            c->i++;
            return 0;
        }
        return -1;
    }
}

static int parse_value(cursor_t *c, json_value_t *v, int depth)
{
    skip_ws(c);
    if (depth > 64) return -1;
    switch (c->s[c->i]) {
    case '{': return parse_container(c, v, depth, 1);
    case '[': return parse_container(c, v, depth, 0);
    case '"':
        v->type = JSON_STRING;
        v->string = parse_string_raw(c);
        return v->string != NULL ? 0 : -1;
    case 't':
        if (strncmp(c->s + c->i, "true", 4) != 0) return -1;
        c->i += 4;
        v->type = JSON_TRUE;
        return 0;
    case 'f':
        if (strncmp(c->s + c->i, "false", 5) != 0) return -1;
        c->i += 5;
        v->type = JSON_FALSE;
        return 0;
    case 'n':
        if (strncmp(c->s + c->i, "null", 4) != 0) return -1;
        c->i += 4;
        v->type = JSON_NULL;
        return 0;
    default: return parse_number(c, v);
    }
}

json_value_t *json_parse(const char *text, size_t *err_at)
{
    cursor_t c = {text, 0, 0};
    json_value_t *v = calloc(1, sizeof *v);
    if (parse_value(&c, v, 0) != 0 || c.bad) {
        if (err_at) *err_at = c.i;
        json_free(v);
        free(v);
        return NULL;
    }
    skip_ws(&c);
    if (text[c.i] != '\0') {
        if (err_at) *err_at = c.i;
        json_free(v);
        free(v);
        return NULL;
    }
    return v;
}

const json_value_t *json_get(const json_value_t *obj, const char *key)
{
    size_t i;
    if (obj == NULL || obj->type != JSON_OBJECT) return NULL;
    for (i = 0; i < obj->count; i++) {
        if (strcmp(obj->items[i].key, key) == 0) return &obj->items[i];
    }
    return NULL;
}

/* Frees what v owns (not v itself, which may live in a parent's array). */
void json_free(json_value_t *v)
{
    size_t i;
    if (v == NULL) return;
    for (i = 0; i < v->count; i++) {
        json_free(&v->items[i]);
    }
    free(v->items);
    free(v->string);
    free(v->key);
    v->items = NULL;
    v->string = v->key = NULL;
    v->count = 0;
}
