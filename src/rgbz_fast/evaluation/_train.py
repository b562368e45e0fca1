"""Fitting learned filters to datasets with the evaluation's protocol."""

from __future__ import annotations

import os
from contextlib import ExitStack
from dataclasses import replace
from pathlib import Path

from .._patterns import get_pattern
from .._progress import ticking
from .._validate import check_choice, check_flag
from ..reconstruction import train
from ._config import EvalConfig
from ._run import dataset_sources, image_frames

__all__ = ["train_filters", "ENCODINGS"]

#: what the training frames hold: linear light (the 8-bit sRGB images through the sRGB
#: EOTF), the sRGB values as they are, or both (every image twice)
ENCODINGS = ("linear", "srgb", "both")


def train_filters(dataset, pattern, *, bit_depth=11, noise=False, linearise=True, encoding=None,
                  seed=0, limit=None, name=None, progress=False, **options):
    """Fit :class:`~rgbz_fast.reconstruction.LearnedFilters` to folders of images.

    Every image becomes a frame of ``pattern`` and its reference Bayer CFA
    exactly as :func:`evaluate` makes them (:func:`image_frames`: sRGB EOTF,
    mosaic at ``bit_depth``; or the sensor model with ``noise``), and
    :func:`rgbz_fast.reconstruction.train` fits the filters to all of them.
    The frames are made again for each of the fit's two passes, so the memory
    does not grow with the dataset. ``rgbz-fast train`` runs this.

    Parameters
    ----------
    dataset : str, Path, list of them, list of ImageSource or None
        A folder of images (:func:`~rgbz_fast.io.folder_dataset`), several
        folders, a list of sources, or None (the sample images). Fit on images
        you will not evaluate on.
    pattern : Pattern or str
        The pattern to fit the filters for.
    bit_depth : int
        Bits of the frames (11: the evaluation's default).
    noise : bool
        Fit on noisy frames (the sensor model, seeds ``seed``, ``seed + 1``...
        per image) instead of noise-free ones.
    linearise : bool
        False: mosaic the sRGB values as they are (the 8-bit sRGB protocol,
        :class:`EvalConfig`'s ``linearise``). Ignored when ``encoding`` is given.
    encoding : {"linear", "srgb", "both"}, optional
        The frames' encoding: ``"both"`` fits on every image linearised and as
        sRGB values (the shipped filters: one fit for both kinds of frames).
        Default: ``"linear"`` if ``linearise`` else ``"srgb"``.
    seed : int
        Noise seed of the first image.
    limit : int, optional
        Only the first ``limit`` images of each folder.
    name : str, optional
        The training set's name kept in the filters (default: the folders'
        names joined by ``+``).
    progress : bool
        Show a progress bar.
    **options
        Passed to :func:`~rgbz_fast.reconstruction.train` (``radius``,
        ``hash_radius``, ``n_strength``, ``n_coherence``, ``n_spread``,
        ``ridge``, ``prior``).

    Returns
    -------
    LearnedFilters
        With ``meta``: ``training_set``, ``n_images`` (frames: twice the
        images with ``encoding="both"``), ``noise``, ``encoding``
        (``"linear"``, ``"srgb"`` or ``"linear+srgb"``) and the fit's settings.

    Examples
    --------
    >>> from rgbz_fast.evaluation import train_filters
    >>> from rgbz_fast.io import sample_dataset
    >>> f = train_filters(sample_dataset()[:1], "mask1", n_strength=1, n_coherence=1, n_spread=1)
    >>> f.meta["training_set"], f.meta["encoding"], f.n_buckets
    ('astronaut', 'linear', 8)
    """
    pattern = get_pattern(pattern)
    progress = check_flag(progress, "progress")
    linearise = check_flag(linearise, "linearise")
    if encoding is None:
        encoding = "linear" if linearise else "srgb"
    encoding = check_choice(encoding, ENCODINGS, "encoding")
    if noise and encoding != "linear":
        raise ValueError("encoding: the sensor model (noise=True) takes linear light; fit noisy "
                         "frames with encoding='linear'")
    folders = (list(dataset) if isinstance(dataset, (list, tuple)) and dataset
               and all(isinstance(d, (str, os.PathLike)) for d in dataset) else None)
    if folders is not None:
        name = name or "+".join(Path(d).resolve().name for d in folders)
        sources = [s for d in folders for s in dataset_sources(d, limit)]
    else:
        if isinstance(dataset, (str, os.PathLike)):
            name = name or Path(dataset).resolve().name
        sources = dataset_sources(dataset, limit)
    name = name or ("+".join(s.name for s in sources) if len(sources) <= 3 else "custom")
    configs = [EvalConfig(patterns=(pattern.tile_string,), bit_depth=bit_depth, noise=noise,
                          linearise=(enc == "linear"), seed=seed, metrics=("cfa_psnr",))
               for enc in (("linear", "srgb") if encoding == "both" else (encoding,))]
    meta = {"training_set": name, "noise": bool(noise),
            "encoding": "linear+srgb" if encoding == "both" else encoding,
            **options.pop("meta", {})}
    frames = _Frames(sources, pattern, configs, progress)
    with frames.fitting:
        return train(frames, meta=meta, **options)


class _Frames:
    """The training frames, made afresh by every ``iter()`` (one image in memory at a time):
    each image in each configuration, with its reference CFA."""

    def __init__(self, sources, pattern, configs, progress):
        self.sources, self.pattern, self.configs = sources, pattern, configs
        self.progress, self.passes = progress, 0
        self.fitting = ExitStack()      # the solve's progress line, from the last image read

    def __iter__(self):
        from tqdm.auto import tqdm
        self.passes += 1
        for i, source in enumerate(tqdm(self.sources,
                                        desc="train" if self.passes == 1 else "train (pass 2)",
                                        unit="img", disable=not self.progress)):
            img = source.load()
            for config in self.configs:
                cfg = replace(config, seed=config.seed + i) if config.noise else config
                frame, ref = image_frames(img, self.pattern, cfg)
                yield replace(frame, reference=ref)
        if self.passes == 2:            # the second pass read every image: the solve follows
            self.fitting.enter_context(ticking("train: fitting the filters", self.progress))
