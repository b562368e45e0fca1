"""Golden outputs: a grid of reconstructions, ToF depths, ISP images and evaluate tables.

Run ``python tests/golden/make_golden.py`` to (re)write ``tests/golden/golden.npz``
(``python tests/golden/make_golden.py tof/mask1 sim/`` recomputes only the cases whose
names start with the prefixes given and keeps every other entry);
``tests/test_golden.py`` recomputes every entry and compares. The file was first
written before the 0.2 restructuring (issue 13) so that the restructured code
could be shown to give bit-identical results; regenerate it only for a
deliberate, documented change of results, and say which entries changed and why
in the commit message.

Entries
-------
* ``recon/...``: SHA-256 of the output bytes of ``reconstruct`` (C kernels only:
  exact on any machine of the same libm);
* ``sim/rng1/...``: frames of ``rng_version=1``, NumPy's random streams of rgbz-fast
  0.1, which must stay the frames that release simulated (they are its ``tof/.../noise1``
  taps and frames);
* ``tof/...``, ``isp/...``, ``eval/...``, ``sim/...``: the arrays themselves.
  These pass through NumPy's and SciPy's transcendental functions (and FFTs),
  whose SIMD code paths may differ by an ulp between CPUs and releases: the
  test compares them exactly when the platform fingerprint matches the one
  recorded here, and to ``rtol=1e-9`` (images and the digital numbers of
  ``sim/``: 1 code value) otherwise.
"""

from __future__ import annotations

import hashlib
import json
import sys
import tempfile
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
GOLDEN = HERE / "golden.npz"


# ----------------------------------------------------------------------------- adapter
# The only place that names where things live in the package.
def api():
    import rgbz_fast as rz
    from rgbz_fast import evaluation, isp, metrics
    from rgbz_fast.simulation import Optics, Scene, ToFSensor

    return {
        "mosaic": rz.mosaic,
        "reconstruct": rz.reconstruct,
        "simulate": rz.simulate,
        "Scene": Scene,
        "Optics": Optics,
        "ToFSensor": ToFSensor,
        "tof_depth": rz.tof_depth,
        "ColourISP": rz.ColourISP,
        "Reconstruction": isp.Reconstruction,
        "demosaic": isp.demosaic,
        "EvalConfig": evaluation.EvalConfig,
        "evaluate": evaluation.evaluate,
        "folder_dataset": rz.io.folder_dataset,
        "metrics": metrics,
    }


# ----------------------------------------------------------------------------- inputs
def base_rgb(shape=(60, 80)):
    """A crop of scikit-image's astronaut: edges, texture, flat areas."""
    import skimage.data

    return np.ascontiguousarray(skimage.data.astronaut()[150:150 + shape[0],
                                                         200:200 + shape[1]])


PATTERNS = ("mask1", "mask2", "rows", "mask1_rggb", "mask2_bggr", "GZGR/BGBG",
            "GRGR/BGBG/GRZR/BGBG")
METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg")
DTYPES = ("uint8", "uint16", "float32", "float64")


def _frames(a):
    """{(pattern, dtype): frame} of the base image."""
    rgb = base_rgb()
    out = {}
    for p in PATTERNS:
        for dt in DTYPES:
            bits = 8 if dt == "uint8" else 11
            out[p, dt] = a["mosaic"](rgb, p, bits, dtype=np.dtype(dt))
    return out


def _recon_cases(a):
    """(name, callable -> ndarray) of the reconstruction grid."""
    frames = _frames(a)
    rec = a["reconstruct"]
    cases = []
    for (p, dt), fr in frames.items():
        methods = METHODS + (("edi_rows",) if p == "rows" else ())
        for m in methods:
            for prec in ("float32", "float64"):
                cases.append((f"recon/{p}/{dt}/{m}/{prec}",
                              lambda fr=fr, m=m, prec=prec: rec(fr, m, precision=prec)))
    # the options, on the uint16 frames of the two masks
    variants = {
        "sg_pure": dict(sg_mode="pure"), "sg_combined": dict(sg_mode="combined"),
        "exp_libm": dict(exp="libm"), "exp_fast": dict(exp="fast"),
        "cd": dict(domain="colour_difference"), "rel0": dict(sigma_rel=0.0),
        "floor": dict(sigma_floor=3.0, sigma_rel=0.25),
        "clip": dict(clip_level=1500.0),
    }
    for p in ("mask1", "mask2", "GZGR/BGBG"):
        for dt in ("uint16", "float64"):
            fr = frames[p, dt]
            for vname, kw in variants.items():
                for m in ("bi", "edi_line", "sg", "edi_central", "bilinear"):
                    if vname == "cd" and m == "bilinear":
                        continue                  # refused (H75): the weighted methods' domain
                    for prec in ("float32", "float64"):
                        cases.append((f"recon/{p}/{dt}/{m}/{prec}/{vname}",
                                      lambda fr=fr, m=m, prec=prec, kw=kw:
                                      rec(fr, m, precision=prec, **kw)))
    # a wider frame: whole blocks of sites in every kernel (rows of 272 Mask1 sites)
    import skimage.data
    wide = np.ascontiguousarray(skimage.data.astronaut()[100:196, :])
    wide = np.concatenate([wide, wide[:, ::-1]], axis=1)[:, :544]
    for p in ("mask1", "mask2", "rows"):
        fr = a["mosaic"](wide, p, 11)
        for m in METHODS + (("edi_rows",) if p == "rows" else ()):
            for prec in ("float32", "float64"):
                cases.append((f"recon/wide/{p}/{m}/{prec}",
                              lambda fr=fr, m=m, prec=prec: rec(fr, m, precision=prec)))
    fr = frames["rows", "uint16"]
    cases.append(("recon/rows/uint16/edi_rows/float32/clip",
                  lambda: rec(fr, "edi_rows", clip_level=1200.0)))
    cases.append(("recon/rows/uint16/edi_rows/float64/edge",
                  lambda: rec(fr, "edi_rows", precision="float64", edge_ratio=0.8)))
    return cases


def _depth_scene(a, shape=(48, 64)):
    """A slanted wall with a box in front and a strip of unknown depth."""
    rng = np.random.default_rng(7)
    rgb = base_rgb(shape).astype(np.float64) / 255.0
    yy, xx = np.mgrid[0:shape[0], 0:shape[1]]
    depth = 1.0 + 0.02 * xx + 0.01 * yy
    depth[10:30, 20:44] = 0.8
    valid = np.ones(shape, bool)
    valid[:, -3:] = False
    ir = 0.3 + 0.4 * rng.random(shape)
    return a["Scene"](rgb ** 2.2, depth=depth, depth_valid=valid, ir_reflectance=ir)


def _tof_cases(a):
    sc = _depth_scene(a)
    cases = []
    for p in ("mask1", "mask2", "rows"):
        for noise in (False, True):
            def run(p=p, noise=noise):
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    fr = a["simulate"](sc, p, seed=3, noise=noise)
                out = {"taps": np.asarray(fr.tof.taps, np.float64),
                       "cfa": np.asarray(fr.data, np.float64)}
                # 0: no denoise, 1: the default (bilateral), 2: the paper's box
                for key, dn in ((0, False), (1, True), (2, "box")):
                    d = a["tof_depth"](fr.tof, denoise=dn)
                    for k in ("depth", "residual", "amplitude", "snr", "sigma", "reflectance"):
                        out[f"{k}_{key}"] = np.asarray(getattr(d, k), np.float64)
                    out[f"flags_{key}"] = d.flags.astype(np.float64)
                return out
            cases.append((f"tof/{p}/noise{int(noise)}", run))

    # the random numbers of rgbz-fast 0.1 (rng_version=1): its frames, bit for bit
    for p in ("mask1", "mask2", "rows"):
        def rng1(p=p):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                fr = a["simulate"](sc, p, seed=3, noise=True, rng_version=1)
            return {"taps": np.asarray(fr.tof.taps, np.float64),
                    "cfa": np.asarray(fr.data, np.float64)}
        cases.append((f"sim/rng1/{p}", rng1))

    def optics_case():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fr = a["simulate"](sc, "mask2", seed=3, noise=True,
                               optics=a["Optics"](f_number=4.0, olpf=1.0, defocus_um=5.0))
        return {"cfa": np.asarray(fr.data, np.float64),
                "taps": np.asarray(fr.tof.taps, np.float64)}
    cases.append(("sim/optics/mask2", optics_case))

    def nonideal_case():
        sensor = a["ToFSensor"](harmonics=((3, 0.04, 0.3), (5, 0.01, 0.0)),
                                tap_contrast=(1.0, 0.97, 1.02, 0.99),
                                modulation_contrast=(0.85, 0.8, 0.7), delay_ps=200.0,
                                delay_fpn_ps=20.0, multipath=(0.1, 0.4),
                                ambient_irradiance=15.0, ambient_suppression=0.9,
                                duty_cycle=0.1)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fr = a["simulate"](sc, "mask2", tof_sensor=sensor, seed=3, noise=True)
        d = a["tof_depth"](fr.tof)
        return {"taps": np.asarray(fr.tof.taps, np.float64), "depth": d.depth,
                "sigma": d.sigma, "flags": d.flags.astype(np.float64)}
    cases.append(("tof/nonideal/mask2", nonideal_case))
    return cases


def _isp_cases(a):
    sc = _depth_scene(a)
    cases = []
    for p in ("mask1", "mask2"):
        for m in ("sg", "edi_line"):
            def run(p=p, m=m):
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    fr = a["simulate"](sc, p, seed=5, noise=True)
                chain = a["ColourISP"](reconstruction=a["Reconstruction"](method=m))
                ref, test = chain.run_pair(fr)
                return {"reference": ref.astype(np.float64), "test": test.astype(np.float64)}
            cases.append((f"isp/{p}/{m}", run))

    def demosaic_case():
        fr = a["mosaic"](base_rgb(), "bayer", 11)
        out = {}
        for dt in ("float32", "float64"):
            for mode in ("reflect", "period"):
                out[f"{dt}_{mode}"] = np.asarray(a["demosaic"](fr.data, "GRBG", mode=mode,
                                                               dtype=dt), np.float64)
        return out
    cases.append(("isp/demosaic_malvar", demosaic_case))
    return cases


def _eval_cases(a):
    import imageio.v3 as iio
    import skimage.data

    def run(noise):
        with tempfile.TemporaryDirectory() as d:
            for name in ("astronaut", "coffee"):
                img = getattr(skimage.data, name)()[:184, :184]
                iio.imwrite(Path(d) / f"{name}.png", img)
            ds = a["folder_dataset"](d)
            metrics = ("cfa_psnr", "cpsnr", "ssim", "ms_ssim", "zipper") if not noise else \
                ("cfa_psnr", "cpsnr")
            cfg = a["EvalConfig"](metrics=metrics, noise=noise, seed=2)
            res = a["evaluate"](ds, cfg, processes=1, progress=False)
            rows = sorted((r["image"], r["pattern"], r["method"], r["metric"], r["value"])
                          for r in res.rows)
        return {"values": np.array([r[4] for r in rows], np.float64),
                "keys": np.array(["/".join(r[:4]) for r in rows])}
    return [("eval/noisefree", lambda: run(False)), ("eval/noisy", lambda: run(True))]


def all_cases(a=None):
    a = a or api()
    return _recon_cases(a) + _tof_cases(a) + _isp_cases(a) + _eval_cases(a)


def digest(arr):
    arr = np.ascontiguousarray(arr)
    h = hashlib.sha256()
    h.update(str(arr.dtype).encode() + str(arr.shape).encode())
    h.update(arr.tobytes())
    return h.hexdigest()


def fingerprint():
    """Versions and CPU features that NumPy's SIMD dispatch depends on."""
    import numpy as np
    import scipy

    try:
        from numpy._core._multiarray_umath import __cpu_features__ as feats
    except ImportError:  # pragma: no cover - NumPy 1.x
        from numpy.core._multiarray_umath import __cpu_features__ as feats
    on = sorted(k for k, v in feats.items() if v)
    try:
        import colour
        cver = colour.__version__
    except Exception:  # pragma: no cover
        cver = "?"
    return json.dumps({"numpy": np.__version__, "scipy": scipy.__version__,
                       "colour": cver, "cpu": on}, sort_keys=True)


def compute(cases):
    """{key: hexdigest or ndarray}."""
    out = {}
    for name, fn in cases:
        res = fn()
        if isinstance(res, dict):
            for k, v in res.items():
                out[f"{name}/{k}"] = np.asarray(v)
        elif name.startswith("recon/"):
            out[name] = digest(res)
        else:
            out[name] = np.asarray(res)
    return out


def main(prefixes=()):
    """Write the golden file; with name ``prefixes`` recompute only the cases whose names
    start with one and keep every other entry of the existing file."""
    cases = all_cases()
    if prefixes:
        cases = [c for c in cases if c[0].startswith(tuple(prefixes))]
        if not cases:
            raise SystemExit(f"no golden case starts with {', '.join(prefixes)}")
    values = compute(cases)
    arrays = {}
    hashes = {}
    if prefixes:
        old = np.load(GOLDEN, allow_pickle=False)
        hashes = json.loads(str(old["__hashes__"]))
        arrays = {k: old[k] for k in old.files if not k.startswith("__")
                  and not any(k.startswith(p) for p in prefixes)}
        hashes = {k: v for k, v in hashes.items() if not k.startswith(tuple(prefixes))}
    for k, v in values.items():
        if isinstance(v, str):
            hashes[k] = v
        else:
            arrays[k] = v
    arrays["__hashes__"] = np.array(json.dumps(hashes, sort_keys=True))
    arrays["__fingerprint__"] = np.array(fingerprint())
    np.savez_compressed(GOLDEN, **arrays)
    print(f"wrote {GOLDEN}: {len(hashes)} hashes, {len(arrays) - 2} arrays")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
