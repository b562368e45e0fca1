/*
 * learned.template.h -- the frame loop of the learned reconstruction for one input
 * element type and one precision. Included by learned.c once per combination, with
 *   IN_T       the element type (uint8_t, uint16_t, float, double)
 *   IS         its suffix (u8, u16, f32, f64)
 *   IN_IS_INT  1 for the integer types (outputs rounded half up)
 *   REAL       the arithmetic (float or double)
 *   RS         its suffix (f32, f64)
 *   RW         the member of rgbz_learned_filters holding the weights in REAL
 *
 * The sites of one phase in one row are processed in blocks of LRN_BLK: the taps are
 * loaded tap-major (v[t][j], tap t of site j), the hash runs on whole rows of v
 * (branch-free selects), and the dot product gathers each site's weight of tap t
 * from the tap-major weight table (w[t][bucket]), so every loop runs over j.
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
#ifndef RW
#error "learned.template.h: define RW (w_f32 or w_f64)"
#endif

#define LRN_CAT3(a, b, c) a##_##b##_##c
#define LRN_CAT(a, b, c) LRN_CAT3(a, b, c)

/* a result as an output element: clamped to [0, maxval] (NaN to 0), integers rounded
   half up; not counted (Table 1 counts no conversion) */
static inline IN_T LRN_CAT(lrn_out, IS, RS)(REAL r, REAL maxval)
{
    r = r > (REAL)0 ? r : (REAL)0;
    r = r > maxval ? maxval : r;
#if IN_IS_INT
    return (IN_T)(r + (REAL)0.5);
#else
    return (IN_T)r;
#endif
}

/* the buckets of the n sites whose taps are v[t][j] (phase k); every loop runs over the
   sites (to the run-time n, so that the compiler vectorises it rather than unrolling it) */
RGBZ_CLONES
static void LRN_CAT(lrn_hash, IS, RS)(REAL (*restrict v)[LRN_BLK], int n,
                                       const rgbz_learned_filters *f, int k,
                                       int32_t *restrict bucket)
{
    REAL e[RGBZ_LEARNED_DIRS][LRN_BLK];
    for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
        const int np = f->n_pairs[k * RGBZ_LEARNED_DIRS + d];
        const int32_t *pa = f->pair_a + ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * f->n_pairs_max;
        const int32_t *pb = f->pair_b + ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * f->n_pairs_max;
        REAL *restrict ed = e[d];
        {
            const REAL *restrict va = v[pa[0]], *restrict vb = v[pb[0]];
            LRN_IVDEP for (int j = 0; j < n; j++) {
                const REAL df = OSUB(va[j], vb[j]);
                ed[j] = OMUL(df, df);
            }
        }
        LRN_NOJAM for (int p = 1; p < np; p++) {
            const REAL *restrict va = v[pa[p]], *restrict vb = v[pb[p]];
            LRN_IVDEP for (int j = 0; j < n; j++) {
                const REAL df = OSUB(va[j], vb[j]);
                ed[j] = OADD(ed[j], OMUL(df, df));
            }
        }
        const REAL inv = (REAL)1 / (REAL)np;
        LRN_IVDEP for (int j = 0; j < n; j++) ed[j] = OMUL(ed[j], inv);
    }
    const int ns = f->n_str, nc = f->n_coh;
    const double *st = f->str_thr + (ptrdiff_t)k * (ns - 1);
    const double *ct = f->coh_thr2 + (ptrdiff_t)k * (nc - 1);
    const REAL C = (REAL)0.92387953251128674, S = (REAL)0.38268343236508978;
    REAL tt[LRN_BLK], m2[LRN_BLK];
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
        bucket[j] = (4 * neg + 2 * left + OCMP(br2 > ar2)) * (ns * nc);
        tt[j] = t;
        m2[j] = OADD(OMUL(a, a), OMUL(b, b));
    }
    for (int i = 0; i < ns - 1; i++) {
        const REAL thr = (REAL)st[i];
        LRN_IVDEP for (int j = 0; j < n; j++) bucket[j] += nc * OCMP(tt[j] > thr);
    }
    if (nc > 1) {
        LRN_IVDEP for (int j = 0; j < n; j++) tt[j] = OMUL(tt[j], tt[j]);
        for (int i = 0; i < nc - 1; i++) {
            const REAL thr = (REAL)ct[i];
            LRN_IVDEP for (int j = 0; j < n; j++) bucket[j] += OCMP(m2[j] > OMUL(thr, tt[j]));
        }
    }
}

/* res[j] = sum_t w[t][bucket[j]] * v[t][j] */
RGBZ_CLONES
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

static int LRN_CAT(lrn_loop, IS, RS)(const IN_T *restrict src, IN_T *restrict dst,
                                     ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                                     const int32_t *phase_map, const rgbz_learned_filters *f,
                                     const ptrdiff_t *colmap, double maxval_d, int workers,
                                     uint64_t *opcounts)
{
    const int R = f->radius;
    const REAL maxval = (REAL)maxval_d;
    const REAL *weights = f->RW;
    (void)opcounts;
#ifdef _OPENMP
    int nth = workers > 0 ? workers : omp_get_max_threads();
#pragma omp parallel for schedule(static) num_threads(nth)
#else
    (void)workers;
#endif
    for (ptrdiff_t y = 0; y < rows; y++) {
        const IN_T *rowp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
        for (int dy = -R; dy <= R; dy++)
            rowp[dy + R] = src + lrn_extend(y + dy, rows, py) * cols;
        memcpy(dst + y * cols, src + y * cols, (size_t)cols * sizeof(IN_T));
        const int32_t *pm = phase_map + (y % py) * px;
        REAL v[RGBZ_LEARNED_MAX_TAPS][LRN_BLK];
        int32_t bucket[LRN_BLK];
        REAL res[LRN_BLK];
        for (int ph0 = 0; ph0 < px && ph0 < cols; ph0++) {
            const int k = pm[ph0];
            if (k < 0) continue;
#ifdef RGBZ_COUNT_OPS
            rgbz_opc_cur_count = opcounts + (size_t)k * RGBZ_NOPS;
#endif
            const int nt = f->n_taps[k];
            const int32_t *tdy = f->tap_dy + (ptrdiff_t)k * f->n_taps_max;
            const int32_t *tdx = f->tap_dx + (ptrdiff_t)k * f->n_taps_max;
            const REAL *w = weights + (ptrdiff_t)k * f->n_taps_max * f->n_buckets;
            for (ptrdiff_t x0 = ph0; x0 < cols; x0 += (ptrdiff_t)px * LRN_BLK) {
                const ptrdiff_t left = (cols - 1 - x0) / px + 1;
                const int n = (int)(left < LRN_BLK ? left : LRN_BLK);
                const ptrdiff_t xl = x0 + (ptrdiff_t)(n - 1) * px;
                if (x0 - R >= 0 && xl + R < cols) {
                    /* interior block: the taps are plain strided loads */
                    for (int t = 0; t < nt; t++) {
                        const IN_T *restrict row = rowp[tdy[t] + R] + x0 + tdx[t];
                        LRN_IVDEP for (int j = 0; j < n; j++) v[t][j] = (REAL)row[(ptrdiff_t)j * px];
                    }
                } else {
                    /* a border block: columns through the period-shift map */
                    for (int t = 0; t < nt; t++) {
                        const IN_T *restrict row = rowp[tdy[t] + R];
                        const ptrdiff_t *cm = colmap + x0 + R + tdx[t];
                        LRN_IVDEP for (int j = 0; j < n; j++) v[t][j] = (REAL)row[cm[(ptrdiff_t)j * px]];
                    }
                }
                LRN_CAT(lrn_hash, IS, RS)(v, n, f, k, bucket);
                LRN_CAT(lrn_dot, IS, RS)(v, n, w, nt, f->n_buckets, bucket, res);
                IN_T *restrict d = dst + y * cols + x0;
                LRN_IVDEP for (int j = 0; j < n; j++)
                    d[(ptrdiff_t)j * px] = LRN_CAT(lrn_out, IS, RS)(res[j], maxval);
            }
        }
    }
    return RGBZ_OK;
}

#undef LRN_CAT
#undef LRN_CAT3
