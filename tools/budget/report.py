#!/usr/bin/env python3
"""report.py - the budget tables in Markdown, from the builds and runs that
tools/budget.sh makes (python3, standard library only).

  report.py --size NAME=BUILD_DIR ...      size images and stack data (-Os)
            --cycles NAME=QEMU_OUTPUT ...  cycle-image outputs (RESULT lines)

Flash/RAM: each fw_<feature>.elf against fw_base.elf (tools/budget/CMakeLists.txt).
Stack: the library's frames from GCC (-fcallgraph-info=su: the .ci call
graphs carry each function's -fstack-usage bytes), frames of C library and
libgcc routines from the linked image's disassembly (their prologue's
push/stmdb/sub sp; their calls); worst case = frame + deepest callee chain.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

# Targets of the issue (Cortex-M0+, -Os), bytes of flash: the search core
# (ssda_match), the pitch stream, the streaming layer (the block source).
# Issue 6's targets; issue 18 set the pitch's to 2 048 and ssda_match's stack to 320
# (met by ssda_match_search, the search with its state in the caller's storage).
M0_FLASH_TARGETS = {"match-match": 2048, "pitch": 2048, "stream-source": 2048}
STACK_LIMIT = 256
STACK_TARGETS = {"ssda_match": 320, "ssda_match_search": 320}
FEATURE_NAMES = {
    "match": "SSDA search (`match.h`)",
    "pitch": "AMDF pitch (`pitch.h`)",
    "stream": "block-streamed images (`stream.h`)",
    "track": "grid tracking (`track.h`)",
    "ncc": "correlation search (`ncc.h`)",
    "relax": "relaxation labelling, median test (`relax.h`)",
    "composite": "composite templates (`composite.h`)",
    "grad": "Fig. 8 operator (`grad.h`)",
    "edge": "seed 001 edges (`edge.h`)",
    "loops": "seed 001 closed loops (`loops.h`)",
    "fourier": "Fourier descriptors (`fourier.h`)",
    "symreg": "symbolic registration (`symreg.h`)",
    "view": "image views (`view.h`)",
    "ssda": "error names (`ssda.h`)",
    "poly": "polynomial maps and their fit (`poly.h`)",
    "warp": "resampling through a map (`warp.h`)",
    "shade": "shading removal (`shade.h`)",
    "register": "control points (`register.h`)",
    "kl": "K-L transform (`kl.h`)",
    "mixture": "Gaussian mixtures of histograms (`mixture.h`)",
    "region": "isolated points, contours, counts (`region.h`)",
}


def cache_value(build, key):
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        for line in f:
            if line.startswith(key + ":"):
                return line.split("=", 1)[1].strip()
    raise SystemExit(f"report.py: {key} not in {build}/CMakeCache.txt")


def read_features(build, kind="features"):
    feats = {}
    path = os.path.join(build, kind + ".txt")
    if kind == "min" and not os.path.exists(path):
        return feats
    with open(path) as f:
        for line in f:
            name, _, fns = line.partition(":")
            feats[name.strip()] = fns.split()
    return feats


def section_sizes(size_tool, elf):
    out = subprocess.run([size_tool, "-B", elf], check=True, capture_output=True, text=True).stdout
    text, data, bss = (int(v) for v in out.splitlines()[1].split()[:3])
    return text + data, data + bss  # flash, RAM


# ---- stack -----------------------------------------------------------------

NODE_RE = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
EDGE_RE = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
BYTES_RE = re.compile(r"\\n(\d+) bytes \(([a-z,]+)\)")


def read_callgraphs(build):
    """Frames and edges of the library's functions from GCC's .ci files, and
    the library calls GCC may emit (<built-in> nodes)."""
    frames, edges, qual, builtins = {}, {}, {}, set()
    pattern = os.path.join(build, "ssda", "lib", "CMakeFiles", "ssda.dir", "**", "*.ci")
    files = glob.glob(pattern, recursive=True)
    if not files:
        raise SystemExit(f"report.py: no .ci call graphs under {build}")
    for path in files:
        with open(path) as f:
            for line in f:
                m = NODE_RE.search(line)
                if m:
                    b = BYTES_RE.search(m.group(2))
                    if b:
                        frames[m.group(1)] = int(b.group(1))
                        qual[m.group(1)] = b.group(2)
                    elif "<built-in>" in m.group(2):
                        builtins.add(m.group(1))
                    continue
                m = EDGE_RE.search(line)
                if m:
                    edges.setdefault(m.group(1), set()).add(m.group(2))
    return frames, edges, qual, builtins


FUNC_RE = re.compile(r"^([0-9a-f]+) <([^>]+)>:$")
INSN_RE = re.compile(r"^\s+[0-9a-f]+:\s+(\S+)\s*(.*)$")
CALL_TARGET_RE = re.compile(r"<([^>+]+)>")


def reg_count(reglist):
    n = 0
    for part in reglist.strip("{} ").split(","):
        part = part.strip()
        m = re.match(r"([a-z]+)(\d+)-[a-z]+(\d+)$", part)
        n += int(m.group(3)) - int(m.group(2)) + 1 if m else (1 if part else 0)
    return n


def read_disassembly(objdump, elf):
    """Frames and call edges of every function of a linked image, from its
    prologue instructions (ARM Thumb and RISC-V)."""
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", elf], check=True,
                         capture_output=True, text=True).stdout
    frames, edges, indirect, labels = {}, {}, set(), {}
    tails, linked = set(), set()  # (caller, callee) by a plain jump / by a call
    fn = None
    push = sub = 0
    for line in out.splitlines():
        m = FUNC_RE.match(line)
        if m:
            labels[int(m.group(1), 16)] = m.group(2)
            if fn:
                frames[fn] = max(frames.get(fn, 0), push + sub)
            fn, push, sub = m.group(2), 0, 0
            continue
        m = INSN_RE.match(line)
        if not m or fn is None:
            continue
        op, args = m.group(1), m.group(2).split(";")[0].split("@")[0].strip()
        if op in ("push", "push.w") or (op.startswith("stmdb") and args.startswith("sp!")):
            push = max(push, 4 * reg_count(args[args.index("{"):]))
        elif op in ("vpush", "vstmdb") and "{" in args:
            regs = args[args.index("{"):]
            push += (8 if "d" in regs else 4) * reg_count(regs)
        elif re.match(r"str\S*$", op) and re.search(r"\[sp, #-(\d+)\]!", args):
            push += int(re.search(r"\[sp, #-(\d+)\]!", args).group(1))
        elif re.match(r"subw?(\.w)?$", op) and re.match(r"sp, (sp, )?#(\d+)", args):
            sub = max(sub, int(re.match(r"sp, (sp, )?#(\d+)", args).group(2)))
        elif op in ("addi", "c.addi", "c.addi16sp") and re.match(r"sp,\s*(sp,\s*)?-(\d+)", args):
            sub = max(sub, int(re.match(r"sp,\s*(sp,\s*)?-(\d+)", args).group(2)))
        if op in ("bl", "blx", "b", "b.w", "b.n", "jal", "j", "call", "tail", "c.j", "c.jal",
                  "jalr", "c.jalr"):
            t = CALL_TARGET_RE.search(m.group(2))
            if t and t.group(1) != fn:
                edges.setdefault(fn, set()).add(t.group(1))  # a call, or a tail call
                if op in ("b", "b.w", "b.n", "j", "c.j", "tail") and ".cold" not in t.group(1):
                    tails.add((fn, t.group(1)))
                else:
                    linked.add((fn, t.group(1)))
            elif not t and op in ("blx", "jalr", "c.jalr"):
                indirect.add(fn)  # through a register
    if fn:
        frames[fn] = max(frames.get(fn, 0), push + sub)
    # Aliases (libgcc's __aeabi_uidiv is __udivsi3...): objdump labels one
    # name per address; give the others the same frame and calls.
    nm = objdump[: -len("objdump")] + "nm" if objdump.endswith("objdump") else "nm"
    syms = subprocess.run([nm, elf], check=True, capture_output=True, text=True).stdout
    by_addr = {}
    for line in syms.splitlines():
        p = line.split()
        if len(p) == 3 and p[1] in "TtWw":
            by_addr.setdefault(int(p[0], 16), []).append(p[2])
    for addr, name in labels.items():
        for alias in by_addr.get(addr, []):
            if alias != name and alias not in frames:
                frames[alias] = frames.get(name, 0)
                edges[alias] = edges.get(name, set())
                if name in indirect:
                    indirect.add(alias)
    return frames, edges, indirect, tails, linked


def stack_worst(build):
    """Worst-case stack of every public function: {name: (bytes, flags, path)}."""
    objdump = cache_value(build, "CMAKE_OBJDUMP")
    frames, edges, qual, builtins = read_callgraphs(build)
    dframes, dedges, dindirect, dtails, dlinked = {}, {}, set(), set(), set()
    for elf in sorted(glob.glob(os.path.join(build, "fw_*.elf"))):
        f, e, i, t, l = read_disassembly(objdump, elf)
        dframes.update(f)
        for k, v in e.items():
            dedges.setdefault(k, set()).update(v)
        dindirect |= i
        dtails |= t
        dlinked |= l
    # Tail calls (a plain jump after the caller's epilogue, in every image):
    # the callee runs on the caller's caller's stack, not on top of the
    # caller's frame.
    tail_only = dtails - dlinked
    memo = {}

    def resolve(name):
        if name in frames:
            return name
        base = name.split(":")[-1]
        return base if base in frames else name

    def worst(node, active):
        if node in memo:
            return memo[node]
        if node in active:
            return (0, {"recursion"}, [node])
        active = active | {node}
        if node == "__indirect_call":
            return (0, {"callback"}, ["(callback)"])
        if node in frames:
            own, calls, flags = frames[node], edges.get(node, ()), set()
            if qual[node] != "static":
                flags.add(qual[node])
        elif node in dframes:
            own, calls, flags = dframes[node], dedges.get(node, ()), set()
            if node in dindirect:
                flags.add("callback")
        elif node in builtins:
            # A libcall GCC listed but the linked code never makes (the
            # operation was expanded inline or optimised away).
            return (0, set(), [])
        else:
            return (0, {"unknown:" + node}, [node])
        best = (own, set(), [node.split(":")[-1]])
        for callee in sorted(calls):
            r = worst(resolve(callee), active)
            flags |= r[1]
            base = node.split(":")[-1]
            if (base, resolve(callee).split(":")[-1]) in tail_only:
                total, path = r[0], [base] + ["(tail) " + r[2][0]] + r[2][1:] if r[2] else [base]
            else:
                total, path = own + r[0], [base] + r[2]
            if total > best[0]:
                best = (total, set(), path)
        result = (best[0], flags, best[2])
        memo[node] = result
        return result

    out = {}
    for fns in read_features(build).values():
        for fn in fns:
            if fn in frames:
                out[fn] = worst(fn, frozenset())
    return out


# ---- cycles ----------------------------------------------------------------

def read_cycles(path):
    res, kernel = {}, "?"
    with open(path) as f:
        for line in f:
            p = line.split()
            if p[:1] == ["KERNEL"]:
                kernel = p[1]
            elif p[:1] == ["RESULT"] and len(p) >= 6:
                res[p[1]] = tuple(int(v) for v in p[2:6])  # instr, units, stack, work
            elif p[:1] == ["FAILED"]:
                raise SystemExit(f"report.py: self-check failed in {path}: {line.strip()}")
    return kernel, res


def fmt(v):
    return f"{v:,}".replace(",", " ")


def core_key(feat):
    """The row a minimal core stands beside: min-pitch-reduced-fixed -> pitch."""
    return re.sub("(-reduced)?(-fixed)?$", "", feat[4:])


def per(instr, units, digits=2):
    return f"{instr / units:.{digits}f}" if units else "-"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--size", action="append", default=[], metavar="NAME=DIR")
    ap.add_argument("--cycles", action="append", default=[], metavar="NAME=FILE")
    ap.add_argument("--min-check", action="append", default=[], metavar="FILE",
                    help="min_check.elf outputs (MINCHECK <checks> <failures>)")
    a = ap.parse_args()
    targets = [s.split("=", 1) for s in a.size]
    w = sys.stdout.write

    if targets:
        feats = read_features(targets[0][1])
        parts = read_features(targets[0][1], "parts")
        # Minimal cores (fw_min-<row>.elf: the library with the switches of
        # min_config.txt), keyed "min-<row>".
        mins = {"min-" + k: v for k, v in read_features(targets[0][1], "min").items()}
        min_config, min_reduced_config, min_fixed_config = "", [], []
        if mins:
            fixed_cfg = os.path.join(targets[0][1], "min_fixed_config.txt")
            if os.path.exists(fixed_cfg):
                with open(fixed_cfg) as f:
                    min_fixed_config = f.read().split()
            with open(os.path.join(targets[0][1], "min_config.txt")) as f:
                min_config = f.read().split()
            red = os.path.join(targets[0][1], "min_reduced_config.txt")
            if os.path.exists(red):
                with open(red) as f:
                    min_reduced_config = f.read().split()
        sizes = {}
        for name, build in targets:
            tool = cache_value(build, "CMAKE_SIZE")
            base = section_sizes(tool, os.path.join(build, "fw_base.elf"))
            for feat in list(feats) + list(parts) + list(mins) + ["all"]:
                elf = os.path.join(build, f"fw_{feat}.elf")
                if not os.path.exists(elf):
                    sizes[(name, feat)] = None  # did not link
                    continue
                f, r = section_sizes(tool, elf)
                sizes[(name, feat)] = (f - base[0], r - base[1])
        w("### Flash and static RAM per feature (bytes, -Os)\n\n")
        no_ram = all(v is None or v[1] == 0 for v in sizes.values())
        w("Each feature's whole public API linked into an empty firmware "
          "(with `--gc-sections`), minus the empty firmware: library code, "
          "constants, and what it pulls from libgcc and the C library "
          "(64-bit division, for instance; `memcpy` and `memset` are in "
          "every firmware, the empty one included, and so not counted). " +
          ("Static RAM (`.data` + `.bss`) is 0 for every feature: all state "
           "is in caller buffers.\n\n" if no_ram else
           "Static RAM (`.data` + `.bss`), where not 0, in parentheses.\n\n"))
        if mins:
            w("*Minimal core* rows: the same functions linked against the library "
              "built with the feature switches of `include/ssda/config.h` (" +
              ", ".join(f"`{c}`" for c in min_config) + "): the search keeps "
              "the exact `auto` and brute-force thresholds, the raster scan, row "
              "order and 8-bit views; the pitch keeps the AMDF of whole frames "
              "(`ssda_pitch_frame`) with early exit, voicing, the dip-run choice "
              "with its octave and below-range checks and the V-shaped "
              "interpolation (its *reduced core* row also leaves out those two "
              "checks, steps 4 and 6 of the definition in `pitch.h`: a build that "
              "accepts only configurations asking for the reduced definition, "
              "`SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE`, whose "
              "estimates differ; docs/pitch.md; its two *fixed configuration* rows are "
              "these cores built for one configuration, `SSDA_CFG_PITCH_FIXED` in "
              "`pitch.h`: 16 kHz, every other setting its default, the flags "
              "`SSDA_PITCH_NO_FILTER` and, reduced, the two of the reduced definition; "
              "their parameters are constants and `ssda_pitch_init` accepts that "
              "configuration only); the streaming layer keeps raster 8-bit "
              "sources read at byte granularity and the plate cache. A feature "
              "left out returns `SSDA_ERR_UNSUPPORTED`.")
            checks = []
            for path in a.min_check:
                with open(path) as f:
                    for line in f:
                        p = line.split()
                        if p[:1] == ["MINCHECK"] and len(p) == 3:
                            if p[2] != "0":
                                raise SystemExit(f"report.py: minimal-core check failed in {path}")
                            checks.append(int(p[1]))
            if checks:
                w(f" The minimal library also runs on the emulated Cortex-M4 "
                  f"(`tools/budget/min_check.c`, {len(checks)} runs of {sum(checks)} checks "
                  "in all, the pitch's fixed-configuration cores among them, all "
                  "passed): its search returns the brute-force minimum, its pitch the period "
                  "of a 200 Hz vowel from whole frames, its streamed search the in-RAM answer, and every option "
                  "left out is refused with the result untouched.")
            w("\n\n")
        w("| feature | " + " | ".join(n for n, _ in targets) + " | Cortex-M0+ target |\n")
        w("|---|" + "---:|" * len(targets) + "---|\n")
        order = [f for f in ("match", "pitch", "stream", "track", "grad", "edge", "loops",
                             "fourier", "symreg", "view", "ssda") if f in feats]
        order += sorted(f for f in feats if f not in order) + ["all"]
        rows = []
        for feat in order:
            rows.append(feat)
            if "min-" + feat in mins:
                rows.append("min-" + feat)
            for suffix in ("-reduced", "-fixed", "-reduced-fixed"):
                if "min-" + feat + suffix in mins:
                    rows.append("min-" + feat + suffix)
            for p in sorted(p for p in parts if p.startswith(feat + "-")):
                rows.append(p)
                rows += sorted(m for m in mins if m == "min-" + p or m.startswith("min-" + p + "+"))
        for feat in rows:
            cells = []
            for name, _ in targets:
                if sizes[(name, feat)] is None:
                    cells.append("does not link")
                    continue
                fl, ram = sizes[(name, feat)]
                cells.append(fmt(fl) + ("" if ram == 0 else f" (+{ram} RAM)"))
            # the pitch's variants: -reduced (steps 4 and 6 left out), -fixed
            # (one configuration, fixed at compile time), both
            fixed = feat in mins and feat.endswith("-fixed")
            reduced = feat in mins and re.sub("-fixed$", "", feat).endswith("-reduced")
            goal = M0_FLASH_TARGETS.get(core_key(feat) if feat in mins and "+" not in feat
                                        else feat)
            m0 = next((sizes[(n, feat)][0] for n, _ in targets
                       if "m0" in n.lower() and sizes[(n, feat)] is not None), None)
            verdict = ""
            if goal and m0 is not None:
                verdict = f"<= {fmt(goal)}: " + ("met" if m0 <= goal else f"**over by {fmt(m0 - goal)}**")
                # never a verdict that hides the reduced definition or the
                # single configuration
                verdict += {(True, False): " (reduced definition)",
                            (False, True): " (one configuration)",
                            (True, True): " (reduced definition, one configuration)"}.get(
                                (reduced, fixed), "")
            if feat == "all":
                label = "everything"
            elif fixed:
                label = ("&nbsp;&nbsp;&nbsp;&nbsp;" + ("reduced" if reduced else "minimal") +
                         " core, its configuration fixed at compile time (`" +
                         "`, `".join(min_fixed_config) + "`)")
            elif reduced:
                label = ("&nbsp;&nbsp;reduced core (no octave or below-range check: `" +
                         "`, `".join(min_reduced_config) + "`)")
            elif feat in mins:
                pad = "&nbsp;" * (4 if "-" in feat[4:] else 2)
                label = pad + ("minimal core" if "+" not in feat else
                               "minimal core + `" + "`, `".join(
                                   x for x in mins[feat] if x not in mins[feat.split("+")[0]]) + "`")
            elif feat in parts:
                label = "&nbsp;&nbsp;of which `ssda_" + feat.split("-", 1)[1] + "*`" + \
                    {"match-match": " (search core)", "stream-source": " (streaming layer)"}.get(feat, "")
            else:
                label = FEATURE_NAMES.get(feat, f"`{feat}.h`")
            w(f"| {label} | " + " | ".join(cells) + f" | {verdict} |\n")

        # Where the bytes go on the first target (the M0+), for the features
        # with a target: library functions and runtime routines by size.
        name0, build0 = targets[0]
        nm = cache_value(build0, "CMAKE_OBJDUMP")[: -len("objdump")] + "nm"
        lib_syms = set()
        for lib in (os.path.join(build0, "ssda", "lib", "libssda.a"), os.path.join(build0, "libssda_min.a"),
                    os.path.join(build0, "libssda_min_reduced.a"),
                    os.path.join(build0, "libssda_min_pitch_fixed.a"),
                    os.path.join(build0, "libssda_min_pitch_reduced_fixed.a")):
            if os.path.exists(lib):
                lib_syms |= set(subprocess.run([nm, "--defined-only", lib],
                                               capture_output=True, text=True).stdout.split())
        base_syms = set(subprocess.run([nm, os.path.join(build0, "fw_base.elf")],
                                       capture_output=True, text=True).stdout.split())
        for feat in [f for f in rows if f in M0_FLASH_TARGETS or
                     (f in mins and "+" not in f and
                      core_key(f) in M0_FLASH_TARGETS)]:
            elf = os.path.join(build0, f"fw_{feat}.elf")
            if not os.path.exists(elf):
                continue
            out = subprocess.run([nm, "-S", "--size-sort", elf], capture_output=True, text=True).stdout
            parts, seen = [], set()
            for line in reversed(out.splitlines()):
                p = line.split()
                if len(p) != 4 or p[3] in base_syms or p[0] in seen:
                    continue
                seen.add(p[0])  # aliases share an address
                # GCC's clones (f.constprop.0, f.isra.0, f.part.0) are the library's too
                parts.append((int(p[1], 16), p[3], p[3] in lib_syms or p[3].split(".")[0] in lib_syms))
            lib = sum(n for n, _, own in parts if own)
            key = core_key(feat) if feat in mins else feat
            title = FEATURE_NAMES.get(key) or ("`ssda_" + key.split("-", 1)[-1] + "*` (" +
                                               {"match-match": "search core",
                                                "stream-source": "streaming layer"}.get(key, key) + ")")
            if feat in mins:
                title += (", reduced core" if re.sub("-fixed$", "", feat).endswith("-reduced")
                          else ", minimal core")
                title += ", fixed configuration" if feat.endswith("-fixed") else ""
            w(f"\n<details><summary>{name0}, {title}: "
              f"{fmt(lib)} B library, {fmt(sum(n for n, _, own in parts) - lib)} B runtime "
              "(libgcc, C library)</summary>\n\n")
            w(", ".join(f"`{n}` {sz}" + ("" if own else "*") for sz, n, own in parts) +
              "\n\n(* runtime routine)\n</details>\n")

        stacks = {name: stack_worst(build) for name, build in targets}
        w("\n### Worst-case stack per public function (bytes, -Os)\n\n")
        w("GCC's `-fstack-usage` frame of each library function (from "
          "`-fcallgraph-info=su`) plus the deepest chain of calls below it, "
          "libgcc and C library routines included (their frames read from "
          "the disassembly). `+cb`: the function calls a caller's callback, "
          "whose stack comes on top. Limit: " + str(STACK_LIMIT) + " B (" +
          ", ".join(f"`{f}`: {v} B" for f, v in STACK_TARGETS.items()) + ").\n\n")
        w("| function | " + " | ".join(n for n, _ in targets) + " | deepest chain (" + targets[0][0] + ") |\n")
        w("|---|" + "---:|" * len(targets) + "---|\n")
        for feat in order[:-1]:
            for fn in feats[feat]:
                cells = []
                for name, _ in targets:
                    r = stacks[name].get(fn)
                    if r is None:
                        cells.append("-")
                        continue
                    cell = str(r[0])
                    if r[0] > STACK_TARGETS.get(fn, STACK_LIMIT):
                        cell = f"**{cell}**"
                    if "callback" in r[1]:
                        cell += " +cb"
                    if "recursion" in r[1] or any(x.startswith("unknown") or x.startswith("dynamic") for x in r[1]):
                        cell += " (" + ", ".join(sorted(x for x in r[1] if x != "callback")) + ")"
                    cells.append(cell)
                r0 = stacks[targets[0][0]].get(fn)
                chain = " > ".join(r0[2]) if r0 else ""
                w(f"| `{fn}` | " + " | ".join(cells) + f" | {chain} |\n")

    runs = [(name, *read_cycles(path)) for name, path in (c.split("=", 1) for c in a.cycles)]
    if runs:
        def get(res, key):
            return res.get(key, (0, 0, 0, 0))
        w("\n### Instructions on the emulated Cortex-M4 (QEMU mps2-an386, `-icount shift=0`)\n\n")
        w("SysTick read before and after each job (1 count = 40 instructions, "
          "+-40 per reading); the method is checked on a loop of known length "
          "each run. Columns: kernel set linked.\n\n")
        names = [f"{n} ({k})" for n, k, _ in runs]
        w("| SAD kernel, instructions per pixel | " + " | ".join(names) + " |\n")
        w("|---|" + "---:|" * len(runs) + "\n")
        for key, label in (("kernel.sad_u8.row16", "8-bit, 16-px row (inside the call)"),
                           ("kernel.sad_u8.row4096", "8-bit, long rows"),
                           ("kernel.sad_u16.row16", "16-bit, 16-px row (inside the call)"),
                           ("kernel.sad_u16.row4096", "16-bit, long rows"),
                           ("kernel.absdiff_i16.row320", "int16 AMDF, 320-sample row"),
                           ("kernel.absdiff_i16.row4096", "int16 AMDF, long rows")):
            w(f"| {label} | " + " | ".join(per(*get(r, key)[:2]) for _, _, r in runs) + " |\n")

        if any("match.none" in r for _, _, r in runs):
            w("\n| 16x16 window in a 32x32 area (16 windows, mean) | " +
              " | ".join(f"{n}: instructions" for n in names) + " | pixel ops | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---:|---:|\n")
            for key, label in (("match.none", "brute force (`SSDA_THRESHOLD_NONE`)"),
                               ("match.auto", "`auto` (raster)"),
                               ("match.auto_predict", "`auto` + prediction"),
                               ("match.auto_bounds", "`auto` + bounds"),
                               ("match.auto_blocks", "`auto` + bounds + blocks (whole bounds at once, tile candidates)"),
                               ("match.auto_predict_bounds", "`auto` + prediction + bounds")):
                r0 = get(runs[0][2], key)
                w(f"| {label} | " + " | ".join(fmt(round(get(r, key)[0] / max(1, get(r, key)[1])))
                                              for _, _, r in runs) +
                  f" | {fmt(round(r0[3] / max(1, r0[1])))} | {r0[2]} |\n")

        if any("track.none" in r for _, _, r in runs):
            w("\n| 7x7 grid tracking, 128x128 image (per window) | " +
              " | ".join(f"{n}: instructions" for n in names) + " | pixel ops | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---:|---:|\n")
            for key, label in (("track.none", "brute force"), ("track.auto", "`auto`"),
                               ("track.auto_predict_bounds", "`auto` + median prediction + bounds"),
                               ("track.auto_predict_bounds_shared",
                                "`auto` + median prediction + bounds, shared tables")):
                r0 = get(runs[0][2], key)
                w(f"| {label} | " + " | ".join(fmt(round(get(r, key)[0] / max(1, get(r, key)[1])))
                                              for _, _, r in runs) +
                  f" | {fmt(round(r0[3] / max(1, r0[1])))} | {r0[2]} |\n")

        if any("push.track_frame" in r for _, _, r in runs):
            w("\n| push-mode tracking, 7x7 grid, 128x128 SECOND pushed row by row, FIRST in RAM | " +
              " | ".join(f"{n}: instructions" for n in names) + " | pixel ops | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---:|---:|\n")
            for key, label in (("push.track_row_idle", "one `ssda_push_row` that solves no grid row"),
                               ("push.track_frame", "whole frame, per pushed row")):
                r0 = get(runs[0][2], key)
                w(f"| {label} | " + " | ".join(fmt(round(get(r, key)[0] / max(1, get(r, key)[1])))
                                              for _, _, r in runs) +
                  f" | {fmt(round(r0[3] / max(1, r0[1])))} | {r0[2]} |\n")

        for geo, label_geo in (("ncc16", "16x16 window in a 32x32 area"),
                               ("ncc20", "20x20 window in a 40x40 area")):
            if any(f"{geo}.full" in r for _, _, r in runs):
                w(f"\n| correlation search, {label_geo} (16 windows, mean) | " +
                  " | ".join(f"{n}: instructions" for n in names) + " | pixel ops | stack peak (B) |\n")
                w("|---|" + "---:|" * len(runs) + "---:|---:|\n")
                for key, label in ((f"{geo}.full", "every position in full (`SSDA_NCC_FULL`)"),
                                   (f"{geo}.early", "early exit (raster)"),
                                   (f"{geo}.early_predict", "early exit + prediction")):
                    r0 = get(runs[0][2], key)
                    w(f"| {label} | " + " | ".join(fmt(round(get(r, key)[0] / max(1, get(r, key)[1])))
                                                  for _, _, r in runs) +
                      f" | {fmt(round(r0[3] / max(1, r0[1])))} | {r0[2]} |\n")

        if any("relax.median" in r for _, _, r in runs):
            w("\n| cleaning a 12x12 vector grid (144 vectors, 10 % outliers) | " +
              " | ".join(f"{n}: instructions" for n in names) + " | vectors changed | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---:|---:|\n")
            for key, label in (("relax.labels10", "relaxation labelling, 10 iterations"),
                               ("relax.labels50", "relaxation labelling, 50 iterations (the default)"),
                               ("relax.median", "normalised median test")):
                r0 = get(runs[0][2], key)
                w(f"| {label} | " + " | ".join(fmt(get(r, key)[0]) for _, _, r in runs) +
                  f" | {r0[3]} | {r0[2]} |\n")

        if any("composite.seed" in r for _, _, r in runs):
            w("\n| composite templates, 81 of 20x20 every 5 px, 96x96 pair | " +
              " | ".join(f"{n}: instructions per template" for n in names) +
              " | pixel ops per template | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---:|---:|\n")
            r0 = get(runs[0][2], "composite.seed")
            w("| origin over the whole image, the others in their disks | " +
              " | ".join(fmt(round(get(r, "composite.seed")[0] / max(1, get(r, "composite.seed")[1])))
                         for _, _, r in runs) +
              f" | {fmt(round(r0[3] / max(1, r0[1])))} | {r0[2]} |\n")

        if any("pitch.full" in r for _, _, r in runs):
            plain = get(runs[0][2], "pitch.plain_amdf_diffs")[3]
            w("\n| pitch frame, 16 kHz, lags 16..320, K = 320, hop 80 (24 voiced frames) | " +
              " | ".join(f"{n}: mean / worst instructions" for n in names) +
              f" | differences (plain AMDF: {fmt(plain)}) | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---:|---:|\n")
            for key, label in (("pitch.full", "full AMDF (`SSDA_PITCH_FULL`)"),
                               ("pitch.early_exit", "early exit"),
                               ("pitch.early_exit_track", "early exit + tracking (`SSDA_PITCH_TRACK`)")):
                r0 = get(runs[0][2], key)
                cells = [fmt(round(get(r, key)[0] / max(1, get(r, key)[1]))) + " / " +
                         fmt(get(r, key + ".worst")[0]) for _, _, r in runs]
                w(f"| {label} | " + " | ".join(cells) +
                  f" | {fmt(round(r0[3] / max(1, r0[1])))} | {r0[2]} |\n")

        if any("segment.kl_acc" in r for _, _, r in runs):
            w("\n| colour segmentation (`kl.h`, `mixture.h`, `region.h`); 256 x 16 RGB, "
              "4 stripes | " + " | ".join(f"{n}: instructions" for n in names) +
              " | per | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---|---:|\n")
            for key, label, per_what in (
                    ("segment.kl_acc", "band statistics (`ssda_kl_acc_add_row`)", "pixel"),
                    ("segment.kl_transform", "three features (`ssda_kl_transform_row`)", "pixel"),
                    ("segment.label", "labels through the table (`ssda_mix_label_row`)", "pixel"),
                    ("segment.clean", "isolated-point removal (`ssda_region_push`)", "pixel"),
                    ("segment.kl_solve", "K-L solve: matrix, Jacobi, plan (`ssda_kl_solve`)", "call"),
                    ("segment.em_fit", "EM, 256 bins, K = 4 (`ssda_mix_fit`)", "iteration"),
                    ("segment.search_fit", "the seed's search, same histogram (`ssda_mix_fit`)",
                     "fit")):
                r0 = get(runs[0][2], key)
                cells = [per(*get(r, key)[:2]) if per_what == "pixel"
                         else fmt(round(get(r, key)[0] / max(1, get(r, key)[1])))
                         for _, _, r in runs]
                w(f"| {label} | " + " | ".join(cells) + f" | {per_what} | {r0[2]} |\n")
        if any("symreg.edge_detect" in r for _, _, r in runs):
            r0 = runs[0][2]
            pairs = get(r0, "symreg.pairs")
            w("\n| seed 001 on a 96 x 96 pair (a quarter turn, 3/4 brightness) | " +
              " | ".join(f"{n}: instructions" for n in names) + " | per | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---|---:|\n")
            for key, label, unit in (
                    ("symreg.edge_detect", "`ssda_edge_detect` (operator + ridge thinning)", "pixel"),
                    ("symreg.edge_refine", "`ssda_edge_refine` (3 x 3 stages, extension, T/I/V)", "pixel"),
                    ("symreg.loops_find", "`ssda_loops_find` (prune, regions, contours)", "call"),
                    ("symreg.fd_compute", "`ssda_fd_compute` (64 samples, order 10)", "loop"),
                    ("symreg.fd_match", "`ssda_fd_match` (s, phi, alpha free)", "match"),
                    ("symreg.fd_match_fixed", "`ssda_fd_match_fixed`", "match"),
                    ("symreg.register", f"`ssda_symreg` ({pairs[3]} loops, {pairs[0]} pairs found)",
                     "REF x MOV loop pair")):
                digits = 1 if unit == "pixel" else 0
                cells = [per(*get(r, key)[:2], digits) if unit != "call" else fmt(get(r, key)[0])
                         for _, _, r in runs]
                w(f"| {label} | " + " | ".join(cells) + f" | {unit} | {get(r0, key)[2]} |\n")
        if any("reg.warp_nearest_o1" in r for _, _, r in runs):
            w("\n| band registration (issue 17) | " +
              " | ".join(f"{n}: instructions" for n in names) + " | per | stack peak (B) |\n")
            w("|---|" + "---:|" * len(runs) + "---|---:|\n")
            for key, label, unit in (
                    ("reg.warp_nearest_o1", "warp, nearest, order 1, in RAM", "output pixel"),
                    ("reg.warp_bilinear_o1", "warp, bilinear, order 1, in RAM", "output pixel"),
                    ("reg.warp_bilinear_o3", "warp, bilinear, order 3, in RAM", "output pixel"),
                    ("reg.warp_bilinear_o2_stream2k", "warp, bilinear, order 2, streamed in 2 KB",
                     "output pixel"),
                    ("reg.points_absncc", "control points, |rho|, 20 in 40", "cell"),
                    ("reg.points_sad", "control points, SSDA, 20 in 40", "cell"),
                    ("reg.fit_o2_16", "fit, order 2, 16 pairs", "fit"),
                    ("reg.shade_add", "shading, accumulate", "pixel"),
                    ("reg.shade_apply", "shading, correct", "pixel")):
                r0 = get(runs[0][2], key)
                w(f"| {label} | " + " | ".join(fmt(round(get(r, key)[0] / max(1, get(r, key)[1])))
                                              for _, _, r in runs) + f" | {unit} | {r0[2]} |\n")


if __name__ == "__main__":
    main()
