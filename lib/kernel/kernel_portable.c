/* kernel_portable.c - the portable C kernel set (the reference). */
#include "kernel/kernels.h"
#include "kernel/portable.h"

uint32_t ssda__sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    return ssda__portable_sad_row_u8(a, b, n);
}

uint32_t ssda__sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    return ssda__portable_sad_row_u16(a, b, n);
}

uint32_t ssda__absdiff_row_i16(const int16_t *a, const int16_t *b, uint32_t n)
{
    return ssda__portable_absdiff_row_i16(a, b, n);
}

const char *ssda__kernel_name(void)
{
    return "portable";
}
