/*
 * metrics_dispatch.c -- the public entry points of the metric kernels (metrics.h): each
 * calls the build of metrics.c for the best instruction set this CPU supports.
 *
 * csrc/meson.build compiles metrics.c for the baseline (suffix `generic`) and, with GCC or
 * Clang on x86-64, for AVX2 and AVX-512, defining RGBZ_METRICS_HAVE_AVX2 / _AVX512 here
 * for the builds it made. The CPU is asked once (__builtin_cpu_supports, which also checks
 * that the OS saves the vector registers).
 */
#include "metrics.h"
#include "metrics_isa.h"

static int mt_isa_available(int isa)
{
#if defined(RGBZ_METRICS_HAVE_AVX2) || defined(RGBZ_METRICS_HAVE_AVX512)
    __builtin_cpu_init();
#endif
    switch (isa) {
    case RGBZ_ISA_GENERIC:
        return 1;
#if defined(RGBZ_METRICS_HAVE_AVX2)
    case RGBZ_ISA_AVX2:
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#endif
#if defined(RGBZ_METRICS_HAVE_AVX512)
    case RGBZ_ISA_AVX512:
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")
               && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw")
               && __builtin_cpu_supports("fma");
#endif
    default:
        return 0;
    }
}

static int mt_best_isa(void)
{
    for (int isa = RGBZ_ISA_AVX512; isa > RGBZ_ISA_GENERIC; isa--)
        if (mt_isa_available(isa)) return isa;
    return RGBZ_ISA_GENERIC;
}

/* -1 until the first call; every thread computes the same value, so the race is benign */
static int mt_isa = -1;

static int mt_current(void)
{
    if (mt_isa < 0) mt_isa = mt_best_isa();
    return mt_isa;
}

int rgbz_metrics_isa(void)
{
    return mt_current();
}

int rgbz_metrics_isa_available(int isa)
{
    return mt_isa_available(isa);
}

int rgbz_metrics_use_isa(int isa)
{
    if (isa == RGBZ_ISA_BEST) {
        mt_isa = mt_best_isa();
        return RGBZ_OK;
    }
    if (!mt_isa_available(isa)) return RGBZ_EINVAL;
    mt_isa = isa;
    return RGBZ_OK;
}

#if defined(RGBZ_METRICS_HAVE_AVX2)
#define MT_CASE_AVX2(name, ...) \
    case RGBZ_ISA_AVX2: return RGBZ_METRICS_ENTRY(name, avx2)(__VA_ARGS__);
#else
#define MT_CASE_AVX2(name, ...)
#endif
#if defined(RGBZ_METRICS_HAVE_AVX512)
#define MT_CASE_AVX512(name, ...) \
    case RGBZ_ISA_AVX512: return RGBZ_METRICS_ENTRY(name, avx512)(__VA_ARGS__);
#else
#define MT_CASE_AVX512(name, ...)
#endif

#define MT_DISPATCH(name, ...)                                                               \
    switch (mt_current()) {                                                                  \
    MT_CASE_AVX512(name, __VA_ARGS__)                                                        \
    MT_CASE_AVX2(name, __VA_ARGS__)                                                          \
    default: return RGBZ_METRICS_ENTRY(name, generic)(__VA_ARGS__);                          \
    }

int rgbz_ssim_sums(int in_type, const void *x, const void *y, const double *x_moments,
                   ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols, const double *weights,
                   int ntaps, double c1, double c2, double *ssim_sum, double *cs_sum,
                   int workers)
{
    MT_DISPATCH(rgbz_ssim_sums, in_type, x, y, x_moments, planes, rows, cols, weights, ntaps,
                c1, c2, ssim_sum, cs_sum, workers)
}

int rgbz_ssim_reference(int in_type, const void *x, ptrdiff_t planes, ptrdiff_t rows,
                        ptrdiff_t cols, const double *weights, int ntaps, double *x_moments,
                        int workers)
{
    MT_DISPATCH(rgbz_ssim_reference, in_type, x, planes, rows, cols, weights, ntaps,
                x_moments, workers)
}

int rgbz_planar(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                ptrdiff_t channels, ptrdiff_t row_stride, void *dst, int workers)
{
    MT_DISPATCH(rgbz_planar, in_type, src, rows, cols, channels, row_stride, dst, workers)
}

int rgbz_downsample2(int in_type, const void *src, ptrdiff_t planes, ptrdiff_t rows,
                     ptrdiff_t cols, double *dst, int workers)
{
    MT_DISPATCH(rgbz_downsample2, in_type, src, planes, rows, cols, dst, workers)
}

int rgbz_srgb_to_lab(int in_type, const void *rgb, ptrdiff_t n, double scale, double *lab,
                     int workers)
{
    MT_DISPATCH(rgbz_srgb_to_lab, in_type, rgb, n, scale, lab, workers)
}

int rgbz_zipper_count(int in_type, const void *ref, const void *test, ptrdiff_t rows,
                      ptrdiff_t cols, double scale, double delta, int64_t *count, int workers)
{
    MT_DISPATCH(rgbz_zipper_count, in_type, ref, test, rows, cols, scale, delta, count,
                workers)
}

int rgbz_zipper_reference(int in_type, const void *ref, ptrdiff_t rows, ptrdiff_t cols,
                          double scale, double *best, uint8_t *nearest, int workers)
{
    MT_DISPATCH(rgbz_zipper_reference, in_type, ref, rows, cols, scale, best, nearest,
                workers)
}

int rgbz_zipper_count_reference(int in_type, const void *test, ptrdiff_t rows, ptrdiff_t cols,
                                double scale, const double *best, const uint8_t *nearest,
                                double delta, int64_t *count, int workers)
{
    MT_DISPATCH(rgbz_zipper_count_reference, in_type, test, rows, cols, scale, best, nearest,
                delta, count, workers)
}

int rgbz_sq_diff_sum(int in_type, const void *a, const void *b, ptrdiff_t rows, ptrdiff_t cols,
                     ptrdiff_t channels, const uint8_t *mask, double *sum, int64_t *count,
                     int workers)
{
    MT_DISPATCH(rgbz_sq_diff_sum, in_type, a, b, rows, cols, channels, mask, sum, count,
                workers)
}
