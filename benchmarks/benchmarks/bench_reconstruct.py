"""Missing-colour reconstruction: method x mask x precision x frame size."""

import numpy as np

from .common import BIG_SHAPE, KODAK_SHAPE, astronaut, need, need_method, rz, skip_if_slow


class ReconstructSuite:
    params = ([KODAK_SHAPE, BIG_SHAPE], ["mask1", "mask2"],
              ["bilinear", "bi", "edi_central", "edi_line", "sg", "learned"],
              ["float32", "float64"])
    param_names = ["shape", "pattern", "method", "precision"]
    timeout = 300

    def setup(self, shape, pattern, method, precision):
        need("reconstruct", "mosaic")
        need_method(method)
        skip_if_slow(shape)
        self.frame = rz.mosaic(astronaut(shape), pattern)
        rz.reconstruct(self.frame.data[:64, :64], method, pattern=pattern, precision=precision)

    def time_reconstruct(self, shape, pattern, method, precision):
        rz.reconstruct(self.frame, method, precision=precision)

    def time_reconstruct_1thread(self, shape, pattern, method, precision):
        rz.reconstruct(self.frame, method, precision=precision, workers=1)

    def peakmem_reconstruct(self, shape, pattern, method, precision):
        rz.reconstruct(self.frame, method, precision=precision)

    def peakmem_setup(self, shape, pattern, method, precision):
        pass


class FastExpSuite:
    """The polynomial exponential of eq. 7 (``exp="fast"``) against the C library's."""

    params = ([KODAK_SHAPE, BIG_SHAPE], ["mask1", "mask2"], ["libm", "fast"])
    param_names = ["shape", "pattern", "exp"]
    timeout = 300

    def setup(self, shape, pattern, exp):
        need("reconstruct", "mosaic")
        skip_if_slow(shape)
        self.frame = rz.mosaic(astronaut(shape), pattern)
        try:
            rz.reconstruct(self.frame.data[:64, :64], "sg", pattern=pattern, exp=exp)
        except TypeError:
            raise NotImplementedError("reconstruct has no exp= option") from None

    def time_sg_float32(self, shape, pattern, exp):
        rz.reconstruct(self.frame, "sg", precision="float32", exp=exp)


class StraightLineSuite:
    """SG float32: the patterns' compiled plans (Mask1's constants, Mask2's straight-line code,
    csrc/recon_mask2.h) against the plan interpreter (``plans_only``), the same bits."""

    params = ([KODAK_SHAPE, BIG_SHAPE], ["mask1", "mask2", "mask2_rggb"], ["compiled", "plans"])
    param_names = ["shape", "pattern", "code"]
    timeout = 300

    def setup(self, shape, pattern, code):
        need("reconstruct", "mosaic")
        skip_if_slow(shape)
        try:
            from rgbz_fast.reconstruction._reconstruct import plans_only
        except ImportError:
            raise NotImplementedError("no plans_only in this version") from None
        self.plans_only = plans_only
        self.frame = rz.mosaic(astronaut(shape), pattern)
        rz.reconstruct(self.frame.data[:64, :64], "sg", pattern=pattern)

    def time_sg_float32(self, shape, pattern, code):
        if code == "plans":
            with self.plans_only():
                rz.reconstruct(self.frame, "sg", precision="float32")
        else:
            rz.reconstruct(self.frame, "sg", precision="float32")


class EdiRowsSuite:
    params = ([(516, 768), (3000, 4000)], ["float32", "float64"])
    param_names = ["shape", "precision"]
    timeout = 300

    def setup(self, shape, precision):
        need("reconstruct", "mosaic", "rows")
        skip_if_slow(shape)
        self.frame = rz.mosaic(astronaut(shape), rz.rows())

    def time_edi_rows(self, shape, precision):
        rz.reconstruct(self.frame, "edi_rows", precision=precision)


class InputTypeSuite:
    """A plain uint16 array (range check on every call) against a validated RawFrame."""

    params = (["array", "rawframe"],)
    param_names = ["input"]

    def setup(self, kind):
        need("reconstruct", "mosaic")
        self.frame = rz.mosaic(astronaut(KODAK_SHAPE), "mask1")
        self.data = np.ascontiguousarray(self.frame.data)

    def time_sg(self, kind):
        if kind == "array":
            rz.reconstruct(self.data, "sg", pattern="mask1")
        else:
            rz.reconstruct(self.frame, "sg")

    def peakmem_sg(self, kind):
        if kind == "array":
            rz.reconstruct(self.data, "sg", pattern="mask1")
        else:
            rz.reconstruct(self.frame, "sg")


class ZGuidedSuite:
    """method="z_guided" from a frame's ToF taps (the amplitude's demodulation included)."""

    params = ([KODAK_SHAPE, BIG_SHAPE], ["mask1", "mask2"], ["float32", "float64"])
    param_names = ["shape", "pattern", "precision"]
    timeout = 600

    def setup(self, shape, pattern, precision):
        need("reconstruct")
        need_method("z_guided")
        skip_if_slow(shape)
        from rgbz_fast.reconstruction import default_z_filters
        from rgbz_fast.simulation import Scene, simulate
        if default_z_filters(pattern) is None:
            raise NotImplementedError(f"no z_guided filters ship for {pattern}")
        scene = Scene.from_rgb(astronaut(shape), depth=np.full(shape, 2.0))
        self.frame = simulate(scene, pattern, seed=0, noise=True)

    def time_z_guided(self, shape, pattern, precision):
        rz.reconstruct(self.frame, "z_guided", precision=precision)

    def time_z_guided_2threads(self, shape, pattern, precision):
        rz.reconstruct(self.frame, "z_guided", precision=precision, workers=2)
