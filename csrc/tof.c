/*
 * tof.c -- indirect time-of-flight: four-tap demodulation and multi-frequency
 * phase unwrapping at the Z sites (the paper's i-ToF sensor and ISP models,
 * section 5.1.2 and 5.2: four shutters 90 degrees apart, a set of three
 * modulation frequencies against phase wrapping; the paper numbers no equation
 * for them, the formulas are these).
 *
 * Tap convention (rgbz_fast.simulation, docs/guide/sensor.md): for frequency f and tap
 * k = 0..3, A_k = offset + a*cos(phi + k*pi/2) (plus the black level, which
 * cancels), so
 *     I = A0 - A2,  Q = A3 - A1,  phi = atan2(Q, I) wrapped to [0, 2*pi),
 *     amplitude = sqrt(I^2 + Q^2) / 2,  offset = (A0 + A1 + A2 + A3) / 4,
 *     distance = c * phi / (4 * pi * f)  (modulo c / (2 f)).
 *
 * Layout: taps (F, 4, N) row-major, of any element type (tof.template.h, once
 * per type; the Python layer passes u16, f32 or f64); outputs (F, N) or (N,)
 * float64. Work is done in blocks of TOF_BLOCK sites, each block's scratch in
 * L1, blocks split across threads.
 *
 * Unwrapping: brute force over the wrap counts w = 0 .. nwrap-1 of the
 * frequency with the longest ambiguity interval A = c / (2 f_base) (nwrap =
 * ceil(max_range / A), at most RGBZ_TOF_MAX_WRAPS: the Python layer bounds
 * max_range by the unambiguous range of the frequency set and by that count);
 * every other frequency i takes the wrap count k_i nearest to the candidate
 * d_base + w A; the candidate with the smallest weighted squared residual
 * sum_i w_i (d_i + k_i a_i - cand)^2 wins (the first one on a tie) and the
 * depth is the weighted mean of the per-frequency distances (weights w_i,
 * typically f_i^2, i.e. inverse depth variance).
 *
 * Per site, with y_i = (d_base - d_i) / a_i and r_i = A / a_i computed once:
 *     x = y_i + w r_i,  k_i = floor(x + 0.5),  residual_i = a_i (k_i - x),
 * so one candidate costs a multiply-add, a floor and a multiply-add per
 * frequency. rgbz_fast._devtools._numpy_tof holds the same arithmetic in NumPy (the tests
 * compare them bit for bit from the same phases).
 *
 * rgbz_tof_depth fuses the two stages (taps -> phase, amplitude, offset,
 * depth, residual, wrap count in one pass over the blocks, no frame-size
 * intermediate array); rgbz_tof_depth_iq does the same from averaged phasors
 * (I, Q), and rgbz_tof_depth_iq_row for one row of them on the calling thread (the
 * guided denoise's output rows), with a path of its own for three frequencies and four
 * wrap counts that computes the same operations per site in registers.
 */
/* No FP trap is ever enabled here, so GCC may compute both arms of a `?:` and
   vectorise the site loops (its default -ftrapping-math forbids that; clang's
   default already allows it). Results are unchanged: no value-changing flag. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math")
#endif
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <stdint.h>
#include "rgbz.h"
#include "rgbz_ops.h"
#include "tof.h"

#define TOF_TWO_PI 6.283185307179586
#define TOF_PI 3.141592653589793
#define TOF_PI_2 1.5707963267948966
#define TOF_PI_4 0.7853981633974483
#define TOF_C 299792458.0

/*
 * atan2(y, x) in [-pi, pi] without libm and without branches (every `?:` is a
 * select, so that loops over sites vectorise): octant reduction to
 * t = min/max in [0, 1], Cephes' reduction of t > 0.66 to (t - 1) / (t + 1)
 * (computed as (min - max) / (min + max), an exact numerator by Sterbenz) and
 * Cephes' degree 4/5 rational approximation of atan on [-0.21, 0.66] (peak
 * relative error 2.6e-18 in exact arithmetic); the low bits of pi/4, pi/2 and
 * pi enter before the final rounding. Measured against numpy.arctan2 on
 * random, tiny (1e-310) and huge (1e300) arguments: at most one ulp of the
 * result (tests/tof/test_tof.py::test_fast_atan2_matches_numpy_to_one_ulp).
 * atan2(0, 0) = 0 (also for -0); infinite arguments give libm's values
 * (pi/4 for two infinities, 0 or pi/2 for one).
 */
static inline double tof_atan2(double y, double x)
{
    const double ax = fabs(x), ay = fabs(y);
    const double mx0 = ax > ay ? ax : ay, mn0 = ax > ay ? ay : ax;
    const int inf = mx0 > DBL_MAX;
    const double mx = inf ? 1.0 : mx0, mn = inf ? (mn0 > DBL_MAX ? 1.0 : 0.0) : mn0;
    const int big = mn > 0.66 * mx;
    const double num = big ? mn - mx : mn;
    const double den = big ? mn + mx : (mx > 0 ? mx : 1.0);
    const double u = num / den, z = u * u;
    const double p = ((((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z
                        - 7.500855792314704667340e1) * z - 1.228866684490136173410e2) * z
                      - 6.485021904942025371773e1) * z;
    const double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z
                       + 4.328810604912902668951e2) * z + 4.853903996359136964868e2) * z
                     + 1.945506571482613964425e2;
    const double a0 = u + u * (p / q);
    const double a1 = big ? TOF_PI_4 + (a0 + 3.061616997868382943065e-17) : a0;
    const double a2 = ay > ax ? TOF_PI_2 + (6.123233995736765886130e-17 - a1) : a1;
    const double a3 = x < 0 ? TOF_PI + (1.2246467991473532e-16 - a2) : a2;
    return y < 0 ? -a3 : a3;
}

/* the phase of (I, Q) in [0, 2 pi) */
static inline double tof_phase(double I, double Q)
{
    OPC_(RGBZ_OP_ATAN2);
    double p = tof_atan2(Q, I);
    p = OCMP(p < 0) ? OADD(p, TOF_TWO_PI) : p;
    return p >= TOF_TWO_PI ? 0.0 : p;  /* -tiny + 2 pi rounds to 2 pi: keep [0, 2 pi) */
}

/* ------------------------------------------------------------------ demodulation */
/* sites per block of the OpenMP loops: the per-block scratch stays in L1 */
#define TOF_BLOCK 128
#define TOF_NBLOCKS(N) (((N) + TOF_BLOCK - 1) / TOF_BLOCK)

/* amplitude = sqrt(I^2 + Q^2) / 2 */
static inline double tof_amplitude(double I, double Q)
{
    OPC_(RGBZ_OP_SQRT);
    return OMUL(0.5, sqrt(OADD(OMUL(I, I), OMUL(Q, Q))));
}

/*
 * One frequency of a block of nb sites from its phasors I, Q: the phase in [0, 2 pi)
 * (stored to ph if not NULL), the distance phase * sc (to dist if not NULL) and the
 * amplitude (to am if not NULL). ok (not NULL): a non-finite I or Q clears ok[k] and
 * gives the phase 0, so that no NaN reaches the unwrapping's floors (a NaN through the
 * int32 floor is undefined behaviour).
 */
RGBZ_INLINE void tof_from_iq(const double *I, const double *Q, ptrdiff_t nb, int *ok,
                             double sc, double *restrict ph, double *restrict dist,
                             double *restrict am)
{
    double phi[TOF_BLOCK];
    for (ptrdiff_t k = 0; k < nb; k++) {
        const int in = !ok || (fabs(I[k]) <= DBL_MAX && fabs(Q[k]) <= DBL_MAX);   /* not NaN */
        if (ok) ok[k] &= in;
        phi[k] = in ? tof_phase(I[k], Q[k]) : 0.0;
    }
    if (ph)
        for (ptrdiff_t k = 0; k < nb; k++) ph[k] = phi[k];
    if (dist)
        for (ptrdiff_t k = 0; k < nb; k++) dist[k] = phi[k] * sc;
    if (am)
        for (ptrdiff_t k = 0; k < nb; k++) am[k] = tof_amplitude(I[k], Q[k]);
}

/* ------------------------------------------------------------------ unwrapping */
typedef struct {
    int F, base, nwrap, n_other, int_floor;
    int other[RGBZ_TOF_MAX_FREQS];          /* the frequencies other than the base one */
    double amb[RGBZ_TOF_MAX_FREQS];         /* c / (2 f_i), m */
    double scale[RGBZ_TOF_MAX_FREQS];       /* amb_i / (2 pi): phase -> distance */
    double inv_amb[RGBZ_TOF_MAX_FREQS];     /* 1 / amb_i */
    double ratio[RGBZ_TOF_MAX_FREQS];       /* amb_base / amb_i */
    double wcost[RGBZ_TOF_MAX_FREQS];       /* w_i amb_i^2 */
    double w[RGBZ_TOF_MAX_FREQS];
    double wsum;
} tof_plan;

static int tof_plan_init(tof_plan *p, ptrdiff_t F, const double *freqs, const double *weights,
                         double max_range)
{
    if (!freqs || !weights || F < 1 || F > RGBZ_TOF_MAX_FREQS || !(max_range > 0))
        return RGBZ_EINVAL;
    p->F = (int)F;
    p->base = 0;
    p->wsum = 0;
    for (int i = 0; i < p->F; i++) {
        if (!(freqs[i] > 0 && freqs[i] <= DBL_MAX) || !(weights[i] >= 0 && weights[i] <= DBL_MAX))
            return RGBZ_EINVAL;
        p->amb[i] = TOF_C / (2.0 * freqs[i]);
        if (p->amb[i] > p->amb[p->base]) p->base = i;
        p->wsum += weights[i];
    }
    if (!(p->wsum > 0 && p->wsum <= DBL_MAX)) return RGBZ_EINVAL;
    /* the count is checked as a double, before any conversion to int: a huge max_range
       would overflow the int (undefined behaviour) */
    const double nw = ceil(max_range / p->amb[p->base] - 1e-12);
    if (!(nw <= RGBZ_TOF_MAX_WRAPS)) return RGBZ_EINVAL;
    p->nwrap = nw < 1 ? 1 : (int)nw;
    double rmax = 1;
    p->n_other = 0;
    for (int i = 0; i < p->F; i++) {
        p->scale[i] = p->amb[i] / TOF_TWO_PI;
        p->inv_amb[i] = 1.0 / p->amb[i];
        p->ratio[i] = p->amb[p->base] / p->amb[i];
        p->wcost[i] = weights[i] * p->amb[i] * p->amb[i];
        p->w[i] = weights[i];
        if (p->ratio[i] > rmax) rmax = p->ratio[i];
        if (i != p->base) p->other[p->n_other++] = i;
    }
    /* |x| <= |y_i| + (nwrap - 1) r_i <= nwrap r_i + 1: below 2^30 the floor goes through
       int32 (exact there, and vectorisable); beyond it, libm's floor */
    p->int_floor = p->nwrap * rmax + 2 < 1073741824.0;
    return RGBZ_OK;
}

/* floor(t) for |t| < 2^31: truncate through int32, step down below negative non-integers */
static inline double tof_floor_i32(double t)
{
    const double k = (double)(int32_t)t;
    return t < k ? k - 1.0 : k;
}

/*
 * Unwrap one block of nb <= TOF_BLOCK sites. d: F rows of TOF_BLOCK distances in
 * [0, amb_i) (finite). Every loop runs over the sites of the block, innermost, so that
 * it vectorises; the wrap count is carried as a double for the same reason. `i32`
 * is a compile-time constant in the two instances below.
 */
RGBZ_INLINE double tof_floor_sel(double t, int i32)
{
    return i32 ? tof_floor_i32(t) : floor(t);
}

RGBZ_INLINE void tof_unwrap_block_impl(const tof_plan *p, const double *d, ptrdiff_t nb,
                                      double *depth, double *residual, int32_t *wraps, int i32)
{
    double y[(RGBZ_TOF_MAX_FREQS - 1) * TOF_BLOCK];
    double cost[TOF_BLOCK], best[TOF_BLOCK], bw[TOF_BLOCK], num[TOF_BLOCK];
    const int b = p->base, no = p->n_other;
    const double *db = d + b * TOF_BLOCK;
    for (int j = 0; j < no; j++) {
        const int i = p->other[j];
        const double *di = d + i * TOF_BLOCK, ia = p->inv_amb[i];
        double *yj = y + j * TOF_BLOCK;
        for (ptrdiff_t k = 0; k < nb; k++) yj[k] = (db[k] - di[k]) * ia;
    }
    for (ptrdiff_t k = 0; k < nb; k++) {
        best[k] = INFINITY;
        bw[k] = 0;
    }
    for (int w = 0; w < p->nwrap; w++) {
        const double wd = (double)w;
        for (ptrdiff_t k = 0; k < nb; k++) cost[k] = 0;
        for (int j = 0; j < no; j++) {
            const int i = p->other[j];
            const double r = w * p->ratio[i], wc = p->wcost[i];
            const double *yj = y + j * TOF_BLOCK;
            for (ptrdiff_t k = 0; k < nb; k++) {
                const double x = yj[k] + r;
                const double e = tof_floor_sel(x + 0.5, i32) - x;
                cost[k] += wc * (e * e);
            }
        }
        for (ptrdiff_t k = 0; k < nb; k++) {
            /* loads, selects, stores: GCC if-converts (and vectorises) this form only */
            const double c = cost[k], bc = best[k], bk = bw[k];
            const int better = c < bc;                 /* the first minimum wins a tie */
            const double nc = better ? c : bc, nk = better ? wd : bk;
            best[k] = nc;
            bw[k] = nk;
        }
    }
    const double wb = p->w[b], ab = p->amb[b];
    for (ptrdiff_t k = 0; k < nb; k++) num[k] = wb * (db[k] + bw[k] * ab);
    for (int j = 0; j < no; j++) {
        const int i = p->other[j];
        const double *di = d + i * TOF_BLOCK, *yj = y + j * TOF_BLOCK;
        const double r = p->ratio[i], wi = p->w[i], ai = p->amb[i];
        for (ptrdiff_t k = 0; k < nb; k++) {
            const double kk = tof_floor_sel(yj[k] + bw[k] * r + 0.5, i32);
            num[k] += wi * (di[k] + kk * ai);
        }
    }
    const double ws = p->wsum;
    for (ptrdiff_t k = 0; k < nb; k++) {
        depth[k] = num[k] / ws;
        residual[k] = sqrt(best[k] / ws);
        wraps[k] = (int32_t)bw[k];
    }
}

RGBZ_CLONES_512 static void tof_unwrap_block_i32(const tof_plan *p, const double *d, ptrdiff_t nb,
                                            double *depth, double *residual, int32_t *wraps)
{
    tof_unwrap_block_impl(p, d, nb, depth, residual, wraps, 1);
}

static void tof_unwrap_block_libm(const tof_plan *p, const double *d, ptrdiff_t nb,
                                  double *depth, double *residual, int32_t *wraps)
{
    tof_unwrap_block_impl(p, d, nb, depth, residual, wraps, 0);
}

static inline void tof_unwrap_block(const tof_plan *p, const double *d, ptrdiff_t nb,
                                    double *depth, double *residual, int32_t *wraps)
{
    if (p->int_floor) tof_unwrap_block_i32(p, d, nb, depth, residual, wraps);
    else tof_unwrap_block_libm(p, d, nb, depth, residual, wraps);
}

/* Unwrap a block whose sites with ok[k] = 0 had an input outside the domain: those are
   reported (depth and residual NaN, wraps -1), never computed. Returns 1 if there was one. */
static int tof_unwrap_checked(const tof_plan *p, const double *d, const int *ok, ptrdiff_t nb,
                              double *depth, double *residual, int32_t *wraps)
{
    int all_ok = 1;
    for (ptrdiff_t k = 0; k < nb; k++) all_ok &= ok[k];
    tof_unwrap_block(p, d, nb, depth, residual, wraps);
    if (all_ok) return 0;
    for (ptrdiff_t k = 0; k < nb; k++) {
        if (!ok[k]) {
            depth[k] = residual[k] = NAN;
            wraps[k] = -1;
        }
    }
    return 1;
}

/* One block [n0, n0 + nb) of tof_unwrap_sites (below): the distances of every frequency from
   the phases or the phasors, then the unwrapping; returns 1 if a site was outside the
   domain. In the three builds of RGBZ_CLONES_512, which compute the same IEEE operations.
   The planes of x and q are N apart, those of phase and amp NO apart. */
RGBZ_CLONES_512 static int tof_unwrap_site_block(const tof_plan *p, const double *x,
                                                 const double *q, ptrdiff_t N, ptrdiff_t NO,
                                                 ptrdiff_t n0, ptrdiff_t nb, double *depth,
                                                 double *residual, int32_t *wraps,
                                                 double *phase, double *amp)
{
    double d[RGBZ_TOF_MAX_FREQS * TOF_BLOCK];
    int ok[TOF_BLOCK];
    for (ptrdiff_t k = 0; k < nb; k++) ok[k] = 1;
    for (int f = 0; f < p->F; f++) {
        const ptrdiff_t o = f * N + n0, oo = f * NO + n0;
        const double sc = p->scale[f];
        double *df = d + f * TOF_BLOCK;
        if (q) {
            tof_from_iq(x + o, q + o, nb, ok, sc, phase ? phase + oo : NULL, df,
                        amp ? amp + oo : NULL);
            continue;
        }
        const double *ph = x + o;
        for (ptrdiff_t k = 0; k < nb; k++) {
            const int in = ph[k] >= 0 && ph[k] < TOF_TWO_PI;   /* false for NaN too */
            ok[k] &= in;
            df[k] = in ? ph[k] * sc : 0.0;              /* no NaN reaches a floor */
        }
    }
    return tof_unwrap_checked(p, d, ok, nb, depth + n0, residual + n0, wraps + n0);
}

/*
 * Unwrapping from phases (q = NULL: x holds the phases (F, N), checked to lie in [0, 2 pi))
 * or from phasors (x = I, q = Q, each (F, N), checked to be finite; phase and amp, if not
 * NULL, get the phase and amplitude). A site outside the domain is reported, not computed:
 * RGBZ_EDOMAIN.
 */
static int tof_unwrap_sites(const double *x, const double *q, ptrdiff_t F, ptrdiff_t N,
                            ptrdiff_t NO, const double *freqs, const double *weights,
                            double max_range, double *depth, double *residual, int32_t *wraps,
                            double *phase, double *amp, int workers)
{
    tof_plan plan;
    if (!x || !depth || !residual || !wraps || N < 0) return RGBZ_EINVAL;
    int st = tof_plan_init(&plan, F, freqs, weights, max_range);
    if (st != RGBZ_OK) return st;
    const tof_plan *p = &plan;
    int bad = 0;
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR_OR(bad)
    for (ptrdiff_t blk = 0; blk < TOF_NBLOCKS(N); blk++) {
        const ptrdiff_t n0 = blk * TOF_BLOCK, nb = N - n0 < TOF_BLOCK ? N - n0 : TOF_BLOCK;
        bad |= tof_unwrap_site_block(p, x, q, N, NO, n0, nb, depth, residual, wraps, phase,
                                     amp);
    }
    return bad ? RGBZ_EDOMAIN : RGBZ_OK;
}

int rgbz_tof_unwrap(const double *phase, ptrdiff_t F, ptrdiff_t N, const double *freqs,
                    const double *weights, double max_range, double *depth,
                    double *residual, int32_t *wraps, int workers)
{
    return tof_unwrap_sites(phase, NULL, F, N, N, freqs, weights, max_range, depth, residual,
                            wraps, NULL, NULL, workers);
}

/* ------------------------------------------------------------------ the tap types */
/* the per-block kernels that read the taps and the loop over the blocks, per element type */
#define RGBZ_TYPE_TEMPLATE "tof.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

/* The entry points that read taps (F, 4, N) of in_type: demodulation only (p = NULL), or
   demodulation and unwrapping with plan p into depth, residual and wraps; phase, amp,
   offset (F, N) where they are not NULL. */
static int tof_taps(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N, const tof_plan *p,
                    double *depth, double *residual, int32_t *wraps, double *phase,
                    double *amp, double *offset, int workers)
{
    if (N == 0) return RGBZ_OK;
#define TOF_TAPS_(s, T)                                                                      \
    return RGBZ_CAT(tof_blocks, s)((const T *)taps, F, N, p, depth, residual, wraps, phase,  \
                                   amp, offset, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, TOF_TAPS_, return RGBZ_EINVAL)
#undef TOF_TAPS_
}

int rgbz_tof_demodulate(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                        double *phase, double *amp, double *offset, int workers)
{
    if (!taps || !phase || !amp || !offset || F < 1 || N < 0) return RGBZ_EINVAL;
    return tof_taps(in_type, taps, F, N, NULL, NULL, NULL, NULL, phase, amp, offset, workers);
}

int rgbz_tof_depth(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N,
                   const double *freqs, const double *weights, double max_range,
                   double *depth, double *residual, int32_t *wraps, double *phase,
                   double *amp, double *offset, int workers)
{
    tof_plan plan;
    if (!taps || !depth || !residual || !wraps || N < 0) return RGBZ_EINVAL;
    int st = tof_plan_init(&plan, F, freqs, weights, max_range);
    if (st != RGBZ_OK) return st;
    return tof_taps(in_type, taps, F, N, &plan, depth, residual, wraps, phase, amp, offset,
                    workers);
}

int rgbz_tof_depth_iq(const double *i_comp, const double *q_comp, ptrdiff_t F,
                      ptrdiff_t N, const double *freqs, const double *weights,
                      double max_range, double *depth, double *residual,
                      int32_t *wraps, double *phase, double *amp, int workers)
{
    if (!q_comp) return RGBZ_EINVAL;
    return tof_unwrap_sites(i_comp, q_comp, F, N, N, freqs, weights, max_range, depth, residual,
                            wraps, phase, amp, workers);
}

int rgbz_tof_depth_iq_strided(const double *i_comp, const double *q_comp, ptrdiff_t F,
                              ptrdiff_t N, ptrdiff_t ldo, const double *freqs,
                              const double *weights, double max_range, double *depth,
                              double *residual, int32_t *wraps, double *phase, double *amp,
                              int workers)
{
    if (!q_comp || ldo < N) return RGBZ_EINVAL;
    return tof_unwrap_sites(i_comp, q_comp, F, N, ldo, freqs, weights, max_range, depth,
                            residual, wraps, phase, amp, workers);
}

/* ------------------------------------------------------------------ one row of phasors */
/* candidate w (its offsets r1, r2) of tof_unwrap_row_f3w4 against the best so far: the
   operations of tof_unwrap_block_impl's candidate loop for one site */
static inline void tof_candidate(double y1, double y2, double r1, double r2, double wc1,
                                 double wc2, double w, double *best, double *bw)
{
    const double u1 = y1 + r1, u2 = y2 + r2;
    const double e1 = tof_floor_i32(u1 + 0.5) - u1, e2 = tof_floor_i32(u2 + 0.5) - u2;
    double cost = 0;
    cost += wc1 * (e1 * e1);
    cost += wc2 * (e2 * e2);
    /* the first minimum wins a tie; bw moves by an exact integer step (a select here would
       keep GCC from if-converting the four candidates into one vector loop) */
    const double better = cost < *best ? 1.0 : 0.0;
    *best = cost < *best ? cost : *best;
    *bw += better * (w - *bw);
}

/* One row of averaged phasors with three frequencies and four wrap counts of the base one
   (the ISP's default frequency set and range, p->int_floor): tof_unwrap_site_block's
   operations on the same values in the same order, each site's values in registers instead
   of the block's scratch rows and every candidate unrolled, so the results are the same bit
   for bit. The planes of x and q are ldi apart, those of phase and amp ldo apart. Returns 1
   if an I or Q was not finite (that site reported as tof_unwrap_checked does). */
RGBZ_CLONES_512 static int tof_unwrap_row_f3w4(const tof_plan *p, const double *x,
                                               const double *q, ptrdiff_t ldi, ptrdiff_t n,
                                               ptrdiff_t ldo, double *restrict depth,
                                               double *restrict residual,
                                               int32_t *restrict wraps,
                                               double *restrict phase, double *restrict amp)
{
    const int b = p->base, i1 = p->other[0], i2 = p->other[1];
    const double *xb = x + b * ldi, *qb = q + b * ldi, *x1 = x + i1 * ldi, *q1 = q + i1 * ldi,
                 *x2 = x + i2 * ldi, *q2 = q + i2 * ldi;
    double *restrict pb = phase + b * ldo, *restrict p1 = phase + i1 * ldo,
           *restrict p2 = phase + i2 * ldo, *restrict ab = amp + b * ldo,
           *restrict a1 = amp + i1 * ldo, *restrict a2 = amp + i2 * ldo;
    const double sb = p->scale[b], s1 = p->scale[i1], s2 = p->scale[i2];
    const double ia1 = p->inv_amb[i1], ia2 = p->inv_amb[i2];
    const double r1 = p->ratio[i1], r2 = p->ratio[i2], wc1 = p->wcost[i1], wc2 = p->wcost[i2];
    /* the candidates' offsets w r_i, as tof_unwrap_block_impl computes them */
    const double r1w[4] = {0 * r1, 1 * r1, 2 * r1, 3 * r1};
    const double r2w[4] = {0 * r2, 1 * r2, 2 * r2, 3 * r2};
    const double wb = p->w[b], w1 = p->w[i1], w2 = p->w[i2], amb = p->amb[b];
    const double am1 = p->amb[i1], am2 = p->amb[i2], ws = p->wsum;
    int bad = 0;
    for (ptrdiff_t k = 0; k < n; k++) {
        const double Ib = xb[k], Qb = qb[k], I1 = x1[k], Q1 = q1[k], I2 = x2[k], Q2 = q2[k];
        const int inb = (fabs(Ib) <= DBL_MAX) & (fabs(Qb) <= DBL_MAX);   /* not NaN */
        const int in1 = (fabs(I1) <= DBL_MAX) & (fabs(Q1) <= DBL_MAX);
        const int in2 = (fabs(I2) <= DBL_MAX) & (fabs(Q2) <= DBL_MAX);
        const double tb = tof_phase(Ib, Qb), t1 = tof_phase(I1, Q1), t2 = tof_phase(I2, Q2);
        const double phb = inb ? tb : 0.0, ph1 = in1 ? t1 : 0.0, ph2 = in2 ? t2 : 0.0;
        pb[k] = phb;
        p1[k] = ph1;
        p2[k] = ph2;
        ab[k] = tof_amplitude(Ib, Qb);
        a1[k] = tof_amplitude(I1, Q1);
        a2[k] = tof_amplitude(I2, Q2);
        const double db = phb * sb, d1 = ph1 * s1, d2 = ph2 * s2;
        const double y1 = (db - d1) * ia1, y2 = (db - d2) * ia2;
        double best = INFINITY, bw = 0;
        tof_candidate(y1, y2, r1w[0], r2w[0], wc1, wc2, 0.0, &best, &bw);
        tof_candidate(y1, y2, r1w[1], r2w[1], wc1, wc2, 1.0, &best, &bw);
        tof_candidate(y1, y2, r1w[2], r2w[2], wc1, wc2, 2.0, &best, &bw);
        tof_candidate(y1, y2, r1w[3], r2w[3], wc1, wc2, 3.0, &best, &bw);
        double num = wb * (db + bw * amb);
        const double k1 = tof_floor_i32(y1 + bw * r1 + 0.5), k2 = tof_floor_i32(y2 + bw * r2 + 0.5);
        num += w1 * (d1 + k1 * am1);
        num += w2 * (d2 + k2 * am2);
        const int ok = inb & in1 & in2;
        bad |= !ok;
        const double dk = num / ws, rk = sqrt(best / ws);
        const int32_t wk = (int32_t)bw;
        depth[k] = ok ? dk : NAN;
        residual[k] = ok ? rk : NAN;
        wraps[k] = ok ? wk : -1;
    }
    return bad;
}

/* rgbz_tof_depth_iq on one thread for phasor planes ldi apart (see tof.h) */
int rgbz_tof_depth_iq_row(const double *i_comp, const double *q_comp, ptrdiff_t F,
                          ptrdiff_t N, ptrdiff_t ldi, ptrdiff_t ldo, const double *freqs,
                          const double *weights, double max_range, double *depth,
                          double *residual, int32_t *wraps, double *phase, double *amp)
{
    tof_plan plan;
    if (!i_comp || !q_comp || !depth || !residual || !wraps || !phase || !amp || N < 0
        || ldi < N || ldo < N)
        return RGBZ_EINVAL;
    int st = tof_plan_init(&plan, F, freqs, weights, max_range);
    if (st != RGBZ_OK) return st;
    if (plan.F == 3 && plan.nwrap == 4 && plan.int_floor)
        return tof_unwrap_row_f3w4(&plan, i_comp, q_comp, ldi, N, ldo, depth, residual, wraps,
                                   phase, amp) ? RGBZ_EDOMAIN : RGBZ_OK;
    int bad = 0;
    for (ptrdiff_t blk = 0; blk < TOF_NBLOCKS(N); blk++) {
        const ptrdiff_t n0 = blk * TOF_BLOCK, nb = N - n0 < TOF_BLOCK ? N - n0 : TOF_BLOCK;
        bad |= tof_unwrap_site_block(&plan, i_comp, q_comp, ldi, ldo, n0, nb, depth, residual,
                                     wraps, phase, amp);
    }
    return bad ? RGBZ_EDOMAIN : RGBZ_OK;
}

/* the block [n0, n0 + nb) of rgbz_tof_phase_iq; 1 if an I or Q was not finite */
RGBZ_CLONES_512 static int tof_phase_block(const double *i_comp, const double *q_comp,
                                           ptrdiff_t F, ptrdiff_t N, ptrdiff_t n0, ptrdiff_t nb,
                                           double *phase, double *amp)
{
    int ok[TOF_BLOCK], bad = 0;
    for (ptrdiff_t k = 0; k < nb; k++) ok[k] = 1;
    for (ptrdiff_t f = 0; f < F; f++) {
        const ptrdiff_t o = f * N + n0;
        tof_from_iq(i_comp + o, q_comp + o, nb, ok, 0.0, phase + o, NULL, amp + o);
    }
    for (ptrdiff_t k = 0; k < nb; k++) bad |= !ok[k];
    return bad;
}

/* Phase and amplitude of phasors (I, Q), each (F, N), without unwrapping: the first half of
   rgbz_tof_depth_iq, bit for bit (the same tof_from_iq). A non-finite I or Q gives the phase
   0 and RGBZ_EDOMAIN. */
int rgbz_tof_phase_iq(const double *i_comp, const double *q_comp, ptrdiff_t F, ptrdiff_t N,
                      double *phase, double *amp, int workers)
{
    if (!i_comp || !q_comp || !phase || !amp || F < 1 || N < 0) return RGBZ_EINVAL;
    int bad = 0;
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR_OR(bad)
    for (ptrdiff_t blk = 0; blk < TOF_NBLOCKS(N); blk++) {
        const ptrdiff_t n0 = blk * TOF_BLOCK, nb = N - n0 < TOF_BLOCK ? N - n0 : TOF_BLOCK;
        bad |= tof_phase_block(i_comp, q_comp, F, N, n0, nb, phase, amp);
    }
    return bad ? RGBZ_EDOMAIN : RGBZ_OK;
}
