/* slide.c - the band slide (slide.h). */
#include <string.h>

#include "slide.h"

void ssda__slide(void *buf, size_t from, size_t end)
{
    unsigned char *b = (unsigned char *)buf;
    size_t done = 0u; /* bytes moved so far */
    while (from + done < end) {
        size_t n = end - from - done < from ? end - from - done : from;
        (void)memcpy(b + done, b + from + done, n);
        done += n;
    }
}
