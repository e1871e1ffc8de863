"""track_scenes.py - image pairs with known motion for the tracking evaluation
(tools/eval-track.sh): synthetic scenes made here, and loaders for real data
given on the command line. numpy and OpenCV (Debian's python3-numpy,
python3-opencv); run with /usr/bin/python3.

Every pair is a dict:
  name, note      labels for the tables
  first, second   2-D uint8 or uint16 arrays (FIRST earlier, SECOND later)
  truth           (H, W, 2) float array: motion (dx, dy) FIRST -> SECOND of the
                  content at each pixel of SECOND (x right, y down), the
                  convention of `ssda track`; None when unknown
  truth_valid     (H, W) bool array: where truth holds (None: everywhere)
  flat            (H, W) bool array: pixels without texture by construction
                  (no echo, clear sky, nodata), or None
  clean_second    SECOND before noise (photographs), for window labels
  reference_only  True when truth is another method's field, not ground truth
  options         extra `ssda track` options the pair needs (--mask-value, ...)

Warps are backward: SECOND(x) = FIRST(x - u(x)), so u(x) is the motion of the
content found at x in SECOND, what a window of SECOND should report. The
procedural textures are evaluated at the warped coordinates (no resampling
error); photographs are resampled by OpenCV's bicubic remap.
"""
import math

import cv2
import numpy as np

SIZE = 512


# ---- flows -------------------------------------------------------------

def smooth_flow(h, w, scale=1.0):
    """A smooth field with sub-pixel values everywhere: |u| <= 4.6, |v| <= 4.0
    px for scale 1 (inside the +-8 px of 16-px windows in 32-px areas)."""
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    u = 2.6 + 2.0 * np.sin(2 * math.pi * y / h + 0.3) + 0.35 * np.sin(2 * math.pi * x / (0.7 * w))
    v = -1.7 + 2.3 * np.cos(2 * math.pi * x / w + 0.5)
    return np.dstack([u * scale, v * scale])


# ---- procedural textures -------------------------------------------------

def value_noise(xs, ys, seed, scales=(128, 64, 32, 16, 8, 4, 2), gain=0.6, extent=768):
    """Cloud-like value noise at float coordinates (xs, ys): sums of
    bilinearly interpolated random grids of the given cell sizes, the
    generator of tools/common/synth_texture.c, continuous so that a warp is
    exact. The grids cover -64 .. extent - 64 in x and y (the same grids for
    every set of coordinates: a frame and its warp see one texture)."""
    rng = np.random.RandomState(seed)
    out = np.zeros_like(xs, dtype=np.float64)
    amp = 1.0
    margin = 64.0
    for c in scales:
        gw = gh = int(extent / c) + 3
        grid = rng.rand(gh, gw)
        fx = (xs + margin) / c
        fy = (ys + margin) / c
        x0 = np.floor(fx).astype(np.int64)
        y0 = np.floor(fy).astype(np.int64)
        tx = fx - x0
        ty = fy - y0
        g00 = grid[y0, x0]
        g01 = grid[y0, x0 + 1]
        g10 = grid[y0 + 1, x0]
        g11 = grid[y0 + 1, x0 + 1]
        out += amp * (g00 * (1 - tx) * (1 - ty) + g01 * tx * (1 - ty) + g10 * (1 - tx) * ty +
                      g11 * tx * ty)
        amp *= gain
    return out


def _coords(h, w, flow=None):
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    if flow is None:
        return x, y
    return x - flow[..., 0], y - flow[..., 1]


def _noisy(img, sigma, rng, where=None, maxval=255):
    """Gaussian noise of sigma grey levels, rounded and clipped; only where
    `where` is True when given (a radar's no-echo and a sensor's nodata stay
    exact)."""
    out = img.astype(np.float64)
    if sigma > 0:
        n = rng.normal(0.0, sigma, img.shape)
        out = out + (n if where is None else n * where)
    return np.clip(np.rint(out), 0, maxval)


def _stretch(a, lo, hi, ref):
    """Map a to lo..hi by the range of ref (the same map for both frames)."""
    return lo + (hi - lo) * (a - ref.min()) / (ref.max() - ref.min())


def scene_texture(sigma=1.0, seed=11, flow_scale=1.0, gain=1.0, offset=0.0, name=None,
                  note=None):
    """Value-noise texture everywhere, moved by the smooth flow."""
    h = w = SIZE
    flow = smooth_flow(h, w, flow_scale)
    rng = np.random.RandomState(seed + 1)
    x, y = _coords(h, w)
    a = value_noise(x, y, seed)
    xs, ys = _coords(h, w, flow)
    b = value_noise(xs, ys, seed)
    first = _noisy(_stretch(a, 0, 255, a), sigma, rng)
    second = _noisy(gain * _stretch(b, 0, 255, a) + offset, sigma, rng)
    return dict(name=name or "texture", note=note or
                "value noise, smooth flow up to 4.6 px, noise sigma %g" % sigma,
                first=first.astype(np.uint8), second=second.astype(np.uint8), truth=flow,
                truth_valid=None, flat=np.zeros((h, w), bool), reference_only=False, options=[])


def scene_radar(seed=21, sigma=2.0):
    """Weather-radar-like: echoes (textured) over no-echo 0 (exactly flat,
    no noise: every placement ties there), about half the image."""
    h = w = SIZE
    flow = smooth_flow(h, w)
    rng = np.random.RandomState(seed + 1)

    def frame(xs, ys):
        cover = value_noise(xs, ys, seed, scales=(128, 64, 32, 16))
        body = value_noise(xs, ys, seed + 7, scales=(32, 16, 8, 4, 2))
        echo = cover > 1.02
        inten = np.clip(30 + 300 * (cover - 1.02) + 120 * (body - 0.9), 8, 255)
        return np.where(echo, inten, 0.0), echo

    a, ea = frame(*_coords(h, w))
    b, eb = frame(*_coords(h, w, flow))
    first = _noisy(a, sigma, rng, ea)
    second = _noisy(b, sigma, rng, eb)
    return dict(name="radar", note="echoes over exact no-echo 0 (%.0f %% of pixels), smooth flow"
                % (100.0 * (1 - eb.mean())),
                first=first.astype(np.uint8), second=second.astype(np.uint8), truth=flow,
                truth_valid=None, flat=~eb, reference_only=False, options=[])


def scene_sky(seed=31, sigma=1.0):
    """Clear sky (a smooth gradient plus sensor noise) with textured clouds."""
    h = w = SIZE
    flow = smooth_flow(h, w)
    rng = np.random.RandomState(seed + 1)

    def frame(xs, ys):
        cover = value_noise(xs, ys, seed, scales=(128, 64, 32))
        body = value_noise(xs, ys, seed + 5, scales=(16, 8, 4, 2))
        cloud = np.clip((cover - 0.92) * 4.0, 0.0, 1.0)
        sky = 90.0 + 40.0 * ys / h
        val = sky * (1 - cloud) + cloud * (150 + 60 * body)
        return val, cloud > 0

    a, ca = frame(*_coords(h, w))
    b, cb = frame(*_coords(h, w, flow))
    first = _noisy(a, sigma, rng)
    second = _noisy(b, sigma, rng)
    return dict(name="sky", note="clouds over clear sky (gradient + noise sigma %g, %.0f %% of "
                "pixels), smooth flow" % (sigma, 100.0 * (1 - cb.mean())),
                first=first.astype(np.uint8), second=second.astype(np.uint8), truth=flow,
                truth_valid=None, flat=~cb, reference_only=False, options=[])


def scene_counts16(seed=41, sigma=2.0):
    """GOES-like 16-bit: a smooth field of 12-bit counts (coarse scales only)
    moved by the smooth flow, noise sigma counts."""
    h = w = SIZE
    flow = smooth_flow(h, w)
    rng = np.random.RandomState(seed + 1)
    sc = (256, 128, 64, 32, 16, 8)
    a = value_noise(*_coords(h, w), seed, scales=sc)
    b = value_noise(*_coords(h, w, flow), seed, scales=sc)
    first = _noisy(_stretch(a, 400, 3600, a), sigma, rng, maxval=65535)
    second = _noisy(_stretch(b, 400, 3600, a), sigma, rng, maxval=65535)
    return dict(name="counts16", note="16-bit smooth 12-bit counts, smooth flow, noise sigma %g"
                % sigma, first=first.astype(np.uint16), second=second.astype(np.uint16),
                truth=flow, truth_valid=None, flat=np.zeros((h, w), bool),
                reference_only=False, options=[])


def synthetic_scenes(quick=False):
    s = [scene_texture(),
         scene_texture(sigma=4.0, seed=12, name="texture-noisy"),
         scene_radar(),
         scene_sky(),
         scene_texture(seed=13, gain=1.08, offset=6.0, name="brightness",
                       note="value noise, SECOND x1.08 + 6 grey levels, noise sigma 1"),
         scene_texture(seed=14, flow_scale=2.4, name="large-motion",
                       note="value noise, smooth flow up to 11 px (beyond the +-8 range)"),
         scene_counts16()]
    return s[:3] if quick else s


# ---- photographs and real pairs --------------------------------------------

def read_gray(path):
    img = cv2.imread(path, cv2.IMREAD_UNCHANGED)
    if img is None:
        raise SystemExit("cannot read %s" % path)
    if img.ndim == 3:
        img = cv2.cvtColor(img[..., :3], cv2.COLOR_BGR2GRAY)
    return img


def warp_photo(path, name, sigma=1.0, seed=51, nodata=None):
    """A photograph moved by the smooth flow (bicubic remap), noise sigma;
    pixels equal to nodata (e.g. 0 outside a satellite scene's footprint)
    stay exact and are the flat region."""
    img = read_gray(path).astype(np.float64)
    h, w = img.shape
    flow = smooth_flow(h, w)
    xs, ys = _coords(h, w, flow)
    second = cv2.remap(img.astype(np.float32), xs.astype(np.float32), ys.astype(np.float32),
                       cv2.INTER_CUBIC, borderMode=cv2.BORDER_REFLECT)
    rng = np.random.RandomState(seed)
    clean = np.clip(np.rint(second), 0, 255).astype(np.uint8)
    flat = None
    if nodata is not None:
        # nodata where the nearest source pixel is nodata
        near = cv2.remap((img == nodata).astype(np.uint8), xs.astype(np.float32),
                         ys.astype(np.float32), cv2.INTER_NEAREST, borderMode=cv2.BORDER_REFLECT)
        flat = near.astype(bool)
        second = np.where(flat, nodata, second)
        first = _noisy(img, sigma, rng, img != nodata)
        second = _noisy(second, sigma, rng, ~flat)
    else:
        first = _noisy(img, sigma, rng)
        second = _noisy(second, sigma, rng)
    note = "photograph, smooth flow up to 4.6 px (bicubic), noise sigma %g" % sigma
    if nodata is not None:
        note += ", nodata %d exact (%.0f %% of pixels)" % (nodata, 100.0 * flat.mean())
    return dict(name=name, note=note, first=first.astype(np.uint8),
                second=second.astype(np.uint8), clean_second=clean, truth=flow,
                truth_valid=None, flat=flat, reference_only=False, options=[])


def piv_pair(first_path, second_path, field_path):
    """PIV Challenge case B (B001): truth is OpenPIV's field (a reference, with
    a few spurious vectors near the vortex core): x, y, u, v, mask with the
    origin at the bottom-left and v up; bilinear between its grid points,
    invalid outside the grid and next to a masked vector."""
    a = read_gray(first_path)
    b = read_gray(second_path)
    h, w = b.shape
    rows = np.loadtxt(field_path, comments="#")
    xs = np.unique(rows[:, 0])
    ys = np.unique(rows[:, 1])
    u = np.zeros((len(ys), len(xs)))
    v = np.zeros_like(u)
    m = np.zeros_like(u)
    for x, y, uu, vv, mm in rows:
        i = np.searchsorted(ys, y)
        j = np.searchsorted(xs, x)
        u[i, j], v[i, j], m[i, j] = uu, vv, mm
    # image rows: y_img = h - y_piv, so v (up) is -dy
    gy, gx = np.mgrid[0:h, 0:w].astype(np.float64)
    py = h - gy
    fi = np.interp(py, ys, np.arange(len(ys)))
    fj = np.interp(gx, xs, np.arange(len(xs)))
    i0 = np.clip(np.floor(fi).astype(int), 0, len(ys) - 2)
    j0 = np.clip(np.floor(fj).astype(int), 0, len(xs) - 2)
    ti, tj = fi - i0, fj - j0

    def bil(f):
        return (f[i0, j0] * (1 - ti) * (1 - tj) + f[i0, j0 + 1] * (1 - ti) * tj +
                f[i0 + 1, j0] * ti * (1 - tj) + f[i0 + 1, j0 + 1] * ti * tj)

    truth = np.dstack([bil(u), -bil(v)])
    valid = ((gx >= xs[0]) & (gx <= xs[-1]) & (py >= ys[0]) & (py <= ys[-1]) &
             (bil(m) == 0))
    return dict(name="piv-B001", note="PIV Challenge 2001 case B, 8-bit; truth = OpenPIV's "
                "reference field (not ground truth)", first=a, second=b, truth=truth,
                truth_valid=valid, flat=None, reference_only=True, options=[])


def goes_pair(first_path, second_path):
    a = read_gray(first_path)
    b = read_gray(second_path)
    return dict(name="goes16", note="GOES-16 band 10, 16-bit, no truth; fill 4095 masked",
                first=a, second=b, truth=None, truth_valid=None, flat=None,
                reference_only=False, options=["--mask-value", "4095"])


def stereo_pair(data_dir, scale=0.5):
    """Middlebury 2014 'motorcycle' (as scikit-image ships it): a rectified
    stereo pair with ground-truth disparity of the left view. FIRST = right
    view, SECOND = left view: the content of the left view at x sits at
    x - d in the right one, so the motion is (+d, 0). Scaled by `scale`
    (disparities x scale); unknown disparities (inf) are invalid."""
    left = read_gray(data_dir + "/motorcycle_left.png")
    right = read_gray(data_dir + "/motorcycle_right.png")
    disp = np.load(data_dir + "/motorcycle_disp.npz")["arr_0"].astype(np.float64)
    valid = np.isfinite(disp)
    disp = np.where(valid, disp, 0.0)
    h, w = left.shape
    nh, nw = int(round(h * scale)), int(round(w * scale))
    left = cv2.resize(left, (nw, nh), interpolation=cv2.INTER_AREA)
    right = cv2.resize(right, (nw, nh), interpolation=cv2.INTER_AREA)
    disp = cv2.resize(disp, (nw, nh), interpolation=cv2.INTER_NEAREST) * scale
    valid = cv2.resize(valid.astype(np.uint8), (nw, nh), interpolation=cv2.INTER_NEAREST) > 0
    truth = np.dstack([disp, np.zeros_like(disp)])
    return dict(name="stereo-motorcycle", note="Middlebury 2014 motorcycle (scikit-image), x%g, "
                "horizontal motion %.0f..%.0f px, ground truth" %
                (scale, disp[valid].min(), disp[valid].max()),
                first=right, second=left, truth=truth, truth_valid=valid, flat=None,
                reference_only=False,
                options=["--search", "%dx%d" % (16 + 2 * int(math.ceil(disp.max() + 1)), 24),
                         "--step", "8"])
