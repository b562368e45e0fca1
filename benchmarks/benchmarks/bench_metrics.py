"""The metrics (C kernels) on a Kodak-size pair, and the dataset evaluation.

The pair is the astronaut tiled to 768x512 and a blurred, noisy copy (8-bit sRGB, as the
evaluation scores them). ``workers`` 1 and all cores: the kernels split rows across threads.
"""

import numpy as np

from .common import KODAK_SHAPE, astronaut, kodak_dir, need, rz


def _pair():
    from scipy import ndimage as ndi

    ref = astronaut(KODAK_SHAPE)
    blurred = ndi.gaussian_filter(ref.astype(np.float64), sigma=(1.0, 1.0, 0))
    noise = np.random.default_rng(0).normal(0, 3, ref.shape)
    return ref, np.clip(np.rint(blurred + noise), 0, 255).astype(np.uint8)


class MetricsSuite:
    params = (["cpsnr", "ssim", "ms_ssim", "zipper", "all_metrics"], [1, None])
    param_names = ["metric", "workers"]

    def setup(self, metric, workers):
        need(f"metrics.{metric}")
        from rgbz_fast import metrics

        fn = getattr(metrics, metric)
        self.ref, self.test = _pair()
        try:
            fn(self.ref[:200, :200], self.test[:200, :200], crop=8, workers=workers)
            self.call = lambda: fn(self.ref, self.test, crop=8, workers=workers)
        except TypeError:                  # a commit before the metrics took workers=
            if workers is not None:
                raise NotImplementedError("no workers= in this commit") from None
            self.call = lambda: fn(self.ref, self.test, crop=8)

    def time_metric(self, metric, workers):
        self.call()


class CFAPSNRSuite:
    params = ([1, None],)
    param_names = ["workers"]

    def setup(self, workers):
        need("metrics.cfa_psnr", "mosaic", "reconstruct")
        from rgbz_fast.metrics import cfa_psnr

        img = astronaut(KODAK_SHAPE)
        frame = rz.mosaic(img, "mask1")
        self.ref = rz.mosaic(img, "bayer").data
        self.out = rz.reconstruct(frame, "sg")
        self.z = frame.z_mask
        kw = {} if workers is None else {"workers": workers}
        try:
            cfa_psnr(self.ref, self.out, self.z, bit_depth=11, **kw)
        except TypeError:
            raise NotImplementedError("no workers= in this commit") from None
        self.call = lambda: cfa_psnr(self.ref, self.out, self.z, bit_depth=11, **kw)

    def time_cfa_psnr(self, workers):
        self.call()


class EvaluateSuite:
    """``evaluate`` (all metrics, both masks, five methods) on the first two Kodak images,
    in-process, one thread per kernel; skipped without ../shared/data/kodak."""

    timeout = 600

    def setup(self):
        need("evaluation.evaluate", "io.folder_dataset")
        d = kodak_dir()
        if d is None:
            raise NotImplementedError("../shared/data/kodak not found")
        self.ds = rz.io.folder_dataset(d, 2)
        rz.evaluation.evaluate(self.ds[:1], processes=1, workers=1, progress=False)

    def time_evaluate_two_kodak_images(self):
        rz.evaluation.evaluate(self.ds, processes=1, workers=1, progress=False)

