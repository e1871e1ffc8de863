/*
 * cycles_main.c - the cycle-count image for QEMU's mps2-an386 (Cortex-M4),
 * run by tools/budget.sh with -icount shift=0. Prints RESULT lines (see
 * budget_timer.h); exits 1 if a self-check failed.
 */
#include <stdio.h>

#include "budget_timer.h"
#include "jobs.h"
#include "kernel/kernels.h"

int main(void)
{
    budget_timer_init();
    printf("KERNEL %s\n", ssda__kernel_name());
    jobs_calibrate();
    jobs_kernel();
#ifdef SSDA_BUDGET_HAVE_MATCH
    jobs_match();
#endif
#ifdef SSDA_BUDGET_HAVE_TRACK
    jobs_track();
#endif
#ifdef SSDA_BUDGET_HAVE_PITCH
    jobs_pitch();
#endif
#ifdef SSDA_BUDGET_HAVE_SEGMENT
    jobs_segment();
#endif
#ifdef SSDA_BUDGET_HAVE_STREAM
    jobs_stream();
#endif
#ifdef SSDA_BUDGET_HAVE_SYMREG
    jobs_symreg();
#endif
    return budget_failed();
}
