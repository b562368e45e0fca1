/*
 * z_guided_guide.c -- the guide of z_guided from the ToF taps (z_guided.h,
 * rgbz_zguided_guide): the mean amplitude of every Z measurement and the noise variance of
 * that mean, on the grid of the tiles, in three threaded passes over the taps and one exact
 * median per frequency. z_guided_guide.template.h holds the passes per element type of the
 * taps; reconstruction/_z_guided.py and tests/_reference/z_guided.py state the formulas.
 *
 * The median of the ratios A_f / mean over the lit sites is exact: a sample of the sites
 * places a bracket around it, the first pass counts the ratios below the bracket and keeps
 * those in it, and a selection among those finds the middle ranks; when the bracket
 * misses them (or holds more than was kept), a second pass keeps every ratio.
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
#define ZGG_SAMPLE 16384   /* sites of the sample that places the median's bracket */

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
    RGBZ_CAT(zgg_pass, s)(pass, (const T *)taps, F, N, lo, hi, gxc, gx, grid, var, nl, blo, \
                          bhi, bel, mine, cap, pos, ratio)
#define ZGG_SAMPLE_(s, T) m = RGBZ_CAT(zgg_sample, s)((const T *)taps, F, N, step, samp)

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
    for (ptrdiff_t iy = 0; iy < gyc; iy++) {
        const int64_t *restrict sr = site_rows + iy * gxc, *restrict sc = site_cols + iy * gxc;
        const int64_t r = zr + (int64_t)py * iy;
        int b = 0;
        RGBZ_IVDEP for (ptrdiff_t ix = 0; ix < gxc; ix++)
            b |= (sr[ix] != r) | (sc[ix] != zc + (int64_t)px * ix);
        bad |= b;
    }
    if (bad) return RGBZ_ZG_SITES;

    /* the bracket of each frequency's median from the sample: ranks m / 2 -+ (3 sqrt(m) +
       16) of its m lit ratios (a median's rank in a sample strays by about sqrt(m) / 2) */
    const ptrdiff_t step = N / ZGG_SAMPLE + 1;
    double blo[RGBZ_TOF_MAX_FREQS], bhi[RGBZ_TOF_MAX_FREQS], ratio[RGBZ_TOF_MAX_FREQS];
    double *samp[RGBZ_TOF_MAX_FREQS] = {NULL};
    double frac = 1.0;   /* the share of the ratios a bracket is expected to hold, at most */
    ptrdiff_t m = 0;
    int status = RGBZ_OK;
    for (ptrdiff_t f = 0; f < F; f++) {
        ratio[f] = 1.0;
        blo[f] = -INFINITY;
        bhi[f] = INFINITY;
    }
    if (F > 1) {
        for (ptrdiff_t f = 0; f < F && status == RGBZ_OK; f++) {
            samp[f] = malloc((size_t)(N / step + 1) * sizeof **samp);
            if (!samp[f]) status = RGBZ_ENOMEM;
        }
        if (status == RGBZ_OK) {
            RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_SAMPLE_, (void)0)
        }
        const ptrdiff_t d = (ptrdiff_t)(3.0 * sqrt((double)m)) + 16;
        if (status == RGBZ_OK && m / 2 - d >= 0 && m / 2 + d < m) {
            for (ptrdiff_t f = 0; f < F; f++) {
                blo[f] = zgg_select(samp[f], m, m / 2 - d);
                bhi[f] = zgg_select(samp[f], m, m / 2 + d);
            }
            frac = (double)(2 * d + 1) / (double)m;
        }
        for (ptrdiff_t f = 0; f < F; f++) free(samp[f]);
        if (status != RGBZ_OK) return status;
    }
    ptrdiff_t *cnt = calloc((size_t)nth * (size_t)(2 * F + 1), sizeof *cnt);
    double **bufs = calloc((size_t)nth * (size_t)F, sizeof *bufs);
    double *sel[RGBZ_TOF_MAX_FREQS] = {NULL};
    ptrdiff_t n_sel[RGBZ_TOF_MAX_FREQS], below[RGBZ_TOF_MAX_FREQS];
    ptrdiff_t total_lit = 0;
    int redo = 0, overflow = 0;
    if (!cnt || !bufs) {
        free(cnt);
        free(bufs);
        return RGBZ_ENOMEM;
    }
    /* pass 1 (grid, counts, the ratios in the brackets); one thread checks that every
       bracket holds the middle ranks and gathers them (else pass 2 keeps every ratio, and it
       gathers again); the medians; pass 3 (variance) */
#ifdef _OPENMP
#pragma omp parallel num_threads(nth)
#endif
    {
#ifdef _OPENMP
        const int t = omp_get_thread_num(), team = omp_get_num_threads();
#else
        const int t = 0, team = 1;
#endif
        const ptrdiff_t lo = N * t / team, hi = N * (t + 1) / team;
        ptrdiff_t *nl = cnt + (size_t)t * (size_t)(2 * F + 1), *bel = nl + 1, *pos = bel + F;
        double **mine = bufs + (size_t)t * (size_t)F;
        /* room for twice the expected share of the bracket's ratios */
        ptrdiff_t cap = F > 1 ? (ptrdiff_t)(2.0 * frac * (double)(hi - lo)) + 1024 : 0;
        cap = cap < hi - lo ? cap : hi - lo;
        int ok = 1;
        for (ptrdiff_t f = 0; f < F && F > 1; f++)
            ok &= (mine[f] = malloc((size_t)(cap + 1) * sizeof **mine)) != NULL;
        if (!ok) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ENOMEM;
        }
        int pass = 1;
        if (ok) {
            RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
        }
        if (F == 1)
            for (ptrdiff_t n = lo; n < hi; n++) var[(n / gxc) * gx + n % gxc] = 0.0;
        for (ptrdiff_t f = 0; f < F; f++)
            if (pos[f] > cap) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
                overflow = 1;
            }
        for (int round = 0; round < 2; round++) {
#ifdef _OPENMP
#pragma omp barrier
#pragma omp single
#endif
            {
                if (round == 0)
                    for (int i = 0; i < team; i++)
                        total_lit += cnt[(size_t)i * (size_t)(2 * F + 1)];
                const ptrdiff_t k1 = (total_lit - 1) / 2, k2 = total_lit / 2;
                const int any = F > 1 && total_lit > 0 && status == RGBZ_OK;
                for (ptrdiff_t f = 0; f < F && any; f++) {
                    ptrdiff_t b = 0, in = 0;
                    for (int i = 0; i < team; i++) {
                        const ptrdiff_t *c = cnt + (size_t)i * (size_t)(2 * F + 1);
                        b += c[1 + f];
                        in += c[1 + F + f];
                    }
                    if (round == 0 && (b > k1 || k2 >= b + in || overflow)) {
                        redo = 1;
                        continue;
                    }
                    below[f] = round == 0 ? b : 0;
                    n_sel[f] = in;
                }
                if (round == 0 && redo) {
                    /* every ratio kept: the brackets widened to everything */
                    for (ptrdiff_t f = 0; f < F; f++) {
                        blo[f] = -INFINITY;
                        bhi[f] = INFINITY;
                    }
                }
                if (!(round == 0 && redo))
                    for (ptrdiff_t f = 0; f < F && any && status == RGBZ_OK; f++) {
                        sel[f] = malloc((size_t)(n_sel[f] > 0 ? n_sel[f] : 1) * sizeof **sel);
                        if (!sel[f]) {
                            status = RGBZ_ENOMEM;
                            break;
                        }
                        ptrdiff_t o = 0;
                        for (int i = 0; i < team; i++) {
                            const ptrdiff_t c = cnt[(size_t)i * (size_t)(2 * F + 1) + 1 + F + f];
                            memcpy(sel[f] + o, bufs[(size_t)i * (size_t)F + f],
                                   (size_t)c * sizeof **sel);
                            o += c;
                        }
                    }
            }
            if (!(round == 0 && redo)) break;
            /* pass 2: every ratio, room for all of this thread's */
            for (ptrdiff_t f = 0; f < F; f++) {
                free(mine[f]);
                mine[f] = malloc((size_t)(hi - lo + 1) * sizeof **mine);
                pos[f] = 0;
                if (!mine[f]) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
                    status = RGBZ_ENOMEM;
                }
            }
            cap = hi - lo;
            pass = 2;
            if (status == RGBZ_OK) {
                RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
            }
        }
#ifdef _OPENMP
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
                const double md = k1 == k2 ? v2 : (v1 + v2) / 2.0;
                ratio[f] = md > 0 ? md : 1.0;
            }
        }
        if (F > 1 && status == RGBZ_OK) {
            pass = 3;
            RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZGG_PASS_, (void)0)
        }
        for (ptrdiff_t f = 0; f < F; f++) free(mine[f]);
    }
    for (ptrdiff_t f = 0; f < F; f++) free(sel[f]);
    free(bufs);
    free(cnt);
    return status;
}
