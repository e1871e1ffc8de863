/* atomic_file.c - temp file + rename. */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static unsigned long counter; /* temp names differ within one process */

int atomic_file_open(atomic_file_t *af, const char *path)
{
    size_t n = strlen(path);
    struct stat st;
    int fd, tries = 0;
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
    /* Not mkstemp: its 0600 would become the output's mode. open() with 0666
       gets what fopen() would give (the umask applies, no need to read it);
       O_EXCL keeps the name ours. */
    do {
        snprintf(af->tmp_path, n + 16, "%s.tmp.%06lx", path,
                 (unsigned long)(((unsigned long)getpid() * 7919u + counter++) & 0xffffffu));
        fd = open(af->tmp_path, O_WRONLY | O_CREAT | O_EXCL, 0666);
    } while (fd < 0 && errno == EEXIST && ++tries < 100);
    /* Replacing a file keeps its mode, as overwriting it in place would. */
    if (fd >= 0 && stat(path, &st) == 0 && S_ISREG(st.st_mode) &&
        fchmod(fd, st.st_mode & 07777) != 0) {
        int e = errno;
        close(fd);
        unlink(af->tmp_path);
        errno = e;
        fd = -1;
    }
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

/* Is standard output a pipe whose reader has gone? stdio keeps no errno of
   an earlier failed write (fflush may then return 0 with the error flag
   set), so ask the descriptor: poll reports POLLERR for such a pipe. */
static int stdout_pipe_closed(void)
{
    struct pollfd p;
    p.fd = STDOUT_FILENO;
    p.events = POLLOUT;
    p.revents = 0;
    return poll(&p, 1, 0) == 1 && (p.revents & POLLERR) != 0;
}

int atomic_file_commit(atomic_file_t *af)
{
    int bad;
    if (af->fp == stdout) {
        /* EPIPE: the reader closed the pipe (| head) and wants no more; not a
           failure (the tools ignore SIGPIPE to get here) */
        errno = 0;
        if (fflush(stdout) == 0 && !ferror(stdout)) {
            return 0;
        }
        return errno == EPIPE || stdout_pipe_closed() ? 0 : -1;
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
