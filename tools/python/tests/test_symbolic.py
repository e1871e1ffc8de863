"""Seed 001 from Python: shape matching (ssda.contour, fd, fd_match) and
registration by closed loops (ssda.edges, loops, symreg) against the ssda
tool's shape and symreg commands, bit for bit, and against known
transforms."""
import json
import math

import numpy as np
import pytest

import ssda
from conftest import write_png


def render(h, w, blobs, A=None, bg=30):
    """Filled ellipses (cx, cy, a, b, theta, grey) on a background; with A
    (2 x 3, a similarity) the blobs are first mapped by it."""
    y, x = np.mgrid[0:h, 0:w].astype(np.float64)
    img = np.full((h, w), float(bg))
    for cx, cy, a, b, th, g in blobs:
        if A is not None:
            s, rot = math.hypot(A[0][0], A[1][0]), math.atan2(A[1][0], A[0][0])
            cx, cy = (A[0][0] * cx + A[0][1] * cy + A[0][2], A[1][0] * cx + A[1][1] * cy + A[1][2])
            a, b, th = a * s, b * s, th + rot
        dx, dy = x - cx, y - cy
        u = (dx * math.cos(th) + dy * math.sin(th)) / a
        v = (-dx * math.sin(th) + dy * math.cos(th)) / b
        img[u * u + v * v <= 1] = g
    return np.round(img).astype(np.uint8)


def blobs(seed, n, h, w):
    r = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        cx, cy = r.uniform(25, w - 25), r.uniform(25, h - 25)
        if all(math.hypot(cx - o[0], cy - o[1]) > 26 for o in out):
            out.append((cx, cy, r.uniform(5, 11), r.uniform(3.5, 7), r.uniform(0, math.pi),
                        r.uniform(150, 240)))
    return out


def similarity(deg, s, tx, ty):
    t = math.radians(deg)
    return [[s * math.cos(t), -s * math.sin(t), tx], [s * math.sin(t), s * math.cos(t), ty]]


def largest_object(img, thr=128):
    """The ssda tool's object: pixels >= thr, largest 8-connected set."""
    from skimage.measure import label
    lab = label(img >= thr, connectivity=2)
    sizes = np.bincount(lab.ravel())
    sizes[0] = 0
    return (lab == int(np.argmax(sizes))).astype(np.uint8)


def test_shape_recovers_a_known_rotation_and_scale():
    one = [(60, 60, 30, 12, 0.3, 255), (75, 52, 8, 8, 0.0, 255)]  # not symmetric
    a = render(120, 120, one, bg=0)
    b = render(160, 160, one, similarity(30, 1.5, 10, 5), bg=0)
    fa, fb = (ssda.fd(ssda.contour(largest_object(im), samples=256).points) for im in (a, b))
    m = ssda.fd_match(fa, fb)
    assert abs(m.s - 1.5) < 0.02 and abs(m.phi_deg - 30) < 1.0 and m.e2 < 0.01
    assert m.s == m.s_q16 / 65536 and m.e2 == m.e2_q16 / 65536
    # with s and phi fixed at the free match's, the same start shift
    f = ssda.fd_match(fa, fb, m.s_q16, m.phi)
    assert (f.s_q16, f.phi) == (m.s_q16, m.phi)
    assert abs(((f.alpha - m.alpha + 2 ** 31) % 2 ** 32) - 2 ** 31) < 2 ** 32 / 512


def test_shape_equals_the_ssda_tool(cli, tmp_path):
    one = [(50, 45, 25, 10, 1.0, 200), (62, 40, 7, 6, 0.0, 200)]
    a = render(100, 110, one)
    b = render(130, 120, one, similarity(-50, 0.8, 30, 20))
    write_png(tmp_path / "a.png", a)
    write_png(tmp_path / "b.png", b)
    cli("shape", "a.png", "b.png", "--json", "out.json", "-q")
    j = json.loads((tmp_path / "out.json").read_text())
    ca, cb = (ssda.contour(largest_object(im), samples=256) for im in (a, b))
    m = ssda.fd_match(ssda.fd(ca.points, order=10), ssda.fd(cb.points, order=10))
    # s and E^2 are dyadic (q / 65536): the tool's JSON holds them exactly; cJSON
    # prints other doubles with 15 digits unless they differ by more than an
    # epsilon, so phi_deg and alpha agree to a few units in the last place (one
    # unit of the integer phi, 2^-32 turn, would differ by 1e-9 relative: caught)
    assert (m.s, m.e2) == (j["s"], j["e2"])
    assert m.phi_deg == pytest.approx(j["phi_deg"], rel=1e-15, abs=0)
    assert m.alpha_turns == pytest.approx(j["alpha_frac"], rel=1e-15, abs=0)
    assert ca.perimeter_q8 / 256.0 == j["a"]["perimeter"]
    assert int(largest_object(a).sum()) == j["a"]["area"]


def test_descriptors_of_many_contours_and_bad_inputs():
    pts = ssda.contour(largest_object(render(60, 60, [(30, 30, 15, 8, 0.4, 255)], bg=0))).points
    one = ssda.fd(pts)
    many = ssda.fd(np.stack([pts, np.roll(pts, 5, axis=0)]))
    assert one.shape == () and many.shape == (2,) and one.dtype == ssda.FD_DTYPE
    assert (many[0] == one) and int(one["order"]) == 10
    assert ssda.fd_match(many[0], many[1]).e2 < 1e-3  # a start shift only
    with pytest.raises(TypeError):
        ssda.fd(pts.astype(np.float64))
    with pytest.raises(ValueError):
        ssda.fd(pts[:, :1])
    with pytest.raises(ssda.Error) as e:
        ssda.fd(pts[:12])  # not a power of two
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ssda.Error):
        ssda.fd(pts, order=40)
    with pytest.raises(TypeError):
        ssda.fd_match(one, pts)
    with pytest.raises(ValueError):
        ssda.fd_match(many, one)
    with pytest.raises(ValueError, match="no nonzero"):
        ssda.contour(np.zeros((8, 8), np.uint8))
    with pytest.raises(ssda.Error) as e:
        ssda.contour(np.ones((8, 8), np.uint8), start=(3, 3))  # not the first pixel
    assert e.value.code == ssda.ERR_ARG


SCENE = blobs(3, 18, 200, 240)
TRUTH = similarity(12, 1.08, 10, -6)


def test_registration_recovers_a_known_map():
    ref, mov = render(200, 240, SCENE), render(200, 240, SCENE, TRUTH)
    lr, lm = ssda.loops(ref), ssda.loops(mov)
    assert len(lr.loops) >= 10 and lr.contours.shape == (len(lr.loops), 64, 2)
    assert lr.loop_stats.loops == len(lr.loops) and lr.map.shape == ref.shape
    r = ssda.symreg(lr, lm)
    assert len(r.pairs) >= 10 and r.rms < 1.0
    assert np.abs(r.affine[:, :2] - np.array(TRUTH)[:, :2]).max() < 0.01
    assert np.abs(r.affine[:, 2] - np.array(TRUTH)[:, 2]).max() < 1.0
    assert abs(r.rotation_deg - 12) < 0.5 and abs(r.scale - 1.08) < 0.01
    # loop centroids of the pairs agree with the map
    c = np.stack([lr.loops["cx_q8"][r.pairs["ref"]], lr.loops["cy_q8"][r.pairs["ref"]]]) / 256
    mapped = r.affine[:, :2] @ c + r.affine[:, 2:]
    moved = np.stack([lm.loops["cx_q8"][r.pairs["mov"]], lm.loops["cy_q8"][r.pairs["mov"]]]) / 256
    assert np.abs(mapped - moved).max() < 3


def test_registration_equals_the_ssda_tool(cli, tmp_path):
    ref, mov = render(200, 240, SCENE), render(200, 240, SCENE, TRUTH)
    write_png(tmp_path / "r.png", ref)
    write_png(tmp_path / "m.png", mov)
    cli("symreg", "r.png", "m.png", "--json", "out.json", "-q")
    j = json.loads((tmp_path / "out.json").read_text())
    lr, lm = ssda.loops(ref), ssda.loops(mov)
    r = ssda.symreg(lr, lm)
    assert (len(lr.loops), len(lm.loops)) == (j["loops_ref"], j["loops_mov"])
    assert r.affine.ravel().tolist() == j["affine"]
    assert (r.rms, r.scale, r.candidates, r.nuclei) == (
        j["rms"], j["scale"], j["candidates"], j["nuclei"])
    assert r.rotation_deg == pytest.approx(j["rotation_deg"], rel=1e-15, abs=0)  # see above
    assert len(r.pairs) == len(j["pairs"])
    for p, q in zip(r.pairs, j["pairs"]):
        assert (int(p["ref"]), int(p["mov"])) == (q["ref_index"], q["mov_index"])
        assert (p["s_q16"] / 65536.0, p["e2_q16"] / 65536.0, p["resid_q8"] / 256.0) == (
            q["s"], q["e2"], q["resid"])
        assert [lr.loops["cx_q8"][p["ref"]] / 256.0, lr.loops["cy_q8"][p["ref"]] / 256.0] == q["ref"]


def test_edges_and_bad_inputs():
    img = render(60, 70, [(35, 30, 15, 9, 0.2, 200)])
    raw = ssda.edges(img, refine=False)
    assert raw.stats is None and raw.map.dtype == np.uint16
    on = (raw.map & 0x400) != 0
    assert on.any() and not on[:2].any() and not on[:, -2:].any()  # no 5 x 5 window there
    ref = ssda.edges(img, gap_max=20, no_close=True)
    assert ref.stats.closed_t + ref.stats.closed_i + ref.stats.closed_v == 0
    with pytest.raises(ssda.Error) as e:
        ssda.edges(img.astype(np.uint16))
    assert e.value.code == ssda.ERR_FORMAT
    with pytest.raises(ssda.Error) as e:
        ssda.edges(img[:4])
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ssda.Error) as e:
        ssda.loops(img, samples=100)  # not a power of two
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ValueError):
        ssda.loops(img, grey_min=-2)
    with pytest.raises(TypeError):
        ssda.symreg(img, img)
    few = ssda.loops(img)
    r = ssda.symreg(few, few)  # one loop: no registration, not an error
    assert len(r.pairs) == 0
