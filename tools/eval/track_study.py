#!/usr/bin/python3
"""track_study.py - the data behind the defaults of issue 15's vector quality
(texture measure and level, uniqueness ratio and neighbourhood, sub-pixel
fit), computed from brute-force SAD surfaces in floating point, independent
of the library. A study, not a test: it prints Markdown.

  /usr/bin/python3 tools/eval/track_study.py [same data options as track_eval.py]

For every window of the seed's job (16 x 16 in 32 x 32, step 16) of every
pair: the full SAD surface (17 x 17 placements), and
  texture   of the window in SECOND, per pixel: mad (mean absolute
            deviation from the mean), sd (standard deviation), grad (the
            smaller of the mean |horizontal| and mean |vertical| neighbour
            difference: the SAD a 1-px shift costs per pixel, the smaller
            of the two directions)
  unique    best SAD outside the (2r+1)^2 neighbourhood of the winner over
            the best SAD (inf when the best is 0 and nothing else is)
  fit       sub-pixel position per axis from the SADs left/centre/right:
            parabola d = (l - r) / (2 (l - 2c + r)); equiangular (V)
            d = (l - r) / (2 (max(l, r) - c)), the exact minimum of
            S(x) = a + s |x - d| sampled at -1, 0, 1
Then tables: how each texture measure separates flat from textured windows
and predicts the error; what each uniqueness ratio keeps and the error of
what it keeps; the endpoint error of each fit.
"""
import argparse
import os
import sys

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import track_scenes  # noqa: E402

WIN, SEARCH, STEP = 16, 32, 16
H = (SEARCH - WIN) // 2  # 8


def geometry(pair):
    """Half ranges and step of the pair's job (the seed's unless its
    options say --search WxH / --step N)."""
    hx = hy = H
    step = STEP
    o = pair["options"]
    for i, opt in enumerate(o[:-1]):
        if opt == "--search":
            sw, _, sh = o[i + 1].partition("x")
            hx, hy = (int(sw) - WIN) // 2, (int(sh or sw) - WIN) // 2
        if opt == "--step":
            step = int(o[i + 1])
    return hx, hy, step


def windows_of(pair):
    """Per window: SAD surface, texture measures, truth, label."""
    hx, hy, step = geometry(pair)
    a = pair["first"].astype(np.int64)
    b = pair["second"].astype(np.int64)
    clean = pair.get("clean_second")
    h, w = b.shape
    fill = 4095 if pair["name"] == "goes16" else None
    out = []
    for y in range(0, h - WIN + 1, step):
        for x in range(0, w - WIN + 1, step):
            if x < hx or y < hy or x + WIN + hx > w or y + WIN + hy > h:
                continue
            win = b[y:y + WIN, x:x + WIN]
            area = a[y - hy:y + WIN + hy, x - hx:x + WIN + hx]
            if fill is not None and ((win == fill).any() or (area == fill).any()):
                continue
            views = sliding_window_view(area, (WIN, WIN))  # (17, 17, 16, 16)
            sad = np.abs(views - win).sum(axis=(2, 3)).astype(np.float64)
            d = win - win.mean()
            gx = np.abs(np.diff(win, axis=1)).mean()
            gy = np.abs(np.diff(win, axis=0)).mean()
            rec = dict(x=x, y=y, sad=sad, hx=hx, hy=hy, mad=np.abs(d).mean(), sd=np.sqrt((d * d).mean()),
                       grad=min(gx, gy), gsum=gx + gy,
                       seed=min((win > win.mean()).sum(), (win <= win.mean()).sum()))
            if pair["flat"] is not None:
                share = pair["flat"][y:y + WIN, x:x + WIN].mean()
                rec["label"] = "flat" if share == 1 else ("textured" if share == 0 else "mixed")
            else:
                src = clean if clean is not None else b
                cw = src[y:y + WIN, x:x + WIN]
                rec["label"] = "flat" if int(cw.max()) - int(cw.min()) <= 2 else "textured"
            rec["truth"] = None
            if pair["truth"] is not None:
                t = pair["truth"][y:y + WIN, x:x + WIN]
                valid = np.ones(t.shape[:2], bool) if pair["truth_valid"] is None else \
                    pair["truth_valid"][y:y + WIN, x:x + WIN]
                if valid.mean() >= 0.75:
                    rec["truth"] = (np.median(t[..., 0][valid]), np.median(t[..., 1][valid]))
            out.append(rec)
    return out


def winner(sad, pred=(0, 0)):
    """Smallest SAD; ties to the placement closest to the prediction
    (squared distance of the motions), then smallest y, then x."""
    m = sad.min()
    py, px = np.nonzero(sad == m)
    hy, hx = (sad.shape[0] - 1) // 2, (sad.shape[1] - 1) // 2
    dxs, dys = hx - px, hy - py
    dist = (dxs - pred[0]) ** 2 + (dys - pred[1]) ** 2
    order = np.lexsort((px, py, dist))
    return py[order[0]], px[order[0]]


def unique_ratio(sad, py, px, r):
    b = sad[py, px]
    mask = np.ones_like(sad, bool)
    mask[max(py - r, 0):py + r + 1, max(px - r, 0):px + r + 1] = False
    if not mask.any():
        return np.inf
    s2 = sad[mask].min()
    if b == 0:
        return np.inf if s2 > 0 else 1.0
    return s2 / b


def fit(l, c, r, method):
    if method == "parabola":
        den = l - 2 * c + r
        return 0.0 if den <= 0 else 0.5 * (l - r) / den
    if method == "equiangular":
        den = max(l, r) - c
        return 0.0 if den <= 0 else 0.5 * (l - r) / den
    return 0.0


def subpixel(sad, py, px, method):
    """Motion (dx, dy) with sub-pixel parts; the position d of the minimum
    in placement coordinates moves the motion by -d."""
    ny, nx = sad.shape
    dx, dy = float((nx - 1) // 2 - px), float((ny - 1) // 2 - py)
    if 0 < px < nx - 1:
        dx -= fit(sad[py, px - 1], sad[py, px], sad[py, px + 1], method)
    if 0 < py < ny - 1:
        dy -= fit(sad[py - 1, px], sad[py, px], sad[py + 1, px], method)
    return dx, dy


def analyse(recs):
    for r in recs:
        py, px = winner(r["sad"])
        r["at_limit"] = px in (0, r["sad"].shape[1] - 1) or py in (0, r["sad"].shape[0] - 1)
        for rad in (1, 2):
            r["u%d" % rad] = unique_ratio(r["sad"], py, px, rad)
        r["min_ps"] = r["sad"][py, px] / (WIN * WIN)
        if r["truth"] is not None:
            tx, ty = r["truth"]
            for m in ("whole", "parabola", "equiangular"):
                dx, dy = subpixel(r["sad"], py, px, m)
                r["e_" + m] = np.hypot(dx - tx, dy - ty)
    return recs


def pct(a):
    return "%.0f %%" % (100.0 * a) if np.isfinite(a) else "-"


def texture_table(name, recs):
    lab = np.array([r["label"] for r in recs])
    print("\n#### %s: texture measures (grey levels per pixel)\n" % name)
    print("| measure | flat windows: median / max | textured windows: 5th pct / median |"
          " level keeping 95 %% of textured | flat flagged at that level |")
    print("|---|---:|---:|---:|---:|")
    for m in ("mad", "sd", "grad", "gsum"):
        v = np.array([r[m] for r in recs])
        f, t = v[lab == "flat"], v[lab == "textured"]
        lvl = np.percentile(t, 5) if len(t) else np.nan
        print("| %s | %s | %s | %.2f | %s |" % (
            m, "%.2f / %.2f" % (np.median(f), f.max()) if len(f) else "-",
            "%.2f / %.2f" % (np.percentile(t, 5), np.median(t)) if len(t) else "-", lvl,
            pct((f < lvl).mean()) if len(f) else "-"))


def error_by_texture(name, recs, measure, levels):
    """Error of the whole-pixel winner by texture level: where matching
    stops working."""
    rows = [r for r in recs if r["truth"] is not None]
    if not rows:
        return
    v = np.array([r[measure] for r in rows])
    e = np.array([r["e_equiangular"] for r in rows])
    print("\n#### %s: sub-pixel (V) error by texture `%s`\n" % (name, measure))
    print("| %s in | windows | mean EPE | share within 1 px |" % measure)
    print("|---|---:|---:|---:|")
    edges = [0] + list(levels) + [np.inf]
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (v >= lo) & (v < hi)
        if sel.any():
            print("| %g .. %g | %d | %.2f | %s |" % (lo, hi, sel.sum(), e[sel].mean(),
                                                    pct((e[sel] <= 1).mean())))


def uniqueness_table(name, recs, tex_measure, tex_level):
    rows = [r for r in recs if r["truth"] is not None and r[tex_measure] >= tex_level]
    if not rows:
        return
    lab = np.array([r["label"] for r in rows])
    lim = np.array([r["at_limit"] for r in rows])
    e = np.array([r["e_equiangular"] for r in rows])
    print("\n#### %s: uniqueness (after %s >= %g, at-limit removed)\n" %
          (name, tex_measure, tex_level))
    print("| neighbourhood | ratio | windows kept | textured kept | flat kept | mean EPE kept |"
          " within 1 px | mean EPE rejected |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    tex = lab == "textured"
    for rad in (1, 2):
        u = np.array([r["u%d" % rad] for r in rows])
        for ratio in (1.0, 1.05, 1.1, 1.2, 1.3, 1.5):
            keep = (u > ratio) & ~lim
            rej = ~keep & ~lim
            print("| %dx%d | %.2f | %s | %s | %d | %.3f | %s | %s |" % (
                2 * rad + 1, 2 * rad + 1, ratio, pct(keep.mean()),
                pct(keep[tex].mean()) if tex.any() else "-", (keep & (lab == "flat")).sum(),
                e[keep].mean() if keep.any() else np.nan, pct((e[keep] <= 1).mean()) if keep.any()
                else "-", "%.2f" % e[rej].mean() if rej.any() else "-"))


def consistency_table(name, recs, tex_measure, tex_level):
    """Pairs without truth: share of windows kept and how many kept vectors
    lie within 1 px of the median of their kept 8-neighbours."""
    if not recs or recs[0]["truth"] is not None:
        return
    for r in recs:
        py, px = winner(r["sad"])
        r["v"] = subpixel(r["sad"], py, px, "equiangular")
    at = {(r["x"], r["y"]): r for r in recs}
    print("\n#### %s: no truth; kept windows and their agreement with kept neighbours\n" % name)
    print("| texture | neighbourhood | ratio | windows kept | kept within 1 px of neighbours' median |")
    print("|---|---|---:|---:|---:|")
    for lvl in (0.0, tex_level):
        for rad in (1, 2):
            for ratio in (1.0, 1.05, 1.1, 1.2):
                keep = {k for k, r in at.items() if r[tex_measure] >= lvl and
                        r["u%d" % rad] > ratio and not r["at_limit"]}
                good = total = 0
                for (x, y) in keep:
                    st = STEP
                    nb = [at[(x + i * st, y + j * st)]["v"] for i in (-1, 0, 1) for j in (-1, 0, 1)
                          if (i or j) and (x + i * st, y + j * st) in keep]
                    if len(nb) < 3:
                        continue
                    mx = np.median([v[0] for v in nb])
                    my = np.median([v[1] for v in nb])
                    v = at[(x, y)]["v"]
                    total += 1
                    good += np.hypot(v[0] - mx, v[1] - my) <= 1.0
                print("| %s >= %g | %dx%d | %.2f | %s | %s |" % (
                    tex_measure, lvl, 2 * rad + 1, 2 * rad + 1, ratio, pct(len(keep) / len(recs)),
                    pct(good / total) if total else "-"))


def fit_table(name, recs):
    rows = [r for r in recs if r["truth"] is not None and not r["at_limit"] and
            r["label"] == "textured" and r["u1"] > 1.1]
    if not rows:
        return
    print("\n#### %s: sub-pixel fits (textured, unique, not at the limit: %d windows)\n" %
          (name, len(rows)))
    print("| fit | mean EPE | median | within 0.5 px | within 1 px |")
    print("|---|---:|---:|---:|---:|")
    for m in ("whole", "parabola", "equiangular"):
        e = np.array([r["e_" + m] for r in rows])
        print("| %s | %.3f | %.3f | %s | %s |" % (m, e.mean(), np.median(e),
                                                 pct((e <= 0.5).mean()), pct((e <= 1).mean())))


def summary(results, level):
    """Compact tables across pairs (results: [(name, recs)])."""
    print("\n### Texture level (mean absolute deviation, sample units): %g\n" % level)
    print("| pair | flat windows (scene) | their largest | flagged | textured windows | "
          "flagged (lost) | error of the flagged textured |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, recs in results:
        lab = np.array([r["label"] for r in recs])
        mad = np.array([r["mad"] for r in recs])
        e = np.array([r.get("e_equiangular", np.nan) for r in recs])
        f, t = lab == "flat", lab == "textured"
        lost = t & (mad < level)
        print("| %s | %d | %s | %s | %d | %s | %s |" % (
            name, f.sum(), "%.2f" % mad[f].max() if f.any() else "-",
            pct((mad[f] < level).mean()) if f.any() else "-", t.sum(), pct(lost.mean() /
            max(t.mean(), 1e-9)) if t.any() else "-",
            "%.2f px" % np.nanmean(e[lost]) if lost.any() and np.isfinite(e[lost]).any() else "-"))
    choices = [(1, 1.10), (2, 1.05), (2, 1.10), (2, 1.20), (2, 1.50)]
    print("\n### Uniqueness after the texture level, at-limit windows removed: textured "
          "windows kept / flat windows kept / mean sub-pixel error of the kept\n")
    print("| pair | " + " | ".join("%dx%d, %.2f" % (2 * r + 1, 2 * r + 1, q) for r, q in choices) +
          " |")
    print("|---|" + "---:|" * len(choices))
    for name, recs in results:
        rows = [r for r in recs if r["mad"] >= level and not r["at_limit"]]
        if not rows:
            continue
        lab = np.array([r["label"] for r in rows])
        e = np.array([r.get("e_equiangular", np.nan) for r in rows])
        cells = []
        for rad, q in choices:
            keep = np.array([r["u%d" % rad] > q for r in rows])
            tex = lab == "textured"
            cells.append("%s / %d / %s" % (pct(keep[tex].mean()) if tex.any() else "-",
                                          (keep & (lab == "flat")).sum(),
                                          "%.2f" % np.nanmean(e[keep]) if keep.any() and
                                          np.isfinite(e[keep]).any() else "-"))
        print("| %s | %s |" % (name, " | ".join(cells)))
    print("\n### Sub-pixel fit: mean endpoint error (px) of textured, unique (5x5, 1.10), "
          "not-at-limit windows\n")
    print("| pair | windows | whole pixels | parabola | equiangular (V) |")
    print("|---|---:|---:|---:|---:|")
    for name, recs in results:
        rows = [r for r in recs if "e_whole" in r and r["label"] == "textured" and
                not r["at_limit"] and r["u2"] > 1.10 and r["mad"] >= level]
        if rows:
            print("| %s | %d | %.3f | %.3f | %.3f |" % (
                name, len(rows), np.mean([r["e_whole"] for r in rows]),
                np.mean([r["e_parabola"] for r in rows]),
                np.mean([r["e_equiangular"] for r in rows])))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-synthetic", action="store_true")
    ap.add_argument("--only")
    ap.add_argument("--piv", nargs=3)
    ap.add_argument("--goes", nargs=2)
    ap.add_argument("--photo", action="append", default=[])
    ap.add_argument("--nodata-photo", action="append", default=[])
    ap.add_argument("--stereo")
    ap.add_argument("--measure", default="mad")
    ap.add_argument("--level", type=float, default=1.25)
    ap.add_argument("--summary", action="store_true", help="only the compact tables across pairs")
    args = ap.parse_args()
    pairs = [] if args.no_synthetic else track_scenes.synthetic_scenes(args.quick)
    for spec in args.photo:
        n, _, p = spec.partition("=")
        pairs.append(track_scenes.warp_photo(p, n))
    for spec in args.nodata_photo:
        n, _, rest = spec.partition("=")
        p, _, v = rest.rpartition(":")
        pairs.append(track_scenes.warp_photo(p, n, nodata=int(v)))
    if args.piv:
        pairs.append(track_scenes.piv_pair(*args.piv))
    if args.stereo:
        pairs.append(track_scenes.stereo_pair(args.stereo))
    if args.goes:
        pairs.append(track_scenes.goes_pair(*args.goes))
    if args.only:
        pairs = [p for p in pairs if p["name"] in args.only.split(",")]
    print("## Vector quality study (issue 15)\n")
    if args.summary:
        summary([(p["name"], analyse(windows_of(p))) for p in pairs], args.level)
        return
    for p in pairs:
        print("\n### %s\n\n%s." % (p["name"], p["note"]))
        recs = analyse(windows_of(p))
        texture_table(p["name"], recs)
        scale = 1.0
        error_by_texture(p["name"], recs, args.measure,
                         [x * scale for x in (0.25, 0.5, 1, 2, 4, 8)])
        uniqueness_table(p["name"], recs, args.measure, args.level * scale)
        fit_table(p["name"], recs)
        consistency_table(p["name"], recs, args.measure, args.level * scale)


if __name__ == "__main__":
    main()
