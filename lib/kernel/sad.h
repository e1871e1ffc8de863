/*
 * sad.h - internal SAD row kernels. Exactly one implementation file
 * (kernel/sad_<name>.c) is linked, chosen at configure time (SSDA_KERNEL).
 * Every implementation returns the exact sum, bit-identical to portable C.
 */
#ifndef SSDA_KERNEL_SAD_H
#define SSDA_KERNEL_SAD_H

#include <stdint.h>

/* Sum of |a[i] - b[i]| for i < n, n <= 65535.
   Worst case 255 * 65535 = 16 711 425 < 2^32. */
uint32_t ssda_sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n);

/* Sum of |a[i] - b[i]| for i < n, n <= 65535.
   Worst case 65535 * 65535 = 4 294 836 225 < 2^32 - 1. */
uint32_t ssda_sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n);

/* Name of the compiled kernel ("portable", "sse2", "armv7em"). */
const char *ssda_sad_kernel_name(void);

#endif /* SSDA_KERNEL_SAD_H */
