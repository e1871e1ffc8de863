/* atomic_file.h - write an output file atomically: temp file + rename, so a
   failed run never leaves a partial output behind. */
#ifndef SSDA_ATOMIC_FILE_H
#define SSDA_ATOMIC_FILE_H
#include <stdio.h>

typedef struct {
    FILE *fp;          /* write here */
    char *final_path;  /* owned */
    char *tmp_path;    /* owned */
} atomic_file_t;

/* Open a temp file beside path. "-" means stdout (no temp, no rename).
   Returns 0, or -1 with errno set. */
int atomic_file_open(atomic_file_t *af, const char *path);
/* Flush, close and rename onto the final path. Returns 0 or -1. */
int atomic_file_commit(atomic_file_t *af);
/* Close and delete the temp file (after an error). */
void atomic_file_abort(atomic_file_t *af);

#endif
