/* sad_portable.c - SAD row kernels in plain C99: the reference kernel. */
#include "kernel/sad.h"

uint32_t ssda_sad_row_u8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 255 * 65535 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (a[i] > b[i]) ? (uint32_t)(a[i] - b[i]) : (uint32_t)(b[i] - a[i]);
    }
    return sum;
}

uint32_t ssda_sad_row_u16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    uint32_t sum = 0u; /* <= 65535 * 65535 < 2^32 */
    uint32_t i;
    for (i = 0u; i < n; i++) {
        sum += (a[i] > b[i]) ? (uint32_t)a[i] - b[i] : (uint32_t)b[i] - a[i];
    }
    return sum;
}

const char *ssda_sad_kernel_name(void)
{
    return "portable";
}
