"""ssda.grad: the Fig. 8 operator against its definition in NumPy, the C
library (cref) and the ssda tool; output arrays and dtypes."""
import numpy as np
import pytest

import ssda
from conftest import read_png, texture, write_png


def fig8(img):
    """E' = |A+B+C-G-H-I| + |A+D+G-C-F-I| on every full 3 x 3 neighbourhood."""
    a = img.astype(np.int64)
    A, B, C = a[:-2, :-2], a[:-2, 1:-1], a[:-2, 2:]
    D, F = a[1:-1, :-2], a[1:-1, 2:]
    G, H, I = a[2:, :-2], a[2:, 1:-1], a[2:, 2:]
    return np.abs(A + B + C - G - H - I) + np.abs(A + D + G - C - F - I)


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("out", [np.uint8, np.uint16])
def test_definition_and_c_library(cref, dtype, out):
    img = texture(37, 53, seed=31, dtype=dtype, smooth=1)
    r = ssda.grad(img, dtype=out)
    safe = {(1, 1): 2, (1, 2): 0, (2, 1): 10, (2, 2): 2}[(img.itemsize, np.dtype(out).itemsize)]
    assert r.image.dtype == out and r.image.shape == (35, 51) and r.saturated == 0
    assert (r.image == fig8(img) >> safe).all()
    for shift in (0, 3):  # 0 saturates 8-bit outputs of full-range data: counted, clipped
        r = ssda.grad(img, dtype=out, shift=shift)
        top = np.iinfo(out).max
        ref = fig8(img) >> shift
        assert (r.image == np.minimum(ref, top)).all()
        assert r.saturated == int((ref > top).sum())
        path = cref.raw("in.raw", img)
        (sat,) = cref("grad", path, 53, 37, img.itemsize, np.dtype(out).itemsize, shift,
                      path.with_suffix(".out"))
        c = np.fromfile(path.with_suffix(".out"), out).reshape(35, 51)
        assert (c == r.image).all() and sat[0] == r.saturated


def test_equals_the_ssda_tool(cli, tmp_path):
    img = texture(40, 50, seed=32, smooth=1)
    write_png(tmp_path / "in.png", img)
    cli("grad", "in.png", "out.png", "--bits", "16", "--shift", "0", "--crop")
    assert (read_png(tmp_path / "out.png") == ssda.grad(img).image).all()


def test_out_array_keeps_the_input_coordinates():
    img = texture(30, 40, seed=33)
    big = np.zeros((30, 40), np.uint16)
    r = ssda.grad(img, out=big[1:-1, 1:-1])
    assert r.image.base is big or np.shares_memory(r.image, big)
    assert (big[1:-1, 1:-1] == fig8(img)).all() and (big[0] == 0).all()
    with pytest.raises(ValueError, match="contiguous rows"):
        ssda.grad(img, out=np.zeros((38, 28), np.uint16).T)
    with pytest.raises(ValueError, match="shape"):
        ssda.grad(img, out=np.zeros((28, 37), np.uint16))
    with pytest.raises(ValueError, match="overlap"):
        img16 = img.astype(np.uint16)
        ssda.grad(img16, out=img16[1:-1, 1:-1])
    with pytest.raises(TypeError):
        ssda.grad(img, out=np.zeros((28, 38), np.float32))
    with pytest.raises(TypeError):
        ssda.grad(img, dtype=np.int16)
    with pytest.raises(ssda.Error) as e:
        ssda.grad(img[:2])
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ssda.Error) as e:
        ssda.grad(img, shift=32)
    assert e.value.code == ssda.ERR_ARG
