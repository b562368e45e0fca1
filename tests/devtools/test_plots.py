"""The depth figures of ``rgbz-fast depth`` (rgbz_fast._devtools.plots) on frames larger than
the figure: drawn from every k-th pixel, the nearest measurement of each, as the full frame."""

from __future__ import annotations

import io

import numpy as np
import pytest

from rgbz_fast._devtools import plots
from rgbz_fast.simulation import Scene, simulate
from rgbz_fast.tof import tof_depth


def test_preview_step():
    assert [plots.preview_step(s) for s in [(512, 768), (1400, 1400), (1401, 80),
                                            (3000, 4000), (6000, 8000)]] == [1, 1, 2, 3, 6]


@pytest.fixture(scope="module")
def wide():
    """A 48 x 3000 Mask2 frame: longer than PREVIEW_PIXELS, quick to simulate."""
    rng = np.random.default_rng(2)
    shape = (48, 3000)
    depth = np.where(np.arange(shape[1])[None, :] < 1500, 1.2, 1.9) * np.ones((shape[0], 1))
    frame = simulate(Scene(rng.random(shape + (3,)), depth=depth), "mask2", seed=1)
    return frame, tof_depth(frame.tof)


def test_the_preview_grid_is_the_full_frames_every_kth_pixel(wide):
    from scipy import ndimage

    _, res = wide
    iy, ix = plots.nearest_measurement(res)
    k = plots.preview_step(res.shape)
    assert k == 3 and iy.shape == (16, 1000)
    measured = res.to_frame(np.ones(res.n_sites, bool), fill=False).astype(bool)
    full = ndimage.distance_transform_edt(~measured, return_distances=False,
                                          return_indices=True)
    np.testing.assert_array_equal(iy, full[0][::k, ::k])
    np.testing.assert_array_equal(ix, full[1][::k, ::k])
    # every grid pixel shows a measured pixel
    assert measured[iy, ix].all()


def test_the_figures_of_a_large_frame(wide):
    from PIL import Image

    frame, res = wide
    nearest = plots.nearest_measurement(res)
    for png in (plots.depth_preview(res, "wide", None, frame.tof.valid, nearest),
                plots.depth_preview(res, "wide"),
                plots.depth_flags_figure(res, "wide", nearest),
                plots.full_depth_preview(res.to_frame(res.depth), "wide")):
        img = Image.open(io.BytesIO(png))
        assert img.format == "PNG" and img.size[0] > 500
    assert plots.depth_preview(res, "wide", nearest=nearest) == plots.depth_preview(res, "wide")
