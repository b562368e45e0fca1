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
 * window), and c (per phase and cell: the guide features of the NumPy path without their
 * factor base, share * u_m for m < 9, mean C + a u_0 and a u_0 - (C_0 - mean C)) and the
 * noise level of each cell come from the Python layer: they depend on the 3x3 Z pixels
 * around the cell only, one value per tile and not per site. The cell of the site at
 * (y, x) is (y / py, x / px).
 *
 * Entry points are typed (one per element type of the frame, suffix u8, u16, f32, f64);
 * precision RGBZ_P_FLOAT32 or RGBZ_P_FLOAT64 chooses the arithmetic and the weights.
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
    const float *g_f32;        /* [n_phases][n_levels * n_buckets][RGBZ_ZG_FEATURES] */
    const double *g_f64;
    int32_t n_base_max;        /* row length of base_idx */
    const int32_t *n_base;     /* [n_phases]: baseline taps of the phase */
    const int32_t *base_idx;   /* [n_phases][n_base_max]: their tap indices */
    ptrdiff_t gy, gx;          /* the grid of cells (tiles) */
    const double *cell;        /* [n_phases][gy][gx][RGBZ_ZG_FEATURES] */
    const int32_t *level;      /* [gy][gx]: the noise level of each cell, 0..n_levels - 1 */
} rgbz_zguided_filters;

/*
 * Reconstruct every Z site of a rows x cols frame (src, dst: not overlapping; dst fully
 * written: colour sites copied, Z sites clipped to [0, maxval], integer types rounded
 * half up). py, px, phase_map: the pattern period and the phase of each tile site (-1 for a
 * colour site). opcounts: counting build only, n_phases x RGBZ_NOPS counters. Borders: a
 * tap outside the frame moves back inside by whole periods.
 */
int rgbz_zguided_u8(const uint8_t *src, uint8_t *dst, ptrdiff_t rows, ptrdiff_t cols, int py,
                    int px, const int32_t *phase_map, const rgbz_zguided_filters *f,
                    int precision, double maxval, int workers, uint64_t *opcounts);
int rgbz_zguided_u16(const uint16_t *src, uint16_t *dst, ptrdiff_t rows, ptrdiff_t cols,
                     int py, int px, const int32_t *phase_map, const rgbz_zguided_filters *f,
                     int precision, double maxval, int workers, uint64_t *opcounts);
int rgbz_zguided_f32(const float *src, float *dst, ptrdiff_t rows, ptrdiff_t cols, int py,
                     int px, const int32_t *phase_map, const rgbz_zguided_filters *f,
                     int precision, double maxval, int workers, uint64_t *opcounts);
int rgbz_zguided_f64(const double *src, double *dst, ptrdiff_t rows, ptrdiff_t cols, int py,
                     int px, const int32_t *phase_map, const rgbz_zguided_filters *f,
                     int precision, double maxval, int workers, uint64_t *opcounts);

/*
 * The cell terms and noise levels (the `cell` and `level` arrays above) of a frame:
 *   grid, var:  the NIR amplitude of every Z pixel and its noise variance, gy x gx (the
 *               tile of row iy, column ix holds its Z pixel at (zr + py iy, zc + px ix),
 *               block x block sites);
 *   chan:       the colour code of every site of the py x px tile (0 R, 1 G, 2 B, 3 Z);
 *   targets:    the target colour of each of the n_phases phases;
 *   lam, thr:   the regularisation of the local model and the n_thr increasing noise
 *               thresholds.
 * For each phase and tile, with the 3 x 3 Z pixels m around it (clamped to the grid):
 * u_m = N_m / mean N - 1, nu = mean V / (mean N)^2 (0 and 1 where mean N = 0), U = sum u^2,
 * share = U / (U + 9 nu), C_m the mean of the pixels of the target colour in the box of
 * Z pixel m and the two pixels around it (borders: whole periods), a = sum u_m (C_m -
 * mean C) / (U + 9 (lam + nu)): cell = (share u_m (9), mean C + a u_4, a u_4 - (C_4 -
 * mean C)); level = the number of thresholds nu exceeds.
 */
int rgbz_zguided_cells_u8(const uint8_t *src, ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                          const int8_t *chan, int zr, int zc, int block, const double *grid,
                          const double *var, ptrdiff_t gy, ptrdiff_t gx, int n_phases,
                          const int32_t *targets, double lam, const double *thr, int n_thr,
                          double *cell, int32_t *level, int workers);
int rgbz_zguided_cells_u16(const uint16_t *src, ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                           const int8_t *chan, int zr, int zc, int block, const double *grid,
                           const double *var, ptrdiff_t gy, ptrdiff_t gx, int n_phases,
                           const int32_t *targets, double lam, const double *thr, int n_thr,
                           double *cell, int32_t *level, int workers);
int rgbz_zguided_cells_f32(const float *src, ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                           const int8_t *chan, int zr, int zc, int block, const double *grid,
                           const double *var, ptrdiff_t gy, ptrdiff_t gx, int n_phases,
                           const int32_t *targets, double lam, const double *thr, int n_thr,
                           double *cell, int32_t *level, int workers);
int rgbz_zguided_cells_f64(const double *src, ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                           const int8_t *chan, int zr, int zc, int block, const double *grid,
                           const double *var, ptrdiff_t gy, ptrdiff_t gx, int n_phases,
                           const int32_t *targets, double lam, const double *thr, int n_thr,
                           double *cell, int32_t *level, int workers);

#endif /* RGBZ_Z_GUIDED_H */
