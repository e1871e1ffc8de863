"""ssda.track: known motion, the C library (cref) field for field, the ssda
tool's JSON, and the grid."""
import json

import numpy as np
import pytest

import ssda
from conftest import shifted_pair, write_png

PREDICT = {"none": 0, "left": 1, "median": 2}
STATUS = {"ok": ssda.TRACK_OK, "excluded": ssda.TRACK_EXCLUDED,
          "masked": ssda.TRACK_MASKED, "edge": ssda.TRACK_EDGE, "flat": ssda.TRACK_FLAT,
          "ambiguous": ssda.TRACK_AMBIGUOUS, "at_limit": ssda.TRACK_AT_LIMIT}
FIELDS = ("sad", "dx", "dy", "sub_dx_q8", "sub_dy_q8", "texture_q8", "x", "y", "unique_q8",
          "status", "exact")


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
def test_known_motion_is_found(dtype):
    first, second = shifted_pair(96, 112, dx=3, dy=-2, seed=21, dtype=dtype)
    r = ssda.track(first, second)
    v = r.vectors
    assert v.shape == (r.grid.rows, r.grid.cols) == (6, 7)
    ok = v["status"] == ssda.TRACK_OK
    assert ok.sum() == r.stats.ok > 0
    assert (v["dx"][ok] == 3).all() and (v["dy"][ok] == -2).all() and v["exact"][ok].all()
    # window positions: the grid's
    ys, xs = np.mgrid[0:r.grid.rows, 0:r.grid.cols]
    assert (v["x"] == xs * 16).all() and (v["y"] == ys * 16).all()
    # edge windows: the area would leave FIRST
    assert (v["status"][0, :] == ssda.TRACK_EDGE).all()
    assert r.grid == ssda.track_grid(112, 96)


CASES = [
    ({}, []),
    ({"predict": "left", "bounds": False}, ["predict=1", "m.flags=0"]),
    ({"predict": "none", "threshold": "none"}, ["predict=0", "m.threshold=1"]),
    ({"window": (12, 8), "search": (20, 18), "step": (6, 5), "roi": (4, 6, 90, 70)},
     ["win_w=12", "win_h=8", "search_w=20", "search_h=18", "step_x=6", "step_y=5",
      "roi_x=4", "roi_y=6", "roi_w=90", "roi_h=70"]),
    ({"exclude": True, "texture_threshold": 100, "texture_min_count": 30, "order": "spread"},
     ["flags=9", "texture_threshold=100", "texture_min_count=30", "m.order=1"]),
    # uniqueness is on by default only in the exact modes
    ({"mask_value": 0, "threshold": "auto_ramp"}, ["flags=2", "mask_value=0", "m.threshold=4"]),
    ({"predict": "none", "scan": "coarse", "threshold": "fixed", "fixed_threshold": 3000},
     ["flags=0", "predict=0", "m.scan=2", "m.threshold=2", "m.fixed_threshold=3000"]),
    ({"flat": False, "unique": False, "subpixel": False}, ["flags=20"]),
    ({"flat_q8": 700, "unique_q8": 400, "unique_radius": 1},
     ["flat_q8=700", "unique_q8=400", "unique_radius=1"]),
]


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("opts,cargs", CASES, ids=[str(i) for i in range(len(CASES))])
def test_every_field_equals_the_c_library(cref, dtype, opts, cargs):
    first, second = shifted_pair(80, 100, dx=-2, dy=1, seed=22, dtype=dtype)
    if "mask_value" in opts:  # a fill patch
        first[30:40, 20:45] = 0
        second[50:60, 60:70] = 0
    if "exclude" in opts:  # flat regions
        first[:, :30] = second[:, :30] = 7
    bpp = np.dtype(dtype).itemsize
    defaults = ["predict=2", "m.flags=1", "flags=8"]  # the binding's defaults (the tool's)
    lines = cref("track", cref.raw("f.raw", first), cref.raw("s.raw", second), 100, 80, bpp,
                 *(defaults + cargs))
    r = ssda.track(first, second, **opts)
    assert [r.grid.count, r.grid.cols, r.grid.rows] == lines[0]
    s = r.stats
    assert [s.pixel_ops, s.positions, s.completed, s.check_pixels, s.windows, s.ok,
            s.excluded, s.masked, s.edge, s.flat, s.ambiguous, s.at_limit] == lines[1]
    got = [[int(v[f]) for f in FIELDS] for v in r.vectors.ravel()]
    assert got == lines[2:]


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("cli_opts,opts", [
    ([], {}),
    (["--predict", "left", "--no-bounds", "--window", "12", "--step", "8x10"],
     {"predict": "left", "bounds": False, "window": 12, "step": (8, 10)}),
    (["--exclude", "120:20", "--mask-value", "3", "--threshold", "none"],
     {"exclude": True, "texture_threshold": 120, "texture_min_count": 20,
      "mask_value": 3, "threshold": "none"}),
])
def test_equals_the_ssda_tool(cli, tmp_path, dtype, cli_opts, opts):
    first, second = shifted_pair(90, 120, dx=4, dy=3, seed=23, dtype=dtype)
    first[0:20, 0:40] = 3
    write_png(tmp_path / "a.png", first)
    write_png(tmp_path / "b.png", second)
    cli("track", "a.png", "b.png", "--json", "out.json", "--quiet", *cli_opts)
    j = json.loads((tmp_path / "out.json").read_text())
    r = ssda.track(first, second, **opts)
    assert [r.grid.cols, r.grid.rows] == [j["grid"]["cols"], j["grid"]["rows"]]
    want = [(w["x"], w["y"], w["dx"], w["dy"], w["sad"], STATUS[w["status"]], w["exact"],
             round(w["sub_dx"] * 256), round(w["sub_dy"] * 256))
            for w in j["windows"]]
    got = [(int(v["x"]), int(v["y"]), int(v["dx"]), int(v["dy"]), int(v["sad"]),
            int(v["status"]), bool(v["exact"]), int(v["sub_dx_q8"]), int(v["sub_dy_q8"]))
           for v in r.vectors.ravel()]
    assert got == want
    for k in ("positions", "completed", "check_pixels", "ok", "excluded",
              "masked", "edge", "flat", "ambiguous", "at_limit"):
        assert getattr(r.stats, k) == j["stats"][k], k
    # pixel_ops: with bounds (threshold not none) the tool builds the bounds'
    # tables once per band of a grid row (shared tables, docs/cli.md
    # --threads) and ssda.track (one ssda_track call, a per-window work
    # buffer) once per window, so the counts differ (either way: on this
    # 120 x 90 pair the tool counts more, on cli_threads' pairs fewer); the
    # binding's count is checked against the C library above, the tool's
    # for any thread count by cli_threads. Without bounds they are equal.
    if not (opts.get("bounds", True) and opts.get("threshold", "auto") != "none"):
        assert j["stats"]["pixel_ops"] == r.stats.pixel_ops


def test_vectors_dtype_is_the_c_struct():
    dt = ssda.TRACK_VECTOR_DTYPE
    assert dt.names == FIELDS
    assert dt["dx"] == np.int32 and dt["sad"] == np.uint64 and dt["exact"] == np.bool_
