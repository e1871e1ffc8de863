/*
 * libc_min.c - memcpy and memset for the freestanding RV32 images (the
 * compiler comes without a C library). Plain byte loops: compiled with
 * -fno-tree-loop-distribute-patterns, or GCC would turn them back into
 * calls to themselves.
 */
#include <string.h>

void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    const unsigned char *s = (const unsigned char *)src;
    while (n-- > 0u) {
        *d++ = *s++;
    }
    return dst;
}

void *memset(void *dst, int c, size_t n)
{
    unsigned char *d = (unsigned char *)dst;
    while (n-- > 0u) {
        *d++ = (unsigned char)c;
    }
    return dst;
}
