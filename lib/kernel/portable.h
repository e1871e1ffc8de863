/*
 * portable.h - reference inner loops in plain C99, as static inline
 * functions: used by kernel_portable.c, by accelerated kernels for the loops
 * they do not speed up, and by tests as the bit-exact reference.
 */
#ifndef SSDA_KERNEL_PORTABLE_H
#define SSDA_KERNEL_PORTABLE_H

#include <stdint.h>

static inline uint32_t ssda__portable_sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 255 * 65535 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (a[i] > b[i]) ? (uint32_t)a[i] - b[i] : (uint32_t)b[i] - a[i];
    }
    return sum;
}

static inline uint32_t ssda__portable_sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65535 * 65535 < 2^32 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (a[i] > b[i]) ? (uint32_t)a[i] - b[i] : (uint32_t)b[i] - a[i];
    }
    return sum;
}

static inline uint32_t ssda__portable_absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65535 * 65535 < 2^32 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        /* int32_t difference: -65535..65535, no overflow */
        int32_t d = (int32_t)a[i] - (int32_t)b[i];
        sum += (d < 0) ? (uint32_t)(-d) : (uint32_t)d;
    }
    return sum;
}

/* Products of one row (correlation): n <= 65536 pixels, so the 8-bit sum
   <= 65536 * 255^2 < 2^32 and the 16-bit one <= 65536 * 65535^2 < 2^48. */
static inline uint32_t ssda__portable_dot_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65536 * 65025 < 2^32 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (uint32_t)a[i] * b[i];
    }
    return sum;
}

static inline uint64_t ssda__portable_dot_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    uint64_t sum = 0u; /* <= 65536 * 65535^2 < 2^48 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (uint64_t)((uint32_t)a[i] * b[i]); /* one product < 2^32 */
    }
    return sum;
}

#endif /* SSDA_KERNEL_PORTABLE_H */
