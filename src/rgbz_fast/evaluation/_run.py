"""Running an evaluation: frames of one image, the metrics of both paths, caching, the pool."""

from __future__ import annotations

import json
import os
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

import numpy as np

from .. import _patterns
from .. import metrics as _metrics
from .._frame import RawFrame, mosaic
from .._patterns import get_pattern
from .._validate import check_processes, check_workers
from ..io import ImageSource, atomic_write, folder_dataset, sample_dataset, to_rgbz
from ..reconstruction import reconstruct
from ..simulation import ColourSensor, Scene, apply_optics, simulate, srgb_to_linear
from ._config import EvalConfig
from ._results import Results

__all__ = ["evaluate", "evaluate_image", "image_frames"]


def _pattern_for(pname, phase):
    """The pattern named ``pname`` on the Bayer phase of a raw file (presets follow the phase)."""
    base = str(pname).lower().split("_")[0]
    if base in ("mask1", "mask2", "rows", "bayer"):
        return getattr(_patterns, base)(phase)
    pattern = get_pattern(pname)
    if pattern.bayer_phase != phase:
        raise ValueError(f"patterns: {pname!r} is built on {pattern.bayer_phase}, the raw file "
                         f"on {phase}")
    return pattern


def image_frames(img, pattern, config):
    """(rgbz_frame, reference_cfa) of one image (RGB array or raw Bayer frame) and pattern.

    A raw Bayer frame keeps its real CFA as the reference and loses its Z sites
    (:func:`rgbz_fast.io.to_rgbz`). An RGB image is linearised (sRGB EOTF for
    integer images) and mosaicked noise-free at ``config.bit_depth``, or run
    through the sensor model (black level 0) when ``config.noise``. With
    ``config.optics`` the linear image is blurred through the lens before the
    mosaic is sampled (the sensor model does it itself for noisy runs); a raw
    frame has been through a real lens already and is left alone.
    """
    pattern = get_pattern(pattern)
    if isinstance(img, RawFrame):
        return to_rgbz(img, _pattern_for(pattern.name, img.pattern.bayer_phase))
    if config.noise:
        scene = Scene.from_rgb(img)
        frame = simulate(scene, pattern, ColourSensor(black_level=0), seed=config.seed,
                         noise=True, optics=config.optics)
        return frame, frame.reference
    if np.issubdtype(img.dtype, np.integer):
        lin = srgb_to_linear(img.astype(np.float64) / float(np.iinfo(img.dtype).max))
    else:
        lin = np.clip(img, 0, 1)
    if config.optics is not None:
        lin = np.clip(apply_optics(lin, config.optics,
                                   pixel_pitch_um=ColourSensor().pixel_pitch_um), 0.0, 1.0)
    frame = mosaic(lin, pattern, config.bit_depth)
    ref = mosaic(lin, pattern.bayer_pattern(), config.bit_depth).data
    return frame, ref


def evaluate_image(source, config, cache_dir=None, workers=1):
    """Every (pattern, method) of ``config`` on one image: a list of tidy rows.

    Each row: ``{"image", "pattern", "method", "metric", "value"}``. Cached
    results are reused; new ones are written to ``cache_dir`` atomically.
    ``workers`` are the threads of each kernel call.
    """
    rows, todo = [], []
    cdir = Path(cache_dir) / _safe(source.name) if cache_dir else None
    for p in config.patterns:
        for m in config.methods:
            cached = _cache_read(cdir, config.key(p, m, source.is_raw)) if cdir else None
            if cached is not None and set(config.metrics) <= set(cached):
                rows += [_row(source.name, p, m, k, cached[k]) for k in config.metrics]
            else:
                todo.append((p, m))
    if not todo:
        return rows
    img = source.load()
    chain = config.colour_isp()
    for pname in dict.fromkeys(p for p, _ in todo):
        frame, ref_cfa = image_frames(img, pname, config)
        pattern = frame.pattern
        phase, bd = pattern.bayer_phase, frame.bit_depth
        z = frame.z_mask
        if config.image_metrics:
            # per pattern: a raw frame is cropped to a whole number of periods; the
            # grey-world gains of the reference are reused on the RGB-Z path (Fig. 19)
            ref_srgb, ref_stages = chain.render(ref_cfa, phase, bit_depth=bd, workers=workers,
                                                return_stages=True)
            gains = ref_stages["gains"]
        for p, m in todo:
            if p != pname:
                continue
            out = reconstruct(frame, m, params=config.params, workers=workers)
            values = {}
            if "cfa_psnr" in config.metrics:
                values["cfa_psnr"] = _metrics.cfa_psnr(ref_cfa, out, z, bit_depth=bd)
            if config.image_metrics:
                test_srgb = chain.render(out, phase, bit_depth=bd, gains=gains, workers=workers)
                values.update(_image_metrics(ref_srgb, test_srgb, config))
            if cdir:
                _cache_write(cdir, config.key(p, m, source.is_raw), values)
            rows += [_row(source.name, p, m, k, values[k]) for k in config.metrics]
    return rows


def _image_metrics(ref, test, config):
    out = {}
    c = config.crop
    if "cpsnr" in config.metrics:
        out["cpsnr"] = _metrics.cpsnr(ref, test, data_range=255, crop=c)
    if "ssim" in config.metrics:
        out["ssim"] = _metrics.ssim(ref, test, data_range=255, crop=c)
    if "ms_ssim" in config.metrics:
        out["ms_ssim"] = _metrics.ms_ssim(ref, test, data_range=255, crop=c)
    if "zipper" in config.metrics:
        out["zipper"] = _metrics.zipper(ref, test, crop=c)
    return out


def _row(image, pattern, method, metric, value):
    return {"image": image, "pattern": pattern, "method": method, "metric": metric,
            "value": float(value)}


def _safe(name):
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in name)


def _cache_read(cdir, key):
    f = cdir / f"{key}.json"
    try:
        return json.loads(f.read_text())
    except (OSError, ValueError):
        return None


def _cache_write(cdir, key, values):
    cdir.mkdir(parents=True, exist_ok=True)
    atomic_write(cdir / f"{key}.json", json.dumps(values, sort_keys=True))


def _pool_task(args):
    source, config, cache_dir, workers = args
    return evaluate_image(source, config, cache_dir, workers=workers)


def evaluate(dataset=None, config=None, *, cache_dir=None, processes=None, workers=None,
             scheduler=None, progress=True, **config_kwargs):
    """Run the Fig. 19 evaluation over a dataset; returns :class:`Results`.

    For every image the *reference path* (plain Bayer CFA, no reconstruction)
    and the *RGB-Z path* (Z sites removed, then reconstructed) go through the
    same colour chain (:meth:`EvalConfig.colour_isp`); the metrics compare them
    at two levels: CFA PSNR on the reconstructed pixels only (eqs. 20-21), then
    CPSNR, SSIM, MS-SSIM and the zipper metric on the 8-bit sRGB images
    (eqs. 22-31). Only what the requested metrics need is computed: CFA PSNR
    alone runs no demosaic; a noise-free run draws no random numbers.

    Parameters
    ----------
    dataset : list of ImageSource, str or Path, optional
        A list (any iterable) from :func:`~rgbz_fast.io.sample_dataset` /
        :func:`~rgbz_fast.io.folder_dataset`, or a folder. Default: the sample
        dataset (runs offline).
    config : EvalConfig, optional
        What to run; keyword arguments build one when it is None.
    cache_dir : str or Path, optional
        Where per-image results are cached (one small JSON file per image x
        pattern x method, written atomically), so an interrupted run resumes
        and a re-run with one more method computes only that method.
    processes : int, optional
        Worker processes of the local pool, one image each (default: all
        cores; 1 runs in-process).
    workers : int, optional
        Threads of each kernel call (default: 1 with a pool of several
        processes, all cores in-process). Results never depend on it.
    scheduler : str or distributed.Client, optional
        A Dask scheduler address (``"tcp://host:8786"``) or client: the same
        tasks run on Dask distributed instead of the local pool and give the
        same numbers.
    progress : bool
        Show a progress bar (tqdm) on stderr.
    """
    if config is None:
        config = EvalConfig(**config_kwargs)
    elif config_kwargs:
        raise TypeError("pass either config or keyword arguments, not both")
    elif not isinstance(config, EvalConfig):
        raise TypeError(f"config: expected an EvalConfig, got {type(config).__name__}")
    nproc = check_processes(processes)
    if dataset is None:
        dataset = sample_dataset()
    elif isinstance(dataset, (str, os.PathLike)):
        dataset = folder_dataset(dataset)
    try:
        dataset = list(dataset)
    except TypeError:
        raise TypeError(f"dataset: expected a list of ImageSource, a folder or None, got "
                        f"{type(dataset).__name__}") from None
    if not dataset:
        raise ValueError("dataset: no images")
    bad = [s for s in dataset if not isinstance(s, ImageSource)]
    if bad:
        raise TypeError(f"dataset: expected ImageSource entries (see folder_dataset), got "
                        f"{type(bad[0]).__name__} {bad[0]!r}")
    names = [s.name for s in dataset]
    if len(set(names)) != len(names):
        raise ValueError("dataset: image names must be unique")
    pooled = scheduler is not None or (nproc > 1 and len(dataset) > 1)
    threads = check_workers(workers if workers is not None else (1 if pooled else None))
    cache_dir = str(cache_dir) if cache_dir is not None else None
    tasks = [(s, config, cache_dir, threads) for s in dataset]
    from tqdm.auto import tqdm
    bar = tqdm(total=len(tasks), desc="evaluate", unit="img", disable=not progress)
    results = {}
    try:
        if scheduler is not None:
            results = _run_dask(tasks, scheduler, bar)
        elif not pooled:
            for t in tasks:
                results[t[0].name] = _pool_task(t)
                bar.update()
        else:
            import multiprocessing as mp
            ctx = mp.get_context("spawn")
            with ProcessPoolExecutor(max_workers=min(nproc, len(tasks)), mp_context=ctx) as ex:
                futs = {ex.submit(_pool_task, t): t[0].name for t in tasks}
                for f in as_completed(futs):
                    results[futs[f]] = f.result()
                    bar.update()
    finally:
        bar.close()
    rows = [r for n in names for r in results[n]]
    return Results(rows, config)


def _run_dask(tasks, scheduler, bar):
    from distributed import Client, as_completed as d_as_completed
    own = not hasattr(scheduler, "submit")
    client = Client(scheduler) if own else scheduler
    try:
        futs = {client.submit(_pool_task, t, pure=False): t[0].name for t in tasks}
        out = {}
        for f in d_as_completed(list(futs)):
            out[futs[f]] = f.result()
            bar.update()
        return out
    finally:
        if own:
            client.close()
