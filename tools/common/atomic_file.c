/* atomic_file.c - all-or-nothing outputs: temp file, fsync, rename (rules in
   atomic_file.h). */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_LINKS 40      /* symlinks followed, as the kernel's limit */
#define TMP_SUFFIX_LEN 11 /* ".tmp." and 6 hex digits */
#define MAX_PENDING 64    /* temp files alive at once that a signal deletes */

/* ---- temp files deleted on SIGINT, SIGTERM, SIGHUP ---- */

static const char *volatile pending[MAX_PENDING];
static const int cleanup_signals[] = {SIGINT, SIGTERM, SIGHUP};
#define NSIGNALS (sizeof cleanup_signals / sizeof cleanup_signals[0])

/* Async-signal-safe: unlink, signal and raise only. The signal stays blocked
   while the handler runs, so the re-raised one is delivered, with the
   default action, as the handler returns. */
static void on_signal(int sig)
{
    int i;
    for (i = 0; i < MAX_PENDING; i++) {
        const char *p = pending[i];
        if (p != NULL) {
            unlink(p);
        }
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

static void block_signals(sigset_t *old)
{
    sigset_t s;
    size_t i;
    sigemptyset(&s);
    for (i = 0; i < NSIGNALS; i++) {
        sigaddset(&s, cleanup_signals[i]);
    }
    sigprocmask(SIG_BLOCK, &s, old);
}

static void restore_signals(const sigset_t *old)
{
    sigprocmask(SIG_SETMASK, old, NULL);
}

/* Once per process. A signal ignored on entry (nohup, a background job)
   stays ignored. */
static void install_handlers(void)
{
    static int installed;
    struct sigaction sa, old;
    size_t i;
    if (installed) {
        return;
    }
    installed = 1;
    signal(SIGXFSZ, SIG_IGN); /* a file-size limit: EFBIG from write() instead */
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (i = 0; i < NSIGNALS; i++) {
        sigaddset(&sa.sa_mask, cleanup_signals[i]);
    }
    for (i = 0; i < NSIGNALS; i++) {
        if (sigaction(cleanup_signals[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN) {
            sigaction(cleanup_signals[i], &sa, NULL);
        }
    }
}

/* Called with the signals blocked. */
static void pending_set(const char *from, const char *to)
{
    int i;
    for (i = 0; i < MAX_PENDING; i++) {
        if (pending[i] == from) {
            pending[i] = to;
            return;
        }
    }
}

static void pending_remove(const char *p)
{
    sigset_t old;
    if (p != NULL) {
        block_signals(&old);
        pending_set(p, NULL);
        restore_signals(&old);
    }
}

/* ---- what a path names ---- */

enum { K_NEW, K_FILE, K_THROUGH, K_FD };

/* The descriptor a path names (/dev/stdout, /dev/stderr, /dev/fd/N,
   /proc/self/fd/N), or -1. Opening those names would reopen what the
   descriptor points to (truncating a file that the shell redirected
   stdout to, or failing for a pipe): they are written through it instead. */
static int named_fd(const char *path)
{
    const char *p = NULL;
    char *end;
    long v;
    if (strcmp(path, "/dev/stdout") == 0) {
        return 1;
    }
    if (strcmp(path, "/dev/stderr") == 0) {
        return 2;
    }
    if (strncmp(path, "/dev/fd/", 8) == 0) {
        p = path + 8;
    } else if (strncmp(path, "/proc/self/fd/", 14) == 0) {
        p = path + 14;
    }
    if (p == NULL || *p < '0' || *p > '9') {
        return -1;
    }
    errno = 0;
    v = strtol(p, &end, 10);
    return *end == '\0' && errno == 0 && v <= INT_MAX ? (int)v : -1;
}

/* The directory part of path ("." when none), malloc'ed. */
static char *dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL) {
        return strdup(".");
    }
    if (slash == path) {
        return strdup("/");
    }
    return strndup(path, (size_t)(slash - path));
}

/* A new file can be made beside path (the temp file, then the rename). */
static int dir_writable(const char *path)
{
    char *dir = dir_of(path);
    int rc, e;
    if (dir == NULL) {
        errno = ENOMEM;
        return -1;
    }
    rc = access(dir, W_OK | X_OK);
    e = errno;
    free(dir);
    errno = e;
    return rc;
}

/* The link cur points to, as a path (relative targets are taken from the
   link's directory). Frees cur. */
static char *follow(char *cur, size_t link_size)
{
    char *target = malloc(link_size + 2u), *out = NULL;
    ssize_t n = target != NULL ? readlink(cur, target, link_size + 1u) : -1;
    if (n >= 0 && (size_t)n <= link_size) {
        target[n] = '\0';
        if (target[0] == '/' || strchr(cur, '/') == NULL) {
            out = strdup(target);
        } else {
            size_t d = (size_t)(strrchr(cur, '/') - cur) + 1u;
            out = malloc(d + (size_t)n + 1u);
            if (out != NULL) {
                memcpy(out, cur, d);
                memcpy(out + d, target, (size_t)n + 1u);
            }
        }
    } else if (n >= 0) {
        errno = EAGAIN; /* the link changed while read */
    }
    if (out == NULL && errno == 0) {
        errno = ENOMEM;
    }
    free(target);
    free(cur);
    return out;
}

/* Follow path's symlinks and say how it is written: K_* (*out: the final
   name, malloc'ed; *fd for K_FD; *mode for K_FILE), or -1 with errno. */
static int classify(const char *path, char **out, int *fd, mode_t *mode)
{
    char *cur = strdup(path);
    int hops, e;
    size_t n = strlen(path);
    if (n > 0 && path[n - 1] == '/') { /* "DIR/": a directory, existing or not */
        free(cur);
        errno = EISDIR;
        return -1;
    }
    for (hops = 0; cur != NULL; hops++) {
        struct stat st;
        if ((*fd = named_fd(cur)) >= 0) {
            *out = cur;
            return K_FD;
        }
        if (lstat(cur, &st) != 0) {
            if (errno != ENOENT || dir_writable(cur) != 0) {
                break;
            }
            *out = cur;
            return K_NEW;
        }
        if (S_ISLNK(st.st_mode)) {
            if (hops == MAX_LINKS) {
                errno = ELOOP;
                break;
            }
            errno = 0;
            cur = follow(cur, (size_t)st.st_size > 0 ? (size_t)st.st_size : PATH_MAX);
            continue;
        }
        *mode = st.st_mode;
        if (S_ISREG(st.st_mode)) {
            if (dir_writable(cur) != 0) {
                break;
            }
            *out = cur;
            return K_FILE;
        }
        if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
            *out = cur;
            return K_THROUGH;
        }
        errno = S_ISDIR(st.st_mode) ? EISDIR : ENOTSUP;
        break;
    }
    e = cur != NULL ? errno : (errno != 0 ? errno : ENOMEM);
    free(cur);
    errno = e;
    return -1;
}

/* ---- temp names ---- */

/* A fresh candidate name beside target: TARGET.tmp.XXXXXX, the target's
   name shortened so that the temp name fits the file system's limit (a
   valid 251-character name must still work). malloc'ed. */
static char *temp_name(const char *target)
{
    static unsigned long counter; /* names differ within one process */
    const char *slash = strrchr(target, '/');
    size_t dirlen = slash != NULL ? (size_t)(slash - target) + 1u : 0u;
    size_t keep = strlen(target + dirlen), size;
    char *dir = dir_of(target), *tmp;
    long name_max = dir != NULL ? pathconf(dir, _PC_NAME_MAX) : -1;
    free(dir);
    if (name_max < 2 * TMP_SUFFIX_LEN) {
        name_max = 255; /* unknown: the common limit */
    }
    if (keep + TMP_SUFFIX_LEN > (size_t)name_max) {
        keep = (size_t)name_max - TMP_SUFFIX_LEN;
    }
    size = dirlen + keep + TMP_SUFFIX_LEN + 1u;
    tmp = malloc(size);
    if (tmp != NULL) {
        unsigned long r = ((unsigned long)getpid() * 7919u + counter++) & 0xffffffu;
        snprintf(tmp, size, "%.*s%.*s.tmp.%06lx", (int)dirlen, target, (int)keep,
                 target + dirlen, r);
    } else {
        errno = ENOMEM;
    }
    return tmp;
}

/* Create a temp file beside target, registered for the signal handler.
   Returns the descriptor (*name malloc'ed) or -1. Not mkstemp: its 0600
   would become the output's mode; open() with 0666 gets what fopen()
   would give (the umask applies); O_EXCL keeps the name ours. */
static int create_temp(const char *target, mode_t mode, char **name)
{
    int fd = -1, tries, e = EEXIST;
    sigset_t old;
    *name = NULL;
    for (tries = 0; tries < 100 && fd < 0 && e == EEXIST; tries++) {
        free(*name);
        if ((*name = temp_name(target)) == NULL) {
            return -1;
        }
        block_signals(&old);
        fd = open(*name, O_WRONLY | O_CREAT | O_EXCL, mode);
        e = errno;
        if (fd >= 0) {
            pending_set(NULL, *name);
        }
        restore_signals(&old);
    }
    if (fd < 0) {
        free(*name);
        *name = NULL;
        errno = e;
    }
    return fd;
}

/* ---- open, commit, abort ---- */

/* K_FD: stdout itself, or a duplicate of the named descriptor. */
static int open_fd(atomic_file_t *af, int fd)
{
    int d;
    af->through = 1;
    if (fd == STDOUT_FILENO) {
        af->fp = stdout;
        return 0;
    }
    if ((d = dup(fd)) < 0) {
        return -1;
    }
    if ((af->fp = fdopen(d, "wb")) == NULL) {
        int e = errno;
        close(d);
        errno = e;
        return -1;
    }
    return 0;
}

/* K_NEW, K_FILE: a temp file beside the target, with the replaced file's mode. */
static int open_temp(atomic_file_t *af, int kind, mode_t mode)
{
    int fd = create_temp(af->target, 0666, &af->tmp_path), e;
    if (fd < 0) {
        return -1;
    }
    af->replaces = kind == K_FILE;
    if ((kind == K_FILE && fchmod(fd, mode & 07777) != 0) ||
        (af->fp = fdopen(fd, "wb")) == NULL) {
        e = errno;
        close(fd);
        errno = e;
        return -1;
    }
    return 0;
}

int atomic_file_open(atomic_file_t *af, const char *path)
{
    int kind, fd = -1, rc, e;
    mode_t mode = 0;
    memset(af, 0, sizeof *af);
    install_handlers();
    if ((af->final_path = strdup(path)) == NULL) {
        errno = ENOMEM;
        return -1;
    }
    if (strcmp(path, "-") == 0) {
        af->through = 1;
        af->fp = stdout;
        return 0;
    }
    kind = classify(path, &af->target, &fd, &mode);
    if (kind == K_FD) {
        rc = open_fd(af, fd);
    } else if (kind == K_THROUGH) {
        /* a FIFO waits here for its reader, as the shell's > would */
        fd = open(af->target, O_WRONLY | O_NOCTTY);
        af->through = 1;
        rc = fd < 0 || (af->fp = fdopen(fd, "wb")) == NULL ? -1 : 0;
        if (rc != 0 && fd >= 0) {
            e = errno;
            close(fd);
            errno = e;
        }
    } else {
        rc = kind < 0 ? -1 : open_temp(af, kind, mode);
    }
    if (rc != 0) {
        e = errno;
        atomic_file_abort(af);
        errno = e;
    }
    return rc;
}

int atomic_file_check(const char *path)
{
    char *target = NULL;
    int fd = -1, kind;
    mode_t mode;
    if (strcmp(path, "-") == 0) {
        return 0;
    }
    kind = classify(path, &target, &fd, &mode);
    free(target);
    if (kind == K_FD && fcntl(fd, F_GETFD) == -1) {
        return -1; /* EBADF */
    }
    return kind < 0 ? -1 : 0;
}

const char *atomic_file_strerror(int e)
{
    return e == ENOTSUP ? "not a regular file, FIFO or character device (not replaced)"
                        : strerror(e);
}

/* Is standard output a pipe whose reader has gone? stdio keeps no errno of
   an earlier failed write (fflush may then return 0 with the error flag
   set), so ask the descriptor: poll reports POLLERR for such a pipe. */
int atomic_file_stdout_gone(void)
{
    struct pollfd p;
    p.fd = STDOUT_FILENO;
    p.events = POLLOUT;
    p.revents = 0;
    return poll(&p, 1, 0) == 1 && (p.revents & POLLERR) != 0;
}

int atomic_file_stdout_errno(void)
{
    int fl = fcntl(STDOUT_FILENO, F_GETFL);
    if (fl == -1 || (fl & O_ACCMODE) == O_RDONLY) {
        return EBADF; /* closed, or held by /dev/null read-only (cli_guard_std_fds) */
    }
    /* What is written is already incomplete: one newline more says why
       (ENOSPC, EFBIG, EIO) where stdio kept no errno. */
    errno = 0;
    if (write(STDOUT_FILENO, "\n", 1) < 0 && errno != 0) {
        return errno;
    }
    return EIO;
}

/* Flush and close one output (fsync a temp file). A reader that has gone
   (EPIPE on stdout or a FIFO) is not a failure. Returns 0 or -1 (errno). */
static int finish_one(atomic_file_t *af)
{
    int bad, e;
    errno = 0;
    if (af->fp == stdout) {
        if ((fflush(stdout) == 0 && !ferror(stdout)) || errno == EPIPE ||
            atomic_file_stdout_gone()) {
            return 0;
        }
        errno = errno != 0 ? errno : atomic_file_stdout_errno();
        return -1;
    }
    bad = fflush(af->fp) != 0 || ferror(af->fp);
    if (bad && af->tmp_path != NULL && (errno == 0 || errno == EBADF)) {
        /* stdio keeps no errno of an earlier failed write: one byte more at
           the temp file's end (deleted anyway) says why (ENOSPC, EFBIG) */
        errno = 0;
        (void)!write(fileno(af->fp), "", 1);
    }
    if (!bad && af->tmp_path != NULL && fsync(fileno(af->fp)) != 0) {
        bad = 1;
    }
    e = errno;
    if (fclose(af->fp) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    af->fp = NULL;
    if (!bad || (af->through && e == EPIPE)) {
        return 0;
    }
    errno = e != 0 ? e : EIO;
    return -1;
}

/* Copy a file whose hard link cannot be made (file systems without links). */
static int copy_file(const char *from, int to)
{
    char buf[65536];
    ssize_t n = 0, w;
    int in = open(from, O_RDONLY), rc = -1;
    while (in >= 0 && (n = read(in, buf, sizeof buf)) > 0) {
        char *p = buf;
        while (n > 0 && (w = write(to, p, (size_t)n)) > 0) {
            p += w;
            n -= w;
        }
        if (n > 0) {
            break;
        }
    }
    if (in >= 0 && n == 0) {
        rc = 0;
    }
    if (in >= 0) {
        close(in);
    }
    return rc;
}

/* Keep the file af is about to replace under a temp name, so that a failed
   group commit can put it back. Called with the signals blocked. */
static int make_backup(atomic_file_t *af)
{
    int tries, fd, e = EEXIST;
    struct stat st;
    for (tries = 0; tries < 100 && e == EEXIST; tries++) {
        free(af->backup);
        if ((af->backup = temp_name(af->target)) == NULL) {
            return -1;
        }
        if (link(af->target, af->backup) == 0) {
            pending_set(NULL, af->backup);
            return 0;
        }
        e = errno;
    }
    if (e == EEXIST || stat(af->target, &st) != 0) {
        free(af->backup);
        af->backup = NULL;
        errno = e;
        return -1;
    }
    fd = create_temp(af->target, st.st_mode & 07777, &af->backup); /* no links: a copy */
    if (fd >= 0 && copy_file(af->target, fd) == 0 && close(fd) == 0) {
        return 0;
    }
    e = errno;
    if (fd >= 0) {
        close(fd);
    }
    if (af->backup != NULL) { /* the partial copy */
        unlink(af->backup);
        pending_set(af->backup, NULL);
        free(af->backup);
        af->backup = NULL;
    }
    errno = e;
    return -1;
}

/* fsync the directory holding path, so that the rename survives a power
   loss. File systems that cannot sync a directory (EINVAL) are let be. */
static int sync_dir(const char *path)
{
    char *dir = dir_of(path);
    int fd = dir != NULL ? open(dir, O_RDONLY | O_DIRECTORY) : -1, rc = 0;
    free(dir);
    if (fd < 0 || (fsync(fd) != 0 && errno != EINVAL)) {
        rc = -1;
    }
    if (fd >= 0) {
        close(fd);
    }
    return rc;
}

/* Put back the outputs renamed before af[failed]: a replaced file from its
   backup, a new one deleted. Called with the signals blocked. */
static void roll_back(atomic_file_t *af, int failed)
{
    int j;
    for (j = 0; j < failed; j++) {
        if (af[j].through) {
            continue;
        }
        if (af[j].backup != NULL) {
            if (rename(af[j].backup, af[j].target) == 0) {
                pending_set(af[j].backup, NULL);
                free(af[j].backup);
                af[j].backup = NULL;
            }
        } else if (!af[j].replaces) {
            unlink(af[j].target);
        }
    }
}

static void release_all(atomic_file_t *af, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        atomic_file_abort(&af[i]);
    }
}

/* Rename every finished temp file into place (signals blocked by the
   caller). Returns 0, or -1 with errno and *failed after rolling back. */
static int rename_all(atomic_file_t *af, int n, int *failed)
{
    int i, last = -1, e;
    for (i = 0; i < n; i++) {
        last = af[i].tmp_path != NULL ? i : last;
    }
    for (i = 0; i < n; i++) { /* the last rename needs no way back */
        if (af[i].tmp_path != NULL && af[i].replaces && i != last && make_backup(&af[i]) != 0) {
            *failed = i;
            return -1;
        }
    }
    for (i = 0; i < n; i++) {
        if (af[i].tmp_path == NULL) {
            continue;
        }
        if (rename(af[i].tmp_path, af[i].target) != 0) {
            e = errno;
            roll_back(af, i);
            *failed = i;
            errno = e;
            return -1;
        }
        pending_set(af[i].tmp_path, NULL);
        free(af[i].tmp_path);
        af[i].tmp_path = NULL;
    }
    for (i = 0; i < n; i++) {
        if (!af[i].through && sync_dir(af[i].target) != 0) {
            *failed = i;
            return -1; /* in place, but not known to be durable */
        }
    }
    return 0;
}

int atomic_file_commit_all(atomic_file_t *af, int n, int *failed)
{
    sigset_t old;
    int i, bad = -1, rc = 0, e = 0;
    for (i = 0; i < n && rc == 0; i++) {
        if (finish_one(&af[i]) != 0) {
            rc = -1;
            bad = i;
            e = errno;
        }
    }
    if (rc == 0) {
        /* no signal between the first rename and the last (or the roll-back) */
        block_signals(&old);
        rc = rename_all(af, n, &bad);
        e = errno;
        release_all(af, n); /* deletes backups and what was not renamed */
        restore_signals(&old);
    } else {
        release_all(af, n);
    }
    if (failed != NULL) {
        *failed = bad;
    }
    errno = e;
    return rc;
}

int atomic_file_commit(atomic_file_t *af)
{
    return atomic_file_commit_all(af, 1, NULL);
}

void atomic_file_abort(atomic_file_t *af)
{
    if (af->fp != NULL && af->fp != stdout) {
        fclose(af->fp);
    }
    af->fp = NULL;
    if (af->tmp_path != NULL) {
        unlink(af->tmp_path);
        pending_remove(af->tmp_path);
    }
    if (af->backup != NULL) {
        unlink(af->backup);
        pending_remove(af->backup);
    }
    free(af->tmp_path);
    free(af->backup);
    free(af->target);
    free(af->final_path);
    memset(af, 0, sizeof *af);
}
