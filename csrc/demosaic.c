/*
 * demosaic.c -- Malvar-He-Cutler (2004) gradient-corrected linear demosaicing
 * and bilinear demosaicing of a Bayer CFA, as C kernels, and the entry point of every
 * demosaic (rgbz_demosaic; Menon 2007 is demosaic_menon.c).
 *
 * H. S. Malvar, L. He, R. Cutler, "High-quality linear interpolation for
 * demosaicing of Bayer-patterned color images", Proc. ICASSP 2004. The filter
 * coefficients (the paper's Fig. 2, as sums of the 5x5 neighbourhood) and the
 * per-site choice of filter are those of colour-demosaicing's
 * demosaicing_CFA_Bayer_Malvar2004, which tests/isp/test_demosaic.py uses as the
 * reference (to 1e-6).
 *
 * Bilinear: colour-demosaicing's demosaicing_CFA_Bayer_bilinear, which convolves
 * each colour's masked plane with [[0,1,0],[1,4,1],[0,1,0]]/4 (green) or
 * [[1,2,1],[2,4,2],[1,2,1]]/4 (red, blue) through scipy.ndimage.convolve. The
 * weights are powers of two, so each product is exact, and scipy adds the taps in
 * double from 0.0 in raster order; dm_bilinear_pixel adds the same nonzero taps
 * in the same order (a masked tap adds +-0, which changes no finite sum), so the
 * result is the reference's bit for bit. With the reflect border the reference
 * masks before it mirrors, so a mirrored tap of another colour adds nothing: the
 * frame's outer pixels take dm_bilinear_taps (demosaic_bilinear.h), the rule
 * itself.
 *
 * Layout: input rows x cols row-major; output rows x cols x 3 (R, G, B)
 * row-major, interleaved. `phase` gives the colour of the 2x2 Bayer quad in
 * raster order (codes R=0, G=1, B=2), e.g. GRBG = {1, 0, 2, 1}.
 * Borders (rgbz_demosaic_mode): RGBZ_DM_REFLECT, scipy.ndimage's half-sample
 * mirror (as the reference); RGBZ_DM_PERIOD, a shift by whole periods (keeps
 * the colour). No clipping (the reference does not clip); the caller clips if
 * it wants. Arithmetic in double; demosaic.template.h is the row loop, once per
 * input element type, with the store of each output type.
 */
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include "rgbz.h"
#include "rgbz_ops.h"
#include "demosaic_bilinear.h"

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

static inline ptrdiff_t dm_extend(ptrdiff_t i, ptrdiff_t n, int mode)
{
    return mode == RGBZ_DM_PERIOD ? dm_period(i, n) : dm_reflect(i, n);
}

/*
 * The filters of one pixel from the sums of its neighbourhood: c0 the pixel, n4 its four
 * neighbours, far4 the four at distance 2 on the axes, diag the four diagonal ones, hz/vt
 * the horizontal/vertical pairs at distance 1 and 2. rgb[] gets R, G, B.
 */
static inline void dm_pixel(const int32_t *ph, int xp, double c0, double n4, double far4,
                            double diag, double hz2, double vt2, double hz1, double vt1,
                            double *rgb)
{
    const int ch = ph[xp];
    if (ch == 1) {
        /* green site: horizontal and vertical colour-difference filters */
        const double hv = (5 * c0 + 4 * hz1 - hz2 - diag + 0.5 * vt2) / 8;
        const double vv = (5 * c0 + 4 * vt1 - vt2 - diag + 0.5 * hz2) / 8;
        const int row_colour = ph[xp ^ 1];   /* R or B, the colour of this row */
        rgb[1] = c0;
        rgb[0] = row_colour == 0 ? hv : vv;
        rgb[2] = row_colour == 0 ? vv : hv;
    } else {
        /* red or blue site: green, and the other colour from the diagonals */
        const double gg = (4 * c0 + 2 * n4 - far4) / 8;
        const double oo = (6 * c0 + 2 * diag - 1.5 * far4) / 8;
        rgb[1] = gg;
        rgb[0] = ch == 0 ? c0 : oo;
        rgb[2] = ch == 0 ? oo : c0;
    }
}

/*
 * Bilinear (colour-demosaicing's filters, scipy's order of the taps: raster order, from 0.0)
 * of one pixel from its 3x3 neighbourhood: c0 the pixel, up/left/right/down its four
 * neighbours, ul/ur/dl/dr the diagonal ones. rgb[] gets R, G, B.
 */
static inline void dm_bilinear_pixel(const int32_t *ph, int xp, double c0, double up,
                                     double left, double right, double down, double ul,
                                     double ur, double dl, double dr, double *rgb)
{
    const int ch = ph[xp];
    if (ch == 1) {
        const int row_colour = ph[xp ^ 1];   /* R or B, the colour of this row */
        const double h = (0.0 + left * 0.5) + right * 0.5;
        const double v = (0.0 + up * 0.5) + down * 0.5;
        rgb[1] = 0.0 + c0;
        rgb[0] = row_colour == 0 ? h : v;
        rgb[2] = row_colour == 0 ? v : h;
    } else {
        const double o = (((0.0 + ul * 0.25) + ur * 0.25) + dl * 0.25) + dr * 0.25;
        rgb[1] = (((0.0 + up * 0.25) + left * 0.25) + right * 0.25) + down * 0.25;
        rgb[0] = ch == 0 ? 0.0 + c0 : o;
        rgb[2] = ch == 0 ? o : 0.0 + c0;
    }
}

/* element i..i+2 of an RGB output of float or double */
static inline void dm_store(void *dst, int out_f64, ptrdiff_t i, const double *rgb)
{
    if (out_f64) {
        double *o = (double *)dst + i;
        o[0] = rgb[0];
        o[1] = rgb[1];
        o[2] = rgb[2];
    } else {
        float *o = (float *)dst + i;
        o[0] = (float)rgb[0];
        o[1] = (float)rgb[1];
        o[2] = (float)rgb[2];
    }
}

/* ---- the row loop per input element type ---- */
#define RGBZ_TYPE_TEMPLATE "demosaic.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

/* the checks of both entry points: RGBZ_OK or RGBZ_EINVAL */
static int dm_check(int out_type, const void *src, void *dst, ptrdiff_t rows, ptrdiff_t cols,
                    const int32_t *phase, int mode)
{
    if (!src || !dst || !phase || rows < 2 || cols < 2 ||
        (mode != RGBZ_DM_REFLECT && mode != RGBZ_DM_PERIOD))
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
    return greens == 2 && (main_diag || anti_diag) ? RGBZ_OK : RGBZ_EINVAL;
}

/* the source of padded column i - 2 for i in [0, cols + 4), or NULL */
static ptrdiff_t *dm_colmap(ptrdiff_t cols, int mode)
{
    ptrdiff_t *colmap = (ptrdiff_t *)malloc((size_t)(cols + 4) * sizeof(ptrdiff_t));
    if (colmap)
        for (ptrdiff_t i = 0; i < cols + 4; i++) colmap[i] = dm_extend(i - 2, cols, mode);
    return colmap;
}

int rgbz_demosaic(int method, int in_type, int out_type, const void *src, void *dst,
                  ptrdiff_t rows, ptrdiff_t cols, const int32_t *phase, int mode, int workers)
{
    if (method != RGBZ_DM_MALVAR && method != RGBZ_DM_BILINEAR && method != RGBZ_DM_MENON)
        return RGBZ_EINVAL;
    int st = dm_check(out_type, src, dst, rows, cols, phase, mode);
    if (st != RGBZ_OK) return st;
    if (method == RGBZ_DM_MENON)
        return rgbz_demosaic_menon(in_type, out_type, src, dst, rows, cols, phase, mode, workers);
    ptrdiff_t *colmap = dm_colmap(cols, mode);
    if (!colmap) return RGBZ_ENOMEM;
#define DM_RUN_(s, T)                                                                       \
    RGBZ_CAT(rgbz_demosaic_rows, s)((const T *)src, dst, method == RGBZ_DM_BILINEAR,        \
                                    out_type == RGBZ_T_F64, rows, cols, phase, colmap, mode, \
                                    workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, DM_RUN_, st = RGBZ_EINVAL)
#undef DM_RUN_
    free(colmap);
    return st;
}
