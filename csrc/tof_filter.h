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

#endif
