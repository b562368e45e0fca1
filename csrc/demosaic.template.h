/*
 * demosaic.template.h -- the Malvar-He-Cutler (2004) demosaic for one input
 * element type (demosaic.c has the algorithm's description, the entry point and
 * the instances). The output is float or double (out_f64), chosen per call: the
 * arithmetic is in double either way, only the store differs.
 *
 * Memory layout: src rows x cols, row-major, row stride cols elements; dst rows x
 * cols x 3 (R, G, B interleaved), row-major. Rows beyond the frame come from
 * `extend` (reflect or period), columns through the column map (colmap[x + 2]).
 *
 * Template parameters (rgbz_templating.h), #defined by rgbz_each_type.h, which
 * demosaic.c includes once:
 *   IN_T   the element type of the CFA: uint8_t, uint16_t, float, double
 *   IS     its suffix: u8, u16, f32, f64
 */
#ifndef IN_T
#error "demosaic.template.h: #define IN_T (the element type of the CFA)"
#endif
#ifndef IS
#error "demosaic.template.h: #define IS (the suffix of IN_T: u8, u16, f32 or f64)"
#endif

/* row y; out_f64 is a compile-time constant in the two calls below, so that each has its
   own loop with the store of its output type */
RGBZ_INLINE void RGBZ_CAT(dm_row, IS)(const IN_T *src, void *dst, int out_f64, ptrdiff_t y,
                                      ptrdiff_t rows, ptrdiff_t cols, const int32_t *phase,
                                      const ptrdiff_t *colmap, int mode)
{
    const IN_T *rp[5];
    for (int d = -2; d <= 2; d++) rp[d + 2] = src + dm_extend(y + d, rows, mode) * cols;
    const int32_t *ph = phase + 2 * (y & 1);
    for (ptrdiff_t x = 0; x < cols; x++) {
        const ptrdiff_t *cm = colmap + x + 2;
        /* the 5x5 neighbourhood of (y, x): P(dy, dx) = rp[dy + 2][cm[dx]] */
        double c0 = (double)rp[2][cm[0]];
        double n4 = (double)rp[1][cm[0]] + (double)rp[3][cm[0]] + (double)rp[2][cm[-1]] +
                    (double)rp[2][cm[1]];
        double far4 = (double)rp[0][cm[0]] + (double)rp[4][cm[0]] + (double)rp[2][cm[-2]] +
                      (double)rp[2][cm[2]];
        double diag = (double)rp[1][cm[-1]] + (double)rp[1][cm[1]] + (double)rp[3][cm[-1]] +
                      (double)rp[3][cm[1]];
        double hz2 = (double)rp[2][cm[-2]] + (double)rp[2][cm[2]];
        double vt2 = (double)rp[0][cm[0]] + (double)rp[4][cm[0]];
        double hz1 = (double)rp[2][cm[-1]] + (double)rp[2][cm[1]];
        double vt1 = (double)rp[1][cm[0]] + (double)rp[3][cm[0]];
        double rgb[3];
        dm_pixel(ph, (int)(x & 1), c0, n4, far4, diag, hz2, vt2, hz1, vt1, rgb);
        dm_store(dst, out_f64, 3 * (y * cols + x), rgb);
    }
}

static void RGBZ_CAT(rgbz_malvar, IS)(const IN_T *src, void *dst, int out_f64, ptrdiff_t rows,
                                      ptrdiff_t cols, const int32_t *phase,
                                      const ptrdiff_t *colmap, int mode, int workers)
{
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t y = 0; y < rows; y++) {
        if (out_f64)
            RGBZ_CAT(dm_row, IS)(src, dst, 1, y, rows, cols, phase, colmap, mode);
        else
            RGBZ_CAT(dm_row, IS)(src, dst, 0, y, rows, cols, phase, colmap, mode);
    }
}
