#!/usr/bin/python3
"""track_eval.py - how far `ssda track`'s vectors can be trusted, on pairs
with known motion (issue 15). A benchmark, not a test: it prints Markdown.

  /usr/bin/python3 tools/eval/track_eval.py --ssda build/eval/tools/cli/ssda
      [--config NAME=OPTIONS ...] [--quick] [--no-synthetic]
      [--piv B001_1.png B001_2.png B001_openpiv.txt] [--goes FIRST SECOND]
      [--photo NAME=PNG ...] [--nodata-photo NAME=PNG:VALUE ...]
      [--stereo SKIMAGE_DATA_DIR] [--csv FILE]

tools/eval-track.sh builds the tool and passes ../shared/data when present.

For each pair and each `ssda track` configuration (its options after the two
file names; the default configuration is a plain `ssda track A B`), per
window of the grid:
  truth      the median of the pair's motion field over the window's pixels
             in SECOND, per component (a window reports one vector for
             content that may move differently across it: SAD follows the
             majority of its pixels); windows with less than 3/4 of their
             pixels under valid truth are left out of the errors
  label      flat: every pixel of the window is flat by the scene's
             construction (no echo, clear sky, nodata) or, for pairs without
             such a mask, the window's pixels in SECOND (before noise, for
             the warped photographs) span at most 2 grey levels; textured: no flat pixel (mask) or not flat (no mask);
             mixed: the rest
  EPE        endpoint error |vector - truth| in px, of `ok` windows only,
             for the whole-pixel (dx, dy) and the sub-pixel (sub_dx, sub_dy)
             vectors (when the JSON has them)
  work       brute force over every window that is neither `edge` nor
             `masked` (each placement summed in full, as without any flat
             or texture test) divided by the pixel operations ssda reports
             (search work plus the pixels its window tests read)
Peers on the same windows: OpenCV's Farneback dense flow (its flow from
SECOND back to FIRST, negated, averaged over the window) and matchTemplate
(TM_SQDIFF and TM_CCOEFF_NORMED over the same search area, whole pixels),
on the windows the first configuration reports `ok`, and on every
textured window.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import track_scenes  # noqa: E402


# ---- running ssda ------------------------------------------------------------

def write_png(path, img):
    if not cv2.imwrite(path, img):
        raise SystemExit("cannot write %s" % path)


def run_ssda(ssda, pair, options, tmp):
    a = os.path.join(tmp, pair["name"] + "_1.png")
    b = os.path.join(tmp, pair["name"] + "_2.png")
    if not os.path.exists(a):
        write_png(a, pair["first"])
        write_png(b, pair["second"])
    out = os.path.join(tmp, "out.json")
    cmd = [ssda, "track", a, b, "--quiet", "--json", out] + pair["options"] + options
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("%s failed (%d): %s" % (" ".join(cmd), p.returncode, p.stderr))
    with open(out) as f:
        doc = json.load(f)
    doc["stderr"] = p.stderr
    return doc


# ---- per-window truth and labels ---------------------------------------------

def window_arrays(doc, pair):
    """Per window: position, status, vectors, truth, label, as numpy arrays."""
    g = doc["grid"]
    ww, wh = g["window_w"], g["window_h"]
    wins = doc["windows"]
    n = len(wins)
    x = np.array([w["x"] for w in wins])
    y = np.array([w["y"] for w in wins])
    status = np.array([w["status"] for w in wins])
    dx = np.array([w["dx"] for w in wins], float)
    dy = np.array([w["dy"] for w in wins], float)
    has_sub = n > 0 and "sub_dx" in wins[0]
    sdx = np.array([w.get("sub_dx", w["dx"]) for w in wins], float)
    sdy = np.array([w.get("sub_dy", w["dy"]) for w in wins], float)
    tx = np.full(n, np.nan)
    ty = np.full(n, np.nan)
    spread = np.full(n, np.nan)
    label = np.array(["textured"] * n, dtype=object)
    sec = pair.get("clean_second", pair["second"])
    for k in range(n):
        sl = (slice(y[k], y[k] + wh), slice(x[k], x[k] + ww))
        if pair["flat"] is not None:
            share = pair["flat"][sl].mean()
            label[k] = "flat" if share == 1.0 else ("textured" if share == 0.0 else "mixed")
        else:
            win = sec[sl]
            label[k] = "flat" if int(win.max()) - int(win.min()) <= 2 else "textured"
        if pair["truth"] is not None:
            t = pair["truth"][sl]
            valid = np.ones(t.shape[:2], bool) if pair["truth_valid"] is None \
                else pair["truth_valid"][sl]
            if valid.mean() >= 0.75:
                tx[k] = np.median(t[..., 0][valid])
                ty[k] = np.median(t[..., 1][valid])
                spread[k] = max(np.ptp(t[..., 0][valid]), np.ptp(t[..., 1][valid]))
    return dict(x=x, y=y, status=status, dx=dx, dy=dy, sdx=sdx, sdy=sdy, has_sub=has_sub,
                tx=tx, ty=ty, spread=spread, label=label, ww=ww, wh=wh, sw=g["search_w"], sh=g["search_h"])


# ---- peers -------------------------------------------------------------------

def to8(img):
    if img.dtype == np.uint8:
        return img
    v = img[img < 4095] if (img == 4095).any() else img
    lo, hi = float(v.min()), float(v.max())
    return np.clip((img.astype(np.float64) - lo) * 255.0 / max(hi - lo, 1.0), 0, 255).astype(np.uint8)


def farneback(pair, w):
    a, b = to8(pair["first"]), to8(pair["second"])
    # flow from SECOND back to FIRST: second(p) ~ first(p + f(p)); motion = -f
    f = cv2.calcOpticalFlowFarneback(b, a, None, 0.5, 3, 15, 3, 5, 1.2, 0)
    n = len(w["x"])
    dx = np.zeros(n)
    dy = np.zeros(n)
    for k in range(n):
        sl = (slice(w["y"][k], w["y"][k] + w["wh"]), slice(w["x"][k], w["x"][k] + w["ww"]))
        dx[k] = -f[sl][..., 0].mean()
        dy[k] = -f[sl][..., 1].mean()
    return dx, dy


def match_template(pair, w, method, searched):
    """matchTemplate on each searched window's area (same geometry as ssda)."""
    a, b = pair["first"], pair["second"]
    if a.dtype != np.uint8:
        a = a.astype(np.float32)
        b = b.astype(np.float32)
    hx, hy = (w["sw"] - w["ww"]) // 2, (w["sh"] - w["wh"]) // 2
    n = len(w["x"])
    dx = np.full(n, np.nan)
    dy = np.full(n, np.nan)
    for k in np.nonzero(searched)[0]:
        x, y = w["x"][k], w["y"][k]
        area = a[y - hy:y - hy + w["sh"], x - hx:x - hx + w["sw"]]
        tmpl = b[y:y + w["wh"], x:x + w["ww"]]
        r = cv2.matchTemplate(area, tmpl, method)
        lo, hi, lo_at, hi_at = cv2.minMaxLoc(r)
        px, py = lo_at if method == cv2.TM_SQDIFF else hi_at
        dx[k] = hx - px
        dy[k] = hy - py
    return dx, dy


# ---- metrics -----------------------------------------------------------------

def epe_stats(ex, ey, tx, ty, sel):
    sel = sel & np.isfinite(tx) & np.isfinite(ex)
    if not sel.any():
        return None
    e = np.hypot(ex[sel] - tx[sel], ey[sel] - ty[sel])
    return dict(n=int(sel.sum()), mean=float(e.mean()), median=float(np.median(e)),
                within1=float((e <= 1.0).mean()))


def fmt_epe(s):
    if s is None:
        return "- | - | -"
    return "%.2f | %.2f | %.0f %%" % (s["mean"], s["median"], 100 * s["within1"])


def neighbour_consistency(w, ok):
    """Share of ok vectors within 1 px of the median of their ok 8-neighbours
    (a truth-free check); windows with fewer than 3 ok neighbours skipped."""
    xs, ys = np.unique(w["x"]), np.unique(w["y"])
    cols, rows = len(xs), len(ys)
    dx = w["sdx"].reshape(rows, cols)
    dy = w["sdy"].reshape(rows, cols)
    okg = ok.reshape(rows, cols)
    good = total = 0
    for r in range(rows):
        for c in range(cols):
            if not okg[r, c]:
                continue
            nb = [(rr, cc) for rr in range(r - 1, r + 2) for cc in range(c - 1, c + 2)
                  if (rr, cc) != (r, c) and 0 <= rr < rows and 0 <= cc < cols and okg[rr, cc]]
            if len(nb) < 3:
                continue
            mx = np.median([dx[p] for p in nb])
            my = np.median([dy[p] for p in nb])
            total += 1
            good += np.hypot(dx[r, c] - mx, dy[r, c] - my) <= 1.0
    return good / total if total else float("nan")


def evaluate(doc, w):
    st = w["status"]
    searchable = (st != "edge") & (st != "masked")
    ok = st == "ok"
    textured = searchable & (w["label"] == "textured")
    flat = searchable & (w["label"] == "flat")
    stats = doc["stats"]
    per = (w["sw"] - w["ww"] + 1) * (w["sh"] - w["wh"] + 1) * w["ww"] * w["wh"]
    brute = per * int(searchable.sum())
    work = stats["pixel_ops"] + stats.get("check_pixels", 0) + stats.get("quality_ops", 0)
    statuses = {}
    for s in st[searchable]:
        statuses[s] = statuses.get(s, 0) + 1
    return dict(
        searchable=int(searchable.sum()), textured=int(textured.sum()), flat=int(flat.sum()),
        ok=int(ok.sum()),
        ok_textured=float((ok & textured).sum() / max(textured.sum(), 1)),
        flat_ok=int((ok & flat).sum()),
        whole=epe_stats(w["dx"], w["dy"], w["tx"], w["ty"], ok),
        sub=epe_stats(w["sdx"], w["sdy"], w["tx"], w["ty"], ok) if w["has_sub"] else None,
        coherent=epe_stats(w["sdx"], w["sdy"], w["tx"], w["ty"], ok & (w["spread"] <= 1.0)),
        work_saved=brute / max(work, 1), statuses=statuses,
        consistency=neighbour_consistency(w, ok),
        median=(float(np.median(w["sdx"][ok])) if ok.any() else float("nan"),
                float(np.median(w["sdy"][ok])) if ok.any() else float("nan")),
        warnings=[l for l in doc["stderr"].splitlines() if "warning" in l])


# ---- report ------------------------------------------------------------------

def report_pair(pair, configs, ssda, tmp, csv_rows):
    print("\n### %s\n\n%s.\n" % (pair["name"], pair["note"]))
    results = []
    for name, opts in configs:
        doc = run_ssda(ssda, pair, opts, tmp)
        w = window_arrays(doc, pair)
        results.append((name, doc, w, evaluate(doc, w)))
    w0 = results[0][2]
    ev0 = results[0][3]
    has_truth = pair["truth"] is not None
    print("%d windows searchable (%d textured, %d flat by the scene); statuses of the first "
          "configuration: %s.\n" % (ev0["searchable"], ev0["textured"], ev0["flat"],
                                    ", ".join("%s %d" % kv for kv in sorted(ev0["statuses"].items()))))
    hdr = "| method | ok / textured | flat reported ok | work saved vs brute force |"
    sep = "|---|---:|---:|---:|"
    if has_truth:
        hdr += " EPE mean | median | <= 1 px | sub-pixel EPE mean | median | <= 1 px |"
        sep += "---:|---:|---:|---:|---:|---:|"
    else:
        hdr += " median motion (ok) | ok within 1 px of neighbours |"
        sep += "---:|---:|"
    print(hdr)
    print(sep)
    for name, doc, w, ev in results:
        row = "| ssda %s | %.1f %% (%d of %d) | %d of %d | %.1fx |" % (
            name, 100 * ev["ok_textured"], int(round(ev["ok_textured"] * ev["textured"])),
            ev["textured"], ev["flat_ok"], ev["flat"], ev["work_saved"])
        if has_truth:
            row += " %s | %s |" % (fmt_epe(ev["whole"]), fmt_epe(ev["sub"]))
        else:
            row += " (%+.2f, %+.2f) | %.1f %% |" % (ev["median"][0], ev["median"][1],
                                                   100 * ev["consistency"])
        print(row)
        for wl in ev["warnings"]:
            print("|  | stderr: %s |||%s" % (wl.replace("|", "/"), "||||||" if has_truth else "||"))
        csv_rows.append((pair["name"], "ssda " + name, ev))
    ev0c = results[0][3]["coherent"]
    if has_truth and ev0c is not None and ev0c["n"] < results[0][3]["ok"]:
        print("\nssda %s, ok windows whose truth varies by at most 1 px across the window "
              "(%d of them; one vector can describe them): sub-pixel EPE mean %.2f, median "
              "%.2f, %.0f %% within 1 px." % (results[0][0], ev0c["n"], ev0c["mean"],
                                              ev0c["median"], 100 * ev0c["within1"]))
    if not has_truth:
        return
    searched = (w0["status"] != "edge") & (w0["status"] != "masked")
    ok_t = (w0["status"] == "ok") & np.isfinite(w0["tx"]) & np.isfinite(w0["ty"])
    if ok_t.any():
        print("\nMedian motion (what `ssda track` prints; FIRST -> SECOND, px): of the ok "
              "vectors, sub-pixel: " + "; ".join(
                  "ssda %s (%+.2f, %+.2f)" % (n, e["median"][0], e["median"][1])
                  for n, _, _, e in results) +
              "; truth over the windows `ssda %s` reports ok: (%+.2f, %+.2f)." % (
                  results[0][0], float(np.median(w0["tx"][ok_t])),
                  float(np.median(w0["ty"][ok_t]))))
    ok0 = w0["status"] == "ok"
    textured = searched & (w0["label"] == "textured")
    peers = [("OpenCV Farneback", farneback(pair, w0)),
             ("OpenCV matchTemplate TM_SQDIFF", match_template(pair, w0, cv2.TM_SQDIFF, searched)),
             ("OpenCV matchTemplate TM_CCOEFF_NORMED",
              match_template(pair, w0, cv2.TM_CCOEFF_NORMED, searched))]
    print("\nOn the same windows (EPE in px: mean | median | share within 1 px):\n")
    print("| method | windows `ssda %s` reports ok | every textured window |" % results[0][0])
    print("|---|---|---|")
    sel_name = "ssda %s" % results[0][0]
    print("| %s (whole px) | %s | %s |" % (
        sel_name, fmt_epe(ev0["whole"]), fmt_epe(epe_stats(w0["dx"], w0["dy"], w0["tx"], w0["ty"],
                                                             textured))))
    if w0["has_sub"]:
        print("| %s (sub-pixel) | %s | %s |" % (
            sel_name, fmt_epe(ev0["sub"]),
            fmt_epe(epe_stats(w0["sdx"], w0["sdy"], w0["tx"], w0["ty"], textured))))
    for name, (dx, dy) in peers:
        print("| %s | %s | %s |" % (name, fmt_epe(epe_stats(dx, dy, w0["tx"], w0["ty"], ok0)),
                                    fmt_epe(epe_stats(dx, dy, w0["tx"], w0["ty"], textured))))


def parse_config(s):
    name, _, opts = s.partition("=")
    return name, opts.split()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ssda", required=True, help="the ssda tool")
    ap.add_argument("--config", action="append", type=parse_config, default=[],
                    help="NAME=OPTIONS: an ssda track configuration (repeatable; the first is "
                    "the one peers are compared on)")
    ap.add_argument("--quick", action="store_true", help="three synthetic pairs only")
    ap.add_argument("--no-synthetic", action="store_true")
    ap.add_argument("--only", help="comma-separated pair names")
    ap.add_argument("--piv", nargs=3, metavar=("FIRST", "SECOND", "FIELD"))
    ap.add_argument("--goes", nargs=2, metavar=("FIRST", "SECOND"))
    ap.add_argument("--photo", action="append", default=[], metavar="NAME=PNG")
    ap.add_argument("--nodata-photo", action="append", default=[], metavar="NAME=PNG:VALUE")
    ap.add_argument("--stereo", metavar="DIR", help="scikit-image data directory (motorcycle)")
    args = ap.parse_args()
    configs = args.config or [("defaults", [])]

    pairs = [] if args.no_synthetic else track_scenes.synthetic_scenes(args.quick)
    for spec in args.photo:
        name, _, path = spec.partition("=")
        pairs.append(track_scenes.warp_photo(path, name))
    for spec in args.nodata_photo:
        name, _, rest = spec.partition("=")
        path, _, value = rest.rpartition(":")
        pairs.append(track_scenes.warp_photo(path, name, nodata=int(value)))
    if args.piv:
        pairs.append(track_scenes.piv_pair(*args.piv))
    if args.stereo:
        pairs.append(track_scenes.stereo_pair(args.stereo))
    if args.goes:
        pairs.append(track_scenes.goes_pair(*args.goes))
    if args.only:
        keep = args.only.split(",")
        pairs = [p for p in pairs if p["name"] in keep]

    print("## Tracking trust evaluation (issue 15)\n")
    print("ssda: `%s`; configurations: %s. Load average: %s." % (
        args.ssda, "; ".join("%s = `ssda track A B %s`" % (n, " ".join(o)) for n, o in configs),
        " ".join(open("/proc/loadavg").read().split()[:3])))
    rows = []
    with tempfile.TemporaryDirectory(prefix="ssda-eval-track-") as tmp:
        for pair in pairs:
            report_pair(pair, configs, args.ssda, tmp, rows)
            for f in os.listdir(tmp):
                os.unlink(os.path.join(tmp, f))
    print("\n### Summary\n")
    print("| pair | configuration | ok / textured | flat ok | work saved | EPE mean whole px | "
          "EPE mean sub-pixel |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for name, cfg, ev in rows:
        print("| %s | %s | %.1f %% | %d / %d | %.1fx | %s | %s |" % (
            name, cfg, 100 * ev["ok_textured"], ev["flat_ok"], ev["flat"], ev["work_saved"],
            "%.2f" % ev["whole"]["mean"] if ev["whole"] else "-",
            "%.2f" % ev["sub"]["mean"] if ev["sub"] else "-"))


if __name__ == "__main__":
    main()
