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
.. [1] V. Rebiere, A. Drouot, B. Granado, A. Bourge, A. Pinna, "Color pixel
       reconstruction for a monolithic RGB-Z CMOS imager", section 5.3.
.. [2] Z. Wang, A. C. Bovik, H. R. Sheikh, E. P. Simoncelli, "Image quality
       assessment: from error visibility to structural similarity," IEEE
       Trans. Image Process. 13(4), 600-612 (2004). :DOI:`10.1109/TIP.2003.819861`
.. [3] Z. Wang, E. P. Simoncelli, A. C. Bovik, "Multiscale structural
       similarity for image quality assessment," Proc. 37th Asilomar Conf.
       Signals, Systems and Computers, 1398-1402 (2003).
       :DOI:`10.1109/ACSSC.2003.1292216`
.. [4] W. Lu, Y.-P. Tan, "Color filter array demosaicking: new method and
       performance measures," IEEE Trans. Image Process. 12(10), 1194-1210
       (2003). :DOI:`10.1109/TIP.2003.816004`
"""

from ._combined import all_metrics
from ._common import SSIM_DATA_RANGE
from ._psnr import cfa_psnr, cpsnr, cpsnr_pooled
from ._ssim import MS_SSIM_WEIGHTS, ms_ssim, ssim
from ._zipper import ZIPPER_INPUTS, delta_e_map, zipper

__all__ = ["cfa_psnr", "cpsnr", "cpsnr_pooled", "ssim", "ms_ssim", "zipper", "delta_e_map",
           "all_metrics", "MS_SSIM_WEIGHTS", "ZIPPER_INPUTS", "SSIM_DATA_RANGE"]
