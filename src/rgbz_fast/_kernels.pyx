# cython: language_level=3, embedsignature=True
"""Thin bridge to the C core (csrc/): typed memoryviews, GIL released, status -> exception.

No logic of its own: the Python layer validates arguments and allocates every
output; this module only adapts buffers and maps status codes.

The same source builds two extension modules (src/rgbz_fast/meson.build):
``rgbz_fast._kernels``, which every user loads, and ``rgbz_fast._kernels_count``,
linked against the counting build of the C core (-DRGBZ_COUNT_OPS), which only
:mod:`rgbz_fast._devtools.opcount` loads. Their Python interface is the same; the counting
module wants ``opcounts`` where the normal one refuses it.

The enums of csrc/rgbz.h are ``cpdef enum`` classes here, and the name -> code
tables of the Python layer (:data:`METHODS`, :data:`PRECISIONS`,
:data:`EXP_MODES`, :data:`DEMOSAIC_MODES`, :data:`OP_CATEGORIES`) are built from
them, so no code is typed twice.
"""

from libc.stdint cimport int8_t, int32_t, int64_t, uint8_t, uint16_t, uint64_t

cdef extern from "rgbz.h" nogil:
    cpdef enum rgbz_status:
        RGBZ_OK
        RGBZ_EINVAL
        RGBZ_ENOMEM
        RGBZ_EDOMAIN
    cpdef enum rgbz_type:
        RGBZ_T_U8
        RGBZ_T_U16
        RGBZ_T_F32
        RGBZ_T_F64
    cpdef enum rgbz_precision:
        RGBZ_P_FLOAT32
        RGBZ_P_FLOAT64
    cpdef enum rgbz_method:
        RGBZ_M_BILINEAR
        RGBZ_M_BI
        RGBZ_M_EDI_CENTRAL
        RGBZ_M_EDI_LINE
        RGBZ_M_SG
        RGBZ_M_EDI_ROWS
    cpdef enum rgbz_exp_mode:
        RGBZ_EXP_LIBM
        RGBZ_EXP_FAST
    cpdef enum rgbz_demosaic_mode:
        RGBZ_DM_REFLECT
        RGBZ_DM_PERIOD
    cpdef enum rgbz_op:
        RGBZ_OP_ADD
        RGBZ_OP_MUL
        RGBZ_OP_DIV
        RGBZ_OP_EXP
        RGBZ_OP_ABS
        RGBZ_OP_CMP
        RGBZ_OP_SQRT
        RGBZ_OP_ATAN2
    enum:
        RGBZ_NOPS
        RGBZ_MAX_TAPS
        RGBZ_MAX_CAND
        RGBZ_MAX_PAIRS
        RGBZ_NGROUPS
        RGBZ_MAX_CD
        RGBZ_TOF_MAX_FREQS
        RGBZ_TOF_MAX_WRAPS
        RGBZ_PLAN_FIELDS
    ctypedef struct rgbz_plan:
        pass
    ctypedef struct rgbz_params:
        double sigma_floor
        double sigma_rel
        double edge_ratio
        double maxval
        int32_t exp_mode
        int32_t workers
        int32_t mask1_fast
        int32_t clip_on
        double clip_level
    int rgbz_plan_layout(int64_t *out, int n)
    int rgbz_mask1_plan(int method, int sg_combined, rgbz_plan *out)
    int rgbz_reconstruct(int in_type, int precision, const void *src, void *dst,
                         Py_ssize_t rows, Py_ssize_t cols, int py, int px,
                         const int32_t *phase_map, const rgbz_plan *plans, int n_plans,
                         const rgbz_params *params, uint64_t *opcounts)
    int rgbz_fast_exp(int type, const void *x, void *out, Py_ssize_t n)
    int rgbz_demosaic_malvar(int in_type, int out_type, const void *src, void *dst,
                             Py_ssize_t rows, Py_ssize_t cols, const int32_t *phase,
                             int mode, int workers)
    int rgbz_tof_demodulate(int in_type, const void *taps, Py_ssize_t F, Py_ssize_t N,
                            double *phase, double *amp, double *offset, int workers)
    int rgbz_tof_unwrap(const double *phase, Py_ssize_t F, Py_ssize_t N, const double *freqs,
                        const double *weights, double max_range, double *depth,
                        double *residual, int32_t *wraps, int workers)
    int rgbz_tof_depth(int in_type, const void *taps, Py_ssize_t F, Py_ssize_t N,
                       const double *freqs, const double *weights, double max_range,
                       double *depth, double *residual, int32_t *wraps, double *phase,
                       double *amp, double *offset, int workers)
    int rgbz_tof_depth_iq(const double *i_comp, const double *q_comp, Py_ssize_t F,
                          Py_ssize_t N, const double *freqs, const double *weights,
                          double max_range, double *depth, double *residual, int32_t *wraps,
                          double *phase, double *amp, int workers)
    int rgbz_have_openmp()
    int rgbz_max_threads()
    int rgbz_counting_build()
    int rgbz_opcount_target(uint64_t *counts)

cdef extern from "learned.h" nogil:
    ctypedef struct rgbz_learned_filters:
        int32_t n_phases, n_buckets, n_taps_max, n_pairs_max, n_str, n_coh, radius
        int32_t hash_radius
        const int32_t *n_taps
        const int32_t *tap_dy
        const int32_t *tap_dx
        const int32_t *n_pairs
        const int32_t *pair_a
        const int32_t *pair_b
        const double *str_thr
        const double *coh_thr2
        const float *w_f32
        const double *w_f64
        const float *wd_f32
        const double *wd_f64
    int rgbz_learned(int in_type, int precision, const void *src, void *dst, Py_ssize_t rows,
                     Py_ssize_t cols, int py, int px, const int32_t *phase_map,
                     const rgbz_learned_filters *f, double maxval, int workers,
                     uint64_t *opcounts)
cdef extern from "z_guided.h" nogil:
    ctypedef struct rgbz_zguided_filters:
        const rgbz_learned_filters *hash
        int32_t n_levels
        const float *w_f32
        const double *w_f64
        const float *g_f32
        const double *g_f64
        int32_t n_base_max
        const int32_t *n_base
        const int32_t *base_idx
        Py_ssize_t gy, gx
        const double *cell
        const int32_t *level
    int rgbz_zguided_u8(const uint8_t *src, uint8_t *dst, Py_ssize_t rows, Py_ssize_t cols,
                        int py, int px, const int32_t *phase_map, const rgbz_zguided_filters *f,
                        int precision, double maxval, int workers, uint64_t *opcounts)
    int rgbz_zguided_u16(const uint16_t *src, uint16_t *dst, Py_ssize_t rows, Py_ssize_t cols,
                         int py, int px, const int32_t *phase_map,
                         const rgbz_zguided_filters *f, int precision, double maxval,
                         int workers, uint64_t *opcounts)
    int rgbz_zguided_f32(const float *src, float *dst, Py_ssize_t rows, Py_ssize_t cols,
                         int py, int px, const int32_t *phase_map,
                         const rgbz_zguided_filters *f, int precision, double maxval,
                         int workers, uint64_t *opcounts)
    int rgbz_zguided_f64(const double *src, double *dst, Py_ssize_t rows, Py_ssize_t cols,
                         int py, int px, const int32_t *phase_map,
                         const rgbz_zguided_filters *f, int precision, double maxval,
                         int workers, uint64_t *opcounts)
    int rgbz_zguided_cells_u8(const uint8_t *src, Py_ssize_t rows, Py_ssize_t cols, int py, int px,
                              const int8_t *chan, int zr, int zc, int block, const double *grid,
                              const double *var, Py_ssize_t gy, Py_ssize_t gx, int n_phases,
                              const int32_t *targets, double lam, const double *thr, int n_thr,
                              double *cell, int32_t *level, int workers)
    int rgbz_zguided_cells_u16(const uint16_t *src, Py_ssize_t rows, Py_ssize_t cols, int py, int px,
                              const int8_t *chan, int zr, int zc, int block, const double *grid,
                              const double *var, Py_ssize_t gy, Py_ssize_t gx, int n_phases,
                              const int32_t *targets, double lam, const double *thr, int n_thr,
                              double *cell, int32_t *level, int workers)
    int rgbz_zguided_cells_f32(const float *src, Py_ssize_t rows, Py_ssize_t cols, int py, int px,
                              const int8_t *chan, int zr, int zc, int block, const double *grid,
                              const double *var, Py_ssize_t gy, Py_ssize_t gx, int n_phases,
                              const int32_t *targets, double lam, const double *thr, int n_thr,
                              double *cell, int32_t *level, int workers)
    int rgbz_zguided_cells_f64(const double *src, Py_ssize_t rows, Py_ssize_t cols, int py, int px,
                              const int8_t *chan, int zr, int zc, int block, const double *grid,
                              const double *var, Py_ssize_t gy, Py_ssize_t gx, int n_phases,
                              const int32_t *targets, double lam, const double *thr, int n_thr,
                              double *cell, int32_t *level, int workers)
cdef extern from "tof_filter.h" nogil:
    int rgbz_tof_bilateral(const double *z_re, const double *z_im, const double *var,
                           const double *g_re, const double *g_im, const double *g_var,
                           const uint8_t *use, const int64_t *row_px, const int64_t *col_px,
                           Py_ssize_t nfreq, Py_ssize_t rows, Py_ssize_t cols,
                           Py_ssize_t reach_rows, Py_ssize_t reach_cols, int64_t radius_px,
                           double inv_h2, double *out_re, double *out_im, double *out_var, double *out_neff,
                           int workers)

ctypedef fused frame_t:
    uint8_t
    uint16_t
    float
    double

ctypedef fused rgb_t:
    float
    double

ctypedef fused tap_t:
    uint16_t
    float
    double


cdef int _type_code(frame_t *p) noexcept nogil:
    if frame_t is uint8_t:
        return RGBZ_T_U8
    elif frame_t is uint16_t:
        return RGBZ_T_U16
    elif frame_t is float:
        return RGBZ_T_F32
    else:
        return RGBZ_T_F64


def _codes(enum_class, prefix):
    """{name: code} of a C enum, the name its member's lower-case suffix after ``prefix``."""
    return {m.name[len(prefix):].lower(): int(m) for m in enum_class}


NOPS = RGBZ_NOPS
TOF_MAX_WRAPS = RGBZ_TOF_MAX_WRAPS
TOF_MAX_FREQS = RGBZ_TOF_MAX_FREQS
#: the sizes of the arrays of one plan (rgbz_plan, csrc/rgbz.h)
PLAN_LIMITS = {"max_taps": RGBZ_MAX_TAPS, "max_cand": RGBZ_MAX_CAND,
               "max_pairs": RGBZ_MAX_PAIRS, "ngroups": RGBZ_NGROUPS, "max_cd": RGBZ_MAX_CD}
#: reconstruction methods, precisions, exponentials, demosaic border modes and operation
#: counters: {name: code}, from the enums of csrc/rgbz.h
METHODS = _codes(rgbz_method, "RGBZ_M_")
PRECISIONS = _codes(rgbz_precision, "RGBZ_P_")
EXP_MODES = _codes(rgbz_exp_mode, "RGBZ_EXP_")
DEMOSAIC_MODES = _codes(rgbz_demosaic_mode, "RGBZ_DM_")
OP_CATEGORIES = _codes(rgbz_op, "RGBZ_OP_")


cdef int _raise_for(int status) except -1:
    if status == RGBZ_OK:
        return 0
    if status == RGBZ_ENOMEM:
        raise MemoryError("scratch allocation failed in a C kernel")
    if status == RGBZ_EINVAL:
        raise RuntimeError("a C kernel rejected its arguments (status 1): "
                           "a bug in the Python validation layer")
    raise RuntimeError(f"C kernel failed with status {status}")


cdef uint64_t *_counters(uint64_t[::1] opcounts, Py_ssize_t need) except? NULL:
    """The counters of a counting call: required by _kernels_count, refused by _kernels."""
    if not rgbz_counting_build():
        if opcounts is not None:
            raise ValueError("opcounts: this module does not count operations; "
                             "use rgbz_fast._kernels_count")
        return NULL
    if opcounts is None or opcounts.shape[0] < need:
        raise ValueError(f"opcounts: the counting module needs {need} counters")
    return &opcounts[0]


def plan_layout():
    """(sizeof(rgbz_plan), field offsets...) as compiled, to check the Python dtype."""
    cdef int64_t out[RGBZ_PLAN_FIELDS + 1]
    _raise_for(rgbz_plan_layout(out, RGBZ_PLAN_FIELDS + 1))
    return tuple(out[i] for i in range(RGBZ_PLAN_FIELDS + 1))


def mask1_plan(int method, int sg_combined=0):
    """The bytes of the constant Mask1 plan of csrc/recon_mask1.h for ``method``."""
    cdef rgbz_plan plan
    _raise_for(rgbz_mask1_plan(method, sg_combined, &plan))
    return (<char *> &plan)[:sizeof(rgbz_plan)]


def fast_exp(const rgb_t[::1] x, rgb_t[::1] out):
    """The fast exponential of the reconstruction (exp="fast") of every element of ``x``."""
    cdef int status
    cdef int t = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    if x.shape[0] == 0:
        return
    with nogil:
        status = rgbz_fast_exp(t, &x[0], &out[0], x.shape[0])
    _raise_for(status)


def have_openmp():
    return bool(rgbz_have_openmp())


def max_threads():
    return int(rgbz_max_threads())


def counting_build():
    """True in rgbz_fast._kernels_count, the module built with -DRGBZ_COUNT_OPS."""
    return bool(rgbz_counting_build())


def reconstruct(const frame_t[:, ::1] src, frame_t[:, ::1] dst, int precision,
                int py, int px, const int32_t[::1] phase_map, const uint8_t[::1] plans,
                int n_plans, double sigma_floor, double sigma_rel, double edge_ratio, double maxval,
                int exp_mode, int workers, uint64_t[::1] opcounts=None, int mask1_fast=0,
                clip_level=None):
    """Run the reconstruction kernel.

    ``opcounts`` (n_plans x NOPS counters): required by the counting module
    (``_kernels_count``, single thread), refused by ``_kernels``.
    ``clip_level`` (DN, or None): known pixels at or above it are clipped; needs
    ``mask1_fast=0`` (the C core rejects the combination otherwise).
    """
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int status
    cdef rgbz_params prm
    cdef uint64_t *counts = _counters(opcounts, <Py_ssize_t> n_plans * RGBZ_NOPS)
    prm.sigma_floor = sigma_floor
    prm.sigma_rel = sigma_rel
    prm.edge_ratio = edge_ratio
    prm.maxval = maxval
    prm.exp_mode = exp_mode
    prm.workers = 1 if counts != NULL else workers
    prm.mask1_fast = mask1_fast
    prm.clip_on = 0 if clip_level is None else 1
    prm.clip_level = 0.0 if clip_level is None else float(clip_level)
    with nogil:
        status = rgbz_reconstruct(
            in_type, precision, &src[0, 0], &dst[0, 0], src.shape[0], src.shape[1],
            py, px, &phase_map[0], <const rgbz_plan *> &plans[0], n_plans, &prm, counts)
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


def tof_demodulate(const tap_t[:, :, ::1] taps, double[:, ::1] phase, double[:, ::1] amp,
                   double[:, ::1] offset, int workers, uint64_t[::1] opcounts=None):
    """Four-tap demodulation: taps (F, 4, N) -> phase, amplitude, offset (F, N).

    ``opcounts`` (NOPS counters): as for :func:`reconstruct`.
    """
    cdef int status
    cdef int in_type = _type_code(<tap_t *> NULL)
    cdef uint64_t *counts = _counters(opcounts, RGBZ_NOPS)
    if taps.shape[2] == 0:
        return
    if counts != NULL:
        _raise_for(rgbz_opcount_target(counts))
        workers = 1
    with nogil:
        status = rgbz_tof_demodulate(in_type, &taps[0, 0, 0], taps.shape[0], taps.shape[2],
                                     &phase[0, 0], &amp[0, 0], &offset[0, 0], workers)
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
    int rgbz_oetf_prepare(int type, const void *x, void *p, Py_ssize_t n, int workers)
    int rgbz_oetf_finish(int type, const void *x, const void *p, Py_ssize_t n, int bits,
                         void *code, int workers)

ctypedef fused code_t:
    uint8_t
    uint16_t


def oetf_prepare(const rgb_t[::1] x, rgb_t[::1] p, int workers):
    """p = 1 where the clipped x is on the OETF's linear segment, else the clipped x."""
    cdef int status
    cdef int t = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    with nogil:
        status = rgbz_oetf_prepare(t, &x[0], &p[0], x.shape[0], workers)
    _raise_for(status)


def oetf_finish(const rgb_t[::1] x, const rgb_t[::1] p, code_t[::1] code, int workers):
    """8- or 16-bit sRGB codes of x, p holding the power 1 / 2.4 of oetf_prepare's output."""
    cdef int status
    cdef int t = RGBZ_T_F32 if rgb_t is float else RGBZ_T_F64
    cdef int bits = 8 if code_t is uint8_t else 16
    with nogil:
        status = rgbz_oetf_finish(t, &x[0], &p[0], x.shape[0], bits, &code[0], workers)
    _raise_for(status)


# ---------------------------------------------------------------------- learned (learned.c)
def learned(const frame_t[:, ::1] src, frame_t[:, ::1] dst, int precision, int py, int px,
            const int32_t[::1] phase_map, const int32_t[::1] n_taps,
            const int32_t[:, ::1] tap_dy, const int32_t[:, ::1] tap_dx,
            const int32_t[:, ::1] n_pairs, const int32_t[:, :, ::1] pair_a,
            const int32_t[:, :, ::1] pair_b, const double[:, ::1] str_thr,
            const double[:, ::1] coh_thr2, const float[:, :, ::1] w_f32,
            const double[:, :, ::1] w_f64, int radius, int hash_radius, double maxval,
            int workers, const float[:, :, :, ::1] wd_f32=None,
            const double[:, :, :, ::1] wd_f64=None, uint64_t[::1] opcounts=None):
    """Run the learned reconstruction. ``opcounts`` (n_phases x NOPS counters): required by
    the counting module (``_kernels_count``, single thread), refused by ``_kernels``.

    Weights are tap-major, (n_phases, n_taps_max, n_buckets); thresholds
    (n_phases, levels - 1), the coherence ones squared; the optional dense weights
    (n_phases, n_buckets, 2 radius + 1, 8) enable the fast path (the layout of learned.h).
    """
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int status
    cdef rgbz_learned_filters f
    cdef double zero = 0.0
    f.n_phases = w_f32.shape[0]
    f.n_taps_max = w_f32.shape[1]
    f.n_buckets = w_f32.shape[2]
    f.n_pairs_max = pair_a.shape[2]
    f.n_str = str_thr.shape[1] + 1
    f.n_coh = coh_thr2.shape[1] + 1
    f.radius = radius
    f.hash_radius = hash_radius
    f.n_taps = &n_taps[0]
    f.tap_dy = &tap_dy[0, 0]
    f.tap_dx = &tap_dx[0, 0]
    f.n_pairs = &n_pairs[0, 0]
    f.pair_a = &pair_a[0, 0, 0]
    f.pair_b = &pair_b[0, 0, 0]
    # a level count of 1 has no threshold: the kernel reads none
    f.str_thr = &str_thr[0, 0] if str_thr.shape[1] else &zero
    f.coh_thr2 = &coh_thr2[0, 0] if coh_thr2.shape[1] else &zero
    f.w_f32 = &w_f32[0, 0, 0]
    f.w_f64 = &w_f64[0, 0, 0]
    f.wd_f32 = NULL
    f.wd_f64 = NULL
    if wd_f32 is not None and wd_f64 is not None:
        if (wd_f32.shape[0] != f.n_phases or wd_f32.shape[1] != f.n_buckets
                or wd_f32.shape[2] != 2 * radius + 1 or wd_f32.shape[3] != 8
                or wd_f64.shape[0] != f.n_phases or wd_f64.shape[1] != f.n_buckets
                or wd_f64.shape[2] != 2 * radius + 1 or wd_f64.shape[3] != 8):
            raise ValueError("learned: inconsistent dense weights")
        f.wd_f32 = &wd_f32[0, 0, 0, 0]
        f.wd_f64 = &wd_f64[0, 0, 0, 0]
    if (tap_dy.shape[0] != f.n_phases or n_taps.shape[0] != f.n_phases
            or w_f64.shape[0] != f.n_phases or w_f64.shape[1] != f.n_taps_max
            or w_f64.shape[2] != f.n_buckets or tap_dy.shape[1] != f.n_taps_max
            or tap_dx.shape[1] != f.n_taps_max or pair_b.shape[2] != f.n_pairs_max):
        raise ValueError("learned: inconsistent filter arrays")
    cdef uint64_t *counts = _counters(opcounts, <Py_ssize_t> f.n_phases * RGBZ_NOPS)
    with nogil:
        status = rgbz_learned(in_type, precision, &src[0, 0], &dst[0, 0], src.shape[0],
                              src.shape[1], py, px, &phase_map[0], &f, maxval, workers, counts)
    _raise_for(status)


# ---------------------------------------------------------------------- z_guided (z_guided.c)
def z_guided(const frame_t[:, ::1] src, frame_t[:, ::1] dst, int precision, int py, int px,
             const int32_t[::1] phase_map, const int32_t[::1] n_taps,
             const int32_t[:, ::1] tap_dy, const int32_t[:, ::1] tap_dx,
             const int32_t[:, ::1] n_pairs, const int32_t[:, :, ::1] pair_a,
             const int32_t[:, :, ::1] pair_b, const double[:, ::1] str_thr,
             const double[:, ::1] coh_thr2, int radius, int hash_radius,
             const float[:, :, ::1] w_f32, const double[:, :, ::1] w_f64,
             const float[:, :, ::1] g_f32, const double[:, :, ::1] g_f64,
             const int32_t[::1] n_base, const int32_t[:, ::1] base_idx,
             const double[:, :, :, ::1] cell, const int32_t[:, ::1] level, double maxval,
             int workers, uint64_t[::1] opcounts=None):
    """Run the z_guided reconstruction (csrc/z_guided.h). The hash arrays are those of
    ``learned`` (LearnedFilters.kernel_arrays of the base filters); colour weights tap-major
    (n_phases, n_taps_max, n_levels * n_buckets), guide weights (n_phases, n_levels *
    n_buckets, 11), the baseline taps (n_phases,) and (n_phases, n_base_max), the cell
    features (n_phases, gy, gx, 11) and noise levels (gy, gx). ``opcounts``: as for
    ``learned``."""
    cdef int status
    cdef rgbz_learned_filters h
    cdef rgbz_zguided_filters f
    cdef double zero = 0.0
    cdef Py_ssize_t n_ph = w_f32.shape[0]
    if (n_taps.shape[0] != n_ph or tap_dy.shape[0] != n_ph or tap_dx.shape[0] != n_ph
            or n_pairs.shape[0] != n_ph or n_pairs.shape[1] != 4 or pair_a.shape[0] != n_ph
            or pair_b.shape[0] != n_ph or pair_a.shape[1] != 4 or pair_b.shape[1] != 4
            or pair_b.shape[2] != pair_a.shape[2] or tap_dy.shape[1] != w_f32.shape[1]
            or tap_dx.shape[1] != w_f32.shape[1] or str_thr.shape[0] != n_ph
            or coh_thr2.shape[0] != n_ph or w_f64.shape[0] != n_ph
            or w_f64.shape[1] != w_f32.shape[1] or w_f64.shape[2] != w_f32.shape[2]
            or g_f32.shape[0] != n_ph or g_f64.shape[0] != n_ph
            or g_f32.shape[1] != w_f32.shape[2] or g_f64.shape[1] != w_f32.shape[2]
            or g_f32.shape[2] != 11 or g_f64.shape[2] != 11 or n_base.shape[0] != n_ph
            or base_idx.shape[0] != n_ph or cell.shape[0] != n_ph or cell.shape[3] != 11
            or cell.shape[1] != level.shape[0] or cell.shape[2] != level.shape[1]
            or dst.shape[0] != src.shape[0] or dst.shape[1] != src.shape[1]
            or phase_map.shape[0] != py * px):
        raise ValueError("z_guided: inconsistent filter arrays")
    h.n_phases = n_ph
    h.n_taps_max = w_f32.shape[1]
    h.n_str = str_thr.shape[1] + 1
    h.n_coh = coh_thr2.shape[1] + 1
    h.n_buckets = 8 * h.n_str * h.n_coh
    if w_f32.shape[2] % h.n_buckets:
        raise ValueError("z_guided: the weights' buckets are not levels x hash buckets")
    h.n_pairs_max = pair_a.shape[2]
    h.radius = radius
    h.hash_radius = hash_radius
    h.n_taps = &n_taps[0]
    h.tap_dy = &tap_dy[0, 0]
    h.tap_dx = &tap_dx[0, 0]
    h.n_pairs = &n_pairs[0, 0]
    h.pair_a = &pair_a[0, 0, 0]
    h.pair_b = &pair_b[0, 0, 0]
    # a level count of 1 has no threshold: the kernel reads none
    h.str_thr = &str_thr[0, 0] if str_thr.shape[1] else &zero
    h.coh_thr2 = &coh_thr2[0, 0] if coh_thr2.shape[1] else &zero
    h.w_f32 = NULL
    h.w_f64 = NULL
    h.wd_f32 = NULL
    h.wd_f64 = NULL
    f.hash = &h
    f.n_levels = w_f32.shape[2] // h.n_buckets
    f.w_f32 = &w_f32[0, 0, 0]
    f.w_f64 = &w_f64[0, 0, 0]
    f.g_f32 = &g_f32[0, 0, 0]
    f.g_f64 = &g_f64[0, 0, 0]
    f.n_base_max = base_idx.shape[1]
    f.n_base = &n_base[0]
    f.base_idx = &base_idx[0, 0]
    f.gy = level.shape[0]
    f.gx = level.shape[1]
    f.cell = &cell[0, 0, 0, 0]
    f.level = &level[0, 0]
    cdef uint64_t *counts = _counters(opcounts, n_ph * RGBZ_NOPS)
    with nogil:
        if frame_t is uint8_t:
            status = rgbz_zguided_u8(&src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py, px,
                                     &phase_map[0], &f, precision, maxval, workers, counts)
        elif frame_t is uint16_t:
            status = rgbz_zguided_u16(&src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py,
                                      px, &phase_map[0], &f, precision, maxval, workers, counts)
        elif frame_t is float:
            status = rgbz_zguided_f32(&src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py,
                                      px, &phase_map[0], &f, precision, maxval, workers, counts)
        else:
            status = rgbz_zguided_f64(&src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py,
                                      px, &phase_map[0], &f, precision, maxval, workers, counts)
    _raise_for(status)


def z_guided_cells(const frame_t[:, ::1] src, int py, int px, const int8_t[::1] chan, int zr,
                   int zc, int block, const double[:, ::1] grid, const double[:, ::1] var,
                   const int32_t[::1] targets, double lam, const double[::1] thr,
                   double[:, :, :, ::1] cell, int32_t[:, ::1] level, int workers):
    """The cell terms (n_phases, gy, gx, 11) and noise levels (gy, gx) of z_guided
    (csrc/z_guided.h) from the frame, the amplitude grid and its variance (gy, gx), the
    colour codes of the tile (py * px), the Z pixel's corner and size, the target colour of
    each phase, the regularisation and the noise thresholds."""
    cdef int status
    cdef double zero = 0.0
    cdef const double *thr_p = &thr[0] if thr.shape[0] else &zero
    if (var.shape[0] != grid.shape[0] or var.shape[1] != grid.shape[1]
            or level.shape[0] != grid.shape[0] or level.shape[1] != grid.shape[1]
            or cell.shape[0] != targets.shape[0] or cell.shape[1] != grid.shape[0]
            or cell.shape[2] != grid.shape[1] or cell.shape[3] != 11
            or chan.shape[0] != py * px or targets.shape[0] == 0):
        raise ValueError("z_guided_cells: inconsistent arrays")
    with nogil:
        if frame_t is uint8_t:
            status = rgbz_zguided_cells_u8(&src[0, 0], src.shape[0], src.shape[1], py, px,
                                             &chan[0], zr, zc, block, &grid[0, 0], &var[0, 0],
                                             grid.shape[0], grid.shape[1], targets.shape[0],
                                             &targets[0], lam, thr_p, thr.shape[0],
                                             &cell[0, 0, 0, 0], &level[0, 0], workers)
        elif frame_t is uint16_t:
            status = rgbz_zguided_cells_u16(&src[0, 0], src.shape[0], src.shape[1], py, px,
                                             &chan[0], zr, zc, block, &grid[0, 0], &var[0, 0],
                                             grid.shape[0], grid.shape[1], targets.shape[0],
                                             &targets[0], lam, thr_p, thr.shape[0],
                                             &cell[0, 0, 0, 0], &level[0, 0], workers)
        elif frame_t is float:
            status = rgbz_zguided_cells_f32(&src[0, 0], src.shape[0], src.shape[1], py, px,
                                             &chan[0], zr, zc, block, &grid[0, 0], &var[0, 0],
                                             grid.shape[0], grid.shape[1], targets.shape[0],
                                             &targets[0], lam, thr_p, thr.shape[0],
                                             &cell[0, 0, 0, 0], &level[0, 0], workers)
        else:
            status = rgbz_zguided_cells_f64(&src[0, 0], src.shape[0], src.shape[1], py, px,
                                             &chan[0], zr, zc, block, &grid[0, 0], &var[0, 0],
                                             grid.shape[0], grid.shape[1], targets.shape[0],
                                             &targets[0], lam, thr_p, thr.shape[0],
                                             &cell[0, 0, 0, 0], &level[0, 0], workers)
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
    int rgbz_tofg_prepare_u16(const uint16_t *taps, Py_ssize_t F, Py_ssize_t N, double gain,
                              double black, double supp, double const_var, double prnu,
                              double white, float *zr, float *zi, float *v, uint8_t *sat,
                              double *offset, int workers)
    int rgbz_tofg_prepare_f32(const float *taps, Py_ssize_t F, Py_ssize_t N, double gain,
                              double black, double supp, double const_var, double prnu,
                              double white, float *zr, float *zi, float *v, uint8_t *sat,
                              double *offset, int workers)
    int rgbz_tofg_prepare_f64(const double *taps, Py_ssize_t F, Py_ssize_t N, double gain,
                              double black, double supp, double const_var, double prnu,
                              double white, float *zr, float *zi, float *v, uint8_t *sat,
                              double *offset, int workers)
    int rgbz_tofg_colour_u8(const uint8_t *guide, Py_ssize_t H, Py_ssize_t W,
                            const int64_t *row_px, Py_ssize_t R, const int64_t *col_px,
                            Py_ssize_t C, int block, double scale, float *col, float *cells,
                            double *lap, int workers)
    int rgbz_tofg_colour_u16(const uint16_t *guide, Py_ssize_t H, Py_ssize_t W,
                             const int64_t *row_px, Py_ssize_t R, const int64_t *col_px,
                             Py_ssize_t C, int block, double scale, float *col, float *cells,
                             double *lap, int workers)
    int rgbz_tofg_colour_f32(const float *guide, Py_ssize_t H, Py_ssize_t W,
                             const int64_t *row_px, Py_ssize_t R, const int64_t *col_px,
                             Py_ssize_t C, int block, double scale, float *col, float *cells,
                             double *lap, int workers)
    int rgbz_tofg_colour_f64(const double *guide, Py_ssize_t H, Py_ssize_t W,
                             const int64_t *row_px, Py_ssize_t R, const int64_t *col_px,
                             Py_ssize_t C, int block, double scale, float *col, float *cells,
                             double *lap, int workers)
    int rgbz_tofg_pass(const float *zr, const float *zi, const float *v, const float *nin,
                       const float *gr, const float *gi, const float *gv, const float *col,
                       const uint8_t *use, Py_ssize_t F, Py_ssize_t R, Py_ssize_t C, int axis,
                       const int64_t *px, Py_ssize_t reach, int64_t radius_px, double inv2h2,
                       double inv2hc2, float *or_, float *oi, double *or64, double *oi64,
                       float *ov, float *on, int workers)
    int rgbz_tofg_validity(const double *amp, const float *var, const double *depth,
                           const double *residual, const uint8_t *sat, Py_ssize_t F,
                           Py_ssize_t N, const double *sigma_scale, const double *refl_coef,
                           double min_snr, double min_amplitude, double max_sigma,
                           double max_residual, double min_reflectance, double max_range,
                           double *snr, double *sigma, double *refl, uint8_t *flags,
                           int workers)
    int rgbz_tofg_flying(const double *depth, const double *sigma, const uint8_t *usable,
                         const float *col, const float *cells, int ncells, Py_ssize_t R,
                         Py_ssize_t C, double step, double k, double contrast, double side,
                         int unflag, uint8_t *flags, double *depth_out, int workers)
    int rgbz_tofg_upsample_u8(const uint8_t *guide, Py_ssize_t H, Py_ssize_t W, double scale,
                              const double *cscale, const double *depth, const double *sigma,
                              const float *col, Py_ssize_t R, Py_ssize_t C, const double *rc,
                              const double *cc, double spacing, Py_ssize_t reach,
                              double inv2s2, double inv2hc2, double tol_k, double tol_min,
                              float *out, float *conf, int workers)
    int rgbz_tofg_upsample_u16(const uint16_t *guide, Py_ssize_t H, Py_ssize_t W, double scale,
                               const double *cscale, const double *depth, const double *sigma,
                               const float *col, Py_ssize_t R, Py_ssize_t C, const double *rc,
                               const double *cc, double spacing, Py_ssize_t reach,
                               double inv2s2, double inv2hc2, double tol_k, double tol_min,
                               float *out, float *conf, int workers)
    int rgbz_tofg_upsample_f32(const float *guide, Py_ssize_t H, Py_ssize_t W, double scale,
                               const double *cscale, const double *depth, const double *sigma,
                               const float *col, Py_ssize_t R, Py_ssize_t C, const double *rc,
                               const double *cc, double spacing, Py_ssize_t reach,
                               double inv2s2, double inv2hc2, double tol_k, double tol_min,
                               float *out, float *conf, int workers)
    int rgbz_tofg_upsample_f64(const double *guide, Py_ssize_t H, Py_ssize_t W, double scale,
                               const double *cscale, const double *depth, const double *sigma,
                               const float *col, Py_ssize_t R, Py_ssize_t C, const double *rc,
                               const double *cc, double spacing, Py_ssize_t reach,
                               double inv2s2, double inv2hc2, double tol_k, double tol_min,
                               float *out, float *conf, int workers)

ctypedef fused guide_t:
    uint8_t
    uint16_t
    float
    double


def tofg_prepare(const tap_t[:, :, ::1] taps, double gain, double black, double supp,
                 double const_var, double prnu, double white, float[:, ::1] zr,
                 float[:, ::1] zi, float[::1] v, uint8_t[::1] sat, double[:, ::1] offset,
                 int workers):
    """Taps (F, 4, N) -> phasors zr, zi (F, N), component variance v (N,), sat |= full scale,
    offset (F, N) when given."""
    cdef int status
    cdef double *of = _opt2(offset)
    cdef Py_ssize_t F = taps.shape[0], N = taps.shape[2]
    if N == 0:
        return
    with nogil:
        if tap_t is uint16_t:
            status = rgbz_tofg_prepare_u16(&taps[0, 0, 0], F, N, gain, black, supp, const_var,
                                           prnu, white, &zr[0, 0], &zi[0, 0], &v[0], &sat[0],
                                           of, workers)
        elif tap_t is float:
            status = rgbz_tofg_prepare_f32(&taps[0, 0, 0], F, N, gain, black, supp, const_var,
                                           prnu, white, &zr[0, 0], &zi[0, 0], &v[0], &sat[0],
                                           of, workers)
        else:
            status = rgbz_tofg_prepare_f64(&taps[0, 0, 0], F, N, gain, black, supp, const_var,
                                           prnu, white, &zr[0, 0], &zi[0, 0], &v[0], &sat[0],
                                           of, workers)
    _raise_for(status)


cdef float *_optf(float[:, :, ::1] a) noexcept:
    return NULL if a is None else &a[0, 0, 0]


def tofg_colour(const guide_t[:, :, ::1] guide, const int64_t[::1] row_px,
                const int64_t[::1] col_px, int block, double scale, float[:, ::1] col,
                float[:, :, ::1] cells, double[::1] lap, int workers):
    """The guide (H, W, 3) at the measurements: col (3, N), cells (block^2, 3, N) or None,
    lap (3,) the sums of |Immerkaer's Laplacian| of col."""
    cdef int status
    cdef float *cp = _optf(cells)
    cdef Py_ssize_t H = guide.shape[0], W = guide.shape[1]
    cdef Py_ssize_t R = row_px.shape[0], C = col_px.shape[0]
    if R == 0 or C == 0:
        return
    with nogil:
        if guide_t is uint8_t:
            status = rgbz_tofg_colour_u8(&guide[0, 0, 0], H, W, &row_px[0], R, &col_px[0], C,
                                         block, scale, &col[0, 0], cp, &lap[0], workers)
        elif guide_t is uint16_t:
            status = rgbz_tofg_colour_u16(&guide[0, 0, 0], H, W, &row_px[0], R, &col_px[0], C,
                                          block, scale, &col[0, 0], cp, &lap[0], workers)
        elif guide_t is float:
            status = rgbz_tofg_colour_f32(&guide[0, 0, 0], H, W, &row_px[0], R, &col_px[0], C,
                                          block, scale, &col[0, 0], cp, &lap[0], workers)
        else:
            status = rgbz_tofg_colour_f64(&guide[0, 0, 0], H, W, &row_px[0], R, &col_px[0], C,
                                          block, scale, &col[0, 0], cp, &lap[0], workers)
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
    mean goes to out_re64/out_im64 (double) when they are given, else out_re/out_im."""
    cdef int status
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
                                &out_var[0], &out_neff[0], workers)
    _raise_for(status)


def tofg_validity(const double[:, ::1] amp, const float[::1] var, const double[::1] depth,
                  const double[::1] residual, const uint8_t[::1] sat,
                  const double[::1] sigma_scale, const double[::1] refl_coef, double min_snr,
                  double min_amplitude, double max_sigma, double max_residual,
                  double min_reflectance, double max_range, double[::1] snr, double[::1] sigma,
                  double[::1] refl, uint8_t[::1] flags, int workers):
    """snr, sigma, implied reflectance and the validity bits (no flying test)."""
    cdef int status
    if depth.shape[0] == 0:
        return
    with nogil:
        status = rgbz_tofg_validity(&amp[0, 0], &var[0], &depth[0], &residual[0], &sat[0],
                                    amp.shape[0], amp.shape[1], &sigma_scale[0], &refl_coef[0],
                                    min_snr, min_amplitude, max_sigma, max_residual,
                                    min_reflectance, max_range, &snr[0], &sigma[0], &refl[0],
                                    &flags[0], workers)
    _raise_for(status)


def tofg_flying(const double[::1] depth, const double[::1] sigma, const uint8_t[::1] usable,
                const float[:, ::1] col, const float[:, :, ::1] cells, Py_ssize_t R,
                Py_ssize_t C, double step, double k, double contrast, double side, int unflag,
                uint8_t[::1] flags, double[::1] depth_out, int workers):
    """The flying-pixel test with colour edges: bits 8 (flying) and 32 (resolved) into flags,
    the resolved depths into depth_out (the measured depth elsewhere)."""
    cdef int status
    cdef const float *cp = NULL
    cdef int ncells = 1
    if cells is not None:
        cp = &cells[0, 0, 0]
        ncells = <int> cells.shape[0]
    if depth.shape[0] == 0:
        return
    with nogil:
        status = rgbz_tofg_flying(&depth[0], &sigma[0], &usable[0], &col[0, 0], cp, ncells, R, C,
                                  step, k, contrast, side, unflag, &flags[0], &depth_out[0],
                                  workers)
    _raise_for(status)


def tofg_upsample(const guide_t[:, :, ::1] guide, double scale, const double[::1] cscale,
                  const double[::1] depth, const double[::1] sigma, const float[:, ::1] col,
                  Py_ssize_t R, Py_ssize_t C, const double[::1] rc, const double[::1] cc,
                  double spacing, Py_ssize_t reach, double inv2s2, double inv2hc2,
                  double tol_k, double tol_min, float[:, ::1] out, float[:, ::1] conf,
                  int workers):
    """Joint bilateral upsampling of the measurements' depth to every pixel of the guide."""
    cdef int status
    cdef Py_ssize_t H = guide.shape[0], W = guide.shape[1]
    if H == 0 or W == 0:
        return
    with nogil:
        if guide_t is uint8_t:
            status = rgbz_tofg_upsample_u8(&guide[0, 0, 0], H, W, scale, &cscale[0], &depth[0],
                                           &sigma[0], &col[0, 0], R, C, &rc[0], &cc[0],
                                           spacing, reach, inv2s2, inv2hc2, tol_k, tol_min,
                                           &out[0, 0], &conf[0, 0], workers)
        elif guide_t is uint16_t:
            status = rgbz_tofg_upsample_u16(&guide[0, 0, 0], H, W, scale, &cscale[0], &depth[0],
                                            &sigma[0], &col[0, 0], R, C, &rc[0], &cc[0],
                                            spacing, reach, inv2s2, inv2hc2, tol_k, tol_min,
                                            &out[0, 0], &conf[0, 0], workers)
        elif guide_t is float:
            status = rgbz_tofg_upsample_f32(&guide[0, 0, 0], H, W, scale, &cscale[0], &depth[0],
                                            &sigma[0], &col[0, 0], R, C, &rc[0], &cc[0],
                                            spacing, reach, inv2s2, inv2hc2, tol_k, tol_min,
                                            &out[0, 0], &conf[0, 0], workers)
        else:
            status = rgbz_tofg_upsample_f64(&guide[0, 0, 0], H, W, scale, &cscale[0], &depth[0],
                                            &sigma[0], &col[0, 0], R, C, &rc[0], &cc[0],
                                            spacing, reach, inv2s2, inv2hc2, tol_k, tol_min,
                                            &out[0, 0], &conf[0, 0], workers)
    _raise_for(status)
