/* median.c - median of Q8 values by selection (median.h). */
#include "median.h"

/* The k-th smallest of v[0..n-1] (k < n), v reordered so that every entry
   after k is at least it. */
static int32_t select_kth(int32_t *v, size_t n, size_t k)
{
    size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        const int32_t pivot = v[lo + (hi - lo) / 2];
        size_t i = lo, j = hi;
        /* Hoare's partition: i and j stop at entries >= and <= the pivot,
           which exist in range (the pivot itself, then what was swapped);
           j never goes below lo - 1, kept >= 0 by stopping at lo. */
        for (;;) {
            while (v[i] < pivot) {
                i++;
            }
            while (v[j] > pivot) {
                j--;
            }
            if (i >= j) {
                break;
            }
            {
                const int32_t t = v[i];
                v[i] = v[j];
                v[j] = t;
            }
            i++;
            j--;
        }
        /* lo..j <= pivot <= j+1..hi (j < hi: the pivot's entry or a swap
           stops it) */
        if (k <= j) {
            hi = j;
        } else {
            lo = j + 1u;
        }
    }
    return v[k];
}

double median_q8(int32_t *v, size_t n)
{
    int32_t lo, hi;
    size_t k;
    if (n == 0u) {
        return 0.0;
    }
    if (n % 2u) {
        return select_kth(v, n, n / 2u) / 256.0;
    }
    /* the lower middle, then the least of the entries after it */
    lo = select_kth(v, n, n / 2u - 1u);
    hi = v[n / 2u];
    for (k = n / 2u + 1u; k < n; k++) {
        hi = v[k] < hi ? v[k] : hi;
    }
    return 0.5 * (lo / 256.0 + hi / 256.0);
}
