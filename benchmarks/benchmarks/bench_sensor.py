"""Sensor simulation (colour + ToF models, paper §5.1) on a small scene."""

import numpy as np

from .common import astronaut, need, rz, skip_if_slow, tile_to


class SensorSuite:
    params = (["mask1", "mask2"], [False, True])
    param_names = ["pattern", "noise"]
    timeout = 120

    def setup(self, pattern, noise):
        need("sensor.simulate", "scene.Scene")
        from rgbz_fast.simulation import Scene
        from rgbz_fast.simulation import simulate

        img = astronaut()[:256, :256]
        yy, xx = np.mgrid[:256, :256]
        self.scene = Scene(img, depth=1.0 + 2.0 * xx / 255 + 0.5 * yy / 255)
        self.simulate = simulate

    def time_simulate(self, pattern, noise):
        self.simulate(self.scene, pattern, seed=0, noise=noise)

    def peakmem_simulate(self, pattern, noise):
        self.simulate(self.scene, pattern, seed=0, noise=noise)


class OpticsSuite:
    """``simulate(..., optics=Optics())`` (the blur of the colour planes and of the ToF
    fields, ten FFT convolutions of the frame) on a scene with a depth step, Kodak size and
    12 MP."""
    params = ([(512, 768), (3000, 4000)],)
    param_names = ["shape"]
    timeout = 600

    def setup(self, shape):
        need("simulation.Optics")
        from rgbz_fast.simulation import Optics, Scene, simulate

        skip_if_slow(shape)
        img = tile_to(astronaut(), shape)
        xx = np.arange(shape[1])[None, :] * np.ones((shape[0], 1))
        self.scene = Scene(img, depth=np.where(xx < shape[1] // 2, 1.2, 1.9))
        self.run = lambda: simulate(self.scene, "mask1", seed=0, optics=Optics())

    def time_simulate_optics(self, shape):
        self.run()

    def peakmem_simulate_optics(self, shape):
        self.run()


class FrameFileSuite:
    """``rgbz_fast.io.save_frame`` and ``load_frame`` of an NPZ frame with its ToF taps
    (12 MP Mask1, 3 M measurements; Kodak size)."""
    params = ([(512, 768), (3000, 4000)],)
    param_names = ["shape"]
    timeout = 300

    def setup(self, shape):
        need("io.save_frame", "io.load_frame")
        import tempfile
        from pathlib import Path

        from rgbz_fast.simulation import Scene, simulate

        skip_if_slow(shape)
        img = tile_to(astronaut(), shape)
        xx = np.arange(shape[1])[None, :] * np.ones((shape[0], 1))
        self.frame = simulate(Scene(img, depth=1.0 + xx / shape[1]), "mask1", seed=0)
        self.tmp = tempfile.TemporaryDirectory()
        self.path = Path(self.tmp.name) / "frame.npz"
        rz.io.save_frame(self.path, self.frame)

    def teardown(self, shape):
        self.tmp.cleanup()

    def time_save_frame(self, shape):
        rz.io.save_frame(self.path, self.frame)

    def time_load_frame(self, shape):
        rz.io.load_frame(self.path)
