"""ssda.kl, ssda.mix_*, ssda.region (seed 004): every field against the C
library (cref) on the same inputs, known answers (a rank-1 colour image, a
two-Gaussian histogram, an isolated pixel), strided inputs, bad inputs
raise."""
import numpy as np
import pytest

import ssda


def colour(h, w, seed, dtype=np.uint8, ch=3):
    rng = np.random.default_rng(seed)
    top = np.iinfo(dtype).max
    base = rng.normal(0.45, 0.12, (h, w))
    img = np.stack([base + rng.normal(0, 0.04, (h, w)) * (k + 1) for k in range(ch)], axis=2)
    img[: h // 2, :, 0] += 0.2  # a redder half: a second colour cluster
    return np.clip(np.round(img * top), 0, top).astype(dtype)


@pytest.mark.parametrize("dtype,ch,opts,cargs", [
    (np.uint8, 3, {}, []),
    (np.uint8, 4, {"matrix": "covariance", "range": "full", "out_max": 255},
     ["matrix=1", "range=1", "out_max=255"]),
    (np.uint16, 3, {"nsigma": 2, "gain_max_q16": 65536, "nodata": 0},
     ["nsigma=2", "gain_max_q16=65536", "nodata=0"]),
])
def test_kl_equals_the_c_library(cref, dtype, ch, opts, cargs):
    img = colour(23, 31, 4, dtype, ch)
    img[3:6, 4:9, :] = 0  # nodata pixels (masked only with nodata=0)
    bpp = np.dtype(dtype).itemsize
    lines = cref("kl", cref.raw("i.raw", img), 31, 23, bpp, ch, *cargs)
    k = ssda.kl(img, **opts)
    assert k.matrix_q30.ravel().tolist() == lines[0]
    assert k.vec_q30.ravel().tolist() == lines[1]
    assert k.lambda_q16.tolist() == lines[2] and k.zvar_q16.tolist() == lines[3]
    assert k.mean_q8.tolist() == lines[4]
    assert [k.count, k.masked, k.sweeps, k.clamped] == lines[5]
    assert k.features.reshape(3 * 23, 31).tolist() == lines[6:]
    if "nodata" in opts:
        assert k.masked == 15 and (k.features[:, 3:6, 4:9] == ssda.KL_NODATA).all()


def test_kl_rank_one_and_views():
    """Bands proportional to one ramp: one eigenvalue 3 (correlation), the
    first eigenvector (1, 1, 1) / sqrt 3; planar and interleaved layouts of
    the same image give the same numbers, read without a copy."""
    ramp = np.tile(np.arange(64, dtype=np.uint16), (8, 1))
    img = np.stack([ramp, 2 * ramp, 3 * ramp], axis=2).astype(np.uint8)
    k = ssda.kl(img)
    assert abs(k.lambda_q16[0] - 3 * 65536) <= 2 and k.lambda_q16[1] <= 2
    assert np.abs(k.vec_q30[0] - round(2**30 / np.sqrt(3))).max() <= 64
    planar = np.ascontiguousarray(img.transpose(2, 0, 1))
    before = ssda._ssda._copies()
    k2 = ssda.kl(planar.transpose(1, 2, 0))  # bands 8 * 64 bytes apart, pixels 1 apart
    assert ssda._ssda._copies() == before
    assert (k2.features == k.features).all() and (k2.vec_q30 == k.vec_q30).all()
    assert ssda.kl(img, features=False).features is None


def two_gaussians(bins=256, total=200000, seed=2):
    rng = np.random.default_rng(seed)
    v = np.concatenate([rng.normal(70, 8, total * 3 // 5), rng.normal(170, 15, total * 2 // 5)])
    return np.clip(np.round(v), 0, bins - 1).astype(np.uint16)


@pytest.mark.parametrize("opts,cargs,rule,band", [
    ({"components": 2}, ["components=2"], 0, 0),
    ({}, [], 1, 0),
    ({"components": 2, "fit": "search", "init": "quantiles", "seed_steps": True},
     ["components=2", "fit=1", "init=1", "flags=1"], 0, 384),
])
def test_mixture_equals_the_c_library(cref, opts, cargs, rule, band):
    values = two_gaussians()
    hist, skipped = ssda.mix_hist(values, bins=256)
    assert skipped == 0 and (hist == np.bincount(values, minlength=256)).all()
    lines = cref("mix", cref.raw("h.raw", hist), 256, rule, band, *cargs)
    m = ssda.mix_fit(hist, **opts)
    fit = 0 if m.fit == "em" else 1
    assert [m.count, m.loglik_q16, m.bic_q16, m.bins, m.total, m.iterations, fit] == lines[0]
    assert m.components.tolist() == [tuple(x) for x in lines[1:1 + m.count]]
    lut = ssda.mix_lut(m, rule="likely" if rule else "band", band_q8=band)
    assert lut.tolist() == lines[1 + m.count]
    assert ssda.mix_band_pixels(m, hist, band_q8=band).tolist() == lines[2 + m.count]
    labels = ssda.mix_label(values, lut)
    assert (labels == lut[values]).all()


def test_mixture_known_components():
    hist, _ = ssda.mix_hist(two_gaussians(), bins=256)
    m = ssda.mix_fit(hist, components=2)
    c = m.components
    assert abs(c["mean_q16"][0] / 65536 - 70) < 0.5 and abs(c["mean_q16"][1] / 65536 - 170) < 0.5
    assert abs(c["sigma_q16"][0] / 65536 - 8) < 0.3 and abs(c["sigma_q16"][1] / 65536 - 15) < 0.5
    assert abs(c["weight_q16"][0] / 65536 - 0.6) < 0.01
    auto = ssda.mix_fit(hist)  # BIC
    assert auto.count >= 2
    # shift folds values into fewer bins
    h2, _ = ssda.mix_hist(two_gaussians(), bins=128, shift=1)
    assert h2.sum() == hist.sum() and (h2 == hist.reshape(128, 2).sum(axis=1)).all()


@pytest.mark.parametrize("op", [0, 1])
def test_region_equals_the_c_library(cref, op):
    rng = np.random.default_rng(7)
    labels = (rng.random((17, 23)) < 0.3).astype(np.uint8) * 2
    labels[5:12, 6:15] = 1
    labels[8, 10] = 3  # an isolated point
    lines = cref("region", cref.raw("l.raw", labels), 23, 17, op)
    out, counts = ssda.region(labels, op="contour" if op else "clean", counts=True)
    assert out.tolist() == lines[:17] and counts.tolist() == lines[17]
    if op == 0:
        assert out[8, 10] == 1 and labels[8, 10] == 3
    strided = np.zeros((17, 40), np.uint8)
    strided[:, :23] = labels
    assert (ssda.region(strided[:, :23], op="contour" if op else "clean") == out).all()


def test_bad_inputs_raise():
    img = colour(8, 9, 1)
    with pytest.raises(TypeError):
        ssda.kl(img.astype(np.float32))
    with pytest.raises(ValueError):
        ssda.kl(img[:, :, :2])
    with pytest.raises(ValueError):
        ssda.kl(img[:, :, 0])
    with pytest.raises(ValueError):
        ssda.kl(img, matrix="pca")
    with pytest.raises(ssda.Error) as e:
        ssda.kl(img, nsigma=17)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ssda.Error) as e:
        ssda.kl(np.zeros((4, 4, 3), np.uint8), nodata=0)  # every pixel masked
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(TypeError):
        ssda.kl(img, bogus=1)
    with pytest.raises(TypeError):
        ssda.mix_hist(np.zeros(5, np.int32))
    with pytest.raises(ValueError):
        ssda.mix_hist(np.zeros(5, np.uint16), bins=5000)
    with pytest.raises(ValueError):
        ssda.mix_hist(np.zeros(5, np.uint16), shift=16)
    with pytest.raises(TypeError):
        ssda.mix_fit(np.zeros(10, np.int64))
    with pytest.raises(ssda.Error) as e:
        ssda.mix_fit(np.zeros(10, np.uint32))  # empty histogram
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ssda.Error) as e:
        ssda.mix_fit(np.ones(10, np.uint32), components=17)
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(TypeError):
        ssda.mix_lut((1, 2, 3))
    m = ssda.mix_fit(np.bincount(two_gaussians(), minlength=256).astype(np.uint32), components=2)
    with pytest.raises(ValueError):
        ssda.mix_lut(m, rule="nearest")
    with pytest.raises(ValueError):
        ssda.mix_band_pixels(m, np.zeros(10, np.uint32))
    with pytest.raises(TypeError):
        ssda.mix_label(np.zeros(4, np.uint16), np.zeros(4, np.uint16))
    with pytest.raises(TypeError):
        ssda.region(np.zeros((4, 4), np.uint16))
    with pytest.raises(ValueError):
        ssda.region(np.zeros((4, 4), np.uint8), op="open")


def test_segment_command_same_numbers(cli, tmp_path):
    """ssda segment's features, K-L vectors, mixtures and region counts are
    the binding's: kl with the tool's out_max (bins - 1) and gain cap (1.0
    for 8-bit), mix_hist / mix_fit / mix_lut / mix_label, region clean."""
    import json
    from PIL import Image
    from conftest import read_png
    img = colour(40, 52, 9)
    Image.fromarray(img, mode="RGB").save(tmp_path / "c.png")
    cli("segment", "c.png", "--components", "2", "--features", "f.png", "--json", "s.json")
    doc = json.loads((tmp_path / "s.json").read_text())
    k = ssda.kl(img, out_max=1023, gain_max_q16=65536)
    # cJSON prints 15 significant digits when they read back within an ulp or
    # so: the integers come back by rounding
    assert (np.round(np.array(doc["kl"]["vectors"]) * 2**30) == k.vec_q30).all()
    assert (np.round(np.array(doc["kl"]["eigenvalues"]) * 65536) == k.lambda_q16).all()
    assert doc["kl"]["clamped_values"] == k.clamped
    for z, feat in enumerate(doc["features"]):
        assert (read_png(tmp_path / f"f-z{z + 1}.png") == k.features[z]).all()
        hist, _ = ssda.mix_hist(k.features[z], bins=feat["bins"])
        m = ssda.mix_fit(hist, components=2)
        labels = ssda.mix_label(k.features[z], ssda.mix_lut(m))
        if doc["clean"]:
            labels, counts = ssda.region(labels, counts=True)
        else:
            counts = np.bincount(labels.ravel(), minlength=256)
        assert (feat["count"], feat["iterations"]) == (m.count, m.iterations)
        band = ssda.mix_band_pixels(m, hist)
        for j, c in enumerate(feat["components"]):
            assert round(c["weight"] * 65536) == m.components["weight_q16"][j]
            assert round(c["mean"] * 65536) == m.components["mean_q16"][j]
            assert round(c["sigma"] * 65536) == m.components["sigma_q16"][j]
            assert c["pixels"] == counts[j + 1] and c["band_pixels"] == band[j]
