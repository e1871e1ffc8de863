/*
 * median.h - the median of Q8 fixed-point values (the tools' median motion
 * of ok vectors), by selection instead of a sort.
 */
#ifndef SSDA_MEDIAN_H
#define SSDA_MEDIAN_H

#include <stddef.h>
#include <stdint.h>

/*
 * The median of v[0..n-1] / 256: the middle value for odd n, the mean of
 * the two middle ones for even n (computed as 0.5 * (a / 256.0 + b /
 * 256.0), the value a sort would give), 0 for n = 0. v is reordered.
 * Linear on average (Hoare's selection, the middle entry as pivot).
 */
double median_q8(int32_t *v, size_t n);

#endif /* SSDA_MEDIAN_H */
