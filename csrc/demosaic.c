/*
 * demosaic.c -- Malvar-He-Cutler (2004) gradient-corrected linear demosaicing
 * of a Bayer CFA, as a C kernel.
 *
 * H. S. Malvar, L. He, R. Cutler, "High-quality linear interpolation for
 * demosaicing of Bayer-patterned color images", Proc. ICASSP 2004. The filter
 * coefficients and the per-site choice of filter are those of
 * colour-demosaicing's demosaicing_CFA_Bayer_Malvar2004, which the tests use
 * as the reference (to 1e-6).
 *
 * Layout: input rows x cols row-major; output rows x cols x 3 (R, G, B)
 * row-major, interleaved. `phase` gives the colour of the 2x2 Bayer quad in
 * raster order (codes R=0, G=1, B=2), e.g. GRBG = {1, 0, 2, 1}.
 * Borders: mode 0 = "reflect" (scipy.ndimage's half-sample mirror, as the
 * reference), mode 1 = "period" (shift by whole periods, keeps the colour).
 * No clipping (the reference does not clip); the caller clips if it wants.
 */
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"

static inline ptrdiff_t dm_reflect(ptrdiff_t i, ptrdiff_t n)
{
    /* scipy 'reflect': (d c b a | a b c d | d c b a) */
    if (n == 1) return 0;
    ptrdiff_t period = 2 * n;
    i %= period;
    if (i < 0) i += period;
    return i < n ? i : period - 1 - i;
}

static inline ptrdiff_t dm_period(ptrdiff_t i, ptrdiff_t n)
{
    if (i < 0) return i + 2 * ((-i + 1) / 2);
    if (i >= n) return i - 2 * ((i - n + 2) / 2);
    return i;
}

#define DM_TEMPLATE(IN_T, IS, OUT_T, OS)                                                        \
static void rgbz_malvar_##IS##_##OS(const IN_T *src, OUT_T *dst, ptrdiff_t rows, ptrdiff_t cols, \
                                    const int32_t *phase, const ptrdiff_t *colmap, int mode,    \
                                    int workers)                                                \
{                                                                                               \
    (void)workers;                                                                              \
    DM_PARALLEL                                                                                 \
    for (ptrdiff_t y = 0; y < rows; y++) {                                                      \
        const IN_T *rp[5];                                                                      \
        for (int d = -2; d <= 2; d++) {                                                         \
            ptrdiff_t yy = mode ? dm_period(y + d, rows) : dm_reflect(y + d, rows);             \
            rp[d + 2] = src + yy * cols;                                                        \
        }                                                                                       \
        const int32_t *ph = phase + 2 * (y & 1);                                                \
        for (ptrdiff_t x = 0; x < cols; x++) {                                                  \
            const ptrdiff_t *cm = colmap + x + 2;                                               \
            /* P(dy, dx): pixel at offset (dy, dx) */                                           \
            double c0 = (double)rp[2][cm[0]];                                                   \
            double n4 = (double)rp[1][cm[0]] + (double)rp[3][cm[0]] + (double)rp[2][cm[-1]] +   \
                        (double)rp[2][cm[1]];                                                   \
            double far4 = (double)rp[0][cm[0]] + (double)rp[4][cm[0]] + (double)rp[2][cm[-2]] + \
                          (double)rp[2][cm[2]];                                                 \
            double diag = (double)rp[1][cm[-1]] + (double)rp[1][cm[1]] + (double)rp[3][cm[-1]] +\
                          (double)rp[3][cm[1]];                                                 \
            double hz2 = (double)rp[2][cm[-2]] + (double)rp[2][cm[2]];                          \
            double vt2 = (double)rp[0][cm[0]] + (double)rp[4][cm[0]];                           \
            double hz1 = (double)rp[2][cm[-1]] + (double)rp[2][cm[1]];                          \
            double vt1 = (double)rp[1][cm[0]] + (double)rp[3][cm[0]];                           \
            int ch = ph[x & 1];                                                                 \
            double r, g, b;                                                                     \
            if (ch == 1) {                                                                      \
                /* green site: horizontal and vertical colour-difference filters */             \
                double hv = (5 * c0 + 4 * hz1 - hz2 - diag + 0.5 * vt2) / 8;                    \
                double vv = (5 * c0 + 4 * vt1 - vt2 - diag + 0.5 * hz2) / 8;                    \
                g = c0;                                                                         \
                int row_colour = ph[(x & 1) ^ 1]; /* R or B, the colour of this row */          \
                if (row_colour == 0) { r = hv; b = vv; } else { b = hv; r = vv; }               \
            } else {                                                                            \
                double gg = (4 * c0 + 2 * n4 - far4) / 8;                                       \
                double oo = (6 * c0 + 2 * diag - 1.5 * far4) / 8;                               \
                g = gg;                                                                         \
                if (ch == 0) { r = c0; b = oo; } else { b = c0; r = oo; }                       \
            }                                                                                   \
            OUT_T *o = dst + 3 * (y * cols + x);                                                \
            o[0] = (OUT_T)r;                                                                    \
            o[1] = (OUT_T)g;                                                                    \
            o[2] = (OUT_T)b;                                                                    \
        }                                                                                       \
    }                                                                                           \
}

#ifdef _OPENMP
#define DM_PARALLEL _Pragma("omp parallel for schedule(static) num_threads(workers > 0 ? workers : omp_get_max_threads())")
#else
#define DM_PARALLEL
#endif

DM_TEMPLATE(uint8_t, u8, float, f32)
DM_TEMPLATE(uint8_t, u8, double, f64)
DM_TEMPLATE(uint16_t, u16, float, f32)
DM_TEMPLATE(uint16_t, u16, double, f64)
DM_TEMPLATE(float, f32, float, f32)
DM_TEMPLATE(float, f32, double, f64)
DM_TEMPLATE(double, f64, float, f32)
DM_TEMPLATE(double, f64, double, f64)

int rgbz_demosaic_malvar(int in_type, int out_type, const void *src, void *dst,
                                   ptrdiff_t rows, ptrdiff_t cols, const int32_t *phase,
                                   int mode, int workers)
{
    if (!src || !dst || !phase || rows < 2 || cols < 2 || (mode != 0 && mode != 1))
        return RGBZ_EINVAL;
    if (out_type != RGBZ_T_F32 && out_type != RGBZ_T_F64) return RGBZ_EINVAL;
    int greens = 0;
    for (int i = 0; i < 4; i++) {
        if (phase[i] < 0 || phase[i] > 2) return RGBZ_EINVAL;
        greens += phase[i] == 1;
    }
    /* a Bayer quad: two greens on one diagonal, red and blue on the other */
    int main_diag = phase[0] == 1 && phase[3] == 1 && phase[1] + phase[2] == 2 && phase[1] != 1;
    int anti_diag = phase[1] == 1 && phase[2] == 1 && phase[0] + phase[3] == 2 && phase[0] != 1;
    if (greens != 2 || !(main_diag || anti_diag)) return RGBZ_EINVAL;
    ptrdiff_t *colmap = (ptrdiff_t *)malloc((size_t)(cols + 4) * sizeof(ptrdiff_t));
    if (!colmap) return RGBZ_ENOMEM;
    for (ptrdiff_t i = 0; i < cols + 4; i++)
        colmap[i] = mode ? dm_period(i - 2, cols) : dm_reflect(i - 2, cols);
    int f64 = out_type == RGBZ_T_F64;
    int st = RGBZ_OK;
    switch (in_type) {
    case RGBZ_T_U8:
        if (f64) rgbz_malvar_u8_f64(src, dst, rows, cols, phase, colmap, mode, workers);
        else rgbz_malvar_u8_f32(src, dst, rows, cols, phase, colmap, mode, workers);
        break;
    case RGBZ_T_U16:
        if (f64) rgbz_malvar_u16_f64(src, dst, rows, cols, phase, colmap, mode, workers);
        else rgbz_malvar_u16_f32(src, dst, rows, cols, phase, colmap, mode, workers);
        break;
    case RGBZ_T_F32:
        if (f64) rgbz_malvar_f32_f64(src, dst, rows, cols, phase, colmap, mode, workers);
        else rgbz_malvar_f32_f32(src, dst, rows, cols, phase, colmap, mode, workers);
        break;
    case RGBZ_T_F64:
        if (f64) rgbz_malvar_f64_f64(src, dst, rows, cols, phase, colmap, mode, workers);
        else rgbz_malvar_f64_f32(src, dst, rows, cols, phase, colmap, mode, workers);
        break;
    default:
        st = RGBZ_EINVAL;
    }
    free(colmap);
    return st;
}
