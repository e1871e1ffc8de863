"""Shared helpers of the binding's tests: inputs with known content, the C
library's results through cref (tests/cref.c), and the ssda tool.

The build (tools/python/CMakeLists.txt) sets SSDA_CREF, SSDA_CLI and
SSDA_DOCS; without them the comparisons are skipped (a pip-installed
package has neither binary), never silently passed."""
import os
import subprocess
import wave

import numpy as np
import pytest

CREF = os.environ.get("SSDA_CREF")
CLI = os.environ.get("SSDA_CLI")
DOCS = os.environ.get("SSDA_DOCS")


def texture(h, w, seed, dtype=np.uint8, smooth=2):
    """A deterministic textured image: noise smoothed by box filters (so
    that a window's SAD minimum is unique), scaled to the dtype's range."""
    rng = np.random.default_rng(seed)
    a = rng.random((h + 2 * smooth, w + 2 * smooth))
    for _ in range(smooth):
        a = (a[:-2, :] + a[1:-1, :] + a[2:, :]) / 3
        a = (a[:, :-2] + a[:, 1:-1] + a[:, 2:]) / 3
    a = (a - a.min()) / (a.max() - a.min())
    top = np.iinfo(dtype).max
    return np.round(a * top).astype(dtype)


def shifted_pair(h, w, dx, dy, seed, dtype=np.uint8):
    """first, second: second is first moved by (dx, dy) (content at (x, y)
    of first appears at (x + dx, y + dy) of second)."""
    big = texture(h + 2 * 16, w + 2 * 16, seed, dtype)
    first = big[16:16 + h, 16:16 + w]
    second = big[16 - dy:16 - dy + h, 16 - dx:16 - dx + w]
    return np.ascontiguousarray(first), np.ascontiguousarray(second)


def tone(rate, seconds, f0, amp=8000, seed=1):
    """int16 harmonic tone with a little noise."""
    t = np.arange(int(rate * seconds)) / rate
    x = amp * (np.sin(2 * np.pi * f0 * t) + 0.5 * np.sin(2 * np.pi * 2 * f0 * t + 0.3))
    x += np.random.default_rng(seed).normal(0, 30, t.size)
    return np.clip(np.round(x), -32768, 32767).astype(np.int16)


@pytest.fixture
def cref(tmp_path):
    """Run cref; returns its stdout lines (split into ints)."""
    if not CREF:
        pytest.skip("SSDA_CREF not set (run through ctest)")

    def run(*args):
        out = subprocess.run([CREF] + [str(a) for a in args], check=True,
                             capture_output=True, text=True).stdout
        return [[int(v) for v in line.split()] for line in out.splitlines()]

    def raw(name, array):
        path = tmp_path / name
        np.ascontiguousarray(array).tofile(path)
        return path

    run.raw = raw
    return run


@pytest.fixture
def cli(tmp_path):
    """Run the ssda tool; returns the CompletedProcess."""
    if not CLI:
        pytest.skip("SSDA_CLI not set (run through ctest with the tools built)")

    def run(*args):
        return subprocess.run([CLI] + [str(a) for a in args], check=True,
                              capture_output=True, text=True, cwd=tmp_path)

    return run


def write_png(path, array):
    """A gray PNG of a uint8 or uint16 array (Pillow)."""
    from PIL import Image
    if array.dtype == np.uint16:
        img = Image.fromarray(array.astype("<u2"), mode="I;16")
    else:
        img = Image.fromarray(array, mode="L")
    img.save(path)
    return path


def read_png(path):
    from PIL import Image
    img = Image.open(path)
    a = np.array(img)
    return a.astype(np.uint16) if img.mode.startswith("I") else a


def write_wav(path, samples, rate):
    with wave.open(str(path), "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(rate)
        w.writeframes(samples.astype("<i2").tobytes())
    return path
