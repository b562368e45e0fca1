"""tifffile, quietly: the one opener of the library's TIFF reads.

tifffile logs what it skips in a damaged file (``<tifffile.TiffPages @...> invalid offset
to first page ...``) on the ``tifffile`` logger, which Python prints on stderr beside the
library's own one-line error. :func:`open_tiff` keeps those records of the calling thread
out of the log and puts them in its error instead; other threads, and a user's own use of
tifffile, log as before.
"""

from __future__ import annotations

import contextlib
import io
import logging
import re
import threading

__all__ = ["open_tiff"]

_local = threading.local()
_install_lock = threading.Lock()
_installed = []


class _Capture(logging.Filter):
    """Drops (and keeps) the records logged by a thread inside :func:`open_tiff`."""

    def filter(self, record):
        sink = getattr(_local, "sink", None)
        if sink is None:
            return True
        sink.append(re.sub(r"^<[^>]*>\s*", "", record.getMessage()))
        return False


#: the loggers tifffile logs on: "tifffile" today, its module's "tifffile.tifffile" before
#: (2023.1, the floor; a filter acts on its own logger's records, not on a child's)
_LOGGERS = ("tifffile", "tifffile.tifffile")


def _install():
    if not _installed:
        with _install_lock:
            if not _installed:
                for name in _LOGGERS:
                    logging.getLogger(name).addFilter(_Capture())
                _installed.append(True)


@contextlib.contextmanager
def open_tiff(blob):
    """``tifffile.TiffFile`` of the bytes ``blob``, with at least one page; what tifffile
    logs meanwhile on this thread is not printed. A file without a readable page is a
    ValueError that says what tifffile found (it had been an IndexError, and a log line)."""
    import tifffile

    _install()
    outer, sink = getattr(_local, "sink", None), []
    _local.sink = sink
    try:
        with tifffile.TiffFile(io.BytesIO(blob)) as tf:
            if not len(tf.pages):
                why = "; ".join(dict.fromkeys(sink)) or "no image file directory"
                raise ValueError(f"it holds no readable page: {why[:160]}")
            yield tf
    finally:
        _local.sink = outer
