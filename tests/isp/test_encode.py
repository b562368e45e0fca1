"""The fused sRGB encoding (csrc/srgb.c around NumPy's power) is the NumPy stages bit for bit.

Reference: the chain's own NumPy stages, ``_quantise(srgb_oetf(correct_colour(x)), bits)``
(what ``ColourISP`` runs when it keeps its stages). Tolerance: none, the codes are equal:
the kernels repeat the stages' operations in their order (clip, the linear segment,
``p * 1.055 - 0.055``, ``* (2**bits - 1) + 0.5``, floor) and the power is NumPy's.
"""

from __future__ import annotations

import numpy as np
import pytest
from _support import load_kodak

import rgbz_fast as rz
from rgbz_fast.isp import ColourCorrection, ColourISP, DefectCorrection, srgb_encode
from rgbz_fast.isp._stages import _encode, _quantise, correct_colour, srgb_oetf


def _stages(x, bits):
    return _quantise(srgb_oetf(correct_colour(x)), bits)


def _thresholds(dtype, bits, n=64):
    """Linear values at which the NumPy stages' code steps up (bisection over the floats),
    for n codes spread over the range."""
    codes = np.unique(np.linspace(1, 2 ** bits - 1, n).astype(np.int64))
    lo = np.zeros(codes.size, dtype)
    hi = np.ones(codes.size, dtype)
    for _ in range(80):
        mid = ((lo.astype(np.float64) + hi) / 2).astype(dtype)
        up = _stages(mid.reshape(-1, 1, 1).repeat(3, axis=2), bits)[:, 0, 0] >= codes
        hi = np.where(up, mid, hi)
        lo = np.where(up, lo, mid)
    return hi


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("bits", [8, 16])
def test_encode_is_the_numpy_stages(rng, dtype, bits):
    x = np.concatenate([rng.uniform(-0.3, 1.3, 600_000), rng.uniform(0, 0.005, 100_000),
                        [0.0, -0.0, 1.0, 0.0031308, 5.0, -5.0]])
    # the few floats on both sides of the code steps, where a rounding would show
    up = down = _thresholds(dtype, bits)
    near = [up]
    for _ in range(3):
        up, down = np.nextafter(up, dtype(np.inf)), np.nextafter(down, dtype(-np.inf))
        near += [up, down]
    x = np.concatenate([x.astype(dtype)] + near)
    x = x[: x.size // 3 * 3].reshape(-1, 1, 3)
    got = _encode(x, bits)
    assert got.dtype == (np.uint8 if bits == 8 else np.uint16) and got.shape == x.shape
    assert np.array_equal(got, _stages(x, bits))
    assert np.array_equal(srgb_encode(x, bits), got)


def test_encode_of_odd_sizes_and_blocks(rng):
    for n in (1, 5, (1 << 18) + 7):
        x = rng.uniform(-0.1, 1.1, (n, 1, 3))
        assert np.array_equal(_encode(x, 8), _stages(x, 8))


@pytest.mark.parametrize("precision", ["float32", "float64"])
@pytest.mark.parametrize("matrix", [None, ((1.2, -0.1, -0.1), (-0.05, 1.1, -0.05),
                                           (0.0, -0.2, 1.2))])
def test_chain_without_stages_gives_the_same_image(precision, matrix):
    img = load_kodak(13, crop=(120, 160))
    lin = rz.simulation.srgb_to_linear(img / 255.0)
    frame = rz.mosaic(lin, "mask1", 11)
    frame = rz.RawFrame(frame.data, frame.pattern, 11, reference=rz.mosaic(lin, "bayer", 11).data)
    for bits in (8, 16):
        isp = ColourISP(defects=DefectCorrection(enabled=False), precision=precision,
                        colour_correction=ColourCorrection(matrix=matrix), output_bits=bits,
                        black_level=0.0)
        fast = isp.run(frame)
        kept, stages = isp.run(frame, return_stages=True)
        assert np.array_equal(fast, kept) and fast.dtype == kept.dtype
        ref = isp.render(frame.reference, "GRBG", bit_depth=11)
        assert np.array_equal(ref, isp.render(frame.reference, "GRBG", bit_depth=11,
                                              return_stages=True)[0])


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("bits", [8, 16])
def test_encode_table_gives_the_codes_of_the_stages(rng, dtype, bits):
    """The thresholds of the fused chain's table (isp._encode_table): the code of a value is
    the number of thresholds at or below it, the code of the NumPy stages bit for bit, at
    and around every threshold (one float either side) and on random values. (Every
    float32 of [0, 1] was checked once, 8 bits: 1 065 353 217 values, none differs.)"""
    from rgbz_fast.isp._encode_table import encode_by_table, encode_thresholds

    t = encode_thresholds(dtype, bits)
    assert t.dtype == dtype and t.size == 2 ** bits and t[0] == 0 and np.all(np.diff(t) > 0)
    x = np.concatenate([rng.random(300_000).astype(dtype), t[1:], np.nextafter(t[1:], dtype(-1)),
                        np.nextafter(t[1:], dtype(2)), np.array([-1, 0, 1, 2, 1e-30], dtype)])
    x = x[:x.size // 3 * 3]
    got = encode_by_table(x, bits)
    np.testing.assert_array_equal(got, _encode(x, bits))
    np.testing.assert_array_equal(got, _stages(x.reshape(-1, 1, 3), bits).reshape(-1))


def test_white_balance_gains_are_the_renders():
    cfa = rz.mosaic(load_kodak(4, crop=(64, 96)), "bayer").data
    chain = ColourISP(black_level=16.0)
    _, stages = chain.render(cfa, "GRBG", return_stages=True)
    np.testing.assert_array_equal(chain.white_balance_gains(cfa, "GRBG"), stages["gains"])
    fixed = chain.replace(white_balance={"gains": (1.5, 1.0, 2.0)})
    assert fixed.white_balance_gains(cfa).tolist() == [1.5, 1.0, 2.0]
    assert chain.replace(white_balance={"method": "none"}).white_balance_gains(cfa).tolist() \
        == [1.0, 1.0, 1.0]
    with pytest.raises(ValueError, match="phase"):
        chain.white_balance_gains(cfa, "mask1")
