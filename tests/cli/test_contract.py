"""The bad-input contract of the command line, and its interrupts.

Rows of docs/reports/robustness.md (``cli.*``), run by the shared runner of
``tests/_contract.py``: exit status 2 and one line ``rgbz-fast CMD: error: ...``
(after argparse's usage lines for usage errors). Then: Ctrl-C exits 130, a broken
frame writes nothing, and SIGTERM during a write leaves no temporary file.
"""

from __future__ import annotations

import signal
import subprocess
import sys
import textwrap
import time

import pytest

from _contract import CliRow, cli_tests, files  # noqa: F401
from rgbz_fast._cli import main

C = CliRow

CLI_ROWS = [
    C("cli.no-command", ("nope",), "argument COMMAND: invalid choice", usage=True),
    C("cli.simulate-no-scene", ("simulate",), "the following arguments are required",
      usage=True),
    C("cli.simulate-missing", ("simulate", "{d}/missing.png"), "scene {d}/missing.png does not"),
    C("cli.simulate-pattern", ("simulate", "{d}/rgb.png", "--pattern", "mask7"),
      "--pattern: 'mask7' is neither a preset"),
    C("cli.simulate-no-bayer", ("simulate", "{d}/rgb.png", "--pattern", "ZR/RG"),
      "--pattern: 'ZR/RG' fits no Bayer phase"),
    C("cli.simulate-seed", ("simulate", "{d}/rgb.png", "--seed", "-1"),
      "argument --seed: expected an integer >= 0, got '-1'", usage=True),
    C("cli.simulate-tiny", ("simulate", "{d}/tiny.png"),
      "scene {d}/tiny.png: frame 1x1 is smaller than one period"),
    C("cli.simulate-corrupt", ("simulate", "{d}/corrupt.png"), "path: cannot read"),
    C("cli.simulate-dark-named", ("simulate", "{d}/small.png", "{d}/rgb.png", "--out",
                                  "{d}/sim_out"),
      "scene {d}/rgb.png: the 99th percentile of the signal is 0"),
    C("cli.simulate-int32", ("simulate", "{d}/int32.tif"),
      "path: {d}/int32.tif holds int32 samples, a type that says nothing about the range of "
      "their values; pass --input-bits"),
    C("cli.reconstruct-colour-matrix-huge", ("reconstruct", "{d}/ok.npz", "--output", "srgb",
                                             "--colour-matrix", "1e300,0,0,0,1,0,0,0,1"),
      "argument --colour-matrix: expected entries within +-1e+30", usage=True),
    C("cli.evaluate-too-small", ("evaluate", "--dataset", "{d}/ds", "--methods", "bi",
                                 "--patterns", "mask1", "--metrics", "ms_ssim", "--crop", "0"),
      "--metrics: image 'a': MS-SSIM with 5 scales needs at least 161 x 161 pixels"),
    C("cli.evaluate-seed-without-noise", ("evaluate", "--dataset", "{d}/ds", "--seed", "3"),
      "--seed: applies with --noise (a noise-free run draws nothing)"),
    C("cli.evaluate-int32", ("evaluate", "--dataset", "{d}/int32.tif"),
      "--dataset: {d}/int32.tif holds int32 samples, a type that says nothing about the range "
      "of their values; convert the file to 8 or 16 bits"),
    C("cli.simulate-cmyk", ("simulate", "{d}/cmyk.jpg"),
      "path: cannot read {d}/cmyk.jpg as an image (it holds CMYK samples"),
    C("cli.evaluate-cmyk", ("evaluate", "--dataset", "{d}/cmyk.tif"),
      "--dataset: cannot read {d}/cmyk.tif as an image (it holds CMYK (separated) samples"),
    C("cli.simulate-over-input", ("simulate", "{d}/collide/a.png", "{d}/collide/a_mask1.npz",
                                  "--out", "{d}/collide"),
      "--out: writing {d}/collide/a_mask1.npz (from {d}/collide/a.png) would overwrite the "
      "input {d}/collide/a_mask1.npz"),
    C("cli.reconstruct-over-input", ("reconstruct", "{d}/collide/a_mask1.npz",
                                     "{d}/collide/a_mask1_sg_cfa.tif", "--out", "{d}/collide"),
      "--out: writing {d}/collide/a_mask1_sg_cfa.tif (from {d}/collide/a_mask1.npz) would "
      "overwrite the input {d}/collide/a_mask1_sg_cfa.tif"),
    C("cli.evaluate-out-in-dataset", ("evaluate", "--dataset", "{d}/ds", "--out", "{d}/ds"),
      "--out: bars_cfa_psnr.png (from the reports) would be written into {d}/ds, a folder read "
      "as input"),
    C("cli.calibrate-over-frame", ("calibrate", "{d}/tof.npz", "--distances", "1.5", "--out",
                                   "{d}/tof.npz"),
      "--out: writing {d}/tof.npz (from the calibration) would overwrite the input "
      "{d}/tof.npz"),
    C("cli.train-into-dataset", ("train", "--dataset", "{d}/ds", "--out", "{d}/ds/f.png"),
      "--out: f.png (from the filters) would be written into {d}/ds, a folder read as input"),
    C("cli.simulate-out-is-file", ("simulate", "{d}/rgb.png", "--out", "{d}/file.txt"), ""),
    C("cli.reconstruct-missing", ("reconstruct", "{d}/missing.npz"), "path: "),
    C("cli.reconstruct-rgb", ("reconstruct", "{d}/rgb.png"),
      "rgb.png: expected a single-channel Bayer mosaic"),
    C("cli.reconstruct-plain-bits", ("reconstruct", "{d}/plain.tif", "--pattern", "mask1"),
      "--bit-depth: required for a plain TIFF/PNG mosaic"),
    C("cli.reconstruct-bits", ("reconstruct", "{d}/plain.tif", "--pattern", "mask1",
                               "--bit-depth", "99"), "--bit-depth: expected 1..16 bits"),
    C("cli.reconstruct-extension", ("reconstruct", "{d}/notes.xyz"),
      "path: unknown raw extension"),
    C("cli.reconstruct-method", ("reconstruct", "{d}/ok.npz", "--method", "edi_rows"),
      "--method: 'edi_rows' needs"),
    C("cli.reconstruct-method-unknown", ("reconstruct", "{d}/ok.npz", "--method", "nope"),
      "--method: expected one of"),
    C("cli.reconstruct-workers", ("reconstruct", "{d}/ok.npz", "--workers", "0"),
      "argument --workers: expected a positive integer, got '0'", usage=True),
    C("cli.reconstruct-precision", ("reconstruct", "{d}/ok.npz", "--precision", "float16"),
      "argument --precision: invalid choice", usage=True),
    C("cli.reconstruct-truncated", ("reconstruct", "{d}/truncated.npz"),
      "path: {d}/truncated.npz is not a readable rgbz-fast frame"),
    C("cli.reconstruct-header", ("reconstruct", "{d}/nokeys.npz"),
      "path: {d}/nokeys.npz is not a readable rgbz-fast frame (missing key 'pattern')"),
    C("cli.reconstruct-corrupt-png", ("reconstruct", "{d}/corrupt.png", "--pattern", "mask1",
                                      "--bit-depth", "11"), "path: cannot read {d}/corrupt.png"),
    C("cli.evaluate-out-empty", ("evaluate", "--dataset", "{d}/ds", "--out", ""),
      "argument --out: an empty path (an unset shell variable?)", usage=True),
    C("cli.reconstruct-frame-empty", ("reconstruct", ""),
      "argument frames: an empty path (an unset shell variable?)", usage=True),
    C("cli.bench-numpy-reference-empty", ("bench", "--quick", "--numpy-reference", ""),
      "argument --numpy-reference: an empty path (an unset shell variable?)", usage=True),
    C("cli.evaluate-empty", ("evaluate", "--dataset", "{d}/empty"),
      "--dataset: no image files in"),
    C("cli.evaluate-patterns-twice", ("evaluate", "--dataset", "{d}/ds", "--patterns",
                                      "mask1,mask1_grbg"),
      "--patterns: 'mask1_grbg' is given twice (as 'mask1')"),
    C("cli.evaluate-methods-twice", ("evaluate", "--dataset", "{d}/ds", "--methods", "sg,sg"),
      "argument --methods: 'sg' is given twice in 'sg,sg'; name each entry once", usage=True),
    C("cli.bench-repeat-huge", ("bench", "--repeat", "100000000"),
      "argument --repeat: expected an integer in [1, 1000], got '100000000'", usage=True),
    C("cli.bench-numpy-reference-no-py", ("bench", "--numpy-reference", "{d}/corrupt.mat"),
      "--numpy-reference: cannot load {d}/corrupt.mat (SyntaxError"),
    C("cli.hardware-pattern-no-z", ("hardware", "--pattern", "bayer"),
      "--pattern: 'bayer' has no Z site; give an RGB-Z pattern such as 'mask1'"),
    C("cli.opcount-image-attribute", ("opcount", "--image", "data_dir"),
      "--image: 'data_dir' is neither a file nor one of scikit-image's RGB sample images"),
    C("cli.opcount-patterns-twice", ("opcount", "--image", "none", "--patterns",
                                     "mask1,mask1_grbg"),
      "--patterns: 'mask1_grbg' is given twice (as 'mask1')"),
    C("cli.hardware-out-in-dataset", ("hardware", "--dataset", "{d}/ds", "--sweep", "--out",
                                      "{d}/ds"),
      "--out: hardware_sweep.png (from the report) would be written into {d}/ds, a folder "
      "read as input"),
    C("cli.tradeoff-out-in-dataset", ("tradeoff", "--dataset", "{d}/ds", "--out", "{d}/ds"),
      "--out: tradeoff.png (from the report) would be written into {d}/ds, a folder read as "
      "input"),
    C("cli.evaluate-missing", ("evaluate", "--dataset", "{d}/missing"), "--dataset: "),
    C("cli.evaluate-crop", ("evaluate", "--dataset", "{d}/ds", "--crop", "-1"),
      "argument --crop: expected an integer >= 0, got '-1'", usage=True),
    C("cli.evaluate-methods", ("evaluate", "--dataset", "{d}/ds", "--methods", "nope"),
      "--methods: unknown method(s)"),
    C("cli.evaluate-metrics", ("evaluate", "--dataset", "{d}/ds", "--metrics", "nope"),
      "--metrics: unknown metric(s)"),
    C("cli.evaluate-patterns", ("evaluate", "--dataset", "{d}/ds", "--patterns", "foo"),
      "pattern: 'foo' is neither"),
    C("cli.evaluate-processes", ("evaluate", "--dataset", "{d}/ds", "--processes", "0"),
      "argument --processes: expected a positive integer, got '0'", usage=True),
    C("cli.evaluate-workers", ("evaluate", "--dataset", "{d}/ds", "--workers", "0"),
      "argument --workers: expected a positive integer, got '0'", usage=True),
    C("cli.evaluate-image-small", ("evaluate", "--dataset", "{d}/small.png", "--processes", "1",
                                   "--no-cache", "--no-plots"),
      "--crop: image 'small': --crop 8 leaves"),
    C("cli.evaluate-corrupt", ("evaluate", "--dataset", "{d}/ds_corrupt", "--processes", "1",
                               "--no-cache", "--metrics", "cfa_psnr"),
      "--dataset: cannot read {d}/ds_corrupt/a.png"),
    C("cli.evaluate-out-is-file", ("evaluate", "--dataset", "{d}/ds", "--processes", "1",
                                   "--metrics", "cfa_psnr", "--out", "{d}/file.txt"), ""),
    C("cli.simulate-grey", ("simulate", "{d}/grey.png"),
      "path: {d}/grey.png is a grey image (16x16); a colour sensor needs colour: pass --grey"),
    C("cli.simulate-max-pixels", ("simulate", "{d}/rgb.png", "--max-pixels", "0"),
      "argument --max-pixels: expected a positive integer, got '0'", usage=True),
    C("cli.reconstruct-plain-bayer", ("reconstruct", "{d}/plain.tif", "--phase", "RGGB",
                                      "--black-level", "0", "--white-level", "1023"),
      "--rgbz-pattern: {d}/plain.tif is a plain Bayer frame (bayer_rggb, no Z sites), so there "
      "is nothing to reconstruct"),
    C("cli.reconstruct-rgbz-on-rgbz", ("reconstruct", "{d}/ok.npz", "--rgbz-pattern", "mask1"),
      "--rgbz-pattern: {d}/ok.npz already has Z sites (pattern mask1)"),
    C("cli.reconstruct-raw-flag-on-frame", ("reconstruct", "{d}/ok.npz", "--phase", "RGGB"),
      "--phase: {d}/ok.npz is an rgbz-fast frame file"),
    C("cli.reconstruct-two-patterns", ("reconstruct", "{d}/plain.tif", "--pattern", "mask1",
                                       "--rgbz-pattern", "mask1"),
      "--pattern: names the pattern of a plain mosaic that already holds Z sites"),
    C("cli.reconstruct-png-phase", ("reconstruct", "{d}/bayer16.png", "--rgbz-pattern",
                                    "mask1"),
      "--phase: bayer16.png does not record its CFA phase, its black level or its white level; "
      "pass --phase (one of GRBG, RGGB, BGGR, GBRG), --black-level (one value or four, per "
      "quad site) and --white-level (or --bit-depth-in;"),
    C("cli.reconstruct-headerless-shape", ("reconstruct", "{d}/bayer.raw", "--rgbz-pattern",
                                           "mask1", "--phase", "RGGB", "--black-level", "0",
                                           "--white-level", "1023"),
      "--shape: the headerless file bayer.raw needs --shape ROWSxCOLS"),
    C("cli.reconstruct-shape-syntax", ("reconstruct", "{d}/bayer.raw", "--shape", "4*4"),
      "argument --shape: expected ROWSxCOLS such as 1080x1920 (rows first), got '4*4'",
      usage=True),
    C("cli.reconstruct-levels-syntax", ("reconstruct", "{d}/bayer.raw", "--black-level", "1,2"),
      "argument --black-level: expected one value or four, got 2", usage=True),
    C("cli.reconstruct-raw-options-deep", ("reconstruct", "{d}/bayer16.png", "--rgbz-pattern",
                                           "mask1", "--raw-options", "{d}/deep.json"),
      "--raw-options: {d}/deep.json nests its JSON too deeply"),
    C("cli.reconstruct-raw-options-unknown", ("reconstruct", "{d}/bayer16.png",
                                              "--rgbz-pattern", "mask1", "--raw-options",
                                              "{d}/unknown.json"),
      "--raw-options: {d}/unknown.json: 'phse' (for '*') is not a raw option"),
    C("cli.reconstruct-raw-options-twice", ("reconstruct", "{d}/bayer16.png",
                                            "--rgbz-pattern", "mask1", "--raw-options",
                                            "{d}/raw_twice.json"),
      "--raw-options: {d}/raw_twice.json gives 'phase' twice"),
    C("cli.evaluate-raw-options-binary", ("evaluate", "--dataset", "{d}/ds", "--raw-options",
                                          "{d}/binary.json"),
      "--raw-options: {d}/binary.json is not a UTF-8 text file"),
    C("cli.calibrate-sensor-deep", ("calibrate", "--simulate", "--sensor", "[" * 5000),
      "--sensor: not JSON"),
    C("cli.reconstruct-raw-options", ("reconstruct", "{d}/bayer16.png", "--rgbz-pattern",
                                      "mask1", "--raw-options", "{d}/raw_options.json"),
      "--raw-options: {d}/raw_options.json should map file names"),
    C("cli.reconstruct-same-output", ("reconstruct", "{d}/ok.npz", "{d}/sub/ok.npz"),
      "--out: {d}/ok.npz and {d}/sub/ok.npz would both write"),
    C("cli.reconstruct-fifo", ("reconstruct", "{d}/fifo.npz"),
      "path: {d}/fifo.npz is a FIFO (named pipe), not a regular file"),
    C("cli.reconstruct-device", ("reconstruct", "{d}/zero.raw", "--shape", "4x4", "--phase",
                                 "RGGB", "--black-level", "0", "--white-level", "1023",
                                 "--rgbz-pattern", "mask1"),
      "path: {d}/zero.raw is a character device, not a regular file"),
    C("cli.reconstruct-max-pixels", ("reconstruct", "{d}/ok.npz", "--max-pixels", "10"),
      "path: {d}/ok.npz declares a 16x16 image (256 pixels), more than the limit of 10 "
      "pixels; raise it with --max-pixels or RGBZ_FAST_MAX_PIXELS"),
    C("cli.reconstruct-zip-bomb", ("reconstruct", "{d}/bomb.npz", "--max-bytes", "1000000"),
      "path: {d}/bomb.npz is not a readable rgbz-fast frame (its arrays declare 2097"),
    C("cli.depth-no-taps", ("depth", "{d}/ok.npz"), "path: {d}/ok.npz holds no ToF taps"),
    C("cli.reconstruct-z_guided-no-taps", ("reconstruct", "{d}/ok.npz", "--method", "z_guided",
                                           "--out", "{d}/zg_out"),
      "--method z_guided: {d}/ok.npz carries no ToF taps, and the method is guided by the NIR"),
    C("cli.depth-range", ("depth", "{d}/tof.npz", "--range", "2:1"),
      "argument --range: expected 0 <= MIN < MAX <= 10000 m and MAX - MIN >= 0.001 m, got "
      "'2:1'", usage=True),
    C("cli.depth-range-huge", ("depth", "{d}/tof.npz", "--range", "1e308:1.7e308"),
      "argument --range: expected 0 <= MIN < MAX <= 10000 m", usage=True),
    C("cli.evaluate-limit-zero", ("evaluate", "--dataset", "{d}/ds", "--limit", "0"),
      "argument --limit: expected a positive integer, got '0'", usage=True),
    C("cli.evaluate-limit-negative", ("evaluate", "--dataset", "{d}/ds", "--limit", "-1"),
      "argument --limit: expected a positive integer, got '-1'", usage=True),
    C("cli.evaluate-grey", ("evaluate", "--dataset", "{d}/ds_grey", "--processes", "1",
                            "--no-cache", "--metrics", "cfa_psnr"),
      "--dataset: {d}/ds_grey/g.png is a grey image (16x16); a colour sensor needs colour: pass "
      "--grey"),
    C("cli.bench-shape", ("bench", "--shape", "1920*1080"),
      "argument --shape: expected ROWSxCOLS such as 1080x1920 (rows first), got '1920*1080'",
      usage=True),
    C("cli.opcount-shape", ("opcount", "--shape", "64"),
      "argument --shape: expected ROWSxCOLS such as 1080x1920 (rows first), got '64'",
      usage=True),
    C("cli.bench-workers", ("bench", "--workers", "0"),
      "argument --workers: expected a positive integer", usage=True),
    C("cli.bench-argument", ("bench", "--nope"), "unrecognized arguments: --nope", usage=True),
    C("cli.opcount-pattern", ("opcount", "--patterns", "nope"), "pattern: 'nope' is neither"),
    C("cli.opcount-argument", ("opcount", "--nope"), "unrecognized arguments: --nope",
      usage=True),
    C("cli.tradeoff-workers", ("tradeoff", "--workers", "0"),
      "argument --workers: expected a positive integer", usage=True),
    C("cli.tradeoff-argument", ("tradeoff", "--nope"), "unrecognized arguments: --nope",
      usage=True),
    C("cli.evaluate-optics-options", ("evaluate", "--dataset", "{d}/ds", "--olpf", "1"),
      "--f-number, --olpf and --defocus-um need --optics"),
    C("cli.calibrate-far-huge", ("calibrate", "--simulate", "--far", "1e308"),
      "argument --far: expected a distance in (0, 1000] m, got '1e308'", usage=True),
    C("cli.calibrate-positions-huge", ("calibrate", "--simulate", "--positions", "100000"),
      "argument --positions: expected an integer in [2, 4096], got '100000'", usage=True),
    C("cli.calibrate-no-frames", ("calibrate",),
      "no frames: give .npz frame files with their --distances, or --simulate"),
    C("cli.calibrate-no-distances", ("calibrate", "{d}/ok.npz"),
      "--distances: one distance per frame is needed"),
    C("cli.calibrate-no-taps", ("calibrate", "{d}/ok.npz", "{d}/ok.npz", "--distances", "1,2",
                                "--out", "{d}/cal.npz"), "sweep: the frame holds no ToF taps"),
    C("cli.calibrate-both", ("calibrate", "{d}/ok.npz", "--simulate"),
      "give frame files or --simulate, not both"),
    C("cli.calibrate-sensor", ("calibrate", "--simulate", "--sensor", "[1]"),
      "--sensor: expected a JSON object of ToFSensor arguments"),
    C("cli.calibrate-sensor-value", ("calibrate", "--simulate", "--sensor",
                                     '{"duty_cycle": 0}'),
      "ToFSensor.duty_cycle: expected a finite number > 0 and <= 1"),
    C("cli.evaluate-depth-sections", ("evaluate-depth", "--sections", "speed"),
      "--sections: unknown ['speed']"),
    C("cli.hardware-method", ("hardware", "--method", "z_guided"),
      "argument --method: invalid choice: 'z_guided'", usage=True),
    C("cli.hardware-width", ("hardware", "--width", "0"),
      "argument --width: expected a positive integer", usage=True),
    C("cli.hardware-workers", ("hardware", "--workers", "0"),
      "argument --workers: expected a positive integer, got '0'", usage=True),
    C("cli.hardware-width-line-buffer", ("hardware", "--dataset", "{d}/ds", "--width", "20000"),
      "--width: expected an integer >= 1 and <= 16384, got 20000"),
    C("cli.hardware-fixed-point-syntax", ("hardware", "--fixed-point", "exp_bits"),
      "argument --fixed-point: expected FIELD=VALUE pairs, got 'exp_bits'", usage=True),
    C("cli.hardware-fixed-point-field", ("hardware", "--fixed-point", "exp_table_size=0"),
      "--fixed-point: exp_table_size: expected a power of two from 2 to 65536 entries, got 0"),
    C("cli.hardware-fixed-point-unknown", ("hardware", "--fixed-point", "exp_size=8"),
      "--fixed-point: fixed_point got an unexpected keyword argument 'exp_size'"),
    C("cli.reconstruct-filters-method", ("reconstruct", "{d}/ok.npz", "--method", "sg",
                                         "--filters", "{d}/learned_mask1.npz"),
      "--filters: sg takes no filters; they are the learned and z_guided methods'"),
    C("cli.reconstruct-filters-kind", ("reconstruct", "{d}/ok.npz", "--method", "learned",
                                       "--filters", "{d}/z_guided_mask1_11bit.npz"),
      "--filters: {d}/z_guided_mask1_11bit.npz hold z_guided filters; --method "
      "learned takes its own kind (rgbz-fast train)"),
    C("cli.reconstruct-filters-pattern", ("reconstruct", "{d}/ok.npz", "--method", "learned",
                                          "--filters", "{d}/learned_mask2.npz"),
      "--filters: none of the given learned filters fits pattern 'mask1' (given: mask2)"),
    C("cli.train-encoding-no-linearise", ("train", "--dataset", "{d}/ds", "--encoding",
                                          "linear", "--no-linearise", "--out", "{d}/t.npz"),
      "--encoding: linear contradicts --no-linearise (the sRGB values); give one of them"),
    C("cli.reconstruct-saturation-level-frame-file", ("reconstruct", "{d}/ok.npz",
                                                      "--saturation-level", "900",
                                                      "--clip-level", "auto"),
      "--saturation-level: {d}/ok.npz is an rgbz-fast frame file, which records its own "
      "pattern, bit depth and levels"),
    C("cli.train-z-guided-bit-depth", ("train", "--dataset", "{d}/ds", "--z-guided",
                                       "--bit-depth", "8", "--out", "{d}/t.npz"),
      "--bit-depth: does not apply with --z-guided (its frames are the sensor model's, 11-bit"),
    C("cli.train-z-guided-no-linearise", ("train", "--dataset", "{d}/ds", "--z-guided",
                                          "--no-linearise", "--out", "{d}/t.npz"),
      "--no-linearise: does not apply with --z-guided"),
    C("cli.train-linearise-encoding-srgb", ("train", "--dataset", "{d}/ds", "--linearise",
                                            "--encoding", "srgb", "--out", "{d}/t.npz"),
      "--encoding: srgb contradicts --linearise (the linear values); give one of them"),
    C("cli.train-radius-below-default-hash-radius", ("train", "--dataset", "{d}/ds",
                                                     "--radius", "2", "--out", "{d}/t.npz"),
      "--radius: 2 is narrower than the default --hash-radius 3 (the gradients' window may not "
      "exceed the filter's); give --hash-radius 2 or less"),
    C("cli.train-noise-no-linearise", ("train", "--dataset", "{d}/ds", "--noise",
                                       "--no-linearise", "--out", "{d}/t.npz"),
      "--no-linearise: the sensor model (--noise) takes linear light; fit noisy frames "
      "without it"),
    C("cli.train-seed-without-z-guided", ("train", "--dataset", "{d}/ds", "--seed", "5",
                                          "--out", "{d}/t.npz"),
      "--seed: applies with --noise or --z-guided (a noise-free fit draws nothing)"),
    C("cli.train-dataset-twice", ("train", "--dataset", "{d}/ds", "--dataset", "{d}/ds/",
                                  "--out", "{d}/t.npz"),
      "--dataset: {d}/ds is given twice (as {d}/ds); name each folder once"),
    C("cli.calibrate-simulate-narrow-sweep", ("calibrate", "--simulate", "--near", "0.1",
                                              "--far", "0.5", "--positions", "9", "--orders",
                                              "4", "--frames-per-position", "1", "--out",
                                              "{d}/cal.npz", "--quiet"),
      "--near/--far/--positions: the walls leave 9"),
    C("cli.calibrate-simulate-option-with-frames", ("calibrate", "{d}/ok.npz", "--distances",
                                                    "1", "--pattern", "mask1"),
      "--pattern: applies to --simulate; frame files bring their own sensor and walls"),
    C("cli.calibrate-distance-huge", ("calibrate", "{d}/ok.npz", "--distances", "1e308"),
      "--distances: 1e+308 is not a distance in (0, 1000] m"),
    C("cli.calibrate-distance-empty-entry", ("calibrate", "{d}/ok.npz", "--distances", "1,,2"),
      "--distances: expected comma-separated metres, got '1,,2'"),
    C("cli.calibrate-dark-empty", ("calibrate", "{d}/ok.npz", "--distances", "1", "--dark"),
      "--dark: expected the lens-capped frame files after it"),
    C("cli.calibrate-simulate-distances", ("calibrate", "--simulate", "--distances", "1,2"),
      "--distances: applies to frame files; --simulate makes the sweep"),
    C("cli.calibrate-orders-over-positions", ("calibrate", "--simulate", "--positions", "10"),
      "--positions: 10 wall positions cannot fit --orders 8 harmonics (2 * orders + 1 = 17 "
      "are needed)"),
    C("cli.calibrate-orders-huge", ("calibrate", "--simulate", "--orders", "33"),
      "argument --orders: expected an integer in [1, 32], got '33'", usage=True),
    C("cli.pattern-study-rgbd-size-alone", ("pattern-study", "--dataset", "{d}/ds",
                                            "--rgbd-size", "64x64", "--out", "{d}/study"),
      "--rgbd-size: applies with --rgbd"),
    C("cli.pattern-study-rgbd-limit-alone", ("pattern-study", "--dataset", "{d}/ds",
                                             "--rgbd-limit", "1", "--out", "{d}/study"),
      "--rgbd-limit: applies with --rgbd"),
    C("cli.pattern-study-rgbd-size-default-alone", ("pattern-study", "--dataset", "{d}/ds",
                                                    "--rgbd-size", "384x384", "--out",
                                                    "{d}/study"),
      "--rgbd-size: applies with --rgbd"),
    C("cli.pattern-study-no-cache-and-cache", ("pattern-study", "--dataset", "{d}/ds",
                                               "--no-cache", "--cache", "{d}/c", "--out",
                                               "{d}/study"),
      "--cache: names the cache that --no-cache turns off; give one of them"),
    C("cli.pattern-study-wall-beyond-range", ("pattern-study", "--dataset", "{d}/ds",
                                              "--wall-distance", "20", "--out", "{d}/study"),
      "--wall-distance: 20 m lies beyond the ToF sensor's unambiguous range (7.495 m)"),
    C("cli.pattern-study-train-limit-alone", ("pattern-study", "--dataset", "{d}/ds",
                                              "--train-limit", "1", "--out", "{d}/study"),
      "--train-limit: applies with --train"),
    C("cli.pattern-study-generate-twice", ("pattern-study", "--dataset", "{d}/ds",
                                           "--generate", "block=1 block=2", "--out",
                                           "{d}/study"),
      "--generate: block is given twice in 'block=1 block=2'"),
    C("cli.pattern-study-generate-empty", ("pattern-study", "--dataset", "{d}/ds",
                                           "--generate", "", "--out", "{d}/study"),
      "--generate: an empty specification"),
    C("cli.evaluate-zoom-no-plots", ("evaluate", "--dataset", "{d}/ds", "--zoom", "0,0",
                                     "--no-plots"),
      "--zoom: places the crop figure, which --no-plots leaves out"),
    C("cli.evaluate-raw-options-no-raw", ("evaluate", "--dataset", "{d}/ds", "--raw-options",
                                          "{d}/raw_ok.json"),
      "--raw-options: the dataset holds no raw file"),
    C("cli.evaluate-table-image-unknown", ("evaluate", "--dataset", "{d}/ds", "--table-image",
                                           "nope"),
      "--table-image: 'nope' is not an image of the dataset"),
    C("cli.reconstruct-saturation-without-auto", ("reconstruct", "{d}/bayer16.png",
                                                  "--rgbz-pattern", "mask1", "--phase", "GRBG",
                                                  "--saturation-level", "1000"),
      "--saturation-level: takes effect with --clip-level auto"),
    C("cli.reconstruct-white-balance-cfa", ("reconstruct", "{d}/ok.npz", "--white-balance",
                                            "2,1,1"),
      "--white-balance: applies to --output srgb; the CFA output is the raw values"),
    C("cli.reconstruct-byteorder-png", ("reconstruct", "{d}/bayer16.png", "--rgbz-pattern",
                                        "mask1", "--phase", "GRBG", "--byteorder", "big"),
      "--byteorder: only headerless files take a byte order; bayer16.png is read with the "
      "'image' reader"),
    C("cli.tradeoff-image-too-small", ("tradeoff", "--dataset", "{d}/tiny.png", "--quick"),
      "--dataset: image 'tiny': frame 1x1 is smaller than one period"),
    C("cli.tradeoff-methods-not-measured", ("tradeoff", "--methods", "edi_rows", "--quick"),
      "--methods: edi_rows not measured by tradeoff; expected some of bilinear, bi"),
    C("cli.hardware-fixed-point-twice", ("hardware", "--fixed-point", "exp_bits=10,exp_bits=12"),
      "argument --fixed-point: 'exp_bits' is given twice in 'exp_bits=10,exp_bits=12'; give "
      "each field once", usage=True),
    C("cli.hardware-fixed-point-empty", ("hardware", "--fixed-point", ","),
      "argument --fixed-point: expected at least one comma-separated entry, got ','",
      usage=True),
    C("cli.opcount-methods-empty", ("opcount", "--image", "none", "--methods", ""),
      "argument --methods: expected at least one comma-separated entry, got ''", usage=True),
    C("cli.pattern-study-methods-empty", ("pattern-study", "--dataset", "{d}/ds", "--methods",
                                          " , "),
      "argument --methods: expected at least one comma-separated entry, got ' , '",
      usage=True),
    C("cli.pattern-study-scheduler", ("pattern-study", "--dataset", "{d}/ds", "--scheduler",
                                      "nope", "--out", "{d}/study"),
      "--scheduler: expected a Dask scheduler address such as tcp://host:8786, or a "
      "distributed.Client, got 'nope'"),
    C("cli.pattern-study-cache-file", ("pattern-study", "--dataset", "{d}/ds", "--cache",
                                       "{d}/ok.npz", "--out", "{d}/study"),
      "cache_dir: {d}/ok.npz exists and is not a folder"),
    C("cli.hardware-pattern", ("hardware", "--pattern", "mask7"),
      "--pattern: 'mask7' is neither a preset"),
    C("cli.hardware-dataset", ("hardware", "--dataset", "{d}/missing"),
      "--dataset: {d}/missing does not exist"),
    C("cli.hardware-out-file", ("hardware", "--out", "{d}/ok.npz"),
      "--out: '{d}/ok.npz' exists and is not a folder"),
    C("cli.config-argument", ("config", "--nope"), "unrecognized arguments: --nope",
      usage=True),
    C("cli.reconstruct-workers-huge", ("reconstruct", "{d}/ok.npz", "--workers", "5000"),
      "argument --workers: expected at most 1024 threads, got '5000'", usage=True),
    C("cli.simulate-long-name", ("simulate", "{d}/" + "a" * 296 + ".png"), "scene: "),
    C("cli.evaluate-long-out", ("evaluate", "--dataset", "{d}/ds", "--out",
                                "{d}/" + "o" * 300), "--out: "),
    C("cli.train-long-dataset", ("train", "--dataset", "{d}/" + "a" * 300, "--out",
                                 "{d}/f.npz"), "--dataset: "),
    C("cli.evaluate-fifo", ("evaluate", "--dataset", "{d}/fifo.tif"),
      "--dataset: {d}/fifo.tif is a FIFO (named pipe), not a regular file"),
    C("cli.simulate-out-uncreatable", ("simulate", "{d}/small.png", "--out", "/proc/rgbz-out"),
      "--out: '/proc/rgbz-out': cannot write in '/proc' (No such file or directory)"),
    C("cli.bench-numpy-reference-without-reference", ("bench", "--no-reference",
                                                      "--numpy-reference", "{d}/missing.py"),
      "--numpy-reference: times the NumPy reference, which --no-reference leaves out"),
    C("cli.bench-kernels-none-match", ("bench", "--kernels", "xyz", "--chain", "--repeat", "1"),
      "--kernels: no case matches 'xyz'"),
    C("cli.hardware-limits-without-dataset", ("hardware", "--max-pixels", "10"),
      "--max-pixels: limits the files the command reads; without --dataset it reads none"),
    C("cli.calibrate-limits-with-simulate", ("calibrate", "--simulate", "--max-bytes", "10"),
      "--max-bytes: limits the files the command reads; --simulate reads none"),
    C("cli.bench-out-under-file", ("bench", "--quick", "--out", "{d}/small.png/results"),
      "--out: '{d}/small.png/results': '{d}/small.png' is not a folder"),
    C("cli.opcount-out-uncreatable", ("opcount", "--shape", "32x32", "--out", "/proc/rgbz-out"),
      "--out: '/proc/rgbz-out': cannot write in '/proc'"),
    C("cli.simulate-scene-twice", ("simulate", "{d}/small.png", "{d}/small.png", "--out",
                                   "{d}/sim_twice"),
      "{d}/small.png: given twice; give each input once"),
    C("cli.simulate-seed-without-noise", ("simulate", "{d}/small.png", "--no-noise",
                                          "--seed", "3"),
      "--seed: draws the sensor noise, which --no-noise leaves out"),
    C("cli.simulate-seed-zero-without-noise", ("simulate", "{d}/small.png", "--no-noise",
                                               "--seed", "0"),
      "--seed: draws the sensor noise, which --no-noise leaves out"),
    C("cli.opcount-quick-shape", ("opcount", "--quick", "--shape", "64x64"),
      "--shape: --quick counts on a 32x32 frame; give one of them"),
    C("cli.simulate-option-twice", ("simulate", "{d}/small.png", "--pattern", "mask1",
                                    "--pattern", "mask2"),
      "--pattern: given twice (only the last would apply)", usage=True),
    C("cli.simulate-flag-and-its-negation", ("simulate", "{d}/small.png", "--noise",
                                             "--no-noise"),
      "--noise, --no-noise: given twice (only the last would apply)", usage=True),
    C("cli.hardware-abbreviation-twice", ("hardware", "--width", "64", "--wid=128"),
      "--width, --wid: given twice (only the last would apply)", usage=True),
    C("cli.hardware-fixed-point-unused", ("hardware", "--fixed-point", "tap_bits=4"),
      "--fixed-point: tap_bits does not reach sg's datapath"),
    C("cli.hardware-sweep-bilinear", ("hardware", "--method", "bilinear", "--sweep"),
      "--sweep: bilinear is exact, with no width to move"),
    C("cli.hardware-learned-no-filters", ("hardware", "--method", "learned", "--pattern",
                                          "rows"),
      "filters: none fits pattern 'rows'; filters ship for mask1, mask2 and their other Bayer "
      "phases; fit some with rgbz-fast train and pass filters=FILE (a library argument: "
      "rgbz-fast hardware has no --filters)"),
    C("cli.hardware-out-under-file", ("hardware", "--out", "{d}/small.png/x/y"),
      "--out: '{d}/small.png/x/y': '{d}/small.png' is not a folder"),
    C("cli.calibrate-shape-huge", ("calibrate", "--simulate", "--shape", "100000x100000",
                                   "--out", "{d}/cal_huge.npz"),
      "--shape: 100000x100000 is 1e+04 megapixels, more than the limit of 200 megapixels "
      "(--max-pixels or RGBZ_FAST_MAX_PIXELS)"),
    C("cli.opcount-shape-huge", ("opcount", "--shape", "100000x100000"),
      "--shape: 100000x100000 is 1e+04 megapixels, more than the limit of 200 megapixels "
      "(RGBZ_FAST_MAX_PIXELS)"),
    C("cli.reconstruct-frame-pattern", ("reconstruct", "{d}/ok.npz", "--pattern", "bayer"),
      "--pattern: {d}/ok.npz records its own pattern 'mask1'; --pattern 'bayer' applies to a "
      "plain TIFF/PNG mosaic"),
    C("cli.reconstruct-frame-bit-depth", ("reconstruct", "{d}/ok.npz", "--bit-depth", "12"),
      "--bit-depth: {d}/ok.npz records its own bit depth 11; --bit-depth 12 applies"),
]

test_cli_contract = cli_tests(CLI_ROWS)


def test_cli_interrupt_exits_130(monkeypatch, capsys):
    import rgbz_fast._cli.config as config_command

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(config_command, "run", interrupted)
    assert main(["config"]) == 130
    assert capsys.readouterr().err.strip() == "rgbz-fast config: interrupted"


def test_cli_reconstruct_of_a_broken_frame_writes_nothing(files, tmp_path, capsys):
    """A frame file that does not load: exit 2, one line naming the file, no traceback, no
    output file."""
    out = tmp_path / "out"
    for name in ("truncated.npz", "nokeys.npz", "notjson.npz"):
        assert main(["reconstruct", str(files / name), "--out", str(out), "--quiet"]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1, err
        assert err[0].startswith(f"rgbz-fast reconstruct: error: path: {files / name} is not "
                                 "a readable rgbz-fast frame"), err
    assert not out.exists() or not [p for p in out.rglob("*") if p.is_file()]


# --------------------------------------------------------------------------- interrupted writes
WRITE_LOOP = textwrap.dedent("""
    import signal, sys
    from pathlib import Path
    from rgbz_fast import _cli, io as rio
    signal.signal(signal.SIGTERM, _cli._terminate)      # what `rgbz-fast CMD` installs
    blob = bytes(range(256)) * (1 << 17)                # 32 MiB per write
    print("ready", flush=True)
    i = 0
    try:
        while True:
            rio.atomic_write(Path(sys.argv[1]) / f"f{i % 3}.bin", blob)
            i += 1
    except _cli.Terminated as exc:
        sys.exit(exc.code)
""")


@pytest.mark.skipif(not hasattr(signal, "SIGTERM"), reason="POSIX signals")
def test_sigterm_during_writes_leaves_no_temporary_file(tmp_path):
    """SIGTERM inside atomic_write leaves no hidden .tmp file: the command line's handler
    turns the signal into an exception, and the write removes its temporary file."""
    out = tmp_path / "w"
    out.mkdir()
    for delay in (0.02, 0.13, 0.31, 0.57):
        proc = subprocess.Popen([sys.executable, "-c", WRITE_LOOP, str(out)],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert proc.stdout.readline().strip() == "ready", proc.stderr.read()
        time.sleep(delay)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=60)
        assert proc.returncode == 128 + signal.SIGTERM, err[-2000:]
        left = sorted(p.name for p in out.iterdir())
        assert not [n for n in left if n.endswith(".tmp")], left
        for p in out.iterdir():
            assert p.stat().st_size == 256 << 17          # whole files only


def test_outputs_are_checked_against_inputs_before_anything_is_written(files, tmp_path,
                                                                      capsys):
    """One input/output collision check (``_cli._common.check_outputs``): an output that is
    an input -- by name, through a symbolic or a hard link -- or that would land in a dataset
    folder as an image is refused before anything is written, and every input keeps its
    bytes. An output folder beside the inputs, or a subfolder of the dataset, is fine."""
    import os
    import shutil

    d = tmp_path / "w"
    shutil.copytree(files / "collide", d)
    shutil.copy(files / "small.png", d / "a.png")
    (d / "link.tif").symlink_to(d / "a_mask1_sg_cfa.tif")
    os.link(d / "a_mask1.npz", d / "hard.npz")
    before = {p.name: p.read_bytes() for p in d.iterdir() if p.is_file()}
    cases = [
        ("reconstruct", str(d / "a_mask1.npz"), str(d / "link.tif"), "--out", str(d)),
        ("simulate", str(d / "a.png"), str(d / "hard.npz"), "--out", str(d)),
        ("simulate", str(d / "a.png"), "--out", str(d), "--format", "npz",
         "--pattern", "mask1"),                                   # over a_mask1.npz: no input
        ("evaluate", "--dataset", str(d), "--out", str(d), "--metrics", "cfa_psnr"),
    ]
    for argv in cases[:2] + cases[3:]:
        assert main([*argv, "--quiet"]) == 2
        assert "would" in capsys.readouterr().err
    assert {p.name: p.read_bytes() for p in d.iterdir() if p.is_file()} == before
    # not an input: a_mask1.npz is rewritten from a.png, as asked
    assert main([*cases[2], "--quiet"]) == 0
    # a subfolder of the dataset is not read (the listing is not recursive)
    ds = tmp_path / "ds"
    shutil.copytree(files / "ds", ds)
    assert main(["evaluate", "--dataset", str(ds), "--out", str(ds / "results"), "--metrics",
                 "cfa_psnr", "--methods", "bi", "--patterns", "mask1", "--quiet"]) == 0
    assert sorted(p.name for p in ds.iterdir()) == ["a.png", "results"]


def test_an_allocation_that_fails_is_one_error_line(files, capsys, monkeypatch):
    """A MemoryError that no size check foresaw ends the command with exit 2 and one error
    line, not a traceback."""
    from rgbz_fast._cli import reconstruct as command

    def no_memory(args):
        raise MemoryError("Unable to allocate 224. GiB")

    monkeypatch.setattr(command, "run", no_memory)
    assert main(["reconstruct", str(files / "ok.npz"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["rgbz-fast reconstruct: error: out of memory (Unable to allocate 224. GiB); "
                   "try a smaller input or --max-pixels"]
