#!/usr/bin/python3
"""symbolic_bench.py - seed 001 side by side with what a user would pick
instead (a benchmark: figures, not pass/fail), in one run:

  shapes        `ssda shape` (Fourier descriptors) on silhouettes under known
                turns and scales: s within 1 %, phi within 0.5 deg; and the
                share of shapes whose best match is the right one, against
                cv2.matchShapes (Hu moments, I1/I2/I3; it gives no s, phi).
  registration  `ssda symreg` (closed loops) against ORB features +
                cv2.estimateAffinePartial2D and cv2.estimateAffine2D (RANSAC)
                on pairs made from each scene by a known similarity (turns
                0..180 deg, scales 0.7..1.4) and a gain (0.5..2): success =
                every corner of REF within 2 px of the truth; corner RMS of
                the successes; memory of each.

usage: symbolic_bench.py --ssda BUILD/tools/cli/ssda --gen BUILD/.../ssda_cli_gen_symreg
           [--shapes DIR] [--scene NAME=PATH ...] [--quick] [--out FILE.md]
Scenes: `synthetic` (rendered by gen_symreg, roofs on textured ground) is
always run; PATH scenes are real images (e.g. ../shared/data/classic/
camera.png) turned and scaled in memory (cv2.warpAffine, linear, borders
reflected). Needs /usr/bin/python3 with cv2 and numpy.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import cv2
import numpy as np


# ---------------------------------------------------------------- helpers

def run_json(cmd):
    """Run cmd (its --json to a temp file) under /usr/bin/time; (dict or None,
    seconds, peak RSS of the process in KB)."""
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as f:
        path = f.name
    with tempfile.NamedTemporaryFile(suffix=".rss", delete=False) as f:
        rss_path = f.name
    t0 = time.perf_counter()
    p = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", rss_path] + cmd +
                       ["--json", path, "-q"], stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
    secs = time.perf_counter() - t0
    data = None
    if p.returncode == 0:
        with open(path) as f:
            data = json.load(f)
    with open(rss_path) as f:
        lines = [ln for ln in f.read().split() if ln.isdigit()]
    os.unlink(path)
    os.unlink(rss_path)
    return data, secs, int(lines[-1]) if lines else 0


def similarity(w, h, deg, scale, tx=0.0, ty=0.0):
    """2 x 3 REF -> MOV: turn deg (+x towards +y) and scale about the centre."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    A = np.array([[scale * c, -scale * s, 0.0], [scale * s, scale * c, 0.0]])
    cx, cy = (w - 1) / 2.0, (h - 1) / 2.0
    A[0, 2] = cx + tx - (A[0, 0] * cx + A[0, 1] * cy)
    A[1, 2] = cy + ty - (A[1, 0] * cx + A[1, 1] * cy)
    return A


def corner_errors(A_est, A_true, w, h):
    C = np.array([[0, 0, 1], [w - 1, 0, 1], [0, h - 1, 1], [w - 1, h - 1, 1]], float).T
    return np.linalg.norm(A_est @ C - A_true @ C, axis=0)


def median(v):
    return float(np.median(v)) if len(v) else float("nan")


# ---------------------------------------------------------------- shapes

def largest_contour(mask):
    cs, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    return max(cs, key=cv2.contourArea)


def transform_silhouette(img, deg, scale):
    """img turned and scaled about its centre on a canvas large enough."""
    h, w = img.shape
    side = int(math.ceil(max(w, h) * scale * 1.5)) + 8
    A = similarity(w, h, deg, scale)
    A[:, 2] += [(side - w) / 2.0, (side - h) / 2.0]
    out = cv2.warpAffine(img, A, (side, side), flags=cv2.INTER_LINEAR, borderValue=0)
    return (out >= 128).astype(np.uint8) * 255


def bench_shapes(ssda, shapes_dir, quick, tmp):
    names = [os.path.join(shapes_dir, f"{i}.png") for i in range(1, 11)]
    imgs = [cv2.imread(n, cv2.IMREAD_GRAYSCALE) for n in names]
    imgs = [(im >= 128).astype(np.uint8) * 255 for im in imgs]
    partner = {i: i ^ 1 for i in range(10)}  # 0-1, 2-3, ... (files 1-2, 3-4, ...)
    angles = [17, 95, 200] if quick else [17, 60, 95, 150, 200, 290]
    scales = [0.7, 1.3] if quick else [0.6, 0.8, 1.25, 1.5]
    rows = []
    # (a) known transforms of each silhouette: s, phi against the truth
    s_err, phi_err, ok_s, ok_phi, n = [], [], 0, 0, 0
    secs = []
    for i, im in enumerate(imgs):
        a = os.path.join(tmp, f"a{i}.png")
        cv2.imwrite(a, im)
        for deg in angles:
            for sc in scales:
                b = os.path.join(tmp, f"b{i}.png")
                cv2.imwrite(b, transform_silhouette(im, deg, sc))
                d, t, _ = run_json([ssda, "shape", a, b])
                secs.append(t)
                n += 1
                if d is None:
                    continue
                es = abs(d["s"] / sc - 1.0)
                ep = abs((d["phi_deg"] - deg + 540.0) % 360.0 - 180.0)
                s_err.append(es)
                phi_err.append(ep)
                ok_s += es <= 0.01
                ok_phi += ep <= 0.5
    rows.append(("transformed silhouettes", n, ok_s, ok_phi, median(s_err), median(phi_err),
                 max(s_err) if s_err else float("nan"), max(phi_err) if phi_err else float("nan")))
    # (b) which shape matches best: ours (E2) vs Hu moments
    e2 = np.full((10, 10), np.inf)
    hu = {m: np.full((10, 10), np.inf) for m in (1, 2, 3)}
    conts = [largest_contour(im) for im in imgs]
    paths = []
    for i, im in enumerate(imgs):
        p = os.path.join(tmp, f"s{i}.png")
        cv2.imwrite(p, im)
        paths.append(p)
    for i in range(10):
        for j in range(10):
            if i == j:
                continue
            d, _, _ = run_json([ssda, "shape", paths[i], paths[j]])
            if d is not None:
                e2[i, j] = d["e2"]
            for m in (1, 2, 3):
                hu[m][i, j] = cv2.matchShapes(conts[i], conts[j], m, 0.0)
    pair_ok = {"ssda E2": sum(int(np.argmin(e2[i]) == partner[i]) for i in range(10))}
    for m in (1, 2, 3):
        pair_ok[f"matchShapes I{m}"] = sum(int(np.argmin(hu[m][i]) == partner[i]) for i in range(10))
    # (c) a transformed shape against the ten originals: is it found?
    self_ok = {k: 0 for k in pair_ok}
    self_n = 0
    for i, im in enumerate(imgs):
        for deg, sc in [(35, 0.75), (160, 1.3)] if quick else [(35, 0.75), (160, 1.3), (250, 0.9)]:
            b = os.path.join(tmp, "t.png")
            t_img = transform_silhouette(im, deg, sc)
            cv2.imwrite(b, t_img)
            tc = largest_contour(t_img)
            ours = []
            for j in range(10):
                d, _, _ = run_json([ssda, "shape", paths[j], b])
                ours.append(d["e2"] if d else np.inf)
            self_ok["ssda E2"] += int(np.argmin(ours) == i)
            for m in (1, 2, 3):
                self_ok[f"matchShapes I{m}"] += int(
                    np.argmin([cv2.matchShapes(conts[j], tc, m, 0.0) for j in range(10)]) == i)
            self_n += 1
    return rows, pair_ok, self_ok, self_n, median(secs)


# ---------------------------------------------------------------- registration

def orb_register(ref, mov, partial):
    """ORB + RANSAC; 2 x 3 REF -> MOV or None; seconds."""
    t0 = time.perf_counter()
    orb = cv2.ORB_create(nfeatures=3000)
    k1, d1 = orb.detectAndCompute(ref, None)
    k2, d2 = orb.detectAndCompute(mov, None)
    if d1 is None or d2 is None or len(k1) < 3 or len(k2) < 3:
        return None, time.perf_counter() - t0
    m = cv2.BFMatcher(cv2.NORM_HAMMING).knnMatch(d1, d2, k=2)
    good = [a for a, b in (x for x in m if len(x) == 2) if a.distance < 0.8 * b.distance]
    if len(good) < 3:
        return None, time.perf_counter() - t0
    src = np.float32([k1[g.queryIdx].pt for g in good])
    dst = np.float32([k2[g.trainIdx].pt for g in good])
    fit = cv2.estimateAffinePartial2D if partial else cv2.estimateAffine2D
    A, _ = fit(src, dst, method=cv2.RANSAC, ransacReprojThreshold=3.0)
    return A, time.perf_counter() - t0


ORB_MEM_CODE = r"""
import sys, cv2, numpy as np
def status(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1])
ref = cv2.imread(sys.argv[1], cv2.IMREAD_GRAYSCALE); mov = cv2.imread(sys.argv[2], cv2.IMREAD_GRAYSCALE)
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")  # reset the peak (VmHWM) to the current RSS
base = status("VmRSS")
if sys.argv[3] == "1":
    orb = cv2.ORB_create(nfeatures=3000)
    k1, d1 = orb.detectAndCompute(ref, None); k2, d2 = orb.detectAndCompute(mov, None)
    m = cv2.BFMatcher(cv2.NORM_HAMMING).knnMatch(d1, d2, k=2)
    good = [a for a, b in (x for x in m if len(x) == 2) if a.distance < 0.8 * b.distance]
    src = np.float32([k1[g.queryIdx].pt for g in good]); dst = np.float32([k2[g.trainIdx].pt for g in good])
    cv2.estimateAffine2D(src, dst, method=cv2.RANSAC, ransacReprojThreshold=3.0)
print(status("VmHWM") - base)
"""


def orb_memory_kb(ref_path, mov_path):
    """Peak RSS growth of a process while it runs ORB + RANSAC on the pair
    (images already loaded; VmHWM reset through /proc/self/clear_refs), KB."""
    out = subprocess.run([sys.executable, "-c", ORB_MEM_CODE, ref_path, mov_path, "1"],
                         capture_output=True, text=True, check=True).stdout
    return int(out.strip())


def scene_pairs(quick):
    angles = [0, 45, 90, 135, 180] if quick else [0, 30, 60, 90, 120, 150, 180]
    scales = [0.7, 1.0, 1.4] if quick else [0.7, 0.85, 1.0, 1.2, 1.4]
    gains = [0.5, 1.0, 2.0]
    out = []
    for ia, a in enumerate(angles):
        for isc, s in enumerate(scales):
            # every gain with every angle, spread over the scales (a Latin design
            # keeps the run short): each (angle, scale) cell gets one gain
            g = gains[(ia + isc) % len(gains)]
            out.append((a, s, g))
    return out


def bench_registration(ssda, gen, scenes, quick, tmp):
    results = {}
    for name, path in scenes:
        res = {k: {"ok": 0, "n": 0, "rms": [], "found": 0, "secs": []}
               for k in ("ssda symreg", "ORB + estimateAffinePartial2D", "ORB + estimateAffine2D")}
        mem = {"lib": [], "ssda_rss": [], "orb_rss": []}
        loops = []
        for k, (deg, sc, gain) in enumerate(scene_pairs(quick)):
            rp, mp = os.path.join(tmp, "r.png"), os.path.join(tmp, "m.png")
            if path is None:  # synthetic: rendered exactly through the transform
                t = subprocess.run([gen, "scene", rp, mp, "--angle", str(deg), "--scale", str(sc),
                                    "--gain", str(gain), "--shift", "5,-3", "--size", "384",
                                    "--seed", str(100 + k)], capture_output=True, text=True,
                                   check=True).stdout.split()
                A_true = np.array([float(v) for v in t]).reshape(2, 3)
                ref = cv2.imread(rp, cv2.IMREAD_GRAYSCALE)
                mov = cv2.imread(mp, cv2.IMREAD_GRAYSCALE)
            else:
                ref = cv2.imread(path, cv2.IMREAD_GRAYSCALE)
                h, w = ref.shape
                A_true = similarity(w, h, deg, sc, 5.0, -3.0)
                mov = cv2.warpAffine(ref, A_true, (w, h), flags=cv2.INTER_LINEAR,
                                     borderMode=cv2.BORDER_REFLECT_101)
                mov = np.clip(mov.astype(np.float32) * gain, 0, 255).astype(np.uint8)
                cv2.imwrite(rp, ref)
                cv2.imwrite(mp, mov)
            h, w = ref.shape
            d, secs, rss = run_json([ssda, "symreg", rp, mp])
            r = res["ssda symreg"]
            r["n"] += 1
            r["secs"].append(secs)
            mem["ssda_rss"].append(rss)
            if d is not None:
                r["found"] += 1
                A = np.array(d["affine"]).reshape(2, 3)
                e = corner_errors(A, A_true, w, h)
                loops.append(min(d["loops_ref"], d["loops_mov"]))
                mem["lib"].append(max(d["lib_bytes_ref"], d["lib_bytes_mov"]) + d["lib_bytes_symreg"])
                if e.max() < 2.0:
                    r["ok"] += 1
                    r["rms"].append(float(np.sqrt((e ** 2).mean())))
            for key, partial in (("ORB + estimateAffinePartial2D", True),
                                 ("ORB + estimateAffine2D", False)):
                A, secs = orb_register(ref, mov, partial)
                r = res[key]
                r["n"] += 1
                r["secs"].append(secs)
                if A is not None:
                    r["found"] += 1
                    e = corner_errors(A, A_true, w, h)
                    if e.max() < 2.0:
                        r["ok"] += 1
                        r["rms"].append(float(np.sqrt((e ** 2).mean())))
            if k == 0:
                mem["orb_rss"].append(orb_memory_kb(rp, mp))
        results[name] = (res, mem, loops, ref.shape)
    return results


# ---------------------------------------------------------------- report

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ssda", required=True)
    ap.add_argument("--gen", required=True)
    ap.add_argument("--shapes")
    ap.add_argument("--scene", action="append", default=[])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out")
    a = ap.parse_args()
    lines = []
    say = lines.append
    load = os.getloadavg()
    say(f"Run: `tools/bench-symbolic.sh{' --quick' if a.quick else ''}`; "
        f"load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}; OpenCV {cv2.__version__}; "
        f"{'quick' if a.quick else 'full'} grid.")
    say("")
    with tempfile.TemporaryDirectory() as tmp:
        if a.shapes:
            rows, pair_ok, self_ok, self_n, secs = bench_shapes(a.ssda, a.shapes, a.quick, tmp)
            say("### Shapes (`ssda shape`, 256 samples, order 10) on the 10 silhouettes of shapes/")
            say("")
            say("| case | runs | s within 1 % | phi within 0.5 deg | median |s/s0 - 1| | median phi error | worst |s/s0 - 1| | worst phi error |")
            say("|---|---:|---:|---:|---:|---:|---:|---:|")
            for name, n, oks, okp, ms, mp, ws, wp in rows:
                say(f"| {name} | {n} | {oks} ({100.0 * oks / n:.0f} %) | {okp} ({100.0 * okp / n:.0f} %) "
                    f"| {100 * ms:.2f} % | {mp:.3f} deg | {100 * ws:.2f} % | {wp:.2f} deg |")
            say("")
            say(f"Median time per `ssda shape` run (process, both PNGs read): {1e3 * secs:.0f} ms.")
            say("")
            say("| matcher | best match is the partner drawing (1-2, 3-4, ...), of 10 | "
                f"a turned and scaled copy finds its original among the 10, of {self_n} |")
            say("|---|---:|---:|")
            for k in pair_ok:
                say(f"| {k} | {pair_ok[k]} | {self_ok[k]} |")
            say("")
        scenes = [("synthetic roofs (gen_symreg, 384 x 384)", None)]
        for s in a.scene:
            name, _, path = s.partition("=")
            scenes.append((name, path))
        results = bench_registration(a.ssda, a.gen, scenes, a.quick, tmp)
    n_pairs = len(scene_pairs(a.quick))
    say(f"### Registration: {n_pairs} pairs per scene (turns, scales, gains below), "
        "success = all four corners within 2 px")
    say("")
    say("| scene | method | success | found a transform | corner RMS of successes (median) | time per pair (median) |")
    say("|---|---|---:|---:|---:|---:|")
    for name, (res, mem, loops, shape) in results.items():
        for k, r in res.items():
            say(f"| {name} | {k} | {r['ok']}/{r['n']} ({100.0 * r['ok'] / r['n']:.0f} %) | "
                f"{r['found']}/{r['n']} | {median(r['rms']):.2f} px | {1e3 * median(r['secs']):.0f} ms |")
    say("")
    say("| scene | size | loops (median, fewer of the two) | ssda library buffers (median) | `ssda symreg` process peak RSS (median) | ORB + RANSAC: peak RSS growth while it runs |")
    say("|---|---|---:|---:|---:|---:|")
    for name, (res, mem, loops, shape) in results.items():
        say(f"| {name} | {shape[1]} x {shape[0]} | {median(loops):.0f} | "
            f"{median(mem['lib']) / 1024:.0f} KB | {median(mem['ssda_rss']) / 1024:.1f} MB | "
            f"{median(mem['orb_rss']) / 1024:.1f} MB |")
    say("")
    say("Library buffers: what `ssda_edge_*`, `ssda_loops_find`, the descriptors and "
        "`ssda_symreg` needed for the larger image of the pair plus the registration "
        "(the JSON's lib_bytes_*). Process peaks include libpng, cairo and the decoded "
        "images; ORB's growth is measured in a Python process after the images are loaded.")
    say("")
    grid = scene_pairs(a.quick)
    say("Pairs: " + ", ".join(f"{d} deg x {s} (gain {g})" for d, s, g in grid) + ".")
    text = "\n".join(lines)
    print(text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
