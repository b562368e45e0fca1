/*
 * tof_guided.c -- the colour-guided ToF ISP (rgbz_fast.tof with guide=) and the guided
 * upsampling of its depth (rgbz_fast.tof.upsample_depth). Declared in tof_guided.h.
 *
 * The chain, one entry point per stage (the Python layer allocates and calls them):
 *   rgbz_tofg_prepare     taps -> phasors (float) and the noise variance of each measurement
 *   rgbz_tofg_colour      the guide image at the measurements, and its noise (Immerkaer)
 *   rgbz_tofg_pass        one 1-D pass of the cross-bilateral mean (rows or columns); two
 *                         rounds of a row pass then a column pass make the 2-D mean
 *   (rgbz_tof_depth_iq)   atan2, amplitude, unwrapping (tof.c)
 *   rgbz_tofg_validity    snr, sigma, implied reflectance and the validity bits
 *   rgbz_tofg_flying      the flying-pixel test with colour edges
 *   rgbz_tofg_agree       the low-signal measurements a usable neighbour confirms (upsample)
 *   rgbz_tofg_upsample    a depth at every pixel of the guide
 *
 * Why a row pass then a column pass: the column pass averages row-pass outputs of
 * different grid rows, which share no measurement, so the variance of the 2-D mean is
 * exactly sum w^2 var / (sum w)^2 of the column pass over the row-pass variances (for
 * given weights), at 2L instead of L^2 neighbours per measurement for an L x L window.
 * The NumPy reference of every stage is tests/_reference/tof.py; the filter computes in
 * float (its sums hold at most a few hundred terms of one sign), the rest in double.
 */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math", "tree-loop-vectorize", "vect-cost-model=dynamic")
#endif
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "rgbz.h"
#include "rgbz_ops.h"
#include "tof_filter.h"
#include "tof_guided.h"

#define TOFG_PI 3.141592653589793
/* a weight exp(-x) with x above this is 0: e^-36 = 2.3e-16 cannot change a mean */
#define TOFG_CUT 36.0f

/* exp(-x) for x in [0, TOFG_CUT] in float, branch-free so that the weight loops vectorise:
   2^(-x log2 e) = 2^-n 2^-f with n the nearest integer and f in [-0.5, 0.5], 2^-f by its
   Taylor polynomial of degree 6 in f ln 2 (relative error below 3e-7), 2^-n by the exponent
   bits. x >= TOFG_CUT gives 0. */
RGBZ_INLINE float tofg_exp_neg(float x)
{
    const float xc = x < TOFG_CUT ? x : TOFG_CUT;
    const float y = xc * 1.44269504f;                          /* in [0, 52] */
    const float n = (y + 12582912.0f) - 12582912.0f;            /* round to nearest */
    const float t = (y - n) * 0.693147181f;
    const float p = 1.0f - t * (1.0f - t * (0.5f - t * (1.0f / 6 - t * (1.0f / 24
                    - t * (1.0f / 120 - t * (1.0f / 720))))));
    const int32_t bits = (127 - (int32_t)n) << 23;
    float scale;
    memcpy(&scale, &bits, sizeof scale);
    const float r = p * scale;
    return x < TOFG_CUT ? r : 0.0f;
}

/* ------------------------------------------------------------------ the guide's colours */
/* |L * plane| at the columns [x0, x1) of row r (interior) into l[0 .. x1 - x0), in double:
   a loop that vectorises */
RGBZ_CLONES_512 static void tofg_lap_row(const float *restrict p, ptrdiff_t r, ptrdiff_t C,
                                         ptrdiff_t x0, ptrdiff_t x1, double *restrict l)
{
    const float *a = p + (r - 1) * C, *b = p + r * C, *c = p + (r + 1) * C;
    for (ptrdiff_t x = x0; x < x1; x++) {
        const double v = (double)a[x - 1] - 2.0 * a[x] + a[x + 1]
                         - 2.0 * b[x - 1] + 4.0 * b[x] - 2.0 * b[x + 1]
                         + (double)c[x - 1] - 2.0 * c[x] + c[x + 1];
        l[x - x0] = fabs(v);
    }
}

/* the interior rows [r0, r0 + nr) (nr <= TOFG_LAPR) of a plane: each row's sum of
   |L * plane| over its interior columns, its terms in column order, into rs; the rows' sums
   advance together (independent chains of additions, where one row's chain waits on the
   latency of every addition) */
#define TOFG_LAPR 8
RGBZ_CLONES_512 static void tofg_lap_rows(const float *p, ptrdiff_t r0, int nr, ptrdiff_t C,
                                          double *rs)
{
    double l[TOFG_LAPR][256], acc[TOFG_LAPR];
    for (int k = 0; k < TOFG_LAPR; k++) acc[k] = 0.0;
    for (int k = nr; k < TOFG_LAPR; k++)
        for (int x = 0; x < 256; x++) l[k][x] = 0.0;
    for (ptrdiff_t x0 = 1; x0 < C - 1; x0 += 256) {
        const ptrdiff_t x1 = C - 1 - x0 < 256 ? C - 1 : x0 + 256;
        for (int k = 0; k < nr; k++) tofg_lap_row(p, r0 + k, C, x0, x1, l[k]);
        for (ptrdiff_t x = 0; x < x1 - x0; x++)
            for (int k = 0; k < TOFG_LAPR; k++) acc[k] += l[k][x];
    }
    for (int k = 0; k < nr; k++) rs[k] = acc[k];
}

/* sum over the interior of |L * plane| for L = [1 -2 1; -2 4 -2; 1 -2 1] (Immerkaer 1996),
   per plane of col (3, R, C), in double: each row's terms in column order, then the rows of
   each of nth consecutive shares (the shares of a static OpenMP schedule of the rows over
   nth threads) in row order, then the shares' sums in order onto 0 */
static void tofg_laplacian(const float *col, ptrdiff_t R, ptrdiff_t C, double *lap, int workers)
{
    const ptrdiff_t N = R * C, n = R - 2 > 0 ? R - 2 : 0;
    const int nth = rgbz_threads(workers);
    /* the rows' sums into a buffer on the threads; without memory for it, each row's sum
       where the order below needs it, on this thread */
    double *rs = malloc((size_t)(3 * n > 0 ? 3 * n : 1) * sizeof *rs);
    if (rs) {
        const ptrdiff_t ng = (n + TOFG_LAPR - 1) / TOFG_LAPR;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nth)
#endif
        for (ptrdiff_t g = 0; g < 3 * ng; g++) {
            const int ch = (int)(g / ng);
            const ptrdiff_t r = (g % ng) * TOFG_LAPR;
            const int nr = n - r < TOFG_LAPR ? (int)(n - r) : TOFG_LAPR;
            tofg_lap_rows(col + ch * N, r + 1, nr, C, rs + ch * n + r);
        }
    }
    for (int ch = 0; ch < 3; ch++) {
        double total = 0.0;
        for (ptrdiff_t i = 0; i < nth; i++) {
            const ptrdiff_t q = n / nth, rem = n % nth;
            const ptrdiff_t a = i * q + (i < rem ? i : rem), b = a + q + (i < rem);
            double part = 0.0;
            for (ptrdiff_t r = a; r < b; r++) {
                double one;
                if (rs)
                    one = rs[ch * n + r];
                else
                    tofg_lap_rows(col + ch * N, r + 1, 1, C, &one);
                part += one;
            }
            total += part;
        }
        lap[ch] = total;
    }
    free(rs);
}

/* The guide's noise sigma (3,) from lap (Immerkaer: sqrt(pi / 2) / (6 (R - 2)(C - 2)) lap,
   at least floor; floor without an interior) and col (3, N), cells (block^2, 3, N; NULL: none)
   multiplied by the float (float)(1 / (sqrt(2) sigma)) of their channel */
static void tofg_colour_scale(ptrdiff_t R, ptrdiff_t C, int block, const double *lap,
                              double floor, double *sigma, float *col, float *cells,
                              int workers)
{
    const ptrdiff_t N = R * C;
    const double interior = (double)(R - 2 > 0 ? R - 2 : 0) * (double)(C - 2 > 0 ? C - 2 : 0);
    float inv[3];
    for (int ch = 0; ch < 3; ch++) {
        const double s = interior > 0.0 ? sqrt(TOFG_PI / 2.0) / (6.0 * interior) * lap[ch]
                                        : 0.0;
        sigma[ch] = s != s ? s : s > floor ? s : floor;     /* NaN stays NaN */
        inv[ch] = (float)(1.0 / (sqrt(2.0) * sigma[ch]));
    }
    const ptrdiff_t planes = cells ? 3 + (ptrdiff_t)block * block * 3 : 3, piece = 1 << 16;
    const ptrdiff_t np = (N + piece - 1) / piece;
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t k = 0; k < planes * np; k++) {
        const ptrdiff_t pl = k / np, n0 = (k % np) * piece;
        const ptrdiff_t n1 = N - n0 < piece ? N : n0 + piece;
        float *restrict a = pl < 3 ? col + pl * N : cells + (pl - 3) * N;
        const float f = inv[pl % 3];
        for (ptrdiff_t n = n0; n < n1; n++) a[n] *= f;
    }
}

/* ------------------------------------------------------------------ the 1-D passes */
typedef struct {
    const float *zr, *zi, *v, *nin, *gr, *gi, *gv, *col;
    const uint8_t *use;
    ptrdiff_t F, R, C;
    int axis;
    const int64_t *px;
    ptrdiff_t reach;
    int64_t radius_px;
    float inv2h2, inv2hc2;
    float *or_, *oi, *ov, *on;
    double *or64, *oi64;
    /* plane strides of the data zr, zi, of the guide gr, gi, of col and of the outputs, and
       the offset of a measurement's output (out[m - ooff]): a pass may run on rows of a grid
       held in a strip buffer (every other plane is indexed by the measurement m) */
    ptrdiff_t zs, gs, cs, os, ooff;
    /* per measurement, for the blocks of pair weights: gate 1 where it may enter as a
       neighbour (use, and n_eff > 0 in a second pass), else 0; rn the reciprocal of its
       n_eff (1 in a first pass, and where n_eff <= 0) */
    const float *gate, *rn;
    /* 1: col holds a fourth plane, each guide variance's fixed-pattern share phi, and the
       phasor term is the pair's Mahalanobis distance (tofg_xp); 0: chi over the variances */
    int fp;
} tofg_pass_args;

/* The phasor term of a pair's weight, symmetric in the two measurements: chi / (gn + gm) -
   2F, chi the summed squared differences of the guide phasors over the F frequencies and gn,
   gm the two guide variances (per component). With fp, their fixed-pattern shares fn, fm:
   a tap's DSNU offset and PRNU gain are the same in every frequency's frame, so a
   measurement's errors of I (and of Q) share a part that is one value in every frequency
   (the taps' offsets barely change with the frequency); the pair's covariance per component
   block is S I + A 1 1^T, S = gn + gm - A the temporal part, A = gn fn + gm fm the fixed one,
   and the Mahalanobis distance (Sherman-Morrison) is (chi - A q / D) / S, D = S + F A, q =
   (sum_f dre)^2 + (sum_f dim)^2: differences the fixed pattern explains, one offset in every
   frequency, weigh less, and the mean no longer prefers the neighbours whose fixed pattern
   resembles the centre's (docs/reports/isp.md, bright near walls). Its expectation is 2F as
   chi's. */
RGBZ_INLINE float tofg_xp(float chi, float sr, float si, float gn, float gm, float fn,
                          float fm, float nf, float bias, const int FP)
{
    if (!FP) return chi / (gn + gm) - bias;
    const float A = gn * fn + gm * fm, S = (gn + gm) - A;
    const float D = S + nf * A, q = sr * sr + si * si;
    /* two divisions, not (chi D - q A) / (S D): that squares the variances' scale, and
       float32 overflowed from variances of about 1e18 (a review's measurement) */
    return (chi - q * (A / D)) / S - bias;
}

/* the weights of one offset over the cells [c0, c1) of a row: w (0 or 1 on entry) times
   exp(-(max(chi_p - 2F, 0) / (2 h^2) + max(chi_c - 3, 0) / (2 h_c^2))), chi_p from the
   summed squared guide differences in chi (divided here by the two variances) */
RGBZ_INLINE void tofg_weights(const tofg_pass_args *p, ptrdiff_t nbase, ptrdiff_t row0,
                                     ptrdiff_t c0, ptrdiff_t c1, float bias,
                                     const float *restrict chi, const float *restrict sr,
                                     const float *restrict si, float *restrict w)
{
    const ptrdiff_t N = p->cs;
    const float *gvn = p->gv + nbase, *gvm = p->gv + row0;
    const float *a0 = p->col + nbase, *a1 = a0 + N, *a2 = a1 + N;
    const float *b0 = p->col + row0, *b1 = b0 + N, *b2 = b1 + N;
    const float *fn = a2 + N, *fm = b2 + N;
    const float ih = p->inv2h2, ic = p->inv2hc2, nf = (float)p->F;
    for (ptrdiff_t c = c0; c < c1; c++) {
        const float xp = p->fp ? tofg_xp(chi[c], sr[c], si[c], gvn[c], gvm[c], fn[c], fm[c],
                                         nf, bias, 1)
                               : tofg_xp(chi[c], 0.0f, 0.0f, gvn[c], gvm[c], 0.0f, 0.0f, nf,
                                         bias, 0);
        const float d0 = a0[c] - b0[c], d1 = a1[c] - b1[c], d2 = a2[c] - b2[c];
        const float xc = (d0 * d0 + d1 * d1) + d2 * d2 - 3.0f;
        const float x = (xp > 0.0f ? xp : 0.0f) * ih + (xc > 0.0f ? xc : 0.0f) * ic;
        w[c] *= tofg_exp_neg(x);
    }
}

/* the output columns [clo, chi_) of row r, any layout; scratch: num_re, num_im (F C each),
   den, w2v, w2n, chi, w, sr, si (C each) */
RGBZ_CLONES_512 static void tofg_pass_row(const tofg_pass_args *p, ptrdiff_t r, float *scratch,
                                      ptrdiff_t clo, ptrdiff_t chi_)
{
    const ptrdiff_t F = p->F, C = p->C, ZS = p->zs, GS = p->gs, OS = p->os;
    const float bias = 2.0f * (float)F;
    float *num_re = scratch, *num_im = num_re + F * C, *den = num_im + F * C;
    float *w2v = den + C, *w2n = w2v + C, *chi = w2n + C, *w = chi + C;
    float *sr = w + C, *si = sr + C;
    for (ptrdiff_t f = 0; f < F; f++)
        for (ptrdiff_t c = clo; c < chi_; c++) num_re[f * C + c] = num_im[f * C + c] = 0.0f;
    for (ptrdiff_t c = clo; c < chi_; c++) den[c] = w2v[c] = w2n[c] = 0.0f;
    const ptrdiff_t row0 = r * C;
    for (ptrdiff_t a = -p->reach; a <= p->reach; a++) {
        ptrdiff_t c0, c1, shift;
        if (p->axis == 0) {                              /* along a column: rows r + a */
            const ptrdiff_t rr = r + a;
            if (rr < 0 || rr >= p->R) continue;
            const int64_t d = p->px[rr] - p->px[r];
            if (d < -p->radius_px || d > p->radius_px) continue;
            c0 = 0;
            c1 = C;
            shift = a * C;
        } else {                                         /* along the row: columns c + a */
            c0 = a < 0 ? -a : 0;
            c1 = a > 0 ? C - a : C;
            shift = a;
        }
        c0 = c0 > clo ? c0 : clo;
        c1 = c1 < chi_ ? c1 : chi_;
        if (c1 <= c0) continue;
        const ptrdiff_t nbase = row0 + shift;
        for (ptrdiff_t c = c0; c < c1; c++) chi[c] = sr[c] = si[c] = 0.0f;
        for (ptrdiff_t f = 0; f < F; f++) {
            const float *gr = p->gr + f * GS, *gi = p->gi + f * GS;
            for (ptrdiff_t c = c0; c < c1; c++) {
                const float dre = gr[nbase + c] - gr[row0 + c];
                const float dim = gi[nbase + c] - gi[row0 + c];
                chi[c] += dre * dre + dim * dim;
                sr[c] += dre;
                si[c] += dim;
            }
        }
        /* w = 1 for a neighbour that may enter, 0 otherwise; then times its weight */
        const uint8_t *use = p->use + nbase;
        for (ptrdiff_t c = c0; c < c1; c++) w[c] = (float)(use[c] != 0);
        if (p->axis == 1) {
            const int64_t *px = p->px, rad = p->radius_px;
            for (ptrdiff_t c = c0; c < c1; c++) {
                const int64_t d = px[c + shift] - px[c];
                w[c] = (d >= -rad && d <= rad) ? w[c] : 0.0f;
            }
        }
        if (p->nin) {
            const float *nn = p->nin + nbase;
            for (ptrdiff_t c = c0; c < c1; c++) w[c] = nn[c] > 0.0f ? w[c] : 0.0f;
        }
        tofg_weights(p, nbase, row0, c0, c1, bias, chi, sr, si, w);
        for (ptrdiff_t f = 0; f < F; f++) {
            const float *zr = p->zr + f * ZS + nbase, *zi = p->zi + f * ZS + nbase;
            float *nr = num_re + f * C, *ni = num_im + f * C;
            for (ptrdiff_t c = c0; c < c1; c++) {
                nr[c] += w[c] * zr[c];
                ni[c] += w[c] * zi[c];
            }
        }
        const float *vv = p->v + nbase;
        if (p->nin) {
            const float *nn = p->nin + nbase;
            for (ptrdiff_t c = c0; c < c1; c++) {
                const float ww = w[c] * w[c];
                den[c] += w[c];
                w2v[c] += ww * vv[c];
                /* times the reciprocal, as the fast blocks (w = 0 where nn = 0) */
                w2n[c] += ww * (1.0f / (nn[c] > 0.0f ? nn[c] : 1.0f));
            }
        } else {
            for (ptrdiff_t c = c0; c < c1; c++) {
                const float ww = w[c] * w[c];
                den[c] += w[c];
                w2v[c] += ww * vv[c];
                w2n[c] += ww;
            }
        }
    }
    for (ptrdiff_t c = clo; c < chi_; c++) {
        const ptrdiff_t m = row0 + c - p->ooff;
        const int ok = den[c] > 0.0f;
        const float inv = ok ? 1.0f / den[c] : 0.0f;
        for (ptrdiff_t f = 0; f < F; f++) {
            const float mr = num_re[f * C + c] * inv, mi = num_im[f * C + c] * inv;
            if (p->or64) {
                p->or64[f * OS + m] = mr;
                p->oi64[f * OS + m] = mi;
            } else {
                p->or_[f * OS + m] = mr;
                p->oi[f * OS + m] = mi;
            }
        }
        p->ov[m] = ok ? w2v[c] * (inv * inv) : HUGE_VALF;
        if (p->nin)
            p->on[m] = ok && w2n[c] > 0.0f ? 1.0f / (w2n[c] * (inv * inv)) : 0.0f;
        else
            p->on[m] = ok && w2n[c] > 0.0f ? den[c] * den[c] / w2n[c] : 0.0f;
    }
}


#define TOFG_BW 16
#define TOFG_UNROLL _Pragma("GCC unroll 4")

/* blocks whose sums one call of tofg_store_span turns into outputs */
#define TOFG_CHUNK 32
#define TOFG_SPAN (TOFG_CHUNK * TOFG_BW)

/* The sums of one block into the span buffer s (planes of TOFG_SPAN floats, the block's
   lanes from column j0): the phasors nr, ni (F planes each), then den, w2v, w2n. */
RGBZ_INLINE void tofg_sums_out(float *restrict s, ptrdiff_t j0, float nr[][TOFG_BW],
                               float ni[][TOFG_BW], const float *den, const float *w2v,
                               const float *w2n, const int NF)
{
    TOFG_UNROLL
    for (int f = 0; f < NF; f++) {
        for (int j = 0; j < TOFG_BW; j++) s[f * TOFG_SPAN + j0 + j] = nr[f][j];
        for (int j = 0; j < TOFG_BW; j++) s[(NF + f) * TOFG_SPAN + j0 + j] = ni[f][j];
    }
    for (int j = 0; j < TOFG_BW; j++) s[2 * NF * TOFG_SPAN + j0 + j] = den[j];
    for (int j = 0; j < TOFG_BW; j++) s[(2 * NF + 1) * TOFG_SPAN + j0 + j] = w2v[j];
    for (int j = 0; j < TOFG_BW; j++) s[(2 * NF + 2) * TOFG_SPAN + j0 + j] = w2n[j];
}

/* The outputs of n <= TOFG_SPAN measurements from m0 from their sums in s (tofg_sums_out):
   the weighted mean phasors, the variance of the mean (HUGE_VALF without weight) and the
   output noise; loops over the span that vectorise, the same operations per measurement as
   the generic row's */
RGBZ_INLINE void tofg_store_span(const tofg_pass_args *p, ptrdiff_t m0, ptrdiff_t n,
                                 const float *restrict s, const int NF)
{
    const ptrdiff_t OS = p->os, mb = m0 - p->ooff;
    const float *restrict den = s + 2 * NF * TOFG_SPAN, *restrict w2v = den + TOFG_SPAN;
    const float *restrict w2n = w2v + TOFG_SPAN;
    float inv[TOFG_SPAN];
    for (ptrdiff_t j = 0; j < n; j++) {
        const int ok = den[j] > 0.0f;
        inv[j] = ok ? 1.0f / den[j] : 0.0f;
    }
    TOFG_UNROLL
    for (int f = 0; f < NF; f++) {
        const float *restrict sr = s + f * TOFG_SPAN, *restrict si = s + (NF + f) * TOFG_SPAN;
        if (p->or64) {
            double *restrict o_r = p->or64 + f * OS + mb, *restrict o_i = p->oi64 + f * OS + mb;
            for (ptrdiff_t j = 0; j < n; j++) {
                o_r[j] = sr[j] * inv[j];
                o_i[j] = si[j] * inv[j];
            }
        } else {
            float *restrict o_r = p->or_ + f * OS + mb, *restrict o_i = p->oi + f * OS + mb;
            for (ptrdiff_t j = 0; j < n; j++) {
                o_r[j] = sr[j] * inv[j];
                o_i[j] = si[j] * inv[j];
            }
        }
    }
    float *restrict ov = p->ov + mb, *restrict on = p->on + mb;
    for (ptrdiff_t j = 0; j < n; j++)
        ov[j] = den[j] > 0.0f ? w2v[j] * (inv[j] * inv[j]) : HUGE_VALF;
    if (p->nin) {
        for (ptrdiff_t j = 0; j < n; j++)
            on[j] = den[j] > 0.0f && w2n[j] > 0.0f ? 1.0f / (w2n[j] * (inv[j] * inv[j]))
                                                    : 0.0f;
    } else {
        for (ptrdiff_t j = 0; j < n; j++)
            on[j] = den[j] > 0.0f && w2n[j] > 0.0f ? den[j] * den[j] / w2n[j] : 0.0f;
    }
}


/* The same mean for 16 output columns at once, the frequency count a compile-time constant:
   the sums stay in registers over the taps (shift[t]: the offset of tap t in the planes;
   every neighbour is on the grid and within the radius), the order of every sum the
   generic row's (offsets in increasing order, frequencies in order). ew: the weight of tap t
   for the output m0 + j at ew[t][j] (tofg_pairs), or NULL: computed here. */
RGBZ_INLINE void tofg_block(
    const tofg_pass_args *p, ptrdiff_t m0, const ptrdiff_t *shift, const float *const *ew,
    int ntaps, float *sums, ptrdiff_t j0, const int NF)
{
    const ptrdiff_t ZS = p->zs, GS = p->gs, N = p->cs;
    const float bias = 2.0f * NF, ih = p->inv2h2, ic = p->inv2hc2;
    float gr0[4][TOFG_BW], gi0[4][TOFG_BW], gv0[TOFG_BW], k0[TOFG_BW], k1[TOFG_BW],
          k2[TOFG_BW];
    float nr[4][TOFG_BW], ni[4][TOFG_BW], den[TOFG_BW], w2v[TOFG_BW], w2n[TOFG_BW];
    for (int j = 0; j < TOFG_BW; j++) {
        TOFG_UNROLL
        for (int f = 0; f < NF; f++) {
            gr0[f][j] = p->gr[f * GS + m0 + j];
            gi0[f][j] = p->gi[f * GS + m0 + j];
            nr[f][j] = ni[f][j] = 0.0f;
        }
        gv0[j] = p->gv[m0 + j];
        k0[j] = p->col[m0 + j];
        k1[j] = p->col[N + m0 + j];
        k2[j] = p->col[2 * N + m0 + j];
        den[j] = w2v[j] = w2n[j] = 0.0f;
    }
    for (int t = 0; t < ntaps; t++) {
        const ptrdiff_t n0 = m0 + shift[t];
        float w[TOFG_BW], rn[TOFG_BW];
        /* w: 1 for a neighbour that may enter; rn: the reciprocal of its n_eff (1 in a first
           pass) */
        for (int j = 0; j < TOFG_BW; j++) {
            w[j] = (float)(p->use[n0 + j] != 0);
            rn[j] = 1.0f;
        }
        if (p->nin)
            for (int j = 0; j < TOFG_BW; j++) {
                const float nn = p->nin[n0 + j];
                w[j] = nn > 0.0f ? w[j] : 0.0f;
                rn[j] = 1.0f / (nn > 0.0f ? nn : 1.0f);
            }
        if (ew) {
            const float *e = ew[t];
            for (int j = 0; j < TOFG_BW; j++) w[j] *= e[j];
        } else {
            for (int j = 0; j < TOFG_BW; j++) {
                float chi = 0.0f, sr = 0.0f, si = 0.0f;
                TOFG_UNROLL
                for (int f = 0; f < NF; f++) {
                    const float dre = p->gr[f * GS + n0 + j] - gr0[f][j];
                    const float dim = p->gi[f * GS + n0 + j] - gi0[f][j];
                    chi += dre * dre + dim * dim;
                    sr += dre;
                    si += dim;
                }
                const float xp = p->fp
                    ? tofg_xp(chi, sr, si, p->gv[n0 + j], gv0[j], p->col[3 * N + n0 + j],
                              p->col[3 * N + m0 + j], (float)NF, bias, 1)
                    : tofg_xp(chi, 0.0f, 0.0f, p->gv[n0 + j], gv0[j], 0.0f, 0.0f, (float)NF,
                              bias, 0);
                const float d0 = p->col[n0 + j] - k0[j], d1 = p->col[N + n0 + j] - k1[j];
                const float d2 = p->col[2 * N + n0 + j] - k2[j];
                const float xc = (d0 * d0 + d1 * d1) + d2 * d2 - 3.0f;
                const float x = (xp > 0.0f ? xp : 0.0f) * ih + (xc > 0.0f ? xc : 0.0f) * ic;
                w[j] *= tofg_exp_neg(x);
            }
        }
        for (int j = 0; j < TOFG_BW; j++) {
            TOFG_UNROLL
            for (int f = 0; f < NF; f++) {
                nr[f][j] += w[j] * p->zr[f * ZS + n0 + j];
                ni[f][j] += w[j] * p->zi[f * ZS + n0 + j];
            }
            const float ww = w[j] * w[j];
            den[j] += w[j];
            w2v[j] += ww * p->v[n0 + j];
            w2n[j] += ww * rn[j];
        }
    }
    tofg_sums_out(sums, j0, nr, ni, den, w2v, w2n, NF);
}


/* tofg_block on the weights of the pairs (ew[t][j] for the output m0 + j and tap t) and
   the gates of p->gate, p->rn: the same sums in the same order, every lane's work the same
   so that the loops vectorise */
RGBZ_INLINE void tofg_block_e(
    const tofg_pass_args *p, ptrdiff_t m0, const ptrdiff_t *shift, const float *const *ew,
    int ntaps, float *sums, ptrdiff_t j0, const int NF)
{
    const ptrdiff_t ZS = p->zs;
    float nr[4][TOFG_BW], ni[4][TOFG_BW], den[TOFG_BW], w2v[TOFG_BW], w2n[TOFG_BW];
    for (int j = 0; j < TOFG_BW; j++) {
        TOFG_UNROLL
        for (int f = 0; f < NF; f++) nr[f][j] = ni[f][j] = 0.0f;
        den[j] = w2v[j] = w2n[j] = 0.0f;
    }
    for (int t = 0; t < ntaps; t++) {
        const ptrdiff_t n0 = m0 + shift[t];
        const float *restrict e = ew[t], *restrict gt = p->gate + n0, *restrict rq = p->rn + n0;
        const float *restrict vv = p->v + n0;
        for (int j = 0; j < TOFG_BW; j++) {
            const float w = gt[j] * e[j];
            TOFG_UNROLL
            for (int f = 0; f < NF; f++) {
                nr[f][j] += w * p->zr[f * ZS + n0 + j];
                ni[f][j] += w * p->zi[f * ZS + n0 + j];
            }
            const float ww = w * w;
            den[j] += w;
            w2v[j] += ww * vv[j];
            w2n[j] += ww * rq[j];
        }
    }
    tofg_sums_out(sums, j0, nr, ni, den, w2v, w2n, NF);
}

/* The weight factor of the pairs (m0 + k, n0 + k), k < cnt, into e[k]: the expression of
   tofg_block's weight, whose every operand is symmetric in the two measurements (squared
   differences, the sum of the two variances), so e(m, n) == e(n, m) bit for bit and each
   pair's exp is taken once for both directions. */
RGBZ_INLINE void tofg_pair(const tofg_pass_args *p, ptrdiff_t m0, ptrdiff_t n0, ptrdiff_t cnt,
                           float *restrict e, const int NF, const int FP)
{
    const ptrdiff_t GS = p->gs, N = p->cs;
    const float bias = 2.0f * NF, ih = p->inv2h2, ic = p->inv2hc2;
    const float *phi = FP ? p->col + 3 * N : p->gv;      /* (not read without FP) */
    for (ptrdiff_t j = 0; j < cnt; j++) {
        float chi = 0.0f, sr = 0.0f, si = 0.0f;
        TOFG_UNROLL
        for (int f = 0; f < NF; f++) {
            const float dre = p->gr[f * GS + n0 + j] - p->gr[f * GS + m0 + j];
            const float dim = p->gi[f * GS + n0 + j] - p->gi[f * GS + m0 + j];
            chi += dre * dre + dim * dim;
            sr += dre;
            si += dim;
        }
        const float xp = tofg_xp(chi, sr, si, p->gv[n0 + j], p->gv[m0 + j],
                                 FP ? phi[n0 + j] : 0.0f, FP ? phi[m0 + j] : 0.0f, (float)NF,
                                 bias, FP);
        const float d0 = p->col[n0 + j] - p->col[m0 + j];
        const float d1 = p->col[N + n0 + j] - p->col[N + m0 + j];
        const float d2 = p->col[2 * N + n0 + j] - p->col[2 * N + m0 + j];
        const float xc = (d0 * d0 + d1 * d1) + d2 * d2 - 3.0f;
        const float x = (xp > 0.0f ? xp : 0.0f) * ih + (xc > 0.0f ? xc : 0.0f) * ic;
        e[j] = tofg_exp_neg(x);
    }
}

RGBZ_CLONES_512 static void tofg_pairs(const tofg_pass_args *p, ptrdiff_t m0, ptrdiff_t n0,
                                       ptrdiff_t cnt, float *e)
{
    if (m0 == n0) {
        /* a measurement with itself: every squared difference is 0 (or NaN, which the
           clamps take to 0), so the exponent is 0 ih + 0 ic for every one */
        const float self = tofg_exp_neg(0.0f * p->inv2h2 + 0.0f * p->inv2hc2);
        for (ptrdiff_t j = 0; j < cnt; j++) e[j] = self;
        return;
    }
    if (p->fp) {
        switch (p->F) {
        case 1: tofg_pair(p, m0, n0, cnt, e, 1, 1); break;
        case 2: tofg_pair(p, m0, n0, cnt, e, 2, 1); break;
        case 3: tofg_pair(p, m0, n0, cnt, e, 3, 1); break;
        default: tofg_pair(p, m0, n0, cnt, e, 4, 1); break;
        }
        return;
    }
    switch (p->F) {
    case 1: tofg_pair(p, m0, n0, cnt, e, 1, 0); break;
    case 2: tofg_pair(p, m0, n0, cnt, e, 2, 0); break;
    case 3: tofg_pair(p, m0, n0, cnt, e, 3, 0); break;
    default: tofg_pair(p, m0, n0, cnt, e, 4, 0); break;
    }
}

/* tofg_store_span for the frame's frequency count */
RGBZ_CLONES_512 static void tofg_store_spans(const tofg_pass_args *p, ptrdiff_t m0,
                                             ptrdiff_t n, const float *s)
{
    switch (p->F) {
    case 1: tofg_store_span(p, m0, n, s, 1); break;
    case 2: tofg_store_span(p, m0, n, s, 2); break;
    case 3: tofg_store_span(p, m0, n, s, 3); break;
    default: tofg_store_span(p, m0, n, s, 4); break;
    }
}

/* the blocks, TOFG_CHUNK at a time: their sums into a buffer, then their outputs */
RGBZ_CLONES_512 static void tofg_blocks(const tofg_pass_args *p, ptrdiff_t m0, ptrdiff_t nblk,
                                        const ptrdiff_t *shift, const float **ew, int ntaps)
{
    float sums[(2 * 4 + 3) * TOFG_SPAN];
    for (ptrdiff_t b0 = 0; b0 < nblk; b0 += TOFG_CHUNK) {
        const ptrdiff_t nb = nblk - b0 < TOFG_CHUNK ? nblk - b0 : TOFG_CHUNK;
        for (ptrdiff_t b = 0; b < nb; b++) {
            const ptrdiff_t m = m0 + (b0 + b) * TOFG_BW, j0 = b * TOFG_BW;
            if (ew && p->gate) {
                switch (p->F) {
                case 1: tofg_block_e(p, m, shift, ew, ntaps, sums, j0, 1); break;
                case 2: tofg_block_e(p, m, shift, ew, ntaps, sums, j0, 2); break;
                case 3: tofg_block_e(p, m, shift, ew, ntaps, sums, j0, 3); break;
                default: tofg_block_e(p, m, shift, ew, ntaps, sums, j0, 4); break;
                }
            } else {
                switch (p->F) {
                case 1: tofg_block(p, m, shift, ew, ntaps, sums, j0, 1); break;
                case 2: tofg_block(p, m, shift, ew, ntaps, sums, j0, 2); break;
                case 3: tofg_block(p, m, shift, ew, ntaps, sums, j0, 3); break;
                default: tofg_block(p, m, shift, ew, ntaps, sums, j0, 4); break;
                }
            }
            if (ew)
                for (int t = 0; t < ntaps; t++) ew[t] += TOFG_BW;
        }
        tofg_store_spans(p, m0 + b0 * TOFG_BW, nb * TOFG_BW, sums);
    }
}

/* Row r: the 16-column blocks whose every tap is on the grid by the fast blocks, the rest by
   the generic row. fast: the grid lines along the axis are `step` pixels apart (and F, reach
   within the blocks' bounds). E: for a row pass, room for (A + 1) C pair weights, A the
   largest tap offset; the pairs' weights are then taken once for both directions (NULL:
   each block computes its own). */
RGBZ_CLONES_512 static void tofg_pass_line(const tofg_pass_args *p, ptrdiff_t r, float *scratch,
                                       int fast, int64_t step, ptrdiff_t clo,
                                       ptrdiff_t chi_, float *E, ptrdiff_t A)
{
    const ptrdiff_t C = p->C;
    ptrdiff_t shift[2 * 64 + 1];
    int ntaps = 0;
    ptrdiff_t lo = clo, hi = chi_;                /* the columns every tap may serve */
    if (fast) {
        for (ptrdiff_t a = -p->reach; a <= p->reach; a++) {
            const int64_t d = (p->axis == 0 ? p->px[r + a < 0 || r + a >= p->R ? r : r + a]
                                             - p->px[r] : (int64_t)a * step);
            if (p->axis == 0 && (r + a < 0 || r + a >= p->R)) continue;
            if (d < -p->radius_px || d > p->radius_px) continue;
            shift[ntaps++] = p->axis == 0 ? a * C : a;
            if (p->axis == 1) {
                lo = -a > lo ? -a : lo;
                hi = C - a < hi ? C - a : hi;
            }
        }
    } else {
        hi = lo;                                  /* no fast block */
    }
    const ptrdiff_t nblk = hi > lo ? (hi - lo) / TOFG_BW : 0;
    const ptrdiff_t fe = lo + nblk * TOFG_BW;
    if (nblk > 0) {
        const float *ew[2 * 64 + 1];
        const int pairs = E && p->axis == 1;
        if (pairs) {
            /* E[a][c] = e(c, c + a) for the columns [lo - a, fe) the blocks reach */
            const ptrdiff_t row0 = r * C;
            for (ptrdiff_t a = 0; a <= A; a++)
                tofg_pairs(p, row0 + lo - a, row0 + lo, fe - lo + a, E + a * C + lo - a);
            for (int t = 0; t < ntaps; t++) {
                const ptrdiff_t a = shift[t];
                ew[t] = a >= 0 ? E + a * C + lo : E + (-a) * C + lo + a;
            }
        }
        tofg_blocks(p, r * C + lo, nblk, shift, pairs ? ew : NULL, ntaps);
    }
    if (nblk == 0) {
        tofg_pass_row(p, r, scratch, clo, chi_);
    } else {
        if (lo > clo) tofg_pass_row(p, r, scratch, clo, lo);
        if (fe < chi_) tofg_pass_row(p, r, scratch, fe, chi_);
    }
}

/* columns per tile of a column pass: the taps' rows of a tile stay in the cache from one
   output row to the next (11 rows x 17 planes x 256 floats = 190 kB) */
#define TOFG_TILE 256

/* A column pass over the columns [c0, c1) (at most TOFG_TILE) of evenly spaced grid rows,
   the output rows [ra, rb) in order: row r's pair weights e(r, r + a), a = 0..A, go to slot
   r mod (A + 1) of ring ((A + 1)^2 TOFG_TILE floats), where the rows below find them as their
   offsets -a (the A rows above ra only fill the ring). */
RGBZ_CLONES_512 static void tofg_pass_tile(const tofg_pass_args *p, float *scratch,
                                           ptrdiff_t c0, ptrdiff_t c1, ptrdiff_t A, float *ring,
                                           ptrdiff_t ra, ptrdiff_t rb)
{
    const ptrdiff_t C = p->C, R = p->R, w = c1 - c0, nblk = w / TOFG_BW;
    const ptrdiff_t fe = c0 + nblk * TOFG_BW, slot = (A + 1) * TOFG_TILE;
    ptrdiff_t shift[2 * 64 + 1];
    const float *ew[2 * 64 + 1];
    for (ptrdiff_t r = ra - A > 0 ? ra - A : 0; r < rb; r++) {
        float *own = ring + (r % (A + 1)) * slot;
        for (ptrdiff_t a = 0; a <= A && r + a < R; a++)
            tofg_pairs(p, r * C + c0, (r + a) * C + c0, w, own + a * TOFG_TILE);
        if (r < ra) continue;
        int ntaps = 0;
        for (ptrdiff_t a = -A; a <= A; a++) {
            if (r + a < 0 || r + a >= R) continue;
            shift[ntaps] = a * C;
            ew[ntaps++] = a >= 0 ? own + a * TOFG_TILE
                                 : ring + ((r + a) % (A + 1)) * slot + (-a) * TOFG_TILE;
        }
        if (nblk > 0) tofg_blocks(p, r * C + c0, nblk, shift, ew, ntaps);
        if (fe < c1) tofg_pass_row(p, r, scratch, nblk > 0 ? fe : c0, c1);
    }
}

/* The shape of a pass along an axis whose grid lines sit at px (nl of them): fast (evenly
   spaced lines `step` apart, and F, reach within the blocks' bounds), the largest tap offset A
   of the fast blocks (|a| <= reach, |a step| <= radius) and the floats of the pair-weight
   buffer of one thread (ebuf: a row pass's (A + 1) C, a tiled column pass's ring). */
typedef struct {
    int fast, tiles;
    int64_t step;
    ptrdiff_t A;
    size_t ebuf;
} tofg_plan;

static tofg_plan tofg_plan_of(const int64_t *px, ptrdiff_t nl, int axis, ptrdiff_t F,
                              ptrdiff_t C, ptrdiff_t reach, int64_t radius_px)
{
    tofg_plan q;
    q.step = nl > 1 ? px[1] - px[0] : 1;
    int uniform = 1;
    for (ptrdiff_t i = 1; i < nl; i++) uniform &= px[i] - px[i - 1] == q.step;
    q.fast = uniform && q.step > 0 && F <= 4 && reach <= 64;
    q.A = q.fast ? (radius_px / q.step < reach ? (ptrdiff_t)(radius_px / q.step) : reach) : 0;
    q.tiles = axis == 0 && C > TOFG_TILE;
    q.ebuf = !q.fast ? 0 : q.tiles ? (size_t)(q.A + 1) * (size_t)(q.A + 1) * TOFG_TILE
           : axis == 1 ? (size_t)(q.A + 1) * (size_t)(C > 0 ? C : 1) : 0;
    return q;
}

/* the gates of the fast blocks for the measurements [n0, n1) (tofg_pass_args) */
static void tofg_gates(const uint8_t *use, const float *nin, ptrdiff_t n0, ptrdiff_t n1,
                       float *gate, float *rn)
{
    for (ptrdiff_t n = n0; n < n1; n++) {
        const float nn = nin ? nin[n] : 1.0f;
        gate[n] = use[n] != 0 && nn > 0.0f ? 1.0f : 0.0f;
        rn[n] = 1.0f / (nn > 0.0f ? nn : 1.0f);
    }
}

/* The output rows [ra, rb) of a pass in one thread: a column pass tile by tile (every tile's
   rows in order), a row pass row by row. scratch: (2F + 7) C floats; E: q->ebuf floats. */
static void tofg_pass_rows(const tofg_pass_args *p, const tofg_plan *q, ptrdiff_t ra,
                           ptrdiff_t rb, float *scratch, float *E)
{
    const ptrdiff_t C = p->C;
    if (q->tiles) {
        for (ptrdiff_t c0 = 0; c0 < C; c0 += TOFG_TILE) {
            const ptrdiff_t c1 = c0 + TOFG_TILE < C ? c0 + TOFG_TILE : C;
            if (q->fast) {
                tofg_pass_tile(p, scratch, c0, c1, q->A, E, ra, rb);
            } else {
                for (ptrdiff_t r = ra; r < rb; r++)
                    tofg_pass_line(p, r, scratch, 0, q->step, c0, c1, NULL, 0);
            }
        }
    } else {
        for (ptrdiff_t r = ra; r < rb; r++)
            tofg_pass_line(p, r, scratch, q->fast, q->step, 0, C, E, q->A);
    }
}

int rgbz_tofg_pass(const float *zr, const float *zi, const float *v, const float *nin,
                   const float *gr, const float *gi, const float *gv, const float *col,
                   const uint8_t *use, ptrdiff_t F, ptrdiff_t R, ptrdiff_t C, int axis,
                   const int64_t *px, ptrdiff_t reach, int64_t radius_px, double inv2h2,
                   double inv2hc2, float *or_, float *oi, double *or64, double *oi64,
                   float *ov, float *on, int fixed, int workers)
{
    if (!zr || !zi || !v || !gr || !gi || !gv || !col || !use || !px || !ov || !on
        || (!or64 && (!or_ || !oi)) || (or64 && !oi64) || F < 1 || F > RGBZ_TOF_MAX_FREQS
        || R < 0 || C < 0 || (axis != 0 && axis != 1) || reach < 0 || radius_px < 0
        || !(inv2h2 >= 0.0) || !(inv2hc2 >= 0.0))
        return RGBZ_EINVAL;
    const size_t per_row = (size_t)(2 * F + 7) * (size_t)(C > 0 ? C : 1);
    int status = RGBZ_OK;
    const tofg_plan q = tofg_plan_of(px, axis == 1 ? C : R, axis, F, C, reach, radius_px);
    const int nth = rgbz_threads(workers);
    (void)nth;
    const ptrdiff_t N = R * C;
    float *gate = q.fast && N > 0 ? malloc((size_t)N * sizeof(float)) : NULL;
    float *rn = q.fast && N > 0 ? malloc((size_t)N * sizeof(float)) : NULL;
    if (!gate || !rn) {                           /* the blocks then compute their own */
        free(gate);
        free(rn);
        gate = rn = NULL;
    } else {
        RGBZ_PARALLEL_FOR
        for (ptrdiff_t r = 0; r < R; r++) tofg_gates(use, nin, r * C, (r + 1) * C, gate, rn);
    }
    const tofg_pass_args p = {zr, zi, v, nin, gr, gi, gv, col, use, F, R, C, axis, px, reach,
                              radius_px, (float)inv2h2, (float)inv2hc2, or_, oi, ov, on,
                              or64, oi64, N, N, N, N, 0, gate, rn, fixed != 0};
#ifdef _OPENMP
#pragma omp parallel num_threads(nth)
#endif
    {
        float *scratch = malloc(per_row * sizeof(float));
        float *E = q.ebuf ? malloc(q.ebuf * sizeof(float)) : NULL;
        if (!scratch || (q.ebuf && !E)) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ENOMEM;
        }
        const int ok = scratch && (!q.ebuf || E);
        if (q.tiles) {
            /* a column pass tile by tile, every tile's rows in order */
            const ptrdiff_t ntile = (C + TOFG_TILE - 1) / TOFG_TILE;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
            for (ptrdiff_t t = 0; t < ntile; t++) {
                const ptrdiff_t c0 = t * TOFG_TILE, c1 = c0 + TOFG_TILE < C ? c0 + TOFG_TILE : C;
                if (!ok) continue;
                if (q.fast) {
                    tofg_pass_tile(&p, scratch, c0, c1, q.A, E, 0, R);
                } else {
                    for (ptrdiff_t r = 0; r < R; r++)
                        tofg_pass_line(&p, r, scratch, 0, q.step, c0, c1, NULL, 0);
                }
            }
        } else {
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
            for (ptrdiff_t r = 0; r < R; r++)
                if (ok) tofg_pass_line(&p, r, scratch, q.fast, q.step, 0, C, E, q.A);
        }
        free(E);
        free(scratch);
    }
    free(gate);
    free(rn);
    return status;
}

/* grid rows of output per strip of the fused denoise when the caller gives none, at most:
   each strip recomputes 2 reach rows of the first row pass and reach rows of the other two
   passes above and below it (at 128 and reach 5, 8 % of the passes' work), and each thread
   holds the buffers of one strip (41 MB for 2000 columns and 3 frequencies) */
#define TOFG_STRIP 128

/* One strip's planes of a pass output (2F + 2 planes of cap C floats: re (F), im (F), var,
   n_eff). */
typedef struct {
    float *re, *im, *var, *neff;
    ptrdiff_t stride;
} tofg_strip_buf;

static tofg_strip_buf tofg_strip_at(float *base, ptrdiff_t F, ptrdiff_t cap, ptrdiff_t C)
{
    const ptrdiff_t s = cap * C;
    tofg_strip_buf b = {NULL, NULL, NULL, NULL, s};
    if (base) {
        b.re = base;
        b.im = base + F * s;
        b.var = base + 2 * F * s;
        b.neff = base + (2 * F + 1) * s;
    }
    return b;
}

/* the args of one pass over the local grid of rows [g0, g0 + Rl) (every input pointer already
   at row g0), output rows [ra, rb) of it to outputs whose row 0 is local row ra */
static tofg_pass_args tofg_local(const float *zr, const float *zi, const float *v,
                                 const float *nin, ptrdiff_t zs, const float *gr,
                                 const float *gi, const float *gv, ptrdiff_t gs,
                                 const float *col, ptrdiff_t cs, const uint8_t *use,
                                 ptrdiff_t F, ptrdiff_t Rl, ptrdiff_t C, int axis,
                                 const int64_t *px, ptrdiff_t reach, int64_t radius_px,
                                 float inv2h2, float inv2hc2, float *or_, float *oi,
                                 double *or64, double *oi64, float *ov, float *on,
                                 ptrdiff_t os, ptrdiff_t ra, const float *gate,
                                 const float *rn)
{
    const tofg_pass_args p = {zr, zi, v, nin, gr, gi, gv, col, use, F, Rl, C, axis, px, reach,
                              radius_px, inv2h2, inv2hc2, or_, oi, ov, on, or64, oi64, zs, gs,
                              cs, os, ra * C, gate, rn};
    return p;
}

/* The four passes strip by strip (any grid lines): rgbz_tofg_denoise's arguments, checked. */
static int tofg_denoise_strips(const float *zr, const float *zi, const float *v,
                               const float *col, const uint8_t *use, ptrdiff_t F, ptrdiff_t R,
                               ptrdiff_t C, const int64_t *row_px, const int64_t *col_px,
                               ptrdiff_t reach_r, ptrdiff_t reach_c, int64_t radius_px,
                               double inv2h2, double inv2hc2, double *or64, double *oi64,
                               float *ov, float *on, const tofg_unwrap_out *uw,
                               ptrdiff_t strip, int fp, int nth)
{
    /* by default a multiple of the threads' count of strips of at most TOFG_STRIP rows, of
       even heights: the threads' shares stay even */
    const ptrdiff_t nt = nth, nauto = nt * ((R + nt * TOFG_STRIP - 1) / (nt * TOFG_STRIP));
    const ptrdiff_t N = R * C, S = strip > 0 ? strip : (R + nauto - 1) / nauto, H = reach_r;
    const tofg_plan qr = tofg_plan_of(col_px, C, 1, F, C, reach_c, radius_px);
    const tofg_plan qc = tofg_plan_of(row_px, R, 0, F, C, reach_r, radius_px);
    /* the rows of a strip's buffers: the first row pass over S + 4H rows, the other passes
       over S + 2H */
    const ptrdiff_t cap1 = S + 4 * H < R ? S + 4 * H : R, cap2 = S + 2 * H < R ? S + 2 * H : R;
    const size_t per_row = (size_t)(2 * F + 7) * (size_t)C;
    const size_t ebuf = qr.ebuf > qc.ebuf ? qr.ebuf : qc.ebuf;
    const size_t nbuf = (size_t)(2 * F + 2) * (size_t)C * (size_t)(cap1 + 2 * cap2)
                        + 2 * (size_t)cap1 * (size_t)C + per_row + ebuf;
    /* unwrapping: the strip's mean phasors (F, S C) in double, I then Q */
    const size_t nmean = uw ? 2 * (size_t)F * (size_t)S * (size_t)C : 0;
    const float fh = (float)inv2h2, fc = (float)inv2hc2;
    const ptrdiff_t nstrip = (R + S - 1) / S;
    int bad = 0, dom = 0;
#ifdef _OPENMP
#pragma omp parallel num_threads(nth) reduction(|:bad, dom)
#endif
    {
        /* gate, rn (cap1 C each), scratch, E, then the planes of 1, 2 and 3 */
        float *buf = malloc(nbuf * sizeof(float));
        double *mean = nmean ? malloc(nmean * sizeof(double)) : NULL;
        if (nmean && !mean) {
            free(buf);
            buf = NULL;
        }
        bad |= !buf;
        float *gate = NULL, *rn = NULL, *scratch = NULL, *E = NULL, *b = NULL;
        if (buf) {
            gate = buf;
            rn = gate + cap1 * C;
            scratch = rn + cap1 * C;
            E = scratch + per_row;
            b = E + ebuf;
        }
        const tofg_strip_buf B1 = tofg_strip_at(b, F, cap1, C);
        const tofg_strip_buf G1 = tofg_strip_at(b ? b + (2 * F + 2) * cap1 * C : NULL, F, cap2,
                                                C);
        const tofg_strip_buf B2 = tofg_strip_at(b ? b + (2 * F + 2) * (cap1 + cap2) * C : NULL,
                                                F, cap2, C);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (ptrdiff_t t = 0; t < nstrip; t++) {
            if (!buf) continue;
            /* output rows [s0, s1); the column passes' rows [a2, b2), the first row pass's
               [a1, b1): every row within reach of an output row that is on the grid */
            const ptrdiff_t s0 = t * S, s1 = s0 + S < R ? s0 + S : R;
            const ptrdiff_t a2 = s0 - H > 0 ? s0 - H : 0, b2 = s1 + H < R ? s1 + H : R;
            const ptrdiff_t a1 = a2 - H > 0 ? a2 - H : 0, b1 = b2 + H < R ? b2 + H : R;
            const ptrdiff_t n1 = b1 - a1, n2 = b2 - a2, o1 = a1 * C, o2 = a2 * C;
            /* 1: rows of the raw phasors guided by themselves, rows [a1, b1) */
            if (qr.fast) tofg_gates(use + o1, NULL, 0, n1 * C, gate, rn);
            tofg_pass_args p = tofg_local(zr + o1, zi + o1, v + o1, NULL, N, zr + o1, zi + o1,
                                          v + o1, N, col + o1, N, use + o1, F, n1, C, 1,
                                          col_px, reach_c, radius_px, fh, fc, B1.re, B1.im,
                                          NULL, NULL, B1.var, B1.neff, B1.stride, 0,
                                          qr.fast ? gate : NULL, qr.fast ? rn : NULL);
            p.fp = fp;
            tofg_pass_rows(&p, &qr, 0, n1, scratch, E);
            /* 2: columns of 1 guided by themselves: the guide of the second round, [a2, b2) */
            if (qc.fast) tofg_gates(use + o1, B1.neff, 0, n1 * C, gate, rn);
            p = tofg_local(B1.re, B1.im, B1.var, B1.neff, B1.stride, B1.re, B1.im, B1.var,
                           B1.stride, col + o1, N, use + o1, F, n1, C, 0, row_px + a1, reach_r,
                           radius_px, fh, fc, G1.re, G1.im, NULL, NULL, G1.var, G1.neff,
                           G1.stride, a2 - a1, qc.fast ? gate : NULL, qc.fast ? rn : NULL);
            p.fp = fp;
            tofg_pass_rows(&p, &qc, a2 - a1, b2 - a1, scratch, E);
            /* 3: rows of the raw phasors guided by 2, [a2, b2) */
            if (qr.fast) tofg_gates(use + o2, NULL, 0, n2 * C, gate, rn);
            p = tofg_local(zr + o2, zi + o2, v + o2, NULL, N, G1.re, G1.im, G1.var, G1.stride,
                           col + o2, N, use + o2, F, n2, C, 1, col_px, reach_c, radius_px, fh,
                           fc, B2.re, B2.im, NULL, NULL, B2.var, B2.neff, B2.stride, 0,
                           qr.fast ? gate : NULL, qr.fast ? rn : NULL);
            p.fp = fp;
            tofg_pass_rows(&p, &qr, 0, n2, scratch, E);
            /* 4: columns of 3 guided by 2, the output rows [s0, s1) in double (to the strip's
               buffer when they are unwrapped here) */
            const ptrdiff_t ns = (s1 - s0) * C;
            double *mr = mean ? mean : or64 + s0 * C, *mi = mean ? mean + F * ns : oi64 + s0 * C;
            if (qc.fast) tofg_gates(use + o2, B2.neff, 0, n2 * C, gate, rn);
            p = tofg_local(B2.re, B2.im, B2.var, B2.neff, B2.stride, G1.re, G1.im, G1.var,
                           G1.stride, col + o2, N, use + o2, F, n2, C, 0, row_px + a2, reach_r,
                           radius_px, fh, fc, NULL, NULL, mr, mi, ov + s0 * C, on + s0 * C,
                           mean ? ns : N, s0 - a2, qc.fast ? gate : NULL, qc.fast ? rn : NULL);
            p.fp = fp;
            tofg_pass_rows(&p, &qc, s0 - a2, s1 - a2, scratch, E);
            if (mean) {
                const int st = rgbz_tof_depth_iq_strided(
                    mr, mi, F, ns, N, uw->freqs, uw->weights, uw->max_range,
                    uw->depth + s0 * C, uw->residual + s0 * C, uw->wraps + s0 * C,
                    uw->phase + s0 * C, uw->amp + s0 * C, 1);
                dom |= st == RGBZ_EDOMAIN;
                bad |= st != RGBZ_OK && st != RGBZ_EDOMAIN;
            }
        }
        free(mean);
        free(buf);
    }
    return bad ? RGBZ_ENOMEM : dom ? RGBZ_EDOMAIN : RGBZ_OK;
}

/* ------------------------------------------------------------------ validity */
typedef struct {
    const double *amp, *depth, *residual, *sigma_scale, *refl_coef;
    const float *var;
    const uint8_t *sat;
    ptrdiff_t N;
    double min_snr, min_amplitude, max_sigma, max_residual, min_reflectance, max_range;
    double *snr, *sigma, *refl;
    uint8_t *flags;
    const double *delta;
    double max_reflectance;
} tofg_valid_args;

/* the measurements [n0, n1) with NF frequencies (a compile-time constant up to 4), delta from n0
   on when DL (a compile-time constant): branch-free, the arrays restrict parameters, blocks of
   TOFG_VB whose flags other than saturation are made as int32 beside the doubles and stored as
   bytes in a loop of their own, so that the loop over the measurements vectorises (with the
   bytes in it, and a test of delta inside, GCC left it scalar: 2026-11-28) */
#define TOFG_VB 256
RGBZ_INLINE void tofg_valid_span(const tofg_valid_args *p, const double *restrict amp,
                                 const float *restrict var, const double *restrict depth,
                                 const double *restrict residual, const uint8_t *restrict sat,
                                 double *restrict snr, double *restrict sigma,
                                 double *restrict refl, uint8_t *restrict flags,
                                 const double *restrict delta, ptrdiff_t n0, ptrdiff_t n1,
                                 const int NF, const int DL)
{
    const ptrdiff_t N = p->N;
    const double cap = TOFG_PI * TOFG_PI / 3.0, inv_f = 1.0 / (double)NF;
    const double min_snr = p->min_snr, min_amplitude = p->min_amplitude;
    const double max_sigma = p->max_sigma, max_residual = p->max_residual;
    const double min_reflectance = p->min_reflectance, max_range = p->max_range;
    const double max_reflectance = p->max_reflectance;
    const int limit = max_sigma >= 0.0;
    double ssc[RGBZ_TOF_MAX_FREQS], rco[RGBZ_TOF_MAX_FREQS];
    int32_t code[TOFG_VB];
    for (int f = 0; f < NF; f++) {
        ssc[f] = p->sigma_scale[f];
        rco[f] = p->refl_coef[f];
    }
    for (ptrdiff_t b0 = n0; b0 < n1; b0 += TOFG_VB) {
        const ptrdiff_t m = n1 - b0 < TOFG_VB ? n1 - b0 : TOFG_VB;
        for (ptrdiff_t j = 0; j < m; j++) {
            const ptrdiff_t n = b0 + j;
            const double vn = var[n], sd = sqrt(vn), d = depth[n];
            const double dd = d > 0.0 ? d : 1.0;
            double s2 = 0.0, amin = INFINITY, rho = 0.0;
            int32_t weak = 0, capped = 0;
            for (int f = 0; f < NF; f++) {
                const double a = amp[f * N + n];
                double ph = vn / (4.0 * a * a);                  /* phase variance */
                capped |= !(ph < cap);
                ph = ph < cap ? ph : cap;                         /* inf and NaN: the cap */
                s2 += ssc[f] * ph;
                amin = a < amin ? a : amin;                       /* NaN: passed over */
                weak |= a < min_amplitude;
                rho += a * rco[f];
            }
            /* the least 2 a / sd over the frequencies in one division: a correctly rounded
               quotient is monotonic in the dividend, so the same value bit for bit; a NaN
               where a frequency's quotient would be one (0 / 0, inf / inf, a NaN sd) gives
               what passing over those did, inf. The low-signal test reads q (a NaN is not
               below min_snr, as inf is not): tested on the select, GCC made a select of masks
               it cannot vectorise */
            const double q = 2.0 * amin / sd;
            const double best = q == q ? q : INFINITY;
            rho = d > 0.0 ? rho * inv_f * dd * dd : 0.0;
            if (DL) {                      /* the fixed-pattern noise's correlation */
                const double sd2 = s2 + delta[n - n0];
                s2 = (!capped && sd2 > 0.0) ? sd2 : s2;
            }
            const double sg = sqrt(s2);
            const int32_t low = (q < min_snr) | weak | (limit & !(sg <= max_sigma));
            /* out of range, or a reflectance no surface has at that depth (an aliased one) */
            const int32_t far = (d < 0.0) | (d > max_range - 5.0 * sg)
                                | (rho < min_reflectance) | (rho > max_reflectance);
            code[j] = (low << 1) | ((residual[n] > max_residual) << 2) | (far << 4);
            snr[n] = best;
            sigma[n] = sg;
            refl[n] = rho;
        }
        for (ptrdiff_t j = 0; j < m; j++)
            flags[b0 + j] = (uint8_t)((sat[b0 + j] != 0) | code[j]);
    }
}

/* the measurements [n0, n1), delta (NULL: none) from n0 on */
RGBZ_CLONES_512 static void tofg_valid_block(const tofg_valid_args *p, ptrdiff_t F,
                                             ptrdiff_t n0, ptrdiff_t n1, const double *delta)
{
#define TOFG_VALID_(nf, dl) tofg_valid_span(p, p->amp, p->var, p->depth, p->residual, p->sat, \
                                            p->snr, p->sigma, p->refl, p->flags, delta, n0,  \
                                            n1, nf, dl)
#define TOFG_VALID_F_(dl)                                                                     \
    switch (F) {                                                                              \
    case 1: TOFG_VALID_(1, dl); break;                                                        \
    case 2: TOFG_VALID_(2, dl); break;                                                        \
    case 3: TOFG_VALID_(3, dl); break;                                                        \
    case 4: TOFG_VALID_(4, dl); break;                                                        \
    default: TOFG_VALID_((int)F, dl); break;                                                  \
    }
    if (delta) {
        TOFG_VALID_F_(1)
    } else {
        TOFG_VALID_F_(0)
    }
#undef TOFG_VALID_F_
#undef TOFG_VALID_
}

int rgbz_tofg_validity(const double *amp, const float *var, const double *depth,
                       const double *residual, const uint8_t *sat, ptrdiff_t F, ptrdiff_t N,
                       const double *sigma_scale, const double *refl_coef, double min_snr,
                       double min_amplitude, double max_sigma, double max_residual,
                       double min_reflectance, double max_range, const double *delta,
                       double *snr, double *sigma, double *refl, uint8_t *flags, int workers,
                       double max_reflectance)
{
    if (!amp || !var || !depth || !residual || !sat || !sigma_scale || !refl_coef || !snr
        || !sigma || !refl || !flags || F < 1 || F > RGBZ_TOF_MAX_FREQS || N < 0)
        return RGBZ_EINVAL;
    const tofg_valid_args p = {amp, depth, residual, sigma_scale, refl_coef, var, sat, N,
                               min_snr, min_amplitude, max_sigma, max_residual,
                               min_reflectance, max_range, snr, sigma, refl, flags, delta,
                               max_reflectance};
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t n0 = 0; n0 < N; n0 += 4096)
        tofg_valid_block(&p, F, n0, N - n0 < 4096 ? N : n0 + 4096, delta ? delta + n0 : NULL);
    return RGBZ_OK;
}

/* rgbz_tofg_usable of the measurements [lo, hi) */
RGBZ_CLONES_512 static void tofg_usable_span(const uint8_t *restrict flags,
                                             const double *restrict depth,
                                             const double *restrict sigma,
                                             const uint8_t *restrict present, uint8_t bad,
                                             ptrdiff_t lo, ptrdiff_t hi,
                                             uint8_t *restrict usable)
{
    /* branch-free, so that it vectorises: |x| < inf is false for NaN and +-inf */
    for (ptrdiff_t m = lo; m < hi; m++)
        usable[m] = (uint8_t)(((flags[m] & bad) == 0) & (fabs(depth[m]) < INFINITY)
                              & (fabs(sigma[m]) < INFINITY)
                              & (present ? present[m] != 0 : 1));
}

/* the validity args of the denoise's outputs (tofg_valid_out) */
static tofg_valid_args tofg_valid_of(const tofg_unwrap_out *uw, const float *var, ptrdiff_t N)
{
    const tofg_valid_out *q = uw->valid;
    const tofg_valid_args p = {uw->amp, uw->depth, uw->residual, q->sigma_scale, q->refl_coef,
                               var, q->sat, N, q->min_snr, q->min_amplitude, q->max_sigma,
                               q->max_residual, q->min_reflectance, q->max_range, q->snr,
                               q->sigma, q->refl, q->flags, NULL, q->max_reflectance};
    return p;
}

/* The fixed-pattern correction of the measurements [n0, n0 + m) into delta[0, m)
   (tofg_valid_out: as tof/_noise.py's fixed_pattern_delta; iq NULL: bit for bit; else the
   means whose phases and amplitudes uw holds, I of n0 + j at iq[f iqs + j], Q at
   iq[(F + f) iqs + j]: rgbz_tof_fixed_pattern_span's cosines from the phasors) */
static void tofg_valid_delta(const tofg_unwrap_out *uw, const double *count, ptrdiff_t F,
                             ptrdiff_t N, ptrdiff_t n0, ptrdiff_t m, double *delta,
                             const double *iq, ptrdiff_t iqs)
{
    const tofg_valid_out *q = uw->valid;
    rgbz_tof_fixed_pattern_span(uw->phase, uw->amp, q->offset, count, F, N, q->sigma_scale,
                                q->black, q->pre, q->var_dsnu, q->fix_dsnu, q->prnu, 1, n0, m,
                                delta, iq, iqs);
    if (q->delay_var != 0.0)
        for (ptrdiff_t j = 0; j < m; j++) {
            const double c = count[n0 + j];
            delta[j] += q->delay_var / ((c >= 1.0 || c != c) ? c : 1.0);
        }
}

/* The validity of the measurements [n0, n0 + m) of the denoise's outputs (var: ov, count:
   on64) on the calling thread, TOFG_VALID_ROW at a time; iq (NULL: none), iqs: their means
   (tofg_valid_delta) */
#define TOFG_VALID_ROW 512
static void tofg_valid_row(const tofg_unwrap_out *uw, const float *var, const double *count,
                           ptrdiff_t F, ptrdiff_t N, ptrdiff_t n0, ptrdiff_t m,
                           const double *iq, ptrdiff_t iqs)
{
    double delta[TOFG_VALID_ROW];
    const tofg_valid_args p = tofg_valid_of(uw, var, N);
    for (ptrdiff_t j = 0; j < m; j += TOFG_VALID_ROW) {
        const ptrdiff_t k = m - j < TOFG_VALID_ROW ? m - j : TOFG_VALID_ROW;
        if (uw->valid->offset)
            tofg_valid_delta(uw, count, F, N, n0 + j, k, delta, iq ? iq + j : NULL, iqs);
        tofg_valid_block(&p, F, n0 + j, n0 + j + k, uw->valid->offset ? delta : NULL);
        if (uw->valid->usable)
            tofg_usable_span(uw->valid->flags, uw->depth, uw->valid->sigma,
                             uw->valid->present, uw->valid->bad, n0 + j, n0 + j + k,
                             uw->valid->usable);
    }
}

/* the prepare stage of [m0, m0 + n) for q's element type (tof_guided.template.h's
   tofg_prepare_span; defined with the instances at the end) */
static void tofg_prep_span(const tofg_prep_in *q, ptrdiff_t F, ptrdiff_t N, ptrdiff_t m0,
                           ptrdiff_t n, float *zr, float *zi, ptrdiff_t os, float *v,
                           uint8_t *hit, double *offset, float *phi);

/* ---------------------------------------------------------------- the sliding pipeline */
/* The four passes of rgbz_tofg_denoise row by row on evenly spaced grid lines. The frame is
   cut into tiles of output columns [c0, c1) (at most TOFG_VIEW of them) and bands of output
   rows [b0, b1); a thread runs a tile's band through the passes one grid row at a time, the
   column passes' inputs held in rings of K = 2H + 1 padded rows (grid row r in slot r mod K),
   so the working set is a few rows of the tile (it stays in the cache) and no row is computed
   twice inside a band. A tile's row passes see the frame's columns [c0 - 2 Ac, c1 + 2 Ac)
   (its view): the first two passes run over all of them (the second-round row pass reaches
   Ac columns beyond the tile into the first round's output, which reaches Ac further), the
   last two over the tile. A padded row holds the view's columns at [pad, pad + cv) and zeros
   (gate 0) around them, so every column runs in the fast blocks: the off-grid neighbours of
   the generic row enter with weight 0 and add +0 to every sum, the same sums bit for bit. */
typedef struct {
    const float *zr, *zi, *v, *col;
    const uint8_t *use;
    ptrdiff_t F, R, C, N;
    ptrdiff_t H, Ac;              /* the column passes' tap offsets |a| <= H, the rows' <= Ac */
    ptrdiff_t pad, W, K;          /* the padded row: W floats, the view from pad on */
    const int64_t *row_px, *col_px;
    ptrdiff_t reach_r, reach_c;
    int64_t radius_px;
    float ih, ic;
    int nrt;                      /* the row passes' taps */
    ptrdiff_t rshift[2 * 64 + 1];
    double *or64, *oi64;
    float *ov, *on;
    double *on64;
    const tofg_unwrap_out *uw;
    const tofg_prep_in *prep;     /* the prepare stage made here (NULL: zr, zi, v read) */
    size_t nfloat, ndouble;       /* one thread's buffers */
    int fp;                       /* col's fourth plane: the fixed-pattern shares (tofg_xp) */
} tofg_slide;

/* a tile: output columns [c0, c1), its view [v0, v0 + cv) of the frame's columns, the blocks
   of the view (nv) and of the output columns (no, from buffer column xo) */
typedef struct {
    ptrdiff_t c0, c1, v0, cv, nv, no, xo;
} tofg_tile;

/* one thread's buffers (floats unless said): see tofg_slide_buf_at */
typedef struct {
    float *raw, *gate, *ones, *E, *colr, *r1, *g2, *n2, *gd, *r3, *g4, *n4, *pr2, *pr4, *tv,
          *tn;
    double *t64;
    float *block;
} tofg_slide_buf;

/* the layout of a thread's buffers from `base` (NULL: only their size into S) */
static tofg_slide_buf tofg_slide_buf_at(tofg_slide *S, float *base)
{
    const size_t F = (size_t)S->F, W = (size_t)S->W, KW = (size_t)S->K * W;
    const size_t A1 = (size_t)S->H + 1, P = (2 * F + 2) * KW;
    tofg_slide_buf b;
    float *f = base;
    b.block = base;
    b.raw = f;                                   /* K rows of (2F + 1) W: the ring of raw rows */
    b.gate = b.raw + (2 * F + 1) * KW;           /* K rows of W */
    b.ones = b.gate + KW;
    b.E = b.ones + W;
    b.colr = b.E + ((size_t)S->Ac + 1) * W;
    b.r1 = b.colr + 4 * KW;                      /* col's planes: 3 colours (and phi) */
    b.g2 = b.r1 + P;
    b.n2 = b.g2 + KW;
    b.gd = b.n2 + KW;
    b.r3 = b.gd + P;
    b.g4 = b.r3 + P;
    b.n4 = b.g4 + KW;
    b.pr2 = b.n4 + KW;
    b.pr4 = b.pr2 + A1 * A1 * W;
    b.tv = b.pr4 + A1 * A1 * W;
    b.tn = b.tv + W;
    const size_t nf = ((size_t)(b.tn + W - f) + 1) & ~(size_t)1;  /* the doubles aligned */
    b.t64 = (double *)(f + nf);
    S->nfloat = nf;
    S->ndouble = 2 * F * W;
    return b;
}

/* the raw row buffer (2F + 1 padded rows: zr, zi, v) and gate row of ring slot r mod K */
static float *tofg_slide_rawrow(const tofg_slide *S, const tofg_slide_buf *b, ptrdiff_t r)
{
    return b->raw + (r % S->K) * (2 * S->F + 1) * S->W;
}

/* grid row r of the taps through the prepare stage in the tile's view into the padded row
   buffers of its ring slot: the phasors, variance and the gates (use, and no tap at full
   scale), the fixed-pattern shares into col's fourth plane's ring row (with S->fp); offset
   and sat written where the row is the band's (own) and the column the tile's */
static void tofg_slide_prep(const tofg_slide *S, const tofg_slide_buf *b, const tofg_tile *T,
                            ptrdiff_t r, int own)
{
    const ptrdiff_t F = S->F, W = S->W, N = S->N, K = S->K, o = r * S->C + T->v0;
    const ptrdiff_t pd = S->pad, KW = K * W;
    float *raw = tofg_slide_rawrow(S, b, r), *gate = b->gate + (r % K) * W;
    float *phi = S->fp ? b->colr + 3 * KW + (r % K) * W : NULL;
    /* the view's columns [0, cv) in three parts: before the tile's, the tile's, after */
    const ptrdiff_t cut[4] = {0, T->c0 - T->v0, T->c1 - T->v0, T->cv};
    uint8_t hit[256];
    for (int part = 0; part < 3; part++) {
        const int mine = own && part == 1;
        for (ptrdiff_t c0 = cut[part]; c0 < cut[part + 1]; c0 += 256) {
            const ptrdiff_t n = cut[part + 1] - c0 < 256 ? cut[part + 1] - c0 : 256;
            const ptrdiff_t x = pd + c0, m = o + c0;
            memset(hit, 0, (size_t)n);
            tofg_prep_span(S->prep, F, N, m, n, raw + x, raw + F * W + x, W, raw + 2 * F * W + x,
                           hit, mine ? S->prep->offset : NULL, phi ? phi + x : NULL);
            for (ptrdiff_t c = 0; c < n; c++)
                gate[x + c] = S->use[m + c] != 0 && !hit[c] ? 1.0f : 0.0f;
            if (mine)
                for (ptrdiff_t c = 0; c < n; c++) S->prep->sat[m + c] |= hit[c];
        }
    }
}

/* grid row r of the frame's raw phasors, variance and use in the tile's view into the padded
   row buffers of its ring slot (the first row pass reads them at r, the second H rows later);
   with S->prep, made from the taps (tofg_slide_prep; own: the row is the band's) */
static void tofg_slide_raw(const tofg_slide *S, const tofg_slide_buf *b, const tofg_tile *T,
                           ptrdiff_t r, int own)
{
    if (S->prep) {
        tofg_slide_prep(S, b, T, r, own);
        return;
    }
    const ptrdiff_t F = S->F, W = S->W, N = S->N, o = r * S->C + T->v0, pd = S->pad;
    const size_t n = (size_t)T->cv * sizeof(float);
    float *raw = tofg_slide_rawrow(S, b, r), *gate = b->gate + (r % S->K) * W;
    for (ptrdiff_t f = 0; f < F; f++) {
        memcpy(raw + f * W + pd, S->zr + f * N + o, n);
        memcpy(raw + (F + f) * W + pd, S->zi + f * N + o, n);
    }
    memcpy(raw + 2 * F * W + pd, S->v + o, n);
    for (ptrdiff_t c = 0; c < T->cv; c++) gate[pd + c] = S->use[o + c] != 0 ? 1.0f : 0.0f;
}

/* the pass arguments of a row pass of the padded raw row r (its data, in its ring slot)
   guided by gr (planes of stride gs) into the ring at base `out` (planes of stride KW) */
static tofg_pass_args tofg_slide_rowargs(const tofg_slide *S, const tofg_slide_buf *b,
                                         ptrdiff_t r, const float *gr, const float *gi,
                                         const float *gv, ptrdiff_t gs, const float *colrow,
                                         float *out)
{
    const ptrdiff_t F = S->F, W = S->W, KW = S->K * W;
    const float *raw = tofg_slide_rawrow(S, b, r), *gate = b->gate + (r % S->K) * W;
    const tofg_pass_args p = {
        raw, raw + F * W, raw + 2 * F * W, NULL, gr, gi, gv, colrow, S->use, F, 1,
        W, 1, S->col_px, S->reach_c, S->radius_px, S->ih, S->ic, out, out + F * KW, out +
        2 * F * KW, out + (2 * F + 1) * KW, NULL, NULL, W, gs, KW, KW, 0, gate, b->ones, S->fp};
    return p;
}

/* one row pass over nblk blocks from buffer column x0 (p: a single padded row) */
static void tofg_slide_row(const tofg_slide *S, const tofg_pass_args *p, float *E,
                           ptrdiff_t x0, ptrdiff_t nblk)
{
    const ptrdiff_t W = S->W, n = nblk * TOFG_BW;
    const float *ew[2 * 64 + 1];
    for (ptrdiff_t a = 0; a <= S->Ac; a++) tofg_pairs(p, x0 - a, x0, n + a, E + a * W + x0 - a);
    for (int t = 0; t < S->nrt; t++) {
        const ptrdiff_t a = S->rshift[t];
        ew[t] = a >= 0 ? E + a * W + x0 : E + (-a) * W + x0 + a;
    }
    tofg_blocks(p, x0, nblk, S->rshift, ew, S->nrt);
}

/* the pair weights e(r, r + a), a = 0..H, of ring row r (nblk blocks from buffer column x0)
   into slot r mod (H + 1) of pr */
static void tofg_slide_colpairs(const tofg_slide *S, const tofg_pass_args *p, float *pr,
                                ptrdiff_t r, ptrdiff_t x0, ptrdiff_t nblk)
{
    const ptrdiff_t H = S->H, W = S->W, K = S->K, n = nblk * TOFG_BW;
    float *own = pr + (r % (H + 1)) * (H + 1) * W;
    for (ptrdiff_t a = 0; a <= H && r + a < S->R; a++)
        tofg_pairs(p, (r % K) * W + x0, ((r + a) % K) * W + x0, n, own + a * W);
}

/* output row r of a column pass over the rings (pair weights in pr) */
static void tofg_slide_col(const tofg_slide *S, const tofg_pass_args *p, const float *pr,
                           ptrdiff_t r, ptrdiff_t x0, ptrdiff_t nblk)
{
    const ptrdiff_t H = S->H, W = S->W, K = S->K, A1 = H + 1;
    ptrdiff_t shift[2 * 64 + 1];
    const float *ew[2 * 64 + 1];
    int nt = 0;
    for (ptrdiff_t a = -H; a <= H; a++) {
        if (r + a < 0 || r + a >= S->R) continue;
        shift[nt] = ((r + a) % K - r % K) * W;
        ew[nt++] = a >= 0 ? pr + (r % A1) * A1 * W + a * W
                          : pr + ((r + a) % A1) * A1 * W + (-a) * W;
    }
    tofg_blocks(p, (r % K) * W + x0, nblk, shift, ew, nt);
}

/* the gates of ring row r of a column pass's data (n_eff in neff) over the view into g, n
   (tofg_gates), the use of its measurements from the raw row's gates (in the ring since the
   first row pass: r is at most 2H rows back) */
static void tofg_slide_gates(const tofg_slide *S, const tofg_slide_buf *b, const tofg_tile *T,
                             const float *neff, float *g, float *n, ptrdiff_t r)
{
    const ptrdiff_t o = (r % S->K) * S->W + S->pad;
    const float *use = b->gate;
    for (ptrdiff_t c = 0; c < T->cv; c++) {
        const float nn = neff[o + c];
        g[o + c] = use[o + c] != 0.0f && nn > 0.0f ? 1.0f : 0.0f;
        n[o + c] = 1.0f / (nn > 0.0f ? nn : 1.0f);
    }
}

/* the tile's outputs of grid row s from t64, tv, tn: stored, or unwrapped (rgbz_tof_depth_iq_row
   on the row's means where t64 holds them) and, with uw->valid, their validity; RGBZ_OK,
   RGBZ_EDOMAIN or another status */
static int tofg_slide_out(const tofg_slide *S, const tofg_slide_buf *b, const tofg_tile *T,
                          ptrdiff_t s)
{
    const ptrdiff_t F = S->F, W = S->W, N = S->N, n = T->c1 - T->c0, o = s * S->C + T->c0;
    const ptrdiff_t x = S->pad + T->c0 - T->v0;
    memcpy(S->ov + o, b->tv + x, (size_t)n * sizeof(float));
    if (S->on64)
        for (ptrdiff_t j = 0; j < n; j++) S->on64[o + j] = b->tn[x + j];
    else
        memcpy(S->on + o, b->tn + x, (size_t)n * sizeof(float));
    if (!S->uw) {
        for (ptrdiff_t f = 0; f < F; f++) {
            memcpy(S->or64 + f * N + o, b->t64 + f * W + x, (size_t)n * sizeof(double));
            memcpy(S->oi64 + f * N + o, b->t64 + (F + f) * W + x, (size_t)n * sizeof(double));
        }
        return RGBZ_OK;
    }
    const tofg_unwrap_out *uw = S->uw;
    const int st = rgbz_tof_depth_iq_row(b->t64 + x, b->t64 + F * W + x, F, n, W, N, uw->freqs,
                                         uw->weights, uw->max_range, uw->depth + o,
                                         uw->residual + o, uw->wraps + o, uw->phase + o,
                                         uw->amp + o);
    if (uw->valid) tofg_valid_row(uw, S->ov, S->on64, F, N, o, n, b->t64 + x, W);
    return st;
}

/* the tile's band of output rows [b0, b1); RGBZ_OK, RGBZ_EDOMAIN or another status */
static int tofg_slide_band(const tofg_slide *S, const tofg_slide_buf *b, const tofg_tile *T,
                           ptrdiff_t b0, ptrdiff_t b1)
{
    const ptrdiff_t F = S->F, C = S->C, R = S->R, H = S->H, W = S->W, K = S->K, KW = K * W;
    const ptrdiff_t pd = S->pad, N = S->N, xo = T->xo, no = T->no, nv = T->nv;
    const ptrdiff_t lo1 = b0 - 2 * H > 0 ? b0 - 2 * H : 0, hi1 = b1 + 2 * H < R ? b1 + 2 * H : R;
    const ptrdiff_t lo2 = b0 - H > 0 ? b0 - H : 0, hi2 = b1 + H < R ? b1 + H : R;
    /* the rows whose column pair weights the outputs reach: H above the first output */
    const ptrdiff_t lp2 = lo2 - H > 0 ? lo2 - H : 0, lp4 = b0 - H > 0 ? b0 - H : 0;
    /* the column passes: 2 = columns of 1 (ring r1) guided by themselves into gd; 4 = columns
       of 3 (ring r3) guided by gd, to t64, tv, tn */
    const tofg_pass_args p2 = {
        b->r1, b->r1 + F * KW, b->r1 + 2 * F * KW, b->r1 + (2 * F + 1) * KW, b->r1,
        b->r1 + F * KW, b->r1 + 2 * F * KW, b->colr, S->use, F, R, W, 0, S->row_px, S->reach_r,
        S->radius_px, S->ih, S->ic, b->gd, b->gd + F * KW, b->gd + 2 * F * KW,
        b->gd + (2 * F + 1) * KW, NULL, NULL, KW, KW, KW, KW, 0, b->g2, b->n2, S->fp};
    tofg_pass_args p4 = {
        b->r3, b->r3 + F * KW, b->r3 + 2 * F * KW, b->r3 + (2 * F + 1) * KW, b->gd,
        b->gd + F * KW, b->gd + 2 * F * KW, b->colr, S->use, F, R, W, 0, S->row_px, S->reach_r,
        S->radius_px, S->ih, S->ic, NULL, NULL, b->tv, b->tn, b->t64, b->t64 + F * W, KW, KW,
        KW, W, 0, b->g4, b->n4, S->fp};
    int st = RGBZ_OK;
    for (ptrdiff_t t = lo1; t < hi1 + 2 * H; t++) {
        if (t < hi1) {                     /* 1: row t of the raw phasors guided by itself */
            const ptrdiff_t so = (t % K) * W;
            for (int k = 0; k < 3 + (S->fp && !S->prep); k++)
                memcpy(b->colr + k * KW + so + pd, S->col + k * N + t * C + T->v0,
                       (size_t)T->cv * sizeof(float));
            tofg_slide_raw(S, b, T, t, t >= b0 && t < b1);
            const float *raw = tofg_slide_rawrow(S, b, t);
            const tofg_pass_args p1 = tofg_slide_rowargs(S, b, t, raw, raw + F * W,
                                                         raw + 2 * F * W, W, b->colr + so,
                                                         b->r1 + so);
            tofg_slide_row(S, &p1, b->E, pd, nv);
            tofg_slide_gates(S, b, T, b->r1 + (2 * F + 1) * KW, b->g2, b->n2, t);
        }
        const ptrdiff_t q = t - H;         /* 2 (over the view) and 3 (the tile) at row q */
        if (q >= lp2 && q < hi2) tofg_slide_colpairs(S, &p2, b->pr2, q, pd, nv);
        if (q >= lo2 && q < hi2) {
            tofg_slide_col(S, &p2, b->pr2, q, pd, nv);
            const ptrdiff_t so = (q % K) * W;
            /* row q's raw data: in its ring slot since the first row pass (H rows ago) */
            const tofg_pass_args p3 = tofg_slide_rowargs(S, b, q, b->gd + so,
                                                         b->gd + F * KW + so,
                                                         b->gd + 2 * F * KW + so, KW,
                                                         b->colr + so, b->r3 + so);
            tofg_slide_row(S, &p3, b->E, xo, no);
            tofg_slide_gates(S, b, T, b->r3 + (2 * F + 1) * KW, b->g4, b->n4, q);
        }
        const ptrdiff_t s = t - 2 * H;     /* 4 (the tile) at row s */
        if (s >= lp4 && s < b1) tofg_slide_colpairs(S, &p4, b->pr4, s, xo, no);
        if (s >= b0 && s < b1) {
            p4.ooff = (s % K) * W;
            tofg_slide_col(S, &p4, b->pr4, s, xo, no);
            const int u = tofg_slide_out(S, b, T, s);
            st = u == RGBZ_OK ? st : st == RGBZ_OK || st == RGBZ_EDOMAIN ? u : st;
        }
    }
    return st;
}

/* output columns per tile of the sliding pipeline, at most: the rings of a tile's view
   (F = 3, H = 5) stay within about a megabyte */
#define TOFG_VIEW 512

int rgbz_tofg_denoise(const float *zr, const float *zi, const float *v, const float *col,
                      const uint8_t *use, ptrdiff_t F, ptrdiff_t R, ptrdiff_t C,
                      const int64_t *row_px, const int64_t *col_px, ptrdiff_t reach_r,
                      ptrdiff_t reach_c, int64_t radius_px, double inv2h2, double inv2hc2,
                      double *or64, double *oi64, float *ov, float *on, double *on64,
                      const tofg_unwrap_out *uw, ptrdiff_t strip, int fixed,
                      const tofg_prep_in *prep, int workers)
{
    if (prep && (!prep->taps || !prep->sat || !prep->offset))
        return RGBZ_EINVAL;
    if ((!prep && (!zr || !zi || !v)) || !col || !use || !row_px || !col_px || !ov
        || (!on && !on64)
        || (!uw && (!or64 || !oi64)) || F < 1 || F > RGBZ_TOF_MAX_FREQS || R < 0 || C < 0
        || reach_r < 0 || reach_c < 0 || radius_px < 0 || !(inv2h2 >= 0.0)
        || !(inv2hc2 >= 0.0))
        return RGBZ_EINVAL;
    if (uw && (!uw->freqs || !uw->weights || !uw->depth || !uw->residual || !uw->wraps
               || !uw->phase || !uw->amp))
        return RGBZ_EINVAL;
    if (uw && uw->valid && (!on64 || !uw->valid->sat || !uw->valid->sigma_scale
                            || !uw->valid->refl_coef || !uw->valid->snr || !uw->valid->sigma
                            || !uw->valid->refl || !uw->valid->flags))
        return RGBZ_EINVAL;
    if (R == 0 || C == 0) return RGBZ_OK;
    const int nth = rgbz_threads(workers);
    const tofg_plan qr = tofg_plan_of(col_px, C, 1, F, C, reach_c, radius_px);
    const tofg_plan qc = tofg_plan_of(row_px, R, 0, F, C, reach_r, radius_px);
    if (prep && (!qr.fast || !qc.fast)) {
        /* the strips read whole planes: the prepare stage over the frame first, then the
           denoise of its planes (use without the taps at full scale, col's fourth plane the
           fixed-pattern shares) */
        const ptrdiff_t N = R * C, np = fixed ? 4 : 3;
        float *z = malloc((size_t)(2 * F + 1 + np) * (size_t)N * sizeof *z);
        uint8_t *u = malloc((size_t)N);
        int st = z && u ? RGBZ_OK : RGBZ_ENOMEM;
        if (st == RGBZ_OK) {
            float *pz = z + 2 * F * N, *pc = pz + N;
            memcpy(pc, col, (size_t)(3 * N) * sizeof *pc);
            st = rgbz_tofg_prepare(prep->in_type, prep->taps, F, N, prep->gain, prep->black,
                                   prep->supp, prep->const_var, prep->prnu, prep->white, z,
                                   z + F * N, pz, prep->sat, prep->offset, prep->fixed_var,
                                   fixed ? pc + 3 * N : NULL, nth);
            for (ptrdiff_t n = 0; n < N; n++) u[n] = use[n] && !prep->sat[n];
            if (st == RGBZ_OK)
                st = rgbz_tofg_denoise(z, z + F * N, pz, pc, u, F, R, C, row_px, col_px,
                                       reach_r, reach_c, radius_px, inv2h2, inv2hc2, or64,
                                       oi64, ov, on, on64, uw, strip, fixed, NULL, workers);
        }
        free(z);
        free(u);
        return st;
    }
    if (!qr.fast || !qc.fast) {
        /* the strips write n_eff in float: into on, or a buffer widened into on64 */
        float *o = on ? on : malloc((size_t)(R * C) * sizeof *o);
        if (!o) return RGBZ_ENOMEM;
        const int st = tofg_denoise_strips(zr, zi, v, col, use, F, R, C, row_px, col_px,
                                           reach_r, reach_c, radius_px, inv2h2, inv2hc2, or64,
                                           oi64, ov, o, uw, strip, fixed != 0, nth);
        const ptrdiff_t N = R * C;
        if (on64) {
            RGBZ_PARALLEL_FOR
            for (ptrdiff_t n = 0; n < N; n++) on64[n] = o[n];
        }
        if (!on) free(o);
        if (uw && uw->valid && (st == RGBZ_OK || st == RGBZ_EDOMAIN)) {
            RGBZ_PARALLEL_FOR
            for (ptrdiff_t n0 = 0; n0 < N; n0 += 4096)
                tofg_valid_row(uw, ov, on64, F, N, n0, N - n0 < 4096 ? N - n0 : 4096, NULL,
                               0);
        }
        return st;
    }
    /* tiles of even widths; bands: `strip` rows each, else as many as make at least two
       tiles' bands a thread (a band recomputes the 4H rows of the first pass and 2H of the
       next two beyond its ends; a tile 4 Ac columns of the first two passes) */
    const ptrdiff_t ntile = (C + TOFG_VIEW - 1) / TOFG_VIEW, tw = (C + ntile - 1) / ntile;
    const ptrdiff_t want = (2 * (ptrdiff_t)nth + ntile - 1) / ntile;
    const ptrdiff_t nb = strip > 0 ? (R + strip - 1) / strip : (want < R ? want : R);
    tofg_slide S;
    S.zr = zr;
    S.zi = zi;
    S.v = v;
    S.col = col;
    S.use = use;
    S.F = F;
    S.R = R;
    S.C = C;
    S.N = R * C;
    S.H = qc.A;
    S.Ac = qr.A;
    S.pad = qr.A;
    /* a view's blocks end at most 16 columns past its cv <= tw + 4 Ac, the tile's reach Ac
       further */
    S.W = qr.A + (tw + 4 * qr.A + 2 * TOFG_BW) / TOFG_BW * TOFG_BW + qr.A;
    S.K = 2 * qc.A + 1;
    S.row_px = row_px;
    S.col_px = col_px;
    S.reach_r = reach_r;
    S.reach_c = reach_c;
    S.radius_px = radius_px;
    S.ih = (float)inv2h2;
    S.ic = (float)inv2hc2;
    S.nrt = 0;
    for (ptrdiff_t a = -qr.A; a <= qr.A; a++) S.rshift[S.nrt++] = a;
    S.or64 = or64;
    S.oi64 = oi64;
    S.ov = ov;
    S.on = on;
    S.on64 = on64;
    S.uw = uw;
    S.prep = prep;
    S.fp = fixed != 0;
    (void)tofg_slide_buf_at(&S, NULL);
    const size_t nbytes = S.nfloat * sizeof(float) + S.ndouble * sizeof(double);
    int bad = 0, dom = 0;
#ifdef _OPENMP
#pragma omp parallel num_threads(nth) reduction(|:bad, dom)
#endif
    {
        float *mem = malloc(nbytes);
        const tofg_slide_buf b = tofg_slide_buf_at(&S, mem);
        bad |= !mem;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
        for (ptrdiff_t k = 0; k < nb * ntile; k++) {
            if (!mem) continue;
            const ptrdiff_t band = k / ntile, j = k % ntile;
            const ptrdiff_t b0 = strip > 0 ? band * strip : band * R / nb;
            const ptrdiff_t b1 = strip > 0 ? (b0 + strip < R ? b0 + strip : R)
                                           : (band + 1) * R / nb;
            tofg_tile T;
            T.c0 = j * tw;
            T.c1 = T.c0 + tw < C ? T.c0 + tw : C;
            T.v0 = T.c0 - 2 * qr.A > 0 ? T.c0 - 2 * qr.A : 0;
            T.cv = (T.c1 + 2 * qr.A < C ? T.c1 + 2 * qr.A : C) - T.v0;
            T.nv = (T.cv + TOFG_BW - 1) / TOFG_BW;
            T.xo = S.pad + T.c0 - T.v0;
            T.no = (T.c1 - T.c0 + TOFG_BW - 1) / TOFG_BW;
            /* zeros: the padding of every row is 0 (finite, gate 0) whatever the last tile
               left there */
            memset(mem, 0, S.nfloat * sizeof(float));
            for (ptrdiff_t x = 0; x < S.W; x++) b.ones[x] = 1.0f;
            const int st = tofg_slide_band(&S, &b, &T, b0, b1);
            dom |= st == RGBZ_EDOMAIN;
            bad |= st != RGBZ_OK && st != RGBZ_EDOMAIN;
        }
        free(mem);
    }
    return bad ? RGBZ_ENOMEM : dom ? RGBZ_EDOMAIN : RGBZ_OK;
}

/* ------------------------------------------------------------------ flying pixels */
typedef struct {
    const double *depth, *sigma;
    const uint8_t *usable;
    const float *col, *cells, *ring;
    int ncells, nring;
    ptrdiff_t R, C;
    double step2, k2, tol_k, contrast, side;
    int unflag;
    uint8_t *flags;
    double *depth_out;
    double max_range;             /* NaN: no range test of the resolved depths */
    uint8_t *valid;               /* NULL: not made; else flags == 0, row by row */
} tofg_fly_args;

static const int tofg_dirs[4][2] = {{0, 1}, {1, 0}, {1, 1}, {1, -1}};

/* usable measurement at (r, c) (0 off the grid) */
static inline int tofg_ok(const tofg_fly_args *p, ptrdiff_t r, ptrdiff_t c)
{
    return r >= 0 && r < p->R && c >= 0 && c < p->C && p->usable[r * p->C + c];
}

/* Whether the second-difference test flags (r, c): a hit centred there, or at a neighbour
   whose pair across the discontinuity includes it. code: the hits of every cell (bit 2e: a
   hit along direction e, bit 2e + 1: its pair is the neighbour at +e). */
static int tofg_candidate(const tofg_fly_args *p, const uint8_t *code, ptrdiff_t r, ptrdiff_t c)
{
    const ptrdiff_t C = p->C, m = r * C + c;
    if (code[m] & 0x55) return 1;
    for (int e = 0; e < 4; e++) {
        const ptrdiff_t dr = tofg_dirs[e][0], dc = tofg_dirs[e][1];
        const int hit = 1 << (2 * e), hi = 2 << (2 * e);
        if (r - dr >= 0 && c - dc >= 0 && c - dc < C
            && (code[m - dr * C - dc] & (hit | hi)) == (hit | hi))
            return 1;
        if (r + dr < p->R && c + dc >= 0 && c + dc < C
            && (code[m + dr * C + dc] & (hit | hi)) == hit)
            return 1;
    }
    return 0;
}

/* the hits centred at the cells of row r along every direction (tofg_candidate's code) */
RGBZ_CLONES_512 static void tofg_hit_row(const tofg_fly_args *p, ptrdiff_t r, uint8_t *code)
{
    /* blocks of 256 cells whose bits gather in int32 beside the doubles and are stored as
       bytes once, the parameters in locals, the arrays restrict: the loops vectorise at the
       clone's width (with the bytes' read-modify-write inside, which may alias anything,
       GCC reloaded the parameters every cell and used half the width) */
    const ptrdiff_t C = p->C, R = p->R;
    const double *restrict d = p->depth, *restrict s = p->sigma;
    const uint8_t *restrict u = p->usable;
    const double k2 = p->k2, step2 = p->step2;
    int32_t bits[256];
    for (ptrdiff_t x0 = 0; x0 < C; x0 += 256) {
        const ptrdiff_t x1 = C - x0 < 256 ? C : x0 + 256;
        for (ptrdiff_t c = x0; c < x1; c++) bits[c - x0] = 0;
        for (int e = 0; e < 4; e++) {
            const ptrdiff_t dr = tofg_dirs[e][0], dc = tofg_dirs[e][1];
            if (r - dr < 0 || r + dr >= R) continue;
            const ptrdiff_t lo_c = dc ? 1 : 0, hi_c = dc ? C - 1 : C, off = dr * C + dc;
            const ptrdiff_t ca = x0 > lo_c ? x0 : lo_c, cb = x1 < hi_c ? x1 : hi_c;
            for (ptrdiff_t c = ca; c < cb; c++) {
                const ptrdiff_t m = r * C + c, lo = m - off, hi = m + off;
                /* every operand loaded (an unusable one may be NaN: it never counts) */
                const int32_t ok = u[m] & u[lo] & u[hi];
                const double down = d[m] - d[lo], up = d[hi] - d[m];
                double jump = up - down;
                jump *= jump;
                const double shi = s[hi], slo = s[lo], sm = s[m];
                double noise = shi * shi + slo * slo;
                noise += 4.0 * (sm * sm);
                noise *= k2;
                noise = noise > step2 ? noise : step2;
                const int32_t hit = ok & (jump > noise), toward = fabs(up) >= fabs(down);
                bits[c - x0] |= (hit << (2 * e)) | ((hit & toward) << (2 * e + 1));
            }
        }
        for (ptrdiff_t c = x0; c < x1; c++) code[r * C + c] = (uint8_t)bits[c - x0];
    }
}

/* tofg_candidate for the cells of row r into cand[0 .. C): in the interior (every neighbour on
   the grid) branch-free, in a loop that vectorises; on the border as tofg_candidate */
RGBZ_CLONES_512 static void tofg_cand_row(const tofg_fly_args *p, const uint8_t *code,
                                          ptrdiff_t r, uint8_t *restrict cand)
{
    const ptrdiff_t C = p->C;
    if (r == 0 || r == p->R - 1 || C < 3) {
        for (ptrdiff_t c = 0; c < C; c++) cand[c] = (uint8_t)tofg_candidate(p, code, r, c);
        return;
    }
    cand[0] = (uint8_t)tofg_candidate(p, code, r, 0);
    cand[C - 1] = (uint8_t)tofg_candidate(p, code, r, C - 1);
    const uint8_t *restrict k = code + r * C, *restrict up = k - C, *restrict dn = k + C;
    /* direction e = (dr, dc): the hit of the neighbour at -e with its pair at +e (both bits
       2e, 2e + 1), or of the neighbour at +e with its pair away (bit 2e alone) */
    for (ptrdiff_t c = 1; c < C - 1; c++) {
        const int v = ((k[c] & 0x55) != 0)
                      | ((k[c - 1] & 0x03) == 0x03) | ((k[c + 1] & 0x03) == 0x01)
                      | ((up[c] & 0x0c) == 0x0c) | ((dn[c] & 0x0c) == 0x04)
                      | ((up[c - 1] & 0x30) == 0x30) | ((dn[c + 1] & 0x30) == 0x10)
                      | ((up[c + 1] & 0xc0) == 0xc0) | ((dn[c - 1] & 0xc0) == 0x40);
        cand[c] = (uint8_t)v;
    }
}

/* the test of a usable candidate cell (tofg_candidate) */
static void tofg_fly_cell(const tofg_fly_args *p, ptrdiff_t r, ptrdiff_t c)
{
    const ptrdiff_t C = p->C, N = p->R * p->C, m = r * C + c;
    /* the two sides among the usable 8-neighbours: split at the middle of the depths */
    const double dm = p->depth[m];
    double lo = dm, hi = dm;
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            if ((a || b) && tofg_ok(p, r + a, c + b)) {
                const double d = p->depth[m + a * C + b];
                lo = d < lo ? d : lo;
                hi = d > hi ? d : hi;
            }
    const double mid = 0.5 * (lo + hi);
    double sum[2] = {0.0, 0.0}, cs[2][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    int cnt[2] = {0, 0};
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            if ((a || b) && tofg_ok(p, r + a, c + b)) {
                const ptrdiff_t n = m + a * C + b;
                const int s = p->depth[n] > mid;
                sum[s] += p->depth[n];
                cnt[s]++;
                for (int ch = 0; ch < 3; ch++) cs[s][ch] += p->col[ch * N + n];
            }
    double dside[2], cside[2][3];
    for (int s = 0; s < 2; s++) {
        const double inv = cnt[s] ? 1.0 / cnt[s] : 0.0;
        dside[s] = sum[s] * inv;
        for (int ch = 0; ch < 3; ch++) cside[s][ch] = cs[s][ch] * inv;
    }
    double tol = p->tol_k * p->sigma[m];
    tol = tol > 0.01 ? tol : 0.01;
    const int near0 = cnt[0] && fabs(dm - dside[0]) <= tol;
    const int near1 = cnt[1] && fabs(dm - dside[1]) <= tol;
    double axis[3], contrast = 0.0;
    for (int ch = 0; ch < 3; ch++) {
        axis[ch] = cside[1][ch] - cside[0][ch];
        contrast += axis[ch] * axis[ch];
    }
    const int sig = cnt[0] && cnt[1] && contrast > p->contrast;
    /* the side of every cell by its colour: t = 0 on side 0, 1 on side 1 */
    int all0 = 1, all1 = 1;
    for (int k = 0; k < p->ncells; k++) {
        const float *cell = p->cells ? p->cells + (ptrdiff_t)k * 3 * N : p->col;
        double t = 0.0;
        for (int ch = 0; ch < 3; ch++) t += (cell[ch * N + m] - cside[0][ch]) * axis[ch];
        t = contrast > 0.0 ? t / contrast : 0.5;
        all0 &= t < p->side;
        all1 &= t > 1.0 - p->side;
    }
    const int pure = sig && ((near0 && all0) || (near1 && all1));
    if (pure && p->unflag && p->ncells > 1) {
        /* The cells' colours place the edge to within a pixel at best (a Z pixel's colours
           are interpolated from the colour pixels around it): a pure measurement also needs
           every pixel bordering its Z pixel nearer its side's colour than the other's, else
           the depth edge may cross the Z pixel and it is flagged flying. */
        const int s1 = !(near0 && all0);
        int ring_ok = 1;
        for (int k = 0; k < p->nring; k++) {
            const float *px = p->ring + (ptrdiff_t)k * 3 * N;
            double t = 0.0;
            for (int ch = 0; ch < 3; ch++) t += (px[ch * N + m] - cside[0][ch]) * axis[ch];
            t /= contrast;                                /* contrast > 0: sig holds */
            ring_ok &= s1 ? t > 0.5 : t < 0.5;
        }
        if (ring_ok) return;
        p->flags[m] |= 8;
        return;
    }
    if (sig && (all0 || all1) && !near0 && !near1) {
        const double dn = all0 ? dside[0] : dside[1];
        p->flags[m] |= 32;
        p->depth_out[m] = dn;
        /* the side's depth under the validity's range test (below 0, within 5 sigma of
           max_range or beyond: out of range): a side may be an aliased surface */
        if (p->max_range == p->max_range && !((dn >= 0.0) & (dn <= p->max_range
                                                              - 5.0 * p->sigma[m])))
            p->flags[m] |= 16;
        return;
    }
    p->flags[m] |= 8;
}

int rgbz_tofg_usable(const uint8_t *flags, const double *depth, const double *sigma,
                     const uint8_t *present, uint8_t bad, ptrdiff_t N, uint8_t *usable,
                     int workers)
{
    if (!flags || !depth || !sigma || !usable || N < 0) return RGBZ_EINVAL;
    const int nth = rgbz_threads(workers);
    (void)nth;
    const ptrdiff_t B = 4096, nb = (N + B - 1) / B;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t b = 0; b < nb; b++)
        tofg_usable_span(flags, depth, sigma, present, bad, b * B, b * B + B < N ? b * B + B : N,
                         usable);
    return RGBZ_OK;
}

int rgbz_tofg_flying_candidates(const double *depth, const double *sigma,
                                const uint8_t *usable, ptrdiff_t R, ptrdiff_t C, double step,
                                double k, uint8_t *cand, int workers)
{
    if (!depth || !sigma || !usable || !cand || R < 0 || C < 0 || !(step >= 0.0)
        || !(k > 0.0) || !(k < INFINITY))
        return RGBZ_EINVAL;
    const tofg_fly_args p = {depth, sigma, usable, NULL, NULL, NULL, 0, 0, R, C, step * step,
                             k * k, 0.0, 0.0, 0.0, 0, NULL, NULL};
    uint8_t *code = malloc((size_t)(R * C > 0 ? R * C : 1));
    if (!code) return RGBZ_ENOMEM;
    const int nth = rgbz_threads(workers);
    (void)nth;
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t r = 0; r < R; r++) tofg_hit_row(&p, r, code);
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t r = 0; r < R; r++) {
        uint8_t *cr = cand + r * C;
        const uint8_t *u = usable + r * C;
        tofg_cand_row(&p, code, r, cr);
        for (ptrdiff_t c = 0; c < C; c++) cr[c] = (uint8_t)((u[c] != 0) & (cr[c] != 0));
    }
    free(code);
    return RGBZ_OK;
}

int rgbz_tofg_flying(const double *depth, const double *sigma, const uint8_t *usable,
                     const float *col, const float *cells, int ncells, const float *ring,
                     int nring, ptrdiff_t R, ptrdiff_t C, double step, double k,
                     double contrast, double side, int unflag, uint8_t *flags,
                     double *depth_out, double max_range, uint8_t *valid, int workers)
{
    if (!depth || !sigma || !usable || !col || !flags || !depth_out || ncells < 1
        || (ncells > 1 && !cells) || nring < 0 || (nring > 0 && !ring) || R < 0 || C < 0
        || !(step >= 0.0) || !(k >= 0.0))
        return RGBZ_EINVAL;
    const tofg_fly_args p = {depth, sigma, usable, col, ncells > 1 ? cells : NULL,
                             nring > 0 ? ring : NULL, ncells, nring, R, C, step * step, k * k,
                             2.5, contrast, side, unflag, flags, depth_out, max_range, valid};
    uint8_t *code = malloc((size_t)(R * C > 0 ? R * C : 1));
    if (!code) return RGBZ_ENOMEM;
    const int nth = rgbz_threads(workers);
    (void)nth;
    /* the copy of the depths row by row with the hits: one thread's copy of a fresh 24 MB
       array (its pages zeroed as it went) took 3-4 ms of a 3 M-measurement call */
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t r = 0; r < R; r++) {
        memcpy(depth_out + r * C, depth + r * C, (size_t)C * sizeof *depth_out);
        tofg_hit_row(&p, r, code);
    }
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel num_threads(nth) reduction(|:bad)
#endif
    {
        uint8_t *cand = malloc((size_t)(C > 0 ? C : 1));
        bad |= !cand;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t r = 0; r < R; r++) {
            if (!cand) continue;
            tofg_cand_row(&p, code, r, cand);
            const uint8_t *u = usable + r * C;
            for (ptrdiff_t c = 0; c < C; c++)
                if ((u[c] != 0) & cand[c]) tofg_fly_cell(&p, r, c);
            if (valid)          /* the row's flags are final: tofg_fly_cell writes its own */
                for (ptrdiff_t c = 0; c < C; c++) valid[r * C + c] = flags[r * C + c] == 0;
        }
        free(cand);
    }
    free(code);
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}

/* ------------------------------------------------------------------ upsampling */
/* the smallest colour weight of an upsampling candidate (exp(-36) = 2.3e-16 is cut to 0) */
#define TOFG_WC_MIN 1e-20f

/* A pixel between grid lines i and i + 1 (centres ctr, sorted) at fraction f of the way:
   lines clamped at the ends (f = 0 there). */
static void tofg_bracket(const double *ctr, ptrdiff_t n, double v, ptrdiff_t *i, float *f)
{
    ptrdiff_t lo = 0, hi = n;                        /* first centre > v */
    while (lo < hi) {
        const ptrdiff_t mid = lo + (hi - lo) / 2;
        if (ctr[mid] <= v) lo = mid + 1;
        else hi = mid;
    }
    if (lo == 0) { *i = 0; *f = 0.0f; return; }
    if (lo == n) { *i = n - 1; *f = 0.0f; return; }
    *i = lo - 1;
    *f = (float)((v - ctr[lo - 1]) / (ctr[lo] - ctr[lo - 1]));
}

typedef struct {
    const double *depth, *sigma;
    const float *col, *prior;
    ptrdiff_t R, C;
    const double *rc, *cc;
    double spacing;
    float inv2s2, inv2hc2, tol_k, tol_min;
} tofg_up_args;

/* the weight of a node without a depth whose own (low-signal) measurement no candidate
   agrees with: it takes part in a pixel's choice as a surface of unknown depth */
#define TOFG_VETO 1.0f

/* The depth at a point of colour pc (scaled) from the candidate measurements m[0..n) with
   spatial weights ws, each times its prior (1 measured, 0 none), among those within otol of
   own (every one when own is NaN): the depth of the heaviest (spatial times colour weight)
   and the weighted mean of those within max(tol_k sigma, tol_min) of it. Returns the summed
   weight of the mean (0: no usable candidate). */
static float tofg_up_mode(const tofg_up_args *p, const float *pc, const ptrdiff_t *m,
                          const float *ws, int n, double own, double otol, float *out)
{
    const ptrdiff_t N = p->R * p->C;
    float w[81], best = 0.0f;
    int kb = -1;
    for (int k = 0; k < n; k++) {
        const float pr = p->prior[m[k]] * ws[k];
        w[k] = 0.0f;
        if (!(pr > 0.0f)) continue;
        if (own == own && !(fabs(p->depth[m[k]] - own) <= otol)) continue;
        const float t0 = pc[0] - p->col[m[k]], t1 = pc[1] - p->col[N + m[k]];
        const float t2 = pc[2] - p->col[2 * N + m[k]];
        const float chi = (t0 * t0 + t1 * t1) + t2 * t2 - 3.0f;
        /* a colour weight never vanishes: where no candidate has the colour (a
           demosaicking artefact at an edge) the spatial weights decide */
        const float wc = tofg_exp_neg((chi > 0.0f ? chi : 0.0f) * p->inv2hc2);
        w[k] = pr * (wc > TOFG_WC_MIN ? wc : TOFG_WC_MIN);
        if (w[k] > best) { best = w[k]; kb = k; }
    }
    if (kb < 0) return 0.0f;
    const double db = p->depth[m[kb]];
    double tol = p->tol_k * p->sigma[m[kb]];
    tol = tol > p->tol_min ? tol : p->tol_min;
    double num = 0.0, den = 0.0;
    for (int k = 0; k < n; k++) {
        const double d = p->depth[m[k]];
        if (w[k] > 0.0f && fabs(d - db) <= tol) {
            num += w[k] * d;
            den += w[k];
        }
    }
    *out = (float)(num / den);
    return (float)den;
}

/* The spatial weights of the fill by offset (di, dj) in [-reach, reach]^2, into sw, when
   the grid lines are evenly spaced at multiples of half a pixel: every difference of
   centres is then exact, so the table holds bit for bit what tofg_fill_node would compute
   for each pair; sall[k]: the sum of the weights of the window of 2^k grid lines (k = 0, 1, 2,
   up to reach) in tofg_fill_node's order, for a window the grid does not clip. Returns 0 (sw
   and sall unused) for any other grid. */
static int tofg_fill_table(const tofg_up_args *p, ptrdiff_t reach, float *sw, float *sall)
{
    const double *ax[2] = {p->rc, p->cc};
    const ptrdiff_t n[2] = {p->R, p->C};
    for (int a = 0; a < 2; a++) {
        if (n[a] <= reach) return 0;
        const double step = n[a] > 1 ? ax[a][1] - ax[a][0] : 0.0;
        for (ptrdiff_t k = 0; k < n[a]; k++) {
            const double v = ax[a][k];
            if (!(fabs(v) < 1e9) || 2.0 * v != floor(2.0 * v)) return 0;
            if (k > 0 && v - ax[a][k - 1] != step) return 0;
        }
    }
    const ptrdiff_t side = 2 * reach + 1;
    for (ptrdiff_t di = -reach; di <= reach; di++) {
        const double ddy = di >= 0 ? p->rc[di] - p->rc[0] : p->rc[0] - p->rc[-di];
        const float dy = (float)(ddy / p->spacing);
        for (ptrdiff_t dj = -reach; dj <= reach; dj++) {
            const double ddx = dj >= 0 ? p->cc[dj] - p->cc[0] : p->cc[0] - p->cc[-dj];
            const float dx = (float)(ddx / p->spacing);
            sw[(di + reach) * side + (dj + reach)] = tofg_exp_neg((dy * dy + dx * dx)
                                                                  * p->inv2s2);
        }
    }
    for (ptrdiff_t lv = 1, k = 0; lv <= reach; lv *= 2, k++) {
        float all = 0.0f;
        for (ptrdiff_t di = -lv; di <= lv; di++)
            for (ptrdiff_t dj = -lv; dj <= lv; dj++)
                all += sw[(di + reach) * side + (dj + reach)];
        sall[k] = all;
    }
    return 1;
}

/* A node without a usable measurement takes the mode over the usable ones within 1, else 2,
   else 4 (at most `reach`) grid lines (Gaussian spatial weights, its own colour); its prior
   becomes a quarter of their normalised weight (0: none there). When the node has a
   measurement of its own too noisy to use (own finite), only candidates within own_k of its
   sigma of it take part, and a node that none agrees with gets no depth (NaN) at the weight
   TOFG_VETO: the pixels around it cannot take a neighbour's surface unchallenged. */
static void tofg_fill_node(const tofg_up_args *p, const float *prior0, const double *own,
                           double own_k, ptrdiff_t r, ptrdiff_t c, ptrdiff_t reach,
                           const float *sw, const float *sall, double *depth, double *sigma,
                           float *prior)
{
    const ptrdiff_t N = p->R * p->C, m = r * p->C + c, C = p->C, side = 2 * reach + 1;
    depth[m] = p->depth[m];
    sigma[m] = p->sigma[m];
    prior[m] = prior0[m];
    if (prior0[m] > 0.0f) return;
    const double om = own ? own[m] : NAN, otol = own_k * p->sigma[m];
    const float pc[3] = {p->col[m], p->col[N + m], p->col[2 * N + m]};
    const tofg_up_args q = {p->depth, p->sigma, p->col, prior0, p->R, p->C, p->rc, p->cc,
                            p->spacing, p->inv2s2, p->inv2hc2, p->tol_k, p->tol_min};
    for (ptrdiff_t lv = 1, k = 0; lv <= reach; lv *= 2, k++) {
        /* the usable candidates alone, in the window's order (tofg_up_mode gives the others
           no weight), and the sum of every node's spatial weight */
        ptrdiff_t mm[81];
        float ww[81], all = 0.0f, out;
        int n = 0;
        const ptrdiff_t i0 = r - lv > 0 ? r - lv : 0, i1 = r + lv < p->R - 1 ? r + lv : p->R - 1;
        const ptrdiff_t j0 = c - lv > 0 ? c - lv : 0, j1 = c + lv < C - 1 ? c + lv : C - 1;
        if (sw) {
            for (ptrdiff_t i = i0; i <= i1; i++) {
                const float *pr = prior0 + i * C, *row = sw + (i - r + reach) * side + reach;
                for (ptrdiff_t j = j0; j <= j1; j++)
                    if (pr[j] > 0.0f) {
                        mm[n] = i * C + j;
                        ww[n++] = row[j - c];
                    }
            }
            if (!n) continue;                    /* nothing usable this far: look farther */
            if (i1 - i0 == 2 * lv && j1 - j0 == 2 * lv) {
                all = sall[k];
            } else {
                for (ptrdiff_t i = i0; i <= i1; i++) {
                    const float *row = sw + (i - r + reach) * side + reach;
                    for (ptrdiff_t j = j0; j <= j1; j++) all += row[j - c];
                }
            }
        } else {
            for (ptrdiff_t i = i0; i <= i1; i++) {
                const float dy = (float)((p->rc[i] - p->rc[r]) / p->spacing);
                for (ptrdiff_t j = j0; j <= j1; j++) {
                    const float dx = (float)((p->cc[j] - p->cc[c]) / p->spacing);
                    const float w = tofg_exp_neg((dy * dy + dx * dx) * p->inv2s2);
                    all += w;
                    if (prior0[i * C + j] > 0.0f) {
                        mm[n] = i * C + j;
                        ww[n++] = w;
                    }
                }
            }
            if (!n) continue;
        }
        const float got = tofg_up_mode(&q, pc, mm, ww, n, om, otol, &out);
        if (got > 0.0f) {
            int kb = 0;                          /* the usable candidate nearest the depth */
            for (int t = 1; t < n; t++)
                if (fabs(p->depth[mm[t]] - out) < fabs(p->depth[mm[kb]] - out)) kb = t;
            depth[m] = out;
            sigma[m] = p->sigma[mm[kb]];
            prior[m] = 0.25f * got / all;
            return;
        }
    }
    if (om == om) {
        depth[m] = NAN;
        prior[m] = TOFG_VETO;
    }
}

/* pixels per chunk of the pixel loop (tofg_up_span) */
#define TOFG_UPB 64

/* The pixels x0 .. x0 + n - 1 (n <= TOFG_UPB) of a row of pixels between grid rows r and r + 1
   (r at the last) at fraction fy, colours pc[ch][j] (scaled): each takes the 4 nodes around it
   with bilinear weights (the filled nodes at their prior), the rule of tofg_up_mode written
   out for four candidates; NaN where the heaviest node has no depth (a veto node) or the
   nodes outside the chosen surface hold more than `ambiguity` of the weight (the colour
   cannot say which surface the pixel is on); a node counts as off it when its depth lies
   more than max(gap, the mean's tolerance) from the chosen one, or it has none (a slanted
   surface's nodes differ by more than the tolerance without being another surface).
   Branch-free, in two loops over the pixels that vectorise (the nodes by gathers): the
   weights and the heaviest node in float, then the mean and the ambiguity in double; every
   weight, sum and comparison is the scalar rule's, in its order (a node without weight adds
   exact zeros). */
RGBZ_CLONES_512 static void tofg_up_span(const tofg_up_args *p, float ambiguity, double gap,
                                         ptrdiff_t r, float fy, const int32_t *restrict cx,
                                         const float *restrict fx, ptrdiff_t x0, ptrdiff_t n,
                                         float pc[3][TOFG_UPB], float *restrict out,
                                         float *restrict conf)
{
    /* the nodes by their column (int32: gathers of 32-bit indices vectorise) in the rows of
       the two grid lines; dr: the second line's offset from the first (0 at the last) */
    const ptrdiff_t C = p->C, N = p->R * C, r1 = r + 1 < p->R ? r + 1 : r;
    const int32_t dr = (int32_t)((r1 - r) * C);
    const float *restrict pr0 = p->prior + r * C, *restrict pr1 = p->prior + r1 * C;
    const float *restrict a0 = p->col + r * C, *restrict a1 = a0 + N, *restrict a2 = a1 + N;
    const float *restrict b0 = p->col + r1 * C, *restrict b1 = b0 + N, *restrict b2 = b1 + N;
    const double *restrict d0 = p->depth + r * C, *restrict d1 = p->depth + r1 * C;
    const double *restrict sg0 = p->sigma + r * C;
    const float ihc = p->inv2hc2, gy = 1.0f - fy;
    const double tol_k = p->tol_k, tol_min = p->tol_min;
    float w0[TOFG_UPB], w1[TOFG_UPB], w2[TOFG_UPB], w3[TOFG_UPB];
    int32_t kb[TOFG_UPB], ca[TOFG_UPB], cb[TOFG_UPB];
    for (ptrdiff_t j = 0; j < n; j++) {
        const int32_t c = cx[x0 + j], c1 = c + 1 < C ? c + 1 : c;
        ca[j] = c;
        cb[j] = c1;
        const float f = fx[x0 + j], g = 1.0f - f;
        const float q0 = pc[0][j], q1 = pc[1][j], q2 = pc[2][j];
        float wk[4];
        /* the weight of node k: spatial ws times its prior times the colour weight; none on
           a grid line (Mask1: 3 pixels in 4) nor from a hole */
#define TOFG_UP_W(k, ws, prv, e0, e1, e2, i)                                                  \
        {                                                                                      \
            const float pr = prv[i] * (ws);                                                    \
            const float t0 = q0 - e0[i], t1 = q1 - e1[i], t2 = q2 - e2[i];                     \
            const float chi = (t0 * t0 + t1 * t1) + t2 * t2 - 3.0f;                            \
            const float wc = tofg_exp_neg((chi > 0.0f ? chi : 0.0f) * ihc);                    \
            wk[k] = pr > 0.0f ? pr * (wc > TOFG_WC_MIN ? wc : TOFG_WC_MIN) : 0.0f;            \
        }
        TOFG_UP_W(0, gy * g, pr0, a0, a1, a2, c)
        TOFG_UP_W(1, gy * f, pr0, a0, a1, a2, c1)
        TOFG_UP_W(2, fy * g, pr1, b0, b1, b2, c)
        TOFG_UP_W(3, fy * f, pr1, b0, b1, b2, c1)
#undef TOFG_UP_W
        float best = 0.0f;
        int32_t kbest = -1;
        for (int k = 0; k < 4; k++) {
            kbest = wk[k] > best ? k : kbest;
            best = wk[k] > best ? wk[k] : best;
        }
        w0[j] = wk[0];
        w1[j] = wk[1];
        w2[j] = wk[2];
        w3[j] = wk[3];
        kb[j] = kbest;
    }
    for (ptrdiff_t j = 0; j < n; j++) {
        const int32_t k = kb[j], c = ca[j], c1 = cb[j];
        const double dk[4] = {d0[c], d0[c1], d1[c], d1[c1]};
        const float wk[4] = {w0[j], w1[j], w2[j], w3[j]};
        const double db = (k & 2) ? ((k & 1) ? dk[3] : dk[2]) : ((k & 1) ? dk[1] : dk[0]);
        double tol = tol_k * sg0[((k & 2) ? dr : 0) + ((k & 1) ? c1 : c)];
        tol = tol > tol_min ? tol : tol_min;
        const double off = gap > tol ? gap : tol;
        double num = 0.0, den = 0.0, other = 0.0;
        for (int q = 0; q < 4; q++) {
            const double d = dk[q], wq = wk[q], e = fabs(d - db);
            const int in = (wk[q] > 0.0f) & (e <= tol);
            num += in ? wq * d : 0.0;
            den += in ? wq : 0.0;
            other += (!in & !(e <= off)) ? wq : 0.0;        /* true for a veto node's NaN */
        }
        const int none = (k < 0) | (db != db) | (other > ambiguity * (den + other));
        out[x0 + j] = none ? NAN : (float)(num / den);
        conf[x0 + j] = none ? 0.0f : (float)den;          /* the bilinear weights sum to 1 */
    }
}

int rgbz_tofg_agree(double *depth, double *low, const uint8_t *lone, const double *sigma,
                    ptrdiff_t R, ptrdiff_t C, double tol_k, double tol_min, int workers)
{
    if (!depth || !low || !lone || !sigma || R < 0 || C < 0 || !(tol_k >= 0.0)
        || !(tol_min >= 0.0))
        return RGBZ_EINVAL;
    const int nth = rgbz_threads(workers);
    (void)nth;
    /* a node writes only itself, and only when lone; it reads the depths of nodes that are
       not lone, which nobody writes: rows in parallel */
    RGBZ_PARALLEL_FOR
    for (ptrdiff_t r = 0; r < R; r++) {
        const ptrdiff_t i0 = r > 0 ? r - 1 : 0, i1 = r + 1 < R ? r + 1 : R - 1;
        for (ptrdiff_t c = 0; c < C; c++) {
            const ptrdiff_t m = r * C + c;
            const double d = low[m];
            if (!lone[m] || d != d) continue;
            double tol = tol_k * sigma[m];
            tol = tol > tol_min ? tol : tol_min;
            const ptrdiff_t j0 = c > 0 ? c - 1 : 0, j1 = c + 1 < C ? c + 1 : C - 1;
            int ok = 0;
            for (ptrdiff_t i = i0; i <= i1 && !ok; i++)
                for (ptrdiff_t j = j0; j <= j1; j++) {
                    const ptrdiff_t n = i * C + j;
                    if (n != m && !lone[n] && fabs(depth[n] - d) <= tol) {   /* NaN: false */
                        ok = 1;
                        break;
                    }
                }
            if (ok) {
                depth[m] = d;
                low[m] = NAN;
            }
        }
    }
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ the element types */
/* prepare, colour and upsample for every element type (tof_guided.template.h), and the entry
   points that call the instance of in_type */
#define RGBZ_TYPE_TEMPLATE "tof_guided.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

int rgbz_tofg_prepare(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N, double gain,
                      double black, double supp, double const_var, double prnu, double white,
                      float *zr, float *zi, float *v, uint8_t *sat, double *offset,
                      double fixed_var, float *phi, int workers)
{
#define TOFG_PREPARE_(s, T)                                                                  \
    return RGBZ_CAT(tofg_prepare, s)((const T *)taps, F, N, gain, black, supp, const_var,    \
                                     prnu, white, zr, zi, v, sat, offset, fixed_var, phi,    \
                                     workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, TOFG_PREPARE_, return RGBZ_EINVAL)
#undef TOFG_PREPARE_
}

static void tofg_prep_span(const tofg_prep_in *q, ptrdiff_t F, ptrdiff_t N, ptrdiff_t m0,
                           ptrdiff_t n, float *zr, float *zi, ptrdiff_t os, float *v,
                           uint8_t *hit, double *offset, float *phi)
{
#define TOFG_PREP_SPAN_(s, T)                                                                \
    RGBZ_CAT(tofg_prepare_span, s)(q, F, N, m0, n, zr, zi, os, v, hit, offset, phi)
    RGBZ_SWITCH_TYPE(q->in_type, RGBZ_ELEMENT_TYPES, TOFG_PREP_SPAN_, break)
#undef TOFG_PREP_SPAN_
}

int rgbz_tofg_colour(int in_type, const void *guide, ptrdiff_t H, ptrdiff_t W,
                     const int64_t *row_px, ptrdiff_t R, const int64_t *col_px, ptrdiff_t C,
                     int block, double scale, float *col, float *cells, double *lap,
                     double floor, double *sigma, int workers)
{
#define TOFG_COLOUR_(s, T)                                                                   \
    return RGBZ_CAT(tofg_colour, s)((const T *)guide, H, W, row_px, R, col_px, C, block,     \
                                    scale, col, cells, lap, floor, sigma, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, TOFG_COLOUR_, return RGBZ_EINVAL)
#undef TOFG_COLOUR_
}

int rgbz_tofg_ring(int in_type, const void *guide, ptrdiff_t H, ptrdiff_t W,
                   const int64_t *row_px, ptrdiff_t R, const int64_t *col_px, ptrdiff_t C,
                   int block, const double *inv, float *ring, int workers)
{
#define TOFG_RING_(s, T)                                                                     \
    return RGBZ_CAT(tofg_ring, s)((const T *)guide, H, W, row_px, R, col_px, C, block, inv,  \
                                  ring, workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, TOFG_RING_, return RGBZ_EINVAL)
#undef TOFG_RING_
}

int rgbz_tofg_upsample(int in_type, const void *guide, ptrdiff_t H, ptrdiff_t W, double scale,
                       const double *cscale, const double *depth, const double *sigma,
                       const float *col, ptrdiff_t R, ptrdiff_t C, const double *rc,
                       const double *cc, double spacing, ptrdiff_t reach, double inv2s2,
                       double inv2hc2, double tol_k, double tol_min, const double *own,
                       double own_k, double ambiguity, double gap, float *out, float *conf,
                       int workers)
{
#define TOFG_UPSAMPLE_(s, T)                                                                 \
    return RGBZ_CAT(tofg_upsample, s)((const T *)guide, H, W, scale, cscale, depth, sigma,   \
                                      col, R, C, rc, cc, spacing, reach, inv2s2, inv2hc2,    \
                                      tol_k, tol_min, own, own_k, ambiguity, gap, out, conf, \
                                      workers)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, TOFG_UPSAMPLE_, return RGBZ_EINVAL)
#undef TOFG_UPSAMPLE_
}
