/*
 * colour_isp.h -- C API of the fused colour ISP (colour_isp.c), plain C99, no Python.h.
 *
 * rgbz_fast.isp.ColourISP.run without its stages, in three passes over the frame instead of
 * one NumPy pass (and one frame-size temporary) per stage:
 *
 *   rgbz_ci_defect_candidates  tests 1 and 2 of the defect detection on every colour pixel
 *                              (isp._defects._candidates);
 *   rgbz_ci_defect_confirm     test 3 on those few candidates (isp._defects._confirm); the
 *                              defects go back to Python for the median fixes;
 *   rgbz_ci_phase_sums         the grey-world sums and counts of each 2x2 phase of the
 *                              complete CFA (isp._stages.grey_world_gains);
 *   rgbz_ci_render_<RS>        white balance, demosaic (Malvar or bilinear), colour matrix, clip, sRGB
 *                              encoding and quantisation, row by row: the white-balanced rows
 *                              live in a ring of 8 rows per thread (they stay in cache), and
 *                              the codes come from the thresholds of isp._encode_table (the
 *                              smallest value of each code) instead of a power.
 *
 * Menon 2007 is no row pass of the render (its stages read whole planes); its chain runs
 * the defect and sums passes, then
 *
 *   rgbz_ci_balance_<RS>       the white balance of the render into a REAL frame;
 *   (rgbz_demosaic_menon)      the demosaic, its own kernel (demosaic_menon.c);
 *   rgbz_ci_encode_rgb_<RS>    the render's tail on the RGB image: colour matrix, clip and
 *                              the codes of the same thresholds, in chunks of pixels.
 *
 * Every pass gives the results of the NumPy stages bit for bit (tests/isp/test_fused.py),
 * except: the sums of a float CFA (added in another order: a relative difference of order
 * 1e-16) and a colour matrix other than the identity (NumPy's matmul may round differently:
 * a linear value a few ulp off, so a code may differ by one at a threshold).
 *
 * Layout: src rows x cols, row-major, of element type in_type (rgbz_type); out rows x cols x 3
 * (R, G, B interleaved), uint8 (bits 8) or uint16 (bits 16). Status codes of rgbz.h.
 */
#ifndef RGBZ_COLOUR_ISP_H
#define RGBZ_COLOUR_ISP_H

#include <stddef.h>
#include <stdint.h>

#include "rgbz.h"

/* neighbours of one tile position in the defect test: the same-colour pixels of the 5x5
   window (12 on a Bayer green, 8 on red and blue) */
enum { RGBZ_CI_MAX_NEIGHBOURS = 24 };

/*
 * Tests 1 and 2 of the defect detection (rgbz_fast.isp.DefectCorrection) on a P x Q tile:
 * for a colour pixel p at tile position k = (y % P) * Q + x % Q, its neighbours are the
 * pixels at (y + offs[k][i][0], x + offs[k][i][1]), i < noff[k], inside the frame (noff[k]
 * < 0: a Z position, never tested). With v, mx, mn the float32 values of p and of the max
 * and min of its neighbours, p is a candidate when
 *     (v - mx > thr and v - mx > k (mx - mn)) or (mn - v > thr and mn - v > k (mx - mn)).
 * The candidates' rows, columns, v - mx, mn - v and mx - mn go to rr, cc, hot, cold, spread
 * (capacity entries at most, in no particular order); *count gets their number, which may
 * exceed capacity (then only capacity were written: call again with more room).
 */
int rgbz_ci_defect_candidates(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                              int32_t P, int32_t Q, const int32_t *noff, const int32_t *offs,
                              float thr, float k, ptrdiff_t capacity, int64_t *rr, int64_t *cc,
                              float *hot, float *cold, float *spread, ptrdiff_t *count,
                              int workers);

/*
 * Test 3 of the defect detection on the n candidates of rgbz_ci_defect_candidates (rr, cc,
 * hot, cold, spread: its outputs; thr and k its thresholds; f the cross factor): ok[i] = 1
 * when candidate i is a defect, the decisions of isp._defects._confirm (the same values:
 * float32 pixels in double, NumPy's pairwise sum of each 24-entry neighbourhood, the trimmed
 * mean, k * spread in float32). RGBZ_EINVAL for a candidate outside the frame.
 */
int rgbz_ci_defect_confirm(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                           int32_t P, int32_t Q, const int32_t *noff, const int32_t *offs,
                           ptrdiff_t n, const int64_t *rr, const int64_t *cc, const float *hot,
                           const float *cold, const float *spread, float thr, float k,
                           double f, uint8_t *ok);

/*
 * Grey-world sums of a complete Bayer CFA: for each 2x2 phase (raster order) the sum and the
 * number of the values below `white` (compared in float32 for a float32 CFA, in double
 * otherwise, as NumPy compares them with a Python float). Integer CFAs are summed exactly.
 */
int rgbz_ci_phase_sums(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                       double white, double *sums, int64_t *counts, int workers);

/*
 * White balance .. output of a complete Bayer CFA, in the precision of the name:
 *   b = clip?((REAL) v - black) * scale[colour])           (isp.white_balance)
 *   rgb = demosaic of b, in double, rounded to REAL         (isp.demosaic, border `mode`;
 *         `method` an rgbz_demosaic_method: Malvar 2004 or bilinear, demosaic.c's formulas)
 *   lin = clip(matrix @ rgb, 0, 1), matrix NULL: identity  (isp.correct_colour)
 *   code = number of thresholds[1 .. 2^bits - 1] <= lin    (isp._encode_table)
 * phase: the colour codes (R 0, G 1, B 2) of the 2x2 Bayer quad in raster order; scale: the
 * R, G, B gains over (white - black); matrix: 9 values, row-major; thresholds: 2^bits
 * non-decreasing values of [0, 1] (t[0] = 0). At least 2 x 2 pixels.
 */
int rgbz_ci_render_f32(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                       const int32_t *phase, int mode, int method, const float *scale,
                       float black, int clip, const float *matrix, const float *thresholds,
                       int bits, void *out, int workers);
int rgbz_ci_render_f64(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                       const int32_t *phase, int mode, int method, const double *scale,
                       double black, int clip, const double *matrix, const double *thresholds,
                       int bits, void *out, int workers);

/*
 * The white balance of rgbz_ci_render alone: out[y][x] = clip?(((REAL) src[y][x] - black) *
 * scale[colour]) (isp.white_balance bit for bit), out rows x cols of REAL. At least 1 x 1.
 */
int rgbz_ci_balance_f32(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                        const int32_t *phase, const float *scale, float black, int clip,
                        float *out, int workers);
int rgbz_ci_balance_f64(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                        const int32_t *phase, const double *scale, double black, int clip,
                        double *out, int workers);

/*
 * The tail of rgbz_ci_render on npix pixels of linear RGB (rgb: npix x 3, interleaved):
 *   lin = clip(matrix @ rgb, 0, 1), matrix NULL: identity  (isp.correct_colour)
 *   code = number of thresholds[1 .. 2^bits - 1] <= lin    (isp._encode_table)
 * into out (npix x 3, uint8 for bits 8, else uint16); the same code (ci_matrix, ci_encode) as
 * the render. For an image that another kernel demosaiced (Menon 2007).
 */
int rgbz_ci_encode_rgb_f32(const float *rgb, ptrdiff_t npix, const float *matrix,
                           const float *thresholds, int bits, void *out, int workers);
int rgbz_ci_encode_rgb_f64(const double *rgb, ptrdiff_t npix, const double *matrix,
                           const double *thresholds, int bits, void *out, int workers);

#endif /* RGBZ_COLOUR_ISP_H */
