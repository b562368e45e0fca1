"""rgbz_fast.reconstruct (C kernels) against the NumPy references of tests/_reference/reconstruction.py.

The references are written from docs/guide/interpretation.md independently of the C
kernels and of rgbz_fast._plans; the two must agree:

* float64 precision on float64 frames: to TOL["float64"] (rtol 1e-9);
* float32 precision: to TOL["float32"] (rtol 1e-4), except at *fragile*
  sites, where float32 may legitimately take another branch than float64:
  the weights of the site are all in the float32 underflow range (their
  float64 sum is below WSUM_F32), so float32 falls back to the plain mean
  (or keeps a few subnormal weights) while float64 still forms the weighted
  mean; or, for edi_rows, two of the five differences (or D_m and
  edge_ratio * c) are equal up to float32 rounding, so the direction chosen
  differs. These sites are counted and must stay a small fraction;
* integer frames: C == floor(ref + 0.5), except +-1 at exact .5 ties.
"""

from __future__ import annotations

import inspect
import zlib
from functools import lru_cache

import numpy as np
import pytest

import rgbz_fast as rz
from _reference.reconstruction import (METHODS, edi_rows_decision_margin, reference_reconstruct,  # noqa: E402
                        round_half_up, shift_index)
from _support import TOL, load_kodak  # noqa: E402

# -- cases ------------------------------------------------------------------------------

PATTERNS = {
    "mask1": lambda: rz.mask1(),
    "mask2": lambda: rz.mask2(),
    "mask1_rggb": lambda: rz.mask1("RGGB"),
    "mask2_bggr": lambda: rz.mask2("BGGR"),
    "custom_ZR/BG": lambda: rz.Pattern("ZR/BG"),
}
ROW_PATTERNS = {"rows": lambda: rz.rows(), "rows_rggb": lambda: rz.rows("RGGB")}
ALL_PATTERNS = {**PATTERNS, **ROW_PATTERNS}
WEIGHTED = ("bilinear", "bi", "edi_central", "edi_line", "sg")
assert set(WEIGHTED) | {"edi_rows"} == set(METHODS) == set(rz.METHODS) - {"learned", "z_guided"}

CASES = ([(pn, m) for pn in PATTERNS for m in WEIGHTED]
         + [(pn, "edi_rows") for pn in ROW_PATTERNS])
CASE_IDS = [f"{pn}-{m}" for pn, m in CASES]

#: float64 weight sum below which float32 weights are in the underflow range
WSUM_F32 = 1e-30
#: edi_rows decision margin below which float32 may choose another direction
MARGIN_F32 = 1e-5
#: largest fraction of the Z sites that may be fragile mismatches in float32
MAX_FRAGILE_MISMATCH = 0.10


#: The reference implements the intensity domain (eq. 13, the default); the
#: colour-difference domain (eq. 5) is compared with its own reference in
#: test_colour_difference_domain_matches_reference; the contract and
#: extreme-value tests run every domain.
_PARAMS = inspect.signature(rz.reconstruct).parameters
HAS_DOMAIN = "domain" in _PARAMS
SPEC_KW = {"domain": "intensity"} if HAS_DOMAIN else {}
DOMAINS = ["intensity", "colour_difference"] if HAS_DOMAIN else [None]


def recon(frame, method, **kw):
    """rz.reconstruct with the spec's options unless told otherwise (domain=None: default)."""
    kw = {**SPEC_KW, **kw}
    if kw.get("domain", "") is None:
        del kw["domain"]
    return rz.reconstruct(frame, method, **kw)


def seeded(*key):
    return np.random.default_rng(zlib.crc32(repr(key).encode()))


def top_of(bit_depth):
    return (1 << bit_depth) - 1


def random_frame(pattern, shape, rng, dtype=np.float64, bit_depth=11, z_junk=False):
    """Random frame in [0, 2^b - 1]; Z sites hold 0 (or random junk if z_junk)."""
    top = top_of(bit_depth)
    if np.issubdtype(np.dtype(dtype), np.floating):
        d = rng.uniform(0, top, shape).astype(dtype)
    else:
        d = rng.integers(0, top + 1, shape).astype(dtype)
    if not z_junk:
        d[pattern.z_mask(shape)] = 0
    return d


def run(data, pattern, method, bit_depth=11, **kw):
    return recon(data, method, pattern=pattern, bit_depth=bit_depth, **kw)


def check_contract(out, data, pattern, bit_depth):
    """Same shape and dtype, colour sites unchanged, finite, in [0, 2^b - 1]."""
    assert out.shape == data.shape
    assert out.dtype == data.dtype
    z = pattern.z_mask(data.shape)
    np.testing.assert_array_equal(out[~z], data[~z])
    assert np.all(np.isfinite(out))
    assert out.min() >= 0 and out.max() <= top_of(bit_depth)


def tol_for(precision, bit_depth):
    """TOL, with the float32 atol scaled to the white level.

    The weighted mean c0 + sum w (c - c0) / sum w cancels when c0 is bright
    and the result dark: float32 then carries an absolute error of a few ulp
    of 2^b - 1 (0.004 DN at 16 bits), whatever the value. TOL's atol
    (1e-3 DN) is meant for 11-bit frames; it scales with 2^b.
    """
    tol = dict(TOL[precision])
    if precision == "float32":
        tol["atol"] *= max(1.0, top_of(bit_depth) / 2047)
    return tol


def compare(out, data, pattern, method, precision, bit_depth=11, **kw):
    """Compare a float-frame C output with the reference; return (n_mismatch, n_fragile)."""
    ref, wsum = reference_reconstruct(data, pattern, method, bit_depth=bit_depth,
                                      return_weight_sum=True, **kw)
    bad = ~np.isclose(out.astype(np.float64), ref, **tol_for(precision, bit_depth))
    if precision == "float64":
        if bad.any():
            ys, xs = np.nonzero(bad)
            raise AssertionError(
                f"{bad.sum()} sites differ from the reference, e.g. ({ys[0]}, {xs[0]}): "
                f"C {out[ys[0], xs[0]]!r} vs ref {ref[ys[0], xs[0]]!r}")
        return 0, 0
    fragile = wsum < WSUM_F32
    if method == "edi_rows":
        fragile |= edi_rows_decision_margin(data, pattern, kw.get("edge_ratio", 0.5)) < MARGIN_F32
    unexplained = bad & ~fragile
    if unexplained.any():
        ys, xs = np.nonzero(unexplained)
        raise AssertionError(
            f"{unexplained.sum()} non-fragile sites differ, e.g. ({ys[0]}, {xs[0]}): "
            f"C {out[ys[0], xs[0]]!r} vs ref {ref[ys[0], xs[0]]!r} (weight sum "
            f"{wsum[ys[0], xs[0]]:.3g})")
    nz = pattern.z_mask(data.shape).sum()
    assert bad.sum() <= MAX_FRAGILE_MISMATCH * nz + 1, (bad.sum(), nz)
    return int(bad.sum()), int(fragile.sum())


def shapes_for(pname):
    p = ALL_PATTERNS[pname]()
    P, Q = p.period
    out = [(37, 41), (P, Q), (2 * P + 1, 3 * Q - 1)]
    if pname.startswith("mask1") or pname.startswith("custom"):
        out.append((4, 4))
    if pname.startswith("mask2"):
        out.append((5, 7))
    return out


SHAPE_CASES = [(pn, m, s) for pn, m in CASES for s in shapes_for(pn)]
SHAPE_IDS = [f"{pn}-{m}-{s[0]}x{s[1]}" for pn, m, s in SHAPE_CASES]


@lru_cache(maxsize=None)
def kodak(n):
    img = load_kodak(n, crop=(64, 96))
    img.setflags(write=False)
    return img


KODAK = (1, 8, 19)


# -- the reference itself -------------------------------------------------------------------

def test_reference_border_rule():
    # i < 0 -> i + P*ceil(-i/P); i >= n -> i - P*ceil((i - n + 1)/P)
    assert shift_index([-1, -2, 0, 3, 4, 5], 4, 2).tolist() == [1, 0, 0, 3, 2, 3]
    assert shift_index([-2, -1, 5, 6], 5, 4).tolist() == [2, 3, 1, 2]
    assert shift_index([-2, -1, 2, 3], 2, 2).tolist() == [0, 1, 0, 1]
    assert shift_index([-4, 7, 9], 6, 6).tolist() == [2, 1, 3]


def test_reference_bilinear_mask1_is_mean_of_the_four_greens():
    p = rz.mask1()                        # ZR/BG: Z at (even, even), greens at (odd, odd)
    d = random_frame(p, (10, 10), seeded("bil"))
    ref = reference_reconstruct(d, p, "bilinear")
    for y, x in [(4, 4), (2, 6), (6, 2)]:
        greens = [d[y + dy, x + dx] for dy in (-1, 1) for dx in (-1, 1)]
        assert ref[y, x] == pytest.approx(np.mean(greens), rel=1e-12)
    # borders: row/col -1 is moved to 1, row/col 10 to 8 (whole periods of 2)
    assert ref[0, 0] == d[1, 1]
    assert ref[8, 0] == pytest.approx((d[7, 1] + d[9, 1]) / 2, rel=1e-12)


def test_reference_sg_mask1_matches_paper_sums():
    """Eqs. 14-19 on Mask1 written literally, with the paper's sums (SG_SW with dh[6, 8]).

    Every Mask1 semi-gradient holds exactly two differences, so the paper's
    sums are twice the spec's means: sigma doubles too and eq. 7 gives the
    same gammas; eq. 19's sums of three gammas are 3x the means, a common
    factor that eq. 12 cancels.
    """
    p = rz.mask1()                        # ZR/BG: Z at (even, even), greens at (odd, odd)
    d = random_frame(p, (12, 12), seeded("sg-hand"))
    ref = reference_reconstruct(d, p, "sg", sigma_rel=0.0)     # sigma = smallest SG, as printed
    y, x = 6, 4

    def I(dy, dx):                        # noqa: E743
        return d[y + dy, x + dx]

    def ok(a, b):                         # same channel, no Z
        ca = p.channel_map(d.shape)[y + a[0], x + a[1]]
        cb = p.channel_map(d.shape)[y + b[0], x + b[1]]
        return ca == cb and ca != rz.Z

    dv, dh = {}, {}
    for j in range(5):
        c = j - 2
        for key, a, b in [(("v", 2 * j), (0, c), (-2, c)), (("v", 2 * j + 1), (0, c), (2, c)),
                          (("h", 2 * j), (c, 0), (c, -2)), (("h", 2 * j + 1), (c, 0), (c, 2))]:
            if ok(a, b):
                (dv if key[0] == "v" else dh)[key[1]] = abs(I(*a) - I(*b))
    SG = {
        "N": sum(dv.get(j, 0) for j in (0, 2, 6, 8)),
        "S": sum(dv.get(j, 0) for j in (1, 3, 7, 9)),
        "W": sum(dh.get(j, 0) for j in (0, 2, 6, 8)),
        "E": sum(dh.get(j, 0) for j in (1, 3, 7, 9)),
        "NW": sum(dv.get(j, 0) + dh.get(j, 0) for j in (0, 2)),
        "SE": sum(dv.get(j, 0) + dh.get(j, 0) for j in (7, 9)),
        "NE": sum(dv.get(j, 0) for j in (6, 8)) + sum(dh.get(j, 0) for j in (1, 3)),
        "SW": sum(dv.get(j, 0) for j in (1, 3)) + sum(dh.get(j, 0) for j in (6, 8)),
    }
    assert len(dv) == 4 and len(dh) == 4          # two differences per SG on Mask1
    sigma = min(SG.values())
    g = {k: np.exp(-v ** 2 / (2 * sigma ** 2)) for k, v in SG.items()}
    w = {(-1, -1): g["N"] + g["W"] + g["NW"],     # 19a, pixel 6
         (-1, 1): g["N"] + g["E"] + g["NE"],      # 19b, pixel 8
         (1, -1): g["S"] + g["W"] + g["SW"],      # 19c, pixel 16
         (1, 1): g["S"] + g["E"] + g["SE"]}       # 19d, pixel 18
    value = sum(wk * I(*k) for k, wk in w.items()) / sum(w.values())
    assert ref[y, x] == pytest.approx(value, rel=1e-12)


@pytest.mark.parametrize("case", ["dominant_b", "no_edge", "tie_b_d", "weak_edge"])
def test_reference_edi_rows_by_hand(case):
    p = rz.rows()                          # rows 4, 5 of every 6 are Z
    d = np.full((12, 14), 500.0)
    d[p.z_mask(d.shape)] = 0
    y, x = 4, 7                            # a Z site; rows 2 and 6 hold its colour
    d[y - 2, x], d[y + 2, x] = 100.0, 900.0        # c = 800, vertical mean 500
    if case == "dominant_b":
        d[y - 2, x - 2], d[y + 2, x + 2] = 300.0, 310.0    # b = 10
        d[y - 2, x + 2], d[y + 2, x - 2] = 0.0, 600.0      # d = 600
        d[y - 2, x - 4], d[y + 2, x + 4] = 0.0, 900.0      # a = 900
        d[y - 2, x + 4], d[y + 2, x - 4] = 0.0, 900.0      # e = 900
        expected = np.median([300.0, 310.0, 500.0])
    elif case == "no_edge":
        for dx in (-4, -2, 2, 4):
            d[y - 2, x + dx], d[y + 2, x - dx] = 0.0, 900.0 - abs(dx)   # all >= 896
        d[y - 2, x], d[y + 2, x] = 400.0, 600.0                          # c = 200 smallest
        expected = 500.0
    elif case == "tie_b_d":
        d[y - 2, x - 2], d[y + 2, x + 2] = 700.0, 720.0    # b = 20, picked before d
        d[y - 2, x + 2], d[y + 2, x - 2] = 10.0, 30.0      # d = 20
        for dx in (-4, 4):
            d[y - 2, x + dx], d[y + 2, x - dx] = 0.0, 1000.0
        expected = np.median([700.0, 720.0, 500.0])
    else:                                   # b < c but not below edge_ratio * c
        d[y - 2, x - 2], d[y + 2, x + 2] = 100.0, 600.0    # b = 500 >= 0.5 * 800
        for dx in (-4, 2, 4):
            d[y - 2, x + dx], d[y + 2, x - dx] = 0.0, 1000.0
        expected = 500.0
    ref = reference_reconstruct(d, p, "edi_rows")
    assert ref[y, x] == expected
    out = run(d, p, "edi_rows", precision="float64")
    assert out[y, x] == expected


# -- C against the reference: random float frames -----------------------------------------

@pytest.mark.parametrize("pname, method, shape", SHAPE_CASES, ids=SHAPE_IDS)
@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_random_frames_match_reference(pname, method, shape, precision):
    p = ALL_PATTERNS[pname]()
    d = random_frame(p, shape, seeded(pname, method, shape))
    out = run(d, p, method, precision=precision)
    check_contract(out, d, p, 11)
    compare(out, d, p, method, precision)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("precision", ["float64", "float32"])
@pytest.mark.parametrize("n", KODAK)
def test_kodak_crops_match_reference(n, pname, method, precision):
    p = ALL_PATTERNS[pname]()
    frame = rz.mosaic(kodak(n), p, bit_depth=11, dtype=np.float64)
    out = recon(frame, method, precision=precision)
    check_contract(out, frame.data, p, 11)
    compare(out, frame.data, p, method, precision)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_float32_frames(pname, method):
    """float32 in, float32 out: the reference sees the same float32 values."""
    p = ALL_PATTERNS[pname]()
    d = random_frame(p, (23, 30), seeded("f32", pname, method), dtype=np.float32)
    for precision in ("float32", "float64"):
        out = run(d, p, method, precision=precision)
        check_contract(out, d, p, 11)
        # the float32 output rounds the result to float32: rtol 1e-4 covers it
        compare(out, d, p, method, "float32")


@pytest.mark.parametrize("pname", list(PATTERNS))
@pytest.mark.parametrize("sg_mode", ["auto", "pure", "combined"])
def test_sg_modes_match_reference(pname, sg_mode):
    p = PATTERNS[pname]()
    d = random_frame(p, (29, 34), seeded("sgmode", pname, sg_mode))
    out = run(d, p, "sg", precision="float64", sg_mode=sg_mode)
    compare(out, d, p, "sg", "float64", sg_mode=sg_mode)


def test_sg_auto_is_pure_on_mask1_and_combined_on_mask2():
    d1 = random_frame(rz.mask1(), (20, 20), seeded("auto1"))
    auto = run(d1, rz.mask1(), "sg", precision="float64")
    np.testing.assert_array_equal(auto, run(d1, rz.mask1(), "sg", precision="float64",
                                            sg_mode="pure"))
    assert not np.array_equal(auto, run(d1, rz.mask1(), "sg", precision="float64",
                                        sg_mode="combined"))
    d2 = random_frame(rz.mask2(), (20, 20), seeded("auto2"))
    auto = run(d2, rz.mask2(), "sg", precision="float64")
    np.testing.assert_array_equal(auto, run(d2, rz.mask2(), "sg", precision="float64",
                                            sg_mode="combined"))
    assert not np.array_equal(auto, run(d2, rz.mask2(), "sg", precision="float64",
                                        sg_mode="pure"))


@pytest.mark.parametrize("sigma_floor", [1e-12, 1e-3, 0.5, 30.0, 1e4])
@pytest.mark.parametrize("method", ["edi_central", "edi_line", "sg"])
@pytest.mark.parametrize("pname", ["mask1", "mask2"])
def test_sigma_floor_matches_reference(pname, method, sigma_floor):
    p = PATTERNS[pname]()
    d = random_frame(p, (24, 28), seeded("floor", pname, method, sigma_floor))
    # flat patches so that the floor is active at some sites
    d[4:12, 4:12] = 700.0
    d[p.z_mask(d.shape)] = 0
    out = run(d, p, method, precision="float64", sigma_floor=sigma_floor)
    compare(out, d, p, method, "float64", sigma_floor=sigma_floor)


@pytest.mark.parametrize("edge_ratio", [0.05, 0.5, 1.0, 3.0])
@pytest.mark.parametrize("pname", list(ROW_PATTERNS))
def test_edge_ratio_matches_reference(pname, edge_ratio):
    p = ROW_PATTERNS[pname]()
    d = random_frame(p, (36, 40), seeded("ratio", pname, edge_ratio))
    for precision in ("float64", "float32"):
        out = run(d, p, "edi_rows", precision=precision, edge_ratio=edge_ratio)
        compare(out, d, p, "edi_rows", precision, edge_ratio=edge_ratio)


# -- custom patterns -----------------------------------------------------------------------

#: Bayer-derived custom tiles (GRBG) whose every candidate is covered by a
#: valid semi-gradient; they exercise red/blue targets, gradient groups and
#: semi-gradients without valid differences (gamma = 0 / all-1 rules).
CUSTOM_OK = {
    "GRGR/BGZG": "Z for blue",
    "GZGR/BGBG": "Z for red",
    "ZRZZ/BGBG": "an EDICentral group without valid pair",
    "ZRZR/BGBZ": "an EDILine group without valid pair",
    "ZRGR/BZBZ/ZRGZ/BGBZ": "EDICentral and EDILine groups without valid pair",
    "GZGR/BGZZ/GRGR/BZBG": "a candidate covered by one invalid and one valid SG",
    "ZRZZ/BGZZ/GRGR/ZGZZ": "invalid groups of every kind",
    "ZZZZ/ZZZZ/ZZGR/ZZBZ": "no valid group at all: every gamma 1; sg falls back to the mean",
}
#: tiles where some candidate has NO valid covering semi-gradient (see
#: test_sg_candidate_without_valid_semi_gradient); the last two are the rows()
#: presets: the missing rows hold no colour, so no vertical difference (eqs.
#: 14-15) is valid, SG_N and SG_S are empty, and the candidates straight
#: above and below, (-2, 0) and (2, 0), are covered by no valid SG.
CUSTOM_UNCOVERED = ["ZRGR/BGZG", "ZZGR/ZZBG", "ZRZR/BGZG",
                    "GR/BG/GR/BG/ZZ/ZZ", "RG/GB/RG/GB/ZZ/ZZ"]


@pytest.mark.parametrize("method", WEIGHTED)
@pytest.mark.parametrize("tile", list(CUSTOM_OK))
def test_custom_patterns_match_reference(tile, method):
    p = rz.Pattern(tile)
    d = random_frame(p, (4 * p.period[0] + 3, 4 * p.period[1] + 1), seeded("custom", tile, method))
    for precision in ("float64", "float32"):
        out = run(d, p, method, precision=precision)
        check_contract(out, d, p, 11)
        compare(out, d, p, method, precision)
    if method == "sg" and "invalid and one valid" in CUSTOM_OK[tile]:
        # the 'mean over the valid covering SGs' reading is the one that is tested
        alt = reference_reconstruct(d, p, "sg", sg_invalid="zero")
        assert not np.allclose(alt, reference_reconstruct(d, p, "sg"))


@pytest.mark.parametrize("method", ["bilinear", "bi", "edi_central", "edi_line"])
@pytest.mark.parametrize("tile", CUSTOM_UNCOVERED)
def test_custom_uncovered_patterns_non_sg(tile, method):
    p = rz.Pattern(tile)
    d = random_frame(p, (4 * p.period[0] + 3, 4 * p.period[1] + 1), seeded("unc", tile, method))
    compare(run(d, p, method, precision="float64"), d, p, method, "float64")


@pytest.mark.parametrize("tile", CUSTOM_UNCOVERED)
def test_sg_candidate_without_valid_semi_gradient(tile):
    """A candidate with no valid covering SG gets the mean of all valid SGs (the spec)."""
    p = rz.Pattern(tile)
    d = random_frame(p, (4 * p.period[0] + 3, 4 * p.period[1] + 1), seeded("unc-sg", tile))
    compare(run(d, p, "sg", precision="float64"), d, p, "sg", "float64")


@pytest.mark.parametrize("sg_mode", ["auto", "pure", "combined"])
@pytest.mark.parametrize("tile", CUSTOM_UNCOVERED)
def test_sg_uncovered_rule_matters(tile, sg_mode):
    """The rule is exercised: giving uncovered candidates 0 would change the result."""
    p = rz.Pattern(tile)
    d = random_frame(p, (4 * p.period[0] + 3, 4 * p.period[1] + 1), seeded("unc-pin", tile))
    out = run(d, p, "sg", precision="float64", sg_mode=sg_mode)
    zero = reference_reconstruct(d, p, "sg", sg_mode=sg_mode, sg_uncovered="zero")
    assert not np.allclose(out, zero, **TOL["float64"])
    compare(out, d, p, "sg", "float64", sg_mode=sg_mode)


# -- integer frames ------------------------------------------------------------------------

INT_KINDS = [(np.uint16, 11), (np.uint8, 8), (np.uint16, 16), (np.uint8, 1), (np.uint16, 12)]
INT_IDS = [f"{np.dtype(t).name}-{b}bit" for t, b in INT_KINDS]


def compare_int(out, data, pattern, method, precision, bit_depth, rare=True, **kw):
    """Integer output == floor(ref + 0.5), except +-1 at (near) .5 ties; returns #flips.

    ``rare``: also require the ties to be rare (random data); structured
    frames (checkerboards, 1-bit data) are full of exact .5 ties.
    """
    ref, wsum = reference_reconstruct(data, pattern, method, bit_depth=bit_depth,
                                      return_weight_sum=True, **kw)
    expect = round_half_up(ref)
    diff = out.astype(np.int64) - expect.astype(np.int64)
    frac_gap = np.abs(ref - np.floor(ref) - 0.5)       # distance to the .5 tie
    tol = tol_for(precision, bit_depth)
    near_tie = frac_gap <= tol["rtol"] * np.abs(ref) + tol["atol"]
    if precision == "float32":
        fragile = wsum < WSUM_F32
        if method == "edi_rows":
            fragile |= edi_rows_decision_margin(data, pattern, kw.get("edge_ratio", 0.5)) \
                < MARGIN_F32
    else:
        fragile = np.zeros(data.shape, bool)
    nonfragile = ~fragile
    assert np.abs(diff[nonfragile]).max(initial=0) <= 1
    bad = (diff != 0) & nonfragile & ~near_tie
    if bad.any():
        ys, xs = np.nonzero(bad)
        raise AssertionError(f"{bad.sum()} sites off by one away from a .5 tie, e.g. "
                             f"({ys[0]}, {xs[0]}): C {out[ys[0], xs[0]]} ref {ref[ys[0], xs[0]]!r}")
    n_mis = int(((diff != 0) & nonfragile).sum())
    if rare:
        # float64: only exact ties flip. float32: eq. 7's argument G^2 / 2 sigma^2 (up to
        # ~100 before exp underflows) carries a relative error of ~1e-7 * itself, so the
        # weights are good to ~1e-5 and results to ~0.01-0.02 DN: ~1 % of the rounded
        # values of random data flip (measured 0-1.1 % per method, Mask1 edi_line worst).
        # Counted on the interior: within two pixels of the border the period-shifted
        # extension repeats pixels inside one window, which makes weights pairwise equal
        # and exact .5 ties common (measured: 4 border ties of 288 sites, EDILine ZR/BG).
        inner = np.zeros(data.shape, bool)
        inner[2:-2, 2:-2] = True
        nz = (pattern.z_mask(data.shape) & inner).sum()
        n_in = int(((diff != 0) & nonfragile & inner).sum())
        limit = 0.01 if precision == "float64" else 0.05
        assert n_in <= limit * nz + 1, (n_in, nz)
    return n_mis


def _check_both_precisions(d, p, method, dtype):
    """The contract in float64 and float32, and the reference: exact for float64 frames,
    within compare_int's tolerance for integer ones."""
    for precision in ("float64", "float32"):
        out = run(d, p, method, precision=precision)
        check_contract(out, d, p, 11)
        if dtype == np.float64:
            compare(out, d, p, method, precision)
        else:
            compare_int(out, d, p, method, precision, 11, rare=False)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("kind", INT_KINDS, ids=INT_IDS)
@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_integer_frames_round_half_up(pname, method, kind, precision):
    dtype, bd = kind
    p = ALL_PATTERNS[pname]()
    d = random_frame(p, (31, 36), seeded("int", pname, method, bd), dtype=dtype, bit_depth=bd)
    out = run(d, p, method, bit_depth=bd, precision=precision)
    check_contract(out, d, p, bd)
    compare_int(out, d, p, method, precision, bd, rare=bd >= 8)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_kodak_uint16(pname, method):
    p = ALL_PATTERNS[pname]()
    frame = rz.mosaic(kodak(KODAK[0]), p, bit_depth=11, dtype=np.uint16)
    for precision in ("float64", "float32"):
        out = recon(frame, method, precision=precision)
        check_contract(out, frame.data, p, 11)
        compare_int(out, frame.data, p, method, precision, 11)


# -- output contract ------------------------------------------------------------------------

@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32, np.float64])
@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_output_contract(pname, method, dtype):
    """Shape, dtype, colour sites, range, finiteness; RawFrame == plain array; input untouched."""
    p = ALL_PATTERNS[pname]()
    bd = 8 if dtype == np.uint8 else 11
    d = random_frame(p, (19, 26), seeded("contract", pname, method), dtype=dtype, bit_depth=bd)
    keep = d.copy()
    frame = rz.RawFrame(d, p, bd)
    for precision in ("float32", "float64"):
        for domain in DOMAINS:
            out = recon(frame, method, precision=precision, domain=domain)
            check_contract(out, d, p, bd)
            assert out is not d and not np.shares_memory(out, d)
            np.testing.assert_array_equal(
                out, run(d, p, method, bit_depth=bd, precision=precision, domain=domain))
    np.testing.assert_array_equal(d, keep)           # input untouched


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_values_at_z_sites_are_ignored(pname, method):
    p = ALL_PATTERNS[pname]()
    clean = random_frame(p, (22, 25), seeded("junk", pname, method))
    junk = clean.copy()
    z = p.z_mask(clean.shape)
    junk[z] = seeded("junk2", pname).uniform(0, 2047, z.sum())
    np.testing.assert_array_equal(run(clean, p, method), run(junk, p, method))


def test_no_z_pattern_is_a_copy():
    p = rz.bayer("RGGB")
    d = random_frame(p, (8, 10), seeded("bayer"))
    for method in WEIGHTED:
        out = run(d, p, method)
        np.testing.assert_array_equal(out, d)
        assert not np.shares_memory(out, d)


# -- extremes -------------------------------------------------------------------------------

FLAT_KINDS = [(np.uint8, 8), (np.uint16, 11), (np.uint16, 16), (np.float32, 11),
              (np.float64, 11), (np.float64, 16)]
FLAT_IDS = [f"{np.dtype(t).name}-{b}bit" for t, b in FLAT_KINDS]


@pytest.mark.parametrize("kind", FLAT_KINDS, ids=FLAT_IDS)
@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_constant_frame_is_exactly_flat(pname, method, kind):
    """All-zero, mid-grey and all-saturated frames come back exactly flat (every domain)."""
    dtype, bd = kind
    p = ALL_PATTERNS[pname]()
    top = top_of(bd)
    for value in (0, 1 << (bd - 1), top):
        for shape in [(13, 17), p.period]:
            d = np.full(shape, value, dtype=dtype)
            d[p.z_mask(shape)] = 0
            expected = np.full(shape, value, dtype=dtype)
            for precision in ("float32", "float64"):
                for exp in ("libm", "fast"):
                    for domain in DOMAINS:
                        out = run(d, p, method, bit_depth=bd, precision=precision, exp=exp,
                                  domain=domain)
                        assert out.dtype == d.dtype
                        np.testing.assert_array_equal(out, expected, err_msg=f"{value} {domain}")
            ref = reference_reconstruct(d, p, method, bit_depth=bd)
            np.testing.assert_array_equal(ref, expected.astype(np.float64))


NON_DYADIC_CASES = [pytest.param(pn, m, id=f"{pn}-{m}") for pn, m in CASES]


@pytest.mark.parametrize("pname, method", NON_DYADIC_CASES)
@pytest.mark.parametrize("domain", DOMAINS)
def test_constant_float_frame_non_dyadic_value_is_flat(pname, method, domain):
    """A constant that is not a short binary fraction (top / 3, 77.7) stays exactly flat.

    With the weighted mean written c0 + sum w (c - c0) / sum w, and in the
    colour-difference domain the other-channel estimates t0 + sum w (t - t0),
    the result is exact in any precision: float64 gives the constant, float32
    arithmetic gives it rounded to float32 (the frame's value cast to float32).
    A plain weighted mean sum w c / sum w is not: a float64 frame of 77.7 would
    come out an ulp high at the Mask2 Z sites, and float32 frames an ulp low.
    """
    p = ALL_PATTERNS[pname]()
    for value in (2047 / 3, 77.7, 0.1):
        d = np.full((13, 17), value)
        d[p.z_mask(d.shape)] = 0
        z = p.z_mask(d.shape)
        out = run(d, p, method, precision="float64", domain=domain)
        assert np.all(out == value), value
        out = run(d, p, method, precision="float32", domain=domain)
        assert np.all(out[z] == float(np.float32(value))), value
        out = run(d.astype(np.float32), p, method, precision="float32", domain=domain)
        assert np.all(out == np.float32(value)), value


@pytest.mark.parametrize("pname", ["mask2", "mask1"])
def test_bilinear_non_dyadic_constant_is_flat_to_a_few_ulp(pname):
    """The flatness failure above stays at the rounding level."""
    p = PATTERNS[pname]()
    d = np.full((9, 11), 1023.37)
    d[p.z_mask(d.shape)] = 0
    np.testing.assert_allclose(run(d, p, "bilinear", precision="float64"), 1023.37,
                               rtol=1e-15, atol=0)
    np.testing.assert_allclose(run(d, p, "bilinear", precision="float32"), 1023.37,
                               rtol=1e-7, atol=0)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("dtype", [np.float64, np.uint16])
def test_single_hot_pixel(pname, method, dtype):
    p = ALL_PATTERNS[pname]()
    shape = (16, 18)
    chan = p.channel_map(shape)
    colour = np.argwhere(chan != rz.Z)
    rng = seeded("hot", pname, method)
    for y, x in colour[rng.choice(len(colour), 6, replace=False)]:
        d = np.zeros(shape, dtype)
        d[y, x] = 2047
        _check_both_precisions(d, p, method, dtype)


def _line_image(shape, col):
    img = np.zeros(shape + (3,), np.uint8)
    img[:, col] = 255
    return img


@pytest.mark.parametrize("method", WEIGHTED)
def test_fig22_one_pixel_line_through_mask1_z_column(method):
    """Paper Fig. 22: a 1-px white line on a Mask1 Z column cannot be recovered.

    GRBG Mask1 has Z at (even, even): column 8 holds only Z and blue sites, and
    every candidate green (+-1, +-1) lies off the line, so the line's missing
    greens come out black with every method.
    """
    p = rz.mask1()
    frame = rz.mosaic(_line_image((24, 24), 8), p, dtype=np.float64)
    for precision in ("float64", "float32"):
        out = recon(frame, method, precision=precision)
        check_contract(out, frame.data, p, 11)
        compare(out, frame.data, p, method, precision)
        assert np.all(out[::2, 8] == 0)
    # the line beside a Z column (column 9: red / green sites) is a proper edge case too
    frame = rz.mosaic(_line_image((24, 24), 9), p, dtype=np.float64)
    for precision in ("float64", "float32"):
        out = recon(frame, method, precision=precision)
        compare(out, frame.data, p, method, precision)
    frame16 = rz.mosaic(_line_image((24, 24), 9), p, dtype=np.uint16)
    compare_int(recon(frame16, method, precision="float64"), frame16.data, p, method,
                "float64", 11, rare=False)


@pytest.mark.parametrize("method", WEIGHTED)
@pytest.mark.parametrize("corner", [(4, 4), (5, 5), (4, 6), (6, 4), (8, 9)])
def test_fig24_corner_on_mask2_z_block(method, corner):
    """Paper Fig. 24: the corner of a bright square sitting on a Mask2 Z block."""
    p = rz.mask2()
    img = np.full((24, 24, 3), 20, np.uint8)
    img[corner[0]:, corner[1]:] = (250, 180, 60)
    for dtype in (np.float64, np.uint16):
        frame = rz.mosaic(img, p, dtype=dtype)
        for precision in ("float64", "float32"):
            out = recon(frame, method, precision=precision)
            check_contract(out, frame.data, p, 11)
            if dtype == np.float64:
                compare(out, frame.data, p, method, precision)
            else:
                compare_int(out, frame.data, p, method, precision, 11, rare=False)


def _checkerboards(shape):
    yy, xx = np.indices(shape)
    return {"pixel": (yy + xx) % 2, "2x2": (yy // 2 + xx // 2) % 2, "3x3": (yy // 3 + xx // 3) % 2,
            "rows": yy % 2, "cols": xx % 2, "4x1": (yy // 4 + xx) % 2}


@pytest.mark.parametrize("board", list(_checkerboards((2, 2))))
@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_checkerboards(pname, method, board):
    p = ALL_PATTERNS[pname]()
    shape = (24, 26)
    b = _checkerboards(shape)[board]
    for dtype in (np.float64, np.uint16):
        d = (b * 2047).astype(dtype)
        d[p.z_mask(shape)] = 0
        _check_both_precisions(d, p, method, dtype)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("content", ["uniform", "binary", "sparse"])
def test_full_16bit_range(pname, method, content):
    p = ALL_PATTERNS[pname]()
    shape = (26, 30)
    rng = seeded("16bit", pname, method, content)
    if content == "uniform":
        d = rng.uniform(0, 65535, shape)
    elif content == "binary":                  # the largest gradients there are
        d = rng.integers(0, 2, shape) * 65535.0
    else:                                      # mostly 0, a few saturated pixels
        d = (rng.random(shape) < 0.05) * 65535.0
    d[p.z_mask(shape)] = 0
    for dtype in (np.float64, np.uint16):
        dd = d.astype(dtype)
        for precision in ("float64", "float32"):
            for exp in ("libm", "fast"):
                out = run(dd, p, method, bit_depth=16, precision=precision, exp=exp)
                check_contract(out, dd, p, 16)           # finite, in range
                if exp == "fast":
                    continue
                if dtype == np.float64:
                    compare(out, dd, p, method, precision, bit_depth=16)
                else:
                    compare_int(out, dd, p, method, precision, 16, rare=content == "uniform")


# -- threads --------------------------------------------------------------------------------

@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
@pytest.mark.parametrize("dtype", [np.float64, np.uint16])
def test_workers_give_identical_results(pname, method, dtype):
    p = ALL_PATTERNS[pname]()
    d = random_frame(p, (67, 45), seeded("workers", pname, method), dtype=dtype)
    for precision in ("float32", "float64"):
        base = run(d, p, method, precision=precision, workers=1)
        for w in (2, 3, None, -1):
            np.testing.assert_array_equal(run(d, p, method, precision=precision, workers=w), base)


# -- bad input (more in tests/reconstruction/test_contract.py) ----------------------------

@pytest.mark.parametrize("pname", ["mask2", "mask2_bggr"])
def test_edi_rows_applies_to_mask2(pname):
    """The rule 'the ten taps are non-Z pixels of the target colour' holds on Mask2.

    Rows +-2 of a Mask2 Z block are whole Bayer rows, so edi_rows applies
    (docs/guide/interpretation.md lists Mask2 among the patterns that raise; its own
    rule says otherwise). C and reference agree that it applies and on the values.
    """
    p = PATTERNS[pname]()
    d = random_frame(p, (21, 23), seeded("rows-mask2", pname))
    for precision in ("float64", "float32"):
        compare(run(d, p, "edi_rows", precision=precision), d, p, "edi_rows", precision)


def test_reference_raises_where_the_kernel_does():
    with pytest.raises(ValueError, match="candidate"):
        reference_reconstruct(np.zeros((8, 8)), rz.Pattern("ZZ/ZG"), "sg")
    with pytest.raises(ValueError, match="edi_rows"):
        reference_reconstruct(np.zeros((8, 8)), rz.mask1(), "edi_rows")


# -- fast exponential -------------------------------------------------------------------------

@pytest.mark.parametrize("precision", ["float64", "float32"])
@pytest.mark.parametrize("pname", list(PATTERNS))
@pytest.mark.parametrize("n", KODAK)
def test_fast_exp_matches_libm(n, pname, precision):
    """exp="fast" agrees with libm to rtol 1e-5, except where every weight is subnormal.

    The fast exponential flushes results below the normal range to 0 while
    libm returns subnormals, so sites whose weights are all that small fall
    back to the plain mean with one and not with the other. The atol covers
    values next to 0 (1e-3 DN in float32, as TOL).
    """
    p = PATTERNS[pname]()
    frame = rz.mosaic(kodak(n), p, bit_depth=11, dtype=np.float64)
    nz = p.z_mask(frame.shape).sum()
    for method in ("edi_central", "edi_line", "sg", "bi"):
        _, wsum = reference_reconstruct(frame.data, p, method, return_weight_sum=True)
        subnormal = (wsum > 0) & (wsum < (WSUM_F32 if precision == "float32" else 1e-290))
        a = recon(frame, method, precision=precision)
        b = recon(frame, method, precision=precision, exp="fast")
        keep = ~subnormal
        np.testing.assert_allclose(b[keep], a[keep], rtol=1e-5, atol=TOL[precision]["atol"])
        assert (a != b)[subnormal].sum() <= 0.02 * nz, ((a != b)[subnormal].sum(), nz)


@pytest.mark.parametrize("sigma_rel", [0.0, 0.25, 1.0])
@pytest.mark.parametrize("method", ["edi_central", "edi_line", "sg"])
@pytest.mark.parametrize("pname", ["mask1", "mask2"])
def test_relative_sigma_floor_matches_reference(pname, method, sigma_rel):
    p = rz.get_pattern(pname)
    d = random_frame(p, (29, 34), seeded("rel", pname, method, sigma_rel))
    out = run(d, p, method, precision="float64", sigma_rel=sigma_rel)
    compare(out, d, p, method, "float64", sigma_rel=sigma_rel)


@pytest.mark.parametrize("method", ["bi", "edi_central", "edi_line", "sg"])
@pytest.mark.parametrize("pname", ["mask1", "mask2", "mask2_rggb", "ZR/BG"])
def test_colour_difference_domain_matches_reference(pname, method):
    """Eq. 5 generalised: weights from the intensities, interpolation of colour differences."""
    p = rz.get_pattern(pname)
    d = random_frame(p, (27, 30), seeded("cd", pname, method))
    out = run(d, p, method, precision="float64", domain="colour_difference")
    compare(out, d, p, method, "float64", domain="colour_difference")


@pytest.mark.parametrize("precision", ["float32", "float64"])
@pytest.mark.parametrize("sg_mode", ["auto", "combined"])
@pytest.mark.parametrize("method", ["bilinear", "bi", "edi_central", "edi_line", "sg"])
@pytest.mark.parametrize("pname", ["mask1", "mask1_rggb", "mask1_bggr", "mask1_gbrg"])
def test_mask1_fast_path_equals_generic_interpreter(pname, method, sg_mode, precision):
    """csrc/recon_mask1.h (the constant plans) against the plans of _plans.py, same options."""
    from rgbz_fast.reconstruction import _reconstruct as R

    p = rz.get_pattern(pname)
    assert R.has_mask1_geometry(p)
    for dtype in (np.uint16, np.float64):
        d = random_frame(p, (23, 30), seeded("fast", pname, method, sg_mode))
        d = np.floor(d).astype(dtype) if dtype == np.uint16 else d
        fast = rz.reconstruct(d, method, pattern=p, precision=precision, sg_mode=sg_mode)
        with R.plans_only():
            slow = rz.reconstruct(d, method, pattern=p, precision=precision, sg_mode=sg_mode)
        if dtype == np.uint16:
            assert np.max(np.abs(fast.astype(int) - slow.astype(int))) <= 1
        else:
            np.testing.assert_allclose(fast, slow, rtol=1e-12 if precision == "float64" else 1e-5,
                                       atol=1e-9 if precision == "float64" else 1e-3)


def test_plans_only_is_scoped_to_its_block_and_thread():
    """plans_only() switches the fast path off inside the block, in its thread only."""
    import threading

    from rgbz_fast.reconstruction import _reconstruct as R

    p = rz.mask1()
    assert R.runs_mask1_fast_path(p, "sg", "intensity")
    assert not R.runs_mask1_fast_path(p, "sg", "colour_difference")
    seen = []
    with R.plans_only():
        assert not R.runs_mask1_fast_path(p, "sg", "intensity")
        t = threading.Thread(target=lambda: seen.append(R.runs_mask1_fast_path(
            p, "sg", "intensity")))
        t.start()
        t.join()
    assert seen == [True] and R.runs_mask1_fast_path(p, "sg", "intensity")
    with pytest.raises(ZeroDivisionError), R.plans_only():
        1 / 0
    assert R.runs_mask1_fast_path(p, "sg", "intensity")


def test_mask1_geometry_detection():
    from rgbz_fast.reconstruction._reconstruct import has_mask1_geometry

    assert all(has_mask1_geometry(rz.mask1(ph)) for ph in rz.BAYER_PHASES)
    assert not has_mask1_geometry(rz.mask2())
    assert not has_mask1_geometry(rz.Pattern("GZ/BG"))     # Z stands in for red
    assert not has_mask1_geometry(rz.bayer())


# -- out= ------------------------------------------------------------------------------------
@pytest.mark.parametrize("pname", ["mask1", "mask2"])
@pytest.mark.parametrize("dtype", [np.uint16, np.float32])
def test_out_buffer_is_reused_and_equals_a_new_result(pname, dtype):
    p = rz.get_pattern(pname)
    d = random_frame(p, (24, 32), seeded("out", pname, str(dtype)))
    d = np.floor(d).astype(dtype)
    expect = rz.reconstruct(d, "sg", pattern=p)
    buf = np.full(d.shape, 7, dtype)
    got = rz.reconstruct(d, "sg", pattern=p, out=buf)
    assert got is buf
    np.testing.assert_array_equal(buf, expect)
    # a second frame into the same buffer: no trace of the first
    d2 = d[::-1].copy()
    np.testing.assert_array_equal(rz.reconstruct(d2, "sg", pattern=p, out=buf),
                                  rz.reconstruct(d2, "sg", pattern=p))


def test_out_rejected_and_left_untouched():
    p = rz.get_pattern("mask1")
    d = np.floor(random_frame(p, (8, 8), seeded("out-bad"))).astype(np.uint16)
    cases = [(np.zeros((8, 9), np.uint16), ValueError, "out: expected shape"),
             (np.zeros((8, 8), np.float32), ValueError, "out: expected shape"),
             (np.zeros((8, 16), np.uint16)[:, ::2], ValueError, "out: expected a C-contiguous"),
             ([[0] * 8] * 8, TypeError, "out: expected a numpy array"),
             (d, ValueError, "out: overlaps")]
    ro = np.zeros((8, 8), np.uint16)
    ro.flags.writeable = False
    cases.append((ro, ValueError, "out: expected a C-contiguous, writeable"))
    for buf, exc, msg in cases:
        before = np.array(buf, copy=True)
        with pytest.raises(exc, match=msg):
            rz.reconstruct(d, "sg", pattern=p, out=buf)
        np.testing.assert_array_equal(np.asarray(buf), before)
    # an error after the checks of out (a method that does not apply): out untouched
    buf = np.full((8, 8), 3, np.uint16)
    with pytest.raises(ValueError):
        rz.reconstruct(d, "edi_rows", pattern=p, out=buf)
    assert (buf == 3).all()


@pytest.mark.parametrize("tile", ["GRZZ/BGZZ/ZZZZ/ZZZZ", "GRGRZZ/BGBGZZ/GRGRZZ/BGBGZZ/ZZZZZZ/ZZZZZZ"])
@pytest.mark.parametrize("method", ["sg", "edi_line"])
def test_plan_without_any_pair_agrees_with_reference(tile, method):
    """Sparse patterns where a site's plan has gradient families but no valid pair at all:
    every gamma is 1, and no gamma is read before it is written (SG included)."""
    from rgbz_fast.reconstruction._plans import build_plans

    p = rz.Pattern(tile)
    _, plans = build_plans(p, "sg", "auto", "intensity")
    assert any(pl["n_pairs"] == 0 and pl["use_sg"] for pl in plans)
    d = random_frame(p, (24, 24), seeded("nopairs", tile, method))
    for precision in ("float64", "float32"):
        out = run(d, p, method, precision=precision)
        compare(out, d, p, method, precision)
        np.testing.assert_array_equal(out, run(d, p, method, precision=precision))
