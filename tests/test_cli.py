"""The rgbz-fast command line: every subcommand, --help, errors with one-line reasons."""

import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from _support import shared_path  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast import io as frameio  # noqa: E402
from rgbz_fast._cli import main  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


def test_help_lists_the_whole_chain(capsys):
    with pytest.raises(SystemExit) as e:
        main(["--help"])
    assert e.value.code == 0
    out = capsys.readouterr().out
    for cmd in ("simulate", "reconstruct", "depth", "evaluate", "train", "calibrate",
                "evaluate-depth", "bench", "opcount", "tradeoff", "config"):
        assert cmd in out


@pytest.mark.parametrize("cmd", ["simulate", "reconstruct", "evaluate"])
def test_subcommand_help(cmd, capsys):
    with pytest.raises(SystemExit) as e:
        main([cmd, "--help"])
    assert e.value.code == 0
    assert "--out" in capsys.readouterr().out


def test_console_script_runs():
    exe = Path(sys.executable).parent / "rgbz-fast"
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "rgbz_fast"]
    r = subprocess.run(cmd + ["config"], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and "OpenMP" in r.stdout


def test_a_plain_mosaic_read_with_two_patterns_writes_two_files(tmp_path):
    """The pattern a plain mosaic is read with is in its output's name, as --rgbz-pattern's
    (both had been written to plain_sg_cfa.tif, the second over the first)."""
    import tifffile

    plain = tmp_path / "plain.tif"
    data = np.random.default_rng(0).integers(0, 2048, (48, 64)).astype(np.uint16)
    tifffile.imwrite(plain, data)
    for pattern in ("mask1", "mask2"):
        assert main(["reconstruct", str(plain), "--pattern", pattern, "--bit-depth", "11",
                     "--out", str(tmp_path / "o"), "--quiet"]) == 0
    for pattern in ("mask1", "mask2"):
        got = tifffile.imread(tmp_path / "o" / f"plain_{pattern}_sg_cfa.tif")
        frame = rz.RawFrame(data, rz.get_pattern(pattern), 11)
        np.testing.assert_array_equal(got, rz.reconstruct(frame, "sg"))


def test_simulate_then_reconstruct(tmp_path, capsys):
    import imageio.v3 as iio
    import skimage.data

    img = skimage.data.astronaut()[:64, :96]
    scene_file = tmp_path / "astro.png"
    iio.imwrite(scene_file, img)
    assert main(["simulate", str(scene_file), "--pattern", "mask2", "--out",
                 str(tmp_path / "frames"), "--quiet"]) == 0
    frame_file = tmp_path / "frames" / "astro_mask2.npz"
    frame = frameio.load_frame(frame_file)
    assert frame.pattern == rz.mask2() and frame.reference is not None and frame.tof is None
    assert main(["reconstruct", str(frame_file), "--method", "sg", "--out",
                 str(tmp_path / "out"), "--quiet"]) == 0
    import tifffile
    cfa = tifffile.imread(tmp_path / "out" / "astro_mask2_sg_cfa.tif")
    assert cfa.shape == (64, 96) and cfa.dtype == np.uint16
    np.testing.assert_array_equal(cfa, rz.reconstruct(frame, "sg"))
    assert main(["reconstruct", str(frame_file), "--output", "srgb", "--out",
                 str(tmp_path / "out"), "--quiet"]) == 0
    png = iio.imread(tmp_path / "out" / "astro_mask2_sg.png")
    assert png.shape == (64, 96, 3) and png.dtype == np.uint8
    # the pair of Fig. 19: the reference's own white balance on both images
    ref_img = iio.imread(tmp_path / "out" / "astro_mask2_reference.png")
    from rgbz_fast.isp import ColourISP, recorded_rendering
    rec = recorded_rendering(frame)
    assert rec["white_gains"] is None                     # grey world on the reference
    isp = ColourISP(precision="float64", black_level=rec["black_level"])
    kw = dict(bit_depth=frame.bit_depth, colour_matrix=rec["colour_matrix"])
    phase = frame.pattern.bayer_phase
    want_ref, stages = isp.render(frame.reference, phase, return_stages=True, **kw)
    np.testing.assert_array_equal(ref_img, want_ref)
    np.testing.assert_array_equal(png, isp.render(rz.reconstruct(frame, "sg"), phase,
                                                  gains=stages["gains"], **kw))


def test_reconstruct_of_a_bad_file_leaves_no_output_folder(tmp_path, capsys):
    bad = tmp_path / "bad.npz"
    bad.write_bytes(b"not a frame")
    out = tmp_path / "out"
    assert main(["reconstruct", str(bad), "--out", str(out), "--quiet"]) == 2
    assert "bad.npz" in capsys.readouterr().err
    assert not out.exists()


def test_simulate_rgbd_scene_with_tof(tmp_path):
    art = shared_path("rgbd", "aloe")
    assert main(["simulate", str(art), "--pattern", "mask1", "--format", "npz", "--out",
                 str(tmp_path), "--quiet", "--seed", "2"]) == 0
    frame = frameio.load_frame(tmp_path / "aloe_mask1.npz")
    assert frame.tof is not None and frame.tof.taps.shape[:2] == (3, 4)


def test_simulate_says_what_each_file_keeps(tmp_path, capsys):
    """A TIFF keeps the mosaic alone: the line had said 'with ToF taps' for a file without
    them; a pattern without Z pixels says so rather than 'no depth'."""
    import imageio.v3 as iio

    scene = tmp_path / "scene"
    scene.mkdir()
    rng = np.random.default_rng(1)
    iio.imwrite(scene / "rgb.png", rng.integers(0, 256, (24, 32, 3), dtype=np.uint8))
    iio.imwrite(scene / "disp1.png", np.full((24, 32), 120, np.uint8))
    (scene / "dmin.txt").write_text("200\n")
    for extra, want in ((["--format", "tiff"], "(24x32, the mosaic only: the ToF taps and the "
                                               "reference CFA need --format npz)"),
                        ([], "(24x32, with ToF taps)"),
                        (["--pattern", "bayer"], "(24x32, no ToF: 'bayer_grbg' has no Z pixel)")):
        assert main(["simulate", str(scene), *extra, "--out", str(tmp_path / "o")]) == 0
        assert capsys.readouterr().out.strip().endswith(want)
    assert frameio.load_frame(tmp_path / "o" / "scene_mask1.tif").tof is None


def test_frame_tiff_round_trip(tmp_path):
    img = np.random.default_rng(0).integers(0, 256, (8, 12, 3), dtype=np.uint8)
    f = rz.mosaic(img, rz.mask1())
    frameio.save_frame(tmp_path / "f.tif", f)
    g = frameio.load_frame(tmp_path / "f.tif")
    assert g.pattern == f.pattern and g.bit_depth == 11
    np.testing.assert_array_equal(g.data, f.data)
    with pytest.raises(ValueError, match="^path: unsupported"):
        frameio.save_frame(tmp_path / "f.jpg", f)
    with pytest.raises(ValueError, match="^path: .* does not exist"):
        frameio.load_frame(tmp_path / "missing.npz")


def test_evaluate_prints_table_and_writes_reports(tmp_path, capsys):
    import imageio.v3 as iio
    import skimage.data

    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "a.png", skimage.data.coffee()[:192, :192])
    iio.imwrite(ds / "b.png", skimage.data.astronaut()[:192, :192])
    assert main(["evaluate", "--dataset", str(ds), "--methods", "bilinear,sg", "--out",
                 str(tmp_path / "rep"), "--quiet", "--processes", "1"]) == 0
    out = capsys.readouterr().out
    assert "mask1" in out and "SG" in out and "CFA PSNR" in out
    assert (tmp_path / "rep" / "summary.md").exists()
    assert (tmp_path / "rep" / "crops_a.png").exists()
    assert main(["evaluate", "--dataset", str(ds), "--methods", "sg", "--metrics", "cfa_psnr",
                 "--out", str(tmp_path / "rep2"), "--quiet", "--json", "--processes", "1"]) == 0
    js = json.loads(capsys.readouterr().out)
    assert "mask2/sg/cfa_psnr" in js


def test_evaluate_offers_every_demosaic(tmp_path, capsys):
    """--demosaic lists the library's demosaics (written out in the CLI so that its parser
    imports no kernel) and bilinear runs."""
    import imageio.v3 as iio
    import skimage.data

    from rgbz_fast._cli.evaluate import DEMOSAICS
    from rgbz_fast.isp import DEMOSAIC_METHODS

    assert DEMOSAICS == DEMOSAIC_METHODS
    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "a.png", skimage.data.coffee()[:96, :96])
    assert main(["evaluate", "--dataset", str(ds), "--methods", "sg", "--metrics", "cpsnr",
                 "--demosaic", "bilinear", "--out", str(tmp_path / "rep"), "--quiet", "--json",
                 "--processes", "1", "--no-plots"]) == 0
    assert "mask1/sg/cpsnr" in json.loads(capsys.readouterr().out)


def test_evaluate_with_optics(tmp_path, capsys):
    import imageio.v3 as iio
    import skimage.data

    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "a.png", skimage.data.coffee()[:96, :96])
    args = ["evaluate", "--dataset", str(ds), "--methods", "bi", "--metrics", "cfa_psnr",
            "--quiet", "--processes", "1", "--json", "--no-plots"]
    assert main(args + ["--out", str(tmp_path / "plain")]) == 0
    plain = json.loads(capsys.readouterr().out)
    assert main(args + ["--out", str(tmp_path / "optics"), "--optics", "--olpf", "1"]) == 0
    blurred = json.loads(capsys.readouterr().out)
    # the blur takes the fine detail the reconstruction has to guess: a higher PSNR
    assert blurred["mask1/bi/cfa_psnr"]["mean"] > plain["mask1/bi/cfa_psnr"]["mean"] + 1
    assert "optics f/2.8 OLPF 1" in (tmp_path / "optics" / "summary.md").read_text()


def test_calibrate_simulated_and_from_frames(tmp_path, capsys):
    out = tmp_path / "cal.npz"
    assert main(["calibrate", "--simulate", "--positions", "20", "--frames-per-position", "1",
                 "--shape", "16x24", "--orders", "4", "--sensor", '{"delay_ps": 100}',
                 "--out", str(out)]) == 0
    assert "fit residual" in capsys.readouterr().out
    cal = rz.tof.ToFCalibration.load(out)
    f = np.array([80e6, 100e6, 120e6])
    np.testing.assert_allclose(cal.mean_offset, 2 * np.pi * f * 100e-12, atol=0.02)
    # frame files of a real (here: simulated) sweep with their distances
    from rgbz_fast.simulation import Scene
    ds = np.linspace(0.6, 2.6, 12)
    names = []
    for k, d in enumerate(ds):
        scene = Scene(np.full((16, 24, 3), 0.5), depth=np.full((16, 24), d))
        frame = rz.simulate(scene, "mask2", seed=k)
        names.append(str(frameio.save_frame(tmp_path / f"wall{k}.npz", frame)))
    out2 = tmp_path / "cal2.npz"
    assert main(["calibrate", *names, "--distances", ",".join(f"{d:.4f}" for d in ds),
                 "--orders", "3", "--out", str(out2), "--quiet"]) == 0
    assert rz.tof.ToFCalibration.load(out2).offsets.shape == (3, 24)


def test_evaluate_depth_prints_the_tables(capsys):
    assert main(["evaluate-depth", "--sections", "sunlight"]) == 0
    out = capsys.readouterr().out
    assert "Sunlight" in out and "burst 0.1 + suppression 0.5" in out
    assert main(["evaluate-depth", "--sections", "sunlight", "--json"]) == 0
    assert "sunlight" in json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("argv, match", [
    (["calibrate"], "no frames"),
    (["calibrate", __file__], "--distances"),
    (["calibrate", "--simulate", "--sensor", "{bad json"], "--sensor: not JSON"),
    (["calibrate", "--simulate", "--sensor", '{"nope": 1}'], "--sensor: got an unexpected"),
    (["calibrate", "--simulate", "--near", "3", "--far", "1"], "--near, --far"),
    (["evaluate-depth", "--sections", "speed"], "sections: unknown"),
    (["evaluate", "--olpf", "1"], "need --optics"),
])
def test_bad_depth_and_optics_arguments(argv, match, capsys, tmp_path):
    if argv[0] == "calibrate":
        argv = argv + ["--out", str(tmp_path / "c.npz")]
    elif argv[0] == "evaluate":
        argv = argv + ["--out", str(tmp_path)]
    code = main(argv)
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1 and err.startswith(f"rgbz-fast {argv[0]}: error:")
    assert re.search(match, err), err


@pytest.mark.parametrize("argv, match", [
    (["calibrate", "--simulate", "--shape", "16by24"], "argument --shape: expected ROWSxCOLS"),
    (["calibrate", "--simulate", "--positions", "1"], "argument --positions: expected an integer in [2, 4096]"),
    (["evaluate", "--optics", "--f-number", "0"], "argument --f-number: expected a positive"),
    (["depth", "x.npz", "--denoise", "gauss"], "argument --denoise: invalid choice"),
])
def test_bad_option_values_are_usage_errors(argv, match, capsys):
    """Option values of the wrong form stop at parsing, with the usage and the option named."""
    with pytest.raises(SystemExit) as e:
        main(argv)
    assert e.value.code == 2
    assert match in capsys.readouterr().err


@pytest.mark.parametrize("argv, match", [
    (["evaluate", "--methods", "nope"], "methods"),
    (["evaluate", "--dataset", "/nonexistent/folder"], "does not exist"),
    (["evaluate", "--patterns", "mask7"], "pattern: 'mask7'"),
    (["reconstruct", "/nonexistent.npz"], "does not exist"),
    (["reconstruct", __file__, "--method", "sg"], ""),
    (["simulate", "/nonexistent.png"], "does not exist"),
    (["simulate", __file__, "--pattern", "mask7"], "pattern"),
])
def test_bad_input_exits_2_with_one_line(argv, match, capsys, tmp_path):
    code = main(argv + ["--out", str(tmp_path)])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1 and err.startswith(f"rgbz-fast {argv[0]}: error:")
    assert re.search(match, err)


def test_readme_test_command_is_ci():
    readme = (REPO / "README.md").read_text()
    ci = (REPO / ".ci" / "run").read_text()
    blocks = re.findall(r"```bash\n(.*?)\n```", readme, re.S)
    test_cmd = [b for b in blocks if "pytest" in b]
    assert len(test_cmd) == 1
    assert test_cmd[0].strip() in ci.splitlines()


def test_readme_python_examples_run(capsys):
    readme = (REPO / "README.md").read_text()
    first, second = re.findall(r"```python\n(.*?)\n```", readme, re.S)[:2]
    ns = {}
    exec(compile(first, "README.md", "exec"), ns)
    out = capsys.readouterr().out
    assert "sg" in out and "dB" in out
    aloe = shared_path("rgbd", "aloe")
    exec(compile(second.replace("../shared/data/rgbd/aloe", str(aloe)), "README.md", "exec"), ns)
    out = capsys.readouterr().out
    # the numbers the README's text quotes
    assert "81.4% of 22240 depth measurements valid; ground truth unknown at 3.8% of them; " \
           "median error 3.5 mm" in out, out


# --------------------------------------------------------------------------- real raw files
RAW_FILES = {
    "colorchart.dng": [],
    "halide_bayer_small.png": ["--phase", "GRBG", "--black-level", "25", "--white-level",
                               "1023"],
    "openisp_test.RAW": ["--shape", "1080x1920", "--phase", "RGGB", "--black-level", "0",
                         "--bit-depth-in", "10", "--saturation-level", "1020", "--clip-level",
                         "auto"],
}


@pytest.mark.parametrize("name", sorted(RAW_FILES))
def test_reconstruct_places_a_z_pattern_on_real_raw(name, tmp_path, capsys):
    """The three real raw files reconstruct from the command line with --rgbz-pattern: the
    output equals the library's to_rgbz + reconstruct, the reference is the real CFA, and
    the Z sites are really reconstructed (not a copy of the input)."""
    import tifffile

    path = shared_path("raw", name)
    if name.endswith(".dng"):
        pytest.importorskip("rawpy")
    out = tmp_path / "out"
    assert main(["reconstruct", str(path), "--rgbz-pattern", "mask1", "--out", str(out)]
                + RAW_FILES[name]) == 0
    printed = capsys.readouterr().out
    assert "CFA PSNR at the Z sites" in printed and " dB" in printed
    stem = path.stem
    cfa = tifffile.imread(out / f"{stem}_mask1_sg_cfa.tif")
    ref = tifffile.imread(out / f"{stem}_mask1_reference_cfa.tif")
    opts = {"--phase": "phase", "--black-level": "black_level", "--white-level": "white_level",
            "--shape": "shape", "--bit-depth-in": "bit_depth_in",
            "--saturation-level": "clip_level"}
    args = RAW_FILES[name]
    kw = {opts[k]: v for k, v in zip(args[::2], args[1::2]) if k in opts}
    auto = "--clip-level" in args                  # the saturation level takes effect
    if "shape" in kw:
        kw["shape"] = tuple(int(v) for v in kw["shape"].split("x"))
    for k in ("black_level", "white_level", "bit_depth_in", "clip_level"):
        if k in kw:
            kw[k] = float(kw[k]) if k != "bit_depth_in" else int(kw[k])
    # the command keeps the file's bit depth
    rgbz, want_ref = frameio.to_rgbz(frameio.read_raw(path, bit_depth="input", **kw), "mask1")
    np.testing.assert_array_equal(ref, want_ref)
    np.testing.assert_array_equal(cfa, rz.reconstruct(rgbz, "sg",
                                                      clip_level="auto" if auto else None))
    z = rgbz.z_mask
    assert np.array_equal(cfa[~z], ref[~z]) and not np.array_equal(cfa[z], rgbz.data[z])


def test_raw_options_file_and_cli_words(tmp_path, capsys):
    """--raw-options gives what a file lacks; a missing option is asked for as a flag."""
    path = shared_path("raw", "openisp_test.RAW")
    assert main(["reconstruct", str(path), "--rgbz-pattern", "mask2", "--out", str(tmp_path),
                 "--quiet", "--raw-options", str(REPO / "data" / "shared_raw_options.json")]) == 0
    assert (tmp_path / "openisp_test_mask2_sg_cfa.tif").exists()
    assert main(["reconstruct", str(path), "--rgbz-pattern", "mask2", "--out", str(tmp_path),
                 "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.strip().startswith(
        "rgbz-fast reconstruct: error: --shape: openisp_test.RAW does not record its size, its "
        "CFA phase, its black level or its white level; pass --shape ROWSxCOLS, --phase")


def test_plain_bayer_frame_is_not_copied_silently(tmp_path, capsys):
    """A plain Bayer file holds no Z site: reconstruct says why there is nothing to
    reconstruct (and how to place Z sites), and writes nothing rather than a copy of it."""
    import tifffile

    bayer = tmp_path / "bayer.tif"
    tifffile.imwrite(bayer, np.full((8, 8), 100, np.uint16))
    out = tmp_path / "out"
    assert main(["reconstruct", str(bayer), "--phase", "RGGB", "--black-level", "0",
                 "--white-level", "1023", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("rgbz-fast reconstruct: error: --rgbz-pattern: ") and \
        "is a plain Bayer frame (bayer_rggb, no Z sites)" in err
    assert not out.exists()
    frame = tmp_path / "f.npz"
    frameio.save_frame(frame, rz.mosaic(np.zeros((8, 8, 3)), "mask1"))
    assert main(["reconstruct", str(frame), "--rgbz-pattern", "mask1", "--out", str(out)]) == 2
    assert "already has Z sites" in capsys.readouterr().err
    assert main(["reconstruct", str(frame), "--phase", "RGGB", "--out", str(out)]) == 2
    assert "--phase: " in capsys.readouterr().err and not out.exists()


def test_two_inputs_writing_one_output_are_refused(tmp_path, capsys):
    """Two inputs whose outputs would have one name in one --out are refused before any is
    written."""
    for sub in ("x", "y"):
        (tmp_path / sub).mkdir()
        frameio.save_frame(tmp_path / sub / "f.npz", rz.mosaic(np.zeros((8, 8, 3)), "mask1"))
    out = tmp_path / "out"
    assert main(["reconstruct", str(tmp_path / "x" / "f.npz"), str(tmp_path / "y" / "f.npz"),
                 "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("rgbz-fast reconstruct: error: --out: ") and "would both write" in err
    assert not out.exists()


def test_simulate_custom_tile_and_failure_leave_no_folders(tmp_path, capsys):
    """A tile pattern names its file with no folder separator (s_zr-bg.npz), and a simulate
    that fails creates no --out folder."""
    import imageio.v3 as iio

    img = tmp_path / "s.png"
    iio.imwrite(img, np.random.default_rng(0).integers(0, 256, (16, 16, 3), dtype=np.uint8))
    out = tmp_path / "out"
    assert main(["simulate", str(img), "--pattern", "ZR/BG", "--out", str(out), "--quiet"]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["s_zr-bg.npz"]
    assert frameio.load_frame(out / "s_zr-bg.npz").pattern == rz.Pattern("ZR/BG")
    grey = tmp_path / "g.png"
    iio.imwrite(grey, np.arange(256, dtype=np.uint8).reshape(16, 16))
    out2 = tmp_path / "out2" / "deeper"
    assert main(["simulate", str(grey), "--out", str(out2), "--quiet"]) == 2
    assert "is a grey image" in capsys.readouterr().err
    assert not (tmp_path / "out2").exists()
    assert main(["simulate", str(grey), "--grey", "--out", str(out2), "--quiet"]) == 0
    assert (out2 / "g_mask1.npz").exists()


def test_depth_subcommand_writes_depth_flags_and_preview(tmp_path, capsys):
    import imageio.v3 as iio
    import tifffile

    aloe = shared_path("rgbd", "aloe")
    frames = tmp_path / "frames"
    assert main(["simulate", str(aloe), "--pattern", "mask2", "--seed", "1", "--out",
                 str(frames), "--quiet"]) == 0
    out = tmp_path / "depth"
    assert main(["depth", str(frames / "aloe_mask2.npz"), "--out", str(out)]) == 0
    line = capsys.readouterr().out
    assert "% valid; flagged: " in line and "ground truth unknown at 3.8 % of them" in line
    frame = frameio.load_frame(frames / "aloe_mask2.npz")
    res = rz.tof_depth(frame.tof)
    depth = tifffile.imread(out / "aloe_mask2_depth.tif")
    assert depth.dtype == np.float32 and depth.shape == frame.shape
    np.testing.assert_array_equal(depth, res.depth_map().astype(np.float32))   # NaN: no depth
    assert np.isnan(depth[~frame.z_mask]).all()
    with tifffile.TiffFile(out / "aloe_mask2_depth.tif") as tf:
        meta = json.loads(tf.pages[0].description)
    assert meta["unit"] == "m" and 0.03 < meta["truth_unknown_fraction"] < 0.04
    flags = tifffile.imread(out / "aloe_mask2_depth-flags.tif")
    assert flags.dtype == np.uint8 and set(np.unique(flags)) <= set(range(32)) | {255}
    z = frame.z_mask
    assert np.all(flags[~z] == 255) and np.mean(flags[z] == 0) > 0.75   # 255: no measurement
    preview = iio.imread(out / "aloe_mask2_depth.png")
    assert preview.dtype == np.uint8 and preview.ndim == 3 and preview.shape[0] > 300
    no_taps = tmp_path / "plain.npz"
    frameio.save_frame(no_taps, rz.mosaic(np.zeros((8, 8, 3)), "mask1"))
    assert main(["depth", str(no_taps), "--out", str(out)]) == 2
    assert "holds no ToF taps" in capsys.readouterr().err


def test_evaluate_skip_bad_and_limit(tmp_path, capsys):
    import imageio.v3 as iio

    ds = tmp_path / "ds"
    ds.mkdir()
    iio.imwrite(ds / "a.png", np.random.default_rng(0).integers(0, 256, (32, 32, 3),
                                                                 dtype=np.uint8))
    (ds / "b.png").write_bytes(b"not a png")
    iio.imwrite(ds / "c.png", np.zeros((32, 32), np.uint8))            # grey
    base = ["evaluate", "--dataset", str(ds), "--metrics", "cfa_psnr", "--methods", "sg",
            "--patterns", "mask1", "--processes", "1", "--no-cache", "--out",
            str(tmp_path / "o"), "--quiet"]
    assert main(base) == 2
    assert "dataset: cannot read" in capsys.readouterr().err
    assert main(base + ["--skip-bad"]) == 0
    cap = capsys.readouterr()
    skipped = [line for line in cap.err.splitlines() if "skipped" in line]
    assert len(skipped) == 2 and "skipped b: --dataset: cannot read" in skipped[0]
    assert "skipped c: --dataset: " in skipped[1] and "--grey" in skipped[1]
    assert "Skipped 2 image(s)" in (tmp_path / "o" / "summary.md").read_text()
    for bad in ("0", "-1"):
        with pytest.raises(SystemExit):
            main(base + ["--limit", bad])
        assert "argument --limit: expected a positive integer" in capsys.readouterr().err


def _options(parser):
    import argparse

    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from ((f"{name} {o}", a) for o, a in _options(sub))
        elif action.option_strings and action.dest not in ("help", "version"):
            yield action.option_strings[-1], action


def test_every_option_has_help_with_its_default_in_user_words(capsys):
    """Help text and its default for every option of every command; no source-tree, Python or
    tracker words."""
    import argparse

    from rgbz_fast._cli import build_parser
    from rgbz_fast._cli._common import Formatter

    ap = build_parser()
    banned = re.compile(r"rgbz_fast\.|\.py\b|docs/|csrc|tests/|\bissue\b|\bB\d+\b|=\)",
                        re.IGNORECASE)
    shown = Formatter("rgbz-fast")
    names = []
    for name, action in _options(ap):
        names.append(name)
        assert action.help and len(action.help) > 10, name
        flag = isinstance(action, (argparse._StoreTrueAction, argparse._StoreConstAction))
        if action.required:
            assert "required" in action.help, name
        elif not flag:
            assert "default" in shown._get_help_string(action), name
        assert not banned.search(action.help), (name, action.help)
    assert "reconstruct --rgbz-pattern" in names and "depth --range" in names
    assert {"bench --kernels", "opcount --image", "tradeoff --dataset"} <= set(names)


def test_shared_options_read_the_same_in_every_command():
    """An option that several commands take has one text (written once, in _cli/_common.py)."""
    ap = build_parser_options()
    for flag in ("--workers", "--max-pixels", "--max-bytes", "--limit", "--patterns",
                 "--clip-level", "--filters", "--domain", "--grey"):
        texts = {a.help for name, a in ap if name.split()[1] == flag}
        # --workers: the kernels', evaluate's (1 while images run side by side), the
        # measuring tools' runs, hardware's frames side by side; --limit: of the dataset,
        # or of each of train's folders
        assert len(texts) <= (4 if flag == "--workers" else 2), (flag, texts)
    workers = {name.split()[0]: a for name, a in ap if name.endswith(" --workers")}
    assert set(workers) == {"reconstruct", "depth", "evaluate", "bench", "tradeoff",
                            "pattern-study", "hardware"}
    assert len({a.type for a in workers.values()}) == 1      # one rule: a positive integer


def build_parser_options():
    from rgbz_fast._cli import build_parser

    return list(_options(build_parser()))


def test_help_names_the_default_output_folders(capsys):
    readme = (REPO / "README.md").read_text()
    for cmd, folder in (("simulate", "rgbz_frames"), ("reconstruct", "rgbz_out"),
                        ("depth", "rgbz_depth"), ("evaluate", "rgbz_results")):
        with pytest.raises(SystemExit):
            main([cmd, "--help"])
        assert f"(default: {folder})" in capsys.readouterr().out
        assert folder in readme, folder


def test_train_then_evaluate_with_the_filters(tmp_path, capsys):
    """rgbz-fast train writes filters that evaluate takes with --filters."""
    import imageio.v3 as iio
    import skimage.data

    data = tmp_path / "images"
    data.mkdir()
    iio.imwrite(data / "a.png", skimage.data.astronaut()[:64, :96])
    iio.imwrite(data / "b.png", skimage.data.coffee()[:64, :96])
    out = tmp_path / "f.npz"
    assert main(["train", "--dataset", str(data), "--pattern", "mask2", "--out", str(out),
                 "--strength", "1", "--coherence", "1", "--spread", "1", "--quiet"]) == 0
    f = rz.reconstruction.LearnedFilters.load(out)
    assert f.pattern == rz.mask2() and f.meta["training_set"] == "images"
    assert f.meta["n_images"] == 2 and f.n_buckets == 8
    # several folders, both encodings: every image twice
    more = tmp_path / "more"
    more.mkdir()
    iio.imwrite(more / "c.png", skimage.data.chelsea()[:64, :96])
    both = tmp_path / "both.npz"
    assert main(["train", "--dataset", str(data), "--dataset", str(more), "--pattern", "mask1",
                 "--out", str(both), "--encoding", "both", "--strength", "1", "--coherence",
                 "1", "--spread", "2", "--quiet"]) == 0
    g = rz.reconstruction.LearnedFilters.load(both)
    assert g.meta["training_set"] == "images+more" and g.meta["encoding"] == "linear+srgb"
    assert g.meta["n_images"] == 6 and g.n_buckets == 16
    assert main(["evaluate", "--dataset", str(data), "--patterns", "mask2", "--methods",
                 "bilinear,learned", "--metrics", "cfa_psnr", "--filters", str(out),
                 "--out", str(tmp_path / "res"), "--no-plots", "--quiet",
                 "--processes", "1"]) == 0
    assert "learned" in capsys.readouterr().out
    # a pattern neither the given filters nor the shipped ones fit: one line, status 2
    assert main(["evaluate", "--dataset", str(data), "--patterns", "rows", "--methods",
                 "learned", "--metrics", "cfa_psnr", "--filters", str(out), "--out",
                 str(tmp_path / "res2"), "--no-plots", "--quiet", "--processes", "1"]) == 2
    err = capsys.readouterr().err
    assert re.match(r"^rgbz-fast evaluate: error: --filters: none of the given learned filters "
                    r"fits pattern 'rows' \(given: mask2\)", err)
    assert main(["train", "--dataset", str(tmp_path / "nope"), "--pattern", "mask1",
                 "--out", str(tmp_path / "g.npz")]) == 2
    assert not (tmp_path / "g.npz").exists()


def test_depth_full_resolution_writes_a_depth_at_every_pixel(tmp_path, capsys):
    """--full-resolution guides the ToF ISP with the frame's colour image and writes
    upsample_depth's map (float32 TIFF), its preview and its confidence (float32 TIFF)."""
    import tifffile

    scene = rz.simulation.Scene(np.full((32, 48, 3), 0.5),
                                depth=np.where(np.arange(48) < 24, 1.0, 2.0)[None, :].repeat(32, 0))
    frame = rz.simulate(scene, "mask2", seed=2)
    path = tmp_path / "step.npz"
    frameio.save_frame(path, frame)
    assert main(["depth", str(path), "--out", str(tmp_path), "--full-resolution"]) == 0
    assert ("step_depth-full.tif, step_depth-full.png, step_depth-full-confidence.tif"
            in capsys.readouterr().out)
    full = tifffile.imread(tmp_path / "step_depth-full.tif")
    conf = tifffile.imread(tmp_path / "step_depth-full-confidence.tif")
    frame = frameio.load_frame(path)                  # as the command reads it
    guide = rz.ColourISP().run(frame)
    want, want_conf = rz.tof.upsample_depth(rz.tof_depth(frame.tof, guide=guide), guide)
    np.testing.assert_array_equal(full, want)
    np.testing.assert_array_equal(conf, want_conf)
    assert full.shape == (32, 48) and (tmp_path / "step_depth-full.png").stat().st_size > 0


def test_depth_validity_options_reach_the_isp(tmp_path, capsys):
    """--flying-step off / --max-sigma off keep measurements the defaults flag; the depth TIFF
    equals tof_depth with the same settings."""
    import tifffile

    scene = rz.simulation.Scene(np.full((32, 48, 3), 0.5),
                                depth=np.where(np.arange(48) < 24, 1.0, 2.0)[None, :].repeat(32, 0))
    frame = rz.simulate(scene, "mask1", seed=2)
    path = tmp_path / "step.npz"
    frameio.save_frame(path, frame)
    for extra, kw in (([], {}), (["--flying-step", "off", "--max-sigma", "off"],
                                 {"flying_step": None, "max_sigma": None})):
        out = tmp_path / ("a" if not extra else "b")
        assert main(["depth", str(path), "--out", str(out), "--quiet", *extra]) == 0
        depth = tifffile.imread(out / "step_depth.tif")
        want = rz.tof_depth(frame.tof, **kw).depth_map().astype(np.float32)
        np.testing.assert_array_equal(depth, want)
    a = tifffile.imread(tmp_path / "a" / "step_depth.tif")
    b = tifffile.imread(tmp_path / "b" / "step_depth.tif")
    assert np.isfinite(b).sum() > np.isfinite(a).sum()      # the step's flying pixels kept


def test_read_limits_reach_every_reader_as_arguments(tmp_path, capsys, monkeypatch):
    """--max-pixels is passed to the readers (into evaluate's worker processes too), not
    through the environment, and the advice of their errors is given as flags."""
    import os

    import imageio.v3 as iio

    monkeypatch.delenv("RGBZ_FAST_MAX_PIXELS", raising=False)
    ds = tmp_path / "ds"
    ds.mkdir()
    for name in ("a", "b"):
        iio.imwrite(ds / f"{name}.png", np.random.default_rng(0).integers(
            0, 256, (32, 32, 3), dtype=np.uint8))
    advice = "raise it with --max-pixels or RGBZ_FAST_MAX_PIXELS"
    assert main(["simulate", str(ds / "a.png"), "--max-pixels", "100", "--out",
                 str(tmp_path / "f"), "--quiet"]) == 2
    assert capsys.readouterr().err.strip().endswith(advice)
    assert main(["evaluate", "--dataset", str(ds), "--max-pixels", "100", "--processes", "2",
                 "--skip-bad", "--no-cache", "--metrics", "cfa_psnr", "--methods", "bi",
                 "--patterns", "mask1", "--out", str(tmp_path / "e"), "--quiet"]) == 2
    err = capsys.readouterr().err.splitlines()
    assert [line.split(": ", 2)[1] for line in err[:2]] == ["skipped a", "skipped b"]
    assert all(line.endswith(advice) for line in err[:2])
    assert err[-1].startswith("rgbz-fast evaluate: error: --dataset: none of the 2 image(s)")
    assert main(["train", "--dataset", str(ds), "--max-pixels", "100", "--out",
                 str(tmp_path / "t.npz"), "--quiet"]) == 2
    assert capsys.readouterr().err.strip().endswith(advice)
    assert "RGBZ_FAST_MAX_PIXELS" not in os.environ
    assert main(["simulate", str(ds / "a.png"), "--max-pixels", "1024", "--out",
                 str(tmp_path / "f"), "--quiet"]) == 0


def test_a_flag_repeated_as_it_is_means_the_same(tmp_path, capsys):
    """--quiet --quiet is harmless (scripts append common flags); --noise --no-noise is not."""
    img = tmp_path / "a.png"
    import imageio.v3 as iio

    iio.imwrite(img, np.random.default_rng(0).integers(0, 256, (16, 16, 3), dtype=np.uint8))
    assert main(["simulate", str(img), "--quiet", "--quiet", "--out", str(tmp_path / "o")]) == 0
    with pytest.raises(SystemExit) as e:             # a usage error, after the usage lines
        main(["simulate", str(img), "--noise", "--no-noise", "--out", str(tmp_path / "o")])
    assert e.value.code == 2
    assert "--noise, --no-noise: given twice" in capsys.readouterr().err


def test_opcount_image_size_is_checked_per_pattern(tmp_path, capsys):
    """A 7x40 image counts Mask1 (its crop holds interior Z sites; any side under 16 had been
    refused) and is refused for Mask2 by name; mask1_rggb gets Table 1's Mask1 row."""
    import imageio.v3 as iio

    img = tmp_path / "small.png"
    iio.imwrite(img, np.random.default_rng(0).integers(0, 256, (7, 40, 3), dtype=np.uint8))
    assert main(["opcount", "--image", str(img), "--patterns", "mask1_rggb", "--methods", "sg",
                 "--text", "--shape", "32x32"]) == 0
    out = capsys.readouterr().out
    assert "/ 72 ×0.56" in out
    assert main(["opcount", "--image", str(img), "--patterns", "mask2", "--methods", "sg"]) == 2
    assert ("--image: small.png is 7x40; pattern 'mask2' needs a crop of at least 8x8 whole "
            "periods") in capsys.readouterr().err
