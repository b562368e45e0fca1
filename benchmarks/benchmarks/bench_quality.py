"""Accuracy tracked per commit: an accuracy regression shows like a speed one."""

from .common import astronaut, kodak_dir, need, need_method, rz


def _cfa_psnr(img, pattern, method):
    from rgbz_fast.metrics import cfa_psnr

    img = img[: img.shape[0] // 4 * 4, : img.shape[1] // 4 * 4]
    ref = rz.mosaic(img, rz.bayer("GRBG")).data
    frame = rz.mosaic(img, pattern)
    out = rz.reconstruct(frame, method, precision="float64")
    return float(cfa_psnr(ref, out, frame.z_mask, bit_depth=frame.bit_depth))


class QualitySuite:
    """Noise-free CFA PSNR (dB) on the Z sites of skimage's astronaut (always available)."""

    unit = "dB"
    params = (["mask1", "mask2"], ["sg", "bilinear", "learned"])
    param_names = ["pattern", "method"]

    def setup(self, pattern, method):
        need("reconstruct", "mosaic", "metrics.cfa_psnr")
        need_method(method)
        self.img = astronaut()

    def track_cfa_psnr_astronaut(self, pattern, method):
        return _cfa_psnr(self.img, pattern, method)


class KodakQualitySuite:
    """The same on a fixed Kodak image (kodim19, the fence); skipped without ../shared/data."""

    unit = "dB"
    params = (["mask1", "mask2"], ["sg", "bilinear", "learned"])
    param_names = ["pattern", "method"]

    def setup(self, pattern, method):
        need("reconstruct", "mosaic", "metrics.cfa_psnr")
        need_method(method)
        d = kodak_dir()
        if d is None:
            raise NotImplementedError("../shared/data/kodak not found")
        import imageio.v3 as iio

        self.img = iio.imread(d / "kodim19.png")[..., :3]

    def track_cfa_psnr_kodim19(self, pattern, method):
        return _cfa_psnr(self.img, pattern, method)
