/*
 * metrics.c -- image-quality metric kernels (see metrics.h for the API and layout contract).
 *
 *  - SSIM and MS-SSIM (Z. Wang, A. C. Bovik, H. R. Sheikh, E. P. Simoncelli, IEEE TIP 13(4),
 *    2004; Z. Wang, E. P. Simoncelli, A. C. Bovik, Asilomar 2003): the five local moments of a
 *    pair of planes filtered by a separable symmetric window over the windows lying wholly
 *    inside the image, one output row at a time (vertical pass into five row buffers, then
 *    horizontal pass and the SSIM formula), so no moment image is stored. The operations are
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

/* linear sRGB -> the three ratios X/Xn, Y/Yn, Z/Zn (colour's matrix, row by row) */
#define MT_XYZ(r, g, b, tx, ty, tz)                                                          \
    do {                                                                                     \
        tx = ((0.4124 * (r) + 0.3576 * (g)) + 0.1805 * (b)) / MT_XN;                          \
        ty = (0.2126 * (r) + 0.7152 * (g)) + 0.0722 * (b);                                    \
        tz = ((0.0193 * (r) + 0.1192 * (g)) + 0.9505 * (b)) / MT_ZN;                          \
    } while (0)

/* Lab of linear sRGB: fast path (ratios < 8); tmax >= 8 when a ratio needs mt_lab_any */
#define MT_LAB(r, g, b, L, A, B, tmax)                                                       \
    do {                                                                                     \
        double tx_, ty_, tz_;                                                                \
        MT_XYZ(r, g, b, tx_, ty_, tz_);                                                      \
        tmax = tx_ > tmax ? tx_ : tmax;                                                      \
        tmax = ty_ > tmax ? ty_ : tmax;                                                      \
        tmax = tz_ > tmax ? tz_ : tmax;                                                      \
        double fx_ = mt_f(tx_), fy_ = mt_f(ty_), fz_ = mt_f(tz_);                            \
        L = 116.0 * fy_ - 16.0;                                                              \
        A = 500.0 * (fx_ - fy_);                                                             \
        B = 200.0 * (fy_ - fz_);                                                             \
    } while (0)

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

/* SSIM: the horizontal pass over the five moment rows m (mt_ssim_vpass) into the five rows
   a (cols - 2 rad values each), the SSIM formula in NumPy's order, and the sums of the SSIM
   and c s values of the row (the first two rows of m, free by then, hold the values) */
static void mt_ssim_hpass(double *m, ptrdiff_t cols, const double *w, int rad,
                          double c1, double c2, double *restrict a, double *ssim_row,
                          double *cs_row)
{
    const ptrdiff_t n = cols - 2 * rad;
    const double wc = w[rad];
    for (int q = 0; q < 5; q++) {
        const double *restrict v = m + q * cols + rad;
        double *restrict o = a + q * n;
        MT_SIMD
        for (ptrdiff_t j = 0; j < n; j++) o[j] = v[j] * wc;
        for (int k = rad; k >= 1; k--) {
            const double wk = w[rad - k];
            MT_SIMD
            for (ptrdiff_t j = 0; j < n; j++) o[j] += (v[j - k] + v[j + k]) * wk;
        }
    }
    const double *ax = a, *ay = a + n, *axx = a + 2 * n, *ayy = a + 3 * n, *axy = a + 4 * n;
    double *restrict ssim_v = (double *)m, *restrict cs_v = (double *)m + cols;
    MT_SIMD
    for (ptrdiff_t j = 0; j < n; j++) {
        const double mx = ax[j], my = ay[j];
        const double vx = axx[j] - mx * mx, vy = ayy[j] - my * my, vxy = axy[j] - mx * my;
        const double lum = (2.0 * mx * my + c1) / (mx * mx + my * my + c1);
        const double cs = (2.0 * vxy + c2) / (vx + vy + c2);
        ssim_v[j] = lum * cs;
        cs_v[j] = cs;
    }
    *ssim_row = mt_sum(ssim_v, n);
    *cs_row = mt_sum(cs_v, n);
}

/* zipper: the count of one row of centre pixels 1..cols-2 (rm, tm: its Lab in the reference
   and the test image; ru, tu above, rd, td below) */
typedef struct {
    double *L, *A, *B;      /* one row of each Lab channel */
} mt_labrow;

static int64_t mt_zipper_row(mt_labrow ru, mt_labrow rm, mt_labrow rd, mt_labrow tu,
                             mt_labrow tm, mt_labrow td, ptrdiff_t cols, double delta)
{
    int64_t cnt = 0;
    MT_SIMD_COUNT(cnt)
    for (ptrdiff_t j = 1; j < cols - 1; j++) {
        const double cl = rm.L[j], ca = rm.A[j], cb = rm.B[j];
        const double ql = tm.L[j], qa = tm.A[j], qb = tm.B[j];
        double best = INFINITY, bl = 0.0, ba = 0.0, bb = 0.0;
#define MT_NB(R, T, dc)                                                                      \
        {                                                                                    \
            double dl = cl - R.L[j + dc], da = ca - R.A[j + dc], db = cb - R.B[j + dc];      \
            double de = sqrt((dl * dl + da * da) + db * db);                                 \
            int closer = de < best;                                                          \
            best = closer ? de : best;                                                       \
            bl = closer ? ql - T.L[j + dc] : bl;                                             \
            ba = closer ? qa - T.A[j + dc] : ba;                                             \
            bb = closer ? qb - T.B[j + dc] : bb;                                             \
        }
        MT_NB(ru, tu, -1) MT_NB(ru, tu, 0) MT_NB(ru, tu, 1)
        MT_NB(rm, tm, -1) MT_NB(rm, tm, 1)
        MT_NB(rd, td, -1) MT_NB(rd, td, 0) MT_NB(rd, td, 1)
#undef MT_NB
        double psi = sqrt((bl * bl + ba * ba) + bb * bb) - best;
        cnt += fabs(psi) > delta;
    }
    return cnt;
}

/* ------------------------------------------------------------------ per element type */
#define RGBZ_TYPE_TEMPLATE "metrics.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

/* ------------------------------------------------------------------ public entry points */
int MT_ENTRY(rgbz_ssim_sums)(int in_type, const void *x, const void *y, ptrdiff_t planes,
                             ptrdiff_t rows, ptrdiff_t cols, const double *weights, int ntaps,
                             double c1, double c2, double *ssim_sum, double *cs_sum, int workers)
{
    if (!x || !y || !weights || !ssim_sum || !cs_sum || planes < 1 || ntaps < 1
        || ntaps % 2 == 0 || ntaps > RGBZ_SSIM_MAX_TAPS || rows < ntaps || cols < ntaps)
        return RGBZ_EINVAL;
    for (int k = 0; k < ntaps / 2; k++)
        if (weights[k] != weights[ntaps - 1 - k]) return RGBZ_EINVAL;
#define MT_CALL_(s, T)                                                                       \
    return RGBZ_CAT(mt_ssim_sums, s)(x, y, planes, rows, cols, weights, ntaps, c1, c2, ssim_sum,   \
                              cs_sum, workers)
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
    return RGBZ_CAT(mt_zipper_count, s)(ref, test, rows, cols, scale, delta, count, workers)
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
