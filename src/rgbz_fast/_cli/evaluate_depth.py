"""``rgbz-fast evaluate-depth``: the ToF chain measured (RGB-D scenes, range, noise,
sunlight, calibration), as Markdown tables or JSON."""

from __future__ import annotations

import sys
from pathlib import Path

from . import _common as c

NAME = "evaluate-depth"


def add_parser(sub):
    p = c.command_parser(
        sub, NAME, "the ToF chain measured: scenes, range, noise, sunlight",
        "Simulate and measure the ToF chain at the library's defaults: the six Middlebury "
        "RGB-D scenes (wrong, wrong-and-valid, caught), depths beyond the unambiguous range "
        "(flagged), depth noise against the predicted sigma, sunlight, and the calibration's "
        "residual cyclic error. Prints Markdown tables.")
    p.add_argument("--data", type=c.path, default=None, metavar="DIR",
                   help="folder of the Middlebury scenes (default: ../shared/data/rgbd when it "
                        "exists; without it the scene sections are skipped)")
    p.add_argument("--rgbnir", type=c.path, default=None, metavar="DIR",
                   help="folder of the RGB-NIR pairs of the rgbnir section (default: rgbnir "
                        "beside --data)")
    p.add_argument("--sections", type=c.csv, default=None,
                   help="comma list from scenes,upsample,rgbnir,range,noise,sunlight,"
                        "calibration (default: all)")
    c.add_patterns(p, default=None, what="comma-separated patterns of the scene sections (scenes, upsample, "
                 "rgbnir): mask1, mask2, rows or tiles such as ZRGR/BGBG/GRZR/BGBG, "
                 "with Z pixels of 1x1 or 2x2 sites (default: mask1,mask2); the other "
                 "sections measure mask1 and mask2")
    c.add_seed(p, 1, "seed of the sensor noise")
    c.add_json(p, "print the rows as JSON")
    c.add_quiet(p, "no progress line")
    c.add_limits(p)
    return p


def run(args):
    from ..evaluation import DEPTH_SECTIONS, depth_report, evaluate_depth

    data = args.data
    if data is None:
        guess = Path("..") / "shared" / "data" / "rgbd"
        data = guess if guess.is_dir() else None
    scene_sections = [s for s in (args.sections or DEPTH_SECTIONS)
                      if s in ("scenes", "upsample")
                      or s == "rgbnir" and args.rgbnir is None]
    if data is None and args.sections and scene_sections:
        # asked for, they had printed nothing (or {}) and exited 0 (the rgbnir pairs are
        # found beside --data)
        raise c.CliError(f"--sections: {scene_sections[0]} needs the data folders: pass "
                         "--data DIR, the RGB-D scenes (../shared/data/rgbd, the default, is "
                         "not beside the current folder; the RGB-NIR pairs are read from "
                         "rgbnir beside it)")
    sections = args.sections or DEPTH_SECTIONS
    # --patterns, --rgbnir given for sections that do not read them: refused before any work,
    # by evaluate_depth's rule (its ValueError, "patterns: ... patterns= applies to ...", is
    # printed in the command's words, "--patterns: ... --patterns applies to ...")
    from ..evaluation._depth import check_unread, reads_data

    check_unread(sections, args.patterns, args.rgbnir, args.data)
    rgbnir = args.rgbnir if args.rgbnir is not None else (
        Path(data).parent / "rgbnir" if data is not None else None)
    if args.rgbnir is not None and not Path(args.rgbnir).is_dir():
        raise c.CliError(f"--rgbnir: {args.rgbnir} is not a folder")
    from ..evaluation._depth_guided import rgbnir_pairs

    found = rgbnir is not None and rgbnir.is_dir() and bool(rgbnir_pairs(rgbnir))
    if "rgbnir" in sections and not found:
        # asked for (--sections or --rgbnir), a missing or pairless folder had printed an
        # empty section (or {}) and exited 0 (H103); the default folder of the default
        # sections is skipped with a line
        flag = "--sections" if args.sections else "--rgbnir"
        if rgbnir is not None and rgbnir.is_dir() and (args.sections or args.rgbnir):
            raise c.CliError(f"{flag}: rgbnir found no pair NNNN_rgb.png + NNNN_nir.png in "
                             f"{rgbnir}")
        if args.sections:
            raise c.CliError(f"--sections: rgbnir needs the RGB-NIR pairs: {rgbnir} is not a "
                             "folder; pass --rgbnir DIR" if rgbnir is not None else
                             "--sections: rgbnir needs the RGB-NIR pairs: pass --rgbnir DIR "
                             "(or --data DIR with rgbnir beside it)")
        if rgbnir is not None:
            print(f"rgbz-fast {NAME}: no RGB-NIR pairs at {rgbnir}: the rgbnir section is "
                  "skipped (--rgbnir DIR)", file=sys.stderr)
    from .._progress import ticking

    # the six scenes and the pairs take half a minute or more: a line whose time ticks on a
    # terminal (the command had shown nothing, and took no --quiet)
    with ticking(f"{NAME}: {','.join(sections)}", c.bars(args)):
        # the default folders only where a section reads them (evaluate_depth refuses a
        # data= or rgbnir= no section reads, as the command refuses --data and --rgbnir)
        result = evaluate_depth(data if reads_data(sections, args.rgbnir) else None,
                                sections=sections, seed=args.seed,
                                patterns=args.patterns,
                                rgbnir=rgbnir if found and "rgbnir" in sections else None,
                                **c.limits(args))
    if args.json:
        # strict JSON, as the other commands' (H40, H48): a value that has none (an RMSE
        # without a valid measurement, a spread of one) is null; it had been NaN, which
        # strict parsers (jq, JSON.parse) refuse
        from .._devtools._common import json_text

        print(json_text(result))
    else:
        if data is None and scene_sections:
            print("(no RGB-D scenes: pass --data; the scene sections are skipped)")
        print(depth_report(result))
    return 0
