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

/* the ratios A_f / mean of the sample's sites i step, i in [i0, i1), into samp[f][i] (NaN
   where the site is not lit, mean <= 0), in the arithmetic of zgg_amplitudes: first the
   amplitudes A_f into samp[f] frequency by frequency (each of the four loads of the loop a
   constant stride through its plane of taps, which the hardware prefetches; the sites' taps
   lie step apart, a cache line each), then the ratios */
static void RGBZ_CAT(zgg_sample, IS)(const IN_T *taps, ptrdiff_t F, ptrdiff_t N,
                                     ptrdiff_t step, ptrdiff_t i0, ptrdiff_t i1,
                                     double *const *samp)
{
    for (ptrdiff_t f = 0; f < F; f++) {
        const IN_T *restrict t0 = taps + 4 * f * N, *restrict t1 = t0 + N;
        const IN_T *restrict t2 = t0 + 2 * N, *restrict t3 = t0 + 3 * N;
        double *restrict a = samp[f];
        for (ptrdiff_t i = i0; i < i1; i++) {
            const ptrdiff_t n = i * step;
            const double I = (double)t0[n] - (double)t2[n], Q = (double)t3[n] - (double)t1[n];
            a[i] = 0.5 * sqrt(I * I + Q * Q);
        }
    }
    for (ptrdiff_t i = i0; i < i1; i++) {
        double mean = samp[0][i];
        for (ptrdiff_t f = 1; f < F; f++) mean = mean + samp[f][i];
        mean /= (double)F;
        for (ptrdiff_t f = 0; f < F; f++) samp[f][i] = mean > 0 ? samp[f][i] / mean : NAN;
    }
}

/* the sites [lo, hi): the mean amplitude of every site into the grid, the noise variance into
   var (from the medians ratio[f]; 0 when F = 1), in NumPy's order: norm_f = A_f / ratio_f,
   its mean over f (summed in order, over F), then sum_f (norm_f - mean)^2 in order, over
   F (F - 1) */
RGBZ_CLONES_512
static void RGBZ_CAT(zgg_pass, IS)(const IN_T *taps, ptrdiff_t F, ptrdiff_t N, ptrdiff_t lo,
                                   ptrdiff_t hi, ptrdiff_t gxc, ptrdiff_t gx, double *grid,
                                   double *var, const double *ratio)
{
    double A[RGBZ_TOF_MAX_FREQS][ZGG_BLOCK], mean[ZGG_BLOCK], val[ZGG_BLOCK];
    const double den = (double)(F * (F - 1));
    for (ptrdiff_t n0 = lo, nb; n0 < hi; n0 += nb) {
        /* a block within one row of the grid: site n is cell (n / gxc, n % gxc), so the
           block's cells are contiguous */
        const ptrdiff_t ix = n0 % gxc;
        nb = hi - n0 < ZGG_BLOCK ? hi - n0 : ZGG_BLOCK;
        nb = gxc - ix < nb ? gxc - ix : nb;
        const ptrdiff_t cell0 = (n0 / gxc) * gx + ix;
        RGBZ_CAT(zgg_amplitudes, IS)(taps, F, N, n0, nb, A, mean);
        memcpy(grid + cell0, mean, (size_t)nb * sizeof *mean);
        double *restrict vo = var + cell0;
        if (F == 1) {
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) vo[k] = 0.0;
            continue;
        }
        for (ptrdiff_t f = 0; f < F; f++) {
            const double r = ratio[f];
            double *restrict af = A[f];
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) af[k] = af[k] / r;
        }
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] = A[0][k];
        for (ptrdiff_t f = 1; f < F; f++)
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] += A[f][k];
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) {
            mean[k] /= (double)F;
            const double d = A[0][k] - mean[k];
            val[k] = d * d;
        }
        for (ptrdiff_t f = 1; f < F; f++)
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) {
                const double d = A[f][k] - mean[k];
                val[k] += d * d;
            }
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) vo[k] = val[k] / den;
    }
}

/* zgg_pass's values of the sites [lo, hi) in float (the kernel's float32 precision): the
   differences I, Q of the taps converted to float (exact for 8- and 16-bit taps), the
   amplitude 0.5 sqrtf(I^2 + Q^2), the means over f as products with 1 / F, the quotients by
   the medians as products with their float reciprocals; grid and var are the row's cells
   0 .. hi - lo - 1. Within a few float roundings of zgg_pass's values rounded to float
   (relative ~1e-6 on grid; on var, ~1e-6 of grid^2 / F^2) */
RGBZ_CLONES_512
static void RGBZ_CAT(zgg_pass32, IS)(const IN_T *taps, ptrdiff_t F, ptrdiff_t N, ptrdiff_t lo,
                                     ptrdiff_t hi, float *grid, float *var,
                                     const double *ratio)
{
    float A[RGBZ_TOF_MAX_FREQS][ZGG_BLOCK], mean[ZGG_BLOCK];
    float rinv[RGBZ_TOF_MAX_FREQS];
    for (ptrdiff_t f = 0; f < F; f++) rinv[f] = (float)(1.0 / ratio[f]);
    const float invF = 1.0f / (float)F, invden = F > 1 ? 1.0f / (float)(F * (F - 1)) : 0.0f;
    for (ptrdiff_t n0 = lo, nb; n0 < hi; n0 += nb) {
        nb = hi - n0 < ZGG_BLOCK ? hi - n0 : ZGG_BLOCK;
        float *restrict go = grid + (n0 - lo), *restrict vo = var + (n0 - lo);
        for (ptrdiff_t f = 0; f < F; f++) {
            const IN_T *restrict a0 = taps + 4 * f * N + n0, *restrict a1 = a0 + N;
            const IN_T *restrict a2 = a0 + 2 * N, *restrict a3 = a0 + 3 * N;
            float *restrict af = A[f];
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) {
                const float I = (float)a0[k] - (float)a2[k], Q = (float)a3[k] - (float)a1[k];
                af[k] = 0.5f * sqrtf(I * I + Q * Q);
            }
        }
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] = A[0][k];
        for (ptrdiff_t f = 1; f < F; f++)
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] += A[f][k];
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) go[k] = mean[k] * invF;
        if (F == 1) {
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) vo[k] = 0.0f;
            continue;
        }
        for (ptrdiff_t f = 0; f < F; f++) {
            const float r = rinv[f];
            float *restrict af = A[f];
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) af[k] *= r;
        }
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] = A[0][k];
        for (ptrdiff_t f = 1; f < F; f++)
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) mean[k] += A[f][k];
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) {
            mean[k] *= invF;
            const float d = A[0][k] - mean[k];
            vo[k] = d * d;
        }
        for (ptrdiff_t f = 1; f < F; f++)
            RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) {
                const float d = A[f][k] - mean[k];
                vo[k] += d * d;
            }
        RGBZ_IVDEP for (ptrdiff_t k = 0; k < nb; k++) vo[k] *= invden;
    }
}
