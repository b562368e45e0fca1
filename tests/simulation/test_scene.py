"""Scenes and their loaders: encodings, depth/disparity, IR estimate, file errors."""

from __future__ import annotations


import numpy as np
import pytest

from _support import shared_path  # noqa: E402

from rgbz_fast.simulation import (CAVE_WAVELENGTHS, Scene, disparity_to_depth,  # noqa: E402
                             estimate_ir_reflectance, load_image, load_rgbd, load_scene,
                             load_spectral, srgb_to_linear)

iio = pytest.importorskip("imageio.v3")


# -- encodings ------------------------------------------------------------------
def test_srgb_eotf_known_values():
    v = np.array([0.0, 0.04045, 0.5, 1.0])
    expected = np.array([0.0, 0.04045 / 12.92, ((0.5 + 0.055) / 1.055) ** 2.4, 1.0])
    np.testing.assert_allclose(srgb_to_linear(v), expected, rtol=1e-12)
    x = np.linspace(0, 1, 1001)
    assert np.all(np.diff(srgb_to_linear(x)) > 0)


@pytest.mark.parametrize("dtype,top", [(np.uint8, 255), (np.uint16, 65535)])
def test_integer_rgb_is_srgb_and_linearised(dtype, top):
    img = np.zeros((2, 2, 3), dtype)
    img[0, 0] = top
    img[1, 1] = top // 2
    s = Scene(img)
    assert s.image.dtype == np.float64 and not s.is_spectral and not s.has_depth
    assert s.image[0, 0, 0] == 1.0 and s.image[0, 1, 0] == 0.0
    np.testing.assert_allclose(s.image[1, 1, 0], srgb_to_linear((top // 2) / top))


@pytest.mark.parametrize("dtype,bits", [(np.uint8, None), (np.uint16, None), (np.uint16, 12),
                                        (np.uint8, 5)])
def test_srgb_decode_in_c_is_the_table_look_up(dtype, bits):
    """The decoding of 8- and 16-bit images (a C look-up on the threads) gives NumPy's
    look-up of the same table, value for value; any layout, sizes around the threads'
    split; a Scene of it skips the range checks its values cannot fail."""
    from rgbz_fast import _kernels
    from rgbz_fast.simulation._scene import srgb_decode, srgb_decode_table

    top = (1 << (bits or 8 * np.dtype(dtype).itemsize)) - 1
    rng = np.random.default_rng(top)
    table = srgb_decode_table(bits or 8 * np.dtype(dtype).itemsize)
    for shape in ((1, 1, 3), (7, 5, 3), (300, 301, 3), (1, (1 << 18) + 3, 3)):
        img = rng.integers(0, top + 1, shape).astype(dtype)
        img.reshape(-1)[:2] = (0, top)
        for view in (img, img[:, ::-1], np.asfortranarray(img)):
            got = srgb_decode(view, "image", bits)
            assert got.flags.c_contiguous and got.dtype == np.float64
            np.testing.assert_array_equal(got, table[view])
        np.testing.assert_array_equal(Scene(img, input_bits=bits).image, table[img])
    if bits is not None:
        # a code beyond the table: refused by the Scene's bits check, and by the kernel
        out = np.empty(3)
        assert not _kernels.decode_lookup(np.array([0, top + 1, 1], dtype), table, out, 1)
        with pytest.raises(ValueError, match=r"^image: integer values span \[0, "):
            Scene(np.array([[[0, top + 1, 1]]], dtype), input_bits=bits)


def test_float_rgb_is_linear_and_encodings_explicit():
    img = np.full((2, 2, 3), 0.5)
    assert Scene(img).image[0, 0, 0] == 0.5
    assert Scene.from_rgb(img, encoding="linear").image[0, 0, 0] == 0.5
    np.testing.assert_allclose(Scene.from_rgb(img, encoding="srgb").image, srgb_to_linear(img))
    u8 = np.full((2, 2, 3), 51, np.uint8)
    np.testing.assert_allclose(Scene.from_rgb(u8, encoding="linear").image, 0.2)
    with pytest.raises(ValueError, match="encoding"):
        Scene.from_rgb(img, encoding="gamma")
    with pytest.raises(ValueError, match="image"):
        Scene.from_rgb(img * 3, encoding="srgb")


def test_scene_copies_inputs_and_is_read_only():
    img = np.full((4, 4, 3), 0.25)
    depth = np.full((4, 4), 2.0)
    s = Scene(img, depth=depth)
    img[:] = 0.9
    depth[:] = 5.0
    assert s.image[0, 0, 0] == 0.25 and s.depth[0, 0] == 2.0
    with pytest.raises(ValueError):
        s.image[0, 0, 0] = 1.0
    assert s.depth_valid.all() and s.depth_valid.dtype == bool


def test_scene_holds_c_order_arrays_and_simulates_the_same():
    """A scene from transposed or fancy-indexed arrays holds C-order copies (the kernels
    read rows; no copy per simulate call) and gives the frame of the C-order scene."""
    from rgbz_fast.simulation import simulate
    rng = np.random.default_rng(5)
    img = rng.random((40, 48, 3))
    depth = 1.0 + rng.random((40, 48))
    valid = rng.random((40, 48)) > 0.1
    ir = rng.random((40, 48))
    fortran = Scene(np.asfortranarray(img), depth=np.asfortranarray(depth),
                    depth_valid=np.asfortranarray(valid), ir_reflectance=np.asfortranarray(ir))
    plain = Scene(img, depth=depth, depth_valid=valid, ir_reflectance=ir)
    for name in ("image", "depth", "depth_valid", "ir_reflectance"):
        assert getattr(fortran, name).flags.c_contiguous, name
        np.testing.assert_array_equal(getattr(fortran, name), getattr(plain, name))
    a, b = (simulate(s, "mask1", seed=2) for s in (fortran, plain))
    np.testing.assert_array_equal(a.data, b.data)
    np.testing.assert_array_equal(a.tof.taps, b.tof.taps)


# -- validation -----------------------------------------------------------------
@pytest.mark.parametrize("kwargs,match", [
    (dict(depth=np.full((4, 4), -1.0)), "depth"),
    (dict(depth=np.full((4, 4), np.nan)), "depth"),
    (dict(depth=np.full((4, 4), np.inf)), "depth"),
    (dict(depth=np.zeros((4, 4))), "depth"),
    (dict(depth=np.ones((4, 5))), "depth"),
    (dict(depth=np.ones((4, 4)), depth_valid=np.ones((4, 5), bool)), "depth_valid"),
    (dict(depth_valid=np.ones((4, 4), bool)), "depth_valid"),
    (dict(ir_reflectance=np.full((4, 4), 1.5)), "ir_reflectance"),
    (dict(ir_reflectance=np.full((3, 4), 0.5)), "ir_reflectance"),
])
def test_bad_depth_and_ir_raise_naming_the_parameter(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Scene(np.full((4, 4, 3), 0.5), **kwargs)


def test_zero_depth_allowed_where_invalid():
    depth = np.ones((4, 4))
    depth[0, 0] = 0.0
    valid = depth > 0
    s = Scene(np.full((4, 4, 3), 0.5), depth=depth, depth_valid=valid)
    assert not s.depth_valid[0, 0]


@pytest.mark.parametrize("image,kwargs,match", [
    (np.full((4, 4, 2), 0.5), {}, "3 channels"),
    (np.full((4, 4), 0.5), {}, "image"),
    (np.full((4, 4, 3), -0.1), {}, "negative"),
    (np.full((4, 4, 3), np.nan), {}, "NaN"),
    (np.full((4, 4, 5), 0.5), dict(wavelengths=[400, 450, 500, 550]), "wavelengths"),
    (np.full((4, 4, 3), 0.5), dict(wavelengths=[400, 450, 450]), "increasing"),
    (np.full((4, 4, 3), 0.5), dict(wavelengths=[100, 450, 500]), "wavelengths"),
])
def test_bad_image_raises(image, kwargs, match):
    with pytest.raises(ValueError, match=match):
        Scene(image, **kwargs)


def test_spectral_scene_scaling():
    cube = np.full((2, 2, 31), 65535, np.uint16)
    s = Scene.from_spectral(cube, CAVE_WAVELENGTHS)
    assert s.is_spectral and s.image.max() == 1.0
    np.testing.assert_array_equal(s.wavelengths, np.arange(400, 701, 10))
    with pytest.raises(ValueError, match="wavelengths"):
        Scene.from_spectral(cube, None)


# -- depth from disparity ---------------------------------------------------------
def test_disparity_to_depth_formula_and_fill():
    disp = np.array([[0, 100, 100], [60, 100, 0]], np.uint8)
    depth, valid = disparity_to_depth(disp, 3740, 0.16, offset=270)
    np.testing.assert_array_equal(valid, disp != 0)
    np.testing.assert_allclose(depth[0, 1], 3740 * 0.16 / 370)
    np.testing.assert_allclose(depth[1, 0], 3740 * 0.16 / 330)
    # unknown pixels take the nearest known depth
    assert depth[0, 0] in (depth[0, 1], depth[1, 0])
    assert depth[1, 2] == depth[1, 1]


def test_disparity_errors():
    with pytest.raises(ValueError, match="invalid"):
        disparity_to_depth(np.zeros((3, 3)), 3740, 0.16)
    with pytest.raises(ValueError, match="offset"):
        disparity_to_depth(np.full((3, 3), 5.0), 3740, 0.16, offset=-10)
    with pytest.raises(ValueError, match="focal_px"):
        disparity_to_depth(np.full((3, 3), 5.0), 0, 0.16)
    with pytest.raises(ValueError, match="baseline_m"):
        disparity_to_depth(np.full((3, 3), 5.0), 3740, -1)


def test_from_rgb_with_disparity():
    disp = np.full((4, 4), 100.0)
    disp[0, 0] = 0
    s = Scene.from_rgb(np.full((4, 4, 3), 0.5), disparity=disp, focal_px=3740,
                       baseline_m=0.16, disparity_offset=270)
    assert not s.depth_valid[0, 0] and s.depth_valid.sum() == 15
    np.testing.assert_allclose(s.depth, 3740 * 0.16 / 370)
    with pytest.raises(ValueError, match="focal_px"):
        Scene.from_rgb(np.full((4, 4, 3), 0.5), disparity=disp)
    with pytest.raises(ValueError, match="not both"):
        Scene.from_rgb(np.full((4, 4, 3), 0.5), disparity=disp, depth=np.ones((4, 4)),
                       focal_px=1, baseline_m=1)


# -- IR reflectance estimate ---------------------------------------------------------
def test_ir_estimate_rgb_and_spectral():
    img = np.zeros((2, 2, 3))
    img[0, 0, 0] = 1.0
    img[0, 1, 1] = 1.0            # green only: no effect on the estimate
    ir = estimate_ir_reflectance(img)
    np.testing.assert_allclose(ir, [[0.8, 0.2], [0.2, 0.2]])
    cube = np.zeros((1, 1, 31))
    cube[..., 25:] = 0.5          # 650..700 nm
    np.testing.assert_allclose(estimate_ir_reflectance(cube, CAVE_WAVELENGTHS), 0.5)
    given = np.full((2, 2), 0.3)
    s = Scene(img, ir_reflectance=given)
    np.testing.assert_array_equal(s.ir_map(), given)
    np.testing.assert_allclose(Scene(img).ir_map(), ir)


# -- loaders -------------------------------------------------------------------------
def test_load_image_8_and_16_bit(tmp_path):
    rgb8 = np.random.default_rng(0).integers(0, 256, (6, 8, 3), dtype=np.uint8)
    iio.imwrite(tmp_path / "a.png", rgb8)
    s = load_image(tmp_path / "a.png")
    np.testing.assert_allclose(s.image, srgb_to_linear(rgb8 / 255.0))
    assert s.name == "a" and s.meta["source"].endswith("a.png")
    rgb16 = rgb8.astype(np.uint16) * 257
    iio.imwrite(tmp_path / "b.tif", rgb16)       # PIL writes no 16-bit RGB PNG
    np.testing.assert_allclose(load_image(tmp_path / "b.tif").image, s.image)
    # float: linear already (photometric named: tifffile 2023.1, the floor, warns without it)
    iio.imwrite(tmp_path / "lin.tif", rgb8 / 255.0, photometric="rgb")
    np.testing.assert_allclose(load_image(tmp_path / "lin.tif").image, rgb8 / 255.0)
    rgba = np.concatenate([rgb8, np.full((6, 8, 1), 255, np.uint8)], axis=2)
    iio.imwrite(tmp_path / "c.png", rgba)
    np.testing.assert_allclose(load_image(tmp_path / "c.png").image, s.image)


def test_load_image_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match="nope.png"):
        load_image(tmp_path / "nope.png")
    iio.imwrite(tmp_path / "grey.png", np.zeros((4, 4), np.uint8))
    with pytest.raises(ValueError, match="is a grey image"):
        load_image(tmp_path / "grey.png")
    (tmp_path / "junk.png").write_bytes(b"not an image")
    with pytest.raises(ValueError, match="junk.png"):
        load_image(tmp_path / "junk.png")


def test_load_spectral_balloons_mat():
    path = shared_path("multispectral", "balloons_ms", "balloons_ms.mat")
    s = load_spectral(path)
    assert s.shape == (256, 256) and s.image.shape[2] == 31 and s.is_spectral
    np.testing.assert_array_equal(s.wavelengths, np.arange(400, 701, 10))
    assert 0 <= s.image.min() and s.image.max() <= 1.0 and s.image.max() > 0.7
    assert s.meta["variable"] == "Omsi" and s.name == "balloons_ms"
    assert load_scene(path).image.shape == s.image.shape
    with pytest.raises(ValueError, match="variable"):
        load_spectral(path, variable="cube")
    with pytest.raises(ValueError, match="wavelengths"):
        load_spectral(path, wavelengths=np.arange(400, 701, 20))


def test_load_spectral_mat_variants(tmp_path):
    from scipy import io as sio

    cube = np.random.default_rng(1).random((4, 5, 3))
    sio.savemat(tmp_path / "one.mat", {"data": cube, "wavelengths": [450.0, 550.0, 650.0]})
    s = load_spectral(tmp_path / "one.mat")
    np.testing.assert_array_equal(s.wavelengths, [450, 550, 650])
    np.testing.assert_allclose(s.image, cube)
    sio.savemat(tmp_path / "two.mat", {"a": cube, "b": cube})
    with pytest.raises(ValueError, match="variable"):
        load_spectral(tmp_path / "two.mat")
    assert load_spectral(tmp_path / "two.mat", variable="b").image.shape == (4, 5, 3)
    (tmp_path / "bad.mat").write_bytes(b"garbage")
    with pytest.raises(ValueError, match="bad.mat"):
        load_spectral(tmp_path / "bad.mat")
    with pytest.raises(FileNotFoundError):
        load_spectral(tmp_path / "missing.mat")


def test_load_spectral_png_folder(tmp_path):
    rng = np.random.default_rng(2)
    bands = rng.integers(0, 65536, (12, 6, 7), dtype=np.uint16)
    for k in range(12):
        iio.imwrite(tmp_path / f"scene_ms_{k + 1}.png", bands[k])    # _2 < _10: natural order
    (tmp_path / "notes.txt").write_text("ignored")
    s = load_spectral(tmp_path)
    np.testing.assert_allclose(s.image, np.moveaxis(bands, 0, -1) / 65535.0)
    np.testing.assert_array_equal(s.wavelengths, 400 + 10 * np.arange(12))
    assert s.meta["band_files"][:3] == ["scene_ms_1.png", "scene_ms_2.png", "scene_ms_3.png"]
    assert load_scene(tmp_path).image.shape == (6, 7, 12)


def test_load_spectral_folder_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match="no PNG"):
        load_spectral(tmp_path)
    iio.imwrite(tmp_path / "b1.png", np.zeros((4, 4), np.uint16))
    iio.imwrite(tmp_path / "b2.png", np.zeros((4, 5), np.uint16))
    with pytest.raises(ValueError, match="b2.png"):
        load_spectral(tmp_path)
    (tmp_path / "b2.png").unlink()
    iio.imwrite(tmp_path / "b2.png", np.zeros((4, 4), np.uint8))
    with pytest.raises(ValueError, match="bit depth"):
        load_spectral(tmp_path)
    (tmp_path / "b2.png").unlink()
    iio.imwrite(tmp_path / "b2.png", np.zeros((4, 4, 3), np.uint8))
    with pytest.raises(ValueError, match="single-band"):
        load_spectral(tmp_path)


#: invalid-pixel fractions (%) stated in ../shared/data/rgbd/SOURCE.md
_RGBD = {"art": 0.5, "aloe": 3.1, "baby1": 0.4, "bowling1": 2.3, "flowerpots": 14.7,
         "rocks1": 4.6}


@pytest.mark.parametrize("name", sorted(_RGBD))
def test_load_rgbd_middlebury(name):
    folder = shared_path("rgbd", name)
    s = load_rgbd(folder)
    disp = iio.imread(folder / "disp1.png")
    dmin = float((folder / "dmin.txt").read_text().split()[0])
    assert s.shape == disp.shape and s.name == name and s.meta["dmin"] == dmin
    np.testing.assert_array_equal(s.depth_valid, disp != 0)
    v = disp[s.depth_valid].astype(float)
    np.testing.assert_allclose(s.depth[s.depth_valid], 3740 * 0.160 / (v + dmin))
    assert 1.1 < s.depth.min() and s.depth.max() < 2.4          # SOURCE.md: 1.15-2.36 m
    assert abs(100 * (1 - s.depth_valid.mean()) - _RGBD[name]) < 0.1


def test_load_rgbd_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match="not a folder"):
        load_rgbd(tmp_path / "none")
    iio.imwrite(tmp_path / "rgb.png", np.zeros((4, 6, 3), np.uint8))
    with pytest.raises(FileNotFoundError, match="disp1.png, dmin.txt"):
        load_rgbd(tmp_path)
    iio.imwrite(tmp_path / "disp1.png", np.full((4, 5), 10, np.uint8))
    (tmp_path / "dmin.txt").write_text("200\n")
    with pytest.raises(ValueError, match="same size"):
        load_rgbd(tmp_path)
    iio.imwrite(tmp_path / "disp1.png", np.full((4, 6), 10, np.uint8))
    assert load_scene(tmp_path).has_depth
    (tmp_path / "dmin.txt").write_text("two hundred")
    with pytest.raises(ValueError, match="dmin.txt"):
        load_rgbd(tmp_path)
    (tmp_path / "dmin.txt").write_text("200")
    iio.imwrite(tmp_path / "disp1.png", np.zeros((4, 6), np.uint8))
    with pytest.raises(ValueError, match="invalid"):
        load_rgbd(tmp_path)


@pytest.mark.parametrize("text", ["270 px", "270\n300", "2_70", "1e300", "-1", "nan"])
def test_load_rgbd_takes_one_plain_disparity_offset(tmp_path, text):
    """dmin.txt: '270 px', two numbers or '2_70' had been read as 270; 1e300 made every
    depth 0 m."""
    iio.imwrite(tmp_path / "rgb.png", np.zeros((4, 6, 3), np.uint8))
    iio.imwrite(tmp_path / "disp1.png", np.full((4, 6), 10, np.uint8))
    (tmp_path / "dmin.txt").write_text(text)
    with pytest.raises(ValueError, match=r"^folder: .*dmin.txt (should hold one number|gives "
                                         r".*; expected a disparity offset in \[0, 100000\])"):
        load_rgbd(tmp_path)


def test_load_rgbd_refuses_a_16_bit_disparity(tmp_path):
    """A 16-bit disp1.png (KITTI's convention: the disparity times 256) read as Middlebury's
    8-bit disparity gave depths 256 times too near, and a table of 0 % valid, exit 0."""
    iio.imwrite(tmp_path / "rgb.png", np.zeros((4, 6, 3), np.uint8))
    iio.imwrite(tmp_path / "disp1.png", np.full((4, 6), 10 * 256, np.uint16))
    (tmp_path / "dmin.txt").write_text("200")
    with pytest.raises(ValueError, match=r"^folder: disp1.png holds uint16 samples; a "
                                         r"Middlebury 2005/2006 disparity is 8-bit grey"):
        load_rgbd(tmp_path)


def test_load_scene_dispatch_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        load_scene(tmp_path / "missing.png")
    (tmp_path / "x.xyz").write_text("?")
    with pytest.raises(ValueError, match="x.xyz"):
        load_scene(tmp_path / "x.xyz")
