"""Real raw Bayer input: camera raw (DNG, CR2, NEF, ...), 16-bit Bayer PNG/TIFF, headerless raw.

Every reader gives the library's :class:`~rgbz_fast.RawFrame`: the plain
Bayer CFA with the black level subtracted, scaled to the working bit depth,
its phase recorded as the frame's pattern (``bayer(phase)``) and the file's
facts in ``frame.meta``. :func:`rgbz_fast.io.to_rgbz` then turns such a frame
into an RGB-Z frame and its reference, the paper's protocol for real raw data
[1]_ (the HDR+ burst dataset [2]_). The reader is chosen by the file's
extension (:mod:`rgbz_fast.io._suffixes`).

Camera raw files need the optional dependency rawpy (LibRaw):
``pip install rgbz-fast[raw]``.

References
----------
.. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", section 5.2.2 (HDR+ burst, real Bayer data, 2x binned) (docs/references.bib: rebiere_rgbz)
.. [2] Hasinoff et al., "Burst photography for high dynamic range and low-light imaging on mobile cameras" (docs/references.bib: hasinoff2016hdrplus)
"""

from __future__ import annotations

import numpy as np

from .._frame import RawFrame, _Adopt, _levels_text
from .._patterns import BAYER_PHASES, bayer
from .._validate import (as_list, check_bit_depth, check_dtype, check_flag, check_path,
                         parse_shape)
from ._errors import ParameterError, Setting
from ._files import (_TIFF_MAGIC, check_size, decode_codes, read_file, read_image,
                     read_limits)
from ._libraw import read_libraw
from ._suffixes import HEADERLESS_EXTENSIONS, IMAGE_EXTENSIONS, LIBRAW_EXTENSIONS, RAW_EXTENSIONS

__all__ = ["read_raw", "list_raw_files"]

_READERS = ("libraw", "image", "headerless")
_OUT_DTYPES = (np.dtype(np.uint8), np.dtype(np.uint16), np.dtype(np.float32),
               np.dtype(np.float64))


def read_raw(path, *, phase=None, black_level=None, white_level=None, clip_level=None,
             shape=None, bit_depth_in=None, byteorder="<", bit_depth=11, downsample=1,
             crop_even=False, dtype=np.uint16, reader=None, max_pixels=None, max_bytes=None):
    """Read a raw Bayer file and normalise it to a :class:`~rgbz_fast.RawFrame`.

    Parameters
    ----------
    path : str or os.PathLike
        The file. The reader is chosen by extension (see ``reader``).
    phase : {"RGGB", "BGGR", "GRBG", "GBRG"}, optional
        CFA phase at pixel (0, 0) of the data as read. Camera raw files carry
        it; PNG/TIFF and headerless files need it.
    black_level : float or sequence of 4 floats, optional
        Black level in the file's digital numbers: one value, or one per site
        of the 2x2 quad in raster order ((0, 0), (0, 1), (1, 0), (1, 1)).
        Camera raw files carry it (per channel); other files need it.
    white_level : float or sequence of 4 floats, optional
        The raw value that maps to full scale. Camera raw files carry it;
        otherwise it defaults to ``2**bit_depth_in - 1`` when ``bit_depth_in``
        is given.
    clip_level : float, optional
        Raw values at or above it are flagged as clipped (saturated).
        Defaults to the white level. Some sensors saturate a little below the
        nominal white level (the openISP test frame stops at 1020 of 1023).
        A level at or below the black level (at some quad site), or less
        than half a code of the frame above it, is refused: every pixel would
        be clipped.
    shape : tuple (rows, cols) or str, optional
        Headerless files only: the frame shape, ``(1080, 1920)`` or
        ``"1080x1920"`` (rows first).
    bit_depth_in : int, optional
        Bits of the stored data (recorded in ``meta``; gives the default
        white level of PNG/TIFF and headerless files). Values are taken as
        stored, LSB-aligned.
    byteorder : {"<", ">"}
        Headerless files only: little- (default) or big-endian uint16.
    bit_depth : int or "input"
        Working bit depth of the frame (default 11, as in the paper), or
        ``"input"``: the file's own, ``bit_depth_in`` when given, else the
        bits of its white level (14 for a white level of 15000), so that a
        frame written back keeps the precision of the file.
    downsample : int
        1 (default) or a binning factor k >= 2: each colour plane is binned
        k x k by averaging, i.e. each output Bayer quad is the mean of a k x k
        block of input quads. The phase is kept. k = 2 is the paper's
        treatment of the HDR+ data. The frame is first cropped (bottom/right)
        to a multiple of 2k.
    crop_even : bool
        Crop the last row and/or column so that both dimensions are even
        (whole Bayer quads). The phase is kept, since cropping happens at the
        bottom and the right.
    dtype : {uint16, uint8, float32, float64}
        dtype of ``frame.data``. Integers are rounded half up; floats keep the
        exact scaled values.
    reader : {"libraw", "image", "headerless"}, optional
        Force a reader instead of dispatching on the extension (e.g. a
        Panasonic ``.raw`` camera file needs ``reader="libraw"``).
    max_pixels, max_bytes : int, optional
        Size limits of the read (see :func:`read_limits`): the file's size
        and the frame it declares, checked before decoding.

    Returns
    -------
    RawFrame
        ``pattern`` is ``bayer(phase)``, ``bit_depth`` is ``bit_depth``, and
        ``meta`` holds:

        * ``"source"`` (str), ``"reader"``, ``"phase"``, ``"make"``,
          ``"model"`` (None when unknown), ``"shape_in"`` (shape as read),
        * ``"black_level"``, ``"white_level"`` (tuples of 4 floats, per quad
          site in raster order, original units), ``"clip_level"``,
          ``"bit_depth_in"``, ``"downsample"``, ``"crop"`` (rows, cols of
          the data as read that were kept),
        * ``"clipped"``: ndarray of bool on the output grid, True where the
          pixel is (or, downsampled, any of its binned pixels is) clipped;
        * ``"clipped_count"`` and ``"clipped_fraction"``: pixels at or above
          ``clip_level`` in the original data as read;
        * camera raw files, when LibRaw has them: ``"white_gains"`` (the
          as-shot white balance, R, G, B with G = 1) and ``"colour_matrix"``
          (nine numbers, row by row: white-balanced camera RGB to linear
          sRGB), which the colour ISP applies
          (:func:`rgbz_fast.isp.recorded_rendering`).

    Warns
    -----
    UserWarning
        ``"white_level: ..."`` when more than a quarter
        (:data:`WHITE_SHARE_WARN`, 25 %) of the pixels as read are at or above
        their white level, with the share, the largest value found and the
        usual white levels: such a white level is likely wrong (102 typed for
        1023 clips 59 % of a 10-bit frame). None of the real raw files of
        ``../shared/data/raw`` comes near it at its correct levels: 0 %, 0.003 %
        and 0 % at or above the white level, 9.8 % at the openISP frame's
        saturation level 1020 (its clipped white chart).

    Raises
    ------
    ImportError
        A camera raw file without rawpy installed.
    FileNotFoundError
        The file does not exist.
    ValueError
        A missing phase, level or shape (every one the file lacks, in one
        message that names the first as its parameter), a headerless file
        whose size does not match ``shape``, an unknown extension, a path
        that is not a regular file (a FIFO, a device, a folder), a file
        larger than the limits, a file
        LibRaw, the PNG or the TIFF decoder cannot read (``"path: ..."``), a
        non-Bayer sensor (X-Trans, CMYG), white level not above black.

    Notes
    -----
    Arguments override the values in the file. With ``b`` the working bit
    depth, black level :math:`k_c` and white level :math:`w_c` of the
    pixel's quad site :math:`c`,

    .. math::

        v_{out} = \\operatorname{clip}\\left(\\operatorname{round}\\left(
        \\frac{v - k_c}{w_c - k_c} (2^b - 1)\\right), 0, 2^b - 1\\right)

    Binning (``downsample``) averages the black-subtracted values before the
    clipping at 0, the scaling and the single rounding, so that the noise
    below the black level of dark areas does not bias the binned values.

    A 16-bit TIFF that ``rgbz-fast reconstruct`` wrote records its phase, the
    black level in its data, its white level and its bit depth in its
    description, under the ``"format": "rgbz-fast CFA"`` key
    (:data:`CFA_TIFF_FORMAT`); they are read from it as a camera raw file's
    are (arguments override them). Other TIFFs' descriptions are not read.

    Camera raw files are read from LibRaw's visible area
    (``raw_image_visible``), without the orientation flag applied. Clipped
    pixels are flagged, not altered: see :func:`~rgbz_fast.io.clipped_mask` and
    ``docs/guide/raw.md`` for what the reconstruction does near them.

    Examples
    --------
    >>> import numpy as np, tempfile, os
    >>> from rgbz_fast.io import read_raw
    >>> tmp = tempfile.TemporaryDirectory()
    >>> path = os.path.join(tmp.name, "tiny.raw")
    >>> np.array([[64, 1023], [600, 64]], "<u2").tofile(path)
    >>> f = read_raw(path, shape=(2, 2), phase="GRBG", black_level=64, bit_depth_in=10)
    >>> f.data
    array([[   0, 2047],
           [1144,    0]], dtype=uint16)
    >>> f.meta["clipped_count"], f.meta["white_level"]
    (1, (1023.0, 1023.0, 1023.0, 1023.0))
    >>> tmp.cleanup()
    """
    path = check_path(path, "path")
    kind = _reader_for(path, reader)
    own_depth = isinstance(bit_depth, str) and bit_depth == "input"
    bd = None if own_depth else check_bit_depth(bit_depth)
    out_dtype = check_dtype(dtype, _OUT_DTYPES)
    if out_dtype == np.uint8 and bd is not None and bd > 8:
        raise ValueError(f"dtype: uint8 cannot hold {bd}-bit data")
    k = _check_downsample(downsample)
    crop_even = check_flag(crop_even, "crop_even")
    if bit_depth_in is not None:
        bit_depth_in = check_bit_depth(bit_depth_in, "bit_depth_in")
    if not isinstance(byteorder, str) or byteorder not in ("<", ">"):
        raise ValueError(f"byteorder: expected '<' (little-endian) or '>' (big-endian), "
                         f"got {byteorder!r}")
    if kind != "headerless" and shape is not None:
        raise ValueError(f"shape: only headerless files take a shape; {path.name} is read "
                         f"with the {kind!r} reader")
    if kind != "headerless" and byteorder != "<":     # it had been ignored
        raise ValueError(f"byteorder: only headerless files take a byte order; {path.name} "
                         f"is read with the {kind!r} reader, whose format records its own")
    limits = read_limits(max_pixels, max_bytes)
    given = dict(shape=shape, phase=phase, black_level=black_level, white_level=white_level,
                 bit_depth_in=bit_depth_in)
    if kind == "headerless" and shape is None:       # cannot be read: ask for all it lacks
        _check_settings(path, kind, {}, given)

    if kind == "libraw":
        data, info = read_libraw(path, limits)
    elif kind == "image":
        data, info = _read_image(path, limits)
    else:
        data, info = _read_headerless(path, shape, byteorder, limits), {}
    _check_settings(path, kind, info, given)

    # arguments override the file
    if phase is None:
        phase = info.get("phase")
    phase = str(phase).upper()
    if phase not in BAYER_PHASES:
        raise ValueError(f"phase: expected one of {', '.join(BAYER_PHASES)}, got {phase!r}")
    if black_level is None:
        black_level = info.get("black_level")
    if white_level is None:
        white_level = info.get("white_level")
    if white_level is None:
        white_level = (1 << bit_depth_in) - 1
    black = _quad_levels(black_level, "black_level")
    white = _quad_levels(white_level, "white_level")
    if np.any(white <= black):
        if (given["white_level"] is None and given["black_level"] is None
                and info.get("white_level") is not None and info.get("black_level") is not None):
            # both the file's own: the file is at fault, not an option nobody gave
            raise ValueError(f"path: {path.name} records a white level of "
                             f"{_levels_text(white)}, not above its black level "
                             f"{_levels_text(black)} at every quad site (give both levels to "
                             "read it anyway)")
        raise ValueError(f"white_level: {_levels_text(white)} must exceed black_level "
                         f"{_levels_text(black)} at every quad site")
    if np.issubdtype(data.dtype, np.integer):
        # levels the data cannot reach: a white level of 1e308 made every pixel 0 (and a CFA
        # PSNR of inf); data beyond a stated bit depth was clipped, half a frame silently
        top_code = int(np.iinfo(data.dtype).max)
        if float(white.max()) > top_code:
            raise ValueError(f"white_level: {_levels_text(white)} is beyond the largest code "
                             f"of the {data.dtype} data ({top_code})")
        if given["bit_depth_in"] is not None and float(white.max()) > (1 << bit_depth_in) - 1:
            raise ValueError(f"white_level: {_levels_text(white)} is beyond the "
                             f"{bit_depth_in}-bit range of bit_depth_in "
                             f"[0, {(1 << bit_depth_in) - 1}]")
        if given["bit_depth_in"] is not None and data.size:
            most = int(data.max())
            if most > (1 << int(bit_depth_in)) - 1:
                raise ValueError(f"bit_depth_in: the data of {path.name} reaches {most}, "
                                 f"beyond the {int(bit_depth_in)}-bit range [0, "
                                 f"{(1 << int(bit_depth_in)) - 1}]")
    if own_depth:
        bd = _input_bits(bit_depth_in or info.get("bit_depth_in"), white)
        if out_dtype == np.uint8 and bd > 8:
            raise ValueError(f"dtype: uint8 cannot hold the {bd}-bit data of {path.name}")
    if clip_level is None:
        clip = white
    else:
        clip = _quad_levels(clip_level, "clip_level")
        _check_clip_level(clip, black, white, bd, out_dtype)

    shape_in = data.shape
    clipped_in = data >= _tile_quad(clip, shape_in)
    n_clipped = int(np.count_nonzero(clipped_in))
    _check_white_share(data, white, n_clipped if np.array_equal(clip, white) else None, path,
                       "given" if given["white_level"] is not None else
                       "the file's own" if info.get("white_level") is not None else
                       f"2^{bit_depth_in} - 1 of bit_depth_in")

    # crop (bottom/right, so the phase at (0, 0) is kept)
    r, c = shape_in
    if k > 1:
        r, c = r - r % (2 * k), c - c % (2 * k)
        if r == 0 or c == 0:
            raise ValueError(f"downsample: a {shape_in[0]}x{shape_in[1]} frame holds no "
                             f"{2 * k}x{2 * k} block to bin")
    elif crop_even:
        r, c = r - r % 2, c - c % 2
    if r < 2 or c < 2:
        raise ValueError(f"{path.name}: frame {shape_in[0]}x{shape_in[1]} is smaller than "
                         "one Bayer quad")
    data = data[:r, :c]
    clipped = clipped_in[:r, :c]

    # black subtraction, binning, scaling, one rounding
    black_map = _tile_quad(black, (r, c))
    span_map = _tile_quad(white - black, (r, c))
    # clipped at 0 only after binning: averaging the negative noise of the dark
    # areas keeps the binned black level unbiased
    lin = (data.astype(np.float64) - black_map) / span_map
    if k > 1:
        lin = _bin_planes(lin, k, np.mean)
        clipped = _bin_planes(clipped, k, np.any)
    top = (1 << bd) - 1
    scaled = np.clip(lin * top, 0.0, top)
    if np.issubdtype(out_dtype, np.integer):
        out = np.floor(scaled + 0.5).astype(out_dtype)
    else:
        out = scaled.astype(out_dtype)
    clipped = np.ascontiguousarray(clipped)
    clipped.setflags(write=False)

    meta = {
        "source": str(path),
        "reader": kind,
        "phase": phase,
        "make": info.get("make"),
        "model": info.get("model"),
        "shape_in": tuple(int(s) for s in shape_in),
        "crop": (int(r), int(c)),
        "black_level": tuple(float(v) for v in black.ravel()),
        "white_level": tuple(float(v) for v in white.ravel()),
        "clip_level": tuple(float(v) for v in clip.ravel()),
        "bit_depth_in": bit_depth_in if bit_depth_in is not None else info.get("bit_depth_in"),
        "downsample": k,
        "clipped": clipped,
        "clipped_count": n_clipped,
        "clipped_fraction": n_clipped / float(shape_in[0] * shape_in[1]),
    }
    for key in ("white_gains", "colour_matrix"):       # camera raw files, when LibRaw has them
        if key in info:
            meta[key] = info[key]
    if kind == "headerless":
        meta["byteorder"] = byteorder
    return RawFrame(_Adopt(out), bayer(phase), bd, meta=meta)


#: the keyword arguments of :func:`read_raw` that say how to read one file (what a dataset's
#: or the command line's raw options may set); the others belong to the caller
RAW_OPTIONS = ("phase", "black_level", "white_level", "clip_level", "shape", "bit_depth_in",
               "byteorder", "downsample", "crop_even", "reader")


def check_raw_options(options, name="raw_options"):
    """``options``, a mapping of file names (or ``"*"``) to mappings of :data:`RAW_OPTIONS`,
    as a dict of dicts; a TypeError or ValueError naming ``name`` otherwise (an unknown
    option was a TypeError of read_raw when the file was read)."""
    if options is None:
        return {}
    if not isinstance(options, dict) or not all(isinstance(v, dict) for v in options.values()):
        raise TypeError(f"{name}: expected a mapping of file names (or \"*\") to mappings "
                        f"of options, got {type(options).__name__}")
    for file, opts in options.items():
        unknown = [k for k in opts if k not in RAW_OPTIONS]
        if unknown:
            raise ValueError(f"{name}: {unknown[0]!r} (for {file!r}) is not a raw option; "
                             f"expected some of {', '.join(RAW_OPTIONS)}")
    return {k: dict(v) for k, v in options.items()}


def list_raw_files(folder, *, recursive=False, extensions=None):
    """The raw files of a folder that :func:`read_raw` can read, sorted by path.

    Parameters
    ----------
    folder : str or os.PathLike
        The folder.
    recursive : bool
        Also look in sub-folders.
    extensions : iterable of str, optional
        Extensions to keep (case-insensitive, with the dot). Default:
        :data:`RAW_EXTENSIONS` (camera raw, PNG/TIFF and headerless).

    Returns
    -------
    list of pathlib.Path
        Hidden files (name starting with ".") are skipped.
    """
    recursive = check_flag(recursive, "recursive")
    folder = check_path(folder, "folder")
    if not folder.is_dir():
        raise NotADirectoryError(f"folder: not a directory: {folder}")
    if extensions is not None and not all(
            isinstance(e, str) for e in as_list(extensions, "extensions")):
        raise TypeError(f"extensions: expected a sequence of extensions ('.png', ...), got "
                        f"{extensions!r:.40}")
    exts = RAW_EXTENSIONS if extensions is None else extensions
    exts = {str(e).lower() if str(e).startswith(".") else "." + str(e).lower() for e in exts}
    files = folder.rglob("*") if recursive else folder.iterdir()
    return sorted(p for p in files
                  if p.is_file() and not p.name.startswith(".") and p.suffix.lower() in exts)



# --------------------------------------------------------------------------- readers
def _reader_for(path, reader):
    if reader is not None:
        if not isinstance(reader, str) or reader.lower() not in _READERS:
            raise ValueError(f"reader: expected one of {', '.join(map(repr, _READERS))}, "
                             f"got {reader!r}")
        return reader.lower()
    ext = path.suffix.lower()
    if ext in LIBRAW_EXTENSIONS:
        return "libraw"
    if ext in IMAGE_EXTENSIONS:
        return "image"
    if ext in HEADERLESS_EXTENSIONS:
        return "headerless"
    raise ParameterError("path", f"unknown raw extension {ext or '(none)'!r} of {path.name}; "
                                 f"expected a camera raw ({', '.join(LIBRAW_EXTENSIONS[:6])}, "
                                 f"...), {'/'.join(IMAGE_EXTENSIONS)} or headerless "
                                 f"{'/'.join(HEADERLESS_EXTENSIONS)}, or ",
                         Setting("reader", "pass reader="))


#: the ``format`` of the description of the CFA TIFFs rgbz-fast writes (``rgbz-fast
#: reconstruct``): a key no other program writes, by which :func:`read_raw` knows to read
#: the phase and levels the description records (the keys of other files are not trusted)
CFA_TIFF_FORMAT = "rgbz-fast CFA"


def cfa_tiff_description(phase, black_level, white_level, bit_depth, **extra):
    """The JSON description of a CFA TIFF rgbz-fast writes: its Bayer phase, the black level
    that stays in its data, its white level and the bits of its data, which :func:`read_raw`
    reads back (``extra``: other keys, recorded and not read)."""
    import json

    return json.dumps({"format": CFA_TIFF_FORMAT, "bayer": phase,
                       "black_level": float(black_level), "white_level": float(white_level),
                       "bit_depth": int(bit_depth), **extra})


def _cfa_tiff_info(description, path):
    """What a CFA TIFF written by rgbz-fast records (:func:`cfa_tiff_description`), as the
    ``info`` of a reader: {} for any other file, whatever its description holds."""
    import json

    try:
        d = json.loads(description or "")
    except (ValueError, RecursionError):
        return {}
    if not isinstance(d, dict) or d.get("format") != CFA_TIFF_FORMAT:
        return {}
    phase, black, white, bits = (d.get(k) for k in ("bayer", "black_level", "white_level",
                                                    "bit_depth"))
    num = (int, float)
    if not (phase in BAYER_PHASES and all(isinstance(v, num) and not isinstance(v, bool)
                                          for v in (black, white))
            and type(bits) is int and 1 <= bits <= 16 and 0 <= black < white < 1 << bits):
        raise ValueError(f"path: {path.name} is a CFA TIFF of rgbz-fast whose description is "
                         f"damaged (phase {phase!r:.12}, black level {black!r:.12}, white "
                         f"level {white!r:.12}, bit depth {bits!r:.12})")
    return {"phase": phase, "black_level": float(black), "white_level": float(white),
            "bit_depth_in": bits}


def _read_image(path, limits):
    desc = []

    def decode(blob):
        data = decode_codes(blob)                   # its errors as before
        if blob[:4] in _TIFF_MAGIC:                 # a TIFF: its description too
            from ._tiff import open_tiff

            with open_tiff(blob) as tf:
                desc.append(tf.pages[0].description)
        return data

    data = read_image(path, "path", decode, max_pixels=limits[0], max_bytes=limits[1])
    info = _cfa_tiff_info(desc[0], path) if desc else {}
    if data.ndim != 2:
        raise ValueError(f"{path.name}: expected a single-channel Bayer mosaic, got an image "
                         f"of shape {data.shape} (a demosaicked RGB image is not raw data)")
    if data.dtype not in (np.uint8, np.uint16):
        raise ValueError(f"{path.name}: expected uint8 or uint16 samples, got {data.dtype}")
    return np.ascontiguousarray(data, dtype=np.uint16), info


#: what a reader asks for when the file does not record it: (what the file lacks, how to give it)
_SETTINGS = {
    "shape": ("its size", (Setting("shape", "shape=(rows, cols)"),)),
    "phase": ("its CFA phase", (Setting("phase"), f" (one of {', '.join(BAYER_PHASES)})")),
    "black_level": ("its black level", (Setting("black_level"),
                                        " (one value or four, per quad site)")),
    "white_level": ("its white level", (Setting("white_level"), " (or ", Setting("bit_depth_in"),
                                        "; the white level is then 2^bits - 1)")),
}


def _input_bits(bit_depth_in, white):
    """The bits of the data as stored: ``bit_depth_in``, else those of the largest white
    level (15000 -> 14), within 1..16."""
    if bit_depth_in is not None:
        return int(bit_depth_in)
    return int(min(16, max(1, np.ceil(np.log2(float(np.max(white)) + 1)))))


def _check_settings(path, kind, info, given):
    """One error naming every setting that neither the file (``info``) nor the arguments
    (``given``) provide, so that a caller learns them all at once."""
    missing = [k for k in ("shape", "phase", "black_level") if given[k] is None
               and info.get(k) is None and (k != "shape" or kind == "headerless")]
    if given["white_level"] is None and info.get("white_level") is None \
            and given["bit_depth_in"] is None:
        missing.append("white_level")
    if not missing:
        return
    if missing == ["shape"]:
        raise ParameterError("shape", f"the headerless file {path.name} needs ",
                             Setting("shape", "shape=(rows, cols)"))
    nouns = [_SETTINGS[k][0] for k in missing]
    parts = [f"{path.name} does not record {_series(nouns, ' or ')}; pass "]
    for j, k in enumerate(missing):
        if j:
            parts.append(" and " if j == len(missing) - 1 else ", ")
        parts.extend(_SETTINGS[k][1])
    raise ParameterError(missing[0], *parts)


def _series(words, last):
    """'a', 'a or b', 'a, b or c'."""
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + last + words[-1]


def _read_headerless(path, shape, byteorder, limits):
    if isinstance(shape, str):                           # "1080x1920", as on the command line
        shape = parse_shape(shape)
    try:
        rows_, cols = (int(s) for s in shape)
    except (TypeError, ValueError):
        raise ValueError(f"shape: expected (rows, cols), got {shape!r}") from None
    if rows_ < 1 or cols < 1:
        raise ValueError(f"shape: expected positive (rows, cols), got {shape!r}")
    check_size((rows_, cols), 2, path, "path", limits=limits)
    blob = read_file(path, "path", max_bytes=limits[1])
    size = len(blob)
    expected = rows_ * cols * 2
    if size != expected:
        raise ValueError(f"shape: {path.name} holds {size} bytes, but {rows_}x{cols} uint16 "
                         f"pixels need {expected} (rows * cols * 2); check shape and that "
                         "the file has no header")
    data = np.frombuffer(blob, dtype=np.dtype(byteorder + "u2")).reshape(rows_, cols)
    return data.astype(np.uint16)        # native byte order, a copy


# --------------------------------------------------------------------------- levels, binning
#: the share of a frame's pixels at or above its white level beyond which :func:`read_raw`
#: warns that the white level is likely wrong (a typo: 102 for 1023 clips 59 % of a 10-bit
#: frame). Measured at their correct levels, the real raw files of ../shared/data/raw hold
#: 0 % (colorchart.dng, white 15000; openisp_test.RAW, white 1023) and 0.003 %
#: (halide_bayer_small.png, white 1023); the brightest, openisp_test.RAW's clipped white
#: chart, holds 9.8 % at its saturation level 1020. A quarter is 2.5 times that; the colour
#: ISP warns of a CFA more than half above its white level (H81), the rendering of a frame
#: already read.
WHITE_SHARE_WARN = 0.25

#: the white levels of the usual raw bit depths, 2^bits - 1, that the warning suggests
_USUAL_WHITE = {10: 1023, 12: 4095, 14: 16383, 16: 65535}


def _check_white_share(data, white, n_at_white, path, source):
    """A UserWarning naming ``white_level`` when more than :data:`WHITE_SHARE_WARN` of the
    data as read (``data``) are at or above the white level of their quad site (``white``):
    such a frame is mostly clipped to full scale, silently, and the level is far more likely
    a typo than the scene (``--white-level 102`` for 1023 wrote outputs, exit 0, while the
    same mistake as ``--bit-depth-in 7`` was refused, H10). ``n_at_white``: that count when
    known (the clipped count, when the clip level is the white level); ``source``: where
    the white level came from."""
    import warnings

    from .._validate import outside_stacklevel

    if not data.size:
        return
    if n_at_white is None:
        n_at_white = int(np.count_nonzero(data >= _tile_quad(white, data.shape)))
    share = n_at_white / data.size
    if share <= WHITE_SHARE_WARN:
        return
    most = int(data.max()) if np.issubdtype(data.dtype, np.integer) else float(data.max())
    usual = ", ".join(f"{w} for {b}-bit data" for b, w in _USUAL_WHITE.items())
    warnings.warn(f"white_level: {100 * share:.1f} % of the pixels of {path.name} are at or "
                  f"above its white level {_levels_text(white)} ({source}) and are clipped "
                  f"to full scale; the largest value found is {most:g}: is the white level "
                  f"the file's? (the usual ones are 2^bits - 1: {usual}; or give "
                  "bit_depth_in=BITS instead)", UserWarning, stacklevel=outside_stacklevel())


def _check_clip_level(clip, black, white, bd, out_dtype):
    """A ValueError naming ``clip_level`` when the saturation level, at some quad site, is
    at or below the black level, or so close to it that it rounds to code 0 of the frame
    (``bd`` bits, ``out_dtype``): every pixel would be taken as clipped. Checked
    where the level enters, so that the error comes before any work and names the level
    given (it had come from the reconstruction, as ``clip_level: (np.float64(20.0), ...)``,
    which the command line read as its --clip-level)."""
    low = clip <= black
    if np.any(low):
        which = "every pixel" if np.all(low) else "every pixel of a quad site where it is"
        raise ValueError(f"clip_level: {_levels_text(clip)} is at or below the black level "
                         f"{_levels_text(black)}: {which} would be clipped")
    if np.issubdtype(out_dtype, np.integer):
        # what frame_clip_level takes: the smallest level scaled to the frame, rounded
        scaled = float(np.min((clip - black) / (white - black) * ((1 << bd) - 1)))
        if np.floor(scaled + 0.5) <= 0:
            raise ValueError(f"clip_level: {_levels_text(clip)} is less than half a code of "
                             f"the {bd}-bit frame above the black level "
                             f"{_levels_text(black)}: every pixel would be clipped")


def _check_downsample(k):
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 1:
        raise ValueError(f"downsample: expected a positive integer binning factor, got {k!r}")
    return int(k)


def _quad_levels(value, name):
    """A scalar or 4 values (quad raster order) -> float64 array of shape (2, 2)."""
    if isinstance(value, (str, bytes, bool, np.bool_)):
        raise TypeError(f"{name}: expected a number or four numbers, got {value!r}")
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a number or four numbers, got {value!r}") from None
    if arr.ndim == 0:
        arr = np.full((2, 2), float(arr))
    elif arr.size == 4:
        arr = arr.reshape(2, 2)
    else:
        raise ValueError(f"{name}: expected one value or four (one per 2x2 quad site), "
                         f"got {np.shape(value)}")
    if not np.all(np.isfinite(arr)) or np.any(arr < 0):
        raise ValueError(f"{name}: expected finite non-negative values, got "
                         f"{_levels_text(arr)}")
    return arr


def _tile_quad(quad, shape):
    r, c = shape
    return np.tile(quad, (-(-r // 2), -(-c // 2)))[:r, :c]


def _bin_planes(a, k, reduce):
    """Bin each colour plane of a mosaic k x k (shape a multiple of 2k); the phase is kept."""
    r, c = a.shape
    # (row-block, row-in-block, row-phase, col-block, col-in-block, col-phase)
    v = a.reshape(r // (2 * k), k, 2, c // (2 * k), k, 2)
    out = reduce(v, axis=(1, 4))
    return out.reshape(r // k, c // k)
