/*
 * metrics_isa.h -- internal: the entry points of metrics.c for each instruction set it is
 * compiled for (csrc/meson.build builds it once per set, with -DRGBZ_METRICS_ISA=<suffix>),
 * which metrics_dispatch.c chooses from at run time. Not part of the C API (metrics.h).
 */
#ifndef RGBZ_METRICS_ISA_H
#define RGBZ_METRICS_ISA_H

#include <stddef.h>
#include <stdint.h>
#include "rgbz_templating.h"

/* the entry point `name` of the build for instruction set `isa`: name_isa */
#define RGBZ_METRICS_ENTRY(name, isa) RGBZ_CAT(name, isa)

#define RGBZ_METRICS_DECLARE(isa)                                                            \
    int RGBZ_METRICS_ENTRY(rgbz_ssim_sums, isa)(                                             \
        int in_type, const void *x, const void *y, const double *x_moments,                   \
        ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols, const double *weights, int ntaps,   \
        double c1, double c2, double *ssim_sum, double *cs_sum, int workers);                 \
    int RGBZ_METRICS_ENTRY(rgbz_ssim_reference, isa)(                                        \
        int in_type, const void *x, ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols,         \
        const double *weights, int ntaps, double *x_moments, int workers);                    \
    int RGBZ_METRICS_ENTRY(rgbz_planar, isa)(                                                \
        int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols, ptrdiff_t channels,     \
        ptrdiff_t row_stride, void *dst, int workers);                                        \
    int RGBZ_METRICS_ENTRY(rgbz_downsample2, isa)(                                           \
        int in_type, const void *src, ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols,       \
        double *dst, int workers);                                                            \
    int RGBZ_METRICS_ENTRY(rgbz_srgb_to_lab, isa)(                                           \
        int in_type, const void *rgb, ptrdiff_t n, double scale, double *lab, int workers);   \
    int RGBZ_METRICS_ENTRY(rgbz_zipper_count, isa)(                                          \
        int in_type, const void *ref, const void *test, ptrdiff_t rows, ptrdiff_t cols,       \
        double scale, double delta, int64_t *count, int workers);                              \
    int RGBZ_METRICS_ENTRY(rgbz_zipper_reference, isa)(                                      \
        int in_type, const void *ref, ptrdiff_t rows, ptrdiff_t cols, double scale,           \
        double *best, uint8_t *nearest, int workers);                                         \
    int RGBZ_METRICS_ENTRY(rgbz_zipper_count_reference, isa)(                                \
        int in_type, const void *test, ptrdiff_t rows, ptrdiff_t cols, double scale,          \
        const double *best, const uint8_t *nearest, double delta, int64_t *count,             \
        int workers);                                                                         \
    int RGBZ_METRICS_ENTRY(rgbz_sq_diff_sum, isa)(                                           \
        int in_type, const void *a, const void *b, ptrdiff_t rows, ptrdiff_t cols,             \
        ptrdiff_t channels, const uint8_t *mask, double *sum, int64_t *count, int workers);

RGBZ_METRICS_DECLARE(generic)
RGBZ_METRICS_DECLARE(avx2)
RGBZ_METRICS_DECLARE(avx512)

#endif /* RGBZ_METRICS_ISA_H */
