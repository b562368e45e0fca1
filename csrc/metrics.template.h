/*
 * metrics.template.h -- the metric kernels of metrics.c for one input element type.
 *
 * Instantiated by metrics.c through rgbz_each_type.h (rgbz_templating.h), with:
 *   IN_T       the element type of the input images (uint8_t, uint16_t, float, double)
 *   IS         its suffix (u8, u16, f32, f64), appended to every function name
 *   IN_IS_INT  1 for the integer types (their sRGB EOTF is a table of every code value)
 * Everything is computed in double; see metrics.c for the algorithms and metrics.h for the
 * layout contract.
 */
#ifndef IN_T
#error "metrics.template.h: #define IN_T (the element type of the images) before including it"
#endif
#ifndef IS
#error "metrics.template.h: #define IS (the suffix of IN_T: u8, u16, f32 or f64)"
#endif
#ifndef IN_IS_INT
#error "metrics.template.h: #define IN_IS_INT (1 for integer IN_T, else 0)"
#endif

#define MT(name) RGBZ_CAT(name, IS)

/* ------------------------------------------------------------------ SSIM */

/* The moments of one output row filtered along the columns, in correlate1d's order for
   symmetric weights (the centre times its weight, then the pairs from the farthest to the
   nearest): x, y point at the centre row of the window (rows above and below at -k * cols,
   +k * cols). The _x pass writes the two rows x, x^2 of m; the _y pass the three rows y, y^2,
   xy. For the default window (radius MT_SSIM_RAD) the taps are unrolled and each sum stays
   in a register; other windows add the pairs row by row into m. The same operations in the
   same order either way. */
static inline MT_INLINE void MT(mt_vx_reg)(const IN_T *x, ptrdiff_t cols, const double *w,
                                           int rad, double *restrict mx, double *restrict mxx)
{
    const double wc = w[rad];
    MT_SIMD
    for (ptrdiff_t j = 0; j < cols; j++) {
        const double xc = (double)x[j];
        double sx = xc * wc, sxx = (xc * xc) * wc;
        MT_UNROLL
        for (int k = rad; k >= 1; k--) {
            const double a = (double)x[j - k * cols], b = (double)x[j + k * cols];
            const double wk = w[rad - k];
            sx += (a + b) * wk;
            sxx += (a * a + b * b) * wk;
        }
        mx[j] = sx;
        mxx[j] = sxx;
    }
}

static void MT(mt_ssim_vpass_x)(const IN_T *x, ptrdiff_t cols, const double *w, int rad,
                                double *restrict m)
{
    double *restrict mx = m, *restrict mxx = m + cols;
    if (rad == MT_SSIM_RAD) {
        MT(mt_vx_reg)(x, cols, w, MT_SSIM_RAD, mx, mxx);
        return;
    }
    const double wc = w[rad];
    MT_SIMD
    for (ptrdiff_t j = 0; j < cols; j++) {
        const double xc = (double)x[j];
        mx[j] = xc * wc;
        mxx[j] = (xc * xc) * wc;
    }
    for (int k = rad; k >= 1; k--) {
        const IN_T *xu = x - k * cols, *xd = x + k * cols;
        const double wk = w[rad - k];
        MT_SIMD
        for (ptrdiff_t j = 0; j < cols; j++) {
            const double a = (double)xu[j], b = (double)xd[j];
            mx[j] += (a + b) * wk;
            mxx[j] += (a * a + b * b) * wk;
        }
    }
}

static inline MT_INLINE void MT(mt_vy_reg)(const IN_T *x, const IN_T *y, ptrdiff_t cols,
                                           const double *w, int rad, double *restrict my,
                                           double *restrict myy, double *restrict mxy)
{
    const double wc = w[rad];
    MT_SIMD
    for (ptrdiff_t j = 0; j < cols; j++) {
        const double xc = (double)x[j], yc = (double)y[j];
        double sy = yc * wc, syy = (yc * yc) * wc, sxy = (xc * yc) * wc;
        MT_UNROLL
        for (int k = rad; k >= 1; k--) {
            const double a = (double)x[j - k * cols], b = (double)x[j + k * cols];
            const double c = (double)y[j - k * cols], d = (double)y[j + k * cols];
            const double wk = w[rad - k];
            sy += (c + d) * wk;
            syy += (c * c + d * d) * wk;
            sxy += (a * c + b * d) * wk;
        }
        my[j] = sy;
        myy[j] = syy;
        mxy[j] = sxy;
    }
}

static void MT(mt_ssim_vpass_y)(const IN_T *x, const IN_T *y, ptrdiff_t cols, const double *w,
                                int rad, double *restrict m)
{
    double *restrict my = m, *restrict myy = m + cols, *restrict mxy = m + 2 * cols;
    if (rad == MT_SSIM_RAD) {
        MT(mt_vy_reg)(x, y, cols, w, MT_SSIM_RAD, my, myy, mxy);
        return;
    }
    const double wc = w[rad];
    MT_SIMD
    for (ptrdiff_t j = 0; j < cols; j++) {
        const double xc = (double)x[j], yc = (double)y[j];
        my[j] = yc * wc;
        myy[j] = (yc * yc) * wc;
        mxy[j] = (xc * yc) * wc;
    }
    for (int k = rad; k >= 1; k--) {
        const IN_T *xu = x - k * cols, *xd = x + k * cols, *yu = y - k * cols, *yd = y + k * cols;
        const double wk = w[rad - k];
        MT_SIMD
        for (ptrdiff_t j = 0; j < cols; j++) {
            const double a = (double)xu[j], b = (double)xd[j];
            const double c = (double)yu[j], d = (double)yd[j];
            my[j] += (c + d) * wk;
            myy[j] += (c * c + d * d) * wk;
            mxy[j] += (a * c + b * d) * wk;
        }
    }
}

/* The default window (radius MT_SSIM_RAD) reads each input row as doubles from a ring
   (mt_vpass_ring) with the products the moments filter (x x; or y y and x y), converted and
   multiplied once per pixel instead of once per tap: a product is the same double whichever
   pass computes it, so the moments are those of mt_ssim_vpass_x / _y bit for bit. */

/* one input row into the ring's slot: ref side a = x, b = x x; test side a = y, b = y y,
   c = x y */
static void MT(mt_ring_row_x)(const IN_T *x, ptrdiff_t cols, double *restrict a,
                              double *restrict b)
{
    MT_SIMD
    for (ptrdiff_t j = 0; j < cols; j++) {
        const double xc = (double)x[j];
        a[j] = xc;
        b[j] = xc * xc;
    }
}

static void MT(mt_ring_row_y)(const IN_T *x, const IN_T *y, ptrdiff_t cols,
                              double *restrict a, double *restrict b, double *restrict c)
{
    MT_SIMD
    for (ptrdiff_t j = 0; j < cols; j++) {
        const double xc = (double)x[j], yc = (double)y[j];
        a[j] = yc;
        b[j] = yc * yc;
        c[j] = xc * yc;
    }
}

/* Input rows up to `last` of plane p into the ring (nq quantities: 2 for x alone, 3 with y);
   *next_r: the next row the ring lacks, from the plane's row `first` on (-1: a new plane). */
static void MT(mt_ring_fill)(const IN_T *x, const IN_T *y, ptrdiff_t p, ptrdiff_t first,
                             ptrdiff_t last, ptrdiff_t rows, ptrdiff_t cols, double *ring,
                             ptrdiff_t *next_r)
{
    const int nq = y ? 3 : 2;
    if (*next_r < first) *next_r = first;
    for (; *next_r <= last; (*next_r)++) {
        const ptrdiff_t r = *next_r, off = (p * rows + r) * cols;
        double *slot = ring + (ptrdiff_t)(r % MT_RING_ROWS) * nq * cols;
        if (y)
            MT(mt_ring_row_y)(x + off, y + off, cols, slot, slot + cols, slot + 2 * cols);
        else
            MT(mt_ring_row_x)(x + off, cols, slot, slot + cols);
    }
}

/* This thread's share [*u0, *u1) of n units, in one contiguous run (the ring's rows follow
   one another). */
static void MT(mt_share)(ptrdiff_t n, ptrdiff_t *u0, ptrdiff_t *u1)
{
    int t = 0, T = 1;
#ifdef _OPENMP
    t = omp_get_thread_num();
    T = omp_get_num_threads();
#endif
    *u0 = n * t / T;
    *u1 = n * (t + 1) / T;
}

/* The reference side of the SSIM of planar x: for each of the planes * (rows - 2 rad) output
   rows u, mom[2 u ocols ...] = the means of the row's windows, then their variances
   (mt_ssim_hpass_x), ocols = cols - 2 rad. */
static int MT(mt_ssim_ref)(const void *xv, ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols,
                           const double *w, int ntaps, double *mom, int workers)
{
    const IN_T *x = (const IN_T *)xv;
    const int rad = ntaps / 2, ring = rad == MT_SSIM_RAD;
    const ptrdiff_t orows = rows - 2 * rad, ocols = cols - 2 * rad, units = planes * orows;
    int failed = 0;
    int nt = mt_threads(workers, units, (double)cols * (6.0 * ntaps + 10.0));
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
#endif
    {
        const size_t n = (size_t)(2 * cols) * (ring ? MT_VROWS + MT_RING_ROWS : 1);
        double *m = (double *)malloc(n * sizeof(double));
        double *rg = m + 2 * MT_VROWS * cols;
        ptrdiff_t u0, u1;
        MT(mt_share)(units, &u0, &u1);
        if (!m && u0 < u1) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            failed = 1;
        }
        ptrdiff_t next_r = -1, plane = -1;
        for (ptrdiff_t u = u0; m && u < u1;) {
            const ptrdiff_t p = u / orows, i = u % orows;
            int g = 1;
            if (ring) {
                g = (int)(u1 - u < orows - i ? u1 - u : orows - i);
                g = g < MT_VROWS ? g : MT_VROWS;
                if (p != plane) next_r = -1, plane = p;
                MT(mt_ring_fill)(x, NULL, p, i, i + 2 * rad + g - 1, rows, cols, rg, &next_r);
                mt_vpass_ring(rg, 2, i, g, cols, w, m);
            } else {
                MT(mt_ssim_vpass_x)(x + (p * rows + i + rad) * cols, cols, w, rad, m);
            }
            for (int t = 0; t < g; t++)
                mt_ssim_hpass_x(m + 2 * t * cols, cols, w, rad, mom + 2 * (u + t) * ocols);
            u += g;
        }
        free(m);
    }
    return failed ? RGBZ_ENOMEM : RGBZ_OK;
}

/* The SSIM sums of x, y; mom: the reference side of x (mt_ssim_ref), or NULL to compute it
   row by row. */
static int MT(mt_ssim_sums)(const void *xv, const void *yv, const double *mom,
                            ptrdiff_t planes, ptrdiff_t rows, ptrdiff_t cols, const double *w,
                            int ntaps, double c1, double c2, double *ssim_sum, double *cs_sum,
                            int workers)
{
    const IN_T *x = (const IN_T *)xv, *y = (const IN_T *)yv;
    const int rad = ntaps / 2, ring = rad == MT_SSIM_RAD;
    const ptrdiff_t orows = rows - 2 * rad, ocols = cols - 2 * rad, units = planes * orows;
    double *rowsum = (double *)malloc((size_t)(2 * units) * sizeof(double));
    if (!rowsum) return RGBZ_ENOMEM;
    int failed = 0;
    int nt = mt_threads(workers, units, (double)cols * ((mom ? 10.0 : 16.0) * ntaps + 40.0));
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
#endif
    {
        /* the y-side moment rows (MT_VROWS rows of 3 with the ring, else one), the x-side
           ones (2 rows), the reference side of one row (2 ocols), five ocols of
           mt_ssim_hpass_y, then the rings of the default window (y side; x side without
           mom) */
        const ptrdiff_t my_n = (ring ? MT_VROWS : 1) * 3 * cols;
        const size_t base = (size_t)(my_n + 2 * cols + 7 * ocols);
        const size_t n = base + (ring ? (size_t)(MT_RING_ROWS * cols) * (mom ? 3 : 5) : 0);
        double *m = (double *)malloc(n * sizeof(double));
        double *mx = m + my_n, *xmom_buf = mx + 2 * cols, *vals = xmom_buf + 2 * ocols;
        double *rg_y = m + base, *rg_x = rg_y + 3 * MT_RING_ROWS * cols;
        ptrdiff_t u0, u1;
        MT(mt_share)(units, &u0, &u1);
        if (!m && u0 < u1) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            failed = 1;
        }
        ptrdiff_t next_ry = -1, next_rx = -1, plane = -1;
        for (ptrdiff_t u = u0; m && u < u1;) {
            const ptrdiff_t p = u / orows, i = u % orows;
            int g = 1;
            if (ring) {
                g = (int)(u1 - u < orows - i ? u1 - u : orows - i);
                g = g < MT_VROWS ? g : MT_VROWS;
                if (p != plane) next_ry = next_rx = -1, plane = p;
                MT(mt_ring_fill)(x, y, p, i, i + 2 * rad + g - 1, rows, cols, rg_y, &next_ry);
                mt_vpass_ring(rg_y, 3, i, g, cols, w, m);
            } else {
                const ptrdiff_t centre = (p * rows + i + rad) * cols;
                MT(mt_ssim_vpass_y)(x + centre, y + centre, cols, w, rad, m);
            }
            for (int t = 0; t < g; t++) {
                const ptrdiff_t ut = u + t;
                double *xmom = xmom_buf;
                if (mom) {
                    xmom = (double *)mom + 2 * ut * ocols;
                } else if (ring) {
                    MT(mt_ring_fill)(x, NULL, p, i + t, i + t + 2 * rad, rows, cols, rg_x,
                                     &next_rx);
                    mt_vpass_ring(rg_x, 2, i + t, 1, cols, w, mx);
                    mt_ssim_hpass_x(mx, cols, w, rad, xmom);
                } else {
                    MT(mt_ssim_vpass_x)(x + (p * rows + i + rad) * cols, cols, w, rad, mx);
                    mt_ssim_hpass_x(mx, cols, w, rad, xmom);
                }
                mt_ssim_hpass_y(m + 3 * t * cols, xmom, cols, w, rad, c1, c2, vals,
                                ssim_sum ? rowsum + 2 * ut : NULL, rowsum + 2 * ut + 1);
            }
            u += g;
        }
        free(m);
    }
    if (!failed) {
        for (ptrdiff_t p = 0; p < planes; p++) {
            double s = 0.0, c = 0.0;
            for (ptrdiff_t i = 0; i < orows; i++) {
                if (ssim_sum) s += rowsum[2 * (p * orows + i)];
                c += rowsum[2 * (p * orows + i) + 1];
            }
            if (ssim_sum) ssim_sum[p] = s;
            cs_sum[p] = c;
        }
    }
    free(rowsum);
    return failed ? RGBZ_ENOMEM : RGBZ_OK;
}

/* ------------------------------------------------------------------ planar copy */
static int MT(mt_planar)(const void *srcv, ptrdiff_t rows, ptrdiff_t cols, ptrdiff_t ch,
                         ptrdiff_t row_stride, void *dstv, int workers)
{
    const IN_T *src = (const IN_T *)srcv;
    IN_T *dst = (IN_T *)dstv;
    const ptrdiff_t plane = rows * cols;
    int nt = mt_threads(workers, rows, 2.0 * (double)(cols * ch));
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nt)
#endif
    for (ptrdiff_t r = 0; r < rows; r++) {
        const IN_T *s = src + r * row_stride;
        if (ch == 3) {             /* RGB: the three planes in one vector pass */
            IN_T *restrict d0 = dst + r * cols, *restrict d1 = d0 + plane;
            IN_T *restrict d2 = d1 + plane;
            MT_SIMD
            for (ptrdiff_t j = 0; j < cols; j++) {
                d0[j] = s[3 * j];
                d1[j] = s[3 * j + 1];
                d2[j] = s[3 * j + 2];
            }
        } else {
            for (ptrdiff_t c = 0; c < ch; c++) {
                IN_T *restrict d = dst + c * plane + r * cols;
                for (ptrdiff_t j = 0; j < cols; j++) d[j] = s[ch * j + c];
            }
        }
    }
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ MS-SSIM decimation */
static int MT(mt_downsample2)(const void *srcv, ptrdiff_t planes, ptrdiff_t rows,
                              ptrdiff_t cols, double *dst, int workers)
{
    const IN_T *src = (const IN_T *)srcv;
    const ptrdiff_t orows = (rows + 1) / 2, ocols = (cols + 1) / 2, half = cols / 2;
    const ptrdiff_t units = planes * orows;
    int nt = mt_threads(workers, units, 6.0 * (double)cols);
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nt)
#endif
    for (ptrdiff_t u = 0; u < units; u++) {
        const ptrdiff_t p = u / orows, i = u % orows;
        const IN_T *r0 = src + (p * rows + 2 * i) * cols;
        const IN_T *r1 = 2 * i + 1 < rows ? r0 + cols : r0;     /* odd: the last row twice */
        double *restrict o = dst + u * ocols;
#if IN_IS_INT
        /* integer codes (8 or 16 bits): the sums of two and of four are exact in int32 as in
           double, so the same value reaches the division; the adds vectorise in integers */
        MT_SIMD
        for (ptrdiff_t j = 0; j < half; j++)
            o[j] = (double)(((int32_t)r0[2 * j] + (int32_t)r0[2 * j + 1])
                            + ((int32_t)r1[2 * j] + (int32_t)r1[2 * j + 1])) / 4.0;
#else
        MT_SIMD
        for (ptrdiff_t j = 0; j < half; j++)
            o[j] = (((double)r0[2 * j] + (double)r0[2 * j + 1])
                    + ((double)r1[2 * j] + (double)r1[2 * j + 1])) / 4.0;
#endif
        if (cols % 2) {
            const double a = (double)r0[cols - 1], b = (double)r1[cols - 1];
            o[half] = ((a + a) + (b + b)) / 4.0;
        }
    }
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ sRGB -> CIELAB */

/* Lab of n interleaved pixels: L[j * os], A[j * os], B[j * os]. scale > 0: sRGB code values
   over scale (lut: their EOTF, integer types only, or NULL); scale == 0: Lab already.
   lin: scratch of 3 n doubles (the linear values, planar, so that the Lab loop vectorises). */
static void MT(mt_lab_run)(const IN_T *src, ptrdiff_t n, double scale, const double *lut,
                           double *restrict lin, double *L, double *A, double *B, ptrdiff_t os)
{
    if (scale == 0.0) {
        MT_SIMD
        for (ptrdiff_t j = 0; j < n; j++) {
            L[j * os] = (double)src[3 * j];
            A[j * os] = (double)src[3 * j + 1];
            B[j * os] = (double)src[3 * j + 2];
        }
        return;
    }
    double *restrict lr = lin, *restrict lg = lin + n, *restrict lb = lin + 2 * n;
#if IN_IS_INT
    if (lut) {
        MT_SIMD
        for (ptrdiff_t j = 0; j < n; j++) {
            lr[j] = lut[src[3 * j]];
            lg[j] = lut[src[3 * j + 1]];
            lb[j] = lut[src[3 * j + 2]];
        }
    } else
#endif
    {
        (void)lut;
        for (ptrdiff_t j = 0; j < n; j++) {
            lr[j] = mt_eotf((double)src[3 * j] / scale);
            lg[j] = mt_eotf((double)src[3 * j + 1] / scale);
            lb[j] = mt_eotf((double)src[3 * j + 2] / scale);
        }
    }
    double tmax = 0.0;
    ptrdiff_t j0 = 0;
#if defined(MT_HAVE_LAB512)
    /* the same operations, scheduled for AVX-512 (metrics_lab512.h, built only with FMA, so
       with MT_QFMA for integer codes as below); the loop below does the last n % 8 */
    j0 = mt_lab512(lr, lg, lb, n, IN_IS_INT, L, A, B, os, &tmax);
#endif
    MT_SIMD_MAX(tmax)
    for (ptrdiff_t j = j0; j < n; j++) {
#if IN_IS_INT && defined(MT_HAVE_QFMA)
        MT_LAB(lr[j], lg[j], lb[j], L[j * os], A[j * os], B[j * os], tmax, MT_QFMA);
#else
        MT_LAB(lr[j], lg[j], lb[j], L[j * os], A[j * os], B[j * os], tmax, MT_QDIV);
#endif
    }
    if (!(tmax < 8.0)) {
        /* rare: a ratio X/Xn, Y/Yn or Z/Zn >= 8 (a float input far above white) */
        for (ptrdiff_t j = 0; j < n; j++) {
            double tx, ty, tz;
            MT_XYZ(lr[j], lg[j], lb[j], tx, ty, tz);
            if (tx >= 8.0 || ty >= 8.0 || tz >= 8.0)
                mt_lab_any(lr[j], lg[j], lb[j], &L[j * os], &A[j * os], &B[j * os]);
        }
    }
}

/* the EOTF table of an integer type, when the image holds more values than the table */
static int MT(mt_lut)(ptrdiff_t npix, double scale, int workers, double **lut)
{
    *lut = NULL;
#if IN_IS_INT
    const ptrdiff_t size = (ptrdiff_t)1 << (8 * sizeof(IN_T));
    if (scale > 0.0 && 3 * npix > size) {
        *lut = mt_eotf_table(size, scale, workers);
        if (!*lut) return RGBZ_ENOMEM;
    }
#else
    (void)npix; (void)scale; (void)workers;
#endif
    return RGBZ_OK;
}

static int MT(mt_srgb_to_lab)(const void *rgbv, ptrdiff_t n, double scale, double *lab,
                              int workers)
{
    const IN_T *rgb = (const IN_T *)rgbv;
    double *lut;
    if (MT(mt_lut)(n, scale, workers, &lut) != RGBZ_OK) return RGBZ_ENOMEM;
    const ptrdiff_t block = 2048, nblocks = (n + block - 1) / block;
    int failed = 0;
    int nt = mt_threads(workers, nblocks, 60.0 * (double)block);
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
#endif
    {
        double *lin = (double *)malloc((size_t)(3 * block) * sizeof(double));
        if (!lin) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            failed = 1;
        }
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t k = 0; k < nblocks; k++) {
            if (!lin) continue;
            const ptrdiff_t j0 = k * block, m = n - j0 < block ? n - j0 : block;
            double *o = lab + 3 * j0;
            MT(mt_lab_run)(rgb + 3 * j0, m, scale, lut, lin, o, o + 1, o + 2, 3);
        }
        free(lin);
    }
    free(lut);
    return failed ? RGBZ_ENOMEM : RGBZ_OK;
}

/* ------------------------------------------------------------------ zipper */

/* The zipper pass over the centre rows 1..rows-2, split in one band per thread, with the Lab
   of each band's rows and the two around it in a ring of three rows per image:
     ref, best, nearest: ref given -> each centre pixel's nearest neighbour in the reference
                         is found (mt_zipper_ref_row), into best/nearest when they are the
                         full (rows - 2) x (cols - 2) arrays (store = 1), else into one
                         scratch row;
                         ref NULL -> best/nearest hold them (rgbz_zipper_reference);
     test:               given -> the pixels with |psi| > delta are counted into *count. */
static int MT(mt_zipper_pass)(const IN_T *ref, const IN_T *test, ptrdiff_t rows,
                              ptrdiff_t cols, double scale, double delta, double *best,
                              uint8_t *nearest, int store, int64_t *count, int workers)
{
    double *lut;
    if (MT(mt_lut)(rows * cols, scale, workers, &lut) != RGBZ_OK) return RGBZ_ENOMEM;
    const ptrdiff_t centres = rows - 2, inner = cols - 2;
    const int images = (ref != NULL) + (test != NULL);
    int64_t total = 0;
    int failed = 0;
    int nt = mt_threads(workers, centres,
                        ((ref ? 170.0 : 0.0) + (test ? 90.0 : 0.0)) * (double)cols);
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt) reduction(+:total)
#endif
    {
        int t = 0, T = 1;
#ifdef _OPENMP
        t = omp_get_thread_num();
        T = omp_get_num_threads();
#endif
        const ptrdiff_t b0 = 1 + centres * t / T, b1 = 1 + centres * (t + 1) / T;
        /* the ring, buf[(image * 3 + slot) * 3 + channel][cols], the linear-RGB scratch of
           mt_lab_run (3 cols), then one row of best and nearest when they are not stored */
        const size_t doubles = (size_t)(9 * images + 3) * (size_t)cols
                               + (ref && !store ? (size_t)inner : 0);
        const size_t bytes = doubles * sizeof(double) + (ref && !store ? (size_t)inner : 0);
        char *buf = b0 < b1 ? (char *)malloc(bytes) : NULL;
        if (b0 < b1 && !buf) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            failed = 1;
        }
        if (buf) {
            double *d = (double *)buf;
            double *lin = d + (ptrdiff_t)(9 * images) * cols;
            double *row_best = lin + 3 * cols;
            uint8_t *row_near = (uint8_t *)(d + doubles);
            mt_labrow rr[3], tr[3];
            for (int s = 0; s < 3; s++) {
                double *rb = d + (ptrdiff_t)(3 * s) * cols;
                double *tb = rb + (ref ? (ptrdiff_t)9 * cols : 0);
                rr[s] = (mt_labrow){rb, rb + cols, rb + 2 * cols};
                tr[s] = (mt_labrow){tb, tb + cols, tb + 2 * cols};
            }
            for (ptrdiff_t q = b0 - 1; q <= b1; q++) {
                const int s = (int)(q % 3);
                if (ref)
                    MT(mt_lab_run)(ref + 3 * q * cols, cols, scale, lut, lin, rr[s].L,
                                   rr[s].A, rr[s].B, 1);
                if (test)
                    MT(mt_lab_run)(test + 3 * q * cols, cols, scale, lut, lin, tr[s].L,
                                   tr[s].A, tr[s].B, 1);
                if (q < b0 + 1) continue;
                const int u = (int)((q - 2) % 3), c = (int)((q - 1) % 3);
                double *bst = best ? best + (q - 2) * inner : NULL;
                uint8_t *nrs = nearest ? nearest + (q - 2) * inner : NULL;
                if (ref) {
                    if (!store) {
                        bst = row_best;
                        nrs = row_near;
                    }
                    mt_zipper_ref_row(rr[u], rr[c], rr[s], cols, bst, nrs);
                }
                if (test) {
                    /* the neighbours' L relative to the centre pixel's, in raster order */
                    const ptrdiff_t ru = tr[u].L - tr[c].L, rd = tr[s].L - tr[c].L;
                    const ptrdiff_t off[8] = {ru - 1, ru, ru + 1, -1, 1, rd - 1, rd, rd + 1};
                    total += mt_zipper_test_row(tr[c].L, cols, off, bst, nrs, delta);
                }
            }
        }
        free(buf);
    }
    free(lut);
    if (failed) return RGBZ_ENOMEM;
    if (count) *count = total;
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ squared differences */

/* one row: the sum of squares of the counted elements (exact in int64 for integer types) and
   their number */
#if IN_IS_INT
typedef int64_t MT(mt_acc);
#else
typedef double MT(mt_acc);
#endif

static MT(mt_acc) MT(mt_sq_row)(const IN_T *a, const IN_T *b, ptrdiff_t cols, ptrdiff_t ch,
                                const uint8_t *mask, int64_t *n)
{
    MT(mt_acc) s = 0;
    int64_t k = 0;
#if IN_IS_INT
    if (ch == 1) {             /* exact integer sums: any order, so vectorised */
        if (!mask) {
            MT_SIMD_COUNT(s)
            for (ptrdiff_t c = 0; c < cols; c++) {
                const int64_t d = (int64_t)a[c] - (int64_t)b[c];
                s += d * d;
            }
            *n = cols;
            return s;
        }
        MT_PRAGMA(omp simd reduction(+:s, k))
        for (ptrdiff_t c = 0; c < cols; c++) {
            const int64_t d = (int64_t)a[c] - (int64_t)b[c];
            const int on = mask[c] != 0;
            s += on ? d * d : 0;
            k += on;
        }
        *n = k;
        return s;
    }
#endif
    for (ptrdiff_t c = 0; c < cols; c++) {
        if (mask && !mask[c]) continue;
        k += ch;
        for (ptrdiff_t q = c * ch; q < (c + 1) * ch; q++) {
#if IN_IS_INT
            const int64_t d = (int64_t)a[q] - (int64_t)b[q];
#else
            const double d = (double)a[q] - (double)b[q];
#endif
            s += d * d;
        }
    }
    *n = k;
    return s;
}

static int MT(mt_sq_diff_sum)(const void *av, const void *bv, ptrdiff_t rows, ptrdiff_t cols,
                              ptrdiff_t ch, const uint8_t *mask, double *sum, int64_t *count,
                              int workers)
{
    const IN_T *a = (const IN_T *)av, *b = (const IN_T *)bv;
    MT(mt_acc) *rs = (MT(mt_acc) *)malloc((size_t)rows * sizeof(MT(mt_acc)));
    int64_t *rn = (int64_t *)malloc((size_t)rows * sizeof(int64_t));
    if (!rs || !rn) {
        free(rs);
        free(rn);
        return RGBZ_ENOMEM;
    }
    if (!mask) {               /* every pixel: rows of cols * ch single elements, the same
                                  elements in the same order */
        cols *= ch;
        ch = 1;
    }
    int nt = mt_threads(workers, rows, 3.0 * (double)(cols * ch));
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nt)
#endif
    for (ptrdiff_t r = 0; r < rows; r++)
        rs[r] = MT(mt_sq_row)(a + r * cols * ch, b + r * cols * ch, cols, ch,
                              mask ? mask + r * cols : NULL, &rn[r]);
    MT(mt_acc) s = 0;
    int64_t k = 0;
    for (ptrdiff_t r = 0; r < rows; r++) {     /* the rows in order: no thread dependence */
        s += rs[r];
        k += rn[r];
    }
    *sum = (double)s;
    *count = k;
    free(rs);
    free(rn);
    return RGBZ_OK;
}

#undef MT
