/*
 * z_guided.c -- the z_guided reconstruction (z_guided.h): z_guided.template.h for every
 * element type and precision, the entry points rgbz_zguided_<precision>
 * (z_guided_entry.template.h, once per precision), and what they share: the checks of the
 * arguments the Python layer validated (a failure here is a bug there) and the column map
 * (z_guided_cells.template.h: the cell terms of a tile row, per precision). The hash, the
 * dot products and the fast path are the learned kernel's (learned_common.h,
 * learned_hash.template.h).
 */
#include <float.h>
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
        f->gx < 1 || !f->chan || !f->targets ||
        (f->grid ? !f->var
                 : (!f->taps || !f->ratio || !f->site_rows || !f->site_cols || f->taps_F < 1 || f->taps_F > RGBZ_TOF_MAX_FREQS ||
                    f->gyc < 1 || f->gxc < 1 || f->gyc > f->gy || f->gxc > f->gx ||
                    (f->taps_type != RGBZ_T_U8 && f->taps_type != RGBZ_T_U16 &&
                     f->taps_type != RGBZ_T_F32 && f->taps_type != RGBZ_T_F64))) ||
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

/* the smallest normal of each precision: keeps share = U / (U + 9 nu) at 0 for U = nu = 0 */
#define RGBZ_TINY_f32 FLT_MIN
#define RGBZ_TINY_f64 DBL_MIN

/* the column map of the taps: x in [-R, cols + R) -> its column inside the frame */
static ptrdiff_t *zg_colmap(const rgbz_zguided_filters *f, ptrdiff_t cols, int px)
{
    const int R = f->hash->radius;
    ptrdiff_t *colmap = malloc((size_t)(cols + 2 * R) * sizeof *colmap);
    if (colmap)
        for (ptrdiff_t x = -R; x < cols + R; x++) colmap[x + R] = lrn_extend(x, cols, px);
    return colmap;
}

/* the cells of a chunk of zg_cell_row: its terms are computed into per-term rows of this
   many cells (the vectorised loop's contiguous stores), then written into the cells' vectors */
#define ZG_CHUNK 64

#if LRN_VECTOR_EXT
/* the 8 floats at p as a vector */
RGBZ_INLINE lrn_v8f zg_ld8(const float *p)
{
    lrn_v8f v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* the terms 0 .. 7 of the 8 cells from column i of the rows tm[m] (row stride ZG_CHUNK) into
   the first 8 floats of those cells' vectors (out, cell stride cvr floats): the 8 x 8 block
   transposed in registers (lrn_transpose8_f32) */
RGBZ_INLINE void zg_put8_f32(const float *tm, ptrdiff_t i, float *out, ptrdiff_t cvr)
{
    /* each row loaded by itself: a loop of memcpy's into the array compiles, in the AVX2
       clone, to a copy through the stack */
    const float *p = tm + i;
    const lrn_v8f r[8] = {zg_ld8(p), zg_ld8(p + ZG_CHUNK), zg_ld8(p + 2 * ZG_CHUNK),
                          zg_ld8(p + 3 * ZG_CHUNK), zg_ld8(p + 4 * ZG_CHUNK),
                          zg_ld8(p + 5 * ZG_CHUNK), zg_ld8(p + 6 * ZG_CHUNK),
                          zg_ld8(p + 7 * ZG_CHUNK)};
    lrn_v8f T[8];
    lrn_transpose8_f32(r, T);
    for (int l = 0; l < 8; l++) memcpy(out + (ptrdiff_t)l * cvr, &T[l], sizeof T[l]);
}

/* the same for doubles: 4 cells, their terms 0 .. 3 and 4 .. 7 as two 4 x 4 blocks */
RGBZ_INLINE void zg_put8_f64(const double *tm, ptrdiff_t i, double *out, ptrdiff_t cvr)
{
    for (int h = 0; h < 8; h += 4) {
        const double *p = tm + (ptrdiff_t)h * ZG_CHUNK + i;
        lrn_v4d r[4];
        memcpy(&r[0], p, sizeof r[0]);
        memcpy(&r[1], p + ZG_CHUNK, sizeof r[1]);
        memcpy(&r[2], p + 2 * ZG_CHUNK, sizeof r[2]);
        memcpy(&r[3], p + 3 * ZG_CHUNK, sizeof r[3]);
        lrn_v4d c[4];
        lrn_transpose4_f64(r, c);
        for (int l = 0; l < 4; l++) memcpy(out + (ptrdiff_t)l * cvr + h, &c[l], sizeof c[l]);
    }
}

/* the values c_8, -1, c_9, c_10 of the 8 cells from column i of the rows tm[8], tm[9],
   tm[10] (row stride ZG_CHUNK) into the 4 floats after the first 8 of those cells' vectors
   (out, cell stride cvr; the 4 floats after them stay 0): a 4 x 8 block transposed */
RGBZ_INLINE void zg_putb_f32(const float *tm, ptrdiff_t i, float *out, ptrdiff_t cvr)
{
    lrn_v8f c8, c9, c10;
    const lrn_v8f m1 = {-1, -1, -1, -1, -1, -1, -1, -1};
    memcpy(&c8, tm + 8 * ZG_CHUNK + i, sizeof c8);
    memcpy(&c9, tm + 9 * ZG_CHUNK + i, sizeof c9);
    memcpy(&c10, tm + 10 * ZG_CHUNK + i, sizeof c10);
    const lrn_v8f t0 = LRN_SHUF8(c8, m1, 0, 8, 1, 9, 4, 12, 5, 13);
    const lrn_v8f t1 = LRN_SHUF8(c8, m1, 2, 10, 3, 11, 6, 14, 7, 15);
    const lrn_v8f t2 = LRN_SHUF8(c9, c10, 0, 8, 1, 9, 4, 12, 5, 13);
    const lrn_v8f t3 = LRN_SHUF8(c9, c10, 2, 10, 3, 11, 6, 14, 7, 15);
    lrn_v8f u[4];   /* u[l]: cell l in the low half, cell l + 4 in the high half */
    u[0] = LRN_SHUF8(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
    u[1] = LRN_SHUF8(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
    u[2] = LRN_SHUF8(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
    u[3] = LRN_SHUF8(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
    for (int l = 0; l < 4; l++) {
        memcpy(out + (ptrdiff_t)l * cvr + 8, &u[l], 4 * sizeof(float));
        memcpy(out + (ptrdiff_t)(l + 4) * cvr + 8, (const char *)&u[l] + 4 * sizeof(float),
               4 * sizeof(float));
    }
}

/* the same for doubles: 4 cells, each value 8 .. 11 of its vector */
RGBZ_INLINE void zg_putb_f64(const double *tm, ptrdiff_t i, double *out, ptrdiff_t cvr)
{
    lrn_v4d c8, c9, c10;
    const lrn_v4d m1 = {-1, -1, -1, -1};
    memcpy(&c8, tm + 8 * ZG_CHUNK + i, sizeof c8);
    memcpy(&c9, tm + 9 * ZG_CHUNK + i, sizeof c9);
    memcpy(&c10, tm + 10 * ZG_CHUNK + i, sizeof c10);
    const lrn_v4d rows[4] = {c8, m1, c9, c10};
    lrn_v4d u[4];
    lrn_transpose4_f64(rows, u);
    for (int l = 0; l < 4; l++) memcpy(out + (ptrdiff_t)l * cvr + 8, &u[l], sizeof u[l]);
}

/* a cell's second row c_8, -1, c_9, c_10, 0, ... -> c_9, c_10, 0, ... (the floats' lanes 6
   and 7 are 0: the in-lane shift by two) */
RGBZ_INLINE lrn_v8f zg_low2_f32(lrn_v8f c)
{
    const lrn_v8f z = {0};
    return LRN_SHUF8(c, z, 2, 3, 8, 8, 6, 7, 8, 8);
}

RGBZ_INLINE lrn_v4d zg_low2_f64(lrn_v4d c)
{
    const lrn_v4d z = {0};
    return LRN_SHUF4(c, z, 2, 3, 4, 4);
}
#endif

/* not 0 when the n sites (sr[i], sc[i]) are not (r, c0 + px i), i = 0 .. n - 1: a row of
   Z pixels in order */
RGBZ_CLONES_512
static int zg_sites_bad(const int64_t *restrict sr, const int64_t *restrict sc, ptrdiff_t n,
                        int64_t r, int64_t c0, int px)
{
    int bad = 0;
    int64_t c = c0;   /* an induction variable: no 64-bit products in the vectorised loop */
    RGBZ_IVDEP for (ptrdiff_t i = 0; i < n; i++) {
        bad |= (sr[i] != r) | (sc[i] != c);
        c += px;
    }
    return bad;
}

/* a row of the guide from the taps in each precision (zg_guide_rows): in double the values
   of rgbz_zguided_guide (those of ToFTaps.amplitude), in float its float arithmetic */
#define zg_taps_row_f64 rgbz_zguided_guide_row
#define zg_taps_row_f32 rgbz_zguided_guide_row_f32

/* ---- the instances: per precision, the frame loops and the entry point ---- */
#define RGBZ_REAL_TEMPLATE "z_guided_entry.template.h"
#include "rgbz_each_real.h"
#undef RGBZ_REAL_TEMPLATE
