"""Slow, obviously correct NumPy references of the C kernels and the vectorised stages.

* :mod:`_reference.reconstruction` -- every reconstruction method, site by site
  (docs/guide/interpretation.md is its specification);
* :mod:`_reference.defects` -- the defect correction, pixel by pixel from its definition;
* :mod:`_reference.metrics` -- SSIM, MS-SSIM, CIELAB and the zipper metric as
  rgbz_fast.metrics computed them in NumPy, SciPy and colour-science before its
  C kernels (csrc/metrics.c).
* :mod:`_reference.tof` -- the ToF ISP's bilateral phasor mean (csrc/tof_filter.c).
* :mod:`_reference.simulation` -- the sensor models' noise-free colour pixels and ideal
  ToF taps (csrc/sim.c), bit for bit.
* :mod:`_reference.demosaic` -- colour-demosaicing's demosaics with the library's two
  borders (csrc/demosaic.c, csrc/demosaic_menon.c: bilinear and Menon 2007 bit for bit).

The ToF kernels are checked against the vectorised NumPy twin
``rgbz_fast._devtools._numpy_tof`` (the bench's baseline), bit for bit; the
sRGB encoding kernels (csrc/srgb.c) against the colour chain's own NumPy
stages (``srgb_oetf`` and ``_quantise``, which it runs when it keeps its
stages), bit for bit (tests/isp/test_encode.py).
"""
