"""What a newcomer meets in the first hour, from the user's side: the commands of the README
and the guides run as a user types them, on small files made here or on the shared data
(skipped with the reason when it is absent)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from _support import delta_e2000, reference_srgb, rgbd_folder, shared_path  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast import io as frameio  # noqa: E402
from rgbz_fast._cli import main  # noqa: E402


# --------------------------------------------------------------------------- depth
@pytest.mark.parametrize("denoise", ["bilateral", "box", "none"])
def test_depth_of_a_staggered_tile_runs_with_every_denoise(tmp_path, capsys, denoise):
    """A staggered tile (Z sites on different columns in different rows) puts its Z
    measurements on an irregular grid; every denoise runs on it, as on Mask1 and Mask2."""
    scene = rgbd_folder(tmp_path / "scene")
    tile = "ZRGR/BGBG/GRZR/BGBG"
    assert main(["simulate", str(scene), "--pattern", tile, "--out", str(tmp_path / "f"),
                 "--quiet"]) == 0
    (frame_file,) = (tmp_path / "f").glob("*.npz")
    out = tmp_path / "d"
    # single 1x1 Z pixels are noisy: keep the noisy measurements, this is about running
    assert main(["depth", str(frame_file), "--denoise", denoise, "--max-sigma", "off",
                 "--out", str(out)]) == 0
    captured = capsys.readouterr()
    assert captured.err == "" and "% valid" in captured.out
    import tifffile

    depth = tifffile.imread(next(out.glob("*_depth.tif")))
    frame = frameio.load_frame(frame_file)
    measured = depth[frame.z_mask]
    valid = measured[np.isfinite(measured)]
    assert depth.shape == frame.shape and valid.size > 0
    # the two planes of the scene: 3740 px * 0.16 m / (60 or 110 + 270)
    assert np.all((valid > 1.45) & (valid < 1.95))


# --------------------------------------------------------------------------- raw datasets
def _advice_keys(line):
    """The --raw-options keys an error line asks for (the quoted words before the file)."""
    import re

    head = line.split("in --raw-options FILE")[0]
    return re.findall(r'"(\w+)"', head.split("pass ", 1)[1].replace('"ROWSxCOLS"', ""))


def test_evaluate_asks_for_raw_settings_in_words_it_accepts(tmp_path, capsys):
    """A one-channel 16-bit Bayer mosaic is not 'a grey image' (and --grey does not score it
    as one); a headerless file's settings are asked for, all at once, as --raw-options keys;
    giving exactly those keys, shapes written ROWSxCOLS, evaluates both."""
    import imageio.v3 as iio
    import skimage.data

    ds = tmp_path / "ds"
    ds.mkdir()
    # a camera's raw: linear light through unbalanced colour filters, 10 bits over black 16
    lin = skimage.data.astronaut()[:96, :96].astype(float) / 255 * [0.45, 1.0, 0.6]
    bayer = rz.mosaic(lin, rz.bayer("GRBG"), bit_depth=10).data + 16
    iio.imwrite(ds / "bayer16.png", bayer.astype(np.uint16))
    (ds / "frame.raw").write_bytes(bayer.astype("<u2").tobytes())
    argv = ["evaluate", "--dataset", str(ds), "--methods", "sg", "--patterns", "mask1",
            "--metrics", "cfa_psnr", "--no-plots", "--no-cache", "--quiet", "--out",
            str(tmp_path / "out")]
    for extra in ([], ["--grey"]):
        assert main(argv + extra + ["--skip-bad"]) == 2             # nothing left to evaluate
        lines = capsys.readouterr().err.splitlines()
        png = next(x for x in lines if "skipped bayer16" in x)
        raw = next(x for x in lines if "skipped frame" in x)
        assert "grey image" not in png and "--grey" not in png
        assert "a raw Bayer mosaic, not a grey photograph" in png
        assert "is a one-channel 16-bit image" in png          # the file's, not a copy's
        assert "--shape" not in raw and "--phase" not in raw
        assert _advice_keys(png) == ["phase", "black_level", "white_level", "bit_depth_in"]
        assert _advice_keys(raw) == ["shape", "phase", "black_level", "white_level",
                                     "bit_depth_in"]
    truth = {"shape": "96x96", "phase": "GRBG", "black_level": 16, "white_level": 1023 + 16}
    options = {"bayer16.png": {k: truth[k] for k in _advice_keys(png)[:3]},
               "frame.raw": {k: truth[k] for k in _advice_keys(raw)[:4]}}
    (tmp_path / "raw.json").write_text(json.dumps(options))
    assert main(argv + ["--raw-options", str(tmp_path / "raw.json")]) == 0
    out = json.loads((tmp_path / "out" / "results.json").read_text())
    psnr = {r["image"]: r["value"] for r in out["rows"]}
    assert set(psnr) == {"bayer16", "frame"} and psnr["bayer16"] == psnr["frame"] < 60


def test_grey_photographs_still_take_the_grey_advice(tmp_path, capsys):
    """A real one-channel photograph (its 2x2 sites alike) keeps the --grey advice, which
    works."""
    import imageio.v3 as iio
    import skimage.data

    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "camera.png", skimage.data.camera()[:96, :96])
    argv = ["evaluate", "--dataset", str(ds), "--methods", "sg", "--patterns", "mask1",
            "--metrics", "cfa_psnr", "--no-plots", "--no-cache", "--quiet", "--out",
            str(tmp_path / "out")]
    assert main(argv) == 2
    assert "is a grey image (96x96); a colour sensor needs colour: pass --grey" in \
        capsys.readouterr().err
    assert main(argv + ["--grey"]) == 0


def test_evaluate_on_the_shared_raw_folder(tmp_path, capsys):
    """The README's raw folder: the advice for each file, followed, evaluates all three."""
    raw = shared_path("raw")
    pytest.importorskip("rawpy")
    argv = ["evaluate", "--dataset", str(raw), "--methods", "sg", "--patterns", "mask1",
            "--metrics", "cfa_psnr", "--no-plots", "--no-cache", "--quiet", "--out",
            str(tmp_path / "out")]
    assert main(argv + ["--grey", "--skip-bad"]) == 0
    err = capsys.readouterr().err
    assert "skipped halide_bayer_small" in err and "skipped openisp_test" in err
    assert "--grey" not in err and "--shape" not in err
    options = {"halide_bayer_small.png": {"phase": "GRBG", "black_level": 25,
                                          "white_level": 1023},
               "openisp_test.RAW": {"shape": "1080x1920", "phase": "RGGB", "black_level": 0,
                                    "bit_depth_in": 10}}
    (tmp_path / "raw.json").write_text(json.dumps(options))
    assert main(argv + ["--raw-options", str(tmp_path / "raw.json")]) == 0
    rows = json.loads((tmp_path / "out" / "results.json").read_text())["rows"]
    psnr = {r["image"]: r["value"] for r in rows}
    assert set(psnr) == {"colorchart", "halide_bayer_small", "openisp_test"}
    assert all(25 < v < 60 for v in psnr.values())


# --------------------------------------------------------------------------- progress
def _stderr_lines(err):
    """The lines a terminal would end up showing (tqdm rewrites a line with carriage
    returns)."""
    return [part for line in err.splitlines() for part in line.split("\r") if part.strip()]


def test_no_progress_bar_into_a_log(tmp_path, capsys, monkeypatch):
    """stderr that is no terminal (a log, a pipe) gets no progress bar, --quiet or not: its
    carriage returns would fill the log; the per-file lines on stdout stay."""
    import rgbz_fast._progress

    monkeypatch.setattr(rgbz_fast._progress, "DELAY", 0.0)
    argv = ["calibrate", "--simulate", "--shape", "24x32", "--positions", "20",
            "--frames-per-position", "1", "--out", str(tmp_path / "cal.npz")]
    assert main(argv) == 0
    out, err = capsys.readouterr()
    assert err == "" and out.startswith("20 frames -> ")


def test_calibrate_shows_the_sweep_and_the_fit_on_stderr(tmp_path, capsys, monkeypatch,
                                                         terminal):
    """A simulated sweep counts its frames, the fit says it is running and for how long
    (here from the start: a step shows after a second); --quiet shows neither, and stdout
    holds only the summary line."""
    import rgbz_fast._progress

    monkeypatch.setattr(rgbz_fast._progress, "DELAY", 0.0)
    argv = ["calibrate", "--simulate", "--shape", "24x32", "--positions", "20",
            "--frames-per-position", "1", "--out", str(tmp_path / "cal.npz")]
    assert main(argv) == 0
    out, err = capsys.readouterr()
    lines = _stderr_lines(err)
    assert any(x.startswith("calibrate: simulating the sweep: 100%") and "28/28" in x
               for x in lines)                                    # 20 walls + 8 dark frames
    assert any(x.startswith("calibrate: fitting 20 frames ... 00:") for x in lines)
    assert out.startswith("20 frames -> ") and out.count("\n") == 1
    assert main(argv + ["--quiet"]) == 0
    assert capsys.readouterr() == ("", "")


def test_train_says_it_is_fitting_after_reading_the_images(tmp_path, capsys, monkeypatch,
                                                           terminal):
    """The bar counts the images; the fit that follows shows its running time, after the
    bar (not a bar stuck at 100 %); --quiet shows nothing."""
    import rgbz_fast._progress

    monkeypatch.setattr(rgbz_fast._progress, "DELAY", 0.0)
    import imageio.v3 as iio
    import skimage.data

    data = tmp_path / "images"
    data.mkdir()
    iio.imwrite(data / "a.png", skimage.data.astronaut()[:64, :96])
    iio.imwrite(data / "b.png", skimage.data.coffee()[:64, :96])
    argv = ["train", "--dataset", str(data), "--pattern", "mask1", "--out",
            str(tmp_path / "f.npz"), "--strength", "1", "--coherence", "1"]
    assert main(argv) == 0
    lines = _stderr_lines(capsys.readouterr().err)
    read = max(i for i, x in enumerate(lines) if x.startswith("train: 100%"))
    fit = min(i for i, x in enumerate(lines) if x.startswith("train: fitting the filters ..."))
    assert read < fit
    assert main(argv + ["--quiet"]) == 0
    assert capsys.readouterr().err == ""


# --------------------------------------------------------------------------- crop figure
def _crop_box(png):
    """The region a crop figure enlarges, as it records it: (row, col, rows, cols)."""
    from PIL import Image

    from rgbz_fast.evaluation._reports import CROP_KEY

    with Image.open(png) as im:
        return tuple(int(v) for v in im.info[CROP_KEY].split(","))


def test_evaluate_crop_figure_shows_structure_on_the_dng(tmp_path, capsys):
    """The automatic crop of the DNG is where an edge is, not the dark noisy strip at the top
    (rows 0:64 before); --zoom chooses another, and one outside the image is refused."""
    dng = shared_path("raw", "colorchart.dng")
    pytest.importorskip("rawpy")
    from rgbz_fast.evaluation import EvalConfig, image_frames
    from rgbz_fast.io import folder_dataset

    ds = tmp_path / "ds"
    ds.mkdir()
    (ds / dng.name).symlink_to(dng)
    argv = ["evaluate", "--dataset", str(ds), "--patterns", "mask1", "--methods", "bilinear,sg",
            "--metrics", "cpsnr", "--no-cache", "--quiet", "--out", str(tmp_path / "out")]
    assert main(argv) == 0
    y0, x0, h, w = _crop_box(tmp_path / "out" / "crops_colorchart.png")
    config = EvalConfig(patterns="mask1", methods=("sg",))
    frame, ref = image_frames(folder_dataset(ds)[0].load(), rz.mask1("RGGB"), config)
    luma = config.colour_isp().render(ref, "RGGB", bit_depth=frame.bit_depth).mean(axis=2)
    window = luma[y0:y0 + h, x0:x0 + w]
    assert (h, w) == (64, 64)
    assert window.std() > 0.5 * luma.std()                              # structure, not flat
    assert window.mean() > np.percentile(luma, 25)                      # not a dark strip
    assert main(argv + ["--zoom", "600,800,48"]) == 0
    assert _crop_box(tmp_path / "out" / "crops_colorchart.png") == (600, 800, 48, 48)
    out = tmp_path / "out"
    before = {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()}
    capsys.readouterr()
    assert main([a if a != "bilinear,sg" else "bi" for a in argv] + ["--zoom", "1150,0"]) == 2
    assert capsys.readouterr().err.strip().startswith(
        "rgbz-fast evaluate: error: --zoom: (1150, 0, 64, 64) is not inside the 1156x1734")
    # refused before anything is written: the last run's reports as they were
    assert {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()} == before


# --------------------------------------------------------------------------- tradeoff plot
def _is_grey(rgba):
    r, g, b = rgba[:3]
    return abs(r - g) < 1e-6 and abs(g - b) < 1e-6 and 0.05 < r < 0.95


def test_tradeoff_plot_legend_hides_no_point_labels_do_not_collide_grey_means_nothing(
        tmp_path, capsys):
    """tradeoff.png, as `rgbz-fast tradeoff` writes it: the legend sits outside every panel,
    the speed axis's labels do not overlap, and no point or legend marker is grey (grey was
    both a method and 'any method' in the shape legend)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.colors import to_rgba

    from rgbz_fast._devtools.plots import tradeoff_figure

    out = tmp_path / "t"
    assert main(["tradeoff", "--quick", "--limit", "1", "--methods", "bilinear,bi,sg,learned",
                 "--out", str(out), "--quiet"]) == 0
    assert (out / "tradeoff.png").read_bytes()[:4] == b"\x89PNG"
    res = json.loads((out / "tradeoff.json").read_text())
    # the points of a full run: some on the Pareto front, speeds over two decades
    for i, r in enumerate(res["rows"]):
        r["pareto"] = i % 3 == 0
        r["mpix_s"] = r["mpix_s_lo"] = r["mpix_s_hi"] = 150.0 * 1.25 ** i
    fig = tradeoff_figure(res)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    (legend,) = fig.legends
    box = legend.get_window_extent(renderer)
    for ax in fig.axes:
        assert not box.overlaps(ax.get_window_extent(renderer))
        labels = [t.get_window_extent(renderer) for t in ax.get_xticklabels()
                  if t.get_visible() and t.get_text()]
        labels.sort(key=lambda b: b.x0)
        assert len(labels) >= 2
        assert all(a.x1 < b.x0 for a, b in zip(labels, labels[1:]))
        for coll in ax.collections:
            for c in list(coll.get_facecolors()) + list(coll.get_edgecolors()):
                assert not _is_grey(c)
    for h in legend.legend_handles:
        for c in (h.get_markerfacecolor(), h.get_markeredgecolor()):
            assert c in ("none", "None") or not _is_grey(to_rgba(c))
    texts = [t.get_text() for t in legend.get_texts()]
    assert {"colour: method", "fill: domain", "shape: precision, exp"} <= set(texts)


# --------------------------------------------------------------------------- colour
def test_a_spectral_scene_comes_out_in_its_colours(tmp_path, capsys):
    """simulate a CAVE cube, reconstruct --output srgb: the sensor's white balance and colour
    matrix travel in the frame file and the PNG is within 3 CIEDE2000 of colour-science's
    rendering; --colour-matrix none --white-balance grey-world shows what it was (washed
    out, tinted)."""
    import imageio.v3 as iio

    cube = shared_path("multispectral", "balloons_ms", "balloons_ms.mat")
    assert main(["simulate", str(cube), "--out", str(tmp_path / "f"), "--quiet"]) == 0
    frame_file = tmp_path / "f" / "balloons_ms_mask1.npz"
    frame = frameio.load_frame(frame_file)
    assert len(frame.meta["colour_matrix"]) == 9 and len(frame.meta["white_gains"]) == 3
    s = rz.ColourSensor()
    scale = (s.photon_flux * s.pixel_area_um2 * s.qe[1] * frame.meta["exposure"]
             * s.system_gain / (s.white_level - s.black_level))
    ref = reference_srgb(rz.simulation.load_spectral(cube), scale)
    argv = ["reconstruct", str(frame_file), "--output", "srgb", "--quiet"]
    assert main(argv + ["--out", str(tmp_path / "auto")]) == 0
    assert main(argv + ["--out", str(tmp_path / "plain"), "--colour-matrix", "none",
                        "--white-balance", "grey-world"]) == 0
    good = iio.imread(tmp_path / "auto" / "balloons_ms_mask1_sg.png")
    plain = iio.imread(tmp_path / "plain" / "balloons_ms_mask1_sg.png")
    assert delta_e2000(ref, good).mean() < 3.0
    assert delta_e2000(ref, plain).mean() > 6.0
    with pytest.raises(SystemExit) as e:
        main(argv + ["--colour-matrix", "1,0,0,0,1,0"])
    assert e.value.code == 2
    assert "argument --colour-matrix: expected auto, none or nine" in capsys.readouterr().err


def test_a_dng_renders_with_its_as_shot_white_balance_and_colour_matrix(tmp_path):
    """The DNG's AsShotNeutral (1, 2.477, 1.462) and colour matrix reach the sRGB output by
    default: the same image as when they are typed on the command line."""
    import imageio.v3 as iio

    dng = shared_path("raw", "colorchart.dng")
    pytest.importorskip("rawpy")
    meta = frameio.read_raw(dng).meta
    np.testing.assert_allclose(meta["white_gains"], (2.477, 1.0, 2.477 / 1.462),
                               rtol=2e-3)
    m = np.reshape(meta["colour_matrix"], (3, 3))
    np.testing.assert_allclose(m.sum(axis=1), 1.0, atol=1e-5)
    argv = ["reconstruct", str(dng), "--rgbz-pattern", "mask1", "--downsample", "2",
            "--output", "srgb", "--quiet"]
    assert main(argv + ["--out", str(tmp_path / "a")]) == 0
    typed = ["--white-balance", ",".join(map(repr, meta["white_gains"])),
             "--colour-matrix", ",".join(map(repr, meta["colour_matrix"]))]
    assert main(argv + typed + ["--out", str(tmp_path / "b")]) == 0
    assert main(argv + ["--white-balance", "grey-world", "--colour-matrix", "none",
                        "--out", str(tmp_path / "c")]) == 0
    a, b, c = (iio.imread(tmp_path / d / "colorchart_mask1_sg.png") for d in "abc")
    np.testing.assert_array_equal(a, b)
    assert np.abs(a.astype(int) - c).mean() > 3


# --------------------------------------------------------------------------- outputs
def test_a_14_bit_dng_is_written_back_with_14_bits(tmp_path):
    """reconstruct keeps a raw file's bit depth unless --bit-depth says otherwise."""
    import tifffile

    dng = shared_path("raw", "colorchart.dng")
    pytest.importorskip("rawpy")
    argv = ["reconstruct", str(dng), "--rgbz-pattern", "mask1", "--quiet", "--out"]
    assert main(argv + [str(tmp_path / "a")]) == 0
    assert main(argv + [str(tmp_path / "b"), "--bit-depth", "11"]) == 0
    for folder, bits in (("a", 14), ("b", 11)):
        with tifffile.TiffFile(tmp_path / folder / "colorchart_mask1_sg_cfa.tif") as tf:
            assert json.loads(tf.pages[0].description)["bit_depth"] == bits
            data = tf.asarray()
        assert (1 << (bits - 1)) <= data.max() < (1 << bits)


def test_a_second_evaluation_leaves_no_file_of_the_first(tmp_path, capsys):
    """Reports of a previous run into the same folder that this run does not write are
    removed; files the evaluation never wrote (and its cache) stay."""
    import imageio.v3 as iio
    import skimage.data

    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "a.png", skimage.data.astronaut()[:64, :64])
    iio.imwrite(ds / "b.png", skimage.data.coffee()[:64, :64])
    out = tmp_path / "out"
    argv = ["evaluate", "--dataset", str(ds), "--patterns", "mask1", "--quiet", "--out",
            str(out)]
    assert main(argv + ["--methods", "bilinear,sg", "--metrics", "cfa_psnr,ssim"]) == 0
    first = {p.name for p in out.iterdir()}
    assert {"bars_ssim.png", "paired_ssim.png", "crops_a.png", "reports.txt"} <= first
    (out / "notes.md").write_text("mine")
    assert main(argv + ["--methods", "sg", "--metrics", "cfa_psnr", "--table-image", "b"]) == 0
    second = {p.name for p in out.iterdir()}
    assert second == {"results.csv", "results.json", "summary.md", "table_b.md",
                      "bars_cfa_psnr.png", "reports.txt", "notes.md", "cache"}
    capsys.readouterr()


def test_output_names_follow_one_scheme(tmp_path, capsys):
    """<input>_<pattern>_<method>[_<product>]: lower-case fields, '-' inside a field."""
    scene = rgbd_folder(tmp_path / "sc")
    frames = tmp_path / "f"
    for pattern in ("bayer", "ZR/BG", "mask2"):
        assert main(["simulate", str(scene), "--pattern", pattern, "--out", str(frames),
                     "--quiet"]) == 0
    assert sorted(p.name for p in frames.iterdir()) == ["sc_bayer-grbg.npz", "sc_mask2.npz",
                                                        "sc_zr-bg.npz"]
    out = tmp_path / "o"
    assert main(["reconstruct", str(frames / "sc_zr-bg.npz"), "--method", "SG", "--out",
                 str(out), "--quiet"]) == 0
    assert main(["reconstruct", str(frames / "sc_mask2.npz"), "--method", "edi_line",
                 "--output", "srgb", "--out", str(out), "--quiet"]) == 0
    assert main(["reconstruct", str(frames / "sc_bayer-grbg.npz"), "--rgbz-pattern", "mask1",
                 "--out", str(out), "--quiet"]) == 0
    assert sorted(p.name for p in out.iterdir()) == [
        "sc_bayer-grbg_mask1_reference_cfa.tif", "sc_bayer-grbg_mask1_sg_cfa.tif",
        "sc_mask2_edi-line.png", "sc_mask2_reference.png",
        "sc_zr-bg_reference_cfa.tif", "sc_zr-bg_sg_cfa.tif"]


def test_gitignore_lists_the_default_output_folders():
    from rgbz_fast._cli import depth, evaluate, reconstruct, simulate

    from _support import REPO

    ignored = (REPO / ".gitignore").read_text().split()
    for command in (simulate, reconstruct, depth, evaluate):
        assert f"/{command.DEFAULT_OUT}/" in ignored
    assert "/tof_calibration.npz" in ignored


def test_a_quick_step_or_an_early_error_shows_no_progress_line(tmp_path, capsys):
    """A step shorter than a second prints nothing: an error stays the only line."""
    from rgbz_fast._progress import ticking

    with ticking("quick: fitting"):
        pass
    assert capsys.readouterr().err == ""
    frame = tmp_path / "plain.npz"
    frameio.save_frame(frame, rz.mosaic(np.zeros((8, 8, 3)), "mask1"))
    assert main(["calibrate", str(frame), str(frame), "--distances", "1,2", "--out",
                 str(tmp_path / "cal.npz")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("rgbz-fast calibrate: error: sweep:")


# --------------------------------------------------------------------------- words
def test_depth_says_why_measurements_are_flagged_in_a_legible_map(tmp_path, capsys):
    """The summary gives each flag's share; the flags PNG is a map of reasons with a legend
    (measurements over their footprint, not a dot grid); the bits stay in a TIFF."""
    import imageio.v3 as iio
    import tifffile

    scene = rgbd_folder(tmp_path / "sc")
    assert main(["simulate", str(scene), "--pattern", "mask1", "--out", str(tmp_path / "f"),
                 "--quiet"]) == 0
    out = tmp_path / "d"
    assert main(["depth", str(tmp_path / "f" / "sc_mask1.npz"), "--out", str(out)]) == 0
    line = capsys.readouterr().out
    frame = frameio.load_frame(tmp_path / "f" / "sc_mask1.npz")
    res = rz.tof_depth(frame.tof)
    share = np.mean((res.flags & rz.tof.FLAG_LOW_SIGNAL) != 0)
    assert share > 0 and f"flagged: {100 * share:.1f} % low signal" in line
    bits = tifffile.imread(out / "sc_mask1_depth-flags.tif")
    np.testing.assert_array_equal(bits[frame.z_mask], res.flags)
    assert np.all(bits[~frame.z_mask] == 255)
    with tifffile.TiffFile(out / "sc_mask1_depth-flags.tif") as tf:
        assert json.loads(tf.pages[0].description)["flags"]["2"] == "low signal"
    figure = iio.imread(out / "sc_mask1_depth-flags.png")
    assert figure.ndim == 3 and figure.shape[2] in (3, 4)
    # over the map, neighbouring pixels mostly agree: no grid of isolated dots
    from rgbz_fast._devtools.plots import FLAG_CATEGORIES

    h, w = figure.shape[:2]
    crop = figure[h // 4: h // 2, w // 4: 3 * w // 4, :3].astype(int)
    colours = {tuple(int(c[i:i + 2], 16) for i in (1, 3, 5)) for _, c in FLAG_CATEGORIES}
    on_map = np.array([[tuple(p) in colours for p in row] for row in crop])
    assert on_map.mean() > 0.9
    same = np.all(crop[:, 1:] == crop[:, :-1], axis=2).mean()
    assert same > 0.8


def test_errors_speak_in_flags_not_python(tmp_path, capsys):
    """A library message's name=value advice reads as the command's flags."""
    for argv, want, unwanted in (
            (["evaluate", "--noise", "--no-linearise", "--limit", "1"],
             "the sensor model (--noise) takes linear light; --no-linearise is a noise-free "
             "protocol", "linearise=False"),
            (["evaluate", "--optics", "--no-linearise", "--limit", "1"], "it needs --linearise",
             "linearise=True"),
            (["evaluate", "--crop", "300", "--limit", "1", "--metrics", "ssim"],
             "crop: image 'astronaut': --crop 300 leaves", "crop=300")):
        assert main(argv + ["--out", str(tmp_path / "o"), "--quiet", "--no-cache"]) == 2
        err = capsys.readouterr().err
        assert want in err and unwanted not in err
    scene = rgbd_folder(tmp_path / "sc")
    assert main(["simulate", str(scene), "--pattern", "ZRGR/BGBG/GRZR/BGBG", "--out",
                 str(tmp_path / "f"), "--quiet"]) == 0                 # no filters ship for it
    assert main(["reconstruct", str(tmp_path / "f" / "sc_zrgr-bgbg-grzr-bgbg.npz"), "--method",
                 "learned",
                 "--out", str(tmp_path / "o"), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.strip().endswith("fit some with rgbz-fast train and pass --filters FILE")
    assert main(["calibrate", "--simulate", "--out", str(tmp_path)]) == 2
    assert "--out: " in capsys.readouterr().err


def test_bench_speaks_to_its_reader(capsys):
    """bench --help and a quick run carry no markup, module path or Python syntax."""
    import re

    with pytest.raises(SystemExit):
        main(["bench", "--help"])
    text = capsys.readouterr().out
    assert main(["bench", "--quick", "--quiet", "--repeat", "1", "--kernels", "bilinear",
                 "--no-reference"]) == 0
    text += capsys.readouterr().out
    jargon = [r"``", r":(func|mod|class):", r"rgbz_fast\.", r"_devtools", r"\*\*", r"\bTrue\b",
              r"\bFalse\b", r"tracemalloc", r"\bnp\.", r"RawFrame", r"in brackets"]
    found = [j for j in jargon if re.search(j, text)]
    assert not found, found
