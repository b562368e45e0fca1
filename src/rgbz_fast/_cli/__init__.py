"""``rgbz-fast``: the whole chain from the command line.

    rgbz-fast simulate    scene file(s) -> raw RGB-Z frame files (NPZ or 16-bit TIFF)
    rgbz-fast reconstruct RGB-Z frames, or camera raw / Bayer files given a Z pattern
                          -> Bayer CFA or sRGB image (and the reference it is compared with)
    rgbz-fast depth       frames with ToF taps -> depth map (float TIFF), flags, preview
    rgbz-fast evaluate    dataset -> metrics tables, CSV/JSON, figures
    rgbz-fast train       dataset -> filters of the "learned" reconstruction (.npz)
    rgbz-fast calibrate   flat-wall sweep -> ToF phase calibration file (cyclic error, offsets)
    rgbz-fast evaluate-depth  the ToF chain measured: RGB-D scenes, range, noise, sunlight
    rgbz-fast bench       kernel speed (Mpix/s) beside OpenCV and NumPy
    rgbz-fast opcount     operations per missing pixel beside the paper's Table 1
    rgbz-fast tradeoff    speed against accuracy, Pareto plot
    rgbz-fast pattern-study  RGB-Z layouts ranked by colour loss, depth noise and cost
    rgbz-fast hardware    the fixed-point model: silicon cost, error against float64, sweep
    rgbz-fast config      how the C kernels were built (OpenMP, flags, threads)

One module per command declares its options (``add_parser(sub)``, with the
shared option helpers of :mod:`._common`) and does its work (``run(args)``);
:func:`main` parses, runs and reports. Every option's help gives its default.
Bad input exits with status 2 and a one-line reason on stderr. Ctrl-C exits
130 and SIGTERM 143; either way no temporary file and no worker process is
left behind. The measuring commands (bench, opcount, tradeoff, pattern-study, hardware)
run the engines of :mod:`rgbz_fast._devtools`, which hold no command-line code.
"""

from ._main import COMMANDS, Terminated, _terminate, build_parser, main

__all__ = ["main", "build_parser", "COMMANDS", "Terminated"]
