/* ncc_ref.c - exhaustive normalised cross-correlation (the compare reference). */
#include "ncc_ref.h"

#include <math.h>
#include <stdlib.h>

int ncc_search(const gray_image_t *img_a, uint32_t ax, uint32_t ay, uint32_t search_w,
               uint32_t search_h, const gray_image_t *img_w, uint32_t wx, uint32_t wy,
               uint32_t win_w, uint32_t win_h, uint32_t *best_x, uint32_t *best_y,
               double *best_ncc)
{
    size_t n = (size_t)win_w * win_h, i;
    double *w = malloc(n * sizeof *w), mean = 0.0, ww = 0.0, best = -2.0;
    uint32_t x, y, px, py, bx = 0, by = 0;
    if (w == NULL) {
        return -1;
    }
    for (y = 0; y < win_h; y++) {
        for (x = 0; x < win_w; x++) {
            w[(size_t)y * win_w + x] = gray_image_get(img_w, wx + x, wy + y);
            mean += w[(size_t)y * win_w + x];
        }
    }
    mean /= (double)n;
    for (i = 0; i < n; i++) {
        w[i] -= mean;
        ww += w[i] * w[i];
    }
    for (py = 0; py + win_h <= search_h; py++) {
        for (px = 0; px + win_w <= search_w; px++) {
            /* sum (S - mS) W' = sum S W' since sum W' = 0 */
            double s = 0.0, ss = 0.0, sw = 0.0, var, ncc;
            for (y = 0; y < win_h; y++) {
                const double *wr = w + (size_t)y * win_w;
                for (x = 0; x < win_w; x++) {
                    double v = gray_image_get(img_a, ax + px + x, ay + py + y);
                    s += v;
                    ss += v * v;
                    sw += v * wr[x];
                }
            }
            var = ss - s * s / (double)n;
            ncc = (var > 1e-9 && ww > 1e-9) ? sw / sqrt(var * ww) : 0.0;
            if (ncc > best + 1e-12) { /* strictly better: raster order keeps the tie rule */
                best = ncc;
                bx = px;
                by = py;
            }
        }
    }
    free(w);
    *best_x = bx;
    *best_y = by;
    *best_ncc = best;
    return 0;
}
