"""ssda.pitch(): a whole signal through one ssda.Pitch stream, with the
integer estimates turned into times and frequencies as the `ssda pitch`
tool turns them (the same double-precision expressions, so the numbers are
the tool's, bit for bit)."""
from dataclasses import dataclass

import numpy as np

from ._ssda import Pitch, PitchInfo


@dataclass(frozen=True)
class PitchTrack:
    """An f0 track: one entry per estimate (every info.hop samples).

    time        s, centre of the frame's span: (frame * hop + span / 2) / rate
                (increasing; the tool's CSV time_s)
    center_time s, centre of the samples the chosen lag compared (est. center;
                the tool's center_s): more precise, not always increasing
    f0          Hz, f0_q16 / 65536 where voiced, else 0
    f0_raw      Hz of the chosen lag even when unvoiced (0 when silent)
    voiced      bool
    confidence  confidence_q15 / 32768 (1 - the normalised difference)
    estimates   the library's estimates (PITCH_ESTIMATE_DTYPE), integers
    info        the resolved parameters (PitchInfo)
    """
    time: np.ndarray
    center_time: np.ndarray
    f0: np.ndarray
    f0_raw: np.ndarray
    voiced: np.ndarray
    confidence: np.ndarray
    estimates: np.ndarray
    info: PitchInfo


def pitch(samples, sample_rate_hz, **options):
    """f0 track of a 1-D int16 signal: Pitch(sample_rate_hz, **options).push(samples).

    sample_rate_hz: 8000..48000 (resample first otherwise). options: those of
    ssda.Pitch (f0_min_hz, f0_max_hz, frame_len, hop, threshold_q15,
    voicing_q15, silence_mad, chunk, lowpass_hz, track, full, no_filter,
    parabolic, no_octave, no_below_range; 0 = the library's default). Returns a PitchTrack.
    """
    p = Pitch(sample_rate_hz, **options)
    est = p.push(samples)
    info = p.info
    frame = est["frame"].astype(np.float64)
    rate = float(info.sample_rate_hz)
    # the centre's offset from the frame start, exact mod 2^32 as the tool keeps it
    offset = (est["center"].astype(np.int64) -
              est["frame"].astype(np.int64) * info.hop) % (1 << 32)
    f0_raw = est["f0_q16"] / 65536.0
    return PitchTrack(
        time=(frame * info.hop + info.span / 2.0) / rate,
        center_time=(frame * info.hop + offset.astype(np.float64)) / rate,
        f0=np.where(est["voiced"], f0_raw, 0.0),
        f0_raw=f0_raw,
        voiced=est["voiced"].copy(),
        confidence=est["confidence_q15"] / 32768.0,
        estimates=est,
        info=info,
    )
