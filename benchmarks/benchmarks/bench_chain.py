"""The whole chain on one frame: sensor simulation -> reconstruction -> demosaic (+ ToF); the
colour ISP by demosaic and colour matrix."""

import numpy as np

from .common import BIG_SHAPE, KODAK_SHAPE, astronaut, need, rz, skip_if_slow


class ChainSuite:
    params = (["mask1", "mask2"], ["bilinear", "sg"])
    param_names = ["pattern", "method"]
    timeout = 120

    def setup(self, pattern, method):
        need("reconstruct", "sensor.simulate", "scene.Scene", "demosaic.demosaic")
        from rgbz_fast.isp import demosaic
        from rgbz_fast.simulation import Scene
        from rgbz_fast.simulation import simulate

        img = astronaut()[:256, :256]
        yy, xx = np.mgrid[:256, :256]
        self.scene = Scene(img, depth=1.0 + 2.0 * xx / 255 + 0.5 * yy / 255)
        self.simulate, self.demosaic = simulate, demosaic
        try:
            from rgbz_fast.tof import demodulate
            self.demodulate = demodulate
        except ImportError:
            self.demodulate = None

    def _run(self, pattern, method):
        frame = self.simulate(self.scene, pattern, seed=0)
        cfa = rz.reconstruct(frame, method)
        rgb = self.demosaic(cfa, frame.pattern.bayer_phase, "malvar2004")
        if self.demodulate is not None and frame.tof is not None:
            self.demodulate(frame.tof.taps)
        return rgb

    def time_chain(self, pattern, method):
        self._run(pattern, method)

    def peakmem_chain(self, pattern, method):
        self._run(pattern, method)


class ColourISPSuite:
    """``ColourISP().run`` on a Mask1 frame (11 bits): the fused C passes with each demosaic
    that has a C kernel (Malvar 2004, bilinear: the stages and colour-demosaicing before),
    with the identity or a colour matrix (a raw frame's recorded one; float32 ``fmaf``)."""
    params = ([KODAK_SHAPE, BIG_SHAPE], ["malvar2004", "bilinear"], [False, True])
    param_names = ["shape", "demosaic", "matrix"]
    timeout = 300

    def setup(self, shape, demosaic, matrix):
        skip_if_slow(shape)
        try:
            from rgbz_fast.isp import ColourISP
        except ImportError:
            raise NotImplementedError("no ColourISP in this commit") from None
        m = ((1.6, -0.4, -0.2), (-0.3, 1.5, -0.2), (0.0, -0.5, 1.5))
        self.chain = ColourISP(demosaicing={"method": demosaic},
                               colour_correction={"matrix": m if matrix else None})
        self.frame = rz.mosaic(astronaut(shape), "mask1", 11)

    def time_colour_isp(self, shape, demosaic, matrix):
        self.chain.run(self.frame)

    def peakmem_colour_isp(self, shape, demosaic, matrix):
        self.chain.run(self.frame)
