"""Fitting learned filters to datasets with the evaluation's protocol."""

from __future__ import annotations

import os
from contextlib import ExitStack
from dataclasses import replace
from pathlib import Path

import numpy as np

from .._patterns import get_pattern
from .._progress import ticking
from .._validate import check_choice, check_flag
from ..reconstruction import train
from ..simulation import Scene, simulate
from ._config import EvalConfig
from ._run import dataset_sources, image_frames

__all__ = ["train_filters", "ENCODINGS"]

#: what the training frames hold: linear light (the 8-bit sRGB images through the sRGB
#: EOTF), the sRGB values as they are, or both (every image twice)
ENCODINGS = ("linear", "srgb", "both")


def train_filters(dataset, pattern, *, bit_depth=11, noise=False, linearise=True, encoding=None,
                  seed=0, limit=None, name=None, progress=False, z_guided=False,
                  **options):
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
    z_guided : bool
        Fit the filters of ``method="z_guided"`` (:func:`~rgbz_fast.reconstruction.train_z_guided`)
        instead, on registered RGB + NIR pairs (a folder of ``NNNN_rgb.png`` +
        ``NNNN_nir.png``; an image without its NIR is refused: a NIR estimated
        from the RGB leaks the answer). Every pair gives two frames of the
        targets' protocol, ``simulate(Scene.from_rgb(rgb, depth=2 m everywhere,
        ir_reflectance=nir), pattern, seed=seed, noise=False)`` and
        ``noise=True`` (default sensors, 11 bits), so that one fit serves
        noise-free and noisy frames; ``noise``, ``linearise`` and
        ``bit_depth`` other than 11 do not apply. The two frames of a pair
        are one group of the fit's cross-validation (``groups``).
    **options
        Passed to :func:`~rgbz_fast.reconstruction.train` (``radius``,
        ``hash_radius``, ``n_strength``, ``n_coherence``, ``n_spread``,
        ``ridge``, ``prior``; with ``z_guided`` those of ``train_z_guided``:
        ``base``, ``ridge``, ``prior``, ``colour_prior``, ``select``,
        ``cv_folds``, ``cv_grid``, ``lam``, ``noise_thresholds``, ``guide``).

    Returns
    -------
    LearnedFilters (ZGuidedFilters with ``z_guided``)
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
    noise = check_flag(noise, "noise")
    if check_flag(z_guided, "z_guided"):
        if encoding not in (None, "linear"):
            # it had been accepted and ignored, "nonsense" included
            raise ValueError(f"encoding: z_guided filters are fitted on the sensor model's "
                             f"linear frames; got {encoding!r:.40}")
        return _train_z_guided(dataset, pattern, bit_depth, noise, linearise, seed, limit, name,
                               progress, options)
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
    info = {"training_set": name, "noise": bool(noise),
            "encoding": "linear+srgb" if encoding == "both" else encoding}
    user_meta = options.pop("meta", None)
    if noise:
        info["seed"] = seed              # the noisy frames' draws: what reproduces the fit
        if isinstance(user_meta, dict) and user_meta.get("seed") == seed:
            # a caller who recorded the seed themselves (as before it was recorded here)
            user_meta = {k: v for k, v in user_meta.items() if k != "seed"}
    meta = _merge_meta(info, user_meta)
    frames = _Frames(sources, pattern, configs, progress)
    with frames.fitting:
        return train(frames, meta=meta, **options)


def _merge_meta(info, meta):
    """What :func:`train_filters` records (the training set, its protocol) with the caller's
    ``meta``: a key of its own (``noise``, ``encoding``...) is a ValueError naming ``meta``
    and the key, as the fit's (:func:`rgbz_fast.reconstruction.train`; the caller's had won,
    recording noise=False for a noisy fit); the training set's name is ``name=``."""
    from ..reconstruction._learned_train import merge_meta

    if isinstance(meta, dict) and "training_set" in meta:
        raise ValueError("meta: 'training_set' is recorded by train_filters itself (the "
                         "folders' names); pass name= for another")
    return merge_meta(info, meta)


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


def _train_z_guided(dataset, pattern, bit_depth, noise, linearise, seed, limit, name, progress,
                    options):
    """:func:`train_filters` with ``z_guided``: the RGB-NIR pairs through the sensor model."""
    if bit_depth != 11 or noise or not linearise:
        bad = ("bit_depth", bit_depth) if bit_depth != 11 else \
            ("noise", noise) if noise else ("linearise", linearise)
        raise ValueError(f"{bad[0]}: z_guided filters are fitted on the sensor model's 11-bit "
                         f"linear frames, noise-free and noisy together; got {bad[1]!r}")
    if isinstance(dataset, (str, os.PathLike)):
        name = name or Path(dataset).resolve().name
    dataset = dataset_sources(dataset, limit)
    name = name or ("+".join(s.name for s in dataset) if len(dataset) <= 3 else "custom")
    bare = [s.name for s in dataset if getattr(s, "nir", None) is None]
    if bare:
        raise ValueError(f"dataset: {bare[0]!r} has no registered NIR image (NNNN_rgb.png + "
                         "NNNN_nir.png); z_guided is fitted on measured NIR only, one estimated "
                         "from the RGB leaks the answer")
    from tqdm.auto import tqdm

    fitting = ExitStack()

    def frames():
        for source in tqdm(dataset, desc="train", unit="img", disable=not progress):
            img = source.load()
            scene = Scene.from_rgb(img, depth=np.full(img.shape[:2], 2.0),
                                   ir_reflectance=source.load_nir())
            for n in (False, True):
                yield simulate(scene, pattern, seed=seed, noise=n)
        fitting.enter_context(ticking("train: fitting the filters", progress))  # pairs read

    if "groups" in options:
        raise TypeError("groups: not an option of train_filters; the two frames of each pair "
                        "are one group")
    meta = _merge_meta({"training_set": name, "seed": seed,
                        "protocol": "sensor model, noise-free + noisy"},
                       options.pop("meta", None))
    groups = [i for i in range(len(dataset)) for _ in (False, True)]
    with fitting:
        return train(frames(), z_guided=True, meta=meta, groups=groups, **options)
