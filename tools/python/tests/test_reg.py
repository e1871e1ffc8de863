"""ssda.poly_init / poly_eval / poly_fit and ssda.shade (seed 002): every
field against the C library (cref), known maps and shading recovered, bad
inputs raise."""
import numpy as np
import pytest

import ssda


def pairs_of(n, w, h, seed, outlier=True):
    """Control points under a known quadratic map, with 0.1 px of noise and
    one misread pair 20 px off."""
    rng = np.random.default_rng(seed)
    ref = rng.uniform(0, [w - 1, h - 1], (n, 2))
    x, y = ref[:, 0], ref[:, 1]
    mov = np.stack([3 + 1.01 * x - 0.02 * y + 2e-5 * x * x,
                    -2 + 0.015 * x + 0.99 * y - 1e-5 * x * y], axis=1)
    mov += rng.normal(0, 0.1, mov.shape)
    if outlier:
        mov[5] += 20
    return np.round(np.hstack([ref, mov]) * 256).astype(np.int32)


@pytest.mark.parametrize("order,maxres", [(1, 512), (2, 0), (3, 0xFFFFFFFF), (2, 100)])
def test_poly_fit_equals_the_c_library(cref, order, maxres):
    pairs = pairs_of(40, 300, 200, seed=order)
    lines = cref("polyfit", cref.raw("p.raw", pairs), 40, 300, 200, order, maxres)
    opts = {"order": order}
    if maxres:
        opts["max_residual_q8"] = maxres
    f = ssda.poly_fit(pairs, (300, 200), **opts)
    assert lines[0] == [f.rms_q8, f.max_q8, f.cond, f.n_used, f.rejected, f.refinements,
                        int(f.within_bound), f.max_leverage_q15, int(f.weak)]
    p = f.poly[0]
    assert lines[1] == (p["u_q24"].tolist() + p["v_q24"].tolist() +
                        [p["cx"], p["cy"], p["kx"], p["ky"], p["order"]])
    assert [[int(r), int(u)] for r, u in zip(f.residual_q8, f.used)] == lines[2:42]
    assert list(ssda.poly_eval(f.poly, 100, 50)) == lines[42]


def test_poly_fit_known_map_and_outlier():
    pairs = pairs_of(60, 400, 300, seed=9)
    f = ssda.poly_fit(pairs, (400, 300))  # order 2, 2 px bound
    assert not f.used[5] and f.rejected == 1 and f.within_bound
    assert not f.weak and 0 < f.max_leverage_q15 < 26214  # 59 pairs for 6 terms
    for x, y in [(0, 0), (200, 150), (399, 299)]:
        u, v = ssda.poly_eval(f.poly, x, y)
        tx = 3 + 1.01 * x - 0.02 * y + 2e-5 * x * x
        ty = -2 + 0.015 * x + 0.99 * y - 1e-5 * x * y
        assert abs(u / 256 - tx) < 0.15 and abs(v / 256 - ty) < 0.15
    ident = ssda.poly_init((400, 300), order=3)
    assert ssda.poly_eval(ident, 123, 45) == (123 * 256, 45 * 256)
    edited = ident.copy()
    edited["u_q24"][0][0] += 5 << 24  # shift x by 5 px
    assert ssda.poly_eval(edited[0], 123, 45) == (128 * 256, 45 * 256)


def vignetted(n, h, w, seed, dtype=np.uint8):
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:h, 0:w]
    s = 40 * np.cos(2 * np.pi * (x - w / 2) / w) + 25 * np.cos(2 * np.pi * (y - h / 2) / h)
    scale = 1 if dtype == np.uint8 else 200
    imgs = (120 + s + rng.normal(0, 6, (n, h, w))) * scale
    return np.clip(np.round(imgs), 0, np.iinfo(dtype).max).astype(dtype)


@pytest.mark.parametrize("dtype,mode,centre", [
    (np.uint8, "max", None), (np.uint16, "min", None), (np.uint8, "max", (7, 3))])
def test_shade_equals_the_c_library(cref, dtype, mode, centre):
    imgs = vignetted(3, 30, 41, seed=2, dtype=dtype)
    bpp = np.dtype(dtype).itemsize
    extra = list(centre) if centre else []
    lines = cref("shade", cref.raw("i.raw", imgs), 3, 41, 30, bpp, int(mode == "min"), *extra)
    s = ssda.shade(imgs, mode=mode, centre=centre)
    assert lines[0] == s.k_q8.ravel().tolist() + [s.centre_x, s.centre_y, s.centre_q8, s.images]
    assert s.corrected.reshape(90, 41).tolist() == lines[1:]
    assert s.corrected.dtype == dtype and s.corrected.shape == imgs.shape


def test_shade_flattens_vignetting():
    imgs = vignetted(4, 48, 64, seed=3)
    s = ssda.shade(imgs)
    assert (s.centre_x, s.centre_y) == (32, 24) and s.images == 4
    before = imgs.astype(float).mean(axis=0)
    after = s.corrected.astype(float).mean(axis=0)
    assert before.std() > 30 and after.std() < 4  # what is left: the noise, 6 / sqrt(4)
    assert abs(after.mean() - (120 + 40 + 25)) < 2  # the level at the centre kept
    one = ssda.shade(imgs[0])
    assert one.images == 1 and one.corrected.shape == (48, 64)


def test_bad_inputs_raise():
    pairs = pairs_of(20, 100, 100, seed=1)
    with pytest.raises(TypeError):
        ssda.poly_fit(pairs.astype(np.float64), (100, 100))
    with pytest.raises(ValueError):
        ssda.poly_fit(pairs[:, :3].copy(), (100, 100))
    with pytest.raises(ssda.Error) as e:
        ssda.poly_fit(pairs[:4], (100, 100), order=2)  # fewer pairs than terms
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ssda.Error) as e:
        ssda.poly_fit(pairs, (100, 100), order=4)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(TypeError):
        ssda.poly_fit(pairs, (100, 100), bogus=1)
    with pytest.raises(ssda.Error) as e:
        ssda.poly_init((0, 10))
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(TypeError):
        ssda.poly_eval(np.zeros(1, np.int64), 1, 2)
    with pytest.raises(ssda.Error) as e:
        ssda.poly_eval(ssda.poly_init((10, 10)), 1000, 2)
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(TypeError):
        ssda.shade(np.zeros((10, 10), np.float32))
    with pytest.raises(ValueError):
        ssda.shade(np.zeros(10, np.uint8))
    with pytest.raises(ssda.Error) as e:
        ssda.shade(np.zeros((2, 10), np.uint8))
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ValueError):
        ssda.shade(np.zeros((10, 10), np.uint8), mode="centre")
    with pytest.raises(ssda.Error) as e:
        ssda.shade(np.zeros((10, 10), np.uint8), centre=(20, 2))
    assert e.value.code == ssda.ERR_SIZE


def test_register_command_same_numbers(cli, tmp_path):
    """ssda register's control points and fit are register_points at the
    tool's offset, then poly_fit of the OK points."""
    import json
    from conftest import texture, write_png
    ref = texture(160, 200, 6)
    y, x = np.mgrid[0:160, 0:200]
    # MOV: REF moved by (3.5, -2) px plus a slight turn (bilinear)
    sx, sy = x - 3.5 + 0.01 * (y - 80), y + 2 - 0.01 * (x - 100)
    x0, y0 = np.clip(np.floor(sx).astype(int), 0, 198), np.clip(np.floor(sy).astype(int), 0, 158)
    fx, fy = np.clip(sx - x0, 0, 1), np.clip(sy - y0, 0, 1)
    r = ref.astype(float)
    mov = ((1 - fx) * (1 - fy) * r[y0, x0] + fx * (1 - fy) * r[y0, x0 + 1] +
           (1 - fx) * fy * r[y0 + 1, x0] + fx * fy * r[y0 + 1, x0 + 1])
    mov = np.round(mov).astype(np.uint8)
    write_png(tmp_path / "r.png", ref)
    write_png(tmp_path / "m.png", mov)
    cli("register", "r.png", "m.png", "-o", "o.png", "--order", "1", "--json", "j.json", "-q")
    doc = json.loads((tmp_path / "j.json").read_text())
    pts, acc = ssda.register_points(ref, mov, offset_x=doc["offset_x"], offset_y=doc["offset_y"])
    assert acc == doc["accepted"] > 8
    ok = pts["status"].ravel() == ssda.REGISTER_OK
    flat = pts.ravel()
    for k, e in enumerate(doc["points"]):
        assert (e["ref_x"] * 256, e["ref_y"] * 256) == (flat["ref_x_q8"][k], flat["ref_y_q8"][k])
        if ok[k]:
            assert (e["mov_x"] * 256, e["mov_y"] * 256) == (flat["mov_x_q8"][k],
                                                            flat["mov_y_q8"][k])
            assert round(e["rho"] * 2**30) == flat["rho_q30"][k]
    pairs = np.stack([flat[n][ok] for n in ("ref_x_q8", "ref_y_q8", "mov_x_q8", "mov_y_q8")],
                     axis=1).astype(np.int32)
    f = ssda.poly_fit(pairs, (200, 160), order=1)
    assert (f.n_used, f.rejected, f.cond) == (doc["used"], doc["rejected"], doc["cond"])
    assert f.rms_q8 == doc["rms"] * 256
    used = [e["used"] for e, o in zip(doc["points"], ok) if o]
    assert used == f.used.tolist()
    # the registered image: MOV warped through the map, bilinear, fill 0
    from conftest import read_png
    out, filled, _ = ssda.warp(mov, f.poly)
    assert (out == read_png(tmp_path / "o.png")).all() and filled > 0
    import io
    streamed = ssda.Source(io.BytesIO(mov.tobytes()), 200, 160, memory=8192)
    assert (ssda.warp(streamed, f.poly, tile_w=40)[0] == out).all()  # through 8 KB of plates


def test_warp_known_shift_and_bad_inputs():
    from conftest import texture
    a = texture(60, 80, 2)
    p = ssda.poly_init((80, 60), order=1)
    p["u_q24"][0][0] += 3 << 24  # moving x = reference x + 3
    out, filled, _ = ssda.warp(a, p, resample="nearest", fill=7)
    assert (out[:, :77] == a[:, 3:]).all() and (out[:, 77:] == 7).all() and filled == 3 * 60
    a16 = a.astype(np.uint16) * 200
    assert (ssda.warp(a16, p, resample="nearest")[0][:, :77] == a16[:, 3:]).all()
    with pytest.raises(ValueError):
        ssda.warp(a, p, resample="cubic")
    with pytest.raises(ssda.Error) as e:
        ssda.warp(a, p, fill=300)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(TypeError):
        ssda.warp(a, np.zeros(3))


def test_register_points_bad_inputs_raise():
    from conftest import texture
    a = texture(100, 100, 1)
    with pytest.raises(ssda.Error) as e:
        ssda.register_points(a, a.astype(np.uint16))
    assert e.value.code == ssda.ERR_FORMAT
    with pytest.raises(ssda.Error) as e:
        ssda.register_points(a, a, window=50, search=40)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ssda.Error) as e:
        ssda.register_points(a, a, grid_x=10, window=20)  # cells narrower than the window
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ValueError):
        ssda.register_points(a, a, metric="ssd")
    with pytest.raises(TypeError):
        ssda.register_points(a, a.astype(np.float32))
    pts, acc = ssda.register_points(a, a)  # itself: every accepted point in place
    ok = pts["status"] == ssda.REGISTER_OK  # (to the sub-pixel parabola's 1/4 px)
    assert acc == ok.sum() > 0
    assert (abs(pts["mov_x_q8"][ok] - pts["ref_x_q8"][ok]) <= 64).all()
    assert (abs(pts["mov_y_q8"][ok] - pts["ref_y_q8"][ok]) <= 64).all()
