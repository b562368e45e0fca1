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

cdef extern from "tof_filter.h" nogil:
    int rgbz_tof_bilateral(const double *z_re, const double *z_im, const double *var,
                           const double *g_re, const double *g_im, const double *g_var,
                           const uint8_t *use, const int64_t *row_px, const int64_t *col_px,
                           Py_ssize_t nfreq, Py_ssize_t rows, Py_ssize_t cols,
                           Py_ssize_t reach_rows, Py_ssize_t reach_cols, int64_t radius_px,
                           double inv_h2, double *out_re, double *out_im, double *out_var, double *out_neff,
                           int workers)

ctypedef fused rgb_t:
    float
    double


def fast_exp(const rgb_t[::1] x, rgb_t[::1] out):
    """The fast exponential of the reconstruction (exp="fast") of every element of ``x``."""
    cdef int status
    if x.shape[0] == 0:
        return
    with nogil:
        if rgb_t is float:
            status = rgbz_fast_exp_f32(&x[0], &out[0], x.shape[0])
        else:
            status = rgbz_fast_exp_f64(&x[0], &out[0], x.shape[0])
    _raise_for(status)


def demosaic_malvar(const frame_t[:, ::1] src, rgb_t[:, :, ::1] dst, const int32_t[::1] phase,
                    int mode, int workers):
    """Malvar-He-Cutler 2004 demosaic: Bayer CFA (rows, cols) -> RGB (rows, cols, 3)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int out_type = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    with nogil:
        status = rgbz_demosaic_malvar(in_type, out_type, &src[0, 0], &dst[0, 0, 0],
                                      src.shape[0], src.shape[1], &phase[0], mode, workers)
    _raise_for(status)


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
    int rgbz_ssim_sums(int in_type, const void *x, const void *y, Py_ssize_t planes,
                       Py_ssize_t rows, Py_ssize_t cols, const double *weights, int ntaps,
                       double c1, double c2, double *ssim_sum, double *cs_sum, int workers)
    int rgbz_downsample2(int in_type, const void *src, Py_ssize_t planes, Py_ssize_t rows,
                         Py_ssize_t cols, double *dst, int workers)
    int rgbz_srgb_to_lab(int in_type, const void *rgb, Py_ssize_t n, double scale,
                         double *lab, int workers)
    int rgbz_zipper_count(int in_type, const void *ref, const void *test, Py_ssize_t rows,
                          Py_ssize_t cols, double scale, double delta, int64_t *count,
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
              const double[::1] weights, double c1, double c2, double[::1] ssim_sum,
              double[::1] cs_sum, int workers):
    """Per-plane sums of the SSIM and contrast-structure maps of planar (planes, rows, cols)
    images over the windows wholly inside them (separable symmetric window ``weights``)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    with nogil:
        status = rgbz_ssim_sums(in_type, &x[0, 0, 0], &y[0, 0, 0], x.shape[0], x.shape[1],
                                x.shape[2], &weights[0], <int> weights.shape[0], c1, c2,
                                &ssim_sum[0], &cs_sum[0], workers)
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
