"""What a newcomer meets in the first hour, from the user's side: the commands of the README
and the guides run as a user types them, on small files made here or on the shared data
(skipped with the reason when it is absent)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from _support import shared_path  # noqa: E402

import rgbz_fast as rz  # noqa: E402
from rgbz_fast import io as frameio  # noqa: E402
from rgbz_fast._cli import main  # noqa: E402


def rgbd_folder(path, shape=(48, 64)):
    """A small Middlebury-style RGB-D scene folder: a textured image, two depth planes."""
    import imageio.v3 as iio

    path.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(3)
    iio.imwrite(path / "rgb.png", rng.integers(40, 220, shape + (3,), dtype=np.uint8))
    disp = np.full(shape, 60, np.uint8)
    disp[:, shape[1] // 2:] = 110                       # a depth step down the middle
    iio.imwrite(path / "disp1.png", disp)
    (path / "dmin.txt").write_text("270\n")
    return path


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
