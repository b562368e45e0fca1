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
    for cmd in ("simulate", "reconstruct", "evaluate", "calibrate", "evaluate-depth", "bench",
                "opcount", "tradeoff", "config"):
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
    assert "Sunlight" in out and "burst 0.1 + suppression 0.9" in out
    assert main(["evaluate-depth", "--sections", "sunlight", "--json"]) == 0
    assert "sunlight" in json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("argv, match", [
    (["calibrate"], "no frames"),
    (["calibrate", __file__], "--distances"),
    (["calibrate", "--simulate", "--shape", "16by24"], "--shape"),
    (["calibrate", "--simulate", "--sensor", "{bad json"], "--sensor: not JSON"),
    (["calibrate", "--simulate", "--sensor", '{"nope": 1}'], "--sensor: got an unexpected"),
    (["calibrate", "--simulate", "--near", "3", "--far", "1"], "--near, --far"),
    (["calibrate", "--simulate", "--positions", "1"], "--positions"),
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
    (["evaluate", "--methods", "nope"], "methods"),
    (["evaluate", "--dataset", "/nonexistent/folder"], "does not exist"),
    (["evaluate", "--workers", "0"], "workers"),
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
    assert "valid depth" in capsys.readouterr().out
