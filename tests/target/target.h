/*
 * target.h - what the Cortex-M test and budget images share: the board hooks
 * called by startup.c, semihosting calls, and the few system registers used.
 */
#ifndef SSDA_TARGET_H
#define SSDA_TARGET_H

#include <stdint.h>

/* System control space (ARMv7-M ARM, B3.2; the same on ARMv6-M/ARMv8-M). */
#define SSDA_TARGET_REG(addr) (*(volatile uint32_t *)(uintptr_t)(addr))
#define SSDA_TARGET_CPACR     0xE000ED88u /* coprocessor access (FPU) */
#define SSDA_TARGET_SYST_CSR  0xE000E010u /* SysTick control and status */
#define SSDA_TARGET_SYST_RVR  0xE000E014u /* SysTick reload value */
#define SSDA_TARGET_SYST_CVR  0xE000E018u /* SysTick current value */

/* Board hooks (weak defaults in startup.c spin; semihost.c overrides). */
void ssda_target_start(void);
__attribute__((noreturn)) void ssda_target_exit(int status);
__attribute__((noreturn)) void ssda_target_fault(uint32_t exception);

/* Semihosting (ARM DUI 0471, "Semihosting operations"), through BKPT 0xAB. */
void ssda_semihost_write0(const char *text);
__attribute__((noreturn)) void ssda_semihost_exit(int status);

#endif /* SSDA_TARGET_H */
