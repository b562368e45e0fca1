/*
 * z_guided.template.h -- the frame loop of the z_guided reconstruction (z_guided.h) for one
 * element type and one precision. Included by z_guided.c once per combination, with
 *   IN_T       the element type (uint8_t, uint16_t, float, double)
 *   IS         its suffix (u8, u16, f32, f64)
 *   IN_IS_INT  1 for the integer types (outputs rounded half up)
 *   REAL       the arithmetic (float or double)
 *   RS         its suffix (f32, f64)
 *   RW, RG     the members of rgbz_zguided_filters holding the colour and guide weights in REAL
 *
 * One site at a time: its taps (through the column map at the borders), the hash of
 * learned.h in the order of csrc/learned.template.h's generic path (so that both methods
 * give a site the same hash bucket), its noise level, one dot product over the taps and one
 * over the guide features of its cell.
 */
#if !defined(IN_T) || !defined(IS) || !defined(IN_IS_INT) || !defined(REAL) || !defined(RS) || \
    !defined(RW) || !defined(RG)
#error "z_guided.template.h: define IN_T, IS, IN_IS_INT, REAL, RS, RW and RG"
#endif

#define ZG_CAT3(a, b, c) a##_##b##_##c
#define ZG_CAT(a, b, c) ZG_CAT3(a, b, c)

/* the hash bucket of one site from its taps v (phase k): learned.h's octant, strength,
   coherence and channel spread of the direction and colour energies */
static int ZG_CAT(zg_hash, IS, RS)(const REAL *v, const rgbz_learned_filters *h, int k)
{
    REAL e[RGBZ_LEARNED_DIRS];
    REAL ec[3] = {0, 0, 0};
    const int nk = h->n_spr;
    for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
        const int np = h->n_pairs[k * RGBZ_LEARNED_DIRS + d];
        const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * h->n_pairs_max;
        const int32_t *pa = h->pair_a + o, *pb = h->pair_b + o, *pc = h->pair_col + o;
        const int spread = nk > 1 && d < RGBZ_LEARNED_SPREAD_DIRS;
        REAL df = OSUB(v[pa[0]], v[pb[0]]);
        REAL s = OMUL(df, df);
        if (spread) ec[pc[0]] = OADD(ec[pc[0]], s);
        for (int p = 1; p < np; p++) {
            df = OSUB(v[pa[p]], v[pb[p]]);
            const REAL sq = OMUL(df, df);
            s = OADD(s, sq);
            if (spread) ec[pc[p]] = OADD(ec[pc[p]], sq);
        }
        e[d] = OMUL(s, (REAL)1 / (REAL)np);
    }
    const int ns = h->n_str, nc = h->n_coh;
    const double *st = h->str_thr + (ptrdiff_t)k * (ns - 1);
    const double *ct = h->coh_thr2 + (ptrdiff_t)k * (nc - 1);
    const double *kt = h->spr_thr + (ptrdiff_t)k * (nk - 1);
    const REAL C = (REAL)0.92387953251128674, S = (REAL)0.38268343236508978;
    const REAL a = OSUB(e[0], e[1]);
    const REAL b = OMUL(OSUB(e[2], e[3]), (REAL)0.5);
    REAL t = OADD(OMUL(OADD(e[0], e[1]), (REAL)0.5), OMUL(OADD(e[2], e[3]), (REAL)0.25));
    /* the doubled-angle vector rotated by 22.5 degrees, then its octant */
    const REAL ar = OSUB(OMUL(C, a), OMUL(S, b));
    const REAL br = OADD(OMUL(S, a), OMUL(C, b));
    const int neg = OCMP(br < 0);
    const REAL ar1 = neg ? -ar : ar, br1 = neg ? -br : br;
    const int left = OCMP(ar1 < 0);
    const REAL ar2 = left ? br1 : ar1, br2 = left ? -ar1 : br1;
    int bucket = (4 * neg + 2 * left + OCMP(br2 > ar2)) * (ns * nc * nk);
    for (int i = 0; i < ns - 1; i++) bucket += OCMP(t > (REAL)st[i]) ? nc * nk : 0;
    if (nc > 1) {
        const REAL m2 = OADD(OMUL(a, a), OMUL(b, b));
        t = OMUL(t, t);
        for (int i = 0; i < nc - 1; i++) bucket += OCMP(m2 > OMUL((REAL)ct[i], t)) ? nk : 0;
    }
    if (nk > 1) {
        /* the largest and the smallest colour energy */
        const REAL r = OMUL(ec[0], (REAL)h->inv_col[k * 3]);
        const REAL g = OMUL(ec[1], (REAL)h->inv_col[k * 3 + 1]);
        const REAL bl = OMUL(ec[2], (REAL)h->inv_col[k * 3 + 2]);
        const REAL hi1 = OCMP(g > r) ? g : r, lo1 = OCMP(g > r) ? r : g;
        const REAL hi = OCMP(bl > hi1) ? bl : hi1, lo = OCMP(bl < lo1) ? bl : lo1;
        for (int i = 0; i < nk - 1; i++) bucket += OCMP(hi > OMUL((REAL)kt[i], lo));
    }
    return bucket;
}

/* the value of one site from its taps v, its phase k and its cell (iy, ix) */
static REAL ZG_CAT(zg_site, IS, RS)(const REAL *v, const rgbz_zguided_filters *f, int k,
                                    ptrdiff_t iy, ptrdiff_t ix)
{
    const rgbz_learned_filters *h = f->hash;
    const int nt = h->n_taps[k];
    const ptrdiff_t nb = (ptrdiff_t)f->n_levels * h->n_buckets;
    const ptrdiff_t b = (ptrdiff_t)f->level[iy * f->gx + ix] * h->n_buckets +
                        ZG_CAT(zg_hash, IS, RS)(v, h, k);
    const REAL *w = f->RW + (ptrdiff_t)k * h->n_taps_max * nb + b;
    REAL res = OMUL(w[0], v[0]);
    for (int t = 1; t < nt; t++) res = OADD(res, OMUL(w[t * nb], v[t]));
    const int32_t *bi = f->base_idx + (ptrdiff_t)k * f->n_base_max;
    const int n_base = f->n_base[k];
    REAL base = v[bi[0]];
    for (int i = 1; i < n_base; i++) base = OADD(base, v[bi[i]]);
    base = OMUL(base, (REAL)1 / (REAL)n_base);
    const REAL *g = f->RG + ((ptrdiff_t)k * nb + b) * RGBZ_ZG_FEATURES;
    const double *c = f->cell + (((ptrdiff_t)k * f->gy + iy) * f->gx + ix) * RGBZ_ZG_FEATURES;
    REAL s = OMUL(g[0], (REAL)c[0]);
    for (int m = 1; m < 9; m++) s = OADD(s, OMUL(g[m], (REAL)c[m]));
    res = OADD(res, OMUL(base, OSUB(s, g[9])));
    res = OADD(res, OMUL(g[9], (REAL)c[9]));
    return OADD(res, OMUL(g[10], (REAL)c[10]));
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
    (void)opcounts;
#ifdef _OPENMP
    const int nth = workers > 0 ? workers : omp_get_max_threads();
#pragma omp parallel for schedule(static) num_threads(nth)
#else
    (void)workers;
#endif
    for (ptrdiff_t y = 0; y < rows; y++) {
        const IN_T *rowp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
        for (int dy = -R; dy <= R; dy++) rowp[dy + R] = src + zg_extend(y + dy, rows, py) * cols;
        const int32_t *pm = phase_map + (y % py) * px;
        IN_T *restrict drow = dst + y * cols;
        memcpy(drow, src + y * cols, (size_t)cols * sizeof(IN_T));
        const ptrdiff_t iy = y / py < f->gy ? y / py : f->gy - 1;
        REAL v[RGBZ_LEARNED_MAX_TAPS];
        for (int c0 = 0; c0 < px && c0 < cols; c0++) {
            const int k = pm[c0];
            if (k < 0) continue;
#ifdef RGBZ_COUNT_OPS
            rgbz_opc_cur = opcounts + (size_t)k * RGBZ_NOPS;
#endif
            const int nt = h->n_taps[k];
            const int32_t *tdy = h->tap_dy + (ptrdiff_t)k * h->n_taps_max;
            const int32_t *tdx = h->tap_dx + (ptrdiff_t)k * h->n_taps_max;
            for (ptrdiff_t x = c0; x < cols; x += px) {
                for (int t = 0; t < nt; t++) v[t] = (REAL)rowp[tdy[t] + R][colmap[x + R + tdx[t]]];
                const ptrdiff_t ix = x / px < f->gx ? x / px : f->gx - 1;
                drow[x] = (IN_T)RGBZ_CAT(rgbz_out, RS)(ZG_CAT(zg_site, IS, RS)(v, f, k, iy, ix),
                                                       maxval, IN_IS_INT);
            }
        }
    }
    return RGBZ_OK;
}

#undef ZG_CAT
#undef ZG_CAT3
