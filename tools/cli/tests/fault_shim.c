/*
 * fault_shim.c - an LD_PRELOAD library for the CLI output tests
 * (cli_outputs.sh): faults and observations the tool cannot make itself.
 *   SSDA_SHIM_FAIL_RENAME=NAME  rename() onto a path whose last component is
 *                               NAME fails with EIO (a rename that fails
 *                               after others succeeded: they must be put back)
 *   SSDA_SHIM_FSYNC_LOG=FILE    every fsync() appends the path of its
 *                               descriptor (from /proc/self/fd) to FILE
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int rename(const char *from, const char *to)
{
    int (*real)(const char *, const char *);
    const char *want = getenv("SSDA_SHIM_FAIL_RENAME");
    const char *base = strrchr(to, '/');
    base = base != NULL ? base + 1 : to;
    if (want != NULL && strcmp(base, want) == 0) {
        errno = EIO;
        return -1;
    }
    *(void **)&real = dlsym(RTLD_NEXT, "rename");
    return real(from, to);
}

int fsync(int fd)
{
    int (*real)(int);
    const char *log = getenv("SSDA_SHIM_FSYNC_LOG");
    if (log != NULL) {
        char link[64], path[4096];
        ssize_t n;
        int out;
        snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
        n = readlink(link, path, sizeof path - 1u);
        if (n > 0 && (out = open(log, O_WRONLY | O_CREAT | O_APPEND, 0644)) >= 0) {
            path[n++] = '\n';
            if (write(out, path, (size_t)n) != n) {
                errno = EIO;
            }
            close(out);
        }
    }
    *(void **)&real = dlsym(RTLD_NEXT, "fsync");
    return real(fd);
}
