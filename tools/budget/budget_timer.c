/* budget_timer.c - SysTick instruction counter and stack painting. */
#include "budget_timer.h"

#include <stdio.h>

#include "target.h"

#define PAINT_BYTES 8192u
#define PAINT_WORD 0xA5C3E1F0u

static uint32_t g_overhead;
static int g_failed;

static uint32_t systick_now(void)
{
    return SSDA_TARGET_REG(SSDA_TARGET_SYST_CVR) & 0xFFFFFFu;
}

static void empty_job(void *ctx)
{
    (void)ctx;
}

/* Kept out of line so that every measurement pays the same call. */
__attribute__((noinline)) static uint32_t measure_ticks(budget_job_fn job, void *ctx)
{
    uint32_t t0 = systick_now();
    job(ctx);
    return (t0 - systick_now()) & 0xFFFFFFu; /* counts down */
}

void budget_timer_init(void)
{
    SSDA_TARGET_REG(SSDA_TARGET_SYST_CSR) = 0u;
    SSDA_TARGET_REG(SSDA_TARGET_SYST_RVR) = 0xFFFFFFu;
    SSDA_TARGET_REG(SSDA_TARGET_SYST_CVR) = 0u; /* any write clears it */
    SSDA_TARGET_REG(SSDA_TARGET_SYST_CSR) = 0x5u; /* ENABLE | CLKSOURCE, no interrupt */
    g_overhead = measure_ticks(empty_job, NULL) * BUDGET_INSTR_PER_TICK;
}

uint32_t budget_instructions(budget_job_fn job, void *ctx)
{
    uint32_t n = measure_ticks(job, ctx) * BUDGET_INSTR_PER_TICK;
    return n > g_overhead ? n - g_overhead : 0u;
}

static inline uint32_t *stack_pointer(void)
{
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    return sp;
}

__attribute__((noinline)) uint32_t budget_stack_peak(budget_job_fn job, void *ctx)
{
    uint32_t *top = stack_pointer();
    uint32_t *bottom = top - PAINT_BYTES / 4u;
    volatile uint32_t *p;
    /* Words below sp are free; leave a few for this function's own calls. */
    for (p = bottom; p < top - 16; p++) {
        *p = PAINT_WORD;
    }
    job(ctx);
    for (p = bottom; p < top && *p == PAINT_WORD; p++) {
    }
    return (uint32_t)((uintptr_t)top - (uintptr_t)p);
}

void budget_report(const char *name, uint32_t instructions, uint32_t units, uint32_t stack,
                   uint64_t work)
{
    /* newlib-nano's printf has no %llu: work is printed as two halves. */
    printf("RESULT %s %lu %lu %lu %lu%09lu\n", name, (unsigned long)instructions,
           (unsigned long)units, (unsigned long)stack,
           (unsigned long)(work / 1000000000u), (unsigned long)(work % 1000000000u));
}

void budget_fail(const char *what)
{
    printf("FAILED %s\n", what);
    g_failed = 1;
}

int budget_failed(void)
{
    return g_failed;
}
