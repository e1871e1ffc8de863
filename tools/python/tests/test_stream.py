"""ssda.Source, stream_match, stream_track: images read through a Python
callable or a file object give what the in-memory calls give; exceptions
raised while reading propagate; a Source is used by one call at a time."""
import io

import numpy as np
import pytest

import ssda
from conftest import shifted_pair, texture


def device(image, offset=0, pad=0):
    """The image's rows (each padded by pad bytes) after offset bytes, as a
    bytes device; returns (bytes, stride)."""
    stride = image.shape[1] * image.itemsize + pad
    buf = bytearray(offset + stride * image.shape[0])
    for y in range(image.shape[0]):
        start = offset + y * stride
        buf[start:start + image.shape[1] * image.itemsize] = image[y].tobytes()
    return bytes(buf), stride


def reader(data, log=None):
    def read(offset, size):
        if log is not None:
            log.append((offset, size))
        return data[offset:offset + size]
    return read


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
def test_stream_track_equals_track(dtype):
    first, second = shifted_pair(120, 100, dx=2, dy=-3, seed=41, dtype=dtype)
    d1, s1 = device(first, offset=6, pad=2 * first.itemsize)
    d2, s2 = device(second)
    mem = ssda.Source(reader(d1), 100, 120, dtype=dtype, offset=6, stride=s1, memory=8000)
    f = io.BytesIO(d2)
    fsrc = ssda.Source(f, 100, 120, dtype=dtype, stride=s2, memory=4000)
    for opts in ({}, {"predict": "none", "exclude": True}):
        want = ssda.track(first, second, **opts)
        got = ssda.stream_track(mem, fsrc, **opts)
        assert (got.vectors == want.vectors).all() and got.grid == want.grid
        if opts.get("predict") == "none":
            assert got.stats == want.stats
        # an array stands for an in-memory source on either side
        assert (ssda.stream_track(first, fsrc, **opts).vectors == want.vectors).all()
        assert (ssda.stream_track(mem, second, **opts).vectors == want.vectors).all()
    assert mem.memory == 8000 and mem.stats.reads > 0 and fsrc.stats.bytes_read > 0


def test_stream_match_rects_file_and_read_size(tmp_path):
    img = texture(90, 70, seed=42, dtype=np.uint16)
    data, stride = device(img)
    (tmp_path / "img.raw").write_bytes(data)
    want = ssda.match(img[10:80, 5:65], img[40:52, 30:44], blocks=False)  # streams: no levels
    with open(tmp_path / "img.raw", "rb") as f:
        src = ssda.Source(f, 70, 90, dtype="uint16", read_size=64, memory=8000)
        got = ssda.stream_match(src, img, area_rect=(5, 10, 60, 70),
                                window_rect=(30, 40, 14, 12))
    assert got == want
    assert src.stats.bytes_read % 64 == 0
    # reads past the end of the device are short by less than read_size: zero-filled
    log = []
    src2 = ssda.Source(reader(data, log), 70, 90, dtype=np.uint16, read_size=64, memory=8000)
    assert ssda.stream_match(src2, img[40:52, 30:44], area_rect=(5, 10, 60, 70)) == want
    assert all(o % 64 == 0 and s % 64 == 0 for o, s in log)
    assert (src2.row(3, 88, 20) == img[88, 3:23]).all()


def test_tiled_source():
    img = texture(50, 45, seed=43)
    tw, th = 16, 8
    across, down = -(-45 // tw), -(-50 // th)
    tiles = np.zeros((down * th, across * tw), np.uint8)
    tiles[:50, :45] = img
    # tile-major bytes: tile (tx, ty) holds its th rows of tw pixels
    data = b"".join(tiles[ty * th:(ty + 1) * th, tx * tw:(tx + 1) * tw].tobytes()
                    for ty in range(down) for tx in range(across))
    src = ssda.Source(reader(data), 45, 50, layout="tiled", tile=(tw, th), memory=3000)
    assert ssda.stream_match(src, img[20:30, 11:20]) == ssda.match(img, img[20:30, 11:20],
                                                                   blocks=False)


class Unplugged(Exception):
    pass


def test_exceptions_raised_while_reading_propagate():
    img = texture(64, 64, seed=44)
    data, _ = device(img)
    calls = []

    def flaky(offset, size):
        calls.append(offset)
        if len(calls) == 3:
            raise Unplugged("cable")
        return data[offset:offset + size]

    src = ssda.Source(flaky, 64, 64, memory=64 * 20)
    with pytest.raises(Unplugged, match="cable") as e:
        ssda.stream_track(src, img, window=8)
    assert any(f.name == "flaky" for f in e.traceback)
    # the source stays usable after a failed read
    assert (ssda.stream_track(src, img, window=8).vectors ==
            ssda.track(img, img, window=8).vectors).all()
    for bad, exc in ((lambda o, s: "text", TypeError), (lambda o, s: b"x", ValueError),
                     (lambda o, s: data[o:o + s] + b"!", ValueError)):
        with pytest.raises(exc, match="read"):
            ssda.stream_match(ssda.Source(bad, 64, 64), img[:8, :8])


def test_a_source_serves_one_call_at_a_time():
    img = texture(40, 40, seed=45)
    data, _ = device(img)
    holder = {}

    def reentrant(offset, size):
        ssda.stream_match(holder["src"], img[:4, :4])  # the source is busy
        return data[offset:offset + size]

    holder["src"] = ssda.Source(reentrant, 40, 40)
    with pytest.raises(RuntimeError, match="in use"):
        ssda.stream_match(holder["src"], img[:8, :8])


def test_bad_sources():
    with pytest.raises(TypeError, match="read"):
        ssda.Source(42, 10, 10)
    with pytest.raises(ssda.Error) as e:
        ssda.Source(lambda o, s: b"", 10, 10, memory=2)
    assert e.value.code == ssda.ERR_BUFFER
    with pytest.raises(ssda.Error) as e:
        ssda.Source(lambda o, s: b"", 0, 10)
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ValueError, match="layout"):
        ssda.Source(lambda o, s: b"", 10, 10, layout="zigzag")
    with pytest.raises(TypeError, match="dtype"):
        ssda.Source(lambda o, s: b"", 10, 10, dtype=np.float32)
