"""ssda.ncc_match and ssda.ncc_at: against a double-precision correlation
coefficient in NumPy (OpenCV's TM_CCOEFF_NORMED), the C library (cref)
field for field, and the coefficient's invariances."""
import numpy as np
import pytest
from numpy.lib.stride_tricks import sliding_window_view

import ssda
from conftest import texture


def rho_map(area, window):
    """rho at every placement, in doubles (0 where a placement is flat)."""
    a = sliding_window_view(area.astype(np.float64), window.shape)
    a = a - a.mean(axis=(2, 3), keepdims=True)
    w = window.astype(np.float64) - window.mean()
    num = (a * w).sum(axis=(2, 3))
    den = np.sqrt((a * a).sum(axis=(2, 3)) * (w * w).sum())
    return np.where(den > 0, num / np.where(den > 0, den, 1), 0.0)


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
def test_the_best_correlation_and_its_value(dtype):
    area = texture(50, 60, seed=71, dtype=dtype)
    window = texture(10, 12, seed=72, dtype=dtype)  # no exact copy: a real maximum
    rho = rho_map(area, window)
    y, x = divmod(int(np.argmax(rho)), rho.shape[1])
    for opts in ({}, {"full": True}, {"predict": (40, 3)}):
        r = ssda.ncc_match(area, window, **opts)
        assert (r.x, r.y) == (x, y), opts
        assert abs(r.rho - rho[y, x]) < 2e-9 and r.rho == r.rho_q30 / 2 ** 30
        assert r.around_q30 is None and not r.flat_window
    r = ssda.ncc_match(area, window, around=True)
    for j in range(3):
        for i in range(3):
            assert abs(r.around_q30[j, i] / 2 ** 30 - rho[y + j - 1, x + i - 1]) < 2e-9
    assert ssda.ncc_at(area, window, x, y) == r.rho_q30
    assert abs(ssda.ncc_at(area, window, 3, 4) / 2 ** 30 - rho[4, 3]) < 2e-9


def test_gain_offset_inversion_and_flat_windows():
    area = texture(40, 40, seed=73)
    window = area[12:24, 20:32]
    brighter = (window.astype(np.int32) // 2 + 60).astype(np.uint8)  # gain 1/2, offset
    r = ssda.ncc_match(area, brighter)
    assert (r.x, r.y) == (20, 12) and r.rho > 0.99
    inverted = (255 - window).astype(np.uint8)
    assert ssda.ncc_match(area, inverted, metric="abs")[:2] == (20, 12)
    assert ssda.ncc_match(area, inverted, metric="abs").rho_q30 == -ssda.NCC_ONE_Q30
    assert ssda.ncc_match(area, inverted)[:2] != (20, 12)  # rho there is -1
    assert ssda.ncc_at(area, inverted, 20, 12) == -ssda.NCC_ONE_Q30
    flat = ssda.ncc_match(area, np.full((5, 5), 9, np.uint8))
    assert flat.flat_window and (flat.x, flat.y, flat.rho_q30) == (0, 0, 0)
    disk = ssda.ncc_match(area, window, predict=(0, 0), radius=5)  # the match is outside
    assert disk.positions < 30 and np.hypot(disk.x, disk.y) <= 5


CASES = [({}, []), ({"full": True}, ["flags=1"]), ({"metric": "abs"}, ["metric=1"]),
         ({"predict": (30, 2), "around": True}, ["flags=10", "predict_x=30", "predict_y=2"]),
         ({"predict": (18, 10), "radius": 7}, ["flags=6", "radius=7", "predict_x=18",
                                              "predict_y=10"])]


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("opts,cargs", CASES, ids=[str(i) for i in range(len(CASES))])
def test_every_field_equals_the_c_library(cref, dtype, opts, cargs):
    area = texture(44, 51, seed=74, dtype=dtype)
    window = texture(9, 13, seed=75, dtype=dtype)
    bpp = np.dtype(dtype).itemsize
    a, w = cref.raw("a.raw", area), cref.raw("w.raw", window)
    (c,) = cref("ncc", a, 51, 44, w, 13, 9, bpp, *cargs)
    r = ssda.ncc_match(area, window, **opts)
    got = [r.x, r.y, r.rho_q30, int(r.flat_window), r.pixel_ops, r.positions, r.completed]
    if r.around_q30 is not None:
        got += r.around_q30.ravel().tolist()
    assert got == c
    (at,) = cref("ncc_at", a, 51, 44, w, 13, 9, bpp, 20, 30)
    assert ssda.ncc_at(area, window, 20, 30) == at[0]


def test_bad_inputs():
    area = texture(40, 300, seed=76)
    with pytest.raises(ssda.Error) as e:
        ssda.ncc_match(area[:8, :8], area)  # window larger than the area
    assert e.value.code == ssda.ERR_SIZE
    big = np.zeros((300, 300), np.uint8)
    with pytest.raises(ssda.Error) as e:  # 257 x 257 > 65536 pixels
        ssda.ncc_match(big, big[:257, :257])
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ssda.Error) as e:
        ssda.ncc_at(area, area[:8, :8], 295, 0)
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ValueError):
        ssda.ncc_match(area, area[:8, :8], metric="max")
    with pytest.raises(TypeError):
        ssda.ncc_match(area, area[:8, :8].astype(np.int16))
    with pytest.raises(TypeError):
        ssda.ncc_at(area, area[:8, :8], 0, 0, full=True)
    with pytest.raises(ssda.Error) as e:
        ssda.ncc_match(area, area[:8, :8].astype(np.uint16))
    assert e.value.code == ssda.ERR_FORMAT
