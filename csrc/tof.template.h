/*
 * tof.template.h -- the per-block ToF kernels that read the taps, for one tap
 * element type (tof.c has the algorithm, the unwrapping, the entry points and
 * the instances).
 *
 * Memory layout: taps (F, 4, N) row-major, A_k of frequency f and site n at
 * taps[(4 f + k) N + n]; outputs (F, N) or (N,) float64. A block is the sites
 * [n0, n0 + nb), nb <= TOF_BLOCK.
 *
 * Template parameters, #defined by the includer (tof.c) and #undefined after:
 *   TAP_T  the element type of the taps: uint16_t, float or double
 *   TS     its suffix: u16, f32 or f64
 */
#ifndef TAP_T
#error "tof.template.h: #define TAP_T (the element type of the taps)"
#endif
#ifndef TS
#error "tof.template.h: #define TS (the suffix of TAP_T: u16, f32 or f64)"
#endif

/* I = A0 - A2, Q = A3 - A1 of frequency f, and the offset (A0 + A1 + A2 + A3) / 4 to of
   if not NULL */
RGBZ_INLINE void RGBZ_CAT(tof_iq, TS)(const TAP_T *restrict taps, ptrdiff_t N, ptrdiff_t f,
                                      ptrdiff_t n0, ptrdiff_t nb, double *restrict I,
                                      double *restrict Q, double *restrict of)
{
    const TAP_T *A0 = taps + 4 * f * N + n0, *A1 = A0 + N, *A2 = A0 + 2 * N, *A3 = A0 + 3 * N;
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
RGBZ_CLONES_512 static void RGBZ_CAT(tof_demod, TS)(const tof_args *a, ptrdiff_t n0, ptrdiff_t nb)
{
    double I[TOF_BLOCK], Q[TOF_BLOCK];
    const ptrdiff_t N = a->N;
    double *restrict phase = a->phase, *restrict amp = a->amp, *restrict offset = a->offset;
    for (ptrdiff_t f = 0; f < a->F; f++) {
        const ptrdiff_t o = f * N + n0;
        RGBZ_CAT(tof_iq, TS)((const TAP_T *)a->taps, N, f, n0, nb, I, Q, offset + o);
        tof_from_iq(I, Q, nb, NULL, 0.0, phase + o, NULL, amp + o);
    }
}

/* demodulation and unwrapping of the block [n0, n0 + nb) (rgbz_tof_depth): depth,
   residual, wraps, and phase, amplitude, offset where they are not NULL */
RGBZ_CLONES_512 static void RGBZ_CAT(tof_depth, TS)(const tof_args *a, ptrdiff_t n0, ptrdiff_t nb)
{
    double d[RGBZ_TOF_MAX_FREQS * TOF_BLOCK], I[TOF_BLOCK], Q[TOF_BLOCK];
    const tof_plan *p = a->p;
    const ptrdiff_t N = a->N;
    for (int f = 0; f < p->F; f++) {
        const ptrdiff_t o = f * N + n0;
        RGBZ_CAT(tof_iq, TS)((const TAP_T *)a->taps, N, f, n0, nb, I, Q,
                             a->offset ? a->offset + o : NULL);
        tof_from_iq(I, Q, nb, NULL, p->scale[f], a->phase ? a->phase + o : NULL,
                    d + f * TOF_BLOCK, a->amp ? a->amp + o : NULL);
    }
    tof_unwrap_block(p, d, nb, a->depth + n0, a->residual + n0, a->wraps + n0);
}
