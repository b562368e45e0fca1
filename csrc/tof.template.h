/*
 * tof.template.h -- the per-block ToF kernels that read the taps, and the loop over the
 * blocks, for one tap element type (tof.c has the algorithm, the unwrapping, the entry
 * points and the instances).
 *
 * Memory layout: taps (F, 4, N) row-major, A_k of frequency f and site n at
 * taps[(4 f + k) N + n]; outputs (F, N) or (N,) float64. A block is the sites
 * [n0, n0 + nb), nb <= TOF_BLOCK.
 *
 * Template parameters (rgbz_templating.h), #defined by rgbz_each_type.h, which tof.c
 * includes once:
 *   IN_T  the element type of the taps
 *   IS    its suffix (u8, u16, f32, f64)
 */
#ifndef IN_T
#error "tof.template.h: #define IN_T (the element type of the taps)"
#endif
#ifndef IS
#error "tof.template.h: #define IS (the suffix of IN_T: u8, u16, f32 or f64)"
#endif

/* I = A0 - A2, Q = A3 - A1 of frequency f, and the offset (A0 + A1 + A2 + A3) / 4 to of
   if not NULL */
RGBZ_INLINE void RGBZ_CAT(tof_iq, IS)(const IN_T *restrict taps, ptrdiff_t N, ptrdiff_t f,
                                      ptrdiff_t n0, ptrdiff_t nb, double *restrict I,
                                      double *restrict Q, double *restrict of)
{
    const IN_T *A0 = taps + 4 * f * N + n0, *A1 = A0 + N, *A2 = A0 + 2 * N, *A3 = A0 + 3 * N;
    for (ptrdiff_t k = 0; k < nb; k++) {
        I[k] = OSUB((double)A0[k], (double)A2[k]);
        Q[k] = OSUB((double)A3[k], (double)A1[k]);
    }
    if (of)
        for (ptrdiff_t k = 0; k < nb; k++)
            of[k] = OMUL(0.25, OADD(OADD((double)A0[k], (double)A1[k]),
                                    OADD((double)A2[k], (double)A3[k])));
}

/* demodulation of the block [n0, n0 + nb): phase, amplitude, offset of every frequency.
   restrict: the outputs never overlap the taps nor each other (the Python layer
   allocates them), which spares the vectoriser its run-time alias checks. */
RGBZ_CLONES_512 static void RGBZ_CAT(tof_demod, IS)(const IN_T *taps, ptrdiff_t F, ptrdiff_t N,
                                                    ptrdiff_t n0, ptrdiff_t nb,
                                                    double *restrict phase,
                                                    double *restrict amp,
                                                    double *restrict offset)
{
    double I[TOF_BLOCK], Q[TOF_BLOCK];
    for (ptrdiff_t f = 0; f < F; f++) {
        const ptrdiff_t o = f * N + n0;
        RGBZ_CAT(tof_iq, IS)(taps, N, f, n0, nb, I, Q, offset + o);
        tof_from_iq(I, Q, nb, NULL, 0.0, phase + o, NULL, amp + o);
    }
}

/* demodulation and unwrapping of the block [n0, n0 + nb) (rgbz_tof_depth): depth,
   residual, wraps, and phase, amplitude, offset where they are not NULL */
RGBZ_CLONES_512 static void RGBZ_CAT(tof_depth, IS)(const IN_T *taps, ptrdiff_t N,
                                                    const tof_plan *p, ptrdiff_t n0,
                                                    ptrdiff_t nb, double *depth,
                                                    double *residual, int32_t *wraps,
                                                    double *phase, double *amp,
                                                    double *offset)
{
    double d[RGBZ_TOF_MAX_FREQS * TOF_BLOCK], I[TOF_BLOCK], Q[TOF_BLOCK];
    for (int f = 0; f < p->F; f++) {
        const ptrdiff_t o = f * N + n0;
        RGBZ_CAT(tof_iq, IS)(taps, N, f, n0, nb, I, Q, offset ? offset + o : NULL);
        tof_from_iq(I, Q, nb, NULL, p->scale[f], phase ? phase + o : NULL, d + f * TOF_BLOCK,
                    amp ? amp + o : NULL);
    }
    tof_unwrap_block(p, d, nb, depth + n0, residual + n0, wraps + n0);
}

/* every block of the N sites, split across threads: demodulated (p = NULL: phase, amp and
   offset are all given) or demodulated and unwrapped with plan p */
static int RGBZ_CAT(tof_blocks, IS)(const IN_T *taps, ptrdiff_t F, ptrdiff_t N,
                                    const tof_plan *p, double *depth, double *residual,
                                    int32_t *wraps, double *phase, double *amp,
                                    double *offset, int workers)
{
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t blk = 0; blk < TOF_NBLOCKS(N); blk++) {
        const ptrdiff_t n0 = blk * TOF_BLOCK, nb = N - n0 < TOF_BLOCK ? N - n0 : TOF_BLOCK;
        if (p)
            RGBZ_CAT(tof_depth, IS)(taps, N, p, n0, nb, depth, residual, wraps, phase, amp,
                                    offset);
        else
            RGBZ_CAT(tof_demod, IS)(taps, F, N, n0, nb, phase, amp, offset);
    }
    return RGBZ_OK;
}
