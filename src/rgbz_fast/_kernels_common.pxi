# The part of the bridge that both extensions hold (src/rgbz_fast/meson.build): _kernels.pyx
# and _kernels_count.pyx include it. It declares the C core's API (csrc/rgbz.h, learned.h),
# takes the Python constants from its enums, and bridges the kernels that the counting build
# counts (reconstruct, learned, z_guided, tof_demodulate) and the build queries.

from libc.stdint cimport int8_t, int32_t, int64_t, uint8_t, uint16_t, uint64_t

# what the entry point of precision fixed reads of rgbz_params (csrc/hw_recon.h)
cdef extern from "hw_recon.h" nogil:
    ctypedef struct rgbz_hw_plan:
        pass
    ctypedef struct rgbz_hw_config:
        pass
    ctypedef struct rgbz_hw_state:
        pass
    ctypedef struct rgbz_fixed_args:
        const rgbz_hw_plan *hw
        const rgbz_hw_config *cfg
        const int32_t *exp_table
        const int32_t *recip_table
        rgbz_hw_state *state
    int rgbz_hw_layout(int64_t *out, int n)

# what the learned filters' entry point of precision fixed reads (csrc/hw_learned.h)
cdef extern from "hw_learned.h" nogil:
    ctypedef struct rgbz_hwl_config:
        pass
    ctypedef struct rgbz_hwl_state:
        pass
    ctypedef struct rgbz_learned_fixed_args:
        const rgbz_hwl_config *cfg
        const int64_t *knorm
        const int64_t *kcol
        const int64_t *str_q
        const int64_t *coh_q
        const int64_t *spr_q
        const int32_t *wq
        rgbz_hwl_state *state
    int rgbz_hwl_layout(int64_t *out, int n)

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
        RGBZ_P_FIXED
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
    cpdef enum rgbz_demosaic_method:
        RGBZ_DM_MALVAR
        RGBZ_DM_BILINEAR
        RGBZ_DM_MENON
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
        int32_t mask2_fast
        int32_t clip_on
        double clip_level
        const rgbz_fixed_args *fixed
    int rgbz_plan_layout(int64_t *out, int n)
    int rgbz_mask1_plan(int method, int sg_combined, rgbz_plan *out)
    int rgbz_mask2_plan_index(const rgbz_plan *p)
    int rgbz_mask2_generic(int on)
    # one entry point per precision, all of this type (csrc/rgbz_templating.h)
    ctypedef int rgbz_reconstruct_fn(int in_type, const void *src, void *dst, Py_ssize_t rows,
                                     Py_ssize_t cols, int py, int px, const int32_t *phase_map,
                                     const rgbz_plan *plans, int n_plans,
                                     const rgbz_params *params, uint64_t *opcounts) noexcept
    rgbz_reconstruct_fn rgbz_reconstruct_f32
    rgbz_reconstruct_fn rgbz_reconstruct_f64
    rgbz_reconstruct_fn rgbz_reconstruct_fixed
    int rgbz_fast_exp_f32(const float *x, float *out, Py_ssize_t n)
    int rgbz_fast_exp_f64(const double *x, double *out, Py_ssize_t n)
    int rgbz_libm_exp_f32(const float *x, float *out, Py_ssize_t n)
    int rgbz_libm_exp_f64(const double *x, double *out, Py_ssize_t n)
    int rgbz_exp_libm_vectorised(int single)
    int rgbz_exp_port_f32(const float *x, float *out, Py_ssize_t n)
    int rgbz_exp_port_f64(const double *x, double *out, Py_ssize_t n)
    int rgbz_float_range(int type, const void *data, Py_ssize_t n, double *lo, double *hi)
    int rgbz_sites_range(const int64_t *rows, const int64_t *cols, Py_ssize_t n,
                         int64_t *lo_hi, int *ordered)
    int rgbz_sites_off_z(const int64_t *rows, const int64_t *cols, Py_ssize_t n, int block,
                         const uint8_t *tile_z, int P, int Q, Py_ssize_t *first)
    int rgbz_demosaic(int method, int in_type, int out_type, const void *src, void *dst,
                      Py_ssize_t rows, Py_ssize_t cols, const int32_t *phase, int mode,
                      int workers)
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
    int rgbz_openmp_release()
    int rgbz_counting_build()
    int rgbz_opcount_target(uint64_t *counts)

cdef extern from "learned.h" nogil:
    ctypedef struct rgbz_learned_filters:
        int32_t n_phases, n_buckets, n_taps_max, n_pairs_max, n_str, n_coh, n_spr, radius
        int32_t hash_radius
        const int32_t *n_taps
        const int32_t *tap_dy
        const int32_t *tap_dx
        const int32_t *n_pairs
        const int32_t *pair_a
        const int32_t *pair_b
        const int32_t *pair_col
        const double *inv_col
        const int32_t *bayer
        const double *str_thr
        const double *coh_thr2
        const double *spr_thr
        const float *w_f32
        const double *w_f64
        const float *wd_f32
        const double *wd_f64
        const rgbz_learned_fixed_args *fixed
    ctypedef int rgbz_learned_fn(int in_type, const void *src, void *dst, Py_ssize_t rows,
                                 Py_ssize_t cols, int py, int px, const int32_t *phase_map,
                                 const rgbz_learned_filters *f, double maxval, int workers,
                                 uint64_t *opcounts) noexcept
    rgbz_learned_fn rgbz_learned_f32
    rgbz_learned_fn rgbz_learned_f64
    rgbz_learned_fn rgbz_learned_fixed
ctypedef fused frame_t:
    uint8_t
    uint16_t
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
TYPES = _codes(rgbz_type, "RGBZ_T_")
EXP_MODES = _codes(rgbz_exp_mode, "RGBZ_EXP_")
DEMOSAIC_MODES = _codes(rgbz_demosaic_mode, "RGBZ_DM_")
#: the demosaic methods of demosaic_kernel: {name: code}; ci_render (the fused colour ISP)
#: takes malvar2004 and bilinear
DEMOSAIC_KERNELS = {"malvar2004": RGBZ_DM_MALVAR, "bilinear": RGBZ_DM_BILINEAR,
                    "menon2007": RGBZ_DM_MENON}
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


cdef extern from "z_guided.h" nogil:
    ctypedef struct rgbz_zguided_filters:
        const rgbz_learned_filters *hash
        int32_t n_levels
        const float *w_f32
        const double *w_f64
        const float *wd_f32
        const double *wd_f64
        const float *g_f32
        const double *g_f64
        int32_t n_base_max
        const int32_t *n_base
        const int32_t *base_idx
        Py_ssize_t gy, gx
        const double *grid
        const double *var
        const void *taps
        const int64_t *site_rows
        const int64_t *site_cols
        int taps_type
        Py_ssize_t taps_F, gyc, gxc
        const double *ratio
        const int8_t *chan
        int32_t zr, zc, block
        const int32_t *targets
        double lam
        const double *thr
    ctypedef int rgbz_zguided_fn(int in_type, const void *src, void *dst, Py_ssize_t rows,
                                 Py_ssize_t cols, int py, int px, const int32_t *phase_map,
                                 const rgbz_zguided_filters *f, double maxval, int workers,
                                 uint64_t *opcounts) noexcept
    rgbz_zguided_fn rgbz_zguided_f32
    rgbz_zguided_fn rgbz_zguided_f64
    int RGBZ_ZG_SITES
    int rgbz_zguided_guide(int in_type, const void *taps, Py_ssize_t F, Py_ssize_t N,
                           const int64_t *site_rows, const int64_t *site_cols, int py, int px,
                           int zr, int zc, Py_ssize_t gy, Py_ssize_t gx, Py_ssize_t gyc,
                           Py_ssize_t gxc, double *grid, double *var, int workers)
    int rgbz_zguided_ratios(int in_type, const void *taps, Py_ssize_t F, Py_ssize_t N,
                            const int64_t *site_rows, const int64_t *site_cols, int py,
                            int px, int zr, int zc, Py_ssize_t gyc, Py_ssize_t gxc,
                            double *ratio, int check, int workers)


ctypedef struct _precision_kernels:
    rgbz_reconstruct_fn *reconstruct
    rgbz_learned_fn *learned
    rgbz_zguided_fn *zguided


cdef _precision_kernels _kernels_of(int precision) except *:
    """The entry points of a precision (RGBZ_PRECISIONS, csrc/rgbz.h), NULL where it has no
    such kernel: the one switch over the precisions."""
    cdef _precision_kernels k
    if precision == RGBZ_P_FLOAT32:
        k.reconstruct, k.learned = rgbz_reconstruct_f32, rgbz_learned_f32
        k.zguided = rgbz_zguided_f32
    elif precision == RGBZ_P_FLOAT64:
        k.reconstruct, k.learned = rgbz_reconstruct_f64, rgbz_learned_f64
        k.zguided = rgbz_zguided_f64
    elif precision == RGBZ_P_FIXED:
        # the integer streaming models (hw_recon.h, hw_learned.h): no z_guided one, and
        # nothing the counting build counts (their operations are rgbz_fast.hardware's, from
        # the plans and filters)
        k.reconstruct, k.learned = rgbz_reconstruct_fixed, rgbz_learned_fixed
        k.zguided = NULL
        if rgbz_counting_build():
            k.reconstruct, k.learned = NULL, NULL
    else:
        raise ValueError(f"precision: expected a code of PRECISIONS {PRECISIONS}, "
                         f"got {precision}")
    return k


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


def mask2_plan_index(const uint8_t[::1] plan):
    """The index of a plan (its bytes) among csrc/recon_mask2.h's, whose sites run as
    straight-line code (float32, exp_mode fast), or -1."""
    if plan.shape[0] != sizeof(rgbz_plan):
        raise ValueError(f"plan: expected {sizeof(rgbz_plan)} bytes, got {plan.shape[0]}")
    return int(rgbz_mask2_plan_index(<const rgbz_plan *> &plan[0]))


def mask2_generic(int on=-1):
    """SG Mask2's straight-line code on its generic instance (``on=1``: what CPUs without
    AVX-512F run) or the CPU's (``0``); ``-1`` leaves it. Returns the setting before, -1 in a
    build without that code. For tests; not to be changed while reconstructions run."""
    return int(rgbz_mask2_generic(on))


def have_openmp():
    return bool(rgbz_have_openmp())


def max_threads():
    return int(rgbz_max_threads())


def openmp_release():
    """End the calling thread's OpenMP threads (started again at the next parallel region);
    0, or OpenMP's error code. Run before every fork (rgbz_fast._kernels registers it)."""
    return int(rgbz_openmp_release())


def counting_build():
    """True in rgbz_fast._kernels_count, the module built with -DRGBZ_COUNT_OPS."""
    return bool(rgbz_counting_build())


def reconstruct(const frame_t[:, ::1] src, frame_t[:, ::1] dst, int precision,
                int py, int px, const int32_t[::1] phase_map, const uint8_t[::1] plans,
                int n_plans, double sigma_floor, double sigma_rel, double edge_ratio, double maxval,
                int exp_mode, int workers, uint64_t[::1] opcounts=None, int mask1_fast=0,
                clip_level=None, int mask2_fast=0):
    """Run the reconstruction kernel.

    ``opcounts`` (n_plans x NOPS counters): required by the counting module
    (``_kernels_count``, single thread), refused by ``_kernels``.
    ``clip_level`` (DN, or None): known pixels at or above it are clipped; with
    ``mask1_fast=1`` the sites with a clipped tap run on the plan given (the counting
    module needs ``mask1_fast=0``). ``mask2_fast=1``: a plan equal byte for byte to one of
    csrc/recon_mask2.h's runs its straight-line code (float32, exp_mode fast; the same bits).
    """
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int status
    cdef rgbz_params prm
    cdef rgbz_reconstruct_fn *kernel = _kernels_of(precision).reconstruct
    cdef uint64_t *counts = _counters(opcounts, <Py_ssize_t> n_plans * RGBZ_NOPS)
    if precision == RGBZ_P_FIXED:
        raise ValueError("precision: the fixed-point model runs through reconstruct_fixed "
                         "(its tables and line buffers)")
    prm.sigma_floor = sigma_floor
    prm.sigma_rel = sigma_rel
    prm.edge_ratio = edge_ratio
    prm.maxval = maxval
    prm.exp_mode = exp_mode
    prm.workers = 1 if counts != NULL else workers
    prm.mask1_fast = mask1_fast
    prm.mask2_fast = mask2_fast
    prm.clip_on = 0 if clip_level is None else 1
    prm.clip_level = 0.0 if clip_level is None else float(clip_level)
    prm.fixed = NULL
    with nogil:
        status = kernel(in_type, &src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py, px,
                        &phase_map[0], <const rgbz_plan *> &plans[0], n_plans, &prm, counts)
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


# ---------------------------------------------------------------------- learned (learned.c)
def learned(const frame_t[:, ::1] src, frame_t[:, ::1] dst, int precision, int py, int px,
            const int32_t[::1] phase_map, const int32_t[::1] n_taps,
            const int32_t[:, ::1] tap_dy, const int32_t[:, ::1] tap_dx,
            const int32_t[:, ::1] n_pairs, const int32_t[:, :, ::1] pair_a,
            const int32_t[:, :, ::1] pair_b, const int32_t[:, :, ::1] pair_col,
            const double[:, ::1] inv_col, const int32_t[::1] bayer,
            const double[:, ::1] str_thr, const double[:, ::1] coh_thr2,
            const double[:, ::1] spr_thr, const float[:, :, ::1] w_f32,
            const double[:, :, ::1] w_f64, int radius, int hash_radius, double maxval,
            int workers, const float[:, :, :, ::1] wd_f32=None,
            const double[:, :, :, ::1] wd_f64=None, uint64_t[::1] opcounts=None):
    """Run the learned reconstruction. ``opcounts`` (n_phases x NOPS counters): required by
    the counting module (``_kernels_count``, single thread), refused by ``_kernels``.

    Weights are tap-major, (n_phases, n_taps_max, n_buckets); thresholds
    (n_phases, levels - 1), the coherence ones squared; ``pair_col`` the colour of each
    pair, ``inv_col`` (n_phases, 3) one over the pairs of each colour, ``bayer`` the colours
    of the 2x2 Bayer tile at the frame's origin (row-major); the optional dense weights
    (n_phases, n_buckets, 2 radius + 1, 8) enable the fast path (the layout of learned.h).
    """
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef int status
    cdef rgbz_learned_filters f
    cdef rgbz_learned_fn *kernel = _kernels_of(precision).learned
    cdef double zero = 0.0
    if kernel == NULL or precision == RGBZ_P_FIXED:
        # precision fixed runs through learned_fixed, which hands over its integer constants
        raise ValueError(f"precision: the learned filters have no kernel of precision code "
                         f"{precision} here")
    f.n_phases = w_f32.shape[0]
    f.n_taps_max = w_f32.shape[1]
    f.n_buckets = w_f32.shape[2]
    f.n_pairs_max = pair_a.shape[2]
    f.n_str = str_thr.shape[1] + 1
    f.n_coh = coh_thr2.shape[1] + 1
    f.n_spr = spr_thr.shape[1] + 1
    f.radius = radius
    f.hash_radius = hash_radius
    f.n_taps = &n_taps[0]
    f.tap_dy = &tap_dy[0, 0]
    f.tap_dx = &tap_dx[0, 0]
    f.n_pairs = &n_pairs[0, 0]
    f.pair_a = &pair_a[0, 0, 0]
    f.pair_b = &pair_b[0, 0, 0]
    f.pair_col = &pair_col[0, 0, 0]
    f.inv_col = &inv_col[0, 0]
    f.bayer = &bayer[0]
    # a level count of 1 has no threshold: the kernel reads none
    f.str_thr = &str_thr[0, 0] if str_thr.shape[1] else &zero
    f.coh_thr2 = &coh_thr2[0, 0] if coh_thr2.shape[1] else &zero
    f.spr_thr = &spr_thr[0, 0] if spr_thr.shape[1] else &zero
    f.w_f32 = &w_f32[0, 0, 0]
    f.w_f64 = &w_f64[0, 0, 0]
    f.wd_f32 = NULL
    f.wd_f64 = NULL
    f.fixed = NULL
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
            or tap_dx.shape[1] != f.n_taps_max or pair_b.shape[2] != f.n_pairs_max
            or pair_col.shape[0] != f.n_phases or pair_col.shape[2] != f.n_pairs_max
            or inv_col.shape[0] != f.n_phases or inv_col.shape[1] != 3
            or bayer.shape[0] != 4 or spr_thr.shape[0] != f.n_phases):
        raise ValueError("learned: inconsistent filter arrays")
    cdef uint64_t *counts = _counters(opcounts, <Py_ssize_t> f.n_phases * RGBZ_NOPS)
    with nogil:
        status = kernel(in_type, &src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py, px,
                        &phase_map[0], &f, maxval, workers, counts)
    _raise_for(status)


# ---------------------------------------------------------------------- z_guided (z_guided.c)
def z_guided(const frame_t[:, ::1] src, frame_t[:, ::1] dst, int precision, int py, int px,
             const int32_t[::1] phase_map, const int32_t[::1] n_taps,
             const int32_t[:, ::1] tap_dy, const int32_t[:, ::1] tap_dx,
             const int32_t[:, ::1] n_pairs, const int32_t[:, :, ::1] pair_a,
             const int32_t[:, :, ::1] pair_b, const int32_t[:, :, ::1] pair_col,
             const double[:, ::1] inv_col, const double[:, ::1] str_thr,
             const double[:, ::1] coh_thr2, const double[:, ::1] spr_thr, int radius,
             int hash_radius, const float[:, :, ::1] w_f32, const double[:, :, ::1] w_f64,
             const float[:, :, ::1] g_f32, const double[:, :, ::1] g_f64,
             const int32_t[::1] n_base, const int32_t[:, ::1] base_idx,
             const double[:, ::1] grid, const double[:, ::1] var, const int8_t[::1] chan,
             int zr, int zc, int block, const int32_t[::1] targets, double lam,
             const double[::1] thr, double maxval, int workers,
             const float[:, :, :, ::1] wd_f32=None, const double[:, :, :, ::1] wd_f64=None,
             const int32_t[::1] bayer=None, uint64_t[::1] opcounts=None,
             const uint8_t[::1] taps=None, int taps_type=0, Py_ssize_t taps_F=0,
             Py_ssize_t gy=0, Py_ssize_t gx=0, Py_ssize_t gyc=0, Py_ssize_t gxc=0,
             const double[::1] ratio=None, const int64_t[::1] site_rows=None,
             const int64_t[::1] site_cols=None):
    """Run the z_guided reconstruction (csrc/z_guided.h). The hash arrays are those of
    ``learned`` (LearnedFilters.kernel_arrays of the base filters); colour weights tap-major
    (n_phases, n_taps_max, n_levels * n_buckets), guide weights (n_phases, n_levels *
    n_buckets, 11), the baseline taps (n_phases,) and (n_phases, n_base_max); the guide: the
    amplitude grid and its variance (gy, gx), the colour codes of the tile (py * px), the Z
    pixel's corner and size, the target colour of each phase, the regularisation and the
    n_levels - 1 noise thresholds; the optional dense colour weights (n_phases, n_levels *
    n_buckets, 2 radius + 1, 8) and the Bayer tile (as for ``learned``) enable the fast path.
    ``opcounts``: as for ``learned``. With ``grid`` and ``var`` None, the guide from the ToF
    taps instead: ``taps`` their bytes ((taps_F, 4, gyc * gxc) elements of type code
    ``taps_type``, TYPES), ``ratio`` their medians (z_guided_ratios), the grid's shape
    (gy, gx) and its complete part (gyc, gxc), ``site_rows`` and ``site_cols`` their sites.
    True when done; False (from the taps only) when the sites are not the complete Z pixels
    in row-major order (``dst`` then holds nothing meaningful)."""
    cdef int status
    cdef rgbz_learned_filters h
    cdef rgbz_zguided_filters f
    cdef double zero = 0.0
    cdef Py_ssize_t n_ph = w_f32.shape[0]
    cdef int in_type = _type_code(<frame_t *> NULL)
    cdef rgbz_zguided_fn *kernel = _kernels_of(precision).zguided
    if kernel == NULL:
        raise ValueError(f"precision: z_guided has no kernel in precision code {precision}")
    if (n_taps.shape[0] != n_ph or tap_dy.shape[0] != n_ph or tap_dx.shape[0] != n_ph
            or n_pairs.shape[0] != n_ph or n_pairs.shape[1] != 4 or pair_a.shape[0] != n_ph
            or pair_b.shape[0] != n_ph or pair_a.shape[1] != 4 or pair_b.shape[1] != 4
            or pair_b.shape[2] != pair_a.shape[2] or pair_col.shape[0] != n_ph
            or pair_col.shape[1] != 4 or pair_col.shape[2] != pair_a.shape[2]
            or inv_col.shape[0] != n_ph or inv_col.shape[1] != 3 or spr_thr.shape[0] != n_ph
            or tap_dy.shape[1] != w_f32.shape[1]
            or tap_dx.shape[1] != w_f32.shape[1] or str_thr.shape[0] != n_ph
            or coh_thr2.shape[0] != n_ph or w_f64.shape[0] != n_ph
            or w_f64.shape[1] != w_f32.shape[1] or w_f64.shape[2] != w_f32.shape[2]
            or g_f32.shape[0] != n_ph or g_f64.shape[0] != n_ph
            or g_f32.shape[1] != w_f32.shape[2] or g_f64.shape[1] != w_f32.shape[2]
            or g_f32.shape[2] != 11 or g_f64.shape[2] != 11 or n_base.shape[0] != n_ph
            or base_idx.shape[0] != n_ph or targets.shape[0] != n_ph
            or (grid is None) != (var is None)
            or (grid is not None and (var.shape[0] != grid.shape[0]
                                      or var.shape[1] != grid.shape[1]))
            or chan.shape[0] != py * px
            or dst.shape[0] != src.shape[0] or dst.shape[1] != src.shape[1]
            or phase_map.shape[0] != py * px):
        raise ValueError("z_guided: inconsistent filter arrays")
    h.n_phases = n_ph
    h.n_taps_max = w_f32.shape[1]
    h.n_str = str_thr.shape[1] + 1
    h.n_coh = coh_thr2.shape[1] + 1
    h.n_spr = spr_thr.shape[1] + 1
    h.n_buckets = 8 * h.n_str * h.n_coh * h.n_spr
    if w_f32.shape[2] % h.n_buckets or thr.shape[0] + 1 != w_f32.shape[2] // h.n_buckets:
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
    h.pair_col = &pair_col[0, 0, 0]
    h.inv_col = &inv_col[0, 0]
    h.bayer = NULL
    if bayer is not None:
        if bayer.shape[0] != 4:
            raise ValueError("z_guided: inconsistent filter arrays")
        h.bayer = &bayer[0]
    # a level count of 1 has no threshold: the kernel reads none
    h.str_thr = &str_thr[0, 0] if str_thr.shape[1] else &zero
    h.coh_thr2 = &coh_thr2[0, 0] if coh_thr2.shape[1] else &zero
    h.spr_thr = &spr_thr[0, 0] if spr_thr.shape[1] else &zero
    h.w_f32 = NULL
    h.w_f64 = NULL
    h.wd_f32 = NULL
    h.wd_f64 = NULL
    h.fixed = NULL
    f.hash = &h
    f.n_levels = w_f32.shape[2] // h.n_buckets
    f.w_f32 = &w_f32[0, 0, 0]
    f.w_f64 = &w_f64[0, 0, 0]
    f.g_f32 = &g_f32[0, 0, 0]
    f.g_f64 = &g_f64[0, 0, 0]
    f.wd_f32 = NULL
    f.wd_f64 = NULL
    if wd_f32 is not None and wd_f64 is not None:
        if (wd_f32.shape[0] != n_ph or wd_f32.shape[1] != w_f32.shape[2]
                or wd_f32.shape[2] != 2 * radius + 1 or wd_f32.shape[3] != 8
                or wd_f64.shape[0] != n_ph or wd_f64.shape[1] != w_f32.shape[2]
                or wd_f64.shape[2] != 2 * radius + 1 or wd_f64.shape[3] != 8):
            raise ValueError("z_guided: inconsistent dense weights")
        f.wd_f32 = &wd_f32[0, 0, 0, 0]
        f.wd_f64 = &wd_f64[0, 0, 0, 0]
    f.n_base_max = base_idx.shape[1]
    f.n_base = &n_base[0]
    f.base_idx = &base_idx[0, 0]
    f.grid = NULL
    f.var = NULL
    f.taps = NULL
    f.ratio = NULL
    f.taps_type = taps_type
    f.taps_F = taps_F
    f.gyc = gyc
    f.gxc = gxc
    if grid is not None:
        f.gy = grid.shape[0]
        f.gx = grid.shape[1]
        f.grid = &grid[0, 0]
        f.var = &var[0, 0]
    else:
        if (taps is None or ratio is None or ratio.shape[0] != taps_F or gyc < 1 or gxc < 1
                or site_rows is None or site_cols is None
                or site_rows.shape[0] != gyc * gxc or site_cols.shape[0] != gyc * gxc
                or gy < gyc or gx < gxc or taps_type not in TYPES.values()
                or taps.shape[0] != taps_F * 4 * gyc * gxc * _TYPE_SIZES[taps_type]):
            raise ValueError("z_guided: inconsistent guide arrays")
        f.gy = gy
        f.gx = gx
        f.taps = &taps[0]
        f.ratio = &ratio[0]
        f.site_rows = &site_rows[0]
        f.site_cols = &site_cols[0]
    f.chan = &chan[0]
    f.zr = zr
    f.zc = zc
    f.block = block
    f.targets = &targets[0]
    f.lam = lam
    f.thr = &thr[0] if thr.shape[0] else &zero
    cdef uint64_t *counts = _counters(opcounts, n_ph * RGBZ_NOPS)
    with nogil:
        status = kernel(in_type, &src[0, 0], &dst[0, 0], src.shape[0], src.shape[1], py, px,
                        &phase_map[0], &f, maxval, workers, counts)
    if status == RGBZ_ZG_SITES and grid is None:
        return False
    _raise_for(status)
    return True


_TYPE_SIZES = {TYPES["u8"]: 1, TYPES["u16"]: 2, TYPES["f32"]: 4, TYPES["f64"]: 8}


def z_guided_ratios(const frame_t[:, :, ::1] taps, const int64_t[::1] site_rows,
                    const int64_t[::1] site_cols, int py, int px, int zr, int zc,
                    Py_ssize_t gyc, Py_ssize_t gxc, double[::1] ratio, int check, int workers):
    """The medians of the guide of z_guided (csrc/z_guided.h, rgbz_zguided_ratios) from ToF
    taps (F, 4, N) into ``ratio`` (F,). True when done; False when the sites are not the
    gyc x gxc complete Z pixels in row-major order (checked only when ``check``)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    if (site_rows.shape[0] != taps.shape[2] or site_cols.shape[0] != taps.shape[2]
            or taps.shape[1] != 4 or ratio.shape[0] != taps.shape[0] or taps.shape[2] == 0):
        raise ValueError("z_guided_ratios: inconsistent arrays")
    with nogil:
        status = rgbz_zguided_ratios(in_type, &taps[0, 0, 0], taps.shape[0], taps.shape[2],
                                     &site_rows[0], &site_cols[0], py, px, zr, zc, gyc, gxc,
                                     &ratio[0], check, workers)
    if status == RGBZ_ZG_SITES:
        return False
    _raise_for(status)
    return True


def z_guided_guide(const frame_t[:, :, ::1] taps, const int64_t[::1] site_rows,
                   const int64_t[::1] site_cols, int py, int px, int zr, int zc,
                   Py_ssize_t gyc, Py_ssize_t gxc, double[:, ::1] grid, double[:, ::1] var,
                   int workers):
    """The guide of z_guided from ToF taps (F, 4, N) (csrc/z_guided.h, rgbz_zguided_guide):
    the mean amplitude and its noise variance of the gyc x gxc complete Z pixels into
    ``grid`` and ``var`` (gy, gx). True when done; False when the sites are not those Z
    pixels in row-major order (nothing is then meaningful in the grids)."""
    cdef int status
    cdef int in_type = _type_code(<frame_t *> NULL)
    if (site_rows.shape[0] != taps.shape[2] or site_cols.shape[0] != taps.shape[2]
            or taps.shape[1] != 4 or var.shape[0] != grid.shape[0]
            or var.shape[1] != grid.shape[1] or taps.shape[2] == 0):
        raise ValueError("z_guided_guide: inconsistent arrays")
    with nogil:
        status = rgbz_zguided_guide(in_type, &taps[0, 0, 0], taps.shape[0], taps.shape[2],
                                    &site_rows[0], &site_cols[0], py, px, zr, zc,
                                    grid.shape[0], grid.shape[1], gyc, gxc, &grid[0, 0],
                                    &var[0, 0], workers)
    if status == RGBZ_ZG_SITES:
        return False
    _raise_for(status)
    return True
