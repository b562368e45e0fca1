"""Running an evaluation: frames of one image, the metrics of both paths, caching, the pool."""

from __future__ import annotations

import hashlib
import os
from functools import lru_cache
import signal
import threading
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path

import numpy as np

from .. import _patterns
from .. import metrics as _metrics
from ..metrics._combined import _colour_metrics
from .._frame import RawFrame, _Adopt, mosaic
from .._patterns import get_pattern
from .._validate import (check_bit_depth, check_flag, check_image, check_path,
                         check_processes, check_workers, integer_bits, merge_params)
from ..io import ImageSource, ParameterError, folder_dataset, sample_dataset, to_rgbz
from ..io._bayer import place_on_phase
from ..reconstruction import NEEDS_TOF, reconstruct
from ..simulation import ColourSensor, Scene, apply_optics, simulate, srgb_to_linear
from ..simulation._scene import srgb_decode, srgb_decode_table
from ._cache import (_cache_read, _cache_write, cache_folder, check_cache_dir,
                     check_scheduler, forget_write_failures)
from ._config import EvalConfig
from ._results import Results

__all__ = ["evaluate", "evaluate_image", "image_frames"]

#: the Pattern of a name of the configuration, made once: every image of a run asks for the
#: same few patterns and their Bayer phases, and get_pattern builds a new Pattern (its tile
#: parsed and checked against the four Bayer phases) at each call. Read only.
_named_pattern = lru_cache(maxsize=64)(get_pattern)


def _pattern_for(pname, bayer):
    """The pattern named ``pname`` on the Bayer arrangement ``bayer`` of a raw file (presets
    follow the file's arrangement; a tile is shifted onto it, :func:`place_on_phase`)."""
    base = str(pname).lower().split("_")[0]
    if base in ("mask1", "mask2", "rows", "bayer"):
        return getattr(_patterns, base)(bayer)
    try:
        return place_on_phase(str(pname), bayer)
    except ValueError as exc:
        raise ValueError(f"patterns: {str(exc).removeprefix('pattern: ')}") from None


def image_frames(img, pattern, config, nir=None):
    """(rgbz_frame, reference_cfa) of one image (RGB array or raw Bayer frame) and pattern.

    A raw Bayer frame keeps its real CFA as the reference and loses its Z sites
    (:func:`rgbz_fast.io.to_rgbz`). An RGB image is linearised (sRGB EOTF for
    integer images; ``config.linearise=False`` keeps the encoded values) and
    mosaicked noise-free at ``config.bit_depth``, or run through the sensor model
    (black level 0) when ``config.noise``. With ``config.optics`` the linear
    image is blurred through the lens before the mosaic is sampled (the sensor
    model does it itself for noisy runs); a raw frame has been through a real
    lens already and is left alone.

    A configuration with a method of :data:`rgbz_fast.NEEDS_TOF`
    (``"z_guided"``) takes every frame from the sensor model, noise-free or
    not (``simulate(Scene.from_rgb(img, depth=2 m everywhere, ir_reflectance=nir),
    pattern, ColourSensor(black_level=0, bit_depth=config.bit_depth), seed=config.seed,
    noise=config.noise)``),
    so that its frames carry ToF taps and every method of the run sees the
    same frames. ``nir``: the registered NIR reflectance of the image, in
    [0, 1] (:meth:`rgbz_fast.io.ImageSource.load_nir`); without it the scene
    estimates one from the RGB, and the frame's ``tof.meta["ir_estimated"]``
    says so.
    """
    if not isinstance(img, RawFrame):
        img = check_image(img, "img", ndim=3)
        if img.shape[2] != 3:
            raise ValueError(f"img: expected an RGB image (rows, cols, 3), got shape {img.shape}")
    config = merge_params(EvalConfig, config, name="config")
    return _frames(img, get_pattern(pattern), config, {}, nir)


def _sensor(config):
    """The colour sensor of the frames the sensor model makes: no black level, and the
    configuration's bit depth (the default sensor's 11 bits had been used whatever it was)."""
    return ColourSensor(black_level=0, bit_depth=config.bit_depth)


def _frames(img, pattern, config, memo, nir=None):
    """:func:`image_frames`, reusing from ``memo`` (one dict per image) the linear image and
    the reference CFAs that the patterns of one image share."""
    if isinstance(img, RawFrame):
        if config.needs_tof:
            raise ValueError(f"methods: {sorted(set(config.methods) & NEEDS_TOF)} need the Z "
                             "pixels' measurements, and a raw camera file has none; evaluate "
                             "them on RGB (+ NIR) images")
        return to_rgbz(img, _pattern_for(pattern.name, img.pattern.bayer_phase))
    if config.needs_tof:
        if "scene" not in memo:
            memo["scene"] = Scene.from_rgb(img, depth=np.full(img.shape[:2], 2.0),
                                           ir_reflectance=nir)
        frame = simulate(memo["scene"], pattern, _sensor(config), seed=config.seed,
                         noise=config.noise, optics=config.optics)
        return frame, frame.reference
    if config.noise:
        scene = Scene.from_rgb(img)
        frame = simulate(scene, pattern, _sensor(config), seed=config.seed,
                         noise=True, optics=config.optics)
        return frame, frame.reference
    if config.linearise and config.optics is None and img.dtype in (np.uint8, np.uint16):
        return _frames_coded(img, pattern, config, memo)
    if "linear" not in memo:
        if not config.linearise:
            memo["linear"] = img
        elif integer_bits(img, "img") is not None:        # the integer widths it takes
            memo["linear"] = srgb_decode(img, "img")
        else:
            memo["linear"] = np.clip(img, 0, 1)
    lin = memo["linear"]
    if config.optics is not None:
        if "optics" not in memo:
            memo["optics"] = np.clip(apply_optics(lin, config.optics,
                                                  pixel_pitch_um=ColourSensor().pixel_pitch_um),
                                      0.0, 1.0)
        lin = memo["optics"]
    shape = pattern.check_shape(lin.shape[:2], "rgb")      # mosaic's name of the image
    references = memo.setdefault("reference", {})          # Bayer pattern -> CFA
    bayer = pattern.bayer_pattern()
    if bayer not in references:
        references[bayer] = mosaic(lin, bayer, config.bit_depth).data
    # mosaic(lin, pattern): the colour of the underlying Bayer at the colour sites, 0 at the
    # Z sites -- the reference CFA with its Z sites cleared, without sampling the image again
    return RawFrame(_Adopt(_without_z(references[bayer], pattern)), pattern,
                    config.bit_depth), references[bayer]


def _frames_coded(img, pattern, config, memo):
    """:func:`_frames` of an 8- or 16-bit sRGB image, linearised, without optics: the
    reference CFA samples the image's codes at its Bayer sites first and looks each up in a
    table of what ``mosaic(srgb_decode(img), bayer, bit_depth)`` makes of that code (the
    same operations on the same values, once per code instead of once per sample)."""
    shape = pattern.check_shape(img.shape[:2], "rgb")      # mosaic's name of the image
    references = memo.setdefault("reference", {})          # Bayer pattern -> CFA
    bayer = pattern.bayer_pattern()
    if bayer not in references:
        top = (1 << check_bit_depth(config.bit_depth)) - 1
        table = srgb_decode_table(8 * img.itemsize).astype(np.float64) * top
        table = np.floor(table + 0.5).astype(np.uint16)
        colour = bayer.bayer_map(shape)
        (py, px), codes = bayer.period, np.empty(shape, img.dtype)
        for dy in range(min(py, shape[0])):                # one strided copy per tile site
            for dx in range(min(px, shape[1])):
                codes[dy::py, dx::px] = img[dy::py, dx::px, colour[dy, dx]]
        references[bayer] = np.take(table, codes)          # table[codes], a third of the time
    return RawFrame(_Adopt(_without_z(references[bayer], pattern)), pattern,
                    config.bit_depth), references[bayer]


def _without_z(cfa, pattern):
    """A copy of ``cfa`` with 0 at the Z sites of ``pattern`` (``cfa[pattern.channel_map(shape)
    == Z] = 0``, one strided store per Z site of the tile instead of a boolean mask)."""
    data = cfa.copy()
    (py, px), tile = pattern.period, pattern.tile
    for dy, dx in zip(*np.nonzero(tile == _patterns.Z)):
        data[dy::py, dx::px] = 0
    return data


def evaluate_image(source, config, cache_dir=None, workers=1):
    """Every (pattern, method) of ``config`` on one image: a list of tidy rows.

    Each row: ``{"image", "pattern", "method", "metric", "value"}``, and for
    a method of :data:`rgbz_fast.NEEDS_TOF` ``"ir_estimated"``: True when the
    image has no registered NIR image (``source.nir``), so that its guide was
    estimated from the very colour it has to find. Cached
    results are reused; new ones are written to ``cache_dir`` atomically. A
    cache entry is keyed by the configuration and by the image's content
    (:meth:`~rgbz_fast.io.ImageSource.fingerprint`), in a folder of its own
    per image name. ``workers`` are the threads of each kernel call.
    """
    return _evaluate_image(source, config, cache_dir, workers)


def _evaluate_image(source, config, cache_dir, workers, stop=None):
    """:func:`evaluate_image`; ``stop`` (a :class:`threading.Event`), when set, ends the
    image before its next (pattern, method) with :class:`_Stopped`."""
    if not isinstance(source, ImageSource):
        raise TypeError(f"source: expected an ImageSource, got {type(source).__name__}")
    config = merge_params(EvalConfig, config, name="config")
    workers = check_workers(workers)
    rows, todo = [], []
    cdir = check_path(cache_dir, "cache_dir") / cache_folder(source.name) \
        if cache_dir is not None else None
    content = source.fingerprint() if cdir else ""

    def key(p, m):
        return hashlib.sha1(f"{config.key(p, m, source.is_raw)} {content}".encode()).hexdigest()[:20]

    estimated = getattr(source, "nir", None) is None
    for p in config.patterns:
        for m in config.methods:
            if not config.applies(p, m):
                continue                         # noted in the results, never run
            cached = _cache_read(cdir, key(p, m)) if cdir else None
            if cached is not None and set(config.metrics) <= set(cached):
                rows += [_row(source.name, p, m, k, cached[k], estimated)
                         for k in config.metrics]
            else:
                todo.append((p, m))
    if not todo:
        return rows
    img = source.load()
    nir = source.load_nir() if config.needs_tof else None
    chain = config.colour_isp()
    memo, renders, metric_memos = {}, [], {}
    for pname in dict.fromkeys(p for p, _ in todo):
        try:
            frame, ref_cfa = _frames(img, _named_pattern(pname), config, memo, nir)
        except ValueError as exc:                # an image smaller than one period
            text = str(exc)
            if text.startswith("scene: "):
                # a black or too dark image under --noise (auto-exposure): the message had
                # named neither the image nor anything evaluate takes (M-04)
                what = text.removeprefix("scene: ").split(" -- ")[0].split("; ")[0]
                raise ValueError(f"dataset: image {source.name!r}: {what}; the noisy frames "
                                 "are auto-exposed: leave the image out (skip_bad=True)") from None
            if not text.startswith("rgb: "):
                raise
            raise ValueError(f"dataset: image {source.name!r}: "
                             f"{text.removeprefix('rgb: ')}") from None
        pattern = frame.pattern
        bayer, bd = pattern.bayer_phase, frame.bit_depth
        phase = _named_pattern(bayer) if bayer is not None else bayer   # the renders' Pattern
        z = frame.z_mask
        if config.image_metrics:
            # per pattern: a raw frame is cropped to a whole number of periods; the
            # grey-world gains of the reference are reused on the RGB-Z path (Fig. 19).
            # Patterns on one Bayer arrangement share their reference CFA, rendered once.
            ref_srgb, gains = _reference_render(chain, ref_cfa, phase, bd, workers, renders)
        for p, m in todo:
            if p != pname:
                continue
            if stop is not None and stop.is_set():
                raise _Stopped
            out = reconstruct(frame, m, params=config.params_for(m), workers=workers)
            values = {}
            if "cfa_psnr" in config.metrics:
                values["cfa_psnr"] = _metrics.cfa_psnr(ref_cfa, out, z, bit_depth=bd)
            if config.image_metrics:
                test_srgb = chain.render(out, phase, bit_depth=bd, gains=gains, workers=workers)
                try:
                    values.update(_image_metrics(ref_srgb, test_srgb, config, workers,
                                                 metric_memos.setdefault(id(ref_srgb), {})))
                except ValueError as exc:            # an image too small for a metric
                    text = str(exc)
                    for given, named in (("reference: ", "metrics"), ("crop: ", "crop")):
                        if text.startswith(given):   # the image named beside the parameter
                            raise ValueError(f"{named}: image {source.name!r}: "
                                             f"{text.removeprefix(given)}") from None
                    raise                            # a message of the caller's parameter
            if cdir:
                _cache_write(cdir, key(p, m), values)
            rows += [_row(source.name, p, m, k, values[k], estimated) for k in config.metrics]
    # in the run's order (patterns, methods), whatever came from the cache: a resumed run's
    # files equal a clean run's byte for byte (the cached rows had come first)
    order = {(p, m): i for i, (p, m) in enumerate((p, m) for p in config.patterns
                                                  for m in config.methods)}
    rows.sort(key=lambda r: order[(r["pattern"], r["method"])])
    return rows


def _reference_render(chain, cfa, bayer, bit_depth, workers, renders):
    """(sRGB image, white-balance gains) of a reference CFA, from ``renders`` (a list of
    earlier (cfa, bayer, bit_depth, image, gains)) when the same CFA was rendered before."""
    for done in renders:
        if done[1:3] == (bayer, bit_depth) and (done[0] is cfa or np.array_equal(done[0], cfa)):
            return done[3], done[4]
    gains = chain.white_balance_gains(cfa, bayer, bit_depth=bit_depth)
    image = chain.render(cfa, bayer, bit_depth=bit_depth, gains=gains, workers=workers)
    renders.append((cfa, bayer, bit_depth, image, gains))
    return image, gains


def _image_metrics(ref, test, config, workers, memo=None):
    """The colour metrics of ``config`` on one pair of 8-bit sRGB images (shared work;
    ``memo``: what the calls with this ``ref`` share, see ``_colour_metrics``; ``ref`` is
    kept alive by the renders of :func:`_reference_render`, so its id keys it)."""
    return _colour_metrics(ref, test, config.image_metrics, 255, config.crop, workers,
                           memo=memo)


def _row(image, pattern, method, metric, value, ir_estimated=False):
    row = {"image": image, "pattern": pattern, "method": method, "metric": metric,
           "value": float(value)}
    if method in NEEDS_TOF:
        row["ir_estimated"] = bool(ir_estimated)
    return row


#: set in a worker process of the local pool (:func:`_worker_init`): its tasks record their
#: warnings, which the parent issues again (:func:`_run_pool`)
_IN_WORKER = False


class _Rows(list):
    """An image's rows from a worker process, with the warnings its evaluation issued as
    (text, category): the parent issues them again, where the caller's filters and the
    command line's one-line format apply (printed by the worker, they came in Python's own
    format, file and source line, past any filter the caller had set)."""

    warnings = ()


def _pool_task(args, stop=None):
    if not _IN_WORKER:
        return _image_task(args, stop)
    import warnings

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")        # the parent's filters decide
        out = _image_task(args, stop)
    out = out if isinstance(out, _Skipped) else _Rows(out)
    out.warnings = [(str(w.message), w.category) for w in caught]
    return out


def dask_run_token():
    """The ``run`` of :func:`dask_task`: (this process's id, a token of the run)."""
    import uuid

    return os.getpid(), uuid.uuid4().hex


def dask_task(fn, arg, run):
    """``(fn(arg), warnings)`` on a Dask worker (module level, so that Dask ships it by
    name): in a worker of another process than the run's (``run``, :func:`dask_run_token`)
    the warnings ``fn`` shows, (text, category), recorded for the task's own thread
    (:class:`_record_thread_warnings`: a Dask worker runs tasks on several threads), which
    :func:`issue_again` issues in the caller; in the caller's own process (an in-process
    cluster) none are recorded, they are the caller's already."""
    if run[0] == os.getpid():
        return fn(arg), ()
    _begin_dask_run(run[1])
    with _record_thread_warnings() as caught:
        value = fn(arg)
    return value, caught


def issue_again(caught, stacklevel=3):
    """Issue the warnings a worker recorded, (text, category), in this process, where the
    caller's filters and the command line's one-line format apply."""
    import warnings

    for text, category in caught:
        warnings.warn(text, category, stacklevel=stacklevel)


#: a worker process's thread-local record of warnings (:func:`_record_thread_warnings`), the
#: showwarning it installed once, and the token of the last run it took a task of
_THREAD_RECORD = threading.local()
_RECORD_HOOK = []
_RECORD_LOCK = threading.Lock()
_DASK_RUN = [None]


def _begin_dask_run(token):
    """A Dask worker outlives a run: the first task of a new run in this worker process
    forgets the cache failures it warned of (each run warns of its own, H121) and the
    warnings Python's registries say were shown (its default action shows a warning once
    per source line for the life of the process: the next run's came to no caller)."""
    import warnings

    with _RECORD_LOCK:
        if _DASK_RUN[0] != token:
            _DASK_RUN[0] = token
            forget_write_failures()
            # a new version of the filters makes every module's registry stale; without
            # the private hook, a catch-all entry of the default action appended (or moved
            # to the end) decides nothing another entry or the default would not
            mutated = getattr(warnings, "_filters_mutated", None)
            if callable(mutated):
                mutated()
            else:                                   # pragma: no cover - another Python
                warnings.simplefilter("default", append=True)


class _record_thread_warnings:
    """The warnings this thread shows while inside, as (text, category), into the list
    the context gives; other threads' go where they went. ``warnings.showwarning`` is
    replaced once per process by a function that looks up the calling thread's record
    (catch_warnings swaps process-wide state, which the other tasks' threads would see).
    The process's filters apply first (Python's default: one warning per source line), the
    caller's when it issues them again."""

    def __enter__(self):
        import warnings

        with _RECORD_LOCK:
            if not _RECORD_HOOK:
                shown = warnings.showwarning

                def showwarning(message, category, filename, lineno, file=None, line=None):
                    got = getattr(_THREAD_RECORD, "got", None)
                    if got is None:
                        return shown(message, category, filename, lineno, file, line)
                    got.append((str(message), category))

                warnings.showwarning = showwarning
                _RECORD_HOOK.append(showwarning)
        self.got = _THREAD_RECORD.got = []
        return self.got

    def __exit__(self, *exc):
        _THREAD_RECORD.got = None
        return False


def _image_task(args, stop=None):
    source, config, cache_dir, workers, skip_bad = args
    try:
        return _evaluate_image(source, config, cache_dir, workers, stop)
    except _WorkerStopped as stop:
        # the writes in progress have removed their temporary files on the way here; the
        # pool's loop would catch the exception and take the next image, so end the process
        os._exit(stop.code)
    except (ValueError, TypeError, OSError) as exc:       # a bad image, not a bug: skipped
        if not skip_bad:
            raise
        skipped = _Skipped(" ".join(str(exc).split()) or type(exc).__name__)
        skipped.error = exc if isinstance(exc, ParameterError) else None    # it pickles
        return skipped


class _NoBar:
    """The progress bar of a quiet run: counts nothing, shows nothing."""

    def update(self, n=1):
        pass

    def close(self):
        pass


class _Skipped(str):
    """The reason an image was skipped (``skip_bad=True``), in place of its rows; ``error``:
    the :class:`~rgbz_fast.io.ParameterError` it came from, if it did, whose settings a caller
    may name in its own words; ``warnings``: as those of :class:`_Rows`."""

    error = None
    warnings = ()


class _Stopped(Exception):
    """The run was stopped (an error elsewhere, an interrupt): a thread of the pool ends its
    image between two (pattern, method), its cache writes done or removed."""


class _WorkerStopped(SystemExit):
    """SIGTERM in a pool worker: unwinds the image in progress (its cache write removes its
    temporary file), then the worker ends (:func:`_pool_task`); raised while the worker waits
    for work, it ends the process as a SystemExit."""


def _worker_init(hangup_to_parent=False):
    """Pool workers end promptly on SIGTERM, cleaning up on the way, and leave SIGINT to the
    parent.

    A Ctrl-C reaches the whole process group: each worker would get its KeyboardInterrupt in
    the middle of an image, the pool would hand it back as that image's result and the
    worker would start the next one. Workers ignore it instead; the parent's interrupt stops
    the pool (:func:`_stop_pool`), which sends SIGTERM. SIGTERM raises
    :class:`_WorkerStopped`, which :func:`_pool_task` turns into the end of the process once
    the writes in progress have cleaned up -- the pool would otherwise catch it too, and
    keep the worker running until it is killed (10 s later, its temporary files left).
    ``hangup_to_parent``: SIGHUP is left to the parent in the same way, when the parent
    handles it (the command line) or ignores it (``nohup``) rather than dying of it.
    """
    def terminated(signum, frame):
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        raise _WorkerStopped(128 + signum)

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, terminated)
    if hangup_to_parent:
        # a closed terminal sends SIGHUP to the whole process group too: the parent, which
        # handles it (the command line) or ignores it (nohup), stops the pool as for Ctrl-C
        signal.signal(signal.SIGHUP, signal.SIG_IGN)
    global _IN_WORKER
    _IN_WORKER = True


def _stop_pool(ex):
    """Stop a process pool now: cancel what has not started, terminate the workers (they
    clean up their temporary files, see :func:`_worker_init`), reap them."""
    procs = list(getattr(ex, "_processes", {}).values())
    for p in procs:
        if p.is_alive():
            p.terminate()
    killed = 0
    for p in procs:
        p.join(timeout=10)
        if p.is_alive():                                 # pragma: no cover - stuck in C
            p.kill()
            p.join(timeout=10)
            # join can return as the worker's pipes close, a moment before the kernel lets
            # it be reaped: only an exit by SIGKILL is a worker that did not stop itself
            killed += p.exitcode == -signal.SIGKILL
    ex.shutdown(wait=True, cancel_futures=True)
    if killed:                                           # pragma: no cover - stuck in C
        import warnings

        warnings.warn(f"{killed} worker process(es) did not stop within 10 s of SIGTERM and "
                      "were killed; their temporary files may remain", RuntimeWarning,
                      stacklevel=3)


def dataset_sources(dataset, limit=None):
    """``dataset`` (a folder, an iterable of ImageSource, or None: the sample images) as a
    non-empty list of ImageSource, the first ``limit`` only when given."""
    if dataset is None:
        dataset = sample_dataset()
    elif isinstance(dataset, (str, os.PathLike)):
        dataset = folder_dataset(dataset)
    try:
        dataset = list(dataset)[:limit] if limit else list(dataset)
    except TypeError:
        raise TypeError(f"dataset: expected a list of ImageSource, a folder or None, got "
                        f"{type(dataset).__name__}") from None
    if not dataset:
        raise ValueError("dataset: no images")
    bad = [s for s in dataset if not isinstance(s, ImageSource)]
    if bad:
        raise TypeError(f"dataset: expected ImageSource entries (see folder_dataset), got "
                        f"{type(bad[0]).__name__} {bad[0]!r}")
    return dataset


def dataset_name(sources):
    """What the images ``sources`` (ImageSource) are called in the figures' titles: the name
    of the folder they all come from, "scikit-image samples", or "" (several places)."""
    places = {"scikit-image samples" if s.location.startswith("skimage:")
              else Path(s.location).resolve().parent.name for s in sources}
    return places.pop() if len(places) == 1 else ""


def evaluate(dataset=None, config=None, *, cache_dir=None, processes=None, workers=None,
             scheduler=None, progress=True, skip_bad=False, **overrides):
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
    config : EvalConfig or dict, optional
        What to run (default ``EvalConfig()``). It plays the part ``params``
        plays elsewhere (``params`` is a field of it: the reconstruction's
        parameters).
    **overrides
        Fields of :class:`EvalConfig` (``metrics=("cfa_psnr",)``,
        ``noise=True``, ``params=ReconstructParams(...)``), applied over
        ``config`` and checked by it.
    cache_dir : str or Path, optional
        Where per-image results are cached (one small JSON file per image x
        pattern x method, written atomically), so an interrupted run resumes
        and a re-run with one more method computes only that method.
    processes : int, optional
        Spawned worker processes, one image each. Default: none; a pool of
        threads of this process takes one image each, as many as there are
        cores (the kernels release the GIL: no process start-up, no second
        import of the package, nothing pickled). 1: one image at a time in
        this process.
    workers : int, optional
        Threads of each kernel call (default: 1 in a pool of several threads
        or processes, all cores one image at a time). Results never depend
        on it.
    scheduler : str or distributed.Client, optional
        A Dask scheduler address (``"tcp://host:8786"``) or client: the same
        tasks run on Dask distributed instead of the local pool and give the
        same numbers; not with ``processes``.
    progress : bool
        Show a progress bar (tqdm) on stderr.
    skip_bad : bool
        Skip the images that cannot be evaluated (a file that does not
        decode, a grey image, an image smaller than a pattern period or the
        crop...): they are listed in :attr:`Results.skipped` with the reason,
        and the others are evaluated. Default: the first one stops the run
        with its error.

    Returns
    -------
    Results

    Notes
    -----
    An interrupt (Ctrl-C, or SIGTERM under the command line) stops the
    local pool before it propagates: a thread ends its image at its next
    (pattern, method), a worker process at once; no worker outlives the
    run, and no temporary cache file is left behind.
    """
    config = merge_params(EvalConfig, config, overrides, name="config", caller="evaluate()")
    nproc = check_processes(processes)
    scheduler = check_scheduler(scheduler)
    if processes is not None and scheduler is not None:       # processes had been dropped
        raise ValueError("processes: local processes, which scheduler replaces; give one of them")
    dataset = dataset_sources(dataset)
    names = [s.name for s in dataset]
    if len(set(names)) != len(names):
        raise ValueError("dataset: image names must be unique")
    pooled = scheduler is not None or (nproc > 1 and len(dataset) > 1)
    threads = check_workers(workers if workers is not None else (1 if pooled else None))
    cache_dir = check_cache_dir(cache_dir)
    if cache_dir is not None:
        cache_dir = str(cache_dir)
        forget_write_failures()
    skip_bad = check_flag(skip_bad, "skip_bad")
    progress = check_flag(progress, "progress")
    tasks = [(s, config, cache_dir, threads, skip_bad) for s in dataset]
    if progress:
        from tqdm.auto import tqdm
        bar = tqdm(total=len(tasks), desc="evaluate", unit="img")
    else:                       # tqdm's import (asyncio with it) would delay the first image
        bar = _NoBar()
    results = {}
    try:
        if scheduler is not None:
            results = _run_dask(tasks, scheduler, bar)
        elif not pooled:
            for t in tasks:
                results[t[0].name] = _pool_task(t)
                bar.update()
        elif processes is None:
            _run_threads(tasks, nproc, bar, results)
        else:
            own_tracker = not _tracker_running()
            try:
                _run_pool(tasks, nproc, bar, results)
            finally:
                if own_tracker:
                    _stop_tracker()
    finally:
        bar.close()
    skipped = [(n, results[n]) for n in names if isinstance(results[n], _Skipped)]
    rows = [r for n in names if not isinstance(results[n], _Skipped) for r in results[n]]
    return Results(rows, config, skipped=skipped,
                   raw_images=[s.name for s in dataset if s.is_raw],
                   dataset=dataset_name(dataset))


def _run_threads(tasks, nthreads, bar, results):
    """The tasks on a pool of threads of this process, their results into ``results``.

    The kernels release the GIL, so the threads compute side by side. Each task runs in a
    copy of the caller's context (its context variables, NumPy's error state). An error or
    an interrupt sets ``stop``: the images not started are cancelled, the ones in progress
    end at their next (pattern, method), and every thread has ended before it propagates.
    """
    import contextvars
    import threading
    from concurrent.futures import ThreadPoolExecutor

    stop = threading.Event()
    ex = ThreadPoolExecutor(max_workers=min(nthreads, len(tasks)),
                            thread_name_prefix="rgbz-evaluate")
    try:
        futs = {ex.submit(contextvars.copy_context().run, _pool_task, t, stop): t[0].name
                for t in tasks}
        for f in as_completed(futs):
            results[futs[f]] = f.result()
            bar.update()
    except BaseException:
        stop.set()
        ex.shutdown(wait=True, cancel_futures=True)
        raise
    ex.shutdown(wait=True)


#: the end of the error of a worker that died under an image (H123), local pool or Dask
_KILLED = ("(the system's out-of-memory killer ends the largest process); the images done are "
           "in the cache, if one is used, and a rerun resumes from them")


def _run_pool(tasks, nproc, bar, results):
    """The tasks on a local pool of spawned processes, their results into ``results``; the
    warnings of each image issued again here (:class:`_Rows`)."""
    import multiprocessing as mp
    ctx = mp.get_context("spawn")
    # SIGHUP: the workers leave it to this process when it does not die of it
    hup = getattr(signal, "SIGHUP", None)
    hangup_to_parent = hup is not None and signal.getsignal(hup) not in (signal.SIG_DFL, None)
    if hangup_to_parent and not _tracker_running():
        _start_tracker_without_hangup()
    ex = ProcessPoolExecutor(max_workers=min(nproc, len(tasks)), mp_context=ctx,
                             initializer=_worker_init, initargs=(hangup_to_parent,))
    try:
        futs = {ex.submit(_pool_task, t): t[0].name for t in tasks}
        for f in as_completed(futs):
            results[futs[f]] = res = f.result()
            issue_again(res.warnings)
            bar.update()
    except BrokenProcessPool:
        # a worker killed from outside (the out-of-memory killer, kill -9): the command had
        # ended with concurrent.futures' traceback
        procs = list((getattr(ex, "_processes", None) or {}).values())
        _stop_pool(ex)
        codes = [p.exitcode for p in procs if p.exitcode is not None and p.exitcode < 0
                 and p.exitcode != -signal.SIGTERM]          # not the ones _stop_pool ended
        del ex
        how = f" by signal {-codes[0]} ({signal.Signals(-codes[0]).name})" \
            if codes and -codes[0] in signal.valid_signals() else ""
        raise ChildProcessError(
            f"processes: a worker process was ended{how} while it evaluated an image "
            f"{_KILLED}; fewer processes take less memory") from None
    except BaseException:
        _stop_pool(ex)                      # an error or an interrupt: no orphaned worker
        del ex                              # its semaphores go before the tracker does
        raise
    ex.shutdown(wait=True)


def _start_tracker_without_hangup():
    """Start multiprocessing's resource tracker with SIGHUP blocked, which it keeps: it is a
    process of this one's group and ignores SIGINT and SIGTERM but not SIGHUP, so a closed
    terminal ended it under a pool this process was stopping (its relaunch printed five
    tracebacks, KeyError '/mp-...'). Blocked, not ignored, here: a SIGHUP meanwhile reaches
    this process once the tracker runs."""
    from multiprocessing import resource_tracker

    if not hasattr(signal, "pthread_sigmask"):       # pragma: no cover - not POSIX
        resource_tracker.ensure_running()
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGHUP})
    try:
        resource_tracker.ensure_running()
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def _tracker_running():
    """Whether this process has a multiprocessing resource tracker running."""
    from multiprocessing import resource_tracker
    return getattr(resource_tracker._resource_tracker, "_pid", None) is not None


def _stop_tracker():
    """Stop and reap the resource tracker that a spawned pool started in this process, once
    the pool's semaphores are gone: left to itself it outlives the run by a moment (it ends
    when it notices that this process has ended), a process that a caller waiting for the
    run's process group sees left behind. The tracker of a pool that is still alive (a
    caller's own) is left alone: its semaphores would start a new one."""
    import gc
    from multiprocessing import resource_tracker

    gc.collect()                            # the pool's queues, and with them its semaphores
    tracker = resource_tracker._resource_tracker
    if getattr(tracker, "_pid", None) is None or not hasattr(tracker, "_stop"):
        return                              # pragma: no cover - another Python's tracker
    if any(getattr(getattr(obj, "_semlock", None), "name", None) is not None
           for obj in gc.get_objects() if type(obj).__module__ == "multiprocessing.synchronize"):
        return                              # named semaphores alive: the tracker keeps them
    tracker._stop()


def _run_dask(tasks, scheduler, bar):
    """The tasks on a Dask scheduler; the warnings of each image that a worker of another
    process recorded issued again here (:func:`dask_task`)."""
    from ._cache import distributed
    dist = distributed()
    Client, d_as_completed = dist.Client, dist.as_completed
    own = not hasattr(scheduler, "submit")
    client = Client(scheduler) if own else scheduler
    run = dask_run_token()
    try:
        futs = {client.submit(dask_task, _image_task, t, run, pure=False): t[0].name
                for t in tasks}
        out = {}
        for f in d_as_completed(list(futs)):
            try:
                out[futs[f]], caught = f.result()
                issue_again(caught)
            except dist.KilledWorker:
                # every worker that ran the image died (the out-of-memory killer, a crash):
                # Dask's KilledWorker had ended the command with a traceback
                raise ChildProcessError(
                    f"scheduler: the Dask workers that evaluated image {futs[f]!r} died while "
                    f"they ran it, each one Dask tried {_KILLED}; the workers' logs say more") \
                    from None
            bar.update()
        return out
    finally:
        if own:
            client.close()
