#!/usr/bin/env python3
"""The README's budget summary, taken from the tables of tools/budget/report.py
(Markdown on stdin), so the two can never disagree. Prints Markdown."""
import re
import sys

# M0+ flash, bytes (issue 6; the pitch's 2 048 from issue 18)
TARGETS = {"search": 2048, "pitch": 2048, "stream": 2048}
STACK_LIMIT = 256
STACK_TARGETS = {"ssda_match": 320, "ssda_match_search": 320}  # issue 18; the others STACK_LIMIT


def rows(text):
    """Every table row as (label, [cells]), label with HTML padding removed."""
    out = []
    for line in text.splitlines():
        if not line.startswith("| ") or line.startswith("|---"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        out.append((cells[0].replace("&nbsp;", "").strip(), cells[1:]))
    return out


def num(cell):
    """The first number of a cell ('4 528', '**552** +cb', '1.00'), or None."""
    m = re.search(r"\d[\d ]*(?:\.\d+)?", cell.replace("*", ""))
    return float(m.group(0).replace(" ", "")) if m else None


def fmt(v):
    return f"{int(v):,}".replace(",", " ")


def find(table, label, after=None):
    """Cells of the first row named label (after the row named `after`)."""
    start = 0
    if after is not None:
        start = next(i for i, (l, _) in enumerate(table) if l == after) + 1
    for l, cells in table[start:]:
        if l == label:
            return cells
    raise SystemExit(f"summary.py: no row '{label}' in the budget tables")


def verdict(value, goal):
    return "met" if value <= goal else "**over**"


def main():
    t = rows(sys.stdin.read())
    header = next(cells for l, cells in t if l == "feature")
    m0 = 0  # first target column is the M0+
    assert header[m0].startswith("M0"), header
    m4 = header.index("M4F")
    search = "of which `ssda_match*` (search core)"
    source = "of which `ssda_source*` (streaming layer)"
    pitch = "AMDF pitch (`pitch.h`)"
    flash = [
        ("SSDA search core (`ssda_match*`)", num(find(t, search)[m0]),
         num(find(t, "minimal core", search)[m0]), TARGETS["search"]),
        ("AMDF pitch (`ssda_pitch*`)", num(find(t, pitch)[m0]),
         num(find(t, "minimal core", pitch)[m0]), TARGETS["pitch"]),
        ("streaming layer (`ssda_source*`)", num(find(t, source)[m0]),
         num(find(t, "minimal core", source)[m0]), TARGETS["stream"]),
    ]
    w = sys.stdout.write
    w("| Cortex-M0+ flash (-Os) | full | minimal core | target |\n|---|---:|---:|---|\n")
    for label, full, small, goal in flash:
        w(f"| {label} | {fmt(full)} B | {fmt(small)} B | {fmt(goal)} B: minimal "
          f"{verdict(small, goal)}, full {verdict(full, goal)} |\n")
        if label.startswith("AMDF pitch"):
            # the reduced core (steps 4 and 6 of the definition left out), apart
            red = next((cells for l, cells in t if l.startswith("reduced core")), None)
            if red is not None:
                v = num(red[m0])
                w(f"| &nbsp;&nbsp;reduced definition (no octave or below-range check) | - | "
                  f"{fmt(v)} B | {fmt(goal)} B: {verdict(v, goal)}, estimates differ "
                  "(docs/pitch.md) |\n")
            # both cores built for one configuration (SSDA_CFG_PITCH_FIXED)
            for core, label, note in (
                    ("minimal", "one configuration, fixed at compile time", ""),
                    ("reduced", "reduced definition, one configuration fixed at compile time",
                     ", estimates differ")):
                fix = next((cells for l, cells in t
                            if l.startswith(core + " core, its configuration fixed")), None)
                if fix is not None:
                    v = num(fix[m0])
                    w(f"| &nbsp;&nbsp;{label} (`SSDA_CFG_PITCH_FIXED`) | - | {fmt(v)} B | "
                      f"{fmt(goal)} B: {verdict(v, goal)}{note} |\n")
    stack = [(f, num(find(t, f"`{f}`")[m4]))
             for f in ("ssda_match", "ssda_match_search", "ssda_pitch_push", "ssda_track")]
    w(f"\n| worst stack (M4F, -Os) | bytes | target |\n|---|---:|---|\n")
    for f, v in stack:
        w(f"| `{f}` | {fmt(v)} (+ callback)" if f != "ssda_pitch_push" else f"| `{f}` | {fmt(v)}")
        goal = STACK_TARGETS.get(f, STACK_LIMIT)
        w(f" | {goal} B: {verdict(v, goal)} |\n")
    sad = find(t, "8-bit, long rows")
    w("\n| Cortex-M4 (QEMU `-icount`, DSP kernels, -O2) | instructions |\n|---|---:|\n")
    w(f"| SAD kernel, 8-bit, long rows | {sad[0]} / pixel (portable C: {sad[1]}) |\n")
    for key, label in (("brute force (`SSDA_THRESHOLD_NONE`)", "16x16 in 32x32: brute force"),
                       ("`auto` (raster)", "16x16 in 32x32: `auto`"),
                       ("`auto` + prediction + bounds", "16x16 in 32x32: `auto` + prediction + bounds")):
        w(f"| {label} | {find(t, key)[0]} |\n")
    full = find(t, "full AMDF (`SSDA_PITCH_FULL`)")[0].split("/")[0].strip()
    early = find(t, "early exit")[0].split("/")[0].strip()
    w(f"| pitch frame, 16 kHz, 50-1000 Hz, mean (full AMDF: {full}) | {early} |\n")


if __name__ == "__main__":
    main()
