/*
 * startup.c - reset handler and vector table for the Cortex-M test and
 * budget images (ARMv6-M, ARMv7-M, ARMv7E-M, ARMv8-M Mainline).
 *
 * Reset: copy .data from its load address in flash to RAM, zero .bss, turn
 * on the FPU when the code was built for one, run the board hook, then
 * main(); main's return value is the image's exit status.
 *
 * The three hooks are weak so that each image picks its world:
 *   ssda_target_start(void)      before main (semihost.c: newlib's handles)
 *   ssda_target_exit(int)        after main, never returns
 *   ssda_target_fault(uint32_t)  an unexpected exception (IPSR number)
 * The defaults here spin, which is what a size-only firmware wants.
 */
#include <stdint.h>

#include "target.h"

/* Linker-script symbols (tests/target/cortex-m-sections.ld). */
extern uint32_t __data_load__[];
extern uint32_t __data_start__[];
extern uint32_t __data_end__[];
extern uint32_t __bss_start__[];
extern uint32_t __bss_end__[];
extern uint32_t __stack_top__[];

int main(void);

void Reset_Handler(void);
void Default_Handler(void);

__attribute__((weak)) void ssda_target_start(void) {}

__attribute__((weak, noreturn)) void ssda_target_exit(int status)
{
    (void)status;
    for (;;) {
    }
}

__attribute__((weak, noreturn)) void ssda_target_fault(uint32_t exception)
{
    (void)exception;
    for (;;) {
    }
}

void Reset_Handler(void)
{
    uint32_t *src = __data_load__;
    uint32_t *dst;
    for (dst = __data_start__; dst < __data_end__; dst++) {
        *dst = *src++;
    }
    for (dst = __bss_start__; dst < __bss_end__; dst++) {
        *dst = 0u;
    }
#if defined(__ARM_FP)
    /* Full access to CP10 and CP11 (the FPU) before any FP instruction:
       the hard-float ABI may use FP registers anywhere after this. */
    SSDA_TARGET_REG(SSDA_TARGET_CPACR) |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    ssda_target_start();
    ssda_target_exit(main());
}

/* Any exception nobody handles: report its number (IPSR) and stop. */
void Default_Handler(void)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    ssda_target_fault(ipsr & 0x1FFu);
}

void NMI_Handler(void) __attribute__((weak, alias("Default_Handler")));
void HardFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void MemManage_Handler(void) __attribute__((weak, alias("Default_Handler")));
void BusFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void UsageFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SecureFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SVC_Handler(void) __attribute__((weak, alias("Default_Handler")));
void DebugMon_Handler(void) __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SysTick_Handler(void) __attribute__((weak, alias("Default_Handler")));

typedef void (*ssda_vector_t)(void);

/* The architectural part of the table; no device interrupts are enabled by
   the images, so none are listed. Entry 0 is the initial stack pointer. */
__attribute__((section(".vectors"), used))
const ssda_vector_t ssda_vector_table[16] = {
    (ssda_vector_t)(uintptr_t)__stack_top__,
    Reset_Handler,
    NMI_Handler,
    HardFault_Handler,
    MemManage_Handler,
    BusFault_Handler,
    UsageFault_Handler,
    SecureFault_Handler,
    0,
    0,
    0,
    SVC_Handler,
    DebugMon_Handler,
    0,
    PendSV_Handler,
    SysTick_Handler,
};
