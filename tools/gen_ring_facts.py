#!/usr/bin/env python3
"""gen_ring_facts.py - the table ring_facts[256] of lib/edge_ring.c: for each
3 x 3 ring code (bit k = neighbour k: E, NE, N, NW, W, SW, S, SE) its runs,
the seed appendix's "unsuitable" pattern, whether deleting the centre keeps
4-connectivity, whether the set neighbours are one 8-connected component,
and how many 4-neighbours are clear. Prints the C initialiser."""


def bit(r, k):
    return (r >> (k & 7)) & 1


def facts(ring):
    runs = even_runs = bg4 = 0
    unsuitable = ring == 0xFF
    for k in range(8):
        if bit(ring, k) and not bit(ring, k + 7):  # a run starts at k
            ln, has_even = 0, False
            while ln < 8 and bit(ring, k + ln):
                has_even = has_even or (k + ln) % 2 == 0
                ln += 1
            runs += 1
            even_runs += has_even
            if ln >= 4 or (ln == 3 and (k + 1) % 2 == 1):  # or 3 round a corner
                unsuitable = True
        if k % 2 == 0 and not bit(ring, k):
            bg4 += 1
    if ring == 0xFF:
        runs = even_runs = 1
    if runs <= 1:
        c8 = runs
    else:  # runs joined across a clear corner between two set 4-neighbours
        joins = sum(1 for k in range(0, 8, 2)
                    if bit(ring, k) and not bit(ring, k + 1) and bit(ring, k + 2))
        c8 = 1 if joins >= runs else runs - joins
    return (min(runs, 3) | (4 if unsuitable else 0) | (8 if even_runs <= 1 else 0) |
            (16 if c8 == 1 else 0) | (bg4 << 5))


if __name__ == "__main__":
    t = [facts(r) for r in range(256)]
    for i in range(0, 256, 16):
        print("    " + ", ".join("0x%02Xu" % v for v in t[i:i + 16]) + ",")
