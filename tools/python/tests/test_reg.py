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
                        int(f.within_bound)]
    p = f.poly[0]
    assert lines[1] == (p["u_q24"].tolist() + p["v_q24"].tolist() +
                        [p["cx"], p["cy"], p["kx"], p["ky"], p["order"]])
    assert [[int(r), int(u)] for r, u in zip(f.residual_q8, f.used)] == lines[2:42]
    assert list(ssda.poly_eval(f.poly, 100, 50)) == lines[42]


def test_poly_fit_known_map_and_outlier():
    pairs = pairs_of(60, 400, 300, seed=9)
    f = ssda.poly_fit(pairs, (400, 300))  # order 2, 2 px bound
    assert not f.used[5] and f.rejected == 1 and f.within_bound
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
