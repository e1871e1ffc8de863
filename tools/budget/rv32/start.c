/* start.c - RV32 C start for the size-budget images: .data copied, .bss
   zeroed, main called (the same work as tests/target/startup.c on ARM). */
#include <stdint.h>

extern uint32_t __data_load__[], __data_start__[], __data_end__[];
extern uint32_t __bss_start__[], __bss_end__[];

int main(void);
void ssda_rv32_start(void);

void ssda_rv32_start(void)
{
    uint32_t *src = __data_load__;
    uint32_t *dst;
    for (dst = __data_start__; dst < __data_end__; dst++) {
        *dst = *src++;
    }
    for (dst = __bss_start__; dst < __bss_end__; dst++) {
        *dst = 0u;
    }
    (void)main();
    for (;;) {
    }
}
