"""The file name suffixes the readers recognise: one list per kind of file, written once.

Every reader and loader of the library (scenes, datasets, raw files, frames)
tells the kind of a file by these lists, so that a suffix one accepts is
accepted by all that read that kind. Suffixes are lower case, with the dot;
compare them with ``path.suffix.lower()``.
"""

from __future__ import annotations

__all__ = ["IMAGE_SUFFIXES", "LIBRAW_EXTENSIONS", "IMAGE_EXTENSIONS", "HEADERLESS_EXTENSIONS",
           "RAW_EXTENSIONS", "RAW_SUFFIXES", "FRAME_SUFFIXES"]

#: pictures (RGB, RGBA or grey): scenes, dataset images (:func:`rgbz_fast.io.read_image`)
IMAGE_SUFFIXES = frozenset({".png", ".tif", ".tiff", ".jpg", ".jpeg", ".bmp", ".ppm", ".pgm",
                            ".webp"})
#: camera raw formats read through rawpy (LibRaw)
LIBRAW_EXTENSIONS = (
    ".dng", ".cr2", ".cr3", ".crw", ".nef", ".nrw", ".arw", ".srf", ".sr2", ".raf",
    ".orf", ".rw2", ".rwl", ".pef", ".ptx", ".srw", ".3fr", ".fff", ".iiq", ".mos",
    ".mef", ".mrw", ".erf", ".kdc", ".dcr", ".x3f",
)
#: single-channel Bayer mosaics stored as an image (a subset of :data:`IMAGE_SUFFIXES`)
IMAGE_EXTENSIONS = (".png", ".tif", ".tiff")
#: one uint16 per pixel, no header (needs ``shape``)
HEADERLESS_EXTENSIONS = (".raw", ".bin")
#: every extension :func:`rgbz_fast.io.read_raw` dispatches on
RAW_EXTENSIONS = LIBRAW_EXTENSIONS + IMAGE_EXTENSIONS + HEADERLESS_EXTENSIONS
#: the files a dataset reads as raw by their name alone (a Bayer PNG/TIFF needs raw options)
RAW_SUFFIXES = frozenset(LIBRAW_EXTENSIONS + HEADERLESS_EXTENSIONS)
#: the frame files of :func:`rgbz_fast.io.save_frame`
FRAME_SUFFIXES = (".npz", ".tif", ".tiff")
