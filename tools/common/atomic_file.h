/*
 * atomic_file.h - write output files all or nothing: each output goes to a
 * temp file beside its target and is renamed into place only when every
 * output of the run is complete (docs/cli.md, "Outputs").
 *
 * What a path names decides how it is written:
 *   - a new name or a regular file: temp file + fsync + rename + fsync of
 *     the directory; a replaced file keeps its permission bits;
 *   - a symbolic link: followed (up to 40 links, dangling ones too); its
 *     target is written that way, the link itself stays;
 *   - "-", /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N: the open
 *     descriptor is written directly ("-" and /dev/stdout: stdout);
 *   - a FIFO or a character device (/dev/null, a terminal): written
 *     directly, never replaced;
 *   - a directory: EISDIR; anything else (block device, socket): ENOTSUP
 *     (atomic_file_strerror words it); nothing is written.
 * Temp files are named TARGET.tmp.XXXXXX (the name shortened when the target's
 * name is too long for it) and are deleted on failure, and on SIGINT, SIGTERM
 * or SIGHUP (a handler installed on the first open, unless the signal is
 * ignored; the signal is re-raised after). SIGXFSZ is ignored, so that a
 * file-size limit is a write error (EFBIG) instead of a kill.
 */
#ifndef SSDA_ATOMIC_FILE_H
#define SSDA_ATOMIC_FILE_H
#include <stdio.h>

typedef struct {
    FILE *fp;          /* write here */
    char *final_path;  /* owned: the path as given (for messages) */
    char *target;      /* owned: what is replaced (symlinks followed) */
    char *tmp_path;    /* owned: the temp file; NULL when written directly */
    char *backup;      /* owned: a link to the replaced file during a group commit */
    int through;       /* 1: written directly (stdout, FIFO, device, /dev/fd/N) */
    int replaces;      /* 1: target was an existing regular file */
} atomic_file_t;

/* Would atomic_file_open(path) succeed? Checks what path names and that its
   directory exists and is writable; creates nothing. 0, or -1 with errno. */
int atomic_file_check(const char *path);
/* Open path for writing as described above. Returns 0, or -1 with errno set. */
int atomic_file_open(atomic_file_t *af, const char *path);
/* Flush, fsync, close and rename onto the target. Returns 0 or -1 (errno;
   the temp file is deleted). */
int atomic_file_commit(atomic_file_t *af);
/*
 * Commit n outputs all or nothing: every one is flushed, synced and closed
 * first (any failure: none is renamed); then each is renamed into place; if
 * a rename fails, the outputs already renamed are put back as they were (a
 * replaced file restored from a hard link, or a copy where links are not
 * supported; a new one deleted). A reader of stdout that has gone (EPIPE) is
 * not a failure. Returns 0, or -1 with errno and *failed (may be NULL) the
 * index of the output that failed. Every af is released either way.
 */
int atomic_file_commit_all(atomic_file_t *af, int n, int *failed);
/* Close and delete the temp file (after an error). Safe on a zeroed struct. */
void atomic_file_abort(atomic_file_t *af);
/* strerror(e), with ENOTSUP worded as atomic_file_open means it. */
const char *atomic_file_strerror(int e);
/* Is standard output a pipe whose reader has gone? */
int atomic_file_stdout_gone(void);
/* After a failed write to stdout whose errno stdio did not keep: why it
   failed (EBADF when closed; else the errno of one probing newline, the
   output being incomplete anyway; EIO when that succeeds). */
int atomic_file_stdout_errno(void);

#endif
