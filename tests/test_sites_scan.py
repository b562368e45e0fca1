"""The measurement sites' checks in C (csrc/scan.c: sites_range, sites_off_z) against NumPy
references, and the frame checks that call them: the same verdicts, the same first bad site.

Tolerance: none; they return integers and flags, equal to the references'."""
import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast import _kernels
from rgbz_fast._patterns import Z
from rgbz_fast._validate import check_sites


def _range_reference(rows, cols):
    ordered = bool(np.all((rows[1:] > rows[:-1]) |
                          ((rows[1:] == rows[:-1]) & (cols[1:] > cols[:-1]))))
    return (rows.min(), rows.max(), cols.min(), cols.max()), ordered


def _off_z_reference(rows, cols, block, tile_z):
    P, Q = tile_z.shape
    ok = np.ones(rows.size, bool)
    for dr in range(block):
        for dc in range(block):
            ok &= tile_z[(rows + dr) % P, (cols + dc) % Q].astype(bool)
    bad = np.flatnonzero(~ok)
    return int(bad[0]) if bad.size else -1


@pytest.mark.parametrize("n", [1, 2, 7, 4095, 4096, 4097, 20000])
def test_sites_range_is_numpys(n):
    rng = np.random.default_rng(n)
    flat = np.sort(rng.choice(10 * n + 10, n, replace=False))
    rows, cols = (flat // 97).astype(np.int64), (flat % 97).astype(np.int64)
    assert _kernels.sites_range(rows, cols) == _range_reference(rows, cols)
    if n > 1:
        for i in sorted({0, (n - 2) // 2, n - 2}):     # a repeat, a swap: out of order
            r, c = rows.copy(), cols.copy()
            r[i + 1], c[i + 1] = r[i], c[i]
            assert _kernels.sites_range(r, c) == _range_reference(r, c)
            assert not _kernels.sites_range(r, c)[1]
            r, c = rows.copy(), cols.copy()
            r[[i, i + 1]], c[[i, i + 1]] = r[[i + 1, i]], c[[i + 1, i]]
            assert _kernels.sites_range(r, c) == _range_reference(r, c)
    big = np.array([0, 2**31 - 1], np.int64), np.array([5, 2**31 - 1], np.int64)
    assert _kernels.sites_range(*big) == ((0, 2**31 - 1, 5, 2**31 - 1), True)


@pytest.mark.parametrize("P,Q", [(1, 1), (2, 2), (3, 5), (4, 4), (6, 7), (8, 2), (49, 3), (3, 98)])
@pytest.mark.parametrize("block", [1, 2])
def test_sites_off_z_is_numpys(P, Q, block):
    rng = np.random.default_rng(P * 10 + Q + block)
    tile_z = (rng.random((P, Q)) < 0.6).astype(np.uint8)
    n = 9000
    rows = rng.integers(0, 2**31 - 2, n).astype(np.int64)
    cols = rng.integers(0, 2**31 - 2, n).astype(np.int64)
    rows[: n // 2] = rng.integers(0, 300, n // 2)      # 49 and 98: the quotient through a
    cols[: n // 2] = rng.integers(0, 300, n // 2)      # double is one short (sites_mod)
    assert _kernels.sites_off_z(rows, cols, block, tile_z) == \
        _off_z_reference(rows, cols, block, tile_z)
    # only Z sites, then one bad one at a chosen place (inside and at the ends of a C block)
    ok = np.ones(n, bool)
    for dr in range(block):
        for dc in range(block):
            ok &= tile_z[(rows + dr) % P, (cols + dc) % Q].astype(bool)
    good_r, good_c = rows[ok], cols[ok]
    if good_r.size:
        assert _kernels.sites_off_z(good_r, good_c, block, tile_z) == -1
    if good_r.size > 10 and (~ok).any():
        for at in (0, min(4095, good_r.size - 1), good_r.size - 1):
            r, c = good_r.copy(), good_c.copy()
            r[at], c[at] = rows[~ok][0], cols[~ok][0]
            assert _kernels.sites_off_z(r, c, block, tile_z) == at
    empty = np.zeros(0, np.int64)
    assert _kernels.sites_off_z(empty, empty, block, tile_z) == -1


def test_sites_off_z_period_49():
    """49 * (1 / 49) rounds below 1: the quotient through a double is one short and the
    remainder must be taken back into the period (a read past the tile otherwise; the tile
    here is the first half of a larger array, whose second half says Z everywhere)."""
    for P in (49, 98):
        big = np.ones((2 * P, 1), np.uint8)
        big[0] = 0
        tile = big[:P]
        for block, row in ((1, P), (2, P - 1)):
            got = _kernels.sites_off_z(np.array([1, row], np.int64), np.zeros(2, np.int64),
                                       block, tile)
            assert got == _off_z_reference(np.array([1, row]), np.zeros(2, int), block, tile)
            assert got == 1


def test_check_sites_paths_agree():
    """The C path (int64, contiguous) and the NumPy path (strided, other types) accept and
    refuse the same sites with the same messages."""
    rows = np.array([0, 0, 1, 3, 3], np.int64)
    cols = np.array([1, 4, 0, 2, 9], np.int64)
    variants = {"c": lambda a: a, "strided": lambda a: np.repeat(a, 2)[::2],
                "int32": lambda a: a.astype(np.int32), "uint16": lambda a: a.astype(np.uint16)}
    for name, f in variants.items():
        r, c, span = check_sites((f(rows), f(cols)), span=True)
        assert span == (0, 3, 0, 9), name
        np.testing.assert_array_equal(r, rows)
        # unordered but distinct: accepted
        check_sites((f(rows[::-1].copy()), f(cols[::-1].copy())))
        with pytest.raises(ValueError, match=r"^sites: the site \(3, 2\) is given twice"):
            check_sites((f(np.r_[rows, 3]), f(np.r_[cols, 2])))
    with pytest.raises(ValueError, match=r"^sites: rows span \[-1, 3\]"):
        check_sites((np.array([-1, 3]), np.array([0, 0])))
    with pytest.raises(ValueError, match=r"^sites: cols span \[0, 2147483648\]"):
        check_sites((np.array([0, 3]), np.array([0, 2**31])))
    assert check_sites((np.zeros(0, int), np.zeros(0, int)), span=True)[2] is None


def test_frame_refuses_a_site_off_the_z_pixels():
    frame = rz.simulate(rz.simulation.Scene(np.full((16, 16, 3), 0.5), depth=np.full((16, 16), 2.0)),
                        "mask2", noise=False)
    tof = frame.tof
    rows, cols = (a.copy() for a in tof.sites)
    tile_z = (frame.pattern.tile == Z)
    assert _kernels.sites_off_z(rows, cols, tof.block, tile_z.astype(np.uint8)) == -1
    cols[3] += 1                                  # half of the 2x2 block on colour pixels
    moved = rz.ToFTaps(tof.taps, tof.frequencies, (rows, cols), tof.block, tof.bit_depth,
                       tof.depth_true, tof.valid, tof.saturated, tof.sensor, tof.shape)
    with pytest.raises(ValueError, match=rf"^tof: the measurement at \({rows[3]}, {cols[3]}\)"):
        rz.RawFrame(frame.data, frame.pattern, frame.bit_depth, tof=moved)
