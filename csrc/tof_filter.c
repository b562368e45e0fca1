/*
 * tof_filter.c -- the edge-aware (bilateral) mean of the ToF phasors over the Z
 * measurements of a window: one pass of rgbz_fast.tof.denoise_phasors_bilateral.
 *
 * Algorithm (Tomasi & Manduchi 1998, with a range kernel measured against the
 * sensor's noise): for the measurement at grid cell (r, c) and every neighbour
 * (r + a, c + b), |a| <= reach_rows, |b| <= reach_cols, that lies within radius_px pixels in rows
 * and in columns and is usable,
 *     chi = sum_f |g_f(nb) - g_f(centre)|^2 / (gv_f(nb) + gv_f(centre)),
 *     x   = 0.5 * inv_h2 * (chi - 2F),
 *     w   = 1 if x <= 0, exp(-x) if x < 36, else 0 (below 2.3e-16: no exp() call),
 *     out_f = sum w z_f(nb) / sum w,  out_var_f = sum w^2 var_f(nb) / (sum w)^2,
 *     neff  = (sum w)^2 / sum w^2,
 * with g the guide phasors (the raw ones, or a first pass's output) and gv the
 * variance of each of their components. Every sum runs over the offsets in the
 * order a = -reach_rows..reach_rows, then b = -reach_cols..reach_cols, and chi over f = 0..F-1: the
 * order of the NumPy reference (tests/_reference/tof.py), which it matches to
 * rounding (libm's exp against NumPy's). A cell that no usable neighbour reaches
 * gets out = 0, out_var = +inf, neff = 0.
 *
 * Layout: the grid of the Z measurements (one cell per distinct row and column of
 * their sites), planar and row-major: z_re, z_im, var, g_re, g_im, g_var, out_re,
 * out_im, out_var are (nfreq, rows, cols); use (rows, cols), 1 = usable; row_px
 * (rows) and col_px (cols) the pixel coordinates of the grid lines; out_neff
 * (rows, cols).
 *
 * Speed: one grid row at a time, each offset a loop over the row's cells (chi and
 * the accumulations vectorise; exp() is called only where chi > 2F). Where
 * rgbz_exp_libm_vectorised(0) has found that rgbz_exp.h's port of glibc's exp()
 * gives this machine's bits (AVX-512F), the exponentials of a row segment run
 * through it eight at a time instead of one call each, and the row loops have
 * AVX-512F and AVX2 clones (RGBZ_CLONES_512: the same operations, so the same
 * bits). Threads: OpenMP over grid rows, each with its own scratch; every cell
 * is computed alone, so the result does not depend on the thread count.
 */
/* As in tof.c: no FP trap is ever enabled, so GCC may vectorise the selects. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math")
#endif
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"
#include "rgbz_templating.h"
#include "rgbz_exp.h"
#include "rgbz_ops.h"
#include "tof_filter.h"

/* weights below exp(-36) = 2.3e-16 are 0: they cannot change a mean of doubles, and
   skipping exp() there (the far side of every edge) halves the time of a pass */
#define RGBZ_TOF_FILTER_CUT 36.0

typedef struct {
    const double *z_re, *z_im, *var, *g_re, *g_im, *g_var;
    const uint8_t *use;
    const int64_t *row_px, *col_px;
    ptrdiff_t nfreq, rows, cols, reach_rows, reach_cols;
    int64_t radius_px;
    double inv_h2;
    double *out_re, *out_im, *out_var, *out_neff;
    int vec_exp;                    /* rgbz_exp_libm_vectorised(0): the port's exp rows */
} filter_args;

/* w[c] for c in [c0, c1) from chi[c] (see the top), the neighbour's usability and distance:
   exp() by the vector port, arg[] its scratch. The port does not cover 0 < x < 2^-54: those
   cells take exp(-0) = 1 from it, which is exp(-x) there (glibc returns 1.0 + x, rounded
   to 1.0 below 2^-54; tests/tof/test_filters.py puts chi one ulp above 2F). */
#ifdef RGBZ_HAVE_EXP_VEC
static inline __attribute__((always_inline)) void filter_weights_vec(
    const filter_args *p, ptrdiff_t b, ptrdiff_t c0, ptrdiff_t c1, ptrdiff_t row_n,
    double bias, const double *restrict chi, double *restrict arg, double *restrict w)
{
    const double k = 0.5 * p->inv_h2;
    const int64_t *restrict cpx = p->col_px, rad = p->radius_px;
    const uint8_t *restrict use = p->use + row_n + b;
    for (ptrdiff_t c = c0; c < c1; c++) {
        const double x = k * (chi[c] - bias);
        const int in = x >= 0x1p-54 && x < RGBZ_TOF_FILTER_CUT;   /* the port covers -x */
        arg[c] = in ? -x : 0.0;
    }
    rgbz_exp_glibc_row(arg + c0, c1 - c0);
    for (ptrdiff_t c = c0; c < c1; c++) {
        const int64_t dc = cpx[c + b] - cpx[c];
        const int ok = (dc >= -rad) & (dc <= rad) & (use[c] != 0);
        const double x = k * (chi[c] - bias);
        const double wc = x > 0.0 ? (x < RGBZ_TOF_FILTER_CUT ? arg[c] : 0.0) : 1.0;
        w[c] = ok ? wc : 0.0;
    }
}
#endif

/* the sums of one frequency and offset: n += w z, w^2 v on the cells [c0, c1) (restrict
   parameters: GCC vectorises the loop) */
static inline __attribute__((always_inline)) void filter_accumulate(
    const double *restrict w, const double *restrict zr, const double *restrict zi,
    const double *restrict v, double *restrict nr, double *restrict ni, double *restrict nv,
    ptrdiff_t c0, ptrdiff_t c1)
{
    for (ptrdiff_t c = c0; c < c1; c++) {
        nr[c] += w[c] * zr[c];
        ni[c] += w[c] * zi[c];
        nv[c] += (w[c] * w[c]) * v[c];
    }
}

/* scratch of one row: num_re, num_im, w2v (nfreq * cols each), den, w2, chi, w, arg (cols) */
RGBZ_CLONES_512 static void filter_row(const filter_args *p, ptrdiff_t r, double *scratch)
{
    const ptrdiff_t F = p->nfreq, C = p->cols, plane = p->rows * p->cols;
    const double bias = 2.0 * (double)F;
    /* disjoint parts of the scratch (restrict: the loops below vectorise) */
    double *restrict num_re = scratch, *restrict num_im = num_re + F * C;
    double *restrict w2v = num_im + F * C, *restrict den = w2v + F * C;
    double *restrict w2 = den + C, *restrict chi = w2 + C, *restrict w = chi + C;
    double *restrict arg = w + C;
    (void)arg;
    for (ptrdiff_t k = 0; k < 3 * F * C + 2 * C; k++) scratch[k] = 0.0;
    for (ptrdiff_t a = -p->reach_rows; a <= p->reach_rows; a++) {
        const ptrdiff_t rr = r + a;
        if (rr < 0 || rr >= p->rows) continue;
        const int64_t dr = p->row_px[rr] - p->row_px[r];
        if (dr < -p->radius_px || dr > p->radius_px) continue;
        const ptrdiff_t row_c = r * C, row_n = rr * C;
        for (ptrdiff_t b = -p->reach_cols; b <= p->reach_cols; b++) {
            const ptrdiff_t c0 = b < 0 ? -b : 0, c1 = b > 0 ? C - b : C;
            if (c1 <= c0) continue;
            /* chi over the frequencies, in order */
            for (ptrdiff_t c = c0; c < c1; c++) chi[c] = 0.0;
            for (ptrdiff_t f = 0; f < F; f++) {
                const double *restrict gr = p->g_re + f * plane;
                const double *restrict gi = p->g_im + f * plane;
                const double *restrict gv = p->g_var + f * plane;
                for (ptrdiff_t c = c0; c < c1; c++) {
                    const double dre = gr[row_n + c + b] - gr[row_c + c];
                    const double dim = gi[row_n + c + b] - gi[row_c + c];
                    chi[c] += (dre * dre + dim * dim) / (gv[row_n + c + b] + gv[row_c + c]);
                }
            }
            /* the weights: usable neighbours within the radius; exp only above 2F */
#ifdef RGBZ_HAVE_EXP_VEC
            if (p->vec_exp) {
                filter_weights_vec(p, b, c0, c1, row_n, bias, chi, arg, w);
            } else
#endif
            for (ptrdiff_t c = c0; c < c1; c++) {
                const int64_t dc = p->col_px[c + b] - p->col_px[c];
                const int near = dc >= -p->radius_px && dc <= p->radius_px;
                const double x = 0.5 * p->inv_h2 * (chi[c] - bias);
                double wc = x > 0.0 ? (x < RGBZ_TOF_FILTER_CUT ? exp(-x) : 0.0) : 1.0;
                w[c] = (near && p->use[row_n + c + b]) ? wc : 0.0;
            }
            for (ptrdiff_t f = 0; f < F; f++)
                filter_accumulate(w, p->z_re + f * plane + row_n + b,
                                  p->z_im + f * plane + row_n + b,
                                  p->var + f * plane + row_n + b, num_re + f * C,
                                  num_im + f * C, w2v + f * C, c0, c1);
            for (ptrdiff_t c = c0; c < c1; c++) {
                den[c] += w[c];
                w2[c] += w[c] * w[c];
            }
        }
    }
    for (ptrdiff_t c = 0; c < C; c++) {
        const ptrdiff_t cell = r * C + c;
        const int ok = den[c] > 0.0;
        const double inv = ok ? 1.0 / den[c] : 0.0;
        for (ptrdiff_t f = 0; f < F; f++) {
            p->out_re[f * plane + cell] = num_re[f * C + c] * inv;
            p->out_im[f * plane + cell] = num_im[f * C + c] * inv;
            p->out_var[f * plane + cell] = ok ? w2v[f * C + c] * (inv * inv) : HUGE_VAL;
        }
        p->out_neff[cell] = w2[c] > 0.0 ? den[c] * den[c] / w2[c] : 0.0;
    }
}

int rgbz_tof_bilateral(const double *z_re, const double *z_im, const double *var,
                       const double *g_re, const double *g_im, const double *g_var,
                       const uint8_t *use, const int64_t *row_px, const int64_t *col_px,
                       ptrdiff_t nfreq, ptrdiff_t rows, ptrdiff_t cols,
                       ptrdiff_t reach_rows, ptrdiff_t reach_cols, int64_t radius_px, double inv_h2,
                       double *out_re, double *out_im, double *out_var, double *out_neff,
                       int workers)
{
    if (!z_re || !z_im || !var || !g_re || !g_im || !g_var || !use || !row_px || !col_px
        || !out_re || !out_im || !out_var || !out_neff || rows < 0 || cols < 0 || nfreq < 1
        || nfreq > RGBZ_TOF_MAX_FREQS || reach_rows < 0 || reach_cols < 0 || radius_px < 0 || !(inv_h2 >= 0.0))
        return RGBZ_EINVAL;
    const filter_args p = {z_re, z_im, var, g_re, g_im, g_var, use, row_px, col_px, nfreq,
                           rows, cols, reach_rows, reach_cols, radius_px, inv_h2, out_re, out_im, out_var,
                           out_neff, rgbz_exp_libm_vectorised(0)};
    const size_t per_row = (size_t)(3 * nfreq + 5) * (size_t)(cols > 0 ? cols : 1);
    int status = RGBZ_OK;
#ifdef _OPENMP
#pragma omp parallel num_threads(workers > 0 ? workers : omp_get_max_threads())
#endif
    {
        double *scratch = malloc(per_row * sizeof(double));
        if (!scratch) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ENOMEM;
        }
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t r = 0; r < rows; r++)
            if (scratch) filter_row(&p, r, scratch);
        free(scratch);
    }
    (void)workers;
    return status;
}

/* ------------------------------------------------------------------ box mean (paper Fig. 17) */

/* tmp[c] = the row sum of v (= in * weight) at grid row r over the row offsets (tof_filter.h) */
static void box_rows(const double *in, const double *weight, ptrdiff_t R, ptrdiff_t C,
                     const int64_t *row_px, const int64_t *offs, ptrdiff_t n_offs,
                     int64_t radius, ptrdiff_t r, double *restrict tmp)
{
    for (ptrdiff_t c = 0; c < C; c++) tmp[c] = 0.0;
    for (ptrdiff_t k = 0; k < n_offs; k++) {
        const ptrdiff_t rr = r + (ptrdiff_t)offs[k];
        if (rr < 0 || rr >= R) continue;
        const int64_t d = row_px[rr] - row_px[r];
        const double ok = d >= -radius && d <= radius ? 1.0 : 0.0;
        const double *restrict v = in + rr * C;
        if (weight) {
            const double *restrict w = weight + rr * C;
            for (ptrdiff_t c = 0; c < C; c++) tmp[c] += (v[c] * w[c]) * ok;
        } else {
            for (ptrdiff_t c = 0; c < C; c++) tmp[c] += v[c] * ok;
        }
    }
}

/* out[c] = the column sum of tmp over the column offsets, times scale[c] (or not: NULL) */
static void box_cols(const double *restrict tmp, ptrdiff_t C, const int64_t *restrict col_px,
                     const int64_t *offs, ptrdiff_t n_offs, int64_t radius,
                     const double *restrict scale, double *restrict out)
{
    for (ptrdiff_t c = 0; c < C; c++) out[c] = 0.0;
    for (ptrdiff_t k = 0; k < n_offs; k++) {
        const ptrdiff_t b = (ptrdiff_t)offs[k];
        const ptrdiff_t c0 = b < 0 ? -b : 0, c1 = b > 0 ? C - b : C;
        for (ptrdiff_t c = c0; c < c1; c++) {
            const int64_t d = col_px[c + b] - col_px[c];
            out[c] += tmp[c + b] * (d >= -radius && d <= radius ? 1.0 : 0.0);
        }
    }
    if (scale)
        for (ptrdiff_t c = 0; c < C; c++) out[c] *= scale[c];
}

int rgbz_tof_box(const double *const *in, double *const *out, ptrdiff_t P, ptrdiff_t R,
                 ptrdiff_t C, const int64_t *row_px, const int64_t *col_px,
                 const int64_t *row_offs, ptrdiff_t n_row_offs, const int64_t *col_offs,
                 ptrdiff_t n_col_offs, int64_t radius, const double *weight, double *count,
                 int workers)
{
    if (!in || !out || !row_px || !col_px || !count || P < 0 || R < 0 || C < 0 ||
        n_row_offs < 0 || n_col_offs < 0 || (n_row_offs && !row_offs) ||
        (n_col_offs && !col_offs) || radius < 0)
        return RGBZ_EINVAL;
    for (ptrdiff_t p = 0; p < P; p++)
        if (!in[p] || !out[p]) return RGBZ_EINVAL;
    if (R == 0 || C == 0) return RGBZ_OK;
    int status = RGBZ_OK;
#ifdef _OPENMP
#pragma omp parallel num_threads(workers > 0 ? workers : omp_get_max_threads())
#endif
    {
        double *buf = malloc((size_t)(2 * C) * sizeof(double));
        if (!buf) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ENOMEM;
        }
        double *tmp = buf, *inv = buf + C;
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t r = 0; r < R; r++) {
            if (!buf) continue;
            /* the count: the sums of the weights (of ones), then its reciprocal */
            if (weight) {
                box_rows(weight, NULL, R, C, row_px, row_offs, n_row_offs, radius, r, tmp);
            } else {                       /* the row sums of ones: the same in every column */
                double ones = 0.0;
                for (ptrdiff_t k = 0; k < n_row_offs; k++) {
                    const ptrdiff_t rr = r + (ptrdiff_t)row_offs[k];
                    if (rr < 0 || rr >= R) continue;
                    const int64_t d = row_px[rr] - row_px[r];
                    ones += d >= -radius && d <= radius ? 1.0 : 0.0;
                }
                for (ptrdiff_t c = 0; c < C; c++) tmp[c] = ones;
            }
            double *cnt = count + r * C;
            box_cols(tmp, C, col_px, col_offs, n_col_offs, radius, NULL, cnt);
            for (ptrdiff_t c = 0; c < C; c++) inv[c] = cnt[c] > 0.0 ? 1.0 / cnt[c] : 0.0;
            for (ptrdiff_t p = 0; p < P; p++) {
                box_rows(in[p], weight, R, C, row_px, row_offs, n_row_offs, radius, r, tmp);
                box_cols(tmp, C, col_px, col_offs, n_col_offs, radius, inv, out[p] + r * C);
            }
        }
        free(buf);
    }
    return status;
}

/* ------------------------------------------------------------------ phasors, tap noise */

#define TOF_PO_(s, T, code, A)                                                              \
    static void tof_po_##s(const T *t, ptrdiff_t F, ptrdiff_t N, double *i, double *q,        \
                           double *offset, int nt)                                          \
    {                                                                                       \
        (void)nt;                                                                           \
        for (ptrdiff_t f = 0; f < F; f++) {                                                 \
            const T *restrict a0 = t + (4 * f) * N, *restrict a1 = a0 + N;                   \
            const T *restrict a2 = a1 + N, *restrict a3 = a2 + N;                            \
            double *restrict pi = i + f * N, *restrict pq = q + f * N;                       \
            double *restrict po = offset + f * N;                                            \
            TOF_PARALLEL_FOR                                                                \
            for (ptrdiff_t n = 0; n < N; n++) {                                             \
                const double v0 = (double)a0[n], v1 = (double)a1[n];                        \
                const double v2 = (double)a2[n], v3 = (double)a3[n];                        \
                pi[n] = v0 - v2;                                                            \
                pq[n] = v3 - v1;                                                            \
                po[n] = ((v0 + v1) + (v2 + v3)) * 0.25;                                     \
            }                                                                               \
        }                                                                                   \
    }
#ifdef _OPENMP
#define TOF_PARALLEL_FOR _Pragma("omp parallel for schedule(static) num_threads(nt)")
#else
#define TOF_PARALLEL_FOR
#endif
RGBZ_ELEMENT_TYPES(TOF_PO_, _)
#undef TOF_PO_

int rgbz_tof_phasors_offset(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N, double *i,
                            double *q, double *offset, int workers)
{
    if (!taps || !i || !q || !offset || F < 1 || N < 0) return RGBZ_EINVAL;
    const int nt = workers > 0 ? workers : 1;
    int st = RGBZ_OK;
#define TOF_PO_CALL_(s, T) tof_po_##s((const T *)taps, F, N, i, q, offset, nt)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, TOF_PO_CALL_, st = RGBZ_EINVAL)
#undef TOF_PO_CALL_
    return st;
}

int rgbz_tof_tap_variance(const double *offset, ptrdiff_t N, double black, double k,
                          double supp, double readout, double prnu, double scale,
                          const double *count, ptrdiff_t count_period, double *out,
                          int workers)
{
    if (!offset || !out || N < 0 || (count && count_period < 1)) return RGBZ_EINVAL;
    const int nt = workers > 0 ? workers : 1;
    const double twelfth = 1.0 / 12.0;
    (void)nt;
    TOF_PARALLEL_FOR
    for (ptrdiff_t n = 0; n < N; n++) {
        double h = offset[n] - black;
        h = (h >= 0.0 || h != h) ? h : 0.0;          /* np.maximum(h, 0): NaN stays */
        double v = h * k;
        if (supp != 0.0) v /= supp;
        v += readout;
        v += twelfth;
        if (prnu != 0.0) {
            h *= prnu;
            v += h * h;
        }
        v = scale * v;
        if (count) {
            const double c = count[n % count_period];
            v /= (c >= 1.0 || c != c) ? c : 1.0;      /* np.maximum(count, 1.0) */
        }
        out[n] = v;
    }
    return RGBZ_OK;
}
#undef TOF_PARALLEL_FOR

/* ------------------------------------------------------------------ validity (unguided ISP) */
/*
 * snr, sigma, the implied reflectance and the validity bits but the flying one of the
 * measurements n in [n0, n1): the NumPy operations of rgbz_fast.tof's unguided chain in their
 * order (tests/_reference/tof.py, unguided_validity), so the same bits.
 */
static void validity_block(const rgbz_tof_validity_args *p, ptrdiff_t n0, ptrdiff_t n1)
{
    const ptrdiff_t F = p->F, N = p->N;
    const double cap = p->phase_var_cap;
    for (ptrdiff_t n = n0; n < n1; n++) {
        /* snr = min_f 2 amp / sqrt(var), NaN if any is NaN (np.min) */
        double snr = 0.0, t = 0.0, rho = 0.0;
        int nan = 0, low_amp = 0, capped = 0;
        const double dep = p->depth[n];
        const int ok = dep > 0.0;
        const double d = ok ? dep : 1.0;
        /* the electrons of a reflectance-1 surface at d (ToFSensor.active_electrons), times
           block^2 */
        const double s1 = p->power / (4.0 * d * d * p->tan_h * p->tan_v) * p->k_cell;
        const double cells = s1 * p->block * p->block;
        for (ptrdiff_t f = 0; f < F; f++) {
            const double a = p->amp[f * N + n], v = p->var[f * N + n];
            const double x = 2.0 * a / sqrt(v);
            nan |= x != x;
            snr = f == 0 ? x : (x < snr ? x : snr);
            low_amp |= a < p->min_amplitude;
            /* the phase variance var / |I + iQ|^2, capped (fmin: a NaN takes the cap) */
            double ph = v / (a * a * 4.0);
            capped |= !(ph < cap);
            ph = fmin(ph, cap) * p->sigma_scale[f];
            t = f == 0 ? ph : t + ph;
            const double q = a / (p->refl_coef[f] * cells);
            rho = f == 0 ? q : rho + q;
        }
        if (nan) snr = NAN;
        if (p->delta && !capped) {
            const double td = t + p->delta[n];
            t = td > 0.0 ? td : t;
        }
        const double sigma = sqrt(t);
        const double refl = ok ? rho / (double)F : 0.0;
        uint8_t fl = p->saturated[n] ? 1 : 0;
        int low = (snr < p->min_snr) | low_amp;
        if (p->max_sigma >= 0.0) low |= !(sigma <= p->max_sigma);
        fl |= low ? 2 : 0;
        fl |= p->residual[n] > p->max_residual ? 4 : 0;
        fl |= ((dep < 0.0) | (dep > p->max_range - 5.0 * sigma) | (refl < p->min_reflectance)
               | (refl > p->max_reflectance)) ? 16 : 0;
        p->snr[n] = snr;
        p->sigma[n] = sigma;
        p->refl[n] = refl;
        p->flags[n] = fl;
    }
}

int rgbz_tof_validity(const rgbz_tof_validity_args *p, int workers)
{
    if (!p || !p->amp || !p->var || !p->depth || !p->residual || !p->saturated
        || !p->sigma_scale || !p->refl_coef || !p->snr || !p->sigma || !p->refl || !p->flags
        || p->F < 1 || p->N < 0)
        return RGBZ_EINVAL;
    const ptrdiff_t B = 4096, nb = (p->N + B - 1) / B;
    (void)workers;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(workers > 0 ? workers : omp_get_max_threads())
#endif
    for (ptrdiff_t b = 0; b < nb; b++)
        validity_block(p, b * B, (b + 1) * B < p->N ? (b + 1) * B : p->N);
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ fixed-pattern correction */
/* cos and sin of x (absolute error about 1e-15 within a few turns, below 1e-13 for |x| < 1e3:
   without FMA the two-part reduction is not exact): x = q pi/2 + r, |r| <= pi/4, Taylor
   series to r^14 / r^15 (the first term left out below 2e-15 of the result), the quadrant
   q mod 4 from the low bits of the rounding's mantissa (q rounded by adding 1.5 2^52), by
   selects: no libm call and no branch, so that a loop of it vectorises. A NaN gives NaN. */
static inline void tof_sincos(double x, double *s_out, double *c_out)
{
    const double magic = 6755399441055744.0;                          /* 1.5 * 2^52 */
    const double y = x * 0.63661977236758134308 + magic;
    uint64_t u;
    memcpy(&u, &y, sizeof u);
    const double q = y - magic;
    const double r = (x - q * 1.57079632679489655800) - q * 6.12323399573676603587e-17;
    const double r2 = r * r;
    double s = -7.6471637318198164759e-13;                          /* -1/15! */
    s = s * r2 + 1.6059043836821614599e-10;                          /* 1/13! */
    s = s * r2 - 2.5052108385441718775e-08;                          /* -1/11! */
    s = s * r2 + 2.7557319223985890653e-06;                          /* 1/9! */
    s = s * r2 - 1.9841269841269841270e-04;                          /* -1/7! */
    s = s * r2 + 8.3333333333333333333e-03;                          /* 1/5! */
    s = s * r2 - 1.6666666666666666667e-01;                          /* -1/3! */
    s = r + r * r2 * s;
    double c = 1.1470745597729724714e-11;                            /* 1/14! */
    c = c * r2 - 2.0876756987868098979e-09;                          /* -1/12! */
    c = c * r2 + 2.7557319223985890653e-07;                          /* 1/10! */
    c = c * r2 - 2.4801587301587301587e-05;                          /* -1/8! */
    c = c * r2 + 1.3888888888888888889e-03;                          /* 1/6! */
    c = c * r2 - 4.1666666666666666667e-02;                          /* -1/4! */
    c = c * r2 + 0.5;
    c = 1.0 - r2 * c;
    const uint64_t k = u & 3;                         /* q mod 4, negative q included */
    const double ss = (k & 1) ? c : s, cc = (k & 1) ? s : c;
    *s_out = (k & 2) ? -ss : ss;
    *c_out = ((k + 1) & 2) ? -cc : cc;
}

#define TOF_FP_B 256

/* measurements [n0, n0 + m), m <= TOF_FP_B, into delta[0, m): the frequencies in the outer
   loop, the measurements in the inner one. IQ: the cosine and sine of each phase from its
   phasor, iq[f iqs + j] (I) and iq[(F + f) iqs + j] (Q) for the measurement n0 + j, as
   I / |z| = I / (2 amp) (the amplitude is |I + iQ| / 2), in place of the polynomial of the
   phase: the same values within a few ulps, a third of the work */
RGBZ_INLINE void fixed_pattern_body(const double *phase, const double *amp,
                                    const double *offset, const double *count, ptrdiff_t F,
                                    ptrdiff_t N, const double *ssc, const double *rsc,
                                    double black, double pre, double var_dsnu, double fix_dsnu,
                                    double prnu2, int shared, double *delta, ptrdiff_t n0,
                                    ptrdiff_t m, const double *iq, ptrdiff_t iqs, const int IQ)
{
    double p0[TOF_FP_B], p1[TOF_FP_B], p2[TOF_FP_B], p3[TOF_FP_B], sh[TOF_FP_B],
        ch[TOF_FP_B], ind[TOF_FP_B], fsum[TOF_FP_B], wsum[TOF_FP_B];
    for (ptrdiff_t j = 0; j < m; j++) {
        p0[j] = p1[j] = p2[j] = p3[j] = sh[j] = ch[j] = 0.0;
        ind[j] = fsum[j] = wsum[j] = 0.0;
    }
    for (ptrdiff_t f = 0; f < F; f++) {
        const double *restrict ph = IQ ? NULL : phase + f * N + n0;
        const double *restrict am = amp + f * N + n0, *restrict of = offset + f * N + n0;
        const double *restrict iv = IQ ? iq + f * iqs : NULL;
        const double *restrict qv = IQ ? iq + (F + f) * iqs : NULL;
        const double rf = rsc[f], sf = ssc[f];
        for (ptrdiff_t j = 0; j < m; j++) {
            const double a = am[j];
            double t = of[j] - black;
            t = (t >= 0.0 || t != t) ? t : 0.0;
            t *= pre;                        /* the charge before the ambient suppression */
            const double half = 0.5 / a;
            double sn, cs;
            if (IQ) {
                cs = iv[j] * half;
                sn = qv[j] * half;
            } else {
                tof_sincos(ph[j], &sn, &cs);
            }
            const double h = rf * half;
            const double ac = a * cs, as = a * sn;
            p0[j] -= sn * (t + ac) * h;
            p2[j] += sn * (t - ac) * h;
            p3[j] += cs * (t + as) * h;
            p1[j] -= cs * (t - as) * h;
            sh[j] += sn * h;
            ch[j] += cs * h;
            const double fixed = var_dsnu + prnu2 * t * t;
            const double w = sf * half * half;              /* the weight of var in t */
            ind[j] += w * fixed;
            fsum[j] += fixed;
            wsum[j] += w;
        }
    }
    const double inv_f = 1.0 / (double)F;
    for (ptrdiff_t j = 0; j < m; j++) {
        const double in = shared ? wsum[j] * fsum[j] * inv_f : ind[j];
        double c = count ? count[n0 + j] : 1.0;
        c = (c >= 1.0 || c != c) ? c : 1.0;                 /* np.maximum(count, 1): NaN stays */
        const double corr = prnu2 * (((p0[j] * p0[j] + p1[j] * p1[j]) + p2[j] * p2[j])
                                     + p3[j] * p3[j])
                            + 2.0 * fix_dsnu * (sh[j] * sh[j] + ch[j] * ch[j]);
        const double d = (corr - 2.0 * in) / c;
        delta[j] = (d - d == 0.0) ? d : 0.0;                /* inf and NaN: 0 */
    }
}

/* fixed_pattern_body of the phases (iq NULL) or of the phasors: a clone per instruction set,
   so that the loops over the measurements vectorise at its width */
RGBZ_CLONES_512
static void fixed_pattern_block(const double *phase, const double *amp, const double *offset,
                                const double *count, ptrdiff_t F, ptrdiff_t N,
                                const double *ssc, const double *rsc, double black,
                                double pre, double var_dsnu, double fix_dsnu, double prnu2,
                                int shared, double *delta, ptrdiff_t n0, ptrdiff_t m,
                                const double *iq, ptrdiff_t iqs)
{
    if (iq)
        fixed_pattern_body(phase, amp, offset, count, F, N, ssc, rsc, black, pre, var_dsnu,
                           fix_dsnu, prnu2, shared, delta, n0, m, iq, iqs, 1);
    else
        fixed_pattern_body(phase, amp, offset, count, F, N, ssc, rsc, black, pre, var_dsnu,
                           fix_dsnu, prnu2, shared, delta, n0, m, NULL, 0, 0);
}

int rgbz_tof_fixed_pattern(const double *phase, const double *amp, const double *offset,
                           const double *count, ptrdiff_t F, ptrdiff_t N,
                           const double *sigma_scale, double black, double pre,
                           double var_dsnu, double fix_dsnu, double prnu, int shared,
                           double *delta, int workers)
{
    if (!phase || !amp || !offset || !sigma_scale || !delta || F < 1
        || F > RGBZ_TOF_MAX_FREQS || N < 0)
        return RGBZ_EINVAL;
    double rsc[RGBZ_TOF_MAX_FREQS];
    for (ptrdiff_t f = 0; f < F; f++) rsc[f] = sqrt(sigma_scale[f]);
    const ptrdiff_t B = TOF_FP_B, nb = (N + B - 1) / B;
    const double prnu2 = prnu * prnu;
    (void)workers;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(workers > 0 ? workers : omp_get_max_threads())
#endif
    for (ptrdiff_t b = 0; b < nb; b++)
        fixed_pattern_block(phase, amp, offset, count, F, N, sigma_scale, rsc, black, pre,
                            var_dsnu, fix_dsnu, prnu2, shared, delta + b * B, b * B,
                            (b + 1) * B < N ? B : N - b * B, NULL, 0);
    return RGBZ_OK;
}

void rgbz_tof_fixed_pattern_span(const double *phase, const double *amp, const double *offset,
                                 const double *count, ptrdiff_t F, ptrdiff_t N,
                                 const double *sigma_scale, double black, double pre,
                                 double var_dsnu, double fix_dsnu, double prnu, int shared,
                                 ptrdiff_t n0, ptrdiff_t m, double *delta, const double *iq,
                                 ptrdiff_t iqs)
{
    double rsc[RGBZ_TOF_MAX_FREQS];
    for (ptrdiff_t f = 0; f < F; f++) rsc[f] = sqrt(sigma_scale[f]);
    for (ptrdiff_t j = 0; j < m; j += TOF_FP_B)
        fixed_pattern_block(phase, amp, offset, count, F, N, sigma_scale, rsc, black, pre,
                            var_dsnu, fix_dsnu, prnu * prnu, shared, delta + j, n0 + j,
                            m - j < TOF_FP_B ? m - j : TOF_FP_B, iq ? iq + j : NULL, iqs);
}
