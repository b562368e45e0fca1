/*
 * hw_recon.c -- the fixed-point streaming model of the missing-colour reconstruction
 * (hw_recon.h says what it models; docs/guide/hardware.md specifies the datapath).
 *
 * Per-pixel path: integers only (int64_t registers, each within the width the Python
 * layer declared and checked for the plan and bit depth), fixed-size arrays, loops whose
 * trip counts are bounded by the RGBZ_MAX_* constants of rgbz.h. Per site of one plan:
 *   1. the differences |a - b| of the plan's pairs, summed per group (eqs. 8-11, 14-18);
 *   2. per family of groups, each sum scaled to L times the group's mean (exact), n sigma =
 *      max(n min, n floor, rel * sum) (eq. 7 with the library's relative floor; n the
 *      family's groups, so that the mean needs no division), and per group
 *      y = (n G / n sigma)^2 log2(e) / 2 through the reciprocal table, saturated;
 *   3. gamma = 2^-y = exp(-G^2 / (2 sigma^2)) as a mantissa (the table of 2^-frac(y)) and an
 *      exponent (floor(y));
 *   4. per candidate the weight of eqs. 2, 6, 19 as a mantissa and an exponent: alpha (a
 *      constant), beta = 1 / (1 + sum |c_k - c_m|) (the reciprocal table), gamma of its
 *      orientation, the sum of its semi-gradients' gammas (aligned to the largest);
 *   5. the weights aligned to the largest, their sums, and the weighted mean of eqs. 12-13
 *      as c0 + round(sum w (c - c0) * 1/sum w) (the reciprocal table); every weight 0: the
 *      plain mean, as the float core falls back.
 * Right shifts of negative values are arithmetic (floor), as in every C compiler this
 * builds with and in NumPy's right_shift.
 */
#include <string.h>
#include "hw_recon.h"
#include "hw_stream.h"

/* the streaming front end holds the window rows of this radius */
typedef char hw_recon_radius_fits[RGBZ_HW_RADIUS <= RGBZ_HW_STREAM_MAX_RADIUS ? 1 : -1];

/* 1/x ~ m 2^-(p + recip_bits) for x >= 1: p = floor(log2 x); the recip_index_bits bits
   after the leading one index the table ("pwl": and the next recip_bits bits interpolate) */
static inline void hw_recip(int64_t x, const rgbz_hw_config *c, const int32_t *RT,
                            int64_t *m, int64_t *p)
{
    const int64_t pp = rgbz_hw_bitlen(x) - 1;
    const int64_t Fi = c->recip_pwl ? c->recip_bits : 0;
    const int64_t F = c->recip_index_bits + Fi;
    const int64_t sh = F - pp;
    const int64_t xf = (sh >= 0 ? x << sh : x >> -sh) - ((int64_t)1 << F);
    const int64_t i = xf >> Fi;
    if (c->recip_pwl) {
        const int64_t fr = xf & (((int64_t)1 << Fi) - 1);
        *m = (int64_t)RT[i] - ((((int64_t)RT[i] - RT[i + 1]) * fr) >> Fi);
    } else {
        *m = RT[i];
    }
    *p = pp;
}

/* 2^-y ~ m 2^-(exp_bits + e) for y >= 0 with ratio_bits fractional bits: e = floor(y); the
   top exp_index_bits bits of the fraction index the table ("pwl": the rest interpolate) */
static inline void hw_exp2neg(int64_t y, const rgbz_hw_config *c, const int32_t *ET,
                              int64_t *m, int64_t *e)
{
    const int64_t Ft = c->ratio_bits, Te = c->exp_index_bits;
    const int64_t yf = y & (((int64_t)1 << Ft) - 1);
    int64_t i, fr = 0, Fi = 0;
    if (Ft >= Te) {
        Fi = Ft - Te;
        i = yf >> Fi;
        fr = yf & (((int64_t)1 << Fi) - 1);
    } else {
        i = yf << (Te - Ft);
    }
    *m = c->exp_pwl ? (int64_t)ET[i] - ((((int64_t)ET[i] - ET[i + 1]) * fr) >> Fi)
                    : (int64_t)ET[i];
    *e = y >> Ft;
}

/* eq. 7 for the family f of groups [g0, g1): the gamma of every group as (gm, ge) */
static void hw_family(const rgbz_hw_plan *h, const rgbz_hw_config *c, const int32_t *ET,
                      const int32_t *RT, const int64_t *sum, int f, int g0, int g1,
                      int64_t *gm, int64_t *ge)
{
    if (h->fam_known[f] == 0) {
        /* no group has a difference: every gamma 1 (a common factor) */
        for (int g = g0; g < g1; g++) {
            gm[g] = ((int64_t)1 << c->exp_bits) - 1;
            ge[g] = 0;
        }
        return;
    }
    int64_t G[RGBZ_NGROUPS], gmin = 0, gsum = 0;
    int first = 1;
    for (int g = g0; g < g1; g++) {
        G[g] = sum[g] * h->group_mult[g];
        if (h->group_mult[g] == 0) continue;
        gmin = (first || G[g] < gmin) ? G[g] : gmin;
        gsum += G[g];
        first = 0;
    }
    /* n sigma (n = fam_known), so that rel * mean = rel * gsum / n needs no division */
    const int64_t nk = h->fam_known[f];
    int64_t sigma = (gmin * nk) << c->sigma_bits;
    if (h->fam_floor[f] > sigma) sigma = h->fam_floor[f];
    if (h->fam_rel[f] * gsum > sigma) sigma = h->fam_rel[f] * gsum;
    int64_t ms, ps;
    hw_recip(sigma, c, RT, &ms, &ps);
    const int64_t mc = (ms * c->cq) >> c->recip_bits;
    const int64_t sh = ps + c->recip_bits - c->sigma_bits - c->ratio_bits;
    for (int g = g0; g < g1; g++) {
        if (h->group_mult[g] == 0) {
            gm[g] = 0;
            ge[g] = 0;
            continue;
        }
        /* t = (n G / n sigma) sqrt(log2(e) / 2) with ratio_bits fractional bits, saturated */
        const int64_t X = G[g] * nk * mc;
        int64_t t;
        if (sh >= 0) {
            t = X >> (sh < 62 ? sh : 62);
            if (t > c->tcap) t = c->tcap;
        } else {
            const int64_t k = -sh < 62 ? -sh : 62;
            t = X > (c->tcap >> k) ? c->tcap : X << k;
        }
        int64_t y = (t * t) >> c->ratio_bits;
        if (y > c->ymax) y = c->ymax;
        hw_exp2neg(y, c, ET, &gm[g], &ge[g]);
    }
}

/* x 2^s for s of either sign */
static inline int64_t hw_shift(int64_t x, int64_t s)
{
    return s >= 0 ? x << s : x >> (-s < 62 ? -s : 62);
}

/* the value of one Z site from its taps v (the plan's order), before clipping */
static int64_t hw_site(const rgbz_plan *p, const rgbz_hw_plan *h, const rgbz_hw_config *c,
                       const int32_t *ET, const int32_t *RT, const int32_t *v)
{
    const int nc = p->n_cand;
    int64_t cv[RGBZ_MAX_CAND], csum = 0;
    for (int k = 0; k < nc && k < RGBZ_MAX_CAND; k++) {
        cv[k] = v[p->cand_tap[k]];
        csum += cv[k];
    }
    /* the plain mean, rounded half up (exact): bilinear, and the fallback of the others */
    const int64_t mean = ((2 * csum + nc) * h->mean_mult) >> h->mean_shift;
    if (p->method == RGBZ_M_BILINEAR) return mean;

    /* gradients and semi-gradients: group sums, then the gammas (eq. 7) */
    int64_t sum[RGBZ_NGROUPS], gm[RGBZ_NGROUPS], ge[RGBZ_NGROUPS];
    for (int g = 0; g < RGBZ_NGROUPS; g++) sum[g] = gm[g] = ge[g] = 0;
    if (p->use_sg || p->use_grad) {
        for (int i = 0; i < p->n_pairs && i < RGBZ_MAX_PAIRS; i++) {
            int64_t d = (int64_t)v[p->pair_a[i]] - v[p->pair_b[i]];
            d = d < 0 ? -d : d;
            for (int g = 0; g < RGBZ_NGROUPS; g++)
                if ((p->pair_gmask[i] >> g) & 1) sum[g] += d;
        }
        if (p->use_sg) hw_family(h, c, ET, RT, sum, 0, 0, 8, gm, ge);
        if (p->use_grad) hw_family(h, c, ET, RT, sum, 1, 8, RGBZ_NGROUPS, gm, ge);
    }

    /* the weights (eqs. 2, 6, 19): mantissa w[k], exponent E[k] (w 2^-E) */
    int64_t w[RGBZ_MAX_CAND], E[RGBZ_MAX_CAND];
    for (int k = 0; k < nc && k < RGBZ_MAX_CAND; k++) {
        int64_t msv = 0, esv = 0;
        if (p->use_sg) {
            /* eq. 19: the gammas of the covering semi-gradients, aligned to the largest */
            int64_t emin = 0;
            int first = 1;
            for (int g = 0; g < 8; g++)
                if ((p->cand_sgmask[k] >> g) & 1) {
                    emin = (first || ge[g] < emin) ? ge[g] : emin;
                    first = 0;
                }
            for (int g = 0; g < 8; g++)
                if ((p->cand_sgmask[k] >> g) & 1) {
                    const int64_t s = ge[g] - emin;
                    msv += gm[g] >> (s < 62 ? s : 62);
                }
            msv *= h->cand_svmult[k];
            esv = emin;
        }
        if (p->use_ab) {
            /* beta (eq. 4): 1 / (1 + sum_m |c_k - c_m|) */
            int64_t S = 1;
            for (int m = 0; m < nc && m < RGBZ_MAX_CAND; m++)
                S += cv[k] > cv[m] ? cv[k] - cv[m] : cv[m] - cv[k];
            int64_t mb, pb;
            hw_recip(S, c, RT, &mb, &pb);
            w[k] = hw_shift(h->cand_ma[k] * mb, c->weight_bits - c->alpha_bits - c->recip_bits);
            E[k] = h->cand_ea[k] + pb;
            if (p->use_grad) {
                const int o = p->cand_ori[k] + 8;
                w[k] = (w[k] * gm[o]) >> c->exp_bits;
                E[k] += ge[o];
            }
            if (p->use_sg) {
                w[k] = (w[k] * msv) >> h->sv_bits;
                E[k] += esv;
            }
        } else {
            w[k] = msv;
            E[k] = esv;
        }
    }

    /* the weighted mean (eqs. 12-13): weights aligned to the largest one */
    int64_t Emin = 0;
    int any = 0;
    for (int k = 0; k < nc && k < RGBZ_MAX_CAND; k++)
        if (w[k] > 0) {
            Emin = (!any || E[k] < Emin) ? E[k] : Emin;
            any = 1;
        }
    if (!any) return mean;
    int64_t den = 0, num = 0;
    for (int k = 0; k < nc && k < RGBZ_MAX_CAND; k++) {
        if (w[k] <= 0) continue;
        const int64_t s = E[k] - Emin;
        const int64_t a = w[k] >> (s < 62 ? s : 62);
        den += a;
        num += a * (cv[k] - cv[0]);
    }
    if (den <= 0) return mean;
    int64_t md, pd;
    hw_recip(den, c, RT, &md, &pd);
    const int64_t sh = pd + c->recip_bits;
    return cv[0] + ((num * md + ((int64_t)1 << (sh - 1))) >> sh);
}

/* what the streamed site needs besides the window */
typedef struct {
    const rgbz_plan *plans;
    const rgbz_hw_plan *hw;
    const rgbz_hw_config *cfg;
    const int32_t *exp_table, *recip_table;
} hw_site_ctx;

/* the streamed site of plan pl in column x: its taps from the window, then hw_site */
static int64_t hw_stream_site(const void *ctx, int32_t pl, const rgbz_hw_stream *s, ptrdiff_t x)
{
    const hw_site_ctx *c = (const hw_site_ctx *)ctx;
    const rgbz_plan *p = &c->plans[pl];
    int32_t v[RGBZ_MAX_TAPS];
    for (int t = 0; t < p->n_taps && t < RGBZ_MAX_TAPS; t++)
        v[t] = rgbz_hw_tap(s, p->tap_dy[t], p->tap_dx[t], x);
    return hw_site(p, &c->hw[pl], c->cfg, c->exp_table, c->recip_table, v);
}

int rgbz_hw_layout(int64_t *out, int n)
{
    const int64_t v[] = {(int64_t)sizeof(rgbz_hw_plan), (int64_t)sizeof(rgbz_hw_config),
                         (int64_t)sizeof(rgbz_hw_state), RGBZ_HW_MAX_WIDTH, RGBZ_HW_MAX_PERIOD,
                         RGBZ_HW_RADIUS, RGBZ_HW_MAX_TABLE};
    const int nv = (int)(sizeof v / sizeof v[0]);
    if (!out || n < nv) return RGBZ_EINVAL;
    for (int i = 0; i < nv; i++) out[i] = v[i];
    return RGBZ_OK;
}

static int hw_check(const rgbz_plan *plans, int n_plans, const rgbz_hw_plan *hw,
                    const rgbz_hw_config *c)
{
    if (c->bit_depth < 1 || c->bit_depth > 16 || c->exp_index_bits < 1 ||
        c->exp_index_bits > 16 || c->recip_index_bits < 1 || c->recip_index_bits > 16 ||
        c->ratio_bits < 0 || c->ratio_bits > 24 || c->recip_bits < 2 || c->recip_bits > 30 ||
        c->exp_bits < 2 || c->exp_bits > 30 || c->sigma_bits < 0 || c->sigma_bits > 24 ||
        c->weight_bits < 2 || c->weight_bits > 40 || c->alpha_bits < 2 || c->alpha_bits > 30)
        return RGBZ_EINVAL;
    for (int i = 0; i < n_plans; i++) {
        const rgbz_plan *p = &plans[i];
        if (p->method < RGBZ_M_BILINEAR || p->method > RGBZ_M_SG || p->use_cd) return RGBZ_EINVAL;
        if (p->n_cand < 1 || p->n_cand > RGBZ_MAX_CAND || p->n_taps < 1 ||
            p->n_taps > RGBZ_MAX_TAPS || p->n_pairs < 0 || p->n_pairs > RGBZ_MAX_PAIRS)
            return RGBZ_EINVAL;
        for (int t = 0; t < p->n_taps; t++)
            if (p->tap_dy[t] < -RGBZ_HW_RADIUS || p->tap_dy[t] > RGBZ_HW_RADIUS ||
                p->tap_dx[t] < -RGBZ_HW_RADIUS || p->tap_dx[t] > RGBZ_HW_RADIUS)
                return RGBZ_EINVAL;
        for (int k = 0; k < p->n_cand; k++)
            if (p->cand_tap[k] < 0 || p->cand_tap[k] >= p->n_taps || p->cand_ori[k] < 0 ||
                p->cand_ori[k] > 3 || p->cand_sgmask[k] < 0 || p->cand_sgmask[k] >= 256)
                return RGBZ_EINVAL;
        for (int k = 0; k < p->n_pairs; k++)
            if (p->pair_a[k] < 0 || p->pair_a[k] >= p->n_taps || p->pair_b[k] < 0 ||
                p->pair_b[k] >= p->n_taps || p->pair_gmask[k] < 0 ||
                p->pair_gmask[k] >= (1 << RGBZ_NGROUPS))
                return RGBZ_EINVAL;
        if (hw[i].mean_shift < 1 || hw[i].mean_shift > 62 || hw[i].sv_bits < 0 ||
            hw[i].sv_bits > 62)
            return RGBZ_EINVAL;
    }
    return RGBZ_OK;
}

int rgbz_reconstruct_fixed(int in_type, const void *src, void *dst, ptrdiff_t rows,
                           ptrdiff_t cols, int py, int px, const int32_t *plan_map,
                           const rgbz_plan *plans, int n_plans, const rgbz_params *params,
                           uint64_t *opcounts)
{
    (void)opcounts;
    if (!params || !params->fixed || params->clip_on || params->mask1_fast) return RGBZ_EINVAL;
    const rgbz_hw_plan *hw = params->fixed->hw;
    const rgbz_hw_config *cfg = params->fixed->cfg;
    const int32_t *exp_table = params->fixed->exp_table;
    const int32_t *recip_table = params->fixed->recip_table;
    rgbz_hw_state *st = params->fixed->state;
    if (!src || !dst || !plan_map || !plans || !hw || !cfg || !exp_table || !recip_table ||
        !st || n_plans < 1)
        return RGBZ_EINVAL;
    if (in_type != RGBZ_T_U8 && in_type != RGBZ_T_U16) return RGBZ_EINVAL;
    if (py < 1 || px < 1 || py > RGBZ_HW_MAX_PERIOD || px > RGBZ_HW_MAX_PERIOD || rows < py ||
        cols < px || cols > RGBZ_HW_MAX_WIDTH)
        return RGBZ_EINVAL;
    for (int i = 0; i < py * px; i++)
        if (plan_map[i] < -1 || plan_map[i] >= n_plans) return RGBZ_EINVAL;
    if (hw_check(plans, n_plans, hw, cfg) != RGBZ_OK) return RGBZ_EINVAL;

    const hw_site_ctx ctx = {plans, hw, cfg, exp_table, recip_table};
    const rgbz_hw_stream s = rgbz_hw_stream_init(rows, cols, RGBZ_HW_RADIUS, py, px,
                                                 &st->lb[0][0], RGBZ_HW_MAX_WIDTH,
                                                 &st->win[0][0], RGBZ_HW_MAX_WC);
    rgbz_hw_stream_frame(&s, in_type, src, dst, plan_map, ((int64_t)1 << cfg->bit_depth) - 1,
                         hw_stream_site, &ctx);
    return RGBZ_OK;
}
