/*
 * tof_guided.template.h -- the stages of the colour-guided ToF ISP that read an array of the
 * caller's element type: the taps (prepare), the guide image (colour, upsample). tof_guided.c
 * has the algorithm, the helpers these call, the instances and the entry points.
 *
 * Template parameters (rgbz_templating.h), #defined by rgbz_each_type.h, which tof_guided.c
 * includes once:
 *   IN_T  the element type of the taps or of the guide
 *   IS    its suffix (u8, u16, f32, f64)
 */
#ifndef IN_T
#error "tof_guided.template.h: #define IN_T (the element type of the taps or the guide)"
#endif
#ifndef IS
#error "tof_guided.template.h: #define IS (the suffix of IN_T: u8, u16, f32 or f64)"
#endif

/* nb <= 256 measurements of the prepare stage, from taps (F, 4, planes N apart) at the first
   one: zr, zi (F planes os apart), v, sat (|=), phi (NULL: not made) at the first one,
   offset (F planes N apart; NULL: not stored) too. A clone per instruction set, so that the
   loops over the measurements vectorise at its width */
RGBZ_CLONES_512 static void RGBZ_CAT(tofg_prepare_block, IS)(
    const IN_T *restrict taps, ptrdiff_t F, ptrdiff_t N, ptrdiff_t nb, double k,
    double black, double const_var, double prnu, double white, double inv_f,
    float *restrict zr, float *restrict zi, ptrdiff_t os, float *restrict v,
    uint8_t *restrict sat, double *restrict offset, double fixed_var, float *restrict phi)
{
    double acc[256], fix[256];
    uint8_t hit[256];
    for (ptrdiff_t j = 0; j < nb; j++) { acc[j] = fix[j] = 0.0; hit[j] = 0; }
    for (ptrdiff_t f = 0; f < F; f++) {
        const IN_T *A0 = taps + 4 * f * N, *A1 = A0 + N, *A2 = A0 + 2 * N, *A3 = A0 + 3 * N;
        float *pr = zr + f * os, *pi = zi + f * os;
        double *po = offset ? offset + f * N : NULL;
        for (ptrdiff_t j = 0; j < nb; j++) {
            double off, mx;
            if (IN_IS_INT) {
                /* integer taps (at most 16 bits): the differences, sums and the largest in
                   int32 are exact, as in double, and take a quarter of the conversions */
                const int32_t a0 = A0[j], a1 = A1[j], a2 = A2[j], a3 = A3[j];
                pr[j] = (float)(a0 - a2);
                pi[j] = (float)(a3 - a1);
                off = 0.25 * (double)((a0 + a1) + (a2 + a3));
                const int32_t m01 = a0 > a1 ? a0 : a1, m23 = a2 > a3 ? a2 : a3;
                mx = (double)(m01 > m23 ? m01 : m23);
            } else {
                const double a0 = A0[j], a1 = A1[j], a2 = A2[j], a3 = A3[j];
                pr[j] = (float)(a0 - a2);
                pi[j] = (float)(a3 - a1);
                off = 0.25 * ((a0 + a1) + (a2 + a3));
                const double m01 = a0 > a1 ? a0 : a1, m23 = a2 > a3 ? a2 : a3;
                mx = m01 > m23 ? m01 : m23;
            }
            if (po) po[j] = off;
            double held = off - black;
            held = held > 0.0 ? held : 0.0;
            const double ph = prnu * held;
            acc[j] += k * held + const_var + ph * ph;
            fix[j] += fixed_var + ph * ph;
            hit[j] |= (uint8_t)(mx >= white);
        }
    }
    for (ptrdiff_t j = 0; j < nb; j++) {
        v[j] = (float)(acc[j] * inv_f);
        sat[j] |= hit[j];
    }
    if (phi)            /* the fixed pattern's share of v: its DSNU and PRNU parts */
        for (ptrdiff_t j = 0; j < nb; j++)
            /* at most 0.99: S = (1 - phi) times the variances stays positive whatever a
               calibration file's dark noise says */
            phi[j] = acc[j] > 0.0 ? (float)(fix[j] < 0.99 * acc[j] ? fix[j] / acc[j]
                                                  : 0.99) : 0.0f;
}

/* the prepare stage of rgbz_tofg_prepare (tof_guided.h) for taps of IN_T */
static int RGBZ_CAT(tofg_prepare, IS)(const IN_T *taps, ptrdiff_t F, ptrdiff_t N, double gain,
                                      double black, double supp, double const_var, double prnu,
                                      double white, float *zr, float *zi, float *v,
                                      uint8_t *sat, double *offset, double fixed_var,
                                      float *phi, int workers)
{
    if (!taps || !zr || !zi || !v || !sat || F < 1 || F > RGBZ_TOF_MAX_FREQS || N < 0)
        return RGBZ_EINVAL;
    const double inv_f = 2.0 / (double)F, k = gain * supp;
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t b0 = 0; b0 < N; b0 += 256)
        RGBZ_CAT(tofg_prepare_block, IS)(taps + b0, F, N, N - b0 < 256 ? N - b0 : 256, k, black,
                                         const_var, prnu, white, inv_f, zr + b0, zi + b0, N,
                                         v + b0, sat + b0, offset ? offset + b0 : NULL,
                                         fixed_var, phi ? phi + b0 : NULL);
    return RGBZ_OK;
}

/* the prepare stage of the measurements [m0, m0 + n) on the calling thread (tofg_prep_span
   in tof_guided.c): zr, zi (planes os apart), v, hit (|= a tap at full scale), phi (NULL:
   not made) from their first, offset (F, N) at m0 (NULL: not stored) */
static void RGBZ_CAT(tofg_prepare_span, IS)(const tofg_prep_in *q, ptrdiff_t F, ptrdiff_t N,
                                            ptrdiff_t m0, ptrdiff_t n, float *zr, float *zi,
                                            ptrdiff_t os, float *v, uint8_t *hit,
                                            double *offset, float *phi)
{
    const IN_T *taps = (const IN_T *)q->taps + m0;
    const double inv_f = 2.0 / (double)F, k = q->gain * q->supp;
    for (ptrdiff_t j = 0; j < n; j += 256)
        RGBZ_CAT(tofg_prepare_block, IS)(taps + j, F, N, n - j < 256 ? n - j : 256, k, q->black,
                                         q->const_var, q->prnu, q->white, inv_f, zr + j, zi + j,
                                         os, v + j, hit + j,
                                         offset ? offset + m0 + j : NULL, q->fixed_var,
                                         phi ? phi + j : NULL);
}

/* the colours of the measurements [n0, n0 + C) of one grid row, whose Z pixels' top-left
   pixels are in guide row y at the columns col_px, for Z pixels of B x B cells (B a
   compile-time constant, so that the cell loops unroll): each channel's sum over the cells
   in double, in the cells' row-major order, times cell_w; each cell times scale into cells
   (NULL: not stored) */
RGBZ_INLINE void RGBZ_CAT(tofg_colour_row, IS)(const IN_T *restrict guide, ptrdiff_t W,
                                               ptrdiff_t y, const int64_t *restrict col_px,
                                               ptrdiff_t C, ptrdiff_t N, ptrdiff_t n0,
                                               double scale, double cell_w,
                                               float *restrict col, float *restrict cells,
                                               const int B)
{
    const IN_T *restrict g0 = guide + y * W * 3;
    float *restrict c0 = col + n0, *restrict c1 = c0 + N, *restrict c2 = c1 + N;
    for (ptrdiff_t c = 0; c < C; c++) {
        const IN_T *q = g0 + col_px[c] * 3;
        double s0 = 0.0, s1 = 0.0, s2 = 0.0;
        for (int dr = 0; dr < B; dr++)
            for (int dc = 0; dc < B; dc++) {
                const IN_T *p = q + (dr * W + dc) * 3;
                s0 += (double)p[0];
                s1 += (double)p[1];
                s2 += (double)p[2];
                if (cells) {
                    float *cp = cells + (ptrdiff_t)(dr * B + dc) * 3 * N + n0 + c;
                    cp[0] = (float)(p[0] * scale);
                    cp[N] = (float)(p[1] * scale);
                    cp[2 * N] = (float)(p[2] * scale);
                }
            }
        c0[c] = (float)(s0 * cell_w);
        c1[c] = (float)(s1 * cell_w);
        c2[c] = (float)(s2 * cell_w);
    }
}

/* rgbz_tofg_ring for a guide of IN_T */
static int RGBZ_CAT(tofg_ring, IS)(const IN_T *guide, ptrdiff_t H, ptrdiff_t W,
                                   const int64_t *row_px, ptrdiff_t R, const int64_t *col_px,
                                   ptrdiff_t C, int block, const double *inv, float *ring,
                                   int workers)
{
    if (!guide || !row_px || !col_px || !inv || !ring || H < 1 || W < 1 || R < 0 || C < 0
        || block < 1 || block > 2)
        return RGBZ_EINVAL;
    const ptrdiff_t N = R * C;
    int offs[16][2], K = 0;
    for (int a = -1; a <= block; a++)
        for (int c = -1; c <= block; c++)
            if (!(a >= 0 && a < block && c >= 0 && c < block)) {
                offs[K][0] = a;
                offs[K][1] = c;
                K++;
            }
    const double i0 = inv[0], i1 = inv[1], i2 = inv[2];
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t r = 0; r < R; r++)
        for (int k = 0; k < K; k++) {
            ptrdiff_t y = row_px[r] + offs[k][0];
            y = y < 0 ? 0 : (y > H - 1 ? H - 1 : y);
            const IN_T *restrict g0 = guide + y * W * 3;
            float *restrict o0 = ring + (ptrdiff_t)k * 3 * N + r * C;
            float *restrict o1 = o0 + N, *restrict o2 = o1 + N;
            const ptrdiff_t dc = offs[k][1];
            for (ptrdiff_t c = 0; c < C; c++) {
                ptrdiff_t x = col_px[c] + dc;
                x = x < 0 ? 0 : (x > W - 1 ? W - 1 : x);
                const IN_T *p = g0 + x * 3;
                o0[c] = (float)((double)p[0] * i0);
                o1[c] = (float)((double)p[1] * i1);
                o2[c] = (float)((double)p[2] * i2);
            }
        }
    return RGBZ_OK;
}

/* the colour stage of rgbz_tofg_colour for a guide of IN_T */
static int RGBZ_CAT(tofg_colour, IS)(const IN_T *guide, ptrdiff_t H, ptrdiff_t W,
                                     const int64_t *row_px, ptrdiff_t R, const int64_t *col_px,
                                     ptrdiff_t C, int block, double scale, float *col,
                                     float *cells, double *lap, double floor, double *sigma,
                                     int workers)
{
    if (!guide || !row_px || !col_px || !col || !lap || R < 0 || C < 0 || block < 1
        || block > 2)
        return RGBZ_EINVAL;
    const ptrdiff_t N = R * C;
    const double cell_w = scale / (double)(block * block);
    for (ptrdiff_t r = 0; r < R; r++)
        if (row_px[r] < 0 || row_px[r] + block > H) return RGBZ_EINVAL;
    for (ptrdiff_t c = 0; c < C; c++)
        if (col_px[c] < 0 || col_px[c] + block > W) return RGBZ_EINVAL;
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t r = 0; r < R; r++) {
        if (block == 1)
            RGBZ_CAT(tofg_colour_row, IS)(guide, W, row_px[r], col_px, C, N, r * C, scale,
                                          cell_w, col, cells, 1);
        else
            RGBZ_CAT(tofg_colour_row, IS)(guide, W, row_px[r], col_px, C, N, r * C, scale,
                                          cell_w, col, cells, 2);
    }
    tofg_laplacian(col, R, C, lap, workers);
    if (sigma) tofg_colour_scale(R, C, block, lap, floor, sigma, col, cells, workers);
    return RGBZ_OK;
}

/* the pixels of row y of a guide of IN_T (scales s[3]) between grid rows r and r + 1 at
   fraction fy, span by span (tofg_up_span) */
RGBZ_CLONES_512 static void RGBZ_CAT(tofg_up_row, IS)(const tofg_up_args *p, const IN_T *guide,
                                                      ptrdiff_t W, ptrdiff_t y, const float *s,
                                                      float ambiguity, double gap, ptrdiff_t r,
                                                      float fy, const int32_t *cx,
                                                      const float *fx, float *out, float *conf)
{
    const float s0 = s[0], s1 = s[1], s2 = s[2];
    for (ptrdiff_t x0 = 0; x0 < W; x0 += TOFG_UPB) {
        const ptrdiff_t n = W - x0 < TOFG_UPB ? W - x0 : TOFG_UPB;
        const IN_T *restrict g = guide + (y * W + x0) * 3;
        float pc[3][TOFG_UPB];
        for (ptrdiff_t j = 0; j < n; j++) {
            pc[0][j] = (float)g[3 * j] * s0;
            pc[1][j] = (float)g[3 * j + 1] * s1;
            pc[2][j] = (float)g[3 * j + 2] * s2;
        }
        tofg_up_span(p, ambiguity, gap, r, fy, cx, fx, x0, n, pc, out + y * W, conf + y * W);
    }
}

/* the upsampling of rgbz_tofg_upsample for a guide of IN_T */
static int RGBZ_CAT(tofg_upsample, IS)(const IN_T *guide, ptrdiff_t H, ptrdiff_t W,
                                       double scale, const double *cscale, const double *depth,
                                       const double *sigma, const float *col, ptrdiff_t R,
                                       ptrdiff_t C, const double *rc, const double *cc,
                                       double spacing, ptrdiff_t reach, double inv2s2,
                                       double inv2hc2, double tol_k, double tol_min,
                                       const double *own, double own_k, double ambiguity,
                                       double gap, float *out, float *conf, int workers)
{
    if (!guide || !cscale || !depth || !sigma || !col || !rc || !cc || !out || !conf
        || H < 0 || W < 0 || R < 1 || C < 1 || !(spacing > 0.0) || reach < 1 || reach > 4
        || !(own_k >= 0.0) || !(ambiguity >= 0.0) || !(gap >= 0.0)
        || C > INT32_MAX / 2)                   /* tofg_up_span's 32-bit node indices */
        return RGBZ_EINVAL;
    const ptrdiff_t N = R * C;
    int32_t *cx = malloc((size_t)(W > 0 ? W : 1) * sizeof *cx);
    float *fx = malloc((size_t)(W > 0 ? W : 1) * sizeof *fx);
    float *prior0 = malloc((size_t)N * sizeof *prior0), *prior = malloc((size_t)N * sizeof *prior);
    double *fd = malloc((size_t)N * sizeof *fd), *fs = malloc((size_t)N * sizeof *fs);
    if (!cx || !fx || !prior0 || !prior || !fd || !fs) {
        free(cx); free(fx); free(prior0); free(prior); free(fd); free(fs);
        return RGBZ_ENOMEM;
    }
    for (ptrdiff_t x = 0; x < W; x++) {
        ptrdiff_t c;
        tofg_bracket(cc, C, (double)x, &c, fx + x);
        cx[x] = (int32_t)c;
    }
    for (ptrdiff_t m = 0; m < N; m++) prior0[m] = depth[m] == depth[m] ? 1.0f : 0.0f;
    const tofg_up_args p0 = {depth, sigma, col, prior0, R, C, rc, cc, spacing,
                             (float)inv2s2, (float)inv2hc2, (float)tol_k, (float)tol_min};
    const int nth = rgbz_threads(workers);
    (void)nth;
    float sw[9 * 9], sall[3];                  /* reach <= 4 */
    const float *swp = tofg_fill_table(&p0, reach, sw, sall) ? sw : NULL;
    /* dynamic: the holes, whose fill is most of the work, cluster in dark regions */
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 8) num_threads(nth)
#endif
    for (ptrdiff_t r = 0; r < R; r++)
        for (ptrdiff_t c = 0; c < C; c++)
            tofg_fill_node(&p0, prior0, own, own_k, r, c, reach, swp, sall, fd, fs, prior);
    const tofg_up_args p = {fd, fs, col, prior, R, C, rc, cc, spacing, (float)inv2s2,
                            (float)inv2hc2, (float)tol_k, (float)tol_min};
    const float s[3] = {(float)(scale * cscale[0]), (float)(scale * cscale[1]),
                        (float)(scale * cscale[2])};
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t y = 0; y < H; y++) {
        ptrdiff_t r;
        float fy;
        tofg_bracket(rc, R, (double)y, &r, &fy);
        RGBZ_CAT(tofg_up_row, IS)(&p, guide, W, y, s, (float)ambiguity, gap, r, fy, cx, fx,
                                  out, conf);
    }
    free(cx); free(fx); free(prior0); free(prior); free(fd); free(fs);
    return RGBZ_OK;
}
