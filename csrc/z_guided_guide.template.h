/*
 * z_guided_guide.template.h -- the guide of z_guided (z_guided.h, rgbz_zguided_guide) for one
 * element type of the ToF taps. Instantiated by z_guided_guide.c through rgbz_each_type.h
 * (rgbz_templating.h), with IN_T and IS.
 *
 * Taps (F, 4, N) row-major: A_k of frequency f and site n at taps[(4 f + k) N + n]. The
 * amplitude of a site at a frequency is tof.c's, 0.5 sqrt(I^2 + Q^2) with I = A0 - A2,
 * Q = A3 - A1 in double, so that it equals ToFTaps.amplitude bit for bit.
 */
#if !defined(IN_T) || !defined(IS)
#error "z_guided_guide.template.h: define IN_T and IS (rgbz_each_type.h)"
#endif

/* the amplitudes A[f][k] of the sites n0 .. n0 + nb - 1 and their mean over the frequencies
   (summed in the order of f, then divided by F: NumPy's mean over the first axis) */
RGBZ_INLINE void RGBZ_CAT(zgg_amplitudes, IS)(const IN_T *restrict taps, ptrdiff_t F,
                                              ptrdiff_t N, ptrdiff_t n0, ptrdiff_t nb,
                                              double (*restrict A)[ZGG_BLOCK],
                                              double *restrict mean)
{
    for (ptrdiff_t f = 0; f < F; f++) {
        const IN_T *restrict a0 = taps + 4 * f * N + n0, *restrict a1 = a0 + N;
        const IN_T *restrict a2 = a0 + 2 * N, *restrict a3 = a0 + 3 * N;
        double *restrict af = A[f];
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) {
            const double I = (double)a0[k] - (double)a2[k], Q = (double)a3[k] - (double)a1[k];
            af[k] = 0.5 * sqrt(I * I + Q * Q);
        }
    }
    RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] = A[0][k];
    for (ptrdiff_t f = 1; f < F; f++)
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] += A[f][k];
    RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] /= (double)F;
}

/*
 * The three passes over the sites [lo, hi) of one thread (z_guided_guide.c runs them
 * between its barriers):
 *   pass 1: the mean amplitude of every site into the grid; the histogram hist[f][bin] of
 *           the ratios A_f / mean of the lit sites (mean > 0) and their count;
 *   pass 2: the ratios that fall into the bins [blo[f], bhi[f]] (the median's) appended to
 *           sel[f] from pos[f] on;
 *   pass 3: the noise variance of every site into var, from ratio[f].
 */
static void RGBZ_CAT(zgg_pass, IS)(int pass, const IN_T *taps, ptrdiff_t F, ptrdiff_t N,
                                   ptrdiff_t lo, ptrdiff_t hi, ptrdiff_t gxc, ptrdiff_t gx,
                                   double *grid, double *var, uint32_t *hist, ptrdiff_t *n_lit,
                                   const int *blo, const int *bhi, double *const *sel,
                                   ptrdiff_t *pos, const double *ratio)
{
    double A[RGBZ_TOF_MAX_FREQS][ZGG_BLOCK], mean[ZGG_BLOCK];
    const double scale = (double)ZGG_BINS / (double)F;
    for (ptrdiff_t n0 = lo; n0 < hi; n0 += ZGG_BLOCK) {
        const ptrdiff_t nb = hi - n0 < ZGG_BLOCK ? hi - n0 : ZGG_BLOCK;
        RGBZ_CAT(zgg_amplitudes, IS)(taps, F, N, n0, nb, A, mean);
        for (ptrdiff_t k = 0; k < nb; k++) {
            const ptrdiff_t n = n0 + k, at = (n / gxc) * gx + n % gxc;
            if (pass == 1) {
                grid[at] = mean[k];
                if (F > 1 && mean[k] > 0) {
                    ++*n_lit;
                    for (ptrdiff_t f = 0; f < F; f++)
                        hist[f * ZGG_BINS + zgg_bin(A[f][k] / mean[k], scale)]++;
                }
            } else if (pass == 2) {
                if (mean[k] > 0)
                    for (ptrdiff_t f = 0; f < F; f++) {
                        const double r = A[f][k] / mean[k];
                        const int b = zgg_bin(r, scale);
                        if (b >= blo[f] && b <= bhi[f]) sel[f][pos[f]++] = r;
                    }
            } else {
                /* NumPy's order: norm = A_f / ratio_f, its mean over f (summed in order, over
                   F), then sum_f (norm_f - mean)^2 in order, over F (F - 1) */
                double nm = A[0][k] / ratio[0];
                for (ptrdiff_t f = 1; f < F; f++) nm += A[f][k] / ratio[f];
                nm /= (double)F;
                double s = 0.0;
                for (ptrdiff_t f = 0; f < F; f++) {
                    const double d = A[f][k] / ratio[f] - nm;
                    s = f ? s + d * d : d * d;
                }
                var[at] = s / (double)(F * (F - 1));
            }
        }
    }
}
