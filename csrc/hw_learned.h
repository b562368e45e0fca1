/*
 * hw_learned.h -- the fixed-point streaming model of the learned reconstruction
 * (method "learned", precision FIXED): the golden model a hardware team builds against.
 *
 * The float kernel (learned.h) and its specification (docs/guide/learned.md) define the
 * hash and the filters; docs/guide/hardware.md specifies this datapath, every register's
 * width and the rounding. The Python layer (rgbz_fast/reconstruction/_fixed_learned.py)
 * quantises the filters' thresholds and weights into the integer constants below and
 * checks, before a call, that no register outgrows the configuration's register_bits.
 *
 * Per Z site of phase k, b-bit pixels v_t (the phase's taps), all integers:
 *   1. S_d = sum over the pairs of direction d of (v_a - v_b)^2 (exact); per colour c,
 *      S_c over the horizontal and vertical pairs of colour c;
 *   2. E_d = S_d * knorm[k][d] and E_c = S_c * kcol[k][c], knorm = round(2^N / n_d),
 *      kcol = round(2^N / n_c) (N = hash_norm_bits): the means scaled by 2^N;
 *   3. A = 4 (E_h - E_v), B = 2 (E_d1 - E_d2), T = 2 (E_h + E_v) + E_d1 + E_d2 (= 4 2^N times
 *      the float hash's a, b, t); strength = #{i: T > str_q[i]} (str_q = floor(4 2^N thr));
 *   4. the normalising shift s = max(0, bitlen(T) - hash_bits): a = A >> s, b = B >> s,
 *      t = T >> s (arithmetic shifts); the doubled-angle vector rotated by 22.5 degrees with
 *      cos_q, sin_q (const_bits fractional bits) and its octant by the float kernel's sign
 *      tests; coherence = #{i: (a^2 + b^2) << const_bits > coh_q[i] t^2}
 *      (coh_q = round(c_i^2 2^const_bits));
 *   5. spread: emax, emin of the E_c, s2 = max(0, bitlen(emax) - hash_bits),
 *      #{i: (emax >> s2) << const_bits > spr_q[i] (emin >> s2)} (spr_q = round(s_i 2^const_bits));
 *   6. bucket as in learned.h; out = (sum_t wq[k][bucket][t] v_t + 2^(F - 1)) >> F
 *      (F = tap_frac: round half up), clipped to [0, 2^b - 1].
 *
 * Streaming: the front end of hw_stream.h (line buffers, a window, one output pixel per
 * step, the float kernel's border rule) with R the filters' radius. Static buffers only: a
 * frame is at most RGBZ_HWL_MAX_WIDTH pixels wide, R <= RGBZ_LEARNED_MAX_RADIUS, P, Q <= 8.
 */
#ifndef HW_LEARNED_H
#define HW_LEARNED_H

#include <stddef.h>
#include <stdint.h>
#include "learned.h"

enum {
    RGBZ_HWL_MAX_WIDTH = 16384,                       /* pixels per row */
    RGBZ_HWL_MAX_PERIOD = 8,
    RGBZ_HWL_MAX_LB = RGBZ_LEARNED_MAX_RADIUS + RGBZ_HWL_MAX_PERIOD - 1,   /* 12 */
    RGBZ_HWL_MAX_WC = RGBZ_LEARNED_MAX_RADIUS + RGBZ_HWL_MAX_PERIOD,       /* 13 */
    RGBZ_HWL_WR = 2 * RGBZ_LEARNED_MAX_RADIUS + 1,                         /* 11 */
};

/* the scalar constants (int64 fields only: the Python dtype has no padding) */
typedef struct {
    int64_t bit_depth;
    int64_t tap_frac;       /* F: fractional bits of the quantised weights */
    int64_t hash_bits;      /* bits kept of a, b, t and of the colour energies */
    int64_t const_bits;     /* fractional bits of cos_q, sin_q, coh_q, spr_q */
    int64_t cos_q, sin_q;   /* round(cos(pi/8) 2^const_bits), round(sin(pi/8) 2^const_bits) */
    int64_t pad_[2];
} rgbz_hwl_config;

typedef struct {
    uint16_t lb[RGBZ_HWL_MAX_LB][RGBZ_HWL_MAX_WIDTH];
    int32_t win[RGBZ_HWL_WR][RGBZ_HWL_MAX_WC];
} rgbz_hwl_state;

/* what rgbz_learned_fixed reads of rgbz_learned_filters (its member fixed) */
typedef struct rgbz_learned_fixed_args {
    const rgbz_hwl_config *cfg;
    const int64_t *knorm;   /* [n_phases][4] */
    const int64_t *kcol;    /* [n_phases][3] */
    const int64_t *str_q;   /* [n_phases][n_str - 1] */
    const int64_t *coh_q;   /* [n_phases][n_coh - 1] */
    const int64_t *spr_q;   /* [n_phases][n_spr - 1] */
    const int32_t *wq;      /* [n_phases][n_buckets][n_taps_max] (bucket-major: a ROM word
                               per bucket and tap) */
    rgbz_hwl_state *state;
} rgbz_learned_fixed_args;

/* sizeof(rgbz_hwl_config), sizeof(rgbz_hwl_state), max width, max period, max radius */
int rgbz_hwl_layout(int64_t *out, int n);

/*
 * rgbz_learned_fixed (learned.h's rgbz_learned_fn): the streaming model over a uint8 or
 * uint16 frame. f: the geometry members (n_phases, n_buckets, n_taps_max, n_pairs_max,
 * n_str, n_coh, n_spr, radius, n_taps, tap_dy, tap_dx, n_pairs, pair_a, pair_b, pair_col)
 * and fixed; the float members are not read. maxval must be 2^bit_depth - 1; workers and
 * opcounts are not read (one thread: the model streams the frame as the chip does).
 */

#endif /* HW_LEARNED_H */
