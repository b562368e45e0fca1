"""The engine of ``rgbz-fast pattern-study``: RGB-Z layouts ranked by colour loss, depth
quality and cost, in one table.

:func:`pattern_study` takes the candidate layouts (presets, tiles, generated
families: :mod:`.pattern_candidates`, which also says which layouts count as
the same) and measures, per layout, with what the library has:

* **colour** -- :func:`rgbz_fast.evaluation.evaluate` on the colour dataset
  (its frames, colour chain and cache): CFA PSNR on the Z sites, CPSNR and the
  zipper metric (share of the 8-bit sRGB image), for every method that
  applies to the layout; ``learned`` is fitted for the layout on the named
  training set (:func:`rgbz_fast.evaluation.train_filters`, cached by layout
  and training set); a method that does not apply is a note in its row;
* **depth** -- the Z fill factor, the measurements per megapixel, and the
  colour-guided ToF ISP (``ToFISP().run(tof, guide=ColourISP().run(frame))``)
  on a flat wall (``WALL``): the ISP's predicted depth noise (every measurement
  of the interior), the valid share and the measured spread of the valid depths;
  with RGB-D scenes, the valid share, the share of valid measurements off by more
  than 5 cm, and the RMSE of the valid ones;
* **cost** -- operations per reconstructed pixel of each method, from the
  counting build of the kernels (every category of ``opcount`` summed), and
  per frame pixel (times the share of Z sites); the ToF demodulation per
  frame pixel; the line buffers and variable multipliers of the fixed-point
  streaming model (:func:`rgbz_fast.hardware.hardware_cost` at its default
  widths) for the methods and periods it models.

Every measurement is a task (the colour and cost of a layout, its wall, one
RGB-D scene) whose result is cached as JSON under ``cache_dir``, so an
interrupted study resumes; tasks run in this process or, with ``scheduler``,
on Dask distributed, with the same numbers.
"""

from __future__ import annotations

import hashlib
import json
import math
import time
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..evaluation._cache import _CACHE_MAX_BYTES, _cache_check, _cache_write, results_version
from ..io import read_file
from ._common import common_means, machine_info
from .pattern_candidates import candidates as find_candidates

__all__ = ["pattern_study", "StudySettings", "METHODS", "COLOUR_METRICS", "WALL",
           "method_note", "op_cost"]

METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "learned")
COLOUR_METRICS = ("cfa_psnr", "cpsnr", "zipper")
#: the flat wall of the noise measurement: distance (m), NIR reflectance, frame (rows, cols)
WALL = {"distance": 2.0, "reflectance": 0.5, "shape": (192, 192)}
#: an error above it (m) makes a valid RGB-D measurement "wrong" (evaluate-depth's tolerance)
TOLERANCE = 0.05


@dataclass(frozen=True)
class StudySettings:
    """What a study measures beyond its layouts (every field enters the cache keys).

    ``methods``: reconstruction methods; ``bit_depth``: of the simulated colour frames;
    ``seed``: of the depth simulations; ``rgbd_size``: (rows, cols) of the centre crop of
    every RGB-D scene (None: the whole scene); ``wall``: :data:`WALL`'s fields.
    """

    methods: tuple = METHODS
    bit_depth: int = 11
    seed: int = 1
    rgbd_size: tuple | None = (384, 384)
    wall_distance: float = WALL["distance"]
    wall_reflectance: float = WALL["reflectance"]
    wall_shape: tuple = WALL["shape"]


def method_note(pattern, method):
    """"" when ``method`` reconstructs ``pattern``, else why not (the library's words)."""
    from ..reconstruction._learned import learned_geometry
    from ..reconstruction._plans import build_plans

    try:
        if method == "learned":
            learned_geometry(pattern)
        else:
            build_plans(pattern, method)
    except ValueError as exc:
        return f"does not apply: {' '.join(str(exc).split())}"
    return ""


def _digest(*parts):
    return hashlib.sha1(json.dumps(parts, sort_keys=True, default=str).encode()).hexdigest()[:20]


#: what :func:`_cache_entry` returns for an entry to compute (missing or bad)
_MISS = object()


def _cache_entry(f, key):
    """The value of the cache entry ``f`` (of ``key``), or :data:`_MISS` to compute it again.

    The entry is evaluate's (:mod:`rgbz_fast.evaluation._cache`): ``{"check": ..., "values":
    ...}``, the checksum binding the values to the key, read through the guarded reader (a
    regular file -- a link followed to one -- of at most 64 kB). Read bare, a FIFO under an
    entry's name had blocked the study forever and an edited entry ({"bi": 1.0} for 41
    operations) had been served without a word (ops/px 0.25 for 10.25). A missing entry is
    a plain miss; any other is recomputed with a warning naming the file."""
    try:
        data = read_file(f, "cache", max_bytes=_CACHE_MAX_BYTES)
    except FileNotFoundError:
        return _MISS
    except (OSError, ValueError) as exc:           # a FIFO, a device, a folder, too large
        # (without the advice to raise max_bytes: an entry is never that large)
        return _bad_entry(" ".join(str(exc).split()).removeprefix("cache: ")
                          .split("; raise it with")[0])
    try:
        entry = json.loads(data.decode("utf-8"))
        if not isinstance(entry, dict) or set(entry) != {"check", "values"}:
            return _bad_entry(f"{f} is not an entry this cache wrote")
        body = json.dumps(entry["values"], sort_keys=True)
    except (ValueError, RecursionError, TypeError):          # UnicodeDecodeError: a ValueError
        return _bad_entry(f"{f} is not JSON")
    if entry["check"] != _cache_check(key, body):
        return _bad_entry(f"{f} does not match its checksum (edited or damaged)")
    return entry["values"]


def _bad_entry(what):
    import warnings

    warnings.warn(f"cache_dir: {what}; the cache entry is computed again", RuntimeWarning,
                  stacklevel=3)
    return _MISS


def _cached(cache_dir, kind, key, compute):
    """``compute()``'s JSON-able result, read from ``cache_dir/kind/key.json`` when there
    and valid (:func:`_cache_entry`), else computed and written there atomically as
    evaluate writes its entries (checksummed; a FIFO or a device under the entry's name
    replaced, a write the cache cannot take a warning); no cache when ``cache_dir`` is
    None."""
    if cache_dir is None:
        return compute()
    folder = Path(cache_dir) / kind
    value = _cache_entry(folder / f"{key}.json", key)
    if value is _MISS:
        value = compute()
        _cache_write(folder, key, value)
    return value


# --------------------------------------------------------------------------- colour + cost
def _filters(cand, train, settings, cache_dir):
    """The learned filters of a layout fitted on the training set ``train`` ((name,
    sources)), cached in ``cache_dir/filters`` by layout, training set and bit depth."""
    from ..evaluation import train_filters
    from ..reconstruction import LearnedFilters

    name, sources = train
    key = _digest("filters", cand.pattern.tile_string, cand.pattern.bayer_phase,
                  settings.bit_depth, name, [s.fingerprint() for s in sources],
                  results_version())
    f = Path(cache_dir) / "filters" / f"{key}.npz" if cache_dir is not None else None
    if f is not None and f.is_file():
        try:
            return LearnedFilters.load(f)
        except ValueError:
            pass
    filters = train_filters(sources, cand.pattern, bit_depth=settings.bit_depth, name=name)
    if f is not None:
        f.parent.mkdir(parents=True, exist_ok=True)
        filters.save(f)
    return filters


def op_cost(pattern, method, filters=None, precision="float64"):
    """Operations per reconstructed (Z) pixel of ``method`` on ``pattern``, every category of
    the counting build summed (``{category: mean}`` and ``"total"``); ``filters``: the
    learned method's (the cost depends on their geometry only)."""
    from .opcount import CATEGORIES, count_operations

    P, Q = pattern.period
    shape = (max(64, 4 * P), max(64, 4 * Q))
    if method != "learned":
        res = count_operations(method, pattern, precision=precision, shape=shape)
        n = sum(g["n_sites"] for g in res.values())
        mean = {k: sum(g["mean"][k] * g["n_sites"] for g in res.values()) / n
                for k in CATEGORIES}
    else:
        from .. import _kernels_count
        from ..reconstruction import _reconstruct as _recon

        rows, cols = (-(-s // p) * p for s, p in zip(shape, (P, Q)))
        rng = np.random.default_rng(0)
        data = rng.integers(0, 1 << filters.bit_depth, (rows, cols), dtype=np.uint16)
        z = pattern.z_mask((rows, cols))
        data[z] = 0
        counts = np.zeros(len(filters.geometry) * _kernels_count.NOPS, np.uint64)
        _recon.run_learned(data, np.empty_like(data), pattern, filters, precision,
                           filters.bit_depth, 1, opcounts=counts, kernels=_kernels_count)
        tot = counts.reshape(len(filters.geometry), -1).sum(axis=0).astype(np.float64)
        mean = {k: float(tot[i]) / int(z.sum()) for i, k in enumerate(CATEGORIES)}
    mean["total"] = float(sum(mean[k] for k in CATEGORIES))
    return mean


def _colour_task(cand, dataset, train, settings, cache_dir, workers):
    """{method: {"per_image": {metric: {image: value}}, "ops_per_z": ..., "note": ...}} of one
    layout; the means are taken over the images of the whole study (:func:`_common_means`)."""
    from ..evaluation import EvalConfig, evaluate
    from ..reconstruction import ReconstructParams

    pattern = cand.pattern
    out, run = {}, []
    filters = None
    for m in settings.methods:
        note = method_note(pattern, m)
        if not note and m == "learned" and train is None:
            note = "not fitted: no training set given"
        out[m] = {"note": note}
        if not note:
            run.append(m)
    if "learned" in run:
        filters = _filters(cand, train, settings, cache_dir)
    if run:
        params = ReconstructParams(precision="float64",
                                   filters=(filters,) if filters is not None else None)
        config = EvalConfig(patterns=(pattern.tile_string,), methods=tuple(run),
                            metrics=COLOUR_METRICS, bit_depth=settings.bit_depth,
                            params=params)
        res = evaluate(dataset, config, processes=1, workers=workers, progress=False,
                       cache_dir=None if cache_dir is None else Path(cache_dir) / "colour")
        # every image's value, not Results.summary()'s means: those leave a +inf out of one
        # column (a flat image: every method exact) and not of the zipper's, and the means
        # of the layouts and methods are to cover the same images (_common_means)
        for m in run:
            out[m]["per_image"] = {k: {} for k in COLOUR_METRICS}
        for r in res.rows:
            if r["pattern"] == pattern.tile_string and r["method"] in out \
                    and r["metric"] in COLOUR_METRICS:
                out[r["method"]]["per_image"][r["metric"]][r["image"]] = float(r["value"])
    cost_key = _digest("cost", pattern.tile_string, pattern.bayer_phase, run,
                       filters.digest if filters is not None else None, results_version())

    def costs():
        return {m: op_cost(pattern, m, filters if m == "learned" else None)["total"]
                for m in run}

    for m, ops in _cached(cache_dir, "cost", cost_key, costs).items():
        out[m]["ops_per_z"] = ops
    if filters is not None:
        out["learned"]["filters"] = f"{filters.meta.get('training_set')} {filters.digest[:8]}"
    return out


def _common_means(colours, images):
    """Set every colour cell's means (``cfa_psnr``, ``cpsnr``, ``zipper`` of each layout and
    method that ran: ``colours``, the colour tasks' results) over the same images
    (:func:`rgbz_fast._devtools._common.common_means`: those on which every cell of the
    study is finite; inf for a cell exact on every image when none is, else None).
    Returns ``(note, left)``: the note on the images left out and their names ("" and []
    when none)."""
    cells = {(ci, m, k): v["per_image"][k] for ci, colour in enumerate(colours)
             for m, v in colour.items() if isinstance(v, dict) and "per_image" in v
             for k in COLOUR_METRICS}
    means, keep, left = common_means(cells, images)
    for (ci, m, k), mean in means.items():
        colours[ci][m][k] = mean
    if not left:
        return "", []
    odd = {x for c in cells.values() for n in left for x in [c.get(n, np.nan)]
           if not np.isfinite(x)}
    why = ("a PSNR of +inf: reconstructed exactly" if all(x == math.inf for x in odd) else
           "+inf: reconstructed exactly; NaN or -inf: a metric not computed")
    seen = len(keep) + len(left)
    if keep:
        return (f"colour means over the {len(keep)} of {seen} images on which every "
                f"layout and method is finite; left out: {', '.join(left)} ({why})"), left
    return (f"no image on which every layout and method is finite ({', '.join(left)}: {why}): "
            "a colour cell shows inf where it is +inf on every image, no mean otherwise"), left


# --------------------------------------------------------------------------- depth
def _depth_of(scene, pattern, seed, margin_blocks=6):
    """(result, tof, inner, note) of the colour-guided ToF ISP on one simulated frame:
    ``inner`` masks the measurements ``margin_blocks`` Z pixels (x2) away from the frame's
    edges; ``note`` says why the ISP ran without the guide, when the colour ISP cannot
    reconstruct the layout ("" otherwise)."""
    from ..isp import ColourISP
    from ..simulation import simulate
    from ..tof import ToFISP

    frame = simulate(scene, pattern, seed=seed)
    tof = frame.tof
    try:
        guide, note = ColourISP().run(frame), ""
    except ValueError as exc:          # the colour ISP's reconstruction does not apply
        guide = None
        note = f"depth without the colour guide ({' '.join(str(exc).split())})"
    res = ToFISP().run(tof, guide=guide)
    r, c = tof.sites
    m = margin_blocks * tof.block * 2
    H, W = scene.depth.shape
    inner = (r >= m) & (r < H - m) & (c >= m) & (c < W - m)
    return res, tof, inner, note


def _wall_task(cand, settings):
    """The wall's depth noise: the ISP's predicted sigma (RMS over the measurements of the
    frame's interior), the measured spread of the valid ones, and the valid share."""
    from ..simulation import Scene

    P, Q = cand.pattern.period
    rows, cols = (-(-s // p) * p for s, p in zip(settings.wall_shape, (P, Q)))
    d = settings.wall_distance
    scene = Scene(np.full((rows, cols, 3), 0.5), depth=np.full((rows, cols), d),
                  ir_reflectance=np.full((rows, cols), settings.wall_reflectance))
    res, tof, inner, note = _depth_of(scene, cand.pattern, settings.seed)
    ok = inner & res.valid
    err = res.depth[ok] - d
    # the prediction of every interior measurement, valid or not: a layout whose
    # measurements the ISP flags (too little signal after the denoise) still gets its noise
    sig = res.sigma[inner]
    sig = sig[np.isfinite(sig)]
    return {"wall_sigma_mm": float(np.sqrt(np.mean(sig ** 2)) * 1e3) if sig.size else None,
            "wall_std_mm": float(err.std() * 1e3) if err.size > 1 else None,
            "wall_valid": float(res.valid[inner].mean()) if inner.any() else None,
            "wall_n": int(ok.sum()), "note": note}


def _rgbd_task(cand, folder, settings):
    """Counts over the known measurements of one RGB-D scene (centre crop)."""
    from ..simulation import Scene, load_rgbd

    scene = load_rgbd(folder)
    if settings.rgbd_size is not None:
        H, W = scene.depth.shape
        h, w = min(settings.rgbd_size[0], H), min(settings.rgbd_size[1], W)
        r0, c0 = (H - h) // 4 * 2, (W - w) // 4 * 2      # even: the Bayer phase is kept
        sl = (slice(r0, r0 + h), slice(c0, c0 + w))
        scene = Scene(scene.image[sl], depth=scene.depth[sl],
                      depth_valid=scene.depth_valid[sl], name=scene.name)
    res, tof, _, note = _depth_of(scene, cand.pattern, settings.seed)
    known = tof.valid
    ok = res.valid & known
    err = res.depth - tof.depth_true
    return {"known": int(known.sum()), "valid": int(ok.sum()),
            "wrong_valid": int((ok & (np.abs(err) > TOLERANCE)).sum()),
            "sq_err_valid": float(np.sum(err[ok] ** 2)), "note": note}


def _task(job):
    """One task of a study (module level, so that Dask can ship it): ``job`` is
    (kind, candidate, arguments, settings, cache_dir, key)."""
    kind, cand, args, settings, cache_dir, key, workers = job
    if kind == "colour":
        dataset, train = args
        return _colour_task(cand, dataset, train, settings, cache_dir, workers)
    if kind == "wall":
        return _cached(cache_dir, "wall", key, lambda: _wall_task(cand, settings))
    return _cached(cache_dir, "rgbd", key, lambda: _rgbd_task(cand, args, settings))


def _depth_models():
    """The depth tasks' models as their keys hold them: the default ToF sensor and ToF ISP,
    and the revision of the ISP's noise model (a change of any had been served stale from a
    cache keyed by the version alone)."""
    from ..simulation import ToFSensor
    from ..tof import ToFISP
    from ..simulation._noise import SIM_REVISION
    from ..tof._noise import NOISE_MODEL

    return repr(ToFSensor()), repr(ToFISP()), NOISE_MODEL, SIM_REVISION


def _jobs(cands, dataset, train, rgbd_scenes, settings, cache_dir, workers):
    jobs = []
    models = _depth_models()
    for c in cands:
        jobs.append(("colour", c, (dataset, train), settings, cache_dir, None, workers))
        if c.block is None:
            continue
        base = (c.pattern.tile_string, c.pattern.bayer_phase, settings.seed, results_version(),
                models)
        jobs.append(("wall", c, None, settings, cache_dir,
                     _digest("wall", *base, settings.wall_distance,
                             settings.wall_reflectance, settings.wall_shape), workers))
        for folder in rgbd_scenes:
            fp = hashlib.sha1(b"".join((Path(folder) / n).read_bytes()
                                       for n in ("rgb.png", "disp1.png", "dmin.txt")))
            jobs.append(("rgbd", c, str(folder), settings, cache_dir,
                         _digest("rgbd", *base, settings.rgbd_size, fp.hexdigest()), workers))
    return jobs


def _run(jobs, scheduler, progress):
    from tqdm.auto import tqdm

    bar = tqdm(total=len(jobs), desc="pattern-study", unit="task", disable=not progress)
    out = [None] * len(jobs)
    try:
        if scheduler is None:
            for i, job in enumerate(jobs):
                bar.set_postfix_str(f"{job[1].name} {job[0]}", refresh=False)
                out[i] = _task(job)
                bar.update()
            return out
        from ..evaluation._cache import distributed
        from ..evaluation._run import dask_run_token, dask_task, issue_again
        dist = distributed()
        Client, as_completed = dist.Client, dist.as_completed
        own = not hasattr(scheduler, "submit")
        client = Client(scheduler) if own else scheduler
        run = dask_run_token()
        try:
            # a worker of another process records its tasks' warnings: issued again here
            futs = {client.submit(dask_task, _task, job, run, pure=False): i
                    for i, job in enumerate(jobs)}
            for f in as_completed(list(futs)):
                out[futs[f]], caught = f.result()
                issue_again(caught)
                bar.update()
        finally:
            if own:
                client.close()
        return out
    finally:
        bar.close()


def _sources(data, limit, name):
    from ..evaluation._run import dataset_sources

    try:
        return dataset_sources(data, limit)
    except (ValueError, TypeError, OSError) as exc:
        msg = " ".join(str(exc).split()).removeprefix("dataset: ")
        raise (TypeError if isinstance(exc, TypeError) else ValueError)(
            f"{name}: {msg}") from None


def pattern_study(dataset=None, *, presets=("mask1", "mask2"), tiles=(), generate=None,
                  methods=None, train=None, train_limit=None, rgbd=None, rgbd_limit=None,
                  limit=None, settings=None, cache_dir=None, scheduler=None, workers=None,
                  progress=True):
    """Measure every candidate layout; returns the JSON-able result (``rows``: one per
    layout and method, see :mod:`.pattern_report` for the columns).

    ``dataset``: colour images (a folder, a list of ImageSource, None: the scikit-image
    samples), the first ``limit``; ``train``: the folder (or list) ``learned`` is fitted
    on, the first ``train_limit`` (None: ``learned`` is a note); ``rgbd``: a folder of
    RGB-D scenes, the first ``rgbd_limit`` (None: no scene rows); ``presets``, ``tiles``,
    ``generate``: the candidates (:func:`.pattern_candidates.candidates`), all checked
    before any work starts; ``methods``: the methods measured (None: ``settings.methods``,
    :data:`METHODS` without ``settings``; given with a ``settings`` whose ``methods`` are
    neither the default nor the same, a ValueError); ``cache_dir``: where each task's
    result is kept (resume); ``scheduler``: a Dask address or client; ``workers``: threads
    of each kernel call. ``train_limit`` without ``train`` and ``rgbd_limit`` without
    ``rgbd`` are refused (they would be ignored).
    """
    t0 = time.perf_counter()
    from ..evaluation._cache import check_cache_dir, check_scheduler, forget_write_failures

    scheduler = check_scheduler(scheduler)
    cache_dir = check_cache_dir(cache_dir)
    forget_write_failures()            # a cache it cannot write: one warning a cause per run
    for limit_name, value, needs, given in (("train_limit", train_limit, "train", train),
                                            ("rgbd_limit", rgbd_limit, "rgbd", rgbd)):
        if value is not None and given is None:
            # the command line refuses them ("applies with --train"); they had been ignored
            raise ValueError(f"{limit_name}: applies with {needs}= (no {needs} given; "
                             f"{limit_name}={value!r} would be ignored)")
    settings = _settings_with(settings, methods)
    if isinstance(tiles, str):
        tiles = tuple(t for t in tiles.split(",") if t.strip())
    cands, notes = find_candidates(presets, tiles, generate)
    if not cands:
        raise ValueError("tiles: no layout to study (give presets, tiles or generate)")
    from ..simulation import ToFSensor

    reach = ToFSensor().unambiguous_range
    if not 0 < settings.wall_distance < reach:
        # the wall's measurements had all been flagged, and its noise ranked all the same
        raise ValueError(f"settings.wall_distance: {settings.wall_distance:g} m is not within "
                         f"the ToF sensor's unambiguous range (0, {reach:.4g}) m; every "
                         "measurement of the wall would be flagged")
    bad = [m for m in settings.methods if m not in METHODS]
    if bad:
        raise ValueError(f"methods: unknown {bad}; expected some of {list(METHODS)}")
    sources = _sources(dataset, limit, "dataset")
    train_set = None
    if train is not None:
        tsrc = _sources(train, train_limit, "train")
        tname = (Path(train).name if isinstance(train, (str, Path)) else "custom") + (
            f"[:{train_limit}]" if train_limit else "")
        overlap = {s.fingerprint() for s in tsrc} & {s.fingerprint() for s in sources}
        if overlap:
            raise ValueError(f"train: {len(overlap)} image(s) are also in the dataset; fit "
                             "on images the study does not evaluate")
        train_set = (tname, tsrc)
    scenes = []
    if rgbd is not None:
        from ..evaluation._depth_guided import scene_folders

        if not Path(rgbd).is_dir():
            raise ValueError(f"rgbd: {rgbd} is not a folder")
        scenes = [Path(rgbd) / n for n in scene_folders(rgbd)][:rgbd_limit]
        if not scenes:
            raise ValueError(f"rgbd: {rgbd} holds no RGB-D scene (rgb.png, disp1.png, "
                             "dmin.txt)")
    jobs = _jobs(cands, sources, train_set, scenes, settings, cache_dir, workers)
    results = _run(jobs, scheduler, progress)
    from .opcount import count_tof_operations

    tof_ops = count_tof_operations()
    colour_note, left_out = _common_means(
        [r for job, r in zip(jobs, results) if job[0] == "colour"], [s.name for s in sources])
    rows = _rows(cands, jobs, results, settings, tof_ops, colour_note)
    return {"rows": rows, "notes": notes, "methods": list(settings.methods),
            # the images the colour means leave out (a +inf PSNR; the rows' notes say so)
            "left_out": left_out,
            "layouts": [{"name": c.name, "tile": c.pattern.tile_string,
                         "bayer": c.pattern.bayer_phase, "source": c.source, "key": c.key,
                         "same_as": c.same_as} for c in cands],
            "dataset": {"name": _set_name(dataset), "images": [s.name for s in sources]},
            "train": None if train_set is None else {
                "name": train_set[0], "images": [s.name for s in train_set[1]]},
            "rgbd": [p.name for p in scenes], "settings": _settings_dict(settings),
            # per measurement and frequency (the demodulation counts one frequency at a time)
            "tof_ops_per_measurement_per_frequency":
                None if tof_ops is None else sum(tof_ops.values()),
            "machine": machine_info(), "scheduler": None if scheduler is None else str(
                scheduler), "wall_time_s": time.perf_counter() - t0}


def _settings_with(settings, methods):
    """``settings`` (None: the defaults) measuring ``methods`` (None: ``settings.methods``).

    ``methods`` given with a ``settings`` of other, non-default methods is refused, naming
    both: which of them the study was to measure is the caller's to say (``methods`` had been
    ignored whenever ``settings`` was given)."""
    if methods is None:
        return StudySettings() if settings is None else settings
    if isinstance(methods, str):
        methods = [m.strip() for m in methods.split(",") if m.strip()]
    methods = tuple(methods)
    if settings is None:
        return StudySettings(methods=methods)
    if tuple(settings.methods) not in (methods, METHODS):
        raise ValueError(f"methods: {list(methods)} conflicts with settings.methods "
                         f"{list(settings.methods)}; give the methods in one of them")
    return replace(settings, methods=methods)


def _set_name(data):
    if data is None:
        return "scikit-image samples"
    return Path(data).name if isinstance(data, (str, Path)) else "custom"


def _settings_dict(s):
    return {k: (list(v) if isinstance(v, tuple) else v) for k, v in s.__dict__.items()}


def _hardware(pattern, method):
    """Line buffers and variable multipliers of the fixed-point model of ``method`` on
    ``pattern`` ({} where the model does not cover them: learned, edi_rows, periods over 8)."""
    from ..hardware import FIXED_METHODS, hardware_cost

    if method not in FIXED_METHODS:
        return {}
    try:
        cost = hardware_cost(pattern, method)
    except ValueError:
        return {}
    return {"line_buffers": cost.line_buffers,
            "multipliers": int(sum(cost.multipliers().values()))}


def _rows(cands, jobs, results, settings, tof_ops, colour_note=""):
    by = {}
    for job, res in zip(jobs, results):
        by.setdefault(job[1].name, []).append((job[0], res))
    freqs = None
    rows = []
    for c in cands:
        parts = by[c.name]
        colour = next(r for k, r in parts if k == "colour")
        wall = next((r for k, r in parts if k == "wall"), None)
        scenes = [r for k, r in parts if k == "rgbd"]
        z_fill = c.pattern.z_fraction
        layout = {"layout": c.name, "tile": c.pattern.tile_string, "bayer": c.pattern.bayer_phase,
                  "source": c.source, "period": "x".join(map(str, c.pattern.period)),
                  "z_pixel": "x".join(map(str, c.z_size)), "z_fill": z_fill,
                  "same_as": ", ".join(c.same_as)}
        if c.block is not None:
            from ..simulation import ToFSensor

            freqs = freqs or len(ToFSensor().frequencies)
            per_pixel = z_fill / (c.block * c.block)
            layout["meas_per_mp"] = per_pixel * 1e6
            layout["tof_ops_per_pixel"] = (None if tof_ops is None else
                                           sum(tof_ops.values()) * freqs * per_pixel)
        if wall is not None:
            layout.update({k: wall[k] for k in ("wall_sigma_mm", "wall_std_mm", "wall_valid")})
        if scenes:
            known = sum(s["known"] for s in scenes)
            valid = sum(s["valid"] for s in scenes)
            layout.update(rgbd_valid=valid / known if known else None,
                          rgbd_wrong=sum(s["wrong_valid"] for s in scenes) / valid
                          if valid else None,
                          rgbd_rmse_mm=float(np.sqrt(sum(s["sq_err_valid"] for s in scenes)
                                                     / valid)) * 1e3 if valid else None)
        # ranked on a mean (None: no image to average; never NaN, which max() had taken as
        # the best and the table printed in bold)
        ranked = [m for m in settings.methods if colour[m].get("cpsnr") is not None
                  and not math.isnan(colour[m]["cpsnr"])]
        best = max(ranked, key=lambda m: colour[m]["cpsnr"]) if ranked else None
        for m in settings.methods:
            r = dict(layout, method=m, best=m == best)
            v = colour[m]
            r.update({k: v.get(k) for k in COLOUR_METRICS})
            ops = v.get("ops_per_z")
            r.update(ops_per_z=ops, ops_per_pixel=None if ops is None else ops * z_fill)
            r.update(_hardware(c.pattern, m) if "cpsnr" in v else {})
            depth_note = (wall or {}).get("note") or next(
                (x["note"] for x in scenes if x.get("note")), "")
            r["note"] = "; ".join(n for n in (v.get("note"), c.note, depth_note,
                                              colour_note if "per_image" in v else "",
                                              v.get("filters") and f"filters {v['filters']}")
                                  if n)
            rows.append(r)
    return rows
