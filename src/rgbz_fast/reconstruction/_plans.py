"""Reconstruction plans, one per Z site of a tile: which kernel pixels each method reads and how.

A *plan* describes the reconstruction of the missing pixels at one Z site of
a pattern's tile (every pixel at that position of the tiled frame): the kernel offsets to gather (taps), the
candidates (known pixels of the target colour) with their distance factor and
orientation, and the pixel pairs whose absolute differences form the
gradients and semi-gradients. The C kernel interprets plans; all the channel
logic (which pixel is which colour, which difference touches a Z pixel) lives
here, once. docs/guide/interpretation.md is the specification.
"""

from __future__ import annotations

import math

import numpy as np

from .. import _kernels
from .._patterns import Pattern, Z, get_pattern
from .._validate import check_choice
from ._params import DOMAINS, SG_MODES, check_domain

__all__ = ["METHODS", "build_plans", "PLAN_DTYPE", "ORIENTATIONS", "SEMI_GRADIENTS"]

#: {method name: code}, from the C enum rgbz_method (csrc/rgbz.h)
METHODS = dict(_kernels.METHODS)
ORIENTATIONS = ("vertical", "horizontal", "diag_nw_se", "diag_ne_sw")
SEMI_GRADIENTS = ("N", "S", "W", "E", "NW", "NE", "SW", "SE")

MAX_TAPS, MAX_CAND, MAX_PAIRS, NGROUPS, MAX_CD = (
    _kernels.PLAN_LIMITS[k] for k in ("max_taps", "max_cand", "max_pairs", "ngroups", "max_cd"))
_SG, _GRAD = 0, 8   # first group index of each family

PLAN_DTYPE = np.dtype([
    ("method", "<i4"), ("n_taps", "<i4"), ("n_cand", "<i4"), ("n_pairs", "<i4"),
    ("use_ab", "<i4"), ("use_grad", "<i4"), ("use_sg", "<i4"), ("sg_scaled", "<i4"),
    ("tap_dy", "<i4", MAX_TAPS), ("tap_dx", "<i4", MAX_TAPS),
    ("cand_tap", "<i4", MAX_CAND), ("cand_ori", "<i4", MAX_CAND),
    ("cand_sgmask", "<i4", MAX_CAND),
    ("pair_a", "<i4", MAX_PAIRS), ("pair_b", "<i4", MAX_PAIRS),
    ("pair_gmask", "<i4", MAX_PAIRS),
    ("target", "<i4"), ("use_cd", "<i4"),
    ("cd_n", "<i4", MAX_CAND + 1), ("cd_tap", "<i4", (MAX_CAND + 1, MAX_CD)),
    ("sum_from_zero", "<i4"), ("gamma_mask", "<i4"),
    ("cand_alpha", "<f8", MAX_CAND), ("cand_sgscale", "<f8", MAX_CAND),
    ("group_scale", "<f8", NGROUPS),
    ("cd_w", "<f8", (MAX_CAND + 1, MAX_CD)),
], align=True)

_LAYOUT_FIELDS = ("method", "use_ab", "tap_dy", "tap_dx", "cand_tap", "cand_ori", "cand_sgmask",
                  "pair_a", "pair_b", "pair_gmask", "target", "use_cd", "cd_n", "cd_tap",
                  "sum_from_zero", "gamma_mask", "cand_alpha", "cand_sgscale", "group_scale",
                  "cd_w")


def check_layout(c_layout):
    """Compare PLAN_DTYPE with the compiled struct (size and offsets)."""
    py = (PLAN_DTYPE.itemsize,) + tuple(PLAN_DTYPE.fields[f][1] for f in _LAYOUT_FIELDS)
    if tuple(c_layout) != py:
        raise ImportError(f"rgbz_fast: the compiled rgbz_plan layout {tuple(c_layout)} differs "
                          f"from the Python one {py}; rebuild the package")


def orientation(dy, dx):
    """Orientation index of a kernel offset: 0 vertical, 1 horizontal, 2 NW-SE, 3 NE-SW."""
    if dx == 0:
        return 0
    if dy == 0:
        return 1
    ang = math.degrees(math.atan2(abs(dy), abs(dx)))   # 0 = horizontal, 90 = vertical
    if ang > 67.5:
        return 0
    if ang < 22.5:
        return 1
    return 2 if dy * dx > 0 else 3


def sg_cover(dy, dx):
    """Indices of the semi-gradients covering a kernel offset (eq. 19, generalised)."""
    s = []
    if dy < 0:
        s.append(0)
    if dy > 0:
        s.append(1)
    if dx < 0:
        s.append(2)
    if dx > 0:
        s.append(3)
    if dy < 0 and dx < 0:
        s.append(4)
    if dy < 0 and dx > 0:
        s.append(5)
    if dy > 0 and dx < 0:
        s.append(6)
    if dy > 0 and dx > 0:
        s.append(7)
    return s


def _window5():
    return [(dy, dx) for dy in range(-2, 3) for dx in range(-2, 3) if (dy, dx) != (0, 0)]


def central_pairs():
    """EDICentral (Fig. 7): per orientation, the centrally symmetric pairs (p, -p) of its area."""
    groups = {o: [] for o in range(4)}
    for dy, dx in _window5():
        if dy > 0 or (dy == 0 and dx > 0):
            groups[orientation(dy, dx)].append(((dy, dx), (-dy, -dx)))
    return groups


def line_pairs():
    """EDILine (eqs. 8-11): per orientation, the mirror pairs across the perpendicular axis."""
    groups = {o: [] for o in range(4)}
    for r in (1, 2):                      # eq. 8: mirror across the horizontal axis
        for c in range(-2, 3):
            groups[0].append(((-r, c), (r, c)))
            groups[1].append(((c, -r), (c, r)))     # eq. 9
    for dy, dx in _window5():
        if dy + dx > 0:                   # eq. 11: mirror across the anti-diagonal
            groups[2].append(((dy, dx), (-dx, -dy)))
        if dy > dx:                       # eq. 10: mirror across the main diagonal
            groups[3].append(((dy, dx), (dx, dy)))
    return groups


def sg_pairs():
    """Semi-gradients (eqs. 14-18): per SG, its differences (centre row/column vs border)."""
    dv, dh = {}, {}
    for j in range(5):
        dv[2 * j] = ((0, j - 2), (-2, j - 2))
        dv[2 * j + 1] = ((0, j - 2), (2, j - 2))
        dh[2 * j] = ((j - 2, 0), (j - 2, -2))
        dh[2 * j + 1] = ((j - 2, 0), (j - 2, 2))
    sets = {
        0: [dv[j] for j in (0, 2, 6, 8)],                 # N  (18a)
        1: [dv[j] for j in (1, 3, 7, 9)],                 # S  (18b)
        2: [dh[j] for j in (0, 2, 6, 8)],                 # W  (18c)
        3: [dh[j] for j in (1, 3, 7, 9)],                 # E  (18d)
        4: [dv[0], dv[2], dh[0], dh[2]],                  # NW (18e)
        5: [dv[6], dv[8], dh[1], dh[3]],                  # NE (18g)
        6: [dv[1], dv[3], dh[6], dh[8]],                  # SW (18h, [4;6] read as [6;8])
        7: [dv[7], dv[9], dh[7], dh[9]],                  # SE (18f)
    }
    return sets


_ROWS_TAPS = [(-2, -4), (2, 4), (-2, -2), (2, 2), (-2, 0), (2, 0), (-2, 2), (2, -2),
              (-2, 4), (2, -4)]


def _sg_mode_pure(cands):
    return all(dy != 0 and dx != 0 for dy, dx in cands)


def colour_difference_estimates(ch, positions, target):
    """Linear estimates of the other channel(s) at each position (eq. 5's I_G, generalised).

    For a green target the other channels are red and blue, for red or blue
    it is green (eq. 5). At a position p, a channel's estimate is the mean of
    its pixels among the 4-neighbours of p; the estimate X_p is the mean of
    the channel estimates. Only channels present around *every* position are
    used, so that X is the same function at the candidates and at the missing
    pixel. Returns a list of {offset: weight} dicts, or None when no channel
    is available everywhere.
    """
    others = (0, 2) if target == 1 else (1,)
    nb4 = ((-1, 0), (1, 0), (0, -1), (0, 1))
    per_pos = []
    for dy, dx in positions:
        d = {}
        for o in others:
            offs = [(dy + a, dx + b) for a, b in nb4 if ch(dy + a, dx + b) == o]
            if offs:
                d[o] = offs
        per_pos.append(d)
    usable = [o for o in others if all(o in d for d in per_pos)]
    if not usable:
        return None
    out = []
    for d in per_pos:
        w: dict[tuple[int, int], float] = {}
        for o in usable:
            for off in d[o]:
                w[off] = w.get(off, 0.0) + 1.0 / (len(d[o]) * len(usable))
        out.append(w)
    return out


def build_plans(pattern: Pattern, method: str, sg_mode: str = "auto",
                domain: str = "intensity"):
    """Return ``(plan_map, plans)`` for ``pattern`` and ``method``.

    plan_map : int32 array of size P*Q, the plan index of each tile site or -1.
    plans : structured array of PLAN_DTYPE.

    Raises ValueError when the method does not apply to the pattern.
    """
    pattern = get_pattern(pattern)
    method = check_choice(method, tuple(METHODS), "method")
    sg_mode = check_choice(sg_mode, SG_MODES, "sg_mode")
    domain = check_choice(domain, DOMAINS, "domain")
    check_domain(method, domain)           # H75: bilinear and edi_rows had ignored it
    P, Q = pattern.period
    tile = pattern.tile
    btile = pattern.bayer_tile()           # raises for patterns with no underlying Bayer
    plan_map = np.full(P * Q, -1, np.int32)
    plans = []

    def ch(r, c, dy, dx):
        return int(tile[(r + dy) % P, (c + dx) % Q])

    for r in range(P):
        for c in range(Q):
            if tile[r, c] != Z:
                continue
            target = int(btile[r, c])
            plan = np.zeros((), PLAN_DTYPE)
            plan["method"] = METHODS[method]
            plan["target"] = target
            # sums from 0, every gamma of a group with differences evaluated: the arithmetic
            # whose operation counts docs/reports/opcount.md reports (csrc/rgbz.h)
            plan["sum_from_zero"] = 1
            taps: dict[tuple[int, int], int] = {}

            def tap(off):
                if off not in taps:
                    if len(taps) >= MAX_TAPS:
                        raise RuntimeError("plan: too many taps")
                    taps[off] = len(taps)
                return taps[off]

            def same(a, b):
                ca, cb = ch(r, c, *a), ch(r, c, *b)
                return ca != Z and ca == cb

            if method == "edi_rows":
                bad = [off for off in _ROWS_TAPS if ch(r, c, *off) != target]
                if bad:
                    raise ValueError(
                        f"method: 'edi_rows' needs the pixels two rows above and below the "
                        f"missing pixel (columns -4..4) to hold its colour; pattern "
                        f"{pattern.name!r} has other channels at {bad[:3]} of tile site ({r}, {c}). "
                        "Use it on row patterns such as rows()")
                for off in _ROWS_TAPS:
                    tap(off)
            else:
                cands = [(dy, dx) for dy, dx in _window5() if ch(r, c, dy, dx) == target]
                if not cands:
                    raise ValueError(
                        f"pattern: the Z site ({r}, {c}) of {pattern.name!r} has no known pixel of "
                        f"its colour ({'RGB'[target]}) in the 5x5 kernel, so {method!r} cannot "
                        "reconstruct it")
                plan["n_cand"] = len(cands)
                for k, (dy, dx) in enumerate(cands):
                    plan["cand_tap"][k] = tap((dy, dx))
                    plan["cand_alpha"][k] = math.exp(-(dy * dy + dx * dx) / 2.0)
                    plan["cand_ori"][k] = orientation(dy, dx)

                groups: dict[int, list] = {}
                if method == "edi_central":
                    groups.update({_GRAD + o: p for o, p in central_pairs().items()})
                    plan["use_ab"], plan["use_grad"] = 1, 1
                elif method == "edi_line":
                    groups.update({_GRAD + o: p for o, p in line_pairs().items()})
                    plan["use_ab"], plan["use_grad"] = 1, 1
                elif method == "bi":
                    plan["use_ab"] = 1
                elif method == "sg":
                    pure = {"auto": _sg_mode_pure(cands), "pure": True,
                            "combined": False}[sg_mode]
                    groups.update({_SG + s: p for s, p in sg_pairs().items()})
                    plan["use_sg"] = 1
                    if not pure:
                        groups.update({_GRAD + o: p for o, p in line_pairs().items()})
                        plan["use_ab"], plan["use_grad"] = 1, 1

                # keep only non-Z differences, of the same channel except in EDILine's
                # diagonal gradients: eqs. 10-11 take every colour pixel, and their mirror
                # pairs across a diagonal of a Bayer mosaic link red with blue ("inter-channel
                # differences", section 4.2.2); merge repeated pairs
                cross_ok = ({_GRAD + 2, _GRAD + 3} if method == "edi_line" or
                            (method == "sg" and plan["use_grad"]) else set())
                pair_mask: dict[tuple, int] = {}
                counts = np.zeros(NGROUPS, int)
                for g, pairs in groups.items():
                    for a, b in pairs:
                        if same(a, b) or (g in cross_ok and ch(r, c, *a) != Z
                                          and ch(r, c, *b) != Z):
                            key = (a, b)
                            pair_mask[key] = pair_mask.get(key, 0) | (1 << g)
                            counts[g] += 1
                if len(pair_mask) > MAX_PAIRS:
                    raise RuntimeError("plan: too many pairs")
                for i, ((a, b), m) in enumerate(pair_mask.items()):
                    plan["pair_a"][i] = tap(a)
                    plan["pair_b"][i] = tap(b)
                    plan["pair_gmask"][i] = m
                plan["n_pairs"] = len(pair_mask)
                plan["group_scale"] = np.where(counts > 0, 1.0 / np.maximum(counts, 1), 0.0)
                evaluated = ([*range(_SG, _GRAD)] if plan["use_sg"] else []) + (
                    [*range(_GRAD, NGROUPS)] if plan["use_grad"] else [])
                plan["gamma_mask"] = sum(1 << g for g in evaluated if counts[g] > 0)

                if plan["use_sg"]:
                    valid = {s for s in range(8) if counts[_SG + s] > 0}
                    nsg = []
                    for k, (dy, dx) in enumerate(cands):
                        cover = [s for s in sg_cover(dy, dx) if s in valid] or sorted(valid)
                        plan["cand_sgmask"][k] = sum(1 << s for s in cover)
                        plan["cand_sgscale"][k] = 1.0 / max(len(cover), 1)
                        nsg.append(len(cover))
                    # a common 1/n cancels in the normalised weights (eq. 12)
                    plan["sg_scaled"] = int(len(set(nsg)) > 1)

                if domain == "colour_difference":
                    est = colour_difference_estimates(lambda dy, dx: ch(r, c, dy, dx),
                                                      cands + [(0, 0)], target)
                    if est is not None:
                        plan["use_cd"] = 1
                        for k, wts in enumerate(est):
                            plan["cd_n"][k] = len(wts)
                            for m, (off, wt) in enumerate(wts.items()):
                                plan["cd_tap"][k, m] = tap(off)
                                plan["cd_w"][k, m] = wt

            plan["n_taps"] = len(taps)
            for off, t in taps.items():
                plan["tap_dy"][t], plan["tap_dx"][t] = off
            plan_map[r * Q + c] = len(plans)
            plans.append(plan)

    arr = np.zeros(len(plans), PLAN_DTYPE)
    for i, plan in enumerate(plans):
        arr[i] = plan
    return plan_map, arr
