/*
 * z_guided.template.h -- the frame loop of the z_guided reconstruction (z_guided.h) for one
 * element type and one precision. Instantiated by z_guided_entry.template.h through
 * rgbz_each_type.h (rgbz_templating.h), once per element type and precision, with
 *   IN_T       the element type (uint8_t, uint16_t, float, double)
 *   IS         its suffix (u8, u16, f32, f64)
 *   IN_IS_INT  1 for the integer types (outputs rounded half up)
 *   REAL       the arithmetic (float or double)
 *   RS         its suffix (f32, f64): the weights are the members w_<RS>, wd_<RS>, g_<RS>
 *
 * The sites of one phase in one row are processed in blocks of LRN_BLK, with the learned
 * kernel's code (learned_hash.template.h), so that both methods give a site the same hash
 * bucket: at the borders the generic path (the taps loaded tap-major, the hash of their
 * pairs, the colour dot product gathering each site's weights of bucket
 * level * n_hash + hash bucket from the tap-major table), in the interior the fast path (the
 * hash from box sums, the colour dot product over the dense window with the dense weights of
 * that bucket); then the guide term of the site's cell (the baseline taps summed in the
 * order of the phase's list). Every loop runs over the sites of a block, and each site's
 * arithmetic does not depend on the block's size. The cell terms come from the thread's
 * zg_cells_<RS>, computed once per tile row and target colour
 * (z_guided_cells.template.h).
 */
#if !defined(IN_T) || !defined(IS) || !defined(IN_IS_INT) || !defined(REAL) || !defined(RS)
#error "z_guided.template.h: define IN_T, IS, IN_IS_INT, REAL and RS"
#endif

#define ZG_CAT RGBZ_CAT3
#define RW RGBZ_CAT(w, RS)
#define RWD RGBZ_CAT(wd, RS)
#define RG RGBZ_CAT(g, RS)
#define ZG_CELLS RGBZ_CAT(zg_cells, RS)

/* the hash, the dot products and the fast path's rows (shared with learned) */
#include "learned_hash.template.h"

/* acc[ix] += row[x0 + PX ix] for the cells ix in [ia, ib), all inside the row (PX a constant
   where it is inlined, so that the strided loads vectorise) */
RGBZ_INLINE void ZG_CAT(zg_cg_add, IS, RS)(REAL *restrict acc, const IN_T *restrict row,
                                           ptrdiff_t x0, const int PX, ptrdiff_t ia,
                                           ptrdiff_t ib)
{
    RGBZ_IVDEP for (ptrdiff_t ix = ia; ix < ib; ix++) acc[ix] += (REAL)row[x0 + PX * ix];
}

/* the colour means of target t in tile row jy (0 <= jy < gy) into the padded row c: for
   each cell, its box's pixels of colour t summed in the order of the box, times the
   reciprocal of their count (REAL) */
RGBZ_CLONES_512
static void ZG_CAT(zg_cg_row, IS, RS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols, int py,
                                      int px, const rgbz_zguided_filters *f,
                                      const ZG_CELLS *st, int t, ptrdiff_t jy,
                                      REAL *restrict c)
{
    const ptrdiff_t gx = f->gx, y0 = f->zr + (ptrdiff_t)py * jy;
    REAL *restrict acc = c + 1;
    for (ptrdiff_t ix = 0; ix < gx; ix++) acc[ix] = 0;
    for (int i = 0; i < st->nbox[t]; i++) {
        const IN_T *restrict row = src + lrn_extend(y0 + st->ey[t][i], rows, py) * cols;
        const ptrdiff_t x0 = f->zc + st->ex[t][i];
        /* the cells whose column x0 + px ix lies inside the frame: [ia, ib) */
        ptrdiff_t ia = x0 < 0 ? (-x0 + px - 1) / px : 0;
        ptrdiff_t ib = x0 < cols ? (cols - 1 - x0) / px + 1 : 0;
        if (ib > gx) ib = gx;
        if (ia > ib) ia = ib;
        for (ptrdiff_t ix = 0; ix < ia; ix++)
            acc[ix] += (REAL)row[lrn_extend(x0 + px * ix, cols, px)];
        switch (px) {   /* the periods of Mask1 and Mask2, unrolled */
        case 2: ZG_CAT(zg_cg_add, IS, RS)(acc, row, x0, 2, ia, ib); break;
        case 4: ZG_CAT(zg_cg_add, IS, RS)(acc, row, x0, 4, ia, ib); break;
        default: ZG_CAT(zg_cg_add, IS, RS)(acc, row, x0, px, ia, ib);
        }
        for (ptrdiff_t ix = ib; ix < gx; ix++)
            acc[ix] += (REAL)row[lrn_extend(x0 + px * ix, cols, px)];
    }
    const REAL inv = (REAL)1 / (REAL)st->nbox[t];
    RGBZ_IVDEP for (ptrdiff_t ix = 0; ix < gx; ix++) acc[ix] *= inv;
    RGBZ_CAT(zg_pad, RS)(c, gx);
}

/* the cell terms [gx][ZG_CVR] of target t in tile row iy, computed if the thread does not
   hold them yet (with the colour means of the rows around it and, once per tile row, the
   noise levels into st->level) */
static const REAL *ZG_CAT(zg_cells_get, IS, RS)(ZG_CELLS *st, const rgbz_zguided_filters *f,
                                                const IN_T *src, ptrdiff_t rows,
                                                ptrdiff_t cols, int py, int px,
                                                ptrdiff_t iy, int t)
{
    const ptrdiff_t gx = f->gx, gy = f->gy, w = gx + 2;
    REAL *out = st->cell + (ptrdiff_t)t * ZG_CVR * gx;
    if (st->cell_tag[t] == iy) return out;
    const REAL *N[3], *V[3], *C[3];
    for (int r = 0; r < 3; r++) {
        ptrdiff_t jy = iy - 1 + r;
        jy = jy < 0 ? 0 : (jy >= gy ? gy - 1 : jy);
        const int slot = (int)(jy % 3);
        REAL *c = st->cg + ((ptrdiff_t)t * 3 + slot) * w;
        if (st->cg_tag[t][slot] != jy) {
            ZG_CAT(zg_cg_row, IS, RS)(src, rows, cols, py, px, f, st, t, jy, c);
            st->cg_tag[t][slot] = jy;
        }
        C[r] = c;
        REAL *n = st->nv + (ptrdiff_t)slot * 2 * w, *v = n + w;
        if (st->nv_tag[slot] != jy) {
            RGBZ_CAT(zg_guide_rows, RS)(st, f, py, px, jy, n, v);
            st->nv_tag[slot] = jy;
        }
        N[r] = n;
        V[r] = v;
    }
    REAL *nu = st->nv + 6 * w;
    RGBZ_CAT(zg_cell_row, RS)(N, V, C, gx, (REAL)f->lam, out, nu);
    if (st->level_tag != iy)
        RGBZ_CAT(zg_level_row, RS)(nu, gx, f->thr, f->n_levels - 1, st->level);
    st->level_tag = iy;
    st->cell_tag[t] = iy;
    return out;
}

/* the buckets b[j] = level * n_hash + bucket[j] of the n sites of phase k in tile row cells
   ix0, ix0 + 1, ... (clamped to the grid) */
RGBZ_INLINE void ZG_CAT(zg_buckets, IS, RS)(const int n, const rgbz_zguided_filters *f,
                                            const int32_t *restrict bucket, ptrdiff_t ix0,
                                            const int32_t *restrict level,
                                            int32_t *restrict b)
{
    const int nbh = f->hash->n_buckets;
    const ptrdiff_t gx = f->gx;
    if (ix0 + n <= gx) {   /* the cells ix0 .. ix0 + n - 1: contiguous */
        RGBZ_IVDEP for (int j = 0; j < n; j++) b[j] = level[ix0 + j] * nbh + bucket[j];
    } else {               /* past the grid's last column: its last cell */
        for (int j = 0; j < n; j++)
            b[j] = level[ix0 + j < gx ? ix0 + j : gx - 1] * nbh + bucket[j];
    }
}

/* the cell terms cj[m][j] (m < RGBZ_ZG_FEATURES: share u_m, then c_9, c_10) of the n sites in
   tile row cells ix0, ix0 + 1, ... (clamped to the grid), from the cell vectors */
RGBZ_INLINE void ZG_CAT(zg_prep, IS, RS)(const int n, const rgbz_zguided_filters *f,
                                         ptrdiff_t ix0, const REAL *restrict cell,
                                         REAL (*restrict cj)[LRN_BLK])
{
    const ptrdiff_t gx = f->gx;
    for (int j = 0; j < n; j++) {
        const REAL *restrict c = cell + (ix0 + j < gx ? ix0 + j : gx - 1) * ZG_CVR;
        for (int m = 0; m < 9; m++) cj[m][j] = c[m];
        cj[9][j] = c[10];
        cj[10][j] = c[11];
    }
}

/* res[j] += the guide term of the n sites of phase k (buckets b, cell terms cj, the sums of
   their baseline taps bsum, divided in place):
   base (sum_{m<9} g[b][m] c_m - g[b][9]) + g[b][9] c_9 + g[b][10] c_10, base = bsum / n_base */
RGBZ_INLINE void ZG_CAT(zg_guide, IS, RS)(const int n, const rgbz_zguided_filters *f, int k,
                                          const int32_t *restrict b,
                                          REAL (*restrict cj)[LRN_BLK], REAL *restrict bsum,
                                          REAL *restrict res)
{
    const ptrdiff_t nb = (ptrdiff_t)f->n_levels * f->hash->n_buckets;
    const REAL *restrict g = f->RG + (ptrdiff_t)k * nb * RGBZ_ZG_FEATURES;
    REAL s[LRN_BLK] = {0};
    const REAL inv_base = (REAL)1 / (REAL)f->n_base[k];
    RGBZ_IVDEP for (int j = 0; j < n; j++) {
        bsum[j] = OMUL(bsum[j], inv_base);
        s[j] = OMUL(g[b[j] * RGBZ_ZG_FEATURES], cj[0][j]);
    }
    for (int m = 1; m < 9; m++) {
        const REAL *restrict cm = cj[m];
        RGBZ_IVDEP for (int j = 0; j < n; j++)
            s[j] = OADD(s[j], OMUL(g[b[j] * RGBZ_ZG_FEATURES + m], cm[j]));
    }
    RGBZ_IVDEP for (int j = 0; j < n; j++) {
        const REAL *gj = g + b[j] * RGBZ_ZG_FEATURES;
        REAL r = OADD(res[j], OMUL(bsum[j], OSUB(s[j], gj[9])));
        r = OADD(r, OMUL(gj[9], cj[9][j]));
        res[j] = OADD(r, OMUL(gj[10], cj[10][j]));
    }
}

/* the generic path: the values res[j] of the n sites x0, x0 + px, ... of phase k (rows rowp,
   through the column map at the borders) in tile row cells ix0, ix0 + 1, ...: the taps, their
   hash, the colour dot product of bucket level * n_hash + hash bucket, the guide term */
RGBZ_CLONES_512
static void ZG_CAT(zg_generic_block, IS, RS)(const IN_T *const *rowp, ptrdiff_t x0, int px,
                                             int n, ptrdiff_t cols, const ptrdiff_t *colmap,
                                             const rgbz_zguided_filters *f, int k,
                                             ptrdiff_t ix0, const REAL *restrict cell,
                                             const int32_t *restrict level,
                                             REAL (*restrict v)[LRN_BLK], REAL *restrict res)
{
    const rgbz_learned_filters *h = f->hash;
    const ptrdiff_t nb = (ptrdiff_t)f->n_levels * h->n_buckets;
    const REAL *restrict w = f->RW + (ptrdiff_t)k * h->n_taps_max * nb;
    int32_t bucket[LRN_BLK], b[LRN_BLK] = {0};
    REAL cj[RGBZ_ZG_FEATURES][LRN_BLK], bsum[LRN_BLK];
    LRN_CAT(lrn_gather, IS, RS)(rowp, x0, px, n, cols, colmap, h, k, v);
    LRN_CAT(lrn_hash, IS, RS)(v, n, h, k, bucket);
    ZG_CAT(zg_buckets, IS, RS)(n, f, bucket, ix0, level, b);
    ZG_CAT(zg_prep, IS, RS)(n, f, ix0, cell, cj);
    LRN_CAT(lrn_dot, IS, RS)(v, n, w, h->n_taps[k], (int)nb, b, res);
    const int32_t *bi = f->base_idx + (ptrdiff_t)k * f->n_base_max;
    RGBZ_IVDEP for (int j = 0; j < n; j++) bsum[j] = v[bi[0]][j];
    for (int i = 1; i < f->n_base[k]; i++) {
        const REAL *restrict vi = v[bi[i]];
        RGBZ_IVDEP for (int j = 0; j < n; j++) bsum[j] = OADD(bsum[j], vi[j]);
    }
    ZG_CAT(zg_guide, IS, RS)(n, f, k, b, cj, bsum, res);
}

#if LRN_VECTOR_EXT
/* one site's accumulator (lrn_site_acc: its dense window against the weights w) plus its
   guide term, lane by lane (z_guided_cells.template.h's layout): base times the products
   of the first two rows of gw and c, plus those of gw's third row and c_9, c_10 */
RGBZ_INLINE void ZG_CAT(zg_site_acc, IS, RS)(const REAL *const *rowp, ptrdiff_t x,
                                             const REAL *restrict w, int rows,
                                             const REAL *restrict gw, const REAL *restrict c,
                                             REAL base, LRN_CAT(lrn_rv, IS, RS) *acc)
{
    typedef LRN_CAT(lrn_rv, IS, RS) rv;
    enum { L = (int)(32 / sizeof(REAL)) };
    rv a, t = {0}, gv, cv;
    LRN_CAT(lrn_site_acc, IS, RS)(rowp, x, w, rows, &a);
    for (int h = 0; h < 8 + L; h += L) {
        memcpy(&gv, gw + h, sizeof gv);
        memcpy(&cv, c + h, sizeof cv);
        t += gv * cv;
    }
    a += t * base;
    memcpy(&gv, gw + 8 + L, sizeof gv);
    *acc = a + gv * RGBZ_CAT(zg_low2, RS)(cv);
}
#endif

/* res[j] = the dense dot product of the site at x0 + j px (its bucket b[j]'s dense weights
   in wd, as lrn_dense_dot) plus its guide term (the guide weights gw of b[j], the cell vector
   of its tile column ix0 + j clamped to the grid, its baseline base[j]); with the vector
   extensions one accumulator per site, its lanes added in lane order for 8 floats' or 4
   doubles' sites at once (lrn_lane_sums) */
RGBZ_INLINE void ZG_CAT(zg_dot_rows, IS, RS)(const REAL *const *rowp, ptrdiff_t x0, int px,
                                             int n, const REAL *restrict wd, const int R,
                                             const int32_t *restrict b,
                                             const REAL *restrict gw,
                                             const REAL *restrict cell, ptrdiff_t ix0,
                                             ptrdiff_t gx, const REAL *restrict base,
                                             REAL (*restrict cj)[LRN_BLK],
                                             const rgbz_zguided_filters *f, int k,
                                             REAL *restrict res)
{
#if LRN_VECTOR_EXT
    typedef LRN_CAT(lrn_rv, IS, RS) rv;
    enum { L = (int)(32 / sizeof(REAL)) };
    const int rows = 2 * R + 1;
    (void)cj;
    (void)f;
    (void)k;
    (void)LRN_CAT(lrn_dense_dot, IS, RS);   /* learned's own dot product: not used here */
    int j = 0;
    for (; j + L <= n; j += L) {
        rv acc[L];
        for (int i = 0; i < L; i++) {
            const ptrdiff_t ix = ix0 + j + i < gx ? ix0 + j + i : gx - 1;
            ZG_CAT(zg_site_acc, IS, RS)(rowp, x0 + (ptrdiff_t)(j + i) * px - R,
                                        wd + (ptrdiff_t)b[j + i] * rows * 8, rows,
                                        gw + (ptrdiff_t)b[j + i] * ZG_GVR, cell + ix * ZG_CVR,
                                        base[j + i], &acc[i]);
        }
        rv sum;
        RGBZ_CAT(lrn_lane_sums, RS)(acc, &sum);
        memcpy(res + j, &sum, sizeof sum);
    }
    /* the last sites of a partial block: the same sums, one site at a time */
    for (; j < n; j++) {
        const ptrdiff_t ix = ix0 + j < gx ? ix0 + j : gx - 1;
        rv a;
        ZG_CAT(zg_site_acc, IS, RS)(rowp, x0 + (ptrdiff_t)j * px - R,
                                    wd + (ptrdiff_t)b[j] * rows * 8, rows,
                                    gw + (ptrdiff_t)b[j] * ZG_GVR, cell + ix * ZG_CVR, base[j],
                                    &a);
        res[j] = LRN_CAT(lrn_lane_total, IS, RS)(a);
    }
#else
    /* the dense dot product, then the guide term of the generic path */
    (void)gw;
    LRN_CAT(lrn_dense_dot, IS, RS)(rowp, x0, px, n, wd, R, b, res);
    (void)gx;
    ZG_CAT(zg_prep, IS, RS)(n, f, ix0, cell, cj);
    REAL bs[LRN_BLK];
    RGBZ_IVDEP for (int j = 0; j < n; j++) bs[j] = base[j] * (REAL)f->n_base[k];
    ZG_CAT(zg_guide, IS, RS)(n, f, k, b, cj, bs, res);
#endif
}

/* base[j]: the mean of the baseline taps of the n sites x0 + j PX of phase k (the REAL rows
   realp[dy + R]), summed in the order of the phase's list (PX a constant where it is
   inlined, so that the strided loads vectorise) */
RGBZ_INLINE void ZG_CAT(zg_base, IS, RS)(const REAL *const *realp, ptrdiff_t x0, const int PX,
                                         const int n, const rgbz_zguided_filters *f, int k,
                                         REAL *restrict base)
{
    const rgbz_learned_filters *h = f->hash;
    const int R = h->radius;
    const int32_t *bi = f->base_idx + (ptrdiff_t)k * f->n_base_max;
    const int32_t *tdy = h->tap_dy + (ptrdiff_t)k * h->n_taps_max;
    const int32_t *tdx = h->tap_dx + (ptrdiff_t)k * h->n_taps_max;
    {
        const REAL *restrict r = realp[tdy[bi[0]] + R] + x0 + tdx[bi[0]];
        RGBZ_IVDEP for (int j = 0; j < n; j++) base[j] = r[(ptrdiff_t)j * PX];
    }
    for (int i = 1; i < f->n_base[k]; i++) {
        const REAL *restrict r = realp[tdy[bi[i]] + R] + x0 + tdx[bi[i]];
        RGBZ_IVDEP for (int j = 0; j < n; j++) base[j] = OADD(base[j], r[(ptrdiff_t)j * PX]);
    }
    const REAL inv_base = (REAL)1 / (REAL)f->n_base[k];
    RGBZ_IVDEP for (int j = 0; j < n; j++) base[j] = OMUL(base[j], inv_base);
}

/* the fast path: the values res[j] of the n sites x0, x0 + px, ... of phase k in row y (the
   REAL rows realp[dy + R]; box sums bx of the phase's sites in the row from m0 on) in tile
   row cells ix0, ix0 + 1, ...: the hash from the box sums, then per site the dense colour
   dot product of bucket level * n_hash + hash bucket with its guide term (gw: the guide
   weights of z_guided_cells.template.h's layout, of phase k) */
RGBZ_CLONES_512
static void ZG_CAT(zg_fast_block, IS, RS)(const REAL *const *realp, ptrdiff_t y, ptrdiff_t x0,
                                          int px, int n, const rgbz_zguided_filters *f, int k,
                                          const REAL *bx, ptrdiff_t m0, ptrdiff_t cols,
                                          ptrdiff_t ix0, const REAL *restrict cell,
                                          const int32_t *restrict level,
                                          const REAL *restrict gw, REAL *restrict res)
{
    const rgbz_learned_filters *h = f->hash;
    const int R = h->radius;
    const ptrdiff_t nb = (ptrdiff_t)f->n_levels * h->n_buckets;
    int32_t bucket[LRN_BLK], b[LRN_BLK] = {0};
    REAL cj[RGBZ_ZG_FEATURES][LRN_BLK], base[LRN_BLK];
    LRN_CAT(lrn_fast_bucket, IS, RS)(y, x0, n, h, k, bx, m0, cols, bucket);
    ZG_CAT(zg_buckets, IS, RS)(n, f, bucket, ix0, level, b);
    /* the baseline: the mean of the baseline taps, summed in the order of the phase's list */
    switch (px) {   /* the periods of Mask1 and Mask2, unrolled */
    case 2: ZG_CAT(zg_base, IS, RS)(realp, x0, 2, n, f, k, base); break;
    case 4: ZG_CAT(zg_base, IS, RS)(realp, x0, 4, n, f, k, base); break;
    default: ZG_CAT(zg_base, IS, RS)(realp, x0, px, n, f, k, base);
    }
    const REAL *wd = f->RWD + (ptrdiff_t)k * nb * (2 * R + 1) * 8;
    gw += (ptrdiff_t)k * nb * ZG_GVR;
    switch (R) {      /* the window radii of the fast path, unrolled */
    case 1: ZG_CAT(zg_dot_rows, IS, RS)(realp, x0, px, n, wd, 1, b, gw, cell, ix0, f->gx, base,
                                        cj, f, k, res); break;
    case 2: ZG_CAT(zg_dot_rows, IS, RS)(realp, x0, px, n, wd, 2, b, gw, cell, ix0, f->gx, base,
                                        cj, f, k, res); break;
    case 3: ZG_CAT(zg_dot_rows, IS, RS)(realp, x0, px, n, wd, 3, b, gw, cell, ix0, f->gx, base,
                                        cj, f, k, res); break;
    default: ZG_CAT(zg_dot_rows, IS, RS)(realp, x0, px, n, wd, R, b, gw, cell, ix0, f->gx,
                                         base, cj, f, k, res);
    }
}

/* the frame loop: every row copied, then the Z sites of its phases, the interior ones
   (columns fast_lo .. fast_hi: the dense window and the hash pairs inside the row) through the
   fast path when fast_ok (z_guided.c), the others through the generic path. One pass over
   the rows: the fast path's rings and the cell terms of a tile row serve the rows of a
   thread that follow (static schedule: consecutive rows); the rings span the row's width
   (the cell terms are computed for whole tile rows, once). */
static int ZG_CAT(zg_loop, IS, RS)(const IN_T *restrict src, IN_T *restrict dst,
                                   ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                                   const int32_t *phase_map, const rgbz_zguided_filters *f,
                                   const ptrdiff_t *colmap, int fast_ok, double maxval_d,
                                   int workers, uint64_t *opcounts)
{
    const rgbz_learned_filters *h = f->hash;
    const int R = h->radius, hr = h->hash_radius;
    const REAL maxval = (REAL)maxval_d;
    const ptrdiff_t fast_lo = R > hr ? R : hr;
    const ptrdiff_t fast_hi = cols - 8 + R < cols - 1 - hr ? cols - 8 + R : cols - 1 - hr;
    const int dense = fast_ok && fast_lo <= fast_hi;
    REAL *valid = NULL, *gw = NULL;
    if (dense) {
        /* valid[tile row][d][x]: 1 where the pixel and its partner along d are both known */
        valid = LRN_CAT(lrn_valid, IS, RS)(cols, py, px, phase_map);
        gw = RGBZ_CAT(zg_guide_weights, RS)(f);
        if (!valid || !gw) {
            free(valid);
            free(gw);
            return RGBZ_ENOMEM;
        }
    }
    /* the columns the fast path converts and reads */
    const ptrdiff_t ra = fast_lo - LRN_HALO > 0 ? fast_lo - LRN_HALO : 0;
    const ptrdiff_t rb = fast_hi + 1 + LRN_HALO < cols ? fast_hi + 1 + LRN_HALO : cols;
    int status = RGBZ_OK;
    (void)opcounts;
#ifdef _OPENMP
    const int nth = workers > 0 ? workers : omp_get_max_threads();
#pragma omp parallel num_threads(nth)
#else
    (void)workers;
#endif
    {
        ZG_CELLS st;
        int ok = RGBZ_CAT(zg_cells_init, RS)(&st, f, py, px) == RGBZ_OK;
        /* the fast path's rows: cs (2 per direction), bxs (1 per direction and the 4 class
           rows, of the sites of one phase), the REAL ring, the D rings */
        REAL *scratch = dense ? malloc((size_t)cols * (3 * RGBZ_LEARNED_DIRS + 4 + LRN_RING +
                                                       RGBZ_LEARNED_DIRS * LRN_RING) *
                                       sizeof(REAL))
                              : NULL;
        ok &= !dense || scratch != NULL;
        if (!ok) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ENOMEM;
        }
        REAL *conv = scratch ? scratch + (ptrdiff_t)(3 * RGBZ_LEARNED_DIRS + 4) * cols : NULL;
        REAL *bxs = scratch ? scratch + (ptrdiff_t)2 * RGBZ_LEARNED_DIRS * cols : NULL;
        REAL *dsq = scratch ? conv + (ptrdiff_t)LRN_RING * cols : NULL;
        const int split = h->n_spr > 1;
        ptrdiff_t ctag[LRN_RING], dtag[RGBZ_LEARNED_DIRS * LRN_RING];
        for (int i = 0; i < LRN_RING; i++) ctag[i] = PTRDIFF_MIN;
        for (int i = 0; i < RGBZ_LEARNED_DIRS * LRN_RING; i++) dtag[i] = PTRDIFF_MIN;
        REAL v[RGBZ_LEARNED_MAX_TAPS][LRN_BLK];
        REAL res[LRN_BLK];
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t y = 0; y < rows; y++) {
            IN_T *restrict drow = dst + y * cols;
            memcpy(drow, src + y * cols, (size_t)cols * sizeof(IN_T));
            if (!ok) continue;
            const int32_t *pm = phase_map + (y % py) * px;
            int row_has_z = 0;
            for (int i = 0; i < px; i++) row_has_z |= pm[i] >= 0;
            if (!row_has_z) continue;
            const IN_T *rowp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
            for (int dy = -R; dy <= R; dy++)
                rowp[dy + R] = src + lrn_extend(y + dy, rows, py) * cols;
            const REAL *realp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
            if (dense) {
                LRN_CAT(lrn_energies, IS, RS)(src, rows, y, py, valid, cols, hr, split, fast_lo,
                                              fast_hi + 1, ra, rb, conv, ctag, dsq, dtag,
                                              scratch);
                for (int dy = -R; dy <= R; dy++)
                    realp[dy + R] = LRN_CAT(lrn_real_row, IS, RS)(src, rows, cols, py, y + dy,
                                                                  ra, rb, conv, ctag);
            }
            const ptrdiff_t iy = y / py < f->gy ? y / py : f->gy - 1;
            for (int c0 = 0; c0 < px && c0 < cols; c0++) {
                const int k = pm[c0];
                if (k < 0) continue;
#ifdef RGBZ_COUNT_OPS
                rgbz_opc_cur = opcounts + (size_t)k * RGBZ_NOPS;
#endif
                const REAL *cell = ZG_CAT(zg_cells_get, IS, RS)(&st, f, src, rows, cols, py,
                                                                  px, iy, f->targets[k]);
                /* the fast sites of this phase: xf .. xl (none when xf > xl) */
                ptrdiff_t xf = cols, xl = -1;
                if (dense) {
                    xf = fast_lo + ((c0 - fast_lo) % px + px) % px;
                    xl = fast_hi - ((fast_hi - c0) % px + px) % px;
                }
                for (ptrdiff_t x0 = c0; x0 < cols;) {
                    if (x0 >= xf && x0 <= xl) {
                        /* the fast sites: their box sums, then blocks of them */
                        LRN_CAT(lrn_rows, IS, RS)(scratch, cols, hr, split, xf, px,
                                                  (int)((xl - xf) / px + 1), bxs);
                        for (ptrdiff_t xb = xf; xb <= xl;) {
                            const ptrdiff_t left = (xl - xb) / px + 1;
                            const int n = (int)(left < LRN_BLK ? left : LRN_BLK);
                            ZG_CAT(zg_fast_block, IS, RS)(realp, y, xb, px, n, f, k, bxs,
                                                          (xb - xf) / px, cols, xb / px, cell,
                                                          st.level, gw, res);
                            for (int j = 0; j < n; j++)
                                drow[xb + (ptrdiff_t)j * px] =
                                    (IN_T)RGBZ_CAT(rgbz_out, RS)(res[j], maxval, IN_IS_INT);
                            xb += (ptrdiff_t)n * px;
                        }
                        x0 = xl + px;
                        continue;
                    }
                    /* border sites: up to the first fast site, or to the end */
                    const ptrdiff_t stop = x0 < xf ? xf : cols;
                    const ptrdiff_t left = (stop - 1 - x0) / px + 1;
                    const int n = (int)(left < LRN_BLK ? left : LRN_BLK);
                    ZG_CAT(zg_generic_block, IS, RS)(rowp, x0, px, n, cols, colmap, f, k,
                                                     x0 / px, cell, st.level, v, res);
                    for (int j = 0; j < n; j++)
                        drow[x0 + (ptrdiff_t)j * px] =
                            (IN_T)RGBZ_CAT(rgbz_out, RS)(res[j], maxval, IN_IS_INT);
                    x0 += (ptrdiff_t)n * px;
                }
            }
        }
        free(scratch);
        if (st.bad && ok) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ZG_SITES;
        }
        RGBZ_CAT(zg_cells_free, RS)(&st);
    }
    free(valid);
    free(gw);
    return status;
}

#undef ZG_CAT
#undef RW
#undef RWD
#undef RG
#undef ZG_CELLS
