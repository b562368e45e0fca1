"""The peak memory of one ``reconstruct`` call, measured in a fresh Python process."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

__all__ = ["measure_memory"]

_MEM_SCRIPT = r"""
import gc, json, sys, tracemalloc
# the parent's import path: `python -c` puts the current folder first, and an `rgbz_fast`
# folder there (a checkout's src/) was imported instead of the package the parent measures
sys.path[:] = json.loads(sys.argv[7])
import numpy as np
import rgbz_fast as rz
path, pattern, method, precision, workers, mode = sys.argv[1:7]
data = np.load(path)
rz.reconstruct(data[:96, :96].copy(), method, pattern=pattern, precision=precision,
               workers=int(workers))                      # warm-up: threads, plans
def status(key):
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
def reset_hwm():
    try:
        with open("/proc/self/clear_refs", "w") as fh:   # "5": reset the peak RSS (Linux >= 4.0)
            fh.write("5")
        return True
    except OSError:
        return False
# one mode per process: freed pages may stay resident (malloc keeps them) and hide the next
frame = rz.RawFrame(data, pattern, 11) if mode == "rawframe" else data
kw = {} if mode == "rawframe" else {"pattern": pattern}
gc.collect()
exact = reset_hwm()
before = status("VmRSS") if exact else status("VmHWM")
tracemalloc.start()
out = rz.reconstruct(frame, method, precision=precision, workers=int(workers), **kw)
_, traced = tracemalloc.get_traced_memory()
tracemalloc.stop()
after = status("VmHWM")
print(json.dumps(dict(rss_before=before, hwm_after=after, traced_peak=traced, hwm_reset=exact,
                      in_bytes=data.nbytes, out_bytes=out.nbytes)))
"""


def measure_memory(data, pattern="mask1", method="sg", precision="float32", workers=None):
    """Peak-memory growth of one ``reconstruct`` call, in a fresh Python process.

    The frame is handed over as a .npy file (``np.load`` allocates nothing but
    the array). Before the call the peak RSS is reset (``/proc/self/clear_refs``,
    Linux >= 4.0), so the growth of the high-water mark (VmHWM, i.e.
    ``ru_maxrss``) over the resident size before the call is everything the call
    touched: the output pages, NumPy temporaries (argument validation), the C
    kernel's scratch and the thread stacks. tracemalloc gives the peak of the
    NumPy (Python allocator) part alone. Two inputs are measured: a plain
    array (``reconstruct`` checks its value range) and a :class:`RawFrame`
    (already validated at construction). Returns ``{"array": {...},
    "rawframe": {...}, ...}``, or None when /proc is not there.
    """
    if not Path("/proc/self/status").exists():
        return None
    workers = workers or (os.cpu_count() or 1)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "frame.npy"
        np.save(path, np.ascontiguousarray(data))
        out = {}
        for mode in ("array", "rawframe"):
            res = subprocess.run([sys.executable, "-c", _MEM_SCRIPT, str(path), str(pattern),
                                  method, precision, str(workers), mode,
                                  json.dumps([os.path.abspath(p) if p else p
                                              for p in sys.path])],
                                 capture_output=True, text=True, timeout=600)
            if res.returncode != 0:
                err = res.stderr.strip().splitlines()
                return {"error": err[-1] if err else "failed"}
            m = json.loads(res.stdout.strip().splitlines()[-1])
            grow = m["hwm_after"] - m["rss_before"]
            budget = m["out_bytes"] + 0.1 * (m["in_bytes"] + m["out_bytes"])
            m.update(rss_growth=grow, rss_growth_over_output=grow / m["out_bytes"],
                     peak_over_in_plus_out=(m["in_bytes"] + grow) / (m["in_bytes"]
                                                                     + m["out_bytes"]),
                     budget_bytes=budget, within_budget=bool(grow <= budget))
            out[mode] = m
    return dict(pattern=str(pattern), method=method, precision=precision, workers=workers,
                shape=list(np.shape(data)), **out)
