/*
 * metrics.c -- image-quality metric kernels (see metrics.h for the API and layout contract).
 *
 *  - SSIM and MS-SSIM (Z. Wang, A. C. Bovik, H. R. Sheikh, E. P. Simoncelli, IEEE TIP 13(4),
 *    2004; Z. Wang, E. P. Simoncelli, A. C. Bovik, Asilomar 2003): the five local moments of a
 *    pair of planes filtered by a separable symmetric window over the windows lying wholly
 *    inside the image, one output row at a time (vertical pass into row buffers, then
 *    horizontal pass and the SSIM formula). What the reference alone gives (its local means
 *    and variances) can be computed once and stored, for a reference compared with many
 *    images; otherwise no moment image is stored. The operations are
 *    those of rgbz_fast.metrics' former NumPy code, in its order: scipy.ndimage.correlate1d
 *    for symmetric weights (centre * w0, then (far pair sum) * w ... (near pair sum) * w),
 *    rows first; then the SSIM formula as NumPy evaluates it left to right. Only the final
 *    mean is summed in a different order (per row, then rows in order).
 *  - sRGB -> CIELAB (IEC 61966-2-1 EOTF; CIE 15:2004 L*a*b*, D65, 2 degree observer) with
 *    the constants colour-science 0.4 uses in XYZ_to_Lab(sRGB_to_XYZ(rgb)): its EOTF
 *    threshold eotf_inverse_sRGB(0.0031308) = 0.040449936 (not the rounded 0.04045), its
 *    4-digit RGB -> XYZ matrix, its D65 white from xy = (0.3127, 0.3290) and its f()
 *    threshold (24/116)^3 with slope 841/108. colour also applies a CAT02 adaptation from the
 *    sRGB white to the same D65 xy, whose matrix is the identity to 3e-17: it is left out.
 *    The cube root is mt_cbrt (below), within 1 ulp of the exact cube root, like the pow(t,
 *    1/3) colour calls.
 *  - The zipper-effect metric (W. Lu, Y.-P. Tan, IEEE TIP 12(10), 2003; Rebiere et al. eqs.
 *    29-31): Lab three rows at a time in a ring buffer per thread, then for each interior
 *    pixel the neighbour with the smallest reference dE (strict <, raster order, so the first
 *    one wins a tie), psi = dE_test - dE_ref at that neighbour, counted when |psi| > delta.
 *    The reference's half (the neighbour and its dE) can be stored once for many test images.
 *
 * Compiled with -ffp-contract=off (csrc/meson.build): a fused multiply-add would change the
 * rounding of the formulas above and the agreement with the NumPy references.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "metrics.h"
#include "metrics_isa.h"
#include "rgbz_templating.h"

/* This file is compiled once per instruction set (csrc/meson.build): RGBZ_METRICS_ISA is the
   suffix of its entry points, which metrics_dispatch.c chooses from at run time. */
#ifndef RGBZ_METRICS_ISA
#error "metrics.c: build with -DRGBZ_METRICS_ISA=generic (or avx2, avx512)"
#endif
#define MT_ENTRY(name) RGBZ_METRICS_ENTRY(name, RGBZ_METRICS_ISA)

/* `omp simd` vectorises the pixel loops (built with -fopenmp-simd, so also when OpenMP itself
   is off). No floating-point reduction clause: a sum's order would depend on the vector
   width; the integer count and the max of the Lab range check do not. */
#define MT_PRAGMA(x) _Pragma(#x)
#define MT_SIMD MT_PRAGMA(omp simd)
#define MT_SIMD_MAX(a) MT_PRAGMA(omp simd reduction(max:a))
#define MT_SIMD_COUNT(a) MT_PRAGMA(omp simd reduction(+:a))

/* Threads for `units` independent units of `work` operations each: the caller's `workers`
   (<= 0: the OpenMP default), but no more than one thread per MT_MIN_WORK operations (about
   a millisecond on one core), so that a small image does not pay the wake-up and the barrier
   of threads that have next to nothing to do (the same rule as the Python layer's
   MIN_PIXELS_PER_THREAD for the pixel kernels). */
#define MT_MIN_WORK 2e6

static int mt_threads(int workers, ptrdiff_t units, double work)
{
#ifdef _OPENMP
    int n = workers > 0 ? workers : omp_get_max_threads();
    double cap = (double)units * work / MT_MIN_WORK;
    if (cap < (double)n) n = cap < 1.0 ? 1 : (int)cap;
    if ((ptrdiff_t)n > units) n = units < 1 ? 1 : (int)units;
    return n;
#else
    (void)workers; (void)units; (void)work;
    return 1;
#endif
}

/* ------------------------------------------------------------------ colour constants */
#define MT_EOTF_KNEE 0.040449936            /* colour's eotf_inverse_sRGB(0.0031308) */
#define MT_LAB_T3 0x1.22354d28f7cd6p-7      /* (24/116)**3 as Python computes it */
#define MT_LAB_K 0x1.f25ed097b425fp+2       /* 841/108 */
#define MT_LAB_C 0x1.1a7b9611a7b96p-3       /* 16/116 */
#define MT_XN 0x1.e6a228c5f3dc7p-1          /* D65 X_n = 0.3127 / 0.3290 (Y_n = 1) */
#define MT_ZN 0x1.16cc7d1ef8103p+0          /* D65 Z_n = (1 - 0.3127 - 0.3290) / 0.3290 */

/* sRGB EOTF of one value in [0, 1] units (values outside are extended by the same formula,
   as colour's spow does for the positive branch). */
static double mt_eotf(double v)
{
    return MT_EOTF_KNEE >= v ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

/* Cube root of t in [2^-9, 8), vectorisable: exact scalings by 8^k bring t into [1/8, 1), a
   cubic gives 5e-3, two Halley steps (the second in correction form) give the root within
   1 ulp of the exact one (measured on 1.5e5 values: at most 1.0 ulp, like pow(t, 1/3)). */
static inline double mt_cbrt(double t)
{
    double s = 1.0;
    int lo = t < 0x1p-6;
    t = lo ? t * 64.0 : t;
    s = lo ? 0.25 : s;
    int mid = t < 0.125;
    t = mid ? t * 8.0 : t;
    s = mid ? s * 0.5 : s;
    int hi = t >= 1.0;
    t = hi ? t * 0.125 : t;
    s = hi ? 2.0 : s;
    double y = ((0x1.2f32bc070f5c5p-1 * t - 0x1.62cbdc013e649p+0) * t + 0x1.7546d8f3a18cep+0)
               * t + 0x1.5d05ae84a1fe9p-2;
    double y3 = y * y * y;
    y = y * (y3 + 2.0 * t) / (2.0 * y3 + t);
    y3 = y * y * y;
    y = y - y * (y3 - t) / (2.0 * y3 + t);
    return y * s;
}

/* CIE 1976 f(t) for t < 8 (mt_cbrt's range; the callers redo larger t with mt_f_any) */
static inline double mt_f(double t)
{
    double c = mt_cbrt(t);
    return t > MT_LAB_T3 ? c : MT_LAB_K * t + MT_LAB_C;
}

static double mt_f_any(double t)
{
    return t > MT_LAB_T3 ? cbrt(t) : MT_LAB_K * t + MT_LAB_C;
}

/* x / c, c one of the white point's constants and rc = 1 / c rounded (both constants): the
   division, or where the instruction set has FMA the same quotient without a division
   instruction (the Lab loop waits for its eight divisions a pixel): q = x rc is within an
   ulp of x / c, so the remainder x - q c is exact in an FMA and q + (x - q c) rc rounds to
   x / c (Markstein's theorem; it needs normal x and quotients, which the linear values of
   integer codes are: 0 or above 1e-6). metrics.template.h takes it for integer inputs; the
   tests compare it with the division on every 8-bit colour. */
#define MT_QDIV(x, c, rc) ((x) / (c))
#if defined(__FMA__)
#define MT_HAVE_QFMA 1
static inline double mt_qfma(double x, double c, double rc)
{
    const double q = x * rc;
    return fma(fma(-q, c, x), rc, q);
}
#define MT_QFMA(x, c, rc) mt_qfma((x), (c), (rc))
#endif
#define MT_RXN (1.0 / MT_XN)
#define MT_RZN (1.0 / MT_ZN)

/* linear sRGB -> the three ratios X/Xn, Y/Yn, Z/Zn (colour's matrix, row by row), the
   divisions by Xn and Zn as QUOT computes them (MT_QDIV or MT_QFMA: the same quotients) */
#define MT_XYZ_Q(r, g, b, tx, ty, tz, QUOT)                                                  \
    do {                                                                                     \
        tx = QUOT((0.4124 * (r) + 0.3576 * (g)) + 0.1805 * (b), MT_XN, MT_RXN);               \
        ty = (0.2126 * (r) + 0.7152 * (g)) + 0.0722 * (b);                                    \
        tz = QUOT((0.0193 * (r) + 0.1192 * (g)) + 0.9505 * (b), MT_ZN, MT_RZN);               \
    } while (0)
#define MT_XYZ(r, g, b, tx, ty, tz) MT_XYZ_Q(r, g, b, tx, ty, tz, MT_QDIV)

/* Lab of linear sRGB: fast path (ratios < 8); tmax >= 8 when a ratio needs mt_lab_any */
#define MT_LAB(r, g, b, L, A, B, tmax, QUOT)                                                 \
    do {                                                                                     \
        double tx_, ty_, tz_;                                                                \
        MT_XYZ_Q(r, g, b, tx_, ty_, tz_, QUOT);                                              \
        tmax = tx_ > tmax ? tx_ : tmax;                                                      \
        tmax = ty_ > tmax ? ty_ : tmax;                                                      \
        tmax = tz_ > tmax ? tz_ : tmax;                                                      \
        double fx_ = mt_f(tx_), fy_ = mt_f(ty_), fz_ = mt_f(tz_);                            \
        L = 116.0 * fy_ - 16.0;                                                              \
        A = 500.0 * (fx_ - fy_);                                                             \
        B = 200.0 * (fy_ - fz_);                                                             \
    } while (0)

#include "metrics_lab512.h"

static void mt_lab_any(double r, double g, double b, double *L, double *A, double *B)
{
    double tx, ty, tz;
    MT_XYZ(r, g, b, tx, ty, tz);
    double fx = mt_f_any(tx), fy = mt_f_any(ty), fz = mt_f_any(tz);
    *L = 116.0 * fy - 16.0;
    *A = 500.0 * (fx - fy);
    *B = 200.0 * (fy - fz);
}

/* EOTF table of the integer code values 0..n-1 over `scale` */
static double *mt_eotf_table(ptrdiff_t n, double scale, int workers)
{
    double *lut = (double *)malloc((size_t)n * sizeof(double));
    if (!lut) return NULL;
    int nt = mt_threads(workers, n, 100.0);
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nt)
#endif
    for (ptrdiff_t v = 0; v < n; v++) lut[v] = mt_eotf((double)v / scale);
    return lut;
}

/* Sum of n values in a fixed order (eight interleaved partial sums, then a tree): the same
   result with any vector width, so scores do not depend on the instruction set. */
static double mt_sum(const double *a, ptrdiff_t n)
{
    double p[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    ptrdiff_t j = 0;
    for (; j + 8 <= n; j += 8)
        for (int l = 0; l < 8; l++) p[l] += a[j + l];
    double s = ((p[0] + p[1]) + (p[2] + p[3])) + ((p[4] + p[5]) + (p[6] + p[7]));
    for (; j < n; j++) s += a[j];
    return s;
}

/* The radius of the default SSIM window (11 taps), whose loops are unrolled; `always_inline`
   lets the constant reach them. */
#define MT_SSIM_RAD 5
#define MT_INLINE __attribute__((always_inline))
#define MT_UNROLL MT_PRAGMA(GCC unroll 8)

/* The horizontal pass of one moment row v (read from v - rad to v + n + rad) into o[0..n),
   correlate1d's order for symmetric weights (the centre times its weight, then the pairs
   from the farthest to the nearest): unrolled, in registers, for the default window; the
   pairs added into o otherwise. */
static inline MT_INLINE void mt_hpass_reg(const double *v, ptrdiff_t n, const double *w,
                                          int rad, double *restrict o)
{
    const double wc = w[rad];
    MT_SIMD
    for (ptrdiff_t j = 0; j < n; j++) {
        double s = v[j] * wc;
        MT_UNROLL
        for (int k = rad; k >= 1; k--) s += (v[j - k] + v[j + k]) * w[rad - k];
        o[j] = s;
    }
}

static void mt_hpass(const double *v, ptrdiff_t n, const double *w, int rad,
                     double *restrict o)
{
    if (rad == MT_SSIM_RAD) {
        mt_hpass_reg(v, n, w, MT_SSIM_RAD, o);
        return;
    }
    const double wc = w[rad];
    MT_SIMD
    for (ptrdiff_t j = 0; j < n; j++) o[j] = v[j] * wc;
    for (int k = rad; k >= 1; k--) {
        const double wk = w[rad - k];
        MT_SIMD
        for (ptrdiff_t j = 0; j < n; j++) o[j] += (v[j - k] + v[j + k]) * wk;
    }
}

/* The vertical pass of the default window from a ring of input rows (metrics.template.h:
   mt_ring_fill): MT_RING_ROWS slots, nq quantities per row at ring + (slot * nq + q) * cols,
   row r in slot r % MT_RING_ROWS. Output row i reads input rows i .. i + 2 MT_SSIM_RAD; its
   quantity q goes to m + (t * nq + q) * cols for the t-th of the g rows i .. i + g - 1
   (g <= MT_VROWS), filtered in the order of mt_ssim_vpass_x / _y: the centre times its weight,
   then the pairs from the farthest to the nearest. MT_VROWS rows at a time read each input
   row once for all of them: the ring is in L2, and its loads are what the pass waits for.
   Eight sums in registers (measured on a Kodak plane, one thread: 10 % faster than four;
   twelve spill, twice as slow). */
#define MT_VROWS 8
#define MT_RING_ROWS (2 * MT_SSIM_RAD + MT_VROWS)

static inline MT_INLINE void mt_vpass_rows(const double *const *r, int g, ptrdiff_t cols,
                                           const double *w, double *const *o)
{
    const double wc = w[MT_SSIM_RAD];
    if (g == MT_VROWS) {
        MT_SIMD
        for (ptrdiff_t j = 0; j < cols; j++) {
            double s[MT_VROWS];
            MT_UNROLL
            for (int t = 0; t < MT_VROWS; t++) s[t] = r[MT_SSIM_RAD + t][j] * wc;
            MT_UNROLL
            for (int k = MT_SSIM_RAD; k >= 1; k--) {
                const double wk = w[MT_SSIM_RAD - k];
                MT_UNROLL
                for (int t = 0; t < MT_VROWS; t++)
                    s[t] += (r[MT_SSIM_RAD + t - k][j] + r[MT_SSIM_RAD + t + k][j]) * wk;
            }
            MT_UNROLL
            for (int t = 0; t < MT_VROWS; t++) o[t][j] = s[t];
        }
        return;
    }
    for (int t = 0; t < g; t++) {
        double *restrict ot = o[t];
        const double *const *rt = r + t;
        MT_SIMD
        for (ptrdiff_t j = 0; j < cols; j++) {
            double s = rt[MT_SSIM_RAD][j] * wc;
            MT_UNROLL
            for (int k = MT_SSIM_RAD; k >= 1; k--)
                s += (rt[MT_SSIM_RAD - k][j] + rt[MT_SSIM_RAD + k][j]) * w[MT_SSIM_RAD - k];
            ot[j] = s;
        }
    }
}

static void mt_vpass_ring(const double *ring, int nq, ptrdiff_t i, int g, ptrdiff_t cols,
                          const double *w, double *m)
{
    for (int q = 0; q < nq; q++) {
        const double *r[MT_RING_ROWS];
        double *o[MT_VROWS];
        for (int k = 0; k < 2 * MT_SSIM_RAD + g; k++)
            r[k] = ring + ((ptrdiff_t)((i + k) % MT_RING_ROWS) * nq + q) * cols;
        for (int t = 0; t < g; t++) o[t] = m + (ptrdiff_t)(t * nq + q) * cols;
        mt_vpass_rows(r, g, cols, w, o);
    }
}

/* SSIM, reference side: the horizontal pass over the two moment rows m (x, x^2 filtered
   along the columns, mt_ssim_vpass_x) into the mean and the variance of x over each of the
   cols - 2 rad windows of the row: mom[0..n) = mu_x, mom[n..2n) = E[x^2] - mu_x^2, the values
   the SSIM formula uses, so that a stored row gives the same SSIM as one computed anew. */
static void mt_ssim_hpass_x(const double *m, ptrdiff_t cols, const double *w, int rad,
                            double *restrict mom)
{
    const ptrdiff_t n = cols - 2 * rad;
    double *restrict mx = mom, *restrict vx = mom + n;
    mt_hpass(m + rad, n, w, rad, mx);
    mt_hpass(m + cols + rad, n, w, rad, vx);
    MT_SIMD
    for (ptrdiff_t j = 0; j < n; j++) vx[j] = vx[j] - mx[j] * mx[j];
}

/* SSIM, test side: the horizontal pass over the three moment rows m (y, y^2, xy filtered
   along the columns, mt_ssim_vpass_y), the reference's row mom (mt_ssim_hpass_x), the SSIM
   formula in NumPy's order, and the sums of the SSIM and c s values of the row (their values
   in a, 5 (cols - 2 rad) doubles of scratch). The default window filters in registers, in
   the loop of the formula, and sums the values as they come (mt_hpass_y_sums); another one
   filters into a first. */
static inline MT_INLINE double mt_ssim_value(double mx, double vx, double my, double eyy,
                                             double exy, double c1, double c2, double *cs_out)
{
    const double vy = eyy - my * my, vxy = exy - mx * my;
    const double lum = (2.0 * mx * my + c1) / (mx * mx + my * my + c1);
    const double cs = (2.0 * vxy + c2) / (vx + vy + c2);
    *cs_out = cs;
    return lum * cs;
}

static inline MT_INLINE double mt_cs_value(double mx, double vx, double my, double eyy,
                                           double exy, double c2)
{
    const double vy = eyy - my * my, vxy = exy - mx * my;
    return (2.0 * vxy + c2) / (vx + vy + c2);
}

/* The default window's horizontal pass, the formula and the row's sums in one loop: the
   sums of mt_sum (eight partial sums over the blocks of eight values, their tree, then the
   tail in order) taken as the values come, so that no value is stored; with_ssim 0: the c s
   values alone (one division a window). Constant with_ssim: the two loops are compiled
   apart. */
static inline MT_INLINE void mt_hpass_y_sums(const double *m, const double *mom, ptrdiff_t cols,
                                             const double *w, double c1, double c2,
                                             int with_ssim, double *ssim_row, double *cs_row)
{
    const ptrdiff_t n = cols - 2 * MT_SSIM_RAD;
    const double *ax = mom, *vxs = mom + n;
    const double *vy = m + MT_SSIM_RAD, *vyy = m + cols + MT_SSIM_RAD;
    const double *vxy = m + 2 * cols + MT_SSIM_RAD;
    const double wc = w[MT_SSIM_RAD];
    double ps[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double pc[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    ptrdiff_t j0 = 0;
#define MT_HSUMS(j)                                                                          \
    double sy = vy[j] * wc, syy = vyy[j] * wc, sxy = vxy[j] * wc;                            \
    MT_UNROLL                                                                                \
    for (int k = MT_SSIM_RAD; k >= 1; k--) {                                                 \
        const double wk = w[MT_SSIM_RAD - k];                                                \
        sy += (vy[j - k] + vy[j + k]) * wk;                                                  \
        syy += (vyy[j - k] + vyy[j + k]) * wk;                                               \
        sxy += (vxy[j - k] + vxy[j + k]) * wk;                                               \
    }
    for (; j0 + 8 <= n; j0 += 8) {
        MT_SIMD
        for (int l = 0; l < 8; l++) {
            const ptrdiff_t j = j0 + l;
            MT_HSUMS(j)
            if (with_ssim) {
                double cs;
                ps[l] += mt_ssim_value(ax[j], vxs[j], sy, syy, sxy, c1, c2, &cs);
                pc[l] += cs;
            } else {
                pc[l] += mt_cs_value(ax[j], vxs[j], sy, syy, sxy, c2);
            }
        }
    }
    double ss = ((ps[0] + ps[1]) + (ps[2] + ps[3])) + ((ps[4] + ps[5]) + (ps[6] + ps[7]));
    double cc = ((pc[0] + pc[1]) + (pc[2] + pc[3])) + ((pc[4] + pc[5]) + (pc[6] + pc[7]));
    for (ptrdiff_t j = j0; j < n; j++) {
        MT_HSUMS(j)
        if (with_ssim) {
            double cs;
            ss += mt_ssim_value(ax[j], vxs[j], sy, syy, sxy, c1, c2, &cs);
            cc += cs;
        } else {
            cc += mt_cs_value(ax[j], vxs[j], sy, syy, sxy, c2);
        }
    }
#undef MT_HSUMS
    if (with_ssim) *ssim_row = ss;
    *cs_row = cc;
}

static void mt_ssim_hpass_y(const double *m, const double *mom, ptrdiff_t cols,
                            const double *w, int rad, double c1, double c2, double *restrict a,
                            double *ssim_row, double *cs_row)
{
    const ptrdiff_t n = cols - 2 * rad;
    const double *ax = mom, *vxs = mom + n;
    double *restrict ssim_v = a, *restrict cs_v = a + n;
    if (rad == MT_SSIM_RAD) {
        if (ssim_row)
            mt_hpass_y_sums(m, mom, cols, w, c1, c2, 1, ssim_row, cs_row);
        else
            mt_hpass_y_sums(m, mom, cols, w, c1, c2, 0, NULL, cs_row);
        return;
    }
    double *ay = a + 2 * n, *ayy = a + 3 * n, *axy = a + 4 * n;
    mt_hpass(m + rad, n, w, rad, ay);
    mt_hpass(m + cols + rad, n, w, rad, ayy);
    mt_hpass(m + 2 * cols + rad, n, w, rad, axy);
    MT_SIMD
    for (ptrdiff_t j = 0; j < n; j++)
        ssim_v[j] = mt_ssim_value(ax[j], vxs[j], ay[j], ayy[j], axy[j], c1, c2, &cs_v[j]);
    if (ssim_row) *ssim_row = mt_sum(ssim_v, n);
    *cs_row = mt_sum(cs_v, n);
}

/* zipper: one row of Lab values per channel */
typedef struct {
    double *L, *A, *B;      /* one row of each Lab channel */
} mt_labrow;

/* zipper, reference side: for each centre pixel 1..cols-2 of the row rm (ru above, rd
   below), the smallest dE to its eight neighbours (strict <, raster order: the first wins a
   tie) into best[j - 1] and that neighbour's raster index 0..7 into nearest[j - 1]. */
static void mt_zipper_ref_row(mt_labrow ru, mt_labrow rm, mt_labrow rd, ptrdiff_t cols,
                              double *restrict best, uint8_t *restrict nearest)
{
    MT_SIMD
    for (ptrdiff_t j = 1; j < cols - 1; j++) {
        const double cl = rm.L[j], ca = rm.A[j], cb = rm.B[j];
        double b = INFINITY;
        int k = 0;
#define MT_NB(R, dc, idx)                                                                    \
        {                                                                                    \
            double dl = cl - R.L[j + dc], da = ca - R.A[j + dc], db = cb - R.B[j + dc];      \
            double de = sqrt((dl * dl + da * da) + db * db);                                 \
            int closer = de < b;                                                             \
            b = closer ? de : b;                                                             \
            k = closer ? idx : k;                                                            \
        }
        MT_NB(ru, -1, 0) MT_NB(ru, 0, 1) MT_NB(ru, 1, 2)
        MT_NB(rm, -1, 3) MT_NB(rm, 1, 4)
        MT_NB(rd, -1, 5) MT_NB(rd, 0, 6) MT_NB(rd, 1, 7)
#undef MT_NB
        best[j - 1] = b;
        nearest[j - 1] = (uint8_t)k;
    }
}

/* zipper, test side: the count of the centre pixels 1..cols-2 of the test row whose
   psi = dE_test(P, I) - best has |psi| > delta, I the reference's nearest neighbour
   (mt_zipper_ref_row). The three rows of the test image's ring lie in one buffer: cL is the
   centre row's L (its A at cL + cols, its B at cL + 2 cols, the same layout for the rows above
   and below), and off[k] the offset of neighbour k's L from the centre pixel's, so that the
   neighbour's three channels are loaded at one computed index (a gather) instead of being
   selected among all eight. */
static int64_t mt_zipper_test_row(const double *cL, ptrdiff_t cols, const ptrdiff_t *off,
                                  const double *best, const uint8_t *nearest, double delta)
{
    int64_t cnt = 0;
    MT_SIMD_COUNT(cnt)
    for (ptrdiff_t j = 1; j < cols - 1; j++) {
        const ptrdiff_t o = j + off[nearest[j - 1]];
        const double bl = cL[j] - cL[o], ba = cL[j + cols] - cL[o + cols];
        const double bb = cL[j + 2 * cols] - cL[o + 2 * cols];
        double psi = sqrt((bl * bl + ba * ba) + bb * bb) - best[j - 1];
        cnt += fabs(psi) > delta;
    }
    return cnt;
}

/* ------------------------------------------------------------------ per element type */
#define RGBZ_TYPE_TEMPLATE "metrics.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

/* ------------------------------------------------------------------ public entry points */
/* the window checks of both SSIM entry points */
static int mt_ssim_args_ok(const void *x, ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols,
                           const double *weights, int ntaps)
{
    if (!x || !weights || planes < 1 || ntaps < 1 || ntaps % 2 == 0
        || ntaps > RGBZ_SSIM_MAX_TAPS || rows < ntaps || cols < ntaps)
        return 0;
    for (int k = 0; k < ntaps / 2; k++)
        if (weights[k] != weights[ntaps - 1 - k]) return 0;
    return 1;
}

int MT_ENTRY(rgbz_ssim_reference)(int in_type, const void *x, ptrdiff_t planes, ptrdiff_t rows,
                                  ptrdiff_t cols, const double *weights, int ntaps,
                                  double *x_moments, int workers)
{
    if (!mt_ssim_args_ok(x, planes, rows, cols, weights, ntaps) || !x_moments)
        return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_ssim_ref, s)(x, planes, rows, cols, weights, ntaps, x_moments, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_ssim_sums)(int in_type, const void *x, const void *y,
                             const double *x_moments, ptrdiff_t planes, ptrdiff_t rows,
                             ptrdiff_t cols, const double *weights, int ntaps, double c1,
                             double c2, double *ssim_sum, double *cs_sum, int workers)
{
    if (!mt_ssim_args_ok(x, planes, rows, cols, weights, ntaps) || !y || !cs_sum)
        return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_ssim_sums, s)(x, y, x_moments, planes, rows, cols, weights, ntaps, c1, \
                                     c2, ssim_sum, cs_sum, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_planar)(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                          ptrdiff_t channels, ptrdiff_t row_stride, void *dst, int workers)
{
    if (!src || !dst || rows < 1 || cols < 1 || channels < 1 || row_stride < cols * channels)
        return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_planar, s)(src, rows, cols, channels, row_stride, dst, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_downsample2)(int in_type, const void *src, ptrdiff_t planes,
                               ptrdiff_t rows, ptrdiff_t cols, double *dst, int workers)
{
    if (!src || !dst || planes < 1 || rows < 1 || cols < 1) return RGBZ_EINVAL;
#define MT_CALL_(s, T) return RGBZ_CAT(mt_downsample2, s)(src, planes, rows, cols, dst, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_srgb_to_lab)(int in_type, const void *rgb, ptrdiff_t n, double scale,
                               double *lab, int workers)
{
    if (!rgb || !lab || n < 0 || !(scale > 0.0)) return RGBZ_EINVAL;
#define MT_CALL_(s, T) return RGBZ_CAT(mt_srgb_to_lab, s)(rgb, n, scale, lab, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_zipper_count)(int in_type, const void *ref, const void *test,
                                ptrdiff_t rows, ptrdiff_t cols, double scale, double delta,
                                int64_t *count, int workers)
{
    if (!ref || !test || !count || rows < 3 || cols < 3 || !(scale >= 0.0)
        || !(delta >= 0.0))
        return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_zipper_pass, s)((const T *)ref, (const T *)test, rows, cols, scale,    \
                                       delta, NULL, NULL, 0, count, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_zipper_reference)(int in_type, const void *ref, ptrdiff_t rows,
                                    ptrdiff_t cols, double scale, double *best,
                                    uint8_t *nearest, int workers)
{
    if (!ref || !best || !nearest || rows < 3 || cols < 3 || !(scale >= 0.0))
        return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_zipper_pass, s)((const T *)ref, NULL, rows, cols, scale, 0.0, best,    \
                                       nearest, 1, NULL, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_zipper_count_reference)(int in_type, const void *test, ptrdiff_t rows,
                                          ptrdiff_t cols, double scale, const double *best,
                                          const uint8_t *nearest, double delta,
                                          int64_t *count, int workers)
{
    if (!test || !best || !nearest || !count || rows < 3 || cols < 3 || !(scale >= 0.0)
        || !(delta >= 0.0))
        return RGBZ_EINVAL;
    uint8_t top = 0;                     /* the largest neighbour index: one vector pass */
    MT_PRAGMA(omp simd reduction(max:top))
    for (ptrdiff_t k = 0; k < (rows - 2) * (cols - 2); k++)
        top = nearest[k] > top ? nearest[k] : top;
    if (top > 7) return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_zipper_pass, s)(NULL, (const T *)test, rows, cols, scale, delta,       \
                                       (double *)best, (uint8_t *)nearest, 0, count, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}

int MT_ENTRY(rgbz_sq_diff_sum)(int in_type, const void *a, const void *b, ptrdiff_t rows,
                               ptrdiff_t cols, ptrdiff_t channels, const uint8_t *mask,
                               double *sum, int64_t *count, int workers)
{
    if (!a || !b || !sum || !count || rows < 1 || cols < 1 || channels < 1) return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_sq_diff_sum, s)(a, b, rows, cols, channels, mask, sum, count, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, MT_CALL_, return RGBZ_EINVAL)
#undef MT_CALL_
}
