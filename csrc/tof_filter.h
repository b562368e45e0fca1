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

/* The unguided ToF ISP's validity (rgbz_fast.tof._validity.validity): for every measurement
   n, from amp and var (F, N) (the per-frequency amplitude and component variance), depth,
   residual (N,) and saturated (N,):
     snr[n]   = min_f 2 amp / sqrt(var) (NaN if one is NaN),
     sigma[n] = sqrt(sum_f sigma_scale[f] fmin(var / (4 amp^2), phase_var_cap)),
     refl[n]  = mean_f amp / (refl_coef[f] s1 block^2) where depth > 0, else 0, with
                s1 = power / (4 d d tan_h tan_v) * k_cell (d = depth, 1 where depth <= 0),
     flags[n] = 1 saturated | 2 low signal (snr < min_snr, an amplitude < min_amplitude, or
                not sigma <= max_sigma when max_sigma >= 0) | 4 residual > max_residual |
                16 out of range (depth < 0, depth > max_range - 5 sigma, refl <
                min_reflectance); the flying bit (8) is not set here.
   Each in the order of the NumPy operations it replaces, so the same bits. */
typedef struct {
    const double *amp, *var, *depth, *residual;
    const uint8_t *saturated;
    ptrdiff_t F, N;
    const double *sigma_scale, *refl_coef;
    double phase_var_cap, power, tan_h, tan_v, k_cell, block;
    double min_snr, min_amplitude, max_sigma, max_residual, min_reflectance, max_range;
    double *snr, *sigma, *refl;
    uint8_t *flags;
} rgbz_tof_validity_args;

int rgbz_tof_validity(const rgbz_tof_validity_args *p, int workers);

#endif
