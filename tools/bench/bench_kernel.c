/*
 * bench_kernel.c - the SAD row kernels alone: every variant of the compiled
 * kernel set this processor runs (x86: SSE2, and AVX2 where present; see
 * lib/kernel/kernel_sse2.c), and the run-time choice the library makes,
 * on rows of 8 to 128 pixels, 8- and 16-bit. A search calls the kernel
 * once per template row, so the short rows are the ones that matter.
 *
 *   ssda-bench-kernel [--reps N]
 *
 * Each repetition times every variant once in turn (interleaved) over the
 * same rows; the median processor time of the thread (waits for a core
 * left out) per row and pixels per nanosecond are
 * printed, with the load average before and after (the machine may be
 * shared). Every variant's sums are checked equal to the portable
 * reference's; the program fails otherwise. Not a test: figures only.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "kernel/kernels.h"
#include "kernel/portable.h"

#define ROWS 4096u   /* distinct row pairs per timing, about 1 MiB of 16-bit pixels */
#define MAXW 128u
#define MAXV 4       /* the public loop + up to three variants */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void print_load(const char *when)
{
    char buf[64] = "?";
    FILE *f = fopen("/proc/loadavg", "r");
    if (f != NULL) {
        if (fgets(buf, sizeof buf, f) == NULL) {
            strcpy(buf, "?");
        }
        fclose(f);
    }
    buf[strcspn(buf, "\n")] = '\0';
    printf("Load average %s: %s\n", when, buf);
}

typedef uint32_t (*sad8_fn)(const uint8_t *, const uint8_t *, uint32_t);
typedef uint32_t (*sad16_fn)(const uint16_t *, const uint16_t *, uint32_t);

static uint8_t *g_a8, *g_b8;
static uint16_t *g_a16, *g_b16;

/* Seconds for `inner` passes over ROWS row pairs of width w; *sum the
   total (checked against the reference). */
static double time8(sad8_fn f, uint32_t w, uint32_t inner, uint64_t *sum)
{
    uint64_t s = 0;
    double t0 = now();
    for (uint32_t k = 0; k < inner; k++) {
        for (uint32_t r = 0; r < ROWS; r++) {
            s += f(g_a8 + (size_t)r * MAXW + (r & 7u), g_b8 + (size_t)r * MAXW, w);
        }
    }
    *sum = s;
    return now() - t0;
}

static double time16(sad16_fn f, uint32_t w, uint32_t inner, uint64_t *sum)
{
    uint64_t s = 0;
    double t0 = now();
    for (uint32_t k = 0; k < inner; k++) {
        for (uint32_t r = 0; r < ROWS; r++) {
            s += f(g_a16 + (size_t)r * MAXW + (r & 7u), g_b16 + (size_t)r * MAXW, w);
        }
    }
    *sum = s;
    return now() - t0;
}

static uint32_t ref8(const uint8_t *a, const uint8_t *b, uint32_t n)
{
    return ssda__portable_sad_row_u8(a, b, n);
}

static uint32_t ref16(const uint16_t *a, const uint16_t *b, uint32_t n)
{
    return ssda__portable_sad_row_u16(a, b, n);
}

int main(int argc, char **argv)
{
    static const uint32_t widths[] = {8u, 16u, 32u, 64u, 128u};
    const char *names[MAXV + 1];
    sad8_fn f8[MAXV + 1];
    sad16_fn f16[MAXV + 1];
    int reps = 15, nv = 0, bad = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
            reps = atoi(argv[++i]);
        } else {
            fprintf(stderr, "usage: %s [--reps N]\n", argv[0]);
            return 2;
        }
    }
    if (reps < 1 || reps > 1000) {
        fprintf(stderr, "ssda-bench-kernel: --reps 1..1000\n");
        return 2;
    }
    names[nv] = "portable C (reference)";
    f8[nv] = ref8;
    f16[nv++] = ref16;
    for (uint32_t v = 0; v < MAXV - 1 && ssda__kernel_variant(v) != NULL; v++) {
        const ssda__kernel_variant_t *k = ssda__kernel_variant(v);
        names[nv] = k->name;
        f8[nv] = k->sad_row_u8;
        f16[nv++] = k->sad_row_u16;
    }
    names[nv] = "library's choice (ssda__sad_row_*)";
    f8[nv] = ssda__sad_row_u8;
    f16[nv++] = ssda__sad_row_u16;

    g_a8 = malloc((size_t)ROWS * MAXW + 8u);
    g_b8 = malloc((size_t)ROWS * MAXW);
    g_a16 = malloc(((size_t)ROWS * MAXW + 8u) * 2u);
    g_b16 = malloc((size_t)ROWS * MAXW * 2u);
    double *t = malloc((size_t)reps * sizeof *t * (size_t)nv);
    if (!g_a8 || !g_b8 || !g_a16 || !g_b16 || !t) {
        fprintf(stderr, "ssda-bench-kernel: out of memory\n");
        return 1;
    }
    srand(12345);
    for (size_t i = 0; i < (size_t)ROWS * MAXW + 8u; i++) {
        g_a8[i] = (uint8_t)rand();
        g_a16[i] = (uint16_t)(rand() & 0x0FFF); /* 12-bit data, as GOES-16 */
    }
    for (size_t i = 0; i < (size_t)ROWS * MAXW; i++) {
        g_b8[i] = (uint8_t)rand();
        g_b16[i] = (uint16_t)(rand() & 0x0FFF);
    }

    printf("# SAD row kernels: compiled set `%s`, %u rows per timing, median of %d interleaved runs\n\n",
           ssda__kernel_name(), ROWS, reps);
    print_load("at the start");
    printf("\n| pixels | row width |");
    for (int v = 0; v < nv; v++) {
        printf(" %s ns/row (px/ns) |", names[v]);
    }
    printf("\n|---|---:|");
    for (int v = 0; v < nv; v++) {
        printf("---:|");
    }
    printf("\n");
    for (int bits = 8; bits <= 16; bits += 8) {
        for (size_t wi = 0; wi < sizeof widths / sizeof widths[0]; wi++) {
            uint32_t w = widths[wi], inner = 2048u / w;
            uint64_t want = 0, got;
            for (int k = 0; k < reps; k++) {
                for (int v = 0; v < nv; v++) {
                    double s = bits == 8 ? time8(f8[v], w, inner, &got)
                                         : time16(f16[v], w, inner, &got);
                    t[(size_t)v * (size_t)reps + (size_t)k] = s / ((double)inner * ROWS);
                    if (v == 0 && k == 0) {
                        want = got;
                    } else if (got != want) {
                        fprintf(stderr, "%s, %d-bit, %u px: sum %llu, reference %llu\n", names[v],
                                bits, w, (unsigned long long)got, (unsigned long long)want);
                        bad = 1;
                    }
                }
            }
            printf("| %d-bit | %u |", bits, w);
            for (int v = 0; v < nv; v++) {
                double *tv = t + (size_t)v * (size_t)reps;
                qsort(tv, (size_t)reps, sizeof *tv, cmp_double);
                double med = tv[reps / 2];
                printf(" %.2f (%.1f) |", 1e9 * med, (double)w / (1e9 * med));
            }
            printf("\n");
        }
    }
    printf("\n");
    print_load("at the end");
    free(g_a8);
    free(g_b8);
    free(g_a16);
    free(g_b16);
    free(t);
    return bad;
}
