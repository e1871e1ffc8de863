#!/usr/bin/env python3
"""seg_compare.py - `ssda segment` against the peers a user would pick, side
by side in one run (issue 20; tools/bench-segment.sh runs it). A benchmark:
it prints Markdown tables, it asserts nothing.

  seg_compare.py SSDA WORKDIR [--reps R] [--image PATH:NODATA:K1,K2,K3 ...]

1. Real images: for each --image (RGB: the three K-L features of `ssda
   segment`; gray: the image itself), the mixture of `ssda segment --fit em`
   and of scikit-learn's GaussianMixture on the feature's pixels, with the
   same number of components. Both models are scored on the same histogram
   (the one `ssda segment` fits): the log-likelihood of each bin's mass under
   the model (sum h(z) ln P(z - 1/2 < x < z + 1/2)), and of the density at
   bin centres (what EM on a histogram maximises). Time: ours is the fit
   alone as `ssda segment` reports it (histogram from the pixels, fit, look-up
   table); scikit-learn's is GaussianMixture.fit on the pixels; medians of
   interleaved runs, one thread (OMP/OpenBLAS/MKL limited to 1 by the script).
2. Scenes with known regions (made here, numpy, fixed seeds): the adjusted
   Rand index against the truth of our labels (EM and the seed's search,
   the most likely component; and the seed's +-2 sigma band with isolated
   points removed), scikit-learn's GaussianMixture, multi-Otsu
   (skimage.filters.threshold_multiotsu) and k-means, each on the same 1-D
   K-L feature with K = the number of regions; and GaussianMixture on the
   RGB pixels (3-D) as the reference a histogram cannot reach.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
from skimage import io
from skimage.filters import threshold_multiotsu
from sklearn.cluster import KMeans
from sklearn.metrics import adjusted_rand_score
from sklearn.mixture import GaussianMixture


def run_ssda(ssda, args):
    r = subprocess.run([ssda, "segment"] + args, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"seg_compare: ssda segment {' '.join(args)} failed:\n{r.stderr}")


def feature_paths(base, n):
    if n == 1:
        return [base]
    stem, ext = os.path.splitext(base)
    return [f"{stem}-z{k + 1}{ext}" for k in range(n)]


def erf_cdf(x):
    return 0.5 * (1.0 + np.vectorize(math.erf)(x / math.sqrt(2.0)))


def loglik_bins(hist, w, mu, sd):
    """sum h(z) ln P(bin z) and sum h(z) ln p(z) of a 1-D mixture (bins)."""
    z = np.nonzero(hist)[0].astype(float)
    h = hist[hist > 0].astype(float)
    mass = np.zeros_like(z)
    dens = np.zeros_like(z)
    for wk, mk, sk in zip(w, mu, sd):
        mass += wk * (erf_cdf((z + 0.5 - mk) / sk) - erf_cdf((z - 0.5 - mk) / sk))
        dens += wk / (sk * math.sqrt(2 * math.pi)) * np.exp(-0.5 * ((z - mk) / sk) ** 2)
    tiny = 1e-300
    return float(np.sum(h * np.log(np.maximum(mass, tiny)))), float(
        np.sum(h * np.log(np.maximum(dens, tiny))))


def real_image(ssda, work, spec, reps):
    path, nodata, comps = spec
    base = os.path.join(work, "feat.png")
    jpath = os.path.join(work, "seg.json")
    args = [path, "--fit", "em", "--components", comps, "--json", jpath, "--features", base, "-q"]
    if nodata != "":
        args += ["--nodata", nodata]
    rows = []
    ours_t, sk_t, sk_models, j = {}, {}, {}, None
    for rep in range(reps):
        # interleaved: ours, then scikit-learn on every feature
        run_ssda(ssda, args)
        with open(jpath) as f:
            j = json.load(f)
        feats = j["features"]
        paths = feature_paths(base, len(feats))
        for k, ft in enumerate(feats):
            ours_t.setdefault(k, []).append(ft["fit_seconds"])
            vals = io.imread(paths[k]).astype(np.int64).ravel()
            vals = vals[vals != 65535]
            x = (vals >> ft["bin_shift"]).astype(float).reshape(-1, 1) if ft["bin_shift"] else \
                vals.astype(float).reshape(-1, 1)
            gm = GaussianMixture(n_components=ft["count"], random_state=rep)
            t0 = time.perf_counter()
            gm.fit(x)
            sk_t.setdefault(k, []).append(time.perf_counter() - t0)
            if rep == 0:
                sk_models[k] = (gm, vals, ft)
    for k, (gm, vals, ft) in sk_models.items():
        bins = ft["bins"]
        hist = np.bincount(vals >> ft["bin_shift"], minlength=bins)[:bins]
        w = [c["weight"] for c in ft["components"]]
        s = sum(w)
        w = [x / s for x in w]
        mu = [c["mean"] for c in ft["components"]]
        sd = [c["sigma"] for c in ft["components"]]
        ours_mass, ours_dens = loglik_bins(hist, w, mu, sd)
        sk_mass, sk_dens = loglik_bins(hist, gm.weights_, gm.means_.ravel(),
                                       np.sqrt(gm.covariances_.ravel()))
        rows.append((os.path.basename(path), ft["feature"], ft["count"], int(hist.sum()),
                     ours_mass, sk_mass, ours_dens, sk_dens,
                     float(np.median(ours_t[k])), float(np.median(sk_t[k])), gm.n_iter_,
                     ft["iterations"]))
    return rows


# ---- scenes with known regions ----

def scene(kind, seed):
    rng = np.random.RandomState(seed)
    h, w = 256, 384
    y, x = np.mgrid[0:h, 0:w].astype(float)
    if kind == "aerial":  # the ssda-demo scene: 5 regions
        colours = np.array([[20, 40, 90], [40, 110, 140], [50, 110, 40], [160, 130, 90],
                            [235, 235, 235]], float)
        coast = 150 + 25 * np.sin(y / 23) + 10 * np.sin(y / 7)
        lab = np.where(x < coast - 30, 1, np.where(x < coast, 2,
                       np.where(np.sin(x / 19) * np.cos(y / 17) > 0.25, 3, 4)))
        lab[(x - 300) ** 2 + (y - 70) ** 2 < 38 ** 2] = 5
        noise = 5.0
    else:  # three regions: gray levels (brightness) or equal-brightness hues
        colours = np.array([[60, 60, 60], [130, 130, 130], [200, 200, 200]], float) \
            if kind == "brightness" else np.array([[160, 115, 100], [125, 125, 125],
                                                   [95, 120, 160]], float)  # sums 375
        lab = np.where(((x - 128) / 90) ** 2 + ((y - 128) / 70) ** 2 <= 1, 1,
                       np.where(np.abs(x - 1.2 * y - 90) < 40, 2, 3))
        noise = 4.0 if kind == "brightness" else 12.0
    shade = 1 + 0.04 * np.sin(x / 41 + y / 29)
    rgb = colours[lab - 1] * shade[..., None] + noise * rng.standard_normal((h, w, 3))
    return np.clip(np.rint(rgb), 0, 255).astype(np.uint8), lab


def scenes(ssda, work):
    out = []
    for kind, k in (("brightness", 3), ("hue", 3), ("aerial", 5)):
        rgb, truth = scene(kind, 20)
        p = os.path.join(work, f"scene-{kind}.png")
        io.imsave(p, rgb, check_contrast=False)
        base = os.path.join(work, "sf.png")
        labels = {}
        for name, extra in (("ssda EM, most likely", ["--fit", "em", "--rule", "likely",
                                                      "--no-clean"]),
                            ("ssda search, most likely", ["--fit", "search", "--rule", "likely",
                                                          "--no-clean"]),
                            ("ssda EM, +-2 sd band, cleaned (the seed)", ["--fit", "em"])):
            lp = os.path.join(work, "sl.png")
            run_ssda(ssda, [p, "--components", str(k), "-o", lp, "--features", base, "-q"]
                     + extra)
            labels[name] = [io.imread(q).ravel() for q in feature_paths(lp, 3)]
        feats = [io.imread(q).astype(float).ravel() for q in feature_paths(base, 3)]
        t = truth.ravel()
        res = {n: [adjusted_rand_score(t, l) for l in ls] for n, ls in labels.items()}
        res["scikit-learn GaussianMixture (1-D)"] = [
            adjusted_rand_score(t, GaussianMixture(k, random_state=0).fit_predict(f[:, None]))
            for f in feats]
        res["multi-Otsu"] = [
            adjusted_rand_score(t, np.digitize(f, threshold_multiotsu(
                f, classes=k, nbins=128 if k >= 5 else 256))) for f in feats]
        res["k-means (1-D)"] = [
            adjusted_rand_score(t, KMeans(k, n_init=4, random_state=0).fit_predict(f[:, None]))
            for f in feats]
        rgb3 = GaussianMixture(k, random_state=0).fit_predict(rgb.reshape(-1, 3).astype(float))
        out.append((kind, k, res, adjusted_rand_score(t, rgb3)))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ssda")
    ap.add_argument("work")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--image", action="append", default=[],
                    help="PATH:NODATA:COMPONENTS (NODATA may be empty)")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    if a.image:
        print("### Real images: our EM against scikit-learn's GaussianMixture, same K\n")
        print("| image | feature | K | pixels | ln L bin mass: ours | scikit-learn | ours - "
              "theirs | ln L density: ours | scikit-learn | time: ours (fit) | scikit-learn | "
              "less time | iterations: ours / theirs |")
        print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for spec in a.image:
            parts = spec.split(":")
            if len(parts) != 3:
                sys.exit(f"seg_compare: --image PATH:NODATA:K, got '{spec}'")
            for r in real_image(a.ssda, a.work, parts, a.reps):
                (img, feat, k, n, om, sm, od, sdn, ot, st, sit, oit) = r
                print(f"| {img} | {feat} | {k} | {n} | {om:.6g} | {sm:.6g} | "
                      f"{100.0 * (om - sm) / abs(sm):+.3f} % | {od:.6g} | {sdn:.6g} | "
                      f"{1e3 * ot:.1f} ms | {1e3 * st:.0f} ms | {st / ot:.0f}x | {oit} / {sit} |")
        print()
    print("### Scenes with known regions: adjusted Rand index against the truth (Z1 / Z2 / Z3)\n")
    print("| scene | K | method | Z1 | Z2 | Z3 |")
    print("|---|---:|---|---:|---:|---:|")
    for kind, k, res, rgb3 in scenes(a.ssda, a.work):
        for name, v in res.items():
            print(f"| {kind} | {k} | {name} | {v[0]:.3f} | {v[1]:.3f} | {v[2]:.3f} |")
        print(f"| {kind} | {k} | scikit-learn GaussianMixture on RGB (3-D, not a histogram) | "
              f"{rgb3:.3f} | | |")


if __name__ == "__main__":
    main()
