"""Dataset evaluation: the paper's Fig. 19 chain on every image x pattern x method.

For every image the *reference path* (plain Bayer CFA, no reconstruction) and
the *RGB-Z path* (Z sites removed, then reconstructed) go through the same
colour chain; the metrics compare them at two levels: CFA PSNR on the
reconstructed pixels only (eqs. 20-21), then CPSNR, SSIM, MS-SSIM and the
zipper metric on the 8-bit sRGB images (eqs. 22-31).

Only what the requested metrics need is computed: CFA PSNR alone runs no
demosaic; a noise-free run draws no random numbers. Results are cached per
image and configuration (one small JSON file per image x pattern x method),
so an interrupted run resumes and a re-run with one more method computes
only that method. Every file is written atomically (temporary file, then
rename). Local runs use a process pool; given a Dask scheduler address the
same tasks run on Dask distributed and give the same numbers.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import math
import os
import tempfile
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from . import metrics as _metrics
from ._frame import mosaic
from ._patterns import get_pattern
from ._plans import METHODS
from ._reconstruct import PRECISIONS, check_reconstruct_options, reconstruct
from ._validate import check_bit_depth, check_choice, check_flag, check_seed, read_image_file

__all__ = ["EvalConfig", "Results", "ImageSource", "sample_dataset", "folder_dataset",
           "evaluate", "evaluate_image", "write_reports", "atomic_write", "PAPER_TABLE3",
           "IMAGE_METRICS", "ALL_METRICS"]

IMAGE_METRICS = ("cpsnr", "ssim", "ms_ssim", "zipper")
ALL_METRICS = ("cfa_psnr",) + IMAGE_METRICS
METRIC_LABELS = {"cfa_psnr": "CFA PSNR (dB)", "cpsnr": "CPSNR (dB)", "ssim": "SSIM",
                 "ms_ssim": "MS-SSIM", "zipper": "Zipper (%)"}
#: the better direction of every metric
HIGHER_IS_BETTER = {"cfa_psnr": True, "cpsnr": True, "ssim": True, "ms_ssim": True,
                    "zipper": False}
METHOD_LABELS = {"bilinear": "bilinear", "bi": "BI", "edi_central": "EDICentral",
                 "edi_line": "EDILine", "sg": "SG", "edi_rows": "EDI rows (Shi)"}

#: the paper's Table 3 (kodim09), for the comparison in the reports
PAPER_TABLE3 = {
    "mask1": {"bi": (24.55, 30.64, 0.9595, 0.9861, 12.493),
              "edi_central": (24.46, 30.81, 0.9607, 0.9861, 12.087),
              "edi_line": (24.97, 31.02, 0.9636, 0.9872, 11.504),
              "sg": (26.9, 32.99, 0.9751, 0.9918, 8.591)},
    "mask2": {"bi": (22.93, 26.70, 0.9163, 0.9676, 9.810),
              "edi_central": (24.83, 29.12, 0.9565, 0.9832, 5.420),
              "edi_line": (25.13, 29.13, 0.9600, 0.9835, 5.434),
              "sg": (26.13, 30.31, 0.9652, 0.9868, 5.041)},
}

_RAW_SUFFIXES = {".dng", ".cr2", ".cr3", ".nef", ".arw", ".raf", ".rw2", ".orf", ".pef",
                 ".srw", ".raw", ".bin"}
_IMAGE_SUFFIXES = {".png", ".tif", ".tiff", ".jpg", ".jpeg", ".bmp", ".ppm", ".webp"}
_SKIMAGE_SAMPLES = ("astronaut", "coffee", "chelsea", "rocket", "immunohistochemistry")


# --------------------------------------------------------------------------- config
@dataclass(frozen=True)
class EvalConfig:
    """What an evaluation runs; every field enters the cache key.

    Parameters
    ----------
    patterns, methods, metrics : tuple of str
        Patterns (``mask1``, ``mask2``, ``rows``, tile strings), reconstruction
        methods and metrics (``cfa_psnr``, ``cpsnr``, ``ssim``, ``ms_ssim``,
        ``zipper``).
    bit_depth : int
        ADC bits of the simulated raw frames (11, as in the paper), 1..16.
    noise : bool
        False: the noise-free mosaic of the image. True: the sensor model of
        :mod:`rgbz_fast.sensor` (same exposure and noise draw on both paths).
    demosaic : str
        Bayer demosaic of both paths (``malvar2004`` or ``menon2007``).
    crop : int
        Border (pixels) left out of the image metrics.
    precision : {"float32", "float64"}
        Arithmetic of the reconstruction kernels.
    reconstruct_options : mapping or tuple of (name, value)
        Extra keyword arguments of :func:`rgbz_fast.reconstruct`
        (``sigma_floor``, ``sg_mode``, ``exp``, ``domain``, ...); stored as a
        tuple of pairs sorted by name. ``method``, ``pattern``,
        ``bit_depth``, ``precision`` and ``workers`` are set by the
        evaluation, not here.
    seed : int
        Noise seed (noisy runs), an integer >= 0.
    clip_level : None, "auto" or float
        The ``clip_level`` of :func:`rgbz_fast.reconstruct`. None (default):
        no clip handling, every known pixel taken as a real value (on the
        openISP frame the clip handling costs CFA PSNR near the clip, so it
        is not the default; docs/raw.md, "Near clipping"). ``"auto"``: raw
        sources use the level their file records
        (:func:`rgbz_fast.rawio.frame_clip_level`), RGB sources none. A
        number (DN of the frames' bit depth): that level for every source.
        A ``clip_level`` in ``reconstruct_options`` wins.

    Raises
    ------
    ValueError, TypeError
        At construction, naming the field, for any value the run could not
        use (so that a bad configuration never reaches a worker process).
    """

    patterns: tuple = ("mask1", "mask2")
    methods: tuple = ("bilinear", "bi", "edi_central", "edi_line", "sg")
    metrics: tuple = ALL_METRICS
    bit_depth: int = 11
    noise: bool = False
    demosaic: str = "malvar2004"
    crop: int = 8
    precision: str = "float64"
    reconstruct_options: tuple = ()
    seed: int = 0
    clip_level: object = None

    def __post_init__(self):
        for name in ("patterns", "methods", "metrics"):
            v = getattr(self, name)
            if isinstance(v, str):
                v = tuple(s for s in v.split(",") if s)
            object.__setattr__(self, name, tuple(v))
        for p in self.patterns:
            get_pattern(p)
        bad = [m for m in self.methods if m not in METHODS]
        if bad:
            raise ValueError(f"methods: unknown method(s) {bad}; expected some of {list(METHODS)}")
        bad = [m for m in self.metrics if m not in ALL_METRICS]
        if bad:
            raise ValueError(f"metrics: unknown metric(s) {bad}; expected some of {list(ALL_METRICS)}")
        if self.demosaic not in ("malvar2004", "menon2007", "bilinear"):
            raise ValueError(f"demosaic: expected 'malvar2004', 'menon2007' or 'bilinear', "
                             f"got {self.demosaic!r}")
        if not isinstance(self.crop, (int, np.integer)) or self.crop < 0:
            raise ValueError(f"crop: expected a non-negative integer, got {self.crop!r}")
        if not self.patterns or not self.methods or not self.metrics:
            raise ValueError("patterns, methods and metrics must each name at least one entry")
        # checked here, not in a worker: a bad value fails before any image is read
        object.__setattr__(self, "bit_depth", check_bit_depth(self.bit_depth))
        object.__setattr__(self, "noise", check_flag(self.noise, "noise"))
        object.__setattr__(self, "precision", check_choice(
            self.precision, tuple(PRECISIONS), "precision"))
        object.__setattr__(self, "reconstruct_options", check_reconstruct_options(
            self.reconstruct_options, "reconstruct_options",
            by="the evaluation (EvalConfig.methods, bit_depth, precision; evaluate's workers)"))
        object.__setattr__(self, "seed", check_seed(self.seed, "seed"))
        if self.clip_level is not None and not isinstance(self.clip_level, str):
            from ._reconstruct import _clip_level
            object.__setattr__(self, "clip_level", _clip_level(self.clip_level, None))
        elif isinstance(self.clip_level, str) and self.clip_level != "auto":
            raise ValueError(f"clip_level: expected 'auto', None or a positive number, "
                             f"got {self.clip_level!r}")

    @property
    def image_metrics(self):
        return tuple(m for m in self.metrics if m in IMAGE_METRICS)

    def key(self, pattern, method, raw=False):
        """Cache key of one (pattern, method) under this configuration.

        ``raw``: the key of a raw source. ``clip_level=None`` (no clip handling) leaves
        every key (and cache) as it was before the option existed, and so does ``"auto"``
        for RGB sources, which it gives no level; raw sources are clipped by ``"auto"``,
        so their key includes it.
        """
        d = asdict(self)
        d.pop("patterns")
        d.pop("methods")
        d.pop("metrics")
        if d["clip_level"] is None or (d["clip_level"] == "auto" and not raw):
            d.pop("clip_level")
        d.update(pattern=str(get_pattern(pattern)), method=method, version=_cache_version())
        blob = json.dumps(d, sort_keys=True, default=str).encode()
        return hashlib.sha1(blob).hexdigest()[:16]

    def label(self):
        if self.clip_level is None:
            clip = ""
        elif self.clip_level == "auto":
            clip = ", clip level of the raw files"
        else:
            clip = f", clip level {self.clip_level:g} DN"
        return (f"{'noisy' if self.noise else 'noise-free'}, {self.bit_depth}-bit, "
                f"demosaic {self.demosaic}, border crop {self.crop} px, {self.precision}{clip}")

    def reconstruct_kwargs(self):
        """Keyword arguments of :func:`rgbz_fast.reconstruct`: clip_level and the options."""
        return {"clip_level": self.clip_level, **dict(self.reconstruct_options)}


def _cache_version():
    from ._build_config import VERSION
    return VERSION


# --------------------------------------------------------------------------- datasets
@dataclass(frozen=True)
class ImageSource:
    """One image of a dataset: a name and where to read it (a path or ``skimage:NAME``).

    Camera raw and bare Bayer files (``raw_options`` holds the keyword
    arguments of :func:`rgbz_fast.rawio.read_raw` they need) load as a Bayer
    :class:`~rgbz_fast.RawFrame`: the real CFA is then the reference and the
    RGB-Z pattern removes its Z sites (the paper's HDR+ protocol).
    """

    name: str
    location: str
    raw_options: tuple = ()
    raw: bool = False

    @property
    def is_raw(self):
        return self.raw or Path(self.location).suffix.lower() in _RAW_SUFFIXES

    def load(self):
        if self.is_raw:
            from .rawio import read_raw
            return read_raw(self.location, **dict(self.raw_options))
        if self.location.startswith("skimage:"):
            import skimage.data
            img = getattr(skimage.data, self.location.split(":", 1)[1])()
        else:
            img = read_image_file(self.location, "dataset")
        img = np.asarray(img)
        if img.ndim == 2:
            img = np.repeat(img[..., None], 3, axis=2)
        if img.ndim != 3 or img.shape[2] not in (3, 4):
            raise ValueError(f"dataset: {self.location} is not an RGB image (shape {img.shape})")
        return np.ascontiguousarray(img[..., :3])


def sample_dataset():
    """Five colour images shipped with scikit-image (astronaut, coffee, ...): runs offline."""
    return [ImageSource(n, f"skimage:{n}") for n in _SKIMAGE_SAMPLES]


def folder_dataset(path, limit=None, raw_options=None):
    """Every image file in a folder (sorted by name): RGB images, or camera raw / Bayer files.

    ``raw_options`` maps a file name (or ``"*"``, for every raw file) to the
    keyword arguments :func:`rgbz_fast.rawio.read_raw` needs for it (phase,
    black and white levels, shape of headerless files, ``downsample=2`` as
    the paper does for HDR+). A file named in ``raw_options`` is read as raw
    even if it is a PNG or TIFF (a 16-bit Bayer mosaic).
    """
    p = Path(path)
    if not p.exists():
        raise ValueError(f"dataset: {p} does not exist")
    if p.is_file():
        files = [p]
    else:
        files = sorted(f for f in p.iterdir()
                       if f.is_file() and f.suffix.lower() in _IMAGE_SUFFIXES | _RAW_SUFFIXES
                       and not f.name.startswith("."))
    if not files:
        raise ValueError(f"dataset: no image files in {p} (looked for "
                         f"{', '.join(sorted(_IMAGE_SUFFIXES))})")
    raw_options = dict(raw_options or {})
    files = files[:limit] if limit else files
    out = []
    for f in files:
        if f.suffix.lower() in _RAW_SUFFIXES or f.name in raw_options:
            opts = {**raw_options.get("*", {}), **raw_options.get(f.name, {})}
            out.append(ImageSource(f.stem, str(f), tuple(sorted(
                (k, tuple(v) if isinstance(v, list) else v) for k, v in opts.items())), raw=True))
        else:
            out.append(ImageSource(f.stem, str(f)))
    return out


# --------------------------------------------------------------------------- the chain
def colour_chain(cfa, phase, bit_depth, gains, demosaic="malvar2004"):
    """White balance -> demosaic -> sRGB gamma -> 8-bit: the chain both paths share.

    The ISP stages of :mod:`rgbz_fast.isp` on a complete Bayer CFA (linear
    values, black level 0); ``gains`` are the white-balance gains estimated
    once, on the reference, and applied to both paths (Fig. 19).
    """
    from .demosaic import demosaic as _demosaic
    from .isp import srgb_encode, white_balance

    balanced, _ = white_balance(cfa, phase, white_level=float((1 << bit_depth) - 1),
                                gains=gains, dtype=np.float64)
    rgb = _demosaic(balanced, phase, method=demosaic, dtype=np.float64)
    return srgb_encode(np.clip(rgb, 0.0, 1.0), bits=8)


def reference_gains(ref_cfa, phase, bit_depth):
    """Grey-world gains of the reference CFA (reused on the RGB-Z path)."""
    from .isp import grey_world_gains

    return grey_world_gains(ref_cfa, phase, white_level=float((1 << bit_depth) - 1))


def _linearise(img):
    """8/16-bit sRGB -> linear [0, 1] (the sRGB EOTF)."""
    v = img.astype(np.float64) / float(np.iinfo(img.dtype).max)
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def _pattern_for(pname, phase):
    """The pattern named ``pname`` on the Bayer phase of a raw file (presets follow the phase)."""
    base = str(pname).lower().split("_")[0]
    if base in ("mask1", "mask2", "rows", "bayer"):
        from . import _patterns
        return getattr(_patterns, base)(phase)
    pattern = get_pattern(pname)
    if pattern.bayer_phase != phase:
        raise ValueError(f"patterns: {pname!r} is built on {pattern.bayer_phase}, the raw file "
                         f"on {phase}")
    return pattern


def _frames(img, pattern, config):
    """(rgbz_frame, reference_cfa) for one image (RGB array or raw Bayer frame) and pattern."""
    from ._frame import RawFrame

    if isinstance(img, RawFrame):
        from .rawio import to_rgbz
        return to_rgbz(img, _pattern_for(pattern.name, img.pattern.bayer_phase))
    if config.noise:
        from .scene import Scene
        from .sensor import ColourSensor, simulate

        scene = Scene.from_rgb(img)
        frame = simulate(scene, pattern, ColourSensor(black_level=0), seed=config.seed,
                         noise=True)
        return frame, frame.reference
    lin = _linearise(img) if np.issubdtype(img.dtype, np.integer) else np.clip(img, 0, 1)
    frame = mosaic(lin, pattern, config.bit_depth)
    ref = mosaic(lin, pattern.bayer_pattern(), config.bit_depth).data
    return frame, ref


def evaluate_image(source, config, cache_dir=None, workers=1):
    """Every (pattern, method) of ``config`` on one image: a list of tidy rows.

    Each row: ``{"image", "pattern", "method", "metric", "value"}``. Cached
    results are reused; new ones are written to ``cache_dir`` atomically.
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
    for pname in dict.fromkeys(p for p, _ in todo):
        pattern = get_pattern(pname)
        frame, ref_cfa = _frames(img, pattern, config)
        pattern = frame.pattern
        z = frame.z_mask
        if config.image_metrics:
            # per pattern: a raw frame is cropped to a whole number of periods
            gains = reference_gains(ref_cfa, pattern.bayer_phase, frame.bit_depth)
            ref_srgb = colour_chain(ref_cfa, pattern.bayer_phase, frame.bit_depth, gains,
                                    config.demosaic)
        for p, m in todo:
            if p != pname:
                continue
            out = reconstruct(frame, m, precision=config.precision, workers=workers,
                              **config.reconstruct_kwargs())
            values = {}
            if "cfa_psnr" in config.metrics:
                values["cfa_psnr"] = _metrics.cfa_psnr(ref_cfa, out, z, bit_depth=frame.bit_depth)
            if config.image_metrics:
                test_srgb = colour_chain(out, pattern.bayer_phase, frame.bit_depth, gains,
                                         config.demosaic)
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


def atomic_write(path, data):
    """Write text or bytes to ``path`` through a temporary file and a rename: never half-written."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    mode = "wb" if isinstance(data, (bytes, bytearray)) else "w"
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)      # mkstemp's 0600 would make reports private
        with os.fdopen(fd, mode) as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


# --------------------------------------------------------------------------- runner
def _pool_task(args):
    source, config, cache_dir = args
    return evaluate_image(source, config, cache_dir, workers=1)


def evaluate(dataset=None, config=None, *, cache_dir=None, workers=None, scheduler=None,
             progress=True, **config_kwargs):
    """Run the Fig. 19 evaluation over a dataset; returns :class:`Results`.

    Parameters
    ----------
    dataset : list of ImageSource, str or Path, optional
        A list (any iterable) from :func:`sample_dataset` /
        :func:`folder_dataset`, or a folder. Default: :func:`sample_dataset`
        (runs offline).
    config : EvalConfig, optional
        What to run; keyword arguments build one when it is None.
    cache_dir : str or Path, optional
        Where per-image results are cached (and resumed from).
    workers : int, optional
        Processes of the local pool (default: all cores; 1 runs in-process).
    scheduler : str or distributed.Client, optional
        A Dask scheduler address (``"tcp://host:8786"``) or client: the same
        tasks run on Dask distributed instead of the local pool.
    progress : bool
        Show a progress bar (tqdm) on stderr.
    """
    if config is None:
        config = EvalConfig(**config_kwargs)
    elif config_kwargs:
        raise TypeError("pass either config or keyword arguments, not both")
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
    cache_dir = str(cache_dir) if cache_dir is not None else None
    tasks = [(s, config, cache_dir) for s in dataset]
    from tqdm.auto import tqdm
    bar = tqdm(total=len(tasks), desc="evaluate", unit="img", disable=not progress)
    results = {}
    try:
        if scheduler is not None:
            results = _run_dask(tasks, scheduler, bar)
        else:
            nproc = workers if workers is not None else (os.cpu_count() or 1)
            if nproc < 1:
                raise ValueError(f"workers: expected a positive integer, got {workers!r}")
            if nproc == 1 or len(tasks) == 1:
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


# --------------------------------------------------------------------------- results
@dataclass
class Results:
    """A tidy table: one row per image, pattern, method and metric."""

    rows: list
    config: EvalConfig = field(default_factory=EvalConfig)

    def __len__(self):
        return len(self.rows)

    def values(self, pattern, method, metric):
        return np.array([r["value"] for r in self.rows if r["pattern"] == pattern
                         and r["method"] == method and r["metric"] == metric], dtype=float)

    def summary(self):
        """{(pattern, method, metric): (mean, std, n)}; infinite values are left out of the mean."""
        out = {}
        for p in self.config.patterns:
            for m in self.config.methods:
                for k in self.config.metrics:
                    v = self.values(p, m, k)
                    v = v[np.isfinite(v)]
                    out[(p, m, k)] = (float(v.mean()) if v.size else math.nan,
                                      float(v.std(ddof=1)) if v.size > 1 else 0.0, int(v.size))
        return out

    def images(self):
        return list(dict.fromkeys(r["image"] for r in self.rows))

    def to_csv(self):
        buf = io.StringIO()
        w = csv.DictWriter(buf, fieldnames=["image", "pattern", "method", "metric", "value"],
                           lineterminator="\n")
        w.writeheader()
        for r in self.rows:
            w.writerow({**r, "value": repr(r["value"])})
        return buf.getvalue()

    def to_json(self):
        return json.dumps({"config": asdict(self.config), "rows": self.rows}, indent=1,
                          default=str)

    def summary_markdown(self, digits=None):
        """Per pattern: a table of mean ± std per method and metric, best per column in bold."""
        s = self.summary()
        fmt = digits or {"cfa_psnr": 2, "cpsnr": 2, "ssim": 4, "ms_ssim": 4, "zipper": 2}
        lines = [f"Mean ± std over {len(self.images())} image(s); {self.config.label()}.", ""]
        for p in self.config.patterns:
            lines.append(f"**{p}**")
            lines.append("")
            hdr = "| method | " + " | ".join(METRIC_LABELS[k] for k in self.config.metrics) + " |"
            lines += [hdr, "|---" * (len(self.config.metrics) + 1) + "|"]
            best = {}
            for k in self.config.metrics:
                means = [s[(p, m, k)][0] for m in self.config.methods]
                finite = [x for x in means if np.isfinite(x)]
                if finite:
                    best[k] = max(finite) if HIGHER_IS_BETTER[k] else min(finite)
            for m in self.config.methods:
                cells = []
                for k in self.config.metrics:
                    mean, std, _ = s[(p, m, k)]
                    cell = f"{mean:.{fmt[k]}f} ± {std:.{fmt[k]}f}"
                    cells.append(f"**{cell}**" if best.get(k) == mean else cell)
                lines.append(f"| {METHOD_LABELS.get(m, m)} | " + " | ".join(cells) + " |")
            lines.append("")
        return "\n".join(lines)

    def image_markdown(self, image):
        """The paper's Table 3 layout for one image, with the paper's kodim09 values beside ours."""
        if image not in self.images():
            raise ValueError(f"image: {image!r} is not in the results ({', '.join(self.images())})")
        lines = []
        for p in self.config.patterns:
            paper = PAPER_TABLE3.get(p, {}) if image.lower().startswith("kodim09") else {}
            lines += [f"**{p}** — {image}" + (" (paper's Table 3 in brackets)" if paper else ""),
                      "", "| metric | " + " | ".join(METHOD_LABELS.get(m, m)
                                                      for m in self.config.methods) + " |",
                      "|---" * (len(self.config.methods) + 1) + "|"]
            for i, k in enumerate(self.config.metrics):
                cells = []
                for m in self.config.methods:
                    v = [r["value"] for r in self.rows if r["image"] == image and r["pattern"] == p
                         and r["method"] == m and r["metric"] == k]
                    cell = f"{v[0]:.4g}" if v else "n/a"
                    if m in paper:
                        j = list(ALL_METRICS).index(k)
                        cell += f" ({paper[m][j]:.4g})"
                    cells.append(cell)
                lines.append(f"| {METRIC_LABELS[k]} | " + " | ".join(cells) + " |")
            lines.append("")
        return "\n".join(lines)

    def plain_table(self):
        """The summary as aligned plain text for the terminal."""
        s = self.summary()
        w = max(len(METHOD_LABELS.get(m, m)) for m in self.config.methods) + 2
        out = []
        for p in self.config.patterns:
            out.append(f"{p}  ({len(self.images())} images; {self.config.label()})")
            out.append(" " * w + "".join(f"{METRIC_LABELS[k]:>20}" for k in self.config.metrics))
            for m in self.config.methods:
                cells = "".join(f"{s[(p, m, k)][0]:>12.4f} ±{s[(p, m, k)][1]:<7.3f}"
                                for k in self.config.metrics)
                out.append(f"{METHOD_LABELS.get(m, m):<{w}}{cells}")
            out.append("")
        return "\n".join(out)


# --------------------------------------------------------------------------- reports
def write_reports(results, out_dir, *, table_image=None, crop_source=None, crop_box=None,
                  plots=True):
    """Write results.csv, results.json, summary.md, a per-image table and the figures.

    Returns the list of files written. ``table_image`` defaults to kodim09
    when present, else the first image. ``crop_source`` (an ImageSource)
    adds a Fig. 21-like crop comparison.

    Raises
    ------
    TypeError
        ``results`` is not a :class:`Results`.
    ValueError
        ``results`` holds no row (an empty table has nothing to summarise;
        nothing is written, not even the folder), or ``table_image`` is not
        one of its images.
    """
    if not isinstance(results, Results):
        raise TypeError(f"results: expected Results, got {type(results).__name__}")
    if not results.rows:
        raise ValueError("results: no rows to report (an evaluation of no image); nothing "
                         "was written")
    images = results.images()
    if table_image is not None and table_image not in images:
        raise ValueError(f"table_image: {table_image!r} is not in the results "
                         f"({', '.join(images)})")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = []

    def put(name, data):
        atomic_write(out / name, data)
        written.append(out / name)

    put("results.csv", results.to_csv())
    put("results.json", results.to_json())
    put("summary.md", "# Evaluation summary\n\n" + results.summary_markdown() + "\n")
    if table_image is None:
        table_image = next((i for i in images if i.lower() == "kodim09"), images[0])
    put(f"table_{_safe(table_image)}.md", results.image_markdown(table_image) + "\n")
    if plots:
        for k in results.config.metrics:
            put(f"bars_{k}.png", bar_chart(results, k))
        if crop_source is not None:
            put(f"crops_{_safe(crop_source.name)}.png",
                crop_figure(crop_source, results.config, box=crop_box))
    return written


def _figure_png(fig):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    import matplotlib.pyplot as plt
    plt.close(fig)
    return buf.getvalue()


def bar_chart(results, metric):
    """Fig. 20-like bars: mean per method and pattern with ±1 std error bars (PNG bytes)."""
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    s = results.summary()
    cfg = results.config
    fig, ax = plt.subplots(figsize=(1.2 + 1.1 * len(cfg.methods) * len(cfg.patterns) / 2, 3.4))
    width = 0.8 / len(cfg.methods)
    x = np.arange(len(cfg.patterns))
    for i, m in enumerate(cfg.methods):
        means = [s[(p, m, metric)][0] for p in cfg.patterns]
        stds = [s[(p, m, metric)][1] for p in cfg.patterns]
        ax.bar(x + (i - (len(cfg.methods) - 1) / 2) * width, means, width, yerr=stds,
               capsize=2, label=METHOD_LABELS.get(m, m))
    ax.set_xticks(x, cfg.patterns)
    ax.set_ylabel(METRIC_LABELS[metric])
    allm = [s[(p, m, metric)][0] for p in cfg.patterns for m in cfg.methods]
    finite = [v for v in allm if np.isfinite(v)]
    if finite and metric not in ("zipper",):
        lo, hi = min(finite), max(finite)
        pad = max(hi - lo, 1e-3)
        ax.set_ylim(lo - 1.5 * pad, hi + 0.8 * pad)
    ax.set_title(f"{METRIC_LABELS[metric]} — {len(results.images())} images "
                 f"({'higher' if HIGHER_IS_BETTER[metric] else 'lower'} is better)", fontsize=9)
    ax.legend(fontsize=7, ncol=min(len(cfg.methods), 5), loc="upper center",
              bbox_to_anchor=(0.5, -0.12))
    ax.grid(axis="y", alpha=0.3)
    return _figure_png(fig)


def crop_figure(source, config, box=None, size=96):
    """Fig. 21-like comparison: reference and each method side by side, per pattern (PNG bytes)."""
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    img = source.load()
    tiles = []
    for pname in config.patterns:
        frame, ref_cfa = _frames(img, get_pattern(pname), config)
        pattern = frame.pattern
        gains = reference_gains(ref_cfa, pattern.bayer_phase, frame.bit_depth)
        ref = colour_chain(ref_cfa, pattern.bayer_phase, frame.bit_depth, gains, config.demosaic)
        row = [("reference", ref)]
        for m in config.methods:
            out = reconstruct(frame, m, precision=config.precision,
                              **config.reconstruct_kwargs())
            row.append((METHOD_LABELS.get(m, m),
                        colour_chain(out, pattern.bayer_phase, frame.bit_depth, gains,
                                     config.demosaic)))
        tiles.append((pname, row))
    if box is None:
        # the crop where the methods differ most from the reference (SG's worst area shown)
        ref = tiles[0][1][0][1].astype(float)
        err = sum(np.abs(t.astype(float) - ref).sum(2) for _, t in tiles[0][1][1:])
        from scipy.ndimage import uniform_filter
        e = uniform_filter(err, size)
        y, x = np.unravel_index(np.argmax(e), e.shape)
        y0 = int(np.clip(y - size // 2, 0, ref.shape[0] - size))
        x0 = int(np.clip(x - size // 2, 0, ref.shape[1] - size))
        box = (y0, x0, size, size)
    y0, x0, h, w = box
    ncol = len(tiles[0][1])
    fig, axes = plt.subplots(len(tiles), ncol, figsize=(1.9 * ncol, 2.05 * len(tiles)),
                             squeeze=False)
    for i, (pname, row) in enumerate(tiles):
        for j, (label, im) in enumerate(row):
            ax = axes[i, j]
            ax.imshow(im[y0:y0 + h, x0:x0 + w], interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title(f"{pname}: {label}" if j else label, fontsize=8)
    fig.suptitle(f"{source.name}, crop rows {y0}:{y0 + h}, cols {x0}:{x0 + w}", fontsize=9)
    return _figure_png(fig)
