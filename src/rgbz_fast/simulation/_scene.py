"""Scenes for the sensor simulation: colour or spectral image, depth, NIR reflectance.

A :class:`Scene` is what the RGB-Z sensor looks at (paper §5.1, Fig. 16):

* a **colour image** in linear RGB (relative scene radiance, 1.0 = a white
  surface) or a **spectral cube** (relative reflectance per band) with its
  wavelengths in nm;
* optionally a **depth map** in metres (the one-way distance the
  time-of-flight pixels measure) with a mask of the pixels whose depth is
  known; a disparity map is converted by :func:`disparity_to_depth`;
* optionally an **NIR reflectance** map at the laser wavelength; when it is
  missing :meth:`Scene.ir_map` gives a documented estimate
  (:func:`estimate_ir_reflectance`).

The loaders of scene files are in :mod:`rgbz_fast.simulation._loaders`
(:func:`~rgbz_fast.simulation.load_scene` and the three it picks from).

Encodings
---------
Integer RGB images are taken as sRGB-encoded (8 or 16 bit) and linearised
with the sRGB EOTF (IEC 61966-2-1):

.. math::

    V_{lin} = V/12.92 \\quad (V \\le 0.04045), \\qquad
    V_{lin} = ((V + 0.055)/1.055)^{2.4} \\quad \\text{otherwise}.

Float RGB images are taken as linear already (use
``Scene.from_rgb(img, encoding="srgb")`` for sRGB-encoded floats). Integer
spectral cubes are divided by their dtype's maximum (65535 for uint16), so a
CAVE cube becomes a relative reflectance in [0, 1].

References
----------
.. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", section 5.1 (simulation chain, Fig. 16) (docs/references.bib: rebiere_rgbz)
.. [2] Yasuma et al., "Generalized assorted pixel camera" -- the CAVE multispectral database (docs/references.bib: yasuma2010cave)
.. [3] Scharstein and Pal, "Learning conditional random fields for stereo" -- Middlebury 2005/2006 ground truth (docs/references.bib: scharstein2007middlebury)
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike  # noqa: F401  (Scene's annotation: get_type_hints reads it)

from .._validate import (FLOAT_DTYPES, check_choice, check_image, check_meta, check_number,
                         integer_bits, read_only_state)

__all__ = ["Scene", "srgb_to_linear", "disparity_to_depth", "estimate_ir_reflectance",
           "CAVE_WAVELENGTHS"]

#: the brightest scene value (relative radiance, 1 = white): the sensor models multiply it
#: by a photon flux, an area and an exposure, which must stay finite doubles
SCENE_MAX = 1e300

#: Wavelengths (nm) of a 31-band CAVE cube: 400, 410, ..., 700.
CAVE_WAVELENGTHS = tuple(float(400 + 10 * k) for k in range(31))

#: IR reflectance estimate: rho_IR = _IR_OFFSET + _IR_SLOPE * (nearest visible band)
_IR_OFFSET = 0.2
_IR_SLOPE = 0.6
_IR_BAND_NM = 650.0


# --------------------------------------------------------------------------
# conversions
# --------------------------------------------------------------------------
def srgb_to_linear(v):
    """The sRGB EOTF: encoded values in [0, 1] -> linear values in [0, 1].

    Examples
    --------
    >>> import numpy as np
    >>> np.round(srgb_to_linear(np.array([0.0, 0.04045, 0.5, 1.0])), 6)
    array([0.      , 0.003131, 0.214041, 1.      ])
    """
    v = check_image(v, "v", dtypes=FLOAT_DTYPES).astype(np.float64)
    if v.min() < 0 or v.max() > 1:
        raise ValueError(f"v: values span [{v.min()}, {v.max()}]; expected encoded values in "
                         "[0, 1]")
    return np.where(v <= 0.04045, v / 12.92, ((np.maximum(v, 0.04045) + 0.055) / 1.055) ** 2.4)


def _fill_nearest(values, valid):
    """Replace the invalid entries of ``values`` by the nearest valid one (Euclidean)."""
    if valid.all():
        return values
    from scipy import ndimage

    idx = ndimage.distance_transform_edt(~valid, return_distances=False, return_indices=True)
    return values[tuple(idx)]


def disparity_to_depth(disparity, focal_px, baseline_m, *, offset=0.0, invalid=0):
    """Metric depth from a stereo disparity map: ``Z = f * B / (d + offset)``.

    Parameters
    ----------
    disparity : array_like, shape (H, W)
        Disparity in pixels (of the resolution that ``focal_px`` refers to).
    focal_px : float
        Focal length in pixels.
    baseline_m : float
        Stereo baseline in metres.
    offset : float, optional
        Added to every disparity before the division (Middlebury's ``dmin``:
        the images were cropped, so the stored disparity is relative).
    invalid : float or None, optional
        The disparity value that marks "unknown" (Middlebury: 0). None if every
        value is a measurement.

    Returns
    -------
    depth : ndarray of float64, shape (H, W)
        Depth in metres. Unknown pixels are filled with the depth of the
        nearest known pixel, so that a sensor simulation sees a plausible
        surface there; ``valid`` says which ones they are.
    valid : ndarray of bool, shape (H, W)
        True where the depth comes from a measured disparity.

    Raises
    ------
    ValueError
        If a known disparity gives ``d + offset <= 0`` (a point at or beyond
        infinity), or if no pixel is known.

    Examples
    --------
    >>> import numpy as np
    >>> d, ok = disparity_to_depth(np.array([[100, 100], [60, 0]]), 3740, 0.16, offset=270)
    >>> np.round(d, 4)
    array([[1.6173, 1.6173],
           [1.8133, 1.8133]])
    >>> ok
    array([[ True,  True],
           [ True, False]])
    """
    disp = check_image(disparity, "disparity", ndim=2,
                       values="disparities in pixels").astype(np.float64)
    f = check_number(focal_px, "focal_px", lo=0, lo_open=True)
    b = check_number(baseline_m, "baseline_m", lo=0, lo_open=True)
    off = check_number(offset, "offset")
    valid = np.ones(disp.shape, bool) if invalid is None else \
        disp != check_number(invalid, "invalid", allow_inf=True)
    if not valid.any():
        raise ValueError("disparity: every pixel is marked invalid "
                         f"(value {invalid}); there is no depth to use")
    total = disp + off
    if np.any(total[valid] <= 0):
        bad = int(np.count_nonzero(total[valid] <= 0))
        raise ValueError(f"disparity: {bad} known pixel(s) have disparity + offset <= 0 "
                         f"(offset {off}); depth would be infinite or negative")
    depth = np.zeros_like(total)
    with np.errstate(over="ignore"):
        depth[valid] = f * b / total[valid]
    if not np.all(np.isfinite(depth[valid])):
        raise ValueError(f"disparity: a known disparity + offset as small as "
                         f"{total[valid].min():g} puts a point at {f:g} * {b:g} / "
                         f"{total[valid].min():g}, beyond the largest double; expected "
                         "disparities in pixels")
    return _fill_nearest(depth, valid), valid


def estimate_ir_reflectance(image, wavelengths=None):
    """The default NIR reflectance estimate used when a scene has none.

    ``rho_IR = 0.2 + 0.6 * clip(x, 0, 1)``, where ``x`` is the scene's
    visible band nearest to the near infrared: the linear red channel of an
    RGB scene, or the mean of the bands at 650 nm and above of a spectral
    scene (the longest band if none reaches 650 nm).

    This is a heuristic, not a measurement: most materials (foliage, fabric
    dyes, paints, skin) reflect at 850-940 nm at least as much as in the red,
    and their NIR reflectance varies less than their visible colour, so the
    red band is compressed into [0.2, 0.8] around a mid grey. Pass a
    measured map as ``Scene(ir_reflectance=...)`` when one exists.

    Parameters
    ----------
    image : ndarray, shape (H, W, C)
        Linear RGB (C = 3) or a spectral cube.
    wavelengths : array_like, shape (C,), optional
        Band centres in nm for a spectral cube.

    Returns
    -------
    ndarray of float64, shape (H, W), values in [0.2, 0.8]
    """
    img = check_image(image, "image", dtypes=FLOAT_DTYPES)
    if wavelengths is None:
        if img.ndim < 2 or img.shape[-1] != 3:
            raise ValueError(f"image: expected linear RGB (rows, cols, 3) or wavelengths= for "
                             f"a spectral cube, got shape {img.shape}")
        x = img[..., 0]
    else:
        wl = check_image(wavelengths, "wavelengths", ndim=1).astype(np.float64)
        if wl.size != img.shape[-1]:
            raise ValueError(f"wavelengths: expected {img.shape[-1]} band centres, got "
                             f"{wl.size}")
        sel = wl >= _IR_BAND_NM
        if not sel.any():
            sel = wl == wl.max()
        x = img[..., sel].mean(axis=-1, dtype=np.float64)
    return _IR_OFFSET + _IR_SLOPE * np.clip(np.asarray(x, dtype=np.float64), 0.0, 1.0)


def _readonly(a, fresh=False):
    """A read-only copy in C order: the simulation's kernels read rows, so a scene built from
    a transposed or fancy-indexed array would otherwise be copied again on every call.
    ``fresh``: ``a`` was made here (a decoded or converted image), so a C-ordered one that
    owns its memory is kept as it is (a 12 MP float64 image: 288 MB not copied)."""
    if not (fresh and a.flags.c_contiguous and a.flags.owndata):
        a = np.array(a, copy=True, order="C")
    a.setflags(write=False)
    return a


# --------------------------------------------------------------------------
# Scene
# --------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class Scene:
    """What the RGB-Z sensor looks at: a colour or spectral image, depth, NIR reflectance.

    Parameters
    ----------
    image : ndarray, shape (H, W, 3) or (H, W, K)
        Linear RGB (relative radiance, 1.0 = white; values above 1 are
        allowed and simply brighter), or a spectral cube of relative
        reflectance with ``wavelengths``. Integer RGB is taken as sRGB
        (8 or 16 bit) and linearised; integer spectral data is divided by its
        dtype's maximum. Values must be finite and >= 0. An integer type
        wider than 16 bits (int32, int64: a list of Python ints) needs
        ``input_bits``.
    wavelengths : array_like, shape (K,), optional
        Band centres in nm (strictly increasing, 300..1100) of a spectral
        cube; None for an RGB scene.
    depth : ndarray, shape (H, W), optional
        Distance in metres from the camera to the surface seen by each pixel
        (the one-way path the time-of-flight pixels measure). Finite and
        >= 0 everywhere, > 0 where ``depth_valid``.
    depth_valid : ndarray of bool, shape (H, W), optional
        False where the depth is not known (its value is then only a filler:
        the sensor still simulates a surface there, and the ToF output marks
        the site invalid). Default: all True.
    ir_reflectance : ndarray, shape (H, W), optional
        Reflectance in [0, 1] at the laser wavelength. Default: the estimate
        of :func:`estimate_ir_reflectance`, computed only if a ToF model
        runs.
    name : str
        A short name for reports.
    meta : dict
        Free-form metadata (source files, conversion constants).
    input_bits : int, optional
        Bits of the values of an integer ``image`` (default: 8 for uint8, 16
        for uint16; required for wider types); the image is divided by
        ``2**input_bits - 1``. Not for float images. The scene keeps the
        converted float image, and None here.

    Attributes
    ----------
    shape : tuple (H, W)
    is_spectral : bool
    has_depth : bool

    Examples
    --------
    >>> import numpy as np
    >>> s = Scene(np.full((4, 4, 3), 255, np.uint8), depth=np.full((4, 4), 1.5))
    >>> s.shape, s.is_spectral, s.has_depth, float(s.image.max())
    ((4, 4), False, True, 1.0)
    """

    image: np.ndarray
    wavelengths: ArrayLike | None = None
    depth: np.ndarray | None = None
    depth_valid: np.ndarray | None = None
    ir_reflectance: np.ndarray | None = None
    name: str = ""
    meta: dict = field(default_factory=dict)
    input_bits: int | None = None

    def __setstate__(self, state):          # a pickled or deep-copied scene stays read-only
        read_only_state(self, state)

    def __post_init__(self):
        img = check_image(self.image, "image", ndim=3)
        integer = np.issubdtype(img.dtype, np.integer) or img.dtype == np.bool_
        bits = self.input_bits
        fresh = False                        # img is the caller's array until converted
        decoded = False                      # values of the sRGB table: in [0, 1]
        if not integer:
            integer_bits(img, "image", bits)          # input_bits with a float image: refused
        if self.wavelengths is None:
            if img.shape[2] != 3:
                raise ValueError(f"image: an RGB scene needs 3 channels in the last axis, got "
                                 f"shape {img.shape}; pass wavelengths= for a spectral cube")
            if integer:
                img = srgb_decode(img, "image", bits)
                fresh = decoded = True
            wl = None
        else:
            wl = check_image(self.wavelengths, "wavelengths").astype(np.float64)
            if wl.ndim != 1 or wl.size != img.shape[2]:
                raise ValueError(f"wavelengths: expected {img.shape[2]} band centres (one per "
                                 f"band of image {img.shape}), got shape {wl.shape}")
            if not np.all(np.isfinite(wl)) or wl.min() < 300 or wl.max() > 1100:
                raise ValueError(f"wavelengths: expected finite values in 300..1100 nm, got "
                                 f"[{wl.min()}, {wl.max()}]")
            if wl.size > 1 and np.any(np.diff(wl) <= 0):
                raise ValueError("wavelengths: expected strictly increasing band centres")
            if wl.size < 3:
                # the sensor's response integrates the bands (white_gains, colour_matrix need
                # three or more): one or two had been taken here, and simulate failed after
                # its whole run, blaming a wavelengths it had not been given
                raise ValueError(f"image: a spectral scene needs at least 3 bands (the "
                                 f"sensor's R, G and B responses integrate them); got "
                                 f"{wl.size} at {', '.join(f'{w:g}' for w in wl)} nm")
            if integer:
                img = _int_to_unit(img, "image", bits)
                fresh = True
            wl = _readonly(wl)
        if not integer and img.dtype not in (np.float32, np.float64):
            img = img.astype(np.float32 if img.dtype == np.float16 else np.float64)
            fresh = True
        if not decoded and img.min() < 0:
            raise ValueError(f"image: holds negative values (min {img.min()}); scene radiance "
                             "and reflectance are >= 0")
        if not decoded and float(img.max()) > SCENE_MAX:     # float32 cannot hold it
            raise ValueError(f"image: values up to {img.max():g}; a relative radiance beyond "
                             f"{SCENE_MAX:g} (white = 1) overflows the sensor models")
        object.__setattr__(self, "image", _readonly(img, fresh))
        object.__setattr__(self, "input_bits", None)          # the image is float now
        object.__setattr__(self, "wavelengths", wl)
        shape = img.shape[:2]

        if self.depth is None:
            if self.depth_valid is not None:
                raise ValueError("depth_valid: given without a depth map")
        else:
            d = check_image(self.depth, "depth", ndim=2,
                            values="distances in metres").astype(np.float64)
            if d.shape != shape:
                raise ValueError(f"depth: shape {d.shape} differs from the image's {shape}")
            if self.depth_valid is None:
                valid = np.ones(shape, bool)
            else:
                valid = np.asarray(self.depth_valid)
                if valid.dtype != np.bool_:
                    raise TypeError(f"depth_valid: expected a bool array, got dtype {valid.dtype}")
                if valid.shape != shape:
                    raise ValueError(f"depth_valid: shape {valid.shape} differs from the "
                                     f"image's {shape}")
            if d.min() < 0:
                raise ValueError(f"depth: holds negative distances (min {d.min()} m); "
                                 "expected metres >= 0")
            if np.any(d[valid] <= 0):
                raise ValueError("depth: a valid pixel is at distance 0 m; mark it invalid with "
                                 "depth_valid or give its distance")
            object.__setattr__(self, "depth", _readonly(d, fresh=True))     # astype's copy
            object.__setattr__(self, "depth_valid", _readonly(valid))

        if self.ir_reflectance is not None:
            ir = check_image(self.ir_reflectance, "ir_reflectance", ndim=2,
                             values="reflectances in [0, 1]").astype(np.float64)
            if ir.shape != shape:
                raise ValueError(f"ir_reflectance: shape {ir.shape} differs from the image's "
                                 f"{shape}")
            if ir.min() < 0 or ir.max() > 1:
                raise ValueError(f"ir_reflectance: values span [{ir.min()}, {ir.max()}]; "
                                 "a reflectance lies in [0, 1]")
            object.__setattr__(self, "ir_reflectance", _readonly(ir, fresh=True))
        if not isinstance(self.name, str):
            raise TypeError(f"name: expected a string, got {type(self.name).__name__}")
        object.__setattr__(self, "meta", check_meta(self.meta, "meta"))

    # -- constructors -------------------------------------------------------
    @classmethod
    def from_rgb(cls, image, *, encoding="auto", depth=None, depth_valid=None,
                 disparity=None, focal_px=None, baseline_m=None, disparity_offset=0.0,
                 invalid_disparity=0, ir_reflectance=None, name="", meta=None, input_bits=None):
        """An RGB scene, with the encoding stated and depth given as depth or disparity.

        Parameters
        ----------
        image : array_like, shape (H, W, 3)
            8/16-bit integers or floats in [0, 1] (sRGB) or >= 0 (linear).
        encoding : {"auto", "srgb", "linear"}
            "auto": integers are sRGB, floats are linear. "srgb": apply the
            sRGB EOTF (floats must lie in [0, 1]). "linear": integers are
            only scaled by their dtype's maximum.
        depth, depth_valid : ndarray, optional
            As in :class:`Scene`.
        disparity : ndarray, optional
            Instead of ``depth``: converted with :func:`disparity_to_depth`
            using ``focal_px``, ``baseline_m``, ``disparity_offset`` and
            ``invalid_disparity``.
        ir_reflectance : ndarray, shape (H, W), optional
            Reflectance in [0, 1] at the laser wavelength, as in :class:`Scene`
            (default: the estimate of :func:`estimate_ir_reflectance`).
        name : str
            A short name for reports.
        meta : dict, optional
            Free-form metadata, copied; a ``disparity`` conversion adds
            ``focal_px``, ``baseline_m`` and ``disparity_offset`` to it.
        input_bits : int, optional
            Bits of the values of an integer image (see :class:`Scene`).
        """
        enc = check_choice(encoding, ("auto", "srgb", "linear"), "encoding")
        img = check_image(image, "image", ndim=3)
        integer = np.issubdtype(img.dtype, np.integer) or img.dtype == np.bool_
        integer_bits(img, "image", input_bits)     # input_bits for integer images only
        if enc == "srgb":
            unit = _int_to_unit(img, "image", input_bits) if integer else \
                img.astype(np.float64)
            if unit.min() < 0 or unit.max() > 1:
                raise ValueError(f"image: sRGB-encoded floats must lie in [0, 1], got "
                                 f"[{unit.min()}, {unit.max()}]")
            img = srgb_to_linear(unit)
        elif enc == "linear" and integer:
            img = _int_to_unit(img, "image", input_bits)
        if enc != "auto":
            input_bits = None                      # converted to float above
        meta = check_meta(meta, "meta", allow_none=True)
        if disparity is not None:
            if depth is not None:
                raise ValueError("disparity: give either depth or disparity, not both")
            if focal_px is None or baseline_m is None:
                raise ValueError("disparity: focal_px and baseline_m are needed to convert a "
                                 "disparity map to metres")
            depth, valid = disparity_to_depth(disparity, focal_px, baseline_m,
                                              offset=disparity_offset, invalid=invalid_disparity)
            depth_valid = valid if depth_valid is None else (np.asarray(depth_valid) & valid)
            meta.update(focal_px=float(focal_px), baseline_m=float(baseline_m),
                        disparity_offset=float(disparity_offset))
        return cls(img, depth=depth, depth_valid=depth_valid, ir_reflectance=ir_reflectance,
                   name=name, meta=meta, input_bits=input_bits)

    @classmethod
    def from_spectral(cls, cube, wavelengths, *, depth=None, depth_valid=None,
                      ir_reflectance=None, name="", meta=None, input_bits=None):
        """A spectral scene: relative reflectance per band and the band centres in nm."""
        if wavelengths is None:
            raise ValueError("wavelengths: a spectral scene needs its band centres in nm")
        return cls(cube, wavelengths=wavelengths, depth=depth, depth_valid=depth_valid,
                   ir_reflectance=ir_reflectance, name=name,
                   meta=check_meta(meta, "meta", allow_none=True), input_bits=input_bits)

    # -- properties -----------------------------------------------------------
    @property
    def shape(self):
        """tuple (H, W): the spatial size."""
        return tuple(int(s) for s in self.image.shape[:2])

    @property
    def is_spectral(self):
        return self.wavelengths is not None

    @property
    def has_depth(self):
        return self.depth is not None

    def ir_map(self):
        """ndarray (H, W): the NIR reflectance, given or estimated.

        See :func:`estimate_ir_reflectance` for the estimate.
        """
        if self.ir_reflectance is not None:
            return self.ir_reflectance
        return estimate_ir_reflectance(self.image, self.wavelengths)

    def __repr__(self):
        kind = (f"spectral {self.image.shape[2]} bands {self.wavelengths[0]:g}-"
                f"{self.wavelengths[-1]:g} nm" if self.is_spectral else "RGB")
        extra = ", with depth" if self.has_depth else ""
        extra += ", with IR reflectance" if self.ir_reflectance is not None else ""
        name = f"{self.name!r}, " if self.name else ""
        return f"Scene({name}{self.shape[0]}x{self.shape[1]} {kind}{extra})"


def srgb_decode(img, name="image", input_bits=None):
    """Linear values of an sRGB-encoded integer image: ``srgb_to_linear(img / (2**bits - 1))``,
    ``bits`` from :func:`integer_bits` (``input_bits`` when given); 8- and 16-bit unsigned
    images through a table of every code's value (the same values, computed once per code
    instead of once per pixel)."""
    if img.dtype not in (np.uint8, np.uint16):
        return srgb_to_linear(_int_to_unit(img, name, input_bits))
    bits = 8 * img.itemsize if input_bits is None else integer_bits(img, name, input_bits)
    # the codes in C order first (an eighth of the output's bytes): the look-up's result
    # is C-ordered, and the scene keeps it without copying it
    from .. import _kernels
    from .._threads import check_workers

    codes = np.ascontiguousarray(img)
    out = np.empty(codes.shape, np.float64)
    # in C on the threads: NumPy's fancy indexing looked the codes up one at a time
    if not _kernels.decode_lookup(codes.reshape(-1), srgb_decode_table(bits), out.reshape(-1),
                                  check_workers(None)):
        raise ValueError(f"{name}: holds codes beyond {bits} bits (max {int(codes.max())})")
    return out


@lru_cache(maxsize=4)
def srgb_decode_table(bits):
    """The linear value of every code of a ``bits``-bit sRGB image (read-only):
    ``srgb_to_linear(code / (2**bits - 1))``, what :func:`srgb_decode` looks codes up in."""
    top = float((1 << bits) - 1)
    table = srgb_to_linear(np.arange(1 << bits, dtype=np.float64) / top)
    table.setflags(write=False)
    return table


def _int_to_unit(img, name, input_bits=None):
    """An integer image in [0, 1]: divided by the top of its range (:func:`integer_bits`)."""
    if img.dtype != np.bool_ and img.min() < 0:
        raise ValueError(f"{name}: signed integer data holds negative values")
    bits = integer_bits(img, name, input_bits)
    return img.astype(np.float64) / float((1 << bits) - 1)
