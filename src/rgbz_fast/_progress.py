"""Progress on stderr for a slow step that has nothing to count: a line whose elapsed time
ticks every second, so that a long fit never looks like a hang.

tqdm draws it (on stderr, as every progress bar of the package); it is imported only when a
step is shown.
"""

from __future__ import annotations

import sys
import threading
from contextlib import contextmanager

__all__ = ["ticking"]


@contextmanager
def ticking(what, enabled=True):
    """``with ticking("train: fitting the filters"):`` shows ``what`` and the time spent in
    the block, refreshed every second by a daemon thread; nothing when not ``enabled``."""
    if not enabled:
        yield
        return
    from tqdm.auto import tqdm

    bar = tqdm(total=None, desc=what, bar_format="{desc} ... {elapsed}", file=sys.stderr)
    stop = threading.Event()

    def tick():
        while not stop.wait(1.0):
            bar.refresh()

    ticker = threading.Thread(target=tick, name="rgbz-fast progress", daemon=True)
    ticker.start()
    try:
        yield
    finally:
        stop.set()
        ticker.join()
        bar.close()
