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

/* floor(log2 x) + 1 of x >= 0 (a priority encoder) */
static inline int64_t hwl_bitlen(int64_t x)
{
    int64_t p = 0;
    for (int s = 32; s >= 1; s >>= 1)
        if ((x >> (p + s)) > 0) p += s;
    return p + (x > 0);
}

/* i moved into [0, n) by whole periods P (n >= P): the float kernel's border rule */
static inline ptrdiff_t hwl_extend(ptrdiff_t i, ptrdiff_t n, ptrdiff_t P)
{
    return i < 0 ? i + P * ((P - 1 - i) / P) : (i >= n ? i - P * ((i - n + P) / P) : i);
}

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
    const int64_t bl = hwl_bitlen(T);
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
        const int64_t bl2 = hwl_bitlen(emax);
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
    const int R = f->radius;
    const int A = R > py - 1 ? R : py - 1;        /* rows of look-ahead */
    const int Ax = R > px - 1 ? R : px - 1;       /* pixels of look-ahead */
    const int NLB = R + A;                        /* line buffers */
    const int WC = R + Ax + 1;                    /* window columns */
    const int WR = 2 * R + 1;                     /* window rows */
    const uint8_t *s8 = (const uint8_t *)src;
    const uint16_t *s16 = (const uint16_t *)src;
    uint8_t *d8 = (uint8_t *)dst;
    uint16_t *d16 = (uint16_t *)dst;

    /* one step per input pixel, blanking included: (rows + A) x (cols + Ax) steps */
    for (ptrdiff_t in_row = 0; in_row < rows + A; in_row++) {
        const ptrdiff_t y = in_row - A;           /* the output row of these steps */
        ptrdiff_t rsel[RGBZ_HWL_WR];              /* frame row of each window row */
        for (int d = 0; d < WR; d++) rsel[d] = y >= 0 ? hwl_extend(y + d - R, rows, py) : 0;
        for (ptrdiff_t x_in = 0; x_in < cols + Ax; x_in++) {
            /* 1. the input pixel; the column x_in of the window rows into the window (the
                  line buffers read before the incoming pixel overwrites the oldest row) */
            if (x_in < cols) {
                int32_t pix = 0;
                if (in_row < rows)
                    pix = in_type == RGBZ_T_U8 ? s8[in_row * cols + x_in]
                                               : s16[in_row * cols + x_in];
                if (y >= 0)
                    for (int d = 0; d < WR; d++)
                        st->win[d][x_in % WC] = rsel[d] == in_row
                                                    ? pix : st->lb[rsel[d] % NLB][x_in];
                if (in_row < rows) st->lb[in_row % NLB][x_in] = (uint16_t)pix;
            }
            /* 2. the output pixel (y, xo) */
            const ptrdiff_t xo = x_in - Ax;
            if (y < 0 || xo < 0) continue;
            const int32_t k = phase_map[(y % py) * px + xo % px];
            int64_t out = st->win[R][xo % WC];    /* a colour site: copied */
            if (k >= 0) {
                int32_t v[RGBZ_LEARNED_MAX_TAPS];
                const ptrdiff_t o = (ptrdiff_t)k * f->n_taps_max;
                for (int t = 0; t < f->n_taps[k] && t < RGBZ_LEARNED_MAX_TAPS; t++)
                    v[t] = st->win[f->tap_dy[o + t] + R]
                                  [hwl_extend(xo + f->tap_dx[o + t], cols, px) % WC];
                out = hwl_site(f, x, k, v);
                out = out < 0 ? 0 : out > top ? top : out;
            }
            if (in_type == RGBZ_T_U8)
                d8[y * cols + xo] = (uint8_t)out;
            else
                d16[y * cols + xo] = (uint16_t)out;
        }
    }
    return RGBZ_OK;
}
