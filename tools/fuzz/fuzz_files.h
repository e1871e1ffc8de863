/*
 * fuzz_files.h - a private temporary folder for the targets that read
 * files (the PNG and WAV readers, the CLI): inputs are written there, and
 * anything a run leaves behind is found and reported. The folder and its
 * contents are removed when the process exits.
 */
#ifndef SSDA_FUZZ_FILES_H
#define SSDA_FUZZ_FILES_H

#include <stddef.h>
#include <stdint.h>

/* The folder (created on the first call; aborts if it cannot be). */
const char *fuzz_dir(void);

/* "folder/name" into buf (len bytes). Returns buf. */
char *fuzz_path(const char *name, char *buf, size_t len);

/* Write n bytes to folder/name (replacing it); path into buf. Returns buf. */
char *fuzz_write(const char *name, const uint8_t *data, size_t n, char *buf, size_t len);

/* Entries of the folder not named in keep (a NULL-terminated list), each
   printed to stderr. */
size_t fuzz_strays(const char *const *keep);

/* Entries whose name contains part (e.g. atomic_file's ".tmp."), printed. */
size_t fuzz_strays_named(const char *part);

/* Remove every entry of the folder except those named in keep. */
void fuzz_clean(const char *const *keep);

#endif /* SSDA_FUZZ_FILES_H */
