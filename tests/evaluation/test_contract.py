"""The bad-input contract of rgbz_fast.evaluation, and runs that are killed or interrupted.

Rows of docs/reports/robustness.md (``evaluation.*``), run by the shared runner of
``tests/_contract.py``; then: the configuration is checked when it is made, reports
of no rows write nothing, a killed evaluation resumes from its cache, SIGTERM stops
the worker pool, and a report is never half-written.
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

import rgbz_fast as rz
from _contract import Row, api_tests, files, rgb  # noqa: F401
from rgbz_fast import evaluation as ev
from rgbz_fast import io as rio

R = Row

ROWS = [
    # -- evaluate, EvalConfig, evaluate_depth, reports -------------------------------------
    R("evaluation.EvalConfig-empty", "EvalConfig(patterns=())",
      lambda f: ev.EvalConfig(patterns=()), ValueError,
      "patterns, methods and metrics must each name at least one entry"),
    R("evaluation.EvalConfig-pattern", "EvalConfig(patterns=('foo',))",
      lambda f: ev.EvalConfig(patterns=("foo",)), ValueError, "pattern: 'foo' is neither"),
    R("evaluation.EvalConfig-pattern-no-z", "EvalConfig(patterns=('bayer',))",
      lambda f: ev.EvalConfig(patterns=("bayer",)), ValueError,
      "patterns: 'bayer' has no Z site; the evaluation measures what is made at the Z sites"),
    R("evaluation.evaluate_depth-pattern-no-z", "evaluate_depth(patterns=('bayer',))",
      lambda f: ev.evaluate_depth(None, patterns=("bayer",)), ValueError,
      "patterns: 'bayer' has no Z site"),
    R("evaluation.EvalConfig-patterns-twice", "EvalConfig(patterns=('mask1', 'mask1_grbg'))",
      lambda f: ev.EvalConfig(patterns=("mask1", "mask1_grbg")), ValueError,
      "patterns: 'mask1_grbg' is given twice (as 'mask1'); name each entry once"),
    R("evaluation.EvalConfig-metrics-twice", "EvalConfig(metrics=('cpsnr', 'cpsnr'))",
      lambda f: ev.EvalConfig(metrics=("cpsnr", "cpsnr")), ValueError,
      "metrics: 'cpsnr' is given twice"),
    R("evaluation.EvalConfig-method", "EvalConfig(methods=('foo',))",
      lambda f: ev.EvalConfig(methods=("foo",)), ValueError, "methods: unknown method(s)"),
    R("evaluation.EvalConfig-metric", "EvalConfig(metrics=('foo',))",
      lambda f: ev.EvalConfig(metrics=("foo",)), ValueError, "metrics: unknown metric(s)"),
    R("evaluation.EvalConfig-demosaic", "EvalConfig(demosaic='x')",
      lambda f: ev.EvalConfig(demosaic="x"), ValueError,
      "demosaic: expected one of 'malvar2004', 'menon2007', 'bilinear'"),
    R("evaluation.EvalConfig-crop", "EvalConfig(crop=-1)", lambda f: ev.EvalConfig(crop=-1),
      ValueError, "crop: expected an integer >= 0"),
    R("evaluation.EvalConfig-optics", "EvalConfig(optics=2.8)",
      lambda f: ev.EvalConfig(optics=2.8),
      TypeError, "optics: expected an Optics or None, got float"),
    R("evaluation.evaluate_depth-sections", "evaluate_depth(sections=('speed',))",
      lambda f: ev.evaluate_depth(None, sections=("speed",)), ValueError,
      "sections: unknown ['speed']"),
    R("evaluation.evaluate_depth-isp", "evaluate_depth(isp='box')",
      lambda f: ev.evaluate_depth(None, sections=("noise",), isp="box"), TypeError,
      "isp: expected a ToFISP"),
    R("evaluation.EvalConfig-bit_depth", "EvalConfig(bit_depth=40)",
      lambda f: ev.EvalConfig(bit_depth=40), ValueError, "bit_depth: expected 1..16 bits"),
    R("evaluation.EvalConfig-bit_depth-type", "EvalConfig(bit_depth='11')",
      lambda f: ev.EvalConfig(bit_depth="11"), TypeError,
      "bit_depth: expected an integer number of bits"),
    R("evaluation.EvalConfig-params", "EvalConfig(params={'foo': 1})",
      lambda f: ev.EvalConfig(params={"foo": 1}), TypeError,
      "params got an unexpected keyword argument 'foo'"),
    R("evaluation.EvalConfig-params-value", "EvalConfig(params={'sigma_floor': -1})",
      lambda f: ev.EvalConfig(params={"sigma_floor": -1}), ValueError,
      "sigma_floor: expected a finite number > 0"),
    R("evaluation.EvalConfig-params-type", "EvalConfig(params='sg_mode=pure')",
      lambda f: ev.EvalConfig(params="sg_mode=pure"), TypeError,
      "params: expected a ReconstructParams, a dict of its fields or None"),
    R("evaluation.EvalConfig-params-workers", "EvalConfig(params={'workers': 2})",
      lambda f: ev.EvalConfig(params={"workers": 2}), TypeError,
      "params got an unexpected keyword argument 'workers'"),
    R("evaluation.EvalConfig-seed", "EvalConfig(seed=-1)", lambda f: ev.EvalConfig(seed=-1),
      ValueError, "seed: expected an integer >= 0"),
    R("evaluation.EvalConfig-noise", "EvalConfig(noise='yes')",
      lambda f: ev.EvalConfig(noise="yes"),
      TypeError, "noise: expected True or False"),
    R("evaluation.evaluate-empty", "evaluate([])",
      lambda f: ev.evaluate([], ev.EvalConfig()), ValueError,
      "dataset: no images"),
    R("evaluation.evaluate-override-unknown", "evaluate(ds, config, cropp=1)",
      lambda f: ev.evaluate([], ev.EvalConfig(), cropp=1), TypeError,
      "evaluate() got an unexpected keyword argument 'cropp' (fields of EvalConfig: "),
    R("evaluation.EvalConfig-type", "evaluate(ds, config='sg')",
      lambda f: ev.evaluate([], "sg"), TypeError,
      "config: expected an EvalConfig, a dict of its fields or None, got str"),
    R("evaluation.evaluate-processes", "evaluate(processes=0)",
      lambda f: ev.evaluate(f / "ds", metrics=("cfa_psnr",), processes=0, progress=False),
      ValueError, "processes: expected None or a positive number of processes"),
    R("evaluation.evaluate-workers", "evaluate(workers=0)",
      lambda f: ev.evaluate(f / "ds", metrics=("cfa_psnr",), workers=0, progress=False),
      ValueError, "workers: expected None, -1 or a positive number of threads"),
    R("evaluation.evaluate-duplicate-names", "evaluate(two images named 'a')",
      lambda f: ev.evaluate([rio.ImageSource("a", "skimage:coffee")] * 2, progress=False),
      ValueError, "dataset: image names must be unique"),
    R("evaluation.evaluate-missing-folder", "evaluate('missing')",
      lambda f: ev.evaluate(f / "missing", progress=False), ValueError, "dataset: "),
    R("evaluation.evaluate-dataset-type", "evaluate(dataset=5)",
      lambda f: ev.evaluate(5, progress=False), TypeError,
      "dataset: expected a list of ImageSource, a folder or None, got int"),
    R("evaluation.evaluate-dataset-entries", "evaluate(['a.png'])",
      lambda f: ev.evaluate([str(f / "rgb.png")], progress=False), TypeError,
      "dataset: expected ImageSource entries"),
    R("evaluation.evaluate-image-too-small", "evaluate(1x1 image)",
      lambda f: ev.evaluate([rio.ImageSource("t", str(f / "tiny.png"))], metrics=("cfa_psnr",),
                            workers=1, progress=False), ValueError,
      "dataset: image 't': frame 1x1 is smaller than one period"),
    R("evaluation.evaluate-crop-too-large", "evaluate(20x20 image, crop=8, ssim)",
      lambda f: ev.evaluate([rio.ImageSource("s", str(f / "small.png"))], metrics=("ssim",),
                            workers=1, progress=False), ValueError,
      "crop: image 's': crop=8 leaves"),
    R("evaluation.evaluate-skip_bad", "evaluate(skip_bad='yes')",
      lambda f: ev.evaluate(f / "ds", metrics=("cfa_psnr",), skip_bad="yes", progress=False),
      TypeError, "skip_bad: expected True or False"),
    R("evaluation.paired_chart-one-method", "paired_chart(results of one method)",
      lambda f: ev.paired_chart(ev.Results([{"image": "a", "pattern": "mask1", "method": "sg",
                                             "metric": "cfa_psnr", "value": 1.0}],
                                           ev.EvalConfig(methods=("sg",))), "cfa_psnr"),
      ValueError, "baseline: 'sg' is the only method; nothing to compare"),
    R("evaluation.write_reports-empty", "write_reports(Results([]))",
      lambda f: ev.write_reports(ev.Results([], ev.EvalConfig()), f / "reports_empty"),
      ValueError, "results: no rows to report"),
    R("evaluation.write_reports-type", "write_reports(list of rows)",
      lambda f: ev.write_reports([], f / "reports_list"), TypeError,
      "results: expected Results"),
    R("evaluation.image_frames-int64", "image_frames(int64 image)",
      lambda f: ev.image_frames(np.full((8, 8, 3), 200), "mask1", ev.EvalConfig()), TypeError,
      "img: an int64 image (a list of Python ints becomes int64) says nothing about the range"),
    R("evaluation.evaluate-int32-tif", "evaluate(folder of an int32 TIFF)",
      lambda f: ev.evaluate([rio.ImageSource("i", str(f / "int32.tif"))], progress=False,
                            metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",)),
      ValueError, "dataset: {d}/int32.tif holds int32 samples"),
    R("evaluation.evaluate-cache-file", "evaluate(cache_dir=a file)",
      lambda f: ev.evaluate(f / "ds", cache_dir=f / "file.txt", progress=False), ValueError,
      "cache_dir: {d}/file.txt exists and is not a folder"),
    R("evaluation.evaluate-fifo", "evaluate(folder_dataset(a FIFO))",
      lambda f: ev.evaluate(rio.folder_dataset(f / "fifo.tif"), progress=False, processes=1,
                            metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",)),
      ValueError, "dataset: {d}/fifo.tif is a FIFO (named pipe), not a regular file"),
]

test_api_contract = api_tests(ROWS)


def test_evaluate_accepts_any_iterable_dataset():
    """The dataset check refuses only what is not a list of ImageSource: any iterable of
    them (here a generator) is read once and evaluated."""
    sources = (rio.ImageSource(n, f"skimage:{n}") for n in ["coffee"])
    res = ev.evaluate(sources, metrics=("cfa_psnr",), methods=("bilinear",),
                      patterns=("mask1",), workers=1, progress=False)
    assert len(res) == 1 and np.isfinite(res.rows[0]["value"])


# --------------------------------------------------------------------------- checked early
def test_write_reports_of_no_rows_writes_nothing(tmp_path):
    """An empty Results is an error before anything is written; old reports stay."""
    empty = ev.Results([], ev.EvalConfig())
    with pytest.raises(ValueError, match="^results: no rows to report"):
        ev.write_reports(empty, tmp_path / "new")
    assert not (tmp_path / "new").exists()
    rows = [{"image": "a", "pattern": "mask1", "method": "sg", "metric": "cfa_psnr",
             "value": 30.0}]
    full = ev.Results(rows, ev.EvalConfig(patterns=("mask1",), methods=("sg",),
                                          metrics=("cfa_psnr",)))
    ev.write_reports(full, tmp_path / "old", plots=False)
    before = {p: p.read_bytes() for p in (tmp_path / "old").iterdir()}
    with pytest.raises(ValueError, match="^results: no rows to report"):
        ev.write_reports(empty, tmp_path / "old", plots=False)
    with pytest.raises(ValueError, match="^table_image: 'b' is not in the results"):
        ev.write_reports(full, tmp_path / "old", plots=False, table_image="b")
    assert {p: p.read_bytes() for p in (tmp_path / "old").iterdir()} == before


def test_eval_config_is_checked_and_normalised_at_construction():
    """A bad field fails at EvalConfig(...), naming it, before any worker runs; good values
    are normalised so that equal configurations share their cache key."""
    cfg = ev.EvalConfig(params=rz.ReconstructParams(precision="float64", sg_mode="pure",
                                                    exp="fast"))
    as_dict = ev.EvalConfig(params={"precision": "float64", "exp": "fast", "sg_mode": "pure"})
    assert as_dict.params == cfg.params and isinstance(as_dict.params, rz.ReconstructParams)
    assert as_dict.key("mask1", "sg") == cfg.key("mask1", "sg")
    assert cfg.key("mask1", "sg") != ev.EvalConfig().key("mask1", "sg")
    hash(as_dict)                                              # still hashable
    np_typed = ev.EvalConfig(bit_depth=np.int64(11), noise=np.False_, seed=np.uint8(0))
    assert np_typed.key("mask1", "sg") == ev.EvalConfig().key("mask1", "sg")
    assert type(np_typed.bit_depth) is int and np_typed.noise is False
    # every field of the parameters is accepted, and what is accepted runs
    frame = rz.mosaic(rgb((8, 8)), "mask1")
    for k, v in rz.ReconstructParams().as_dict().items():
        params = ev.EvalConfig(params={k: v}).params
        rz.reconstruct(frame, "sg", params=params)
    for bad, exc in (({"method": "sg"}, TypeError), ({"pattern": "mask1"}, TypeError),
                     ({"sigma_rel": None}, TypeError), ({1: 2}, TypeError),
                     ({"domain": "lab"}, ValueError), ({"clip_level": -1}, ValueError),
                     ({"clip_level": "high"}, TypeError), ({"out": None}, TypeError)):
        with pytest.raises(exc):
            ev.EvalConfig(params=bad)


# --------------------------------------------------------------------------- interrupted runs
def test_cache_entries_are_read_guarded_and_validated(files, tmp_path):
    """The evaluation's cache is read through the guarded reader and checked: a FIFO under an
    entry's name does not block, and a damaged or tampered entry (NaN, 1e999, text, a value
    out of its metric's range, not an object, a value edited without its checksum) is
    recomputed and written again, never served as a result; a cache that cannot take an
    entry costs a warning, not the result."""
    import os

    from _support import run_past_a_fifo

    kw = dict(metrics=("cfa_psnr", "ssim"), methods=("bi",), patterns=("mask1",),
              progress=False, processes=1)
    src = [rio.ImageSource("s", str(files / "small.png"))]
    want = ev.evaluate(src, cache_dir=tmp_path, crop=0, **kw).rows
    (entry,) = tmp_path.rglob("*.json")
    good = entry.read_text()
    for bad in ('{"cfa_psnr": NaN, "ssim": 0.5}', '{"cfa_psnr": 1e999, "ssim": 0.5}',
                '{"cfa_psnr": 20.0, "ssim": 7.0}', '{"cfa_psnr": "20", "ssim": 0.5}',
                '{"cfa_psnr": 20.0, "ssim": -Infinity}', "[20.0, 0.5]", "\xff\xfe",
                '{"cfa_psnr": 20.0, "ssim": 0.5, "zz": 1.0}',
                # a plausible value edited by hand: the checksum no longer matches
                good.replace(str(json.loads(good)["values"]["cfa_psnr"]), "99.5"),
                json.dumps({**json.loads(good), "values": {"cfa_psnr": 99.5, "ssim": 0.5}})):
        entry.write_text(bad)
        assert ev.evaluate(src, cache_dir=tmp_path, crop=0, **kw).rows == want, bad
        assert entry.read_text() == good, bad
    # an entry the cache cannot take (a folder under its name): the result, and a warning
    entry.unlink()
    entry.mkdir()
    with pytest.warns(RuntimeWarning, match="^cache_dir: could not write"):
        assert ev.evaluate(src, cache_dir=tmp_path, crop=0, **kw).rows == want
    entry.rmdir()
    ev.evaluate(src, cache_dir=tmp_path, crop=0, **kw)
    entry.unlink()
    os.mkfifo(entry)
    done = run_past_a_fifo(lambda: ev.evaluate(src, cache_dir=tmp_path, crop=0, **kw).rows,
                           entry, 60, "a FIFO in the cache blocked the evaluation")
    assert done == [want] and entry.is_file() and entry.read_text() == good


def test_a_cache_that_cannot_take_any_entry_warns_once_a_cause(files, tmp_path, monkeypatch):
    """A cache folder of no write permission failed every entry with a warning of its own
    (`rgbz-fast evaluate --cache DIR`, DIR not writable: 30 lines for 3 images, 240 on
    Kodak; found as a non-root user, where root writes anyway): one warning for each cause
    (the error and the folder it names) in an evaluation, the results all there; the next
    evaluation warns again."""
    import errno
    import warnings

    from rgbz_fast.evaluation import _cache

    kw = dict(metrics=("cfa_psnr",), methods=("bi", "sg"), patterns=("mask1", "mask2"),
              progress=False, processes=1, crop=0)
    src = [rio.ImageSource(n, str(files / "small.png")) for n in ("a", "b", "c")]
    want = ev.evaluate(src, **kw).rows
    # the image folders cannot be made (a file under each name): one cause, the cache's
    for s in src:
        (tmp_path / "c1" / _cache.cache_folder(s.name)).parent.mkdir(exist_ok=True)
        (tmp_path / "c1" / _cache.cache_folder(s.name)).write_text("x")
    for _ in range(2):
        with warnings.catch_warnings(record=True) as got:
            warnings.simplefilter("always")
            assert ev.evaluate(src, cache_dir=tmp_path / "c1", **kw).rows == want
        msgs = [str(w.message) for w in got if issubclass(w.category, RuntimeWarning)]
        assert len(msgs) == 1 and msgs[0].startswith("cache_dir: could not write"), msgs
        assert "other entries that fail so are kept and not named either" in msgs[0]

    # a full disk: the error names no file; one warning for the run
    def full(*a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(_cache, "atomic_write", full)
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        assert ev.evaluate(src, cache_dir=tmp_path / "c2", **kw).rows == want
    msgs = [str(w.message) for w in got if issubclass(w.category, RuntimeWarning)]
    assert len(msgs) == 1 and "No space left on device" in msgs[0], msgs


def test_a_worker_processs_warnings_are_the_callers(files, tmp_path, capfd):
    """With processes=2 a warning of an image's evaluation (here: its cache folder cannot be
    made) was printed by the worker process in Python's own format, file and source line,
    past the caller's filters and the command line's one-line format: the parent issues it
    again."""
    import warnings

    from rgbz_fast.evaluation import _cache

    kw = dict(metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",), progress=False,
              crop=0)
    src = [rio.ImageSource(n, str(files / "small.png")) for n in ("a", "b")]
    want = ev.evaluate(src, processes=1, **kw).rows
    (tmp_path / "c").mkdir()
    for s in src:
        (tmp_path / "c" / _cache.cache_folder(s.name)).write_text("x")
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        assert ev.evaluate(src, processes=2, cache_dir=tmp_path / "c", **kw).rows == want
    msgs = [str(w.message) for w in got if issubclass(w.category, RuntimeWarning)]
    assert 1 <= len(msgs) <= 2, msgs                 # one a cause in each worker process
    assert all(m.startswith("cache_dir: could not write") for m in msgs), msgs
    capfd.readouterr()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                 # the caller's filter holds
        assert ev.evaluate(src, processes=2, cache_dir=tmp_path / "c", **kw).rows == want
    assert "cache_dir" not in capfd.readouterr().err      # no worker printed it itself


def test_a_full_disk_leaves_the_previous_reports_whole(files, tmp_path, monkeypatch):
    """A full disk at the third report: the reports had been written one by one after the
    previous run's others were removed, so the folder held two new files, the previous
    run's rest and its list: the set of two runs. Now every file is written to a temporary
    first and nothing is renamed until all are: the error names the file, the folder is the
    previous run's, byte for byte, and no temporary file stays (H126)."""
    import errno
    import os

    from _support import disk_full_at

    kw = dict(metrics=("cfa_psnr",), patterns=("mask1",), progress=False, crop=0)
    first = ev.evaluate([rio.ImageSource("a", str(files / "small.png"))], processes=1,
                        methods=("bi", "sg"), **kw)
    second = ev.evaluate([rio.ImageSource("c", str(files / "small.png"))], processes=1,
                         methods=("bi",), **kw)
    out = tmp_path / "rep"
    ev.write_reports(first, out, plots=False)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    assert "table_a.md" in before
    fsync = os.fsync
    monkeypatch.setattr(os, "fsync", disk_full_at(3))
    with pytest.raises(OSError) as got:
        ev.write_reports(second, out, plots=False)
    assert got.value.errno == errno.ENOSPC and got.value.filename.startswith(str(out))
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    monkeypatch.setattr(os, "fsync", fsync)
    ev.write_reports(second, out, plots=False)              # the disk has room again
    names = {p.name for p in out.iterdir()}
    assert "table_c.md" in names and "table_a.md" not in names    # the previous run's gone
    assert (out / "results.csv").read_text() == second.to_csv()


def test_a_dask_workers_warnings_are_the_callers(files, tmp_path, capfd):
    """With a Dask scheduler the workers (other processes, two task threads each) printed an
    image's warnings themselves, in Python's format, past the caller's filters; they are
    recorded for each task's thread and the caller issues them again. A worker outlives a
    run: the next run warns of its own cache failures again (H125)."""
    import warnings

    distributed = pytest.importorskip("distributed")
    from rgbz_fast.evaluation import _cache

    kw = dict(metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",), progress=False,
              crop=0)
    src = [rio.ImageSource(n, str(files / "small.png")) for n in ("a", "b", "c")]
    want = ev.evaluate(src, processes=1, **kw).rows
    (tmp_path / "c").mkdir()
    for s in src:
        (tmp_path / "c" / _cache.cache_folder(s.name)).write_text("x")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        for _ in range(2):
            with warnings.catch_warnings(record=True) as got:
                warnings.simplefilter("always")
                assert ev.evaluate(src, scheduler=cluster.scheduler_address,
                                   cache_dir=tmp_path / "c", **kw).rows == want
            msgs = [str(w.message) for w in got if issubclass(w.category, RuntimeWarning)]
            assert len(msgs) == 1, msgs              # one cause, one worker process
            assert msgs[0].startswith("cache_dir: could not write"), msgs
        capfd.readouterr()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")             # the caller's filter holds
            assert ev.evaluate(src, scheduler=cluster.scheduler_address,
                               cache_dir=tmp_path / "c", **kw).rows == want
        assert "cache_dir" not in capfd.readouterr().err   # no worker printed it itself


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="SIGKILL of a worker: POSIX")
def test_a_worker_killed_from_outside_is_one_error_naming_processes(files, tmp_path):
    """A worker process ended by SIGKILL (the out-of-memory killer's signal) broke the pool:
    `rgbz-fast evaluate --processes 2` ended with concurrent.futures' traceback (exit 1).
    It is one error naming ``processes`` and the signal, the other worker stopped, no
    temporary file left; the command line prints it as its one error line (an OSError:
    exit 2)."""
    import multiprocessing

    from _support import KilledSource

    src = [rio.ImageSource("a", str(files / "small.png")),
           KilledSource("b", str(files / "small.png"))]
    with pytest.raises(ChildProcessError,
                       match=r"^processes: a worker process was ended by signal 9 \(SIGKILL\)"):
        ev.evaluate(src, metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",),
                    progress=False, processes=2, crop=0, cache_dir=tmp_path / "c")
    assert not [p for p in tmp_path.rglob("*") if p.name.endswith(".tmp")]
    assert multiprocessing.active_children() == []        # the other worker stopped too


def _cache_files(cache):
    return sorted(p for p in Path(cache).rglob("*") if p.is_file())


def test_killed_evaluate_resumes_from_its_cache(tmp_path):
    """SIGKILL `rgbz-fast evaluate` once its first cache file exists; the rerun resumes.

    Nothing visible is ever half-written: every cache file of the killed run parses,
    temporary files are hidden (".name.XXXX.tmp") and never carry a final name, and
    the reports are either absent or complete. The resumed run reuses every cached
    result (the files are not rewritten) and gives the numbers of a fresh run.
    """
    import imageio.v3 as iio

    ds = tmp_path / "ds"
    ds.mkdir()
    rng = np.random.default_rng(0)
    for i in range(4):
        img = rng.integers(0, 256, (96, 128, 3), dtype=np.uint8)
        iio.imwrite(ds / f"img{i}.png", img)
    out, cache = tmp_path / "out", tmp_path / "cache"
    argv = [sys.executable, "-m", "rgbz_fast", "evaluate", "--dataset", str(ds), "--out",
            str(out), "--cache", str(cache), "--processes", "1", "--quiet", "--no-plots",
            "--metrics", "cfa_psnr,cpsnr", "--methods", "bilinear,bi,edi_central,edi_line,sg",
            "--patterns", "mask1,mask2"]
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 300
    visible = []
    while time.monotonic() < deadline and proc.poll() is None:
        visible = [p for p in _cache_files(cache) if not p.name.startswith(".")]
        if visible:
            break
        time.sleep(0.005)
    assert proc.poll() is None, "evaluate finished before it could be killed"
    assert visible, "no cache file appeared"
    proc.send_signal(signal.SIGKILL)
    proc.communicate(timeout=60)
    assert proc.returncode == -signal.SIGKILL

    # nothing half-written under a final name
    survivors = _cache_files(cache)
    finals = [p for p in survivors if not p.name.startswith(".")]
    assert finals
    for p in finals:
        assert p.suffix == ".json" and isinstance(json.loads(p.read_text()), dict), p
    for p in survivors:
        if p.name.startswith("."):
            assert p.name.endswith(".tmp"), p
    for p in _cache_files(out) if out.exists() else []:
        if p.suffix == ".json" and p.parent == out:
            json.loads(p.read_text())
    mtimes = {p: p.stat().st_mtime_ns for p in finals}

    # resume: the rerun finishes, reuses the cached results and equals a fresh run
    r = subprocess.run(argv + ["--json"], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr[-3000:]
    resumed = json.loads(r.stdout)
    for p, t in mtimes.items():
        assert p.stat().st_mtime_ns == t, f"{p} was recomputed"
    fresh = ev.evaluate(rio.folder_dataset(ds), ev.EvalConfig(
        patterns=("mask1", "mask2"), methods=("bilinear", "bi", "edi_central", "edi_line", "sg"),
        metrics=("cfa_psnr", "cpsnr")), workers=1, progress=False)
    for (p, m, k), (mean, _, n) in fresh.summary().items():
        got = resumed[f"{p}/{m}/{k}"]
        assert got["n"] == n and got["mean"] == pytest.approx(mean, rel=1e-12), (p, m, k)
    reports = sorted(q.name for q in out.iterdir() if q.is_file())
    assert {"results.csv", "results.json", "summary.md"} <= set(reports)
    assert not [q for q in out.iterdir() if q.name.endswith(".tmp")]


def _children(pid):
    """Live (non-zombie) processes whose parent is ``pid``, from /proc."""
    out = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            fields = stat.rsplit(")", 1)[1].split()
            if int(fields[1]) == pid and fields[0] != "Z":
                out.append(int(entry.name))
    return out


def _cmdline(pid):
    try:
        return Path(f"/proc/{pid}/cmdline").read_text()
    except OSError:                                      # it has just ended
        return ""


def _alive(pid):
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


def _stop_a_running_pool(tmp_path, stop, pool="processes", hangup_ignored=False):
    """Start `rgbz-fast evaluate --processes 2` (``pool="threads"``: the default pool of
    threads) in a session of its own, call ``stop(proc)`` once the pool runs and the cache
    has an entry; (return code, stderr, seconds from the signal to the exit, the worker
    processes, the cache folder)."""
    import imageio.v3 as iio

    ds = tmp_path / "ds"
    ds.mkdir()
    rng = np.random.default_rng(1)
    for i in range(6):
        iio.imwrite(ds / f"img{i}.png", rng.integers(0, 256, (256, 320, 3), dtype=np.uint8))
    cache = tmp_path / "cache"
    argv = [sys.executable, "-m", "rgbz_fast", "evaluate", "--dataset", str(ds), "--out",
            str(tmp_path / "out"), "--cache", str(cache), "--quiet", "--no-plots"]
    argv += ["--processes", "2"] if pool == "processes" else []
    # SIGINT as a terminal gives it: a shell starts a background job (`pytest ... &`) with
    # SIGINT ignored, the child inherits that, and Ctrl-C rightly did nothing (exit 0)
    # (hangup_ignored: started as nohup starts a command)
    def dispositions():
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        signal.signal(signal.SIGHUP, signal.SIG_IGN if hangup_ignored else signal.SIG_DFL)

    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, preexec_fn=dispositions)
    deadline = time.monotonic() + 300
    workers = []
    while time.monotonic() < deadline and proc.poll() is None:
        workers = [c for c in _children(proc.pid) if "multiprocessing" in _cmdline(c)]
        if len(workers) >= 2 * (pool == "processes") and list(cache.rglob("*.json")):
            break
        time.sleep(0.02)
    assert proc.poll() is None and list(cache.rglob("*.json")), "the pool never ran"
    t0 = time.monotonic()
    stop(proc)
    _, err = proc.communicate(timeout=120)
    return proc.returncode, err, time.monotonic() - t0, workers, cache


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc: Linux")
@pytest.mark.parametrize("how", ["sigterm", "ctrl-c", "hangup"])
def test_a_stopped_evaluation_pool_ends_at_once_and_cleans_up(tmp_path, how):
    """SIGTERM to `rgbz-fast evaluate --processes 2`, or Ctrl-C to its process group, stops
    the pool's workers before the process exits (143, 130): no worker outlives the run, no
    temporary cache file is left, and no worker has to be killed (evaluate warns when one
    did not stop within 10 s of its SIGTERM). The workers used to catch the signal as a
    failed image and go on to the next (10-20 s, then SIGKILL, temporary files left)."""
    import os

    def stop(proc):
        if how == "sigterm":
            proc.send_signal(signal.SIGTERM)
        else:                                    # as a terminal does: the process group
            os.killpg(proc.pid, signal.SIGHUP if how == "hangup" else signal.SIGINT)

    code, err, seconds, workers, cache = _stop_a_running_pool(tmp_path, stop)
    assert len(workers) >= 2, "the pool's processes were never seen"
    want = {"sigterm": (128 + signal.SIGTERM, "terminated"), "ctrl-c": (130, "interrupted"),
            "hangup": (128 + signal.SIGHUP, "terminated (hangup)")}[how]
    assert code == want[0], err[-2000:]
    assert err.strip().splitlines()[-1] == f"rgbz-fast evaluate: {want[1]}"
    assert "were killed" not in err, f"the workers did not stop by themselves ({seconds:.1f} s)"
    assert "Traceback" not in err, err[-2000:]        # nor the pool's resource tracker died
    time.sleep(0.5)
    assert not [w for w in workers if _alive(w)], "orphaned worker processes"
    assert not [p for p in cache.rglob("*") if p.name.endswith(".tmp")]


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc: Linux")
@pytest.mark.parametrize("how", ["sigterm", "ctrl-c", "hangup"])
def test_a_stopped_thread_pool_ends_its_images_and_cleans_up(tmp_path, how):
    """SIGTERM to `rgbz-fast evaluate` (its default pool of threads), or Ctrl-C to its
    process group: the threads end their images at the next (pattern, method), the command
    exits 143 or 130 with its one line, leaves no temporary cache file, and every cache entry
    it wrote is whole (the next run reads it)."""
    import os

    def stop(proc):
        if how == "sigterm":
            proc.send_signal(signal.SIGTERM)
        else:                                    # as a terminal does: the process group
            os.killpg(proc.pid, signal.SIGHUP if how == "hangup" else signal.SIGINT)

    code, err, seconds, workers, cache = _stop_a_running_pool(tmp_path, stop, "threads")
    assert workers == [], "the default pool started processes"
    want = {"sigterm": (128 + signal.SIGTERM, "terminated"), "ctrl-c": (130, "interrupted"),
            "hangup": (128 + signal.SIGHUP, "terminated (hangup)")}[how]
    assert code == want[0], err[-2000:]
    assert err.strip().splitlines()[-1] == f"rgbz-fast evaluate: {want[1]}"
    assert not [p for p in cache.rglob("*") if p.name.endswith(".tmp")]
    for entry in cache.rglob("*.json"):
        assert set(json.loads(entry.read_text())) == {"check", "values"}, entry


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc: Linux")
def test_a_hangup_leaves_a_nohup_run_running(tmp_path):
    """Started with SIGHUP ignored (`nohup rgbz-fast evaluate --processes 2 ...`), a closed
    terminal's SIGHUP to the process group changes nothing: the command does not take
    SIGHUP over, its workers ignore it as their parent does, and the run ends with its
    reports (exit 0)."""
    import os

    def hang_up(proc):
        os.killpg(proc.pid, signal.SIGHUP)

    code, err, seconds, workers, cache = _stop_a_running_pool(tmp_path, hang_up,
                                                              hangup_ignored=True)
    assert len(workers) >= 2, "the pool's processes were never seen"
    assert code == 0, err[-2000:]
    assert (tmp_path / "out" / "results.csv").is_file()


REPORT_LOOP = textwrap.dedent("""
    import sys
    from pathlib import Path
    from rgbz_fast import evaluation as ev
    rows = [{"image": f"img{i}", "pattern": p, "method": m, "metric": k, "value": i * 0.5}
            for i in range(60) for p in ("mask1", "mask2")
            for m in ("bilinear", "bi", "edi_central", "edi_line", "sg")
            for k in ("cfa_psnr", "cpsnr", "ssim", "ms_ssim", "zipper")]
    res = ev.Results(rows, ev.EvalConfig())
    print("ready", flush=True)
    while True:
        ev.write_reports(res, Path(sys.argv[1]), plots=False)
""")


def test_reports_are_never_half_written_when_killed(tmp_path):
    """Kill a process that rewrites the reports in a loop, at several moments; every
    visible report is complete (CSV rows, JSON that parses, Markdown tables whole).

    Each file is all-or-nothing; the set is written file by file, so a kill between
    two files leaves the earlier ones new and the later ones from the previous run.
    """
    out = tmp_path / "reports"
    checked = 0
    for delay in (0.05, 0.37, 0.81):            # one round of reports takes ~0.35 s
        proc = subprocess.Popen([sys.executable, "-c", REPORT_LOOP, str(out)],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert proc.stdout.readline().strip() == "ready", proc.stderr.read()
        time.sleep(delay)
        proc.kill()
        proc.communicate(timeout=60)
        for p in (out.iterdir() if out.exists() else ()):
            if p.name.startswith("."):
                assert p.name.endswith(".tmp")      # a temporary file, never a final name
                continue
            text = p.read_text()
            checked += 1
            if p.name == "results.csv":
                assert len(text.splitlines()) == 1 + 60 * 2 * 5 * 5 and text.endswith("\n")
            elif p.name == "results.json":
                assert len(json.loads(text)["rows"]) == 60 * 2 * 5 * 5
            elif p.name == "summary.md":
                # per mask: the means table and the paired differences to bilinear
                assert text.endswith("\n") and text.count("| SG |") == 4, text[-200:]
            elif p.suffix == ".md":
                assert text.endswith("\n") and text.count("| Zipper (%) |") == 2, text[-200:]
    assert checked >= 4, "the reports were never written before the kills"


def _group(pgid):
    """The live processes of process group ``pgid``."""
    out = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[2]) == pgid and fields[0] != "Z":
                out.append(int(entry.name))
    return out


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc: Linux")
def test_a_pooled_evaluation_leaves_no_process_behind(tmp_path):
    """`rgbz-fast evaluate --processes 2` in a session of its own: once it has exited,
    nothing of its process group runs (the spawned pool's resource tracker used to outlive
    it)."""
    argv = [sys.executable, "-m", "rgbz_fast", "evaluate", "--limit", "2", "--processes", "2",
            "--metrics", "cfa_psnr", "--methods", "bilinear", "--patterns", "mask1",
            "--no-cache", "--no-plots", "--quiet", "--out", str(tmp_path / "out")]
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    _, err = proc.communicate(timeout=300)
    assert proc.returncode == 0, err[-2000:]
    assert _group(proc.pid) == [], "processes left behind"
