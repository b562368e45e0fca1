"""Helpers of the test suite: the shared real data (skipped when absent), tolerances."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

#: the root of the source checkout
REPO = Path(__file__).resolve().parents[1]
SHARED_DATA = Path(os.environ.get("RGBZ_SHARED_DATA", REPO.parent / "shared" / "data"))

#: tolerance of C kernels against their NumPy references, by compute precision
TOL = {"float64": dict(rtol=1e-9, atol=1e-9), "float32": dict(rtol=1e-4, atol=1e-3)}


def shared_path(*parts):
    """Path under ../shared/data, or skip the test with a clear reason."""
    p = SHARED_DATA.joinpath(*parts)
    if not p.exists():
        pytest.skip(f"shared test data not found: {p} (a user's checkout has no ../shared/data)")
    return p


def load_kodak(n, crop=None):
    """Kodak image n (1..24) as uint8 RGB, optionally a (rows, cols) centre crop."""
    import imageio.v3 as iio

    img = iio.imread(shared_path("kodak", f"kodim{n:02d}.png"))
    if crop is not None:
        r0 = (img.shape[0] - crop[0]) // 2
        c0 = (img.shape[1] - crop[1]) // 2
        r0 -= r0 % 4
        c0 -= c0 % 4
        img = img[r0:r0 + crop[0], c0:c0 + crop[1]]
    return np.ascontiguousarray(img)


def npy_bytes(shape, dtype, payload=b""):
    """An ``.npy`` member that *declares* ``shape`` and ``dtype``, followed by ``payload``
    (which need not match: the hostile files of the robustness tests lie)."""
    import io

    b = io.BytesIO()
    np.lib.format.write_array_header_1_0(b, {"descr": np.dtype(dtype).str,
                                            "fortran_order": False, "shape": shape})
    return b.getvalue() + payload


def write_npz(path, **members):
    """A deflated NPZ from arrays, or raw ``.npy`` bytes (see :func:`npy_bytes`)."""
    import io
    import zipfile

    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, v in members.items():
            if not isinstance(v, bytes):
                b = io.BytesIO()
                np.save(b, np.asarray(v), allow_pickle=False)
                v = b.getvalue()
            zf.writestr(name + ".npy", v)
    return path


def frame_header(**fields):
    """The JSON header of an rgbz-fast NPZ frame (Mask1, 11 bits), with ``fields`` over it."""
    import json

    h = {"format": "rgbz-fast raw frame", "pattern": "ZR/BG", "bit_depth": 11, "meta": {}}
    h.update(fields)
    return np.array(json.dumps(h))
