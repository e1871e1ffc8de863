#!/usr/bin/python3
"""track_metric_eval.py - `ssda track --metric sad|ncc|absncc` under
brightness changes (issue 16). A benchmark, not a test: prints Markdown.

  /usr/bin/python3 tools/eval/track_metric_eval.py --ssda build/rel/tools/cli/ssda
      [--image PNG ...] [--size 256] [--motion 2.6,-1.4]

For each image (8-bit gray; a smooth synthetic texture is always added), a
pair with a known motion: FIRST is the image's central square, SECOND the
same square moved by the motion (bilinear), times a gain plus an offset
(gains 0.7 0.85 1.0 1.2 1.4 x offsets -30 0 +30, clamped to 0..255), plus
uniform noise of +-2 grey levels on both. Each pair is tracked by the tool's
defaults (16x16 windows in 32x32 areas, step 16) with each metric; a window
counts as right when its (dx, dy) is within 1 px of the motion in both
components. Printed: the share of `ok` windows that are right, min / mean
over the 15 settings, the mean number of `ok` windows (of the 196 the grid
searches; with ncc and absncc the correlation decides ok or at_limit), and
the tool's time (the SAD tracking plus, for ncc and absncc, the correlation
search; medians over the settings).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

import cv2
import numpy as np

GAINS = (0.7, 0.85, 1.0, 1.2, 1.4)
OFFSETS = (-30.0, 0.0, 30.0)
METRICS = ("sad", "ncc", "absncc")


def texture(size, seed=5):
    rng = np.random.default_rng(seed)
    img = np.zeros((size, size))
    for scale in (64, 32, 16, 8, 4):
        small = rng.uniform(0, 1, (size // scale + 2, size // scale + 2))
        img += cv2.resize(small, (size + 2 * scale, size + 2 * scale),
                          interpolation=cv2.INTER_CUBIC)[scale:scale + size, scale:scale + size] * scale
    img -= img.min()
    return (img / img.max() * 200 + 25).astype(np.float64)


def pair(img, size, motion, gain, offset, rng):
    h, w = img.shape
    x0, y0 = (w - size) // 2, (h - size) // 2
    first = img[y0:y0 + size, x0:x0 + size]
    # SECOND(x, y) = FIRST(x - dx, y - dy): the content moves by (dx, dy)
    m = np.float32([[1, 0, motion[0]], [0, 1, motion[1]]])
    second = cv2.warpAffine(img.astype(np.float32), m, (w, h), flags=cv2.INTER_LINEAR,
                            borderMode=cv2.BORDER_REFLECT)[y0:y0 + size, x0:x0 + size]
    second = gain * second + offset

    def finish(a):
        return np.clip(np.rint(a + rng.uniform(-2, 2, a.shape)), 0, 255).astype(np.uint8)
    return finish(first), finish(second)


def track(ssda, a, b, metric):
    out = subprocess.run([ssda, "track", a, b, "--metric", metric, "--json", "-", "--quiet"],
                         check=True, capture_output=True, text=True).stdout
    doc = json.loads(out)
    return doc["windows"], doc["stats"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ssda", required=True)
    ap.add_argument("--image", action="append", default=[])
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--motion", default="2.6,-1.4")
    args = ap.parse_args()
    motion = tuple(float(v) for v in args.motion.split(","))
    images = [("synthetic texture", texture(args.size + 64))]
    for path in args.image:
        img = cv2.imread(path, cv2.IMREAD_GRAYSCALE)
        if img is None or min(img.shape) < args.size:
            sys.exit(f"track_metric_eval.py: cannot use {path}")
        images.append((os.path.basename(path), img.astype(np.float64)))
    print(f"load average {os.getloadavg()[0]:.2f} {os.getloadavg()[1]:.2f} {os.getloadavg()[2]:.2f}"
          f" (start); {args.size}x{args.size} pairs, motion {motion}, 15 gain/offset settings\n")
    print("| image | " + " | ".join(f"`--metric {m}`: within 1 px, min / mean" for m in METRICS) +
          " | " + " | ".join(f"{m}: ok windows" for m in METRICS) +
          " | " + " | ".join(f"{m}: ms" for m in METRICS) + " |")
    print("|---|" + "---:|" * (3 * len(METRICS)))
    rng = np.random.default_rng(1)
    with tempfile.TemporaryDirectory() as tmp:
        a, b = os.path.join(tmp, "a.png"), os.path.join(tmp, "b.png")
        for name, img in images:
            shares = {m: [] for m in METRICS}
            times = {m: [] for m in METRICS}
            oks = {m: [] for m in METRICS}
            for gain in GAINS:
                for offset in OFFSETS:
                    first, second = pair(img, args.size, motion, gain, offset, rng)
                    cv2.imwrite(a, first)
                    cv2.imwrite(b, second)
                    for m in METRICS:
                        wins, st = track(args.ssda, a, b, m)
                        ok = [w for w in wins if w["status"] == "ok"]
                        right = sum(abs(w["dx"] - motion[0]) <= 1 and abs(w["dy"] - motion[1]) <= 1
                                    for w in ok)
                        shares[m].append(100.0 * right / max(1, len(ok)))
                        oks[m].append(len(ok))
                        times[m].append(1e3 * (st["time_s"] + st.get("metric_time_s", 0.0)))
            print(f"| {name} | " +
                  " | ".join(f"{min(shares[m]):.1f} % / {statistics.mean(shares[m]):.1f} %"
                             for m in METRICS) + " | " +
                  " | ".join(f"{statistics.mean(oks[m]):.0f}" for m in METRICS) + " | " +
                  " | ".join(f"{statistics.median(times[m]):.2f}" for m in METRICS) + " |")
    print(f"\nload average {os.getloadavg()[0]:.2f} (end)")


if __name__ == "__main__":
    main()
