/* synth_texture.c - synthetic textured pairs (see header). */
#include "synth_texture.h"

#include <math.h>
#include <stdlib.h>

static const double k_pi = 3.14159265358979323846;

int synth_texture(uint8_t *img, int w, int h, unsigned seed)
{
    static const int scales[] = {128, 64, 32, 16, 8, 4, 2};
    size_t n = (size_t)w * (size_t)h, i;
    double *acc = calloc(n, sizeof *acc);
    double lo = 1e30, hi = -1e30, amp = 1.0;
    if (acc == NULL) {
        return -1;
    }
    srand(seed);
    for (size_t s = 0; s < sizeof scales / sizeof scales[0]; s++) {
        int c = scales[s], gw = w / c + 2, gh = h / c + 2;
        double *grid = malloc((size_t)gw * (size_t)gh * sizeof *grid);
        if (grid == NULL) {
            free(acc);
            return -1;
        }
        for (i = 0; i < (size_t)gw * (size_t)gh; i++) {
            grid[i] = (double)rand() / RAND_MAX;
        }
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double fx = (double)x / c, fy = (double)y / c;
                int x0 = (int)fx, y0 = (int)fy;
                double tx = fx - x0, ty = fy - y0;
                const double *g0 = grid + (size_t)y0 * (size_t)gw + (size_t)x0, *g1 = g0 + gw;
                acc[(size_t)y * (size_t)w + (size_t)x] +=
                    amp * (g0[0] * (1 - tx) * (1 - ty) + g0[1] * tx * (1 - ty) +
                           g1[0] * (1 - tx) * ty + g1[1] * tx * ty);
            }
        }
        free(grid);
        amp *= 0.6;
    }
    for (i = 0; i < n; i++) {
        lo = acc[i] < lo ? acc[i] : lo;
        hi = acc[i] > hi ? acc[i] : hi;
    }
    for (i = 0; i < n; i++) {
        img[i] = (uint8_t)lround(255.0 * (acc[i] - lo) / (hi - lo));
    }
    free(acc);
    return 0;
}

void synth_moved_field(int x, int y, int w, int h, int *u, int *v)
{
    *u = (int)lround(3.0 + 2.0 * sin(2 * k_pi * y / h));
    *v = (int)lround(-2.0 + 2.5 * cos(2 * k_pi * x / w));
}

void synth_moved(const uint8_t *first, uint8_t *second, int w, int h, unsigned seed)
{
    srand(seed);
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            int u, v, sx, sy, val;
            synth_moved_field(x, y, w, h, &u, &v);
            sx = x - u;
            sy = y - v;
            sx = sx < 0 ? 0 : (sx >= w ? w - 1 : sx);
            sy = sy < 0 ? 0 : (sy >= h ? h - 1 : sy);
            val = first[(size_t)sy * (size_t)w + (size_t)sx] + rand() % 5 - 2;
            second[(size_t)y * (size_t)w + (size_t)x] = (uint8_t)(val < 0 ? 0 : (val > 255 ? 255 : val));
        }
    }
}
