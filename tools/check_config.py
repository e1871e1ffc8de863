#!/usr/bin/env python3
"""Compile lib/ with each feature switch of include/ssda/config.h alone, and
with all of them, the way the library is compiled (-Werror and the project's
warnings), for each configured build given (tools/check-config.sh makes them).

Why: a switch is a documented build of the library, but the test builds use
the full library, the budget's minimal cores set many switches at once, and
the QEMU/cross builds none; so a switch alone could stop compiling unseen
(SSDA_CFG_NO_BOUNDS alone did in session 7). Only the files whose
preprocessed text the switch changes are compiled again (the others compile
as in the full build), so a build directory takes seconds, not minutes.

Usage: tools/check_config.py CONFIG_H BUILD_DIR...   (each BUILD_DIR has
compile_commands.json for the target ssda). Exit 1 on any failure, with
the compiler's messages.
"""
import hashlib
import json
import os
import re
import shlex
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor


def switches(config_h):
    with open(config_h, encoding="utf-8") as f:
        names = re.findall(r"#\s*define\s+(SSDA_CFG_NO_[A-Z0-9_]+)", f.read())
    return sorted(set(names))


def lib_commands(build):
    with open(os.path.join(build, "compile_commands.json"), encoding="utf-8") as f:
        entries = json.load(f)
    out = []
    for e in entries:
        src = e["file"]
        if "/lib/" not in src.replace(os.sep, "/"):
            continue
        args = e.get("arguments") or shlex.split(e["command"])
        # drop "-o obj" and "-c": re-added per run
        clean, skip = [], False
        for a in args:
            if skip:
                skip = False
                continue
            if a == "-o":
                skip = True
                continue
            if a == "-c" or a == src:
                continue
            clean.append(a)
        out.append((e["directory"], clean, src))
    return out


def run(directory, args):
    p = subprocess.run(args, cwd=directory, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def preprocessed(job):
    directory, args, src, defs = job
    rc, out, err = run(directory, args + defs + ["-E", "-P", src])
    if rc != 0:
        return None, err
    return hashlib.sha256(out.encode()).hexdigest(), ""


def compile_one(job):
    directory, args, src, defs = job
    return run(directory, args + defs + ["-c", src, "-o", os.devnull])


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    names = switches(sys.argv[1])
    configs = [[n] for n in names] + [names]
    failed = 0
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        for build in sys.argv[2:]:
            cmds = lib_commands(build)
            base = list(pool.map(preprocessed, [(d, a, s, []) for d, a, s in cmds]))
            compiled = 0
            for cfg in configs:
                defs = ["-D" + n for n in cfg]
                jobs = [(d, a, s, defs) for d, a, s in cmds]
                pre = list(pool.map(preprocessed, jobs))
                todo = [j for j, p, b in zip(jobs, pre, base) if p[0] is None or p[0] != b[0]]
                compiled += len(todo)
                for j, (rc, out, err) in zip(todo, pool.map(compile_one, todo)):
                    if rc != 0:
                        failed += 1
                        label = "all switches" if len(cfg) > 1 else cfg[0]
                        print(f"check_config: {os.path.basename(build)}: {label}: "
                              f"{os.path.relpath(j[2])} does not compile:\n{out}{err}",
                              file=sys.stderr)
            print(f"check_config: {build}: {len(configs)} configurations "
                  f"({len(names)} switches alone, all together), {compiled} compilations",
                  file=sys.stderr)
    if failed:
        sys.exit(f"check_config: {failed} failures")


if __name__ == "__main__":
    main()
