/* atomic_file.c - temp file + rename. */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int atomic_file_open(atomic_file_t *af, const char *path)
{
    size_t n = strlen(path);
    int fd;
    memset(af, 0, sizeof *af);
    if (strcmp(path, "-") == 0) {
        af->fp = stdout;
        return 0;
    }
    af->final_path = strdup(path);
    af->tmp_path = malloc(n + 16);
    if (af->final_path == NULL || af->tmp_path == NULL) {
        atomic_file_abort(af);
        errno = ENOMEM;
        return -1;
    }
    memcpy(af->tmp_path, path, n);
    memcpy(af->tmp_path + n, ".tmp.XXXXXX", 12);
    fd = mkstemp(af->tmp_path);
    if (fd < 0 || (af->fp = fdopen(fd, "wb")) == NULL) {
        int e = errno;
        if (fd >= 0) {
            close(fd);
            unlink(af->tmp_path);
        }
        free(af->tmp_path);
        af->tmp_path = NULL;
        atomic_file_abort(af);
        errno = e;
        return -1;
    }
    return 0;
}

int atomic_file_commit(atomic_file_t *af)
{
    int bad;
    if (af->fp == stdout) {
        return fflush(stdout) == 0 ? 0 : -1;
    }
    bad = ferror(af->fp) != 0;
    bad |= fclose(af->fp) != 0;
    af->fp = NULL;
    if (!bad && rename(af->tmp_path, af->final_path) == 0) {
        free(af->tmp_path);
        free(af->final_path);
        af->tmp_path = af->final_path = NULL;
        return 0;
    }
    atomic_file_abort(af);
    return -1;
}

void atomic_file_abort(atomic_file_t *af)
{
    if (af->fp != NULL && af->fp != stdout) {
        fclose(af->fp);
    }
    af->fp = NULL;
    if (af->tmp_path != NULL) {
        unlink(af->tmp_path);
    }
    free(af->tmp_path);
    free(af->final_path);
    af->tmp_path = af->final_path = NULL;
}
