/*
 * z_guided_entry.template.h -- the z_guided reconstruction in one precision: the frame loop
 * of z_guided.template.h for each element type, and the entry point rgbz_zguided_<RS>
 * (z_guided.h). Instantiated by z_guided.c through rgbz_each_real.h, with REAL and RS
 * (rgbz_templating.h).
 */
#if !defined(REAL) || !defined(RS)
#error "z_guided_entry.template.h: #define REAL and RS (the precision) before including it"
#endif

#include "z_guided_cells.template.h"

#define RGBZ_TYPE_TEMPLATE "z_guided.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

int RGBZ_CAT(rgbz_zguided, RS)(int in_type, const void *src, void *dst, ptrdiff_t rows,
                               ptrdiff_t cols, int py, int px, const int32_t *phase_map,
                               const rgbz_zguided_filters *f, double maxval, int workers,
                               uint64_t *opcounts)
{
    int st = zg_check(src, dst, f, rows, cols, py, px, phase_map);
    if (st != RGBZ_OK) return st;
#ifdef RGBZ_COUNT_OPS
    if (!opcounts) return RGBZ_EINVAL;
    workers = 1;
#endif
    ptrdiff_t *colmap = zg_colmap(f, cols, px);
    if (!colmap) return RGBZ_ENOMEM;
    const int fast_ok = lrn_fast_ok(f->hash, f->wd_f32 && f->wd_f64, py, px, phase_map);
#define ZG_LOOP_(s, T)                                                                       \
    st = RGBZ_CAT3(zg_loop, s, RS)((const T *)src, (T *)dst, rows, cols, py, px, phase_map,  \
                                   f, colmap, fast_ok, maxval, workers, opcounts)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, ZG_LOOP_, st = RGBZ_EINVAL)
#undef ZG_LOOP_
    free(colmap);
    return st;
}
