"""SG's CFA PSNR margins over BI and EDILine, per optics: the margin table of
docs/reports/results.md ("With optics").

    python tools/sg_margins.py results/kodak-none/results.csv \
        results/kodak-optics/results.csv results/kodak-olpf/results.csv

Each file is the results.csv of one ``rgbz-fast evaluate`` run (no optics, f/2.8,
f/2.8 + OLPF, in that order). Per pattern and method, one Markdown row: for each
run the mean over the images of SG minus the method (and on how many images SG
is better), then the same difference on kodim09 alone.
"""

import csv
import sys
from collections import defaultdict

import numpy as np


def load(path):
    """{(pattern, method): {image: CFA PSNR}} of one results.csv."""
    v = defaultdict(dict)
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if r["metric"] == "cfa_psnr":
                v[r["pattern"], r["method"]][r["image"]] = float(r["value"])
    return v


def main(paths):
    runs = [load(p) for p in paths]
    for pattern in ("mask1", "mask2"):
        for other, label in (("bi", "BI"), ("edi_line", "EDILine")):
            cells, k9 = [], []
            for v in runs:
                sg, o = v[pattern, "sg"], v[pattern, other]
                d = np.array([sg[i] - o[i] for i in sorted(sg)])
                cells.append(f"{d.mean():+.2f} ({(d > 0).sum()}/{d.size})")
                k9.append(f"{sg['kodim09'] - o['kodim09']:+.2f}")
            print(f"| {pattern.title()} SG − {label} | " + " | ".join(cells + k9) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
