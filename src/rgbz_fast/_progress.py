"""Progress on stderr for a slow step that has nothing to count: a line whose elapsed time
ticks every second, so that a long fit never looks like a hang.

tqdm draws it (on stderr, as every progress bar of the package); it is imported only when a
step is shown. A step that ends within :data:`DELAY` seconds shows nothing, so a quick step
or an early error leaves stderr as it was.
"""

from __future__ import annotations

import sys
import threading
from contextlib import contextmanager

__all__ = ["ticking", "DELAY"]

#: seconds a step runs before its line appears
DELAY = 1.0


@contextmanager
def ticking(what, enabled=True):
    """``with ticking("train: fitting the filters"):`` shows ``what`` and the time spent in
    the block once it has run :data:`DELAY` seconds, refreshed every second by a daemon
    thread; nothing when not ``enabled``."""
    if not enabled:
        yield
        return
    stop = threading.Event()
    delay = DELAY

    def tick():
        if stop.wait(delay):
            return
        from tqdm.auto import tqdm

        bar = tqdm(total=None, desc=what, bar_format="{desc} ... {elapsed}", file=sys.stderr,
                   initial=0)
        bar.start_t -= delay                 # the time the step has run, not the bar
        while not stop.wait(1.0):
            bar.refresh()
        bar.refresh()
        bar.close()

    ticker = threading.Thread(target=tick, name="rgbz-fast progress", daemon=True)
    ticker.start()
    try:
        yield
    finally:
        stop.set()
        ticker.join()
