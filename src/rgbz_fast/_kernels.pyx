# cython: language_level=3, embedsignature=True
"""Thin bridge to the C core (csrc/): typed memoryviews, GIL released, status -> exception.

No logic of its own: the Python layer validates arguments and allocates every
output; this module only adapts buffers and maps status codes.

Two extension modules share ``_kernels_common.pxi`` (src/rgbz_fast/meson.build):
``rgbz_fast._kernels`` (this file: every kernel), which every user loads, and
``rgbz_fast._kernels_count`` (``_kernels_count.pyx``: the counted kernels, reconstruct,
learned and tof_demodulate, with the same constants), linked against the counting build
of the C core (-DRGBZ_COUNT_OPS), which only :mod:`rgbz_fast._devtools.opcount` loads.
Their common functions have the same interface; the counting module wants ``opcounts``
where the normal one refuses it.

The enums of csrc/rgbz.h are ``cpdef enum`` classes here, and the name -> code
tables of the Python layer (:data:`METHODS`, :data:`PRECISIONS`,
:data:`EXP_MODES`, :data:`DEMOSAIC_MODES`, :data:`OP_CATEGORIES`) are built from
them, so no code is typed twice.
"""

include "_kernels_common.pxi"


def _release_before_fork():
    # libgomp's threads do not survive fork: a child that starts a parallel region after its
    # parent ran one waited forever on threads it does not have (multiprocessing's "fork",
    # ProcessPoolExecutor's default on Linux). Ended before the fork, they are started
    # anew on both sides (probe round 24, M-01: robustness.md H106)
    rgbz_openmp_release()


import os as _os
if hasattr(_os, "register_at_fork"):
    _os.register_at_fork(before=_release_before_fork)


from libc.math cimport INFINITY, NAN
from libc.string cimport memset
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from libc.stdint cimport uint32_t

cdef extern from "tof_filter.h" nogil:
    int rgbz_tof_bilateral(const double *z_re, const double *z_im, const double *var,
                           const double *g_re, const double *g_im, const double *g_var,
                           const uint8_t *use, const int64_t *row_px, const int64_t *col_px,
                           Py_ssize_t nfreq, Py_ssize_t rows, Py_ssize_t cols,
                           Py_ssize_t reach_rows, Py_ssize_t reach_cols, int64_t radius_px,
                           double inv_h2, double *out_re, double *out_im, double *out_var, double *out_neff,
                           int workers)
    ctypedef struct rgbz_tof_validity_args:
        const double *amp
        const double *var
        const double *depth
        const double *residual
        const uint8_t *saturated
        Py_ssize_t F
        Py_ssize_t N
        const double *sigma_scale
        const double *refl_coef
        double phase_var_cap, power, tan_h, tan_v, k_cell, block
        double min_snr, min_amplitude, max_sigma, max_residual, min_reflectance, max_range
        double max_reflectance
        double *snr
        double *sigma
        double *refl
        uint8_t *flags
        const double *delta
    int rgbz_tof_validity(const rgbz_tof_validity_args *p, int workers)
    int rgbz_tof_fixed_pattern(const double *phase, const double *amp, const double *offset,
                               const double *count, Py_ssize_t F, Py_ssize_t N,
                               const double *sigma_scale, double black, double pre,
                               double var_dsnu, double fix_dsnu, double prnu, int shared,
                               double *delta, int workers)
    int rgbz_tof_phasors_offset(int in_type, const void *taps, Py_ssize_t F, Py_ssize_t N,
                                double *i, double *q, double *offset, int workers)
    int rgbz_tof_tap_variance(const double *offset, Py_ssize_t N, double black, double k,
                              double supp, double readout, double prnu, double scale,
                              const double *count, Py_ssize_t count_period, double *out,
                              int workers)
    int rgbz_tof_box(const double *const *inp, double *const *out, Py_ssize_t P, Py_ssize_t R,
                     Py_ssize_t C, const int64_t *row_px, const int64_t *col_px,
                     const int64_t *row_offs, Py_ssize_t n_row_offs, const int64_t *col_offs,
                     Py_ssize_t n_col_offs, int64_t radius, const double *weight,
                     double *count, int workers)

ctypedef fused rgb_t:
    float
    double


ctypedef int (*exp_f32_fn)(const float *, float *, Py_ssize_t) noexcept nogil
ctypedef int (*exp_f64_fn)(const double *, double *, Py_ssize_t) noexcept nogil


cdef _exp_each(const rgb_t[::1] x, rgb_t[::1] out, exp_f32_fn f32, exp_f64_fn f64):
    """out = f(x) element by element, f the entry point of x's precision."""
    cdef int status
    if out.shape[0] != x.shape[0]:
        raise ValueError(f"out: expected {x.shape[0]} values, got {out.shape[0]}")
    if x.shape[0] == 0:
        return
    with nogil:
        if rgb_t is float:
            status = f32(&x[0], &out[0], x.shape[0])
        else:
            status = f64(&x[0], &out[0], x.shape[0])
    _raise_for(status)


def fast_exp(const rgb_t[::1] x, rgb_t[::1] out):
    """The fast exponential of the reconstruction (exp="fast") of every element of ``x``."""
    _exp_each(x, out, rgbz_fast_exp_f32, rgbz_fast_exp_f64)


def libm_exp(const rgb_t[::1] x, rgb_t[::1] out):
    """exp() (float64) or expf() (float32) of every element of ``x`` as the reconstruction
    computes it with exp="libm": the C library's bits (its vector port where
    :func:`libm_exp_vectorised`)."""
    _exp_each(x, out, rgbz_libm_exp_f32, rgbz_libm_exp_f64)


def exp_port(const rgb_t[::1] x, rgb_t[::1] out):
    """The vector port's value of exp(x) (float64) or expf(x) (float32), one value at a time,
    whatever this machine's own function gives (csrc/rgbz_exp.h; for the tests)."""
    _exp_each(x, out, rgbz_exp_port_f32, rgbz_exp_port_f64)


def libm_exp_vectorised(bint single=False):
    """Whether exp="libm" in float64 (``single``: float32) runs through the vector port of
    glibc's exp() (expf()): the CPU runs AVX-512F and this machine's function gives the
    port's bits; otherwise the reconstruction calls the function itself."""
    return bool(rgbz_exp_libm_vectorised(single))


def demosaic_kernel(int method, const frame_t[:, ::1] src, rgb_t[:, :, ::1] dst,
                    const int32_t[::1] phase, int mode, int workers):
    """Demosaic (csrc/demosaic.c), method a code of DEMOSAIC_KERNELS (Malvar 2004; bilinear:
    colour-demosaicing's filters and scipy's order of the taps, bit for bit; Menon 2007,
    csrc/demosaic_menon.c: colour-demosaicing's operations in its order, bit for bit): Bayer
    CFA (rows, cols) -> RGB (rows, cols, 3)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int out_type = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    with nogil:
        status = rgbz_demosaic(method, in_type, out_type, &src[0, 0], &dst[0, 0, 0],
                               src.shape[0], src.shape[1], &phase[0], mode, workers)
    _raise_for(status)


def demosaic_malvar(src, dst, phase, int mode, int workers):
    """Malvar-He-Cutler 2004 demosaic (demosaic_kernel's Malvar; the asv suite of older
    commits calls it by this name)."""
    demosaic_kernel(RGBZ_DM_MALVAR, src, dst, phase, mode, workers)


def float_range(a):
    """(smallest, largest) value of a C-contiguous float32 or float64 array (both NaN if it
    holds NaN; csrc/scan.c): the argument checks' one pass."""
    cdef const float[::1] f
    cdef const double[::1] d
    cdef double lo = 0.0, hi = 0.0
    cdef int status
    flat = a.reshape(-1)
    if flat.dtype.char == "f":
        f = flat
        with nogil:
            status = rgbz_float_range(RGBZ_T_F32, &f[0], f.shape[0], &lo, &hi)
    else:
        d = flat
        with nogil:
            status = rgbz_float_range(RGBZ_T_F64, &d[0], d.shape[0], &lo, &hi)
    _raise_for(status)
    return lo, hi


def sites_range(const int64_t[::1] rows, const int64_t[::1] cols):
    """((smallest row, largest row, smallest column, largest column), ordered) of n >= 1
    measurement sites in one pass (csrc/scan.c); ordered: strictly increasing row-major
    (no site twice)."""
    cdef int64_t lo_hi[4]
    cdef int ordered = 0, status
    if cols.shape[0] != rows.shape[0]:
        raise ValueError("sites_range: rows and cols differ in length")
    with nogil:
        status = rgbz_sites_range(&rows[0], &cols[0], rows.shape[0], lo_hi, &ordered)
    _raise_for(status)
    return (lo_hi[0], lo_hi[1], lo_hi[2], lo_hi[3]), bool(ordered)


def sites_off_z(const int64_t[::1] rows, const int64_t[::1] cols, int block,
                const uint8_t[:, ::1] tile_z):
    """The index of the first site whose block x block cells are not all Z sites of the
    repeated tile, or -1 (csrc/scan.c); sites in [0, 2**31 - 2]."""
    cdef Py_ssize_t first = -1, n = rows.shape[0]
    cdef int status
    if cols.shape[0] != n:
        raise ValueError("sites_off_z: rows and cols differ in length")
    if n == 0:
        return -1
    with nogil:
        status = rgbz_sites_off_z(&rows[0], &cols[0], n, block, &tile_z[0, 0],
                                  tile_z.shape[0], tile_z.shape[1], &first)
    _raise_for(status)
    return first


def tof_unwrap(const double[:, ::1] phase, const double[::1] freqs, const double[::1] weights,
               double max_range, double[::1] depth, double[::1] residual, int32_t[::1] wraps,
               int workers):
    """Multi-frequency phase unwrapping (brute force over the base frequency's wraps).

    Returns False when a phase lies outside [0, 2 pi) or is NaN (the kernel's
    RGBZ_EDOMAIN; the caller names the parameter), True otherwise.
    """
    cdef int status
    if phase.shape[1] == 0:
        return True
    with nogil:
        status = rgbz_tof_unwrap(&phase[0, 0], phase.shape[0], phase.shape[1], &freqs[0],
                                 &weights[0], max_range, &depth[0], &residual[0], &wraps[0],
                                 workers)
    if status == RGBZ_EDOMAIN:
        return False
    _raise_for(status)
    return True


cdef double *_opt2(double[:, ::1] a) noexcept:
    return NULL if a is None else &a[0, 0]


def tof_depth(const tap_t[:, :, ::1] taps, const double[::1] freqs, const double[::1] weights,
              double max_range, double[::1] depth, double[::1] residual, int32_t[::1] wraps,
              double[:, ::1] phase=None, double[:, ::1] amp=None, double[:, ::1] offset=None,
              int workers=0):
    """Fused demodulation + unwrapping: taps (F, 4, N) -> depth, residual, wraps (N,) and,
    when given, phase, amplitude, offset (F, N)."""
    cdef int status
    cdef int in_type = _type_code(<tap_t *> NULL)
    cdef double *ph = _opt2(phase)
    cdef double *am = _opt2(amp)
    cdef double *of = _opt2(offset)
    if taps.shape[2] == 0:
        return
    with nogil:
        status = rgbz_tof_depth(in_type, &taps[0, 0, 0], taps.shape[0], taps.shape[2],
                                &freqs[0], &weights[0], max_range, &depth[0], &residual[0],
                                &wraps[0], ph, am, of, workers)
    _raise_for(status)


def tof_depth_iq(const double[:, ::1] i, const double[:, ::1] q, const double[::1] freqs,
                 const double[::1] weights, double max_range, double[::1] depth,
                 double[::1] residual, int32_t[::1] wraps, double[:, ::1] phase=None,
                 double[:, ::1] amp=None, int workers=0):
    """Phasors I, Q (F, N) -> phase, amplitude (when given), depth, residual, wraps.

    Returns False when an I or Q is not finite (RGBZ_EDOMAIN), True otherwise.
    """
    cdef int status
    cdef double *ph = _opt2(phase)
    cdef double *am = _opt2(amp)
    if i.shape[1] == 0:
        return True
    with nogil:
        status = rgbz_tof_depth_iq(&i[0, 0], &q[0, 0], i.shape[0], i.shape[1], &freqs[0],
                                   &weights[0], max_range, &depth[0], &residual[0], &wraps[0],
                                   ph, am, workers)
    if status == RGBZ_EDOMAIN:
        return False
    _raise_for(status)
    return True


# ---------------------------------------------------------------------- metrics (metrics.c)
cdef extern from "metrics.h" nogil:
    int RGBZ_SSIM_MAX_TAPS
    int rgbz_ssim_sums(int in_type, const void *x, const void *y, const double *x_moments,
                       Py_ssize_t planes, Py_ssize_t rows, Py_ssize_t cols,
                       const double *weights, int ntaps, double c1, double c2,
                       double *ssim_sum, double *cs_sum, int workers)
    int rgbz_ssim_reference(int in_type, const void *x, Py_ssize_t planes, Py_ssize_t rows,
                            Py_ssize_t cols, const double *weights, int ntaps,
                            double *x_moments, int workers)
    int rgbz_planar(int in_type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                    Py_ssize_t channels, Py_ssize_t row_stride, void *dst, int workers)
    int rgbz_downsample2(int in_type, const void *src, Py_ssize_t planes, Py_ssize_t rows,
                         Py_ssize_t cols, double *dst, int workers)
    int rgbz_srgb_to_lab(int in_type, const void *rgb, Py_ssize_t n, double scale,
                         double *lab, int workers)
    int rgbz_zipper_count(int in_type, const void *ref, const void *test, Py_ssize_t rows,
                          Py_ssize_t cols, double scale, double delta, int64_t *count,
                          int workers)
    int rgbz_zipper_reference(int in_type, const void *ref, Py_ssize_t rows, Py_ssize_t cols,
                              double scale, double *best, uint8_t *nearest, int workers)
    int rgbz_zipper_count_reference(int in_type, const void *test, Py_ssize_t rows,
                                    Py_ssize_t cols, double scale, const double *best,
                                    const uint8_t *nearest, double delta, int64_t *count,
                                    int workers)
    int rgbz_sq_diff_sum(int in_type, const void *a, const void *b, Py_ssize_t rows,
                         Py_ssize_t cols, Py_ssize_t channels, const uint8_t *mask,
                         double *sum, int64_t *count, int workers)
    int RGBZ_ISA_BEST, RGBZ_ISA_GENERIC, RGBZ_ISA_AVX2, RGBZ_ISA_AVX512
    int rgbz_metrics_isa()
    int rgbz_metrics_use_isa(int isa)
    int rgbz_metrics_isa_available(int isa)

SSIM_MAX_TAPS = RGBZ_SSIM_MAX_TAPS
#: the instruction sets the metric kernels are built for (csrc/metrics_dispatch.c)
METRICS_ISAS = {"generic": RGBZ_ISA_GENERIC, "avx2": RGBZ_ISA_AVX2, "avx512": RGBZ_ISA_AVX512}


def metrics_isa():
    """Name of the instruction set the metric kernels run."""
    cdef int isa = rgbz_metrics_isa()
    return next(name for name, code in METRICS_ISAS.items() if code == isa)


def metrics_isas_available():
    """The instruction sets built and supported by this CPU, narrowest first."""
    return [name for name, code in METRICS_ISAS.items() if rgbz_metrics_isa_available(code)]


def metrics_use_isa(name=None):
    """Run the metric kernels on instruction set ``name`` (None: the best). Not thread-safe:
    for tests and benchmarks."""
    _raise_for(rgbz_metrics_use_isa(RGBZ_ISA_BEST if name is None else METRICS_ISAS[name]))


def ssim_sums(const frame_t[:, :, ::1] x, const frame_t[:, :, ::1] y,
              const double[:, :, ::1] x_moments, const double[::1] weights, double c1,
              double c2, double[::1] ssim_sum, double[::1] cs_sum, int workers):
    """Per-plane sums of the SSIM and contrast-structure maps of planar (planes, rows, cols)
    images over the windows wholly inside them (separable symmetric window ``weights``);
    ``x_moments``: :func:`ssim_reference` of ``x``, or None; ``ssim_sum`` None: the
    contrast-structure sums alone."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef const double *mom = NULL
    cdef double *ssim_out = NULL
    if ssim_sum is not None:
        ssim_out = &ssim_sum[0]
    cdef Py_ssize_t n = weights.shape[0]
    if x_moments is not None:
        if (x_moments.shape[0] != x.shape[0] * (x.shape[1] - n + 1) or x_moments.shape[1] != 2
                or x_moments.shape[2] != x.shape[2] - n + 1):
            raise ValueError("x_moments: not the shape of ssim_reference(x)")
        mom = &x_moments[0, 0, 0]
    with nogil:
        status = rgbz_ssim_sums(in_type, &x[0, 0, 0], &y[0, 0, 0], mom, x.shape[0],
                                x.shape[1], x.shape[2], &weights[0], <int> n, c1, c2,
                                ssim_out, &cs_sum[0], workers)
    _raise_for(status)


def ssim_reference(const frame_t[:, :, ::1] x, const double[::1] weights,
                   double[:, :, ::1] x_moments, int workers):
    """What the SSIM of planar ``x`` takes from ``x`` alone: ``x_moments`` (planes *
    (rows - n + 1), 2, cols - n + 1), the local means and variances of each window row."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef Py_ssize_t n = weights.shape[0]
    if (x_moments.shape[0] != x.shape[0] * (x.shape[1] - n + 1) or x_moments.shape[1] != 2
            or x_moments.shape[2] != x.shape[2] - n + 1):
        raise ValueError("x_moments: expected (planes * (rows - n + 1), 2, cols - n + 1)")
    with nogil:
        status = rgbz_ssim_reference(in_type, &x[0, 0, 0], x.shape[0], x.shape[1],
                                     x.shape[2], &weights[0], <int> n, &x_moments[0, 0, 0],
                                     workers)
    _raise_for(status)


def planar(const frame_t[:, :, :] src, frame_t[:, :, ::1] dst, int workers):
    """(rows, cols, channels) -> (channels, rows, cols): ``src`` with contiguous pixels (its
    rows may lie further apart: a crop), ``dst`` contiguous, of the same type."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef Py_ssize_t size = sizeof(frame_t)
    if dst.shape[0] != src.shape[2] or dst.shape[1] != src.shape[0] \
            or dst.shape[2] != src.shape[1]:
        raise ValueError("dst: not the (channels, rows, cols) of src")
    if src.strides[2] != size or src.strides[1] != size * src.shape[2] \
            or src.strides[0] % size:
        raise ValueError("src: expected contiguous pixels, rows a whole number of elements apart")
    if src.shape[0] == 0 or src.shape[1] == 0 or src.shape[2] == 0:
        return
    with nogil:
        status = rgbz_planar(in_type, &src[0, 0, 0], src.shape[0], src.shape[1], src.shape[2],
                             src.strides[0] // size, &dst[0, 0, 0], workers)
    _raise_for(status)


def downsample2(const frame_t[:, :, ::1] src, double[:, :, ::1] dst, int workers):
    """2 x 2 mean decimation of planar (planes, rows, cols) -> (planes, ceil(rows / 2),
    ceil(cols / 2)), an odd last row or column repeated."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    with nogil:
        status = rgbz_downsample2(in_type, &src[0, 0, 0], src.shape[0], src.shape[1],
                                  src.shape[2], &dst[0, 0, 0], workers)
    _raise_for(status)


def srgb_to_lab(const frame_t[:, ::1] rgb, double scale, double[:, ::1] lab, int workers):
    """sRGB code values (n, 3) over ``scale`` -> CIELAB (n, 3), D65."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    with nogil:
        status = rgbz_srgb_to_lab(in_type, &rgb[0, 0], rgb.shape[0], scale, &lab[0, 0],
                                  workers)
    _raise_for(status)


def zipper_count(const frame_t[:, :, ::1] ref, const frame_t[:, :, ::1] test, double scale,
                 double delta, int workers):
    """Interior pixels of two (rows, cols, 3) images with |psi| > delta (sRGB over ``scale``,
    or CIELAB when ``scale`` is 0)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int64_t count = 0
    with nogil:
        status = rgbz_zipper_count(in_type, &ref[0, 0, 0], &test[0, 0, 0], ref.shape[0],
                                   ref.shape[1], scale, delta, &count, workers)
    _raise_for(status)
    return int(count)


def zipper_reference(const frame_t[:, :, ::1] ref, double scale, double[:, ::1] best,
                     uint8_t[:, ::1] nearest, int workers):
    """The reference half of :func:`zipper_count`: for each interior pixel of ``ref``
    ((rows - 2, cols - 2) arrays) the smallest dE to a neighbour and that neighbour (0..7)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    if (best.shape[0] != ref.shape[0] - 2 or best.shape[1] != ref.shape[1] - 2
            or nearest.shape[0] != best.shape[0] or nearest.shape[1] != best.shape[1]):
        raise ValueError("best, nearest: expected (rows - 2, cols - 2) arrays")
    with nogil:
        status = rgbz_zipper_reference(in_type, &ref[0, 0, 0], ref.shape[0], ref.shape[1],
                                       scale, &best[0, 0], &nearest[0, 0], workers)
    _raise_for(status)


def zipper_count_reference(const frame_t[:, :, ::1] test, double scale,
                           const double[:, ::1] best, const uint8_t[:, ::1] nearest,
                           double delta, int workers):
    """:func:`zipper_count` of ``test`` against the reference of :func:`zipper_reference`."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int64_t count = 0
    if (best.shape[0] != test.shape[0] - 2 or best.shape[1] != test.shape[1] - 2
            or nearest.shape[0] != best.shape[0] or nearest.shape[1] != best.shape[1]):
        raise ValueError("best, nearest: expected (rows - 2, cols - 2) arrays")
    with nogil:
        status = rgbz_zipper_count_reference(in_type, &test[0, 0, 0], test.shape[0],
                                             test.shape[1], scale, &best[0, 0],
                                             &nearest[0, 0], delta, &count, workers)
    _raise_for(status)
    return int(count)


def sq_diff_sum(const frame_t[:, :, ::1] a, const frame_t[:, :, ::1] b,
                const uint8_t[:, ::1] mask, int workers):
    """(sum of (a - b)^2, number of elements) over the pixels of (rows, cols, channels) images
    where ``mask`` (rows, cols) is nonzero, or over every pixel when ``mask`` is None."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef double total = 0.0
    cdef int64_t count = 0
    cdef const uint8_t *m = NULL if mask is None else &mask[0, 0]
    with nogil:
        status = rgbz_sq_diff_sum(in_type, &a[0, 0, 0], &b[0, 0, 0], a.shape[0], a.shape[1],
                                  a.shape[2], m, &total, &count, workers)
    _raise_for(status)
    return total, int(count)


# ---------------------------------------------------------------------- sRGB encoding (srgb.c)
cdef extern from "srgb.h" nogil:
    int rgbz_oetf_prepare_f32(const float *x, float *p, Py_ssize_t n, int workers)
    int rgbz_oetf_prepare_f64(const double *x, double *p, Py_ssize_t n, int workers)
    int rgbz_oetf_finish_f32(const float *x, const float *p, Py_ssize_t n, int code_type,
                             void *code, int workers)
    int rgbz_oetf_finish_f64(const double *x, const double *p, Py_ssize_t n, int code_type,
                             void *code, int workers)
    int rgbz_decode_lookup(int code_type, const void *code, Py_ssize_t n, const double *table,
                           Py_ssize_t size, double *out, int workers)

ctypedef fused code_t:
    uint8_t
    uint16_t


def oetf_prepare(const rgb_t[::1] x, rgb_t[::1] p, int workers):
    """p = 1 where the clipped x is on the OETF's linear segment, else the clipped x."""
    cdef int status
    with nogil:
        if rgb_t is float:
            status = rgbz_oetf_prepare_f32(&x[0], &p[0], x.shape[0], workers)
        else:
            status = rgbz_oetf_prepare_f64(&x[0], &p[0], x.shape[0], workers)
    _raise_for(status)


def oetf_finish(const rgb_t[::1] x, const rgb_t[::1] p, code_t[::1] code, int workers):
    """8- or 16-bit sRGB codes of x, p holding the power 1 / 2.4 of oetf_prepare's output."""
    cdef int status
    cdef int code_type = RGBZ_T_U8 if code_t is uint8_t else RGBZ_T_U16
    with nogil:
        if rgb_t is float:
            status = rgbz_oetf_finish_f32(&x[0], &p[0], x.shape[0], code_type, &code[0],
                                          workers)
        else:
            status = rgbz_oetf_finish_f64(&x[0], &p[0], x.shape[0], code_type, &code[0],
                                          workers)
    _raise_for(status)


def decode_lookup(const code_t[::1] code, const double[::1] table, double[::1] out,
                  int workers):
    """out = table[code] (8- or 16-bit codes), threaded: the sRGB decoding's look-up.
    Returns False when a code is not below the table's length (out holds table[0] there)."""
    cdef int status
    cdef int code_type = RGBZ_T_U8 if code_t is uint8_t else RGBZ_T_U16
    if out.shape[0] != code.shape[0]:
        raise ValueError("decode_lookup: out and code differ in length")
    if code.shape[0] == 0:
        return True
    with nogil:
        status = rgbz_decode_lookup(code_type, &code[0], code.shape[0], &table[0],
                                    table.shape[0], &out[0], workers)
    if status == RGBZ_EDOMAIN:
        return False
    _raise_for(status)
    return True


# ---------------------------------------------------------------------- ToF bilateral (tof_filter.c)
def tof_bilateral(const double[:, :, ::1] z_re, const double[:, :, ::1] z_im,
                  const double[:, :, ::1] var, const double[:, :, ::1] g_re,
                  const double[:, :, ::1] g_im, const double[:, :, ::1] g_var,
                  const uint8_t[:, ::1] use, const int64_t[::1] row_px,
                  const int64_t[::1] col_px, Py_ssize_t reach_rows, Py_ssize_t reach_cols, int64_t radius_px,
                  double inv_h2, double[:, :, ::1] out_re, double[:, :, ::1] out_im,
                  double[:, :, ::1] out_var, double[:, ::1] out_neff, int workers):
    """One bilateral pass on the grid of Z measurements (csrc/tof_filter.c): planes
    (F, rows, cols) of the phasors, their variances, the guide and its variances, use
    (rows, cols) -> out_re, out_im, out_var (F, rows, cols), out_neff (rows, cols)."""
    cdef int status
    if z_re.shape[1] == 0 or z_re.shape[2] == 0:
        return
    with nogil:
        status = rgbz_tof_bilateral(&z_re[0, 0, 0], &z_im[0, 0, 0], &var[0, 0, 0],
                                    &g_re[0, 0, 0], &g_im[0, 0, 0], &g_var[0, 0, 0],
                                    &use[0, 0], &row_px[0], &col_px[0], z_re.shape[0],
                                    z_re.shape[1], z_re.shape[2], reach_rows, reach_cols,
                                    radius_px, inv_h2,
                                    &out_re[0, 0, 0], &out_im[0, 0, 0], &out_var[0, 0, 0],
                                    &out_neff[0, 0], workers)
    _raise_for(status)


def tof_phasors_offset(const frame_t[:, :, ::1] taps, double[:, ::1] i, double[:, ::1] q,
                       double[:, ::1] offset, int workers):
    """I, Q and the offset (F, N) of taps (F, 4, N) (csrc/tof_filter.c)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef Py_ssize_t F = taps.shape[0], N = taps.shape[2]
    if (taps.shape[1] != 4 or i.shape[0] != F or i.shape[1] != N or q.shape[0] != F
            or q.shape[1] != N or offset.shape[0] != F or offset.shape[1] != N):
        raise ValueError("tof_phasors_offset: inconsistent array shapes")
    if N == 0:
        return
    with nogil:
        status = rgbz_tof_phasors_offset(in_type, &taps[0, 0, 0], F, N, &i[0, 0], &q[0, 0],
                                         &offset[0, 0], workers)
    _raise_for(status)


def tof_tap_variance(const double[::1] offset, double black, double k, double supp,
                     double readout, double prnu, double scale, count, double[::1] out,
                     int workers):
    """The ISP's variance of a phasor component from the offsets (flattened), times scale,
    over max(count, 1) (count None, or (P,) repeated along the offsets) (csrc/tof_filter.c)."""
    cdef const double[::1] c
    cdef const double *cp = NULL
    cdef Py_ssize_t period = 1
    cdef int status
    if out.shape[0] != offset.shape[0]:
        raise ValueError("tof_tap_variance: inconsistent array shapes")
    if count is not None:
        c = count
        period = c.shape[0]
        if period == 0 or offset.shape[0] % period:
            raise ValueError("tof_tap_variance: inconsistent array shapes")
        cp = &c[0]
    if offset.shape[0] == 0:
        return
    with nogil:
        status = rgbz_tof_tap_variance(&offset[0], offset.shape[0], black, k, supp, readout,
                                       prnu, scale, cp, period, &out[0], workers)
    _raise_for(status)


def tof_box(list planes, list outs, const int64_t[::1] row_px, const int64_t[::1] col_px,
            const int64_t[::1] row_offs, const int64_t[::1] col_offs, int64_t radius,
            weight, double[:, ::1] count, int workers):
    """The paper's box mean on the grid of Z measurements (csrc/tof_filter.c, rgbz_tof_box):
    planes and outs, lists of 1-D C-contiguous float64 arrays of rows x cols values (the grid
    in row-major order; the lists keep them alive during the call); weight None or (rows,
    cols) float64; count (rows, cols)."""
    cdef Py_ssize_t P = len(planes), R = count.shape[0], C = count.shape[1], k
    cdef const double[::1] a
    cdef double[::1] o
    cdef const double[:, ::1] w
    cdef const double *wp = NULL
    cdef int status
    if len(outs) != P or row_px.shape[0] != R or col_px.shape[0] != C:
        raise ValueError("tof_box: inconsistent array shapes")
    if weight is not None:
        w = weight
        if w.shape[0] != R or w.shape[1] != C:
            raise ValueError("tof_box: inconsistent array shapes")
        if R * C:
            wp = &w[0, 0]
    if R * C == 0:
        return
    cdef const double **ip = <const double **> PyMem_Malloc(max(P, 1) * sizeof(double *))
    cdef double **op = <double **> PyMem_Malloc(max(P, 1) * sizeof(double *))
    if ip == NULL or op == NULL:
        PyMem_Free(ip)
        PyMem_Free(op)
        raise MemoryError()
    try:
        for k in range(P):
            a = planes[k]
            o = outs[k]
            if a.shape[0] != R * C or o.shape[0] != R * C:
                raise ValueError("tof_box: inconsistent array shapes")
            ip[k] = &a[0]
            op[k] = &o[0]
        with nogil:
            status = rgbz_tof_box(ip, op, P, R, C, &row_px[0], &col_px[0],
                                  &row_offs[0] if row_offs.shape[0] else NULL,
                                  row_offs.shape[0],
                                  &col_offs[0] if col_offs.shape[0] else NULL,
                                  col_offs.shape[0], radius, wp, &count[0, 0], workers)
    finally:
        PyMem_Free(ip)
        PyMem_Free(op)
    _raise_for(status)


def tof_validity(const double[:, ::1] amp, const double[:, ::1] var, const double[::1] depth,
                 const double[::1] residual, const uint8_t[::1] saturated,
                 const double[::1] sigma_scale, const double[::1] refl_coef,
                 double phase_var_cap, double power, double tan_h, double tan_v,
                 double k_cell, double block, double min_snr, double min_amplitude,
                 double max_sigma, double max_residual, double min_reflectance,
                 double max_range, double[::1] snr, double[::1] sigma, double[::1] refl,
                 uint8_t[::1] flags, int workers, const double[::1] delta=None,
                 double max_reflectance=INFINITY):
    """The unguided ToF ISP's snr, sigma, implied reflectance and validity bits but the
    flying one (csrc/tof_filter.c, rgbz_tof_validity); amp, var (F, N), the rest (N,),
    sigma_scale and refl_coef (F,); max_sigma < 0: no limit; delta (N,) or None: the
    fixed-pattern correction of sigma^2 (tof_fixed_pattern); max_reflectance: out of range
    above it (inf: no bound)."""
    cdef Py_ssize_t F = amp.shape[0], n = amp.shape[1]
    if (var.shape[0] != F or var.shape[1] != n or sigma_scale.shape[0] != F
            or refl_coef.shape[0] != F or depth.shape[0] != n or residual.shape[0] != n
            or saturated.shape[0] != n or snr.shape[0] != n or sigma.shape[0] != n
            or refl.shape[0] != n or flags.shape[0] != n
            or (delta is not None and delta.shape[0] != n)):
        raise ValueError(f"tof_validity: expected (F, N) and (N,) planes, F = {F}, N = {n}")
    if n == 0:
        return
    cdef rgbz_tof_validity_args a
    a.amp = &amp[0, 0]
    a.var = &var[0, 0]
    a.depth = &depth[0]
    a.residual = &residual[0]
    a.saturated = &saturated[0]
    a.F = F
    a.N = n
    a.sigma_scale = &sigma_scale[0]
    a.refl_coef = &refl_coef[0]
    a.phase_var_cap = phase_var_cap
    a.power = power
    a.tan_h = tan_h
    a.tan_v = tan_v
    a.k_cell = k_cell
    a.block = block
    a.min_snr = min_snr
    a.min_amplitude = min_amplitude
    a.max_sigma = max_sigma
    a.max_residual = max_residual
    a.min_reflectance = min_reflectance
    a.max_range = max_range
    a.max_reflectance = max_reflectance
    a.snr = &snr[0]
    a.sigma = &sigma[0]
    a.refl = &refl[0]
    a.flags = &flags[0]
    a.delta = &delta[0] if delta is not None else NULL
    cdef int status
    with nogil:
        status = rgbz_tof_validity(&a, workers)
    _raise_for(status)


def tof_fixed_pattern(const double[:, ::1] phase, const double[:, ::1] amp,
                      const double[:, ::1] offset, const double[::1] count,
                      const double[::1] sigma_scale, double black, double pre,
                      double var_dsnu, double fix_dsnu, double prnu, bint shared,
                      double[::1] delta, int workers):
    """The fixed-pattern correction of the depth variance (csrc/tof_filter.c,
    rgbz_tof_fixed_pattern): phase, amp, offset (F, N); count (N,) or None; sigma_scale (F,);
    delta (N,) receives it."""
    cdef Py_ssize_t F = phase.shape[0], n = phase.shape[1]
    if (amp.shape[0] != F or amp.shape[1] != n or offset.shape[0] != F
            or offset.shape[1] != n or sigma_scale.shape[0] != F or delta.shape[0] != n
            or (count is not None and count.shape[0] != n)):
        raise ValueError(f"tof_fixed_pattern: expected (F, N) and (N,) planes, F = {F}, "
                         f"N = {n}")
    if n == 0:
        return
    cdef const double *cp = &count[0] if count is not None else NULL
    cdef int status
    with nogil:
        status = rgbz_tof_fixed_pattern(&phase[0, 0], &amp[0, 0], &offset[0, 0], cp, F, n,
                                        &sigma_scale[0], black, pre, var_dsnu, fix_dsnu,
                                        prnu, shared, &delta[0], workers)
    _raise_for(status)


# ---------------------------------------------------------------------- fixed-point model (hw_recon.c)
ctypedef fused int_frame_t:
    uint8_t
    uint16_t


def hw_layout():
    """(sizeof rgbz_hw_plan, sizeof rgbz_hw_config, sizeof rgbz_hw_state, max width, max
    period, kernel radius, max table entries) as compiled."""
    cdef int64_t out[7]
    _raise_for(rgbz_hw_layout(out, 7))
    return tuple(out[i] for i in range(7))


def reconstruct_fixed(const int_frame_t[:, ::1] src, int_frame_t[:, ::1] dst, int py, int px,
                      const int32_t[::1] plan_map, const uint8_t[::1] plans, int n_plans,
                      const uint8_t[::1] hw, const uint8_t[::1] cfg,
                      const int32_t[::1] exp_table, const int32_t[::1] recip_table,
                      uint8_t[::1] state):
    """Run the entry point of precision fixed (rgbz_reconstruct_fixed, the fixed-point
    streaming model): plans as for :func:`reconstruct`, hw the rgbz_hw_plan bytes of each,
    cfg the rgbz_hw_config bytes, the two tables, and ``state`` (sizeof rgbz_hw_state bytes,
    the line buffers and the window), handed over in rgbz_params.fixed."""
    cdef int status
    cdef int in_type = RGBZ_T_U8 if int_frame_t is uint8_t else RGBZ_T_U16
    cdef rgbz_reconstruct_fn *kernel = _kernels_of(RGBZ_P_FIXED).reconstruct
    cdef rgbz_fixed_args args
    cdef rgbz_params prm
    if kernel == NULL:
        raise ValueError("precision: this module has no kernel of precision 'fixed'")
    memset(&prm, 0, sizeof(prm))        # the float fields are not read by this precision
    args.hw = <const rgbz_hw_plan *> &hw[0]
    args.cfg = <const rgbz_hw_config *> &cfg[0]
    args.exp_table = &exp_table[0]
    args.recip_table = &recip_table[0]
    args.state = <rgbz_hw_state *> &state[0]
    prm.workers = 1
    prm.fixed = &args
    with nogil:
        status = kernel(in_type, &src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py, px,
                        &plan_map[0], <const rgbz_plan *> &plans[0], n_plans, &prm, NULL)
    _raise_for(status)


def hwl_layout():
    """(sizeof rgbz_hwl_config, sizeof rgbz_hwl_state, max width, max period, max radius) as
    compiled (csrc/hw_learned.h)."""
    cdef int64_t out[5]
    _raise_for(rgbz_hwl_layout(out, 5))
    return tuple(out[i] for i in range(5))


def learned_fixed(const int_frame_t[:, ::1] src, int_frame_t[:, ::1] dst, int py, int px,
                  const int32_t[::1] phase_map, const int32_t[::1] n_taps,
                  const int32_t[:, ::1] tap_dy, const int32_t[:, ::1] tap_dx,
                  const int32_t[:, ::1] n_pairs, const int32_t[:, :, ::1] pair_a,
                  const int32_t[:, :, ::1] pair_b, const int32_t[:, :, ::1] pair_col,
                  int n_str, int n_coh, int n_spr, int radius, const uint8_t[::1] cfg,
                  const int64_t[:, ::1] knorm, const int64_t[:, ::1] kcol,
                  const int64_t[::1] str_q, const int64_t[::1] coh_q, const int64_t[::1] spr_q,
                  const int32_t[:, :, ::1] wq, double maxval, uint8_t[::1] state):
    """Run the learned filters' entry point of precision fixed (rgbz_learned_fixed, the
    fixed-point streaming model of csrc/hw_learned.h): the geometry of the filters
    (as for :func:`learned`), ``cfg`` the rgbz_hwl_config bytes, the integer hash constants
    (thresholds flattened, one int64 at least each), the quantised weights (n_phases,
    n_buckets, n_taps_max), and ``state`` (sizeof rgbz_hwl_state bytes)."""
    cdef int status
    cdef int in_type = RGBZ_T_U8 if int_frame_t is uint8_t else RGBZ_T_U16
    cdef rgbz_learned_fn *kernel = _kernels_of(RGBZ_P_FIXED).learned
    cdef rgbz_learned_fixed_args args
    cdef rgbz_learned_filters f
    if kernel == NULL:
        raise ValueError("precision: this module has no learned kernel of precision 'fixed'")
    if (tap_dy.shape[0] != n_taps.shape[0] or tap_dx.shape[0] != n_taps.shape[0]
            or tap_dy.shape[1] != wq.shape[2] or tap_dx.shape[1] != wq.shape[2]
            or n_pairs.shape[0] != n_taps.shape[0] or n_pairs.shape[1] != 4
            or pair_a.shape[0] != n_taps.shape[0] or pair_b.shape[2] != pair_a.shape[2]
            or pair_col.shape[2] != pair_a.shape[2] or wq.shape[0] != n_taps.shape[0]
            or knorm.shape[0] != n_taps.shape[0] or knorm.shape[1] != 4
            or kcol.shape[0] != n_taps.shape[0] or kcol.shape[1] != 3
            or str_q.shape[0] < max(n_taps.shape[0] * (n_str - 1), 1)
            or coh_q.shape[0] < max(n_taps.shape[0] * (n_coh - 1), 1)
            or spr_q.shape[0] < max(n_taps.shape[0] * (n_spr - 1), 1)
            or state.shape[0] < hwl_layout()[1]):
        raise ValueError("learned_fixed: inconsistent arrays")
    memset(&f, 0, sizeof(f))            # the float members are not read by this precision
    f.n_phases = wq.shape[0]
    f.n_buckets = wq.shape[1]
    f.n_taps_max = wq.shape[2]
    f.n_pairs_max = pair_a.shape[2]
    f.n_str, f.n_coh, f.n_spr = n_str, n_coh, n_spr
    f.radius = radius
    f.hash_radius = radius
    f.n_taps = &n_taps[0]
    f.tap_dy = &tap_dy[0, 0]
    f.tap_dx = &tap_dx[0, 0]
    f.n_pairs = &n_pairs[0, 0]
    f.pair_a = &pair_a[0, 0, 0]
    f.pair_b = &pair_b[0, 0, 0]
    f.pair_col = &pair_col[0, 0, 0]
    args.cfg = <const rgbz_hwl_config *> &cfg[0]
    args.knorm = &knorm[0, 0]
    args.kcol = &kcol[0, 0]
    args.str_q = &str_q[0]
    args.coh_q = &coh_q[0]
    args.spr_q = &spr_q[0]
    args.wq = &wq[0, 0, 0]
    args.state = <rgbz_hwl_state *> &state[0]
    f.fixed = &args
    with nogil:
        status = kernel(in_type, &src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py, px,
                        &phase_map[0], &f, maxval, 1, NULL)
    _raise_for(status)


# ---------------------------------------------------------------------- sensor simulation (sim.c)
cdef extern from "sim.h" nogil:
    ctypedef struct rgbz_sim_noise:
        int32_t noise, shot, quantise
        double prnu, dsnu, read_noise, full_well, black, gain, top, dark
        uint32_t key_temporal[4]
        uint32_t key_fpn[4]
    ctypedef struct rgbz_sim_tof_light:
        double k, power, th, tv, ambient, duty, c25, suppression, unambiguous
        double speed_of_light, two_pi
        int32_t nfreq
        double four_pi_f[16]
        double shift_re[4]
        double shift_im[4]
    void rgbz_sim_key(const uint64_t *words, Py_ssize_t nwords, uint64_t stream, uint32_t *key)
    int rgbz_sim_blocks(uint32_t c0, uint32_t c1, uint32_t c2, uint32_t c3, const uint32_t *key,
                        Py_ssize_t n, uint32_t *out)
    int rgbz_sim_variates(int kind, const double *lam, uint32_t c1, uint32_t c2,
                          const uint32_t *key, Py_ssize_t n, double *out, int workers)
    int rgbz_sim_math(int which, const double *x, Py_ssize_t n, double *out)
    int rgbz_sim_tof_field(const double *d, const double *s, Py_ssize_t n, double four_pi_f,
                           double speed_of_light, double two_pi, int order, double *re,
                           double *im, int workers)
    int rgbz_sim_z_sites(const uint8_t *tile_z, int P, int Q, Py_ssize_t rows, Py_ssize_t cols,
                         int block, int64_t *site_r, int64_t *site_c, Py_ssize_t *count,
                         int workers)
    int rgbz_sim_rate_hist(int type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                           Py_ssize_t row_stride, Py_ssize_t col_stride,
                           const Py_ssize_t *chan_off, const int32_t *tile, int P, int Q,
                           const double *per_unit, uint64_t *hist, int workers)
    int rgbz_sim_rate_gather(int type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                             Py_ssize_t row_stride, Py_ssize_t col_stride,
                             const Py_ssize_t *chan_off, const int32_t *tile, int P, int Q,
                             const double *per_unit, uint32_t lo16, uint32_t hi16, double *out,
                             Py_ssize_t cap, Py_ssize_t *count, int workers)
    int rgbz_sim_colour(int type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                        Py_ssize_t row_stride, Py_ssize_t col_stride, const Py_ssize_t *chan_off,
                        const int32_t *tile, const uint8_t *tile_z, int P, int Q,
                        const double *per_unit, double exposure, const rgbz_sim_noise *nz,
                        void *ref, void *data, int64_t *saturated, int workers)
    int rgbz_sim_tof(const double *depth, const uint8_t *depth_valid, Py_ssize_t rows,
                     Py_ssize_t cols, int ir_type, const void *ir, Py_ssize_t ir_rs,
                     Py_ssize_t ir_cs, int ir_estimate, const int64_t *site_r,
                     const int64_t *site_c, Py_ssize_t n, int block,
                     const rgbz_sim_tof_light *light, const rgbz_sim_noise *nz, void *taps,
                     double *depth_true, uint8_t *valid, uint8_t *beyond, uint8_t *sat,
                     double *max_depth, int workers)
    int rgbz_sim_tof_expose(const double *mean, const double *suppress, const int64_t *site_r,
                            const int64_t *site_c, Py_ssize_t n, int nfreq,
                            const rgbz_sim_noise *nz, void *taps, uint8_t *sat, int workers)

ctypedef fused dn_t:
    uint16_t
    double


cdef rgbz_sim_noise _sim_noise(dict p, const uint32_t[::1] keys) except *:
    """The C noise chain of a dict of its fields (rgbz_fast.simulation._noise.noise_fields)."""
    cdef rgbz_sim_noise nz
    nz.noise, nz.shot, nz.quantise = p["noise"], p["shot"], p["quantise"]
    nz.prnu, nz.dsnu, nz.read_noise = p["prnu"], p["dsnu"], p["read_noise"]
    nz.full_well, nz.black, nz.gain = p["full_well"], p["black"], p["gain"]
    nz.top, nz.dark = p["top"], p["dark"]
    cdef int i
    if keys.shape[0] != 8:
        raise ValueError("keys: expected the 8 words of the temporal and fixed-pattern keys")
    for i in range(4):
        nz.key_temporal[i] = keys[i]
        nz.key_fpn[i] = keys[4 + i]
    return nz


def sim_key(const uint64_t[::1] words, uint64_t stream):
    """The four 32-bit words of the key of a seed's 64-bit words and a stream."""
    cdef uint32_t key[4]
    rgbz_sim_key(&words[0], words.shape[0], stream, key)
    return int(key[0]), int(key[1]), int(key[2]), int(key[3])


def sim_blocks(uint32_t c0, uint32_t c1, uint32_t c2, uint32_t c3, const uint32_t[::1] key,
               uint32_t[:, ::1] out):
    """Threefry4x32-20 blocks at counters (c0 + i, c1, c2, c3) and key (4 words) into
    out (n, 4)."""
    cdef int status
    if key.shape[0] != 4:
        raise ValueError("key: expected 4 words")
    if out.shape[0] == 0:
        return
    with nogil:
        status = rgbz_sim_blocks(c0, c1, c2, c3, &key[0], out.shape[0], &out[0, 0])
    _raise_for(status)


def sim_variates(int kind, const double[::1] lam, uint32_t c1, uint32_t c2,
                 const uint32_t[::1] key, double[::1] out, int workers):
    """Standard normals (kind 0) or Poisson variates of means lam (kind 1) into out."""
    cdef int status
    cdef const double *lp = &lam[0] if lam.shape[0] else NULL
    if out.shape[0] == 0:
        return
    with nogil:
        status = rgbz_sim_variates(kind, lp, c1, c2, &key[0], out.shape[0], &out[0], workers)
    _raise_for(status)


def sim_math(int which, const double[::1] x, double[::1] out):
    """The Box-Muller transform's log (0), sin (1) or cos (2) of 2 pi x."""
    cdef int status
    if x.shape[0] == 0:
        return
    with nogil:
        status = rgbz_sim_math(which, &x[0], x.shape[0], &out[0])
    _raise_for(status)


def sim_tof_field(const double[::1] d, const double[::1] s, double four_pi_f,
                  double speed_of_light, double two_pi, int order, double[::1] re,
                  double[::1] im, int workers):
    """re + i im = s e^{i order phi}, phi = (four_pi_f d / speed_of_light) mod two_pi, as
    ToFSensor._returns computes it in NumPy (the same bits)."""
    cdef int status
    cdef Py_ssize_t n = d.shape[0]
    if s.shape[0] != n or re.shape[0] != n or im.shape[0] != n:
        raise ValueError("sim_tof_field: inconsistent array shapes")
    if n == 0:
        return
    with nogil:
        status = rgbz_sim_tof_field(&d[0], &s[0], n, four_pi_f, speed_of_light, two_pi, order,
                                    &re[0], &im[0], workers)
    _raise_for(status)


def sim_z_sites(const uint8_t[:, ::1] tile_z, Py_ssize_t rows, Py_ssize_t cols, int block,
                int workers):
    """(rows, cols) int64 arrays of the Z measurements' top-left cells, row-major, on
    ``workers`` threads."""
    import numpy as np
    cdef int status
    cdef Py_ssize_t n = 0
    status = rgbz_sim_z_sites(&tile_z[0, 0], tile_z.shape[0], tile_z.shape[1], rows, cols,
                              block, NULL, NULL, &n, 1)
    _raise_for(status)
    r = np.empty(n, np.int64)
    c = np.empty(n, np.int64)
    cdef int64_t[::1] rv = r, cv = c
    if n:
        status = rgbz_sim_z_sites(&tile_z[0, 0], tile_z.shape[0], tile_z.shape[1], rows, cols,
                                  block, &rv[0], &cv[0], &n, workers)
        _raise_for(status)
    return r, c


def sim_rate_hist(const rgb_t[::1] src, Py_ssize_t rows, Py_ssize_t cols, Py_ssize_t row_stride,
                  Py_ssize_t col_stride, const Py_ssize_t[::1] chan_off,
                  const int32_t[:, ::1] tile, const double[::1] per_unit, uint64_t[::1] hist,
                  int workers):
    """Histogram (65536 bins) of the top 16 bits of every site's signal rate."""
    cdef int status
    cdef int t = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    with nogil:
        status = rgbz_sim_rate_hist(t, &src[0], rows, cols, row_stride, col_stride, &chan_off[0],
                                    &tile[0, 0], tile.shape[0], tile.shape[1], &per_unit[0],
                                    &hist[0], workers)
    _raise_for(status)


def sim_rate_gather(const rgb_t[::1] src, Py_ssize_t rows, Py_ssize_t cols,
                    Py_ssize_t row_stride, Py_ssize_t col_stride,
                    const Py_ssize_t[::1] chan_off, const int32_t[:, ::1] tile,
                    const double[::1] per_unit, uint32_t lo16, uint32_t hi16, double[::1] out,
                    int workers):
    """The rates whose top 16 bits lie in [lo16, hi16] into out; returns how many there are."""
    cdef int status
    cdef int t = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    cdef Py_ssize_t count = 0
    cdef double dummy = 0
    cdef double *op = &out[0] if out.shape[0] else &dummy
    with nogil:
        status = rgbz_sim_rate_gather(t, &src[0], rows, cols, row_stride, col_stride,
                                      &chan_off[0], &tile[0, 0], tile.shape[0], tile.shape[1],
                                      &per_unit[0], lo16, hi16, op, out.shape[0], &count,
                                      workers)
    _raise_for(status)
    return int(count)


def sim_colour(const rgb_t[::1] src, Py_ssize_t rows, Py_ssize_t cols, Py_ssize_t row_stride,
               Py_ssize_t col_stride, const Py_ssize_t[::1] chan_off, const int32_t[:, ::1] tile,
               const uint8_t[:, ::1] tile_z, const double[::1] per_unit, double exposure,
               dict noise, const uint32_t[::1] keys, dn_t[:, ::1] ref, dn_t[:, ::1] data,
               int workers):
    """The colour pixels through the noise chain into ref (and data, 0 at the Z sites, if
    not None); returns the number of saturated samples."""
    cdef int status
    cdef int t = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    cdef rgbz_sim_noise nz = _sim_noise(noise, keys)
    cdef int64_t nsat = 0
    cdef void *dp = NULL
    cdef const uint8_t *zp = NULL
    cdef bint u16
    if dn_t is uint16_t:
        u16 = True
    else:
        u16 = False
    if u16 != bool(nz.quantise):
        raise ValueError("sim_colour: uint16 outputs go with quantise, float64 without")
    if data is not None:
        dp = &data[0, 0]
        zp = &tile_z[0, 0]
    with nogil:
        status = rgbz_sim_colour(t, &src[0], rows, cols, row_stride, col_stride, &chan_off[0],
                                 &tile[0, 0], zp, tile.shape[0], tile.shape[1], &per_unit[0],
                                 exposure, &nz, &ref[0, 0], dp, &nsat, workers)
    _raise_for(status)
    return int(nsat)


cdef rgbz_sim_tof_light _sim_light(const double[::1] vals, const double[::1] four_pi_f,
                                   const double[::1] shift_re,
                                   const double[::1] shift_im) except *:
    cdef rgbz_sim_tof_light L
    cdef int i
    if four_pi_f.shape[0] > 16 or shift_re.shape[0] != 4 or shift_im.shape[0] != 4:
        raise ValueError("sim_tof: at most 16 frequencies and 4 tap shifts")
    L.k, L.power, L.th, L.tv, L.ambient = vals[0], vals[1], vals[2], vals[3], vals[4]
    L.duty, L.c25, L.suppression, L.unambiguous = vals[5], vals[6], vals[7], vals[8]
    L.speed_of_light, L.two_pi = vals[9], vals[10]
    L.nfreq = four_pi_f.shape[0]
    for i in range(L.nfreq):
        L.four_pi_f[i] = four_pi_f[i]
    for i in range(4):
        L.shift_re[i] = shift_re[i]
        L.shift_im[i] = shift_im[i]
    return L


def sim_tof(const double[:, ::1] depth, const uint8_t[:, ::1] depth_valid, const rgb_t[::1] ir,
            Py_ssize_t ir_rs, Py_ssize_t ir_cs, int ir_estimate, const int64_t[::1] site_r,
            const int64_t[::1] site_c, int block, const double[::1] light,
            const double[::1] four_pi_f, const double[::1] shift_re, const double[::1] shift_im,
            dict noise, const uint32_t[::1] keys, dn_t[:, :, ::1] taps, double[::1] depth_true,
            uint8_t[::1] valid, uint8_t[::1] beyond, uint8_t[::1] sat, int workers):
    """The taps (F, 4, n) of ideal Z pixels and their per-site flags; returns the largest
    valid cell depth (-inf if none)."""
    cdef int status
    cdef int t = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    cdef rgbz_sim_noise nz = _sim_noise(noise, keys)
    cdef rgbz_sim_tof_light L = _sim_light(light, four_pi_f, shift_re, shift_im)
    cdef double dmax = 0
    cdef Py_ssize_t n = site_r.shape[0]
    cdef bint u16
    if dn_t is uint16_t:
        u16 = True
    else:
        u16 = False
    if u16 != bool(nz.quantise):
        raise ValueError("sim_tof: uint16 taps go with quantise, float64 without")
    if n == 0:
        return float("-inf")
    with nogil:
        status = rgbz_sim_tof(&depth[0, 0], &depth_valid[0, 0], depth.shape[0], depth.shape[1],
                              t, &ir[0], ir_rs, ir_cs, ir_estimate, &site_r[0], &site_c[0], n,
                              block, &L, &nz, &taps[0, 0, 0], &depth_true[0], &valid[0],
                              &beyond[0], &sat[0], &dmax, workers)
    _raise_for(status)
    return float(dmax)


def sim_tof_expose(const double[:, :, ::1] mean, const double[::1] suppress,
                   const int64_t[::1] site_r, const int64_t[::1] site_c, dict noise,
                   const uint32_t[::1] keys, dn_t[:, :, ::1] taps, uint8_t[::1] sat,
                   int workers):
    """The noise chain of taps whose mean electrons (F, 4, n) are given (suppress: per site,
    or None)."""
    cdef int status
    cdef rgbz_sim_noise nz = _sim_noise(noise, keys)
    cdef const double *sp = NULL
    cdef Py_ssize_t n = mean.shape[2]
    cdef bint u16
    if dn_t is uint16_t:
        u16 = True
    else:
        u16 = False
    if u16 != bool(nz.quantise):
        raise ValueError("sim_tof_expose: uint16 taps go with quantise, float64 without")
    if suppress is not None:
        sp = &suppress[0] if suppress.shape[0] else NULL
    if n == 0:
        return
    with nogil:
        status = rgbz_sim_tof_expose(&mean[0, 0, 0], sp, &site_r[0], &site_c[0], n,
                                     mean.shape[0], &nz, &taps[0, 0, 0], &sat[0], workers)
    _raise_for(status)


# ---------------------------------------------------------------------- ToF phase of phasors (tof.h)
cdef extern from "tof.h" nogil:
    int rgbz_tof_phase_iq(const double *i_comp, const double *q_comp, Py_ssize_t F,
                          Py_ssize_t N, double *phase, double *amp, int workers)


def tof_phase_iq(const double[:, ::1] i, const double[:, ::1] q, double[:, ::1] phase,
                 double[:, ::1] amp, int workers):
    """Phasors I, Q (F, N) -> phase in [0, 2 pi) and amplitude (F, N), no unwrapping.

    Returns False when an I or Q is not finite (RGBZ_EDOMAIN), True otherwise.
    """
    cdef int status
    if i.shape[1] == 0:
        return True
    with nogil:
        status = rgbz_tof_phase_iq(&i[0, 0], &q[0, 0], i.shape[0], i.shape[1], &phase[0, 0],
                                   &amp[0, 0], workers)
    if status == RGBZ_EDOMAIN:
        return False
    _raise_for(status)
    return True


# ---------------------------------------------------------------------- colour-guided ToF ISP (tof_guided.h)
cdef extern from "tof_guided.h" nogil:
    int rgbz_tofg_prepare(int in_type, const void *taps, Py_ssize_t F, Py_ssize_t N,
                          double gain, double black, double supp, double const_var, double prnu,
                          double white, float *zr, float *zi, float *v, uint8_t *sat,
                          double *offset, double fixed_var, float *phi, int workers)
    int rgbz_tofg_ring(int in_type, const void *guide, Py_ssize_t H, Py_ssize_t W,
                       const int64_t *row_px, Py_ssize_t R, const int64_t *col_px,
                       Py_ssize_t C, int block, const double *inv, float *ring, int workers)
    int rgbz_tofg_colour(int in_type, const void *guide, Py_ssize_t H, Py_ssize_t W,
                         const int64_t *row_px, Py_ssize_t R, const int64_t *col_px,
                         Py_ssize_t C, int block, double scale, float *col, float *cells,
                         double *lap, double floor, double *sigma, int workers)
    int rgbz_tofg_pass(const float *zr, const float *zi, const float *v, const float *nin,
                       const float *gr, const float *gi, const float *gv, const float *col,
                       const uint8_t *use, Py_ssize_t F, Py_ssize_t R, Py_ssize_t C, int axis,
                       const int64_t *px, Py_ssize_t reach, int64_t radius_px, double inv2h2,
                       double inv2hc2, float *or_, float *oi, double *or64, double *oi64,
                       float *ov, float *on, int fixed, int workers)
    ctypedef struct tofg_valid_out:
        const uint8_t *sat
        const double *sigma_scale
        const double *refl_coef
        double min_snr
        double min_amplitude
        double max_sigma
        double max_residual
        double min_reflectance
        double max_range
        double max_reflectance
        double *snr
        double *sigma
        double *refl
        uint8_t *flags
        const double *offset
        double black
        double pre
        double var_dsnu
        double fix_dsnu
        double prnu
        double delay_var
        uint8_t *usable
        const uint8_t *present
        uint8_t bad
    ctypedef struct tofg_prep_in:
        int in_type
        const void *taps
        double gain
        double black
        double supp
        double const_var
        double prnu
        double white
        double fixed_var
        uint8_t *sat
        double *offset
    ctypedef struct tofg_unwrap_out:
        const double *freqs
        const double *weights
        double max_range
        double *depth
        double *residual
        int32_t *wraps
        double *phase
        double *amp
        const tofg_valid_out *valid
    int rgbz_tofg_denoise(const float *zr, const float *zi, const float *v, const float *col,
                          const uint8_t *use, Py_ssize_t F, Py_ssize_t R, Py_ssize_t C,
                          const int64_t *row_px, const int64_t *col_px, Py_ssize_t reach_r,
                          Py_ssize_t reach_c, int64_t radius_px, double inv2h2,
                          double inv2hc2, double *or64, double *oi64, float *ov, float *on,
                          double *on64, const tofg_unwrap_out *uw, Py_ssize_t strip,
                          int fixed, const tofg_prep_in *prep, int workers)
    int rgbz_tofg_validity(const double *amp, const float *var, const double *depth,
                           const double *residual, const uint8_t *sat, Py_ssize_t F,
                           Py_ssize_t N, const double *sigma_scale, const double *refl_coef,
                           double min_snr, double min_amplitude, double max_sigma,
                           double max_residual, double min_reflectance, double max_range,
                           const double *delta, double *snr, double *sigma, double *refl,
                           uint8_t *flags, int workers, double max_reflectance)
    int rgbz_tofg_usable(const uint8_t *flags, const double *depth, const double *sigma,
                         const uint8_t *present, uint8_t bad, Py_ssize_t N, uint8_t *usable,
                         int workers)
    int rgbz_tofg_flying_candidates(const double *depth, const double *sigma,
                                    const uint8_t *usable, Py_ssize_t R, Py_ssize_t C,
                                    double step, double k, uint8_t *cand, int workers)
    int rgbz_tofg_flying(const double *depth, const double *sigma, const uint8_t *usable,
                         const float *col, const float *cells, int ncells, const float *ring,
                         int nring, Py_ssize_t R, Py_ssize_t C, double step, double k,
                         double contrast, double side, int unflag, uint8_t *flags,
                         double *depth_out, double max_range, uint8_t *valid, int workers)
    int rgbz_tofg_agree(double *depth, double *low, const uint8_t *lone, const double *sigma,
                        Py_ssize_t R, Py_ssize_t C, double tol_k, double tol_min, int workers)
    int rgbz_tofg_upsample(int in_type, const void *guide, Py_ssize_t H, Py_ssize_t W,
                           double scale, const double *cscale, const double *depth,
                           const double *sigma, const float *col, Py_ssize_t R, Py_ssize_t C,
                           const double *rc, const double *cc, double spacing,
                           Py_ssize_t reach, double inv2s2, double inv2hc2, double tol_k,
                           double tol_min, const double *own, double own_k, double ambiguity,
                           double gap, float *out, float *conf, int workers)

def tofg_prepare(const tap_t[:, :, ::1] taps, double gain, double black, double supp,
                 double const_var, double prnu, double white, float[:, ::1] zr,
                 float[:, ::1] zi, float[::1] v, uint8_t[::1] sat, double[:, ::1] offset,
                 int workers, double fixed_var=0.0, float[::1] phi=None):
    """Taps (F, 4, N) -> phasors zr, zi (F, N), component variance v (N,), sat |= full scale,
    offset (F, N) when given; phi (N,), when given, the share of v that the fixed pattern
    gives (fixed_var, the DSNU's per-tap variance in DN^2, and the PRNU part of each tap)."""
    cdef int status
    cdef int in_type = _type_code(<tap_t *> NULL)
    cdef double *of = _opt2(offset)
    cdef float *ph = NULL if phi is None else &phi[0]
    cdef Py_ssize_t F = taps.shape[0], N = taps.shape[2]
    if phi is not None and phi.shape[0] != N:
        raise ValueError(f"phi: expected {N} values, got {phi.shape[0]}")
    if N == 0:
        return
    with nogil:
        status = rgbz_tofg_prepare(in_type, &taps[0, 0, 0], F, N, gain, black, supp, const_var,
                                   prnu, white, &zr[0, 0], &zi[0, 0], &v[0], &sat[0], of,
                                   fixed_var, ph, workers)
    _raise_for(status)


cdef float *_optf(float[:, :, ::1] a) noexcept:
    return NULL if a is None else &a[0, 0, 0]


def tofg_colour(const frame_t[:, :, ::1] guide, const int64_t[::1] row_px,
                const int64_t[::1] col_px, int block, double scale, float[:, ::1] col,
                float[:, :, ::1] cells, double[::1] lap, int workers, double floor=0.0,
                double[::1] sigma=None):
    """The guide (H, W, 3) at the measurements: col (3, N), cells (block^2, 3, N) or None,
    lap (3,) the sums of |Immerkaer's Laplacian| of col. With sigma (3,) given, also the
    guide's noise (Immerkaer, at least floor) into sigma, and col and cells divided by
    sqrt(2) sigma of their channel (times its float reciprocal)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef float *cp = _optf(cells)
    cdef double *sp = NULL if sigma is None else &sigma[0]
    if sigma is not None and sigma.shape[0] != 3:
        raise ValueError(f"sigma: expected 3 channels, got {sigma.shape[0]}")
    cdef Py_ssize_t H = guide.shape[0], W = guide.shape[1]
    cdef Py_ssize_t R = row_px.shape[0], C = col_px.shape[0]
    if R == 0 or C == 0:
        return
    with nogil:
        status = rgbz_tofg_colour(in_type, &guide[0, 0, 0], H, W, &row_px[0], R, &col_px[0], C,
                                  block, scale, &col[0, 0], cp, &lap[0], floor, sp, workers)
    _raise_for(status)


def tofg_ring(const frame_t[:, :, ::1] guide, const int64_t[::1] row_px,
              const int64_t[::1] col_px, int block, const double[::1] inv,
              float[:, :, ::1] ring, int workers):
    """The guide (H, W, 3) at the pixels bordering each Z pixel, times inv (3,) per channel:
    ring (4 block + 4, 3, R C), the offsets in row-major order, clamped to the frame."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef Py_ssize_t H = guide.shape[0], W = guide.shape[1]
    cdef Py_ssize_t R = row_px.shape[0], C = col_px.shape[0]
    if inv.shape[0] != 3:
        raise ValueError(f"inv: expected 3 channels, got {inv.shape[0]}")
    if (block not in (1, 2) or guide.shape[2] != 3 or ring.shape[0] != 4 * block + 4
            or ring.shape[1] != 3 or ring.shape[2] != R * C):
        raise ValueError("tofg_ring: inconsistent array shapes")
    if R == 0 or C == 0 or H == 0 or W == 0:
        return
    with nogil:
        status = rgbz_tofg_ring(in_type, &guide[0, 0, 0], H, W, &row_px[0], R, &col_px[0], C,
                                block, &inv[0], &ring[0, 0, 0], workers)
    _raise_for(status)


cdef const float *_optv(const float[::1] a) noexcept:
    return NULL if a is None else &a[0]


def tofg_pass(const float[:, ::1] zr, const float[:, ::1] zi, const float[::1] v,
              const float[::1] nin, const float[:, ::1] gr, const float[:, ::1] gi,
              const float[::1] gv, const float[:, ::1] col, const uint8_t[::1] use,
              Py_ssize_t R, Py_ssize_t C, int axis, const int64_t[::1] px, Py_ssize_t reach,
              int64_t radius_px, double inv2h2, double inv2hc2, float[:, ::1] out_re,
              float[:, ::1] out_im, double[:, ::1] out_re64, double[:, ::1] out_im64,
              float[::1] out_var, float[::1] out_neff, int workers):
    """One 1-D pass of the guided cross-bilateral mean (rows: axis 1, columns: axis 0); the
    mean goes to out_re64/out_im64 (double) when they are given, else out_re/out_im. col
    (3, N), or (4, N) with each measurement's fixed-pattern share of its variance: the range
    kernel then takes the fixed pattern's correlation across frequencies."""
    cdef int status
    if col.shape[0] not in (3, 4) or col.shape[1] != R * C:
        raise ValueError(f"col: expected (3, {R * C}) or (4, {R * C}), got "
                         f"{(col.shape[0], col.shape[1])}")
    cdef const float *pn = _optv(nin)
    cdef float *o_r = NULL
    cdef float *o_i = NULL
    cdef double *o_r64 = NULL
    cdef double *o_i64 = NULL
    if out_re64 is not None:
        o_r64 = &out_re64[0, 0]
        o_i64 = &out_im64[0, 0]
    else:
        o_r = &out_re[0, 0]
        o_i = &out_im[0, 0]
    if R == 0 or C == 0:
        return
    with nogil:
        status = rgbz_tofg_pass(&zr[0, 0], &zi[0, 0], &v[0], pn, &gr[0, 0], &gi[0, 0], &gv[0],
                                &col[0, 0], &use[0], zr.shape[0], R, C, axis, &px[0], reach,
                                radius_px, inv2h2, inv2hc2, o_r, o_i, o_r64, o_i64,
                                &out_var[0], &out_neff[0], col.shape[0] == 4, workers)
    _raise_for(status)


def tofg_denoise(const float[:, ::1] zr, const float[:, ::1] zi, const float[::1] v,
                 const float[:, ::1] col, const uint8_t[::1] use, const int64_t[::1] row_px,
                 const int64_t[::1] col_px, Py_ssize_t reach_r, Py_ssize_t reach_c,
                 int64_t radius_px, double inv2h2, double inv2hc2, double[:, ::1] out_re,
                 double[:, ::1] out_im, float[::1] out_var, float[::1] out_neff, int workers,
                 const double[::1] freqs=None, const double[::1] weights=None,
                 double max_range=0.0, double[::1] depth=None, double[::1] residual=None,
                 int32_t[::1] wraps=None, double[:, ::1] phase=None, double[:, ::1] amp=None,
                 Py_ssize_t strip=0, double[::1] count=None, uint8_t[::1] sat=None,
                 const double[::1] sigma_scale=None, const double[::1] refl_coef=None,
                 const double[::1] limits=None, double[::1] snr=None, double[::1] sigma=None,
                 double[::1] refl=None, uint8_t[::1] flags=None,
                 double[:, ::1] offset=None, const double[::1] fixed=None, taps=None,
                 const double[::1] prepare=None, uint8_t[::1] usable=None,
                 const uint8_t[::1] present=None, int usable_bits=0):
    """The guided denoise: the four passes of tofg_pass (rows, columns, rows guided by the
    columns' output, columns) fused strip by strip; the last pass's outputs, bit for bit.
    With depth given (and freqs, weights, residual, wraps, phase, amp), the means are
    unwrapped strip by strip (tof_depth_iq, bit for bit) instead of stored in out_re, out_im
    (then None); strip: grid rows per strip (0: the kernel's default); count (N,), when
    given, takes n_eff in double (out_neff may then be None); col as tofg_pass's. With flags
    given (and depth, count, sat, sigma_scale, refl_coef, snr, sigma, refl, and limits =
    (min_snr, min_amplitude, max_sigma, max_residual, min_reflectance, max_range,
    max_reflectance)), each unwrapped row's validity is made as tofg_validity's (bit for bit),
    with delta = tof_fixed_pattern(phase, amp, offset, count, sigma_scale, black, pre,
    var_dsnu, fix_dsnu, prnu, shared=True) + delay_var / max(count, 1) when offset (F, N) is
    given and fixed = (black, pre, var_dsnu, fix_dsnu, prnu, delay_var). With taps (F, 4, N)
    of uint16, float32 or float64 given (and prepare = (gain, black, supp, const_var, prnu,
    white, fixed_var), sat, offset), the prepare stage (tofg_prepare) is made inside, row by
    row: zr, zi, v are not read (None), sat |= a tap at full scale and offset is written,
    use is taken as before the stage (its hits are left out), and col's fourth plane, when
    col has one, is the stage's phi. With usable (N,) given (and flags), it takes tofg_usable
    of each row's flags, depth and sigma with present (None: every one) and the bits
    usable_bits. Returns False when a mean is not finite (RGBZ_EDOMAIN), True otherwise."""
    cdef int status
    cdef Py_ssize_t R = row_px.shape[0], C = col_px.shape[0]
    cdef Py_ssize_t nf
    cdef tofg_valid_out vo
    cdef tofg_prep_in pi
    cdef tofg_prep_in *ppi = NULL
    cdef const uint16_t[:, :, ::1] t16
    cdef const float[:, :, ::1] t32
    cdef const double[:, :, ::1] t64
    cdef const float *pzr = NULL
    cdef const float *pzi = NULL
    cdef const float *pv = NULL
    if taps is not None:
        import numpy as np
        if prepare is None or sat is None or offset is None or prepare.shape[0] != 7:
            raise TypeError("tofg_denoise: taps needs prepare (7 values), sat and offset")
        if taps.dtype == np.uint16:
            t16 = taps
            pi.taps, pi.in_type, nf = &t16[0, 0, 0], RGBZ_T_U16, t16.shape[0]
        elif taps.dtype == np.float32:
            t32 = taps
            pi.taps, pi.in_type, nf = &t32[0, 0, 0], RGBZ_T_F32, t32.shape[0]
        elif taps.dtype == np.float64:
            t64 = taps
            pi.taps, pi.in_type, nf = &t64[0, 0, 0], RGBZ_T_F64, t64.shape[0]
        else:
            raise TypeError(f"taps: expected uint16, float32 or float64, got {taps.dtype}")
        if taps.shape[1] != 4 or taps.shape[2] != R * C or sat.shape[0] != R * C \
                or offset.shape[0] != nf or offset.shape[1] != R * C:
            raise ValueError(f"tofg_denoise: expected taps (F, 4, {R * C}), sat ({R * C},) "
                             f"and offset (F, {R * C})")
        pi.gain, pi.black, pi.supp, pi.const_var = prepare[0], prepare[1], prepare[2], \
            prepare[3]
        pi.prnu, pi.white, pi.fixed_var = prepare[4], prepare[5], prepare[6]
        pi.sat = &sat[0]
        pi.offset = &offset[0, 0]
        ppi = &pi
    else:
        if zr is None or zi is None or v is None:
            raise TypeError("tofg_denoise: expected zr, zi and v, or taps")
        nf = zr.shape[0]
        pzr, pzi, pv = &zr[0, 0], &zi[0, 0], &v[0]
    if col.shape[0] not in (3, 4) or col.shape[1] != R * C:
        raise ValueError(f"col: expected (3, {R * C}) or (4, {R * C}), got "
                         f"{(col.shape[0], col.shape[1])}")
    cdef tofg_unwrap_out uw
    cdef tofg_unwrap_out *puw = NULL
    cdef double *o_r = NULL
    cdef double *o_i = NULL
    cdef float *o_n = NULL if out_neff is None else &out_neff[0]
    cdef double *o_n64 = NULL if count is None else &count[0]
    if R == 0 or C == 0:
        return True
    if o_n == NULL and o_n64 == NULL:
        raise TypeError("out_neff: expected a float32 array (N,) when count is None, got None")
    if depth is not None:
        uw.freqs = &freqs[0]
        uw.weights = &weights[0]
        uw.max_range = max_range
        uw.depth = &depth[0]
        uw.residual = &residual[0]
        uw.wraps = &wraps[0]
        uw.phase = &phase[0, 0]
        uw.amp = &amp[0, 0]
        uw.valid = NULL
        puw = &uw
        if flags is not None:
            if count is None or sat is None or sigma_scale is None or refl_coef is None \
                    or limits is None or snr is None or sigma is None or refl is None:
                raise TypeError("tofg_denoise: flags needs count, sat, sigma_scale, "
                                "refl_coef, limits, snr, sigma and refl")
            for n in (sat.shape[0], snr.shape[0], sigma.shape[0], refl.shape[0],
                      flags.shape[0]):
                if n != R * C:
                    raise ValueError(f"tofg_denoise: expected {R * C} measurements, got {n}")
            if sigma_scale.shape[0] != nf or refl_coef.shape[0] != nf or limits.shape[0] != 7:
                raise ValueError("tofg_denoise: expected sigma_scale and refl_coef of F "
                                 "values, limits of 7")
            vo.sat = &sat[0]
            vo.sigma_scale = &sigma_scale[0]
            vo.refl_coef = &refl_coef[0]
            vo.min_snr, vo.min_amplitude, vo.max_sigma = limits[0], limits[1], limits[2]
            vo.max_residual, vo.min_reflectance = limits[3], limits[4]
            vo.max_range, vo.max_reflectance = limits[5], limits[6]
            vo.snr = &snr[0]
            vo.sigma = &sigma[0]
            vo.refl = &refl[0]
            vo.flags = &flags[0]
            vo.offset = NULL
            vo.black = vo.pre = vo.var_dsnu = vo.fix_dsnu = vo.prnu = vo.delay_var = 0.0
            vo.usable, vo.present, vo.bad = NULL, NULL, <uint8_t> usable_bits
            if usable is not None:
                if usable.shape[0] != R * C or (present is not None
                                                and present.shape[0] != R * C):
                    raise ValueError(f"tofg_denoise: expected usable and present of {R * C}")
                vo.usable = &usable[0]
                vo.present = NULL if present is None else &present[0]
            if offset is not None:
                if offset.shape[0] != nf or offset.shape[1] != R * C or fixed is None \
                        or fixed.shape[0] != 6:
                    raise ValueError(f"tofg_denoise: expected offset ({nf}, {R * C}) and "
                                     "fixed of 6 values")
                vo.offset = &offset[0, 0]
                vo.black, vo.pre, vo.var_dsnu = fixed[0], fixed[1], fixed[2]
                vo.fix_dsnu, vo.prnu, vo.delay_var = fixed[3], fixed[4], fixed[5]
            uw.valid = &vo
    else:
        o_r = &out_re[0, 0]
        o_i = &out_im[0, 0]
    with nogil:
        status = rgbz_tofg_denoise(pzr, pzi, pv, &col[0, 0], &use[0], nf, R, C, &row_px[0],
                                   &col_px[0], reach_r, reach_c, radius_px, inv2h2, inv2hc2,
                                   o_r, o_i, &out_var[0], o_n, o_n64, puw, strip,
                                   col.shape[0] == 4, ppi, workers)
    if status == RGBZ_EDOMAIN:
        return False
    _raise_for(status)
    return True


def tofg_validity(const double[:, ::1] amp, const float[::1] var, const double[::1] depth,
                  const double[::1] residual, const uint8_t[::1] sat,
                  const double[::1] sigma_scale, const double[::1] refl_coef, double min_snr,
                  double min_amplitude, double max_sigma, double max_residual,
                  double min_reflectance, double max_range, double[::1] snr, double[::1] sigma,
                  double[::1] refl, uint8_t[::1] flags, int workers,
                  const double[::1] delta=None, double max_reflectance=INFINITY):
    """snr, sigma, implied reflectance and the validity bits (no flying test); delta (N,)
    or None: the fixed-pattern correction of sigma^2 (tof_fixed_pattern); max_reflectance:
    out of range above it (inf: no bound)."""
    cdef int status
    if depth.shape[0] == 0:
        return
    if delta is not None and delta.shape[0] != depth.shape[0]:
        raise ValueError(f"tofg_validity: expected delta of {depth.shape[0]} measurements")
    cdef const double *dp = &delta[0] if delta is not None else NULL
    with nogil:
        status = rgbz_tofg_validity(&amp[0, 0], &var[0], &depth[0], &residual[0], &sat[0],
                                    amp.shape[0], amp.shape[1], &sigma_scale[0], &refl_coef[0],
                                    min_snr, min_amplitude, max_sigma, max_residual,
                                    min_reflectance, max_range, dp, &snr[0], &sigma[0],
                                    &refl[0], &flags[0], workers, max_reflectance)
    _raise_for(status)


def tofg_usable(const uint8_t[::1] flags, const double[::1] depth, const double[::1] sigma,
                const uint8_t[::1] present, uint8_t bad, uint8_t[::1] usable, int workers):
    """usable = 1 where flags has none of the bits bad, depth and sigma are finite and present
    (None: every one) is nonzero, else 0; all (N,)."""
    cdef Py_ssize_t n = flags.shape[0]
    cdef const uint8_t *pp = NULL
    if depth.shape[0] != n or sigma.shape[0] != n or usable.shape[0] != n:
        raise ValueError(f"tofg_usable: expected planes of {n} measurements")
    if present is not None:
        if present.shape[0] != n:
            raise ValueError(f"tofg_usable: expected present of {n} measurements")
        pp = &present[0]
    if n == 0:
        return
    cdef int status
    with nogil:
        status = rgbz_tofg_usable(&flags[0], &depth[0], &sigma[0], pp, bad, n, &usable[0],
                                  workers)
    _raise_for(status)


def tofg_flying_candidates(const double[::1] depth, const double[::1] sigma,
                           const uint8_t[::1] usable, Py_ssize_t R, Py_ssize_t C, double step,
                           double k, uint8_t[::1] cand, int workers):
    """The candidates of the flying-pixel test (rgbz_fast.tof.flying_pixels) on the grid
    (R, C): cand = 1 at the usable measurements at a depth discontinuity; all (R * C,)."""
    cdef Py_ssize_t n = R * C
    if R < 0 or C < 0 or depth.shape[0] != n or sigma.shape[0] != n or \
            usable.shape[0] != n or cand.shape[0] != n:
        raise ValueError(f"tofg_flying_candidates: expected planes of {R} x {C} measurements")
    if n == 0:
        return
    cdef int status
    with nogil:
        status = rgbz_tofg_flying_candidates(&depth[0], &sigma[0], &usable[0], R, C, step, k,
                                             &cand[0], workers)
    _raise_for(status)


def tofg_flying(const double[::1] depth, const double[::1] sigma, const uint8_t[::1] usable,
                const float[:, ::1] col, const float[:, :, ::1] cells,
                const float[:, :, ::1] ring, Py_ssize_t R, Py_ssize_t C, double step, double k,
                double contrast, double side, int unflag, uint8_t[::1] flags,
                double[::1] depth_out, int workers, double max_range=NAN,
                uint8_t[::1] valid=None):
    """The flying-pixel test with colour edges: bits 8 (flying) and 32 (resolved) into flags,
    the resolved depths into depth_out (the measured depth elsewhere); ring (nring, 3, N) or
    None: the colours of the pixels bordering each Z pixel. max_range (NaN: none): a resolved
    depth below 0 or above max_range - 5 sigma also gets bit 16 (out of range). valid (N,),
    when given, takes flags == 0 of the final flags."""
    cdef int status
    cdef const float *cp = NULL
    cdef const float *rp = NULL
    cdef int ncells = 1
    cdef int nring = 0
    if cells is not None:
        cp = &cells[0, 0, 0]
        ncells = <int> cells.shape[0]
    if ring is not None and ring.shape[0] > 0:
        rp = &ring[0, 0, 0]
        nring = <int> ring.shape[0]
    if valid is not None and valid.shape[0] != depth.shape[0]:
        raise ValueError(f"tofg_flying: expected valid of {depth.shape[0]} measurements")
    if depth.shape[0] == 0:
        return
    with nogil:
        status = rgbz_tofg_flying(&depth[0], &sigma[0], &usable[0], &col[0, 0], cp, ncells, rp,
                                  nring, R, C, step, k, contrast, side, unflag, &flags[0],
                                  &depth_out[0], max_range,
                                  NULL if valid is None else &valid[0], workers)
    _raise_for(status)


def tofg_agree(double[::1] depth, double[::1] low, const uint8_t[::1] lone,
               const double[::1] sigma, Py_ssize_t R, Py_ssize_t C, double tol_k, double tol_min,
               int workers):
    """In place on the grid (R, C): the candidates (lone) whose low-signal depth lies within
    max(tol_k sigma, tol_min) of a usable neighbour's move from low into depth; all (R * C,)."""
    cdef Py_ssize_t n = R * C
    if R < 0 or C < 0 or depth.shape[0] != n or low.shape[0] != n or lone.shape[0] != n or \
            sigma.shape[0] != n:
        raise ValueError(f"tofg_agree: expected planes of {R} x {C} measurements")
    if n == 0:
        return
    cdef int status
    with nogil:
        status = rgbz_tofg_agree(&depth[0], &low[0], &lone[0], &sigma[0], R, C, tol_k, tol_min,
                                 workers)
    _raise_for(status)


def tofg_upsample(const frame_t[:, :, ::1] guide, double scale, const double[::1] cscale,
                  const double[::1] depth, const double[::1] sigma, const float[:, ::1] col,
                  Py_ssize_t R, Py_ssize_t C, const double[::1] rc, const double[::1] cc,
                  double spacing, Py_ssize_t reach, double inv2s2, double inv2hc2,
                  double tol_k, double tol_min, const double[::1] own, double own_k,
                  double ambiguity, double gap, float[:, ::1] out, float[:, ::1] conf,
                  int workers):
    """Joint bilateral upsampling of the measurements' depth to every pixel of the guide
    (own: the nodes' own too-noisy measurements or None)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef const double *po = NULL
    if own is not None:
        po = &own[0]
    cdef Py_ssize_t H = guide.shape[0], W = guide.shape[1]
    if H == 0 or W == 0:
        return
    with nogil:
        status = rgbz_tofg_upsample(in_type, &guide[0, 0, 0], H, W, scale, &cscale[0], &depth[0],
                                    &sigma[0], &col[0, 0], R, C, &rc[0], &cc[0], spacing, reach,
                                    inv2s2, inv2hc2, tol_k, tol_min, po, own_k, ambiguity, gap,
                                    &out[0, 0], &conf[0, 0], workers)
    _raise_for(status)


# ---------------------------------------------------------------------- fused colour ISP (colour_isp.h)
cdef extern from "colour_isp.h" nogil:
    int RGBZ_CI_MAX_NEIGHBOURS
    int rgbz_ci_defect_candidates(int in_type, const void *src, Py_ssize_t rows,
                                  Py_ssize_t cols, int32_t P, int32_t Q, const int32_t *noff,
                                  const int32_t *offs, float thr, float k, Py_ssize_t capacity,
                                  int64_t *rr, int64_t *cc, float *hot, float *cold,
                                  float *spread, Py_ssize_t *count, int workers)
    int rgbz_ci_defect_confirm(int in_type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                               int32_t P, int32_t Q, const int32_t *noff, const int32_t *offs,
                               Py_ssize_t n, const int64_t *rr, const int64_t *cc,
                               const float *hot, const float *cold, const float *spread,
                               float thr, float k, double f, uint8_t *ok)
    int rgbz_ci_phase_sums(int in_type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                           double white, double *sums, int64_t *counts, int workers)
    int rgbz_ci_render_f32(int in_type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                           const int32_t *phase, int mode, int method, const float *scale,
                           float black,
                           int clip, const float *matrix, const float *thresholds, int bits,
                           void *out, int workers)
    int rgbz_ci_render_f64(int in_type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                           const int32_t *phase, int mode, int method, const double *scale,
                           double black,
                           int clip, const double *matrix, const double *thresholds, int bits,
                           void *out, int workers)
    int rgbz_ci_balance_f32(int in_type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                            const int32_t *phase, const float *scale, float black, int clip,
                            float *out, int workers)
    int rgbz_ci_balance_f64(int in_type, const void *src, Py_ssize_t rows, Py_ssize_t cols,
                            const int32_t *phase, const double *scale, double black, int clip,
                            double *out, int workers)
    int rgbz_ci_encode_rgb_f32(const float *rgb, Py_ssize_t npix, const float *matrix,
                               const float *thresholds, int bits, void *out, int workers)
    int rgbz_ci_encode_rgb_f64(const double *rgb, Py_ssize_t npix, const double *matrix,
                               const double *thresholds, int bits, void *out, int workers)

#: neighbours of one tile position in the defect test (the offsets' second axis)
CI_MAX_NEIGHBOURS = RGBZ_CI_MAX_NEIGHBOURS


def ci_defect_candidates(const frame_t[:, ::1] src, const int32_t[::1] noff,
                         const int32_t[:, :, :, ::1] offs, float thr, float k,
                         int64_t[::1] rr, int64_t[::1] cc, float[::1] hot, float[::1] cold,
                         float[::1] spread, int workers):
    """Tests 1 and 2 of the defect detection; the candidates' count (it may exceed the room
    of the outputs, which then hold the first ones: call again with more room)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef Py_ssize_t count = 0, cap = rr.shape[0]
    if (cc.shape[0] < cap or hot.shape[0] < cap or cold.shape[0] < cap
            or spread.shape[0] < cap or offs.shape[3] != 2
            or offs.shape[2] != RGBZ_CI_MAX_NEIGHBOURS
            or noff.shape[0] != offs.shape[0] * offs.shape[1]):
        raise ValueError("ci_defect_candidates: inconsistent array shapes")
    with nogil:
        status = rgbz_ci_defect_candidates(
            in_type, &src[0, 0] if src.shape[0] * src.shape[1] else NULL,
            src.shape[0], src.shape[1], <int32_t> offs.shape[0], <int32_t> offs.shape[1],
            &noff[0], &offs[0, 0, 0, 0], thr, k, cap,
            &rr[0] if cap else NULL, &cc[0] if cap else NULL, &hot[0] if cap else NULL,
            &cold[0] if cap else NULL, &spread[0] if cap else NULL, &count, workers)
    _raise_for(status)
    return count


def ci_defect_confirm(const frame_t[:, ::1] src, const int32_t[::1] noff,
                      const int32_t[:, :, :, ::1] offs, const int64_t[::1] rr,
                      const int64_t[::1] cc, const float[::1] hot, const float[::1] cold,
                      const float[::1] spread, float thr, float k, double f, uint8_t[::1] ok):
    """Test 3 of the defect detection on the candidates of ci_defect_candidates: ok[i] = 1
    where candidate i is a defect."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef Py_ssize_t n = rr.shape[0]
    if (cc.shape[0] != n or hot.shape[0] != n or cold.shape[0] != n or spread.shape[0] != n
            or ok.shape[0] != n or offs.shape[3] != 2
            or offs.shape[2] != RGBZ_CI_MAX_NEIGHBOURS
            or noff.shape[0] != offs.shape[0] * offs.shape[1]):
        raise ValueError("ci_defect_confirm: inconsistent array shapes")
    if n == 0:
        return
    with nogil:
        status = rgbz_ci_defect_confirm(
            in_type, &src[0, 0], src.shape[0], src.shape[1], <int32_t> offs.shape[0],
            <int32_t> offs.shape[1], &noff[0], &offs[0, 0, 0, 0], n, &rr[0], &cc[0], &hot[0],
            &cold[0], &spread[0], thr, k, f, &ok[0])
    _raise_for(status)


def ci_phase_sums(const frame_t[:, ::1] src, double white, double[::1] sums,
                  int64_t[::1] counts, int workers):
    """The grey-world sums and counts of the four 2x2 phases of a complete Bayer CFA."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    if sums.shape[0] < 4 or counts.shape[0] < 4:
        raise ValueError("ci_phase_sums: sums and counts need 4 entries")
    with nogil:
        status = rgbz_ci_phase_sums(in_type, &src[0, 0], src.shape[0], src.shape[1], white,
                                    &sums[0], &counts[0], workers)
    _raise_for(status)


def ci_render(const frame_t[:, ::1] src, const int32_t[::1] phase, int mode,
              const rgb_t[::1] scale, rgb_t black, int clip, const rgb_t[::1] matrix,
              const rgb_t[::1] thresholds, code_t[:, :, ::1] out, int workers,
              int method=RGBZ_DM_MALVAR):
    """White balance .. output of a complete Bayer CFA (matrix: 9 values, or empty for the
    identity); the precision is the type of scale, black, matrix and thresholds; method: a
    code of DEMOSAIC_KERNELS."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int bits = 8 if code_t is uint8_t else 16
    cdef const rgb_t *m = &matrix[0] if matrix.shape[0] else NULL
    if (phase.shape[0] != 4 or scale.shape[0] != 3 or matrix.shape[0] not in (0, 9)
            or thresholds.shape[0] != (1 << bits) or out.shape[2] != 3
            or out.shape[0] != src.shape[0] or out.shape[1] != src.shape[1]):
        raise ValueError("ci_render: inconsistent array shapes")
    with nogil:
        if rgb_t is float:
            status = rgbz_ci_render_f32(in_type, &src[0, 0], src.shape[0], src.shape[1],
                                        &phase[0], mode, method, &scale[0], black, clip, m,
                                        &thresholds[0], bits, &out[0, 0, 0], workers)
        else:
            status = rgbz_ci_render_f64(in_type, &src[0, 0], src.shape[0], src.shape[1],
                                        &phase[0], mode, method, &scale[0], black, clip, m,
                                        &thresholds[0], bits, &out[0, 0, 0], workers)
    _raise_for(status)


def ci_balance(const frame_t[:, ::1] src, const int32_t[::1] phase, const rgb_t[::1] scale,
               rgb_t black, int clip, rgb_t[:, ::1] out, int workers):
    """The white balance of ci_render alone (isp.white_balance bit for bit) into out, of the
    precision of scale, black and out."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    if (phase.shape[0] != 4 or scale.shape[0] != 3 or out.shape[0] != src.shape[0]
            or out.shape[1] != src.shape[1] or src.shape[0] < 1 or src.shape[1] < 1):
        raise ValueError("ci_balance: inconsistent array shapes")
    with nogil:
        if rgb_t is float:
            status = rgbz_ci_balance_f32(in_type, &src[0, 0], src.shape[0], src.shape[1],
                                         &phase[0], &scale[0], black, clip, &out[0, 0], workers)
        else:
            status = rgbz_ci_balance_f64(in_type, &src[0, 0], src.shape[0], src.shape[1],
                                         &phase[0], &scale[0], black, clip, &out[0, 0], workers)
    _raise_for(status)


def ci_encode_rgb(const rgb_t[:, :, ::1] rgb, const rgb_t[::1] matrix,
                  const rgb_t[::1] thresholds, code_t[:, :, ::1] out, int workers):
    """ci_render's tail on linear RGB (rows, cols, 3): colour matrix (9 values, or empty for
    the identity), clip and codes (uint8 out: 8 bits, uint16: 16) by the thresholds; the
    precision is the type of rgb, matrix and thresholds."""
    cdef int status
    cdef int bits = 8 if code_t is uint8_t else 16
    cdef const rgb_t *m = &matrix[0] if matrix.shape[0] else NULL
    cdef Py_ssize_t npix = rgb.shape[0] * rgb.shape[1]
    if (matrix.shape[0] not in (0, 9) or thresholds.shape[0] != (1 << bits)
            or rgb.shape[2] != 3 or out.shape[2] != 3
            or out.shape[0] != rgb.shape[0] or out.shape[1] != rgb.shape[1]):
        raise ValueError("ci_encode_rgb: inconsistent array shapes")
    if npix == 0:
        return
    with nogil:
        if rgb_t is float:
            status = rgbz_ci_encode_rgb_f32(&rgb[0, 0, 0], npix, m, &thresholds[0], bits,
                                            &out[0, 0, 0], workers)
        else:
            status = rgbz_ci_encode_rgb_f64(&rgb[0, 0, 0], npix, m, &thresholds[0], bits,
                                            &out[0, 0, 0], workers)
    _raise_for(status)


# ---------------------------------------------------------------------------------------------
# The pool of large blocks (csrc/pool.h) behind rgbz_fast._memory: arrays over a PoolBlock give
# its memory back to the pool, not to the system, when the last of them is freed.

from cpython.buffer cimport PyBUF_FORMAT
from libc.stdint cimport uintptr_t

cdef extern from "Python.h":
    int PyTraceMalloc_Track(unsigned int domain, uintptr_t ptr, size_t size)
    int PyTraceMalloc_Untrack(unsigned int domain, uintptr_t ptr)

# NumPy's tracemalloc domain (numpy.lib.tracemalloc_domain): a block is an array's data, and
# tracemalloc counts it as NumPy's own (the bench's peak memory of one call included)
cdef unsigned int _NUMPY_DOMAIN = 389047

cdef extern from "pool.h":
    size_t rgbz_pool_size(size_t n) nogil
    void *rgbz_pool_take(size_t n) nogil
    void rgbz_pool_give(void *block, size_t size) nogil
    size_t rgbz_pool_set_limit(size_t limit) nogil
    size_t rgbz_pool_get_limit() nogil
    void rgbz_pool_stats(size_t *blocks, size_t *nbytes, size_t *reused, size_t *mapped) nogil


cdef class PoolBlock:
    """A writable buffer of ``nbytes`` bytes from the pool (csrc/pool.h), its contents
    undefined; its memory goes back to the pool when the block (and every array or
    memoryview over it) is freed."""
    cdef char *ptr
    cdef size_t size
    cdef Py_ssize_t shape[1]
    cdef Py_ssize_t strides[1]

    def __cinit__(self, Py_ssize_t nbytes):
        if nbytes < 0:
            raise ValueError(f"nbytes: expected >= 0, got {nbytes}")
        self.size = rgbz_pool_size(<size_t>nbytes)
        if self.size == 0:
            raise MemoryError(f"nbytes: {nbytes} bytes cannot be allocated")
        with nogil:
            self.ptr = <char *>rgbz_pool_take(<size_t>nbytes)
        if self.ptr == NULL:
            raise MemoryError(f"nbytes: the system has no {nbytes} bytes to give")
        self.shape[0] = nbytes
        self.strides[0] = 1
        PyTraceMalloc_Track(_NUMPY_DOMAIN, <uintptr_t>self.ptr, self.size)

    def __getbuffer__(self, Py_buffer *buf, int flags):
        buf.buf = self.ptr
        buf.obj = self
        buf.len = self.shape[0]
        buf.readonly = 0
        buf.itemsize = 1
        buf.format = NULL
        if flags & PyBUF_FORMAT:
            buf.format = b"B"
        buf.ndim = 1
        buf.shape = self.shape
        buf.strides = self.strides
        buf.suboffsets = NULL
        buf.internal = NULL

    def __releasebuffer__(self, Py_buffer *buf):
        pass

    def __dealloc__(self):
        if self.ptr != NULL:
            PyTraceMalloc_Untrack(_NUMPY_DOMAIN, <uintptr_t>self.ptr)
            with nogil:
                rgbz_pool_give(self.ptr, self.size)
            self.ptr = NULL


def pool_set_limit(size_t limit):
    """Set the bytes the pool keeps (the kept blocks beyond it given back to the system now);
    returns the previous limit."""
    cdef size_t old
    with nogil:
        old = rgbz_pool_set_limit(limit)
    return old


def pool_stats():
    """(limit, kept blocks, kept bytes, blocks reused, blocks newly mapped)."""
    cdef size_t blocks, nbytes, reused, mapped
    rgbz_pool_stats(&blocks, &nbytes, &reused, &mapped)
    return rgbz_pool_get_limit(), blocks, nbytes, reused, mapped


def pool_block_size(size_t nbytes):
    """The bytes the pool maps for a request of ``nbytes`` (rounded up to 2 MiB)."""
    return rgbz_pool_size(nbytes)
