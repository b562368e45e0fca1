/*
 * tof_filter.h -- the edge-aware (bilateral) phasor mean of the ToF ISP (tof_filter.c).
 * Plain C99, no Python.h; status codes of rgbz.h.
 */
#ifndef RGBZ_TOF_FILTER_H
#define RGBZ_TOF_FILTER_H

#include <stddef.h>
#include <stdint.h>

int rgbz_tof_bilateral(const double *z_re, const double *z_im, const double *var,
                       const double *g_re, const double *g_im, const double *g_var,
                       const uint8_t *use, const int64_t *row_px, const int64_t *col_px,
                       ptrdiff_t nfreq, ptrdiff_t rows, ptrdiff_t cols,
                       ptrdiff_t reach_rows, ptrdiff_t reach_cols, int64_t radius_px, double inv_h2,
                       double *out_re, double *out_im, double *out_var, double *out_neff,
                       int workers);

/* The paper's box mean (rgbz_fast.tof.denoise_phasors) on the grid of the Z measurements
   (R x C cells, row-major; row_px, col_px the pixel coordinates of the grid lines): for every
   plane p < P, in[p] and out[p] (R*C each),
       tmp[r][c] = 0 + sum over a in row_offs (in order, 0 <= r + a < R) of
                   v[r + a][c] * (|row_px[r + a] - row_px[r]| <= radius ? 1 : 0),
       sum[r][c] = 0 + the same over b in col_offs along the row, of tmp,
       out[p][r][c] = sum[r][c] * (count > 0 ? 1 / count : 0),
   with v = in[p] * weight (weight NULL: v = in[p]) and count[r][c] the same sums of weight
   (of 1 without one). The operations of the NumPy code it replaced, in its order
   (tests/_reference/tof.py, denoise_phasors), so the same bits, NaN and inf included. */
int rgbz_tof_box(const double *const *in, double *const *out, ptrdiff_t P, ptrdiff_t R,
                 ptrdiff_t C, const int64_t *row_px, const int64_t *col_px,
                 const int64_t *row_offs, ptrdiff_t n_row_offs, const int64_t *col_offs,
                 ptrdiff_t n_col_offs, int64_t radius, const double *weight, double *count,
                 int workers);

/* I = A0 - A2, Q = A3 - A1 and offset = 0.25 ((A0 + A1) + (A2 + A3)) of taps (F, 4, N) of
   in_type (an rgbz_type; the rgbz_fast.tof._stages._phasors_offset NumPy operations: each
   tap converted to double first), into i, q, offset (F, N) */
int rgbz_tof_phasors_offset(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N, double *i,
                            double *q, double *offset, int workers);

/* The variance the ToF ISP gives a phasor component (rgbz_fast.tof._noise.tap_variance,
   its NumPy operations in their order): for x = offset[n] (n < N),
       h = max(x - black, 0) (NaN stays NaN),  v = h k,  v /= supp (supp != 0),
       v += readout,  v += 1/12,  v += (h prnu)^2 (prnu != 0),
       out[n] = (scale v) / max(count[n], 1) (count NULL: scale v). */
int rgbz_tof_tap_variance(const double *offset, ptrdiff_t N, double black, double k,
                          double supp, double readout, double prnu, double scale,
                          const double *count, ptrdiff_t count_period, double *out,
                          int workers);

/* The unguided ToF ISP's validity (rgbz_fast.tof._validity.validity): for every measurement
   n, from amp and var (F, N) (the per-frequency amplitude and component variance), depth,
   residual (N,) and saturated (N,):
     snr[n]   = min_f 2 amp / sqrt(var) (NaN if one is NaN),
     sigma[n] = sqrt(t), t = sum_f sigma_scale[f] fmin(var / (4 amp^2), phase_var_cap), and
                with delta given, t + delta[n] instead where no frequency reached the cap
                and t + delta[n] > 0,
     refl[n]  = mean_f amp / (refl_coef[f] s1 block^2) where depth > 0, else 0, with
                s1 = power / (4 d d tan_h tan_v) * k_cell (d = depth, 1 where depth <= 0),
     flags[n] = 1 saturated | 2 low signal (snr < min_snr, an amplitude < min_amplitude, or
                not sigma <= max_sigma when max_sigma >= 0) | 4 residual > max_residual |
                16 out of range (depth < 0, depth > max_range - 5 sigma, refl <
                min_reflectance or refl > max_reflectance: an aliased depth); the flying
                bit (8) is not set here.
   Each in the order of the NumPy operations it replaces, so the same bits. */
typedef struct {
    const double *amp, *var, *depth, *residual;
    const uint8_t *saturated;
    ptrdiff_t F, N;
    const double *sigma_scale, *refl_coef;
    double phase_var_cap, power, tan_h, tan_v, k_cell, block;
    double min_snr, min_amplitude, max_sigma, max_residual, min_reflectance, max_range;
    double max_reflectance;     /* +inf: no upper bound */
    double *snr, *sigma, *refl;
    uint8_t *flags;
    const double *delta;    /* (N,) rgbz_tof_fixed_pattern's correction, or NULL */
} rgbz_tof_validity_args;

int rgbz_tof_validity(const rgbz_tof_validity_args *p, int workers);

/* The fixed-pattern correction of the depth variance (rgbz_fast.tof._noise.fixed_pattern_delta):
   DSNU and PRNU are the same in the frames of every frequency, so the depth errors they cause
   at the F frequencies are correlated, which the per-frequency sum of the validity does not
   know. For measurement n, with c_f, s_f = cos, sin phase[f, n] (the phasor's angle in the
   taps' own frame), a_f = amp[f, n], T_f = pre max(offset[f, n] - black, 0) (a NaN stays;
   pre = 1 / (1 - s) for an ambient suppression s: PRNU acts on the charge the tap
   collected, before the suppression drains its share), h_f = sqrt(sigma_scale[f]) / (2 a_f),
   m = max(count[n], 1) (count NULL: 1; NaN stays), and the taps A0 = T + a c, A2 = T - a c,
   A3 = T + a s, A1 = T - a s (I = A0 - A2, Q = A3 - A1):
     P0 = -sum_f s_f A0_f h_f, P2 = sum_f s_f A2_f h_f, P3 = sum_f c_f A3_f h_f,
     P1 = -sum_f c_f A1_f h_f, S = sum_f s_f h_f, K = sum_f c_f h_f,
     corr = (prnu^2 (P0^2 + P1^2 + P2^2 + P3^2) + 2 fix_dsnu (S^2 + K^2)) / m,
   the variance of the depth (the f^2-weighted mean of the per-frequency distances) that a
   tap gain 1 + prnu z_k and an offset sqrt(fix_dsnu) z'_k, both fixed across frequencies,
   give; and ind, what the validity's sum holds of them as independent per-frequency noise
   (the tap variance's var_dsnu + prnu^2 T^2, which leaves out the taps' modulation):
     ind = sum_f sigma_scale[f] 2 (var_dsnu + prnu^2 T_f^2) / (4 a_f^2 m)   (shared 0),
     ind = sum_f sigma_scale[f] 2 mean_g(var_dsnu + prnu^2 T_g^2) / (4 a_f^2 m) (shared 1: the
           guided chain's one variance per measurement, the mean over the frequencies).
   delta[n] = corr - ind, 0 where it is not finite; F <= RGBZ_TOF_MAX_FREQS. The cosines and
   sines come from a polynomial (absolute error below 1e-13 for |phase| < 1e3, about 1e-15
   within a few turns), not libm, branch-free and vectorised (about 17 ns of CPU per
   measurement of 3 frequencies). */
int rgbz_tof_fixed_pattern(const double *phase, const double *amp, const double *offset,
                           const double *count, ptrdiff_t F, ptrdiff_t N,
                           const double *sigma_scale, double black, double pre,
                           double var_dsnu, double fix_dsnu, double prnu, int shared,
                           double *delta, int workers);

/* rgbz_tof_fixed_pattern of the measurements [n0, n0 + m) into delta[0, m), on the calling
   thread (no checks: F within 1..RGBZ_TOF_MAX_FREQS); iq NULL: the same values bit for bit.
   iq not NULL: the phasors whose phases and amplitudes phase and amp are (rgbz_tof_depth_iq's),
   I of measurement n0 + j at iq[f iqs + j], Q at iq[(F + f) iqs + j]; their cosine and sine
   then come from I / (2 amp), Q / (2 amp), not from the phase (within a few ulps of it; phase
   is not read). The guided denoise calls it on each output row as it unwraps it
   (tofg_valid_out in tof_guided.h). */
void rgbz_tof_fixed_pattern_span(const double *phase, const double *amp, const double *offset,
                                 const double *count, ptrdiff_t F, ptrdiff_t N,
                                 const double *sigma_scale, double black, double pre,
                                 double var_dsnu, double fix_dsnu, double prnu, int shared,
                                 ptrdiff_t n0, ptrdiff_t m, double *delta, const double *iq,
                                 ptrdiff_t iqs);

#endif
