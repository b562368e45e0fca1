/*
 * z_guided_guide.c -- the guide of z_guided from the ToF taps (z_guided.h,
 * rgbz_zguided_guide): the mean amplitude of every Z measurement and the noise variance of
 * that mean, on the grid of the tiles. The median per frequency of the ratios A_f / mean runs
 * over a fixed sample of the sites (every step-th, step = N / RGBZ_ZG_SAMPLE + 1: all of them
 * in a frame of fewer sites), exact over that sample; then one threaded pass over the taps
 * gives both grids. z_guided_guide.template.h holds the sample and the pass per element type
 * of the taps; reconstruction/_z_guided.py and tests/_reference/z_guided.py state the
 * formulas.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"
#include "rgbz_ops.h"
#include "rgbz_templating.h"
#include "z_guided.h"

#define ZGG_BLOCK 256      /* sites per block of a pass: its amplitudes stay in L1 */

#define RGBZ_TYPE_TEMPLATE "z_guided_guide.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

/* the k-th smallest of a[0 .. n - 1] (0 <= k < n), reordering a so that a[i] <= a[k] for
   i < k and a[i] >= a[k] for i > k (Hoare's selection, middle pivot) */
static double zgg_select(double *a, ptrdiff_t n, ptrdiff_t k)
{
    ptrdiff_t l = 0, r = n - 1;
    while (l < r) {
        const double p = a[l + (r - l) / 2];
        ptrdiff_t i = l, j = r;
        while (i <= j) {
            while (a[i] < p) i++;
            while (a[j] > p) j--;
            if (i <= j) {
                const double t = a[i];
                a[i] = a[j];
                a[j] = t;
                i++;
                j--;
            }
        }
        if (k <= j) r = j;
        else if (k >= i) l = i;
        else break;
    }
    return a[k];
}

#define ZGG_PASS_(s, T)                                                                      \
    RGBZ_CAT(zgg_pass, s)((const T *)taps, F, N, lo, hi, gxc, gx, grid, var, ratio)
#define ZGG_PASS32_(s, T)                                                                    \
    RGBZ_CAT(zgg_pass32, s)((const T *)taps, F, N, lo, lo + gxc, grid, var, ratio)
#define ZGG_SAMPLE_(s, T) RGBZ_CAT(zgg_sample, s)((const T *)taps, F, N, step, i0, i1, samp)

int rgbz_zguided_ratios(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                        const int64_t *site_rows, const int64_t *site_cols, int py, int px,
                        int zr, int zc, ptrdiff_t gyc, ptrdiff_t gxc, double *ratio,
                        int check, int workers)
{
    if (!taps || (check && (!site_rows || !site_cols)) || !ratio || F < 1 ||
        F > RGBZ_TOF_MAX_FREQS ||
        py <= 0 || px <= 0 || gyc < 1 || gxc < 1)
        return RGBZ_EINVAL;
    if (in_type != RGBZ_T_U8 && in_type != RGBZ_T_U16 && in_type != RGBZ_T_F32 &&
        in_type != RGBZ_T_F64)
        return RGBZ_EINVAL;
    if (N != gyc * gxc) return RGBZ_ZG_SITES;
    const int nth = rgbz_threads(workers);
    (void)nth;                                  /* read by the OpenMP pragmas only */
    /* the sites must be the complete Z pixels in row-major order: site n is the cell
       (n / gxc, n % gxc) */
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nth) reduction(| : bad) if (check)
#endif
    for (ptrdiff_t iy = 0; iy < gyc * (check != 0); iy++) {
        const int64_t *restrict sr = site_rows + iy * gxc, *restrict sc = site_cols + iy * gxc;
        const int64_t r = zr + (int64_t)py * iy;
        int b = 0;
        RGBZ_IVDEP for (ptrdiff_t ix = 0; ix < gxc; ix++)
            b |= (sr[ix] != r) | (sc[ix] != zc + (int64_t)px * ix);
        bad |= b;
    }
    if (bad) return RGBZ_ZG_SITES;

    /* the medians r_f over the sample: its ratios (NaN: not lit), the lit ones compacted,
       NumPy's median of them (the middle value, or the mean of the two middle ones); 1 when
       no site of the sample is lit or the median is not > 0 */
    for (ptrdiff_t f = 0; f < F; f++) ratio[f] = 1.0;
    if (F == 1) return RGBZ_OK;
    const ptrdiff_t step = N / RGBZ_ZG_SAMPLE + 1, ns = (N - 1) / step + 1;
    double *samp[RGBZ_TOF_MAX_FREQS] = {NULL};
    int status = RGBZ_OK;
    for (ptrdiff_t f = 0; f < F; f++)
        if (!(samp[f] = malloc((size_t)ns * sizeof **samp))) status = RGBZ_ENOMEM;
    if (status == RGBZ_OK) {
#ifdef _OPENMP
#pragma omp parallel num_threads(nth)
#endif
        {
            const int t = rgbz_thread_num(), team = rgbz_team_size();
            const ptrdiff_t i0 = ns * t / team, i1 = ns * (t + 1) / team;
            RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_SAMPLE_, (void)0)
        }
        /* the lit sites are the same for every frequency (mean > 0) */
        ptrdiff_t m = 0;
        for (ptrdiff_t i = 0; i < ns; i++) {
            if (isnan(samp[0][i])) continue;
            for (ptrdiff_t f = 0; f < F; f++) samp[f][m] = samp[f][i];
            m++;
        }
        const ptrdiff_t k1 = (m - 1) / 2, k2 = m / 2;
        for (ptrdiff_t f = 0; f < F && m > 0; f++) {
            double *s = samp[f];
            const double v2 = zgg_select(s, m, k2);
            double v1 = v2;
            if (k1 != k2) {
                v1 = s[0];
                for (ptrdiff_t i = 1; i < k2; i++) v1 = s[i] > v1 ? s[i] : v1;
            }
            const double md = k1 == k2 ? v2 : (v1 + v2) / 2.0;
            ratio[f] = md > 0 ? md : 1.0;
        }
    }
    for (ptrdiff_t f = 0; f < F; f++) free(samp[f]);
    return status;
}

void rgbz_zguided_guide_row(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                            ptrdiff_t lo, ptrdiff_t gxc, const double *ratio, double *grid,
                            double *var)
{
    /* the sites lo .. lo + gxc - 1 (lo a multiple of gxc: one grid row) into cells 0 ..
       gxc - 1 of grid and var (a pass whose grid rows are 0 apart) */
    const ptrdiff_t hi = lo + gxc, gx = 0;
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
}

void rgbz_zguided_guide_row_f32(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                                ptrdiff_t lo, ptrdiff_t gxc, const double *ratio, float *grid,
                                float *var)
{
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS32_, (void)0)
}

int rgbz_zguided_guide(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                       const int64_t *site_rows, const int64_t *site_cols, int py, int px,
                       int zr, int zc, ptrdiff_t gy, ptrdiff_t gx, ptrdiff_t gyc, ptrdiff_t gxc,
                       double *grid, double *var, int workers)
{
    if (!grid || !var || gyc > gy || gxc > gx) return RGBZ_EINVAL;
    double ratio[RGBZ_TOF_MAX_FREQS];
    const int st = rgbz_zguided_ratios(in_type, taps, F, N, site_rows, site_cols, py, px, zr,
                                       zc, gyc, gxc, ratio, 1, workers);
    if (st != RGBZ_OK) return st;
    /* one pass over the taps: both grids */
    const int nth = rgbz_threads(workers);
    (void)nth;                                  /* read by the OpenMP pragma only */
#ifdef _OPENMP
#pragma omp parallel num_threads(nth)
#endif
    {
        const int t = rgbz_thread_num(), team = rgbz_team_size();
        const ptrdiff_t lo = N * t / team, hi = N * (t + 1) / team;
        RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
    }
    return RGBZ_OK;
}
