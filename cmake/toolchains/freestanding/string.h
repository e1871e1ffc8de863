/*
 * string.h for freestanding builds (rv32imc.cmake: the compiler comes
 * without a C library). It declares only the two C library functions the
 * ssda library may call, so that any other use fails to compile there; the
 * firmware links its own memcpy and memset (every libc has them, and GCC may
 * emit calls to them even in freestanding code).
 */
#ifndef SSDA_FREESTANDING_STRING_H
#define SSDA_FREESTANDING_STRING_H

#include <stddef.h>

void *memcpy(void *restrict dst, const void *restrict src, size_t n);
void *memset(void *dst, int c, size_t n);

#endif /* SSDA_FREESTANDING_STRING_H */
