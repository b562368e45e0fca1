/*
 * hw_learned.c -- the fixed-point streaming model of the learned reconstruction
 * (hw_learned.h says what it models; docs/guide/hardware.md specifies the datapath).
 *
 * Per-pixel path: integers only (int64_t registers, each within the width the Python
 * layer declared and checked for the filters and bit depth), fixed-size arrays, loops whose
 * trip counts are bounded by the RGBZ_LEARNED_* and RGBZ_HWL_* constants. Right shifts of
 * negative values are arithmetic (floor), as in every C compiler this builds with and in
 * NumPy's right_shift.
 */
#include <string.h>
#include "hw_learned.h"
#include "hw_stream.h"

/* the streaming front end holds the window rows of this radius */
typedef char hw_learned_radius_fits[RGBZ_LEARNED_MAX_RADIUS <= RGBZ_HW_STREAM_MAX_RADIUS ? 1 : -1];

/* the bucket of one site of phase k from its taps v (hw_learned.h, steps 1-5) */
static int32_t hwl_bucket(const rgbz_learned_filters *f, const rgbz_learned_fixed_args *x,
                          int k, const int32_t *v)
{
    const rgbz_hwl_config *c = x->cfg;
    int64_t E[RGBZ_LEARNED_DIRS], S[RGBZ_LEARNED_DIRS], Sc[3] = {0, 0, 0};
    for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
        const int np = f->n_pairs[k * RGBZ_LEARNED_DIRS + d];
        const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * f->n_pairs_max;
        S[d] = 0;
        for (int p = 0; p < np; p++) {
            const int64_t df = (int64_t)v[f->pair_a[o + p]] - v[f->pair_b[o + p]];
            S[d] += df * df;
            if (d < RGBZ_LEARNED_SPREAD_DIRS) Sc[f->pair_col[o + p]] += df * df;
        }
        E[d] = S[d] * x->knorm[k * RGBZ_LEARNED_DIRS + d];
    }
    const int ns = f->n_str, nc = f->n_coh, nk = f->n_spr;
    const int64_t A = 4 * (E[0] - E[1]), B = 2 * (E[2] - E[3]);
    const int64_t T = 2 * (E[0] + E[1]) + E[2] + E[3];
    int32_t strength = 0;
    for (int i = 0; i < ns - 1; i++) strength += T > x->str_q[(ptrdiff_t)k * (ns - 1) + i];

    /* the normalising shift: |A|, |B| <= 2 T, so |a|, |b| <= 2^(hash_bits + 1) */
    const int64_t bl = rgbz_hw_bitlen(T);
    const int64_t sh = bl > c->hash_bits ? bl - c->hash_bits : 0;
    const int64_t a = A >> sh, b = B >> sh, t = T >> sh;
    const int64_t ar = c->cos_q * a - c->sin_q * b;
    const int64_t br = c->sin_q * a + c->cos_q * b;
    const int neg = br < 0;
    const int64_t ar1 = neg ? -ar : ar, br1 = neg ? -br : br;
    const int left = ar1 < 0;
    const int64_t ar2 = left ? br1 : ar1, br2 = left ? -ar1 : br1;
    const int32_t octant = 4 * neg + 2 * left + (br2 > ar2);

    int32_t coherence = 0;
    if (nc > 1) {
        const int64_t m2 = (a * a + b * b) << c->const_bits;
        const int64_t t2 = t * t;
        for (int i = 0; i < nc - 1; i++)
            coherence += m2 > x->coh_q[(ptrdiff_t)k * (nc - 1) + i] * t2;
    }
    int32_t spread = 0;
    if (nk > 1) {
        int64_t ec[3], emax, emin;
        for (int col = 0; col < 3; col++) ec[col] = Sc[col] * x->kcol[k * 3 + col];
        emax = ec[0] > ec[1] ? ec[0] : ec[1];
        emax = ec[2] > emax ? ec[2] : emax;
        emin = ec[0] < ec[1] ? ec[0] : ec[1];
        emin = ec[2] < emin ? ec[2] : emin;
        const int64_t bl2 = rgbz_hw_bitlen(emax);
        const int64_t sh2 = bl2 > c->hash_bits ? bl2 - c->hash_bits : 0;
        const int64_t hi = (emax >> sh2) << c->const_bits, lo = emin >> sh2;
        for (int i = 0; i < nk - 1; i++)
            spread += hi > x->spr_q[(ptrdiff_t)k * (nk - 1) + i] * lo;
    }
    return ((octant * ns + strength) * nc + coherence) * nk + spread;
}

/* the value of one Z site of phase k (before clipping): the bucket's filter, rounded */
static int64_t hwl_site(const rgbz_learned_filters *f, const rgbz_learned_fixed_args *x, int k,
                        const int32_t *v)
{
    const int32_t bucket = hwl_bucket(f, x, k, v);
    const int32_t *w = x->wq + ((ptrdiff_t)k * f->n_buckets + bucket) * f->n_taps_max;
    int64_t acc = 0;
    for (int t = 0; t < f->n_taps[k] && t < RGBZ_LEARNED_MAX_TAPS; t++)
        acc += (int64_t)w[t] * v[t];
    const int64_t F = x->cfg->tap_frac;
    return F > 0 ? (acc + ((int64_t)1 << (F - 1))) >> F : acc;
}

/* the streamed site of phase k in column x: its taps from the window, then hwl_site */
static int64_t hwl_stream_site(const void *ctx, int32_t k, const rgbz_hw_stream *s, ptrdiff_t x)
{
    const rgbz_learned_filters *f = (const rgbz_learned_filters *)ctx;
    int32_t v[RGBZ_LEARNED_MAX_TAPS];
    const ptrdiff_t o = (ptrdiff_t)k * f->n_taps_max;
    for (int t = 0; t < f->n_taps[k] && t < RGBZ_LEARNED_MAX_TAPS; t++)
        v[t] = rgbz_hw_tap(s, f->tap_dy[o + t], f->tap_dx[o + t], x);
    return hwl_site(f, f->fixed, k, v);
}

int rgbz_hwl_layout(int64_t *out, int n)
{
    const int64_t v[] = {(int64_t)sizeof(rgbz_hwl_config), (int64_t)sizeof(rgbz_hwl_state),
                         RGBZ_HWL_MAX_WIDTH, RGBZ_HWL_MAX_PERIOD, RGBZ_LEARNED_MAX_RADIUS};
    const int nv = (int)(sizeof v / sizeof v[0]);
    if (!out || n < nv) return RGBZ_EINVAL;
    for (int i = 0; i < nv; i++) out[i] = v[i];
    return RGBZ_OK;
}

static int hwl_check(const rgbz_learned_filters *f, const rgbz_learned_fixed_args *x)
{
    const rgbz_hwl_config *c = x->cfg;
    if (c->bit_depth < 1 || c->bit_depth > 16 || c->tap_frac < 0 || c->tap_frac > 40 ||
        c->hash_bits < 2 || c->hash_bits > 40 || c->const_bits < 0 || c->const_bits > 40)
        return RGBZ_EINVAL;
    if (f->n_phases < 1 || f->n_buckets < 1 || f->n_taps_max < 1 ||
        f->n_taps_max > RGBZ_LEARNED_MAX_TAPS || f->radius < 1 ||
        f->radius > RGBZ_LEARNED_MAX_RADIUS || f->n_str < 1 || f->n_coh < 1 || f->n_spr < 1 ||
        f->n_buckets != 8 * f->n_str * f->n_coh * f->n_spr || f->n_pairs_max < 1)
        return RGBZ_EINVAL;
    for (int k = 0; k < f->n_phases; k++) {
        if (f->n_taps[k] < 1 || f->n_taps[k] > f->n_taps_max) return RGBZ_EINVAL;
        for (int t = 0; t < f->n_taps[k]; t++) {
            const int dy = f->tap_dy[k * f->n_taps_max + t], dx = f->tap_dx[k * f->n_taps_max + t];
            if (dy < -f->radius || dy > f->radius || dx < -f->radius || dx > f->radius)
                return RGBZ_EINVAL;
        }
        for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
            const int np = f->n_pairs[k * RGBZ_LEARNED_DIRS + d];
            const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * f->n_pairs_max;
            if (np < 1 || np > f->n_pairs_max) return RGBZ_EINVAL;
            for (int p = 0; p < np; p++)
                if (f->pair_a[o + p] < 0 || f->pair_a[o + p] >= f->n_taps[k] ||
                    f->pair_b[o + p] < 0 || f->pair_b[o + p] >= f->n_taps[k] ||
                    f->pair_col[o + p] < 0 || f->pair_col[o + p] > 2)
                    return RGBZ_EINVAL;
        }
    }
    return RGBZ_OK;
}

int rgbz_learned_fixed(int in_type, const void *src, void *dst, ptrdiff_t rows, ptrdiff_t cols,
                       int py, int px, const int32_t *phase_map, const rgbz_learned_filters *f,
                       double maxval, int workers, uint64_t *opcounts)
{
    (void)workers;
    (void)opcounts;
    if (!src || !dst || !phase_map || !f || !f->fixed) return RGBZ_EINVAL;
    const rgbz_learned_fixed_args *x = f->fixed;
    if (!x->cfg || !x->knorm || !x->kcol || !x->str_q || !x->coh_q || !x->spr_q || !x->wq ||
        !x->state || !f->n_taps || !f->tap_dy || !f->tap_dx || !f->n_pairs || !f->pair_a ||
        !f->pair_b || !f->pair_col)
        return RGBZ_EINVAL;
    if (in_type != RGBZ_T_U8 && in_type != RGBZ_T_U16) return RGBZ_EINVAL;
    if (py < 1 || px < 1 || py > RGBZ_HWL_MAX_PERIOD || px > RGBZ_HWL_MAX_PERIOD || rows < py ||
        cols < px || cols > RGBZ_HWL_MAX_WIDTH)
        return RGBZ_EINVAL;
    if (hwl_check(f, x) != RGBZ_OK) return RGBZ_EINVAL;
    const int64_t top = ((int64_t)1 << x->cfg->bit_depth) - 1;
    if ((double)top != maxval) return RGBZ_EINVAL;
    for (int i = 0; i < py * px; i++)
        if (phase_map[i] < -1 || phase_map[i] >= f->n_phases) return RGBZ_EINVAL;

    rgbz_hwl_state *st = x->state;
    const rgbz_hw_stream s = rgbz_hw_stream_init(rows, cols, f->radius, py, px, &st->lb[0][0],
                                                 RGBZ_HWL_MAX_WIDTH, &st->win[0][0],
                                                 RGBZ_HWL_MAX_WC);
    rgbz_hw_stream_frame(&s, in_type, src, dst, phase_map, top, hwl_stream_site, f);
    return RGBZ_OK;
}
