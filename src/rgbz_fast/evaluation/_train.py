"""Fitting learned filters to a dataset with the evaluation's protocol."""

from __future__ import annotations

import os
from contextlib import ExitStack
from dataclasses import replace
from pathlib import Path

from .._patterns import get_pattern
from .._progress import ticking
from ..reconstruction import train
from ._config import EvalConfig
from ._run import dataset_sources, image_frames

__all__ = ["train_filters"]


def train_filters(dataset, pattern, *, bit_depth=11, noise=False, linearise=True, seed=0,
                  limit=None, name=None, progress=False, **options):
    """Fit :class:`~rgbz_fast.reconstruction.LearnedFilters` to a folder of images.

    Every image becomes a frame of ``pattern`` and its reference Bayer CFA
    exactly as :func:`evaluate` makes them (:func:`image_frames`: sRGB EOTF,
    mosaic at ``bit_depth``; or the sensor model with ``noise``), and
    :func:`rgbz_fast.reconstruction.train` fits the filters to all of them.
    ``rgbz-fast train`` runs this.

    Parameters
    ----------
    dataset : str, Path, list of ImageSource or None
        A folder of images (:func:`~rgbz_fast.io.folder_dataset`), a list of
        sources, or None (the sample images). Fit on images you will not
        evaluate on.
    pattern : Pattern or str
        The pattern to fit the filters for.
    bit_depth : int
        Bits of the frames (11: the evaluation's default).
    noise : bool
        Fit on noisy frames (the sensor model, seeds ``seed``, ``seed + 1``...
        per image) instead of noise-free ones.
    linearise : bool
        False: mosaic the sRGB values as they are (the 8-bit sRGB protocol,
        :class:`EvalConfig`'s ``linearise``).
    seed : int
        Noise seed of the first image.
    limit : int, optional
        Only the first ``limit`` images.
    name : str, optional
        The training set's name kept in the filters (default: the folder's
        name).
    progress : bool
        Show a progress bar.
    **options
        Passed to :func:`~rgbz_fast.reconstruction.train` (``radius``,
        ``hash_radius``, ``n_strength``, ``n_coherence``, ``ridge``, ``prior``).

    Returns
    -------
    LearnedFilters
        With ``meta``: ``training_set``, ``n_images``, ``noise``,
        ``encoding`` (``"linear"`` or ``"srgb"``) and the fit's settings.

    Examples
    --------
    >>> from rgbz_fast.evaluation import train_filters
    >>> from rgbz_fast.io import sample_dataset
    >>> f = train_filters(sample_dataset()[:1], "mask1", n_strength=1, n_coherence=1)
    >>> f.meta["training_set"], f.meta["encoding"], f.n_buckets
    ('astronaut', 'linear', 8)
    """
    pattern = get_pattern(pattern)
    config = EvalConfig(patterns=(pattern.tile_string,), bit_depth=bit_depth, noise=noise,
                        linearise=linearise, seed=seed, metrics=("cfa_psnr",))
    if isinstance(dataset, (str, os.PathLike)):
        name = name or Path(dataset).resolve().name
    dataset = dataset_sources(dataset, limit)
    name = name or ("+".join(s.name for s in dataset) if len(dataset) <= 3 else "custom")
    from tqdm.auto import tqdm

    fitting = ExitStack()

    def frames():
        for i, source in enumerate(tqdm(dataset, desc="train", unit="img",
                                        disable=not progress)):
            cfg = replace(config, seed=config.seed + i) if noise else config
            frame, ref = image_frames(source.load(), pattern, cfg)
            yield replace(frame, reference=ref)
        fitting.enter_context(ticking("train: fitting the filters", progress))  # images read

    meta = {"training_set": name, "noise": bool(noise),
            "encoding": "linear" if linearise else "srgb", **options.pop("meta", {})}
    with fitting:
        return train(frames(), meta=meta, **options)
