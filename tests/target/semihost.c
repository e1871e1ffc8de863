/*
 * semihost.c - the test images' link to the host through semihosting:
 * newlib's rdimon library carries printf/putchar output (Unity), and the exit
 * status of main() becomes qemu-system-arm's exit status, which CTest reads.
 * A fault prints the exception number and ends the run with status 1, so a
 * crashing test fails at once instead of hanging the emulator.
 */
#include <stdint.h>
#include <stdlib.h>

#include "target.h"

/* Semihosting operation numbers. */
#define SH_SYS_WRITE0 0x04u
#define SH_SYS_EXIT 0x18u
#define SH_SYS_EXIT_EXTENDED 0x20u
/* Reason codes for SYS_EXIT. */
#define SH_ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define SH_ADP_STOPPED_RUNTIME_ERROR 0x20023u

/* newlib's rdimon: opens the semihosting stdin/stdout/stderr handles. */
void initialise_monitor_handles(void);

static uint32_t semihost_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void ssda_semihost_write0(const char *text)
{
    (void)semihost_call(SH_SYS_WRITE0, text);
}

/* SYS_EXIT_EXTENDED carries the status itself (QEMU, semihosting v2): an
   ARM32 SYS_EXIT could only say "success" or "failure". */
void ssda_semihost_exit(int status)
{
    uint32_t block[2];
    block[0] = SH_ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)status;
    (void)semihost_call(SH_SYS_EXIT_EXTENDED, block);
    /* Not supported by this host: plain SYS_EXIT, failure if status != 0. */
    (void)semihost_call(SH_SYS_EXIT,
                        (const void *)(uintptr_t)(status == 0 ? SH_ADP_STOPPED_APPLICATION_EXIT
                                                              : SH_ADP_STOPPED_RUNTIME_ERROR));
    for (;;) {
    }
}

void ssda_target_start(void)
{
    initialise_monitor_handles();
}

/* Unity's main returns the number of failures: any nonzero count is
   status 1, so that 256 failures never read as success. exit() flushes
   stdio before newlib's _exit. */
void ssda_target_exit(int status)
{
    exit(status != 0 ? 1 : 0);
}

void ssda_target_fault(uint32_t exception)
{
    static const char digits[] = "0123456789";
    char msg[] = "\n*** unexpected exception ###, stopping ***\n";
    char *p = msg;
    while (*p != '#') {
        p++;
    }
    p[0] = digits[(exception / 100u) % 10u];
    p[1] = digits[(exception / 10u) % 10u];
    p[2] = digits[exception % 10u];
    ssda_semihost_write0(msg);
    ssda_semihost_exit(1);
}
