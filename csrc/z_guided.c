/*
 * z_guided.c -- the z_guided reconstruction (z_guided.h): 4 element types x 2 precisions of
 * z_guided.template.h, and the typed entry points that check the arguments the Python
 * layer validated (a failure here is a bug there) and build the column map.
 */
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"
#include "rgbz_ops.h"
#include "z_guided.h"

/* the border rule of every kernel: an index outside [0, n) moves back inside by whole
   periods P (n >= P), so that the pixel keeps its colour */
static inline ptrdiff_t zg_extend(ptrdiff_t i, ptrdiff_t n, ptrdiff_t P)
{
    return i < 0 ? i + P * ((P - 1 - i) / P) : (i >= n ? i - P * ((i - n + P) / P) : i);
}

#define IN_T uint8_t
#define IS u8
#define IN_IS_INT 1
#include "z_guided.instances.h"
#define IN_T uint16_t
#define IS u16
#define IN_IS_INT 1
#include "z_guided.instances.h"
#define IN_T float
#define IS f32
#define IN_IS_INT 0
#include "z_guided.instances.h"
#define IN_T double
#define IS f64
#define IN_IS_INT 0
#include "z_guided.instances.h"

static int zg_check(const rgbz_zguided_filters *f, ptrdiff_t rows, ptrdiff_t cols, int py,
                    int px, const int32_t *phase_map, int precision)
{
    if (!f || !f->hash || f->n_levels < 1 || f->gy < 1 || f->gx < 1 || !f->cell || !f->level ||
        !f->w_f32 || !f->w_f64 || !f->g_f32 || !f->g_f64 || !f->n_base || !f->base_idx ||
        f->n_base_max < 1 || (precision != RGBZ_P_FLOAT32 && precision != RGBZ_P_FLOAT64))
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
    for (ptrdiff_t i = 0; i < f->gy * f->gx; i++)
        if (f->level[i] < 0 || f->level[i] >= f->n_levels) return RGBZ_EINVAL;
    for (int k = 0; k < h->n_phases; k++) {
        const int nt = h->n_taps[k], nb = f->n_base[k];
        if (nt <= 0 || nt > h->n_taps_max || nb < 1 || nb > f->n_base_max) return RGBZ_EINVAL;
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

/* the column map of the taps: x in [-R, cols + R) -> its column inside the frame */
static ptrdiff_t *zg_colmap(const rgbz_zguided_filters *f, ptrdiff_t cols, int px)
{
    const int R = f->hash->radius;
    ptrdiff_t *colmap = malloc((size_t)(cols + 2 * R) * sizeof *colmap);
    if (colmap)
        for (ptrdiff_t x = -R; x < cols + R; x++) colmap[x + R] = zg_extend(x, cols, px);
    return colmap;
}

#define ZG_ENTRY(is, T)                                                                        \
    int rgbz_zguided_##is(const T *src, T *dst, ptrdiff_t rows, ptrdiff_t cols, int py,      \
                          int px, const int32_t *phase_map, const rgbz_zguided_filters *f,    \
                          int precision, double maxval, int workers, uint64_t *opcounts)      \
    {                                                                                          \
        int status = zg_check(f, rows, cols, py, px, phase_map, precision);                   \
        if (status != RGBZ_OK) return status;                                                  \
        ZG_COUNTING_ONLY(if (!opcounts) return RGBZ_EINVAL; workers = 1;)                     \
        ptrdiff_t *colmap = zg_colmap(f, cols, px);                                            \
        if (!colmap) return RGBZ_ENOMEM;                                                       \
        status = precision == RGBZ_P_FLOAT64                                                   \
                     ? zg_loop_##is##_f64(src, dst, rows, cols, py, px, phase_map, f, colmap, \
                                          maxval, workers, opcounts)                           \
                     : zg_loop_##is##_f32(src, dst, rows, cols, py, px, phase_map, f, colmap, \
                                          maxval, workers, opcounts);                          \
        free(colmap);                                                                          \
        return status;                                                                         \
    }

#ifdef RGBZ_COUNT_OPS
#define ZG_COUNTING_ONLY(code) code
#else
#define ZG_COUNTING_ONLY(code)
#endif

ZG_ENTRY(u8, uint8_t)
ZG_ENTRY(u16, uint16_t)
ZG_ENTRY(f32, float)
ZG_ENTRY(f64, double)

/* the cell terms are one per tile and not counted (the counting build runs them too, on one
   thread, without touching its counters) */
#ifdef _OPENMP
#define ZG_NTHREADS(w) ((w) > 0 ? (w) : omp_get_max_threads())
#define ZG_CELLS_PARALLEL _Pragma("omp parallel for schedule(static) num_threads(zg_nth)")
#else
#define ZG_NTHREADS(w) ((void)(w), 1)
#define ZG_CELLS_PARALLEL
#endif

/* the 11 terms of a tile from the 3 x 3 amplitudes N, their variances V and colour means C
   (in the order of reconstruction/_z_guided.py's cell_terms), and nu */
static void zg_cell_terms(const double *N, const double *V, const double *C, double lam,
                          double *out, double *nu_out)
{
    double nb = 0.0, vb = 0.0, cb = 0.0;
    for (int m = 0; m < 9; m++) {
        nb += N[m];
        vb += V[m];
        cb += C[m];
    }
    nb /= 9.0;
    vb /= 9.0;
    cb /= 9.0;
    const int lit = nb > 0.0;
    const double inv = 1.0 / (lit ? nb : 1.0);
    double u[9], U = 0.0, ud = 0.0;
    for (int m = 0; m < 9; m++) {
        u[m] = lit ? N[m] * inv - 1.0 : 0.0;
        U += u[m] * u[m];
    }
    const double nu = lit ? vb * inv * inv : 1.0;
    for (int m = 0; m < 9; m++) ud += u[m] * (C[m] - cb);
    const double share = U / (U + 9.0 * nu + 2.2250738585072014e-308);
    const double a = ud / (U + 9.0 * (lam + nu));
    const double au = a * u[4];
    for (int m = 0; m < 9; m++) out[m] = share * u[m];
    out[9] = cb + au;
    out[10] = au - (C[4] - cb);
    *nu_out = nu;
}

static int zg_cells_check(ptrdiff_t rows, ptrdiff_t cols, int py, int px, const int8_t *chan,
                          int zr, int zc, int block, ptrdiff_t gy, ptrdiff_t gx, int n_phases,
                          const int32_t *targets, const double *thr, int n_thr)
{
    if (py <= 0 || px <= 0 || rows < py || cols < px || zr < 0 || zc < 0 || zr >= py ||
        zc >= px || (block != 1 && block != 2) || gy < 1 || gx < 1 || n_phases < 1 ||
        n_thr < 0 || (n_thr > 0 && !thr) || !chan || !targets)
        return RGBZ_EINVAL;
    for (int k = 0; k < n_phases; k++) {
        int found = 0;
        for (int i = 0; i < py * px; i++) found |= chan[i] == targets[k];
        if (targets[k] < 0 || targets[k] > 2 || !found) return RGBZ_EINVAL;
    }
    return RGBZ_OK;
}

/* the offsets (ey, ex) of the pixels of colour t in the box of a Z pixel and the two pixels
   around it, row-major (the same for every tile: the tile keeps the colours); returns their
   number */
static int zg_box_offsets(const int8_t *chan, int py, int px, int zr, int zc, int block, int t,
                          int *ey, int *ex)
{
    int n = 0;
    for (int dy = -2; dy < block + 2; dy++)
        for (int dx = -2; dx < block + 2; dx++) {
            const int y = ((zr + dy) % py + py) % py, x = ((zc + dx) % px + px) % px;
            if (chan[y * px + x] == t) {
                ey[n] = dy;
                ex[n] = dx;
                n++;
            }
        }
    return n;
}

/* the second pass: the terms of every tile of rows iy from the amplitude grid, its variance
   and the colour means cg (n_phases, gy, gx) */
static void zg_cells_terms(const double *grid, const double *var, const double *cg,
                           ptrdiff_t gy, ptrdiff_t gx, int n_phases, double lam,
                           const double *thr, int n_thr, double *cell, int32_t *level,
                           ptrdiff_t iy)
{
    for (ptrdiff_t ix = 0; ix < gx; ix++) {
        double N[9], V[9], C[9], nu = 1.0;
        ptrdiff_t at[9];
        int m = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++, m++) {
                ptrdiff_t jy = iy + dy, jx = ix + dx;
                jy = jy < 0 ? 0 : (jy >= gy ? gy - 1 : jy);
                jx = jx < 0 ? 0 : (jx >= gx ? gx - 1 : jx);
                at[m] = jy * gx + jx;
                N[m] = grid[at[m]];
                V[m] = var[at[m]];
            }
        for (int k = 0; k < n_phases; k++) {
            for (m = 0; m < 9; m++) C[m] = cg[k * gy * gx + at[m]];
            zg_cell_terms(N, V, C, lam, cell + ((k * gy + iy) * gx + ix) * RGBZ_ZG_FEATURES,
                          &nu);
        }
        int lv = 0;
        for (int i = 0; i < n_thr; i++) lv += nu > thr[i];
        level[iy * gx + ix] = lv;
    }
}

/* the entry points: the colour means of every Z pixel's box (one pass), then the terms */
#define ZG_CELLS(is, T)                                                                        \
    int rgbz_zguided_cells_##is(const T *src, ptrdiff_t rows, ptrdiff_t cols, int py, int px, \
                                const int8_t *chan, int zr, int zc, int block,                \
                                const double *grid, const double *var, ptrdiff_t gy,          \
                                ptrdiff_t gx, int n_phases, const int32_t *targets,           \
                                double lam, const double *thr, int n_thr, double *cell,       \
                                int32_t *level, int workers)                                  \
    {                                                                                          \
        int status = zg_cells_check(rows, cols, py, px, chan, zr, zc, block, gy, gx,          \
                                    n_phases, targets, thr, n_thr);                            \
        if (status != RGBZ_OK) return status;                                                  \
        double *cg = malloc((size_t)n_phases * (size_t)gy * (size_t)gx * sizeof *cg);         \
        int *ey = malloc((size_t)n_phases * 36 * 2 * sizeof *ey);                              \
        int *nbox = malloc((size_t)n_phases * sizeof *nbox);                                  \
        if (!cg || !ey || !nbox) {                                                             \
            free(cg);                                                                          \
            free(ey);                                                                          \
            free(nbox);                                                                        \
            return RGBZ_ENOMEM;                                                                \
        }                                                                                      \
        for (int k = 0; k < n_phases; k++)                                                     \
            nbox[k] = zg_box_offsets(chan, py, px, zr, zc, block, targets[k], ey + k * 72,    \
                                     ey + k * 72 + 36);                                        \
        const int zg_nth = ZG_NTHREADS(workers);                                               \
        (void)zg_nth;                                                                          \
        ZG_CELLS_PARALLEL                                                                      \
        for (ptrdiff_t iy = 0; iy < gy; iy++) {                                                \
            const ptrdiff_t y0 = zr + (ptrdiff_t)py * iy;                                      \
            for (ptrdiff_t ix = 0; ix < gx; ix++) {                                            \
                const ptrdiff_t x0 = zc + (ptrdiff_t)px * ix;                                  \
                const int inside = y0 - 2 >= 0 && y0 + block + 1 < rows && x0 - 2 >= 0 &&    \
                                   x0 + block + 1 < cols;                                      \
                for (int k = 0; k < n_phases; k++) {                                           \
                    const int *oy = ey + k * 72, *ox = ey + k * 72 + 36;                       \
                    double s = 0.0;                                                            \
                    for (int i = 0; i < nbox[k]; i++) {                                        \
                        const ptrdiff_t y = inside ? y0 + oy[i] : zg_extend(y0 + oy[i], rows, py); \
                        const ptrdiff_t x = inside ? x0 + ox[i] : zg_extend(x0 + ox[i], cols, px); \
                        s += (double)src[y * cols + x];                                        \
                    }                                                                          \
                    cg[(k * gy + iy) * gx + ix] = s / (double)nbox[k];                         \
                }                                                                              \
            }                                                                                  \
        }                                                                                      \
        ZG_CELLS_PARALLEL                                                                      \
        for (ptrdiff_t iy = 0; iy < gy; iy++)                                                  \
            zg_cells_terms(grid, var, cg, gy, gx, n_phases, lam, thr, n_thr, cell, level, iy); \
        free(cg);                                                                              \
        free(ey);                                                                              \
        free(nbox);                                                                            \
        return RGBZ_OK;                                                                        \
    }

ZG_CELLS(u8, uint8_t)
ZG_CELLS(u16, uint16_t)
ZG_CELLS(f32, float)
ZG_CELLS(f64, double)
