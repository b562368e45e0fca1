"""How the floor of eq. 7's sigma moves EDILine against BI and EDICentral, as a Markdown table.

    python tools/edi_floor_sweep.py DATASET [PATTERN] [SIGMA_RELS]

    python tools/edi_floor_sweep.py ../shared/data/train_extra/sun_hays80 mask1 0,0.25,0.5,1,4

For each ``sigma_rel`` (comma-separated; default 0,0.25,0.5,1,4; 0 is eq. 7 as printed,
0.5 the library's default) one noise-free evaluation of BI, EDICentral and EDILine on
PATTERN (default mask1), float64, every metric: the mean of each, and the paired
differences EDILine - BI and EDILine - EDICentral (mean over the images, and on how
many images EDILine is better; lower is better for the zipper metric). BI does not use
sigma, so its row is the same for every floor; a large floor makes every edge factor
about 1 and the EDI methods tend to BI.
"""

import sys

import numpy as np

from rgbz_fast.evaluation import EvalConfig, evaluate

METRICS = ("cfa_psnr", "cpsnr", "ssim", "ms_ssim", "zipper")
LABELS = {"cfa_psnr": "CFA PSNR", "cpsnr": "CPSNR", "ssim": "SSIM", "ms_ssim": "MS-SSIM",
          "zipper": "zipper"}


def _cell(res, pattern, a, b, metric):
    diffs = res.paired(pattern, a, metric, baseline=b)[0]
    wins = int(np.sum(diffs < 0 if metric == "zipper" else diffs > 0))
    digits = 4 if metric in ("ssim", "ms_ssim") else 3
    return f"{diffs.mean():+.{digits}f}, {wins}/{diffs.size}"


def main(dataset, pattern="mask1", sigma_rels="0,0.25,0.5,1,4"):
    floors = [float(s) for s in sigma_rels.split(",")]
    lines = [f"`{dataset}`, {pattern}: the means of BI, EDICentral, EDILine; then the paired "
             "differences (mean, images where EDILine is better)", "",
             "| sigma_rel | metric | BI | EDICentral | EDILine | EDILine - BI | "
             "EDILine - EDICentral |", "|---" * 7 + "|"]
    for sr in floors:
        cfg = EvalConfig(patterns=(pattern,), methods=("bi", "edi_central", "edi_line"),
                         params={"precision": "float64", "sigma_rel": sr})
        res = evaluate(dataset, cfg, progress=False)
        s = res.summary()
        for k in METRICS:
            digits = 4 if k in ("ssim", "ms_ssim") else 3
            means = " | ".join(f"{s[(pattern, m, k)][0]:.{digits}f}"
                               for m in ("bi", "edi_central", "edi_line"))
            lines.append(f"| {sr:g} | {LABELS[k]} | {means} | "
                         f"{_cell(res, pattern, 'edi_line', 'bi', k)} | "
                         f"{_cell(res, pattern, 'edi_line', 'edi_central', k)} |")
    print("\n".join(lines))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(*sys.argv[1:4])
