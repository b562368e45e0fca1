/*
 * recon_core.template.h -- the per-site arithmetic of the missing-colour
 * reconstruction, written once: every method, every pattern, the
 * colour-difference domain, the clipped-pixel rule, for a block of sites that
 * share one plan.
 *
 * Paper: V. Rebiere et al., "Color pixel reconstruction for a monolithic RGB-Z
 * CMOS imager", section 4; the choices made where it is vague are in
 * docs/guide/interpretation.md, the rule near clipping in docs/guide/raw.md:
 *   bilinear                 mean of the candidates
 *   bi (eqs. 2-5)            w = alpha * beta
 *   edi_central (eqs. 6-7)   w = alpha * beta * gamma(ori), central pairs (Fig. 7)
 *   edi_line (eqs. 8-13)     w = alpha * beta * gamma(ori), axis mirror pairs (Fig. 9)
 *   sg (eqs. 14-19)          w = sum of the gammas of the covering semi-gradients
 *                            (Mask1); times alpha*beta*gamma of the axis gradients
 *                            otherwise (Mask2; sg_mode "combined")
 *   edi_rows (eqs. 1a-1e)    Shi et al.: median along the dominant edge
 * and the weighted mean of eqs. 12-13, in the intensity domain (eq. 13) or the
 * colour-difference domain (eq. 5).
 *
 * Memory layout: a block is tap-major, v[t][j] = tap t (kernel pixel
 * (tap_dy[t], tap_dx[t]) of the plan) of site j, j < n <= RGBZ_BLK, so that
 * every step below is a loop over the sites of the block, which the compiler
 * vectorises, and the plan's control flow runs once per block. The frame loop
 * (recon_loop.template.h) gathers the block and converts the results.
 *
 * One core, three uses (rgbz_core's instances below):
 *   - a plan built in Python, no clipped pixel (the plan is run-time data);
 *   - the same with clipped pixels (clipped != NULL: bit t of clipped[j] says that
 *     tap t of site j is clipped);
 *   - a Mask1 plan of recon_mask1.h, a compile-time constant: rgbz_core is
 *     inlined into a function that passes its address, and GCC folds the plan's
 *     fields through the inlined code (the old hand-written Mask1 kernels).
 * Every operation goes through the counting macros of rgbz_ops.h; the counting
 * build runs blocks of one site (RGBZ_BLK = 1), so a branch taken per block is
 * counted per site.
 *
 * After the core: the frame loop (recon_loop.template.h) per element type, and the
 * entry points of this precision, rgbz_reconstruct_<RS> and rgbz_fast_exp_<RS> (rgbz.h).
 *
 * Template parameters (rgbz_templating.h), #defined by the includer (recon_f32.c,
 * recon_f64.c) and #undefined after:
 *   REAL       float or double: the precision of the arithmetic
 *   RS         its suffix, f32 or f64 (names: rgbz_core_f32, ...); the helpers of the
 *              precision are rgbz_ops.h's of that suffix
 */
#ifndef REAL
#error "recon_core.template.h: #define REAL (float or double) before including it"
#endif
#ifndef RS
#error "recon_core.template.h: #define RS (the suffix of REAL: f32 or f64)"
#endif
#ifndef RGBZ_BLK
#error "recon_core.template.h: include recon.h (RGBZ_BLK, the sites per block) first"
#endif

/* the helpers of this precision (rgbz_ops.h) */
#define RABSDIFF RGBZ_CAT(OABSDIFF, RS)
#define REXP_LIBM RGBZ_CAT(rgbz_exp_libm, RS)
#define REXP_FAST RGBZ_CAT(rgbz_exp_poly, RS)
#define RFN(name) RGBZ_CAT(name, RS)
#define BLOOP for (int j = 0; j < n; j++)
#define RCLIPPED(mask, t) ((int)(((mask) >> (t)) & 1u))
/* the most pairs of one gradient group summed in one pass over the block: its
   2 * RGBZ_PAIRS_PASS tap pointers, G and the index fit the general registers (more are
   parked in vector registers, one vector-port move per difference and vector of sites) */
#define RGBZ_PAIRS_PASS 5      /* rgbz_groups_block's switch has the cases 1..5 */

/* the run-time tuning of eq. 7 and of edi_rows, in the precision of the arithmetic */
typedef struct {
    REAL floor_, rel, edge_ratio;
    int exp_mode;
} RFN(rgbz_knobs);

/* mean of nc values per site as c0 + sum(c_k - c0) / nc: exactly c0 when all are equal */
RGBZ_INLINE void RFN(rgbz_mean_block)(const REAL *const *c, int nc, int n, REAL *restrict out)
{
    if (nc == 1) {
        BLOOP out[j] = c[0][j];
        return;
    }
    REAL s[RGBZ_BLK];
    BLOOP s[j] = OSUB(c[1][j], c[0][j]);
    for (int k = 2; k < nc; k++) BLOOP s[j] = OADD(s[j], OSUB(c[k][j], c[0][j]));
    BLOOP out[j] = OADD(c[0][j], ODIV(s[j], (REAL)nc));
}

static inline REAL RFN(rgbz_median3)(REAL a, REAL b, REAL c)
{
    /* median of three with three comparisons */
    if (OCMP(a > b)) {
        REAL t = a;
        a = b;
        b = t;
    }
    if (OCMP(b > c)) b = c;
    return OCMP(a > b) ? a : b;
}

/*
 * edi_rows (eqs. 1a-1e), per site: the taps are the pairs (a1,a2),(b1,b2),(c1,c2),(d1,d2),
 * (e1,e2) of five directions through the missing pixel, c the vertical. The direction of the
 * smallest difference wins (ties in the order c, b, d, a, e); if it is not c and its
 * difference is below edge_ratio times c's, the value is the median of its two pixels and
 * the vertical mean, else the vertical mean. Near clipping, a direction whose two pixels
 * are clipped cannot be chosen, and if c is one there is no edge test.
 */
RGBZ_INLINE void RFN(rgbz_rows_block)(const REAL *const *v, int n, const uint64_t *clipped,
                                      REAL edge_ratio, REAL *restrict r)
{
    static const int order[5] = {2, 1, 3, 0, 4};
    BLOOP {
        const uint64_t cm = clipped ? clipped[j] : 0;
        REAL D[5];
        int known[5];
        for (int i = 0; i < 5; i++) {
            known[i] = !(RCLIPPED(cm, 2 * i) && RCLIPPED(cm, 2 * i + 1));
            D[i] = known[i] ? RABSDIFF(v[2 * i][j], v[2 * i + 1][j]) : (REAL)0;
        }
        const REAL vert = OMUL(OADD(v[4][j], v[5][j]), (REAL)0.5);
        r[j] = vert;
        if (!known[2]) continue;            /* the edge test is relative to c */
        int m = 2;
        for (int i = 1; i < 5; i++)
            if (known[order[i]] && OCMP(D[order[i]] < D[m])) m = order[i];
        if (m != 2 && OCMP(D[m] < OMUL(edge_ratio, D[2])))
            r[j] = RFN(rgbz_median3)(v[2 * m][j], v[2 * m + 1][j], vert);
    }
}

/*
 * `np` (a compile-time 1..RGBZ_PAIRS_PASS where it is called) consecutive pairs of one
 * group, added in their order to G, or starting it (started = 0: the first difference is
 * the sum), in one pass over the sites: the running sum stays in a register. Near
 * clipping a pair whose two pixels are clipped adds nothing and is not counted in cnt.
 */
RGBZ_INLINE void RFN(rgbz_pairs_into)(const rgbz_plan *p, int i0, int np, const REAL *const *v,
                                      int n, const uint64_t *clipped, int started,
                                      REAL *restrict G, uint8_t *restrict cnt)
{
    const REAL *a[RGBZ_PAIRS_PASS], *b[RGBZ_PAIRS_PASS];
    int ta[RGBZ_PAIRS_PASS], tb[RGBZ_PAIRS_PASS];
    for (int i = 0; i < np; i++) {
        ta[i] = p->pair_a[i0 + i];
        tb[i] = p->pair_b[i0 + i];
        a[i] = v[ta[i]];
        b[i] = v[tb[i]];
    }
    RGBZ_IVDEP
    BLOOP {
        REAL acc = started ? G[j] : (REAL)0;  /* never reads a G not yet written */
        int kept = 0;
        for (int i = 0; i < np; i++) {
            const int keep = !clipped || !(RCLIPPED(clipped[j], ta[i]) && RCLIPPED(clipped[j], tb[i]));
            const REAL d = keep ? RABSDIFF(a[i][j], b[i][j]) : (REAL)0;
            acc = (started || i) ? (keep ? OADD(acc, d) : acc) : d;
            kept += keep;
        }
        G[j] = acc;
        if (clipped) cnt[j] += (uint8_t)kept;
    }
}

/*
 * The difference of pair i added to each of its `ng` groups (a compile-time 2..4 where it
 * is called; started: which groups already have a term), in one pass over the sites.
 */
RGBZ_INLINE void RFN(rgbz_pair_into_groups)(const rgbz_plan *p, int i, int ng,
                                            const REAL *const *v, int n,
                                            const uint64_t *clipped, uint32_t started,
                                            REAL (*G)[RGBZ_BLK], uint8_t (*cnt)[RGBZ_BLK])
{
    const int ta = p->pair_a[i], tb = p->pair_b[i];
    const REAL *restrict a = v[ta], *restrict b = v[tb];
    REAL *Gq[4];
    uint8_t *cq[4];
    int st[4];
    uint32_t m = (uint32_t)p->pair_gmask[i];
    for (int q = 0; q < ng; q++, m &= m - 1) {
        const int g = rgbz_ctz(m);
        Gq[q] = G[g];
        cq[q] = cnt[g];
        st[q] = (int)((started >> g) & 1u);
    }
    RGBZ_IVDEP
    BLOOP {
        const int keep = !clipped || !(RCLIPPED(clipped[j], ta) && RCLIPPED(clipped[j], tb));
        const REAL d = keep ? RABSDIFF(a[j], b[j]) : (REAL)0;
        for (int q = 0; q < ng; q++) {
            const REAL acc = st[q] ? Gq[q][j] : (REAL)0;   /* never reads a G not yet written */
            Gq[q][j] = st[q] ? (keep ? OADD(acc, d) : acc) : d;
            if (clipped) cq[q][j] += (uint8_t)keep;
        }
    }
}

/*
 * The gradient groups (EDICentral's areas, section 4.2.1 and Fig. 7; eqs. 8-11 and
 * 14-18): each the mean absolute difference of its
 * pixel pairs. A pair belongs to the groups of its bit mask. The sums are taken in the
 * plan's pair order -- which is part of the result, float addition not being associative
 * (recon_mask1.h) --; a run of consecutive pairs of one group is summed in passes of up
 * to RGBZ_PAIRS_PASS pairs of nearly equal length, a pair of several groups (the
 * semi-gradients) has its difference computed once. Near clipping a pair whose two pixels
 * are clipped is skipped and cnt[g][j] counts the pairs group g has left at site j;
 * without clipping cnt is not written. The sums become means in rgbz_gammas_block, their
 * only reader.
 */
RGBZ_INLINE void RFN(rgbz_groups_block)(const rgbz_plan *p, const REAL *const *v, int n,
                                        const uint64_t *clipped, REAL (*G)[RGBZ_BLK],
                                        uint8_t (*cnt)[RGBZ_BLK])
{
    uint32_t started = 0;
    if (p->sum_from_zero) {
        /* 0 + d is d (d = |a - b| >= +0): a group's first difference is assigned rather
           than added to a 0; only the groups without a difference are zeroed. The counting
           build does the same, so that it counts what runs (it had added every difference
           to a 0: one addition a gradient group more than reconstruct() does, on every
           plan's row of docs/reports/opcount.md) */
        uint32_t touched = 0;
        for (int i = 0; i < p->n_pairs; i++) touched |= (uint32_t)p->pair_gmask[i];
        for (int g = 0; g < RGBZ_NGROUPS; g++)
            if (!((touched >> g) & 1u)) BLOOP G[g][j] = (REAL)0;
    }
    if (clipped)
        for (int g = 0; g < RGBZ_NGROUPS; g++) BLOOP cnt[g][j] = 0;
    for (int i = 0; i < p->n_pairs;) {
        const uint32_t m = (uint32_t)p->pair_gmask[i];
        if (m && !(m & (m - 1))) {
            /* one group: the run of its consecutive pairs (the gradients of Mask2 have 7 to
               9), in passes of at most RGBZ_PAIRS_PASS */
            const int g = rgbz_ctz(m);
            int run = 1;
            while (i + run < p->n_pairs && (uint32_t)p->pair_gmask[i + run] == m) run++;
            /* a run longer than RGBZ_PAIRS_PASS pairs in passes of nearly equal length */
            const int passes = (run + RGBZ_PAIRS_PASS - 1) / RGBZ_PAIRS_PASS;
            const int np = (run + passes - 1) / passes;
            const int st = (int)((started >> g) & 1u);
            switch (np) {
            case 1: RFN(rgbz_pairs_into)(p, i, 1, v, n, clipped, st, G[g], cnt[g]); break;
            case 2: RFN(rgbz_pairs_into)(p, i, 2, v, n, clipped, st, G[g], cnt[g]); break;
            case 3: RFN(rgbz_pairs_into)(p, i, 3, v, n, clipped, st, G[g], cnt[g]); break;
            case 4: RFN(rgbz_pairs_into)(p, i, 4, v, n, clipped, st, G[g], cnt[g]); break;
            default: RFN(rgbz_pairs_into)(p, i, 5, v, n, clipped, st, G[g], cnt[g]); break;
            }
            started |= m;
            i += np;
            continue;
        }
        /* a difference shared by several groups (at most 4, rgbz_check_plans): computed
           once, added to each in one pass */
        switch (rgbz_popcount(m)) {
        case 2: RFN(rgbz_pair_into_groups)(p, i, 2, v, n, clipped, started, G, cnt); break;
        case 3: RFN(rgbz_pair_into_groups)(p, i, 3, v, n, clipped, started, G, cnt); break;
        default: RFN(rgbz_pair_into_groups)(p, i, 4, v, n, clipped, started, G, cnt); break;
        }
        started |= m;
        i++;
    }
}

/* the argument of eq. 7's exponential, -G^2 / (2 sigma^2) with inv = 1 / (2 sigma^2), of
   a known group (counted with its exponential); 0 for an unknown one */
static inline REAL RFN(rgbz_exp_arg)(REAL G, REAL inv, int known)
{
    return known ? (OPC_(RGBZ_OP_EXP), -OMUL(OMUL(G, G), inv)) : (REAL)0;
}

/* the same from ninv = -inv, the negation taken once per site rather than once per group:
   G^2 * (-inv) and -(G^2 * inv) are the same number (rounding is symmetric in the sign) */
static inline REAL RFN(rgbz_exp_narg)(REAL G, REAL ninv)
{
    return (OPC_(RGBZ_OP_EXP), OMUL(OMUL(G, G), ninv));
}

/*
 * row[j] = exp(row[j]), j < n, with exp()'s (expf()'s) bits (exp_mode RGBZ_EXP_LIBM_VEC):
 * rgbz_exp.h's vector port of glibc's function when it covers every argument of the row,
 * else the function one value at a time.
 */
RGBZ_INLINE void RFN(rgbz_exp_libm_row)(REAL *restrict row, int n)
{
#ifdef RGBZ_HAVE_EXP_VEC
    int covered = 1;
    if (sizeof(REAL) == sizeof(double)) {
        BLOOP covered &= rgbz_exp_glibc_covers((double)row[j]);
        if (covered) {
            rgbz_exp_glibc_row((double *)(void *)row, n);
            return;
        }
    } else {
        BLOOP covered &= rgbz_expf_glibc_covers((float)row[j]);
        if (covered) {
            rgbz_expf_glibc_row((float *)(void *)row, n);
            return;
        }
    }
#endif
    BLOOP row[j] = REXP_LIBM(row[j]);
}

/*
 * rgbz_gammas_block without clipped pixels, for a family of NG groups from g0 (compile-time
 * NG, REL = rel > 0, FAST = the exponential where it is called: 1 the fast one, 2 exp()'s
 * bits from its vector port (rgbz_exp_libm_row), 0 exp()) whose groups all have
 * differences and all get a gamma: the same operations in the same order per site, with
 * the family's means, minimum and sum in registers rather than one pass over the block
 * per group and quantity.
 */
RGBZ_INLINE void RFN(rgbz_gammas_full)(const rgbz_plan *p, REAL (*G)[RGBZ_BLK], int g0, int NG,
                                       int REL, int FAST, const RFN(rgbz_knobs) *kn, int n,
                                       REAL (*gamma)[RGBZ_BLK])
{
    const REAL floor_ = kn->floor_, rel = kn->rel;
    REAL sc[RGBZ_NGROUPS];
    RGBZ_UNROLL
    for (int q = 0; q < NG; q++) sc[q] = (REAL)p->group_scale[g0 + q];
    RGBZ_IVDEP
    BLOOP {
        REAL gm[RGBZ_NGROUPS], gmin = (REAL)0, gsum = (REAL)0;
        RGBZ_UNROLL
        for (int q = 0; q < NG; q++) {
            gm[q] = OMUL(G[g0 + q][j], sc[q]);
            gmin = (!q || OCMP(gm[q] < gmin)) ? gm[q] : gmin;
            if (REL) gsum = !q ? gm[q] : OADD(gsum, gm[q]);
        }
        REAL sg = OCMP(gmin > floor_) ? gmin : floor_;
        if (REL) {
            const REAL rf = ODIV(OMUL(rel, gsum), (REAL)NG);
            sg = OCMP(rf > sg) ? rf : sg;
        }
        const REAL ninv = -ODIV((REAL)1, OMUL((REAL)2, OMUL(sg, sg)));
        RGBZ_UNROLL
        for (int q = 0; q < NG; q++)
            gamma[g0 + q][j] = FAST == 1 ? REXP_FAST(RFN(rgbz_exp_narg)(gm[q], ninv))
                             : FAST == 2 ? RFN(rgbz_exp_narg)(gm[q], ninv)
                                         : REXP_LIBM(RFN(rgbz_exp_narg)(gm[q], ninv));
    }
    if (FAST == 2)
        for (int q = 0; q < NG; q++) RFN(rgbz_exp_libm_row)(gamma[g0 + q], n);
}

/*
 * The gamma factors (eq. 7) of the family of groups [g0, g1) (the semi-gradients 0..7
 * or the gradients 8..11), from the group sums G of rgbz_groups_block: each group's mean
 * G * group_scale (near clipping G / cnt), then sigma = max(min G, floor, rel * mean G)
 * over the known groups of the site, gamma = exp(-G^2 / (2 sigma^2)) for the groups of
 * gamma_mask (the others are never read); an unknown group gets 0; if no group of the
 * family is known, every gamma is 1. A group is known when the plan gives it differences
 * (group_scale > 0) and, near clipping, when it has one left at the site (cnt > 0).
 */
RGBZ_INLINE void RFN(rgbz_gammas_block)(const rgbz_plan *p, REAL (*G)[RGBZ_BLK],
                                        const uint8_t (*cnt)[RGBZ_BLK], int clip, int g0,
                                        int g1, const RFN(rgbz_knobs) *kn, int n,
                                        REAL (*gamma)[RGBZ_BLK])
{
    const REAL floor_ = kn->floor_, rel = kn->rel;
    int n_known = 0, n_gamma = 0;
    for (int g = g0; g < g1; g++) {
        n_known += p->group_scale[g] > 0.0;
        n_gamma += (p->gamma_mask >> g) & 1;
    }
    if (!clip && n_known == g1 - g0 && n_gamma == g1 - g0 && (g1 - g0 == 8 || g1 - g0 == 4)) {
        /* every group known and evaluated (the semi-gradients and gradients of the SG
           plans): the family in registers */
        const int e = kn->exp_mode == RGBZ_EXP_FAST ? 1
                    : kn->exp_mode == RGBZ_EXP_LIBM_VEC ? 2 : 0;
        const int r = rel > (REAL)0;
#define RGBZ_GAMMAS_FULL_(NG)                                                             \
        do {                                                                              \
            if (r) {                                                                      \
                if (e == 1) RFN(rgbz_gammas_full)(p, G, g0, NG, 1, 1, kn, n, gamma);      \
                else if (e == 2) RFN(rgbz_gammas_full)(p, G, g0, NG, 1, 2, kn, n, gamma); \
                else RFN(rgbz_gammas_full)(p, G, g0, NG, 1, 0, kn, n, gamma);             \
            } else {                                                                      \
                if (e == 1) RFN(rgbz_gammas_full)(p, G, g0, NG, 0, 1, kn, n, gamma);      \
                else if (e == 2) RFN(rgbz_gammas_full)(p, G, g0, NG, 0, 2, kn, n, gamma); \
                else RFN(rgbz_gammas_full)(p, G, g0, NG, 0, 0, kn, n, gamma);             \
            }                                                                             \
        } while (0)
        if (g1 - g0 == 8) RGBZ_GAMMAS_FULL_(8);
        else RGBZ_GAMMAS_FULL_(4);
#undef RGBZ_GAMMAS_FULL_
        return;
    }
    if (!n_known) {
        for (int g = g0; g < g1; g++) BLOOP gamma[g][j] = (REAL)1;
        return;
    }
    REAL gmin[RGBZ_BLK], gsum[RGBZ_BLK], inv[RGBZ_BLK];
    uint8_t nk[RGBZ_BLK];                  /* clip: known groups of the site so far */
    if (clip) BLOOP {
        gmin[j] = gsum[j] = (REAL)0;
        nk[j] = 0;
    }
    int first = 1;
    for (int g = g0; g < g1; g++) {
        if (!(p->group_scale[g] > 0.0)) continue;
        REAL *restrict Gg = G[g];
        const REAL sc = (REAL)p->group_scale[g];
        BLOOP {
            if (clip && !cnt[g][j]) continue;
            /* near clipping 1 / cnt as the plans store it (1.0 / count in double): the
               unclipped value when cnt is complete */
            Gg[j] = OMUL(Gg[j], clip ? (REAL)(1.0 / (double)cnt[g][j]) : sc);
            const int f = clip ? !nk[j] : first;
            gmin[j] = (f || OCMP(Gg[j] < gmin[j])) ? Gg[j] : gmin[j];
            if (rel > (REAL)0) gsum[j] = f ? Gg[j] : OADD(gsum[j], Gg[j]);
            if (clip) nk[j]++;
        }
        first = 0;
    }
    BLOOP {
        REAL sg = OCMP(gmin[j] > floor_) ? gmin[j] : floor_;
        if (rel > (REAL)0) {
            const REAL rf = ODIV(OMUL(rel, gsum[j]), (REAL)(clip ? nk[j] : n_known));
            sg = OCMP(rf > sg) ? rf : sg;
        }
        inv[j] = ODIV((REAL)1, OMUL((REAL)2, OMUL(sg, sg)));
    }
    for (int g = g0; g < g1; g++) {
        REAL *restrict out = gamma[g];
        if (!(p->group_scale[g] > 0.0)) {
            BLOOP out[j] = clip && !nk[j] ? (REAL)1 : (REAL)0;
            continue;
        }
        if (!((p->gamma_mask >> g) & 1)) continue;
        const REAL *restrict Gg = G[g];
        if (kn->exp_mode == RGBZ_EXP_FAST)
            BLOOP out[j] = REXP_FAST(RFN(rgbz_exp_arg)(Gg[j], inv[j], !clip || cnt[g][j]));
        else if (kn->exp_mode == RGBZ_EXP_LIBM_VEC) {
            BLOOP out[j] = RFN(rgbz_exp_arg)(Gg[j], inv[j], !clip || cnt[g][j]);
            RFN(rgbz_exp_libm_row)(out, n);
        } else
            BLOOP out[j] = REXP_LIBM(RFN(rgbz_exp_arg)(Gg[j], inv[j], !clip || cnt[g][j]));
        /* near clipping: an unknown group 0, every gamma 1 where no group is known */
        if (clip) BLOOP out[j] = !nk[j] ? (REAL)1 : cnt[g][j] ? out[j] : (REAL)0;
    }
}

/* out = the sum of nr (a compile-time 1..4 where it is called) rows, in their order */
RGBZ_INLINE void RFN(rgbz_rows_sum)(const REAL *const *rows, int nr, int n, REAL *restrict out)
{
    BLOOP {
        REAL s = rows[0][j];
        for (int i = 1; i < nr; i++) s = OADD(s, rows[i][j]);
        out[j] = s;
    }
}

/*
 * beta's sums without clipped pixels, S[k][j] = 1 + sum_{m != k} |c_k - c_m| with the
 * differences added in the order of the pair loop of rgbz_core (pairs (k, m), k < m, k
 * outer), for `nc` candidates, a compile-time constant where it is called: the loops over
 * the pairs unroll, the loop over the sites vectorises, and the nc running sums stay in
 * registers rather than being loaded and stored once per pair.
 */
RGBZ_INLINE void RFN(rgbz_beta_sums)(const REAL *const *c, int nc, int n, REAL (*S)[RGBZ_BLK])
{
    RGBZ_IVDEP
    BLOOP {
        REAL cc[RGBZ_MAX_CAND], s[RGBZ_MAX_CAND];
        RGBZ_UNROLL
        for (int k = 0; k < nc; k++) {
            cc[k] = c[k][j];
            s[k] = (REAL)1;
        }
        RGBZ_UNROLL
        for (int k = 0; k < nc; k++) {
            RGBZ_UNROLL
            for (int m = k + 1; m < nc; m++) {
                const REAL d = RABSDIFF(cc[k], cc[m]);
                s[k] = OADD(s[k], d);
                s[m] = OADD(s[m], d);
            }
        }
        RGBZ_UNROLL
        for (int k = 0; k < nc; k++) S[k][j] = s[k];
    }
}

/* the factors of the weight of one candidate (rgbz_weigh) */
typedef struct {
    const REAL *S, *gamma, *sv, *c, *c0;   /* beta's sums, gamma(ori), eq. 19's sum, c_k, c_0 */
    REAL alpha;
    int k, first;          /* first: k = 1 and the numerator starts with its first term */
} RFN(rgbz_weights);

/* the weight of candidate f->k at site j, from the factors the method uses (ab: alpha *
   beta, eq. 2; grad: gamma of its orientation, eq. 6; sg: eq. 19's sum), added to the
   sums of eqs. 12-13 */
RGBZ_INLINE void RFN(rgbz_weigh_sv)(const RFN(rgbz_weights) *f, int j, int ab, int grad,
                                    int sg, REAL sv, REAL *restrict den, REAL *restrict num)
{
    REAL w = ab ? ODIV(f->alpha, f->S[j]) : (REAL)1;
    if (grad) w = OMUL(w, f->gamma[j]);
    if (sg) w = (ab || grad) ? OMUL(w, sv) : sv;
    if (f->k == 0) {
        den[j] = w;
    } else {
        den[j] = OADD(den[j], w);
        const REAL t = OMUL(w, OSUB(f->c[j], f->c0[j]));
        num[j] = f->first ? t : OADD(num[j], t);
    }
}

/* the same with eq. 19's sum read from f->sv */
RGBZ_INLINE void RFN(rgbz_weigh)(const RFN(rgbz_weights) *f, int j, int ab, int grad, int sg,
                                 REAL *restrict den, REAL *restrict num)
{
    RFN(rgbz_weigh_sv)(f, j, ab, grad, sg, sg ? f->sv[j] : (REAL)0, den, num);
}

/* eq. 19's sum scaled by sc where the plan scales it (scaled). x * 1 is x exactly, so the
   normal build multiplies every sum by sc (1 where it is not scaled: no per-site select);
   the counting build counts the multiplication only where the plan has it. */
#ifdef RGBZ_COUNT_OPS
#define RSGSCALE(x, scaled, sc) ((scaled) ? OMUL(x, sc) : (x))
#else
#define RSGSCALE(x, scaled, sc) ((void)(scaled), (x) * (sc))
#endif

/* SG's weight of candidate f->k (ab_grad: times alpha * beta * gamma(ori), the combined
   mode) with eq. 19's sum of the nr (a compile-time 1..4 where it is called) gamma rows
   taken in the same pass, in their order: the sum never goes through memory */
RGBZ_INLINE void RFN(rgbz_weigh_sg)(const RFN(rgbz_weights) *f, const REAL *const *rows, int nr,
                                    int scaled, REAL sc, int ab_grad, int n, REAL *restrict den,
                                    REAL *restrict num)
{
    RGBZ_IVDEP
    BLOOP {
        REAL sv = rows[0][j];
        for (int i = 1; i < nr; i++) sv = OADD(sv, rows[i][j]);
        sv = RSGSCALE(sv, scaled, sc);
        RFN(rgbz_weigh_sv)(f, j, ab_grad, ab_grad, 1, sv, den, num);
    }
}

/*
 * Reconstruct the n sites of a block: v tap-major (see the top), r[j] the value of site j
 * before the conversion to the output type. clipped: NULL, or the clipped taps of each
 * site (the rule of docs/guide/raw.md, "Near clipping": a difference between two clipped pixels
 * is unknown and skipped -- gradient and semi-gradient pairs, the terms of beta, the
 * directions of edi_rows --; one between a clipped and an unclipped pixel is kept; a
 * clipped pixel is still used as a value). A site with no clipped tap gives exactly what
 * it gives with clipped = NULL.
 */
RGBZ_INLINE void RFN(rgbz_core)(const rgbz_plan *p, const REAL *const *v, int n,
                                const uint64_t *clipped, const RFN(rgbz_knobs) *kn,
                                REAL *restrict r)
{
    if (n < 1) return;
    if (p->method == RGBZ_M_EDI_ROWS) {
        RFN(rgbz_rows_block)(v, n, clipped, kn->edge_ratio, r);
        return;
    }
    const int nc = p->n_cand, use_ab = p->use_ab, use_grad = p->use_grad, use_sg = p->use_sg;
    if (nc < 1) return;                     /* rejected by rgbz_check_plans */
    const REAL *c[RGBZ_MAX_CAND];
    for (int k = 0; k < nc; k++) c[k] = v[p->cand_tap[k]];
    if (p->method == RGBZ_M_BILINEAR) {
        RFN(rgbz_mean_block)(c, nc, n, r);
        return;
    }

    /* gradients and semi-gradients (Fig. 7, eqs. 8-11, 14-18) and their gammas (eq. 7) */
    REAL gamma[RGBZ_NGROUPS][RGBZ_BLK];
    if (use_sg || use_grad) {
        if (p->n_pairs == 0) {
            /* no difference at all: every gamma 1, as for a family without one */
            for (int g = 0; g < RGBZ_NGROUPS; g++) BLOOP gamma[g][j] = (REAL)1;
        } else {
            REAL G[RGBZ_NGROUPS][RGBZ_BLK];
            uint8_t cnt[RGBZ_NGROUPS][RGBZ_BLK];
            RFN(rgbz_groups_block)(p, v, n, clipped, G, cnt);
            if (use_sg)
                RFN(rgbz_gammas_block)(p, G, cnt, clipped != NULL, 0, 8, kn, n, gamma);
            if (use_grad)
                RFN(rgbz_gammas_block)(p, G, cnt, clipped != NULL, 8, 12, kn, n, gamma);
        }
    }

    /* the intensity factor beta (eq. 4): 1 / (1 + sum_m |c_k - c_m|), as S_k = the sum.
       Near clipping a term between two clipped candidates is skipped; a candidate that
       lost terms (u_k < nc - 1 left) has its sum rescaled to the nc - 1 terms of eq. 4,
       one with none left keeps S = 1. */
    REAL S[RGBZ_MAX_CAND][RGBZ_BLK];
    if (use_ab && !clipped && (nc == 8 || nc == 11)) {
        /* the candidate counts of Mask2: sums in registers (Mask1's 4 candidates, 6 pairs,
           gain nothing: measured 0.98x on BI) */
        if (nc == 8)
            RFN(rgbz_beta_sums)(c, 8, n, S);
        else
            RFN(rgbz_beta_sums)(c, 11, n, S);
    } else if (use_ab) {
        uint8_t u[RGBZ_MAX_CAND][RGBZ_BLK];
        for (int k = 0; k < nc; k++) BLOOP {
            S[k][j] = (REAL)1;
            u[k][j] = 0;
        }
        for (int k = 0; k < nc; k++)
            for (int m = k + 1; m < nc; m++) {
                const int tk = p->cand_tap[k], tm = p->cand_tap[m];
                const REAL *restrict ck = c[k], *restrict cm = c[m];
                REAL *restrict Sk = S[k], *restrict Sm = S[m];
                BLOOP {
                    if (clipped && RCLIPPED(clipped[j], tk) && RCLIPPED(clipped[j], tm)) continue;
                    const REAL d = RABSDIFF(ck[j], cm[j]);
                    Sk[j] = OADD(Sk[j], d);
                    Sm[j] = OADD(Sm[j], d);
                    if (clipped) {
                        u[k][j]++;
                        u[m][j]++;
                    }
                }
            }
        if (clipped)
            for (int k = 0; k < nc; k++) BLOOP {
                if (u[k][j] > 0 && u[k][j] < nc - 1)
                    S[k][j] = OADD((REAL)1, ODIV(OMUL(OSUB(S[k][j], (REAL)1), (REAL)(nc - 1)),
                                                 (REAL)u[k][j]));
            }
    }

    /* the colour-difference domain (eq. 5): interpolate c_k - X_k, add back X at the site */
    REAL cdv[RGBZ_MAX_CAND][RGBZ_BLK], baseb[RGBZ_BLK];
    const REAL *cv[RGBZ_MAX_CAND], *base = NULL;
    for (int k = 0; k < nc; k++) cv[k] = c[k];
    if (p->use_cd) {
        for (int k = 0; k <= nc; k++) {
            /* X_k = t0 + sum_m w_m (t_m - t0), the weights summing to 1: exactly t0 on a flat
               area, so that X_0 + (c - X_k) gives back c (sum_m w_m t_m rounds X_k and X_0
               differently and lands an ulp off) */
            REAL x[RGBZ_BLK];
            const REAL *restrict t0 = v[p->cd_tap[k][0]];
            BLOOP x[j] = t0[j];
            for (int m = 1; m < p->cd_n[k]; m++) {
                const REAL wm = (REAL)p->cd_w[k][m];
                const REAL *restrict tm = v[p->cd_tap[k][m]];
                BLOOP x[j] = OADD(x[j], OMUL(wm, OSUB(tm[j], t0[j])));
            }
            if (k < nc) {
                BLOOP cdv[k][j] = OSUB(c[k][j], x[j]);
                cv[k] = cdv[k];
            } else {
                BLOOP baseb[j] = x[j];
                base = baseb;
            }
        }
    }

    /* weights (eqs. 2, 6, 19) and the weighted mean (eqs. 12-13) as c0 + sum_k w_k (c_k - c0)
       / sum_k w_k, exactly c0 on flat input: one pass per candidate */
    REAL num[RGBZ_BLK], den[RGBZ_BLK];
    BLOOP num[j] = den[j] = (REAL)0;
    const int combo = use_ab | use_grad << 1 | use_sg << 2;
    for (int k = 0; k < nc; k++) {
        RFN(rgbz_weights) f;
        REAL svb[RGBZ_BLK];
        f.S = S[k];
        f.gamma = gamma[8 + p->cand_ori[k]];
        f.sv = NULL;                        /* set below when the method has it */
        f.c = cv[k];
        f.c0 = cv[0];
        f.alpha = (REAL)p->cand_alpha[k];
        f.k = k;
        f.first = k == 1 && !p->sum_from_zero;
        if (use_sg) {
            /* eq. 19: the sum of the gammas of the semi-gradients covering the candidate
               (an unknown one adds its gamma of 0), in mask order; scaled when the
               candidates have different numbers of them */
            const REAL *rows[8];
            int nr = 0;
            for (uint32_t m = (uint32_t)p->cand_sgmask[k]; m; m &= m - 1) rows[nr++] = gamma[rgbz_ctz(m)];
            if ((combo == 4 || combo == 7) && nr >= 1 && nr <= 4) {
                /* SG and SG combined: the sum in the pass of the weight */
                const int sc_on = p->sg_scaled;
                const REAL sc = sc_on ? (REAL)p->cand_sgscale[k] : (REAL)1;
#define RGBZ_WSG_(NR, AB) RFN(rgbz_weigh_sg)(&f, rows, NR, sc_on, sc, AB, n, den, num)
                if (combo == 7) {
                    switch (nr) {
                    case 1: RGBZ_WSG_(1, 1); break;
                    case 2: RGBZ_WSG_(2, 1); break;
                    case 3: RGBZ_WSG_(3, 1); break;
                    default: RGBZ_WSG_(4, 1); break;
                    }
                } else {
                    switch (nr) {
                    case 1: RGBZ_WSG_(1, 0); break;
                    case 2: RGBZ_WSG_(2, 0); break;
                    case 3: RGBZ_WSG_(3, 0); break;
                    default: RGBZ_WSG_(4, 0); break;
                    }
                }
#undef RGBZ_WSG_
                continue;
            }
            switch (nr) {
            case 0: BLOOP svb[j] = (REAL)0; break;
            case 1: RFN(rgbz_rows_sum)(rows, 1, n, svb); break;
            case 2: RFN(rgbz_rows_sum)(rows, 2, n, svb); break;
            case 3: RFN(rgbz_rows_sum)(rows, 3, n, svb); break;
            default: RFN(rgbz_rows_sum)(rows, 4, n, svb); break;
            }
            for (int i = 4; i < nr; i++) BLOOP svb[j] = OADD(svb[j], rows[i][j]);
            if (p->sg_scaled) {
                const REAL sc = (REAL)p->cand_sgscale[k];
                BLOOP svb[j] = OMUL(svb[j], sc);
            }
            f.sv = svb;
        }
        /* the factors as compile-time flags for the methods' combinations, so that each
           loop has no branch (GCC does not unswitch a loop this long by itself) */
        switch (combo) {
        case 1: BLOOP RFN(rgbz_weigh)(&f, j, 1, 0, 0, den, num); break;          /* BI */
        case 3: BLOOP RFN(rgbz_weigh)(&f, j, 1, 1, 0, den, num); break;          /* EDI */
        case 4: BLOOP RFN(rgbz_weigh)(&f, j, 0, 0, 1, den, num); break;          /* SG */
        case 7: BLOOP RFN(rgbz_weigh)(&f, j, 1, 1, 1, den, num); break;          /* SG combined */
        default:
            BLOOP RFN(rgbz_weigh)(&f, j, use_ab, use_grad, use_sg, den, num);
            break;
        }
    }
    /* every weight underflowed (or a non-finite input): the plain mean of the candidates */
    int fallback = 0;
    BLOOP fallback |= !(den[j] > (REAL)0);
    {
        const REAL *restrict c0 = cv[0];
        BLOOP {
            const REAL q = den[j] > (REAL)0 ? den[j] : (REAL)1;
            r[j] = den[j] > (REAL)0 ? OADD(c0[j], ODIV(num[j], q)) : c0[j];
        }
    }
    if (fallback) {
        REAL mean[RGBZ_BLK];
        RFN(rgbz_mean_block)(cv, nc, n, mean);
        BLOOP r[j] = den[j] > (REAL)0 ? r[j] : mean[j];
    }
    if (base) BLOOP r[j] = OADD(base[j], r[j]);
}

/* ---- the instances: a plan built in Python, with and without clipped pixels, and the
   Mask1 plans of recon_mask1.h as compile-time constants (one function each, so that
   GCC folds the plan into the inlined core) ---- */
RGBZ_CLONES_512 static void RFN(rgbz_core_plan)(const rgbz_plan *p, const REAL *const *v, int n,
                                            const RFN(rgbz_knobs) *kn, REAL *restrict r)
{
    RFN(rgbz_core)(p, v, n, NULL, kn, r);
}

/* one build, for the baseline instruction set: only the sites with a clipped tap run it,
   gathered into blocks of their own (recon_loop.template.h); its clones were measured: 35 s
   more compile time per precision for 1.03-1.13x on SG with 0.1-6 % of the pixels clipped */
static void RFN(rgbz_core_clip)(const rgbz_plan *p, const REAL *const *v, int n,
                                const uint64_t *clipped, const RFN(rgbz_knobs) *kn,
                                REAL *restrict r)
{
    RFN(rgbz_core)(p, v, n, clipped, kn, r);
}

/* clones: bilinear and BI on Mask1 run slower on 1 thread with the AVX-512F clone (BI
   float32: 800 against 1030 Mpix/s; docs/reports/benchmarks.md), the others faster */
#define RGBZ_M1_CORE(name, clones)                                                       \
    clones static void RFN(rgbz_core_m1_##name)(const REAL *const *v, int n,              \
                                                const RFN(rgbz_knobs) *kn, REAL *r)      \
    {                                                                                    \
        RFN(rgbz_core)(&rgbz_mask1_##name, v, n, NULL, kn, r);                           \
    }
RGBZ_M1_CORE(bilinear, RGBZ_CLONES)
RGBZ_M1_CORE(bi, RGBZ_CLONES)
RGBZ_M1_CORE(edi_central, RGBZ_CLONES_512)
RGBZ_M1_CORE(edi_line, RGBZ_CLONES_512)
RGBZ_M1_CORE(sg, RGBZ_CLONES_512)
RGBZ_M1_CORE(sg_combined, RGBZ_CLONES_512)
#undef RGBZ_M1_CORE

/* indexed as rgbz_mask1_plans */
static void (*const RFN(rgbz_mask1_core)[RGBZ_M1_NPLANS])(const REAL *const *, int,
                                                           const RFN(rgbz_knobs) *, REAL *) = {
    RFN(rgbz_core_m1_bilinear), RFN(rgbz_core_m1_bi), RFN(rgbz_core_m1_edi_central),
    RFN(rgbz_core_m1_edi_line), RFN(rgbz_core_m1_sg), RFN(rgbz_core_m1_sg_combined),
};

/* ---- the frame loop (recon_loop.template.h) for each element type ---- */
#define RGBZ_TYPE_TEMPLATE "recon_loop.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

/* ---- the entry points of this precision (rgbz.h) ---- */
int RFN(rgbz_reconstruct)(int in_type, const void *src, void *dst, ptrdiff_t rows,
                          ptrdiff_t cols, int py, int px, const int32_t *phase_map,
                          const rgbz_plan *plans, int n_plans, const rgbz_params *prm,
                          uint64_t *opcounts)
{
    int ry, rx;
    ptrdiff_t *colmap;
    int st = rgbz_recon_setup(src, dst, rows, cols, py, px, phase_map, plans, n_plans, prm,
                              opcounts, &ry, &rx, &colmap);
    if (st != RGBZ_OK) return st;
#define RECON_LOOP_(s, T)                                                                    \
    st = RGBZ_CAT3(rgbz_recon_loop, s, RS)((const T *)src, (T *)dst, rows, cols, py, px,    \
                                           phase_map, plans, ry, rx, colmap, prm, opcounts)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, RECON_LOOP_, st = RGBZ_EINVAL)
#undef RECON_LOOP_
    free(colmap);
    return st;
}

/* exp() of n values as the frame loops compute it with exp_mode RGBZ_EXP_LIBM: blocks of
   RGBZ_BLK through rgbz_exp_libm_row where the port runs, else the function itself */
int RFN(rgbz_libm_exp)(const REAL *x, REAL *out, ptrdiff_t n)
{
    if (!x || !out || n < 0) return RGBZ_EINVAL;
    const int vec = rgbz_exp_libm_vectorised(sizeof(REAL) == sizeof(float));
    for (ptrdiff_t i0 = 0; i0 < n; i0 += RGBZ_BLK) {
        const int m = (int)(n - i0 < RGBZ_BLK ? n - i0 : RGBZ_BLK);
        REAL *restrict row = out + i0;
        for (int j = 0; j < m; j++) row[j] = x[i0 + j];
        if (vec) RFN(rgbz_exp_libm_row)(row, m);
        else for (int j = 0; j < m; j++) row[j] = REXP_LIBM(row[j]);
    }
    return RGBZ_OK;
}

int RFN(rgbz_fast_exp)(const REAL *x, REAL *out, ptrdiff_t n)
{
    if (!x || !out || n < 0) return RGBZ_EINVAL;
    for (ptrdiff_t i = 0; i < n; i++) out[i] = REXP_FAST(x[i]);
    return RGBZ_OK;
}

#undef RSGSCALE
#undef RCLIPPED
#undef BLOOP
#undef RFN
#undef RABSDIFF
#undef REXP_LIBM
#undef REXP_FAST
