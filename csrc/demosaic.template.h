/*
 * demosaic.template.h -- the Malvar-He-Cutler (2004) and the bilinear demosaic
 * for one input element type (demosaic.c has the algorithm's description, the entry point and
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

/* bilinear, pixel x of row y by the rule (demosaic_bilinear.h): rows u, m, d the sources of
   rows y - 1, y, y + 1, which are yu, y, yd */
RGBZ_INLINE void RGBZ_CAT(dm_bilinear_edge, IS)(const IN_T *u, const IN_T *m, const IN_T *d,
                                                ptrdiff_t yu, ptrdiff_t y, ptrdiff_t yd,
                                                ptrdiff_t x, const int32_t *phase,
                                                const ptrdiff_t *colmap, double *rgb)
{
    const IN_T *rw[3] = {u, m, d};
    const ptrdiff_t ry[3] = {yu, y, yd}, cx[3] = {colmap[x + 1], x, colmap[x + 3]};
    double v[9];
    int c[9];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            v[3 * i + k] = (double)rw[i][cx[k]];
            c[3 * i + k] = phase[2 * (ry[i] & 1) + (cx[k] & 1)];
        }
    dm_bilinear_taps(v, c, rgb);
}

/* bilinear, row y (as dm_row); with the reflect border the outer pixels by the rule */
RGBZ_INLINE void RGBZ_CAT(dm_bilinear_row, IS)(const IN_T *src, void *dst, int out_f64,
                                               ptrdiff_t y, ptrdiff_t rows, ptrdiff_t cols,
                                               const int32_t *phase, const ptrdiff_t *colmap,
                                               int mode)
{
    const ptrdiff_t yu = dm_extend(y - 1, rows, mode), yd = dm_extend(y + 1, rows, mode);
    const IN_T *u = src + yu * cols, *m = src + y * cols, *d = src + yd * cols;
    const int32_t *ph = phase + 2 * (y & 1);
    const int reflect = mode == RGBZ_DM_REFLECT;
    const ptrdiff_t x0 = reflect, x1 = reflect ? cols - 1 : cols;
    double rgb[3];
    if (reflect && (y == 0 || y == rows - 1)) {
        for (ptrdiff_t x = 0; x < cols; x++) {
            RGBZ_CAT(dm_bilinear_edge, IS)(u, m, d, yu, y, yd, x, phase, colmap, rgb);
            dm_store(dst, out_f64, 3 * (y * cols + x), rgb);
        }
        return;
    }
    for (ptrdiff_t x = x0; x < x1; x++) {
        const ptrdiff_t l = colmap[x + 1], r = colmap[x + 3];
        dm_bilinear_pixel(ph, (int)(x & 1), (double)m[x], (double)u[x], (double)m[l],
                          (double)m[r], (double)d[x], (double)u[l], (double)u[r], (double)d[l],
                          (double)d[r], rgb);
        dm_store(dst, out_f64, 3 * (y * cols + x), rgb);
    }
    if (reflect) {
        RGBZ_CAT(dm_bilinear_edge, IS)(u, m, d, yu, y, yd, 0, phase, colmap, rgb);
        dm_store(dst, out_f64, 3 * y * cols, rgb);
        RGBZ_CAT(dm_bilinear_edge, IS)(u, m, d, yu, y, yd, cols - 1, phase, colmap, rgb);
        dm_store(dst, out_f64, 3 * (y * cols + cols - 1), rgb);
    }
}

/* every row, Malvar's or bilinear (a compile-time constant in each call below, so that each
   has its own loop with the store of its output type) */
static void RGBZ_CAT(rgbz_demosaic_rows, IS)(const IN_T *src, void *dst, int bilinear,
                                             int out_f64, ptrdiff_t rows, ptrdiff_t cols,
                                             const int32_t *phase, const ptrdiff_t *colmap,
                                             int mode, int workers)
{
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t y = 0; y < rows; y++) {
        if (bilinear && out_f64)
            RGBZ_CAT(dm_bilinear_row, IS)(src, dst, 1, y, rows, cols, phase, colmap, mode);
        else if (bilinear)
            RGBZ_CAT(dm_bilinear_row, IS)(src, dst, 0, y, rows, cols, phase, colmap, mode);
        else if (out_f64)
            RGBZ_CAT(dm_row, IS)(src, dst, 1, y, rows, cols, phase, colmap, mode);
        else
            RGBZ_CAT(dm_row, IS)(src, dst, 0, y, rows, cols, phase, colmap, mode);
    }
}
