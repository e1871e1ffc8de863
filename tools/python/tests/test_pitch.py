"""ssda.pitch / ssda.Pitch: the C library (cref) field for field, the ssda
tool's CSV, a known tone, and independence from how the stream is cut."""
import csv

import numpy as np
import pytest

import ssda
from conftest import tone, write_wav

FLAGS = {"track": 1, "full": 2, "no_filter": 4, "parabolic": 8, "no_octave": 16,
         "no_below_range": 32}


@pytest.mark.parametrize("opts", [
    {}, {"track": True, "parabolic": True}, {"full": True, "no_filter": True},
    {"no_octave": True, "no_below_range": True},
    {"f0_min_hz": 80, "f0_max_hz": 400, "hop": 100, "frame_len": 300, "chunk": 7,
     "threshold_q15": 8000, "voicing_q15": 6000, "silence_mad": 40, "lowpass_hz": 700},
])
def test_every_field_equals_the_c_library(cref, opts):
    rate = 16000
    x = np.concatenate([tone(rate, 0.25, 196.0), np.zeros(2000, np.int16),
                        tone(rate, 0.2, 311.0, seed=2)])
    cargs = ["%s=%d" % (k, v) for k, v in opts.items() if k not in FLAGS]
    cargs.append("flags=%d" % sum(b for k, b in FLAGS.items() if opts.get(k)))
    lines = cref("pitch", cref.raw("x.raw", x), x.size, rate, *cargs)
    est = ssda.Pitch(rate, **opts).push(x)
    names = ssda.PITCH_ESTIMATE_DTYPE.names
    assert [[int(e[n]) for n in names] for e in est] == lines
    assert len(lines) > 10


def test_a_tone_and_cut_independence():
    rate = 22050
    x = tone(rate, 0.5, 220.0)
    tr = ssda.pitch(x, rate)
    assert tr.voiced[2:].all()
    assert np.abs(tr.f0[2:] - 220.0).max() < 1.0
    p = ssda.Pitch(rate)
    parts = [p.push(x[i:i + 777]) for i in range(0, x.size, 777)]
    assert (np.concatenate(parts) == tr.estimates).all()
    # strided samples (every other one of a longer array) are copied, same answer
    y = np.zeros(2 * x.size, np.int16)
    y[::2] = x
    assert (ssda.Pitch(rate).push(y[::2]) == tr.estimates).all()
    p.reset()
    assert (p.push(x) == tr.estimates).all()
    assert tr.info.sample_rate_hz == rate and tr.info.hop == p.info.hop


def test_equals_the_ssda_tool(cli, tmp_path):
    rate = 16000
    x = np.concatenate([tone(rate, 0.3, 180.0), np.zeros(3000, np.int16),
                        tone(rate, 0.3, 260.0, amp=3000)])
    write_wav(tmp_path / "x.wav", x, rate)
    cli("pitch", "x.wav", "--csv", "f0.csv", "--quiet", "--hop-ms", "10")
    rows = list(csv.DictReader(open(tmp_path / "f0.csv")))
    tr = ssda.pitch(x, rate, hop=160)
    assert len(rows) == tr.time.size
    for i, row in enumerate(rows):  # the tool's formats, so equal values print equal
        assert row["time_s"] == "%.6f" % tr.time[i]
        assert row["f0_hz"] == "%.3f" % tr.f0[i]
        assert row["voiced"] == "%d" % tr.voiced[i]
        assert row["confidence"] == "%.4f" % tr.confidence[i]
        assert row["center_s"] == "%.6f" % tr.center_time[i]


def test_bad_configs_raise():
    with pytest.raises(ssda.Error) as e:
        ssda.Pitch(96000)
    assert e.value.code == ssda.ERR_ARG and "ssda_pitch" in str(e.value)
    with pytest.raises(ssda.Error) as e:
        ssda.Pitch(16000, frame_len=8)
    assert e.value.code == ssda.ERR_SIZE
    with pytest.raises(TypeError):
        ssda.Pitch(16000).push(np.zeros(100, np.float32))
    with pytest.raises(ValueError):
        ssda.Pitch(16000).push(np.zeros((100, 2), np.int16))
    with pytest.raises(TypeError):
        ssda.Pitch(16000, hopp=3)
    with pytest.raises(ValueError):
        ssda.Pitch(16000, hop=70000)
