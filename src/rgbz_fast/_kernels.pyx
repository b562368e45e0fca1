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

from libc.stdint cimport int32_t, int64_t, uint8_t, uint16_t, uint64_t

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
