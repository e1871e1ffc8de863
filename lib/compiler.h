/* compiler.h - internal: compiler hints, empty where unsupported. */
#ifndef SSDA_COMPILER_H
#define SSDA_COMPILER_H

/* Keep a cold or rarely-run function out of its callers: its locals then
   stay off their frames, which bounds the worst-case stack of the hot
   chains (docs/target.md). Never changes a result. */
#if defined(__GNUC__) || defined(__clang__)
#define SSDA_NOINLINE __attribute__((noinline))
#else
#define SSDA_NOINLINE
#endif

/* Inline a small fast path even at -Os, where a call would stack one more
   frame on a deep chain. Never changes a result. */
#if defined(__GNUC__) || defined(__clang__)
#define SSDA_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SSDA_ALWAYS_INLINE inline
#endif

#endif /* SSDA_COMPILER_H */
