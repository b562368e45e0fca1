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
  primitives every other function goes through (errors name the parameter;
  reads are bounded by :func:`read_limits`; writes are never partial).
"""

from ._datasets import IMAGE_SUFFIXES, RAW_SUFFIXES, ImageSource, folder_dataset, sample_dataset
from ._files import (DEFAULT_MAX_BYTES, DEFAULT_MAX_PIXELS, MAX_BYTES_ENV, MAX_PIXELS_ENV,
                     atomic_write, check_size, read_file, read_image, read_limits, rgb_image)
from ._frames import FRAME_SUFFIXES, load_frame, read_npz, save_frame
from ._raw import (HEADERLESS_EXTENSIONS, IMAGE_EXTENSIONS, LIBRAW_EXTENSIONS, RAW_EXTENSIONS,
                   clipped_mask, frame_clip_level, list_raw_files, read_raw, to_rgbz)

__all__ = ["save_frame", "load_frame", "read_npz", "FRAME_SUFFIXES",
           "read_raw", "list_raw_files", "to_rgbz", "clipped_mask", "frame_clip_level",
           "LIBRAW_EXTENSIONS", "IMAGE_EXTENSIONS", "HEADERLESS_EXTENSIONS", "RAW_EXTENSIONS",
           "ImageSource", "folder_dataset", "sample_dataset", "IMAGE_SUFFIXES", "RAW_SUFFIXES",
           "read_image", "read_file", "read_limits", "rgb_image", "check_size", "atomic_write",
           "DEFAULT_MAX_PIXELS", "DEFAULT_MAX_BYTES", "MAX_PIXELS_ENV", "MAX_BYTES_ENV"]
