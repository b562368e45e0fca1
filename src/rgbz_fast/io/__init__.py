"""Reading and writing: raw frame files, camera raw and Bayer files, image datasets.

* :func:`save_frame`, :func:`load_frame` -- RGB-Z frames as NPZ (everything: data,
  reference, ToF taps, metadata) or 16-bit TIFF (the mosaic and its metadata).
* :func:`read_raw` -- real Bayer data: camera raw (DNG, CR2, NEF, ... through
  rawpy), 16-bit Bayer PNG/TIFF, headerless raw; :func:`to_rgbz` places an RGB-Z
  pattern on such a frame (the paper's HDR+ protocol), :func:`clipped_mask` and
  :func:`frame_clip_level` say where it saturates.
* :func:`folder_dataset`, :func:`sample_dataset`, :class:`ImageSource` -- the one
  dataset loader of the evaluation, trade-off and training commands.
* :func:`read_file`, :func:`read_image`, :func:`atomic_write` -- the file
  primitives every other function goes through (reads are bounded by
  :func:`read_limits`, given as ``max_pixels`` and ``max_bytes``; writes are never
  partial).
* :class:`ParameterError` -- the ValueError of the readers: it names the
  parameter at fault (``param``) and spells the settings of its advice
  (:class:`Setting`) so that a caller can give them in its own words.
* The suffixes each reader recognises: :data:`IMAGE_SUFFIXES`, :data:`RAW_SUFFIXES`,
  :data:`RAW_EXTENSIONS` (and its parts), :data:`FRAME_SUFFIXES`, one list each.
"""

from ._bayer import clipped_mask, frame_clip_level, to_rgbz
from ._datasets import ImageSource, folder_dataset, sample_dataset
from ._errors import ParameterError, Setting
from ._files import (DEFAULT_MAX_BYTES, DEFAULT_MAX_PIXELS, MAX_BYTES_ENV, MAX_PIXELS_ENV,
                     atomic_write, check_size, read_file, read_image, read_limits, rgb_image)
from ._frames import load_frame, read_npz, save_frame
from ._raw import list_raw_files, read_raw
from ._suffixes import (FRAME_SUFFIXES, HEADERLESS_EXTENSIONS, IMAGE_EXTENSIONS, IMAGE_SUFFIXES,
                        LIBRAW_EXTENSIONS, RAW_EXTENSIONS, RAW_SUFFIXES)

__all__ = ["save_frame", "load_frame", "read_npz", "FRAME_SUFFIXES",
           "read_raw", "list_raw_files", "to_rgbz", "clipped_mask", "frame_clip_level",
           "LIBRAW_EXTENSIONS", "IMAGE_EXTENSIONS", "HEADERLESS_EXTENSIONS", "RAW_EXTENSIONS",
           "ImageSource", "folder_dataset", "sample_dataset", "IMAGE_SUFFIXES", "RAW_SUFFIXES",
           "read_image", "read_file", "read_limits", "rgb_image", "check_size", "atomic_write",
           "DEFAULT_MAX_PIXELS", "DEFAULT_MAX_BYTES", "MAX_PIXELS_ENV", "MAX_BYTES_ENV",
           "ParameterError", "Setting"]
