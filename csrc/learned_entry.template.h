/*
 * learned_entry.template.h -- the learned reconstruction in one precision: the frame loop
 * of learned.template.h for each element type, and the entry point rgbz_learned_<RS>
 * (learned.h). Instantiated by learned.c through rgbz_each_real.h, with REAL and RS
 * (rgbz_templating.h).
 */
#if !defined(REAL) || !defined(RS)
#error "learned_entry.template.h: #define REAL and RS (the precision) before including it"
#endif

#define RGBZ_TYPE_TEMPLATE "learned.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

int RGBZ_CAT(rgbz_learned, RS)(int in_type, const void *src, void *dst, ptrdiff_t rows,
                               ptrdiff_t cols, int py, int px, const int32_t *phase_map,
                               const rgbz_learned_filters *f, double maxval, int workers,
                               uint64_t *opcounts)
{
    ptrdiff_t *colmap;
    int fast_ok;
    int st = lrn_setup(src, dst, rows, cols, py, px, phase_map, f, opcounts, &workers, &colmap,
                       &fast_ok);
    if (st != RGBZ_OK) return st;
#define LRN_LOOP_(s, T)                                                                      \
    st = RGBZ_CAT3(lrn_loop, s, RS)((const T *)src, (T *)dst, rows, cols, py, px, phase_map, \
                                    f, colmap, fast_ok, maxval, workers, opcounts)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, LRN_LOOP_, st = RGBZ_EINVAL)
#undef LRN_LOOP_
    free(colmap);
    return st;
}
