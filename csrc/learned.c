/*
 * learned.c -- the learned reconstruction (learned.h): learned.template.h for every element
 * type and precision, the entry points rgbz_learned_<precision> (learned_entry.template.h,
 * once per precision), and what they share: the checks of the arguments the Python layer
 * validated (a failure here is a bug there), the choice of the fast path and the column map.
 */
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"
#include "rgbz_ops.h"
#include "learned.h"

#include "learned_common.h"

static int lrn_check(const rgbz_learned_filters *f, ptrdiff_t rows, ptrdiff_t cols, int py,
                     int px, const int32_t *phase_map)
{
    if (!f || f->n_phases <= 0 || f->n_buckets <= 0 || f->n_str < 1 || f->n_coh < 1 ||
        f->n_spr < 1 || f->n_buckets != 8 * f->n_str * f->n_coh * f->n_spr || f->radius < 0 ||
        f->radius > RGBZ_LEARNED_MAX_RADIUS || f->n_taps_max <= 0 ||
        f->n_taps_max > RGBZ_LEARNED_MAX_TAPS || f->hash_radius > f->radius || py <= 0 || px <= 0 || rows < py || cols < px)
        return RGBZ_EINVAL;
    for (int i = 0; i < py * px; i++)
        if (phase_map[i] >= f->n_phases) return RGBZ_EINVAL;
    for (int i = 0; i < 4; i++)
        if (f->bayer[i] < 0 || f->bayer[i] > 2) return RGBZ_EINVAL;
    for (int k = 0; k < f->n_phases; k++) {
        const int nt = f->n_taps[k];
        if (nt <= 0 || nt > f->n_taps_max) return RGBZ_EINVAL;
        for (int t = 0; t < nt; t++) {
            const int dy = f->tap_dy[k * f->n_taps_max + t], dx = f->tap_dx[k * f->n_taps_max + t];
            if (dy < -f->radius || dy > f->radius || dx < -f->radius || dx > f->radius)
                return RGBZ_EINVAL;
        }
        for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
            const int np = f->n_pairs[k * RGBZ_LEARNED_DIRS + d];
            if (np <= 0 || np > f->n_pairs_max) return RGBZ_EINVAL;
            const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * f->n_pairs_max;
            for (int p = 0; p < np; p++)
                if (f->pair_a[o + p] < 0 || f->pair_a[o + p] >= nt || f->pair_b[o + p] < 0 ||
                    f->pair_b[o + p] >= nt || f->pair_col[o + p] < 0 || f->pair_col[o + p] > 2)
                    return RGBZ_EINVAL;
        }
    }
    return RGBZ_OK;
}

/* The checks and the set-up of rgbz_learned_<precision>: RGBZ_OK with *colmap a malloc'ed
   map of the columns x in [-radius, cols + radius) moved into the frame by whole periods
   (colmap[x + radius]; the caller frees it), *fast_ok from lrn_fast_ok and *workers 1 in the
   counting build; otherwise the status to return (nothing then to free). */
static int lrn_setup(const void *src, const void *dst, ptrdiff_t rows, ptrdiff_t cols, int py,
                     int px, const int32_t *phase_map, const rgbz_learned_filters *f,
                     const uint64_t *opcounts, int *workers, ptrdiff_t **colmap, int *fast_ok)
{
    if (!src || !dst || !phase_map) return RGBZ_EINVAL;
    int status = lrn_check(f, rows, cols, py, px, phase_map);
    if (status != RGBZ_OK) return status;
#ifdef RGBZ_COUNT_OPS
    if (!opcounts) return RGBZ_EINVAL;
    *workers = 1;
#else
    (void)opcounts;
    (void)workers;
#endif
    const int R = f->radius;
    ptrdiff_t *cm = malloc((size_t)(cols + 2 * R) * sizeof *cm);
    if (!cm) return RGBZ_ENOMEM;
    for (ptrdiff_t x = -R; x < cols + R; x++) cm[x + R] = lrn_extend(x, cols, px);
    *colmap = cm;
    *fast_ok = lrn_fast_ok(f, f->wd_f32 && f->wd_f64, py, px, phase_map);
    return RGBZ_OK;
}

/* ---- the instances: per precision, the frame loops and the entry point ---- */
#define RGBZ_REAL_TEMPLATE "learned_entry.template.h"
#include "rgbz_each_real.h"
#undef RGBZ_REAL_TEMPLATE
