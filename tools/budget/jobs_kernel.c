/* jobs_kernel.c - instructions per pixel of the compiled kernel set. */
#include "jobs.h"

#include "budget_timer.h"
#include "kernel/kernels.h"

#define LONG_ROW 4096u

static uint8_t g_a8[LONG_ROW], g_b8[LONG_ROW];
static uint16_t g_a16[LONG_ROW], g_b16[LONG_ROW];

typedef struct {
    uint32_t n;     /* pixels per call */
    uint32_t reps;  /* calls */
    uint32_t kind;  /* 0 u8, 1 u16, 2 i16, 3 an empty function */
    uint32_t sink;  /* keeps the sums alive */
} kernel_job_t;

/* The same call with nothing inside: its cost (the loop, the arguments, the
   call and return) is subtracted, leaving the kernel's own instructions. */
__attribute__((noinline)) static uint32_t empty_row(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    __asm__ volatile("" ::"r"(a), "r"(b), "r"(n));
    return 0u;
}

static void kernel_job(void *ctx)
{
    kernel_job_t *j = (kernel_job_t *)ctx;
    uint32_t r, s = 0u;
    for (r = 0; r < j->reps; r++) {
        /* Consecutive rows of one long buffer, as the engine walks a window. */
        uint32_t off = (r * j->n) % (LONG_ROW - j->n + 1u);
        switch (j->kind) {
        case 0:
            s += ssda__sad_row_u8(g_a8 + off, g_b8 + off, j->n);
            break;
        case 1:
            s += ssda__sad_row_u16(g_a16 + off, g_b16 + off, j->n);
            break;
        case 3:
            s += empty_row(g_a8 + off, g_b8 + off, j->n);
            break;
        default:
            s += ssda__absdiff_row_i16((const int16_t *)g_a16 + off,
                                      (const int16_t *)g_b16 + off, j->n);
            break;
        }
    }
    j->sink = s;
}

static void run(const char *name, uint32_t kind, uint32_t n, uint32_t reps)
{
    kernel_job_t j = {n, reps, kind, 0u};
    kernel_job_t empty = {n, reps, 3u, 0u};
    uint32_t instr = budget_instructions(kernel_job, &j);
    uint32_t frame = budget_instructions(kernel_job, &empty);
    budget_report(name, instr > frame ? instr - frame : 0u, n * reps, 0u, (uint64_t)n * reps);
}

void jobs_kernel(void)
{
    uint32_t st = 0x4B45524Eu, i;
    for (i = 0; i < LONG_ROW; i++) {
        uint32_t v = jobs_rand(&st);
        g_a8[i] = (uint8_t)v;
        g_b8[i] = (uint8_t)(v >> 8);
        g_a16[i] = (uint16_t)(v >> 16);
        g_b16[i] = (uint16_t)jobs_rand(&st);
    }
    /* A 16-pixel row (one window row: the kernel's entry and exit count),
       and the long-row rate its inner loop approaches. */
    run("kernel.sad_u8.row16", 0u, 16u, 1024u);
    run("kernel.sad_u8.row4096", 0u, LONG_ROW, 16u);
    run("kernel.sad_u16.row16", 1u, 16u, 1024u);
    run("kernel.sad_u16.row4096", 1u, LONG_ROW, 16u);
    run("kernel.absdiff_i16.row320", 2u, 320u, 64u);
    run("kernel.absdiff_i16.row4096", 2u, LONG_ROW, 16u);
}
