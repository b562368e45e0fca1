/*
 * z_guided.c -- the z_guided reconstruction (z_guided.h): z_guided.template.h for every
 * element type and precision, the entry points rgbz_zguided_<precision>
 * (z_guided_entry.template.h, once per precision), and what they share: the checks of the
 * arguments the Python layer validated (a failure here is a bug there), the column map and
 * the cell terms of a tile row. The hash, the dot products and the fast path are the learned
 * kernel's (learned_common.h, learned_hash.template.h).
 */
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"
#include "rgbz_ops.h"
#include "rgbz_templating.h"
#include "learned_common.h"
#include "z_guided.h"

#define ZG_MAX_BOX 36   /* the pixels of a Z pixel's box: (2 + 2 + 2)^2 at most */

static int zg_check(const void *src, const void *dst, const rgbz_zguided_filters *f,
                    ptrdiff_t rows, ptrdiff_t cols, int py, int px, const int32_t *phase_map)
{
    if (!src || !dst || !phase_map || !f || !f->hash || f->n_levels < 1 || f->gy < 1 ||
        f->gx < 1 || !f->grid || !f->var || !f->chan || !f->targets ||
        (f->n_levels > 1 && !f->thr) || !f->w_f32 || !f->w_f64 || !f->g_f32 || !f->g_f64 ||
        !f->n_base || !f->base_idx || f->n_base_max < 1 || (f->block != 1 && f->block != 2) ||
        f->zr < 0 || f->zc < 0 || f->zr >= py || f->zc >= px)
        return RGBZ_EINVAL;
    const rgbz_learned_filters *h = f->hash;
    if (h->n_phases <= 0 || h->n_str < 1 || h->n_coh < 1 || h->n_spr < 1 ||
        h->n_buckets != 8 * h->n_str * h->n_coh * h->n_spr || h->radius < 0 ||
        h->radius > RGBZ_LEARNED_MAX_RADIUS || h->n_taps_max <= 0 ||
        h->n_taps_max > RGBZ_LEARNED_MAX_TAPS || py <= 0 || px <= 0 || rows < py || cols < px)
        return RGBZ_EINVAL;
    for (int i = 0; i < py * px; i++)
        if (phase_map[i] >= h->n_phases) return RGBZ_EINVAL;
    /* the spread term indexes the colour energies by pair_col */
    if (h->n_spr > 1) {
        if (!h->pair_col || !h->inv_col || !h->spr_thr) return RGBZ_EINVAL;
        for (ptrdiff_t i = 0; i < (ptrdiff_t)h->n_phases * RGBZ_LEARNED_DIRS * h->n_pairs_max; i++)
            if (h->pair_col[i] < 0 || h->pair_col[i] > 2) return RGBZ_EINVAL;
    }
    for (int k = 0; k < h->n_phases; k++) {
        const int nt = h->n_taps[k], nb = f->n_base[k];
        if (nt <= 0 || nt > h->n_taps_max || nb < 1 || nb > f->n_base_max) return RGBZ_EINVAL;
        /* the target colour: 0..2, and present in the tile (its colour means have pixels) */
        int found = 0;
        for (int i = 0; i < py * px; i++) found |= f->chan[i] == f->targets[k];
        if (f->targets[k] < 0 || f->targets[k] > 2 || !found) return RGBZ_EINVAL;
        for (int t = 0; t < nt; t++) {
            const int dy = h->tap_dy[k * h->n_taps_max + t], dx = h->tap_dx[k * h->n_taps_max + t];
            if (dy < -h->radius || dy > h->radius || dx < -h->radius || dx > h->radius)
                return RGBZ_EINVAL;
        }
        for (int i = 0; i < nb; i++)
            if (f->base_idx[k * f->n_base_max + i] < 0 || f->base_idx[k * f->n_base_max + i] >= nt)
                return RGBZ_EINVAL;
        for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
            const int np = h->n_pairs[k * RGBZ_LEARNED_DIRS + d];
            if (np <= 0 || np > h->n_pairs_max) return RGBZ_EINVAL;
            const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * h->n_pairs_max;
            for (int p = 0; p < np; p++)
                if (h->pair_a[o + p] < 0 || h->pair_a[o + p] >= nt || h->pair_b[o + p] < 0 ||
                    h->pair_b[o + p] >= nt)
                    return RGBZ_EINVAL;
        }
    }
    return RGBZ_OK;
}

/* ---- the cell terms (z_guided.h), one tile row and target colour at a time, in double ---- */

/* what a thread keeps of the cell terms: for each target colour t, the colour means of
   three tile rows (a ring, slot = tile row mod 3, tagged) padded by one cell on each side
   with the edge cell, and the terms of one tile row, [11][gx] (tagged); the noise levels of
   one tile row (tagged); the padded amplitude and variance rows; the box offsets */
typedef struct {
    ptrdiff_t gx;
    double *cg;                 /* [3 targets][3 slots][gx + 2] */
    ptrdiff_t cg_tag[3][3];
    double *cell;               /* [3 targets][RGBZ_ZG_FEATURES][gx] */
    ptrdiff_t cell_tag[3];
    int32_t *level;             /* [gx] */
    ptrdiff_t level_tag;
    double *nv;                 /* [7][gx + 2]: N of rows iy - 1 .. iy + 1, then V, then nu */
    ptrdiff_t nv_tag;
    int nbox[3];
    int ey[3][ZG_MAX_BOX], ex[3][ZG_MAX_BOX];
} zg_cells;

/* a thread's cell state (buffers, empty tags, the box offsets of each colour: the pixels of
   colour t in the box of the Z pixel and the two pixels around it, row-major, the same for
   every tile); RGBZ_ENOMEM */
static int zg_cells_init(zg_cells *s, const rgbz_zguided_filters *f, int py, int px)
{
    const ptrdiff_t gx = f->gx;
    s->gx = gx;
    s->cg = malloc((size_t)9 * (size_t)(gx + 2) * sizeof *s->cg);
    s->cell = malloc((size_t)3 * RGBZ_ZG_FEATURES * (size_t)gx * sizeof *s->cell);
    s->level = malloc((size_t)gx * sizeof *s->level);
    s->nv = malloc((size_t)7 * (size_t)(gx + 2) * sizeof *s->nv);
    for (int t = 0; t < 3; t++) {
        s->cell_tag[t] = PTRDIFF_MIN;
        for (int i = 0; i < 3; i++) s->cg_tag[t][i] = PTRDIFF_MIN;
        int n = 0;
        for (int dy = -2; dy < f->block + 2; dy++)
            for (int dx = -2; dx < f->block + 2; dx++) {
                const int y = ((f->zr + dy) % py + py) % py, x = ((f->zc + dx) % px + px) % px;
                if (f->chan[y * px + x] == t) {
                    s->ey[t][n] = dy;
                    s->ex[t][n] = dx;
                    n++;
                }
            }
        s->nbox[t] = n;
    }
    s->level_tag = PTRDIFF_MIN;
    s->nv_tag = PTRDIFF_MIN;
    return s->cg && s->cell && s->level && s->nv ? RGBZ_OK : RGBZ_ENOMEM;
}

static void zg_cells_free(zg_cells *s)
{
    free(s->cg);
    free(s->cell);
    free(s->level);
    free(s->nv);
}

/* pads row r (gx values at r[1 ..]) with its edge values at r[0] and r[gx + 1] */
static inline void zg_pad(double *r, ptrdiff_t gx)
{
    r[0] = r[1];
    r[gx + 1] = r[gx];
}

/* the cell terms of tile row iy: out[m][ix] (RGBZ_ZG_FEATURES rows of gx) and the relative
   noise nu[ix], from the padded rows N[3], V[3], C[3] (rows iy - 1 .. iy + 1, clamped;
   index ix + 1 is cell ix). Every sum in the order of m, as cell_terms. */
RGBZ_CLONES_512
static void zg_cell_row(const double *const *N, const double *const *V, const double *const *C,
                        ptrdiff_t gx, double lam, double *restrict out, double *restrict nu_out)
{
    const double *restrict n0 = N[0], *restrict n1 = N[1], *restrict n2 = N[2];
    const double *restrict v0 = V[0], *restrict v1 = V[1], *restrict v2 = V[2];
    const double *restrict c0 = C[0], *restrict c1 = C[1], *restrict c2 = C[2];
    RGBZ_IVDEP for (ptrdiff_t ix = 0; ix < gx; ix++) {
        const double n_[9] = {n0[ix], n0[ix + 1], n0[ix + 2], n1[ix], n1[ix + 1], n1[ix + 2],
                              n2[ix], n2[ix + 1], n2[ix + 2]};
        const double v_[9] = {v0[ix], v0[ix + 1], v0[ix + 2], v1[ix], v1[ix + 1], v1[ix + 2],
                              v2[ix], v2[ix + 1], v2[ix + 2]};
        const double c_[9] = {c0[ix], c0[ix + 1], c0[ix + 2], c1[ix], c1[ix + 1], c1[ix + 2],
                              c2[ix], c2[ix + 1], c2[ix + 2]};
        double nb = 0.0, vb = 0.0, cb = 0.0;
        for (int m = 0; m < 9; m++) {
            nb += n_[m];
            vb += v_[m];
            cb += c_[m];
        }
        nb /= 9.0;
        vb /= 9.0;
        cb /= 9.0;
        const int lit = nb > 0.0;
        const double inv = 1.0 / (lit ? nb : 1.0);
        double u[9], U = 0.0, ud = 0.0;
        for (int m = 0; m < 9; m++) {
            u[m] = lit ? n_[m] * inv - 1.0 : 0.0;
            U += u[m] * u[m];
        }
        const double nu = lit ? vb * inv * inv : 1.0;
        for (int m = 0; m < 9; m++) ud += u[m] * (c_[m] - cb);
        const double share = U / (U + 9.0 * nu + 2.2250738585072014e-308);
        const double a = ud / (U + 9.0 * (lam + nu));
        const double au = a * u[4];
        for (int m = 0; m < 9; m++) out[m * gx + ix] = share * u[m];
        out[9 * gx + ix] = cb + au;
        out[10 * gx + ix] = au - (c_[4] - cb);
        nu_out[ix] = nu;
    }
}

/* the noise levels of a tile row: how many of the n_thr thresholds nu exceeds */
static void zg_level_row(const double *restrict nu, ptrdiff_t gx, const double *thr, int n_thr,
                         int32_t *restrict lvl)
{
    for (ptrdiff_t ix = 0; ix < gx; ix++) lvl[ix] = 0;
    for (int i = 0; i < n_thr; i++) {
        const double t = thr[i];
        RGBZ_IVDEP for (ptrdiff_t ix = 0; ix < gx; ix++) lvl[ix] += nu[ix] > t;
    }
}

/* the column map of the taps: x in [-R, cols + R) -> its column inside the frame */
static ptrdiff_t *zg_colmap(const rgbz_zguided_filters *f, ptrdiff_t cols, int px)
{
    const int R = f->hash->radius;
    ptrdiff_t *colmap = malloc((size_t)(cols + 2 * R) * sizeof *colmap);
    if (colmap)
        for (ptrdiff_t x = -R; x < cols + R; x++) colmap[x + R] = lrn_extend(x, cols, px);
    return colmap;
}

/* ---- the instances: per precision, the frame loops and the entry point ---- */
#define RGBZ_REAL_TEMPLATE "z_guided_entry.template.h"
#include "rgbz_each_real.h"
#undef RGBZ_REAL_TEMPLATE
