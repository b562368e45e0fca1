"""Dataset evaluation: tidy results, caching and resume, atomic files, reports, Dask."""

import json
import math
import sys

import numpy as np
import pytest

from _support import shared_path  # noqa: E402

import rgbz_fast as rz
from rgbz_fast import evaluation as ev
from rgbz_fast import io as rio  # noqa: E402


@pytest.fixture
def tiny_dataset(tmp_path):
    """Three small RGB images written to a folder (crops of scikit-image's samples)."""
    import imageio.v3 as iio
    import skimage.data

    folder = tmp_path / "imgs"
    folder.mkdir()
    for name, img in (("astro", skimage.data.astronaut()[100:292, 100:292]),
                      ("coffee", skimage.data.coffee()[50:242, 200:392]),
                      ("cat", skimage.data.chelsea()[40:232, 100:292])):
        iio.imwrite(folder / f"{name}.png", img)
    return folder


FAST = dict(patterns=("mask1", "mask2"), methods=("bilinear", "sg"),
            metrics=("cfa_psnr", "cpsnr", "ssim", "ms_ssim", "zipper"))


def test_evaluate_rows_and_summary(tiny_dataset):
    res = ev.evaluate(rio.folder_dataset(tiny_dataset), processes=1, progress=False, **FAST)
    assert len(res) == 3 * 2 * 2 * 5
    assert set(res.images()) == {"astro", "coffee", "cat"}
    s = res.summary()
    for p in FAST["patterns"]:
        for k in FAST["metrics"]:
            mean, std, n = s[(p, "sg", k)]
            assert n == 3 and np.isfinite(mean)
        # the semi-gradients beat the bilinear baseline on these images (CFA PSNR)
        assert s[(p, "sg", "cfa_psnr")][0] > s[(p, "bilinear", "cfa_psnr")][0]
    md = res.summary_markdown()
    assert "| SG |" in md and "**mask1**" in md
    assert "CFA PSNR" in res.plain_table()


def test_config_takes_keyword_overrides(tiny_dataset):
    """evaluate's parameter rule: ``config`` (an EvalConfig or a dict of its fields) with
    keyword overrides of its fields, the same run as the merged configuration."""
    ds = rio.folder_dataset(tiny_dataset)
    merged = ev.EvalConfig(patterns=("mask1",), methods=("sg",), metrics=("cfa_psnr",),
                           crop=2)
    want = ev.evaluate(ds, merged, processes=1, progress=False)
    got = ev.evaluate(ds, ev.EvalConfig(methods=("sg",), crop=2), patterns=("mask1",),
                      metrics=("cfa_psnr",), processes=1, progress=False)
    assert got.config == merged and got.rows == want.rows
    got = ev.evaluate(ds, {"methods": ("sg",), "crop": 2}, patterns="mask1",
                      metrics="cfa_psnr", processes=1, progress=False)
    assert got.config == merged and got.rows == want.rows


def test_cfa_psnr_only_runs_no_demosaic(tiny_dataset, monkeypatch):
    import rgbz_fast.isp as dm

    def boom(*a, **k):
        raise AssertionError("demosaic must not run for CFA PSNR alone")
    monkeypatch.setattr(dm, "demosaic", boom)
    res = ev.evaluate(rio.folder_dataset(tiny_dataset), processes=1, progress=False,
                      metrics=("cfa_psnr",), methods=("sg",))
    assert len(res) == 3 * 2


def test_cache_resume_and_one_more_method(tiny_dataset, tmp_path, monkeypatch):
    cache = tmp_path / "cache"
    ds = rio.folder_dataset(tiny_dataset)
    first = ev.evaluate(ds, cache_dir=cache, processes=1, progress=False,
                        metrics=("cfa_psnr",), methods=("bilinear",))
    files = sorted(cache.rglob("*.json"))
    assert len(files) == 3 * 2
    calls = []
    import rgbz_fast.evaluation._run as mod
    real = mod.reconstruct
    monkeypatch.setattr(mod, "reconstruct", lambda f, m, **k: calls.append(m) or real(f, m, **k))
    second = ev.evaluate(ds, cache_dir=cache, processes=1, progress=False,
                         metrics=("cfa_psnr",), methods=("bilinear", "edi_line"))
    assert calls and set(calls) == {"edi_line"}            # only the new method ran
    assert np.array_equal(second.values("mask1", "bilinear", "cfa_psnr"),
                          first.values("mask1", "bilinear", "cfa_psnr"))
    assert not list(cache.rglob("*.tmp"))
    # H85: the rows in the run's order, as a clean run's (the cached ones had come first)
    clean = ev.evaluate(ds, processes=1, progress=False, metrics=("cfa_psnr",),
                        methods=("bi", "edi_line", "bilinear"))
    third = ev.evaluate(ds, cache_dir=cache, processes=1, progress=False,
                        metrics=("cfa_psnr",), methods=("bi", "edi_line", "bilinear"))
    assert third.to_csv() == clean.to_csv()


def test_cached_results_carry_the_code_that_computed_them(tiny_dataset, tmp_path,
                                                          monkeypatch):
    """H85: the cache's version was the package's (0.1.0 on every commit), so after the
    shipped z_guided filters were refitted (or a kernel changed) a cached evaluation served
    the old numbers. The key now holds a digest of the package's modules, shipped filters and
    extension modules: another digest recomputes."""
    from rgbz_fast import _build_config
    from rgbz_fast.evaluation import _cache

    version = _cache.results_version()
    assert version.startswith(_build_config.VERSION + "+") and len(version.split("+")[1]) == 12
    cache = tmp_path / "cache"
    ds = rio.folder_dataset(tiny_dataset)
    kw = dict(cache_dir=cache, processes=1, progress=False, metrics=("cfa_psnr",),
              methods=("bilinear",))
    ev.evaluate(ds, **kw)
    calls = []
    import rgbz_fast.evaluation._run as mod
    real = mod.reconstruct
    monkeypatch.setattr(mod, "reconstruct", lambda f, m, **k: calls.append(m) or real(f, m, **k))
    ev.evaluate(ds, **kw)
    assert calls == []                                     # the same code: served
    monkeypatch.setattr(_cache, "_REVISION", [_build_config.VERSION + "+000000000000"])
    ev.evaluate(ds, **kw)
    assert len(calls) == 3 * 2                             # another: every entry recomputed


def test_interrupted_run_resumes(tiny_dataset, tmp_path, monkeypatch):
    """A run killed after its first image leaves complete cache files; the re-run reuses them."""
    cache = tmp_path / "cache"
    ds = rio.folder_dataset(tiny_dataset)
    import rgbz_fast.evaluation._run as mod
    real = mod._evaluate_image
    seen = []

    def dying(source, *a, **k):
        if seen:
            raise KeyboardInterrupt
        seen.append(source.name)
        return real(source, *a, **k)
    monkeypatch.setattr(mod, "_evaluate_image", dying)
    with pytest.raises(KeyboardInterrupt):
        ev.evaluate(ds, cache_dir=cache, processes=1, progress=False, metrics=("cfa_psnr",),
                    methods=("sg",))
    monkeypatch.setattr(mod, "_evaluate_image", real)
    done = {p.parent.name for p in cache.rglob("*.json")}
    assert done == {mod.cache_folder(n) for n in seen}
    full = ev.evaluate(ds, cache_dir=cache, processes=1, progress=False, metrics=("cfa_psnr",),
                       methods=("sg",))
    fresh = ev.evaluate(ds, processes=1, progress=False, metrics=("cfa_psnr",), methods=("sg",))
    assert full.rows == fresh.rows


def test_atomic_write_never_leaves_partial_files(tmp_path):
    target = tmp_path / "out.txt"
    rio.atomic_write(target, "old")

    with pytest.raises(TypeError):
        rio.atomic_write(target, 123)            # write fails: the old file stays
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["out.txt"]


def test_thread_and_process_pools_equal_serial(tiny_dataset, monkeypatch):
    """The default pool (threads of this process, as many as cores) and a pool of spawned
    processes give the serial run's rows, in its order."""
    import os
    import threading

    from rgbz_fast.evaluation import _run

    monkeypatch.setattr(os, "cpu_count", lambda: 2)        # a pool even on one core
    seen = []
    task = _run._pool_task
    monkeypatch.setattr(_run, "_pool_task", lambda *a: seen.append(
        threading.current_thread().name) or task(*a))
    ds = rio.folder_dataset(tiny_dataset)
    kw = dict(progress=False, metrics=("cfa_psnr", "cpsnr", "ssim", "zipper"),
              methods=("bi", "sg"))
    serial = ev.evaluate(ds, processes=1, **kw).rows
    seen.clear()
    assert ev.evaluate(ds, **kw).rows == serial
    assert len(seen) == 3 and all(n.startswith("rgbz-evaluate") for n in seen), seen
    monkeypatch.setattr(_run, "_pool_task", task)          # the processes import it by name
    assert ev.evaluate(ds, processes=2, **kw).rows == serial


def _pool_threads():
    import threading
    return [t for t in threading.enumerate() if t.name.startswith("rgbz-evaluate")]


def test_thread_pool_stops_at_a_bad_image_and_leaves_no_thread(tiny_dataset, monkeypatch):
    """A bad image in the thread pool stops the run with its error once every thread has
    ended; with ``skip_bad`` it is listed and the others give the serial rows."""
    import os

    monkeypatch.setattr(os, "cpu_count", lambda: 2)
    (tiny_dataset / "broken.png").write_bytes(b"\x89PNG\r\n\x1a\n not a png")
    ds = rio.folder_dataset(tiny_dataset)
    kw = dict(progress=False, metrics=("cfa_psnr",), methods=("sg",), patterns=("mask1",))
    with pytest.raises(ValueError, match="broken"):
        ev.evaluate(ds, **kw)
    assert _pool_threads() == []
    res = ev.evaluate(ds, skip_bad=True, **kw)
    assert [name for name, _ in res.skipped] == ["broken"]
    good = [s for s in ds if s.name != "broken"]
    assert res.rows == ev.evaluate(good, processes=1, **kw).rows


def test_thread_pool_tasks_see_the_callers_context(monkeypatch):
    """Each task of the thread pool runs in a copy of the caller's context: a context
    variable set around evaluate() (here the Mask1 fast-path switch) reaches the kernels."""
    from rgbz_fast.evaluation import _run
    from rgbz_fast.reconstruction import _reconstruct

    class Bar:
        def update(self):
            pass

    monkeypatch.setattr(_run, "_pool_task", lambda t, stop: [_reconstruct._FAST_PATH.get()])
    tasks = [(type("S", (), {"name": f"img{i}"})(),) for i in range(4)]
    token = _reconstruct._FAST_PATH.set(False)
    try:
        results = {}
        _run._run_threads(tasks, 2, Bar(), results)
    finally:
        _reconstruct._FAST_PATH.reset(token)
    assert results == {f"img{i}": [False] for i in range(4)}
    assert _pool_threads() == []


def test_a_stopped_image_ends_before_its_next_method(tiny_dataset, tmp_path):
    """A thread of the pool asked to stop ends its image before the next (pattern,
    method): nothing is computed or cached after the request."""
    import threading

    from rgbz_fast.evaluation import _run

    stop = threading.Event()
    stop.set()
    source = rio.folder_dataset(tiny_dataset)[0]
    with pytest.raises(_run._Stopped):
        _run._evaluate_image(source, ev.EvalConfig(methods=("sg",)), tmp_path / "cache", 1,
                             stop)
    assert not (tmp_path / "cache").exists() or not list((tmp_path / "cache").rglob("*"))


def test_dask_local_cluster_equals_local_run(tiny_dataset):
    distributed = pytest.importorskip("distributed")
    ds = rio.folder_dataset(tiny_dataset)
    kw = dict(progress=False, metrics=("cfa_psnr", "ssim"), methods=("edi_line", "sg"),
              patterns=("mask1",))
    local = ev.evaluate(ds, processes=1, **kw)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        remote = ev.evaluate(ds, scheduler=cluster.scheduler_address, **kw)
    assert remote.rows == local.rows


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="SIGKILL of a worker: POSIX")
def test_dask_workers_killed_by_an_image_is_one_error_naming_it(tiny_dataset):
    """Every Dask worker that ran an image died (here: by SIGKILL from the image's own load,
    as the out-of-memory killer ends one): Dask's KilledWorker ended the command with a
    traceback; it is one error naming ``scheduler`` and the image (H123)."""
    distributed = pytest.importorskip("distributed")
    from _support import KilledSource

    ds = rio.folder_dataset(tiny_dataset)[:1] + [KilledSource("killer",
                                                              str(tiny_dataset / "cat.png"))]
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        with pytest.raises(ChildProcessError,
                           match=r"^scheduler: the Dask workers that evaluated image 'killer' "
                                 r"died"):
            ev.evaluate(ds, scheduler=cluster.scheduler_address, progress=False,
                        metrics=("cfa_psnr",), methods=("bi",), patterns=("mask1",))


def test_reports_written(tiny_dataset, tmp_path):
    ds = rio.folder_dataset(tiny_dataset)
    res = ev.evaluate(ds, processes=1, progress=False, **FAST)
    files = ev.write_reports(res, tmp_path / "rep", crop_source=ds[0])
    names = {f.name for f in files}
    assert {"results.csv", "results.json", "summary.md", "table_astro.md",
            "bars_cfa_psnr.png", "bars_zipper.png", "paired_cfa_psnr.png", "paired_zipper.png",
            "crops_astro.png"} <= names
    assert "Paired differences to bilinear" in (tmp_path / "rep" / "summary.md").read_text()
    for f in files:
        if f.suffix == ".png":
            assert f.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and f.stat().st_size > 5000
    data = json.loads((tmp_path / "rep" / "results.json").read_text())
    assert len(data["rows"]) == len(res)
    csv = (tmp_path / "rep" / "results.csv").read_text().splitlines()
    assert csv[0] == "image,pattern,method,metric,value" and len(csv) == len(res) + 1


def test_noisy_evaluation_uses_same_noise_on_both_paths(tiny_dataset):
    ds = rio.folder_dataset(tiny_dataset)[:1]
    a = ev.evaluate(ds, processes=1, progress=False, noise=True, metrics=("cfa_psnr",),
                    methods=("sg",), seed=3)
    b = ev.evaluate(ds, processes=1, progress=False, noise=True, metrics=("cfa_psnr",),
                    methods=("sg",), seed=3)
    assert a.rows == b.rows
    clean = ev.evaluate(ds, processes=1, progress=False, metrics=("cfa_psnr",), methods=("sg",))
    assert a.rows != clean.rows


@pytest.mark.parametrize("needs_tof", [False, True])
def test_frames_of_the_sensor_model_take_the_bit_depth(needs_tof):
    """Noisy frames (and every frame of a run with z_guided) come from the sensor model at the
    configuration's bit depth: the default sensor's 11 bits had been used, while the report's
    header said 8-bit."""
    img = np.random.default_rng(0).integers(0, 256, (32, 32, 3), dtype=np.uint8)
    methods = ("sg", "z_guided") if needs_tof else ("sg",)
    for bits in (8, 12):
        cfg = ev.EvalConfig(noise=not needs_tof, bit_depth=bits, methods=methods)
        frame, ref = ev.image_frames(img, "mask1", cfg)
        assert frame.bit_depth == bits and ref.max() <= 2 ** bits - 1
        assert ref.max() > 2 ** (bits - 1)                  # the range is used


def test_noisy_keys_at_other_bit_depths_are_new():
    """The noisy frames of a bit depth other than 11 changed (they had been 11-bit), and then
    every noisy frame with the shot noise of H80 (``sim_revision``): their cache keys changed
    with them; noise-free runs keep theirs."""
    key = lambda **kw: ev.EvalConfig(**kw).key("mask1", "sg")          # noqa: E731
    import hashlib
    import json
    from dataclasses import asdict

    from rgbz_fast.evaluation._config import _cache_version

    def old_key(cfg):                      # the key before: without "sensor_bits"
        d = asdict(cfg)
        for k in ("patterns", "methods", "metrics", "linearise", "optics"):
            d.pop(k)
        params = d.pop("params")
        for k in ("clip_level", "filters", "fixed_point"):
            params.pop(k)
        d.update(params, pattern=str(rz.get_pattern("mask1")), method="sg",
                 version=_cache_version())
        return hashlib.sha1(json.dumps(d, sort_keys=True, default=str).encode()).hexdigest()[:16]

    for kw, same in ((dict(noise=True, bit_depth=11), False), (dict(bit_depth=8), True),
                     (dict(noise=True, bit_depth=8), False), (dict(), True)):
        assert (key(**kw) == old_key(ev.EvalConfig(**kw))) == same


def test_table3_with_paper_values(tmp_path):
    kodak = shared_path("kodak")
    ds = [s for s in rio.folder_dataset(kodak) if s.name == "kodim09"]
    res = ev.evaluate(ds, processes=1, progress=False, methods=("bi", "edi_central",
                                                              "edi_line", "sg"))
    md = res.image_markdown("kodim09")
    assert "(24.55)" in md and "(26.9)" in md and "(5.041)" in md


@pytest.mark.parametrize("kw, match", [
    (dict(methods=("nope",)), "^methods:"), (dict(metrics=("psnr",)), "^metrics:"),
    (dict(patterns=("mask7",)), "^pattern:"), (dict(demosaic="ahd"), "^demosaic:"),
    (dict(crop=-1), "^crop:"),
])
def test_bad_config(kw, match):
    with pytest.raises(ValueError, match=match):
        ev.EvalConfig(**kw)


def test_bad_dataset(tmp_path):
    with pytest.raises(ValueError, match="^dataset: .* does not exist"):
        rio.folder_dataset(tmp_path / "missing")
    with pytest.raises(ValueError, match="^dataset: no image files"):
        rio.folder_dataset(tmp_path)


def test_cache_follows_the_image_content_and_exact_name(tmp_path):
    """A changed image is recomputed (the key holds its SHA-256), and names that sanitise
    alike ("a b", "a_b") get separate cache folders."""
    import imageio.v3 as iio

    folder = tmp_path / "imgs"
    folder.mkdir()
    rng = np.random.default_rng(0)
    for name in ("a b.png", "a_b.png"):
        iio.imwrite(folder / name, rng.integers(0, 256, (32, 32, 3), dtype=np.uint8))
    kw = dict(cache_dir=tmp_path / "cache", processes=1, progress=False,
              metrics=("cfa_psnr",), methods=("sg",), patterns=("mask1",))
    first = ev.evaluate(rio.folder_dataset(folder), **kw)
    a, b = (first.values("mask1", "sg", "cfa_psnr"))
    assert a != b                                    # two images, two results
    assert len({p.parent for p in (tmp_path / "cache").rglob("*.json")}) == 2
    iio.imwrite(folder / "a b.png", np.full((32, 32, 3), 128, np.uint8))   # flat: exact
    second = ev.evaluate(rio.folder_dataset(folder), **kw)
    fresh = ev.evaluate(rio.folder_dataset(folder), processes=1, progress=False,
                        metrics=("cfa_psnr",), methods=("sg",), patterns=("mask1",))
    assert second.rows == fresh.rows and second.rows != first.rows
    assert second.values("mask1", "sg", "cfa_psnr")[0] == np.inf


def test_figures_show_every_error_bar_and_hide_nothing(tiny_dataset):
    """The y axis spans every whisker (no bar is cut off at the top), the legend sits
    outside the plot, and the paired chart shows each image's difference and zero."""
    from rgbz_fast.evaluation import _reports

    res = ev.evaluate(rio.folder_dataset(tiny_dataset), processes=1, progress=False, **FAST)
    s = res.summary()
    for k in FAST["metrics"]:
        fig = _reports._bar_figure(res, k)
        ax = fig.axes[0]
        lo, hi = ax.get_ylim()
        for (p, m, kk), (mean, std, _) in s.items():
            if kk == k:
                assert lo < mean - std and mean + std < hi, (p, m, k)
        fig.canvas.draw()
        legend = ax.get_legend().get_window_extent()
        assert legend.x0 >= ax.get_window_extent().x1            # beside, not over, the data
        fig = _reports._paired_figure(res, k)
        lo, hi = fig.axes[0].get_ylim()
        for p in FAST["patterns"]:
            diffs, mean, ci_lo, ci_hi = res.paired(p, "sg", k)
            assert diffs.size == 3 and lo < min(diffs.min(), ci_lo, 0) and \
                max(diffs.max(), ci_hi, 0) < hi
        import matplotlib.pyplot as plt
        plt.close("all")


def test_paired_differences_are_per_image():
    rows = [{"image": i, "pattern": "mask1", "method": m, "metric": "cpsnr", "value": v}
            for i, (a, b) in enumerate([(30.0, 31.0), (20.0, 21.2), (40.0, 40.8)])
            for m, v in (("bilinear", a), ("sg", b))]
    res = ev.Results(rows, ev.EvalConfig(methods=("bilinear", "sg"), metrics=("cpsnr",),
                                         patterns=("mask1",)))
    diffs, mean, lo, hi = res.paired("mask1", "sg", "cpsnr")
    np.testing.assert_allclose(diffs, [1.0, 1.2, 0.8])
    from scipy import stats
    half = stats.t.ppf(0.975, 2) * np.std([1.0, 1.2, 0.8], ddof=1) / np.sqrt(3)
    assert mean == pytest.approx(1.0) and (lo, hi) == pytest.approx((1 - half, 1 + half))
    assert lo > 0                     # sure, although the images spread over 20 dB


def test_t_quantiles_of_the_intervals_are_scipys():
    """The table of the paired intervals' t quantiles holds scipy.special.stdtrit's values
    (bit for bit with the scipy it was made with, within an ulp of a recent one), and the
    degrees of freedom beyond it ask scipy. 1 and 2 degrees of freedom have closed forms:
    the table holds them within an ulp whatever scipy is installed. An older scipy's
    stdtrit (1.10, the floor) is off by up to 4.1e-9 relative, 2e-11 at one degree of
    freedom: against such a scipy (told by its value at 1) the table is held within 1e-8."""
    from scipy.special import stdtrit

    from rgbz_fast.evaluation._results import _T975, _t975

    exact = {1: math.tan(math.pi * 0.475), 2: 0.95 * math.sqrt(2.0 / (1.0 - 0.95 ** 2))}
    for df, want in exact.items():
        assert _t975(df) == pytest.approx(want, rel=2.3e-16, abs=0), df
    accurate = float(stdtrit(1, 0.975)) == pytest.approx(exact[1], rel=2.3e-16, abs=0)
    for df in range(1, len(_T975) + 3):
        want = float(stdtrit(df, 0.975))
        assert _t975(df) == pytest.approx(want, rel=3e-16 if accurate else 1e-8, abs=0), df
    assert _t975(len(_T975) + 1) == float(stdtrit(len(_T975) + 1, 0.975))


@pytest.mark.parametrize("pattern", ["mask1", "mask2", "rows", "bayer", "ZR/BG", "ZZGR/ZZBG"])
@pytest.mark.parametrize("bit_depth", [8, 11])
def test_frames_are_the_mosaics_of_the_image(pattern, bit_depth):
    """The RGB-Z frame of an image is its pattern's mosaic (made from the reference CFA by
    clearing the Z sites), and the reference the mosaic of the pattern's Bayer."""
    img = np.random.default_rng(3).integers(0, 256, (40, 48, 3), dtype=np.uint8)
    frame, reference = ev.image_frames(img, pattern, ev.EvalConfig(bit_depth=bit_depth))
    lin = rz.simulation.srgb_to_linear(img / 255.0)
    want = rz.mosaic(lin, pattern, bit_depth)
    assert np.array_equal(frame.data, want.data) and frame.data.dtype == want.data.dtype
    assert frame.pattern == want.pattern and frame.bit_depth == bit_depth
    assert np.array_equal(reference, rz.mosaic(lin, want.pattern.bayer_pattern(),
                                               bit_depth).data)


# ------------------------------------------------------------------ raw files in the header

def test_the_header_says_when_every_method_ran_on_the_sensor_models_frames():
    """With z_guided in the methods every frame comes from the sensor model, and the other
    methods' scores move (bilinear on Mask2 by about 1.4 dB on astronaut): the header says so,
    a run without it does not."""
    with_z = ev.EvalConfig(methods=("bilinear", "sg", "z_guided"))
    assert ("noise-free, 11-bit, every method on the sensor model's frames (for z_guided's Z "
            "taps), demosaic") in with_z.label()
    assert "sensor model" not in ev.EvalConfig(methods=("bilinear", "sg")).label()


def test_the_header_says_which_images_were_raw_files():
    """The mosaic's noise and bit depth describe the RGB images alone: a raw file is measured
    at its own bit depth (a 14-bit DNG's table had said '11-bit')."""
    cfg = ev.EvalConfig(patterns=("mask1",), methods=("bi",), metrics=("cpsnr",))
    rows = [{"image": n, "pattern": "mask1", "method": "bi", "metric": "cpsnr", "value": 30.0}
            for n in ("chart", "kodim01", "kodim02")]
    mosaic = "noise-free, 11-bit, demosaic"
    assert ev.Results(rows, cfg).label().startswith(mosaic)
    mixed = ev.Results(rows, cfg, raw_images=["chart"])
    assert mixed.label().startswith("2 RGB images (noise-free, 11-bit) and 1 raw file at "
                                    "its own bit depth, noise and lens, demosaic")
    assert "2 RGB images (noise-free, 11-bit) and 1 raw file" in mixed.summary_markdown()
    assert "and 1 raw file" in mixed.plain_table()
    raw = ev.Results(rows[:1], cfg, raw_images=["chart", "skipped_one"])
    assert raw.label().startswith("raw file at its own bit depth, noise and lens, demosaic")
    back = ev.Results.from_json(mixed.to_json())
    assert back.raw_images == ["chart"] and back.label() == mixed.label()
    with pytest.raises(TypeError, match="raw_images"):
        ev.Results(rows, cfg, raw_images=[1])


def test_evaluate_lists_the_raw_files_it_read(tmp_path):
    """evaluate() records which sources were raw: a bare Bayer PNG read through raw_options."""
    pytest.importorskip("PIL")
    from PIL import Image

    rng = np.random.default_rng(3)
    bayer = (rng.random((64, 64)) * 4000 + 64).astype(np.uint16)
    Image.fromarray(bayer).save(tmp_path / "b.png")
    Image.fromarray((rng.random((64, 64, 3)) * 255).astype(np.uint8)).save(tmp_path / "c.png")
    opts = (("phase", "RGGB"), ("black_level", 64), ("white_level", 4095), ("bit_depth_in", 12))
    srcs = [rio.ImageSource("b", str(tmp_path / "b.png"), raw_options=opts, raw=True),
            rio.ImageSource("c", str(tmp_path / "c.png"))]
    res = ev.evaluate(srcs, ev.EvalConfig(patterns=("mask1",), methods=("bi",), metrics=("cpsnr",),
                                    crop=4))
    assert res.raw_images == ["b"]
    assert res.label().startswith("1 RGB image (noise-free, 11-bit) and 1 raw file")


def test_raw_options_naming_no_file_of_the_folder_are_warned_about(tmp_path):
    """A misspelt key's options apply to no file: said (a warning), not refused, since one
    options file may serve several folders (data/shared_raw_options.json); a dataset of one
    file of a folder takes a file shared by the folder without a word."""
    import imageio.v3 as iio

    iio.imwrite(tmp_path / "a.png", np.zeros((16, 16, 3), np.uint8))
    opts = {"A.png": {"phase": "RGGB"}, "sub/a.png": {"phase": "RGGB"}}
    with pytest.warns(UserWarning, match=r"^raw_options: 'A.png', 'sub/a.png' name no image "
                                         r"file of .*; their options apply to no file"):
        srcs = rio.folder_dataset(tmp_path, raw_options=opts)
    assert [s.is_raw for s in srcs] == [False]
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rio.folder_dataset(tmp_path / "a.png", raw_options=opts)


def test_the_lens_is_the_rgb_images_in_a_mixed_header():
    """--optics applies to the RGB images the evaluation mosaics, not to a raw file."""
    from rgbz_fast.simulation import Optics

    cfg = ev.EvalConfig(patterns=("mask1",), methods=("bi",), metrics=("cpsnr",),
                        optics=Optics())
    rows = [{"image": n, "pattern": "mask1", "method": "bi", "metric": "cpsnr", "value": 30.0}
            for n in ("chart", "kodim01")]
    label = ev.Results(rows, cfg, raw_images=["chart"]).label()
    assert label.startswith("1 RGB image (noise-free, 11-bit, optics f/2.8) and 1 raw file at "
                            "its own bit depth, noise and lens, demosaic")
    assert ev.Results(rows, cfg).label().endswith("optics f/2.8")


def test_reports_interrupted_while_made_leave_the_previous_run_whole(tiny_dataset, tmp_path,
                                                                     monkeypatch):
    """H85: write_reports wrote file by file and removed the previous run's files last, so a
    run interrupted while its figures were drawn left its tables beside the previous run's
    figures. Every report is now made before any is written."""
    import rgbz_fast.evaluation._reports as rep

    ds = rio.folder_dataset(tiny_dataset)
    kw = dict(processes=1, progress=False, metrics=("cfa_psnr",))
    first = ev.evaluate(ds, methods=("bi", "sg"), **kw)
    out = tmp_path / "rep"
    ev.write_reports(first, out)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    second = ev.evaluate(ds, methods=("edi_line", "bilinear"), **kw)
    monkeypatch.setattr(rep, "paired_chart", lambda *a, **k: (_ for _ in ()).throw(
        KeyboardInterrupt))
    with pytest.raises(KeyboardInterrupt):
        ev.write_reports(second, out)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
