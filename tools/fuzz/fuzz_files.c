/* fuzz_files.c - the file-based targets' private temporary folder. */
#define _POSIX_C_SOURCE 200809L
#include "fuzz_files.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fuzz_input.h"

static char g_dir[4096];

static int kept(const char *name, const char *const *keep)
{
    size_t i;
    if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0) {
        return 1;
    }
    for (i = 0; keep != NULL && keep[i] != NULL; i++) {
        if (strcmp(name, keep[i]) == 0) {
            return 1;
        }
    }
    return 0;
}

/* Visit every entry not in keep (and, if part is given, whose name
   contains it): print it, remove it, or both. */
static size_t sweep(const char *const *keep, const char *part, int print, int remove_it)
{
    DIR *d = opendir(fuzz_dir());
    struct dirent *e;
    size_t n = 0;
    char path[4200];
    FUZZ_CHECK(d != NULL);
    while ((e = readdir(d)) != NULL) {
        if (kept(e->d_name, keep) || (part != NULL && strstr(e->d_name, part) == NULL)) {
            continue;
        }
        n++;
        if (print) {
            fprintf(stderr, "fuzz: left behind: %s/%s\n", g_dir, e->d_name);
        }
        if (remove_it) {
            snprintf(path, sizeof path, "%s/%s", g_dir, e->d_name);
            unlink(path);
        }
    }
    closedir(d);
    return n;
}

static void remove_dir(void)
{
    if (g_dir[0] != '\0') {
        sweep(NULL, NULL, 0, 1);
        rmdir(g_dir);
        g_dir[0] = '\0';
    }
}

const char *fuzz_dir(void)
{
    if (g_dir[0] == '\0') {
        const char *tmp = getenv("TMPDIR");
        snprintf(g_dir, sizeof g_dir, "%s/ssda-fuzz-XXXXXX",
                 tmp != NULL && tmp[0] != '\0' ? tmp : "/tmp");
        FUZZ_CHECK(mkdtemp(g_dir) != NULL);
        atexit(remove_dir);
    }
    return g_dir;
}

char *fuzz_path(const char *name, char *buf, size_t len)
{
    snprintf(buf, len, "%s/%s", fuzz_dir(), name);
    return buf;
}

char *fuzz_write(const char *name, const uint8_t *data, size_t n, char *buf, size_t len)
{
    FILE *f = fopen(fuzz_path(name, buf, len), "wb");
    FUZZ_CHECK(f != NULL);
    FUZZ_CHECK(n == 0 || fwrite(data, 1, n, f) == n);
    FUZZ_CHECK(fclose(f) == 0);
    return buf;
}

size_t fuzz_strays(const char *const *keep)
{
    return sweep(keep, NULL, 1, 0);
}

size_t fuzz_strays_named(const char *part)
{
    return sweep(NULL, part, 1, 0);
}

void fuzz_clean(const char *const *keep)
{
    sweep(keep, NULL, 0, 1);
}
