/*
 * state.h - internal: the one validity test of the library's stateful
 * objects (ssda_source_t, ssda_push_t, ssda_pitch_t, ssda_kl_acc_t,
 * ssda_kl_t, ssda_region_t), lwrb style. Each
 * carries a private `magic` field that its init function writes last, with
 * a value of its own type; every later call compares it before touching
 * anything else. A zero-filled object (static storage, memset) is never
 * valid, nor one of another type; one holding leftover bytes is refused
 * unless they happen to spell the value.
 */
#ifndef SSDA_STATE_H
#define SSDA_STATE_H

#include <stdbool.h>
#include <stdint.h>

#define SSDA__MAGIC_SOURCE 0x53524345u /* "SRCE" */
#define SSDA__MAGIC_PUSH 0x50555348u   /* "PUSH" */
#define SSDA__MAGIC_PITCH 0x50495443u  /* "PITC" */
#define SSDA__MAGIC_KL_ACC 0x4B4C4143u /* "KLAC" */
#define SSDA__MAGIC_KL 0x4B4C5458u     /* "KLTX" */
#define SSDA__MAGIC_REGION 0x52454749u /* "REGI" */

/* Whether an object whose magic field holds `magic` was initialised as a
   `kind` (one of the values above). */
static inline bool ssda__valid(uint32_t magic, uint32_t kind)
{
    return magic == kind;
}

#endif /* SSDA_STATE_H */
