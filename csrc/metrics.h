/*
 * metrics.h -- C API of the image-quality metric kernels (metrics.c), plain C99, no Python.h.
 *
 * The kernels behind rgbz_fast.metrics: SSIM / MS-SSIM moments with a separable symmetric
 * window (Wang et al. 2004, 2003), the 2 x 2 mean decimation between MS-SSIM scales, sRGB ->
 * CIELAB (IEC 61966-2-1, CIE 15) and the zipper-effect metric of Lu & Tan 2003 (Rebiere et
 * al. eqs. 29-31) fused with that conversion.
 *
 * Layout: every array is C-contiguous, row-major, with strides in elements. Planar inputs are
 * (planes, rows, cols); colour images are interleaved (rows, cols, 3). Element types are the
 * RGBZ_T_* codes of rgbz.h (uint8, uint16, float32, float64); every computation is in double.
 * The Python layer validates and allocates the outputs; a kernel returns RGBZ_OK,
 * RGBZ_EINVAL (an argument Python should have rejected) or RGBZ_ENOMEM (scratch).
 * Results never depend on `workers` (threads; <= 0 means the OpenMP default): every sum is
 * formed per row and the rows are added in order by one thread.
 */
#ifndef RGBZ_METRICS_H
#define RGBZ_METRICS_H

#include <stddef.h>
#include <stdint.h>

#include "rgbz.h"

/* Longest SSIM window (taps) the kernel accepts. */
#define RGBZ_SSIM_MAX_TAPS 255

/*
 * SSIM sums of one image pair x, y: planar (planes, rows, cols) arrays of in_type.
 *   weights: ntaps (odd, <= RGBZ_SSIM_MAX_TAPS, <= rows and cols) symmetric, normalised 1-D
 *            window; the 2-D window is its outer product. The five local moments are filtered
 *            along the rows, then the columns, with scipy.ndimage.correlate1d's order of
 *            operations for symmetric weights (so they equal gaussian_filter's bit for bit).
 *   x_moments: what x alone gives (rgbz_ssim_reference of this x and window), for the calls
 *            that compare one reference with many images; NULL: computed here. The sums are
 *            the same bit for bit either way.
 *   c1, c2:  the constants (0.01 L)^2 and (0.03 L)^2.
 *   ssim_sum[p], cs_sum[p]: the sums, over the (rows - ntaps + 1) x (cols - ntaps + 1) windows
 *            lying wholly inside plane p, of the SSIM map l c s and of the contrast-structure
 *            map c s = (2 s_xy + c2) / (s_x^2 + s_y^2 + c2). ssim_sum NULL: only the cs sums
 *            (the scales of MS-SSIM between the first and the last), the same values.
 */
int rgbz_ssim_sums(int in_type, const void *x, const void *y, const double *x_moments,
                   ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols, const double *weights,
                   int ntaps, double c1, double c2, double *ssim_sum, double *cs_sum,
                   int workers);

/*
 * The reference side of the SSIM of x (planar, as in rgbz_ssim_sums, same window): for each
 * plane p and window row i, two rows of (cols - ntaps + 1) doubles at x_moments +
 * 2 (p (rows - ntaps + 1) + i) (cols - ntaps + 1): the local means, then the local variances.
 */
int rgbz_ssim_reference(int in_type, const void *x, ptrdiff_t planes, ptrdiff_t rows,
                        ptrdiff_t cols, const double *weights, int ntaps, double *x_moments,
                        int workers);

/*
 * Planar copy: src (rows, cols, channels) of in_type, its rows row_stride elements apart and
 * its pixels contiguous (a crop of an interleaved image) -> dst (channels, rows, cols),
 * contiguous: what the SSIM kernels read.
 */
int rgbz_planar(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                ptrdiff_t channels, ptrdiff_t row_stride, void *dst, int workers);

/*
 * 2 x 2 mean decimation (Wang et al.'s MS-SSIM code): src planar (planes, rows, cols) of
 * in_type -> dst (planes, (rows + 1) / 2, (cols + 1) / 2) double,
 * dst = ((a00 + a01) + (a10 + a11)) / 4, an odd last row or column repeated (NumPy's
 * 'symmetric' pad), the order of operations of NumPy's mean over the two 2-long axes.
 */
int rgbz_downsample2(int in_type, const void *src, ptrdiff_t planes, ptrdiff_t rows,
                     ptrdiff_t cols, double *dst, int workers);

/*
 * sRGB -> CIE L*a*b* (D65, CIE 1931 2 degree observer) of n interleaved RGB pixels of in_type,
 * code values over `scale` (255 for 8-bit, 65535 for 16-bit, 1 for [0, 1]; values outside
 * [0, scale] are converted as they are): lab (n, 3) double, L* in 0..100.
 * colour-science's XYZ_to_Lab(sRGB_to_XYZ(rgb / scale)) with its constants (metrics.c).
 */
int rgbz_srgb_to_lab(int in_type, const void *rgb, ptrdiff_t n, double scale, double *lab,
                     int workers);

/*
 * Zipper-effect metric (Lu & Tan 2003; Rebiere et al. eqs. 29-31) of two (rows, cols, 3)
 * interleaved images of in_type, rows, cols >= 3.
 *   scale > 0: the images are sRGB code values over `scale`, converted as rgbz_srgb_to_lab
 *              does, three rows at a time (no Lab image is stored);
 *   scale = 0: the images are CIELAB already.
 *   count:     the number of the (rows - 2) x (cols - 2) interior pixels whose psi =
 *              dE_test(P, I) - dE_ref(P, I) has |psi| > delta, where I is the neighbour of P
 *              (8-neighbourhood) with the smallest reference dE, the first in raster order
 *              on a tie.
 */
int rgbz_zipper_count(int in_type, const void *ref, const void *test, ptrdiff_t rows,
                      ptrdiff_t cols, double scale, double delta, int64_t *count, int workers);

/*
 * The zipper count in two halves, for one reference compared with many images:
 * rgbz_zipper_reference finds, for each of the (rows - 2) x (cols - 2) interior pixels P of
 * ref (row-major), the neighbour I with the smallest reference dE: best = that dE, nearest =
 * I's raster index in the 3 x 3 neighbourhood without P (0..7: the row above left to right,
 * left, right, the row below); rgbz_zipper_count_reference counts the pixels of test with
 * |dE_test(P, I) - best| > delta. The count equals rgbz_zipper_count's bit for bit.
 */
int rgbz_zipper_reference(int in_type, const void *ref, ptrdiff_t rows, ptrdiff_t cols,
                          double scale, double *best, uint8_t *nearest, int workers);
int rgbz_zipper_count_reference(int in_type, const void *test, ptrdiff_t rows, ptrdiff_t cols,
                                double scale, const double *best, const uint8_t *nearest,
                                double delta, int64_t *count, int workers);

/*
 * Sum of squared differences (the MSE of the PSNRs): a, b of in_type hold rows x cols pixels of
 * `channels` elements each, C-contiguous. A pixel counts when mask is NULL or mask[r * cols + c]
 * is nonzero (all its channels then count).
 *   sum:   the sum of (a - b)^2 over the counted elements, exact for the integer types (summed
 *          in 64-bit integers), in a fixed order for the float types;
 *   count: the number of counted elements.
 */
int rgbz_sq_diff_sum(int in_type, const void *a, const void *b, ptrdiff_t rows, ptrdiff_t cols,
                     ptrdiff_t channels, const uint8_t *mask, double *sum, int64_t *count,
                     int workers);

/*
 * Instruction sets (metrics_dispatch.c). The kernels are compiled for each set the compiler
 * offers on x86-64 (AVX-512: F, VL, DQ, BW with 512-bit vectors; AVX2), and for the baseline;
 * every call runs the best one the CPU supports. All give the same results bit for bit (no
 * fused multiply-add, sums in a fixed order).
 *   rgbz_metrics_isa():        the set in use (RGBZ_ISA_*).
 *   rgbz_metrics_use_isa(isa): use `isa` from now on, or the best one for RGBZ_ISA_BEST;
 *                              RGBZ_EINVAL when it was not built or the CPU lacks it.
 *                              Not thread-safe: for tests and benchmarks.
 */
#define RGBZ_ISA_BEST (-1)
#define RGBZ_ISA_GENERIC 0
#define RGBZ_ISA_AVX2 1
#define RGBZ_ISA_AVX512 2
int rgbz_metrics_isa(void);
int rgbz_metrics_use_isa(int isa);
/* whether `isa` was compiled and runs on this CPU (1) or not (0) */
int rgbz_metrics_isa_available(int isa);

#endif /* RGBZ_METRICS_H */
