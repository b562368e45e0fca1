"""Indirect time-of-flight: four-tap demodulation and three-frequency unwrapping.

``ToFSuite`` times the C kernels (two passes, and the fused one-pass kernel of
``tof_isp.demodulate_unwrap`` where the commit has it); ``ToFNumPySuite`` the
vectorised NumPy implementation of the same algorithm (``rgbz_fast._devtools._numpy_tof``),
so that ``asv compare`` shows the ratio of the two (target: C >= 5x NumPy).
"""

import numpy as np

from .common import SKIP_SLOW, astronaut, skip_if_slow, tile_to

try:
    from rgbz_fast.simulation import SPEED_OF_LIGHT as C
except ImportError:                 # commits before the subpackages
    from rgbz_fast.sensor import SPEED_OF_LIGHT as C

FREQS = np.array([80e6, 100e6, 120e6])


def _taps(n, seed=0):
    rng = np.random.default_rng(seed)
    depth = rng.uniform(0.3, 7.0, n)
    taps = np.empty((FREQS.size, 4, n), np.uint16)
    for i, f in enumerate(FREQS):
        phi = 4 * np.pi * f * depth / C
        for k in range(4):
            taps[i, k] = np.round(964 + 700 * np.cos(phi + k * np.pi / 2))
    return taps


class ToFSuite:
    # Z measurements: Mask2 of a Kodak frame, Mask1 of a Kodak frame, Mask1 of 4000x3000
    params = ([24_576, 98_304, 3_000_000],)
    param_names = ["n_sites"]
    timeout = 300

    def setup(self, n):
        try:
            from rgbz_fast import _kernels
            _kernels.tof_demodulate, _kernels.tof_unwrap
        except (ImportError, AttributeError):
            raise NotImplementedError("no ToF kernels in this commit") from None
        if SKIP_SLOW and n > 1_000_000:
            raise NotImplementedError("skipped: ASV_SKIP_SLOW is set")
        self.k = _kernels
        self.taps = _taps(n)
        self.phase, self.amp, self.off = (np.empty((FREQS.size, n)) for _ in range(3))
        self.k.tof_demodulate(self.taps, self.phase, self.amp, self.off, 0)
        self.w = FREQS ** 2 / (FREQS ** 2).sum()
        self.depth, self.resid = np.empty(n), np.empty(n)
        self.wraps = np.empty(n, np.int32)

    def time_demodulate(self, n):
        self.k.tof_demodulate(self.taps, self.phase, self.amp, self.off, 0)

    def time_unwrap(self, n):
        self.k.tof_unwrap(self.phase, FREQS, self.w, C / (2 * 20e6), self.depth, self.resid,
                          self.wraps, 0)

    def time_demodulate_unwrap(self, n):
        self.k.tof_demodulate(self.taps, self.phase, self.amp, self.off, 0)
        self.k.tof_unwrap(self.phase, FREQS, self.w, C / (2 * 20e6), self.depth, self.resid,
                          self.wraps, 0)

    def time_fused(self, n):
        """One pass: taps -> phase, amplitude, offset, depth, residual, wraps (public API)."""
        try:
            from rgbz_fast.tof import demodulate_unwrap
        except ImportError:
            raise NotImplementedError("no fused ToF kernel in this commit") from None
        demodulate_unwrap(self.taps, FREQS)

    def time_fused_1thread(self, n):
        try:
            from rgbz_fast.tof import demodulate_unwrap
        except ImportError:
            raise NotImplementedError("no fused ToF kernel in this commit") from None
        demodulate_unwrap(self.taps, FREQS, workers=1)


class ToFNumPySuite:
    """The NumPy twin of the fused kernel, same data: the denominator of the x NumPy ratio."""
    params = ([98_304, 3_000_000],)
    param_names = ["n_sites"]
    timeout = 300

    def setup(self, n):
        try:
            from rgbz_fast._devtools._numpy_tof import numpy_tof_depth
        except ImportError:
            raise NotImplementedError("no NumPy ToF twin in this commit") from None
        if SKIP_SLOW and n > 1_000_000:
            raise NotImplementedError("skipped: ASV_SKIP_SLOW is set")
        self.fn = numpy_tof_depth
        self.taps = _taps(n)

    def time_numpy(self, n):
        self.fn(self.taps, FREQS)


class ToFISPSuite:
    """The whole ToF ISP (``tof_depth``) on a Mask1 wall with a depth step, by denoise:
    the edge-aware default (two passes of the C bilateral kernel, window 9), the paper's
    box mean (C since 2026-11-26, NumPy before; window 5) and none (the fused kernel).
    Frames: 512x768 (Kodak) and 4000x3000 (12 MP, 3 million Z measurements)."""
    params = ([(512, 768), (3000, 4000)], ["bilateral", "box", "none"])
    param_names = ["shape", "denoise"]
    timeout = 600

    def setup(self, shape, denoise):
        try:
            from rgbz_fast.simulation import ToFSensor, ToFTaps
            from rgbz_fast.tof import denoise_phasors_bilateral, tof_depth  # noqa: F401
        except ImportError:
            raise NotImplementedError("no edge-aware ToF ISP in this commit") from None
        skip_if_slow(shape)
        rows, cols = (a * 2 for a in np.nonzero(np.ones((shape[0] // 2, shape[1] // 2), bool)))
        n = rows.size
        rng = np.random.default_rng(0)
        depth = np.where(cols < shape[1] // 2, 1.2, 1.9)
        taps = np.empty((FREQS.size, 4, n), np.uint16)
        for i, f in enumerate(FREQS):
            phi = 4 * np.pi * f * depth / C
            for k in range(4):
                taps[i, k] = np.round(400 + 120 * np.cos(phi + k * np.pi / 2)
                                      + rng.normal(0, 9, n))
        self.fn = tof_depth
        self.tof = ToFTaps(taps, FREQS, (rows, cols), 1, 11, depth, np.ones(n, bool),
                           np.zeros(n, bool), ToFSensor(pixel_pitch_um=2.8), shape)

    def time_tof_depth(self, shape, denoise):
        self.fn(self.tof, denoise=denoise)


class GuidedToFISPSuite:
    """The colour-guided ToF ISP (``ToFISP().run(tof, guide=image)``) and ``upsample_depth``
    on a simulated frame with a depth step and its own colour image, by pattern: Mask1 (1x1
    Z pixels) and Mask2 (2x2, where the flying-pixel test also reads the ring of pixels
    around each Z pixel); Kodak size and 12 MP."""
    params = ([(512, 768), (3000, 4000)], ["mask1", "mask2"])
    param_names = ["shape", "pattern"]
    timeout = 600

    def setup(self, shape, pattern):
        try:
            from rgbz_fast.isp import ColourISP
            from rgbz_fast.simulation import Scene, simulate
            from rgbz_fast.tof import ToFISP, upsample_depth
        except ImportError:
            raise NotImplementedError("no colour-guided ToF ISP in this commit") from None
        skip_if_slow(shape)
        img = tile_to(astronaut(), shape)
        xx = np.arange(shape[1])[None, :] * np.ones((shape[0], 1))
        frame = simulate(Scene(img, depth=np.where(xx < shape[1] // 2, 1.2, 1.9)), pattern,
                         seed=1)
        self.tof, self.guide = frame.tof, ColourISP().run(frame)
        self.isp, self.upsample = ToFISP(), upsample_depth
        self.result = self.isp.run(self.tof, guide=self.guide)

    def time_guided_isp(self, shape, pattern):
        self.isp.run(self.tof, guide=self.guide)

    def time_upsample_depth(self, shape, pattern):
        self.upsample(self.result, self.guide)


class GuidedToFISPPoolSuite:
    """The colour-guided ToF ISP with the memory pool (``rgbz_fast.memory_pool``) on, the
    default, and off: a call of a loop whose results land on the pages the previous call's
    freed results kept, against one that writes them into fresh pages (the pool emptied
    before each call). Mask1, the frame of ``GuidedToFISPSuite``."""
    params = ([(512, 768), (3000, 4000)], ["on", "off"])
    param_names = ["shape", "pool"]
    timeout = 600

    def setup(self, shape, pool):
        import rgbz_fast as rz
        if not hasattr(rz, "memory_pool"):
            raise NotImplementedError("no memory pool in this commit")
        GuidedToFISPSuite.setup(self, shape, "mask1")
        self.pool = rz.memory_pool
        self.limit = rz.memory_pool()["limit"]

    def teardown(self, shape, pool):
        self.pool(self.limit)

    def time_guided_isp(self, shape, pool):
        if pool == "off":
            self.pool(0)
            self.isp.run(self.tof, guide=self.guide)
            self.pool(self.limit)
        else:
            self.isp.run(self.tof, guide=self.guide)
