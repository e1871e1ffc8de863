"""ssda.composite, ssda.relax, ssda.relax_median (seed 003): every field
against the C library (cref) and the ssda flow command on the same inputs,
a known motion recovered, an outlier cleaned, bad inputs raise."""
import json

import numpy as np
import pytest

import ssda
from conftest import texture, write_png

Q8 = 256


def moved(h, w, dx, dy, seed, dtype=np.uint8):
    """A texture and the same moved by (dx, dy) px (borders wrap)."""
    a = texture(h + 8, w + 8, seed, dtype)
    return a[4:4 + h, 4:4 + w], a[4 - dy:4 - dy + h, 4 - dx:4 - dx + w]


def test_known_motion_every_template():
    ref, nxt = moved(64, 72, 3, -2, seed=5)
    r = ssda.composite(ref, nxt, tp=12, step=6, min_radius=2)
    t = r.templates
    assert t.shape == (r.rows, r.cols) and r.count == r.rows * r.cols
    ok = t["status"] == ssda.COMPOSITE_OK
    assert r.ok == ok.sum() > 0.8 * r.count
    assert (t["dx"][ok] == 3 * Q8).all() and (t["dy"][ok] == -2 * Q8).all()
    assert r.templates.flat[r.origin]["origin"] == 1
    assert r.mean_rho == r.mean_rho_q30 / 2**30 and r.mean_rho > 0.99
    # the templates' places: every step px from the region's corner
    assert (t["x"][0] == np.arange(r.cols) * 6).all() and (t["y"][:, 0] == np.arange(r.rows) * 6).all()


@pytest.mark.parametrize("dtype,opts,cargs", [
    (np.uint8, {}, []),
    (np.uint8, {"tp": 10, "step": 4, "subpixel": True}, ["tp=10", "step=4", "flags=1"]),
    (np.uint16, {"tp": 14, "step": 7, "metric": "abs", "radius_q8": 32, "min_radius": 4,
                 "roi_x": 3, "roi_y": 5, "roi_w": 50, "roi_h": 40, "min_std_q8": 900},
     ["tp=14", "step=7", "metric=1", "radius_q8=32", "min_radius=4", "roi_x=3", "roi_y=5",
      "roi_w=50", "roi_h=40", "min_std_q8=900"]),
])
def test_composite_equals_the_c_library(cref, dtype, opts, cargs):
    ref, nxt = moved(60, 66, -2, 3, seed=9, dtype=dtype)
    nxt = nxt.copy()
    nxt[20:30, 20:34] = nxt[20:30, 20:34][::-1]  # local disorder: varied rho and vectors
    bpp = np.dtype(dtype).itemsize
    a, b = cref.raw("r.raw", ref), cref.raw("n.raw", nxt)
    lines = cref("composite", a, 66, 60, b, 66, 60, bpp, *cargs)
    r = ssda.composite(ref, nxt, **opts)
    assert lines[0] == [r.cols, r.rows, r.count, r.ok, r.origin, r.mean_rho_q30, r.pixel_ops]
    t = r.templates.reshape(-1)
    got = [[int(v) for v in rec] for rec in t[["var", "dx", "dy", "rho_q30", "x", "y",
                                              "status", "origin"]].tolist()]
    assert got == lines[1:]


def field_with_outlier(rows=7, cols=9, seed=3):
    rng = np.random.default_rng(seed)
    dx = np.full((rows, cols), 5, np.int32) + rng.integers(-1, 2, (rows, cols)).astype(np.int32)
    dy = np.full((rows, cols), -3, np.int32)
    dx[3, 4], dy[3, 4] = -20, 17  # one wild vector
    st = np.zeros((rows, cols), np.uint8)
    st[0, 0] = 1  # one invalid node
    return dx, dy, st


@pytest.mark.parametrize("opts,cargs", [
    ({}, []),
    ({"iterations": 7, "keep": True}, ["iterations=7", "flags=1"]),
    ({"iterations": 20, "len_step_q8": 300}, ["iterations=20", "len_step_q8=300"]),
])
def test_relax_equals_the_c_library(cref, opts, cargs):
    dx, dy, st = field_with_outlier()
    lines = cref("relax", cref.raw("dx.raw", dx), cref.raw("dy.raw", dy), cref.raw("st.raw", st),
                 9, 7, 0, *cargs)
    out = ssda.relax(dx, dy, st, **opts)
    assert out.shape == (7, 9) and out.dtype == ssda.RELAX_DTYPE
    assert [[int(v) for v in rec] for rec in out.reshape(-1).tolist()] == lines


@pytest.mark.parametrize("opts,cargs", [
    ({}, []),
    ({"threshold_q8": 300, "eps_q8": 1}, ["threshold_q8=300", "eps_q8=1"]),
])
def test_median_equals_the_c_library(cref, opts, cargs):
    dx, dy, st = field_with_outlier(seed=4)
    lines = cref("median", cref.raw("dx.raw", dx), cref.raw("dy.raw", dy), "-", 9, 7, 0, *cargs)
    out = ssda.relax_median(dx, dy, **opts)
    assert [[int(v) for v in rec] for rec in out.reshape(-1).tolist()] == lines


def test_outlier_cleaned_others_kept():
    dx, dy, st = field_with_outlier()
    for out in (ssda.relax(dx, dy, st, keep=True), ssda.relax_median(dx, dy, st)):
        assert out["flags"][0, 0] == 0 and out["dx_q8"][0, 0] == 0  # invalid: not written
        assert out["flags"][3, 4] & ssda.RELAX_CHANGED
        assert 4 * Q8 <= out["dx_q8"][3, 4] <= 6 * Q8 and out["dy_q8"][3, 4] == -3 * Q8
        assert (out["flags"][1:, 1:] & ssda.RELAX_VALID).all()


def test_strided_fields_read_in_place():
    """The composite templates' fields (views with a 32-byte stride) and a
    transposed copy give the same answer as contiguous arrays."""
    ref, nxt = moved(50, 56, 1, 2, seed=2)
    t = ssda.composite(ref, nxt, tp=10, step=5).templates
    a = ssda.relax(t["dx"], t["dy"], t["status"], frac_bits=8)
    b = ssda.relax(np.ascontiguousarray(t["dx"]), np.ascontiguousarray(t["dy"]),
                   np.ascontiguousarray(t["status"]), frac_bits=8)
    c = ssda.relax(np.asfortranarray(t["dx"]), t["dy"].copy(order="F"), t["status"], frac_bits=8)
    assert a.tobytes() == b.tobytes() == c.tobytes()


def test_flow_command_same_numbers(cli, tmp_path):
    ref, nxt = moved(64, 70, 2, 1, seed=11)
    nxt = nxt.copy()
    nxt[26:44, 26:44] = texture(18, 18, 77)  # a patch that moved nowhere: outliers
    write_png(tmp_path / "r.png", ref)
    write_png(tmp_path / "n.png", nxt)
    for extra, clean in ((["--relax", "12"], "relax"), (["--relax-median"], "median")):
        cli("flow", "r.png", "n.png", "--tp", "12", "--tp-step", "6", "--json", "f.json", *extra)
        doc = json.loads((tmp_path / "f.json").read_text())
        r = ssda.composite(ref, nxt, tp=12, step=6)
        t = r.templates.reshape(-1)
        if clean == "relax":
            c = ssda.relax(r.templates["dx"], r.templates["dy"], r.templates["status"],
                           frac_bits=8, iterations=12).reshape(-1)
        else:
            c = ssda.relax_median(r.templates["dx"], r.templates["dy"], r.templates["status"],
                                  frac_bits=8).reshape(-1)
        assert (doc["cols"], doc["rows"], doc["ok"], doc["origin"]) == (r.cols, r.rows, r.ok,
                                                                        r.origin)
        assert doc["pixel_ops"] == r.pixel_ops
        items = doc["templates"]
        assert len(items) == r.count
        changed = 0
        for k, it in enumerate(items):
            assert (it["x"], it["y"]) == (t["x"][k], t["y"][k])
            if t["status"][k] == ssda.COMPOSITE_OK:
                # 4 decimals hold a Q8 value to within 1/512: the integer back exactly
                assert round(it["dx"] * Q8) == t["dx"][k] and round(it["dy"] * Q8) == t["dy"][k]
                assert abs(it["rho"] - t["rho_q30"][k] / 2**30) <= 5e-7
                assert round(it["relax_dx"] * Q8) == c["dx_q8"][k]
                assert round(it["relax_dy"] * Q8) == c["dy_q8"][k]
                assert it["changed"] == bool(c["flags"][k] & ssda.RELAX_CHANGED)
                changed += it["changed"]
        assert doc["changed"] == changed > 0


def test_bad_inputs_raise():
    a = texture(40, 40, 1)
    dx = np.zeros((3, 4), np.int32)
    with pytest.raises(TypeError):
        ssda.composite(a, [[1, 2]])
    with pytest.raises(ssda.Error) as e:
        ssda.composite(a, a.astype(np.uint16))
    assert e.value.code == ssda.ERR_FORMAT
    with pytest.raises(ssda.Error) as e:
        ssda.composite(a, a, tp=300)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ssda.Error) as e:
        ssda.composite(a, a[:10, :10], tp=20)
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ValueError):
        ssda.composite(a, a, metric="l2")
    with pytest.raises(TypeError):
        ssda.composite(a, a, bogus=1)
    with pytest.raises(TypeError):
        ssda.relax(dx.astype(np.int64), dx)
    with pytest.raises(TypeError):
        ssda.relax(dx, dx.astype(np.float32))
    with pytest.raises(ValueError):
        ssda.relax(dx, dx[:2])
    with pytest.raises(ValueError):
        ssda.relax(dx.reshape(-1), dx.reshape(-1))
    with pytest.raises(ValueError):
        ssda.relax(dx, dx, np.zeros((3, 5), np.uint8))
    with pytest.raises(ValueError):
        ssda.relax(dx, dx, frac_bits=9)
    with pytest.raises(ValueError):
        ssda.relax(np.zeros((0, 4), np.int32), np.zeros((0, 4), np.int32))
    with pytest.raises(ssda.Error) as e:
        ssda.relax(dx, dx, iterations=1001)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ssda.Error) as e:
        ssda.relax_median(dx + (1 << 24), dx)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(TypeError):
        ssda.relax_median(dx, dx, iterations=3)
