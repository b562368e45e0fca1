"""Helpers of the test suite: the shared real data (skipped when absent), tolerances."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from rgbz_fast.io import ImageSource

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


def _colour():
    """colour-science, imported as the library does (it leaves NumPy's print options alone)."""
    from rgbz_fast._deps import import_colour

    return import_colour()


def delta_e2000(a8, b8):
    """CIEDE2000 per pixel between two 8-bit sRGB images."""
    colour = _colour()

    def lab(im):
        return colour.XYZ_to_Lab(colour.sRGB_to_XYZ(np.asarray(im) / 255.0))

    return colour.delta_E(lab(a8), lab(b8), method="CIE 2000")


def reference_srgb(scene, scale=1.0):
    """The spectral scene rendered directly by colour-science: reflectance under D65, CIE 1931
    2-degree observer, XYZ (white Y = 1) times ``scale`` (an exposure), sRGB, 8 bits."""
    colour = _colour()
    wl = scene.wavelengths
    shape = colour.SpectralShape(wl[0], wl[-1], wl[1] - wl[0])
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    xyz = colour.msds_to_XYZ(scene.image, cmfs, d65, method="Integration", shape=shape) / 100
    lin = np.clip(colour.XYZ_to_sRGB(xyz * scale, apply_cctf_encoding=False), 0, 1)
    return np.round(colour.cctf_encoding(lin) * 255).astype(np.uint8)


def rgbd_folder(path, shape=(48, 64), seed=3):
    """A small Middlebury-style RGB-D scene folder (rgb.png, disp1.png, dmin.txt): a textured
    image and two depth planes, for the command-line tests."""
    import imageio.v3 as iio

    path.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    iio.imwrite(path / "rgb.png", rng.integers(40, 220, shape + (3,), dtype=np.uint8))
    disp = np.full(shape, 60, np.uint8)
    disp[:, shape[1] // 2:] = 110
    iio.imwrite(path / "disp1.png", disp)
    (path / "dmin.txt").write_text("270\n")
    return path


def run_past_a_fifo(fn, fifo, timeout, what):
    """``[fn()]``, run on a thread that a reader blocked on the FIFO ``fifo`` cannot hang: past
    ``timeout`` seconds the FIFO is opened for writing (the reader sees its end) and the test
    fails with ``what``."""
    import threading

    done = []
    t = threading.Thread(target=lambda: done.append(fn()), daemon=True)
    t.start()
    t.join(timeout)
    if t.is_alive():                                      # unblock the reader, then fail
        with open(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK), "w"):
            pass
        pytest.fail(what)
    return done


def calibration_fields(**kw):
    """The fields of a small valid ToFCalibration (2 frequencies, 3 sites of a 4x4 frame, one
    harmonic), ``kw`` over them."""
    fields = dict(frequencies=np.array([80e6, 100e6]), offsets=np.zeros((2, 3)),
                  coefficients=np.zeros((2, 1, 2)),
                  sites=(np.array([0, 0, 2]), np.array([0, 2, 2])), block=1, shape=(4, 4))
    fields.update(kw)
    return fields


class KilledSource(ImageSource):
    """An ImageSource whose load() ends its own process by SIGKILL, as the out-of-memory
    killer ends a worker: for the process pool's tests (a spawned worker imports this
    module by name, as the test's process did)."""

    def load(self):
        import signal

        os.kill(os.getpid(), signal.SIGKILL)


def disk_full_at(n):
    """A stand-in for ``os.fsync`` that fails with ENOSPC (a full disk: the error names no
    file) at its n-th call and syncs the others: for the tests of files written as a set."""
    import errno

    fsync, calls = os.fsync, []

    def fsync_or_full(fd):
        calls.append(fd)
        if len(calls) == n:
            raise OSError(errno.ENOSPC, "No space left on device")
        return fsync(fd)

    return fsync_or_full
