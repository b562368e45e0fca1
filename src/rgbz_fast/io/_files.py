"""Files: atomic writes, bounded reads with size limits, and the one reader that decodes images.

Every file the library writes goes through :func:`atomic_write` (a temporary
file in the same folder, then a rename), so a crash, an error or a SIGTERM
never leaves a half-written file under the final name, nor a temporary file.
Every file it reads goes through :func:`read_file` (a regular file -- not a
FIFO, a device or a folder -- of at most ``max_bytes``), and every image file
through :func:`read_image`, which checks the size the file declares against
the limits (:func:`read_limits`) before decoding it and turns a file that does
not decode into a ValueError naming the parameter and the path.
"""

from __future__ import annotations

import io
import os
import secrets
import stat
import struct
import warnings
from pathlib import Path

import numpy as np

from .._validate import as_array, as_list, check_flag, check_path, integer_bits
from ._decode import PNM_MAGIC, decode_pillow, decode_pnm, decode_tiff
from ._errors import ParameterError, Setting

__all__ = ["atomic_write", "read_image", "read_file", "rgb_image", "sample_bits", "read_limits",
           "check_size",
           "DEFAULT_MAX_PIXELS", "DEFAULT_MAX_BYTES", "MAX_PIXELS_ENV", "MAX_BYTES_ENV"]

#: default largest image (rows x cols) a reader decodes: 200 megapixels
DEFAULT_MAX_PIXELS = 200_000_000
#: default largest file a reader reads, and largest array it decodes: 2 GiB
DEFAULT_MAX_BYTES = 2 * 2**30
#: environment variables that replace the defaults when a call gives no limit
MAX_PIXELS_ENV = "RGBZ_FAST_MAX_PIXELS"
MAX_BYTES_ENV = "RGBZ_FAST_MAX_BYTES"


def raise_it(limit):
    """The advice of an error about a read limit: how to raise ``limit`` ("max_pixels" or
    "max_bytes"), as message parts of a :class:`ParameterError`."""
    env = MAX_PIXELS_ENV if limit == "max_pixels" else MAX_BYTES_ENV
    return ("; raise it with ", Setting(limit), f" or {env}")


def _limit(value, name, env, default):
    if value is None:
        text = os.environ.get(env, "").strip()
        if not text:
            return default
        try:
            value = int(text.replace("_", ""))
        except ValueError:
            raise ParameterError(env, f"expected a positive integer, got {text!r}") from None
        if value < 1:
            raise ParameterError(env, f"expected a positive integer, got {text!r}")
        return value
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name}: expected a positive integer, got {value!r}")
    if value < 1:
        raise ParameterError(name, f"expected a positive integer, got {value!r}")
    return min(int(value), _NO_LIMIT)       # a limit beyond any file is no limit


#: a limit larger than any file or image (and than what a read may ask for)
_NO_LIMIT = 1 << 62


def read_limits(max_pixels=None, max_bytes=None):
    """The size limits of a read: ``(max_pixels, max_bytes)``.

    Each is the argument when given, else the environment variable
    (``RGBZ_FAST_MAX_PIXELS``, ``RGBZ_FAST_MAX_BYTES``), else the default
    (:data:`DEFAULT_MAX_PIXELS`, 200 megapixels; :data:`DEFAULT_MAX_BYTES`,
    2 GiB). Every reader takes ``max_pixels`` and ``max_bytes`` and passes
    them on; the environment variables set the limits of a whole program
    (and of the processes it starts) without changing its calls.

    Examples
    --------
    >>> from rgbz_fast.io import read_limits
    >>> read_limits(max_pixels=4096)[0]
    4096
    >>> read_limits(max_pixels=0)
    Traceback (most recent call last):
    ...
    rgbz_fast.io.ParameterError: max_pixels: expected a positive integer, got 0
    """
    return (_limit(max_pixels, "max_pixels", MAX_PIXELS_ENV, DEFAULT_MAX_PIXELS),
            _limit(max_bytes, "max_bytes", MAX_BYTES_ENV, DEFAULT_MAX_BYTES))


def check_size(shape, itemsize, path, name="path", *, limits=None):
    """:class:`ParameterError` naming ``name`` when an array of ``shape`` breaks the limits.

    ``shape`` is what a file declares (rows, cols, ...): its first two
    dimensions are the pixels, and the product times ``itemsize`` the bytes
    it decodes to. Called before the array is allocated.
    """
    if limits is not None and (not isinstance(limits, (tuple, list)) or len(limits) != 2):
        raise TypeError(f"limits: expected (max_pixels, max_bytes), got {limits!r:.40}")
    max_pixels, max_bytes = read_limits(*(limits or ()))
    if not all(isinstance(s, (int, np.integer)) and not isinstance(s, bool) and s >= 0
               for s in as_list(shape, "shape", "a sequence of sizes")):
        raise TypeError(f"shape: expected a sequence of sizes (integers >= 0), got "
                        f"{shape!r:.40}")
    if isinstance(itemsize, bool) or not isinstance(itemsize, (int, np.integer)) \
            or itemsize < 1:
        raise TypeError(f"itemsize: expected a positive number of bytes, got {itemsize!r}")
    shape = tuple(int(s) for s in shape)
    pixels = int(np.prod(shape[:2], dtype=object)) if shape else 1
    nbytes = int(np.prod(shape, dtype=object)) * int(itemsize)
    dims = "x".join(str(s) for s in shape)
    if pixels > max_pixels:
        raise ParameterError(name, f"{path} declares a {dims} image ("
                                   + (f"{pixels / 1e6:.1f} megapixels" if pixels >= 100_000
                                      else f"{pixels} pixels")      # not '0.0 megapixels'
                                   + f"), more than the limit of {max_pixels} pixels",
                             *raise_it("max_pixels"))
    if nbytes > max_bytes:
        raise ParameterError(name, f"{path} declares {dims} values of {itemsize} bytes "
                                   f"({nbytes} bytes), more than the limit of {max_bytes} bytes",
                             *raise_it("max_bytes"))


def _file_kind(mode):
    for test, kind in ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return kind
    return "not a regular file"


def _existing_kind(path):
    """What ``path`` is when it exists and is not a regular file or a folder (a device, a
    FIFO, a socket), else None."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return None
    return None if stat.S_ISREG(mode) or stat.S_ISDIR(mode) else _file_kind(mode)


def read_file(path, name="path", *, max_bytes=None):
    """The bytes of a regular file, read at most ``max_bytes`` (never blocks, never unbounded).

    Parameters
    ----------
    path : str or os.PathLike
        The file (symbolic links are followed).
    name : str
        The parameter named in the errors.
    max_bytes : int, optional
        The largest file accepted (see :func:`read_limits`).

    Raises
    ------
    FileNotFoundError
        The file does not exist.
    ValueError
        ``"{name}: ..."``: the path is a folder, a FIFO, a device or a
        socket (``/dev/zero`` or a named pipe would read forever or block),
        the file is larger than ``max_bytes``, or it cannot be read.

    Examples
    --------
    >>> from rgbz_fast.io import read_file
    >>> read_file("/dev/zero")
    Traceback (most recent call last):
    ...
    rgbz_fast.io.ParameterError: path: /dev/zero is a character device, not a regular file
    """
    p = check_path(path, name)
    # the byte limit alone: a bad RGBZ_FAST_MAX_PIXELS broke every read, --max-pixels given
    limit = _limit(max_bytes, "max_bytes", MAX_BYTES_ENV, DEFAULT_MAX_BYTES)
    try:
        # O_NONBLOCK: opening a FIFO for reading would wait for a writer
        fd = os.open(p, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        raise FileNotFoundError(f"{name}: no such file: {p}") from None
    except IsADirectoryError:
        raise ParameterError(name, f"{p} is a folder, not a regular file") from None
    except OSError as exc:
        raise ParameterError(name, f"cannot open {p} ({exc.strerror or exc})") from None
    st = os.fstat(fd)                  # the file opened, not what the name points to now
    if not stat.S_ISREG(st.st_mode):
        os.close(fd)
        kind = _file_kind(st.st_mode)
        raise ParameterError(name, f"{p} is {kind}"
                             + ("" if kind.startswith("not") else ", not a regular file"))
    with os.fdopen(fd, "rb") as fh:
        if st.st_size > limit:
            raise ParameterError(name, f"{p} is {st.st_size} bytes, more than the limit of "
                                       f"{limit} bytes", *raise_it("max_bytes"))
        try:
            data = _read_bounded(fh, st.st_size, limit)
        except OSError as exc:
            raise ParameterError(name, f"cannot read {p} ({exc.strerror or exc})") from None
    if len(data) > limit:
        raise ParameterError(name, f"{p} grew beyond the limit of {limit} bytes while being "
                                   "read")
    return data


def _read_bounded(fh, size, limit):
    """At most ``limit + 1`` bytes of ``fh``: the ``size`` its fstat gave first, then 1 MiB
    at a time if it grew meanwhile (a read of ``limit + 1`` bytes at once allocates that
    much, whatever the file holds)."""
    parts, total = [], 0
    want = min(limit, size) + 1
    while total <= limit:
        part = fh.read(want)
        if not part:
            break
        parts.append(part)
        total += len(part)
        want = min(1 << 20, limit + 1 - total)
    return b"".join(parts)


def _unlink(path):
    try:
        os.unlink(path)
    except OSError:
        pass


def _temporary_stem(path):
    """The part of ``path``'s name its temporary file keeps: all of it, or as much as fits
    the folder's longest name with the 22 bytes the temporary name adds (a 240-byte output
    name is valid; its temporary name of 262 bytes was not)."""
    try:
        longest = os.pathconf(path.parent, "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):
        longest = 255
    room = max(longest - 22, 8)
    raw = os.fsencode(path.name)
    return path.name if len(raw) <= room else os.fsdecode(raw[:room])


def atomic_write(path, data):
    """Write text or bytes to ``path`` through a temporary file and a rename: never half-written.

    The temporary file is hidden (``.NAME.XXXXXXXXXXXXXXXX.tmp``, a random
    name created exclusively) in the destination folder and removed if the
    write fails or is interrupted (an exception, Ctrl-C, or a SIGTERM, which
    the command line turns into an exception); the file gets the permissions
    the umask gives a new file. Text is written as UTF-8, a lone surrogate in it
    escaped (``\\udce9``: how Python names the byte 0xE9 of a file name that is not
    UTF-8, such as ``b"caf\\xe9.png"``). A symbolic link is
    followed: the file it names is replaced, the link stays. A device, a
    FIFO or a socket at ``path`` is refused (a ValueError naming ``path``):
    the rename would have put a regular file in its place.

    Examples
    --------
    >>> import os, tempfile
    >>> from rgbz_fast.io import atomic_write
    >>> d = tempfile.TemporaryDirectory()
    >>> atomic_write(os.path.join(d.name, "a.txt"), "±1 dB")
    >>> os.listdir(d.name)
    ['a.txt']
    >>> d.cleanup()
    """
    tmp, path = _write_temporary(path, data)
    try:
        os.replace(tmp, path)
    except BaseException:
        _unlink(tmp)
        raise


def atomic_write_all(items, before_renames=None):
    """Write every ``(path, data)`` of ``items`` as :func:`atomic_write` does, all or none:
    each to its temporary file first, and only when every one is written (a full disk
    fails one of them), the renames, in order. A failure or an interrupt before the renames
    removes the temporary files and leaves every destination as it was; an error names the
    file. ``before_renames``: called once every file is written, before the first rename.
    Returns the destination paths (a link's target where a path is a symbolic link)."""
    written = []
    try:
        for path, data in items:
            written.append(_write_temporary(path, data))
        if before_renames is not None:
            before_renames()
        for tmp, path in written:
            os.replace(tmp, path)
    except BaseException:
        for tmp, _ in written:
            _unlink(tmp)                # those renamed are gone already: nothing to undo
        raise
    return [path for _, path in written]


def _write_temporary(path, data):
    """The checks of :func:`atomic_write`, then ``data`` in a new temporary file beside
    ``path``, flushed to the disk: (the temporary file, the destination). Nothing is left
    behind on a failure; an OSError that named no file names ``path``."""
    if not isinstance(data, (str, bytes, bytearray, memoryview)):
        raise TypeError(f"data: expected str or bytes, got {type(data).__name__}")
    path = check_path(path, "path")
    if path.is_symlink():                          # the file it names is replaced, as by open()
        path = Path(os.path.realpath(path))
    if path.is_dir():                              # os.replace would name the temporary file
        raise ParameterError("path", f"{path} is a folder; expected a file to write")
    kind = _existing_kind(path)
    if kind is not None:                           # a device or a FIFO: never replaced by a file
        raise ParameterError("path", f"{path} is {kind}, not a regular file; expected a file "
                                     "to write")
    path.parent.mkdir(parents=True, exist_ok=True)
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    stem = _temporary_stem(path)
    while True:
        tmp = path.parent / f".{stem}.{secrets.token_hex(8)}.tmp"
        try:
            fd = os.open(tmp, flags, 0o666)        # the umask applies, as to any new file
            break
        except FileExistsError:
            continue                               # not ours: never touched
        except BaseException:
            # the name is random and created exclusively, so if it exists now this call
            # made it, and an interrupt may land between the creation and the assignment
            _unlink(tmp)
            raise
    try:
        # errors: a report that names an image whose file name is not UTF-8 holds the
        # surrogate Python decodes its byte to, which strict UTF-8 refused, and with it the
        # whole report after the evaluation ("surrogates not allowed", naming nothing);
        # escaped, the name stays readable (the last two hex digits are the byte), and
        # inside a JSON string the escape is JSON's own: the same name read back
        with os.fdopen(fd, "w" if isinstance(data, str) else "wb",
                       **({"encoding": "utf-8", "errors": "backslashreplace"}
                          if isinstance(data, str) else {})) as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
    except BaseException as exc:
        _unlink(tmp)
        if isinstance(exc, OSError) and exc.filename is None and exc.errno is not None:
            # a write's or an fsync's error (a full disk, a quota) names no file: the command
            # line said "error: [Errno 28] No space left on device" of nothing in particular
            raise OSError(exc.errno, exc.strerror, str(path)) from exc
        raise
    return tmp, path


_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_TIFF_MAGIC = (b"II*\x00", b"MM\x00*", b"II+\x00", b"MM\x00+")
#: samples per pixel of the PNG colour types (grey, RGB, palette, grey + alpha, RGBA)
_PNG_CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


def _png_header(data):
    """(rows, cols, channels, bit depth) from a PNG's IHDR chunk, or None."""
    if len(data) < 33 or data[:8] != _PNG_SIGNATURE or data[12:16] != b"IHDR":
        return None
    cols, rows, bits, colour = struct.unpack(">IIBB", data[16:26])
    return rows, cols, _PNG_CHANNELS.get(colour, 4), bits


def _declared_shape(data):
    """(shape, itemsize) an image file declares in its header, before any decoding; or None.

    PNG: the IHDR chunk. TIFF: the tags of the first page. Other formats:
    Pillow's lazy ``Image.open``, which reads the header only. None when the
    header cannot be read (the decoder then reports the file as unreadable).
    """
    png = _png_header(data)
    if png is not None:
        rows, cols, channels, bits = png
        return (rows, cols, channels), 2 if bits == 16 else 1
    try:
        if data[:4] in _TIFF_MAGIC:
            from ._tiff import open_tiff

            with open_tiff(data) as tf:
                page = tf.pages[0]
                return tuple(page.shape), np.dtype(page.dtype).itemsize
        from PIL import Image

        with Image.open(io.BytesIO(data)) as im:
            cols, rows = im.size
            return (rows, cols, len(im.getbands())), 2 if im.mode.startswith("I;16") else 4 \
                if im.mode in ("I", "F") else 1
    except Exception:  # noqa: BLE001 - a header no parser reads: the decoder says why
        return None


def _decode_png16_colour(data):
    """A 16-bit RGB or RGBA PNG at full precision (Pillow keeps only the high bytes).

    Pillow unfilters and inflates the image data correctly (bytes per pixel 6
    or 8) and then unpacks one byte of each big-endian sample: ``RGB;16B``
    gives the high bytes, ``RGB;16L`` -- little-endian unpacking of the same
    bytes -- the low ones. Decoding twice and combining them gives the 16-bit
    values with Pillow's own (tested) decoder, interlaced files included.
    """
    from PIL import Image

    # a tile is (decoder, extents, offset, args): a NamedTuple since Pillow 11, a plain
    # tuple before (the attribute .args and _replace had made every 16-bit colour PNG
    # unreadable with Pillow 9 and 10)
    def with_rawmode(t, rawmode):
        args = t[3]
        args = rawmode if isinstance(args, str) else (rawmode,) + tuple(args[1:])
        return t._replace(args=args) if hasattr(t, "_replace") else (*t[:3], args)

    def plane(rawmode):
        with Image.open(io.BytesIO(data)) as im:
            im.tile = [with_rawmode(t, rawmode) for t in im.tile]
            im.load()
            return np.asarray(im, dtype=np.uint16)

    with Image.open(io.BytesIO(data)) as im:
        high = im.tile[0][3]
        high = high if isinstance(high, str) else high[0]
    if high not in ("RGB;16B", "RGBA;16B"):
        raise ValueError(f"unexpected 16-bit PNG layout {high!r} in this Pillow version")
    return (plane(high) << 8) | plane(high[:-1] + "L")


def _decode_default(data, suffix):
    png = _png_header(data)
    if png is not None and png[3] == 16:
        if png[2] in (3, 4):
            return _decode_png16_colour(data)
        if png[2] == 2:
            raise ValueError("a 16-bit grey + alpha PNG cannot be read at full precision; "
                             "save it without alpha")
    if data[:4] in _TIFF_MAGIC:
        return decode_tiff(data)
    if data[:2] in PNM_MAGIC:
        return decode_pnm(data)
    if png is not None:
        from PIL import UnidentifiedImageError

        try:
            plain = _decode_png8(data) if png[3] == 8 else None   # None: imageio's case
            if plain is not None:
                return plain
            out = _decode_png_pillow(data)
            if png[3] == 16 and data[25] == 0 and out.dtype == np.int32:
                # a 16-bit grey PNG: Pillow 10.1 with imageio 2.30 (the floors) opens it in
                # mode "I" and gives int32 samples, each the 16-bit code (H118)
                out = out.astype(np.uint16)
            return out
        except UnidentifiedImageError:                 # its message shows a memory address
            raise ValueError("a damaged PNG that Pillow cannot identify: a chunk's CRC or "
                             "the header") from None
    return decode_pillow(data)


def _decode_png_pillow(data):
    """The other PNGs (palette, 1-4 bits, 16-bit grey, ...) by imageio's Pillow plugin alone:
    on a damaged file imageio tried its other plugins in turn, and OpenCV's and libpng's lines
    reached stderr before an error of "index `Ellipsis`". A palette index beyond the PLTE
    is refused (Pillow painted it black), and Pillow's advice to convert a palette image
    with a transparency chunk is not passed on (the image is read as its colours)."""
    import imageio.v3 as iio
    from PIL import Image

    if data[25] == 3:                                   # colour type 3: a palette
        entries = _png_palette_entries(data)
        if entries is not None:
            with Image.open(io.BytesIO(data)) as im:
                top = int(np.asarray(im).max(initial=0))
            if top >= entries:
                raise ValueError(f"palette index {top} beyond its PLTE of {entries} entries")
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Palette images with Transparency")
        return iio.imread(data, extension=".png", plugin="pillow")


def _png_palette_entries(data):
    """The number of colours of a PNG's PLTE chunk, or None when the chunks cannot be walked
    to it (the decoder then says what is wrong)."""
    pos = 8
    while pos + 8 <= len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"PLTE":
            return n // 3
        if kind == b"IDAT":
            return None
        pos += 12 + n
    return None


def decode_codes(data):
    """As the default decoder, but a TIFF's samples stay the codes it stores when they fill
    fewer bits than their type (a 12-bit raw mosaic in uint16: its white level is its own;
    :func:`~rgbz_fast.io._decode.decode_tiff`'s ``full_range``)."""
    if data[:4] in _TIFF_MAGIC:
        return decode_tiff(data, full_range=False)
    return _decode_default(data, "")


def _decode_png8(data):
    """An 8-bit grey, grey + alpha, RGB or RGBA PNG of one frame, as ``imageio.v3.imread``
    reads it (its Pillow plugin: the pixels of Pillow's decoder in its mode, a writeable
    copy), without imageio's plugin machinery; None for what imageio converts or stacks
    (palettes, animated PNGs) and for what Pillow opens in another mode."""
    from PIL import Image

    with Image.open(io.BytesIO(data)) as im:
        if im.format != "PNG" or im.mode not in ("L", "LA", "RGB", "RGBA") \
                or getattr(im, "custom_mimetype", None) == "image/apng":
            return None
        return np.array(im)


def read_image(path, name="path", decode=None, *, max_pixels=None, max_bytes=None):
    """Decode an image file (PNG, TIFF, ...) read into memory first, as an ndarray.

    Parameters
    ----------
    path : str or os.PathLike
        The file; a missing file raises ``FileNotFoundError`` (callers check
        existence first when they promise another error).
    name : str
        The parameter named in the error message.
    decode : callable, optional
        ``decode(data: bytes) -> array_like``; default: by the format the
        bytes start with, whatever the extension: 16-bit RGB(A) PNGs at full
        precision, the first page of a TIFF (palette colours, MINISWHITE
        inverted, planar samples interleaved, samples of fewer bits than
        their type scaled to its range), PGM/PPM at 8 or 16 bits, other
        formats through Pillow (first frame, palette colours); CMYK, CIELAB
        and YCbCr samples are refused (:mod:`rgbz_fast.io._decode`).
    max_pixels, max_bytes : int, optional
        Size limits (see :func:`read_limits`): the file's size, the image
        size its header declares (checked before decoding) and the decoded
        array.

    Returns
    -------
    ndarray
        As stored: uint8 or uint16 (16-bit PNGs, grey or colour, keep their
        16 bits), shape (rows, cols) or (rows, cols, channels); but a PGM/PPM
        whose maximum value is not 255 or 65535 (a 12-bit PGM: 4095) is
        rescaled to the full range of its type, as its format defines the
        samples relative to that maximum.

    Raises
    ------
    ValueError
        ``"{name}: cannot read {path} as an image (...)"`` when the bytes do
        not decode, or decode to no pixel; ``"{name}: ..."`` when the path is
        not a regular file or the image is larger than the limits.

    Notes
    -----
    imageio leaks the file handles it opens when a file fails to decode
    (``ResourceWarning``) and raises ``OSError``, ``ValueError`` and other
    types depending on the plugin; decoding bytes leaves nothing to leak and
    gives one exception type. The reason is kept on one line (the command
    line prints one line per error). Pillow reads 16-bit colour PNGs as 8-bit
    (it drops the low byte); they are decoded here at full precision.

    Examples
    --------
    >>> import numpy as np, os, tempfile
    >>> from rgbz_fast.io import read_image
    >>> d = tempfile.TemporaryDirectory()
    >>> path = os.path.join(d.name, "grey16.png")
    >>> import imageio.v3 as iio
    >>> iio.imwrite(path, np.array([[0, 65535]], np.uint16))
    >>> read_image(path)
    array([[    0, 65535]], dtype=uint16)
    >>> read_image(path, max_pixels=1)
    Traceback (most recent call last):
    ...
    rgbz_fast.io.ParameterError: path: ... declares a 1x2x1 image (2 pixels), more than the limit of 1 pixels; ...
    >>> d.cleanup()
    """
    p = check_path(path, name)
    limits = read_limits(max_pixels, max_bytes)
    data = read_file(p, name, max_bytes=limits[1])
    declared = _declared_shape(data)
    if declared is not None:
        check_size(*declared, p, name, limits=limits)
    try:
        img = decode(data) if decode is not None else _decode_default(data, p.suffix.lower())
        img = np.asarray(img)
    except Exception as exc:  # noqa: BLE001 - the decoders raise many types for bad data
        reason = " ".join(str(exc).split()) or type(exc).__name__
        raise ParameterError(name, f"cannot read {p} as an image ({reason})") from None
    if img.size == 0:
        raise ParameterError(name, f"cannot read {p} as an image (it decodes to no pixel, "
                                   f"shape {img.shape})")
    check_size(img.shape, img.dtype.itemsize, p, name, limits=limits)
    return img


def rgb_image(img, path, name="path", *, grey=False):
    """An image as read (RGB, RGBA, grey, grey + alpha) as RGB, or a ValueError naming ``name``.

    The one grey-image policy of the library (scenes, datasets, the command
    line): a grey image is refused -- a colour sensor needs colour, and a
    grey image in a colour dataset is more often a mistake than a wish --
    unless ``grey=True``, which repeats its one channel into R, G and B (a
    neutral scene). Alpha is dropped.

    Examples
    --------
    >>> import numpy as np
    >>> from rgbz_fast.io import rgb_image
    >>> rgb_image(np.zeros((2, 3), np.uint8), "g.png", grey=True).shape
    (2, 3, 3)
    >>> rgb_image(np.zeros((2, 3), np.uint8), "g.png")
    Traceback (most recent call last):
    ...
    rgbz_fast.io.ParameterError: path: g.png is a grey image (2x3); a colour sensor needs colour: ...
    """
    grey = check_flag(grey, "grey")
    img = as_array(img, "img")
    if img.ndim == 3 and img.shape[2] in (2, 4):
        img = img[..., :-1]                           # alpha
    if img.ndim == 3 and img.shape[2] == 1:
        img = img[..., 0]
    if img.ndim == 2:
        if not grey:
            raise ParameterError(name, f"{path} is a grey image ({img.shape[0]}x{img.shape[1]}); "
                                       "a colour sensor needs colour: pass ",
                                 Setting("grey", "grey=True"), " to repeat it into R, G and B")
        img = np.repeat(img[..., None], 3, axis=2)
    if img.ndim != 3 or img.shape[2] != 3:
        raise ParameterError(name, f"{path} holds an image of shape {img.shape}; expected "
                                   "RGB (rows, cols, 3), RGBA or grey")
    return np.ascontiguousarray(img)


def sample_bits(img, path, input_bits=None, name="path", *, settable=True):
    """The bits of the samples of an image read from ``path`` (None for floats): the library's
    one rule for integer images (:func:`rgbz_fast._validate.integer_bits`), in the words of a
    file. 8- and 16-bit files say their range; wider integer samples (a 32-bit TIFF) need
    ``input_bits``, else a :class:`ParameterError` naming ``name`` and the file (which asks
    for ``input_bits`` only when the caller can pass it: ``settable``)."""
    try:
        return integer_bits(img, name, input_bits)
    except TypeError:
        fix = ("pass ", Setting("input_bits"), " (the bits the values use, e.g. 12) or "
               "convert the file to 8 or 16 bits") if settable else \
            ("convert the file to 8 or 16 bits (a dataset's images say their range by their "
             "type)",)
        raise ParameterError(name, f"{path} holds {img.dtype} samples, a type that says nothing "
                                   "about the range of their values; ", *fix) from None
    except ValueError as exc:
        if str(exc).startswith("input_bits:"):
            raise
        raise ParameterError(name, f"{path}: {str(exc).removeprefix(name + ': ')}") from None
