"""rgbz-fast: simulate a monolithic RGB-Z CMOS imager and reconstruct its images.

The colour sites and the indirect time-of-flight depth (Z) sites share one
pixel matrix; the colour missing at every Z site is reconstructed (bilateral,
edge-directed and semi-gradient methods of Rebiere et al.) before the usual
ISP, and the depth comes from the Z pixels' four taps. The per-pixel kernels
are C (csrc/), threaded with OpenMP.

Subpackages, from the sensor to the report:

* :mod:`rgbz_fast.simulation` -- scenes and the colour and i-ToF sensor models;
* :mod:`rgbz_fast.reconstruction` -- the missing colour at the Z sites;
* :mod:`rgbz_fast.isp` -- the colour ISP (defects, white balance, demosaic, sRGB);
* :mod:`rgbz_fast.tof` -- the ToF ISP (demodulation, denoise, unwrapping, depth);
* :mod:`rgbz_fast.metrics` -- CFA PSNR, CPSNR, SSIM, MS-SSIM, zipper;
* :mod:`rgbz_fast.evaluation` -- the paper's Fig. 19 protocol over a dataset;
* :mod:`rgbz_fast.io` -- frame files, camera raw, datasets.

The names most used are re-exported here.
"""

import os as _os
import sys as _sys
from typing import TYPE_CHECKING as _TYPE_CHECKING


def _the_command():
    """Whether this process is the ``rgbz-fast`` command: its console script, or ``python -m
    rgbz_fast`` (whose ``sys.argv[0]`` is not yet the module's while the package loads)."""
    if _sys.argv and _os.path.basename(_sys.argv[0]).removesuffix(".exe") == "rgbz-fast":
        return True
    argv = list(getattr(_sys, "orig_argv", ()))
    return any(a == "-m" and argv[i + 1:i + 2] == ["rgbz_fast"] for i, a in enumerate(argv))


if "numpy" not in _sys.modules and _the_command():
    # The command, not the library: its kernels run their own threads, while the threads
    # OpenBLAS starts when NumPy loads spin idle for about 0.15 s of CPU, which a 2-thread
    # evaluation on 2 cores pays (a few % of its CPU on Kodak, docs/guide/performance.md). A set
    # OPENBLAS_NUM_THREADS is left alone; an importing program is never touched.
    _os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

if (_the_command() and "GOMP_SPINCOUNT" not in _os.environ
        and "OMP_WAIT_POLICY" not in _os.environ):
    # The command, before its kernels load libgomp: after each parallel region libgomp's idle
    # threads spin 300000 rounds by default (about 3 ms on the 2-core host), taking a core from
    # whatever threaded call comes next (OpenCV's edge-aware demosaic right after a
    # reconstruction: 11.5 ms instead of 8.4, and bench's paired ratios swung with it). 30000
    # rounds (about 0.3 ms) keep the threads hot from one region to the next. A set
    # GOMP_SPINCOUNT or OMP_WAIT_POLICY is left alone; an importing program is never touched
    # (docs/guide/performance.md says how to do the same there).
    _os.environ["GOMP_SPINCOUNT"] = "30000"

if _the_command():
    def _interrupted(kind, value, tb, hook=_sys.excepthook):
        # Ctrl-C while the command loads (the package's imports, about 0.5 s before main()
        # catches it): the command's line and status, not a traceback through the imports
        if not issubclass(kind, KeyboardInterrupt):
            return hook(kind, value, tb)
        try:
            print("rgbz-fast: interrupted", file=_sys.stderr, flush=True)
        except (OSError, ValueError, AttributeError):
            pass
        _os._exit(130)

    _sys.excepthook = _interrupted

from . import evaluation, io, isp, metrics, reconstruction, simulation
from ._build_config import VERSION as __version__
from ._compat import install_aliases as _install_aliases
from ._config import config, show_config
from ._frame import RawFrame, ToFTaps, mosaic
from ._memory import memory_pool
from ._patterns import (B, BAYER_PHASES, G, Pattern, R, Z, bayer, get_pattern, mask1, mask2,
                        rows)
from .isp import ColourISP
from .reconstruction import (METHODS, NEEDS_TOF, PRECISIONS, FixedPointConfig, ReconstructParams,
                             reconstruct)
from .simulation import ColourSensor, Scene, ToFSensor, load_scene, simulate

__all__ = [
    "__version__", "show_config", "config", "memory_pool",
    "Pattern", "bayer", "mask1", "mask2", "rows", "get_pattern", "R", "G", "B", "Z",
    "BAYER_PHASES", "RawFrame", "ToFTaps", "mosaic",
    "reconstruct", "ReconstructParams", "FixedPointConfig", "METHODS", "NEEDS_TOF", "PRECISIONS",
    "Scene", "load_scene", "ColourSensor", "ToFSensor", "simulate",
    "ColourISP", "tof_depth", "ToFISP", "ToFDepth",
    "simulation", "reconstruction", "isp", "tof", "metrics", "evaluation", "io",
]

if _TYPE_CHECKING:
    # what type checkers see (py.typed is shipped); at run time these come lazily, below
    from . import tof
    from .tof import ToFDepth, ToFISP, tof_depth

# the ToF chain is imported at its first use: the colour chain's commands (evaluate,
# reconstruct) never load it
_install_aliases(__name__, lazy={"tof": ("tof", None), "ToFDepth": ("tof", "ToFDepth"),
                                 "ToFISP": ("tof", "ToFISP"), "tof_depth": ("tof", "tof_depth")})
del _install_aliases
