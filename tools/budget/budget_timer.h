/*
 * budget_timer.h - instruction counts and stack peaks on an emulated
 * Cortex-M (qemu-system-arm -icount shift=0, see tools/budget.sh).
 *
 * With -icount shift=0 QEMU advances virtual time by exactly 1 ns per
 * executed instruction, and the MPS2 boards clock SysTick from the 25 MHz
 * system clock (CLKSOURCE = 1): one SysTick count = 40 instructions. The
 * 24-bit counter is read before and after a job; jobs must stay below
 * 2^24 counts (671 million instructions), which every job here does.
 */
#ifndef SSDA_BUDGET_TIMER_H
#define SSDA_BUDGET_TIMER_H

#include <stdint.h>

#define BUDGET_INSTR_PER_TICK 40u

typedef void (*budget_job_fn)(void *ctx);

/* Start SysTick free-running from 0xFFFFFF at the processor clock. */
void budget_timer_init(void);

/* Instructions spent in job(ctx), less the cost of an empty job (the
   call and the two counter reads), to within +-40. */
uint32_t budget_instructions(budget_job_fn job, void *ctx);

/* Bytes of stack job(ctx) used below the caller's stack pointer (found by
   painting 8 KiB of free stack with a pattern before the call). */
uint32_t budget_stack_peak(budget_job_fn job, void *ctx);

/* One line of the result protocol tools/budget.sh reads:
   "RESULT <name> <instructions> <units> <stack bytes> <work>": a job of
   <units> items (pixels, windows, frames) took <instructions>, peaked at
   <stack bytes> of stack, and did <work> library operations (pixel_ops or
   differences; 0 where not counted). */
void budget_report(const char *name, uint32_t instructions, uint32_t units, uint32_t stack,
                   uint64_t work);

/* Report a failed self-check and remember to exit with status 1. */
void budget_fail(const char *what);
int budget_failed(void);

#endif /* SSDA_BUDGET_TIMER_H */
