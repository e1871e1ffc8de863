/*
 * slide.h - internal: the one band-slide routine, shared by the plate cache
 * (stream_plate.c), the push ring (stream_push.c) and the pitch buffer
 * (pitch.c): the part of a buffer still needed moves to its start.
 */
#ifndef SSDA_SLIDE_H
#define SSDA_SLIDE_H

#include <stddef.h>

#include "compiler.h"

/* Move bytes [from, end) of buf to [0, end - from) (0 < from <= end). By
   memcpy in blocks of at most `from` bytes, front to back, so that no
   block's source and destination overlap (memmove is not in the library's
   freestanding set). */
SSDA_INTERNAL void ssda__slide(void *buf, size_t from, size_t end);

#endif /* SSDA_SLIDE_H */
