/*
 * recon_site.h -- the per-pixel reconstruction of one missing colour value,
 * for every method, in precision REAL. Included by recon.c once per REAL with
 *   REAL (float|double), RS (suffix f32|f64), RABSDIFF, REXP_LIBM, REXP_FAST.
 *
 * v[] holds the taps of the plan (kernel pixels gathered by the loop). The
 * methods follow docs/guide/interpretation.md:
 *   bilinear                 mean of the candidates
 *   bi (eqs. 2-5)            w = alpha * beta
 *   edi_central (eqs. 6-7)   w = alpha * beta * gamma(ori), central pairs
 *   edi_line (eqs. 8-13)     w = alpha * beta * gamma(ori), axis mirror pairs
 *   sg (eqs. 14-19)          w = sum of the gammas of the covering
 *                            semi-gradients (Mask1); times alpha*beta*gamma
 *                            of the axis gradients otherwise (Mask2)
 *   edi_rows (eqs. 1a-1e)    Shi et al.: median along the dominant edge
 */
#define RCAT2(a, b) a##_##b
#define RCAT(a, b) RCAT2(a, b)
#define RFN(name) RCAT(name, RS)

/* gamma factors (eq. 7) of the groups [g0, g1) whose bit is set in `known`:
   sigma = max(min G, floor, rel * mean G) over the known groups; an unknown group
   gets 0; if no group of [g0, g1) is known, every gamma is 1 */
static inline void RFN(rgbz_gammas_known)(const REAL *G, uint32_t known, int g0, int g1,
                                          REAL floor_, REAL rel, int exp_mode, REAL *gamma)
{
    REAL gmin = (REAL)0, gsum = (REAL)0;
    int any = 0;
    for (int g = g0; g < g1; g++) {
        if (!((known >> g) & 1u)) continue;
        if (!any || OCMP(G[g] < gmin)) gmin = G[g];
        if (rel > (REAL)0) gsum = any ? OADD(gsum, G[g]) : G[g];
        any++;
    }
    if (!any) {
        for (int g = g0; g < g1; g++) gamma[g] = (REAL)1;
        return;
    }
    REAL sigma = OCMP(gmin > floor_) ? gmin : floor_;
    if (rel > (REAL)0) {
        REAL rfloor = ODIV(OMUL(rel, gsum), (REAL)any);
        if (OCMP(rfloor > sigma)) sigma = rfloor;
    }
    REAL two_s2 = OMUL((REAL)2, OMUL(sigma, sigma));
    REAL inv = ODIV((REAL)1, two_s2);
    for (int g = g0; g < g1; g++) {
        if (!((known >> g) & 1u)) { gamma[g] = (REAL)0; continue; }
        REAL arg = -OMUL(OMUL(G[g], G[g]), inv);
        OPC_(RGBZ_OP_EXP);
        gamma[g] = exp_mode == RGBZ_EXP_FAST ? REXP_FAST(arg) : REXP_LIBM(arg);
    }
}

/* gamma factors of the groups [g0, g1) of a plan: a group is known when the plan gives
   it differences (group_scale > 0) */
static inline void RFN(rgbz_gammas)(const REAL *G, const rgbz_plan *p, int g0, int g1,
                                    REAL floor_, REAL rel, int exp_mode, REAL *gamma)
{
    uint32_t known = 0;
    for (int g = g0; g < g1; g++)
        if (p->group_scale[g] > 0.0) known |= 1u << g;
    RFN(rgbz_gammas_known)(G, known, g0, g1, floor_, rel, exp_mode, gamma);
}

/* gamma factors of n groups that all hold differences (the Mask1 fast path):
   the same arithmetic as rgbz_gammas */
static inline void RFN(rgbz_gammas4)(const REAL *G, int n, REAL floor_, REAL rel, int exp_mode,
                                     REAL *gamma)
{
    REAL gmin = G[0], gsum = G[0];
    for (int g = 1; g < n; g++) {
        if (OCMP(G[g] < gmin)) gmin = G[g];
        if (rel > (REAL)0) gsum = OADD(gsum, G[g]);
    }
    REAL sigma = OCMP(gmin > floor_) ? gmin : floor_;
    if (rel > (REAL)0) {
        REAL rfloor = ODIV(OMUL(rel, gsum), (REAL)n);
        if (OCMP(rfloor > sigma)) sigma = rfloor;
    }
    REAL two_s2 = OMUL((REAL)2, OMUL(sigma, sigma));
    REAL inv = ODIV((REAL)1, two_s2);
    REAL arg[8];
    for (int g = 0; g < n; g++) arg[g] = -OMUL(OMUL(G[g], G[g]), inv);
    if (exp_mode == RGBZ_EXP_FAST) {
        for (int g = 0; g < n; g++) gamma[g] = REXP_FAST(arg[g]);     /* vectorises */
    } else {
        for (int g = 0; g < n; g++) gamma[g] = REXP_LIBM(arg[g]);
    }
    for (int g = 0; g < n; g++) OPC_(RGBZ_OP_EXP);
}

static inline REAL RFN(rgbz_median3)(REAL a, REAL b, REAL c)
{
    /* median of three with three comparisons */
    if (OCMP(a > b)) { REAL t = a; a = b; b = t; }
    if (OCMP(b > c)) b = c;
    return OCMP(a > b) ? a : b;
}

/* mean of n values as c0 + sum(c_k - c0) / n: exactly c0 when all are equal */
static inline REAL RFN(rgbz_mean)(const REAL *c, int n)
{
    if (n == 1) return c[0];
    REAL s = OSUB(c[1], c[0]);
    for (int k = 2; k < n; k++) s = OADD(s, OSUB(c[k], c[0]));
    return OADD(c[0], ODIV(s, (REAL)n));
}

/* The end of every weighted method, shared by rgbz_site and rgbz_site_clip: the values
   interpolated -- the candidates c (eq. 13), or in the colour-difference domain (eq. 5)
   their differences to the estimate X_k of the other channel(s), added back to the
   estimate X_0 at the missing pixel -- weighted by alpha * beta (S: beta's sums),
   gamma (eq. 6) and the semi-gradients (eq. 19), normalised (eqs. 12-13). */
static inline REAL RFN(rgbz_site_value)(const REAL *v, const rgbz_plan *p, REAL *c,
                                        const REAL *S, const REAL *gamma)
{
    const int nc = p->n_cand;
    REAL base = (REAL)0;
    if (p->use_cd) {
        for (int k = 0; k <= nc; k++) {
            /* X_k = t0 + sum_m w_m (t_m - t0), the weights summing to 1: exactly t0 on a
               flat area, so that X_0 + (c - X_k) gives back c (sum_m w_m t_m rounds X_k
               and X_0 differently and lands an ulp off) */
            const REAL t0 = v[p->cd_tap[k][0]];
            REAL x = t0;
            for (int m = 1; m < p->cd_n[k]; m++)
                x = OADD(x, OMUL((REAL)p->cd_w[k][m], OSUB(v[p->cd_tap[k][m]], t0)));
            if (k < nc) c[k] = OSUB(c[k], x);
            else base = x;
        }
    }

    /* weights (eqs. 2, 6, 19) and the weighted mean (eqs. 12-13) */
    REAL num = (REAL)0, den = (REAL)0;
    for (int k = 0; k < nc; k++) {
        REAL w;
        if (p->use_ab) w = ODIV((REAL)p->cand_alpha[k], S[k]);
        else w = (REAL)1;
        if (p->use_grad) w = OMUL(w, gamma[8 + p->cand_ori[k]]);
        if (p->use_sg) {
            int32_t m = p->cand_sgmask[k];
            REAL s = (REAL)0;
            int first = 1;
            while (m) {
                int g = __builtin_ctz((unsigned)m);
                s = first ? gamma[g] : OADD(s, gamma[g]);
                first = 0;
                m &= m - 1;
            }
            if (p->sg_scaled) s = OMUL(s, (REAL)p->cand_sgscale[k]);
            w = (p->use_ab || p->use_grad) ? OMUL(w, s) : s;
        }
        den = k ? OADD(den, w) : w;
        if (k) num = OADD(num, OMUL(w, OSUB(c[k], c[0])));
    }
    REAL r;
    if (!(den > (REAL)0)) {
        /* every weight underflowed: plain mean of the candidates */
        r = RFN(rgbz_mean)(c, nc);
    } else {
        r = OADD(c[0], ODIV(num, den));
    }
    return p->use_cd ? OADD(base, r) : r;
}

static inline REAL RFN(rgbz_site)(const REAL *v, const rgbz_plan *p, REAL floor_, REAL rel,
                                  REAL edge_ratio, int exp_mode)
{
    const int nc = p->n_cand;
    REAL c[RGBZ_MAX_CAND];

    if (p->method == RGBZ_M_EDI_ROWS) {
        /* taps: (a1,a2),(b1,b2),(c1,c2),(d1,d2),(e1,e2); c is the vertical */
        REAL D[5];
        for (int i = 0; i < 5; i++) D[i] = RABSDIFF(v[2 * i], v[2 * i + 1]);
        REAL vert = OMUL(OADD(v[4], v[5]), (REAL)0.5);
        static const int order[5] = {2, 1, 3, 0, 4};   /* tie order c, b, d, a, e */
        int m = 2;
        for (int i = 1; i < 5; i++)
            if (OCMP(D[order[i]] < D[m])) m = order[i];
        if (m != 2 && OCMP(D[m] < OMUL((REAL)edge_ratio, D[2])))
            return RFN(rgbz_median3)(v[2 * m], v[2 * m + 1], vert);
        return vert;
    }

    for (int k = 0; k < nc; k++) c[k] = v[p->cand_tap[k]];

    if (p->method == RGBZ_M_BILINEAR) return RFN(rgbz_mean)(c, nc);

    /* gradient groups: mean absolute difference of their pairs */
    REAL G[RGBZ_NGROUPS], gamma[RGBZ_NGROUPS];
    if (p->n_pairs == 0)
        /* no difference at all: every gamma 1, as rgbz_gammas gives a family without one */
        for (int g = 0; g < RGBZ_NGROUPS; g++) gamma[g] = (REAL)1;
    if (p->n_pairs > 0) {
        for (int g = 0; g < RGBZ_NGROUPS; g++) G[g] = (REAL)0;
        for (int i = 0; i < p->n_pairs; i++) {
            REAL d = RABSDIFF(v[p->pair_a[i]], v[p->pair_b[i]]);
            int32_t m = p->pair_gmask[i];
            while (m) {
                int g = __builtin_ctz((unsigned)m);
                G[g] = OADD(G[g], d);
                m &= m - 1;
            }
        }
        for (int g = 0; g < RGBZ_NGROUPS; g++)
            if (p->group_scale[g] > 0.0) G[g] = OMUL(G[g], (REAL)p->group_scale[g]);
        if (p->use_sg) RFN(rgbz_gammas)(G, p, 0, 8, floor_, rel, exp_mode, gamma);
        if (p->use_grad) RFN(rgbz_gammas)(G, p, 8, 12, floor_, rel, exp_mode, gamma);
    }

    /* intensity factor beta (eq. 4): 1 / (1 + sum_m |c_k - c_m|) */
    REAL S[RGBZ_MAX_CAND];
    if (p->use_ab) {
        for (int k = 0; k < nc; k++) S[k] = (REAL)1;
        for (int k = 0; k < nc; k++)
            for (int m = k + 1; m < nc; m++) {
                REAL d = RABSDIFF(c[k], c[m]);
                S[k] = OADD(S[k], d);
                S[m] = OADD(S[m], d);
            }
    }

    return RFN(rgbz_site_value)(v, p, c, S, gamma);
}



/*
 * The same arithmetic over a block of n <= RGBZ_BLK sites that share one plan,
 * stored tap-major (v[t][j]: tap t of site j), so that every step is a loop
 * over the sites the compiler vectorises; the plan's control flow runs once per
 * block instead of once per site. Operation for operation what rgbz_site does
 * (the counting build counts the same; results agree to the last bit up to
 * vector/scalar code generation, which contracts nothing in ISO C mode).
 * edi_rows is not handled here (the loop keeps it on rgbz_site).
 */
#ifndef RGBZ_BLK
#define RGBZ_BLK 32
#endif
#define BLOOP for (int j = 0; j < n; j++)

static inline void RFN(rgbz_mean_block)(const REAL *const *c, int nc, int n, REAL *restrict out)
{
    if (nc == 1) { BLOOP out[j] = c[0][j]; return; }
    REAL s[RGBZ_BLK];
    BLOOP s[j] = OSUB(c[1][j], c[0][j]);
    for (int k = 2; k < nc; k++) BLOOP s[j] = OADD(s[j], OSUB(c[k][j], c[0][j]));
    BLOOP out[j] = OADD(c[0][j], ODIV(s[j], (REAL)nc));
}

static inline void RFN(rgbz_gammas_block)(REAL (*G)[RGBZ_BLK], const rgbz_plan *p, int g0, int g1,
                                   REAL floor_, REAL rel, int exp_mode, int n,
                                   REAL (*gamma)[RGBZ_BLK])
{
    int any = 0;
    for (int g = g0; g < g1; g++) any += p->group_scale[g] > 0.0;
    if (!any) {
        for (int g = g0; g < g1; g++) BLOOP gamma[g][j] = (REAL)1;
        return;
    }
    REAL gmin[RGBZ_BLK], gsum[RGBZ_BLK], inv[RGBZ_BLK];
    int first = 1;
    for (int g = g0; g < g1; g++) {
        if (p->group_scale[g] <= 0.0) continue;
        const REAL *restrict Gg = G[g];
        if (first) {
            BLOOP gmin[j] = Gg[j];
            BLOOP gsum[j] = Gg[j];
            first = 0;
        } else {
            BLOOP gmin[j] = OCMP(Gg[j] < gmin[j]) ? Gg[j] : gmin[j];
            if (rel > (REAL)0) BLOOP gsum[j] = OADD(gsum[j], Gg[j]);
        }
    }
    if (rel > (REAL)0) {
        BLOOP {
            REAL sg = OCMP(gmin[j] > floor_) ? gmin[j] : floor_;
            const REAL rf = ODIV(OMUL(rel, gsum[j]), (REAL)any);
            sg = OCMP(rf > sg) ? rf : sg;
            inv[j] = ODIV((REAL)1, OMUL((REAL)2, OMUL(sg, sg)));
        }
    } else {
        BLOOP {
            const REAL sg = OCMP(gmin[j] > floor_) ? gmin[j] : floor_;
            inv[j] = ODIV((REAL)1, OMUL((REAL)2, OMUL(sg, sg)));
        }
    }
    for (int g = g0; g < g1; g++) {
        REAL *restrict out = gamma[g];
        if (p->group_scale[g] <= 0.0) { BLOOP out[j] = (REAL)0; continue; }
        const REAL *restrict Gg = G[g];
        BLOOP out[j] = -OMUL(OMUL(Gg[j], Gg[j]), inv[j]);
#ifdef RGBZ_COUNT_OPS
        BLOOP OPC_(RGBZ_OP_EXP);
#endif
        if (exp_mode == RGBZ_EXP_FAST) BLOOP out[j] = REXP_FAST(out[j]);
        else BLOOP out[j] = REXP_LIBM(out[j]);
    }
}

RGBZ_CLONES static void RFN(rgbz_site_block)(REAL (*v)[RGBZ_BLK], int n, const rgbz_plan *p,
                                             REAL floor_, REAL rel, int exp_mode,
                                             REAL *restrict r)
{
    const int nc = p->n_cand;
    const REAL *c[RGBZ_MAX_CAND];
    for (int k = 0; k < nc; k++) c[k] = v[p->cand_tap[k]];
    if (p->method == RGBZ_M_BILINEAR) {
        RFN(rgbz_mean_block)(c, nc, n, r);
        return;
    }

    REAL G[RGBZ_NGROUPS][RGBZ_BLK], gamma[RGBZ_NGROUPS][RGBZ_BLK];
    if (p->n_pairs == 0 && (p->use_sg || p->use_grad))
        /* no difference at all: every gamma 1, as rgbz_gammas gives a family without one */
        for (int g = 0; g < RGBZ_NGROUPS; g++) BLOOP gamma[g][j] = (REAL)1;
    if (p->n_pairs > 0) {
        for (int g = 0; g < RGBZ_NGROUPS; g++) BLOOP G[g][j] = (REAL)0;
        for (int i = 0; i < p->n_pairs; i++) {
            const REAL *restrict a = v[p->pair_a[i]], *restrict b = v[p->pair_b[i]];
            REAL d[RGBZ_BLK];
            BLOOP d[j] = RABSDIFF(a[j], b[j]);
            int32_t m = p->pair_gmask[i];
            while (m) {
                int g = __builtin_ctz((unsigned)m);
                REAL *restrict Gg = G[g];
                BLOOP Gg[j] = OADD(Gg[j], d[j]);
                m &= m - 1;
            }
        }
        for (int g = 0; g < RGBZ_NGROUPS; g++)
            if (p->group_scale[g] > 0.0) {
                const REAL sc = (REAL)p->group_scale[g];
                BLOOP G[g][j] = OMUL(G[g][j], sc);
            }
        if (p->use_sg) RFN(rgbz_gammas_block)(G, p, 0, 8, floor_, rel, exp_mode, n, gamma);
        if (p->use_grad) RFN(rgbz_gammas_block)(G, p, 8, 12, floor_, rel, exp_mode, n, gamma);
    }

    /* beta (eq. 4) */
    REAL S[RGBZ_MAX_CAND][RGBZ_BLK];
    if (p->use_ab) {
        for (int k = 0; k < nc; k++) BLOOP S[k][j] = (REAL)1;
        for (int k = 0; k < nc; k++)
            for (int m = k + 1; m < nc; m++) {
                const REAL *restrict ck = c[k], *restrict cm = c[m];
                REAL *restrict Sk = S[k], *restrict Sm = S[m];
                BLOOP {
                    const REAL d = RABSDIFF(ck[j], cm[j]);
                    Sk[j] = OADD(Sk[j], d);
                    Sm[j] = OADD(Sm[j], d);
                }
            }
    }

    /* the colour-difference domain (eq. 5) */
    REAL cdv[RGBZ_MAX_CAND][RGBZ_BLK], base[RGBZ_BLK];
    const REAL *cv[RGBZ_MAX_CAND];
    for (int k = 0; k < nc; k++) cv[k] = c[k];
    if (p->use_cd) {
        for (int k = 0; k <= nc; k++) {
            REAL x[RGBZ_BLK];        /* relative to the first tap, as in rgbz_site_value */
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
                BLOOP base[j] = x[j];
            }
        }
    }

    /* weights (eqs. 2, 6, 19) and the weighted mean (eqs. 12-13) */
    REAL num[RGBZ_BLK], den[RGBZ_BLK];
    BLOOP num[j] = (REAL)0;
    for (int k = 0; k < nc; k++) {
        REAL w[RGBZ_BLK];
        if (p->use_ab) {
            const REAL al = (REAL)p->cand_alpha[k];
            BLOOP w[j] = ODIV(al, S[k][j]);
        } else {
            BLOOP w[j] = (REAL)1;
        }
        if (p->use_grad) {
            const REAL *restrict gg = gamma[8 + p->cand_ori[k]];
            BLOOP w[j] = OMUL(w[j], gg[j]);
        }
        if (p->use_sg) {
            int32_t m = p->cand_sgmask[k];
            REAL sv[RGBZ_BLK];
            int first = 1;
            while (m) {
                int g = __builtin_ctz((unsigned)m);
                const REAL *restrict gg = gamma[g];
                if (first) BLOOP sv[j] = gg[j];
                else BLOOP sv[j] = OADD(sv[j], gg[j]);
                first = 0;
                m &= m - 1;
            }
            if (first) BLOOP sv[j] = (REAL)0;
            if (p->sg_scaled) {
                const REAL sc = (REAL)p->cand_sgscale[k];
                BLOOP sv[j] = OMUL(sv[j], sc);
            }
            if (p->use_ab || p->use_grad) BLOOP w[j] = OMUL(w[j], sv[j]);
            else BLOOP w[j] = sv[j];
        }
        if (k == 0) {
            BLOOP den[j] = w[j];
        } else {
            const REAL *restrict ck = cv[k], *restrict c0 = cv[0];
            BLOOP {
                den[j] = OADD(den[j], w[j]);
                num[j] = OADD(num[j], OMUL(w[j], OSUB(ck[j], c0[j])));
            }
        }
    }
#ifdef RGBZ_COUNT_OPS
    BLOOP {
        if (!(den[j] > (REAL)0)) {
            REAL cj[RGBZ_MAX_CAND];
            for (int k = 0; k < nc; k++) cj[k] = cv[k][j];
            r[j] = RFN(rgbz_mean)(cj, nc);
        } else {
            r[j] = OADD(cv[0][j], ODIV(num[j], den[j]));
        }
    }
#else
    {
        REAL mean[RGBZ_BLK];
        RFN(rgbz_mean_block)(cv, nc, n, mean);     /* every weight underflowed */
        const REAL *restrict c0 = cv[0];
        BLOOP {
            const REAL q = den[j] > (REAL)0 ? den[j] : (REAL)1;
            r[j] = den[j] > (REAL)0 ? c0[j] + num[j] / q : mean[j];
        }
    }
#endif
    if (p->use_cd) BLOOP r[j] = OADD(base[j], r[j]);
}
#undef BLOOP

/*
 * The same site near clipping (docs/guide/raw.md, "Near clipping"; docs/guide/interpretation.md).
 * `clipped` has bit t set when tap t holds a clipped (saturated) value: a lower bound of
 * the truth. It is used as a value; in a weight, what is unknown is only a difference
 * between two clipped pixels (both true values are somewhere >= the level, their clipped
 * difference 0 is fake flatness). A difference between a clipped pixel a and an unclipped
 * pixel b is a true lower bound of |a_true - b| ("at least this much edge") and is kept:
 *   - a difference (gradient pair, semi-gradient pair, edi_rows direction) whose two
 *     pixels are both clipped is skipped, like a difference touching a Z pixel, and a
 *     group is the mean of the differences it has left; a group with none left is
 *     unknown: left out of sigma and gamma = 0 (the rule for groups without valid
 *     differences), every gamma 1 if no group of the family is known; the factors
 *     built from the gammas (eq. 6 per orientation, eq. 19 per candidate) are unchanged,
 *     so a candidate covered only by unknown semi-gradients gets 0;
 *   - beta (eq. 4): a term between two clipped candidates is skipped; a clipped candidate
 *     sums its u terms to the unclipped candidates, rescaled to the n - 1 terms of eq. 4;
 *     an unclipped candidate keeps all its terms; if every candidate is clipped no term
 *     is left and every beta is 1;
 *   - edi_rows: a direction whose two pixels are clipped cannot be chosen; if the vertical
 *     one (c) is such a direction there is no edge test and the value is the vertical mean.
 * Where no tap is clipped the loop calls rgbz_site, so clip_on changes nothing there; where
 * no two clipped taps form a difference this function computes what rgbz_site does.
 * The loop keeps the output at or above the smallest candidate when every candidate is
 * clipped (saturation preserved).
 */
static inline REAL RFN(rgbz_site_clip)(const REAL *v, uint64_t clipped, const rgbz_plan *p,
                                       REAL floor_, REAL rel, REAL edge_ratio, int exp_mode)
{
#define RCLIPPED(t) ((clipped >> (t)) & 1u)
    const int nc = p->n_cand;
    REAL c[RGBZ_MAX_CAND];

    if (p->method == RGBZ_M_EDI_ROWS) {
        REAL D[5];
        int known[5];
        for (int i = 0; i < 5; i++) {
            known[i] = !(RCLIPPED(2 * i) && RCLIPPED(2 * i + 1));
            D[i] = known[i] ? RABSDIFF(v[2 * i], v[2 * i + 1]) : (REAL)0;
        }
        REAL vert = OMUL(OADD(v[4], v[5]), (REAL)0.5);
        if (!known[2]) return vert;            /* the edge test is relative to c */
        static const int order[5] = {2, 1, 3, 0, 4};
        int m = 2;
        for (int i = 1; i < 5; i++)
            if (known[order[i]] && OCMP(D[order[i]] < D[m])) m = order[i];
        if (m != 2 && OCMP(D[m] < OMUL((REAL)edge_ratio, D[2])))
            return RFN(rgbz_median3)(v[2 * m], v[2 * m + 1], vert);
        return vert;
    }

    for (int k = 0; k < nc; k++) c[k] = v[p->cand_tap[k]];

    if (p->method == RGBZ_M_BILINEAR) return RFN(rgbz_mean)(c, nc);

    /* gradient groups: mean absolute difference of their pairs, less the clipped-clipped ones */
    REAL G[RGBZ_NGROUPS], gamma[RGBZ_NGROUPS];
    uint32_t known = 0;
    if (p->n_pairs == 0)
        for (int g = 0; g < RGBZ_NGROUPS; g++) gamma[g] = (REAL)1;     /* as in rgbz_site */
    if (p->n_pairs > 0) {
        int cnt[RGBZ_NGROUPS];
        for (int g = 0; g < RGBZ_NGROUPS; g++) {
            G[g] = (REAL)0;
            cnt[g] = 0;
        }
        for (int i = 0; i < p->n_pairs; i++) {
            if (RCLIPPED(p->pair_a[i]) && RCLIPPED(p->pair_b[i])) continue;
            REAL d = RABSDIFF(v[p->pair_a[i]], v[p->pair_b[i]]);
            int32_t m = p->pair_gmask[i];
            while (m) {
                int g = __builtin_ctz((unsigned)m);
                G[g] = OADD(G[g], d);
                cnt[g]++;
                m &= m - 1;
            }
        }
        for (int g = 0; g < RGBZ_NGROUPS; g++)
            if (p->group_scale[g] > 0.0 && cnt[g] > 0) {
                known |= 1u << g;
                /* 1 / cnt as the plans store it: the unclipped value when cnt is complete */
                G[g] = OMUL(G[g], (REAL)(1.0 / (double)cnt[g]));
            }
        if (p->use_sg) RFN(rgbz_gammas_known)(G, known, 0, 8, floor_, rel, exp_mode, gamma);
        if (p->use_grad) RFN(rgbz_gammas_known)(G, known, 8, 12, floor_, rel, exp_mode, gamma);
    }

    /* intensity factor beta (eq. 4) without the terms between two clipped candidates */
    REAL S[RGBZ_MAX_CAND];
    if (p->use_ab) {
        int u[RGBZ_MAX_CAND], cl[RGBZ_MAX_CAND];
        for (int k = 0; k < nc; k++) {
            S[k] = (REAL)1;
            u[k] = 0;
            cl[k] = (int)RCLIPPED(p->cand_tap[k]);
        }
        for (int k = 0; k < nc; k++)
            for (int m = k + 1; m < nc; m++) {
                if (cl[k] && cl[m]) continue;
                REAL d = RABSDIFF(c[k], c[m]);
                S[k] = OADD(S[k], d);
                S[m] = OADD(S[m], d);
                u[k]++;
                u[m]++;
            }
        /* only a clipped candidate loses terms: rescaled to the n - 1 of eq. 4. One with none
           left (every candidate clipped) keeps S = 1, and so does every other candidate */
        for (int k = 0; k < nc; k++)
            if (u[k] > 0 && u[k] < nc - 1)
                S[k] = OADD((REAL)1, ODIV(OMUL(OSUB(S[k], (REAL)1), (REAL)(nc - 1)), (REAL)u[k]));
    }

    /* the weighted mean as rgbz_site (clipped values are used as values; an unknown
       semi-gradient enters eq. 19 with its gamma of 0) */
    return RFN(rgbz_site_value)(v, p, c, S, gamma);
#undef RCLIPPED
}

#undef RFN
#undef RCAT
#undef RCAT2
