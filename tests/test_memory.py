"""The pool of large result arrays (rgbz_fast._memory over csrc/pool.c): arrays like
numpy.empty's, memory kept for the next request of its size up to the limit, the limit's
checks, tracemalloc's count, threads and fork; and the guided ToF ISP and upsample_depth
giving the same results on memory a freed result left full of other values as on fresh
memory (their outputs are written whole, never read before)."""

from __future__ import annotations

import os
import sys
import threading
import tracemalloc

import numpy as np
import pytest

import rgbz_fast as rz
from rgbz_fast import _kernels, _memory

MiB = 1 << 20


@pytest.fixture
def pool():
    """The pool with its default limit and nothing kept; the limit restored after. The
    garbage collector is off meanwhile: the pooled arrays of an earlier test's garbage
    cycles, collected in the middle of a test, would change what the pool keeps."""
    import gc
    gc.collect()
    limit = rz.memory_pool()["limit"]
    rz.memory_pool(0)
    rz.memory_pool(limit)
    gc.disable()
    try:
        yield rz.memory_pool
    finally:
        gc.enable()
        rz.memory_pool(limit)


def _address(a):
    return a.__array_interface__["data"][0]


def _block(a):
    """The PoolBlock at the end of the array's base chain, or None."""
    while a is not None and not isinstance(a, _kernels.PoolBlock):
        a = a.obj if isinstance(a, memoryview) else a.base
    return a


def test_empty_is_numpy_empty_below_the_threshold_and_a_pool_block_above(pool):
    small = _memory.empty((10, 10), np.float32)
    assert small.base is None and small.shape == (10, 10) and small.dtype == np.float32
    big = _memory.empty((3, 500_000))
    assert isinstance(_block(big), _kernels.PoolBlock)
    assert big.shape == (3, 500_000) and big.dtype == np.float64
    assert big.flags.c_contiguous and big.flags.writeable and big.flags.aligned
    assert _address(big) % (2 * MiB) == 0
    big[:] = 7.0
    assert float(big.sum()) == 7.0 * big.size
    assert _memory.empty([2, 600_000], np.float32).shape == (2, 600_000)     # any sequence
    assert _memory.empty(np.int64(600_000)).shape == (600_000,)
    with pytest.raises(ValueError):
        _memory.empty((-1, 4))                  # numpy.empty's own error
    like = _memory.empty_like(big)
    assert like.shape == big.shape and like.dtype == big.dtype and _block(like) is not None
    assert not np.shares_memory(like, big)
    assert _memory.empty(5_000_000, np.uint8).shape == (5_000_000,)
    assert _memory.empty(2_000_000, np.uint8).base is None       # below 4 MiB
    # object arrays never: their memory would have to hold references
    assert _memory.empty(1 << 20, object).base is None


def test_freed_memory_is_kept_and_handed_to_the_next_request_of_its_size(pool):
    a = _memory.empty(5 * MiB, np.uint8)
    where = _address(a)
    before = pool()
    del a
    after = pool()
    assert after["kept_bytes"] == before["kept_bytes"] + _kernels.pool_block_size(5 * MiB)
    assert after["kept_blocks"] == before["kept_blocks"] + 1
    b = _memory.empty(5 * MiB + 5, np.uint8)        # the same 6 MiB block
    assert _address(b) == where
    assert pool()["reused"] == after["reused"] + 1
    c = _memory.empty(9 * MiB, np.uint8)            # another size: a new block
    assert _address(c) != where and pool()["mapped"] == after["mapped"] + 1


def test_the_limit_bounds_what_is_kept_oldest_first_and_zero_turns_the_pool_off(pool):
    pool(10 * MiB)
    a, b, c = (_memory.empty(4 * MiB, np.uint8) for _ in range(3))
    first, second, third = _address(a), _address(b), _address(c)
    del a
    del b                                       # 8 MiB kept
    assert pool()["kept_bytes"] == 8 * MiB
    del c                                       # 12 MiB > 10: the oldest (a's) goes
    assert pool()["kept_bytes"] == 8 * MiB and pool()["kept_blocks"] == 2
    x, y = _memory.empty(4 * MiB, np.uint8), _memory.empty(4 * MiB, np.uint8)
    assert (_address(x), _address(y)) == (third, second)     # the most recent first
    assert first not in (_address(x), _address(y))
    del x, y
    big = _memory.empty(12 * MiB, np.uint8)     # larger than the limit: never kept
    del big
    assert pool()["kept_bytes"] <= 10 * MiB
    info = pool(0)
    assert info == dict(info, limit=0, kept_bytes=0, kept_blocks=0)
    assert _memory.empty(4 * MiB, np.uint8).base is None


@pytest.mark.parametrize("limit, error, match", [
    (-1, ValueError, r"limit: expected 0 <= limit < 2\*\*63 bytes, got -1"),
    (2**63, ValueError, "limit: expected 0 <= limit"),
    (1.5e9, TypeError, "limit: expected an int number of bytes"),
    (True, TypeError, "got bool"),
    ("1G", TypeError, "got str"),
])
def test_a_bad_limit_is_refused_naming_it_and_changes_nothing(pool, limit, error, match):
    before = pool()["limit"]
    with pytest.raises(error, match=match):
        pool(limit)
    assert pool()["limit"] == before


def test_numpy_integers_are_limits(pool):
    assert pool(np.int64(64 * MiB))["limit"] == 64 * MiB


def test_tracemalloc_counts_a_block_as_numpys_memory(pool):
    tracemalloc.start()
    try:
        base = tracemalloc.get_traced_memory()[0]
        a = _memory.empty(6 * MiB, np.uint8)
        held = tracemalloc.get_traced_memory()[0] - base
        assert 6 * MiB <= held < 6 * MiB + 4096
        snap = tracemalloc.take_snapshot().filter_traces(
            [tracemalloc.DomainFilter(True, np.lib.tracemalloc_domain)])
        assert sum(t.size for t in snap.traces) >= 6 * MiB
        del a
        assert tracemalloc.get_traced_memory()[0] - base < 4096
    finally:
        tracemalloc.stop()


def test_threads_never_share_a_block(pool):
    # four threads take and free blocks of three sizes; every live array keeps its own values
    pool(40 * MiB)
    errors = []

    def work(seed):
        rng = np.random.default_rng(seed)
        live = []
        for i in range(200):
            a = _memory.empty(int(rng.choice([4, 5, 7])) * MiB, np.uint8)
            a[:] = seed
            live.append(a)
            if len(live) > 3:
                old = live.pop(int(rng.integers(len(live))))
                if not (old == seed).all():
                    errors.append(seed)
        live.clear()

    threads = [threading.Thread(target=work, args=(s,)) for s in range(1, 5)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    info = pool()
    assert info["kept_bytes"] <= 40 * MiB and info["kept_blocks"] <= 64


@pytest.mark.skipif(not hasattr(os, "fork"), reason="os.fork: POSIX only")
def test_a_forked_child_takes_and_frees_blocks(pool):
    a = _memory.empty(5 * MiB, np.uint8)
    a[:] = 5
    pid = os.fork()
    if pid == 0:                                # the child: its copy of the pool works
        code = 1
        try:
            b = _memory.empty(5 * MiB, np.uint8)
            ok = (a == 5).all() and not np.shares_memory(a, b)
            del a, b
            code = 0 if ok and rz.memory_pool()["kept_blocks"] >= 1 else 1
        finally:
            os._exit(code)
    _, status = os.waitpid(pid, 0)
    assert os.WEXITSTATUS(status) == 0
    assert (a == 5).all()


# --------------------------------------------------------------------------- the chain
def _poisoned(pool, value, blocks=48):
    """Keep `blocks` 2 MiB blocks filled with `value`'s bytes: the next requests take them."""
    arrays = [_memory.empty(2 * MiB, np.uint8) for _ in range(blocks)]
    for a in arrays:
        a.view(np.float64)[:] = value
    arrays.clear()


@pytest.mark.parametrize("pattern, freqs", [("mask1", None), ("mask2", None), ("rows", None),
                                            ("mask1", (40e6, 60e6, 80e6, 100e6, 120e6))])
def test_guided_isp_and_upsample_give_the_same_results_on_used_memory(pool, monkeypatch,
                                                                     pattern, freqs):
    # the five frequencies take the strips (the prepare stage over the frame first); rows'
    # Z sites are no full grid of measurements (the present mask)
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "tof"))
    try:
        from test_guided import _frame
    finally:
        sys.path.pop(0)
    from rgbz_fast.simulation import ToFSensor
    from rgbz_fast.tof import ToFISP, upsample_depth
    frame, guide, _ = _frame(pattern, shape=(96, 128),
                             sensor=None if freqs is None else ToFSensor(frequencies=freqs))
    pool(0)
    fresh = ToFISP().run(frame.tof, guide=guide, workers=2)
    fresh_up = upsample_depth(fresh, guide, workers=2)
    pool(256 * MiB)
    monkeypatch.setattr(_memory, "POOL_MIN_BYTES", 0)   # every array from the pool
    for value in (np.nan, -1e300):
        _poisoned(pool, value)
        used = ToFISP().run(frame.tof, guide=guide, workers=2)
        assert _block(used.depth) is not None and _block(used.phase) is not None
        for name in fresh.__dataclass_fields__:
            a, b = getattr(fresh, name), getattr(used, name)
            if isinstance(a, np.ndarray):
                np.testing.assert_array_equal(b, a, err_msg=name)
        _poisoned(pool, value)
        up = upsample_depth(used, guide, workers=2)
        assert _block(up[0]) is not None
        for a, b in zip(fresh_up, up):
            np.testing.assert_array_equal(b, a)


@pytest.mark.parametrize("pattern", ["mask1", "mask2", "bayer"])
@pytest.mark.parametrize("bits", [8, 16])
def test_colour_isp_fused_path_gives_the_same_image_on_used_memory(pool, monkeypatch, pattern,
                                                                   bits):
    # the fused path's image and defect-corrected CFA come from the pool; planted hot and cold
    # pixels make the defect pass correct something (its copy on the pool too)
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "isp"))
    try:
        from test_fused import _frame
    finally:
        sys.path.pop(0)
    data, pat = _frame(pattern, shape=(96, 128))
    chain = rz.ColourISP(output_bits=bits)
    pool(0)
    fresh = chain.run(data, pattern=pat, workers=2)
    assert _block(fresh) is None
    pool(256 * MiB)
    monkeypatch.setattr(_memory, "POOL_MIN_BYTES", 0)   # every array from the pool
    for value in (np.nan, -1e300):
        _poisoned(pool, value)
        before = pool()["reused"]
        used = chain.run(data, pattern=pat, workers=2)
        assert _block(used) is not None
        assert pool()["reused"] > before
        np.testing.assert_array_equal(used, fresh)
        assert used.flags.c_contiguous and used.flags.writeable


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS and /proc: Linux")
def test_kept_memory_goes_back_when_a_new_array_does_not_fit_the_address_space():
    # under ulimit -v, 400 MiB kept by the pool would leave no room for a 300 MiB array: the
    # pool gives its blocks back and the array is made (in a child: the limit is the process's)
    import subprocess
    code = """
import resource, re
import numpy as np
from rgbz_fast import _memory
MiB = 1 << 20
vm = int(re.search(r"VmSize:\\s+(\\d+)", open("/proc/self/status").read()).group(1)) * 1024
resource.setrlimit(resource.RLIMIT_AS, (vm + 600 * MiB, resource.RLIM_INFINITY))
kept = [_memory.empty(100 * MiB, np.uint8) for _ in range(4)]
del kept
assert _memory.memory_pool()["kept_bytes"] == 400 * MiB
b = _memory.empty(300 * MiB, np.uint8)
b[:] = 1
assert _memory.memory_pool()["kept_bytes"] == 0
print("ok")
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr[-2000:]
    assert r.stdout.strip() == "ok"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS: POSIX")
def test_the_default_limit_is_an_eighth_of_a_smaller_address_space_limit():
    import subprocess
    code = ("import resource; resource.setrlimit(resource.RLIMIT_AS, (4 << 30, "
            "resource.RLIM_INFINITY)); import rgbz_fast; print(rgbz_fast.memory_pool()['limit'])")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr[-2000:]
    assert int(r.stdout) == (4 << 30) // 8
    import resource
    soft = resource.getrlimit(resource.RLIMIT_AS)[0]      # this process's own
    assert _memory._default_limit() == (_memory.DEFAULT_LIMIT if soft == resource.RLIM_INFINITY
                                        else min(_memory.DEFAULT_LIMIT, soft // 8))


def test_the_build_report_shows_the_pool(pool):
    import io
    pool(256 * MiB)
    out = io.StringIO()
    rz.show_config(out)
    assert "memory pool   : keeps up to 256 MiB of freed result arrays" in out.getvalue()
    assert rz.config()["memory_pool"]["limit"] == 256 * MiB
