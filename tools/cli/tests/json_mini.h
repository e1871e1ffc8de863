/* json_mini.h - a small strict JSON reader for the CLI tests (RFC 8259 values;
   numbers kept as double). Parsing a file also proves it is well-formed. */
#ifndef SSDA_JSON_MINI_H
#define SSDA_JSON_MINI_H

#include <stddef.h>

typedef enum { JSON_NULL, JSON_FALSE, JSON_TRUE, JSON_NUMBER, JSON_STRING, JSON_ARRAY,
               JSON_OBJECT } json_type_t;

typedef struct json_value {
    json_type_t type;
    double number;
    char *string;               /* JSON_STRING; also the key of an object member */
    char *key;                  /* set when this value is an object member */
    struct json_value *items;   /* JSON_ARRAY / JSON_OBJECT: count entries */
    size_t count;
} json_value_t;

/* Parse the whole text; returns a tree (free with json_free) or NULL, with
   the byte offset of the error in *err_at. */
json_value_t *json_parse(const char *text, size_t *err_at);
/* Member of an object by key, or NULL. */
const json_value_t *json_get(const json_value_t *obj, const char *key);
void json_free(json_value_t *v);

#endif
