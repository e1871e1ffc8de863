/*
 * fuzz_input.h - reading a fuzzer's byte string as a stream of choices, and
 * the harnesses' assertion. Once the bytes run out every read returns 0, so
 * any prefix of an input is an input too (libFuzzer shrinks by cutting).
 */
#ifndef SSDA_FUZZ_INPUT_H
#define SSDA_FUZZ_INPUT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    const uint8_t *p;
    size_t n;
} fuzz_in_t;

static inline uint32_t fuzz_u8(fuzz_in_t *in)
{
    if (in->n == 0) {
        return 0;
    }
    in->n--;
    return *in->p++;
}

static inline uint32_t fuzz_u16(fuzz_in_t *in)
{
    uint32_t lo = fuzz_u8(in);
    return lo | (fuzz_u8(in) << 8);
}

static inline uint32_t fuzz_u32(fuzz_in_t *in)
{
    uint32_t lo = fuzz_u16(in);
    return lo | (fuzz_u16(in) << 16);
}

static inline uint64_t fuzz_u64(fuzz_in_t *in)
{
    uint64_t lo = fuzz_u32(in);
    return lo | ((uint64_t)fuzz_u32(in) << 32);
}

/* A value in lo..hi (inclusive; hi - lo < 2^32), from as few bytes as the
   range needs. */
static inline uint32_t fuzz_range(fuzz_in_t *in, uint32_t lo, uint32_t hi)
{
    uint32_t span = hi - lo, v;
    if (span == 0) {
        return lo;
    }
    v = span < 256u ? fuzz_u8(in) : span < 65536u ? fuzz_u16(in) : fuzz_u32(in);
    return span == UINT32_MAX ? v : lo + v % (span + 1u);
}

/* True with probability about 1 / n (n >= 1). */
static inline int fuzz_one_in(fuzz_in_t *in, uint32_t n)
{
    return fuzz_range(in, 0, n - 1u) == 0;
}

/* Up to n of the remaining bytes; *len receives how many. */
static inline const uint8_t *fuzz_bytes(fuzz_in_t *in, size_t n, size_t *len)
{
    const uint8_t *p = in->p;
    if (n > in->n) {
        n = in->n;
    }
    in->p += n;
    in->n -= n;
    *len = n;
    return p;
}

/* A broken invariant: print it and abort, so libFuzzer keeps the input. */
#define FUZZ_CHECK(cond)                                                                 \
    do {                                                                                 \
        if (!(cond)) {                                                                   \
            fprintf(stderr, "fuzz check failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__); \
            abort();                                                                     \
        }                                                                                \
    } while (0)

#endif /* SSDA_FUZZ_INPUT_H */
