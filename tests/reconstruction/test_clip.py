"""reconstruct(clip_level=...): clipped (saturated) pixels kept out of the weights.

The rules are in docs/guide/raw.md ("Near clipping") and docs/guide/interpretation.md; the
NumPy reference (tests/_reference/reconstruction.py, ``clip_level=``) is written from them.
Here: C against the reference on random frames with random clipped regions
(every pattern and method where it applies, float and integer frames, both
domains); the rule itself, that a difference between a clipped and an
unclipped pixel is used and one between two clipped pixels is not (beta and
the semi-gradients, by hand; isolated clipped pixels change nothing);
``clip_level=None`` and a level above the data are bit-identical to the call
without it; saturated areas stay saturated; the openISP frame of
../shared/data/raw (skipped when absent); "auto", frame_clip_level, evaluate
and the CLI.
"""

from __future__ import annotations

import zlib

import numpy as np
import pytest


import rgbz_fast as rz  # noqa: E402
from _reference.reconstruction import (edi_rows_decision_margin, reference_reconstruct,  # noqa: E402
                        round_half_up)
from _support import TOL, shared_path  # noqa: E402
from rgbz_fast.reconstruction import _reconstruct as R  # noqa: E402
from rgbz_fast.reconstruction._plans import build_plans  # noqa: E402
from rgbz_fast import io as rio  # noqa: E402
from rgbz_fast.io import clipped_mask, frame_clip_level, read_raw, to_rgbz  # noqa: E402

WEIGHTED = ("bilinear", "bi", "edi_central", "edi_line", "sg")
PATTERNS = ("mask1", "mask2", "mask1_rggb", "mask2_bggr", "ZR/BG", "GRGR/BGZG",
            "ZRZR/BGBZ", "ZRGR/BGZG")
CASES = ([(p, m) for p in PATTERNS for m in WEIGHTED]
         + [(p, "edi_rows") for p in ("rows", "rows_rggb", "mask2")])
IDS = [f"{p}-{m}" for p, m in CASES]
TOP = 2047
#: float64 weight sum below which float32 weights are in the underflow range
WSUM_F32 = 1e-30
RAW_ARGS = dict(shape=(1080, 1920), phase="RGGB", black_level=0, bit_depth_in=10,
                clip_level=1020)


@pytest.fixture
def plans_only():
    """Every site on the plans of _plans.py: the clipped call (which never takes the Mask1
    fast path) and the unclipped one run the same code, so they compare bit for bit."""
    with R.plans_only():
        yield


def seeded(*key):
    return np.random.default_rng(zlib.crc32(repr(key).encode()))


def clipped_frame(pattern, shape, rng, level, dtype=np.float64):
    """Random data with clipped blobs: flat at the level, above it, and isolated pixels."""
    d = rng.uniform(0, level, shape)
    for k in range(6):
        y, x = rng.integers(0, shape[0]), rng.integers(0, shape[1])
        h, w = rng.integers(1, 9, 2)
        blob = d[y:y + h, x:x + w]
        blob[...] = level if k % 2 else rng.uniform(level, TOP, blob.shape)
    d[rng.random(shape) < 0.04] = level
    if np.issubdtype(np.dtype(dtype), np.integer):
        d = np.floor(d)
    d = d.astype(dtype)
    d[pattern.z_mask(shape)] = 0
    return d


def recon(d, p, m, **kw):
    return rz.reconstruct(d, m, pattern=p, domain=kw.pop("domain", "intensity"), **kw)


def compare(out, d, p, m, precision, level, **kw):
    """C (float frame) against the reference; float32 may differ at fragile sites only."""
    ref, wsum = reference_reconstruct(d, p, m, clip_level=level, return_weight_sum=True, **kw)
    bad = ~np.isclose(out.astype(np.float64), ref, **TOL[precision])
    if precision == "float32":
        bad &= ~(wsum < WSUM_F32)
        if m == "edi_rows":
            bad &= ~(edi_rows_decision_margin(d, p, clip_level=level) < 1e-5)
    if bad.any():
        ys, xs = np.nonzero(bad)
        raise AssertionError(f"{bad.sum()} sites differ, e.g. ({ys[0]}, {xs[0]}): C "
                             f"{out[ys[0], xs[0]]!r} ref {ref[ys[0], xs[0]]!r}")
    return ref


# -- C against the reference ---------------------------------------------------------------

@pytest.mark.parametrize("pname, method", CASES, ids=IDS)
@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_random_clipped_frames_match_reference(pname, method, precision):
    p = rz.get_pattern(pname)
    rng = seeded("clip", pname, method)
    for shape, level in (((37, 41), 1500.0), ((4 * p.period[0] + 3, 4 * p.period[1] + 1), 900.5)):
        d = clipped_frame(p, shape, rng, level)
        out = recon(d, p, method, precision=precision, clip_level=level)
        assert (out[~p.z_mask(shape)] == d[~p.z_mask(shape)]).all()
        compare(out, d, p, method, precision, level)
        # the rule is exercised: the result differs from the one that ignores clipping
        if method != "bilinear":
            assert not np.array_equal(out, recon(d, p, method, precision=precision))


@pytest.mark.parametrize("method", ["bi", "edi_central", "edi_line", "sg"])
@pytest.mark.parametrize("pname", ["mask1", "mask2", "mask2_rggb"])
def test_colour_difference_domain_matches_reference(pname, method):
    p = rz.get_pattern(pname)
    d = clipped_frame(p, (29, 34), seeded("clip-cd", pname, method), 1700.0)
    out = recon(d, p, method, precision="float64", clip_level=1700.0, domain="colour_difference")
    compare(out, d, p, method, "float64", 1700.0, domain="colour_difference")


@pytest.mark.parametrize("sg_mode", ["pure", "combined"])
@pytest.mark.parametrize("pname", ["mask1", "mask2"])
def test_sg_modes_match_reference(pname, sg_mode):
    p = rz.get_pattern(pname)
    d = clipped_frame(p, (29, 34), seeded("clip-sg", pname, sg_mode), 1300.0)
    out = recon(d, p, "sg", precision="float64", clip_level=1300.0, sg_mode=sg_mode)
    compare(out, d, p, "sg", "float64", 1300.0, sg_mode=sg_mode)


@pytest.mark.parametrize("pname, method", CASES, ids=IDS)
def test_integer_frames_round_half_up(pname, method):
    p = rz.get_pattern(pname)
    d = clipped_frame(p, (31, 36), seeded("clip-int", pname, method), 1800, dtype=np.uint16)
    for precision in ("float64", "float32"):
        out = recon(d, p, method, precision=precision, clip_level=1800)
        ref, wsum = reference_reconstruct(d, p, method, clip_level=1800, return_weight_sum=True)
        diff = out.astype(np.int64) - round_half_up(ref).astype(np.int64)
        fragile = (wsum < WSUM_F32) if precision == "float32" else np.zeros(d.shape, bool)
        if method == "edi_rows" and precision == "float32":
            fragile |= edi_rows_decision_margin(d, p, clip_level=1800) < 1e-5
        assert np.abs(diff[~fragile]).max() <= 1           # +-1 only at .5 ties
        assert (diff[~fragile] != 0).mean() < (0.01 if precision == "float64" else 0.05)


# -- the rule: which differences count --------------------------------------------------------

@pytest.mark.parametrize("pname, method", CASES, ids=IDS)
def test_isolated_clipped_pixels_change_nothing(pname, method, plans_only):
    """No difference joins two clipped pixels: every clipped-unclipped difference is used
    as it is (a lower bound of the true one), so the result is the unclipped one, exactly."""
    p = rz.get_pattern(pname)
    rng = seeded("isolated", pname, method)
    shape, level = (62, 66), 1500
    z = p.z_mask(shape)
    for dtype in (np.uint16, np.float64):
        d = rng.uniform(0, level - 1, shape)
        # one clipped colour pixel per 12 x 12 cell (at least 10 px apart), 12 px from the
        # border: no 5x5 or 5x9 window (nor a tap moved back across the border) holds two
        n = 0
        for y in range(12, shape[0] - 12, 12):
            for x in range(12, shape[1] - 12, 12):
                for k in rng.permutation(9):                    # a colour pixel near it
                    yy, xx = y + k // 3, x + k % 3
                    if not z[yy, xx]:
                        d[yy, xx] = rng.uniform(level, TOP)
                        n += 1
                        break
        assert n == 16
        d = (np.floor(d) if dtype == np.uint16 else d).astype(dtype)
        d[z] = 0
        for precision in ("float32", "float64"):
            np.testing.assert_array_equal(recon(d, p, method, precision=precision,
                                                clip_level=level),
                                          recon(d, p, method, precision=precision))
        if dtype == np.float64:
            compare(recon(d, p, method, precision="float64", clip_level=level), d, p, method,
                    "float64", level)


def _mask1_site(level, rng):
    """A Mask1 frame below the level and its centre Z site (y, x); (0, +-1) red, (+-1, 0)
    blue, (+-1, +-1) the four green candidates."""
    p = rz.mask1()
    d = rng.uniform(200, level - 300, (20, 20))
    d[p.z_mask(d.shape)] = 0
    return p, d, 10, 10


def test_beta_skips_only_the_terms_between_two_clipped_candidates():
    """BI on Mask1 (four diagonal candidates, equal alpha): beta by hand from eq. 4 with
    the clipped-clipped term left out and the clipped candidates' sums rescaled to 3 terms."""
    level = 1500.0
    p, d, y, x = _mask1_site(level, seeded("beta"))
    pos = [(-1, -1), (-1, 1), (1, -1), (1, 1)]
    c = np.array([1510.0, 1900.0, 1300.0, 1420.0])        # two clipped, two not
    for (dy, dx), v in zip(pos, c):
        d[y + dy, x + dx] = v
    clipped = c >= level
    S = np.ones(4)
    for k in range(4):
        terms = [abs(c[k] - c[m]) for m in range(4) if m != k and not (clipped[k] and clipped[m])]
        S[k] = 1 + 3 / len(terms) * sum(terms)
    assert S[0] == 1 + 1.5 * (210 + 90)                   # |1510 - 1900| not in it
    expect = np.sum(c / S) / np.sum(1 / S)
    out = recon(d, p, "bi", precision="float64", clip_level=level)
    np.testing.assert_allclose(out[y, x], expect, rtol=1e-12)
    # without clip handling |1510 - 1900| counts; leaving out every term with a clipped
    # pixel (not only clipped-clipped ones) would give the two clipped candidates the beta
    # of the least trusted unclipped one, which is far from the expected value
    full = 1 + np.abs(c[:, None] - c[None, :]).sum(axis=1)
    assert abs(recon(d, p, "bi", precision="float64")[y, x] - np.sum(c / full) / np.sum(1 / full)) < 1e-9
    old = np.array([1 + 3 * 120.0] * 4)
    assert abs(expect - np.sum(c / old) / np.sum(1 / old)) > 10


def test_semi_gradients_use_clipped_unclipped_but_not_clipped_clipped_differences():
    """SG on Mask1 (pure: every semi-gradient difference is red-red or blue-blue, the
    candidates are green). All red and blue pixels of the window clipped: no semi-gradient
    is known, the output is the candidates' mean whatever the clipped values are. One red
    pixel unclipped: its differences to the clipped reds are lower bounds that count, so
    the output moves with a clipped red value."""
    level = 1500.0
    rng = seeded("sg-rule")
    p, d, y, x = _mask1_site(level, rng)
    chan = p.channel_map(d.shape)
    win = np.zeros(d.shape, bool)
    win[y - 2:y + 3, x - 2:x + 3] = True
    rb = win & ((chan == 0) | (chan == 2))
    cand = [d[y + dy, x + dx] for dy in (-1, 1) for dx in (-1, 1)]

    def site(frame):
        return recon(frame, p, "sg", precision="float64", clip_level=level)[y, x]

    outs = []
    for _ in range(3):
        d[rb] = rng.uniform(level, TOP, rb.sum())           # all clipped, values vary
        outs.append(site(d))
    np.testing.assert_allclose(outs, np.mean(cand), rtol=1e-12)
    d[y, x - 1] = level - 400                               # red (0, -1) unclipped
    a = site(d)
    d[y - 2, x - 1] = level + 500                           # its clipped partner (-2, -1)
    b = site(d)
    d[y - 2, x - 1] = TOP
    c = site(d)
    assert len({a, b, c}) == 3, (a, b, c)
    assert all(o != pytest.approx(np.mean(cand), abs=1e-6) for o in (a, b, c))
    for v in (level + 500, TOP):
        d[y - 2, x - 1] = v
        ref = reference_reconstruct(d, p, "sg", clip_level=level)
        assert site(d) == pytest.approx(ref[y, x], rel=1e-9)


# -- no clipping: exactly today's result --------------------------------------------------------

@pytest.mark.parametrize("pname, method", CASES, ids=IDS)
def test_none_and_a_level_above_the_data_are_bit_identical(pname, method):
    """clip_level=None, and a level no colour pixel reaches, change nothing (Mask1 fast path too)."""
    p = rz.get_pattern(pname)
    for dtype in (np.uint16, np.float64):
        d = clipped_frame(p, (26, 30), seeded("same", pname, method), 1600, dtype=dtype)
        hi = float(d[~p.z_mask(d.shape)].max())
        d[p.z_mask(d.shape)] = TOP if dtype == np.uint16 else 2047.0   # Z values never count
        for precision in ("float32", "float64"):
            base = recon(d, p, method, precision=precision)
            for level in (None, hi + 0.5, TOP + 1.0, 1e9):
                np.testing.assert_array_equal(
                    recon(d, p, method, precision=precision, clip_level=level), base)
            if method != "bilinear":
                assert not np.array_equal(recon(d, p, method, precision=precision,
                                                clip_level=1600), base)


@pytest.mark.parametrize("method", WEIGHTED)
@pytest.mark.parametrize("pname", ["mask1", "mask2"])
def test_sites_without_clipped_taps_equal_the_interpreter(pname, method, plans_only):
    """A site none of whose taps is clipped takes the unclipped code: bit-identical."""
    p = rz.get_pattern(pname)
    d = clipped_frame(p, (40, 44), seeded("far", pname, method), 1500, dtype=np.uint16)
    base = recon(d, p, method, precision="float32")
    out = recon(d, p, method, precision="float32", clip_level=1500)
    # (4 px from the border a tap moved back by a period may reach further than 2 px)
    near = clipped_mask(d, 1500, radius=2)
    near[:4], near[-4:], near[:, :4], near[:, -4:] = True, True, True, True
    np.testing.assert_array_equal(out[~near], base[~near])


@pytest.mark.parametrize("method", WEIGHTED)
def test_workers_give_identical_results(method):
    p = rz.mask2()
    d = clipped_frame(p, (67, 45), seeded("workers", method), 1200, dtype=np.uint16)
    base = recon(d, p, method, clip_level=1200, workers=1)
    for w in (2, 3, None):
        np.testing.assert_array_equal(recon(d, p, method, clip_level=1200, workers=w), base)


# -- saturation kept ---------------------------------------------------------------------------

@pytest.mark.parametrize("pname, method", CASES, ids=IDS)
@pytest.mark.parametrize("domain", ["intensity", "colour_difference"])
def test_saturated_areas_stay_saturated(pname, method, domain):
    """Every candidate clipped: the output is at least the smallest of them (>= clip_level)."""
    if method in ("bilinear", "edi_rows") and domain != "intensity":
        pytest.skip("the domain does not apply")
    p = rz.get_pattern(pname)
    shape = (36, 40)
    rng = seeded("sat", pname, method, domain)
    for dtype, level in ((np.uint16, 1900), (np.float64, 1900.25), (np.float32, 1833.3)):
        d = rng.uniform(0, 1000, shape)
        d[8:28, 8:30] = level                                 # flat and saturated
        d[30:, :] = rng.uniform(level, TOP, (shape[0] - 30, shape[1]))   # saturated, textured
        d = (np.floor(d) if dtype == np.uint16 else d).astype(dtype)
        level = dtype(level)
        d[p.z_mask(shape)] = 0
        for precision in ("float32", "float64"):
            out = recon(d, p, method, precision=precision, clip_level=level, domain=domain)
            z = p.z_mask(shape)
            flat = np.zeros(shape, bool)
            flat[12:24, 12:26] = True
            assert (out[flat & z] >= level).all()             # flat saturated: the level
            np.testing.assert_allclose(out[flat & z], level, rtol=1e-6)
            inner = np.zeros(shape, bool)
            inner[32:, :] = True
            assert (out[inner & z] >= level).all()
            # without clip handling the colour-difference domain leaves the saturation
            if domain == "colour_difference" and dtype == np.float64 and precision == "float64":
                ref = reference_reconstruct(d, p, method, clip_level=level, domain=domain)
                np.testing.assert_allclose(out, ref, **TOL["float64"])


# -- the openISP frame --------------------------------------------------------------------------

@pytest.fixture(scope="module")
def openisp():
    f = read_raw(shared_path("raw", "openisp_test.RAW"), **RAW_ARGS)
    return {name: to_rgbz(f, name) for name in ("mask1", "mask2")}


@pytest.mark.parametrize("method", WEIGHTED + ("edi_rows",))
@pytest.mark.parametrize("pname", ["mask1", "mask2"])
def test_openisp_near_clipping(openisp, pname, method):
    """The real clipped chart background: C == reference near it, far sites untouched, and
    the fair measure of docs/guide/raw.md ("Near clipping") is finite on both paths.

    Fair measure: the Z sites whose own reference is not clipped but whose 5x5 window
    holds a clipped pixel (the reference of a clipped site is itself only a lower bound).
    """
    if method == "edi_rows" and pname == "mask1":
        pytest.skip("edi_rows does not apply to Mask1")
    rgbz, ref = openisp[pname]
    level = frame_clip_level(rgbz)
    assert level == 2041.0                                 # raw 1020 of white 1023, 11 bits
    out = rz.reconstruct(rgbz, method, clip_level="auto")
    np.testing.assert_array_equal(out, rz.reconstruct(rgbz, method, clip_level=level))
    base = rz.reconstruct(rgbz, method)
    clip = clipped_mask(rgbz)
    window = clipped_mask(rgbz, radius=4 if method == "edi_rows" else 2)
    z = rgbz.z_mask
    near = window & ~clip & z
    assert near.sum() > 30_000
    window[:4], window[-4:], window[:, :4], window[:, -4:] = True, True, True, True
    # far from clipping: the clip_level=None call's bits (on Mask1 its fast path too)
    np.testing.assert_array_equal(out[~window], base[~window])
    # C against the reference on a block of the frame that holds clipped pixels
    ys, xs = np.nonzero(near)
    y0, x0 = max(ys[len(ys) // 2] - 40, 0), max(xs[len(xs) // 2] - 40, 0)
    y0, x0 = y0 - y0 % 4, x0 - x0 % 4
    sites = np.zeros(z.shape, bool)
    sites[y0:y0 + 96, x0:x0 + 96] = True
    r = reference_reconstruct(rgbz.data, rgbz.pattern, method, clip_level=level, sites=sites)
    s = sites & z
    assert (s & near).sum() > 100
    diff = out[s].astype(np.int64) - round_half_up(r[s]).astype(np.int64)
    assert np.abs(diff).max() <= 1 and (diff != 0).mean() < 0.05
    for o in (base, out):
        e = o[near].astype(np.float64) - ref[near]
        assert np.isfinite(10 * np.log10(TOP ** 2 / np.mean(e ** 2)))


# -- arguments, "auto", frame_clip_level --------------------------------------------------------

@pytest.mark.parametrize("value, exc", [(np.nan, ValueError), (-1.0, ValueError),
                                        (0, ValueError), (np.inf, ValueError),
                                        ("high", TypeError), (True, TypeError),
                                        ([1000], TypeError), (object(), TypeError)])
def test_bad_clip_level(value, exc):
    with pytest.raises(exc, match="^clip_level"):
        rz.reconstruct(np.zeros((8, 8)), pattern="mask1", clip_level=value)


def test_auto_uses_the_raw_level_and_nothing_else():
    p = rz.mask1("RGGB")
    d = clipped_frame(p, (20, 24), seeded("auto"), 1900, dtype=np.uint16)
    meta = {"black_level": (0.0,) * 4, "white_level": (1023.0,) * 4,
            "clip_level": (950.0,) * 4}
    level = float(np.floor(950 / 1023 * 2047 + 0.5))
    f = rz.RawFrame(d, p, meta=meta)
    assert frame_clip_level(f) == level
    np.testing.assert_array_equal(rz.reconstruct(f, "sg", clip_level="auto"),
                                  rz.reconstruct(f, "sg", clip_level=level))
    # no levels recorded, or a plain array: "auto" is no clip handling
    for frame, kw in ((rz.RawFrame(d, p), {}), (d, {"pattern": p})):
        np.testing.assert_array_equal(rz.reconstruct(frame, "sg", clip_level="auto", **kw),
                                      rz.reconstruct(frame, "sg", **kw))


def test_frame_clip_level_scaling():
    p = rz.bayer("RGGB")
    meta = {"black_level": (64.0, 60.0, 60.0, 64.0), "white_level": (1023.0,) * 4,
            "clip_level": (1023.0,) * 4}
    assert frame_clip_level(rz.RawFrame(np.zeros((4, 4), np.uint16), p, meta=meta)) == 2047.0
    meta["clip_level"] = (1000.0,) * 4
    exact = (1000.0 - 64.0) / (1023.0 - 64.0) * 2047        # the smaller of the two
    assert frame_clip_level(rz.RawFrame(np.zeros((4, 4), np.uint16), p, meta=meta)) == \
        np.floor(exact + 0.5)
    assert frame_clip_level(rz.RawFrame(np.zeros((4, 4)), p, meta=meta)) == exact
    assert frame_clip_level(rz.RawFrame(np.zeros((4, 4), np.float32), p, meta=meta)) == \
        float(np.float32(exact))
    assert frame_clip_level(rz.RawFrame(np.zeros((4, 4)), p)) is None
    with pytest.raises(TypeError, match="frame"):
        frame_clip_level(np.zeros((4, 4)))


@pytest.mark.parametrize("dtype", [np.uint16, np.float32, np.float64])
def test_read_raw_level_flags_exactly_the_clipped_pixels(tmp_path, dtype):
    """The level of a headerless file lands on its clipped pixels in every output dtype."""
    rng = np.random.default_rng(3)
    raw = rng.integers(0, 1021, (24, 32)).astype("<u2")
    raw[4:9, 5:12] = 1020
    raw.tofile(tmp_path / "f.raw")
    f = read_raw(tmp_path / "f.raw", shape=(24, 32), phase="GRBG", black_level=12,
                 bit_depth_in=10, clip_level=1019, dtype=dtype)
    level = frame_clip_level(f)
    np.testing.assert_array_equal(f.data >= level, raw >= 1019)


def test_saved_frame_keeps_the_level(tmp_path):
    from rgbz_fast import io as frameio

    p = rz.mask1("RGGB")
    d = clipped_frame(p, (12, 12), seeded("save"), 1900, dtype=np.uint16)
    f = rz.RawFrame(d, p, meta={"black_level": (0.0,) * 4, "white_level": (1023.0,) * 4,
                                "clip_level": (950.0,) * 4})
    g = frameio.load_frame(frameio.save_frame(tmp_path / "f.npz", f))
    assert frame_clip_level(g) == frame_clip_level(f)


def _sites_with_a_clipped_tap(d, p, method, level):
    """Per pixel: a Z site at least 4 pixels from the border one of whose plan's taps (those
    of _plans.py) is at or above the level."""
    phase_map, plans = build_plans(p, method, "auto", "intensity")
    P, Q = p.period
    out = np.zeros(d.shape, bool)
    for y in range(4, d.shape[0] - 4):
        for x in range(4, d.shape[1] - 4):
            k = phase_map[(y % P) * Q + x % Q]
            if k < 0:
                continue
            pl = plans[k]
            out[y, x] = any(d[y + int(pl["tap_dy"][t]), x + int(pl["tap_dx"][t])] >= level
                            for t in range(int(pl["n_taps"])))
    return out


@pytest.mark.parametrize("method", WEIGHTED)
@pytest.mark.parametrize("dtype", [np.uint16, np.float64])
def test_mask1_fast_path_with_a_clip_level(method, dtype):
    """With a clip level the Mask1 fast path still runs: a site with a clipped tap is computed
    again by the clipped-pixel rule on the plans of _plans.py (the bits of the plans-only
    call there), every other site is the clip_level=None call's, bit for bit (the fast path
    and the plans differ in the order of their sums: by rounding, at a few sites)."""
    p = rz.mask1()
    d = clipped_frame(p, (40, 70), seeded("m1clip", method, dtype), 1500, dtype=dtype)
    base = recon(d, p, method, precision="float64")
    out = recon(d, p, method, precision="float64", clip_level=1500)
    with R.plans_only():
        plans_out = recon(d, p, method, precision="float64", clip_level=1500)
    hit = _sites_with_a_clipped_tap(d, p, method, 1500)
    assert hit.sum() > 50
    np.testing.assert_array_equal(out[hit], plans_out[hit])
    inner = np.zeros(d.shape, bool)
    inner[4:-4, 4:-4] = True
    np.testing.assert_array_equal(out[inner & ~hit], base[inner & ~hit])


def test_counting_kernel_rejects_clip_with_the_mask1_fast_path():
    # the counting build keeps the two apart: its counts would hold both cores at a site
    from rgbz_fast import _kernels, _kernels_count

    p = rz.mask1()
    plan_map, plans, n = R._plans_for(p, "sg", "auto", "intensity")
    d = np.zeros((8, 8))
    counts = np.zeros(n * _kernels_count.NOPS, np.uint64)
    with pytest.raises(RuntimeError, match="status 1"):
        _kernels_count.reconstruct(d, np.empty_like(d), 1, 2, 2, plan_map, plans, n, 1e-3,
                                   0.5, 0.5, 2047.0, 0, 1, opcounts=counts, mask1_fast=1,
                                   clip_level=100.0)
    out = np.empty_like(d)                 # the library's kernel takes it
    _kernels.reconstruct(d, out, 1, 2, 2, plan_map, plans, n, 1e-3, 0.5, 0.5, 2047.0, 0, 1,
                         mask1_fast=1, clip_level=100.0)
    assert (out == 0).all()


# -- evaluate and the CLI -----------------------------------------------------------------------

def test_eval_config_clip_level():
    from rgbz_fast.evaluation import EvalConfig

    def cfg(level):
        return EvalConfig(params=rz.ReconstructParams(precision="float64", clip_level=level))

    c = cfg("auto")
    assert EvalConfig().params.clip_level is None           # off by default (docs/guide/raw.md)
    assert c.params.clip_level == "auto"
    assert cfg(2000).params.clip_level == 2000.0
    for bad, exc in (("high", TypeError), (np.nan, ValueError), (-3, ValueError),
                     (True, TypeError)):
        with pytest.raises(exc, match="clip_level"):
            cfg(bad)
    # None (the default) and, for RGB sources, "auto" stay out of the cache key (the key of
    # a run that clips nothing does not depend on the clip option); raw sources key on
    # "auto" and on a level
    off = EvalConfig()
    assert c.key("mask1", "sg") == off.key("mask1", "sg")
    assert off.key("mask1", "sg", raw=True) == off.key("mask1", "sg")
    assert c.key("mask1", "sg", raw=True) != c.key("mask1", "sg")
    assert cfg(2000).key("mask1", "sg") != off.key("mask1", "sg")


def _raw_file(tmp_path):
    rng = np.random.default_rng(7)
    raw = rng.integers(100, 900, (64, 64)).astype("<u2")
    raw[10:30, 20:44] = 1020
    raw[40:50, 5:9] = 1020
    folder = tmp_path / "raw"
    folder.mkdir()
    raw.tofile(folder / "chart.raw")
    return folder


def test_evaluate_raw_source_passes_the_level(tmp_path, monkeypatch):
    import rgbz_fast.evaluation as ev
    import rgbz_fast.evaluation._run as run

    folder = _raw_file(tmp_path)
    opts = {"*": dict(shape=[64, 64], phase="RGGB", black_level=0, bit_depth_in=10,
                      clip_level=1020)}
    ds = rio.folder_dataset(folder, raw_options=opts)
    seen = []
    real = run.reconstruct
    monkeypatch.setattr(run, "reconstruct",
                        lambda f, m, **k: seen.append(R._resolve_clip(k["params"].clip_level, f))
                        or real(f, m, **k))
    kw = dict(processes=1, progress=False, metrics=("cfa_psnr",), methods=("edi_line",),
              patterns=("mask1",))
    on = ev.evaluate(ds, params=rz.ReconstructParams(precision="float64", clip_level="auto"),
                     **kw).values("mask1", "edi_line", "cfa_psnr")
    off = ev.evaluate(ds, **kw).values("mask1", "edi_line", "cfa_psnr")   # the default
    assert seen == [2041.0, None]
    assert on[0] != off[0]


def test_cli_clip_level(tmp_path, capsys):
    import tifffile

    from rgbz_fast import io as frameio
    from rgbz_fast._cli import main

    folder = _raw_file(tmp_path)
    f = read_raw(folder / "chart.raw", shape=(64, 64), phase="RGGB", black_level=0,
                 bit_depth_in=10, clip_level=1020)
    rgbz, _ = to_rgbz(f, "mask1")
    src = frameio.save_frame(tmp_path / "chart.npz", rgbz)
    outs = {}
    for flag in ("auto", "off", "2041", None):
        out = tmp_path / str(flag)
        assert main(["reconstruct", str(src), "--method", "edi_line", "--out", str(out),
                     "--quiet"] + (["--clip-level", flag] if flag else [])) == 0
        outs[flag] = tifffile.imread(out / "chart_edi-line_cfa.tif")
    np.testing.assert_array_equal(outs[None], outs["off"])             # off by default
    np.testing.assert_array_equal(outs["auto"], rz.reconstruct(rgbz, "edi_line",
                                                               clip_level=2041.0))
    np.testing.assert_array_equal(outs["auto"], outs["2041"])
    np.testing.assert_array_equal(outs["off"], rz.reconstruct(rgbz, "edi_line"))
    assert not np.array_equal(outs["auto"], outs["off"])
    with pytest.raises(SystemExit) as e:
        main(["reconstruct", str(src), "--clip-level", "nan"])
    assert e.value.code == 2
    assert "clip-level" in capsys.readouterr().err
