/*
 * tof.c -- indirect time-of-flight: four-tap demodulation and multi-frequency
 * phase unwrapping at the Z sites.
 *
 * Tap convention (rgbz_fast.sensor, docs/sensor.md): for frequency f and tap
 * k = 0..3, A_k = offset + a*cos(phi + k*pi/2) (plus the black level, which
 * cancels), so
 *     I = A0 - A2,  Q = A3 - A1,  phi = atan2(Q, I) wrapped to [0, 2*pi),
 *     amplitude = sqrt(I^2 + Q^2) / 2,  offset = (A0 + A1 + A2 + A3) / 4,
 *     distance = c * phi / (4 * pi * f)  (modulo c / (2 f)).
 *
 * Layout: taps (F, 4, N) row-major, element type u16, f32 or f64; outputs
 * (F, N) float64. Unwrapping: brute force over the wrap counts of the
 * frequency with the longest ambiguity interval; every other frequency takes
 * its nearest wrap count; the candidate with the smallest weighted squared
 * residual wins and the depth is the weighted mean of the per-frequency
 * distances (weights w_i, typically f_i^2, i.e. inverse depth variance).
 */
#include <math.h>
#include <stdlib.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"
#include "rgbz_ops.h"

#define TOF_TWO_PI 6.283185307179586
#define TOF_C 299792458.0

#define TOF_DEMOD(T, S)                                                                           \
static void rgbz_tof_demod_##S(const T *taps, ptrdiff_t F, ptrdiff_t N, double *phase,           \
                               double *amp, double *offset, int workers)                         \
{                                                                                                 \
    (void)workers;                                                                                \
    for (ptrdiff_t f = 0; f < F; f++) {                                                           \
        const T *a0 = taps + (4 * f + 0) * N, *a1 = taps + (4 * f + 1) * N;                       \
        const T *a2 = taps + (4 * f + 2) * N, *a3 = taps + (4 * f + 3) * N;                       \
        double *ph = phase + f * N, *am = amp + f * N, *of = offset + f * N;                      \
        TOF_PARALLEL                                                                              \
        for (ptrdiff_t n = 0; n < N; n++) {                                                       \
            double A0 = (double)a0[n], A1 = (double)a1[n], A2 = (double)a2[n], A3 = (double)a3[n];\
            double I = OSUB(A0, A2), Q = OSUB(A3, A1);                                            \
            OPC_(RGBZ_OP_ATAN2);                                                                  \
            double p = atan2(Q, I);                                                               \
            if (OCMP(p < 0)) p = OADD(p, TOF_TWO_PI);                                             \
            if (p >= TOF_TWO_PI) p = 0.0;  /* -tiny + 2 pi rounds to 2 pi: keep [0, 2 pi) */     \
            ph[n] = p;                                                                            \
            OPC_(RGBZ_OP_SQRT);                                                                   \
            am[n] = OMUL(0.5, sqrt(OADD(OMUL(I, I), OMUL(Q, Q))));                                \
            of[n] = OMUL(0.25, OADD(OADD(A0, A1), OADD(A2, A3)));                                 \
        }                                                                                         \
    }                                                                                             \
}

#ifdef _OPENMP
#define TOF_PARALLEL _Pragma("omp parallel for schedule(static) num_threads(workers > 0 ? workers : omp_get_max_threads())")
#else
#define TOF_PARALLEL
#endif

TOF_DEMOD(uint16_t, u16)
TOF_DEMOD(float, f32)
TOF_DEMOD(double, f64)

int RGBZ_SYM(rgbz_tof_demodulate)(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                                  double *phase, double *amp, double *offset, int workers)
{
    if (!taps || !phase || !amp || !offset || F < 1 || N < 0) return RGBZ_EINVAL;
    if (N == 0) return RGBZ_OK;
    switch (in_type) {
    case RGBZ_T_U16: rgbz_tof_demod_u16(taps, F, N, phase, amp, offset, workers); break;
    case RGBZ_T_F32: rgbz_tof_demod_f32(taps, F, N, phase, amp, offset, workers); break;
    case RGBZ_T_F64: rgbz_tof_demod_f64(taps, F, N, phase, amp, offset, workers); break;
    default: return RGBZ_EINVAL;
    }
    return RGBZ_OK;
}

int RGBZ_SYM(rgbz_tof_unwrap)(const double *phase, ptrdiff_t F, ptrdiff_t N, const double *freqs,
                              const double *weights, double max_range, double *depth,
                              double *residual, int32_t *wraps, int workers)
{
    if (!phase || !freqs || !weights || !depth || !residual || F < 1 || F > 16 || N < 0 ||
        !(max_range > 0))
        return RGBZ_EINVAL;
    (void)workers;
    double amb[16], wsum = 0;
    int base = 0;
    for (ptrdiff_t i = 0; i < F; i++) {
        if (!(freqs[i] > 0) || !(weights[i] >= 0)) return RGBZ_EINVAL;
        amb[i] = TOF_C / (2.0 * freqs[i]);
        if (amb[i] > amb[base]) base = (int)i;
        wsum += weights[i];
    }
    if (!(wsum > 0)) return RGBZ_EINVAL;
    const int nwrap = (int)ceil(max_range / amb[base] - 1e-12);
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(workers > 0 ? workers : omp_get_max_threads())
#endif
    for (ptrdiff_t n = 0; n < N; n++) {
        double best = INFINITY, best_d = 0;
        int best_w = 0;
        double d0 = phase[base * N + n] / TOF_TWO_PI * amb[base];
        for (int w = 0; w < nwrap; w++) {
            double cand = d0 + w * amb[base];
            double cost = 0, num = 0;
            for (ptrdiff_t i = 0; i < F; i++) {
                double di = phase[i * N + n] / TOF_TWO_PI * amb[i];
                double k = floor((cand - di) / amb[i] + 0.5);
                di += k * amb[i];
                double e = di - cand;
                cost += weights[i] * e * e;
                num += weights[i] * di;
            }
            if (cost < best) {
                best = cost;
                best_d = num / wsum;
                best_w = w;
            }
        }
        depth[n] = best_d;
        residual[n] = sqrt(best / wsum);
        if (wraps) wraps[n] = best_w;
    }
    return RGBZ_OK;
}
