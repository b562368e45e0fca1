/*
 * colour_isp.template.h -- the fused render of colour_isp.c (white balance .. output) in one
 * precision. Instantiated by colour_isp.c once per precision, with
 *   REAL, RS   the float type of the arithmetic (float, double) and its suffix (f32, f64),
 *              appended to every name;
 * the row kernel, below, once per element type of the CFA: this file instantiates itself
 * with IN_T, IS and IN_IS_INT defined.
 */
#ifndef REAL
#error "colour_isp.template.h: #define REAL (float or double) and RS first"
#endif

#ifndef IN_T
/* ---------------------------------------------------------------- per precision */

/* The code of a linear value v in [0, 1]: the number of thresholds t[1 .. top] <= v. The
   bucket of v (its bits >> shift, counted from `base`; the bits of non-negative floats are
   ordered as the floats) gives the code of the bucket's smallest value, at most `span` below
   v's; `steps` halvings of 2^steps (>= span + 1) codes find v's without a branch, over the
   thresholds padded with 2^steps values above 1. */
typedef struct {
    const REAL *t;          /* the thresholds, padded */
    const uint16_t *start;  /* the code of each bucket's smallest value */
    CI_UINT(RS) base, last; /* the first and the last bucket */
    int shift, steps;
} RGBZ_CAT(ci_codes, RS);

RGBZ_INLINE int RGBZ_CAT(ci_code, RS)(const RGBZ_CAT(ci_codes, RS) *tab, REAL v, int steps)
{
    CI_UINT(RS) u;
    memcpy(&u, &v, sizeof u);
    u >>= tab->shift;
    u = u < tab->base ? tab->base : (u > tab->last ? tab->last : u);
    int c = tab->start[u - tab->base];
    for (int s = 1 << (steps - 1); s > 0; s >>= 1) c += tab->t[c + s] <= v ? s : 0;
    return c;
}

/* the bucket table and the padded thresholds of t (2^bits values) in one block, which the
   caller frees; NULL when out of memory */
static void *RGBZ_CAT(ci_build_codes, RS)(RGBZ_CAT(ci_codes, RS) *tab, const REAL *t, int bits)
{
    /* 2^k buckets per octave over the 20 octaves below 1 (a value below 2^-20 has the code
       0 or 1): a bucket spans at most 1 code for 8 bits, 6 for 16 (float32 and float64) */
    const int k = bits == 8 ? 8 : 12;
    const REAL low = (REAL)9.5367431640625e-07;      /* 2^-20 */
    const REAL one = 1;
    const int top = (1 << bits) - 1;
    CI_UINT(RS) ulow, uone;
    memcpy(&ulow, &low, sizeof ulow);
    memcpy(&uone, &one, sizeof uone);
    tab->shift = CI_MANT(RS) - k;
    tab->base = ulow >> tab->shift;
    tab->last = uone >> tab->shift;
    const ptrdiff_t n = (ptrdiff_t)(tab->last - tab->base) + 1;
    const ptrdiff_t npad = (ptrdiff_t)top + 1 + 64;
    REAL *tp = (REAL *)malloc((size_t)npad * sizeof(REAL) + (size_t)n * sizeof(uint16_t));
    if (!tp) return NULL;
    uint16_t *start = (uint16_t *)(tp + npad);
    start[0] = 0;                                   /* holds 0, whose code is 0 */
    int c = 0, span = 0;
    for (ptrdiff_t i = 1; i < n; i++) {
        const CI_UINT(RS) u = (tab->base + (CI_UINT(RS))i) << tab->shift;
        REAL lo;
        memcpy(&lo, &u, sizeof lo);
        while (c < top && t[c + 1] <= lo) c++;
        start[i] = (uint16_t)c;
        if (c - start[i - 1] > span) span = c - start[i - 1];
    }
    if (top - c > span) span = top - c;
    int steps = 1;
    while ((1 << steps) <= span) steps++;
    if (steps > 6) {                                /* not these thresholds */
        free(tp);
        return NULL;
    }
    memcpy(tp, t, (size_t)(top + 1) * sizeof(REAL));
    for (ptrdiff_t i = top + 1; i < npad; i++) tp[i] = (REAL)2;     /* above every v */
    tab->t = tp;
    tab->start = start;
    tab->steps = steps;
    return tp;
}

/* what a row kernel needs, beside the frame */
typedef struct {
    const int32_t *phase;
    const ptrdiff_t *colmap;        /* cols + 4 entries: the source of padded column j - 2 */
    REAL scale[3], black;
    int clip, mode;
    int has_matrix;
    REAL m[9];
    RGBZ_CAT(ci_codes, RS) codes;
} RGBZ_CAT(ci_render_args, RS);

RGBZ_INLINE REAL RGBZ_CAT(ci_clip01, RS)(REAL v)
{
    return v < (REAL)0 ? (REAL)0 : (v > (REAL)1 ? (REAL)1 : v);
}

/* Malvar 2004 at x of the five white-balanced rows r[0..4] (rows y-2 .. y+2), into rgb:
   demosaic.c's dm_pixel term for term, in double. A green site (green), the colour of its
   row being rc (0: R, 2: B); or a red or blue site of colour ch. */
RGBZ_INLINE void RGBZ_CAT(ci_green, RS)(const double *const *r, ptrdiff_t x, int rc, double *rgb)
{
    const double c0 = (double)r[2][x];
    const double diag = (double)r[1][x - 1] + (double)r[1][x + 1] + (double)r[3][x - 1] +
                        (double)r[3][x + 1];
    const double hz2 = (double)r[2][x - 2] + (double)r[2][x + 2];
    const double vt2 = (double)r[0][x] + (double)r[4][x];
    const double hz1 = (double)r[2][x - 1] + (double)r[2][x + 1];
    const double vt1 = (double)r[1][x] + (double)r[3][x];
    const double hv = (5 * c0 + 4 * hz1 - hz2 - diag + 0.5 * vt2) / 8;
    const double vv = (5 * c0 + 4 * vt1 - vt2 - diag + 0.5 * hz2) / 8;
    rgb[1] = c0;
    rgb[0] = rc == 0 ? hv : vv;
    rgb[2] = rc == 0 ? vv : hv;
}

RGBZ_INLINE void RGBZ_CAT(ci_colour, RS)(const double *const *r, ptrdiff_t x, int ch, double *rgb)
{
    const double c0 = (double)r[2][x];
    const double n4 = (double)r[1][x] + (double)r[3][x] + (double)r[2][x - 1] +
                      (double)r[2][x + 1];
    const double far4 = (double)r[0][x] + (double)r[4][x] + (double)r[2][x - 2] +
                        (double)r[2][x + 2];
    const double diag = (double)r[1][x - 1] + (double)r[1][x + 1] + (double)r[3][x - 1] +
                        (double)r[3][x + 1];
    const double gg = (4 * c0 + 2 * n4 - far4) / 8;
    const double oo = (6 * c0 + 2 * diag - 1.5 * far4) / 8;
    rgb[1] = gg;
    rgb[0] = ch == 0 ? c0 : oo;
    rgb[2] = ch == 0 ? oo : c0;
}

/* the codes of one pixel's demosaicked rgb at o[0..2]: rounded to REAL (isp.demosaic's
   output type), the colour matrix, the clip and the code */
RGBZ_INLINE void RGBZ_CAT(ci_store, RS)(const RGBZ_CAT(ci_render_args, RS) *a, const double *rgb,
                                        int has_matrix, int steps, int bits8, void *o, ptrdiff_t i)
{
    REAL v[3] = {(REAL)rgb[0], (REAL)rgb[1], (REAL)rgb[2]};
    if (has_matrix) {
        const REAL *m = a->m;
        REAL w[3];
        for (int k = 0; k < 3; k++)
            w[k] = RGBZ_CAT(CI_DOT3, RS)(m[3 * k], v[0], m[3 * k + 1], v[1], m[3 * k + 2], v[2]);
        v[0] = w[0]; v[1] = w[1]; v[2] = w[2];
    }
    for (int k = 0; k < 3; k++) {
        const int c = RGBZ_CAT(ci_code, RS)(&a->codes, RGBZ_CAT(ci_clip01, RS)(v[k]), steps);
        if (bits8) ((uint8_t *)o)[i + k] = (uint8_t)c;
        else ((uint16_t *)o)[i + k] = (uint16_t)c;
    }
}

/* Output row y from the five white-balanced rows rp[0..4] (rows y-2 .. y+2 after the
   border rule, each padded by two columns on both sides). gfirst (a green at even x), rc
   (the row's other colour), has_matrix, steps and bits8 are constants in every call, so
   that each combination is a loop of its own without a branch per pixel. */
RGBZ_INLINE void RGBZ_CAT(ci_row, RS)(double *const *rp, ptrdiff_t y, ptrdiff_t cols,
                                      const RGBZ_CAT(ci_render_args, RS) *a, void *out,
                                      int gfirst, int rc, int has_matrix, int steps, int bits8)
{
    const double *r[5] = {rp[0] + 2, rp[1] + 2, rp[2] + 2, rp[3] + 2, rp[4] + 2};
    const ptrdiff_t o = 3 * y * cols;
    double rgb[3];
    ptrdiff_t x = 0;
    for (; x + 1 < cols; x += 2) {
        if (gfirst) RGBZ_CAT(ci_green, RS)(r, x, rc, rgb);
        else RGBZ_CAT(ci_colour, RS)(r, x, rc, rgb);
        RGBZ_CAT(ci_store, RS)(a, rgb, has_matrix, steps, bits8, out, o + 3 * x);
        if (gfirst) RGBZ_CAT(ci_colour, RS)(r, x + 1, rc, rgb);
        else RGBZ_CAT(ci_green, RS)(r, x + 1, rc, rgb);
        RGBZ_CAT(ci_store, RS)(a, rgb, has_matrix, steps, bits8, out, o + 3 * (x + 1));
    }
    if (x < cols) {
        if (gfirst) RGBZ_CAT(ci_green, RS)(r, x, rc, rgb);
        else RGBZ_CAT(ci_colour, RS)(r, x, rc, rgb);
        RGBZ_CAT(ci_store, RS)(a, rgb, has_matrix, steps, bits8, out, o + 3 * x);
    }
}

/* ci_row with its constants: the steps of the table (1 for 8 bits, 3 for 16) and the rest */
#define CI_ROW_STEPS_(G, RC, M, B)                                                          \
    do {                                                                                    \
        if (a->codes.steps == 1) RGBZ_CAT(ci_row, RS)(rp, y, cols, a, out, G, RC, M, 1, B);   \
        else if (a->codes.steps == 2) RGBZ_CAT(ci_row, RS)(rp, y, cols, a, out, G, RC, M, 2, B); \
        else if (a->codes.steps == 3) RGBZ_CAT(ci_row, RS)(rp, y, cols, a, out, G, RC, M, 3, B); \
        else RGBZ_CAT(ci_row, RS)(rp, y, cols, a, out, G, RC, M, a->codes.steps, B);          \
    } while (0)

static void RGBZ_CAT(ci_row_any, RS)(double *const *rp, ptrdiff_t y, ptrdiff_t cols,
                                     const RGBZ_CAT(ci_render_args, RS) *a, void *out, int bits)
{
    const int32_t *ph = a->phase + 2 * (y & 1);
    const int gfirst = ph[0] == 1;
    const int rc = gfirst ? ph[1] : ph[0];
#define CI_ROW_B_(G, RC, M)                                                                 \
    do {                                                                                    \
        if (bits == 8) CI_ROW_STEPS_(G, RC, M, 1);                                          \
        else CI_ROW_STEPS_(G, RC, M, 0);                                                    \
    } while (0)
#define CI_ROW_M_(G, RC)                                                                    \
    do {                                                                                    \
        if (a->has_matrix) CI_ROW_B_(G, RC, 1);                                             \
        else CI_ROW_B_(G, RC, 0);                                                           \
    } while (0)
    if (gfirst) {
        if (rc == 0) CI_ROW_M_(1, 0);
        else CI_ROW_M_(1, 2);
    } else {
        if (rc == 0) CI_ROW_M_(0, 0);
        else CI_ROW_M_(0, 2);
    }
#undef CI_ROW_M_
#undef CI_ROW_B_
}
#undef CI_ROW_STEPS_

#define IN_T uint8_t
#define IS u8
#define IN_IS_INT 1
#include "colour_isp.template.h"
#undef IN_T
#undef IS
#undef IN_IS_INT
#define IN_T uint16_t
#define IS u16
#define IN_IS_INT 1
#include "colour_isp.template.h"
#undef IN_T
#undef IS
#undef IN_IS_INT
#define IN_T float
#define IS f32
#define IN_IS_INT 0
#include "colour_isp.template.h"
#undef IN_T
#undef IS
#undef IN_IS_INT
#define IN_T double
#define IS f64
#define IN_IS_INT 0
#include "colour_isp.template.h"
#undef IN_T
#undef IS
#undef IN_IS_INT

int RGBZ_CAT(rgbz_ci_render, RS)(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                                 const int32_t *phase, int mode, const REAL *scale, REAL black,
                                 int clip, const REAL *matrix, const REAL *thresholds, int bits,
                                 void *out, int workers)
{
    if (!src || !out || !phase || !scale || !thresholds || rows < 2 || cols < 2 ||
        (bits != 8 && bits != 16) || (mode != RGBZ_DM_REFLECT && mode != RGBZ_DM_PERIOD) ||
        !ci_bayer_phase(phase))
        return RGBZ_EINVAL;
    RGBZ_CAT(ci_render_args, RS) a;
    a.phase = phase;
    a.mode = mode;
    a.clip = clip;
    a.black = black;
    for (int i = 0; i < 3; i++) a.scale[i] = scale[i];
    a.has_matrix = matrix != NULL;
    for (int i = 0; i < 9; i++) a.m[i] = matrix ? matrix[i] : (REAL)(i % 4 == 0);
    for (int i = 1; i < (1 << bits); i++)
        if (!(thresholds[i] >= thresholds[i - 1]) || !(thresholds[i] <= (REAL)1))
            return RGBZ_EINVAL;
    if (thresholds[0] != (REAL)0) return RGBZ_EINVAL;
    ptrdiff_t *colmap = (ptrdiff_t *)malloc((size_t)(cols + 4) * sizeof *colmap);
    void *codes = RGBZ_CAT(ci_build_codes, RS)(&a.codes, thresholds, bits);
    if (!colmap || !codes) {
        free(colmap);
        free(codes);
        return codes ? RGBZ_ENOMEM : RGBZ_EINVAL;
    }
    for (ptrdiff_t i = 0; i < cols + 4; i++) colmap[i] = ci_extend(i - 2, cols, mode);
    a.colmap = colmap;
    int st = RGBZ_OK;
#define CI_RENDER_(s, T) st = RGBZ_CAT3(ci_render, RS, s)((const T *)src, rows, cols, &a, out, \
                                                          bits, workers)
    CI_SWITCH_TYPE(in_type, CI_RENDER_, st = RGBZ_EINVAL)
#undef CI_RENDER_
    free(colmap);
    free(codes);
    return st;
}

#else
/* ---------------------------------------------------------------- per element type */

/* the white-balanced row r of the frame into dst[2 .. cols + 1], its border columns into
   dst[0, 1, cols + 2, cols + 3] (the columns colmap names): isp.white_balance's operations
   in REAL, kept as double (exact), the type the demosaic computes in */
static void RGBZ_CAT3(ci_balance, RS, IS)(const IN_T *src, ptrdiff_t r, ptrdiff_t cols,
                                          const RGBZ_CAT(ci_render_args, RS) *a, double *dst)
{
    const IN_T *row = src + r * cols;
    const int32_t *ph = a->phase + 2 * (r & 1);
    const REAL s0 = a->scale[ph[0]], s1 = a->scale[ph[1]], black = a->black;
    double *d = dst + 2;
    ptrdiff_t x = 0;
    if (a->clip) {
        for (; x + 1 < cols; x += 2) {
            REAL u = (REAL)row[x], w = (REAL)row[x + 1];
            u = u - black;
            w = w - black;
            u = u * s0;
            w = w * s1;
            d[x] = RGBZ_CAT(ci_clip01, RS)(u);
            d[x + 1] = RGBZ_CAT(ci_clip01, RS)(w);
        }
    } else {
        for (; x + 1 < cols; x += 2) {
            REAL u = (REAL)row[x], w = (REAL)row[x + 1];
            u = u - black;
            w = w - black;
            d[x] = u * s0;
            d[x + 1] = w * s1;
        }
    }
    if (x < cols) {
        REAL u = (REAL)row[x];
        u = u - black;
        u = u * s0;
        d[x] = a->clip ? RGBZ_CAT(ci_clip01, RS)(u) : u;
    }
    const ptrdiff_t *cm = a->colmap;
    dst[0] = d[cm[0]];
    dst[1] = d[cm[1]];
    dst[cols + 2] = d[cm[cols + 2]];
    dst[cols + 3] = d[cm[cols + 3]];
}

/* every output row: each thread renders a band of consecutive rows, keeping the last 8
   white-balanced rows in a ring (a row r in slot r % 8; the 5 rows of an output row are 5
   consecutive frame rows or fewer after the border rule, so they never share a slot) */
static int RGBZ_CAT3(ci_render, RS, IS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols,
                                        const RGBZ_CAT(ci_render_args, RS) *a, void *out,
                                        int bits, int workers)
{
    const int nt = ci_threads(workers, rows * cols);
    int bad = 0;
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt) reduction(|:bad)
#endif
    {
        const ptrdiff_t stride = cols + 4;
        double *ring = (double *)malloc((size_t)(8 * stride) * sizeof *ring);
        ptrdiff_t tag[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
        ptrdiff_t y0 = 0, y1 = rows;
#ifdef _OPENMP
        {
            const ptrdiff_t t = omp_get_thread_num(), n = omp_get_num_threads();
            y0 = rows * t / n;
            y1 = rows * (t + 1) / n;
        }
#endif
        if (!ring) {
            bad = 1;
        } else {
            for (ptrdiff_t y = y0; y < y1; y++) {
                double *rp[5];
                for (int d = 0; d < 5; d++) {
                    const ptrdiff_t r = ci_extend(y + d - 2, rows, a->mode);
                    double *slot = ring + (r & 7) * stride;
                    if (tag[r & 7] != r) {
                        RGBZ_CAT3(ci_balance, RS, IS)(src, r, cols, a, slot);
                        tag[r & 7] = r;
                    }
                    rp[d] = slot;
                }
                RGBZ_CAT(ci_row_any, RS)(rp, y, cols, a, out, bits);
            }
        }
        free(ring);
    }
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}
#endif
