/*
 * rgbz.h -- public C API of the rgbz-fast core (plain C99, no Python.h).
 *
 * Algorithms: missing-colour reconstruction at the Z (depth) sites of an RGB-Z
 * frame (recon.c: V. Rebiere et al., "Color pixel reconstruction for a
 * monolithic RGB-Z CMOS imager", section 4, eqs. 2-19 and Table 1; Shi et al.'s
 * row method, eqs. 1a-1e), Malvar-He-Cutler 2004 demosaicing (demosaic.c) and
 * four-tap time-of-flight demodulation with multi-frequency unwrapping (tof.c).
 *
 * Memory layout contract: every image is a C-contiguous, row-major array of
 * `rows * cols` elements; strides are `cols` elements. The caller (the Python
 * layer) validates shapes and allocates every output; the kernels never
 * allocate an output and return an rgbz_status (RGBZ_OK on success).
 *
 * The same sources build twice (csrc/meson.build): the library of the
 * extension rgbz_fast._kernels, and a counting library (-DRGBZ_COUNT_OPS) of
 * the extension rgbz_fast._kernels_count, whose arithmetic macros (rgbz_ops.h)
 * also count operations (`rgbz-fast opcount`). Both export the same names;
 * each extension links one library and exports nothing but its PyInit_*.
 *
 * The enums below are also the Python constants: _kernels.pyx declares them
 * as `cpdef enum`s, and the Python layer builds its name -> code tables
 * (METHODS, PRECISIONS, EXP_MODES, DEMOSAIC_MODES) from them.
 *
 * Element types and precisions (rgbz_templating.h): an entry point's name carries the
 * precision of its arithmetic (rgbz_reconstruct_f32); the element type of a frame is an
 * rgbz_type code beside a void pointer.
 */
#ifndef RGBZ_H
#define RGBZ_H

#include <stddef.h>
#include <stdint.h>

/* status codes */
typedef enum rgbz_status {
    RGBZ_OK = 0,
    RGBZ_EINVAL = 1,   /* an argument the Python layer should have rejected */
    RGBZ_ENOMEM = 2,   /* scratch allocation failed */
    RGBZ_EDOMAIN = 3,  /* an input value outside the kernel's domain (a ToF phase outside
                          [0, 2 pi), a non-finite phasor): the Python layer names it */
} rgbz_status;

/* element types of frames */
typedef enum rgbz_type {
    RGBZ_T_U8 = 0,
    RGBZ_T_U16 = 1,
    RGBZ_T_F32 = 2,
    RGBZ_T_F64 = 3,
} rgbz_type;

/*
 * The precisions of the reconstruction's arithmetic, X(suffix, NAME) each: the enum member
 * RGBZ_P_<NAME> (numbered in this order; the Python name is the lower-case NAME) and the
 * entry points rgbz_reconstruct_<suffix> and rgbz_learned_<suffix> declared below. A new
 * precision is one more line here plus its arithmetic (rgbz_templating.h says where).
 */
#define RGBZ_PRECISIONS(X) \
    X(f32, FLOAT32)        \
    X(f64, FLOAT64)        \
    X(fixed, FIXED)

#define RGBZ_P_MEMBER_(s, NAME) RGBZ_P_##NAME,
typedef enum rgbz_precision {
    RGBZ_PRECISIONS(RGBZ_P_MEMBER_)
    RGBZ_NPRECISIONS
} rgbz_precision;
#undef RGBZ_P_MEMBER_

/* reconstruction methods (the Python names are the lower-case suffixes) */
typedef enum rgbz_method {
    RGBZ_M_BILINEAR = 0,
    RGBZ_M_BI = 1,
    RGBZ_M_EDI_CENTRAL = 2,
    RGBZ_M_EDI_LINE = 3,
    RGBZ_M_SG = 4,
    RGBZ_M_EDI_ROWS = 5,
} rgbz_method;

/* exponential used by the gamma factors (eq. 7) */
typedef enum rgbz_exp_mode {
    RGBZ_EXP_LIBM = 0,   /* C library exp/expf: correctly rounded to ~1 ulp */
    RGBZ_EXP_FAST = 1,   /* range reduction + Taylor polynomial (rgbz_ops.h): relative error
                            below 3e-7 in float32, 1e-8 in float64 (docs/reports/tradeoff.md) */
} rgbz_exp_mode;

/* border modes of the demosaic */
typedef enum rgbz_demosaic_mode {
    RGBZ_DM_REFLECT = 0,  /* scipy.ndimage 'reflect' (half-sample mirror) */
    RGBZ_DM_PERIOD = 1,   /* shift by whole 2x2 periods: a padded pixel keeps its colour */
} rgbz_demosaic_mode;

/* demosaic methods (rgbz_demosaic, and the fused colour ISP of colour_isp.h) */
typedef enum rgbz_demosaic_method {
    RGBZ_DM_MALVAR = 0,    /* Malvar-He-Cutler 2004 */
    RGBZ_DM_BILINEAR = 1,  /* bilinear */
    RGBZ_DM_MENON = 2,     /* Menon-Andriani-Calvagno 2007 (rgbz_demosaic only: not a row pass
                              of rgbz_ci_render; the fused colour ISP runs it between
                              rgbz_ci_balance and rgbz_ci_encode_rgb) */
} rgbz_demosaic_method;

/* operation counters (Table 1 categories plus the rest); RGBZ_NOPS counts them */
typedef enum rgbz_op {
    RGBZ_OP_ADD = 0,   /* additions and subtractions */
    RGBZ_OP_MUL = 1,
    RGBZ_OP_DIV = 2,
    RGBZ_OP_EXP = 3,
    RGBZ_OP_ABS = 4,
    RGBZ_OP_CMP = 5,   /* comparisons, min, max */
    RGBZ_OP_SQRT = 6,
    RGBZ_OP_ATAN2 = 7,
} rgbz_op;

/* sizes: the counters, the arrays of one plan, the ToF limits */
enum {
    RGBZ_NOPS = 8,
    RGBZ_MAX_TAPS = 40,
    RGBZ_MAX_CAND = 24,
    RGBZ_MAX_PAIRS = 96,
    RGBZ_NGROUPS = 12,    /* 0..7 semi-gradients N S W E NW NE SW SE; 8..11 gradients V H D1 D2 */
    RGBZ_MAX_CD = 8,      /* taps of one colour-difference estimate */
    RGBZ_MAX_PAIR_GROUPS = 4,  /* groups one pair serves (the semi-gradients share theirs: 2) */
    RGBZ_TOF_MAX_FREQS = 16,
    RGBZ_TOF_MAX_WRAPS = 1024,
};

/*
 * A plan says how to reconstruct the missing pixels of one phase of the
 * pattern (one Z position in the tile). It is built and validated in Python
 * (rgbz_fast/_plans.py, whose PLAN_DTYPE mirrors this struct and is checked
 * against rgbz_plan_layout) and read here as plain data: taps are kernel
 * offsets, candidates and pairs index the taps. recon_core.template.h is the
 * one interpreter of plans; recon_mask1.h holds the Mask1 plans as compile-time
 * constants.
 */
typedef struct {
    int32_t method, n_taps, n_cand, n_pairs;
    int32_t use_ab, use_grad, use_sg, sg_scaled;
    int32_t tap_dy[RGBZ_MAX_TAPS], tap_dx[RGBZ_MAX_TAPS];
    int32_t cand_tap[RGBZ_MAX_CAND], cand_ori[RGBZ_MAX_CAND], cand_sgmask[RGBZ_MAX_CAND];
    int32_t pair_a[RGBZ_MAX_PAIRS], pair_b[RGBZ_MAX_PAIRS], pair_gmask[RGBZ_MAX_PAIRS];
    int32_t target, use_cd;
    /* colour-difference domain (eq. 5): X_k = sum_m cd_w[k][m] * v[cd_tap[k][m]] (computed as
       t0 + sum_{m >= 1} cd_w[k][m] (t_m - t0), the weights summing to 1) estimates the other
       channel(s) at candidate k (k < n_cand) and at the missing pixel (k = n_cand) */
    int32_t cd_n[RGBZ_MAX_CAND + 1], cd_tap[RGBZ_MAX_CAND + 1][RGBZ_MAX_CD];
    /* How the sums start, and which gammas are evaluated. Neither changes a result; both
       are how the two historical code paths did their arithmetic, kept so that the
       operation counts (docs/reports/opcount.md) are those of each path:
       sum_from_zero = 1 (Python plans): the group sums and the numerator of eq. 13 start
         at 0 and add every term; 0 (recon_mask1.h): they start with their first term;
       gamma_mask: the groups whose gamma (eq. 7) is evaluated. Python plans: every group
         with differences; recon_mask1.h: only those a candidate reads. */
    int32_t sum_from_zero, gamma_mask;
    double cand_alpha[RGBZ_MAX_CAND], cand_sgscale[RGBZ_MAX_CAND];
    double group_scale[RGBZ_NGROUPS];
    double cd_w[RGBZ_MAX_CAND + 1][RGBZ_MAX_CD];
} rgbz_plan;

typedef struct {
    double sigma_floor;   /* absolute floor of sigma in eq. 7, in DN */
    double sigma_rel;     /* relative floor: sigma >= sigma_rel * mean gradient of the family */
    double edge_ratio;    /* edi_rows: dominant-edge threshold */
    double maxval;        /* white level 2^b - 1: outputs are clipped to [0, maxval] */
    int32_t exp_mode;     /* an rgbz_exp_mode */
    int32_t workers;      /* threads; <= 0 means the OpenMP default */
    int32_t mask1_fast;   /* 1: the pattern has the Mask1 geometry: its interior sites run the
                             constant plans of recon_mask1.h */
    int32_t mask2_fast;   /* 1: a plan equal to one of recon_mask2.h's runs its straight-line
                             code (float32, the fast exponential; the same bits) */
    int32_t clip_on;      /* 1: known pixels >= clip_level are clipped (saturated); a
                             difference of the weights between two of them is skipped
                             (docs/guide/raw.md, "Near clipping"); with mask1_fast, the
                             sites with a clipped tap run on plans[0] (the counting build
                             needs mask1_fast = 0). */
    double clip_level;    /* in the frame's DN; read only when clip_on */
    /* precision FIXED only (NULL for the others): the fixed-point model's configuration,
       integer constants per plan, tables and line buffers (rgbz_fixed_args, hw_recon.h) */
    const struct rgbz_fixed_args *fixed;
} rgbz_params;

/* sizeof(rgbz_plan) and the offsets of its fields, in declaration order (RGBZ_PLAN_FIELDS
   numbers), so that Python can check its structured dtype against this header. */
#define RGBZ_PLAN_FIELDS 20
int rgbz_plan_layout(int64_t *out, int n);

/* The compile-time Mask1 plan that the interior sites of a Mask1 frame run for `method`
   (sg_combined: SG with the EDILine weights, sg_mode "combined"), copied to *out, so that
   the tests can compare it with the plan _plans.py builds. RGBZ_EINVAL if there is none. */
int rgbz_mask1_plan(int method, int sg_combined, rgbz_plan *out);
/* the index of *p among csrc/recon_mask2.h's plans (SG on Mask2 at any Bayer phase: the plans
   that run as straight-line code in float32 with the fast exponential), -1 for any other plan
   or in a build without that code (the counting build, a compiler other than GCC's family) */
int rgbz_mask2_plan_index(const rgbz_plan *p);
/* on = 1: recon_mask2.h's code runs its generic instance (what CPUs without AVX-512F run)
   even where its AVX-512F one would; 0: back to the CPU's; < 0: unchanged. Returns the
   setting before (-1 in a build without that code). For tests: not thread-safe against
   running reconstructions. */
int rgbz_mask2_generic(int on);

/*
 * rgbz_reconstruct_<precision> (f32, f64, fixed: one per entry of RGBZ_PRECISIONS, all of
 * this type): reconstruct the missing colour of every Z site in that precision. fixed is
 * the integer streaming model of hw_recon.h: integer frames, params->fixed, no counters
 * (its operations are counted from the plans, rgbz_fast.hardware).
 *   src, dst: rows x cols frames of element type `in_type` (an rgbz_type; dst fully
 *             written: colour sites copied, Z sites reconstructed, clipped, rounded
 *             half up for integer types). src and dst must not overlap.
 *   py, px:   pattern period; phase_map[(y % py) * px + (x % px)] is the plan
 *             index of that site, or -1 for a colour site.
 *   opcounts: counting build only: n_plans x RGBZ_NOPS counters (required there;
 *             ignored, and may be NULL, in the normal build).
 */
typedef int rgbz_reconstruct_fn(int in_type, const void *src, void *dst, ptrdiff_t rows,
                                ptrdiff_t cols, int py, int px, const int32_t *phase_map,
                                const rgbz_plan *plans, int n_plans, const rgbz_params *params,
                                uint64_t *opcounts);
#define RGBZ_DECLARE_RECONSTRUCT_(s, NAME) rgbz_reconstruct_fn rgbz_reconstruct_##s;
RGBZ_PRECISIONS(RGBZ_DECLARE_RECONSTRUCT_)
#undef RGBZ_DECLARE_RECONSTRUCT_

/*
 * Demosaic of a Bayer CFA (demosaic.c): method an rgbz_demosaic_method, Malvar-He-Cutler
 * 2004, bilinear (colour-demosaicing's demosaicing_CFA_Bayer_bilinear bit for bit) or
 * Menon 2007 (demosaic_menon.c: its demosaicing_CFA_Bayer_Menon2007 bit for bit).
 *   src rows x cols (in_type), dst rows x cols x 3 (out_type RGBZ_T_F32 or RGBZ_T_F64),
 *   phase: the 2x2 quad colours in raster order (R=0, G=1, B=2),
 *   mode: an rgbz_demosaic_mode.
 */
int rgbz_demosaic(int method, int in_type, int out_type, const void *src, void *dst,
                  ptrdiff_t rows, ptrdiff_t cols, const int32_t *phase, int mode, int workers);
/* Menon 2007 (demosaic_menon.c), which rgbz_demosaic calls with the arguments it checked */
int rgbz_demosaic_menon(int in_type, int out_type, const void *src, void *dst, ptrdiff_t rows,
                        ptrdiff_t cols, const int32_t *phase, int mode, int workers);

/* Four-tap demodulation (tof.c): taps (F, 4, N) of in_type (an rgbz_type) ->
   phase in [0, 2 pi), amplitude, offset, each (F, N) float64. */
int rgbz_tof_demodulate(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                        double *phase, double *amp, double *offset, int workers);

/* Multi-frequency unwrapping (tof.c): phase (F, N) in [0, 2 pi), frequencies (Hz), weights (F),
   max_range (m) -> depth (N, m), weighted RMS residual (N, m), wrap count of the
   base frequency (N). The search covers nwrap = max(1, ceil(max_range / A)) wraps of the
   base frequency (A = its c / (2 f)); nwrap > RGBZ_TOF_MAX_WRAPS or F > RGBZ_TOF_MAX_FREQS
   is RGBZ_EINVAL. A phase outside [0, 2 pi) (or NaN) gives RGBZ_EDOMAIN (that site's
   outputs are NaN / -1; the others are computed). */
int rgbz_tof_unwrap(const double *phase, ptrdiff_t F, ptrdiff_t N, const double *freqs,
                    const double *weights, double max_range, double *depth,
                    double *residual, int32_t *wraps, int workers);

/* Fused demodulation + unwrapping (tof.c): taps (F, 4, N) of in_type (an rgbz_type) ->
   depth, residual, wraps as rgbz_tof_unwrap, and phase, amplitude, offset (F, N) as
   rgbz_tof_demodulate (each may be NULL: not stored). One pass per site, no intermediate
   arrays. */
int rgbz_tof_depth(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                   const double *freqs, const double *weights, double max_range,
                   double *depth, double *residual, int32_t *wraps, double *phase,
                   double *amp, double *offset, int workers);

/* The same from phasors I, Q (F, N) (e.g. after the denoise): phase and amplitude (may be
   NULL), depth, residual, wraps. A non-finite I or Q gives RGBZ_EDOMAIN. */
int rgbz_tof_depth_iq(const double *i_comp, const double *q_comp, ptrdiff_t F,
                      ptrdiff_t N, const double *freqs, const double *weights,
                      double max_range, double *depth, double *residual,
                      int32_t *wraps, double *phase, double *amp, int workers);

/* The same with the planes of phase and amp ldo (>= N) apart: the rows of a larger (F, ldo)
   array (the fused guided denoise unwraps strip by strip). */
int rgbz_tof_depth_iq_strided(const double *i_comp, const double *q_comp, ptrdiff_t F,
                              ptrdiff_t N, ptrdiff_t ldo, const double *freqs,
                              const double *weights, double max_range, double *depth,
                              double *residual, int32_t *wraps, double *phase, double *amp,
                              int workers);

/* The same on the calling thread for the planes of I and Q ldi (>= N) apart and those of phase
   and amp ldo (>= N) apart (every output given): the guided denoise unwraps each output row
   from its buffer of means. Three frequencies with four wrap counts of the base one (the
   ISP's defaults) take a path of their own; the results are rgbz_tof_depth_iq's bit for bit. */
int rgbz_tof_depth_iq_row(const double *i_comp, const double *q_comp, ptrdiff_t F,
                          ptrdiff_t N, ptrdiff_t ldi, ptrdiff_t ldo, const double *freqs,
                          const double *weights, double max_range, double *depth,
                          double *residual, int32_t *wraps, double *phase, double *amp);

/* The fast exponential of rgbz_ops.h (exp_mode RGBZ_EXP_FAST) of n values, in float and
   double, so that the tests can measure it against libm. */
int rgbz_fast_exp_f32(const float *x, float *out, ptrdiff_t n);
int rgbz_fast_exp_f64(const double *x, double *out, ptrdiff_t n);

/* exp() / expf() of n values as the reconstruction computes them with exp_mode
   RGBZ_EXP_LIBM: the C library's own bits, through a vector port of glibc's algorithm
   (rgbz_exp.h) where rgbz_exp_libm_vectorised(single) says this machine's exp() (single = 0)
   or expf() (1) is that algorithm, else by calling it */
int rgbz_libm_exp_f32(const float *x, float *out, ptrdiff_t n);
int rgbz_libm_exp_f64(const double *x, double *out, ptrdiff_t n);
int rgbz_exp_libm_vectorised(int single);
/* the ports alone, value by value, for the arguments they cover (for the tests) */
int rgbz_exp_port_f32(const float *x, float *out, ptrdiff_t n);
int rgbz_exp_port_f64(const double *x, double *out, ptrdiff_t n);

/* the smallest and largest value of n floats of type (RGBZ_T_F32 or RGBZ_T_F64) in one pass
   (scan.c): a NaN makes the range not finite */
int rgbz_float_range(int type, const void *data, ptrdiff_t n, double *lo, double *hi);
/* one pass over n >= 1 measurement sites (rows[i], cols[i]) (scan.c): lo_hi = {smallest row,
   largest row, smallest column, largest column}; *ordered = 1 when they are in strictly
   increasing row-major order (so no site is given twice) */
int rgbz_sites_range(const int64_t *rows, const int64_t *cols, ptrdiff_t n, int64_t lo_hi[4],
                     int *ordered);
/* *first = the index of the first site whose block x block cells are not all Z sites of a
   P x Q tile of Z flags repeated over the frame, or -1 (scan.c); sites in [0, 2^31 - 2] */
int rgbz_sites_off_z(const int64_t *rows, const int64_t *cols, ptrdiff_t n, int block,
                     const uint8_t *tile_z, int P, int Q, ptrdiff_t *first);

/* build information */
int rgbz_have_openmp(void);
int rgbz_max_threads(void);
/* before a fork: the calling thread's OpenMP threads ended, 0 (or an OpenMP error code) */
int rgbz_openmp_release(void);
int rgbz_counting_build(void);
/* counting build: the RGBZ_NOPS counters that the ToF kernels add to (single thread);
   a no-op in the normal build */
int rgbz_opcount_target(uint64_t *counts);

#endif /* RGBZ_H */
