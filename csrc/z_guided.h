/*
 * z_guided.h -- the colour reconstruction guided by the NIR amplitude of the Z pixels
 * (method "z_guided"; rgbz_fast/reconstruction/_z_guided.py is the NumPy path, and
 * docs/guide/z_guided.md the specification).
 *
 * Every Z site is the learned method's dot product (learned.h: the taps of its phase, the
 * hash of their structure) with weights chosen by the bucket
 *   b = level(cell) * n_hash + hash bucket,
 * plus the guide term over the 11 guide features of its cell:
 *   res = sum_t w[t][b] x_t + base * (sum_{m<9} g[b][m] c_m - g[b][9])
 *         + g[b][9] c_9 + g[b][10] c_10,
 * where base is the mean of the phase's baseline taps (the target colour in the 5x5
 * window), and c (per target colour and cell: the guide features of the NumPy path without
 * their factor base, share * u_m for m < 9, mean C + a u_0 and a u_0 - (C_0 - mean C)) and
 * the noise level of each cell depend on the 3x3 Z pixels around the cell only: the kernel
 * computes them once per tile row and target colour (stated below), in the rows it
 * reconstructs. The cell of the site at (y, x) is (y / py, x / px).
 *
 * rgbz_zguided_guide gives the amplitude grid and its variance from the ToF taps.
 */
#ifndef RGBZ_Z_GUIDED_H
#define RGBZ_Z_GUIDED_H

#include <stddef.h>
#include <stdint.h>
#include "learned.h"

#define RGBZ_ZG_FEATURES 11   /* the guide features of a cell: 9 amplitudes, 2 local model */

typedef struct {
    /* the base learned filters' geometry and hash (their weights are not read) */
    const rgbz_learned_filters *hash;
    int32_t n_levels;          /* noise levels of the guide: buckets = n_levels * hash buckets */
    const float *w_f32;        /* [n_phases][n_taps_max][n_levels * n_buckets] (tap-major) */
    const double *w_f64;
    /* optional (NULL: not used), for radius <= 3: the colour weights on the dense window
       (learned.h's layout), [n_phases][n_levels * n_buckets][2 radius + 1][8]; the hash's
       bayer is then needed with the spread term */
    const float *wd_f32;
    const double *wd_f64;
    const float *g_f32;        /* [n_phases][n_levels * n_buckets][RGBZ_ZG_FEATURES] */
    const double *g_f64;
    int32_t n_base_max;        /* row length of base_idx */
    const int32_t *n_base;     /* [n_phases]: baseline taps of the phase */
    const int32_t *base_idx;   /* [n_phases][n_base_max]: their tap indices */
    /* the guide: the NIR amplitude of every Z pixel and its noise variance, gy x gx (the
       tile of row iy, column ix holds its Z pixel at (zr + py iy, zc + px ix), block x
       block sites) */
    ptrdiff_t gy, gx;
    const double *grid, *var;
    /* or, when grid is NULL, their rows computed in the rows that use them, as
       rgbz_zguided_guide_row does: from the ToF taps (taps_F, 4, gyc * gxc) of element type
       taps_type (an rgbz_type) of the gyc x gxc complete Z pixels in row-major order, and the
       medians ratio (taps_F values: rgbz_zguided_ratios); the cells past them take the last
       complete row and column. site_rows, site_cols: the sites of the taps; the kernel checks
       that they are those Z pixels in row-major order, else returns RGBZ_ZG_SITES (dst then
       holds nothing meaningful) */
    const void *taps;
    const int64_t *site_rows, *site_cols;
    int taps_type;
    ptrdiff_t taps_F, gyc, gxc;
    const double *ratio;
    const int8_t *chan;        /* [py * px]: the colour code of every site of the tile */
    int32_t zr, zc, block;
    const int32_t *targets;    /* [n_phases]: the target colour of each phase, 0..2 */
    double lam;                /* the regularisation of the local model */
    const double *thr;         /* [n_levels - 1]: the increasing noise thresholds */
} rgbz_zguided_filters;

/*
 * rgbz_zguided_<precision> (float32 and float64; the fixed-point precision has none):
 * reconstruct every Z site of a rows x cols frame of element type in_type (an rgbz_type)
 * in that precision (its arithmetic and the weights w_<precision>, g_<precision>). src,
 * dst: not overlapping; dst fully written: colour sites copied, Z sites clipped to
 * [0, maxval], integer types rounded half up. py, px, phase_map: the pattern period and
 * the phase of each tile site (-1 for a colour site). opcounts: counting build only,
 * n_phases x RGBZ_NOPS counters (the cell terms, one per tile, are not counted). Borders: a
 * tap outside the frame moves back inside by whole periods.
 */
typedef int rgbz_zguided_fn(int in_type, const void *src, void *dst, ptrdiff_t rows,
                            ptrdiff_t cols, int py, int px, const int32_t *phase_map,
                            const rgbz_zguided_filters *f, double maxval, int workers,
                            uint64_t *opcounts);
rgbz_zguided_fn rgbz_zguided_f32;
rgbz_zguided_fn rgbz_zguided_f64;

/* rgbz_zguided_guide: the sites are not the complete Z pixels in row-major order */
#define RGBZ_ZG_SITES 100
/* rgbz_zguided_guide's medians run over every s-th site, s = N / RGBZ_ZG_SAMPLE + 1: all
   of a frame of fewer sites, else between half of RGBZ_ZG_SAMPLE and RGBZ_ZG_SAMPLE */
#define RGBZ_ZG_SAMPLE 16384

/*
 * The guide from the ToF taps (F, 4, N) of in_type (an rgbz_type): grid[iy * gx + ix] the
 * mean over the frequencies of the amplitude (tof.c's, 0.5 |I + iQ|) of the Z pixel of
 * tile (iy, ix), var the noise variance of that mean,
 *   sum_f (A_f / r_f - mean_f A_f / r_f)^2 / (F (F - 1))   (0 when F = 1),
 * r_f the median over the lit sites (mean > 0) of the sample of A_f / mean (NumPy's median;
 * 1 when no site of the sample is lit or the median is not > 0), the sample being the sites
 * 0, s, 2 s, ... with s = N / RGBZ_ZG_SAMPLE + 1 (every site of a frame of fewer than
 * RGBZ_ZG_SAMPLE). Site n (site_rows[n], site_cols[n]) must be the
 * Z pixel of tile (n / gxc, n % gxc), N = gyc * gxc: the gyc x gxc complete Z pixels in
 * row-major order (else RGBZ_ZG_SITES); the other cells of the gy x gx grids are not
 * written. The result does not depend on workers.
 */
int rgbz_zguided_guide(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                       const int64_t *site_rows, const int64_t *site_cols, int py, int px,
                       int zr, int zc, ptrdiff_t gy, ptrdiff_t gx, ptrdiff_t gyc, ptrdiff_t gxc,
                       double *grid, double *var, int workers);

/*
 * The two parts of rgbz_zguided_guide: rgbz_zguided_ratios checks the sites when check is
 * not 0 (RGBZ_ZG_SITES, as rgbz_zguided_guide; with check 0 the sites are not read and the
 * caller checks them: the kernel's guide from the taps) and gives the medians ratio[f] (F
 * values);
 * rgbz_zguided_guide_row gives, from them, the grid and var values of the gxc sites from lo
 * on (lo a multiple of gxc: one row of the grid) into grid[0 .. gxc - 1], var[0 ..], the
 * values of rgbz_zguided_guide bit for bit.
 */
int rgbz_zguided_ratios(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                        const int64_t *site_rows, const int64_t *site_cols, int py, int px,
                        int zr, int zc, ptrdiff_t gyc, ptrdiff_t gxc, double *ratio,
                        int check, int workers);
void rgbz_zguided_guide_row(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                            ptrdiff_t lo, ptrdiff_t gxc, const double *ratio, double *grid,
                            double *var);
/* rgbz_zguided_guide_row in float (the float32 kernel's guide from the taps): the taps'
   differences, the amplitudes, their means and the variance in float, the means and the
   quotients by the medians as products with reciprocals; within a few float roundings of
   rgbz_zguided_guide_row's values (relative ~1e-6 on grid, ~1e-6 of grid^2 on var), not
   bit for bit */
void rgbz_zguided_guide_row_f32(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                                ptrdiff_t lo, ptrdiff_t gxc, const double *ratio, float *grid,
                                float *var);

/*
 * The cell terms and the noise level of tile (iy, ix) for a target colour t, with the 3 x 3
 * Z pixels m around it (clamped to the grid): u_m = N_m / mean N - 1, nu = mean V /
 * (mean N)^2 (0 and 1 where mean N = 0), U = sum u^2, share = U / (U + 9 nu), C_m the mean
 * of the pixels of colour t in the box of Z pixel m and the two pixels around it (borders:
 * whole periods), a = sum u_m (C_m - mean C) / (U + 9 (lam + nu)): cell = (share u_m (9),
 * mean C + a u_4, a u_4 - (C_4 - mean C)); level = the number of thresholds nu exceeds.
 * Every sum runs in the order of m (row-major), as reconstruction/_z_guided.py's
 * cell_terms, in double.
 */

#endif /* RGBZ_Z_GUIDED_H */
