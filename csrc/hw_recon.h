/*
 * hw_recon.h -- the fixed-point streaming model of the missing-colour reconstruction
 * (precision "fixed"): the golden model a hardware team builds against.
 *
 * Paper: Rebiere et al., section 4 (eqs. 2-19); the datapath, every register's width and
 * the tables are specified in docs/guide/hardware.md. The model interprets the plans of
 * the float core (rgbz_plan, rgbz.h: which kernel pixels are candidates, which
 * differences form which gradient or semi-gradient) plus, per plan, the integer
 * constants of rgbz_hw_plan that the Python layer derives from it
 * (rgbz_fast/reconstruction/_fixed.py): one model serves every method the plans
 * describe except edi_rows, and every pattern whose row and column periods are at most
 * RGBZ_HW_MAX_PERIOD.
 *
 * Streaming: the front end of hw_stream.h (line buffers, a window, one output pixel per
 * step, the float core's border rule) with R = RGBZ_HW_RADIUS.
 *
 * Arithmetic: integers only in the per-pixel path (int64_t registers whose worst-case
 * widths the Python layer declares and checks against the configuration before a call:
 * no register can wrap). exp() of eq. 7 is a table of 2^-u, u in [0, 1), and a shift;
 * every division is a reciprocal table (nearest entry or piecewise-linear) and a multiply.
 * Memory: the line buffers and the window are fixed-size arrays of rgbz_hw_state (no
 * allocation anywhere in the model): a frame is at most RGBZ_HW_MAX_WIDTH pixels wide.
 * An HLS flow makes the state a static of its top function.
 */
#ifndef HW_RECON_H
#define HW_RECON_H

#include <stddef.h>
#include <stdint.h>
#include "rgbz.h"

enum {
    RGBZ_HW_RADIUS = 2,                 /* the 5x5 kernel of the plans */
    RGBZ_HW_MAX_WIDTH = 16384,          /* pixels per row (line buffer depth) */
    RGBZ_HW_MAX_PERIOD = 8,             /* row and column period of the pattern */
    RGBZ_HW_MAX_LB = RGBZ_HW_RADIUS + RGBZ_HW_MAX_PERIOD - 1,  /* line buffers: 9 */
    RGBZ_HW_MAX_WC = RGBZ_HW_RADIUS + RGBZ_HW_MAX_PERIOD,      /* window columns: 10 */
    RGBZ_HW_WR = 2 * RGBZ_HW_RADIUS + 1,                       /* window rows: 5 */
    RGBZ_HW_MAX_TABLE = 65537,          /* entries of a table (65536, + 1 for "pwl") */
    RGBZ_HW_PLAN_FIELDS = 11,
    RGBZ_HW_CONFIG_FIELDS = 16,
};

/* the integer constants of one plan (index: the plan's); int64 fields only, so that the
   Python dtype has no padding to agree on */
typedef struct {
    int64_t group_mult[RGBZ_NGROUPS];  /* L_f / n_g: the group sum times it is L_f times the
                                          group's mean (L_f the lcm of the counts n_g of the
                                          family's groups); 0: the group has no difference */
    int64_t fam_known[2];              /* groups with differences, per family: the
                                          semi-gradients 0..7, the gradients 8..11 */
    int64_t fam_rel[2];                /* round(sigma_rel 2^sigma_bits): the relative floor
                                          (it multiplies the family's sum: n sigma) */
    int64_t fam_floor[2];              /* max(1, round(sigma_floor n L_f 2^sigma_bits)) */
    int64_t cand_ma[RGBZ_MAX_CAND];    /* alpha_k = cand_ma 2^-(alpha_bits + cand_ea) (eq. 3) */
    int64_t cand_ea[RGBZ_MAX_CAND];
    int64_t cand_svmult[RGBZ_MAX_CAND];  /* eq. 19's sum times it: lcm / its count, or 1 */
    int64_t sv_bits;                   /* bits of eq. 19's factor (its declared width) */
    int64_t mean_mult, mean_shift;     /* floor(S / n + 1/2) =
                                          ((2 S + n) mean_mult) >> mean_shift */
    int64_t pad_;                      /* keeps the size a multiple of 16 bytes */
} rgbz_hw_plan;

/* the configuration: FixedPointConfig (rgbz_fast/reconstruction/_fixed_config.py) and the
   bit depth */
typedef struct {
    int64_t bit_depth;
    int64_t exp_pwl, exp_index_bits, exp_bits, exp_range_bits;
    int64_t recip_pwl, recip_index_bits, recip_bits;
    int64_t ratio_bits, sigma_bits, alpha_bits, weight_bits;
    int64_t cq;      /* round(sqrt(log2(e) / 2) 2^recip_bits): 1/sigma -> the scaled ratio */
    int64_t tcap;    /* the scaled ratio saturates here (y = t^2 reaches ymax) */
    int64_t ymax;    /* 2^(exp_range_bits + ratio_bits) - 1 */
    int64_t pad_;
} rgbz_hw_config;

/* the line buffers and the window registers */
typedef struct {
    uint16_t lb[RGBZ_HW_MAX_LB][RGBZ_HW_MAX_WIDTH];
    int32_t win[RGBZ_HW_WR][RGBZ_HW_MAX_WC];
} rgbz_hw_state;

/* sizeof(rgbz_hw_plan), sizeof(rgbz_hw_config), sizeof(rgbz_hw_state), and the limits above,
   so that Python can check its dtypes and allocate the state */
int rgbz_hw_layout(int64_t *out, int n);

/* What precision FIXED reads of rgbz_params (its member fixed): hw, one rgbz_hw_plan per
   plan; cfg; exp_table (2^exp_index_bits entries, + 1 with exp_pwl) and recip_table
   (likewise): the tables' contents; state: the line buffers and the window. */
typedef struct rgbz_fixed_args {
    const rgbz_hw_plan *hw;
    const rgbz_hw_config *cfg;
    const int32_t *exp_table;
    const int32_t *recip_table;
    rgbz_hw_state *state;
} rgbz_fixed_args;

/*
 * rgbz_reconstruct_fixed (rgbz.h, the entry point of precision FIXED, of the type every
 * precision shares): the fixed-point streaming reconstruction of a frame of in_type
 * RGBZ_T_U8 or RGBZ_T_U16 (rows x cols, C-contiguous; dst of the same type, fully written:
 * colour sites copied, Z sites reconstructed, clipped to [0, 2^bit_depth - 1]). phase_map,
 * plans as for every precision (methods bilinear, bi, edi_central, edi_line, sg; intensity
 * domain; no clip level, no Mask1 constant plans); params->fixed as above (the other fields
 * of params are not read: the configuration holds what they say, as integers); opcounts
 * is not read. One thread: the model streams the frame as the chip does. Returns
 * RGBZ_EINVAL for arguments the Python layer should have refused.
 */

#endif /* HW_RECON_H */
