"""Datasets: the images an evaluation, a trade-off study or a training run reads.

One loader for every command: :func:`folder_dataset` lists the image files of
a folder (RGB images, or camera raw and bare Bayer files with the options
:func:`rgbz_fast.io.read_raw` needs), :func:`sample_dataset` the colour images
shipped with scikit-image (offline), and :meth:`ImageSource.load` reads one.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .._validate import check_flag, check_path
from ._errors import ParameterError, Setting
from ._files import read_file, read_image, rgb_image, sample_bits
from ._raw import check_raw_options, read_raw
from ._suffixes import IMAGE_SUFFIXES, RAW_SUFFIXES

__all__ = ["ImageSource", "folder_dataset", "sample_dataset", "IMAGE_SUFFIXES",
           "RAW_SUFFIXES"]

_SKIMAGE_SAMPLES = ("astronaut", "coffee", "chelsea", "rocket", "immunohistochemistry")


@dataclass(frozen=True)
class ImageSource:
    """One image of a dataset: a name and where to read it (a path or ``skimage:NAME``).

    Camera raw and bare Bayer files (``raw_options`` holds the keyword
    arguments of :func:`rgbz_fast.io.read_raw` they need) load as a Bayer
    :class:`~rgbz_fast.RawFrame`: the real CFA is then the reference and the
    RGB-Z pattern removes its Z sites (the paper's HDR+ protocol). A grey
    image is refused unless ``grey`` (see :func:`rgbz_fast.io.rgb_image`); a
    one-channel image whose four 2x2 sites differ as a raw mosaic's do
    (:data:`MOSAIC_RATIO`, :data:`MOSAIC_CONTRAST`) is refused even with ``grey``: its entry
    in ``raw_options`` (phase and levels) reads it as raw. A raw file's missing
    settings are asked for as entries of ``raw_options``.
    ``max_pixels`` and ``max_bytes`` are the read limits of the file
    (:func:`rgbz_fast.io.read_limits`); a source carries them to the process
    that loads it. ``nir``: the location of a registered near-infrared image
    of the same scene (a folder's ``NNNN_nir.png`` beside ``NNNN_rgb.png``),
    read by :meth:`load_nir`.
    """

    name: str
    location: str
    raw_options: tuple = ()
    raw: bool = False
    grey: bool = False
    max_pixels: int | None = None
    max_bytes: int | None = None
    nir: str | None = None

    def __post_init__(self):
        for name in ("name", "location"):
            if not isinstance(getattr(self, name), str):
                raise TypeError(f"ImageSource.{name}: expected a string, got "
                                f"{type(getattr(self, name)).__name__}")
        for name in ("raw", "grey"):
            check_flag(getattr(self, name), f"ImageSource.{name}")
        # kept as folder_dataset keeps them, so that the frozen source hashes and equals
        # the same source from folder_dataset (a dict had been kept as it was: unhashable)
        object.__setattr__(self, "raw_options", _options_tuple(self.raw_options))

    @property
    def is_raw(self):
        return self.raw or Path(self.location).suffix.lower() in RAW_SUFFIXES

    def load(self):
        """The image: a Bayer :class:`~rgbz_fast.RawFrame` for a raw source (``is_raw``),
        else the colour image as an (H, W, 3) array (8 or 16 bits, or float), read within
        the source's limits; a ValueError naming ``dataset`` says what is wrong with it."""
        limits = dict(max_pixels=self.max_pixels, max_bytes=self.max_bytes)
        if self.is_raw:
            try:
                return read_raw(self.location, **limits, **dict(self.raw_options))
            except ParameterError as exc:
                if exc.settings and set(exc.settings) <= RAW_SETTINGS:
                    # a dataset gives a raw file its settings through raw_options
                    raise ParameterError(exc.param, *exc.parts, " in ",
                                         _raw_options_setting(self.location)) from None
                raise
        if self.location.startswith("skimage:"):
            import skimage.data
            img = getattr(skimage.data, self.location.split(":", 1)[1])()
        else:
            img = read_image(self.location, "dataset", **limits)
            _refuse_mosaic(img, self.location)
        img = rgb_image(img, self.location, "dataset", grey=self.grey)
        sample_bits(img, self.location, name="dataset", settable=False)  # 8/16 bits, floats
        return img

    def load_nir(self):
        """The registered NIR image as float64 reflectance in [0, 1] (the file's values over
        its type's maximum, the first channel of a multi-channel file), or None without one."""
        if self.nir is None:
            return None
        img = np.asarray(read_image(self.nir, "dataset", max_pixels=self.max_pixels,
                                    max_bytes=self.max_bytes))
        if img.ndim == 3:
            img = img[..., 0]
        if img.ndim != 2:
            raise ParameterError("dataset", f"{self.nir}: expected a one-channel NIR image, "
                                            f"got shape {img.shape}")
        if np.issubdtype(img.dtype, np.integer):
            return img.astype(np.float64) / float(np.iinfo(img.dtype).max)
        return np.clip(img.astype(np.float64), 0.0, 1.0)

    def fingerprint(self):
        """SHA-256 of what the image is: the file's bytes (with the raw options and the
        grey flag), or the name of a scikit-image sample. Part of the evaluation's cache
        key, so a changed file is never served stale results."""
        import hashlib

        h = hashlib.sha256()
        if self.location.startswith("skimage:"):
            import skimage

            h.update(f"{self.location} {skimage.__version__}".encode())
        else:
            h.update(read_file(self.location, "dataset", max_bytes=self.max_bytes))
        if self.nir is not None:
            h.update(read_file(self.nir, "dataset", max_bytes=self.max_bytes))
        h.update(repr((sorted(self.raw_options), self.is_raw, self.grey)).encode())
        return h.hexdigest()


#: the read_raw settings a dataset's raw_options give a file
RAW_SETTINGS = frozenset({"shape", "phase", "black_level", "white_level", "bit_depth_in",
                          "clip_level", "downsample", "byteorder"})

#: how a raw Bayer mosaic shows in one channel, against a grey photograph: its four 2x2
#: sites differ in mean (their colour filters) by more than this ratio ...
MOSAIC_RATIO = 1.15
#: ... and each site departs from the mean of its two neighbours, along the rows or the
#: columns, by more than this fraction of the mean level. Natural grey images (Kodak and
#: CBSD68 in grey, 32x32 crops and up) stay below 1.26 and 0.08, uniform noise of 64x64
#: below 1.09 and 0.09; the three shared camera raws are above 1.5 and 0.37.
MOSAIC_CONTRAST = 0.15
#: smaller images are not tested: their site means are too noisy to tell
MOSAIC_MIN_SIDE = 64


def _options_tuple(options):
    """The keyword arguments of read_raw as an ImageSource keeps them: sorted (name, value)
    pairs, lists made tuples; from a dict or such pairs (a TypeError naming
    ``ImageSource.raw_options`` otherwise)."""
    if isinstance(options, dict):
        options = options.items()
    try:
        pairs = [(k, tuple(v) if isinstance(v, list) else v) for k, v in options]
    except (TypeError, ValueError):
        raise TypeError(f"ImageSource.raw_options: expected a dict of read_raw's keyword "
                        f"arguments or (name, value) pairs, got {options!r:.60}") from None
    if not all(isinstance(k, str) for k, _ in pairs):
        raise TypeError("ImageSource.raw_options: the names of read_raw's keyword arguments "
                        "are strings")
    return tuple(sorted(pairs, key=lambda kv: kv[0]))


def _raw_options_setting(location):
    """How a dataset gives the settings of one raw file: its entry of ``raw_options``."""
    import json

    return Setting("raw_options", f"raw_options[{json.dumps(Path(location).name)}]")


def _refuse_mosaic(img, location):
    """A ParameterError when a one-channel image looks like a raw Bayer mosaic: read as grey,
    it would be scored as a photograph of its own colour-filter pattern."""
    a = np.asarray(img)
    if a.ndim == 3 and a.shape[2] == 1:
        a = a[..., 0]
    if a.ndim != 2 or min(a.shape) < MOSAIC_MIN_SIDE:
        return
    bits = a.dtype.itemsize * 8                  # the file's samples, before the float copy
    a = a.astype(np.float64)
    means = [float(a[i::2, j::2].mean()) for i in (0, 1) for j in (0, 1)]
    if not max(means) > MOSAIC_RATIO * min(means):
        return
    rows = a[:, 1:-1] - (a[:, :-2] + a[:, 2:]) / 2          # second differences: ~0 where
    cols = a[1:-1, :] - (a[:-2, :] + a[2:, :]) / 2          # the image is smooth
    contrast = max(abs(float(d[i::2, j::2].mean())) for d in (rows, cols) for i in (0, 1)
                   for j in (0, 1))
    if not contrast > MOSAIC_CONTRAST * float(a.mean()):
        return
    name = Path(location).name
    raise ParameterError(
        "dataset", f"{location} is a one-channel {bits}-bit image whose four "
        f"2x2 sites differ (means {', '.join(f'{m:.0f}' for m in means)}): a raw Bayer mosaic, "
        f"not a grey photograph; to evaluate {name} as raw, pass ", Setting("phase"), ", ",
        Setting("black_level"), " and ", Setting("white_level"), " (or ",
        Setting("bit_depth_in"), ") in ", _raw_options_setting(location))


def sample_dataset():
    """Five colour images shipped with scikit-image (astronaut, coffee, ...): runs offline."""
    return [ImageSource(n, f"skimage:{n}") for n in _SKIMAGE_SAMPLES]


def folder_dataset(path, limit=None, raw_options=None, *, grey=False, max_pixels=None,
                   max_bytes=None):
    """Every image file in a folder (sorted by name): RGB images, or camera raw / Bayer files.

    ``raw_options`` maps a file name (or ``"*"``, for every raw file) to the
    keyword arguments :func:`rgbz_fast.io.read_raw` needs for it (phase,
    black and white levels, shape of headerless files, ``downsample=2`` as
    the paper does for HDR+). A file named in ``raw_options`` is read as raw
    even if it is a PNG or TIFF (a 16-bit Bayer mosaic); a name that is no image file of the
    folder is warned about (its options apply to no file). ``limit``: the first
    ``limit`` files only (a positive integer). ``grey``: accept grey images,
    repeated into R, G and B (:func:`rgbz_fast.io.rgb_image`). ``max_pixels``,
    ``max_bytes``: the read limits of every file (:func:`rgbz_fast.io.read_limits`).

    Raises
    ------
    ValueError
        The folder does not exist or holds no image file, ``limit`` is not
        a positive integer, or two files have the same name stem
        (``a.png`` and ``a.tif``: their results would be one image's).

    A registered RGB + NIR pair, ``NNNN_rgb.<ext>`` and ``NNNN_nir.<ext>``
    (the layout of ``../shared/data/rgbnir``), is one source named ``NNNN``
    whose :attr:`ImageSource.nir` is the NIR file: the guide of
    ``method="z_guided"``, never an image of its own.
    """
    grey = check_flag(grey, "grey")
    if limit is not None and (isinstance(limit, bool) or not isinstance(limit, (int, np.integer))
                              or limit < 1):
        raise ParameterError("limit", f"expected a positive number of images, got {limit!r}")
    p = check_path(path, "dataset")
    if not p.exists():
        raise ParameterError("dataset", f"{p} does not exist")
    if not p.is_dir():                             # a file, or a FIFO the reader will refuse
        files = [p]
    else:
        named = [f for f in p.iterdir() if f.suffix.lower() in IMAGE_SUFFIXES | RAW_SUFFIXES
                 and not f.name.startswith(".")]
        files = sorted(f for f in named if f.is_file())
        odd = sorted(f.name for f in named if not f.is_file() and not f.is_dir())
        if odd:                 # they had been left out without a word (a folder is no image)
            import warnings

            warnings.warn(f"dataset: left out {', '.join(map(repr, odd))} of {p}: not "
                          "regular files (a broken link, a FIFO, a socket or a device)",
                          UserWarning, stacklevel=2)
    if not files:
        raise ParameterError("dataset", f"no image files in {p} (looked for "
                                        f"{', '.join(sorted(IMAGE_SUFFIXES))})")
    raw_options = check_raw_options(raw_options)
    listed = {f.name for f in files}
    unknown = [k for k in raw_options if k != "*" and k not in listed]
    if unknown and p.is_dir():      # a misspelt name's options would be used by no file (one
        import warnings             # file of a folder may take a file shared by the folder)

        one = len(unknown) == 1
        warnings.warn(f"raw_options: {', '.join(map(repr, unknown))} name{'s' if one else ''} "
                      f"no image file of {p}; {'its' if one else 'their'} options apply to no "
                      "file (a key is a file's name, or \"*\" for every raw file)",
                      UserWarning, stacklevel=2)
    nir = {f.name[:-len("_rgb" + f.suffix)]: f.with_name(f.name[:-len("_rgb" + f.suffix)]
                                                         + "_nir" + f.suffix)
           for f in files if f.stem.endswith("_rgb")}
    nir = {k: v for k, v in nir.items() if v.is_file()}
    files = [f for f in files if not (f.stem.endswith("_nir") and f.stem[:-4] in nir)]
    files = files[:limit] if limit else files
    out = []
    common = dict(grey=grey, max_pixels=max_pixels, max_bytes=max_bytes)
    for f in files:
        if f.suffix.lower() in RAW_SUFFIXES or f.name in raw_options:
            opts = {**raw_options.get("*", {}), **raw_options.get(f.name, {})}
            out.append(ImageSource(f.stem, str(f), _options_tuple(opts), raw=True, **common))
        elif f.stem.endswith("_rgb") and f.stem[:-4] in nir:
            out.append(ImageSource(f.stem[:-4], str(f), nir=str(nir[f.stem[:-4]]), **common))
        else:
            out.append(ImageSource(f.stem, str(f), **common))
    stems = [s.name for s in out]
    dup = sorted({n for n in stems if stems.count(n) > 1})
    if dup:
        raise ParameterError("dataset", f"several files are named {dup[0]!r} (e.g. "
                             f"{', '.join(Path(s.location).name for s in out if s.name == dup[0])}"
                             "); images are reported by name, so rename one")
    return out
