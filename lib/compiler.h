/* compiler.h - internal: compiler hints, empty where unsupported. */
#ifndef SSDA_COMPILER_H
#define SSDA_COMPILER_H

/*
 * SEALED LIBRARY. Only the functions of include/ssda/<module>.h are the library's
 * interface. Everything else in lib/ is `static`, or, when several lib
 * files share it, carries the reserved prefix `ssda__` (two underscores),
 * is declared in an internal header of lib/ (never in include/), and is
 * marked SSDA_INTERNAL there:
 *
 *     SSDA_INTERNAL int ssda__match_rows(const ssda__rows_t *area, ...);
 *
 * SSDA_INTERNAL gives the symbol hidden visibility where the toolchain has
 * it (GCC and Clang on ELF targets): a shared object or firmware image
 * built from libssda.a then exports no internal name. The static library
 * still holds them as global symbols (several objects share them), hence
 * the prefix: a user's firmware cannot collide with a name it could not
 * write by accident. The test lib_symbols (cmake/CheckSymbols.cmake) lists
 * the built library's symbols with nm and fails on any defined global name
 * that is neither declared in include/ssda/<module>.h nor prefixed `ssda__`.
 */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(_WIN32) && !defined(__CYGWIN__)
#define SSDA_INTERNAL __attribute__((visibility("hidden")))
#else
#define SSDA_INTERNAL
#endif

/* Keep a cold or rarely-run function out of its callers: its locals then
   stay off their frames, which bounds the worst-case stack of the hot
   chains (docs/target.md). Never changes a result. */
#if defined(__GNUC__) || defined(__clang__)
#define SSDA_NOINLINE __attribute__((noinline))
#else
#define SSDA_NOINLINE
#endif

/* One shared copy of a small helper in a build for size (-Os defines
   __OPTIMIZE_SIZE__: a call is shorter than each inlined copy on Thumb-1),
   inlined as the compiler sees fit otherwise (-O2, where the instruction
   counts are measured). Never changes a result. */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE_SIZE__)
#define SSDA_SIZE_NOINLINE __attribute__((noinline))
#else
#define SSDA_SIZE_NOINLINE
#endif

/* Inline a small fast path even at -Os, where a call would stack one more
   frame on a deep chain. Never changes a result. */
#if defined(__GNUC__) || defined(__clang__)
#define SSDA_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SSDA_ALWAYS_INLINE inline
#endif

#endif /* SSDA_COMPILER_H */
