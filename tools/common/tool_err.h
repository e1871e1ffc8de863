/* tool_err.h - the one way tools/common reports an error to its caller: a
   one-line message written into the caller's buffer. */
#ifndef SSDA_TOOL_ERR_H
#define SSDA_TOOL_ERR_H

#include <stddef.h>

/* printf into err (errlen bytes, truncated); nothing when err is NULL or
   errlen 0. */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
void tool_set_err(char *err, size_t errlen, const char *fmt, ...);

#endif
