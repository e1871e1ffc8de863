"""docs/python.md's notebook: its python cells run in order in one
namespace, each printing exactly the text cell shown after it, and the
plot is written."""
import contextlib
import io
import os
import re

import pytest

from conftest import DOCS


def cells(text):
    """(code, expected output or None) for each ```python cell."""
    blocks = re.findall(r"```(python|text)\n(.*?)```", text, re.S)
    out = []
    for i, (kind, body) in enumerate(blocks):
        if kind == "python":
            nxt = blocks[i + 1] if i + 1 < len(blocks) else None
            out.append((body, nxt[1] if nxt and nxt[0] == "text" else None))
    return out


def test_notebook_runs_as_shown(tmp_path, monkeypatch):
    if not DOCS:
        pytest.skip("SSDA_DOCS not set (run through ctest)")
    with open(os.path.join(DOCS, "python.md"), encoding="utf-8") as f:
        nb = cells(f.read())
    assert len(nb) >= 5
    monkeypatch.chdir(tmp_path)
    env = {}
    for code, want in nb:
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            exec(compile(code, "docs/python.md", "exec"), env)
        if want is not None:
            assert buf.getvalue() == want, code
    png = tmp_path / "field.png"
    assert png.stat().st_size > 10000
    from PIL import Image
    assert Image.open(png).size == (460, 345)
