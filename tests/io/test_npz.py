"""The NPZ writer (rgbz_fast.io._npz.npz_bytes): archives that numpy.load, zipfile and
rgbz_fast.io.read_npz read back to the same arrays, the same bytes on any thread count, the
zip64 path, and frames and calibrations saved through it."""

from __future__ import annotations

import io
import zipfile

import numpy as np
import pytest

from rgbz_fast.io import read_npz
from rgbz_fast.io import _npz


def _arrays(rng, big=False):
    n = 1_000_000 if big else 1000
    return {"data": rng.integers(0, 2048, (n // 1000, 1000), dtype=np.uint16),
            "header": np.array('{"format": "x", "bit_depth": 11}'),
            "taps": rng.integers(0, 4096, (3, 4, n // 4), dtype=np.uint16),
            "rows": np.arange(n // 4, dtype=np.int64),
            "depth": rng.random(n // 4),
            "valid": rng.random(n // 4) < 0.5,
            "empty": np.zeros((0, 3)),
            "fortran": np.asfortranarray(rng.random((7, 5))),
            "scalar": np.float64(2.5)}


def _check(blob, arrays, tmp_path):
    assert zipfile.ZipFile(io.BytesIO(blob)).testzip() is None
    back = np.load(io.BytesIO(blob))
    assert back.files == list(arrays)
    for k, a in arrays.items():
        a = np.asanyarray(a)
        assert back[k].dtype == a.dtype and back[k].shape == a.shape, k
        np.testing.assert_array_equal(back[k], a)
    assert np.isfortran(back["fortran"])
    path = tmp_path / "a.npz"
    path.write_bytes(blob)
    got = read_npz(path)
    assert list(got) == list(arrays)
    for k, a in arrays.items():
        np.testing.assert_array_equal(got[k], np.asanyarray(a))


@pytest.mark.parametrize("big", [False, True], ids=["small", "threaded"])
def test_archives_read_back_and_do_not_depend_on_threads(big, tmp_path):
    arrays = _arrays(np.random.default_rng(1), big)
    blobs = [_npz.npz_bytes(arrays, workers=w) for w in (1, 2)]
    assert blobs[0] == blobs[1]
    _check(blobs[0], arrays, tmp_path)
    # deflated members, no larger than numpy's own level-6 archive by more than a few %
    ref = io.BytesIO()
    np.savez_compressed(ref, **arrays)
    assert all(i.compress_type == zipfile.ZIP_DEFLATED
               for i in zipfile.ZipFile(io.BytesIO(blobs[0])).infolist())
    if big:
        assert len(blobs[0]) < 1.05 * len(ref.getvalue())


def test_archives_past_4_gib_take_the_zip64_path(monkeypatch, tmp_path):
    """A member or an offset past the 32-bit fields goes through zipfile (zip64 records):
    the limit lowered to a few bytes stands in for 4 GiB of arrays."""
    arrays = _arrays(np.random.default_rng(2))
    ours = zipfile.ZipFile(io.BytesIO(_npz.npz_bytes(arrays))).infolist()
    monkeypatch.setattr(_npz, "_LIMIT", 64)
    blob = _npz.npz_bytes(arrays)
    _check(blob, arrays, tmp_path)
    # zipfile's records (made on Unix) rather than this module's (MS-DOS, no extra fields)
    assert {i.create_system for i in ours} == {0}
    assert {i.create_system for i in zipfile.ZipFile(io.BytesIO(blob)).infolist()} == {3}


def test_objects_and_bad_thread_counts_are_refused():
    with pytest.raises(ValueError, match="pickle"):
        _npz.npz_bytes({"x": np.array([{"a": 1}], dtype=object)})
    for bad, exc in ((0, ValueError), (-1, ValueError), (1.5, TypeError), (True, TypeError),
                     ("2", TypeError)):
        with pytest.raises(exc, match="workers"):
            _npz.npz_bytes({"x": np.zeros(3)}, workers=bad)


def test_frames_and_calibrations_round_trip(tmp_path):
    import rgbz_fast as rz
    from rgbz_fast.simulation import Scene, ToFSensor, simulate
    from rgbz_fast.tof import ToFCalibration

    rng = np.random.default_rng(3)
    scene = Scene(rng.random((40, 48, 3)), depth=1.0 + rng.random((40, 48)))
    frame = simulate(scene, "mask1", tof_sensor=ToFSensor(), seed=2)
    path = rz.io.save_frame(tmp_path / "f.npz", frame)
    back = rz.io.load_frame(path)
    np.testing.assert_array_equal(back.data, frame.data)
    np.testing.assert_array_equal(back.reference, frame.reference)
    np.testing.assert_array_equal(back.tof.taps, frame.tof.taps)
    np.testing.assert_array_equal(back.tof.depth_true, frame.tof.depth_true)
    cal = ToFCalibration(frequencies=np.array([80e6, 100e6]), offsets=np.ones((2, 3)),
                         coefficients=np.zeros((2, 1, 2)), sites=(np.arange(3), np.arange(3)),
                         block=1, shape=(4, 4))
    c = ToFCalibration.load(cal.save(tmp_path / "c.npz"))
    np.testing.assert_array_equal(c.offsets, cal.offsets)


def test_a_damaged_member_of_a_large_archive_is_named(tmp_path):
    """Members of 4 MiB and more are inflated on threads: a damaged one still gives the
    reader's error naming the file, whichever thread met it."""
    arrays = _arrays(np.random.default_rng(6), big=True)
    blob = bytearray(_npz.npz_bytes(arrays))
    info = zipfile.ZipFile(io.BytesIO(bytes(blob))).getinfo("taps.npy")
    start = info.header_offset + 30 + len("taps.npy")
    blob[start + 1000:start + 1400] = bytes(400)           # inside the deflate stream
    path = tmp_path / "bad.npz"
    path.write_bytes(bytes(blob))
    with pytest.raises(ValueError, match=r"path: .*bad\.npz is not a readable NPZ archive"):
        read_npz(path)
    assert list(read_npz(path, keys=["data", "rows"])) == ["data", "rows"]
