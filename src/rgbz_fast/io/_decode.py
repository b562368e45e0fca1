"""Decoding image bytes into the samples they mean: what each format's header says they are.

:func:`rgbz_fast.io.read_image` decodes every image file here. A decoder
returns the picture's samples -- grey, RGB or RGB + alpha, in the file's own
bit depth -- or raises ValueError saying what the file holds instead:

* TIFF (tifffile, first page): a palette image gives its colours, not its
  indices; MINISWHITE is inverted (0 is white there); planar samples (RGB,
  grey + alpha) become interleaved, (rows, cols, samples); samples of fewer
  bits than their type (12 in uint16) are scaled to its full range, as a
  PNM's maxval (a raw mosaic keeps its codes); CMYK (SEPARATED), CIELAB and
  uncompressed YCbCr are refused -- their samples are no RGB, and a converted
  CMYK needs its colour profile.
* PGM and PPM (``P2``, ``P3``, ``P5``, ``P6``): 8-bit samples as uint8 and
  16-bit ones as uint16, the format's own rule; a ``maxval`` other than 255
  or 65535 is scaled to that full range (a 12-bit PGM of maxval 4095 is no
  darker than a 16-bit one). Pillow reads 16-bit ones as 8 bits or as int32.
* JPEG, BMP, WebP, GIF (Pillow, first frame): a palette image gives its
  colours; CMYK and CIELAB are refused as in TIFF.
* PNG through imageio, 16-bit colour PNGs at full precision
  (:func:`rgbz_fast.io._files._decode_png16_colour`).
"""

from __future__ import annotations

import io
import re

import numpy as np

from ._tiff import open_tiff

__all__ = ["decode_tiff", "decode_pnm", "decode_pillow", "PNM_MAGIC"]

#: the PNM formats decoded here: grey and colour, ASCII and binary
PNM_MAGIC = (b"P2", b"P3", b"P5", b"P6")

#: TIFF photometric interpretations whose samples are not grey or RGB, and what they are
_TIFF_REFUSED = {5: "CMYK (separated)", 8: "CIELAB", 9: "ICC L*a*b*", 10: "ITU L*a*b*",
                 32844: "LogL", 32845: "LogLuv"}
_MINISWHITE, _PALETTE, _YCBCR = 0, 3, 6
#: Pillow modes whose samples are not grey or RGB
_PIL_REFUSED = {"CMYK": "CMYK", "LAB": "CIELAB", "HSV": "HSV"}


def _refuse(kind):
    raise ValueError(f"it holds {kind} samples, not RGB or grey; convert it to RGB first "
                     "(a CMYK image with its colour profile)")


def decode_tiff(data, full_range=True):
    """The first page of a TIFF as grey, RGB or RGBA samples (see the module docstring).

    ``full_range``: integer samples of fewer bits than their type (BitsPerSample 2-7 in
    uint8, 9-15 in uint16: tifffile unpacks them when imagecodecs is installed) are scaled
    to the type's full range, rounded half up, as a PNM's ``maxval`` is (a 12-bit TIFF had
    read 16 times too dark); False keeps the stored codes (a raw mosaic, whose white level
    is its own)."""
    with open_tiff(data) as tf:
        page = tf.pages[0]
        photometric = int(page.photometric)
        if photometric in _TIFF_REFUSED:
            _refuse(_TIFF_REFUSED[photometric])
        if photometric == _YCBCR and int(page.compression) != 7:     # 7: JPEG decodes to RGB
            _refuse("YCbCr")
        img = page.asarray()
        if photometric == _PALETTE:
            cmap = page.colormap
            if cmap is None or img.dtype.kind not in "bu":
                raise ValueError("a palette image without a colour map")
            if int(img.max()) >= cmap.shape[1]:
                raise ValueError(f"palette index {int(img.max())} beyond its colour map of "
                                 f"{cmap.shape[1]} entries")
            img = np.moveaxis(cmap, 0, -1)[img]             # (rows, cols, 3), 16-bit colours
        elif (int(page.planarconfig) == 2 and int(page.samplesperpixel) > 1
              and img.ndim == 3 and img.shape[0] == int(page.samplesperpixel)):
            # planar -> interleaved: RGB(A), and grey + alpha, whose (2, rows, cols) had
            # read as two rows of colour when 3 or 4 pixels wide
            img = np.moveaxis(img, 0, -1)
        bits = int(page.bitspersample)
        if photometric == _MINISWHITE:
            img = _invert(img, bits)
    if full_range and photometric != _PALETTE and img.dtype.kind == "u":
        img = _to_full_range(img, bits)
    return img


def _to_full_range(img, bits):
    """Unsigned samples of ``bits`` bits scaled to their type's full range, rounded half up
    exactly (as :func:`decode_pnm`'s maxval); unchanged when the bits fill the type."""
    n = 8 * img.dtype.itemsize
    if not 1 < bits < n:
        return img
    top, maxval = (1 << n) - 1, (1 << bits) - 1
    if img.size and int(img.max()) > maxval:
        raise ValueError(f"a sample of {int(img.max())} above its {bits}-bit range")
    return ((img.astype(np.uint64) * (2 * top) + maxval) // (2 * maxval)).astype(img.dtype)


def _invert(img, bits=None):
    """0 is white: the samples of a MINISWHITE image as the usual 0-is-black ones, against
    the top of their ``bits`` (a 12-bit one in uint16 against 4095, not 65535: the scaling
    to the full range comes after) or of their type."""
    if img.dtype == np.bool_:
        return ~img
    if img.dtype.kind == "u":
        n = 8 * img.dtype.itemsize
        top = (1 << bits) - 1 if bits is not None and 1 < bits < n else np.iinfo(img.dtype).max
        return (top - img.astype(np.int64)).clip(0).astype(img.dtype)
    raise ValueError(f"a MINISWHITE image of {img.dtype} samples (0 is white) has no top "
                     "value to invert from")


_TOKEN = re.compile(rb"(?:\s|#[^\n]*\n?)*([^\s#]+)")


def decode_pnm(data):
    """A PGM or PPM (``P2``, ``P3``, ``P5``, ``P6``) as uint8 or uint16 samples."""
    magic = data[:2]
    if magic not in PNM_MAGIC:
        raise ValueError(f"not a PGM/PPM file (magic {magic!r})")
    pos, fields = 2, []
    for _ in range(3):                              # width, height, maxval
        m = _TOKEN.match(data, pos)
        if m is None or not m.group(1).isdigit():
            raise ValueError("a damaged header (width, height and maxval expected)")
        fields.append(int(m.group(1)))
        pos = m.end()
    cols, rows, maxval = fields
    if not (rows > 0 and cols > 0 and 0 < maxval < 65536):
        raise ValueError(f"a header of {rows}x{cols} pixels with maxval {maxval} (expected "
                         "positive sizes and a maxval of 1..65535)")
    channels = 1 if magic in (b"P2", b"P5") else 3
    count = rows * cols * channels
    if magic in (b"P5", b"P6"):
        pos += 1                                    # the one whitespace before the samples
        dtype = np.dtype(">u2") if maxval > 255 else np.dtype(np.uint8)
        need = count * dtype.itemsize
        if len(data) - pos < need:
            raise ValueError(f"truncated: {len(data) - pos} bytes of samples, {need} needed")
        samples = np.frombuffer(data, dtype, count, pos).astype(np.uint16)
    else:
        text = data[pos:].split()
        if len(text) < count or not all(t.isdigit() for t in text[:count]):
            raise ValueError(f"truncated or damaged: {count} decimal samples needed")
        samples = np.array([int(t) for t in text[:count]], dtype=np.int64)
    if samples.size and int(samples.max()) > maxval:
        raise ValueError(f"a sample of {int(samples.max())} above its maxval {maxval}")
    top = 255 if maxval <= 255 else 65535
    if maxval != top:           # to the full range of 8 or 16 bits, rounded half up, exactly
        samples = (samples.astype(np.int64) * (2 * top) + maxval) // (2 * maxval)
    img = samples.astype(np.uint8 if top == 255 else np.uint16)
    return img.reshape((rows, cols) if channels == 1 else (rows, cols, 3))


def decode_pillow(data):
    """Any other format Pillow reads (JPEG, BMP, WebP, GIF...), first frame, as samples."""
    from PIL import Image, UnidentifiedImageError

    try:
        im = Image.open(io.BytesIO(data))
    except UnidentifiedImageError:                   # its message shows a memory address
        raise ValueError("not an image format this library reads (PNG, TIFF, JPEG, BMP, "
                         "WebP, GIF, PGM/PPM)") from None
    with im:
        mode = im.mode
        if mode in _PIL_REFUSED:
            _refuse(_PIL_REFUSED[mode])
        if mode in ("P", "PA"):
            im = im.convert("RGBA" if "transparency" in im.info or mode == "PA" else "RGB")
        elif mode == "YCbCr":
            im = im.convert("RGB")
        elif mode in ("I", "F") and im.format not in ("TIFF",):
            raise ValueError(f"{im.format} samples of Pillow mode {mode!r} (32-bit) have no "
                             "range to read them by")
        return np.asarray(im)
