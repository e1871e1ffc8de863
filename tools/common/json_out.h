/*
 * json_out.h - the JSON the tools write, through cJSON (libcjson-dev): keys
 * and strings escaped for any file name or value, numbers exact, one layout.
 *
 *   cJSON *doc = json_out_object();             // start here (catches OOM)
 *   cJSON_AddNumberToObject(doc, "x", 37);       // cJSON for the usual members
 *   cJSON_AddStringToObject(doc, "file", path);
 *   json_out_add_u64(doc, "pixel_ops", ops);     // 64-bit counts, exact
 *   json_out_add_fixed(doc, "time_s", secs, 6);  // "0.001020"
 *   rc = json_out_write("out.json", doc, NULL, err, sizeof err);   // or "-"
 *   cJSON_Delete(doc);
 *
 * A command with several outputs opens them with cli_outputs_open (all or
 * nothing) and prints each with json_out_print.
 *
 * Numbers: cJSON stores doubles; it prints an integer up to 10^15 exactly
 * (32-bit values are fine with cJSON_AddNumberToObject), a fraction with up
 * to 17 significant digits, and NaN or infinity as null. A 64-bit count
 * goes through json_out_add_u64 / json_out_add_i64, a value with a fixed
 * number of decimals through json_out_add_fixed (null when not finite).
 */
#ifndef SSDA_JSON_OUT_H
#define SSDA_JSON_OUT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cjson/cJSON.h>

/* A new empty object. Also makes every later cJSON allocation failure
   known to json_out_print and json_out_write (which then fail with ENOMEM
   instead of writing a document with members missing). NULL when out of
   memory. */
cJSON *json_out_object(void);

/* v printed with exactly `decimals` digits after the point (0..17), as
   printf's %.*f; null when v is not finite. Returns the item or NULL. */
cJSON *json_out_fixed(double v, int decimals);
/* An unsigned or signed 64-bit integer, every digit exact. */
cJSON *json_out_u64(uint64_t v);
cJSON *json_out_i64(int64_t v);
/* A Q8 fixed-point value (v_q8 / 256) with its 8 decimals, exact: the
   bytes of json_out_fixed(v_q8 / 256.0, 8) for |v_q8| < 2^53, any int64_t
   accepted, without floating point. */
cJSON *json_out_q8(int64_t v_q8);
/* A string as valid UTF-8: each byte that does not start a well-formed
   UTF-8 sequence becomes U+FFFD (a file name on Linux may hold any bytes;
   cJSON would copy them, and the document would not be JSON). Use it for
   file names and any text from outside. cJSON escapes quotes, backslashes
   and control characters either way. */
cJSON *json_out_string(const char *s);
/* The same, added to obj under name. Return the item or NULL. */
cJSON *json_out_add_string(cJSON *obj, const char *name, const char *s);
cJSON *json_out_add_fixed(cJSON *obj, const char *name, double v, int decimals);
cJSON *json_out_add_q8(cJSON *obj, const char *name, int64_t v_q8);
cJSON *json_out_add_u64(cJSON *obj, const char *name, uint64_t v);
cJSON *json_out_add_i64(cJSON *obj, const char *name, int64_t v);

/* A long array made one item at a time while printing (each printed, then
   deleted), so that a million-window grid never holds a million cJSON
   objects. The document holds an (empty) array member called name as the
   placeholder that fixes its place; item(ctx, i) makes element i
   (i < count) or returns NULL when out of memory. */
typedef struct {
    const char *name;
    size_t count;
    cJSON *(*item)(void *ctx, size_t i);
    void *ctx;
} json_out_lazy_t;

/*
 * Print doc and a newline to f. Layout: an object's scalar members on one
 * line; a member holding an object or array starts a new line (one space
 * in); an array of objects puts each on its own line (two spaces in):
 *     {"width":128,"height":128,
 *      "grid":{"cols":8,"rows":8},
 *      "windows":[
 *       {"x":0,"y":0},
 *       {"x":16,"y":0}]}
 * A document of scalars is one line. lazy may be NULL. Returns 0, or -1
 * (errno ENOMEM) when the document could not be made. Write errors are left
 * in f's error flag, for the commit of the output to report (a reader of
 * stdout that has gone is not an error there); printing stops at the first.
 */
int json_out_print(FILE *f, const cJSON *doc, const json_out_lazy_t *lazy);

/* Print doc to path atomically (atomic_file.h: temp file, fsync, rename; "-"
   is stdout). Returns 0, or -1 with a message naming path in err (errlen
   bytes) and no file left. */
int json_out_write(const char *path, const cJSON *doc, const json_out_lazy_t *lazy, char *err,
                   size_t errlen);

#endif /* SSDA_JSON_OUT_H */
