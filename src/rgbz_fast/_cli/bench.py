"""``rgbz-fast bench``: kernel speed (Mpix/s) beside OpenCV and NumPy."""

from __future__ import annotations

from . import _common as c

NAME = "bench"
DESCRIPTION = """\
The speed of every C kernel, beside OpenCV and the NumPy references.

Self-contained: the frame is scikit-image's astronaut mirrored and tiled up to
3000x4000 (rows x cols), mosaicked to 11-bit uint16 on each pattern. For every
kernel (each reconstruction method x pattern x precision, the Malvar 2004
demosaic, ToF demodulation and unwrapping) it reports the speed in frame
megapixels per second (all pixels of the frame over the wall time of one
call), the median and the interquartile range of N calls (after one warm-up
call), with 1 thread and with all threads. Beside it:

* OpenCV's Bayer demosaic of the same-size Bayer frame in the same run,
  bilinear (COLOR_BayerGR2RGB) and edge-aware (COLOR_BayerGR2RGB_EA), with 1
  thread and all threads; "n/a" without cv2. Ratios are speed ratios, ours /
  theirs (> 1: we are faster), same thread setting, paired: each timed call of
  a case alternates with one call of each OpenCV demosaic, and the ratio is
  the median of the rounds' ratios, so that a change of the machine's load
  during the run hits both sides alike.
* With --numpy-reference FILE (a slow NumPy implementation of the
  reconstruction: tests/_reference/reconstruction.py of a source checkout),
  that implementation of each method, timed on a crop of the same frame and
  scaled to Mpix/s; the ratio is
  our 1-thread speed over it ("n/a" without the option). The Malvar demosaic is
  compared with colour-demosaicing's NumPy/SciPy implementation and the
  demodulation with a NumPy one-liner.
* ToF section: demodulation + unwrapping of the Z measurements of a Mask1
  frame of that size (3 million at 3000x4000; 3 frequencies x 4 taps,
  synthetic 11-bit taps of depths in [0.3, 7] m) in million measurements per
  second: the fused C kernel with 1 thread and all threads beside a vectorised
  NumPy implementation of the same algorithm, timed in turn in the same loop,
  with the check that both agree. The target is >= 5x NumPy with all threads.
* --chain: the colour ISP (defects -> SG float32 reconstruction -> white
  balance -> C Malvar demosaic -> colour correction -> sRGB gamma -> 8-bit
  output) on the Mask1 frame: the fused path (ColourISP.run, C passes over row
  strips) and the NumPy stages (run with return_stages, seconds per stage),
  timed in the same rounds as OpenCV's edge-aware demosaic with the same
  threads, with the paired speed ratios (medians); and the sensor
  simulation of the image with a depth plane (as rgbz-fast simulate makes it, 3 ToF
  frequencies, no optics), noise-free and noisy, on Mask1 and Mask2 (targets on
  the full frame, Mask1: <= 0.5 s noise-free, <= 1 s noisy); and the ToF ISP on
  the simulated Mask1 frame as a loop over frames runs it: the ISP guided by the
  frame's own colour image (target >= 20 M measurements/s on the full frame), then
  upsample_depth of its result (target >= 50 Mpix/s), the results dropped before
  the next round; and the unguided ISP on its own.
* Peak memory of one reconstruct call on the full frame, measured in a fresh
  subprocess: the growth of the peak resident set size across the call, and
  the peak of its NumPy allocations, against the input
  and output sizes. The budget is input + output + 10 %, i.e. a growth of at
  most output + 0.1 (input + output).

Numbers from a shared machine are noisy: the load average before and after the
run is printed with them. Every case is called once untimed (thread start-up,
caches), then timed --repeat times. "All threads" is the thread count the
library really uses on that frame: a kernel call takes at most one thread per
262,144 pixels (512x512), so on a small frame it is fewer than the cores, and
the report shows the count. --quick is a smoke test: small frame,
few runs; its numbers are not comparable with anything, so it prints no ratio
and no target verdict ("quick run: numbers not comparable, no verdict"). A
full run gives the verdicts of the targets, which are defined on the
3000x4000 frame: another --shape gives the ratios but no verdict."""


def add_parser(sub):
    p = c.command_parser(sub, NAME, "kernel speed beside OpenCV and NumPy", DESCRIPTION)
    c.add_repeat(p, "timed runs per case (default 5, --quick 3)")
    c.add_shape(p, None, "frame size ROWSxCOLS (default 3000x4000, with --quick 192x256)")
    p.add_argument("--kernels", type=c.csv, default=None,
                   help="comma-separated substrings; run only the cases whose label "
                        "('reconstruct sg mask1 float32', 'demosaic', 'tof') contains one; "
                        "the ToF section runs when one is a substring of 'tof sites' "
                        "('tof sites' alone: that section only) (default: every case)")
    p.add_argument("--no-reference", action="store_true",
                   help="skip the NumPy and colour-demosaicing baselines")
    p.add_argument("--numpy-reference", type=c.path, default=None, metavar="FILE",
                   help="also time a slow NumPy implementation of the reconstruction: a "
                        "Python file defining reference_reconstruct, such as the one among "
                        "the tests of a source checkout (default: none)")
    p.add_argument("--no-memory", action="store_true",
                   help="skip the peak-memory measurement (a separate process)")
    p.add_argument("--no-tof-sites", action="store_true",
                   help="skip the ToF section (C vs NumPy in M measurements/s)")
    p.add_argument("--chain", action="store_true",
                   help="also time the colour ISP (fused and stage by stage), the simulation "
                        "and the ToF ISP")
    c.add_report_options(p)
    return p


def run(args):
    from .._devtools import bench
    from .._devtools._common import json_text

    shape = bench.check_shape(c.made_shape(args, args.shape), "--shape") if args.shape else (
        bench.QUICK_SHAPE if args.quick else bench.FULL_SHAPE)
    repeat = args.repeat or (3 if args.quick else 5)
    out = c.output_folder(args.out)
    crop = (48, 64) if args.quick else (240, 320)
    crop = (min(crop[0], shape[0]), min(crop[1], shape[1]))
    if args.numpy_reference and args.no_reference:
        raise c.CliError("--numpy-reference: times the NumPy reference, which --no-reference "
                         "leaves out")
    numpy_ref = None
    if args.numpy_reference:
        numpy_ref = bench.load_numpy_reference(args.numpy_reference, "--numpy-reference")
    # a --kernels that matches nothing is refused (NoCase) before any section runs
    res = bench.run_benchmarks(shape, repeat, args.workers, crop, args.kernels,
                               not args.no_reference, not args.no_memory, not c.bars(args),
                               not args.no_tof_sites, args.chain, numpy_reference=numpy_ref,
                               quick=args.quick)
    res["command"] = c.command_line(args)
    table = bench.format_table(res)
    print(json_text(res) if args.json else table)     # before the files: kept if a write fails
    c.write_report(out, {"bench.json": json_text(res) + "\n", "bench.txt": table + "\n"})
    return 0
