/* jobs_common.c - test data and the method check. */
#include "jobs.h"

#include "budget_timer.h"

uint32_t jobs_rand(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

void jobs_texture_u8(uint8_t *img, uint32_t w, uint32_t h, uint32_t seed)
{
    static uint16_t tmp[128u * 128u];
    uint32_t pass, x, y, st = seed | 1u;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            img[y * w + x] = (uint8_t)(jobs_rand(&st) >> 24);
        }
    }
    for (pass = 0; pass < 2u; pass++) {
        for (y = 0; y < h; y++) {
            for (x = 0; x < w; x++) {
                uint32_t s = 0u, c = 0u;
                uint32_t y0 = y > 0u ? y - 1u : 0u, y1 = y + 1u < h ? y + 1u : h - 1u;
                uint32_t x0 = x > 0u ? x - 1u : 0u, x1 = x + 1u < w ? x + 1u : w - 1u;
                uint32_t yy, xx;
                for (yy = y0; yy <= y1; yy++) {
                    for (xx = x0; xx <= x1; xx++) {
                        s += img[yy * w + xx];
                        c++;
                    }
                }
                tmp[y * w + x] = (uint16_t)(s / c);
            }
        }
        /* Stretch back to the full 0..255 range (smoothing shrinks it). */
        for (y = 0; y < w * h; y++) {
            int32_t v = ((int32_t)tmp[y] - 128) * 3 + 128;
            img[y] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
        }
    }
}

static void loop_job(void *ctx)
{
    uint32_t n = *(const uint32_t *)ctx;
    __asm__ volatile("1: subs %0, %0, #1\n\tbne 1b" : "+r"(n) : : "cc");
}

void jobs_calibrate(void)
{
    uint32_t n = 100000u;
    uint32_t instr = budget_instructions(loop_job, &n);
    /* 2 instructions per iteration, plus a load; +-40 for the counter. */
    budget_report("calibrate.loop", instr, 2u * n, 0u, 0u);
    if (instr + 80u < 2u * n || instr > 2u * n + 80u) {
        budget_fail("calibration: SysTick does not count 40 instructions per tick "
                    "(is QEMU running with -icount shift=0?)");
    }
}
