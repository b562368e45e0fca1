"""Slow, plain NumPy reference implementations of the reconstruction methods.

Written straight from docs/guide/interpretation.md and the paper (Rebiere et al.:
section 2.2, eqs. 1a-1e, and section 4, eqs. 2-19), independently of the C kernels and of
``rgbz_fast._plans``: the tests check that the two implementations of the one
specification agree.

Everything is vectorised over the Z sites: for every missing pixel we gather
the 5x5 window (5x9 for ``edi_rows``) of values *and* channel codes, then
evaluate the equations with boolean masks on ``(n_sites, 25)`` arrays.
Arithmetic is float64. :func:`reference_reconstruct` returns the clipped but
unrounded value of every pixel of the frame (colour sites copied).

With ``clip_level`` the rules of docs/guide/raw.md ("Near clipping") apply: a known
pixel at or above the level is *clipped*; a difference between two clipped
pixels is skipped (a clipped-unclipped one is a true lower bound and is kept),
in the gradients, the semi-gradients, the edi_rows directions and the terms of
beta (a clipped candidate's sum rescaled to the n - 1 terms of eq. 4), and a
site whose candidates are all clipped keeps at least the smallest of them. They
are written here from that page, not from the C code.
"""

from __future__ import annotations

import numpy as np

__all__ = ["reference_reconstruct", "round_half_up", "edi_rows_decision_margin", "METHODS",
           "shift_index", "window_offsets", "orientation"]

R, G, B, Z = 0, 1, 2, 3
METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "edi_rows")

# 5x5 kernel, row-major: index = (dy + 2) * 5 + (dx + 2)  (Fig. 11)
OFF = np.array([(dy, dx) for dy in range(-2, 3) for dx in range(-2, 3)])
DY, DX = OFF[:, 0], OFF[:, 1]


def K(dy, dx):
    """Index of kernel position (dy, dx) in the row-major 5x5 window."""
    assert -2 <= dy <= 2 and -2 <= dx <= 2
    return (dy + 2) * 5 + (dx + 2)


# -- borders ------------------------------------------------------------------

def shift_index(i, n, period):
    """Border rule: an index outside [0, n) moves back inside by whole periods.

    i < 0   -> i + P * ceil(-i / P)
    i >= n  -> i - P * ceil((i - n + 1) / P)
    so that the tap keeps its colour (the tile is P-periodic).
    """
    i = np.asarray(i, dtype=np.int64)
    out = i.copy()
    neg = i < 0
    out[neg] = i[neg] + period * (-(i[neg] // period))          # P*ceil(-i/P)
    big = i >= n
    out[big] = i[big] - period * (-(-(i[big] - n + 1) // period))  # P*ceil((i-n+1)/P)
    if np.any((out < 0) | (out >= n)):
        raise ValueError("frame smaller than one period")
    return out


def window_offsets(half_rows, half_cols):
    return np.array([(dy, dx) for dy in range(-half_rows, half_rows + 1)
                     for dx in range(-half_cols, half_cols + 1)])


def gather(data, chan, ys, xs, offsets, period):
    """Values and channel codes of the window around each site: (n_sites, len(offsets))."""
    n_rows, n_cols = data.shape
    P, Q = period
    yy = shift_index(ys[:, None] + offsets[None, :, 0], n_rows, P)
    xx = shift_index(xs[:, None] + offsets[None, :, 1], n_cols, Q)
    return data[yy, xx].astype(np.float64), chan[yy, xx]


def gather_mask(mask, ys, xs, offsets, period):
    """A bool frame gathered like :func:`gather`: (n_sites, len(offsets))."""
    n_rows, n_cols = mask.shape
    P, Q = period
    yy = shift_index(ys[:, None] + offsets[None, :, 0], n_rows, P)
    xx = shift_index(xs[:, None] + offsets[None, :, 1], n_cols, Q)
    return mask[yy, xx]


# -- common pieces --------------------------------------------------------------

def orientation(dy, dx):
    """0 vertical (dx = 0), 1 horizontal (dy = 0), 2 NW-SE (dy*dx > 0), 3 NE-SW (dy*dx < 0).

    The knight moves (1, 2), (2, 1) are closer in angle to the diagonal
    (18.4 deg) than to the axis (26.6 deg), so the sign of dy*dx decides.
    The centre (0, 0) is never a candidate; it is given -1.
    """
    dy, dx = np.asarray(dy), np.asarray(dx)
    o = np.full(np.broadcast(dy, dx).shape, -1)
    o = np.where((dx == 0) & (dy != 0), 0, o)
    o = np.where((dy == 0) & (dx != 0), 1, o)
    o = np.where(dy * dx > 0, 2, o)
    o = np.where(dy * dx < 0, 3, o)
    return o


ORI = orientation(DY, DX)                       # orientation of each kernel position
ALPHA = np.exp(-(DY ** 2 + DX ** 2) / 2.0)      # eq. 3, sigma = 1


def pair_differences(vals, codes, pairs, clip=None, cross=None):
    """|I(a) - I(b)| for each (a, b) in pairs and whether it is valid.

    A difference is valid only if neither pixel is Z and both have the same
    channel (a difference touching a Z pixel or linking two colours is skipped),
    except for the pairs flagged in ``cross`` (bool per pair), where two
    different colours are allowed (EDILine's diagonal gradients, eqs. 10-11:
    "inter-channel differences"); and, given the (n, 25) bool array ``clip``,
    not both pixels are clipped (a clipped-unclipped difference is a lower bound of
    the true one and stays valid).
    """
    a = np.array([p[0] for p in pairs])
    b = np.array([p[1] for p in pairs])
    ca, cb = codes[:, a], codes[:, b]
    same = ca == cb
    if cross is not None:
        same = same | np.asarray(cross, bool)[None, :]
    valid = (ca != Z) & (cb != Z) & same
    if clip is not None:
        valid &= ~(clip[:, a] & clip[:, b])
    d = np.abs(vals[:, a] - vals[:, b])
    return np.where(valid, d, 0.0), valid


def group_means(diffs, valid, groups):
    """Mean of the valid differences of each group -> (values, group_valid)."""
    n = diffs.shape[0]
    G_ = np.zeros((n, len(groups)))
    ok = np.zeros((n, len(groups)), dtype=bool)
    for g, members in enumerate(groups):
        members = list(members)
        cnt = valid[:, members].sum(axis=1)
        s = diffs[:, members].sum(axis=1)
        ok[:, g] = cnt > 0
        G_[:, g] = np.where(cnt > 0, s / np.maximum(cnt, 1), 0.0)
    return G_, ok


def discriminate(G_, ok, sigma_floor, sigma_rel=0.0):
    """Eq. 7: gamma = exp(-G^2 / (2 sigma^2)), sigma = max(min valid G, sigma_floor,
    sigma_rel * mean valid G) (the relative floor of docs/guide/interpretation.md).

    Groups without a valid difference are left out of the minimum and get 0;
    if no group of a site is valid, every gamma of the site is 1.
    """
    any_ok = ok.any(axis=1)
    gmin = np.where(ok, G_, np.inf).min(axis=1)
    sigma = np.maximum(np.where(any_ok, gmin, 0.0), sigma_floor)
    if sigma_rel > 0:
        nvalid = np.maximum(ok.sum(axis=1), 1)
        gmean = np.where(ok, G_, 0.0).sum(axis=1) / nvalid
        sigma = np.maximum(sigma, sigma_rel * gmean)
    with np.errstate(under="ignore", over="ignore"):
        gam = np.exp(-(G_ ** 2) / (2.0 * sigma[:, None] ** 2))
    gam = np.where(ok, gam, 0.0)
    gam[~any_ok] = 1.0
    return gam


def intensity_factor(vals, cand, clip=None):
    """Eq. 4: beta_k = 1 / (1 + sum over all candidates m of |c_k - c_m|).

    With ``clip`` (docs/guide/raw.md, "Near clipping"): the differences between two
    clipped candidates are not used. A candidate with u >= 1 differences left has
    S = 1 + (n - 1) / u * (their sum), n the number of candidates; one with none
    left (every candidate clipped) has S = 1; beta = 1 / S.
    """
    v = np.where(cand, vals, 0.0)
    d = np.abs(v[:, :, None] - v[:, None, :])
    if clip is None:
        d = d * (cand[:, :, None] & cand[:, None, :])
        return 1.0 / (1.0 + d.sum(axis=2))
    use = cand[:, :, None] & cand[:, None, :] & ~(clip[:, :, None] & clip[:, None, :])
    use &= ~np.eye(cand.shape[1], dtype=bool)[None]    # no k = m term
    u = use.sum(axis=2)
    n = cand.sum(axis=1)[:, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        S = 1.0 + (d * use).sum(axis=2) * (n - 1) / u
    S = np.where(u > 0, S, 1.0)
    return 1.0 / S


def plain_mean(vals, cand):
    return np.where(cand, vals, 0.0).sum(axis=1) / cand.sum(axis=1)


def weighted_mean(vals, cand, w, diag=None):
    """Eqs. 12-13 as c0 + sum w (c - c0) / sum w (c0: first candidate, row-major).

    Falls back to the plain candidate mean where sum w is not > 0. If ``diag``
    is a dict, the weight sums are stored in ``diag["weight_sum"]``.
    """
    n = vals.shape[0]
    w = np.where(cand, w, 0.0)
    first = np.argmax(cand, axis=1)
    c0 = vals[np.arange(n), first]
    den = w.sum(axis=1)
    num = (w * np.where(cand, vals - c0[:, None], 0.0)).sum(axis=1)
    good = den > 0
    if diag is not None:
        diag["weight_sum"] = den
    with np.errstate(divide="ignore", invalid="ignore"):
        wm = c0 + num / np.where(good, den, 1.0)
    return np.where(good, wm, plain_mean(vals, cand))


# -- gradient definitions --------------------------------------------------------

def _edi_central_groups():
    """Fig. 7 areas; one pair (p, -p) per centrally symmetric couple, taken once."""
    pairs, groups = [], [[] for _ in range(4)]
    for k in range(25):
        dy, dx = DY[k], DX[k]
        if (dy, dx) == (0, 0):
            continue
        m = K(-dy, -dx)
        if k < m:                                 # take each couple once
            groups[ORI[k]].append(len(pairs))
            pairs.append((k, m))
    return pairs, groups


def _edi_line_groups():
    """Eqs. 8-11 restricted to the 5x5 window (mirror pairs across the kernel axes)."""
    pairs, groups = [], [[] for _ in range(4)]

    def add(o, a, b):
        groups[o].append(len(pairs))
        pairs.append((K(*a), K(*b)))

    for r in (1, 2):
        for c in range(-2, 3):
            add(0, (-r, c), (r, c))               # eq. 8: across the horizontal axis
            add(1, (c, -r), (c, r))               # eq. 9: across the vertical axis
    seen2, seen3 = set(), set()
    for r in range(-2, 3):
        for c in range(-2, 3):
            # NW-SE (index 2, eq. 11): (r, c) / (-c, -r), across the anti-diagonal
            if r != -c:
                key = frozenset({(r, c), (-c, -r)})
                if key not in seen2:
                    seen2.add(key)
                    add(2, (r, c), (-c, -r))
            # NE-SW (index 3, eq. 10): (r, c) / (c, r), across the main diagonal
            if r != c:
                key = frozenset({(r, c), (c, r)})
                if key not in seen3:
                    seen3.add(key)
                    add(3, (r, c), (c, r))
    return pairs, groups


EDI_CENTRAL_PAIRS, EDI_CENTRAL_GROUPS = _edi_central_groups()
EDI_LINE_PAIRS, EDI_LINE_GROUPS = _edi_line_groups()
assert [len(g) for g in EDI_CENTRAL_GROUPS] == [2, 2, 4, 4]
assert [len(g) for g in EDI_LINE_GROUPS] == [10, 10, 10, 10]
# eqs. 10-11 use every colour pixel: the diagonal groups' pairs may link two colours
EDI_LINE_CROSS = np.zeros(len(EDI_LINE_PAIRS), bool)
EDI_LINE_CROSS[EDI_LINE_GROUPS[2] + EDI_LINE_GROUPS[3]] = True


def _sg_definitions():
    """Eqs. 14-17 (dv, dh, j = 0..4) and eq. 18 (SG groups, SW with dh[6, 8])."""
    pairs = []
    dv, dh = {}, {}
    for j in range(5):
        c = j - 2
        dv[2 * j] = len(pairs)
        pairs.append((K(0, c), K(-2, c)))       # eq. 14: centre row vs top row
        dv[2 * j + 1] = len(pairs)
        pairs.append((K(0, c), K(2, c)))        # eq. 15: centre row vs bottom row
        dh[2 * j] = len(pairs)
        pairs.append((K(c, 0), K(c, -2)))       # eq. 16: centre column vs left column
        dh[2 * j + 1] = len(pairs)
        pairs.append((K(c, 0), K(c, 2)))        # eq. 17: centre column vs right column
    sg = {
        "N": [dv[i] for i in (0, 2, 6, 8)],                     # 18a
        "S": [dv[i] for i in (1, 3, 7, 9)],                     # 18b
        "W": [dh[i] for i in (0, 2, 6, 8)],                     # 18c
        "E": [dh[i] for i in (1, 3, 7, 9)],                     # 18d
        "NW": [dv[0], dv[2], dh[0], dh[2]],                     # 18e
        "SE": [dv[7], dv[9], dh[7], dh[9]],                     # 18f
        "NE": [dv[6], dv[8], dh[1], dh[3]],                     # 18g
        "SW": [dv[1], dv[3], dh[6], dh[8]],                     # 18h ([4;6] read as [6;8])
    }
    return pairs, list(sg), [sg[k] for k in sg]


SG_PAIRS, SG_NAMES, SG_GROUPS = _sg_definitions()


def sg_cover(dy, dx):
    """Names of the semi-gradients covering kernel position (dy, dx) (eq. 19 generalised)."""
    names = []
    if dy < 0:
        names.append("N")
    if dy > 0:
        names.append("S")
    if dx < 0:
        names.append("W")
    if dx > 0:
        names.append("E")
    if dy != 0 and dx != 0:
        names.append(("N" if dy < 0 else "S") + ("W" if dx < 0 else "E"))
    return names


# SG_COVER[k, s]: semi-gradient s covers kernel position k
SG_COVER = np.zeros((25, len(SG_NAMES)), dtype=bool)
for _k in range(25):
    for _name in sg_cover(DY[_k], DX[_k]):
        SG_COVER[_k, SG_NAMES.index(_name)] = True


# -- the methods on gathered windows --------------------------------------------------

def _edi_gamma(vals, codes, pairs, groups, sigma_floor, sigma_rel, clip=None, cross=None):
    d, v = pair_differences(vals, codes, pairs, clip, cross)
    G_, ok = group_means(d, v, groups)
    return discriminate(G_, ok, sigma_floor, sigma_rel)      # (n, 4), indexed by orientation


def _gamma_at_candidates(gam):
    """gamma_{o(k)} for every kernel position k (0 at the centre)."""
    o = np.where(ORI >= 0, ORI, 0)
    g = gam[:, o]
    g[:, ORI < 0] = 0.0
    return g


def sg_weights(vals, codes, sigma_floor, sg_invalid="exclude", sg_uncovered="all_valid",
               sigma_rel=0.0, clip=None):
    """Per-position semi-gradient factor: mean of the discriminated SGs covering it (eq. 19).

    sg_invalid="exclude" (default): the mean runs over the *valid* covering SGs;
    sg_invalid="zero": invalid covering SGs count in the mean with g = 0 (the
    spec says both "invalid SGs get g = 0" and "the mean of the g of the SGs
    covering", which read together give this; the kernel does "exclude").
    A position none of whose covering SGs is valid gets the mean of every valid SG of
    the site (sg_uncovered="all_valid", the default: the spec of
    docs/guide/interpretation.md, and what rgbz_fast's plans do) or, with
    sg_uncovered="zero", 0.
    With ``clip`` (docs/guide/raw.md, "Near clipping"), an SG whose differences all join
    two clipped pixels is *unknown* at that site: like an SG without differences it is
    left out of sigma and its g is 0 (all g are 1 if no SG is known), but it still
    covers its positions (which SGs cover a position depends on the pattern only).
    """
    d, v = pair_differences(vals, codes, SG_PAIRS, clip)
    SG, known = group_means(d, v, SG_GROUPS)    # eq. 18, each SG the mean of its differences
    g = discriminate(SG, known, sigma_floor, sigma_rel)    # eq. 7
    if clip is None:
        ok = known
    else:                                       # the pattern's SGs, clipping aside
        _, ok = group_means(*pair_differences(vals, codes, SG_PAIRS), SG_GROUPS)
    n = vals.shape[0]
    cover = np.broadcast_to(SG_COVER[None, :, :], (n,) + SG_COVER.shape)   # (n, 25, 8)
    valid_cover = cover & ok[:, None, :]
    if sg_uncovered == "all_valid":
        none = ~valid_cover.any(axis=2)                                    # (n, 25)
        valid_cover = np.where(none[:, :, None], ok[:, None, :], valid_cover)
        cover = np.where(none[:, :, None], ok[:, None, :], cover)
    elif sg_uncovered != "zero":
        raise ValueError(sg_uncovered)
    if sg_invalid == "exclude":
        use = valid_cover
    elif sg_invalid == "zero":
        use = cover
    else:
        raise ValueError(sg_invalid)
    cnt = use.sum(axis=2)
    s = (g[:, None, :] * use).sum(axis=2)
    return np.where(cnt > 0, s / np.maximum(cnt, 1), 0.0)   # (n, 25)


def _reconstruct_5x5(vals, codes, target, method, sigma_floor, sigma_rel, sg_mode, sg_invalid,
                     sg_uncovered="all_valid", diag=None, cd=None, clip=None):
    cand = (codes == target[:, None]) & (codes != Z)
    cand[:, K(0, 0)] = False
    if method == "bilinear":
        return plain_mean(vals, cand)
    if cd is not None:
        # eq. 5 generalised: weights from the intensities, interpolation of c - X
        xhat, x0, use = cd
        inner = _reconstruct_5x5_weights(vals, codes, target, method, sigma_floor, sigma_rel,
                                         sg_mode, sg_invalid, sg_uncovered, clip)
        plain = weighted_mean(vals, cand, inner, diag)
        cdv = weighted_mean(vals - np.nan_to_num(xhat), cand, inner) + np.nan_to_num(x0)
        return np.where(use, cdv, plain)
    return weighted_mean(vals, cand, _reconstruct_5x5_weights(
        vals, codes, target, method, sigma_floor, sigma_rel, sg_mode, sg_invalid,
        sg_uncovered, clip), diag)


def _reconstruct_5x5_weights(vals, codes, target, method, sigma_floor, sigma_rel, sg_mode,
                             sg_invalid, sg_uncovered, clip=None):
    """The unnormalised weights of eqs. 2, 6 and 19 at every kernel position."""
    cand = (codes == target[:, None]) & (codes != Z)
    cand[:, K(0, 0)] = False
    alpha = np.broadcast_to(ALPHA, vals.shape)
    beta = intensity_factor(vals, cand, clip)
    if method == "bi":
        return alpha * beta                                                 # eq. 2
    if method == "edi_central":
        gam = _edi_gamma(vals, codes, EDI_CENTRAL_PAIRS, EDI_CENTRAL_GROUPS, sigma_floor,
                         sigma_rel, clip)
        return alpha * beta * _gamma_at_candidates(gam)                     # eq. 6
    gam_line = _edi_gamma(vals, codes, EDI_LINE_PAIRS, EDI_LINE_GROUPS, sigma_floor, sigma_rel,
                          clip, EDI_LINE_CROSS)
    w_line = alpha * beta * _gamma_at_candidates(gam_line)
    if method == "edi_line":
        return w_line
    if method == "sg":
        sgk = sg_weights(vals, codes, sigma_floor, sg_invalid, sg_uncovered, sigma_rel, clip)
        diagonal = (DY != 0) & (DX != 0)
        if sg_mode == "pure":
            pure = np.ones(len(vals), dtype=bool)
        elif sg_mode == "combined":
            pure = np.zeros(len(vals), dtype=bool)
        elif sg_mode == "auto":
            pure = ~np.any(cand & ~diagonal[None, :], axis=1)
        else:
            raise ValueError(f"sg_mode: {sg_mode!r}")
        return np.where(pure[:, None], sgk, w_line * sgk)                   # eq. 19
    raise ValueError(f"method: unknown {method!r}")


def colour_difference_estimates(data, chan, ys, xs, period, target):
    """X at every 5x5 position and at the missing pixel (docs/guide/interpretation.md, eq. 5).

    X(p) = mean over the usable other channels (R and B for a green target, G
    for red/blue) of the mean of that channel's 4-neighbours of p; a channel is
    usable at a site if every candidate and the missing pixel have at least one
    4-neighbour of it. Returns (xhat (n, 25), x0 (n,), use (n,) bool).
    """
    off7 = window_offsets(3, 3)
    v7, c7 = gather(data, chan, ys, xs, off7, period)
    idx7 = {(int(dy), int(dx)): i for i, (dy, dx) in enumerate(off7)}
    n = len(ys)
    cand = np.zeros((n, 25), bool)
    _, c5 = gather(data, chan, ys, xs, OFF, period)
    cand = (c5 == target[:, None]) & (c5 != Z)
    cand[:, K(0, 0)] = False
    nb4 = ((-1, 0), (1, 0), (0, -1), (0, 1))
    # per position, per channel: sum and count of 4-neighbours
    sums = np.zeros((n, 25, 3))
    cnts = np.zeros((n, 25, 3))
    for k, (dy, dx) in enumerate(OFF):
        for a, b in nb4:
            j = idx7[(int(dy) + a, int(dx) + b)]
            for o in range(3):
                hit = c7[:, j] == o
                sums[:, k, o] += np.where(hit, v7[:, j], 0.0)
                cnts[:, k, o] += hit
    others = np.where(target[:, None] == 1, np.array([[1, 0, 1]]), np.array([[0, 1, 0]]))
    relevant = cand.copy()
    relevant[:, K(0, 0)] = True
    # usable channel: present at every relevant position
    present = cnts > 0
    usable = others.astype(bool) & np.all(present | ~relevant[:, :, None], axis=1)
    nuse = usable.sum(axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        means = sums / cnts
    means = np.where(usable[:, None, :] & present, means, 0.0)
    xhat = means.sum(axis=2) / np.maximum(nuse, 1)[:, None]
    return xhat, xhat[:, K(0, 0)], nuse > 0


# edi_rows: offsets of the 5x9 window, index = (dy + 2) * 9 + (dx + 4)
ROWS_OFF = window_offsets(2, 4)


def _R(dy, dx):
    return (dy + 2) * 9 + (dx + 4)


# direction -> (pixel above, pixel below), eqs. 1a-1e
ROWS_DIRS = {
    "a": ((-2, -4), (2, 4)),
    "b": ((-2, -2), (2, 2)),
    "c": ((-2, 0), (2, 0)),
    "d": ((-2, 2), (2, -2)),
    "e": ((-2, 4), (2, -4)),
}
ROWS_TIE_ORDER = ("c", "b", "d", "a", "e")


def _rows_known(clip):
    """(n, 5) bool: direction (in tie order) whose two pixels are not both clipped."""
    return np.stack([~(clip[:, _R(*ROWS_DIRS[d][0])] & clip[:, _R(*ROWS_DIRS[d][1])])
                     for d in ROWS_TIE_ORDER], axis=1)


def _reconstruct_rows(vals, codes, target, edge_ratio, clip=None):
    """Eqs. 1a-1e. With ``clip``: a direction whose two pixels are clipped cannot be
    chosen; if c (the vertical) is one of them, there is no edge test: vertical mean."""
    taps = [_R(*p) for d in ROWS_TIE_ORDER for p in ROWS_DIRS[d]]
    ok = (codes[:, taps] == target[:, None]) & (codes[:, taps] != Z)
    if not ok.all():
        raise ValueError("edi_rows: the ten taps are not all of the target colour")
    D = np.stack([np.abs(vals[:, _R(*ROWS_DIRS[d][0])] - vals[:, _R(*ROWS_DIRS[d][1])])
                  for d in ROWS_TIE_ORDER], axis=1)
    known = np.ones(D.shape, bool) if clip is None else _rows_known(clip)
    m = np.argmin(np.where(known, D, np.inf), axis=1)   # first minimum: tie order
    c = D[:, 0]
    vert = (vals[:, _R(-2, 0)] + vals[:, _R(2, 0)]) / 2.0
    out = vert.copy()
    dominant = known[:, 0] & (m != 0) & (D[np.arange(len(m)), m] < edge_ratio * c)
    for i in np.nonzero(dominant)[0]:
        up, down = ROWS_DIRS[ROWS_TIE_ORDER[m[i]]]
        out[i] = np.median([vals[i, _R(*up)], vals[i, _R(*down)], vert[i]])
    return out


# -- public entry point ---------------------------------------------------------------

def reference_reconstruct(data, pattern, method, bit_depth=11, sigma_floor=1e-3,
                          sigma_rel=0.5, edge_ratio=0.5, sg_mode="auto", sg_invalid="exclude",
                          sg_uncovered="all_valid", return_weight_sum=False,
                          domain="intensity", clip_level=None, sites=None):
    """Reference reconstruction: float64 frame, colour sites copied, Z sites clipped.

    The values at Z sites are not rounded; use :func:`round_half_up` to compare
    with an integer output. With ``return_weight_sum=True`` also return a frame
    holding, at every Z site, the sum of the (unnormalised) weights of eq. 12
    (NaN at colour sites and for methods without weights): where it is tiny
    (float32 underflow range) a float32 kernel may legitimately fall back to
    the plain mean while float64 does not.

    ``clip_level``: known pixels at or above it are clipped (docs/guide/raw.md, "Near
    clipping"). ``sites``: a bool frame; only the Z sites where it is True are
    reconstructed (the other Z sites are NaN), to keep large frames affordable.
    """
    data = np.asarray(data)
    shape = data.shape
    chan = pattern.channel_map(shape)
    missing = pattern.missing_colour(shape)
    out = data.astype(np.float64).copy()
    zmask = chan == Z
    if sites is not None:
        out[zmask & ~np.asarray(sites, bool)] = np.nan
        zmask = zmask & np.asarray(sites, bool)
    ys, xs = np.nonzero(zmask)
    clipped = None if clip_level is None else (data >= clip_level) & (chan != Z)
    if ys.size == 0:
        return (out, np.full(shape, np.nan)) if return_weight_sum else out
    target = missing[ys, xs].astype(np.int64)
    if method == "edi_rows":
        vals, codes = gather(data, chan, ys, xs, ROWS_OFF, pattern.period)
        clip = None if clipped is None else gather_mask(clipped, ys, xs, ROWS_OFF, pattern.period)
        v = _reconstruct_rows(vals, codes, target, edge_ratio, clip)
        cand = np.zeros(vals.shape, bool)
        cand[:, [_R(*p) for d in ROWS_TIE_ORDER for p in ROWS_DIRS[d]]] = True
        diag = {}
    elif method in METHODS:
        vals, codes = gather(data, chan, ys, xs, OFF, pattern.period)
        clip = None if clipped is None else gather_mask(clipped, ys, xs, OFF, pattern.period)
        cand = (codes == target[:, None]) & (codes != Z)
        if not cand.any(axis=1).all():
            raise ValueError(f"pattern {pattern.name!r}: a Z site has no candidate")
        diag = {}
        cd = None
        if domain == "colour_difference" and method != "bilinear":
            cd = colour_difference_estimates(data, chan, ys, xs, pattern.period, target)
        elif domain != "intensity":
            raise ValueError(f"domain: {domain!r}")
        v = _reconstruct_5x5(vals, codes, target, method, sigma_floor, sigma_rel, sg_mode,
                             sg_invalid, sg_uncovered, diag, cd, clip)
    else:
        raise ValueError(f"method: unknown {method!r}")
    top = float((1 << bit_depth) - 1)
    v = np.clip(v, 0.0, top)
    if clip is not None:
        # saturation kept: every candidate clipped -> at least the smallest of them
        allc = np.all(clip | ~cand, axis=1)
        lo = np.where(cand, vals, np.inf).min(axis=1)
        v = np.where(allc, np.maximum(v, lo), v)
    out[ys, xs] = v
    if return_weight_sum:
        wsum = np.full(shape, np.nan)
        if "weight_sum" in diag:
            wsum[ys, xs] = diag["weight_sum"]
        return out, wsum
    return out


def round_half_up(v):
    return np.floor(np.asarray(v, dtype=np.float64) + 0.5)


def edi_rows_decision_margin(data, pattern, edge_ratio=0.5, clip_level=None):
    """How fragile the edi_rows decision of each Z site is (NaN at colour sites).

    The smallest gap, relative to max(D) (at least 1 DN), between two of the
    five differences a..e (pairs that are both exactly 0 are robust and
    skipped), or between D_m and edge_ratio * c. A site with a margin below
    ~1e-5 may take another branch when the kernel computes in float32.
    With ``clip_level``, directions whose two pixels are clipped take no part.
    """
    data = np.asarray(data)
    shape = data.shape
    chan = pattern.channel_map(shape)
    ys, xs = np.nonzero(chan == Z)
    out = np.full(shape, np.nan)
    if ys.size == 0:
        return out
    vals, _ = gather(data, chan, ys, xs, ROWS_OFF, pattern.period)
    D = np.stack([np.abs(vals[:, _R(*ROWS_DIRS[d][0])] - vals[:, _R(*ROWS_DIRS[d][1])])
                  for d in ROWS_TIE_ORDER], axis=1)
    known = np.ones(D.shape, bool)
    if clip_level is not None:
        clip = gather_mask((data >= clip_level) & (chan != Z), ys, xs, ROWS_OFF, pattern.period)
        known = _rows_known(clip)
    scale = np.maximum(np.where(known, D, 0).max(axis=1), 1.0)
    gaps = [np.abs(D[:, i] - D[:, j]) + np.where((D[:, i] == 0) & (D[:, j] == 0), np.inf, 0)
            + np.where(known[:, i] & known[:, j], 0, np.inf)
            for i in range(5) for j in range(i + 1, 5)]
    m = np.argmin(np.where(known, D, np.inf), axis=1)
    Dm, c = D[np.arange(len(m)), m], D[:, 0]
    gaps.append(np.abs(Dm - edge_ratio * c) + np.where((Dm == 0) & (c == 0), np.inf, 0)
                + np.where(known[:, 0], 0, np.inf))
    out[ys, xs] = np.min(np.stack(gaps, axis=1), axis=1) / scale
    return out
