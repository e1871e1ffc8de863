"""ssda for Python: the ssda C library's exact, fixed-point SSDA template
matching, grid tracking, differential operator, block-streamed images and
AMDF pitch, on NumPy arrays, with the numbers the firmware computes, bit for
bit. See docs/python.md; every function's docstring names the C call.

Images are 2-D uint8 or uint16 arrays, sound 1-D int16 arrays; the library
reads them in place when their layout allows (rows of contiguous pixels,
positive row stride), else from a copy. Errors of the library raise
ssda.Error (code, message, function); wrong dtypes and shapes raise
TypeError / ValueError. Searches release the GIL.
"""
from ._ssda import (  # noqa: F401  (the extension's whole API)
    COMPOSITE_DTYPE, COMPOSITE_EDGE, COMPOSITE_FLAT, COMPOSITE_OK, ERR_ARG, ERR_BUFFER,
    ERR_FORMAT, ERR_IO, ERR_NULL, ERR_OVERFLOW, ERR_SIZE, ERR_STATE, ERR_STRIDE,
    ERR_UNSUPPORTED, FD_DTYPE, KERNEL, KL_NODATA, LOOP_DTYPE, MATCH_UNIQUE_NONE,
    MIX_COMPONENT_DTYPE, NCC_MAX_PIXELS, NCC_NONE, NCC_ONE_Q30, PAIR_DTYPE,
    PITCH_ESTIMATE_DTYPE, POLY_DTYPE, REGISTER_BORDER, REGISTER_FLAT, REGISTER_LOW_RHO,
    REGISTER_OK, REGISTER_OUTSIDE, REGISTER_POINT_DTYPE, RELAX_CHANGED, RELAX_CLASSES,
    RELAX_DTYPE, RELAX_VALID, TRACK_AMBIGUOUS, TRACK_AT_LIMIT, TRACK_EDGE, TRACK_EXCLUDED,
    TRACK_FLAT, TRACK_MASKED, TRACK_OK, TRACK_VECTOR_DTYPE, VERSION_MAJOR, VERSION_MINOR,
    VERSION_PATCH,
    CompositeResult, Contour, EdgeStats, Edges, Error, FdMatch, GradResult, Grid, KlResult,
    LoopStats, LoopsResult, MatchResult, MixModel, NccResult, Pitch, PitchInfo, PolyFit,
    ShadeResult, Source, SourceStats, SymregResult, TrackResult, TrackStats, __version__,
    composite, contour, edges, fd, fd_match, grad, kl, loops, match, mix_band_pixels, mix_fit,
    mix_hist, mix_label, mix_lut, ncc_at, ncc_match, poly_eval, poly_fit, poly_init, region,
    register_points, relax, relax_median, sad_at, shade, stream_match, stream_track, strerror,
    symreg, track, track_grid, warp,
)
from ._pitch_track import PitchTrack, pitch  # noqa: F401

__all__ = [name for name in dir() if not name.startswith("_")] + ["__version__"]
