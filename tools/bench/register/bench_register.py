#!/usr/bin/python3
"""bench_register.py - issue 17's registration benchmark, side by side in one run.

Methods on the same pairs:
  ssda seed     `ssda register` as the seed: |rho| > 0.65, 4 x 4 cells, 20 x 20
                windows in 40 x 40 areas (+-10 px around the automatic offset)
  ssda wide     the same with 6 x 6 cells and 64 x 64 areas (+-22 px)
  ssda sad      wide, `--metric sad` (the seed's SSDA alternative)
  ECC affine    OpenCV findTransformECC, MOTION_AFFINE (translation at 1/4 scale first)
  ECC homog.    the same with MOTION_HOMOGRAPHY
  ORB+RANSAC    OpenCV ORB (5000 features), Hamming cross-check, estimateAffine2D
  GDAL order N  gdalwarp -order N on ssda wide's control points (GCPs), its map
                read back with gdaltransform -i

Pairs (REF, MOV, truth: REF pixel -> MOV pixel):
  known warps of classic/camera.png and moon.png, made here (cv2.remap,
  bicubic): shift, rotation 3 deg, a 2nd-order map, a 3rd-order map, the 2nd
  with gain 0.7 + 30, with inverted contrast, and rotation 15 deg (beyond the
  seed's method); homography/graf img1 -> img2, img3 with the true H; and
  multiband bands 2-5 against band 1 (no truth: agreement with ECC affine, and
  ssda's round trip REF -> MOV -> REF).

[used/cells]: control points used by the fit / cells of the grid.
Mapping error: RMS and max distance to the truth over a 21 x 21 grid of REF
points (those whose true position lies inside MOV). CPU time: medians of
--reps interleaved runs (ssda, ssda SAD, ECC, ORB in turn), user + system; for ssda the whole process (PNG
decoding, offset, control points, fit, resampling, PNG and JSON encoding),
its registration without file I/O (offset + points + fit + warp, clock()
inside the process) and its map alone (offset + points + fit); the
control points alone with |rho| and with SAD (the seed's speed claim); for
the peers the estimate and the estimate + resampling (no file I/O).

  bench_register.py --ssda build/bench/tools/cli/ssda --data ../shared/data [--reps 3]
"""
import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time

import cv2
import numpy as np

GRID = 21


def cpu():
    return time.process_time()


def child_cpu(cmd):
    """Run cmd, return (cpu seconds of the child, returncode, stdout)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return t, p.returncode, p.stdout + p.stderr


# ---- maps: functions (N, 2) REF px -> (N, 2) MOV px ----

def poly_map(cx, cy):
    ex = [0, 1, 0, 2, 1, 0, 3, 2, 1, 0]
    ey = [0, 0, 1, 0, 1, 2, 0, 1, 2, 3]

    def f(p):
        X, Y = p[:, 0], p[:, 1]
        x = sum(c * X ** ex[t] * Y ** ey[t] for t, c in enumerate(cx))
        y = sum(c * X ** ex[t] * Y ** ey[t] for t, c in enumerate(cy))
        return np.stack([x, y], 1)
    return f


def homog_map(H):
    def f(p):
        q = np.c_[p, np.ones(len(p))] @ np.asarray(H, float).T
        return q[:, :2] / q[:, 2:3]
    return f


def affine_map(A):
    return homog_map(np.vstack([np.asarray(A, float), [0, 0, 1]]))


def rotation(w, h, deg, tx, ty, s=1.0):
    c, sn = s * math.cos(math.radians(deg)), s * math.sin(math.radians(deg))
    cxm, cym = w / 2, h / 2
    # x = cx + tx + c (X - cx) - sn (Y - cy)
    return affine_map([[c, -sn, cxm + tx - c * cxm + sn * cym], [sn, c, cym + ty - sn * cxm - c * cym]])


def inverse_grid(m, w, h, iters=30):
    """For every MOV pixel, the REF position mapping to it (fixed-point)."""
    xs, ys = np.meshgrid(np.arange(w, dtype=float), np.arange(h, dtype=float))
    tgt = np.stack([xs.ravel(), ys.ravel()], 1)
    p = tgt.copy()
    for _ in range(iters):
        p -= m(p) - tgt
    return p[:, 0].reshape(h, w).astype(np.float32), p[:, 1].reshape(h, w).astype(np.float32)


def make_mov(ref, m):
    h, w = ref.shape
    mx, my = inverse_grid(m, w, h)
    return cv2.remap(ref, mx, my, cv2.INTER_CUBIC, borderMode=cv2.BORDER_REFLECT)


def check_points(w, h, truth, mw, mh):
    xs = np.linspace(0.05 * w, 0.95 * w, GRID)
    ys = np.linspace(0.05 * h, 0.95 * h, GRID)
    p = np.array([[x, y] for y in ys for x in xs])
    if truth is None:
        return p
    t = truth(p)
    inside = (t[:, 0] > 5) & (t[:, 1] > 5) & (t[:, 0] < mw - 6) & (t[:, 1] < mh - 6)
    return p[inside]


def err_of(est, truth, p):
    if est is None:
        return None
    d = np.hypot(*(est(p) - truth(p)).T)
    if not np.all(np.isfinite(d)):
        return None
    return float(np.sqrt(np.mean(d * d))), float(d.max())


# ---- methods ----

WIDE = ["--grid", "6x6", "--search", "64"]


def run_ssda(ssda, ref_path, mov_path, tmp, order, metric, reps, extra=()):
    js = os.path.join(tmp, "ssda.json")
    out = os.path.join(tmp, "ssda_out.png")
    times, own = [], []
    doc = None
    for _ in range(reps):
        t, rc, txt = child_cpu([ssda, "register", ref_path, mov_path, "-o", out, "--json", js,
                                "--order", str(order), "--metric", metric, "-q"] + list(extra))
        if rc != 0:
            return None, txt.strip().splitlines()[-1] if txt.strip() else "exit %d" % rc, None, None
        doc = json.load(open(js))
        times.append(t)
        own.append((doc["cpu_offset_s"] + doc["cpu_points_s"] + doc["cpu_fit_s"],
                    doc["cpu_warp_s"], doc["cpu_points_s"]))
    m = poly_map(doc["coeffs_x"], doc["coeffs_y"])
    return m, doc, float(np.median(times)), tuple(np.median(np.array(own), 0))


def ecc(ref, mov, mode):
    r = ref.astype(np.float32)
    m = mov.astype(np.float32)
    crit = (cv2.TERM_CRITERIA_EPS | cv2.TERM_CRITERIA_COUNT, 200, 1e-6)
    t0 = cpu()
    rs = cv2.resize(r, None, fx=0.25, fy=0.25, interpolation=cv2.INTER_AREA)
    ms = cv2.resize(m, None, fx=0.25, fy=0.25, interpolation=cv2.INTER_AREA)
    wt = np.eye(2, 3, dtype=np.float32)
    try:
        _, wt = cv2.findTransformECC(rs, ms, wt, cv2.MOTION_TRANSLATION, crit, None, 5)
        if mode == cv2.MOTION_HOMOGRAPHY:
            W = np.eye(3, dtype=np.float32)
        else:
            W = np.eye(2, 3, dtype=np.float32)
        W[0, 2], W[1, 2] = wt[0, 2] * 4, wt[1, 2] * 4
        _, W = cv2.findTransformECC(r, m, W, mode, crit, None, 5)
    except cv2.error:
        return None, cpu() - t0, None
    t1 = cpu()
    h, w = ref.shape
    if mode == cv2.MOTION_HOMOGRAPHY:
        cv2.warpPerspective(mov, W, (w, h), flags=cv2.INTER_LINEAR + cv2.WARP_INVERSE_MAP)
        est = homog_map(W)
    else:
        cv2.warpAffine(mov, W, (w, h), flags=cv2.INTER_LINEAR + cv2.WARP_INVERSE_MAP)
        est = affine_map(W)
    return est, t1 - t0, cpu() - t0


def orb(ref, mov):
    t0 = cpu()
    r8 = cv2.normalize(ref, None, 0, 255, cv2.NORM_MINMAX).astype(np.uint8)
    m8 = cv2.normalize(mov, None, 0, 255, cv2.NORM_MINMAX).astype(np.uint8)
    det = cv2.ORB_create(5000)
    kr, dr = det.detectAndCompute(r8, None)
    km, dm = det.detectAndCompute(m8, None)
    if dr is None or dm is None:
        return None, cpu() - t0, None
    matches = cv2.BFMatcher(cv2.NORM_HAMMING, crossCheck=True).match(dr, dm)
    if len(matches) < 3:
        return None, cpu() - t0, None
    pr = np.float32([kr[x.queryIdx].pt for x in matches])
    pm = np.float32([km[x.trainIdx].pt for x in matches])
    A, _ = cv2.estimateAffine2D(pr, pm, method=cv2.RANSAC, ransacReprojThreshold=3.0)
    t1 = cpu()
    if A is None:
        return None, t1 - t0, None
    h, w = ref.shape
    cv2.warpAffine(mov, A, (w, h), flags=cv2.INTER_LINEAR + cv2.WARP_INVERSE_MAP)
    return affine_map(A), t1 - t0, cpu() - t0


def gdal(doc, mov_path, tmp, order, check):
    """gdalwarp -order N with ssda's accepted control points as GCPs (MOV
    pixel/line -> REF x/y as the georeference); its map REF -> MOV read back
    with gdaltransform -i at the check points."""
    pts = [p for p in doc["points"] if p["used"]]
    if len(pts) < (order + 1) * (order + 2) // 2:
        return None, None, None
    vrt = os.path.join(tmp, "gcp.vrt")
    cmd = ["gdal_translate", "-q", "-of", "VRT"]
    for p in pts:  # GCP: pixel line (in MOV) -> easting northing (REF px, y negated)
        cmd += ["-gcp", "%.4f" % (p["mov_x"] + 0.5), "%.4f" % (p["mov_y"] + 0.5),
                "%.4f" % (p["ref_x"] + 0.5), "%.4f" % (-(p["ref_y"] + 0.5))]
    cmd += [mov_path, vrt]
    subprocess.run(cmd, check=True)
    t, rc, _ = child_cpu(["gdalwarp", "-q", "-overwrite", "-order", str(order), "-r", "bilinear",
                          "-tr", "1", "1", "-te", "0", str(-doc["height"]), str(doc["width"]), "0",
                          vrt, os.path.join(tmp, "gdal_out.tif")])
    if rc != 0:
        return None, None, None
    inp = "\n".join("%.6f %.6f" % (x + 0.5, -(y + 0.5)) for x, y in check) + "\n"
    p = subprocess.run(["gdaltransform", "-i", "-order", str(order), vrt], input=inp,
                       stdout=subprocess.PIPE, text=True, check=True)
    got = np.array([[float(v) for v in line.split()[:2]] for line in p.stdout.strip().splitlines()])
    got -= 0.5
    lut = {(round(a, 6), round(b, 6)): g for (a, b), g in zip(check, got)}

    def est(q):
        return np.array([lut[(round(a, 6), round(b, 6))] for a, b in q])
    return est, t, t


def fmt(e):
    return "fail" if e is None else "%.3f / %.2f" % e


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ssda", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="ssda-bench-reg-")
    D = a.data
    cases = []
    for name in ("camera", "moon"):
        ref = cv2.imread(os.path.join(D, "classic", name + ".png"), cv2.IMREAD_GRAYSCALE)
        h, w = ref.shape
        quad = poly_map([7.3, 1.004, -0.0087, 2.0e-5, -1.0e-5, 1.5e-5],
                        [-4.6, 0.0087, 1.004, -1.2e-5, 2.2e-5, 0.5e-5])
        cub = poly_map([5.1, 0.995, 0.01, 1.0e-5, -2e-5, 1e-5, 3e-8, -2e-8, 2e-8, -1e-8],
                       [3.2, -0.01, 1.003, 2e-5, 1e-5, -1e-5, -2e-8, 3e-8, -1e-8, 2e-8])
        known = [("shift", affine_map([[1, 0, 7.3], [0, 1, -4.6]]), 1, None),
                 ("rot 3 deg", rotation(w, h, 3.0, 4.0, 2.0), 1, None),
                 ("2nd order", quad, 2, None),
                 ("3rd order", cub, 3, None),
                 ("2nd + gain 0.7, +30", quad, 2, "gain"),
                 ("2nd, inverted", quad, 2, "invert"),
                 ("rot 15 deg", rotation(w, h, 15.0, 3.0, -2.0), 1, None)]
        for label, m, order, photo in known:
            mov = make_mov(ref.astype(np.float32), m)
            if photo == "gain":
                mov = 0.7 * mov + 30
            elif photo == "invert":
                mov = 255 - mov
            mov = np.clip(np.rint(mov), 0, 255).astype(np.uint8)
            rp = os.path.join(tmp, name + ".png")
            mp = os.path.join(tmp, "%s-%d.png" % (name, len(cases)))
            cv2.imwrite(rp, ref)
            cv2.imwrite(mp, mov)
            cases.append(("%s, %s" % (name, label), rp, mp, ref, mov, m, order))
    g = os.path.join(D, "homography", "graf")
    for k in (2, 3):
        ref = cv2.imread(os.path.join(g, "img1.png"), cv2.IMREAD_GRAYSCALE)
        mov = cv2.imread(os.path.join(g, "img%d.png" % k), cv2.IMREAD_GRAYSCALE)
        H = np.loadtxt(os.path.join(g, "H1to%dp" % k))
        rp, mp = os.path.join(tmp, "graf1.png"), os.path.join(tmp, "graf%d.png" % k)
        cv2.imwrite(rp, ref)
        cv2.imwrite(mp, mov)
        cases.append(("graf img1 -> img%d (homography)" % k, rp, mp, ref, mov, homog_map(H), 3))
    mb = os.path.join(D, "multiband")
    for k in (2, 3, 4, 5):
        rp, mp = os.path.join(mb, "IMG_0001_1.png"), os.path.join(mb, "IMG_0001_%d.png" % k)
        ref = cv2.imread(rp, cv2.IMREAD_UNCHANGED)
        mov = cv2.imread(mp, cv2.IMREAD_UNCHANGED)
        cases.append(("multiband 1 -> %d" % k, rp, mp, ref, mov, None, 2))
    if a.only:
        cases = [c for c in cases if a.only in c[0]]

    load = os.getloadavg()[0]
    print("Load average at start: %.2f; reps %d (medians); error: RMS / max px over a %dx%d grid; "
          "time: CPU s" % (load, a.reps, GRID, GRID))
    print()
    print("| pair | ssda seed | ssda wide | ssda sad (wide) | GDAL -order N (wide's points) | ECC affine | ECC homography | ORB + RANSAC affine | ssda wide CPU: process / map + warp / map | control points CPU: \\|rho\\| / SAD | ECC affine CPU: estimate / +resample | ECC (+resample) over ssda: map + warp / process | ORB CPU | gdalwarp CPU |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for label, rp, mp, ref, mov, truth, order in cases:
        h, w = ref.shape
        mh, mw = mov.shape
        check = check_points(w, h, truth, mw, mh)
        res = {}
        seed, doc_seed, _, _ = run_ssda(a.ssda, rp, mp, tmp, order, "absncc", 1)
        ecc_t, orb_t, ours_t, sad_t = [], [], [], []
        ea = eh = ob = None
        for _ in range(a.reps):  # interleaved: ssda, SAD, ECC, ORB in turn
            ours, doc, tw, to = run_ssda(a.ssda, rp, mp, tmp, order, "absncc", 1, WIDE)
            if ours is not None:
                ours_t.append((tw, to))
            sad, doc_s, _, ts = run_ssda(a.ssda, rp, mp, tmp, order, "sad", 1, WIDE)
            if sad is not None:
                sad_t.append(ts)
            ea, te, tr = ecc(ref, mov, cv2.MOTION_AFFINE)
            ecc_t.append((te, tr if tr is not None else float("nan")))
            ob, to, _ = orb(ref, mov)
            orb_t.append(to)
        eh, _, _ = ecc(ref, mov, cv2.MOTION_HOMOGRAPHY)
        gd = t_gd = None
        if ours is not None:
            gd, t_gd, _ = gdal(doc, mp, tmp, order, check)
        if truth is None:
            # no truth: ECC affine as the reference, and ssda's round trip
            ref_map = ea
            row = [label + " (vs ECC affine)"]
            for est in (seed, ours, sad, gd, ea, eh, ob):
                row.append(fmt(err_of(est, ref_map, check)) if ref_map is not None and est is not None else "fail")
            back, _, _, _ = run_ssda(a.ssda, mp, rp, tmp, order, "absncc", 1, WIDE)
            if ours is not None and back is not None:
                p = check
                rt = np.hypot(*(back(ours(p)) - p).T)
                row[2] += " (round trip %.3f / %.2f" % (math.sqrt(np.mean(rt * rt)), rt.max())
                if ob is not None:
                    row[2] += "; vs ORB %s" % fmt(err_of(ours, ob, check))
                row[2] += ")"
        else:
            row = [label]
            for est in (seed, ours, sad, gd, ea, eh, ob):
                row.append(fmt(err_of(est, truth, check)))
        if seed is None:
            row[1] = "fail: " + str(doc_seed).split(": ", 2)[-1].split(" (")[0]
        else:
            row[1] += " [%d/%d]" % (doc_seed["used"], doc_seed["grid_x"] * doc_seed["grid_y"])
        if ours is None:
            row[2] = "fail: " + str(doc).split(": ", 2)[-1].split(" (")[0]
        else:
            row[2] += " [%d/%d]" % (doc["used"], doc["grid_x"] * doc["grid_y"])
        t_whole = float(np.median([x[0] for x in ours_t])) if ours_t else float("nan")
        t_map = float(np.median([x[1][0] for x in ours_t])) if ours_t else float("nan")
        t_reg = float(np.median([x[1][0] + x[1][1] for x in ours_t])) if ours_t else float("nan")
        t_pts = float(np.median([x[1][2] for x in ours_t])) if ours_t else float("nan")
        t_sad = float(np.median([x[2] for x in sad_t])) if sad_t else None
        te = float(np.median([x[0] for x in ecc_t]))
        trs = [x[1] for x in ecc_t if not math.isnan(x[1])]
        tr = float(np.median(trs)) if trs else float("nan")
        row.append("%.3f / %.3f / %.3f" % (t_whole, t_reg, t_map) if ours is not None else "-")
        row.append("%.4f / %.4f" % (t_pts, t_sad) if sad is not None and ours is not None else "-")
        row.append("%.3f / %.3f" % (te, tr))
        row.append("%.1fx / %.1fx" % (tr / t_reg, tr / t_whole)
                   if ours is not None and not math.isnan(tr) else "-")
        row.append("%.3f" % float(np.median(orb_t)))
        row.append("%.3f" % t_gd if t_gd is not None else "-")
        print("| " + " | ".join(row) + " |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
