/*
 * recon_mask1.h -- the Mask1 fast path: every method of recon_site.h for the
 * one geometry of Mask1 (a 2x2 Bayer tile whose green on one colour row is a Z
 * pixel, any phase), with the kernel offsets as compile-time constants.
 *
 * Around every Mask1 Z site: Z at (even, even) offsets, one colour X at
 * (even, odd), the other Y at (odd, even), green at (odd, odd); the four
 * candidates are the greens (-1,-1), (-1,1), (1,-1), (1,1) (Fig. 11: pixels
 * 6, 8, 16, 18). The gradient pairs below are exactly those _plans.py builds
 * for this geometry (same-channel, non-Z pairs; docs/interpretation.md), so
 * the values equal the generic path's up to the order of the additions; the
 * NumPy reference checks both. Interior pixels only: the loop hands the two
 * border rows/columns to the generic path.
 *
 * Included by recon.c with IN_T, IS, IN_IS_INT, REAL, RS, RABSDIFF, REXP_*.
 */
#define M1CAT3(a, b, c) a##_##b##_##c
#define M1CAT(a, b, c) M1CAT3(a, b, c)
#define M1G2(a, b) a##_##b
#define M1G(a, b) M1G2(a, b)

static int M1CAT(rgbz_mask1_rows, IS, RS)(const IN_T *restrict src, IN_T *restrict dst,
                                          ptrdiff_t y, ptrdiff_t cols, int zrow_phase,
                                          int zcol_phase, const rgbz_plan *p,
                                          const rgbz_params *prm, ptrdiff_t x0, ptrdiff_t x1)
{
    const REAL floor_ = (REAL)prm->sigma_floor;
    const REAL rel = (REAL)prm->sigma_rel;
    const REAL maxval = (REAL)prm->maxval;
    const int exp_mode = prm->exp_mode;
    const int method = p->method;
    const int combined = p->use_grad && p->use_sg;
    const REAL alpha = (REAL)p->cand_alpha[0];        /* all four candidates: exp(-1) */
    const ptrdiff_t S = cols;
    (void)zrow_phase;
    ptrdiff_t xs = x0 + ((x0 & 1) != zcol_phase);
    for (ptrdiff_t x = xs; x < x1; x += 2) {
        const IN_T *q = src + y * S + x;
#define P(dy, dx) ((REAL)q[(dy) * S + (dx)])
        REAL c[4] = {P(-1, -1), P(-1, 1), P(1, -1), P(1, 1)};
        REAL r;
        if (method == RGBZ_M_BILINEAR) {
            r = M1G(rgbz_mean, RS)(c, 4);
        } else {
            REAL w[4];
            REAL gam_line[4] = {1, 1, 1, 1};    /* per candidate */
            if (method == RGBZ_M_EDI_CENTRAL || method == RGBZ_M_EDI_LINE || combined) {
                REAL G[4];
                if (method == RGBZ_M_EDI_CENTRAL) {
                    G[0] = OMUL(RABSDIFF(P(1, 0), P(-1, 0)), (REAL)1);
                    G[1] = OMUL(RABSDIFF(P(0, 1), P(0, -1)), (REAL)1);
                    G[2] = OMUL(OADD(OADD(RABSDIFF(P(1, 1), P(-1, -1)), RABSDIFF(P(2, 1), P(-2, -1))),
                                     RABSDIFF(P(1, 2), P(-1, -2))), (REAL)(1.0 / 3.0));
                    G[3] = OMUL(OADD(OADD(RABSDIFF(P(1, -1), P(-1, 1)), RABSDIFF(P(2, -1), P(-2, 1))),
                                     RABSDIFF(P(1, -2), P(-1, 2))), (REAL)(1.0 / 3.0));
                } else {
                    /* eq. 8: rows -2/2 at odd columns, rows -1/1 at every column */
                    REAL v = OADD(RABSDIFF(P(-2, -1), P(2, -1)), RABSDIFF(P(-2, 1), P(2, 1)));
                    v = OADD(v, RABSDIFF(P(-1, -2), P(1, -2)));
                    v = OADD(v, RABSDIFF(P(-1, -1), P(1, -1)));
                    v = OADD(v, RABSDIFF(P(-1, 0), P(1, 0)));
                    v = OADD(v, RABSDIFF(P(-1, 1), P(1, 1)));
                    v = OADD(v, RABSDIFF(P(-1, 2), P(1, 2)));
                    /* eq. 9: the transpose */
                    REAL h = OADD(RABSDIFF(P(-1, -2), P(-1, 2)), RABSDIFF(P(1, -2), P(1, 2)));
                    h = OADD(h, RABSDIFF(P(-2, -1), P(-2, 1)));
                    h = OADD(h, RABSDIFF(P(-1, -1), P(-1, 1)));
                    h = OADD(h, RABSDIFF(P(0, -1), P(0, 1)));
                    h = OADD(h, RABSDIFF(P(1, -1), P(1, 1)));
                    h = OADD(h, RABSDIFF(P(2, -1), P(2, 1)));
                    /* eq. 11 (NW-SE): mirror pairs across the anti-diagonal, (dy,dx)/(-dx,-dy);
                       one green pair and six red/blue ("inter-channel") pairs */
                    REAL d2 = OADD(RABSDIFF(P(-1, 2), P(-2, 1)), RABSDIFF(P(0, 1), P(-1, 0)));
                    d2 = OADD(d2, RABSDIFF(P(1, 0), P(0, -1)));
                    d2 = OADD(d2, RABSDIFF(P(1, 1), P(-1, -1)));
                    d2 = OADD(d2, RABSDIFF(P(1, 2), P(-2, -1)));
                    d2 = OADD(d2, RABSDIFF(P(2, -1), P(1, -2)));
                    d2 = OADD(d2, RABSDIFF(P(2, 1), P(-1, -2)));
                    /* eq. 10 (NE-SW): mirror pairs across the main diagonal, (dy,dx)/(dx,dy) */
                    REAL d3 = OADD(RABSDIFF(P(-1, -2), P(-2, -1)), RABSDIFF(P(0, -1), P(-1, 0)));
                    d3 = OADD(d3, RABSDIFF(P(1, -2), P(-2, 1)));
                    d3 = OADD(d3, RABSDIFF(P(1, -1), P(-1, 1)));
                    d3 = OADD(d3, RABSDIFF(P(1, 0), P(0, 1)));
                    d3 = OADD(d3, RABSDIFF(P(2, -1), P(-1, 2)));
                    d3 = OADD(d3, RABSDIFF(P(2, 1), P(1, 2)));
                    G[0] = OMUL(v, (REAL)(1.0 / 7.0));
                    G[1] = OMUL(h, (REAL)(1.0 / 7.0));
                    G[2] = OMUL(d2, (REAL)(1.0 / 7.0));
                    G[3] = OMUL(d3, (REAL)(1.0 / 7.0));
                }
                REAL gam[4];
                M1G(rgbz_gammas4, RS)(G, 4, floor_, rel, exp_mode, gam);
                gam_line[0] = gam[2];     /* (-1,-1): NW-SE */
                gam_line[1] = gam[3];     /* (-1, 1): NE-SW */
                gam_line[2] = gam[3];
                gam_line[3] = gam[2];
            }
            if (method == RGBZ_M_SG) {
                REAL dv2 = RABSDIFF(P(0, -1), P(-2, -1)), dv3 = RABSDIFF(P(0, -1), P(2, -1));
                REAL dv6 = RABSDIFF(P(0, 1), P(-2, 1)), dv7 = RABSDIFF(P(0, 1), P(2, 1));
                REAL dh2 = RABSDIFF(P(-1, 0), P(-1, -2)), dh3 = RABSDIFF(P(-1, 0), P(-1, 2));
                REAL dh6 = RABSDIFF(P(1, 0), P(1, -2)), dh7 = RABSDIFF(P(1, 0), P(1, 2));
                const REAL half = (REAL)0.5;
                REAL SG[8] = {OMUL(OADD(dv2, dv6), half), OMUL(OADD(dv3, dv7), half),   /* N S */
                              OMUL(OADD(dh2, dh6), half), OMUL(OADD(dh3, dh7), half),   /* W E */
                              OMUL(OADD(dv2, dh2), half), OMUL(OADD(dv6, dh3), half),   /* NW NE */
                              OMUL(OADD(dv3, dh6), half), OMUL(OADD(dv7, dh7), half)};  /* SW SE */
                REAL g[8];
                M1G(rgbz_gammas4, RS)(SG, 8, floor_, rel, exp_mode, g);
                w[0] = OADD(OADD(g[0], g[2]), g[4]);   /* eq. 19a: N + W + NW */
                w[1] = OADD(OADD(g[0], g[3]), g[5]);   /* 19b: N + E + NE */
                w[2] = OADD(OADD(g[1], g[2]), g[6]);   /* 19c: S + W + SW */
                w[3] = OADD(OADD(g[1], g[3]), g[7]);   /* 19d: S + E + SE */
            }
            if (method != RGBZ_M_SG || combined) {
                /* alpha * beta (eqs. 2-4), times gamma (eq. 6) */
                REAL d01 = RABSDIFF(c[0], c[1]), d02 = RABSDIFF(c[0], c[2]);
                REAL d03 = RABSDIFF(c[0], c[3]), d12 = RABSDIFF(c[1], c[2]);
                REAL d13 = RABSDIFF(c[1], c[3]), d23 = RABSDIFF(c[2], c[3]);
                REAL Sk[4] = {OADD(OADD(OADD((REAL)1, d01), d02), d03),
                              OADD(OADD(OADD((REAL)1, d01), d12), d13),
                              OADD(OADD(OADD((REAL)1, d02), d12), d23),
                              OADD(OADD(OADD((REAL)1, d03), d13), d23)};
                for (int k = 0; k < 4; k++) {
                    REAL a = ODIV(alpha, Sk[k]);
                    if (method != RGBZ_M_BI) a = OMUL(a, gam_line[k]);
                    w[k] = combined ? OMUL(a, w[k]) : a;
                }
            }
            REAL den = OADD(OADD(OADD(w[0], w[1]), w[2]), w[3]);
            if (!(den > (REAL)0)) {
                r = M1G(rgbz_mean, RS)(c, 4);
            } else {
                REAL num = OMUL(w[1], OSUB(c[1], c[0]));
                num = OADD(num, OMUL(w[2], OSUB(c[2], c[0])));
                num = OADD(num, OMUL(w[3], OSUB(c[3], c[0])));
                r = OADD(c[0], ODIV(num, den));
            }
        }
#undef P
        if (!(r > (REAL)0)) r = (REAL)0;
        if (r > maxval) r = maxval;
#if IN_IS_INT
        dst[y * S + x] = (IN_T)(r + (REAL)0.5);
#else
        dst[y * S + x] = (IN_T)r;
#endif
    }
    return RGBZ_OK;
}

/*
 * SG on Mask1 (the paper's method, eqs. 14-19, sg_mode "pure"), written for the
 * vector units: the sites of a row are processed in blocks of M1_BLOCK, one
 * branch-free loop per step (gather + semi-gradients + eq. 7's arguments; the
 * exponentials; weights + eq. 5), so that the compiler vectorises each loop
 * (the stride-2 loads become shuffles). The operations and their order per site
 * are those of rgbz_mask1_rows above (the opcount build counts the same), so
 * the results are the same to the last bit up to the compiler's vector/scalar
 * code generation (no FMA contraction in ISO C mode).
 */
#ifndef M1_BLOCK
#define M1_BLOCK 128
#endif
RGBZ_CLONES static void M1CAT(rgbz_mask1_sg_rows, IS, RS)(const IN_T *restrict src, IN_T *restrict dst,
                                               ptrdiff_t y, ptrdiff_t cols, int zcol_phase,
                                               const rgbz_params *prm, ptrdiff_t x0, ptrdiff_t x1)
{
    const REAL floor_ = (REAL)prm->sigma_floor;
    const REAL rel = (REAL)prm->sigma_rel;
    const REAL maxval = (REAL)prm->maxval;
    const int fast_exp = prm->exp_mode == RGBZ_EXP_FAST;
    const ptrdiff_t S = cols;
    const ptrdiff_t xs = x0 + ((x0 & 1) != zcol_phase);
    const ptrdiff_t n_all = xs < x1 ? (x1 - xs + 1) / 2 : 0;
    const IN_T *restrict rm2 = src + (y - 2) * S, *restrict rm1 = src + (y - 1) * S;
    const IN_T *restrict r00 = src + y * S;
    const IN_T *restrict rp1 = src + (y + 1) * S, *restrict rp2 = src + (y + 2) * S;
    REAL arg[8][M1_BLOCK];
    REAL cand[4][M1_BLOCK];
    IN_T res[M1_BLOCK];
    const REAL half = (REAL)0.5;

    for (ptrdiff_t b0 = 0; b0 < n_all; b0 += M1_BLOCK) {
        const int n = (int)(n_all - b0 < M1_BLOCK ? n_all - b0 : M1_BLOCK);
        const ptrdiff_t xb = xs + 2 * b0;
        /* 1: gather, semi-gradients (eqs. 14-18), sigma and the arguments of eq. 7 */
        for (int k = 0; k < n; k++) {
            const ptrdiff_t x = xb + 2 * k;
            const REAL a_m2m1 = (REAL)rm2[x - 1], a_m2p1 = (REAL)rm2[x + 1];
            const REAL a_m1m2 = (REAL)rm1[x - 2], a_m1m1 = (REAL)rm1[x - 1], a_m10 = (REAL)rm1[x];
            const REAL a_m1p1 = (REAL)rm1[x + 1], a_m1p2 = (REAL)rm1[x + 2];
            const REAL a_0m1 = (REAL)r00[x - 1], a_0p1 = (REAL)r00[x + 1];
            const REAL a_p1m2 = (REAL)rp1[x - 2], a_p1m1 = (REAL)rp1[x - 1], a_p10 = (REAL)rp1[x];
            const REAL a_p1p1 = (REAL)rp1[x + 1], a_p1p2 = (REAL)rp1[x + 2];
            const REAL a_p2m1 = (REAL)rp2[x - 1], a_p2p1 = (REAL)rp2[x + 1];
            const REAL dv2 = RABSDIFF(a_0m1, a_m2m1), dv3 = RABSDIFF(a_0m1, a_p2m1);
            const REAL dv6 = RABSDIFF(a_0p1, a_m2p1), dv7 = RABSDIFF(a_0p1, a_p2p1);
            const REAL dh2 = RABSDIFF(a_m10, a_m1m2), dh3 = RABSDIFF(a_m10, a_m1p2);
            const REAL dh6 = RABSDIFF(a_p10, a_p1m2), dh7 = RABSDIFF(a_p10, a_p1p2);
            REAL g[8];
            g[0] = OMUL(OADD(dv2, dv6), half);   /* N */
            g[1] = OMUL(OADD(dv3, dv7), half);   /* S */
            g[2] = OMUL(OADD(dh2, dh6), half);   /* W */
            g[3] = OMUL(OADD(dh3, dh7), half);   /* E */
            g[4] = OMUL(OADD(dv2, dh2), half);   /* NW */
            g[5] = OMUL(OADD(dv6, dh3), half);   /* NE */
            g[6] = OMUL(OADD(dv3, dh6), half);   /* SW */
            g[7] = OMUL(OADD(dv7, dh7), half);   /* SE */
            /* eq. 7: sigma = max(min SG, floor, rel * mean SG) -- as rgbz_gammas4 */
            REAL gmin = g[0], gsum = g[0];
            for (int j = 1; j < 8; j++) {
                gmin = OCMP(g[j] < gmin) ? g[j] : gmin;
                gsum = rel > (REAL)0 ? OADD(gsum, g[j]) : gsum;   /* counted only if used */
            }
            REAL sigma = OCMP(gmin > floor_) ? gmin : floor_;
            if (rel > (REAL)0) {
                const REAL rfloor = ODIV(OMUL(rel, gsum), (REAL)8);
                sigma = OCMP(rfloor > sigma) ? rfloor : sigma;
            }
            const REAL inv = ODIV((REAL)1, OMUL((REAL)2, OMUL(sigma, sigma)));
            for (int j = 0; j < 8; j++) arg[j][k] = -OMUL(OMUL(g[j], g[j]), inv);
            cand[0][k] = a_m1m1;
            cand[1][k] = a_m1p1;
            cand[2][k] = a_p1m1;
            cand[3][k] = a_p1p1;
        }
        /* 2: the eight exponentials of eq. 7 per site */
        for (int j = 0; j < 8; j++) {
            REAL *restrict a = arg[j];
            if (fast_exp) {
                for (int k = 0; k < n; k++) a[k] = REXP_FAST(a[k]);
            } else {
                for (int k = 0; k < n; k++) a[k] = REXP_LIBM(a[k]);
            }
        }
#ifdef RGBZ_COUNT_OPS
        for (int k = 0; k < 8 * n; k++) OPC_(RGBZ_OP_EXP);
#endif
        /* 3: weights (eq. 19) and the weighted mean (eq. 5) */
        for (int k = 0; k < n; k++) {
            const REAL c0 = cand[0][k], c1 = cand[1][k], c2 = cand[2][k], c3 = cand[3][k];
            const REAL w0 = OADD(OADD(arg[0][k], arg[2][k]), arg[4][k]);   /* 19a: N + W + NW */
            const REAL w1 = OADD(OADD(arg[0][k], arg[3][k]), arg[5][k]);   /* 19b: N + E + NE */
            const REAL w2 = OADD(OADD(arg[1][k], arg[2][k]), arg[6][k]);   /* 19c: S + W + SW */
            const REAL w3 = OADD(OADD(arg[1][k], arg[3][k]), arg[7][k]);   /* 19d: S + E + SE */
            const REAL den = OADD(OADD(OADD(w0, w1), w2), w3);
            REAL num = OMUL(w1, OSUB(c1, c0));
            num = OADD(num, OMUL(w2, OSUB(c2, c0)));
            num = OADD(num, OMUL(w3, OSUB(c3, c0)));
            /* den >= exp(-1/2) for finite input (sigma >= the smallest SG); the mean
               (rgbz_mean's formula) covers non-finite input */
            const REAL mean = c0 + (((c1 - c0) + (c2 - c0)) + (c3 - c0)) / (REAL)4;
            const REAL q = den > (REAL)0 ? den : (REAL)1;
            REAL r = den > (REAL)0 ? OADD(c0, ODIV(num, q)) : mean;
#ifdef RGBZ_COUNT_OPS
            if (!(den > (REAL)0)) {     /* the fallback mean: 6 additions, 1 division */
                for (int i = 0; i < 6; i++) OPC_(RGBZ_OP_ADD);
                OPC_(RGBZ_OP_DIV);
            }
#endif
            r = r > (REAL)0 ? r : (REAL)0;    /* also maps a NaN to 0 */
            r = r > maxval ? maxval : r;
#if IN_IS_INT
            res[k] = (IN_T)(r + (REAL)0.5);
#else
            res[k] = (IN_T)r;
#endif
        }
        IN_T *restrict d = dst + y * S + xb;
        for (int k = 0; k < n; k++) d[2 * k] = res[k];
    }
}

/*
 * BI, EDICentral and EDILine on Mask1 (eqs. 2-13), in the same block form as
 * rgbz_mask1_sg_rows: (1) the four gradients, sigma and eq. 7's arguments,
 * (2) the exponentials, (3) alpha * beta * gamma and the weighted mean. The
 * operations per site are those of rgbz_mask1_rows (same counts, same order).
 */
RGBZ_CLONES static void M1CAT(rgbz_mask1_ab_rows, IS, RS)(const IN_T *restrict src,
                                                           IN_T *restrict dst, ptrdiff_t y,
                                                           ptrdiff_t cols, int zcol_phase,
                                                           const rgbz_plan *p,
                                                           const rgbz_params *prm, ptrdiff_t x0,
                                                           ptrdiff_t x1)
{
    const REAL floor_ = (REAL)prm->sigma_floor;
    const REAL rel = (REAL)prm->sigma_rel;
    const REAL maxval = (REAL)prm->maxval;
    const int fast_exp = prm->exp_mode == RGBZ_EXP_FAST;
    const int method = p->method;
    const REAL alpha = (REAL)p->cand_alpha[0];        /* all four candidates: exp(-1) */
    const ptrdiff_t S = cols;
    const ptrdiff_t xs = x0 + ((x0 & 1) != zcol_phase);
    const ptrdiff_t n_all = xs < x1 ? (x1 - xs + 1) / 2 : 0;
    const IN_T *restrict rm2 = src + (y - 2) * S, *restrict rm1 = src + (y - 1) * S;
    const IN_T *restrict r00 = src + y * S;
    const IN_T *restrict rp1 = src + (y + 1) * S, *restrict rp2 = src + (y + 2) * S;
    REAL arg[4][M1_BLOCK];
    IN_T res[M1_BLOCK];
    if (method == RGBZ_M_BI)
        /* BI has no gamma; step 3 may still read these (the compiler turns its
           "times gamma unless BI" into a blend), so give them a harmless 1 rather
           than indeterminate stack bytes (denormal garbage cost BI 2x its time) */
        for (int j = 2; j < 4; j++)
            for (int k = 0; k < M1_BLOCK; k++) arg[j][k] = (REAL)1;

    for (ptrdiff_t b0 = 0; b0 < n_all; b0 += M1_BLOCK) {
        const int n = (int)(n_all - b0 < M1_BLOCK ? n_all - b0 : M1_BLOCK);
        const ptrdiff_t xb = xs + 2 * b0;
        if (method != RGBZ_M_BI) {
            /* 1: the gradients of eqs. 6 (central) or 8-11 (axes), sigma, eq. 7's arguments */
            for (int k = 0; k < n; k++) {
                const ptrdiff_t x = xb + 2 * k;
#define Q(dy, dx) ((REAL)((dy) == -2 ? rm2 : (dy) == -1 ? rm1 : (dy) == 0 ? r00 : (dy) == 1 ? rp1 : rp2)[x + (dx)])
                REAL G[4];
                if (method == RGBZ_M_EDI_CENTRAL) {
                    G[0] = OMUL(RABSDIFF(Q(1, 0), Q(-1, 0)), (REAL)1);
                    G[1] = OMUL(RABSDIFF(Q(0, 1), Q(0, -1)), (REAL)1);
                    G[2] = OMUL(OADD(OADD(RABSDIFF(Q(1, 1), Q(-1, -1)), RABSDIFF(Q(2, 1), Q(-2, -1))),
                                     RABSDIFF(Q(1, 2), Q(-1, -2))), (REAL)(1.0 / 3.0));
                    G[3] = OMUL(OADD(OADD(RABSDIFF(Q(1, -1), Q(-1, 1)), RABSDIFF(Q(2, -1), Q(-2, 1))),
                                     RABSDIFF(Q(1, -2), Q(-1, 2))), (REAL)(1.0 / 3.0));
                } else {
                    REAL v = OADD(RABSDIFF(Q(-2, -1), Q(2, -1)), RABSDIFF(Q(-2, 1), Q(2, 1)));
                    v = OADD(v, RABSDIFF(Q(-1, -2), Q(1, -2)));
                    v = OADD(v, RABSDIFF(Q(-1, -1), Q(1, -1)));
                    v = OADD(v, RABSDIFF(Q(-1, 0), Q(1, 0)));
                    v = OADD(v, RABSDIFF(Q(-1, 1), Q(1, 1)));
                    v = OADD(v, RABSDIFF(Q(-1, 2), Q(1, 2)));
                    REAL h = OADD(RABSDIFF(Q(-1, -2), Q(-1, 2)), RABSDIFF(Q(1, -2), Q(1, 2)));
                    h = OADD(h, RABSDIFF(Q(-2, -1), Q(-2, 1)));
                    h = OADD(h, RABSDIFF(Q(-1, -1), Q(-1, 1)));
                    h = OADD(h, RABSDIFF(Q(0, -1), Q(0, 1)));
                    h = OADD(h, RABSDIFF(Q(1, -1), Q(1, 1)));
                    h = OADD(h, RABSDIFF(Q(2, -1), Q(2, 1)));
                    REAL d2 = OADD(RABSDIFF(Q(-1, 2), Q(-2, 1)), RABSDIFF(Q(0, 1), Q(-1, 0)));
                    d2 = OADD(d2, RABSDIFF(Q(1, 0), Q(0, -1)));
                    d2 = OADD(d2, RABSDIFF(Q(1, 1), Q(-1, -1)));
                    d2 = OADD(d2, RABSDIFF(Q(1, 2), Q(-2, -1)));
                    d2 = OADD(d2, RABSDIFF(Q(2, -1), Q(1, -2)));
                    d2 = OADD(d2, RABSDIFF(Q(2, 1), Q(-1, -2)));
                    REAL d3 = OADD(RABSDIFF(Q(-1, -2), Q(-2, -1)), RABSDIFF(Q(0, -1), Q(-1, 0)));
                    d3 = OADD(d3, RABSDIFF(Q(1, -2), Q(-2, 1)));
                    d3 = OADD(d3, RABSDIFF(Q(1, -1), Q(-1, 1)));
                    d3 = OADD(d3, RABSDIFF(Q(1, 0), Q(0, 1)));
                    d3 = OADD(d3, RABSDIFF(Q(2, -1), Q(-1, 2)));
                    d3 = OADD(d3, RABSDIFF(Q(2, 1), Q(1, 2)));
                    G[0] = OMUL(v, (REAL)(1.0 / 7.0));
                    G[1] = OMUL(h, (REAL)(1.0 / 7.0));
                    G[2] = OMUL(d2, (REAL)(1.0 / 7.0));
                    G[3] = OMUL(d3, (REAL)(1.0 / 7.0));
                }
#undef Q
                REAL gmin = G[0], gsum = G[0];
                for (int j = 1; j < 4; j++) {
                    gmin = OCMP(G[j] < gmin) ? G[j] : gmin;
                    gsum = rel > (REAL)0 ? OADD(gsum, G[j]) : gsum;
                }
                REAL sigma = OCMP(gmin > floor_) ? gmin : floor_;
                if (rel > (REAL)0) {
                    const REAL rfloor = ODIV(OMUL(rel, gsum), (REAL)4);
                    sigma = OCMP(rfloor > sigma) ? rfloor : sigma;
                }
                const REAL inv = ODIV((REAL)1, OMUL((REAL)2, OMUL(sigma, sigma)));
                /* only the diagonal gammas weigh a Mask1 candidate; the axis ones set sigma */
                arg[0][k] = (REAL)0;
                arg[1][k] = (REAL)0;
                arg[2][k] = -OMUL(OMUL(G[2], G[2]), inv);
                arg[3][k] = -OMUL(OMUL(G[3], G[3]), inv);
            }
            /* 2: the exponentials (only the two diagonal ones are used) */
            for (int j = 2; j < 4; j++) {
                REAL *restrict a = arg[j];
                if (fast_exp) {
                    for (int k = 0; k < n; k++) a[k] = REXP_FAST(a[k]);
                } else {
                    for (int k = 0; k < n; k++) a[k] = REXP_LIBM(a[k]);
                }
            }
#ifdef RGBZ_COUNT_OPS
            for (int k = 0; k < 2 * n; k++) OPC_(RGBZ_OP_EXP);
#endif
        }
        /* 3: alpha * beta (eqs. 2-4) times gamma (eq. 6), weighted mean (eqs. 12-13) */
        for (int k = 0; k < n; k++) {
            const ptrdiff_t x = xb + 2 * k;
            const REAL c0 = (REAL)rm1[x - 1], c1 = (REAL)rm1[x + 1];
            const REAL c2 = (REAL)rp1[x - 1], c3 = (REAL)rp1[x + 1];
            const REAL d01 = RABSDIFF(c0, c1), d02 = RABSDIFF(c0, c2);
            const REAL d03 = RABSDIFF(c0, c3), d12 = RABSDIFF(c1, c2);
            const REAL d13 = RABSDIFF(c1, c3), d23 = RABSDIFF(c2, c3);
            REAL w0 = ODIV(alpha, OADD(OADD(OADD((REAL)1, d01), d02), d03));
            REAL w1 = ODIV(alpha, OADD(OADD(OADD((REAL)1, d01), d12), d13));
            REAL w2 = ODIV(alpha, OADD(OADD(OADD((REAL)1, d02), d12), d23));
            REAL w3 = ODIV(alpha, OADD(OADD(OADD((REAL)1, d03), d13), d23));
            if (method != RGBZ_M_BI) {
                const REAL g2 = arg[2][k], g3 = arg[3][k];
                w0 = OMUL(w0, g2);     /* (-1,-1): NW-SE */
                w1 = OMUL(w1, g3);     /* (-1, 1): NE-SW */
                w2 = OMUL(w2, g3);
                w3 = OMUL(w3, g2);
            }
            const REAL den = OADD(OADD(OADD(w0, w1), w2), w3);
            REAL num = OMUL(w1, OSUB(c1, c0));
            num = OADD(num, OMUL(w2, OSUB(c2, c0)));
            num = OADD(num, OMUL(w3, OSUB(c3, c0)));
            /* the plain mean (rgbz_mean's formula) when every weight underflows */
            const REAL mean = c0 + (((c1 - c0) + (c2 - c0)) + (c3 - c0)) / (REAL)4;
            const REAL q = den > (REAL)0 ? den : (REAL)1;
            REAL r = den > (REAL)0 ? OADD(c0, ODIV(num, q)) : mean;
#ifdef RGBZ_COUNT_OPS
            if (!(den > (REAL)0)) {     /* the fallback mean: 6 additions, 1 division */
                for (int i = 0; i < 6; i++) OPC_(RGBZ_OP_ADD);
                OPC_(RGBZ_OP_DIV);
            }
#endif
            r = r > (REAL)0 ? r : (REAL)0;
            r = r > maxval ? maxval : r;
#if IN_IS_INT
            res[k] = (IN_T)(r + (REAL)0.5);
#else
            res[k] = (IN_T)r;
#endif
        }
        IN_T *restrict d = dst + y * S + xb;
        for (int k = 0; k < n; k++) d[2 * k] = res[k];
    }
}

#undef M1CAT
#undef M1CAT3
#undef M1G
#undef M1G2
