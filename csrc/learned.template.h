/*
 * learned.template.h -- the frame loop of the learned reconstruction for one input
 * element type and one precision. Instantiated by learned_entry.template.h through
 * rgbz_each_type.h (rgbz_templating.h), once per element type and precision, with
 *   IN_T       the element type (uint8_t, uint16_t, float, double)
 *   IS         its suffix (u8, u16, f32, f64)
 *   IN_IS_INT  1 for the integer types (outputs rounded half up)
 *   REAL       the arithmetic (float or double)
 *   RS         its suffix (f32, f64): the weights are the members w_<RS>, wd_<RS> of
 *              rgbz_learned_filters (RW, RWD below)
 *
 * The sites of one phase in one row are processed in blocks of LRN_BLK: the taps are
 * loaded tap-major (v[t][j], tap t of site j), the hash runs on whole rows of v
 * (branch-free selects), and the dot product gathers each site's weight of tap t
 * from the tap-major weight table (w[t][bucket]), so every loop runs over j. Interior sites
 * take the fast path (box sums, dense weights: learned_hash.template.h), the sites of a phase
 * in a strip row all at once.
 */
#ifndef IN_T
#error "learned.template.h: define IN_T (the element type)"
#endif
#ifndef IS
#error "learned.template.h: define IS (the element type's suffix)"
#endif
#ifndef IN_IS_INT
#error "learned.template.h: define IN_IS_INT (1 for integer element types)"
#endif
#ifndef REAL
#error "learned.template.h: define REAL (float or double)"
#endif
#ifndef RS
#error "learned.template.h: define RS (the precision's suffix)"
#endif

/* the weights of this instance (LRN_CAT, learned_common.h: its names) */
#define RW RGBZ_CAT(w, RS)
#define RWD RGBZ_CAT(wd, RS)

/* the hash, the dot products and the fast path's rows (shared with z_guided) */
#include "learned_hash.template.h"


/* the sites x0, x0 + px, ... (n of them, n <= LRN_BLK) of phase k through the generic path:
   taps gathered tap-major (through the column map at the borders), hash pairs, dot */
static void LRN_CAT(lrn_generic_block, IS, RS)(const IN_T *const *rowp, ptrdiff_t x0, int px,
                                                int n, ptrdiff_t cols,
                                                const ptrdiff_t *colmap,
                                                const rgbz_learned_filters *f, int k,
                                                const REAL *w, REAL (*v)[LRN_BLK],
                                                int32_t *bucket, REAL *res)
{
    LRN_CAT(lrn_gather, IS, RS)(rowp, x0, px, n, cols, colmap, f, k, v);
    LRN_CAT(lrn_hash, IS, RS)(v, n, f, k, bucket);
    LRN_CAT(lrn_dot, IS, RS)(v, n, w, f->n_taps[k], f->n_buckets, bucket, res);
}

/* the border sites (ys[j], xs[j]) of phase k, n <= LRN_BLK of them from any rows, through the
   per-site path (taps through the column map, hash pairs, dot), written to dst: the border
   sites of the fast path, gathered across rows so that the per-site path runs on whole
   blocks (row by row it had two sites or so per block) */
static void LRN_CAT(lrn_border_block, IS, RS)(const IN_T *src, IN_T *dst, ptrdiff_t rows,
                                               ptrdiff_t cols, int py, const ptrdiff_t *ys,
                                               const ptrdiff_t *xs, int n,
                                               const ptrdiff_t *colmap,
                                               const rgbz_learned_filters *f, int k,
                                               const REAL *w, REAL maxval, REAL (*v)[LRN_BLK],
                                               int32_t *bucket, REAL *res)
{
    const int R = f->radius, nt = f->n_taps[k];
    const int32_t *tdy = f->tap_dy + (ptrdiff_t)k * f->n_taps_max;
    const int32_t *tdx = f->tap_dx + (ptrdiff_t)k * f->n_taps_max;
    const IN_T *rp[2 * RGBZ_LEARNED_MAX_RADIUS + 1][LRN_BLK];
    for (int dy = -R; dy <= R; dy++)
        for (int j = 0; j < n; j++) rp[dy + R][j] = src + lrn_extend(ys[j] + dy, rows, py) * cols;
    for (int t = 0; t < nt; t++) {
        const IN_T *const *rt = rp[tdy[t] + R];
        const ptrdiff_t *cm = colmap + R + tdx[t];
        for (int j = 0; j < n; j++) v[t][j] = (REAL)rt[j][cm[xs[j]]];
    }
    LRN_CAT(lrn_hash, IS, RS)(v, n, f, k, bucket);
    LRN_CAT(lrn_dot, IS, RS)(v, n, w, nt, f->n_buckets, bucket, res);
    for (int j = 0; j < n; j++)
        dst[ys[j] * cols + xs[j]] = (IN_T)RGBZ_CAT(rgbz_out, RS)(res[j], maxval, IN_IS_INT);
}

static int LRN_CAT(lrn_loop, IS, RS)(const IN_T *restrict src, IN_T *restrict dst,
                                     ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                                     const int32_t *phase_map, const rgbz_learned_filters *f,
                                     const ptrdiff_t *colmap, int fast_ok,
                                     double maxval_d, int workers, uint64_t *opcounts)
{
    const int R = f->radius, hr = f->hash_radius;
    const REAL maxval = (REAL)maxval_d;
    const REAL *weights = f->RW;
    /* the fast path's sites: the dense window (columns x - R .. x - R + 7) and the hash pairs
       (columns x - hr .. x + hr) inside the row */
    const ptrdiff_t fast_lo = R > hr ? R : hr;
    const ptrdiff_t fast_hi = cols - 8 + R < cols - 1 - hr ? cols - 8 + R : cols - 1 - hr;
    const REAL *dense = fast_ok ? f->RWD : NULL;
    REAL *valid = NULL;
    if (dense) {
        /* valid[tile row][d][x]: 1 where the pixel and its partner along d are both known */
        valid = LRN_CAT(lrn_valid, IS, RS)(cols, py, px, phase_map);
        if (!valid) return RGBZ_ENOMEM;
    }
    int status = RGBZ_OK;
    (void)opcounts;
#ifdef _OPENMP
    int nth = workers > 0 ? workers : omp_get_max_threads();
#pragma omp parallel num_threads(nth)
#else
    (void)workers;
#endif
    {
        /* the fast path's rows: cs (2 per direction), bxs (1 per direction and the 4 class
           rows, of the sites of one phase), the REAL ring, the D rings */
        REAL *scratch = dense ? malloc((size_t)cols * (3 * RGBZ_LEARNED_DIRS + 4 + LRN_RING +
                                                       RGBZ_LEARNED_DIRS * LRN_RING + 1) *
                                       sizeof(REAL))
                              : NULL;
        /* the fast sites of one phase in a strip row, all at once: their results (the last
           row of scratch) and buckets */
        int32_t *fbucket = scratch ? malloc((size_t)cols * sizeof *fbucket) : NULL;
        REAL *fres = fbucket ? scratch + (ptrdiff_t)(3 * RGBZ_LEARNED_DIRS + 4 + LRN_RING +
                                                     RGBZ_LEARNED_DIRS * LRN_RING) * cols
                             : NULL;
        if (!fbucket) {
            free(scratch);
            scratch = NULL;
        }
        REAL *conv = scratch ? scratch + (ptrdiff_t)(3 * RGBZ_LEARNED_DIRS + 4) * cols : NULL;
        REAL *bxs = scratch ? scratch + (ptrdiff_t)2 * RGBZ_LEARNED_DIRS * cols : NULL;
        const int split = f->n_spr > 1;
        REAL *dsq = scratch ? conv + (ptrdiff_t)LRN_RING * cols : NULL;
        ptrdiff_t ctag[LRN_RING], dtag[RGBZ_LEARNED_DIRS * LRN_RING];
        const int nomem = dense && !scratch;
        if (nomem) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            status = RGBZ_ENOMEM;
        }
        const int fast = scratch && fast_lo <= fast_hi;
        REAL v[RGBZ_LEARNED_MAX_TAPS][LRN_BLK];
        int32_t bucket[LRN_BLK];
        REAL res[LRN_BLK];
        /* the fast path's border sites waiting for a block of their phase k: pend_n[k] of
           them, rows pend[k][0][...], columns pend[k][1][...] (without the memory, each
           row's border sites run on their own) */
        ptrdiff_t (*pend)[2][LRN_BLK] = fast ? malloc((size_t)f->n_phases * sizeof *pend) : NULL;
        int *pend_n = fast ? calloc((size_t)f->n_phases, sizeof *pend_n) : NULL;
        const int batch = pend && pend_n;
        /* every row: the colour sites and the border (generic) sites; the fast sites below,
           in strips. Both loops give each thread the same rows (static schedule), which the
           rings need: a thread's rows are consecutive within each strip. */
#ifdef _OPENMP
#pragma omp for schedule(static) nowait
#endif
        for (ptrdiff_t y = 0; y < rows; y++) {
            const IN_T *rowp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
            for (int dy = -R; dy <= R; dy++)
                rowp[dy + R] = src + lrn_extend(y + dy, rows, py) * cols;
            const int32_t *pm = phase_map + (y % py) * px;
            int row_has_z = 0;
            for (int i = 0; i < px; i++) row_has_z |= pm[i] >= 0;
            IN_T *restrict drow = dst + y * cols;
            const IN_T *srow = src + y * cols;
            if (!row_has_z || !fast) {
                memcpy(drow, srow, (size_t)cols * sizeof(IN_T));
            } else {   /* the strips copy fast_lo .. fast_hi */
                memcpy(drow, srow, (size_t)fast_lo * sizeof(IN_T));
                memcpy(drow + fast_hi + 1, srow + fast_hi + 1,
                       (size_t)(cols - 1 - fast_hi) * sizeof(IN_T));
            }
            if (!row_has_z || nomem) continue;
            for (int ph0 = 0; ph0 < px && ph0 < cols; ph0++) {
                const int k = pm[ph0];
                if (k < 0) continue;
#ifdef RGBZ_COUNT_OPS
                rgbz_opc_cur = opcounts + (size_t)k * RGBZ_NOPS;
#endif
                const REAL *w = weights + (ptrdiff_t)k * f->n_taps_max * f->n_buckets;
                /* the fast sites of this phase: xf .. xl (none when xf > xl) */
                ptrdiff_t xf = cols, xl = -1;
                if (fast) {
                    xf = fast_lo + ((ph0 - fast_lo) % px + px) % px;
                    xl = fast_hi - ((fast_hi - ph0) % px + px) % px;
                }
                for (ptrdiff_t x0 = ph0; x0 < cols;) {
                    if (x0 >= xf && x0 <= xl) {   /* skip the fast sites */
                        x0 = xl + px;
                        continue;
                    }
                    if (batch) {   /* a border site of the fast path: to its phase's block */
                        pend[k][0][pend_n[k]] = y;
                        pend[k][1][pend_n[k]] = x0;
                        if (++pend_n[k] == LRN_BLK) {
                            LRN_CAT(lrn_border_block, IS, RS)(src, dst, rows, cols, py,
                                                              pend[k][0], pend[k][1], LRN_BLK,
                                                              colmap, f, k, w, maxval, v,
                                                              bucket, res);
                            pend_n[k] = 0;
                        }
                        x0 += px;
                        continue;
                    }
                    /* border sites: up to the first fast site, or to the end */
                    const ptrdiff_t stop = x0 < xf ? xf : cols;
                    const ptrdiff_t left = (stop - 1 - x0) / px + 1;
                    const int n = (int)(left < LRN_BLK ? left : LRN_BLK);
                    LRN_CAT(lrn_generic_block, IS, RS)(rowp, x0, px, n, cols, colmap, f, k, w, v,
                                                       bucket, res);
                    for (int j = 0; j < n; j++)
                        drow[x0 + (ptrdiff_t)j * px] =
                            (IN_T)RGBZ_CAT(rgbz_out, RS)(res[j], maxval, IN_IS_INT);
                    x0 += (ptrdiff_t)n * px;
                }
            }
        }
        /* this thread's last border sites (its rows: the same thread wrote their colour
           sites above) */
        for (int k = 0; batch && k < f->n_phases; k++)
            if (pend_n[k])
                LRN_CAT(lrn_border_block, IS, RS)(src, dst, rows, cols, py, pend[k][0],
                                                  pend[k][1], pend_n[k], colmap, f, k,
                                                  weights + (ptrdiff_t)k * f->n_taps_max *
                                                                f->n_buckets,
                                                  maxval, v, bucket, res);
        free(pend);
        free(pend_n);
        /* the fast sites, in strips of LRN_STRIP columns so that the rings' part of a strip
           stays in the cache from one Z row to the next */
        for (ptrdiff_t sa = fast_lo; fast && sa <= fast_hi; sa += LRN_STRIP) {
            const ptrdiff_t sb = sa + LRN_STRIP < fast_hi + 1 ? sa + LRN_STRIP : fast_hi + 1;
            const ptrdiff_t ra = sa - LRN_HALO > 0 ? sa - LRN_HALO : 0;
            const ptrdiff_t rb = sb + LRN_HALO < cols ? sb + LRN_HALO : cols;
            for (int i = 0; i < LRN_RING; i++) ctag[i] = PTRDIFF_MIN;
            for (int i = 0; i < RGBZ_LEARNED_DIRS * LRN_RING; i++) dtag[i] = PTRDIFF_MIN;
#ifdef _OPENMP
#pragma omp for schedule(static) nowait
#endif
            for (ptrdiff_t y = 0; y < rows; y++) {
                const int32_t *pm = phase_map + (y % py) * px;
                int row_has_z = 0;
                for (int i = 0; i < px; i++) row_has_z |= pm[i] >= 0;
                if (!row_has_z) continue;
                IN_T *restrict drow = dst + y * cols;
                memcpy(drow + sa, src + y * cols + sa, (size_t)(sb - sa) * sizeof(IN_T));
                const REAL *realp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
                LRN_CAT(lrn_energies, IS, RS)(src, rows, y, py, valid, cols, hr, split, sa, sb,
                                              ra, rb, conv, ctag, dsq, dtag, scratch);
                for (int dy = -R; dy <= R; dy++)
                    realp[dy + R] = LRN_CAT(lrn_real_row, IS, RS)(src, rows, cols, py, y + dy,
                                                                  ra, rb, conv, ctag);
                for (int ph0 = 0; ph0 < px; ph0++) {
                    const int k = pm[ph0];
                    if (k < 0) continue;
                    /* the sites of this phase in the strip (all of them fast sites): their
                       box sums, then blocks of them */
                    const ptrdiff_t xs = sa + ((ph0 - sa) % px + px) % px;
                    if (xs >= sb) continue;
                    const int n = (int)((sb - 1 - xs) / px + 1);
                    LRN_CAT(lrn_rows, IS, RS)(scratch, cols, hr, split, xs, px, n, bxs);
                    LRN_CAT(lrn_fast_bucket, IS, RS)(y, xs, n, f, k, bxs, 0, cols, fbucket);
                    LRN_CAT(lrn_dense_dot, IS, RS)(realp, xs, px, n,
                                                   dense + (ptrdiff_t)k * f->n_buckets *
                                                               (2 * R + 1) * 8,
                                                   R, fbucket, fres);
                    for (int j = 0; j < n; j++)
                        drow[xs + (ptrdiff_t)j * px] =
                            (IN_T)RGBZ_CAT(rgbz_out, RS)(fres[j], maxval, IN_IS_INT);
                }
            }
        }
        free(scratch);
        free(fbucket);
    }
    free(valid);
    return status;
}

#undef RW
#undef RWD
