"""Image-quality metrics of Rebiere et al., section 5.3 (eqs. 20-31).

Two levels of assessment are used in the paper [1]_:

* on the reconstructed CFA image, the PSNR restricted to the reconstructed
  (Z) sites: :func:`cfa_psnr` (eqs. 20-21);
* on the full-colour image at the end of the ISP: the colour PSNR
  :func:`cpsnr` (eqs. 22-23, with :func:`cpsnr_pooled` for a data set),
  the SSIM :func:`ssim` (eqs. 24-27) [2]_, the multi-scale SSIM
  :func:`ms_ssim` (eq. 28) [3]_ and the zipper-effect metric :func:`zipper`
  (eqs. 29-31) [4]_. :func:`all_metrics` returns the four colour metrics.

Every function takes the reference first and the image under test second
and works in float64 whatever the input dtype, so uint8 and float inputs
holding the same values give the same results; every score is returned as a
Python ``float``. The arithmetic runs in C kernels (``csrc/metrics.c``:
threads over rows, ``workers=``, with the same result for every thread count),
checked against the former NumPy, SciPy and colour-science implementations
(``tests/_reference/metrics.py``), scikit-image and colour-science.

``crop`` removes that many pixels from each border of the rows and columns
before anything else is computed (the usual way to keep demosaicing border
artefacts out of a score).

References
----------
.. [1] Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z CMOS imager", section 5.3 (docs/references.bib: rebiere_rgbz)
.. [2] Wang et al., "Image quality assessment: from error visibility to structural similarity" (docs/references.bib: wang2004ssim)
.. [3] Wang, Simoncelli and Bovik, "Multiscale structural similarity for image quality assessment" (docs/references.bib: wang2003msssim)
.. [4] Lu and Tan, "Color filter array demosaicking: new method and performance measures" (docs/references.bib: lu2003zipper)
"""

from ._combined import all_metrics
from ._common import SSIM_DATA_RANGE
from ._psnr import cfa_psnr, cpsnr, cpsnr_pooled
from ._ssim import MS_SSIM_WEIGHTS, ms_ssim, ssim
from ._zipper import ZIPPER_INPUTS, delta_e_map, zipper

__all__ = ["cfa_psnr", "cpsnr", "cpsnr_pooled", "ssim", "ms_ssim", "zipper", "delta_e_map",
           "all_metrics", "MS_SSIM_WEIGHTS", "ZIPPER_INPUTS", "SSIM_DATA_RANGE"]
