"""Malvar 2004, bilinear and Menon 2007 demosaic of the full Bayer CFA (C kernels; bilinear
and Menon 2007 ran through colour-demosaicing before their kernels)."""

import numpy as np

from .common import BIG_SHAPE, KODAK_SHAPE, astronaut, need, rz, skip_if_slow


class DemosaicSuite:
    params = ([KODAK_SHAPE, BIG_SHAPE], ["float32", "float64"])
    param_names = ["shape", "dtype"]
    timeout = 300

    def setup(self, shape, dtype):
        need("mosaic", "bayer")
        skip_if_slow(shape)
        self.cfa = rz.mosaic(astronaut(shape), rz.bayer("GRBG")).data
        self.dtype = np.dtype(dtype)
        try:
            from rgbz_fast.isp import demosaic
            self.fn = lambda: demosaic(self.cfa, "GRBG", "malvar2004", dtype=self.dtype)
            self.bilinear = lambda: demosaic(self.cfa, "GRBG", "bilinear", dtype=self.dtype)
            self.menon = lambda: demosaic(self.cfa, "GRBG", "menon2007", dtype=self.dtype)
        except ImportError:
            try:
                from rgbz_fast import _kernels
                _kernels.demosaic_malvar
            except (ImportError, AttributeError):
                raise NotImplementedError("no Malvar demosaic in this commit") from None
            phase = np.array([1, 0, 2, 1], np.int32)

            def fn():
                out = np.empty(self.cfa.shape + (3,), self.dtype)
                _kernels.demosaic_malvar(self.cfa, out, phase, 0, 0)
                return out
            self.fn = fn
            self.bilinear = self.menon = None

    def time_malvar(self, shape, dtype):
        self.fn()

    def peakmem_malvar(self, shape, dtype):
        self.fn()

    def time_bilinear(self, shape, dtype):
        if self.bilinear is None:
            raise NotImplementedError("no isp.demosaic in this commit")
        self.bilinear()

    def peakmem_bilinear(self, shape, dtype):
        if self.bilinear is None:
            raise NotImplementedError("no isp.demosaic in this commit")
        self.bilinear()

    def time_menon(self, shape, dtype):
        if self.menon is None:
            raise NotImplementedError("no isp.demosaic in this commit")
        self.menon()

    def peakmem_menon(self, shape, dtype):
        if self.menon is None:
            raise NotImplementedError("no isp.demosaic in this commit")
        self.menon()
