/*
 * z_guided.template.h -- the frame loop of the z_guided reconstruction (z_guided.h) for one
 * element type and one precision. Instantiated by z_guided_entry.template.h through
 * rgbz_each_type.h (rgbz_templating.h), once per element type and precision, with
 *   IN_T       the element type (uint8_t, uint16_t, float, double)
 *   IS         its suffix (u8, u16, f32, f64)
 *   IN_IS_INT  1 for the integer types (outputs rounded half up)
 *   REAL       the arithmetic (float or double)
 *   RS         its suffix (f32, f64): the weights are the members w_<RS>, g_<RS>
 *
 * The sites of one phase in one row are processed in blocks of ZG_BLK, as the learned
 * kernel's generic path (learned.template.h): the taps loaded tap-major (v[t][j], tap t of
 * site j), the hash on whole rows of v (branch-free selects, in the order of the learned
 * kernel's generic path, so that both methods give a site the same hash bucket), the dot
 * products gathering each site's weights from the tap-major table (w[t][bucket]) and the
 * guide weights of its bucket; every loop runs over j. Each site's arithmetic is that of
 * the per-site formulation (the tap sum in the order of t, then the guide term), so the
 * block size changes no bit. The cell terms come from the thread's zg_cells, computed once
 * per tile row and target colour (z_guided.c).
 */
#if !defined(IN_T) || !defined(IS) || !defined(IN_IS_INT) || !defined(REAL) || !defined(RS)
#error "z_guided.template.h: define IN_T, IS, IN_IS_INT, REAL and RS"
#endif

#define ZG_CAT RGBZ_CAT3
#define RW RGBZ_CAT(w, RS)
#define RG RGBZ_CAT(g, RS)

/* acc[ix] += row[x0 + PX ix] for the cells ix in [ia, ib), all inside the row (PX a constant
   where it is inlined, so that the strided loads vectorise) */
RGBZ_INLINE void ZG_CAT(zg_cg_add, IS, RS)(double *restrict acc, const IN_T *restrict row,
                                           ptrdiff_t x0, const int PX, ptrdiff_t ia,
                                           ptrdiff_t ib)
{
    RGBZ_IVDEP for (ptrdiff_t ix = ia; ix < ib; ix++) acc[ix] += (double)row[x0 + PX * ix];
}

/* the colour means of target t in tile row jy (0 <= jy < gy) into the padded row c: for
   each cell, its box's pixels of colour t summed in the order of the box, over their count */
RGBZ_CLONES_512
static void ZG_CAT(zg_cg_row, IS, RS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols, int py,
                                      int px, const rgbz_zguided_filters *f, const zg_cells *st,
                                      int t, ptrdiff_t jy, double *restrict c)
{
    const ptrdiff_t gx = f->gx, y0 = f->zr + (ptrdiff_t)py * jy;
    double *restrict acc = c + 1;
    for (ptrdiff_t ix = 0; ix < gx; ix++) acc[ix] = 0.0;
    for (int i = 0; i < st->nbox[t]; i++) {
        const IN_T *restrict row = src + zg_extend(y0 + st->ey[t][i], rows, py) * cols;
        const ptrdiff_t x0 = f->zc + st->ex[t][i];
        /* the cells whose column x0 + px ix lies inside the frame: [ia, ib) */
        ptrdiff_t ia = x0 < 0 ? (-x0 + px - 1) / px : 0;
        ptrdiff_t ib = x0 < cols ? (cols - 1 - x0) / px + 1 : 0;
        if (ib > gx) ib = gx;
        if (ia > ib) ia = ib;
        for (ptrdiff_t ix = 0; ix < ia; ix++)
            acc[ix] += (double)row[zg_extend(x0 + px * ix, cols, px)];
        switch (px) {   /* the periods of Mask1 and Mask2, unrolled */
        case 2: ZG_CAT(zg_cg_add, IS, RS)(acc, row, x0, 2, ia, ib); break;
        case 4: ZG_CAT(zg_cg_add, IS, RS)(acc, row, x0, 4, ia, ib); break;
        default: ZG_CAT(zg_cg_add, IS, RS)(acc, row, x0, px, ia, ib);
        }
        for (ptrdiff_t ix = ib; ix < gx; ix++)
            acc[ix] += (double)row[zg_extend(x0 + px * ix, cols, px)];
    }
    const double n = (double)st->nbox[t];
    for (ptrdiff_t ix = 0; ix < gx; ix++) acc[ix] /= n;
    zg_pad(c, gx);
}

/* the cell terms [RGBZ_ZG_FEATURES][gx] of target t in tile row iy, computed if the thread
   does not hold them yet (with the colour means of the rows around it and, once per tile
   row, the noise levels into st->level) */
static const double *ZG_CAT(zg_cells_get, IS, RS)(zg_cells *st, const rgbz_zguided_filters *f,
                                                  const IN_T *src, ptrdiff_t rows,
                                                  ptrdiff_t cols, int py, int px,
                                                  ptrdiff_t iy, int t)
{
    const ptrdiff_t gx = f->gx, gy = f->gy, w = gx + 2;
    double *out = st->cell + (ptrdiff_t)t * RGBZ_ZG_FEATURES * gx;
    if (st->cell_tag[t] == iy) return out;
    const double *N[3], *V[3], *C[3];
    for (int r = 0; r < 3; r++) {
        ptrdiff_t jy = iy - 1 + r;
        jy = jy < 0 ? 0 : (jy >= gy ? gy - 1 : jy);
        const int slot = (int)(jy % 3);
        double *c = st->cg + ((ptrdiff_t)t * 3 + slot) * w;
        if (st->cg_tag[t][slot] != jy) {
            ZG_CAT(zg_cg_row, IS, RS)(src, rows, cols, py, px, f, st, t, jy, c);
            st->cg_tag[t][slot] = jy;
        }
        C[r] = c;
        double *n = st->nv + (ptrdiff_t)r * w, *v = st->nv + (ptrdiff_t)(3 + r) * w;
        if (st->nv_tag != iy) {
            memcpy(n + 1, f->grid + jy * gx, (size_t)gx * sizeof *n);
            memcpy(v + 1, f->var + jy * gx, (size_t)gx * sizeof *v);
            zg_pad(n, gx);
            zg_pad(v, gx);
        }
        N[r] = n;
        V[r] = v;
    }
    st->nv_tag = iy;
    double *nu = st->nv + 6 * w;
    zg_cell_row(N, V, C, gx, f->lam, out, nu);
    if (st->level_tag != iy) zg_level_row(nu, gx, f->thr, f->n_levels - 1, st->level);
    st->level_tag = iy;
    st->cell_tag[t] = iy;
    return out;
}

/* the buckets of the n sites whose taps are v[t][j] (phase k): learned.h's octant,
   strength, coherence and channel spread of the direction and colour energies */
RGBZ_INLINE void ZG_CAT(zg_hash_n, IS, RS)(REAL (*restrict v)[ZG_BLK], const int n,
                                           const rgbz_learned_filters *h, int k,
                                           int32_t *restrict bucket)
{
    REAL e[RGBZ_LEARNED_DIRS][ZG_BLK];
    REAL ec[3][ZG_BLK];
    const int nk = h->n_spr, ns = h->n_str, nc = h->n_coh;
    for (int c = 0; c < 3; c++)
        for (int j = 0; j < n; j++) ec[c][j] = 0;
    for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
        const int np = h->n_pairs[k * RGBZ_LEARNED_DIRS + d];
        const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * h->n_pairs_max;
        const int32_t *pa = h->pair_a + o, *pb = h->pair_b + o, *pc = h->pair_col + o;
        const int spread = nk > 1 && d < RGBZ_LEARNED_SPREAD_DIRS;
        REAL *restrict ed = e[d];
        {   /* the first pair sets the sum */
            const REAL *restrict va = v[pa[0]], *restrict vb = v[pb[0]];
            RGBZ_IVDEP for (int j = 0; j < n; j++) {
                const REAL df = OSUB(va[j], vb[j]);
                ed[j] = OMUL(df, df);
            }
            if (spread) {
                REAL *restrict ecp = ec[pc[0]];
                RGBZ_IVDEP for (int j = 0; j < n; j++) ecp[j] = OADD(ecp[j], ed[j]);
            }
        }
        ZG_NOJAM for (int p = 1; p < np; p++) {
            const REAL *restrict va = v[pa[p]], *restrict vb = v[pb[p]];
            if (spread) {
                REAL *restrict ecp = ec[pc[p]];
                RGBZ_IVDEP for (int j = 0; j < n; j++) {
                    const REAL df = OSUB(va[j], vb[j]);
                    const REAL sq = OMUL(df, df);
                    ed[j] = OADD(ed[j], sq);
                    ecp[j] = OADD(ecp[j], sq);
                }
            } else {
                RGBZ_IVDEP for (int j = 0; j < n; j++) {
                    const REAL df = OSUB(va[j], vb[j]);
                    ed[j] = OADD(ed[j], OMUL(df, df));
                }
            }
        }
        const REAL inv = (REAL)1 / (REAL)np;
        RGBZ_IVDEP for (int j = 0; j < n; j++) ed[j] = OMUL(ed[j], inv);
    }
    const double *sth = h->str_thr + (ptrdiff_t)k * (ns - 1);
    const double *cth = h->coh_thr2 + (ptrdiff_t)k * (nc - 1);
    const double *kth = h->spr_thr + (ptrdiff_t)k * (nk - 1);
    const REAL C = (REAL)0.92387953251128674, S = (REAL)0.38268343236508978;
    REAL tt[ZG_BLK] = {0}, m2[ZG_BLK] = {0};
    RGBZ_IVDEP for (int j = 0; j < n; j++) {
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
        const REAL thr = (REAL)sth[i];
        RGBZ_IVDEP for (int j = 0; j < n; j++) bucket[j] += OCMP(tt[j] > thr) ? nc * nk : 0;
    }
    if (nc > 1) {
        RGBZ_IVDEP for (int j = 0; j < n; j++) tt[j] = OMUL(tt[j], tt[j]);
        for (int i = 0; i < nc - 1; i++) {
            const REAL thr = (REAL)cth[i];
            RGBZ_IVDEP for (int j = 0; j < n; j++)
                bucket[j] += OCMP(m2[j] > OMUL(thr, tt[j])) ? nk : 0;
        }
    }
    if (nk > 1) {
        /* the largest and the smallest colour energy (tt: largest, m2: smallest) */
        const REAL ir = (REAL)h->inv_col[k * 3], ig = (REAL)h->inv_col[k * 3 + 1];
        const REAL ib = (REAL)h->inv_col[k * 3 + 2];
        RGBZ_IVDEP for (int j = 0; j < n; j++) {
            const REAL r = OMUL(ec[0][j], ir), g = OMUL(ec[1][j], ig);
            const REAL bl = OMUL(ec[2][j], ib);
            const REAL hi1 = OCMP(g > r) ? g : r, lo1 = OCMP(g > r) ? r : g;
            tt[j] = OCMP(bl > hi1) ? bl : hi1;
            m2[j] = OCMP(bl < lo1) ? bl : lo1;
        }
        for (int i = 0; i < nk - 1; i++) {
            const REAL thr = (REAL)kth[i];
            RGBZ_IVDEP for (int j = 0; j < n; j++) bucket[j] += OCMP(tt[j] > OMUL(thr, m2[j]));
        }
    }
}

/* zg_hash_n with the block's size a constant for a whole block (so that every loop over the
   sites runs as whole vectors, without a remainder; the same arithmetic per site) */
RGBZ_CLONES_512
static void ZG_CAT(zg_hash, IS, RS)(REAL (*restrict v)[ZG_BLK], int n,
                                    const rgbz_learned_filters *h, int k,
                                    int32_t *restrict bucket)
{
    if (n == ZG_BLK) ZG_CAT(zg_hash_n, IS, RS)(v, ZG_BLK, h, k, bucket);
    else ZG_CAT(zg_hash_n, IS, RS)(v, n, h, k, bucket);
}

/* res[j] = sum_t w[t][bucket[j]] * v[t][j], in the order of t */
RGBZ_INLINE ZG_NOJAM_FN void ZG_CAT(zg_colour_dot_n, IS, RS)(REAL (*restrict v)[ZG_BLK], const int n,
                                          const REAL *restrict w, int n_taps,
                                          ptrdiff_t n_buckets, const int32_t *restrict bucket,
                                          REAL *restrict res)
{
    RGBZ_IVDEP for (int j = 0; j < n; j++) res[j] = OMUL(w[bucket[j]], v[0][j]);
    ZG_NOJAM for (int t = 1; t < n_taps; t++) {
        const REAL *restrict wt = w + (ptrdiff_t)t * n_buckets;
        const REAL *restrict vt = v[t];
        RGBZ_IVDEP for (int j = 0; j < n; j++) res[j] = OADD(res[j], OMUL(wt[bucket[j]], vt[j]));
    }
}

/* zg_colour_dot_n with the block's size a constant for a whole block */
RGBZ_CLONES_512 ZG_NOJAM_FN
static void ZG_CAT(zg_colour_dot, IS, RS)(REAL (*restrict v)[ZG_BLK], int n,
                                          const REAL *restrict w, int n_taps,
                                          ptrdiff_t n_buckets, const int32_t *restrict bucket,
                                          REAL *restrict res)
{
    if (n == ZG_BLK) ZG_CAT(zg_colour_dot_n, IS, RS)(v, ZG_BLK, w, n_taps, n_buckets, bucket, res);
    else ZG_CAT(zg_colour_dot_n, IS, RS)(v, n, w, n_taps, n_buckets, bucket, res);
}

/* the values res[j] of the n sites x0, x0 + px, ... of phase k (taps v[t][j], hash buckets
   bucket[j]) in tile row cells ix0, ix0 + 1, ... (clamped to the grid): the colour dot
   product of bucket level * n_hash + bucket, then the guide term of the cell terms cell */
RGBZ_INLINE void ZG_CAT(zg_dot_n, IS, RS)(REAL (*restrict v)[ZG_BLK], const int n,
                                   const rgbz_zguided_filters *f, int k,
                                   const int32_t *restrict bucket, ptrdiff_t ix0,
                                   const double *restrict cell, const int32_t *restrict level,
                                   REAL *restrict res)
{
    const rgbz_learned_filters *h = f->hash;
    const int nt = h->n_taps[k], nbh = h->n_buckets;
    const ptrdiff_t nb = (ptrdiff_t)f->n_levels * nbh, gx = f->gx;
    const REAL *restrict w = f->RW + (ptrdiff_t)k * h->n_taps_max * nb;
    const REAL *restrict g = f->RG + (ptrdiff_t)k * nb * RGBZ_ZG_FEATURES;
    int32_t b[ZG_BLK] = {0};
    REAL cj[RGBZ_ZG_FEATURES][ZG_BLK];
    if (ix0 + n <= gx) {   /* the cells ix0 .. ix0 + n - 1: contiguous */
        RGBZ_IVDEP for (int j = 0; j < n; j++) b[j] = level[ix0 + j] * nbh + bucket[j];
        for (int m = 0; m < RGBZ_ZG_FEATURES; m++) {
            const double *restrict cm = cell + (ptrdiff_t)m * gx + ix0;
            RGBZ_IVDEP for (int j = 0; j < n; j++) cj[m][j] = (REAL)cm[j];
        }
    } else {               /* past the grid's last column: its last cell */
        for (int j = 0; j < n; j++) {
            const ptrdiff_t ix = ix0 + j < gx ? ix0 + j : gx - 1;
            b[j] = level[ix] * nbh + bucket[j];
            for (int m = 0; m < RGBZ_ZG_FEATURES; m++) cj[m][j] = (REAL)cell[m * gx + ix];
        }
    }
    ZG_CAT(zg_colour_dot, IS, RS)(v, n, w, nt, nb, b, res);
    const int32_t *bi = f->base_idx + (ptrdiff_t)k * f->n_base_max;
    const int n_base = f->n_base[k];
    REAL base[ZG_BLK] = {0}, s[ZG_BLK] = {0};
    RGBZ_IVDEP for (int j = 0; j < n; j++) base[j] = v[bi[0]][j];
    for (int i = 1; i < n_base; i++) {
        const REAL *restrict vi = v[bi[i]];
        RGBZ_IVDEP for (int j = 0; j < n; j++) base[j] = OADD(base[j], vi[j]);
    }
    const REAL inv_base = (REAL)1 / (REAL)n_base;
    RGBZ_IVDEP for (int j = 0; j < n; j++) {
        base[j] = OMUL(base[j], inv_base);
        s[j] = OMUL(g[b[j] * RGBZ_ZG_FEATURES], cj[0][j]);
    }
    for (int m = 1; m < 9; m++) {
        const REAL *restrict cm = cj[m];
        RGBZ_IVDEP for (int j = 0; j < n; j++)
            s[j] = OADD(s[j], OMUL(g[b[j] * RGBZ_ZG_FEATURES + m], cm[j]));
    }
    RGBZ_IVDEP for (int j = 0; j < n; j++) {
        const REAL *gj = g + b[j] * RGBZ_ZG_FEATURES;
        REAL r = OADD(res[j], OMUL(base[j], OSUB(s[j], gj[9])));
        r = OADD(r, OMUL(gj[9], cj[9][j]));
        res[j] = OADD(r, OMUL(gj[10], cj[10][j]));
    }
}

/* zg_dot_n with the block's size a constant for a whole block */
RGBZ_CLONES_512
static void ZG_CAT(zg_dot, IS, RS)(REAL (*restrict v)[ZG_BLK], int n,
                                   const rgbz_zguided_filters *f, int k,
                                   const int32_t *restrict bucket, ptrdiff_t ix0,
                                   const double *restrict cell, const int32_t *restrict level,
                                   REAL *restrict res)
{
    if (n == ZG_BLK) ZG_CAT(zg_dot_n, IS, RS)(v, ZG_BLK, f, k, bucket, ix0, cell, level, res);
    else ZG_CAT(zg_dot_n, IS, RS)(v, n, f, k, bucket, ix0, cell, level, res);
}

/* the taps v[t][j] of the n sites x0, x0 + PX, ... of phase k inside the row (PX a
   constant where it is inlined, so that the strided loads vectorise) */
RGBZ_INLINE void ZG_CAT(zg_gather_in, IS, RS)(const IN_T *const *rowp, ptrdiff_t x0,
                                              const int PX, const int n, const int32_t *tdy,
                                              const int32_t *tdx, int nt, int R,
                                              REAL (*restrict v)[ZG_BLK])
{
    for (int t = 0; t < nt; t++) {
        const IN_T *restrict row = rowp[tdy[t] + R] + x0 + tdx[t];
        RGBZ_IVDEP for (int j = 0; j < n; j++) v[t][j] = (REAL)row[(ptrdiff_t)j * PX];
    }
}

/* the taps v[t][j] of the n sites x0, x0 + px, ... of phase k (rows rowp[dy + R]; through
   the column map at the borders) */
RGBZ_CLONES_512
static void ZG_CAT(zg_gather, IS, RS)(const IN_T *const *rowp, ptrdiff_t x0, int px, int n,
                                      ptrdiff_t cols, const ptrdiff_t *colmap,
                                      const rgbz_learned_filters *h, int k,
                                      REAL (*restrict v)[ZG_BLK])
{
    const int R = h->radius, nt = h->n_taps[k];
    const int32_t *tdy = h->tap_dy + (ptrdiff_t)k * h->n_taps_max;
    const int32_t *tdx = h->tap_dx + (ptrdiff_t)k * h->n_taps_max;
    const ptrdiff_t xl = x0 + (ptrdiff_t)(n - 1) * px;
    if (x0 - R >= 0 && xl + R < cols) {
        switch (px) {   /* the periods of Mask1 and Mask2, unrolled */
        case 2:
            if (n == ZG_BLK) ZG_CAT(zg_gather_in, IS, RS)(rowp, x0, 2, ZG_BLK, tdy, tdx, nt, R, v);
            else ZG_CAT(zg_gather_in, IS, RS)(rowp, x0, 2, n, tdy, tdx, nt, R, v);
            break;
        case 4:
            if (n == ZG_BLK) ZG_CAT(zg_gather_in, IS, RS)(rowp, x0, 4, ZG_BLK, tdy, tdx, nt, R, v);
            else ZG_CAT(zg_gather_in, IS, RS)(rowp, x0, 4, n, tdy, tdx, nt, R, v);
            break;
        default: ZG_CAT(zg_gather_in, IS, RS)(rowp, x0, px, n, tdy, tdx, nt, R, v);
        }
    } else {
        for (int t = 0; t < nt; t++) {
            const IN_T *restrict row = rowp[tdy[t] + R];
            const ptrdiff_t *cm = colmap + x0 + R + tdx[t];
            RGBZ_IVDEP for (int j = 0; j < n; j++) v[t][j] = (REAL)row[cm[(ptrdiff_t)j * px]];
        }
    }
}

static int ZG_CAT(zg_loop, IS, RS)(const IN_T *restrict src, IN_T *restrict dst,
                                   ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                                   const int32_t *phase_map, const rgbz_zguided_filters *f,
                                   const ptrdiff_t *colmap, double maxval_d, int workers,
                                   uint64_t *opcounts)
{
    const rgbz_learned_filters *h = f->hash;
    const int R = h->radius;
    const REAL maxval = (REAL)maxval_d;
    int status = RGBZ_OK;
    (void)opcounts;
#ifdef _OPENMP
    const int nth = workers > 0 ? workers : omp_get_max_threads();
#pragma omp parallel num_threads(nth)
#else
    (void)workers;
#endif
    {
        zg_cells st;
        const int ok = zg_cells_init(&st, f, py, px) == RGBZ_OK;
        if (!ok) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ENOMEM;
        }
        REAL v[RGBZ_LEARNED_MAX_TAPS][ZG_BLK];
        int32_t bucket[ZG_BLK];
        REAL res[ZG_BLK];
        /* static: each thread's rows are consecutive, so that its cell terms and colour
           means of a tile row serve the rows that follow */
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t y = 0; y < rows; y++) {
            IN_T *restrict drow = dst + y * cols;
            memcpy(drow, src + y * cols, (size_t)cols * sizeof(IN_T));
            if (!ok) continue;
            const IN_T *rowp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
            for (int dy = -R; dy <= R; dy++)
                rowp[dy + R] = src + zg_extend(y + dy, rows, py) * cols;
            const int32_t *pm = phase_map + (y % py) * px;
            const ptrdiff_t iy = y / py < f->gy ? y / py : f->gy - 1;
            for (int c0 = 0; c0 < px && c0 < cols; c0++) {
                const int k = pm[c0];
                if (k < 0) continue;
#ifdef RGBZ_COUNT_OPS
                rgbz_opc_cur = opcounts + (size_t)k * RGBZ_NOPS;
#endif
                const double *cell = ZG_CAT(zg_cells_get, IS, RS)(&st, f, src, rows, cols, py,
                                                                  px, iy, f->targets[k]);
                for (ptrdiff_t x0 = c0; x0 < cols;) {
                    const ptrdiff_t left = (cols - 1 - x0) / px + 1;
                    const int n = (int)(left < ZG_BLK ? left : ZG_BLK);
                    ZG_CAT(zg_gather, IS, RS)(rowp, x0, px, n, cols, colmap, h, k, v);
                    ZG_CAT(zg_hash, IS, RS)(v, n, h, k, bucket);
                    ZG_CAT(zg_dot, IS, RS)(v, n, f, k, bucket, x0 / px, cell, st.level, res);
                    for (int j = 0; j < n; j++)
                        drow[x0 + (ptrdiff_t)j * px] =
                            (IN_T)RGBZ_CAT(rgbz_out, RS)(res[j], maxval, IN_IS_INT);
                    x0 += (ptrdiff_t)n * px;
                }
            }
        }
        zg_cells_free(&st);
    }
    return status;
}

#undef ZG_CAT
#undef RW
#undef RG
