"""The training sets of the learned filters, and their splits.

    python tools/learned_fit.py PATTERN OUT.npz [--heldout]

Fits filters on the three folders below in both encodings (``rgbz-fast train --encoding both``
with the settings of :data:`OPTIONS`), on every image or, with ``--heldout``, without the
held-out quarter of each folder (every fourth image in name order, starting with the first),
which tools/learned_targets.py reports on. The shipped filters (reconstruction/data/) are the
``--heldout`` fit, so the held-out scores are those of the filters users get.

Every fitted image also enters once with its colour saturated (:func:`saturate`, a factor
drawn from :data:`SATURATION` per image): natural photographs alone teach the filters a
channel correlation that saturated, weakly correlated content does not have. Only the
images of the fit are saturated; the held-out quarter never enters it in any form.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from dataclasses import dataclass

import numpy as np

from rgbz_fast.evaluation import train_filters
from rgbz_fast.io import ImageSource, folder_dataset

DATA = Path(__file__).resolve().parents[1].parent / "shared" / "data"
#: the training folders under the shared data folder
FOLDERS = {"cbsd68": "cbsd68", "manga109": "train_extra/manga109",
           "sun_hays80": "train_extra/sun_hays80"}
#: the settings of the shipped fit (tools/learned_selection.py, docs/guide/learned.md)
OPTIONS = dict(n_strength=3, n_coherence=3, n_spread=3, ridge=1e-3, prior=50.0)
#: the range of the saturation factor of the fit's saturated copies (uniform, one per image)
SATURATION = (1.5, 2.5)


def saturate(img8, k):
    """The issue's saturation protocol: skimage rgb2hsv on the 8-bit values, S x ``k`` clipped
    at 1, hsv2rgb, rounded to 8 bits."""
    from skimage.color import hsv2rgb, rgb2hsv
    hsv = rgb2hsv(img8)
    hsv[..., 1] = np.clip(hsv[..., 1] * k, 0, 1)
    return np.round(hsv2rgb(hsv) * 255).astype(np.uint8)


@dataclass(frozen=True)
class Saturated(ImageSource):
    """An image of a training folder with its saturation multiplied by ``k``."""

    k: float = 2.0

    def load(self):
        return saturate(super().load(), self.k)


def saturated_copies(sources, k_range=SATURATION, seed=0):
    """One :class:`Saturated` copy of every source, ``k`` uniform in ``k_range`` (one draw per
    source in order, from ``seed``: the same copies on every run)."""
    ks = np.random.default_rng(seed).uniform(*k_range, size=len(sources))
    return [Saturated(**{**s.__dict__, "name": f"{s.name}_sat{k:.2f}"}, k=float(k))
            for s, k in zip(sources, ks)]


def split(name, data=DATA, keep=lambda i: True):
    """The images ``i`` (name order) of a training folder with ``keep(i)``."""
    return [s for i, s in enumerate(folder_dataset(Path(data) / FOLDERS[name])) if keep(i)]


def heldout_split(name, data=DATA):
    """(held-out images, the others) of a training folder: every fourth from the first."""
    return split(name, data, lambda i: i % 4 == 0), split(name, data, lambda i: i % 4 != 0)


def fit(pattern, data=DATA, hold_out=None, keep=None, progress=False, saturation=SATURATION,
        **options):
    """Filters fitted on the three folders in both encodings; ``hold_out``: any true value
    leaves the held-out quarter of every folder out; ``keep(i)`` selects images otherwise.
    ``saturation``: the range of the factors of the fitted images' saturated copies (None:
    no copies)."""
    if hold_out:
        keep = lambda i: i % 4 != 0  # noqa: E731
    sources = [s for name in FOLDERS for s in split(name, data, keep or (lambda i: True))]
    label = "+".join(Path(f).name for f in FOLDERS.values())
    if hold_out:
        label += " without the held-out quarter"
    if saturation is not None:
        sources += saturated_copies(sources, saturation)
        label += f", and each saturated x U({saturation[0]:g}, {saturation[1]:g})"
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
