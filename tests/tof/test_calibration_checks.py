"""Every field of a ToF calibration is checked where it is made, by a caller or a file: NaN,
0 or negative frequencies, float, negative or out-of-frame sites, a bool or float block, a
shape of floats, bools or three values, and a meta that is no dict are refused with a message
naming the field; repr never fails; a damaged or edited file is a ValueError naming it."""

from __future__ import annotations

import json
import re
from dataclasses import replace

import numpy as np
import pytest

from rgbz_fast.simulation import Scene, ToFSensor, simulate_tof
from _support import calibration_fields
from rgbz_fast.tof import ToFCalibration, calibrate




def _cal(**kw):
    return ToFCalibration(**calibration_fields(**kw))


BAD = [
    ("frequencies-nan", dict(frequencies=[np.nan, 100e6]), ValueError, "frequencies"),
    ("frequencies-inf", dict(frequencies=[np.inf, 100e6]), ValueError, "frequencies"),
    ("frequencies-zero", dict(frequencies=[0.0, 100e6]), ValueError, "frequencies"),
    ("frequencies-negative", dict(frequencies=[-80e6, 100e6]), ValueError, "frequencies"),
    ("frequencies-2d", dict(frequencies=[[80e6, 100e6]]), ValueError, "frequencies"),
    ("frequencies-empty", dict(frequencies=[], offsets=np.zeros((0, 3)),
                               coefficients=np.zeros((0, 1, 2))), ValueError, "frequencies"),
    ("frequencies-twice", dict(frequencies=[100e6, 100e6]), ValueError, "frequencies"),
    ("frequencies-text", dict(frequencies=["80e6", "100e6"]), TypeError, "frequencies"),
    ("frequencies-bool", dict(frequencies=[True, True]), TypeError, "frequencies"),
    ("frequencies-complex", dict(frequencies=[80e6 + 1j, 100e6]), TypeError, "frequencies"),
    ("shape-negative", dict(shape=(-4, 4)), ValueError, "shape"),
    ("shape-zero", dict(shape=(0, 4)), ValueError, "shape"),
    ("shape-float", dict(shape=(4.0, 4)), TypeError, "shape"),
    ("shape-float-array", dict(shape=np.array([4.0, 4.0])), TypeError, "shape"),
    ("shape-bool", dict(shape=(True, 4)), TypeError, "shape"),
    ("shape-three", dict(shape=(4, 4, 1)), ValueError, "shape"),
    ("shape-int", dict(shape=4), TypeError, "shape"),
    ("shape-text", dict(shape="44"), TypeError, "shape"),
    ("shape-none", dict(shape=None), TypeError, "shape"),
    ("shape-huge", dict(shape=(4, 1 << 40)), ValueError, "shape"),
    ("shape-smaller-than-block", dict(shape=(1, 4), block=2, sites=([], []),
                                      offsets=np.zeros((2, 0))),
     ValueError, "shape"),
    ("sites-row-outside", dict(sites=([0, 0, 4], [0, 2, 2])), ValueError, "sites"),
    ("sites-col-outside", dict(sites=([0, 0, 2], [0, 2, 9])), ValueError, "sites"),
    ("sites-block-overhangs", dict(block=2, sites=([0, 0, 2], [0, 2, 3])), ValueError,
     "sites"),
    ("sites-negative", dict(sites=([-1, 0, 2], [0, 2, 2])), ValueError, "sites"),
    ("sites-float-integral", dict(sites=(np.array([0.0, 0, 2]), np.array([0.0, 2, 2]))),
     TypeError, "sites"),
    ("sites-float-fraction", dict(sites=([0.5, 0, 2], [0, 2, 2])), TypeError, "sites"),
    ("sites-text", dict(sites=(np.array(["0", "0", "2"]), [0, 2, 2])), TypeError, "sites"),
    ("sites-bool", dict(sites=([False, False, True], [0, 2, 2])), TypeError, "sites"),
    ("sites-three-arrays", dict(sites=([0, 0, 2], [0, 2, 2], [0, 0, 0])), TypeError,
     "sites"),
    ("sites-lengths", dict(sites=([0, 0, 2], [0, 2])), ValueError, "sites"),
    ("sites-2d", dict(sites=([[0, 0, 2]], [[0, 2, 2]])), ValueError, "sites"),
    ("sites-twice", dict(sites=([0, 0, 0], [0, 0, 2])), ValueError, "sites"),
    ("sites-none", dict(sites=None), TypeError, "sites"),
    ("block-true", dict(block=True), ValueError, "block"),
    ("block-numpy-bool", dict(block=np.True_), ValueError, "block"),
    ("block-float", dict(block=1.0), ValueError, "block"),
    ("block-three", dict(block=3), ValueError, "block"),
    ("block-text", dict(block="1"), ValueError, "block"),
    ("meta-list", dict(meta=[("a", 1)]), TypeError, "meta"),
    ("meta-none", dict(meta=None), TypeError, "meta"),
    ("meta-int-key", dict(meta={1: 2}), TypeError, "meta"),
    ("offsets-text", dict(offsets=np.full((2, 3), "0")), TypeError, "offsets"),
    ("offsets-object", dict(offsets=np.full((2, 3), None, object)), TypeError, "offsets"),
    ("offsets-bool", dict(offsets=np.zeros((2, 3), bool)), TypeError, "offsets"),
    ("coefficients-complex", dict(coefficients=np.zeros((2, 1, 2), complex)), TypeError,
     "coefficients"),
    ("dark-text", dict(dark=np.full((4, 3), "1")), TypeError, "dark"),
    ("dark-nan", dict(dark=np.full((4, 3), np.nan)), ValueError, "dark"),
]


@pytest.mark.parametrize("kw, exc, name", [c[1:] for c in BAD], ids=[c[0] for c in BAD])
def test_a_bad_field_is_refused_naming_it(kw, exc, name):
    with pytest.raises(exc, match=f"^{name}: "):
        _cal(**kw)


def test_bool_block_and_float_shape_are_refused_not_converted():
    with pytest.raises(ValueError, match=r"^block: expected 1 or 2, got True"):
        _cal(block=True)
    with pytest.raises(ValueError, match=r"^block: expected 1 or 2, got 2\.0"):
        _cal(block=2.0)
    with pytest.raises(TypeError, match=r"^shape: expected two integers \(rows, cols\), "
                                        r"got \(4\.5, 4\)"):
        _cal(shape=(4.5, 4))


def test_out_of_frame_sites_are_refused():
    """A block of block x block pixels at every site must lie inside the frame."""
    with pytest.raises(ValueError, match=r"^sites: rows span \[0, 4\]; .* inside the 4x4 "
                                         r"frame \(rows <= 3\)"):
        _cal(sites=([0, 0, 4], [0, 2, 2]))
    with pytest.raises(ValueError, match=r"^sites: cols span \[0, 3\]; a 2x2 block .* "
                                         r"\(cols <= 2\)"):
        _cal(block=2, sites=([0, 0, 2], [0, 2, 3]))
    # the last block that fits is accepted
    cal = _cal(block=2, sites=([0, 0, 2], [0, 2, 2]))
    assert cal.shape == (4, 4) and cal.block == 2


def test_valid_values_are_normalised():
    """Lists, integral NumPy scalars and integer dtypes of any width are accepted and stored
    as int / tuple of int / own read-only int64 and float64 arrays (the caller's arrays stay
    writable)."""
    offsets = np.zeros((2, 3))
    rows = np.array([0, 0, 2], np.int32)
    cal = _cal(frequencies=[80e6, 100e6], offsets=offsets, block=np.int64(1),
               shape=np.array([4, 4], np.uint16), sites=(rows, [0, 2, 2]))
    assert cal.block == 1 and type(cal.block) is int
    assert cal.shape == (4, 4) and all(type(v) is int for v in cal.shape)
    assert cal.sites[0].dtype == np.int64 and cal.frequencies.dtype == np.float64
    assert offsets.flags.writeable and rows.flags.writeable
    assert not cal.offsets.flags.writeable and not cal.sites[1].flags.writeable
    # no sites at all is a calibration of nothing, but a consistent one
    empty = _cal(offsets=np.zeros((2, 0)), sites=([], []))
    assert empty.sites[0].size == 0 and "0 measurements" in repr(empty)


@pytest.mark.parametrize("meta", [
    {}, {"fit_rms_m": 0.5}, {"fit_rms_m": "abc"}, {"fit_rms_m": [None]},
    {"fit_rms_m": [[1e-3]]}, {"fit_rms_m": {"a": 1}}, {"fit_rms_m": []},
    {"fit_rms_m": [1e-3, "x"]}, {"fit_rms_m": [1, [2, 3]]}, {"fit_rms_m": [float("nan")]},
    {"fit_rms_m": [True]}, {"fit_rms_m": np.array([1e-3, 2e-3])}, {"x": object()},
])
def test_repr_never_fails(meta, tmp_path):
    cal = _cal(meta=meta)
    text = repr(cal)
    assert text.startswith("ToFCalibration(3 measurements, 80, 100 MHz, 1 harmonics")
    # and save keeps what JSON holds, leaving out the rest; the file loads
    back = ToFCalibration.load(cal.save(tmp_path / "c.npz"))
    assert repr(back).startswith("ToFCalibration(3 measurements")


def test_repr_shows_the_fit_rms():
    assert repr(_cal(meta={"fit_rms_m": [1e-3, 2.5e-3]})).endswith("fit RMS 2.50 mm)")
    assert "fit RMS" not in repr(_cal(meta={"fit_rms_m": 3}))


def test_save_keeps_json_meta_and_drops_the_rest(tmp_path):
    meta = {"frames": np.int64(3), "name": "wall", "flag": np.True_, "none": None,
            "rms": np.array([1e-3, 2e-3]), "labels": ["a", "b"], "mixed": [1, "a"],
            "obj": [object()], "ragged": [[1], [2, 3]], "nested": {"a": 1}}
    back = ToFCalibration.load(_cal(meta=meta).save(tmp_path / "c.npz"))
    assert back.meta == {"frames": 3, "name": "wall", "flag": True, "none": None,
                         "rms": [1e-3, 2e-3], "labels": ["a", "b"]}


def _sweep_calibration():
    sensor = ToFSensor(delay_ps=50.0, harmonics=((3, 0.05, 0.0),))
    ds = np.linspace(0.6, 2.6, 12)
    sweep = [simulate_tof(Scene(np.full((8, 8, 3), 0.5), depth=np.full((8, 8), d)), "mask2",
                          sensor, noise=False) for d in ds]
    capped = simulate_tof(Scene(np.full((8, 8, 3), 0.5), depth=np.full((8, 8), 1.0)), "mask2",
                          replace(sensor, optical_power_w=1e-12, ambient_irradiance=0.0),
                          noise=False)
    return calibrate(sweep, ds, orders=4, dark=[capped])


@pytest.fixture(scope="module")
def saved(tmp_path_factory):
    """A calibration made by calibrate (with dark offsets), its file and the file's arrays."""
    cal = _sweep_calibration()
    path = cal.save(tmp_path_factory.mktemp("cal") / "cal.npz")
    with np.load(path) as z:
        arrays = {k: z[k] for k in z.files}
    return cal, path, arrays


def test_a_calibration_from_calibrate_round_trips_bit_for_bit(saved):
    cal, path, _ = saved
    back = ToFCalibration.load(path)
    for name in ("frequencies", "offsets", "coefficients", "dark"):
        a, b = getattr(cal, name), getattr(back, name)
        assert a.dtype == b.dtype and a.tobytes() == b.tobytes(), name
    for a, b in zip(cal.sites, back.sites):
        assert a.dtype == b.dtype == np.int64 and np.array_equal(a, b)
    assert (back.block, back.shape, back.meta) == (cal.block, cal.shape, cal.meta)
    assert repr(back) == repr(cal)


def _edited(tmp_path, arrays, header=None, drop=(), **replace):
    out = {k: v for k, v in arrays.items() if k not in drop}
    out.update(replace)
    if header is not None:
        h = json.loads(str(arrays["header"]))
        h.update(header)
        for k in [k for k, v in header.items() if v is _DROP]:
            del h[k]
        out["header"] = np.array(json.dumps(h))
    path = tmp_path / "edited.npz"
    np.savez(path, **out)
    return path


_DROP = object()


def _refused(path, what):
    with pytest.raises(ValueError, match=f"^path: {re.escape(str(path))} .*{what}"):
        ToFCalibration.load(path)


@pytest.mark.parametrize("member", ["frequencies", "offsets", "coefficients", "rows", "cols",
                                    "header"])
def test_load_names_a_missing_member(saved, tmp_path, member):
    _refused(_edited(tmp_path, saved[2], drop=(member,)), member)


def test_load_without_dark_is_a_calibration_without_dark(saved, tmp_path):
    assert ToFCalibration.load(_edited(tmp_path, saved[2], drop=("dark",))).dark is None


@pytest.mark.parametrize("member, field", [("frequencies", "frequencies"),
                                           ("offsets", "offsets"),
                                           ("coefficients", "coefficients"),
                                           ("rows", "sites"), ("cols", "sites"),
                                           ("dark", "dark")])
@pytest.mark.parametrize("edit", ["text", "bool", "complex", "0-d", "empty", "nan"])
def test_load_names_a_damaged_member(saved, tmp_path, member, field, edit):
    a = saved[2][member]
    value = {"text": a.astype(str), "bool": a.astype(bool), "complex": a.astype(complex),
             "0-d": np.array(a.reshape(-1)[0]), "empty": a[:0],
             "nan": np.full(a.shape, np.nan)}[edit]
    if edit == "0-d" and member == "frequencies":
        field = "offsets"                # one frequency where the offsets have two
    elif edit == "empty" and member in ("rows", "cols"):
        field = "sites"                  # rows and cols of different lengths
    elif edit == "empty" and member == "frequencies":
        field = "frequencies"
    elif edit == "nan" and member in ("rows", "cols"):
        field = "sites"                  # float indices
    _refused(_edited(tmp_path, saved[2], **{member: value}), re.escape(f"{field}: "))


@pytest.mark.parametrize("member", ["frequencies", "rows", "offsets"])
def test_load_refuses_object_arrays_without_unpickling(saved, tmp_path, member):
    value = np.array(list(saved[2][member].ravel()), dtype=object)
    _refused(_edited(tmp_path, saved[2], **{member: value}),
             f"member {member}.npy holds Python objects")


@pytest.mark.parametrize("member", ["rows", "cols"])
def test_load_refuses_float_and_out_of_frame_sites(saved, tmp_path, member):
    a = saved[2][member]
    _refused(_edited(tmp_path, saved[2], **{member: a.astype(np.float64)}),
             "sites: expected integer pixel indices")
    _refused(_edited(tmp_path, saved[2], **{member: a + 100}), r"sites: .* span")
    _refused(_edited(tmp_path, saved[2], **{member: a - 100}), r"sites: .* >= 0")


@pytest.mark.parametrize("header, what", [
    ({"block": True}, "block: expected 1 or 2, got True"),
    ({"block": 1.5}, "block: expected 1 or 2"),
    ({"block": 2.0}, "block: expected 1 or 2"),
    ({"block": "2"}, "block: expected 1 or 2"),
    ({"block": None}, "block: expected 1 or 2"),
    ({"block": _DROP}, "lacks 'block'"),
    ({"shape": [8.0, 8]}, r"shape: expected two integers"),
    ({"shape": [True, 8]}, r"shape: expected two integers"),
    ({"shape": [8, 8, 1]}, r"shape: expected a \(rows, cols\) frame shape, got 3"),
    ({"shape": 8}, r"shape: expected a \(rows, cols\)"),
    ({"shape": None}, r"shape: expected a \(rows, cols\)"),
    ({"shape": {"a": 1}}, r"shape: expected a \(rows, cols\)"),
    ({"shape": [-8, 8]}, r"shape: expected two integers in"),
    ({"shape": [4, 4]}, r"sites: .* inside the 4x4 frame"),
    ({"shape": _DROP}, "lacks 'shape'"),
    ({"meta": [1]}, "meta: expected a dict, got list"),
    ({"meta": "x"}, "meta: expected a dict, got str"),
    ({"format": "something else"}, "not a ToF calibration file"),
])
def test_load_names_a_damaged_header(saved, tmp_path, header, what):
    _refused(_edited(tmp_path, saved[2], header=header), what)


def test_load_refuses_a_header_that_is_not_a_json_object(saved, tmp_path):
    text = str(saved[2]["header"])
    for value in (np.array([text]), np.array(3), np.array("[1]"), np.array("{"),
                  np.array("[" * 100000 + "]" * 100000)):
        _refused(_write(tmp_path, {**saved[2], "header": value}), "not a ToF calibration file")


def _write(tmp_path, arrays):
    path = tmp_path / "edited.npz"
    np.savez(path, **arrays)
    return path


def test_a_header_meta_with_odd_content_loads_and_prints(saved, tmp_path):
    for meta in ({"fit_rms_m": 3}, {"fit_rms_m": ["a"]}, {"fit_rms_m": [[1, 2]]},
                 {"fit_rms_m": None}, {}):
        back = ToFCalibration.load(_edited(tmp_path, saved[2], header={"meta": meta}))
        assert back.meta == meta and repr(back).startswith("ToFCalibration(")
    # a file without meta (none written) has an empty one
    back = ToFCalibration.load(_edited(tmp_path, saved[2], header={"meta": _DROP}))
    assert back.meta == {}
