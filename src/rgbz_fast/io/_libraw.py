"""Camera raw files through LibRaw (rawpy): the visible CFA, its phase and levels, the
camera's colour, with LibRaw's own complaints and lazy failures turned into one error."""

from __future__ import annotations

import contextlib
import io
import os
import sys
import tempfile
import threading
import warnings

import numpy as np

from .._patterns import BAYER_PHASES
from ._files import check_size, read_file

__all__ = ["read_libraw"]

#: held while a read redirects the process's file descriptor 2 and the tifffile logger: two
#: threads redirecting at once would leave fd 2 on the first one's temporary file
_PROCESS_STATE = threading.Lock()


def read_libraw(path, limits):
    """(the visible CFA, what LibRaw says of it) of the camera raw file ``path``; a ValueError
    naming ``path`` when LibRaw cannot read it, with what it printed."""
    try:
        import rawpy
    except ImportError:
        raise ImportError(f"reading camera raw files such as {path.name} needs rawpy (LibRaw): "
                          "pip install rawpy  (or pip install rgbz-fast[raw])") from None
    blob = read_file(path, "path", max_bytes=limits[1])
    try:
        with _PROCESS_STATE, _c_stderr() as said:
            data, info = _libraw_mosaic(rawpy, blob, path, limits)
    except rawpy.LibRawError as exc:
        # LibRaw decodes lazily: a truncated or damaged file fails when the pixels are
        # unpacked, after the header was read, with its own exception types
        reason = exc.args[0] if exc.args else exc
        if isinstance(reason, bytes):
            reason = reason.decode("utf-8", "replace")
        told = " ".join(dict.fromkeys(line.strip() for line in said if line.strip()))
        raise ValueError(f"path: LibRaw cannot read {path.name}: {type(exc).__name__}: "
                         f"{reason}" + (f" ({told})" if told else "")) from None
    return data, info


@contextlib.contextmanager
def _c_stderr():
    """What C code writes to file descriptor 2 meanwhile, as a list of lines.

    LibRaw prints its own complaints there ("unknown file: Unexpected end of file", once per
    read attempt), which would come before the one error line of the command line. They are
    caught here: part of the error when the read fails, written out as they were when it
    succeeds.
    """
    said = []
    try:
        sys.stderr.flush()
        saved = os.dup(2)
    except (OSError, ValueError, AttributeError):       # no file descriptor 2 to catch
        yield said
        return
    failed = True
    with tempfile.TemporaryFile() as tmp:
        os.dup2(tmp.fileno(), 2)
        try:
            yield said
            failed = False
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            tmp.seek(0)
            text = tmp.read()
            said += text.decode("utf-8", "replace").splitlines()
            if text and not failed:
                os.write(2, text)


def _libraw_mosaic(rawpy, blob, path, limits):
    """The visible CFA and what LibRaw says of it, from the bytes of a camera raw file."""
    with rawpy.imread(io.BytesIO(blob)) as raw:
        if raw.raw_type != rawpy.RawType.Flat:
            raise ValueError(f"path: {path.name} is not a CFA mosaic (LibRaw raw_type "
                             f"{raw.raw_type.name}, e.g. a linear DNG)")
        pattern = raw.raw_pattern
        desc = raw.color_desc.decode("ascii", "replace")
        if pattern is None or pattern.shape != (2, 2):
            shp = None if pattern is None else pattern.shape
            raise ValueError(f"path: {path.name} is not a 2x2 Bayer sensor (CFA pattern {shp}, "
                             f"colours {desc!r}; X-Trans and Foveon are not supported)")
        tiff = _tiff_metadata(blob)
        filters, end = tiff["filters"], tiff["end"]
        if end is not None and end > len(blob):
            # LibRaw reads the bytes it is given: an uncompressed mosaic cut by one byte came
            # back with its last pixel wrong and no error
            raise ValueError(f"path: {path.name} is truncated: its mosaic's strips end at byte "
                             f"{end}, the file holds {len(blob)}")
        if filters is not None and not set(filters) <= set("RGB"):
            # LibRaw maps a DNG's cyan, magenta, yellow or white filters onto its R, G, B
            # labels: read as RGB, such a mosaic would be processed as one without a word
            raise ValueError(f"path: {path.name} has the colour filters {filters!r} (its "
                             "CFAPattern; C cyan, M magenta, Y yellow, W white), not an RGB "
                             "Bayer sensor's")
        letters = "".join(desc[int(i)] for i in pattern.ravel())
        if letters not in BAYER_PHASES:
            raise ValueError(f"path: {path.name} has the CFA {letters!r} (LibRaw's colours "
                             f"{desc!r}), not an RGB Bayer phase")
        bl = raw.black_level_per_channel      # indexed by colour index
        black = [float(bl[int(i)]) for i in pattern.ravel()]
        wl = raw.white_level
        check_size((raw.sizes.height, raw.sizes.width), 2, path, "path", limits=limits)
        data = np.array(raw.raw_image_visible, dtype=np.uint16, copy=True)
        colour = _camera_colour(raw, desc)
    make, model = tiff["make"], tiff["model"]
    info = {"phase": letters, "black_level": black, "white_level": float(wl),
            "make": make, "model": model, **colour}
    return data, info


def _camera_colour(raw, desc):
    """The as-shot white balance (R, G, B gains, G = 1) and the matrix from white-balanced
    camera RGB to linear sRGB that LibRaw gives for the file; each left out when LibRaw has
    none (zeros) for it."""
    out = {}
    idx = [desc.index(c) for c in "RGB"]
    try:
        wb = np.asarray(raw.camera_whitebalance, np.float64)[idx]
        if np.all(np.isfinite(wb)) and np.all(wb > 0):
            out["white_gains"] = tuple(float(v) for v in wb / wb[1])
        m = np.asarray(raw.color_matrix, np.float64)[:, idx]
        if m.shape == (3, 3) and np.all(np.isfinite(m)) and np.any(m != 0):
            out["colour_matrix"] = tuple(float(v) for v in m.ravel())
    except (AttributeError, IndexError, ValueError):     # an older rawpy, a partial file
        pass
    return out


def _tiff_metadata(blob):
    """What the TIFF structure most raw formats are built on says, in one parse: Make and
    Model of IFD0; of the IFD holding the mosaic (IFD0 or a SubIFD with a CFAPattern tag, DNG
    and TIFF/EP), the colours of its CFAPattern as letters of RGBCMYW through its
    CFAPlaneColor (the DNG way; without that tag the pattern holds the colour codes
    themselves, the TIFF/EP way) and the byte its strips or tiles end at. Each None when the
    file does not hold it or it cannot be read (a non-TIFF raw): metadata only, LibRaw's
    reading stands without it."""
    from ._tiff import open_tiff                # tifffile logs each damaged tag it skips

    out = {"make": None, "model": None, "filters": None, "end": None}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            with open_tiff(blob) as tif:
                first = tif.pages[0]
                for key, tag in (("make", "Make"), ("model", "Model")):
                    t = first.tags.get(tag)
                    out[key] = str(t.value).strip() if t is not None else None
                for page in [first] + list(getattr(first, "pages", None) or []):
                    cfa = page.tags.get(33422)               # CFAPattern
                    if cfa is None:
                        continue
                    codes = bytes(cfa.value)
                    plane = page.tags.get(50710)             # CFAPlaneColor
                    if plane is not None:
                        planes = bytes(plane.value)
                        codes = bytes(planes[c] if c < len(planes) else 255 for c in codes)
                    out["filters"] = "".join("RGBCMYW"[c] if c < 7 else "?" for c in codes)
                    ends = [int(o) + int(n) for o, n in zip(page.dataoffsets,
                                                             page.databytecounts)]
                    out["end"] = max(ends) if ends else None
                    break
    except Exception:  # noqa: BLE001 - metadata only: LibRaw's reading stands without it
        pass
    return out
