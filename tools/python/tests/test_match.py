"""ssda.match and ssda.sad_at: against a brute force in NumPy, the C
library (cref) field for field, and the ssda tool; views and copies."""
import json

import numpy as np
import pytest
from numpy.lib.stride_tricks import sliding_window_view

import ssda
from conftest import texture, write_png

THRESHOLDS = {"auto": 0, "none": 1, "fixed": 2, "ramp": 3, "auto_ramp": 4}
SCANS = {"raster": 0, "predict": 1, "coarse": 2}
ORDERS = {"rows": 0, "spread": 1}


def brute(area, window):
    """All SADs (int64) and the best (x, y, sad) by the tie rule."""
    win = sliding_window_view(area.astype(np.int64), window.shape)
    sads = np.abs(win - window.astype(np.int64)).sum(axis=(2, 3))
    k = int(np.argmin(sads))  # first minimum in row-major order: smallest y, then x
    y, x = divmod(k, sads.shape[1])
    return sads, x, y, int(sads[y, x])


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
def test_exact_modes_find_the_brute_force_minimum(dtype):
    area = texture(48, 56, seed=3, dtype=dtype)
    window = area[17:29, 30:40].copy()
    window[0, 0] ^= 1  # not a perfect copy: the minimum is a real minimum
    sads, x, y, sad = brute(area, window)
    for opts in [{}, {"bounds": False}, {"threshold": "none"}, {"order": "spread"},
                 {"predict": (3, 40)}]:
        r = ssda.match(area, window, **opts)
        assert (r.x, r.y, r.sad, r.exact) == (x, y, sad, True), opts
    assert ssda.sad_at(area, window, 5, 7) == int(sads[7, 5])
    assert ssda.sad_at(area, window, x, y) == sad


OPTION_SETS = [
    {},
    {"bounds": False},
    {"threshold": "none", "bounds": False},
    {"threshold": "fixed", "fixed_threshold": 20000},
    {"threshold": "fixed", "fixed_threshold": 10, "bounds": False},  # all cut: fallback
    {"threshold": "ramp", "lambda_q8": 3 * 256, "k_q8": 384},
    {"threshold": "auto_ramp", "bounds": False},
    {"scan": "coarse", "coarse_step": 5},
    {"scan": "predict", "predict": (-4, 100), "order": "spread"},
    {"blocks": False},
    {"threshold": "fixed", "fixed_threshold": 20000, "blocks": True},
]


def flags_of(opts):
    """SSDA_MATCH_BOUNDS (1), and SSDA_MATCH_BLOCKS (16) where blocks=None
    adds them: with the bounds under the auto threshold."""
    bounds = opts.get("bounds", True)
    blocks = opts.get("blocks")
    if blocks is None:
        blocks = bounds and opts.get("threshold", "auto") == "auto"
    return (1 if bounds else 0) | (16 if blocks else 0)


def cref_args(opts):
    args = ["threshold=%d" % THRESHOLDS[opts.get("threshold", "auto")],
            "scan=%d" % SCANS[opts.get("scan", "predict" if "predict" in opts else "raster")],
            "order=%d" % ORDERS[opts.get("order", "rows")],
            "flags=%d" % flags_of(opts)]
    for k in ("k_q8", "lambda_q8", "fixed_threshold", "coarse_step"):
        if k in opts:
            args.append("%s=%d" % (k, opts[k]))
    if "predict" in opts:
        args += ["predict_x=%d" % opts["predict"][0], "predict_y=%d" % opts["predict"][1]]
    return args


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("opts", OPTION_SETS, ids=lambda o: ",".join(map(str, o.values())) or "default")
def test_every_field_equals_the_c_library(cref, dtype, opts):
    area = texture(40, 52, seed=5, dtype=dtype)
    window = texture(9, 11, seed=6, dtype=dtype)  # no exact copy: ties and cuts happen
    bpp = np.dtype(dtype).itemsize
    a, w = cref.raw("a.raw", area), cref.raw("w.raw", window)
    (c,) = cref("match", a, 52, 40, w, 11, 9, bpp, *cref_args(opts))
    r = ssda.match(area, window, **opts)
    assert [r.x, r.y, r.sad, int(r.exact), r.pixel_ops, r.positions, r.completed] == c
    (s,) = cref("sad_at", a, 52, 40, w, 11, 9, bpp, 17, 23)
    assert ssda.sad_at(area, window, 17, 23) == s[0]


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("cli_opts,opts", [
    ([], {}),
    (["--threshold", "none", "--no-bounds"], {"threshold": "none", "bounds": False}),
    (["--threshold", "auto-ramp", "--scan", "coarse"], {"threshold": "auto_ramp", "scan": "coarse"}),
])
def test_equals_the_ssda_tool(cli, tmp_path, dtype, cli_opts, opts):
    area = texture(60, 70, seed=9, dtype=dtype)
    window = area[31:47, 12:28].copy()
    write_png(tmp_path / "s.png", area)
    write_png(tmp_path / "w.png", window)
    j = json.loads(cli("match", "s.png", "w.png", "--json", *cli_opts).stdout)
    r = ssda.match(area, window, **opts)
    # the binding's defaults are the tool's, block levels included (docs/cli.md)
    assert (r.x, r.y, r.sad, r.exact, r.positions, r.pixel_ops, r.completed) == (
        j["x"], j["y"], j["sad"], j["exact"], j["positions"], j["pixel_ops"], j["completed"])


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
def test_block_levels_on_a_large_window(cref, dtype):
    """A 40 x 48 window (block levels in use): the brute-force minimum with
    and without them, every field the C library's, less work with them."""
    area = texture(100, 120, seed=13, dtype=dtype)
    window = area[37:77, 51:99].copy()
    window[5, 7] ^= 3
    _, x, y, sad = brute(area, window)
    bpp = np.dtype(dtype).itemsize
    a, w = cref.raw("a.raw", area), cref.raw("w.raw", window)
    got = {}
    for blocks in (None, True, False):
        r = ssda.match(area, window, blocks=blocks)
        assert (r.x, r.y, r.sad, r.exact) == (x, y, sad, True), blocks
        (c,) = cref("match", a, 120, 100, w, 48, 40, bpp,
                    *cref_args({"blocks": blocks}))
        assert [r.x, r.y, r.sad, int(r.exact), r.pixel_ops, r.positions, r.completed] == c
        got[blocks] = r
    assert got[None] == got[True]
    assert got[True].pixel_ops < got[False].pixel_ops


def test_blocks_need_bounds():
    area = texture(40, 40, seed=2, dtype=np.uint8)
    with pytest.raises(ssda.Error) as e:
        ssda.match(area, area[:16, :16], bounds=False, blocks=True)
    assert e.value.code == ssda.ERR_ARG
    assert ssda.match(area, area[:16, :16], bounds=False).exact  # None: none without bounds


def test_views_are_used_where_the_layout_allows():
    base = texture(80, 90, seed=11, dtype=np.uint16)
    window = base[40:52, 50:60].copy()
    want = ssda.match(np.ascontiguousarray(base[5:75, 3:88]), window)
    before = ssda._ssda._copies()
    assert ssda.match(base[5:75, 3:88], window) == want  # a region: a view
    assert ssda.match(base[5:75, 3:88], window[:, :]) == want
    assert ssda._ssda._copies() == before
    # layouts with no view: copied, same answer
    f = np.asfortranarray(base[5:75, 3:88])
    flipped = np.ascontiguousarray(base[5:75, 3:88][::-1])[::-1]  # negative row stride
    raw = np.zeros(70 * 85 * 2 + 1, np.uint8)
    odd = raw[1:].view(np.uint16).reshape(70, 85)  # misaligned uint16
    odd[...] = base[5:75, 3:88]
    for a in (f, flipped, odd, base[5:75, 3:88].T.T):
        assert ssda.match(a, window) == want
    assert ssda._ssda._copies() == before + 3  # .T.T is the original layout again
    # a strided window (every other column) is copied too
    assert ssda.match(base, base[::2, ::2][:8, :8]).sad == ssda.match(
        base, np.ascontiguousarray(base[::2, ::2][:8, :8])).sad
