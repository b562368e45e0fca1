"""Property-based robustness tests (hypothesis): never a crash, a hang or silent garbage.

For any frame shape from 1x1 up (odd sizes, sizes that are not a multiple of the
pattern period), every frame dtype, every preset pattern in every Bayer phase,
random custom tiles, every method and every option, a public kernel call either

* raises ValueError or TypeError whose message starts with the name of the
  offending parameter (``"frame: ..."``, ``"pattern: ..."``, ``"method: ..."``), or
* returns a valid result: right shape and dtype, finite, within [0, 2**b - 1],
  colour sites copied bit for bit, and each reconstructed value within the range
  of the known pixels of its colour (a weighted mean with positive weights, the
  intensity domain); on float64 frames in float64 precision it also equals the
  NumPy reference of tests/_reference/reconstruction.py (the border shift of tiny frames, where
  the 5x5 window wraps several periods, is where the kernels are most fragile).

The same for the Malvar demosaic, the ToF demodulation and unwrapping. Example
counts are sized so that the whole file runs in well under a minute on two
cores; CI loads the derandomized "deterministic" profile of conftest.py.
"""

from __future__ import annotations

import re

import numpy as np
import pytest


hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, event, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from _reference.learned import reference_learned  # noqa: E402
from _reference.reconstruction import reference_reconstruct  # noqa: E402
from rgbz_fast.isp import demosaic  # noqa: E402
from rgbz_fast.tof import demodulate, unwrap  # noqa: E402

DTYPES = (np.uint8, np.uint16, np.float32, np.float64)
PHASES = rz.BAYER_PHASES
PRESETS = [f"{base}_{ph.lower()}" for base in ("mask1", "mask2", "rows", "bayer")
           for ph in PHASES]
#: the plan methods; "learned" (filters fitted per pattern and bit depth) has its own test below,
#: the methods that need the Z pixels' measurements (NEEDS_TOF) theirs
METHODS = tuple(m for m in rz.METHODS if m != "learned" and m not in rz.NEEDS_TOF)
#: a message that names the parameter it is about: "frame: ...", "ToFSensor.bit_depth: ..."
NAMED = re.compile(r"^[A-Za-z_][\w.\[\], ]*: ")

def quick(n):
    """Example count n, no deadline (the first call may wait for an editable rebuild)."""
    return settings(max_examples=n, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


# --------------------------------------------------------------------------- strategies
@st.composite
def custom_tiles(draw):
    """Tile strings: mostly a Bayer tile of even period with random Z sites, some pure noise."""
    if draw(st.integers(0, 4)) == 0:                       # anything at all, often invalid
        p, q = draw(st.integers(1, 4)), draw(st.integers(1, 4))
        codes = draw(st.lists(st.sampled_from("RGBZ"), min_size=p * q, max_size=p * q))
        return "/".join("".join(codes[r * q:(r + 1) * q]) for r in range(p))
    phase = draw(st.sampled_from(PHASES))
    p, q = draw(st.sampled_from([2, 4, 6])), draw(st.sampled_from([2, 4, 6]))
    rows = []
    for r in range(p):
        row = ""
        for c in range(q):
            letter = phase[2 * (r % 2) + (c % 2)]
            row += "Z" if draw(st.integers(0, 3)) == 0 else letter
        rows.append(row)
    return "/".join(rows)


patterns = st.one_of(st.sampled_from(PRESETS), custom_tiles())


@st.composite
def frames(draw, pattern, dtype, bit_depth):
    """A frame of one of several contents, values within the bit depth."""
    P, Q = pattern.period                    # half the frames hold at least one period
    rows = draw(st.integers(draw(st.sampled_from([1, P])), 19))
    cols = draw(st.integers(draw(st.sampled_from([1, Q])), 19))
    top = (1 << bit_depth) - 1
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    kind = draw(st.sampled_from(["random", "flat", "zero", "max", "binary", "spike",
                                 "tiny", "ramp"]))
    shape = (rows, cols)
    if kind == "random":
        d = rng.uniform(0, top, shape)
    elif kind == "flat":
        d = np.full(shape, float(rng.integers(0, top + 1)))
    elif kind == "zero":
        d = np.zeros(shape)
    elif kind == "max":
        d = np.full(shape, float(top))
    elif kind == "binary":                        # the largest gradients there are
        d = rng.integers(0, 2, shape) * float(top)
    elif kind == "spike":                         # one-pixel feature on a dark frame
        d = np.zeros(shape)
        d[rng.integers(0, rows), rng.integers(0, cols)] = top
    elif kind == "tiny":                          # denormal-range floats (if the dtype has them)
        tiny = 1e-310 if dtype == np.float64 else 1e-40
        d = rng.integers(0, 4, shape) * tiny
    else:
        d = np.add.outer(np.arange(rows), np.arange(cols)) * (top / max(rows + cols - 2, 1))
    if np.issubdtype(np.dtype(dtype), np.integer):
        d = np.floor(d + 0.5)
    d = np.clip(d, 0, top).astype(dtype)
    return d


def _named_error(exc):
    assert NAMED.match(str(exc)), f"error message does not name a parameter: {exc!r}"


# --------------------------------------------------------------------------- reconstruct
@quick(1000)
@given(data=st.data(), pattern_name=patterns, method=st.sampled_from(METHODS),
       dtype=st.sampled_from(DTYPES), precision=st.sampled_from(["float32", "float64"]),
       domain=st.sampled_from(["intensity", "colour_difference"]),
       sg_mode=st.sampled_from(["auto", "pure", "combined"]),
       exp=st.sampled_from(["libm", "fast"]), workers=st.sampled_from([1, 2, 3]))
def test_reconstruct_never_crashes_or_returns_garbage(data, pattern_name, method, dtype,
                                                      precision, domain, sg_mode, exp,
                                                      workers):
    bit_depth = data.draw(st.integers(1, 8 if dtype == np.uint8 else 16), label="bit_depth")
    sigma_floor = data.draw(st.sampled_from([1e-300, 1e-12, 1e-3, 1.0, 1e6]),
                            label="sigma_floor")
    sigma_rel = data.draw(st.sampled_from([0.0, 0.5, 10.0]), label="sigma_rel")
    edge_ratio = data.draw(st.sampled_from([1e-9, 0.5, 4.0]), label="edge_ratio")
    try:
        pattern = rz.get_pattern(pattern_name)
    except (ValueError, TypeError) as exc:
        _named_error(exc)
        return
    frame = data.draw(frames(pattern, dtype, bit_depth), label="frame")
    before = frame.copy()
    kw = dict(pattern=pattern, bit_depth=bit_depth, precision=precision, workers=workers,
              sigma_floor=sigma_floor, sigma_rel=sigma_rel, edge_ratio=edge_ratio,
              sg_mode=sg_mode, exp=exp, domain=domain)
    try:
        out = rz.reconstruct(frame, method, **kw)
    except (ValueError, TypeError) as exc:
        _named_error(exc)
        event(f"rejected: {str(exc).split(':')[0]}")
        P, Q = pattern.period
        small = frame.shape[0] < P or frame.shape[1] < Q
        # the colour-difference domain is the weighted methods' (H75)
        domain_refused = (method in ("bilinear", "edi_rows") and domain != "intensity"
                          and str(exc).startswith("domain: "))
        assert small or pattern.bayer_phase is None or domain_refused or re.match(
            r"^(pattern|method): ", str(exc)), exc
        return
    finally:
        np.testing.assert_array_equal(frame, before)          # the input is never modified
    top = (1 << bit_depth) - 1
    assert out.shape == frame.shape and out.dtype == frame.dtype
    assert np.all(np.isfinite(out))
    assert out.min() >= 0 and out.max() <= top
    z = pattern.z_mask(frame.shape)
    np.testing.assert_array_equal(out[~z], frame[~z])
    if not z.any():
        event("accepted: no Z site")
        return
    event("accepted")
    if domain == "intensity" or method == "bilinear":
        # a weighted mean of known pixels of the target colour: inside their range
        missing = pattern.missing_colour(frame.shape)
        bmap = pattern.bayer_map(frame.shape)
        f64 = frame.astype(np.float64)
        for c in np.unique(missing[z]):
            known = f64[(bmap == c) & ~z]
            if known.size == 0:
                continue
            got = out[missing == c].astype(np.float64)
            slack = 0.5 if np.issubdtype(out.dtype, np.integer) else 1e-5 * max(top, 1)
            assert got.min() >= known.min() - slack and got.max() <= known.max() + slack
    if precision == "float64" and exp == "libm":
        # the kernel reads the frame's values and computes in double: the reference up
        # to rounding of the output (float32, or half up to an integer)
        event("compared with the reference")
        with np.errstate(all="ignore"):     # the reference's 0/0 where sigma**2 underflows
            ref = reference_reconstruct(frame, pattern, method, bit_depth=bit_depth,
                                        sigma_floor=sigma_floor, sigma_rel=sigma_rel,
                                        edge_ratio=edge_ratio, sg_mode=sg_mode,
                                        domain="intensity" if method == "bilinear" else domain)
        tol = {np.float64: 1e-9 * max(top, 1), np.float32: 1e-6 * max(top, 1)}.get(
            dtype, 0.5 + 1e-6 * top)
        np.testing.assert_allclose(out.astype(np.float64), ref, rtol=1e-9, atol=tol)


@quick(300)
@given(data=st.data(), pattern_name=st.sampled_from(["mask1", "mask2", "mask1_rggb", "mask2_bggr",
                                                    "mask2_gbrg"]),
       bit_depth=st.sampled_from([8, 11]), dtype=st.sampled_from(DTYPES),
       precision=st.sampled_from(["float32", "float64"]), workers=st.sampled_from([1, 2]))
def test_learned_never_crashes_or_returns_garbage(data, pattern_name, bit_depth, dtype,
                                                  precision, workers):
    """The shipped filters on any frame: a valid result (its linear filters may overshoot
    the range of the known pixels, never [0, 2**b - 1]), the reference in float64 (but at
    the fragile sites of tests/_reference/learned.py)."""
    if dtype == np.uint8 and bit_depth > 8:
        dtype = np.uint16
    pattern = rz.get_pattern(pattern_name)
    frame = data.draw(frames(pattern, dtype, bit_depth), label="frame")
    before = frame.copy()
    try:
        out = rz.reconstruct(frame, "learned", pattern=pattern, bit_depth=bit_depth,
                             precision=precision, workers=workers)
    except (ValueError, TypeError) as exc:
        _named_error(exc)
        P, Q = pattern.period
        assert frame.shape[0] < P or frame.shape[1] < Q, exc
        return
    finally:
        np.testing.assert_array_equal(frame, before)
    top = (1 << bit_depth) - 1
    assert out.shape == frame.shape and out.dtype == frame.dtype
    assert np.all(np.isfinite(out)) and out.min() >= 0 and out.max() <= top
    z = pattern.z_mask(frame.shape)
    np.testing.assert_array_equal(out[~z], frame[~z])
    if precision == "float64":
        # fragile sites (an isotropic window: its orientation is rounding noise) excepted
        ref, fragile = reference_learned(
            frame, rz.reconstruction.default_filters(pattern), return_fragile=True,
            bit_depth=bit_depth)
        tol = {np.float64: 1e-9 * top, np.float32: 1e-6 * top}.get(dtype, 0.5 + 1e-6 * top)
        keep = z & ~fragile
        if (z & fragile).any():
            event("fragile sites left out")
        np.testing.assert_allclose(out.astype(np.float64)[keep], ref[keep], rtol=1e-9,
                                   atol=tol)


@quick(150)
@given(pattern_name=st.sampled_from(PRESETS), method=st.sampled_from(METHODS),
       dtype=st.sampled_from(DTYPES), value=st.integers(0, 255),
       shape=st.tuples(st.integers(1, 13), st.integers(1, 13)))
def test_flat_frame_stays_flat(pattern_name, method, dtype, value, shape):
    """A constant frame reconstructs to the same constant, at any size and in any domain."""
    pattern = rz.get_pattern(pattern_name)
    frame = np.full(shape, value, dtype)
    weighted = method not in ("bilinear", "edi_rows")      # the others refuse the domain
    for domain in ("intensity", "colour_difference") if weighted else ("intensity",):
        try:
            out = rz.reconstruct(frame, method, pattern=pattern, bit_depth=8, domain=domain)
        except ValueError as exc:
            _named_error(exc)
            return
        assert np.all(out == frame), (domain, np.unique(out))


# --------------------------------------------------------------------------- bad arrays
@quick(200)
@given(shape=st.lists(st.integers(0, 5), min_size=0, max_size=4),
       dtype=st.sampled_from([np.uint8, np.uint16, np.int8, np.int32, np.int64, np.float16,
                              np.float32, np.float64, np.complex64, np.bool_, object,
                              ">u2", ">f8"]),
       poison=st.sampled_from([None, np.nan, np.inf, -np.inf, -1.0, 1e30]),
       pattern_name=st.sampled_from(PRESETS))
def test_arbitrary_arrays_are_rejected_cleanly(shape, dtype, poison, pattern_name):
    """Any ndim, any size (0 included), any dtype, NaN/inf/out-of-range: ValueError/TypeError."""
    a = np.zeros(shape, dtype=dtype)
    if poison is not None and a.size and np.dtype(dtype).kind == "f":
        with np.errstate(over="ignore"):              # 1e30 is inf in float16
            a.flat[0] = poison
    try:
        out = rz.reconstruct(a, "sg", pattern=pattern_name)
    except (ValueError, TypeError) as exc:
        _named_error(exc)
        return
    # accepted: a real 2-D frame of a supported dtype (either byte order), within the 11-bit
    # range
    assert a.ndim == 2 and np.dtype(dtype).newbyteorder("=") in (np.uint8, np.uint16,
                                                                  np.float32, np.float64)
    assert out.shape == a.shape and np.all(np.isfinite(out))


# --------------------------------------------------------------------------- demosaic
@quick(300)
@given(shape=st.tuples(st.integers(1, 17), st.integers(1, 17)),
       dtype=st.sampled_from(DTYPES + (np.int16, np.bool_)),
       phase=st.sampled_from(PHASES), mode=st.sampled_from(["reflect", "period"]),
       kind=st.sampled_from(["random", "flat", "zero", "max", "spike", "tiny"]),
       out_dtype=st.sampled_from([None, np.float32, np.float64]),
       seed=st.integers(0, 2**32 - 1))
def test_malvar_demosaic_is_finite_and_exact_on_flat(shape, dtype, phase, mode, kind,
                                                     out_dtype, seed):
    rng = np.random.default_rng(seed)
    top = {np.uint8: 255, np.bool_: 1}.get(dtype, 65535)
    if kind == "random":
        cfa = rng.uniform(0, top, shape)
    elif kind == "flat":
        cfa = np.full(shape, float(rng.integers(0, top + 1)))
    elif kind == "zero":
        cfa = np.zeros(shape)
    elif kind == "max":
        cfa = np.full(shape, float(top))
    elif kind == "spike":
        cfa = np.zeros(shape)
        cfa[rng.integers(0, shape[0]), rng.integers(0, shape[1])] = top
    else:
        cfa = rng.integers(0, 3, shape) * (1e-310 if dtype == np.float64 else 1e-40)
    cfa = cfa.astype(dtype)
    if dtype == np.bool_:                      # a mask, not CFA values: refused, never 0/1 DN
        with pytest.raises(TypeError, match="^cfa: dtype bool is not supported"):
            demosaic(cfa, phase, mode=mode, dtype=out_dtype)
        return
    try:
        rgb = demosaic(cfa, phase, mode=mode, dtype=out_dtype)
    except ValueError as exc:
        _named_error(exc)
        assert min(shape) < 2
        return
    assert rgb.shape == shape + (3,)
    assert np.all(np.isfinite(rgb))
    # every Malvar filter sums to 1, with positive taps summing to at most 1.75 and
    # negative ones to at least -0.75: out - lo lies in [-0.75, 1.75] * (hi - lo)
    lo, hi = float(cfa.min()), float(cfa.max())
    tol = 1e-6 * max(hi, 1e-300)
    assert rgb.min() >= lo - 0.75 * (hi - lo) - tol and rgb.max() <= lo + 1.75 * (hi - lo) + tol
    if kind in ("flat", "zero", "max"):
        np.testing.assert_allclose(rgb, float(cfa.flat[0]), rtol=1e-6)


# --------------------------------------------------------------------------- ToF
@quick(300)
@given(F=st.integers(1, 4), n=st.integers(0, 40), dtype=st.sampled_from(
    [np.uint16, np.float32, np.float64, np.uint8, np.int32]),
    kind=st.sampled_from(["random", "equal", "zero", "max", "one_hot"]),
    seed=st.integers(0, 2**32 - 1), workers=st.sampled_from([1, 2, 3]))
def test_demodulate_outputs_are_finite_and_in_range(F, n, dtype, kind, seed, workers):
    rng = np.random.default_rng(seed)
    top = 255 if dtype == np.uint8 else 2047
    shape = (F, 4, n)
    if kind == "random":
        taps = rng.integers(0, top + 1, shape)
    elif kind == "equal":                              # zero amplitude: phase undefined
        taps = np.broadcast_to(rng.integers(0, top + 1, (F, 1, n)), shape)
    elif kind == "zero":
        taps = np.zeros(shape)
    elif kind == "max":                                # saturated taps
        taps = np.full(shape, top)
    else:
        taps = np.zeros(shape)
        taps[:, rng.integers(0, 4)] = top
    taps = np.ascontiguousarray(taps).astype(dtype)
    phase, amp, off = demodulate(taps, workers=workers)
    for a in (phase, amp, off):
        assert a.shape == (F, n) and a.dtype == np.float64 and np.all(np.isfinite(a))
    assert np.all((phase >= 0) & (phase < 2 * np.pi))
    assert np.all(amp >= 0) and np.all(amp <= top / np.sqrt(2) + 1e-9)
    assert np.all((off >= 0) & (off <= top))
    if kind in ("equal", "zero", "max"):
        assert np.all(amp == 0)


@quick(200)
@given(d=st.lists(st.floats(0, 7.4948), min_size=1, max_size=30),
       noise=st.sampled_from([0.0, 1e-3, 0.05]), seed=st.integers(0, 2**32 - 1))
def test_unwrap_recovers_depth_inside_the_unambiguous_range(d, noise, seed):
    """Noise-free or slightly noisy phases of depths in [0, 7.4948] m unwrap back to the depth."""
    c = 299_792_458.0
    f = np.array([80e6, 100e6, 120e6])
    d = np.asarray(d)
    rng = np.random.default_rng(seed)
    phase = np.mod(4 * np.pi * f[:, None] * d[None] / c + rng.normal(0, noise, (3, d.size)),
                   2 * np.pi)
    depth, residual, wraps = unwrap(phase, f)
    assert np.all(np.isfinite(depth)) and np.all(np.isfinite(residual))
    assert np.all(depth >= -0.1) and np.all(depth <= 7.495 + 0.1)
    amb = c / (2 * 80e6)
    err = np.abs(depth - d)
    err = np.minimum(err, np.abs(err - 7.4948))            # 0 and 7.4948 m are the same phase
    if noise == 0:
        assert err.max() < 1e-6, (d[np.argmax(err)], depth[np.argmax(err)])
    elif noise == 1e-3:
        assert err.max() < 0.01
    assert np.all((wraps >= 0) & (wraps < np.ceil(7.4948 / amb)))
