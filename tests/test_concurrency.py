"""Concurrency and determinism (docs/reports/robustness.md, "Concurrency and determinism").

* The same call from 8 Python threads at once equals the serial result, for
  every kernel (reconstruction, Malvar demosaic, ToF demodulation and
  unwrapping) and for the stages built on them; the kernels release the GIL.
* Results are bit-identical for every ``workers`` value (1, 2, 3, 7).
* The same seed gives the same simulation, in this process and in a fresh one;
  another seed gives another draw.
"""

from __future__ import annotations

import hashlib
import subprocess
import sys
import threading
import time
import textwrap
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest


import rgbz_fast as rz  # noqa: E402
from rgbz_fast import _kernels  # noqa: E402
from rgbz_fast import simulation as sensor  # noqa: E402
from rgbz_fast import tof as tof_isp  # noqa: E402
from rgbz_fast.isp import demosaic  # noqa: E402
from rgbz_fast.simulation import Scene  # noqa: E402

PATTERNS = {"mask1": rz.mask1, "mask2": rz.mask2, "rows": rz.rows,
            "mask1_bggr": lambda: rz.mask1("BGGR"), "custom": lambda: rz.Pattern("ZRGR/BGBG")}
METHODS = ("bilinear", "bi", "edi_central", "edi_line", "sg", "edi_rows")
CASES = [(p, m) for p in PATTERNS for m in METHODS
         if m != "edi_rows" or p in ("rows", "mask2")]
CASE_IDS = [f"{p}-{m}" for p, m in CASES]
NTHREADS = 8


def frame_for(pattern, shape=(97, 131), dtype=np.uint16, seed=0):
    d = np.random.default_rng(seed).integers(0, 2048, shape).astype(dtype)
    d[pattern.z_mask(shape)] = 0
    return d


def in_threads(fn, n=NTHREADS):
    """Run fn() n times at once (released together by a barrier); return the results."""
    barrier = threading.Barrier(n)

    def task(_):
        barrier.wait()
        return fn()

    with ThreadPoolExecutor(max_workers=n) as ex:
        return list(ex.map(task, range(n)))


# --------------------------------------------------------------------------- many threads
@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_reconstruct_from_many_threads_equals_serial(pname, method):
    pattern = PATTERNS[pname]()
    data = {dt: frame_for(pattern, dtype=dt) for dt in (np.uint8, np.uint16, np.float32,
                                                        np.float64)}
    data[np.uint8] = (data[np.uint16] >> 3).astype(np.uint8)
    calls = [(dt, pr, dom) for dt in data for pr in ("float32", "float64")
             for dom in ("intensity", "colour_difference")
             if dom == "intensity" or method not in ("bilinear", "edi_rows")]      # H75
    rz.reconstruction._reconstruct._plans_for.cache_clear()            # plans are built concurrently too

    def call(dt, pr, dom):
        return rz.reconstruct(data[dt], method, pattern=pattern,
                              bit_depth=8 if dt == np.uint8 else 11, precision=pr,
                              domain=dom, workers=2)

    serial = [call(*c) for c in calls]
    rz.reconstruction._reconstruct._plans_for.cache_clear()
    # each thread runs every call, in its own order
    rng = np.random.default_rng(1)
    orders = [rng.permutation(len(calls)) for _ in range(NTHREADS)]
    counter = iter(range(NTHREADS))
    lock = threading.Lock()

    def worker():
        with lock:
            order = orders[next(counter)]
        return {int(i): call(*calls[i]) for i in order}

    for got in in_threads(worker):
        for i, ref in enumerate(serial):
            np.testing.assert_array_equal(got[i], ref, err_msg=str(calls[i]))


def test_stages_from_many_threads_equal_serial():
    """Demosaic, ToF demodulation/unwrapping, the colour ISP and the ToF ISP in 8 threads."""
    from rgbz_fast.isp import ColourISP

    rng = np.random.default_rng(2)
    cfa = rng.uniform(0, 2047, (120, 160))
    scene = Scene(rng.random((48, 64, 3)), depth=rng.uniform(0.5, 7.0, (48, 64)))
    frame = sensor.simulate(scene, "mask1", seed=3)
    taps = frame.tof.taps
    phase = np.mod(rng.normal(3, 2, (3, 5000)), 2 * np.pi)
    f = np.array([80e6, 100e6, 120e6])
    jobs = {
        "malvar": lambda: demosaic(cfa, "GRBG", workers=2),
        "malvar_period": lambda: demosaic(cfa, "RGGB", mode="period", dtype=np.float64),
        "demodulate": lambda: tof_isp.demodulate(taps, workers=2),
        "unwrap": lambda: tof_isp.unwrap(phase, f, workers=2),
        "demodulate_unwrap": lambda: tof_isp.demodulate_unwrap(taps, f, workers=2),
        "tof_depth": lambda: tof_isp.tof_depth(frame).depth,
        "colour_isp": lambda: ColourISP().run(frame, workers=2),
    }
    for name, fn in jobs.items():
        ref = fn()
        for got in in_threads(fn):
            for a, b in zip(np.atleast_1d(got) if not isinstance(got, tuple) else got,
                            np.atleast_1d(ref) if not isinstance(ref, tuple) else ref):
                np.testing.assert_array_equal(a, b, err_msg=name)


def _progress_while(fn):
    """Iterations of a pure-Python loop in this thread while fn() runs in another one."""
    done = threading.Event()
    t = threading.Thread(target=lambda: (fn(), done.set()))
    count = 0
    t.start()
    while not done.is_set():
        count += 1
    t.join()
    return count


@pytest.mark.parametrize("kernel", ["reconstruct", "malvar", "demodulate", "unwrap"])
def test_kernels_release_the_gil(kernel):
    """While a kernel runs (~0.2 s, one thread) this thread keeps running Python code.

    With the GIL held for the whole C call the loop below would stall for the
    call's duration; released, it spins freely. The comparison is against the
    same loop running beside time.sleep (which releases the GIL) for as long.
    """
    rng = np.random.default_rng(4)
    if kernel == "reconstruct":
        data = frame_for(rz.mask2(), (1200, 1200))
        fn = lambda: rz.reconstruct(data, "sg", pattern="mask2", workers=1)  # noqa: E731
    elif kernel == "malvar":
        cfa = rng.uniform(0, 2047, (2000, 2000))
        fn = lambda: demosaic(cfa, workers=1)  # noqa: E731
    elif kernel == "demodulate":
        taps = rng.integers(0, 2048, (3, 4, 1_000_000), dtype=np.uint16)
        fn = lambda: tof_isp.demodulate(taps, workers=1)  # noqa: E731
    else:
        # 1024 wrap candidates (the most unwrap searches) keep the vectorised kernel busy
        # for ~0.1 s on 200 000 measurements; 80/100/120 MHz would take ~3 ms, too short
        ph = rng.uniform(0, 2 * np.pi, (2, 200_000))
        fn = lambda: tof_isp.unwrap(ph, [80e6, 100.078125e6], workers=1)  # noqa: E731
    fn()                                                  # warm up (plans, page faults)
    t0 = time.perf_counter()
    fn()
    dt = time.perf_counter() - t0
    spins = _progress_while(fn)
    baseline = _progress_while(lambda: time.sleep(dt))
    # released: the same order of magnitude as beside sleep; held: (almost) nothing
    assert spins > 0.05 * baseline, (spins, baseline, dt)


# --------------------------------------------------------------------------- workers
WORKERS = (1, 2, 3, 7)


@pytest.mark.parametrize("pname, method", CASES, ids=CASE_IDS)
def test_reconstruct_identical_for_every_workers_value(pname, method):
    pattern = PATTERNS[pname]()
    for dt in (np.uint16, np.float32, np.float64):
        data = frame_for(pattern, (61, 47), dtype=dt, seed=5)
        for pr in ("float32", "float64"):
            for exp in ("libm", "fast"):
                outs = [rz.reconstruct(data, method, pattern=pattern, precision=pr, exp=exp,
                                       workers=w) for w in WORKERS]
                for w, o in zip(WORKERS[1:], outs[1:]):
                    np.testing.assert_array_equal(o, outs[0], err_msg=f"{dt} {pr} {exp} w={w}")


def test_other_kernels_identical_for_every_workers_value():
    rng = np.random.default_rng(6)
    cfa = rng.uniform(0, 2047, (63, 45))
    taps = rng.integers(0, 2048, (3, 4, 1001)).astype(np.uint16)
    phase = rng.uniform(0, 2 * np.pi, (3, 1001))
    f = [80e6, 100e6, 120e6]
    for fn in (lambda w: demosaic(cfa, "BGGR", workers=w),
               lambda w: demosaic(cfa.astype(np.uint16), mode="period", workers=w),
               lambda w: tof_isp.demodulate(taps, workers=w),
               lambda w: tof_isp.unwrap(phase, f, workers=w),
               lambda w: tof_isp.demodulate_unwrap(taps, f, workers=w)):
        outs = [fn(w) for w in WORKERS]
        for o in outs[1:]:
            for a, b in zip(np.atleast_1d(o) if not isinstance(o, tuple) else o,
                            np.atleast_1d(outs[0]) if not isinstance(outs[0], tuple)
                            else outs[0]):
                np.testing.assert_array_equal(a, b)


# --------------------------------------------------------------------------- seeds
def _scene():
    rng = np.random.default_rng(7)
    return Scene(rng.random((24, 32, 3)), depth=rng.uniform(0.5, 7.0, (24, 32)))


def _digest(frame):
    h = hashlib.sha256()
    for a in (frame.data, frame.reference, frame.tof.taps, frame.tof.saturated):
        h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()


@pytest.mark.parametrize("pattern", ["mask1", "mask2"])
def test_same_seed_same_simulation(pattern):
    scene = _scene()
    a = sensor.simulate(scene, pattern, seed=11)
    b = sensor.simulate(scene, pattern, seed=11)
    assert _digest(a) == _digest(b)
    c = sensor.simulate(scene, pattern, seed=12)
    assert not np.array_equal(a.data, c.data) and not np.array_equal(a.tof.taps, c.tof.taps)
    # fixed-pattern noise follows the sensor's fpn_seed, not the frame seed
    d = sensor.simulate(scene, pattern, sensor.ColourSensor(fpn_seed=1), seed=11)
    assert not np.array_equal(a.data, d.data)
    # noise-free runs do not depend on the seed at all
    n1 = sensor.simulate(scene, pattern, seed=1, noise=False)
    n2 = sensor.simulate(scene, pattern, seed=2, noise=False)
    assert _digest(n1) == _digest(n2)


def test_same_seed_same_simulation_in_threads_and_in_a_fresh_process():
    scene = _scene()
    ref = _digest(sensor.simulate(scene, "mask2", seed=21))
    assert set(in_threads(lambda: _digest(sensor.simulate(scene, "mask2", seed=21)))) == {ref}
    code = (
        "import sys, hashlib, numpy as np\n"
        f"sys.path.insert(0, {str(Path(__file__).parent)!r})\n"
        "from test_concurrency import _scene, _digest\n"
        "from rgbz_fast import simulation as sensor\n"
        "print(_digest(sensor.simulate(_scene(), 'mask2', seed=21)))\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr[-2000:]
    assert r.stdout.strip().splitlines()[-1] == ref


def test_kernel_thread_count_is_reported():
    """workers=None runs on every core; the build says whether OpenMP is on."""
    assert isinstance(_kernels.have_openmp(), bool)
    assert _kernels.max_threads() >= 1


def test_config_reports_the_threads_a_call_takes(monkeypatch):
    """show_config's thread count is what workers=None runs, not OpenMP's own default (which
    OMP_NUM_THREADS sets and the kernels do not use: it had printed 1 with OMP_NUM_THREADS=1
    while a call ran on every core)."""
    import io
    import os

    from rgbz_fast._threads import check_workers

    assert rz.config()["default_workers"] == check_workers(None) == (os.cpu_count() or 1)
    monkeypatch.setenv("OMP_NUM_THREADS", "1")
    out = io.StringIO()
    rz.show_config(out)
    text = out.getvalue()
    assert f"threads       : {check_workers(None)} per call by default" in text
    if _kernels.have_openmp():
        assert "OMP_NUM_THREADS=1 is not used: pass workers=" in text
    # config reports, it does not refuse: a stack size no thread could take is for a call
    monkeypatch.setenv("OMP_STACKSIZE", "4000G")
    assert rz.config()["default_workers"] == (os.cpu_count() or 1)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="ulimit -v and /proc: Linux")
@pytest.mark.skipif("ASAN_OPTIONS" in __import__("os").environ,
                    reason="under AddressSanitizer (tools/sanitize.sh): its shadow memory is "
                           "terabytes of address space, which ulimit -v forbids")
def test_too_many_threads_for_the_address_space_is_a_clear_error():
    """Under ``ulimit -v 4000000`` libgomp would abort the process at workers=512 ("Thread
    creation failed"): check_workers refuses counts beyond the bound the limit leaves, and a
    count within it runs."""
    import resource

    code = textwrap.dedent("""
        import sys, numpy as np, rgbz_fast as rz
        a = np.zeros((600, 600), np.uint16)
        try:
            rz.reconstruct(a, "sg", pattern="mask1", workers=int(sys.argv[1]))
            print("ran")
        except ValueError as exc:
            print(exc)
    """)

    def limited():
        resource.setrlimit(resource.RLIMIT_AS, (4_000_000 * 1024, 4_000_000 * 1024))
        resource.setrlimit(resource.RLIMIT_STACK, (8 * 2**20, 8 * 2**20))

    def run(workers):
        r = subprocess.run([sys.executable, "-c", code, str(workers)], capture_output=True,
                           text=True, timeout=300, preexec_fn=limited)
        assert r.returncode == 0, r.stderr[-500:]          # no abort
        return r.stdout.strip()

    out = run(512)
    assert out.startswith("workers: 512 threads cannot be started here (the address-space "
                          "limit, ulimit -v 4000000 kB, leaves room for "), out
    n = int(out.rsplit(" ", 1)[1])
    assert 100 < n < 512
    # a few stacks below the bound: the next process's own address space is not the same
    # to the MiB (a full run on Python 3.10 measured room for 407, then 406)
    assert run(n - 4) == "ran"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="ulimit -v: Linux")
@pytest.mark.skipif("ASAN_OPTIONS" in __import__("os").environ,
                    reason="under AddressSanitizer (tools/sanitize.sh): its shadow memory is "
                           "terabytes of address space, which ulimit -v forbids")
def test_a_thread_stack_the_system_refuses_is_a_clear_error():
    """``OMP_STACKSIZE=32G`` made libgomp abort the interpreter inside reconstruct(workers=2)
    ("Thread creation failed", no error line from the CLI): the stacks OpenMP would ask for
    are checked before the first parallel region, in the API and on the command line (here
    under ``ulimit -v 8000000``, so that no 32 GiB stack fits); one thread runs, and a stack
    the system grants changes nothing."""
    import os
    import resource
    import tempfile

    code = textwrap.dedent("""
        import sys, numpy as np, rgbz_fast as rz
        a = np.zeros((600, 600), np.uint16)
        try:
            rz.reconstruct(a, "sg", pattern="mask1", workers=int(sys.argv[1]))
            print("ran")
        except ValueError as exc:
            print(exc)
    """)

    def limited():
        resource.setrlimit(resource.RLIMIT_AS, (8_000_000 * 1024, 8_000_000 * 1024))

    def run(argv, stack):
        env = {**os.environ, "OMP_STACKSIZE": stack}
        r = subprocess.run([sys.executable, *argv], capture_output=True, text=True,
                           timeout=300, preexec_fn=limited, env=env)
        assert r.returncode in (0, 2), (r.returncode, r.stderr[-500:])     # no abort
        return r.returncode, (r.stdout.strip().splitlines() or [""])[-1], \
            (r.stderr.strip().splitlines() or [""])[-1]

    want = ("OMP_STACKSIZE: '32G' asks for a stack of 32 GiB for each of the 1 thread(s) "
            "OpenMP starts for workers=2, which this system refuses")
    assert run(["-c", code, "2"], "32G")[1].startswith(want)
    assert run(["-c", code, "1"], "32G")[1] == "ran"
    assert run(["-c", code, "2"], "16M")[1] == "ran"
    assert run(["-c", code, "2"], "not a size")[1] == "ran"        # libgomp ignores it too
    # below the smallest stack pthreads takes: libgomp warns and keeps its default stack
    assert run(["-c", code, "2"], "0")[1] == "ran"
    assert run(["-c", code, "2"], "1k")[1] == "ran"
    with tempfile.TemporaryDirectory() as d:
        frame = Path(d) / "f.npz"
        rz.io.save_frame(frame, rz.mosaic(np.random.default_rng(0).random((64, 64, 3)),
                                          "mask1"))
        code_cli, _, line = run(["-m", "rgbz_fast", "reconstruct", str(frame), "--out",
                                 str(Path(d) / "out"), "--quiet", "--workers", "2"], "32G")
        # the command line says it in its own words: the option, not the keyword
        assert code_cli == 2 and line.startswith(
            "rgbz-fast reconstruct: error: " + want.replace("workers=2", "--workers 2"))
        assert line.endswith("or pass --workers 1")
        assert not (Path(d) / "out").exists()


@pytest.mark.parametrize("copier", ["pickle", "deepcopy"])
def test_copies_for_worker_processes_keep_their_arrays_read_only(copier):
    """Pattern, RawFrame, ToFTaps and Scene reach worker processes pickled: their arrays stay
    read-only, as the constructors left them (NumPy unpickles arrays writeable, so an 11-bit
    frame's copy took 65535 past the checks, and a copied tile's cached has_z went stale)."""
    import copy
    import pickle

    from rgbz_fast.simulation import Scene, simulate

    clone = (lambda o: pickle.loads(pickle.dumps(o))) if copier == "pickle" else copy.deepcopy
    scene = Scene(np.full((16, 16, 3), 0.5), depth=np.full((16, 16), 1.0))
    frame = simulate(scene, "mask1", seed=1)
    arrays = {"tile": lambda c: c.tile, "frame.data": lambda c: c.data,
              "frame.tof.taps": lambda c: c.tof.taps, "frame.pattern": lambda c: c.pattern.tile,
              "tof.sites": lambda c: c.sites[0], "scene.image": lambda c: c.image,
              "scene.depth": lambda c: c.depth}
    objects = {"tile": rz.mask1(), "frame.data": frame, "frame.tof.taps": frame,
               "frame.pattern": frame, "tof.sites": frame.tof, "scene.image": scene,
               "scene.depth": scene}
    for name, get in arrays.items():
        c = clone(objects[name])
        with pytest.raises(ValueError, match="read-only"):
            get(c)[(0,) * get(c).ndim] = 1
    back = clone(frame)
    np.testing.assert_array_equal(back.data, frame.data)
    assert back.pattern == frame.pattern and back.bit_depth == frame.bit_depth
    # the filters too: their identity is a digest computed once, so a writeable copy could
    # change its weights and still compare equal to (and share a cache key with) the shipped
    from rgbz_fast.reconstruction import default_filters, default_z_filters

    for filters in (default_filters("mask1"), default_z_filters("mask1")):
        c = clone(filters)
        with pytest.raises(ValueError, match="read-only"):
            c.weights[(0,) * c.weights.ndim] = 0
        assert c == filters
