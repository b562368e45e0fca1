"""The training sets of the learned filters, and their splits.

    python tools/learned_fit.py PATTERN OUT.npz [--heldout]

Fits filters on the three folders below in both encodings (``rgbz-fast train --encoding both``
with the settings of :data:`OPTIONS`), on every image or, with ``--heldout``, without the
held-out quarter of each folder (every fourth image in name order, starting with the first),
which tools/learned_targets.py reports on. The shipped filters (reconstruction/data/) are the
``--heldout`` fit, so the held-out scores are those of the filters users get.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rgbz_fast.evaluation import train_filters
from rgbz_fast.io import folder_dataset

DATA = Path(__file__).resolve().parents[1].parent / "shared" / "data"
#: the training folders under the shared data folder
FOLDERS = {"cbsd68": "cbsd68", "manga109": "train_extra/manga109",
           "sun_hays80": "train_extra/sun_hays80"}
#: the settings of the shipped fit (tools/learned_selection.py, docs/guide/learned.md)
OPTIONS = dict(n_strength=3, n_coherence=3, n_spread=3, ridge=1e-3, prior=50.0)


def split(name, data=DATA, keep=lambda i: True):
    """The images ``i`` (name order) of a training folder with ``keep(i)``."""
    return [s for i, s in enumerate(folder_dataset(Path(data) / FOLDERS[name])) if keep(i)]


def heldout_split(name, data=DATA):
    """(held-out images, the others) of a training folder: every fourth from the first."""
    return split(name, data, lambda i: i % 4 == 0), split(name, data, lambda i: i % 4 != 0)


def fit(pattern, data=DATA, hold_out=None, keep=None, progress=False, **options):
    """Filters fitted on the three folders in both encodings; ``hold_out``: any true value
    leaves the held-out quarter of every folder out; ``keep(i)`` selects images otherwise."""
    if hold_out:
        keep = lambda i: i % 4 != 0  # noqa: E731
    sources = [s for name in FOLDERS for s in split(name, data, keep or (lambda i: True))]
    label = "+".join(Path(f).name for f in FOLDERS.values())
    if hold_out:
        label += " without the held-out quarter"
    command = f"python tools/learned_fit.py {pattern} OUT.npz" + (" --heldout" if hold_out else "")
    return train_filters(sources, pattern, encoding="both", name=label, progress=progress,
                         **{**OPTIONS, "meta": {"command": command}, **options})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("pattern")
    ap.add_argument("out", type=Path)
    ap.add_argument("--heldout", action="store_true")
    args = ap.parse_args()
    fit(args.pattern, hold_out=args.heldout, progress=True).save(args.out)


if __name__ == "__main__":
    main()
