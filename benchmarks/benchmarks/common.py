"""Data and switches shared by the suites (no benchmarks here).

Every import of the package is guarded so that asv can still run older
commits that lack a module: a missing piece makes ``setup`` raise
NotImplementedError, which asv reports as skipped.
"""

import os
from pathlib import Path

import numpy as np

try:
    import rgbz_fast as rz
except ImportError:  # pragma: no cover
    rz = None

#: the 4000x3000 cases take minutes in a full run: ASV_SKIP_SLOW=1 skips them
SKIP_SLOW = os.environ.get("ASV_SKIP_SLOW", "0") not in ("", "0")
KODAK_SHAPE = (512, 768)     # rows, cols of a landscape Kodak image
BIG_SHAPE = (3000, 4000)     # a 4000x3000 (12 Mpix) frame


def need(*names):
    """Raise NotImplementedError (asv: skipped) if rgbz_fast or one of its attributes is missing."""
    if rz is None:
        raise NotImplementedError("rgbz_fast is not importable")
    for name in names:
        obj = rz
        for part in name.split("."):
            try:
                obj = getattr(obj, part)
            except AttributeError:
                try:
                    import importlib
                    obj = importlib.import_module(f"{obj.__name__}.{part}")
                except ImportError:
                    raise NotImplementedError(f"rgbz_fast.{name} is not available") from None


def need_method(method):
    """Raise NotImplementedError (asv: skipped) for a method this commit's reconstruct lacks."""
    if method not in getattr(rz, "METHODS", ()):
        raise NotImplementedError(f"method {method!r} is not available")


def skip_if_slow(shape):
    if SKIP_SLOW and shape[0] * shape[1] > 4_000_000:
        raise NotImplementedError("skipped: ASV_SKIP_SLOW is set")


def tile_to(img, shape):
    """Mirror-tile an image up to ``shape`` (rows, cols)."""
    rows, cols = shape
    ny, nx = -(-rows // img.shape[0]), -(-cols // img.shape[1])
    band = np.concatenate([img if j % 2 == 0 else img[:, ::-1] for j in range(nx)], axis=1)
    full = np.concatenate([band if i % 2 == 0 else band[::-1] for i in range(ny)], axis=0)
    return np.ascontiguousarray(full[:rows, :cols])


def astronaut(shape=None):
    import skimage.data

    img = skimage.data.astronaut()
    return img if shape is None else tile_to(img, shape)


def kodak_dir():
    """../shared/data/kodak of the project's workspace, or None (a user's clone has none)."""
    env = os.environ.get("RGBZ_SHARED_DATA")
    roots = [Path(env)] if env else []
    here = Path(__file__).resolve()
    roots += [p / "shared" / "data" for p in here.parents]
    for r in roots:
        if (r / "kodak" / "kodim01.png").is_file():
            return r / "kodak"
    return None
