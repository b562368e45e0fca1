"""The figures' text after the round-24 figure probe (PL01-PL10): what the tables say, the
figures say too (z_guided's leaking guide, n/a, left-out images, the settings), legends
explain what is drawn and nothing that is not, and long names do not run together. Checked
on the matplotlib objects (text, legend entries, counts), on tiny inputs."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import matplotlib

matplotlib.use("Agg")

from rgbz_fast._devtools import plots  # noqa: E402
from rgbz_fast.evaluation import EvalConfig, Results  # noqa: E402
from rgbz_fast.evaluation import _reports  # noqa: E402

TILE = "ZRGRGRGR/BGBGBGBG/GRGRZRGR/BGBGBGBG"


def _rows(values, estimated=()):
    """Rows of (image, pattern, method, metric, value); ``estimated``: the methods whose rows
    are marked "ir_estimated" (z_guided without a registered NIR image)."""
    out = []
    for i, p, m, k, v in values:
        row = {"image": i, "pattern": p, "method": m, "metric": k, "value": v}
        if m in estimated:
            row["ir_estimated"] = True
        out.append(row)
    return out


def _grid(patterns, methods, images=("a", "b", "c"), metric="cpsnr", skip=(), value=None):
    value = value or (lambda i, p, m: 30.0 + 2 * images.index(i) + methods.index(m))
    return [(i, p, m, metric, value(i, p, m)) for i in images for p in patterns for m in methods
            if (p, m) not in skip]


def _texts(fig):
    fig.canvas.draw()
    return [t.get_text() for t in fig.findobj(matplotlib.text.Text) if t.get_text()]


def _all_text(fig):
    return " ".join(_texts(fig)).lower()


def _legend_texts(fig):
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend()] + list(fig.legends)
    return [t.get_text() for lg in legends for t in lg.get_texts()]


def _overlaps(fig, texts):
    r = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(r) for t in texts if t.get_visible() and t.get_text()]
    return [(a, b) for n, a in enumerate(boxes) for b in boxes[n + 1:]
            if min(a.x1, b.x1) - max(a.x0, b.x0) > 1 and min(a.y1, b.y1) - max(a.y0, b.y0) > 1]


@pytest.fixture(autouse=True)
def _close_figures():
    """The figures the tests keep open, closed (pyplot warns of more than 20)."""
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


@pytest.fixture
def kept(monkeypatch):
    """The figures plots.py draws, kept as matplotlib objects (and still rendered)."""
    figs = []

    def keep(fig, **kwargs):
        fig.canvas.draw()
        figs.append(fig)
        return b""

    monkeypatch.setattr(plots, "_png", keep)
    return figs


# --------------------------------------------------------------------------- PL05
def _leaky_results():
    methods = ("bilinear", "sg", "z_guided")
    cfg = EvalConfig(patterns=("mask1",), methods=methods, metrics=("cpsnr",))
    return Results(_rows(_grid(("mask1",), methods), estimated=("z_guided",)), cfg)


@pytest.mark.parametrize("figure", [_reports._bar_figure, _reports._paired_figure])
def test_charts_mark_z_guided_on_an_estimated_nir(figure):
    res = _leaky_results()
    assert res.ir_estimated("mask1", "z_guided")
    fig = figure(res, "cpsnr")
    texts = _texts(fig)
    assert "z_guided*" in texts                    # the legend entry or the tick label
    assert "z_guided" not in texts                 # never unmarked
    note = [t for t in texts if t.startswith("* z_guided:")]
    assert len(note) == 1 and "estimated from the RGB on 3 of 3 images" in note[0] \
        and "leaks the answer" in note[0].replace("\n", " ")


def test_charts_of_measured_nir_have_no_mark():
    methods = ("bilinear", "z_guided")
    res = Results(_rows(_grid(("mask1",), methods)),
                  EvalConfig(patterns=("mask1",), methods=methods, metrics=("cpsnr",)))
    for fig in (_reports._bar_figure(res, "cpsnr"), _reports._paired_figure(res, "cpsnr")):
        text = _all_text(fig)
        assert "z_guided*" not in text and "leaks" not in text


def test_crop_figure_marks_z_guided_on_an_estimated_nir_only(tmp_path, monkeypatch):
    import imageio.v3 as iio

    from rgbz_fast.io import ImageSource

    figs = []
    monkeypatch.setattr(_reports, "_figure_png",
                        lambda fig, metadata=None: (figs.append(fig), b"")[-1])
    rng = np.random.default_rng(0)
    iio.imwrite(tmp_path / "a.png", rng.integers(0, 256, (32, 48, 3), dtype=np.uint8))
    iio.imwrite(tmp_path / "a_nir.png", rng.integers(0, 256, (32, 48), dtype=np.uint8))
    cfg = EvalConfig(patterns=("mask1",), methods=("bilinear", "z_guided"), metrics=("cpsnr",))
    _reports.crop_figure(ImageSource("a", str(tmp_path / "a.png")), cfg, box=(8, 8, 16, 16))
    _reports.crop_figure(ImageSource("a", str(tmp_path / "a.png"),
                                     nir=str(tmp_path / "a_nir.png")), cfg, box=(8, 8, 16, 16))
    estimated, measured = (_texts(f) for f in figs)
    assert "mask1: z_guided*" in estimated
    assert any(t.startswith("* z_guided: NIR estimated") for t in estimated)
    # a registered NIR image is the guide, as in the evaluation: nothing to mark
    assert "mask1: z_guided" in measured
    assert not any("leaks" in t for t in measured)


def _tradeoff_res(methods=("sg", "z_guided"), pareto=None, quick=True, estimated=("k1",)):
    rows = []
    for p in ("mask1",):
        for n, m in enumerate(methods):
            for j, prec in enumerate(("float64", "float32")):
                rows.append({"pattern": p, "method": m, "precision": prec, "exp": "libm",
                             "domain": "intensity", "cfa_psnr": 30.0 + n + j,
                             "mpix_s": 10.0 * (1 + n + j), "mpix_s_lo": 5.0 * (1 + n + j),
                             "mpix_s_hi": 8.0 * (1 + n + j),
                             "pareto": None if pareto is None else pareto(n, j)})
    return {"rows": rows, "repeat": 2, "workers": 1, "threads_used": 1, "speed_frame": [64, 96],
            "dataset": "data", "images": ["k1", "k2"], "quick": quick,
            "ir_estimated": list(estimated)}


def test_tradeoff_figure_marks_z_guided_on_an_estimated_nir():
    fig = plots.tradeoff_figure(_tradeoff_res())
    assert "z_guided*" in _legend_texts(fig)
    assert any(t.startswith("* z_guided: the NIR was estimated from the RGB on 1 of 2")
               for t in _texts(fig))
    fig = plots.tradeoff_figure(_tradeoff_res(estimated=()))
    assert "z_guided" in _legend_texts(fig) and "leaks" not in _all_text(fig)


# --------------------------------------------------------------------------- PL10
def test_paired_chart_counts_the_dots_it_draws_and_says_what_is_left_out():
    def value(i, p, m):
        return math.inf if i == "flat" else (20.0 if m == "bilinear" else 21.0 + len(i))

    methods = ("bilinear", "sg")
    res = Results(_rows(_grid(("mask1",), methods, images=("flat", "a", "bb"), value=value)),
                  EvalConfig(patterns=("mask1",), methods=methods, metrics=("cpsnr",)))
    fig = _reports._paired_figure(res, "cpsnr")
    fig.canvas.draw()
    dots = sum(len(line.get_xdata()) for line in fig.axes[0].get_lines()
               if line.get_marker() == ".")
    title = fig._suptitle.get_text()
    assert dots == 2
    assert "dots = images (2 of 3" in title and "images (3)" not in title
    note = [t for t in _texts(fig) if t.startswith("Left out:")]
    assert len(note) == 1 and "SG on mask1: 1 of 3 images" in note[0]
    assert "+inf" in note[0]


def test_paired_chart_of_complete_images_keeps_the_plain_count():
    methods = ("bilinear", "sg")
    res = Results(_rows(_grid(("mask1",), methods)),
                  EvalConfig(patterns=("mask1",), methods=methods, metrics=("cpsnr",)))
    fig = _reports._paired_figure(res, "cpsnr")
    assert "dots = images (3)," in fig._suptitle.get_text()
    assert not any(t.startswith("Left out:") for t in _texts(fig))


# --------------------------------------------------------------------------- PL02
def _sweep_rows():
    rows = []
    for label, bits, within, meets, pareto in (
            ("default", 4368, 100.0, True, False), ("recip_table_size=16", 3922, 100.0, True, True),
            ("weight_bits=13", 4370, 100.0, True, False), ("recip_bits=10", 4101, 99.87, False,
                                                          False),
            ("recip_table_size=8", 3700, 99.2, False, True),
            ("exp=table", 3106, 66.0, False, True)):
        rows.append({"label": label, "bits": {"tables": bits // 3, "datapath": bits - bits // 3},
                     "within_1lsb_pct": within, "meets_target": meets, "pareto": pareto,
                     "error": {"linear": {"images": 2, "within_1lsb_pct": within}}})
    return rows + [{"label": "broken", "error": "too wide"}]


def test_hardware_sweep_plot_labels_legend_exact_rows_and_title(kept):
    plots.hardware_sweep_plot(_sweep_rows(), "sg on mask1", dataset="kodak")
    (fig,) = kept
    ax = fig.axes[0]
    labels = [t for t in ax.texts if t.get_text()]
    assert {t.get_text() for t in labels} == {"default", "recip_table_size=16",
                                              "recip_table_size=8", "exp=table"}
    assert not _overlaps(fig, labels)                           # (a) no smear
    legend = _legend_texts(fig)
    assert {"meets the target", "misses the target", "Pareto front (labelled)"} <= set(legend)
    assert any(t.startswith("target:") for t in legend)
    assert any(t.startswith("0 %: exact") for t in legend)      # (b) the floor said
    # the exact rows drawn as triangles, the others as dots
    markers = [c.get_paths()[0].vertices.shape[0] for c in ax.collections]
    assert len(set(markers)) == 2
    assert ax.get_title() == "sg on mask1, dataset kodak, 2 images"
    # the refused configuration has no point: the figure names it (it had said nothing)
    assert any(t.startswith("Not drawn: 1 configuration the model refused (broken;")
               for t in _texts(fig))


# --------------------------------------------------------------------------- PL06
@pytest.mark.parametrize("figure", [_reports._bar_figure, _reports._paired_figure])
def test_charts_write_n_a_where_a_method_does_not_apply(figure):
    patterns, methods = ("mask1", "rows"), ("bilinear", "sg", "learned")
    cfg = EvalConfig(patterns=patterns, methods=methods, metrics=("cpsnr",))
    assert not cfg.applies("rows", "learned")
    res = Results(_rows(_grid(patterns, methods, skip={("rows", "learned")})), cfg)
    texts = _texts(figure(res, "cpsnr"))
    assert texts.count("n/a") == 1
    note = [t for t in texts if t.startswith("n/a: ")]
    assert len(note) == 1 and "learned on rows" in note[0]


# --------------------------------------------------------------------------- PL04
def test_full_depth_preview_says_what_grey_is(kept):
    depth = np.full((20, 30), 1.5)
    depth[:4] = np.nan
    plots.full_depth_preview(depth, "full")
    plots.full_depth_preview(np.full((20, 30), 1.5), "full")
    with_nan, without = kept
    assert _legend_texts(with_nan) == ["no depth (NaN, 20.0 %)"]
    assert without.axes[0].get_legend() is None


def test_depth_command_gives_both_previews_one_colour_scale(tmp_path, monkeypatch):
    from rgbz_fast._cli import main
    from rgbz_fast.io import save_frame
    from rgbz_fast.simulation import Scene, simulate

    rng = np.random.default_rng(3)
    shape = (32, 48)
    depth = np.where(np.arange(shape[1])[None, :] < 24, 1.2, 1.9) * np.ones((shape[0], 1))
    path = save_frame(tmp_path / "f.npz", simulate(Scene(rng.random(shape + (3,)), depth=depth),
                                                   "mask1", seed=1))
    scales = {}
    for name in ("depth_preview", "full_depth_preview"):
        real = getattr(plots, name)

        def spy(arr, title, scale=None, *a, _real=real, _name=name, **k):
            scales[_name] = scale
            return _real(arr, title, scale, *a, **k)
        monkeypatch.setattr(plots, name, spy)
    assert main(["depth", str(path), "--full-resolution", "--out", str(tmp_path / "o"),
                 "--quiet"]) == 0
    assert scales["depth_preview"] is not None
    assert scales["depth_preview"] == scales["full_depth_preview"]
    # --range is both previews' scale as given
    assert main(["depth", str(path), "--full-resolution", "--range", "1:2", "--out",
                 str(tmp_path / "r"), "--quiet"]) == 0
    assert tuple(scales["depth_preview"]) == tuple(scales["full_depth_preview"]) == (1.0, 2.0)


# --------------------------------------------------------------------------- PL03
def test_tradeoff_legend_explains_the_iqr_line_and_no_front_of_a_quick_run():
    fig = plots.tradeoff_figure(_tradeoff_res(estimated=()))
    legend = _legend_texts(fig)
    assert any("IQR of the timed runs" in t and "best run" in t for t in legend)
    assert not any("pareto" in t.lower() or "ringed" in t for t in legend)
    fig = plots.tradeoff_figure(_tradeoff_res(estimated=(), quick=False,
                                              pareto=lambda n, j: n == j))
    assert {"Pareto front", "ringed, dashed"} <= set(_legend_texts(fig))


# --------------------------------------------------------------------------- PL09
def test_shares_as_the_summary_writes_them():
    assert plots.share_text(4, 12288) == "< 0.1 %"
    assert plots.share_text(12284, 12288) == "> 99.9 %"
    assert plots.share_text(12288, 12288) == "100 %"
    assert plots.share_text(0, 12288) == "0 %"
    assert plots.share_text(1053, 10000) == "10.5 %"


def test_flags_legend_never_says_zero_of_a_drawn_category(kept):
    from rgbz_fast import tof
    from rgbz_fast.simulation import Scene, simulate

    rng = np.random.default_rng(2)
    frame = simulate(Scene(rng.random((128, 192, 3)), depth=np.full((128, 192), 1.5)),
                     "mask1", seed=1)
    res = tof.tof_depth(frame.tof)
    assert res.n_sites > 2000                  # one site is below 0.05 %
    flags = np.zeros(res.n_sites, np.int64)
    flags[0] = tof.FLAG_SATURATED | tof.FLAG_LOW_SIGNAL       # one of many: several reasons
    res = dataclasses.replace(res, flags=flags)
    plots.depth_flags_figure(res, "flags")
    legend = _legend_texts(kept[0])
    assert legend == ["valid (> 99.9 %)", "several reasons (< 0.1 %)"], legend


# --------------------------------------------------------------------------- PL08
def test_charts_say_the_settings_of_the_run():
    methods = ("bilinear", "sg")
    texts = {}
    for noise in (True, False):
        cfg = EvalConfig(patterns=("mask1",), methods=methods, metrics=("cpsnr",), noise=noise)
        res = Results(_rows(_grid(("mask1",), methods)), cfg)
        label = res.label()
        for kind, fig in (("bars", _reports._bar_figure(res, "cpsnr")),
                          ("paired", _reports._paired_figure(res, "cpsnr"))):
            text = " ".join(_texts(fig)).replace("\n", " ")
            assert label in text, (kind, label)
            texts[(kind, noise)] = text
    assert texts[("bars", True)] != texts[("bars", False)]
    assert texts[("paired", True)] != texts[("paired", False)]


# --------------------------------------------------------------------------- PL07
def test_pattern_study_legend_does_not_repeat_a_cost(kept):
    rows = [{"layout": name, "method": "bilinear", "best": True, "cpsnr": c, "wall_sigma_mm": w,
             "ops_per_pixel": 1.8, "tile": "RG/GB"}
            for name, c, w in (("mask1", 30.0, 3.0), ("mask2", 29.0, 2.0))]
    res = {"rows": rows, "settings": {"wall_distance": 2.0},
           "dataset": {"name": "data", "images": ["a"]}}
    plots.pattern_study_plot(res)
    legend = _legend_texts(kept[0])
    assert len(legend) == len(set(legend)), legend
    assert "1.8 ops per pixel" in legend and "Pareto front" in legend
    # one layout on the front: no dashed line drawn, none in the legend
    plots.pattern_study_plot({**res, "rows": rows[:1]})
    legend = _legend_texts(kept[1])
    assert "Pareto front" not in legend and "on the Pareto front" in legend


# --------------------------------------------------------------------------- PL01
def test_a_long_tile_name_does_not_run_into_other_text(tmp_path, monkeypatch):
    import imageio.v3 as iio

    from rgbz_fast.io import ImageSource

    patterns, methods = ("mask1", TILE), ("bilinear", "sg")
    res = Results(_rows(_grid(patterns, methods)),
                  EvalConfig(patterns=patterns, methods=methods, metrics=("cpsnr",)))
    fig = _reports._bar_figure(res, "cpsnr")
    fig.canvas.draw()
    assert not _overlaps(fig, fig.axes[0].get_xticklabels())
    assert fig.axes[0].get_xticklabels()[1].get_text().replace("\n", "") == TILE
    fig = _reports._paired_figure(res, "cpsnr")
    fig.canvas.draw()
    assert not _overlaps(fig, [ax.title for ax in fig.axes] + [fig._suptitle])
    figs = []
    monkeypatch.setattr(_reports, "_figure_png",
                        lambda f, metadata=None: (f.canvas.draw(), figs.append(f), b"")[-1])
    iio.imwrite(tmp_path / "a.png", np.random.default_rng(0).integers(0, 256, (32, 48, 3),
                                                                        dtype=np.uint8))
    cfg = EvalConfig(patterns=patterns, methods=methods, metrics=("cpsnr",))
    _reports.crop_figure(ImageSource("a", str(tmp_path / "a.png")), cfg, box=(8, 8, 16, 16))
    (crop,) = figs
    assert not _overlaps(crop, [ax.title for ax in crop.axes] + [crop._suptitle])


def test_the_charts_name_the_dataset(tmp_path):
    """PL08's second half: the charts named the run's settings but not its images; the
    dataset's name now travels with the results (results.json too) into the titles."""
    import imageio.v3 as iio

    from rgbz_fast.evaluation import Results, evaluate
    from rgbz_fast.evaluation._reports import _bar_figure, _paired_figure

    ds = tmp_path / "my_scenes"
    ds.mkdir()
    rng = np.random.default_rng(0)
    for n in ("a", "b"):
        iio.imwrite(ds / f"{n}.png", rng.integers(30, 220, (32, 32, 3), dtype=np.uint8))
    res = evaluate(str(ds), patterns=("mask1",), methods=("bilinear", "sg"),
                   metrics=("cfa_psnr",), progress=False)
    assert res.dataset == "my_scenes"
    assert Results.from_json(res.to_json()).dataset == "my_scenes"
    bar = _bar_figure(res, "cfa_psnr")
    assert "my_scenes: noise-free" in bar.axes[0].get_title()
    paired = _paired_figure(res, "cfa_psnr")
    assert "my_scenes: noise-free" in paired._suptitle.get_text()
    # a list of images has no name: the settings alone
    assert Results(res.rows, res.config).dataset == ""
