/*
 * demosaic_menon.c -- Menon, Andriani & Calvagno (2007) demosaicing with directional
 * filtering and a posteriori decision (DDFAPD), with its refining step, as a C kernel.
 *
 * D. Menon, S. Andriani, G. Calvagno, "Demosaicing with directional filtering and a
 * posteriori decision", IEEE Trans. Image Processing 16(1), 2007. The algorithm is
 * colour-demosaicing's demosaicing_CFA_Bayer_Menon2007 (refining_step=True), operation for
 * operation, so that the result is the reference's bit for bit (tests/isp/test_demosaic.py):
 *   - scipy.ndimage.convolve1d of a symmetric odd filter w computes
 *     x[0] * w[0] + (x[-1] + x[1]) * w[1] + ..., pairs from the outermost in (ni_filters.c,
 *     its symmetric branch); a pair whose weight is 0 adds +-0, which changes no finite sum
 *     (only the sign of a zero), so it is left out here;
 *   - scipy.ndimage.convolve of the 5x5 decision kernel k flips k and adds the nonzero taps
 *     in raster order of the flipped kernel, from 0.0 (dmm_decide_row lists them);
 *   - every multiply and add rounded on its own: this file is compiled with
 *     -ffp-contract=off (csrc/meson.build), as NumPy's ufuncs do not fuse.
 * The borders are the reference's: _cnv_h/_cnv_v are convolve1d(mode="mirror") and the shift
 * of D_H/D_V is np.pad(mode="reflect"), both the whole-sample mirror (d c b | a b c d | c b
 * a), applied to each intermediate plane at the frame's edge (dmm_mirror; it keeps the
 * parity, so a mirrored tap has the colour of the tap it stands for); the decision sums are
 * convolve(mode="constant"), zeros outside the frame. Any size from 2x2 up is the reference's
 * (the mirror of a 2-pixel axis repeats it: a b | a b | a b).
 *
 * The stages, in the reference's terms (C the CFA, per row q of the frame):
 *   CFA  C as double, padded by the mirror;
 *   GHV  G_H, G_V: C at the green sites, else the directional filters h_0 + h_1;
 *   D    D_H = |C_H(x) - C_H(x + 2)|, D_V likewise down, C_H = C - G_H at red and blue;
 *   G    d_H, d_V (the 5x5 sums), M = d_V >= d_H, G = M ? G_H : G_V;
 *   S    red and blue at the green sites (the reference's first four np.where);
 *   X    the other colour at the red and blue sites (its last two);
 *   G1   the refined green at the red and blue sites (refining_step_Menon2007's first part);
 *   RB2  the refined red and blue at the green sites (its second part);
 *   the output row: the refined blue at red sites and red at blue sites (its last part).
 * Each stage reads the ones before it at most 2 rows up or down. A band of output rows is
 * computed row by row, each stage in a ring of its last few rows (dmm_ensure computes a
 * stage's rows on demand, its inputs first), so that the scratch of a band is a few dozen
 * rows, not planes of the frame, and each row is computed once (plus the rows of a band's
 * margin). A value is the same function of the CFA whatever band computes it, so the result
 * does not depend on the thread count.
 *
 * Borders (rgbz_demosaic_mode): RGBZ_DM_REFLECT, the reference's own (above); RGBZ_DM_PERIOD,
 * the reference on the CFA padded by DMM_PERIOD_PAD pixels shifted by whole periods, cropped
 * (what rgbz_fast.isp.demosaic gave before this kernel): the stages run on that virtual frame,
 * whose rows and columns map to the CFA's (dmm_period).
 *
 * Layout: src rows x cols row-major (in_type: an rgbz_type); dst rows x cols x 3 (R, G, B)
 * row-major, float or double; phase the 2x2 quad's colours in raster order (R=0, G=1, B=2).
 * Arithmetic in double; no clipping (the reference does not clip).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include "rgbz.h"
#include "rgbz_ops.h"

/* the columns on each side of a row in a ring: the horizontal taps reach x +- 2 */
#define DMM_PAD 2
/* RGBZ_DM_PERIOD: the margin of whole periods around the CFA (the one rgbz_fast.isp.demosaic
   gave colour-demosaicing before this kernel). Beyond the CFA it repeats the CFA's last
   period, which the frame's own mirror leaves as it is, so a wider margin gives the same
   image (tests/isp/test_demosaic.py compares with the reference padded by 8) */
#define DMM_PERIOD_PAD 8

/* the stages (each computes one row of its rings at a time) */
enum { DMM_CFA, DMM_GHV, DMM_D, DMM_G, DMM_S, DMM_X, DMM_G1, DMM_RB2, DMM_NSTAGES };
/* the rings of double rows; M (the decision, uint8) is the stage G's second ring */
enum { R_CFA, R_GH, R_GV, R_DH, R_DV, R_G, R_RS, R_BS, R_X, R_G1, R_R2, R_B2, DMM_NRINGS };
static const int dmm_stage_of[DMM_NRINGS] = {DMM_CFA, DMM_GHV, DMM_GHV, DMM_D, DMM_D, DMM_G,
                                             DMM_S, DMM_S, DMM_X, DMM_G1, DMM_RB2, DMM_RB2};
/* Rows of each ring: one more than the fewest with which every row a stage reads is still in
   its ring (the CFA's 11: the stage GHV runs 8 rows ahead of the output row and reads 2
   beyond it, the output row reads its own). These spans follow from the order of the
   dmm_ensure calls, the same for every frame; they were found by building with
   -DDMM_CHECK_RINGS (a read of a row no longer or not yet in its ring fails the call) on
   frames of 2 to 57 rows, in bands of 1 row and up, with both borders. */
static const int dmm_ring_rows[DMM_NSTAGES] = {12, 6, 6, 6, 6, 2, 4, 4};
/* the up-margin of each stage: how many rows above a band's first output row it computes
   (the sum of the upward reaches on the path to the output row) */
static const int dmm_margin[DMM_NSTAGES] = {8, 6, 6, 4, 3, 0, 2, 1};

typedef struct {
    const void *src;
    int in_type, out_f64;
    ptrdiff_t rows, cols;      /* the CFA */
    ptrdiff_t vrows, vcols;    /* the frame the stages run on (the CFA, or padded) */
    ptrdiff_t pad;             /* output pixel (y, x) is the frame's (y + pad, x + pad) */
    const ptrdiff_t *rmap, *cmap;  /* the frame's rows, columns in the CFA (NULL: the same) */
    const int32_t *phase;
    void *dst;
    ptrdiff_t stride;          /* of a ring row: vcols + 2 DMM_PAD */
    double *ring[DMM_NRINGS];
    uint8_t *m;                /* the decision M, dmm_ring_rows[DMM_G] rows of vcols */
    const double *zero;        /* a row of zeros: D outside the frame (mode "constant") */
    const uint8_t *green;      /* 2 rows of vcols: 1 at the green sites of even, odd rows */
    ptrdiff_t next[DMM_NSTAGES];   /* each stage has computed its rows [first, next) */
#ifdef DMM_CHECK_RINGS
    ptrdiff_t first[DMM_NSTAGES];
    int *bad;
#endif
} dmm_ctx;

/* the whole-sample mirror (scipy 'mirror', np.pad 'reflect') of index i on n >= 2 */
static inline ptrdiff_t dmm_mirror(ptrdiff_t i, ptrdiff_t n)
{
    const ptrdiff_t period = 2 * (n - 1);
    i %= period;
    if (i < 0) i += period;
    return i < n ? i : period - i;
}

/* the source of index i of an axis of n padded by pad on each side, shifted back by whole
   periods (rgbz_fast.isp._demosaic's former _period_index) */
static inline ptrdiff_t dmm_period(ptrdiff_t i, ptrdiff_t n, ptrdiff_t pad)
{
    i -= pad;
    if (i < 0) return i + 2 * ((-i + 1) / 2);
    if (i >= n) return i - 2 * ((i - n + 2) / 2);
    return i;
}

/* row q (in the frame) of a ring; dmm_ensure has computed it */
static inline double *dmm_row(const dmm_ctx *c, int ring, ptrdiff_t q)
{
    const int s = dmm_stage_of[ring];
#ifdef DMM_CHECK_RINGS
    if (q < c->first[s] || q >= c->next[s] || q < c->next[s] - dmm_ring_rows[s]) *c->bad = 1;
#endif
    return c->ring[ring] + (q % dmm_ring_rows[s]) * c->stride + DMM_PAD;
}

/* the row a stage is computing (row q of its ring) */
static inline double *dmm_slot(const dmm_ctx *c, int ring, ptrdiff_t q)
{
    return c->ring[ring] + (q % dmm_ring_rows[dmm_stage_of[ring]]) * c->stride + DMM_PAD;
}

/* row q + d of a ring, mirrored into the frame */
static inline const double *dmm_near(const dmm_ctx *c, int ring, ptrdiff_t q, ptrdiff_t d)
{
    return dmm_row(c, ring, dmm_mirror(q + d, c->vrows));
}

/* the decision M of row q (check: as dmm_row; the stage G computing it: 0) */
static inline uint8_t *dmm_m(const dmm_ctx *c, ptrdiff_t q, int check)
{
#ifdef DMM_CHECK_RINGS
    const ptrdiff_t nx = c->next[DMM_G];
    if (check && (q < c->first[DMM_G] || q >= nx || q < nx - dmm_ring_rows[DMM_G])) *c->bad = 1;
#else
    (void)check;
#endif
    return c->m + (q % dmm_ring_rows[DMM_G]) * c->vcols;
}

/* the padding of a ring row by the mirror */
static void dmm_pad_mirror(double *p, ptrdiff_t n)
{
    for (ptrdiff_t d = 1; d <= DMM_PAD; d++) {
        p[-d] = p[dmm_mirror(-d, n)];
        p[n - 1 + d] = p[dmm_mirror(n - 1 + d, n)];
    }
}

/* whether row q holds red (else blue) */
static inline int dmm_red_row(const int32_t *phase, ptrdiff_t q)
{
    return phase[2 * (q & 1)] == 0 || phase[2 * (q & 1) + 1] == 0;
}

static void dmm_run(dmm_ctx *c, int stage, ptrdiff_t q);

/* computes the rows of `stage` up to r (at most the frame's last) */
static void dmm_ensure(dmm_ctx *c, int stage, ptrdiff_t r)
{
    if (r > c->vrows - 1) r = c->vrows - 1;
    while (c->next[stage] <= r) {
        dmm_run(c, stage, c->next[stage]);
        c->next[stage]++;
    }
}

/* CFA: row q as double, padded */
static void dmm_cfa(dmm_ctx *c, ptrdiff_t q)
{
    double *restrict p = dmm_slot(c, R_CFA, q);
    const ptrdiff_t n = c->vcols, sy = c->rmap ? c->rmap[q] : q;
    const ptrdiff_t *cm = c->cmap;
#define DMM_LOAD_(s, T)                                                  \
    {                                                                   \
        const T *sr = (const T *)c->src + sy * c->cols;                 \
        if (cm)                                                         \
            for (ptrdiff_t x = 0; x < n; x++) p[x] = (double)sr[cm[x]]; \
        else                                                            \
            for (ptrdiff_t x = 0; x < n; x++) p[x] = (double)sr[x];     \
    }
    RGBZ_SWITCH_TYPE(c->in_type, RGBZ_ELEMENT_TYPES, DMM_LOAD_, (void)0)
#undef DMM_LOAD_
    dmm_pad_mirror(p, n);
}

/*
 * The pixel loops of the stages, over n pixels of a row from its pointers (restrict: the rows
 * of different rings never overlap), so that they vectorise: every value is computed at every
 * pixel and the colour picks it by a select (green[x]: 1 at the row's green sites; a stage's
 * values at the sites it is not for are never read), with every load unconditional.
 * RGBZ_CLONES: the AVX2 clone computes the same IEEE operations (-ffp-contract=off).
 */

/* GHV: h_0 + h_1 along the row (h) and down the column (v), C at the green sites */
RGBZ_CLONES static void dmm_ghv_row(const double *restrict c0, const double *restrict u1,
                                    const double *restrict d1, const double *restrict u2,
                                    const double *restrict d2, const uint8_t *restrict green,
                                    double *restrict gh, double *restrict gv, ptrdiff_t n)
{
    for (ptrdiff_t x = 0; x < n; x++) {
        const double c = c0[x];
        const double h =
            (c0[x - 1] + c0[x + 1]) * 0.5 + (c * 0.5 + (c0[x - 2] + c0[x + 2]) * -0.25);
        const double v = (u1[x] + d1[x]) * 0.5 + (c * 0.5 + (u2[x] + d2[x]) * -0.25);
        gh[x] = green[x] ? c : h;
        gv[x] = green[x] ? c : v;
    }
}

/* D: |C_H(x) - C_H(x + 2)| and |C_V(y) - C_V(y + 2)|; at a green site G_H = G_V = C, so
   C_H = C_V = 0 there (x + 2 has the colour of x, also where the pad mirrors it) and D is 0,
   as the reference's C_H, which is 0 at the green sites */
RGBZ_CLONES static void dmm_d_row(const double *restrict c0, const double *restrict c2,
                                  const double *restrict gh, const double *restrict gv0,
                                  const double *restrict gv2, double *restrict dh,
                                  double *restrict dv, ptrdiff_t n)
{
    for (ptrdiff_t x = 0; x < n; x++) {
        dh[x] = fabs((c0[x] - gh[x]) - (c0[x + 2] - gh[x + 2]));
        dv[x] = fabs((c0[x] - gv0[x]) - (c2[x] - gv2[x]));
    }
}

/* G: the decision sums (h: D_H rows y-2..y+2, v: D_V rows y-2..y), M = d_V >= d_H and the
   green it picks (at the green sites G_H = G_V = C) */
RGBZ_CLONES static void dmm_decide_row(const double *restrict h0, const double *restrict h1,
                                       const double *restrict h2, const double *restrict h3,
                                       const double *restrict h4, const double *restrict v0,
                                       const double *restrict v1, const double *restrict v2,
                                       const double *restrict gh, const double *restrict gv,
                                       double *restrict g, uint8_t *restrict m, ptrdiff_t n)
{
    for (ptrdiff_t x = 0; x < n; x++) {
        const double sh = h0[x - 2] + h0[x] + h1[x - 1] + h2[x - 2] * 3.0 + h2[x] * 3.0 +
                          h3[x - 1] + h4[x - 2] + h4[x];
        const double sv = v0[x - 2] + v0[x] * 3.0 + v0[x + 2] + v1[x - 1] + v1[x + 1] +
                          v2[x - 2] + v2[x] * 3.0 + v2[x + 2];
        const double a = gh[x], b = gv[x];
        const int mh = sv >= sh;
        m[x] = (uint8_t)mh;
        g[x] = mh ? a : b;
    }
}

/* S and RB2: the colour estimated along the row (hz) and the one down the column (vt) at
   the green sites, in the reference's order of operations: S, G + _cnv(R, k_b) -
   _cnv(G, k_b) (the neighbours' R is C; G is C at the site); RB2, G1 + _cnv(R - G1, k_b)
   (G1 is C at the site, R - G1 is C - G1 at its neighbours) */
RGBZ_CLONES static void dmm_s_row(const double *restrict c0, const double *restrict cu,
                                  const double *restrict cd, const double *restrict g0,
                                  const double *restrict gu, const double *restrict gd,
                                  double *restrict hz, double *restrict vt, ptrdiff_t n)
{
    for (ptrdiff_t x = 0; x < n; x++) {
        const double g = g0[x];
        hz[x] = (g + (c0[x - 1] + c0[x + 1]) * 0.5) - (g0[x - 1] + g0[x + 1]) * 0.5;
        vt[x] = (g + (cu[x] + cd[x]) * 0.5) - (gu[x] + gd[x]) * 0.5;
    }
}

RGBZ_CLONES static void dmm_rb2_row(const double *restrict c0, const double *restrict cu,
                                    const double *restrict cd, const double *restrict g0,
                                    const double *restrict gu, const double *restrict gd,
                                    double *restrict hz, double *restrict vt, ptrdiff_t n)
{
    for (ptrdiff_t x = 0; x < n; x++) {
        const double c = c0[x];
        hz[x] = c + ((c0[x - 1] - g0[x - 1]) + (c0[x + 1] - g0[x + 1])) * 0.5;
        vt[x] = c + ((cu[x] - gu[x]) + (cd[x] - gd[x])) * 0.5;
    }
}

/* X: c + (o(x-1) + o(x+1)) / 2 - (s(x-1) + s(x+1)) / 2 along the row where M, else down
   the column (o: the colour the site gets, s: its own, both of S at the green neighbours) */
RGBZ_CLONES static void dmm_x_row(const double *restrict c0, const double *restrict o0,
                                  const double *restrict s0, const double *restrict ou,
                                  const double *restrict od, const double *restrict su,
                                  const double *restrict sd, const uint8_t *restrict m,
                                  double *restrict xo, ptrdiff_t n)
{
    for (ptrdiff_t x = 0; x < n; x++) {
        const double c = c0[x];
        const double hz = (c + (o0[x - 1] + o0[x + 1]) * 0.5) - (s0[x - 1] + s0[x + 1]) * 0.5;
        const double vt = (c + (ou[x] + od[x]) * 0.5) - (su[x] + sd[x]) * 0.5;
        xo[x] = m[x] ? hz : vt;
    }
}

/* G1: C - _cnv(D, FIR) along the row where M, else down the column, D = C - G at the site
   and s - C at its green neighbours (s: S's estimate of the site's colour); C at green */
RGBZ_CLONES static void dmm_g1_row(const double *restrict c0, const double *restrict cu,
                                   const double *restrict cd, const double *restrict g0,
                                   const double *restrict s0, const double *restrict su,
                                   const double *restrict sd, const uint8_t *restrict m,
                                   const uint8_t *restrict green, double *restrict g1,
                                   ptrdiff_t n)
{
    const double t = 1.0 / 3;   /* ones(3) / 3 */
    for (ptrdiff_t x = 0; x < n; x++) {
        const double c = c0[x], d0 = c - g0[x];
        const double hz = d0 * t + ((s0[x - 1] - c0[x - 1]) + (s0[x + 1] - c0[x + 1])) * t;
        const double vt = d0 * t + ((su[x] - cu[x]) + (sd[x] - cd[x])) * t;
        const double refined = c - (m[x] ? hz : vt);
        g1[x] = green[x] ? c : refined;
    }
}

/* the output row: at a green site (R2, C, B2); at a red one (C, G1, C - f), at a blue one
   (C + f, G1, C), f = _cnv(R - B, FIR) along the row where M, else down the column, R - B
   being C - X at red, X - C at blue (the same number negated, exactly) and R2 - B2 at the
   green neighbours; out_f64 a constant in each instance below */
RGBZ_INLINE void dmm_out_row_(const double *restrict c0, const double *restrict g1,
                              const double *restrict xo, const double *restrict r0,
                              const double *restrict b0, const double *restrict ru,
                              const double *restrict rd, const double *restrict bu,
                              const double *restrict bd, const uint8_t *restrict m,
                              const uint8_t *restrict green, int red, void *restrict dst,
                              int out_f64, ptrdiff_t n)
{
    const double t = 1.0 / 3;
    for (ptrdiff_t x = 0; x < n; x++) {
        const double c = c0[x], cx = c - xo[x];
        const double d0 = red ? cx : -cx;
        const double hz = d0 * t + ((r0[x - 1] - b0[x - 1]) + (r0[x + 1] - b0[x + 1])) * t;
        const double vt = d0 * t + ((ru[x] - bu[x]) + (rd[x] - bd[x])) * t;
        const double f = m[x] ? hz : vt;
        const double r = red ? c : c + f, b = red ? c - f : c;
        const double gr = r0[x], gg = g1[x], gb = b0[x];
        const double rgb0 = green[x] ? gr : r, rgb1 = green[x] ? c : gg;
        const double rgb2 = green[x] ? gb : b;
        if (out_f64) {
            double *o = (double *)dst + 3 * x;
            o[0] = rgb0;
            o[1] = rgb1;
            o[2] = rgb2;
        } else {
            float *o = (float *)dst + 3 * x;
            o[0] = (float)rgb0;
            o[1] = (float)rgb1;
            o[2] = (float)rgb2;
        }
    }
}
#define DMM_OUT_ARGS_                                                                         \
    const double *restrict c0, const double *restrict g1, const double *restrict xo,         \
        const double *restrict r0, const double *restrict b0, const double *restrict ru,     \
        const double *restrict rd, const double *restrict bu, const double *restrict bd,     \
        const uint8_t *restrict m, const uint8_t *restrict green, int red, void *restrict dst, \
        ptrdiff_t n
RGBZ_CLONES static void dmm_out_row_f64(DMM_OUT_ARGS_)
{
    dmm_out_row_(c0, g1, xo, r0, b0, ru, rd, bu, bd, m, green, red, dst, 1, n);
}
RGBZ_CLONES static void dmm_out_row_f32(DMM_OUT_ARGS_)
{
    dmm_out_row_(c0, g1, xo, r0, b0, ru, rd, bu, bd, m, green, red, dst, 0, n);
}
#undef DMM_OUT_ARGS_

/* ---- the stages: row q of the frame, from the rows of the stages before ---- */

/* the green mask of row q (1 at its green sites) */
static inline const uint8_t *dmm_green(const dmm_ctx *c, ptrdiff_t q)
{
    return c->green + (q & 1) * c->vcols;
}

/* GHV: G_H and G_V of row q. The reference: np.where(G_m == 0, _cnv_h(C, h_0) +
   _cnv_h(C, h_1), G), h_0 = [0, .5, 0, .5, 0] (its pairs (x-2, x+2) and x weigh 0),
   h_1 = [-.25, 0, .5, 0, -.25] (its pair (x-1, x+1) weighs 0) */
static void dmm_ghv(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_CFA, q + 2);
    double *gh = dmm_slot(c, R_GH, q), *gv = dmm_slot(c, R_GV, q);
    dmm_ghv_row(dmm_row(c, R_CFA, q), dmm_near(c, R_CFA, q, -1), dmm_near(c, R_CFA, q, 1),
                dmm_near(c, R_CFA, q, -2), dmm_near(c, R_CFA, q, 2), dmm_green(c, q), gh, gv,
                c->vcols);
    dmm_pad_mirror(gh, c->vcols);   /* D reads C_H at x + 2 */
}

/* D: D_H and D_V of row q: |C_H - C_H shifted left by 2| and |C_V - C_V shifted up by 2|
   (np.pad "reflect" beyond the edge), C_H = C - G_H at the red and blue sites, 0 at green;
   padded by zeros (the decision sums' mode "constant") */
static void dmm_d(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_GHV, q + 2);
    const ptrdiff_t q2 = dmm_mirror(q + 2, c->vrows), n = c->vcols;
    double *dh = dmm_slot(c, R_DH, q), *dv = dmm_slot(c, R_DV, q);
    dmm_d_row(dmm_row(c, R_CFA, q), dmm_row(c, R_CFA, q2), dmm_row(c, R_GH, q),
              dmm_row(c, R_GV, q), dmm_row(c, R_GV, q2), dh, dv, n);
    for (ptrdiff_t d = 1; d <= DMM_PAD; d++)
        dh[-d] = dh[n - 1 + d] = dv[-d] = dv[n - 1 + d] = 0.0;
}

/* G: the decision of row q and the green it picks. d_H = convolve(D_H, k), d_V =
   convolve(D_V, k.T), mode "constant": scipy correlates with the flipped kernel, adding its
   nonzero taps in raster order from 0.0 (0.0 + a is a: D >= 0); rows outside the frame
   are zeros */
static void dmm_decide(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_D, q + 2);
    const double *h[5];
    for (int d = -2; d <= 2; d++)
        h[d + 2] = q + d >= 0 && q + d < c->vrows ? dmm_row(c, R_DH, q + d) : c->zero + DMM_PAD;
    const double *v0 = q >= 2 ? dmm_row(c, R_DV, q - 2) : c->zero + DMM_PAD;
    const double *v1 = q >= 1 ? dmm_row(c, R_DV, q - 1) : c->zero + DMM_PAD;
    double *g = dmm_slot(c, R_G, q);
    dmm_decide_row(h[0], h[1], h[2], h[3], h[4], v0, v1, dmm_row(c, R_DV, q),
                   dmm_row(c, R_GH, q), dmm_row(c, R_GV, q), g, dmm_m(c, q, 0), c->vcols);
    dmm_pad_mirror(g, c->vcols);
}

/* S: red and blue at the green sites of row q (the reference's R and B after its first four
   np.where): G + _cnv(R, k_b) - _cnv(G, k_b), k_b = [.5, 0, .5], along the row for the
   colour of the row, down the column for the other */
static void dmm_s(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_G, q + 1);
    double *rs = dmm_slot(c, R_RS, q), *bs = dmm_slot(c, R_BS, q);
    const int red = dmm_red_row(c->phase, q);
    dmm_s_row(dmm_row(c, R_CFA, q), dmm_near(c, R_CFA, q, -1), dmm_near(c, R_CFA, q, 1),
              dmm_row(c, R_G, q), dmm_near(c, R_G, q, -1), dmm_near(c, R_G, q, 1),
              red ? rs : bs, red ? bs : rs, c->vcols);
    dmm_pad_mirror(rs, c->vcols);
    dmm_pad_mirror(bs, c->vcols);
}

/* X: the other colour at the red and blue sites of row q (the reference's last two
   np.where): at blue, M ? B + _cnv_h(R) - _cnv_h(B) : the same down the column, the
   neighbours green sites (S); at red, the same with R and B swapped */
static void dmm_x(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_S, q + 1);
    const int red = dmm_red_row(c->phase, q);
    const int o = red ? R_BS : R_RS, s = red ? R_RS : R_BS;
    dmm_x_row(dmm_row(c, R_CFA, q), dmm_row(c, o, q), dmm_row(c, s, q), dmm_near(c, o, q, -1),
              dmm_near(c, o, q, 1), dmm_near(c, s, q, -1), dmm_near(c, s, q, 1),
              dmm_m(c, q, 1), dmm_slot(c, R_X, q), c->vcols);
}

/* G1: the refined green at the red and blue sites of row q: C - (M ? _cnv_h(D, FIR) :
   _cnv_v(D, FIR)), D = R - G for red (B - G for blue), FIR = [1/3] * 3 */
static void dmm_g1(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_S, q + 1);
    const int s = dmm_red_row(c->phase, q) ? R_RS : R_BS;
    double *g1 = dmm_slot(c, R_G1, q);
    dmm_g1_row(dmm_row(c, R_CFA, q), dmm_near(c, R_CFA, q, -1), dmm_near(c, R_CFA, q, 1),
               dmm_row(c, R_G, q), dmm_row(c, s, q), dmm_near(c, s, q, -1),
               dmm_near(c, s, q, 1), dmm_m(c, q, 1), dmm_green(c, q), g1, c->vcols);
    dmm_pad_mirror(g1, c->vcols);
}

/* RB2: the refined red and blue at the green sites of row q: G1 + _cnv(R - G1, k_b) for red,
   along the row in a red row, down the column in a blue one; blue likewise. G1 is C at a
   green site; the neighbours are red (blue) sites, where R - G1 is C - G1 */
static void dmm_rb2(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_G1, q + 1);
    double *r2 = dmm_slot(c, R_R2, q), *b2 = dmm_slot(c, R_B2, q);
    const int red = dmm_red_row(c->phase, q);
    dmm_rb2_row(dmm_row(c, R_CFA, q), dmm_near(c, R_CFA, q, -1), dmm_near(c, R_CFA, q, 1),
                dmm_row(c, R_G1, q), dmm_near(c, R_G1, q, -1), dmm_near(c, R_G1, q, 1),
                red ? r2 : b2, red ? b2 : r2, c->vcols);
    dmm_pad_mirror(r2, c->vcols);
    dmm_pad_mirror(b2, c->vcols);
}

static void dmm_run(dmm_ctx *c, int stage, ptrdiff_t q)
{
    switch (stage) {
    case DMM_CFA: dmm_cfa(c, q); break;
    case DMM_GHV: dmm_ghv(c, q); break;
    case DMM_D: dmm_d(c, q); break;
    case DMM_G: dmm_decide(c, q); break;
    case DMM_S: dmm_s(c, q); break;
    case DMM_X: dmm_x(c, q); break;
    case DMM_G1: dmm_g1(c, q); break;
    default: dmm_rb2(c, q); break;
    }
}

/* output row q of the frame (the CFA's q - pad): at red sites blue is R - _cnv(R - B, FIR),
   at blue sites red is B + _cnv(R - B, FIR), along the row where M, with R - B at the site
   from X and at the green neighbours R2 - B2 */
static void dmm_out(dmm_ctx *c, ptrdiff_t q)
{
    dmm_ensure(c, DMM_RB2, q + 1);
    dmm_ensure(c, DMM_X, q);
    const ptrdiff_t p = c->pad;   /* even: the parity of a column is that of its pixel */
    const int red = dmm_red_row(c->phase, q);
    const double *c0 = dmm_row(c, R_CFA, q) + p, *g1 = dmm_row(c, R_G1, q) + p;
    const double *xo = dmm_row(c, R_X, q) + p;
    const double *r0 = dmm_row(c, R_R2, q) + p, *b0 = dmm_row(c, R_B2, q) + p;
    const double *ru = dmm_near(c, R_R2, q, -1) + p, *rd = dmm_near(c, R_R2, q, 1) + p;
    const double *bu = dmm_near(c, R_B2, q, -1) + p, *bd = dmm_near(c, R_B2, q, 1) + p;
    const uint8_t *m = dmm_m(c, q, 1) + p, *green = dmm_green(c, q) + p;
    const ptrdiff_t i = 3 * (q - p) * c->cols;
    if (c->out_f64)
        dmm_out_row_f64(c0, g1, xo, r0, b0, ru, rd, bu, bd, m, green, red, (double *)c->dst + i,
                        c->cols);
    else
        dmm_out_row_f32(c0, g1, xo, r0, b0, ru, rd, bu, bd, m, green, red, (float *)c->dst + i,
                        c->cols);
}

/* output rows [y0, y1) of the CFA: RGBZ_OK or RGBZ_ENOMEM */
static int dmm_band(const dmm_ctx *proto, ptrdiff_t y0, ptrdiff_t y1, int *bad)
{
    dmm_ctx c = *proto;
    size_t nrows = 1;   /* the zero row */
    for (int r = 0; r < DMM_NRINGS; r++) nrows += (size_t)dmm_ring_rows[dmm_stage_of[r]];
    double *buf = (double *)calloc(nrows * (size_t)c.stride, sizeof(double));
    uint8_t *m = (uint8_t *)calloc((size_t)dmm_ring_rows[DMM_G] * (size_t)c.vcols, 1);
    if (!buf || !m) {
        free(buf);
        free(m);
        return RGBZ_ENOMEM;
    }
    double *p = buf;
    for (int r = 0; r < DMM_NRINGS; r++) {
        c.ring[r] = p;
        p += (ptrdiff_t)dmm_ring_rows[dmm_stage_of[r]] * c.stride;
    }
    c.zero = p;
    c.m = m;
    for (int s = 0; s < DMM_NSTAGES; s++) {
        const ptrdiff_t f = y0 + c.pad - dmm_margin[s];
        c.next[s] = f > 0 ? f : 0;
#ifdef DMM_CHECK_RINGS
        c.first[s] = c.next[s];
#endif
    }
#ifdef DMM_CHECK_RINGS
    c.bad = bad;
#else
    (void)bad;
#endif
    for (ptrdiff_t y = y0 + c.pad; y < y1 + c.pad; y++) dmm_out(&c, y);
    free(buf);
    free(m);
    return RGBZ_OK;
}

int rgbz_demosaic_menon(int in_type, int out_type, const void *src, void *dst, ptrdiff_t rows,
                        ptrdiff_t cols, const int32_t *phase, int mode, int workers)
{
    dmm_ctx c;
    memset(&c, 0, sizeof c);
    c.src = src;
    c.dst = dst;
    c.in_type = in_type;
    c.out_f64 = out_type == RGBZ_T_F64;
    c.rows = rows;
    c.cols = cols;
    c.phase = phase;
    c.pad = mode == RGBZ_DM_PERIOD ? DMM_PERIOD_PAD : 0;
    c.vrows = rows + 2 * c.pad;
    c.vcols = cols + 2 * c.pad;
    c.stride = c.vcols + 2 * DMM_PAD;
    /* the period maps, and the green masks of the even and odd rows (an even margin keeps the
       Bayer arrangement: the frame's phase is the CFA's) */
    const size_t nmap = c.pad ? (size_t)(c.vrows + c.vcols) : 0;
    ptrdiff_t *maps = (ptrdiff_t *)malloc(nmap * sizeof(ptrdiff_t) + (size_t)(2 * c.vcols));
    if (!maps) return RGBZ_ENOMEM;
    if (c.pad) {
        for (ptrdiff_t i = 0; i < c.vrows; i++) maps[i] = dmm_period(i, rows, c.pad);
        for (ptrdiff_t i = 0; i < c.vcols; i++) maps[c.vrows + i] = dmm_period(i, cols, c.pad);
        c.rmap = maps;
        c.cmap = maps + c.vrows;
    }
    uint8_t *green = (uint8_t *)(maps + nmap);
    for (ptrdiff_t i = 0; i < 2 * c.vcols; i++)
        green[i] = phase[2 * (i >= c.vcols) + ((i % c.vcols) & 1)] == 1;
    c.green = green;
    /* one band of rows per thread: a band computes the rows of its margin again (about 8
       rows of each stage), which the 2^18 pixels per thread (kernel_threads) make small */
    const int nth = rgbz_threads(workers);
    const ptrdiff_t nb = nth < rows ? nth : rows;
    int bad = 0, check = 0;
    RGBZ_PARALLEL_FOR_OR(bad)
    for (ptrdiff_t b = 0; b < nb; b++)
        bad |= dmm_band(&c, rows * b / nb, rows * (b + 1) / nb, &check) != RGBZ_OK;
    free(maps);
    if (bad) return RGBZ_ENOMEM;
    return check ? RGBZ_EINVAL : RGBZ_OK;
}
