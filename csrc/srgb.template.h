/*
 * srgb.template.h -- the sRGB encoding of srgb.c in one precision. Instantiated by srgb.c
 * through rgbz_each_real.h (rgbz_templating.h), with
 *   REAL  the float type of the values (float, double)
 *   RS    its suffix (f32, f64), appended to every function name;
 * the finish, below, once per integer element type of the codes: this file instantiates
 * itself through rgbz_each_type.h (IN_T, IS, IN_IS_INT; a float type defines nothing).
 */
#ifndef REAL
#error "srgb.template.h: #define REAL (float or double) before including it"
#endif
#ifndef RS
#error "srgb.template.h: #define RS (the suffix of REAL: f32 or f64)"
#endif

#ifndef IN_T
/* p = 1 where the clipped x is on the OETF's linear segment, else the clipped x */
static void RGBZ_CAT(sr_prepare, RS)(const REAL *x, REAL *p, ptrdiff_t n, int workers)
{
    const REAL knee = (REAL)0.0031308;
    int nt = rgbz_threads_per_values(workers, n);
    (void)nt;
    SR_FOR(nt)
    for (ptrdiff_t i = 0; i < n; i++) {
        const REAL v = SR_CLIP(REAL, x[i]);
        p[i] = v <= knee ? (REAL)1 : v;
    }
}

#define RGBZ_TYPE_TEMPLATE "srgb.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

int RGBZ_CAT(rgbz_oetf_prepare, RS)(const REAL *x, REAL *p, ptrdiff_t n, int workers)
{
    if (!x || !p || n < 0) return RGBZ_EINVAL;
    RGBZ_CAT(sr_prepare, RS)(x, p, n, workers);
    return RGBZ_OK;
}

int RGBZ_CAT(rgbz_oetf_finish, RS)(const REAL *x, const REAL *p, ptrdiff_t n, int code_type,
                                   void *code, int workers)
{
    if (!x || !p || !code || n < 0) return RGBZ_EINVAL;
#define SR_FINISH_(s, T) RGBZ_CAT3(sr_finish, RS, s)(x, p, n, (T *)code, workers)
    RGBZ_SWITCH_TYPE(code_type, RGBZ_INT_TYPES, SR_FINISH_, return RGBZ_EINVAL)
#undef SR_FINISH_
    return RGBZ_OK;
}

#elif IN_IS_INT
/* the codes of x, p holding the power 1 / 2.4 of the prepared values; top = 2^bits - 1,
   the largest code of IN_T */
static void RGBZ_CAT3(sr_finish, RS, IS)(const REAL *x, const REAL *p, ptrdiff_t n,
                                         IN_T *code, int workers)
{
    const REAL knee = (REAL)0.0031308, a = (REAL)1.055, b = (REAL)0.055, s = (REAL)12.92;
    const REAL top = (REAL)(IN_T)-1, half = (REAL)0.5;
    int nt = rgbz_threads_per_values(workers, n);
    (void)nt;
    SR_FOR(nt)
    for (ptrdiff_t i = 0; i < n; i++) {
        const REAL v = SR_CLIP(REAL, x[i]);
        REAL e = p[i] * a;
        e = e - b;
        e = v <= knee ? v * s : e;
        REAL q = e * top;
        q = q + half;
        code[i] = (IN_T)(int32_t)q;          /* q >= 0.5: truncation = floor */
    }
}
#endif
