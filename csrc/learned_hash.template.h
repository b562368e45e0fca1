/*
 * learned_hash.template.h -- what the learned kernel (learned.template.h) and the z_guided
 * kernel (z_guided.template.h) share for one element type and one precision: the hash of a
 * block of sites from their taps (the generic path) or from box sums (the fast path), the
 * dot product of the taps, the fast path's rows and its dense dot product, and the gather of
 * the taps. Included by both templates (instantiated through rgbz_each_type.h, with IN_T,
 * IS, IN_IS_INT, REAL and RS), after learned_common.h.
 */
#if !defined(IN_T) || !defined(IS) || !defined(IN_IS_INT) || !defined(REAL) || !defined(RS)
#error "learned_hash.template.h: define IN_T, IS, IN_IS_INT, REAL and RS"
#endif

/* the buckets of n sites from their direction energies e[d][j] and their colour energies
   ec[c][j] (learned.h) */
static inline void LRN_CAT(lrn_bucket, IS, RS)(REAL (*restrict e)[LRN_BLK],
                                               REAL (*restrict ec)[LRN_BLK], int n,
                                               const rgbz_learned_filters *f, int k,
                                               int32_t *restrict bucket)
{
    const int ns = f->n_str, nc = f->n_coh, nk = f->n_spr;
    const double *st = f->str_thr + (ptrdiff_t)k * (ns - 1);
    const double *ct = f->coh_thr2 + (ptrdiff_t)k * (nc - 1);
    const double *kt = f->spr_thr + (ptrdiff_t)k * (nk - 1);
    const REAL C = (REAL)0.92387953251128674, S = (REAL)0.38268343236508978;
    REAL tt[LRN_BLK], m2[LRN_BLK];         /* written for j < n before any read */
    LRN_IVDEP for (int j = 0; j < n; j++) {
        const REAL a = OSUB(e[0][j], e[1][j]);
        const REAL b = OMUL(OSUB(e[2][j], e[3][j]), (REAL)0.5);
        const REAL t = OADD(OMUL(OADD(e[0][j], e[1][j]), (REAL)0.5),
                            OMUL(OADD(e[2][j], e[3][j]), (REAL)0.25));
        /* the doubled-angle vector rotated by 22.5 degrees, then its octant */
        const REAL ar = OSUB(OMUL(C, a), OMUL(S, b));
        const REAL br = OADD(OMUL(S, a), OMUL(C, b));
        const int neg = OCMP(br < 0);
        const REAL ar1 = neg ? -ar : ar, br1 = neg ? -br : br;
        const int left = OCMP(ar1 < 0);
        const REAL ar2 = left ? br1 : ar1, br2 = left ? -ar1 : br1;
        bucket[j] = (4 * neg + 2 * left + OCMP(br2 > ar2)) * (ns * nc * nk);
        tt[j] = t;
        m2[j] = OADD(OMUL(a, a), OMUL(b, b));
    }
    for (int i = 0; i < ns - 1; i++) {
        const REAL thr = (REAL)st[i];
        LRN_IVDEP for (int j = 0; j < n; j++) bucket[j] += OCMP(tt[j] > thr) ? nc * nk : 0;
    }
    if (nc > 1) {
        LRN_IVDEP for (int j = 0; j < n; j++) tt[j] = OMUL(tt[j], tt[j]);
        for (int i = 0; i < nc - 1; i++) {
            const REAL thr = (REAL)ct[i];
            LRN_IVDEP for (int j = 0; j < n; j++)
                bucket[j] += OCMP(m2[j] > OMUL(thr, tt[j])) ? nk : 0;
        }
    }
    if (nk > 1) {
        /* the largest and the smallest colour energy (tt: largest, m2: smallest) */
        LRN_IVDEP for (int j = 0; j < n; j++) {
            const REAL r = ec[0][j], g = ec[1][j], b = ec[2][j];
            const REAL hi1 = OCMP(g > r) ? g : r, lo1 = OCMP(g > r) ? r : g;
            tt[j] = OCMP(b > hi1) ? b : hi1;
            m2[j] = OCMP(b < lo1) ? b : lo1;
        }
        for (int i = 0; i < nk - 1; i++) {
            const REAL thr = (REAL)kt[i];
            LRN_IVDEP for (int j = 0; j < n; j++) bucket[j] += OCMP(tt[j] > OMUL(thr, m2[j]));
        }
    }
}

/* the bucket of one site, lrn_bucket's arithmetic in its order, from its direction energies
   e0 .. e3 and (spread: a constant where it is inlined) its colour energies r, g, b, with at
   most two thresholds of each kind: st, ct, kt hold them padded with +inf (a padded strength
   or coherence level never counts: t > inf and m2 > inf * t^2 are false, inf * 0 is NaN;
   likewise a padded spread level); ms, mc: the bucket steps of a strength and a coherence
   level, mo that of an octant */
LRN_INLINE int32_t LRN_CAT(lrn_bucket1, IS, RS)(REAL e0, REAL e1, REAL e2, REAL e3, REAL r,
                                               REAL g, REAL b_, const int spread,
                                               const REAL *st, const REAL *ct, const REAL *kt,
                                               int32_t mo, int32_t ms, int32_t mc)
{
    const REAL C = (REAL)0.92387953251128674, S = (REAL)0.38268343236508978;
    const REAL a = OSUB(e0, e1);
    const REAL b = OMUL(OSUB(e2, e3), (REAL)0.5);
    const REAL t = OADD(OMUL(OADD(e0, e1), (REAL)0.5), OMUL(OADD(e2, e3), (REAL)0.25));
    const REAL ar = OSUB(OMUL(C, a), OMUL(S, b));
    const REAL br = OADD(OMUL(S, a), OMUL(C, b));
    const int neg = OCMP(br < 0);
    const REAL ar1 = neg ? -ar : ar, br1 = neg ? -br : br;
    const int left = OCMP(ar1 < 0);
    const REAL ar2 = left ? br1 : ar1, br2 = left ? -ar1 : br1;
    int32_t bk = (4 * neg + 2 * left + OCMP(br2 > ar2)) * mo;
    const REAL m2 = OADD(OMUL(a, a), OMUL(b, b)), t2 = OMUL(t, t);
    bk += (OCMP(t > st[0]) ? ms : 0) + (OCMP(t > st[1]) ? ms : 0);
    bk += (OCMP(m2 > OMUL(ct[0], t2)) ? mc : 0) + (OCMP(m2 > OMUL(ct[1], t2)) ? mc : 0);
    if (spread) {
        const REAL hi1 = OCMP(g > r) ? g : r, lo1 = OCMP(g > r) ? r : g;
        const REAL hi = OCMP(b_ > hi1) ? b_ : hi1, lo = OCMP(b_ < lo1) ? b_ : lo1;
        bk += OCMP(hi > OMUL(kt[0], lo)) + OCMP(hi > OMUL(kt[1], lo));
    }
    return bk;
}

/* the buckets of the n sites whose taps are v[t][j] (phase k); every loop runs over the
   sites (to the run-time n, so that the compiler vectorises it rather than unrolling it) */
LRN_CLONES
static void LRN_CAT(lrn_hash, IS, RS)(REAL (*restrict v)[LRN_BLK], int n,
                                       const rgbz_learned_filters *f, int k,
                                       int32_t *restrict bucket)
{
    REAL e[RGBZ_LEARNED_DIRS][LRN_BLK];
    REAL ec[3][LRN_BLK];
    const int spread = f->n_spr > 1;
    for (int c = 0; c < 3; c++)
        for (int j = 0; j < n; j++) ec[c][j] = 0;
    for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
        const int np = f->n_pairs[k * RGBZ_LEARNED_DIRS + d];
        const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * f->n_pairs_max;
        const int32_t *pa = f->pair_a + o, *pb = f->pair_b + o, *pc = f->pair_col + o;
        REAL *restrict ed = e[d];
        {   /* the first pair sets the sum */
            const REAL *restrict va = v[pa[0]], *restrict vb = v[pb[0]];
            REAL *restrict ecp = ec[pc[0]];
            LRN_IVDEP for (int j = 0; j < n; j++) {
                const REAL df = OSUB(va[j], vb[j]);
                ed[j] = OMUL(df, df);
            }
            if (spread && d < RGBZ_LEARNED_SPREAD_DIRS)
                LRN_IVDEP for (int j = 0; j < n; j++) ecp[j] = OADD(ecp[j], ed[j]);
        }
        LRN_NOJAM for (int p = 1; p < np; p++) {
            const REAL *restrict va = v[pa[p]], *restrict vb = v[pb[p]];
            REAL *restrict ecp = ec[pc[p]];
            if (spread && d < RGBZ_LEARNED_SPREAD_DIRS) {
                LRN_IVDEP for (int j = 0; j < n; j++) {
                    const REAL df = OSUB(va[j], vb[j]);
                    const REAL sq = OMUL(df, df);
                    ed[j] = OADD(ed[j], sq);
                    ecp[j] = OADD(ecp[j], sq);
                }
            } else {
                LRN_IVDEP for (int j = 0; j < n; j++) {
                    const REAL df = OSUB(va[j], vb[j]);
                    ed[j] = OADD(ed[j], OMUL(df, df));
                }
            }
        }
        const REAL inv = (REAL)1 / (REAL)np;
        LRN_IVDEP for (int j = 0; j < n; j++) ed[j] = OMUL(ed[j], inv);
    }
    if (spread)
        for (int c = 0; c < 3; c++) {
            const REAL inv = (REAL)f->inv_col[k * 3 + c];
            LRN_IVDEP for (int j = 0; j < n; j++) ec[c][j] = OMUL(ec[c][j], inv);
        }
    LRN_CAT(lrn_bucket, IS, RS)(e, ec, n, f, k, bucket);
}

/* res[j] = sum_t w[t][bucket[j]] * v[t][j] */
LRN_CLONES
static void LRN_CAT(lrn_dot, IS, RS)(REAL (*restrict v)[LRN_BLK], int n, const REAL *restrict w,
                                      int n_taps, int n_buckets, const int32_t *restrict bucket,
                                      REAL *restrict res)
{
    LRN_IVDEP for (int j = 0; j < n; j++) res[j] = OMUL(w[bucket[j]], v[0][j]);
    LRN_NOJAM for (int t = 1; t < n_taps; t++) {
        const REAL *restrict wt = w + (ptrdiff_t)t * n_buckets;
        const REAL *restrict vt = v[t];
        LRN_IVDEP for (int j = 0; j < n; j++) res[j] = OADD(res[j], OMUL(wt[bucket[j]], vt[j]));
    }
}

/*
 * The fast path of a row (radius <= 3, learned.h's dense weights). The hash energies are
 * box sums: for direction d, E_d of the site at x is the sum over the rectangle of pair
 * starts (learned.h) of D_d = V_d (I(p + s_d) - I(p))^2, V_d = 1 where both pixels are
 * known, times 1 / n_d. Each thread keeps two rings of LRN_RING rows, indexed by the
 * logical row (outside the frame: moved back by whole periods, so a function of the row
 * alone): the frame rows as REAL (converted once, read by the differences and the dot
 * products) and, per direction, the rows of D_d (computed once, read by the three or four
 * Z rows whose rectangles hold them). The sums then run down the ring rows, for every
 * column of the row at once (cs), and along the row (bx), in the order of the per-site
 * formulation's box sums: contiguous loops over x. The dot product reads each window row
 * as 8 contiguous REAL pixels against the bucket's dense weights.
 */

/* the ring row of logical row Y (slot Y mod LRN_RING), or -1 before it is computed */
static inline int LRN_CAT(lrn_slot, IS, RS)(ptrdiff_t Y)
{
    return (int)(((Y % LRN_RING) + LRN_RING) % LRN_RING);
}

/* logical row Y as REAL: the frame row itself when it is already REAL, else its slot of the
   ring (columns ra .. rb - 1 converted once; tag[slot] says which logical row a slot holds) */
static const REAL *LRN_CAT(lrn_real_row, IS, RS)(const IN_T *src, ptrdiff_t rows,
                                                  ptrdiff_t cols, int py, ptrdiff_t Y,
                                                  ptrdiff_t ra, ptrdiff_t rb, REAL *ring,
                                                  ptrdiff_t *tag)
{
    const IN_T *restrict s = src + lrn_extend(Y, rows, py) * cols;
#if !IN_IS_INT
    if (sizeof(IN_T) == sizeof(REAL)) return (const REAL *)(const void *)s;
#endif
    const int slot = LRN_CAT(lrn_slot, IS, RS)(Y);
    REAL *restrict r = ring + (ptrdiff_t)slot * cols;
    if (tag[slot] != Y) {
        LRN_IVDEP for (ptrdiff_t x = ra; x < rb; x++) r[x] = (REAL)s[x];
        tag[slot] = Y;
    }
    return r;
}

/* D[x] = v[x] (b[x] - a[x])^2 for x in [xa, xb) (b already shifted by the step's columns) */
LRN_CLONES
static void LRN_CAT(lrn_dsq, IS, RS)(REAL *restrict D, const REAL *restrict a,
                                      const REAL *restrict b, const REAL *restrict v,
                                      ptrdiff_t xa, ptrdiff_t xb)
{
    LRN_IVDEP for (ptrdiff_t x = xa; x < xb; x++) {
        const REAL df = OSUB(b[x], a[x]);
        D[x] = OMUL(v[x], OMUL(df, df));
    }
}

/* c[x] = sum over nr rows i of D_i[x], in the order of i (nr is a constant where it is
   inlined, so that the rows unroll and x vectorises; one pass, one store per x) */
LRN_INLINE void LRN_CAT(lrn_colsum, IS, RS)(REAL *restrict c, const REAL *const *D,
                                               const int nr, ptrdiff_t xa, ptrdiff_t xb)
{
    LRN_IVDEP for (ptrdiff_t x = xa; x < xb; x++) {
        REAL s = 0;
        for (int i = 0; i < nr; i++) s = OADD(s, D[i][x]);
        c[x] = s;
    }
}

/* c[x] = sum over the nr rows D_i of D_i[x], in the order of i, for any nr (the constant
   row counts of the box sums unrolled) */
LRN_INLINE void LRN_CAT(lrn_sum_rows, IS, RS)(REAL *restrict c, const REAL *const *D, int nr,
                                                 ptrdiff_t xa, ptrdiff_t xb)
{
    switch (nr) {
    case 1: LRN_CAT(lrn_colsum, IS, RS)(c, D, 1, xa, xb); break;
    case 2: LRN_CAT(lrn_colsum, IS, RS)(c, D, 2, xa, xb); break;
    case 3: LRN_CAT(lrn_colsum, IS, RS)(c, D, 3, xa, xb); break;
    case 4: LRN_CAT(lrn_colsum, IS, RS)(c, D, 4, xa, xb); break;
    case 5: LRN_CAT(lrn_colsum, IS, RS)(c, D, 5, xa, xb); break;
    case 7: LRN_CAT(lrn_colsum, IS, RS)(c, D, 7, xa, xb); break;
    default: LRN_CAT(lrn_colsum, IS, RS)(c, D, nr, xa, xb);
    }
}

/* the row stage of one direction at n sites x = x0 + m PX (c0, c1: its column sums, the rows
   of even and of odd offset from the rectangle's first row, already moved by its first
   column; nc columns; PX and nc are constants where it is inlined): bxd[m] the box sum of
   site m and, when split, k[2 r + p][m] (+)= the part of the rows of offset parity r and the
   columns of offset parity p (assigned when first, else added). Unsplit, c0 holds every row
   and c1 is not read. */
LRN_INLINE void LRN_CAT(lrn_rowstage, IS, RS)(const REAL *restrict c0, const REAL *restrict c1,
                                                 const int nc, const int split, const int first,
                                                 ptrdiff_t x0, const int PX, int n,
                                                 REAL *restrict bxd, REAL *restrict k0,
                                                 REAL *restrict k1, REAL *restrict k2,
                                                 REAL *restrict k3)
{
    if (!split) {
        LRN_IVDEP for (int m = 0; m < n; m++) {
            const ptrdiff_t x = x0 + (ptrdiff_t)m * PX;
            REAL s = 0;
            for (int j = 0; j < nc; j++) s = OADD(s, c0[x + j]);
            bxd[m] = s;
        }
        return;
    }
    LRN_IVDEP for (int m = 0; m < n; m++) {
        const ptrdiff_t x = x0 + (ptrdiff_t)m * PX;
        REAL s0e = c0[x], s1e = c1[x], s0o = 0, s1o = 0;
        for (int j = 2; j < nc; j += 2) {
            s0e = OADD(s0e, c0[x + j]);
            s1e = OADD(s1e, c1[x + j]);
        }
        if (nc > 1) {
            s0o = c0[x + 1];
            s1o = c1[x + 1];
        }
        for (int j = 3; j < nc; j += 2) {
            s0o = OADD(s0o, c0[x + j]);
            s1o = OADD(s1o, c1[x + j]);
        }
        bxd[m] = OADD(OADD(s0e, s0o), OADD(s1e, s1o));
        if (first) {
            k0[m] = s0e;
            k1[m] = s0o;
            k2[m] = s1e;
            k3[m] = s1o;
        } else {
            k0[m] = OADD(k0[m], s0e);
            k1[m] = OADD(k1[m], s0o);
            k2[m] = OADD(k2[m], s1e);
            k3[m] = OADD(k3[m], s1o);
        }
    }
}

/* the column stage of Z row y, columns [xa + clo, xb + chi) of each direction's rectangle:
   the D rows from the rings (computed where a slot does not hold them yet), summed down the
   rectangle's rows into cs[2 d] or, for the directions of the spread term when split, into
   cs[2 d] and cs[2 d + 1]: the rows of even and of odd offset from its first row apart */
LRN_CLONES
static void LRN_CAT(lrn_energies, IS, RS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t y, int py,
                                           const REAL *restrict valid, ptrdiff_t cols, int hr,
                                           int split, ptrdiff_t xa, ptrdiff_t xb, ptrdiff_t ra,
                                           ptrdiff_t rb, REAL *conv,
                                           ptrdiff_t *ctag, REAL *dsq, ptrdiff_t *dtag,
                                           REAL *restrict cs)
{
    static const int SY[RGBZ_LEARNED_DIRS] = {0, 2, 2, 2}, SX[RGBZ_LEARNED_DIRS] = {2, 0, 2, -2};
    for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
        const int sy = SY[d], sx = SX[d];
        /* the rectangle of pair starts: rows dlo..dhi, columns clo..chi */
        const int dlo = -hr, dhi = hr - sy, nr = dhi - dlo + 1;
        const int clo = sx < 0 ? -hr - sx : -hr, chi = sx > 0 ? hr - sx : hr;
        const ptrdiff_t ca = xa + clo, cb = xb + chi;
        const REAL *D[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
        for (int i = 0; i < nr; i++) {
            const ptrdiff_t Y = y + dlo + i;
            const int slot = LRN_CAT(lrn_slot, IS, RS)(Y);
            REAL *Dr = dsq + ((ptrdiff_t)d * LRN_RING + slot) * cols;
            if (dtag[d * LRN_RING + slot] != Y) {
                const REAL *a = LRN_CAT(lrn_real_row, IS, RS)(src, rows, cols, py, Y, ra, rb,
                                                              conv, ctag);
                const REAL *b = LRN_CAT(lrn_real_row, IS, RS)(src, rows, cols, py, Y + sy, ra,
                                                              rb, conv, ctag);
                const ptrdiff_t tr = ((Y % py) + py) % py;
                LRN_CAT(lrn_dsq, IS, RS)(Dr, a, b + sx,
                                         valid + (tr * RGBZ_LEARNED_DIRS + d) * cols, ca, cb);
                dtag[d * LRN_RING + slot] = Y;
            }
            D[i] = Dr;
        }
        if (!split || d >= RGBZ_LEARNED_SPREAD_DIRS) {
            LRN_CAT(lrn_sum_rows, IS, RS)(cs + (ptrdiff_t)2 * d * cols, D, nr, ca, cb);
            continue;
        }
        for (int r = 0; r < 2; r++) {
            const REAL *Dp[RGBZ_LEARNED_MAX_RADIUS + 1];
            int np = 0;
            for (int i = r; i < nr; i += 2) Dp[np++] = D[i];
            LRN_CAT(lrn_sum_rows, IS, RS)(cs + (ptrdiff_t)(2 * d + r) * cols, Dp, np, ca, cb);
        }
    }
}

/* the row stage of every direction at the n sites x0 + m px of a phase (column sums cs of
   lrn_energies): bx[d][m], one row per direction, and with the spread term (split) the four
   class rows bx[4 + 2 r + p][m]: over the horizontal and vertical directions, the pair
   starts whose row offset from y - hr has the parity r and whose column offset from x - hr
   the parity p (both rectangles start at row y - hr and column x - hr), so each class is one
   Bayer colour */
LRN_CLONES
static void LRN_CAT(lrn_rows, IS, RS)(const REAL *cs, ptrdiff_t cols, int hr, int split,
                                       ptrdiff_t x0, int px, int n, REAL *bx)
{
    static const int SX[RGBZ_LEARNED_DIRS] = {2, 0, 2, -2};
    REAL *k[4];
    for (int q = 0; q < 4; q++) k[q] = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + q) * cols;
    for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
        const int sx = SX[d];
        const int clo = sx < 0 ? -hr - sx : -hr, chi = sx > 0 ? hr - sx : hr;
        const int nc = chi - clo + 1, sp = split && d < RGBZ_LEARNED_SPREAD_DIRS;
        const REAL *c0 = cs + (ptrdiff_t)2 * d * cols + clo;
        const REAL *c1 = c0 + cols;
        REAL *bxd = bx + (ptrdiff_t)d * cols;
        /* the column counts of hash radius 3 and the periods of Mask1 and Mask2, unrolled */
#define LRN_ROWS_(NC, PXC)                                                                    \
        LRN_CAT(lrn_rowstage, IS, RS)(c0, c1, NC, sp, d == 0, x0, PXC, n, bxd, k[0], k[1], k[2], \
                                      k[3])
        if (nc == 5 && px == 2) LRN_ROWS_(5, 2);
        else if (nc == 7 && px == 2) LRN_ROWS_(7, 2);
        else if (nc == 5 && px == 4) LRN_ROWS_(5, 4);
        else if (nc == 7 && px == 4) LRN_ROWS_(7, 4);
        else LRN_ROWS_(nc, px);
#undef LRN_ROWS_
    }
}

/* res[j]: the dot product of the dense window of the site at x0 + j px (rows: the REAL rows
   y - R .. y + R) with its bucket's dense weights (rows of 8: the 7 pixels of the window row
   and one weight of 0). With GCC or Clang each row is one or two 32-byte vector operations
   (vector extensions: the auto-vectoriser leaves this loop scalar), and the lanes of each
   site's accumulator are added in lane order for 8 floats' or 4 doubles' sites at once
   (their accumulators transposed in registers: lrn_lane_sums_<RS>, learned.c); the fast
   path never runs in the
   counting build, which counts the per-site formulation. */
#if LRN_VECTOR_EXT
/* 32-byte vectors (AVX2's width: 8 floats or 4 doubles; wider ones are expanded element by
   element) */
#define LRN_LANES ((int)(32 / sizeof(REAL)))
typedef REAL LRN_CAT(lrn_rv, IS, RS) __attribute__((vector_size(32)));
#endif
#if LRN_VECTOR_EXT
/* one site's accumulator over its window rows into *acc (lane l: window column h + l) */
LRN_INLINE void LRN_CAT(lrn_site_acc, IS, RS)(const REAL *const *rowp, ptrdiff_t x,
                                              const REAL *restrict w, int rows,
                                              LRN_CAT(lrn_rv, IS, RS) *acc)
{
    typedef LRN_CAT(lrn_rv, IS, RS) rv;
    rv a = {0};
    for (int dy = 0; dy < rows; dy++)
        for (int h = 0; h < 8; h += LRN_LANES) {
            rv xv, wv;
            memcpy(&xv, rowp[dy] + x + h, sizeof xv);
            memcpy(&wv, w + dy * 8 + h, sizeof wv);
            a += wv * xv;
        }
    *acc = a;
}
/* the lanes of one accumulator added in lane order */
LRN_INLINE REAL LRN_CAT(lrn_lane_total, IS, RS)(LRN_CAT(lrn_rv, IS, RS) a)
{
    REAL lanes[LRN_LANES];
    memcpy(lanes, &a, sizeof a);
    REAL sum = lanes[0];
    for (int l = 1; l < LRN_LANES; l++) sum += lanes[l];
    return sum;
}
#endif
LRN_INLINE void LRN_CAT(lrn_dense_dot_rows, IS, RS)(const REAL *const *rowp, ptrdiff_t x0,
                                                       int px, int n,
                                                       const REAL *restrict wd, const int R,
                                                       const int32_t *restrict bucket,
                                                       REAL *restrict res)
{
    const int rows = 2 * R + 1;
#if LRN_VECTOR_EXT
    typedef LRN_CAT(lrn_rv, IS, RS) rv;
    enum { L = LRN_LANES };
    /* float: 16 sites at a time, two a 64-byte vector (lrn_dense_pairs_f32); then 8 */
    int j = RGBZ_CAT(lrn_dense_pairs, RS)(rowp, x0, px, n, wd, R, bucket, res);
    for (; j + L <= n; j += L) {
        /* L sites' accumulators acc[i] (lane l: window column h + l), then their lanes added
           in lane order for the L sites at once: the accumulators transposed in registers */
        rv acc[L];
        for (int i = 0; i < L; i++) {
            LRN_CAT(lrn_site_acc, IS, RS)(rowp, x0 + (ptrdiff_t)(j + i) * px - R,
                                          wd + (ptrdiff_t)bucket[j + i] * rows * 8, rows,
                                          &acc[i]);
        }
        rv sum;
        RGBZ_CAT(lrn_lane_sums, RS)(acc, &sum);
        memcpy(res + j, &sum, sizeof sum);
    }
    /* the last sites of a partial block: the same sums, one site at a time */
    for (; j < n; j++) {
        rv a;
        LRN_CAT(lrn_site_acc, IS, RS)(rowp, x0 + (ptrdiff_t)j * px - R,
                                      wd + (ptrdiff_t)bucket[j] * rows * 8, rows, &a);
        res[j] = LRN_CAT(lrn_lane_total, IS, RS)(a);
    }
#else
    for (int j = 0; j < n; j++) {
        const REAL *restrict w = wd + (ptrdiff_t)bucket[j] * rows * 8;
        const ptrdiff_t x = x0 + (ptrdiff_t)j * px - R;
        REAL acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (int dy = 0; dy < rows; dy++) {
            const REAL *restrict r = rowp[dy] + x;
            const REAL *restrict wr = w + dy * 8;
            for (int c = 0; c < 8; c++) acc[c] = OADD(acc[c], OMUL(wr[c], r[c]));
        }
        res[j] = OADD(OADD(OADD(acc[0], acc[4]), OADD(acc[2], acc[6])),
                      OADD(OADD(acc[1], acc[5]), OADD(acc[3], acc[7])));
    }
#endif
}
#ifdef LRN_LANES
#undef LRN_LANES
#endif

LRN_CLONES
static void LRN_CAT(lrn_dense_dot, IS, RS)(const REAL *const *rowp, ptrdiff_t x0, int px,
                                            int n, const REAL *restrict wd, int R,
                                            const int32_t *restrict bucket,
                                            REAL *restrict res)
{
    switch (R) {      /* the window radii of the fast path, unrolled */
    case 1: LRN_CAT(lrn_dense_dot_rows, IS, RS)(rowp, x0, px, n, wd, 1, bucket, res); break;
    case 2: LRN_CAT(lrn_dense_dot_rows, IS, RS)(rowp, x0, px, n, wd, 2, bucket, res); break;
    case 3: LRN_CAT(lrn_dense_dot_rows, IS, RS)(rowp, x0, px, n, wd, 3, bucket, res); break;
    default: LRN_CAT(lrn_dense_dot_rows, IS, RS)(rowp, x0, px, n, wd, R, bucket, res);
    }
}

/* the buckets of the fast path's sites x0, x0 + px, ... (n of them, any number) of phase k in
   row y: their energies from the box sums bx of the phase's sites in the row, from m0 on (with
   the spread term also the colour energies, from its class rows: lrn_rows) */
LRN_CLONES
static void LRN_CAT(lrn_fast_bucket, IS, RS)(ptrdiff_t y, ptrdiff_t x0, int n,
                                              const rgbz_learned_filters *f, int k,
                                              const REAL *bx, ptrdiff_t m0, ptrdiff_t cols,
                                              int32_t *restrict bucket)
{
    REAL e[RGBZ_LEARNED_DIRS][LRN_BLK];
    REAL ec[3][LRN_BLK];
    const int ns = f->n_str, nc = f->n_coh, nk = f->n_spr;
    if (ns <= 3 && nc <= 3 && nk <= 3) {
        /* at most two thresholds of each kind: one pass over the sites, every value in
           registers (lrn_bucket1, the same arithmetic as lrn_bucket's passes) */
        const REAL inf = (REAL)INFINITY;
        REAL st[2] = {inf, inf}, ct[2] = {inf, inf}, kt[2] = {inf, inf};
        for (int i = 0; i < ns - 1; i++) st[i] = (REAL)f->str_thr[(ptrdiff_t)k * (ns - 1) + i];
        for (int i = 0; i < nc - 1; i++) ct[i] = (REAL)f->coh_thr2[(ptrdiff_t)k * (nc - 1) + i];
        for (int i = 0; i < nk - 1; i++) kt[i] = (REAL)f->spr_thr[(ptrdiff_t)k * (nk - 1) + i];
        const int32_t mo = ns * nc * nk, ms = nc * nk, mc = nk;
        const int32_t *np = f->n_pairs + k * RGBZ_LEARNED_DIRS;
        const REAL i0 = (REAL)1 / (REAL)np[0], i1 = (REAL)1 / (REAL)np[1];
        const REAL i2 = (REAL)1 / (REAL)np[2], i3 = (REAL)1 / (REAL)np[3];
        const REAL *restrict b0 = bx + m0, *restrict b1 = bx + cols + m0;
        const REAL *restrict b2 = bx + 2 * cols + m0, *restrict b3 = bx + 3 * cols + m0;
        if (nk > 1) {
            int cls[4];
            lrn_colour_classes(f, y, x0, cls);
            const int cr = cls[0], g0 = cls[1], g1 = cls[2], cb = cls[3];
            const REAL *restrict kr = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + cr) * cols + m0;
            const REAL *restrict kb = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + cb) * cols + m0;
            const REAL *restrict kg0 = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + g0) * cols + m0;
            const REAL *restrict kg1 = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + g1) * cols + m0;
            const REAL ir = (REAL)f->inv_col[k * 3], ig = (REAL)f->inv_col[k * 3 + 1];
            const REAL ib = (REAL)f->inv_col[k * 3 + 2];
            LRN_IVDEP for (int j = 0; j < n; j++)
                bucket[j] = LRN_CAT(lrn_bucket1, IS, RS)(
                    OMUL(b0[j], i0), OMUL(b1[j], i1), OMUL(b2[j], i2), OMUL(b3[j], i3),
                    OMUL(kr[j], ir), OMUL(OADD(kg0[j], kg1[j]), ig), OMUL(kb[j], ib), 1, st, ct,
                    kt, mo, ms, mc);
        } else {
            LRN_IVDEP for (int j = 0; j < n; j++)
                bucket[j] = LRN_CAT(lrn_bucket1, IS, RS)(
                    OMUL(b0[j], i0), OMUL(b1[j], i1), OMUL(b2[j], i2), OMUL(b3[j], i3), 0, 0, 0,
                    0, st, ct, kt, mo, ms, mc);
        }
        return;
    }
    /* more levels: lrn_bucket, LRN_BLK sites at a time */
    for (int j0 = 0; j0 < n; j0 += LRN_BLK) {
        const int nb = n - j0 < LRN_BLK ? n - j0 : LRN_BLK;
        const ptrdiff_t mb = m0 + j0;
        for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
            const REAL inv = (REAL)1 / (REAL)f->n_pairs[k * RGBZ_LEARNED_DIRS + d];
            const REAL *restrict b = bx + (ptrdiff_t)d * cols + mb;
            LRN_IVDEP for (int j = 0; j < nb; j++) e[d][j] = OMUL(b[j], inv);
        }
        if (f->n_spr > 1) {
            int cls[4];
            lrn_colour_classes(f, y, x0, cls);
            const int cr = cls[0], g0 = cls[1], g1 = cls[2], cb = cls[3];
            const REAL *restrict kr = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + cr) * cols + mb;
            const REAL *restrict kb = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + cb) * cols + mb;
            const REAL *restrict kg0 = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + g0) * cols + mb;
            const REAL *restrict kg1 = bx + (ptrdiff_t)(RGBZ_LEARNED_DIRS + g1) * cols + mb;
            const REAL ir = (REAL)f->inv_col[k * 3], ig = (REAL)f->inv_col[k * 3 + 1];
            const REAL ib = (REAL)f->inv_col[k * 3 + 2];
            LRN_IVDEP for (int j = 0; j < nb; j++) {
                ec[0][j] = OMUL(kr[j], ir);
                ec[1][j] = OMUL(OADD(kg0[j], kg1[j]), ig);
                ec[2][j] = OMUL(kb[j], ib);
            }
        }
        LRN_CAT(lrn_bucket, IS, RS)(e, ec, nb, f, k, bucket + j0);
    }
}

/* the taps v[t][j] of the n sites x0, x0 + px, ... (n <= LRN_BLK) of phase k, tap-major
   (rows rowp[dy + R]; through the column map at the borders) */
static void LRN_CAT(lrn_gather, IS, RS)(const IN_T *const *rowp, ptrdiff_t x0, int px, int n,
                                         ptrdiff_t cols, const ptrdiff_t *colmap,
                                         const rgbz_learned_filters *f, int k,
                                         REAL (*restrict v)[LRN_BLK])
{
    const int R = f->radius, nt = f->n_taps[k];
    const int32_t *tdy = f->tap_dy + (ptrdiff_t)k * f->n_taps_max;
    const int32_t *tdx = f->tap_dx + (ptrdiff_t)k * f->n_taps_max;
    const ptrdiff_t xl = x0 + (ptrdiff_t)(n - 1) * px;
    if (x0 - R >= 0 && xl + R < cols) {
        for (int t = 0; t < nt; t++) {
            const IN_T *restrict row = rowp[tdy[t] + R] + x0 + tdx[t];
            LRN_IVDEP for (int j = 0; j < n; j++) v[t][j] = (REAL)row[(ptrdiff_t)j * px];
        }
    } else {
        for (int t = 0; t < nt; t++) {
            const IN_T *restrict row = rowp[tdy[t] + R];
            const ptrdiff_t *cm = colmap + x0 + R + tdx[t];
            LRN_IVDEP for (int j = 0; j < n; j++) v[t][j] = (REAL)row[cm[(ptrdiff_t)j * px]];
        }
    }
}

/* the fast path's rows valid[tile row][d][x] (py x RGBZ_LEARNED_DIRS rows of cols, malloc'ed;
   NULL: no memory): 1 where the pixel and its partner along d are both known */
static REAL *LRN_CAT(lrn_valid, IS, RS)(ptrdiff_t cols, int py, int px,
                                         const int32_t *phase_map)
{
    static const int SY[RGBZ_LEARNED_DIRS] = {0, 2, 2, 2};
    static const int SX[RGBZ_LEARNED_DIRS] = {2, 0, 2, -2};
    REAL *valid = malloc((size_t)py * RGBZ_LEARNED_DIRS * (size_t)cols * sizeof(REAL));
    if (!valid) return NULL;
    for (int r = 0; r < py; r++)
        for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
            const int r2 = (r + SY[d]) % py;
            REAL *vr = valid + ((ptrdiff_t)r * RGBZ_LEARNED_DIRS + d) * cols;
            for (ptrdiff_t x = 0; x < cols; x++) {
                const ptrdiff_t x2 = ((x + SX[d]) % px + px) % px;
                vr[x] = (REAL)(phase_map[r * px + x % px] < 0 && phase_map[r2 * px + x2] < 0);
            }
        }
    return valid;
}
