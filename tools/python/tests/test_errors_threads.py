"""Bad inputs raise clear exceptions (never a crash); library errors carry
the library's code and message; searches release the GIL."""
import threading
import time

import numpy as np
import pytest

import ssda
from conftest import texture

IMG = texture(32, 32, seed=51)
W = IMG[4:12, 6:14].copy()


@pytest.mark.parametrize("bad,exc,msg", [
    (IMG.astype(np.int32), TypeError, "uint8 or uint16 array, got dtype int32"),
    (IMG.astype(np.float64), TypeError, "float64"),
    (IMG.astype(bool), TypeError, "bool"),
    (IMG.astype(">u2"), TypeError, ">u2"),
    (IMG.tolist(), TypeError, "numpy array"),
    (IMG[0], ValueError, "2-D"),
    (IMG[None], ValueError, "2-D"),
    (IMG[:0], ValueError, "0 rows"),
    (np.zeros((2, 70000), np.uint8), ValueError, "70000 columns"),
])
def test_bad_images(bad, exc, msg):
    for call in (lambda: ssda.match(bad, W), lambda: ssda.match(IMG, bad),
                 lambda: ssda.track(bad, IMG), lambda: ssda.grad(bad),
                 lambda: ssda.stream_track(IMG, bad)):
        with pytest.raises(exc, match=msg):
            call()


def test_library_errors_carry_code_and_message():
    with pytest.raises(ssda.Error) as e:
        ssda.match(W, IMG)  # window larger than area
    assert e.value.code == ssda.ERR_SIZE == -3
    assert e.value.message == ssda.strerror(-3) == "bad dimensions"
    assert e.value.function == "ssda_match_search"
    assert str(e.value) == "ssda_match_search: bad dimensions (code -3)"
    with pytest.raises(ssda.Error) as e:
        ssda.match(IMG, W.astype(np.uint16))
    assert e.value.code == ssda.ERR_FORMAT
    with pytest.raises(ssda.Error) as e:
        ssda.match(IMG, W, threshold="ramp")  # lambda 0
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ssda.Error) as e:
        ssda.sad_at(IMG, W, 30, 0)
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(ssda.Error) as e:
        ssda.track(IMG, IMG, window=40)
    assert e.value.code == ssda.ERR_SIZE and e.value.function == "ssda_track_grid"
    with pytest.raises(ssda.Error) as e:
        ssda.track(IMG, IMG, predict="left", scan="coarse")
    assert e.value.code == ssda.ERR_ARG
    with pytest.raises(ssda.Error) as e:
        ssda.track(IMG, IMG, mask_value=300)  # beyond 8-bit
    assert e.value.code == ssda.ERR_ARG


@pytest.mark.parametrize("kw,exc", [
    ({"threshold": "fast"}, ValueError), ({"threshold": 1}, TypeError),
    ({"scan": "spiral"}, ValueError), ({"k_q8": -1}, ValueError), ({"k_q8": 1.5}, TypeError),
    ({"k_q8": 65536}, ValueError), ({"fixed_threshold": 2 ** 64}, ValueError),
    ({"predict": (1,)}, ValueError), ({"predict": 3}, TypeError),
    ({"predict": (2 ** 31, 0)}, ValueError), ({"tresholds": "auto"}, TypeError),
])
def test_bad_options(kw, exc):
    with pytest.raises(exc):
        ssda.match(IMG, W, **kw)


def test_bad_track_options_and_arguments():
    for kw, exc in (({"window": 0}, ValueError), ({"window": (8, 8, 8)}, ValueError),
                    ({"roi": (0, 0, 8)}, ValueError), ({"predict": "up"}, ValueError),
                    ({"mask_value": -1}, ValueError), ({"windows": 8}, TypeError)):
        with pytest.raises(exc):
            ssda.track(IMG, IMG, **kw)
    with pytest.raises(TypeError, match="2 positional"):
        ssda.track(IMG)
    with pytest.raises(TypeError, match="4 positional"):
        ssda.sad_at(IMG, W, 1)
    assert ssda.match(IMG, W, predict=np.array([3, 4])).exact  # numpy integers are fine
    assert ssda.track(IMG, IMG, window=np.uint16(8), threshold=None).stats.windows == 16


def test_searches_release_the_gil():
    """While a long search runs in a thread, the main thread keeps running
    Python code; a call holding the GIL would stall it for the whole search."""
    big = texture(700, 700, seed=52)
    win = big[300:396, 300:396].copy()
    t0 = time.perf_counter()
    ssda.match(big[:400, :400], win, threshold="none", bounds=False)
    one = time.perf_counter() - t0
    done = threading.Event()
    result = {}

    def work():
        result["r"] = ssda.match(big, win, threshold="none", bounds=False)
        done.set()

    ticks = 0
    t = threading.Thread(target=work)
    t.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    t.join()
    assert result["r"].sad == 0 and (result["r"].x, result["r"].y) == (300, 300)
    # the search ran ~ 3 x `one` (>= tens of ms): the main thread woke many times
    assert ticks >= 10, (ticks, one)


def test_concurrent_searches_agree():
    imgs = [texture(200, 200, seed=60 + i) for i in range(4)]
    wins = [im[50 + 20 * i:82 + 20 * i, 70:102].copy() for i, im in enumerate(imgs)]
    want = [ssda.match(im, w) for im, w in zip(imgs, wins)]
    got = [None] * 4

    def run(i):
        for _ in range(5):
            got[i] = ssda.match(imgs[i], wins[i])

    threads = [threading.Thread(target=run, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert got == want


def test_pitch_state_serves_one_thread_at_a_time():
    p = ssda.Pitch(48000, f0_min_hz=10, full=True)
    x = (np.random.default_rng(5).normal(0, 3000, 48000 * 2)).astype(np.int16)
    errors = []

    def push():
        try:
            p.push(x)
        except RuntimeError as e:
            errors.append(e)

    threads = [threading.Thread(target=push) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    # either they happened not to overlap, or the late ones were refused: never a race
    assert all("in use" in str(e) for e in errors)


def test_the_module_exports_its_init_function_only():
    import shutil
    import subprocess
    if not shutil.which("nm"):
        pytest.skip("no nm")
    out = subprocess.run(["nm", "-D", "--defined-only", ssda._ssda.__file__],
                         capture_output=True, text=True, check=True).stdout
    assert [line.split()[-1] for line in out.splitlines()] == ["PyInit__ssda"]
