"""Scenes read from files: plain images, spectral cubes, RGB-D folders.

:func:`load_image` (a plain image file), :func:`load_spectral` (a MATLAB
``.mat`` cube such as CAVE ``balloons_ms.mat`` or a folder with one band per
PNG file), :func:`load_rgbd` (a Middlebury-style folder with ``rgb.png``,
``disp1.png`` and ``dmin.txt``) and :func:`load_scene`, which picks one of
them from what the path holds. Every file goes through the guarded readers of
:mod:`rgbz_fast.io` (size limits, FIFOs and devices refused); what a
:class:`~rgbz_fast.simulation.Scene` holds, and how integer images are
linearised, is in :mod:`rgbz_fast.simulation._scene`.

References
----------
.. [1] Yasuma et al., "Generalized assorted pixel camera" -- the CAVE multispectral database (docs/references.bib: yasuma2010cave)
.. [2] Scharstein and Pal, "Learning conditional random fields for stereo" -- Middlebury 2005/2006 ground truth (docs/references.bib: scharstein2007middlebury)
"""

from __future__ import annotations

import math
import re
from io import BytesIO
from pathlib import Path

import numpy as np

from .._validate import check_flag, check_path
from ..io._files import (check_size, read_file, read_image, read_limits, rgb_image,
                         sample_bits)
from ..io._suffixes import IMAGE_SUFFIXES as _IMAGE_SUFFIXES
from ._scene import Scene

__all__ = ["load_image", "load_spectral", "load_rgbd", "load_scene", "MIDDLEBURY_FOCAL_PX",
           "MIDDLEBURY_BASELINE_M"]

#: Focal length (full-size pixels) of the Middlebury 2005/2006 stereo rigs.
MIDDLEBURY_FOCAL_PX = 3740.0
#: Baseline (metres) of the Middlebury 2005/2006 stereo rigs.
MIDDLEBURY_BASELINE_M = 0.160


def _require_file(path, what):
    p = check_path(path, what)
    if not p.exists():
        raise FileNotFoundError(f"{what}: {p} not found")
    return p                      # a folder, FIFO or device: the reader says what it is


def load_image(path, *, encoding="auto", depth=None, depth_valid=None, ir_reflectance=None,
               name=None, grey=False, input_bits=None, max_pixels=None, max_bytes=None):
    """Load a plain image file (PNG, TIFF, JPEG, ...) as an RGB :class:`Scene`.

    8- and 16-bit files are sRGB-encoded and linearised (16-bit PNGs at their
    full precision); float TIFFs are linear. An alpha channel is dropped. A
    grey image is refused unless ``grey=True`` (see :func:`rgbz_fast.io.rgb_image`).
    A file of wider integer samples (a 32-bit TIFF) needs ``input_bits``, the
    bits its values use (see :class:`Scene`).
    ``max_pixels``, ``max_bytes``: the read limits (:func:`rgbz_fast.io.read_limits`).

    Raises
    ------
    FileNotFoundError
        If the file does not exist.
    ValueError
        If it is not an RGB(A) image (or a grey one with ``grey=True``), is
        not a regular file, or is larger than the read limits
        (:func:`rgbz_fast.io.read_limits`).
    """
    p = _require_file(path, "path")
    check_flag(grey, "grey")
    _check_name(name)
    img = rgb_image(read_image(p, "path", max_pixels=max_pixels, max_bytes=max_bytes), p,
                    grey=grey)
    sample_bits(img, p, input_bits)
    return Scene.from_rgb(img, encoding=encoding, depth=depth, depth_valid=depth_valid,
                          ir_reflectance=ir_reflectance, name=name or p.stem,
                          meta={"source": str(p)}, input_bits=input_bits)


def _check_name(name):
    if name is not None and not isinstance(name, str):
        raise TypeError(f"name: expected a string or None, got {type(name).__name__}")


def _natural_key(p):
    return [int(t) if t.isdigit() else t.lower() for t in re.split(r"(\d+)", p.name)]


def load_spectral(path, *, wavelengths=None, variable=None, depth=None, depth_valid=None,
                  ir_reflectance=None, name=None, input_bits=None, max_pixels=None,
                  max_bytes=None):
    """Load a spectral cube: a MATLAB ``.mat`` file or a folder with one band per PNG file.

    Parameters
    ----------
    path : str or Path
        A ``.mat`` file (v5/v7, read with :func:`scipy.io.loadmat`) holding an
        (H, W, K) array, or a folder of single-band PNG files (read in
        natural order of their names: ``band_2`` before ``band_10``).
    wavelengths : array_like, shape (K,), optional
        Band centres in nm. Default: ``400 + 10*k`` (the CAVE convention,
        400..700 nm for 31 bands); a ``.mat`` file's own ``wavelengths``
        variable (or ``wavelength``, ``wl``, ``bands``) is used when present.
    variable : str, optional
        The variable of a ``.mat`` file; default ``Omsi`` (CAVE), else the
        only 3-D numeric array in the file.
    depth, depth_valid : ndarray, shape (H, W), optional
        Depth in metres and where it is known, as in :class:`Scene`.
    ir_reflectance : ndarray, shape (H, W), optional
        Reflectance in [0, 1] at the laser wavelength, as in :class:`Scene`
        (default: the estimate of :func:`estimate_ir_reflectance`).
    name : str, optional
        A short name for reports; default: the file's stem, or the folder's
        name.
    input_bits : int, optional
        Bits of the values of an integer cube wider than 16 bits (see
        :class:`Scene`); 8- and 16-bit cubes say their range.
    max_pixels, max_bytes : int, optional
        The read limits (:func:`rgbz_fast.io.read_limits`).

    Raises
    ------
    FileNotFoundError
        If the path or the folder's PNG files are missing.
    ValueError
        If the bands differ in shape or dtype, the variable is ambiguous or
        missing, or the wavelengths do not match the band count.
    """
    p = check_path(path, "path")
    _check_name(name)
    meta = {"source": str(p)}
    if p.is_dir():
        files = sorted((f for f in p.iterdir() if f.suffix.lower() == ".png" and f.is_file()),
                       key=_natural_key)
        if not files:
            cubes = sorted(f.name for f in p.iterdir() if f.suffix.lower() == ".mat"
                           and f.is_file())
            hint = f" (it holds {', '.join(cubes[:3])}: pass the .mat file itself)" if cubes \
                else ""
            raise FileNotFoundError(f"path: no PNG band files in folder {p}{hint}")
        bands = []
        for f in files:
            b = read_image(f, "path", max_pixels=max_pixels, max_bytes=max_bytes)
            if b.ndim != 2:
                raise ValueError(f"path: band file {f.name} has shape {b.shape}; expected a "
                                 "single-band (grey) image")
            if bands and (b.shape != bands[0].shape or b.dtype != bands[0].dtype):
                raise ValueError(f"path: band file {f.name} is {b.shape} {b.dtype}, but "
                                 f"{files[0].name} is {bands[0].shape} {bands[0].dtype}; "
                                 "every band must have the same size and bit depth")
            bands.append(b)
        cube = np.stack(bands, axis=-1)
        meta["band_files"] = [f.name for f in files]
        file_wl = None
    elif p.exists():                       # a FIFO or a device: read_file says what it is
        from scipy import io as sio

        blob = read_file(p, "path", max_bytes=max_bytes)
        try:
            limits = read_limits(max_pixels, max_bytes)
            for var, shape, kind in sio.whosmat(BytesIO(blob)):   # headers only
                check_size(shape, 8, p, "path", limits=limits)
            mat = sio.loadmat(BytesIO(blob))
        except NotImplementedError:
            raise ValueError(f"path: {p.name} is a MATLAB v7.3 (HDF5) file; save it with "
                             "-v7 or read it with h5py and use Scene.from_spectral") from None
        except ValueError as exc:
            if str(exc).startswith("path: "):             # a size limit
                raise
            raise ValueError(f"path: cannot read {p} as a MATLAB .mat file ({exc})") from None
        except Exception as exc:
            raise ValueError(f"path: cannot read {p} as a MATLAB .mat file ({exc})") from None
        arrays = {k: v for k, v in mat.items() if not k.startswith("__")}
        if variable is None:
            if "Omsi" in arrays:
                variable = "Omsi"
            else:
                cubes = [k for k, v in arrays.items() if isinstance(v, np.ndarray)
                         and v.ndim == 3 and np.issubdtype(v.dtype, np.number)]
                if len(cubes) != 1:
                    raise ValueError(f"variable: {p.name} holds {len(cubes)} 3-D arrays "
                                     f"({cubes}); name the cube with variable=")
                variable = cubes[0]
        if variable not in arrays:
            raise ValueError(f"variable: {variable!r} is not in {p.name} (it holds "
                             f"{sorted(arrays)})")
        cube = np.asarray(arrays[variable])
        if cube.ndim != 3:
            raise ValueError(f"variable: {variable!r} has shape {cube.shape}; expected (H, W, K)")
        file_wl = wl_key = None
        for k in ("wavelengths", "wavelength", "wl", "bands"):
            if k in arrays:
                file_wl = np.asarray(arrays[k], dtype=np.float64).ravel()
                wl_key = k
                break
        meta["variable"] = variable
    else:
        raise FileNotFoundError(f"path: {p} not found")
    sample_bits(cube, p, input_bits)
    k = cube.shape[2]
    source = None
    if wavelengths is None:
        if file_wl is not None:
            wavelengths, source = file_wl, f"the file's variable {wl_key!r}"
        else:
            wavelengths = 400.0 + 10.0 * np.arange(k)
            source = f"CAVE's convention 400 + 10 k nm for its {k} bands (none given)"
    try:
        return Scene.from_spectral(cube, wavelengths, depth=depth, depth_valid=depth_valid,
                                   ir_reflectance=ir_reflectance,
                                   name=name or (p.stem if p.is_file() else folder_name(p)),
                                   meta=meta,
                                   input_bits=input_bits)
    except ValueError as exc:
        if source is None or not str(exc).startswith("wavelengths:"):
            raise
        # where the band centres came from: the caller gave none (G5: the message had named
        # a 'wavelengths' the caller never passed)
        raise ValueError(f"{exc} (from {source}; pass wavelengths=)") from None


def folder_name(path):
    """The name of the folder ``path``: its own, or, for '.', '..' or 'a/..' (whose
    ``Path.name`` is '' or '..'), that of the folder it leads to ('' had named the scene of
    ``rgbz-fast simulate .`` and its frame file '_mask1.npz')."""
    p = Path(path)
    return p.name if p.name not in ("", ".", "..") else p.resolve().name


#: the largest disparity offset (pixels) of dmin.txt: Middlebury's are 200-300; 1e300 made
#: every depth 0 m
DMIN_MAX = 1e5


def load_rgbd(folder, *, focal_px=MIDDLEBURY_FOCAL_PX, baseline_m=MIDDLEBURY_BASELINE_M,
              ir_reflectance=None, name=None, grey=False, max_pixels=None, max_bytes=None):
    """Load a Middlebury-style RGB-D folder: ``rgb.png``, ``disp1.png``, ``dmin.txt``.

    The depth is ``Z = focal_px * baseline_m / (v + dmin)`` with ``v`` the
    value of ``disp1.png`` (full-size pixels at every stored resolution) and
    ``v = 0`` unknown: with the defaults (f = 3740 px, B = 160 mm),
    ``Z[mm] = 3740*160/(v + dmin)``. Unknown pixels are filled with the
    nearest known depth and marked in ``Scene.depth_valid``.

    Note that Middlebury's Z is measured along the optical axis; the scene
    uses it as the distance the ToF pixels see (the line-of-sight distance is
    at most about 3 % longer at the corners of these images). ``max_pixels``,
    ``max_bytes``: the read limits of the images (:func:`rgbz_fast.io.read_limits`).

    Raises
    ------
    FileNotFoundError
        If the folder or one of the three files is missing (all missing files
        are named).
    ValueError
        If ``dmin.txt`` is not one number in [0, 1e5], ``disp1.png`` is not an
        8-bit single-band image of the size of ``rgb.png``, or no pixel has a
        disparity.
    """
    check_flag(grey, "grey")
    _check_name(name)
    d = check_path(folder, "folder")
    if not d.is_dir():
        raise FileNotFoundError(f"folder: {d} is not a folder")
    needed = ("rgb.png", "disp1.png", "dmin.txt")
    missing = [n for n in needed if not (d / n).is_file()]
    if missing:
        raise FileNotFoundError(f"folder: {d} lacks {', '.join(missing)} (an RGB-D scene "
                                f"folder holds {', '.join(needed)})")
    text = read_file(d / "dmin.txt", "folder", max_bytes=4096).decode("utf-8", "replace").strip()
    try:
        (token,) = text.split()                 # '270 px' or '270\n300' is not one number
        dmin = float(token.replace("_", "!"))   # float() reads '2_70' as 270
    except ValueError:
        raise ValueError(f"folder: {d / 'dmin.txt'} should hold one number (the disparity "
                         f"offset), got {text[:40]!r}") from None
    if not math.isfinite(dmin) or not 0 <= dmin <= DMIN_MAX:
        raise ValueError(f"folder: {d / 'dmin.txt'} gives {dmin:g}; expected a disparity "
                         f"offset in [0, {DMIN_MAX:g}] pixels (Middlebury's are 200-300)")
    limits = dict(max_pixels=max_pixels, max_bytes=max_bytes)
    rgb = rgb_image(read_image(d / "rgb.png", "folder", **limits), d / "rgb.png", "folder",
                    grey=grey)
    disp = read_image(d / "disp1.png", "folder", **limits)
    if disp.ndim == 3 and disp.shape[2] in (3, 4) and np.all(disp[..., 0:1] == disp[..., :3]):
        disp = disp[..., 0]
    if disp.ndim != 2:
        raise ValueError(f"folder: disp1.png has shape {disp.shape}; expected a grey image")
    if disp.dtype != np.uint8:
        # a 16-bit disparity is another convention (KITTI's: the disparity times 256), whose
        # values read as Middlebury's made depths 256 times too near, without a word
        raise ValueError(f"folder: disp1.png holds {disp.dtype} samples; a Middlebury "
                         "2005/2006 disparity is 8-bit grey (the disparity in pixels); convert "
                         "another convention to it, or pass the disparity to "
                         "Scene.from_rgb(disparity=, disparity_offset=) with its scale")
    if disp.shape != rgb.shape[:2]:
        raise ValueError(f"folder: disp1.png is {disp.shape[0]}x{disp.shape[1]} but rgb.png is "
                         f"{rgb.shape[0]}x{rgb.shape[1]} (rows x cols); they must be the same "
                         "size")
    try:
        return Scene.from_rgb(rgb, disparity=disp, focal_px=focal_px, baseline_m=baseline_m,
                              disparity_offset=dmin, invalid_disparity=0,
                              ir_reflectance=ir_reflectance, name=name or folder_name(d),
                              meta={"source": str(d), "dmin": dmin})
    except ValueError as exc:
        raise ValueError(f"folder: {d}: {exc}") from None


def load_scene(path, **kwargs):
    """Load a scene from a path, choosing the loader from what it holds.

    * a folder with ``disp1.png`` -> :func:`load_rgbd`;
    * a ``.mat`` file or a folder of PNG files -> :func:`load_spectral`;
    * an image file -> :func:`load_image`.

    Keyword arguments go to the chosen loader; ``grey`` (see
    :func:`rgbz_fast.io.rgb_image`) to the RGB ones only; ``input_bits`` to
    the image and spectral loaders (an RGB-D folder's PNG files say their
    range, so it is refused there).
    """
    p = check_path(path, "path")
    grey = check_flag(kwargs.pop("grey", False), "grey")
    if p.is_dir():
        if (p / "disp1.png").exists() or (p / "rgb.png").exists():
            if kwargs.get("input_bits") is not None:
                raise ValueError(f"input_bits: applies to image files and spectral cubes; "
                                 f"{p} is an RGB-D folder, whose PNG files say their range")
            kwargs.pop("input_bits", None)
            return load_rgbd(p, grey=grey, **kwargs)
        return load_spectral(p, **kwargs)
    if not p.exists():
        raise FileNotFoundError(f"path: {p} not found")
    if p.suffix.lower() == ".mat":
        return load_spectral(p, **kwargs)
    if p.suffix.lower() in _IMAGE_SUFFIXES:
        return load_image(p, grey=grey, **kwargs)
    raise ValueError(f"path: cannot tell what kind of scene {p.name} holds; expected an image "
                     "file, a .mat cube or a scene folder")
