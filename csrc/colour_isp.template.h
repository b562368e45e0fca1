/*
 * colour_isp.template.h -- the fused render of colour_isp.c (white balance .. output) in one
 * precision. Instantiated by colour_isp.c once per precision, with
 *   REAL, RS   the float type of the arithmetic (float, double) and its suffix (f32, f64),
 *              appended to every name;
 * through rgbz_each_real.h (rgbz_templating.h); the row kernel, below, once per element
 * type of the CFA: this file instantiates itself through rgbz_each_type.h (IN_T, IS,
 * IN_IS_INT).
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
    const int32_t *start;   /* the code of each bucket's smallest value */
    CI_UINT(RS) base, last; /* the first and the last bucket */
    int shift, steps;
    /* one step (steps 1) in float32: each bucket's start code c in the high half and the
       bits of t[c + 1] in the low half, so that one 8-byte load gives both; else NULL */
    const uint64_t *pair;
    /* one step in float64: t[c + 1] of each bucket's start code c, so that the bucket gives
       both (two loads at one index, not one after the other); else NULL */
    const REAL *next;
} RGBZ_CAT(ci_codes, RS);

RGBZ_INLINE int RGBZ_CAT(ci_code, RS)(const RGBZ_CAT(ci_codes, RS) *tab, REAL v, int steps)
{
    CI_UINT(RS) u;
    memcpy(&u, &v, sizeof u);
    u >>= tab->shift;
    u = u < tab->base ? tab->base : (u > tab->last ? tab->last : u);
    int32_t c = tab->start[(int32_t)(u - tab->base)];
    for (int s = 1 << (steps - 1); s > 0; s >>= 1) c += tab->t[c + s] <= v ? s : 0;
    return c;
}

/* the bucket table and the padded thresholds of t (2^bits values) in one block, which the
   caller frees; NULL when out of memory */
static void *RGBZ_CAT(ci_build_codes, RS)(RGBZ_CAT(ci_codes, RS) *tab, const REAL *t, int bits)
{
    /* 2^k buckets per octave over the 20 octaves below 1 (a value below 2^-20 has the code
       0 or 1): a bucket spans at most 1 code for 8 bits, 3 for 16 (float32 and float64), so
       that a code takes one threshold test or two (2^12 buckets per octave left 6 codes and
       three tests in a row: 16-bit output 1.20x slower, 1 thread) */
    const int k = bits == 8 ? 8 : 13;
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
    /* one block: the pairs (8-byte aligned), the padded thresholds, the float64 buckets'
       next thresholds, the start codes */
    const size_t npair = sizeof(REAL) == 4 ? (size_t)n : 0;
    const size_t nnext = sizeof(REAL) == 8 ? (size_t)n : 0;
    uint64_t *pair = (uint64_t *)malloc(npair * sizeof(uint64_t) + (size_t)npad * sizeof(REAL) +
                                        nnext * sizeof(REAL) + (size_t)n * sizeof(int32_t));
    if (!pair) return NULL;
    REAL *tp = (REAL *)(pair + npair);
    REAL *next = tp + npad;
    int32_t *start = (int32_t *)(next + nnext);
    start[0] = 0;                                   /* holds 0, whose code is 0 */
    int c = 0, span = 0;
    for (ptrdiff_t i = 1; i < n; i++) {
        const CI_UINT(RS) u = (tab->base + (CI_UINT(RS))i) << tab->shift;
        REAL lo;
        memcpy(&lo, &u, sizeof lo);
        while (c < top && t[c + 1] <= lo) c++;
        start[i] = c;
        if (c - start[i - 1] > span) span = c - start[i - 1];
    }
    if (top - c > span) span = top - c;
    int steps = 1;
    while ((1 << steps) <= span) steps++;
    if (steps > 6) {                                /* not these thresholds */
        free(pair);
        return NULL;
    }
    memcpy(tp, t, (size_t)(top + 1) * sizeof(REAL));
    for (ptrdiff_t i = top + 1; i < npad; i++) tp[i] = (REAL)2;     /* above every v */
    tab->t = tp;
    tab->start = start;
    tab->steps = steps;
    tab->pair = NULL;
    tab->next = NULL;
    if (nnext && steps == 1) {
        for (ptrdiff_t i = 0; i < n; i++) next[i] = tp[start[i] + 1];
        tab->next = next;
    }
    if (npair && steps == 1) {
        for (ptrdiff_t i = 0; i < n; i++) {
            uint32_t tb;
            memcpy(&tb, tp + start[i] + 1, sizeof tb);
            pair[i] = (uint64_t)tb | (uint64_t)(uint32_t)start[i] << 32;
        }
        tab->pair = pair;
    }
    return pair;
}

/* what a row kernel needs, beside the frame */
typedef struct {
    const int32_t *phase;
    const ptrdiff_t *colmap;        /* cols + 4 entries: the source of padded column j - 2 */
    REAL scale[3], black;
    int clip, mode;
    int method;                     /* an rgbz_demosaic_method */
    ptrdiff_t rows;
    int has_matrix;
    REAL m[9];
    RGBZ_CAT(ci_codes, RS) codes;
} RGBZ_CAT(ci_render_args, RS);

/* [0, 1]; -0 becomes +0 (whose bits the code lookup reads) */
RGBZ_INLINE REAL RGBZ_CAT(ci_clip01, RS)(REAL v)
{
    return v <= (REAL)0 ? (REAL)0 : (v > (REAL)1 ? (REAL)1 : v);
}

/* isp.white_balance of one value, its operations in its order and type: v - black, times the
   scale of the pixel's colour, clipped to [0, 1] when clip (ci_balance, ci_balance_rows) */
RGBZ_INLINE REAL RGBZ_CAT(ci_wb, RS)(REAL v, REAL black, REAL s, int clip)
{
    v = v - black;
    v = v * s;
    return clip ? RGBZ_CAT(ci_clip01, RS)(v) : v;
}

/* The white-balanced rows are kept as two planes of double (exact: REAL values), the even
   columns and the odd ones, each with 3 cells of border before: plane p of a row holds
   column 2 j + p at index j + 3, so that every tap of the demosaic is a unit-stride read in
   j and the loops below vectorise. CI_PLANE is a plane's length for `cols` columns. */
#define CI_PLANE(cols) ((cols) / 2 + 6)

/* Malvar 2004 of the n greens of a row at x = 2 j + gp: s[k] the plane of parity gp of row
   y + k - 2 (at its cell 0, index j + 3 above), t[k] the other plane shifted so that t[k][j]
   and t[k][j + 1] are the columns x - 1 and x + 1. Out: the row colour's value to oa (R on
   an R row), the other's to ob, green to og. demosaic.c's dm_pixel term for term, in double,
   rounded to REAL as isp.demosaic stores it. */
CI_CLONES static void RGBZ_CAT(ci_greens, RS)(const double *const *s, const double *const *t, ptrdiff_t n,
                                    REAL *restrict oa, REAL *restrict og, REAL *restrict ob)
{
    const double *s0 = s[0], *s1 = s[1], *s2 = s[2], *s3 = s[3], *s4 = s[4];
    const double *t1 = t[1], *t2 = t[2], *t3 = t[3];
    for (ptrdiff_t j = 0; j < n; j++) {
        const double c0 = s2[j];
        const double diag = t1[j] + t1[j + 1] + t3[j] + t3[j + 1];
        const double hz2 = s2[j - 1] + s2[j + 1];
        const double vt2 = s0[j] + s4[j];
        const double hz1 = t2[j] + t2[j + 1];
        const double vt1 = s1[j] + s3[j];
        const double hv = (5 * c0 + 4 * hz1 - hz2 - diag + 0.5 * vt2) / 8;
        const double vv = (5 * c0 + 4 * vt1 - vt2 - diag + 0.5 * hz2) / 8;
        og[j] = (REAL)c0;
        oa[j] = (REAL)hv;
        ob[j] = (REAL)vv;
    }
}

/* the n red or blue sites of a row: s and t as above with the parities swapped; the site's
   own colour to oc, green to og, the other colour to oo */
CI_CLONES static void RGBZ_CAT(ci_colours, RS)(const double *const *s, const double *const *t,
                                     ptrdiff_t n, REAL *restrict oc, REAL *restrict og,
                                     REAL *restrict oo)
{
    const double *s0 = s[0], *s1 = s[1], *s2 = s[2], *s3 = s[3], *s4 = s[4];
    const double *t1 = t[1], *t2 = t[2], *t3 = t[3];
    for (ptrdiff_t j = 0; j < n; j++) {
        const double c0 = s2[j];
        const double n4 = s1[j] + s3[j] + t2[j] + t2[j + 1];
        const double far4 = s0[j] + s4[j] + s2[j - 1] + s2[j + 1];
        const double diag = t1[j] + t1[j + 1] + t3[j] + t3[j + 1];
        const double gg = (4 * c0 + 2 * n4 - far4) / 8;
        const double other = (6 * c0 + 2 * diag - 1.5 * far4) / 8;
        oc[j] = (REAL)c0;
        og[j] = (REAL)gg;
        oo[j] = (REAL)other;
    }
}

/* Bilinear (demosaic.c's dm_bilinear_pixel, in double from 0.0 in scipy's order of the
   taps, rounded to REAL) of the n greens of a row, with s, t, oa, og, ob as ci_greens */
CI_CLONES static void RGBZ_CAT(ci_bilinear_greens, RS)(const double *const *s,
                                                       const double *const *t, ptrdiff_t n,
                                                       REAL *restrict oa, REAL *restrict og,
                                                       REAL *restrict ob)
{
    const double *s1 = s[1], *s2 = s[2], *s3 = s[3], *t2 = t[2];
    for (ptrdiff_t j = 0; j < n; j++) {
        og[j] = (REAL)(0.0 + s2[j]);
        oa[j] = (REAL)((0.0 + t2[j] * 0.5) + t2[j + 1] * 0.5);
        ob[j] = (REAL)((0.0 + s1[j] * 0.5) + s3[j] * 0.5);
    }
}

/* bilinear of the n red or blue sites of a row, with s, t, oc, og, oo as ci_colours */
CI_CLONES static void RGBZ_CAT(ci_bilinear_colours, RS)(const double *const *s,
                                                        const double *const *t, ptrdiff_t n,
                                                        REAL *restrict oc, REAL *restrict og,
                                                        REAL *restrict oo)
{
    const double *s1 = s[1], *s2 = s[2], *s3 = s[3], *t1 = t[1], *t2 = t[2], *t3 = t[3];
    for (ptrdiff_t j = 0; j < n; j++) {
        oc[j] = (REAL)(0.0 + s2[j]);
        og[j] = (REAL)((((0.0 + s1[j] * 0.25) + t2[j] * 0.25) + t2[j + 1] * 0.25) +
                       s3[j] * 0.25);
        oo[j] = (REAL)((((0.0 + t1[j] * 0.25) + t1[j + 1] * 0.25) + t3[j] * 0.25) +
                       t3[j + 1] * 0.25);
    }
}

/* bilinear with the reflect border: pixel x of row y by the rule (demosaic_bilinear.h),
   into the planar scratch par (as ci_row's) */
static void RGBZ_CAT(ci_bilinear_edge, RS)(double *const *rp, ptrdiff_t y, ptrdiff_t x,
                                           ptrdiff_t cols, const RGBZ_CAT(ci_render_args, RS) *a,
                                           REAL *(*par)[3])
{
    const ptrdiff_t hp = CI_PLANE(cols);
    double v[9], rgb[3];
    int c[9];
    for (int i = 0; i < 3; i++) {
        const ptrdiff_t ry = ci_extend(y + i - 1, a->rows, a->mode);
        for (int k = 0; k < 3; k++) {
            const ptrdiff_t cc = x + k - 1;      /* >= -1: its plane cell by an arithmetic shift */
            const ptrdiff_t jc = cc >= 0 ? cc / 2 : -1;
            v[3 * i + k] = rp[i + 1][(cc & 1) * hp + 3 + jc];
            c[3 * i + k] = a->phase[2 * (ry & 1) + (a->colmap[cc + 2] & 1)];
        }
    }
    dm_bilinear_taps(v, c, rgb);
    for (int k = 0; k < 3; k++) par[x & 1][k][x >> 1] = (REAL)rgb[k];
}

/* the colour matrix on n pixels of planes r, g, b, in place */
CI_CLONES_FMA static void RGBZ_CAT(ci_matrix, RS)(const REAL *m, REAL *restrict r,
                                                  REAL *restrict g, REAL *restrict b,
                                                  ptrdiff_t n)
{
    for (ptrdiff_t j = 0; j < n; j++) {
        const REAL v0 = r[j], v1 = g[j], v2 = b[j];
        r[j] = RGBZ_CAT(CI_DOT3, RS)(m[0], v0, m[1], v1, m[2], v2);
        g[j] = RGBZ_CAT(CI_DOT3, RS)(m[3], v0, m[4], v1, m[5], v2);
        b[j] = RGBZ_CAT(CI_DOT3, RS)(m[6], v0, m[7], v1, m[8], v2);
    }
}

/* the bucket of a clipped value v: the code of its smallest value (see ci_code) */
RGBZ_INLINE int32_t RGBZ_CAT(ci_start, RS)(const RGBZ_CAT(ci_codes, RS) *tab, REAL v)
{
    union { REAL f; CI_UINT(RS) u; } bits = {v};
    CI_UINT(RS) u = bits.u >> tab->shift;
    u = u < tab->base ? tab->base : (u > tab->last ? tab->last : u);
    return tab->start[(int32_t)(u - tab->base)];
}

/* the codes of n values (clipped first): the vector codes of the precision if the CPU has
   them, then ci_code with its steps written out for the tables of 8 bits (1) and 16 (2) */
static void RGBZ_CAT(ci_encode, RS)(const RGBZ_CAT(ci_codes, RS) *tab, const REAL *v,
                                    uint16_t *restrict code, ptrdiff_t n)
{
    const REAL *t = tab->t;
    ptrdiff_t j = RGBZ_CAT(CI_ENCODE_FAST, RS)(tab, v, code, n);
    if (tab->steps == 1) {
        for (; j < n; j++) {
            const REAL x = RGBZ_CAT(ci_clip01, RS)(v[j]);
            int32_t c = RGBZ_CAT(ci_start, RS)(tab, x);
            c += t[c + 1] <= x ? 1 : 0;
            code[j] = (uint16_t)c;
        }
    } else if (tab->steps == 2) {
        for (; j < n; j++) {
            const REAL x = RGBZ_CAT(ci_clip01, RS)(v[j]);
            int32_t c = RGBZ_CAT(ci_start, RS)(tab, x);
            c += t[c + 2] <= x ? 2 : 0;
            c += t[c + 1] <= x ? 1 : 0;
            code[j] = (uint16_t)c;
        }
    } else {
        for (; j < n; j++)
            code[j] = (uint16_t)RGBZ_CAT(ci_code, RS)(tab, RGBZ_CAT(ci_clip01, RS)(v[j]),
                                                      tab->steps);
    }
}

/* The tail of the render on n pixels of the planes pl (R, G, B): the colour matrix m (NULL:
   none) in place, then the codes into the planes code, code + h and code + 2 h. For each
   parity of a row (ci_row) and each chunk of an RGB image (rgbz_ci_encode_rgb). */
static void RGBZ_CAT(ci_finish, RS)(const REAL *m, const RGBZ_CAT(ci_codes, RS) *codes,
                                    REAL *const *pl, uint16_t *code, ptrdiff_t h, ptrdiff_t n)
{
    if (m) RGBZ_CAT(ci_matrix, RS)(m, pl[0], pl[1], pl[2], n);
    for (int k = 0; k < 3; k++) RGBZ_CAT(ci_encode, RS)(codes, pl[k], code + k * h, n);
}

/* Output row y from the five white-balanced rows rp[0..4] (rows y-2 .. y+2 after the border
   rule, as planes): the demosaic per parity into the planar scratch lin (6 planes of h
   values: R, G, B of the even columns, then of the odd ones), the matrix, the codes (code,
   the same layout), then interleaved into the output row. */
static void RGBZ_CAT(ci_row, RS)(double *const *rp, ptrdiff_t y, ptrdiff_t cols,
                                 const RGBZ_CAT(ci_render_args, RS) *a, REAL *lin,
                                 uint16_t *code, void *out, int bits)
{
    const int32_t *ph = a->phase + 2 * (y & 1);
    const int gp = ph[0] == 1 ? 0 : 1;              /* the parity of the greens */
    const int rc = ph[1 - gp];                      /* the row's other colour: 0 R, 2 B */
    const ptrdiff_t hp = CI_PLANE(cols), h = cols / 2 + 1;
    const ptrdiff_t ng = (cols - gp + 1) / 2, nc = (cols - (1 - gp) + 1) / 2;
    const double *s[5], *t[5];
    REAL *par[2][3];
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < 3; k++) par[p][k] = lin + (3 * p + k) * h;
    /* the greens: the other plane's x - 1 is its cell j - 1 when the greens are even */
    for (int k = 0; k < 5; k++) {
        s[k] = rp[k] + gp * hp + 3;
        t[k] = rp[k] + (1 - gp) * hp + 3 - (gp == 0);
    }
    REAL **gpl = par[gp];
    if (a->method == RGBZ_DM_BILINEAR)
        RGBZ_CAT(ci_bilinear_greens, RS)(s, t, ng, gpl[rc], gpl[1], gpl[2 - rc]);
    else
        RGBZ_CAT(ci_greens, RS)(s, t, ng, gpl[rc], gpl[1], gpl[2 - rc]);
    for (int k = 0; k < 5; k++) {
        s[k] = rp[k] + (1 - gp) * hp + 3;
        t[k] = rp[k] + gp * hp + 3 - (gp == 1);
    }
    REAL **cpl = par[1 - gp];
    if (a->method == RGBZ_DM_BILINEAR)
        RGBZ_CAT(ci_bilinear_colours, RS)(s, t, nc, cpl[rc], cpl[1], cpl[2 - rc]);
    else
        RGBZ_CAT(ci_colours, RS)(s, t, nc, cpl[rc], cpl[1], cpl[2 - rc]);
    if (a->method == RGBZ_DM_BILINEAR && a->mode == RGBZ_DM_REFLECT) {
        /* the outer pixels, whose mirrored taps may be of another colour */
        if (y == 0 || y == a->rows - 1) {
            for (ptrdiff_t x = 0; x < cols; x++)
                RGBZ_CAT(ci_bilinear_edge, RS)(rp, y, x, cols, a, par);
        } else {
            RGBZ_CAT(ci_bilinear_edge, RS)(rp, y, 0, cols, a, par);
            RGBZ_CAT(ci_bilinear_edge, RS)(rp, y, cols - 1, cols, a, par);
        }
    }
    const ptrdiff_t nn[2] = {(cols + 1) / 2, cols / 2};
    for (int p = 0; p < 2; p++)
        RGBZ_CAT(ci_finish, RS)(a->has_matrix ? a->m : NULL, &a->codes, par[p],
                                code + 3 * p * h, h, nn[p]);
    if (bits == 8) ci_interleave8(code, h, cols, (uint8_t *)out + 3 * y * cols);
    else ci_interleave16(code, h, cols, (uint16_t *)out + 3 * y * cols);
}

/* the n pixels of interleaved RGB at rgb into 3 planes of h values at lin (R, G, B) */
CI_CLONES static void RGBZ_CAT(ci_deinterleave, RS)(const REAL *restrict rgb, ptrdiff_t n,
                                                    ptrdiff_t h, REAL *restrict lin)
{
    REAL *restrict p0 = lin, *restrict p1 = lin + h, *restrict p2 = lin + 2 * h;
    for (ptrdiff_t j = 0; j < n; j++) {
        p0[j] = rgb[3 * j];
        p1[j] = rgb[3 * j + 1];
        p2[j] = rgb[3 * j + 2];
    }
}

#define RGBZ_TYPE_TEMPLATE "colour_isp.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

/* 2^bits non-decreasing thresholds in [0, 1], the first 0 */
static int RGBZ_CAT(ci_thresholds_ok, RS)(const REAL *thresholds, int bits)
{
    for (int i = 1; i < (1 << bits); i++)
        if (!(thresholds[i] >= thresholds[i - 1]) || !(thresholds[i] <= (REAL)1)) return 0;
    return thresholds[0] == (REAL)0;
}

int RGBZ_CAT(rgbz_ci_render, RS)(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                                 const int32_t *phase, int mode, int method, const REAL *scale,
                                 REAL black, int clip, const REAL *matrix,
                                 const REAL *thresholds, int bits, void *out, int workers)
{
    if (!src || !out || !phase || !scale || !thresholds || rows < 2 || cols < 2 ||
        (bits != 8 && bits != 16) || (mode != RGBZ_DM_REFLECT && mode != RGBZ_DM_PERIOD) ||
        (method != RGBZ_DM_MALVAR && method != RGBZ_DM_BILINEAR) || !ci_bayer_phase(phase))
        return RGBZ_EINVAL;
    RGBZ_CAT(ci_render_args, RS) a;
    a.phase = phase;
    a.mode = mode;
    a.method = method;
    a.rows = rows;
    a.clip = clip;
    a.black = black;
    for (int i = 0; i < 3; i++) a.scale[i] = scale[i];
    a.has_matrix = matrix != NULL;
    for (int i = 0; i < 9; i++) a.m[i] = matrix ? matrix[i] : (REAL)(i % 4 == 0);
    if (!RGBZ_CAT(ci_thresholds_ok, RS)(thresholds, bits)) return RGBZ_EINVAL;
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
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, CI_RENDER_, st = RGBZ_EINVAL)
#undef CI_RENDER_
    free(colmap);
    free(codes);
    return st;
}

/* white balance alone: ci_balance's arithmetic (isp.white_balance's) into a plain REAL frame,
   bands of rows per thread */
int RGBZ_CAT(rgbz_ci_balance, RS)(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                                  const int32_t *phase, const REAL *scale, REAL black,
                                  int clip, REAL *out, int workers)
{
    if (!src || !out || !phase || !scale || rows < 1 || cols < 1 || !ci_bayer_phase(phase) ||
        in_type < RGBZ_T_U8 || in_type > RGBZ_T_F64)
        return RGBZ_EINVAL;
    const int nt = rgbz_threads_per_values(workers, rows * cols);
    int bad = 0;
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt) reduction(|:bad)
#endif
    {
        ptrdiff_t y0, y1;
        ci_band(rows, &y0, &y1);
        int st = RGBZ_OK;
#define CI_BALANCE_(s, T) RGBZ_CAT3(ci_balance_rows, RS, s)((const T *)src, y0, y1, cols, \
                                                            phase, scale, black, clip, out)
        RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, CI_BALANCE_, st = RGBZ_EINVAL)
#undef CI_BALANCE_
        bad |= st != RGBZ_OK;
    }
    return bad ? RGBZ_EINVAL : RGBZ_OK;
}

/* the render's tail on an RGB image: chunks of CI_CHUNK pixels into 3 planes
   (ci_deinterleave), ci_finish (matrix, codes), interleaved back; bands of pixels per thread */
int RGBZ_CAT(rgbz_ci_encode_rgb, RS)(const REAL *rgb, ptrdiff_t npix, const REAL *matrix,
                                     const REAL *thresholds, int bits, void *out, int workers)
{
    if (npix < 0 || !thresholds || (bits != 8 && bits != 16) || (npix > 0 && (!rgb || !out)))
        return RGBZ_EINVAL;
    if (!RGBZ_CAT(ci_thresholds_ok, RS)(thresholds, bits)) return RGBZ_EINVAL;
    if (npix == 0) return RGBZ_OK;
    RGBZ_CAT(ci_codes, RS) codes;
    void *block = RGBZ_CAT(ci_build_codes, RS)(&codes, thresholds, bits);
    if (!block) return RGBZ_EINVAL;         /* as rgbz_ci_render */
    REAL m[9];
    for (int i = 0; i < 9; i++) m[i] = matrix ? matrix[i] : (REAL)(i % 4 == 0);
    const int nt = rgbz_threads_per_values(workers, npix);
    int bad = 0;
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt) reduction(|:bad)
#endif
    {
        const ptrdiff_t h = CI_CHUNK;
        REAL *lin = (REAL *)malloc((size_t)(3 * h) * sizeof *lin);
        uint16_t *code = (uint16_t *)malloc((size_t)(3 * h) * sizeof *code);
        ptrdiff_t p0, p1;
        ci_band(npix, &p0, &p1);
        if (!lin || !code) {
            bad = 1;
        } else {
            REAL *const pl[3] = {lin, lin + h, lin + 2 * h};
            for (ptrdiff_t s = p0; s < p1; s += CI_CHUNK) {
                const ptrdiff_t n = p1 - s < CI_CHUNK ? p1 - s : CI_CHUNK;
                RGBZ_CAT(ci_deinterleave, RS)(rgb + 3 * s, n, h, lin);
                RGBZ_CAT(ci_finish, RS)(matrix ? m : NULL, &codes, pl, code, h, n);
                if (bits == 8) ci_interleave3_8(code, h, n, (uint8_t *)out + 3 * s);
                else ci_interleave3_16(code, h, n, (uint16_t *)out + 3 * s);
            }
        }
        free(lin);
        free(code);
    }
    free(block);
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}
#else
/* ---------------------------------------------------------------- per element type */

/* the white-balanced row r of the frame into its two planes at dst (CI_PLANE), with the
   border columns -4 .. -1 and cols .. cols + 3 by the border rule: isp.white_balance's
   operations in REAL, kept as double (exact), the type the demosaic computes in */
CI_CLONES static void RGBZ_CAT3(ci_balance, RS, IS)(const IN_T *src, ptrdiff_t r, ptrdiff_t cols,
                                          const RGBZ_CAT(ci_render_args, RS) *a, double *dst)
{
    const IN_T *row = src + r * cols;
    const int32_t *ph = a->phase + 2 * (r & 1);
    const REAL s0 = a->scale[ph[0]], s1 = a->scale[ph[1]], black = a->black;
    const ptrdiff_t hp = CI_PLANE(cols);
    double *e = dst + 3, *o = dst + hp + 3;
    const ptrdiff_t n = cols / 2;
    const int clip = a->clip;
    /* the loop once per value of clip, a constant in each: ci_wb's test is then gone */
#define CI_WB_PLANES_(CLIP)                                                                 \
    for (ptrdiff_t j = 0; j < n; j++) {                                                     \
        e[j] = RGBZ_CAT(ci_wb, RS)((REAL)row[2 * j], black, s0, CLIP);                     \
        o[j] = RGBZ_CAT(ci_wb, RS)((REAL)row[2 * j + 1], black, s1, CLIP);                 \
    }
    if (clip) { CI_WB_PLANES_(1) } else { CI_WB_PLANES_(0) }
#undef CI_WB_PLANES_
    if (cols & 1) e[n] = RGBZ_CAT(ci_wb, RS)((REAL)row[cols - 1], black, s0, clip);
    /* column c lives at (c & 1 ? o : e)[c >> 1] (an arithmetic shift: c >= -4) */
    for (int side = 0; side < 2; side++) {
        for (ptrdiff_t k = 0; k < 4; k++) {
            const ptrdiff_t c = side ? cols + k : -4 + k;
            const ptrdiff_t from = ci_extend(c, cols, a->mode);
            const double v = (from & 1 ? o : e)[from >> 1];
            const ptrdiff_t jc = c >= 0 ? c / 2 : -((-c + 1) / 2);
            (c & 1 ? o : e)[jc] = v;
        }
    }
}

/* every output row: each thread renders a band of consecutive rows, keeping the last 8
   white-balanced rows in a ring (a row r in slot r % 8; the 5 rows of an output row are 5
   consecutive frame rows or fewer after the border rule, so they never share a slot) */
static int RGBZ_CAT3(ci_render, RS, IS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols,
                                        const RGBZ_CAT(ci_render_args, RS) *a, void *out,
                                        int bits, int workers)
{
    const int nt = rgbz_threads_per_values(workers, rows * cols);
    int bad = 0;
    (void)nt;
#ifdef _OPENMP
#pragma omp parallel num_threads(nt) reduction(|:bad)
#endif
    {
        const ptrdiff_t stride = 2 * CI_PLANE(cols), h = cols / 2 + 1;
        double *ring = (double *)malloc((size_t)(8 * stride) * sizeof *ring);
        REAL *lin = (REAL *)malloc((size_t)(6 * h) * sizeof *lin);
        uint16_t *code = (uint16_t *)malloc((size_t)(6 * h) * sizeof *code);
        ptrdiff_t tag[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
        ptrdiff_t y0, y1;
        ci_band(rows, &y0, &y1);
        if (!ring || !lin || !code) {
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
                RGBZ_CAT(ci_row, RS)(rp, y, cols, a, lin, code, out, bits);
            }
        }
        free(ring);
        free(lin);
        free(code);
    }
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}

/* isp.white_balance of rows y0 .. y1 - 1 into out (rows x cols of REAL): the stage's
   operations in its order and type, as ci_balance: (REAL) v - black, times the scale of the
   pixel's colour, clipped to [0, 1] when clip */
CI_CLONES static void RGBZ_CAT3(ci_balance_rows, RS, IS)(const IN_T *src, ptrdiff_t y0,
                                                       ptrdiff_t y1, ptrdiff_t cols,
                                                       const int32_t *phase, const REAL *scale,
                                                       REAL black, int clip, REAL *out)
{
    const ptrdiff_t n = cols / 2;
    for (ptrdiff_t y = y0; y < y1; y++) {
        const IN_T *restrict row = src + y * cols;
        REAL *restrict o = out + y * cols;
        const int32_t *ph = phase + 2 * (y & 1);
        const REAL s0 = scale[ph[0]], s1 = scale[ph[1]];
#define CI_WB_ROW_(CLIP)                                                                    \
        for (ptrdiff_t j = 0; j < n; j++) {                                                 \
            o[2 * j] = RGBZ_CAT(ci_wb, RS)((REAL)row[2 * j], black, s0, CLIP);             \
            o[2 * j + 1] = RGBZ_CAT(ci_wb, RS)((REAL)row[2 * j + 1], black, s1, CLIP);     \
        }
        if (clip) { CI_WB_ROW_(1) } else { CI_WB_ROW_(0) }
#undef CI_WB_ROW_
        if (cols & 1) o[cols - 1] = RGBZ_CAT(ci_wb, RS)((REAL)row[cols - 1], black, s0, clip);
    }
}
#endif
