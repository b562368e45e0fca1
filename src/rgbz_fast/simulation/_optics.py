"""The lens in front of the pixels: a point-spread function from the optical transfer function.

A scene image gives the radiance at the centre of every pixel; the optics and
the pixel turn it into what a pixel collects. :class:`Optics` describes a
rotationally symmetric, aberration-free lens with optional defocus and an
optional optical low-pass filter (OLPF); its optical transfer function (OTF) is
the product [1]_ [2]_

.. math::

    H(\\xi, \\eta) = H_{diff}(\\rho) \\; H_{defocus}(\\rho) \\; H_{OLPF}(\\xi, \\eta) \\;
                   H_{pixel}(\\xi, \\eta),  \\qquad \\rho = \\sqrt{\\xi^2 + \\eta^2}

with spatial frequencies in cycles per pixel (``xi = nu * p``, ``nu`` in
cycles/um, ``p`` the pixel pitch in um):

* diffraction by a circular pupil (incoherent light, Goodman [1]_ eq. 6-32):
  ``H_diff = (2/pi) (acos(s) - s sqrt(1 - s^2))`` for ``s = rho / rho_c < 1``,
  else 0, with the cut-off ``rho_c = p / (lambda N)`` (``lambda`` in um,
  ``N`` the f-number); averaged over the wavelengths of a colour channel's
  band;
* defocus, in the geometric approximation (a uniform blur disk of diameter
  ``b``; a focus error ``dz`` in the image space gives ``b = dz / N``):
  ``H_defocus = 2 J1(pi b nu) / (pi b nu)``. It is exact for ``b = 0`` and
  the usual approximation when the defocus is several waves [3]_;
* a four-spot birefringent OLPF that splits every ray into four displaced by
  ``d = olpf * p`` in rows and in columns [4]_:
  ``H_OLPF = cos(pi olpf xi) cos(pi olpf eta)`` (``olpf = 1``: the first
  zero at the Nyquist frequency, the classic design);
* the pixel aperture, a square of side ``sqrt(fill_factor) * p`` that
  integrates the light falling on it [2]_: ``sinc(sqrt(ff) xi) sinc(sqrt(ff) eta)``.

The discrete kernel (:meth:`Optics.psf`) is the continuous PSF integrated over
each pixel's aperture and sampled at whole-pixel offsets, i.e. the inverse
Fourier transform of ``H`` at integer pixel positions. Because ``H_diff``
vanishes beyond ``rho_c``, that integral is over a bounded region and is
computed exactly by a discrete Fourier transform on a grid of ``L x M``
samples per axis (``L`` cycles/pixel >= 2 rho_c, ``M`` pixels of period);
the only approximation is the period ``M``, at least 16 first-zero radii of
the Airy disc and 8 times the defocus and OLPF blur (the Airy tails beyond
``M / 2`` pixels alias back: 0.26-0.34 % of the energy at f/2.8 on a 2.8 um
pitch, 0.52-0.69 % on 1.4 um, from the blue band to the red, within the 1 % the
cut below leaves out). The
kernel is cut where at most 1 % of its energy lies outside (the far rings of
the Airy pattern, a veiling glare a demosaicing study does not need; the kept
core is the blur at the pixel scale) and scaled to sum to 1 (a fill factor
below 1 loses light; that loss belongs in the quantum efficiency, so the optics
conserves the signal). The frequency grid is at most 8192 x 8192 samples
(``MAX_GRID``): a lens whose cut-off frequency or blur needs more (an f-number
near 0.5 at a large pixel pitch, a defocus of hundreds of pixels) is refused
with the parameters that ask for it, rather than allocating gigabytes.

References
----------
.. [1] Goodman, *Introduction to Fourier Optics*, section 6.3: the OTF of a diffraction-limited circular pupil (docs/references.bib: goodman2005fourier)
.. [2] Boreman, *Modulation Transfer Function in Optical and Electro-Optical Systems*: cascading MTFs, the pixel-aperture sinc (docs/references.bib: boreman2001mtf)
.. [3] Stokseth, "Properties of a defocused optical system": the defocused OTF and its geometric limit (docs/references.bib: stokseth1969defocus)
.. [4] Greivenkamp, "Color dependent optical prefilter for the suppression of aliasing artifacts": birefringent optical low-pass filters (docs/references.bib: greivenkamp1990olpf)
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from .._validate import check_image, check_number, check_workers, kernel_threads

__all__ = ["Optics", "apply_optics"]

#: wavelengths averaged over a colour channel's band
_BAND_SAMPLES = 5
#: energy left outside the cut kernel
_TAIL = 1e-2
#: the largest frequency grid (samples per axis) a kernel is computed on: its OTF and inverse
#: FFT take about 60 bytes a sample (4 GB at 8192 x 8192)
MAX_GRID = 8192


def _band(value, name):
    """(lo, hi) nm of a band given as one wavelength or a pair."""
    try:
        v = tuple(float(x) for x in np.atleast_1d(np.asarray(value, dtype=np.float64)))
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a wavelength in nm or a (low, high) band, "
                        f"got {value!r}") from None
    if len(v) == 1:
        v = v * 2
    if len(v) != 2 or not all(math.isfinite(x) and 200 <= x <= 2000 for x in v) or v[0] > v[1]:
        raise ValueError(f"{name}: expected a wavelength or a (low, high) band within "
                         f"200..2000 nm, got {value!r}")
    return v


@dataclass(frozen=True)
class Optics:
    """A diffraction-limited lens with optional defocus and OLPF, and the pixel aperture.

    See the module docstring for the transfer functions and how the kernel
    is computed. :func:`~rgbz_fast.simulation.simulate` and
    :func:`~rgbz_fast.simulation.simulate_colour` apply it to the scene when
    given (``optics=``); without it the scene reaches the pixels unblurred
    (every result of the library without optics is unchanged).

    Parameters
    ----------
    f_number : float
        Working f-number ``N`` of the lens (2.8: the lens the colour sensor's
        ``photon_flux`` assumes). The diffraction cut-off is ``1 / (lambda N)``.
    bands_nm : tuple of 3 (low, high) pairs
        The wavelength bands of the R, G and B channels over which the
        diffraction OTF is averaged for an RGB scene (570-650, 490-580,
        420-510 nm: the half-maximum bands of typical Bayer filters). A
        spectral scene uses each band's own wavelength instead.
    olpf : float
        Spot separation of a four-spot OLPF in pixel pitches (0: no OLPF;
        1: zeros at the Nyquist frequency), in [0, 2].
    defocus_um : float
        Diameter of the geometric blur disk in um (0: in focus). A focus
        error ``dz`` um behind or before the sensor gives ``dz / f_number``.
    fill_factor : float
        Share of the pixel's area that integrates light, in (0, 1] (1: gapless
        microlenses).

    Examples
    --------
    >>> import numpy as np
    >>> k = Optics(f_number=2.8).psf(540.0, pixel_pitch_um=2.8)
    >>> k.shape, round(float(k.sum()), 12), bool(k[k.shape[0] // 2, k.shape[1] // 2] == k.max())
    ((21, 21), 1.0, True)
    >>> round(float(Optics(f_number=2.8).mtf(0.5, 540.0, pixel_pitch_um=2.8)), 4)
    0.4205
    """

    f_number: float = 2.8
    bands_nm: tuple = ((570.0, 650.0), (490.0, 580.0), (420.0, 510.0))
    olpf: float = 0.0
    defocus_um: float = 0.0
    fill_factor: float = 1.0

    def __post_init__(self):
        object.__setattr__(self, "f_number", check_number(self.f_number, "Optics.f_number",
                                                          lo=0.5, hi=64))
        try:
            bands = tuple(self.bands_nm)
        except TypeError:
            raise TypeError(f"Optics.bands_nm: expected 3 (low, high) bands in nm, got "
                            f"{self.bands_nm!r}") from None
        if len(bands) != 3:
            raise ValueError(f"Optics.bands_nm: expected 3 bands (R, G, B), got {len(bands)}")
        object.__setattr__(self, "bands_nm",
                           tuple(_band(b, "Optics.bands_nm") for b in bands))
        object.__setattr__(self, "olpf", check_number(self.olpf, "Optics.olpf", lo=0, hi=2))
        object.__setattr__(self, "defocus_um", check_number(self.defocus_um,
                                                            "Optics.defocus_um", lo=0, hi=1000))
        object.__setattr__(self, "fill_factor", check_number(
            self.fill_factor, "Optics.fill_factor", lo=0, hi=1, lo_open=True))

    # -- transfer functions ---------------------------------------------------------
    def otf(self, xi, eta, wavelength_nm, *, pixel_pitch_um, f_number=None):
        """The OTF at spatial frequencies ``(xi, eta)`` in cycles per pixel.

        Parameters
        ----------
        xi, eta : array_like
            Frequencies along rows and columns (broadcast together).
        wavelength_nm : float or (float, float)
            One wavelength, or a band whose diffraction OTF is averaged over
            5 evenly spaced wavelengths.
        pixel_pitch_um : float
            The pixel pitch (um): frequencies in cycles per pixel scale with it.
        f_number : float, optional
            Overrides :attr:`f_number` (the ToF model uses its own lens).

        Returns
        -------
        ndarray of float64
            Real (the system is symmetric); negative where the defocus or the
            OLPF reverses the contrast.
        """
        lo, hi = _band(wavelength_nm, "wavelength_nm")
        p = check_number(pixel_pitch_um, "pixel_pitch_um", lo=0.1, hi=100)
        n = self.f_number if f_number is None else check_number(f_number, "f_number",
                                                                lo=0.5, hi=64)
        xi = check_image(xi, "xi").astype(np.float64)
        eta = check_image(eta, "eta").astype(np.float64)
        for a, label in ((xi, "xi"), (eta, "eta")):
            if np.abs(a).max() > 1e6:       # sin(pi x) of larger ones is NaN beyond 1e308
                raise ValueError(f"{label}: expected frequencies within +-1e6 cycles per "
                                 f"pixel, got up to {np.abs(a).max():g}")
        try:
            xi, eta = np.broadcast_arrays(xi, eta)
        except ValueError:
            raise ValueError(f"eta: shape {eta.shape} does not broadcast with xi "
                             f"{xi.shape}") from None
        rho = np.hypot(xi, eta)
        lams = np.linspace(lo, hi, _BAND_SAMPLES) if hi > lo else np.array([lo])
        h = np.zeros(rho.shape)
        for lam in lams:
            s = np.minimum(rho * (lam * 1e-3) * n / p, 1.0)
            h += (2 / np.pi) * (np.arccos(s) - s * np.sqrt(1.0 - s * s))
        h /= lams.size
        if self.defocus_um > 0:
            from scipy.special import j1

            x = np.pi * (self.defocus_um / p) * rho
            safe = np.where(x > 0, x, 1.0)
            h *= np.where(x > 0, 2 * j1(safe) / safe, 1.0)
        if self.olpf > 0:
            h *= np.cos(np.pi * self.olpf * xi) * np.cos(np.pi * self.olpf * eta)
        a = math.sqrt(self.fill_factor)
        h *= np.sinc(a * xi) * np.sinc(a * eta)
        return h

    def mtf(self, frequency, wavelength_nm, *, pixel_pitch_um, f_number=None):
        """``|OTF|`` along the rows at ``frequency`` cycles per pixel (see :meth:`otf`)."""
        f = check_image(frequency, "frequency")
        return np.abs(self.otf(f, np.zeros(f.shape), wavelength_nm,
                               pixel_pitch_um=pixel_pitch_um, f_number=f_number))

    def psf(self, wavelength_nm, *, pixel_pitch_um, f_number=None):
        """The discrete kernel: the PSF integrated over each pixel, at whole-pixel offsets.

        Parameters
        ----------
        wavelength_nm, pixel_pitch_um, f_number
            As :meth:`otf`.

        Returns
        -------
        ndarray of float64, shape (2 R + 1, 2 R + 1)
            Non-negative, symmetric, summing to 1; ``R`` is the smallest
            radius that leaves at most 1 % of the energy outside.

        Raises
        ------
        ValueError
            The frequency grid the kernel needs (cut-off frequency times blur
            extent) is beyond ``MAX_GRID`` samples per axis.
        """
        band = _band(wavelength_nm, "wavelength_nm")
        p = check_number(pixel_pitch_um, "pixel_pitch_um", lo=0.1, hi=100)
        n = self.f_number if f_number is None else check_number(f_number, "f_number",
                                                                lo=0.5, hi=64)
        return _psf_cached(self, band, p, n).copy()

    def channel_psfs(self, *, pixel_pitch_um):
        """The three kernels of the R, G and B bands (:meth:`psf` of each of :attr:`bands_nm`)."""
        return [self.psf(b, pixel_pitch_um=pixel_pitch_um) for b in self.bands_nm]


@functools.lru_cache(maxsize=64)
def _psf_cached(optics, band, pitch, f_number):
    lam_min = band[0] * 1e-3
    cutoff = pitch / (lam_min * f_number)                 # cycles per pixel
    L = int(math.ceil(2 * cutoff)) + 1                    # sampled frequency span
    # the period must hold the widest blur: the defocus disc and the OLPF's split, or four
    # first-zero radii of the Airy disc at the band's longest wavelength (at f/64 and a
    # 0.5 um pitch that radius is 109 pixels: a period sized on the defocus alone wrapped
    # the Airy core onto itself, a flat 63 x 63 box whose MTF passed what the lens cuts)
    airy_px = 1.22 * band[-1] * 1e-3 * f_number / pitch
    blur_px = max(optics.defocus_um / pitch + 2 * optics.olpf + 1, 4 * airy_px)
    M = 64
    while M < 8 * blur_px + 16:
        M *= 2
    N = L * M
    if N > MAX_GRID:
        raise ValueError(
            f"optics: the kernel at f_number={f_number:g}, pixel_pitch_um={pitch:g}, "
            f"defocus_um={optics.defocus_um:g} and olpf={optics.olpf:g} needs a {N} x {N} "
            f"frequency grid ({L} samples per cycle for a cut-off of {cutoff:.3g} cycles per "
            f"pixel, a period of {M} pixels for a blur of {blur_px:.3g}, the Airy disc's first "
            f"zero at {airy_px:.3g} pixels); the model computes up to {MAX_GRID} x {MAX_GRID}: "
            + ("raise f_number, or lower the pixel pitch" if M == 64 else
               "lower f_number or defocus_um, or raise the pixel pitch"))
    f = np.fft.fftfreq(N, d=1.0 / L)                      # spacing 1 / M cycles/pixel
    H = optics.otf(f[:, None], f[None, :], band, pixel_pitch_um=pitch, f_number=f_number)
    fine = np.fft.ifft2(H).real * (L * L)
    k = np.fft.fftshift(fine[::L, ::L])                   # whole pixels, centred at M // 2
    np.maximum(k, 0.0, out=k)
    c = M // 2
    total = k.sum()
    radius = 1
    while radius < c - 1:
        inner = k[c - radius:c + radius + 1, c - radius:c + radius + 1].sum()
        if total - inner <= _TAIL * total:
            break
        radius += 1
    k = k[c - radius:c + radius + 1, c - radius:c + radius + 1]
    k = 0.5 * (k + k[::-1, ::-1])                         # exact symmetry
    return k / k.sum()


def _convolve(plane, kernel, *, signed=False, workers=1):
    """``plane`` convolved with ``kernel``, the borders mirrored (edge pixel repeated).

    A non-negative plane stays non-negative (FFT round-off below 0 is cut)
    unless ``signed`` (the real and imaginary parts of the ToF phasors). The FFTs run
    on ``workers`` threads (a checked count; pocketfft transforms each line alone, so the
    result does not depend on it).
    """
    import scipy.fft
    from scipy.signal import oaconvolve

    r = kernel.shape[0] // 2
    padded = np.pad(np.asarray(plane, np.float64), r, mode="symmetric")
    with scipy.fft.set_workers(kernel_threads(workers, padded.size)):
        out = oaconvolve(padded, kernel, mode="valid")
    if not signed:
        np.maximum(out, 0.0, out=out)
    return out


def apply_optics(image, optics, *, pixel_pitch_um, wavelengths=None, f_number=None,
                 workers=None):
    """Blur an image of scene radiance through :class:`Optics` and the pixel aperture.

    Parameters
    ----------
    image : ndarray, shape (H, W, 3) or (H, W, K) or (H, W)
        Linear values (>= 0): an RGB image (the channel bands of
        ``optics.bands_nm``), a spectral cube with ``wavelengths``, or one
        plane with one wavelength.
    optics : Optics
    pixel_pitch_um : float
        The sensor's pixel pitch in um.
    wavelengths : array_like, optional
        One wavelength (nm) per band of a spectral cube, or the wavelength of
        a single plane; None for RGB.
    f_number : float, optional
        Overrides ``optics.f_number``.
    workers : int, optional
        Threads of the FFTs (None or -1: all cores). The result does not
        depend on it.

    Returns
    -------
    ndarray of float64, same shape
        Every channel convolved with its kernel (borders mirrored). The
        blur conserves the sum of each channel away from the borders.

    Examples
    --------
    >>> import numpy as np
    >>> img = np.zeros((9, 9, 3)); img[4, 4] = 1.0
    >>> out = apply_optics(img, Optics(), pixel_pitch_um=2.8)
    >>> out.shape, bool(np.allclose(out.sum(axis=(0, 1)), 1.0)), bool(out[4, 4, 1] < 1.0)
    ((9, 9, 3), True, True)
    """
    if not isinstance(optics, Optics):
        raise TypeError(f"optics: expected an Optics, got {type(optics).__name__}")
    img = check_image(image, "image", ndim=(2, 3))
    nthreads = check_workers(workers)
    if img.min() < 0:
        raise ValueError(f"image: holds negative values (min {img.min()}); expected linear "
                         "values >= 0")
    if img.max() > 1e300:
        raise ValueError(f"image: values up to {img.max():g}; the convolution overflows "
                         "beyond 1e300 (linear values, 1 = white)")
    if img.ndim == 2:
        if wavelengths is None:
            raise ValueError("wavelengths: a single plane needs its wavelength in nm")
        return _convolve(img, optics.psf(wavelengths, pixel_pitch_um=pixel_pitch_um,
                                         f_number=f_number), workers=nthreads)
    if img.ndim != 3:
        raise ValueError(f"image: expected a 2-D or 3-D array, got shape {img.shape}")
    if wavelengths is None:
        if img.shape[2] != 3:
            raise ValueError(f"wavelengths: a {img.shape[2]}-band image needs one wavelength "
                             "per band (None is for RGB)")
        kernels = [optics.psf(b, pixel_pitch_um=pixel_pitch_um, f_number=f_number)
                   for b in optics.bands_nm]
    else:
        wl = check_image(wavelengths, "wavelengths").astype(np.float64).reshape(-1)
        if wl.size != img.shape[2]:
            raise ValueError(f"wavelengths: expected {img.shape[2]} values, got {wl.size}")
        kernels = [optics.psf(float(w), pixel_pitch_um=pixel_pitch_um, f_number=f_number)
                   for w in wl]
    out = np.empty(img.shape, np.float64)
    for c, k in enumerate(kernels):
        out[..., c] = _convolve(img[..., c], k, workers=nthreads)
    return out
