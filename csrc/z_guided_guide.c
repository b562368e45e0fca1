/*
 * z_guided_guide.c -- the guide of z_guided from the ToF taps (z_guided.h,
 * rgbz_zguided_guide): the mean amplitude of every Z measurement and the noise variance of
 * that mean, on the grid of the tiles, in three threaded passes over the taps and one exact
 * median per frequency. z_guided_guide.template.h holds the passes per element type of the
 * taps; reconstruction/_z_guided.py and tests/_reference/z_guided.py state the formulas.
 *
 * The median of the ratios A_f / mean over the lit sites is exact: a histogram of the
 * ratios (ZGG_BINS bins of [0, F], a monotone map, so that the k-th smallest ratio lies in
 * the bin where the histogram's cumulative count passes k), then a selection among the
 * ratios of the one or two bins that hold the middle ranks.
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
#define ZGG_BINS 65536     /* bins of a frequency's histogram of ratios */

/* the bin of a ratio r >= 0 (scale = ZGG_BINS / F): non-decreasing in r */
static inline int zgg_bin(double r, double scale)
{
    const double b = r * scale;
    return b < 1.0 ? 0 : (b >= (double)(ZGG_BINS - 1) ? ZGG_BINS - 1 : (int)b);
}

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

/* the thread's share [lo, hi) of n sites when nth threads split them */
static void zgg_share(ptrdiff_t n, int nth, int t, ptrdiff_t *lo, ptrdiff_t *hi)
{
    *lo = n * t / nth;
    *hi = n * (t + 1) / nth;
}

#define ZGG_PASS_(s, T)                                                                      \
    RGBZ_CAT(zgg_pass, s)(pass, (const T *)taps, F, N, lo, hi, gxc, gx, grid, var, h, nl,  \
                          blo, bhi, sel, pos, ratio)

int rgbz_zguided_guide(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                       const int64_t *site_rows, const int64_t *site_cols, int py, int px,
                       int zr, int zc, ptrdiff_t gy, ptrdiff_t gx, ptrdiff_t gyc, ptrdiff_t gxc,
                       double *grid, double *var, int workers)
{
    if (!taps || !site_rows || !site_cols || !grid || !var || F < 1 ||
        F > RGBZ_TOF_MAX_FREQS || py <= 0 || px <= 0 || gyc < 1 || gxc < 1 || gyc > gy ||
        gxc > gx)
        return RGBZ_EINVAL;
    if (in_type != RGBZ_T_U8 && in_type != RGBZ_T_U16 && in_type != RGBZ_T_F32 &&
        in_type != RGBZ_T_F64)
        return RGBZ_EINVAL;
    if (N != gyc * gxc) return RGBZ_ZG_SITES;
#ifdef _OPENMP
    const int nth = workers > 0 ? workers : omp_get_max_threads();
#else
    const int nth = 1;
    (void)workers;
#endif
    /* the sites must be the complete Z pixels in row-major order: site n is the cell
       (n / gxc, n % gxc) */
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nth) reduction(| : bad)
#endif
    for (ptrdiff_t n = 0; n < N; n++)
        bad |= site_rows[n] != zr + (int64_t)py * (n / gxc) ||
               site_cols[n] != zc + (int64_t)px * (n % gxc);
    if (bad) return RGBZ_ZG_SITES;

    uint32_t *hist = F > 1 ? calloc((size_t)nth * (size_t)F * ZGG_BINS, sizeof *hist) : NULL;
    ptrdiff_t *n_lit = calloc((size_t)nth, sizeof *n_lit);
    ptrdiff_t *offs = calloc((size_t)nth * (size_t)F, sizeof *offs);
    if ((F > 1 && !hist) || !n_lit || !offs) {
        free(hist);
        free(n_lit);
        free(offs);
        return RGBZ_ENOMEM;
    }
    double ratio[RGBZ_TOF_MAX_FREQS];
    double *sel[RGBZ_TOF_MAX_FREQS] = {NULL};
    int blo[RGBZ_TOF_MAX_FREQS] = {0}, bhi[RGBZ_TOF_MAX_FREQS] = {0};
    ptrdiff_t below[RGBZ_TOF_MAX_FREQS], n_sel[RGBZ_TOF_MAX_FREQS];
    ptrdiff_t total_lit = 0;
    int status = RGBZ_OK;
    for (ptrdiff_t f = 0; f < F; f++) ratio[f] = 1.0;
    /* pass 1 on every thread; then (one thread) the median's bins and every thread's place
       in the list of their ratios; pass 2; the medians; pass 3 */
#ifdef _OPENMP
#pragma omp parallel num_threads(nth)
#endif
    {
#ifdef _OPENMP
        const int t = omp_get_thread_num(), team = omp_get_num_threads();
#else
        const int t = 0, team = 1;
#endif
        ptrdiff_t lo, hi, pos[RGBZ_TOF_MAX_FREQS];
        zgg_share(N, team, t, &lo, &hi);
        uint32_t *h = hist ? hist + (size_t)t * (size_t)F * ZGG_BINS : NULL;
        ptrdiff_t *nl = n_lit + t;
        int pass = 1;
        RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
        if (F == 1)
            for (ptrdiff_t n = lo; n < hi; n++) var[(n / gxc) * gx + n % gxc] = 0.0;
#ifdef _OPENMP
#pragma omp barrier
#pragma omp single
#endif
        {
            for (int i = 0; i < team; i++) total_lit += n_lit[i];
            if (F > 1 && total_lit > 0 && status == RGBZ_OK) {
                /* the middle ranks: k1 = (n - 1) / 2 and k2 = n / 2 (equal when n is odd) */
                const ptrdiff_t k1 = (total_lit - 1) / 2, k2 = total_lit / 2;
                for (ptrdiff_t f = 0; f < F && status == RGBZ_OK; f++) {
                    ptrdiff_t cum = 0, cnt = 0;
                    blo[f] = bhi[f] = -1;
                    for (int b = 0; b < ZGG_BINS; b++) {
                        ptrdiff_t c = 0;
                        for (int i = 0; i < team; i++)
                            c += hist[((size_t)i * (size_t)F + (size_t)f) * ZGG_BINS + b];
                        if (blo[f] < 0 && cum + c > k1) {
                            blo[f] = b;
                            below[f] = cum;
                        }
                        if (cum + c > k2) {
                            bhi[f] = b;
                            break;
                        }
                        cum += c;
                    }
                    /* every thread's count in the bins gives its place in sel[f] */
                    for (int i = 0; i < team; i++) {
                        const uint32_t *hf = hist + ((size_t)i * (size_t)F + (size_t)f) * ZGG_BINS;
                        offs[(size_t)i * (size_t)F + (size_t)f] = cnt;
                        for (int b = blo[f]; b <= bhi[f]; b++) cnt += hf[b];
                    }
                    sel[f] = malloc((size_t)(cnt > 0 ? cnt : 1) * sizeof **sel);
                    if (!sel[f]) status = RGBZ_ENOMEM;
                    n_sel[f] = cnt;   /* the ratios in sel[f] */
                }
            }
        }
        if (F > 1 && total_lit > 0 && status == RGBZ_OK) {
            for (ptrdiff_t f = 0; f < F; f++)
                pos[f] = offs[(size_t)t * (size_t)F + (size_t)f];
            pass = 2;
            RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
        }
#ifdef _OPENMP
#pragma omp barrier
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t f = 0; f < F; f++) {
            if (F > 1 && total_lit > 0 && status == RGBZ_OK) {
                const ptrdiff_t k1 = (total_lit - 1) / 2 - below[f];
                const ptrdiff_t k2 = total_lit / 2 - below[f];
                /* NumPy's median: the middle value, or the mean of the two middle ones */
                const double v2 = zgg_select(sel[f], n_sel[f], k2);
                double v1 = v2;
                if (k1 != k2) {
                    v1 = sel[f][0];
                    for (ptrdiff_t i = 1; i < k2; i++) v1 = sel[f][i] > v1 ? sel[f][i] : v1;
                }
                const double m = k1 == k2 ? v2 : (v1 + v2) / 2.0;
                ratio[f] = m > 0 ? m : 1.0;
            }
        }
        if (F > 1 && status == RGBZ_OK) {
            pass = 3;
            RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
        }
    }
    for (ptrdiff_t f = 0; f < F; f++) free(sel[f]);
    free(hist);
    free(n_lit);
    free(offs);
    return status;
}
