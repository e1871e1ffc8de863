/* tool_err.c - error messages into a caller's buffer. */
#include "tool_err.h"

#include <stdarg.h>
#include <stdio.h>

void tool_set_err(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (err == NULL || errlen == 0) {
        return;
    }
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}
